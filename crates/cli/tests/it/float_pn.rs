//! The float path of the PN and line-congruence ops (`rcagd build --float`, session 15):
//! random exact recipes of `pn_anticaustic`, `pn_planar` and `line_congruence_strips`
//! built exactly and in `f64` agree by the rule of [`rcagd_cli::float_agreement`] at
//! `float::REL` (1e-12 relative), every `f64` certificate holds and is inexact, every
//! float object is marked `arithmetic = "f64"`. The other ops of the topic were tried with
//! their generic builders ([`survey`], and property tests whose failing draws are quoted in
//! `float::NO_FLOAT_PATH`) and withdrawn.
//!
//! Where the exact op refuses an input (developable, no splitting, singular on the
//! domain, a cusp of an offset) the case is skipped. Where the float path refuses an input
//! the exact op accepts, the refusal must be one of regularity decided by `f64` Bernstein
//! signs ([`f64_refusal_is_a_sign`]); nothing else is compared then.

use crate::float::{agree, build, obj, pos, pt, q};
use proptest::prelude::*;
use rcagd_cli::build::{build_recipe_with, Arithmetic};
use rcagd_cli::recipe::Recipe;

/// The ops of this file with a float path, and those tried (`survey`): the others say
/// why not in `float::NO_FLOAT_PATH`.
const OPS: &[&str] = &[
    "pn_model",
    "pn_loft",
    "pn_ruled",
    "pn_canal",
    "pn_developable",
    "pn_developable_edge",
    "pn_developable_motion",
    "pn_cone_motion",
    "pn_two_sheet_hyperboloid",
    "pn_laguerre",
    "pn_anticaustic",
    "pn_planar",
    "line_congruence_strips",
];

/// `true` if an `f64` build's error is a regularity decision by `f64` Bernstein signs (a
/// zero of the regularity polynomial within rounding of the domain: the float path may
/// refuse what the exact signs accept, as for `pn_graph`).
fn f64_refusal_is_a_sign(message: &str) -> bool {
    [
        "not regular",
        "singular point",
        "cusp",
        "vanishes",
        "degenerat",
    ]
    .iter()
    .any(|w| message.contains(w))
}

/// Builds `src` exactly; if the exact op accepts it, builds it in `f64` and compares
/// ([`agree`]); an `f64` refusal must be a sign decision ([`f64_refusal_is_a_sign`]).
fn compare(op: &str, src: &str) -> Result<(), TestCaseError> {
    let Ok(e) = build(src, Arithmetic::Exact) else {
        return Ok(());
    };
    match build(src, Arithmetic::Float) {
        Ok(f) => agree(op, &e, &f).map_err(TestCaseError::fail),
        Err(m) if f64_refusal_is_a_sign(&m) => Ok(()),
        Err(m) => Err(TestCaseError::fail(format!(
            "{op}: the f64 build refuses what the exact one builds: {m}\n{src}"
        ))),
    }
}

/// A grid of `n` random rows of power coefficients, each of the same random length
/// (at most `deg + 1`: a grid is rectangular).
fn rows(n: usize, deg: usize) -> impl Strategy<Value = String> {
    (1..=deg + 1)
        .prop_flat_map(move |w| proptest::collection::vec(proptest::collection::vec(q(), w), n))
        .prop_map(|r| {
            let r: Vec<String> = r.iter().map(|x| format!("[{}]", x.join(", "))).collect();
            format!("[{}]", r.join(", "))
        })
}

/// A homogeneous point with a positive weight (so that the strips' points stay finite
/// for non-negative parameters).
fn weighted() -> impl Strategy<Value = String> {
    (1i64..=4, pt(3)).prop_map(|(w, p)| format!("[{w}, {}]", &p[1..p.len() - 1]))
}

/// A random rectangle `[u0, u1, v0, v1]` in quarters.
fn domain() -> impl Strategy<Value = String> {
    (-4i64..=3, 1i64..=4, -4i64..=3, 1i64..=4).prop_map(|(u0, du, v0, dv)| {
        format!(
            "[\"{u0}/4\", \"{}/4\", \"{v0}/4\", \"{}/4\"]",
            u0 + du,
            v0 + dv
        )
    })
}

/// Up to two random offset distances.
fn distances() -> impl Strategy<Value = String> {
    proptest::collection::vec(q(), 0..=2).prop_map(|d| format!("[{}]", d.join(", ")))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Anticaustics of random polynomial mirrors (degree ≤ 2 in u and v) at random levels,
    /// and planar PH curves of random isotropic graphs F(t) (degree ≤ 3) with offsets.
    #[test]
    fn pn_anticaustics_and_planar_curves_agree(
        mirror in rows(3, 2), level in q(), dom in domain(), dist in distances(),
        f in proptest::collection::vec(q(), 1..=4), t0 in -8i64..=6, dt in 1i64..=4,
    ) {
        let body = format!("mirror = {mirror}\nlevel = {level}\ndomain = {dom}\ndistances = {dist}\n");
        compare("pn_anticaustic", &obj("pn_anticaustic", &body))?;
        let body = format!(
            "function = [{}]\ninterval = [\"{t0}/4\", \"{}/4\"]\ndistances = {dist}\n",
            f.join(", "), t0 + dt
        );
        compare("pn_planar", &obj("pn_planar", &body))?;
    }

    /// Line nets (hyperbolic, elliptic, parabolic) of random axes and chords of random
    /// twisted cubics (positive weights, parameters ≥ 0: the strips stay finite), drawn
    /// as strips.
    #[test]
    fn line_congruence_strips_agree(
        kind in 0usize..4, p in proptest::collection::vec(weighted(), 4),
        du in 1i64..=4, v in proptest::collection::vec(pos(), 1..=3),
        twist in pos(), l1 in 1i64..=4,
    ) {
        let congruence = ["hyperbolic", "elliptic", "parabolic", "cubic_chords"][kind];
        let body = format!(
            "congruence = \"{congruence}\"\npoints = [{}]\nu = [0, \"{du}/4\"]\nv = [{}]\ntwist = {twist}\nlambda = [0, \"{l1}/4\"]\n",
            p.join(", "), v.join(", ")
        );
        compare("line_congruence_strips", &obj("line_congruence_strips", &body))?;
    }
}

/// A survey, not a test: every example and gallery object of the ops tried in session 15
/// ([`OPS`]), built exactly and in `f64`, with the comparison's verdict and the times (the
/// evidence of `float::NO_FLOAT_PATH` for the withdrawn ones). Run with
/// `cargo test -p rcagd-cli --test it float_pn::survey -- --ignored --nocapture`.
#[test]
#[ignore = "a survey, not a test"]
fn survey() {
    let mut cases: Vec<(String, Recipe)> = Vec::new();
    for name in OPS {
        let op = rcagd_cli::ops::find(name).unwrap();
        let r = Recipe::parse("example.toml", op.example, None).unwrap();
        cases.push((format!("{name} (example)"), r));
    }
    for path in crate::float::gallery_recipe_paths() {
        let text = std::fs::read_to_string(&path).unwrap();
        let r = Recipe::parse(&path.display().to_string(), &text, None).unwrap();
        for o in r.objects.iter().filter(|o| OPS.contains(&o.op.as_str())) {
            let one = Recipe {
                file: r.file.clone(),
                objects: vec![o.clone()],
            };
            cases.push((format!("{} ({})", o.name, o.op), one));
        }
    }
    for (what, r) in cases {
        let t = std::time::Instant::now();
        let e = build_recipe_with(&r, Arithmetic::Exact, |_| {});
        let te = t.elapsed().as_secs_f64();
        let t = std::time::Instant::now();
        let f = build_recipe_with(&r, Arithmetic::Float, |_| {});
        let tf = t.elapsed().as_secs_f64();
        let verdict = match (&e, &f) {
            (Ok(e), Ok(f)) => agree(&what, e, f).err().unwrap_or_else(|| "agree".into()),
            (Err(a), _) => format!("exact error {}", a[0]),
            (_, Err(b)) => format!("f64 error {}", b[0]),
        };
        println!("{what}: exact {te:.3}s f64 {tf:.3}s: {verdict}");
    }
}
