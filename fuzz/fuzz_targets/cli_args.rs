//! Fuzzes the command line's parser (the tool's own clap definitions, `rolling_disk::parse`) on
//! arbitrary arguments, NUL-separated: a command or clap's error, rendered as a message, never
//! a panic. Corpus: `fuzz/corpus/cli_args` (the commands of the README).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let args = std::iter::once("rolling-disk").chain(text.split('\0'));
    if let Err(e) = rolling_disk::parse(args) {
        let message = e.render().to_string();
        assert!(!message.is_empty());
    }
});
