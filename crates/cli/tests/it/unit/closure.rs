//! Unit tests of `rcagd_cli::closure` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_cli::closure::*;
use rcagd_cli::model::{Geometry, Object};
use rcagd_cli::recipe::Recipe;
use rcagd_io::quantity::Quantity;

fn build(src: &str) -> Vec<Object> {
    let r = Recipe::parse("r.toml", src, None).unwrap();
    rcagd_cli::build::build_recipe(&r, |_| {}).unwrap()
}

#[test]
fn a_closed_cover_closes_and_one_with_a_piece_missing_is_reported() {
    let torus =
        build("[[object]]\nname = \"t\"\nop = \"torus\"\nmajor_radius = 3\nminor_radius = 1\n");
    assert_eq!(should_close(&torus[0]), Some("a whole torus"));
    assert_eq!(closure_warning(&torus[0]), None);
    let mut sphere = build("[[object]]\nname = \"s\"\nop = \"sphere_cover\"\n");
    assert_eq!(closure_warning(&sphere[0]), None);
    // a piece missing: the shell is open and the object is annotated
    let Geometry::Patches(p) = &mut sphere[0].geometry else {
        panic!("patches expected");
    };
    p.pop();
    let w = annotate(&mut sphere[0]).expect("a warning");
    assert!(w.contains("does not close") && w.contains("open"), "{w}");
    assert!(sphere[0].values.iter().any(|v| v.name == "closure_warning"));
    // a pipe around a spine closed with G¹ should close, and does (its seam is
    // closed exactly, rcagd::canal::seam); an open spine need not close
    let open = build(
        "[[object]]\nname = \"q\"\nop = \"pipe\"\npoints = [[0, 0, 0], [4, 0, 0], [4, 4, 0]]\nradius = \"1/20\"\n",
    );
    assert_eq!(should_close(&open[0]), None);
    let closed = build(
        "[[object]]\nname = \"c\"\nop = \"pipe\"\npoints = [[0, 0, 0], [3, 0, 0], [1, 4, 0], [-1, 0, 0], [0, 0, 0]]\nradius = \"1/8\"\n",
    );
    assert_eq!(
        should_close(&closed[0]),
        Some("a pipe around a closed spine")
    );
    assert_eq!(closure_warning(&closed[0]), None);
    // with one patch of the seam removed it is reported again
    let mut cut = closed[0].clone();
    let Geometry::Patches(p) = &mut cut.geometry else {
        panic!("patches expected");
    };
    p.pop();
    assert!(closure_warning(&cut).is_some_and(|w| w.contains("does not close")));
}

#[test]
fn a_pipe_around_a_closed_spine_file_should_close() {
    // the same G¹-closed quartic loop as a spine file (rcagd JSON, homogeneous
    // [w, wx, wy, wz]): the rule no longer depends on how the spine was given
    let dir = std::env::temp_dir().join(format!("rcagd-closure-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let spine = dir.join("loop.json");
    std::fs::write(
        &spine,
        r#"{"kind": "curve", "control_points": [[1, 0, 0, 0], [1, 3, 0, 0], [1, 1, 4, 0], [1, -1, 0, 0], [1, 0, 0, 0]]}"#,
    )
    .unwrap();
    let recipe = format!(
        "[[object]]\nname = \"f\"\nop = \"pipe\"\nspine_file = {:?}\nradius = \"1/8\"\n",
        spine.display().to_string()
    );
    let from_file = build(&recipe);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(
        should_close(&from_file[0]),
        Some("a pipe around a closed spine")
    );
    assert_eq!(closure_warning(&from_file[0]), None);
    // a loop closed with G⁰ only (end tangent (2, 1, 0) against start tangent
    // (3, 0, 0)) is not a closed tube: its end discs meet, and the op refuses it
    let r = Recipe::parse(
        "r.toml",
        "[[object]]\nname = \"k\"\nop = \"pipe\"\npoints = [[0, 0, 0], [3, 0, 0], [1, 4, 0], [-2, -1, 0], [0, 0, 0]]\nradius = \"1/100\"\n",
        None,
    )
    .unwrap();
    let err = rcagd_cli::build::build_recipe(&r, |_| {}).unwrap_err();
    assert!(format!("{err:?}").contains("intersects itself"), "{err:?}");
    // an open spine says so
    let open = build(
        "[[object]]\nname = \"q\"\nop = \"pipe\"\npoints = [[0, 0, 0], [4, 0, 0], [4, 4, 0]]\nradius = \"1/20\"\n",
    );
    assert!(
        open[0]
            .values
            .iter()
            .any(|v| v.name == rcagd_cli::ops::canal::SPINE_CLOSED
                && v.value == Quantity::Bool(false))
    );
}
