//! The figures' captions: one text template each, `templates/figures/NAME.txt.tera`, the prose
//! around the numbers its figure computes. A template may wrap its lines: a caption is one
//! paragraph, so each line break is read as a space.

use super::FigureError;
use serde::Serialize;

/// The caption templates compiled into the binary, by name: `(name, template)`.
macro_rules! caption_templates {
    ($($name:literal),* $(,)?) => {
        /// Every caption template, by name.
        pub const CAPTIONS: &[(&str, &str)] = &[$((
            $name,
            include_str!(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../../templates/figures/",
                $name,
                ".txt.tera"
            )),
        )),*];
    };
}

caption_templates!(
    "Odot",
    "Omega",
    "coverage",
    "energy-drift",
    "fig1",
    "frequency",
    "inverse-omega",
    "lab-frame-difference",
    "mechanisms",
    "omega_band",
    "path",
    "peer-difference",
    "peer-tilt",
    "premises",
    "residuals",
    "slip-stick",
    "slip-stick-path",
    "sound-spectrogram",
    "sound_track",
    "spin-down-alpha",
    "stability-map",
    "tek-zoom",
    "tek04",
    "work-precision",
);

/// The caption `name` rendered from `values` (its numbers, already written).
pub fn caption(name: &str, values: &impl Serialize) -> Result<String, FigureError> {
    let source = CAPTIONS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, s)| s.trim_end().replace('\n', " "))
        .ok_or_else(|| format!("the report has no caption template {name:?}"))?;
    crate::parts::prose::text(&format!("the caption of {name}"), &source, values)
        .map_err(|e| FigureError::Data(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::CAPTIONS;
    use std::path::Path;

    /// Every file of `templates/figures/` is a registered caption, with the same text.
    #[test]
    fn every_caption_file_is_registered() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../templates/figures");
        let mut files: Vec<(String, String)> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .filter_map(Result::ok)
            .map(|e| {
                let name = e.file_name().to_string_lossy().into_owned();
                let stem = name.strip_suffix(".txt.tera").unwrap_or(&name).to_string();
                (stem, std::fs::read_to_string(e.path()).unwrap_or_default())
            })
            .collect();
        files.sort();
        let mut registered: Vec<(String, String)> = CAPTIONS
            .iter()
            .map(|(n, t)| (n.to_string(), t.to_string()))
            .collect();
        registered.sort();
        assert_eq!(files, registered);
    }
}
