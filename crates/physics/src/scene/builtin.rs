//! The scenes shipped in `paper/scenes/`, compiled into the binary so that it runs with no files
//! at hand.

/// (name, YAML source) of every built-in scene, in the order they are listed.
pub const BUILTIN: &[(&str, &str)] = &[
    (
        "spinning-coin",
        include_str!("../../../../paper/scenes/spinning-coin.yaml"),
    ),
    (
        "nutating-coin",
        include_str!("../../../../paper/scenes/nutating-coin.yaml"),
    ),
    (
        "rolling-circle",
        include_str!("../../../../paper/scenes/rolling-circle.yaml"),
    ),
    (
        "negative-b",
        include_str!("../../../../paper/scenes/negative-b.yaml"),
    ),
    (
        "wheel-straight",
        include_str!("../../../../paper/scenes/wheel-straight.yaml"),
    ),
    (
        "vertical-spin",
        include_str!("../../../../paper/scenes/vertical-spin.yaml"),
    ),
    (
        "vertical-spin-frictionless",
        include_str!("../../../../paper/scenes/vertical-spin-frictionless.yaml"),
    ),
    (
        "spin-down",
        include_str!("../../../../paper/scenes/spin-down.yaml"),
    ),
    (
        "spin-down-adiabatic",
        include_str!("../../../../paper/scenes/spin-down-adiabatic.yaml"),
    ),
    (
        "benchmark",
        include_str!("../../../../paper/scenes/benchmark.yaml"),
    ),
    (
        "wheel-thrown-sliding",
        include_str!("../../../../paper/scenes/wheel-thrown-sliding.yaml"),
    ),
    (
        "slip-stick",
        include_str!("../../../../paper/scenes/slip-stick.yaml"),
    ),
    (
        "coin-bounce",
        include_str!("../../../../paper/scenes/coin-bounce.yaml"),
    ),
];

/// The built-in scene whose name is nearest to `name` ([`crate::nearest`]).
pub fn nearest(name: &str) -> Option<&'static str> {
    crate::nearest::nearest(name, BUILTIN.iter().map(|(n, _)| *n))
}

/// The source of the built-in scene `name`.
pub fn source(name: &str) -> Option<&'static str> {
    BUILTIN.iter().find(|(n, _)| *n == name).map(|(_, s)| *s)
}
