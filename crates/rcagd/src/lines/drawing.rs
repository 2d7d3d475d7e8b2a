//! Line congruences drawn as ruled patches (docs/math/lines-and-canal.md, "Drawing
//! congruences").
//!
//! A congruence given by two points per line, `p(u, v) ∨ q(u, v)` (polynomial homogeneous
//! points), is drawn as strips: strip `k` is the ruled surface of the lines along the
//! parameter segment `v = v_k + σu`, `u ∈ [u₀, u₁]`, cut to the segment
//! `X(u, λ) = (1 − λ) p + λ q`, `λ ∈ [λ₀, λ₁]`, a rational Bézier patch of bidegree
//! `(deg_u, 1)` (`σ = 0`: the lines through one point of the second axis, a plane fan for a
//! hyperbolic net; `σ ≠ 0`: a ruled surface of the congruence).
//!
//! [`congruence_strips`] builds the congruence from a [`CongruenceSpec`] (net by its axes,
//! chord congruence of a twisted cubic, collineation net, (1, n)-congruence), certifies it
//! and returns the strips with positive Bernstein weights.

use super::generation::{GeneratedNet, GenerationError};
use super::net::{LineNet, NetError, NetKind, PointRow};
use super::order_one::{CubicChordCongruence, OneNCongruence, OrderOneError};
use super::parametrized::ParametrizedCongruence;
use super::plucker::wedge;
use crate::error::format_scalar;
use crate::pn::poly::{patch_of, sign_on_domain, Domain, Sign};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Poly, Scalar};
use rcagd_geom::weight_sign::{split_patches_adaptive, SignRule};
use rcagd_geom::BezierPatch;
use thiserror::Error;

/// Errors of [`congruence_strips`].
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum DrawError {
    /// Wrong number of input points or coordinates.
    #[error("{0}")]
    Input(String),
    /// An empty parameter interval.
    #[error("empty interval: {0}")]
    EmptyInterval(String),
    /// A strip's weight vanishes on its rectangle (a line point at infinity).
    #[error("strip {strip}: the weight vanishes near (u, λ) = ({u}, {lambda}); choose a λ range whose points stay finite")]
    PointAtInfinity {
        /// The strip index.
        strip: usize,
        /// Parameter `u` of the zero.
        u: String,
        /// Parameter `λ` of the zero.
        lambda: String,
    },
    /// A net failure.
    #[error(transparent)]
    Net(#[from] NetError),
    /// A generation failure.
    #[error(transparent)]
    Generation(#[from] GenerationError),
    /// An order-one congruence failure.
    #[error(transparent)]
    OrderOne(#[from] OrderOneError),
}

/// The congruence to draw.
#[derive(Debug, Clone)]
pub enum CongruenceSpec<F> {
    /// A regular net by its axes: `c₀, c₁, d₀, d₁` ([`LineNet::hyperbolic`],
    /// [`LineNet::parabolic`]) or `Re c₀, Im c₀, Re c₁, Im c₁` ([`LineNet::elliptic`]).
    Net(NetKind, Vec<[F; 4]>),
    /// The chords `k(u) ∨ k(v)` of the twisted cubic `a₀ + t a₁ + t² a₂ + t³ a₃`.
    CubicChords([[F; 4]; 4]),
    /// The joins `x ∨ κ(x)` of a collineation `a₀, a₁, a₂ ↦ b₀, b₁, b₂`
    /// ([`GeneratedNet::from_plane_collineation`]).
    Collineation([[F; 4]; 3], [[F; 4]; 3]),
    /// The parabolic net of the pencil projectivity `c₀ + u c₁ ↦ ε₀ + u ε₁`
    /// ([`GeneratedNet::from_pencil_projectivity`]): the point row `c` and the two planes.
    PencilProjectivity(PointRow<F>, [F; 4], [F; 4]),
    /// The (1, n)-congruence of the line `g₀ ∨ g₁` and the curve `Σ tᵐ kₘ`: lines
    /// `k(u) ∨ (g₀ + v g₁)`.
    OneN([F; 4], [F; 4], Vec<[F; 4]>),
    /// The parabolic net of the tangents of the ruled surface `X(u, v) = p(u) + v q(u)`
    /// along the generator `u = u₀` ([`GeneratedNet::from_ruled_surface_tangents`]): the
    /// power coefficients of `p` and `q` (homogeneous points) and `u₀`.
    RuledSurfaceTangents(Vec<[F; 4]>, Vec<[F; 4]>, F),
    /// Any two-parameter congruence `p(u, v) ∨ q(u, v)` ([`ParametrizedCongruence`], e.g.
    /// the normal congruence of a surface); an ideal `q` is drawn as the segment
    /// `p + λq` ([`ParametrizedCongruence::segment_points`]).
    Parametrized(Box<ParametrizedCongruence<F>>),
}

/// The drawn congruence: strips and the certificates of the congruence and of the weights.
#[derive(Debug, Clone)]
pub struct CongruenceDrawing<F> {
    /// Positive-weight rational Bézier patches (homogeneous, weight first).
    pub patches: Vec<BezierPatch<F>>,
    /// The congruence's certificates, the per-strip "rulings are congruence lines" identity
    /// and the weight certificate.
    pub certificates: Vec<Certificate>,
}

fn empty<F: Scalar>(name: &str, r: &(F, F)) -> Result<(), DrawError> {
    if r.0 < r.1 {
        Ok(())
    } else {
        Err(DrawError::EmptyInterval(format!(
            "{name} = [{}, {}]",
            format_scalar(&r.0),
            format_scalar(&r.1)
        )))
    }
}

/// The congruence of `spec`, certified, drawn as strips (module docs) for `v ∈ v_values`,
/// `u ∈ u`, twist `σ` and the segment `λ ∈ lambda`.
///
/// # Errors
/// The construction's own errors ([`DrawError::Net`], [`DrawError::Generation`],
/// [`DrawError::OrderOne`]), [`DrawError::Input`] for malformed point lists,
/// [`DrawError::EmptyInterval`], [`DrawError::PointAtInfinity`].
pub fn congruence_strips<F: Scalar>(
    spec: &CongruenceSpec<F>,
    u: (F, F),
    v_values: &[F],
    twist: &F,
    lambda: (F, F),
) -> Result<CongruenceDrawing<F>, DrawError> {
    empty("u", &u)?;
    empty("λ", &lambda)?;
    let (p, q, mut certs) = match spec {
        CongruenceSpec::Net(kind, pts) => {
            if pts.len() != 4 {
                return Err(DrawError::Input(format!(
                    "a net needs four points (c₀, c₁, d₀, d₁ or Re c₀, Im c₀, Re c₁, Im c₁), got {}",
                    pts.len()
                )));
            }
            let four: [[F; 4]; 4] = core::array::from_fn(|k| pts[k].clone());
            let net = LineNet::from_points(*kind, &four)?;
            let (p, q) = net.line_points();
            (p, q, net.certify())
        }
        CongruenceSpec::CubicChords(a) => {
            let c = CubicChordCongruence::new(a.clone())?;
            let k = |var: usize| -> [MPoly<F>; 4] {
                let t = MPoly::var(2, var);
                let mut w = MPoly::constant(2, F::one());
                let mut out: [MPoly<F>; 4] = core::array::from_fn(|_| MPoly::zero(2));
                for ak in a {
                    for (o, x) in out.iter_mut().zip(ak) {
                        *o = &*o + &w.scale(x);
                    }
                    w = &w * &t;
                }
                out
            };
            (k(0), k(1), c.certify())
        }
        CongruenceSpec::Collineation(a, b) => {
            let g = GeneratedNet::from_plane_collineation(a, b)?;
            let pt = |x: &[[F; 4]; 3]| -> [MPoly<F>; 4] {
                core::array::from_fn(|k| {
                    &(&MPoly::constant(2, x[0][k].clone()) + &MPoly::var(2, 0).scale(&x[1][k]))
                        + &MPoly::var(2, 1).scale(&x[2][k])
                })
            };
            (pt(a), pt(b), g.certify())
        }
        CongruenceSpec::PencilProjectivity(c, e0, e1) => {
            let g = GeneratedNet::from_pencil_projectivity(c.clone(), e0, e1)?;
            let net = g
                .line_net()
                .ok_or(DrawError::Net(NetError::DegenerateProjectivity))?;
            let (p, q) = net.line_points();
            (p, q, g.certify())
        }
        CongruenceSpec::OneN(g0, g1, curve) => {
            let k: [Poly<F>; 4] =
                core::array::from_fn(|j| Poly::new(curve.iter().map(|c| c[j].clone()).collect()));
            let c = OneNCongruence::new(g0.clone(), g1.clone(), k.clone())?;
            let p: [MPoly<F>; 4] = core::array::from_fn(|j| MPoly::from_poly(&k[j], 2, 0));
            let q: [MPoly<F>; 4] = core::array::from_fn(|j| {
                &MPoly::constant(2, g0[j].clone()) + &MPoly::var(2, 1).scale(&g1[j])
            });
            (p, q, c.certify())
        }
        CongruenceSpec::RuledSurfaceTangents(pc, qc, u0) => {
            let poly = |c: &[[F; 4]]| -> [Poly<F>; 4] {
                core::array::from_fn(|j| Poly::new(c.iter().map(|x| x[j].clone()).collect()))
            };
            let g = GeneratedNet::from_ruled_surface_tangents(&poly(pc), &poly(qc), u0)?;
            let net = g
                .line_net()
                .ok_or(DrawError::Net(NetError::DegenerateProjectivity))?;
            let (p, q) = net.line_points();
            (p, q, g.certify())
        }
        CongruenceSpec::Parametrized(c) => {
            let (p, q) = c.segment_points();
            (p, q, c.certify())
        }
    };
    // the drawn lines are the congruence lines p ∧ q (checked against the certified
    // congruence by the certificates above, which are stated for the same p, q or p ∧ q)
    let h = wedge(&p, &q);
    certs.push(Certificate::decide(
        "the drawn rulings p(u, v) ∨ q(u, v) are lines (p ∧ q ≢ 0)",
        h.iter().any(|x| !x.is_zero()),
        F::EXACT,
        || "p ∧ q ≡ 0".into(),
    ));
    let dom = Domain::new(u.0.clone(), u.1.clone(), lambda.0.clone(), lambda.1.clone())
        .map_err(|e| DrawError::EmptyInterval(e.to_string()))?;
    let mut patches = Vec::new();
    let mut bad = 0usize;
    for (k, vk) in v_values.iter().enumerate() {
        // v = v_k + σ u
        let uu = Poly::new(vec![F::zero(), F::one()]);
        let vv = Poly::new(vec![vk.clone(), twist.clone()]);
        let lam = MPoly::var(2, 1);
        let one_minus = &MPoly::constant(2, F::one()) - &lam;
        let mut x: Vec<MPoly<F>> = Vec::with_capacity(4);
        for j in 0..4 {
            let pj = p[j]
                .substitute_univariate(&[uu.clone(), vv.clone()])
                .map_err(|e| DrawError::Input(e.to_string()))?;
            let qj = q[j]
                .substitute_univariate(&[uu.clone(), vv.clone()])
                .map_err(|e| DrawError::Input(e.to_string()))?;
            x.push(
                &(&one_minus * &MPoly::from_poly(&pj, 2, 0))
                    + &(&lam * &MPoly::from_poly(&qj, 2, 0)),
            );
        }
        let sign = match sign_on_domain(&x[0], &dom, 4096) {
            Sign::Positive => F::one(),
            Sign::Negative => -F::one(),
            Sign::ZeroAt(z) | Sign::Changes(z, _) | Sign::Undecided(z) => {
                return Err(DrawError::PointAtInfinity {
                    strip: k,
                    u: format_scalar(&z[0]),
                    lambda: format_scalar(&z[1]),
                })
            }
        };
        let coords: Vec<MPoly<F>> = x.iter().map(|c| c.scale(&sign)).collect();
        let patch = patch_of(&coords, &dom).map_err(|e| DrawError::Input(e.to_string()))?;
        let split = split_patches_adaptive(vec![patch], SignRule::Positive, (6, 6))
            .map_err(|e| DrawError::Input(e.to_string()))?;
        bad += split.failed;
        patches.extend(split.pieces);
    }
    let n = patches.len();
    certs.push(Certificate::decide(
        format!("every Bernstein weight of the {n} strip patches is > 0"),
        bad == 0,
        F::EXACT,
        || format!("{bad} pieces keep a weight ≤ 0"),
    ));
    Ok(CongruenceDrawing {
        patches,
        certificates: certs,
    })
}

/// A rational point family `f(u, v)` (homogeneous, weight first; e.g. a focal sheet of a
/// congruence) as positive-weight rational Bézier patches on the rectangle
/// `[u₀, u₁] × [v₀, v₁]`, with the weight certificate.
///
/// # Errors
/// [`DrawError::EmptyInterval`], [`DrawError::PointAtInfinity`] (the weight vanishes on
/// the rectangle; `strip` is 0 and `lambda` holds the `v` of the zero), [`DrawError::Input`]
/// if the Bernstein conversion fails.
pub fn point_family_patches<F: Scalar>(
    f: &[MPoly<F>; 4],
    u: (F, F),
    v: (F, F),
) -> Result<(Vec<BezierPatch<F>>, Certificate), DrawError> {
    empty("u", &u)?;
    empty("v", &v)?;
    let dom =
        Domain::new(u.0, u.1, v.0, v.1).map_err(|e| DrawError::EmptyInterval(e.to_string()))?;
    let sign = match sign_on_domain(&f[0], &dom, 4096) {
        Sign::Positive => F::one(),
        Sign::Negative => -F::one(),
        Sign::ZeroAt(z) | Sign::Changes(z, _) | Sign::Undecided(z) => {
            return Err(DrawError::PointAtInfinity {
                strip: 0,
                u: format_scalar(&z[0]),
                lambda: format_scalar(&z[1]),
            })
        }
    };
    let coords: Vec<MPoly<F>> = f.iter().map(|c| c.scale(&sign)).collect();
    let patch = patch_of(&coords, &dom).map_err(|e| DrawError::Input(e.to_string()))?;
    let split = split_patches_adaptive(vec![patch], SignRule::Positive, (6, 6))
        .map_err(|e| DrawError::Input(e.to_string()))?;
    let n = split.pieces.len();
    let bad = split.failed;
    let cert = Certificate::decide(
        format!("every Bernstein weight of the {n} sheet patches is > 0"),
        bad == 0,
        F::EXACT,
        || format!("{bad} pieces keep a weight ≤ 0"),
    );
    Ok((split.pieces, cert))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn v4(a: [i64; 4]) -> [Rational; 4] {
        a.map(Rational::from)
    }

    #[test]
    fn strips_of_a_hyperbolic_net_and_of_cubic_chords() {
        let r = |n, d| Rational::from_ratio(n, d);
        let spec = CongruenceSpec::Net(
            NetKind::Hyperbolic,
            vec![
                v4([1, 0, 0, 0]),
                v4([0, 1, 0, 0]),
                v4([1, 0, 1, 1]),
                v4([0, 0, 1, 0]),
            ],
        );
        let d = congruence_strips(
            &spec,
            (r(-1, 1), r(1, 1)),
            &[r(0, 1), r(1, 2)],
            &r(1, 1),
            (r(0, 1), r(1, 1)),
        )
        .expect("strips");
        assert!(
            Certificate::all_hold(&d.certificates),
            "{:?}",
            d.certificates
        );
        assert!(d.patches.len() >= 2);
        let spec = CongruenceSpec::CubicChords([
            v4([1, 0, 0, 0]),
            v4([0, 1, 0, 0]),
            v4([0, 0, 1, 0]),
            v4([0, 0, 0, 1]),
        ]);
        let d = congruence_strips(
            &spec,
            (r(-1, 1), r(1, 1)),
            &[r(1, 2)],
            &r(1, 1),
            (r(0, 1), r(1, 1)),
        )
        .expect("chords");
        assert!(Certificate::all_hold(&d.certificates));
        // a segment reaching the point at infinity of the second axis
        let spec = CongruenceSpec::Net(
            NetKind::Hyperbolic,
            vec![
                v4([1, 0, 0, 0]),
                v4([0, 1, 0, 0]),
                v4([0, 2, 0, 1]),
                v4([0, 0, 1, 0]),
            ],
        );
        assert!(matches!(
            congruence_strips(
                &spec,
                (r(0, 1), r(1, 1)),
                &[r(0, 1)],
                &r(1, 1),
                (r(0, 1), r(1, 1))
            ),
            Err(DrawError::PointAtInfinity { .. })
        ));
        assert!(matches!(
            congruence_strips(
                &spec,
                (r(1, 1), r(0, 1)),
                &[r(0, 1)],
                &r(1, 1),
                (r(0, 1), r(1, 2))
            ),
            Err(DrawError::EmptyInterval(_))
        ));
    }
}
