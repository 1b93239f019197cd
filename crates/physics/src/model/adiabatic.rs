//! The paper's one-state spin-down law, eq 76:
//! $$\dot\alpha = -\frac{2\epsilon}{5}\Omega^\beta \approx -\frac{2\epsilon}{5}\left(\frac{g}{ak}\right)^{\beta/2}\frac{1}{\alpha^{\beta/2}}$$
//!
//! It rests on the small-angle energy of eq 72, the power balance of eq 73 and the steady
//! precession $\Omega^2 \approx g/ak\alpha$ of eq 31. It is a CLAIM of the paper: it is integrated
//! here so that it can be compared with the full dissipative model, never used as a reference.

use crate::disk::Disk;
use crate::model::dissipation::PowerLaw;
use crate::model::rolling::record_common;
use crate::model::{Extras, Layout, Model, Motion, Quantity};
use crate::solve::{Dynamics, State};

/// Eq 76's law: a single state, $\alpha$.
#[derive(Debug, Clone)]
pub struct Adiabatic {
    /// The disk.
    pub disk: Disk,
    /// The dissipation law of eq 75.
    pub law: PowerLaw,
    layout: Layout,
}

impl Adiabatic {
    /// The law for this disk and dissipation.
    pub fn new(disk: Disk, law: PowerLaw) -> Self {
        Self {
            disk,
            law,
            layout: Layout::new(1, Extras::default()),
        }
    }

    /// $\Omega$ from eq 31 in its small-angle form used by eq 76, $\Omega^2 = g / a k \alpha$.
    pub fn precession(&self, alpha: f64) -> f64 {
        (self.disk.g / (self.disk.a * self.disk.k * alpha)).sqrt()
    }

    /// Eq 76's right-hand side, $-\frac{2\epsilon}{5}\Omega^\beta$ with $\Omega$ from eq 31.
    pub fn alpha_dot(&self, alpha: f64) -> f64 {
        -0.4 * self.law.epsilon * self.precession(alpha).powf(self.law.beta)
    }
}

impl Dynamics<1> for Adiabatic {
    fn rhs(&self, y: &State<1>, dy: &mut State<1>) {
        dy[0] = self.alpha_dot(y[0]);
    }
}

impl Model<1> for Adiabatic {
    fn layout(&self) -> &Layout {
        &self.layout
    }

    fn motion(&self, y: &State<1>) -> Motion {
        Motion {
            alpha: y[0],
            alpha_dot: self.alpha_dot(y[0]),
            precession: self.precession(y[0]),
            spin: 0.0,
        }
    }

    /// Eq 72's small-angle energy, $\frac12 m a^2\dot\alpha^2 + \frac32 m a g\alpha$.
    fn energy(&self, y: &State<1>) -> f64 {
        let d = &self.disk;
        let ad = self.alpha_dot(y[0]);
        0.5 * d.m * d.a * d.a * ad * ad + 1.5 * d.m * d.a * d.g * y[0]
    }

    fn record(&self, y: &State<1>, q: Quantity, out: &mut Vec<f64>) -> bool {
        match q {
            Quantity::Energy => {
                out.push(self.energy(y));
                true
            }
            _ => record_common(&self.layout, &self.motion(y), y, q, out),
        }
    }

    fn state(&self, m: &Motion) -> State<1> {
        State::<1>::new(m.alpha)
    }
}
