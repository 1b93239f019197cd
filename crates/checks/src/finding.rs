//! What a check finds: the paper's claim against an independent reference, the error, the
//! tolerance and the rule it came from, and a verdict.

use serde::Serialize;
use std::fmt;

/// How the reference was obtained (DESIGN.md's table, strongest first).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Against the lab-frame Newton-Euler model.
    IndependentModel,
    /// A quantity measured on integrations of the equations of motion.
    Integration,
    /// Jacobian at an equilibrium (dual numbers) and its eigenvalues.
    Linearization,
    /// A threshold located by bisection on the outcome of integrations.
    Threshold,
    /// The claim's premises solved numerically.
    Derivation,
    /// Both sides at many random points, derivatives exact (dual numbers).
    Identity,
    /// The error of an approximation at shrinking values of its small parameter.
    Asymptotic,
    /// The drift of an invariant along an integration.
    Conservation,
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Method::IndependentModel => "independent model",
            Method::Integration => "integration",
            Method::Linearization => "linearization",
            Method::Threshold => "threshold",
            Method::Derivation => "derivation",
            Method::Identity => "identity",
            Method::Asymptotic => "asymptotic",
            Method::Conservation => "conservation",
        })
    }
}

/// The verdict on one equation or claim.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Verdict {
    /// Within tolerance over its whole domain.
    Holds,
    /// An approximation whose error falls at the claimed order as its small parameter shrinks.
    HoldsApproximately {
        /// The order fitted to the measured errors.
        measured_order: f64,
        /// The order the approximation claims.
        claimed_order: f64,
    },
    /// Outside tolerance: see the finding's `at`, `claimed`, `reference` and `error`.
    Fails,
    /// A convention, consistent with the rest of the paper.
    Definition,
    /// It would hold, but only as a consequence of a premise that another finding rejects (the
    /// finding's `premises_failing` names them): not a verdict on the paper's conclusion.
    PremiseFails,
    /// An order-of-magnitude estimate, read as the paper's data file says it is
    /// (`estimate:` in equations.yaml): its scaling (the exponent) is confirmed and its constant
    /// is within the reading's factor of the reference's, but not within the reference's own
    /// tolerance (the finding's `claimed` and `reference` say by how much).
    Estimate {
        /// The printed constant over the reference's.
        constant_ratio: f64,
        /// The factor the reading allows, either way.
        factor: f64,
    },
    /// A claim that fails and states the same fact as a numbered equation that fails too
    /// (`restates:` in claims.yaml): one fact, counted once, at the equation. The finding keeps
    /// the claim's own numbers.
    Restates {
        /// The printed number of the equation it restates.
        equation: u32,
    },
    /// A claim that fails and is a part of another claim's statement that fails too
    /// (`part_of:` in claims.yaml: the paper's "hence" drawn from the same number): one
    /// statement, counted once, at that claim. The finding keeps the part's own numbers.
    PartOf {
        /// The id of the claim it is a part of.
        claim: &'static str,
    },
    /// A number that is wrong in the unit printed beside it and right in the unit the text
    /// means ("Hz" for rad/s, "g-cm^-1-s" for g/(cm s)): a unit misprint, reported as one and
    /// never silently read in the unit meant. The finding's `at` gives both readings.
    UnitMisprint,
    /// The verdict changes under a reasonable alternative to a choice the paper leaves open
    /// (where a claim is evaluated, where a dissipative torque acts): the finding's `robustness`
    /// gives each alternative's value and verdict, the first being the reading it was made
    /// under ([`crate::robustness`]).
    DependsOn {
        /// The choice, in words.
        choice: &'static str,
    },
    /// A printed relation right up to a factor with a dimension: it drops a factor of the
    /// physics (`L = -Omega 3-hat` for $-k m a^2\Omega\hat{\mathbf 3}$), its direction right.
    /// The subject's dimensional analysis names the factor.
    DimensionalSlip,
}

impl Verdict {
    /// True for every verdict but [`Verdict::Fails`], [`Verdict::Restates`] (a failing fact
    /// counted at its equation), [`Verdict::PartOf`] (one counted at the claim of its
    /// statement), [`Verdict::UnitMisprint`], [`Verdict::DependsOn`] and
    /// [`Verdict::DimensionalSlip`].
    pub fn passes(&self) -> bool {
        !matches!(
            self,
            Verdict::Fails
                | Verdict::Restates { .. }
                | Verdict::PartOf { .. }
                | Verdict::UnitMisprint
                | Verdict::DependsOn { .. }
                | Verdict::DimensionalSlip
        )
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Verdict::Holds => write!(f, "holds"),
            Verdict::HoldsApproximately { measured_order, .. } => {
                write!(f, "holds approximately (order {measured_order:.2})")
            }
            Verdict::Fails => write!(f, "FAILS"),
            Verdict::Definition => write!(f, "definition"),
            Verdict::PremiseFails => write!(f, "holds only under a premise that fails"),
            Verdict::Estimate { constant_ratio, .. } => write!(
                f,
                "order-of-magnitude estimate (scaling confirmed; constant {constant_ratio:.3} \
                 times the reference's)"
            ),
            Verdict::UnitMisprint => write!(f, "unit misprint (right in the unit meant)"),
            Verdict::DependsOn { choice } => write!(f, "depends on {choice}"),
            Verdict::DimensionalSlip => write!(f, "dimensional slip"),
            Verdict::PartOf { claim } => {
                write!(
                    f,
                    "FAILS as a part of {claim} (one statement, counted there)"
                )
            }
            Verdict::Restates { equation } => {
                write!(
                    f,
                    "FAILS as eq {equation} does (the same fact, counted there)"
                )
            }
        }
    }
}

/// A tolerance and the rule that fixed it (never a number tuned until green).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Tolerance {
    /// The largest error accepted.
    pub value: f64,
    /// Why this value.
    pub rule: String,
}

impl Tolerance {
    /// Expressions of a few dozen floating-point operations evaluated at O(1) arguments: their
    /// relative round-off stays far below 1e-12 (about 4500 ulp) unless something is wrong.
    pub fn roundoff() -> Self {
        Self {
            value: 1e-12,
            rule: "round-off: 1e-12 relative (about 4500 ulp) for closed-form expressions".into(),
        }
    }

    /// Quantities measured on integrations at relative tolerance `rtol`: DOP853's global error
    /// over the runs used here stays within 100 x rtol, and measuring (interpolating a crossing,
    /// a period) adds no more than as much again. Below rtol 1e-12 the round-off of the
    /// thousands of steps of a run (~1e4 x 1e-16) bounds what any rtol reaches, so the rule
    /// uses max(rtol, 1e-12).
    pub fn solver(rtol: f64) -> Self {
        Self {
            value: 1e3 * rtol.max(1e-12),
            rule: format!("integration: 1000 x max(rtol, 1e-12), rtol = {rtol:e}"),
        }
    }

    /// A threshold bracketed by bisection to relative width `width`.
    pub fn bisection(width: f64) -> Self {
        Self {
            value: 2.0 * width,
            rule: format!("bisection: twice the final bracket's relative width ({width:e})"),
        }
    }

    /// Two power laws scale alike when their log-log slopes, fitted over the same window,
    /// agree within 5 % (relative): the window's small-parameter corrections move a slope by
    /// far less, and a different exponent of the forms the paper uses (1/3 against 1/2, 1/6
    /// against 1/4) by far more.
    pub fn exponent() -> Self {
        Self {
            value: 0.05,
            rule: "scaling: log-log slopes within 5 % of each other".into(),
        }
    }

    /// An approximation's fitted order must match the claimed order within 0.25 (an order fitted
    /// over two decades of the small parameter, with the next order's contamination).
    pub fn order() -> Self {
        Self {
            value: 0.25,
            rule: "asymptotic: fitted order within 0.25 of the claimed order".into(),
        }
    }
}

/// The worst disagreement seen while sweeping a check over its domain.
#[derive(Debug, Clone, PartialEq)]
pub struct Worst {
    /// Largest error seen (|claimed - reference| / scale); infinite if a value was NaN.
    pub error: f64,
    /// The claimed value there.
    pub claimed: f64,
    /// The reference value there.
    pub reference: f64,
    /// Where (a point of the domain, in words).
    pub at: String,
    /// How many points were compared.
    pub points: usize,
    /// The unit of `claimed` and `reference` there, as paper/symbols.yaml writes it (`1` for a
    /// pure number); empty when the comparison did not say.
    pub unit: String,
}

impl Default for Worst {
    fn default() -> Self {
        Self {
            error: 0.0,
            claimed: f64::NAN,
            reference: f64::NAN,
            at: String::new(),
            points: 0,
            unit: String::new(),
        }
    }
}

impl Worst {
    /// Records one comparison; `scale` turns the difference into a relative error (pass
    /// `reference.abs()` for a plain relative error, or a characteristic size of the quantity).
    pub fn add(&mut self, claimed: f64, reference: f64, scale: f64, at: impl FnOnce() -> String) {
        self.add_in(claimed, reference, scale, "", at);
    }

    /// [`Worst::add`] for values in `unit` (kept with the worst point).
    pub fn add_in(
        &mut self,
        claimed: f64,
        reference: f64,
        scale: f64,
        unit: &str,
        at: impl FnOnce() -> String,
    ) {
        let e = (claimed - reference).abs() / scale;
        self.add_error(claimed, reference, e, unit, at);
    }

    /// Records one comparison whose error is not a difference of the two values: `error` is
    /// what the comparison measured (infinite if it is not a number), `claimed` and `reference`
    /// are what it shows beside it.
    pub fn add_error(
        &mut self,
        claimed: f64,
        reference: f64,
        error: f64,
        unit: &str,
        at: impl FnOnce() -> String,
    ) {
        self.points += 1;
        let e = if error.is_finite() {
            error
        } else {
            f64::INFINITY
        };
        if e > self.error || self.points == 1 {
            self.error = e;
            self.claimed = claimed;
            self.reference = reference;
            self.at = at();
            self.unit = unit.to_string();
        }
    }
}

/// One check's result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Finding {
    /// How the reference was obtained.
    pub method: Method,
    /// What was compared, in words.
    pub compared: String,
    /// The claimed value at the worst point.
    pub claimed: f64,
    /// The reference value at the worst point.
    pub reference: f64,
    /// The unit of `claimed` and `reference` as paper/symbols.yaml writes it (`1` for a pure
    /// number; `order` when they are the claimed and fitted orders of an approximation), where
    /// the comparison knows it: the printed relations compared side by side take it from a side
    /// of the chain that is one symbol, the other checks state it ([`Finding::in_unit`]). Empty
    /// where a check does not say.
    pub unit: String,
    /// The error there (relative unless `compared` says otherwise).
    pub error: f64,
    /// The tolerance and its rule.
    pub tolerance: Tolerance,
    /// The verdict.
    pub verdict: Verdict,
    /// Where the worst error was, and over how many points.
    pub at: String,
    /// A scene or figure that shows it, if any.
    pub shown_by: Option<String>,
    /// The one comparison a reader needs, in the paper's terms (set by the checks whose
    /// `claimed` and `reference` are orders or errors rather than the quantity itself).
    pub headline: Option<Headline>,
    /// The premises (claim ids, or `eq N`) that rest under it and fail, when its verdict is
    /// [`Verdict::PremiseFails`].
    pub premises_failing: Vec<String>,
    /// The verdicts under the alternatives to the choices the paper leaves open, the reading
    /// this finding was made under first ([`crate::robustness`]); empty where the check tries
    /// none.
    pub robustness: Vec<Alternative>,
    /// The verdict the check gave on its own, before the premises it rests on were read: set
    /// when a failing premise made it [`Verdict::PremiseFails`].
    #[serde(skip)]
    pub verdict_alone: Option<Verdict>,
}

/// One comparison in the paper's terms: a named quantity, the value the paper prints (or
/// implies: said so), the true value from the reference, its unit, and where.
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Headline {
    /// What is compared, in words and the paper's symbols.
    pub quantity: String,
    /// The paper's value.
    pub paper: f64,
    /// `printed` when the paper writes the number, `implied` when it follows from what it writes.
    pub paper_is: String,
    /// The reference's value.
    pub reference: f64,
    /// The unit (`1` for a pure number).
    pub unit: String,
    /// Where (a point of the domain).
    pub at: String,
}

impl Headline {
    /// A headline for `quantity`: the paper's value (`printed` or `implied`) and the true one.
    pub fn new(
        quantity: impl Into<String>,
        paper: f64,
        paper_is: &str,
        reference: f64,
        unit: &str,
        at: impl Into<String>,
    ) -> Self {
        Self {
            quantity: quantity.into(),
            paper,
            paper_is: paper_is.into(),
            reference,
            unit: unit.into(),
            at: at.into(),
        }
    }
}

/// What a swept equation states: a relation that must hold, or a convention (a definition)
/// checked for consistency with the rest.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stated {
    /// A relation: it holds or fails.
    Relation,
    /// A definition: consistent (`Definition`) or it fails.
    Definition,
}

impl Finding {
    /// A relation's finding from a sweep: holds when the worst error is within tolerance, fails
    /// otherwise.
    pub fn from_worst(
        method: Method,
        compared: impl Into<String>,
        worst: Worst,
        tolerance: Tolerance,
    ) -> Self {
        Self::judged(method, compared, worst, tolerance, Stated::Relation)
    }

    /// A definition's finding from a sweep: `Definition` when the worst error is within
    /// tolerance, fails otherwise.
    pub fn definition(
        method: Method,
        compared: impl Into<String>,
        worst: Worst,
        tolerance: Tolerance,
    ) -> Self {
        Self::judged(method, compared, worst, tolerance, Stated::Definition)
    }

    /// A finding from a sweep of what `stated` says.
    pub fn judged(
        method: Method,
        compared: impl Into<String>,
        worst: Worst,
        tolerance: Tolerance,
        stated: Stated,
    ) -> Self {
        let ok = worst.points > 0 && worst.error <= tolerance.value;
        let verdict = match (ok, stated) {
            (false, _) => Verdict::Fails,
            (true, Stated::Definition) => Verdict::Definition,
            (true, Stated::Relation) => Verdict::Holds,
        };
        Self {
            method,
            compared: compared.into(),
            claimed: worst.claimed,
            reference: worst.reference,
            unit: worst.unit,
            error: worst.error,
            at: format!("{} (worst of {} points)", worst.at, worst.points),
            tolerance,
            verdict,
            shown_by: None,
            headline: None,
            premises_failing: Vec::new(),
            robustness: Vec::new(),
            verdict_alone: None,
        }
    }

    /// A finding for an approximation: the errors `errors[i]` measured at small-parameter values
    /// `small[i]` are fitted to a power law; it holds approximately when the fitted order is
    /// within [`Tolerance::order`] of `claimed_order` and the error at the smallest parameter is
    /// below the largest one's (it really shrinks).
    pub fn from_order(
        compared: impl Into<String>,
        small: &[f64],
        errors: &[f64],
        claimed_order: f64,
    ) -> Self {
        let measured = numerics::fit::log_log_slope(small, errors);
        let tolerance = Tolerance::order();
        let err = (measured - claimed_order).abs();
        let shrinking = errors.first().zip(errors.last()).is_some_and(|(a, b)| {
            let (first_p, last_p) = (small[0], small[small.len() - 1]);
            if last_p < first_p {
                b < a
            } else {
                a < b
            }
        });
        let ok = err.is_finite() && err <= tolerance.value && shrinking;
        let i_min = (0..small.len())
            .min_by(|&i, &j| small[i].total_cmp(&small[j]))
            .unwrap_or(0);
        Self {
            method: Method::Asymptotic,
            compared: compared.into(),
            claimed: claimed_order,
            reference: measured,
            unit: "order".into(),
            error: err,
            at: format!(
                "small parameter from {:.3e} to {:.3e}; error {:.3e} at the smallest",
                small.iter().copied().fold(f64::INFINITY, f64::min),
                small.iter().copied().fold(0.0, f64::max),
                errors.get(i_min).copied().unwrap_or(f64::NAN)
            ),
            tolerance,
            verdict: if ok {
                Verdict::HoldsApproximately {
                    measured_order: measured,
                    claimed_order,
                }
            } else {
                Verdict::Fails
            },
            shown_by: None,
            headline: None,
            premises_failing: Vec::new(),
            robustness: Vec::new(),
            verdict_alone: None,
        }
    }

    /// Sets the headline comparison.
    pub fn with_headline(mut self, h: Headline) -> Self {
        // The headline's unit is the finding's where the two compare the same values.
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits();
        if self.unit.is_empty() && same(h.paper, self.claimed) && same(h.reference, self.reference)
        {
            self.unit = h.unit.clone();
        }
        self.headline = Some(h);
        self
    }

    /// States the unit of `claimed` and `reference` (as paper/symbols.yaml writes units; `1`
    /// for a pure number), unless the comparison already recorded one.
    pub fn in_unit(mut self, unit: &str) -> Self {
        if self.unit.is_empty() {
            self.unit = unit.to_string();
        }
        self
    }

    /// Names a scene or figure that shows this finding.
    pub fn shown_by(mut self, what: impl Into<String>) -> Self {
        self.shown_by = Some(what.into());
        self
    }
}

/// One reasonable reading of a choice the paper leaves open, and the verdict under it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Alternative {
    /// The choice the paper leaves open, in words ("the point of evaluation").
    pub choice: &'static str,
    /// This reading of it, in words, with its parameters.
    pub alternative: String,
    /// The reference's value under it, in the finding's unit.
    pub reference: f64,
    /// The verdict under it.
    pub verdict: Verdict,
}

impl Alternative {
    /// An alternative reading of `choice`.
    pub fn new(
        choice: &'static str,
        alternative: impl Into<String>,
        reference: f64,
        verdict: Verdict,
    ) -> Self {
        Self {
            choice,
            alternative: alternative.into(),
            reference,
            verdict,
        }
    }
}
