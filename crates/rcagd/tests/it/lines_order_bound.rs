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
