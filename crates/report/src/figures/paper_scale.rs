//! The paper's figures at the paper's size. Each of its figures is printed 3.0 in wide; drawn
//! at that width with the fonts of a full-width figure, their labels would shrink to 3 pt. So
//! the paper-size versions are laid out on a small canvas ([`size`]: 360 x 270 px for a chart,
//! 480 x 360 for the geometry of figure 1) with the usual font sizes, and shown 3.0 in wide
//! beside a description, in our words, of what the paper's own figure shows: labels come out
//! at 6-8 pt, the size of the paper's.

use super::Figure;
use std::path::Path;

/// The paper's width of a figure, in inches (every `\includegraphics[width=3.0in]` of it).
pub const PAPER_WIDTH_IN: f64 = 3.0;

/// The paper's figures by our names, with their label in the paper's LaTeX and what the
/// paper's figure shows (its caption and the text that discusses it, described in our words): one
/// text file each, `templates/paper-figures/NAME.txt`, a paragraph whose line breaks are spaces.
macro_rules! paper_figures {
    ($(($name:literal, $label:literal)),* $(,)?) => {
        /// Every paper figure: `(our name, the paper's label, its description's file)`.
        pub const PAPER_FIGURES: &[(&str, &str, &str)] = &[$((
            $name,
            $label,
            include_str!(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../../templates/paper-figures/",
                $name,
                ".txt"
            )),
        )),*];
    };
}

paper_figures!(
    ("fig1", "fig1"),
    ("tek04", "tek04"),
    ("tek01", "tek01"),
    ("tek02", "tek02"),
    ("Omega", "Omega"),
    ("tek726", "tek726"),
    ("tek728", "tek728"),
    ("Odot", "Odot"),
);

/// The canvas a paper-size version is laid out on, in px (at scale 1).
pub fn size(name: &str) -> (u32, u32) {
    if name == "fig1" {
        (480, 360)
    } else {
        (360, 270)
    }
}

/// The paper's label and description of one of our figures, if it is one of the paper's.
pub fn paper_figure(name: &str) -> Option<(&'static str, String)> {
    PAPER_FIGURES
        .iter()
        .find(|(n, _, _)| *n == name)
        .map(|(_, label, says)| (*label, says.trim_end().replace('\n', " ")))
}

impl Figure {
    /// The paper-size version as SVG (laid out on [`size`]).
    pub fn paper_svg(&self) -> Result<String, super::FigureError> {
        let (w, h) = size(self.name);
        self.drawing.to_svg(w, h)
    }

    /// The paper-size version as a PNG at 360 dpi for its 3.0 in width.
    pub fn paper_png(&self, path: &Path) -> Result<(), super::FigureError> {
        let (w, h) = size(self.name);
        let scale = PAPER_WIDTH_IN * 360.0 / w as f64;
        self.drawing.to_png_sized(path, (w, h), scale)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_paper_figure_is_one_of_ours_in_the_papers_order() {
        let ours: Vec<&str> = PAPER_FIGURES.iter().map(|(n, _, _)| *n).collect();
        let in_report: Vec<&str> = super::super::names()
            .into_iter()
            .filter(|n| ours.contains(n))
            .collect();
        assert_eq!(ours, in_report);
        assert!(PAPER_FIGURES.iter().all(|(_, _, says)| says.len() > 40));
        assert_eq!(size("fig1"), (480, 360));
        assert!(paper_figure("stability-map").is_none());
    }

    /// Every file of `templates/paper-figures/` is a registered paper figure's description.
    #[test]
    fn every_description_file_is_registered() {
        let dir =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../templates/paper-figures");
        let mut files: Vec<String> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .filter_map(Result::ok)
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect();
        files.sort();
        let mut registered: Vec<String> = PAPER_FIGURES
            .iter()
            .map(|(n, _, _)| format!("{n}.txt"))
            .collect();
        registered.sort();
        assert_eq!(files, registered);
    }
}
