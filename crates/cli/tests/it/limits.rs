//! The per-op limits (issue 19, item 1): every limit is checked before the op starts,
//! the refusal names the limit and the `rcagd build` option that raises it, and the
//! option does raise it; `rcagd ops NAME` states the limits.

use crate::common::{bin, stderr, stdout, temp_dir, write};
use std::path::Path;

/// `rcagd build RECIPE ARGS…`: (exit code, standard error).
fn build(recipe: &Path, args: &[&str]) -> (Option<i32>, String) {
    let o = bin()
        .arg("build")
        .arg(recipe)
        .args(args)
        .output()
        .expect("run");
    (o.status.code(), stderr(&o))
}

/// Refused with exit 2 naming `phrases` under the default limits (or `tight`), built
/// with `raised`.
fn refused_then_raised(recipe: &Path, tight: &[&str], phrases: &[&str], raised: &[&str]) {
    let (code, err) = build(recipe, tight);
    assert_eq!(code, Some(2), "{err}");
    for p in phrases {
        assert!(err.contains(p), "{p:?} not in {err}");
    }
    let (code, err) = build(recipe, raised);
    assert_eq!(code, Some(0), "{err}");
}

#[test]
fn every_op_limit_is_named_and_can_be_raised() {
    let dir = temp_dir("op-limits");
    // degree: 70 control points ask for degree 69
    let pts: Vec<String> = (0..70).map(|i| format!("[{i}, {}]", i % 3)).collect();
    let curve = write(
        &dir,
        "degree.toml",
        &format!(
            "[[object]]\nname = \"c\"\nop = \"bezier_curve\"\npoints = [{}]\n",
            pts.join(", ")
        ),
    );
    refused_then_raised(
        &curve,
        &[],
        &["degree 69", "the limit is degree 64", "--max-degree"],
        &["--max-degree", "69"],
    );
    // list items: the same curve under a tighter item limit
    refused_then_raised(
        &curve,
        &["--max-degree", "80", "--max-points", "20"],
        &["70 items", "--max-points"],
        &["--max-degree", "80", "--max-points", "70"],
    );
    // a sample count
    let ph = write(
        &dir,
        "samples.toml",
        "[[object]]\nname = \"h\"\nop = \"ph_curve\"\nquaternions = [[1, 0, 1, 0], [0, 1, 0, 1]]\nsamples = 9\n",
    );
    refused_then_raised(
        &ph,
        &["--max-samples", "5"],
        &["`samples` = 9", "--max-samples"],
        &["--max-samples", "9"],
    );
    // magnitudes: a centre 1e30 beside a radius 1
    let far = write(
        &dir,
        "magnitude.toml",
        "[[object]]\nname = \"c\"\nop = \"circle\"\ncenter = [1e30, 0]\nradius = 1\n",
    );
    refused_then_raised(
        &far,
        &[],
        &["30.0 decimal orders", "center", "--max-magnitude"],
        &["--max-magnitude", "31"],
    );
    // the error points at the parameter
    let (_, err) = build(&far, &[]);
    assert!(err.contains("magnitude.toml:4:"), "{err}");
}

#[test]
fn ops_name_states_the_limits() {
    let o = bin().args(["ops", "bezier_curve"]).output().expect("run");
    let s = stdout(&o);
    assert!(s.contains("limits"), "{s}");
    assert!(s.contains("`points`: degree ≤ 64"), "{s}");
    assert!(
        s.contains("--max-degree") && s.contains("--max-points"),
        "{s}"
    );
    assert!(
        s.contains("--max-magnitude") && s.contains("--max-digits"),
        "{s}"
    );
    let o = bin().args(["ops", "ph_curve"]).output().expect("run");
    assert!(stdout(&o).contains("`samples` ≤ 1000 (`--max-samples`)"));
}

#[test]
fn build_shows_progress_on_request() {
    let dir = temp_dir("progress");
    let two = write(
        &dir,
        "two.toml",
        "[[object]]\nname = \"a\"\nop = \"circle\"\ncenter = [0, 0]\nradius = 1\n\n\
         [[object]]\nname = \"b\"\nop = \"circle\"\ncenter = [1, 0]\nradius = 2\n",
    );
    // standard error is a pipe here: no progress unless asked for
    let (code, err) = build(&two, &[]);
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("built"), "{err}");
    let (code, err) = build(&two, &["--progress"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("built 2/2"), "{err}");
    assert!(err.contains(": a") && err.contains(": b"), "{err}");
}
