//! The premises graph drawn as a figure, in the manner of the dependency graphs of Lean
//! blueprints: one node per numbered equation, an arrow from each premise to the equation that
//! cites it (`premises` of paper/equations.yaml), nodes coloured by verdict, root causes
//! outlined, and the arrows along which an error is inherited drawn red.
//!
//! Layout: an equation's row is the length of the longest chain of premises above it, so every
//! arrow points down; within a row the nodes are ordered by the mean position of their premises
//! (one barycentre pass, which removes most crossings), ties by number. Hand-written: the graph
//! has 85 nodes and 14 rows, and a general layout crate (graphviz bindings, layout-rs) would add
//! a dependency for what these thirty lines do.

use super::{premises_first, Cause};
use plotters::coord::Shift;
use plotters::prelude::*;
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write;

/// How a node is coloured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// Holds.
    Holds,
    /// Holds at its claimed order.
    Approx,
    /// A consistent definition.
    Definition,
    /// An order-of-magnitude estimate whose scaling holds.
    Estimate,
    /// Would hold, but only under a premise that fails.
    PremiseFails,
    /// Fails.
    Fails,
    /// Not checkable, or could not run.
    Unchecked,
}

impl Status {
    /// (fill, stroke) colours, the report's verdict colours.
    fn colours(self) -> (RGBColor, RGBColor) {
        match self {
            Status::Holds => (RGBColor(0xe3, 0xf4, 0xea), RGBColor(0x0b, 0x5d, 0x2a)),
            Status::Approx => (RGBColor(0xe6, 0xf0, 0xfb), RGBColor(0x12, 0x46, 0x7a)),
            Status::Definition => (RGBColor(0xf0, 0xf0, 0xf0), RGBColor(0x44, 0x44, 0x44)),
            Status::Estimate => (RGBColor(0xf3, 0xe8, 0xfb), RGBColor(0x5b, 0x2a, 0x86)),
            Status::PremiseFails => (RGBColor(0xfc, 0xec, 0xdc), RGBColor(0x8a, 0x4b, 0x08)),
            Status::Fails => (RGBColor(0xfd, 0xe4, 0xe1), RGBColor(0x9b, 0x1c, 0x0c)),
            Status::Unchecked => (RGBColor(0xff, 0xf4, 0xd6), RGBColor(0x7a, 0x52, 0x00)),
        }
    }

    fn word(self) -> &'static str {
        match self {
            Status::Holds => "holds",
            Status::Approx => "holds approximately",
            Status::Definition => "definition",
            Status::Estimate => "estimate",
            Status::PremiseFails => "premise fails",
            Status::Fails => "fails",
            Status::Unchecked => "not checked",
        }
    }
}

/// One equation in the graph, placed in the unit square (x right, y down).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GraphNode {
    /// Printed number.
    pub number: u32,
    /// Horizontal place, 0..1.
    pub x: f64,
    /// Vertical place, 0..1 (row over the last row).
    pub y: f64,
    /// Verdict colour.
    pub status: Status,
    /// Outlined: a root cause.
    pub root: bool,
    /// Tooltip: verdict and cause.
    pub note: String,
}

/// The premises graph, laid out.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PremisesGraph {
    /// The nodes.
    pub nodes: Vec<GraphNode>,
    /// (premise, equation, inherited): an arrow, red when the equation inherits an error along it.
    pub edges: Vec<(u32, u32, bool)>,
}

impl PremisesGraph {
    /// Lays the graph out from each equation's premises, verdict and cause.
    pub fn new(
        premises: &BTreeMap<u32, Vec<u32>>,
        status: &dyn Fn(u32) -> Status,
        causes: &BTreeMap<u32, Cause>,
    ) -> Self {
        let numbers: Vec<u32> = premises.keys().copied().collect();
        let of = |n: u32| premises.get(&n).cloned().unwrap_or_default();
        let order = premises_first(&of, &numbers);
        let mut row: BTreeMap<u32, usize> = BTreeMap::new();
        for &n in &order {
            let r = of(n)
                .iter()
                .filter(|&&p| p != n)
                .filter_map(|p| row.get(p))
                .map(|r| r + 1)
                .max()
                .unwrap_or(0);
            row.insert(n, r);
        }
        let rows = row.values().copied().max().unwrap_or(0) + 1;
        let mut x: BTreeMap<u32, f64> = BTreeMap::new();
        for r in 0..rows {
            let mut members: Vec<(f64, u32)> = row
                .iter()
                .filter(|(_, &rr)| rr == r)
                .map(|(&n, _)| {
                    let xs: Vec<f64> = of(n).iter().filter_map(|p| x.get(p)).copied().collect();
                    let bary = if xs.is_empty() {
                        f64::from(n) / 85.0
                    } else {
                        xs.iter().sum::<f64>() / xs.len() as f64
                    };
                    (bary, n)
                })
                .collect();
            members.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            let m = members.len() as f64;
            for (i, (_, n)) in members.iter().enumerate() {
                x.insert(*n, (i as f64 + 0.5) / m);
            }
        }
        let inherited = |p: u32, n: u32| match causes.get(&n) {
            Some(Cause::Inherits { from, .. }) => from.contains(&p),
            Some(Cause::RootCause {
                also_inherits_from, ..
            }) => also_inherits_from.contains(&p),
            _ => false,
        };
        let nodes = numbers
            .iter()
            .map(|&n| {
                let s = status(n);
                let cause = causes.get(&n);
                GraphNode {
                    number: n,
                    x: x.get(&n).copied().unwrap_or(0.5),
                    y: (row.get(&n).copied().unwrap_or(0) as f64 + 0.5) / rows as f64,
                    status: s,
                    root: matches!(cause, Some(Cause::RootCause { .. })),
                    note: match cause {
                        Some(c) => format!("eq {n}: {}; {}", s.word(), c.describe()),
                        None => format!("eq {n}: {}", s.word()),
                    },
                }
            })
            .collect();
        let edges = numbers
            .iter()
            .flat_map(|&n| {
                of(n)
                    .into_iter()
                    .filter(move |&p| p != n && premises.contains_key(&p))
                    .map(move |p| (p, n, inherited(p, n)))
            })
            .collect();
        Self { nodes, edges }
    }

    fn place(&self, n: u32, w: f64, h: f64, margin: f64) -> Option<(f64, f64)> {
        self.nodes.iter().find(|m| m.number == n).map(|m| {
            (
                margin + m.x * (w - 2.0 * margin),
                margin + m.y * (h - 2.0 * margin),
            )
        })
    }

    /// An SVG whose nodes link to their findings (`#eq-N`) and carry their verdict and cause as
    /// a tooltip: for the HTML report.
    pub fn to_linked_svg(&self, width: u32, height: u32) -> String {
        let (w, h) = (f64::from(width), f64::from(height));
        let r = 11.0;
        let mut s = String::new();
        let _ = write!(
            s,
            r##"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" role="img" aria-label="premises graph"><rect width="100%" height="100%" fill="white"/>"##
        );
        let hex = |c: RGBColor| format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2);
        // Plain arrows first, inherited ones on top.
        for pass in [false, true] {
            for &(p, n, inh) in self.edges.iter().filter(|e| e.2 == pass) {
                if let (Some(a), Some(b)) = (self.place(p, w, h, 20.0), self.place(n, w, h, 20.0)) {
                    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                    let len = dx.hypot(dy).max(1e-9);
                    let (ux, uy) = (dx / len, dy / len);
                    let colour = if inh { "#c0392b" } else { "#aaaaaa" };
                    // The line, then an arrowhead drawn as a triangle at the node's rim (no
                    // markers: the report refers to nothing, not even a fragment, by url()).
                    let (tx, ty) = (b.0 - ux * (r + 1.0), b.1 - uy * (r + 1.0));
                    let (bx, by) = (tx - ux * 6.0, ty - uy * 6.0);
                    let _ = write!(
                        s,
                        r#"<line x1="{:.1}" y1="{:.1}" x2="{bx:.1}" y2="{by:.1}" stroke="{colour}" stroke-width="{}"/><path d="M{tx:.1},{ty:.1} L{:.1},{:.1} L{:.1},{:.1} z" fill="{colour}"/>"#,
                        a.0 + ux * r,
                        a.1 + uy * r,
                        if inh { 2.2 } else { 0.8 },
                        bx - uy * 3.0,
                        by + ux * 3.0,
                        bx + uy * 3.0,
                        by - ux * 3.0,
                    );
                }
            }
        }
        for m in &self.nodes {
            let Some((cx, cy)) = self.place(m.number, w, h, 20.0) else {
                continue;
            };
            let (fill, stroke) = m.status.colours();
            let _ = write!(
                s,
                r##"<a href="#eq-{n}"><title>{note}</title><circle cx="{cx:.1}" cy="{cy:.1}" r="{r}" fill="{fill}" stroke="{stroke}" stroke-width="{sw}"/><text x="{cx:.1}" y="{ty:.1}" font-size="10" font-family="DejaVu Serif, serif" text-anchor="middle" fill="{stroke}">{n}</text></a>"##,
                n = m.number,
                note = escape(&m.note),
                fill = hex(fill),
                stroke = hex(stroke),
                sw = if m.root { 3.5 } else { 1.0 },
                ty = cy + 3.5,
            );
        }
        s.push_str("</svg>");
        s
    }

    /// Draws the graph on a plotters backend (the PNG of the LaTeX report); `scale` multiplies
    /// sizes.
    pub fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        scale: f64,
    ) -> Result<(), crate::figures::FigureError> {
        let err = |e: DrawingAreaErrorKind<DB::ErrorType>| {
            crate::figures::FigureError::Draw(e.to_string())
        };
        root.fill(&WHITE).map_err(err)?;
        let (w, h) = root.dim_in_pixel();
        let (w, h) = (f64::from(w), f64::from(h));
        let margin = 20.0 * scale;
        let r = 11.0 * scale;
        let px = |p: (f64, f64)| (p.0.round() as i32, p.1.round() as i32);
        for pass in [false, true] {
            for &(p, n, inh) in self.edges.iter().filter(|e| e.2 == pass) {
                if let (Some(a), Some(b)) =
                    (self.place(p, w, h, margin), self.place(n, w, h, margin))
                {
                    let colour = if inh {
                        RGBColor(0xc0, 0x39, 0x2b)
                    } else {
                        RGBColor(0xbb, 0xbb, 0xbb)
                    };
                    let width = ((if inh { 2.2 } else { 0.8 }) * scale).round().max(1.0) as u32;
                    root.draw(&PathElement::new(
                        vec![px(a), px(b)],
                        colour.stroke_width(width),
                    ))
                    .map_err(err)?;
                }
            }
        }
        let font = ("sans-serif", 10.0 * scale).into_font();
        for m in &self.nodes {
            let Some(c) = self.place(m.number, w, h, margin) else {
                continue;
            };
            let (fill, stroke) = m.status.colours();
            root.draw(&Circle::new(px(c), r.round() as i32, fill.filled()))
                .map_err(err)?;
            let sw = ((if m.root { 3.5 } else { 1.0 }) * scale).round() as u32;
            root.draw(&Circle::new(
                px(c),
                r.round() as i32,
                stroke.stroke_width(sw.max(1)),
            ))
            .map_err(err)?;
            let style = font
                .clone()
                .color(&stroke)
                .pos(plotters::style::text_anchor::Pos::new(
                    plotters::style::text_anchor::HPos::Center,
                    plotters::style::text_anchor::VPos::Center,
                ));
            root.draw(&Text::new(m.number.to_string(), px(c), style))
                .map_err(err)?;
        }
        root.present().map_err(err)
    }
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrows_point_down_and_inherited_ones_are_marked() {
        let premises: BTreeMap<u32, Vec<u32>> = [(1, vec![]), (2, vec![1]), (3, vec![2, 1])]
            .into_iter()
            .collect();
        let causes: BTreeMap<u32, Cause> = [
            (
                2,
                Cause::RootCause {
                    also_inherits_from: vec![],
                    own_error: None,
                },
            ),
            (
                3,
                Cause::Inherits {
                    from: vec![2],
                    roots: vec![2],
                    derivation_error: 0.0,
                },
            ),
        ]
        .into_iter()
        .collect();
        let g = PremisesGraph::new(
            &premises,
            &|n| if n == 1 { Status::Holds } else { Status::Fails },
            &causes,
        );
        let y = |n: u32| g.nodes.iter().find(|m| m.number == n).map(|m| m.y).unwrap();
        assert!(y(1) < y(2) && y(2) < y(3));
        assert!(g.edges.contains(&(2, 3, true)) && g.edges.contains(&(1, 3, false)));
        assert!(g.nodes.iter().any(|m| m.number == 2 && m.root));
        let svg = g.to_linked_svg(300, 200);
        assert!(svg.contains(r##"href="#eq-3""##) && svg.contains("inherits from eq 2"));
        assert_eq!(svg.matches("<circle").count(), 3);
    }
}
