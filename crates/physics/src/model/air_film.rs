//! The squeeze film of air under a disk rolling at a small tilt: the dissipation of Moffatt's
//! mechanism (sec. 11, eqs 82-83), derived here from lubrication theory because the paper quotes
//! its result without the derivation.
//!
//! **Geometry.** With $b = 0$ and the tilt $\alpha$ small, the disk's lower face is a plane
//! through the contact point, which runs round a circle of radius $a$ at the rate $\Omega$. At a
//! table point $\mathbf r = a\boldsymbol\rho$ under the disk the air gap is
//! $h = a\alpha\,H$ with $H = 1 - \boldsymbol\rho\cdot\hat{\mathbf e}(\psi)$, $\hat{\mathbf e}$ the
//! direction of the contact point and $\dot\psi = \Omega$. The face moves up and down at
//! $\partial h/\partial t = -a\alpha\Omega\,\boldsymbol\rho\cdot\hat{\mathbf e}_\perp$; its
//! horizontal speed is smaller by another factor $\alpha$ and is neglected.
//!
//! **Flow.** In the thin gap the air's pressure obeys Reynolds' equation
//! $\nabla\cdot(h^3\nabla p) = 12\eta\,\partial h/\partial t$, with $p = 0$ (ambient) at the rim.
//! Writing $p = (12\eta\Omega/\alpha^2)P$, the shape function $P$ solves
//! $\nabla_\rho\cdot(H^3\nabla_\rho P) = -\boldsymbol\rho\cdot\hat{\mathbf e}_\perp$ on the unit
//! disk with $P = 0$ on its edge, and the viscous dissipation
//! $\Phi = \int h^3|\nabla p|^2/12\eta\,dA = -\int p\,\partial h/\partial t\,dA$ is
//! $$\Phi = 12\,I\,\frac{\eta a^3\Omega^2}{\alpha}, \qquad
//!   I = \int_{\rho<1} H^3|\nabla P|^2\,dA = \int_{\rho<1} P\,\rho_\perp\,dA,$$
//! a pure number. With $\Omega^2 \propto 1/\alpha$ at small tilt this is a power $\propto\Omega^4$:
//! the $\beta = 4$ of eq 75, as the paper says of Moffatt's model.
//!
//! **The number $I$.** The operator degenerates at the contact point ($H = 0$ there), where $P$
//! is unbounded. [`super::film_bound`] solves the problem by conforming finite elements on a
//! mesh that opens up the contact point: each grid's value is a lower bound on $I$, and the
//! bounds converge at the second order (0.1061897, 0.1066159, 0.1067243, 0.1067517 for 64, 128,
//! 256 and 512 cells; successive differences fall by 3.93 and 3.97). [`SqueezeFilm::solved`]
//! extrapolates the 128- and 256-cell bounds: $I = 0.106760$, uncertain by $2.5\times10^{-6}$
//! (its distance from the 64/128 extrapolation); the 256/512 extrapolation, 0.1067608, lies
//! within it. Finite volumes on a polar grid ([`dissipation_number`]), a discretization that
//! shares nothing with it, approach from above (0.1137, 0.1100, 0.1082, 0.1073 for 25, 50,
//! 100, 200 radial cells), their error falling a little faster than the cell size.
//! Hand-written because the Reynolds equation on this wedge is the field's own problem; the
//! sparse Cholesky factorization is nalgebra-sparse's.
//!
//! **Where it applies.** Lubrication needs the gap thinner than the viscous layer that the
//! moving wedge drives, $a\alpha \ll \sqrt{\nu/\Omega}$ ($\nu = \eta/\rho_{air}$): for the toy
//! disk (a = 37.5 mm) at $\Omega$ = 300 rad/s that is $\alpha \ll 0.006$ rad, the last moments
//! of a spin-down. [`SqueezeFilm::gap_over_layer`] gives the ratio.

use super::film_bound;
use crate::disk::Disk;
use nalgebra::DVector;
use nalgebra_sparse::factorization::CscCholesky;
use nalgebra_sparse::{CooMatrix, CscMatrix};
use std::f64::consts::PI;
use std::sync::OnceLock;

/// The squeeze film's dissipation number $I$ with its discretization uncertainty.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SqueezeFilm {
    /// $I$, extrapolated to a vanishing cell size.
    pub coefficient: f64,
    /// The extrapolation's distance from the one of the next coarser grids: a bound on the
    /// discretization error that remains.
    pub uncertainty: f64,
}

/// Cells of the coarsest of the three grids of [`SqueezeFilm::solved`] (the others have two
/// and four times as many).
pub const COARSEST: usize = 64;

/// The process's $I$: solved at its first use, or a value kept from an earlier run of the same
/// program ([`SqueezeFilm::keep`]).
static FILM: OnceLock<SqueezeFilm> = OnceLock::new();

impl SqueezeFilm {
    /// $I$ from the lower bounds of conforming finite elements on grids of 64, 128 and 256
    /// cells, extrapolated at the second order (see [`film_bound::extrapolated`]); computed once per
    /// process, unless [`SqueezeFilm::keep`] gave it first.
    pub fn solved() -> Self {
        *FILM.get_or_init(Self::computed)
    }

    /// $I$ computed now, as [`SqueezeFilm::solved`] computes it: the same number to the bit.
    pub fn computed() -> Self {
        let number = film_bound::extrapolated(COARSEST);
        SqueezeFilm {
            coefficient: number.estimate,
            uncertainty: number.uncertainty,
        }
    }

    /// Makes `film` the process's $I$, for a value that [`SqueezeFilm::computed`] gave in an
    /// earlier run of this same program (kept between runs by the report crate's cache, which
    /// trusts only an intact entry of this build). False when the process already has its $I$,
    /// which then stays.
    pub fn keep(film: SqueezeFilm) -> bool {
        FILM.set(film).is_ok()
    }

    /// The process's $I$ when it has one yet (solved or kept), without solving it.
    pub fn settled() -> Option<Self> {
        FILM.get().copied()
    }

    /// The power the air film takes from the disk (W, positive),
    /// $\Phi = 12 I\eta a^3\Omega^2/\alpha$, for air of viscosity `eta` (Pa s).
    pub fn dissipation(&self, disk: &Disk, eta: f64, alpha: f64, precession: f64) -> f64 {
        12.0 * self.coefficient * eta * disk.a.powi(3) * precession * precession / alpha
    }

    /// The gap $a\alpha$ over the viscous layer $\sqrt{\nu/\Omega}$ (kinematic viscosity `nu`,
    /// m^2/s): lubrication theory needs it well below 1.
    pub fn gap_over_layer(disk: &Disk, nu: f64, alpha: f64, precession: f64) -> f64 {
        disk.a * alpha * (precession.abs() / nu).sqrt()
    }
}

/// The tilts over which the idealized squeeze film describes a disk that still rolls: above the
/// tilt where its suction reaches one atmosphere and above the tilt where the disk, falling by
/// the film's law, would leave the table; below the tilt where the air's inertia counts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Window {
    /// Where the suction $12\eta\Omega/\alpha^2$ equals `p_atm` (rad); below it the air cavitates.
    pub suction: f64,
    /// Where $a|\ddot\alpha| = g$ along $\alpha^3 = K\tau$, $K = 24I\eta a/km$:
    /// $\alpha^5 = (2/9)K^2 a/g$ (rad); below it the disk leaves the table.
    pub contact: f64,
    /// Where the reduced Reynolds number $\Omega a^2\alpha^2/\nu$ is 1 (rad); above it the air's
    /// inertia counts.
    pub inertia: f64,
}

impl Window {
    /// The window for `disk` in air of viscosity `eta` (Pa s), kinematic viscosity `nu`
    /// (m^2/s) and pressure `p_atm` (Pa), with $\Omega^2 = g/(ak\alpha)$ (steady $b = 0$ motion
    /// at small tilt).
    pub fn of(film: SqueezeFilm, disk: &Disk, eta: f64, nu: f64, p_atm: f64) -> Self {
        let (a, k, g, m) = (disk.a, disk.k, disk.g, disk.m);
        let omega_scale = (g / (a * k)).sqrt(); // Omega = omega_scale alpha^(-1/2)
        let rate = 24.0 * film.coefficient * eta * a / (k * m);
        Self {
            suction: (12.0 * eta * omega_scale / p_atm).powf(0.4),
            contact: (2.0 / 9.0 * rate * rate * a / g).powf(0.2),
            inertia: (nu / (omega_scale * a * a)).powf(2.0 / 3.0),
        }
    }

    /// The lowest tilt of the window (rad).
    pub fn low(&self) -> f64 {
        self.suction.max(self.contact)
    }

    /// True when some tilt satisfies all three conditions.
    pub fn is_open(&self) -> bool {
        self.low() < self.inertia
    }
}

/// $I$ by cell-centred finite volumes on the half disk $0 < \theta < \pi$ ($P$ is odd in
/// $\rho_\perp$, so $P = 0$ on the diameter), `nr` radial cells and `2 nr` angular ones, with
/// $\hat{\mathbf e} = \hat{\mathbf x}$, so $H = 1 - \rho\cos\theta$.
pub fn dissipation_number(nr: usize) -> f64 {
    film_number(nr, &|r, t| (1.0 - r * t.cos()).powi(3))
}

/// $\int P\rho_\perp dA$ where $\nabla\cdot(G\nabla P) = -\rho_\perp$ on the unit disk, $P = 0$ on
/// its edge, for a film conductance $G(\rho, \theta) = H^3$ given by `conductance`. The
/// five-point system is symmetric positive definite (a Dirichlet edge); it is factored
/// (Cholesky) with the angle as the outer index, which keeps its band `nr` wide.
fn film_number(nr: usize, conductance: &dyn Fn(f64, f64) -> f64) -> f64 {
    let nt = 2 * nr;
    let (dr, dt) = (1.0 / nr as f64, PI / nt as f64);
    let index = |i: usize, j: usize| j * nr + i;
    let n = nr * nt;
    let mut coo = CooMatrix::new(n, n);
    let mut load = DVector::zeros(n);
    for j in 0..nt {
        let t = (j as f64 + 0.5) * dt;
        for i in 0..nr {
            let r = (i as f64 + 0.5) * dr;
            let p = index(i, j);
            let mut diagonal = 0.0;
            // Outer radial face: a neighbour, or the rim (P = 0 half a cell away).
            let outer = r + 0.5 * dr;
            if i + 1 < nr {
                let c = conductance(outer, t) * outer * dt / dr;
                coo.push(p, index(i + 1, j), -c);
                diagonal += c;
            } else {
                diagonal += conductance(outer, t) * outer * dt / (0.5 * dr);
            }
            if i > 0 {
                let inner = r - 0.5 * dr;
                let c = conductance(inner, t) * inner * dt / dr;
                coo.push(p, index(i - 1, j), -c);
                diagonal += c;
            }
            // Angular faces: a neighbour, or the diameter (P = 0 half a cell away).
            let faces = [
                (-1.0, j.checked_sub(1)),
                (1.0, Some(j + 1).filter(|&q| q < nt)),
            ];
            for (side, face) in faces {
                let tf = t + side * 0.5 * dt;
                match face {
                    Some(q) => {
                        let c = conductance(r, tf) * dr / (r * dt);
                        coo.push(p, index(i, q), -c);
                        diagonal += c;
                    }
                    None => diagonal += conductance(r, tf) * dr / (r * 0.5 * dt),
                }
            }
            coo.push(p, p, diagonal);
            load[p] = r * t.sin() * r * dr * dt;
        }
    }
    match CscCholesky::factor(&CscMatrix::from(&coo)) {
        // Both halves of the disk contribute alike.
        Ok(chol) => 2.0 * load.dot(&chol.solve(&load).column(0)),
        // Symmetric, diagonally dominant, with a Dirichlet edge: positive definite for every
        // nr >= 1, so this is unreachable; NaN makes any check that uses it fail.
        Err(_) => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_finite_volumes_converge_from_above_at_first_order() {
        let i: Vec<f64> = [12, 24, 48]
            .iter()
            .map(|&n| dissipation_number(n))
            .collect();
        assert!(i[0] > i[1] && i[1] > i[2], "{i:?}");
        // First order: successive differences halve (ratio within 0.35-0.65).
        let ratio = (i[1] - i[2]) / (i[0] - i[1]);
        assert!((0.35..0.65).contains(&ratio), "{i:?}, ratio {ratio}");
    }

    #[test]
    fn the_number_lies_between_the_finest_bound_and_the_finite_volumes() {
        let film = SqueezeFilm::solved();
        let number = film_bound::extrapolated(COARSEST);
        // Below: the conforming elements' bound on the finest grid. Above: the finite volumes
        // on 48 radial cells, which approach from above.
        assert!(number.lower_bound < film.coefficient, "{number:?}");
        assert!(film.coefficient < dissipation_number(48), "{film:?}");
        // What a cache keeps is `computed`'s value: the process's own to the bit.
        assert_eq!(SqueezeFilm::computed(), film);
        assert_eq!(number.estimate.to_bits(), film.coefficient.to_bits());
        // Five digits: the extrapolation moved by less than 1e-5 between the grid pairs.
        assert!(film.uncertainty < 1e-5, "{film:?}");
        assert!((1.9..2.1).contains(&number.observed_order), "{number:?}");
        // A referee's own solution of the same film (quoted in the project's issue on verdicts
        // a referee can sign): I = 0.106762 +- 0.000002.
        let referee: f64 = 0.106762;
        assert!(
            (film.coefficient - referee).abs() < film.uncertainty + 2e-6,
            "{film:?}"
        );
    }

    /// The next finer grid (512 cells) confirms the stated uncertainty: its extrapolation lies
    /// within it.
    #[test]
    #[ignore = "slow: the 512-cell grid, about 5 s"]
    fn a_finer_grid_stays_within_the_stated_uncertainty() {
        let film = SqueezeFilm::solved();
        let finer = film_bound::extrapolated(2 * COARSEST);
        println!("{film:?}\n{finer:?}");
        assert!(
            (finer.estimate - film.coefficient).abs() < film.uncertainty,
            "{film:?} {finer:?}"
        );
        assert!(finer.lower_bound < film.coefficient, "{finer:?}");
    }

    #[test]
    fn the_toy_disks_window_is_open_and_its_edges_are_where_their_conditions_turn() {
        let film = SqueezeFilm::solved();
        let toy = Disk {
            a: 0.0375,
            k: 0.25,
            m: 0.4,
            g: 9.81,
        };
        let w = Window::of(film, &toy, 1.8e-5, 1.5e-5, 101_325.0);
        assert!(w.is_open(), "{w:?}");
        let omega = |alpha: f64| (toy.g / (toy.a * toy.k * alpha)).sqrt();
        // At each edge its own condition is met with equality.
        let suction = 12.0 * 1.8e-5 * omega(w.suction) / (w.suction * w.suction);
        assert!((suction / 101_325.0 - 1.0).abs() < 1e-12, "{suction}");
        let reynolds = omega(w.inertia) * toy.a * toy.a * w.inertia * w.inertia / 1.5e-5;
        assert!((reynolds - 1.0).abs() < 1e-12, "{reynolds}");
        // alpha = (K tau)^(1/3): a |alpha''| = (2/9) a K^2 / alpha^5 = g at the contact edge.
        let k_rate = 24.0 * film.coefficient * 1.8e-5 * toy.a / (toy.k * toy.m);
        let accel = 2.0 / 9.0 * toy.a * k_rate * k_rate / w.contact.powi(5);
        assert!((accel / toy.g - 1.0).abs() < 1e-12, "{accel}");
    }

    #[test]
    fn a_parallel_gap_has_its_closed_form() {
        // With H = 1 the problem is lap P = -y on the unit disk: P = y (1 - r^2)/8, and
        // I = int y P dA = (1/8) int_0^1 int r^2 sin^2(theta) (1 - r^2) r dr dtheta = pi/96.
        let i = film_number(64, &|_, _| 1.0);
        assert!((i / (PI / 96.0) - 1.0).abs() < 1e-3, "{i}");
    }
}
