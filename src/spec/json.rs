//! JSON in and out.
//!
//! In: a small RFC 8259 reader that keeps what spec validation needs and serde_json drops: the
//! position of every value (for `line:column` in messages), duplicate object keys (an error in
//! ndfplot's formats), key order, and the literal text of every number (the Range rule counts the
//! decimals written in the JSON literal).
//!
//! Out: [`to_string`], the one way ndfplot writes JSON: serde_json, with every number in the
//! shortest round-trip form of docs/contracts.md.
//!
//! It never decides what a document means (that is `curve` and `scene`).

use crate::problem::{excerpt, one_line};
use serde::Serialize;
use std::{fmt, io};

/// Deepest nesting accepted; deeper documents are rejected instead of exhausting the stack.
pub const MAX_DEPTH: usize = 128;

/// A parsed JSON value with the 1-based line and column where it starts.
#[derive(Debug, Clone, PartialEq)]
pub struct Node {
    /// The value.
    pub value: Value,
    /// 1-based line of the value's first character.
    pub line: usize,
    /// 1-based column (in characters) of the value's first character.
    pub col: usize,
}

/// A JSON value. Objects keep their members in document order, duplicates included.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// `null`
    Null,
    /// `true` / `false`
    Bool(bool),
    /// A number with its literal text.
    Number(Number),
    /// A string, unescaped.
    String(String),
    /// An array.
    Array(Vec<Node>),
    /// An object: (key, value) pairs in document order.
    Object(Vec<(String, Node)>),
}

/// A JSON number: its nearest f64 and the literal as written (`0.40`, `1e-3`).
#[derive(Debug, Clone, PartialEq)]
pub struct Number {
    /// The correctly rounded f64 value of the literal.
    pub value: f64,
    /// The literal text exactly as written in the document.
    pub literal: String,
}

impl Number {
    /// Decimal places written in the literal (`0.25` → 2, `3` → 0), or `None` when the literal
    /// uses an exponent (`1e-3`), for which the Range rule does not round.
    pub fn decimals(&self) -> Option<usize> {
        if self.literal.contains(['e', 'E']) {
            return None;
        }
        Some(
            self.literal
                .split_once('.')
                .map_or(0, |(_, frac)| frac.len()),
        )
    }
}

impl Value {
    /// The JSON type name, for messages (`"a number"`, `"an object"`).
    pub fn kind(&self) -> &'static str {
        match self {
            Value::Null => "null",
            Value::Bool(_) => "a boolean",
            Value::Number(_) => "a number",
            Value::String(_) => "a string",
            Value::Array(_) => "an array",
            Value::Object(_) => "an object",
        }
    }
}

impl fmt::Display for Node {
    /// Compact JSON text of the value (numbers as written), as an [`excerpt`].
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut text = String::new();
        write_compact(&self.value, &mut text);
        f.write_str(&excerpt(&text))
    }
}

fn write_compact(value: &Value, out: &mut String) {
    match value {
        Value::Null => out.push_str("null"),
        Value::Bool(b) => out.push_str(if *b { "true" } else { "false" }),
        Value::Number(n) => out.push_str(&n.literal),
        Value::String(s) => out.push_str(&to_string(s)),
        Value::Array(items) => {
            out.push('[');
            for (i, item) in items.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                write_compact(&item.value, out);
            }
            out.push(']');
        }
        Value::Object(members) => {
            out.push('{');
            for (i, (key, item)) in members.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                out.push_str(&to_string(key));
                out.push(':');
                write_compact(&item.value, out);
            }
            out.push('}');
        }
    }
}

/// Compact JSON text of `value` (serde_json), with every f64 in shortest round-trip form, as
/// Rust's `{:?}` prints it (`1.0`, `0.1`, `1e-7`, `1e16`, `1000000000000000.0`): the number form
/// of docs/contracts.md, which serde_json's own float formatting does not follow (it prints `1e15` for
/// 1000000000000000.0). serde_json writes a non-finite f64 as `null`; ndfplot prints only finite
/// numbers, so callers check before.
pub fn to_string<T: Serialize + ?Sized>(value: &T) -> String {
    let mut out = Vec::with_capacity(64);
    value
        .serialize(&mut serde_json::Serializer::with_formatter(
            &mut out,
            RoundTripFloats,
        ))
        .expect("ndfplot's values serialize to JSON in memory");
    String::from_utf8(out).expect("serde_json writes UTF-8")
}

/// serde_json's compact formatting, floats as `{:?}`.
struct RoundTripFloats;

impl serde_json::ser::Formatter for RoundTripFloats {
    fn write_f64<W: ?Sized + io::Write>(&mut self, writer: &mut W, value: f64) -> io::Result<()> {
        write!(writer, "{value:?}")
    }
}

/// A syntax error with its 1-based position.
#[derive(Debug, Clone, PartialEq)]
pub struct SyntaxError {
    /// 1-based line.
    pub line: usize,
    /// 1-based column in characters.
    pub col: usize,
    /// What was wrong.
    pub message: String,
}

impl fmt::Display for SyntaxError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}: invalid JSON: {}",
            self.line, self.col, self.message
        )
    }
}

/// Parses one JSON document (surrounding whitespace allowed, nothing else after it).
pub fn parse(text: &str) -> Result<Node, SyntaxError> {
    let mut parser = Parser {
        chars: text.chars().collect(),
        pos: 0,
        line: 1,
        col: 1,
    };
    parser.skip_whitespace();
    let node = parser.value(0)?;
    parser.skip_whitespace();
    if parser.pos < parser.chars.len() {
        return Err(parser.error("unexpected text after the JSON value"));
    }
    Ok(node)
}

struct Parser {
    chars: Vec<char>,
    pos: usize,
    line: usize,
    col: usize,
}

impl Parser {
    fn error(&self, message: impl Into<String>) -> SyntaxError {
        SyntaxError {
            line: self.line,
            col: self.col,
            message: message.into(),
        }
    }

    /// The next character for messages: `'x'` or `end of input`.
    fn found(&self) -> String {
        self.peek().map_or_else(
            || "end of input".to_string(),
            |c| format!("'{}'", one_line(&c.to_string())),
        )
    }

    fn peek(&self) -> Option<char> {
        self.chars.get(self.pos).copied()
    }

    fn bump(&mut self) -> Option<char> {
        let ch = self.peek()?;
        self.pos += 1;
        if ch == '\n' {
            self.line += 1;
            self.col = 1;
        } else {
            self.col += 1;
        }
        Some(ch)
    }

    fn skip_whitespace(&mut self) {
        while matches!(self.peek(), Some(' ' | '\t' | '\n' | '\r')) {
            self.bump();
        }
    }

    fn expect(&mut self, wanted: char) -> Result<(), SyntaxError> {
        match self.peek() {
            Some(ch) if ch == wanted => {
                self.bump();
                Ok(())
            }
            Some(ch) => Err(self.error(format!("expected '{wanted}', found '{ch}'"))),
            None => Err(self.error(format!("expected '{wanted}', found end of input"))),
        }
    }

    fn value(&mut self, depth: usize) -> Result<Node, SyntaxError> {
        if depth > MAX_DEPTH {
            return Err(self.error(format!("nesting deeper than {MAX_DEPTH} levels")));
        }
        let (line, col) = (self.line, self.col);
        let value = match self.peek() {
            None => return Err(self.error("unexpected end of input")),
            Some('{') => self.object(depth)?,
            Some('[') => self.array(depth)?,
            Some('"') => Value::String(self.string()?),
            Some('t') => self.keyword("true", Value::Bool(true))?,
            Some('f') => self.keyword("false", Value::Bool(false))?,
            Some('n') => self.keyword("null", Value::Null)?,
            Some(c) if c == '-' || c.is_ascii_digit() => Value::Number(self.number()?),
            Some(_) => return Err(self.error(format!("unexpected character {}", self.found()))),
        };
        Ok(Node { value, line, col })
    }

    fn keyword(&mut self, word: &str, value: Value) -> Result<Value, SyntaxError> {
        let (line, col) = (self.line, self.col);
        for wanted in word.chars() {
            if self.peek() != Some(wanted) {
                return Err(SyntaxError {
                    line,
                    col,
                    message: format!("invalid literal, expected '{word}'"),
                });
            }
            self.bump();
        }
        Ok(value)
    }

    fn object(&mut self, depth: usize) -> Result<Value, SyntaxError> {
        self.expect('{')?;
        let mut members = Vec::new();
        self.skip_whitespace();
        if self.peek() == Some('}') {
            self.bump();
            return Ok(Value::Object(members));
        }
        loop {
            self.skip_whitespace();
            if self.peek() != Some('"') {
                return Err(self.error(format!("expected a string key, found {}", self.found())));
            }
            let key = self.string()?;
            self.skip_whitespace();
            self.expect(':')?;
            self.skip_whitespace();
            let node = self.value(depth + 1)?;
            members.push((key, node));
            self.skip_whitespace();
            let found = self.found();
            match self.bump() {
                Some(',') => continue,
                Some('}') => return Ok(Value::Object(members)),
                _ => {
                    return Err(self.error(format!(
                        "expected ',' or '}}' after an object member, found {found}"
                    )));
                }
            }
        }
    }

    fn array(&mut self, depth: usize) -> Result<Value, SyntaxError> {
        self.expect('[')?;
        let mut items = Vec::new();
        self.skip_whitespace();
        if self.peek() == Some(']') {
            self.bump();
            return Ok(Value::Array(items));
        }
        loop {
            self.skip_whitespace();
            items.push(self.value(depth + 1)?);
            self.skip_whitespace();
            let found = self.found();
            match self.bump() {
                Some(',') => continue,
                Some(']') => return Ok(Value::Array(items)),
                _ => {
                    return Err(self.error(format!(
                        "expected ',' or ']' after an array element, found {found}"
                    )));
                }
            }
        }
    }

    fn string(&mut self) -> Result<String, SyntaxError> {
        self.expect('"')?;
        let mut out = String::new();
        loop {
            match self.bump() {
                None => return Err(self.error("unterminated string")),
                Some('"') => return Ok(out),
                Some('\\') => out.push(self.escape()?),
                Some(c) if (c as u32) < 0x20 => {
                    return Err(self.error("control character in string (escape it)"));
                }
                Some(c) => out.push(c),
            }
        }
    }

    fn escape(&mut self) -> Result<char, SyntaxError> {
        Ok(match self.bump() {
            Some('"') => '"',
            Some('\\') => '\\',
            Some('/') => '/',
            Some('b') => '\u{8}',
            Some('f') => '\u{c}',
            Some('n') => '\n',
            Some('r') => '\r',
            Some('t') => '\t',
            Some('u') => {
                let high = self.hex4()?;
                if (0xD800..0xDC00).contains(&high) {
                    if self.bump() != Some('\\') || self.bump() != Some('u') {
                        return Err(self.error("unpaired surrogate in \\u escape"));
                    }
                    let low = self.hex4()?;
                    if !(0xDC00..0xE000).contains(&low) {
                        return Err(self.error("invalid low surrogate in \\u escape"));
                    }
                    let code = 0x10000 + ((high - 0xD800) << 10) + (low - 0xDC00);
                    char::from_u32(code).ok_or_else(|| self.error("invalid \\u escape"))?
                } else {
                    char::from_u32(high)
                        .ok_or_else(|| self.error("unpaired surrogate in \\u escape"))?
                }
            }
            _ => return Err(self.error("invalid escape sequence")),
        })
    }

    fn hex4(&mut self) -> Result<u32, SyntaxError> {
        let mut code = 0;
        for _ in 0..4 {
            let digit = self.bump().and_then(|c| c.to_digit(16));
            code =
                code * 16 + digit.ok_or_else(|| self.error("expected 4 hex digits after \\u"))?;
        }
        Ok(code)
    }

    fn digits(&mut self, literal: &mut String) -> usize {
        let mut count = 0;
        while let Some(c) = self.peek().filter(char::is_ascii_digit) {
            literal.push(c);
            self.bump();
            count += 1;
        }
        count
    }

    fn number(&mut self) -> Result<Number, SyntaxError> {
        let mut literal = String::new();
        if self.peek() == Some('-') {
            literal.push('-');
            self.bump();
        }
        let first = self.peek();
        if self.digits(&mut literal) == 0 {
            return Err(self.error("expected a digit"));
        }
        if first == Some('0') && literal.trim_start_matches('-').len() > 1 {
            return Err(self.error("leading zeros are not allowed in JSON numbers"));
        }
        if self.peek() == Some('.') {
            literal.push('.');
            self.bump();
            if self.digits(&mut literal) == 0 {
                return Err(self.error("expected a digit after '.'"));
            }
        }
        if let Some(e @ ('e' | 'E')) = self.peek() {
            literal.push(e);
            self.bump();
            if let Some(sign @ ('+' | '-')) = self.peek() {
                literal.push(sign);
                self.bump();
            }
            if self.digits(&mut literal) == 0 {
                return Err(self.error("expected a digit in the exponent"));
            }
        }
        let value: f64 = literal.parse().map_err(|_| self.error("invalid number"))?;
        if !value.is_finite() {
            return Err(self.error(format!(
                "number {} is outside the range of a double",
                excerpt(&literal)
            )));
        }
        Ok(Number { value, literal })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn object(text: &str) -> Vec<(String, Node)> {
        match parse(text).unwrap().value {
            Value::Object(members) => members,
            other => panic!("not an object: {other:?}"),
        }
    }

    #[test]
    fn keeps_duplicates_order_and_literals() {
        let members = object(r#"{"b": 0.40, "a": 1e-3, "b": -2}"#);
        let keys: Vec<_> = members.iter().map(|(k, _)| k.as_str()).collect();
        assert_eq!(keys, ["b", "a", "b"]);
        let Value::Number(n) = &members[0].1.value else {
            panic!()
        };
        assert_eq!(
            (n.value, n.literal.as_str(), n.decimals()),
            (0.4, "0.40", Some(2))
        );
        let Value::Number(n) = &members[1].1.value else {
            panic!()
        };
        assert_eq!((n.value, n.decimals()), (0.001, None));
    }

    #[test]
    fn positions_are_one_based_lines_and_columns() {
        let members = object("{\n  \"x\": [1,\n    true]\n}");
        assert_eq!((members[0].1.line, members[0].1.col), (2, 8));
        let Value::Array(items) = &members[0].1.value else {
            panic!()
        };
        assert_eq!((items[1].line, items[1].col), (3, 5));
    }

    #[test]
    fn unescapes_strings() {
        let node = parse(r#""a\"b\\c\u00e9\ud83d\ude00""#).unwrap();
        assert_eq!(node.value, Value::String("a\"b\\cé😀".into()));
    }

    #[test]
    fn syntax_errors_name_line_and_column() {
        let cases = [
            ("{\"a\": 1,}", 1, 9),
            ("{\"a\" 1}", 1, 6),
            ("[1, 2", 1, 6),
            ("{\n\"a\": tru}", 2, 6),
            ("01", 1, 3),
            ("1.", 1, 3),
            ("\"abc", 1, 5),
            ("1e999", 1, 6),
            ("{} x", 1, 4),
            ("", 1, 1),
        ];
        for (text, line, col) in cases {
            let err = parse(text).unwrap_err();
            assert_eq!((err.line, err.col), (line, col), "{text:?}: {err}");
        }
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_stack_overflow() {
        let text = "[".repeat(100_000);
        let err = parse(&text).unwrap_err();
        assert!(err.message.contains("nesting"), "{err}");
    }

    #[test]
    fn writes_numbers_in_shortest_round_trip_form() {
        let numbers = [
            1.0,
            0.1,
            1e-300,
            1e-7,
            1e-5,
            1e15,
            1e16,
            123456789012345680.0,
            6.123233995736766e-17,
            -0.0,
        ];
        let expected: Vec<String> = numbers.iter().map(|v| format!("{v:?}")).collect();
        assert_eq!(to_string(&numbers), format!("[{}]", expected.join(",")));
        assert_eq!(to_string("a\"b\\c\n"), r#""a\"b\\c\n""#);
    }

    #[test]
    fn display_is_compact_and_truncated() {
        let node = parse(r#"{ "ndf" : "phong", "alpha_p" : [1, 2.50] }"#).unwrap();
        assert_eq!(node.to_string(), r#"{"ndf":"phong","alpha_p":[1,2.50]}"#);
        let long = parse(&format!("\"{}\"", "x".repeat(100))).unwrap();
        // The excerpt every message quotes: 60 characters and an ellipsis.
        assert_eq!(long.to_string(), format!("\"{}…", "x".repeat(59)));
    }
}
