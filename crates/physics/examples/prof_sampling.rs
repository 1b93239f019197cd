use physics::run::run_streamed_rows;
use physics::scene::Scene;
use std::hint::black_box;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let yaml = std::fs::read_to_string(&args[1]).unwrap();
    let n: usize = args[2].parse().unwrap();
    let s = Scene::parse(&yaml, "x.yaml").unwrap();
    let mut total = 0u64;
    let t = std::time::Instant::now();
    for _ in 0..n {
        let mut sink = |rows: &[f64]| total += black_box(rows).len() as u64;
        black_box(run_streamed_rows(black_box(&s), None, &mut sink).unwrap());
    }
    eprintln!("{total} {:?} per run", t.elapsed() / n as u32);
}
