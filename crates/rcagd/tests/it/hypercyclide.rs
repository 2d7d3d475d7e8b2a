//! Regular quadrics as PN surfaces (Peternell, Theorem 4.6) in the principal frame, with
//! the ruled member ψ of the pencil φ* + μΩ*, and hypercyclides (Prop. 4.3, §4.7).

use rcagd::pn::hypercyclide::{Hypercyclide, PeSimilarity, RegularQuadric};
use rcagd::pn::PnError;
use rcagd::Certified;
use rcagd_algebra::{Certificate, Rational, Scalar};

type Q = Rational;

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d)
}

fn assert_exact(certs: &[Certificate]) {
    for c in certs {
        assert!(c.holds && c.exact, "certificate failed: {c}");
    }
}

#[test]
fn smoke_ellipsoid_principal_frame() {
    let e = RegularQuadric::Ellipsoid {
        a: q(25, 3),
        b: q(5, 1),
        c: q(3, 1),
    };
    let h = Hypercyclide::<Q>::quadric(e, true).expect("rational");
    eprintln!("degree {:?} cover {:?}", h.surface().degree(), h.cover());
    assert_exact(&h.certify());
}
