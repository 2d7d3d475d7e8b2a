//! The worked examples of S. Besednjak, *DPH-krivulje in polinomske vijačnice*, chapters 3,
//! 4, 8 and 9, reproduced exactly (docs/math/ph-curves.md). Printed values that the thesis
//! gets wrong are replaced by the corrected value, with a comment citing the erratum.
//!
//! The printed data of chapter 8 (α, β, quaternion coefficients, control points, power
//! form, gcd(x',y',z'), σ, |κ/τ|) are transcribed from the thesis (via an independent
//! sympy transcription of its printed values).

use rcagd::ph::dph::{dph_septic, dph_septic_z_roots};
use rcagd::ph::hermite::seed_xi_quartic;
use rcagd::ph::*;
use rcagd_algebra::complex::Complex;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{parse_rational, Certificate, Poly, Rational};

type Q = Rational;

fn q(s: &str) -> Q {
    parse_rational(s).expect("number")
}
fn qi(n: i64) -> Q {
    Q::from(n)
}
fn c(re: &str, im: &str) -> Complex<Q> {
    Complex::new(q(re), q(im))
}
fn ci(re: i64, im: i64) -> Complex<Q> {
    Complex::new(qi(re), qi(im))
}
fn poly(c: &[&str]) -> Poly<Q> {
    Poly::new(c.iter().map(|s| q(s)).collect())
}
fn origin() -> [Q; 3] {
    [qi(0), qi(0), qi(0)]
}
fn assert_certs(certs: &[Certificate]) {
    for c in certs {
        assert!(c.holds, "certificate failed: {c}");
        assert!(c.exact, "certificate not exact: {c}");
    }
}

/// Printed data of one chapter-8 example.
struct Printed {
    alpha: &'static [(&'static str, &'static str)],
    beta: &'static [(&'static str, &'static str)],
    quats: &'static [[&'static str; 4]],
    points: &'static [[&'static str; 3]],
    xyz: [&'static [&'static str]; 3],
    gcd: &'static [&'static str],
    sigma: &'static [&'static str],
    /// `(κ/τ)² = kt2_num/kt2_den` (printed `|κ/τ|`, squared).
    kt2_num: &'static [&'static str],
    kt2_den: &'static [&'static str],
}

/// Checks every printed quantity of a chapter-8 example against the curve built by the
/// library, plus all certificates. `axis` is the exact solution `a` of `a·r' ≡ σ`
/// (exact recomputation) or `None` for a non-helical curve.
fn check_printed(ex: &Printed, curve: &PhCurve<Q>, axis: Option<[&str; 3]>) {
    let (al, be) = curve.hopf_coefficients();
    let pa: Vec<Complex<Q>> = ex.alpha.iter().map(|(a, b)| c(a, b)).collect();
    let pb: Vec<Complex<Q>> = ex.beta.iter().map(|(a, b)| c(a, b)).collect();
    assert_eq!(al, pa, "α coefficients");
    assert_eq!(be, pb, "β coefficients");
    let pq: Vec<Quaternion<Q>> = ex
        .quats
        .iter()
        .map(|x| Quaternion::new(q(x[0]), q(x[1]), q(x[2]), q(x[3])))
        .collect();
    assert_eq!(curve.coefficients(), &pq[..], "quaternion coefficients");
    let pts: Vec<[Q; 3]> = ex
        .points
        .iter()
        .map(|p| [q(p[0]), q(p[1]), q(p[2])])
        .collect();
    assert_eq!(curve.control_points(), pts, "control points (8.2)");
    let pos = curve.position();
    for (k, pk) in pos.iter().enumerate() {
        assert_eq!(*pk, poly(ex.xyz[k]), "power-basis component {k}");
    }
    assert_certs(&curve.certify());
    assert_certs(&curve.certify_arc_length());
    assert_certs(&curve.certify_curvature());
    assert_certs(&curve.euler_rodrigues_frame().certify());
    let pc = curve.to_poly_curve();
    assert_eq!(pc.hodograph_gcd(), poly(ex.gcd), "gcd(x', y', z')");
    assert_eq!(pc.speed(), &poly(ex.sigma), "σ");
    // PH test of the power form recovers σ
    let pc2 = PhPolyCurve::from_polynomials(pos.clone()).expect("PH");
    assert_eq!(pc2.speed(), &poly(ex.sigma));
    // DPH, Frenet frame
    let dph = pc.dph().expect("every chapter-8 curve is DPH");
    assert_certs(&pc.certify_dph(&dph));
    assert_certs(&pc.frenet_frame(&dph).certify());
    // (κ/τ)² = ρ³/trip² equals the printed |κ/τ|²
    let rho = pc.rho().unwrap();
    let trip = pc.triple_product();
    let lhs = &rho.pow(3) * &poly(ex.kt2_den);
    let rhs = &poly(ex.kt2_num) * &(&trip * &trip);
    assert_eq!(lhs, rhs, "|κ/τ|");
    match (pc.helix_test().unwrap(), axis) {
        (HelixTest::Helix(h), Some(a)) => {
            assert_eq!(h.a, [q(a[0]), q(a[1]), q(a[2])], "axis vector a (a·r' ≡ σ)");
            assert_certs(&pc.certify_helix(&h));
            assert!(matches!(
                curve.classify().unwrap(),
                DphClass::Dph { helical: true, .. }
            ));
            // tan²ψ = |a|² − 1 is the printed |κ/τ|² (a constant)
            assert_eq!(
                &poly(ex.kt2_num),
                &Poly::constant(h.tan2_psi()).scale(&poly(ex.kt2_den).coeff(0))
            );
        }
        (HelixTest::NotHelix, None) => {
            assert!(!pc.kappa_over_tau_squared().unwrap().is_constant());
            assert!(matches!(
                curve.classify().unwrap(),
                DphClass::Dph { helical: false, .. }
            ));
        }
        (t, a) => panic!("helix test {t:?} but expected axis {a:?}"),
    }
}
const EX8_1: Printed = Printed {
    alpha: &[("1", "1"), ("2", "2"), ("3", "2"), ("3", "1")],
    beta: &[("0", "1"), ("0", "2"), ("1", "1"), ("2", "-1")],
    quats: &[
        ["1", "1", "1", "0"],
        ["2", "2", "2", "0"],
        ["3", "2", "1", "1"],
        ["3", "1", "-1", "2"],
    ],
    points: &[
        ["0", "0", "0"],
        ["1/7", "2/7", "-2/7"],
        ["3/7", "6/7", "-6/7"],
        ["1", "62/35", "-12/7"],
        ["21/10", "99/35", "-87/35"],
        ["253/70", "137/35", "-93/35"],
        ["353/70", "177/35", "-68/35"],
        ["403/70", "227/35", "-18/35"],
    ],
    xyz: [
        &["0", "1", "3", "5", "7/2", "-48/5", "3", "-1/7"],
        &["0", "2", "6", "2", "-9", "36/5", "-2", "2/7"],
        &["0", "-2", "-6", "0", "13", "-24/5", "-1", "2/7"],
    ],
    gcd: &["1"],
    sigma: &["3", "18", "9", "-54", "54", "-18", "3"],
    kt2_num: &["5"],
    kt2_den: &["4"],
};

const EX8_2: Printed = Printed {
    alpha: &[("0", "5"), ("-3", "11/3"), ("0", "3"), ("1", "1")],
    beta: &[("1", "-1"), ("2", "5/3"), ("-5/3", "13/3"), ("2", "5")],
    quats: &[
        ["0", "5", "-1", "1"],
        ["-3", "11/3", "5/3", "2"],
        ["0", "3", "13/3", "-5/3"],
        ["1", "1", "5", "2"],
    ],
    points: &[
        ["0", "0", "0"],
        ["23/7", "-10/7", "10/7"],
        ["41/7", "-25/21", "62/21"],
        ["42/5", "-11/105", "100/21"],
        ["66/7", "376/105", "692/105"],
        ["269/35", "706/105", "246/35"],
        ["577/105", "971/105", "246/35"],
        ["172/105", "1181/105", "216/35"],
    ],
    xyz: [
        &["0", "23", "-15", "24", "-76", "252/5", "20/3", "-80/7"],
        &["0", "-10", "35", "-86/3", "90", "-784/5", "108", "-184/7"],
        &["0", "10", "2", "20/3", "-16", "-72/5", "88/3", "-80/7"],
    ],
    gcd: &["1/4", "0", "1", "-2", "1"],
    sigma: &["27", "-50", "162", "-416", "724", "-632", "216"],
    kt2_num: &["829"],
    kt2_den: &["4"],
};

const EX8_3: Printed = Printed {
    alpha: &[("1", "0"), ("5/3", "1/3"), ("2", "5/3"), ("1", "3")],
    beta: &[("2", "0"), ("10/3", "2/3"), ("11/3", "7/3"), ("4", "2")],
    quats: &[
        ["1", "0", "0", "2"],
        ["5/3", "1/3", "2/3", "10/3"],
        ["2", "5/3", "7/3", "11/3"],
        ["1", "3", "2", "4"],
    ],
    points: &[
        ["0", "0", "0"],
        ["-3/7", "4/7", "0"],
        ["-8/7", "32/21", "0"],
        ["-46/21", "62/21", "2/35"],
        ["-374/105", "517/105", "11/35"],
        ["-37/7", "53/7", "103/105"],
        ["-148/21", "75/7", "13/5"],
        ["-178/21", "95/7", "191/35"],
    ],
    xyz: [
        &["0", "-3", "-6", "-5/3", "2", "-2", "10/3", "-8/7"],
        &["0", "4", "8", "10/3", "-1", "2", "-10/3", "4/7"],
        &["0", "0", "0", "2", "3", "-2/5", "2", "-8/7"],
    ],
    gcd: &["1", "0", "1"],
    sigma: &["5", "20", "11", "-8", "18", "-28", "12"],
    kt2_num: &["10"],
    kt2_den: &["1"],
};

const EX8_4: Printed = Printed {
    alpha: &[("1", "0"), ("0", "2"), ("-4", "5/3"), ("-4", "-2")],
    beta: &[("0", "1"), ("-5/3", "0"), ("-1", "-10/3"), ("2", "-3")],
    quats: &[
        ["1", "0", "1", "0"],
        ["0", "2", "0", "-5/3"],
        ["-4", "5/3", "-10/3", "-1"],
        ["-4", "-2", "-3", "2"],
    ],
    points: &[
        ["0", "0", "0"],
        ["0", "0", "-2/7"],
        ["0", "1/21", "-2/7"],
        ["1/15", "3/35", "-46/105"],
        ["4/15", "3/35", "-20/21"],
        ["4/5", "-1/7", "-326/105"],
        ["22/15", "-10/21", "-626/105"],
        ["37/15", "-22/21", "-158/15"],
    ],
    xyz: [
        &["0", "0", "0", "7/3", "0", "14/5", "-14/3", "2"],
        &["0", "0", "1", "-2", "1", "-4", "14/3", "-12/7"],
        &["0", "-2", "6", "-46/3", "8", "-136/5", "32", "-12"],
    ],
    gcd: &["1/2", "0", "1", "-2", "1"],
    sigma: &["2", "-12", "47", "-32", "138", "-196", "86"],
    kt2_num: &["1"],
    kt2_den: &["49"],
};

const EX8_5: Printed = Printed {
    alpha: &[("1", "0"), ("0", "2"), ("-4", "3"), ("-12", "-2")],
    beta: &[("0", "1"), ("-5/3", "0"), ("-7/3", "-10/3"), ("2", "-29/3")],
    quats: &[
        ["1", "0", "1", "0"],
        ["0", "2", "0", "-5/3"],
        ["-4", "3", "-10/3", "-7/3"],
        ["-12", "-2", "-29/3", "2"],
    ],
    points: &[
        ["0", "0", "0"],
        ["0", "0", "-2/7"],
        ["0", "1/21", "-2/7"],
        ["1/15", "3/35", "-46/105"],
        ["32/105", "3/35", "-48/35"],
        ["104/105", "1/105", "-466/105"],
        ["962/315", "-34/105", "-1486/105"],
        ["1079/105", "-58/35", "-5086/105"],
    ],
    xyz: [
        &["0", "0", "0", "7/3", "4/3", "14/5", "22/9", "86/63"],
        &["0", "0", "1", "-2", "1", "-4/5", "-2/3", "-4/21"],
        &[
            "0", "-2", "6", "-46/3", "-20/3", "-56/5", "-40/3", "-124/21",
        ],
    ],
    gcd: &["1"],
    sigma: &["2", "-12", "47", "80/3", "58", "244/3", "382/9"],
    kt2_num: &[
        "81", "0", "648", "-1296", "2592", "-7776", "14256", "-23328", "42120", "-62208", "75168",
        "-88128", "93312", "-72576", "36288", "-10368", "1296",
    ],
    kt2_den: &[
        "3969", "18144", "-1944", "26784", "372384", "-196992", "-879984", "2238048", "-2102040",
        "-6412800", "4010400", "-2515584", "11149696", "-1383680", "3113280", "-1692800", "211600",
    ],
};

const EX8_6: Printed = Printed {
    alpha: &[("1", "0"), ("1", "0"), ("2", "-1/3"), ("2", "-5")],
    beta: &[("-1", "0"), ("-4/3", "0"), ("-8/3", "2/3"), ("-2", "7")],
    quats: &[
        ["1", "0", "0", "-1"],
        ["1", "0", "0", "-4/3"],
        ["2", "-1/3", "2/3", "-8/3"],
        ["2", "-5", "7", "-2"],
    ],
    points: &[
        ["0", "0", "0"],
        ["0", "-2/7", "0"],
        ["-1/21", "-13/21", "0"],
        ["-16/105", "-39/35", "-2/105"],
        ["-37/105", "-13/7", "-8/105"],
        ["-24/35", "-323/105", "-6/35"],
        ["-137/105", "-548/105", "-38/105"],
        ["-71/15", "-1718/105", "-158/105"],
    ],
    xyz: [
        &["0", "0", "-1", "-1/3", "-1", "3/5", "-1", "-2"],
        &["0", "-2", "-1", "-4", "1", "-18/5", "2/3", "-52/7"],
        &["0", "0", "0", "-2/3", "0", "2/5", "-2/3", "-4/7"],
    ],
    gcd: &["1/2", "-1", "1"],
    sigma: &["2", "2", "13", "-4", "17", "-2", "54"],
    kt2_num: &["1"],
    kt2_den: &["4"],
};

const EX8_7: Printed = Printed {
    alpha: &[("1", "0"), ("1", "0"), ("2", "1"), ("2", "-1")],
    beta: &[("-1", "0"), ("-4/3", "0"), ("-8/3", "-2/3"), ("-2", "5/3")],
    quats: &[
        ["1", "0", "0", "-1"],
        ["1", "0", "0", "-4/3"],
        ["2", "1", "-2/3", "-8/3"],
        ["2", "-1", "5/3", "-2"],
    ],
    points: &[
        ["0", "0", "0"],
        ["0", "-2/7", "0"],
        ["-1/21", "-13/21", "0"],
        ["-16/105", "-39/35", "-2/105"],
        ["-37/105", "-13/7", "-4/35"],
        ["-64/105", "-331/105", "-38/105"],
        ["-247/315", "-436/105", "-58/105"],
        ["-109/105", "-202/35", "-14/15"],
    ],
    xyz: [
        &["0", "0", "-1", "-1/3", "-1", "11/5", "-5/9", "-22/63"],
        &["0", "-2", "-1", "-4", "1", "-26/5", "34/3", "-124/21"],
        &["0", "0", "0", "-2/3", "-4/3", "2/5", "2", "-4/3"],
    ],
    gcd: &["1"],
    sigma: &["2", "2", "13", "-4", "25", "-206/3", "382/9"],
    kt2_num: &[
        "81", "-324", "0", "3240", "-9396", "7776", "20736", "-77760", "128304", "-129600",
        "82944", "-31104", "5184",
    ],
    kt2_den: &[
        "324", "3888", "2592", "-38016", "157680", "-275616", "155808", "208512", "-581760",
        "300288", "260544", "-203136", "33856",
    ],
};

const EX8_8: Printed = Printed {
    alpha: &[("1", "0"), ("1", "-1"), ("-1", "4"), ("-1", "9")],
    beta: &[("-1", "1"), ("-1/3", "2"), ("-5/3", "-5"), ("-5", "-10")],
    quats: &[
        ["1", "0", "1", "-1"],
        ["1", "-1", "2", "-1/3"],
        ["-1", "4", "-5", "-5/3"],
        ["-1", "9", "-10", "-5"],
    ],
    points: &[
        ["0", "0", "0"],
        ["-1/7", "-2/7", "-2/7"],
        ["-1/3", "-13/21", "-4/7"],
        ["-8/21", "-29/35", "-26/35"],
        ["26/105", "26/35", "8/35"],
        ["-1/5", "-16/15", "-34/35"],
        ["-341/105", "-429/35", "-284/35"],
        ["-986/105", "-1279/35", "-834/35"],
    ],
    xyz: [
        &["0", "-1", "-1", "20/3", "12", "-276/5", "36", "-48/7"],
        &["0", "-2", "-1", "6", "52", "-872/5", "100", "-120/7"],
        &["0", "-2", "0", "4", "32", "-552/5", "64", "-80/7"],
    ],
    gcd: &["1"],
    sigma: &["3", "2", "-26", "-248", "1068", "-744", "152"],
    kt2_num: &["1"],
    kt2_den: &["64"],
};

const EX8_9: Printed = Printed {
    alpha: &[("1", "0"), ("1", "0"), ("2", "1"), ("2", "3")],
    beta: &[("-1", "0"), ("-2/3", "0"), ("-2/3", "-1"), ("0", "-2")],
    quats: &[
        ["1", "0", "0", "-1"],
        ["1", "0", "0", "-2/3"],
        ["2", "1", "-1", "-2/3"],
        ["2", "3", "-2", "0"],
    ],
    points: &[
        ["0", "0", "0"],
        ["0", "-2/7", "0"],
        ["1/21", "-11/21", "0"],
        ["6/35", "-83/105", "0"],
        ["2/5", "-113/105", "1/35"],
        ["86/105", "-163/105", "9/35"],
        ["23/15", "-86/35", "29/35"],
        ["296/105", "-146/35", "69/35"],
    ],
    xyz: [
        &["0", "0", "1", "1", "0", "6/5", "-2/3", "2/7"],
        &["0", "-2", "1", "-8/3", "3", "-28/5", "8/3", "-4/7"],
        &["0", "0", "0", "0", "1", "12/5", "-2", "4/7"],
    ],
    gcd: &["1"],
    sigma: &["2", "-2", "9", "-8", "30", "-20", "6"],
    kt2_num: &["1", "8", "4", "-40", "64", "-64", "40", "-16", "4"],
    kt2_den: &["0", "0", "144", "-144", "84", "168", "-92", "32", "64"],
};

// ------------------------------------------------------------------ chapter 3 and 4

/// Besednjak Example 3.13 (after Farouki): a DPH septic that is not a helix.
/// σ and |r'×r''| as printed; τ/κ corrected per docs/math/ph-curves.md, Errata E8: the thesis prints
/// `(2t⁶+9t⁴−9)/(9(t²+1)²)`, with τ from (2.14) it is `−(2t⁶+9t⁴−9)/(9(t²+1)²)`.
#[test]
fn example_3_13_dph_septic_not_helix() {
    let r = [
        poly(&["0", "-3", "0", "1", "0", "1/5", "0", "1/21"]),
        poly(&["0", "0", "3", "0", "-1/2"]),
        poly(&["0", "0", "0", "-2"]),
    ];
    let pc = PhPolyCurve::from_polynomials(r).expect("PH");
    let s6 = poly(&["9", "0", "9", "0", "3", "0", "1"]);
    assert_eq!(pc.speed(), &s6.scale(&q("1/3")), "σ = (t⁶+3t⁴+9t²+9)/3");
    let cr = pc.cross_r1_r2();
    let norm = &poly(&["2", "0", "2"]) * &s6; // 2(t²+1)(t⁶+3t⁴+9t²+9)
    let cr2 = &(&(&cr[0] * &cr[0]) + &(&cr[1] * &cr[1])) + &(&cr[2] * &cr[2]);
    assert_eq!(cr2, &norm * &norm, "|r'×r''| = 2(t²+1)(t⁶+3t⁴+9t²+9)");
    let dph = pc.dph().expect("DPH");
    assert_eq!(dph.c, qi(1));
    assert_eq!(dph.omega_tilde, poly(&["6", "0", "6"]), "ω = 6(t²+1)");
    assert_certs(&pc.certify_dph(&dph));
    assert_certs(&pc.frenet_frame(&dph).certify());
    // τ/κ = trip/ω³ = −(2t⁶+9t⁴−9)/(9(t²+1)²)  (docs/math/ph-curves.md, Errata E8: the thesis drops the sign)
    let trip = pc.triple_product();
    let w3 = dph.omega_tilde.pow(3);
    let lhs = &trip * &poly(&["9", "0", "18", "0", "9"]);
    let corrected = -(&poly(&["-9", "0", "0", "0", "9", "0", "2"]) * &w3);
    assert_eq!(
        lhs, corrected,
        "τ/κ (corrected sign, docs/math/ph-curves.md, Errata E8)"
    );
    let printed = &poly(&["-9", "0", "0", "0", "9", "0", "2"]) * &w3;
    assert_ne!(lhs, printed, "the printed sign is wrong");
    assert!(matches!(pc.helix_test().unwrap(), HelixTest::NotHelix));
    assert!(!pc.kappa_over_tau_squared().unwrap().is_constant());
}

/// Besednjak Example 4.4: a PH cubic, DPH with ω ≡ 2, triple product −16, κ/τ = −1/2.
#[test]
fn example_4_4_cubic_is_dph_and_helix() {
    let r = [
        poly(&["0", "-1", "0", "1/3"]),
        poly(&["0", "2", "-2", "2/3"]),
        poly(&["0", "-2", "1", "-2/3"]),
    ];
    let pc = PhPolyCurve::from_polynomials(r).expect("PH");
    let h = pc.hodograph();
    assert_eq!(h[0], poly(&["-1", "0", "1"]));
    assert_eq!(h[1], poly(&["2", "-4", "2"]));
    assert_eq!(h[2], poly(&["-2", "2", "-2"]));
    assert_eq!(pc.speed(), &poly(&["3", "-4", "3"]));
    let cr = pc.cross_r1_r2();
    assert_eq!(cr[0], poly(&["-4", "0", "4"]));
    assert_eq!(cr[1], poly(&["2", "-8", "2"]));
    assert_eq!(cr[2], poly(&["4", "-8", "4"]));
    assert_eq!(pc.triple_product(), Poly::constant(qi(-16)));
    let dph = pc.dph().unwrap();
    assert_eq!(dph.omega_tilde, Poly::constant(qi(2)), "ω ≡ 2");
    // κ/τ = ω³/trip = 8/(−16) = −1/2; |κ/τ|² = tan²ψ = |a|² − 1
    let kt = pc.kappa_over_tau_squared().unwrap();
    assert!(kt.is_constant());
    assert_eq!(kt.eval(&qi(0)), Some(q("1/4")));
    let hx = pc.helix().unwrap();
    assert_eq!(hx.tan2_psi(), q("1/4"));
    assert_certs(&pc.certify_helix(&hx));
    assert_certs(&pc.certify_arc_length());
    assert_eq!(pc.arc_length(), qi(2), "∫₀¹(3t²−4t+3) = 1 − 2 + 3");
}

/// Besednjak Example 4.5: a PH quintic that is not DPH. σ and ρ as printed. Erratum E18 (docs/math/ph-curves.md):
/// the printed hodograph and `r'×r''` are not those of the printed curve; they belong
/// to a different curve, which is PH with `σ = (2t²−2t+1)(4t²−2t+3)` and even DPH with
/// `ρ = 8(2t²−2t+1)²`.
#[test]
fn example_4_5_ph_quintic_not_dph() {
    let r = [
        poly(&["0", "0", "0", "10/3", "-7", "17/5"]),
        poly(&["0", "0", "2", "-4/3", "1", "-6/5"]),
        poly(&["0", "-2", "0", "-14/3", "11", "-6"]),
    ];
    let pc = PhPolyCurve::from_polynomials(r).expect("PH");
    assert_eq!(pc.speed(), &poly(&["2", "0", "18", "-52", "35"]));
    let rho = pc.rho().unwrap();
    assert_eq!(
        rho,
        poly(&["1", "-4", "3", "6", "2"]).scale(&qi(16)),
        "ρ = 16(2t⁴+6t³+3t²−4t+1)"
    );
    assert!(matches!(pc.dph_test().unwrap(), DphTest::NotDph { .. }));
    assert!(matches!(pc.dph(), Err(rcagd::ph::PhError::NotDph(_))));
    // docs/math/ph-curves.md, Errata E18: the printed hodograph is not r'
    let printed_h = [
        poly(&["-1", "0", "2", "-4"]),
        poly(&["2", "-6", "12", "-12", "8"]),
        poly(&["-2", "6", "-8", "4"]),
    ];
    assert_ne!(pc.hodograph()[0], printed_h[0]);
    // … it is the hodograph of another PH curve, which is DPH
    let integ = |p: &Poly<Q>| {
        let mut v = vec![qi(0)];
        v.extend(
            p.coeffs()
                .iter()
                .enumerate()
                .map(|(k, c)| c.clone() / Q::from(k as i64 + 1)),
        );
        Poly::new(v)
    };
    let other = PhPolyCurve::from_polynomials([
        integ(&printed_h[0]),
        integ(&printed_h[1]),
        integ(&printed_h[2]),
    ])
    .expect("the printed hodograph is Pythagorean");
    assert_eq!(
        other.speed(),
        &(&poly(&["1", "-2", "2"]) * &poly(&["3", "-2", "4"]))
    );
    let q2 = poly(&["1", "-2", "2"]);
    assert_eq!(
        other.rho().unwrap(),
        (&q2 * &q2).scale(&qi(8)),
        "ρ = 8(2t²−2t+1)²"
    );
    let cr = other.cross_r1_r2();
    let q4 = &q2 * &q2;
    assert_eq!(
        cr[0],
        &q4 * &poly(&["0", "16", "-8"]),
        "printed (r'×r'')_x = −8(t−2)t(2t²−2t+1)²"
    );
    assert_eq!(cr[1], q4.scale(&qi(6)));
    assert_eq!(cr[2], &q4 * &poly(&["6", "-8", "-8"]));
    let d = other.dph().expect("DPH");
    assert_eq!(
        d.c,
        qi(32),
        "ω = √32·(t² − t + 1/2), c not a rational square"
    );
    assert_certs(&other.certify_dph(&d));
}

/// Besednjak Lemma 2.1 / docs/math/ph-curves.md, "Prescribed tangents (Lemma 2.1)": `Q i Q* = (−1, 2, 2)` has the rational solution
/// `Q = i + j + k`.
#[test]
fn lemma_2_1_example() {
    let qq = solve_qiq(&[qi(-1), qi(2), qi(2)], None).unwrap();
    assert_eq!(qq, Quaternion::new(qi(0), qi(1), qi(1), qi(1)));
}

// ------------------------------------------------------------------ chapter 8

/// Besednjak Example 8.1: cubic reparametrization of the line/circle (6.5).
#[test]
fn example_8_1_cubic_reparametrization() {
    let seed = LineCircle::new(ci(1, 0), ci(1, 1), ci(1, -1), ci(0, 1)).unwrap();
    let f = [qi(1), qi(2), qi(2), qi(1)];
    let g = [qi(1), qi(2), qi(3), qi(3)];
    let curve = seed.reparametrized_helix(&f, &g, origin()).unwrap();
    check_printed(&EX8_1, &curve, Some(["0", "3/2", "0"]));
    // ω = 6√5·t(t³−2t²+2t+2): ρ = 180 ω̃², ω vanishes at t = 0 (inflection at the start)
    let d = curve.to_poly_curve().dph().unwrap();
    assert_eq!(d.c, qi(180));
    assert_eq!(d.omega_tilde, poly(&["0", "2", "2", "-2", "1"]));
    assert!(curve
        .to_poly_curve()
        .frenet_frame(&d)
        .eval_scaled(&qi(0))
        .is_none());
    assert!(
        curve.coefficients_in_real_plane(),
        "A_i = f_i V_0 + g_i V_1 (Besednjak §6.3)"
    );
    assert_eq!(
        curve.proportionality(),
        seed.predicted_proportionality(&f, &g, &[ci(1, 0)])
    );
}

/// The classical Frenet frame where the polynomial `ω̃` is negative (a regression: the
/// normal and binormal were divided by the signed `ω̃`, so they flipped wherever
/// `ω̃ < 0`). On the Example 8.1 curve `ω̃ = 2t + 2t² − 2t³ + t⁴ < 0` at `t = −1/2`.
#[test]
fn frenet_frame_is_classical_where_omega_is_negative() {
    let seed = LineCircle::new(ci(1, 0), ci(1, 1), ci(1, -1), ci(0, 1)).unwrap();
    let f = [qi(1), qi(2), qi(2), qi(1)];
    let g = [qi(1), qi(2), qi(3), qi(3)];
    let pc = seed
        .reparametrized_helix(&f, &g, origin())
        .unwrap()
        .to_poly_curve();
    let d = pc.dph().unwrap();
    let frame = pc.frenet_frame(&d);
    let dot = |a: &[Q; 3], b: &[Q; 3]| &(&(&a[0] * &b[0]) + &(&a[1] * &b[1])) + &(&a[2] * &b[2]);
    let cross = |a: &[Q; 3], b: &[Q; 3]| {
        [
            &(&a[1] * &b[2]) - &(&a[2] * &b[1]),
            &(&a[2] * &b[0]) - &(&a[0] * &b[2]),
            &(&a[0] * &b[1]) - &(&a[1] * &b[0]),
        ]
    };
    for t in [q("-1/2"), q("1/3"), q("-1/5")] {
        let w = d.omega_tilde.eval(&t);
        let (tt, p, b) = frame.eval_scaled(&t).unwrap();
        let bn = frame.binormal_numerator();
        let rxr = [bn[0].eval(&t), bn[1].eval(&t), bn[2].eval(&t)];
        // b along r'×r'' whatever the sign of ω̃ …
        assert!(dot(&b, &rxr) > qi(0), "t = {t}, ω̃ = {w}");
        // … and (t, p, b) right-handed: p = b × t (scaled by √c like b)
        assert_eq!(p, cross(&b, &tt), "t = {t}, ω̃ = {w}");
    }
    assert!(d.omega_tilde.eval(&q("-1/2")) < qi(0));
}

/// Besednjak Example 8.2: multiplication by the quadratic `w = (1, 1+i, 1)`.
#[test]
fn example_8_2_multiplication() {
    let seed = LineCircle::new(ci(0, 5), ci(1, 1), ci(1, -1), ci(2, 5)).unwrap();
    let w = [ci(1, 0), ci(1, 1), ci(1, 0)];
    let curve = seed.multiplied_helix(&w, origin()).unwrap();
    check_printed(&EX8_2, &curve, Some(["-6", "-4", "25/2"]));
    assert_eq!(
        curve.proportionality(),
        seed.predicted_proportionality(&[qi(0), qi(1)], &[qi(1), qi(1)], &w)
    );
}

/// Besednjak Example 8.3: quadratic reparametrization then linear multiplication.
#[test]
fn example_8_3_reparametrization_and_multiplication() {
    let seed = LineCircle::new(ci(1, 1), ci(1, 0), ci(1, -1), ci(2, 0)).unwrap();
    let f = [qi(1), qi(2), qi(1)];
    let g = [qi(1), qi(2), qi(2)];
    let w = [ci(1, 0), ci(1, 1)];
    let curve = seed.helix(&f, &g, &w, origin()).unwrap();
    check_printed(&EX8_3, &curve, Some(["-3", "-1", "1"]));
    let d = curve.to_poly_curve().dph().unwrap();
    assert_eq!(d.c, qi(160), "ω = 4√10·t(t+1)(t²+1)");
    assert_eq!(d.omega_tilde, poly(&["0", "1", "1", "1", "1"]));
}

fn septic(
    h: &[i64],
    w: &[Complex<Q>],
    a0: Complex<Q>,
    a1: Complex<Q>,
    b0: Complex<Q>,
    z: &Complex<Q>,
) -> PhCurve<Q> {
    let h: Vec<Q> = h.iter().map(|&x| qi(x)).collect();
    dph_septic(&h, w, &a0, &a1, &b0, z, origin()).expect("septic DPH")
}

/// Besednjak Examples 8.4 (helical) and 8.5 (non-helical): `st h = 0`, `st w = 2`, the two
/// roots of (5.8), `z = (4w_1² − w_0w_2)/9` and `z = w_0w_2/3`.
#[test]
fn examples_8_4_and_8_5_h0_w2() {
    let w = [ci(1, 0), ci(1, 1), ci(0, 1)];
    let z2 = {
        let w1 = &w[1];
        let w1sq = Complex::new(
            w1.re.clone() * w1.re.clone() - w1.im.clone() * w1.im.clone(),
            qi(2) * w1.re.clone() * w1.im.clone(),
        );
        let w0w2 = ci(0, 1);
        Complex::new(
            (qi(4) * w1sq.re - w0w2.re) / qi(9),
            (qi(4) * w1sq.im - w0w2.im) / qi(9),
        )
    };
    let z1 = Complex::new(qi(0), q("1/3"));
    let roots = dph_septic_z_roots(&[qi(1)], &w).unwrap();
    assert!(
        roots.contains(&z1) && roots.contains(&z2),
        "(5.8) roots {roots:?}"
    );
    let c84 = septic(&[1], &w, ci(1, 0), ci(0, 2), ci(0, 1), &z2);
    check_printed(&EX8_4, &c84, Some(["1/7", "0", "-1"]));
    assert_eq!(
        c84.classify().unwrap(),
        DphClass::Dph {
            h_degree: 0,
            w_degree: 2,
            helical: true
        }
    );
    let c85 = septic(&[1], &w, ci(1, 0), ci(0, 2), ci(0, 1), &z1);
    check_printed(&EX8_5, &c85, None);
    assert_eq!(
        c85.classify().unwrap(),
        DphClass::Dph {
            h_degree: 0,
            w_degree: 2,
            helical: false
        }
    );
    // Prop 7.6 decomposition printed in Ex 8.5 (checked in f64; it involves √2):
    // α = a_1(t−τ_1)³ + a_2(t−τ_2)³, β = b_1(t−τ_1)³ + b_2(t−τ_2)³, τ_1 = (1+√2+i)/2.
    let s2 = 2f64.sqrt();
    let cm = |a: (f64, f64), b: (f64, f64)| (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0);
    let cube = |x: (f64, f64)| cm(cm(x, x), x);
    let (t1, t2) = (((1.0 + s2) / 2.0, 0.5), ((1.0 - s2) / 2.0, 0.5));
    let pa1 = ((s2 - 1.0) / 2.0, (4.0 * s2 - 5.0) / 2.0);
    let pa2 = (-(s2 + 1.0) / 2.0, -(4.0 * s2 + 5.0) / 2.0);
    let pb1 = ((6.0 - 5.0 * s2) / 3.0, (s2 - 1.0) / 3.0);
    let pb2 = ((6.0 + 5.0 * s2) / 3.0, -(s2 + 1.0) / 3.0);
    let (al, be) = c85.to_f64().hopf_polys();
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        let e1 = cube((t - t1.0, -t1.1));
        let e2 = cube((t - t2.0, -t2.1));
        let a = cm(pa1, e1);
        let b = cm(pa2, e2);
        let av = al.eval(&Complex::new(t, 0.0));
        assert!(
            (a.0 + b.0 - av.re).abs() < 1e-9 && (a.1 + b.1 - av.im).abs() < 1e-9,
            "α at t = {t}"
        );
        let a = cm(pb1, e1);
        let b = cm(pb2, e2);
        let bv = be.eval(&Complex::new(t, 0.0));
        assert!(
            (a.0 + b.0 - bv.re).abs() < 1e-9 && (a.1 + b.1 - bv.im).abs() < 1e-9,
            "β at t = {t}"
        );
    }
    // a_1b_2 − a_2b_1 = −√2 i/3
    let d = (
        cm(pa1, pb2).0 - cm(pa2, pb1).0,
        cm(pa1, pb2).1 - cm(pa2, pb1).1,
    );
    assert!(d.0.abs() < 1e-12 && (d.1 + s2 / 3.0).abs() < 1e-12);
}

/// Besednjak Examples 8.6 (helical) and 8.7 (non-helical): `st h = 2`, `st w = 1`.
/// Erratum E16 (docs/math/ph-curves.md): the second root of (5.10) is `(h_2w_0² + h_1w_0w_1 + h_0w_1²)/9` (the thesis
/// prints `− h_0w_1²`, with which the linear system of Ex 8.6 has no solution).
/// Erratum E20 (docs/math/ph-curves.md): Ex 8.6 solves (5.9), not (5.7).
#[test]
fn examples_8_6_and_8_7_h2_w1() {
    let h = [1, 2, 1];
    let w = [ci(0, 1), ci(1, 0)];
    // w_0 = i, w_1 = 1: corrected root (h_2w_0² + h_1w_0w_1 + h_0w_1²)/9 = (−1 + 2i + 1)/9
    let z_corrected = Complex::new(qi(0), q("2/9"));
    let z_printed = Complex::new(q("-2/9"), q("2/9")); // (−1 + 2i − 1)/9
    let z_a = Complex::new(qi(0), q("2/3")); // h_1w_0w_1/3
    let roots = dph_septic_z_roots(&[qi(1), qi(2), qi(1)], &w).unwrap();
    assert!(
        roots.contains(&z_corrected) && roots.contains(&z_a),
        "(5.10) roots {roots:?}"
    );
    let hq: Vec<Q> = h.iter().map(|&x| qi(x)).collect();
    assert!(
        matches!(
            dph_septic(
                &hq,
                &w,
                &ci(1, 0),
                &ci(1, 0),
                &ci(-1, 0),
                &z_printed,
                origin()
            ),
            Err(rcagd::ph::PhError::NoRealSolution(_))
        ),
        "docs/math/ph-curves.md, Errata E16: the printed root gives no solution"
    );
    let c86 = septic(&h, &w, ci(1, 0), ci(1, 0), ci(-1, 0), &z_corrected);
    check_printed(&EX8_6, &c86, Some(["0", "-1", "-1/2"]));
    assert_eq!(
        c86.classify().unwrap(),
        DphClass::Dph {
            h_degree: 2,
            w_degree: 1,
            helical: true
        }
    );
    // Prop 7.7/7.8: helical iff gcd(α, β) is non-constant
    let (a, b) = c86.hopf_polys();
    assert_eq!(
        a.gcd(&b).degree(),
        Some(1),
        "gcd(α, β) = t − 1/2 + i/2 (up to a unit)"
    );
    let c87 = septic(&h, &w, ci(1, 0), ci(1, 0), ci(-1, 0), &z_a);
    check_printed(&EX8_7, &c87, None);
    assert_eq!(
        c87.classify().unwrap(),
        DphClass::Dph {
            h_degree: 2,
            w_degree: 1,
            helical: false
        }
    );
    let (a, b) = c87.hopf_polys();
    assert_eq!(a.gcd(&b).degree(), Some(0));
}

/// Besednjak Examples 8.8 (helical, Δ = 0) and 8.9 (non-helical, Δ = −9): `st h = 4`,
/// `st w = 0`. Erratum E22 (docs/math/ph-curves.md): `Δ = 9h_2² + 3h_0h_4 − 12h_1h_3` (the thesis prints `h_1h_4`,
/// which would give 216 and 15); docs/math/ph-curves.md, Errata E21: Ex 8.7 cites (5.8)/(5.7) for (5.10)/(5.9).
#[test]
fn examples_8_8_and_8_9_h4_w0() {
    let h88 = [-1i64, 2, 3, 4, -5];
    let delta = |h: &[i64]| 9 * h[2] * h[2] + 3 * h[0] * h[4] - 12 * h[1] * h[3];
    let misprint = |h: &[i64]| 9 * h[2] * h[2] + 3 * h[0] * h[4] - 12 * h[1] * h[4];
    assert_eq!((delta(&h88), misprint(&h88)), (0, 216));
    let hq: Vec<Q> = h88.iter().map(|&x| qi(x)).collect();
    let roots = dph_septic_z_roots(&hq, &[ci(1, 0)]).unwrap();
    assert_eq!(roots[0], ci(1, 0), "z = (3h_2 + √Δ)/9 = 1");
    let c88 = septic(&h88, &[ci(1, 0)], ci(1, 0), ci(1, -1), ci(-1, 1), &roots[0]);
    check_printed(&EX8_8, &c88, Some(["-1/4", "-3/4", "-5/8"]));
    assert_eq!(
        c88.classify().unwrap(),
        DphClass::Dph {
            h_degree: 4,
            w_degree: 0,
            helical: true
        }
    );
    let h89 = [1i64, 2, 2, 2, 1];
    assert_eq!((delta(&h89), misprint(&h89)), (-9, 15));
    let hq: Vec<Q> = h89.iter().map(|&x| qi(x)).collect();
    let roots = dph_septic_z_roots(&hq, &[ci(1, 0)]).unwrap();
    // negative sign at the root: z = (3h_2 − √Δ)/9 = (6 − 3i)/9
    let zm = Complex::new(q("2/3"), q("-1/3"));
    assert_eq!(roots[1], zm);
    let c89 = septic(&h89, &[ci(1, 0)], ci(1, 0), ci(1, 0), ci(-1, 0), &zm);
    check_printed(&EX8_9, &c89, None);
    assert_eq!(
        c89.classify().unwrap(),
        DphClass::Dph {
            h_degree: 4,
            w_degree: 0,
            helical: false
        }
    );
}

// ------------------------------------------------------------------ chapter 9

/// The data of Besednjak's Example 9.1 (`p_s = 0`, `d_s = (1,0,1)`, `p_f = (1,1,1)`,
/// `d_f = (0,1,1)`), shared by the tests of the Hermite solver, its enclosures and the
/// library-first API.
pub(crate) fn example_9_1_data() -> HermiteData<Q> {
    HermiteData::new(
        origin(),
        [qi(1), qi(0), qi(1)],
        [qi(1), qi(1), qi(1)],
        [qi(0), qi(1), qi(1)],
    )
}

/// Besednjak Example 9.1: `p_s = 0`, `d_s = (1,0,1)`, `p_f = (1,1,1)`, `d_f = (0,1,1)`.
/// Four real roots, two admissible, four interpolants; values as printed (docs/math/ph-curves.md:
/// "All claims hold"); the printed axis of the ξ₂ pair is the opposite vector with
/// ψ = 148.728°, equivalent to ours (ψ = 31.2717°).
#[test]
fn example_9_1_hermite() {
    let data = example_9_1_data();
    let sol = data.solve_exact().expect("solutions");
    assert!(
        sol.m.is_rational(),
        "|d_s||d_f| = 2 is rational: the quartic is over Q"
    );
    assert_eq!(sol.quartic.degree(), Some(4));
    assert_eq!(sol.roots.len(), 4, "four real roots (9.31)");
    assert_eq!(
        sol.roots.iter().filter(|r| r.valid).count(),
        2,
        "ξ₁, ξ₃ rejected"
    );
    assert_eq!(sol.interpolants.len(), 4);
    assert_certs(
        &sol.certify()
            .into_iter()
            .filter(|c| c.exact)
            .collect::<Vec<_>>(),
    );
    for c in sol.certify() {
        assert!(c.holds, "{c}");
    }
    let close = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol * b.abs().max(1.0);
    let mut seen = [false; 4];
    for s in &sol.interpolants {
        let HelixTest::Helix(hx) = &s.helix else {
            panic!("helix expected")
        };
        let axis = hx.axis_f64();
        let psi = hx.psi_f64().to_degrees();
        if close(s.k0.abs(), 1.705_394_7, 1e-6) {
            // ξ₂: k_0 = −k_2 = ∓1.705395, φ = −2.109108, E = 322.30 (both)
            assert!(close(s.k2, -s.k0, 1e-9));
            assert!(close(s.phi, -2.109_108, 1e-6), "φ = {}", s.phi);
            assert!(close(s.xi, -1.761_857, 1e-6));
            assert!(
                close(s.bending_energy, 322.298_11, 1e-6),
                "E = {}",
                s.bending_energy
            );
            assert!(
                close(axis[0], 0.309_913, 1e-5)
                    && close(axis[1], 0.309_913, 1e-5)
                    && close(axis[2], 0.898_837, 1e-5)
            );
            assert!(close(psi, 31.2717, 1e-5) && close(180.0 - psi, 148.728, 1e-5));
            assert!(close(hx.kappa_over_tau_abs_f64(), 0.607_333, 1e-5));
            seen[if s.k0 > 0.0 { 0 } else { 1 }] = true;
            assert!(!s.least_energy);
        } else {
            // ξ₄: k_0 = k_2 = ±1.850380, φ = 1.169321, E = 1.27 (+) and 89.58 (−)
            assert!(close(s.k0.abs(), 1.850_380_1, 1e-6), "k0 = {}", s.k0);
            assert!(close(s.k2, s.k0, 1e-9));
            assert!(close(s.phi, 1.169_321, 1e-6), "φ = {}", s.phi);
            assert!(close(s.xi, 0.661_850, 1e-5));
            assert!(
                close(axis[0], 0.354_664, 1e-5)
                    && close(axis[1], 0.354_664, 1e-5)
                    && close(axis[2], 0.865_117, 1e-5)
            );
            assert!(close(psi, 30.3998, 1e-5));
            assert!(close(hx.kappa_over_tau_abs_f64(), 0.586_692, 1e-5));
            if s.k0 > 0.0 {
                assert!(
                    close(s.bending_energy, 1.273_595_4, 1e-6),
                    "E = {}",
                    s.bending_energy
                );
                assert!(s.least_energy, "the least-energy interpolant");
                seen[2] = true;
            } else {
                assert!(
                    close(s.bending_energy, 89.576_305, 1e-6),
                    "E = {}",
                    s.bending_energy
                );
                seen[3] = true;
            }
        }
    }
    assert_eq!(seen, [true; 4]);
    assert_eq!(sol.best().len(), 1);
    // The seed's ξ-quartic (9.30), normalised so that d₄ = −3765.49, and its roots (9.31).
    let d = seed_xi_quartic(&data).unwrap();
    let printed = [-5064.36, -80193.2, 88889.6, 68726.2, -3765.49];
    for k in 0..5 {
        let v = d[k] * printed[4] / d[4];
        assert!(
            close(v, printed[k], 2e-5),
            "d_{k}: {v} vs printed {}",
            printed[k]
        );
    }
    for xi in [-0.059_419, -1.761_857, 19.411_014, 0.661_850] {
        let v = d.iter().rev().fold(0.0, |a, c| a * xi + c);
        let dv = d
            .iter()
            .enumerate()
            .skip(1)
            .rev()
            .fold(0.0, |a, (k, c)| a * xi + k as f64 * c);
        assert!(
            (v / dv).abs() < 1e-5 * xi.abs().max(1.0),
            "ξ = {xi} is a root of (9.27)"
        );
    }
    // f64 path agrees
    let solf = data.solve_f64().unwrap();
    assert_eq!(solf.interpolants.len(), 4);
    let mut ef: Vec<f64> = solf.interpolants.iter().map(|i| i.bending_energy).collect();
    let mut ee: Vec<f64> = sol.interpolants.iter().map(|i| i.bending_energy).collect();
    ef.sort_by(f64::total_cmp);
    ee.sort_by(f64::total_cmp);
    for (a, b) in ef.iter().zip(&ee) {
        assert!(close(*a, *b, 1e-9));
    }
}

/// Degenerate Hermite data give typed errors (docs/math/ph-curves.md, "Hermite interpolation by helical PH quintics", docs/math/ph-curves.md, Errata E25).
#[test]
fn hermite_errors() {
    let z = origin();
    let e = |d: HermiteData<Q>| d.solve_exact().expect_err("error");
    assert!(matches!(
        e(HermiteData::new(
            z.clone(),
            z.clone(),
            [qi(1), qi(0), qi(0)],
            [qi(0), qi(1), qi(0)]
        )),
        rcagd::ph::PhError::ZeroTangent(_)
    ));
    assert!(matches!(
        e(HermiteData::new(
            z.clone(),
            [qi(1), qi(0), qi(0)],
            z.clone(),
            [qi(0), qi(1), qi(0)]
        )),
        rcagd::ph::PhError::CoincidentEndPoints(_)
    ));
    assert!(matches!(
        e(HermiteData::new(
            z.clone(),
            [qi(1), qi(0), qi(0)],
            [qi(1), qi(1), qi(0)],
            [qi(2), qi(0), qi(0)]
        )),
        rcagd::ph::PhError::ParallelEndTangents(_)
    ));
    // collinear data with antiparallel end tangents, d_s = (1,0,0), d_f = (−1,0,0),
    // p_f − p_s = (−1,0,0): h = (−120,0,0) = r_1d_s + r_2d_f with r_1r_2 = 25 has the
    // solution r_1 = −60 + √3625 > 0, so 16k_0k_2 = 5 and every φ interpolates — a
    // one-parameter family, reported as a typed error (not enumerated)
    let family = HermiteData::new(
        z.clone(),
        [qi(1), qi(0), qi(0)],
        [qi(-1), qi(0), qi(0)],
        [qi(-1), qi(0), qi(0)],
    );
    let ex = family.solve_exact();
    assert!(
        matches!(ex, Err(rcagd::ph::PhError::Degenerate(_))),
        "{ex:?}"
    );
}

// ------------------------------------------------------------------ chapter 6 relations

/// `α_1 = α_0c_{10} + α_3c_{13}`, `α_2 = α_0c_{20} + α_3c_{23}` and the same for `β`
/// (i.e. `A_1 = A_0c_{10} + A_3c_{13}`, … with the `c`'s multiplying on the right).
fn check_septic_relations(curve: &PhCurve<Q>, c: [Complex<Q>; 4]) {
    let (a, b) = curve.hopf_coefficients();
    assert_eq!(a.len(), 4, "a septic");
    let [c10, c13, c20, c23] = c;
    for x in [&a, &b] {
        assert_eq!(
            x[1],
            x[0].clone() * c10.clone() + x[3].clone() * c13.clone(),
            "A_1 = A_0 c10 + A_3 c13"
        );
        assert_eq!(
            x[2],
            x[0].clone() * c20.clone() + x[3].clone() * c23.clone(),
            "A_2 = A_0 c20 + A_3 c23"
        );
    }
}

/// Besednjak (6.15) on Example 8.1 (cubic reparametrization): `c10 = 2h_3/(3k)`,
/// `c13 = h_0/(3k)`, `c20 = h_4/(3k)`, `c23 = 2h_1/(3k)` with the Bernstein coefficients
/// `h_i` of `f'g − fg'` and `k = f_3g_0 − f_0g_3` (real c's: a general helix).
#[test]
fn relations_6_15_cubic_reparametrization() {
    let seed = LineCircle::new(ci(1, 0), ci(1, 1), ci(1, -1), ci(0, 1)).unwrap();
    let f = [1i64, 2, 2, 1];
    let g = [1i64, 2, 3, 3];
    let curve = seed
        .reparametrized_helix(&f.map(qi), &g.map(qi), origin())
        .unwrap();
    let h = [
        qi(3 * (f[1] * g[0] - f[0] * g[1])),
        q("3/2") * qi(f[2] * g[0] - f[0] * g[2]),
        q("3/2") * qi(f[2] * g[1] - f[1] * g[2]) + q("1/2") * qi(f[3] * g[0] - f[0] * g[3]),
        q("3/2") * qi(f[3] * g[1] - f[1] * g[3]),
        qi(3 * (f[3] * g[2] - f[2] * g[3])),
    ];
    let k = qi(f[3] * g[0] - f[0] * g[3]);
    let r = |x: Q| Complex::new(x, qi(0));
    let k3 = qi(3) * k;
    check_septic_relations(
        &curve,
        [
            r(qi(2) * h[3].clone() / k3.clone()),
            r(h[0].clone() / k3.clone()),
            r(h[4].clone() / k3.clone()),
            r(qi(2) * h[1].clone() / k3),
        ],
    );
    assert!(curve.coefficients_in_real_plane());
}

/// Besednjak (6.22) on Example 8.2 (multiplication by a quadratic `w`): `c10 = 2w_1/(3w_0)`,
/// `c13 = w_0/(3w_2)`, `c20 = w_2/(3w_0)`, `c23 = 2w_1/(3w_2)` (complex: a monotone helix).
#[test]
fn relations_6_22_multiplication() {
    let seed = LineCircle::new(ci(0, 5), ci(1, 1), ci(1, -1), ci(2, 5)).unwrap();
    let w = [ci(1, 0), ci(1, 1), ci(1, 0)];
    let curve = seed.multiplied_helix(&w, origin()).unwrap();
    let three = ci(3, 0);
    let two = ci(2, 0);
    check_septic_relations(
        &curve,
        [
            two.clone() * w[1].clone() / (three.clone() * w[0].clone()),
            w[0].clone() / (three.clone() * w[2].clone()),
            w[2].clone() / (three.clone() * w[0].clone()),
            two * w[1].clone() / (three * w[2].clone()),
        ],
    );
    assert!(
        !curve.coefficients_in_real_plane(),
        "a monotone (non-general) helix: the A_i span more than a real 2-plane"
    );
}

/// Besednjak (6.24) on Example 8.3 (quadratic reparametrization, then linear `w`):
/// `c10 = (h_1w_1 + h_2w_0)/(3h_1w_0)`, `c13 = h_0w_0/(3h_1w_1)`, `c20 = h_2w_1/(3h_1w_0)`,
/// `c23 = (h_1w_0 + h_0w_1)/(3h_1w_1)` with `h` of (6.9).
#[test]
fn relations_6_24_reparametrization_and_multiplication() {
    let seed = LineCircle::new(ci(1, 1), ci(1, 0), ci(1, -1), ci(2, 0)).unwrap();
    let f = [1i64, 2, 1];
    let g = [1i64, 2, 2];
    let w = [ci(1, 0), ci(1, 1)];
    let curve = seed.helix(&f.map(qi), &g.map(qi), &w, origin()).unwrap();
    let r = |x: i64| Complex::new(qi(x), qi(0));
    let h = [
        r(2 * (f[1] * g[0] - f[0] * g[1])),
        r(f[2] * g[0] - f[0] * g[2]),
        r(2 * (f[2] * g[1] - f[1] * g[2])),
    ];
    let (w0, w1) = (w[0].clone(), w[1].clone());
    let three = r(3);
    check_septic_relations(
        &curve,
        [
            (h[1].clone() * w1.clone() + h[2].clone() * w0.clone())
                / (three.clone() * h[1].clone() * w0.clone()),
            h[0].clone() * w0.clone() / (three.clone() * h[1].clone() * w1.clone()),
            h[2].clone() * w1.clone() / (three.clone() * h[1].clone() * w0.clone()),
            (h[1].clone() * w0.clone() + h[0].clone() * w1.clone()) / (three * h[1].clone() * w1),
        ],
    );
}
