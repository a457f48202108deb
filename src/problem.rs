//! Input problems with their location, collected so that every problem of a file is reported at once.
//!
//! Message shape (docs/contracts.md): `error: <file or argument>: <JSON path or key>: <what> (got <value>, expected <…>)`.

use std::fmt;

/// One problem in one input, located by a JSON path (`panels[1].curves[0].alpha_b`) or a
/// `line:column` for syntax errors.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// JSON path, key or `line:column`; empty when the problem concerns the whole input.
    pub at: String,
    /// What is wrong, including `(got …, expected …)` where that applies.
    pub message: String,
}

impl Problem {
    /// A problem at `at` described by `message`.
    pub fn new(at: impl Into<String>, message: impl Into<String>) -> Problem {
        Problem {
            at: at.into(),
            message: message.into(),
        }
    }
}

/// Every problem found in one input (a file, a `--curve` argument, …).
#[derive(Debug, Clone, PartialEq)]
pub struct Problems {
    /// The file path or argument name the problems belong to.
    pub source: String,
    /// The problems, in document order.
    pub list: Vec<Problem>,
}

/// Most problems of one source printed; the rest are counted in a last line.
pub const MAX_PRINTED_PROBLEMS: usize = 100;

impl Problems {
    /// The problems as the `error` field of a batch output's row: `<at>: <message>` joined with
    /// `; ` on one line (the source is the row's own `line`); past [`MAX_PRINTED_PROBLEMS`], a count
    /// of the rest.
    pub fn field(&self) -> String {
        let mut parts: Vec<String> = self
            .list
            .iter()
            .take(MAX_PRINTED_PROBLEMS)
            .map(|p| match p.at.is_empty() {
                true => one_line(&p.message).into_owned(),
                false => format!("{}: {}", one_line(&p.at), one_line(&p.message)),
            })
            .collect();
        if self.list.len() > MAX_PRINTED_PROBLEMS {
            parts.push(format!(
                "{} more problems not shown",
                self.list.len() - MAX_PRINTED_PROBLEMS
            ));
        }
        parts.join("; ")
    }
}

impl fmt::Display for Problems {
    /// One `error: <source>: <at>: <message>` line per problem, without a trailing newline; past
    /// [`MAX_PRINTED_PROBLEMS`], one line saying how many more there are.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, problem) in self.list.iter().take(MAX_PRINTED_PROBLEMS).enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "error: {}: ", one_line(&self.source))?;
            if !problem.at.is_empty() {
                write!(f, "{}: ", one_line(&problem.at))?;
            }
            write!(f, "{}", one_line(&problem.message))?;
        }
        if self.list.len() > MAX_PRINTED_PROBLEMS {
            write!(
                f,
                "\nerror: {}: {} more problems not shown",
                one_line(&self.source),
                self.list.len() - MAX_PRINTED_PROBLEMS
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for Problems {}

/// Characters that reorder the text around them on a terminal (the Unicode bidirectional
/// controls): escaped by [`one_line`] like control characters, so a quoted value cannot make a
/// message read differently from what it says.
const BIDI_CONTROLS: [(char, char); 4] = [
    ('\u{061c}', '\u{061c}'),
    ('\u{200e}', '\u{200f}'),
    ('\u{202a}', '\u{202e}'),
    ('\u{2066}', '\u{2069}'),
];

/// Whether [`one_line`] escapes `c`: a control character or a bidirectional control.
fn escaped(c: char) -> bool {
    c.is_control()
        || BIDI_CONTROLS
            .iter()
            .any(|&(first, last)| (first..=last).contains(&c))
}

/// `text` with its control characters (and the bidirectional controls) escaped as in JSON (`\n`,
/// `\u0007`, `\u202e`), so that a message quoting a key or value that holds a line break still
/// takes exactly one line, and a quoted file's bytes cannot drive the terminal.
pub fn one_line(text: &str) -> std::borrow::Cow<'_, str> {
    if !text.chars().any(escaped) {
        return std::borrow::Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for ch in text.chars() {
        match ch {
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if escaped(c) => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    std::borrow::Cow::Owned(out)
}

/// Longest excerpt of a file's header or of a value that a message quotes, in characters.
pub const MAX_EXCERPT_CHARS: usize = 60;

/// At most [`MAX_EXCERPT_CHARS`] characters of `text`, control characters escaped as by
/// [`one_line`], and `…` appended when cut: what a message may quote of a file or of a value given
/// by the user, however long.
pub fn excerpt(text: &str) -> String {
    let cut: String = text.chars().take(MAX_EXCERPT_CHARS).collect();
    let mut out = one_line(&cut).into_owned();
    if text.chars().nth(MAX_EXCERPT_CHARS).is_some() {
        out.push('…');
    }
    out
}

/// Joins a JSON path and an object key: `("panels[0]", "title")` → `panels[0].title`. The key is
/// quoted as an [`excerpt`]: a path never echoes a long or control-laden key whole.
pub fn join_key(path: &str, key: &str) -> String {
    let key = excerpt(key);
    if path.is_empty() {
        key
    } else {
        format!("{path}.{key}")
    }
}

/// Joins a JSON path and an array index: `("panels", 2)` → `panels[2]`.
pub fn join_index(path: &str, index: usize) -> String {
    format!("{path}[{index}]")
}

/// The candidate nearest to `word` by edit distance, if it is close enough to be a likely
/// misspelling (distance ≤ max(1, len/3)); else the one candidate `word` (3 characters or more)
/// begins, a name cut short (`alpha` → `alpha_tr`).
pub fn did_you_mean<'a>(
    word: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> Option<&'a str> {
    let candidates: Vec<&'a str> = candidates.into_iter().collect();
    nearest(word, &candidates).or_else(|| {
        let mut longer = candidates
            .iter()
            .filter(|c| word.len() >= 3 && c.len() > word.len() && c.starts_with(word));
        match (longer.next(), longer.next()) {
            (Some(only), None) => Some(*only),
            _ => None,
        }
    })
}

/// The candidate nearest to `word` by edit distance within max(1, len/3).
fn nearest<'a>(word: &str, candidates: &[&'a str]) -> Option<&'a str> {
    let length = word.chars().count();
    let limit = (length / 3).max(1);
    // The distance is at least the difference of the lengths: a candidate farther than the limit
    // by length alone is not compared (a long unknown key costs no quadratic table).
    candidates
        .iter()
        .filter(|c| c.chars().count().abs_diff(length) <= limit)
        .map(|&c| (edit_distance(word, c), c))
        .filter(|&(d, _)| d <= limit)
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

/// Most names a suggestion lists when several begin with what was given.
const MAX_SUGGESTED: usize = 4;

/// Appends `; did you mean "<x>"?` when a near candidate exists ([`did_you_mean`]), or `; did you
/// mean one of "<x>", "<y>"?` when several (at most [`MAX_SUGGESTED`]) begin with a `word` of three
/// or more characters (`alpha` on ABC: `alpha_abc1`, `alpha_abc2`).
pub fn suggestion<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> String {
    let candidates: Vec<&'a str> = candidates.into_iter().collect();
    if let Some(c) = did_you_mean(word, candidates.iter().copied()) {
        return format!("; did you mean \"{c}\"?");
    }
    let longer: Vec<String> = candidates
        .iter()
        .filter(|c| word.len() >= 3 && c.len() > word.len() && c.starts_with(word))
        .map(|c| format!("\"{c}\""))
        .collect();
    match longer.len() {
        2..=MAX_SUGGESTED => format!("; did you mean one of {}?", longer.join(", ")),
        _ => String::new(),
    }
}

/// Edit distance in characters counting insertions, deletions, substitutions and swaps of
/// adjacent characters (optimal string alignment), so `stlye` is one edit from `style`.
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    d[0] = (0..=b.len()).collect();
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            d[i][j] = (d[i - 1][j] + 1)
                .min(d[i][j - 1] + 1)
                .min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                d[i][j] = d[i][j].min(d[i - 2][j - 2] + 1);
            }
        }
    }
    d[a.len()][b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_name_cut_short_suggests_the_one_name_it_begins() {
        assert_eq!(
            did_you_mean("alpha", ["alpha_tr", "quantity"]),
            Some("alpha_tr")
        );
        assert_eq!(did_you_mean("alpha", ["alpha_abc1", "alpha_abc2"]), None);
        // Several that it begins are listed, as long as they are few.
        assert_eq!(
            suggestion("alpha", ["alpha_abc1", "alpha_abc2", "quantity"]),
            "; did you mean one of \"alpha_abc1\", \"alpha_abc2\"?"
        );
        assert_eq!(suggestion("a", ["alpha_abc1", "alpha_abc2"]), "");
        assert_eq!(did_you_mean("al", ["alpha_tr"]), None);
        assert_eq!(
            did_you_mean("stlye", ["style", "styles_of_old"]),
            Some("style")
        );
    }

    #[test]
    fn excerpts_are_bounded_and_printable() {
        assert_eq!(excerpt("theta"), "theta");
        assert_eq!(excerpt("a\u{7}b\nc"), "a\\u0007b\\nc");
        let long = "x".repeat(1000);
        assert_eq!(excerpt(&long).chars().count(), MAX_EXCERPT_CHARS + 1);
    }

    #[test]
    fn suggests_near_names_only() {
        let names = ["alpha_b", "alpha_p", "alpha_tr"];
        assert_eq!(did_you_mean("alpha_bb", names), Some("alpha_b"));
        assert_eq!(did_you_mean("alfa_tr", names), Some("alpha_tr"));
        assert_eq!(did_you_mean("roughness", names), None);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(did_you_mean("stlye", ["style", "label"]), Some("style"));
    }

    #[test]
    fn formats_one_line_per_problem() {
        let problems = Problems {
            source: "x.json".into(),
            list: vec![
                Problem::new("a.b", "bad (got 1, expected 2)"),
                Problem::new("", "empty"),
            ],
        };
        assert_eq!(
            problems.to_string(),
            "error: x.json: a.b: bad (got 1, expected 2)\nerror: x.json: empty"
        );
        let problems = Problems {
            source: "x.json".into(),
            list: vec![Problem::new("a\nb", "got \"c\td\u{7}\"")],
        };
        assert_eq!(
            problems.to_string(),
            "error: x.json: a\\nb: got \"c\\td\\u0007\""
        );
    }
}
