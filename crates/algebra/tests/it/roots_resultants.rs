//! Cross-checks of gcd, resultants, real-root isolation and multivariate polynomials.
//!
//! The library isolates roots with Descartes' rule in the Bernstein basis and computes
//! resultants by the subresultant PRS; the independent checks here are Sturm sequences
//! (root counts), fraction-free Bareiss elimination on the Sylvester matrix
//! (resultants), and the product formula `Res(p, q) = lc(p)ⁿ lc(q)ᵐ ∏(αᵢ − βⱼ)` for
//! polynomials built from known linear factors.

use dashu_int::{IBig, UBig};
use num_traits::{One, Zero};
use proptest::prelude::*;
use rcagd_algebra::mpoly::{resultant_in, MPoly};
use rcagd_algebra::resultant::{
    discriminant, resultant, resultant_formal, resultant_poly, sylvester_matrix,
    sylvester_matrix_formal,
};
use rcagd_algebra::roots::{
    count_real_roots_in, isolate_real_roots, isolate_real_roots_in,
    isolate_real_roots_with_multiplicity, rational_roots, real_roots_f64, real_roots_f64_of,
    square_free_decomposition, RootInterval,
};
use rcagd_algebra::{Poly, Rational, Scalar};

type P = Poly<Rational>;

fn q(a: i64, b: i64) -> Rational {
    Rational::from_parts_signed(IBig::from(a), IBig::from(b))
}

fn from_roots(roots: &[(Rational, usize)]) -> P {
    roots
        .iter()
        .fold(P::constant(Rational::one()), |acc, (r, m)| {
            &acc * &P::new(vec![-r.clone(), Rational::one()]).pow(*m as u32)
        })
}

// ---------------------------------------------------------------- Sturm sequences

/// The Sturm sequence `s₀ = p, s₁ = p′, s_{k+1} = −rem(s_{k−1}, s_k)`.
fn sturm_sequence(p: &P) -> Vec<P> {
    let mut seq = vec![p.clone(), p.derivative()];
    while let Some(last) = seq.last() {
        if last.is_zero() {
            seq.pop();
            break;
        }
        let prev = &seq[seq.len() - 2];
        let (_, r) = prev.div_rem(last).expect("nonzero divisor");
        seq.push(-r);
    }
    seq
}

fn sign(x: &Rational) -> i32 {
    if x.is_zero() {
        0
    } else if *x < Rational::zero() {
        -1
    } else {
        1
    }
}

fn variations_at(seq: &[P], x: &Rational) -> usize {
    let signs: Vec<i32> = seq
        .iter()
        .map(|s| sign(&s.eval(x)))
        .filter(|&s| s != 0)
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// Distinct real roots of `p ≠ 0` in the closed interval `[lo, hi]` by Sturm's theorem
/// applied to the square-free part: `V(lo) − V(hi)` counts the roots in `(lo, hi]`.
fn sturm_count(p: &P, lo: &Rational, hi: &Rational) -> usize {
    let s = p.square_free();
    if s.degree().unwrap_or(0) == 0 {
        return 0;
    }
    let seq = sturm_sequence(&s);
    let at_lo = usize::from(s.eval(lo).is_zero());
    variations_at(&seq, lo) - variations_at(&seq, hi) + at_lo
}

/// A power of two beyond every root (Cauchy: 1 + max |aᵢ/aₙ|).
fn cauchy_bound(p: &P) -> Rational {
    let lc = p.leading();
    let m = p
        .coeffs()
        .iter()
        .map(|c| c.clone() / lc.clone())
        .map(|c| if c < Rational::zero() { -c } else { c })
        .fold(Rational::zero(), |a, b| if b > a { b } else { a });
    m + Rational::one()
}

// ---------------------------------------------------------------- Bareiss

/// The determinant by fraction-free Bareiss elimination (every division exact).
fn bareiss_det(mut a: Vec<Vec<Rational>>) -> Rational {
    let n = a.len();
    if n == 0 {
        return Rational::one();
    }
    let mut sign_flip = false;
    let mut prev = Rational::one();
    for k in 0..n - 1 {
        if a[k][k].is_zero() {
            match (k + 1..n).find(|&r| !a[r][k].is_zero()) {
                Some(r) => {
                    a.swap(k, r);
                    sign_flip = !sign_flip;
                }
                None => return Rational::zero(),
            }
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let v = (a[i][j].clone() * a[k][k].clone() - a[i][k].clone() * a[k][j].clone())
                    / prev.clone();
                a[i][j] = v;
            }
        }
        prev = a[k][k].clone();
    }
    let d = a[n - 1][n - 1].clone();
    if sign_flip {
        -d
    } else {
        d
    }
}

// ---------------------------------------------------------------- strategies

fn int_poly(max_len: usize) -> impl Strategy<Value = P> {
    prop::collection::vec(-9i64..=9, 1..=max_len).prop_map(|c| P::from_ints(&c))
}

fn nonzero_int_poly(max_len: usize) -> impl Strategy<Value = P> {
    int_poly(max_len).prop_filter("nonzero", |p| !p.is_zero())
}

fn rat_poly(max_len: usize) -> impl Strategy<Value = P> {
    prop::collection::vec((-30i64..=30, 1i64..=8), 1..=max_len)
        .prop_map(|c| P::new(c.into_iter().map(|(a, b)| q(a, b)).collect()))
        .prop_filter("nonzero", |p| !p.is_zero())
}

fn rational() -> impl Strategy<Value = Rational> {
    (-40i64..=40, 1i64..=9).prop_map(|(a, b)| q(a, b))
}

/// Planted rational roots with multiplicities 1..=3.
fn planted_roots() -> impl Strategy<Value = Vec<(Rational, usize)>> {
    prop::collection::vec((rational(), 1usize..=3), 0..=4)
}

/// A factor without rational roots: 1, t² + 1, t² − 2, t² − 3 or (t² − 2)(t² + t + 1).
fn irrational_factor() -> impl Strategy<Value = (P, Vec<f64>)> {
    prop_oneof![
        Just((P::from_ints(&[1]), vec![])),
        Just((P::from_ints(&[1, 0, 1]), vec![])),
        Just((
            P::from_ints(&[-2, 0, 1]),
            vec![-core::f64::consts::SQRT_2, core::f64::consts::SQRT_2]
        )),
        Just((P::from_ints(&[-3, 0, 1]), vec![-(3f64.sqrt()), 3f64.sqrt()])),
        Just((
            &P::from_ints(&[-2, 0, 1]) * &P::from_ints(&[1, 1, 1]),
            vec![-core::f64::consts::SQRT_2, core::f64::consts::SQRT_2]
        )),
    ]
}

fn distinct_sorted(roots: &[(Rational, usize)]) -> Vec<Rational> {
    let mut v: Vec<Rational> = roots.iter().map(|(r, _)| r.clone()).collect();
    v.sort();
    v.dedup();
    v
}

/// The adjacent `f64`s (finite, non-zero `x` of moderate size).
fn neighbours(x: f64) -> (f64, f64) {
    let bits = x.to_bits();
    if x > 0.0 {
        (f64::from_bits(bits - 1), f64::from_bits(bits + 1))
    } else if x < 0.0 {
        (f64::from_bits(bits + 1), f64::from_bits(bits - 1))
    } else {
        (-f64::from_bits(1), f64::from_bits(1))
    }
}

fn exact(x: f64) -> Rational {
    x.to_rational().expect("finite")
}

/// `x` is the correctly rounded value of a root of `p`: a root lies in
/// `[(x⁻ + x)/2, (x + x⁺)/2]`.
fn is_correctly_rounded_root(p: &P, x: f64) -> bool {
    let (a, b) = neighbours(x);
    let two = q(2, 1);
    let lo = (exact(a) + exact(x)) / two.clone();
    let hi = (exact(x) + exact(b)) / two;
    sturm_count(p, &lo, &hi) >= 1
}

fn check_isolation(p: &P, ivs: &[RootInterval]) -> Result<(), TestCaseError> {
    let s = p.square_free();
    for w in ivs.windows(2) {
        // open intervals may share an endpoint (which is not a root)
        prop_assert!(w[0].hi <= w[1].lo, "not sorted/disjoint: {:?}", w);
        prop_assert!(w[0].lo < w[1].hi, "not sorted/disjoint: {:?}", w);
    }
    for iv in ivs {
        if iv.is_exact() {
            prop_assert!(p.eval(&iv.lo).is_zero());
        } else {
            prop_assert!(iv.lo < iv.hi);
            let (a, b) = (s.eval(&iv.lo), s.eval(&iv.hi));
            prop_assert!(sign(&a) * sign(&b) == -1, "no sign change on {:?}", iv);
            prop_assert_eq!(sturm_count(p, &iv.lo, &iv.hi), 1);
        }
    }
    Ok(())
}

// ---------------------------------------------------------------- fixed examples

#[test]
fn zero_polynomial_and_constants_are_errors_not_panics() {
    let z = P::zero();
    assert!(isolate_real_roots(&z).is_err());
    assert!(isolate_real_roots_in(&z, &q(-1, 1), &q(1, 1)).is_err());
    assert!(count_real_roots_in(&z, &q(-1, 1), &q(1, 1)).is_err());
    assert!(isolate_real_roots_with_multiplicity(&z).is_err());
    assert!(real_roots_f64(&z).is_empty());
    assert!(rational_roots(&z).is_empty());
    assert!(real_roots_f64_of(&Poly::<f64>::zero()).is_err());
    assert!(real_roots_f64_of(&Poly::new(vec![f64::INFINITY, 1.0])).is_err());
    assert!(discriminant(&z).is_err());
    assert!(sylvester_matrix(&z, &P::x()).is_err());
    assert_eq!(resultant(&z, &P::x()), q(0, 1));
    let c = P::constant(q(-7, 3));
    assert!(isolate_real_roots(&c).expect("constant").is_empty());
    assert_eq!(count_real_roots_in(&c, &q(-5, 1), &q(5, 1)).expect("ok"), 0);
    assert!(real_roots_f64(&c).is_empty());
    assert!(rational_roots(&c).is_empty());
    assert!(discriminant(&c).is_err());
    assert!(square_free_decomposition(&c).is_empty());
}

#[test]
fn wilkinson_like_and_clustered_roots() {
    // ∏_{k=1}^{12} (t − k/7): twelve close rational roots
    let roots: Vec<(Rational, usize)> = (1..=12).map(|k| (q(k, 7), 1)).collect();
    let p = from_roots(&roots);
    let ivs = isolate_real_roots(&p).expect("nonzero");
    assert_eq!(ivs.len(), 12);
    check_isolation(&p, &ivs).expect("valid");
    assert_eq!(rational_roots(&p), distinct_sorted(&roots));
    let f = real_roots_f64(&p);
    for (x, k) in f.iter().zip(1..=12) {
        assert_eq!(*x, k as f64 / 7.0);
    }
}

#[test]
fn huge_coefficients() {
    // roots ±(2¹⁰⁰ + 1)/3 and 1/(2¹⁰⁰), times t² − 2
    let big = IBig::from(UBig::ONE << 100usize);
    let r1 = Rational::from_parts_signed(big.clone() + IBig::ONE, IBig::from(3));
    let r2 = Rational::from_parts(IBig::ONE, UBig::ONE << 100usize);
    let p = &from_roots(&[(r1.clone(), 2), (-r1.clone(), 1), (r2.clone(), 1)])
        * &P::from_ints(&[-2, 0, 1]);
    let ivs = isolate_real_roots(&p).expect("nonzero");
    assert_eq!(ivs.len(), 5);
    check_isolation(&p, &ivs).expect("valid");
    let mut expected = vec![-r1.clone(), r2.clone(), r1.clone()];
    expected.sort();
    assert_eq!(rational_roots(&p), expected);
    let f = real_roots_f64(&p);
    assert_eq!(f.len(), 5);
    for x in &f {
        assert!(is_correctly_rounded_root(&p, *x), "{x}");
    }
    let m = isolate_real_roots_with_multiplicity(&p).expect("nonzero");
    assert_eq!(
        m.iter().map(|(_, k)| *k).collect::<Vec<_>>(),
        vec![1, 1, 1, 1, 2]
    );
}

#[test]
fn resultant_product_formula_examples() {
    // p = 3(t − 1)(t + 2), q = −2(t − 1/2)³: Res = 3³(−2)²∏(αᵢ − βⱼ)
    let p = from_roots(&[(q(1, 1), 1), (q(-2, 1), 1)]).scale(&q(3, 1));
    let r = from_roots(&[(q(1, 2), 3)]).scale(&q(-2, 1));
    let prod = (q(1, 1) - q(1, 2)).pow(3) * (q(-2, 1) - q(1, 2)).pow(3);
    assert_eq!(resultant(&p, &r), q(27, 1) * q(4, 1) * prod);
    assert_eq!(
        resultant(&p, &r),
        bareiss_det(sylvester_matrix(&p, &r).expect("nonzero"))
    );
}

// ---------------------------------------------------------------- properties

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// gcd divides both, and any common factor multiplied in is found.
    #[test]
    fn gcd_divides_and_is_maximal(a in rat_poly(5), b in rat_poly(5), c in nonzero_int_poly(4)) {
        let ac = &a * &c;
        let bc = &b * &c;
        let g = ac.gcd(&bc);
        prop_assert!(ac.div_rem(&g).expect("nonzero").1.is_zero());
        prop_assert!(bc.div_rem(&g).expect("nonzero").1.is_zero());
        prop_assert!(g.div_rem(&c).expect("nonzero").1.is_zero(), "common factor lost");
        // cofactors are coprime
        let ca = ac.div_exact(&g).expect("divides");
        let cb = bc.div_exact(&g).expect("divides");
        prop_assert_eq!(ca.gcd(&cb).degree(), Some(0));
    }

    /// Res(a, b) = 0 ⇔ deg gcd(a, b) > 0; Res matches Bareiss on the Sylvester matrix and
    /// the swap rule Res(b, a) = (−1)^{mn} Res(a, b).
    #[test]
    fn resultant_vanishes_iff_common_factor(
        a in rat_poly(5), b in rat_poly(5), c in int_poly(3), share in any::<bool>()
    ) {
        let (a, b) = if share && c.degree().unwrap_or(0) > 0 { (&a * &c, &b * &c) } else { (a, b) };
        let r = resultant(&a, &b);
        let g = a.gcd(&b);
        prop_assert_eq!(r.is_zero(), g.degree().unwrap_or(0) > 0);
        let det = bareiss_det(sylvester_matrix(&a, &b).expect("nonzero"));
        prop_assert_eq!(&r, &det);
        let (m, n) = (a.degree().unwrap_or(0), b.degree().unwrap_or(0));
        let swapped = resultant(&b, &a);
        prop_assert_eq!(if (m * n) % 2 == 1 { -swapped } else { swapped }, r);
    }

    /// Res(c∏(t−αᵢ), d∏(t−βⱼ)) = cⁿ dᵐ ∏(αᵢ − βⱼ).
    #[test]
    fn resultant_product_formula(
        ra in planted_roots(), rb in planted_roots(), c in rational(), d in rational()
    ) {
        prop_assume!(!c.is_zero() && !d.is_zero());
        let p = from_roots(&ra).scale(&c);
        let r = from_roots(&rb).scale(&d);
        let (m, n) = (p.degree().unwrap_or(0), r.degree().unwrap_or(0));
        let mut expected = c.pow(n as isize) * d.pow(m as isize);
        for (alpha, ma) in &ra {
            for (beta, mb) in &rb {
                expected *= (alpha.clone() - beta.clone()).pow((ma * mb) as isize);
            }
        }
        prop_assert_eq!(resultant(&p, &r), expected);
    }

    /// disc(p) = 0 ⇔ p has a multiple root; disc = (−1)^{n(n−1)/2} Res(p, p′)/lc.
    #[test]
    fn discriminant_detects_multiple_roots(p in rat_poly(6)) {
        prop_assume!(p.degree().unwrap_or(0) >= 1);
        let d = discriminant(&p).expect("degree ≥ 1");
        let multiple = p.gcd(&p.derivative()).degree().unwrap_or(0) > 0;
        prop_assert_eq!(d.is_zero(), multiple);
        let n = p.degree().unwrap_or(0);
        let det = bareiss_det(sylvester_matrix(&p, &p.derivative()).expect("nonzero"))
            / p.leading();
        prop_assert_eq!(d, if (n * (n - 1) / 2) % 2 == 1 { -det } else { det });
    }

    /// Isolation agrees with Sturm's count on the whole line and on random closed
    /// intervals, intervals are disjoint, sorted, each with a sign change and one root.
    #[test]
    fn isolation_agrees_with_sturm(p in nonzero_int_poly(9), lo in rational(), w in rational()) {
        let ivs = isolate_real_roots(&p).expect("nonzero");
        check_isolation(&p, &ivs)?;
        if p.degree().unwrap_or(0) > 0 {
            let b = cauchy_bound(&p);
            prop_assert_eq!(ivs.len(), sturm_count(&p, &-b.clone(), &b));
        } else {
            prop_assert!(ivs.is_empty());
        }
        let hi = lo.clone() + if w < Rational::zero() { -w } else { w };
        let inside = isolate_real_roots_in(&p, &lo, &hi).expect("valid interval");
        check_isolation(&p, &inside)?;
        for iv in &inside {
            prop_assert!(lo <= iv.lo && iv.hi <= hi);
        }
        prop_assert_eq!(inside.len(), sturm_count(&p, &lo, &hi));
        prop_assert_eq!(count_real_roots_in(&p, &lo, &hi).expect("ok"), inside.len());
    }

    /// Products of known linear factors (t − a/b)^k, times a factor without rational
    /// roots, give back exactly those roots; roots at the ends of a closed interval are
    /// reported exactly; multiplicities are recovered.
    #[test]
    fn planted_roots_are_recovered(
        roots in planted_roots(), extra in irrational_factor(), c in rational()
    ) {
        prop_assume!(!c.is_zero());
        let (f, irr) = extra;
        let p = &from_roots(&roots).scale(&c) * &f;
        let expected = distinct_sorted(&roots);
        prop_assert_eq!(rational_roots(&p), expected.clone());
        for r in rational_roots(&p) {
            prop_assert!(p.eval(&r).is_zero());
        }
        let ivs = isolate_real_roots(&p).expect("nonzero");
        prop_assert_eq!(ivs.len(), expected.len() + irr.len());
        check_isolation(&p, &ivs)?;
        // f64 roots: exactly the rationals (correctly rounded) and the irrationals.
        let mut want: Vec<f64> = expected.iter().map(Scalar::to_f64).collect();
        want.extend(irr.iter().copied());
        want.sort_by(|a, b| a.partial_cmp(b).expect("finite"));
        let got = real_roots_f64(&p);
        prop_assert_eq!(got.len(), want.len());
        for (g, w) in got.iter().zip(&want) {
            prop_assert!((g - w).abs() <= 4.0 * f64::EPSILON * w.abs().max(1e-300), "{} vs {}", g, w);
            prop_assert!(is_correctly_rounded_root(&p, *g), "{} not correctly rounded", g);
        }
        // multiplicities
        let mult = isolate_real_roots_with_multiplicity(&p).expect("nonzero");
        for (iv, k) in &mult {
            if let Some((_, m)) = roots.iter().find(|(r, _)| iv.contains(r)) {
                let total: usize = roots.iter().filter(|(r, _)| iv.contains(r)).map(|(_, m)| m).sum();
                prop_assert_eq!(*k, total, "root {:?} multiplicity {}", iv, m);
            } else {
                prop_assert_eq!(*k, 1);
            }
        }
        // closed interval whose ends are the extreme planted roots
        if let (Some(first), Some(last)) = (expected.first(), expected.last()) {
            let inside = isolate_real_roots_in(&p, first, last).expect("valid");
            prop_assert!(inside.first().is_some_and(|iv| iv.is_exact() && iv.lo == *first));
            prop_assert!(inside.last().is_some_and(|iv| iv.is_exact() && iv.lo == *last));
            prop_assert_eq!(inside.len(), sturm_count(&p, first, last));
        }
    }

    /// Refinement to any width keeps exactly one root inside a nested interval.
    #[test]
    fn refine_keeps_exactly_one_root(p in nonzero_int_poly(8), k in 1u32..200) {
        let width = Rational::from_parts(IBig::ONE, UBig::ONE << k as usize);
        for iv in isolate_real_roots(&p).expect("nonzero") {
            let mut r = iv.clone();
            r.refine(&p, &width).expect("isolating interval");
            prop_assert!(r.width() <= width);
            prop_assert!(iv.lo <= r.lo && r.hi <= iv.hi);
            prop_assert_eq!(sturm_count(&p, &r.lo, &r.hi), 1);
            if r.is_exact() {
                prop_assert!(p.eval(&r.lo).is_zero());
            } else {
                let s = p.square_free();
                prop_assert_eq!(sign(&s.eval(&r.lo)) * sign(&s.eval(&r.hi)), -1);
            }
        }
    }

    /// f64 roots lie in the exact intervals and are correctly rounded; the f64-coefficient
    /// entry point agrees on polynomials with exactly representable coefficients.
    #[test]
    fn f64_roots_agree_with_exact_intervals(p in nonzero_int_poly(8)) {
        let ivs = isolate_real_roots(&p).expect("nonzero");
        let f = real_roots_f64(&p);
        prop_assert_eq!(f.len(), ivs.len());
        for (x, iv) in f.iter().zip(&ivs) {
            prop_assert!(Scalar::to_f64(&iv.lo) <= *x && *x <= Scalar::to_f64(&iv.hi));
            prop_assert!(is_correctly_rounded_root(&p, *x), "{} not correctly rounded", x);
            prop_assert_eq!(iv.root_f64(&p).expect("isolating"), *x);
        }
        let pf: Poly<f64> = p.map(Scalar::to_f64);
        prop_assert_eq!(real_roots_f64_of(&pf).expect("finite"), f);
    }

    /// Yun's decomposition multiplies back to the monic input.
    #[test]
    fn square_free_decomposition_multiplies_back(roots in planted_roots(), extra in irrational_factor()) {
        let p = &from_roots(&roots) * &extra.0;
        let d = square_free_decomposition(&p);
        let prod = d.iter().fold(P::constant(Rational::one()), |acc, (f, k)| &acc * &f.pow(*k as u32));
        prop_assert_eq!(prod, p.monic());
        for (f, _) in &d {
            prop_assert_eq!(f.gcd(&f.derivative()).degree(), Some(0));
        }
    }
}

// ---------------------------------------------------------------- bivariate

fn bivariate() -> impl Strategy<Value = MPoly<Rational>> {
    prop::collection::vec(((0u32..=3, 0u32..=3), -6i64..=6), 1..=6).prop_map(|terms| {
        MPoly::from_terms(
            2,
            terms
                .into_iter()
                .map(|((i, j), c)| (vec![i, j], q(c, 1)))
                .collect(),
        )
        .expect("length 2")
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Res_x(f, g)(y₀) equals the formal Sylvester determinant of f(·, y₀), g(·, y₀).
    #[test]
    fn resultant_poly_specializes(f in bivariate(), g in bivariate(), y0 in rational()) {
        let r = resultant_in(&f, &g, 0).expect("bivariate");
        let fb = f.to_bivariate(0, 1).expect("bivariate");
        let gb = g.to_bivariate(0, 1).expect("bivariate");
        prop_assert_eq!(&r, &resultant_poly(&fb, &gb));
        let (Some(m), Some(n)) = (fb.degree(), gb.degree()) else {
            prop_assert!(r.is_zero());
            return Ok(());
        };
        let fs = Poly::new(fb.coeffs().iter().map(|c| c.eval(&y0)).collect());
        let gs = Poly::new(gb.coeffs().iter().map(|c| c.eval(&y0)).collect());
        let det = bareiss_det(sylvester_matrix_formal(&fs, m, &gs, n).expect("formal"));
        prop_assert_eq!(r.eval(&y0), det.clone());
        prop_assert_eq!(resultant_formal(&fs, m, &gs, n).expect("formal"), det);
    }

    /// A common zero (x₀, y₀) of f and g makes Res_x vanish at y₀ and Res_y at x₀.
    #[test]
    fn common_zero_is_a_root_of_the_resultant(
        f in bivariate(), g in bivariate(), x0 in rational(), y0 in rational()
    ) {
        // Shift constants so that (x₀, y₀) is a common zero.
        let fix = |p: &MPoly<Rational>| {
            let v = p.eval(&[x0.clone(), y0.clone()]).expect("2 values");
            p - &MPoly::constant(2, v)
        };
        let (f, g) = (fix(&f), fix(&g));
        let rx = resultant_in(&f, &g, 0).expect("bivariate");
        let ry = resultant_in(&f, &g, 1).expect("bivariate");
        // Res of two polynomials of degree 0 in the eliminated variable is 1 by convention.
        if f.degree_in(0).unwrap_or(0) + g.degree_in(0).unwrap_or(0) > 0 {
            prop_assert!(rx.eval(&y0).is_zero());
        }
        if f.degree_in(1).unwrap_or(0) + g.degree_in(1).unwrap_or(0) > 0 {
            prop_assert!(ry.eval(&x0).is_zero());
        }
    }

    /// MPoly is a commutative ring and evaluation / substitution are homomorphisms.
    #[test]
    fn mpoly_ring_laws_and_homomorphisms(
        a in bivariate(), b in bivariate(), c in bivariate(), x0 in rational(), y0 in rational(),
        k in 0u32..4
    ) {
        prop_assert_eq!(&(&a * &b) * &c, &a * &(&b * &c));
        prop_assert_eq!(&a * &(&b + &c), &(&a * &b) + &(&a * &c));
        prop_assert_eq!(&a * &b, &b * &a);
        prop_assert!((&a - &a).is_zero());
        prop_assert_eq!(-(-&a), a.clone());
        let pt = [x0.clone(), y0.clone()];
        let ev = |p: &MPoly<Rational>| p.eval(&pt).expect("2 values");
        prop_assert_eq!(ev(&(&a * &b)), ev(&a) * ev(&b));
        prop_assert_eq!(ev(&(&a + &b)), ev(&a) + ev(&b));
        prop_assert_eq!(ev(&a.pow(k)), ev(&a).pow(k as isize));
        // product rule
        for i in 0..2 {
            prop_assert_eq!((&a * &b).partial(i), &(&a.partial(i) * &b) + &(&a * &b.partial(i)));
        }
        // substitution of a curve (x(t), y(t)) is a ring homomorphism
        let xt = Poly::new(vec![x0.clone(), q(1, 1), q(-1, 2)]);
        let yt = Poly::new(vec![y0.clone(), q(2, 3)]);
        let sub = |p: &MPoly<Rational>| p.substitute_univariate(&[xt.clone(), yt.clone()]).expect("2 polys");
        prop_assert_eq!(sub(&(&a * &b)), &sub(&a) * &sub(&b));
        prop_assert_eq!(sub(&a).eval(&Rational::zero()), ev(&a));
        // univariate views round-trip
        let u = a.to_univariate_in(1).expect("small degree");
        prop_assert_eq!(MPoly::from_univariate_in(&u, 1), a.clone());
        // homogenization: H(x, y, 1) = a(x, y)
        let h = a.homogenize();
        prop_assert!(h.is_homogeneous());
        prop_assert_eq!(h.eval(&[x0.clone(), y0.clone(), q(1, 1)]).expect("3 values"), ev(&a));
    }
}
