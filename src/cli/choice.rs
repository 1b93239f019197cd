//! Option values chosen from a library's own list of named variants (an accuracy preset, a sound
//! coding), so that the library crates need no command-line crate: each variant's name and help
//! come from the library, and the parser here turns them into clap's possible values.

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};

/// A value named on the command line: every variant, its name and a one-line help.
pub(crate) trait Named: Copy + Send + Sync + 'static {
    /// Every variant, in the order `--help` lists them.
    const ALL: &'static [Self];
    /// The name a user types.
    fn name(self) -> &'static str;
    /// What the variant is, in one line.
    fn help(self) -> &'static str;
}

/// The parser of a [`Named`] value: refuses any other name with clap's list of the valid ones.
pub(crate) fn parser<T: Named>() -> impl TypedValueParser<Value = T> {
    let values = T::ALL
        .iter()
        .map(|v| PossibleValue::new(v.name()).help(v.help()));
    PossibleValuesParser::new(values).try_map(|s: String| {
        T::ALL
            .iter()
            .copied()
            .find(|v| v.name() == s)
            .ok_or_else(|| format!("{s:?} is not one of the listed values"))
    })
}

impl Named for studies::precision::Accuracy {
    const ALL: &'static [Self] = &Self::ALL;
    fn name(self) -> &'static str {
        self.name()
    }
    fn help(self) -> &'static str {
        self.summary()
    }
}

impl Named for experiment::SoundFormat {
    const ALL: &'static [Self] = &Self::ALL;
    fn name(self) -> &'static str {
        self.name()
    }
    fn help(self) -> &'static str {
        self.summary()
    }
}
