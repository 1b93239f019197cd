//! Files read and written by `rolling-disk`: reading with limits (a bounded size, a clear error
//! naming the file), and writing so that a reader never sees half a file or a mix of two runs.

pub mod atomic;
pub mod input;
pub mod inputs;
pub mod kept;
pub mod output;
pub mod output_file;
pub mod streamed;
pub mod temporary;
