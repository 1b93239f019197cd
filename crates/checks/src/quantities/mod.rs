//! The catalogue of quantities the tool computes, each named, with its parameters, unit, method
//! and tolerance rule (`rolling-disk quantities` lists them). A claim of claims.yaml that names
//! one (`quantity: { name: vertical-spin-threshold, contact: frictionless, k: 0.25 }`) is checked
//! with no Rust written for it: the quantity is computed at the claim's parameters and judged
//! against the printed number by the claim's `rule`, or, without one, by the quantity's own
//! tolerance ([`crate::equations::claims::catalogued`]).
//!
//! Every quantity is computed from the references alone (the rolling and frictionless models'
//! equations of motion, their exact Jacobians, bisection): never from a printed formula, so a
//! claim that restates a formula of the paper is compared with something independent of it.
//! All are for the dimensionless disk $a = g = m = 1$: rates in $\sqrt{g/a}$, forces in $mg$.
//!
//! One family a file: [`threshold`] (spinning about a vertical diameter), [`steady`] (steady
//! motion and the friction it needs), [`oscillation`] (small oscillations about it),
//! [`contact`] (the least contact force over a run with eq 75's drag), [`order`] (the order of
//! a printed approximation against one of the others).

mod contact;
mod order;
mod oscillation;
mod steady;
mod threshold;
mod validate;

use crate::finding::{Method, Tolerance};
use crate::harness::Bench;
pub use contact::{least_contact_force, LeastContact};
pub use validate::{of_claim, validate};

/// A quantity of the catalogue.
#[derive(Debug, Clone, Copy)]
pub struct Quantity {
    /// Its name, as a claim gives it.
    pub name: &'static str,
    /// What it is, in words.
    pub means: &'static str,
    /// Its unit (a claim naming it must print its number in this unit).
    pub unit: &'static str,
    /// The method of its reference.
    pub method: Method,
    /// How it is computed, in words.
    pub how: &'static str,
    /// The tolerance its method allows when a claim gives no `rule`, on the check's bench.
    pub tolerance: fn(&Bench) -> Tolerance,
    /// Its parameters.
    pub parameters: &'static [Parameter],
    /// Computes it at the given parameters (every one given and in its range, [`validate`]),
    /// reading the paper and the solver's settings from the check's bench.
    pub compute: fn(&Values, &Bench) -> Computed,
}

/// A parameter of a quantity.
#[derive(Debug, Clone, Copy)]
pub struct Parameter {
    /// Its name, as a claim gives it.
    pub name: &'static str,
    /// What it is, in words.
    pub means: &'static str,
    /// Its values: numbers in a range, or one of some words.
    pub kind: Kind,
    /// Its value when a claim leaves it out; `None` when a claim must give it.
    pub default: Option<Value>,
}

/// The values a parameter takes.
#[derive(Debug, Clone, Copy)]
pub enum Kind {
    /// A number strictly between `above` and `below`, in `unit` (a whole number where `whole`).
    Number {
        /// Its unit.
        unit: &'static str,
        /// The open interval's lower end.
        above: f64,
        /// Its upper end.
        below: f64,
        /// Whether only whole numbers are values (an equation's number).
        whole: bool,
    },
    /// One of these words.
    Choice(&'static [&'static str]),
}

/// A parameter's value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// A number.
    Number(f64),
    /// A word of a [`Kind::Choice`].
    Word(&'static str),
}

impl std::fmt::Display for Value {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Value::Number(x) => write!(f, "{x}"),
            Value::Word(w) => f.write_str(w),
        }
    }
}

/// A quantity's parameters, every one with its value (given or default), in the catalogue's
/// order.
#[derive(Debug, Clone, PartialEq)]
pub struct Values(pub Vec<(&'static str, Value)>);

impl Values {
    /// The number `name` (0 where the catalogue has no such number: [`validate`] lets none
    /// through).
    pub fn number(&self, name: &str) -> f64 {
        self.0
            .iter()
            .find_map(|(n, v)| match v {
                Value::Number(x) if *n == name => Some(*x),
                _ => None,
            })
            .unwrap_or(0.0)
    }

    /// The word `name` ("" where none).
    pub fn word(&self, name: &str) -> &'static str {
        self.0
            .iter()
            .find_map(|(n, v)| match v {
                Value::Word(w) if *n == name => Some(*w),
                _ => None,
            })
            .unwrap_or("")
    }

    /// "k = 0.25, contact = rolling", for messages.
    pub fn describe(&self) -> String {
        self.0
            .iter()
            .map(|(n, v)| format!("{n} = {v}"))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// A quantity computed: its value (NaN where its reference could not be located), and where
/// and how it was found.
#[derive(Debug, Clone)]
pub struct Computed {
    /// The value, in the quantity's unit.
    pub value: f64,
    /// Where and how, for the finding.
    pub at: String,
    /// For an order: the small parameter's values and the errors there, which
    /// [`crate::finding::Finding::from_order`] fits and judges.
    pub series: Option<(Vec<f64>, Vec<f64>)>,
}

impl Computed {
    /// A value, and where and how it was found.
    pub fn value(value: f64, at: String) -> Self {
        Self {
            value,
            at,
            series: None,
        }
    }
}

/// Every quantity of the catalogue.
pub const QUANTITIES: &[Quantity] = &[
    threshold::VERTICAL_SPIN_THRESHOLD,
    steady::STEADY_PRECESSION_RATE,
    steady::FRICTION_NEEDED,
    oscillation::NUTATION_FREQUENCY,
    oscillation::NUTATION_RATIO,
    contact::LEAST_CONTACT_FORCE,
    order::APPROXIMATION_ORDER,
];

/// The quantity named `name`, if the catalogue has it.
pub fn find(name: &str) -> Option<&'static Quantity> {
    QUANTITIES.iter().find(|q| q.name == name)
}

/// The inertia factor $k$ (eq 18), a parameter of most quantities.
const K: Parameter = Parameter {
    name: "k",
    means: "the inertia factor k of eq 18 (1/4 for a uniform disk, 1/2 for a hoop)",
    kind: Kind::Number {
        unit: "1",
        above: 0.0,
        below: 10.0,
        whole: false,
    },
    default: None,
};

/// The tilt $\alpha_0$ of a steady motion.
const ALPHA0: Parameter = Parameter {
    name: "alpha0",
    means: "the tilt alpha_0 of the steady motion, between the disk's plane and the table",
    kind: Kind::Number {
        unit: "rad",
        above: 0.0,
        below: std::f64::consts::FRAC_PI_2,
        whole: false,
    },
    default: None,
};

/// The radius $b/a$ of the centre of mass's circle (eq 28).
const B_OVER_A: Parameter = Parameter {
    name: "b_over_a",
    means: "b/a, the radius of the centre of mass's circle over the disk's radius (0: the \
            centre of mass at rest)",
    kind: Kind::Number {
        unit: "1",
        above: -1.0,
        below: 100.0,
        whole: false,
    },
    default: Some(Value::Number(0.0)),
};

#[cfg(test)]
mod tests;
