//! A text recording's cells and units, as every layout writes them: a line split into its cells
//! (whatever the separator), the unit a header cell names, and the factors of time and signal
//! units to seconds and volts. The plain CSV reader ([`super::csv`]) and the instruments'
//! layouts ([`super::scope_layout`]) both read with them.

/// The cells of a line, split at semicolons, else commas, else tabs, else runs of spaces (a
/// line with semicolons is split at them: its commas are decimal commas); each cell's
/// surrounding double quotes dropped (`"time_s"`); empty cells at the end (trailing separators)
/// dropped.
pub(crate) fn cells(s: &str) -> Vec<&str> {
    fn unquote(c: &str) -> &str {
        let c = c.trim();
        c.strip_prefix('"')
            .and_then(|x| x.strip_suffix('"'))
            .unwrap_or(c)
            .trim()
    }
    let mut c: Vec<&str> = if s.contains(';') {
        s.split(';').map(unquote).collect()
    } else if s.contains(',') {
        s.split(',').map(unquote).collect()
    } else if s.contains('\t') {
        s.split('\t').map(unquote).collect()
    } else {
        s.split_whitespace().map(unquote).collect()
    };
    while c.last().is_some_and(|x| x.is_empty()) {
        c.pop();
    }
    c
}

/// The unit written in a header cell: in parentheses or brackets (`Time (ms)`, `CH1 [V]`), or
/// after the last `_` or `/` (`time_s`, `t/ms`); `None` when the cell names none.
pub(crate) fn header_unit(cell: &str) -> Option<&str> {
    let c = cell.trim();
    for (open, close) in [('(', ')'), ('[', ']')] {
        if let (Some(a), Some(b)) = (c.rfind(open), c.rfind(close)) {
            if a < b {
                return Some(c[a + 1..b].trim());
            }
        }
    }
    c.rfind(['_', '/']).map(|k| c[k + 1..].trim())
}

/// The factor to seconds of a time unit.
pub(crate) fn time_factor(unit: &str) -> Option<f64> {
    match unit {
        "s" | "sec" | "S" | "seconds" | "second" => Some(1.0),
        "ms" => Some(1e-3),
        "us" | "µs" | "μs" => Some(1e-6),
        "ns" => Some(1e-9),
        _ => None,
    }
}

/// The factor to volts of a signal unit; other units (counts, a.u.) are kept as they are: the
/// timing does not depend on the signal's scale.
pub(crate) fn signal_factor(unit: &str) -> f64 {
    match unit {
        "mV" => 1e-3,
        "uV" | "µV" | "μV" => 1e-6,
        "kV" => 1e3,
        _ => 1.0,
    }
}
