//! The real toy for the report: the peer program's stored runs compared with this tool
//! ([`crate::peer::stored`]) and what the toy's thickness does to the paper's numbers
//! ([`crate::thickness`]), its steady motions ([`crate::toy_steady`]).

use crate::peer::stored::{compare_stored, StoredComparison};
use crate::thickness::Thickness;
use crate::toy_steady::ToySteady;
use crate::StudyError;
use serde::{Deserialize, Serialize};

/// The toy's studies.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Toy {
    /// Every stored peer run against this tool's run of its scene.
    pub peer: Vec<StoredComparison>,
    /// The toy against the thin disk.
    pub thickness: Thickness,
    /// Eqs 29-30 for the toy: its steady motions and condition on $b$.
    pub steady: ToySteady,
}

/// The three studies, side by side on rayon's threads (each is deterministic on its own, so the
/// result does not depend on the threads).
pub fn compute() -> Result<Toy, StudyError> {
    let (peer, (thickness, steady)) = rayon::join(compare_stored, || {
        rayon::join(crate::thickness::compute, crate::toy_steady::compute)
    });
    Ok(Toy {
        peer: peer.map_err(|e| StudyError::Unusable(e.to_string()))?,
        thickness: thickness?,
        steady: steady?,
    })
}
