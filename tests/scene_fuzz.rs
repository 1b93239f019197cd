//! Property tests of the scene reader with large case counts: whatever the text, it returns in
//! bounded time with either a scene or one sentence (file and line, no serde jargon, values
//! cut), never a panic. The cargo-fuzz targets in `fuzz/` explore the same entry point without
//! bound; crashes they find become cases in `regressions` below.

use physics::scene::{builtin::BUILTIN, Scene};
use proptest::prelude::*;

/// Asserts what every answer of the reader must satisfy. (The cases are drawn from a fixed seed,
/// so that CI runs the same ones every time; `fuzz/` explores without bound.)
fn answers_well(src: &str) {
    match Scene::parse(src, "fuzz.yaml") {
        Ok(scene) => {
            assert!(scene.stop.time.is_finite() && scene.stop.time > 0.0);
            assert!(scene.disk.a.is_finite() && scene.disk.a > 0.0);
        }
        Err(e) => {
            let text = e.to_string();
            assert!(text.starts_with("fuzz.yaml"), "{text}");
            assert!(!text.contains('\n'), "more than one line: {text:?}");
            assert!(
                text.chars().count() < 800,
                "{} characters",
                text.chars().count()
            );
            for jargon in [
                "invalid type",
                "struct Scene",
                "expected f64",
                "unknown variant",
            ] {
                assert!(!text.contains(jargon), "{jargon:?} in {text}");
            }
        }
    }
}

/// The characters YAML gives meaning to, plus a few that break it.
const ALPHABET: &[char] = &[
    ' ', ' ', '\n', '\r', '\t', ':', '-', '{', '}', '[', ']', ',', '#', '"', '\'', '|', '>', '&',
    '*', '!', '%', '@', '`', '?', '.', '0', '1', '9', 'e', 'a', 'k', '\u{feff}', '\u{0}', 'é',
];

fn yamlish() -> impl Strategy<Value = String> {
    proptest::collection::vec(proptest::sample::select(ALPHABET), 0..200)
        .prop_map(|cs| cs.into_iter().collect())
}

/// A built-in scene with a few random edits: a character replaced, inserted or removed.
fn mutated() -> impl Strategy<Value = String> {
    let edits = proptest::collection::vec(
        (
            0usize..3,
            any::<prop::sample::Index>(),
            proptest::sample::select(ALPHABET),
        ),
        1..6,
    );
    (0..BUILTIN.len(), edits).prop_map(|(which, edits)| {
        let mut cs: Vec<char> = BUILTIN[which].1.chars().collect();
        for (kind, at, c) in edits {
            let i = at.index(cs.len().max(1)).min(cs.len());
            match kind {
                0 if i < cs.len() => cs[i] = c,
                1 => cs.insert(i, c),
                _ if i < cs.len() => {
                    cs.remove(i);
                }
                _ => {}
            }
        }
        cs.into_iter().collect()
    })
}

/// A built-in scene with one number replaced by an extreme one.
fn extreme_number() -> impl Strategy<Value = String> {
    let numbers = prop_oneof![
        Just("0".to_string()),
        Just("-0.0".to_string()),
        Just(".nan".to_string()),
        Just(".inf".to_string()),
        Just("-.inf".to_string()),
        Just("1e308".to_string()),
        Just("1e-320".to_string()),
        Just("4294967296".to_string()),
        Just("-1".to_string()),
        any::<f64>().prop_map(|x| format!("{x:e}")),
    ];
    (0..BUILTIN.len(), any::<prop::sample::Index>(), numbers).prop_map(|(which, at, n)| {
        let src = BUILTIN[which].1;
        let spots: Vec<usize> = src
            .match_indices(": ")
            .map(|(i, _)| i + 2)
            .filter(|&i| src[i..].starts_with(|c: char| c.is_ascii_digit() || c == '-'))
            .collect();
        if spots.is_empty() {
            return src.to_string();
        }
        let i = spots[at.index(spots.len())];
        let end = src[i..]
            .find([',', ' ', '}', '\n'])
            .map_or(src.len(), |j| i + j);
        format!("{}{n}{}", &src[..i], &src[end..])
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 10_000, failure_persistence: None, rng_seed: proptest::test_runner::RngSeed::Fixed(20_261_123), ..ProptestConfig::default() })]

    #[test]
    fn any_yamlish_text(src in yamlish()) {
        answers_well(&src);
    }

    #[test]
    fn built_in_scenes_with_random_edits(src in mutated()) {
        answers_well(&src);
    }

    #[test]
    fn built_in_scenes_with_extreme_numbers(src in extreme_number()) {
        answers_well(&src);
    }

    #[test]
    fn any_text_at_all(src in ".{0,300}") {
        answers_well(&src);
    }
}

/// Hostile inputs for the reader (from hostile runs and from fuzzing).
#[test]
fn regressions() {
    for src in [
        "\u{feff}",
        "\r",
        "\r\n\r\n",
        "name: x\r\rdisk: { radius: 1 }",
        // Found by the property test: a complex key holding a line break.
        "? .\n\n -",
        &format!("name: {}", "[".repeat(1000)),
        &format!("name: {}", "{a: ".repeat(1000)),
        "disk: *a",
        "&a [*a]",
        "name: !!binary aGk=",
        "? [a]\n: b",
    ] {
        answers_well(src);
    }
}
