//! A synthetic sound written as a file people use: WAV (16-bit, 24-bit or 32-bit float, through
//! `hound`) or FLAC (16-bit, through the pure-Rust `flacenc` encoder), mono, at any rate.

use crate::error::ExperimentError;
use crate::formats::wav::{encode_wav, WavCoding};
use flacenc::component::BitRepr;
use flacenc::error::Verify;
use flacenc::source::{Fill, FrameBuf};

/// The coding of a written sound.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
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

impl SoundFormat {
    /// Every coding, in the order `--format` lists them.
    pub const ALL: [SoundFormat; 4] = [
        SoundFormat::Wav,
        SoundFormat::Wav24,
        SoundFormat::WavFloat,
        SoundFormat::Flac,
    ];

    /// The coding's name, as `--format` takes it.
    pub fn name(self) -> &'static str {
        match self {
            SoundFormat::Wav => "wav",
            SoundFormat::Wav24 => "wav24",
            SoundFormat::WavFloat => "wav-float",
            SoundFormat::Flac => "flac",
        }
    }

    /// The coding, in one line.
    pub fn summary(self) -> &'static str {
        match self {
            SoundFormat::Wav => "WAV, 16-bit integer",
            SoundFormat::Wav24 => "WAV, 24-bit integer",
            SoundFormat::WavFloat => "WAV, 32-bit float",
            SoundFormat::Flac => "FLAC, 16-bit",
        }
    }
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

/// Samples per FLAC block, at most.
const FLAC_BLOCK: usize = 4096;

/// Encodes a mono signal as 16-bit FLAC: whole blocks of $b$ samples, then the rest as one shorter
/// last block of its own length, and the stream information stating $b$ as both the least and the
/// greatest block (the last block is exempt), as a fixed-block stream must. $b$ is the largest
/// up to [`FLAC_BLOCK`] that leaves no rest or one of at least 32 samples (the encoder's least
/// block). The stream's MD5 is left unset (zero, as FLAC allows).
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
    if samples.len() < 32 {
        return Err(fail(format!(
            "{} samples: the encoder's blocks hold at least 32; write WAV",
            samples.len()
        )));
    }
    let n = samples.len();
    let block = (32..=FLAC_BLOCK.min(n))
        .rev()
        .find(|b| n.is_multiple_of(*b) || n % b >= 32)
        .unwrap_or(n);
    let whole = n / block * block;
    let source = flacenc::source::MemSource::from_samples(&samples[..whole], 1, 16, rate as usize);
    let mut stream = flacenc::encode_with_fixed_block_size(&config, source, block)
        .map_err(|e| fail(format!("{e:?}")))?;
    let rest = &samples[whole..];
    if !rest.is_empty() {
        let mut buf = FrameBuf::with_size(1, rest.len()).map_err(|e| fail(format!("{e:?}")))?;
        buf.fill_interleaved(rest)
            .map_err(|e| fail(format!("{e:?}")))?;
        let frame =
            flacenc::encode_fixed_size_frame(&config, &buf, whole / block, stream.stream_info())
                .map_err(|e| fail(format!("{e:?}")))?;
        stream.add_frame(frame);
        let info = stream.stream_info_mut();
        info.set_block_sizes(block, block)
            .map_err(|e| fail(format!("{e:?}")))?;
        info.set_total_samples(n);
    }
    stream.stream_info_mut().set_md5_digest(&[0; 16]);
    let mut sink = flacenc::bitsink::ByteSink::new();
    stream
        .write(&mut sink)
        .map_err(|e| fail(format!("{e:?}")))?;
    Ok(sink.as_slice().to_vec())
}

#[cfg(test)]
mod tests {
    use crate::formats::recording::parse_recording;
    use crate::Channels;

    /// FLAC of any length decodes to the samples written (16-bit rounding apart).
    #[test]
    fn flac_of_any_length_reads_back() {
        let e = super::flac_bytes(&[0.1; 10], 22_050)
            .unwrap_err()
            .to_string();
        assert!(e.contains("10 samples") && e.contains("WAV"), "{e}");
        for n in [
            40usize,
            4096,
            4096 * 3 + 5,
            4096 * 3 + 100,
            4099,
            220_500,
            480_000,
        ] {
            let v: Vec<f64> = (0..n).map(|j| 0.3 * (j as f64 * 0.05).sin()).collect();
            let bytes = super::flac_bytes(&v, 22_050).unwrap();
            let r = parse_recording(bytes, "x.flac", Channels::Mix).unwrap();
            assert_eq!(r.trace.v.len(), n, "{n}");
            let err = r
                .trace
                .v
                .iter()
                .zip(&v)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            assert!(err < 1.0 / 32767.0, "{n}: {err}");
        }
    }
}
