//! `check --paper DIR` on hostile papers: LaTeX nested thousands deep, files of many megabytes,
//! YAML errors on enormous lines, and an equation that cannot be evaluated. Each is refused or
//! reported in a few lines naming the file, the equation and the column, quickly, with exit
//! status 1: never a stack overflow, a panic, an echo of the input, or a verdict from a claim
//! that is not a number.

use std::path::PathBuf;
use std::process::Command;
use std::time::{Duration, Instant};

const EQUATIONS: &str = include_str!("../paper/equations.yaml");
const EQ1: &str = r"'\mathbf{a} = a \hat{\mathbf{3}}'";

fn dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "rolling-disk-paper-limits-{tag}-{}",
        std::process::id()
    ));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs `check --paper DIR` with `args`: exit code, stdout, stderr, and how long it took.
fn check(d: &PathBuf, args: &[&str]) -> (Option<i32>, String, String, Duration) {
    let started = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
        .arg("check")
        .arg("--paper")
        .arg(d)
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
        started.elapsed(),
    )
}

/// A paper whose eq 1 is `latex`, checked: refused with exit 1, within 2 s, in a short message
/// naming eq 1, a column and containing `says`.
fn refused_eq1(tag: &str, latex: &str, says: &str) {
    let d = dir(tag);
    assert!(EQUATIONS.contains(EQ1));
    std::fs::write(
        d.join("equations.yaml"),
        EQUATIONS.replacen(EQ1, &format!("'{latex}'"), 1),
    )
    .unwrap();
    let (code, _, err, took) = check(&d, &["--only", "1"]);
    assert_eq!(code, Some(1), "{tag}: {err}");
    assert!(took < Duration::from_secs(2), "{tag}: took {took:?}");
    assert!(
        err.contains("eq 1: column") && err.contains(says),
        "{tag}: {err}"
    );
    assert!(err.len() < 1000, "{tag}: {} bytes of messages", err.len());
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn latex_nested_thousands_deep_is_refused_without_overflowing_the_stack() {
    let parens = |n: usize| format!("{}a{}", "(".repeat(n), ")".repeat(n));
    let fracs = |n: usize| format!("{}1{}", r"\frac{1}{".repeat(n), "}".repeat(n));
    // Past the size limit the size is refused; within it, the depth, at the group past it.
    for (tag, nested, says) in [
        ("parens4000", parens(4000), "characters"),
        ("frac3000", fracs(3000), "characters"),
        ("parens300", parens(300), "nested more than 256"),
        ("frac300", fracs(300), "nested more than 256"),
    ] {
        refused_eq1(tag, &format!(r"\mathbf{{a}} = {nested}"), says);
    }
    let sum = vec!["a"; 1000].join(" + ");
    refused_eq1(
        "sum1000",
        &format!(r"\mathbf{{a}} = {sum}"),
        "operations deep",
    );
    refused_eq1(
        "div",
        r"\mathbf{a} = a \div 2",
        r"\frac{numerator}{denominator}",
    );
}

#[test]
fn a_huge_or_broken_yaml_file_is_refused_quoting_at_most_a_line() {
    // 20 MB on one line: refused by its size before it is read.
    let d = dir("huge");
    std::fs::write(d.join("equations.yaml"), EQUATIONS).unwrap();
    std::fs::write(d.join("symbols.yaml"), "x".repeat(20 << 20)).unwrap();
    let (code, _, err, took) = check(&d, &["--only", "1"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(took < Duration::from_secs(2), "took {took:?}");
    assert!(
        err.contains("symbols.yaml") && err.contains("bytes"),
        "{err}"
    );
    assert!(err.len() < 1000, "{} bytes of messages", err.len());
    // Within the limit, a value of the wrong type on a 500 KB line: serde's message quotes the
    // value; the message keeps a line's start and the location.
    std::fs::write(d.join("symbols.yaml"), "y".repeat(500_000)).unwrap();
    let (code, _, err, _) = check(&d, &["--only", "1"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("symbols.yaml"), "{err}");
    assert!(err.len() < 1000, "{} bytes of messages", err.len());
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    std::fs::remove_dir_all(&d).ok();
}

/// An equation that cannot be evaluated (eq 31 with the square root of -1 added) is reported
/// as a check that could not evaluate its claim: `check --json` carries no verdict "fails"
/// whose claimed value is not a finite number, and the CLI exits 1 saying a check could not run.
#[test]
fn a_claim_that_is_not_a_number_is_an_error_never_a_failure() {
    let d = dir("nan");
    let eq31 = r"'\Omega_0^2 = \frac{g}{a k \sin\alpha_0}'";
    assert!(EQUATIONS.contains(eq31));
    let edited = EQUATIONS.replacen(
        eq31,
        r"'\Omega_0^2 = \frac{g}{a k \sin\alpha_0} + \sqrt{- 1}'",
        1,
    );
    std::fs::write(d.join("equations.yaml"), edited).unwrap();
    let (code, out, err, _) = check(&d, &["--json", "--only", "31,73,76,79,83"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("could not run"), "{err}");
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let checks = doc["checks"].as_array().unwrap();
    assert!(!checks.is_empty());
    let mut eq31_seen = false;
    for c in checks {
        let text = c.to_string();
        if c["name"] == "eq 31" {
            eq31_seen = true;
            assert!(
                text.contains("could not evaluate the claim"),
                "eq 31: {text}"
            );
            assert!(c["cause"].is_null(), "eq 31: {text}");
        }
        for outcome in [&c["outcome"], &c["derivation"]] {
            if outcome.to_string().contains("\"fails\"") {
                assert!(
                    outcome["claimed"].as_f64().is_some_and(f64::is_finite),
                    "{text}"
                );
            }
        }
        assert!(!text.contains("eq 31 relation"), "{text}");
    }
    assert!(eq31_seen, "{out}");
    std::fs::remove_dir_all(&d).ok();
}
