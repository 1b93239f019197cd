//! Fuzzes the scene file path end to end (bounded read, BOM and line ends, parse, validate):
//! the bytes are written to a file and loaded, so invalid UTF-8 is exercised too.
#![no_main]

use libfuzzer_sys::fuzz_target;
use physics::scene::Scene;

fuzz_target!(|data: &[u8]| {
    let path = std::env::temp_dir().join(format!("rolling-disk-fuzz-{}.yaml", std::process::id()));
    if std::fs::write(&path, data).is_err() {
        return;
    }
    if let Err(e) = Scene::load(&path.display().to_string()) {
        let message = e.to_string();
        assert!(!message.contains('\n'), "{message:?}");
    }
});
