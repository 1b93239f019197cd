//! A printed inequality read as a threshold: where its sides meet, and which side of the
//! reference's edge it allows.

use super::{solve_printed, Bench};
use crate::finding::Worst;

/// A printed inequality of eq `n` (its first) read as a threshold on `quantity`: the value where
/// its two sides meet, solved for in `[lo, hi]` from the printed text (NaN if none), and whether
/// it holds at the two probes `below` and `above` the reference's edge.
pub struct PrintedThreshold {
    /// Where the printed sides meet.
    pub edge: f64,
    /// Whether the printed inequality holds at the probe below and at the probe above.
    pub holds: [bool; 2],
    /// The inequality, for messages.
    pub relation: String,
    /// The range of the quantity the edge was sought in.
    pub bracket: (f64, f64),
}

/// Reads eq `n`'s first inequality as a threshold on `quantity` (see [`PrintedThreshold`]).
pub fn printed_threshold(
    b: &Bench,
    n: u32,
    quantity: &'static str,
    bind: &paper::Bindings<f64>,
    bracket: (f64, f64),
    probes: [f64; 2],
) -> PrintedThreshold {
    use paper::Value;
    let eq = b.paper.equation(n);
    let rels = eq.relations();
    let Some(rel) = rels.iter().find(|r| r.rel.is_inequality()).copied() else {
        return PrintedThreshold {
            edge: f64::NAN,
            holds: [false, false],
            relation: format!("eq {n} prints no inequality"),
            bracket,
        };
    };
    let edge = solve_printed(eq, &rel, quantity, bind, bracket.0, bracket.1).unwrap_or(f64::NAN);
    let holds = probes.map(|x| {
        let mut bb = bind.clone();
        bb.set(quantity, Value::Scalar(x));
        match (eq.scalar(rel.lhs, &bb), eq.scalar(rel.rhs, &bb)) {
            (Ok(l), Ok(r)) => rel.rel.holds(l, r),
            _ => false,
        }
    });
    PrintedThreshold {
        edge,
        holds,
        relation: rel.name(),
        bracket,
    }
}

/// Adds a threshold's comparison to `w`: the printed edge (read through [`Bench::claim`])
/// against the reference's, and the printed direction against the reference's verdicts at the
/// probes (`allowed[i]`: the motion exists or is stable there).
///
/// A direction that disagrees is a failure the printed text can be evaluated for, so it is
/// recorded with finite values: the printed edge beside the reference's, and as the error the
/// length of the range tried on which the printed inequality says the opposite of the
/// reference (from the edge to the bracket's end, on each side whose probe disagrees),
/// relative to the edge's size (`|edge|`, or the bracket's width where the edge is 0).
pub fn add_threshold(
    b: &Bench,
    w: &mut Worst,
    printed: &PrintedThreshold,
    reference_edge: f64,
    allowed: [bool; 2],
    at: &dyn Fn() -> String,
) {
    w.add(
        b.claim(printed.edge),
        reference_edge,
        reference_edge.abs(),
        || format!("{}: {}", printed.relation, at()),
    );
    if printed.holds != allowed {
        let (lo, hi) = printed.bracket;
        let wrong = [reference_edge - lo, hi - reference_edge];
        let length: f64 = (0..2)
            .filter(|&i| printed.holds[i] != allowed[i])
            .map(|i| wrong[i].max(0.0))
            .sum();
        let size = if reference_edge == 0.0 {
            hi - lo
        } else {
            reference_edge.abs()
        };
        w.add_error(
            b.claim(printed.edge),
            reference_edge,
            length / size,
            "",
            || {
                format!(
                    "{}: the printed inequality {} below the edge and {} above it, where the reference {} and {}: it is wrong over {:.4e} of the range [{lo:.4e}, {hi:.4e}] tried: {}",
                    printed.relation,
                    if printed.holds[0] { "holds" } else { "fails" },
                    if printed.holds[1] { "holds" } else { "fails" },
                    if allowed[0] { "allows" } else { "forbids" },
                    if allowed[1] { "allows" } else { "forbids" },
                    length,
                    at()
                )
            },
        );
    }
}
