//! The filters a room and a phone put between a disk and a recording: a phone's high-pass, a
//! room's reverberation and a phone's automatic gain control. Each acts on a sampled signal in
//! place and is deterministic.

use std::f64::consts::TAU;

/// A second-order Butterworth high-pass at `corner` Hz (the RBJ biquad, $Q = 1/\sqrt2$):
/// $$H(s) = \frac{s^2}{s^2 + \sqrt2\,\omega_c s + \omega_c^2},$$
/// bilinear-transformed at `rate` S/s. Below the corner a line of frequency $f$ is attenuated
/// about $(f/f_c)^2$: a phone's microphone passes little of a disk's lowest lines.
pub fn high_pass(x: &mut [f64], corner: f64, rate: f64) {
    let ([b0, b1, b2], [a1, a2]) = high_pass_coefficients(corner, rate);
    let (mut x1, mut x2, mut y1, mut y2) = (0.0, 0.0, 0.0, 0.0);
    for v in x.iter_mut() {
        let y = b0 * *v + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
        (x2, x1, y2, y1) = (x1, *v, y1, y);
        *v = y;
    }
}

/// The [`high_pass`]'s coefficients $(b_0, b_1, b_2)$ and $(a_1, a_2)$, normalised by $a_0$.
fn high_pass_coefficients(corner: f64, rate: f64) -> ([f64; 3], [f64; 2]) {
    let w0 = TAU * corner / rate;
    let alpha = w0.sin() / std::f64::consts::SQRT_2;
    let c = w0.cos();
    let a0 = 1.0 + alpha;
    (
        [(1.0 + c) / 2.0 / a0, -(1.0 + c) / a0, (1.0 + c) / 2.0 / a0],
        [-2.0 * c / a0, (1.0 - alpha) / a0],
    )
}

/// The [`high_pass`]'s amplitude response at `f` Hz, $|H(e^{i\omega})|$ with
/// $\omega = 2\pi f/\mathrm{rate}$: what it leaves of a steady line at $f$.
pub fn high_pass_gain(corner: f64, rate: f64, f: f64) -> f64 {
    let ([b0, b1, b2], [a1, a2]) = high_pass_coefficients(corner, rate);
    let w = TAU * f / rate;
    // The modulus of c0 + c1 e^{-iw} + c2 e^{-2iw}: the numerator, then the denominator.
    let mag = |c0: f64, c1: f64, c2: f64| {
        let re = c0 + c1 * w.cos() + c2 * (2.0 * w).cos();
        let im = -c1 * w.sin() - c2 * (2.0 * w).sin();
        re.hypot(im)
    };
    mag(b0, b1, b2) / mag(1.0, a1, a2)
}

/// Schroeder's reverberator: four parallel feedback combs (29.7, 37.1, 41.1 and 43.7 ms) and
/// two all-passes (5.0 and 1.7 ms, gain 0.7), each comb's gain $g = 10^{-3 d/T_{60}}$ so that
/// the tail falls 60 dB in `t60` s; `wet` of the reverberated signal is added to the dry.
pub fn reverb(x: &mut [f64], t60: f64, wet: f64, rate: f64) {
    if wet <= 0.0 || t60 <= 0.0 {
        return;
    }
    let delay = |s: f64| ((s * rate).round() as usize).max(1);
    let mut sum = vec![0.0; x.len()];
    for d in [0.0297, 0.0371, 0.0411, 0.0437] {
        let n = delay(d);
        let g = 10f64.powf(-3.0 * d / t60);
        let mut buf = vec![0.0; n];
        for (j, (s, &v)) in sum.iter_mut().zip(x.iter()).enumerate() {
            let k = j % n;
            let y = v + g * buf[k];
            buf[k] = y;
            *s += 0.25 * y;
        }
    }
    for d in [0.005, 0.0017] {
        let n = delay(d);
        let g = 0.7;
        // The canonical all-pass: w_n = u_n + g w_{n-D}, y_n = -g w_n + w_{n-D}.
        let mut buf = vec![0.0; n];
        for (j, s) in sum.iter_mut().enumerate() {
            let k = j % n;
            let w = *s + g * buf[k];
            let y = -g * w + buf[k];
            buf[k] = w;
            *s = y;
        }
    }
    for (v, s) in x.iter_mut().zip(&sum) {
        *v += wet * s;
    }
}

/// A phone's automatic gain control: a peak follower of $|x|$ (attack `attack` s, release
/// `release` s) and a gain $\min(g_{max}, L/\mathrm{env})$ that holds the peaks near the
/// target $L$, smoothed over the release, so the disk's rising level is flattened and a bump
/// ducks what follows it.
pub fn agc(x: &mut [f64], target: f64, max_gain: f64, (attack, release): (f64, f64), rate: f64) {
    let ka = 1.0 - (-1.0 / (attack * rate)).exp();
    let kr = 1.0 - (-1.0 / (release * rate)).exp();
    let mut env = target;
    let mut gain = 1.0;
    for v in x.iter_mut() {
        let a = v.abs();
        env += if a > env { ka } else { kr } * (a - env);
        let want = (target / env.max(1e-9)).min(max_gain);
        gain += kr * (want - gain);
        *v *= gain;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rms(x: &[f64]) -> f64 {
        (x.iter().map(|v| v * v).sum::<f64>() / x.len() as f64).sqrt()
    }

    fn sine(f: f64, rate: f64, n: usize) -> Vec<f64> {
        (0..n).map(|j| (TAU * f * j as f64 / rate).sin()).collect()
    }

    #[test]
    fn the_high_pass_attenuates_below_its_corner_as_the_square_of_the_ratio() {
        let rate = 8000.0;
        let mut low = sine(10.0, rate, 80_000);
        let mut high = sine(1000.0, rate, 80_000);
        high_pass(&mut low, 100.0, rate);
        high_pass(&mut high, 100.0, rate);
        let low = rms(&low[40_000..]) * 2f64.sqrt();
        let high = rms(&high[40_000..]) * 2f64.sqrt();
        assert!((low / 0.01 - 1.0).abs() < 0.02, "gain at f_c/10: {low}");
        assert!((high - 1.0).abs() < 0.01, "gain at 10 f_c: {high}");
    }

    #[test]
    fn the_high_pass_gain_is_what_the_filter_does_to_a_steady_line() {
        let rate = 8000.0;
        for f in [10.0, 70.0, 100.0, 1000.0] {
            let mut x = sine(f, rate, 80_000);
            high_pass(&mut x, 100.0, rate);
            let measured = rms(&x[40_000..]) * 2f64.sqrt();
            let gain = high_pass_gain(100.0, rate, f);
            assert!(
                (measured / gain - 1.0).abs() < 2e-3,
                "{f} Hz: {measured} {gain}"
            );
        }
        assert!((high_pass_gain(100.0, rate, 100.0) - 0.5f64.sqrt()).abs() < 1e-3);
    }

    #[test]
    fn the_reverb_tail_falls_sixty_db_in_t60() {
        let rate = 8000.0;
        let mut x = vec![0.0; 16_000];
        x[0] = 1.0;
        reverb(&mut x, 0.5, 1.0, rate);
        let window = |t: f64| rms(&x[(t * rate) as usize..((t + 0.1) * rate) as usize]);
        let fall = 20.0 * (window(0.1) / window(0.6)).log10();
        assert!((fall - 60.0).abs() < 8.0, "fall over T60: {fall} dB");
    }

    #[test]
    fn the_agc_brings_a_quiet_and_a_loud_tone_to_its_target() {
        let rate = 8000.0;
        for amp in [0.01, 0.5] {
            let mut x: Vec<f64> = sine(200.0, rate, 40_000).iter().map(|v| amp * v).collect();
            agc(&mut x, 0.2, 100.0, (0.001, 0.3), rate);
            let peak = x[30_000..].iter().fold(0.0f64, |m, v| m.max(v.abs()));
            assert!(
                (peak / 0.2 - 1.0).abs() < 0.1,
                "amplitude {amp}: peak {peak}"
            );
        }
    }
}
