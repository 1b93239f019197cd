//! A synthetic sound written as a file people use: WAV (16-bit, 24-bit or 32-bit float, through
//! `hound`) or FLAC (16-bit, through the pure-Rust `flacenc` encoder), mono, at any rate.

use crate::error::ExperimentError;
use crate::wav::{encode_wav, WavCoding};
use flacenc::component::BitRepr;
use flacenc::error::Verify;

/// The coding of a written sound.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum SoundFormat {
    /// WAV, 16-bit integer.
    Wav,
    /// WAV, 24-bit integer.
    Wav24,
    /// WAV, 32-bit float.
    WavFloat,
    /// FLAC, 16-bit.
    Flac,
}

/// Encodes a mono signal of full scale 1 (clipped there) at `rate` S/s.
pub fn encode_sound(v: &[f64], rate: u32, format: SoundFormat) -> Result<Vec<u8>, ExperimentError> {
    let coding = match format {
        SoundFormat::Wav => WavCoding::Int16,
        SoundFormat::Wav24 => WavCoding::Int24,
        SoundFormat::WavFloat => WavCoding::Float32,
        SoundFormat::Flac => return flac_bytes(v, rate),
    };
    encode_wav(v, rate, coding)
        .map_err(|e| ExperimentError::Setting(format!("the WAV cannot be encoded ({e})")))
}

/// Encodes a mono signal as 16-bit FLAC.
pub fn flac_bytes(v: &[f64], rate: u32) -> Result<Vec<u8>, ExperimentError> {
    let fail =
        |what: String| ExperimentError::Setting(format!("the FLAC cannot be encoded ({what})"));
    let samples: Vec<i32> = v
        .iter()
        .map(|x| (x.clamp(-1.0, 1.0) * 32767.0).round() as i32)
        .collect();
    let config = flacenc::config::Encoder::default()
        .into_verified()
        .map_err(|e| fail(format!("{e:?}")))?;
    let source = flacenc::source::MemSource::from_samples(&samples, 1, 16, rate as usize);
    let stream = flacenc::encode_with_fixed_block_size(&config, source, config.block_size)
        .map_err(|e| fail(format!("{e:?}")))?;
    let mut sink = flacenc::bitsink::ByteSink::new();
    stream
        .write(&mut sink)
        .map_err(|e| fail(format!("{e:?}")))?;
    Ok(sink.as_slice().to_vec())
}
