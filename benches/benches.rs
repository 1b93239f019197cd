//! Every benchmark of the workspace in one target (`harness = false`), one module of
//! [`suite`] per subject.
//!
//! ```text
//! cargo bench --bench benches                       # every criterion benchmark
//! cargo bench --bench benches -- sampling           # those whose name holds "sampling"
//! cargo bench --bench benches -- --scipy-reference  # the Rust side of scripts/compare
//! ROLLING_DISK_BENCH=scipy-reference cargo bench --bench benches   # the same
//! ```
//!
//! The scipy_reference run (see [`suite::scipy_reference`]) is not a criterion benchmark: it
//! prints one JSON document and takes its own options (`--scene NAME`, `--drift`, `--study`,
//! `--quick`) after `--scipy-reference`.

use criterion::Criterion;

mod suite;

/// The flag, and the value of `ROLLING_DISK_BENCH`, that run scipy_reference instead of the
/// criterion benchmarks.
const SCIPY_REFERENCE: &str = "scipy-reference";

fn main() {
    let flag = format!("--{SCIPY_REFERENCE}");
    let by_flag = std::env::args().any(|a| a == flag);
    let by_env = std::env::var("ROLLING_DISK_BENCH").is_ok_and(|v| v == SCIPY_REFERENCE);
    if by_flag || by_env {
        suite::scipy_reference::main();
        return;
    }
    let mut c = Criterion::default().configure_from_args();
    suite::rhs::all(&mut c);
    suite::solver::all(&mut c);
    suite::solver_steps::all(&mut c);
    suite::scenes::all(&mut c);
    suite::sampling::all(&mut c);
    suite::sliding::all(&mut c);
    suite::check::all(&mut c);
    suite::report::all(&mut c);
    suite::experiment::all(&mut c);
    c.final_summary();
}
