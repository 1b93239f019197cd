//! `precision` on a built-in scene with mode switches (`slip-stick`, which slides, sticks and
//! slides again): every integrator's run is measured over the whole run, its switches located
//! as events, or it ends with a reason; none gives up at a switch, and the study costs under
//! 5 s of processor time (wall time on a shared machine is bounded at 60 s only to catch a hang).

use super::sandbox::bounded;
use crate::common::temp_dir;
use std::time::Duration;

#[test]
fn precision_on_a_scene_with_mode_switches_measures_the_whole_run_in_under_5_s() {
    let dir = temp_dir("hostile", "precision");
    let ran = bounded(
        &dir,
        &["precision", "slip-stick", "--quick"],
        Duration::from_secs(60),
    );
    assert!(ran.ok, "{}", ran.stderr);
    println!(
        "{}\nprocessor time {:?}, wall {:?}",
        ran.stdout, ran.cpu, ran.took
    );
    assert!(
        ran.cpu < Duration::from_secs(5),
        "{:?} of processor time",
        ran.cpu
    );
    assert!(ran.cpu > Duration::ZERO, "no processor time read");
    let rows: Vec<&str> = ran
        .stdout
        .lines()
        .filter(|l| l.starts_with("dopri5 ") || l.starts_with("dop853 ") || l.starts_with("rk4 "))
        .collect();
    assert!(rows.len() >= 12, "{}", ran.stdout);
    for row in &rows {
        assert!(
            !row.contains("gave up") && !row.contains("became stiff"),
            "a run gave up: {row}"
        );
        // The adaptive methods reach the end; a fixed step either reaches it or says why not.
        let adaptive = !row.starts_with("rk4 ");
        assert!(
            row.ends_with("reached the end time") || (!adaptive && row.contains("went unstable")),
            "{row}"
        );
    }
    // Their orders fitted over the whole run, near the nominal ones.
    for (method, nominal) in [("dopri5", 5.0), ("dop853", 8.0)] {
        let order: f64 = ran
            .stdout
            .lines()
            .find_map(|l| l.trim().strip_prefix(&format!("{method}: observed order ")))
            .and_then(|r| r.split_whitespace().next())
            .and_then(|v| v.parse().ok())
            .unwrap_or(f64::NAN);
        assert!(order >= nominal - 0.5, "{method}: order {order}");
    }
}
