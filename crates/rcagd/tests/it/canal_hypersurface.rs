//! The Möbius model (Peternell, *Rational Parametrizations for Envelopes of Quadric
//! Families*, (2.12), (2.13)), Thm 2.3 from a curve of P⁴, and canal hypersurfaces of Rⁿ
//! (the remark after Thm 2.3, Cor. 2.3) through §5.1.

use rcagd::conic_surface::cones::CanalViaCones;
use rcagd::conic_surface::mobius::{canal_from_mobius_curve, mobius_spheres, CanalHypersurface};
use rcagd::conic_surface::quadric_family::QuadricFamilyError;
use rcagd::Certified;
use rcagd_algebra::{Poly, Rational, Scalar};

type Q = Rational;
type P = Poly<Q>;

fn p(c: &[i64]) -> P {
    Poly::from_ints(c)
}

fn q(a: i64, b: i64) -> Q {
    Q::from_ratio(a, b)
}

/// (2.13) against its definition: the sphere μ(p) is the stereographic image (from the
/// north pole N = (1, 0, …, 0, 1)) of Q ∩ (polar hyperplane of p). For p = (1, 1, 1, 0, 0):
/// centre (1, 1, 0), radius² 1; the points x of Q with −p₀x₀ + p₁x₁ + … = 0 below map to
/// yᵢ = xᵢ/(x₀ − x₄) on that sphere.
#[test]
fn mobius_2_13_against_the_polar_hyperplane() {
    let c: Vec<P> = [1, 1, 1, 0, 0].iter().map(|&k| p(&[k])).collect();
    let (m, r, w) = mobius_spheres(&c).expect("sphere");
    assert_eq!(w, p(&[1]));
    assert_eq!(m, vec![p(&[1]), p(&[1]), p(&[0])]);
    assert_eq!(r, p(&[1]));
    // points of Q (−x₀² + x₁² + x₂² + x₃² + x₄² = 0) on the polar hyperplane
    // −x₀ + x₁ + x₂ = 0 (both checked below)
    for x in [
        [1i64, 1, 0, 0, 0],
        [1, 0, 1, 0, 0],
        [3, 2, 1, 2, 0],
        [3, 1, 2, 0, 2],
    ] {
        let on_q = -x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3] + x[4] * x[4];
        assert_eq!(on_q, 0);
        assert_eq!(-x[0] + x[1] + x[2], 0);
        let d = x[0] - x[4];
        let y: Vec<Q> = (1..4).map(|i| q(x[i], d)).collect();
        let centre = [q(1, 1), q(1, 1), q(0, 1)];
        let dist: Q = (0..3).fold(Q::ZERO, |acc, i| {
            let e = &y[i] - &centre[i];
            acc + &e * &e
        });
        assert_eq!(dist, Q::ONE, "x = {x:?}");
    }
}

/// Thm 2.3: the curve c(t) = (t²/4, t, 0, 0, t²/4 − 1) of P⁴ is the sphere family with
/// centres (t, 0, 0) and r² = 1 + t²/2 (r irrational); its canal surface is certified by
/// both constructions (cones of revolution, and §5.1 on the characteristic circles).
#[test]
fn theorem_2_3_from_a_curve_in_p4() {
    let c = vec![
        Poly::new(vec![Q::ZERO, Q::ZERO, q(1, 4)]),
        p(&[0, 1]),
        p(&[0]),
        p(&[0]),
        Poly::new(vec![Q::from(-1), Q::ZERO, q(1, 4)]),
    ];
    let (m, r, w) = mobius_spheres(&c).expect("spheres");
    assert_eq!(w, p(&[1]));
    assert_eq!(r, Poly::new(vec![Q::ONE, Q::ZERO, q(1, 2)]));
    let canal = canal_from_mobius_curve(&c).expect("canal");
    assert!(canal.all_hold(), "{:?}", canal.certify());
    assert_eq!(canal.dim(), 3);
    assert_eq!(canal.degree().1, 2);
    let cones =
        CanalViaCones::new([m[0].clone(), m[1].clone(), m[2].clone()], r, w).expect("cones");
    assert!(cones.all_hold());
}

/// Cor. 2.3 in R⁴ and R⁵: centres on (t, t², 0, 0) with r² = 1 (a pipe) and on
/// (t, 0, 0, 0, 0) with r² = 1 + t²/2 (a hyperboloid of revolution in R⁵): certified, degree
/// 2 in u; a point evaluated in f64 lies on its sphere.
#[test]
fn canal_hypersurfaces_in_r4_and_r5() {
    let pipe = CanalHypersurface::new(
        vec![p(&[0, 1]), p(&[0, 0, 1]), p(&[0]), p(&[0])],
        p(&[1]),
        p(&[1]),
    )
    .expect("pipe");
    assert!(pipe.all_hold(), "{:?}", pipe.certify());
    assert_eq!(pipe.point().len(), 5);
    let y: Vec<f64> = pipe
        .point()
        .iter()
        .map(|c| c.map(Scalar::to_f64).eval(&[0.3, -0.7, 1.1]).expect("eval"))
        .collect();
    let (t, y0) = (0.3f64, y[0]);
    let d2 = (y[1] / y0 - t).powi(2)
        + (y[2] / y0 - t * t).powi(2)
        + (y[3] / y0).powi(2)
        + (y[4] / y0).powi(2);
    assert!((d2 - 1.0).abs() < 1e-9, "|y − m|² = {d2}");
    let hyp = CanalHypersurface::new(
        vec![p(&[0, 1]), p(&[0]), p(&[0]), p(&[0]), p(&[0])],
        Poly::new(vec![Q::ONE, Q::ZERO, q(1, 2)]),
        p(&[1]),
    )
    .expect("R⁵");
    assert!(hyp.all_hold(), "{:?}", hyp.certify());
    assert_eq!(hyp.degree().1, 2);
}

#[test]
fn named_refusals() {
    // c₀ ≡ c₄: hyperplanes
    let c = vec![p(&[1, 1]), p(&[0, 1]), p(&[0]), p(&[0]), p(&[1, 1])];
    assert!(matches!(
        mobius_spheres(&c),
        Err(QuadricFamilyError::Degenerate(_))
    ));
    assert!(matches!(
        mobius_spheres(&c[..3]),
        Err(QuadricFamilyError::Shape(_))
    ));
    // centres that do not move
    assert!(matches!(
        CanalHypersurface::new(
            vec![p(&[1]), p(&[0]), p(&[0]), p(&[0])],
            p(&[0, 1]),
            p(&[1])
        ),
        Err(QuadricFamilyError::Degenerate(_))
    ));
    // |ṁ|² − ṙ² < 0 everywhere: spheres growing faster than they move have no real
    // characteristic sphere (r = 2t, m = (t, 0, 0, 0)): Q(t) is definite
    assert!(matches!(
        CanalHypersurface::new(
            vec![p(&[0, 1]), p(&[0]), p(&[0]), p(&[0])],
            p(&[0, 0, 4]),
            p(&[1])
        ),
        Err(QuadricFamilyError::NoRealPoints { .. })
    ));
    // n = 2 is not a hypersurface family of this kind
    assert!(matches!(
        CanalHypersurface::new(vec![p(&[0, 1]), p(&[0])], p(&[1]), p(&[1])),
        Err(QuadricFamilyError::Shape(_))
    ));
}
