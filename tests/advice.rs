//! Every refusal's advice is right: each case below is refused with a sentence naming the fix,
//! the fix is applied as the sentence says, and the re-run succeeds. Inputs that could hang
//! are refused (or finish) within seconds.

use crate::common::{cli_timed, read_wav_i16, temp_dir, write_wav_i16};
use std::time::Duration;

/// The word (up to a space, a comma or a closing parenthesis) after `lead` in `text`, as the
/// user would copy it from the message.
fn word_after<'t>(text: &'t str, lead: &str) -> &'t str {
    let i = text
        .find(lead)
        .unwrap_or_else(|| panic!("`{lead}` not in: {text}"));
    let rest = &text[i + lead.len()..];
    let end = rest.find([' ', ',', ')', '\n']).unwrap_or(rest.len());
    rest[..end].trim_end_matches(['.', ';', ':'])
}

const COIN: &str = "name: t
description: a test coin
disk: { radius: 0.01213, k: 0.25, mass: 0.00567, g: 9.81 }
model: rolling
start: { steady: { alpha0: 0.3, b: 0.0 } }
stop: { time: 1.0 }
record: [alpha, precession, spin]
";

const SPIN_DOWN: &str = "name: t
description: a test spin-down
disk: { radius: 0.0375, k: 0.25, mass: 0.4, g: 9.81 }
model: dissipative
dissipation: { epsilon: 1.2e-6, beta: 2.0 }
start: { steady: { alpha0: 0.15, b: 0.0 } }
stop: { time: 60.0, lift_off: true, alpha_below: 1.0e-4 }
";

const BOUNCE: &str = "name: t
description: a test bounce
disk: { radius: 0.0375, k: 0.25, mass: 0.4, g: 9.81 }
model: sliding
friction: { mu: 0.3, restitution: 0.5 }
start: { explicit: { alpha: 1.3, alpha_dot: -30.0, precession: 5.0, spin: 20.0 } }
stop: { time: 0.5 }
sample: 0.001
";

/// A scene refused with `says`, and the scene the advice makes of it (given the message).
struct Case {
    name: &'static str,
    scene: String,
    says: &'static str,
    fix: fn(&str, &str) -> String,
}

fn cases() -> Vec<Case> {
    vec![
        Case {
            name: "max_steps 5e7, as docs/limits.md bounds it",
            scene: format!("{COIN}solver: {{ method: dop853, max_steps: 5e7 }}\n"),
            says: "lower max_steps to ",
            fix: |scene, msg| scene.replace("5e7", word_after(msg, "lower max_steps to ")),
        },
        Case {
            name: "sampling finer than the row limit",
            // Rows are streamed: the limit is the rows the wall-time budget can write.
            scene: format!("{COIN}sample: 1.0e-10\n"),
            says: "raise sample to ",
            fix: |scene, msg| scene.replace("1.0e-10", word_after(msg, "raise sample to ")),
        },
        Case {
            name: "rtol below double precision",
            scene: format!("{COIN}solver: {{ method: dop853, rtol: 1.0e-20, atol: 1.0e-12 }}\n"),
            says: "use rtol ",
            fix: |scene, msg| scene.replace("1.0e-20", word_after(msg, "use rtol ")),
        },
        Case {
            name: "a precession no run can resolve",
            scene: COIN.replace(
                "{ steady: { alpha0: 0.3, b: 0.0 } }",
                "{ vertical_spin: { precession: 1.5e7 } }",
            ),
            says: "lower stop.time to ",
            fix: |scene, msg| {
                scene.replace(
                    "time: 1.0",
                    &format!("time: {}", word_after(msg, "lower stop.time to ")),
                )
            },
        },
        Case {
            name: "mu 1e300",
            scene: BOUNCE.replace("mu: 0.3", "mu: 1e300"),
            says: "to 10 (real",
            fix: |scene, _| scene.replace("mu: 1e300", "mu: 10"),
        },
        Case {
            name: "beta 1e6",
            scene: SPIN_DOWN.replace("beta: 2.0", "beta: 1e6"),
            says: "at most 10",
            fix: |scene, _| scene.replace("beta: 1e6", "beta: 10"),
        },
        Case {
            name: "a key given twice",
            scene: COIN.replacen(
                "description: a test coin\n",
                "description: a test coin\nname: u\n",
                1,
            ),
            says: ":3:1: the key `name` is given twice",
            fix: |scene, _| scene.replacen("name: u\n", "", 1),
        },
        Case {
            name: "a hexadecimal radius",
            scene: COIN.replace("radius: 0.01213", "radius: 0x1"),
            says: "write it in decimal",
            fix: |scene, _| scene.replace("radius: 0x1", "radius: 1"),
        },
        Case {
            name: "25,000 mechanisms",
            scene: format!(
                "{}mechanisms:\n{}",
                SPIN_DOWN.replace("dissipation: { epsilon: 1.2e-6, beta: 2.0 }\n", ""),
                "  - viscous_rolling: { time: 1.0e-8 }\n".repeat(25_000)
            ),
            says: "list each kind of mechanism once",
            fix: |scene, _| {
                let head = &scene[..scene.find("mechanisms:").unwrap_or(0)];
                format!("{head}mechanisms:\n  - viscous_rolling: {{ time: 2.0e-4 }}\n")
            },
        },
    ]
}

#[test]
fn every_refusal_names_a_fix_that_works() {
    let dir = temp_dir("advice", "table");
    for (i, case) in cases().into_iter().enumerate() {
        let file = format!("case{i}.yaml");
        std::fs::write(dir.join(&file), &case.scene).expect("written");
        let (ok, _, err, took) = cli_timed(&dir, &["simulate", &file]);
        assert!(!ok, "{}: accepted", case.name);
        assert!(err.contains(case.says), "{}: {err}", case.name);
        assert!(!err.contains("panicked"), "{}: {err}", case.name);
        assert!(
            took < Duration::from_secs(2),
            "{}: refused after {took:?}",
            case.name
        );
        let fixed = (case.fix)(&case.scene, &err);
        std::fs::write(dir.join(&file), &fixed).expect("written");
        let (ok, out, err, _) = cli_timed(&dir, &["simulate", &file]);
        assert!(ok, "{}: the advised fix fails:\n{fixed}\n{err}", case.name);
        assert!(out.contains("ended"), "{}: {out}", case.name);
    }
}

#[test]
fn options_out_of_range_are_refused_with_a_fix_that_works() {
    let dir = temp_dir("advice", "options");
    for (bad, good, says) in [
        (
            &["precision", "--quick", "--target", "0"][..],
            &["precision", "--quick", "--target", "1e-8"][..],
            "--target 0: give the error to reach as a number between 0 and 1",
        ),
        (
            &["precision", "--quick", "--target", "nan"],
            &["precision", "--quick", "--target", "1e-8"],
            "--target NaN: give the error",
        ),
        (
            &[
                "experiment",
                "simulate",
                "--csv",
                "g.csv",
                "--glitches",
                "1e9",
            ],
            &[
                "experiment",
                "simulate",
                "--csv",
                "g.csv",
                "--glitches",
                "1000",
            ],
            "isolated glitches per second from 0 to 1000",
        ),
    ] {
        let (ok, _, err, took) = cli_timed(&dir, bad);
        assert!(!ok, "{bad:?} accepted");
        assert!(err.contains(says), "{bad:?}: {err}");
        assert!(
            took < Duration::from_secs(2),
            "{bad:?}: refused after {took:?}"
        );
        let (ok, _, err, _) = cli_timed(&dir, good);
        assert!(ok, "{good:?}: {err}");
    }
}

#[test]
fn a_contact_only_model_says_when_the_table_would_have_to_pull() {
    let dir = temp_dir("advice", "contact");
    let rolling = BOUNCE
        .replace("model: sliding\n", "model: rolling\n")
        .replace("friction: { mu: 0.3, restitution: 0.5 }\n", "");
    std::fs::write(dir.join("rolling.yaml"), &rolling).expect("written");
    let (_, out, err, _) = cli_timed(&dir, &["simulate", "rolling.yaml"]);
    assert!(
        err.contains("warning") && err.contains("the normal force is -"),
        "{err}"
    );
    assert!(err.contains("use model: sliding"), "{err}");
    assert!(out.contains("not physics"), "{out}");
    // The advice applied: the sliding model follows the flight, without the warning.
    std::fs::write(dir.join("sliding.yaml"), BOUNCE).expect("written");
    let (ok, out, err, _) = cli_timed(&dir, &["simulate", "sliding.yaml"]);
    assert!(ok, "{err}");
    assert!(
        !err.contains("warning") && !out.contains("not physics"),
        "{err}{out}"
    );
    // A spin-down that stops at lift-off (F_z = 0) is not warned about.
    std::fs::write(dir.join("spin.yaml"), SPIN_DOWN).expect("written");
    let (ok, out, err, _) = cli_timed(&dir, &["simulate", "spin.yaml"]);
    assert!(ok, "{err}");
    assert!(
        !err.contains("warning") && !out.contains("not physics"),
        "{err}{out}"
    );
}

#[test]
fn a_newcomers_minimal_scenes_run_and_say_what_they_use() {
    let dir = temp_dir("advice", "newcomer");
    let adiabatic = "name: a
description: the adiabatic law with nothing but what it needs
disk: { radius: 0.0375, k: 0.25, mass: 0.4, g: 9.81 }
model: adiabatic
dissipation: { epsilon: 1.2e-6, beta: 2.0 }
start: { explicit: { alpha: 0.15 } }
stop: { time: 1.0 }
";
    std::fs::write(dir.join("adiabatic.yaml"), adiabatic).expect("written");
    let (ok, _, err, _) = cli_timed(&dir, &["simulate", "adiabatic.yaml"]);
    assert!(ok, "{err}");
    std::fs::write(
        dir.join("rk4.yaml"),
        format!("{COIN}solver: {{ method: rk4 }}\n"),
    )
    .expect("written");
    let (ok, out, err, _) = cli_timed(&dir, &["simulate", "rk4.yaml"]);
    assert!(ok, "{err}");
    assert!(out.contains("rk4, fixed step 1e-3 s"), "{out}");
    assert!(!out.contains("rtol 1e-10"), "{out}");
    // The checks' default accuracy is named once, as rtol 1e-12, wherever a default is said.
    let (_, out, _, _) = cli_timed(&dir, &["check", "--help"]);
    for line in out.lines().filter(|l| l.contains("rtol")) {
        if let Some(i) = line.find("default") {
            assert!(line[i..].contains("1e-12"), "{line}");
        }
    }
}

#[test]
fn stereo_channels_that_cancel_are_refused_with_the_channel_to_take() {
    let dir = temp_dir("advice", "cancel");
    let (ok, _, err, _) = cli_timed(&dir, &["experiment", "simulate", "--wav", "mono.wav"]);
    assert!(ok, "{err}");
    let (mono, rate) = read_wav_i16(&dir.join("mono.wav"));
    // Channel 2 is channel 1 with its sign reversed (-32768 has no opposite in 16 bits).
    let stereo: Vec<i16> = mono
        .iter()
        .flat_map(|&x| {
            let x = x.max(-i16::MAX);
            [x, -x]
        })
        .collect();
    write_wav_i16(&dir.join("cancel.wav"), &stereo, rate, 2);
    let (ok, _, err, took) = cli_timed(&dir, &["experiment", "analyze", "cancel.wav"]);
    assert!(!ok, "a silent mix accepted");
    assert!(err.contains("channels cancel when mixed"), "{err}");
    assert!(took < Duration::from_secs(2), "refused after {took:?}");
    let channel = word_after(&err, "--channel ");
    let (ok, out, err, _) = cli_timed(
        &dir,
        &["experiment", "analyze", "cancel.wav", "--channel", channel],
    );
    assert!(ok, "the advised --channel {channel} fails: {err}");
    assert!(out.contains("beta = "), "{out}");
    // The flag named is the command line's own.
    let (_, help, _, _) = cli_timed(&dir, &["experiment", "analyze", "--help"]);
    assert!(help.contains("--channel <N|mix>"), "{help}");
}

#[test]
fn an_analysis_past_its_budget_says_so_and_the_raised_budget_works() {
    let dir = temp_dir("advice", "budget");
    for (make, file) in [("--csv", "light.csv"), ("--wav", "sound.wav")] {
        let (ok, _, err, _) = cli_timed(&dir, &["experiment", "simulate", make, file]);
        assert!(ok, "{err}");
        let tiny = ["experiment", "analyze", file, "--max-seconds", "0.001"];
        let (ok, out, err, took) = cli_timed(&dir, &tiny);
        assert!(!ok, "{file}: analysed within 1 ms");
        assert!(out.is_empty(), "{file}: {out}");
        assert_eq!(err.lines().count(), 1, "{file}: {err}");
        assert!(
            err.contains(&format!(
                "the analysis of {file} ran past the wall-time budget of 0.001 s"
            )) && err.contains("raise the budget with --max-seconds SECONDS"),
            "{file}: {err}"
        );
        assert!(took < Duration::from_secs(2), "{file}: {took:?}");
        let raised = ["experiment", "analyze", file, "--max-seconds", "60"];
        let (ok, out, err, _) = cli_timed(&dir, &raised);
        assert!(ok, "{file}: the raised budget fails: {err}");
        assert!(out.contains("beta = "), "{file}: {out}");
        // Progress is drawn on a terminal only: piped, stderr holds no spinner.
        assert!(err.trim().is_empty(), "{file}: {err:?}");
    }
}
