//! The next [`BATCH`] times of a sampling grid $t_g + n\,\Delta t$, and how many of them a step
//! holds.

use super::BATCH;

/// Writes the grid's times $t_g + \Delta t\,(n_0 + k)$ for $k = 0 \ldots$ [`BATCH`]$- 1$ to
/// `times` (`origin` $= t_g$, `dt` $= \Delta t$, `base` $= n_0$ as a double) and returns how
/// many of them are neither past the step's end `t_b` nor at or past `guard`: those are the
/// first ones, since the times rise with $k$ and the test is monotone. The same operations in
/// every build (AVX-512F, AVX2 or the baseline, chosen at run time by [`numerics::wider`]), so
/// the same bits.
#[inline]
pub(super) fn grid_times(
    origin: f64,
    dt: f64,
    base: f64,
    t_b: f64,
    guard: f64,
    times: &mut [f64; BATCH],
) -> usize {
    #[cfg(target_arch = "x86_64")]
    if numerics::wider::avx512() {
        // SAFETY: the processor has AVX-512F, checked just above.
        return unsafe { grid_avx512(origin, dt, base, t_b, guard, times) };
    }
    #[cfg(target_arch = "x86_64")]
    if numerics::wider::avx2() {
        // SAFETY: the processor has AVX2, checked just above.
        return unsafe { grid_avx2(origin, dt, base, t_b, guard, times) };
    }
    grid_plain(origin, dt, base, t_b, guard, times)
}

/// [`grid_times`] compiled for AVX-512F.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f")]
fn grid_avx512(o: f64, dt: f64, base: f64, t_b: f64, guard: f64, t: &mut [f64; BATCH]) -> usize {
    grid_plain(o, dt, base, t_b, guard, t)
}

/// [`grid_times`] compiled for AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn grid_avx2(o: f64, dt: f64, base: f64, t_b: f64, guard: f64, t: &mut [f64; BATCH]) -> usize {
    grid_plain(o, dt, base, t_b, guard, t)
}

/// [`grid_times`]'s loops, in the build this is inlined into.
#[inline(always)]
fn grid_plain(
    origin: f64,
    dt: f64,
    base: f64,
    t_b: f64,
    guard: f64,
    times: &mut [f64; BATCH],
) -> usize {
    for (k, t) in times.iter_mut().enumerate() {
        *t = origin + dt * (base + k as f64);
    }
    times
        .iter()
        .map(|&t| usize::from(!(t > t_b || t >= guard)))
        .sum::<usize>()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    /// Every build's times and count against the baseline's, and the count against the
    /// times' own test one by one, on random grids and step ends (`NaN` and infinite guards
    /// among them).
    #[test]
    fn every_build_gives_the_baselines_times_and_count() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(49);
        let mut compared = [0usize; 2];
        for trial in 0..20_000 {
            let origin = rng.random_range(-10.0..10.0);
            let dt = 10f64.powf(rng.random_range(-6.0..0.0));
            let base = rng.random_range(0..1_000_000u64) as f64;
            let t_b = origin + dt * (base + rng.random_range(-2.0..40.0));
            let guard = match trial % 10 {
                0 => f64::INFINITY,
                1 => f64::NAN,
                _ => origin + dt * (base + rng.random_range(-2.0..40.0)),
            };
            let mut plain = [0.0; BATCH];
            let n = grid_plain(origin, dt, base, t_b, guard, &mut plain);
            let by_one = plain
                .iter()
                .take_while(|&&t| !(t > t_b || t >= guard))
                .count();
            assert_eq!(n, by_one, "trial {trial}");
            let mut t = [0.0; BATCH];
            assert_eq!(grid_times(origin, dt, base, t_b, guard, &mut t), n);
            assert_eq!(t.map(f64::to_bits), plain.map(f64::to_bits));
            #[cfg(target_arch = "x86_64")]
            if numerics::wider::avx2() {
                let mut t = [0.0; BATCH];
                // SAFETY: the processor has AVX2, checked just above.
                assert_eq!(
                    unsafe { grid_avx2(origin, dt, base, t_b, guard, &mut t) },
                    n
                );
                assert_eq!(t.map(f64::to_bits), plain.map(f64::to_bits));
                compared[0] += 1;
            }
            #[cfg(target_arch = "x86_64")]
            if numerics::wider::avx512() {
                let mut t = [0.0; BATCH];
                // SAFETY: the processor has AVX-512F, checked just above.
                assert_eq!(
                    unsafe { grid_avx512(origin, dt, base, t_b, guard, &mut t) },
                    n
                );
                assert_eq!(t.map(f64::to_bits), plain.map(f64::to_bits));
                compared[1] += 1;
            }
        }
        eprintln!("compared: {compared:?} (AVX2, AVX-512F)");
    }
}
