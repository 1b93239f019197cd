//! A study's numbers as the report prints them: a table with a caption, each column headed by
//! its quantity and unit, each cell already written by [`crate::number`] or the study's own
//! precision.

use serde::Serialize;

/// One table of a study.
#[derive(Debug, Clone, Serialize)]
pub struct StudyTable {
    /// What the table shows, in a sentence (units are in the column heads).
    pub caption: String,
    /// Each column's quantity and unit, as `tilt α₀ (rad)`.
    pub columns: Vec<String>,
    /// The rows, one cell per column.
    pub rows: Vec<Vec<String>>,
}

impl StudyTable {
    /// A table of `columns` with no rows yet.
    pub fn new(caption: impl Into<String>, columns: &[&str]) -> Self {
        Self {
            caption: caption.into(),
            columns: columns.iter().map(|c| c.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    /// Appends a row; it must have one cell per column.
    pub fn row(&mut self, cells: Vec<String>) {
        debug_assert_eq!(cells.len(), self.columns.len(), "{}", self.caption);
        self.rows.push(cells);
    }
}
