//! The degree-reducing frame of Peternell §4.5.1 and Proposition 4.1: envelopes of cones of
//! revolution spanned by two cycle families whose unit normal drops from degree `2k` to
//! `2k − 2` in `t` when built in the frame `x₃ ∥ ζ`, `ζ·M(τ) = −R(τ)` at the zeros of a
//! quadratic factor of `|M|² − R²`.

use proptest::prelude::*;
use rcagd::pn::reducing_frame::{reducing_frames, ReducedConeEnvelope};
use rcagd::pn::ruled::CycleFamily;
use rcagd::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Rational, Scalar};

type Q = Rational;

fn qi(p: i64) -> Q {
    Q::from(p)
}

fn t() -> MPoly<Q> {
    MPoly::var(2, 0)
}

fn c(x: i64) -> MPoly<Q> {
    MPoly::constant(2, qi(x))
}

/// The rotation of the quaternion `(a, b, c, d)` (rational, orthogonal).
fn rotation(qt: [i64; 4]) -> [[Q; 3]; 3] {
    let [a, b, cc, d] = qt.map(qi);
    let n = a.clone() * a.clone()
        + b.clone() * b.clone()
        + cc.clone() * cc.clone()
        + d.clone() * d.clone();
    let two = qi(2);
    let m = [
        [
            a.clone() * a.clone() + b.clone() * b.clone()
                - cc.clone() * cc.clone()
                - d.clone() * d.clone(),
            two.clone() * (b.clone() * cc.clone() - a.clone() * d.clone()),
            two.clone() * (b.clone() * d.clone() + a.clone() * cc.clone()),
        ],
        [
            two.clone() * (b.clone() * cc.clone() + a.clone() * d.clone()),
            a.clone() * a.clone() - b.clone() * b.clone() + cc.clone() * cc.clone()
                - d.clone() * d.clone(),
            two.clone() * (cc.clone() * d.clone() - a.clone() * b.clone()),
        ],
        [
            two.clone() * (b.clone() * d.clone() - a.clone() * cc.clone()),
            two.clone() * (cc.clone() * d.clone() + a.clone() * b.clone()),
            a.clone() * a.clone() - b.clone() * b.clone() - cc.clone() * cc.clone()
                + d.clone() * d.clone(),
        ],
    ];
    m.map(|row| row.map(|x| x / n.clone()))
}

/// Cycle families with `M = Qᵀ M′`, `R`, where in the frame `M′₁ + iM′₂ = (t − i)(e + if)`,
/// `M′₃ = R = g(t² + 1)/2`: then `|M|² − R² = (t² + 1)(e² + f²)` and `ζ = Qᵀe₃` satisfies
/// `ζ·M(±i) = −R(±i)`... up to the sign of `ζ` (both are tried). `c₂` is a given cycle
/// family, `c₁ = c₂ + (M; R)`.
fn families(
    e: [i64; 2],
    f: [i64; 2],
    g: i64,
    qt: [i64; 4],
    c2: ([[i64; 3]; 3], [i64; 3]),
) -> (CycleFamily<Q>, CycleFamily<Q>) {
    let lin = |a: [i64; 2]| &c(a[0]) + &t().scale(&qi(a[1]));
    let (e, f) = (lin(e), lin(f));
    let t2p1 = &(&t() * &t()) + &c(1);
    let m1 = &(&t() * &e) + &f;
    let m2 = &(&t() * &f) - &e;
    let m3 = t2p1.scale(&Q::from_ratio(g, 2));
    let r = m3.clone();
    let mp = [m1, m2, m3];
    let rot = rotation(qt);
    // M = Qᵀ M′
    let m: [MPoly<Q>; 3] = std::array::from_fn(|i| {
        (0..3).fold(MPoly::zero(2), |acc, j| &acc + &mp[j].scale(&rot[j][i]))
    });
    let quad =
        |cf: [i64; 3]| &(&c(cf[0]) + &t().scale(&qi(cf[1]))) + &(&t() * &t()).scale(&qi(cf[2]));
    let centre2: [MPoly<Q>; 3] = std::array::from_fn(|i| quad(c2.0[i]));
    let radius2 = quad(c2.1);
    let centre1: [MPoly<Q>; 3] = std::array::from_fn(|i| &centre2[i] + &m[i]);
    let radius1 = &radius2 + &r;
    (
        CycleFamily::new(centre1, radius1, c(1)).expect("family 1"),
        CycleFamily::new(centre2, radius2, c(1)).expect("family 2"),
    )
}

fn assert_reduced(c1: CycleFamily<Q>, c2: CycleFamily<Q>) -> ReducedConeEnvelope<Q> {
    let env = ReducedConeEnvelope::new(c1, c2).expect("envelope");
    let certs = env.certify();
    let failing: Vec<_> = certs
        .iter()
        .filter(|c| !c.holds)
        .map(|c| c.property.clone())
        .collect();
    assert!(failing.is_empty(), "{failing:#?}");
    assert!(certs.iter().all(|c| c.exact));
    env
}

/// A fixed example of degree k = 2 rotated by the quaternion (1, 1, 2, 3): the frame is
/// found, the unit normal has degree 2k − 2 = 2 in t where the given coordinates give 4.
#[test]
fn prop_4_1_frame_reduces_the_normal_to_2k_minus_2() {
    let (c1, c2) = families(
        [1, 2],
        [-1, 1],
        2,
        [1, 1, 2, 3],
        ([[0, 1, 0], [1, 0, 1], [0, 0, 0]], [1, 1, 0]),
    );
    let env = assert_reduced(c1.clone(), c2.clone());
    assert_eq!(env.data_degree(), 2);
    let frame = env.frame().expect("a reducing frame");
    // ζ = ±(row 3 of the rotation)
    let rot = rotation([1, 1, 2, 3]);
    let plus = (0..3).all(|i| frame.zeta[i] == rot[2][i]);
    let minus = (0..3).all(|i| frame.zeta[i] == -rot[2][i].clone());
    assert!(plus || minus, "ζ = {:?}", frame.zeta);
    let n_deg = env.envelope().surface().normal_degree().0;
    assert_eq!(n_deg, 2, "deg_t n");
    assert_eq!(
        env.unreduced_degrees().0,
        4,
        "deg_t n in the given coordinates"
    );
    // the same family without rotation: the given frame is already the reducing one (up to
    // the orientation of ζ)
    let (a, b) = families(
        [1, 2],
        [-1, 1],
        2,
        [1, 0, 0, 0],
        ([[0, 1, 0], [1, 0, 1], [0, 0, 0]], [1, 1, 0]),
    );
    let env0 = assert_reduced(a, b);
    assert_eq!(env0.envelope().surface().normal_degree().0, 2);
    // the frames of the data
    let (m, r) = {
        let (m1, r1, _) = c1.parts();
        let (m2, r2, _) = c2.parts();
        (
            std::array::from_fn::<MPoly<Q>, 3, _>(|i| m1[i] - m2[i]),
            r1 - r2,
        )
    };
    let frames = reducing_frames(&m, &r);
    assert!(!frames.is_empty());
    for f in &frames {
        assert!(f.certify(&m, &r).iter().all(|c| c.holds));
    }
}

/// A family whose `|M|² − R² = 1 + t⁴` is irreducible over Q (no linear or quadratic
/// factor, so no frame of §4.5.1): the envelope is built in the given coordinates and no
/// frame (and no Prop. 4.1 degree) is claimed.
#[test]
fn no_frame_keeps_the_given_coordinates() {
    // M = (1, t², t), R = t
    let c1 = CycleFamily::new([c(1), &t() * &t(), t()], &t() + &c(1), c(1)).expect("c1");
    let c2 = CycleFamily::new([c(0), c(0), c(0)], c(1), c(1)).expect("c2");
    let env = ReducedConeEnvelope::new(c1, c2).expect("envelope");
    assert!(env.frame().is_none());
    let certs = env.certify();
    assert!(certs.iter().all(|c| c.holds), "{certs:#?}");
    assert!(!certs.iter().any(|c| c.property.contains("Prop. 4.1")));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]

    /// Random data of degree 2 built around a random rational frame: the search finds a
    /// frame, every certificate holds exactly (PN, tangency to both cycle families, contact
    /// with every cone, the frame's divisibility) and deg_t n ≤ 2k − 2.
    #[test]
    fn random_families_reach_the_prop_4_1_degree(
        e in prop::array::uniform2(-3i64..=3),
        f in prop::array::uniform2(-3i64..=3),
        g in prop::sample::select(vec![-2i64, -1, 1, 2, 3]),
        qt in prop::array::uniform4(-3i64..=3),
        cm in prop::array::uniform3(prop::array::uniform3(-2i64..=2)),
        cr in prop::array::uniform3(-2i64..=2),
    ) {
        prop_assume!(qt.iter().any(|&x| x != 0));
        prop_assume!(e != [0, 0] || f != [0, 0]);
        let (c1, c2) = families(e, f, g, qt, (cm, cr));
        let env = match ReducedConeEnvelope::new(c1, c2) {
            Ok(env) => env,
            // a developable or degenerate envelope of the random data: nothing to reduce
            Err(rcagd::pn::PnError::Developable(_)) => return Ok(()),
            Err(err) => return Err(TestCaseError::fail(format!("{err}"))),
        };
        let certs = env.certify();
        for cert in &certs {
            prop_assert!(cert.holds && cert.exact, "{}", cert);
        }
        prop_assert!(env.frame().is_some());
        let k = env.data_degree();
        prop_assert!(env.envelope().surface().normal_degree().0 <= 2 * k - 2);
    }
}
