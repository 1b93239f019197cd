//! The mutation score as the report shows it: the stored scores of the built-in paper
//! ([`checks::mutation::StoredScores`], kept current by `tests/mutation.rs`), since running the
//! suite takes about a minute. A report on another paper (`--paper DIR`) says how to score it.

use checks::mutation::StoredScores;
use paper::{Paper, PaperSource};

/// The scores to show for `paper`, and the summary's sentence about them.
pub fn scores_for(paper: &Paper) -> (Option<StoredScores>, String) {
    match (&paper.source, StoredScores::built_in()) {
        (PaperSource::BuiltIn, Ok(stored)) => {
            let (made, killed, within) = stored.totals();
            let unscored: Vec<String> = stored
                .scores
                .iter()
                .filter(|s| s.printed_fails)
                .map(|s| s.equation.to_string())
                .collect();
            let sentence = format!(
                "Mutation score: {killed} of {made} mutants of the printed equations killed, each \
                 by its own equation's check (a constant scaled by 1.001 or raised by 1, a sign \
                 flipped, sin for cos, a term or factor dropped, a cross product's factors swapped, a power raised, an inequality \
                 reversed){}; no score for eqs {}, whose printed forms already fail. Stored from \
                 rolling-disk mutants --json and recomputed by the test suite; each equation \
                 below gives its own.",
                if within > 0 {
                    format!(
                        "; {within} more, of equations read as order-of-magnitude estimates, \
                         move a constant within the estimate's factor and are accepted by its \
                         reading"
                    )
                } else {
                    String::new()
                },
                unscored.join(", ")
            );
            (Some(stored), sentence)
        }
        (PaperSource::BuiltIn, Err(e)) => (
            None,
            format!(
                "Mutation score unavailable: the stored scores of this build do not read ({e})."
            ),
        ),
        (PaperSource::Dir(dir), _) => (
            None,
            format!(
                "Mutation score: not computed for the paper read from {} (it takes about a \
                 minute); run rolling-disk mutants --paper {}.",
                dir.display(),
                dir.display()
            ),
        ),
    }
}
