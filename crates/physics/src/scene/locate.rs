//! Finding the line of a key in a scene file, so that errors found after parsing (a negative
//! radius, an impossible steady motion) can still name the line to change.

/// The 1-based line of the key at `path` (e.g. `["disk", "k"]`) in YAML `source`, block or
/// flow style, found by looking for each key in turn after the previous one. `None` when absent.
pub fn line_of(source: &str, path: &[&str]) -> Option<usize> {
    let lines: Vec<&str> = source.lines().collect();
    let (mut line, mut col) = (0usize, 0usize);
    for key in path {
        let (l, c) = find_key(&lines, line, col, key)?;
        line = l;
        col = c + key.len();
    }
    Some(line + 1)
}

/// The first occurrence of `key:` as a whole key at or after (`line`, `col`), skipping comments.
fn find_key(lines: &[&str], line: usize, col: usize, key: &str) -> Option<(usize, usize)> {
    for (i, text) in lines.iter().enumerate().skip(line) {
        let code = text.split('#').next().unwrap_or("");
        let start = if i == line { col.min(code.len()) } else { 0 };
        let mut from = start;
        while let Some(off) = code.get(from..).and_then(|s| s.find(key)) {
            let at = from + off;
            let before = code[..at].chars().next_back();
            let after = code[at + key.len()..].trim_start().chars().next();
            let starts_key = before.is_none_or(|c| c == ' ' || c == '{' || c == ',' || c == '-');
            if starts_key && after == Some(':') {
                return Some((i, at));
            }
            from = at + key.len();
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_keys_in_block_and_flow_style() {
        let src = "name: x\n# k: not this\ndisk: { radius: 0.1, k: 0.25 }\nstart:\n  steady:\n    alpha0: 0.3\n    b: 0\nstop: { time: 1 }\n";
        assert_eq!(line_of(src, &["disk", "k"]), Some(3));
        assert_eq!(line_of(src, &["disk", "radius"]), Some(3));
        assert_eq!(line_of(src, &["start", "steady", "b"]), Some(7));
        assert_eq!(line_of(src, &["stop", "time"]), Some(8));
        assert_eq!(line_of(src, &["solver"]), None);
    }
}
