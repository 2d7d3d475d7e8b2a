//! Unit tests of `rcagd_cli::source` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_cli::source::*;

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
fn long_text_is_clipped_around_the_caret() {
    let name = "é".repeat(1_000_000);
    let f = SourceFile::new("r.toml", format!("op = 1\nname = \"{name}\" # tail\n"));
    let d = f.error(
        Span::new(14, 16 + name.len()),
        format!("bad name {}", clip(&name)),
    );
    let s = d.to_string();
    assert!(s.len() < 3 * 4 * MAX_SHOWN, "{} bytes", s.len());
    assert!(s.starts_with("r.toml:2:8: error: bad name éé"), "{s}");
    assert!(s.contains(&format!("… ({} bytes)\n", name.len())), "{s}");
    // the window starts at the line's start (the caret is near it) and is cut after
    let lines: Vec<&str> = s.lines().collect();
    assert!(
        lines[2].starts_with("2 | name = \"éé") && lines[2].ends_with('…'),
        "{s}"
    );
    assert_eq!(
        lines[3],
        format!("  |        {}", "^".repeat(MAX_SHOWN - 7))
    );
    // a caret far into a long line: the window moves to it, marked at both ends
    let long = format!("{}X{}", "a".repeat(5000), "b".repeat(5000));
    let f = SourceFile::new("r.toml", long.clone());
    let s = f.error(Span::new(5000, 5001), "here").to_string();
    let lines: Vec<&str> = s.lines().collect();
    let caret = lines[3].find('^').expect("caret");
    assert_eq!(lines[2].chars().nth(caret), Some('X'), "{s}");
    assert!(
        lines[2].starts_with("1 | …a") && lines[2].ends_with("b…"),
        "{s}"
    );
    assert_eq!(clip("short"), "short");
    // the safety net: a message line is cut after MAX_LINE characters
    let s = f
        .error(Span::new(0, 1), "m".repeat(10 * MAX_LINE))
        .to_string();
    assert!(
        s.starts_with(&format!(
            "r.toml:1:1: error: {}… (20000 bytes)\n",
            "m".repeat(MAX_LINE)
        )),
        "{s}"
    );
}

#[test]
fn many_diagnostics_are_capped_and_long_notes_not_repeated() {
    let f = SourceFile::new("r.toml", "k = 1\n".repeat(20_000));
    let list = "parameters of `circle`:\n  radius: number".to_string();
    let diags: Vec<Diagnostic> = (0..20_000)
        .map(|i| {
            f.error(Span::new(6 * i, 6 * i + 1), "unknown parameter `k`")
                .note("did you mean `x`?")
                .note(list.clone())
        })
        .collect();
    let s = render_all(&diags);
    assert_eq!(
        s.matches("error: unknown parameter").count(),
        MAX_DIAGNOSTICS
    );
    assert_eq!(s.matches("radius: number").count(), 1, "{s}");
    assert_eq!(
        s.matches("parameters of `circle` (as above)").count(),
        MAX_DIAGNOSTICS - 1
    );
    assert_eq!(s.matches("did you mean").count(), MAX_DIAGNOSTICS);
    assert!(
        s.ends_with("… and 19950 more errors (the first 50 are shown)\n20000 errors\n"),
        "{s}"
    );
    assert_eq!(render_all(&diags[..1]), diags[0].to_string());
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
