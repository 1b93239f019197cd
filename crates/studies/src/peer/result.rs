//! Reading the peer's `result.txt`: a header line of 31 names, then one row per print step:
//! 30 numbers (time; $\psi, \theta, \phi$; $\omega_{1,2,3}$; the centre's velocity in frame (1);
//! the centre; the contact point; its velocity; $\boldsymbol\omega$ in frame (1); forces;
//! friction ratio; slip speed; force angle) and the mode, `rolling` or `sliding`.

use super::mapping::PeerState;
use super::PeerError;

/// The columns a row must have before its mode.
const NUMBERS: usize = 30;

/// One row of `result.txt`.
#[derive(Debug, Clone, PartialEq)]
pub struct PeerRow {
    /// Time (s).
    pub t: f64,
    /// The state.
    pub state: PeerState,
    /// True while rolling, false while sliding.
    pub rolling: bool,
    /// The contact point's slip speed (m/s).
    pub slip_speed: f64,
    /// The normal force over the weight, $F_z/mg$ (its `FN/WGT`).
    pub normal: f64,
    /// The friction force's size over the weight, $|\mathbf F_t|/mg$ (its `FT/WGT`).
    pub tangential: f64,
}

/// The rows of a `result.txt` text; `file` names it in errors.
pub fn parse(text: &str, file: &str) -> Result<Vec<PeerRow>, PeerError> {
    let mut rows = Vec::new();
    let mut lines = text.lines().enumerate();
    match lines.next() {
        Some((_, h)) if h.split_whitespace().next() == Some("TNOW") => {}
        _ => {
            return Err(PeerError::Result(
                file.to_string(),
                1,
                "the first line is not the peer's header (TNOW PSI THETA ...): give the \
                 result.txt the peer wrote"
                    .into(),
            ))
        }
    }
    for (i, line) in lines {
        if line.trim().is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split_whitespace().collect();
        let bad = |why: String| PeerError::Result(file.to_string(), i + 1, why);
        if fields.len() != NUMBERS + 1 {
            return Err(bad(format!(
                "{} fields where the peer writes {} numbers and a mode (a number too wide for \
                 its F18.7 format runs into its neighbour: rerun the peer with a shorter end \
                 time)",
                fields.len(),
                NUMBERS
            )));
        }
        let mut x = [0.0; NUMBERS];
        for (k, f) in fields[..NUMBERS].iter().enumerate() {
            x[k] = f
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| bad(format!("column {} is `{f}`, not a number", k + 1)))?;
        }
        let rolling = match fields[NUMBERS] {
            "rolling" => true,
            "sliding" => false,
            m => return Err(bad(format!("the mode is `{m}`, not rolling or sliding"))),
        };
        rows.push(PeerRow {
            t: x[0],
            state: PeerState {
                psi: x[1],
                theta: x[2],
                phi: x[3],
                omega: [x[4], x[5], x[6]],
                velocity: [x[7], x[8], x[9]],
                centre: [x[10], x[11], x[12]],
            },
            rolling,
            slip_speed: x[28],
            normal: x[25],
            tangential: x[26],
        });
    }
    if rows.is_empty() {
        return Err(PeerError::Result(
            file.to_string(),
            1,
            "no rows after the header: the peer stopped before its first print step".into(),
        ));
    }
    Ok(rows)
}

/// The times at which the mode changes: the first row in the new mode.
pub fn switches(rows: &[PeerRow]) -> Vec<(f64, bool)> {
    rows.windows(2)
        .filter(|w| w[0].rolling != w[1].rolling)
        .map(|w| (w[1].t, w[1].rolling))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_rows_and_refuses_a_broken_line() {
        let head = "      TNOW            PSI   THETA\n";
        let row = |t: f64, mode: &str| {
            let mut s = String::new();
            for k in 0..NUMBERS {
                s.push_str(&format!("{:18.7}", if k == 0 { t } else { 0.5 }));
            }
            format!("{s}      {mode}\n")
        };
        let text = format!("{head}{}{}", row(0.0, "sliding"), row(0.001, "rolling"));
        let rows = parse(&text, "r.txt").unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(switches(&rows), vec![(0.001, true)]);
        assert_eq!(rows[1].state.theta, 0.5);
        let broken = format!(
            "{head}{}",
            row(0.0, "sliding").replace("0.5000000", "*********")
        );
        let e = parse(&broken, "r.txt").unwrap_err().to_string();
        assert!(e.contains("r.txt:2"), "{e}");
        assert!(parse("x\n", "r.txt").is_err());
    }
}
