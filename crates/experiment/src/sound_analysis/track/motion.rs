//! The pitch's motion within a frame, added to the frame's uncertainty: a line that moves by
//! $\ddot\Omega$ across a frame of length $T$ is read at its window's weighted mean, off the
//! centre's value by about $\tfrac12|\ddot\Omega|\,\mathrm{var}_w T^2$.

use super::TrackPoint;
use std::f64::consts::PI;

/// Adds the pitch's motion within each frame to its uncertainty (see [`super`]'s
/// documentation).
pub(super) fn add_motion(points: &mut [TrackPoint]) {
    let n = points.len();
    if n < 3 {
        return;
    }
    let mid = |p: &TrackPoint| 0.5 * (p.a + p.b);
    let curv: Vec<f64> = (0..n)
        .map(|k| {
            let j = k.clamp(1, n - 2);
            let (p, q, r) = (&points[j - 1], &points[j], &points[j + 1]);
            let (t0, t1, t2) = (mid(p), mid(q), mid(r));
            let d1 = (q.omega - p.omega) / (t1 - t0);
            let d2 = (r.omega - q.omega) / (t2 - t1);
            2.0 * (d2 - d1) / (t2 - t0)
        })
        .collect();
    let var_w = (0.25 - 15.0 / (8.0 * PI * PI)) / 3.0;
    for (p, c) in points.iter_mut().zip(curv) {
        let t = p.b - p.a;
        let motion = 0.5 * c.abs() * var_w * t * t;
        p.sigma = p.sigma.hypot(motion);
    }
}
