//! Fuzzes the reader of a paper's LaTeX source (`paper::tex`: comments, environments, numbering,
//! `\def` and `\newcommand` expanded) and the equation reader on what it finds: numbered
//! equations or a sentence naming the line, never a panic or a hang. Corpus: the paper's source.
#![no_main]

use libfuzzer_sys::fuzz_target;
use paper::parse::parse;
use paper::tex::equations;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    match equations(text) {
        Ok(found) => {
            for e in found {
                let _ = parse(&e.latex);
            }
        }
        Err(message) => assert!(message.starts_with("line ")),
    }
});
