//! A sound recording too long to be read whole (more than
//! [`MAX_SOUND_SAMPLES`](crate::formats::input::MAX_SOUND_SAMPLES) per channel, or a file over
//! [`MAX_BYTES`]), read in pieces: decoded a piece at a time (WAV frames through `hound`,
//! packets through `symphonia`), its channels mixed as the whole-file path mixes them (each
//! advanced by its delay, [`stereo`](crate::formats::stereo), from the same blocks), and
//! low-passed and decimated as it goes ([`decimate`](crate::formats::decimate)), so that what
//! is held is the one decimated channel: an hour at 48 kS/s is 28.8 million samples at 8 kS/s.
//!
//! The file is decoded two or three times: to count its frames where its header does not say
//! (every format but WAV), to keep the blocks the channels' delays are measured on (a mix of
//! several channels), and to mix and decimate. Recordings up to [`MAX_SOUND_SECONDS`] are read.

use crate::error::ExperimentError;
use crate::formats::channel::{
    check_shape, mix_used, refuse, refuse_cancelled, Channels, Recording, RecordingInfo,
    MAX_CHANNELS,
};
use crate::formats::container::{container, ADTS_PRIMING};
use crate::formats::decimate::{Decimator, BAND_HZ};
use crate::formats::decoding::{
    each_packet, open_track, truncated, undecodable, AudioTrack, UNDECODABLE_FIX,
};
use crate::formats::input::MAX_BYTES;
use crate::formats::stereo::{blocks_read, delays_of};
use crate::trace::Trace;
use hound::{SampleFormat, WavReader};
use std::collections::VecDeque;
use std::io::{BufReader, Read};
use std::path::Path;
use symphonia::core::codecs::DecoderOptions;
use symphonia::core::errors::Error as DecodeError;

/// The longest sound recording read (s): two hours.
pub const MAX_SOUND_SECONDS: usize = 7200;

/// Frames handed on at once while decoding a WAV.
const PIECE: usize = 1 << 14;

/// What a decoded file is.
struct Meta {
    rate: u32,
    n_ch: usize,
    format: String,
}

/// Hands on the interleaved samples of a file in pieces (each a whole number of frames).
type Each<'a> = dyn FnMut(&[f64], usize) -> Result<(), ExperimentError> + 'a;

/// Reads a long recording of any supported format in pieces, decimated to the band the
/// analysis uses.
pub fn read_long(path: &Path, channels: Channels) -> Result<Recording, ExperimentError> {
    let file = path.display().to_string();
    let mut head = [0u8; 64];
    let got = std::fs::File::open(path)
        .and_then(|f| f.take(64).read(&mut head))
        .map_err(|e| ExperimentError::Io {
            file: file.clone(),
            message: format!("cannot read it ({e})"),
        })?;
    let Some((container, ext)) = container(&head[..got]) else {
        return Err(refuse(
            &file,
            "sound",
            "its content is not a sound format this tool reads".into(),
            "export the recording as WAV or FLAC",
        ));
    };
    let decode = |each: &mut Each<'_>| {
        if ext == "wav" {
            decode_wav(path, &file, each, &mut None, false)
        } else {
            decode_packets(path, &file, container, ext, each)
        }
    };
    let (n, meta) = match ext {
        "wav" => wav_header(path, &file)?,
        _ => {
            let mut n = 0usize;
            let m = decode(&mut |x, ch| {
                n += x.len() / ch;
                Ok(())
            })?;
            (n, m)
        }
    };
    let (rate, n_ch) = (meta.rate, meta.n_ch);
    check_shape(rate, n_ch, n, &meta.format, &file)?;
    if n > MAX_SOUND_SECONDS * rate as usize {
        return Err(ExperimentError::SoundTooLong {
            file,
            rate,
            limit: MAX_SOUND_SECONDS * rate as usize,
        });
    }
    let delays = match channels {
        Channels::Mix if n_ch > 1 => channel_delays(n, &meta, &decode)?,
        _ => vec![0; n_ch],
    };
    if let Channels::One(k) = channels {
        if !(1..=n_ch).contains(&k) {
            return Err(refuse(
                &file,
                &meta.format,
                format!("channel {k} was asked for; the file has {n_ch}"),
                "choose a channel from 1 to the file's count, or mix them",
            ));
        }
    }
    let mut dec = Decimator::new(rate, n.div_ceil(crate::formats::decimate::factor(rate)))?;
    let q = dec.factor();
    let mut sums = vec![0.0; n_ch];
    let mut mixed_ss = 0.0;
    {
        let mut out = |x: f64| {
            mixed_ss += x * x;
            dec.push(x);
        };
        let mut mixer = Mixer::new(n, n_ch, &delays);
        decode(&mut |x, ch| {
            for frame in x.chunks_exact(ch) {
                for (s, v) in sums.iter_mut().zip(frame) {
                    *s += v * v;
                }
                match channels {
                    Channels::One(k) => out(frame[k - 1]),
                    _ if ch == 1 => out(frame[0]),
                    _ => mixer.frame(frame, &mut out),
                }
            }
            Ok(())
        })?;
        if matches!(channels, Channels::Mix) && n_ch > 1 {
            mixer.finish(&mut out);
        }
    }
    let used = match channels {
        Channels::One(k) => format!("channel {k} of {n_ch}"),
        Channels::Mix if n_ch == 1 => "mono".to_string(),
        Channels::Mix => {
            let levels: Vec<f64> = sums.iter().map(|s| (s / n.max(1) as f64).sqrt()).collect();
            refuse_cancelled(
                &levels,
                (mixed_ss / n.max(1) as f64).sqrt(),
                &meta.format,
                &file,
            )?;
            mix_used(n_ch, &delays, rate)
        }
    };
    let v = dec.finish()?;
    let out_rate = f64::from(rate) / q as f64;
    let used = if q > 1 {
        format!(
            "{used}; read in pieces, low-passed below {:.0} Hz and decimated {q}:1 to {out_rate} S/s (the band to {BAND_HZ:.0} Hz the analysis uses)",
            0.5 * out_rate
        )
    } else {
        format!("{used}; read in pieces")
    };
    Ok(Recording {
        trace: Trace {
            source: file,
            t: (0..v.len()).map(|j| j as f64 / out_rate).collect(),
            v,
            truth: None,
        },
        info: RecordingInfo {
            format: meta.format,
            sample_rate: rate,
            channels: n_ch,
            used,
            samples: n,
            seconds: n as f64 / f64::from(rate),
        },
    })
}

/// Each channel's delay behind the first, measured on the blocks [`blocks_read`] names, kept
/// from one decoding of the file.
fn channel_delays(
    n: usize,
    meta: &Meta,
    decode: &dyn Fn(&mut Each<'_>) -> Result<Meta, ExperimentError>,
) -> Result<Vec<isize>, ExperimentError> {
    let blocks = blocks_read(n, meta.rate);
    let mut kept: Vec<Vec<f64>> = blocks.iter().map(|_| Vec::new()).collect();
    let mut at = 0usize;
    decode(&mut |x, ch| {
        let frames = x.len() / ch;
        for (b, &(start, end)) in blocks.iter().enumerate() {
            let (from, to) = (start.max(at), end.min(at + frames));
            if from < to {
                kept[b].extend_from_slice(&x[(from - at) * ch..(to - at) * ch]);
            }
        }
        at += frames;
        Ok(())
    })?;
    let n_ch = meta.n_ch;
    let sample = |j: usize, c: usize| {
        let b = blocks.partition_point(|&(start, _)| start <= j) - 1;
        kept[b][(j - blocks[b].0) * n_ch + c]
    };
    Ok(delays_of(n, n_ch, meta.rate, &sample))
}

/// The channels' mean with each advanced by its delay, made frame by frame as
/// [`aligned_mean`](crate::formats::stereo::aligned_mean) makes it from the whole recording:
/// the frames a mixed sample needs are kept, and no others.
struct Mixer<'a> {
    n: usize,
    n_ch: usize,
    delays: &'a [isize],
    behind: usize,
    ahead: usize,
    frames: VecDeque<f64>,
    first: usize,
    next: usize,
}

impl<'a> Mixer<'a> {
    fn new(n: usize, n_ch: usize, delays: &'a [isize]) -> Self {
        let behind = delays
            .iter()
            .map(|d| (-d).max(0) as usize)
            .max()
            .unwrap_or(0);
        let ahead = delays
            .iter()
            .map(|d| (*d).max(0) as usize)
            .max()
            .unwrap_or(0);
        Self {
            n,
            n_ch,
            delays,
            behind,
            ahead,
            frames: VecDeque::new(),
            first: 0,
            next: 0,
        }
    }

    /// Takes the next frame and hands on every mixed sample it completes.
    fn frame(&mut self, x: &[f64], out: &mut dyn FnMut(f64)) {
        self.frames.extend(x);
        let last = self.first + self.frames.len() / self.n_ch - 1;
        while self.next < self.n && self.next + self.ahead <= last {
            self.emit(out);
        }
    }

    /// Hands on the mixed samples left once every frame has been taken.
    fn finish(&mut self, out: &mut dyn FnMut(f64)) {
        while self.next < self.n {
            self.emit(out);
        }
    }

    fn emit(&mut self, out: &mut dyn FnMut(f64)) {
        let j = self.next;
        let available = self.first + self.frames.len() / self.n_ch;
        let (s, k) = (0..self.n_ch).fold((0.0, 0usize), |(s, k), c| {
            let i = j as isize + self.delays[c];
            if (0..self.n.min(available) as isize).contains(&i) {
                let at = (i as usize - self.first) * self.n_ch + c;
                (s + self.frames[at], k + 1)
            } else {
                (s, k)
            }
        });
        out(s / k.max(1) as f64);
        self.next += 1;
        while self.first + self.behind < self.next && !self.frames.is_empty() {
            self.frames.drain(..self.n_ch);
            self.first += 1;
        }
    }
}

/// A WAV's frame count, rate, channels and coding, by its header.
fn wav_header(path: &Path, file: &str) -> Result<(usize, Meta), ExperimentError> {
    let mut frames = None;
    let meta = decode_wav(path, file, &mut |_, _| Ok(()), &mut frames, true)?;
    Ok((frames.unwrap_or(0), meta))
}

/// Decodes a WAV from its start, a piece at a time.
fn decode_wav(
    path: &Path,
    file: &str,
    each: &mut Each<'_>,
    declared: &mut Option<usize>,
    header_only: bool,
) -> Result<Meta, ExperimentError> {
    let wav = |message: String| ExperimentError::Wav {
        file: file.into(),
        message,
    };
    let f = std::fs::File::open(path).map_err(|e| ExperimentError::Io {
        file: file.into(),
        message: format!("cannot open it ({e})"),
    })?;
    let mut reader = WavReader::new(BufReader::new(f)).map_err(|e| wav(e.to_string()))?;
    let spec = reader.spec();
    let ch = usize::from(spec.channels);
    if ch == 0 || ch > MAX_CHANNELS || spec.sample_rate == 0 {
        return Err(wav(format!(
            "{} channels at {} S/s; mono, stereo or up to 8 channels are read",
            spec.channels, spec.sample_rate
        )));
    }
    let frames = reader.duration() as usize;
    let truncated = |e: hound::Error, got: usize| truncated(file, e, got / ch, frames);
    let mut buf = Vec::with_capacity(PIECE * ch);
    let mut got = 0usize;
    let format = match (spec.sample_format, spec.bits_per_sample) {
        (SampleFormat::Float, 32) => "WAV, 32-bit float".to_string(),
        (SampleFormat::Int, b @ 8..=32) => format!("WAV, {b}-bit integer PCM"),
        (f, b) => return Err(wav(format!("{b}-bit {f:?} samples are not supported"))),
    };
    *declared = Some(frames);
    let meta = Meta {
        rate: spec.sample_rate,
        n_ch: ch,
        format,
    };
    if header_only {
        return Ok(meta);
    }
    let full = (1u64 << (spec.bits_per_sample.clamp(1, 32) - 1)) as f64;
    let mut take = |x: f64, buf: &mut Vec<f64>, got: &mut usize| -> Result<(), ExperimentError> {
        buf.push(x);
        if buf.len() == PIECE * ch {
            *got += buf.len();
            each(buf, ch)?;
            buf.clear();
        }
        Ok(())
    };
    if spec.sample_format == SampleFormat::Float {
        for s in reader.samples::<f32>() {
            let x = s.map_err(|e| truncated(e, got + buf.len()))?;
            if !x.is_finite() {
                return Err(wav("a sample is NaN or infinite".into()));
            }
            take(f64::from(x), &mut buf, &mut got)?;
        }
    } else {
        for s in reader.samples::<i32>() {
            let x = s.map_err(|e| truncated(e, got + buf.len()))?;
            take(f64::from(x) / full, &mut buf, &mut got)?;
        }
    }
    let whole = buf.len() / ch * ch;
    if whole > 0 {
        each(&buf[..whole], ch)?;
    }
    Ok(meta)
}

/// Decodes FLAC, Ogg Vorbis, MP3, M4A/AAC, AIFF or CAF from its start, a packet at a time,
/// the encoder's priming left out as [`recording`](crate::formats::recording) leaves it out.
fn decode_packets(
    path: &Path,
    file: &str,
    container: &str,
    ext: &str,
    each: &mut Each<'_>,
) -> Result<Meta, ExperimentError> {
    let bad = |e: DecodeError| undecodable(file, container, e);
    let edit = if ext == "m4a" {
        crate::formats::input::read_bounded(path, MAX_BYTES)
            .ok()
            .and_then(|b| crate::formats::mp4_edit::sound_edit(&b))
    } else {
        None
    };
    let f = std::fs::File::open(path).map_err(|e| ExperimentError::Io {
        file: file.into(),
        message: format!("cannot open it ({e})"),
    })?;
    let AudioTrack {
        mut reader,
        id,
        params,
        mut format,
    } = open_track(Box::new(f), file, container, ext)?;
    let mut decoder = symphonia::default::get_codecs()
        .make(&params, &DecoderOptions::default())
        .map_err(bad)?;
    let mut rate = params.sample_rate.unwrap_or(0);
    let mut channels = params.channels.map_or(0, |c| c.count());
    let (skip, keep) = match &edit {
        Some(e) => (
            (e.start * f64::from(rate)).round() as usize,
            e.duration.map(|d| (d * f64::from(rate)).round() as usize),
        ),
        None if ext == "aac" => (ADTS_PRIMING, None),
        None => (0, None),
    };
    let (mut seen, mut kept) = (0usize, 0usize);
    each_packet(
        reader.as_mut(),
        decoder.as_mut(),
        id,
        &bad,
        &mut |s, r, c| {
            rate = r;
            channels = c.max(1);
            let x: Vec<f64> = s.iter().map(|&x| f64::from(x)).collect();
            if let Some(j) = x.iter().position(|x| !x.is_finite()) {
                return Err(refuse(
                    file,
                    &format,
                    format!("sample {} decodes to NaN or infinity", seen * channels + j),
                    UNDECODABLE_FIX,
                ));
            }
            let frames = x.len() / channels;
            let from = skip.saturating_sub(seen).min(frames);
            let to = keep.map_or(frames, |k| frames.min(from + k.saturating_sub(kept)));
            seen += frames;
            if from < to {
                kept += to - from;
                each(&x[from * channels..to * channels], channels)?;
            }
            Ok(())
        },
    )?;
    if edit.is_some() {
        format = format!("{format}, its edit list's {skip} priming samples left out");
    } else if ext == "aac" {
        format = format!(
            "{format}, {} encoder priming samples left out (a raw AAC stream does not record \
             its encoder's delay: these are AAC-LC encoders' usual {ADTS_PRIMING})",
            skip.min(seen)
        );
    }
    Ok(Meta {
        rate,
        n_ch: channels,
        format,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::formats::decimate::Decimator;
    use crate::formats::recording::parse_recording;
    use crate::formats::wav::{encode_wav_channels, WavCoding};

    /// Two microphones' noise-like sound, the second 29 samples later, with a tone.
    fn stereo(n: usize, rate: u32) -> [Vec<f64>; 2] {
        let mut state = 99u64;
        let sound: Vec<f64> = (0..n + 29)
            .map(|j| {
                state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
                let tone = (std::f64::consts::TAU * 440.0 * j as f64 / f64::from(rate)).sin();
                0.2 * (((state >> 33) as f64 / (1u64 << 31) as f64) - 0.5) + 0.3 * tone
            })
            .collect();
        [
            sound[29..].to_vec(),
            sound[..n].iter().map(|x| 0.8 * x).collect(),
        ]
    }

    /// The whole-file path's recording, decimated after it is read.
    fn whole_then_decimated(bytes: Vec<u8>, channels: Channels, rate: u32) -> (Vec<f64>, String) {
        let r = parse_recording(bytes, "x", channels).unwrap();
        let mut d = Decimator::new(rate, 0).unwrap();
        r.trace.v.iter().for_each(|&x| d.push(x));
        (d.finish().unwrap(), r.info.used)
    }

    /// A short file read in pieces gives what the whole-file path gives, decimated the same
    /// way: the same delay found, the same mixed samples, sample for sample, for the mix, one
    /// channel, 16-bit and float WAV and FLAC.
    #[test]
    fn reading_in_pieces_gives_the_whole_files_samples() {
        let dir = std::env::temp_dir().join(format!("rolling-disk-long-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let rate = 48_000u32;
        let [l, r] = stereo(3 * rate as usize + 123, rate);
        for coding in [WavCoding::Int16, WavCoding::Float32] {
            let bytes = encode_wav_channels(&[&l, &r], rate, coding).unwrap();
            let path = dir.join("two.wav");
            std::fs::write(&path, &bytes).unwrap();
            for channels in [Channels::Mix, Channels::One(2)] {
                let (want, used) = whole_then_decimated(bytes.clone(), channels, rate);
                let got = read_long(&path, channels).unwrap();
                assert_eq!(got.trace.v, want, "{coding:?} {channels:?}");
                assert!(
                    got.info.used.starts_with(&used),
                    "{} / {used}",
                    got.info.used
                );
                assert!(
                    got.info.used.contains("decimated 6:1 to 8000 S/s"),
                    "{}",
                    got.info.used
                );
                assert_eq!(got.trace.t[1], 1.0 / 8000.0);
                assert_eq!(got.info.samples, l.len());
            }
        }
        assert!(read_long(&dir.join("two.wav"), Channels::Mix)
            .unwrap()
            .info
            .used
            .contains("channel 2 advanced by 0.604 ms"));
        let flac = crate::formats::sound_file::flac_bytes(&l, 44_100).unwrap();
        let path = dir.join("one.flac");
        std::fs::write(&path, &flac).unwrap();
        let (want, _) = whole_then_decimated(flac, Channels::Mix, 44_100);
        let got = read_long(&path, Channels::Mix).unwrap();
        assert_eq!(got.trace.v, want);
        assert!(
            got.info.used.contains("decimated 5:1 to 8820 S/s"),
            "{}",
            got.info.used
        );
        std::fs::remove_dir_all(&dir).ok();
    }
}
