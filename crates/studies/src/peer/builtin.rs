//! A built-in scene as the peer can run it. The built-in sliding scenes are thin disks under
//! $g = 9.81$ m/s²; the peer's disk has a thickness, and its gravity is fixed in its source
//! ([`super::response::PEER_G`]). The mapping changes exactly two things and says so:
//! - $g$ becomes the peer's;
//! - a thin disk gets the nominal thickness [`NOMINAL_THICKNESS`] with no fillet, so its
//!   $I_{22}/ma^2$ is $\frac14 + t^2/12a^2$ ($\frac14 + 2.4\times10^{-6}$ for the 37.5 mm toy)
//!   and its rim's axial offset $t/2$.
//!
//! Everything else, the start included, is read from the scene's own YAML, so a start given as
//! a steady motion is that of the mapped disk. `peer export` and `peer compare` map a built-in
//! scene the same way; a scene from a file is never mapped.

use super::response::PEER_G;
use super::PeerError;
use physics::scene::Scene;

/// The thickness given to a thin built-in disk (m).
pub const NOMINAL_THICKNESS: f64 = 2e-4;

/// The scene the peer runs for `scene`, with a note for each value the mapping changed; the
/// scene itself, without notes, when it is not built in or needs no change.
pub fn for_peer(scene: &Scene) -> Result<(Scene, Vec<String>), PeerError> {
    let Some(name) = scene.source.strip_prefix("builtin:") else {
        return Ok((scene.clone(), Vec::new()));
    };
    let Some(&(_, text)) = physics::scene::builtin::BUILTIN
        .iter()
        .find(|(n, _)| *n == name)
    else {
        return Ok((scene.clone(), Vec::new()));
    };
    if !scene.model.has_coulomb_friction() {
        // Refused by the response file with its reason; nothing to map.
        return Ok((scene.clone(), Vec::new()));
    }
    let fail = |why: String| PeerError::Scene(scene.source.clone(), why);
    let d = &scene.disk;
    let mut notes = Vec::new();
    if (d.g - PEER_G).abs() > 1e-12 {
        notes.push(format!(
            "g {} -> {PEER_G} m/s^2, the peer's (fixed in its source)",
            d.g
        ));
    }
    let disk = match scene.toy.solid {
        Some(_) => None,
        None => {
            notes.push(format!(
                "a nominal thickness of {NOMINAL_THICKNESS} m for the thin disk, no fillet \
                 (I22/(m a^2) {} -> {:.7})",
                d.k,
                0.25 + NOMINAL_THICKNESS * NOMINAL_THICKNESS / (12.0 * d.a * d.a)
            ));
            Some(format!(
                "disk: {{ radius: {}, mass: {}, thickness: {NOMINAL_THICKNESS}, g: {PEER_G} }}",
                d.a, d.m
            ))
        }
    };
    if notes.is_empty() {
        return Ok((scene.clone(), notes));
    }
    // The built-in scenes write their disk on one line, `disk: { ... }`.
    let mut replaced = false;
    let mapped: Vec<String> = text
        .lines()
        .map(|l| match (l.starts_with("disk:"), &disk) {
            (true, Some(new)) => {
                replaced = true;
                new.clone()
            }
            (true, None) => {
                replaced = true;
                l.replacen(&format!("g: {}", d.g), &format!("g: {PEER_G}"), 1)
            }
            _ => l.to_string(),
        })
        .collect();
    if !replaced {
        return Err(fail(
            "its disk is not written on one line `disk: { ... }`".into(),
        ));
    }
    let source = format!("builtin:{name} (mapped for the peer)");
    let out =
        Scene::parse(&(mapped.join("\n") + "\n"), &source).map_err(|e| fail(e.to_string()))?;
    if (out.disk.g - PEER_G).abs() > 1e-12 || out.toy.solid.is_none() {
        return Err(fail("its disk line could not be mapped".into()));
    }
    Ok((out, notes))
}
