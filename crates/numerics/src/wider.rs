//! The run-time choice of the wider vector builds: whether this processor has AVX2 (or
//! AVX-512F), so that a loop compiled a second time with `#[target_feature(enable = "avx2")]`
//! (or a third with `"avx512f"`) may run.
//!
//! A loop compiled both ways makes the same IEEE operations in the same order: the wider build
//! only puts four doubles in a register where the baseline (SSE2) puts two. Rust never fuses a
//! multiply and an add unless asked (`mul_add`), and `fma` is not enabled, so the two builds give
//! the same bits. Each loop that has both is tested both ways: [`crate::trig`]'s tests call its
//! two builds, and [`baseline_only`] makes every loop take the baseline build for a while, so
//! that a test compares whole results of both.

use std::sync::atomic::{AtomicBool, Ordering};

/// Set while [`baseline_only`] runs.
static BASELINE: AtomicBool = AtomicBool::new(false);

/// True when the wider build may run: the processor running this program has AVX2 (the
/// standard library caches the answer) and no [`baseline_only`] is under way. `false` off
/// x86-64.
#[inline]
pub fn avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        !BASELINE.load(Ordering::Relaxed) && std::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// True when the widest build may run: the processor has AVX-512F (eight doubles to a
/// register, the loops that have that build; it implies AVX2) and no [`baseline_only`] is
/// under way. `false` off x86-64.
#[inline]
pub fn avx512() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        !BASELINE.load(Ordering::Relaxed) && std::is_x86_feature_detected!("avx512f")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// Runs `f` with every loop that has a wider build taking the baseline one instead. The
/// choice is the process's, so code running on other threads meanwhile takes the baseline
/// build too; the builds give the same bits, so only its speed changes.
pub fn baseline_only<T>(f: impl FnOnce() -> T) -> T {
    let before = BASELINE.swap(true, Ordering::Relaxed);
    let out = f();
    BASELINE.store(before, Ordering::Relaxed);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_baseline_is_chosen_while_asked_and_the_processor_decides_after() {
        let has = avx2();
        assert!(!baseline_only(avx2));
        assert_eq!(avx2(), has);
        let has512 = avx512();
        assert!(!baseline_only(avx512));
        assert_eq!(avx512(), has512);
        #[cfg(target_arch = "x86_64")]
        assert_eq!(has512, std::is_x86_feature_detected!("avx512f"));
        #[cfg(target_arch = "x86_64")]
        assert_eq!(has, std::is_x86_feature_detected!("avx2"));
    }
}
