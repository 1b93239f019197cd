//! Fuzzes the WAV reader on arbitrary bytes: a recording or an error, never a panic, a hang or
//! an allocation sized by a header field. Corpus: `fuzz/corpus/wav`.
#![no_main]

use experiment::wav::parse_wav;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(e) = parse_wav(data, "fuzz.wav") {
        assert!(e.to_string().chars().count() < 800);
    }
});
