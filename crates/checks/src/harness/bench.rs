//! What a check runs with: the paper whose claims it reads, the perturbation the mutation sweep
//! applies to every claimed value, and the solver's settings.

use paper::Paper;
use physics::solve::{Method, Settings};
use std::sync::OnceLock;

/// The paper compiled into the binary, read once. Its three files are checked by the tests, so
/// failing to read them is a defect of this build, not of any input.
pub fn built_in_paper() -> &'static Paper {
    static PAPER: OnceLock<Paper> = OnceLock::new();
    PAPER.get_or_init(|| match Paper::built_in() {
        Ok(p) => p,
        Err(e) => panic!("the built-in paper does not read (a defect of this build): {e}"),
    })
}

/// What a check runs with.
#[derive(Debug, Clone, Copy)]
pub struct Bench<'p> {
    /// The paper whose claims are checked: the built-in one, or one read with `--paper DIR`.
    pub paper: &'p Paper,
    /// Relative perturbation applied to every claimed value (0 in normal runs, 1e-3 in the
    /// mutation test).
    pub perturbation: f64,
    /// The solver's relative tolerance for integrations.
    pub rtol: f64,
    /// The integration method (the `--accuracy` preset's; DOP853 by default).
    pub method: Method,
}

impl Default for Bench<'static> {
    fn default() -> Self {
        Self {
            paper: built_in_paper(),
            perturbation: 0.0,
            rtol: 1e-12,
            method: Method::Dop853,
        }
    }
}

impl<'p> Bench<'p> {
    /// The default bench on another paper.
    pub fn with_paper(paper: &'p Paper) -> Self {
        Self {
            paper,
            ..Bench::default()
        }
    }

    /// The same bench with the claimed side perturbed by relative `p`.
    pub fn perturbed(p: f64) -> Bench<'static> {
        Bench {
            perturbation: p,
            ..Bench::default()
        }
    }

    /// A claimed value, as the check must see it: multiplied by (1 + perturbation). For an
    /// inequality, pass its bound.
    pub fn claim(&self, x: f64) -> f64 {
        x * (1.0 + self.perturbation)
    }

    /// The same bench with integrations at least as accurate as rtol `finest`, for a check that
    /// cannot resolve its claim otherwise (a residual's order of convergence, a growth test
    /// under bisection), whatever accuracy preset the user chose.
    pub fn resolving(&self, finest: f64) -> Self {
        Self {
            rtol: self.rtol.min(finest),
            // A tolerance tightened past the preset's is the high-order method's job.
            method: if finest < self.rtol {
                Method::Dop853
            } else {
                self.method
            },
            ..*self
        }
    }

    /// Solver settings for the integrations of a check: this bench's method and rtol, atol =
    /// 1e-2 rtol (the presets' rule).
    pub fn settings(&self) -> Settings {
        Settings {
            method: self.method,
            rtol: self.rtol,
            atol: self.rtol * 1e-2,
            ..Settings::default()
        }
    }
}
