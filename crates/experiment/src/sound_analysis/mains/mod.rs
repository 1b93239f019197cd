//! Mains hum in a sound recording: found and subtracted ([`hum`]), a line judged hum
//! ([`stands_out`]), a line's power under a window
//! ([`line_power`]), and the mains phase followed as the grid's frequency wanders ([`drift`]) on
//! all the lines of one grid at once ([`phase`]).

pub mod drift;
pub mod hum;
pub mod line_power;
pub mod phase;
pub mod stands_out;
