//! One peak of the light signal, and the crossings of half height that time it: each located
//! on the cubic through the four samples around it, with its uncertainty from the noise and the
//! edge's slope.

use serde::Serialize;

/// One peak.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Peak {
    /// Its time $t_i$ (s), the mean of the two crossings.
    pub t: f64,
    /// The standard uncertainty of $t_i$ from the noise (s).
    pub sigma: f64,
    /// The rising crossing (s).
    pub rise: f64,
    /// The falling crossing (s).
    pub fall: f64,
    /// The envelope's span at the peak (V).
    pub span: f64,
    /// The crossing level above the low envelope (V).
    pub height: f64,
    /// The mean absolute slope of the signal at the two crossings (V/s).
    pub slope: f64,
}

/// A crossing of `level` between samples `k` and `k + 1`: its time and uncertainty.
fn crossing(t: &[f64], v: &[f64], k: usize, level: f64, sigma_v: f64) -> (f64, f64, f64) {
    let n = t.len();
    let s0 = if k >= 1 && k + 2 < n { k - 1 } else { k };
    let m = if s0 + 3 < n && s0 + 1 == k { 4 } else { 2 };
    let (ts, vs) = (&t[s0..s0 + m], &v[s0..s0 + m]);
    // Lagrange weights and their derivatives at s.
    let weights = |s: f64| {
        let mut l = [0.0; 4];
        let mut dl = [0.0; 4];
        for i in 0..m {
            let mut li = 1.0;
            let mut dli = 0.0;
            for j in 0..m {
                if i != j {
                    let d = ts[i] - ts[j];
                    dli = dli * (s - ts[j]) / d + li / d;
                    li *= (s - ts[j]) / d;
                }
            }
            l[i] = li;
            dl[i] = dli;
        }
        (l, dl)
    };
    let p = |s: f64| {
        let (l, _) = weights(s);
        (0..m).map(|i| l[i] * vs[i]).sum::<f64>() - level
    };
    let (mut a, mut b) = (t[k], t[k + 1]);
    let rising = v[k + 1] > v[k];
    for _ in 0..50 {
        let mid = 0.5 * (a + b);
        if (p(mid) < 0.0) == rising {
            a = mid;
        } else {
            b = mid;
        }
    }
    let s = 0.5 * (a + b);
    let (l, dl) = weights(s);
    let slope: f64 = (0..m).map(|i| dl[i] * vs[i]).sum();
    let secant = (v[k + 1] - v[k]) / (t[k + 1] - t[k]);
    let slope = if slope.abs() > 0.25 * secant.abs() {
        slope
    } else {
        secant
    };
    let l2: f64 = l[..m].iter().map(|x| x * x).sum();
    let g = edge_slope(t, v, k).unwrap_or(slope.abs());
    (s, sigma_v * l2.sqrt() / g, g)
}

/// The slope of the edge at the sample interval $[k, k+1]$ for the crossing's uncertainty: the
/// least-squares line through the six samples $k-2, \dots, k+3$ (`None` nearer the record's
/// ends). The crossing's error is $\delta t = -\delta p/g$ with $g$ the slope of the noise-free
/// signal; the derivative of the cubic through four noisy samples at the noisy root is a poor
/// stand-in where the edge rises by only a few noise deviations per sample (the spin-down's slow
/// start): its own noise is about $1.2\,\sigma_v/\Delta t$, and the root falls where the noise
/// steepens the edge, so on the coverage study's traces it is 1.5 times the line's on average and
/// makes the stated timing uncertainty 1.36 times too small. The
/// line's slope has noise $\sigma_v/(\Delta t\sqrt{17.5}) = 0.24\,\sigma_v/\Delta t$, does not
/// depend on where the root fell, and is exact for a quadratic edge (the six samples are
/// symmetric about the interval's middle).
fn edge_slope(t: &[f64], v: &[f64], k: usize) -> Option<f64> {
    if k < 2 || k + 4 > t.len() {
        return None;
    }
    let (ts, vs) = (&t[k - 2..k + 4], &v[k - 2..k + 4]);
    let mt = ts.iter().sum::<f64>() / 6.0;
    let mv = vs.iter().sum::<f64>() / 6.0;
    let sxy: f64 = ts.iter().zip(vs).map(|(a, b)| (a - mt) * (b - mv)).sum();
    let sxx: f64 = ts.iter().map(|a| (a - mt).powi(2)).sum();
    let g = (sxy / sxx).abs();
    (g > 0.0 && g.is_finite()).then_some(g)
}

/// The crossing of an edge that noise may cross several times: the mean of its first and last
/// crossings in the direction of the edge between `from` and `last` (the last one), so that
/// the choice leans neither early nor late.
pub(crate) fn edge(
    t: &[f64],
    v: &[f64],
    from: usize,
    last: usize,
    level: f64,
    sigma_v: f64,
    rising: bool,
) -> (f64, f64, f64) {
    let (tl, sl, gl) = crossing(t, v, last, level, sigma_v);
    let crosses = |k: usize| {
        if rising {
            v[k] <= level && v[k + 1] > level
        } else {
            v[k] >= level && v[k + 1] < level
        }
    };
    match (from..last).find(|&k| crosses(k)) {
        Some(k) => {
            let (tf, sf, _) = crossing(t, v, k, level, sigma_v);
            (0.5 * (tf + tl), 0.5 * (sf + sl), gl)
        }
        None => (tl, sl, gl),
    }
}
