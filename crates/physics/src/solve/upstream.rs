//! The path through `ode_solvers` 0.6.2: classical RK4 and DOPRI5 (and its DOP853, kept for
//! comparison with [`super::dop853`]).
//!
//! `ode_solvers` can only stop after an accepted step and has no dense output in sparse mode: a
//! stop event is detected on the step ends and then located by bisection on re-integrations from
//! the start of the step that crossed it, and samples are re-integrated from the step before.

use super::dop853::{StepControl, CONTROL};
use super::{
    Batch, Dynamics, Ending, Event, Method, Problem, Settings, Sink, Solution, State, Stats,
};
use crate::budget::Deadline;
use ode_solvers::dop_shared::IntegrationError;
use ode_solvers::{Dop853, Dopri5, OutputType, Rk4, System};

/// A fixed step is taken as unresolved, and the run as unstable, when the part of the step
/// beyond first order exceeds this multiple of its first-order (Euler) part.
///
/// The first-order part is taken as the largest of the recent steps' (a maximum that decays by
/// 1 % a step, so over about a hundred steps): at the turning points of a nutation the slope
/// passes near zero while the curvature does not, and the step's own Euler part would make the
/// ratio spike there without any instability.
///
/// For a linear mode $\dot y = \lambda y$ the RK4 step multiplies $y$ by
/// $R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24$ with $z = h\lambda$, so the ratio is
/// $|z/2 + z^2/6 + z^3/24|$. It reaches 1 at $z = -2.785$, exactly RK4's stability limit on the
/// negative real axis, and at $|z| \approx 2.1$ on the imaginary axis (the limit there is
/// $2\sqrt 2$, where the phase is already wrong by a large fraction of a turn). The ratio needs no
/// extra evaluation: `ode_solvers` hands the step's first slope $f(y_n)$ to the step-end callback.
pub const RK4_RESOLUTION: f64 = 1.0;

/// Bridges a [`Dynamics`] to `ode_solvers`: ignores the time it is passed, watches the events,
/// the finiteness of the state, the wall-time budget and (for RK4) the resolution of each step.
struct Bridge<'p, 'a, D, const N: usize> {
    dynamics: &'a D,
    events: &'p [Event<'a, N>],
    progress: Option<&'a dyn Fn(f64)>,
    /// The last accepted step end at which no event had happened.
    prev: (f64, State<N>),
    /// The last accepted step end, whatever happened there.
    last: (f64, State<N>),
    crossed: bool,
    non_finite: Option<f64>,
    steps: u64,
    /// Watch each fixed step's resolution (RK4 only).
    fixed_step: bool,
    unstable: Option<(f64, f64, f64)>,
    /// The decaying maximum of the recent steps' Euler parts.
    scale: f64,
    deadline: Option<Deadline>,
    timed_out: Option<f64>,
    /// Right-hand-side evaluations, counted here since `ode_solvers` reports its own count only
    /// for a run that ends without an error.
    evaluations: std::cell::Cell<u64>,
}

impl<'p, 'a, D: Dynamics<N>, const N: usize> Bridge<'p, 'a, D, N> {
    fn new(dynamics: &'a D, events: &'p [Event<'a, N>], t0: f64, y0: State<N>) -> Self {
        Self {
            dynamics,
            events,
            progress: None,
            prev: (t0, y0),
            last: (t0, y0),
            crossed: false,
            non_finite: None,
            steps: 0,
            fixed_step: false,
            unstable: None,
            scale: 0.0,
            deadline: None,
            timed_out: None,
            evaluations: std::cell::Cell::new(0),
        }
    }

    /// The step from `self.last` to `(t, y)` with first slope `dy`: `Some((ratio, h))` when its
    /// higher-order part exceeds [`RK4_RESOLUTION`] times the recent Euler parts, or the size
    /// of the state itself (a step that jumps). A floor of 1e-6 of the state's size keeps
    /// round-off in a motion at rest from counting.
    fn unresolved(&mut self, t: f64, y: &State<N>, dy: &State<N>) -> Option<(f64, f64)> {
        let (t_a, y_a) = &self.last;
        let h = t - t_a;
        let euler = dy * h;
        self.scale = euler.norm().max(0.99 * self.scale);
        let rest = (y - y_a - euler).norm();
        let floor = 1e-6 * (1.0 + y_a.norm());
        let unresolved = rest > RK4_RESOLUTION * self.scale && rest > floor;
        let jump = rest > y_a.norm() + euler.norm();
        (unresolved || jump).then(|| (rest / self.scale.max(f64::MIN_POSITIVE), h))
    }
}

impl<D: Dynamics<N>, const N: usize> System<f64, State<N>> for &mut Bridge<'_, '_, D, N> {
    fn system(&self, _t: f64, y: &State<N>, dy: &mut State<N>) {
        self.evaluations.set(self.evaluations.get() + 1);
        self.dynamics.rhs(y, dy);
    }

    fn solout(&mut self, t: f64, y: &State<N>, dy: &State<N>) -> bool {
        self.steps += 1;
        if self.steps.is_multiple_of(256) {
            if let Some(p) = self.progress {
                p(t);
            }
        }
        if self.steps.is_multiple_of(64) && self.deadline.is_some_and(|d| d.passed()) {
            self.timed_out = Some(t);
            return true;
        }
        if !y.iter().all(|v| v.is_finite()) {
            self.non_finite = Some(t);
            return true;
        }
        if self.fixed_step {
            if let Some((ratio, h)) = self.unresolved(t, y, dy) {
                self.unstable = Some((t, ratio, h));
                return true;
            }
            self.last = (t, *y);
        }
        if self.events.iter().any(|e| (e.value)(y) <= 0.0) {
            self.crossed = true;
            return true;
        }
        self.prev = (t, *y);
        false
    }
}

type Raw<const N: usize> = (
    Result<ode_solvers::dop_shared::Stats, IntegrationError>,
    Vec<f64>,
    Vec<State<N>>,
);

/// DOPRI5's controller, stabilized as Hairer's code sets it.
const DOPRI5_CONTROL: StepControl = StepControl {
    safety: 0.9,
    beta: 0.04,
    fac_min: 0.2,
    fac_max: 10.0,
};

/// One run of an `ode_solvers` integrator from `t0` to `t_end`, keeping every accepted step.
/// `first_step` = 0 lets the adaptive methods choose it.
fn raw_run<D: Dynamics<N>, const N: usize>(
    bridge: &mut Bridge<'_, '_, D, N>,
    settings: &Settings,
    t0: f64,
    y0: State<N>,
    t_end: f64,
    first_step: f64,
) -> Raw<N> {
    let span = t_end - t0;
    let n_max = settings.max_steps;
    macro_rules! finish {
        ($s:ident) => {{
            let r = $s.integrate();
            let (t, y) = $s.results().get();
            (r, t.clone(), y.clone())
        }};
    }
    // Each method with its step-size controller: `ode_solvers`' DOP853 with the constants of
    // ours, DOPRI5 with Hairer's stabilized one.
    macro_rules! adaptive {
        ($solver:ident, $control:expr) => {{
            let c: StepControl = $control;
            let mut s = $solver::from_param(
                bridge,
                t0,
                t_end,
                span,
                y0,
                settings.rtol,
                settings.atol,
                c.safety,
                c.beta,
                c.fac_min,
                c.fac_max,
                span,
                first_step,
                n_max,
                1000,
                OutputType::Sparse,
            );
            finish!(s)
        }};
    }
    match settings.method {
        Method::Dop853 => adaptive!(Dop853, CONTROL),
        Method::Dopri5 => adaptive!(Dopri5, DOPRI5_CONTROL),
        Method::Rk4 => {
            // ode_solvers takes ceil(span / step) steps of the full step and so overshoots
            // t_end: shorten the step so that a whole number of steps ends exactly there.
            let h = if first_step > 0.0 {
                first_step
            } else {
                settings.step
            };
            let n = (span / h).ceil().max(1.0);
            let mut s = Rk4::new(bridge, t0, y0, t_end, span / n);
            finish!(s)
        }
    }
}

/// The state at `t0 + tau` re-integrated from `(t0, y0)` with the same method and tolerances:
/// one RK4 step, or an adaptive run that first tries the whole interval in one step.
fn advance<D: Dynamics<N>, const N: usize>(
    dynamics: &D,
    settings: &Settings,
    t0: f64,
    y0: State<N>,
    tau: f64,
    stats: &mut Stats,
) -> State<N> {
    if tau <= 0.0 {
        return y0;
    }
    let mut bridge = Bridge::new(dynamics, &[], t0, y0);
    let (r, _, y) = raw_run(&mut bridge, settings, t0, y0, t0 + tau, tau);
    if let Ok(s) = r {
        stats.extra_evaluations += u64::from(s.num_eval);
    }
    *y.last().unwrap_or(&y0)
}

/// Integrates a checked problem (see [`super::solve`]) with `ode_solvers`, from a start at which
/// no event holds.
pub(super) fn run<D: Dynamics<N>, const N: usize>(
    problem: Problem<'_, D, N>,
    settings: &Settings,
    deadline: Deadline,
) -> Solution<N> {
    let (t0, y0) = (problem.t0, problem.y0);
    let mut stats = Stats::default();
    let mut bridge = Bridge::new(problem.dynamics, &problem.events, t0, y0);
    bridge.progress = problem.progress;
    bridge.fixed_step = settings.method == Method::Rk4;
    bridge.deadline = Some(deadline);
    let (result, mut ts, mut ys) = raw_run(&mut bridge, settings, t0, y0, problem.t_end, 0.0);
    let (crossed, non_finite, prev) = (bridge.crossed, bridge.non_finite, bridge.prev);
    let (unstable, timed_out) = (bridge.unstable, bridge.timed_out);
    let mut ending = Ending::TimeReached;
    match result {
        Ok(s) => {
            stats.evaluations = u64::from(s.num_eval);
            stats.accepted = u64::from(s.accepted_steps);
            stats.rejected = u64::from(s.rejected_steps);
        }
        Err(e) => {
            ending = match e {
                IntegrationError::StepSizeUnderflow { x } => Ending::StepCollapse { t: x },
                IntegrationError::MaxNumStepReached { x, n_step } => Ending::TooManySteps {
                    t: x,
                    steps: n_step,
                    needs: Ending::pace(u64::from(n_step), t0, x, problem.t_end),
                },
                IntegrationError::StiffnessDetected { x } => Ending::Stiff { t: x },
            };
            stats.accepted = ts.len().saturating_sub(1) as u64;
            stats.evaluations = bridge.evaluations.get();
        }
    }
    if let Some(t) = non_finite {
        ending = Ending::NonFinite { t };
        ts.pop();
        ys.pop();
    } else if let Some((t, ratio, step)) = unstable {
        ending = Ending::Unstable { t, ratio, step };
        ts.pop();
        ys.pop();
    } else if let Some(t) = timed_out {
        ending = Ending::WallTime {
            t,
            seconds: deadline.seconds(),
        };
    } else if crossed {
        let (t_a, y_a) = prev;
        let t_b = ts.last().copied().unwrap_or(t0);
        let (index, t_e, y_e) = locate(
            problem.dynamics,
            settings,
            &problem.events,
            t_a,
            y_a,
            t_b,
            &mut stats,
        );
        ts.pop();
        ys.pop();
        ts.push(t_e);
        ys.push(y_e);
        ending = Ending::Event {
            index,
            name: problem.events[index].name.clone(),
            t: t_e,
        };
    }
    if let Some(p) = problem.progress {
        p(*ts.last().unwrap_or(&t0));
    }

    // A batch sink takes each re-integrated sample as a batch of one.
    let batched = problem.on_batch.is_some();
    let mut on_batch = problem.on_batch;
    let mut one = |t: f64, y: &State<N>| {
        if let Some(sink) = on_batch.as_mut() {
            sink(&Batch::one(t, y));
        }
    };
    let on_sample: Option<Sink<'_, N>> = if batched {
        Some(&mut one)
    } else {
        problem.on_sample.map(|sink| sink as Sink<'_, N>)
    };
    let (t, y) = match problem.sample {
        None => (ts, ys),
        Some(dt) => {
            let (t, y, complete) = resample(
                problem.dynamics,
                settings,
                &ts,
                &ys,
                problem.sample_origin.unwrap_or(t0),
                dt,
                &deadline,
                &mut stats,
                on_sample,
                problem.on_step,
            );
            if !complete && ending.is_complete() {
                ending = Ending::WallTime {
                    t: *t.last().unwrap_or(&t0),
                    seconds: deadline.seconds(),
                };
            }
            (t, y)
        }
    };
    Solution {
        t,
        y,
        stats,
        ending,
    }
}

/// The earliest event that crossed in the step from `(t_a, y_a)` to `t_b`, located by bisection
/// on the re-integrated state. Returns its index, time and the state there (where it holds).
fn locate<D: Dynamics<N>, const N: usize>(
    dynamics: &D,
    settings: &Settings,
    events: &[Event<'_, N>],
    t_a: f64,
    y_a: State<N>,
    t_b: f64,
    stats: &mut Stats,
) -> (usize, f64, State<N>) {
    let y_b = advance(dynamics, settings, t_a, y_a, t_b - t_a, stats);
    // The step ends showed a crossing, so at least one event fires at t_b or before.
    super::driver::first_crossing(events, t_a, t_b, y_b, |dt| {
        advance(dynamics, settings, t_a, y_a, dt, stats)
    })
}

/// Samples a solution on the grid `origin + n dt` from its first step on, each sample
/// re-integrated from the last accepted step before it. The final point (end time or event) is kept as the last sample.
/// The flag is false when the wall-time budget ran out first (the samples then stop there).
/// With a sink the samples go there and only the final point is returned. `on_step` takes each
/// step's end before the samples that lie in that step (see [`super::Problem::on_step`]).
#[allow(clippy::too_many_arguments)]
fn resample<const N: usize, D: Dynamics<N>>(
    dynamics: &D,
    settings: &Settings,
    ts: &[f64],
    ys: &[State<N>],
    origin: f64,
    dt: f64,
    deadline: &Deadline,
    stats: &mut Stats,
    mut sink: Option<Sink<'_, N>>,
    mut on_step: Option<super::StepSink<'_, N>>,
) -> (Vec<f64>, Vec<State<N>>, bool) {
    let Some((&t_last, &y_last)) = ts.last().zip(ys.last()) else {
        return (Vec::new(), Vec::new(), true);
    };
    let mut out_t = Vec::new();
    let mut out_y = Vec::new();
    let mut j = 0;
    // The next step whose end goes to `on_step`.
    let mut reported = 1;
    let t0 = ts[0];
    let mut n = ((t0 - origin) / dt).floor().max(0.0) as u64;
    while origin + dt * (n as f64) < t0 {
        n += 1;
    }
    loop {
        let t = origin + dt * n as f64;
        if t >= t_last - 1e-12 * dt.max(t_last.abs()) {
            break;
        }
        if n.is_multiple_of(64) && deadline.passed() {
            out_t.push(t_last);
            out_y.push(y_last);
            return (out_t, out_y, false);
        }
        while j + 1 < ts.len() && ts[j + 1] <= t {
            j += 1;
        }
        // The steps up to the one that holds t: the first, and each that starts before t.
        if let Some(on_step) = on_step.as_mut() {
            while reported < ts.len() && (reported == 1 || ts[reported - 1] < t) {
                on_step(ts[reported], &ys[reported], None);
                reported += 1;
            }
        }
        let y = advance(dynamics, settings, ts[j], ys[j], t - ts[j], stats);
        match sink.as_mut() {
            Some(sink) => sink(t, &y),
            None => {
                out_t.push(t);
                out_y.push(y);
            }
        }
        n += 1;
    }
    if let Some(on_step) = on_step.as_mut() {
        for (t, y) in ts.iter().zip(ys).skip(reported) {
            on_step(*t, y, None);
        }
    }
    out_t.push(t_last);
    out_y.push(y_last);
    (out_t, out_y, true)
}
