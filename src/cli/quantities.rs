//! `rolling-disk quantities`: the catalogue of quantities a claim of claims.yaml can name to be
//! checked with no Rust ([`checks::quantities`]), as text or JSON.

use checks::equations::Bench;
use checks::quantities::{Kind, Quantity, Value, QUANTITIES};

/// The arguments of `rolling-disk quantities`.
#[derive(clap::Args)]
pub struct Args {
    /// Print the catalogue as JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

impl Args {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        let entries: Vec<Entry> = QUANTITIES.iter().map(Entry::of).collect();
        if self.json {
            let json: Vec<serde_json::Value> = entries.iter().map(Entry::json).collect();
            let text = serde_json::to_string_pretty(&json)
                .map_err(|e| anyhow::anyhow!("cannot write JSON: {e}"))?;
            println!("{text}");
        } else {
            for e in &entries {
                print!("{}", e.text());
            }
            println!(
                "A claim names one in claims.yaml as `quantity: {{ name: NAME, PARAMETER: VALUE, \
                 ... }}`, with `claimed_value` in the quantity's unit (docs/paper-input.md)."
            );
        }
        Ok(())
    }
}

/// A quantity as listed.
struct Entry {
    name: &'static str,
    means: &'static str,
    unit: &'static str,
    method: String,
    how: &'static str,
    tolerance: String,
    parameters: Vec<ParameterEntry>,
}

/// A parameter as listed: a number in an open interval, or one of some words.
struct ParameterEntry {
    name: &'static str,
    means: &'static str,
    unit: Option<&'static str>,
    above: Option<f64>,
    below: Option<f64>,
    /// Whether only whole numbers are values.
    whole: bool,
    one_of: Option<&'static [&'static str]>,
    /// The value when a claim leaves it out; absent when a claim must give it.
    default: Option<String>,
}

impl Entry {
    fn of(q: &Quantity) -> Self {
        Self {
            name: q.name,
            means: q.means,
            unit: q.unit,
            method: q.method.to_string(),
            how: q.how,
            tolerance: (q.tolerance)(&Bench::default()).rule,
            parameters: q
                .parameters
                .iter()
                .map(|p| {
                    let (unit, above, below, whole, one_of) = match p.kind {
                        Kind::Number {
                            unit,
                            above,
                            below,
                            whole,
                        } => (Some(unit), Some(above), Some(below), whole, None),
                        Kind::Choice(words) => (None, None, None, false, Some(words)),
                    };
                    ParameterEntry {
                        name: p.name,
                        means: p.means,
                        unit,
                        above,
                        below,
                        whole,
                        one_of,
                        default: p.default.as_ref().map(Value::to_string),
                    }
                })
                .collect(),
        }
    }

    /// The entry as JSON: a parameter's `unit`, `above` and `below` for a number (and `whole:
    /// true` where only whole numbers are values), `one_of` for a word, `default` where it has
    /// one.
    fn json(&self) -> serde_json::Value {
        let parameters: Vec<serde_json::Value> = self
            .parameters
            .iter()
            .map(|p| {
                let mut v = serde_json::json!({ "name": p.name, "means": p.means });
                let fields = [
                    ("unit", p.unit.map(serde_json::Value::from)),
                    ("above", p.above.map(serde_json::Value::from)),
                    ("below", p.below.map(serde_json::Value::from)),
                    (
                        "one_of",
                        p.one_of.map(|w| serde_json::Value::from(w.to_vec())),
                    ),
                    ("whole", p.whole.then_some(serde_json::Value::from(true))),
                    ("default", p.default.clone().map(serde_json::Value::from)),
                ];
                for (key, value) in fields {
                    if let Some(value) = value {
                        v[key] = value;
                    }
                }
                v
            })
            .collect();
        serde_json::json!({
            "name": self.name,
            "means": self.means,
            "unit": self.unit,
            "method": self.method,
            "how": self.how,
            "tolerance": self.tolerance,
            "parameters": parameters,
        })
    }

    fn text(&self) -> String {
        let mut out = format!(
            "{} [{}]\n  {}\n  method: {}: {}\n  tolerance without a rule: {}\n",
            self.name, self.unit, self.means, self.method, self.how, self.tolerance
        );
        for p in &self.parameters {
            let values = match (p.one_of, p.unit, p.above, p.below) {
                (Some(words), _, _, _) => format!("one of {}", words.join(", ")),
                (None, Some(unit), Some(above), Some(below)) => {
                    let number = if p.whole {
                        "a whole number"
                    } else {
                        "a number"
                    };
                    format!("{number} in ({above}, {below}) {unit}")
                }
                _ => String::new(),
            };
            let default = p
                .default
                .as_ref()
                .map_or(" (required)".to_string(), |d| format!(" (default {d})"));
            out.push_str(&format!("  {}: {values}{default}: {}\n", p.name, p.means));
        }
        out.push('\n');
        out
    }
}
