//! One pipeline: the full report computes each study once, and building it from the results,
//! or timed study by study (`report -v`), gives the same report to the byte.

use checks::equations::Bench;
use report::render;

/// One pipeline: a full report computes every study exactly once, and building the report
/// from those results (which computes nothing) gives the report `build` gives.
#[test]
fn a_full_report_computes_each_study_once() {
    use report::build::from_results;
    use report::pipeline::{compute, RunConfig};
    use report::study;
    let results = compute(&RunConfig::report(Bench::default()), &|_| {}).unwrap();
    crate::common::assert_computed_once(&results, study::names(study::ALL));
    let (report, figures) = from_results(&Bench::default(), &results, &|_| {}).unwrap();
    // The figures of the studies, and the premises graph drawn from the checks.
    assert_eq!(figures.len(), report::figures::names().len() + 1);
    assert_eq!(&render::json(&report).unwrap(), &super::built().3);
    assert_eq!(&render::html(&report).unwrap(), &super::built().0);
}

/// `report -v`: the studies timed one after another, each study and each stage after them
/// with its wall and CPU seconds, and the same report to the byte.
#[test]
fn a_timed_report_is_the_same_report_with_a_timing_per_study_and_stage() {
    use report::build::build_timed;
    use report::timing::Timings;
    let timings = Timings::new();
    let (report, figures) = build_timed(&Bench::default(), &|_| {}, &timings).unwrap();
    assert_eq!(&render::json(&report).unwrap(), &super::built().3);
    assert_eq!(&render::html(&report).unwrap(), &super::built().0);
    assert_eq!(figures.len(), super::built().2.len());
    let rows = timings.rows();
    let names: Vec<&str> = rows.iter().map(|r| r.name.as_str()).collect();
    for s in report::study::names(report::study::ALL)
        .into_iter()
        .chain(["figures", "parts", "document"])
    {
        assert_eq!(
            names.iter().filter(|n| **n == s).count(),
            1,
            "{s}: {names:?}"
        );
    }
    assert!(
        rows.iter().all(|r| r.wall >= 0.0 && r.cpu >= 0.0),
        "{rows:?}"
    );
    // The checks integrate: they take measurable CPU time.
    assert!(
        rows.iter().any(|r| r.name == "checks" && r.cpu > 0.0),
        "{rows:?}"
    );
}
