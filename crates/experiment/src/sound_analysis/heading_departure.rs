//! Tests of a spin whose heading departs from eq 79 over the record: the law
//! $$\Omega = \left(\frac{C}{t_0 - t}\right)^{1/(\beta+2)} \quad (79),$$
//! integrated to the heading $\psi(t) = -C^{p}(t_0 - t)^{1-p}/(1 - p)$, $p = 1/(\beta + 2)$,
//! plus a slow oscillation $a \sin(2\pi (t - t_{lead})/T)$ that no $(\beta, t_0, C)$ takes out:
//! the phase's residuals then show structure (see
//! [`residual_structure`](crate::sound_analysis::residual_structure)), and the fit of the phase
//! seeded from the track's frames ([`short_spin`](crate::sound_analysis::short_spin)) is refused
//! for it, where the same spin without the oscillation stands.

#[cfg(test)]
mod tests {
    use crate::fit::plausibility::Plausibility;
    use crate::sound_analysis::analysis::analyze_sound;
    use crate::sound_analysis::short_spin::analysed;
    use crate::sound_analysis::track::TrackSettings;
    use crate::trace::{Trace, Truth};
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;
    use rand_distr::{Distribution, StandardNormal};
    use std::f64::consts::TAU;

    /// Samples per second of the recording.
    const RATE: f64 = 8000.0;

    /// $\beta = 2$, $t_0 = 2.5$ s, 20 Hz at $t_0 - 2$ s, silent before 0.8 s and after $t_0$, a
    /// fundamental of amplitude 0.3 with two harmonics, Gaussian noise of 0.1 (seeded), and the
    /// heading's oscillation of `amplitude` (rad) and period 0.8 s.
    fn recording(amplitude: f64) -> Trace {
        let (beta, t0, lead) = (2.0, 2.5, 0.8);
        let p = 1.0 / (beta + 2.0);
        let c = (TAU * 20.0_f64).powf(beta + 2.0) * 2.0;
        let psi = |t: f64| {
            -(c.powf(p) * (t0 - t).powf(1.0 - p)) / (1.0 - p)
                + amplitude * (TAU * (t - lead) / 0.8).sin()
        };
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let t: Vec<f64> = (0..((t0 + 1.0) * RATE) as usize)
            .map(|j| j as f64 / RATE)
            .collect();
        let v = t
            .iter()
            .map(|&t| {
                let g: f64 = StandardNormal.sample(&mut rng);
                let tone = if t < lead || t >= t0 {
                    0.0
                } else {
                    let h = psi(t);
                    0.3 * (h.sin() + 0.5 * (2.0 * h + 0.3).sin() + 0.25 * (3.0 * h + 0.7).sin())
                };
                tone + 0.1 * g
            })
            .collect();
        Trace {
            source: "departure.wav".into(),
            t,
            v,
            truth: Some(Truth {
                beta,
                t0,
                t_stop: t0,
                tau_rem: 0.0,
                c: Some(c),
                origin: "eq 79 with an oscillation of the heading".into(),
            }),
        }
    }

    /// The phase's fit seeded from the track's frames, as the analysis makes it where the track's
    /// own fit is refused.
    fn from_phase(
        amplitude: f64,
    ) -> (
        Trace,
        Result<crate::sound_analysis::analysed::SoundAnalysis, String>,
    ) {
        let trace = recording(amplitude);
        let checks = Plausibility::default();
        let track = analyze_sound(&trace, &TrackSettings::default(), &checks)
            .expect("the track's own fit stands")
            .track;
        let a = analysed(&trace, &track, &checks, "the track's fit refused");
        (trace, a)
    }

    #[test]
    fn a_heading_that_departs_from_eq_79_shows_structure_and_the_phase_is_refused() {
        let (_, a) = from_phase(0.1);
        let why = a.map(|a| a.to_string()).expect_err("refused");
        assert!(
            why.contains(
                "the phase's fit of the short spin is not the result: its residuals show structure"
            ) && why.contains("no drift of the law across the record is measured"),
            "{why}"
        );
        // The same spin on eq 79 alone stands, and its intervals hold the truth.
        let (trace, a) = from_phase(0.0);
        let a = a.expect("the phase of eq 79 alone stands");
        let (l, truth) = (a.law(), trace.truth.unwrap());
        assert!(l.from_phase, "{a}");
        assert!((l.beta - truth.beta).abs() <= 1.96 * l.beta_sigma, "{a}");
        assert!((l.t0 - truth.t0).abs() <= 1.96 * l.t0_sigma, "{a}");
    }
}
