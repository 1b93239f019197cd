//! Fuzzes the reader of the paper's symbol table (`symbols.yaml`, read by `Paper::from_texts`
//! beside the built-in equations and claims) on arbitrary text: a paper or an error that names
//! the file and quotes at most a line of the input, never a panic or a hang.
//! Corpus: `fuzz/corpus/symbols` (the built-in table and parts of it).
#![no_main]

use libfuzzer_sys::fuzz_target;
use paper::{Paper, PaperSource, Texts};

fuzz_target!(|data: &[u8]| {
    let Ok(symbols) = std::str::from_utf8(data) else {
        return;
    };
    let texts = Texts {
        symbols,
        ..Texts::BUILT_IN
    };
    if let Err(e) = Paper::from_texts(PaperSource::BuiltIn, texts) {
        let message = e.to_string();
        assert!(!message.is_empty());
        assert!(message.chars().count() < 2000, "{message:?}");
    }
});
