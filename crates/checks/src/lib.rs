//! The checks: each of the paper's equations and numeric claims compared with a reference that
//! does not use it (the registry [`equations`], run by [`check`]; the [`harness`] they share),
//! the verdicts ([`finding`]), root causes against inherited failures ([`cause`]), verdicts that
//! agree with their premises (`agreement`), the verdicts under the choices the paper leaves
//! open ([`robustness`], under a looser reading of every rule: `readings`), the mutation suite ([`mutation`]), the corrected forms ([`corrections`]) and the selection of what to check ([`select`]).

mod agreement;
mod card_parameters;
pub mod cause;
pub mod check;
pub mod checked;
pub mod corrections;
pub mod dimensions;
pub mod equations;
pub mod finding;
pub mod harness;
pub mod mutation;
pub mod quantities;
mod readings;
pub mod robustness;
pub mod select;
mod tally;
