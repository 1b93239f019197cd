//! The real toy: the peer program's stored runs against this tool, and the toy's thickness
//! against the paper's thin-disk numbers (`studies::toy`). Nothing of it depends on the paper:
//! its stored runs, scenes and scans are part of the program, so its result is computed once
//! per build and kept in the cache ([`crate::cache`]).

use super::{Kept, Observer, Study};
use crate::cache::{decode, encode};
use crate::error::ReportError;
use checks::equations::Bench;
use studies::peer::stored::Differences;

/// The toy's studies.
pub struct Toy;

impl Study for Toy {
    type Output = studies::toy::Toy;
    const NAME: &'static str = "toy";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<studies::toy::Toy, ReportError> {
        Ok(studies::toy::compute()?)
    }

    fn kept(&self, _: &Bench) -> Option<Kept<studies::toy::Toy>> {
        Some(Kept {
            inputs: Vec::new(),
            encode: |t| encode(&(t, figure_series(t))),
            decode: |b| {
                let (mut t, series): (studies::toy::Toy, Vec<Series>) = decode(b)?;
                restore(&mut t, series)?;
                Ok(t)
            },
        })
    }
}

/// The series of one peer comparison's differences that `report.json` leaves out (they are for
/// the figures): its tilt gap and its tilts.
type Series = (Vec<(f64, f64)>, Vec<[f64; 3]>);

/// Every comparison's left-out series, the regularized run's then the sharp one's when there is
/// one, in the comparisons' order.
fn figure_series(t: &studies::toy::Toy) -> Vec<Series> {
    t.peer
        .iter()
        .flat_map(|p| std::iter::once(&p.regularized).chain(p.sharp.as_ref()))
        .map(|d| (d.tilt_gap.clone(), d.tilts.clone()))
        .collect()
}

/// Puts [`figure_series`]'s series back in their places.
fn restore(t: &mut studies::toy::Toy, series: Vec<Series>) -> Result<(), String> {
    let places: Vec<&mut Differences> = t
        .peer
        .iter_mut()
        .flat_map(|p| std::iter::once(&mut p.regularized).chain(p.sharp.as_mut()))
        .collect();
    if places.len() != series.len() {
        return Err(format!(
            "{} series for {} comparisons",
            series.len(),
            places.len()
        ));
    }
    for (d, (gap, tilts)) in places.into_iter().zip(series) {
        d.tilt_gap = gap;
        d.tilts = tilts;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_kept_toy_reads_back_equal_to_the_computed_one_in_every_field() {
        let t = studies::toy::compute().unwrap();
        let kept = Toy.kept(&Bench::default()).unwrap();
        let back = (kept.decode)(&(kept.encode)(&t).unwrap()).unwrap();
        // PartialEq compares every field, those report.json leaves out too, and the figures'
        // series are not empty: an encoding that lost them would fail here.
        assert!(t.peer.iter().any(|p| !p.regularized.tilts.is_empty()));
        assert_eq!(back, t);
        // To the bit, not only to ==: the JSON the report writes is the same text.
        assert_eq!(
            serde_json::to_string(&back).unwrap(),
            serde_json::to_string(&t).unwrap()
        );
    }
}
