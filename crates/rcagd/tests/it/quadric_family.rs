//! Rational one-parameter families of quadrics in Pⁿ (Peternell, *Rational
//! Parametrizations for Envelopes of Quadric Families*, §5.1, Cor. 5.1, Prop. 5.1): a
//! polynomial point on every quadric and the stereographic parametrization g(t, u), the
//! named refusals, and random families built from a known point (never missed) with an f64
//! check of the exact certificate.

use proptest::prelude::*;
use rcagd::conic_surface::quadric_family::{diagonal_family, QuadricFamily, QuadricFamilyError};
use rcagd::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Poly, Rational, Scalar};

type Q = Rational;
type P = Poly<Q>;

fn p(c: &[i64]) -> P {
    Poly::from_ints(c)
}

fn check(fam: &QuadricFamily) -> rcagd::conic_surface::quadric_family::QuadricFamilyParam {
    let g = fam.parametrize().expect("a parametrization");
    let certs = g.certify();
    assert!(certs.iter().all(|c| c.holds), "{certs:?}");
    g
}

/// The §1.5 conic (1.35), `−x₀²(1+t²)²(t⁴+12t²+3)² + x₁² + x₂²(t⁴+18t²+5)(t⁴+6t²+1) = 0`,
/// as a family of conics in P² (n = 2): a point and the parametrization, degree 2 in u.
#[test]
fn conic_1_35_as_a_family_in_p2() {
    let a = p(&[1, 0, 1]);
    let b = p(&[3, 0, 12, 0, 1]);
    let l = -&(&(&a * &a) * &(&b * &b));
    let n = &p(&[5, 0, 18, 0, 1]) * &p(&[1, 0, 6, 0, 1]);
    let fam = QuadricFamily::new(diagonal_family(&[l, p(&[1]), n])).expect("family");
    assert_eq!(fam.dim(), 2);
    let g = check(&fam);
    assert_eq!(g.degree().1, 2);
}

/// (1.32): the regular quadric x₀² + x₁² + x₂² − x₃² = 0 (a sphere), constant in t: the
/// parametrization from the engine's point is certified and of degree 2 in (u₁, u₂).
#[test]
fn sphere_1_32() {
    let fam = QuadricFamily::new(diagonal_family(&[p(&[1]), p(&[1]), p(&[1]), p(&[-1])]))
        .expect("family");
    let g = check(&fam);
    assert_eq!(g.degree(), (0, 2));
    assert_eq!(g.map().len(), 4);
}

/// The rationality caveat of the seed's conventions: x² + y² = (t² + 2)z² has real points
/// for every t but no polynomial point over Q (t² + 2 takes the value 2 at t = 0 and 3 at
/// t = 1; the engine's obstruction is named).
#[test]
fn no_point_over_q_is_proven_for_conics() {
    let fam =
        QuadricFamily::new(diagonal_family(&[p(&[1]), p(&[1]), p(&[-2, 0, -1])])).expect("family");
    match fam.parametrize() {
        Err(QuadricFamilyError::NoRationalPoint(s)) => {
            assert!(s.contains("no point"), "{s}")
        }
        other => panic!("expected a proof of non-existence, got {other:?}"),
    }
    // the cones over that conic family in P³ (rank 3): still a proof
    let cone = QuadricFamily::new(diagonal_family(&[
        p(&[1]),
        p(&[1]),
        p(&[-2, 0, -1]),
        p(&[0]),
    ]))
    .expect("family");
    assert_eq!(cone.rank(), 3);
    assert!(matches!(
        cone.parametrize(),
        Err(QuadricFamilyError::NoRationalPoint(_))
    ));
}

/// A family with no real points at t = 0 is refused with the parameter named; rank 2
/// (pairs of planes) and a non-symmetric matrix are named errors.
#[test]
fn named_refusals() {
    let fam = QuadricFamily::new(diagonal_family(&[
        p(&[1]),
        p(&[1]),
        p(&[1, 0, -1]),
        p(&[0, 0, 1]),
    ]))
    .expect("family");
    // Q(0) = diag(1, 1, 1, 0) is only semidefinite, Q(1/2) = diag(1, 1, 3/4, 1/4) definite
    match fam.parametrize() {
        Err(QuadricFamilyError::NoRealPoints { t, sign }) => {
            assert_eq!(sign, "positive");
            let a = fam.at(&t);
            assert!(a.determinant().expect("square") > Q::ZERO);
        }
        other => panic!("expected NoRealPoints, got {other:?}"),
    }
    assert_eq!(
        QuadricFamily::new(diagonal_family(&[p(&[1]), p(&[0, 1]), p(&[0])])).err(),
        Some(QuadricFamilyError::Rank(2))
    );
    let mut m = diagonal_family(&[p(&[1]), p(&[1]), p(&[-1])]);
    m[0][1] = p(&[0, 1]);
    assert_eq!(
        QuadricFamily::new(m).err(),
        Some(QuadricFamilyError::NotSymmetric(0, 1))
    );
    assert!(matches!(
        QuadricFamily::new(vec![vec![p(&[1]), p(&[0])], vec![p(&[0]), p(&[-1])]]),
        Err(QuadricFamilyError::Shape(_))
    ));
}

/// A family in P⁴ that is not diagonal (a moving quadric cone of rank 4 plus mixed terms):
/// the point is regular and the map is certified.
#[test]
fn family_in_p4_with_mixed_terms() {
    // x₀x₁ + (1 + t²)x₂² − t·x₂x₃ + x₃² − (2 + t)²·x₄² (rank 5)
    let z = p(&[0]);
    let half = Poly::constant(Q::from_ratio(1, 2));
    let m = vec![
        vec![z.clone(), half.clone(), z.clone(), z.clone(), z.clone()],
        vec![half, z.clone(), z.clone(), z.clone(), z.clone()],
        vec![
            z.clone(),
            z.clone(),
            p(&[1, 0, 1]),
            Poly::new(vec![Q::ZERO, Q::from_ratio(-1, 2)]),
            z.clone(),
        ],
        vec![
            z.clone(),
            z.clone(),
            Poly::new(vec![Q::ZERO, Q::from_ratio(-1, 2)]),
            p(&[1]),
            z.clone(),
        ],
        vec![z.clone(), z.clone(), z.clone(), z.clone(), -&p(&[4, 4, 1])],
    ];
    let fam = QuadricFamily::new(m).expect("family");
    assert_eq!(fam.rank(), 5);
    let g = check(&fam);
    assert_eq!(g.map().len(), 5);
    assert_eq!(g.degree().1, 2);
}

fn poly_of(c: &[i64]) -> P {
    p(c)
}

/// `Aᵀ·D·A` for a polynomial matrix `A(t)` and a constant diagonal `D`.
fn congruent(a: &[Vec<P>], d: &[i64]) -> Vec<Vec<P>> {
    let n = a.len();
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    (0..n).fold(Poly::zero(), |acc, k| {
                        &acc + &(&a[k][i] * &a[k][j]).scale(&Q::from(d[k]))
                    })
                })
                .collect()
        })
        .collect()
}

fn f64_residual(
    g: &rcagd::conic_surface::quadric_family::QuadricFamilyParam,
    t: f64,
    u: &[f64],
) -> (f64, f64) {
    let mut x = vec![t];
    x.extend_from_slice(u);
    let gv: Vec<f64> = g
        .map()
        .iter()
        .map(|m| {
            let mf: MPoly<f64> = m.map(Scalar::to_f64);
            mf.eval(&x).expect("eval")
        })
        .collect();
    let q = g.family().matrix();
    let n = gv.len();
    let mut s = 0.0;
    let mut scale = 0.0;
    for i in 0..n {
        for j in 0..n {
            let qij = q[i][j].map(Scalar::to_f64).eval(&t);
            s += gv[i] * qij * gv[j];
            scale += (gv[i] * qij * gv[j]).abs();
        }
    }
    (s, scale)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// Families `Aᵀ·D·A` with `D` a regular quadric with a rational point (a sphere-like
    /// `(1, 1, …, −1)` or a split form) and a random polynomial `A(t)`: they have a point,
    /// which must never be missed, and the exact certificate agrees with an f64 evaluation.
    #[test]
    fn families_built_from_a_point_are_never_missed(
        n in 2usize..5,
        coeffs in proptest::collection::vec(-1i64..2, 25),
        diag_kind in 0usize..3,
        t in -2.0f64..2.0, u in proptest::collection::vec(-2.0f64..2.0, 3)
    ) {
        let size = n + 1;
        // A = I + t·B, B strictly upper triangular (det A = 1)
        let a: Vec<Vec<P>> = (0..size)
            .map(|i| {
                (0..size)
                    .map(|j| poly_of(&[i64::from(i == j), if j > i { coeffs[i * 5 + j] } else { 0 }]))
                    .collect()
            })
            .collect();
        let d: Vec<i64> = (0..size)
            .map(|i| match diag_kind {
                0 => if i + 1 == size { -1 } else { 1 },
                1 => if i % 2 == 0 { 1 } else { -1 },
                _ => if i == 0 { 2 } else if i + 1 == size { -1 } else { 1 + i as i64 },
            })
            .collect();
        // D has the rational points (1, 0, …, 0, 1), (1, 1, 0, …) and (1, 1, 0, …, 0, 2)
        let m = congruent(&a, &d);
        let fam = match QuadricFamily::new(m) {
            Ok(f) => f,
            Err(QuadricFamilyError::Rank(_)) => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
        };
        if fam.rank() < size {
            return Ok(());
        }
        let g = fam.parametrize();
        prop_assert!(g.is_ok(), "missed a point: {:?}", g.err());
        let g = g.expect("checked");
        let certs = g.certify();
        prop_assert!(certs.iter().all(|c| c.holds), "{certs:?}");
        let (s, scale) = f64_residual(&g, t, &u[..n - 1]);
        prop_assert!(s.abs() <= 1e-9 * scale.max(1.0), "f64 residual {s} (scale {scale})");
    }
}
