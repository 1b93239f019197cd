//! The synthetic experiment's spin-down in the sliding model: the lab-frame disk with Coulomb
//! friction, lift-off and landing ([`physics::model::sliding`]), losing energy by eq 75's law as a
//! drag torque. Where the rolling model must roll to the end, this disk may slip, leave the
//! table and land before its tilt reaches the floor: recordings from both models.
//!
//! What the light and the microphone see is the upper face's normal. The sliding model carries
//! the disk's orientation as a quaternion, whose symmetry axis $\hat{\mathbf 1} = R\,\mathbf e_x$
//! gives the upper normal $\hat{\mathbf n} = -\hat{\mathbf 1}$, and from it the paper's tilt and
//! the heading of the light model ([`crate::synthetic::light`]):
//! $$\hat{\mathbf n} = (\sin\alpha\sin\psi,\ -\sin\alpha\cos\psi,\ \cos\alpha), \qquad
//!   \alpha = \operatorname{atan2}(|\hat{\mathbf n}_h|, n_z), \quad \psi = \operatorname{atan2}(n_x, -n_y),$$
//! with $\psi$ unwrapped from sample to sample (it turns by $\Omega\,\Delta t$, far less than
//! $\pi$ per sample at any rate that resolves the signal).

use crate::error::ExperimentError;
use crate::trace::Motion;
use crate::trace::Truth;
use physics::dispatch::sliding_model;
use physics::model::dissipation::PowerLaw;
use physics::model::lab_frame::Snapshot;
use physics::model::sliding::contact_events::contact_events;
use physics::model::sliding::{Flow, Mode};
use physics::model::Model;
use physics::run::sliding::integrate_into;
use physics::scene::Scene;
use physics::solve::{Ending, State};
use std::f64::consts::{PI, TAU};

/// Integrates a sliding scene (validated by [`crate::synthetic::simulate::simulate_motion`])
/// once, sampled at `rate` from its start, and keeps the `samples` grid points of the record
/// that ends at record time `end_at` (the record starts on the first grid point at or after
/// $t_{stop} - $ `end_at`, so the spin-down ends at most one sample before `end_at`).
pub fn sliding_motion(
    scene: &Scene,
    law: PowerLaw,
    end_at: f64,
    rate: f64,
    samples: usize,
) -> Result<Motion, ExperimentError> {
    let scene_err = |message: String| ExperimentError::in_scene(&scene.name, message);
    let m = sliding_model(scene);
    let dt = 1.0 / rate;
    // The record's grid points, taken as the run makes them: two numbers a sample are kept,
    // not the run's whole state, so the row limit of a held run does not apply. The record
    // starts a whole number of samples before the stop, which is known only at the end, so
    // every grid point from the start of the run is kept.
    let mut alpha_all = Vec::new();
    let mut heading_all = Vec::new();
    let mut unwrap = Unwrap::default();
    let mut take = |t: f64, y: &State<14>, _: &Mode| {
        let k = t / dt;
        let j = k.round();
        // Switches and the stop are off the grid: only grid points are samples.
        if (k - j).abs() > 1e-6 || (j as usize) < alpha_all.len() {
            return;
        }
        let s = Snapshot::of(scene.disk.a, y);
        let n = -s.e1;
        alpha_all.resize(j as usize, f64::NAN);
        heading_all.resize(j as usize, f64::NAN);
        alpha_all.push(n.x.hypot(n.y).atan2(n.z));
        heading_all.push(unwrap.next(n.x.atan2(-n.y)));
    };
    let run =
        integrate_into(&m, scene, Some(dt), &mut take).map_err(|e| scene_err(e.to_string()))?;
    let Ending::Event { t: t_stop, .. } = run.ending else {
        return Err(scene_err(format!(
            "the spin-down did not end ({}); raise stop.time or alpha_below",
            run.ending
        )));
    };
    let first = (t_stop - end_at) / dt;
    if first <= 0.0 {
        return Err(scene_err(format!(
            "the spin-down lasts {t_stop:.3} s, but the record starts {end_at} s before its end: \
             start at a larger alpha0 or lower epsilon"
        )));
    }
    let first = first.ceil() as usize;
    let t_start = first as f64 * dt;
    let window = |v: &[f64]| -> Vec<f64> {
        (0..samples)
            .map(|j| v.get(first + j).copied().unwrap_or(f64::NAN))
            .collect()
    };
    let alpha = window(&alpha_all);
    let heading = window(&heading_all);

    let last = run.y.len() - 1;
    let flow = Flow {
        model: &m,
        mode: run.mode.get(last).copied().unwrap_or(Mode::Stick),
    };
    let end = flow.motion(&run.y[last]);
    let events = contact_events(&run);
    let slips = events.iter().filter(|e| e.to == "slip").count();
    let flights = events.iter().filter(|e| e.to == "flight").count();
    let impacts = events
        .iter()
        .filter(|e| e.what.starts_with("impact"))
        .count();
    let first_slip = events
        .iter()
        .find(|e| e.to == "slip")
        .map_or(String::from("never slips"), |e| {
            format!("first slips at record time {:.4} s", e.t - t_start)
        });
    let friction = m.friction;
    Ok(Motion {
        t: (0..samples).map(|j| j as f64 * dt).collect(),
        alpha,
        heading,
        truth: Truth::at_stop(
            law.beta,
            t_stop - t_start,
            end.alpha.max(0.0),
            end.alpha_dot,
            format!(
                "sliding model, beta = {}, epsilon = {}, mu = {}, restitution = {}, scene {}: \
                 {first_slip}; {slips} slips, {flights} flights, {impacts} impacts",
                law.beta, law.epsilon, friction.mu, friction.restitution, scene.name
            ),
        ),
    })
}

/// Makes a heading continuous from its values in $(-\pi, \pi]$.
#[derive(Debug, Default)]
struct Unwrap {
    last: Option<f64>,
    turns: f64,
}

impl Unwrap {
    fn next(&mut self, wrapped: f64) -> f64 {
        if let Some(prev) = self.last {
            let d = wrapped - prev;
            if d > PI {
                self.turns -= TAU;
            } else if d < -PI {
                self.turns += TAU;
            }
        }
        self.last = Some(wrapped);
        wrapped + self.turns
    }
}

#[cfg(test)]
mod tests {
    use super::Unwrap;

    #[test]
    fn the_heading_is_unwrapped_both_ways() {
        let mut u = Unwrap::default();
        let up: Vec<f64> = [3.0, -3.0, -2.0].iter().map(|&x| u.next(x)).collect();
        assert!(
            (up[1] - (std::f64::consts::TAU - 3.0)).abs() < 1e-12,
            "{up:?}"
        );
        let mut u = Unwrap::default();
        let down: Vec<f64> = [-3.0, 3.0].iter().map(|&x| u.next(x)).collect();
        assert!(
            (down[1] - (3.0 - std::f64::consts::TAU)).abs() < 1e-12,
            "{down:?}"
        );
    }
}
