//! The work budget of `rcagd build --max-seconds` (issue 19, item 1): a construction
//! still working at the deadline ends promptly with a named error, exit 2, and nothing
//! is written.

use crate::common::{bin, temp_dir, write};
use std::time::{Duration, Instant};

/// A recipe that takes many seconds of exact work (the fuzz finding
/// `line_congruence_parametrized` with a coefficient `1e-12`: 14 s CPU alone, in the
/// resultants and gcds of its order and class).
const SLOW: &str = r#"
[[object]]
name = "slow"
op = "line_congruence_parametrized"
surface = [[[1, 0, 0, 3], [0, 0, 4, 0], [1, 0, 0, -3]], [[0, 2, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]], [[1, 0, 0, -3], [1e-12, 0, 0, 0], [0, 0, 0, 0]]]
u = ["-1/2", "1/2"]
v = ["-1/2", 0, "1/2"]
lambda = [0, "1/4"]
"#;

#[test]
fn max_seconds_ends_a_slow_build_with_a_named_error_and_writes_nothing() {
    let dir = temp_dir("budget-slow");
    let recipe = write(&dir, "slow.toml", SLOW);
    let out = dir.join("out");
    let start = Instant::now();
    let o = bin()
        .arg("build")
        .arg(&recipe)
        .args(["--max-seconds", "1", "--format", "json,step", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    let took = start.elapsed();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains(
            "work limit exceeded: building \"slow\" took more than 1 s (raise with --max-seconds)"
        ),
        "{err}"
    );
    // located at the object's op, no panic message
    assert!(err.contains("slow.toml:4:1"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    assert!(!out.exists(), "nothing may be written");
    // promptly: the budget and the time to start and parse (generous for a loaded machine)
    assert!(took < Duration::from_secs(20), "took {took:?}");
}

#[test]
fn max_seconds_is_documented_and_zero_means_no_budget_for_a_quick_recipe() {
    let o = bin().args(["build", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&o.stdout);
    assert!(
        help.contains("--max-seconds") && help.contains("[default: 600]"),
        "{help}"
    );
    let dir = temp_dir("budget-quick");
    let recipe = write(
        &dir,
        "quick.toml",
        "[[object]]\nname = \"c\"\nop = \"bezier_curve\"\npoints = [[0, 0], [1, 2], [3, 1]]\n",
    );
    for secs in ["0", "1", "600"] {
        let o = bin()
            .arg("build")
            .arg(&recipe)
            .args(["--max-seconds", secs])
            .output()
            .unwrap();
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
}

/// An object that builds in about 0.15 s CPU and whose ten exporters take about 2 s CPU
/// (test profile, session 19: meshes and pictures; 8 s before the exact boundary curves
/// were taken from the net; fuzz corpus `sphere_family_envelope-timeout-a083bd00fa6deeb5`);
/// `NAME` is replaced per copy.
const SLOW_EXPORT: &str = r#"
[[object]]
name = "NAME"
op = "sphere_family_envelope"
net = "hyperbolic"
points = [[1, 0, 0, 0], [0, 0, 1, 0], [1, 0, 0, 1], [0, 1, 0, 0]]
a = [[0], [0], [1]]
b = [[0, 0, 1]]
domain = ["1/4", 1, "1/4", 1]
spheres = 2
other_sheet = true
combine = true
"#;

#[test]
fn max_seconds_bounds_the_exporters_too_and_nothing_is_written() {
    let dir = temp_dir("budget-export");
    // ten copies: about 20 s CPU of exports, far over the 2 s budget on any machine, while
    // each construction (budgeted per object) takes a small part of it
    let text: String = (1..=10)
        .map(|k| SLOW_EXPORT.replace("NAME", &format!("fz{k}")))
        .collect();
    let recipe = write(&dir, "slow-export.toml", &text);
    let out = dir.join("out");
    let start = Instant::now();
    let o = bin()
        .arg("build")
        .arg(&recipe)
        .args([
            "--max-seconds",
            "2",
            "--format",
            "json,step,iges,obj,stl,ply,gltf,svg,exact,png",
        ])
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let took = start.elapsed();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("work limit exceeded: exporting \"fz1\", \"fz2\""),
        "{err}"
    );
    assert!(err.contains(", … as JSON, STEP, IGES, OBJ"), "{err}");
    assert!(err.contains("took more than 2 s"), "{err}");
    assert!(err.contains("nothing was written"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    assert!(!out.exists(), "nothing may be written");
    assert!(took < Duration::from_secs(60), "took {took:?}");
}
