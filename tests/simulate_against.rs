//! `simulate --against FILE.csv`: a run compared row by row with one `--csv` recorded. An
//! unchanged scene matches in every cell; a cell moved by less than the scene's atol + rtol x
//! |recorded| is no change and one moved by more is, named by row and column; an edited scene
//! is said changed with status 3.

use crate::common::{cli_piped, cli_status, temp_dir};
use std::path::Path;

/// A short nutating coin (0.05 s) in `dir/coin.yaml`, and its recorded run in `dir/coin.csv`.
fn recorded(dir: &Path) -> String {
    let (code, template, err) = cli_status(dir, &["scenes", "--show", "nutating-coin"]);
    assert_eq!(code, 0, "{err}");
    let yaml = template.replace("stop: { time: 1.0 }", "stop: { time: 0.05 }");
    assert_ne!(yaml, template);
    std::fs::write(dir.join("coin.yaml"), &yaml).unwrap();
    let (code, _, err) = cli_status(dir, &["simulate", "coin.yaml", "--csv", "coin.csv"]);
    assert_eq!(code, 0, "{err}");
    yaml
}

/// `coin.csv` with row `row` (from 1), column `column` moved by `by`, as `moved.csv`.
fn moved(dir: &Path, row: usize, column: usize, by: f64) -> f64 {
    let csv = std::fs::read_to_string(dir.join("coin.csv")).unwrap();
    let mut lines: Vec<String> = csv.lines().map(str::to_string).collect();
    let mut cells: Vec<String> = lines[row].split(',').map(str::to_string).collect();
    let x: f64 = cells[column].parse().unwrap();
    cells[column] = format!("{:.16e}", x + by);
    lines[row] = cells.join(",");
    std::fs::write(dir.join("moved.csv"), lines.join("\n") + "\n").unwrap();
    x
}

#[test]
fn a_run_matches_its_recording_and_a_moved_cell_is_named() {
    let dir = temp_dir("against", "trace");
    let yaml = recorded(&dir);
    let (code, out, err) = cli_status(&dir, &["simulate", "coin.yaml", "--against", "coin.csv"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("every cell within atol 1e-12 + rtol 1e-10"),
        "{out}"
    );

    // The recording on standard input.
    let csv = std::fs::read(dir.join("coin.csv")).unwrap();
    let (code, out, err) = cli_piped(&dir, &["simulate", "coin.yaml", "--against", "-"], &csv);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("against stdin: "), "{out}");

    // Row 7, column alpha_rad (index 1): atol 1e-12 + rtol 1e-10 x |alpha| allowed.
    let alpha: f64 = std::fs::read_to_string(dir.join("coin.csv"))
        .unwrap()
        .lines()
        .nth(7)
        .unwrap()
        .split(',')
        .nth(1)
        .unwrap()
        .parse()
        .unwrap();
    let allowed = 1e-12 + 1e-10 * alpha.abs();
    moved(&dir, 7, 1, 0.5 * allowed);
    let (code, out, err) = cli_status(&dir, &["simulate", "coin.yaml", "--against", "moved.csv"]);
    assert_eq!(code, 0, "{out}{err}");
    moved(&dir, 7, 1, 2.0 * allowed);
    let (code, out, err) = cli_status(&dir, &["simulate", "coin.yaml", "--against", "moved.csv"]);
    assert_eq!(code, 3, "{out}{err}");
    assert!(
        out.contains("first difference: row 7 column alpha_rad"),
        "{out}"
    );
    assert!(out.contains("1 cell(s) beyond their tolerance"), "{out}");
    assert!(err.contains("differs from its recording"), "{err}");

    // The scene edited: its first row already differs.
    let edited = yaml.replace("alpha: 1.0e-3", "alpha: 1.1e-3");
    assert_ne!(edited, yaml);
    std::fs::write(dir.join("edited.yaml"), edited).unwrap();
    let (code, out, err) = cli_status(&dir, &["simulate", "edited.yaml", "--against", "coin.csv"]);
    assert_eq!(code, 3, "{out}{err}");
    assert!(
        out.contains("first difference: row 1 column alpha_rad"),
        "{out}"
    );

    // Another scene's recording: its columns are said.
    let (code, out, err) = cli_status(&dir, &["simulate", "spin-down", "--against", "coin.csv"]);
    assert_eq!(code, 3, "{out}{err}");
    assert!(out.contains("columns: recorded"), "{out}");

    // A recording that is not one: its line and column, status 1.
    std::fs::write(dir.join("bad.csv"), "t_s,alpha_rad\n0,abc\n").unwrap();
    let (code, _, err) = cli_status(&dir, &["simulate", "coin.yaml", "--against", "bad.csv"]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("bad.csv:2: column alpha_rad (`abc`) is not a number"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
