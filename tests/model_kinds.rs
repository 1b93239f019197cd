//! What a model supports is answered in one place: `physics::scene::ModelKind`'s methods
//! (crates/physics/src/scene/model_kind.rs), and the one exhaustive dispatch
//! (crates/physics/src/dispatch.rs). Everywhere else asks those methods, so a new model is its
//! file, its variant with its answers, and its dispatch arm.

use super::architecture::{code_lines, rust_files, source_dirs};
use physics::scene::ModelKind;

/// The files allowed to match on the kind: the answers and the dispatch.
const MATCHING_ALLOWED: &[&str] = &["scene/model_kind.rs", "dispatch.rs"];

/// The lines of `text` that match on a model kind: a `matches!` naming one, or a match arm
/// (`ModelKind::X =>` or `ModelKind::X |`).
fn kind_matches(text: &str) -> Vec<usize> {
    code_lines(text)
        .into_iter()
        .filter(|(_, l)| {
            let l = l.trim();
            (l.contains("matches!") && l.contains("ModelKind::"))
                || (l.starts_with("ModelKind::") || l.starts_with("| ModelKind::"))
                    && (l.contains("=>") || l.trim_end().ends_with('|') || l.contains(" | "))
        })
        .map(|(n, _)| n)
        .collect()
}

#[test]
fn only_the_model_kind_and_the_dispatch_match_on_a_model() {
    let mut files = Vec::new();
    for d in source_dirs() {
        rust_files(&d, &mut files);
    }
    let mut found = Vec::new();
    for f in &files {
        let path = f.to_string_lossy().replace('\\', "/");
        if MATCHING_ALLOWED.iter().any(|a| path.ends_with(a)) {
            continue;
        }
        let text = std::fs::read_to_string(f).unwrap();
        for n in kind_matches(&text) {
            found.push(format!("{path}:{n}"));
        }
    }
    assert!(
        found.is_empty(),
        "these lines match on a model kind; ask a method of ModelKind instead \
         (crates/physics/src/scene/model_kind.rs): {found:?}"
    );
}

#[test]
fn the_rule_would_catch_a_scattered_match() {
    let planted = "fn f(m: ModelKind) -> bool {\n    matches!(m, ModelKind::Rolling | ModelKind::LabFrame)\n}\n";
    assert_eq!(kind_matches(planted), vec![2]);
    let arm = "match m {\n    ModelKind::Sliding => 1,\n    _ => 0,\n}\n";
    assert_eq!(kind_matches(arm), vec![2]);
    let naming = "return Err(absent(s, \"friction\", ModelKind::Sliding));\n";
    assert!(kind_matches(naming).is_empty());
}

#[test]
fn every_model_answers_consistently() {
    for m in ModelKind::ALL {
        // A model with Coulomb friction is neither frictionless nor energy-conserving.
        if m.has_coulomb_friction() {
            assert!(!m.is_frictionless() && !m.conserves_energy(), "{m}");
        }
        // What conserves energy takes no dissipation law.
        assert!(!(m.conserves_energy() && m.takes_dissipation_law()), "{m}");
        // Eq 76's law has no contact, so no lab coordinates.
        if m.is_spin_down_law() {
            assert!(!m.is_lab_frame() && m.takes_dissipation_law(), "{m}");
        }
    }
}
