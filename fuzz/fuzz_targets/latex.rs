//! Fuzzes the reader of the paper's LaTeX (the expression grammar of `src/paper/parse/`) on
//! arbitrary text: relations or an error whose column lies in the text, never a panic or a
//! hang. Corpus: `fuzz/corpus/latex` (the paper's 85 equations, one per file).
#![no_main]

use libfuzzer_sys::fuzz_target;
use paper::parse::parse;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Err(e) = parse(text) {
        assert!(
            e.column >= 1 && e.column <= text.chars().count() + 1,
            "{e:?}"
        );
        assert!(!e.message.is_empty());
    }
});
