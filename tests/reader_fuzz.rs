//! Property tests of the other readers of user input (the scene reader has `scene_fuzz.rs`): the
//! paper's LaTeX and symbol table, scope CSVs, WAV files and the command line's arguments. Whatever the input, each returns in bounded time with
//! a value or an error sentence, never a panic. Seeded, so that CI runs the same cases each time.

use experiment::{parse_trace, wav::parse_wav};
use paper::parse::parse;
use paper::{Paper, PaperSource, Texts};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

/// LaTeX tokens the paper uses, and a few that break it.
const TOKENS: &[&str] = &[
    r"\frac", r"\sqrt", r"\sin", r"\cos", r"\cot", r"\alpha", r"\Omega", r"\omega", r"\dot",
    r"\ddot", r"\hat", r"\vec", r"\mathbf", r"\mathrm", r"\left", r"\right", r"\cdot", r"\times",
    r"\approx", r"\geq", r"\equiv", r"\propto", r"\qquad", "{", "}", "(", ")", "[", "]", "|", "^",
    "_", "+", "-", "/", "=", "<", ">", ",", "a", "k", "t", "1", "2", "10", "1.8", " ", "\\", "é",
];

fn latex() -> impl Strategy<Value = String> {
    proptest::collection::vec(proptest::sample::select(TOKENS), 0..60).prop_map(|v| v.concat())
}

fn csvish() -> impl Strategy<Value = String> {
    let cell = proptest::sample::select(
        &[
            "0",
            "1e-3",
            "-2.5",
            "nan",
            "inf",
            "x",
            "",
            " ",
            "1,",
            "\t",
            ";",
            "#",
            "\"",
            "Time (ms)",
            "\u{feff}",
            "\r",
            "\n",
            "\r\n",
            "1e308",
            "-0",
        ][..],
    );
    proptest::collection::vec(cell, 0..200).prop_map(|v| v.concat())
}

fn wavish() -> impl Strategy<Value = Vec<u8>> {
    // A RIFF/WAVE header with random fields, or random bytes.
    let header = (
        any::<u16>(),
        1u16..3,
        any::<u32>(),
        prop_oneof![Just(8u16), Just(16), Just(24), Just(32), any::<u16>()],
    )
        .prop_map(|(fmt, ch, rate, bits)| {
            let mut v = Vec::new();
            v.extend_from_slice(b"RIFF");
            v.extend_from_slice(&1000u32.to_le_bytes());
            v.extend_from_slice(b"WAVEfmt ");
            v.extend_from_slice(&16u32.to_le_bytes());
            v.extend_from_slice(&(fmt % 4).to_le_bytes());
            v.extend_from_slice(&ch.to_le_bytes());
            v.extend_from_slice(&rate.to_le_bytes());
            v.extend_from_slice(&rate.wrapping_mul(4).to_le_bytes());
            v.extend_from_slice(&4u16.to_le_bytes());
            v.extend_from_slice(&bits.to_le_bytes());
            v.extend_from_slice(b"data");
            v.extend_from_slice(&64u32.to_le_bytes());
            v
        });
    (header, proptest::collection::vec(any::<u8>(), 0..256)).prop_map(|(mut h, body)| {
        h.extend(body);
        h
    })
}

/// Lines of a symbol table, the paper's and broken ones, in any order.
fn symbolsish() -> impl Strategy<Value = String> {
    let line = proptest::sample::select(vec![
        "'a': { quantity: a, means: \"radius\", unit: m }\n",
        "'\\alpha': { quantity: alpha, means: \"tilt\", unit: rad }\n",
        "'k': { quantity: k, means: \"inertia\", unit: '1' }\n",
        "'a': { quantity: a }\n",
        "'x': [1, 2\n",
        "  - nested\n",
        "'\\frac{': { quantity: q, means: \"m\", unit: s }\n",
        "key: value\n",
        "&a [*a]\n",
        "# a comment\n",
        "'\u{e9}': { quantity: e, means: \"\", unit: '' }\n",
        "\t\n",
    ]);
    proptest::collection::vec(line, 0..40).prop_map(|v| v.concat())
}

/// Command lines of the tool's words, values and nonsense.
fn argsish() -> impl Strategy<Value = Vec<String>> {
    let word = proptest::sample::select(vec![
        "simulate",
        "report",
        "check",
        "scenes",
        "experiment",
        "analyze",
        "peer",
        "precision",
        "figures",
        "mutants",
        "--csv",
        "--wav",
        "--json",
        "--out",
        "--channel",
        "--max-seconds",
        "--target",
        "--glitches",
        "--rate",
        "--format",
        "--only",
        "--paper",
        "--help",
        "-h",
        "--",
        "-",
        "spin-down",
        "x.csv",
        "2",
        "mix",
        "1e9",
        "nan",
        "-1",
        "",
        "=",
        "--csv=-",
        "\u{e9}",
        "--max-seconds=0",
    ]);
    proptest::collection::vec(word.prop_map(String::from), 0..8)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, failure_persistence: None, rng_seed: RngSeed::Fixed(20_261_126), ..ProptestConfig::default() })]

    #[test]
    fn the_symbol_table_reader_answers_in_a_bounded_message(symbols in symbolsish()) {
        let texts = Texts { symbols: &symbols, ..Texts::BUILT_IN };
        if let Err(e) = Paper::from_texts(PaperSource::BuiltIn, texts) {
            let text = e.to_string();
            prop_assert!(!text.is_empty() && text.chars().count() < 2000, "{text}");
        }
    }

    #[test]
    fn the_command_line_parses_or_says_why(args in argsish()) {
        let all = std::iter::once("rolling-disk".to_string()).chain(args);
        if let Err(e) = rolling_disk::parse(all) {
            prop_assert!(!e.render().to_string().is_empty());
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, failure_persistence: None, rng_seed: RngSeed::Fixed(20_261_124), ..ProptestConfig::default() })]

    #[test]
    fn the_latex_reader_answers_or_locates(src in latex()) {
        if let Err(e) = parse(&src) {
            prop_assert!(e.column >= 1 && e.column <= src.chars().count() + 1, "{e:?} for {src:?}");
            prop_assert!(!e.message.is_empty());
        }
    }

    #[test]
    fn the_csv_reader_answers_in_one_sentence(src in csvish()) {
        if let Err(e) = parse_trace(&src, "fuzz.csv") {
            let text = e.to_string();
            prop_assert!(text.contains("fuzz.csv"), "{text}");
        }
    }

    #[test]
    fn the_wav_reader_never_panics(bytes in wavish()) {
        let _ = parse_wav(&bytes, "fuzz.wav");
    }
}

/// Regressions found by cargo-fuzz (fuzz/README.md), kept as inputs under tests/fixtures/fuzz/.
mod regressions {
    use super::*;
    use std::path::PathBuf;

    fn fixture(name: &str) -> Vec<u8> {
        let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("tests/fixtures/fuzz")
            .join(name);
        std::fs::read(p).unwrap()
    }

    /// Nested `\frac{d...` that are not derivatives: each level was parsed twice (once as a
    /// failed derivative), so 626 bytes took over 6 s; now once.
    #[test]
    fn nested_fractions_that_look_like_derivatives_parse_at_once() {
        let text = String::from_utf8(fixture("latex-nested-fractions.tex")).unwrap();
        let start = std::time::Instant::now();
        let _ = parse(&text);
        let deeper = text.repeat(4);
        let _ = parse(&deeper);
        let took = start.elapsed().as_secs_f64();
        assert!(took < 0.5, "{took} s");
        // Derivatives still read as derivatives.
        let (chains, _) = parse(r"P = \frac{d U}{dt} = \frac{d^2 x}{dt^2}").unwrap();
        assert_eq!(chains.len(), 1);
    }

    /// A cell of control characters was quoted whole, escaped to over 800 characters; now cut
    /// to a few dozen, on one line.
    #[test]
    fn a_long_bad_cell_is_quoted_cut() {
        let text = String::from_utf8(fixture("csv-long-cell.csv")).unwrap();
        let e = parse_trace(&text, "fuzz.csv").unwrap_err().to_string();
        assert!(e.contains("fuzz.csv:2"), "{e}");
        // 40 characters at most, each at most `\u{XXXX}` escaped, plus the sentence.
        assert!(e.chars().count() < 500, "{} chars: {e}", e.chars().count());
        assert!(e.contains("(159 characters)"), "{e}");
        assert!(!e.contains('\n'), "{e}");
    }
}
