//! A row recorded at once ([`Model::record_row`], what shares its work between columns) is the
//! row recorded column by column ([`Model::record`]), and rows recorded a batch at a time
//! ([`Model::record_rows`]) are those rows, to the bit, in every model a scene can build, in the
//! AVX2 build of the batch's loops where the processor has it and in the baseline one.

use crate::dispatch::{dispatch, problem, Visit};
use crate::model::{Model, Quantity};
use crate::scene::{builtin, ModelKind, Scene};
use crate::solve::{solve, Batch, State, BATCH};

/// Compares, on the states of the first 0.05 s of the scene's run, one row of every quantity
/// the model records against the same columns one at a time; returns the rows compared.
struct SameRow;

impl Visit for SameRow {
    type Out = usize;

    fn visit<M: Model<N>, const N: usize>(self, model: &M, scene: &Scene) -> usize {
        let y0 = model.state(&scene.start);
        let mut scratch = Vec::new();
        let quantities: Vec<Quantity> = Quantity::ALL
            .into_iter()
            .filter(|&q| model.record(&y0, q, &mut scratch))
            .collect();
        let sol = solve(problem(model, scene, y0, 0.05), &scene.settings).expect("it runs");
        let states: Vec<State<N>> = std::iter::once(y0).chain(sol.y).collect();
        for y in &states {
            let mut one_by_one = Vec::new();
            for &q in &quantities {
                assert!(model.record(y, q, &mut one_by_one));
            }
            let mut force = Vec::new();
            let has_force = model.record(y, Quantity::NormalForce, &mut force);
            for asked in [true, false] {
                let mut row = vec![-1.0];
                let shared = model.record_row(y, &quantities, asked, &mut row);
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                assert_eq!(
                    bits(&row[1..]),
                    bits(&one_by_one),
                    "{}: {quantities:?}",
                    scene.name
                );
                assert_eq!(row[0], -1.0, "{}: the row is appended to", scene.name);
                assert_eq!(shared.energy.to_bits(), model.energy(y).to_bits());
                let expected = (asked && has_force).then(|| force[0].to_bits());
                assert_eq!(
                    shared.normal_force.map(f64::to_bits),
                    expected,
                    "{}",
                    scene.name
                );
            }
        }
        // Rows in batches (with and without the contact force recorded, with and without the
        // normal force asked) against the rows one by one.
        let no_force: Vec<Quantity> = quantities
            .iter()
            .copied()
            .filter(|q| !matches!(q, Quantity::NormalForce | Quantity::Friction))
            .collect();
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        for asked in [&quantities, &no_force] {
            for force_asked in [false, true] {
                for chunk in states.chunks(BATCH - 3) {
                    let mut batch = Batch::default();
                    let mut one_by_one = Vec::new();
                    let (mut energies, mut forces) = (Vec::new(), Vec::new());
                    for (j, y) in chunk.iter().enumerate() {
                        let t = 0.01 * j as f64;
                        assert!(batch.push(t, y));
                        one_by_one.push(t);
                        let shared = model.record_row(y, asked, force_asked, &mut one_by_one);
                        energies.push(shared.energy);
                        forces.push(shared.normal_force.unwrap_or(f64::NAN));
                    }
                    let record = |rows: &mut Vec<f64>| {
                        let (mut energy, mut force) = ([0.0; BATCH], [-7.0; BATCH]);
                        model.record_rows(
                            &batch,
                            asked,
                            rows,
                            &mut energy,
                            force_asked.then_some(&mut force),
                        );
                        (energy, force)
                    };
                    let mut rows = vec![-1.0];
                    let (energy, force) = record(&mut rows);
                    // The baseline build of the same loops (the one above is AVX2's where
                    // the processor has it).
                    let mut baseline = vec![-1.0];
                    let (baseline_energy, baseline_force) =
                        numerics::wider::baseline_only(|| record(&mut baseline));
                    let k = chunk.len();
                    let name = &scene.name;
                    assert_eq!(bits(&baseline), bits(&rows), "{name}: baseline");
                    assert_eq!(bits(&baseline_energy[..k]), bits(&energy[..k]), "{name}");
                    assert_eq!(bits(&baseline_force[..k]), bits(&force[..k]), "{name}");
                    assert_eq!(rows[0], -1.0, "{name}: the rows are appended to");
                    assert_eq!(bits(&rows[1..]), bits(&one_by_one), "{name}: {asked:?}");
                    assert_eq!(bits(&energy[..k]), bits(&energies), "{name}");
                    if force_asked {
                        assert_eq!(bits(&force[..k]), bits(&forces), "{name}: F_z");
                    } else {
                        assert!(force.iter().all(|&f| f == -7.0), "{name}: F_z not asked");
                    }
                }
            }
        }
        states.len()
    }
}

#[test]
fn a_row_recorded_at_once_is_its_columns_recorded_one_by_one_in_every_model() {
    let mut models = Vec::new();
    for (name, src) in builtin::BUILTIN {
        let base = Scene::parse(src, &format!("{name}.yaml")).expect("a built-in scene");
        for kind in [None, Some(ModelKind::LabFrame)] {
            let mut scene = base.clone();
            if let Some(k) = kind {
                if scene.model != ModelKind::Rolling {
                    continue;
                }
                scene.model = k;
            }
            // Every quantity asked, so that the model carries every optional state.
            scene.record = Quantity::ALL.to_vec();
            let rows = dispatch(&scene, SameRow);
            assert!(rows > 1, "{name}: no state compared");
            models.push(scene.model);
        }
    }
    for kind in [
        ModelKind::Rolling,
        ModelKind::Dissipative,
        ModelKind::Frictionless,
        ModelKind::Adiabatic,
        ModelKind::LabFrame,
        ModelKind::Sliding,
    ] {
        assert!(models.contains(&kind), "no built-in scene of {kind:?}");
    }
}
