//! Eqs 1-11: the triad, the tilt and the rates, against the triad built from the rotation.

use super::rolling::A;
use super::{
    at, identity, kin1, kin_bindings, printed_kinematics, printed_relations, rate_scale, sample,
    Bench, Finding, Kin, Stated, Value, Worst, POINTS, RATE, THREE, V,
};

/// A printed identity of eqs 1-7 and 9-11 and what it is compared with: its relations at
/// random states of the rotation (`sample`), the symbols bound to the triad CONSTRUCTED from
/// that rotation, each difference measured against `scale` (a length or a rate of the state).
struct Identity {
    number: u32,
    scale: fn(&Kin<f64>) -> f64,
    quantity: &'static str,
    stated: Stated,
    reference: &'static str,
}

/// The identities, one row each, with the equation's printed form and its reference.
#[rustfmt::skip]
const IDENTITIES: &[Identity] = &[
    // Eq 1, $\mathbf a = a\hat{\mathbf 3}$ (definition): the offset of the contact point from the
    // centre. Reference: the lowest point of the rim, found in body coordinates, against $a$ times
    // the constructed $\hat{\mathbf 3}$.
    Identity { number: 1, scale: |_| A, quantity: "$\\mathbf{a}$", stated: Stated::Definition, reference: "the printed $\\mathbf{a}$ against the offset of the rim's lowest point (body coordinates)" },
    // Eq 2, $\vec\omega = \vec\omega_{123} + \omega_{rel}\hat{\mathbf 1}$ (definition). Reference:
    // the disk's angular velocity from $\dot R R^T$, the triad's from $\dot T T^T$, and the measured
    // rate of a face mark relative to the triad.
    Identity { number: 2, scale: rate_scale, quantity: "$\\vec\\omega$", stated: Stated::Definition, reference: "the printed composition of $\\vec\\omega$ against the axial vector of $\\dot R R^{T}$" },
    // Eq 3, $\vec\omega_{123} = \Omega\hat{\mathbf z} + \dot\alpha\hat{\mathbf 2} =
    // -\Omega\cos\alpha\hat{\mathbf 1} + \dot\alpha\hat{\mathbf 2} - \Omega\sin\alpha\hat{\mathbf 3}$.
    // Reference: the triad's angular velocity from $\dot T T^T$; each printed equality in turn.
    Identity { number: 3, scale: rate_scale, quantity: "$\\vec\\omega_{123}$", stated: Stated::Relation, reference: "both printed equalities for $\\vec\\omega_{123}$ against the axial vector of $\\dot T T^{T}$" },
    // Eq 4, $\hat{\mathbf z} = -\cos\alpha\hat{\mathbf 1} - \sin\alpha\hat{\mathbf 3}$. Reference:
    // the lab's vertical; $\alpha$ is the disk plane's tilt (the nutation angle).
    Identity { number: 4, scale: |_| 1.0, quantity: "$\\hat{\\mathbf{z}}$", stated: Stated::Relation, reference: "the printed $\\hat{\\mathbf{z}}$ against the lab's vertical" },
    // Eq 5, $d\hat{\mathbf 1}/dt = \vec\omega_{123}\times\hat{\mathbf 1} = -\Omega\sin\alpha
    // \hat{\mathbf 2} - \dot\alpha\hat{\mathbf 3}$. Reference: the exact derivative of the
    // constructed axis and the measured $\vec\omega_{123}$.
    Identity { number: 5, scale: rate_scale, quantity: "the axis' rate", stated: Stated::Relation, reference: "$d\\hat{\\mathbf{1}}/dt$, both printed equalities, against the exact derivative" },
    // Eq 6, $d\hat{\mathbf 2}/dt = \vec\omega_{123}\times\hat{\mathbf 2} = \Omega\sin\alpha
    // \hat{\mathbf 1} - \Omega\cos\alpha\hat{\mathbf 3} = -\Omega\hat{\mathbf r}$ (the printed stray
    // comma dropped). Reference: the exact derivative of the constructed axis.
    Identity { number: 6, scale: rate_scale, quantity: "the axis' rate", stated: Stated::Relation, reference: "$d\\hat{\\mathbf{2}}/dt$, all three printed equalities, against the exact derivative" },
    // Eq 7, $d\hat{\mathbf 3}/dt = \vec\omega_{123}\times\hat{\mathbf 3} = \dot\alpha\hat{\mathbf 1}
    // + \Omega\cos\alpha\hat{\mathbf 2}$. Reference: the exact derivative of the constructed axis.
    Identity { number: 7, scale: rate_scale, quantity: "the axis' rate", stated: Stated::Relation, reference: "$d\\hat{\\mathbf{3}}/dt$, both printed equalities, against the exact derivative" },
    // Eq 9, $d\hat{\mathbf r}/dt = \Omega\hat{\mathbf 2}$. Reference: the exact derivative of the
    // constructed $\hat{\mathbf r}$.
    Identity { number: 9, scale: rate_scale, quantity: "$\\hat{\\mathbf{r}}$'s rate", stated: Stated::Relation, reference: "the printed rate of $\\hat{\\mathbf{r}}$ against its exact derivative" },
    // Eq 10, $\vec\omega = \omega_1\hat{\mathbf 1} + \dot\alpha\hat{\mathbf 2} -
    // \Omega\sin\alpha\hat{\mathbf 3}$, with $\omega_1 = \vec\omega\cdot\hat{\mathbf 1}$. Reference:
    // the axial vector of $\dot R R^T$ (the 2 and 3 components are the content).
    Identity { number: 10, scale: rate_scale, quantity: "$\\vec\\omega$", stated: Stated::Relation, reference: "the printed triad form of $\\vec\\omega$ against $\\dot R R^{T}$" },
    // Eq 11, $\omega_1 = \omega_{rel} - \Omega\cos\alpha$ (definition). Reference: $\vec\omega\cdot
    // \hat{\mathbf 1}$ from $\dot R R^T$, the measured rate of a face mark relative to the triad and
    // the measured precession.
    Identity { number: 11, scale: rate_scale, quantity: "$\\omega_1$", stated: Stated::Definition, reference: "the printed $\\omega_1$ against $\\vec\\omega \\cdot \\hat{\\mathbf{1}}$ from $\\dot R R^{T}$" },
];

/// The check of eq `N`, one of [`IDENTITIES`].
pub(super) fn identity_check<const N: u32>(b: &Bench) -> Finding {
    let row = IDENTITIES
        .iter()
        .find(|r| r.number == N)
        .expect("every identity check is registered for a row of IDENTITIES");
    let w = printed_kinematics(b, N, u64::from(N), row.scale, row.quantity);
    identity(row.reference, w, row.stated)
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
        printed_relations(b, 8, &bind, 1.0, &mut w, &|| at(&k, r"$\hat{\mathbf{r}}$"));
    }
    identity(
        "the printed $\\hat{\\mathbf{r}}$ against $\\hat{\\mathbf{3}}$'s horizontal direction and $\\hat{\\mathbf{2}} \\times \\hat{\\mathbf{z}}$",
        w,
        Stated::Definition,
    )
}

// ------------------------------------------------------------------------------------------
// Eqs 12-17: rolling without slipping
// ------------------------------------------------------------------------------------------
