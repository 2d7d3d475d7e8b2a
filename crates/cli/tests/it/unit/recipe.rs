//! Unit tests of `rcagd_cli::recipe` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_cli::recipe::*;
use rcagd_cli::source::Diagnostic;

fn first_error(name: &str, src: &str) -> Diagnostic {
    Recipe::parse(name, src, None).unwrap_err().remove(0)
}

#[test]
fn reads_toml_and_json_alike() {
    let t = Recipe::parse(
        "r.toml",
        "[[object]]\nname = \"a\"\nop = \"circle\"\nradius = 2\n",
        None,
    )
    .unwrap();
    let j = Recipe::parse(
        "r.json",
        "{\"object\": [{\"name\": \"a\", \"op\": \"circle\", \"radius\": 2}]}",
        None,
    )
    .unwrap();
    for r in [&t, &j] {
        assert_eq!(r.objects.len(), 1);
        assert_eq!(r.objects[0].name, "a");
        assert_eq!(r.objects[0].op, "circle");
        assert_eq!(r.objects[0].params.len(), 1);
        assert_eq!(r.objects[0].params[0].key, "radius");
    }
    let p = t.file.line_col(t.objects[0].op_key_span.start);
    assert_eq!((p.line, p.column), (3, 1));
}

#[test]
fn extension_that_chose_the_wrong_format_is_named() {
    let toml_text = "[[object]]\nname = \"c\"\nop = \"circle\"\nradius = 1\n";
    let json_text = r#"{"object": [{"name": "c", "op": "circle", "radius": 1}]}"#;
    let s = first_error("r.json", toml_text).to_string();
    assert!(s.contains("JSON syntax error"), "{s}");
    assert!(
        s.contains(
            "the file's extension chose JSON, but the file reads as TOML: rename it to `.toml`"
        ),
        "{s}"
    );
    let s = first_error("r.toml", json_text).to_string();
    assert!(s.contains("TOML syntax error"), "{s}");
    assert!(s.contains("reads as JSON: rename it to `.json`"), "{s}");
    // broken in both formats, or the format forced: no hint
    let s = first_error("r.json", "[[object]\n").to_string();
    assert!(!s.contains("extension"), "{s}");
    let e = Recipe::parse("r.json", toml_text, Some(Format::Json)).expect_err("JSON");
    assert!(!e[0].to_string().contains("extension"), "{}", e[0]);
}

#[test]
fn sniffs_format() {
    assert_eq!(Format::sniff("  \n{\"object\": []}"), Format::Json);
    assert_eq!(Format::sniff("[[object]]"), Format::Toml);
    let r = Recipe::parse(
        "recipe.txt",
        "{\"object\": [{\"name\": \"a\", \"op\": \"x\"}]}",
        None,
    );
    assert!(r.is_ok());
}

#[test]
fn structural_errors() {
    let d = first_error("r.toml", "[[object]]\nop = \"circle\"\n");
    assert!(d.message.contains("no `name`"), "{d}");
    assert_eq!((d.line, d.column), (1, 1));
    let d = first_error(
        "r.toml",
        "[[object]]\nname = \"a\"\nop = \"c\"\n[[object]]\nname = \"a\"\nop = \"c\"\n",
    );
    assert!(d.message.contains("duplicate object name"), "{d}");
    assert_eq!((d.line, d.column), (5, 8));
    assert!(d.to_string().contains("line 2, column 8"), "{d}");
    let d = first_error("r.toml", "[[objects]]\nname = \"a\"\n");
    assert!(d.message.contains("unknown top-level key"), "{d}");
    assert!(d.to_string().contains("did you mean `object`"), "{d}");
    let d = first_error("r.toml", "[[object]]\nname = \"a b\"\nop = \"c\"\n");
    assert!(d.message.contains("name contains"), "{d}");
    let d = first_error("r.json", "[1]");
    assert!(
        d.message.contains("expected the recipe to be a table"),
        "{d}"
    );
    let d = first_error("r.toml", "");
    assert!(d.message.contains("no objects"), "{d}");
    let d = first_error("r.toml", "[[object]]\nname = 3\n");
    assert!(d.message.contains("`name` must be a string"), "{d}");
    assert_eq!((d.line, d.column), (2, 8));
}

#[test]
fn invalid_utf8() {
    let d = Recipe::from_bytes("r.toml", b"a = 1\nb = \xff", None)
        .unwrap_err()
        .remove(0);
    assert!(d.message.contains("UTF-8"), "{d}");
    assert_eq!((d.line, d.column), (2, 5));
}
