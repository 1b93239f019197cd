//! A line the march holds still is not the disk's.
//!
//! A line whose frames, from the first that held it, move by less than any disk's line rises
//! over that time ([`still_line`], [`holds_still`]) is a mains line the hum's removal did not
//! find (a recording of a few seconds, its mains fundamental covered in every block by bumps, the
//! disk's sweep and the shudder) or the shudder's ring: followed, it would hold the search's
//! band where the disk's line is not, until a harmonic of the disk crossed it and was taken for
//! the line. Its frames are left off every line, its pitch is masked in the frames searched
//! over the whole band as the hum's lines are, and the line is searched for anew.

use super::rising::{holds_still, LineEnd};
use super::{one_line, Frame};

/// The line the last frames `held` hold: its first frame's index in `held` and its pitch,
/// where it holds still in a recording of `span` seconds ([`holds_still`] from its first frame
/// to its last, over three frames or more). The line is the frames at the end of `held` that
/// are one line ([`one_line`]), from where it was first held: a mains line the hum's removal
/// did not find, heard in the lead-in before the disk (followed, it would hold the search's
/// band where the disk's line is not, until a harmonic of the disk crossed it), or the
/// shudder's ring after $t_0$. A disk's line rises by more than
/// [`least_rise`](super::rising::least_rise) over any stretch, and over the whole of it since it was
/// first held, so a stretch of it held near a mains line it crosses is not taken for one; and
/// only frames that measure their pitch to a fraction of that rise can show a line still.
pub(super) fn still_line(held: &[Frame], span: f64) -> Option<(usize, f64)> {
    let n = held.len();
    let mut from = n.checked_sub(1)?;
    while from > 0 && one_line(&held[from - 1..=from]) {
        from -= 1;
    }
    if n - from < 3 || !one_line(&held[from..]) {
        return None;
    }
    let end = |fr: &Frame| {
        fr.est.map(|e| LineEnd {
            t: 0.5 * (fr.a + fr.b),
            f: e.f,
            sigma: e.sigma,
        })
    };
    let (first, last) = (end(&held[from])?, end(&held[n - 1])?);
    holds_still(first, last, span).then_some((from, last.f))
}
