//! The `cyclide_blend` op with `point2` (the fitting contact sphere computed by the library),
//! `dupin_cyclide_spheres` in all three plane types, and the `pn_cone_envelope` op in the
//! degree-reducing frame.

use crate::common::{build_json_certified, value_exact};

/// The elbow from any sphere of cylinder 2: the same quarter torus as with `sphere2`; the
/// other side gives the mirrored elbow.
#[test]
fn cyclide_blend_from_any_sphere_of_cone_two() {
    let with = |extra: &str| {
        format!(
            "[[object]]\nname = \"elbow\"\nop = \"cyclide_blend\"\nsphere1 = [2, 0, 0, 1]\ndirection1 = [1, 0, 0, 0]\ndirection2 = [0, 1, 0, 0]\n{extra}\n"
        )
    };
    let given = build_json_certified("cyc-given", &with("sphere2 = [0, 2, 0, 1]"), "elbow");
    let fitted = build_json_certified("cyc-fitted", &with("point2 = [0, 7, 0, 1]"), "elbow");
    assert_eq!(given["control_points"], fitted["control_points"]);
    let other = build_json_certified(
        "cyc-other",
        &with("point2 = [0, 7, 0, 1]\nside2 = -1"),
        "elbow",
    );
    assert_ne!(given["control_points"], other["control_points"]);
    assert_eq!(value_exact(&other, "kind"), "ring");
}

/// The gallery's cone envelope is built in the frame ζ = (0, 1, 0) with a unit normal of
/// degree 2k − 2 = 2 in t.
#[test]
fn cone_envelope_reports_its_reducing_frame() {
    let recipe = "[[object]]\nname = \"env\"\nop = \"pn_cone_envelope\"\ncenter1 = [[0, 2, 0], [0, 0, 1], [2, 0, 0]]\nradius1 = [3]\ncenter2 = [[0], [1], [0]]\nradius2 = [1]\ndomain = [1, 2, \"1/4\", 1]\n";
    let v = build_json_certified("cone-env-frame", recipe, "env");
    assert_eq!(value_exact(&v, "normal_degree_t"), "2");
    assert!(
        value_exact(&v, "frame_axis").contains('1'),
        "{}",
        value_exact(&v, "frame_axis")
    );
    let props: Vec<String> = v["certificates"]
        .as_array()
        .expect("certificates")
        .iter()
        .map(|c| c["property"].as_str().unwrap_or("").to_string())
        .collect();
    assert!(props.iter().any(|p| p.contains("Prop. 4.1")), "{props:#?}");
}

/// Three spheres on a pe hyperbola (spheres of the second family of the printed ring
/// cyclide) give that ring cyclide (16 patches); three spheres in a γ-plane give the
/// parabolic cyclide on the box `t × s` (one patch); all certificates hold.
#[test]
fn dupin_cyclide_spheres_on_a_hyperbola_and_in_a_gamma_plane() {
    let hyper = "[[object]]\nname = \"c\"\nop = \"dupin_cyclide_spheres\"\ncenters = [[0, 3, 0], [0, -3, 0], [0, \"15/4\", 3]]\nradii = [9, -1, \"41/4\"]\noffset = 1\n";
    let v = build_json_certified("cyc-hyperbola", hyper, "c");
    assert_eq!(value_exact(&v, "kind"), "ring");
    let gamma = "[[object]]\nname = \"c\"\nop = \"dupin_cyclide_spheres\"\ncenters = [[0, 0, 0], [1, 1, 1], [2, 2, 4]]\nradii = [1, 2, 5]\nt = [-1, 1]\ns = [-1, 1]\n";
    let v = build_json_certified("cyc-gamma", gamma, "c");
    assert_eq!(value_exact(&v, "kind"), "parabolic");
}
