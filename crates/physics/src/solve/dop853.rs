//! The crate's own DOP853 stepper: Dormand and Prince's explicit Runge-Kutta pair of order
//! 8(5,3) with the error control, step-size controller, first-step guess, stiffness test and
//! dense output of order 7 that Hairer published with his `dop853` (Hairer, Norsett and Wanner,
//! *Solving Ordinary Differential Equations I*, 2nd ed., sections II.4, II.6 and II.10).
//!
//! Written here rather than taken from `ode_solvers` 0.6.2 because that crate, with the same
//! tableau, spends about twice the solver overhead per evaluation (it clones and allocates state
//! vectors inside the step), has no dense output without evaluating it on every step, and sets
//! the nodes $c_{12}, c_{13}$ to 0. The algorithm below follows the published description; the
//! code is this crate's own. Every system here is autonomous ([`Dynamics`]), so no node enters
//! the right-hand side.
//!
//! One step from $(t, y)$ with step $h$ forms the stages
//! $k_i = f\big(y + h \sum_{j<i} a_{ij} k_j\big)$, $i = 1..12$, the 8th-order solution
//! $y_1 = y + h \sum_i b_i k_i$ and two error estimates: the 5th-order one
//! $e_5 = h \sum_i e_i k_i$ and the 3rd-order one $e_3 = h (\sum_i b_i k_i - \hat b_1 k_1 -
//! \hat b_9 k_9 - \hat b_{12} k_{12})$. With $s_i = \mathrm{atol} + \mathrm{rtol}\,\max(|y_i|,
//! |y_{1,i}|)$, $E_5 = \sum_i (e_{5,i}/s_i)^2$ and $E_3 = \sum_i (e_{3,i}/s_i)^2$ the error is
//! $$\mathrm{err} = \frac{E_5}{\sqrt{n (E_5 + 0.01 E_3)}},$$
//! an estimate of order 8 that behaves like the 5th-order one at large steps. The next step is
//! $h / \max(1/6, \min(1/0.333, \mathrm{err}^{1/8} / 0.9))$; after a rejection the step may not
//! grow. The first step is Hairer's guess from $f(y_0)$ and one explicit Euler step.

pub(super) use super::dense::Dense;
use super::tableau::*;
use super::{Dynamics, State, Stats};

/// A step-size controller's constants, as Hairer's codes set them by default.
#[derive(Debug, Clone, Copy)]
pub(super) struct StepControl {
    /// Safety factor on the step the error estimate allows.
    pub(super) safety: f64,
    /// Exponent of the previous step's error in the stabilized (PI) controller; 0 for none.
    pub(super) beta: f64,
    /// The new step is at least this fraction of the old one ...
    pub(super) fac_min: f64,
    /// ... and at most this multiple.
    pub(super) fac_max: f64,
}

/// DOP853's controller (no stabilization).
pub(super) const CONTROL: StepControl = StepControl {
    safety: 0.9,
    beta: 0.0,
    fac_min: 0.333,
    fac_max: 6.0,
};
/// Accepted steps between two stiffness tests (the test then runs on every step while it fires).
const STIFF_EVERY: u64 = 1000;
/// $|h \lambda|$ above which a step counts as stiff: the boundary of DOP853's stability region
/// along the negative real axis is near 6.1.
const STIFF_BOUND: f64 = 6.1;
/// Consecutive stiff steps that end the run.
const STIFF_COUNT: u32 = 15;

/// How a call to [`Dop853::step`] ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Outcome {
    /// One step was accepted; [`Dop853::t`] and [`Dop853::y`] moved to its end.
    Accepted,
    /// The step fell below what floating point resolves at the current time.
    Collapse,
    /// The stiffness test fired [`STIFF_COUNT`] times in a row.
    Stiff,
}

/// `y + h * sum(c_j k_j)`, component by component, in the order Hairer's code sums.
#[inline(always)]
fn combine<const N: usize, const M: usize>(
    y: &State<N>,
    h: f64,
    terms: [(f64, &State<N>); M],
) -> State<N> {
    let mut out = *y;
    for i in 0..N {
        let mut s = 0.0;
        for (c, k) in &terms {
            s += c * k[i];
        }
        out[i] += h * s;
    }
    out
}

/// The DOP853 integrator's state between steps.
pub(super) struct Dop853<'a, D, const N: usize> {
    f: &'a D,
    rtol: f64,
    atol: f64,
    h_max: f64,
    /// Current time.
    pub(super) t: f64,
    /// Current state.
    pub(super) y: State<N>,
    /// Start of the last accepted step and the state there.
    t_old: f64,
    y_old: State<N>,
    /// The last accepted step.
    h_old: f64,
    /// The step to try next.
    h: f64,
    /// Stages 1..13 of the last step (stage 13 is $f$ at its end, the next step's stage 1).
    k: [State<N>; 13],
    /// Stage 13 of the last accepted step still waits to become stage 1.
    fresh: bool,
    /// The last step tried was rejected: the next accepted one may not grow.
    reject: bool,
    stiff_hits: u32,
    stiff_misses: u32,
    /// Work done.
    pub(super) stats: Stats,
}

impl<'a, D: Dynamics<N>, const N: usize> Dop853<'a, D, N> {
    /// Starts at `(t0, y0)` with the first step guessed from the problem (2 evaluations), steps
    /// never longer than `h_max`.
    pub(super) fn new(f: &'a D, rtol: f64, atol: f64, t0: f64, y0: State<N>, h_max: f64) -> Self {
        let mut s = Self::starting(f, rtol, atol, t0, y0, h_max);
        s.stats.evaluations += 1;
        s.h = s.first_step();
        s
    }

    /// Starts at `(t0, y0)` trying `h_max` as the first step (1 evaluation).
    pub(super) fn with_first_step(
        f: &'a D,
        rtol: f64,
        atol: f64,
        t0: f64,
        y0: State<N>,
        h_max: f64,
    ) -> Self {
        let mut s = Self::starting(f, rtol, atol, t0, y0, h_max);
        s.h = h_max;
        s
    }

    fn starting(f: &'a D, rtol: f64, atol: f64, t0: f64, y0: State<N>, h_max: f64) -> Self {
        let mut k = [State::<N>::zeros(); 13];
        f.rhs(&y0, &mut k[0]);
        Self {
            f,
            rtol,
            atol,
            h_max: h_max.abs(),
            t: t0,
            y: y0,
            t_old: t0,
            y_old: y0,
            h_old: 0.0,
            h: 0.0,
            k,
            fresh: false,
            reject: false,
            stiff_hits: 0,
            stiff_misses: 0,
            stats: Stats {
                evaluations: 1,
                ..Stats::default()
            },
        }
    }

    /// Hairer's first-step guess: $h_0 = 0.01 \|y_0\| / \|f(y_0)\|$, then an explicit Euler step
    /// estimates the second derivative and $h = \min(100 h_0, (0.01 / \max(\|f_0\|,
    /// \|f'\|))^{1/8}, h_{\max})$, norms weighted by $\mathrm{atol} + \mathrm{rtol}|y_0|$.
    fn first_step(&self) -> f64 {
        let (y, f0) = (&self.y, &self.k[0]);
        let (mut dnf, mut dny) = (0.0, 0.0);
        for i in 0..N {
            let sk = self.atol + self.rtol * y[i].abs();
            dnf += (f0[i] / sk).powi(2);
            dny += (y[i] / sk).powi(2);
        }
        let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
            1e-6
        } else {
            (dny / dnf).sqrt() * 0.01
        };
        h = h.min(self.h_max);
        let y1 = y + f0 * h;
        let mut f1 = State::<N>::zeros();
        self.f.rhs(&y1, &mut f1);
        let mut der2 = 0.0;
        for i in 0..N {
            let sk = self.atol + self.rtol * y[i].abs();
            der2 += ((f1[i] - f0[i]) / sk).powi(2);
        }
        let der2 = der2.sqrt() / h;
        let der12 = der2.abs().max(dnf.sqrt());
        let h1 = if der12 <= 1e-15 {
            (h * 1e-3).max(1e-6)
        } else {
            (0.01 / der12).powf(1.0 / 8.0)
        };
        (100.0 * h).min(h1).min(self.h_max)
    }

    /// Takes one accepted step towards `t_end` (never beyond it), rejecting and retrying as the
    /// error control asks.
    pub(super) fn step(&mut self, t_end: f64) -> Outcome {
        if self.fresh {
            // Stage 1 of this step is stage 13 of the last accepted one (kept until now for
            // the dense output of that step).
            self.k[0] = self.k[12];
            self.fresh = false;
        }
        loop {
            if 0.1 * self.h.abs() <= f64::EPSILON * self.t.abs() || self.h <= 0.0 {
                return Outcome::Collapse;
            }
            let mut h = self.h;
            if self.t + 1.01 * h - t_end > 0.0 {
                h = t_end - self.t;
            }
            let (err, y_new, y12) = self.stages(h);
            let fac11 = if err.is_nan() {
                f64::INFINITY
            } else {
                // err^(1/8) as three square roots: a few ulps from `powf(0.125)` and several
                // times cheaper, which matters at one call per step of 12 evaluations.
                err.sqrt().sqrt().sqrt()
            };
            if err <= 1.0 {
                let fac = (1.0 / CONTROL.fac_max)
                    .max((1.0 / CONTROL.fac_min).min(fac11 / CONTROL.safety));
                let mut h_new = h / fac;
                self.stats.accepted += 1;
                self.f.rhs(&y_new, &mut self.k[12]);
                self.stats.evaluations += 1;
                if self.stiff(h, &y_new, &y12) {
                    return Outcome::Stiff;
                }
                h_new = h_new.min(self.h_max);
                if self.reject {
                    h_new = h_new.min(h);
                }
                self.reject = false;
                self.t_old = self.t;
                self.y_old = self.y;
                self.h_old = h;
                self.t = if h == t_end - self.t {
                    t_end
                } else {
                    self.t + h
                };
                self.y = y_new;
                self.h = h_new;
                self.fresh = true;
                return Outcome::Accepted;
            }
            self.h = h / (1.0 / CONTROL.fac_min).min(fac11 / CONTROL.safety);
            self.reject = true;
            if self.stats.accepted >= 1 {
                self.stats.rejected += 1;
            }
        }
    }

    /// The right-hand side at the end of the last accepted step, $f(t, y)$ (its stage 13,
    /// which the next step takes as its stage 1).
    pub(super) fn end_rate(&self) -> &State<N> {
        &self.k[12]
    }

    /// Replaces the state reached by the last accepted step (a projection moved it) and
    /// evaluates the first stage of the next step there (1 evaluation).
    pub(super) fn restart_from(&mut self, y: State<N>) {
        self.y = y;
        self.f.rhs(&self.y, &mut self.k[12]);
        self.stats.evaluations += 1;
    }

    /// Hairer's stiffness test, every [`STIFF_EVERY`] accepted steps and on every step while it
    /// fires: $|h\lambda| \approx h \|k_{13} - k_{12}\| / \|y_1 - Y_{12}\|$ with $Y_{12}$ the
    /// argument of stage 12. True when it fired [`STIFF_COUNT`] times in a row.
    fn stiff(&mut self, h: f64, y_new: &State<N>, y12: &State<N>) -> bool {
        if !(self.stats.accepted.is_multiple_of(STIFF_EVERY) || self.stiff_hits > 0) {
            return false;
        }
        let num = (self.k[12] - self.k[11]).norm_squared();
        let den = (y_new - y12).norm_squared();
        let h_lambda = if den > 0.0 {
            h * (num / den).sqrt()
        } else {
            0.0
        };
        if h_lambda > STIFF_BOUND {
            self.stiff_misses = 0;
            self.stiff_hits += 1;
            return self.stiff_hits == STIFF_COUNT;
        }
        self.stiff_misses += 1;
        if self.stiff_misses == 6 {
            self.stiff_hits = 0;
        }
        false
    }

    /// Stages 2..12 from `self.y` with step `h` (11 evaluations; stage 1 is `self.k[0]`):
    /// returns the error, the 8th-order solution and the argument of stage 12.
    fn stages(&mut self, h: f64) -> (f64, State<N>, State<N>) {
        let y = self.y;
        let f = self.f;
        let k = &mut self.k;
        let mut yy = combine(&y, h, [(A21, &k[0])]);
        f.rhs(&yy, &mut k[1]);
        yy = combine(&y, h, [(A31, &k[0]), (A32, &k[1])]);
        f.rhs(&yy, &mut k[2]);
        yy = combine(&y, h, [(A41, &k[0]), (A43, &k[2])]);
        f.rhs(&yy, &mut k[3]);
        yy = combine(&y, h, [(A51, &k[0]), (A53, &k[2]), (A54, &k[3])]);
        f.rhs(&yy, &mut k[4]);
        yy = combine(&y, h, [(A61, &k[0]), (A64, &k[3]), (A65, &k[4])]);
        f.rhs(&yy, &mut k[5]);
        yy = combine(
            &y,
            h,
            [(A71, &k[0]), (A74, &k[3]), (A75, &k[4]), (A76, &k[5])],
        );
        f.rhs(&yy, &mut k[6]);
        yy = combine(
            &y,
            h,
            [
                (A81, &k[0]),
                (A84, &k[3]),
                (A85, &k[4]),
                (A86, &k[5]),
                (A87, &k[6]),
            ],
        );
        f.rhs(&yy, &mut k[7]);
        yy = combine(
            &y,
            h,
            [
                (A91, &k[0]),
                (A94, &k[3]),
                (A95, &k[4]),
                (A96, &k[5]),
                (A97, &k[6]),
                (A98, &k[7]),
            ],
        );
        f.rhs(&yy, &mut k[8]);
        yy = combine(
            &y,
            h,
            [
                (A101, &k[0]),
                (A104, &k[3]),
                (A105, &k[4]),
                (A106, &k[5]),
                (A107, &k[6]),
                (A108, &k[7]),
                (A109, &k[8]),
            ],
        );
        f.rhs(&yy, &mut k[9]);
        yy = combine(
            &y,
            h,
            [
                (A111, &k[0]),
                (A114, &k[3]),
                (A115, &k[4]),
                (A116, &k[5]),
                (A117, &k[6]),
                (A118, &k[7]),
                (A119, &k[8]),
                (A1110, &k[9]),
            ],
        );
        f.rhs(&yy, &mut k[10]);
        let y12 = combine(
            &y,
            h,
            [
                (A121, &k[0]),
                (A124, &k[3]),
                (A125, &k[4]),
                (A126, &k[5]),
                (A127, &k[6]),
                (A128, &k[7]),
                (A129, &k[8]),
                (A1210, &k[9]),
                (A1211, &k[10]),
            ],
        );
        f.rhs(&y12, &mut k[11]);
        self.stats.evaluations += 11;

        let (mut err5, mut err3) = (0.0, 0.0);
        let mut y_new = y;
        for i in 0..N {
            let b = B1 * k[0][i]
                + B6 * k[5][i]
                + B7 * k[6][i]
                + B8 * k[7][i]
                + B9 * k[8][i]
                + B10 * k[9][i]
                + B11 * k[10][i]
                + B12 * k[11][i];
            y_new[i] = y[i] + h * b;
            let sk = self.atol + self.rtol * y[i].abs().max(y_new[i].abs());
            let e3 = b - BHH1 * k[0][i] - BHH2 * k[8][i] - BHH3 * k[11][i];
            let e5 = ER1 * k[0][i]
                + ER6 * k[5][i]
                + ER7 * k[6][i]
                + ER8 * k[7][i]
                + ER9 * k[8][i]
                + ER10 * k[9][i]
                + ER11 * k[10][i]
                + ER12 * k[11][i];
            err3 += (e3 / sk) * (e3 / sk);
            err5 += (e5 / sk) * (e5 / sk);
        }
        let mut deno = err5 + 0.01 * err3;
        if deno <= 0.0 {
            deno = 1.0;
        }
        let err = h.abs() * err5 * (1.0 / (N as f64 * deno)).sqrt();
        (err, y_new, y12)
    }

    /// The dense output of the last accepted step: three more evaluations (counted as extra),
    /// made only for a step that needs it (an event or a sample inside it). Valid until the
    /// next call to [`Dop853::step`]. In the AVX2 build where the processor has it
    /// ([`numerics::wider`]): the same IEEE operations in the same order (no fused multiply-add),
    /// so the same bits, four components to a register.
    pub(super) fn dense(&mut self) -> Dense<N> {
        #[cfg(target_arch = "x86_64")]
        if numerics::wider::avx2() {
            // SAFETY: the processor has AVX2, checked just above.
            return unsafe { self.dense_avx2() };
        }
        self.dense_rows()
    }

    /// [`Dop853::dense`] compiled for AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn dense_avx2(&mut self) -> Dense<N> {
        self.dense_rows()
    }

    /// [`Dop853::dense`]'s stages and coefficients, in the build this is inlined into (the
    /// baseline one when called directly).
    #[inline(always)]
    fn dense_rows(&mut self) -> Dense<N> {
        let (y, h, f) = (self.y_old, self.h_old, self.f);
        let k = &self.k;
        let mut k14 = State::<N>::zeros();
        let mut k15 = State::<N>::zeros();
        let mut k16 = State::<N>::zeros();
        let yy = combine(
            &y,
            h,
            [
                (A141, &k[0]),
                (A147, &k[6]),
                (A148, &k[7]),
                (A149, &k[8]),
                (A1410, &k[9]),
                (A1411, &k[10]),
                (A1412, &k[11]),
                (A1413, &k[12]),
            ],
        );
        f.rhs(&yy, &mut k14);
        let yy = combine(
            &y,
            h,
            [
                (A151, &k[0]),
                (A156, &k[5]),
                (A157, &k[6]),
                (A158, &k[7]),
                (A1511, &k[10]),
                (A1512, &k[11]),
                (A1513, &k[12]),
                (A1514, &k14),
            ],
        );
        f.rhs(&yy, &mut k15);
        let yy = combine(
            &y,
            h,
            [
                (A161, &k[0]),
                (A166, &k[5]),
                (A167, &k[6]),
                (A168, &k[7]),
                (A169, &k[8]),
                (A1613, &k[12]),
                (A1614, &k14),
                (A1615, &k15),
            ],
        );
        f.rhs(&yy, &mut k16);
        self.stats.extra_evaluations += 3;

        let mut r = [State::<N>::zeros(); 8];
        let d = [
            [
                D41, D46, D47, D48, D49, D410, D411, D412, D413, D414, D415, D416,
            ],
            [
                D51, D56, D57, D58, D59, D510, D511, D512, D513, D514, D515, D516,
            ],
            [
                D61, D66, D67, D68, D69, D610, D611, D612, D613, D614, D615, D616,
            ],
            [
                D71, D76, D77, D78, D79, D710, D711, D712, D713, D714, D715, D716,
            ],
        ];
        let kd = [
            &k[0], &k[5], &k[6], &k[7], &k[8], &k[9], &k[10], &k[11], &k[12], &k14, &k15, &k16,
        ];
        for i in 0..N {
            let ydiff = self.y[i] - y[i];
            let bspl = h * k[0][i] - ydiff;
            r[0][i] = y[i];
            r[1][i] = ydiff;
            r[2][i] = bspl;
            r[3][i] = ydiff - h * k[12][i] - bspl;
            for (row, dr) in d.iter().enumerate() {
                let mut s = 0.0;
                for (c, kk) in dr.iter().zip(&kd) {
                    s += c * kk[i];
                }
                r[4 + row][i] = h * s;
            }
        }
        Dense {
            t_old: self.t_old,
            h,
            r,
        }
    }
}
