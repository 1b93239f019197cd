//! The synthetic experiment, where the truth is known: a spin-down ([`simulate`], or the sliding
//! model in [`sliding_record`], or one dissipation mechanism alone in [`mechanism_record`] and
//! side by side in [`mechanisms`]; or eq 79 exactly in [`law`]) seen through the light model
//! ([`light`], with its [`scope`]) or heard by a microphone ([`sound`]), with what a real
//! recording adds ([`artifacts`]); a phone's recording of a spin in a room, stereo, with
//! its filters, made apart from the analysis ([`phone_room`], with [`room_filters`]); and what
//! such a sound can tell at best, its Cramér-Rao bound ([`bound`]).

pub mod artifacts;
pub mod bound;
pub mod law;
pub mod light;
pub mod mechanism_record;
pub mod mechanisms;
pub mod phone_room;
pub mod room_filters;
pub mod scope;
pub mod simulate;
pub mod sliding_record;
pub mod sound;
