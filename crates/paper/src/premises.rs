//! The equations' `premises` as a graph: every premise a printed number from 1 to 85, and no
//! equation following, directly or through others, from itself. A refusal names the file, the
//! line of the `premises` key, the equation and a change that makes the list valid.

use super::{EquationEntry, PaperError};

/// The 1-based line of eq `number`'s `key` in the equations file `text`, or of its `number` key
/// when `key` is not found below it (a flow-style entry), or `None` when the entry is not found.
pub(crate) fn key_line(text: &str, number: u32, key: &str) -> Option<usize> {
    let mut entry_line = None;
    for (i, line) in text.lines().enumerate() {
        let t = line.trim_start().trim_start_matches('-').trim_start();
        if let Some(n) = t.strip_prefix("number:") {
            if entry_line.is_some() {
                break;
            }
            if n.trim().parse::<u32>().ok() == Some(number) {
                entry_line = Some(i + 1);
            }
            continue;
        }
        if entry_line.is_some() && t.starts_with(&format!("{key}:")) {
            return Some(i + 1);
        }
    }
    entry_line
}

/// `file:line` of eq `number`'s `premises`, or `file` alone when the line is not found.
fn located(file: &str, text: &str, number: u32) -> String {
    key_line(text, number, "premises").map_or(file.to_string(), |l| format!("{file}:{l}"))
}

/// Refuses a premise that is not a printed number (1 to 85) and a cycle of premises, naming the
/// `premises` line of the equation where the cycle closes and the entries to change.
pub(crate) fn check(entries: &[EquationEntry], text: &str, file: &str) -> Result<(), PaperError> {
    for e in entries {
        if let Some(&bad) = e.premises.iter().find(|p| !(1..=85).contains(*p)) {
            return Err(PaperError::Structure {
                file: located(file, text, e.number),
                message: format!(
                    "eq {}, key `premises`: {bad} is not an equation number; list the printed \
                     numbers (1 to 85) of the equations eq {} follows from, without {bad}",
                    e.number, e.number
                ),
            });
        }
    }
    let premises = |n: u32| -> &[u32] {
        entries
            .iter()
            .find(|e| e.number == n)
            .map_or(&[], |e| e.premises.as_slice())
    };
    if let Some(cycle) = first_cycle(&premises, entries.iter().map(|e| e.number)) {
        let last = cycle[cycle.len() - 2];
        let first = cycle[0];
        let path = cycle
            .iter()
            .map(|n| format!("eq {n}"))
            .collect::<Vec<_>>()
            .join(" -> ");
        let fix = if cycle.len() == 2 {
            format!("remove {first} from eq {first}'s `premises`")
        } else {
            format!(
                "remove {first} from eq {last}'s `premises`, or {} from eq {first}'s (line {})",
                cycle[1],
                key_line(text, first, "premises").map_or("?".into(), |l| l.to_string())
            )
        };
        return Err(PaperError::Structure {
            file: located(file, text, last),
            message: format!(
                "eq {last}, key `premises`: a cycle of premises ({path}): an equation cannot \
                 follow from itself; {fix}"
            ),
        });
    }
    Ok(())
}

/// The first cycle met by a depth-first walk from each of `numbers` in turn, as the path from
/// the equation where it starts back to that equation (`[76, 77, 76]`; `[76, 76]` for an
/// equation listing itself).
fn first_cycle<'a>(
    premises: &dyn Fn(u32) -> &'a [u32],
    numbers: impl Iterator<Item = u32>,
) -> Option<Vec<u32>> {
    // 1: on the current path; 2: finished, no cycle through it.
    let mut state = std::collections::BTreeMap::<u32, u8>::new();
    for start in numbers {
        if state.contains_key(&start) {
            continue;
        }
        // The path, each with the index of its next premise to visit.
        let mut path: Vec<(u32, usize)> = vec![(start, 0)];
        state.insert(start, 1);
        while let Some(&mut (n, ref mut next)) = path.last_mut() {
            let Some(&p) = premises(n).get(*next) else {
                state.insert(n, 2);
                path.pop();
                continue;
            };
            *next += 1;
            match state.get(&p) {
                Some(1) => {
                    let from = path.iter().position(|&(m, _)| m == p).unwrap_or(0);
                    let mut cycle: Vec<u32> = path[from..].iter().map(|&(m, _)| m).collect();
                    cycle.push(p);
                    return Some(cycle);
                }
                Some(_) => {}
                None => {
                    state.insert(p, 1);
                    path.push((p, 0));
                }
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::{first_cycle, key_line};

    fn graph<'a>(edges: &'a [(u32, &'static [u32])]) -> impl Fn(u32) -> &'static [u32] + 'a {
        move |n| edges.iter().find(|e| e.0 == n).map_or(&[][..], |e| e.1)
    }

    #[test]
    fn cycles_are_found_with_their_path_and_a_tree_has_none() {
        let two: &[(u32, &'static [u32])] = &[(76, &[31, 77]), (77, &[76]), (31, &[])];
        assert_eq!(
            first_cycle(&graph(two), [76, 77, 31].into_iter()),
            Some(vec![76, 77, 76])
        );
        let own: &[(u32, &'static [u32])] = &[(5, &[5])];
        assert_eq!(first_cycle(&graph(own), [5].into_iter()), Some(vec![5, 5]));
        let three: &[(u32, &'static [u32])] = &[(1, &[2]), (2, &[3]), (3, &[1])];
        assert_eq!(
            first_cycle(&graph(three), [2].into_iter()),
            Some(vec![2, 3, 1, 2])
        );
        // A premise with a larger number, and two paths to one premise, are no cycle.
        let tree: &[(u32, &'static [u32])] = &[(3, &[4]), (5, &[3, 4]), (4, &[])];
        assert_eq!(first_cycle(&graph(tree), [3, 4, 5].into_iter()), None);
    }

    #[test]
    fn the_line_of_a_key_is_that_of_its_entry() {
        let text = "- number: 1\n  premises: []\n- number: 2\n  label: e2\n  premises: [1]\n";
        assert_eq!(key_line(text, 2, "premises"), Some(5));
        assert_eq!(key_line(text, 1, "premises"), Some(2));
        assert_eq!(key_line(text, 3, "premises"), None);
        // A flow-style entry: the line of its number.
        assert_eq!(
            key_line("- {number: 4, premises: [9]}\n", 4, "premises"),
            None
        );
    }
}
