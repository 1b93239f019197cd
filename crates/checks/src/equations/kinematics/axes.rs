//! Eqs 1-11: the triad, the tilt and the rates, against the triad built from the rotation.

use super::rolling::A;
use super::{
    at, identity, kin1, kin_bindings, printed_kinematics, printed_relations, rate_scale, sample,
    Bench, Finding, Stated, Value, Worst, POINTS, RATE, THREE, V,
};

/// Eq 1, $\mathbf a = a\hat{\mathbf 3}$ (definition): the offset of the contact point from the
/// centre. Reference: the lowest point of the rim, found in body coordinates, against $a$ times
/// the constructed $\hat{\mathbf 3}$.
pub(super) fn eq1(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 1, 1, |_| A, "a");
    identity(
        "the printed a against the offset of the rim's lowest point (body coordinates)",
        w,
        Stated::Definition,
    )
}

/// Eq 2, $\vec\omega = \vec\omega_{123} + \omega_{rel}\hat{\mathbf 1}$ (definition). Reference:
/// the disk's angular velocity from $\dot R R^T$, the triad's from $\dot T T^T$, and the measured
/// rate of a face mark relative to the triad.
pub(super) fn eq2(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 2, 2, rate_scale, "omega");
    identity(
        "the printed composition of omega against the axial vector of dR/dt R^T",
        w,
        Stated::Definition,
    )
}

/// Eq 3, $\vec\omega_{123} = \Omega\hat{\mathbf z} + \dot\alpha\hat{\mathbf 2} =
/// -\Omega\cos\alpha\hat{\mathbf 1} + \dot\alpha\hat{\mathbf 2} - \Omega\sin\alpha\hat{\mathbf 3}$.
/// Reference: the triad's angular velocity from $\dot T T^T$; each printed equality in turn.
pub(super) fn eq3(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 3, 3, rate_scale, "omega_123");
    identity(
        "both printed equalities for omega_123 against the axial vector of dT/dt T^T",
        w,
        Stated::Relation,
    )
}

/// Eq 4, $\hat{\mathbf z} = -\cos\alpha\hat{\mathbf 1} - \sin\alpha\hat{\mathbf 3}$. Reference:
/// the lab's vertical; $\alpha$ is the disk plane's tilt (the nutation angle).
pub(super) fn eq4(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 4, 4, |_| 1.0, "z");
    identity(
        "the printed z against the lab's vertical",
        w,
        Stated::Relation,
    )
}

/// Eq 5, $d\hat{\mathbf 1}/dt = \vec\omega_{123}\times\hat{\mathbf 1} = -\Omega\sin\alpha
/// \hat{\mathbf 2} - \dot\alpha\hat{\mathbf 3}$. Reference: the exact derivative of the
/// constructed axis and the measured $\vec\omega_{123}$.
pub(super) fn eq5(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 5, 5, rate_scale, "the axis' rate");
    identity(
        "d1/dt, both printed equalities, against the exact derivative",
        w,
        Stated::Relation,
    )
}

/// Eq 6, $d\hat{\mathbf 2}/dt = \vec\omega_{123}\times\hat{\mathbf 2} = \Omega\sin\alpha
/// \hat{\mathbf 1} - \Omega\cos\alpha\hat{\mathbf 3} = -\Omega\hat{\mathbf r}$ (the printed stray
/// comma dropped). Reference: the exact derivative of the constructed axis.
pub(super) fn eq6(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 6, 6, rate_scale, "the axis' rate");
    identity(
        "d2/dt, all three printed equalities, against the exact derivative",
        w,
        Stated::Relation,
    )
}

/// Eq 7, $d\hat{\mathbf 3}/dt = \vec\omega_{123}\times\hat{\mathbf 3} = \dot\alpha\hat{\mathbf 1}
/// + \Omega\cos\alpha\hat{\mathbf 2}$. Reference: the exact derivative of the constructed axis.
pub(super) fn eq7(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 7, 7, rate_scale, "the axis' rate");
    identity(
        "d3/dt, both printed equalities, against the exact derivative",
        w,
        Stated::Relation,
    )
}

/// Eq 8, $\hat{\mathbf r} = \hat{\mathbf 2}\times\hat{\mathbf z} = -\sin\alpha\hat{\mathbf 1} +
/// \cos\alpha\hat{\mathbf 3}$ (definition). Reference: where the disk leans with axis 1 below the
/// horizontal ($\cos\alpha > 0.1$), $\hat{\mathbf r}$ is bound to the horizontal direction of
/// $\hat{\mathbf 3}$ (figure 1's $\hat{\mathbf r}$ points from the centre's vertical towards the
/// contact point); elsewhere to the constructed $\hat{\mathbf 2}\times\hat{\mathbf z}$.
pub(super) fn eq8(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for (h, t) in sample(8, POINTS, RATE) {
        let k = kin1(&h, t);
        let mut bind = kin_bindings(&k);
        let t3 = k.axes[THREE];
        let horizontal = V::new(t3[0], t3[1], 0.0);
        if k.alpha.cos() > 0.1 {
            let dir = horizontal / horizontal.norm();
            bind.set("r_hat", Value::Vector(dir));
        }
        printed_relations(b, 8, &bind, 1.0, &mut w, &|| at(&k, "r-hat"));
    }
    identity(
        "the printed r-hat against 3's horizontal direction and 2 x z",
        w,
        Stated::Definition,
    )
}

/// Eq 9, $d\hat{\mathbf r}/dt = \Omega\hat{\mathbf 2}$. Reference: the exact derivative of the
/// constructed $\hat{\mathbf r}$.
pub(super) fn eq9(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 9, 9, rate_scale, "r-hat's rate");
    identity(
        "the printed rate of r-hat against its exact derivative",
        w,
        Stated::Relation,
    )
}

/// Eq 10, $\vec\omega = \omega_1\hat{\mathbf 1} + \dot\alpha\hat{\mathbf 2} -
/// \Omega\sin\alpha\hat{\mathbf 3}$, with $\omega_1 = \vec\omega\cdot\hat{\mathbf 1}$. Reference:
/// the axial vector of $\dot R R^T$ (the 2 and 3 components are the content).
pub(super) fn eq10(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 10, 10, rate_scale, "omega");
    identity(
        "the printed triad form of omega against dR/dt R^T",
        w,
        Stated::Relation,
    )
}

/// Eq 11, $\omega_1 = \omega_{rel} - \Omega\cos\alpha$ (definition). Reference: $\vec\omega\cdot
/// \hat{\mathbf 1}$ from $\dot R R^T$, the measured rate of a face mark relative to the triad and
/// the measured precession.
pub(super) fn eq11(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 11, 11, rate_scale, "omega_1");
    identity(
        "the printed omega_1 against omega . 1 from dR/dt R^T",
        w,
        Stated::Definition,
    )
}

// ------------------------------------------------------------------------------------------
// Eqs 12-17: rolling without slipping
// ------------------------------------------------------------------------------------------
