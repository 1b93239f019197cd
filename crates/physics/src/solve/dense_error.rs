//! The error of DOP853's dense output, against integrations that land on the sample.
//!
//! A sampled run writes each sample from the interpolant $y(t_{\mathrm{old}} + \theta h)$ of
//! the step that holds it (order 7). Here every accepted step of a run is interpolated at random
//! $\theta \in (0, 1)$ and compared with a run of the same tolerances started at the step's
//! start that lands on the same time, in the error control's own scale
//! $\max_i |y_{\mathrm{dense},i} - y_{\mathrm{land},i}| / (\mathrm{atol} + \mathrm{rtol}
//! \max(|y_{a,i}|, |y_{b,i}|))$: the interpolant is as accurate as the tolerance asks when this
//! stays of order 1. A cubic Hermite interpolant on the same steps (order 3, what a sampler
//! without dense output would use) fails the same bound, so the bound tells the two apart.

use super::dop853::{Dop853, Outcome};
use super::driver::dense_tolerances;
use super::{Dynamics, State};
use crate::dispatch::{dispatch, sliding_model, Visit};
use crate::model::sliding::{Flow, Mode};
use crate::model::Model;
use crate::scene::{builtin, Scene};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use super::arenstorf::{start as arenstorf_start, Arenstorf, PERIOD};

/// The largest difference over a run's steps from `y0` over `span` between an interpolant and
/// landing runs, in the scale of the tolerance asked (`rtol`, `atol` = `rtol`): (dense output,
/// cubic Hermite). The run integrates at the tolerances of a run that samples on its dense
/// output ([`dense_tolerances`]); each landing run at those too, from the step's start.
fn worst_errors<D: Dynamics<N>, const N: usize>(
    f: &D,
    y0: State<N>,
    span: f64,
    rtol: f64,
    samples_per_step: usize,
    tighten: bool,
) -> (f64, f64) {
    let atol = rtol;
    let (rtol_run, atol_run) = if tighten {
        dense_tolerances(rtol, atol)
    } else {
        (rtol, atol)
    };
    let mut rng = ChaCha8Rng::seed_from_u64(49);
    let mut s = Dop853::new(f, rtol_run, atol_run, 0.0, y0, span);
    let (mut dense_worst, mut hermite_worst) = (0.0_f64, 0.0_f64);
    while s.t < span {
        let (t_a, y_a) = (s.t, s.y);
        assert_eq!(s.step(span), Outcome::Accepted);
        let (t_b, y_b) = (s.t, s.y);
        let d = s.dense();
        let h = t_b - t_a;
        let (mut f_a, mut f_b) = (State::<N>::zeros(), State::<N>::zeros());
        f.rhs(&y_a, &mut f_a);
        f.rhs(&y_b, &mut f_b);
        for _ in 0..samples_per_step {
            let theta: f64 = rng.random_range(0.05..0.95);
            let t = t_a + theta * h;
            let mut land = Dop853::with_first_step(f, rtol_run, atol_run, t_a, y_a, t - t_a);
            while land.t < t {
                assert_eq!(land.step(t), Outcome::Accepted);
            }
            // Cubic Hermite on the step's ends and slopes.
            let (h00, h10) = (
                (1.0 + 2.0 * theta) * (1.0 - theta).powi(2),
                theta * (1.0 - theta).powi(2),
            );
            let (h01, h11) = (
                theta * theta * (3.0 - 2.0 * theta),
                theta * theta * (theta - 1.0),
            );
            let hermite = y_a * h00 + f_a * (h * h10) + y_b * h01 + f_b * (h * h11);
            let dense = d.at(t);
            for i in 0..N {
                let sk = atol + rtol * y_a[i].abs().max(y_b[i].abs());
                dense_worst = dense_worst.max((dense[i] - land.y[i]).abs() / sk);
                hermite_worst = hermite_worst.max((hermite[i] - land.y[i]).abs() / sk);
            }
        }
    }
    (dense_worst, hermite_worst)
}

/// The interpolant's error, in the scale of the tolerance asked, stays below this at every
/// tolerance: of the tolerance's order. Integrated at the tolerance asked, the interpolant
/// (local error $O(h^8)$, against the step's $O(h^9)$) would reach 2.8, 17 and 46 tolerances on
/// Arenstorf's orbit at rtol 1e-6, 1e-9 and 1e-12; [`dense_tolerances`] tightens the run so
/// that it stays of the tolerance's order.
const BOUND: f64 = 3.0;

#[test]
fn the_dense_output_is_as_accurate_as_the_tolerance_asks() {
    let y0 = arenstorf_start();
    for rtol in [1e-6, 1e-9, 1e-12] {
        let (dense, hermite) = worst_errors(&Arenstorf, y0, PERIOD, rtol, 4, true);
        eprintln!("rtol {rtol:.0e}: dense output {dense:.3}, cubic Hermite {hermite:.3e}");
        assert!(
            dense < BOUND,
            "rtol {rtol}: dense output off by {dense} tolerances"
        );
        assert!(
            hermite > BOUND,
            "rtol {rtol}: a cubic interpolant passes too ({hermite}): the bound tells nothing"
        );
    }
}

/// Runs [`worst_errors`] on the model a scene builds, over its first `span` seconds.
struct OnModel {
    span: f64,
    rtol: f64,
}

impl Visit for OnModel {
    type Out = f64;

    fn visit<M: Model<N>, const N: usize>(self, model: &M, scene: &Scene) -> f64 {
        worst_errors(
            model,
            model.state(&scene.start),
            self.span,
            self.rtol,
            3,
            true,
        )
        .0
    }
}

fn scene(name: &str, model: Option<&str>) -> Scene {
    let mut src = builtin::source(name).unwrap().to_string();
    if let Some(m) = model {
        let from = src
            .lines()
            .find(|l| l.starts_with("model:"))
            .unwrap()
            .to_string();
        src = src.replace(&from, &format!("model: {m}"));
    }
    Scene::parse(&src, name).unwrap()
}

/// Every model's samples (rolling, the lab frame, frictionless, the sliding model in each of
/// its modes) are as accurate as the tolerance asks at random times of every step.
#[test]
fn every_model_samples_its_dense_output_to_the_tolerance() {
    for rtol in [1e-6, 1e-9, 1e-12] {
        for (name, model) in [
            ("nutating-coin", None),
            ("nutating-coin", Some("lab-frame")),
            ("vertical-spin-frictionless", None),
        ] {
            let worst = dispatch(&scene(name, model), OnModel { span: 1.0, rtol });
            eprintln!("{name} {model:?} rtol {rtol:.0e}: dense output {worst:.3}");
            assert!(worst < BOUND, "{name} {model:?} rtol {rtol}: {worst}");
        }
        let s = scene("slip-stick", None);
        let sliding = sliding_model(&s);
        let (start_mode, y0) = sliding.enter_contact(&sliding.start_state(&s.start));
        for mode in [Mode::Stick, start_mode] {
            let flow = Flow {
                model: &sliding,
                mode,
            };
            let (worst, _) = worst_errors(&flow, y0, 0.2, rtol, 3, true);
            eprintln!("slip-stick {mode:?} rtol {rtol:.0e}: dense output {worst:.3}");
            assert!(worst < BOUND, "slip-stick {mode:?} rtol {rtol}: {worst}");
        }
    }
}

/// A sliding run across its mode switches, sampled as `simulate` samples it (each segment on
/// its dense output): every segment's first second, from the state the switch leaves,
/// interpolated at random times of its steps against runs that land there.
#[test]
fn the_sliding_model_samples_its_dense_output_across_its_switches() {
    use crate::run::sliding::integrate_sampled;
    use crate::solve::Settings;
    let mut s = scene("slip-stick", None);
    for rtol in [1e-6, 1e-9, 1e-12] {
        s.settings = Settings::dop853(rtol, rtol);
        let model = sliding_model(&s);
        let run = integrate_sampled(&model, &s, Some(1e-3), true).unwrap();
        assert!(run.switches.len() >= 2, "{} switches", run.switches.len());
        let mut ends: Vec<f64> = run.switches.iter().map(|w| w.t).collect();
        ends.push(*run.t.last().unwrap());
        for (k, w) in run.switches.iter().enumerate() {
            // The state the switch leaves: the last point at its time (the jump's, or the
            // segment's end where the jump keeps the state).
            let j = (0..run.t.len())
                .rfind(|&j| run.t[j] == w.t)
                .expect("the switch's point");
            let flow = Flow {
                model: &model,
                mode: w.to,
            };
            // The first second after the switch, as for every model above.
            let span = (ends[k + 1] - w.t).min(1.0);
            let (worst, _) = worst_errors(&flow, run.y[j], span, rtol, 3, true);
            eprintln!("slip-stick rtol {rtol:.0e}, after switch {k} ({:?}, {span:.3} s): dense output {worst:.3}", w.to);
            assert!(
                worst < BOUND,
                "slip-stick rtol {rtol}, after switch {k}: {worst}"
            );
        }
    }
}
