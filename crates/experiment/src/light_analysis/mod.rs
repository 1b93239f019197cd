//! The light signal analysed by the paper's method: the trace cleaned ([`clean`]), each peak
//! timed by its half-height crossings ([`peak`], found along the record by [`peak_search`], with
//! the pulses' drifting shape removed by [`pulse_drift`]), the rates $\Omega_i$ and
//! $d\Omega_i/dt$ ([`rates`]), the fitting window ([`window`], with [`settings`]), an end the
//! record contradicts ([`early_end`]), and the whole analysis ([`analysis`]).

pub mod analysis;
pub mod clean;
pub mod early_end;
pub mod peak;
pub mod peak_search;
pub mod pulse_drift;
pub mod rates;
pub mod settings;
pub mod window;
