//! The name a user most likely meant: of the names a command knows (built-in scenes, figures,
//! claim ids), the nearest to a mistyped one in edit distance (strsim's Levenshtein), when it is
//! near enough to be what was meant: at most a third of its letters, and at least two, differ.

/// The first of `names` nearest to `name`, if near enough.
pub fn nearest<'n>(name: &str, names: impl IntoIterator<Item = &'n str>) -> Option<&'n str> {
    names
        .into_iter()
        .map(|n| (strsim::levenshtein(name, n), n))
        .min_by_key(|(d, _)| *d)
        .filter(|(d, _)| *d <= (name.len() / 3).max(2))
        .map(|(_, n)| n)
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_near_name_is_found_and_a_far_one_is_not() {
        let names = ["spinning-coin", "nutating-coin", "stability-map"];
        assert_eq!(super::nearest("spinning-con", names), Some("spinning-coin"));
        assert_eq!(super::nearest("stabilty-map", names), Some("stability-map"));
        assert_eq!(super::nearest("zzzzzzzzzzzz", names), None);
    }
}
