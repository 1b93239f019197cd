//! Reading the recordings, and writing the synthetic ones as files people use: the one door
//! through which a file is read ([`input`]), a scope's CSV ([`csv`], the instruments' layouts in
//! [`scope_layout`], the cells and units both read in [`cells`]), sound as WAV ([`wav`]) and
//! as every other format ([`recording`], with the MP4 edit list in [`mp4_edit`], the container told by content in [`container`] and the decoding both kinds of reader share in [`decoding`]), a long recording read in pieces
//! ([`long`], decimated as it is read by [`decimate`]), one channel at
//! its rate ([`channel`]), several mixed with their delays ([`stereo`]), and a synthetic sound encoded ([`sound_file`]).

pub mod cells;
pub mod channel;
pub mod container;
pub mod csv;
pub mod decimate;
pub mod decoding;
pub mod input;
pub mod long;
pub mod mp4_edit;
pub mod recording;
pub mod scope_layout;
pub mod sound_file;
pub mod stereo;
pub mod wav;
