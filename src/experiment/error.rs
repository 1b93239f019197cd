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
    #[error("{file}:{line}: {found} column(s) where two are needed (time in s, signal in V): a column is missing")]
    MissingColumn {
        /// The file.
        file: String,
        /// The 1-based line.
        line: usize,
        /// How many cells the line has.
        found: usize,
    },
    /// A cell that is not a number.
    #[error("{file}:{line}: the {column} cell {cell:?} is not a number")]
    NotANumber {
        /// The file.
        file: String,
        /// The 1-based line.
        line: usize,
        /// Which column ("time" or "signal").
        column: String,
        /// The cell as written.
        cell: String,
    },
    /// NaN or infinity.
    #[error("{file}:{line}: the {column} is {value} (NaN or infinite): remove or repair this row")]
    NonFinite {
        /// The file.
        file: String,
        /// The 1-based line.
        line: usize,
        /// Which column.
        column: String,
        /// The value read.
        value: f64,
    },
    /// Time does not increase.
    #[error("{file}:{line}: the time {t} s does not increase from the previous row's {previous} s: samples must be in time order, each time once")]
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
    /// The signal never varies above its noise.
    #[error("{file}: the signal is flat (it varies by {span:.3e} V peak to peak, against a noise of {noise:.3e} V rms): there are no pulses to time")]
    FlatSignal {
        /// The file.
        file: String,
        /// Peak-to-peak variation.
        span: f64,
        /// The estimated noise.
        noise: f64,
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
