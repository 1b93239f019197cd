//! The harness every check shares: what a check runs with ([`Bench`], whose
//! [`Bench::claim`] is the one door through which a claimed value is read, so that the mutation
//! sweep can move it), the comparison of a printed relation's sides at a point ([`printed`]),
//! a printed inequality read as a threshold ([`threshold`]), the worst of several order fits
//! ([`order`]) and the disk's constants under the paper's names ([`bindings`]).
//!
//! The harness knows no check and no registry: the checks import it, never the other way.

pub mod bench;
pub mod bindings;
pub mod order;
pub mod printed;
pub mod threshold;

pub use bench::{built_in_paper, Bench};
pub use bindings::disk_constants;
pub use order::worst_order;
pub use printed::{
    implied_square, last_side, printed_relation, printed_relations, solve_printed,
    solve_printed_with, term_scale,
};
pub use threshold::{add_threshold, printed_threshold, PrintedThreshold};
