//! Eq 79's three parameters as every fit of it states them, whatever it was fitted to (the light's
//! $1/\Omega$ by eq 84, the sound's pitch track, the sound's phase): $\beta$, $t_0$ and $\ln C$
//! in $\Omega = (C/(t_0 - t))^{1/(\beta+2)}$, each with its standard uncertainty.

use crate::fit::least_squares::Solved;
use serde::Serialize;

/// $\beta$, $t_0$ and $\ln C$ of eq 79 with their standard uncertainties.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LawFit {
    /// $\beta$.
    pub beta: f64,
    /// Its standard uncertainty.
    pub beta_sigma: f64,
    /// $t_0$ (s).
    pub t0: f64,
    /// Its standard uncertainty (s).
    pub t0_sigma: f64,
    /// $\ln C$ ($C$ in $s^{-(\beta+1)}$ for eq 84's $1/\Omega$; the law's own units otherwise).
    pub ln_c: f64,
    /// Its standard uncertainty.
    pub ln_c_sigma: f64,
}

impl LawFit {
    /// The parameters $(\beta, t_0, \ln C)$ of a solved fit, its first three (a phase's fit
    /// adds its phase offset after them), with the square roots of their variances.
    pub fn of<const P: usize>(s: &Solved<P>) -> Self {
        const { assert!(P >= 3, "eq 79 has three parameters") };
        LawFit {
            beta: s.p[0],
            beta_sigma: s.cov[(0, 0)].sqrt(),
            t0: s.p[1],
            t0_sigma: s.cov[(1, 1)].sqrt(),
            ln_c: s.p[2],
            ln_c_sigma: s.cov[(2, 2)].sqrt(),
        }
    }
}

/// A fit that carries eq 79's parameters reads them as its own fields (`fit.beta`), through
/// this.
macro_rules! reads_law_fit {
    ($fit:ty) => {
        impl std::ops::Deref for $fit {
            type Target = $crate::fit::law_fit::LawFit;
            fn deref(&self) -> &Self::Target {
                &self.parameters
            }
        }
        impl std::ops::DerefMut for $fit {
            fn deref_mut(&mut self) -> &mut Self::Target {
                &mut self.parameters
            }
        }
    };
}
pub(crate) use reads_law_fit;
