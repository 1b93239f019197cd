//! The paper's own numbers of section 11, recomputed from its fitted constants
//! ($\beta = 2$, $C^{-1/4} = 0.0055$ s, $k = 1/4$). The paper's "Hz" are rad/s
//! ($\Omega_i = 2\pi/\Delta t$).
//!
//! - **One period left.** With eq 79, $t_0 - t = 2\pi/\Omega$ when
//!   $\Omega^{\beta+2} = C\Omega/2\pi$, i.e. $\Omega_1 = (C/2\pi)^{1/(\beta+1)}$
//!   ($= (C/2\pi)^{1/3}$ for $\beta = 2$); the paper: 560 "Hz" and 0.011 s.
//! - **Loss of contact** (eqs 80-81):
//!   $\Omega_{max} = \left(\frac{k(\beta+2)^2}{2\beta}\right)^{1/2(\beta+1)} C^{1/(\beta+1)}$ at
//!   $t_0 - t_{max} = \left(\frac{2\beta}{k(\beta+2)^2}\right)^{(\beta+2)/2(\beta+1)} C^{-1/(\beta+1)}$;
//!   for $\beta = 2$, $k = 1/4$ the bracket is 1: $C^{1/3}$ = 1030 "Hz" and $C^{-1/3}$ = 0.001 s.
//! - **Exponents.** $\Omega \propto (t_0 - t)^{-1/(\beta+2)}$ (eq 79) and
//!   $d\Omega/dt \propto \Omega^{\beta+3}$ (eq 85): -1/4 for rolling friction ($\beta = 2$),
//!   -1/6 for Moffatt's air film ($\beta = 4$, eq 83).

use serde::Serialize;
use std::f64::consts::PI;
use std::fmt;

/// One model of friction's exponents.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Exponents {
    /// What it is.
    pub model: String,
    /// $\beta$.
    pub beta: f64,
    /// The exponent of $\Omega \propto (t_0 - t)^{e}$: $-1/(\beta+2)$.
    pub omega_vs_time: f64,
    /// The slope of $\log(d\Omega/dt)$ against $\log\Omega$: $\beta + 3$.
    pub omega_dot_slope: f64,
}

/// The numbers of section 11 recomputed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PaperNumbers {
    /// $\beta$ used.
    pub beta: f64,
    /// $k$ used.
    pub k: f64,
    /// The fitted $C^{-1/(\beta+2)}$ (s).
    pub c_inv_root: f64,
    /// $C$ (s^-(beta+1)).
    pub c: f64,
    /// $\Omega$ when one period remains (rad/s); the paper: 560.
    pub omega_one_period: f64,
    /// That period, $2\pi/\Omega$ (s); the paper: 0.011.
    pub time_one_period: f64,
    /// $\Omega_{max}$ at loss of contact, eq 80 (rad/s); the paper: 1030.
    pub omega_lift_off: f64,
    /// $t_0 - t_{max}$, eq 81 (s); the paper: 0.001.
    pub time_lift_off: f64,
    /// The exponents of the models of friction.
    pub exponents: Vec<Exponents>,
}

/// $\Omega$ when one period remains: $(C/2\pi)^{1/(\beta+1)}$.
pub fn omega_one_period(c: f64, beta: f64) -> f64 {
    (c / (2.0 * PI)).powf(1.0 / (beta + 1.0))
}

/// Eq 80: $\Omega_{max}$ at loss of contact.
pub fn omega_lift_off(c: f64, beta: f64, k: f64) -> f64 {
    (k * (beta + 2.0).powi(2) / (2.0 * beta)).powf(1.0 / (2.0 * (beta + 1.0)))
        * c.powf(1.0 / (beta + 1.0))
}

/// Eq 81: $t_0 - t_{max}$ at loss of contact.
pub fn time_lift_off(c: f64, beta: f64, k: f64) -> f64 {
    (2.0 * beta / (k * (beta + 2.0).powi(2))).powf((beta + 2.0) / (2.0 * (beta + 1.0)))
        * c.powf(-1.0 / (beta + 1.0))
}

/// The numbers for a fit $(\beta, C^{-1/(\beta+2)})$ and inertia factor $k$.
pub fn numbers(beta: f64, c_inv_root: f64, k: f64) -> PaperNumbers {
    let c = c_inv_root.powf(-(beta + 2.0));
    let om1 = omega_one_period(c, beta);
    let models = [
        ("rolling friction, force independent of speed (eq 74)", 0.0),
        ("power proportional to Omega (eq 73)", 1.0),
        ("rolling friction proportional to contact speed", 2.0),
        ("Moffatt's revised air film", 2.5),
        ("air drag, force as speed squared", 3.0),
        ("Moffatt's air film (eqs 82-83)", 4.0),
    ];
    PaperNumbers {
        beta,
        k,
        c_inv_root,
        c,
        omega_one_period: om1,
        time_one_period: 2.0 * PI / om1,
        omega_lift_off: omega_lift_off(c, beta, k),
        time_lift_off: time_lift_off(c, beta, k),
        exponents: models
            .iter()
            .map(|(m, b)| Exponents {
                model: (*m).into(),
                beta: *b,
                omega_vs_time: -1.0 / (b + 2.0),
                omega_dot_slope: b + 3.0,
            })
            .collect(),
    }
}

impl fmt::Display for PaperNumbers {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "section 11 from beta = {}, C^(-1/(beta+2)) = {} s, k = {} (C = {:.4e}); \"Hz\" are rad/s",
            self.beta, self.c_inv_root, self.k, self.c
        )?;
        writeln!(
            f,
            "  one period left: Omega = {:.0} rad/s, t0 - t = {:.4} s   (paper: 560, 0.011)",
            self.omega_one_period, self.time_one_period
        )?;
        writeln!(
            f,
            "  loss of contact (eqs 80-81): Omega = {:.0} rad/s, t0 - t = {:.5} s   (paper: 1030, 0.001)",
            self.omega_lift_off, self.time_lift_off
        )?;
        for e in &self.exponents {
            writeln!(
                f,
                "  beta = {:<3}: Omega ~ (t0 - t)^({:.4}), dOmega/dt ~ Omega^{}   {}",
                e.beta, e.omega_vs_time, e.omega_dot_slope, e.model
            )?;
        }
        Ok(())
    }
}
