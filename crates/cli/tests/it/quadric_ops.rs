//! The quadric ops (`crates/cli/src/ops/quadric.rs`) through the `rcagd` binary: every
//! op's error paths give a located error (`file:line:col`) naming the violated
//! precondition, never a panic; a recipe with a point off the sphere fails cleanly.

use crate::common::{bin, temp_dir, write};
use std::path::{Path, PathBuf};
use std::process::Output;

fn run(dir: &Path, name: &str, text: &str) -> (PathBuf, Output) {
    let p = write(dir, name, text);
    let o = bin().arg("build").arg(&p).output().expect("run rcagd");
    (p, o)
}

/// The 1-based line and column of the value of `key` (the first `key = ` in `text`),
/// or of the `op` key when `key` is `None`.
fn position(text: &str, key: Option<&str>) -> (usize, usize) {
    let needle = key.map_or("op = ".to_string(), |k| format!("{k} = "));
    for (i, line) in text.lines().enumerate() {
        if let Some(c) = line.find(&needle) {
            let col = if key.is_some() { c + needle.len() } else { c };
            return (i + 1, col + 1);
        }
    }
    panic!("no `{needle}` in the recipe");
}

/// Builds `text`; expects exit code 2, the error at the value of `key` (or the op key)
/// and `needle` in the message. Returns stderr.
fn expect_error(tag: &str, text: &str, key: Option<&str>, needle: &str) -> String {
    let dir = temp_dir(&format!("quadric-ops-{tag}"));
    let (p, o) = run(&dir, &format!("{tag}.toml"), text);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "{tag}: {err}");
    assert!(
        !err.contains("panicked") && !err.contains("internal error"),
        "{tag}: {err}"
    );
    let (line, col) = position(text, key);
    let want = format!("{}:{line}:{col}: error: ", p.display());
    let first = err.lines().next().unwrap_or("");
    assert!(
        first.starts_with(&want),
        "{tag}: expected {want:?}, got:\n{err}"
    );
    assert!(
        first.contains(needle),
        "{tag}: expected {needle:?} in:\n{err}"
    );
    assert!(o.stdout.is_empty(), "{tag}: nothing printed on error");
    err
}

fn recipe(op: &str, body: &str) -> String {
    format!("# test\n[[object]]\nname = \"x\"\nop = \"{op}\"\n{body}")
}

const FIVE: &str = r#"points = [[1, 0, 0], ["3/5", "4/5", 0], [0, "3/5", "4/5"], ["-2/3", "1/3", "2/3"], ["-2/7", "-3/7", "6/7"]]"#;

#[test]
fn interpolation_errors_are_located() {
    // a point off the sphere: the residual Xᵀ Q X is named
    let err = expect_error(
        "off-sphere",
        &recipe(
            "quadric_interpolate",
            "points = [[1, 0, 0], [0, 1, 0], [1, 1, 1]]\n",
        ),
        Some("points"),
        "point 2",
    );
    assert!(
        err.contains("is not on the quadric") && err.contains("Xᵀ Q X = -2"),
        "{err}"
    );
    expect_error(
        "repeated-point",
        &recipe(
            "quadric_interpolate",
            "points = [[1, 0, 0], [0, 1, 0], [1, 0, 0]]\n",
        ),
        Some("points"),
        "points 0 and 2 coincide",
    );
    expect_error(
        "repeated-param",
        &recipe(
            "quadric_interpolate",
            "points = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]\nparams = [0, \"1/2\", \"1/2\"]\n",
        ),
        Some("params"),
        "parameters 1 and 2 coincide",
    );
    expect_error(
        "param-count",
        &recipe(
            "quadric_interpolate",
            "points = [[1, 0, 0], [0, 1, 0]]\nparams = [0]\n",
        ),
        Some("params"),
        "2 points but 1 parameters",
    );
    expect_error(
        "not-tangent",
        &recipe(
            "quadric_interpolate",
            "points = [[1, 0, 0], [0, 1, 0]]\ntangents = [[1, 0, 0], [0, 0, 0]]\n",
        ),
        Some("tangents"),
        "tangent 0 is not tangent",
    );
    expect_error(
        "tangent-count",
        &recipe(
            "quadric_interpolate",
            "points = [[1, 0, 0], [0, 1, 0]]\ntangents = [[0, 1, 0]]\n",
        ),
        Some("tangents"),
        "2 points but 1 tangents",
    );
    // five points in general position need degree 4: degree 2 (n = 1) has no solution
    expect_error(
        "low-degree",
        &recipe("quadric_interpolate", &format!("{FIVE}\ndegree = 1\n")),
        Some("degree"),
        "no interpolant of preimage degree 1",
    );
    expect_error(
        "negative-degree",
        &recipe("quadric_interpolate", &format!("{FIVE}\ndegree = -1\n")),
        Some("degree"),
        "between 0 and 32",
    );
    expect_error(
        "two-coordinates",
        &recipe("quadric_interpolate", "points = [[1, 0], [0, 1]]\n"),
        Some("points"),
        "point 0 must be [x, y, z]",
    );
    let many: Vec<String> = (0..65).map(|_| "[1, 0, 0]".to_string()).collect();
    expect_error(
        "too-many-points",
        &recipe(
            "quadric_interpolate",
            &format!("points = [{}]\n", many.join(", ")),
        ),
        Some("points"),
        "at most 64 interpolation points, got 65",
    );
    // the zero vector is no projective point
    expect_error(
        "zero-point",
        &recipe(
            "quadric_interpolate",
            "points = [[1, 1, 0, 0], [0, 0, 0, 0]]\n",
        ),
        Some("points"),
        "zero vector",
    );
}

#[test]
fn quadric_parameter_errors_are_located() {
    let curve = "points = [[0, 0, 0], [1, 1, 0]]\n";
    expect_error(
        "matrix-missing",
        &recipe(
            "quadric_curve_image",
            &format!("{curve}quadric = \"matrix\"\n"),
        ),
        Some("quadric"),
        "needs the `matrix` parameter",
    );
    expect_error(
        "matrix-unused",
        &recipe(
            "quadric_curve_image",
            &format!(
                "{curve}matrix = [[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 0], [0, 0, 0, -1]]\n"
            ),
        ),
        Some("matrix"),
        "set quadric = \"matrix\"",
    );
    expect_error(
        "matrix-not-symmetric",
        &recipe(
            "quadric_curve_image",
            &format!("{curve}quadric = \"matrix\"\nmatrix = [[-1, 1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]\n"),
        ),
        Some("matrix"),
        "not symmetric",
    );
    expect_error(
        "matrix-3x3",
        &recipe(
            "quadric_curve_image",
            &format!("{curve}quadric = \"matrix\"\nmatrix = [[-1, 0, 0], [0, 1, 0], [0, 0, 1]]\n"),
        ),
        Some("matrix"),
        "4×4",
    );
    // x² + y² + z² + w² = 0: no real point
    expect_error(
        "definite",
        &recipe(
            "quadric_curve_image",
            &format!("{curve}quadric = \"matrix\"\nmatrix = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]\n"),
        ),
        Some("matrix"),
        "no real curves",
    );
    // x² + y² + z² = 7: real, but no rational point (7 = 8·0 + 7, Legendre)
    expect_error(
        "no-rational-point",
        &recipe(
            "quadric_curve_image",
            &format!("{curve}quadric = \"matrix\"\nmatrix = [[-7, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]\n"),
        ),
        Some("matrix"),
        "no rational point",
    );
    expect_error(
        "point-off-quadric",
        &recipe(
            "quadric_curve_image",
            &format!("{curve}quadric = \"ellipsoid\"\ncoefficients = [3, 2, 1]\nrational_point = [1, 0, 0]\n"),
        ),
        Some("rational_point"),
        "not on the quadric",
    );
    expect_error(
        "coefficient-count",
        &recipe(
            "quadric_curve_image",
            &format!("{curve}quadric = \"ellipsoid\"\ncoefficients = [3, 2]\n"),
        ),
        Some("coefficients"),
        "takes 3 parameters, got 2",
    );
    expect_error(
        "zero-axis",
        &recipe(
            "quadric_curve_image",
            &format!("{curve}quadric = \"ellipsoid\"\ncoefficients = [3, 0, 1]\n"),
        ),
        Some("coefficients"),
        "must be finite and non-zero",
    );
    // the x-axis is a focal (exceptional) line of ψ: its image vanishes identically
    expect_error(
        "exceptional-line",
        &recipe(
            "quadric_curve_image",
            "points = [[0, 0, 0], [1, 0, 0]]\nquadric = \"hyperbolic_paraboloid_xy\"\n",
        ),
        None,
        "vanishes identically",
    );
    expect_error(
        "zero-weight",
        &recipe("quadric_curve_image", &format!("{curve}weights = [1, 0]\n")),
        Some("weights"),
        "weight of control point 1 is zero",
    );
    expect_error(
        "curve-2d",
        &recipe("quadric_curve_image", "points = [[0, 0], [1, 1]]\n"),
        Some("points"),
        "control point 0 must be [x, y, z]",
    );
}

#[test]
fn patch_errors_are_located() {
    expect_error(
        "weights-shape",
        &recipe(
            "quadric_patch_image",
            "net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]\nweights = [[1, 1]]\n",
        ),
        Some("weights"),
        "the weights do not have the same shape",
    );
    expect_error(
        "homogeneous-and-weights",
        &recipe(
            "quadric_patch_image",
            "net = [[[1, 0, 0, 0], [1, 0, 1, 0]], [[1, 1, 0, 0], [1, 1, 1, 0]]]\nhomogeneous = true\nweights = [[1, 1], [1, 1]]\n",
        ),
        Some("weights"),
        "not both",
    );
    // the patch lies in the focal line of ψ (the deprecated name "seed_paraboloid" of
    // "hyperbolic_paraboloid_xy" is still accepted)
    expect_error(
        "patch-exceptional",
        &recipe(
            "quadric_patch_image",
            "net = [[[0, 0, 0], [1, 0, 0]], [[2, 0, 0], [3, 0, 0]]]\nquadric = \"seed_paraboloid\"\n",
        ),
        None,
        "vanishes identically",
    );
}

const CORNERS: &str = r#"corners = [[0, 0, -1], [1, 0, 0], ["2/3", "2/3", "1/3"], [0, 1, 0]]"#;

#[test]
fn miquel_patch_errors_are_located() {
    // not a Miquel configuration: the error gives det[p1, q2, p3, q4]
    let err = expect_error(
        "not-miquel",
        &recipe(
            "quadric_miquel_patch",
            &format!("{CORNERS}\ncircle_points = [[\"4/5\", 0, \"-3/5\"], [0, \"3/5\", \"4/5\"], [\"4/9\", \"8/9\", \"1/9\"], [0, \"4/5\", \"-3/5\"]]\n"),
        ),
        Some("circle_points"),
        "not in Miquel position",
    );
    assert!(
        err.contains("det[p1, q2, p3, q4] = -16/37 (must be 0)"),
        "{err}"
    );
    expect_error(
        "corner-off",
        &recipe(
            "quadric_miquel_patch",
            "corners = [[0, 0, -1], [1, 0, 0], [1, 1, 0], [0, 1, 0]]\ncircle_points = [[\"4/5\", 0, \"-3/5\"], [\"8/9\", \"4/9\", \"1/9\"], [\"4/9\", \"8/9\", \"1/9\"], [0, \"4/5\", \"-3/5\"]]\n",
        ),
        Some("corners"),
        "corner p3",
    );
    expect_error(
        "circle-point-off",
        &recipe(
            "quadric_miquel_patch",
            &format!("{CORNERS}\ncircle_points = [[\"4/5\", 0, \"-3/5\"], [1, 1, 1], [\"4/9\", \"8/9\", \"1/9\"], [0, \"4/5\", \"-3/5\"]]\n"),
        ),
        Some("circle_points"),
        "circle point e23",
    );
    expect_error(
        "three-corners",
        &recipe(
            "quadric_miquel_patch",
            "corners = [[0, 0, -1], [1, 0, 0], [0, 1, 0]]\ncircle_points = [[1, 0, 0], [1, 0, 0], [1, 0, 0], [1, 0, 0]]\n",
        ),
        Some("corners"),
        "give exactly 4 corners, got 3",
    );
    expect_error(
        "zero-weight",
        &recipe(
            "quadric_miquel_patch",
            &format!("{CORNERS}\ncircle_points = [[\"4/5\", 0, \"-3/5\"], [\"8/9\", \"4/9\", \"1/9\"], [\"4/9\", \"8/9\", \"1/9\"], [0, \"4/5\", \"-3/5\"]]\nweight = 0\n"),
        ),
        Some("weight"),
        "non-zero",
    );
    // a corner repeated
    expect_error(
        "repeated-corner",
        &recipe(
            "quadric_miquel_patch",
            "corners = [[0, 0, -1], [0, 0, -1], [1, 0, 0], [0, 1, 0]]\ncircle_points = [[\"4/5\", 0, \"-3/5\"], [\"8/9\", \"4/9\", \"1/9\"], [\"4/9\", \"8/9\", \"1/9\"], [0, \"4/5\", \"-3/5\"]]\n",
        ),
        None,
        "corners p1 and p2 coincide",
    );
}

#[test]
fn sphere_cover_errors_are_located() {
    expect_error(
        "zero-radius",
        &recipe("sphere_cover", "radii = [1, 0, 1]\n"),
        Some("radii"),
        "semi-axis b is 0",
    );
}

#[test]
fn a_recipe_with_a_point_off_the_sphere_fails_cleanly_and_writes_nothing() {
    let dir = temp_dir("quadric-ops-clean");
    let out = dir.join("out");
    let text = "[[object]]\nname = \"good\"\nop = \"sphere_cover\"\n\n[[object]]\nname = \"bad\"\nop = \"quadric_interpolate\"\npoints = [[1, 0, 0], [0, 1, 0], [\"1/2\", \"1/2\", \"1/2\"]]\n";
    let p = dir.join("clean.toml");
    std::fs::write(&p, text).expect("write");
    let o = bin()
        .arg("build")
        .arg(&p)
        .arg("--out")
        .arg(&out)
        .output()
        .expect("run rcagd");
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains(&format!("{}:8:10: error: ", p.display())),
        "{err}"
    );
    assert!(
        err.contains("point 2 (1, 1/2, 1/2, 1/2) is not on the quadric"),
        "{err}"
    );
    assert!(err.contains("Xᵀ Q X = 1/4"), "{err}");
    assert!(
        !out.join("good.json").exists(),
        "nothing is written on error"
    );
}

#[test]
fn every_example_builds_with_all_certificates() {
    for op in rcagd_cli::ops::quadric::OPS {
        let dir = temp_dir(&format!("quadric-ops-ex-{}", op.name));
        let (_, o) = run(&dir, "ex.toml", op.example);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}: {}",
            op.name,
            String::from_utf8_lossy(&o.stderr)
        );
        let json: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
        let text = json.to_string();
        assert!(
            text.contains("\"all_certificates_hold\":true"),
            "{}",
            op.name
        );
        assert!(!text.contains("\"holds\":false"), "{}", op.name);
    }
}

/// `"seed_paraboloid"` is a deprecated alias of `"hyperbolic_paraboloid_xy"` (z = xy):
/// both give the same patch.
#[test]
fn seed_paraboloid_is_an_alias() {
    let dir = crate::common::temp_dir("paraboloid-alias");
    let net = "net = [[[0, 0, 1], [0, 1, 1]], [[1, 0, 1], [1, 1, 2]]]\n";
    let text = format!(
        "[[object]]\nname = \"new\"\nop = \"quadric_patch_image\"\n{net}quadric = \"hyperbolic_paraboloid_xy\"\n\n[[object]]\nname = \"old\"\nop = \"quadric_patch_image\"\n{net}quadric = \"seed_paraboloid\"\n"
    );
    let out = crate::common::build_json_in(&dir, &text);
    let read = |n: &str| crate::common::read_json(&out, n);
    let (a, b) = (read("new"), read("old"));
    assert_eq!(a["control_points"], b["control_points"]);
    assert_eq!(a["all_certificates_hold"], true);
}
