//! The float paths of session 15 (`rcagd build --float`, issue 20 item 3): line geometry
//! (and, as they are added, canal blends, sphere families, conic surfaces, the
//! n-dimensional ops, RRMF sweeps and quadric interpolation). Each op: random exact
//! recipes built exactly and in `f64` agree by the one rule of
//! [`rcagd_cli::float_agreement::agree`] at 1e-12 relative (the same control points up to
//! rounding, every `f64` certificate holding and inexact), and every float object says
//! `arithmetic = "f64"`.

use crate::float::{build, marked, obj, pt, q, REL};
use proptest::prelude::*;
use rcagd_cli::build::Arithmetic;
use rcagd_cli::float;
use rcagd_cli::float_agreement;

/// Builds `src` exactly; if the exact op accepts it, the float path must build it too
/// and agree (the exact op's refusals are its exceptional sets, not compared). Returns
/// whether the exact op built it.
fn check(src: &str) -> Result<bool, TestCaseError> {
    let Ok(exact) = build(src, Arithmetic::Exact) else {
        return Ok(false);
    };
    let f =
        build(src, Arithmetic::Float).map_err(|m| TestCaseError::fail(format!("{src}\n{m}")))?;
    float_agreement::agree(&exact, &f, REL)
        .map_err(|m| TestCaseError::fail(format!("{src}\n{m}")))?;
    marked(src, &f).map_err(|m| TestCaseError::fail(format!("{src}\n{m}")))?;
    Ok(true)
}

/// Each op of this file has a float path (its property test is below).
#[test]
fn the_session_15_ops_have_a_float_path() {
    for name in [
        "line_through_points",
        "line_of_planes",
        "regulus",
        "pn_hypersurface",
    ] {
        assert!(float::has_float_path(name), "{name}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// `line_through_points` (random points), `line_of_planes` (random planes and
    /// extent) and `regulus` (three random lines: pairwise skew almost always).
    #[test]
    fn lines_and_reguli_agree(
        p in pt(3), q2 in pt(3), u in pt(4), v in pt(4), e in (1i64..=9, 1i64..=4),
        l in proptest::collection::vec((pt(3), pt(3)), 3),
    ) {
        check(&obj("line_through_points", &format!("p = {p}\nq = {q2}\n")))?;
        check(&obj("line_of_planes", &format!("u = {u}\nv = {v}\nextent = \"{}/{}\"\n", e.0, e.1)))?;
        let lines: Vec<String> = l.iter().map(|(a, b)| format!("[{a}, {b}]")).collect();
        check(&obj("regulus", &format!("lines = [{}]\n", lines.join(", "))))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// `pn_hypersurface` of R⁴ with a random quadratic support function (numerator
    /// terms in u₁, u₂, u₃), a random offset distance and a random picture domain.
    #[test]
    fn pn_hypersurfaces_agree(
        terms in proptest::collection::vec((q(), 0u32..=2, 0u32..=2, 0u32..=1), 1..=4),
        d in q(), s0 in 0i64..=3, t0 in 0i64..=3,
    ) {
        let support: Vec<String> = terms
            .iter()
            .map(|(c, a, b, e)| format!("[{c}, {a}, {b}, {e}]"))
            .collect();
        check(&obj(
            "pn_hypersurface",
            &format!(
                "dimension = 4\nsupport = [{}]\nslice = [0, 0, \"1/2\"]\ndomain = [\"{s0}/4\", \"{}/4\", \"{t0}/4\", \"{}/4\"]\ndistances = [{d}]\n",
                support.join(", "),
                s0 + 1,
                t0 + 1
            ),
        ))?;
    }
}
