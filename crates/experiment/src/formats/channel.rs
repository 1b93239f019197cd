//! One channel of a recording at its rate: the limits every format is held to, the choice
//! of channel, and what the file was. Every decoder (WAV, compressed formats) ends here.

use crate::error::ExperimentError;
use crate::trace::Trace;
use serde::Serialize;

/// The lowest and highest sample rates read (S/s).
pub const RATES: (u32, u32) = (1000, 384_000);

/// The fewest samples per channel read.
pub const MIN_SAMPLES: usize = 16;

/// The most channels read.
pub const MAX_CHANNELS: usize = 8;

/// Which channel of a multi-channel recording is analysed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Channels {
    /// The channels' mean, each aligned in time with the first
    /// ([`stereo`](crate::formats::stereo)).
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
    /// The channel analysed ("mix of 2", "mix of 2, channel 2 advanced by 0.771 ms",
    /// "channel 1 of 2", "mono").
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

/// A mix this many times quieter (rms) than its loudest channel is the channels cancelling:
/// -60 dB, far below what two microphones of one room give (their sum is at most 6 dB down
/// where they are in phase and about 3 dB down where they are not).
const CANCELLED: f64 = 1e-3;

/// Refuses a mix of channels that cancel (one the other with its sign reversed): the mean of
/// such channels is silence, whatever the disk did.
fn refuse_cancelling(
    interleaved: &[f64],
    mix: &[f64],
    n_ch: usize,
    format: &str,
    file: &str,
) -> Result<(), ExperimentError> {
    let levels: Vec<f64> = (1..=n_ch)
        .map(|k| rms(&mut interleaved.chunks_exact(n_ch).map(|c| c[k - 1])))
        .collect();
    refuse_cancelled(&levels, rms(&mut mix.iter().copied()), format, file)
}

/// The root mean square of the values.
fn rms(x: &mut dyn Iterator<Item = f64>) -> f64 {
    let (sum, n) = x.fold((0.0, 0usize), |(s, n), v| (s + v * v, n + 1));
    (sum / n.max(1) as f64).sqrt()
}

/// Refuses a mix whose rms `mixed` is [`CANCELLED`] times below the loudest of the channels'
/// rms `levels`.
pub(crate) fn refuse_cancelled(
    levels: &[f64],
    mixed: f64,
    format: &str,
    file: &str,
) -> Result<(), ExperimentError> {
    let n_ch = levels.len();
    let (loudest, level) =
        levels.iter().enumerate().fold(
            (1, 0.0),
            |best, (k, &r)| {
                if r > best.1 {
                    (k + 1, r)
                } else {
                    best
                }
            },
        );
    if level > 0.0 && mixed < CANCELLED * level {
        let mean = if mixed > 0.0 {
            format!(
                "{:.0} dB below channel {loudest}",
                -20.0 * (mixed / level).log10()
            )
        } else {
            "silence".to_string()
        };
        return Err(refuse(
            file,
            format,
            format!(
                "its {n_ch} channels cancel when mixed (they are opposite in sign): \
                 their mean is {mean}"
            ),
            &format!("analyse one channel alone: --channel {loudest}"),
        ));
    }
    Ok(())
}

pub(crate) fn refuse(file: &str, format: &str, message: String, fix: &str) -> ExperimentError {
    ExperimentError::Audio {
        file: file.into(),
        format: format.into(),
        message,
        fix: fix.into(),
    }
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
    let samples = interleaved.len() / n_ch.max(1);
    check_shape(rate, n_ch, samples, &format, file)?;
    let (v, used): (Vec<f64>, String) = match channels {
        Channels::Mix if n_ch == 1 => (interleaved, "mono".into()),
        Channels::Mix => {
            let d = crate::formats::stereo::delays(&interleaved, n_ch, rate);
            let v = crate::formats::stereo::aligned_mean(&interleaved, n_ch, &d);
            refuse_cancelling(&interleaved, &v, n_ch, &format, file)?;
            let used = mix_used(n_ch, &d, rate);
            (v, used)
        }
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

/// Refuses a rate outside [`RATES`], a channel count outside 1 to [`MAX_CHANNELS`] and fewer
/// than [`MIN_SAMPLES`] samples per channel.
pub(crate) fn check_shape(
    rate: u32,
    n_ch: usize,
    samples: usize,
    format: &str,
    file: &str,
) -> Result<(), ExperimentError> {
    if !(RATES.0..=RATES.1).contains(&rate) {
        return Err(refuse(
            file,
            format,
            format!("a sample rate of {rate} S/s"),
            "record or export at a rate between 1000 and 384000 S/s (44100 or 48000 is usual)",
        ));
    }
    if n_ch == 0 || n_ch > MAX_CHANNELS {
        return Err(refuse(
            file,
            format,
            format!("{n_ch} channels"),
            "export the recording as mono or stereo",
        ));
    }
    if samples < MIN_SAMPLES {
        return Err(refuse(
            file,
            format,
            format!("it holds {samples} sample(s) per channel, fewer than {MIN_SAMPLES}"),
            "record the whole spin-down, from a few seconds before the disk settles until it is silent",
        ));
    }
    Ok(())
}

/// The words for a mix of `n_ch` channels advanced by `d` samples at `rate` S/s: "mix of 2" or
/// "mix of 2, channel 2 advanced by 0.771 ms".
pub(crate) fn mix_used(n_ch: usize, d: &[isize], rate: u32) -> String {
    let shifts: Vec<String> = d
        .iter()
        .enumerate()
        .filter(|(_, &s)| s != 0)
        .map(|(c, &s)| {
            format!(
                "channel {} {} {:.3} ms",
                c + 1,
                if s > 0 { "advanced by" } else { "delayed by" },
                1e3 * s.unsigned_abs() as f64 / f64::from(rate)
            )
        })
        .collect();
    if shifts.is_empty() {
        format!("mix of {n_ch}")
    } else {
        format!("mix of {n_ch}, {}", shifts.join(", "))
    }
}
