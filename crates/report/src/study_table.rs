//! A study's section as the report prints it, in the form of a paper: a paragraph of what was
//! run and found, numbered tables with captions (each column headed by its quantity and unit,
//! each cell written by [`crate::number`]), its figures by number, and the full program output
//! only behind a disclosure (HTML) or in the appendix (LaTeX).

use serde::Serialize;

/// One study's section: the same parts for every study, rendered by the same template
/// partials (`templates/partials/study_section.*`).
#[derive(Debug, Clone, Serialize)]
pub struct StudySection {
    /// Its heading.
    pub title: String,
    /// What was run and found, in a paragraph that cites its tables and figures by number.
    pub summary: String,
    /// Its numbers.
    pub tables: Vec<StudyTable>,
    /// The full program output, for the disclosure and the appendix.
    pub output: String,
    /// What the output holds, in a phrase (the disclosure's summary).
    pub output_title: String,
}

/// Numbers the tables of `sections`, in the order they are given (the report's), from 1; returns
/// the next free number.
pub fn number_tables<'a>(sections: impl IntoIterator<Item = &'a mut Vec<StudyTable>>) -> usize {
    let mut next = 1;
    for tables in sections {
        for t in tables.iter_mut() {
            t.number = next;
            next += 1;
        }
    }
    next
}

/// "Table 3" or "Tables 2-7": how a paragraph cites `tables`.
pub fn cite(tables: &[StudyTable]) -> String {
    match tables {
        [] => String::new(),
        [t] => format!("Table {}", t.number),
        [first, .., last] => format!("Tables {}–{}", first.number, last.number),
    }
}

/// One table of a study.
#[derive(Debug, Clone, Serialize)]
pub struct StudyTable {
    /// Its number in the report (Table 1, Table 2, ..), the same in the HTML and the LaTeX.
    pub number: usize,
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
            number: 0,
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
