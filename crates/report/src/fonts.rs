//! The fonts the HTML report carries inside itself, so that its figures and equations look the
//! same on every machine and are set in one design: TeX Gyre DejaVu Math, the OpenType math font
//! drawn on DejaVu Serif, for the MathML of the equations, and DejaVu Serif for the figures'
//! SVG text (their PNGs are drawn with the same file, [`crate::figures::chart::FIGURE_FONT`]).
//! Without them a browser sets the equations in whatever math font the machine has (Latin
//! Modern here, Cambria or STIX elsewhere) beside figure labels in some other font. The body
//! text is left to the reader's sans-serif.

use std::sync::OnceLock;

/// The family name the report's CSS gives the embedded DejaVu Serif.
pub const FIGURE_FAMILY: &str = "Report DejaVu Serif";

/// The family name the report's CSS gives the embedded TeX Gyre DejaVu Math.
pub const MATH_FAMILY: &str = "Report DejaVu Math";

const MATH_FONT: &[u8] = include_bytes!("../../../assets/fonts/TeXGyreDejaVuMath.otf");

/// The `@font-face` rules of both fonts, the files inlined as base64 `data:` URLs (the report
/// fetches nothing), followed by the rules that use them: the figures' SVG text in DejaVu
/// Serif, every `<math>` in the math font.
pub fn css() -> &'static str {
    static CSS: OnceLock<String> = OnceLock::new();
    CSS.get_or_init(|| {
        use base64::Engine;
        let b64 = |bytes: &[u8]| base64::engine::general_purpose::STANDARD.encode(bytes);
        format!(
            "@font-face {{ font-family: \"{FIGURE_FAMILY}\"; src: url(data:font/ttf;base64,{}) format(\"truetype\"); }}\n\
             @font-face {{ font-family: \"{MATH_FAMILY}\"; src: url(data:font/otf;base64,{}) format(\"opentype\"); }}\n\
             figure svg text {{ font-family: \"{FIGURE_FAMILY}\", \"DejaVu Serif\", serif; }}\n\
             math {{ font-family: \"{MATH_FAMILY}\", math; }}\n",
            b64(crate::figures::chart::FIGURE_FONT_FILE),
            b64(MATH_FONT)
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_fonts_are_inlined_whole_and_used() {
        let css = css();
        use base64::Engine;
        let decoded: Vec<Vec<u8>> = css
            .split("base64,")
            .skip(1)
            .map(|s| {
                let data = &s[..s.find(')').unwrap()];
                base64::engine::general_purpose::STANDARD
                    .decode(data)
                    .unwrap()
            })
            .collect();
        assert_eq!(
            decoded,
            vec![
                crate::figures::chart::FIGURE_FONT_FILE.to_vec(),
                MATH_FONT.to_vec()
            ]
        );
        // The math font is a math font: it has the OpenType MATH table browsers lay MathML out by.
        assert!(MATH_FONT.windows(4).any(|w| w == b"MATH"));
        assert!(css.contains(&format!("math {{ font-family: \"{MATH_FAMILY}\"")));
        assert!(css.contains(&format!(
            "figure svg text {{ font-family: \"{FIGURE_FAMILY}\""
        )));
    }
}
