//! The one check of a JSON object's keys: every key given twice, and every key the object does
//! not accept (with a "did you mean"), each reported at its JSON path.
//!
//! Curves (`curve`) and scenes (`scene::reader`) both check their objects here. It looks at keys
//! only: it never reads a value, decides what a document means, or does numerics.

use crate::problem::{MAX_PRINTED_PROBLEMS, Problem, join_key, suggestion};
use crate::spec::json::Node;

/// The keys an object accepts, for [`check`].
#[derive(Debug, Clone, Copy)]
pub struct Accepted<'a> {
    /// What the object is, for messages: `Some("a difference")` gives "unknown key for a
    /// difference", `None` gives "unknown key".
    pub object: Option<&'a str>,
    /// The accepted keys the message lists as expected and suggests from.
    pub listed: &'a [&'a str],
    /// Keys accepted without being listed (a curve's model key, read before its parameters).
    pub unlisted: &'a [&'a str],
}

impl Accepted<'_> {
    fn contains(&self, key: &str) -> bool {
        self.listed.contains(&key) || self.unlisted.contains(&key)
    }
}

/// The problems of an object's `members` at JSON path `path`, in document order: every repeated
/// key (at its second and later occurrences) as a duplicate, and, when `accepted` is given, every
/// other key outside it as unknown, `(got <value>, expected one of: <listed>)` plus a "did you
/// mean" when a listed key is near.
/// Linear in the number of members: the keys seen so far are kept in a hash set, and past the
/// [`MAX_PRINTED_PROBLEMS`] that can be printed an unknown key's message is only counted (it
/// skips the list and the "did you mean", a search of every accepted key).
pub fn validate(
    members: &[(String, Node)],
    path: &str,
    accepted: Option<&Accepted>,
) -> Vec<Problem> {
    let mut problems = Vec::new();
    let mut seen = std::collections::HashSet::with_capacity(members.len());
    for (key, value) in members {
        if !seen.insert(key.as_str()) {
            problems.push(Problem::new(join_key(path, key), duplicate_key(value)));
        } else if let Some(accepted) = accepted.filter(|a| !a.contains(key)) {
            if problems.len() >= MAX_PRINTED_PROBLEMS {
                problems.push(Problem::new(join_key(path, key), "unknown key".to_owned()));
                continue;
            }
            let object = accepted
                .object
                .map_or_else(String::new, |o| format!(" for {o}"));
            let expected = if accepted.listed.is_empty() {
                "no keys".to_string()
            } else {
                format!("one of: {}", accepted.listed.join(", "))
            };
            problems.push(Problem::new(
                join_key(path, key),
                format!(
                    "unknown key{object} (got {value}, expected {expected}){}",
                    suggestion(key, accepted.listed.iter().copied())
                ),
            ));
        }
    }
    problems
}

/// The message for a key given twice; `value` is the repeated key's value.
pub fn duplicate_key(value: &Node) -> String {
    format!("duplicate key (got a second value {value}, expected each key once)")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::json::{self, Value};

    fn members(text: &str) -> Vec<(String, Node)> {
        match json::parse(text).unwrap().value {
            Value::Object(members) => members,
            other => panic!("not an object: {other:?}"),
        }
    }

    #[test]
    fn reports_duplicates_and_unknown_keys_in_document_order() {
        let accepted = Accepted {
            object: Some("a thing"),
            listed: &["style", "label"],
            unlisted: &["ndf"],
        };
        let found = validate(
            &members(r#"{"ndf":1,"stlye":2,"label":3,"label":4,"x":5}"#),
            "p",
            Some(&accepted),
        );
        let found: Vec<(&str, &str)> = found
            .iter()
            .map(|p| (p.at.as_str(), p.message.as_str()))
            .collect();
        assert_eq!(
            found,
            [
                (
                    "p.stlye",
                    "unknown key for a thing (got 2, expected one of: style, label); did you mean \"style\"?"
                ),
                (
                    "p.label",
                    "duplicate key (got a second value 4, expected each key once)"
                ),
                (
                    "p.x",
                    "unknown key for a thing (got 5, expected one of: style, label)"
                ),
            ]
        );
    }

    #[test]
    fn without_accepted_keys_only_duplicates_are_reported() {
        let found = validate(&members(r#"{"a":1,"b":2,"a":3}"#), "", None);
        assert_eq!(found.len(), 1);
        assert_eq!(found[0].at, "a");
    }
}
