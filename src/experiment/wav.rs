//! Sound recordings as WAV files (`hound`): read (mono or stereo, 8-32 bit integer or 32-bit
//! float, any rate) into a [`Trace`] of full-scale units, and written (16-bit mono) by
//! `experiment simulate`.
//!
//! Reading goes through [`read_bounded`](crate::experiment::input::read_bounded) like every
//! file; the header's sample count is checked against [`MAX_SAMPLES`] before any sample is
//! decoded. Channels are averaged to one.

use crate::experiment::error::ExperimentError;
use crate::experiment::input::{read_bounded, MAX_BYTES, MAX_SAMPLES};
use crate::experiment::trace::Trace;
use hound::{SampleFormat, WavReader, WavSpec, WavWriter};
use std::io::Cursor;
use std::path::Path;

/// Reads a WAV file into a trace (time in s from the first sample, signal in full-scale units).
pub fn read_wav(path: impl AsRef<Path>) -> Result<Trace, ExperimentError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    let bytes = read_bounded(path, MAX_BYTES)?;
    parse_wav(&bytes, &file)
}

/// Decodes WAV bytes; `file` names them in errors.
pub fn parse_wav(bytes: &[u8], file: &str) -> Result<Trace, ExperimentError> {
    let wav = |message: String| ExperimentError::Wav {
        file: file.into(),
        message,
    };
    let mut reader = WavReader::new(Cursor::new(bytes)).map_err(|e| wav(e.to_string()))?;
    let spec = reader.spec();
    if spec.channels == 0 || spec.channels > 2 {
        return Err(wav(format!(
            "{} channels; mono or stereo is read",
            spec.channels
        )));
    }
    if spec.sample_rate == 0 {
        return Err(wav("a sample rate of 0".into()));
    }
    let frames = reader.duration() as usize;
    if frames > MAX_SAMPLES {
        return Err(ExperimentError::TooManySamples {
            file: file.into(),
            line: 0,
            limit: MAX_SAMPLES,
        });
    }
    if frames < 16 {
        return Err(ExperimentError::Empty { file: file.into() });
    }
    let ch = spec.channels as usize;
    let mut mono = Vec::with_capacity(frames);
    let mut acc = 0.0;
    let mut k = 0;
    let mut push = |x: f64| {
        acc += x;
        k += 1;
        if k == ch {
            mono.push(acc / ch as f64);
            acc = 0.0;
            k = 0;
        }
    };
    match (spec.sample_format, spec.bits_per_sample) {
        (SampleFormat::Float, 32) => {
            for s in reader.samples::<f32>() {
                let x = s.map_err(|e| wav(e.to_string()))?;
                if !x.is_finite() {
                    return Err(wav("a sample is NaN or infinite".into()));
                }
                push(f64::from(x));
            }
        }
        (SampleFormat::Int, b @ 8..=32) => {
            let full = (1u64 << (b - 1)) as f64;
            for s in reader.samples::<i32>() {
                push(f64::from(s.map_err(|e| wav(e.to_string()))?) / full);
            }
        }
        (f, b) => {
            return Err(wav(format!("{b}-bit {f:?} samples are not supported")));
        }
    }
    let rate = f64::from(spec.sample_rate);
    Ok(Trace {
        source: file.into(),
        t: (0..mono.len()).map(|j| j as f64 / rate).collect(),
        v: mono,
        truth: None,
    })
}

/// Encodes a uniformly sampled signal (full scale 1, clipped there) as 16-bit mono WAV bytes.
pub fn wav_bytes(v: &[f64], sample_rate: u32) -> Result<Vec<u8>, hound::Error> {
    let spec = WavSpec {
        channels: 1,
        sample_rate,
        bits_per_sample: 16,
        sample_format: SampleFormat::Int,
    };
    let mut out = Cursor::new(Vec::with_capacity(2 * v.len() + 64));
    {
        let mut w = WavWriter::new(&mut out, spec)?;
        for &x in v {
            let s = (x.clamp(-1.0, 1.0) * 32767.0).round() as i16;
            w.write_sample(s)?;
        }
        w.finalize()?;
    }
    Ok(out.into_inner())
}
