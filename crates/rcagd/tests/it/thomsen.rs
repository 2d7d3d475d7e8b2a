//! Thomsen's classification A–F and Lemma 1.1 (Peternell, *Rational Parametrizations for
//! Envelopes of Quadric Families*, §1.1) on one family of each type: the type at t = 0,
//! Lemma 1.1 at t = 0 by two independent tests, the identity π ≡ −(γᵀγ)²·a₂ over Q[t],
//! and the certified parametrization (the gallery surfaces of `examples/recipes/thomsen.toml`).
//!
//! The families are `C(t) = Pᵀ·[[D + tE, 0], [0, 0]]·P`, `D = diag(1, 1, −1)`,
//! `P = [[I, t·b], [0, 1]]`: at t = 0 the conic lies in x₃ = 0 and `Ċ` has the block form
//! `[[E, D·b], [bᵀD, 0]]`, so `det(C + sĊ) = −s²·wᵀadj(D + sE)w`, `w = D·b`: parabolic ⇔
//! `bᵀDb = 0` (b = (1, 0, 1)), and `E` selects the further zeros (hand computation, checked
//! with sympy).

use rcagd::conic_surface::{ConicFamily, ConicType, Thomsen};
use rcagd::Certified;
use rcagd_algebra::{Poly, Rational};

type Q = Rational;
type P = Poly<Q>;
type Mat4 = [[P; 4]; 4];

/// `C(t)` of the module docs.
pub fn thomsen_family(b: [i64; 3], e: [[i64; 3]; 3]) -> Mat4 {
    let d = [1i64, 1, -1];
    // K = [[D + tE, 0], [0, 0]]
    let k: Mat4 = core::array::from_fn(|i| {
        core::array::from_fn(|j| {
            if i < 3 && j < 3 {
                Poly::from_ints(&[if i == j { d[i] } else { 0 }, e[i][j]])
            } else {
                Poly::zero()
            }
        })
    });
    let p: Mat4 = core::array::from_fn(|i| {
        core::array::from_fn(|j| {
            if i == j {
                Poly::from_ints(&[1])
            } else if j == 3 && i < 3 {
                Poly::from_ints(&[0, b[i]])
            } else {
                Poly::zero()
            }
        })
    });
    core::array::from_fn(|i| {
        core::array::from_fn(|j| {
            let mut s = Poly::zero();
            for a in 0..4 {
                for c in 0..4 {
                    s = &s + &(&(&p[a][i] * &k[a][c]) * &p[c][j]);
                }
            }
            s
        })
    })
}

/// One family per type: (type, b, E).
pub fn cases() -> Vec<(Thomsen, [i64; 3], [[i64; 3]; 3])> {
    vec![
        (Thomsen::A, [0, 0, 1], [[0, 0, 0], [0, 1, 0], [0, 0, 0]]),
        (Thomsen::B, [1, 0, 0], [[0, 0, 0], [0, 0, -1], [0, -1, 2]]),
        (Thomsen::C, [0, 0, 1], [[1, 0, 0], [0, 1, 0], [0, 0, -1]]),
        (Thomsen::D, [1, 0, 1], [[0, 0, 0], [0, 0, -1], [0, -1, 2]]),
        (Thomsen::E, [1, 0, 1], [[0, 0, 0], [0, 0, 1], [0, 1, 0]]),
        (Thomsen::F, [1, 0, 1], [[0, 0, 0], [0, 0, 0], [0, 0, 0]]),
    ]
}

#[test]
fn lemma_1_1_on_every_thomsen_type() {
    let t0 = Q::ZERO;
    for (ty, b, e) in cases() {
        let fam = ConicFamily::new(thomsen_family(b, e)).expect("family");
        assert_eq!(fam.thomsen_at(&t0).expect("type"), ty);
        let parabolic_case = matches!(ty, Thomsen::D | Thomsen::E | Thomsen::F);
        let (parabolic, asymptotic) = fam.lemma_1_1_at(&t0).expect("decided");
        assert_eq!(parabolic, parabolic_case, "{ty:?}");
        assert_eq!(asymptotic, parabolic_case, "{ty:?}");
        assert_eq!(
            fam.conic_type_at(&t0).expect("type") == ConicType::Parabolic,
            parabolic_case
        );
        let l = fam.lemma_1_1();
        assert!(l.all_hold(), "{ty:?}: {:?}", l.certify());
        // a₂(0) = 0 exactly for the parabolic types
        assert_eq!(l.asymptotic.eval(&t0).is_zero(), parabolic_case, "{ty:?}");
        // the identities and the parametrization
        assert!(fam.identities().iter().all(|c| c.holds), "{ty:?}");
        let s = fam.parametrize().expect("parametrization");
        assert!(s.all_hold(), "{ty:?}: {:?}", s.certify());
        eprintln!("{ty:?}: bidegree {:?}", s.degree());
    }
}

/// Lemma 1.1 at other parameters of the same families: the two tests agree.
#[test]
fn lemma_1_1_identity_on_random_parameters() {
    for (_, b, e) in cases() {
        let fam = ConicFamily::new(thomsen_family(b, e)).expect("family");
        for k in [-3i64, -1, 1, 2, 5] {
            let t = Q::from_parts(k.into(), 3u8.into());
            if let Ok((p, a)) = fam.lemma_1_1_at(&t) {
                assert_eq!(p, a, "t = {t}");
            }
        }
    }
}

/// Circles x² + y² = ρ(t), z = t (a surface of revolution): the tangent developable along
/// each circle is a cone of revolution, so the family is of type C at every parameter and
/// the surface is the envelope of those cones (Peternell §2.2). ρ = 1 + t² (a hyperboloid
/// of one sheet; the circles have the rational points (1, t)): the vertex lies on the axis,
/// and every envelope point lies on its circle. A type-A family is refused.
#[test]
fn type_c_surface_of_revolution_as_envelope_of_cones() {
    use rcagd::conic_surface::cones::TypeCEnvelope;
    // C = u·uᵀ − ρ·diag(0, 1, 1, 0), u = (1, 0, 0, t): planes tangent to the circle
    let u = [p(&[1]), p(&[0]), p(&[0]), p(&[0, 1])];
    let rho = p(&[1, 0, 1]);
    let c: Mat4 = core::array::from_fn(|i| {
        core::array::from_fn(|j| {
            let uu = &u[i] * &u[j];
            if i == j && (i == 1 || i == 2) {
                &uu - &rho
            } else {
                uu
            }
        })
    });
    let fam = ConicFamily::new(c).expect("family");
    for k in [-2i64, 1, 3] {
        assert_eq!(
            fam.thomsen_at(&Q::from(k)).expect("type"),
            Thomsen::C,
            "t = {k}"
        );
    }
    let env = TypeCEnvelope::new(&fam).expect("type C");
    let certs = env.certify();
    assert!(certs.iter().all(|c| c.holds), "{certs:?}");
    // the vertex lies on the axis x = y = 0
    let v = env.vertex();
    assert!(v[1].is_zero() && v[2].is_zero(), "{v:?}");
    // the Thomsen-A family of the gallery is refused with the reason
    let (_, b, e) = cases()[0];
    let a = ConicFamily::new(thomsen_family(b, e)).expect("family");
    let err = TypeCEnvelope::new(&a).expect_err("type A");
    assert!(err.to_string().contains("type C"), "{err}");
}

fn p(c: &[i64]) -> P {
    Poly::from_ints(c)
}
