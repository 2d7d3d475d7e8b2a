//! The float path (`rcagd build --float`, module `rcagd_cli::float`): for every op with
//! a float builder, its doc example, every gallery object it builds and random exact
//! recipes are built exactly and in `f64`; the control points agree to 1e-12 relative
//! to the object's largest homogeneous coordinate, every `f64` certificate holds (and
//! says `exact = false`), and every float object says `arithmetic = "f64"`.

use crate::common::bin;
use proptest::prelude::*;
use rcagd_cli::build::{build_recipe_with, Arithmetic};
use rcagd_cli::float::{self, FLOAT_OPS};
use rcagd_cli::float_agreement;
use rcagd_cli::model::Object;
use rcagd_cli::recipe::Recipe;
use rcagd_io::quantity::Quantity;

/// The agreement demanded of float and exact control points (issue 20).
pub(crate) const REL: f64 = 1e-12;

/// For measuring by hand (`RCAGD_FLOAT_MEASURE=1 … -- --nocapture`): prints the smallest
/// tolerance `10^(k/4)`, `k ≥ −64`, at which the objects agree piece by piece
/// ([`float_agreement::agree`]; "none" if not within 1e-5 or split differently). Prints
/// nothing without the variable; never decides a test.
pub(crate) fn measure(what: &str, exact: &[Object], float: &[Object]) {
    if std::env::var_os("RCAGD_FLOAT_MEASURE").is_none() {
        return;
    }
    let tol = (0..=44)
        .map(|i| 10f64.powf(-16.0 + f64::from(i) / 4.0))
        .find(|t| float_agreement::agree(exact, float, *t).is_ok());
    eprintln!(
        "measured {what}: {}",
        tol.map_or("none".to_string(), |t| format!("{t:.2e}"))
    );
}

/// The one object of `src` built by the plain `f64` instantiation of its op
/// ([`float::F64_INSTANCES`]: the ops whose float path runs in double-double).
pub(crate) fn build_f64_instance(src: &str) -> Result<Vec<Object>, String> {
    let r = Recipe::parse("r.toml", src, None).map_err(|d| d[0].to_string())?;
    let o = r.objects.first().ok_or("no object")?;
    let (op, args) = rcagd_cli::build::check_object(&r.file, o).map_err(|d| d[0].to_string())?;
    let f = float::F64_INSTANCES
        .iter()
        .find(|f| f.name == op.name)
        .ok_or_else(|| format!("{} has no f64 instance", op.name))?;
    (f.build)(&args).map_err(|e| e.message)
}

pub(crate) fn build(src: &str, arithmetic: Arithmetic) -> Result<Vec<Object>, String> {
    let r = Recipe::parse("r.toml", src, None).map_err(|d| d[0].to_string())?;
    build_recipe_with(&r, arithmetic, |_| {}).map_err(|d| d[0].to_string())
}

/// Float and exact objects agree by the one rule of [`float_agreement::agree`] at `REL`;
/// besides, every float object has certificates and is marked `arithmetic = "f64"`.
pub(crate) fn agree(what: &str, exact: &[Object], float: &[Object]) -> Result<(), String> {
    float_agreement::agree(exact, float, REL).map_err(|m| format!("{what}: {m}"))?;
    marked(what, float)
}

/// Every float object has certificates and says `arithmetic = "f64"`.
pub(crate) fn marked(what: &str, float: &[Object]) -> Result<(), String> {
    for f in float {
        if f.certificates.is_empty() {
            return Err(format!("{what} ({}): no certificates", f.name));
        }
        let marked = f
            .values
            .iter()
            .any(|v| v.name == float::ARITHMETIC && v.value == Quantity::Text("f64".into()));
        if !marked {
            return Err(format!("{what} ({}): not marked arithmetic = f64", f.name));
        }
    }
    Ok(())
}

fn check(what: &str, src: &str) -> Result<(), String> {
    let exact = build(src, Arithmetic::Exact)?;
    let float = build(src, Arithmetic::Float)?;
    agree_or_split(what, &exact, &float)
}

/// As [`agree`], or a different split ([`float_agreement::agree_or_split`]). Findings of
/// the property tests (session 12, docs/plans/float.md): `dupin_canal` (center 0,
/// rho = 20/3, r0 = 0, s = −4/6: 20 exact, 18 f64 patches) and `circle_arc` (centre
/// (5, 0), radius 5, parameters 2/5 → −3/7: 3 exact, 4 f64 pieces).
pub(crate) fn agree_or_split(what: &str, exact: &[Object], float: &[Object]) -> Result<(), String> {
    float_agreement::agree_or_split(exact, float, REL).map_err(|m| format!("{what}: {m}"))?;
    marked(what, float)
}

/// The display parameters of `ph_curve` and `ph_helix` (frames, combs, feeds: extra
/// objects that have no float path and are refused by it) are dropped, so the curve
/// itself is compared.
fn without_display_objects(r: &Recipe) -> Recipe {
    let mut r = r.clone();
    for o in &mut r.objects {
        let op = o.op.clone();
        o.params.retain(|e| !float::is_display_param(&op, &e.key));
    }
    r
}

/// Gallery objects whose `f64` build is another parametrization of the same surface:
/// the same objects and degrees, holding inexact certificates, no control-point
/// comparison. Empty since session 15: `three_spheres_on_a_pe_hyperbola` (norm ratio `ab`
/// not a square over Q: the exact build parametrizes the conjugate pe hyperbola through a
/// rational point, `f64` took the square-ratio construction) now agrees, because the float
/// path replays the exact construction's decisions (`rcagd::cyclide::Route`).
const KNOWN_REPARAMETRIZED: &[(&str, &str)] = &[];

fn check_reparametrized(what: &str, r: &Recipe) {
    let e = build_recipe_with(r, Arithmetic::Exact, |_| {})
        .unwrap_or_else(|d| panic!("{what} (exact): {}", d[0]));
    let f = build_recipe_with(r, Arithmetic::Float, |_| {})
        .unwrap_or_else(|d| panic!("{what} (f64): {}", d[0]));
    assert_eq!(e.len(), f.len(), "{what}: object counts");
    for (a, b) in e.iter().zip(&f) {
        assert_eq!(
            a.degree_summary(),
            b.degree_summary(),
            "{what} ({})",
            a.name
        );
        let bad = float_agreement::bad_certificate(b);
        assert!(
            bad.is_none(),
            "{what} ({}): float certificate {bad:?}",
            b.name
        );
    }
}

/// Builds a parsed recipe exactly and in `f64` and compares.
fn check_recipe(what: &str, r: &Recipe) {
    let r = without_display_objects(r);
    let e = build_recipe_with(&r, Arithmetic::Exact, |_| {})
        .unwrap_or_else(|d| panic!("{what} (exact): {}", d[0]));
    let f = build_recipe_with(&r, Arithmetic::Float, |_| {})
        .unwrap_or_else(|d| panic!("{what} (f64): {}", d[0]));
    agree(what, &e, &f).unwrap();
}

#[test]
fn every_float_op_is_registered_and_its_example_agrees() {
    for f in FLOAT_OPS {
        let op = rcagd_cli::ops::find(f.name).unwrap_or_else(|| panic!("{} is no op", f.name));
        check_recipe(
            f.name,
            &Recipe::parse("example.toml", op.example, None).unwrap(),
        );
    }
}

#[test]
fn every_op_without_a_float_path_says_why() {
    for op in rcagd_cli::ops::all() {
        let line = float::describe(op.name);
        assert!(line.starts_with("float path"), "{line}");
        assert_eq!(
            float::has_float_path(op.name),
            float::no_float_reason(op.name).is_none()
        );
    }
}

/// The gallery's recipe files (`examples/recipes/*.toml`), sorted.
pub(crate) fn gallery_recipe_paths() -> Vec<std::path::PathBuf> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/recipes");
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    paths.sort();
    paths
}

/// The gallery's objects whose op has a float path, one recipe at a time.
#[test]
fn gallery_objects_with_a_float_path_agree() {
    let mut n = 0;
    for path in gallery_recipe_paths() {
        let text = std::fs::read_to_string(&path).unwrap();
        let r = Recipe::parse(&path.display().to_string(), &text, None).unwrap();
        for obj in &r.objects {
            if !float::has_float_path(&obj.op) {
                continue;
            }
            let one = Recipe {
                file: r.file.clone(),
                objects: vec![obj.clone()],
            };
            // a type the float path refuses by design (`line_congruence_strips`' reguli,
            // `float::REGULI_REFUSED`) or for an open finding (`float::UNVERIFIED_REFUSED`;
            // none since session 18: `sphere_family_envelope`'s elliptic nets, other sheets
            // and spheres build in double-double and are compared): skipped
            if let Err(d) = build_recipe_with(&one, Arithmetic::Float, |_| {}) {
                if d[0].message.contains(float::REGULI_REFUSED)
                    || d[0].message.contains(float::UNVERIFIED_REFUSED)
                {
                    continue;
                }
            }
            if KNOWN_REPARAMETRIZED
                .iter()
                .any(|(name, _)| *name == obj.name)
            {
                check_reparametrized(&obj.name, &one);
            } else {
                check_recipe(&obj.name, &one);
            }
            n += 1;
        }
    }
    assert!(n >= 10, "only {n} gallery objects have a float path");
}

#[test]
fn build_float_marks_the_json_and_refuses_ops_without_a_float_path() {
    let dir = crate::common::temp_dir("float_cli");
    let ok = dir.join("ok.toml");
    std::fs::write(
        &ok,
        "[[object]]\nname = \"c\"\nop = \"circle\"\nradius = 2\n",
    )
    .unwrap();
    let out = bin().args(["build", "--float"]).arg(&ok).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("\"arithmetic\""), "{text}");
    assert!(
        text.contains("\"exact\": false") || text.contains("\"exact\":false"),
        "{text}"
    );
    let bad = dir.join("bad.toml");
    let pipe = rcagd_cli::ops::find("pipe_ph").unwrap().example;
    std::fs::write(&bad, pipe).unwrap();
    let out = bin().args(["build", "--float"]).arg(&bad).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("has no float path"), "{err}");
    assert!(err.contains("ops with a float path: circle_arc"), "{err}");
    let out = bin().args(["ops", "circle"]).output().unwrap();
    assert!(
        String::from_utf8_lossy(&out.stdout).contains("float path (`rcagd build --float`): yes")
    );
}

// ----------------------------------------------------------------- random recipes

/// A small rational `p/q` as recipe text.
pub(crate) fn q() -> impl Strategy<Value = String> {
    (-40i64..=40, 1i64..=12).prop_map(|(p, d)| format!("\"{p}/{d}\""))
}

pub(crate) fn pos() -> impl Strategy<Value = String> {
    (1i64..=40, 1i64..=12).prop_map(|(p, d)| format!("\"{p}/{d}\""))
}

pub(crate) fn pt(dim: usize) -> impl Strategy<Value = String> {
    proptest::collection::vec(q(), dim).prop_map(|v| format!("[{}]", v.join(", ")))
}

pub(crate) fn pts(
    dim: usize,
    n: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = Vec<String>> {
    proptest::collection::vec(pt(dim), n)
}

/// A rational point of the circle (c, r): c + r·((1 − s²)/(1 + s²), 2s/(1 + s²)), s = a/b.
fn on_circle(c: (i64, i64), r: i64, a: i64, b: i64) -> String {
    let (n, d) = (b * b - a * a, a * a + b * b);
    let x = format!("\"{}/{}\"", c.0 * d + r * n, d);
    let y = format!("\"{}/{}\"", c.1 * d + r * 2 * a * b, d);
    format!("[{x}, {y}]")
}

pub(crate) fn obj(op: &str, body: &str) -> String {
    format!("[[object]]\nname = \"o\"\nop = \"{op}\"\n{body}")
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Circles, arcs (any turn, so 1 to 4 pieces) and cylinder patches.
    #[test]
    fn circles_arcs_and_cylinders_agree(
        cx in -9i64..=9, cy in -9i64..=9, r in 1i64..=20,
        a0 in -9i64..=9, b0 in 1i64..=9, a1 in -9i64..=9, b1 in 1i64..=9,
        cw in any::<bool>(), z0 in -5i64..=5, h in 1i64..=7,
    ) {
        prop_assume!(a0 * b1 != a1 * b0);
        let (from, to) = (on_circle((cx, cy), r, a0, b0), on_circle((cx, cy), r, a1, b1));
        let centre = format!("center = [{cx}, {cy}]\nradius = {r}\n");
        check("circle", &obj("circle", &centre)).map_err(TestCaseError::fail)?;
        let arc = format!("{centre}from = {from}\nto = {to}\n");
        let arc_src = obj("circle_arc", &format!("{arc}clockwise = {cw}\n"));
        let cyl_src = obj("cylinder_patch", &format!("{arc}z0 = {z0}\nz1 = {}\n", z0 + h));
        if a0 * a1 + b0 * b1 == 0 {
            // Exactly antipodal ends (s₀·s₁ = −1): the exact op sees the turn
            // (from − c) × (to − c) = 0 and splits the half circle into two pieces; in
            // f64 the turn is a rounding residue ±ε and the arc is one piece through
            // ~180° (weight ≈ 0) or two: the piece count is ill-conditioned at exactly
            // 180°, so only that the float path builds is required here.
            build(&arc_src, Arithmetic::Float).map_err(TestCaseError::fail)?;
        } else {
            check("circle_arc", &arc_src).map_err(TestCaseError::fail)?;
            check("cylinder_patch", &cyl_src).map_err(TestCaseError::fail)?;
        }
    }

    /// Inline curves (positive weights), their degree elevation and subdivision.
    #[test]
    fn bezier_kernel_ops_agree(
        p in pts(3, 2..=7), w in proptest::collection::vec(pos(), 7),
        by in 1i64..=6, at in 1i64..=11,
    ) {
        let w = &w[..p.len()];
        let body = format!("points = [{}]\nweights = [{}]\n", p.join(", "), w.join(", "));
        check("bezier_curve", &obj("bezier_curve", &body)).map_err(TestCaseError::fail)?;
        check("degree_elevate", &obj("degree_elevate", &format!("{body}by = {by}\n")))
            .map_err(TestCaseError::fail)?;
        check("subdivide", &obj("subdivide", &format!("{body}at = \"{at}/12\"\n")))
            .map_err(TestCaseError::fail)?;
    }

    #[test]
    fn bezier_patches_agree(
        rows in proptest::collection::vec(pts(3, 3..=3), 2..=4),
        w in proptest::collection::vec(pos(), 12),
    ) {
        let net: Vec<String> = rows.iter().map(|r| format!("[{}]", r.join(", "))).collect();
        let wr: Vec<String> = (0..rows.len())
            .map(|i| format!("[{}]", w[3 * i..3 * i + 3].join(", ")))
            .collect();
        let body = format!("net = [{}]\nweights = [{}]\n", net.join(", "), wr.join(", "));
        check("bezier_patch", &obj("bezier_patch", &body)).map_err(TestCaseError::fail)?;
    }

    /// Images of curves and bilinear patches on the unit sphere (δ), the paraboloid (ψ)
    /// and an ellipsoid given by its matrix (its rational point found exactly), and
    /// covers of ellipsoids.
    #[test]
    fn quadric_images_and_covers_agree(
        p in pts(3, 2..=4), net in proptest::collection::vec(pts(3, 2..=2), 2..=2),
        which in 0usize..3, c in pt(3), radii in proptest::collection::vec(pos(), 3),
    ) {
        let quadric = match which {
            0 => "quadric = \"unit_sphere\"\n".to_string(),
            1 => "quadric = \"hyperbolic_paraboloid_xy\"\n".to_string(),
            _ => "quadric = \"matrix\"\nmatrix = [[-4, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 4]]\n".to_string(),
        };
        let curve = format!("{quadric}points = [{}]\n", p.join(", "));
        let e = build(&obj("quadric_curve_image", &curve), Arithmetic::Exact);
        // data in the exceptional set is an input error of both paths
        if let Ok(e) = e {
            let f = build(&obj("quadric_curve_image", &curve), Arithmetic::Float)
                .map_err(TestCaseError::fail)?;
            agree("quadric_curve_image", &e, &f).map_err(TestCaseError::fail)?;
        }
        let rows: Vec<String> = net.iter().map(|r| format!("[{}]", r.join(", "))).collect();
        let patch = format!("{quadric}net = [{}]\n", rows.join(", "));
        if let Ok(e) = build(&obj("quadric_patch_image", &patch), Arithmetic::Exact) {
            let f = build(&obj("quadric_patch_image", &patch), Arithmetic::Float)
                .map_err(TestCaseError::fail)?;
            agree("quadric_patch_image", &e, &f).map_err(TestCaseError::fail)?;
        }
        check("sphere_cover", &obj("sphere_cover", &format!("center = {c}\nradii = [{}]\n", radii.join(", "))))
            .map_err(TestCaseError::fail)?;
    }

    /// Tori and Dupin cyclides (tilted pe circles, the default pe frame with a random
    /// centre and size, parabolic cyclides over random boxes).
    #[test]
    fn tori_and_cyclides_agree(
        c in pt(3), rr in 2i64..=30, rho in 1i64..=29, d in 1i64..=6,
        sp in -5i64..=5, r0 in q(), cr in -6i64..=6, t0 in -3i64..=0, t1 in 1i64..=3,
    ) {
        prop_assume!(rho < rr);
        check("torus", &obj("torus", &format!("center = {c}\nmajor_radius = \"{rr}/{d}\"\nminor_radius = \"{rho}/{d}\"\n")))
            .map_err(TestCaseError::fail)?;
        let src = obj("dupin_canal", &format!("center = {c}\nrho = \"{rr}/{d}\"\nr0 = {r0}\ns = \"{sp}/6\"\n"));
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            let f = build(&src, Arithmetic::Float).map_err(TestCaseError::fail)?;
            agree_or_split("dupin_canal", &e, &f).map_err(TestCaseError::fail)?;
        }
        let src = obj("dupin_cyclide", &format!("center = [0, 0, 0, {cr}]\nrho = \"{rr}/{d}\"\n"));
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            let f = build(&src, Arithmetic::Float).map_err(TestCaseError::fail)?;
            agree("dupin_cyclide", &e, &f).map_err(TestCaseError::fail)?;
        }
        let src = obj("dupin_cyclide_parabolic", &format!("t = [{t0}, {t1}]\ns = [{t0}, {t1}]\n"));
        check("dupin_cyclide_parabolic", &src).map_err(TestCaseError::fail)?;
    }

    /// PN surfaces of random polynomial graphs F(u, v), support functions h(u, v) and
    /// surfaces of revolution of PH profiles on random rectangles, with offsets (where
    /// the exact op finds them regular).
    #[test]
    fn pn_graphs_and_supports_agree(
        g in proptest::collection::vec(proptest::collection::vec(q(), 3), 3),
        u0 in -4i64..=2, v0 in -4i64..=2, du in 1i64..=4, dv in 1i64..=4,
        dist in proptest::collection::vec(q(), 0..=2),
    ) {
        let grid: Vec<String> = g.iter().map(|r| format!("[{}]", r.join(", "))).collect();
        let rest = format!(
            "domain = [\"{u0}/4\", \"{}/4\", \"{v0}/4\", \"{}/4\"]\ndistances = [{}]\n",
            u0 + du, v0 + dv, dist.join(", ")
        );
        // a surface of revolution of a PH profile with preimage (row 0, row 1) of `g`
        let uv: Vec<String> = g.iter().take(2).map(|r| r.join(", ")).collect();
        let src = obj(
            "pn_revolution",
            &format!("u = [{}]\nv = [{}]\nstart = [{}, 0]\n{rest}", uv[0], uv[1], 1 + du),
        );
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            if let Ok(f) = build(&src, Arithmetic::Float) {
                agree("pn_revolution", &e, &f).map_err(TestCaseError::fail)?;
            }
        }
        for (op, key) in [("pn_graph", "coefficients"), ("pn_support", "support")] {
            let src = obj(op, &format!("{key} = [{}]\n{rest}", grid.join(", ")));
            if let Ok(e) = build(&src, Arithmetic::Exact) {
                // regularity decided by Bernstein signs: an f64 sign may refuse a surface
                // the exact signs accept (a zero of the regularity polynomial near the
                // domain); what the float path builds must agree
                if let Ok(f) = build(&src, Arithmetic::Float) {
                    agree(op, &e, &f).map_err(TestCaseError::fail)?;
                }
            }
        }
    }

    /// Spatial PH curves from quaternion preimages; planar PH curves and their offsets.
    #[test]
    fn ph_curves_and_offsets_agree(
        quats in pts(4, 1..=4), start in pt(3),
        pre in pts(2, 1..=4), start2 in pt(2), d in q(),
    ) {
        let body = format!("quaternions = [{}]\nstart = {start}\n", quats.join(", "));
        let src = obj("ph_curve", &body);
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            let f = build(&src, Arithmetic::Float).map_err(TestCaseError::fail)?;
            agree("ph_curve", &e, &f).map_err(TestCaseError::fail)?;
        }
        let body = format!("preimage = [{}]\nstart = {start2}\n", pre.join(", "));
        let src = obj("ph_planar_curve", &body);
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            let f = build(&src, Arithmetic::Float).map_err(TestCaseError::fail)?;
            agree("ph_planar_curve", &e, &f).map_err(TestCaseError::fail)?;
        }
        let src = obj("ph_planar_offset", &format!("{body}distance = {d}\n"));
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            // a weight function with a zero near [0, 1] is refused by the float path
            // (it does not decide it); everything it builds must agree
            if let Ok(f) = build(&src, Arithmetic::Float) {
                agree("ph_planar_offset", &e, &f).map_err(TestCaseError::fail)?;
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Polynomial helices from random line/circle seeds with random reparametrizations
    /// f/g (positive g) and multipliers w (session 13: the f64 construction certificate
    /// αβ' − α'β ≡ (f'g − fg')(a0b1 − a1b0)w² is scaled by its terms' magnitudes).
    #[test]
    fn ph_helices_agree(
        seed in pts(2, 4..=4), f in proptest::collection::vec(q(), 2..=3),
        g in proptest::collection::vec(pos(), 3), w in pts(2, 1..=2), start in pt(3),
    ) {
        let g = &g[..f.len()];
        let body = format!(
            "a0 = {}\na1 = {}\nb0 = {}\nb1 = {}\nf = [{}]\ng = [{}]\nw = [{}]\nstart = {start}\n",
            seed[0], seed[1], seed[2], seed[3], f.join(", "), g.join(", "), w.join(", ")
        );
        let src = obj("ph_helix", &body);
        // degenerate seeds (a0b1 = a1b0), constant f/g, straight lines: input errors
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            let f = build(&src, Arithmetic::Float).map_err(TestCaseError::fail)?;
            agree("ph_helix", &e, &f).map_err(TestCaseError::fail)?;
        }
    }

    /// C2 PH quintic splines through random points (natural and closed ends).
    #[test]
    fn ph_planar_splines_agree(p in pts(2, 3..=5), closed in any::<bool>()) {
        let ends = if closed { "closed" } else { "natural" };
        let src = obj("ph_planar_spline", &format!("points = [{}]\nends = \"{ends}\"\n", p.join(", ")));
        // coincident consecutive points, Newton–Raphson without convergence: input errors
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            let f = build(&src, Arithmetic::Float).map_err(TestCaseError::fail)?;
            agree("ph_planar_spline", &e, &f).map_err(TestCaseError::fail)?;
        }
    }

    /// Helical PH quintic Hermite interpolants of random data (session 14): the exact op's
    /// curves (exact, or enclosed from the exact root and written to 2⁻⁸⁰) against the
    /// float path's `f64` curves, ranked and named alike, at `REL` (1e-12). Until session
    /// 18 this test allowed 1e-10: the elimination quartic's coefficients were formed in
    /// `f64` and the root carried their rounding times its condition number (finding:
    /// 2.4·10⁻¹² for `p_s = 0`, `d_s = (0, −1, 0)`, `p_f = (0, 0, −1)`, `d_f = (0, −9, 1)`);
    /// since session 16 the elimination is formed exactly from the `f64` data
    /// (`HermiteData::solve_f64`), and 800 random draws agreed at 1e-12.
    #[test]
    fn ph_hermites_agree(p in pts(3, 2..=2), d in pts(3, 2..=2)) {
        let src = obj(
            "ph_hermite",
            &format!("p_s = {}\nd_s = {}\np_f = {}\nd_f = {}\n", p[0], d[0], p[1], d[1]),
        );
        // coincident points, zero or parallel tangents, no real solution: input errors
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            let f = build(&src, Arithmetic::Float).map_err(TestCaseError::fail)?;
            rcagd_cli::float_agreement::agree(&e, &f, REL)
                .map_err(|m| TestCaseError::fail(format!("ph_hermite: {m}")))?;
            marked("ph_hermite", &f).map_err(TestCaseError::fail)?;
        }
    }

    /// Planar PH quintic Hermite interpolants of random data, all four (session 14): the
    /// exact op's curves (exact square roots, or an `f64` solution rounded to rationals)
    /// against the float path's `f64` curves.
    #[test]
    fn ph_planar_hermites_agree(p in pts(2, 2..=2), d in pts(2, 2..=2)) {
        let src = obj(
            "ph_planar_hermite",
            &format!("p0 = {}
d0 = {}
p1 = {}
d1 = {}
select = \"all\"\n", p[0], d[0], p[1], d[1]),
        );
        // coincident points, zero tangents: input errors
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            let f = build(&src, Arithmetic::Float).map_err(TestCaseError::fail)?;
            agree("ph_planar_hermite", &e, &f).map_err(TestCaseError::fail)?;
        }
    }

    /// Cyclides through three random oriented spheres, and cyclide blends of random cones
    /// (the second contact sphere fitted to a random sphere of cone 2).
    #[test]
    fn cyclides_of_spheres_and_blends_agree(
        c in pts(3, 3..=3), r in proptest::collection::vec(q(), 3),
        p1 in pt(4), d1 in pt(4), d2 in pt(4), q2 in pt(4),
    ) {
        let src = obj("dupin_cyclide_spheres", &format!("centers = [{}]\nradii = [{}]\n", c.join(", "), r.join(", ")));
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            let f = build(&src, Arithmetic::Float).map_err(TestCaseError::fail)?;
            agree_or_split("dupin_cyclide_spheres", &e, &f).map_err(TestCaseError::fail)?;
        }
        let src = obj("cyclide_blend", &format!("sphere1 = {p1}\ndirection1 = {d1}\ndirection2 = {d2}\npoint2 = {q2}\n"));
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            let f = build(&src, Arithmetic::Float).map_err(TestCaseError::fail)?;
            agree_or_split("cyclide_blend", &e, &f).map_err(TestCaseError::fail)?;
        }
    }
}

/// The fuzzer's finding of session 14 (`rcagd fuzz --op dupin_cyclide_spheres --seed 14
/// --cases 403`, cases 38, 137, 162, 166, 207 and 364): the exact op decides whether a
/// norm ratio is a square over Q, which rational point a conic has and which Gram entries
/// are 0; `f64` decided them by itself (every positive number a square, a rounding residue
/// a pivot) and built another parametrization (five cases) or refused ("span(U, V)^⊥ is not
/// a Lorentzian plane", case 364). The float path now replays the exact decisions
/// (`rcagd::cyclide::three_spheres_route`): the control points agree at 1e-12.
#[test]
fn cyclides_of_the_fuzzers_three_spheres_agree() {
    for (centers, radii) in [
        ("[[0, 0, 0], [1, 0, 0], [0, 1, 0]]", "[0, 10, 10]"),
        ("[[0, 0, -1], [4, 0, 0], [0, 4, 0]]", "[1, 1, 1]"),
        (
            "[[0, 0, 0], [1, 0, 0], [0, 1, 0]]",
            "[1.0000000001, 10, 10]",
        ),
        ("[[0, 0, 0], [1, 0, 0], [0, 1, 0]]", "[-1, 10, 10]"),
        ("[[0, 0, 1.0000000001], [4, 0, 0], [0, 4, 0]]", "[1, 1, 1]"),
        ("[[0, 0, \"-39/5\"], [1, 0, 0], [0, 1, 0]]", "[0, 10, 10]"),
    ] {
        let src = obj(
            "dupin_cyclide_spheres",
            &format!("centers = {centers}\nradii = {radii}\n"),
        );
        let exact = build(&src, Arithmetic::Exact).unwrap_or_else(|e| panic!("{src}: {e}"));
        let float = build(&src, Arithmetic::Float).unwrap_or_else(|e| panic!("{src}: {e}"));
        agree(&src, &exact, &float).unwrap();
    }
}

/// Random draws of the float tests that failed before session 17 (docs/plans/float.md,
/// "Session 17, floatfix"; their regression lines are in
/// `proptest-regressions/float.txt`): point spheres whose conjugate conic, formed in
/// `f64`, was off by 3.5e-12 and 3.0e-13 relative (now the exact families rounded once,
/// `rcagd::cyclide::DupinCyclide::rounded`), and a draw whose `f64` contact certificate
/// failed by its tolerance's scale (now the magnitude of its terms).
#[test]
fn cyclides_of_the_open_draws_agree() {
    for (centers, radii) in [
        (
            "[[\"-19/7\", -1, -16], [2, 3, \"-11/2\"], [\"-32/11\", \"-7/6\", \"33/2\"]]",
            "[\"-11/10\", -2, 0]",
        ),
        (
            "[[\"33/8\", -2, 10], [\"-4/3\", \"17/3\", \"23/10\"], [13, \"-35/2\", \"-31/6\"]]",
            "[\"34/7\", \"10/3\", \"-10/3\"]",
        ),
        ("[[2, 3, 2], [1, -3, 1], [2, 2, -1]]", "[-3, -1, 0]"),
    ] {
        let src = obj(
            "dupin_cyclide_spheres",
            &format!("centers = {centers}\nradii = {radii}\n"),
        );
        let exact = build(&src, Arithmetic::Exact).unwrap_or_else(|e| panic!("{src}: {e}"));
        let float = build(&src, Arithmetic::Float).unwrap_or_else(|e| panic!("{src}: {e}"));
        agree(&src, &exact, &float).unwrap();
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Three spheres with small integer centres and radii (the fuzzer's kind of input:
    /// symmetric positions, norm ratios that are not squares, Gram entries that vanish
    /// exactly): the float path builds the exact parametrization.
    #[test]
    fn cyclides_of_integer_spheres_agree(
        c in proptest::collection::vec(proptest::collection::vec(-3i64..=3, 3), 3),
        r in proptest::collection::vec(-3i64..=12, 3),
    ) {
        let fmt = |v: &[i64]| format!("[{}]", v.iter().map(i64::to_string).collect::<Vec<_>>().join(", "));
        let centers = format!("[{}]", c.iter().map(|p| fmt(p)).collect::<Vec<_>>().join(", "));
        let src = obj("dupin_cyclide_spheres", &format!("centers = {centers}\nradii = {}\n", fmt(&r)));
        if let Ok(e) = build(&src, Arithmetic::Exact) {
            let f = build(&src, Arithmetic::Float).map_err(|m| TestCaseError::fail(format!("{src}: {m}")))?;
            agree_or_split(&src, &e, &f).map_err(TestCaseError::fail)?;
        }
    }
}

/// The gallery objects of the ops whose float path runs in double-double
/// ([`float::F64_INSTANCES`]), built one at a time on one thread: exact, plain `f64` and
/// double-double (best of 3 each, same run). Run with
/// `cargo test -p rcagd-cli --test it float::double_double_timings -- --ignored --nocapture`.
#[test]
#[ignore = "a measurement, not a test"]
fn double_double_timings() {
    use rcagd_cli::build::{build_object_with, check_object};
    use std::time::Instant;
    let paths = gallery_recipe_paths();
    // the gallery recipes, then each op's example (`common_transversals` has no gallery
    // object)
    let mut sources: Vec<(String, String)> = paths
        .iter()
        .map(|p| {
            let name = p.file_stem().unwrap().to_string_lossy().to_string();
            (name, std::fs::read_to_string(p).unwrap())
        })
        .collect();
    for f in float::F64_INSTANCES {
        let spec = rcagd_cli::ops::find(f.name).unwrap();
        sources.push((format!("example of {}", f.name), spec.example.to_string()));
    }
    println!("| recipe | objects | exact (ms) | f64 (ms) | double-double (ms) | dd / f64 |");
    println!("|---|---|---|---|---|---|");
    let (mut te, mut tf, mut td) = (0.0, 0.0, 0.0);
    for (name, text) in sources {
        let r = Recipe::parse("r.toml", &text, None).unwrap();
        let objs: Vec<_> = r
            .objects
            .iter()
            .filter(|o| float::F64_INSTANCES.iter().any(|f| f.name == o.op))
            .collect();
        if objs.is_empty() {
            continue;
        }
        let best = |run: &dyn Fn()| {
            (0..3)
                .map(|_| {
                    let t = Instant::now();
                    run();
                    t.elapsed().as_secs_f64() * 1e3
                })
                .fold(f64::INFINITY, f64::min)
        };
        let e = best(&|| {
            for o in &objs {
                build_object_with(&r.file, o, Arithmetic::Exact).unwrap();
            }
        });
        let f = best(&|| {
            for o in &objs {
                let (op, args) = check_object(&r.file, o).unwrap();
                let inst = float::F64_INSTANCES
                    .iter()
                    .find(|f| f.name == op.name)
                    .unwrap();
                // an f64 refusal (a replayed factor that does not divide) is timed too
                let _ = (inst.build)(&args);
            }
        });
        let d = best(&|| {
            for o in &objs {
                build_object_with(&r.file, o, Arithmetic::Float).unwrap();
            }
        });
        te += e;
        tf += f;
        td += d;
        println!(
            "| {name} | {} | {e:.2} | {f:.2} | {d:.2} | {:.1}× |",
            objs.len(),
            d / f
        );
    }
    println!("| all | | {te:.2} | {tf:.2} | {td:.2} | {:.1}× |", td / tf);
}

/// The measurement of docs/BENCHMARKS.md, "The float path": every gallery recipe's
/// objects that have a float path, built one at a time on one thread, exact then `f64`
/// (best of 3 each, same run). Run with
/// `cargo test -p rcagd-cli --test it float::timings -- --ignored --nocapture`.
#[test]
#[ignore = "a measurement, not a test"]
fn timings() {
    use rcagd_cli::build::build_object_with;
    use std::time::Instant;
    let paths = gallery_recipe_paths();
    println!("| recipe | objects with a float path | exact (ms) | f64 (ms) | ratio |");
    println!("|---|---|---|---|---|");
    let (mut te, mut tf) = (0.0, 0.0);
    for path in paths {
        let text = std::fs::read_to_string(&path).unwrap();
        let r = without_display_objects(
            &Recipe::parse(&path.display().to_string(), &text, None).unwrap(),
        );
        let objs: Vec<_> = r
            .objects
            .iter()
            .filter(|o| float::has_float_path(&o.op))
            .collect();
        if objs.is_empty() {
            continue;
        }
        let time = |a: Arithmetic| {
            (0..3)
                .map(|_| {
                    let t = Instant::now();
                    for o in &objs {
                        build_object_with(&r.file, o, a).unwrap();
                    }
                    t.elapsed().as_secs_f64() * 1e3
                })
                .fold(f64::INFINITY, f64::min)
        };
        let (e, f) = (time(Arithmetic::Exact), time(Arithmetic::Float));
        te += e;
        tf += f;
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        println!(
            "| {name} | {} | {e:.2} | {f:.2} | {:.1}× |",
            objs.len(),
            e / f
        );
    }
    println!("| all | | {te:.2} | {tf:.2} | {:.1}× |", te / tf);
}
