//! The conic-point engine (`X²L + Y²M + Z²N ≡ 0` over `Q[t]`, and `aX² + bY² + cZ² = 0` over
//! `Q`) against independent checks: exhaustive searches within proven bounds, families built
//! from a known point, and the sum-of-two-squares factorization over `Q(i)`.

use proptest::prelude::*;
use rcagd_algebra::conic_point::{
    certify_conic_point, certify_conic_point_ext, conic_point, rational_conic_point, ConicPoint,
    ConicPointError, Obstruction, Place, TernaryOutcome, MAX_FAMILY_DEGREE,
};
use rcagd_algebra::sum_of_squares::{sum_of_two_squares, SumOfSquares, SumOfSquaresError};
use rcagd_algebra::{Poly, Rational};

fn p(c: &[i64]) -> Poly<Rational> {
    Poly::from_ints(c)
}

/// An integer point of `ax² + by² + cz² = 0` with `0 < max |·| ≤ h` (brute force).
fn search_ternary(a: i64, b: i64, c: i64, h: i64) -> Option<(i64, i64, i64)> {
    for x in 0..=h {
        for y in -h..=h {
            for z in -h..=h {
                if (x, y, z) != (0, 0, 0) && a * x * x + b * y * y + c * z * z == 0 {
                    return Some((x, y, z));
                }
            }
        }
    }
    None
}

fn nonzero() -> impl Strategy<Value = i64> {
    prop_oneof![-12i64..=-1, 1i64..=12]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Legendre's theorem against exhaustive search: for `|a|, |b|, |c| ≤ 12` a solvable
    /// conic has a point with `|x| ≤ √|bc| ≤ 12` etc. (Holzer's bound), so a search up
    /// to 12 decides.
    #[test]
    fn ternary_agrees_with_search(a in nonzero(), b in nonzero(), c in nonzero()) {
        let found = search_ternary(a, b, c, 12);
        let out = rational_conic_point(&Rational::from(a), &Rational::from(b), &Rational::from(c))
            .expect("decided");
        match out {
            TernaryOutcome::Point(pt) => {
                prop_assert!(found.is_some(), "engine point but none by search: {a} {b} {c}");
                let s = Rational::from(a) * &pt[0] * &pt[0]
                    + Rational::from(b) * &pt[1] * &pt[1]
                    + Rational::from(c) * &pt[2] * &pt[2];
                prop_assert!(s.is_zero());
            }
            TernaryOutcome::NoPoint(place) => {
                prop_assert!(found.is_none(), "engine says none over {place} but {found:?}: {a} {b} {c}");
                if place == Place::Real {
                    prop_assert!((a > 0) == (b > 0) && (b > 0) == (c > 0));
                }
            }
        }
    }

    /// A family built from a known polynomial point: the engine must find a point.
    #[test]
    fn never_misses_a_point(
        x in prop::collection::vec(-4i64..=4, 1..4),
        y in prop::collection::vec(-4i64..=4, 1..4),
        z in prop::collection::vec(-4i64..=4, 1..3),
        l in prop::collection::vec(-5i64..=5, 1..4),
        m in prop::collection::vec(-5i64..=5, 1..4),
        n0 in prop::collection::vec(-3i64..=3, 1..3),
    ) {
        // N = (−X²L − Y²M)/Z² needs Z² | X²L + Y²M; take N = −(X²L + Y²M)·N0 and
        // scale L, M by Z²N0: X²(LZ²N0) + Y²(MZ²N0) + Z²·N = 0.
        let (x, y, z, l, m, n0) = (p(&x), p(&y), p(&z), p(&l), p(&m), p(&n0));
        prop_assume!(!z.is_zero() && !n0.is_zero() && !l.is_zero() && !m.is_zero());
        let n = -&(&(&(&x * &x) * &l) + &(&(&y * &y) * &m));
        prop_assume!(!n.is_zero());
        let z2 = &z * &z;
        let ll = &(&l * &z2) * &n0;
        let mm = &(&m * &z2) * &n0;
        let nn = &n * &n0;
        let coeffs = [ll.clone(), mm.clone(), nn.clone()];
        prop_assert!(certify_conic_point(&coeffs, &[x.clone(), y.clone(), z.clone()]).holds);
        let out = conic_point(&ll, &mm, &nn).expect("decided");
        match out {
            ConicPoint::Rational(pt) => prop_assert!(certify_conic_point(&coeffs, &pt).holds),
            other => prop_assert!(false, "missed a point: {other:?}"),
        }
    }

    /// The point is of least degree among those the method reaches: a family built from a
    /// random point `(X, Y, Z)` of degree `k` gets a certified point of degree `≤ k`
    /// (`L`, `M` random, `N = −(X²L + Y²M)/Z²` made polynomial by scaling `L`, `M` by `Z²`).
    #[test]
    fn families_from_a_point_of_degree_k_get_degree_at_most_k(
        x in prop::collection::vec(-6i64..=6, 1..4),
        y in prop::collection::vec(-6i64..=6, 1..4),
        z in prop::collection::vec(-3i64..=3, 1..3),
        l in prop::collection::vec(-9i64..=9, 1..5),
        m in prop::collection::vec(-9i64..=9, 1..5),
    ) {
        let (x, y, z, l, m) = (p(&x), p(&y), p(&z), p(&l), p(&m));
        prop_assume!(!z.is_zero() && !l.is_zero() && !m.is_zero());
        let pt0 = [x.clone(), y.clone(), z.clone()];
        let k = pt0.iter().filter_map(|q| q.degree()).max().unwrap_or(0);
        let n = -&(&(&(&x * &x) * &l) + &(&(&y * &y) * &m));
        prop_assume!(!n.is_zero());
        let z2 = &z * &z;
        let coeffs = [&l * &z2, &m * &z2, n];
        prop_assert!(certify_conic_point(&coeffs, &pt0).holds);
        let out = conic_point(&coeffs[0], &coeffs[1], &coeffs[2]).expect("decided");
        let ConicPoint::Rational(pt) = out else {
            return Err(TestCaseError::fail(format!("missed a point: {out:?}")));
        };
        prop_assert!(certify_conic_point(&coeffs, &pt).holds);
        let dg = pt.iter().filter_map(|q| q.degree()).max().unwrap_or(0);
        prop_assert!(dg <= k, "degree {dg} > {k}: {pt:?} for {coeffs:?} (built from {pt0:?})");
    }

    /// Random families: a point found by exhaustive search (degree ≤ 1, coefficients in
    /// −2..2) must be found by the engine; a point of the engine is certified; an
    /// obstruction at infinity over R means one sign of the leading coefficients.
    #[test]
    fn random_families_agree_with_search(
        l in prop::collection::vec(-3i64..=3, 1..4),
        m in prop::collection::vec(-3i64..=3, 1..4),
        n in prop::collection::vec(-3i64..=3, 1..4),
    ) {
        let (l, m, n) = (p(&l), p(&m), p(&n));
        prop_assume!(!l.is_zero() && !m.is_zero() && !n.is_zero());
        let coeffs = [l.clone(), m.clone(), n.clone()];
        let mut found = false;
        let r = -2i64..=2;
        'search: for x0 in r.clone() { for x1 in r.clone() { for y0 in r.clone() { for y1 in r.clone() {
            for z0 in r.clone() { for z1 in r.clone() {
                if (x0, x1, y0, y1, z0, z1) == (0, 0, 0, 0, 0, 0) { continue; }
                let pt = [p(&[x0, x1]), p(&[y0, y1]), p(&[z0, z1])];
                if certify_conic_point(&coeffs, &pt).holds { found = true; break 'search; }
            }}
        }}}}
        let out = conic_point(&l, &m, &n).expect("decided");
        match &out {
            ConicPoint::Rational(pt) => prop_assert!(certify_conic_point(&coeffs, pt).holds),
            ConicPoint::QuadraticField { point, .. } => {
                prop_assert!(!found, "a rational point exists: {out:?}");
                prop_assert!(certify_conic_point_ext(&coeffs, point).holds);
            }
            ConicPoint::NoPoint { obstruction, reduced } => {
                prop_assert!(!found, "a rational point exists: {out:?}");
                if let Obstruction::AtInfinity { place: Place::Real, .. } = obstruction {
                    let s: Vec<bool> = reduced.iter().map(|c| c.leading() > Rational::ZERO).collect();
                    prop_assert!(s[0] == s[1] && s[1] == s[2]);
                }
            }
        }
    }

    /// The special case `X² + Y² = D`: the factorization over `Q(i)` and the conic engine
    /// (local conditions + Legendre) agree on whether `D` is a sum of two rational squares.
    #[test]
    fn two_squares_agree(
        a in prop::collection::vec(-4i64..=4, 1..4),
        b in prop::collection::vec(-4i64..=4, 1..4),
        c in 1i64..=30,
        extra in prop::collection::vec(-3i64..=3, 0..3),
    ) {
        // D = c·(a² + b²)·e² with an extra factor e: a sum of two squares iff c is one
        let (a, b) = (p(&a), p(&b));
        let e = if extra.is_empty() { p(&[1]) } else { p(&extra) };
        prop_assume!(!e.is_zero());
        let d = &(&(&(&a * &a) + &(&b * &b)) * &(&e * &e)).scale(&Rational::from(c)) + &p(&[0]);
        prop_assume!(!d.is_zero());
        let sos = sum_of_two_squares(&d);
        let conic = conic_point(&p(&[1]), &p(&[1]), &-&d).expect("decided");
        let rational_sos = matches!(sos, Ok(SumOfSquares::Rational { .. }));
        if let Ok(s) = &sos { prop_assert!(s.verifies(&d)); }
        prop_assert!(!matches!(sos, Err(SumOfSquaresError::Negative(_))));
        prop_assert_eq!(rational_sos, conic.rational().is_some(), "D = {:?}", d);
    }
}

/// Input above the degree bound is refused with a named error, not attempted.
#[test]
fn degree_bound_is_a_named_error() {
    let big = Poly::new(
        (0..=(MAX_FAMILY_DEGREE as i64))
            .map(|k| Rational::from(k % 5 + 1))
            .collect(),
    );
    match conic_point(&big, &p(&[1]), &p(&[0, -1])) {
        Err(ConicPointError::TooLarge { degree, limit }) => {
            assert_eq!((degree, limit), (MAX_FAMILY_DEGREE + 1, MAX_FAMILY_DEGREE));
        }
        other => panic!("{other:?}"),
    }
    // at the bound it is attempted (X² − Y² = 0 has the point (1, 1, 0); N = t^198)
    let mut c = vec![Rational::ZERO; MAX_FAMILY_DEGREE - 1];
    c.push(Rational::ONE);
    let at = Poly::new(c);
    assert!(matches!(
        conic_point(&p(&[1]), &p(&[-1]), &at),
        Ok(ConicPoint::Rational(_))
    ));
}

#[test]
fn named_fields_and_obstructions() {
    // X² + Y² = 3(t² + 1)²·Z²: only over Q(√3) (obstruction at infinity, Q_3)
    let d = p(&[3, 0, 6, 0, 3]);
    let out = conic_point(&p(&[1]), &p(&[1]), &-&d).expect("decided");
    match out {
        ConicPoint::QuadraticField {
            radicand,
            point,
            obstruction: Obstruction::AtInfinity { place, .. },
        } => {
            assert_eq!(place, Place::Prime(3u8.into()));
            assert!(certify_conic_point_ext(&[p(&[1]), p(&[1]), -&d], &point).holds);
            assert!(
                radicand == Rational::from(3)
                    || radicand == Rational::ONE.clone() * Rational::from(3)
            );
        }
        o => panic!("{o:?}"),
    }
    // X² + Y² = (t² + 2)Z²: −1 is not a square in Q(√−2)
    let out = conic_point(&p(&[1]), &p(&[1]), &p(&[-2, 0, -1])).expect("decided");
    match out {
        ConicPoint::NoPoint {
            obstruction: Obstruction::Residue { factor, .. },
            ..
        } => assert_eq!(factor, p(&[2, 0, 1])),
        o => panic!("{o:?}"),
    }
}
