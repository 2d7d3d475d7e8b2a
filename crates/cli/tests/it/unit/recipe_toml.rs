//! Unit tests of `rcagd_cli::recipe::toml` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_cli::recipe::toml::*;
use rcagd_cli::recipe::{NumberText, ValueKind};

#[test]
fn keeps_number_text_and_order() {
    let src = "[[object]]\nname = \"a\"\nop = \"x\"\nz = 0.1\nb = [1_000, 0x1F, -2e-3]\n";
    let v = parse(src).unwrap();
    let objs = v.get("object").unwrap().value.as_array().unwrap();
    let keys: Vec<&str> = objs[0]
        .as_table()
        .unwrap()
        .iter()
        .map(|e| e.key.as_str())
        .collect();
    assert_eq!(keys, ["name", "op", "z", "b"]);
    let z = &objs[0].get("z").unwrap().value;
    assert_eq!(
        z.kind,
        ValueKind::Number(NumberText {
            raw: "0.1".into(),
            radix: 10
        })
    );
    assert_eq!(&src[z.span.start..z.span.end], "0.1");
    let b = objs[0].get("b").unwrap().value.as_array().unwrap();
    assert_eq!(b[0].preview(), "1000");
    assert_eq!(b[1].preview(), "0x1F");
    assert_eq!(b[2].preview(), "-2e-3");
}

#[test]
fn syntax_error_has_span() {
    let e = parse("a = [1, 2\n").unwrap_err();
    assert!(e.message.contains("unclosed array"), "{}", e.message);
    assert_eq!(e.span.start, 9);
}
