//! Checks of the numeric and qualitative claims in the paper's prose (`paper/claims.yaml`).

use super::Claim;

/// The claim checks.
pub const CLAIMS: &[Claim] = &[];
