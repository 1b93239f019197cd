//! What a recording's first bytes say it is: its container, told by content and not by the
//! file's name, for the whole-file reader ([`recording`](crate::formats::recording)) and the
//! reader in pieces ([`long`](crate::formats::long)) alike.

/// The priming samples an AAC-LC encoder puts before the sound (one frame of 1024, ffmpeg's and
/// FAAC's), left out of a raw ADTS stream, which does not record its own.
pub const ADTS_PRIMING: usize = 1024;

/// Whether the first bytes are an ADTS frame header: the 12-bit sync word and layer 00 (MPEG
/// audio's layers I-III, which share the sync word, have a non-zero layer).
fn adts(bytes: &[u8]) -> bool {
    bytes.len() > 1 && bytes[0] == 0xFF && bytes[1] & 0xF6 == 0xF0
}

/// A sound format recognised by its first bytes that no decoder here reads: Ogg Opus
/// (`symphonia` 0.5 has no Opus decoder; the pure-Rust ones on crates.io, `opus-decoder` 0.1,
/// `opus-pure` 0.2, `opus-rs` 0.1, are early releases not built in), refused with the
/// conversion to make.
pub(crate) fn unread(bytes: &[u8]) -> Option<&'static str> {
    let head = &bytes[..bytes.len().min(64)];
    if head.starts_with(b"OggS") && head.windows(8).any(|w| w == b"OpusHead") {
        Some("Ogg Opus")
    } else {
        None
    }
}

/// Whether the first bytes are an AIFF or AIFF-C file: an IFF `FORM` whose type is `AIFF` or
/// `AIFC`.
fn aiff(bytes: &[u8]) -> bool {
    bytes.starts_with(b"FORM") && matches!(bytes.get(8..12), Some(b"AIFF" | b"AIFC"))
}

/// The container, by the file's first bytes.
pub(crate) fn container(bytes: &[u8]) -> Option<(&'static str, &'static str)> {
    let head = |s: &[u8]| bytes.starts_with(s);
    if head(b"RIFF") || head(b"RF64") || head(b"RIFX") {
        Some(("WAV", "wav"))
    } else if head(b"fLaC") {
        Some(("FLAC", "flac"))
    } else if aiff(bytes) {
        Some(("AIFF", "aiff"))
    } else if head(b"caff") {
        Some(("Core Audio (CAF)", "caf"))
    } else if head(b"OggS") {
        Some(("Ogg", "ogg"))
    } else if bytes.len() > 8 && &bytes[4..8] == b"ftyp" {
        Some(("M4A/MP4", "m4a"))
    } else if adts(bytes) {
        Some(("raw AAC (ADTS)", "aac"))
    } else if head(b"ID3") || (bytes.len() > 1 && bytes[0] == 0xFF && bytes[1] & 0xE0 == 0xE0) {
        Some(("MP3", "mp3"))
    } else {
        None
    }
}
