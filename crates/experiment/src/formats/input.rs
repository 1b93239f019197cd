//! The one door through which the experiment reads a file: bounded, and regular files only.
//!
//! A recording is read whole into memory, so its size is refused above a documented limit
//! instead of being read (and then fitted into a bound). A FIFO, a device (`/dev/zero`), a
//! directory or a socket is refused at once, before any read, so that nothing blocks or grows
//! without end. The size is checked before reading and again while reading (a file that grows
//! while it is read is cut at the limit plus one byte and refused).

use crate::error::ExperimentError;
use std::io::Read;
use std::path::Path;

/// The largest file read (bytes): 256 MiB, five times a 2,000,000-row CSV of full-precision
/// numbers, or 2,000,000 stereo 32-bit samples with room to spare.
pub const MAX_BYTES: u64 = 256 * 1024 * 1024;

/// The most samples (per channel) a trace may hold: 2,000,000, forty times the paper's record
/// of 50,000 samples (10 s at 5 kS/s), or 41 s of audio at 48 kHz.
pub const MAX_SAMPLES: usize = 2_000_000;

/// The most samples (per channel) a sound recording may hold: 6,000,000, 125 s at 48 kHz or
/// 62.5 s at 96 kHz (a spin-down's whole sound with its lead-in); decoded as two channels of
/// 64-bit samples they take 96 MB.
pub const MAX_SOUND_SAMPLES: usize = 6_000_000;

/// Reads a regular file of at most `limit` bytes.
pub fn read_bounded(path: &Path, limit: u64) -> Result<Vec<u8>, ExperimentError> {
    let file = path.display().to_string();
    let io = |message: String| ExperimentError::Io {
        file: file.clone(),
        message,
    };
    let meta = std::fs::metadata(path).map_err(|e| io(format!("cannot read it ({e})")))?;
    if !meta.is_file() {
        let kind = if meta.is_dir() {
            "a directory"
        } else {
            "not a regular file (a pipe, a device or a socket)"
        };
        return Err(io(format!(
            "this is {kind}: give the path of a recording saved as a file"
        )));
    }
    if meta.len() > limit {
        return Err(ExperimentError::TooLarge {
            file: file.clone(),
            bytes: meta.len(),
            limit,
        });
    }
    let f = std::fs::File::open(path).map_err(|e| io(format!("cannot open it ({e})")))?;
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    f.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| io(format!("cannot read it ({e})")))?;
    if bytes.len() as u64 > limit {
        return Err(ExperimentError::TooLarge {
            file,
            bytes: bytes.len() as u64,
            limit,
        });
    }
    Ok(bytes)
}

/// The formats a recording is read in, in words, for messages.
pub const FORMATS_READ: &str = "a scope CSV (text), or sound as WAV, FLAC, Ogg Vorbis, MP3, \
                                M4A/AAC, raw AAC (ADTS), AIFF or CAF";

/// The first bytes of a file in words: up to 8 in hexadecimal, and as text where printable
/// (`52 49 46 46 ... ("RIFF....")`).
pub fn first_bytes(bytes: &[u8]) -> String {
    let head = &bytes[..bytes.len().min(8)];
    let hex: Vec<String> = head.iter().map(|b| format!("{b:02x}")).collect();
    let text: String = head
        .iter()
        .map(|&b| {
            if b.is_ascii_graphic() || b == b' ' {
                b as char
            } else {
                '.'
            }
        })
        .collect();
    format!("{} (\"{text}\")", hex.join(" "))
}

/// Whether bytes are binary rather than text in some encoding: a NUL byte, or more than one
/// in ten of the first 512 bytes a control character other than tab, CR or LF.
pub fn is_binary(bytes: &[u8]) -> bool {
    let head = &bytes[..bytes.len().min(512)];
    let control = head
        .iter()
        .filter(|&&b| b < 0x20 && !matches!(b, b'\t' | b'\r' | b'\n'))
        .count();
    head.contains(&0) || control * 10 > head.len()
}
