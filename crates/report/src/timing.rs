//! Where a report's time goes: the wall time and the process's CPU time of each study and of each
//! stage after them (`rolling-disk report -v`). Timings go to standard error, never into the
//! report's files, whose bytes do not depend on them.

use std::sync::Mutex;
use std::time::Instant;

/// The wall and CPU seconds of one study or stage.
#[derive(Debug, Clone, PartialEq)]
pub struct Timing {
    /// The study's name, or the stage's (`figures`, `parts`, `document`, `writing`).
    pub name: String,
    /// Wall-clock seconds.
    pub wall: f64,
    /// CPU seconds of the whole process (every thread) over the same span.
    pub cpu: f64,
}

/// The timings of one report, in the order they were taken.
#[derive(Debug, Default)]
pub struct Timings {
    rows: Mutex<Vec<Timing>>,
}

/// CPU seconds used so far by every thread of this process.
pub fn cpu_seconds() -> f64 {
    let t = rustix::time::clock_gettime(rustix::time::ClockId::ProcessCPUTime);
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
}

impl Timings {
    /// No timing yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Runs `work`, and records its wall and CPU seconds under `name`. The CPU time is the whole
    /// process's: it is the work's own only when nothing else of the process runs meanwhile.
    pub fn time<T>(&self, name: &str, work: impl FnOnce() -> T) -> T {
        let (wall, cpu) = (Instant::now(), cpu_seconds());
        let out = work();
        self.record(Timing {
            name: name.to_string(),
            wall: wall.elapsed().as_secs_f64(),
            cpu: cpu_seconds() - cpu,
        });
        out
    }

    /// Adds a timing taken elsewhere.
    pub fn record(&self, timing: Timing) {
        self.rows
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .push(timing);
    }

    /// Every timing, in the order taken.
    pub fn rows(&self) -> Vec<Timing> {
        self.rows
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .clone()
    }

    /// The timings as a table: one line per study or stage, its share of the CPU time, and the
    /// total.
    pub fn table(&self) -> String {
        let rows = self.rows();
        let cpu: f64 = rows.iter().map(|r| r.cpu).sum();
        let wall: f64 = rows.iter().map(|r| r.wall).sum();
        let width = rows.iter().map(|r| r.name.len()).max().unwrap_or(0).max(5);
        let mut out = format!(
            "{:width$}  {:>8}  {:>8}  {:>6}\n",
            "", "wall s", "CPU s", "CPU %"
        );
        for r in rows.iter().chain(std::iter::once(&Timing {
            name: "total".into(),
            wall,
            cpu,
        })) {
            let share = if cpu > 0.0 { 100.0 * r.cpu / cpu } else { 0.0 };
            out += &format!(
                "{:width$}  {:>8.3}  {:>8.3}  {:>5.1}%\n",
                r.name, r.wall, r.cpu, share
            );
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_span_of_work_is_timed_in_cpu_and_wall_seconds() {
        let t = Timings::new();
        let sum = t.time("spin", || {
            let start = Instant::now();
            let mut x = 0u64;
            while start.elapsed().as_millis() < 30 {
                x = std::hint::black_box(x.wrapping_add(1));
            }
            x
        });
        assert!(sum > 0);
        let rows = t.rows();
        assert_eq!(rows.len(), 1);
        assert_eq!(rows[0].name, "spin");
        assert!(rows[0].wall >= 0.030, "{rows:?}");
        // A busy loop uses CPU (the process's: other tests' threads may add to it).
        assert!(rows[0].cpu > 0.0, "{rows:?}");
    }

    #[test]
    fn the_table_has_a_line_per_timing_and_their_total() {
        let t = Timings::new();
        for (name, cpu) in [("checks", 3.0), ("toy", 1.0)] {
            t.record(Timing {
                name: name.into(),
                wall: cpu * 2.0,
                cpu,
            });
        }
        let table = t.table();
        let lines: Vec<&str> = table.lines().collect();
        assert_eq!(lines.len(), 4, "{table}");
        assert!(
            lines[1].starts_with("checks") && lines[1].ends_with("75.0%"),
            "{table}"
        );
        assert!(
            lines[2].starts_with("toy") && lines[2].ends_with("25.0%"),
            "{table}"
        );
        assert!(
            lines[3].contains("8.000") && lines[3].contains("4.000"),
            "{table}"
        );
    }
}
