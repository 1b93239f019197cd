//! Fuzzes the budgets: an arbitrary wall-time budget (from bytes, any f64) and a built-in
//! scene with an arbitrary end time must give a refusal of the budget, a run, or a run ended by
//! the budget that says so, never a panic. The twin in the suite is
//! `tests/hostile/budgets.rs` (`no_budget_makes_a_check_panic`).
#![no_main]

use libfuzzer_sys::fuzz_target;
use physics::scene::Scene;

const SCENES: &[&str] = &["spinning-coin", "slip-stick", "nutating-coin", "vertical-spin"];

fuzz_target!(|data: &[u8]| {
    if data.len() < 17 {
        return;
    }
    let seconds = f64::from_le_bytes(data[0..8].try_into().unwrap_or([0; 8]));
    let end = f64::from_le_bytes(data[8..16].try_into().unwrap_or([0; 8]));
    let name = SCENES[data[16] as usize % SCENES.len()];
    if physics::budget::set_wall_seconds(seconds).is_err() {
        return;
    }
    let Ok(mut scene) = Scene::load(name) else {
        return;
    };
    if !(end.is_finite() && end > 0.0 && end < 0.5) {
        return;
    }
    scene.stop.time = end;
    if let Ok(r) = physics::run::run(&scene, None) {
        let _ = r.ending.to_string();
    }
});
