//! Running a scene: build the model with only the states it needs, integrate, record.

mod contact_watch;
mod csv;
pub mod sliding;
mod table;

pub use csv::csv_row;
pub use table::{ContactLost, Run};

use crate::solve::Solution;

use crate::budget;
use crate::dispatch::{dispatch, problem, Visit};
use crate::model::{Model, Quantity};
use crate::scene::Scene;
use crate::solve::{held_samples, solve, Batch, Ending, SettingsError, State, BATCH};
use contact_watch::ContactWatch;
use std::cell::RefCell;

/// Runs a scene and holds its rows in [`Run::rows`]. `progress` receives the simulated time
/// now and then. A held run records at most [`budget::MAX_ROWS`] rows: a scene that samples
/// more finely is refused before integrating (by [`solve`]), and an unsampled run that takes
/// more steps is refused after it; [`run_streamed`] holds none and has no such limit.
pub fn run(scene: &Scene, progress: Option<&dyn Fn(f64)>) -> Result<Run, SettingsError> {
    if let Some(dt) = scene.sample {
        held_samples(scene.stop.time, dt)?;
    }
    let mut rows = Vec::new();
    let width = columns(scene).len();
    let mut hold = |batch: &[f64]| rows.extend(batch.chunks_exact(width).map(<[f64]>::to_vec));
    let mut r = record_run(scene, progress, &mut hold, true)?;
    r.rows = rows;
    Ok(r)
}

/// Takes each recorded row (the time, then the scene's quantities) as it is made.
pub type RowSink<'a> = &'a mut dyn FnMut(&[f64]);

/// Takes the recorded rows as they are made, one or more at a time: whole rows of
/// [`columns`]`(scene).len()` numbers each, back to back, in time order.
pub type RowsSink<'a> = &'a mut dyn FnMut(&[f64]);

/// Runs a scene and hands each recorded row to `sink` as it is made, holding none: the
/// returned [`Run`] has no [`Run::rows`], and [`Run::recorded`] counts them. A sampled run costs
/// one polynomial evaluation per sample and state (DOP853's dense output) and whatever the
/// recorded quantities cost.
pub fn run_streamed(
    scene: &Scene,
    progress: Option<&dyn Fn(f64)>,
    sink: RowSink<'_>,
) -> Result<Run, SettingsError> {
    let width = columns(scene).len();
    let mut each = |rows: &[f64]| rows.chunks_exact(width).for_each(&mut *sink);
    record_run(scene, progress, &mut each, true)
}

/// [`run_streamed`] with the rows handed on as they are made together: those of one step's
/// samples in one call ([`RowsSink`]), so that a caller pays no call per row.
pub fn run_streamed_rows(
    scene: &Scene,
    progress: Option<&dyn Fn(f64)>,
    sink: RowsSink<'_>,
) -> Result<Run, SettingsError> {
    record_run(scene, progress, sink, true)
}

/// Runs a scene, handing each row to `sink`; DOP853's samples from its dense output when
/// `dense` (see [`crate::solve::Problem::dense_samples`]), otherwise each re-integrated from the
/// step before it.
fn record_run(
    scene: &Scene,
    progress: Option<&dyn Fn(f64)>,
    sink: RowsSink<'_>,
    dense: bool,
) -> Result<Run, SettingsError> {
    // The sliding model samples each segment of its hybrid run on that segment's dense output
    // (`HybridProblem::dense_samples`).
    if scene.model.has_coulomb_friction() {
        return sliding::run_streamed(scene, sink, dense);
    }
    dispatch(
        scene,
        Integrate {
            progress,
            sink,
            dense,
        },
    )
}

/// Integrates and records whatever model the scene builds.
struct Integrate<'p, 's> {
    progress: Option<&'p dyn Fn(f64)>,
    sink: RowsSink<'s>,
    dense: bool,
}

impl Visit for Integrate<'_, '_> {
    type Out = Result<Run, SettingsError>;

    fn visit<M: Model<N>, const N: usize>(self, model: &M, scene: &Scene) -> Self::Out {
        let y0 = model.state(&scene.start);
        // A sampled run looks for a loss of contact at its steps' ends and only then at the
        // rows of the steps next to a negative end; an unsampled run's rows are its steps, and
        // a run that records the normal force computes it at every row anyway.
        let watch = scene
            .sample
            .filter(|_| !scene.record.contains(&Quantity::NormalForce))
            .map(|dt| ContactWatch::new(model, 0.0, &y0, dt));
        let recorder = RefCell::new(Recorder::new(model, scene, &y0, self.sink, watch.as_ref()));
        let mut scratch = Vec::new();
        let mut step_end = |t: f64, y: &State<N>, dy: Option<&State<N>>| {
            if let Some(w) = &watch {
                w.step_end(model, t, y, dy, &mut scratch);
            }
        };
        let mut take_batch = |batch: &Batch<N>| recorder.borrow_mut().take_batch(batch);
        let mut p = problem(model, scene, y0, scene.stop.time);
        p.progress = self.progress;
        p.sample = scene.sample;
        p.dense_samples = self.dense;
        if scene.sample.is_some() {
            // Each step's samples come together, from one evaluation of its dense output over
            // all of them, and go on as one call of rows.
            p.on_batch = Some(&mut take_batch);
            p.on_step = Some(&mut step_end);
        }
        let sol = solve(p, &scene.settings)?;
        let mut recorder = recorder.into_inner();
        let rows = sol.t.len() as u64;
        if scene.sample.is_none() && rows > budget::MAX_ROWS {
            return Err(SettingsError::Rows {
                rows,
                limit: budget::MAX_ROWS,
                suggest: scene.stop.time / (budget::MAX_ROWS as f64 / 10.0),
            });
        }
        // The last point of a run stopped by an event (lift_off: F_z = 0) is the located zero,
        // whose sign is the root finder's: not a loss of contact within the run.
        let (n, stopped) = (sol.t.len(), matches!(sol.ending, Ending::Event { .. }));
        for (i, (t, y)) in sol.t.iter().zip(&sol.y).enumerate() {
            recorder.checks_contact = !(stopped && i + 1 == n);
            recorder.take(*t, y);
        }
        Ok(recorder.finish(&sol))
    }
}

/// Turns the states of a run into its rows, one at a time, keeping the energy's largest change
/// and the first loss of contact.
struct Recorder<'m, 's, M, const N: usize> {
    model: &'m M,
    scene: &'m Scene,
    columns: Vec<String>,
    e0: f64,
    energy_change: f64,
    contact_lost: Option<ContactLost>,
    /// Whether the next row may count as a loss of contact.
    checks_contact: bool,
    /// Which rows of a sampled run to check for a loss of contact (every row without it).
    watch: Option<&'m ContactWatch<N>>,
    recorded: u64,
    row: Vec<f64>,
    /// The rows of a batch, one after another.
    rows: Vec<f64>,
    sink: RowsSink<'s>,
}

impl<'m, 's, M: Model<N>, const N: usize> Recorder<'m, 's, M, N> {
    fn new(
        model: &'m M,
        scene: &'m Scene,
        y0: &State<N>,
        sink: RowsSink<'s>,
        watch: Option<&'m ContactWatch<N>>,
    ) -> Self {
        let columns = columns(scene);
        Self {
            model,
            scene,
            row: Vec::with_capacity(columns.len()),
            rows: Vec::with_capacity(BATCH * columns.len()),
            columns,
            e0: model.energy(y0),
            energy_change: 0.0,
            contact_lost: None,
            checks_contact: true,
            watch,
            recorded: 0,
            sink,
        }
    }

    /// Records one row. Each quantity is computed once: the energy (for the row and for the
    /// largest change) and the normal force (for the row and for the loss of contact, looked
    /// for until the first) are shared ([`Model::record_row`]), so a row costs what its
    /// quantities cost.
    fn take(&mut self, t: f64, y: &State<N>) {
        let looks = self.contact_lost.is_none()
            && self.checks_contact
            && self.watch.is_none_or(ContactWatch::armed);
        self.row.clear();
        self.row.push(t);
        let shared = self
            .model
            .record_row(y, &self.scene.record, looks, &mut self.row);
        if let Some(f) = shared.normal_force.filter(|&f| looks && f < 0.0) {
            self.contact_lost = Some(ContactLost { t, normal_force: f });
            if let Some(w) = self.watch {
                w.mark_found();
            }
        }
        (self.sink)(&self.row);
        self.recorded += 1;
        let energy = shared.energy;
        self.energy_change = self.energy_change.max(((energy - self.e0) / self.e0).abs());
    }

    /// Records the rows of a batch of samples, all of one step: as [`Recorder::take`] records
    /// each, but with each column computed over the batch ([`Model::record_rows`]), the
    /// normal force too where the rows are looked at for a loss of contact (the first row of
    /// the batch with $F_z < 0$ is the one [`Recorder::take`] row after row finds).
    fn take_batch(&mut self, batch: &Batch<N>) {
        let looks = self.contact_lost.is_none()
            && self.checks_contact
            && self.watch.is_none_or(ContactWatch::armed);
        let n = batch.len();
        let (mut energy, mut force) = ([0.0; BATCH], [f64::NAN; BATCH]);
        self.rows.clear();
        self.model.record_rows(
            batch,
            &self.scene.record,
            &mut self.rows,
            &mut energy,
            looks.then_some(&mut force),
        );
        let lost = looks.then(|| force[..n].iter().position(|&f| f < 0.0));
        if let Some(j) = lost.flatten() {
            self.contact_lost = Some(ContactLost {
                t: batch.times()[j],
                normal_force: force[j],
            });
            if let Some(w) = self.watch {
                w.mark_found();
            }
        }
        (self.sink)(&self.rows);
        self.recorded += n as u64;
        self.energy_change = self
            .energy_change
            .max(largest_change(&energy[..n], self.e0) / self.e0.abs());
    }

    fn finish(self, sol: &Solution<N>) -> Run {
        let (_, y_end) = sol.last();
        Run {
            scene: self.scene.name.clone(),
            model: self.scene.model,
            states: N,
            columns: self.columns,
            rows: Vec::new(),
            recorded: self.recorded,
            stats: sol.stats,
            ending: sol.ending.clone(),
            last: self.model.motion(&y_end),
            energy: (self.e0, self.model.energy(&y_end)),
            energy_change: self.energy_change,
            contact_events: Vec::new(),
            contact_lost: self.contact_lost,
        }
    }
}

/// The largest $|E_j - E_0|$ over a batch's energies; `NaN`s are passed over, as
/// [`f64::max`] passes them. Divided by $|E_0|$ it is the largest of the rows'
/// $|(E_j - E_0)/E_0|$ to the bit: $(E_j - E_0)/E_0$ and $|E_j - E_0|/|E_0|$ are the same
/// number up to sign, and a correctly rounded division by a positive number keeps the order of
/// its dividends, so the largest quotient is the quotient of the largest.
#[inline]
fn largest_change(energy: &[f64], e0: f64) -> f64 {
    let mut lanes = [0.0f64; 4];
    let mut chunks = energy.chunks_exact(4);
    for chunk in &mut chunks {
        for (m, &e) in lanes.iter_mut().zip(chunk) {
            let d = (e - e0).abs();
            *m = if d > *m { d } else { *m };
        }
    }
    let mut m = lanes[0].max(lanes[1]).max(lanes[2].max(lanes[3]));
    for &e in chunks.remainder() {
        m = m.max((e - e0).abs());
    }
    m
}

/// The columns a scene records, with units: the time, then each recorded quantity's.
pub fn columns(scene: &Scene) -> Vec<String> {
    let mut columns = vec!["t_s".to_string()];
    for q in &scene.record {
        columns.extend(q.columns().iter().map(|c| c.to_string()));
    }
    columns
}

impl Run {
    /// The run as CSV: a header of column names with units, then one row per recorded time
    /// ([`csv_row`]).
    pub fn to_csv(&self) -> String {
        let mut s = self.columns.join(",").into_bytes();
        s.push(b'\n');
        for row in &self.rows {
            csv_row(row, &mut s);
        }
        String::from_utf8(s).unwrap_or_default()
    }

    /// The values of one column.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let i = self.columns.iter().position(|c| c == name)?;
        Some(self.rows.iter().map(|r| r[i]).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::largest_change;

    /// The change over a batch, divided once, against each row's relative change kept row by
    /// row as a single row's recording keeps it: the same bits, with `NaN`s, zeros, infinities
    /// and a zero or `NaN` start among them.
    #[test]
    fn the_largest_change_over_a_batch_is_the_row_by_row_one_to_the_bit() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
        let odd = [f64::NAN, 0.0, -0.0, f64::INFINITY, 1e-310, 1e300];
        for trial in 0..20_000 {
            let e0 = match trial % 50 {
                0 => 0.0,
                1 => f64::NAN,
                2 => -3.0e-4,
                _ => rng.random_range(1e-6..1.0),
            };
            let n = rng.random_range(0..=32);
            let e: Vec<f64> = (0..n)
                .map(|_| match rng.random_range(0..40) {
                    0 => odd[rng.random_range(0..odd.len())],
                    1 => e0,
                    _ => e0 * (1.0 + rng.random_range(-1e-9..1e-9)),
                })
                .collect();
            let before = if trial % 3 == 0 {
                0.0
            } else {
                rng.random_range(0.0..1e-9)
            };
            let row_by_row = e
                .iter()
                .fold(before, |m: f64, &e| m.max(((e - e0) / e0).abs()));
            let batch = before.max(largest_change(&e, e0) / e0.abs());
            assert_eq!(batch.to_bits(), row_by_row.to_bits(), "e0 {e0:e}, {e:?}");
        }
    }
}
