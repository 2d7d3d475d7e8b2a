//! Pipes for exchange (issue 17): `pipe_ph` never exports worse than `pipe` on the same
//! spine, and random PH quintic and septic spines with radii below their curvature radius
//! always give pipes that build, certify and export to STEP and IGES.
//!
//! The property test runs `PROPTEST_CASES` cases (default 32). With
//! `RCAGD_PIPE_SAMPLES=DIR` every case also writes its STEP, IGES and exact sidecar to
//! `DIR` for `scripts/occ_check.sh DIR --strict-warnings`.

use crate::common::{bin, run_ok, temp_dir};
use proptest::prelude::*;
use rcagd_cli::build::build_recipe;
use rcagd_cli::model::{Geometry, Object};
use rcagd_cli::recipe::Recipe;
use std::path::Path;

/// The spine of issue 17: the PH quintic with preimage coefficients `1`, `1 + i + k`,
/// `j + k`, radius 1/8.
const PIPE_PH: &str = r#"[[object]]
name = "pipe_ph_issue17"
op = "pipe_ph"
coefficients = [[1, 0, 0, 0], [1, 1, 0, 1], [0, 0, 1, 1]]
radius = "1/8"
"#;

/// The same spine as Bézier control points (the integral of `A i A*`).
const PIPE: &str = r#"[[object]]
name = "pipe_issue17"
op = "pipe"
points = [[0, 0, 0], ["1/5", 0, 0], ["2/5", "1/5", 0], ["8/15", "8/15", "1/5"], ["1/3", "14/15", "1/5"], ["-1/15", "14/15", "1/5"]]
radius = "1/8"
"#;

fn build(text: &str) -> Vec<Object> {
    let recipe = Recipe::parse("t.toml", text, None).expect("recipe parses");
    build_recipe(&recipe, |_| {}).expect("recipe builds")
}

/// `(number of patches, number of control points, bidegrees)` of a patch object.
fn size(o: &Object) -> (usize, usize, Vec<(usize, usize)>) {
    match &o.geometry {
        Geometry::Patches(ps) => (
            ps.len(),
            ps.iter()
                .map(|p| (p.degree().0 + 1) * (p.degree().1 + 1))
                .sum(),
            ps.iter().map(|p| p.degree()).collect(),
        ),
        g => panic!("{}: unexpected geometry {}", o.name, g.kind()),
    }
}

/// Issue 17, item 1: `pipe_ph` used to build 32 patches of bidegree (13, 2) with a weight
/// 0 (certificate failure, STEP export exit 2); `pipe` on the same spine 4 patches (9, 2).
/// Both ops now keep the smallest exact construction that exports.
#[test]
fn pipe_ph_exports_no_worse_than_pipe_on_the_issue_spine() {
    let ph = build(PIPE_PH);
    let gen = build(PIPE);
    for o in ph.iter().chain(&gen) {
        assert!(
            o.certificates.iter().all(|c| c.holds && c.exact),
            "{}: {:?}",
            o.name,
            o.certificates
                .iter()
                .filter(|c| !c.holds)
                .collect::<Vec<_>>()
        );
    }
    let (n_ph, cp_ph, deg_ph) = size(&ph[0]);
    let (_, cp_gen, _) = size(&gen[0]);
    assert!(cp_ph <= cp_gen, "pipe_ph {cp_ph} > pipe {cp_gen}");
    assert_eq!((n_ph, cp_ph), (4, 120), "{deg_ph:?}");
    assert!(deg_ph.iter().all(|&d| d == (9, 2)), "{deg_ph:?}");
    rcagd_io::step::write_step(&ph).expect("STEP export");
    rcagd_io::iges::write_iges(&ph).expect("IGES export");
}

/// The binary exits 0 and writes STEP and IGES for the issue's recipe (it exited 2 with
/// "control point 1 has weight 0").
#[test]
fn pipe_ph_issue_recipe_exports_through_the_binary() {
    let dir = temp_dir("pipes-bin");
    let recipe = dir.join("pipe.toml");
    std::fs::write(&recipe, PIPE_PH).expect("write recipe");
    run_ok(
        bin()
            .args(["build", "--format", "step,iges", "--out"])
            .arg(&dir)
            .arg(&recipe),
    );
    for ext in ["step", "igs"] {
        let f = dir.join(format!("pipe_ph_issue17.{ext}"));
        assert!(
            std::fs::metadata(&f).is_ok_and(|m| m.len() > 0),
            "{} missing; files: {:?}",
            f.display(),
            std::fs::read_dir(&dir).map(|d| d
                .filter_map(|e| e.ok().map(|e| e.file_name()))
                .collect::<Vec<_>>())
        );
    }
}

/// Builds a one-object recipe expecting an error: `(line, message)`.
fn build_err(text: &str) -> (usize, String) {
    let recipe = Recipe::parse("t.toml", text, None).expect("recipe parses");
    let d = build_recipe(&recipe, |_| {}).expect_err("the recipe must fail");
    (d[0].line, d[0].message.clone())
}

/// Named errors: a radius not below the spine's radius of curvature (at the radius, with
/// the parameter interval), a zero-length tangent (at the spine).
#[test]
fn pipes_refuse_local_self_intersection_and_zero_tangents() {
    // the parabola (t, t², 0): least radius of curvature 1/2 at t = 0
    let (line, msg) = build_err(
        "[[object]]\nname = \"p\"\nop = \"pipe\"\npoints = [[0, 0, 0], [\"1/2\", 0, 0], [1, 1, 0]]\nradius = 1\n",
    );
    assert_eq!(line, 5, "{msg}");
    assert!(
        msg.contains("radius of curvature") && msg.contains("t in [0, 0.383210]"),
        "{msg}"
    );
    // (t², t², 0): m′(0) = 0
    let (line, msg) = build_err(
        "[[object]]\nname = \"p\"\nop = \"pipe\"\npoints = [[0, 0, 0], [0, 0, 0], [1, 1, 0]]\nradius = \"1/10\"\n",
    );
    assert_eq!(line, 4, "{msg}");
    assert!(
        msg.contains("zero-length tangent") && msg.contains("t = 0"),
        "{msg}"
    );
    // the PH quintic of the issue with a radius above its least radius of curvature
    let (line, msg) = build_err(&PIPE_PH.replace("\"1/8\"", "2"));
    assert_eq!(line, 5, "{msg}");
    assert!(msg.contains("radius of curvature"), "{msg}");
}

type Quat = [i64; 4];

fn qmul(a: &[f64; 4], b: &[f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// `A(t)` of Bernstein coefficients, its derivative, in f64.
fn preimage(coeffs: &[Quat], t: f64) -> ([f64; 4], [f64; 4]) {
    let n = coeffs.len() - 1;
    let mut a = [0.0; 4];
    let mut da = [0.0; 4];
    let binom = |n: usize, k: usize| -> f64 {
        (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
    };
    for (k, c) in coeffs.iter().enumerate() {
        let b = binom(n, k) * t.powi(k as i32) * (1.0 - t).powi((n - k) as i32);
        // d/dt B_k^n = n (B_{k-1}^{n-1} − B_k^{n-1})
        let db = if n == 0 {
            0.0
        } else {
            let prev = if k >= 1 {
                binom(n - 1, k - 1) * t.powi(k as i32 - 1) * (1.0 - t).powi((n - k) as i32)
            } else {
                0.0
            };
            let this = if k < n {
                binom(n - 1, k) * t.powi(k as i32) * (1.0 - t).powi((n - 1 - k) as i32)
            } else {
                0.0
            };
            n as f64 * (prev - this)
        };
        for i in 0..4 {
            a[i] += b * c[i] as f64;
            da[i] += db * c[i] as f64;
        }
    }
    (a, da)
}

/// The least radius of curvature `|r'|³ / |r' × r''|` of the PH curve `r' = A i A*` on
/// 2001 samples of `[0, 1]` (`0` where `r' = 0`).
fn min_curvature_radius(coeffs: &[Quat]) -> f64 {
    let i = [0.0, 1.0, 0.0, 0.0];
    let mut best = f64::INFINITY;
    for s in 0..=2000 {
        let t = f64::from(s) / 2000.0;
        let (a, da) = preimage(coeffs, t);
        let conj = |q: &[f64; 4]| [q[0], -q[1], -q[2], -q[3]];
        let h = qmul(&qmul(&a, &i), &conj(&a));
        // (A i A*)' = A' i A* + A i A'*
        let h1 = qmul(&qmul(&da, &i), &conj(&a));
        let h2 = qmul(&qmul(&a, &i), &conj(&da));
        let d1 = [h[1], h[2], h[3]];
        let d2 = [h1[1] + h2[1], h1[2] + h2[2], h1[3] + h2[3]];
        let cr = [
            d1[1] * d2[2] - d1[2] * d2[1],
            d1[2] * d2[0] - d1[0] * d2[2],
            d1[0] * d2[1] - d1[1] * d2[0],
        ];
        let speed = (d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2]).sqrt();
        let k = (cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]).sqrt();
        if speed == 0.0 {
            return 0.0;
        }
        if k > 0.0 {
            best = best.min(speed * speed * speed / k);
        }
    }
    best
}

fn quat() -> impl Strategy<Value = Quat> {
    [-3i64..=3, -3i64..=3, -3i64..=3, -3i64..=3]
}

fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(32)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Random PH quintics (3 preimage coefficients) and septics (4), radius a random
    /// fraction `k/10` (`k = 1 … 8`) of the least sampled radius of curvature (rounded
    /// down to a dyadic number): the pipe builds, every certificate holds exactly, STEP
    /// and IGES export.
    #[test]
    fn random_ph_pipes_build_certify_and_export(
        coeffs in prop::collection::vec(quat(), 3..=4),
        k in 1i64..=8,
        negative in any::<bool>(),
    ) {
        prop_assume!(coeffs.iter().any(|a| a.iter().any(|&x| x != 0)));
        let rho = min_curvature_radius(&coeffs);
        prop_assume!(rho.is_finite() && rho > 1e-3);
        // r = ⌊2^10 · k ρ / 10⌋ / 2^10 > 0
        let num = (rho * k as f64 / 10.0 * 1024.0).floor() as i64;
        prop_assume!(num > 0);
        let coeff_text: Vec<String> = coeffs
            .iter()
            .map(|a| format!("[{}, {}, {}, {}]", a[0], a[1], a[2], a[3]))
            .collect();
        let recipe = format!(
            "[[object]]\nname = \"pipe\"\nop = \"pipe_ph\"\ncoefficients = [{}]\nradius = \"{num}/1024\"\norientation = \"{}\"\n",
            coeff_text.join(", "),
            if negative { "negative" } else { "positive" }
        );
        let parsed = Recipe::parse("t.toml", &recipe, None).expect("recipe parses");
        let objs = match build_recipe(&parsed, |_| {}) {
            Ok(o) => o,
            // below the radius of curvature a pipe can still meet itself globally (found at
            // random: preimage [[0,1,1,2],[-2,-3,-2,-3],[0,0,-1,0]], r = 18/1024, spine points
            // at t ≈ 0.065 and 0.323 are 0.0329 apart < 2r): the refusal must say so, with
            // spine points closer than 2r (or, undecided, within 1 % of it)
            Err(d) => {
                let msg = d.first().map_or(String::new(), |x| x.message.clone());
                let num_after = |key: &str| -> f64 {
                    msg.split(key).nth(1).and_then(|t| t.split([' ', ')']).next()).and_then(|x| x.parse().ok()).unwrap_or(f64::NAN)
                };
                if msg.contains("intersects itself") {
                    let (dist, dia) = (num_after("points are "), num_after("2|r| is "));
                    prop_assert!(dist <= dia, "{recipe}\n{msg}");
                    return Ok(());
                }
                if msg.contains("(undecided)") {
                    let (dist, dia) = (num_after("within ≈ "), num_after("2|r| is "));
                    prop_assert!((dist - dia).abs() <= 0.01 * dia, "{recipe}\n{msg}");
                    return Ok(());
                }
                return Err(TestCaseError::fail(format!("{recipe}\n{msg}")));
            }
        };
        for c in &objs[0].certificates {
            prop_assert!(c.holds && c.exact, "{recipe}\n{c:?}");
        }
        let step = rcagd_io::step::write_step(&objs);
        prop_assert!(step.is_ok(), "{recipe}\nSTEP: {:?}", step.err());
        let iges = rcagd_io::iges::write_iges(&objs);
        prop_assert!(iges.is_ok(), "{recipe}\nIGES: {:?}", iges.err());
        if let Ok(dir) = std::env::var("RCAGD_PIPE_SAMPLES") {
            let dir = Path::new(&dir);
            std::fs::create_dir_all(dir).expect("sample dir");
            let tag: String = coeffs
                .iter()
                .flat_map(|a| a.iter().map(|x| format!("{}", x + 3)))
                .collect::<String>();
            let name = format!("pipe_{tag}_{num}_{}", u8::from(negative));
            let mut o = objs[0].clone();
            o.name = name.clone();
            let one = vec![o];
            std::fs::write(dir.join(format!("{name}.step")), rcagd_io::step::write_step(&one).expect("step")).expect("write");
            std::fs::write(dir.join(format!("{name}.igs")), rcagd_io::iges::write_iges(&one).expect("iges")).expect("write");
            let side = rcagd_io::step::exact_sidecar(&one).expect("sidecar");
            std::fs::write(dir.join(format!("{name}.exact.json")), side.to_string()).expect("write");
        }
    }
}

/// The issue spine as an exact Bézier curve, split at `t = 1/2` into two pieces.
fn issue_spine_pieces() -> Vec<rcagd_geom::BezierCurve<rcagd_algebra::Rational>> {
    use rcagd_algebra::{Rational, Scalar};
    let pts = [
        [0, 0, 0, 1],
        [1, 0, 0, 5],
        [2, 1, 0, 5],
        [8, 8, 3, 15],
        [5, 14, 3, 15],
        [-1, 14, 3, 15],
    ];
    let hom: Vec<Vec<Rational>> = pts
        .iter()
        .map(|p| {
            let d = Rational::from(p[3]);
            vec![
                Rational::from(1),
                Rational::from(p[0]) / d.clone(),
                Rational::from(p[1]) / d.clone(),
                Rational::from(p[2]) / d,
            ]
        })
        .collect();
    let c = rcagd_geom::BezierCurve::from_homogeneous(hom).expect("spine");
    let half = Rational::from_ratio(1, 2);
    vec![
        c.restrict(&Rational::from(0), &half).expect("left"),
        c.restrict(&half, &Rational::from(1)).expect("right"),
    ]
}

/// Issue 17, item 2: the spine read from STEP, IGES and exact JSON files (two curve
/// pieces, chained), the pipe built per piece; a file without curves is a named error.
#[test]
fn pipe_around_a_spine_file() {
    let dir = temp_dir("pipes-spine");
    let spine = Object::new(
        "spine",
        "test",
        serde_json::json!({}),
        Geometry::Curves(issue_spine_pieces()),
        Vec::new(),
    );
    let objs = vec![spine];
    let files = [
        (
            "spine.step",
            rcagd_io::step::write_step(&objs).expect("step"),
        ),
        (
            "spine.igs",
            rcagd_io::iges::write_iges(&objs).expect("iges"),
        ),
        (
            "spine.json",
            rcagd_io::json::objects_to_json(&objs).to_string(),
        ),
    ];
    std::fs::write(
        dir.join("spine.exact.json"),
        rcagd_io::step::exact_sidecar(&objs)
            .expect("sidecar")
            .to_string(),
    )
    .expect("write sidecar");
    let mut sizes = Vec::new();
    for (name, text) in &files {
        let path = dir.join(name);
        std::fs::write(&path, text).expect("write spine");
        let recipe = format!(
            "[[object]]\nname = \"p\"\nop = \"pipe\"\nspine_file = {:?}\nradius = \"1/8\"\n",
            path.display().to_string()
        );
        let parsed = Recipe::parse("t.toml", &recipe, None).expect("recipe parses");
        let o =
            build_recipe(&parsed, |_| {}).unwrap_or_else(|d| panic!("{name}: {}", d[0].message));
        assert!(
            o[0].certificates.iter().all(|c| c.holds && c.exact),
            "{name}: {:?}",
            o[0].certificates
                .iter()
                .filter(|c| !c.holds)
                .collect::<Vec<_>>()
        );
        assert!(
            o[0].certificates.iter().any(|c| c.property.contains("(G¹")),
            "{name}: no join certificate"
        );
        rcagd_io::step::write_step(&o).expect("STEP export");
        sizes.push(size(&o[0]).1);
    }
    assert!(sizes.iter().all(|&n| n > 0), "{sizes:?}");
    // a file with a patch and no curve
    let patch = build(PIPE);
    let path = dir.join("patch.json");
    std::fs::write(&path, rcagd_io::json::objects_to_json(&patch).to_string()).expect("write");
    let (line, msg) = build_err(&format!(
        "[[object]]\nname = \"p\"\nop = \"pipe\"\nspine_file = {:?}\nradius = \"1/8\"\n",
        path.display().to_string()
    ));
    assert_eq!(line, 4, "{msg}");
    assert!(msg.contains("has no curves"), "{msg}");
    // a relative spine_file is found beside the recipe, whatever the working directory
    let recipe = dir.join("relative.toml");
    std::fs::write(
        &recipe,
        "[[object]]\nname = \"p\"\nop = \"pipe\"\nspine_file = \"spine.json\"\nradius = \"1/8\"\n",
    )
    .expect("write recipe");
    run_ok(
        bin()
            .current_dir(env!("CARGO_TARGET_TMPDIR"))
            .arg("build")
            .arg(&recipe),
    );
}

/// Issue 17, item 3: the cubic B-spline spine written by OpenCascade (a TRIMMED_CURVE of a
/// B_SPLINE_CURVE_WITH_KNOTS with three spans) has no rational pipe; the `pipe` op builds the
/// exact pipe around a certified PH spline within the tolerance, and says so in its
/// certificates. `approximate = "never"` names the field instead; a bad tolerance is blamed
/// on `tolerance`.
#[test]
fn pipe_around_an_imported_bspline() {
    let spine =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/spines/bspline_spine.step");
    let recipe = |extra: &str| {
        format!(
            "[[object]]\nname = \"p\"\nop = \"pipe\"\nspine_file = {:?}\nradius = \"1/5\"\n{extra}",
            spine.display().to_string()
        )
    };
    let o = build(&recipe("tolerance = \"1/100\"\n"));
    let certs = &o[0].certificates;
    assert!(
        certs.iter().all(|c| c.holds && c.exact),
        "{:?}",
        certs.iter().filter(|c| !c.holds).collect::<Vec<_>>()
    );
    let dev = certs
        .iter()
        .find(|c| c.property.contains("spine deviation"))
        .expect("the spine deviation is certified");
    assert!(dev.property.contains("within ε"), "{}", dev.property);
    assert!(certs.iter().any(|c| c.property.contains("(G¹")));
    rcagd_io::step::write_step(&o).expect("STEP export");
    rcagd_io::iges::write_iges(&o).expect("IGES export");
    let (line, msg) = build_err(&recipe("approximate = \"never\"\n"));
    assert_eq!(line, 4, "{msg}");
    assert!(msg.contains("extension") || msg.contains("Q(√"), "{msg}");
    let (line, msg) = build_err(&recipe("tolerance = \"-1/10\"\n"));
    assert_eq!(line, 6, "{msg}");
    assert!(msg.contains("tolerance must be positive"), "{msg}");
    let (line, msg) = build_err(&recipe("tolerance = \"1/1000000000000000000000000000\"\n"));
    assert_eq!(line, 6, "{msg}");
    assert!(msg.contains("tolerance"), "{msg}");
}

/// A pipe whose spine crosses itself (the cubic loop (0,0), (3,3), (−2,3), (1,0), least radius
/// of curvature ≈ 0.47, crossing near t ≈ 0.07 and 0.93) is refused by the global check with
/// a named error at the radius (issue 17 item 5), and the binary exits 2.
#[test]
fn self_intersecting_pipe_is_refused_at_the_radius() {
    let text = "[[object]]\nname = \"loop\"\nop = \"pipe\"\npoints = [[0, 0, 0], [3, 3, 0], [-2, 3, 0], [1, 0, 0]]\nradius = \"1/10\"\n";
    let (line, msg) = build_err(text);
    assert_eq!(line, 5, "{msg}");
    assert!(msg.contains("intersects itself"), "{msg}");
    assert!(
        msg.contains("t ≈ 0.066987") && msg.contains("t ≈ 0.933013"),
        "{msg}"
    );
    let dir = temp_dir("pipes-selfx");
    let recipe = dir.join("loop.toml");
    std::fs::write(&recipe, text).expect("write recipe");
    let out = bin()
        .args(["build", "--format", "step", "--out"])
        .arg(&dir)
        .arg(&recipe)
        .output()
        .expect("run");
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    assert!(String::from_utf8_lossy(&out.stderr).contains("intersects itself"));
    // a thin enough pipe around a spine that does not cross: certified embedded
    let objs = build(&text.replace("[-2, 3, 0], [1, 0, 0]", "[4, 3, 0], [5, 0, 0]"));
    let certs = &objs[0].certificates;
    assert!(
        certs
            .iter()
            .any(|c| c.holds && c.property.contains("no two normal discs")),
        "{certs:#?}"
    );
}

/// The `canal_chain` op (issue 17, item 6): a closed chain of four quarter circles with
/// radius 1/4 (a torus; the joints and the seam run on smoothly) builds, every certificate
/// holds and its value says that the tube is closed; the op's open example (a lifted PH
/// cubic in three pieces with a shrinking radius) is certified and not closed; and with
/// the third piece reversed (a joint where the tangent turns back) it is refused, naming
/// the joint.
#[test]
fn canal_chain_op_certifies_closed_and_open_chains() {
    let closed = |o: &Object| {
        o.values
            .iter()
            .find(|v| v.name == rcagd_cli::ops::canal::SPINE_CLOSED)
            .map(|v| v.value == rcagd_io::quantity::Quantity::Bool(true))
            .expect("spine_closed")
    };
    let torus = build(
        r#"[[object]]
name = "canal_chain_torus"
op = "canal_chain"
pieces = [[[1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 0], [-1, 1, 0], [-1, 0, 0]], [[-1, 0, 0], [-1, -1, 0], [0, -1, 0]], [[0, -1, 0], [1, -1, 0], [1, 0, 0]]]
weights = [[1, 1, 2], [1, 1, 2], [1, 1, 2], [1, 1, 2]]
radius = [["1/4"], ["1/4"], ["1/4"], ["1/4"]]
"#,
    );
    let o = &torus[0];
    assert!(
        o.certificates.iter().all(|c| c.holds && c.exact),
        "{:?}",
        o.certificates
    );
    assert!(closed(o));
    assert!(
        o.certificates
            .iter()
            .any(|c| c.property.contains("4 spine pieces, closed")),
        "{:?}",
        o.certificates
    );
    assert!(o
        .certificates
        .iter()
        .any(|c| c.property.starts_with("spine piece 3: ")));
    let example = rcagd_cli::ops::find("canal_chain").expect("op").example;
    let open = build(example);
    assert!(
        open[0].certificates.iter().all(|c| c.holds),
        "{:?}",
        open[0].certificates
    );
    assert!(!closed(&open[0]));
    let reversed = example.replace(
        r#"[["9173/16200", "4/9", "-1/12"], ["877/1080", "28/27", "-5/36"], ["1193/1800", "20/9", "-7/36"], ["-403/600", 4, "-1/4"]]"#,
        r#"[["9173/16200", "4/9", "-1/12"], ["1193/1800", "20/9", "-7/36"], ["877/1080", "28/27", "-5/36"], ["-403/600", 4, "-1/4"]]"#,
    );
    assert_ne!(reversed, example);
    let recipe = Recipe::parse("t.toml", &reversed, None).expect("recipe parses");
    let err = build_recipe(&recipe, |_| {}).expect_err("a corner is refused");
    let text = format!("{err:?}");
    assert!(text.contains("joint 1/2"), "{text}");
}
