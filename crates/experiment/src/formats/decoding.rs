//! What the whole-file readers ([`recording`](crate::formats::recording),
//! [`wav`](crate::formats::wav)) and the reader in pieces ([`long`](crate::formats::long)) share
//! in decoding: `symphonia`'s packets decoded one after another, and the message for a WAV cut
//! short.

use crate::error::ExperimentError;
use crate::formats::channel::refuse;
use symphonia::core::audio::SampleBuffer;
use symphonia::core::codecs::{CodecParameters, Decoder, CODEC_TYPE_NULL};
use symphonia::core::errors::Error as DecodeError;
use symphonia::core::formats::{FormatOptions, FormatReader};
use symphonia::core::io::{MediaSource, MediaSourceStream};
use symphonia::core::meta::MetadataOptions;
use symphonia::core::probe::Hint;

/// What to do with a file `symphonia` cannot open or decode.
pub(crate) const UNDECODABLE_FIX: &str =
    "the file may be damaged or use a coding this tool does not decode: export it as WAV or FLAC";

/// A compressed recording `symphonia` cannot open or decode, refused naming its container.
pub(crate) fn undecodable(file: &str, container: &str, e: DecodeError) -> ExperimentError {
    refuse(
        file,
        container,
        format!("not decodable ({e})"),
        UNDECODABLE_FIX,
    )
}

/// A compressed recording's first audio track, opened: the container's reader, the track's id
/// and parameters, and what it is (the container and the coding's name).
pub(crate) struct AudioTrack {
    pub reader: Box<dyn FormatReader>,
    pub id: u32,
    pub params: CodecParameters,
    pub format: String,
}

/// Opens the first audio track of `source`, a `container` file named with extension `ext`, in
/// gapless mode (MP3's and Ogg's encoder samples left out by the decoder).
pub(crate) fn open_track(
    source: Box<dyn MediaSource>,
    file: &str,
    container: &str,
    ext: &str,
) -> Result<AudioTrack, ExperimentError> {
    let mss = MediaSourceStream::new(source, Default::default());
    let mut hint = Hint::new();
    hint.with_extension(ext);
    let options = FormatOptions {
        enable_gapless: true,
        ..FormatOptions::default()
    };
    let probed = symphonia::default::get_probe()
        .format(&hint, mss, &options, &MetadataOptions::default())
        .map_err(|e| undecodable(file, container, e))?;
    let reader = probed.format;
    let track = reader
        .tracks()
        .iter()
        .find(|t| t.codec_params.codec != CODEC_TYPE_NULL)
        .ok_or_else(|| refuse(file, container, "no audio track".into(), UNDECODABLE_FIX))?;
    let (id, params) = (track.id, track.codec_params.clone());
    let codec = symphonia::default::get_codecs()
        .get_codec(params.codec)
        .map_or("unknown coding", |d| d.long_name);
    Ok(AudioTrack {
        reader,
        id,
        params,
        format: format!("{container}, {codec}"),
    })
}

/// What [`each_packet`] hands each packet's samples to: the interleaved samples, the rate (S/s)
/// and the channel count.
pub(crate) type Samples<'a> = dyn FnMut(&[f32], u32, usize) -> Result<(), ExperimentError> + 'a;

/// Decodes track `id` of `reader` packet by packet to its end, handing `each` every packet's
/// interleaved samples with the sample rate and channel count its buffer states. A packet that
/// fails to decode is skipped (symphonia's decoders take up again at the next one); any other
/// error is `bad`'s.
pub(crate) fn each_packet(
    reader: &mut dyn FormatReader,
    decoder: &mut dyn Decoder,
    id: u32,
    bad: &dyn Fn(DecodeError) -> ExperimentError,
    each: &mut Samples<'_>,
) -> Result<(), ExperimentError> {
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
        let mut sb = SampleBuffer::<f32>::new(buf.capacity() as u64, spec);
        sb.copy_interleaved_ref(buf);
        each(sb.samples(), spec.rate, spec.channels.count())?;
    }
    Ok(())
}

/// A WAV's samples that fail to read after `got` of the `frames` samples per channel its header
/// declares: a file cut short (an I/O error, which bytes in memory give only where they end),
/// or the decoder's own complaint.
pub(crate) fn truncated(file: &str, e: hound::Error, got: usize, frames: usize) -> ExperimentError {
    match e {
        hound::Error::IoError(_) => refuse(
            file,
            "WAV",
            format!(
                "truncated: it ends after {got} of the {frames} samples per channel its header \
                 declares"
            ),
            "copy or export the whole file again",
        ),
        e => ExperimentError::Wav {
            file: file.into(),
            message: e.to_string(),
        },
    }
}
