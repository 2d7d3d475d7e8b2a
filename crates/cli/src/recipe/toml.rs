//! TOML recipes: parsed with the `toml` crate's spanned document API
//! ([`toml::de::DeTable::parse`]), which keeps the position of every key and value
//! and the source text of every number, then converted into a [`RecipeValue`] tree.
//!
//! `DeTable` stores keys sorted; entries are put back into source order by their
//! spans. The spanned table of an `[[object]]` spans its header.

use super::json::SyntaxError;
use super::tree::{Entry, NumberText, RecipeValue, ValueKind};
use crate::source::Span;
use toml::de::{DeTable, DeValue};
use toml::Spanned;

/// The deepest nesting converted (the `toml` parser itself stops at 80 levels).
const MAX_DEPTH: usize = 128;

/// Parses a TOML document into a value tree (a table).
///
/// # Errors
/// The parser's first error with its span, or an error for nesting beyond the limit.
pub fn parse(text: &str) -> Result<RecipeValue, SyntaxError> {
    let doc = DeTable::parse(text).map_err(|e| {
        let span = e.span().map(Span::from).unwrap_or_default();
        SyntaxError {
            span,
            message: e.message().trim().to_string(),
        }
    })?;
    let span = Span::new(0, text.len());
    let entries = table(doc.get_ref(), 0)?;
    Ok(RecipeValue::new(ValueKind::Table(entries), span))
}

fn table(t: &DeTable<'_>, depth: usize) -> Result<Vec<Entry>, SyntaxError> {
    let mut entries = Vec::with_capacity(t.len());
    for (k, v) in t.iter() {
        entries.push(Entry {
            key: k.get_ref().to_string(),
            key_span: Span::from(k.span()),
            value: value(v, depth + 1)?,
        });
    }
    entries.sort_by_key(|e| (e.key_span.start, e.value.span.start));
    Ok(entries)
}

fn value(v: &Spanned<DeValue<'_>>, depth: usize) -> Result<RecipeValue, SyntaxError> {
    let span = Span::from(v.span());
    if depth > MAX_DEPTH {
        return Err(SyntaxError {
            span,
            message: format!("nesting deeper than {MAX_DEPTH} levels"),
        });
    }
    let kind = match v.get_ref() {
        DeValue::String(s) => ValueKind::String(s.to_string()),
        DeValue::Integer(i) => ValueKind::Number(NumberText {
            raw: i.as_str().to_string(),
            radix: i.radix(),
        }),
        DeValue::Float(f) => ValueKind::Number(NumberText {
            raw: f.as_str().to_string(),
            radix: 10,
        }),
        DeValue::Boolean(b) => ValueKind::Bool(*b),
        DeValue::Datetime(d) => ValueKind::Datetime(d.to_string()),
        DeValue::Array(a) => ValueKind::Array(
            a.iter()
                .map(|x| value(x, depth + 1))
                .collect::<Result<_, _>>()?,
        ),
        DeValue::Table(t) => ValueKind::Table(table(t, depth)?),
    };
    Ok(RecipeValue::new(kind, span))
}
