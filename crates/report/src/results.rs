//! The results layer: every study's result as plain data ([`Results`]), between the pipeline
//! that computes them (`crate::pipeline`) and the figures and renderers that only read them.

use crate::study::{Output, Study};
use std::collections::BTreeMap;
use std::fmt;

/// Every computed study's result, under the study's name.
#[derive(Clone, Default)]
pub struct Results {
    outputs: BTreeMap<&'static str, Output>,
    /// The paper the results were computed from (the figures that draw its printed curves read
    /// it: the stability map, the frequency figure).
    pub paper: Option<paper::Paper>,
    /// How many times each study was computed to make these results.
    pub computed: BTreeMap<&'static str, usize>,
}

impl Results {
    /// No study computed yet, for `paper`.
    pub fn of(paper: Option<paper::Paper>) -> Self {
        Self {
            paper,
            ..Self::default()
        }
    }

    /// The result of `study`, if it was computed.
    pub fn get<S: Study>(&self, _study: &S) -> Option<&S::Output> {
        self.outputs.get(S::NAME)?.downcast_ref()
    }

    /// The result of `study`, or the sentence saying that `reader` (the report, the figures)
    /// needs it and it was not computed.
    pub fn required<S: Study>(&self, study: &S, reader: &str) -> Result<&S::Output, String> {
        self.get(study).ok_or_else(|| {
            format!(
                "{reader} need the {} study, which was not computed",
                S::NAME
            )
        })
    }

    /// Keeps `output` as the result of the study `name`, counting the computation.
    pub(crate) fn insert(&mut self, name: &'static str, output: Output) {
        *self.computed.entry(name).or_insert(0) += 1;
        self.outputs.insert(name, output);
    }
}

impl fmt::Debug for Results {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Results")
            .field("studies", &self.outputs.keys().collect::<Vec<_>>())
            .field("computed", &self.computed)
            .finish_non_exhaustive()
    }
}
