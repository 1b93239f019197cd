//! Reading numbers back from the README and `docs/`, and running the tool for the values they
//! must equal.

use serde_json::Value;
use std::process::{Command, Output};
use std::sync::OnceLock;

pub const BIN: &str = env!("CARGO_BIN_EXE_rolling-disk");
pub const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// A file of the repository, as written.
pub fn raw(path: &str) -> String {
    std::fs::read_to_string(format!("{ROOT}/{path}")).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// A file of the repository with the lines of each paragraph joined, so that a sentence reads
/// the same wherever its lines break.
pub fn prose(path: &str) -> String {
    raw(path)
        .replace("\n\n", "\u{0}")
        .replace('\n', " ")
        .replace('\u{0}', "\n\n")
}

/// Runs the tool with `args`.
pub fn tool(args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .output()
        .expect("the binary runs")
}

/// `check --json`, run once for all the tests of a test binary.
pub fn check_json() -> &'static Value {
    static DOCUMENT: OnceLock<Value> = OnceLock::new();
    DOCUMENT.get_or_init(|| {
        let out = tool(&["check", "--json"]);
        assert!(
            out.status.success(),
            "check --json: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice(&out.stdout).expect("check --json prints JSON")
    })
}

/// Every check of `check --json`.
pub fn checks() -> &'static [Value] {
    check_json()["checks"]
        .as_array()
        .expect("check --json lists its checks")
}

/// The check of `check --json` named `name` ("eq 43" or a claim's id).
pub fn check_named(name: &str) -> &'static Value {
    checks()
        .iter()
        .find(|c| c["name"] == name)
        .unwrap_or_else(|| panic!("check --json has no check named {name}"))
}

/// A check's verdict, as `check --json` words it.
pub fn verdict(check: &Value) -> Option<&str> {
    check["outcome"]["verdict"].as_str()
}

/// The equations whose verdict is `wanted`, in order.
pub fn equations_with(wanted: &str) -> Vec<u32> {
    let mut out: Vec<u32> = checks()
        .iter()
        .filter(|c| verdict(c) == Some(wanted))
        .filter_map(|c| c["equation"].as_u64())
        .map(|n| n as u32)
        .collect();
    out.sort_unstable();
    out
}

/// The whole number that ends `text` (after spaces and bold marks), if any.
pub fn last_number(text: &str) -> Option<u64> {
    text.trim_end()
        .trim_end_matches("**")
        .rsplit(|c: char| !c.is_ascii_digit())
        .next()?
        .parse()
        .ok()
}

/// The number written just before `words` in `text` (the last one, if several).
pub fn count_before(text: &str, words: &str) -> Option<u64> {
    last_number(&text[..text.find(words)?])
}

/// The number, as written (digits, decimal point, thousands commas), that follows `words` in
/// `text`, past spaces and bold marks.
pub fn number_after<'t>(text: &'t str, words: &str) -> Option<&'t str> {
    let rest = text[text.find(words)? + words.len()..]
        .trim_start()
        .trim_start_matches("**");
    let end = rest
        .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == ','))
        .unwrap_or(rest.len());
    let number = rest[..end].trim_end_matches(['.', ',']);
    (!number.is_empty()).then_some(number)
}

/// Whether `printed`, a decimal as written, is `value` rounded to the digits printed.
pub fn agrees(printed: &str, value: f64) -> bool {
    let decimals = printed.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    match printed.parse::<f64>() {
        Ok(p) => (value - p).abs() <= 0.5 * 10f64.powi(-decimals) + 1e-12 * value.abs().max(1.0),
        Err(_) => false,
    }
}

/// Equation numbers written as a list: `43, 72, 73, 76-79, 82 and 83`.
pub fn equation_list(text: &str) -> Vec<u32> {
    let number = |s: &str| -> u32 {
        s.trim()
            .parse()
            .unwrap_or_else(|_| panic!("not an equation number: {s:?} in {text:?}"))
    };
    let mut out = Vec::new();
    for item in text.replace(" and ", ",").split(',') {
        let item = item.trim();
        if item.is_empty() {
            continue;
        }
        match item.split_once('-') {
            Some((first, last)) => out.extend(number(first)..=number(last)),
            None => out.push(number(item)),
        }
    }
    out
}

/// The equations listed in the first `(eqs ...)` after `words`.
pub fn equations_in_parentheses_after(text: &str, words: &str) -> Vec<u32> {
    let at = text
        .find(words)
        .unwrap_or_else(|| panic!("{words:?} is not in the text"));
    let rest = &text[at..];
    let open = rest
        .find("(eqs ")
        .unwrap_or_else(|| panic!("no (eqs ...) after {words:?}"))
        + "(eqs ".len();
    let close = open + rest[open..].find(')').expect("a closing parenthesis");
    equation_list(&rest[open..close])
}

/// The range `lo to hi` (or `lo and hi`) written right after `words`.
pub fn range_after(text: &str, words: &str) -> Option<(f64, f64)> {
    let rest = &text[text.find(words)? + words.len()..];
    let mut tokens = rest.split_whitespace();
    let lo = tokens.next()?.parse().ok()?;
    if !matches!(tokens.next()?, "to" | "and") {
        return None;
    }
    let hi = tokens
        .next()?
        .trim_end_matches([',', ':', ';', '.'])
        .parse()
        .ok()?;
    Some((lo, hi))
}

/// The row of a Markdown table whose first cell is `first`.
pub fn row<'t>(text: &'t str, first: &str) -> &'t str {
    let start = format!("| {first} |");
    text.lines()
        .find(|l| l.starts_with(&start))
        .unwrap_or_else(|| panic!("no table row starting {start:?}"))
}

/// A built-in scene as `scenes --show` prints it, below its comments.
pub fn built_in_scene(name: &str) -> String {
    let out = tool(&["scenes", "--show", name]);
    assert!(out.status.success(), "scenes --show {name}");
    String::from_utf8(out.stdout)
        .expect("UTF-8")
        .lines()
        .skip_while(|l| l.starts_with('#') || l.trim().is_empty())
        .map(|l| format!("{l}\n"))
        .collect()
}

/// Simulates the scene `text` and returns the tool's refusal of it.
pub fn refusal(tag: &str, text: &str) -> String {
    let dir =
        std::env::temp_dir().join(format!("rolling-disk-readme-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    let path = dir.join("scene.yaml");
    std::fs::write(&path, text).expect("the scene is written");
    let out = tool(&["simulate", path.to_str().expect("a UTF-8 path")]);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(!out.status.success(), "{tag}: the tool accepted the scene");
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Whether `w` is a date written `YYYY-MM-DD`.
pub fn is_date(w: &[u8]) -> bool {
    let digits = |s: &[u8]| s.iter().all(u8::is_ascii_digit);
    digits(&w[..4]) && w[4] == b'-' && digits(&w[5..7]) && w[7] == b'-' && digits(&w[8..10])
}
