//! No input may panic the CLI: random texts, mutations of valid recipes (truncation,
//! deletion, insertion, byte flips), random bytes and deep nesting, through the
//! library (many cases) and through the binary (a few).

use crate::common::{bin, temp_dir};
use proptest::prelude::*;
use rcagd_cli::build::build_recipe;
use rcagd_cli::recipe::{Format, Recipe};

const VALID_TOML: &str = r#"[[object]]
name = "arc"
op = "circle_arc"
center = ["1/2", -1]
radius = 5
from = [3.5, 3]
to = [-3.5, 2]

[[object]]
name = "c"
op = "cylinder_patch"
radius = 2
from = ["6/5", "8/5"]
to = ["-8/5", "6/5"]
z0 = -0.5
z1 = 1.25

[[object]]
name = "b"
op = "bezier_patch"
net = [[[0, 0, 0], [1, 0, 1]], [[0, 1, 1], [1, 1, 0]]]
weights = [[1, 2], [3, 4]]
"#;

const VALID_JSON: &str = r#"{"object": [
  {"name": "arc", "op": "circle_arc", "center": ["1/2", -1], "radius": 5, "from": [3.5, 3], "to": [-3.5, 2]},
  {"name": "k", "op": "bezier_curve", "points": [[1, 1, 0], [1, 1, 1], [2, 0, 2]], "homogeneous": true},
  {"name": "c", "op": "circle", "radius": 0.25}
]}"#;

/// Parses and builds; every diagnostic must be inside the file.
fn check_no_panic(text: &str, format: Option<Format>) {
    let file = match format {
        Some(Format::Json) => "fuzz.json",
        Some(Format::Toml) => "fuzz.toml",
        None => "fuzz.txt",
    };
    let lines = text.split('\n').count().max(1);
    let check = |d: &rcagd_cli::source::Diagnostic| {
        assert!(
            d.line >= 1 && d.line <= lines,
            "line {} of {lines}: {d}",
            d.line
        );
        assert!(d.column >= 1, "{d}");
        let _ = d.to_string();
    };
    match Recipe::parse(file, text, format) {
        Ok(r) => {
            if let Err(ds) = build_recipe(&r, |_| {}) {
                ds.iter().for_each(check);
            }
        }
        Err(ds) => {
            assert!(!ds.is_empty());
            ds.iter().for_each(check);
        }
    }
}

fn mutate(base: &str, ops: &[(u8, usize, char)]) -> String {
    let mut s: Vec<char> = base.chars().collect();
    for &(kind, pos, c) in ops {
        if s.is_empty() {
            s.push(c);
            continue;
        }
        let i = pos % s.len();
        match kind % 4 {
            0 => s.truncate(i),
            1 => {
                s.remove(i);
            }
            2 => s.insert(i, c),
            _ => s[i] = c,
        }
    }
    s.into_iter().collect()
}

fn recipe_char() -> impl Strategy<Value = char> {
    prop_oneof![
        prop::sample::select(vec![
            '[', ']', '{', '}', '"', '\'', ',', ':', '=', '.', '/', '-', '+', 'e', '0', '1', '9',
            '\n', ' ', '#', '\\', 'x', '_', 'é', '\t', '\r', '\0',
        ]),
        any::<char>(),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn mutated_toml_never_panics(ops in prop::collection::vec((any::<u8>(), any::<usize>(), recipe_char()), 1..6)) {
        check_no_panic(&mutate(VALID_TOML, &ops), Some(Format::Toml));
    }

    #[test]
    fn mutated_json_never_panics(ops in prop::collection::vec((any::<u8>(), any::<usize>(), recipe_char()), 1..6)) {
        let text = mutate(VALID_JSON, &ops);
        check_no_panic(&text, Some(Format::Json));
        check_no_panic(&text, None);
    }

    #[test]
    fn random_text_never_panics(chars in prop::collection::vec(recipe_char(), 0..200)) {
        let text: String = chars.into_iter().collect();
        check_no_panic(&text, Some(Format::Toml));
        check_no_panic(&text, Some(Format::Json));
    }

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..200)) {
        let _ = Recipe::from_bytes("fuzz.toml", &bytes, None);
        let _ = Recipe::from_bytes("fuzz.json", &bytes, None);
    }

    #[test]
    fn random_numbers_are_exact_or_rejected(text in "[-+]?[0-9]{0,4}(\\.[0-9]{0,3})?([eE][-+]?[0-9]{1,8})?(/[0-9e.]{0,4})?") {
        let recipe = format!(
            "[[object]]\nname = \"a\"\nop = \"bezier_curve\"\npoints = [[\"{text}\", 0], [1, 1]]\n"
        );
        check_no_panic(&recipe, None);
    }
}

#[test]
fn every_truncation_of_a_valid_recipe_is_handled() {
    for text in [VALID_TOML, VALID_JSON] {
        for (i, _) in text.char_indices() {
            check_no_panic(&text[..i], None);
        }
    }
}

#[test]
fn deep_nesting_is_bounded() {
    for depth in [10, 100, 1000, 100_000] {
        let toml = format!(
            "[[object]]\nname = \"a\"\nop = \"circle\"\nradius = {}1{}\n",
            "[".repeat(depth),
            "]".repeat(depth)
        );
        check_no_panic(&toml, Some(Format::Toml));
        let inline = format!(
            "[[object]]\nname = \"a\"\nop = \"circle\"\nradius = {}\n",
            "{a = ".repeat(depth)
        );
        check_no_panic(&inline, Some(Format::Toml));
        let json = format!(
            "{{\"object\": [{{\"name\": \"a\", \"op\": \"circle\", \"radius\": {}1{}}}]}}",
            "[".repeat(depth),
            "]".repeat(depth)
        );
        check_no_panic(&json, Some(Format::Json));
        check_no_panic(&"{\"a\":".repeat(depth), Some(Format::Json));
    }
}

/// A handful of broken inputs through the real binary: exit code 2, a located error,
/// no panic message.
#[test]
fn binary_survives_broken_inputs() {
    let dir = temp_dir("cli-fuzz");
    let mut cases: Vec<(String, Vec<u8>)> = vec![
        ("empty.toml".into(), Vec::new()),
        ("bytes.toml".into(), vec![0xff, 0xfe, 0x00, 0x5b, 0x5b]),
        ("deep.json".into(), "[".repeat(200_000).into_bytes()),
        (
            "deep.toml".into(),
            format!("a = {}", "[".repeat(200_000)).into_bytes(),
        ),
        ("nul.toml".into(), b"[[object]]\nname = \"a\0\"\n".to_vec()),
    ];
    for (k, cut) in [7usize, 40, 95, 150].into_iter().enumerate() {
        cases.push((
            format!("cut{k}.toml"),
            VALID_TOML.as_bytes()[..cut].to_vec(),
        ));
        cases.push((
            format!("cut{k}.json"),
            VALID_JSON.as_bytes()[..cut].to_vec(),
        ));
    }
    for (name, bytes) in cases {
        let p = dir.join(&name);
        std::fs::write(&p, &bytes).expect("write");
        let o = bin().arg("build").arg(&p).output().expect("run");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name}: {err}");
        assert!(!err.contains("panicked"), "{name}: {err}");
        assert!(
            err.starts_with(&format!("{}:", p.display())),
            "{name}: {err}"
        );
    }
}
