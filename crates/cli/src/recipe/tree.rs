//! The format-independent value tree of a recipe, with source positions.
//!
//! TOML and JSON recipes are both converted into [`RecipeValue`]s, so the ops and the
//! parameter checks see one representation. Numbers keep their source text (never an
//! `f64`), so that `0.1` is read as exactly 1/10.

use crate::source::Span;

/// The source text of a number literal.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NumberText {
    /// Digits as written (TOML underscores removed; without the `0x`/`0o`/`0b` prefix).
    pub raw: String,
    /// 10, or 16/8/2 for TOML's prefixed integers.
    pub radix: u32,
}

/// One `key = value` entry of a table, in source order.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// The key.
    pub key: String,
    /// Where the key is written.
    pub key_span: Span,
    /// The value.
    pub value: RecipeValue,
}

/// The kinds of recipe values.
#[derive(Debug, Clone, PartialEq)]
pub enum ValueKind {
    /// A number literal (integer or decimal), exact text.
    Number(NumberText),
    /// A string.
    String(String),
    /// `true` / `false`.
    Bool(bool),
    /// JSON `null`.
    Null,
    /// A TOML date/time (never valid as a parameter, kept for the error message).
    Datetime(String),
    /// An array.
    Array(Vec<RecipeValue>),
    /// A table (TOML table, JSON object), entries in source order.
    Table(Vec<Entry>),
}

/// A recipe value with its position in the source.
#[derive(Debug, Clone, PartialEq)]
pub struct RecipeValue {
    /// What the value is.
    pub kind: ValueKind,
    /// Where it is written.
    pub span: Span,
}

impl RecipeValue {
    /// A value of the given kind at `span`.
    pub fn new(kind: ValueKind, span: Span) -> Self {
        RecipeValue { kind, span }
    }

    /// The type name used in messages: "number", "string", "array", …
    pub fn type_name(&self) -> &'static str {
        match &self.kind {
            ValueKind::Number(_) => "number",
            ValueKind::String(_) => "string",
            ValueKind::Bool(_) => "boolean",
            ValueKind::Null => "null",
            ValueKind::Datetime(_) => "date-time",
            ValueKind::Array(_) => "array",
            ValueKind::Table(_) => "table",
        }
    }

    /// The entries if this is a table.
    pub fn as_table(&self) -> Option<&[Entry]> {
        match &self.kind {
            ValueKind::Table(t) => Some(t),
            _ => None,
        }
    }

    /// The elements if this is an array.
    pub fn as_array(&self) -> Option<&[RecipeValue]> {
        match &self.kind {
            ValueKind::Array(a) => Some(a),
            _ => None,
        }
    }

    /// The string if this is a string.
    pub fn as_str(&self) -> Option<&str> {
        match &self.kind {
            ValueKind::String(s) => Some(s),
            _ => None,
        }
    }

    /// The entry `key` of a table.
    pub fn get(&self, key: &str) -> Option<&Entry> {
        self.as_table()?.iter().find(|e| e.key == key)
    }

    /// A short rendering of the value for messages (`"abc"`, `1.5`, `[…]`).
    pub fn preview(&self) -> String {
        match &self.kind {
            ValueKind::Number(n) => match n.radix {
                16 => format!("0x{}", n.raw),
                8 => format!("0o{}", n.raw),
                2 => format!("0b{}", n.raw),
                _ => crate::source::clip(&n.raw).into_owned(),
            },
            ValueKind::String(s) => {
                let short: String = s.chars().take(40).collect();
                if short.len() < s.len() {
                    format!("{short:?}…")
                } else {
                    format!("{s:?}")
                }
            }
            ValueKind::Bool(b) => b.to_string(),
            ValueKind::Null => "null".into(),
            ValueKind::Datetime(d) => d.clone(),
            ValueKind::Array(_) => "[…]".into(),
            ValueKind::Table(_) => "{…}".into(),
        }
    }
}
