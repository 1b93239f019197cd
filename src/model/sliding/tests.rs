//! Unit tests of the contact laws (the closed forms and limits are in `tests/sliding.rs`).
