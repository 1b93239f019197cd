//! The premises graph ([`PremisesGraph`], laid out by the checks) drawn: as a linked SVG for the
//! HTML report and on a plotters backend for the LaTeX report's PNG. Nodes are coloured by
//! verdict, root causes outlined, and the arrows along which an error is inherited drawn red.

use super::FigureError;
use checks::cause::graph::{PremisesGraph, Status};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::fmt::Write;

/// (fill, stroke) colours, the report's verdict colours.
fn colours(status: Status) -> (RGBColor, RGBColor) {
    match status {
        Status::Holds => (RGBColor(0xe3, 0xf4, 0xea), RGBColor(0x0b, 0x5d, 0x2a)),
        Status::Approx => (RGBColor(0xe6, 0xf0, 0xfb), RGBColor(0x12, 0x46, 0x7a)),
        Status::Definition => (RGBColor(0xf0, 0xf0, 0xf0), RGBColor(0x44, 0x44, 0x44)),
        Status::Estimate => (RGBColor(0xf3, 0xe8, 0xfb), RGBColor(0x5b, 0x2a, 0x86)),
        Status::PremiseFails => (RGBColor(0xfc, 0xec, 0xdc), RGBColor(0x8a, 0x4b, 0x08)),
        Status::Fails => (RGBColor(0xfd, 0xe4, 0xe1), RGBColor(0x9b, 0x1c, 0x0c)),
        Status::Depends => (RGBColor(0xdc, 0xf4, 0xf1), RGBColor(0x0b, 0x5f, 0x57)),
        Status::Unchecked => (RGBColor(0xff, 0xf4, 0xd6), RGBColor(0x7a, 0x52, 0x00)),
    }
}

/// An SVG whose nodes link to their findings (`#eq-N`) and carry their verdict and cause as
/// a tooltip: for the HTML report.
pub fn linked_svg(g: &PremisesGraph, width: u32, height: u32) -> String {
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
        for &(p, n, inh) in g.edges.iter().filter(|e| e.2 == pass) {
            if let (Some(a), Some(b)) = (g.place(p, w, h, 20.0), g.place(n, w, h, 20.0)) {
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
    for m in &g.nodes {
        let Some((cx, cy)) = g.place(m.number, w, h, 20.0) else {
            continue;
        };
        let (fill, stroke) = colours(m.status);
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
    g: &PremisesGraph,
    root: &DrawingArea<DB, Shift>,
    scale: f64,
) -> Result<(), FigureError> {
    let err = |e: DrawingAreaErrorKind<DB::ErrorType>| FigureError::Draw(e.to_string());
    root.fill(&WHITE).map_err(err)?;
    let (w, h) = root.dim_in_pixel();
    let (w, h) = (f64::from(w), f64::from(h));
    let margin = 20.0 * scale;
    let r = 11.0 * scale;
    let px = |p: (f64, f64)| (p.0.round() as i32, p.1.round() as i32);
    for pass in [false, true] {
        for &(p, n, inh) in g.edges.iter().filter(|e| e.2 == pass) {
            if let (Some(a), Some(b)) = (g.place(p, w, h, margin), g.place(n, w, h, margin)) {
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
    for m in &g.nodes {
        let Some(c) = g.place(m.number, w, h, margin) else {
            continue;
        };
        let (fill, stroke) = colours(m.status);
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

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;
    use checks::cause::graph::GraphNode;

    #[test]
    fn the_linked_svg_links_every_node_and_carries_its_note() {
        let node = |number: u32, y: f64, status: Status, note: &str| GraphNode {
            number,
            x: 0.5,
            y,
            status,
            root: number == 2,
            note: note.to_string(),
        };
        let g = PremisesGraph {
            nodes: vec![
                node(1, 0.0, Status::Holds, "holds"),
                node(2, 0.5, Status::Fails, "fails: root cause"),
                node(3, 1.0, Status::Fails, "fails: inherits from eq 2"),
            ],
            edges: vec![(1, 2, false), (2, 3, true)],
        };
        let svg = linked_svg(&g, 300, 200);
        assert!(svg.contains(r##"href="#eq-3""##) && svg.contains("inherits from eq 2"));
        assert_eq!(svg.matches("<circle").count(), 3);
        assert_eq!(
            svg.matches("#c0392b").count(),
            2,
            "one inherited arrow: line and head"
        );
    }

    #[test]
    fn a_node_that_depends_on_a_choice_has_its_own_colour() {
        let (fill, stroke) = colours(Status::Depends);
        assert!(
            [
                Status::Fails,
                Status::PremiseFails,
                Status::Holds,
                Status::Unchecked
            ]
            .iter()
            .all(|&s| colours(s) != (fill, stroke)),
            "depends is drawn apart from every other verdict"
        );
        let g = PremisesGraph {
            nodes: vec![GraphNode {
                number: 57,
                x: 0.5,
                y: 0.5,
                status: Status::Depends,
                root: false,
                note: "eq 57: depends on a choice the paper leaves open".into(),
            }],
            edges: vec![],
        };
        let svg = linked_svg(&g, 300, 200);
        assert!(svg.contains("#dcf4f1") && !svg.contains("#fde4e1"));
    }
}
