//! Hybrid systems: smooth flows that switch at located events.
//!
//! A hybrid system has a discrete mode (rolling, sliding, flying, ...) and in each mode a smooth
//! autonomous flow $\dot y = f_m(y)$ with guard functions $g_{m,i}(y)$. A mode's flow runs until
//! the first guard falls from positive to zero or below; the system then jumps: it picks the
//! next mode and may change the state (an impact, a projection onto a constraint), and the next
//! flow starts from there. [`run_hybrid`] drives that loop on top of [`crate::solve::solve`],
//! which locates each guard's crossing to [`crate::solve::EVENT_TIME_TOLERANCE`] by bisection on
//! re-integrations of the crossing step (`ode_solvers` has no event location), so every switch
//! happens at the located time, not at a step end, and no smoothing of the switching law is
//! needed.
//!
//! The rules a [`Hybrid`] must keep, and this driver relies on:
//! - every guard of the mode a jump lands in is positive at the state it lands on (a guard
//!   already at zero would end the next flow at once; the driver counts such empty flows as
//!   switches, so a system that breaks the rule ends with [`Ending::Halted`], never a loop);
//! - jumps are few: at most `max_switches` per run, beyond which the run halts with a stated
//!   reason (a Zeno cascade of bounces, chattering).
//!
//! Sampling at a fixed interval is aligned on the global grid $t_0 + n\,\Delta t$ across
//! segments ([`Problem::sample_origin`]); each segment's run samples its own flow (DOP853 on
//! its dense output).

use crate::solve::{
    held_samples, solve, Ending, Event, Problem, Settings, SettingsError, State, Stats,
};
use std::fmt;

/// What happens at a located guard crossing.
#[derive(Debug, Clone, PartialEq)]
pub enum Jump<M, const N: usize> {
    /// Go on in mode `mode` from state `y` (the same time).
    To {
        /// The next mode.
        mode: M,
        /// The state it starts from (after an impact or a projection, or unchanged).
        y: State<N>,
        /// A short description for the log ("stick -> slip", "impact").
        what: String,
    },
    /// The run ends here as a completed stop at this guard (a stop the user asked for).
    Stop,
    /// The model cannot go on: the run ends with this reason.
    Halt(String),
}

/// A hybrid system with modes `Self::Mode`.
pub trait Hybrid<const N: usize> {
    /// The discrete mode, with whatever data its flow needs.
    type Mode: Clone + fmt::Debug;
    /// The smooth flow of one mode.
    type Flow<'a>: crate::solve::Dynamics<N>
    where
        Self: 'a;
    /// The flow in `mode`.
    fn flow(&self, mode: &Self::Mode) -> Self::Flow<'_>;
    /// The guards of `mode`: the flow ends where the first of them reaches zero.
    fn guards<'a>(&'a self, mode: &Self::Mode) -> Vec<Event<'a, N>>;
    /// The jump when guard `guard` of `mode` fired in state `y`.
    fn jump(&self, mode: &Self::Mode, guard: usize, y: &State<N>) -> Jump<Self::Mode, N>;
}

/// One switch of a hybrid run.
#[derive(Debug, Clone, PartialEq)]
pub struct Switch<M> {
    /// When (s).
    pub t: f64,
    /// The guard that fired.
    pub guard: String,
    /// The mode before.
    pub from: M,
    /// The mode after.
    pub to: M,
    /// What the jump did.
    pub what: String,
}

/// A hybrid run: the recorded points with the mode each belongs to, the switches, the work
/// and why it ended.
#[derive(Debug, Clone)]
pub struct HybridSolution<M, const N: usize> {
    /// Times (nondecreasing; a jump that changes the state repeats its time).
    pub t: Vec<f64>,
    /// States.
    pub y: Vec<State<N>>,
    /// The mode of each point.
    pub mode: Vec<M>,
    /// Every switch, in order.
    pub switches: Vec<Switch<M>>,
    /// Solver work summed over the segments.
    pub stats: Stats,
    /// Why the run ended.
    pub ending: Ending,
}

/// How to run a hybrid system.
pub struct HybridProblem<'a, H, const N: usize>
where
    H: Hybrid<N>,
{
    /// The system.
    pub system: &'a H,
    /// Start mode.
    pub mode: H::Mode,
    /// Start time.
    pub t0: f64,
    /// Start state.
    pub y0: State<N>,
    /// End time.
    pub t_end: f64,
    /// Stop events that hold in every mode (built afresh for each segment).
    pub stops: &'a dyn Fn() -> Vec<Event<'a, N>>,
    /// Sample every this many seconds on the grid $t_0 + n\Delta t$; `None` keeps the steps.
    pub sample: Option<f64>,
    /// Most switches before the run halts.
    pub max_switches: usize,
    /// Takes every point as it is made, so that none is held: the solution then holds only
    /// the first point and the last.
    pub on_point: Option<PointSink<'a, H::Mode, N>>,
    /// Take DOP853's samples from each segment's dense output instead of re-integrating each
    /// from the step before it (see [`Problem::dense_samples`]); on by default. Each segment
    /// then integrates at the tightened tolerances of a dense run, so that its samples are as
    /// accurate as the settings ask, after a switch as before it (`dense_error`).
    pub dense_samples: bool,
}

/// Takes each point of a hybrid run with its mode ([`HybridProblem::on_point`]).
pub type PointSink<'a, M, const N: usize> = &'a mut dyn FnMut(f64, &State<N>, &M);

fn no_stops<'a, const N: usize>() -> Vec<Event<'a, N>> {
    Vec::new()
}

impl<'a, H: Hybrid<N>, const N: usize> HybridProblem<'a, H, N> {
    /// A problem with no stop events, no sampling and at most 10 000 switches.
    pub fn new(system: &'a H, mode: H::Mode, t0: f64, y0: State<N>, t_end: f64) -> Self {
        Self {
            system,
            mode,
            t0,
            y0,
            t_end,
            stops: &no_stops::<'a, N>,
            sample: None,
            max_switches: 10_000,
            on_point: None,
            dense_samples: true,
        }
    }
}

/// Writes a point: to the sink (the solution then keeps only its first point and this one) or
/// to the solution.
fn emit<M: Clone, const N: usize>(
    out: &mut HybridSolution<M, N>,
    sink: &mut Option<PointSink<'_, M, N>>,
    t: f64,
    y: State<N>,
    mode: &M,
) {
    if let Some(sink) = sink.as_mut() {
        sink(t, &y, mode);
        out.t.truncate(1);
        out.y.truncate(1);
        out.mode.truncate(1);
    }
    out.t.push(t);
    out.y.push(y);
    out.mode.push(mode.clone());
}

fn add(stats: &mut Stats, s: &Stats) {
    stats.evaluations += s.evaluations;
    stats.accepted += s.accepted;
    stats.rejected += s.rejected;
    stats.extra_evaluations += s.extra_evaluations;
}

/// Refuses a run that cannot start: settings out of range, an empty or infinite span, a
/// sample step that is not a positive number, or more samples than a held run may keep.
fn check_run<H: Hybrid<N>, const N: usize>(
    p: &HybridProblem<'_, H, N>,
    settings: &Settings,
) -> Result<(), SettingsError> {
    settings.validate()?;
    let span = p.t_end - p.t0;
    if !(span.is_finite() && span > 0.0) {
        return Err(SettingsError::Span(span));
    }
    if let Some(dt) = p.sample {
        if !(dt.is_finite() && dt > 0.0) {
            return Err(SettingsError::Sample(dt));
        }
        if p.on_point.is_none() {
            held_samples(span, dt)?;
        }
    }
    Ok(())
}

/// Runs a hybrid system: flows, located guard crossings and jumps until the end time, a stop
/// event, a solver failure, a halt of the model or `max_switches` switches.
pub fn run_hybrid<H: Hybrid<N>, const N: usize>(
    p: HybridProblem<'_, H, N>,
    settings: &Settings,
) -> Result<HybridSolution<H::Mode, N>, SettingsError> {
    check_run(&p, settings)?;
    let mut out = HybridSolution {
        t: vec![p.t0],
        y: vec![p.y0],
        mode: vec![p.mode.clone()],
        switches: Vec::new(),
        stats: Stats::default(),
        ending: Ending::TimeReached,
    };
    let (mut t, mut y, mut mode) = (p.t0, p.y0, p.mode);
    // The last sample written (sampled runs).
    let mut last_sample = p.t0;
    let mut next_sample: u64 = 1;
    let mut sink = p.on_point;
    if let Some(sink) = sink.as_mut() {
        sink(p.t0, &p.y0, &mode);
    }
    loop {
        let guards = p.system.guards(&mode);
        let n_guards = guards.len();
        let flow = p.system.flow(&mode);
        let mut problem = Problem::new(&flow, t, y, p.t_end);
        problem.events = guards;
        problem.events.extend((p.stops)());
        let dense = p.sample.is_some() && p.dense_samples;
        if dense {
            problem.sample = p.sample;
            problem.sample_origin = Some(p.t0);
            problem.dense_samples = true;
        }
        // A sampled segment's samples lie on the run's grid; the grid time the run starts on
        // is already the first point.
        let mut take = |ts: f64, ys: &State<N>| {
            if ts > last_sample {
                last_sample = ts;
                emit(&mut out, &mut sink, ts, *ys, &mode);
            }
        };
        if dense {
            problem.on_sample = Some(&mut take);
        }
        let names: Vec<String> = problem.events.iter().map(|e| e.name.clone()).collect();
        let sol = solve(problem, settings)?;
        add(&mut out.stats, &sol.stats);
        let (t_end, y_end) = sol.last();
        match p.sample {
            None => {
                for (ti, yi) in sol.t.iter().zip(&sol.y).skip(1) {
                    emit(&mut out, &mut sink, *ti, *yi, &mode);
                }
            }
            // Each sample re-integrated from the last accepted step before it.
            Some(dt) if !dense => {
                let mut j = 0;
                loop {
                    let ts = p.t0 + dt * next_sample as f64;
                    if ts >= t_end {
                        break;
                    }
                    while j + 1 < sol.t.len() && sol.t[j + 1] <= ts {
                        j += 1;
                    }
                    let ys = if ts > sol.t[j] {
                        let s = solve(Problem::new(&flow, sol.t[j], sol.y[j], ts), settings)?;
                        out.stats.extra_evaluations += s.stats.total_evaluations();
                        s.last().1
                    } else {
                        sol.y[j]
                    };
                    emit(&mut out, &mut sink, ts, ys, &mode);
                    next_sample += 1;
                }
            }
            Some(_) => {}
        }
        // Sampled runs keep the end of every segment too (a switch, a stop, the end time).
        let push_end = |out: &mut HybridSolution<H::Mode, N>,
                        sink: &mut Option<PointSink<'_, H::Mode, N>>,
                        m: &H::Mode| { emit(out, sink, t_end, y_end, m) };
        match sol.ending {
            Ending::Event { index, t: te, .. } if index < n_guards => {
                if p.sample.is_some() {
                    push_end(&mut out, &mut sink, &mode);
                }
                if out.switches.len() >= p.max_switches {
                    out.ending = Ending::Halted {
                        t: te,
                        reason: format!(
                            "{} switches, the most allowed (a cascade of ever shorter phases: \
                             chattering or a Zeno sequence of bounces)",
                            p.max_switches
                        ),
                    };
                    return Ok(out);
                }
                match p.system.jump(&mode, index, &y_end) {
                    Jump::Stop => {
                        out.ending = sol.ending.clone();
                        return Ok(out);
                    }
                    Jump::Halt(reason) => {
                        out.ending = Ending::Halted { t: te, reason };
                        return Ok(out);
                    }
                    Jump::To {
                        mode: next,
                        y: y_next,
                        what,
                    } => {
                        out.switches.push(Switch {
                            t: te,
                            guard: names[index].clone(),
                            from: mode.clone(),
                            to: next.clone(),
                            what,
                        });
                        if y_next != y_end {
                            emit(&mut out, &mut sink, te, y_next, &next);
                        }
                        if te >= p.t_end {
                            out.ending = Ending::TimeReached;
                            return Ok(out);
                        }
                        (t, y, mode) = (te, y_next, next);
                    }
                }
            }
            ending => {
                if p.sample.is_some() {
                    push_end(&mut out, &mut sink, &mode);
                }
                out.ending = ending;
                return Ok(out);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    //! The driver on systems with closed-form switching times: a bouncing ball (impacts with
    //! restitution) and a block sliding to rest under Coulomb friction.
    use super::*;
    use crate::solve::Dynamics;

    const G: f64 = 9.81;

    /// A ball: state (height, velocity); one mode, guard: height reaches 0; jump: v -> -e v.
    struct Ball {
        e: f64,
    }
    struct Fall;
    impl Dynamics<2> for Fall {
        fn rhs(&self, y: &State<2>, dy: &mut State<2>) {
            dy[0] = y[1];
            dy[1] = -G;
        }
    }
    impl Hybrid<2> for Ball {
        type Mode = ();
        type Flow<'a> = Fall;
        fn flow(&self, _: &()) -> Fall {
            Fall
        }
        fn guards<'a>(&'a self, _: &()) -> Vec<Event<'a, 2>> {
            // At the bounce the height is 0 and rising: the guard is the height while falling.
            vec![Event::new(
                "lands",
                |y: &State<2>| {
                    if y[1] > 0.0 {
                        1.0
                    } else {
                        y[0]
                    }
                },
            )]
        }
        fn jump(&self, _: &(), _: usize, y: &State<2>) -> Jump<(), 2> {
            Jump::To {
                mode: (),
                y: State::<2>::new(0.0, -self.e * y[1]),
                what: "bounce".into(),
            }
        }
    }
    fn settings() -> Settings {
        Settings::dop853(1e-12, 1e-14)
    }

    #[test]
    fn bounces_happen_at_their_closed_form_times() {
        let ball = Ball { e: 0.5 };
        let h0: f64 = 1.0;
        let sol = run_hybrid(
            HybridProblem::new(&ball, (), 0.0, State::<2>::new(h0, 0.0), 2.0),
            &settings(),
        )
        .unwrap();
        // First landing at sqrt(2 h0 / g); each later flight lasts e times the one before.
        let t1 = (2.0 * h0 / G).sqrt();
        let mut expected = vec![t1];
        let mut flight = 2.0 * t1 * ball.e;
        while expected.len() < 4 {
            expected.push(expected.last().unwrap() + flight);
            flight *= ball.e;
        }
        assert!(sol.switches.len() >= 4, "{:?}", sol.switches);
        for (s, t) in sol.switches.iter().zip(&expected) {
            assert!((s.t - t).abs() < 1e-9, "switch at {} vs {t}", s.t);
        }
    }

    #[test]
    fn a_zeno_cascade_halts_with_a_reason() {
        let ball = Ball { e: 0.5 };
        let mut p = HybridProblem::new(&ball, (), 0.0, State::<2>::new(1.0, 0.0), 5.0);
        p.max_switches = 30;
        let sol = run_hybrid(p, &settings()).unwrap();
        assert!(
            matches!(sol.ending, Ending::Halted { .. }),
            "{:?}",
            sol.ending
        );
        assert_eq!(sol.switches.len(), 30);
    }

    /// A block on a table: state (x, v); modes slide (+1 or -1 direction) and stick.
    struct Block {
        mu: f64,
    }
    #[derive(Debug, Clone, Copy, PartialEq)]
    enum BlockMode {
        Slide(f64),
        Stick,
    }
    struct BlockFlow(f64);
    impl Dynamics<2> for BlockFlow {
        fn rhs(&self, y: &State<2>, dy: &mut State<2>) {
            dy[0] = y[1];
            dy[1] = self.0;
        }
    }
    impl Hybrid<2> for Block {
        type Mode = BlockMode;
        type Flow<'a> = BlockFlow;
        fn flow(&self, m: &BlockMode) -> BlockFlow {
            BlockFlow(match m {
                BlockMode::Slide(s) => -self.mu * G * s,
                BlockMode::Stick => 0.0,
            })
        }
        fn guards<'a>(&'a self, m: &BlockMode) -> Vec<Event<'a, 2>> {
            match *m {
                BlockMode::Slide(s) => vec![Event::new("stops", move |y: &State<2>| s * y[1])],
                BlockMode::Stick => vec![],
            }
        }
        fn jump(&self, _: &BlockMode, _: usize, y: &State<2>) -> Jump<BlockMode, 2> {
            Jump::To {
                mode: BlockMode::Stick,
                y: *y,
                what: "slide -> stick".into(),
            }
        }
    }

    #[test]
    fn a_sliding_block_stops_where_coulomb_says() {
        let (mu, v0) = (0.3, 2.0);
        let block = Block { mu };
        let t_stop = v0 / (mu * G);
        let x_stop = v0 * v0 / (2.0 * mu * G);
        // Samples from the dense output (the default) and re-integrated from the step before
        // each, on one grid across the switch: both on the closed form at every sample.
        for dense in [true, false] {
            let mut p = HybridProblem::new(
                &block,
                BlockMode::Slide(1.0),
                0.0,
                State::<2>::new(0.0, v0),
                3.0,
            );
            p.sample = Some(0.01);
            p.dense_samples = dense;
            let sol = run_hybrid(p, &settings()).unwrap();
            assert_eq!(sol.switches.len(), 1);
            assert!((sol.switches[0].t - t_stop).abs() < 1e-10);
            let x_end = sol.y.last().unwrap()[0];
            assert!((x_end - x_stop).abs() < 1e-10, "{x_end}");
            for (t, y) in sol.t.iter().zip(&sol.y) {
                let tc = t.min(t_stop);
                let x = v0 * tc - 0.5 * mu * G * tc * tc;
                assert!((y[0] - x).abs() < 1e-10, "dense {dense}: x({t}) = {}", y[0]);
            }
            // Samples on the global grid, across both segments, and the end.
            assert_eq!(sol.t.len(), 302, "{}", sol.t.len());
            for w in sol.t.windows(2) {
                assert!(w[1] >= w[0]);
            }
            assert_eq!(*sol.t.last().unwrap(), 3.0);
        }
    }
}
