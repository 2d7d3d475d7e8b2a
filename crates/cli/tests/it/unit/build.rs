//! Unit tests of `rcagd_cli::build` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_cli::build::*;
use rcagd_cli::ops;
use rcagd_cli::recipe::Recipe;
use rcagd_cli::source::{Diagnostic, SourceFile, Span};
use rcagd_cli::{EXIT_FAIL, EXIT_INPUT};

fn errors(src: &str) -> Vec<Diagnostic> {
    let r = Recipe::parse("r.toml", src, None).unwrap();
    build_recipe(&r, |_| {}).unwrap_err()
}

#[test]
fn every_default_is_valid() {
    for op in ops::all() {
        for p in op.params {
            assert!(default_value(p).is_ok(), "{}.{}", op.name, p.name);
            assert!(
                !(p.required && p.default.is_some()),
                "{}.{}",
                op.name,
                p.name
            );
        }
    }
}

#[test]
fn op_names_are_unique() {
    let names: Vec<&str> = ops::all().map(|o| o.name).collect();
    for (i, n) in names.iter().enumerate() {
        assert!(!names[..i].contains(n), "duplicate op {n}");
    }
}

/// The examples are built once for this test and `docs::every_op_example_builds`
/// (`common::op_examples`).
#[test]
fn every_example_builds_and_holds() {
    let examples = crate::common::op_examples();
    assert_eq!(
        examples.iter().map(|ex| ex.op).collect::<Vec<_>>(),
        ops::all().map(|op| op.name).collect::<Vec<_>>()
    );
    for ex in examples {
        let recipe_ops = ex
            .recipe_ops
            .as_ref()
            .unwrap_or_else(|e| panic!("{}: {e}", ex.op));
        assert!(
            recipe_ops.iter().any(|o| o == ex.op),
            "{} example does not use it",
            ex.op
        );
        let objs = match &ex.built {
            Some(Ok(objs)) => objs,
            Some(Err(e)) => panic!("{}: {e}", ex.op),
            None => panic!("{}: not built", ex.op),
        };
        for o in objs {
            assert!(
                o.certificates.iter().all(|c| c.holds),
                "{}: {:?}",
                ex.op,
                o.certificates
            );
        }
    }
}

#[test]
fn an_internal_error_exits_1_and_an_input_error_2() {
    let file = SourceFile::new("r.toml", "x");
    let e = |m: &str| vec![file.error(Span::default(), m.to_string())];
    let panicked = "cannot build \"a\" (op `circle`): internal error (please report): the construction panicked: x";
    assert_eq!(build_error_exit(&e(panicked)), EXIT_FAIL);
    assert_eq!(
        build_error_exit(&e("internal error: default of `x`")),
        EXIT_FAIL
    );
    assert_eq!(
        build_error_exit(&e("unknown op \"internal error\"")),
        EXIT_INPUT
    );
    assert_eq!(
        build_error_exit(&e(
            "cannot build \"a\" (op `circle`): the radius must be positive"
        )),
        EXIT_INPUT
    );
}

#[test]
fn located_errors() {
    let d = errors("[[object]]\nname = \"a\"\nop = \"bezier_curv\"\n");
    assert_eq!((d[0].line, d[0].column), (3, 6));
    assert!(
        d[0].to_string().contains("did you mean \"bezier_curve\""),
        "{}",
        d[0]
    );
    let d =
        errors("[[object]]\nname = \"a\"\nop = \"bezier_curve\"\npoints = [[0, 0]]\npoint = 1\n");
    assert_eq!((d[0].line, d[0].column), (5, 1));
    assert!(
        d[0].message.contains("unknown parameter `point`"),
        "{}",
        d[0]
    );
    let d = errors("[[object]]\nname = \"a\"\nop = \"bezier_curve\"\n");
    assert_eq!((d[0].line, d[0].column), (1, 1));
    assert!(
        d[0].message.contains("needs the parameter `points`"),
        "{}",
        d[0]
    );
    assert!(
        d[0].to_string()
            .contains("points: list of points (required)"),
        "{}",
        d[0]
    );
    let d =
        errors("[[object]]\nname = \"a\"\nop = \"bezier_curve\"\npoints = [[0, 0], [1, \"x\"]]\n");
    assert_eq!((d[0].line, d[0].column), (4, 23));
    assert!(d[0].message.contains("not a number: \"x\""), "{}", d[0]);
    let d = errors("[[object]]\nname = \"a\"\nop = \"bezier_curve\"\npoints = [[0, 0], [1, 1]]\nweights = [1]\n");
    assert_eq!((d[0].line, d[0].column), (5, 11));
    assert!(
        d[0].message.contains("2 control points but 1 weights"),
        "{}",
        d[0]
    );
}
