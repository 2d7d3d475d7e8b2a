//! The `sweep` topic ops: `ph_rrmf` (a PH curve with its exact rational RMF) and
//! `sweep_rrmf` (an exact twist-free sweep of a rational profile), through the binary:
//! every certificate holds, STEP and IGES are written, a curve without a rational RMF is
//! refused with the reason named.

use crate::common::{bin, build_json_certified, build_refused, stderr, temp_dir, write};

const ELLIPSE: &str = r#"profile = [
  [[1, 0], [1, "1/2"], [0, "1/2"]],
  [[0, "1/2"], [-1, "1/2"], [-1, 0]],
  [[-1, 0], [-1, "-1/2"], [0, "-1/2"]],
  [[0, "-1/2"], [1, "-1/2"], [1, 0]],
]
weights = [[1, 1, 2], [2, 1, 1], [1, 1, 2], [2, 1, 1]]
"#;

#[test]
fn ph_rrmf_from_generator_and_from_quaternions() {
    let v = build_json_certified(
        "rrmf_gen",
        "[[object]]\nname = \"c\"\nop = \"ph_rrmf\"\na0 = [2, 0, 1, 0]\na1 = [1, 2, 0, -1]\n",
        "c",
    );
    let certs = v["certificates"].to_string();
    assert!(certs.contains("rotation-minimizing") && certs.contains("quintic RRMF condition"));
    // a planar quintic given by quaternions: its ERF is already an RMF
    build_json_certified(
        "rrmf_planar",
        "[[object]]\nname = \"p\"\nop = \"ph_rrmf\"\nquaternions = [[1, 0, 0, 2], [3, 0, 0, -1], [2, 0, 0, 1]]\n",
        "p",
    );
}

#[test]
fn ph_rrmf_refuses_generic_quintic() {
    let dir = temp_dir("rrmf_refused");
    let err = build_refused(
        &dir,
        "[[object]]\nname = \"g\"\nop = \"ph_rrmf\"\nquaternions = [[1, 0, 0, 0], [1, 1, 0, 1], [0, 0, 1, 1]]\n",
    );
    assert!(err.contains("not an RRMF curve"), "{err}");
    let err = build_refused(
        &dir,
        "[[object]]\nname = \"g\"\nop = \"ph_rrmf\"\na0 = [0, 0, 0, 0]\na1 = [1, 2, 0, -1]\n",
    );
    assert!(err.contains("A_0 ≠ 0"), "{err}");
}

#[test]
fn sweep_rrmf_ellipse_exports_step_and_iges() {
    let dir = temp_dir("rrmf_sweep");
    let recipe = format!(
        "[[object]]\nname = \"s\"\nop = \"sweep_rrmf\"\na0 = [2, 0, 1, 0]\na1 = [1, 2, 0, -1]\n{ELLIPSE}"
    );
    let file = write(&dir, "r.toml", &recipe);
    let out = dir.join("out");
    let o = bin()
        .arg("build")
        .arg(&file)
        .args(["--format", "json,step,iges", "--out"])
        .arg(&out)
        .output()
        .expect("run rcagd");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(out.join("s.step").exists() && out.join("s.igs").exists());
    let v = crate::common::read_json(&out, "s");
    assert_eq!(v["all_certificates_hold"], true);
    assert_eq!(v["degree_summary"], "4 patches of bidegree (2, 13)");
    let err = build_refused(
        &dir,
        &format!("{}\n[[object]]\nname = \"t\"\nop = \"sweep_rrmf\"\na0 = [2, 0, 1, 0]\na1 = [1, 2, 0, -1]\nprofile = [[[1, 0], [0, 1]]]\nweights = [[1, -1]]\n", ""),
    );
    assert!(err.contains("weight"), "{err}");
}

/// RRMF Hermite data through the op: an exact RRMF quintic whose certificates hold, the
/// data matched to rounding (the residuals are reported as values).
#[test]
fn ph_rrmf_hermite_interpolates() {
    let v = build_json_certified(
        "rrmf_hermite",
        "[[object]]\nname = \"h\"\nop = \"ph_rrmf\"\nhermite = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [3, 1, 1], [1, 1, 0], [0, 0, 1]]\n",
        "h",
    );
    let val = |n: &str| {
        v["values"]
            .as_array()
            .unwrap()
            .iter()
            .find(|x| x["name"] == n)
            .unwrap()["f64"]
            .as_f64()
            .unwrap()
    };
    assert!(val("point_residual") < 1e-12);
    assert!(val("tangent_residual") < 1e-12);
    assert!(val("frame_residual") < 1e-9);
    let dir = temp_dir("rrmf_hermite_bad");
    let err = build_refused(
        &dir,
        "[[object]]\nname = \"h\"\nop = \"ph_rrmf\"\nhermite = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [3, 1, 1], [1, 1, 0], [0, 0, 1]]\n",
    );
    assert!(err.contains("not orthogonal"), "{err}");
}
