//! The registry assembled from the catalogue and the rows.

use super::*;
use crate::finding::Verdict;

/// A toy check: what a new equation's check function would be.
fn toy_check(b: &Bench) -> Finding {
    let mut f = (kinematics::EQUATIONS[0].check)(b);
    f.at = "the toy equation".into();
    f
}

#[test]
fn a_toy_equation_is_registered_from_its_row() {
    // Step 1: its catalogue entry (number and label, as paper/equations.yaml gives them).
    let mut entries = catalogue();
    entries.push((86, "toy"));
    // Steps 2 and 3: its check function and one row in its section.
    let toy: &[Row] = &[row(86, toy_check)];
    let mut sections = SECTIONS.to_vec();
    sections.push(toy);
    let all = assemble(&entries, &sections).unwrap();
    let e = all.iter().find(|e| e.number == 86).unwrap();
    assert_eq!(e.label, "toy");
    assert_eq!((e.check)(&Bench::default()).at, "the toy equation");
    assert_eq!(all.len(), equations().len() + 1);
    // Without its row it is registered as unchecked, not silently checked by something else.
    let without = assemble(&entries, SECTIONS).unwrap();
    assert!(without.iter().all(|e| e.number != 86));
}

#[test]
fn a_row_without_an_entry_or_twice_is_refused() {
    let toy: &[Row] = &[row(86, toy_check)];
    let entries = catalogue();
    assert_eq!(
        assemble(&entries, &[SECTIONS, &[toy]].concat()).unwrap_err(),
        RegistryError::RowWithoutEntry(86)
    );
    let again: &[Row] = &[row(1, toy_check)];
    assert_eq!(
        assemble(&entries, &[SECTIONS, &[again]].concat()).unwrap_err(),
        RegistryError::TwoRows(1)
    );
}

#[test]
fn every_equation_of_the_catalogue_is_registered_and_read_from_its_latex() {
    let all = equations();
    let numbers: Vec<u32> = all.iter().map(|e| e.number).collect();
    assert_eq!(numbers, (1..=85).collect::<Vec<u32>>());
    assert_eq!(from_latex(), numbers);
    for e in &all {
        let entry = &built_in_paper().equation(e.number).entry;
        assert_eq!(e.label, entry.label);
    }
    // The registry runs its checks as registered: eq 1 is a consistent definition.
    assert_eq!(
        (all[0].check)(&Bench::default()).verdict,
        Verdict::Definition
    );
}

/// Each failing equation is recomputed under a choice of substance the paper leaves open (the
/// range or point of evaluation, the disk's k, the dissipation's form), not only a looser
/// tolerance: each alternative gives its own value, and each stays a failure (robust).
#[test]
fn the_failing_equations_have_a_substantive_alternative() {
    let all = equations();
    let substantive = [
        "the range of evaluation",
        "the point of evaluation",
        "k of the disk",
        "the dissipation's form",
    ];
    for n in [43, 72, 73, 76, 77, 78, 79, 84] {
        let e = all.iter().find(|e| e.number == n).unwrap();
        let f = (e.check)(&Bench::default());
        let own: Vec<_> = f
            .robustness
            .iter()
            .filter(|a| substantive.contains(&a.choice))
            .collect();
        assert!(
            own.len() >= 2,
            "eq {n}: {:?}",
            f.robustness
                .iter()
                .map(|a| &a.alternative)
                .collect::<Vec<_>>()
        );
        assert_eq!(f.verdict, Verdict::Fails, "eq {n} fails robustly: {own:?}");
        assert!(
            own.iter()
                .all(|a| a.verdict == Verdict::Fails && a.reference.is_finite()),
            "eq {n}: {own:?}"
        );
    }
}
