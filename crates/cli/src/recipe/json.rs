//! A small strict JSON parser (RFC 8259) that keeps byte spans and the exact text of
//! numbers.
//!
//! `serde_json` forgets positions of values and reads numbers as `f64`; recipes need
//! both (errors point at the offending value, `0.1` is exactly 1/10). Nesting is
//! bounded by [`MAX_DEPTH`] so no input can overflow the stack. Duplicate keys are an
//! error.

use super::tree::{Entry, NumberText, RecipeValue, ValueKind};
use crate::source::Span;

/// The deepest nesting of arrays and objects accepted.
pub const MAX_DEPTH: usize = 64;

/// A JSON syntax error at a byte span.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SyntaxError {
    /// Where the problem is.
    pub span: Span,
    /// What is wrong.
    pub message: String,
}

/// Parses a complete JSON document.
///
/// # Errors
/// The first syntax error, with its position.
pub fn parse(text: &str) -> Result<RecipeValue, SyntaxError> {
    let mut p = Parser {
        text,
        bytes: text.as_bytes(),
        pos: 0,
        depth: 0,
    };
    // A UTF-8 byte order mark is tolerated.
    if text.starts_with('\u{feff}') {
        p.pos = 3;
    }
    p.skip_ws();
    if p.pos >= p.bytes.len() {
        return Err(p.err_here("empty document: expected a JSON value"));
    }
    let v = p.value()?;
    p.skip_ws();
    if p.pos < p.bytes.len() {
        return Err(p.err_here(format!(
            "unexpected {} after the end of the JSON document",
            p.describe_here()
        )));
    }
    Ok(v)
}

struct Parser<'a> {
    text: &'a str,
    bytes: &'a [u8],
    pos: usize,
    depth: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.pos).copied()
    }

    fn err(&self, start: usize, end: usize, message: impl Into<String>) -> SyntaxError {
        SyntaxError {
            span: Span::new(start, end),
            message: message.into(),
        }
    }

    /// An error at the current position, one character wide.
    fn err_here(&self, message: impl Into<String>) -> SyntaxError {
        let w = self.char_here().map_or(0, char::len_utf8);
        self.err(self.pos, self.pos + w, message)
    }

    fn char_here(&self) -> Option<char> {
        self.text.get(self.pos..).and_then(|s| s.chars().next())
    }

    /// "end of input" or "character 'x'".
    fn describe_here(&self) -> String {
        match self.char_here() {
            None => "end of input".into(),
            Some(c) if c.is_control() => format!("character {c:?}"),
            Some(c) => format!("character '{c}'"),
        }
    }

    fn skip_ws(&mut self) {
        while let Some(b' ' | b'\t' | b'\n' | b'\r') = self.peek() {
            self.pos += 1;
        }
    }

    fn value(&mut self) -> Result<RecipeValue, SyntaxError> {
        match self.peek() {
            Some(b'{') => self.object(),
            Some(b'[') => self.array(),
            Some(b'"') => {
                let start = self.pos;
                let s = self.string()?;
                Ok(RecipeValue::new(
                    ValueKind::String(s),
                    Span::new(start, self.pos),
                ))
            }
            Some(b'-' | b'0'..=b'9') => self.number(),
            Some(b't') => self.literal("true", ValueKind::Bool(true)),
            Some(b'f') => self.literal("false", ValueKind::Bool(false)),
            Some(b'n') => self.literal("null", ValueKind::Null),
            Some(b'\'') => Err(self.err_here("JSON strings use double quotes, not '")),
            Some(b'+' | b'.') => Err(self.err_here(
                "a JSON number starts with a digit or '-' (write exact numbers as strings: \"0.5\", \"3/7\")",
            )),
            _ => Err(self.err_here(format!("expected a JSON value, found {}", self.describe_here()))),
        }
    }

    fn literal(&mut self, word: &str, kind: ValueKind) -> Result<RecipeValue, SyntaxError> {
        let start = self.pos;
        if self.bytes[start..].starts_with(word.as_bytes()) {
            let end = start + word.len();
            // `truex` is not `true` followed by garbage we want to blame later.
            if let Some(b) = self.bytes.get(end) {
                if b.is_ascii_alphanumeric() || *b == b'_' {
                    return Err(self.bad_word(start));
                }
            }
            self.pos = end;
            Ok(RecipeValue::new(kind, Span::new(start, end)))
        } else {
            Err(self.bad_word(start))
        }
    }

    fn bad_word(&self, start: usize) -> SyntaxError {
        let end = self.bytes[start..]
            .iter()
            .position(|b| !(b.is_ascii_alphanumeric() || *b == b'_'))
            .map_or(self.bytes.len(), |n| start + n)
            .max(start + 1);
        let word = self.text.get(start..end).unwrap_or("?");
        self.err(
            start,
            end,
            format!("unknown literal `{}` (expected true, false, null, a number, a string, an array or an object)", crate::source::clip(word)),
        )
    }

    fn enter(&mut self) -> Result<(), SyntaxError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(self.err_here(format!("nesting deeper than {MAX_DEPTH} levels")));
        }
        Ok(())
    }

    fn array(&mut self) -> Result<RecipeValue, SyntaxError> {
        let start = self.pos;
        self.enter()?;
        self.pos += 1; // '['
        let mut items = Vec::new();
        self.skip_ws();
        if self.peek() == Some(b']') {
            self.pos += 1;
        } else {
            loop {
                self.skip_ws();
                if self.peek() == Some(b']') {
                    return Err(self.err_here("trailing comma before ']' is not allowed in JSON"));
                }
                if self.peek().is_none() {
                    return Err(self.err(start, start + 1, "unclosed array: missing ']'"));
                }
                items.push(self.value()?);
                self.skip_ws();
                match self.peek() {
                    Some(b',') => self.pos += 1,
                    Some(b']') => {
                        self.pos += 1;
                        break;
                    }
                    None => return Err(self.err(start, start + 1, "unclosed array: missing ']'")),
                    _ => {
                        return Err(self.err_here(format!(
                            "expected ',' or ']' after an array element, found {}",
                            self.describe_here()
                        )))
                    }
                }
            }
        }
        self.depth -= 1;
        Ok(RecipeValue::new(
            ValueKind::Array(items),
            Span::new(start, self.pos),
        ))
    }

    fn object(&mut self) -> Result<RecipeValue, SyntaxError> {
        let start = self.pos;
        self.enter()?;
        self.pos += 1; // '{'
        let mut entries: Vec<Entry> = Vec::new();
        self.skip_ws();
        if self.peek() == Some(b'}') {
            self.pos += 1;
        } else {
            loop {
                self.skip_ws();
                match self.peek() {
                    Some(b'"') => {}
                    Some(b'}') => {
                        return Err(
                            self.err_here("trailing comma before '}' is not allowed in JSON")
                        )
                    }
                    None => return Err(self.err(start, start + 1, "unclosed object: missing '}'")),
                    _ => {
                        return Err(self.err_here(format!(
                            "expected a key in double quotes, found {}",
                            self.describe_here()
                        )))
                    }
                }
                let key_start = self.pos;
                let key = self.string()?;
                let key_span = Span::new(key_start, self.pos);
                if entries.iter().any(|e| e.key == key) {
                    return Err(self.err(
                        key_start,
                        self.pos,
                        format!("duplicate key {:?}", crate::source::clip(&key)),
                    ));
                }
                self.skip_ws();
                if self.peek() != Some(b':') {
                    return Err(self.err_here(format!(
                        "expected ':' after the key {key:?}, found {}",
                        self.describe_here()
                    )));
                }
                self.pos += 1;
                self.skip_ws();
                let value = self.value()?;
                entries.push(Entry {
                    key,
                    key_span,
                    value,
                });
                self.skip_ws();
                match self.peek() {
                    Some(b',') => self.pos += 1,
                    Some(b'}') => {
                        self.pos += 1;
                        break;
                    }
                    None => return Err(self.err(start, start + 1, "unclosed object: missing '}'")),
                    _ => {
                        return Err(self.err_here(format!(
                            "expected ',' or '}}' after an object member, found {}",
                            self.describe_here()
                        )))
                    }
                }
            }
        }
        self.depth -= 1;
        Ok(RecipeValue::new(
            ValueKind::Table(entries),
            Span::new(start, self.pos),
        ))
    }

    /// Parses a string starting at the opening quote; leaves `pos` after the closing quote.
    fn string(&mut self) -> Result<String, SyntaxError> {
        let start = self.pos;
        self.pos += 1; // '"'
        let mut out = String::new();
        loop {
            let Some(c) = self.char_here() else {
                return Err(self.err(start, start + 1, "unterminated string: missing '\"'"));
            };
            match c {
                '"' => {
                    self.pos += 1;
                    return Ok(out);
                }
                '\\' => {
                    let esc_start = self.pos;
                    self.pos += 1;
                    let Some(e) = self.char_here() else {
                        return Err(self.err(
                            start,
                            start + 1,
                            "unterminated string: missing '\"'",
                        ));
                    };
                    self.pos += e.len_utf8();
                    match e {
                        '"' => out.push('"'),
                        '\\' => out.push('\\'),
                        '/' => out.push('/'),
                        'b' => out.push('\u{8}'),
                        'f' => out.push('\u{c}'),
                        'n' => out.push('\n'),
                        'r' => out.push('\r'),
                        't' => out.push('\t'),
                        'u' => {
                            let hi = self.hex4(esc_start)?;
                            let c = if (0xD800..0xDC00).contains(&hi) {
                                // A high surrogate must be followed by \uDC00–\uDFFF.
                                if self.bytes[self.pos..].starts_with(b"\\u") {
                                    self.pos += 2;
                                    let lo = self.hex4(esc_start)?;
                                    if !(0xDC00..0xE000).contains(&lo) {
                                        return Err(self.err(
                                            esc_start,
                                            self.pos,
                                            "invalid surrogate pair in \\u escape",
                                        ));
                                    }
                                    char::from_u32(0x10000 + ((hi - 0xD800) << 10) + (lo - 0xDC00))
                                } else {
                                    None
                                }
                            } else {
                                char::from_u32(hi)
                            };
                            match c {
                                Some(c) => out.push(c),
                                None => {
                                    return Err(self.err(
                                        esc_start,
                                        self.pos,
                                        "unpaired surrogate in \\u escape",
                                    ))
                                }
                            }
                        }
                        other => {
                            return Err(self.err(
                                esc_start,
                                self.pos,
                                format!("invalid escape '\\{other}' in string"),
                            ))
                        }
                    }
                }
                c if (c as u32) < 0x20 => {
                    return Err(self.err_here(if c == '\n' {
                        "unterminated string: line break inside a string".to_string()
                    } else {
                        format!("control character {c:?} inside a string must be escaped")
                    }));
                }
                c => {
                    out.push(c);
                    self.pos += c.len_utf8();
                }
            }
        }
    }

    /// Four hex digits of a `\u` escape.
    fn hex4(&mut self, esc_start: usize) -> Result<u32, SyntaxError> {
        let digits = self.bytes.get(self.pos..self.pos + 4);
        match digits {
            Some(d) if d.iter().all(u8::is_ascii_hexdigit) => {
                let mut v = 0u32;
                for &b in d {
                    v = v * 16 + (b as char).to_digit(16).unwrap_or(0);
                }
                self.pos += 4;
                Ok(v)
            }
            _ => Err(self.err(
                esc_start,
                (self.pos + 4).min(self.bytes.len()),
                "\\u must be followed by four hex digits",
            )),
        }
    }

    /// `-? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)?`
    fn number(&mut self) -> Result<RecipeValue, SyntaxError> {
        let start = self.pos;
        if self.peek() == Some(b'-') {
            self.pos += 1;
        }
        match self.peek() {
            Some(b'0') => {
                self.pos += 1;
                if let Some(b'0'..=b'9') = self.peek() {
                    return Err(self.err(
                        start,
                        self.pos + 1,
                        "leading zeros are not allowed in JSON numbers",
                    ));
                }
            }
            Some(b'1'..=b'9') => self.digits(),
            _ => {
                return Err(
                    self.err_here(format!("expected a digit, found {}", self.describe_here()))
                )
            }
        }
        if self.peek() == Some(b'.') {
            self.pos += 1;
            if !matches!(self.peek(), Some(b'0'..=b'9')) {
                return Err(self.err_here("expected a digit after the decimal point"));
            }
            self.digits();
        }
        if let Some(b'e' | b'E') = self.peek() {
            self.pos += 1;
            if let Some(b'+' | b'-') = self.peek() {
                self.pos += 1;
            }
            if !matches!(self.peek(), Some(b'0'..=b'9')) {
                return Err(self.err_here("expected a digit in the exponent"));
            }
            self.digits();
        }
        let raw = self.text.get(start..self.pos).unwrap_or("").to_string();
        Ok(RecipeValue::new(
            ValueKind::Number(NumberText { raw, radix: 10 }),
            Span::new(start, self.pos),
        ))
    }

    fn digits(&mut self) {
        while let Some(b'0'..=b'9') = self.peek() {
            self.pos += 1;
        }
    }
}
