//! Fuzzes the scene reader on arbitrary text: it must answer with a scene or one bounded
//! sentence, never panic or hang. Corpus: `fuzz/corpus/scene` (the built-in scenes to start).
#![no_main]

use libfuzzer_sys::fuzz_target;
use physics::scene::Scene;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Err(e) = Scene::parse(text, "fuzz.yaml") {
        let message = e.to_string();
        assert!(!message.contains('\n'), "{message:?}");
        assert!(message.chars().count() < 800, "{message:?}");
    }
});
