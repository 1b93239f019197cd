//! The edit list of an MP4 (M4A) file's sound track: which of its decoded samples the file
//! means to be heard.
//!
//! An AAC encoder starts with priming samples (1024 or 2112) and pads the last frame; the file
//! says which samples to play in the sound track's edit list (`moov/trak/edts/elst`: the first
//! entry's media time, in the track's time scale from `mdia/mdhd`, is where playing starts, and
//! its segment duration, in the movie's time scale from `moov/mvhd`, how long it plays). A
//! decoder that ignores it shifts every time by the priming, about 23 ms at 44.1 kHz, which moves
//! the fitted $t_0$ by as much. Only the box headers and these fields are read.

/// The first edit of the sound track: where playing starts and how long it lasts, in seconds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Edit {
    /// The decoded time at which playing starts (s).
    pub start: f64,
    /// How long it plays (s); `None` when the edit says "to the end".
    pub duration: Option<f64>,
}

/// The boxes in `data`: (type, body).
fn boxes(data: &[u8]) -> impl Iterator<Item = ([u8; 4], &[u8])> {
    let mut pos = 0usize;
    std::iter::from_fn(move || {
        let head = data.get(pos..pos + 8)?;
        let size32 = u32::from_be_bytes(head[..4].try_into().ok()?) as usize;
        let kind: [u8; 4] = head[4..8].try_into().ok()?;
        let (start, size) = match size32 {
            0 => (pos + 8, data.len() - pos),
            1 => {
                let large = data.get(pos + 8..pos + 16)?;
                (
                    pos + 16,
                    usize::try_from(u64::from_be_bytes(large.try_into().ok()?)).ok()?,
                )
            }
            s => (pos + 8, s),
        };
        let end = pos.checked_add(size)?;
        if end > data.len() || start > end {
            return None;
        }
        pos = end;
        Some((kind, &data[start..end]))
    })
}

/// The first box of type `kind` in `data`.
fn child<'a>(data: &'a [u8], kind: &[u8; 4]) -> Option<&'a [u8]> {
    boxes(data).find(|(k, _)| k == kind).map(|(_, b)| b)
}

/// A big-endian unsigned integer of `n` bytes at `at`.
fn uint(data: &[u8], at: usize, n: usize) -> Option<u64> {
    let b = data.get(at..at + n)?;
    Some(b.iter().fold(0u64, |a, &x| (a << 8) | u64::from(x)))
}

/// The time scale of an `mvhd` or `mdhd` body (units per second).
fn timescale(body: &[u8]) -> Option<u64> {
    let at = if body.first()? == &1 { 20 } else { 12 };
    uint(body, at, 4).filter(|&t| t > 0)
}

/// The first edit of the first sound track of the MP4 file `bytes`; `None` when the file has no
/// sound track with an edit list (or is not an MP4), or the edit starts with an empty span.
pub fn sound_edit(bytes: &[u8]) -> Option<Edit> {
    let moov = child(bytes, b"moov")?;
    let movie_scale = timescale(child(moov, b"mvhd")?)?;
    let trak = boxes(moov).filter(|(k, _)| k == b"trak").find(|(_, t)| {
        child(t, b"mdia")
            .and_then(|m| child(m, b"hdlr"))
            .and_then(|h| h.get(8..12))
            == Some(b"soun".as_slice())
    })?;
    let trak = trak.1;
    let media_scale = timescale(child(child(trak, b"mdia")?, b"mdhd")?)?;
    let elst = child(child(trak, b"edts")?, b"elst")?;
    let v1 = elst.first()? == &1;
    let count = uint(elst, 4, 4)?;
    if count == 0 {
        return None;
    }
    let (duration, media_time) = if v1 {
        (uint(elst, 8, 8)?, uint(elst, 16, 8)? as i64)
    } else {
        (
            uint(elst, 8, 4)?,
            i64::from(uint(elst, 12, 4)? as u32 as i32),
        )
    };
    if media_time < 0 {
        return None;
    }
    Some(Edit {
        start: media_time as f64 / media_scale as f64,
        duration: (duration > 0).then(|| duration as f64 / movie_scale as f64),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A box of type `kind` around `body`.
    fn mk(kind: &[u8; 4], body: &[u8]) -> Vec<u8> {
        let mut v = ((body.len() + 8) as u32).to_be_bytes().to_vec();
        v.extend_from_slice(kind);
        v.extend_from_slice(body);
        v
    }

    /// An `mvhd`/`mdhd` body of version 0 with `scale`.
    fn header(scale: u32) -> Vec<u8> {
        let mut b = vec![0u8; 12];
        b.extend_from_slice(&scale.to_be_bytes());
        b.extend_from_slice(&[0u8; 8]);
        b
    }

    #[test]
    fn the_sound_tracks_first_edit_is_read() {
        let mut elst = vec![0u8, 0, 0, 0, 0, 0, 0, 1];
        elst.extend_from_slice(&7000u32.to_be_bytes());
        elst.extend_from_slice(&1024u32.to_be_bytes());
        elst.extend_from_slice(&[0, 1, 0, 0]);
        let mut hdlr = vec![0u8; 8];
        hdlr.extend_from_slice(b"soun");
        let mdia = [mk(b"mdhd", &header(44_100)), mk(b"hdlr", &hdlr)].concat();
        let trak = [mk(b"edts", &mk(b"elst", &elst)), mk(b"mdia", &mdia)].concat();
        let moov = [mk(b"mvhd", &header(1000)), mk(b"trak", &trak)].concat();
        let file = [mk(b"ftyp", b"M4A \0\0\0\0"), mk(b"moov", &moov)].concat();
        let e = sound_edit(&file).unwrap();
        assert!((e.start - 1024.0 / 44_100.0).abs() < 1e-12, "{e:?}");
        assert_eq!(e.duration, Some(7.0));
        assert_eq!(sound_edit(b"not an mp4 at all"), None);
        assert_eq!(sound_edit(&file[..file.len() - 5]), None);
    }
}
