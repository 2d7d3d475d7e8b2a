//! The sphere-family ops (`crates/cli/src/ops/sphere_family.rs`): a family given by its
//! centres and radii is recognized (net, support functions, envelope, certificates), and
//! every failure is located at the parameter that causes it — the net's `points`, the
//! support functions `a`, `b`, or the family's `centre` — with the named reason.

use rcagd_algebra::Rational;
use rcagd_cli::build::build_recipe;
use rcagd_cli::model::{Geometry, Object};
use rcagd_cli::recipe::Recipe;

fn build(text: &str) -> Vec<Object> {
    let recipe = Recipe::parse("t.toml", text, None).expect("recipe parses");
    build_recipe(&recipe, |_| {}).expect("recipe builds")
}

/// Builds a one-object recipe expecting an error: `(line, message)`.
fn build_err(text: &str) -> (usize, String) {
    let recipe = Recipe::parse("t.toml", text, None).expect("recipe parses");
    let d = build_recipe(&recipe, |_| {}).expect_err("the recipe must fail");
    (d[0].line, d[0].message.clone())
}

const HEAD: &str = "[[object]]\nname = \"f\"\n";

#[test]
fn a_family_given_by_centres_and_radii_is_recognized_and_certified() {
    // Gruber (3.15): centres (−u², 2u, 2v), radii 4u + v² (§3.3.1)
    let text = format!(
        "{HEAD}op = \"sphere_family_recognize\"\ncentre = [[[0, 0, 0], [0, 0, 2]], [[0, 2, 0], [0, 0, 0]], [[-1, 0, 0], [0, 0, 0]]]\nradius = [[0, 0, 1], [4, 0, 0]]\ndomain = [\"1/4\", 1, \"1/4\", 1]\n"
    );
    let objs = build(&text);
    assert_eq!(objs.len(), 1);
    let o = &objs[0];
    crate::common::assert_exact_patches_certifying(o, "recognized family is the given one");
    // the same envelope as the net recipe of §3.3.1
    let net = build(&format!(
        "{HEAD}op = \"sphere_family_envelope\"\nnet = \"hyperbolic\"\npoints = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 2, 0, 1], [0, 0, 1, 0]]\na = [[0], [0], [1]]\nb = [[0, 0, 1]]\ndomain = [\"1/4\", 1, \"1/4\", 1]\n"
    ));
    let pts = |o: &Object| match &o.geometry {
        Geometry::Patches(p) => p
            .iter()
            .map(|x| {
                x.eval(
                    &(Rational::from(1) / Rational::from(2)),
                    &(Rational::from(1) / Rational::from(3)),
                )
                .ok()
            })
            .collect::<Vec<_>>(),
        _ => Vec::new(),
    };
    assert_eq!(pts(o), pts(&net[0]));
}

#[test]
fn recognition_errors_are_located_at_the_family() {
    // centres (u, v, u³ + v²), radii uv: the normal lines span 5 dimensions
    let text = format!(
        "{HEAD}op = \"sphere_family_recognize\"\ncentre = [[[0, 0, 0], [0, 1, 0], [0, 0, 1]], [[1, 0, 0], [0, 0, 0], [0, 0, 0]], [[0, 0, 0], [0, 0, 0], [0, 0, 0]], [[0, 0, 1], [0, 0, 0], [0, 0, 0]]]\nradius = [[0, 0], [0, 1]]\n"
    );
    let (line, msg) = build_err(&text);
    assert_eq!(line, 4, "{msg}");
    assert!(
        msg.contains("not a fibration") && msg.contains("5-dimensional"),
        "{msg}"
    );
    // nested spheres: centres (u, v, v²), radii 2u
    let text = format!(
        "{HEAD}op = \"sphere_family_recognize\"\ncentre = [[[0, 0, 0], [0, 1, 0], [0, 0, 1]], [[1, 0, 0], [0, 0, 0], [0, 0, 0]]]\nradius = [[0], [2]]\n"
    );
    let (line, msg) = build_err(&text);
    assert_eq!(line, 4, "{msg}");
    assert!(msg.contains("no real envelope"), "{msg}");
    // a centre coefficient with two coordinates
    let (line, msg) = build_err(&format!(
        "{HEAD}op = \"sphere_family_recognize\"\ncentre = [[[0, 0], [1, 0]]]\nradius = [[0, 1]]\n"
    ));
    assert_eq!(line, 4, "{msg}");
    assert!(msg.contains("three [x, y, z]"), "{msg}");
}

#[test]
fn support_function_errors_name_a_or_b() {
    let net =
        "net = \"hyperbolic\"\npoints = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 2, 0, 1], [0, 0, 1, 0]]\n";
    // a depends on v: blamed on a (line 6)
    let (line, msg) = build_err(&format!(
        "{HEAD}op = \"sphere_family_envelope\"\n{net}a = [[0, 1], [0, 0], [1, 0]]\nb = [[0, 0, 1]]\n"
    ));
    assert_eq!(line, 6, "{msg}");
    assert!(msg.contains("a_v"), "{msg}");
    // b depends on u: blamed on b (line 7)
    let (line, msg) = build_err(&format!(
        "{HEAD}op = \"sphere_family_envelope\"\n{net}a = [[0], [0], [1]]\nb = [[0, 0, 1], [1, 0, 0]]\n"
    ));
    assert_eq!(line, 7, "{msg}");
    assert!(msg.contains("b_u"), "{msg}");
    // a degenerate net (the axes meet): blamed on points (line 5)
    let (line, msg) = build_err(&format!(
        "{HEAD}op = \"sphere_family_envelope\"\nnet = \"hyperbolic\"\npoints = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]\na = [[0], [0], [1]]\nb = [[0, 0, 1]]\n"
    ));
    assert_eq!(line, 5, "{msg}");
    assert!(msg.contains("axes"), "{msg}");
    // parabolic a_u ≠ b_v: blamed on b
    let (line, msg) = build_err(&format!(
        "{HEAD}op = \"sphere_family_envelope\"\nnet = \"parabolic\"\npoints = [[1, 0, 0, 0], [0, 0, 0, 1], [1, -1, 0, 0], [0, 0, 1, 0]]\na = [[0], [0], [1]]\nb = [[0, 0], [0, 1]]\n"
    ));
    assert_eq!(line, 7, "{msg}");
    assert!(msg.contains("a_u ≠ b_v"), "{msg}");
}

#[test]
fn the_centre_surface_is_a_second_object() {
    let objs = build(&format!(
        "{HEAD}op = \"sphere_family_envelope\"\nnet = \"hyperbolic\"\npoints = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 2, 0, 1], [0, 0, 1, 0]]\na = [[0], [0], [1]]\nb = [[0, 0, 1]]\ncentres = true\n"
    ));
    assert_eq!(objs.len(), 2);
    assert_eq!(objs[1].name, "f_centres");
    assert!(objs[1].certificates.iter().all(|c| c.holds && c.exact));
    // a corner of the centre patch is π(Φ(s, t)) at (s, t) = (1/4, 1/4): Φ = (−u², 2u, 2v, …)
    // with u, v from (3.17); it lies on the paraboloid x = −y²/4 of (3.15)
    let Geometry::Patches(p) = &objs[1].geometry else {
        panic!("patches")
    };
    for piece in p {
        let c = piece
            .eval(&Rational::from(0), &Rational::from(0))
            .expect("corner");
        assert_eq!(
            c[0].clone(),
            -(c[1].clone() * c[1].clone()) / Rational::from(4)
        );
    }
}

/// The polar example of §3.3.4 with `spheres`, `other_sheet` and `combine`.
fn polar(extra: &str) -> String {
    format!(
        "{HEAD}op = \"sphere_family_envelope\"\nnet = \"hyperbolic\"\npoints = [[1, 0, 0, 0], [0, 0, 0, -1], [0, 1, 0, 0], [0, 0, 1, 0]]\na = [[0], [0], [1]]\nb = [[0, 0, 1]]\ndomain = [\"1/4\", 1, \"1/4\", 1]\n{extra}"
    )
}

fn patch_count(o: &Object) -> usize {
    match &o.geometry {
        Geometry::Patches(p) => p.len(),
        _ => 0,
    }
}

#[test]
fn both_sheets_and_enveloped_spheres_are_certified_objects() {
    // §3.3.1 (passant axes): the other sheet has bidegree (14, 14), the spheres 16 patches each
    let text = format!(
        "{HEAD}op = \"sphere_family_envelope\"\nnet = \"hyperbolic\"\npoints = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 2, 0, 1], [0, 0, 1, 0]]\na = [[0], [0], [1]]\nb = [[0, 0, 1]]\ndomain = [\"1/4\", 1, \"1/4\", 1]\nspheres = 2\nother_sheet = true\n"
    );
    let objs = build(&text);
    let names: Vec<&str> = objs.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["f", "f_other_sheet", "f_spheres"]);
    crate::common::assert_exact_patches_certifying(&objs[1], "|Ψ − π(Φ)|² ≡ Φ₄²");
    crate::common::assert_exact_patches_certifying(&objs[2], "second contact point");
    assert_eq!(patch_count(&objs[2]), 32, "two sixteen-patch sphere covers");
    let certs = &objs[2].certificates;
    assert!(
        certs
            .iter()
            .filter(|c| c.property.contains("contact point"))
            .count()
            == 4,
        "two contact points per sphere"
    );
    // combined: one object holding both sheets and the spheres, with all certificates
    let one = build(&format!("{text}combine = true\n"));
    assert_eq!(one.len(), 1);
    assert_eq!(
        patch_count(&one[0]),
        patch_count(&objs[0]) + patch_count(&objs[1]) + 32
    );
    assert_eq!(
        one[0].certificates.len(),
        objs.iter().map(|o| o.certificates.len()).sum::<usize>()
    );
    assert!(one[0].certificates.iter().all(|c| c.holds));
}

#[test]
fn enveloped_sphere_options_fail_at_their_parameter() {
    for (extra, want) in [("spheres = -1\n", "≥ 0"), ("spheres = 17\n", "at most 16")] {
        let (line, msg) = build_err(&polar(extra));
        assert_eq!(line, 9, "{msg}");
        assert!(msg.contains(want), "{msg}");
    }
    // §3.5.3 a: the sphere at (1/2, 1/2) has radius 0
    let text = format!(
        "{HEAD}op = \"sphere_family_envelope\"\nnet = \"parabolic\"\npoints = [[1, 0, 0, 1], [0, 0, 1, 0], [0, 1, 0, 0], [0, 0, 0, 1]]\na = [[0], [0], [1]]\nb = [[0, 0], [0, 2]]\ndomain = [\"1/4\", 1, \"1/4\", 1]\nspheres = 2\n"
    );
    let (line, msg) = build_err(&text);
    assert_eq!(line, 9, "{msg}");
    assert!(msg.contains("non-zero"), "{msg}");
}

const RULED: &str =
    "[[object]]\nname = \"r\"\nop = \"line_congruence_strips\"\ncongruence = \"ruled_tangents\"\n";

#[test]
fn the_tangents_of_a_ruled_surface_along_a_generator_are_drawn_as_a_parabolic_net() {
    // X(t, v) = (1, t, v, tv): the hyperbolic paraboloid z = xy
    let objs = build(&format!(
        "{RULED}points = [[1, 0, 0, 0], [0, 1, 0, 0]]\nruling = [[0, 0, 1, 0], [0, 0, 0, 1]]\nt0 = \"1/2\"\nu = [-1, 1]\nv = [-1, 0, 1]\ntwist = 0\nlambda = [\"-1/2\", \"1/2\"]\n"
    ));
    crate::common::assert_exact_patches_certifying(&objs[0], "lies in the tangent plane");
    assert_eq!(patch_count(&objs[0]), 3);
    // a cone (constant vertex p): every generator is torsal
    let (line, msg) = build_err(&format!(
        "{RULED}points = [[1, 0, 0, 0]]\nruling = [[0, 1, 0, 0], [0, 0, 1, 0]]\n"
    ));
    assert_eq!(line, 5, "{msg}");
    assert!(msg.contains("torsal"), "{msg}");
    // the ruling is required
    let (line, msg) = build_err(&format!("{RULED}points = [[1, 0, 0, 0], [0, 1, 0, 0]]\n"));
    assert!(msg.contains("ruling"), "{line}: {msg}");
}

#[test]
fn the_cyclographic_construction_draws_both_contact_points() {
    let text = format!(
        "{HEAD}op = \"sphere_family_cyclographic\"\nnet = \"hyperbolic\"\npoints = [[1, 0, 0, 0], [0, 0, 0, -1], [0, 1, 0, 0], [0, 0, 1, 0]]\na = [[0], [0], [1]]\nb = [[0, 0, 1]]\nat = [[\"1/2\", \"1/2\"], [\"3/4\", \"1/3\"]]\n"
    );
    let objs = build(&text);
    let o = &objs[0];
    assert!(matches!(&o.geometry, Geometry::Curves(c) if c.len() == 4));
    assert!(
        o.certificates.iter().all(|c| c.holds && c.exact),
        "{:#?}",
        o.certificates
    );
    assert_eq!(
        o.certificates
            .iter()
            .filter(|c| c.property.contains("other sheet"))
            .count(),
        2
    );
    // a parameter point on an axis (no unique net line) or of the wrong size: at `at`
    let (line, msg) = build_err(&text.replace(
        "at = [[\"1/2\", \"1/2\"], [\"3/4\", \"1/3\"]]",
        "at = [[\"1/2\", \"1/2\", 1]]",
    ));
    assert_eq!(line, 8, "{msg}");
    assert!(msg.contains("[s, t]"), "{msg}");
}

const PARAMETRIZED: &str = "[[object]]\nname = \"n\"\nop = \"line_congruence_parametrized\"\n";

/// `[W, X, Y, Z]` power coefficients of the paraboloid z = u² + v² (rows u⁰, u¹, u²).
const PARABOLOID: &str = "surface = [[[1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], [[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]], [[0, 0, 0, 1], [0, 0, 0, 0], [0, 0, 0, 0]]]\n";

fn value_int(o: &Object, name: &str) -> i64 {
    match o.values.iter().find(|v| v.name == name).map(|v| &v.value) {
        Some(rcagd_io::quantity::Quantity::Integer(k)) => *k,
        other => panic!("{name}: {other:?}"),
    }
}

#[test]
fn a_normal_congruence_is_drawn_with_order_class_and_its_rational_focal_sheet() {
    let objs = build(&format!(
        "{PARAMETRIZED}{PARABOLOID}u = [\"1/4\", 1]\nv = [0, \"1/2\"]\nlambda = [0, \"1/2\"]\nfocal_sheets = true\ndomain = [\"1/4\", 1, 0, \"1/2\"]\n"
    ));
    // the strips and the evolute; the axis (a focal curve) is reported, not drawn
    assert_eq!(
        objs.len(),
        2,
        "{:?}",
        objs.iter().map(|o| &o.name).collect::<Vec<_>>()
    );
    crate::common::assert_exact_patches_certifying(&objs[0], "order 3 and class 2");
    crate::common::assert_exact_patches_certifying(&objs[0], "focal sheet 1: det(p, q, f_u, f_v)");
    crate::common::assert_exact_patches_certifying(&objs[0], "orthogonal to the surface");
    assert_eq!(
        (
            value_int(&objs[0], "order"),
            value_int(&objs[0], "class"),
            value_int(&objs[0], "mu")
        ),
        (3, 2, 1)
    );
    // the paraboloid of revolution: its base points at infinity are not ordinary, the
    // Bézout bound (7) stays above the count (5)
    assert!(!value_bool(&objs[0], "order_class_exact"));
    assert_eq!(
        (
            value_int(&objs[0], "order_at_most"),
            value_int(&objs[0], "class_at_most")
        ),
        (5, 4)
    );
    assert_eq!(objs[1].name, "n_focal_1");
    crate::common::assert_exact_patches_certifying(&objs[1], "sheet patches is > 0");
    // the elliptic paraboloid z = u² + 2v²: irrational focal sheets, a located error
    let (line, msg) = build_err(&format!(
        "{PARAMETRIZED}surface = [[[1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 2]], [[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]], [[0, 0, 0, 1], [0, 0, 0, 0], [0, 0, 0, 0]]]\nfocal_sheets = true\ndomain = [0, 1, 0, 1]\n"
    ));
    assert_eq!(line, 5, "{msg}");
    assert!(msg.contains("irrational"), "{msg}");
    // without focal sheets it builds, order 5 and class 2
    let objs = build(&format!(
        "{PARAMETRIZED}surface = [[[1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 2]], [[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]], [[0, 0, 0, 1], [0, 0, 0, 0], [0, 0, 0, 0]]]\n"
    ));
    assert_eq!(
        (value_int(&objs[0], "order"), value_int(&objs[0], "class")),
        (5, 2)
    );
    // exact: the counts reach the Bézout bound
    assert!(value_bool(&objs[0], "order_class_exact"));
    match objs[0]
        .values
        .iter()
        .find(|v| v.name == "order_class")
        .map(|v| &v.value)
    {
        Some(rcagd_io::quantity::Quantity::Text(t)) => {
            assert!(t.starts_with("order 5, class 2 (exact"), "{t}")
        }
        other => panic!("order_class: {other:?}"),
    }
}

fn value_bool(o: &Object, name: &str) -> bool {
    match o.values.iter().find(|v| v.name == name).map(|v| &v.value) {
        Some(rcagd_io::quantity::Quantity::Bool(b)) => *b,
        other => panic!("{name}: {other:?}"),
    }
}

#[test]
fn a_congruence_of_two_point_families_and_its_input_errors() {
    // the lines meeting the conic (1 + u², 2u, 0, 1 − u²) and the line (1, 5, v, 0): (2, 2),
    // both focal sheets curves
    let pq = "p = [[[1, 0, 0, 1]], [[0, 2, 0, 0]], [[1, 0, 0, -1]]]\nq = [[[1, 5, 0, 0], [0, 0, 1, 0]]]\n";
    let objs = build(&format!(
        "{PARAMETRIZED}{pq}u = [0, 1]\nv = [0, 1]\ntwist = 1\n"
    ));
    crate::common::assert_exact_patches_certifying(&objs[0], "order 2 and class 2");
    let (_, msg) = build_err(&format!(
        "{PARAMETRIZED}{pq}focal_sheets = true\ndomain = [0, 1, 0, 1]\n"
    ));
    assert!(msg.contains("both focal sheets are curves"), "{msg}");
    // both inputs, none, a malformed point, too many trials
    let (_, msg) = build_err(&format!("{PARAMETRIZED}{PARABOLOID}{pq}"));
    assert!(msg.contains("either"), "{msg}");
    let (_, msg) = build_err(PARAMETRIZED);
    assert!(msg.contains("either"), "{msg}");
    let (_, msg) = build_err(&format!(
        "{PARAMETRIZED}p = [[[1, 0, 0]]]\nq = [[[0, 1, 0]]]\n"
    ));
    assert!(msg.contains("four coordinates"), "{msg}");
    let (_, msg) = build_err(&format!("{PARAMETRIZED}{PARABOLOID}trials = 9\n"));
    assert!(msg.contains("between 2 and 6"), "{msg}");
    // a curve has no normal congruence
    let (_, msg) = build_err(&format!(
        "{PARAMETRIZED}surface = [[[1, 0, 0, 0]], [[0, 1, 1, 0]], [[0, 0, 0, 1]]]\n"
    ));
    assert!(msg.contains("tangent plane"), "{msg}");
}

#[test]
fn the_cyclographic_construction_runs_at_spheres_of_a_given_family() {
    // Gruber (3.15) as a plain family: centres (−u², 2u, 2v), radii 4u + v²
    let fam = format!(
        "{HEAD}op = \"sphere_family_recognize\"\ncentre = [[[0, 0, 0], [0, 0, 2]], [[0, 2, 0], [0, 0, 0]], [[-1, 0, 0], [0, 0, 0]]]\nradius = [[0, 0, 1], [4, 0, 0]]\ndomain = [\"1/4\", 1, \"1/4\", 1]\n"
    );
    let objs = build(&format!("{fam}at = [[2, \"1/3\"]]\n"));
    assert_eq!(objs.len(), 2);
    let o = &objs[1];
    assert_eq!(o.name, "f_contacts");
    assert!(matches!(&o.geometry, Geometry::Curves(c) if c.len() == 2));
    assert!(
        o.certificates.iter().all(|c| c.holds && c.exact),
        "{:#?}",
        o.certificates
    );
    assert_eq!(
        o.certificates
            .iter()
            .filter(|c| c.property.contains("on S_u"))
            .count(),
        2
    );
    // a timelike tangent plane (|u| < √3): no real contact point, located at `at`
    let (line, msg) = build_err(&format!("{fam}at = [[\"1/2\", \"1/3\"]]\n"));
    assert_eq!(line, 7, "{msg}");
    assert!(msg.contains("timelike"), "{msg}");
    // irrational contact points are named, not rounded
    let (_, msg) = build_err(&format!("{fam}at = [[3, \"1/2\"]]\n"));
    assert!(msg.contains("irrational") && msg.contains('√'), "{msg}");
}

#[test]
fn the_reguli_generation_of_a_net_is_drawn_and_certified() {
    let reguli =
        "[[object]]\nname = \"r\"\nop = \"line_congruence_strips\"\ncongruence = \"reguli\"\n";
    let pts = "points = [[1, 1, 0, 0], [1, 0, 1, 1], [1, 0, 0, 0], [1, 0, 0, 1], [1, -1, 0, 0], [1, 0, -1, 1], [1, 1, 0, 0], [1, 0, -1, 1], [1, 0, 0, 0], [1, 0, 0, 1], [1, -1, 0, 0], [1, 0, 1, 1]]\n";
    let objs = build(&format!(
        "{reguli}{pts}u = [0, 1]\nv = [\"1/10\", \"9/10\"]\n"
    ));
    crate::common::assert_exact_patches_certifying(&objs[0], "are its generators");
    crate::common::assert_exact_patches_certifying(&objs[0], "exactly two independent complexes");
    assert_eq!(patch_count(&objs[0]), 2);
    // two transversal parameters are needed
    let (_, msg) = build_err(&format!("{reguli}{pts}u = [0, 1]\nv = [0]\n"));
    assert!(msg.contains("two transversal parameters"), "{msg}");
    // a regulus needs pairwise skew lines: a and b meet at the origin
    let bad = "points = [[1, 0, 0, 0], [1, 0, 1, 1], [1, 0, 0, 0], [1, 0, 0, 1], [1, -1, 0, 0], [1, 0, -1, 1], [1, 1, 0, 0], [1, 0, -1, 1], [1, 0, 0, 0], [1, 0, 0, 1], [1, -1, 0, 0], [1, 0, 1, 1]]\n";
    let (_, msg) = build_err(&format!(
        "{reguli}{bad}u = [0, 1]\nv = [\"1/10\", \"9/10\"]\n"
    ));
    assert!(msg.contains("skew"), "{msg}");
    // eleven points
    let (_, msg) = build_err(&format!("{reguli}points = [[1, 0, 0, 0]]\n"));
    assert!(msg.contains("needs 12 points"), "{msg}");
}

#[test]
fn the_cyclographic_image_of_a_plane_is_typed_and_certified() {
    let head = "[[object]]\nname = \"p\"\nop = \"cyclographic_plane_image\"\n";
    // cycles (u, v, 0) with radius 1 + u/2: spacelike, two image planes over Q(√3)
    let objs = build(&format!(
        "{head}point = [0, 0, 0, 1]\ndirections = [[1, 0, 0, \"1/2\"], [0, 1, 0, 0]]\ncycles = [[0, 0], [2, 0]]\n"
    ));
    let o = &objs[0];
    crate::common::assert_exact_patches_certifying(o, "image plane 1 touches the cycle");
    assert_eq!(patch_count(o), 32);
    let kind = o.values.iter().find(|v| v.name == "kind").expect("kind");
    assert!(matches!(&kind.value, rcagd_io::quantity::Quantity::Text(t) if t == "spacelike"));
    // radius growing faster than the centre moves: timelike, no image plane
    let objs = build(&format!(
        "{head}point = [0, 0, 0, 1]\ndirections = [[1, 0, 0, 2], [0, 1, 0, 0]]\ncycles = [[0, 0]]\n"
    ));
    let kind = objs[0]
        .values
        .iter()
        .find(|v| v.name == "kind")
        .expect("kind");
    assert!(matches!(&kind.value, rcagd_io::quantity::Quantity::Text(t) if t == "timelike"));
    // a point cycle cannot be drawn; the radius direction alone spans no envelope
    let (_, msg) = build_err(&format!(
        "{head}point = [0, 0, 0, 1]\ndirections = [[1, 0, 0, 1], [0, 1, 0, 0]]\ncycles = [[-1, 0]]\n"
    ));
    assert!(msg.contains("(-1, 0)"), "{msg}");
    let (_, msg) = build_err(&format!(
        "{head}point = [0, 0, 0, 1]\ndirections = [[0, 0, 0, 1], [0, 1, 0, 0]]\n"
    ));
    assert!(msg.contains("g' × h'"), "{msg}");
}

#[test]
fn the_pencil_and_bundle_generation_is_drawn_and_certified() {
    let head = "[[object]]\nname = \"b\"\nop = \"line_congruence_strips\"\ncongruence = \"pencil_bundle\"\n";
    let objs = build(&format!(
        "{head}points = [[0, 1, 0, 0], [0, 0, 0, 1], [-1, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]\nu = [\"1/2\", 2]\nv = [0, 1]\ntwist = 0\nlambda = [\"-1/2\", \"1/2\"]\n"
    ));
    crate::common::assert_exact_patches_certifying(&objs[0], "passes through the vertex c(u)");
    // φ₂ (x − 1 + z = 0) misses the axis: a bundle of lines, not a net
    let (_, msg) = build_err(&format!(
        "{head}points = [[0, 1, 0, 0], [0, 0, 0, 1], [-1, 1, 0, 0], [0, 0, 1, 0], [-1, 1, 0, 1]]\n"
    ));
    assert!(msg.contains("φ₂ must contain the axis"), "{msg}");
    let (_, msg) = build_err(&format!("{head}points = [[0, 1, 0, 0]]\n"));
    assert!(msg.contains("needs 5 points"), "{msg}");
}

#[test]
fn rational_support_functions_through_the_op() {
    // §3.3.1's net with a = u²/(1 + u²) and b = v²/(v² + 3): a rational family Φ, the
    // envelope certified; a zero denominator is an input error at the support function
    let net = "op = \"sphere_family_envelope\"\nnet = \"hyperbolic\"\npoints = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 2, 0, 1], [0, 0, 1, 0]]\na = [[0], [0], [1]]\nb = [[0, 0, 1]]\ndomain = [1, 2, \"1/4\", 1]\n";
    let objs = build(&format!(
        "{HEAD}{net}a_denominator = [[1], [0], [1]]\nb_denominator = [[3, 0, 1]]\n"
    ));
    crate::common::assert_exact_patches_certifying(&objs[0], "Φ solves (3.7)");
    let (_, m) = build_err(&format!("{HEAD}{net}a_denominator = [[0]]\n"));
    assert!(m.contains("denominator 0"), "{m}");
    // b's denominator must depend on v only, as b does
    let (_, m) = build_err(&format!("{HEAD}{net}b_denominator = [[3], [1]]\n"));
    assert!(m.contains("b_u"), "{m}");
}
