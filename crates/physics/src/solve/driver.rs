//! Drives the crate's own DOP853 ([`super::dop853`]) over a [`Problem`]: the step loop, the
//! step limit, the wall-time budget, progress, stop events and sampling.
//!
//! Events and samples use the dense output of the step they fall in (DOP853's interpolant of
//! order 7, [`Dense`]): a step that holds a sample or an event costs three more evaluations,
//! and each sample after that one polynomial evaluation per component, however finely the run
//! samples. An event crossing is seen on the step ends, as with `ode_solvers`, and located by
//! bisection on the step's interpolant to [`EVENT_TIME_TOLERANCE`].
//!
//! With a projection ([`Problem::project`]) every accepted step's end is moved onto the
//! invariant before the next step starts from it (one more evaluation per step, counted).

use super::dop853::{Dense, Dop853, Outcome};
use super::grid::grid_times;
use super::settings::RTOL_LEAST;
use super::{
    Batch, BatchSink, Dynamics, Ending, Event, Problem, Settings, Sink, Solution, State, BATCH,
    EVENT_TIME_TOLERANCE,
};
use crate::budget::Deadline;

/// Where the samples stand on the grid $t_g + n\,\Delta t$: the next sample index and the rows
/// written so far.
struct Sampler<'s, const N: usize> {
    origin: f64,
    dt: f64,
    next: u64,
    t: Vec<f64>,
    y: Vec<State<N>>,
    /// Takes the samples as they are made (then `t` and `y` stay empty).
    sink: Option<Sink<'s, N>>,
    /// Takes them a step's worth at a time instead (then `sink` is not used).
    batch_sink: Option<BatchSink<'s, N>>,
    /// The batch being filled.
    batch: Box<Batch<N>>,
    /// Samples from the dense output; otherwise each is re-integrated from its step's start.
    dense: bool,
}

impl<'s, const N: usize> Sampler<'s, N> {
    /// A sampler on the grid `origin + n dt` whose first sample is the first grid time at or
    /// after `t0`.
    fn new(
        origin: f64,
        dt: f64,
        t0: f64,
        (sink, batch_sink): (Option<Sink<'s, N>>, Option<BatchSink<'s, N>>),
        dense: bool,
    ) -> Self {
        let mut s = Self {
            origin,
            dt,
            next: ((t0 - origin) / dt).floor().max(0.0) as u64,
            t: Vec::new(),
            y: Vec::new(),
            sink,
            batch_sink,
            batch: Box::default(),
            dense,
        };
        while s.time(s.next) < t0 {
            s.next += 1;
        }
        s
    }

    fn time(&self, n: u64) -> f64 {
        grid_time(self.origin, self.dt, n)
    }

    /// The time before which samples are written in a run that ends at `t_stop`: `t_stop` less
    /// a margin of 1e-12 relative (the end itself is always written as the last row).
    fn guard(&self, t_stop: f64) -> f64 {
        t_stop - 1e-12 * self.dt.max(t_stop.abs())
    }

    /// True when a sample falls in a step ending at `t_b` of a run that ends at `t_stop`.
    fn due(&self, t_b: f64, t_stop: f64) -> bool {
        let t = self.time(self.next);
        t <= t_b && t < self.guard(t_stop)
    }

    /// Writes the samples up to `t_b` and strictly before the guard of `t_stop` from `state_at`.
    fn fill(&mut self, t_b: f64, t_stop: f64, mut state_at: impl FnMut(f64) -> State<N>) {
        let guard = self.guard(t_stop);
        loop {
            let t = self.time(self.next);
            if t > t_b || t >= guard {
                return;
            }
            let y = state_at(t);
            match (self.batch_sink.as_mut(), self.sink.as_mut()) {
                (Some(sink), _) => sink(&Batch::one(t, &y)),
                (None, Some(sink)) => sink(t, &y),
                (None, None) => {
                    self.t.push(t);
                    self.y.push(y);
                }
            }
            self.next += 1;
        }
    }

    /// [`Sampler::fill`] from the step's dense output `d`: with a batch sink, the samples
    /// evaluated [`BATCH`] at a time ([`Dense::fill`], the same states to the bit).
    fn fill_dense(&mut self, t_b: f64, t_stop: f64, d: &Dense<N>) {
        let guard = self.guard(t_stop);
        let Some(sink) = self.batch_sink.as_mut() else {
            return self.fill(t_b, t_stop, |t| d.at(t));
        };
        let mut times = [0.0; BATCH];
        loop {
            // The next BATCH times of the grid at once, then those of this step, which come
            // first: the grid's times rise with their index and the test is monotone.
            // (next + k) as a double, exactly: both are integers below 2^53.
            let base = (self.next as i64) as f64;
            let n = grid_times(self.origin, self.dt, base, t_b, guard, &mut times);
            self.next += n as u64;
            if n == 0 {
                return;
            }
            d.fill(&times[..n], &mut self.batch);
            sink(&self.batch);
            if n < BATCH {
                return;
            }
        }
    }
}

/// The time $t_g + n\,\Delta t$ of sample `n` of the grid. A run has fewer than $2^{53}$
/// samples, so `n` converts exactly through a signed integer (one instruction, where an
/// unsigned one takes several).
#[inline]
fn grid_time(origin: f64, dt: f64, n: u64) -> f64 {
    origin + dt * (n as i64) as f64
}

/// The tolerances at which a run that samples on its dense output integrates, so that its
/// samples are as accurate as `rtol` and `atol` ask.
///
/// A step is accepted when its error estimate, which bounds the solution of order 8 (local
/// error $O(h^9)$), is below the tolerance $\tau$; the interpolant of order 7 has a local error
/// $O(h^8)$, so at the steps $h \propto \tau^{1/9}$ that $\tau$ allows it reaches about
/// $c\,\tau^{8/9}$, that is $c\,\tau^{-1/9}$ tolerances ($c \approx 2$: 2.8, 17 and 46 at
/// $\tau$ = 1e-6, 1e-9, 1e-12 in `dense_error`). Integrating at $\tau / K$ with
/// $K = 2\,\mathrm{rtol}^{-1/9}$ brings it to about $K^{1/9}$ (1.5 at rtol 1e-12) of the
/// tolerance asked, for $K^{1/8}$ more steps (1.6x at rtol 1e-12), none more per sample. The
/// tightened `rtol` stays at or above [`RTOL_LEAST`], where double precision ends.
pub(crate) fn dense_tolerances(rtol: f64, atol: f64) -> (f64, f64) {
    let k = (2.0 * rtol.powf(-1.0 / 9.0)).max(1.0);
    let k = k.min(rtol / RTOL_LEAST).max(1.0);
    (rtol / k, atol / k)
}

/// The state at `t_a + tau` re-integrated from `(t_a, y_a)` with the same tolerances, first
/// trying the whole interval in one step; its evaluations are added to `extra`.
fn advance<D: Dynamics<N>, const N: usize>(
    f: &D,
    settings: &Settings,
    t_a: f64,
    y_a: State<N>,
    tau: f64,
    extra: &mut u64,
) -> State<N> {
    if tau <= 0.0 {
        return y_a;
    }
    let t_b = t_a + tau;
    let mut s = Dop853::with_first_step(f, settings.rtol, settings.atol, t_a, y_a, tau);
    while s.t < t_b {
        if s.step(t_b) != Outcome::Accepted {
            break;
        }
    }
    *extra += s.stats.evaluations;
    s.y
}

/// The earliest event that crossed in the step of `dense` from `t_a` to `t_b`, located by
/// bisection on the interpolant: its index, time and the interpolated state there (where it
/// holds).
fn locate<const N: usize>(
    events: &[Event<'_, N>],
    dense: &Dense<N>,
    t_a: f64,
    t_b: f64,
    y_b: State<N>,
) -> (usize, f64, State<N>) {
    first_crossing(events, t_a, t_b, y_b, |dt| dense.at(t_a + dt))
}

/// Integrates a checked problem (see [`super::solve`]) from a start at which no event holds.
pub(super) fn run<D: Dynamics<N>, const N: usize>(
    problem: Problem<'_, D, N>,
    settings: &Settings,
    deadline: Deadline,
) -> Solution<N> {
    let (t0, y0, t_end) = (problem.t0, problem.y0, problem.t_end);
    let (rtol, atol) = if problem.sample.is_some() && problem.dense_samples {
        dense_tolerances(settings.rtol, settings.atol)
    } else {
        (settings.rtol, settings.atol)
    };
    let mut s = Dop853::new(problem.dynamics, rtol, atol, t0, y0, t_end - t0);
    let origin = problem.sample_origin.unwrap_or(t0);
    let mut sinks = Some((problem.on_sample, problem.on_batch));
    let mut on_step = problem.on_step.filter(|_| problem.sample.is_some());
    let mut sampler = problem.sample.map(|dt| {
        let sinks = sinks.take().unwrap_or_default();
        Sampler::new(origin, dt, t0, sinks, problem.dense_samples)
    });
    let (mut ts, mut ys) = (vec![t0], vec![y0]);
    // The last point reached where the state is finite (and no event has fired before).
    let mut last = (t0, y0);
    let mut attempts: u64 = 0;
    let max_steps = u64::from(settings.max_steps);
    let ending = loop {
        if s.t >= t_end {
            break Ending::TimeReached;
        }
        let before = s.stats.accepted + s.stats.rejected;
        if attempts >= max_steps {
            break Ending::TooManySteps {
                t: s.t,
                steps: settings.max_steps,
                needs: Ending::pace(max_steps, t0, s.t, t_end),
            };
        }
        let (t_a, y_a) = (s.t, s.y);
        match s.step(t_end) {
            Outcome::Collapse => break Ending::StepCollapse { t: s.t },
            Outcome::Stiff => break Ending::Stiff { t: s.t },
            Outcome::Accepted => {}
        }
        attempts += (s.stats.accepted + s.stats.rejected - before).max(1);
        let (t_b, y_b) = (s.t, s.y);
        if !y_b.iter().all(|v| v.is_finite()) {
            break Ending::NonFinite { t: t_b };
        }
        if problem.events.iter().any(|e| (e.value)(&y_b) <= 0.0) {
            let d = s.dense();
            let (index, t_e, y_e) = locate(&problem.events, &d, t_a, t_b, y_b);
            if let Some(on_step) = on_step.as_mut() {
                on_step(t_e, &y_e, None);
            }
            if let Some(sm) = sampler.as_mut() {
                let mut extra = 0;
                if sm.dense {
                    sm.fill_dense(t_e, t_e, &d);
                } else {
                    sm.fill(t_e, t_e, |t| {
                        advance(problem.dynamics, settings, t_a, y_a, t - t_a, &mut extra)
                    });
                }
                s.stats.extra_evaluations += extra;
            }
            last = (t_e, y_e);
            break Ending::Event {
                index,
                name: problem.events[index].name.clone(),
                t: t_e,
            };
        }
        if let Some(on_step) = on_step.as_mut() {
            on_step(t_b, &y_b, Some(s.end_rate()));
        }
        if let Some(sm) = sampler.as_mut() {
            if sm.due(t_b, t_end) {
                let mut extra = 0;
                if sm.dense {
                    let d = s.dense();
                    sm.fill_dense(t_b, t_end, &d);
                } else {
                    sm.fill(t_b, t_end, |t| {
                        advance(problem.dynamics, settings, t_a, y_a, t - t_a, &mut extra)
                    });
                }
                s.stats.extra_evaluations += extra;
            }
        }
        // The projection comes after the step's events and samples, which use its dense
        // output and its start; the next step starts from the projected state.
        let y_b = match &problem.project {
            Some(project) => {
                let mut y = y_b;
                project(&mut y);
                s.restart_from(y);
                y
            }
            None => y_b,
        };
        if sampler.is_none() {
            ts.push(t_b);
            ys.push(y_b);
        }
        last = (t_b, y_b);
        let n = s.stats.accepted;
        if n.is_multiple_of(256) {
            if let Some(p) = problem.progress {
                p(t_b);
            }
        }
        if n.is_multiple_of(64) && deadline.passed() {
            break Ending::WallTime {
                t: t_b,
                seconds: deadline.seconds(),
            };
        }
    };
    if let Some(p) = problem.progress {
        p(last.0);
    }
    let (t, y) = match sampler {
        Some(mut sm) => {
            sm.t.push(last.0);
            sm.y.push(last.1);
            (sm.t, sm.y)
        }
        None => {
            if matches!(ending, Ending::Event { .. }) {
                ts.push(last.0);
                ys.push(last.1);
            }
            (ts, ys)
        }
    };
    let stats = s.stats;
    Solution {
        t,
        y,
        stats,
        ending,
    }
}

/// The earliest of `events` that holds at the step's end `(t_b, y_b)`, located by bisection on
/// the state `state_after(dt)` at time `t_a + dt` to [`EVENT_TIME_TOLERANCE`]: its index, time
/// and the state there (where it holds). With no event holding, the step's end.
pub(super) fn first_crossing<const N: usize>(
    events: &[Event<'_, N>],
    t_a: f64,
    t_b: f64,
    y_b: State<N>,
    mut state_after: impl FnMut(f64) -> State<N>,
) -> (usize, f64, State<N>) {
    let mut best: Option<(usize, f64, State<N>)> = None;
    for (i, e) in events.iter().enumerate() {
        if (e.value)(&y_b) > 0.0 {
            continue;
        }
        let (mut lo, mut hi) = (0.0, t_b - t_a);
        let mut y_hi = y_b;
        while hi - lo > EVENT_TIME_TOLERANCE * 0.5 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            let y_mid = state_after(mid);
            if (e.value)(&y_mid) <= 0.0 {
                hi = mid;
                y_hi = y_mid;
            } else {
                lo = mid;
            }
        }
        if best.as_ref().is_none_or(|b| t_a + hi < b.1) {
            best = Some((i, t_a + hi, y_hi));
        }
    }
    best.unwrap_or((0, t_b, y_b))
}
