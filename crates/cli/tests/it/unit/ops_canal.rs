//! Unit tests of `rcagd_cli::ops::canal` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_cli::build::build_recipe;
use rcagd_cli::recipe::Recipe;

/// Builds a one-object recipe; `Err(message)` with the diagnostic's line and message.
fn build(text: &str) -> Result<Vec<rcagd_cli::model::Object>, (usize, String)> {
    let recipe =
        Recipe::parse("t.toml", text, None).map_err(|d| (d[0].line, d[0].message.clone()))?;
    build_recipe(&recipe, |_| {}).map_err(|d| (d[0].line, d[0].message.clone()))
}

/// The pipe of radius 1/4 around the quarter circle `((1 − t²), 2t)/(1 + t²)` (weights
/// 1, 1, 2): Krasauskas' pencil gives biquadratic patches, Peternell–Pottmann (4, 2).
#[test]
fn canal_surface_methods_give_their_degrees() {
    let recipe = |method: &str| {
        format!("[[object]]\nname = \"c\"\nop = \"canal_surface\"\npoints = [[1, 0, 0], [1, 1, 0], [0, 1, 0]]\nweights = [1, 1, 2]\nradius = [\"1/4\"]\nmethod = \"{method}\"\n")
    };
    let degrees = |method: &str| -> Vec<(usize, usize)> {
        let o = build(&recipe(method)).expect("canal surface");
        assert!(
            o[0].certificates.iter().all(|c| c.holds),
            "{method}: {:?}",
            o[0].certificates
        );
        match &o[0].geometry {
            rcagd_cli::model::Geometry::Patches(ps) => ps.iter().map(|p| p.degree()).collect(),
            g => panic!("{method}: unexpected geometry {}", g.kind()),
        }
    };
    assert!(degrees("lowest").iter().all(|&d| d == (2, 2)));
    assert!(degrees("krasauskas").iter().all(|&d| d == (2, 2)));
    assert!(degrees("peternell-pottmann").iter().all(|&d| d == (4, 2)));
    let e = build(&recipe("bezier")).expect_err("unknown method");
    assert_eq!(e.0, 7, "{e:?}");
}

#[test]
fn coincident_points_are_an_error_at_the_point() {
    let e = build(
        "[[object]]\nname = \"l\"\nop = \"line_through_points\"\np = [1, 2, 3]\nq = [1, 2, 3]\n",
    )
    .expect_err("coincident");
    assert_eq!(e.0, 5, "{e:?}");
    assert!(e.1.contains("coincident points"), "{e:?}");
}

#[test]
fn lines_through_points_and_planes_give_pluecker_coordinates() {
    let o = build(
        "[[object]]\nname = \"l\"\nop = \"line_through_points\"\np = [0, 0, 0]\nq = [1, 2, 3]\n",
    )
    .expect("line");
    assert!(o[0].certificates.iter().all(|c| c.holds));
    assert!(
        o[0].certificates[0]
            .property
            .contains("l = (1, 2, 3, 0, 0, 0)"),
        "{:?}",
        o[0].certificates[0]
    );
    let e = build(
        "[[object]]\nname = \"l\"\nop = \"line_of_planes\"\nu = [0, 1, 0, 0]\nv = [2, 2, 0, 0]\n",
    )
    .expect_err("parallel planes");
    assert!(e.1.contains("parallel"), "{e:?}");
}

#[test]
fn regulus_needs_skew_lines() {
    let e = build("[[object]]\nname = \"r\"\nop = \"regulus\"\nlines = [[[0, 0, 0], [1, 0, 0]], [[0, 0, 0], [0, 1, 0]], [[0, 0, 1], [1, 1, 1]]]\n")
        .expect_err("meeting lines");
    assert_eq!(e.0, 4, "{e:?}");
    assert!(e.1.contains("must be skew"), "{e:?}");
}

#[test]
fn no_real_envelope_names_the_interval_at_the_radius() {
    // m = (t, 0, 0) on [0, 1], r = 2t: |m'| = 1 < |r'| = 2 everywhere
    let e = build("[[object]]\nname = \"c\"\nop = \"canal_surface\"\npoints = [[0, 0, 0], [1, 0, 0]]\nradius = [1, 3]\n")
        .expect_err("no envelope");
    assert_eq!(e.0, 5, "{e:?}");
    assert!(
        e.1.contains("no real envelope") && e.1.contains("(0, 1)"),
        "{e:?}"
    );
}

#[test]
fn degenerate_spine_is_an_error() {
    let e = build(
        "[[object]]\nname = \"c\"\nop = \"pipe\"\npoints = [[1, 1, 1], [1, 1, 1]]\nradius = 1\n",
    )
    .expect_err("constant spine");
    assert!(e.1.contains("degenerate spine"), "{e:?}");
}

#[test]
fn extension_fields_are_named() {
    // m = (3t, 3t², 2t³) (a PH cubic), r = t: D = 4(3t² + 1)(3t² + 2) needs √3 and √6
    let e = build("[[object]]\nname = \"c\"\nop = \"canal_surface\"\npoints = [[0, 0, 0], [1, 0, 0], [2, 1, 0], [3, 3, 2]]\nradius = [0, \"1/3\", \"2/3\", 1]\n")
        .expect_err("extension");
    assert!(e.1.contains("extension") || e.1.contains("Q(√"), "{e:?}");
}
