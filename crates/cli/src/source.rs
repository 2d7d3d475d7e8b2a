//! Source files, byte spans, line/column positions and diagnostics.
//!
//! Every problem the CLI reports about a recipe is a [`Diagnostic`]: a message, the
//! file, a 1-based line and column (columns count Unicode scalar values, not bytes),
//! a snippet of the offending line with a caret, and optional notes. The first line
//! of a rendered diagnostic is `file:line:column: error: message`, the form editors
//! and `grep` understand.

use std::fmt;

/// A half-open byte range `start..end` into a source text.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Span {
    /// First byte.
    pub start: usize,
    /// One past the last byte.
    pub end: usize,
}

impl Span {
    /// The span `start..end`.
    pub fn new(start: usize, end: usize) -> Self {
        Span {
            start,
            end: end.max(start),
        }
    }
}

impl From<std::ops::Range<usize>> for Span {
    fn from(r: std::ops::Range<usize>) -> Self {
        Span::new(r.start, r.end)
    }
}

/// A 1-based line and column (in characters).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LineCol {
    /// Line number, starting at 1.
    pub line: usize,
    /// Column number in characters, starting at 1.
    pub column: usize,
}

/// A named source text with a line index.
#[derive(Debug, Clone)]
pub struct SourceFile {
    name: String,
    text: String,
    line_starts: Vec<usize>,
}

impl SourceFile {
    /// A source file called `name` (shown in diagnostics) with the given text.
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> Self {
        let text = text.into();
        let mut line_starts = vec![0];
        line_starts.extend(
            text.bytes()
                .enumerate()
                .filter(|&(_, b)| b == b'\n')
                .map(|(i, _)| i + 1),
        );
        SourceFile {
            name: name.into(),
            text,
            line_starts,
        }
    }

    /// The name shown in diagnostics.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The full text.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Clamps a byte offset into the text and onto a character boundary.
    fn clamp(&self, offset: usize) -> usize {
        let mut o = offset.min(self.text.len());
        while o > 0 && !self.text.is_char_boundary(o) {
            o -= 1;
        }
        o
    }

    /// The 0-based line index containing byte `offset`.
    fn line_index(&self, offset: usize) -> usize {
        match self.line_starts.binary_search(&offset) {
            Ok(i) => i,
            Err(i) => i.saturating_sub(1),
        }
    }

    /// The 1-based line and column of a byte offset (clamped into the text).
    pub fn line_col(&self, offset: usize) -> LineCol {
        let o = self.clamp(offset);
        let li = self.line_index(o);
        let start = self.line_starts.get(li).copied().unwrap_or(0);
        let column = self.text.get(start..o).map_or(0, |s| s.chars().count()) + 1;
        LineCol {
            line: li + 1,
            column,
        }
    }

    /// The text of the 1-based line `line`, without its line terminator.
    pub fn line_text(&self, line: usize) -> &str {
        let Some(&start) = self.line_starts.get(line.wrapping_sub(1)) else {
            return "";
        };
        let end = self
            .line_starts
            .get(line)
            .copied()
            .unwrap_or(self.text.len());
        self.text
            .get(start..end)
            .unwrap_or("")
            .trim_end_matches(['\n', '\r'])
    }

    /// A diagnostic at `span` of this file.
    pub fn error(&self, span: Span, message: impl Into<String>) -> Diagnostic {
        let start = self.clamp(span.start);
        let end = self.clamp(span.end.max(span.start));
        let pos = self.line_col(start);
        let line_text = self.line_text(pos.line);
        // Caret width: the span's characters on its first line, at least one.
        let line_end_col = line_text.chars().count() + 1;
        let end_pos = self.line_col(end);
        let width = if end_pos.line == pos.line {
            end_pos.column.saturating_sub(pos.column)
        } else {
            line_end_col.saturating_sub(pos.column)
        }
        .max(1);
        Diagnostic {
            file: self.name.clone(),
            line: pos.line,
            column: pos.column,
            message: message.into(),
            snippet: Some(Box::new(Snippet::window(line_text, pos.column - 1, width))),
            notes: Vec::new(),
        }
    }
}

/// The most characters of user text (a name, a value, a source line) that a message
/// shows; longer text is cut by [`clip`].
pub const MAX_SHOWN: usize = 200;

/// `s` itself when it has at most [`MAX_SHOWN`] characters, else its first
/// [`MAX_SHOWN`] characters followed by `… (N bytes)`: error output stays bounded
/// whatever the user wrote (a 10 MB object name is not echoed).
pub fn clip(s: &str) -> std::borrow::Cow<'_, str> {
    clip_to(s, MAX_SHOWN)
}

/// The most characters of one line of a message or note: a safety net for user text
/// that reaches a message without [`clip`] (an op's list of names is longer than
/// [`MAX_SHOWN`]).
pub const MAX_LINE: usize = 2000;

/// `s` cut after `max` characters, with `… (N bytes)`.
fn clip_to(s: &str, max: usize) -> std::borrow::Cow<'_, str> {
    match s.char_indices().nth(max) {
        None => std::borrow::Cow::Borrowed(s),
        Some((cut, _)) => std::borrow::Cow::Owned(format!("{}… ({} bytes)", &s[..cut], s.len())),
    }
}

/// The source line shown under a diagnostic: at most [`MAX_SHOWN`] characters of it
/// around the caret (`…` marks a cut).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Snippet {
    line_text: String,
    /// 0-based character position of the caret in `line_text`.
    caret: usize,
    width: usize,
}

impl Snippet {
    /// The window of `line` shown for a caret at character `col` (0-based) of `width`
    /// characters.
    fn window(line: &str, col: usize, width: usize) -> Snippet {
        let n = line.chars().count();
        if n <= MAX_SHOWN {
            return Snippet {
                line_text: line.to_string(),
                caret: col,
                width,
            };
        }
        // a little context before the caret, the rest after it
        let first = col
            .saturating_sub(MAX_SHOWN / 5)
            .min(n.saturating_sub(MAX_SHOWN));
        let last = (first + MAX_SHOWN).min(n);
        let mut text = String::new();
        if first > 0 {
            text.push('…');
        }
        text.extend(line.chars().skip(first).take(last - first));
        if last < n {
            text.push('…');
        }
        let caret = col.saturating_sub(first) + usize::from(first > 0);
        Snippet {
            line_text: text,
            caret,
            width: width.min(last.saturating_sub(col)).max(1),
        }
    }
}

/// A located error message about an input file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Diagnostic {
    /// File name as given by the user.
    pub file: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column (characters).
    pub column: usize,
    /// The main message.
    pub message: String,
    snippet: Option<Box<Snippet>>,
    /// Extra lines: hints, expected parameters, the list of ops.
    pub notes: Vec<String>,
}

impl Diagnostic {
    /// A diagnostic about a whole file (no position inside it): reported at 1:1.
    pub fn whole_file(file: impl Into<String>, message: impl Into<String>) -> Self {
        Diagnostic {
            file: file.into(),
            line: 1,
            column: 1,
            message: message.into(),
            snippet: None,
            notes: Vec::new(),
        }
    }

    /// Adds a note line.
    pub fn note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(note.into());
        self
    }

    /// Adds several note lines.
    pub fn notes(mut self, notes: impl IntoIterator<Item = String>) -> Self {
        self.notes.extend(notes);
        self
    }
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{}:{}:{}: error: {}",
            clip_to(&self.file, MAX_LINE),
            self.line,
            self.column,
            clip_lines(&self.message)
        )?;
        if let Some(s) = &self.snippet {
            let num = self.line.to_string();
            let pad = " ".repeat(num.len());
            // Replace tabs so that the caret lines up.
            let text: String = s
                .line_text
                .chars()
                .map(|c| if c == '\t' { ' ' } else { c })
                .collect();
            writeln!(f, "{pad} |")?;
            writeln!(f, "{num} | {text}")?;
            writeln!(f, "{pad} | {}{}", " ".repeat(s.caret), "^".repeat(s.width))?;
        }
        for n in &self.notes {
            for (i, l) in n.lines().map(|l| clip_to(l, MAX_LINE)).enumerate() {
                if i == 0 {
                    writeln!(f, "  = {l}")?;
                } else {
                    writeln!(f, "    {l}")?;
                }
            }
        }
        Ok(())
    }
}

/// The most diagnostics [`render_all`] prints for one input.
pub const MAX_DIAGNOSTICS: usize = 50;

/// Renders diagnostics for the terminal, bounded whatever the input: at most
/// [`MAX_DIAGNOSTICS`] of them, then `… and N more errors`; a note of several lines
/// (an op's parameter list) is printed in full once, later repeats as its first line
/// with `(as above)`; a final count when there is more than one.
pub fn render_all(diags: &[Diagnostic]) -> String {
    let mut out = String::new();
    let mut shown: std::collections::HashSet<&str> = std::collections::HashSet::new();
    for d in diags.iter().take(MAX_DIAGNOSTICS) {
        let mut d2 = d.clone();
        d2.notes = d
            .notes
            .iter()
            .map(|n| {
                if !n.contains('\n') || shown.insert(n.as_str()) {
                    n.clone()
                } else {
                    let first = n.lines().next().unwrap_or("");
                    format!("{} (as above)", first.trim_end_matches(':'))
                }
            })
            .collect();
        out.push_str(&d2.to_string());
    }
    if diags.len() > MAX_DIAGNOSTICS {
        out.push_str(&format!(
            "… and {} more errors (the first {MAX_DIAGNOSTICS} are shown)\n",
            diags.len() - MAX_DIAGNOSTICS
        ));
    }
    if diags.len() > 1 {
        out.push_str(&format!("{} errors\n", diags.len()));
    }
    out
}

/// Every line of `s` cut after [`MAX_LINE`] characters.
fn clip_lines(s: &str) -> String {
    s.lines()
        .map(|l| clip_to(l, MAX_LINE))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The edit distance between two strings (for "did you mean …?" suggestions).
pub fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    let mut cur = vec![0; b.len() + 1];
    for (i, ca) in a.iter().enumerate() {
        cur[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != cb);
            cur[j + 1] = sub.min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    prev[b.len()]
}

/// The candidate closest to `word`, if it is close enough to be a plausible typo.
pub fn closest<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let lw = word.to_ascii_lowercase();
    let len = lw.chars().count();
    candidates
        .into_iter()
        .filter_map(|c| {
            let limit = (c.chars().count() / 3).max(2);
            // the distance is at least the difference of the lengths: a 10 MB word is
            // not compared character by character with every op name
            if len.abs_diff(c.chars().count()) > limit {
                return None;
            }
            let d = edit_distance(&lw, &c.to_ascii_lowercase());
            (d <= limit).then_some((d, c))
        })
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}
