//! What a recorded sample costs: a scene run end to end as `simulate` runs it
//! ([`physics::run::run_streamed_rows`], the rows of a step handed on together) at one row per
//! 0.1 ms against one per 10 ms, for each model and event path (rolling with its stop events,
//! sliding with mode switches, frictionless, the lab frame), rows discarded; and a minute at
//! 48 kHz written as CSV to a file, row by row, as `simulate --csv` writes it.
//!
//! `cargo bench --bench benches -- sampling`; the ratio of the two rates is the price of sampling (the
//! target is at most 1.5).

use criterion::Criterion;
use physics::run::{csv_row, run_streamed, run_streamed_rows};
use physics::scene::Scene;
use std::hint::black_box;
use std::io::Write;

/// A built-in scene with its stop time and sampling interval replaced (and its model, if given).
fn scene(name: &str, time: f64, sample: f64, model: Option<&str>) -> Scene {
    let (_, src) = physics::scene::builtin::BUILTIN
        .iter()
        .find(|(n, _)| *n == name)
        .expect("a built-in scene");
    let mut yaml: String = src
        .lines()
        .map(|l| {
            if l.starts_with("stop:") {
                format!("stop: {{ time: {time} }}")
            } else if l.starts_with("sample:") {
                format!("sample: {sample:e}")
            } else if let (true, Some(m)) = (l.starts_with("model:"), model) {
                format!("model: {m}")
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    yaml.push('\n');
    Scene::parse(&yaml, &format!("{name}.yaml")).expect("a valid scene")
}

fn sampling(c: &mut Criterion) {
    let mut group = c.benchmark_group("sampling");
    group.sample_size(10);
    for (name, time, model) in [
        ("nutating-coin", 10.0, None),
        ("slip-stick", 2.0, None),
        ("vertical-spin-frictionless", 5.0, None),
        ("nutating-coin", 10.0, Some("lab-frame")),
    ] {
        for dt in [1e-2, 1e-4] {
            let s = scene(name, time, dt, model);
            let label = format!("{}/{time} s every {dt:e} s", model.unwrap_or(name));
            group.bench_function(label, |b| {
                b.iter(|| {
                    let mut n = 0u64;
                    let mut sink = |rows: &[f64]| n += black_box(rows).len() as u64;
                    black_box(run_streamed_rows(black_box(&s), None, &mut sink).expect("runs"));
                    n
                })
            });
        }
    }
    let minute = scene("nutating-coin", 60.0, 1.0 / 48_000.0, None);
    let path = std::env::temp_dir().join(format!("sampling-bench-{}.csv", std::process::id()));
    group.bench_function("nutating-coin/60 s at 48 kHz to CSV", |b| {
        b.iter(|| {
            let f = std::fs::File::create(&path).expect("a temporary file");
            let mut out = std::io::BufWriter::with_capacity(1 << 16, f);
            let mut line = Vec::with_capacity(256);
            let mut sink = |row: &[f64]| {
                line.clear();
                csv_row(row, &mut line);
                out.write_all(&line).expect("written");
            };
            black_box(run_streamed(&minute, None, &mut sink).expect("runs"));
            out.flush().expect("flushed");
        })
    });
    let _ = std::fs::remove_file(&path);
    group.finish();
}

/// Every benchmark of this module.
pub fn all(c: &mut Criterion) {
    sampling(c);
}
