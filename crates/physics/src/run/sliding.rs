//! A scene with `model: sliding`: run the model built by [`sliding_model`] through the hybrid
//! driver and record the scene's quantities in the mode of each recorded point.

use super::table::Run;
use super::RowSink;
use crate::dispatch::sliding_model;
use crate::events::PointSink;
use crate::model::sliding::contact_events::contact_events;
use crate::model::sliding::{Flow, Mode, Sliding, SlidingRun};
use crate::model::Model;
use crate::scene::Scene;
use crate::solve::{Event, SettingsError, State};
use std::f64::consts::{FRAC_PI_2, PI};

/// Runs a sliding scene, handing each recorded row to `sink` as it is made (see
/// [`super::run_streamed`]): the scene's stop events hold in every mode.
pub fn run_streamed(scene: &Scene, sink: RowSink<'_>, dense: bool) -> Result<Run, SettingsError> {
    let model = sliding_model(scene);
    let columns = super::columns(scene);
    // The run starts from the start state as contact takes it (see `Sliding::run`).
    let e0 = model.energy(&model.enter_contact(&model.start_state(&scene.start)).1);
    let mut energy_change: f64 = 0.0;
    let mut recorded: u64 = 0;
    let mut row = Vec::with_capacity(columns.len());
    let mut take = |t: f64, y: &State<14>, mode: &Mode| {
        let flow = Flow {
            model: &model,
            mode: *mode,
        };
        // The energy once, for the row and for the largest change.
        row.clear();
        row.push(t);
        let energy = flow.record_row(y, &scene.record, false, &mut row).energy;
        sink(&row);
        recorded += 1;
        energy_change = energy_change.max(((energy - e0) / e0).abs());
    };
    let sol = run_model(&model, scene, scene.sample, Some(&mut take), dense)?;
    let last = sol.y.len() - 1;
    let flow = Flow {
        model: &model,
        mode: sol.mode.get(last).copied().unwrap_or(Mode::Stick),
    };
    Ok(Run {
        scene: scene.name.clone(),
        model: scene.model,
        states: 14,
        columns,
        rows: Vec::new(),
        recorded,
        stats: sol.stats,
        ending: sol.ending.clone(),
        last: flow.motion(&sol.y[last]),
        energy: (e0, model.energy(&sol.y[last])),
        energy_change,
        contact_events: contact_events(&sol),
        contact_lost: None,
    })
}

/// Integrates `model` (built by [`model`]) from the scene's start to its stop, sampled every
/// `sample` seconds if given: the scene's stop events (the disk flat on the table, `alpha_below`)
/// hold in every mode.
pub fn integrate(
    model: &Sliding,
    scene: &Scene,
    sample: Option<f64>,
) -> Result<SlidingRun, SettingsError> {
    run_model(model, scene, sample, None, true)
}

/// [`integrate`] with its samples from the dense output when `dense`, otherwise each
/// re-integrated from the step before it (on the steps of the unsampled run).
pub fn integrate_sampled(
    model: &Sliding,
    scene: &Scene,
    sample: Option<f64>,
    dense: bool,
) -> Result<SlidingRun, SettingsError> {
    run_model(model, scene, sample, None, dense)
}

/// [`integrate`], handing every point to `on_point` instead of holding it: the run returned
/// keeps its switches and its last point only, so a record of any length fits in memory.
pub fn integrate_into(
    model: &Sliding,
    scene: &Scene,
    sample: Option<f64>,
    on_point: PointSink<'_, Mode, 14>,
) -> Result<SlidingRun, SettingsError> {
    run_model(model, scene, sample, Some(on_point), true)
}

/// [`integrate`], handing every point to `on_point` instead of holding it.
fn run_model(
    model: &Sliding,
    scene: &Scene,
    sample: Option<f64>,
    mut on_point: Option<PointSink<'_, Mode, 14>>,
    dense: bool,
) -> Result<SlidingRun, SettingsError> {
    let alpha = |y: &State<14>| tilt(y);
    let below = scene.stop.alpha_below;
    let thick = model.toy.solid.is_some();
    let side = if scene.start.alpha < FRAC_PI_2 {
        1.0
    } else {
        -1.0
    };
    let stops = move || {
        let mut v = vec![
            Event::new("the disk fell flat on the table (alpha reached 0)", alpha),
            Event::new(
                "the disk fell flat on the table (alpha reached pi)",
                move |y: &State<14>| PI - alpha(y),
            ),
        ];
        if thick {
            v.push(Event::new(
                "the thick disk reached the vertical, where it stands on a line (the point \
                 contact model ends)",
                move |y: &State<14>| side * (FRAC_PI_2 - alpha(y)),
            ));
        }
        if let Some(b) = below {
            v.push(Event::new(
                format!("alpha fell below {b} rad"),
                move |y: &State<14>| alpha(y) - b,
            ));
        }
        v
    };
    let y0 = model.start_state(&scene.start);
    let on_point: Option<PointSink<'_, Mode, 14>> = match on_point.as_mut() {
        Some(p) => Some(&mut **p),
        None => None,
    };
    model.run_into(
        &y0,
        scene.stop.time,
        &scene.settings,
        sample,
        &stops,
        on_point,
        dense,
    )
}

/// The paper's $\alpha$ straight from the quaternion (the stop events are evaluated at every
/// step end, so they skip the full snapshot of the geometry): the symmetry axis in the lab is
/// $\hat{\mathbf n} = R\,\mathbf e_x$, $\cos\alpha = -n_z$, $\sin\alpha = |\mathbf n_h|$.
fn tilt(y: &State<14>) -> f64 {
    let (w, i, j, k) = (y[0], y[1], y[2], y[3]);
    let q2 = w * w + i * i + j * j + k * k;
    let nx = (w * w + i * i - j * j - k * k) / q2;
    let ny = 2.0 * (i * j + w * k) / q2;
    let nz = 2.0 * (i * k - w * j) / q2;
    nx.hypot(ny).atan2(-nz)
}
