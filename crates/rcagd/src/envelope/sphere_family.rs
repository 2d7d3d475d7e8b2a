//! The envelope of a two-parameter sphere family from a line net and support functions
//! (D. Gruber, "Rationale Parametrisierungen von Kugelhüllflächen", 2008, §3.1–3.5).
//!
//! **Cyclographic model.** A sphere with centre `m` and signed radius `r` is the point
//! `Φ = (m, r) ∈ R^{3,1}`; a two-parameter family is a surface `Φ(u, v)`. The ideal points of
//! `R^{3,1}` form the 3-space `ω` with the absolute quadric `Ω: y₁² + y₂² + y₃² − y₄² = 0`,
//! parametrized by `w(s, t) = (2s, 2t, 1 − s² − t², 1 + s² + t²)` (Gruber (3.4)). An
//! isotropic line through `Φ` with direction `w ∈ Ω` meets `x₄ = 0` in
//! `Φ₁..₃ − Φ₄ (w₁, w₂, w₃)/w₄`, a point of the sphere `Φ` (Gruber §1.2). It is a point of the
//! envelope iff `w` is Lorentz-orthogonal to the tangent plane of `Φ`, i.e. `w` lies on the
//! ideal line `h` of the normal plane (Gruber §3.1.2). Each `h` meets Ω in two points: the
//! two sheets of the envelope (one contact point with each sphere per sheet).
//!
//! **Construction of §3.2.** Choose the normal lines `h(u, v)` to form a regular line net
//! ([`LineNet`]); the tangent ideal lines are the polars `g = E h`, spanned by the polar
//! planes `e = D c`, `f = D d` of the points `c`, `d` spanning `h`
//! (`D = diag(1, 1, 1, −1)`). Support functions `a`, `b` fix the tangent hyperplanes
//! `eᵀx = a`, `fᵀx = b`; the surface `Φ` they envelope solves the linear system (3.7):
//!
//! ```text
//! eᵀx = a,  e_uᵀx = a_u,  e_vᵀx = a_v,   fᵀx = b,  f_uᵀx = b_u,  f_vᵀx = b_v.
//! ```
//!
//! It is consistent (rank 4) under the conditions of the net type:
//! hyperbolic `e_v = f_u = 0`, `a_v = b_u = 0` ((3.10), (3.11)); elliptic the same with
//! `d = c̄` and `b = ā` (the printed (3.44) `e_v = conj(f_u)` is vacuous; the intended
//! condition is `f(v) = ē(v)`, `b = ā`: see `docs/math/sphere-families.md#elliptic`);
//! parabolic `e_v = 0`, `e_u = f_v`, `a_v = 0`, `a_u = b_v` ((3.54), (3.55)). For the nets of
//! [`LineNet`] the determinant of the four independent rows is the constant
//! `det(c₀, c₁, d₀, d₁)` (up to sign), so `Φ` is polynomial in the net parameters.
//! For elliptic nets the system is solved over R in `(m, n)`, `u = m − i n`: the real and
//! imaginary parts of `eᵀx = a` and `e_uᵀx = a_u` (the `f` rows are their conjugates).
//!
//! **Reparametrization (3.16).** The net is a fibration of `ω`: the net line through
//! `w(s, t)` has rational parameters `(u, v)(s, t)` ([`LineNet::parameters_of_point`]), so
//! `Φ(s, t) = Φ(u(s, t), v(s, t))` and
//!
//! ```text
//! Ψ(s, t) = π(Φ) − Φ₄ · (w₁, w₂, w₃)/w₄
//! ```
//!
//! is a rational parametrization of the whole envelope (both sheets: the two points of
//! `h ∩ Ω` are two parameter points `(s, t)`, exchanged by [`SphereFamilyEnvelope::other_sheet`]).
//!
//! **Certificates** (exact polynomial identities for exact scalars): the system (3.7) and the
//! tangency (3.8) `eᵀΦ_u = eᵀΦ_v = fᵀΦ_u = fᵀΦ_v = 0` in the net parameters; the
//! consistency conditions of the net type; the fibration `M(h(u(s,t), v(s,t))) w(s,t) ≡ 0`;
//! and the envelope property
//! `|Ψ − π(Φ)|² ≡ Φ₄²`, `⟨Ψ − π(Φ), ∂ₛπ(Φ)⟩ + Φ₄ ∂ₛΦ₄ ≡ 0`, `⟨Ψ − π(Φ), ∂ₜπ(Φ)⟩ + Φ₄ ∂ₜΦ₄ ≡ 0`
//! (the envelope point lies on its sphere `S` and on `S_s`, `S_t` of (3.1)–(3.3), with the
//! sign of (3.3) corrected to `⟨x − m, m_u⟩ + r r_u = 0`: see
//! `docs/math/sphere-families.md#sign`).
//!
//! **Direct envelope (§3.1.1).** [`SphereFamilyEnvelope::direct_envelope`] intersects the
//! line `S_u ∩ S_v` with the sphere `S` at given net parameters — a quadratic equation,
//! solved in the square-root extension — as an independent cross-check of `Ψ`.

use crate::error::format_scalar;
use crate::lines::net::{
    cst2, fibration_certificate, omega_form, omega_parametrization, CPoly, NetParameters,
};
use crate::lines::{AxisPosition, LineNet, NetError, NetKind, SqrtScalar};
use crate::pn::poly::{
    cancel_common, cancel_gcd, det4, gcd2, identity_cert, mag, normalize_content, patch_of,
    sign_on_domain, zero_cert, Domain, Sign,
};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::weight_sign::{split_patches_adaptive, SignRule};
use rcagd_geom::BezierPatch;
use thiserror::Error;

/// Errors of the sphere-family envelope. Every variant names the violated precondition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum SphereFamilyError {
    /// The net is degenerate.
    #[error(transparent)]
    Net(#[from] NetError),
    /// The support functions violate the consistency condition of the net type.
    #[error("inconsistent support functions: {0}")]
    InconsistentSupport(String),
    /// The system (3.7) has no unique solution.
    #[error("the linear system (3.7) is singular: det = 0 (Gruber §3.2 needs rank 4)")]
    SingularSystem,
    /// `Φ` is a point or a curve (its two partial derivatives are dependent), so the family
    /// is at most one-parametric.
    #[error("the sphere family degenerates: Φ_u ∧ Φ_v ≡ 0 (constant or linear support functions give a point or a curve, Gruber §3.3)")]
    DegenerateFamily,
    /// The envelope's denominator vanishes on the requested parameter rectangle.
    #[error("the envelope has a pole in the parameter rectangle: {0}")]
    PoleInDomain(String),
    /// A parameter point where the envelope (or the net line, or the sphere) is undefined.
    #[error("undefined at the parameters: {0}")]
    Undefined(String),
    /// The characteristic points of the sphere are not real (the tangent plane of `Φ` is
    /// timelike: `h` misses Ω, Gruber §3.1.2).
    #[error("no real envelope point: {0}")]
    NoRealEnvelope(String),
    /// A parameter rectangle is empty.
    #[error("invalid parameter rectangle: {0}")]
    InvalidDomain(String),
}

impl SphereFamilyError {
    /// The input of [`SphereFamilyEnvelope::from_data`] that violates the precondition, as a
    /// recipe names it: `"points"` (the net), `"a"`, `"a_imaginary"`, `"b"` (the support
    /// functions) or `"domain"`.
    pub fn input(&self) -> &'static str {
        match self {
            SphereFamilyError::Net(_)
            | SphereFamilyError::SingularSystem
            | SphereFamilyError::Undefined(_)
            | SphereFamilyError::NoRealEnvelope(_) => "points",
            SphereFamilyError::DegenerateFamily => "a",
            SphereFamilyError::PoleInDomain(_) | SphereFamilyError::InvalidDomain(_) => "domain",
            SphereFamilyError::InconsistentSupport(m) => {
                if m.starts_with("b_u")
                    || m.starts_with("b ≠")
                    || m.starts_with("a_u ≠ b_v")
                    || m.starts_with("the support function b")
                {
                    "b"
                } else if m.starts_with("a_v") {
                    "a"
                } else if m
                    .starts_with("the support functions of a hyperbolic or parabolic net are real")
                {
                    "a_imaginary"
                } else {
                    "points"
                }
            }
        }
    }
}

/// A support function `a(u, v) = (re + i·im)/den` (Gruber (3.6)): real part and, for
/// elliptic nets, imaginary part of the numerator, and a real denominator (1 for a
/// polynomial support function), polynomials in the net parameters `u` = variable 0,
/// `v` = variable 1. A rational support function gives a rational family `Φ`: the
/// equations of (3.7) are multiplied by their denominators (`a_u = (p_u q − p q_u)/q²`).
#[derive(Debug, Clone)]
pub struct Support<F> {
    /// Real part of the numerator.
    pub re: MPoly<F>,
    /// Imaginary part of the numerator (zero for hyperbolic and parabolic nets).
    pub im: MPoly<F>,
    /// The real denominator (the constant 1 for a polynomial support function).
    pub den: MPoly<F>,
}

impl<F: Scalar> Support<F> {
    /// A real support function.
    pub fn real(re: MPoly<F>) -> Self {
        Support {
            re,
            im: MPoly::zero(2),
            den: MPoly::constant(2, F::one()),
        }
    }

    /// A complex support function `re + i·im`.
    pub fn complex(re: MPoly<F>, im: MPoly<F>) -> Self {
        Support {
            re,
            im,
            den: MPoly::constant(2, F::one()),
        }
    }

    /// This support function divided by the real polynomial `den` (a rational support
    /// function; `den` must not vanish identically, else [`SphereFamilyEnvelope::new`]
    /// refuses it).
    pub fn over(self, den: MPoly<F>) -> Self {
        Support {
            den: &self.den * &den,
            ..self
        }
    }

    /// `true` for a polynomial support function (constant denominator).
    pub fn is_polynomial(&self) -> bool {
        self.den.total_degree().unwrap_or(0) == 0
    }

    /// The univariate polynomial `Σ cₖ xᵏ` (real coefficients, lowest first) in variable `var`.
    pub fn univariate(coeffs: &[F], var: usize) -> Self {
        let mut p = MPoly::zero(2);
        for (k, c) in coeffs.iter().enumerate() {
            let mut e = [0u32; 2];
            if let Some(x) = e.get_mut(var) {
                *x = k as u32;
            }
            p = &p + &MPoly::monomial(2, &e, c.clone());
        }
        Support::real(p)
    }

    /// `Σ g[i][j] uⁱ vʲ` from a grid of power coefficients.
    pub fn from_grid(grid: &[Vec<F>]) -> Self {
        Support::real(grid_poly(grid))
    }

    /// The conjugate support function in the second parameter, `ā(v)` (the `b` of an
    /// elliptic net for the support function `a(u)`, Gruber (3.44) corrected).
    pub fn conjugate_in_v(&self) -> Self {
        Support {
            re: swap_vars(&self.re),
            im: -&swap_vars(&self.im),
            den: swap_vars(&self.den),
        }
    }

    fn as_cpoly(&self) -> CPoly<F> {
        CPoly {
            re: self.re.clone(),
            im: self.im.clone(),
        }
    }

    /// The support function with each coefficient mapped by `f`.
    pub fn map<G: Scalar>(&self, f: impl Fn(&F) -> G + Copy) -> Support<G> {
        Support {
            re: self.re.map(f),
            im: self.im.map(f),
            den: self.den.map(f),
        }
    }

    /// The numerators of the derivative `∂a/∂x_i = (p_i q − p q_i)/q²` (real and imaginary
    /// parts; the denominator is `q²`).
    fn derivative_numerators(&self, i: usize) -> (MPoly<F>, MPoly<F>) {
        let q = &self.den;
        let qi = q.partial(i);
        (
            &(&self.re.partial(i) * q) - &(&self.re * &qi),
            &(&self.im.partial(i) * q) - &(&self.im * &qi),
        )
    }
}

/// The subcases of Gruber chapter 3 (net type and position of the axes with respect to Ω).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Subcase {
    /// §3.3.1: hyperbolic, both axes passants.
    HyperbolicPassantPassant,
    /// §3.3.2: hyperbolic, both axes secants.
    HyperbolicSecantSecant,
    /// §3.3.3: hyperbolic, both axes tangents.
    HyperbolicTangentTangent,
    /// §3.3.4: hyperbolic, a secant and a passant (not polar).
    HyperbolicSecantPassant,
    /// §3.3.4 (second example): a secant and a passant polar with respect to Ω.
    HyperbolicPolar,
    /// §3.3.5: hyperbolic, a secant and a tangent.
    HyperbolicSecantTangent,
    /// §3.3.6: hyperbolic, a passant and a tangent.
    HyperbolicPassantTangent,
    /// §3.4.1: elliptic, secant axes.
    EllipticSecant,
    /// §3.4.2: elliptic, tangent axes.
    EllipticTangent,
    /// §3.5.1: parabolic, the axis a passant.
    ParabolicPassant,
    /// §3.5.2: parabolic, the axis a secant.
    ParabolicSecant,
    /// §3.5.3 a): parabolic, tangent axis, the pencil at the contact point in the tangent
    /// plane of Ω.
    ParabolicTangentA,
    /// §3.5.3 b): parabolic, tangent axis, the pencil plane cuts Ω in a conic.
    ParabolicTangentB,
}

impl Subcase {
    /// The section of Gruber chapter 3 (`"3.3.1"`, …, `"3.5.3b"`; `"3.3.4p"` for the polar
    /// variant).
    pub fn section(&self) -> &'static str {
        match self {
            Subcase::HyperbolicPassantPassant => "3.3.1",
            Subcase::HyperbolicSecantSecant => "3.3.2",
            Subcase::HyperbolicTangentTangent => "3.3.3",
            Subcase::HyperbolicSecantPassant => "3.3.4",
            Subcase::HyperbolicPolar => "3.3.4p",
            Subcase::HyperbolicSecantTangent => "3.3.5",
            Subcase::HyperbolicPassantTangent => "3.3.6",
            Subcase::EllipticSecant => "3.4.1",
            Subcase::EllipticTangent => "3.4.2",
            Subcase::ParabolicPassant => "3.5.1",
            Subcase::ParabolicSecant => "3.5.2",
            Subcase::ParabolicTangentA => "3.5.3a",
            Subcase::ParabolicTangentB => "3.5.3b",
        }
    }

    /// The subcase of a net (Gruber §3.3–3.5; the classification of 3.4.1 and of 3.5.3 b
    /// corrected, see `docs/math/sphere-families.md#classification`).
    pub fn of_net<F: Scalar>(net: &LineNet<F>) -> Subcase {
        use AxisPosition::*;
        let pos = net.axis_positions();
        let p0 = pos.first().copied().unwrap_or(Passant);
        let p1 = pos.get(1).copied().unwrap_or(p0);
        match net.kind() {
            NetKind::Hyperbolic => match (p0, p1) {
                (Passant, Passant) => Subcase::HyperbolicPassantPassant,
                (Secant, Secant) => Subcase::HyperbolicSecantSecant,
                (Tangent, Tangent) => Subcase::HyperbolicTangentTangent,
                (Secant, Passant) | (Passant, Secant) => {
                    if net.axes_polar() {
                        Subcase::HyperbolicPolar
                    } else {
                        Subcase::HyperbolicSecantPassant
                    }
                }
                (Secant, Tangent) | (Tangent, Secant) => Subcase::HyperbolicSecantTangent,
                (Passant, Tangent) | (Tangent, Passant) => Subcase::HyperbolicPassantTangent,
            },
            NetKind::Elliptic => match p0 {
                Tangent => Subcase::EllipticTangent,
                _ => Subcase::EllipticSecant,
            },
            NetKind::Parabolic => match p0 {
                Passant => Subcase::ParabolicPassant,
                Secant => Subcase::ParabolicSecant,
                Tangent => match net.parabolic_tangent_case_a() {
                    Some(false) => Subcase::ParabolicTangentB,
                    _ => Subcase::ParabolicTangentA,
                },
            },
        }
    }
}

/// The two points of the direct envelope `S ∩ S_u ∩ S_v` (Gruber §3.1.1) over the
/// square-root extension of the scalar.
#[derive(Debug, Clone, PartialEq)]
pub struct DirectEnvelope<E> {
    /// `m + y₀ + λ n`.
    pub plus: [E; 3],
    /// `m + y₀ − λ n`.
    pub minus: [E; 3],
}

/// The envelope of the sphere family of a line net and two support functions (module docs).
#[derive(Debug, Clone)]
pub struct SphereFamilyEnvelope<F> {
    net: LineNet<F>,
    a: Support<F>,
    b: Support<F>,
    /// `Φ = phi/phi_den` in the net parameters.
    phi: [MPoly<F>; 4],
    phi_den: MPoly<F>,
    params: NetParameters<F>,
    /// `Φ(s, t) = phi_st/phi_st_den`.
    phi_st: [MPoly<F>; 4],
    phi_st_den: MPoly<F>,
    /// Homogeneous `(W, X, Y, Z)` of `Ψ(s, t)`.
    psi: [MPoly<F>; 4],
    /// The common factors divided out by the construction ([`Reductions`]): recorded by
    /// an exact build, replayed by an inexact one built along them.
    reductions: Reductions<F>,
}

/// The common polynomial factors the construction of a [`SphereFamilyEnvelope`] divides
/// out, in order: the gcd of `Φ`'s numerators and denominator, the gcds of the two net
/// parameter fractions, the factors cancelled from `Φ(s, t)` and from `Ψ(s, t)`, and (when
/// the other sheet was asked for) from `Ψ₂(s, t)`.
///
/// Whether a polynomial divides another is a decision of exact algebra: over `Q` the gcd
/// and the trial divisions decide it; in `f64` a rounded coefficient makes every
/// candidate fail or a near-factor pass. So an exact build records the divisors
/// ([`SphereFamilyEnvelope::reductions`]) and an `f64` build of the same input divides by
/// the same (converted) polynomials ([`SphereFamilyEnvelope::new_along`]), each division
/// accepted only if its remainder is rounding (`div_exact`'s tolerance): the same
/// construction, the same degrees, the same control points up to rounding.
#[derive(Debug, Clone)]
pub struct Reductions<F> {
    /// The factors divided out by each step of the construction, in order (a gcd, or the
    /// candidate factors of a trial division with their multiplicity; empty where nothing
    /// was divided).
    pub divisors: Vec<Vec<MPoly<F>>>,
    /// The factors divided out of the other sheet `Ψ₂(s, t)`, if recorded
    /// ([`SphereFamilyEnvelope::with_other_sheet_divisor`]).
    pub other_sheet: Option<Vec<MPoly<F>>>,
    /// The monomials of each polynomial after each step (of the exact build): a term an
    /// inexact build has beyond them is a rounding residue of an exact 0 (e.g. a
    /// coefficient of Cramer's rule that cancels over Q) and is dropped.
    pub supports: Vec<Vec<Vec<Vec<u32>>>>,
    /// The monomials of the other sheet's coordinates, if recorded.
    pub other_sheet_support: Option<Vec<Vec<Vec<u32>>>>,
}

impl<F: Scalar> Reductions<F> {
    /// The divisors converted to another scalar type.
    pub fn map<G: Scalar>(&self, f: impl Fn(&F) -> G + Copy) -> Reductions<G> {
        Reductions {
            divisors: self
                .divisors
                .iter()
                .map(|v| v.iter().map(|p| p.map(f)).collect())
                .collect(),
            other_sheet: self
                .other_sheet
                .as_ref()
                .map(|v| v.iter().map(|p| p.map(f)).collect()),
            supports: self.supports.clone(),
            other_sheet_support: self.other_sheet_support.clone(),
        }
    }
}

/// The number of reduction steps of [`SphereFamilyEnvelope::new`].
const REDUCTION_STEPS: usize = 5;

/// The monomials of each polynomial of a step.
type Monomials = Vec<Vec<Vec<u32>>>;

/// The replay of one step: its factors and, if recorded, its monomials.
type Replay<'a, F> = Option<(&'a Vec<MPoly<F>>, Option<&'a Monomials>)>;

/// One reduction step: with `replay`, divides every polynomial by each recorded factor in
/// turn (an error if one does not divide up to rounding); else runs `reduce` (the exact
/// construction's own gcd or trial division) and records the factors it divided by.
fn reduction_step<F: Scalar>(
    polys: &mut [MPoly<F>],
    replay: Replay<'_, F>,
    record: &mut Vec<Vec<MPoly<F>>>,
    reduce: impl FnOnce(&mut [MPoly<F>]) -> Vec<MPoly<F>>,
) -> Result<(), SphereFamilyError> {
    let factors = match replay {
        Some((fs, support)) => {
            for d in fs {
                if d.total_degree().unwrap_or(0) == 0 {
                    continue;
                }
                // scaled to largest coefficient 1: `div_exact`'s inexact tolerance is
                // relative to |p|·|d|, which a divisor with large coefficients inflates
                let big = d
                    .terms()
                    .map(|(_, c)| c.clone())
                    .max_by(|x, y| x.to_f64().abs().total_cmp(&y.to_f64().abs()));
                let unit = match big {
                    Some(c) if !F::EXACT && !c.is_zero() => d.scale(&(F::one() / c)),
                    _ => d.clone(),
                };
                let qs = polys
                    .iter()
                    .map(|p| replayed_quotient(p, &unit))
                    .collect::<Option<Vec<_>>>()
                    .ok_or_else(|| {
                        SphereFamilyError::Undefined(format!(
                            "the replayed exact common factor (step {}, degree {}) does not divide in this arithmetic",
                            record.len() + 1,
                            d.total_degree().unwrap_or(0)
                        ))
                    })?;
                polys.clone_from_slice(&qs);
            }
            if let Some(sup) = support {
                prune(polys, sup);
            }
            fs.clone()
        }
        None => reduce(polys),
    };
    record.push(factors);
    Ok(())
}

/// The monomials of each polynomial.
fn support_of<F: Scalar>(polys: &[MPoly<F>]) -> Vec<Vec<Vec<u32>>> {
    polys
        .iter()
        .map(|p| p.terms().map(|(e, _)| e.to_vec()).collect())
        .collect()
}

/// Drops the terms of each polynomial outside the exact build's monomials `support` (the
/// same number of polynomials, else nothing is dropped).
fn prune<F: Scalar>(polys: &mut [MPoly<F>], support: &[Vec<Vec<u32>>]) {
    if support.len() != polys.len() {
        return;
    }
    for (p, sup) in polys.iter_mut().zip(support) {
        let kept: Vec<(Vec<u32>, F)> = p
            .terms()
            .filter(|(e, _)| sup.iter().any(|x| x.as_slice() == *e))
            .map(|(e, c)| (e.to_vec(), c.clone()))
            .collect();
        if let Ok(q) = MPoly::from_terms(p.nvars(), kept) {
            *p = q;
        }
    }
}

/// The quotient `p / d` of a division that the exact build proved exact (a replayed
/// factor): exact scalars divide exactly (`div_exact`); inexact ones run the division
/// algorithm to the end, moving leading terms not divisible by `d`'s leading monomial to
/// a remainder, and accept the quotient if the remainder is rounding (at most `10⁻⁶` of
/// `p`'s largest coefficient: the decision that `d` divides was taken over Q, so the
/// remainder only tells a replay of another input; the quotient's accuracy is what the
/// float tests measure).
fn replayed_quotient<F: Scalar>(p: &MPoly<F>, d: &MPoly<F>) -> Option<MPoly<F>> {
    if F::EXACT {
        return crate::pn::poly::div_exact(p, d);
    }
    let nv = p.nvars().max(d.nvars()).max(2);
    let pad = |e: &[u32]| -> Vec<u32> {
        let mut v = e.to_vec();
        v.resize(nv.max(e.len()), 0);
        v
    };
    let (lde, ldc) = d.terms().last().map(|(e, c)| (pad(e), c.clone()))?;
    if ldc.is_zero() {
        return None;
    }
    let mut r = p.clone();
    let mut q = MPoly::zero(nv);
    let mut rem = 0.0f64;
    let mut guard = 0usize;
    while let Some((le, lc)) = r.terms().last().map(|(e, c)| (pad(e), c.clone())) {
        guard += 1;
        if guard > 1_000_000 {
            return None;
        }
        let t = MPoly::monomial(nv, &le, lc.clone());
        if le.iter().zip(&lde).any(|(a, b)| a < b) {
            rem = rem.max(lc.to_f64().abs());
            r = &r - &t;
            continue;
        }
        let e: Vec<u32> = le.iter().zip(&lde).map(|(a, b)| a - b).collect();
        let qt = MPoly::monomial(nv, &e, lc / ldc.clone());
        r = &r - &(&qt * d);
        // the leading term cancels up to rounding: drop what is left of it
        let left = r
            .terms()
            .find(|(e2, _)| pad(e2) == le)
            .map(|(_, c)| c.clone());
        if let Some(c) = left {
            r = &r - &MPoly::monomial(nv, &le, c);
        }
        q = &q + &qt;
    }
    (rem <= 1e-6 * mag(p)).then_some(q)
}

/// [`cancel_common`] returning the factors it divided out, with multiplicity (exact
/// scalars; for inexact ones [`cancel_common_checked`], recording none).
fn cancel_common_factors<F: Scalar>(
    polys: &mut [MPoly<F>],
    candidates: &[MPoly<F>],
) -> Vec<MPoly<F>> {
    if !F::EXACT {
        cancel_common_checked(polys, candidates);
        return Vec::new();
    }
    let mut out = Vec::new();
    for c in candidates {
        if c.total_degree().unwrap_or(0) == 0 {
            continue;
        }
        for _ in 0..cancel_common(polys, core::slice::from_ref(c)) {
            out.push(c.clone());
        }
    }
    out
}

/// [`cancel_gcd`] as a reduction step (exact scalars; a no-op recording nothing for
/// inexact ones).
fn cancel_gcd_step<F: Scalar>(polys: &mut [MPoly<F>]) -> Vec<MPoly<F>> {
    let g = cancel_gcd(polys);
    if F::EXACT && g.total_degree().unwrap_or(0) > 0 {
        vec![g]
    } else {
        Vec::new()
    }
}

fn grid_poly<F: Scalar>(grid: &[Vec<F>]) -> MPoly<F> {
    let mut p = MPoly::zero(2);
    for (i, row) in grid.iter().enumerate() {
        for (j, c) in row.iter().enumerate() {
            p = &p + &MPoly::monomial(2, &[i as u32, j as u32], c.clone());
        }
    }
    p
}

fn swap_vars<F: Scalar>(p: &MPoly<F>) -> MPoly<F> {
    let mut out = MPoly::zero(2);
    for (e, c) in p.terms() {
        let i = e.first().copied().unwrap_or(0);
        let j = e.get(1).copied().unwrap_or(0);
        out = &out + &MPoly::monomial(2, &[j, i], c.clone());
    }
    out
}

fn is_zero_poly<F: Scalar>(p: &MPoly<F>, scale: f64) -> bool {
    p.terms()
        .all(|(_, c)| crate::lines::is_small(c, scale.max(1.0)))
}

/// `p(x) = Σ cⱼ xʲ` (complex coefficients, polynomial in variable `var` only) at the complex
/// polynomial `x`.
fn complex_subst<F: Scalar>(p: &CPoly<F>, var: usize, x: &CPoly<F>) -> CPoly<F> {
    let deg =
        p.re.degree_in(var)
            .unwrap_or(0)
            .max(p.im.degree_in(var).unwrap_or(0));
    let mut acc = CPoly::real(MPoly::zero(2));
    let mut pw = CPoly::real(MPoly::constant(2, F::one()));
    for k in 0..=deg {
        let mut e = [0u32; 2];
        if let Some(z) = e.get_mut(var) {
            *z = k;
        }
        let c = CPoly {
            re: cst2(&p.re.coeff(&e)),
            im: cst2(&p.im.coeff(&e)),
        };
        acc = acc.add(&c.mul(&pw));
        pw = pw.mul(x);
    }
    acc
}

fn cdot4<F: Scalar>(a: &[CPoly<F>; 4], x: &[MPoly<F>; 4]) -> CPoly<F> {
    a.iter()
        .zip(x)
        .fold(CPoly::real(MPoly::zero(2)), |acc, (p, q)| {
            acc.add(&CPoly {
                re: &p.re * q,
                im: &p.im * q,
            })
        })
}

fn cpartial<F: Scalar>(p: &CPoly<F>, i: usize) -> CPoly<F> {
    CPoly {
        re: p.re.partial(i),
        im: p.im.partial(i),
    }
}

/// A derivation of complex polynomials (`∂/∂u` or `∂/∂v`).
type CDeriv<'a, F> = Box<dyn Fn(&CPoly<F>) -> CPoly<F> + 'a>;

/// One equation `rowᵀ x = rhs` of (3.7) with its name.
/// `rowᵀ x = rhs / den`.
struct Equation<F> {
    name: &'static str,
    row: [CPoly<F>; 4],
    rhs: CPoly<F>,
    den: CPoly<F>,
}

impl<F: Scalar> SphereFamilyEnvelope<F> {
    /// The envelope of the sphere family of the net `net` and the support functions `a`
    /// (of the planes `e = D c`) and `b` (of `f = D d`) (module docs).
    ///
    /// # Errors
    /// [`SphereFamilyError::InconsistentSupport`] if `a`, `b` violate the condition of the
    /// net type ((3.11), (3.43) with `b = ā`, (3.55)); [`SphereFamilyError::SingularSystem`]
    /// if (3.7) has no unique solution; [`SphereFamilyError::DegenerateFamily`] if `Φ` is a
    /// point or a curve; [`SphereFamilyError::Net`] if the net is no fibration of Ω.
    pub fn new(net: &LineNet<F>, a: Support<F>, b: Support<F>) -> Result<Self, SphereFamilyError> {
        Self::new_along(net, a, b, None)
    }

    /// [`Self::new`] replaying the common factors an exact build of the same input divided
    /// out ([`Reductions`], from [`Self::reductions`] of the exact envelope converted to
    /// `F`); `None`: decide them here (the exact construction).
    ///
    /// # Errors
    /// As [`Self::new`]; [`SphereFamilyError::Undefined`] if a replayed divisor does not
    /// divide up to rounding (the replay is not of this input).
    pub fn new_along(
        net: &LineNet<F>,
        a: Support<F>,
        b: Support<F>,
        replay: Option<&Reductions<F>>,
    ) -> Result<Self, SphereFamilyError> {
        if let Some(r) = replay {
            if r.divisors.len() != REDUCTION_STEPS {
                return Err(SphereFamilyError::Undefined(format!(
                    "a replay has {REDUCTION_STEPS} reduction steps, got {}",
                    r.divisors.len()
                )));
            }
        }
        let step =
            |k: usize| replay.and_then(|r| r.divisors.get(k).map(|f| (f, r.supports.get(k))));
        let mut supports: Vec<Vec<Vec<Vec<u32>>>> = Vec::with_capacity(REDUCTION_STEPS);
        let mut record: Vec<Vec<MPoly<F>>> = Vec::with_capacity(REDUCTION_STEPS);
        check_support(net, &a, &b)?;
        let eqs = equations(net, &a, &b);
        let (rows, rhs) = real_system(net, &eqs);
        let r: [&[MPoly<F>; 4]; 4] = [&rows[0], &rows[1], &rows[2], &rows[3]];
        let det = det4(r);
        if is_zero_poly(&det, 1.0) {
            return Err(SphereFamilyError::SingularSystem);
        }
        let phi: [MPoly<F>; 4] = core::array::from_fn(|i| {
            let m: [[MPoly<F>; 4]; 4] = core::array::from_fn(|k| {
                let mut row = rows[k].clone();
                if let Some(x) = row.get_mut(i) {
                    *x = rhs[k].clone();
                }
                row
            });
            det4([&m[0], &m[1], &m[2], &m[3]])
        });
        let mut all: Vec<MPoly<F>> = phi.to_vec();
        all.push(det);
        reduction_step(&mut all, step(0), &mut record, cancel_gcd_step)?;
        supports.push(support_of(&all));
        normalize_content(&mut all);
        let phi: [MPoly<F>; 4] = core::array::from_fn(|k| all[k].clone());
        let phi_den = all[4].clone();
        // Φ_u ∧ Φ_v ≢ 0 (quotient rule numerators)
        let du: Vec<MPoly<F>> = phi
            .iter()
            .map(|p| &(&p.partial(0) * &phi_den) - &(p * &phi_den.partial(0)))
            .collect();
        let dv: Vec<MPoly<F>> = phi
            .iter()
            .map(|p| &(&p.partial(1) * &phi_den) - &(p * &phi_den.partial(1)))
            .collect();
        let sc = phi.iter().map(mag).fold(1.0, f64::max).powi(4);
        let regular = (0..4).any(|i| {
            (i + 1..4).any(|j| !is_zero_poly(&(&(&du[i] * &dv[j]) - &(&du[j] * &dv[i])), sc))
        });
        if !regular {
            return Err(SphereFamilyError::DegenerateFamily);
        }
        // reparametrization (3.16)
        let w = omega_parametrization::<F>();
        let mut params = net.parameters_of_point(&w)?;
        for (n, d) in [(0, 1), (2, 3)] {
            let mut pair = if n == 0 {
                vec![params.first.clone(), params.first_den.clone()]
            } else {
                vec![params.second.clone(), params.second_den.clone()]
            };
            reduction_step(&mut pair, step(1 + n / 2), &mut record, cancel_gcd_step)?;
            supports.push(support_of(&pair));
            normalize_content(&mut pair);
            let _ = d;
            if n == 0 {
                params.first = pair[0].clone();
                params.first_den = pair[1].clone();
            } else {
                params.second = pair[0].clone();
                params.second_den = pair[1].clone();
            }
        }
        let d = NetParameters::degree_bounds(all.iter());
        let mut st: Vec<MPoly<F>> = all.iter().map(|p| params.substitute(p, d)).collect();
        let candidates = factor_candidates(&params, &w);
        reduction_step(&mut st, step(3), &mut record, |p| {
            cancel_common_factors(p, &candidates)
        })?;
        supports.push(support_of(&st));
        normalize_content(&mut st);
        let phi_st: [MPoly<F>; 4] = core::array::from_fn(|k| st[k].clone());
        let phi_st_den = st[4].clone();
        // Ψ = (W, X, Y, Z) = (D w₄, Nᵢ w₄ − N₄ wᵢ)
        let mut psi = vec![&phi_st_den * &w[3]];
        for i in 0..3 {
            psi.push(&(&phi_st[i] * &w[3]) - &(&phi_st[3] * &w[i]));
        }
        reduction_step(&mut psi, step(4), &mut record, |p| {
            cancel_common_factors(p, &candidates)
        })?;
        supports.push(support_of(&psi));
        normalize_content(&mut psi);
        Ok(SphereFamilyEnvelope {
            net: net.clone(),
            a,
            b,
            phi,
            phi_den,
            params,
            phi_st,
            phi_st_den,
            psi: core::array::from_fn(|k| psi[k].clone()),
            reductions: Reductions {
                divisors: record,
                other_sheet: replay.and_then(|r| r.other_sheet.clone()),
                supports,
                other_sheet_support: replay.and_then(|r| r.other_sheet_support.clone()),
            },
        })
    }

    /// The common factors this construction divided out ([`Reductions`]; meaningful for
    /// exact scalars, which decide them; the other sheet's only after
    /// [`Self::with_other_sheet_divisor`]).
    pub fn reductions(&self) -> &Reductions<F> {
        &self.reductions
    }

    /// The envelope with the other sheet's divisor recorded in [`Self::reductions`] (for a
    /// replay that builds the other sheet).
    pub fn with_other_sheet_divisor(mut self) -> Self {
        let (psi2, d, _) = self.other_sheet_and_divisor();
        self.reductions.other_sheet = Some(d);
        self.reductions.other_sheet_support = Some(support_of(&psi2));
        self
    }

    /// The envelope from plain data (a recipe): the net type, its point rows
    /// (`[c₀, c₁, d₀, d₁]` for hyperbolic and parabolic nets with `d(u, v) = d₀ + u d₁ + v c₁`
    /// for the latter; `[Re c₀, Im c₀, Re c₁, Im c₁]` for elliptic nets), the support
    /// function `a` as a grid of power coefficients of `uⁱvʲ` (with an imaginary part for
    /// elliptic nets) and `b` (default for elliptic nets: `ā(v)`), each optionally divided
    /// by a real denominator grid (`dens = [a's, b's]`: rational support functions).
    ///
    /// # Errors
    /// [`SphereFamilyError::InconsistentSupport`] for a wrong number of rows or a missing
    /// `b`, and every error of [`LineNet`] and [`Self::new`].
    pub fn from_data(
        kind: NetKind,
        rows: &[Vec<F>],
        a: &[Vec<F>],
        a_im: Option<&[Vec<F>]>,
        b: Option<&[Vec<F>]>,
        dens: [Option<&[Vec<F>]>; 2],
    ) -> Result<Self, SphereFamilyError> {
        Self::from_data_along(kind, rows, a, a_im, b, dens, None)
    }

    /// [`Self::from_data`] along the reductions of an exact build ([`Self::new_along`]).
    ///
    /// # Errors
    /// As [`Self::from_data`] and [`Self::new_along`].
    pub fn from_data_along(
        kind: NetKind,
        rows: &[Vec<F>],
        a: &[Vec<F>],
        a_im: Option<&[Vec<F>]>,
        b: Option<&[Vec<F>]>,
        dens: [Option<&[Vec<F>]>; 2],
        replay: Option<&Reductions<F>>,
    ) -> Result<Self, SphereFamilyError> {
        let bad = |m: String| SphereFamilyError::InconsistentSupport(m);
        let rows4: Vec<[F; 4]> = rows
            .iter()
            .map(|r| {
                <[F; 4]>::try_from(r.clone()).map_err(|_| {
                    bad(format!(
                        "a point of ω has four coordinates, got {}",
                        r.len()
                    ))
                })
            })
            .collect::<Result<_, _>>()?;
        if rows4.len() != 4 {
            return Err(bad(format!(
                "the net needs four points (c₀, c₁, d₀, d₁ or Re c₀, Im c₀, Re c₁, Im c₁), got {}",
                rows4.len()
            )));
        }
        let four: [[F; 4]; 4] = core::array::from_fn(|k| rows4[k].clone());
        let net = LineNet::from_points(kind, &four)?;
        let over = |s: Support<F>, d: Option<&[Vec<F>]>| match d {
            Some(g) => s.over(grid_poly(g)),
            None => s,
        };
        let a = over(
            Support::complex(
                grid_poly(a),
                a_im.map(grid_poly).unwrap_or_else(|| MPoly::zero(2)),
            ),
            dens[0],
        );
        let b = match (b, kind) {
            (Some(g), _) => over(Support::from_grid(g), dens[1]),
            (None, NetKind::Elliptic) => a.conjugate_in_v(),
            (None, _) => {
                return Err(bad(
                    "the support function b is required for hyperbolic and parabolic nets".into(),
                ))
            }
        };
        Self::new_along(&net, a, b, replay)
    }

    /// The net.
    pub fn net(&self) -> &LineNet<F> {
        &self.net
    }

    /// The support functions `(a, b)` in the net parameters.
    pub fn supports(&self) -> (&Support<F>, &Support<F>) {
        (&self.a, &self.b)
    }

    /// The subcase of Gruber chapter 3.
    pub fn subcase(&self) -> Subcase {
        Subcase::of_net(&self.net)
    }

    /// `Φ = (numerators, denominator)` in the net parameters (`(u, v)`, or `(m, n)` for
    /// elliptic nets): the cyclographic preimage of the family, centre `Φ₁..₃/den`, radius
    /// `Φ₄/den`.
    pub fn phi(&self) -> (&[MPoly<F>; 4], &MPoly<F>) {
        (&self.phi, &self.phi_den)
    }

    /// The reparametrization `(u, v)(s, t)` (or `(m, n)(s, t)`) of (3.16).
    pub fn reparametrization(&self) -> &NetParameters<F> {
        &self.params
    }

    /// `Φ(s, t) = (numerators, denominator)`.
    pub fn phi_st(&self) -> (&[MPoly<F>; 4], &MPoly<F>) {
        (&self.phi_st, &self.phi_st_den)
    }

    /// The homogeneous coordinates `(W, X, Y, Z)` of the envelope `Ψ(s, t) = (X, Y, Z)/W`.
    pub fn homogeneous(&self) -> &[MPoly<F>; 4] {
        &self.psi
    }

    /// `(deg_s, deg_t)` of the homogeneous envelope.
    pub fn bidegree(&self) -> (usize, usize) {
        self.psi.iter().fold((0, 0), |(a, b), p| {
            (
                a.max(p.degree_in(0).unwrap_or(0) as usize),
                b.max(p.degree_in(1).unwrap_or(0) as usize),
            )
        })
    }

    /// The total degree of the homogeneous envelope.
    pub fn total_degree(&self) -> usize {
        self.psi
            .iter()
            .filter_map(|p| p.total_degree())
            .max()
            .unwrap_or(0)
    }

    /// `Ψ(s, t)`.
    ///
    /// # Errors
    /// [`SphereFamilyError::Undefined`] where the denominator vanishes.
    pub fn eval(&self, s: &F, t: &F) -> Result<[F; 3], SphereFamilyError> {
        let x = [s.clone(), t.clone()];
        let v: Vec<F> = self
            .psi
            .iter()
            .map(|p| p.eval(&x).unwrap_or_else(|_| F::zero()))
            .collect();
        let w = v.first().cloned().unwrap_or_else(F::zero);
        let Some(inv) = w.inv().filter(|_| !w.is_zero()) else {
            return Err(SphereFamilyError::Undefined(format!(
                "Ψ has a pole at (s, t) = ({}, {})",
                format_scalar(s),
                format_scalar(t)
            )));
        };
        Ok(core::array::from_fn(|k| {
            v.get(k + 1).cloned().unwrap_or_else(F::zero) * inv.clone()
        }))
    }

    fn eval_ratio(
        num: &[MPoly<F>; 4],
        den: &MPoly<F>,
        x: &[F; 2],
        what: &str,
    ) -> Result<[F; 4], SphereFamilyError> {
        let d = den.eval(x).unwrap_or_else(|_| F::zero());
        if d.is_zero() {
            return Err(SphereFamilyError::Undefined(format!(
                "{what} at ({}, {})",
                format_scalar(&x[0]),
                format_scalar(&x[1])
            )));
        }
        Ok(core::array::from_fn(|k| {
            num[k].eval(x).unwrap_or_else(|_| F::zero()) / d.clone()
        }))
    }

    /// The sphere `(centre, radius)` enveloped at `Ψ(s, t)`.
    ///
    /// # Errors
    /// [`SphereFamilyError::Undefined`] where `Φ(s, t)` has a pole.
    pub fn sphere_at(&self, s: &F, t: &F) -> Result<([F; 3], F), SphereFamilyError> {
        let p = Self::eval_ratio(
            &self.phi_st,
            &self.phi_st_den,
            &[s.clone(), t.clone()],
            "Φ(s, t) has a pole",
        )?;
        Ok(([p[0].clone(), p[1].clone(), p[2].clone()], p[3].clone()))
    }

    /// The sphere `Φ` at net parameters `(p, q)`.
    ///
    /// # Errors
    /// [`SphereFamilyError::Undefined`] where `Φ` has a pole.
    pub fn sphere_at_parameters(&self, p: &F, q: &F) -> Result<([F; 3], F), SphereFamilyError> {
        let x = Self::eval_ratio(
            &self.phi,
            &self.phi_den,
            &[p.clone(), q.clone()],
            "Φ has a pole",
        )?;
        Ok(([x[0].clone(), x[1].clone(), x[2].clone()], x[3].clone()))
    }

    /// The net parameters `(u, v)(s, t)` of the net line through `w(s, t)`.
    ///
    /// # Errors
    /// [`SphereFamilyError::Undefined`] where a denominator vanishes.
    pub fn parameters_at(&self, s: &F, t: &F) -> Result<(F, F), SphereFamilyError> {
        self.params.at(s, t).ok_or_else(|| {
            SphereFamilyError::Undefined(format!(
                "the net line through w({}, {}) is not unique (a point of an axis)",
                format_scalar(s),
                format_scalar(t)
            ))
        })
    }

    /// The parameter point `(s', t')` of the other sheet: the second intersection point of
    /// the net line through `w(s, t)` with Ω, `w' = ⟨p, p⟩ w − 2⟨w, p⟩ p` for a second point
    /// `p` of the line (`⟨·,·⟩` the form of Ω), `(s', t') = (w'₁, w'₂)/(w'₃ + w'₄)`.
    /// Returns `(s, t)` itself where the net line touches Ω.
    ///
    /// # Errors
    /// [`SphereFamilyError::Undefined`] where the net line is not unique or `w'` is the
    /// point `(0, 0, −1, 1)` outside the parametrization.
    pub fn other_sheet(&self, s: &F, t: &F) -> Result<(F, F), SphereFamilyError> {
        let (p, q) = self.parameters_at(s, t)?;
        let line = self
            .net
            .line_at(&p, &q)
            .map_err(|e| SphereFamilyError::Undefined(e.to_string()))?;
        let w = crate::cyclographic::omega_point(s, t);
        let (p1, p2) = line.points();
        let pick = if crate::lines::proportional(&p1, &w) {
            p2
        } else {
            p1
        };
        let pp = omega_form(&pick, &pick);
        let wp = omega_form(&w, &pick);
        let two = F::from_i64(2);
        let w2: [F; 4] = core::array::from_fn(|k| {
            pp.clone() * w[k].clone() - two.clone() * wp.clone() * pick[k].clone()
        });
        if crate::lines::proportional(&w2, &w) || w2.iter().all(|x| x.is_zero()) {
            return Ok((s.clone(), t.clone()));
        }
        let den = w2[2].clone() + w2[3].clone();
        if den.is_zero() {
            return Err(SphereFamilyError::Undefined(
                "the other sheet's point is w = (0, 0, −1, 1), outside Ω(s, t)".into(),
            ));
        }
        Ok((w2[0].clone() / den.clone(), w2[1].clone() / den))
    }

    /// The rational Bézier patch of `Ψ` on `[s₀, s₁] × [t₀, t₁]`.
    ///
    /// # Errors
    /// [`SphereFamilyError::InvalidDomain`] for an empty rectangle,
    /// [`SphereFamilyError::PoleInDomain`] if the denominator `W` vanishes on it (decided by
    /// Bernstein coefficients and subdivision).
    pub fn patch(&self, s: (F, F), t: (F, F)) -> Result<BezierPatch<F>, SphereFamilyError> {
        patch_of_homogeneous(&self.psi, s, t)
    }

    /// The centre surface `π(Φ(s, t))` of the enveloped spheres on `[s₀, s₁] × [t₀, t₁]`
    /// (the sphere touching `Ψ(s, t)` has its centre there), as positive-weight pieces with
    /// the certificate that every weight is positive.
    ///
    /// # Errors
    /// [`SphereFamilyError::InvalidDomain`] for an empty rectangle,
    /// [`SphereFamilyError::PoleInDomain`] if the denominator of `Φ(s, t)` vanishes on it.
    pub fn centre_patches(
        &self,
        s: (F, F),
        t: (F, F),
    ) -> Result<(Vec<BezierPatch<F>>, Certificate), SphereFamilyError> {
        let d = Domain::new(s.0, s.1, t.0, t.1)
            .map_err(|e| SphereFamilyError::InvalidDomain(e.to_string()))?;
        let den = &self.phi_st_den;
        let sign = match sign_on_domain(den, &d, 4096) {
            Sign::Positive => F::one(),
            Sign::Negative => -F::one(),
            Sign::ZeroAt(p) | Sign::Changes(p, _) | Sign::Undecided(p) => {
                return Err(SphereFamilyError::PoleInDomain(format!(
                    "the denominator of Φ(s, t) vanishes near (s, t) = ({}, {})",
                    format_scalar(&p[0]),
                    format_scalar(&p[1])
                )))
            }
        };
        let coords: Vec<MPoly<F>> = [den, &self.phi_st[0], &self.phi_st[1], &self.phi_st[2]]
            .iter()
            .map(|p| p.scale(&sign))
            .collect();
        let patch =
            patch_of(&coords, &d).map_err(|e| SphereFamilyError::InvalidDomain(e.to_string()))?;
        let split = split_patches_adaptive(vec![patch], SignRule::Positive, (6, 6))
            .map_err(|e| SphereFamilyError::InvalidDomain(e.to_string()))?;
        let (pieces, bad) = (split.pieces, split.failed);
        let n = pieces.len();
        let cert = Certificate::decide(
            format!("every Bernstein weight of the {n} centre-surface patches is > 0"),
            bad == 0,
            F::EXACT,
            || format!("{bad} pieces keep a weight ≤ 0"),
        );
        Ok((pieces, cert))
    }

    /// The envelope on `[s₀, s₁] × [t₀, t₁]` as rational Bézier patches whose Bernstein
    /// weights are all positive (the patch of [`Self::patch`], negated if `W < 0`, bisected
    /// where a weight is ≤ 0), with the certificate that every weight is positive.
    ///
    /// # Errors
    /// As [`Self::patch`].
    pub fn export_patches(
        &self,
        s: (F, F),
        t: (F, F),
    ) -> Result<(Vec<BezierPatch<F>>, Certificate), SphereFamilyError> {
        export_pieces(&self.psi, s, t)
    }

    /// The envelope converted to another scalar type (e.g. `f64`), rebuilt from the
    /// converted net and support functions.
    ///
    /// # Errors
    /// As [`Self::new`] (f64 data may become degenerate).
    pub fn map_scalar<G: Scalar>(
        &self,
        f: impl Fn(&F) -> G + Copy,
    ) -> Result<SphereFamilyEnvelope<G>, SphereFamilyError> {
        let net = self.net.map_scalar(f);
        SphereFamilyEnvelope::new(&net, self.a.map(f), self.b.map(f))
    }
}

/// [`cancel_common`] on the homogeneous vector `polys`; for inexact scalars the result is
/// kept only if it is the same projective point as before at three sample parameters
/// (`f64` division drops coefficients below a tolerance relative to the largest one, which
/// for polynomials of high degree can accept a candidate that does not divide: then the
/// common factor is kept, as the exact path would not have found it either).
fn cancel_common_checked<F: Scalar>(polys: &mut [MPoly<F>], candidates: &[MPoly<F>]) {
    if F::EXACT {
        cancel_common(polys, candidates);
        return;
    }
    let before = polys.to_vec();
    cancel_common(polys, candidates);
    let samples = [
        ((3, 10), (7, 10)),
        ((-11, 10), (9, 20)),
        ((23, 10), (-3, 5)),
    ];
    let at = |ps: &[MPoly<F>], (s, t): ((i64, i64), (i64, i64))| -> Vec<f64> {
        let x = [F::from_ratio(s.0, s.1), F::from_ratio(t.0, t.1)];
        ps.iter()
            .map(|p| p.eval(&x).map(|v| v.to_f64()).unwrap_or(f64::NAN))
            .collect()
    };
    let parallel = samples.iter().all(|&st| {
        let (a, b) = (at(&before, st), at(polys, st));
        let na = a.iter().map(|x| x * x).sum::<f64>().sqrt();
        let nb = b.iter().map(|x| x * x).sum::<f64>().sqrt();
        (0..a.len())
            .all(|i| (0..a.len()).all(|j| (a[i] * b[j] - a[j] * b[i]).abs() <= 1e-8 * na * nb))
    });
    if !parallel {
        polys.clone_from_slice(&before);
    }
}

/// The rational Bézier patch of the homogeneous `psi` on `[s₀, s₁] × [t₀, t₁]`, refused
/// where its weight `psi[0]` vanishes (Bernstein coefficients and subdivision).
fn patch_of_homogeneous<F: Scalar>(
    psi: &[MPoly<F>; 4],
    s: (F, F),
    t: (F, F),
) -> Result<BezierPatch<F>, SphereFamilyError> {
    let d = Domain::new(s.0, s.1, t.0, t.1)
        .map_err(|e| SphereFamilyError::InvalidDomain(e.to_string()))?;
    match sign_on_domain(&psi[0], &d, 4096) {
        Sign::Positive | Sign::Negative => {}
        Sign::ZeroAt(p) | Sign::Changes(p, _) | Sign::Undecided(p) => {
            return Err(SphereFamilyError::PoleInDomain(format!(
                "the weight W(s, t) vanishes near (s, t) = ({}, {})",
                format_scalar(&p[0]),
                format_scalar(&p[1])
            )))
        }
    }
    patch_of(psi, &d).map_err(|e| SphereFamilyError::InvalidDomain(e.to_string()))
}

/// The patch of `psi` negated if its weight is negative, bisected where a Bernstein weight
/// is ≤ 0, with the certificate that every weight is positive.
fn export_pieces<F: Scalar>(
    psi: &[MPoly<F>; 4],
    s: (F, F),
    t: (F, F),
) -> Result<(Vec<BezierPatch<F>>, Certificate), SphereFamilyError> {
    let mut p = patch_of_homogeneous(psi, s, t)?;
    let dim = p.dim() + 1;
    // W has one sign on the rectangle (checked above): the corner weight W(s₀, t₀)
    let neg = p.coords().first().is_some_and(|w| *w < F::zero());
    if neg {
        let (m, n) = p.degree();
        let flat: Vec<F> = p.coords().iter().map(|x| -x.clone()).collect();
        p = BezierPatch::from_flat(dim - 1, m, n, flat)
            .map_err(|e| SphereFamilyError::InvalidDomain(e.to_string()))?;
    }
    let split = split_patches_adaptive(vec![p], SignRule::Positive, (6, 6))
        .map_err(|e| SphereFamilyError::InvalidDomain(e.to_string()))?;
    let (pieces, bad) = (split.pieces, split.failed);
    let n = pieces.len();
    let cert = Certificate::decide(
        format!(
            "every Bernstein weight of the {n} envelope patches is > 0 (no pole on the rectangle)"
        ),
        bad == 0,
        F::EXACT,
        || format!("{bad} pieces keep a weight ≤ 0 after 12 bisections"),
    );
    Ok((pieces, cert))
}

/// `(Φ, Φ_u, Φ_v)` at one parameter.
type Jet<F> = ([F; 4], [F; 4], [F; 4]);

/// The two envelope points of the cyclographic construction (Gruber §3.1.2) with the
/// isotropic directions that project them.
#[derive(Debug, Clone, PartialEq)]
pub struct CyclographicEnvelope<E> {
    /// The intersections `H₁, H₂` of the ideal line `h` of the normal plane with `Ω`.
    pub isotropic: [[E; 4]; 2],
    /// The envelope points `fₖ = π(Φ) − Φ₄ (Hₖ₁, Hₖ₂, Hₖ₃)/Hₖ₄`.
    pub points: [[E; 3]; 2],
}

impl<F: SqrtScalar> SphereFamilyEnvelope<F> {
    /// The cyclographic construction of the envelope at the net parameters `(p, q)`
    /// (Gruber §3.1.2, after Peternell and Odehnal): the tangent plane `τ` of `Φ` at
    /// `F = Φ(p, q)` has the ideal line `g = Φ_u ∧ Φ_v` (points of `ω`), the normal plane the
    /// polar line `h = E g` (Gruber (1.19)); `h` meets `Ω` in `H₁, H₂` (a quadratic
    /// equation: `H = a + μb` for two points `a, b` of `h`,
    /// `⟨a, a⟩ + 2μ⟨a, b⟩ + μ²⟨b, b⟩ = 0` in the Lorentz form), and the isotropic lines
    /// `F ∨ Hₖ` meet `x₄ = 0` in the envelope points `fₖ = π(F) − F₄ (Hₖ₁, Hₖ₂, Hₖ₃)/Hₖ₄`.
    /// Independent of the net: the construction sees `Φ` only; the net's fibration is what
    /// makes `Hₖ` rational in the parameters of `Ω` (§3.2).
    ///
    /// # Errors
    /// [`SphereFamilyError::Undefined`] where `Φ` has a pole or `Φ_u ∧ Φ_v = 0`,
    /// [`SphereFamilyError::NoRealEnvelope`] where the tangent plane is timelike (`h` misses
    /// `Ω`).
    pub fn cyclographic_envelope(
        &self,
        p: &F,
        q: &F,
    ) -> Result<CyclographicEnvelope<F::Ext>, SphereFamilyError> {
        let (val, fu, fv) = self.phi_jet(p, q)?;
        let g = crate::lines::plucker::wedge(&fu, &fv);
        if g.iter().all(|x| x.is_zero()) {
            return Err(SphereFamilyError::Undefined(
                "Φ_u ∧ Φ_v = 0: Φ is singular here".into(),
            ));
        }
        let h = crate::lines::Line::from_coords_unchecked(g).polar_omega();
        let (a, b) = h.points();
        let (aa, ab, bb) = (omega_form(&a, &a), omega_form(&a, &b), omega_form(&b, &b));
        let disc = ab.clone() * ab.clone() - aa.clone() * bb.clone();
        let Some(root) = disc.sqrt_ext() else {
            return Err(SphereFamilyError::NoRealEnvelope(format!(
                "the tangent plane of Φ at ({}, {}) is timelike: its normal line h misses Ω",
                format_scalar(p),
                format_scalar(q)
            )));
        };
        let (ae, be): ([F::Ext; 4], [F::Ext; 4]) = (
            core::array::from_fn(|k| a[k].embed()),
            core::array::from_fn(|k| b[k].embed()),
        );
        // H = (⟨a,b⟩ ∓ √disc)·b − ⟨b,b⟩·a is a root of the quadratic in projective form
        // (μ = (−⟨a,b⟩ ± √disc)/⟨b,b⟩, scaled by −⟨b,b⟩); if ⟨b,b⟩ = 0, b itself and
        // ⟨a,a⟩b − 2⟨a,b⟩a are the two points.
        // Inexact scalars: an exact ⟨b,b⟩ = 0 may be a rounding residue, and then
        // ⟨a,b⟩ ∓ √disc cancels in one of the two roots. With c₁ = ⟨a,b⟩ + sign(⟨a,b⟩)√disc
        // (no cancellation) the other coefficient is c₂ = ⟨a,a⟩⟨b,b⟩/c₁ (Vieta), and
        // c₂·b − ⟨b,b⟩·a = (⟨b,b⟩/c₁)(⟨a,a⟩·b − c₁·a): the same projective point as
        // ⟨a,a⟩·b − c₁·a, which needs no division and tends to the exact branch's second
        // point as ⟨b,b⟩ → 0 (Higham, "Accuracy and Stability of Numerical Algorithms",
        // §1.8, the quadratic formula). Same order as the exact branches (the root with
        // ⟨a,b⟩ − √disc first); the contact points below are projective in H.
        let hs: [[F::Ext; 4]; 2] = if !F::EXACT {
            let negative = ab < F::zero();
            let c1 = if negative {
                ab.embed() - root.clone()
            } else {
                ab.embed() + root.clone()
            };
            let far: [F::Ext; 4] =
                core::array::from_fn(|k| c1.clone() * be[k].clone() - bb.embed() * ae[k].clone());
            let near: [F::Ext; 4] =
                core::array::from_fn(|k| aa.embed() * be[k].clone() - c1.clone() * ae[k].clone());
            if negative {
                [far, near]
            } else {
                [near, far]
            }
        } else if bb.is_zero() {
            [
                be.clone(),
                core::array::from_fn(|k| {
                    aa.embed() * be[k].clone() - (ab.clone() + ab.clone()).embed() * ae[k].clone()
                }),
            ]
        } else {
            let mk = |sgn: bool| -> [F::Ext; 4] {
                let c = if sgn {
                    ab.embed() - root.clone()
                } else {
                    ab.embed() + root.clone()
                };
                core::array::from_fn(|k| c.clone() * be[k].clone() - bb.embed() * ae[k].clone())
            };
            [mk(true), mk(false)]
        };
        let mut points: Vec<[F::Ext; 3]> = Vec::with_capacity(2);
        for hk in &hs {
            if num_traits::Zero::is_zero(&hk[3]) {
                return Err(SphereFamilyError::Undefined(
                    "an isotropic direction with H₄ = 0".into(),
                ));
            }
            let f4 = val[3].embed() / hk[3].clone();
            points.push(core::array::from_fn(|i| {
                val[i].embed() - f4.clone() * hk[i].clone()
            }));
        }
        let [p0, p1] = <[[F::Ext; 3]; 2]>::try_from(points)
            .map_err(|_| SphereFamilyError::Undefined("two points".into()))?;
        Ok(CyclographicEnvelope {
            isotropic: hs,
            points: [p0, p1],
        })
    }

    /// The cyclographic construction ([`Self::cyclographic_envelope`]) at the sphere
    /// `Φ(s, t)` of the rational parameter point `(s, t)` of Ω: the sphere `(centre,
    /// radius)` and its two contact points. The net line through `w(s, t)` is the normal
    /// line `h`, so both points of `h ∩ Ω` (`w(s, t)` and the other sheet's `w'`) are
    /// rational and so are the contact points.
    ///
    /// # Errors
    /// Those of [`Self::cyclographic_envelope`] and [`Self::parameters_at`];
    /// [`SphereFamilyError::Undefined`] if a contact point is not in the base field (cannot
    /// happen at a rational point of Ω; reported rather than rounded).
    #[allow(clippy::type_complexity)]
    pub fn cyclographic_contacts(
        &self,
        s: &F,
        t: &F,
    ) -> Result<(([F; 3], F), [[F; 3]; 2]), SphereFamilyError> {
        let (p, q) = self.parameters_at(s, t)?;
        let c = self.cyclographic_envelope(&p, &q)?;
        let sphere = self.sphere_at_parameters(&p, &q)?;
        let back = |x: &F::Ext| -> Result<F, SphereFamilyError> {
            x.to_rational()
                .map(|r| F::from_rational(&r))
                .ok_or_else(|| {
                    SphereFamilyError::Undefined(format!(
                        "a contact point at ({}, {}) is irrational",
                        format_scalar(s),
                        format_scalar(t)
                    ))
                })
        };
        let mut pts: Vec<[F; 3]> = Vec::with_capacity(2);
        for pt in &c.points {
            pts.push([back(&pt[0])?, back(&pt[1])?, back(&pt[2])?]);
        }
        let [a, b] = <[[F; 3]; 2]>::try_from(pts)
            .map_err(|_| SphereFamilyError::Undefined("two contact points".into()))?;
        Ok((sphere, [a, b]))
    }

    /// Certificate: at the parameter `(s, t)` of `Ω`, `Ψ(s, t)` is one of the two points of
    /// the cyclographic construction ([`Self::cyclographic_envelope`]) at the net parameters
    /// of `(s, t)` — exact over the square-root extension.
    pub fn cyclographic_certificate(&self, s: &F, t: &F) -> Certificate {
        let prop = format!(
            "Ψ({}, {}) is a point of the cyclographic construction at its sphere (Gruber §3.1.2)",
            format_scalar(s),
            format_scalar(t)
        );
        let run = || -> Result<bool, SphereFamilyError> {
            let x = self.eval(s, t)?;
            let (p, q) = self.parameters_at(s, t)?;
            let c = self.cyclographic_envelope(&p, &q)?;
            let sc = 1.0 + x.iter().map(|v| v.to_f64().abs()).fold(0.0, f64::max);
            Ok(c.points.iter().any(|pt| {
                (0..3).all(|k| crate::lines::is_small(&(pt[k].clone() - x[k].embed()), sc))
            }))
        };
        match run() {
            Ok(ok) => Certificate::decide(prop, ok, F::EXACT, || "Ψ is neither point".into()),
            Err(e) => Certificate::fails(prop, e.to_string(), F::EXACT),
        }
    }

    /// `Φ(p, q)` and its partial derivatives (affine, the denominator divided out).
    fn phi_jet(&self, p: &F, q: &F) -> Result<Jet<F>, SphereFamilyError> {
        let x = [p.clone(), q.clone()];
        let ev = |m: &MPoly<F>| m.eval(&x).unwrap_or_else(|_| F::zero());
        let d = ev(&self.phi_den);
        if d.is_zero() {
            return Err(SphereFamilyError::Undefined("Φ has a pole".into()));
        }
        let (d_u, d_v) = (ev(&self.phi_den.partial(0)), ev(&self.phi_den.partial(1)));
        let val: [F; 4] = core::array::from_fn(|k| ev(&self.phi[k]) / d.clone());
        let der = |i: usize, dd: &F| -> [F; 4] {
            core::array::from_fn(|k| {
                (ev(&self.phi[k].partial(i)) - val[k].clone() * dd.clone()) / d.clone()
            })
        };
        let (fu, fv) = (der(0, &d_u), der(1, &d_v));
        Ok((val, fu, fv))
    }

    /// The direct envelope `S ∩ S_u ∩ S_v` at the net parameters `(p, q)` (Gruber §3.1.1,
    /// with the sign of (3.3) corrected): with `m, r` the sphere and `y = x − m`,
    /// `⟨y, m_u⟩ = −r r_u`, `⟨y, m_v⟩ = −r r_v`, `|y|² = r²`. The first two fix
    /// `y₀ ∈ span(m_u, m_v)`; then `y = y₀ ± λ n`, `n = m_u × m_v`,
    /// `λ² = (r² − |y₀|²)/|n|²` — a square root in [`SqrtScalar::Ext`].
    ///
    /// # Errors
    /// [`SphereFamilyError::Undefined`] where `Φ` has a pole or `m_u × m_v = 0` (a singular
    /// point of the centre surface), [`SphereFamilyError::NoRealEnvelope`] where `λ² < 0`.
    pub fn direct_envelope(
        &self,
        p: &F,
        q: &F,
    ) -> Result<DirectEnvelope<F::Ext>, SphereFamilyError> {
        let (val, fu, fv) = self.phi_jet(p, q)?;
        let dot3 = |a: &[F; 4], b: &[F; 4]| {
            a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
        };
        let r = val[3].clone();
        let (g11, g12, g22) = (dot3(&fu, &fu), dot3(&fu, &fv), dot3(&fv, &fv));
        let det = g11.clone() * g22.clone() - g12.clone() * g12.clone();
        if det.is_zero() {
            return Err(SphereFamilyError::Undefined(
                "m_u × m_v = 0: the centre surface is singular here".into(),
            ));
        }
        let (r1, r2) = (-(r.clone() * fu[3].clone()), -(r.clone() * fv[3].clone()));
        let alpha = (r1.clone() * g22 - r2.clone() * g12.clone()) / det.clone();
        let beta = (r2 * g11 - r1 * g12) / det.clone();
        let y0: [F; 3] =
            core::array::from_fn(|k| alpha.clone() * fu[k].clone() + beta.clone() * fv[k].clone());
        let n = [
            fu[1].clone() * fv[2].clone() - fu[2].clone() * fv[1].clone(),
            fu[2].clone() * fv[0].clone() - fu[0].clone() * fv[2].clone(),
            fu[0].clone() * fv[1].clone() - fu[1].clone() * fv[0].clone(),
        ];
        let y0sq = y0.iter().fold(F::zero(), |a, x| a + x.clone() * x.clone());
        // |n|² = det G (Lagrange identity)
        let lam2 = (r.clone() * r - y0sq) / det;
        let Some(lam) = lam2.sqrt_ext() else {
            return Err(SphereFamilyError::NoRealEnvelope(format!(
                "λ² = {} < 0 at ({}, {}): the net line misses Ω",
                format_scalar(&lam2),
                format_scalar(p),
                format_scalar(q)
            )));
        };
        let base: [F::Ext; 3] = core::array::from_fn(|k| (val[k].clone() + y0[k].clone()).embed());
        let ne: [F::Ext; 3] = core::array::from_fn(|k| n[k].embed());
        Ok(DirectEnvelope {
            plus: core::array::from_fn(|k| base[k].clone() + lam.clone() * ne[k].clone()),
            minus: core::array::from_fn(|k| base[k].clone() - lam.clone() * ne[k].clone()),
        })
    }
}

/// Candidate common factors of `Φ(s, t)` and `Ψ(s, t)`: the variables, `w₄ = 1 + s² + t²`,
/// the reparametrization denominators and their common and cofactor parts. (A general
/// bivariate gcd of the high-degree coordinates is much slower and finds no other factors
/// in the examples; cancelling fewer factors never affects the certificates, only the
/// degree.)
fn factor_candidates<F: Scalar>(params: &NetParameters<F>, w: &[MPoly<F>; 4]) -> Vec<MPoly<F>> {
    let (a, b) = (&params.first_den, &params.second_den);
    let g = gcd2(a, b);
    let mut out = vec![MPoly::var(2, 0), MPoly::var(2, 1), w[3].clone(), g.clone()];
    for x in [a, b] {
        // x / gcd
        out.push(crate::pn::poly::div_exact(x, &g).unwrap_or_else(|| x.clone()));
        out.push(x.clone());
    }
    out.sort_by_key(|p| std::cmp::Reverse(p.total_degree().unwrap_or(0)));
    out
}

/// The consistency conditions on the support functions (3.11), (3.43)/(3.44) corrected,
/// (3.55).
fn check_support<F: Scalar>(
    net: &LineNet<F>,
    a: &Support<F>,
    b: &Support<F>,
) -> Result<(), SphereFamilyError> {
    let sc = 1.0;
    let bad = |m: &str| Err(SphereFamilyError::InconsistentSupport(m.to_string()));
    if is_zero_poly(&a.den, sc) || is_zero_poly(&b.den, sc) {
        return bad("a support function has the denominator 0");
    }
    let (a_u, a_v) = (a.derivative_numerators(0), a.derivative_numerators(1));
    let (b_u, b_v) = (b.derivative_numerators(0), b.derivative_numerators(1));
    match net.kind() {
        NetKind::Hyperbolic | NetKind::Parabolic => {
            if !is_zero_poly(&a.im, sc) || !is_zero_poly(&b.im, sc) {
                return bad("the support functions of a hyperbolic or parabolic net are real");
            }
        }
        NetKind::Elliptic => {}
    }
    if !is_zero_poly(&a_v.0, sc) || !is_zero_poly(&a_v.1, sc) {
        return bad("a_v ≢ 0: the support function a depends on u only ((3.11), (3.43), (3.55))");
    }
    match net.kind() {
        NetKind::Hyperbolic => {
            if !is_zero_poly(&b_u.0, sc) {
                return bad(
                    "b_u ≢ 0: the support function b of a hyperbolic net depends on v only (3.11)",
                );
            }
        }
        NetKind::Elliptic => {
            if !is_zero_poly(&b_u.0, sc) || !is_zero_poly(&b_u.1, sc) {
                return bad(
                    "b_u ≢ 0: the support function b of an elliptic net depends on v only (3.43)",
                );
            }
            // b = ā(v) cross-multiplied: b.re·ā.den = ā.re·b.den, likewise the imaginary parts
            let conj = a.conjugate_in_v();
            let cross = |x: &MPoly<F>, y: &MPoly<F>| &(x * &conj.den) - &(y * &b.den);
            if !is_zero_poly(&cross(&b.re, &conj.re), sc)
                || !is_zero_poly(&cross(&b.im, &conj.im), sc)
            {
                return bad("b ≠ ā: the support functions of an elliptic net are conjugate, b(v) = ā(v) (Gruber (3.44), corrected)");
            }
        }
        NetKind::Parabolic => {
            // a_u = b_v cross-multiplied by the denominators q_a², q_b²
            let qa2 = &a.den * &a.den;
            let qb2 = &b.den * &b.den;
            if !is_zero_poly(&(&(&a_u.0 * &qb2) - &(&b_v.0 * &qa2)), sc) {
                return bad("a_u ≠ b_v: the support functions of a parabolic net satisfy a_u = b_v (3.55), i.e. b = v·a'(u) + b₀(u)");
            }
        }
    }
    Ok(())
}

/// The six equations of (3.7) as complex rows in the net parameters; for elliptic nets the
/// parameters are `(m, n)` with `u = m − i n`, `v = m + i n`.
fn equations<F: Scalar>(net: &LineNet<F>, a: &Support<F>, b: &Support<F>) -> Vec<Equation<F>> {
    let c = net.axis_c();
    let d = net.axis_d();
    let cpolar = |x: &[CPoly<F>; 4]| -> [CPoly<F>; 4] {
        [x[0].clone(), x[1].clone(), x[2].clone(), x[3].neg()]
    };
    let e = cpolar(&c);
    let f = cpolar(&d);
    let (ac, bc, aq, bq) = match net.kind() {
        NetKind::Elliptic => {
            let u = CPoly {
                re: MPoly::var(2, 0),
                im: -&MPoly::var(2, 1),
            };
            let v = u.conj();
            (
                complex_subst(&a.as_cpoly(), 0, &u),
                complex_subst(&b.as_cpoly(), 1, &v),
                complex_subst(&CPoly::real(a.den.clone()), 0, &u),
                complex_subst(&CPoly::real(b.den.clone()), 1, &v),
            )
        }
        _ => (
            a.as_cpoly(),
            b.as_cpoly(),
            CPoly::real(a.den.clone()),
            CPoly::real(b.den.clone()),
        ),
    };
    // derivatives with respect to u and v
    let (du, dv): (CDeriv<'_, F>, CDeriv<'_, F>) = match net.kind() {
        NetKind::Elliptic => {
            // ∂/∂u = (∂_m + i ∂_n)/2 and ∂/∂v = (∂_m − i ∂_n)/2 on functions of u = m − i n, v = m + i n
            let half = F::from_ratio(1, 2);
            let h2 = half.clone();
            (
                Box::new(move |p: &CPoly<F>| {
                    let (pm, pn) = (cpartial(p, 0), cpartial(p, 1));
                    CPoly {
                        re: (&pm.re - &pn.im).scale(&half),
                        im: (&pm.im + &pn.re).scale(&half),
                    }
                }),
                Box::new(move |p: &CPoly<F>| {
                    let (pm, pn) = (cpartial(p, 0), cpartial(p, 1));
                    CPoly {
                        re: (&pm.re + &pn.im).scale(&h2),
                        im: (&pm.im - &pn.re).scale(&h2),
                    }
                }),
            )
        }
        _ => (
            Box::new(|p: &CPoly<F>| cpartial(p, 0)),
            Box::new(|p: &CPoly<F>| cpartial(p, 1)),
        ),
    };
    let dvec = |g: &dyn Fn(&CPoly<F>) -> CPoly<F>, x: &[CPoly<F>; 4]| -> [CPoly<F>; 4] {
        core::array::from_fn(|k| g(&x[k]))
    };
    // (p/q)' = (p' q − p q')/q²
    let quot = |g: &dyn Fn(&CPoly<F>) -> CPoly<F>, p: &CPoly<F>, q: &CPoly<F>| -> CPoly<F> {
        g(p).mul(q).sub(&p.mul(&g(q)))
    };
    let (aq2, bq2) = (aq.mul(&aq), bq.mul(&bq));
    vec![
        Equation {
            name: "eᵀx = a",
            row: e.clone(),
            rhs: ac.clone(),
            den: aq.clone(),
        },
        Equation {
            name: "e_uᵀx = a_u",
            row: dvec(&*du, &e),
            rhs: quot(&*du, &ac, &aq),
            den: aq2.clone(),
        },
        Equation {
            name: "e_vᵀx = a_v",
            row: dvec(&*dv, &e),
            rhs: quot(&*dv, &ac, &aq),
            den: aq2,
        },
        Equation {
            name: "fᵀx = b",
            row: f.clone(),
            rhs: bc.clone(),
            den: bq.clone(),
        },
        Equation {
            name: "f_uᵀx = b_u",
            row: dvec(&*du, &f),
            rhs: quot(&*du, &bc, &bq),
            den: bq2.clone(),
        },
        Equation {
            name: "f_vᵀx = b_v",
            row: dvec(&*dv, &f),
            rhs: quot(&*dv, &bc, &bq),
            den: bq2,
        },
    ]
}

/// The four independent real rows of (3.7): hyperbolic `e, e_u, f, f_v`; parabolic
/// `e, e_u, f, f_u`; elliptic `Re e, Im e, Re e_u, Im e_u`.
fn real_system<F: Scalar>(
    net: &LineNet<F>,
    eqs: &[Equation<F>],
) -> ([[MPoly<F>; 4]; 4], [MPoly<F>; 4]) {
    // (den · row)ᵀ x = rhs, whose real and imaginary parts are real equations
    let scaled = |k: usize| -> [CPoly<F>; 4] {
        let e = &eqs[k];
        core::array::from_fn(|i| e.row[i].mul(&e.den))
    };
    let re = |k: usize| -> ([MPoly<F>; 4], MPoly<F>) {
        let r = scaled(k);
        (
            core::array::from_fn(|i| r[i].re.clone()),
            eqs[k].rhs.re.clone(),
        )
    };
    let im = |k: usize| -> ([MPoly<F>; 4], MPoly<F>) {
        let r = scaled(k);
        (
            core::array::from_fn(|i| r[i].im.clone()),
            eqs[k].rhs.im.clone(),
        )
    };
    let picks = match net.kind() {
        NetKind::Hyperbolic => [re(0), re(1), re(3), re(5)],
        NetKind::Parabolic => [re(0), re(1), re(3), re(4)],
        NetKind::Elliptic => [re(0), im(0), re(1), im(1)],
    };
    let rows = core::array::from_fn(|k| picks[k].0.clone());
    let rhs = core::array::from_fn(|k| picks[k].1.clone());
    (rows, rhs)
}

impl<F: Scalar> Certified for SphereFamilyEnvelope<F> {
    /// The consistency conditions of the net type, the system (3.7), the tangency (3.8), the
    /// fibration (3.16) and the envelope identities (module docs), exact for exact scalars.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        let eqs = equations(&self.net, &self.a, &self.b);
        // consistency conditions of the planes
        let zero_vec = |x: &[CPoly<F>; 4]| -> MPoly<F> {
            x.iter().fold(MPoly::zero(2), |acc, p| {
                &(&acc + &(&p.re * &p.re)) + &(&p.im * &p.im)
            })
        };
        match self.net.kind() {
            NetKind::Hyperbolic | NetKind::Elliptic => {
                out.push(zero_cert(
                    "e_v ≡ 0 and f_u ≡ 0: each pencil depends on one parameter ((3.10), (3.42))",
                    &(&zero_vec(&eqs[2].row) + &zero_vec(&eqs[4].row)),
                    1.0,
                ));
            }
            NetKind::Parabolic => {
                out.push(zero_cert("e_v ≡ 0 (3.54)", &zero_vec(&eqs[2].row), 1.0));
                let diff: [CPoly<F>; 4] =
                    core::array::from_fn(|k| eqs[1].row[k].sub(&eqs[5].row[k]));
                out.push(zero_cert("e_u ≡ f_v (3.54)", &zero_vec(&diff), 1.0));
            }
        }
        // (3.7): (rowᵀ Φ)·q − rhs · den ≡ 0 (q the equation's denominator)
        for eq in &eqs {
            let lhs = cdot4(&eq.row, &self.phi).mul(&eq.den);
            let r = CPoly {
                re: &eq.rhs.re * &self.phi_den,
                im: &eq.rhs.im * &self.phi_den,
            };
            let res = lhs.sub(&r);
            let scale = 16.0 * (mag(&lhs.re) + mag(&lhs.im) + mag(&r.re) + mag(&r.im));
            out.push(zero_cert(
                &format!("Φ solves (3.7): {}", eq.name),
                &(&(&res.re * &res.re) + &(&res.im * &res.im)),
                scale * scale,
            ));
        }
        // (3.8): e, f annihilate Φ_p, Φ_q (quotient-rule numerators)
        for i in 0..2 {
            let dphi: [MPoly<F>; 4] = core::array::from_fn(|k| {
                &(&self.phi[k].partial(i) * &self.phi_den)
                    - &(&self.phi[k] * &self.phi_den.partial(i))
            });
            for (name, row) in [("e", &eqs[0].row), ("f", &eqs[3].row)] {
                let v = cdot4(row, &dphi);
                let pname = if i == 0 {
                    self.net.parameter_names().0
                } else {
                    self.net.parameter_names().1
                };
                out.push(identity_cert(
                    &format!("tangent plane T = E ∩ F: {name}ᵀ Φ_{pname} ≡ 0 (3.8)"),
                    &(&(&v.re * &v.re) + &(&v.im * &v.im)),
                    &MPoly::zero(2),
                ));
            }
        }
        let w = omega_parametrization::<F>();
        out.push(fibration_certificate(&self.net, &self.params, &w));
        out.extend(envelope_certificates(
            &self.psi,
            &self.phi_st,
            &self.phi_st_den,
        ));
        out
    }
}

/// `|Ψ − m|² ≡ r²`, `⟨Ψ − m, m_s⟩ + r r_s ≡ 0`, `⟨Ψ − m, m_t⟩ + r r_t ≡ 0` for
/// `Ψ = (X, Y, Z)/W` and `(m, r) = N/D`, cleared of denominators:
/// `|P D − N Q|² − N₄² Q² ≡ 0` and `⟨P D − N Q, N_s D − N D_s⟩ + Q N₄ (N₄,s D − N₄ D_s) ≡ 0`
/// (`P = (X, Y, Z)`, `Q = W`).
pub(crate) fn envelope_certificates<F: Scalar>(
    psi: &[MPoly<F>; 4],
    n: &[MPoly<F>; 4],
    d: &MPoly<F>,
) -> Vec<Certificate> {
    let q = &psi[0];
    let diff: [MPoly<F>; 3] = core::array::from_fn(|k| &(&psi[k + 1] * d) - &(&n[k] * q));
    let sq = diff.iter().fold(MPoly::zero(2), |acc, x| &acc + &(x * x));
    let rq = &n[3] * q;
    let mut out = vec![identity_cert(
        "the envelope point lies on its sphere: |Ψ − π(Φ)|² ≡ Φ₄² (Gruber (3.1))",
        &sq,
        &(&rq * &rq),
    )];
    for (i, name) in [(0usize, "s"), (1, "t")] {
        let dn: [MPoly<F>; 4] =
            core::array::from_fn(|k| &(&n[k].partial(i) * d) - &(&n[k] * &d.partial(i)));
        let lhs = (0..3).fold(MPoly::zero(2), |acc, k| &acc + &(&diff[k] * &dn[k]));
        let rhs = -&(&(q * &n[3]) * &dn[3]);
        out.push(identity_cert(
            &format!("tangency: ⟨Ψ − π(Φ), ∂{name}π(Φ)⟩ + Φ₄ ∂{name}Φ₄ ≡ 0 (Gruber (3.3), sign corrected)"),
            &lhs,
            &rhs,
        ));
    }
    out
}

/// An enveloped sphere of [`SphereFamilyEnvelope::enveloped_spheres`]: the parameter point
/// `(s, t)` of its contact point on the first sheet, the other sheet's parameter point, the
/// sphere and its exact sixteen-patch cover.
#[derive(Debug, Clone)]
pub struct EnvelopedSphere<F> {
    /// `(s, t)`: `Ψ(s, t)` is a contact point.
    pub at: (F, F),
    /// `(s', t')` = [`SphereFamilyEnvelope::other_sheet`]`(s, t)`: the second contact point.
    pub other: (F, F),
    /// Centre `π(Φ(s, t))` and radius `|Φ₄(s, t)|`.
    pub sphere: ([F; 3], F),
    /// The sphere as sixteen biquadratic patches (`quadric::sphere_cover`).
    pub cover: crate::quadric::SphereCover<F>,
}

impl<F: Scalar> SphereFamilyEnvelope<F> {
    /// `n` spheres of the family at the parameter points
    /// `(s₀ + k/(n+1) (s₁ − s₀), t₀ + k/(n+1) (t₁ − t₀))`, `k = 1..n`, of the rectangle's
    /// diagonal, each as an exact sphere cover (sixteen biquadratic patches, Farin's
    /// stereographic construction in `quadric::sphere_cover`), with both contact points:
    /// the sphere `Φ(s, t)` touches the envelope in `Ψ(s, t)` and in `Ψ(s', t')`,
    /// `(s', t')` the other intersection of its normal line `h` with Ω (Gruber §3.1.2).
    ///
    /// # Errors
    /// [`SphereFamilyError::InvalidDomain`] for an empty rectangle or `n = 0`,
    /// [`SphereFamilyError::Undefined`] where `Φ` has a pole, the radius is zero or a contact
    /// point is not defined.
    pub fn enveloped_spheres(
        &self,
        s: (F, F),
        t: (F, F),
        n: usize,
    ) -> Result<Vec<EnvelopedSphere<F>>, SphereFamilyError> {
        if n == 0 || !(s.0 < s.1 && t.0 < t.1) {
            return Err(SphereFamilyError::InvalidDomain(
                "enveloped spheres need n ≥ 1 and a rectangle with s₀ < s₁, t₀ < t₁".into(),
            ));
        }
        let m = F::from_i64(n as i64 + 1);
        (1..=n)
            .map(|k| {
                let f = F::from_i64(k as i64) / m.clone();
                let sk = s.0.clone() + f.clone() * (s.1.clone() - s.0.clone());
                let tk = t.0.clone() + f * (t.1.clone() - t.0.clone());
                let (c, r) = self.sphere_at(&sk, &tk)?;
                let r = if r < F::zero() { -r } else { r };
                let other = self.other_sheet(&sk, &tk)?;
                let cover =
                    crate::quadric::sphere_cover(c.clone(), [r.clone(), r.clone(), r.clone()])
                        .map_err(|e| {
                            SphereFamilyError::Undefined(format!(
                                "the sphere at (s, t) = ({}, {}): {e}",
                                format_scalar(&sk),
                                format_scalar(&tk)
                            ))
                        })?;
                Ok(EnvelopedSphere {
                    at: (sk, tk),
                    other,
                    sphere: (c, r),
                    cover,
                })
            })
            .collect()
    }

    /// The certificates of an enveloped sphere: its cover's (every patch on the sphere,
    /// watertight) and the contact: `|Ψ(s, t) − m|² = r²` and `|Ψ(s', t') − m|² = r²` (both
    /// contact points on the sphere, exact evaluation), and the tangency
    /// `⟨Ψ − m, ∂π(Φ)⟩ + Φ₄ ∂Φ₄ ≡ 0` holds identically by [`Certified::certify`].
    pub fn enveloped_sphere_certificates(&self, e: &EnvelopedSphere<F>) -> Vec<Certificate> {
        let mut out = e.cover.certify();
        let (c, r) = &e.sphere;
        for ((ps, pt), sheet) in [(&e.at, "first"), (&e.other, "second")] {
            let property = format!(
                "the {sheet} contact point Ψ({}, {}) lies on the sphere of centre ({}, {}, {}) and radius {}",
                format_scalar(ps),
                format_scalar(pt),
                format_scalar(&c[0]),
                format_scalar(&c[1]),
                format_scalar(&c[2]),
                format_scalar(r)
            );
            out.push(match self.eval(ps, pt) {
                Ok(x) => {
                    let d = (0..3).fold(F::zero(), |acc, k| {
                        let dk = x[k].clone() - c[k].clone();
                        acc + dk.clone() * dk
                    }) - r.clone() * r.clone();
                    // the size of the terms that cancel: Σ (|xₖ| + |mₖ|)² + r² (an f64
                    // residual is rounding of these, not of the cancelled result)
                    let scale = 1.0
                        + (0..3)
                            .map(|k| (x[k].to_f64().abs() + c[k].to_f64().abs()).powi(2))
                            .sum::<f64>()
                        + r.to_f64() * r.to_f64();
                    let ok = if F::EXACT {
                        d.is_zero()
                    } else {
                        d.to_f64().abs() <= 1e-9 * scale
                    };
                    Certificate::decide(property, ok, F::EXACT, || {
                        format!("|Ψ − m|² − r² = {}", format_scalar(&d))
                    })
                }
                Err(err) => Certificate::fails(property, err.to_string(), F::EXACT),
            });
        }
        out
    }

    /// The other sheet over the same parameters: `Ψ₂(s, t) = π(Φ(s, t)) − Φ₄(s, t) (w'₁, w'₂,
    /// w'₃)/w'₄` with `w' = ⟨p, p⟩ w − 2⟨w, p⟩ p` the second intersection of the net line
    /// `h(s, t)` through `w(s, t)` with Ω (`p = h ∩ {y₄ = 0}`, `⟨·,·⟩` the form of Ω;
    /// Gruber §3.1.2: `h ∩ Ω` are the two isotropic directions of the contact points).
    /// `Ψ₂(s, t)` is the second contact point of the same sphere `Φ(s, t)` that touches `Ψ`
    /// in `Ψ(s, t)`: [`Self::other_sheet`] as a rational map. Homogeneous `(W, X, Y, Z)`.
    pub fn other_sheet_homogeneous(&self) -> [MPoly<F>; 4] {
        self.other_sheet_and_divisor().0
    }

    /// [`Self::other_sheet_homogeneous`] and the common factor divided out (replayed from
    /// [`Reductions::other_sheet`] if recorded and the scalar is inexact).
    /// The third value: `true` if a replayed factor did not divide (the factors are then
    /// kept, and [`Self::other_sheet_patches`] refuses).
    fn other_sheet_and_divisor(&self) -> ([MPoly<F>; 4], Vec<MPoly<F>>, bool) {
        let w = omega_parametrization::<F>();
        let (a, b) = self.net.line_points();
        let subst = |x: &[MPoly<F>; 4]| -> [MPoly<F>; 4] {
            let d = NetParameters::degree_bounds(x.iter());
            let mut v: Vec<MPoly<F>> = x.iter().map(|p| self.params.substitute(p, d)).collect();
            normalize_content(&mut v);
            core::array::from_fn(|k| v[k].clone())
        };
        let (a, b) = (subst(&a), subst(&b));
        // p = h ∩ {y₄ = 0} = a₄ b − b₄ a: never a real point of Ω (those have y₄ ≠ 0), so
        // never w, and w'₄ = ⟨p, p⟩ w₄ with ⟨p, p⟩ = p₁² + p₂² + p₃² > 0 adds no pole
        let p: [MPoly<F>; 4] = core::array::from_fn(|k| &(&a[3] * &b[k]) - &(&b[3] * &a[k]));
        let pp = omega_form(&p, &p);
        let wp = omega_form(&w, &p);
        let two = MPoly::constant(2, F::from_i64(2));
        let w2: [MPoly<F>; 4] = core::array::from_fn(|k| &(&pp * &w[k]) - &(&(&two * &wp) * &p[k]));
        let mut psi = vec![&self.phi_st_den * &w2[3]];
        for i in 0..3 {
            psi.push(&(&self.phi_st[i] * &w2[3]) - &(&self.phi_st[3] * &w2[i]));
        }
        let mut candidates = factor_candidates(&self.params, &w);
        candidates.push(w2[3].clone());
        candidates.sort_by_key(|p| std::cmp::Reverse(p.total_degree().unwrap_or(0)));
        let replay = self
            .reductions
            .other_sheet
            .as_ref()
            .filter(|_| !F::EXACT)
            .map(|f| (f, self.reductions.other_sheet_support.as_ref()));
        let mut record = Vec::new();
        let failed = reduction_step(&mut psi, replay, &mut record, |p| {
            cancel_common_factors(p, &candidates)
        })
        .is_err();
        if failed {
            record = vec![Vec::new()];
        }
        normalize_content(&mut psi);
        let d = record.pop().unwrap_or_default();
        (core::array::from_fn(|k| psi[k].clone()), d, failed)
    }

    /// The other sheet [`Self::other_sheet_homogeneous`] on `[s₀, s₁] × [t₀, t₁]` as
    /// positive-weight rational Bézier patches, with its certificates: the envelope
    /// identities `|Ψ₂ − π(Φ)|² ≡ Φ₄²`, `⟨Ψ₂ − π(Φ), ∂π(Φ)⟩ + Φ₄ ∂Φ₄ ≡ 0` in `s` and `t`
    /// (exact polynomial identities), `Ψ₂ ≢ Ψ` unless the net lines touch Ω, and every weight
    /// positive.
    ///
    /// # Errors
    /// As [`Self::export_patches`] (a pole of `Ψ₂` on the rectangle).
    pub fn other_sheet_patches(
        &self,
        s: (F, F),
        t: (F, F),
    ) -> Result<(Vec<BezierPatch<F>>, Vec<Certificate>), SphereFamilyError> {
        let (psi2, _, failed) = self.other_sheet_and_divisor();
        if failed {
            return Err(SphereFamilyError::Undefined(
                "the float path does not build this other sheet: a common factor the exact build divides out does not divide the f64 numerators up to rounding (10⁻⁶); build it without --float".into(),
            ));
        }
        let mut certs = self.other_sheet_certificates_of(&psi2);
        let (pieces, weight) = export_pieces(&psi2, s, t)?;
        certs.push(weight);
        Ok((pieces, certs))
    }

    /// The certificates of the other sheet [`Self::other_sheet_homogeneous`]: the envelope
    /// identities `|Ψ₂ − π(Φ)|² ≡ Φ₄²`, `⟨Ψ₂ − π(Φ), ∂π(Φ)⟩ + Φ₄ ∂Φ₄ ≡ 0` in `s` and `t`, and
    /// `Ψ₂ ≢ Ψ` unless the net lines touch Ω.
    pub fn other_sheet_certificates(&self) -> Vec<Certificate> {
        self.other_sheet_certificates_of(&self.other_sheet_homogeneous())
    }

    fn other_sheet_certificates_of(&self, psi2: &[MPoly<F>; 4]) -> Vec<Certificate> {
        let mut certs = envelope_certificates(psi2, &self.phi_st, &self.phi_st_den);
        let same = (0..4).all(|i| {
            (i + 1..4).all(|j| (&(&psi2[i] * &self.psi[j]) - &(&psi2[j] * &self.psi[i])).is_zero())
        });
        let touching = self
            .net
            .axis_positions()
            .iter()
            .all(|p| matches!(p, AxisPosition::Tangent));
        certs.push(Certificate::decide(
            "the second sheet Ψ₂ is a different map than Ψ (the net lines are not tangents of Ω)",
            !same || touching,
            F::EXACT,
            || "Ψ₂ ≡ Ψ up to a factor".into(),
        ));
        certs
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lines::PointRow;
    use rcagd_algebra::Rational;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }
    fn row(a: [i64; 4], b: [i64; 4]) -> PointRow<Rational> {
        PointRow::new(a.map(q), b.map(q)).expect("row")
    }

    #[test]
    fn gruber_331_phi_and_certificates() {
        let net = LineNet::hyperbolic(
            row([1, 0, 0, 0], [0, 1, 0, 0]),
            row([0, 2, 0, 1], [0, 0, 1, 0]),
        )
        .expect("net");
        let a = Support::univariate(&[q(0), q(0), q(1)], 0);
        let b = Support::univariate(&[q(0), q(0), q(1)], 1);
        let env = SphereFamilyEnvelope::new(&net, a, b).expect("env");
        // (3.15): Φ = (−u², 2u, 2v, 4u + v²)
        let (c, r) = env.sphere_at_parameters(&q(3), &q(5)).expect("sphere");
        assert_eq!(c.to_vec(), vec![q(-9), q(6), q(10)]);
        assert_eq!(r, q(37));
        assert_eq!(env.subcase(), Subcase::HyperbolicPassantPassant);
        let certs = env.certify();
        assert!(Certificate::all_hold(&certs), "{certs:#?}");
    }
}
