//! The figures' one font, shipped with the crate and registered with plotters once.

use plotters::style::FontStyle;
use std::sync::Once;

static FONT: Once = Once::new();

/// The family the figures are drawn in: DejaVu Serif, shipped with the crate
/// (assets/fonts, with its licence) so that figures never depend on the fonts of the machine,
/// and chosen because the report's math font, TeX Gyre DejaVu Math, is drawn on it: the
/// symbols of a figure look like those of the equations beside it.
pub const FIGURE_FONT: &str = "DejaVu Serif";

/// The file of [`FIGURE_FONT`] (the HTML report embeds it for the SVG figures).
pub const FIGURE_FONT_FILE: &[u8] = include_bytes!("../../../../assets/fonts/DejaVuSerif.ttf");

/// Registers [`FIGURE_FONT`] with plotters, once, also under the generic names plotters' own
/// defaults ask for (a mesh's labels default to "sans-serif"), so that every text is in it.
pub fn register_font() {
    FONT.call_once(|| {
        for name in [FIGURE_FONT, "serif", "sans-serif"] {
            // The font is part of the crate; failing to parse it is a build defect caught by the
            // tests (every figure is drawn by them).
            let _ = plotters::style::register_font(name, FontStyle::Normal, FIGURE_FONT_FILE);
        }
    });
}
