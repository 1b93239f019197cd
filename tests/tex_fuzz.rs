//! Property tests of the readers of an author's own LaTeX: the equation reader on the forms real
//! sources use (`\over`, font switches, rows and alignment points, `\text`, `\label`, nested
//! environments, Unicode), and the source reader (environments, numbering, macros) on arbitrary
//! text built from its pieces. Whatever the input, each returns in bounded time with a value or
//! an error sentence whose column lies in the text, never a panic. Seeded, so that CI runs the
//! same cases each time.

use paper::parse::parse;
use paper::tex::equations;
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

/// Pieces of an author's equations.
const TOKENS: &[&str] = &[
    r"\over",
    r"{\bf ",
    r"{\rm ",
    r"\mathrm{d}",
    r"\operatorname{sin}",
    r"\frac",
    r"\frac12",
    r"\dot",
    r"\vec",
    r"\hat",
    r"\mathbf",
    r"\alpha",
    r"\Omega",
    r"\sin",
    r"\cdot",
    r"\times",
    "&",
    "&=&",
    r"\\",
    r"\label{e1}",
    r"\tag{A}",
    r"\nonumber",
    r"\text{for }",
    r"\text{(x)}",
    r"\begin{aligned}",
    r"\end{aligned}",
    r"\begin{cases}",
    "α",
    "\u{2212}",
    "|",
    "d",
    "dt",
    "/",
    "{",
    "}",
    "(",
    ")",
    "^",
    "_",
    "+",
    "=",
    "<",
    ",",
    ".",
    "a",
    "b",
    "1",
    "2",
    " ",
    "\\",
    "%",
];

/// Pieces of a source: environments, definitions and their uses.
const SOURCE: &[&str] = &[
    r"\begin{document}",
    r"\begin{equation}",
    r"\end{equation}",
    r"\begin{eqnarray}",
    r"\end{eqnarray}",
    r"\begin{align*}",
    r"\end{align*}",
    r"\def\x#1{#1 \over #1}",
    r"\def\y{\y}",
    r"\newcommand{\z}[2]{#2 #1}",
    r"\x",
    r"\y",
    r"\z",
    r"\label{e",
    "}",
    "{",
    "&",
    r"\\",
    r"\nonumber",
    r"\tag{",
    "a = b",
    "%",
    "\n",
    " ",
    "#",
    "[",
    "]",
];

fn from(pieces: &'static [&'static str], n: usize) -> impl Strategy<Value = String> {
    proptest::collection::vec(proptest::sample::select(pieces), 0..n).prop_map(|v| v.concat())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, failure_persistence: None, rng_seed: RngSeed::Fixed(20_261_128), ..ProptestConfig::default() })]

    #[test]
    fn the_equation_reader_answers_or_locates(src in from(TOKENS, 40)) {
        if let Err(e) = parse(&src) {
            prop_assert!(e.column >= 1 && e.column <= src.chars().count() + 1, "{e:?}");
            prop_assert!(!e.message.is_empty());
        }
    }

    #[test]
    fn the_source_reader_answers_in_a_sentence(src in from(SOURCE, 60)) {
        match equations(&src) {
            Ok(found) => {
                for e in found {
                    prop_assert!(e.line >= 1 && e.line <= src.lines().count() + 1);
                }
            }
            Err(message) => prop_assert!(message.starts_with("line ") && message.len() < 400),
        }
    }
}
