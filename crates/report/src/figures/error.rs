//! What can go wrong drawing a figure.

use std::fmt::Display;

/// A figure that could not be made: the sentence says which and why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FigureError {
    /// The plotting backend failed (a font, a file, an area too small); plotters' message.
    #[error("{0}")]
    Draw(String),
    /// The results cannot make the figure (too few points, a missing column, a non-finite
    /// range), or a figure name or study is unknown or missing; the sentence names the figure.
    #[error("{0}")]
    Data(String),
}

/// `.drawn()` on a plotters result: its error as [`FigureError::Draw`].
pub trait Drawn<T> {
    /// The result with the backend's error turned into [`FigureError::Draw`].
    fn drawn(self) -> Result<T, FigureError>;
}

impl<T, E: Display> Drawn<T> for Result<T, E> {
    fn drawn(self) -> Result<T, FigureError> {
        self.map_err(|e| FigureError::Draw(e.to_string()))
    }
}

impl From<String> for FigureError {
    fn from(s: String) -> Self {
        FigureError::Data(s)
    }
}

impl From<&str> for FigureError {
    fn from(s: &str) -> Self {
        FigureError::Data(s.to_string())
    }
}

/// The layers above still speak in sentences: a figure's error is its sentence.
impl From<FigureError> for String {
    fn from(e: FigureError) -> Self {
        e.to_string()
    }
}
