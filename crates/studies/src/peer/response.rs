//! The peer's response file for a scene: the answers to its prompts, one a line, in the order
//! of its manual launch mode (radius, height, fillet, density; the Euler angles in degrees; the
//! launch mode 0; $\omega_{1,2,3}$; the centre's velocity in frame (1); the static and kinetic
//! coefficients; the resistance lever arms over the radius in $x$, $y$, $z$; end time, print
//! step, relative and absolute tolerance). Comments after `#` name each line.

use super::mapping::PeerState;
use super::PeerError;
use physics::dispatch::sliding_model;
use physics::scene::Scene;

/// The peer's gravity, fixed in its source (m/s²).
pub const PEER_G: f64 = 9.8067;

/// The response file for `scene` (see the module documentation), or why the peer cannot run it.
///
/// The peer's mass comes from a density; it is set to $m/V$ with $V$ this tool's volume of the
/// solid. The peer uses its mass only for energies (its energy stop and report), its equations
/// being per unit mass.
pub fn response(scene: &Scene) -> Result<String, PeerError> {
    let refuse = |why: String| Err(PeerError::Scene(scene.source.clone(), why));
    if !scene.model.has_coulomb_friction() {
        return refuse(format!(
            "the peer integrates the disk with friction; this scene is model: {}: use model: sliding",
            scene.model
        ));
    }
    let Some(solid) = scene.toy.solid else {
        return refuse(
            "the peer's disk has a thickness (with none its mass and energy stop vanish): add \
             disk: { thickness: 2e-4 } for a nearly thin disk"
                .into(),
        );
    };
    if (scene.disk.g - PEER_G).abs() > 1e-12 {
        return refuse(format!(
            "the peer's gravity is fixed at {PEER_G} m/s^2: set disk: {{ g: {PEER_G} }}"
        ));
    }
    let Some(dt) = scene.sample else {
        return refuse("the peer writes its state every print step: add sample: 1e-3 (s)".into());
    };
    let m = sliding_model(scene);
    let (mu_s, mu_k) = (m.friction.mu, m.mu_kinetic());
    if mu_s > 1.0 {
        return refuse(format!(
            "the peer accepts friction coefficients up to 1, got {mu_s}: lower friction"
        ));
    }
    if m.friction.restitution != 0.0 {
        return refuse(
            "the peer has no flight and no impacts: set friction: { restitution: 0 }".into(),
        );
    }
    if scene.dissipation.is_some() {
        return refuse("the peer has no drag law: remove `dissipation`".into());
    }
    let a = scene.disk.a;
    let resistance = m.toy.resistance.unwrap_or_default();
    let st = &scene.start;
    let mut peer = PeerState::from_paper(st.alpha, st.alpha_dot, st.precession, st.spin, 0.0);
    let (p, q) = solid.offsets(a, st.alpha.cos(), st.alpha.sin());
    // e2 = -x1 (heading 0: e2 = (1, 0, 0)), r = y1 (module `mapping`).
    let slip = nalgebra::Vector3::new(scene.slip.forward, -scene.slip.sideways, 0.0);
    let v = peer.rolling_velocity(p, q, slip);
    peer.velocity = v;
    let deg = |x: f64| x.to_degrees();
    let lines: Vec<(String, &str)> = vec![
        (fmt(a), "Disk radius [m]"),
        (fmt(solid.thickness), "Disk height [m]"),
        (fmt(solid.fillet), "Disk fillet radius [m]"),
        (
            fmt(scene.disk.m / solid.volume),
            "Disk density [kg/m^3] (mass / volume)",
        ),
        (fmt(deg(peer.psi)), "Initial Z rotation psi [deg]"),
        (
            fmt(deg(peer.theta)),
            "Initial X rotation theta [deg] (90 - alpha)",
        ),
        (fmt(deg(peer.phi)), "Initial Y rotation phi [deg]"),
        ("0".into(), "Initial condition mode: manual"),
        (fmt(peer.omega[0]), "Omega1 [rad/s] (-alpha_dot)"),
        (fmt(peer.omega[1]), "Omega2 [rad/s] (-spin)"),
        (fmt(peer.omega[2]), "Omega3 [rad/s] (precession cos theta)"),
        (fmt(v[0]), "Centre velocity Vx [m/s] (frame 1)"),
        (fmt(v[1]), "Centre velocity Vy [m/s] (frame 1)"),
        (fmt(mu_s), "Static friction coefficient"),
        (fmt(mu_k), "Kinetic friction coefficient"),
        (
            "0".into(),
            "Rolling resistance x/R (tipping: not modelled here)",
        ),
        (fmt(resistance.rolling / a), "Rolling resistance y/R"),
        (fmt(resistance.boring / a), "Boring resistance z/R"),
        (fmt(scene.stop.time), "End time [s]"),
        (fmt(dt), "Print time step [s]"),
        (fmt(scene.settings.rtol), "Relative tolerance"),
        (fmt(scene.settings.atol), "Absolute tolerance"),
    ];
    let mut out = format!(
        "# Response file for M. Batista's Euler disk program, written by rolling-disk peer export\n\
         # from the scene {} ({}).\n",
        scene.name, scene.source
    );
    for (value, what) in lines {
        out.push_str(&format!("{value:<24} # {what}\n"));
    }
    Ok(out)
}

/// Shortest text that reads back to the same number.
fn fmt(x: f64) -> String {
    let s = format!("{x:e}");
    if s.parse::<f64>() == Ok(x) {
        s
    } else {
        format!("{x:.17e}")
    }
}
