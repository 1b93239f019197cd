//! The parallel sweeps (rayon) give the same results whatever the number of threads.

use checks::check::{run_checks, Selection};
use checks::equations::Bench;
use checks::mutation::mutation_scores;

#[test]
fn checks_do_not_depend_on_the_thread_count() {
    let bench = Bench::default();
    let only = Selection::parse("23-30,60-63").unwrap();
    let one = run_checks(&bench, &only, 1, &|_, _| {}).unwrap();
    let three = run_checks(&bench, &only, 3, &|_, _| {}).unwrap();
    assert!(!one.is_empty());
    assert_eq!(
        serde_json::to_string(&one).unwrap(),
        serde_json::to_string(&three).unwrap()
    );
}

#[test]
fn mutation_scores_do_not_depend_on_the_thread_count() {
    let bench = Bench::default();
    let score = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| mutation_scores(&bench, &[23, 24], &|_, _| {}))
    };
    let (one, three) = (score(1), score(3));
    assert!(one.iter().any(|s| s.mutants > 0));
    assert_eq!(
        serde_json::to_string(&one).unwrap(),
        serde_json::to_string(&three).unwrap()
    );
}
