//! A sound recording as a person has it: WAV (through `hound`, 8-32 bit integer or 32-bit float)
//! or a compressed file a phone or an editor writes (FLAC, MP3, Ogg Vorbis, M4A/AAC, through the
//! pure-Rust `symphonia` decoders), read into a [`Trace`] of full-scale units with what the file
//! is ([`RecordingInfo`]: format, rate, channels, length).
//!
//! The container is recognised by its first bytes, not by the file's name. Every file goes
//! through [`read_bounded`] (size limit, regular files only); the decoded length is checked
//! against [`MAX_SAMPLES`] per channel while decoding, so memory stays bounded. The channels are
//! averaged, or one is chosen ([`Channels`]).

use crate::experiment::error::ExperimentError;
use crate::experiment::input::{read_bounded, MAX_BYTES, MAX_SAMPLES};
use crate::experiment::trace::Trace;
use serde::Serialize;
use std::path::Path;
use symphonia::core::audio::SampleBuffer;
use symphonia::core::codecs::{DecoderOptions, CODEC_TYPE_NULL};
use symphonia::core::errors::Error as DecodeError;
use symphonia::core::formats::FormatOptions;
use symphonia::core::io::MediaSourceStream;
use symphonia::core::meta::MetadataOptions;
use symphonia::core::probe::Hint;

/// The lowest and highest sample rates read (S/s).
pub const RATES: (u32, u32) = (1000, 384_000);

/// The fewest samples per channel read.
pub const MIN_SAMPLES: usize = 16;

/// The most channels read.
pub const MAX_CHANNELS: usize = 8;

/// Which channel of a multi-channel recording is analysed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Channels {
    /// The channels' mean.
    Mix,
    /// One channel, counted from 1.
    One(usize),
}

/// What a recording file is.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RecordingInfo {
    /// Container and coding, e.g. "WAV, 16-bit integer PCM" or "FLAC".
    pub format: String,
    /// Samples per second.
    pub sample_rate: u32,
    /// Channels in the file.
    pub channels: usize,
    /// The channel analysed ("mix of 2", "channel 1 of 2", "mono").
    pub used: String,
    /// Samples per channel.
    pub samples: usize,
    /// Length (s).
    pub seconds: f64,
}

impl std::fmt::Display for RecordingInfo {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}, {} S/s, {} channel(s) ({}), {} samples, {:.3} s",
            self.format, self.sample_rate, self.channels, self.used, self.samples, self.seconds
        )
    }
}

/// A recording read: its signal and what the file was.
#[derive(Debug, Clone, PartialEq)]
pub struct Recording {
    /// Time (s from the first sample) and signal (full-scale units).
    pub trace: Trace,
    /// The file's format, rate, channels and length.
    pub info: RecordingInfo,
}

/// The container, by the file's first bytes.
fn container(bytes: &[u8]) -> Option<(&'static str, &'static str)> {
    let head = |s: &[u8]| bytes.starts_with(s);
    if head(b"RIFF") || head(b"RF64") || head(b"RIFX") {
        Some(("WAV", "wav"))
    } else if head(b"fLaC") {
        Some(("FLAC", "flac"))
    } else if head(b"OggS") {
        Some(("Ogg", "ogg"))
    } else if bytes.len() > 8 && &bytes[4..8] == b"ftyp" {
        Some(("M4A/MP4", "m4a"))
    } else if head(b"ID3") || (bytes.len() > 1 && bytes[0] == 0xFF && bytes[1] & 0xE0 == 0xE0) {
        Some(("MP3", "mp3"))
    } else {
        None
    }
}

fn refuse(file: &str, format: &str, message: String, fix: &str) -> ExperimentError {
    ExperimentError::Audio {
        file: file.into(),
        format: format.into(),
        message,
        fix: fix.into(),
    }
}

/// Reads a recording of any supported format.
pub fn read_recording(
    path: impl AsRef<Path>,
    channels: Channels,
) -> Result<Recording, ExperimentError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    let bytes = read_bounded(path, MAX_BYTES)?;
    parse_recording(bytes, &file, channels)
}

/// Decodes a recording's bytes; `file` names them in errors.
pub fn parse_recording(
    bytes: Vec<u8>,
    file: &str,
    channels: Channels,
) -> Result<Recording, ExperimentError> {
    let Some((format, ext)) = container(&bytes) else {
        return Err(refuse(
            file,
            "sound",
            "the first bytes are not those of a WAV, FLAC, Ogg, MP3 or M4A file".into(),
            "export the recording as WAV, FLAC, MP3, Ogg Vorbis or M4A",
        ));
    };
    let (interleaved, rate, n_ch, format) = if ext == "wav" {
        crate::experiment::wav::decode_wav(&bytes, file)?
    } else {
        decode_compressed(bytes, file, format, ext)?
    };
    mix(interleaved, rate, n_ch, format, file, channels)
}

/// Checks rate and length, and reduces interleaved samples to one channel.
pub(crate) fn mix(
    interleaved: Vec<f64>,
    rate: u32,
    n_ch: usize,
    format: String,
    file: &str,
    channels: Channels,
) -> Result<Recording, ExperimentError> {
    if !(RATES.0..=RATES.1).contains(&rate) {
        return Err(refuse(
            file,
            &format,
            format!("a sample rate of {rate} S/s"),
            "record or export at a rate between 1000 and 384000 S/s (44100 or 48000 is usual)",
        ));
    }
    if n_ch == 0 || n_ch > MAX_CHANNELS {
        return Err(refuse(
            file,
            &format,
            format!("{n_ch} channels"),
            "export the recording as mono or stereo",
        ));
    }
    let samples = interleaved.len() / n_ch;
    if samples < MIN_SAMPLES {
        return Err(refuse(
            file,
            &format,
            format!("it holds {samples} sample(s) per channel, fewer than {MIN_SAMPLES}"),
            "record the whole spin-down, from a few seconds before the disk settles until it is silent",
        ));
    }
    let (v, used): (Vec<f64>, String) = match channels {
        Channels::Mix if n_ch == 1 => (interleaved, "mono".into()),
        Channels::Mix => (
            interleaved
                .chunks_exact(n_ch)
                .map(|c| c.iter().sum::<f64>() / n_ch as f64)
                .collect(),
            format!("mix of {n_ch}"),
        ),
        Channels::One(k) if (1..=n_ch).contains(&k) => (
            interleaved.chunks_exact(n_ch).map(|c| c[k - 1]).collect(),
            format!("channel {k} of {n_ch}"),
        ),
        Channels::One(k) => {
            return Err(refuse(
                file,
                &format,
                format!("channel {k} was asked for; the file has {n_ch}"),
                "choose a channel from 1 to the file's count, or mix them",
            ))
        }
    };
    let r = f64::from(rate);
    let info = RecordingInfo {
        format,
        sample_rate: rate,
        channels: n_ch,
        used,
        samples,
        seconds: samples as f64 / r,
    };
    Ok(Recording {
        trace: Trace {
            source: file.into(),
            t: (0..v.len()).map(|j| j as f64 / r).collect(),
            v,
            truth: None,
        },
        info,
    })
}

/// Decodes FLAC, Ogg Vorbis, MP3 or M4A/AAC bytes to interleaved full-scale samples.
fn decode_compressed(
    bytes: Vec<u8>,
    file: &str,
    container: &str,
    ext: &str,
) -> Result<(Vec<f64>, u32, usize, String), ExperimentError> {
    let fix = "the file may be damaged or use a coding this tool does not decode: export it as WAV or FLAC";
    let bad = |e: DecodeError| refuse(file, container, format!("not decodable ({e})"), fix);
    let mss = MediaSourceStream::new(Box::new(std::io::Cursor::new(bytes)), Default::default());
    let mut hint = Hint::new();
    hint.with_extension(ext);
    let probed = symphonia::default::get_probe()
        .format(
            &hint,
            mss,
            &FormatOptions::default(),
            &MetadataOptions::default(),
        )
        .map_err(bad)?;
    let mut reader = probed.format;
    let track = reader
        .tracks()
        .iter()
        .find(|t| t.codec_params.codec != CODEC_TYPE_NULL)
        .ok_or_else(|| refuse(file, container, "no audio track".into(), fix))?;
    let (id, params) = (track.id, track.codec_params.clone());
    let codec = symphonia::default::get_codecs()
        .get_codec(params.codec)
        .map_or("unknown coding", |d| d.long_name);
    let format = format!("{container}, {codec}");
    let n_ch = params.channels.map_or(0, |c| c.count());
    if params.n_frames.is_some_and(|n| n > MAX_SAMPLES as u64) {
        return Err(ExperimentError::TooManySamples {
            file: file.into(),
            line: 0,
            limit: MAX_SAMPLES,
        });
    }
    let mut decoder = symphonia::default::get_codecs()
        .make(&params, &DecoderOptions::default())
        .map_err(bad)?;
    let mut out: Vec<f64> = Vec::new();
    let mut rate = params.sample_rate.unwrap_or(0);
    let mut channels = n_ch;
    loop {
        let packet = match reader.next_packet() {
            Ok(p) => p,
            Err(DecodeError::IoError(e)) if e.kind() == std::io::ErrorKind::UnexpectedEof => break,
            Err(DecodeError::ResetRequired) => break,
            Err(e) => return Err(bad(e)),
        };
        if packet.track_id() != id {
            continue;
        }
        let buf = match decoder.decode(&packet) {
            Ok(b) => b,
            Err(DecodeError::DecodeError(_)) => continue,
            Err(e) => return Err(bad(e)),
        };
        let spec = *buf.spec();
        rate = spec.rate;
        channels = spec.channels.count();
        let mut sb = SampleBuffer::<f32>::new(buf.capacity() as u64, spec);
        sb.copy_interleaved_ref(buf);
        out.extend(sb.samples().iter().map(|&x| f64::from(x)));
        if out.len() > MAX_SAMPLES * channels.max(1) {
            return Err(ExperimentError::TooManySamples {
                file: file.into(),
                line: 0,
                limit: MAX_SAMPLES,
            });
        }
    }
    if let Some(j) = out.iter().position(|x| !x.is_finite()) {
        return Err(refuse(
            file,
            &format,
            format!("sample {j} decodes to NaN or infinity"),
            fix,
        ));
    }
    Ok((out, rate, channels, format))
}
