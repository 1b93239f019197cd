//! Whether a line the track holds rises as a settling disk's does.
//!
//! By eq 79, $\Omega = (C/(t_0 - t))^{1/(\beta+2)}$, a disk's rate rises over any stretch of its
//! spin: over a line held for $D$ seconds and ending $r$ seconds before $t_0$,
//! $$\frac{\Omega_{last}}{\Omega_{first}} = \left(1 + \frac{D}{r}\right)^{1/(\beta+2)}
//!   \ge \left(1 + \frac{D}{L}\right)^{1/(\beta_{max}+2)},$$
//! $L$ the recording's span (which holds the line and its end, $r \le L$) and $\beta_{max} = 8$
//! the top of the range of physical dissipation laws
//! ([`Plausibility::beta_range`](crate::fit::plausibility::Plausibility::beta_range)). A line
//! that rises by less, or by no more than three of its sigmas, holds still: the ring the disk's
//! shudder leaves after $t_0$, a mains line or one of its harmonics, a reverberation's tail. Such
//! a line is not followed while one that rises is heard, and a track that holds one is not
//! taken for the disk's while a track that rises is made.

/// The top of the range of $\beta$ a line's least rise is reckoned with (see the module's
/// documentation): the default range's.
pub use crate::fit::plausibility::BETA_MAX;

/// One end of a line: its middle time (s), pitch and the pitch's standard uncertainty (any one
/// unit of frequency).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineEnd {
    /// The frame's middle (s).
    pub t: f64,
    /// The pitch.
    pub f: f64,
    /// Its standard uncertainty.
    pub sigma: f64,
}

/// The least ratio of last over first pitch of a disk's line held for `held` seconds in a
/// recording of `span` seconds: $(1 + D/L)^{1/(\beta_{max}+2)}$.
pub fn least_rise(held: f64, span: f64) -> f64 {
    (1.0 + (held / span).max(0.0)).powf(1.0 / (BETA_MAX + 2.0))
}

/// Whether the line from `first` to `last` rises as a disk's does in a recording of `span`
/// seconds: by at least [`least_rise`] and by more than three of the two ends' sigmas.
pub fn rises(first: LineEnd, last: LineEnd, span: f64) -> bool {
    let rise = last.f - first.f;
    last.t > first.t
        && rise > 3.0 * first.sigma.hypot(last.sigma)
        && last.f >= least_rise(last.t - first.t, span) * first.f
}

/// Whether the line from `first` to `last` holds still in a recording of `span` seconds: its
/// pitch moves, up or down, by less than the least rise a disk's line makes over the time
/// between them ([`least_rise`], $\rho$), by more than three of the two ends' sigmas,
/// $$\left|\ln\frac{f_{last}}{f_{first}}\right| < \ln\rho - 3\,\frac{\sqrt{\sigma_{first}^2 + \sigma_{last}^2}}{f_{first}}.$$
/// A disk's line never does (it rises by at least $\rho$); frames whose pitch is uncertain by
/// more than a third of that rise cannot show it.
pub fn holds_still(first: LineEnd, last: LineEnd, span: f64) -> bool {
    let margin = 3.0 * first.sigma.hypot(last.sigma) / first.f;
    last.t > first.t
        && (last.f / first.f).ln().abs() < least_rise(last.t - first.t, span).ln() - margin
}

#[cfg(test)]
mod tests {
    use super::*;

    fn end(t: f64, f: f64, sigma: f64) -> LineEnd {
        LineEnd { t, f, sigma }
    }

    #[test]
    fn a_disks_line_rises_and_a_ring_or_a_mains_line_holds_still() {
        // Eq 79 at beta = 2 from 26.5 Hz over half a second, 0.6 s before t0, in 3.6 s.
        let law = |tau: f64| 26.5 * (1.1_f64 / tau).powf(0.25);
        assert!(rises(
            end(2.25, law(1.1), 0.01),
            end(2.75, law(0.6), 0.02),
            3.6
        ));
        // The shudder's ring: 1499.5 Hz to 1499.8 Hz (well beyond its sigmas) in 3.6 s.
        assert!(!rises(
            end(3.125, 1499.51, 0.02),
            end(3.375, 1499.78, 0.04),
            3.6
        ));
        // A mains line wandering by 0.1 Hz over the whole record.
        assert!(!rises(end(0.25, 60.0, 0.01), end(3.4, 60.1, 0.01), 3.6));
        // A disk's line within its sigmas, and one that falls.
        assert!(!rises(end(1.0, 20.0, 0.5), end(1.5, 21.0, 0.5), 3.6));
        assert!(!rises(end(1.0, 21.0, 0.01), end(1.5, 20.0, 0.01), 3.6));
    }

    #[test]
    fn the_first_five_seconds_of_a_minutes_spin_rise_enough() {
        // Eq 79 at beta = 3, t0 60 s after the first frame, in a record of 62 s: the slowest
        // rise of the phone set's spins, over its first 5 s.
        let law = |tau: f64| 4.0 * (60.0 / tau).powf(0.2);
        let (a, b) = (law(60.0), law(55.0));
        assert!(b / a > least_rise(5.0, 62.0), "{}", b / a);
        assert!(rises(end(0.0, a, 0.002), end(5.0, b, 0.002), 62.0));
    }

    /// Seed 40 of the phone set (1.2 s of sound from 24.6 Hz at 16 kS/s): after $t_0$ the
    /// shudder rings at 1500 Hz over more frames than the disk's line holds at the shortest
    /// search frames, and above the noise by as much. The track follows the disk's rising line,
    /// not the ring, and the short spin's intervals hold the truth.
    #[test]
    fn a_ring_after_t0_held_over_more_frames_than_the_disk_is_not_followed() {
        use crate::fit::plausibility::Plausibility;
        use crate::sound_analysis::analysis::analyze_sound;
        use crate::sound_analysis::track::TrackSettings;
        use crate::synthetic::phone_room::PhoneRoom;
        use std::f64::consts::TAU;
        let room = PhoneRoom::draw(40);
        let trace = room.record().unwrap().read_back("phone.wav").unwrap();
        let a = analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default())
            .expect("analysed");
        let t0 = room.t0();
        assert!(a.track.points.len() >= 2, "{a}");
        for p in &a.track.points {
            let m = 0.5 * (p.a + p.b);
            let truth = room.law.precession(t0 - m);
            assert!(p.b < t0, "a frame after t0: {p:?}");
            assert!(
                (p.omega / truth - 1.0).abs() < 0.02,
                "{p:?} against {}",
                truth / TAU
            );
        }
        let l = a.law();
        assert!((l.beta - room.law.beta).abs() <= 1.96 * l.beta_sigma, "{a}");
        assert!((l.t0 - t0).abs() <= 1.96 * l.t0_sigma, "{a}");
    }
}
