//! The premises graph laid out for a figure (drawn by the report), in the manner of the dependency graphs of Lean
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
use crate::finding::Verdict;
use serde::Serialize;
use std::collections::BTreeMap;

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
    /// Its verdict changes under a reasonable alternative to a choice the paper leaves open:
    /// neither a failure nor a pass.
    Depends,
    /// Not checkable, or could not run.
    Unchecked,
}

impl Status {
    /// The verdict in words (the tooltip's first word).
    pub fn word(self) -> &'static str {
        match self {
            Status::Holds => "holds",
            Status::Approx => "holds approximately",
            Status::Definition => "definition",
            Status::Estimate => "estimate",
            Status::PremiseFails => "premise fails",
            Status::Fails => "fails",
            Status::Depends => "depends on a choice the paper leaves open",
            Status::Unchecked => "not checked",
        }
    }

    /// The colour class of a verdict: a verdict that depends on a choice is drawn apart from
    /// the failures, as the closing line counts it apart.
    pub fn of(verdict: Verdict) -> Status {
        match verdict {
            Verdict::Holds => Status::Holds,
            Verdict::HoldsApproximately { .. } => Status::Approx,
            Verdict::Definition => Status::Definition,
            Verdict::Estimate { .. } => Status::Estimate,
            Verdict::PremiseFails => Status::PremiseFails,
            Verdict::DependsOn { .. } => Status::Depends,
            Verdict::Fails
            | Verdict::Restates { .. }
            | Verdict::PartOf { .. }
            | Verdict::UnitMisprint
            | Verdict::DimensionalSlip => Status::Fails,
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

    /// Where node `n` sits on a `w` by `h` canvas with `margin` on every side.
    pub fn place(&self, n: u32, w: f64, h: f64, margin: f64) -> Option<(f64, f64)> {
        self.nodes.iter().find(|m| m.number == n).map(|m| {
            (
                margin + m.x * (w - 2.0 * margin),
                margin + m.y * (h - 2.0 * margin),
            )
        })
    }
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
    }

    #[test]
    fn a_verdict_that_depends_on_a_choice_is_not_drawn_as_a_failure() {
        let depends = Status::of(Verdict::DependsOn {
            choice: "the point of evaluation",
        });
        assert_eq!(depends, Status::Depends);
        assert_ne!(depends, Status::of(Verdict::Fails));
        assert_eq!(Status::of(Verdict::Fails), Status::Fails);
        assert_eq!(Status::of(Verdict::PremiseFails), Status::PremiseFails);
    }
}
