//! The CLI's input and output reliability (issue 19, item 2): `gallery --out` checked
//! before building and written all or nothing, bounded error output, and the smaller
//! messages (zero denominator, a recipe whose extension chose the wrong format, empty
//! lists).

use crate::common::{bin, stderr, temp_dir, write};

/// Every entry of `dir`, sorted (names only).
fn listing(dir: &std::path::Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .expect("read dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// An output directory that cannot be written is refused before the build, with exit 2
/// and a message naming it; a path below a regular file cannot be created.
#[test]
fn gallery_refuses_an_unwritable_out_before_building() {
    let dir = temp_dir("messages-gallery-unwritable");
    let file = write(&dir, "plain-file", "x");
    let below = file.join("sub");
    let o = bin()
        .args(["gallery", "--quiet", "--only", "analysis", "--out"])
        .arg(&below)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains(&below.display().to_string()),
        "{}",
        stderr(&o)
    );
    // /proc/self exists but nobody (root included) can create a file in it
    if cfg!(target_os = "linux") {
        let t = std::time::Instant::now();
        let o = bin()
            .args(["gallery", "--quiet", "--out", "/proc/self"])
            .output()
            .expect("run");
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        let e = stderr(&o);
        assert!(
            e.contains("cannot write into the output directory /proc/self"),
            "{e}"
        );
        // refused before building the whole gallery (which takes minutes in debug)
        assert!(t.elapsed().as_secs() < 20, "{:?}", t.elapsed());
    }
}

/// A gallery write that fails (here: the temporary of `index.html`, the last file, is a
/// directory in the way) leaves the directory as it was: no new file, no temporary, an
/// old file of a gallery name unchanged; the same run into a clean directory writes
/// everything and leaves no temporary behind.
#[test]
fn gallery_writes_all_or_nothing() {
    let dir = temp_dir("messages-gallery-atomic");
    let out = dir.join("g");
    std::fs::create_dir_all(out.join(".index.html.rcagd-partial")).expect("mkdir");
    std::fs::write(out.join("report.json"), "old").expect("write");
    let before = listing(&out);
    let o = bin()
        .args(["gallery", "--quiet", "--only", "analysis", "--out"])
        .arg(&out)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("index.html"), "{}", stderr(&o));
    assert!(stderr(&o).contains("nothing was written"), "{}", stderr(&o));
    assert_eq!(listing(&out), before);
    assert_eq!(
        std::fs::read_to_string(out.join("report.json")).expect("read"),
        "old"
    );
    // the way cleared, the same run writes every file and no temporary
    std::fs::remove_dir(out.join(".index.html.rcagd-partial")).expect("rmdir");
    let o = bin()
        .args(["gallery", "--quiet", "--only", "analysis", "--out"])
        .arg(&out)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let after = listing(&out);
    assert!(
        after.iter().all(|f| !f.contains("rcagd-partial")),
        "{after:?}"
    );
    for f in ["index.html", "report.json", "gallery-all.step"] {
        assert!(after.iter().any(|x| x == f), "{f} missing: {after:?}");
    }
    assert_ne!(
        std::fs::read_to_string(out.join("report.json")).expect("read"),
        "old"
    );
    // a fresh directory (created by the run) gets the same files
    let fresh = dir.join("fresh");
    let o = bin()
        .args(["gallery", "--quiet", "--only", "analysis", "--out"])
        .arg(&fresh)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(listing(&fresh).len(), after.len());
}

/// Runs `rcagd build FILE` on a recipe written to a fresh directory; returns (exit
/// code, standard error).
fn build_err(tag: &str, file: &str, text: &str) -> (Option<i32>, String) {
    let dir = temp_dir(tag);
    let path = write(&dir, file, text);
    let o = bin().arg("build").arg(&path).output().expect("run");
    (o.status.code(), stderr(&o))
}

/// A 10 MB object name, key or number is not echoed: the source line is shown as a
/// window of about 200 characters and the text in messages is cut with `… (N bytes)`.
#[test]
fn long_user_text_is_not_echoed_in_full() {
    let big = "a".repeat(10_000_000);
    let cases = [
        format!("[[object]]\nname = \"{big}\"\nop = \"circle\"\nradius = 1\n"),
        format!("[[object]]\nname = \"c\"\nop = \"circle\"\nradius = 1\n{big} = 2\n"),
        format!("[[object]]\nname = \"c\"\nop = \"{big}\"\nradius = 1\n"),
        format!("[[object]]\nname = \"c\"\nop = \"circle\"\nradius = \"{big}\"\n"),
        format!(
            "[[object]]\nname = \"c\"\nop = \"circle\"\nradius = 1{}x\n",
            "0".repeat(10_000_000)
        ),
    ];
    for (i, text) in cases.iter().enumerate() {
        let (code, e) = build_err(&format!("messages-long-{i}"), "r.toml", text);
        assert_eq!(code, Some(2), "case {i}: {}", &e[..e.len().min(2000)]);
        assert!(
            e.len() < 8_000,
            "case {i}: {} bytes of error output",
            e.len()
        );
        assert!(e.contains("error:"), "case {i}: {e}");
        // the unknown key and op are named, cut, with their length
        let cut = format!("{}… (10000000 bytes)", "a".repeat(200));
        match i {
            1 => assert!(e.contains(&format!("unknown parameter `{cut}`")), "{e}"),
            2 => assert!(e.contains(&format!("unknown op \"{cut}\"")), "{e}"),
            _ => {}
        }
    }
}

/// A recipe with 20 000 unknown keys prints 50 diagnostics, the parameter list once,
/// and the count of the rest.
#[test]
fn many_errors_print_a_bounded_report() {
    let keys: String = (0..20_000).map(|i| format!("k{i} = 1\n")).collect();
    let text = format!("[[object]]\nname = \"c\"\nop = \"circle\"\nradius = 1\n{keys}");
    let (code, e) = build_err("messages-many", "r.toml", &text);
    assert_eq!(code, Some(2));
    assert_eq!(e.matches(": error: ").count(), 50, "{e}");
    assert_eq!(e.matches("parameters of `circle`:").count(), 1, "{e}");
    assert_eq!(
        e.matches("parameters of `circle` (as above)").count(),
        49,
        "{e}"
    );
    assert!(
        e.ends_with("… and 19950 more errors (the first 50 are shown)\n20000 errors\n"),
        "{}",
        &e[e.len().saturating_sub(500)..]
    );
    assert!(e.len() < 20_000, "{} bytes", e.len());
}

/// `"1/0"` as a number says "zero denominator" (as a string and inside a point), once.
#[test]
fn zero_denominator_is_named() {
    for (i, value) in [
        "radius = \"1/0\"",
        "radius = \"-3/0.0\"",
        "center = [\"1/0\", 0]\nradius = 1",
    ]
    .iter()
    .enumerate()
    {
        let text = format!("[[object]]\nname = \"c\"\nop = \"circle\"\n{value}\n");
        let (code, e) = build_err(&format!("messages-zero-den-{i}"), "r.toml", &text);
        assert_eq!(code, Some(2), "{e}");
        assert!(e.contains(": zero denominator"), "{e}");
        if i == 0 {
            assert!(e.contains("`radius`: \"1/0\": zero denominator"), "{e}");
        }
    }
    // other bad numbers keep the hint on how to write one
    let text = "[[object]]\nname = \"c\"\nop = \"circle\"\nradius = \"x1\"\n";
    let (_, e) = build_err("messages-not-number", "r.toml", text);
    assert!(e.contains("not a number: \"x1\""), "{e}");
    assert!(e.contains("a fraction \"3/7\""), "{e}");
}

/// A `.json` recipe that holds TOML (and the reverse) gets a hint that the extension
/// chose the format.
#[test]
fn wrong_extension_is_hinted() {
    let toml_text = "[[object]]\nname = \"c\"\nop = \"circle\"\nradius = 1\n";
    let (code, e) = build_err("messages-ext-json", "r.json", toml_text);
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("JSON syntax error"), "{e}");
    assert!(
        e.contains(
            "the file's extension chose JSON, but the file reads as TOML: rename it to `.toml`"
        ),
        "{e}"
    );
    let json_text = r#"{"object": [{"name": "c", "op": "circle", "radius": 1}]}"#;
    let (code, e) = build_err("messages-ext-toml", "r.toml", json_text);
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("reads as JSON: rename it to `.json`"), "{e}");
    // the renamed files build
    let (code, e) = build_err("messages-ext-ok", "r.toml", toml_text);
    assert_eq!(code, Some(0), "{e}");
}

/// An empty list for a list parameter that needs numbers is an "empty" error naming the
/// parameter and pointing at it (exit 2), not an unrelated geometric message.
#[test]
fn empty_lists_are_named() {
    let cases = [
        ("pn_planar", "function = []", "function"),
        (
            "canal_surface",
            "points = [[0, 0, 0], [1, 0, 0]]\nradius = []",
            "radius",
        ),
    ];
    for (i, (op, params, name)) in cases.iter().enumerate() {
        let text = format!("[[object]]\nname = \"c\"\nop = \"{op}\"\n{params}\n");
        let (code, e) = build_err(&format!("messages-empty-{i}"), "r.toml", &text);
        assert_eq!(code, Some(2), "{e}");
        assert!(
            e.contains(&format!("`{name}` is empty: give at least one number")),
            "{e}"
        );
        let line = text
            .lines()
            .position(|l| l.starts_with(name))
            .expect("line")
            + 1;
        assert!(e.contains(&format!("r.toml:{line}:")), "{e}");
    }
    // an optional list without a default may be empty (`at = []`, `distances = []`:
    // none); where that is meaningless the op's own error still points at it
    let text =
        "[[object]]\nname = \"c\"\nop = \"pn_planar\"\nfunction = [0, 0, 1]\ndenominator = []\n";
    let (code, e) = build_err("messages-empty-optional", "r.toml", text);
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("r.toml:5:15: error:"), "{e}");
    assert!(e.contains("non-zero denominator"), "{e}");
    // the same op with a list builds (the check is about emptiness only)
    let text = "[[object]]\nname = \"c\"\nop = \"pn_planar\"\nfunction = [0, 0, 1]\n";
    let (code, e) = build_err("messages-empty-ok", "r.toml", text);
    assert_eq!(code, Some(0), "{e}");
}

/// A user's object name that clashes with a name an op generates for its extra results
/// (`h_2` of `ph_hermite` named `h`) is an input error naming both objects; nothing is
/// written.
#[test]
fn a_name_clashing_with_a_generated_name_is_explained() {
    let dir = temp_dir("messages-name-clash");
    let recipe = write(
        &dir,
        "clash.toml",
        "[[object]]\nname = \"h\"\nop = \"ph_hermite\"\np_s = [0, 0, 0]\nd_s = [1, 0, 1]\np_f = [1, 1, 1]\nd_f = [0, 1, 1]\n\n[[object]]\nname = \"h_2\"\nop = \"circle\"\nradius = 1\n",
    );
    let out = dir.join("out");
    let o = bin()
        .arg("build")
        .arg(&recipe)
        .arg("--out")
        .arg(&out)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("two results are called \"h_2\"")
            && e.contains("object \"h\" (op `ph_hermite`")
            && e.contains("object \"h_2\" (op `circle`)"),
        "{e}"
    );
    assert!(!out.exists());
}

/// `canal_surface` with a radius that vanishes identically is an input error at `radius`
/// (exit 2), as `pipe` with radius 0 is; a radius vanishing at one end only still builds.
#[test]
fn canal_surface_refuses_a_zero_radius() {
    let dir = temp_dir("messages-canal-zero-radius");
    let e = crate::common::build_refused(
        &dir,
        "[[object]]\nname = \"c\"\nop = \"canal_surface\"\npoints = [[0, 0, 0], [0, 2, 0], [4, 4, 0]]\nradius = [0, 0]\n",
    );
    assert!(
        e.contains("vanishes identically") && e.contains("radius = [0, 0]"),
        "{e}"
    );
}
