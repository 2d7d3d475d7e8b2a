//! Recipes: reading TOML or JSON files into a list of [`RecipeObject`]s with positions.
//!
//! A recipe is a list of objects, each with a unique `name`, an `op` and the op's
//! parameters:
//!
//! ```toml
//! [[object]]
//! name = "quarter"
//! op = "circle_arc"
//! center = [0, 0]
//! radius = 1
//! ```
//!
//! or in JSON `{"object": [{"name": "quarter", "op": "circle_arc", …}]}`.
//! The format is chosen by the file extension (`.toml`, `.json`), otherwise by the
//! content (a document starting with `{` is JSON).

pub mod json;
pub mod toml;
pub mod tree;

use crate::source::{clip, closest, Diagnostic, SourceFile, Span};
pub use tree::{Entry, NumberText, RecipeValue, ValueKind};

/// The two recipe syntaxes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// TOML, `[[object]]` tables.
    Toml,
    /// JSON, `{"object": [ … ]}`.
    Json,
}

impl Format {
    /// The format for a file name: by extension, else `None`.
    pub fn from_extension(path: &str) -> Option<Format> {
        let ext = std::path::Path::new(path)
            .extension()?
            .to_str()?
            .to_ascii_lowercase();
        match ext.as_str() {
            "toml" => Some(Format::Toml),
            "json" => Some(Format::Json),
            _ => None,
        }
    }

    /// Guesses the format from the text: JSON if the first non-blank character is `{`.
    pub fn sniff(text: &str) -> Format {
        match text
            .trim_start_matches('\u{feff}')
            .trim_start()
            .chars()
            .next()
        {
            Some('{') => Format::Json,
            _ => Format::Toml,
        }
    }
}

/// One `[[object]]` of a recipe.
#[derive(Debug, Clone)]
pub struct RecipeObject {
    /// The unique name (also the output file stem).
    pub name: String,
    /// The op name.
    pub op: String,
    /// Where the `op` key is written (construction errors point here).
    pub op_key_span: Span,
    /// Where the op's value is written (unknown-op errors point here).
    pub op_span: Span,
    /// The object's table (TOML: the `[[object]]` header; JSON: the `{ … }`).
    pub span: Span,
    /// All other entries: the op's parameters, in source order.
    pub params: Vec<Entry>,
}

/// A parsed recipe: its source and its objects.
#[derive(Debug, Clone)]
pub struct Recipe {
    /// The source (for positions in diagnostics).
    pub file: SourceFile,
    /// The objects in source order.
    pub objects: Vec<RecipeObject>,
}

/// The longest accepted object name.
pub const MAX_NAME_LEN: usize = 100;

/// Checks that an object name is usable as a file name stem on every platform.
pub fn check_name(name: &str) -> Result<(), String> {
    if name.is_empty() {
        return Err("the object name is empty".into());
    }
    if name.chars().count() > MAX_NAME_LEN {
        return Err(format!(
            "the object name is longer than {MAX_NAME_LEN} characters"
        ));
    }
    if name.starts_with('.') {
        return Err("the object name must not start with '.'".into());
    }
    if let Some(c) = name
        .chars()
        .find(|c| !(c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.')))
    {
        return Err(format!(
            "the object name contains {c:?}; use letters, digits, '_', '-' and '.' (it becomes a file name)"
        ));
    }
    Ok(())
}

impl Recipe {
    /// Reads a recipe from raw bytes; `file_name` is used for the format (by
    /// extension) and in diagnostics.
    ///
    /// # Errors
    /// All problems found, each with its position.
    pub fn from_bytes(
        file_name: &str,
        bytes: &[u8],
        format: Option<Format>,
    ) -> Result<Recipe, Vec<Diagnostic>> {
        match std::str::from_utf8(bytes) {
            Ok(text) => Recipe::parse(file_name, text, format),
            Err(e) => {
                let lossy = String::from_utf8_lossy(bytes.get(..e.valid_up_to()).unwrap_or(&[]));
                let file = SourceFile::new(file_name, lossy.as_ref());
                let at = lossy.len();
                Err(vec![file.error(
                    Span::new(at, at),
                    format!("the file is not valid UTF-8 (byte {})", e.valid_up_to() + 1),
                )])
            }
        }
    }

    /// Parses a recipe text. `format`: forced format, else by extension of
    /// `file_name`, else by content.
    ///
    /// # Errors
    /// All problems found, each with its position.
    pub fn parse(
        file_name: &str,
        text: &str,
        format: Option<Format>,
    ) -> Result<Recipe, Vec<Diagnostic>> {
        let file = SourceFile::new(file_name, text);
        let by_extension = format.is_none() && Format::from_extension(file_name).is_some();
        let format = format
            .or_else(|| Format::from_extension(file_name))
            .unwrap_or_else(|| Format::sniff(text));
        let parse = |f: Format| match f {
            Format::Toml => toml::parse(text),
            Format::Json => json::parse(text),
        };
        let name = |f: Format| match f {
            Format::Toml => "TOML",
            Format::Json => "JSON",
        };
        let root = parse(format).map_err(|e| {
            let mut d = file.error(
                e.span,
                format!("{} syntax error: {}", name(format), e.message),
            );
            // a `.json` file holding TOML (or the reverse): the extension chose the format
            let other = match format {
                Format::Toml => Format::Json,
                Format::Json => Format::Toml,
            };
            if by_extension && parse(other).is_ok() {
                d = d.note(format!(
                    "the file's extension chose {}, but the file reads as {}: rename it to \
                     `.{}`",
                    name(format),
                    name(other),
                    name(other).to_ascii_lowercase()
                ));
            }
            vec![d]
        })?;
        let objects = objects(&file, &root, format)?;
        Ok(Recipe { file, objects })
    }
}

fn objects(
    file: &SourceFile,
    root: &RecipeValue,
    format: Format,
) -> Result<Vec<RecipeObject>, Vec<Diagnostic>> {
    let shape_note = match format {
        Format::Toml => "a recipe is a list of [[object]] tables, each with `name`, `op` and the op's parameters",
        Format::Json => "a JSON recipe is {\"object\": [ {\"name\": …, \"op\": …, …}, … ]}",
    };
    let Some(entries) = root.as_table() else {
        return Err(vec![file
            .error(
                root.span,
                format!(
                    "expected the recipe to be a table, found {}",
                    crate::value::describe(root)
                ),
            )
            .note(shape_note)]);
    };
    let mut diags = Vec::new();
    let mut list = None;
    for e in entries {
        if e.key == "object" {
            list = Some(e);
        } else {
            let mut d = file.error(
                e.key_span,
                format!("unknown top-level key `{}`", clip(&e.key)),
            );
            if let Some(s) = closest(&e.key, ["object"]) {
                d = d.note(format!("did you mean `{s}`?"));
            }
            diags.push(d.note(shape_note));
        }
    }
    let Some(list) = list else {
        let span = match format {
            Format::Toml => Span::new(0, 0),
            Format::Json => root.span,
        };
        diags.push(
            file.error(span, "the recipe has no objects")
                .note(shape_note),
        );
        return Err(diags);
    };
    let Some(items) = list.value.as_array() else {
        diags.push(
            file.error(
                list.value.span,
                format!(
                    "`object` must be an array of tables, found {}",
                    crate::value::describe(&list.value)
                ),
            )
            .note(shape_note),
        );
        return Err(diags);
    };
    if items.is_empty() {
        diags.push(
            file.error(list.value.span, "the recipe has no objects")
                .note(shape_note),
        );
    }
    let mut out: Vec<RecipeObject> = Vec::new();
    let mut seen: Vec<(String, Span)> = Vec::new();
    for item in items {
        match object(file, item) {
            Ok(o) => {
                if let Some((_, first)) = seen.iter().find(|(n, _)| *n == o.name) {
                    let first = file.line_col(first.start);
                    let at = item.get("name").map_or(item.span, |e| e.value.span);
                    diags.push(
                        file.error(at, format!("duplicate object name {:?}", clip(&o.name)))
                            .note(format!(
                                "the first object called {:?} is at line {}, column {}; names must be unique",
                                o.name, first.line, first.column
                            )),
                    );
                } else {
                    let at = item.get("name").map_or(item.span, |e| e.value.span);
                    seen.push((o.name.clone(), at));
                    out.push(o);
                }
            }
            Err(d) => diags.push(d),
        }
    }
    if diags.is_empty() {
        Ok(out)
    } else {
        Err(diags)
    }
}

fn object(file: &SourceFile, item: &RecipeValue) -> Result<RecipeObject, Diagnostic> {
    let Some(entries) = item.as_table() else {
        return Err(file.error(
            item.span,
            format!(
                "expected an object table, found {}",
                crate::value::describe(item)
            ),
        ));
    };
    let string_field = |key: &str| -> Result<(&Entry, String), Diagnostic> {
        let e = entries.iter().find(|e| e.key == key).ok_or_else(|| {
            file.error(item.span, format!("the object has no `{key}`"))
                .note("every object needs `name` (unique) and `op` (see `rcagd ops`)")
        })?;
        match &e.value.kind {
            ValueKind::String(s) => Ok((e, s.clone())),
            _ => Err(file.error(
                e.value.span,
                format!(
                    "`{key}` must be a string, found {}",
                    crate::value::describe(&e.value)
                ),
            )),
        }
    };
    let (name_entry, name) = string_field("name")?;
    check_name(&name).map_err(|m| file.error(name_entry.value.span, m))?;
    let (op_entry, op) = string_field("op")?;
    Ok(RecipeObject {
        name,
        op,
        op_key_span: op_entry.key_span,
        op_span: op_entry.value.span,
        span: item.span,
        params: entries
            .iter()
            .filter(|e| e.key != "name" && e.key != "op")
            .cloned()
            .collect(),
    })
}
