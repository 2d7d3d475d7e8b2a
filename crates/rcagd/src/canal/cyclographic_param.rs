//! The cyclographic parametrization `Γ(s, t)` of Gruber §2.3 as a rational alternative when
//! the constructions in the spine parameter need a quadratic field
//! (docs/math/lines-and-canal.md, "Canal surfaces": cyclographic construction for quadratic
//! families; docs/math/sphere-families.md, "Canal surfaces by the cyclographic
//! parametrization").
//!
//! Peternell–Pottmann and Krasauskas parametrize the canal surface by the spine parameter
//! `p` and an angle; they are rational over `Q` only if `D = |ṁ|² − ṙ²` is a sum of two
//! squares over `Q(p)` — a rational point on every characteristic circle, rational in `p`.
//! The cyclographic map does not need one: for a family `k(p) = (m, r)(p)` of degree ≤ 2
//! the contact condition `⟨w(s, t), k̇(p)⟩ = 0` (`w` the isotropic direction on Ω) is linear
//! in `p`, so `p = N(s, t)/Dn(s, t)` is rational (Gruber (2.21)) and
//! `Γ(s, t) = π(k(p)) − r(p)·(w₁, w₂, w₃)/w₄` covers the whole envelope over `Q`
//! ([`QuadraticCanal`]). Its parameter rectangles are regions of Ω(s, t), not spine
//! intervals: a curve `p = const` is a conic of the `(s, t)` plane without a rational
//! parametrization in `p` exactly when `D` does not split — which is why the spine-parameter
//! constructions fail there.
//!
//! [`canal_surface_rational`] tries the spine-parameter constructions
//! ([`canal_surface_pole_free`]) first and falls back to `Γ` when they need `Q(√d)`.
//!
//! **Non-constant weight.** A rational family `k(p) = (M, R)(p)/W(p)` of degree `n ≤ 2`
//! whose weight is `W = c(p − ρ)ⁿ` (a single rational root of multiplicity `n`) becomes
//! polynomial under the Möbius change `p = ρ + 1/p'`: every homogeneous coordinate
//! `P(p)` becomes `P'(p') = p'ⁿ P((ρp' + 1)/p') = Σ_k P_k (ρp' + 1)^k p'^{n−k}`, and
//! `W' = c` is constant ([`polynomial_form`]). The spheres are the same, so `Γ(s, t)` (which
//! depends only on the family of spheres, not on its parameter) is built from the
//! polynomial form; the identity `P'(p') W(ρp' + 1, p') ≡ W' P(ρp' + 1, p')` (homogeneous
//! forms) is certified. Other weights (two distinct roots, an irreducible quadratic, a
//! simple root with `n = 2`) make the contact condition quadratic in `p` and are refused
//! (`IrrationalSplit`).

use super::envelope::{CanalBuild, CanalOptions, CanalSurface, QuadraticCanal};
use super::frame::{canal_surface_pole_free, EXPORT_SPLITS};
use super::{CanalError, CanalSpine};
use crate::error::format_scalar;
use crate::Certified;
use rcagd_algebra::{Certificate, Poly, Rational};
use rcagd_geom::weight_sign::{split_patches_adaptive, SignRule};
use rcagd_geom::BezierPatch;

/// A canal surface over `Q`: in the spine parameter, or by the cyclographic
/// parametrization when the former needs a quadratic field.
#[derive(Debug, Clone)]
pub enum RationalCanal {
    /// Peternell–Pottmann or Krasauskas, over `Q` ([`canal_surface_pole_free`]), with the
    /// certificates of no local self-intersection ([`super::check_canal_regularity`]) and
    /// of no global one ([`super::check_canal_embedded`]) on the domain of the options
    /// (none without a domain).
    Spine(Box<CanalSurface<Rational>>, Vec<Certificate>),
    /// `Γ(s, t)` on a rectangle of Ω(s, t) (module docs).
    Cyclographic(Box<CyclographicCanal>),
}

/// The cyclographic parametrization of a quadratic family on a rectangle of Ω(s, t).
#[derive(Debug, Clone)]
pub struct CyclographicCanal {
    surface: QuadraticCanal<Rational>,
    radicand: Rational,
    patches: Vec<BezierPatch<Rational>>,
    /// For a family with weight `c(p − ρ)ⁿ`: `ρ` and the identity residuals of the Möbius
    /// change (module docs).
    mobius: Option<(Rational, Vec<Poly<Rational>>)>,
    /// No local self-intersection on the rectangle
    /// ([`super::check_cyclographic_regularity`]).
    regular: Certificate,
    /// No global self-intersection on the rectangle
    /// ([`super::check_cyclographic_embedded`]).
    embedded: Certificate,
}

/// `p'ⁿ P((ρp' + 1)/p')` for `P` of degree `≤ n`.
fn mobius_poly(p: &Poly<Rational>, rho: &Rational, n: usize) -> Poly<Rational> {
    let lin = Poly::new(vec![Rational::from(1), rho.clone()]);
    let x = Poly::new(vec![Rational::from(0), Rational::from(1)]);
    (0..=n).fold(Poly::zero(), |acc, k| {
        let c = p.coeff(k);
        if c == Rational::from(0) {
            return acc;
        }
        &acc + &(&lin.pow(k as u32) * &x.pow((n - k) as u32)).scale(&c)
    })
}

/// The polynomial form of a family of degree `n ≤ 2` with weight `c(p − ρ)ⁿ` under the
/// Möbius change `p = ρ + 1/p'` (module docs): `Some((spine', ρ))`, `None` if the weight is
/// constant already or has another shape.
pub fn polynomial_form(spine: &CanalSpine<Rational>) -> Option<(CanalSpine<Rational>, Rational)> {
    let w = spine.weight();
    let dw = w.degree()?;
    let n = spine.homogeneous().iter().filter_map(Poly::degree).max()?;
    if dw == 0 || dw != n || n > 2 {
        return None;
    }
    let lead = w.coeff(n);
    let rho = -w.coeff(n - 1) / (Rational::from(n as i64) * lead.clone());
    // W = lead·(p − ρ)ⁿ exactly
    let root = Poly::new(vec![-rho.clone(), Rational::from(1)]);
    if w != &root.pow(n as u32).scale(&lead) {
        return None;
    }
    let m = spine.center_polys();
    let spine2 = CanalSpine::new(
        Poly::constant(lead),
        [
            mobius_poly(&m[0], &rho, n),
            mobius_poly(&m[1], &rho, n),
            mobius_poly(&m[2], &rho, n),
        ],
        mobius_poly(spine.radius_poly(), &rho, n),
    )
    .ok()?;
    Some((spine2, rho))
}

/// The residuals `P'(p')·W(ρp' + 1, p') − W'·P(ρp' + 1, p')` of the Möbius change
/// (homogeneous forms of degree `n`; all zero when the two families agree).
fn mobius_residuals(
    old: &CanalSpine<Rational>,
    new: &CanalSpine<Rational>,
    rho: &Rational,
) -> Vec<Poly<Rational>> {
    let n = old
        .homogeneous()
        .iter()
        .filter_map(Poly::degree)
        .max()
        .unwrap_or(0);
    let (ho, hn) = (old.homogeneous(), new.homogeneous());
    let w_old = mobius_poly(&ho[0], rho, n);
    (1..5)
        .map(|k| &(&hn[k] * &w_old) - &(&mobius_poly(&ho[k], rho, n) * &hn[0]))
        .collect()
}

impl CyclographicCanal {
    /// `Γ(s, t)` and its reparametrization.
    pub fn surface(&self) -> &QuadraticCanal<Rational> {
        &self.surface
    }

    /// The radicand `d` of the field `Q(√d)` the spine-parameter constructions need.
    pub fn radicand(&self) -> &Rational {
        &self.radicand
    }

    /// The Bézier pieces of `Γ` on the rectangle, every Bernstein weight positive.
    pub fn patches(&self) -> &[BezierPatch<Rational>] {
        &self.patches
    }
}

impl Certified for CyclographicCanal {
    /// The identities of [`QuadraticCanal`] (`Γ` lies on the sphere `k(p(s, t))` and on its
    /// characteristic plane; `w ⊥ k̇`), and the positive weights of the pieces.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.surface.certify();
        out.push(self.regular.clone());
        out.push(self.embedded.clone());
        if let Some((rho, res)) = &self.mobius {
            out.push(Certificate::decide(
                format!(
                    "the family with weight c(p − ({rho}))ⁿ is the polynomial family of p' = 1/(p − ({rho})): P'(p')·W(ρp' + 1, p') ≡ W'·P(ρp' + 1, p') for the centre and the radius"
                ),
                res.iter().all(Poly::is_zero),
                true,
                || format!("{} non-zero residuals", res.iter().filter(|r| !r.is_zero()).count()),
            ));
        }
        let n = self.patches.len();
        let ok = self
            .patches
            .iter()
            .all(|p| p.weights().iter().all(|w| *w > Rational::from(0)));
        out.push(Certificate::decide(
            format!(
                "every Bernstein weight of the {n} pieces of Γ is > 0 (no pole on the rectangle)"
            ),
            ok,
            true,
            || "a piece has a weight ≤ 0".to_string(),
        ));
        out
    }
}

/// The canal surface of `spine` over `Q`: [`canal_surface_pole_free`] when it is rational;
/// when it needs `Q(√d)` and the family is polynomial of degree ≤ 2, the cyclographic
/// parametrization `Γ(s, t)` on `cyclographic_domain = [s₀, s₁, t₀, t₁]` (module docs).
///
/// A surface in the spine parameter is checked for local self-intersections on the domain of
/// `options` ([`super::check_canal_regularity`]) and for global ones (no two characteristic
/// discs meet, [`super::check_canal_embedded`]), `Γ` for local ones on its rectangle
/// ([`super::check_cyclographic_regularity`]) and for global ones (no two characteristic
/// discs over the spine parameters the rectangle reaches meet,
/// [`super::check_cyclographic_embedded`]).
///
/// # Errors
/// The errors of [`canal_surface_pole_free`]; [`CanalError::SingularCanal`] where the
/// surface in the spine parameter intersects itself locally on the domain of `options`;
/// [`CanalError::CanalSelfIntersects`] where two of its characteristic discs meet
/// (globally), [`CanalError::CanalPartsNotApart`] where that is undecided;
/// [`CanalError::SingularCyclographic`] where `Γ` is singular on the rectangle;
/// [`CanalError::CyclographicDiscsMeet`] or [`CanalError::CanalPartsNotApart`] where two
/// characteristic discs over the spine parameters of the rectangle meet or could not be
/// shown apart;
/// [`CanalError::IrrationalSplit`] when the
/// spine-parameter constructions need `Q(√d)` and `Γ` does not apply (degree > 2 or a
/// non-constant weight); [`CanalError::CyclographicDomainNeeded`] when `Γ` applies but no
/// rectangle is given; [`CanalError::InvalidArgument`] for an empty rectangle or one where
/// `Γ` has a pole.
pub fn canal_surface_rational(
    spine: &CanalSpine<Rational>,
    options: &CanalOptions,
    cyclographic_domain: Option<&[Rational; 4]>,
) -> Result<RationalCanal, CanalError> {
    let radicand = match canal_surface_pole_free(spine, options)? {
        CanalBuild::Rational(s) => {
            // no local and no global self-intersection on the spine domain (decided exactly)
            let regular = match &options.domain {
                Some((a, b)) => vec![
                    super::regularity::check_canal_regularity(spine, (a, b))?,
                    super::canal_global::check_canal_embedded(spine, (a, b))?,
                ],
                None => Vec::new(),
            };
            return Ok(RationalCanal::Spine(Box::new(s), regular));
        }
        CanalBuild::Extension { radicand, .. } => radicand,
    };
    let (surface, mobius, family) = match QuadraticCanal::from_spine(spine) {
        Ok(s) => (s, None, spine.clone()),
        Err(_) => {
            let irr = || CanalError::IrrationalSplit {
                radicand: format_scalar(&radicand),
            };
            let (poly, rho) = polynomial_form(spine).ok_or_else(irr)?;
            let s = QuadraticCanal::from_spine(&poly).map_err(|_| irr())?;
            let res = mobius_residuals(spine, &poly, &rho);
            (s, Some((rho, res)), poly)
        }
    };
    let Some([s0, s1, t0, t1]) = cyclographic_domain else {
        return Err(CanalError::CyclographicDomainNeeded {
            radicand: format_scalar(&radicand),
        });
    };
    if s0 >= s1 || t0 >= t1 {
        return Err(CanalError::InvalidArgument(format!(
            "empty rectangle [{}, {}] × [{}, {}] of Ω(s, t)",
            format_scalar(s0),
            format_scalar(s1),
            format_scalar(t0),
            format_scalar(t1)
        )));
    }
    let patch = surface.patch((s0, s1), (t0, t1))?;
    let split = split_patches_adaptive(vec![patch], SignRule::Positive, EXPORT_SPLITS)
        .map_err(|e| CanalError::InvalidArgument(e.to_string()))?;
    if split.failed > 0 {
        return Err(CanalError::InvalidArgument(format!(
            "Γ(s, t) has a pole on the rectangle [{}, {}] × [{}, {}]: its weight Dn(s, t)²·(1 + s² + t²) vanishes where the spine parameter p = N/Dn is infinite — choose a rectangle off the curve Dn = 0",
            format_scalar(s0),
            format_scalar(s1),
            format_scalar(t0),
            format_scalar(t1)
        )));
    }
    let rect = [s0.clone(), s1.clone(), t0.clone(), t1.clone()];
    let regular =
        super::regularity::check_cyclographic_regularity(&family, surface.parameter(), &rect)?;
    let embedded =
        super::canal_global::check_cyclographic_embedded(&family, surface.parameter(), &rect)?;
    Ok(RationalCanal::Cyclographic(Box::new(CyclographicCanal {
        surface,
        radicand,
        patches: split.pieces,
        mobius,
        regular,
        embedded,
    })))
}

/// A canal surface along a chain of spine pieces ([`canal_chain_rational`]): one surface
/// over `Q` in the spine parameter per piece, with the certificates of every piece and the
/// chain's global one.
#[derive(Debug, Clone)]
pub struct CanalChain {
    /// The surface of each piece (its domain the piece's interval).
    pub pieces: Vec<CanalSurface<Rational>>,
    /// The last end joins the first start smoothly (a closed tube).
    pub closed: bool,
    /// Per piece: no local self-intersection ([`super::check_canal_regularity`]); then the
    /// chain: no two characteristic discs at distinct points meet
    /// ([`super::check_canal_chain_embedded`]).
    regular: Vec<Certificate>,
}

impl Certified for CanalChain {
    /// Every piece's own certificates (prefixed `spine piece k:`), its local regularity,
    /// and the global check of the whole chain.
    fn certify(&self) -> Vec<Certificate> {
        let mut out: Vec<Certificate> = Vec::new();
        for (k, s) in self.pieces.iter().enumerate() {
            out.extend(s.certify().into_iter().map(|c| Certificate {
                property: format!("spine piece {k}: {}", c.property),
                ..c
            }));
        }
        out.extend(self.regular.iter().cloned());
        out
    }
}

/// The canal surface along a chain of spine pieces `(m_k, r_k)` on `[a_k, b_k]`, joined end
/// to start, exact over `Q`: each piece by [`canal_surface_pole_free`] on its interval
/// (the options' domain is replaced by it), no local self-intersection certified per piece
/// ([`super::check_canal_regularity`]), every joint checked to run on smoothly (the same
/// sphere, tangent direction and `r dr/dσ`, decided exactly,
/// [`super::canal_joint_defect`]; a corner would make the surfaces overlap on its inner
/// side), and no two characteristic discs at distinct points of the whole chain meeting
/// ([`super::check_canal_chain_embedded`]; across the joints and, when the last end joins
/// the first start smoothly, through the seam) — docs/math/pipes.md#canal-global, "Chains
/// and closed spines".
///
/// # Errors
/// [`CanalError::InvalidArgument`] for an empty chain; [`CanalError::SpinePiece`] around
/// the errors of one piece (its construction needs `Q(√d)`: `IrrationalSplit`; it is
/// locally singular: `SingularCanal`, …); [`CanalError::DegenerateSpine`] naming a joint
/// whose spine ends do not meet or form a corner (or where a weight or tangent vanishes),
/// [`CanalError::InvalidArgument`] naming a joint where the radius or its slope
/// `r dr/dσ` jumps; [`CanalError::CanalSelfIntersects`] naming the two intervals (and
/// pieces) whose discs meet, with an exact witness pair; [`CanalError::CanalPartsNotApart`]
/// where that stays undecided.
pub fn canal_chain_rational(
    chain: &[(CanalSpine<Rational>, (Rational, Rational))],
    options: &CanalOptions,
) -> Result<CanalChain, CanalError> {
    use super::canal_global::{canal_joint_defect, JointDefect};
    if chain.is_empty() {
        return Err(CanalError::InvalidArgument("no spine piece".into()));
    }
    let piece_err = |k: usize| {
        move |e: CanalError| CanalError::SpinePiece {
            index: k,
            source: Box::new(e),
        }
    };
    for k in 0..chain.len() - 1 {
        let ((first, (_, end)), (second, (start, _))) = (&chain[k], &chain[k + 1]);
        if let Some(d) = canal_joint_defect(first, end, second, start) {
            let text = format!(
                "joint {k}/{} (the end t = {} of spine piece {k} and the start t = {} of piece {}): {d}",
                k + 1,
                format_scalar(end),
                format_scalar(start),
                k + 1
            );
            return Err(match d {
                JointDefect::RadiusJump | JointDefect::SlopeJump => {
                    CanalError::InvalidArgument(text)
                }
                _ => CanalError::DegenerateSpine(text),
            });
        }
    }
    let mut pieces = Vec::with_capacity(chain.len());
    let mut regular = Vec::with_capacity(chain.len() + 1);
    for (k, (spine, (a, b))) in chain.iter().enumerate() {
        let opts = CanalOptions {
            domain: Some((a.clone(), b.clone())),
            ..options.clone()
        };
        match canal_surface_pole_free(spine, &opts).map_err(piece_err(k))? {
            CanalBuild::Rational(s) => pieces.push(s),
            CanalBuild::Extension { radicand, .. } => {
                return Err(piece_err(k)(CanalError::IrrationalSplit {
                    radicand: format_scalar(&radicand),
                }))
            }
        }
        let local =
            super::regularity::check_canal_regularity(spine, (a, b)).map_err(piece_err(k))?;
        regular.push(Certificate {
            property: format!("spine piece {k}: {}", local.property),
            ..local
        });
    }
    let (last, first) = (&chain[chain.len() - 1], &chain[0]);
    let closed = canal_joint_defect(&last.0, &last.1 .1, &first.0, &first.1 .0).is_none();
    regular.push(super::canal_global::check_canal_chain_embedded(chain)?);
    Ok(CanalChain {
        pieces,
        closed,
        regular,
    })
}
