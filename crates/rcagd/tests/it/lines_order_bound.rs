//! Order and class exactly: the proved lower bounds of `order_and_class_decided` against the
//! Bézout upper bound of `(m + n)·μ` minus the base points (`rcagd::lines::order_bound`,
//! docs/math/lines-and-canal.md, "An upper bound by Bézout").

use rcagd::lines::ParametrizedCongruence;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::Rational;

fn p(s: &[(i64, u32, u32)]) -> MPoly<Rational> {
    s.iter().fold(MPoly::zero(2), |a, &(c, i, j)| {
        &a + &MPoly::monomial(2, &[i, j], Rational::from(c))
    })
}

fn check(
    name: &str,
    oc: &rcagd::lines::OrderClass,
    want: (usize, usize, usize),
    exact: bool,
    upper: usize,
) {
    assert_eq!((oc.order, oc.class, oc.mu), want, "{name}");
    let u = oc.upper.as_ref().expect("a bound");
    assert_eq!(u.bound, upper, "{name}: {u:?}");
    assert!((oc.order + oc.class) * oc.mu <= u.bound, "{name}");
    assert_eq!(oc.exact(), exact, "{name}: {}", oc.describe());
    assert_eq!(oc.exact_certificate().holds, exact, "{name}");
    if exact {
        assert_eq!(oc.at_most(), Some((oc.order, oc.class)), "{name}");
        assert!(oc.describe().contains("exact"), "{name}");
    } else {
        assert!(oc.describe().contains("at least"), "{name}");
    }
}

fn w() -> MPoly<Rational> {
    p(&[(1, 0, 0), (1, 2, 0), (1, 0, 2)])
}

/// The quadric normal congruences (classical counts: G. Salmon, "A Treatise on the Analytic
/// Geometry of Three Dimensions", 1882, §§ 199–200), the (2, 2)-congruence of a conic and a
/// line, the chords of the twisted cubic: exact where the lower bounds reach the Bézout
/// bound; the paraboloid of revolution stays "at least" (its base points at the circular
/// points `[1 : ±i : 0]` are not ordinary: `9 − 2 = 7 > 5`).
#[test]
fn bounds_of_known_congruences() {
    // (name, surface, (order, class, μ), exact, upper bound of (m + n)·μ)
    type Case = (
        &'static str,
        [MPoly<Rational>; 4],
        (usize, usize, usize),
        bool,
        usize,
    );
    let normals: Vec<Case> = vec![
        (
            "sphere",
            [
                w(),
                p(&[(2, 1, 0)]),
                p(&[(2, 0, 1)]),
                p(&[(1, 0, 0), (-1, 2, 0), (-1, 0, 2)]),
            ],
            (1, 0, 2),
            true,
            2,
        ),
        (
            "paraboloid of revolution",
            [
                p(&[(1, 0, 0)]),
                p(&[(1, 1, 0)]),
                p(&[(1, 0, 1)]),
                p(&[(1, 2, 0), (1, 0, 2)]),
            ],
            (3, 2, 1),
            false,
            7,
        ),
        (
            "elliptic paraboloid",
            [
                p(&[(1, 0, 0)]),
                p(&[(1, 1, 0)]),
                p(&[(1, 0, 1)]),
                p(&[(1, 2, 0), (2, 0, 2)]),
            ],
            (5, 2, 1),
            true,
            7,
        ),
        (
            "ellipsoid",
            [
                w(),
                p(&[(2, 1, 0)]),
                p(&[(4, 0, 1)]),
                p(&[(3, 0, 0), (-3, 2, 0), (-3, 0, 2)]),
            ],
            (6, 2, 1),
            true,
            8,
        ),
    ];
    for (name, x, want, exact, upper) in normals {
        let c = ParametrizedCongruence::normals(x).expect("normals");
        let oc = c.order_class(3).expect("decided");
        check(name, &oc, want, exact, upper);
    }
    let conic = [
        p(&[(1, 0, 0), (1, 2, 0)]),
        p(&[(2, 1, 0)]),
        MPoly::zero(2),
        p(&[(1, 0, 0), (-1, 2, 0)]),
    ];
    let g = [
        p(&[(1, 0, 0)]),
        p(&[(5, 0, 0)]),
        p(&[(1, 0, 1)]),
        MPoly::zero(2),
    ];
    let c = ParametrizedCongruence::new(conic, g).expect("(2, 2)");
    let oc = c.order_class(3).expect("decided");
    check("conic and line", &oc, (2, 2, 1), true, 4);
    // chords of the normal twisted cubic: p = k(u), q = k(v)
    let k = |v: usize| -> [MPoly<Rational>; 4] {
        core::array::from_fn(|i| {
            let mut e = [0u32; 2];
            e[v] = i as u32;
            MPoly::monomial(2, &e, Rational::ONE)
        })
    };
    let c = ParametrizedCongruence::new(k(0), k(1)).expect("chords");
    let oc = c.order_class(3).expect("decided");
    check("cubic chords", &oc, (1, 3, 2), true, 8);
}

mod props {
    use super::*;
    use proptest::prelude::*;

    fn lin(a: [i64; 4], b: [i64; 4], var: usize) -> [MPoly<Rational>; 4] {
        core::array::from_fn(|i| {
            let mut e = [0u32; 2];
            e[var] = 1;
            &MPoly::constant(2, Rational::from(a[i]))
                + &MPoly::monomial(2, &e, Rational::from(b[i]))
        })
    }

    fn det4(m: [[i64; 4]; 4]) -> i64 {
        let mut d = 0i64;
        for k in 0..24 {
            let perm = nth_perm(k);
            d += perm_sign(&perm) * (0..4).map(|r| m[r][perm[r]]).product::<i64>();
        }
        d
    }

    fn nth_perm(mut k: usize) -> [usize; 4] {
        let mut items = vec![0usize, 1, 2, 3];
        let mut out = [0usize; 4];
        for (i, f) in [6usize, 2, 1, 1].iter().enumerate() {
            let j = k / f;
            k %= f;
            out[i] = items.remove(j);
        }
        out
    }

    fn perm_sign(p: &[usize; 4]) -> i64 {
        let mut s = 1;
        for i in 0..4 {
            for j in i + 1..4 {
                if p[i] > p[j] {
                    s = -s;
                }
            }
        }
        s
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(16))]

        /// The lines meeting two random skew lines (a hyperbolic net, `p = A + uB`,
        /// `q = C + vD`): order 1 and class 1 exactly (bidegree (1, 1): `2·1·1 = 2`).
        #[test]
        fn random_nets_are_exact(
            a in proptest::array::uniform4(-4i64..5),
            b in proptest::array::uniform4(-4i64..5),
            c in proptest::array::uniform4(-4i64..5),
            d in proptest::array::uniform4(-4i64..5),
        ) {
            prop_assume!(det4([a, b, c, d]) != 0);
            let cong = ParametrizedCongruence::new(lin(a, b, 0), lin(c, d, 1)).expect("net");
            let oc = cong.order_class(3).expect("decided");
            prop_assert_eq!((oc.order, oc.class, oc.mu), (1, 1, 1));
            prop_assert!(oc.exact(), "{}", oc.describe());
            prop_assert!(oc.exact_certificate().holds);
        }
    }
}
