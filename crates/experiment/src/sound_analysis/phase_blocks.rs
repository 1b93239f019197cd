//! The sound's phase, followed turn by turn: the same information as the light's one peak per
//! turn.
//!
//! The disk's sound is $p(t) = A\,g(t)\sum_h a_h \sin(h\psi(t) + \phi_h)$, $\psi$ the heading
//! ([`sound`](crate::synthetic::sound)), so the phase of its $h$-th harmonic is $h\psi + $ const. Given a
//! reference heading $\Phi(t)$ (eq 79 integrated, [`fit::phase`](crate::fit::eq84_85::phase)), the record is
//! cut into **blocks of a whole, even number $N \ge 2$ of reference turns** (as many as fit in
//! 0.1 s), from $\Phi_a$ to $\Phi_a + 2\pi N$, and each harmonic is demodulated with the samples
//! weighted by the heading they span, $d\Phi = \Omega\,dt$:
//! $$z_h = \sum_j \Omega(t_j)\,x_j\,e^{-ih\Phi(t_j)}\,\Delta t_j \approx
//!   \int_{\Phi_a}^{\Phi_a + 2\pi N} x\,e^{-ih\Phi}\,d\Phi,$$
//! $\Delta t_j$ the part of sample $j$'s interval $[t_j - \Delta t/2,\, t_j + \Delta t/2]$ that
//! lies within the block $[t_a, t_b]$: $\Delta t$ inside, less at the two ends, so that the sum
//! spans the $N$ turns to a fraction of a sample at any rate.
//! In the heading the sound is a sum of lines at whole numbers of cycles per turn, and the
//! transform of a window of $N$ whole turns vanishes at every whole offset, so the other
//! harmonics and the negative-frequency images leak nothing into $z_h$ however fast the pitch
//! rises. (A window cut at whole samples instead would be up to a sample short of the turns,
//! through which a harmonic leaks in proportion to $\Delta t/(t_b - t_a)$: behind a phone's
//! high-pass, where the fundamental is 40 dB below its harmonics, enough at 8 kS/s to lower the
//! fundamental's signal-to-noise by a tenth.) $\arg z_h = h(\psi - \Phi) + $ const, averaged
//! over the block, is referred to its weighted centroid time $\bar t$; as the reference converges to the heading
//! ([`phase_fit`](crate::sound_analysis::phase_fit)), $\psi - \Phi$ tends to a constant and the centroid's
//! approximation to exact.
//!
//! **Noise.** The same sums at the half-way lines $(h \pm \tfrac12)$ cycles per turn fall
//! between the harmonics ($N/2$ bins from each, a whole number, so again nothing leaks): they hold
//! only noise. Their mean power per unit $\sum_j w_j^2$ ($w_j = \Omega(t_j)$), pooled over the
//! block and its two neighbours on each side, gives the noise's power $\nu_h$ in $z_h$, and
//! $\mathrm{Var}(\arg z_h) = \nu_h / (2|z_h|^2)$ (high signal-to-noise).
//!
//! **Harmonics combined.** The heading's offset is read first from one line, the **base**
//! harmonic $b$: $u_b = \arg z_b / b$ (unwrapped from block to block as $\arg z_b$, where the
//! reference may drift by turns). The base is the fundamental where it stands `min_snr` times
//! above its noise in as many blocks as the fit needs (`min_blocks`): its phase counts the turns
//! themselves, and the high-pass's corner is read against it
//! ([`high_pass`](crate::sound_analysis::high_pass)). Otherwise it is the harmonic that stands
//! `min_snr` above its noise in the most blocks (the lowest of equal counts): behind a phone's
//! high-pass far above a short spin's fundamental, only harmonics 2-6 are heard, and the
//! fundamental's phase is noise while the second harmonic's holds the heading. Each other harmonic gives the offset
//! $u_b + \mathrm{wrap}(\arg z_h - c_h - h u_b)/h$, $c_h$ its constant phase (the circular mean
//! over the record of $\arg z_h - h u_b$); the block's datum is their inverse-variance mean, its
//! variance the inverse of the summed inverses. Blocks whose base harmonic stands less than
//! `min_snr` times above its noise are left out.

use crate::fit::eq84_85::phase;
use nalgebra::SVector;
use rayon::prelude::*;
use rustfft::num_complex::Complex;
use std::f64::consts::{PI, TAU};

/// Harmonics demodulated (at most; only those below [`MAX_HZ`] and 0.45 of the sample rate).
pub const HARMONICS: usize = 4;

/// Harmonics are used up to this frequency (Hz).
pub const MAX_HZ: f64 = 3500.0;

/// A block's heading offset from the reference.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Block {
    /// Block start and end (s).
    pub a: f64,
    /// (see `a`)
    pub b: f64,
    /// The window's centroid time $\bar t$ (s).
    pub t: f64,
    /// Reference turns in the block, $N$.
    pub turns: usize,
    /// The heading minus the reference, wrapped to $(-\pi, \pi]$ about `expect` (rad).
    pub offset: f64,
    /// Its standard uncertainty (rad).
    pub sigma: f64,
    /// The base harmonic's power over the noise's in $z_b$.
    pub snr: f64,
    /// The base harmonic $b$ the offset is read from (see the module's documentation): 1, the
    /// fundamental, unless it stands above its noise in fewer blocks than the fit needs.
    pub base: usize,
    /// Each harmonic's power over the noise's in $z_h$ (index $h - 1$; NaN where absent).
    pub snrs: [f64; HARMONICS],
    /// Per harmonic $h \ne b$ (index $h - 1$; NaN where the block has no such harmonic, and at
    /// the base): its phase against $h$ times the base's offset,
    /// $\mathrm{wrap}(\arg z_h - c_h - h u_b)$ (rad), which the heading does not move and a
    /// filter's phase $\varphi$ moves by $\varphi(h\Omega) - (h/b)\varphi(b\Omega)$ less its
    /// mean over the record.
    pub split: [f64; HARMONICS],
    /// Its variance $\mathrm{Var}(\arg z_h) + h^2\,\mathrm{Var}(u_b)$ (rad²).
    pub split_var: [f64; HARMONICS],
    /// Per harmonic $h \ge 1$ (index $h - 1$; NaN where absent): $\arg z_h$ against $h$ times
    /// the reference heading plus the shift (rad), and its variance (rad²), for the harmonic
    /// fitted alone ([`harmonic_agreement`](crate::sound_analysis::harmonic_agreement)).
    pub phase: [f64; HARMONICS],
    /// (see `phase`)
    pub phase_var: [f64; HARMONICS],
    /// The weight of harmonic $h$ in `offset`, $\mathrm{offset} = u_b + \sum_{h \ne b}
    /// W_h\,\mathrm{split}_h / h$ (index $h - 1$; 0 where absent and at the base).
    pub weight: [f64; HARMONICS],
}

/// How blocks are cut and kept.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlockSettings {
    /// Longest block (s), unless two turns take longer.
    pub max_block: f64,
    /// A block is kept when its base harmonic's power stands this many times above the noise's
    /// (see the module's documentation).
    pub min_snr: f64,
    /// The fewest blocks the heading is fitted to.
    pub min_blocks: usize,
}

impl Default for BlockSettings {
    fn default() -> Self {
        Self {
            max_block: 0.1,
            min_snr: 20.0,
            min_blocks: 12,
        }
    }
}

/// The time at which eq 79's heading $\Phi(t) = -C^q(t_0 - t)^{1-q}/(1-q)$ equals `phi` (< 0).
pub fn time_at(p: &SVector<f64, 3>, phi: f64) -> f64 {
    let q = 1.0 / (p[0] + 2.0);
    let tau = ((1.0 - q) * (-phi) * (-q * p[2]).exp()).powf(1.0 / (1.0 - q));
    p[1] - tau
}

/// A record's samples: `x`, the first at `t_start`, interval `dt`.
pub struct Samples<'a> {
    /// The samples.
    pub x: &'a [f64],
    /// Time of the first (s).
    pub t_start: f64,
    /// Interval (s).
    pub dt: f64,
}

/// One block's sums: the harmonics' $z_h$, the noise probes' mean power per $\sum w^2$, the
/// centroid and $\sum w^2$.
struct Sums {
    z: [Complex<f64>; HARMONICS],
    noise: [f64; HARMONICS],
    t: f64,
    w2: f64,
}

/// Demodulates samples `x` (the first at `t_start`, interval `dt`) over the block
/// $[t_a, t_b]$ of whole reference turns.
fn sums(
    x: &[f64],
    t_start: f64,
    dt: f64,
    p: &SVector<f64, 3>,
    (ta, tb): (f64, f64),
    harmonics: usize,
) -> Sums {
    // The samples whose intervals reach into the block.
    let j0 = ((ta - t_start) / dt).round().max(0.0) as usize;
    let j1 = (((tb - t_start) / dt).round().max(0.0) as usize).min(x.len().saturating_sub(1));
    let mut z = [Complex::new(0.0, 0.0); HARMONICS];
    let mut probe = [0.0f64; HARMONICS];
    let mut lo = [Complex::new(0.0, 0.0); HARMONICS];
    let mut hi = [Complex::new(0.0, 0.0); HARMONICS];
    let (mut sw, mut swt, mut w2) = (0.0, 0.0, 0.0);
    let mut e = [Complex::new(0.0, 0.0); 2 * HARMONICS + 2];
    let mut heading = Hermite::new(p, t_start, dt, j0, j1);
    for (j, &xj) in x.iter().enumerate().take(j1 + 1).skip(j0) {
        let t = t_start + j as f64 * dt;
        // dPhi = Omega dt: each sample weighs as the heading it spans within the block.
        let (phi, omega) = heading.at(j);
        let w = omega * (((t + 0.5 * dt).min(tb) - (t - 0.5 * dt).max(ta)) / dt).clamp(0.0, 1.0);
        let (s, c) = (-0.5 * phi).sin_cos();
        // e[k] = exp(-i k phi / 2)
        e[0] = Complex::new(1.0, 0.0);
        e[1] = Complex::new(c, s);
        for k in 2..=2 * harmonics + 1 {
            e[k] = e[k - 1] * e[1];
        }
        let wx = w * xj;
        for h in 0..harmonics {
            z[h] += e[2 * (h + 1)] * wx;
            lo[h] += e[2 * h + 1] * wx;
            hi[h] += e[2 * h + 3] * wx;
        }
        sw += w;
        swt += w * t;
        w2 += w * w;
    }
    for h in 0..harmonics {
        probe[h] = 0.5 * (lo[h].norm_sqr() + hi[h].norm_sqr()) / w2.max(f64::MIN_POSITIVE);
    }
    Sums {
        z,
        noise: probe,
        t: if sw > 0.0 { swt / sw } else { 0.5 * (ta + tb) },
        w2,
    }
}

/// Samples between the nodes at which the heading is evaluated exactly.
const STRIDE: usize = 16;

/// Eq 79's heading and rate at samples `j0..=j1`, exact at every [`STRIDE`]-th sample and cubic
/// (Hermite, from the heading and the rate at both ends) between: over $h$ = 16 samples the
/// error is about $h^4 \Phi^{(4)}/384$, below $10^{-5}$ rad at 8 kS/s even 5 ms before $t_0$.
struct Hermite<'a> {
    p: &'a SVector<f64, 3>,
    t_start: f64,
    dt: f64,
    j1: usize,
    /// The current span's first and last sample, and the heading and rate at both.
    a: usize,
    b: usize,
    ends: [(f64, f64); 2],
}

impl<'a> Hermite<'a> {
    fn new(p: &'a SVector<f64, 3>, t_start: f64, dt: f64, j0: usize, j1: usize) -> Self {
        let mut h = Self {
            p,
            t_start,
            dt,
            j1,
            a: j0,
            b: j0,
            ends: [(0.0, 0.0); 2],
        };
        h.span(j0);
        h
    }

    /// The exact heading and rate at sample `j`.
    fn exact(&self, j: usize) -> (f64, f64) {
        let (phi, omega, _) = phase(self.p, self.t_start + j as f64 * self.dt);
        (phi, omega)
    }

    /// Starts the span at sample `a`.
    fn span(&mut self, a: usize) {
        self.a = a;
        self.b = (a + STRIDE).min(self.j1.max(a + 1));
        self.ends = [self.exact(a), self.exact(self.b)];
    }

    /// The heading and the rate at sample `j` (non-decreasing from call to call).
    fn at(&mut self, j: usize) -> (f64, f64) {
        if j >= self.b && j > self.a {
            self.span(j);
        }
        if j == self.a {
            return self.ends[0];
        }
        let h = (self.b - self.a) as f64 * self.dt;
        let u = (j - self.a) as f64 / (self.b - self.a) as f64;
        let [(f0, w0), (f1, w1)] = self.ends;
        let (u2, u3) = (u * u, u * u * u);
        let phi = (2.0 * u3 - 3.0 * u2 + 1.0) * f0
            + (u3 - 2.0 * u2 + u) * h * w0
            + (-2.0 * u3 + 3.0 * u2) * f1
            + (u3 - u2) * h * w1;
        let omega = ((6.0 * u2 - 6.0 * u) * f0 + (-6.0 * u2 + 6.0 * u) * f1) / h
            + (3.0 * u2 - 4.0 * u + 1.0) * w0
            + (3.0 * u2 - 2.0 * u) * w1;
        (phi, omega)
    }
}

/// The value of `x` wrapped to $(-\pi, \pi]$.
pub fn wrap(x: f64) -> f64 {
    let y = x.rem_euclid(TAU);
    if y > PI {
        y - TAU
    } else {
        y
    }
}

/// The blocks between `first` and `last` (s) of the record `rec`, demodulated against eq 79's
/// heading `p` = $(\beta, t_0, \ln C)$ plus the offset `shift` (rad); each block's offset is
/// wrapped about zero. With `unwrap`, the fundamental's offsets are instead unwrapped from block
/// to block (for a reference whose offset may drift by turns over the record).
pub fn blocks(
    rec: &Samples<'_>,
    p: &SVector<f64, 3>,
    shift: f64,
    (first, last): (f64, f64),
    unwrap: bool,
    s: &BlockSettings,
) -> Vec<Block> {
    let (x, t_start, dt) = (rec.x, rec.t_start, rec.dt);
    let fs = 1.0 / dt;
    // Each block's start, end, turns and harmonics; then their sums, independent of each other,
    // on rayon's threads (the order kept, so the result does not depend on them).
    let mut cuts: Vec<(f64, f64, usize, usize)> = Vec::new();
    let mut ta = first;
    while ta < last {
        let (phi_a, omega, _) = phase(p, ta);
        if !(phi_a.is_finite() && omega.is_finite() && omega > 0.0) {
            break;
        }
        let turns = 2 * ((omega * s.max_block / (2.0 * TAU)).floor() as usize).max(1);
        let tb = time_at(p, phi_a + TAU * turns as f64);
        if !(tb.is_finite() && tb <= last) {
            break;
        }
        // Harmonics that stay below the limit at the block's end.
        let f_end = phase(p, tb).1 / TAU;
        let harmonics = (1..=HARMONICS)
            .take_while(|&h| h as f64 * f_end < MAX_HZ.min(0.45 * fs))
            .count();
        if harmonics == 0 {
            break;
        }
        cuts.push((ta, tb, turns, harmonics));
        ta = tb;
    }
    let raw: Vec<(f64, f64, usize, Sums, usize)> = cuts
        .into_par_iter()
        .map(|(ta, tb, turns, harmonics)| {
            let sm = sums(x, t_start, dt, p, (ta, tb), harmonics);
            (ta, tb, turns, sm, harmonics)
        })
        .collect();
    combine(&raw, shift, unwrap, s)
}

/// The blocks' data from their sums (see the module's documentation).
fn combine(
    raw: &[(f64, f64, usize, Sums, usize)],
    shift: f64,
    unwrap: bool,
    s: &BlockSettings,
) -> Vec<Block> {
    let n = raw.len();
    // Pooled noise per unit sum of w^2, over the block and two neighbours each side.
    let pooled = |k: usize, h: usize| -> f64 {
        let r = k.saturating_sub(2)..(k + 3).min(n);
        let (mut sum, mut cnt) = (0.0, 0.0f64);
        for j in r {
            if h < raw[j].4 {
                sum += raw[j].3.noise[h];
                cnt += 1.0;
            }
        }
        sum / cnt.max(1.0)
    };
    // Per block and harmonic: the phase (rad) and its variance.
    let rot = Complex::from_polar(1.0, -shift);
    let mut per: Vec<Vec<(f64, f64)>> = Vec::with_capacity(n);
    let mut snrs: Vec<[f64; HARMONICS]> = Vec::with_capacity(n);
    for (k, r) in raw.iter().enumerate() {
        let mut v = Vec::with_capacity(r.4);
        for h in 0..r.4 {
            let zh = r.3.z[h] * rot.powu(h as u32 + 1);
            let nu = pooled(k, h) * r.3.w2;
            let var = nu / (2.0 * zh.norm_sqr()).max(f64::MIN_POSITIVE);
            v.push((zh.arg(), var));
        }
        let mut snr = [f64::NAN; HARMONICS];
        for (h, x) in snr.iter_mut().enumerate().take(r.4) {
            *x = r.3.z[h].norm_sqr() / (pooled(k, h) * r.3.w2).max(f64::MIN_POSITIVE);
        }
        snrs.push(snr);
        per.push(v);
    }
    // The base: the fundamental where it stands above `min_snr` in the blocks a fit needs,
    // else the harmonic above it in the most blocks, the lowest of equal counts.
    let above = |h: usize| (0..n).filter(|&k| snrs[k][h] >= s.min_snr).count();
    let b = if above(0) >= s.min_blocks {
        0
    } else {
        (0..HARMONICS).rev().max_by_key(|&h| above(h)).unwrap_or(0)
    };
    let bb = (b + 1) as f64;
    let kept: Vec<usize> = (0..n).filter(|&k| snrs[k][b] >= s.min_snr).collect();
    // The base's offsets, wrapped or unwrapped (as its phase), and their variances.
    let mut ub: Vec<f64> = kept.iter().map(|&k| per[k][b].0).collect();
    if unwrap {
        for i in 1..ub.len() {
            ub[i] = ub[i - 1] + wrap(ub[i] - ub[i - 1]);
        }
    }
    let u: Vec<f64> = ub.iter().map(|v| v / bb).collect();
    let u_var: Vec<f64> = kept.iter().map(|&k| per[k][b].1 / (bb * bb)).collect();
    // Each other harmonic's constant phase c_h.
    let mut c = [0.0f64; HARMONICS];
    for (h, ch) in c.iter_mut().enumerate().filter(|(h, _)| *h != b) {
        let mut acc = Complex::new(0.0, 0.0);
        for (i, &k) in kept.iter().enumerate() {
            if let Some(&(ph, var)) = per[k].get(h) {
                let hh = (h + 1) as f64;
                let wgt = 1.0 / (var + hh * hh * u_var[i]);
                acc += Complex::from_polar(wgt, ph - hh * u[i]);
            }
        }
        *ch = acc.arg();
    }
    kept.iter()
        .enumerate()
        .map(|(i, &k)| {
            let (mut num, mut den) = (u[i] / u_var[i], 1.0 / u_var[i]);
            let (mut split, mut split_var, mut weight) = (
                [f64::NAN; HARMONICS],
                [f64::NAN; HARMONICS],
                [0.0; HARMONICS],
            );
            for (h, &(ph, var)) in per[k].iter().enumerate().filter(|(h, _)| *h != b) {
                let hh = (h + 1) as f64;
                split[h] = wrap(ph - c[h] - hh * u[i]);
                split_var[h] = var + hh * hh * u_var[i];
                let est = u[i] + split[h] / hh;
                num += est * hh * hh / var;
                den += hh * hh / var;
                weight[h] = hh * hh / var;
            }
            for w in weight.iter_mut() {
                *w /= den;
            }
            let (mut phase, mut phase_var) = ([f64::NAN; HARMONICS], [f64::NAN; HARMONICS]);
            for (h, &(ph, var)) in per[k].iter().enumerate() {
                (phase[h], phase_var[h]) = (ph, var);
            }
            let r = &raw[k];
            Block {
                a: r.0,
                b: r.1,
                t: r.3.t,
                turns: r.2,
                offset: num / den,
                sigma: den.recip().sqrt(),
                snr: snrs[k][b],
                base: b + 1,
                snrs: snrs[k],
                split,
                split_var,
                phase,
                phase_var,
                weight,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{blocks, BlockSettings, Samples};
    use crate::fit::eq84_85::phase;
    use nalgebra::SVector;

    /// A disk's sound behind a phone's high-pass, its fundamental 40 dB below the second and
    /// third harmonics, with no noise: the blocks' noise probes at the half-way lines hold only
    /// what leaks into them, so the fundamental's signal-to-noise measures the leak. At 8 kS/s,
    /// as at 48 kS/s, it stays above 10^5 in every block (a window cut at whole samples leaks
    /// enough to bring it to a median of 150, and 11 in the worst block, at 8 kS/s), and the
    /// blocks' offsets agree to 10^-4 rad.
    #[test]
    fn blocks_span_their_turns_at_any_rate() {
        // Eq 79 with beta = 2, Omega = 100 rad/s seven seconds before t0 = 10 s.
        let p = SVector::<f64, 3>::new(2.0, 10.0, (100f64.powi(4) * 7.0).ln());
        let record = |fs: f64| -> Vec<f64> {
            (0..(9.0 * fs) as usize)
                .map(|j| {
                    let phi = phase(&p, j as f64 / fs).0;
                    0.01 * phi.sin() + (2.0 * phi + 0.3).sin() + 0.5 * (3.0 * phi + 1.0).sin()
                })
                .collect()
        };
        let settings = BlockSettings {
            min_snr: 0.0,
            ..BlockSettings::default()
        };
        let at = |x: &[f64], fs: f64| {
            let rec = Samples {
                x,
                t_start: 0.0,
                dt: 1.0 / fs,
            };
            blocks(&rec, &p, 0.0, (1.0, 8.0), false, &settings)
        };
        let (x8, x48) = (record(8000.0), record(48_000.0));
        let (b8, b48) = (at(&x8, 8000.0), at(&x48, 48_000.0));
        assert!(
            b8.len() > 40 && b8.len() == b48.len(),
            "{} {}",
            b8.len(),
            b48.len()
        );
        for (a, b) in b8.iter().zip(&b48) {
            assert!(
                a.snr > 1e5 && b.snr > 1e5,
                "{:.3} s: {} and {}",
                a.a,
                a.snr,
                b.snr
            );
            assert!((a.offset - b.offset).abs() < 1e-4, "{:.3} s", a.a);
        }
    }

    /// The same law behind a phone's high-pass that leaves no fundamental at all, its second
    /// and third harmonics over white noise: the fundamental's phase is noise in every block,
    /// so the heading is read from the second harmonic, the line above the noise in most
    /// blocks, and the blocks' offsets from the law scatter about zero as their sigmas say.
    #[test]
    fn without_a_fundamental_the_heading_is_read_from_the_line_heard() {
        use rand::SeedableRng;
        use rand_distr::{Distribution, Normal};
        let p = SVector::<f64, 3>::new(2.0, 10.0, (100f64.powi(4) * 7.0).ln());
        let fs = 8000.0;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
        let noise = Normal::new(0.0, 0.05).unwrap();
        let x: Vec<f64> = (0..(9.0 * fs) as usize)
            .map(|j| {
                let phi = phase(&p, j as f64 / fs).0;
                (2.0 * phi + 0.3).sin() + 0.5 * (3.0 * phi + 1.0).sin() + noise.sample(&mut rng)
            })
            .collect();
        let rec = Samples {
            x: &x,
            t_start: 0.0,
            dt: 1.0 / fs,
        };
        let bl = blocks(&rec, &p, 0.0, (1.0, 8.0), false, &BlockSettings::default());
        assert!(bl.len() > 40, "{} blocks", bl.len());
        // The constant phase of the second harmonic, 0.3 - pi/2, halved, is the offset.
        let c = super::wrap(0.3 - 0.5 * std::f64::consts::PI) / 2.0;
        let z: Vec<f64> = bl
            .iter()
            .map(|b| super::wrap(b.offset - c) / b.sigma)
            .collect();
        assert!(bl.iter().all(|b| b.base == 2), "{bl:?}");
        let n = z.len() as f64;
        let mean = z.iter().sum::<f64>() / n;
        let rms = (z.iter().map(|v| v * v).sum::<f64>() / n).sqrt();
        assert!(mean.abs() < 3.0 / n.sqrt(), "mean offset {mean} sigmas");
        assert!((0.7..1.5).contains(&rms), "rms offset {rms} sigmas");
    }
}
