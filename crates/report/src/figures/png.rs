//! The PNG encoder of the figures' bitmaps.

use super::error::{Drawn, FigureError};

/// Writes 8-bit RGB pixels as a PNG file, whole, through the files crate's door: deflate at its fast setting with the Paeth filter,
/// which suits flat colour and line art; the report's PNGs take the faster encoding over the
/// smaller file.
pub fn write(path: &std::path::Path, rgb: &[u8], (w, h): (u32, u32)) -> Result<(), FigureError> {
    let mut bytes = Vec::new();
    let mut encoder = ::png::Encoder::new(&mut bytes, w, h);
    encoder.set_color(::png::ColorType::Rgb);
    encoder.set_depth(::png::BitDepth::Eight);
    encoder.set_compression(::png::Compression::Fast);
    encoder.set_filter(::png::FilterType::Paeth);
    let mut writer = encoder.write_header().drawn()?;
    writer.write_image_data(rgb).drawn()?;
    writer.finish().drawn()?;
    files::output::write_set_file(path, &bytes).drawn()
}
