//! The Python package's static stubs follow the op registry (`cargo test` checks what
//! only CI's Python section checked before, after a change to an op's parameters).
//!
//! `rcagd/__init__.py` creates a function for every op it does not write by hand
//! (`_op_function`: required parameters first, then the optional ones, then the
//! keyword-only `name` and `float`; a parameter spelled like a Python keyword takes a
//! trailing underscore). Their static stubs are the block between [`BEGIN`] and [`END`] of
//! `rcagd/__init__.pyi`, generated here: run
//! `RCAGD_BLESS_STUBS=1 cargo test -p rcagd-cli --test it python_stubs` to rewrite it.
//! The hand-written functions must take every parameter of their op by name (or
//! through `**options`).

use std::collections::BTreeSet;
use std::path::PathBuf;

const BEGIN: &str = "# --- generated from the op registry (crates/cli/tests/it/python_stubs.rs): one function per op ---";
const END: &str = "# --- end of generated stubs ---";

/// Python 3's `keyword.kwlist`.
const PY_KEYWORDS: &[&str] = &[
    "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class", "continue",
    "def", "del", "elif", "else", "except", "finally", "for", "from", "global", "if", "import",
    "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return", "try", "while",
    "with", "yield",
];

fn package() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../python/python/rcagd")
}

fn py_name(n: &str) -> String {
    if PY_KEYWORDS.contains(&n) {
        format!("{n}_")
    } else {
        n.to_string()
    }
}

/// The stub type of an op parameter type (`ParamKind::type_name`).
fn stub_type(kind: &str) -> &'static str {
    match kind {
        "number" => "Number",
        "integer" => "int",
        "boolean" => "bool",
        "point [x, y]" | "point [x, y, z]" | "point [x, y, …]" => "Point",
        "list of numbers" => "Sequence[Number]",
        "list of points" => "Points",
        "net of points (list of rows)" => "Net",
        "grid of numbers (list of rows)" => "Grid",
        _ => "str", // "string", "one of …"
    }
}

/// The names `rcagd/__init__.py` binds at module level itself (functions, classes,
/// assignments), which the registry loop does not replace.
fn hand_written(init_py: &str) -> BTreeSet<String> {
    init_py
        .lines()
        .filter_map(|l| {
            let l = l
                .strip_prefix("def ")
                .or_else(|| l.strip_prefix("class "))
                .unwrap_or(l);
            let end = l
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(l.len());
            let (name, rest) = l.split_at(end);
            let rest = rest.trim_start();
            (!name.is_empty()
                && (rest.starts_with('(') || rest.starts_with(':') || rest.starts_with('=')))
            .then(|| name.to_string())
        })
        .collect()
}

/// The generated stub block for every op without a hand-written function.
fn stub_block(hand: &BTreeSet<String>) -> String {
    let mut ops: Vec<_> = rcagd_cli::ops::all()
        .filter(|op| !hand.contains(op.name))
        .collect();
    ops.sort_by_key(|op| op.name);
    let mut out = vec![BEGIN.to_string()];
    for op in ops {
        let required = op.params.iter().filter(|p| p.required);
        let optional = op.params.iter().filter(|p| !p.required);
        let mut args: Vec<String> = required
            .map(|p| format!("{}: {}", py_name(p.name), stub_type(&p.kind.type_name())))
            .chain(optional.map(|p| {
                format!(
                    "{}: Optional[{}] = ...",
                    py_name(p.name),
                    stub_type(&p.kind.type_name())
                )
            }))
            .collect();
        args.push("*, name: str = ...".into());
        args.push("float: bool = ...".into());
        out.push(format!(
            "def {}({}) -> Object: ...",
            op.name,
            args.join(", ")
        ));
    }
    out.push(END.to_string());
    out.join("\n") + "\n"
}

#[test]
fn generated_python_stubs_follow_the_op_registry() {
    let init_py = std::fs::read_to_string(package().join("__init__.py")).unwrap();
    let path = package().join("__init__.pyi");
    let text = std::fs::read_to_string(&path).unwrap();
    let block = stub_block(&hand_written(&init_py));
    let (head, tail) = match (text.find(BEGIN), text.find(END)) {
        (Some(b), Some(e)) => (&text[..b], &text[e + END.len() + 1..]),
        _ => (text.as_str(), ""),
    };
    let current = text.get(head.len()..text.len() - tail.len()).unwrap_or("");
    if current == block {
        return;
    }
    if std::env::var_os("RCAGD_BLESS_STUBS").is_some() {
        std::fs::write(&path, format!("{head}{block}{tail}")).unwrap();
        return;
    }
    let stale: Vec<&str> = block
        .lines()
        .filter(|l| !current.lines().any(|c| c == *l))
        .collect();
    panic!(
        "the generated stubs of {} are stale; run \
         `RCAGD_BLESS_STUBS=1 cargo test -p rcagd-cli --test it python_stubs`. New or changed:\n{}",
        path.display(),
        stale.join("\n")
    );
}

#[test]
fn hand_written_python_functions_take_every_parameter_of_their_op() {
    let init_py = std::fs::read_to_string(package().join("__init__.py")).unwrap();
    let hand = hand_written(&init_py);
    let mut missing = Vec::new();
    for op in rcagd_cli::ops::all().filter(|op| hand.contains(op.name)) {
        let Some(start) = init_py.find(&format!("\ndef {}(", op.name)) else {
            continue; // a class or an alias: checked by the Python tests
        };
        let sig = &init_py[start..];
        let sig = &sig[..sig.find("):").map_or(sig.len(), |e| e + 1)];
        if sig.contains("**") {
            continue;
        }
        for p in op.params {
            let n = py_name(p.name);
            let named = sig
                .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .any(|w| w == n);
            if !named {
                missing.push(format!("{}: {n}", op.name));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "hand-written Python functions (crates/python/python/rcagd/__init__.py) without \
         their op's parameter: {missing:?}"
    );
}

#[test]
fn hand_written_names_are_read_from_module_level_definitions() {
    let src = "def torus(a, b):\n    x = 1\nclass Object:\n_KEYWORDS = 3\n    def inner(self):\n";
    let names: Vec<_> = hand_written(src).into_iter().collect();
    assert_eq!(names, ["Object", "_KEYWORDS", "torus"]);
}
