//! The physical ranges a scene may ask for, and why.
//!
//! Each bound leaves six or more decades around the paper's disks (a coin of a = 12 mm, the
//! Euler's Disk of a = 37.5 mm, m = 0.4 kg) while keeping every product the models form far
//! from overflow and underflow: the energy $m g a$, the rates $\sqrt{g/a}$ and the squares
//! $a^2\Omega^2$ of eqs 23-25. Outside them the arithmetic can still return numbers (a radius of
//! 1e308 reported an energy drift of exactly 0), but not meaningful ones, so a scene is refused
//! with the range and the reason instead.

/// A supported range of one scene value.
#[derive(Debug, Clone, Copy)]
pub struct Range {
    /// The key path in the scene.
    pub key: &'static [&'static str],
    /// Smallest value (inclusive).
    pub min: f64,
    /// Largest value (inclusive).
    pub max: f64,
    /// The unit, for messages.
    pub unit: &'static str,
    /// Why the range.
    pub why: &'static str,
}

impl Range {
    /// The range `bounds` (smallest, largest, both inclusive) of the value at `key`, in `unit`,
    /// and why.
    pub const fn new(
        key: &'static [&'static str],
        bounds: (f64, f64),
        unit: &'static str,
        why: &'static str,
    ) -> Self {
        Range {
            key,
            min: bounds.0,
            max: bounds.1,
            unit,
            why,
        }
    }

    /// `None` when `x` lies in the range, else the sentence to show.
    pub fn refuse(&self, x: f64) -> Option<String> {
        if x.is_finite() && x >= self.min && x <= self.max {
            return None;
        }
        Some(super::message::compact_numbers(&format!(
            "{} = {x} is outside the supported range {:e} to {:e}{}: {}",
            self.key.join("."),
            self.min,
            self.max,
            self.unit,
            self.why
        )))
    }
}

/// The disk's radius $a$.
#[rustfmt::skip]
pub const RADIUS: Range = Range::new(&["disk", "radius"], (1e-6, 1e3), " m",
    "from a micron to a kilometre keeps g/a and m g a well inside double precision");

/// The disk's mass $m$.
#[rustfmt::skip]
pub const MASS: Range = Range::new(&["disk", "mass"], (1e-9, 1e9), " kg",
    "beyond, energies and forces leave the range where the tolerances were designed");

/// Gravity $g$.
#[rustfmt::skip]
pub const GRAVITY: Range = Range::new(&["disk", "g"], (1e-3, 1e4), " m/s^2",
    "from a small asteroid to a thousand Earths; the time scale sqrt(a/g) sets every step");

/// The inertia factor $k$ of eq 18.
#[rustfmt::skip]
pub const INERTIA_FACTOR: Range = Range::new(&["disk", "k"], (1e-6, 1.0), "",
    "a thin body has k <= 1/2 (I_11 = 2 k m a^2 is at most m a^2, a hoop), and up to 1 is accepted for numerical studies; 1/4 is a uniform disk");

/// Largest starting rate, in units of the disk's natural rate $\sqrt{g/a}$.
pub const MAX_RATE_IN_NATURAL_UNITS: f64 = 1e6;

/// The refusal, if any, of a starting rate `w` (rad/s) of the disk `a`, `g`, named `key`.
pub fn refuse_rate(key: &str, w: f64, a: f64, g: f64) -> Option<String> {
    let limit = MAX_RATE_IN_NATURAL_UNITS * (g / a).sqrt();
    if w.is_finite() && w.abs() <= limit {
        return None;
    }
    Some(format!(
        "start: {key} = {w} rad/s is beyond the supported {limit:.3e} rad/s (a million times \
         sqrt(g/a)): the motion would change on time scales below a microsecond of the natural \
         period, where the step sizes lose their meaning"
    ))
}

/// The refusal, if any, of a starting slip speed `v` (m/s) of the disk `a`, `g`, named `key`:
/// the same bound as [`refuse_rate`]'s, in the natural speed $\sqrt{g a}$.
pub fn refuse_slip(key: &str, v: f64, a: f64, g: f64) -> Option<String> {
    let limit = MAX_RATE_IN_NATURAL_UNITS * (g * a).sqrt();
    if v.is_finite() && v.abs() <= limit {
        return None;
    }
    Some(format!(
        "start: slip {key} = {v} m/s is beyond the supported {limit:.3e} m/s (a million times \
         sqrt(g a)): the contact would change on time scales below a microsecond of the natural \
         period, where the step sizes lose their meaning"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_papers_disks_lie_inside_and_absurd_ones_outside() {
        assert!(RADIUS.refuse(0.0375).is_none());
        assert!(RADIUS.refuse(0.01213).is_none());
        assert!(MASS.refuse(0.00567).is_none());
        assert!(GRAVITY.refuse(9.81).is_none());
        assert!(INERTIA_FACTOR.refuse(0.25).is_none());
        assert!(INERTIA_FACTOR.refuse(0.5).is_none());
        let m = RADIUS.refuse(1e308).unwrap_or_default();
        assert!(m.starts_with("disk.radius = 1e308 is outside"), "{m}");
        assert!(INERTIA_FACTOR.refuse(1.5).is_some());
        assert!(MASS.refuse(f64::NAN).is_some());
        assert!(refuse_rate("spin", 100.0, 0.0375, 9.81).is_none());
        assert!(refuse_rate("spin", 1e300, 0.0375, 9.81).is_some());
        assert!(refuse_slip("forward", 0.5, 0.0375, 9.81).is_none());
        let m = refuse_slip("forward", 1e6, 0.0375, 9.81).unwrap_or_default();
        assert!(m.contains("beyond the supported 6.065e5 m/s"), "{m}");
    }
}
