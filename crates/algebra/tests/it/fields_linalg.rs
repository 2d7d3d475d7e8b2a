//! Property tests for the exact number fields (`Q(√d)`, `Q(i)`, rational quaternions)
//! and for exact linear algebra, with random exact inputs; the `f64` versions are
//! checked against the exact results.

use dashu_int::IBig;
use num_traits::{One, Zero};
use proptest::prelude::*;
use rcagd_algebra::complex::{self, Complex};
use rcagd_algebra::linalg::{
    null_space_f64, rank_f64, solve_f64, solve_least_squares_f64, LinalgError, Matrix, Solution,
};
use rcagd_algebra::quadratic::{sqrt_in_extension, QuadExt};
use rcagd_algebra::quaternion::{self, Quaternion};
use rcagd_algebra::{Field, Poly, Rational, Ring, Scalar};
use std::cmp::Ordering;

// ------------------------------------------------------------------ strategies

fn q(p: i64, d: i64) -> Rational {
    Rational::from_parts_signed(IBig::from(p), IBig::from(d))
}

/// Small rationals `p/d`, `|p| ≤ 30`, `1 ≤ d ≤ 12`.
fn rat() -> impl Strategy<Value = Rational> + Clone {
    (-30i64..=30, 1i64..=12).prop_map(|(p, d)| q(p, d))
}

/// Small integers as rationals (for matrices whose f64 image is exact).
fn int() -> impl Strategy<Value = Rational> + Clone {
    (-5i64..=5).prop_map(Rational::from)
}

/// Square-free radicands.
fn radicand() -> impl Strategy<Value = Rational> {
    prop::sample::select(vec![2i64, 3, 5, 6, 7, 10, 11, 13, 15, 17, 19, 21, 1001])
        .prop_map(Rational::from)
}

fn quad_in(d: Rational) -> impl Strategy<Value = QuadExt> {
    (rat(), rat()).prop_map(move |(a, b)| QuadExt::new(a, b, d.clone()).expect("non-square d"))
}

/// Three elements of one random field `Q(√d)`.
fn quad_triple() -> impl Strategy<Value = (QuadExt, QuadExt, QuadExt)> {
    radicand().prop_flat_map(|d| (quad_in(d.clone()), quad_in(d.clone()), quad_in(d)))
}

/// Elements with heavy cancellation: `(a + b√d)^k` and its conjugate for `k ≤ 12`.
fn quad_hard() -> impl Strategy<Value = QuadExt> {
    (radicand(), -9i64..=9, -9i64..=9, 1u32..=12, any::<bool>()).prop_map(|(d, a, b, k, c)| {
        let base = QuadExt::new(Rational::from(a), Rational::from(b), d).expect("non-square d");
        let mut x = QuadExt::one();
        for _ in 0..k {
            x *= base.clone();
        }
        if c {
            x.conj()
        } else {
            x
        }
    })
}

fn complex() -> impl Strategy<Value = Complex<Rational>> {
    (rat(), rat()).prop_map(|(re, im)| Complex::new(re, im))
}

fn quat() -> impl Strategy<Value = Quaternion<Rational>> {
    (rat(), rat(), rat(), rat()).prop_map(|(w, x, y, z)| Quaternion::new(w, x, y, z))
}

fn quat_poly() -> impl Strategy<Value = Poly<Quaternion<Rational>>> {
    prop::collection::vec(quat(), 1..=3).prop_map(Poly::new)
}

fn matrix_of(
    rows: usize,
    cols: usize,
    entry: impl Strategy<Value = Rational> + Clone,
) -> impl Strategy<Value = Matrix<Rational>> {
    prop::collection::vec(entry, rows * cols)
        .prop_map(move |data| Matrix::from_vec(rows, cols, data).expect("sized"))
}

fn square(
    entry: impl Strategy<Value = Rational> + Clone + 'static,
) -> BoxedStrategy<Matrix<Rational>> {
    (1usize..=4)
        .prop_flat_map(move |n| matrix_of(n, n, entry.clone()))
        .boxed()
}

/// A random `m × n` matrix of rank at most `r` (a product `m×r · r×n`), so that
/// kernels and underdetermined systems occur often.
fn low_rank(
    entry: impl Strategy<Value = Rational> + Clone + 'static,
) -> BoxedStrategy<Matrix<Rational>> {
    (1usize..=4, 1usize..=4, 1usize..=3)
        .prop_flat_map(move |(m, n, r)| {
            (
                matrix_of(m, r, entry.clone()),
                matrix_of(r, n, entry.clone()),
            )
        })
        .prop_map(|(a, b)| a.mul(&b).expect("inner dimensions agree"))
        .boxed()
}

fn any_matrix(
    entry: impl Strategy<Value = Rational> + Clone + 'static,
) -> BoxedStrategy<Matrix<Rational>> {
    prop_oneof![
        (1usize..=4, 1usize..=4).prop_flat_map(move |(m, n)| matrix_of(m, n, entry.clone())),
        low_rank(int()),
    ]
    .boxed()
}

// ------------------------------------------------------------------ helpers

/// Laplace (cofactor) expansion along the first row: an independent determinant.
fn det_cofactor(a: &[Vec<Rational>]) -> Rational {
    let n = a.len();
    if n == 0 {
        return Rational::ONE;
    }
    let mut acc = Rational::ZERO;
    for j in 0..n {
        let minor: Vec<Vec<Rational>> = a[1..]
            .iter()
            .map(|r| {
                r.iter()
                    .enumerate()
                    .filter(|&(k, _)| k != j)
                    .map(|(_, v)| v.clone())
                    .collect()
            })
            .collect();
        let term = &a[0][j] * det_cofactor(&minor);
        if j % 2 == 0 {
            acc += term;
        } else {
            acc -= term;
        }
    }
    acc
}

fn rows(m: &Matrix<Rational>) -> Vec<Vec<Rational>> {
    m.row_iter().map(<[Rational]>::to_vec).collect()
}

fn is_zero_vec(v: &[Rational]) -> bool {
    v.iter().all(Zero::is_zero)
}

fn next_up(x: f64) -> f64 {
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let b = x.to_bits();
    f64::from_bits(if x > 0.0 { b + 1 } else { b - 1 })
}

fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

fn exact(x: f64) -> QuadExt {
    QuadExt::rational(Rational::try_from(x).expect("finite"))
}

fn cfg(cases: u32) -> ProptestConfig {
    ProptestConfig::with_cases(cases)
}

// ------------------------------------------------------------------ Q(√d)

proptest! {
    #![proptest_config(cfg(48))]

    #[test]
    fn quad_field_axioms((x, y, z) in quad_triple()) {
        prop_assert_eq!((x.clone() + y.clone()) + z.clone(), x.clone() + (y.clone() + z.clone()));
        prop_assert_eq!((x.clone() * y.clone()) * z.clone(), x.clone() * (y.clone() * z.clone()));
        prop_assert_eq!(x.clone() * y.clone(), y.clone() * x.clone());
        prop_assert_eq!(
            x.clone() * (y.clone() + z.clone()),
            x.clone() * y.clone() + x.clone() * z.clone()
        );
        prop_assert!((x.clone() - x.clone()).is_zero());
        prop_assert_eq!(x.clone() + QuadExt::zero(), x.clone());
        prop_assert_eq!(x.clone() * QuadExt::one(), x.clone());
        // norm and conjugation are multiplicative
        prop_assert_eq!((x.clone() * y.clone()).norm(), x.norm() * y.norm());
        prop_assert_eq!((x.clone() * y.clone()).conj(), x.conj() * y.conj());
        match x.inv() {
            Some(inv) => {
                prop_assert_eq!(x.clone() * inv, QuadExt::one());
                prop_assert_eq!((y.clone() / x.clone()) * x.clone(), y.clone());
            }
            None => prop_assert!(x.is_zero()),
        }
        // checked operations agree with the operators inside one field
        prop_assert_eq!(x.checked_mul(&y).expect("same field"), x.clone() * y.clone());
        prop_assert_eq!(x.checked_sub(&y).expect("same field"), x.clone() - y.clone());
    }

    #[test]
    fn quad_rational_embedding_adopts_field((x, _, _) in quad_triple(), r in rat()) {
        let qr = QuadExt::rational(r.clone());
        let s = qr.clone() + x.clone();
        prop_assert_eq!(s.clone() - x.clone(), qr.clone());
        prop_assert!(s.same_field(&x));
        let prod = qr.clone() * x.clone();
        prop_assert_eq!(prod.b(), &(r * x.b()));
    }

    #[test]
    fn quad_order_agrees_with_f64((x, y, _) in quad_triple(), w in quad_in(Rational::from(3))) {
        for (u, v) in [(&x, &y), (&x, &w)] {
            let (fu, fv) = (Scalar::to_f64(u), Scalar::to_f64(v));
            if (fu - fv).abs() > 1e-9 * (1.0 + fu.abs() + fv.abs()) {
                prop_assert_eq!(u < v, fu < fv, "{} vs {}", u, v);
                prop_assert_eq!(u.partial_cmp(v), fu.partial_cmp(&fv));
            }
            // antisymmetry and consistency with equality, also across fields
            prop_assert_eq!(u.cmp(v), v.cmp(u).reverse());
            prop_assert_eq!(u.cmp(v) == Ordering::Equal, u == v);
        }
        prop_assert_eq!(Scalar::abs(&x) >= QuadExt::zero(), true);
        prop_assert_eq!(x.sign(), x.cmp(&QuadExt::zero()));
    }

    #[test]
    fn quad_to_f64_is_correctly_rounded(x in prop_oneof![quad_hard(), quad_triple().prop_map(|t| t.0)]) {
        let v = Scalar::to_f64(&x);
        prop_assert!(v.is_finite());
        if v == 0.0 {
            prop_assert!(x.is_zero());
        } else {
            // x lies between the midpoints to the neighbouring doubles (≤ ½ ulp)
            let two = QuadExt::from(2);
            let lo = (exact(next_down(v)) + exact(v)) / two.clone();
            let hi = (exact(v) + exact(next_up(v))) / two;
            prop_assert!(lo <= x && x <= hi, "to_f64({}) = {:e}", x, v);
        }
    }

    #[test]
    fn sqrt_in_extension_squares_back(r in rat(), s in 0i64..=20) {
        let qv = &r * &r * Rational::from(s);
        let root = sqrt_in_extension(&qv).expect("non-negative");
        prop_assert_eq!(root.clone() * root.clone(), QuadExt::rational(qv.clone()));
        prop_assert!(root >= QuadExt::zero());
        // a common field for q and q/9
        let other = sqrt_in_extension(&(qv / Rational::from(9))).expect("non-negative");
        prop_assert!(root.same_field(&other));
        prop_assert_eq!(other * QuadExt::from(3), root);
    }
}

// ------------------------------------------------------------------ Q(i)

proptest! {
    #![proptest_config(cfg(48))]

    #[test]
    fn complex_field_axioms(x in complex(), y in complex(), z in complex()) {
        prop_assert_eq!((x.clone() + y.clone()) + z.clone(), x.clone() + (y.clone() + z.clone()));
        prop_assert_eq!((x.clone() * y.clone()) * z.clone(), x.clone() * (y.clone() * z.clone()));
        prop_assert_eq!(x.clone() * y.clone(), y.clone() * x.clone());
        prop_assert_eq!(
            x.clone() * (y.clone() + z.clone()),
            x.clone() * y.clone() + x.clone() * z.clone()
        );
        prop_assert_eq!((x.clone() * y.clone()).norm_sq(), x.norm_sq() * y.norm_sq());
        prop_assert_eq!((x.clone() * y.clone()).conj(), x.conj() * y.conj());
        match x.inv() {
            Some(inv) => {
                prop_assert_eq!(x.clone() * inv, Complex::one());
                prop_assert_eq!((y.clone() / x.clone()) * x.clone(), y);
            }
            None => prop_assert!(x.is_zero()),
        }
    }

    #[test]
    fn complex_over_quadratic_field((a, b, c) in quad_triple()) {
        let z = Complex::new(a, b);
        let w = Complex::new(c.clone(), c);
        if let Some(inv) = z.inv() {
            prop_assert_eq!(z.clone() * inv, Complex::one());
        }
        prop_assert_eq!((z.clone() * w.clone()).norm_sq(), z.norm_sq() * w.norm_sq());
    }

    #[test]
    fn complex_poly_norm(p in prop::collection::vec(complex(), 0..=4)) {
        let p = Poly::new(p);
        let n = complex::norm_sq_poly(&p);
        let prod = &p * &complex::conj_poly(&p);
        prop_assert_eq!(prod, n.map(|c| Complex::from_real(c.clone())));
        let (re, im) = complex::re_im_polys(&p);
        prop_assert_eq!(complex::from_re_im_polys(&re, &im), p);
    }
}

// ------------------------------------------------------------------ quaternions

proptest! {
    #![proptest_config(cfg(48))]

    #[test]
    fn quaternion_ring_laws(p in quat(), r in quat(), s in quat()) {
        prop_assert_eq!((p.clone() * r.clone()) * s.clone(), p.clone() * (r.clone() * s.clone()));
        prop_assert_eq!(
            p.clone() * (r.clone() + s.clone()),
            p.clone() * r.clone() + p.clone() * s.clone()
        );
        prop_assert_eq!(
            (r.clone() + s.clone()) * p.clone(),
            r.clone() * p.clone() + s.clone() * p.clone()
        );
        prop_assert_eq!((p.clone() * r.clone()).norm_sq(), p.norm_sq() * r.norm_sq());
        prop_assert_eq!((p.clone() * r.clone()).conj(), r.conj() * p.conj());
        prop_assert_eq!(p.clone() * p.conj(), Quaternion::from_real(p.norm_sq()));
        match p.inverse() {
            Some(inv) => {
                prop_assert_eq!(p.clone() * inv.clone(), Quaternion::one());
                prop_assert_eq!(inv * p.clone(), Quaternion::one());
            }
            None => prop_assert!(p.is_zero()),
        }
    }

    #[test]
    fn ph_hodograph_identity(a in quat_poly(), u in (rat(), rat(), rat())) {
        // r' = A i A* is a pure vector with |r'|² = |A|⁴ (the PH certificate of docs/math/ph-curves.md)
        let r = quaternion::sandwich_i(&a);
        prop_assert!(quaternion::scalar_poly(&r).is_zero());
        let [x, y, z] = quaternion::vector_polys(&r);
        let sigma = quaternion::norm_sq_poly(&a);
        prop_assert_eq!(&(&(&x * &x) + &(&y * &y)) + &(&z * &z), &sigma * &sigma);
        prop_assert_eq!(quaternion::sandwich(&a, &Quaternion::i()), r);
        // general pure u: A u A* pure, |A u A*|² = |A|⁴ |u|²
        let uq = Quaternion::from_vector([u.0, u.1, u.2]);
        let ru = quaternion::sandwich(&a, &uq);
        prop_assert!(quaternion::scalar_poly(&ru).is_zero());
        let [x, y, z] = quaternion::vector_polys(&ru);
        let lhs = &(&(&x * &x) + &(&y * &y)) + &(&z * &z);
        prop_assert_eq!(lhs, (&sigma * &sigma).scale(&uq.norm_sq()));
        // A A* = |A|² as polynomials
        let aa = &a * &quaternion::conj_poly(&a);
        prop_assert_eq!(aa, sigma.map(|c| Quaternion::from_real(c.clone())));
    }
}

// ------------------------------------------------------------------ linear algebra

proptest! {
    #![proptest_config(cfg(48))]

    #[test]
    fn determinant_methods_agree(a in square(rat())) {
        let d = a.determinant().expect("square");
        prop_assert_eq!(&d, &det_cofactor(&rows(&a)));
        prop_assert_eq!(&d, &a.determinant_integral().expect("square"));
        prop_assert_eq!(&d, &a.transpose().determinant().expect("square"));
        prop_assert_eq!(d.is_zero(), a.rank() < a.rows());
        match a.inverse() {
            Ok(inv) => {
                prop_assert!(!d.is_zero());
                prop_assert_eq!(a.mul(&inv).expect("square"), Matrix::identity(a.rows()));
                prop_assert_eq!(inv.determinant().expect("square") * d, Rational::ONE);
            }
            Err(e) => {
                prop_assert!(d.is_zero());
                prop_assert!(matches!(e, LinalgError::Singular { .. }), "unexpected error");
            }
        }
    }

    #[test]
    fn determinant_is_multiplicative(
        (a, b) in (1usize..=4).prop_flat_map(|n| (matrix_of(n, n, rat()), matrix_of(n, n, rat())))
    ) {
        let ab = a.mul(&b).expect("same size");
        prop_assert_eq!(
            ab.determinant().expect("square"),
            a.determinant().expect("square") * b.determinant().expect("square")
        );
    }

    #[test]
    fn solve_results_satisfy_system(a in any_matrix(rat()), seed in prop::collection::vec(rat(), 4)) {
        let n = a.cols();
        let rank = a.rank();
        // a consistent right-hand side b = A x₀ and an arbitrary one
        let x0: Vec<Rational> = seed.iter().take(n).cloned().collect();
        let b_cons = a.mul_vec(&x0).expect("length n");
        let b_any: Vec<Rational> = seed.iter().cycle().take(a.rows()).cloned().collect();
        for (b, must_solve) in [(b_cons, true), (b_any, false)] {
            let sol = a.solve(&b).expect("length m");
            match &sol {
                Solution::Unique(x) => {
                    prop_assert_eq!(rank, n);
                    prop_assert_eq!(a.mul_vec(x).expect("length n"), b.clone());
                }
                Solution::Underdetermined { particular, null_space } => {
                    prop_assert!(rank < n);
                    prop_assert_eq!(a.mul_vec(particular).expect("length n"), b.clone());
                    prop_assert_eq!(null_space.len(), n - rank);
                    for v in null_space {
                        prop_assert!(is_zero_vec(&a.mul_vec(v).expect("length n")));
                    }
                }
                Solution::Inconsistent => {
                    prop_assert!(!must_solve);
                    // b is not in the column space: rank [A | b] = rank A + 1
                    let aug = Matrix::from_fn(a.rows(), n + 1, |i, j| {
                        if j < n { a.get(i, j).cloned().unwrap_or_default() } else { b[i].clone() }
                    });
                    prop_assert_eq!(aug.rank(), rank + 1);
                }
            }
        }
    }

    #[test]
    fn null_space_and_rank(a in any_matrix(rat())) {
        let ns = a.null_space();
        let rank = a.rank();
        prop_assert_eq!(rank + ns.len(), a.cols());
        for v in &ns {
            prop_assert!(is_zero_vec(&a.mul_vec(v).expect("length cols")));
        }
        if !ns.is_empty() {
            let nm = Matrix::from_columns(a.cols(), &ns).expect("columns of length cols");
            prop_assert!(a.mul(&nm).expect("cols × nullity").is_zero());
            prop_assert_eq!(nm.rank(), ns.len()); // a basis: independent
        }
        let (r, pivots) = a.rref();
        prop_assert_eq!(pivots.len(), rank);
        prop_assert_eq!(r.rref().0, r.clone());
        prop_assert_eq!(a.transpose().rank(), rank);
    }

    #[test]
    fn f64_versions_agree_with_exact(a in any_matrix(int()), b in prop::collection::vec(int(), 4)) {
        let af = a.to_f64();
        let rank = a.rank();
        prop_assert_eq!(rank_f64(&af, 1e-12).expect("finite"), rank);
        let nsf = null_space_f64(&af, 1e-12).expect("finite");
        prop_assert_eq!(nsf.len(), a.cols() - rank);
        for v in &nsf {
            let av = af.mul_vec(v).expect("length cols");
            prop_assert!(av.iter().all(|x| x.abs() < 1e-9), "A·v = {:?}", av);
        }
        if a.is_square() {
            let bq: Vec<Rational> = b.iter().take(a.rows()).cloned().collect();
            let bf: Vec<f64> = bq.iter().map(Scalar::to_f64).collect();
            match a.solve_unique(&bq) {
                Ok(x) => {
                    let xf = solve_f64(&af, &bf).expect("regular");
                    for (e, f) in x.iter().zip(&xf) {
                        let e = Scalar::to_f64(e);
                        prop_assert!((e - f).abs() <= 1e-6 * (1.0 + e.abs()), "{} vs {}", e, f);
                    }
                    let xl = solve_least_squares_f64(&af, &bf, 1e-12).expect("finite");
                    for (e, f) in x.iter().zip(&xl) {
                        let e = Scalar::to_f64(e);
                        prop_assert!((e - f).abs() <= 1e-6 * (1.0 + e.abs()), "{} vs {}", e, f);
                    }
                }
                Err(_) => prop_assert!(rank < a.rows()),
            }
        }
    }
}

#[test]
fn dimension_errors_are_typed() {
    let a = Matrix::from_rows(vec![vec![q(1, 1), q(2, 1)]]).expect("1×2");
    assert!(matches!(
        a.solve(&[q(1, 1), q(1, 1)]),
        Err(LinalgError::DimensionMismatch { .. })
    ));
    assert!(matches!(a.inverse(), Err(LinalgError::NotSquare { .. })));
    assert!(matches!(
        a.mul(&a),
        Err(LinalgError::DimensionMismatch { .. })
    ));
    assert!(matches!(
        solve_f64(&a.to_f64(), &[1.0]),
        Err(LinalgError::NotSquare { .. })
    ));
    let e: rcagd_algebra::AlgebraError = LinalgError::Singular { op: "x" }.into();
    assert!(matches!(e, rcagd_algebra::AlgebraError::DivisionByZero(_)));
}

#[test]
fn quadratic_ring_generic_use() {
    // QuadExt works as a Scalar in generic code: evaluate t² − 2 at √2.
    fn eval<S: Scalar>(t: S) -> S {
        t.clone() * t - S::from_i64(2)
    }
    let s2 = QuadExt::sqrt_d(&Rational::from(2)).expect("non-square");
    assert!(eval(s2).is_zero());
    let p: Poly<QuadExt> = Poly::from_ints(&[-2, 0, 1]);
    let s8 = QuadExt::sqrt_d(&Rational::from(8)).expect("non-square");
    assert_eq!(p.eval(&(s8 / QuadExt::from(2))), QuadExt::zero());
    assert_eq!(<QuadExt as Ring>::from_i64(3), QuadExt::from(3));
}
