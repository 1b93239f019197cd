//! Fuzzes the scope-CSV reader on arbitrary text: it must answer with a trace or one error that
//! names the file, never panic or hang. Corpus: `fuzz/corpus/csv`.
#![no_main]

use experiment::parse_trace;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Err(e) = parse_trace(text, "fuzz.csv") {
        let message = e.to_string();
        assert!(message.contains("fuzz.csv"), "{message:?}");
        assert!(message.chars().count() < 800, "{message:?}");
    }
});
