//! `plane_positivity` against an independent check: the decision on random polynomials
//! `s₁² + s₂² + c` (random quadratics `sᵢ`, a constant `c` of either sign) and
//! `s₁ s₂ + c` (indefinite) is compared with exact values on a dense rational grid and
//! with what is known by construction (`c > 0` ⇒ positive; a grid value ≤ 0 ⇒ not).

use num_traits::Zero;
use proptest::prelude::*;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::plane_positivity::{plane_positivity, PlanePositivity};
use rcagd_algebra::rational::Rational;

fn quadratic(c: &[i64; 6]) -> MPoly<Rational> {
    let mons = [[0u32, 0], [1, 0], [0, 1], [2, 0], [1, 1], [0, 2]];
    let mut p = MPoly::zero(2);
    for (k, e) in mons.iter().enumerate() {
        p = &p + &MPoly::monomial(2, e, Rational::from(c[k]));
    }
    p
}

/// The least value of `g` on the grid `{−4, −4 + 1/8, …, 4}²`, exactly.
fn grid_min(g: &MPoly<Rational>) -> Rational {
    let mut m: Option<Rational> = None;
    for i in -32i64..=32 {
        for j in -32i64..=32 {
            let p = [
                Rational::from(i) / Rational::from(8),
                Rational::from(j) / Rational::from(8),
            ];
            let v = g.eval(&p).unwrap();
            if m.as_ref().is_none_or(|m| v < *m) {
                m = Some(v);
            }
        }
    }
    m.unwrap()
}

fn check(g: &MPoly<Rational>, positive_by_construction: bool) {
    let r = plane_positivity(g).unwrap();
    let min = grid_min(g);
    match &r {
        PlanePositivity::Positive(_) => {
            assert!(
                min > Rational::zero(),
                "called positive, but a grid value is {min}"
            )
        }
        PlanePositivity::NotPositive { point, value } => {
            assert!(
                !positive_by_construction,
                "positive by construction, witness {point:?}"
            );
            assert_eq!(&g.eval(point).unwrap(), value);
            assert!(*value <= Rational::zero());
        }
        PlanePositivity::Zero { .. } => assert!(!positive_by_construction),
        PlanePositivity::Undecided(_) => {}
    }
    if min <= Rational::zero() {
        assert!(!matches!(r, PlanePositivity::Positive(_)));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn sums_of_squares_with_a_constant(
        a in proptest::array::uniform6(-3i64..=3),
        b in proptest::array::uniform6(-3i64..=3),
        c in -4i64..=4,
    ) {
        let (p, q) = (quadratic(&a), quadratic(&b));
        let g = &(&(&p * &p) + &(&q * &q)) + &MPoly::constant(2, Rational::from(c) / Rational::from(4));
        let r = plane_positivity(&g).unwrap();
        check(&g, c > 0);
        // positive by construction must be proved unless it touches zero numerically
        if c > 0 {
            prop_assert!(matches!(r, PlanePositivity::Positive(_)), "{:?}", r);
        }
    }

    #[test]
    fn indefinite_products(
        a in proptest::array::uniform6(-3i64..=3),
        b in proptest::array::uniform6(-3i64..=3),
        c in -4i64..=4,
    ) {
        let (p, q) = (quadratic(&a), quadratic(&b));
        let g = &(&p * &q) + &MPoly::constant(2, Rational::from(c));
        check(&g, false);
    }
}
