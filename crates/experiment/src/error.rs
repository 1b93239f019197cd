//! Everything that can go wrong in the experiment, as sentences that name the file, the line
//! and what to change. Nothing in this module panics on bad input: it returns one of these.

use thiserror::Error;

/// Why a trace could not be made, read or analysed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ExperimentError {
    /// The file could not be read or written.
    #[error("{file}: {message}")]
    Io {
        /// The file.
        file: String,
        /// What the system said.
        message: String,
    },
    /// The file holds no header line at all.
    #[error("{file}: the file is empty: a scope CSV needs a header line (time_s,signal_V) and data rows")]
    Empty {
        /// The file.
        file: String,
    },
    /// A header and no data.
    #[error("{file}:{line}: the header is the last line: there are no data rows to analyse")]
    HeaderOnly {
        /// The file.
        file: String,
        /// The header's line.
        line: usize,
    },
    /// A row (or the header) has fewer than two columns.
    #[error("{file}:{line}: {found} column(s) where two are needed (time in s, signal in V): a column is missing; separate the two columns by a comma, a tab or spaces")]
    MissingColumn {
        /// The file.
        file: String,
        /// The 1-based line.
        line: usize,
        /// How many cells the line has.
        found: usize,
    },
    /// A cell that is not a number.
    #[error("{file}:{line}:{col}: the {column} cell \"{cell}\" is not a number: write a plain decimal number (e.g. 0.0125 or 1.25e-2)")]
    NotANumber {
        /// The file.
        file: String,
        /// The 1-based line.
        line: usize,
        /// Which column ("time" or "signal").
        column: String,
        /// The 1-based column.
        col: usize,
        /// The cell as written.
        cell: String,
    },
    /// A number written with a decimal comma.
    #[error("{file}:{line}:{col}: the {column} cell \"{cell}\" has a decimal comma: write the file with a decimal point (replace each decimal ',' with '.'; a spreadsheet writes it when its language is English)")]
    DecimalComma {
        /// The file.
        file: String,
        /// The 1-based line.
        line: usize,
        /// Which column ("time" or "signal").
        column: String,
        /// The 1-based column.
        col: usize,
        /// The cell as written.
        cell: String,
    },
    /// NaN or infinity.
    #[error(
        "{file}:{line}:{col}: the {column} is {value} (NaN or infinite): remove or repair this row"
    )]
    NonFinite {
        /// The file.
        file: String,
        /// The 1-based line.
        line: usize,
        /// Which column.
        column: String,
        /// The 1-based column.
        col: usize,
        /// The value read.
        value: f64,
    },
    /// Time does not increase.
    #[error("{file}:{line}:1: the time {t} s does not increase from the previous row's {previous} s: samples must be in time order, each time once")]
    NotIncreasing {
        /// The file.
        file: String,
        /// The 1-based line.
        line: usize,
        /// Previous time.
        previous: f64,
        /// This time.
        t: f64,
    },
    /// The file is larger than the reader accepts.
    #[error("{file}: the file holds {bytes} bytes, more than the {limit} this tool reads: cut the recording to the spin-down's last seconds, or decimate it")]
    TooLarge {
        /// The file.
        file: String,
        /// Its size (bytes).
        bytes: u64,
        /// The limit (bytes).
        limit: u64,
    },
    /// More samples than the analysis accepts.
    #[error("{file}:{line}: more than {limit} samples: cut the recording to the spin-down's last seconds, or decimate it")]
    TooManySamples {
        /// The file.
        file: String,
        /// The line (CSV) or 0 (WAV) where the limit was passed.
        line: usize,
        /// The limit.
        limit: usize,
    },
    /// A sound recording longer than the analysis holds.
    #[error("{file}: more than {limit} samples per channel ({} s at {rate} S/s), the most a sound recording may hold: cut it to the spin-down's last {} s, for example `ffmpeg -sseof -{} -i {file} cut.wav`, and analyse cut.wav", limit / (*rate).max(1) as usize, keep_s(*limit, *rate), keep_s(*limit, *rate))]
    SoundTooLong {
        /// The file.
        file: String,
        /// Its sample rate (S/s).
        rate: u32,
        /// The limit (samples per channel).
        limit: usize,
    },
    /// A unit in a header this reader does not know.
    #[error("{file}:{line}:{column}: unknown unit \"{unit}\" in the header: write the time in s, ms or us and the signal in V or mV (or no unit)")]
    UnknownUnit {
        /// The file.
        file: String,
        /// The 1-based line.
        line: usize,
        /// The 1-based column.
        column: usize,
        /// The unit as written.
        unit: String,
    },
    /// The columns of a scope CSV cannot be chosen: several channels and none named, or a
    /// `--time`/`--signal` the file does not hold.
    #[error("{file}:{line}: {message}")]
    Columns {
        /// The file.
        file: String,
        /// The 1-based line of the header (or the first row).
        line: usize,
        /// What was found and what to give.
        message: String,
    },
    /// A WAV file that cannot be decoded.
    #[error("{file}: not a readable WAV file ({message}): save the recording as PCM or float WAV (8-32 bit, mono or stereo)")]
    Wav {
        /// The file.
        file: String,
        /// What the decoder said.
        message: String,
    },
    /// The work ran past the wall-time budget (`--max-seconds`).
    #[error(transparent)]
    OverBudget(#[from] physics::budget::OverBudget),
    /// A sound recording that can be read but not used, or not decoded.
    #[error("{file}: {format} recording: {message}: {fix}")]
    Audio {
        /// The file.
        file: String,
        /// What the file is (container and coding).
        format: String,
        /// What is wrong.
        message: String,
        /// What to change.
        fix: String,
    },
    /// The data are not a disk spinning down: the analysis refuses to report a fit.
    #[error("{file}: not a spin-down, no fit reported: {reason}")]
    Refused {
        /// The file.
        file: String,
        /// Why, with the numbers.
        reason: String,
    },
    /// The signal never varies above its noise.
    #[error("{file}: no pulse stands out of the noise: the signal varies by {span:.3e} V peak to peak, {} times its noise of {noise:.3e} V rms, and a pulse must span more than {min_span_sigmas} times it{}", ratio(*span, *noise), flat_or_noise(*span, *noise))]
    FlatSignal {
        /// The file.
        file: String,
        /// Peak-to-peak variation.
        span: f64,
        /// The estimated noise.
        noise: f64,
        /// The span a pulse must have, in noise deviations.
        min_span_sigmas: f64,
    },
    /// Too few peaks (or too few in the fitting window).
    #[error("{file}: {found} {what}, fewer than the {needed} needed to fit: {hint}")]
    TooFewPeaks {
        /// The file.
        file: String,
        /// What was counted.
        what: String,
        /// How many.
        found: usize,
        /// How many are needed.
        needed: usize,
        /// What to change.
        hint: String,
    },
    /// A setting that cannot be used.
    #[error("invalid setting: {0}")]
    Setting(String),
    /// The scene cannot make a synthetic spin-down.
    #[error("scene {scene}: {message}")]
    Scene {
        /// The scene's name.
        scene: String,
        /// What is wrong and what to change.
        message: String,
    },
    /// A fit did not converge.
    #[error("{file}: the fit of {what} did not converge: {message}")]
    Fit {
        /// The file.
        file: String,
        /// Which fit.
        what: String,
        /// Why.
        message: String,
    },
}

impl ExperimentError {
    /// The scene `name` cannot make a synthetic spin-down, for the reason `message`.
    pub fn in_scene(name: &str, message: String) -> Self {
        Self::Scene {
            scene: name.to_string(),
            message,
        }
    }
}

/// `span / noise` in words for a message, `-` when the noise is zero.
/// The seconds of a recording at `rate` S/s to keep under `limit` samples: the whole seconds
/// below the limit, less one for the cut's slack.
fn keep_s(limit: usize, rate: u32) -> usize {
    (limit / rate.max(1) as usize).saturating_sub(1).max(1)
}

fn ratio(span: f64, noise: f64) -> String {
    if noise > 0.0 {
        format!("{:.1}", span / noise)
    } else {
        "-".into()
    }
}

/// What a signal without pulses is: flat (no more than rounding) or noise alone.
fn flat_or_noise(span: f64, noise: f64) -> &'static str {
    if span <= 2.0 * noise || span == 0.0 {
        ": the signal is flat; check that the photodiode is connected and lit"
    } else {
        ": the record is noise alone; check the photodiode's gain and that the disk passes it"
    }
}
