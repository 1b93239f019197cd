//! Projection onto an invariant: after every accepted step the state is moved back onto the
//! level set of a conserved quantity (Hairer, Lubich and Wanner, *Geometric Numerical
//! Integration*, sec. IV.4, "standard projection").
//!
//! For a conserved $I(y)$ with value $I_0$ at the start, the projected state is the point of
//! $\{I = I_0\}$ nearest to the step's result $\tilde y$ (Euclidean norm in the state's own
//! components): $y = \tilde y + \lambda\,\nabla I(\tilde y)$, with $\lambda$ from Newton's
//! iteration on $I(\tilde y + \lambda\nabla I(\tilde y)) = I_0$ (the gradient held at
//! $\tilde y$, as Hairer et al. recommend: it costs no more and converges as fast, since
//! $\tilde y$ is within the tolerance of the manifold). The gradient is taken by central
//! differences; its error tilts the direction of the correction, not the level it reaches.
//!
//! Written here because it is a step of the integrator (it needs the step loop of the crate's
//! own DOP853, which `ode_solvers` does not expose), not general numerics a crate provides.

use super::State;
use serde::{Deserialize, Serialize};

/// What a run may be projected onto (a scene's `solver: { project: energy }`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Projection {
    /// The total energy (eq 26 for the rolling model; the frictionless and lab-frame models'
    /// own energies): for models without dissipation only.
    Energy,
}

impl std::fmt::Display for Projection {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Projection::Energy => "energy",
        })
    }
}

/// Newton iterations at most; each solves a scalar equation, so two usually reach round-off.
const ITERATIONS: usize = 4;

/// Moves `y` onto the level `level` of `invariant` along the invariant's gradient at `y`
/// (see the module doc). Leaves `y` unchanged where the gradient vanishes or is not finite,
/// or where the correction would not be finite.
pub fn onto_level<const N: usize>(
    invariant: impl Fn(&State<N>) -> f64,
    level: f64,
    y: &mut State<N>,
) {
    let mut grad = State::<N>::zeros();
    for i in 0..N {
        let h = 1e-7 * y[i].abs().max(1.0);
        let (mut up, mut down) = (*y, *y);
        up[i] += h;
        down[i] -= h;
        grad[i] = (invariant(&up) - invariant(&down)) / (2.0 * h);
    }
    let g2 = grad.norm_squared();
    if !(g2.is_finite() && g2 > 0.0) {
        return;
    }
    let start = *y;
    let mut lambda = 0.0;
    for _ in 0..ITERATIONS {
        let moved = start + grad * lambda;
        let residual = invariant(&moved) - level;
        if !residual.is_finite() {
            return;
        }
        // d/dlambda I(start + lambda grad) = grad(moved) . grad, taken as |grad|^2.
        let delta = residual / g2;
        lambda -= delta;
        if delta.abs() * g2.sqrt() <= f64::EPSILON * start.norm().max(f64::MIN_POSITIVE) {
            break;
        }
    }
    let projected = start + grad * lambda;
    if projected.iter().all(|v| v.is_finite()) {
        *y = projected;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_near_a_circle_lands_on_it_along_the_radius() {
        let r2 = |y: &State<2>| y[0] * y[0] + y[1] * y[1];
        let mut y = State::<2>::new(0.6 * 1.001, 0.8 * 1.001);
        onto_level(r2, 1.0, &mut y);
        assert!((r2(&y) - 1.0).abs() < 1e-15, "level {}", r2(&y));
        // Along the radius: the direction is kept.
        assert!(
            (y[0] / y[1] - 0.75).abs() < 1e-12,
            "direction {}",
            y[0] / y[1]
        );
    }

    #[test]
    fn a_flat_invariant_leaves_the_state_alone() {
        let mut y = State::<2>::new(0.3, -0.2);
        onto_level(|_| 5.0, 1.0, &mut y);
        assert_eq!(y, State::<2>::new(0.3, -0.2));
    }

    #[test]
    fn a_nonlinear_level_is_reached_to_round_off() {
        // An energy-like invariant with a potential: |v|^2/2 + sin(x).
        let e = |y: &State<3>| 0.5 * (y[1] * y[1] + y[2] * y[2]) + y[0].sin();
        let mut y = State::<3>::new(0.4, 1.0, -2.0);
        let level = e(&y);
        y[1] += 1e-6;
        y[0] -= 3e-7;
        onto_level(e, level, &mut y);
        assert!(
            ((e(&y) - level) / level).abs() < 4.0 * f64::EPSILON,
            "{}",
            e(&y) - level
        );
    }
}
