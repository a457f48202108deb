//! The built-in figure catalogue: the `configs/*.json` specs, embedded at build time, found by id
//! (the file name without `.json`).

include!(concat!(env!("OUT_DIR"), "/catalogue.rs"));

/// The id of a catalogue entry: its file name without `.json`.
fn id_of(name: &str) -> &str {
    name.strip_suffix(".json").unwrap_or(name)
}

/// The catalogue entry with id `id`: (file name, spec text).
pub fn find(id: &str) -> Option<(&'static str, &'static str)> {
    CATALOGUE
        .iter()
        .copied()
        .find(|(name, _)| id_of(name) == id)
}

/// Every catalogue id, in catalogue order.
pub fn ids() -> impl Iterator<Item = &'static str> {
    CATALOGUE.iter().map(|(name, _)| id_of(name))
}

/// `id<TAB>title` per catalogue entry, one line each (an untitled spec shows an empty title).
pub fn listing() -> String {
    CATALOGUE
        .iter()
        .map(|(name, text)| {
            let title = serde_json::from_str::<serde_json::Value>(text)
                .ok()
                .and_then(|spec| spec["title"].as_str().map(str::to_owned))
                .unwrap_or_default();
            format!("{}\t{title}\n", id_of(name))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entries_are_found_by_id_and_listed_with_their_titles() {
        let (name, text) = find("gtr-gamma").unwrap();
        assert_eq!(name, "gtr-gamma.json");
        assert!(text.contains("\"id\": \"gtr-gamma\""));
        assert!(find("gtr-gamma.json").is_none() && find("nope").is_none());
        let listing = listing();
        assert_eq!(listing.lines().count(), ids().count());
        assert!(
            listing
                .lines()
                .any(|l| l.starts_with("gtr-gamma\tGeneralized Trowbridge–Reitz"))
        );
    }
}
