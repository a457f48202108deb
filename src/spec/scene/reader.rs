//! Typed access to JSON objects with every problem recorded at its JSON path.
//!
//! Validation code asks for fields through a [`Reader`]; a wrong type, an unknown or duplicate
//! key becomes a [`Problem`] and the read returns `None`, so one pass reports everything.

use crate::problem::{Problem, join_key, suggestion};
use crate::spec::json::{Node, Value};
use crate::spec::keys::{self, Accepted};

/// The characters a text field refuses, as inclusive ranges: Unicode's control characters (category
/// Cc: C0, DEL and C1), which no figure format can show (SVG's XML refuses most of them), and the
/// noncharacters U+FFFE and U+FFFF. The JSON Schema's text pattern is made from this table.
pub const REFUSED_IN_TEXT: [(char, char); 3] = [
    ('\u{0}', '\u{1f}'),
    ('\u{7f}', '\u{9f}'),
    ('\u{fffe}', '\u{ffff}'),
];

/// Longest text a field holds, in characters: a title or label of a few lines is tens of
/// characters, and longer text only slows the drawing (a 100 000-character label took 22 s to
/// rasterize).
pub const MAX_TEXT_CHARS: usize = 1000;

/// Collects the problems found while reading one document.
#[derive(Debug, Default)]
pub struct Reader {
    /// Problems in the order found.
    pub problems: Vec<Problem>,
    /// Where the document's data files may be read from; `None` for documents not read from disk
    /// (the built-in catalogue, arguments).
    pub data: Option<crate::spec::datafile::DataScope>,
    /// The fallible work (fits, data files) described so far, in the order met.
    pub pending: Vec<super::Pending>,
}

/// An object's members, checked for unknown and duplicate keys.
#[derive(Debug, Clone, Copy)]
pub struct Object<'a> {
    members: &'a [(String, Node)],
    path: &'a str,
}

impl<'a> Object<'a> {
    /// Wraps members that were already checked for unknown keys elsewhere.
    pub fn from_members(members: &'a [(String, Node)], path: &'a str) -> Object<'a> {
        Object { members, path }
    }

    /// The node under `key`, if present.
    pub fn get(&self, key: &str) -> Option<&'a Node> {
        self.members.iter().find(|(k, _)| k == key).map(|(_, n)| n)
    }

    /// The JSON path of `key` in this object.
    pub fn path_of(&self, key: &str) -> String {
        join_key(self.path, key)
    }

    /// The object's JSON path.
    pub fn path(&self) -> &'a str {
        self.path
    }
}

impl Reader {
    /// Records a problem.
    pub fn report(&mut self, at: impl Into<String>, message: impl Into<String>) {
        self.problems.push(Problem::new(at, message));
    }

    /// Reads `node` as an object whose keys must all be in `allowed`; unknown keys (with a
    /// "did you mean") and duplicates are reported ([`keys::validate`]), the object is still returned.
    pub fn object<'a>(
        &mut self,
        node: &'a Node,
        path: &'a str,
        allowed: &[&str],
    ) -> Option<Object<'a>> {
        let Value::Object(members) = &node.value else {
            self.report(path, format!("expected an object (got {node})"));
            return None;
        };
        let accepted = Accepted {
            object: None,
            listed: allowed,
            unlisted: &[],
        };
        self.problems
            .extend(keys::validate(members, path, Some(&accepted)));
        Some(Object { members, path })
    }

    /// A string field; `None` when absent or of the wrong type (reported).
    pub fn string(&mut self, object: &Object, key: &str) -> Option<String> {
        let node = object.get(key)?;
        match &node.value {
            Value::String(s) => Some(s.clone()),
            other => {
                self.report(
                    object.path_of(key),
                    format!("expected a string (got {} {node})", other.kind()),
                );
                None
            }
        }
    }

    /// The value of a check whose problems (if any) are recorded instead.
    pub fn accept<T>(&mut self, checked: Result<T, Vec<Problem>>) -> Option<T> {
        checked
            .map_err(|problems| self.problems.extend(problems))
            .ok()
    }

    /// A string field that is drawn as text (a title, a label, a column name shown on an axis): a
    /// string without the characters of [`REFUSED_IN_TEXT`], at most [`MAX_TEXT_CHARS`] long.
    /// `None` when absent, of the wrong type, holding one or too long (reported).
    pub fn text(&mut self, object: &Object, key: &str) -> Option<String> {
        let text = self.string(object, key)?;
        match text.chars().find(|c| {
            REFUSED_IN_TEXT
                .iter()
                .any(|&(first, last)| (first..=last).contains(c))
        }) {
            Some(bad) => {
                self.report(
                    object.path_of(key),
                    format!(
                        "control character U+{:04X} in text (got \"{}\", expected printable text)",
                        bad as u32,
                        crate::problem::excerpt(&text)
                    ),
                );
                None
            }
            None if text.chars().count() > MAX_TEXT_CHARS => {
                self.report(
                    object.path_of(key),
                    format!(
                        "text too long (got {} characters, expected at most {MAX_TEXT_CHARS})",
                        text.chars().count()
                    ),
                );
                None
            }
            None => Some(text),
        }
    }

    /// A boolean field; `None` when absent or of the wrong type (reported).
    pub fn boolean(&mut self, object: &Object, key: &str) -> Option<bool> {
        let node = object.get(key)?;
        match &node.value {
            Value::Bool(b) => Some(*b),
            other => {
                self.report(
                    object.path_of(key),
                    format!("expected true or false (got {} {node})", other.kind()),
                );
                None
            }
        }
    }

    /// A number field that must satisfy `ok` (described by `expected`); `None` when absent or
    /// invalid (reported).
    pub fn number(
        &mut self,
        object: &Object,
        key: &str,
        ok: impl Fn(f64) -> bool,
        expected: &str,
    ) -> Option<f64> {
        let node = object.get(key)?;
        match &node.value {
            Value::Number(n) if ok(n.value) => Some(n.value),
            Value::Number(n) => {
                self.report(
                    object.path_of(key),
                    format!("out of range (got {}, expected {expected})", n.literal),
                );
                None
            }
            other => {
                self.report(
                    object.path_of(key),
                    format!("expected a number (got {} {node})", other.kind()),
                );
                None
            }
        }
    }

    /// A field holding `[low, high]` with low < high, both finite and satisfying `ok`, and a finite span
    /// high − low.
    pub fn interval(
        &mut self,
        object: &Object,
        key: &str,
        ok: impl Fn(f64) -> bool,
        expected: &str,
    ) -> Option<(f64, f64)> {
        let node = object.get(key)?;
        let at = object.path_of(key);
        if let Value::Array(items) = &node.value {
            if let [
                Node {
                    value: Value::Number(a),
                    ..
                },
                Node {
                    value: Value::Number(b),
                    ..
                },
            ] = items.as_slice()
            {
                // A span past the largest double (±1e308) would reach the axes as ∞ and NaN ticks.
                let span_finite = (b.value - a.value).is_finite();
                if a.value < b.value && span_finite && ok(a.value) && ok(b.value) {
                    return Some((a.value, b.value));
                }
                self.report(at, format!("invalid interval (got {node}, expected [low, high] with low < high, high − low finite, {expected})"));
                return None;
            }
        }
        self.report(at, format!("expected [low, high] (got {node})"));
        None
    }

    /// A field holding one of `choices`; `None` when absent or invalid (reported with a suggestion).
    pub fn choice(
        &mut self,
        object: &Object,
        key: &str,
        choices: &[&'static str],
    ) -> Option<&'static str> {
        let text = self.string(object, key)?;
        let found = choices.iter().find(|&&c| c == text).copied();
        if found.is_none() {
            self.report(
                object.path_of(key),
                format!(
                    "unknown value (got \"{}\", expected one of: {}){}",
                    crate::problem::excerpt(&text),
                    choices.join(", "),
                    suggestion(&text, choices.iter().copied())
                ),
            );
        }
        found
    }
}
