//! How deeply a scene file nests, measured before the YAML reader sees it.
//!
//! The YAML reader takes time that grows with the square of the nesting depth of flow
//! collections (`[[[[...]]]]`: 36 s for a 200 KB file), and a scene never needs more than four
//! levels. [`check`] scans the text once, in linear time, and reports the first place where the
//! depth passes [`MAX_DEPTH`], so that such a file is refused at once.

/// Deepest nesting a scene file may have (block indentation levels plus flow brackets).
pub const MAX_DEPTH: usize = 32;

/// `Err((line, column))`, both 1-based, of the first place deeper than [`MAX_DEPTH`].
pub fn check(src: &str) -> Result<(), (usize, usize)> {
    let mut indents: Vec<usize> = Vec::new();
    for (i, line) in src.lines().enumerate() {
        let body = line.trim_start_matches(' ');
        let indent = line.len() - body.len();
        if body.is_empty() || body.starts_with('#') {
            continue;
        }
        while indents.last().is_some_and(|&top| top >= indent) {
            indents.pop();
        }
        indents.push(indent);
        // "- - - x" opens one block sequence per dash on the same line.
        let dashes = body
            .split(' ')
            .take_while(|w| *w == "-")
            .count()
            .saturating_sub(1);
        if indents.len() + dashes > MAX_DEPTH {
            return Err((i + 1, indent + 1));
        }
    }
    let (mut depth, mut line, mut col) = (0usize, 1usize, 0usize);
    let (mut quote, mut comment, mut prev) = (None::<char>, false, '\n');
    for c in src.chars() {
        col += 1;
        if c == '\n' {
            line += 1;
            col = 0;
            comment = false;
            prev = c;
            continue;
        }
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if comment => {}
            None => match c {
                '#' if prev.is_whitespace() => comment = true,
                '"' | '\'' => quote = Some(c),
                '[' | '{' => {
                    depth += 1;
                    if depth > MAX_DEPTH {
                        return Err((line, col));
                    }
                }
                ']' | '}' => depth = depth.saturating_sub(1),
                _ => {}
            },
        }
        prev = c;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ordinary_scenes_pass_and_deep_ones_are_found_where_they_pass_the_limit() {
        for (_, src) in crate::scene::builtin::BUILTIN {
            assert_eq!(check(src), Ok(()));
        }
        let flow = format!("name: {}{}\n", "[".repeat(100_000), "]".repeat(100_000));
        assert_eq!(check(&flow), Err((1, 6 + MAX_DEPTH + 1)));
        let block: String = (0..40).map(|i| format!("{}k:\n", " ".repeat(i))).collect();
        assert_eq!(check(&block), Err((MAX_DEPTH + 1, MAX_DEPTH + 1)));
        let dashes = format!("record:\n{}x\n", "- ".repeat(50));
        assert!(check(&dashes).is_err());
        assert_eq!(
            check("name: '[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[['\n"),
            Ok(())
        );
    }
}
