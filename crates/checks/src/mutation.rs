//! The mutation suite: mutants of each equation's printed LaTeX ([`paper::mutate`]) run
//! through the checks. A mutant is killed when the check of ITS equation fails with a verdict:
//! a check that could not evaluate the mutant (its claimed value is not a number) has not told
//! it from the printed form, so such a mutant is listed apart (`unevaluated`), never counted as
//! killed. A survivor is
//! listed with what was changed, for a reader to judge (mathematically equivalent, outside the
//! checked domain, or a weak check to fix). An equation whose printed form already fails its own
//! check is judged instead by its derivation check (whether it follows from its printed
//! premises, [`crate::equations::derivations`]) when it has one that its printed form passes:
//! eq 77 is wrong physically, but a mutant of it no longer follows from eq 76. Otherwise it has
//! no score: a check that already fails would "kill" every mutant without telling anything.
//!
//! Each mutant is classed by what it changes ([`change`]): a mutant of an estimate that its
//! check still reads as the estimate is "within the reading" only when it moves a constant;
//! one that moves an exponent (which the reading fixes exactly) or a sign is a survivor, its
//! class named.

mod change;

use crate::check::evaluated;
use crate::equations::{derivations, equations};
use crate::finding::Finding;
use crate::finding::Verdict;
use crate::harness::Bench;
use paper::mutate::mutants;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// The score of one equation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Score {
    /// The printed number.
    pub equation: u32,
    /// How many mutants were made.
    pub mutants: usize,
    /// How many its check failed on.
    pub killed: usize,
    /// What was changed in each survivor.
    pub survivors: Vec<String>,
    /// Mutants of an equation read as an order-of-magnitude estimate that its check still
    /// reads as one and that move only a constant: a constant moved within the estimate's
    /// factor, which the reading accepts by design (neither killed nor survivors). A mutant
    /// that moves an exponent or a sign and still reads as the estimate is a survivor.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub within_reading: Vec<String>,
    /// Mutants whose check could not evaluate them (a claimed value that is not a number: a
    /// symbol left without a value, the root of a negative number): neither killed nor
    /// survivors, with what was changed and why.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub unevaluated: Vec<String>,
    /// The printed equation itself fails its check: its mutants say nothing (a check that
    /// already fails "kills" everything), so none are run.
    pub printed_fails: bool,
    /// The check that judged the mutants: `truth` (the equation's own check) or `derivation`.
    pub judged_by: String,
}

/// Runs the mutants of the equations `numbers` through their checks (on `bench`'s paper).
/// `progress(done, total)` is called after each equation.
pub fn mutation_scores(
    bench: &Bench,
    numbers: &[u32],
    progress: &dyn Fn(usize, usize),
) -> Vec<Score> {
    let all = equations();
    let derived = derivations();
    let mut out = Vec::new();
    for (i, &n) in numbers.iter().enumerate() {
        let Some(truth) = all.iter().find(|e| e.number == n).map(|e| e.check) else {
            continue;
        };
        let mut check: fn(&Bench) -> Finding = truth;
        let mut judged_by = "truth";
        let printed = check(bench).verdict;
        let estimate = matches!(printed, Verdict::Estimate { .. });
        // An estimate is judged by its derivation where it has one (a constant moved by 1e-3
        // cannot leave an estimate's reading, but it no longer follows from its premises).
        let mut printed_fails = printed == Verdict::Fails || estimate;
        if printed_fails {
            if let Some(d) = derived.iter().find(|d| d.number == n) {
                if (d.check)(bench).verdict != Verdict::Fails {
                    (check, judged_by, printed_fails) = (d.check, "derivation", false);
                }
            }
        }
        if printed_fails && estimate {
            (judged_by, printed_fails) = ("truth, as an estimate", false);
        }
        let ms = if printed_fails {
            Vec::new()
        } else {
            mutants(&bench.paper.equation(n).chains)
        };
        let mut score = Score {
            equation: n,
            mutants: ms.len(),
            killed: 0,
            survivors: Vec::new(),
            within_reading: Vec::new(),
            unevaluated: Vec::new(),
            printed_fails,
            judged_by: judged_by.into(),
        };
        // The mutants of one equation are independent: checked in parallel on rayon's pool,
        // collected in their order, so the score does not depend on the thread count.
        let verdicts: Vec<(Result<Verdict, String>, _, _)> = ms
            .into_par_iter()
            .map(|m| {
                let class = change::change(&bench.paper.equation(n).chains, &m.chains);
                let paper = bench.paper.with_chains(n, m.chains);
                let b = Bench {
                    paper: &paper,
                    ..*bench
                };
                let verdict = evaluated(check(&b), &b).map(|f| f.verdict);
                (verdict, m.change, class)
            })
            .collect();
        for (verdict, change, class) in verdicts {
            match verdict {
                Ok(Verdict::Fails) => score.killed += 1,
                Ok(Verdict::Estimate { .. }) if class == change::Change::Constant => {
                    score.within_reading.push(change)
                }
                Ok(Verdict::Estimate { .. }) => score.survivors.push(format!(
                    "{change} (changes {class}, which the estimate's reading fixes: still read \
                     as the estimate)"
                )),
                Ok(_) => score.survivors.push(change),
                Err(why) => score.unevaluated.push(format!("{change} ({why})")),
            }
        }
        out.push(score);
        progress(i + 1, numbers.len());
    }
    out
}

/// The scores of the whole built-in paper, stored in `snapshots/mutants.json` because the suite
/// takes about a minute (too long for every report): `tests/mutation.rs` recomputes them and
/// fails when the stored file differs (re-bless with `ROLLING_DISK_BLESS=1`), so the report can
/// show them without running them, and they cannot go stale.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredScores {
    /// SHA-256 of the transcription they were computed on (`report.json`'s `paper.sha256`).
    pub paper_sha256: String,
    /// The scores, by equation.
    pub scores: Vec<Score>,
}

/// The stored file, as compiled into the binary.
pub const STORED: &str = include_str!("../../../snapshots/mutants.json");

impl StoredScores {
    /// The stored scores; an error only if the file in this build is malformed (a test reads it).
    pub fn built_in() -> Result<Self, serde_json::Error> {
        serde_json::from_str(STORED)
    }

    /// The score of equation `n`, if it has one.
    pub fn of(&self, n: u32) -> Option<&Score> {
        self.scores.iter().find(|s| s.equation == n)
    }

    /// Mutants made and killed over the equations that have a score, leaving out those an
    /// estimate's reading accepts; and how many those are.
    pub fn totals(&self) -> (usize, usize, usize) {
        self.scores
            .iter()
            .filter(|s| !s.printed_fails)
            .fold((0, 0, 0), |(m, k, w), s| {
                let within = s.within_reading.len();
                (m + s.mutants - within, k + s.killed, w + within)
            })
    }
}

impl Score {
    /// The score in one sentence, as the report shows it under the equation.
    pub fn describe(&self) -> String {
        if self.printed_fails {
            return "no mutation score: the printed form already fails its own check, so every \
                    mutant would fail it too"
                .into();
        }
        let by = match self.judged_by.as_str() {
            "derivation" => {
                "its derivation from its printed premises (the printed form fails its own check \
                 or is an estimate)"
            }
            "truth, as an estimate" => "its own check, read as an estimate",
            _ => "its own check",
        };
        let mut text = format!(
            "mutants of the printed LaTeX: {} of {} killed by {by}",
            self.killed, self.mutants
        );
        if !self.within_reading.is_empty() {
            text.push_str(&format!(
                "; {} within the estimate's reading (a constant moved inside its factor): {}",
                self.within_reading.len(),
                self.within_reading.join("; ")
            ));
        }
        if !self.unevaluated.is_empty() {
            text.push_str(&format!(
                "; {} its check could not evaluate (not counted as killed): {}",
                self.unevaluated.len(),
                self.unevaluated.join("; ")
            ));
        }
        if !self.survivors.is_empty() {
            text.push_str(&format!("; survivors: {}", self.survivors.join("; ")));
        }
        text
    }
}
