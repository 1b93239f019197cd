//! The models a scene can name, and what each supports. Every question of the form "does this
//! model take a friction law, conserve energy, live in lab coordinates?" is answered here, so a
//! new model is its file in `model/`, its variant and answers here, and its arm in
//! [`crate::dispatch::dispatch`]; no other code matches on the kind.

use serde::{Deserialize, Serialize};
use std::fmt;

/// The model a scene integrates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ModelKind {
    /// Rolling without slipping, eqs 23-25.
    Rolling,
    /// No friction at the contact, eqs 60-62.
    Frictionless,
    /// Rolling with the power-law dissipation of eq 75 as a torque.
    Dissipative,
    /// The paper's one-state spin-down law, eq 76.
    Adiabatic,
    /// The independent Newton-Euler model in lab coordinates, rolling without slipping.
    LabFrame,
    /// The independent Newton-Euler model in lab coordinates, without friction.
    LabFrameFrictionless,
    /// The lab-frame model with Coulomb friction, stick/slip and flight.
    Sliding,
}

impl ModelKind {
    /// Every model, in the order the docs list them.
    pub const ALL: [ModelKind; 7] = [
        ModelKind::Rolling,
        ModelKind::Frictionless,
        ModelKind::Dissipative,
        ModelKind::Adiabatic,
        ModelKind::LabFrame,
        ModelKind::LabFrameFrictionless,
        ModelKind::Sliding,
    ];

    /// The name a scene's `model:` takes.
    pub fn name(self) -> &'static str {
        match self {
            ModelKind::Rolling => "rolling",
            ModelKind::Frictionless => "frictionless",
            ModelKind::Dissipative => "dissipative",
            ModelKind::Adiabatic => "adiabatic",
            ModelKind::LabFrame => "lab-frame",
            ModelKind::LabFrameFrictionless => "lab-frame-frictionless",
            ModelKind::Sliding => "sliding",
        }
    }

    /// Coulomb friction at the contact, with stick, slip and flight: the model takes a friction
    /// law and a start slip, and reports its switches of contact.
    pub fn has_coulomb_friction(self) -> bool {
        self == ModelKind::Sliding
    }

    /// No friction at all at the contact: its contact point slides freely.
    pub fn is_frictionless(self) -> bool {
        matches!(
            self,
            ModelKind::Frictionless | ModelKind::LabFrameFrictionless
        )
    }

    /// The energy is a constant of the motion (no dissipation of any kind), so a run may be
    /// projected onto its level.
    pub fn conserves_energy(self) -> bool {
        matches!(
            self,
            ModelKind::Rolling
                | ModelKind::Frictionless
                | ModelKind::LabFrame
                | ModelKind::LabFrameFrictionless
        )
    }

    /// The model takes eq 75's power law (as a torque, as the spin-down law itself, or as a drag
    /// beside friction).
    pub fn takes_dissipation_law(self) -> bool {
        matches!(
            self,
            ModelKind::Dissipative | ModelKind::Adiabatic | ModelKind::Sliding
        )
    }

    /// The model is eq 76's one-state spin-down law, with no tilt or angles of its own.
    pub fn is_spin_down_law(self) -> bool {
        self == ModelKind::Adiabatic
    }

    /// The model integrates the disk in lab coordinates, so it knows the contact point's motion.
    pub fn is_lab_frame(self) -> bool {
        matches!(
            self,
            ModelKind::LabFrame | ModelKind::LabFrameFrictionless | ModelKind::Sliding
        )
    }

    /// The disk spins down through a whole motion to its end (eq 75's law acting on the full
    /// state): what the experiment's synthetic records need.
    pub fn spins_down_in_motion(self) -> bool {
        self.takes_dissipation_law() && !self.is_spin_down_law()
    }

    /// The independent lab-frame model that referees this one (the same contact, in lab
    /// coordinates), where there is one.
    pub fn lab_frame_referee(self) -> Option<ModelKind> {
        if !self.conserves_energy() {
            None
        } else if self.is_frictionless() {
            Some(ModelKind::LabFrameFrictionless)
        } else {
            Some(ModelKind::LabFrame)
        }
    }
}

impl fmt::Display for ModelKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_model_reads_back_from_its_name() {
        for m in ModelKind::ALL {
            let read: ModelKind = serde_yaml::from_str(m.name()).unwrap();
            assert_eq!(read, m);
        }
    }

    #[test]
    fn a_referee_is_a_lab_frame_model_with_the_same_contact() {
        for m in ModelKind::ALL {
            if let Some(r) = m.lab_frame_referee() {
                assert!(r.is_lab_frame() && r.conserves_energy(), "{m} -> {r}");
                assert_eq!(r.is_frictionless(), m.is_frictionless(), "{m} -> {r}");
                assert_eq!(r.lab_frame_referee(), Some(r), "{r} referees itself");
            }
        }
        assert_eq!(ModelKind::Sliding.lab_frame_referee(), None);
        assert_eq!(ModelKind::Dissipative.lab_frame_referee(), None);
    }
}
