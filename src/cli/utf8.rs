//! A scene argument that is not UTF-8: refused naming the argument, with a fix. Scene files are
//! found by name (a path, or `builtin:NAME`), and every message names them, so a scene name must
//! be text; other paths (`--csv`, `--out`) are taken as the system gives them.

use clap::builder::{OsStringValueParser, TypedValueParser};

/// The parser of a SCENE argument.
pub(crate) fn scene() -> impl TypedValueParser<Value = String> {
    OsStringValueParser::new().try_map(|s| {
        s.into_string().map_err(|s| {
            format!(
                "`{}` is not valid UTF-8 (the characters shown as \u{fffd}): rename the scene file, \
                 or the folder it is in, with UTF-8 characters",
                s.to_string_lossy()
            )
        })
    })
}
