//! The float paths of session 16 (`rcagd build --float`, issue 20 item 3): the RRMF ops,
//! the canal surface of a normal field and the Miquel patch on a quadric. Each op: random exact recipes built exactly and in `f64` agree
//! by the one rule of [`rcagd_cli::float_agreement::agree`] (or `agree_or_split` where a
//! positive-weight split may cut elsewhere) at 1e-12 relative, and every float object
//! says `arithmetic = "f64"`. The generators draw inputs the exact op builds (stated per
//! property), so whose draws the exact op always refuses cannot pass vacuously.

use crate::float::{build, marked, obj, REL};
use proptest::prelude::*;
use rcagd_algebra::Scalar;
use rcagd_cli::build::Arithmetic;
use rcagd_cli::float;
use rcagd_cli::float_agreement;
use rcagd_cli::model::Object;

/// The extra relative rounding of an object whose patches are assembled in the power
/// basis along their second parameter and converted to Bernstein form (`sweep_rrmf`:
/// `rcagd::ph::sweep::sweep_profile` forms `r·d`, `F₁`, `F₂` as power polynomials in `t`
/// and converts them with `bernstein::to_bernstein` to degree `n`). The conversion rounds
/// each Bernstein coefficient by up to about `(n + 1)·ε·S` with `S = Σⱼ |aⱼ|` the sum of the
/// power coefficients it is formed from (the condition number of the power-to-Bernstein
/// map is `S / max|b|`, which reaches `2ⁿ`): the bound `16·(n + 1)·ε·S` of
/// `float_agreement::power_form_slack` (the `ph_planar_offset` rule), with `S` from the
/// exact patch's own power coefficients, in the units of the comparison (each piece divided
/// by its largest |weight|, relative to the object's largest coordinate). Measured: the
/// draw `a0 = [3, 2/7, 5/7, −5]`, `a1 = [−1, 3/7, −2/3, 2/11]`, `x = 7/8`, `start = [0, 4, 0]`
/// (bidegree (2, 13), `S = 1.8·10⁶` against a largest coordinate 71) was off by
/// 1.45·10⁻¹² relative; its bound is 1.3·10⁻⁹.
fn power_basis_slack(exact: &[Object]) -> f64 {
    let mut slack = 0.0f64;
    for o in exact {
        let (mut s_max, mut scale) = (0.0f64, f64::MIN_POSITIVE);
        for p in o.geometry.patches() {
            let (nu, nv) = p.degree();
            let w = (0..=nu)
                .flat_map(|i| (0..=nv).map(move |j| (i, j)))
                .map(|(i, j)| Scalar::to_f64(&p.control_point(i, j)[0]).abs())
                .fold(0.0, f64::max);
            if w == 0.0 {
                continue;
            }
            let binom = |n: usize, k: usize| -> f64 {
                (0..k).fold(1.0, |acc, j| acc * (n - j) as f64 / (j + 1) as f64)
            };
            for i in 0..=nu {
                for c in 0..p.control_point(i, 0).len() {
                    let b: Vec<f64> = (0..=nv)
                        .map(|j| Scalar::to_f64(&p.control_point(i, j)[c]))
                        .collect();
                    scale = scale.max(b.iter().fold(0.0f64, |m, x| m.max(x.abs())) / w);
                    let s: f64 = (0..=nv)
                        .map(|j| {
                            (0..=j)
                                .map(|k| {
                                    let sign = if (j - k) % 2 == 0 { 1.0 } else { -1.0 };
                                    sign * b[k] * binom(nv, k) * binom(nv - k, j - k)
                                })
                                .sum::<f64>()
                                .abs()
                        })
                        .sum();
                    s_max = s_max.max(16.0 * (nv + 1) as f64 * f64::EPSILON * s / w);
                }
            }
        }
        slack = slack.max(s_max / scale);
    }
    slack
}

/// Builds `src` exactly; if the exact op accepts it, the float path must build it too
/// and agree (`split`: [`float_agreement::agree_or_split`]) to [`REL`] plus `extra(exact)`.
/// Returns whether the exact op built it (its refusals are its exceptional sets, not
/// compared).
fn check_with(src: &str, split: bool, extra: fn(&[Object]) -> f64) -> Result<bool, TestCaseError> {
    let Ok(exact) = build(src, Arithmetic::Exact) else {
        return Ok(false);
    };
    let f =
        build(src, Arithmetic::Float).map_err(|m| TestCaseError::fail(format!("{src}\n{m}")))?;
    let rel = REL + extra(&exact);
    let r = if split {
        float_agreement::agree_or_split(&exact, &f, rel)
    } else {
        float_agreement::agree(&exact, &f, rel)
    };
    r.map_err(|m| TestCaseError::fail(format!("{src}\n{m}")))?;
    marked(src, &f).map_err(|m| TestCaseError::fail(format!("{src}\n{m}")))?;
    Ok(true)
}

/// [`check_with`] at [`REL`].
fn check(src: &str, split: bool) -> Result<bool, TestCaseError> {
    check_with(src, split, |_| 0.0)
}

/// A small rational `p/q` as recipe text (numerators in `-n..=n`).
fn qn(n: i64) -> impl Strategy<Value = String> {
    (-n..=n, 1i64..=12).prop_map(|(p, d)| format!("\"{p}/{d}\""))
}

fn ptn(dim: usize, n: i64) -> impl Strategy<Value = String> {
    proptest::collection::vec(qn(n), dim).prop_map(|v| format!("[{}]", v.join(", ")))
}

/// Each op of this file has a float path (its property test is below).
#[test]
fn the_session_16_ops_have_a_float_path() {
    for name in [
        "ph_rrmf",
        "sweep_rrmf",
        "canal_surface_normal_field",
        "quadric_miquel_patch",
    ] {
        assert!(float::has_float_path(name), "{name}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// `ph_rrmf` and `sweep_rrmf` of random RRMF quintics (the generator `a0`, `a1`, `x`,
    /// random start): the exact frame cancels a common factor over Q and its rotation
    /// polynomial comes from Rothstein–Trager over Q(i); the float path replays both
    /// (`RationalRmf::along`). The sweep: a random profile of two joined quadratic pieces
    /// with positive weights.
    #[test]
    fn rrmf_frames_and_sweeps_agree(
        a0 in ptn(4, 6), a1 in ptn(4, 6), x in qn(8), start in ptn(3, 20),
        prof in proptest::collection::vec((qn(3), qn(3)), 5),
        w in proptest::collection::vec(1i64..=4, 6),
    ) {
        let curve = format!("a0 = {a0}\na1 = {a1}\nx = {x}\nstart = {start}\n");
        // A_0 ≠ 0 and the frame exists for every generated quintic: the exact op refuses
        // only A_0 = 0, so every draw with A_0 ≠ 0 is compared
        let built = check(&obj("ph_rrmf", &format!("{curve}samples = 5\n")), false)?;
        prop_assert!(built || a0.split(", ").all(|c| c.starts_with("\"0/") || c.starts_with("[\"0/")), "the exact ph_rrmf refused {curve}");
        let p: Vec<String> = prof.iter().map(|(a, b)| format!("[{a}, {b}]")).collect();
        let profile = format!(
            "profile = [[{}, {}, {}], [{}, {}, {}]]\nweights = [[{}, {}, {}], [{}, {}, {}]]\n",
            p[0], p[1], p[2], p[2], p[3], p[4], w[0], w[1], w[2], w[3], w[4], w[5]
        );
        // the stated power-basis rounding of the sweep's assembly (`power_basis_slack`)
        check_with(&obj("sweep_rrmf", &format!("{curve}{profile}")), true, power_basis_slack)?;
    }

    /// `canal_surface_normal_field`: a random polynomial spine m(t) of degree ≤ 3, a
    /// constant rational unit field n₀ = (2a, 2b, a² + b² − 1)/(a² + b² + 1) and the radius
    /// r(t) = r₀ − ⟨n₀, m(t) − m(0)⟩ (so that ⟨n₀, ṁ⟩ + ṙ ≡ 0), on a random domain.
    #[test]
    fn canal_normal_fields_agree(
        spine in proptest::collection::vec(proptest::collection::vec(-12i64..=12, 3), 2..=4),
        a in (-5i64..=5, 1i64..=4), b in (-5i64..=5, 1i64..=4), r0 in (1i64..=30, 1i64..=4),
        t0 in 0i64..=3, u0 in -4i64..=3,
    ) {
        use rcagd_algebra::Rational;
        let q = |p: i64, d: i64| Rational::from(p) / Rational::from(d);
        let (a, b) = (q(a.0, a.1), q(b.0, b.1));
        let s = a.clone() * a.clone() + b.clone() * b.clone();
        let d = s.clone() + Rational::from(1);
        let n = [
            Rational::from(2) * a / d.clone(),
            Rational::from(2) * b / d.clone(),
            (s - Rational::from(1)) / d,
        ];
        let f = |x: &Rational| format!("\"{x}\"");
        let mut radius = vec![q(r0.0, r0.1)];
        for c in spine.iter().skip(1) {
            let dot = (0..3).fold(Rational::from(0), |acc, k| acc + Rational::from(c[k]) * n[k].clone());
            radius.push(-dot);
        }
        let spine: Vec<String> = spine
            .iter()
            .map(|c| format!("[{}, {}, {}]", c[0], c[1], c[2]))
            .collect();
        let body = format!(
            "spine = [{}]\nradius = [{}]\nnormal = [[{}, {}, {}]]\ndomain = [\"{t0}/4\", \"{}/4\", \"{u0}/2\", \"{}/2\"]\n",
            spine.join(", "),
            radius.iter().map(f).collect::<Vec<_>>().join(", "),
            f(&n[0]), f(&n[1]), f(&n[2]),
            t0 + 1,
            u0 + 1,
        );
        check(&obj("canal_surface_normal_field", &body), true)?;
    }
}

/// A random Miquel configuration on the unit sphere: the image under δ of a random
/// bilinear patch (integer corners), its corners and the images of its edge midpoints as
/// recipe text (`None` where a point is at infinity or the library refuses the patch).
fn miquel_recipe(c: &[Vec<i64>], weight: &str) -> Option<String> {
    use rcagd::quadric::{BiquadraticPatch, Delta};
    use rcagd_algebra::Rational;
    let h = |v: &Vec<i64>| -> [Rational; 4] { core::array::from_fn(|k| Rational::from(v[k])) };
    let p = BiquadraticPatch::from_bilinear(&Delta, h(&c[0]), h(&c[1]), h(&c[2]), h(&c[3])).ok()?;
    let y = p.patch();
    let (z, half, one) = (
        Rational::from(0),
        Rational::from(1) / Rational::from(2),
        Rational::from(1),
    );
    let at = |u: &Rational, v: &Rational| -> Option<String> {
        let x = y.eval(u, v).ok()?;
        Some(format!(
            "[{}]",
            x.iter()
                .map(|a| format!("\"{a}\""))
                .collect::<Vec<_>>()
                .join(", ")
        ))
    };
    let corners = [at(&z, &z)?, at(&one, &z)?, at(&one, &one)?, at(&z, &one)?];
    let circle = [
        at(&half, &z)?,
        at(&one, &half)?,
        at(&half, &one)?,
        at(&z, &half)?,
    ];
    Some(obj(
        "quadric_miquel_patch",
        &format!(
            "corners = [{}]\ncircle_points = [{}]\nweight = {weight}\n",
            corners.join(", "),
            circle.join(", ")
        ),
    ))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// `quadric_miquel_patch` on the unit sphere: the corners and circle points of the
    /// image of a random bilinear patch under δ (a Miquel configuration by construction),
    /// a random essential weight. The exact op's choice among the sign flips is replayed.
    #[test]
    fn miquel_patches_agree(
        c in proptest::collection::vec(proptest::collection::vec(-4i64..=4, 4), 4),
        w in qn(5),
    ) {
        if let Some(src) = miquel_recipe(&c, &w) {
            check(&src, true)?;
        }
    }
}
