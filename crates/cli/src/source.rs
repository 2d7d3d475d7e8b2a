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
        let line_text = self.line_text(pos.line).to_string();
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
            snippet: Some(Snippet { line_text, width }),
            notes: Vec::new(),
        }
    }
}

/// The source line shown under a diagnostic.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Snippet {
    line_text: String,
    width: usize,
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
    snippet: Option<Snippet>,
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
            self.file, self.line, self.column, self.message
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
            writeln!(
                f,
                "{pad} | {}{}",
                " ".repeat(self.column.saturating_sub(1)),
                "^".repeat(s.width)
            )?;
        }
        for n in &self.notes {
            for (i, l) in n.lines().enumerate() {
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
    candidates
        .into_iter()
        .map(|c| (edit_distance(&lw, &c.to_ascii_lowercase()), c))
        .filter(|&(d, c)| d <= (c.chars().count() / 3).max(2))
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_col_is_one_based_in_chars() {
        let f = SourceFile::new("x", "ab\nçd = 1\n\nz");
        assert_eq!(f.line_col(0), LineCol { line: 1, column: 1 });
        assert_eq!(f.line_col(3), LineCol { line: 2, column: 1 });
        // 'ç' is two bytes; 'd' is at byte 5, column 2.
        assert_eq!(f.line_col(5), LineCol { line: 2, column: 2 });
        assert_eq!(f.line_col(4), LineCol { line: 2, column: 1 }); // inside 'ç'
        assert_eq!(f.line_col(12), LineCol { line: 4, column: 1 });
        assert_eq!(f.line_col(999), LineCol { line: 4, column: 2 });
        assert_eq!(f.line_text(2), "çd = 1");
        assert_eq!(f.line_text(3), "");
        assert_eq!(f.line_text(9), "");
    }

    #[test]
    fn renders_caret() {
        let f = SourceFile::new("r.toml", "op = \"circl\"\n");
        let d = f
            .error(Span::new(5, 12), "unknown op")
            .note("did you mean?");
        let s = d.to_string();
        assert!(s.starts_with("r.toml:1:6: error: unknown op\n"), "{s}");
        assert!(s.contains("  |      ^^^^^^^\n"), "{s}");
        assert!(s.contains("  = did you mean?"), "{s}");
    }

    #[test]
    fn suggestions() {
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(
            closest("circl_arc", ["circle", "circle_arc", "cylinder_patch"]),
            Some("circle_arc")
        );
        assert_eq!(closest("zzzzzz", ["circle", "circle_arc"]), None);
    }
}
