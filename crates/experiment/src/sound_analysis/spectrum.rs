//! One frame of a sound recording: its fundamental, with sub-bin precision and an uncertainty
//! (`rustfft`).
//!
//! **Transform.** The frame's $n$ samples (mean removed) are weighted by the Hann window
//! $w(t) = \sin^2(\pi t/T)$ and, in the same complex transform, by its derivative
//! $w'(t) = (\pi/T)\sin(2\pi t/T)$, zero-padded to at least $4n$ points. Both spectra come from
//! one FFT of $x\,(w + i\,w')$ by conjugate symmetry.
//!
//! **Which line.** The fundamental is the bin $k$ in the search band that maximises the harmonic
//! family's score
//! $$S(k) = \sum_{h=1}^{4} \max\!\left(0, \ln\frac{|X_w(hk)|^2}{N(hk)}\right)$$
//! over the harmonics below [`MAX_HARMONIC_HZ`], each harmonic's power over its own noise floor
//! $N(f)$ ([`noise_floor`]): at the true fundamental every harmonic of the disk counts, at half
//! of it only the even ones, at a multiple of it only some. Each harmonic is weighed against the
//! noise at its own frequency, not by its loudness: a phone's high-pass that leaves the
//! fundamental far below its third harmonic lowers the noise there as much, so the family, not
//! the loudest line, names the fundamental.
//!
//! **Hum masked where the line is searched for.** In a frame searched for the line (`masked`),
//! a harmonic $hk$ that lies within the window's main lobe ($\pm 2/T$) of a mains line the
//! analysis subtracted ([`Analyser::mask`]) is left out of the sum (the sum of the others
//! scaled by the harmonics' count over theirs) and of the estimate: what is left of the hum
//! there is not the disk's, and a fundamental whose every harmonic but one is on the hum is
//! no fundamental of the disk (a family is named by two lines at least: one line left clear
//! may be a mains line the hum's removal did not find, and scaled up it would outweigh the
//! disk's family). A frame that follows a line already held, searched within a narrow
//! band about its predicted pitch, is not masked: its short frames' lobes ($2/T$ grows as $T$
//! shrinks near $t_0$) would cover most of the band below a few hundred hertz, and leave the
//! disk's line read from its weakest harmonics or not at all.
//!
//! **Where on the line.** Each harmonic's peak bin $p$ is refined two ways:
//! - by **reassignment** (the estimate used): for a sinusoid of frequency $f_0$,
//!   $X_{w'}(f) = 2\pi i\,(f - f_0)X_w(f)$, so
//!   $$\hat f = f_p - \frac{1}{2\pi}\,\mathrm{Im}\frac{X_{w'}(f_p)}{X_w(f_p)};$$
//! - by a **parabola** through the log-magnitudes of bins $p-1, p, p+1$ (the cross-check).
//!
//! The harmonics' estimates $\hat f_h/h$ are combined with weights $h^2\rho_h$, where
//! $\rho_h = |X_w(p_h)|^2/P_n - 1$ is the harmonic's power over the noise's per bin $P_n$ (the
//! median power between the harmonics divided by $\ln 2$, the median of an exponential
//! variate over its mean).
//!
//! **Uncertainty from the noise.** For a sinusoid in white noise the Cramér-Rao bound of its
//! frequency over a frame of duration $T$ is, with the windowed peak-to-noise ratio $\rho$,
//! $\sigma_f^2 \approx 2/((2\pi T)^2\rho)$; the Hann window widens it by [`HANN_FACTOR`]
//! (measured: see `tests/experiment_audio.rs`). The harmonics give
//! $$\sigma_{f_1} = \frac{k_{Hann}\sqrt2}{2\pi T\sqrt{\sum_h h^2\rho_h}}.$$
//! Nothing here depends on the sample rate: $T$ and the band are in seconds and hertz.

use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::f64::consts::PI;
use std::sync::Arc;

/// Harmonics are used up to this frequency (Hz), so that recordings at 8 kHz and above see the
/// same harmonics.
pub const MAX_HARMONIC_HZ: f64 = 3500.0;

/// The Hann window's widening of the frequency's standard deviation over the rectangular
/// window's bound.
pub const HANN_FACTOR: f64 = 1.3;

/// A peak counts as a harmonic in the family's score only where its power exceeds this fraction
/// of the strongest power within 4 resolution cells of it: the Hann window's first sidelobe is
/// 31.5 dB (a power ratio of 7e-4) below its line, so a loud line's sidelobes are not taken for
/// lines of their own.
const SIDELOBE: f64 = 3e-3;

/// The fundamental found in one frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// The fundamental by reassignment (Hz).
    pub f: f64,
    /// Its standard uncertainty from the noise (Hz).
    pub sigma: f64,
    /// The fundamental by parabolic interpolation (Hz), the cross-check.
    pub check: f64,
    /// $\sum_h \rho_h$: the harmonics' power over the noise's per bin.
    pub snr: f64,
}

/// A frame analyser for one sample rate; it keeps its FFT plans.
pub struct Analyser {
    fs: f64,
    /// Mains lines (Hz) whose residue is masked.
    mask: Vec<f64>,
    planner: FftPlanner<f64>,
    plans: Vec<(usize, Arc<dyn Fft<f64>>)>,
}

impl Analyser {
    /// An analyser for samples at `fs` S/s.
    pub fn new(fs: f64) -> Self {
        Self {
            fs,
            mask: Vec::new(),
            planner: FftPlanner::new(),
            plans: Vec::new(),
        }
    }

    /// Masks the mains lines `lines` (Hz) in every frame analysed after (see the module's
    /// documentation).
    pub fn mask(&mut self, lines: &[f64]) {
        self.mask = lines.to_vec();
    }

    /// Whether frequency `f` (Hz) lies within `width` (Hz) of a masked line.
    fn masked(&self, f: f64, width: f64) -> bool {
        self.mask.iter().any(|m| (f - m).abs() < width)
    }

    fn plan(&mut self, n: usize) -> Arc<dyn Fft<f64>> {
        if let Some((_, p)) = self.plans.iter().find(|(m, _)| *m == n) {
            return p.clone();
        }
        let p = self.planner.plan_fft_forward(n);
        self.plans.push((n, p.clone()));
        p
    }

    /// The fundamental of frame `x` searched between `lo` and `hi` Hz, with the mains lines
    /// masked when `masked` (see the module's documentation); `None` when no harmonic stands
    /// `min_snr` times above the noise.
    pub fn fundamental(
        &mut self,
        x: &[f64],
        (lo, hi): (f64, f64),
        min_snr: f64,
        masked: bool,
    ) -> Option<Estimate> {
        let n = x.len();
        if n < 16 {
            return None;
        }
        let nfft = (4 * n).next_power_of_two();
        let (fs, nf) = (self.fs, nfft as f64);
        let bin = fs / nf;
        let mean = x.iter().sum::<f64>() / n as f64;
        let dw = PI * fs / n as f64;
        let mut buf: Vec<Complex<f64>> = x
            .iter()
            .enumerate()
            .map(|(j, v)| {
                let u = PI * (j as f64 + 0.5) / n as f64;
                let d = v - mean;
                Complex::new(d * u.sin().powi(2), d * dw * (2.0 * u).sin())
            })
            .collect();
        buf.resize(nfft, Complex::new(0.0, 0.0));
        self.plan(nfft).process(&mut buf);
        let half = nfft / 2;
        // X_w(k) = (Z(k) + conj Z(N-k))/2, X_w'(k) = (Z(k) - conj Z(N-k))/(2i).
        let split = |k: usize| -> (Complex<f64>, Complex<f64>) {
            let (z, c) = (buf[k], buf[(nfft - k) % nfft].conj());
            ((z + c) * 0.5, (z - c) * Complex::new(0.0, -0.5))
        };
        let top = (MAX_HARMONIC_HZ.min(0.45 * fs) / bin) as usize;
        let power: Vec<f64> = (0..=half.min(top + 3))
            .map(|k| split(k).0.norm_sqr())
            .collect();
        let k_lo = ((lo / bin).floor() as usize).max(2);
        let k_hi = ((hi / bin).ceil() as usize).min(top.saturating_sub(2));
        let cells = nfft / n;
        let floor = noise_floor(&power, cells);
        let reach = (cells / 2).max(2);
        let over = |k: usize| {
            let span = k.saturating_sub(reach)..=(k + reach).min(power.len() - 1);
            let p = span
                .clone()
                .max_by(|a, b| power[*a].total_cmp(&power[*b]))
                .unwrap_or(k);
            let near = p.saturating_sub(4 * cells)..=(p + 4 * cells).min(power.len() - 1);
            let lead = near.map(|j| power[j]).fold(0.0, f64::max);
            if p == *span.start() || p == *span.end() || power[p] < SIDELOBE * lead {
                return 0.0;
            }
            (power[p] / floor[p]).max(1.0).ln()
        };
        let lobe = 2.0 * fs / n as f64;
        let clear = |k: usize| !masked || !self.masked(k as f64 * bin, lobe);
        let k0 = (k_lo..=k_hi)
            .map(|k| {
                let (s, terms, used) = (1..=4).filter(|h| h * k + 2 < power.len()).fold(
                    (0.0, 0, 0),
                    |(s, terms, used), h| {
                        if clear(h * k) {
                            (s + over(h * k), terms + 1, used + 1)
                        } else {
                            (s, terms + 1, used)
                        }
                    },
                );
                let s = if used == terms || used >= 2 {
                    s * terms as f64 / used.max(1) as f64
                } else {
                    0.0
                };
                (k, s)
            })
            .max_by(|a, b| a.1.total_cmp(&b.1))?
            .0;
        let noise = self.noise(&power, k0, n, bin)?;
        let (mut num, mut num_check, mut den, mut snr, mut best) = (0.0, 0.0, 0.0, 0.0, 0.0f64);
        for h in 1..=4usize {
            let c = h * k0;
            if c + 3 >= power.len() {
                break;
            }
            if !clear(c) {
                continue;
            }
            let p = (c.saturating_sub(2).max(1)..=c + 2)
                .max_by(|a, b| power[*a].total_cmp(&power[*b]))?;
            let rho = power[p] / noise - 1.0;
            best = best.max(rho);
            if rho < min_snr {
                continue;
            }
            let (xw, xd) = split(p);
            let f_re = p as f64 * bin - (xd / xw).im / (2.0 * PI);
            let ln = |k: usize| power[k].max(f64::MIN_POSITIVE).ln();
            let f_par = (p as f64 + vertex(ln(p - 1), ln(p), ln(p + 1))) * bin;
            let u = (h * h) as f64 * rho;
            num += u * f_re / h as f64;
            num_check += u * f_par / h as f64;
            den += u;
            snr += rho;
        }
        if best < min_snr || den <= 0.0 {
            return None;
        }
        let t = n as f64 / fs;
        Some(Estimate {
            f: num / den,
            sigma: HANN_FACTOR * 2f64.sqrt() / (2.0 * PI * t * den.sqrt()),
            check: num_check / den,
            snr,
        })
    }
}

impl Analyser {
    /// The noise's power per bin about a fundamental at bin `k0` of a frame of `n` samples: the
    /// median power over $[f/2, 6f]$ outside $\pm 2/T$ of the harmonics, divided by $\ln 2$
    /// (an exponential variate's median over its mean); where fewer than 8 such bins are left
    /// (a low pitch in a short frame), the lowest quartile of the whole band divided by
    /// $\ln(4/3)$.
    fn noise(&self, power: &[f64], k0: usize, n: usize, bin: f64) -> Option<f64> {
        let f = k0 as f64 * bin;
        let guard = 2.0 * self.fs / n as f64;
        let last = power.len() - 1;
        let band = (0.5 * f / bin) as usize..=((6.0 * f / bin) as usize).min(last);
        let local: Vec<f64> = band
            .clone()
            .filter(|&k| {
                let g = k as f64 * bin;
                (1..=7).all(|h| (g - h as f64 * f).abs() > guard)
            })
            .map(|k| power[k])
            .collect();
        let m = if local.len() >= 8 {
            median(local)? / std::f64::consts::LN_2
        } else {
            let mut all: Vec<f64> = band.map(|k| power[k]).collect();
            if all.is_empty() {
                return None;
            }
            let q = all.len() / 4;
            *all.select_nth_unstable_by(q, f64::total_cmp).1 / (4.0f64 / 3.0).ln()
        };
        Some(m.max(f64::MIN_POSITIVE))
    }
}

/// The noise's power per bin at each bin of `power` (a frame's spectrum with `cells` bins per
/// resolution cell $1/T$): the lowest quartile of the bins about it divided by $\ln(4/3)$ (an
/// exponential variate's lower quartile over its mean), over spans of at least 8 resolution
/// cells and an eighth of their frequency, so that the lines in a span, each $4/T$ wide, leave
/// most of its bins to the noise.
pub fn noise_floor(power: &[f64], cells: usize) -> Vec<f64> {
    let mut floor = vec![f64::MIN_POSITIVE; power.len()];
    let mut start = 0;
    while start < power.len() {
        let width = (8 * cells.max(1)).max(start / 8);
        let end = (start + width).min(power.len());
        let mut span = power[start..end].to_vec();
        let q = span.len() / 4;
        let level = *span.select_nth_unstable_by(q, f64::total_cmp).1 / (4.0f64 / 3.0).ln();
        floor[start..end].fill(level.max(f64::MIN_POSITIVE));
        start = end;
    }
    floor
}

/// The parabola's vertex offset through three values around a local maximum.
fn vertex(l: f64, c: f64, r: f64) -> f64 {
    let d = l - 2.0 * c + r;
    if d < 0.0 {
        (0.5 * (l - r) / d).clamp(-0.5, 0.5)
    } else {
        0.0
    }
}

/// The median of `v` (`None` when empty).
fn median(mut v: Vec<f64>) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    let m = v.len() / 2;
    Some(*v.select_nth_unstable_by(m, f64::total_cmp).1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    /// A disk's line at 20 Hz (harmonics at 20, 40, 60 and 80 Hz) under the residue of 50 Hz
    /// mains hum with its harmonics, each fifty times louder: unmasked, the hum's family wins the
    /// family's score; with the mains lines masked, the disk's fundamental is found.
    #[test]
    fn a_masked_mains_line_is_not_taken_for_the_fundamental() {
        use rand::SeedableRng;
        use rand_distr::{Distribution, StandardNormal};
        let (fs, n) = (4000.0, 2000);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let x: Vec<f64> = (0..n)
            .map(|j| {
                let t = j as f64 / fs;
                let disk: f64 = (1..=4)
                    .map(|h| 0.02 * (TAU * 20.0 * f64::from(h) * t + 0.4 * f64::from(h)).sin())
                    .sum();
                let noise: f64 = StandardNormal.sample(&mut rng);
                let hum: f64 = (1..=4)
                    .map(|h| (TAU * 50.0 * f64::from(h) * t + 0.3 * f64::from(h)).sin())
                    .sum();
                disk + hum + 3e-4 * noise
            })
            .collect();
        let mut an = Analyser::new(fs);
        an.mask(&[50.0, 100.0, 150.0, 200.0]);
        let open = an.fundamental(&x, (5.0, 200.0), 30.0, false).unwrap();
        assert!((open.f - 20.0).abs() > 1.0, "unmasked: {} Hz", open.f);
        let masked = an.fundamental(&x, (5.0, 200.0), 30.0, true).unwrap();
        assert!((masked.f - 20.0).abs() < 0.05, "masked: {} Hz", masked.f);
    }

    /// A disk's family at 10 Hz (six equal lines) in white noise, both through a phone's
    /// high-pass at 160 Hz: the fundamental comes out 36 times weaker than its sixth harmonic
    /// (loudness would name 20 or 30 Hz), but each line stands as far over the noise at its own
    /// frequency, so the family names 10 Hz.
    #[test]
    fn behind_a_high_pass_the_family_names_the_fundamental() {
        use crate::synthetic::room_filters::high_pass;
        use rand::SeedableRng;
        use rand_distr::{Distribution, StandardNormal};
        let fs = 4000.0;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        let mut x: Vec<f64> = (0..6000)
            .map(|j| {
                let t = j as f64 / fs;
                let r: f64 = StandardNormal.sample(&mut rng);
                let disk: f64 = (1..=6)
                    .map(|h| (TAU * 10.0 * f64::from(h) * t + 0.9 * f64::from(h)).sin())
                    .sum();
                disk + 0.01 * r
            })
            .collect();
        high_pass(&mut x, 160.0, fs);
        let frame = &x[4000..6000];
        let mut an = Analyser::new(fs);
        let e = an.fundamental(frame, (5.0, 200.0), 30.0, true).unwrap();
        assert!(
            (e.f - 10.0).abs() < 0.05,
            "the family's fundamental: {} Hz",
            e.f
        );
    }
}
