//! The legend text of a sweep: its members' labels merged into one ranged label
//! (`α_tr = 0.4`, …, `α_tr = 0.9` → `α_tr = 0.4 … 0.9`), so that a legend summarizes a sweep in one
//! row instead of listing it.
//!
//! Works on the drawn labels alone: labels that share their text and differ only in numbers merge,
//! number by number; anything else is left to the legend to list. It decides no placement and
//! draws nothing.

/// Most values a varying number lists (`a₁ = 1, 10, 100, 1000`) before it is shown as a range.
pub(super) const MAX_LISTED: usize = 4;
/// The range mark between the first and the last value: a horizontal ellipsis between spaces, as
/// the notebooks' panel titles write it.
pub(super) const RANGE_MARK: &str = " … ";

/// A piece of a label: text, or a number as written.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Piece<'a> {
    Text(&'a str),
    Number(&'a str),
}

/// Splits `label` into text and the numbers in it. A number starts with a digit (or a minus sign
/// before one) that does not continue a name or markup (`a1`, `α_{2}`, `x^2` keep their digits as
/// text) and runs over digits, one decimal point and an exponent.
fn pieces(label: &str) -> Vec<Piece<'_>> {
    let chars: Vec<(usize, char)> = label.char_indices().collect();
    let mut out = Vec::new();
    let (mut i, mut text_start) = (0, 0);
    while i < chars.len() {
        let (at, c) = chars[i];
        let previous = i.checked_sub(1).map(|j| chars[j].1);
        let joins_name = previous
            .is_some_and(|p| p.is_alphanumeric() || matches!(p, '_' | '{' | '^' | '\\' | '.'));
        let digit_at = |j: usize| chars.get(j).is_some_and(|(_, c)| c.is_ascii_digit());
        let starts =
            !joins_name && (c.is_ascii_digit() || (matches!(c, '-' | '−') && digit_at(i + 1)));
        if !starts {
            i += 1;
            continue;
        }
        let mut j = i + 1;
        let mut point = false;
        while j < chars.len() {
            let c = chars[j].1;
            if c.is_ascii_digit() {
                j += 1;
            } else if c == '.' && !point && digit_at(j + 1) {
                point = true;
                j += 1;
            } else if c == 'e'
                && (digit_at(j + 1)
                    || (chars.get(j + 1).is_some_and(|x| x.1 == '-') && digit_at(j + 2)))
            {
                j += 2;
                while digit_at(j) {
                    j += 1;
                }
                break;
            } else {
                break;
            }
        }
        // A number glued to letters after it (`2nd`, `3D`) is part of a name.
        if chars.get(j).is_some_and(|(_, c)| c.is_alphabetic()) {
            i = j;
            continue;
        }
        let end = chars.get(j).map_or(label.len(), |(b, _)| *b);
        if text_start < at {
            out.push(Piece::Text(&label[text_start..at]));
        }
        out.push(Piece::Number(&label[at..end]));
        text_start = end;
        i = j;
    }
    if text_start < label.len() {
        out.push(Piece::Text(&label[text_start..]));
    }
    out
}

fn value(text: &str) -> Option<f64> {
    text.replace('−', "-").parse().ok()
}

/// Whether `values` step evenly (within a relative 1e-6 of the step), at least three of them.
fn evenly_spaced(values: &[f64]) -> bool {
    if values.len() < 3 {
        return false;
    }
    let step = values[1] - values[0];
    step != 0.0
        && values
            .windows(2)
            .all(|w| ((w[1] - w[0]) - step).abs() <= 1e-6 * step.abs().max(f64::MIN_POSITIVE))
}

/// The one label that stands for a sweep whose members are labelled `labels` (in sweep order), or
/// `None` when they do not merge (their text differs other than in numbers, or fewer than two).
///
/// Labels that are all the same are that label: the row's shade ramp says it is a sweep.
/// Numbers equal in every label stay as written. A number that varies becomes `first … last`, or,
/// when it is the only one that varies, takes at most [`MAX_LISTED`] values and they do not step
/// evenly, the list of its values (`1, 10, 100, 1000`): a range then would hide where the values
/// lie. Several varying numbers vary together (one sweep), so each becomes a range.
pub(super) fn summarize(labels: &[&str]) -> Option<String> {
    if labels.len() < 2 {
        return None;
    }
    let split: Vec<Vec<Piece>> = labels.iter().map(|l| pieces(l)).collect();
    let first = &split[0];
    let same_shape = split.iter().all(|p| {
        p.len() == first.len()
            && p.iter().zip(first).all(|pair| match pair {
                (Piece::Text(a), Piece::Text(b)) => a == b,
                (Piece::Number(_), Piece::Number(_)) => true,
                _ => false,
            })
    });
    if !same_shape {
        return None;
    }
    let column = |i: usize| -> Vec<&str> {
        split
            .iter()
            .map(|p| match p[i] {
                Piece::Number(n) | Piece::Text(n) => n,
            })
            .collect()
    };
    let varies = |i: usize| {
        let col = column(i);
        col.iter().any(|n| *n != col[0])
    };
    let varying = (0..first.len()).filter(|&i| varies(i)).count();
    let mut out = String::new();
    for (i, piece) in first.iter().enumerate() {
        match piece {
            Piece::Text(text) => out.push_str(text),
            Piece::Number(n) if !varies(i) => out.push_str(n),
            Piece::Number(_) => {
                let col = column(i);
                let numbers: Option<Vec<f64>> = col.iter().map(|n| value(n)).collect();
                let listed = varying == 1
                    && col.len() <= MAX_LISTED
                    && !numbers.as_deref().is_some_and(evenly_spaced);
                if listed {
                    out.push_str(&col.join(", "));
                } else {
                    out.push_str(col[0]);
                    out.push_str(RANGE_MARK);
                    out.push_str(col[col.len() - 1]);
                }
            }
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sweep_of_one_parameter_becomes_a_range_or_a_short_list() {
        let tr: Vec<String> = ["0.4", "0.5", "0.6", "0.7", "0.8", "0.9"]
            .iter()
            .map(|v| format!("α_{{tr}} = {v}"))
            .collect();
        let tr: Vec<&str> = tr.iter().map(String::as_str).collect();
        assert_eq!(summarize(&tr).unwrap(), "α_{tr} = 0.4 … 0.9");
        assert_eq!(
            summarize(&["ABC a₁ = 1", "ABC a₁ = 10", "ABC a₁ = 100", "ABC a₁ = 1000"]).unwrap(),
            "ABC a₁ = 1, 10, 100, 1000"
        );
        // Evenly stepped, even when short: a range.
        assert_eq!(
            summarize(&["a = 0.1", "a = 0.2", "a = 0.3"]).unwrap(),
            "a = 0.1 … 0.3"
        );
        assert_eq!(summarize(&["a = 0.5", "a = 1"]).unwrap(), "a = 0.5, 1");
    }

    #[test]
    fn numbers_that_vary_together_become_ranges_and_equal_ones_stay() {
        let labels = [
            "α_p = 10.5 (α_b = 0.4)",
            "α_p = 6 (α_b = 0.5)",
            "α_p = 0 (α_b = 1)",
        ];
        assert_eq!(
            summarize(&labels).unwrap(),
            "α_p = 10.5 … 0 (α_b = 0.4 … 1)"
        );
        assert_eq!(
            summarize(&["SGD a₂ = 0.5, a₁ = 1", "SGD a₂ = 0.5, a₁ = 2"]).unwrap(),
            "SGD a₂ = 0.5, a₁ = 1, 2"
        );
        assert_eq!(
            summarize(&["η = −1.5", "η = −2.5", "η = 1e-3"]).unwrap(),
            "η = −1.5, −2.5, 1e-3"
        );
    }

    #[test]
    fn digits_of_names_and_markup_are_text() {
        assert_eq!(
            pieces("c_{1} x2 = 3.5e-2 (3D)"),
            vec![
                Piece::Text("c_{1} x2 = "),
                Piece::Number("3.5e-2"),
                Piece::Text(" (3D)"),
            ]
        );
        // Labels that differ in text do not merge, nor do single or identical ones.
        assert_eq!(summarize(&["gold", "silver"]), None);
        assert_eq!(summarize(&["c_{1} = 1", "c_{2} = 1"]), None);
        assert_eq!(summarize(&["a = 1"]), None);
        assert_eq!(
            summarize(&["by hand", "by hand", "by hand"]).as_deref(),
            Some("by hand"),
            "one label for every member is the sweep's row"
        );
    }
}
