//! Property tests of the line geometry (Gruber §1.1) and the cyclographic model (§1.2)
//! with random exact inputs: the Klein quadric identity and every incidence hold exactly;
//! `f64` agrees with the exact results.

use num_traits::Zero;
use proptest::prelude::*;
use rcagd::cyclographic::{lorentz, OrientedSphere};
use rcagd::lines::plucker::{klein_form, wedge};
use rcagd::lines::regulus::common_perpendicular;
use rcagd::lines::{
    common_transversals, CommonTransversals, CongruenceKind, FocalLines, Line, LineError,
    LinearComplex, LinearCongruence, Regulus,
};
use rcagd::Certified;
use rcagd_algebra::linalg::Matrix;
use rcagd_algebra::{QuadExt, Rational, Scalar};

fn q(n: i64) -> Rational {
    Rational::from(n)
}

fn point() -> impl Strategy<Value = [Rational; 4]> {
    (1i64..4, -6i64..7, -6i64..7, -6i64..7).prop_map(|(w, a, b, c)| [q(w), q(a), q(b), q(c)])
}

fn vec6() -> impl Strategy<Value = [Rational; 6]> {
    proptest::array::uniform6(-5i64..6).prop_map(|a| a.map(q))
}

fn line() -> impl Strategy<Value = Line<Rational>> {
    (point(), point()).prop_filter_map("distinct points", |(p, r)| Line::from_points(&p, &r).ok())
}

fn det4(rows: [[Rational; 4]; 4]) -> Rational {
    Matrix::from_rows(rows.iter().map(|r| r.to_vec()).collect())
        .expect("4×4")
        .determinant()
        .expect("square")
}

fn ext(l: &Line<Rational>) -> Line<QuadExt> {
    l.map_scalar(|x| QuadExt::rational(x.clone()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn plucker_identity_and_incidence(p in point(), r in point()) {
        match Line::from_points(&p, &r) {
            Ok(l) => {
                prop_assert!(klein_form(l.coords()).is_zero());
                prop_assert!(l.contains_point(&p) && l.contains_point(&r));
                prop_assert!(l.all_hold());
                let (u, v) = l.planes();
                prop_assert!(l.lies_in_plane(&u) && l.lies_in_plane(&v));
                prop_assert!(Line::from_planes(&u, &v).expect("planes").same_line(&l));
                let (a, b) = l.points();
                prop_assert!(Line::from_points(&a, &b).expect("pts").same_line(&l));
                // E² = −I and the Klein quadric is preserved by the polarity
                let h = l.polar_omega();
                prop_assert!(h.klein_form().is_zero());
                // f64 agrees
                let lf = Line::from_points(&p.clone().map(|x| Scalar::to_f64(&x)), &r.clone().map(|x| Scalar::to_f64(&x))).expect("f64");
                for (x, y) in lf.coords().iter().zip(l.coords()) {
                    prop_assert!((x - Scalar::to_f64(y)).abs() < 1e-9);
                }
            }
            Err(LineError::CoincidentPoints(..)) => {
                prop_assert!(wedge(&p, &r).iter().all(|x| x.is_zero()));
            }
            Err(e) => prop_assert!(false, "{e}"),
        }
    }

    #[test]
    fn meeting_is_coplanarity(g in line(), h in line()) {
        let (a, b) = g.points();
        let (c, d) = h.points();
        let coplanar = det4([a, b, c, d]).is_zero();
        prop_assert_eq!(g.meets(&h), coplanar);
        if coplanar && !g.same_line(&h) {
            let x = g.intersection(&h).expect("meet");
            prop_assert!(g.contains_point(&x) && h.contains_point(&x));
            let e = g.joining_plane(&h).expect("plane");
            prop_assert!(g.lies_in_plane(&e) && h.lies_in_plane(&e));
        }
        if !coplanar && !g.is_at_infinity() && !h.is_at_infinity() {
            let n = common_perpendicular(&g, &h).expect("perp");
            prop_assert!(n.meets(&g) && n.meets(&h));
            let (dn, dg, dh) = (n.direction(), g.direction(), h.direction());
            let dot = |a: &[Rational; 3], b: &[Rational; 3]| (0..3).fold(q(0), |s, i| s + a[i].clone() * b[i].clone());
            prop_assert!(dot(&dn, &dg).is_zero() && dot(&dn, &dh).is_zero());
        }
    }

    #[test]
    fn null_polarity(c in vec6(), p in point()) {
        let Ok(cx) = LinearComplex::new(c) else { return Ok(()); };
        prop_assert!(cx.all_hold(), "{:?}", cx.certify());
        if let Ok(u) = cx.null_plane(&p) {
            let inc = (0..4).fold(q(0), |s, i| s + u[i].clone() * p[i].clone());
            prop_assert!(inc.is_zero());
            if !cx.is_singular() {
                let back = cx.null_point(&u).expect("null point");
                prop_assert!(Line::from_points(&back, &p).is_err(), "null point of π(p) is p");
            }
        }
    }

    #[test]
    fn congruences_classify_and_certify(c1 in vec6(), c2 in vec6()) {
        let (Ok(a), Ok(b)) = (LinearComplex::new(c1), LinearComplex::new(c2)) else { return Ok(()); };
        let Ok(net) = LinearCongruence::new(a, b) else { return Ok(()); };
        let d = net.discriminant();
        let kind = net.kind();
        match kind {
            CongruenceKind::Hyperbolic => prop_assert!(d > q(0)),
            CongruenceKind::Elliptic => prop_assert!(d < q(0)),
            CongruenceKind::Parabolic => prop_assert!(d.is_zero()),
            CongruenceKind::Degenerate => {}
        }
        let certs = net.certify();
        prop_assert!(net.all_hold(), "{:?} {:?}", kind, certs);
        if let Ok(FocalLines::Hyperbolic([f1, f2])) = net.focal_lines() {
            prop_assert!(f1.klein_form().is_zero() && f2.klein_form().is_zero());
        }
    }

    #[test]
    fn reguli(a in line(), b in line(), c in line(), s in -5i64..6) {
        match Regulus::from_lines(&a, &b, &c) {
            Ok(r) => {
                prop_assert!(r.all_hold(), "{:?}", r.certify());
                let t = r.transversal(&q(s));
                prop_assert!(t.meets(&a) && t.meets(&b) && t.meets(&c));
                let g = r.generator(&q(s), &q(1));
                prop_assert!(g.meets(&t) && g.klein_form().is_zero());
            }
            Err(LineError::NotSkew(..)) => {
                prop_assert!(a.meets(&b) || a.meets(&c) || b.meets(&c));
            }
            Err(e) => prop_assert!(false, "{e}"),
        }
    }

    #[test]
    fn transversals_of_four_lines(l in proptest::array::uniform4(line())) {
        match common_transversals([&l[0], &l[1], &l[2], &l[3]]).expect("transversals") {
            CommonTransversals::Two(ts) => {
                for t in &ts {
                    prop_assert!(t.klein_form().is_zero());
                    for x in &l {
                        prop_assert!(t.reciprocal_product(&ext(x)).is_zero());
                    }
                }
            }
            CommonTransversals::One(t) => {
                prop_assert!(t.klein_form().is_zero());
                for x in &l {
                    prop_assert!(t.meets(x));
                }
            }
            CommonTransversals::ComplexPair { re, im } => {
                for x in &l {
                    let xe = ext(x);
                    prop_assert!(rcagd::lines::reciprocal_product(&re, xe.coords()).is_zero());
                    prop_assert!(rcagd::lines::reciprocal_product(&im, xe.coords()).is_zero());
                }
            }
            CommonTransversals::Infinitely(basis) => {
                for v in &basis {
                    for x in &l {
                        prop_assert!(rcagd::lines::reciprocal_product(v, x.coords()).is_zero());
                    }
                }
            }
        }
    }

    #[test]
    fn oriented_contact_is_isotropy(
        m in proptest::array::uniform3(-5i64..6), r1 in -4i64..5,
        dir in proptest::array::uniform3(-3i64..4), k in 1i64..4
    ) {
        // k₂ = k₁ + isotropic vector (d, ±|d|) with |d| rational: use Pythagorean (3,4,0;5)
        let _ = dir;
        let k1 = OrientedSphere::new(m.map(q), q(r1));
        let iso = [q(3 * k), q(4 * k), q(0), q(5 * k)];
        let p2: [Rational; 4] = core::array::from_fn(|i| k1.to_point()[i].clone() + iso[i].clone());
        let k2 = OrientedSphere::from_point(&p2);
        prop_assert!(lorentz(&iso, &iso).is_zero());
        prop_assert!(k1.in_oriented_contact(&k2));
        let c = k1.contact(&k2).expect("contact");
        prop_assert!(c.all_hold());
    }
}
