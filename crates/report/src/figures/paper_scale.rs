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
/// paper's figure shows (its caption and the text that discusses it, described in our words).
pub const PAPER_FIGURES: [(&str, &str, &str); 8] = [
    (
        "fig1",
        "fig1",
        "A sketch of the disk of radius a on the plane with the triad used throughout: axis 1 \
         along the symmetry axis at angle α from the upward vertical z, axis 3 from the centre \
         to the contact point, axis 2 = 3 × 1 horizontal, r = 2 × z horizontal; ω₁ is the spin \
         about axis 1 and Ω the turning of the triad about the vertical; the contact point \
         moves on a circle of radius r whose axis passes at distance b from the centre of mass.",
    ),
    (
        "tek04",
        "tek04",
        "Ten seconds of a phototransistor's output, sampled at 5 kS/s, watching light reflected \
         from a spinning Tangent Toy Euler's Disk: one pulse per turn of the contact point.",
    ),
    (
        "tek01",
        "tek01",
        "The last quarter second of the same record: the pulses come faster and weaker until \
         the signal goes flat.",
    ),
    (
        "tek02",
        "tek02",
        "The last 0.06 s of the record; from it the paper judges that the motion ends (t₀) \
         between 7.26 and 7.28 s.",
    ),
    (
        "Omega",
        "Omega",
        "Ω against t, one point per cycle, from the peak times tᵢ as Ωᵢ = 2π/(tᵢ₊₁ − tᵢ), the \
         peak of a cycle taken midway between its half-height edges.",
    ),
    (
        "tek726",
        "tek726",
        "1/Ω against t₀ − t on logarithmic axes for t₀ = 7.26 s, with straight lines (drawn, \
         not fitted) of eq 84's slope for several β; the paper reads β = 2 as fitting the whole \
         sample and takes C^(−1/4) = 0.0055 s^(3/4) from this plot.",
    ),
    (
        "tek728",
        "tek728",
        "The same plot for t₀ = 7.28 s: the last cycles flatten towards a smaller apparent β \
         (about 0), which the paper finds inconsistent with its dΩ/dt plot.",
    ),
    (
        "Odot",
        "Odot",
        "dΩ/dt against Ω on logarithmic axes, with lines of eq 85's slope for several β; \
         the paper uses it to rule out the β = 0 that t₀ = 7.28 s would suggest.",
    ),
];

/// The canvas a paper-size version is laid out on, in px (at scale 1).
pub fn size(name: &str) -> (u32, u32) {
    if name == "fig1" {
        (480, 360)
    } else {
        (360, 270)
    }
}

/// The paper's label and description of one of our figures, if it is one of the paper's.
pub fn paper_figure(name: &str) -> Option<(&'static str, &'static str)> {
    PAPER_FIGURES
        .iter()
        .find(|(n, _, _)| *n == name)
        .map(|(_, label, says)| (*label, *says))
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
}
