//! Factorization over `Q(√d)(i)` (`rcagd_algebra::factor_ext`): random products of linear
//! factors over `K = Q(√d)(i)` and of rational quadratics are factored completely, the
//! product of the factors is the square-free part, and every linear factor is found.

use proptest::prelude::*;
use rcagd_algebra::complex::Complex;
use rcagd_algebra::factor_ext::{factor_biquadratic, to_biquad, BiquadPoly};
use rcagd_algebra::{Poly, QuadExt, Rational};

fn qe(a: i64, b: i64, d: i64) -> QuadExt {
    QuadExt::new(Rational::from(a), Rational::from(b), Rational::from(d)).expect("field")
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn random_products_factor_completely(
        d in prop_oneof![Just(2i64), Just(3), Just(5), Just(6), Just(7)],
        lins in proptest::collection::vec(proptest::array::uniform4(-3i64..4), 1..4),
        quad in proptest::array::uniform2(-3i64..4),
    ) {
        let mut l: BiquadPoly = Poly::constant(Complex::from_real(QuadExt::rational(Rational::ONE)));
        let mut want: Vec<BiquadPoly> = Vec::new();
        for c in &lins {
            // t − (a + b√d + i(c₀ + c₁√d))
            let root = Complex::new(qe(c[0], c[1], d), qe(c[2], c[3], d));
            let f = Poly::new(vec![-root, Complex::from_real(QuadExt::rational(Rational::ONE))]);
            if !want.contains(&f) {
                want.push(f.clone());
                l = &l * &f;
            }
        }
        // a rational quadratic t² + q₀t + q₁ (irreducible or not over K)
        let rq = to_biquad(&Poly::from_ints(&[quad[1], quad[0], 1]));
        l = &l * &rq;
        let f = factor_biquadratic(&l, &Rational::from(d)).expect("factor");
        prop_assert!(f.complete);
        for w in &want {
            prop_assert!(f.factors.contains(w), "{w:?} missing in {:?}", f.factors);
        }
        let prod = f.factors.iter().fold(
            Poly::constant(Complex::from_real(QuadExt::rational(Rational::ONE))),
            |a, b| &a * b,
        );
        let sf = l.div_exact(&l.gcd(&l.derivative())).expect("square-free part");
        prop_assert_eq!(prod, sf.monic());
        // every factor divides l
        for g in &f.factors {
            prop_assert!(l.div_rem(g).expect("div").1 == Poly::zero());
        }
    }
}
