//! Sound recordings as WAV files (`hound`): read (mono, stereo or up to eight channels, 8-32 bit
//! integer or 32-bit float, 1-384 kS/s) into a [`Trace`] of full-scale units, and written
//! (16-bit, 24-bit or float, any rate) by `experiment simulate`.
//!
//! Reading goes through [`read_bounded`](crate::formats::input::read_bounded) like every
//! file; the header's sample count is checked against [`MAX_SOUND_SAMPLES`] before any sample is
//! decoded, and a longer file is read in pieces and decimated ([`long`](crate::formats::long)). [`read_wav`] averages the channels;
//! [`read_recording`](crate::formats::recording::read_recording) can choose one.

use crate::error::ExperimentError;
use crate::formats::channel::{mix, refuse, Channels};
use crate::formats::decoding::truncated;
use crate::formats::input::{read_bounded, MAX_BYTES, MAX_SOUND_SAMPLES};
use crate::trace::Trace;
use hound::{SampleFormat, WavReader, WavSpec, WavWriter};
use std::io::Cursor;
use std::path::Path;

/// Reads a WAV file into a trace (time in s from the first sample, signal in full-scale units).
pub fn read_wav(path: impl AsRef<Path>) -> Result<Trace, ExperimentError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    match read_bounded(path, MAX_BYTES).and_then(|b| parse_wav(&b, &file)) {
        Err(ExperimentError::SoundTooLong { .. } | ExperimentError::TooLarge { .. }) => {
            Ok(crate::formats::long::read_long(path, Channels::Mix)?.trace)
        }
        r => r,
    }
}

/// Decodes WAV bytes, channels averaged; `file` names them in errors.
pub fn parse_wav(bytes: &[u8], file: &str) -> Result<Trace, ExperimentError> {
    let (v, rate, ch, format) = decode_wav(bytes, file)?;
    Ok(mix(v, rate, ch, format, file, Channels::Mix)?.trace)
}

/// Decodes WAV bytes to interleaved full-scale samples, the rate, the channel count and a
/// description of the coding.
pub(crate) fn decode_wav(
    bytes: &[u8],
    file: &str,
) -> Result<(Vec<f64>, u32, usize, String), ExperimentError> {
    let wav = |message: String| ExperimentError::Wav {
        file: file.into(),
        message,
    };
    let mut reader = WavReader::new(Cursor::new(bytes)).map_err(|e| match e {
        // Bytes in memory fail to read only where they end.
        hound::Error::IoError(_) => refuse(
            file,
            "WAV",
            format!("truncated: its {} bytes end inside the header", bytes.len()),
            "copy or export the whole file again",
        ),
        e => wav(e.to_string()),
    })?;
    let spec = reader.spec();
    let ch = usize::from(spec.channels);
    if ch == 0 || ch > crate::formats::channel::MAX_CHANNELS {
        return Err(wav(format!(
            "{} channels; mono, stereo or up to 8 channels are read",
            spec.channels
        )));
    }
    if spec.sample_rate == 0 {
        return Err(wav("a sample rate of 0".into()));
    }
    let frames = reader.duration() as usize;
    if frames > MAX_SOUND_SAMPLES {
        return Err(ExperimentError::SoundTooLong {
            file: file.into(),
            rate: spec.sample_rate,
            limit: MAX_SOUND_SAMPLES,
        });
    }
    let mut v = Vec::with_capacity(frames * ch);
    // A data chunk cut short: the header declares more samples than the file holds.
    let truncated = |e: hound::Error, got: usize| truncated(file, e, got / ch, frames);
    let format = match (spec.sample_format, spec.bits_per_sample) {
        (SampleFormat::Float, 32) => {
            for s in reader.samples::<f32>() {
                let x = s.map_err(|e| truncated(e, v.len()))?;
                if !x.is_finite() {
                    return Err(wav("a sample is NaN or infinite".into()));
                }
                v.push(f64::from(x));
            }
            "WAV, 32-bit float".to_string()
        }
        (SampleFormat::Int, b @ 8..=32) => {
            let full = (1u64 << (b - 1)) as f64;
            for s in reader.samples::<i32>() {
                let x = s.map_err(|e| truncated(e, v.len()))?;
                v.push(f64::from(x) / full);
            }
            format!("WAV, {b}-bit integer PCM")
        }
        (f, b) => {
            return Err(wav(format!("{b}-bit {f:?} samples are not supported")));
        }
    };
    Ok((v, spec.sample_rate, ch, format))
}

/// How [`encode_wav`] stores samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WavCoding {
    /// 16-bit integer.
    Int16,
    /// 24-bit integer.
    Int24,
    /// 32-bit float.
    Float32,
}

/// Encodes a uniformly sampled signal (full scale 1, clipped there) as 16-bit mono WAV bytes.
pub fn wav_bytes(v: &[f64], sample_rate: u32) -> Result<Vec<u8>, hound::Error> {
    encode_wav(v, sample_rate, WavCoding::Int16)
}

/// Encodes a uniformly sampled signal (full scale 1, clipped there) as mono WAV bytes.
pub fn encode_wav(v: &[f64], sample_rate: u32, coding: WavCoding) -> Result<Vec<u8>, hound::Error> {
    encode_wav_channels(&[v], sample_rate, coding)
}

/// Encodes channels of equal length (full scale 1, clipped there) as one WAV's bytes, the
/// channels interleaved in the order given.
pub fn encode_wav_channels(
    channels: &[&[f64]],
    sample_rate: u32,
    coding: WavCoding,
) -> Result<Vec<u8>, hound::Error> {
    let (bits, sample_format) = match coding {
        WavCoding::Int16 => (16, SampleFormat::Int),
        WavCoding::Int24 => (24, SampleFormat::Int),
        WavCoding::Float32 => (32, SampleFormat::Float),
    };
    let n = channels.iter().map(|c| c.len()).min().unwrap_or(0);
    let spec = WavSpec {
        channels: channels.len() as u16,
        sample_rate,
        bits_per_sample: bits,
        sample_format,
    };
    let mut out = Cursor::new(Vec::with_capacity(4 * n * channels.len() + 64));
    {
        let mut w = WavWriter::new(&mut out, spec)?;
        for x in (0..n).flat_map(|j| channels.iter().map(move |c| c[j])) {
            let x = x.clamp(-1.0, 1.0);
            match coding {
                WavCoding::Int16 => w.write_sample((x * 32767.0).round() as i16)?,
                WavCoding::Int24 => w.write_sample((x * 8_388_607.0).round() as i32)?,
                WavCoding::Float32 => w.write_sample(x as f32)?,
            }
        }
        w.finalize()?;
    }
    Ok(out.into_inner())
}
