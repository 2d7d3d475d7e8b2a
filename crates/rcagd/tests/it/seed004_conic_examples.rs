//! Peternell, *Rational Parametrizations for Envelopes of Quadric Families*, chapters 1, 2
//! and §5.1 (conic surfaces, envelopes of quadratic cones, rational points on conic
//! families): the printed examples reproduced exactly over Q (corrected where the printed
//! formula is wrong; see docs/math/conic-surfaces.md), and the callers of the
//! sum-of-squares engine.

use rcagd::canal::{sum_of_two_squares, CanalError, SumOfSquares};
use rcagd::pn::ruled::{find_two_squares, CanalPn, CycleFamily};
use rcagd::pn::PnError;
use rcagd::Certified;
use rcagd_algebra::conic_point::{certify_conic_point, conic_point, ConicPoint};
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Poly, Rational};

type Q = Rational;

fn p(c: &[i64]) -> Poly<Q> {
    Poly::from_ints(c)
}
fn t_() -> MPoly<Q> {
    MPoly::var(2, 0)
}
fn k(c: Q) -> MPoly<Q> {
    MPoly::constant(2, c)
}

/// (1.35): `−x₀²(1+t²)²(t⁴+12t²+3)² + x₁² + x₂²(t⁴+18t²+5)(t⁴+6t²+1) = 0`. The printed
/// solution `(1, (1+t²)(6t²+2), 1+t²)` satisfies it, and the engine finds a point itself.
#[test]
fn ch1_conic_1_35_point() {
    let a = p(&[1, 0, 1]);
    let b = p(&[3, 0, 12, 0, 1]);
    let l = -&(&(&a * &a) * &(&b * &b));
    let n = &p(&[5, 0, 18, 0, 1]) * &p(&[1, 0, 6, 0, 1]);
    let coeffs = [l.clone(), p(&[1]), n.clone()];
    let printed = [p(&[1]), &a * &p(&[2, 0, 6]), a.clone()];
    assert!(certify_conic_point(&coeffs, &printed).holds);
    let out = conic_point(&l, &p(&[1]), &n).expect("decided");
    let pt = out.rational().expect("a rational point");
    assert!(certify_conic_point(&coeffs, pt).holds);
    // degree bound of the engine (docs/math/conic-surfaces.md): the reduced family is
    // (−1, 1, N) with deg N = 8, so deg ≤ 8/2 = 4 there, and the square factor
    // (1+t²)(t⁴+12t²+3) of L (degree 6) multiplies Y and Z: at most 10 (the printed
    // solution has degree 4; the engine does not minimise the degree)
    let dmax = pt.iter().filter_map(|x| x.degree()).max().unwrap_or(0);
    assert!(dmax <= 10, "degree {dmax}");
}

/// The sum-of-two-squares callers use one engine: `t² + 9` (which the earlier search of
/// the PN module missed) is `t² + 3²` for both.
#[test]
fn two_squares_callers_agree() {
    let d = p(&[9, 0, 1]);
    let s = sum_of_two_squares(&d).expect("sos");
    assert!(matches!(s, SumOfSquares::Rational { .. }) && s.verifies(&d));
    let t = t_();
    let dm = &(&t * &t) + &k(Q::from(9));
    let [a, b] = find_two_squares(&dm).expect("found");
    let lhs = &(&a.num * &a.num) * &(&b.den * &b.den);
    let lhs = &lhs + &(&(&b.num * &b.num) * &(&a.den * &a.den));
    let rhs = &dm * &(&(&a.den * &a.den) * &(&b.den * &b.den));
    assert_eq!(lhs, rhs);
    // the conic engine agrees: X² + Y² = (t² + 9)Z²
    assert!(matches!(
        conic_point(&p(&[1]), &p(&[1]), &-&d).expect("decided"),
        ConicPoint::Rational(_)
    ));
    // not a sum of two squares: the canal error names the extension
    assert!(matches!(
        sum_of_two_squares(&p(&[2, 0, 0, 0, 1])),
        Err(CanalError::NeedsLargerExtension(_))
    ));
}

/// Regression: the PN canal surface of the spine `(5t, t²/2, 0)` with radius `r = 1 + 4t`
/// (`|m′|² − r′² = t² + 9`) was refused; it is built and certified now.
#[test]
fn pn_canal_t2_plus_9() {
    let t = t_();
    let half = Q::from_parts(1.into(), 2u8.into());
    let fam = CycleFamily::new(
        [t.scale(&Q::from(5)), (&t * &t).scale(&half), k(Q::ZERO)],
        &k(Q::ONE) + &t.scale(&Q::from(4)),
        k(Q::ONE),
    )
    .expect("family");
    let canal = CanalPn::new(fam, None).expect("t² + 9 is a sum of two squares");
    let certs = canal.certify();
    assert!(!certs.is_empty());
    for c in &certs {
        assert!(c.holds && c.exact, "{c}");
    }
}

/// A canal family whose `|m′|² − r′² = 3` is no sum of two rational squares: the error
/// names the spine/radius expression and the field it needs, and no parameter that the
/// `pn_canal` op does not have.
#[test]
fn pn_canal_refusal_message() {
    let t = t_();
    let fam = CycleFamily::new(
        [t.scale(&Q::from(2)), k(Q::ZERO), k(Q::ZERO)],
        t.clone(),
        k(Q::ONE),
    )
    .expect("family");
    match CanalPn::new(fam, None) {
        Err(PnError::NoRationalPoint(m)) => {
            assert!(m.contains("|m′(t)|² − r′(t)²"), "{m}");
            assert!(m.contains("Q(√3)"), "{m}");
            assert!(
                !m.contains("pass") && !m.contains("NOTES") && !m.contains("seed"),
                "{m}"
            );
        }
        Err(e) => panic!("{e}"),
        Ok(_) => panic!("3 is not a sum of two rational squares"),
    }
}
