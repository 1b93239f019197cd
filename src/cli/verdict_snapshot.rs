//! A snapshot of `check`'s derived results for a user's own loop: every check's verdict, its
//! cause, and its numbers (the claimed value, the reference's, the error) each with the change
//! it may take, with the tool's version, the paper's hash and the integration settings. Written
//! by `check --snapshot FILE`, compared by `check --against FILE`, rewritten by `--bless`.
//!
//! A number $x$ of a check whose tolerance is $\tau$ (the rule that judged its verdict) may move
//! by $\tau \max(1, |x|)$: relative to its size, absolute below 1, so that a change the check
//! itself could not tell from round-off or the solver's error is not a change. A verdict or a
//! cause that differs in any way is a change. The bytes are stable: keys in one order, numbers
//! in the shortest form that reads back to the same double.

use checks::cause::Cause;
use checks::check::Checked;
use checks::finding::Verdict;
use serde_json::{json, Map, Value};
use std::fmt::Write as _;

/// The `schema` of a snapshot.
pub(crate) const SCHEMA: &str = "https://rolling-disk.invalid/schemas/check-snapshot.schema.json";

/// The rule a snapshot's number tolerances follow, as the snapshot states it.
const RULE: &str = "a number may move by its check's tolerance times max(1, |number|)";

/// The numbers of a finding that a snapshot keeps, by name.
const NUMBERS: [&str; 3] = ["claimed", "reference", "error"];

/// A verdict in words, with what a `depends` or `restates` verdict depends on or restates.
fn verdict_words(v: &Verdict) -> String {
    match v {
        Verdict::Holds => "holds".into(),
        Verdict::HoldsApproximately { .. } => "holds approximately".into(),
        Verdict::Definition => "definition".into(),
        Verdict::Estimate { .. } => "estimate".into(),
        Verdict::PremiseFails => "premise fails".into(),
        Verdict::Fails => "fails".into(),
        Verdict::Restates { equation } => format!("fails, restating eq {equation}"),
        Verdict::UnitMisprint => "unit misprint".into(),
        Verdict::DependsOn { choice } => format!("depends on {choice}"),
        Verdict::DimensionalSlip => "dimensional slip".into(),
        Verdict::PartOf { claim } => format!("fails, as a part of {claim}"),
    }
}

/// A failing equation's cause in words, without its numbers.
fn cause_words(c: &Cause) -> String {
    let eqs = |v: &[u32]| {
        v.iter()
            .map(|n| format!("eq {n}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    match c {
        Cause::RootCause { .. } => "root cause".into(),
        Cause::Inherits { roots, .. } => format!("inherits from {}", eqs(roots)),
        Cause::Undetermined { failed_premises } => {
            format!("undetermined ({} fails)", eqs(failed_premises))
        }
    }
}

/// A number and the change it may take, as JSON (a number that is not finite is `null`).
fn number(x: f64, tolerance: f64) -> Value {
    json!({ "value": x, "tolerance": tolerance * x.abs().max(1.0) })
}

/// One check's entry.
fn entry(c: &Checked) -> Value {
    let mut e = Map::new();
    e.insert("name".into(), c.subject.name().into());
    match &c.finding {
        Ok(f) => {
            e.insert("verdict".into(), verdict_words(&f.verdict).into());
            let t = f.tolerance.value;
            let numbers: Map<String, Value> = NUMBERS
                .iter()
                .zip([f.claimed, f.reference, f.error])
                .map(|(name, x)| (name.to_string(), number(x, t)))
                .collect();
            e.insert("numbers".into(), numbers.into());
            e.insert("tolerance".into(), t.into());
            e.insert("unit".into(), f.unit.clone().into());
        }
        Err(message) => {
            e.insert("verdict".into(), "could not run".into());
            e.insert("message".into(), message.clone().into());
        }
    }
    e.insert(
        "cause".into(),
        c.cause
            .as_ref()
            .map(cause_words)
            .map_or(Value::Null, Value::from),
    );
    e.into()
}

/// The snapshot of the checks `checked` of `paper`, run by `method` at `rtol`.
pub(crate) fn snapshot(
    checked: &[Checked],
    paper: &paper::Paper,
    method: &str,
    rtol: f64,
) -> Value {
    let source = report::json::PaperSource::of(report::document::PAPER, paper);
    json!({
        "schema": SCHEMA,
        "tool": { "name": "rolling-disk", "version": crate::VERSION },
        "paper": { "title": source.title, "source": source.source, "sha256": source.sha256 },
        "settings": { "method": method, "rtol": rtol },
        "rule": RULE,
        "checks": checked.iter().map(entry).collect::<Vec<_>>(),
    })
}

/// The bytes of a snapshot: pretty JSON, keys sorted, a final newline.
pub(crate) fn to_bytes(snapshot: &Value) -> Vec<u8> {
    let mut text = serde_json::to_string_pretty(snapshot).unwrap_or_default();
    text.push('\n');
    text.into_bytes()
}

/// Reads a snapshot's text, `file` naming it in errors.
pub(crate) fn parse(text: &str, file: &str) -> anyhow::Result<Value> {
    let v: Value = serde_json::from_str(text).map_err(|e| {
        anyhow::anyhow!(
            "{file}:{}:{}: not a check snapshot ({e}); write one with `rolling-disk check --snapshot {file}`",
            e.line(),
            e.column()
        )
    })?;
    let schema = v.get("schema").and_then(Value::as_str);
    if schema != Some(SCHEMA) {
        return Err(anyhow::anyhow!(
            "{file}: key schema is {}, not {SCHEMA}: this is not a check snapshot of this tool; \
             write one with `rolling-disk check --snapshot {file}`",
            schema.map_or("absent".to_string(), |s| format!("`{s}`"))
        ));
    }
    let Some(checks) = v.get("checks").and_then(Value::as_array) else {
        return Err(anyhow::anyhow!(
            "{file}: key checks is absent or not a list; write the snapshot again with \
             `rolling-disk check --snapshot {file}`"
        ));
    };
    for (i, c) in checks.iter().enumerate() {
        let named = c.get("name").and_then(Value::as_str).is_some();
        let judged = c.get("verdict").and_then(Value::as_str).is_some();
        if !named || !judged {
            return Err(anyhow::anyhow!(
                "{file}: checks[{i}] has no {} text; write the snapshot again with \
                 `rolling-disk check --snapshot {file}`",
                if named { "verdict" } else { "name" }
            ));
        }
    }
    Ok(v)
}

/// One difference between a snapshot and a run.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Change {
    /// The check's name (`eq 76`, a claim's id).
    pub check: String,
    /// What changed: `verdict`, `cause`, a number's name, or `check` (present on one side).
    pub what: String,
    /// Before (the snapshot's).
    pub before: String,
    /// After (this run's).
    pub after: String,
    /// The change the number may take, for a number.
    pub tolerance: Option<f64>,
}

/// What differs between a snapshot and a run: the changes, and notes on what they were made
/// from (the tool, the paper, the settings).
#[derive(Debug, Clone, Default)]
pub(crate) struct Diff {
    /// Changes of verdicts, causes and numbers, in the run's order of checks.
    pub changes: Vec<Change>,
    /// The tool, paper or settings that differ (said, never a change by itself).
    pub notes: Vec<String>,
    /// Checks compared.
    pub checks: usize,
}

impl Diff {
    /// The names of the checks with a change, each once, in order.
    pub(crate) fn changed_checks(&self) -> Vec<&str> {
        let mut names: Vec<&str> = Vec::new();
        for c in &self.changes {
            if !names.contains(&c.check.as_str()) {
                names.push(&c.check);
            }
        }
        names
    }
}

/// A value of a snapshot as text for the diff.
fn shown(v: Option<&Value>) -> String {
    match v {
        None => "absent".into(),
        Some(Value::Null) => "none".into(),
        Some(Value::String(s)) => s.clone(),
        Some(Value::Number(n)) => match n.as_f64() {
            Some(x) => format!("{x:.9e}"),
            None => n.to_string(),
        },
        Some(other) => other.to_string(),
    }
}

/// The differences of one check present on both sides.
fn compare_check(name: &str, before: &Value, after: &Value, changes: &mut Vec<Change>) {
    for key in ["verdict", "cause", "message"] {
        if before.get(key) != after.get(key) {
            changes.push(Change {
                check: name.into(),
                what: key.into(),
                before: shown(before.get(key)),
                after: shown(after.get(key)),
                tolerance: None,
            });
        }
    }
    for key in NUMBERS {
        let old = before.get("numbers").and_then(|n| n.get(key));
        let new = after.get("numbers").and_then(|n| n.get(key));
        let value = |v: Option<&Value>| v.and_then(|v| v.get("value")).and_then(Value::as_f64);
        let tolerance = old.and_then(|v| v.get("tolerance")).and_then(Value::as_f64);
        let moved = match (value(old), value(new), tolerance) {
            (Some(a), Some(b), Some(t)) => (b - a).abs() > t,
            (None, None, _) => false,
            _ => true,
        };
        if moved {
            changes.push(Change {
                check: name.into(),
                what: key.into(),
                before: shown(old.and_then(|v| v.get("value"))),
                after: shown(new.and_then(|v| v.get("value"))),
                tolerance,
            });
        }
    }
}

/// A note when the field at `path` of the two snapshots differs.
fn note(before: &Value, after: &Value, path: &[&str], what: &str, notes: &mut Vec<String>) {
    let at = |v: &Value| path.iter().try_fold(v, |v, k| v.get(k)).cloned();
    let (a, b) = (at(before), at(after));
    if a != b {
        notes.push(format!(
            "{what}: {} -> {}",
            shown(a.as_ref()),
            shown(b.as_ref())
        ));
    }
}

/// What differs between the snapshot `before` and this run's `after` (both read by [`parse`] or
/// made by [`snapshot`]).
pub(crate) fn diff(before: &Value, after: &Value) -> Diff {
    let mut d = Diff::default();
    note(before, after, &["tool", "version"], "tool", &mut d.notes);
    note(
        before,
        after,
        &["paper", "source"],
        "paper source",
        &mut d.notes,
    );
    note(
        before,
        after,
        &["paper", "sha256"],
        "paper sha256",
        &mut d.notes,
    );
    note(
        before,
        after,
        &["settings", "method"],
        "method",
        &mut d.notes,
    );
    note(before, after, &["settings", "rtol"], "rtol", &mut d.notes);
    let list = |v: &Value| v.get("checks").and_then(Value::as_array).cloned();
    let (old, new) = (
        list(before).unwrap_or_default(),
        list(after).unwrap_or_default(),
    );
    let name = |c: &Value| {
        c.get("name")
            .and_then(Value::as_str)
            .unwrap_or("")
            .to_string()
    };
    let presence = |check: String, before: &str, after: &str| Change {
        check,
        what: "check".into(),
        before: before.into(),
        after: after.into(),
        tolerance: None,
    };
    for a in &new {
        match old.iter().find(|b| name(b) == name(a)) {
            Some(b) => compare_check(&name(a), b, a, &mut d.changes),
            None => d.changes.push(presence(name(a), "absent", "present")),
        }
    }
    for b in &old {
        if !new.iter().any(|a| name(a) == name(b)) {
            d.changes.push(presence(name(b), "present", "absent"));
        }
    }
    d.checks = new.len().max(old.len());
    d
}

/// The diff as text for a reader: the notes, then one line per change (check, what, before,
/// after, tolerance), then one line of totals naming `file`.
pub(crate) fn render(d: &Diff, file: &str) -> String {
    let mut s = String::new();
    for n in &d.notes {
        let _ = writeln!(s, "note: {n}");
    }
    if !d.changes.is_empty() {
        let _ = writeln!(
            s,
            "{:<34} {:<10} {:<22} {:<22} tolerance",
            "check", "what", "before", "after"
        );
        for c in &d.changes {
            let _ = writeln!(
                s,
                "{:<34} {:<10} {:<22} {:<22} {}",
                c.check,
                c.what,
                c.before,
                c.after,
                c.tolerance.map_or("-".to_string(), |t| format!("{t:.3e}"))
            );
        }
    }
    let changed = d.changed_checks();
    if changed.is_empty() {
        let _ = writeln!(s, "against {file}: no change in {} checks", d.checks);
    } else {
        let _ = writeln!(
            s,
            "against {file}: {} of {} checks changed: {}",
            changed.len(),
            d.checks,
            changed.join(", ")
        );
    }
    s
}
