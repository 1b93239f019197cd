//! Running the checks: in parallel, results in registry order whatever the scheduling.
//!
//! A check runs only when what it reads from the paper is there: a claim check needs its claim
//! in the paper's claims.yaml and, where the built-in claim states a `rule` for its wording,
//! the rule (and the printed number it reads) too; otherwise the check is reported as one that
//! could not run, naming the key to add. Nothing else in a check can fail on user input (the
//! mutation suite runs every mutant of every printed equation through the checks without a
//! panic), so a panic in a check is a defect of this program and is not caught.

use crate::cause::{classify, Cause, Node};
pub use crate::checked::{Checked, Subject};
use crate::equations;
use crate::finding::Finding;
use crate::harness::Bench;
pub use crate::tally::Tally;
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Why a selection of checks could not be run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CheckError {
    /// An `--only` range with its ends swapped.
    #[error("--only: the range {part} runs backwards; write {hi}-{lo}")]
    Backwards {
        /// The range as written.
        part: String,
        /// Its larger end.
        lo: u32,
        /// Its smaller end.
        hi: u32,
    },
    /// An `--only` item that starts like a number but is not an equation number or a range.
    #[error("--only: {0} is not an equation number from 1 to 85 or a range like 23-25")]
    NotANumber(String),
    /// An equation selected that has no check.
    #[error("--only: equation {0} has no check yet")]
    NoCheck(u32),
    /// A claim id that no check has.
    #[error("--only: {0} is neither an equation number nor the id of a checked claim")]
    UnknownClaim(String),
    /// A claim names a quantity of the catalogue wrongly (an unknown name or parameter, a value
    /// out of range): the sentence names the file, the line, the key and the fix.
    #[error("{0}")]
    Quantity(String),
    /// The thread pool could not start.
    #[error("could not start {threads} threads for the checks: {reason}")]
    Threads {
        /// Threads asked for.
        threads: usize,
        /// The system's reason.
        reason: String,
    },
}

/// The binary and the report print the sentence.
impl From<CheckError> for String {
    fn from(e: CheckError) -> Self {
        e.to_string()
    }
}

/// Which checks to run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Selection {
    /// Equation numbers; `None` for all.
    pub numbers: Option<Vec<u32>>,
    /// Claim ids; `None` for all, an empty list for none.
    pub claims: Option<Vec<String>>,
}

impl Selection {
    /// Parses `--only` text: numbers, ranges (`23-25`) and claim ids, comma-separated.
    pub fn parse(text: &str) -> Result<Self, CheckError> {
        let (mut numbers, mut claims) = (Vec::new(), Vec::new());
        for part in text.split(',').map(str::trim).filter(|p| !p.is_empty()) {
            let range: Vec<&str> = part.splitn(2, '-').collect();
            let num = |s: &str| s.parse::<u32>().ok().filter(|n| (1..=85).contains(n));
            match range.as_slice() {
                [a] if num(a).is_some() => numbers.push(num(a).unwrap_or(0)),
                [a, b] if num(a).is_some() && num(b).is_some() => {
                    let (a, b) = (num(a).unwrap_or(0), num(b).unwrap_or(0));
                    if a > b {
                        return Err(CheckError::Backwards {
                            part: part.to_string(),
                            lo: a,
                            hi: b,
                        });
                    }
                    numbers.extend(a..=b);
                }
                _ if part.chars().next().is_some_and(|c| c.is_ascii_digit()) => {
                    return Err(CheckError::NotANumber(part.to_string()))
                }
                _ => claims.push(part.to_string()),
            }
        }
        Ok(Self {
            numbers: Some(numbers),
            claims: Some(claims),
        })
    }
}

/// One check to run: what, its section, the check, its derivation check if any, and whether
/// its result is shown (a premise run only to classify a selected equation is not).
type Job = (Subject, u32, Run, Option<fn(&Bench) -> Finding>, bool);

/// How a check runs: a check written in Rust, or the claim's quantity of the catalogue computed
/// and judged against its printed value ([`equations::claims::catalogued`]).
#[derive(Debug, Clone, Copy)]
enum Run {
    /// A registered check.
    Registered(fn(&Bench) -> Finding),
    /// A claim naming a quantity of the catalogue ([`crate::quantities`]).
    Catalogued,
}

/// The selected equations and, transitively, their premises (a failing equation can only be
/// told a root cause or an inherited error knowing its premises' verdicts).
fn with_premises(bench: &Bench, numbers: &[u32]) -> Vec<u32> {
    let mut all: std::collections::BTreeSet<u32> = numbers.iter().copied().collect();
    let mut todo: Vec<u32> = numbers.to_vec();
    while let Some(n) = todo.pop() {
        if !(1..=85).contains(&n) {
            continue;
        }
        for &p in &bench.paper.equation(n).entry.premises {
            if all.insert(p) {
                todo.push(p);
            }
        }
    }
    all.into_iter().collect()
}

/// The claims the selection rests on (`rests_on` of its equations and claims, and of those
/// claims in turn): run silently beside it, so that a verdict does not depend on what else was
/// selected.
fn premise_claims(bench: &Bench, selection: &Selection, numbers: Option<&[u32]>) -> Vec<String> {
    let paper = bench.paper;
    let mut todo: Vec<String> = Vec::new();
    for e in &paper.equations {
        if numbers.is_none_or(|ns| ns.contains(&e.entry.number)) {
            todo.extend(e.entry.rests_on.iter().cloned());
        }
    }
    for c in &paper.claims {
        if selection
            .claims
            .as_ref()
            .is_none_or(|ids| ids.contains(&c.id))
        {
            todo.extend(c.rests_on.iter().cloned());
        }
    }
    let mut all: Vec<String> = Vec::new();
    while let Some(id) = todo.pop() {
        if id.starts_with("eq ") || all.contains(&id) {
            continue;
        }
        if let Some(c) = paper.claims.iter().find(|c| c.id == id) {
            todo.extend(c.rests_on.iter().cloned());
        }
        all.push(id);
    }
    all
}

fn jobs(bench: &Bench, selection: &Selection) -> Result<Vec<Job>, CheckError> {
    let sections: Vec<u32> = bench
        .paper
        .equations
        .iter()
        .map(|e| e.entry.section)
        .collect();
    let claim_sections = &bench.paper.claims;
    let mut out: Vec<Job> = Vec::new();
    let registered = equations::equations();
    let derivations = equations::derivations();
    // The equations a selected claim restates run too (silently), so that its verdict does not
    // depend on what else was selected.
    let restated = bench.paper.claims.iter().filter_map(|c| {
        let wanted = selection
            .claims
            .as_ref()
            .is_none_or(|ids| ids.contains(&c.id));
        c.restates.filter(|_| wanted)
    });
    let needed = selection.numbers.as_ref().map(|ns| {
        let ns: Vec<u32> = ns.iter().copied().chain(restated).collect();
        with_premises(bench, &ns)
    });
    if let Some(numbers) = &selection.numbers {
        for n in numbers {
            if !registered.iter().any(|e| e.number == *n) {
                return Err(CheckError::NoCheck(*n));
            }
        }
    }
    for e in registered {
        let shown = selection
            .numbers
            .as_ref()
            .is_none_or(|ns| ns.contains(&e.number));
        let needed = needed.as_ref().is_none_or(|ns| ns.contains(&e.number));
        if shown || needed {
            let section = sections.get(e.number as usize - 1).copied().unwrap_or(0);
            out.push((
                Subject::Equation {
                    number: e.number,
                    label: e.label,
                },
                section,
                Run::Registered(e.check),
                derivations
                    .iter()
                    .find(|d| d.number == e.number)
                    .map(|d| d.check),
                shown,
            ));
        }
    }
    let premises = premise_claims(bench, selection, needed.as_deref());
    crate::quantities::validate(bench.paper).map_err(CheckError::Quantity)?;
    // The registered checks, in their order, then the claims naming a quantity of the
    // catalogue, in claims.yaml's order.
    let all_claims: Vec<(String, Run)> = equations::claims()
        .into_iter()
        .map(|c| (c.id.to_string(), Run::Registered(c.check)))
        .chain(
            claim_sections
                .iter()
                .filter(|c| c.quantity.named().is_some())
                .map(|c| (c.id.clone(), Run::Catalogued)),
        )
        .collect();
    if let Some(ids) = &selection.claims {
        for id in ids {
            if !all_claims.iter().any(|(c, _)| c == id) {
                return Err(CheckError::UnknownClaim(id.clone()));
            }
        }
    }
    for (id, run) in all_claims {
        let wanted = selection
            .claims
            .as_ref()
            .is_none_or(|ids| ids.contains(&id));
        if wanted || premises.contains(&id) {
            let section = claim_sections
                .iter()
                .find(|e| e.id == id)
                .map_or(0, |e| e.section);
            out.push((Subject::Claim { id }, section, run, None, wanted));
        }
    }
    Ok(out)
}

/// Runs the selected checks on a rayon pool of `threads` threads; `progress(done, total)` after
/// each. The results come back in the selection's order whatever the thread count: each check
/// reads only the bench, and rayon's indexed collect keeps the order.
pub fn run_checks(
    bench: &Bench,
    selection: &Selection,
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Vec<Checked>, CheckError> {
    let jobs = jobs(bench, selection)?;
    let mut all = run_jobs(bench, &jobs, threads, progress)?;
    attach_causes(bench, &mut all);
    crate::agreement::attach_premises(bench, &mut all);
    crate::agreement::attach_restated(bench, &mut all);
    crate::agreement::attach_parts(bench, &mut all);
    crate::readings::attach(bench, &mut all);
    crate::agreement::attach_inherited(&mut all);
    Ok(all
        .into_iter()
        .zip(&jobs)
        .filter_map(|(c, job)| job.4.then_some(c))
        .collect())
}

/// The checks of the selection alone: no premise is run and no cause attached, for a study that
/// reads only the findings (the corrections' verdicts), at a fraction of the cost.
pub fn run_findings(
    bench: &Bench,
    selection: &Selection,
    threads: usize,
) -> Result<Vec<Checked>, CheckError> {
    let jobs: Vec<Job> = jobs(bench, selection)?
        .into_iter()
        .filter(|job| job.4)
        .collect();
    run_jobs(bench, &jobs, threads, &|_, _| {})
}

/// Runs `jobs` on a pool of `threads` threads, in their order.
fn run_jobs(
    bench: &Bench,
    jobs: &[Job],
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Vec<Checked>, CheckError> {
    let total = jobs.len();
    let done = AtomicUsize::new(0);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.max(1))
        .build()
        .map_err(|e| CheckError::Threads {
            threads,
            reason: e.to_string(),
        })?;
    let all: Vec<Checked> = pool.install(|| {
        jobs.par_iter()
            .map(|job| {
                let (subject, section, check, derivation, _) = job.clone();
                let stage = format!("the check of {}", subject.name());
                let checked = physics::budget::in_stage(&stage, || {
                    let (finding, unvalued) = paper::unvalued::recording(|| {
                        match (missing_input(bench, &subject), &subject, check) {
                            (Some(why), _, _) => Err(why),
                            (None, Subject::Claim { id }, Run::Catalogued) => {
                                Ok(equations::claims::catalogued(bench, id))
                            }
                            (None, Subject::Claim { id }, Run::Registered(check)) => Ok(
                                equations::claims::with_printed_headline(bench, id, check(bench)),
                            ),
                            (None, _, Run::Registered(check)) => Ok(check(bench)),
                            (None, Subject::Equation { .. }, Run::Catalogued) => {
                                unreachable!(
                                    "jobs() gives a quantity of the catalogue to claims only"
                                )
                            }
                        }
                    });
                    let finding = finding
                        .and_then(|f| evaluated(f, bench))
                        .map_err(|why| naming_unvalued(why, &unvalued));
                    let dimensions = crate::dimensions::of(bench, &subject, finding.as_ref().ok());
                    let finding =
                        finding.map(|f| crate::dimensions::slip(&subject, f, &dimensions));
                    Checked {
                        subject,
                        section,
                        finding,
                        derivation: derivation.map(|d| {
                            let (f, unvalued) = paper::unvalued::recording(|| d(bench));
                            evaluated(f, bench).map_err(|why| naming_unvalued(why, &unvalued))
                        }),
                        cause: None,
                        dimensions,
                    }
                });
                progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
                checked
            })
            .collect()
    });
    Ok(all)
}

/// Why a check could not run, with the symbols it found without a value (each named with its
/// equation and column, [`paper::unvalued`]): the cause, where the claim is not a number.
fn naming_unvalued(why: String, unvalued: &[String]) -> String {
    if unvalued.is_empty() {
        return why;
    }
    format!(
        "{why}; with no value in this check: {} (write the equation with the symbols its check \
         binds)",
        unvalued.join("; ")
    )
}

/// A finding whose claimed value is not a number (NaN or infinite) gives no verdict: the claim
/// could not be evaluated (a symbol without a value, an operation on values of the wrong kinds,
/// a square root of a negative number), so the check reports that instead of failing the paper,
/// and the finding can be neither a failure nor a root cause.
/// The same holds for a finding whose error is not a number: a comparison that gives no number
/// is not evidence against the paper.
///
/// A reference that is not a number was not located (a bisection whose predicate did not change
/// over its bracket, an integration cut short by the budget): that too is reported as a check
/// that could not run, never as a failure of the paper.
pub fn evaluated(f: Finding, bench: &Bench) -> Result<Finding, String> {
    if !f.reference.is_finite() {
        return Err(format!(
            "the reference could not be located (an integration stopped early, or a bisection's \
             bracket held no edge): {}",
            f.at
        ));
    }
    if !f.claimed.is_finite() {
        Err(format!(
            "could not evaluate the claim ({}): {}",
            bench.paper.origin(),
            f.at
        ))
    } else if !f.error.is_finite() {
        Err(format!(
            "could not evaluate the comparison ({}): the error is {} ({})",
            bench.paper.origin(),
            f.error,
            f.at
        ))
    } else {
        Ok(f)
    }
}

/// Why the check of `subject` cannot run on `bench`'s paper, if it cannot: its claim is missing
/// from claims.yaml, or lacks the `rule` (and the `claimed_value` the rule reads) that the
/// built-in claim has and the check judges by.
fn missing_input(bench: &Bench, subject: &Subject) -> Option<String> {
    let Subject::Claim { id } = subject else {
        return None;
    };
    let Some(found) = bench.paper.claims.iter().find(|c| c.id == *id) else {
        return Some(format!(
            "claims.yaml has no claim `{id}`: add it back (its check reads the printed value there)"
        ));
    };
    let built_in = paper::Paper::built_in_shared()
        .claims
        .iter()
        .find(|c| c.id == *id);
    if found.rule.is_some() && built_in.as_ref().is_some_and(|c| c.rule.is_none()) {
        return Some(format!(
            "claims.yaml, claim `{id}`: its check makes its own comparison and reads no `rule`; \
             remove the rule (it would be shown without being applied)"
        ));
    }
    if found.claimed_value.is_none()
        && built_in
            .as_ref()
            .is_some_and(|c| c.claimed_value.is_some() && c.rule.is_none())
    {
        return Some(format!(
            "claims.yaml, claim `{id}`: its check compares with the printed number: give \
             `claimed_value`"
        ));
    }
    if built_in.is_some_and(|c| c.rule.is_some()) {
        match &found.rule {
            None => {
                return Some(format!(
                    "claims.yaml, claim `{id}`: add a `rule` saying how its wording is read \
                     (for example `rule: {{ words: about, within: 0.05 }}`)"
                ))
            }
            Some(r) if r.range.is_none() && found.claimed_value.is_none() => {
                return Some(format!(
                    "claims.yaml, claim `{id}`: its rule compares with the printed number: give \
                     `claimed_value`"
                ))
            }
            Some(_) => {}
        }
    }
    None
}

/// Classifies every failing equation among `checked` ([`crate::cause`]).
fn attach_causes(bench: &Bench, checked: &mut [Checked]) {
    let causes = {
        let mut nodes = std::collections::BTreeMap::new();
        for c in checked.iter() {
            if let Subject::Equation { number, .. } = c.subject {
                nodes.insert(
                    number,
                    Node {
                        premises: &bench.paper.equation(number).entry.premises,
                        truth: c.finding.as_ref().ok(),
                        derivation: c.derivation.as_ref().and_then(|d| d.as_ref().ok()),
                    },
                );
            }
        }
        classify(&nodes)
    };
    for c in checked.iter_mut() {
        if let Subject::Equation { number, .. } = c.subject {
            c.cause = causes.get(&number).cloned();
        }
    }
}

/// The cause settled for each equation among `checked` that has one (a root cause, an inherited
/// error, or undetermined), by equation number.
pub fn equation_causes(checked: &[Checked]) -> std::collections::BTreeMap<u32, Cause> {
    checked
        .iter()
        .filter_map(|c| match (&c.subject, &c.cause) {
            (Subject::Equation { number, .. }, Some(cause)) => Some((*number, cause.clone())),
            _ => None,
        })
        .collect()
}
