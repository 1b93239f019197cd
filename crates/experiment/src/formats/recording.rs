//! A sound recording as a person has it: WAV (through `hound`, 8-32 bit integer or 32-bit float)
//! or a file a phone or an editor writes (FLAC, MP3, Ogg Vorbis, M4A/AAC, AIFF/AIFF-C, Core Audio
//! CAF, through the pure-Rust `symphonia` decoders), read into a [`Trace`] of full-scale units with what the file
//! is ([`RecordingInfo`]: format, rate, channels, length).
//!
//! The samples an encoder adds are left out: MP3's (its LAME header) and Ogg's by the decoder in
//! gapless mode, M4A's by the file's edit list ([`mp4_edit`](crate::formats::mp4_edit)). A raw
//! AAC stream (ADTS, a `.aac` file) records no encoder delay: the [`ADTS_PRIMING`] samples that
//! AAC-LC encoders put first (ffmpeg's, FAAC's) are left out, and the format says so.
//!
//! The container is recognised by its first bytes, not by the file's name. Every file goes
//! through [`read_bounded`] (size limit, regular files only); the decoded length is checked
//! against [`MAX_SOUND_SAMPLES`] per channel while decoding, so memory stays bounded. The channels are
//! averaged, or one is chosen ([`Channels`]). A recording over either limit is read again in
//! pieces and decimated to the band the analysis uses ([`long`](crate::formats::long)).

use crate::error::ExperimentError;
use crate::formats::channel::{mix, refuse, Channels, Recording};
pub use crate::formats::container::ADTS_PRIMING;
use crate::formats::container::{container, unread};
use crate::formats::decoding::{each_packet, open_track, undecodable, AudioTrack, UNDECODABLE_FIX};
use crate::formats::input::{read_bounded, MAX_BYTES, MAX_SOUND_SAMPLES};
use std::path::Path;
use symphonia::core::codecs::DecoderOptions;
use symphonia::core::errors::Error as DecodeError;

/// Reads a recording of any supported format.
pub fn read_recording(
    path: impl AsRef<Path>,
    channels: Channels,
) -> Result<Recording, ExperimentError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    let whole = read_bounded(path, MAX_BYTES).and_then(|b| parse_recording(b, &file, channels));
    match whole {
        Err(ExperimentError::SoundTooLong { .. } | ExperimentError::TooLarge { .. })
            if is_recording(path) =>
        {
            crate::formats::long::read_long(path, channels)
        }
        r => r,
    }
}

/// Whether the file at `path` is a sound recording by its first bytes (WAV, FLAC, Ogg, MP3,
/// M4A, raw AAC, AIFF or CAF), whatever its name; `false` when it cannot be read (the reader then says why).
pub fn is_recording(path: &Path) -> bool {
    use std::io::Read;
    let mut head = [0u8; 12];
    let n = std::fs::File::open(path)
        .and_then(|f| f.take(12).read(&mut head))
        .unwrap_or(0);
    container(&head[..n]).is_some()
}

/// Decodes a recording's bytes; `file` names them in errors.
pub fn parse_recording(
    bytes: Vec<u8>,
    file: &str,
    channels: Channels,
) -> Result<Recording, ExperimentError> {
    if let Some(what) = unread(&bytes) {
        return Err(refuse(
            file,
            what,
            "this tool has no Opus decoder".into(),
            "convert it to WAV or FLAC, for example `ffmpeg -i FILE.opus FILE.wav`, and analyse \
             the WAV",
        ));
    }
    let Some((format, ext)) = container(&bytes) else {
        return Err(refuse(
            file,
            "sound",
            format!(
                "its content is not a format this tool reads: the first bytes are {}",
                crate::formats::input::first_bytes(&bytes)
            ),
            &format!(
                "the formats read are {}: export the recording in one of them",
                crate::formats::input::FORMATS_READ
            ),
        ));
    };
    let (interleaved, rate, n_ch, format) = if ext == "wav" {
        crate::formats::wav::decode_wav(&bytes, file)?
    } else {
        decode_compressed(bytes, file, format, ext)?
    };
    mix(interleaved, rate, n_ch, format, file, channels)
}

/// Decodes FLAC, Ogg Vorbis, MP3, M4A/AAC, AIFF or CAF bytes to interleaved full-scale samples.
fn decode_compressed(
    bytes: Vec<u8>,
    file: &str,
    container: &str,
    ext: &str,
) -> Result<(Vec<f64>, u32, usize, String), ExperimentError> {
    let bad = |e: DecodeError| undecodable(file, container, e);
    let edit = if ext == "m4a" {
        crate::formats::mp4_edit::sound_edit(&bytes)
    } else {
        None
    };
    let AudioTrack {
        mut reader,
        id,
        params,
        format,
    } = open_track(Box::new(std::io::Cursor::new(bytes)), file, container, ext)?;
    let n_ch = params.channels.map_or(0, |c| c.count());
    if params
        .n_frames
        .is_some_and(|n| n > MAX_SOUND_SAMPLES as u64)
    {
        return Err(ExperimentError::SoundTooLong {
            file: file.into(),
            rate: params.sample_rate.unwrap_or(0),
            limit: MAX_SOUND_SAMPLES,
        });
    }
    let mut decoder = symphonia::default::get_codecs()
        .make(&params, &DecoderOptions::default())
        .map_err(bad)?;
    let mut out: Vec<f64> = Vec::new();
    let mut rate = params.sample_rate.unwrap_or(0);
    let mut channels = n_ch;
    each_packet(
        reader.as_mut(),
        decoder.as_mut(),
        id,
        &bad,
        &mut |x, r, c| {
            rate = r;
            channels = c;
            out.extend(x.iter().map(|&x| f64::from(x)));
            if out.len() > MAX_SOUND_SAMPLES * channels.max(1) {
                return Err(ExperimentError::SoundTooLong {
                    file: file.into(),
                    rate,
                    limit: MAX_SOUND_SAMPLES,
                });
            }
            Ok(())
        },
    )?;
    let format = match edit {
        Some(e) => {
            // The samples the edit list plays (the encoder's priming and padding left out).
            let ch = channels.max(1);
            let skip = ((e.start * f64::from(rate)).round() as usize * ch).min(out.len());
            out.drain(..skip);
            if let Some(d) = e.duration {
                out.truncate((d * f64::from(rate)).round() as usize * ch);
            }
            format!(
                "{format}, its edit list's {} priming samples left out",
                skip / ch
            )
        }
        None if ext == "aac" => {
            let ch = channels.max(1);
            let skip = (ADTS_PRIMING * ch).min(out.len());
            out.drain(..skip);
            format!(
                "{format}, {} encoder priming samples left out (a raw AAC stream does not record \
                 its encoder's delay: these are AAC-LC encoders' usual {ADTS_PRIMING})",
                skip / ch
            )
        }
        None => format,
    };
    if let Some(j) = out.iter().position(|x| !x.is_finite()) {
        return Err(refuse(
            file,
            &format,
            format!("sample {j} decodes to NaN or infinity"),
            UNDECODABLE_FIX,
        ));
    }
    Ok((out, rate, channels, format))
}
