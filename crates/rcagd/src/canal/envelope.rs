//! The rational parametrization of a canal surface (Gruber §2.1 (2.10)–(2.17),
//! Peternell–Pottmann; docs/math/lines-and-canal.md, "Canal surfaces", corrected) and the cyclographic
//! construction for quadratic families (Gruber §2.3, docs/math/lines-and-canal.md, "Canal surfaces").
//!
//! **Peternell–Pottmann recipe (docs/math/lines-and-canal.md, "Canal surfaces").** With the derivative numerators
//! `P = (P₁, P₂, P₃, P₄) ∝ (ṁ, ṙ)` ([`CanalSpine::derivative_numerators`]) and a split
//! `D = P₁² + P₂² + P₃² − P₄² = g₁² + g₂²` ([`super::sum_of_squares`]), pick a coordinate axis
//! `j` and a sign `σ` with `c = P₄ + σPⱼ ≢ 0` (if `c ≡ 0` for one axis the stereographic image
//! of the characteristic circles is a line; another axis is used), and let `a, b` be the
//! other two axes. In the frame `(a, b, σ·j)` the unit normals of the envelope along the
//! characteristic circle are the inverse stereographic images (centre `(0, 0, 1)`) of the
//! circle with centre `μ = −(P_a, P_b)/c` and radius² `ρ² = D/c²` (2.13, corrected per
//! docs/math/lines-and-canal.md, Errata G4: the denominator is squared). The rational point `δ̃ = μ + g̃`,
//! `g̃ = (g₁, g₂)/c`, is reflected in the diameters with normals `n = (u, 1)` (2.15):
//!
//! ```text
//! k(t, u) = δ̃ − 2⟨g̃, n⟩/⟨n, n⟩·n,     K₀ = c(u² + 1),
//! K₁ = (g₁ − P_a)(u² + 1) − 2(g₁u + g₂)u,   K₂ = (g₂ − P_b)(u² + 1) − 2(g₁u + g₂),
//! q = (2K₁K₀, 2K₂K₀, K₁² + K₂² − K₀²)/(K₀² + K₁² + K₂²)          (2.16)
//! x(t, u) = m(t) + r(t) q(t, u)                                   (2.17)
//! ```
//!
//! All four homogeneous components of `q` vanish at `u = ±i` (there `K₀ = 0` and
//! `K₁ = ±iK₂`), so `u² + 1` is divided out: the characteristic circles get degree 2 in `u`.
//! Common factors in `t` (and in `u`) are removed for exact scalars. For polynomial `m, r` of
//! degree `k` the bidegree is at most `(3k − 2, 2)`.
//!
//! **Certificates** (polynomial identities in `(t, u)`, homogeneous `X = (X₀, X₁, X₂, X₃)`,
//! spine `(W, M, R)`): `Σ(XᵢW − MᵢX₀)² − R²X₀² ≡ 0` (`|x − m|² = r²`),
//! `Σ(XᵢW − MᵢX₀)Pᵢ + R X₀ P₄ ≡ 0` (`(x − m)·ṁ + r ṙ = 0`, the contact condition, sign per
//! docs/math/lines-and-canal.md, Errata G3), `⟨x − m, x_u⟩ ≡ 0`, `⟨x − m, x_t⟩ ≡ 0` (the normal passes through the
//! spine: the surface touches every sphere), and the split `g₁² + g₂² ≡ D`.
//!
//! **Degree.** The exact builder tries every admissible axis and every choice of Gaussian
//! factors of `D` (Gruber (2.35)) with this construction and with Krasauskas' reduced
//! pencil ([`super::krasauskas`], over `Q` or over the field `Q(√d)` of the split), and keeps the lowest bidegree ([`Method`]); the
//! Krasauskas bound of Gruber Satz 2 (2.37) is computed by [`krasauskas_bound`] for
//! comparison — note docs/math/lines-and-canal.md, Errata G9: as printed it holds for rational `γ` and overestimates
//! for polynomial data (e.g. `m = (t, t²/2, 0)`, `r = t`: (2.37) gives `(6, 2)`, the
//! construction gives `(4, 2)`).
//!
//! **Cyclographic construction for quadratic `k` (docs/math/lines-and-canal.md, "Canal surfaces", Gruber §2.3).** For a polynomial
//! curve `k(p) ∈ R^{3,1}` of degree ≤ 2, `k̇(p) = a + b p` and the condition
//! `⟨w(s,t), k̇(p)⟩_pe = 0` for the isotropic direction `w(s,t) = (2s, 2t, 1 − s² − t²,
//! 1 + s² + t²)` is linear in `p`: `p = −⟨w, a⟩/⟨w, b⟩`, and
//! `Γ(s, t) = π(k(p)) − k₄(p)·(w₁, w₂, w₃)/w₄` is a rational parametrization over `Q` of the
//! whole envelope (no square root at all) — [`QuadraticCanal`].

use super::bipoly::{bidegree, patch_of, BiPoly};
use super::krasauskas;
use super::sum_of_squares::{sum_of_two_squares_approx, SumOfSquares};
use super::{CanalError, CanalSpine};
use crate::error::format_scalar;
use crate::Certified;
use rcagd_algebra::factor::coprime_mod_p;
use rcagd_algebra::roots::{isolate_real_roots, square_free_decomposition};
use rcagd_algebra::{Certificate, Poly, QuadExt, Rational, Scalar};
use rcagd_geom::certify::polynomial_is_zero_scaled;
use rcagd_geom::BezierPatch;

/// Which oriented family is enveloped: `(m; r)` or `(m; −r)` (the same surface with the
/// opposite unit normal `q`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Orientation {
    /// The family as given.
    #[default]
    Positive,
    /// The family `(m; −r)`.
    Negative,
}

/// The stereographic frame of the construction: `c = P₄ + sign·P_axis`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AxisChoice {
    /// The axis `j ∈ {0, 1, 2}` that plays the role of `x₃` in (2.13).
    pub axis: usize,
    /// `+1` or `−1`.
    pub positive: bool,
}

impl AxisChoice {
    /// The six admissible choices, `x₃` first (Gruber's frame).
    pub fn all() -> [AxisChoice; 6] {
        let mut out = [AxisChoice {
            axis: 2,
            positive: true,
        }; 6];
        for (k, (axis, positive)) in [
            (2, true),
            (2, false),
            (1, true),
            (1, false),
            (0, true),
            (0, false),
        ]
        .into_iter()
        .enumerate()
        {
            out[k] = AxisChoice { axis, positive };
        }
        out
    }

    /// `(j, a, b)`: the axis `j` (clamped to `0..3`) and the other two axes in order.
    fn indices(&self) -> (usize, usize, usize) {
        let j = self.axis.min(2);
        let mut others = (0..3).filter(|&i| i != j);
        let a = others.next().unwrap_or(0);
        let b = others.next().unwrap_or(1);
        (j, a, b)
    }

    /// `P₄ + σPⱼ` of the derivative numerators: `c` of (2.13) and `α` of Krasauskas' form.
    pub(crate) fn pole_polynomial<F: Scalar>(&self, p: &[Poly<F>; 4]) -> Poly<F> {
        let (j, _, _) = self.indices();
        if self.positive {
            &p[3] + &p[j]
        } else {
            &p[3] - &p[j]
        }
    }

    /// The numerators `P_a`, `P_b` of the two other axes.
    pub(crate) fn other_numerators<'a, F: Scalar>(
        &self,
        p: &'a [Poly<F>; 4],
    ) -> (&'a Poly<F>, &'a Poly<F>) {
        let (_, a, b) = self.indices();
        (&p[a], &p[b])
    }

    /// The normal `q` in the user's frame from its components along `a`, `b` and `σ j`.
    pub(crate) fn place<F: Scalar>(
        &self,
        along_a: BiPoly<F>,
        along_b: BiPoly<F>,
        along_j: BiPoly<F>,
    ) -> [BiPoly<F>; 3] {
        let (j, a, b) = self.indices();
        let mut q: [BiPoly<F>; 3] = [BiPoly::zero(), BiPoly::zero(), BiPoly::zero()];
        q[a] = along_a;
        q[b] = along_b;
        q[j] = if self.positive {
            along_j
        } else {
            along_j.neg()
        };
        q
    }
}

/// Options of the canal-surface builders.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CanalOptions {
    /// The orientation of the family.
    pub orientation: Orientation,
    /// The choice of Gaussian factors (bit `k` picks `π̄ₖ`); `None`: the lowest degree.
    pub choice: Option<usize>,
    /// The stereographic axis; `None`: the lowest degree among the admissible ones.
    pub axis: Option<AxisChoice>,
    /// The parameter domain `[a, b]` on which the envelope must be real; `None`: all of `R`.
    /// If `D < 0` outside `[a, b]`, the family is reparametrized by
    /// `t = (a + b s²)/(1 + s²)` (Peternell §4.5), which is real for all `s`.
    pub domain: Option<(Rational, Rational)>,
    /// Which constructions the exact builder may use ([`Method::Lowest`]: every one, the
    /// lowest bidegree wins).
    pub method: Method,
}

/// The constructions [`canal_surface`] may use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Try Peternell–Pottmann and Krasauskas' reduced pencil for every axis and split, keep
    /// the lowest bidegree.
    #[default]
    Lowest,
    /// Only the Peternell–Pottmann construction (Gruber §2.1).
    PeternellPottmann,
    /// Only Krasauskas' reduced pencil (Gruber §2.4; over `Q` with factors over `Q(i)`, or
    /// over `Q(√d)` with factors over `Q(√d)(i)` when the split of `D` needs `√d`).
    Krasauskas,
}

/// The characteristic circle `K(t) ∩ K̇(t)` at one parameter (Gruber §2.1).
#[derive(Debug, Clone, PartialEq)]
pub struct CharacteristicCircle<F> {
    /// Centre `m − (r P₄/|P_m|²) P_m`.
    pub center: [F; 3],
    /// The normal of its plane (the spine tangent direction `P_m ∥ ṁ`).
    pub normal: [F; 3],
    /// Squared radius `r² D/|P_m|²` (zero: a point).
    pub radius_sq: F,
}

/// A rational canal surface `x(t, u)` in homogeneous coordinates with its defining data.
#[derive(Clone, PartialEq)]
pub struct CanalSurface<F> {
    spine: CanalSpine<F>,
    numerators: [Poly<F>; 4],
    split: [Poly<F>; 2],
    axis: AxisChoice,
    x: [BiPoly<F>; 4],
    reparametrized: Option<(Rational, Rational)>,
    domain: Option<(Rational, Rational)>,
    construction: Construction,
    /// The homogeneous unit normal the surface was built from (how it was built, not part
    /// of the value: equality and `Debug` ignore it).
    normals: BuiltNormals<F>,
}

/// The data of the surface (the normals it was built from are not part of it).
impl<F: std::fmt::Debug> std::fmt::Debug for CanalSurface<F> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CanalSurface")
            .field("spine", &self.spine)
            .field("numerators", &self.numerators)
            .field("split", &self.split)
            .field("axis", &self.axis)
            .field("x", &self.x)
            .field("reparametrized", &self.reparametrized)
            .field("domain", &self.domain)
            .field("construction", &self.construction)
            .finish()
    }
}

/// The homogeneous unit normal `(q₀, q)` of the characteristic circles from which the
/// envelope `X = (W q₀, M q₀ + R q)` of a [`CanalSurface`] was built, before the common
/// factors of `X` were removed ([`envelope_from_normals`]); `None` for a surface that was
/// mapped or converted after its construction. Shared by clones; two surfaces are equal
/// whether or not they carry it.
#[derive(Clone)]
struct BuiltNormals<F>(Option<std::sync::Arc<[BiPoly<F>; 4]>>);

impl<F> PartialEq for BuiltNormals<F> {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

/// Which construction produced a [`CanalSurface`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Construction {
    /// Peternell–Pottmann (Gruber §2.1, (2.10)–(2.17); module docs).
    #[default]
    PeternellPottmann,
    /// Krasauskas' pencil `f_s(a + u b)` reduced by (2.36) ([`super::krasauskas`]).
    Krasauskas {
        /// `max(deg a, deg b)` of the first pencil.
        initial_degree: usize,
        /// `max(deg a, deg b)` after the reduction.
        reduced_degree: usize,
        /// The number of reduction steps.
        steps: usize,
    },
}

impl<F: Scalar> CanalSurface<F> {
    /// A surface on all of `R` (no domain, no reparametrization) from its parts.
    fn from_parts(
        spine: &CanalSpine<F>,
        numerators: &[Poly<F>; 4],
        split: &[Poly<F>; 2],
        axis: AxisChoice,
        x: [BiPoly<F>; 4],
        construction: Construction,
    ) -> Self {
        CanalSurface {
            spine: spine.clone(),
            numerators: numerators.clone(),
            split: split.clone(),
            axis,
            x,
            reparametrized: None,
            domain: None,
            construction,
            normals: BuiltNormals(None),
        }
    }

    /// [`Self::from_parts`] of the envelope of the normal `(q₀, q)` (common factors removed
    /// for exact scalars), remembering the normal ([`Self::mirrored`]).
    fn from_normals(
        spine: &CanalSpine<F>,
        numerators: &[Poly<F>; 4],
        split: &[Poly<F>; 2],
        axis: AxisChoice,
        normals: [BiPoly<F>; 4],
        construction: Construction,
    ) -> Result<Self, CanalError> {
        let [q0, q1, q2, q3] = &normals;
        let mut x = envelope_from_normals(spine, q0, &[q1.clone(), q2.clone(), q3.clone()]);
        if F::EXACT {
            reduce(&mut x)?;
        }
        let mut s = Self::from_parts(spine, numerators, split, axis, x, construction);
        s.normals = BuiltNormals(Some(std::sync::Arc::new(normals)));
        Ok(s)
    }
}

fn sq<F: Scalar>(p: &Poly<F>) -> Poly<F> {
    p * p
}

fn poly_scale<F: Scalar>(p: &Poly<F>) -> f64 {
    p.coeffs()
        .iter()
        .map(|x| x.to_f64().abs())
        .fold(0.0, f64::max)
}

fn bi_scale<F: Scalar>(b: &BiPoly<F>) -> f64 {
    b.coeffs().iter().map(poly_scale).fold(0.0, f64::max)
}

fn small<F: Scalar>(p: &Poly<F>, scale: f64) -> bool {
    if F::EXACT {
        p.is_zero()
    } else {
        poly_scale(p) <= 1e-9 * scale.max(1.0)
    }
}

/// Builds `x(t, u)` for one axis choice (module docs).
fn build<F: Scalar>(
    spine: &CanalSpine<F>,
    numerators: &[Poly<F>; 4],
    g: &[Poly<F>; 2],
    axis: AxisChoice,
) -> Result<CanalSurface<F>, CanalError> {
    let p = numerators;
    let (j, _, _) = axis.indices();
    let (pa, pb) = axis.other_numerators(p);
    let c = axis.pole_polynomial(p);
    let s = p.iter().map(poly_scale).fold(0.0, f64::max);
    if small(&c, s) {
        return Err(CanalError::DegenerateSpine(format!(
            "ṙ {} ṁ{} ≡ 0 for this axis: the stereographic image of the characteristic circles is a line (use another axis)",
            if axis.positive { "+" } else { "−" },
            j + 1
        )));
    }
    let [g1, g2] = g;
    let two = F::from_i64(2);
    let k0 = BiPoly::new(vec![c.clone(), Poly::zero(), c]);
    let k1 = BiPoly::new(vec![g1 - pa, g2.scale(&-two.clone()), -&(g1 + pa)]);
    let k2 = BiPoly::new(vec![-&(g2 + pb), g1.scale(&-two.clone()), g2 - pb]);
    let (k00, k11, k22) = (k0.mul(&k0), k1.mul(&k1), k2.mul(&k2));
    let q0 = k00.add(&k11).add(&k22).div_u2_plus_1()?;
    let qa = k1.mul(&k0).scale(&two).div_u2_plus_1()?;
    let qb = k2.mul(&k0).scale(&two).div_u2_plus_1()?;
    let qj = k11.add(&k22).sub(&k00).div_u2_plus_1()?;
    let [q1, q2, q3] = axis.place(qa, qb, qj);
    CanalSurface::from_normals(
        spine,
        numerators,
        g,
        axis,
        [q0, q1, q2, q3],
        Construction::PeternellPottmann,
    )
}

/// `X = (W q₀, M q₀ + R q)`: the envelope `x = m + r q/q₀` (2.17) in homogeneous
/// coordinates from the homogeneous unit normal `(q₀, q)` of the characteristic circles.
pub(crate) fn envelope_from_normals<F: Scalar>(
    spine: &CanalSpine<F>,
    q0: &BiPoly<F>,
    q: &[BiPoly<F>; 3],
) -> [BiPoly<F>; 4] {
    let w = spine.weight();
    let m = spine.center_polys();
    let r = spine.radius_poly();
    [
        q0.mul_t(w),
        q0.mul_t(&m[0]).add(&q[0].mul_t(r)),
        q0.mul_t(&m[1]).add(&q[1].mul_t(r)),
        q0.mul_t(&m[2]).add(&q[2].mul_t(r)),
    ]
}

/// The monic `gcd` of polynomials (zero if all are zero), lowest degrees first and stopped
/// as soon as it is `1` (the same value as the `gcd` of all of them, at a fraction of the
/// cost when there is no common factor).
fn common_factor<'a, F: Scalar + 'a>(polys: impl Iterator<Item = &'a Poly<F>>) -> Poly<F> {
    let mut ps: Vec<&Poly<F>> = polys.filter(|p| !p.is_zero()).collect();
    ps.sort_by_key(|p| p.degree());
    // the usual case, no common factor: two of the lowest degree coprime, proved modulo a
    // prime (exact scalars)
    if F::EXACT {
        if let (Some(p), Some(q)) = (ps.first(), ps.get(1)) {
            if coprime_mod_p(p, q) {
                return Poly::constant(F::one());
            }
        }
    }
    let mut acc = Poly::zero();
    for p in ps {
        acc = acc.gcd(p);
        if acc.degree() == Some(0) {
            break;
        }
    }
    acc
}

/// Removes the common factors in `t` and in `u` of the four components (exact scalars).
fn reduce<F: Scalar>(x: &mut [BiPoly<F>; 4]) -> Result<(), CanalError> {
    let ct = common_factor(x.iter().flat_map(|b| b.coeffs().iter()));
    if ct.degree().is_some_and(|d| d > 0) {
        for b in x.iter_mut() {
            *b = b.div_t(&ct)?;
        }
    }
    let xt: Vec<BiPoly<F>> = x.iter().map(BiPoly::transpose).collect();
    let cu = common_factor(xt.iter().flat_map(|b| b.coeffs().iter()));
    if cu.degree().is_some_and(|d| d > 0) {
        for b in x.iter_mut() {
            *b = b.transpose().div_t(&cu)?.transpose();
        }
    }
    Ok(())
}

fn degree_key<F: Scalar>(s: &CanalSurface<F>) -> (usize, usize, usize) {
    let (dt, du) = s.degree();
    (dt, du, s.x.iter().map(BiPoly::num_terms).sum())
}

/// Builds with the given split, trying the requested or all axes; keeps the lowest degree.
fn build_best<F: Scalar>(
    spine: &CanalSpine<F>,
    g: &[Poly<F>; 2],
    axis: Option<AxisChoice>,
) -> Result<CanalSurface<F>, CanalError> {
    let numerators = spine.derivative_numerators()?;
    let axes: Vec<AxisChoice> = match axis {
        Some(a) => vec![a],
        None => AxisChoice::all().to_vec(),
    };
    let mut best: Option<CanalSurface<F>> = None;
    let mut last_err = None;
    for a in axes {
        match build(spine, &numerators, g, a) {
            Ok(s) => {
                let better = match &best {
                    None => true,
                    Some(b) => degree_key(&s) < degree_key(b),
                };
                if better {
                    best = Some(s);
                }
                if !F::EXACT {
                    break;
                }
            }
            Err(e) => last_err = Some(e),
        }
    }
    best.ok_or_else(|| {
        last_err.unwrap_or_else(|| CanalError::DegenerateSpine("no admissible axis".into()))
    })
}

/// The irreducible factors of `det(a, b)` over the coefficient field with `i`, for step 3
/// of the Krasauskas reduction ([`super::krasauskas`]).
pub(crate) type Factors<'a, F> = &'a dyn krasauskas::FactorSource<F>;

/// Builds `x(t, u)` from Krasauskas' reduced pencil for one axis choice over `Q`
/// (factors over `Q(i)`, [`krasauskas::gaussian_factors_of`], through `memo`).
pub(crate) fn build_krasauskas(
    spine: &CanalSpine<Rational>,
    numerators: &[Poly<Rational>; 4],
    g: &[Poly<Rational>; 2],
    axis: AxisChoice,
    balance_at: &Rational,
    memo: &krasauskas::FactorMemo,
) -> Result<CanalSurface<Rational>, CanalError> {
    build_krasauskas_with(spine, numerators, g, axis, balance_at, memo)
}

/// Builds `x(t, u)` from Krasauskas' reduced pencil for one axis choice
/// ([`super::krasauskas`]), over `Q` (factors over `Q(i)`) or `Q(√d)` (factors over
/// `Q(√d)(i)`).
pub(crate) fn build_krasauskas_with<F: krasauskas::RealRoots>(
    spine: &CanalSpine<F>,
    numerators: &[Poly<F>; 4],
    g: &[Poly<F>; 2],
    axis: AxisChoice,
    balance_at: &Rational,
    factors: Factors<'_, F>,
) -> Result<CanalSurface<F>, CanalError> {
    let mut pencil = krasauskas::reduced_pencil(numerators, g, axis, factors)?;
    pencil.balance_at(balance_at);
    let d = spine.discriminant()?;
    if krasauskas::has_interior_base_point(&pencil, &d)? {
        return Err(CanalError::DegenerateSpine(
            "the reduced Krasauskas pencil collapses a characteristic circle (det(a, b) has a real root where D ≠ 0)".into(),
        ));
    }
    let [q0, xr, xi, xd] = pencil.sphere_image();
    let [q1, q2, q3] = axis.place(xr, xi, xd);
    let s = CanalSurface::from_normals(
        spine,
        numerators,
        g,
        axis,
        [q0, q1, q2, q3],
        Construction::Krasauskas {
            initial_degree: pencil.initial_degree,
            reduced_degree: pencil.degree(),
            steps: pencil.steps,
        },
    )?;
    if s.x.iter().all(BiPoly::is_zero) {
        return Err(CanalError::DegenerateSpine(
            "the Krasauskas pencil gives the zero point".into(),
        ));
    }
    Ok(s)
}

/// [`build_best`] over an exact field (`Q` or `Q(√d)`), also trying Krasauskas' reduced
/// pencil for every admissible axis (step 3 with `factors`).
fn build_best_exact<F: krasauskas::RealRoots>(
    spine: &CanalSpine<F>,
    g: &[Poly<F>; 2],
    axis: Option<AxisChoice>,
    method: Method,
    balance_at: &Rational,
    factors: Factors<'_, F>,
) -> Result<CanalSurface<F>, CanalError> {
    let (mut best, err) = match method {
        Method::PeternellPottmann => return build_best(spine, g, axis),
        Method::Krasauskas => (None, None),
        Method::Lowest => match build_best(spine, g, axis) {
            Ok(s) => (Some(s), None),
            Err(e) => (None, Some(e)),
        },
    };
    let numerators = spine.derivative_numerators()?;
    let axes: Vec<AxisChoice> = match axis {
        Some(a) => vec![a],
        None => AxisChoice::all().to_vec(),
    };
    for a in axes {
        if let Ok(s) = build_krasauskas_with(spine, &numerators, g, a, balance_at, factors) {
            let better = match &best {
                None => true,
                Some(b) => degree_key(&s) < degree_key(b),
            };
            if better {
                best = Some(s);
            }
        }
    }
    best.ok_or_else(|| {
        err.unwrap_or_else(|| {
            CanalError::DegenerateSpine("no admissible axis for Krasauskas' pencil".into())
        })
    })
}

fn check_split<F: Scalar>(d: &Poly<F>, g: &[Poly<F>; 2]) -> Result<(), CanalError> {
    let s = &sq(&g[0]) + &sq(&g[1]);
    let r = &s - d;
    // f64: rounding grows with the size of the squared terms, not of D
    let n = (d.degree().unwrap_or(0) + 1) as f64;
    let scale = poly_scale(d)
        .max(poly_scale(&g[0]).powi(2))
        .max(poly_scale(&g[1]).powi(2))
        * n;
    if small(&r, scale) {
        Ok(())
    } else {
        Err(CanalError::NotASplit(format!(
            "g₁² + g₂² − D has {} non-zero coefficients (largest ≈ {:e})",
            r.coeffs().iter().filter(|x| !x.is_zero()).count(),
            poly_scale(&r)
        )))
    }
}

/// The canal surface of `spine` from a given split `D = g₁² + g₂²` (generic over the
/// scalar; `D` as in [`CanalSpine::discriminant`]). The orientation and axis options apply;
/// `choice` and `domain` are ignored (the split is given).
///
/// # Errors
/// [`CanalError::NotASplit`] if `g₁² + g₂² ≠ D`; [`CanalError::DegenerateSpine`] as in
/// [`CanalSpine::derivative_numerators`] or if no axis is admissible.
pub fn canal_surface_with_split<F: Scalar>(
    spine: &CanalSpine<F>,
    g1: &Poly<F>,
    g2: &Poly<F>,
    options: &CanalOptions,
) -> Result<CanalSurface<F>, CanalError> {
    let spine = match options.orientation {
        Orientation::Positive => spine.clone(),
        Orientation::Negative => spine.reversed(),
    };
    let d = spine.discriminant()?;
    let g = [g1.clone(), g2.clone()];
    check_split(&d, &g)?;
    build_best(&spine, &g, options.axis)
}

/// The result of the exact builder: over `Q`, or over one quadratic field `Q(√d)`.
#[derive(Debug, Clone, PartialEq)]
pub enum CanalBuild {
    /// A parametrization with rational coefficients.
    Rational(CanalSurface<Rational>),
    /// A parametrization over `Q(√radicand)` (the split of `D` needs it).
    Extension {
        /// The square-free radicand `d`.
        radicand: Rational,
        /// The surface over `Q(√d)`.
        surface: CanalSurface<QuadExt>,
    },
}

impl CanalBuild {
    /// `(deg_t, deg_u)`.
    pub fn degree(&self) -> (usize, usize) {
        match self {
            CanalBuild::Rational(s) => s.degree(),
            CanalBuild::Extension { surface, .. } => surface.degree(),
        }
    }

    /// `None` over `Q`, `Some(d)` over `Q(√d)`.
    pub fn radicand(&self) -> Option<&Rational> {
        match self {
            CanalBuild::Rational(_) => None,
            CanalBuild::Extension { radicand, .. } => Some(radicand),
        }
    }

    /// The rational surface, if the build is rational.
    pub fn as_rational(&self) -> Option<&CanalSurface<Rational>> {
        match self {
            CanalBuild::Rational(s) => Some(s),
            CanalBuild::Extension { .. } => None,
        }
    }

    /// The surface over `QuadExt` (rationals embedded for a rational build).
    pub fn to_ext(&self) -> CanalSurface<QuadExt> {
        match self {
            CanalBuild::Rational(s) => s.map_scalar(|x| QuadExt::rational(x.clone())),
            CanalBuild::Extension { surface, .. } => surface.clone(),
        }
    }

    /// The surface in `f64` (for tessellation and export).
    pub fn to_f64(&self) -> CanalSurface<f64> {
        match self {
            CanalBuild::Rational(s) => s.map_scalar(Scalar::to_f64),
            CanalBuild::Extension { surface, .. } => surface.map_scalar(Scalar::to_f64),
        }
    }
}

impl Certified for CanalBuild {
    fn certify(&self) -> Vec<Certificate> {
        match self {
            CanalBuild::Rational(s) => s.certify(),
            CanalBuild::Extension { surface, radicand } => {
                let mut c = surface.certify();
                for x in &mut c {
                    x.property = format!("{} [over Q(√{})]", x.property, format_scalar(radicand));
                }
                c
            }
        }
    }
}

/// Reparametrizes the family by `t = (a + b s²)/(1 + s²)` (homogeneous substitution of
/// degree `k`): real for every `s` when `D ≥ 0` on `[a, b]` (Peternell §4.5).
fn reparametrize<F: Scalar>(spine: &CanalSpine<F>, a: &F, b: &F) -> CanalSpine<F> {
    let k = spine.degree();
    let num = Poly::new(vec![a.clone(), F::zero(), b.clone()]);
    let den = Poly::new(vec![F::one(), F::zero(), F::one()]);
    let sub = |p: &Poly<F>| {
        let mut acc = Poly::zero();
        for (i, c) in p.coeffs().iter().enumerate() {
            let term = &num.pow(i as u32) * &den.pow((k - i) as u32);
            acc = &acc + &term.scale(c);
        }
        acc
    };
    let [w, m0, m1, m2, r] = spine.homogeneous();
    CanalSpine {
        w: sub(&w),
        m: [sub(&m0), sub(&m1), sub(&m2)],
        r: sub(&r),
        numerators: super::NumeratorCache::new(),
    }
}

/// The family oriented per `options`, checked for a real envelope on the domain (or on `R`),
/// and reparametrized by `t = (a + b s²)/(1 + s²)` when `D < 0` outside the domain `[a, b]`
/// (then `Some((a, b))` is returned beside it).
#[allow(clippy::type_complexity)]
fn oriented_on_domain(
    spine: &CanalSpine<Rational>,
    options: &CanalOptions,
    memo: &krasauskas::FactorMemo,
) -> Result<(CanalSpine<Rational>, Option<(Rational, Rational)>), CanalError> {
    let mut spine = match options.orientation {
        Orientation::Positive => spine.clone(),
        Orientation::Negative => spine.reversed(),
    };
    let mut reparam = None;
    if let Some((a, b)) = &options.domain {
        memo.check_real_envelope(&spine, Some((a, b)))?;
        if memo.check_real_envelope(&spine, None).is_err() {
            spine = reparametrize(&spine, a, b);
            reparam = Some((a.clone(), b.clone()));
        }
    } else {
        memo.check_real_envelope(&spine, None)?;
    }
    Ok((spine, reparam))
}

/// The canal surface of a rational family, exactly: over `Q` when `D` is a sum of two
/// rational squares, otherwise over the quadratic field it needs (said in the result),
/// otherwise an error — never silently in `f64` (module docs, [`super::sum_of_squares`]).
///
/// # Errors
/// [`CanalError::NoRealEnvelope`] naming the interval where `|ṁ| < |ṙ|` (on the domain, or
/// on `R` without one); [`CanalError::DegenerateSpine`]; [`CanalError::NeedsLargerExtension`];
/// [`CanalError::Factorization`]; [`CanalError::ZeroRadius`] for a radius that vanishes
/// identically (the envelope is the spine itself, not a surface).
pub fn canal_surface(
    spine: &CanalSpine<Rational>,
    options: &CanalOptions,
) -> Result<CanalBuild, CanalError> {
    canal_surface_memo(spine, options, &krasauskas::FactorMemo::default())
}

/// [`canal_surface`] with the exact factorizations taken from (and added to) `memo` (the
/// same result: the memo only returns what the factorization would).
pub(crate) fn canal_surface_memo(
    spine: &CanalSpine<Rational>,
    options: &CanalOptions,
    memo: &krasauskas::FactorMemo,
) -> Result<CanalBuild, CanalError> {
    if spine.r.is_zero() {
        return Err(CanalError::ZeroRadius);
    }
    let (spine, reparam) = oriented_on_domain(spine, options, memo)?;
    let d = spine.discriminant()?;
    let split = memo.gaussian_split(&d)?;
    // the Krasauskas pencil is balanced at the middle of the domain (s = 0 after the
    // reparametrization of a domain, t = 0 without one)
    let mid = match (&options.domain, &reparam) {
        (Some((a, b)), None) => (a.clone() + b.clone()) / Rational::from(2),
        _ => Rational::ZERO,
    };
    let choices: Vec<usize> = match options.choice {
        Some(c) => vec![c],
        None => (0..split.num_choices().min(16)).collect(),
    };
    let mut best: Option<CanalBuild> = None;
    let mut last_err = None;
    for choice in choices {
        let sos = match split.decompose(choice) {
            Ok(s) => s,
            Err(e) => {
                last_err = Some(CanalError::from(e));
                continue;
            }
        };
        let built = match &sos {
            SumOfSquares::Rational { g1, g2 } => build_best_exact(
                &spine,
                &[g1.clone(), g2.clone()],
                options.axis,
                options.method,
                &mid,
                memo,
            )
            .map(|mut s| {
                s.reparametrized = reparam.clone();
                s.domain = options.domain.clone();
                CanalBuild::Rational(s)
            }),
            SumOfSquares::Extension { radicand, g1, g2 } => {
                let se = spine.map_scalar(|x| QuadExt::rational(x.clone()));
                let factors = |l: &Poly<rcagd_algebra::Complex<QuadExt>>| {
                    krasauskas::biquadratic_factors_of(l, radicand)
                };
                build_best_exact(
                    &se,
                    &[g1.clone(), g2.clone()],
                    options.axis,
                    options.method,
                    &mid,
                    &krasauskas::FnFactors(&factors),
                )
                .map(|mut s| {
                    s.reparametrized = reparam.clone();
                    s.domain = options.domain.clone();
                    CanalBuild::Extension {
                        radicand: radicand.clone(),
                        surface: s,
                    }
                })
            }
        };
        match built {
            Ok(b) => {
                let better = match &best {
                    None => true,
                    Some(old) => {
                        let (a, c) = (b.degree(), old.degree());
                        (a.0 + a.1, a) < (c.0 + c.1, c)
                    }
                };
                if better {
                    best = Some(b);
                }
            }
            Err(e) => last_err = Some(e),
        }
    }
    best.ok_or_else(|| {
        last_err.unwrap_or_else(|| CanalError::DegenerateSpine("no construction".into()))
    })
}

/// The canal surface in `f64` from exact data: orientation, reality check, domain
/// reparametrization, `D` and its square-free decomposition are exact; only the roots of the
/// square-free odd part of `D` are approximated ([`sum_of_two_squares_approx`]); the
/// parametrization is built in `f64` and its certificates are tolerance checks. For data
/// whose exact split needs more than one quadratic field.
///
/// # Errors
/// As [`canal_surface`] (without [`CanalError::NeedsLargerExtension`]).
pub fn canal_surface_approx(
    spine: &CanalSpine<Rational>,
    options: &CanalOptions,
) -> Result<CanalSurface<f64>, CanalError> {
    let (spine, reparam) = oriented_on_domain(spine, options, &krasauskas::FactorMemo::default())?;
    let d = spine.discriminant()?;
    let (g1, g2) = sum_of_two_squares_approx(&d)?;
    // the f64 numerators are not divided by their content: scale the split accordingly
    let content = {
        let wd = spine.weight().derivative();
        let x = [
            &spine.center_polys()[0],
            &spine.center_polys()[1],
            &spine.center_polys()[2],
            spine.radius_poly(),
        ];
        let p: Vec<Poly<Rational>> = x
            .iter()
            .map(|xi| &(spine.weight() * &xi.derivative()) - &(&wd * *xi))
            .collect();
        p.iter()
            .fold(Poly::zero(), |acc: Poly<Rational>, q| acc.gcd(q))
    };
    let cf = content.map(Scalar::to_f64);
    let sf = spine.map_scalar(Scalar::to_f64);
    let opts = CanalOptions {
        orientation: Orientation::Positive,
        ..options.clone()
    };
    let mut s = canal_surface_with_split(&sf, &(&g1 * &cf), &(&g2 * &cf), &opts)?;
    s.reparametrized = reparam;
    s.domain = options.domain.clone();
    Ok(s)
}

/// The canal surface of an `f64` family: its coefficients are exact binary rationals, so
/// this is [`canal_surface_approx`] of the exactly converted family.
///
/// # Errors
/// As [`canal_surface_approx`]; [`CanalError::InvalidArgument`] for non-finite input.
pub fn canal_surface_f64(
    spine: &CanalSpine<f64>,
    options: &CanalOptions,
) -> Result<CanalSurface<f64>, CanalError> {
    let conv = |p: &Poly<f64>| -> Result<Poly<Rational>, CanalError> {
        Ok(Poly::new(
            p.coeffs()
                .iter()
                .map(|x| {
                    Scalar::to_rational(x).ok_or_else(|| {
                        CanalError::InvalidArgument("non-finite coefficient in the family".into())
                    })
                })
                .collect::<Result<Vec<_>, _>>()?,
        ))
    };
    let [w, m0, m1, m2, r] = spine.homogeneous();
    let exact = CanalSpine::new(conv(&w)?, [conv(&m0)?, conv(&m1)?, conv(&m2)?], conv(&r)?)?;
    canal_surface_approx(&exact, options)
}

impl<F: Scalar> CanalSurface<F> {
    /// The homogeneous coordinates `(X₀, X₁, X₂, X₃)` as polynomials in `(t, u)`.
    pub fn homogeneous(&self) -> &[BiPoly<F>; 4] {
        &self.x
    }

    /// The family actually enveloped (after orientation and reparametrization).
    pub fn spine(&self) -> &CanalSpine<F> {
        &self.spine
    }

    /// The split `(g₁, g₂)` of `D` used.
    pub fn split(&self) -> (&Poly<F>, &Poly<F>) {
        (&self.split[0], &self.split[1])
    }

    /// The construction that produced the parametrization.
    pub fn construction(&self) -> Construction {
        self.construction
    }

    /// The stereographic axis used.
    pub fn axis(&self) -> AxisChoice {
        self.axis
    }

    /// `Some((a, b))` if the family was reparametrized by `t = (a + b s²)/(1 + s²)` (the
    /// surface parameter is then `s`).
    pub fn reparametrization(&self) -> Option<&(Rational, Rational)> {
        self.reparametrized.as_ref()
    }

    /// The bidegree `(deg_t, deg_u)`.
    pub fn degree(&self) -> (usize, usize) {
        bidegree(&self.x)
    }

    /// The homogeneous point `X(t, u)`.
    pub fn eval_homogeneous(&self, t: &F, u: &F) -> [F; 4] {
        core::array::from_fn(|k| self.x[k].eval(t, u))
    }

    /// The point `x(t, u)`.
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] where `X₀ = 0`.
    pub fn eval(&self, t: &F, u: &F) -> Result<[F; 3], CanalError> {
        let h = self.eval_homogeneous(t, u);
        let inv = h[0].inv().ok_or_else(|| {
            CanalError::InvalidArgument(format!(
                "X₀({}, {}) = 0: the point is at infinity",
                format_scalar(t),
                format_scalar(u)
            ))
        })?;
        Ok([
            h[1].clone() * inv.clone(),
            h[2].clone() * inv.clone(),
            h[3].clone() * inv,
        ])
    }

    /// The point of the characteristic circle at `t` for `u = ∞`.
    pub fn eval_at_u_infinity(&self, t: &F) -> [F; 4] {
        let n = self.degree().1;
        core::array::from_fn(|k| self.x[k].coeffs().get(n).map_or(F::zero(), |p| p.eval(t)))
    }

    /// The characteristic circle at `t` (centre, plane normal, radius²).
    ///
    /// # Errors
    /// [`CanalError::DegenerateSpine`] where `W(t) = 0` or `ṁ(t) = 0`.
    pub fn characteristic_circle(&self, t: &F) -> Result<CharacteristicCircle<F>, CanalError> {
        let (m, r) = self.spine.eval(t)?;
        let p: [F; 4] = core::array::from_fn(|k| self.numerators[k].eval(t));
        let pm = [p[0].clone(), p[1].clone(), p[2].clone()];
        let nn = crate::lines::dot(&pm, &pm);
        let inv = nn
            .inv()
            .ok_or_else(|| CanalError::DegenerateSpine(format!("ṁ({}) = 0", format_scalar(t))))?;
        let k = r.clone() * p[3].clone() * inv.clone();
        let d = nn.clone() - p[3].clone() * p[3].clone();
        Ok(CharacteristicCircle {
            center: core::array::from_fn(|i| m[i].clone() - k.clone() * pm[i].clone()),
            normal: pm,
            radius_sq: r.clone() * r * d * inv,
        })
    }

    /// The characteristic circle at `t` as homogeneous polynomials in `u` (degree ≤ 2).
    pub fn circle_polys(&self, t: &F) -> [Poly<F>; 4] {
        core::array::from_fn(|k| self.x[k].at_t(t))
    }

    /// The Bézier patch on `[t₀, t₁] × [u₀, u₁]`.
    ///
    /// # Errors
    /// Only a geometry failure underneath.
    pub fn patch(&self, t: (&F, &F), u: (&F, &F)) -> Result<BezierPatch<F>, CanalError> {
        Ok(patch_of(&self.x, t, u)?)
    }

    /// Two patches over `[t₀, t₁]` covering the whole characteristic circles: `u ∈ [−1, 1]`
    /// and, in the chart `u = 1/v`, `v ∈ [−1, 1]`.
    ///
    /// # Errors
    /// Only a geometry failure underneath.
    pub fn full_patches(&self, t: (&F, &F)) -> Result<[BezierPatch<F>; 2], CanalError> {
        let one = F::one();
        let m1 = -F::one();
        let n = self.degree().1;
        let rev: Vec<BiPoly<F>> = self.x.iter().map(|b| b.reverse_u(n)).collect();
        Ok([
            patch_of(&self.x, t, (&m1, &one))?,
            patch_of(&rev, t, (&m1, &one))?,
        ])
    }

    /// The scalar type converted.
    pub fn map_scalar<G: Scalar>(&self, f: impl Fn(&F) -> G + Copy) -> CanalSurface<G> {
        CanalSurface {
            spine: self.spine.map_scalar(f),
            numerators: core::array::from_fn(|k| self.numerators[k].map(f)),
            split: [self.split[0].map(f), self.split[1].map(f)],
            axis: self.axis,
            x: core::array::from_fn(|k| self.x[k].map_scalar(f)),
            reparametrized: self.reparametrized.clone(),
            domain: self.domain.clone(),
            construction: self.construction,
            normals: BuiltNormals(None),
        }
    }

    /// The surface mapped by the orthogonal matrix `q` (`x ↦ q x`), re-attached to `spine`,
    /// which must be the family of `self` mapped by the same `q` (for example the surface
    /// built in a rotated or reflected frame, mapped back to the user's frame; the canal
    /// identities and the split `g₁² + g₂² = D` are invariant under orthogonal maps). The
    /// reported [`Self::axis`] stays the one of the construction frame.
    ///
    /// # Errors
    /// As [`CanalSpine::derivative_numerators`] of `spine`.
    pub fn transformed(
        &self,
        q: &[[F; 3]; 3],
        spine: &CanalSpine<F>,
    ) -> Result<CanalSurface<F>, CanalError> {
        let mut x = self.x.clone();
        for (i, row) in q.iter().enumerate() {
            x[i + 1] = (0..3).fold(BiPoly::zero(), |acc, j| {
                acc.add(&self.x[j + 1].scale(&row[j]))
            });
        }
        Ok(CanalSurface {
            spine: spine.clone(),
            numerators: spine.derivative_numerators()?,
            split: self.split.clone(),
            axis: self.axis,
            x,
            reparametrized: self.reparametrized.clone(),
            domain: self.domain.clone(),
            construction: self.construction,
            normals: BuiltNormals(None),
        })
    }

    /// The surface the same construction gives in the opposite frame `(j, −σ)` of this
    /// surface's frame `(j, σ)`, derived from the normal it was built from, for a family
    /// with `ṙ ≡ 0` (a pipe: `P₄ ≡ 0`); `None` when this surface does not carry its normal
    /// or `P₄ ≢ 0`.
    ///
    /// With `P₄ ≡ 0` the pole polynomial of the opposite frame is `α' = P₄ − σPⱼ = −α` and
    /// `P_a`, `P_b` (hence `β`) are the same. Peternell–Pottmann ((2.13)–(2.17), [`build`]):
    /// `k₀ ↦ −k₀`, `k₁`, `k₂` unchanged, so `q₀` and `q_j` are unchanged and `q_a`, `q_b`
    /// change sign; placed with the sign `−σ` on axis `j`, the normal is `(q₀, −q)`.
    /// Krasauskas ([`super::krasauskas`]): the first pencil of `−α` is `Δ(a, b)` with
    /// `Δ = diag(1, −1)`, and every step of the reduction is `Δ`-equivariant (the leading
    /// coefficients, the monic `gcd`s and contents, `det(Δa, Δb) = −det(a, b)` has the same
    /// monic factors, the linear system of step 3 has the rows of its second entry negated
    /// together with their right-hand sides, so the same reduced echelon form and the same
    /// `ρ`; the balancing uses `|a|²` and `Re⟨a, b⟩` only), so the reduced pencil is `Δ`
    /// of this one; `f_s(U₀, −U₁)` negates the middle two components of (2.29), which,
    /// placed with `−σ`, again gives `(q₀, −q)`. Either way the surface of the opposite frame
    /// is the envelope of `(q₀, −q)` with its common factors removed, the construction
    /// record unchanged.
    ///
    /// # Errors
    /// As the removal of common factors ([`envelope_from_normals`]).
    pub(crate) fn mirrored(&self) -> Option<Result<Self, CanalError>> {
        let normals = self.normals.0.as_ref()?;
        if !self.numerators[3].is_zero() {
            return None;
        }
        let [q0, q1, q2, q3] = &**normals;
        let axis = AxisChoice {
            axis: self.axis.axis,
            positive: !self.axis.positive,
        };
        Some(
            CanalSurface::from_normals(
                &self.spine,
                &self.numerators,
                &self.split,
                axis,
                [q0.clone(), q1.neg(), q2.neg(), q3.neg()],
                self.construction,
            )
            .map(|mut s| {
                s.reparametrized = self.reparametrized.clone();
                s.domain = self.domain.clone();
                s
            }),
        )
    }

    /// The same family and split with the homogeneous coordinates `x` instead: a
    /// reparametrization of this surface (the seam of a closed pipe,
    /// [`super::seam`]); [`Certified::certify`] decides the canal identities for `x`.
    pub(crate) fn with_homogeneous(&self, x: [BiPoly<F>; 4]) -> Self {
        CanalSurface {
            x,
            normals: BuiltNormals(None),
            ..self.clone()
        }
    }

    /// The parameter domain `[a, b]` requested at construction (`None`: all of `R`).
    pub fn domain(&self) -> Option<&(Rational, Rational)> {
        self.domain.as_ref()
    }

    /// The same surface restricted to the domain `[a, b]` (a surface built on all of `R`,
    /// not reparametrized).
    pub(crate) fn on_domain(mut self, a: &Rational, b: &Rational) -> Self {
        self.domain = Some((a.clone(), b.clone()));
        self
    }

    /// The characteristic circle at an end of the domain (`0`: `t = a`, `1`: `t = b`) as
    /// homogeneous polynomials in `u`; for a reparametrized family `t = a ↔ s = 0` and
    /// `t = b ↔ s = ∞` (the leading coefficients in `s`).
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] without a domain.
    pub fn end_circle(&self, end: usize) -> Result<[Poly<F>; 4], CanalError> {
        let (a, b) = self.domain.clone().ok_or_else(|| {
            CanalError::InvalidArgument("the surface has no parameter domain".into())
        })?;
        if self.reparametrized.is_some() {
            if end == 0 {
                return Ok(self.circle_polys(&F::zero()));
            }
            let n = self.degree().0;
            return Ok(core::array::from_fn(|k| {
                Poly::new(self.x[k].coeffs().iter().map(|p| p.coeff(n)).collect())
            }));
        }
        let t = if end == 0 { a } else { b };
        Ok(self.circle_polys(&F::from_rational(&t)))
    }

    /// Bézier patches covering the parameter domain and the whole characteristic circles:
    /// `[a, b] × (u ∈ [−1, 1], chart u = 1/v)` (2 patches), or for a reparametrized family
    /// `s ∈ [0, 1]` and the chart `s = 1/σ`, `σ ∈ [0, 1]` (4 patches, `t = a … b`).
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] without a domain; geometry failures.
    pub fn domain_patches(&self) -> Result<Vec<BezierPatch<F>>, CanalError> {
        self.domain_patches_by(&self.charts(&self.x), &|_, ch, t, u| patch_of(ch, t, u))
    }

    /// The weights of [`Self::domain_patches`] in `f64`: the same patches (same charts,
    /// same bidegree, the weight computed by the same `f64` operations as in the patches of
    /// `self.map_scalar(Scalar::to_f64)`), each as a patch of dimension 1 whose second
    /// coordinate is `0` — all the candidate search needs to estimate the size of an export
    /// (its positive-weight split looks at the weights only).
    ///
    /// # Errors
    /// As [`Self::domain_patches`].
    pub(crate) fn domain_weight_patches_f64(&self) -> Result<Vec<BezierPatch<f64>>, CanalError> {
        // the weight's charts only (the same coefficients as the weight row of the charts of
        // the whole surface in f64), with the bidegrees of the whole charts
        let w = self.x[0].map_scalar(Scalar::to_f64);
        let degrees = self.chart_bidegrees();
        self.domain_patches_by(&self.charts(&[w]), &|k, ch: &[BiPoly<f64>], t, u| {
            // the bidegree of the whole chart, as `patch_of`
            let (m, n) = degrees
                .get(k)
                .copied()
                .ok_or_else(|| rcagd_geom::GeomError::Dimension("no chart".into()))?;
            let w = ch
                .first()
                .ok_or_else(|| rcagd_geom::GeomError::Dimension("no weight".into()))?
                .bernstein_on(t, u, m, n)?;
            let coords: Vec<f64> = w.into_iter().flat_map(|x| [x, 0.0]).collect();
            BezierPatch::from_flat(1, m, n, coords)
        })
    }

    /// The patches of [`Self::domain_patches`] from the charts ([`Self::charts`] of `self.x`,
    /// or of a part or conversion of it), chart `k` made into a patch by `patch(k, …)`.
    fn domain_patches_by<G: Scalar>(
        &self,
        charts: &[Vec<BiPoly<G>>],
        patch: &ChartPatch<'_, G>,
    ) -> Result<Vec<BezierPatch<G>>, CanalError> {
        let (a, b) = self.domain.clone().ok_or_else(|| {
            CanalError::InvalidArgument("the surface has no parameter domain".into())
        })?;
        let (zero, one, m1) = (G::zero(), G::one(), -G::one());
        // Krasauskas builds: u ∈ [−1, 0] and [0, 1] per chart (the weight |a + u b|² is
        // balanced at u = 0, see `krasauskas::Pencil::balance_at`)
        let u_ranges: Vec<(&G, &G)> = match self.construction {
            Construction::Krasauskas { .. } => vec![(&m1, &zero), (&zero, &one)],
            Construction::PeternellPottmann => vec![(&m1, &one)],
        };
        let t_range = if self.reparametrized.is_some() {
            (zero.clone(), one.clone())
        } else {
            (G::from_rational(&a), G::from_rational(&b))
        };
        let mut out = Vec::new();
        for (k, ch) in charts.iter().enumerate() {
            for u in &u_ranges {
                out.push(patch(k, ch, (&t_range.0, &t_range.1), *u)?);
            }
        }
        Ok(out)
    }

    /// The charts of [`Self::domain_patches_by`] from the homogeneous coordinates `x`: `x`
    /// and `x` with `u ↦ 1/u`, and for a reparametrized surface (`t ∈ [0, 1]` then stands for
    /// half of the domain) both again with `t ↦ 1/t`.
    pub(super) fn charts<G: Scalar>(&self, x: &[BiPoly<G>]) -> Vec<Vec<BiPoly<G>>> {
        let (nt, nu) = self.degree();
        let with_reversed_u = |x: Vec<BiPoly<G>>| -> [Vec<BiPoly<G>>; 2] {
            let r = x.iter().map(|c| c.reverse_u(nu)).collect();
            [x, r]
        };
        if self.reparametrized.is_some() {
            let rev: Vec<BiPoly<G>> = x
                .iter()
                .map(|c| c.transpose().reverse_u(nt).transpose())
                .collect();
            let [c0, c1] = with_reversed_u(x.to_vec());
            let [c2, c3] = with_reversed_u(rev);
            vec![c0, c1, c2, c3]
        } else {
            with_reversed_u(x.to_vec()).into()
        }
    }

    /// The bidegrees of [`Self::charts`] of `self.x`, from the supports of the coordinates
    /// (`u ↦ 1/u` turns `deg_u` into `n_u − ` the least power of `u`, `t ↦ 1/t` likewise in
    /// `t`), without building the charts.
    pub(crate) fn chart_bidegrees(&self) -> Vec<(usize, usize)> {
        let (nt, nu) = self.degree();
        let of = |rev_t: bool, rev_u: bool| -> (usize, usize) {
            let degs = self.x.iter().filter_map(|c| {
                let dt = if rev_t {
                    nt - c.low_degree_t()?
                } else {
                    c.degree_t()?
                };
                let du = if rev_u {
                    nu - c.low_degree_u()?
                } else {
                    c.degree_u()?
                };
                Some((dt, du))
            });
            degs.fold((0, 0), |(a, b), (dt, du)| (a.max(dt), b.max(du)))
        };
        if self.reparametrized.is_some() {
            vec![
                of(false, false),
                of(false, true),
                of(true, false),
                of(true, true),
            ]
        } else {
            vec![of(false, false), of(false, true)]
        }
    }

    /// Everything [`Self::domain_weight_patches_f64`] reads: the weight `x₀`, the bidegree
    /// of every chart ([`Self::charts`], in order), the kind of construction (its `u`
    /// ranges), the reparametrization and the domain. Two surfaces with equal keys have the
    /// same weight patches, hence the same export estimate — the candidate search computes
    /// it once per key (a mirrored frame's candidate has the weight of the one it was
    /// derived from, [`Self::mirrored`]).
    pub(crate) fn weight_patch_key(&self) -> WeightPatchKey<F> {
        WeightPatchKey {
            weight: self.x[0].clone(),
            charts: self.chart_bidegrees(),
            krasauskas: matches!(self.construction, Construction::Krasauskas { .. }),
            reparametrized: self.reparametrized.clone(),
            domain: self.domain.clone(),
        }
    }
}

/// The data of [`CanalSurface::domain_weight_patches_f64`] ([`CanalSurface::weight_patch_key`]).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct WeightPatchKey<F> {
    weight: BiPoly<F>,
    charts: Vec<(usize, usize)>,
    krasauskas: bool,
    reparametrized: Option<(Rational, Rational)>,
    domain: Option<(Rational, Rational)>,
}

/// The patch of one chart's homogeneous coordinates on `[t₀, t₁] × [u₀, u₁]`
/// ([`patch_of`], or the weight alone).
type ChartPatch<'a, G> = dyn Fn(usize, &[BiPoly<G>], (&G, &G), (&G, &G)) -> Result<BezierPatch<G>, rcagd_geom::GeomError>
    + 'a;

fn bi_cert<F: Scalar>(property: &str, b: &BiPoly<F>, scale: f64) -> Certificate {
    polynomial_is_zero_scaled(property, &b.all_coeffs(), scale)
}

/// The canal-surface identities of homogeneous coordinates `x` with respect to the family
/// `spine` (derivative numerators `p`), as polynomial identities in `(t, u)`: sphere
/// `|x − m|² ≡ r²`, contact `(x − m)·ṁ + r ṙ ≡ 0`, normality `⟨x − m, x_u⟩ ≡ 0` and
/// `⟨x − m, x_t⟩ ≡ 0`.
pub(crate) fn canal_certificates<F: Scalar>(
    spine: &CanalSpine<F>,
    p: &[Poly<F>; 4],
    x: &[BiPoly<F>; 4],
) -> Vec<Certificate> {
    let mut out = Vec::new();
    let w = spine.weight();
    let m = spine.center_polys();
    let dx: [BiPoly<F>; 3] = core::array::from_fn(|i| x[i + 1].mul_t(w).sub(&x[0].mul_t(&m[i])));
    let x0 = &x[0];
    let r = spine.radius_poly();
    let sx = x.iter().map(bi_scale).fold(0.0, f64::max);
    let ss = spine
        .homogeneous()
        .iter()
        .map(poly_scale)
        .fold(0.0, f64::max);
    let sd = sx * ss * 4.0;
    let sphere = dx
        .iter()
        .fold(BiPoly::zero(), |acc, d| acc.add(&d.mul(d)))
        .sub(&x0.mul_t(r).mul(&x0.mul_t(r)));
    out.push(bi_cert(
        "|x − m|² − r² ≡ 0 (x(t,u) lies on the sphere K(t), Gruber (2.1))",
        &sphere,
        sd * sd,
    ));
    let sp = p.iter().map(poly_scale).fold(0.0, f64::max);
    let contact = (0..3)
        .fold(BiPoly::zero(), |acc, i| acc.add(&dx[i].mul_t(&p[i])))
        .add(&x0.mul_t(&(r * &p[3])));
    out.push(bi_cert(
        "(x − m)·ṁ + r ṙ ≡ 0 (contact condition K̇(t), Gruber (2.2), sign corrected)",
        &contact,
        sd * sp * 4.0,
    ));
    for (name, dir) in [("u", 0), ("t", 1)] {
        let xd: Vec<BiPoly<F>> = x
            .iter()
            .map(|b| {
                if dir == 0 {
                    b.partial_u()
                } else {
                    b.partial_t()
                }
            })
            .collect();
        let tangent: Vec<BiPoly<F>> = (1..4)
            .map(|i| xd[i].mul(x0).sub(&x[i].mul(&xd[0])))
            .collect();
        let ortho = (0..3).fold(BiPoly::zero(), |acc, i| acc.add(&dx[i].mul(&tangent[i])));
        out.push(bi_cert(
            &format!("⟨x − m, x_{name}⟩ ≡ 0 (the surface normal passes through the spine point)"),
            &ortho,
            sd * sx * sx * 64.0,
        ));
    }
    out
}

impl<F: Scalar> Certified for CanalSurface<F> {
    /// The canal-surface identities as polynomial identities in `(t, u)` (module docs):
    /// sphere `|x − m|² ≡ r²`, contact `(x − m)·ṁ + r ṙ ≡ 0`, normality `⟨x − m, x_u⟩ ≡ 0`
    /// and `⟨x − m, x_t⟩ ≡ 0`, and the split `g₁² + g₂² ≡ D`.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = canal_certificates(&self.spine, &self.numerators, &self.x);
        match self.spine.discriminant() {
            Ok(d) => {
                let s = &(&sq(&self.split[0]) + &sq(&self.split[1])) - &d;
                let n = (d.degree().unwrap_or(0) + 1) as f64;
                let scale = poly_scale(&d)
                    .max(poly_scale(&self.split[0]).powi(2))
                    .max(poly_scale(&self.split[1]).powi(2))
                    .max(1.0)
                    * n;
                out.push(polynomial_is_zero_scaled(
                    "g₁² + g₂² ≡ D = P₁² + P₂² + P₃² − P₄² (sum of two squares)",
                    s.coeffs(),
                    scale,
                ));
            }
            Err(e) => out.push(Certificate::fails("g₁² + g₂² ≡ D", e.to_string(), F::EXACT)),
        }
        out
    }
}

/// The Krasauskas degree bound of Gruber Satz 2 (2.37) for a family `γ = (m, r)` of degree
/// `k`: `(k + n, 2)` with `n = 2·max(k − 1, 2k − 2 − Σ⌈pᵢ/2⌉)`, the `pᵢ` the multiplicities of
/// the complex-conjugate root pairs of `D` (2.35). docs/math/lines-and-canal.md, Errata G9: valid for rational `γ`;
/// for polynomial data the construction can be lower.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KrasauskasBound {
    /// The degree `k` of `γ`.
    pub k: usize,
    /// The multiplicities `pᵢ` of the conjugate root pairs of `D`.
    pub pair_multiplicities: Vec<usize>,
    /// `n` of (2.37).
    pub n: usize,
    /// The bound `(k + n, 2)`.
    pub bidegree: (usize, usize),
}

/// [`KrasauskasBound`] of a rational family.
///
/// # Errors
/// As [`CanalSpine::discriminant`].
pub fn krasauskas_bound(spine: &CanalSpine<Rational>) -> Result<KrasauskasBound, CanalError> {
    let d = spine.discriminant()?;
    let k = spine.degree();
    let mut pairs = Vec::new();
    for (f, mult) in square_free_decomposition(&d) {
        let real = isolate_real_roots(&f)?.len();
        let deg = f.degree().unwrap_or(0);
        for _ in 0..(deg.saturating_sub(real) / 2) {
            pairs.push(mult);
        }
    }
    let sum: usize = pairs.iter().map(|p| p.div_ceil(2)).sum();
    let n = 2 * (k.saturating_sub(1)).max((2 * k).saturating_sub(2).saturating_sub(sum));
    Ok(KrasauskasBound {
        k,
        pair_multiplicities: pairs,
        n,
        bidegree: (k + n, 2),
    })
}

// ----------------------------------------------------------------------------------------
// quadratic families: the cyclographic construction (Gruber §2.3)
// ----------------------------------------------------------------------------------------

/// The envelope of a quadratic family `k(p) = k₀ + k₁p + k₂p²` in `R^{3,1}` by the
/// cyclographic map (module docs, docs/math/lines-and-canal.md, "Canal surfaces"): a rational parametrization `Γ(s, t)` over the
/// scalar field of `k` (no square root), covering the whole envelope as `(s, t)` ranges
/// over `R²` (plus the point at infinity of the isotropic directions).
#[derive(Debug, Clone, PartialEq)]
pub struct QuadraticCanal<F> {
    k: [Poly<F>; 4],
    /// `p(s, t) = N/Dn`.
    num: BiPoly<F>,
    den: BiPoly<F>,
    x: [BiPoly<F>; 4],
}

/// `w(s, t)` as bivariate polynomials (first variable `s`, second `t`).
fn omega_bi<F: Scalar>() -> [BiPoly<F>; 4] {
    let one = F::one();
    let two = F::from_i64(2);
    let s2 = Poly::new(vec![F::zero(), F::zero(), one.clone()]);
    [
        BiPoly::from_t(Poly::new(vec![F::zero(), two.clone()])),
        BiPoly::new(vec![Poly::zero(), Poly::constant(two)]),
        BiPoly::new(vec![
            &Poly::constant(one.clone()) - &s2,
            Poly::zero(),
            Poly::constant(-one.clone()),
        ]),
        BiPoly::new(vec![
            &Poly::constant(one.clone()) + &s2,
            Poly::zero(),
            Poly::constant(one),
        ]),
    ]
}

fn pe_bi<F: Scalar>(w: &[BiPoly<F>; 4], v: &[F; 4]) -> BiPoly<F> {
    w[0].scale(&v[0])
        .add(&w[1].scale(&v[1]))
        .add(&w[2].scale(&v[2]))
        .sub(&w[3].scale(&v[3]))
}

impl<F: Scalar> QuadraticCanal<F> {
    /// From the polynomial family `k(p) = (m₁, m₂, m₃, r)(p)` of degree ≤ 2.
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] for degree > 2; [`CanalError::DegenerateSpine`] if
    /// `k̇ ≡ const` is isotropic or zero, or `⟨w, b⟩ ≡ 0`.
    pub fn new(k: [Poly<F>; 4]) -> Result<Self, CanalError> {
        if k.iter().any(|p| p.degree().is_some_and(|d| d > 2)) {
            return Err(CanalError::InvalidArgument(
                "the cyclographic construction of Gruber §2.3 needs a family of degree ≤ 2".into(),
            ));
        }
        let a: [F; 4] = core::array::from_fn(|i| k[i].coeff(1));
        let b: [F; 4] = core::array::from_fn(|i| F::from_i64(2) * k[i].coeff(2));
        let w = omega_bi::<F>();
        let num = pe_bi(&w, &a).neg();
        let den = pe_bi(&w, &b);
        if den.is_zero() {
            return Err(CanalError::DegenerateSpine(
                "k̈ = 0 (a line of R^{3,1}): the envelope is a cone or cylinder of revolution, the parameter p is not a function of the isotropic direction".into(),
            ));
        }
        // K_i homogenized in (N, Dn): k_i0 Dn² + k_i1 N Dn + k_i2 N²
        let (nn, nd, dd) = (num.mul(&num), num.mul(&den), den.mul(&den));
        let kh: [BiPoly<F>; 4] = core::array::from_fn(|i| {
            dd.scale(&k[i].coeff(0))
                .add(&nd.scale(&k[i].coeff(1)))
                .add(&nn.scale(&k[i].coeff(2)))
        });
        let x = [
            dd.mul(&w[3]),
            kh[0].mul(&w[3]).sub(&kh[3].mul(&w[0])),
            kh[1].mul(&w[3]).sub(&kh[3].mul(&w[1])),
            kh[2].mul(&w[3]).sub(&kh[3].mul(&w[2])),
        ];
        Ok(QuadraticCanal { k, num, den, x })
    }

    /// From a spine of degree ≤ 2 with constant weight.
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] for a non-constant weight; as [`Self::new`].
    pub fn from_spine(spine: &CanalSpine<F>) -> Result<Self, CanalError> {
        let w = spine.weight();
        if w.degree() != Some(0) {
            return Err(CanalError::InvalidArgument(
                "the cyclographic construction needs a polynomial family (constant weight)".into(),
            ));
        }
        let inv = w
            .coeff(0)
            .inv()
            .ok_or_else(|| CanalError::DegenerateSpine("zero weight".into()))?;
        let m = spine.center_polys();
        Self::new([
            m[0].scale(&inv),
            m[1].scale(&inv),
            m[2].scale(&inv),
            spine.radius_poly().scale(&inv),
        ])
    }

    /// The homogeneous coordinates `(X₀, X₁, X₂, X₃)` of `Γ(s, t)` (first variable `s`).
    pub fn homogeneous(&self) -> &[BiPoly<F>; 4] {
        &self.x
    }

    /// The reparametrization `p(s, t) = N/Dn` (Gruber (2.21)).
    pub fn parameter(&self) -> (&BiPoly<F>, &BiPoly<F>) {
        (&self.num, &self.den)
    }

    /// `(deg_s, deg_t)`.
    pub fn degree(&self) -> (usize, usize) {
        bidegree(&self.x)
    }

    /// The point `Γ(s, t)`.
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] where `X₀ = 0`.
    pub fn eval(&self, s: &F, t: &F) -> Result<[F; 3], CanalError> {
        let h: [F; 4] = core::array::from_fn(|k| self.x[k].eval(s, t));
        let inv = h[0].inv().ok_or_else(|| {
            CanalError::InvalidArgument(format!(
                "X₀({}, {}) = 0",
                format_scalar(s),
                format_scalar(t)
            ))
        })?;
        Ok(core::array::from_fn(|i| h[i + 1].clone() * inv.clone()))
    }

    /// The Bézier patch on `[s₀, s₁] × [t₀, t₁]`.
    ///
    /// # Errors
    /// Only a geometry failure underneath.
    pub fn patch(&self, s: (&F, &F), t: (&F, &F)) -> Result<BezierPatch<F>, CanalError> {
        Ok(patch_of(&self.x, s, t)?)
    }
}

impl<F: Scalar> Certified for QuadraticCanal<F> {
    /// `|Γ − m(p)|² ≡ r(p)²` and `(Γ − m(p))·ṁ(p) + r(p)ṙ(p) ≡ 0` as polynomial identities
    /// in `(s, t)` with `p = N/Dn` substituted homogeneously, and `⟨w, k̇(p)⟩_pe ≡ 0`.
    fn certify(&self) -> Vec<Certificate> {
        let (nn, nd, dd) = (
            self.num.mul(&self.num),
            self.num.mul(&self.den),
            self.den.mul(&self.den),
        );
        let kh: Vec<BiPoly<F>> = (0..4)
            .map(|i| {
                dd.scale(&self.k[i].coeff(0))
                    .add(&nd.scale(&self.k[i].coeff(1)))
                    .add(&nn.scale(&self.k[i].coeff(2)))
            })
            .collect();
        // k̇(p)·Dn = a Dn + b N
        let kd: Vec<BiPoly<F>> = (0..4)
            .map(|i| {
                self.den
                    .scale(&self.k[i].coeff(1))
                    .add(&self.num.scale(&(F::from_i64(2) * self.k[i].coeff(2))))
            })
            .collect();
        let x0 = &self.x[0];
        let dx: Vec<BiPoly<F>> = (0..3)
            .map(|i| self.x[i + 1].mul(&dd).sub(&kh[i].mul(x0)))
            .collect();
        let sc = self.x.iter().map(bi_scale).fold(1.0, f64::max)
            * kh.iter().map(bi_scale).fold(1.0, f64::max);
        let sphere = dx
            .iter()
            .fold(BiPoly::zero(), |acc, d| acc.add(&d.mul(d)))
            .sub(&kh[3].mul(x0).mul(&kh[3].mul(x0)));
        let contact = (0..3)
            .fold(BiPoly::zero(), |acc, i| acc.add(&dx[i].mul(&kd[i])))
            .add(&kh[3].mul(x0).mul(&kd[3]));
        let w = omega_bi::<F>();
        let iso = w[0]
            .mul(&kd[0])
            .add(&w[1].mul(&kd[1]))
            .add(&w[2].mul(&kd[2]))
            .sub(&w[3].mul(&kd[3]));
        vec![
            bi_cert(
                "|Γ − m(p)|² − r(p)² ≡ 0 (Gruber §2.3, p = N/Dn)",
                &sphere,
                sc * sc * 16.0,
            ),
            bi_cert(
                "(Γ − m(p))·ṁ(p) + r(p)ṙ(p) ≡ 0 (contact, Gruber (2.2), sign corrected)",
                &contact,
                sc * sc * 16.0,
            ),
            bi_cert(
                "⟨w(s,t), k̇(p(s,t))⟩_pe ≡ 0 (the isotropic direction is orthogonal to the tangent, (2.20)/(2.21))",
                &iso,
                sc,
            ),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(c: &[i64]) -> Poly<Rational> {
        Poly::from_ints(c)
    }
    fn q(n: i64, d: i64) -> Rational {
        Rational::from_ratio(n, d)
    }

    #[test]
    fn notes_counterexample_degree() {
        // m = (t, t²/2, 0), r = t: D = t², split (t, 0): bidegree (4, 2) < Krasauskas (6, 2)
        let spine = CanalSpine::polynomial(
            [
                p(&[0, 1]),
                Poly::new(vec![q(0, 1), q(0, 1), q(1, 2)]),
                p(&[]),
            ],
            p(&[0, 1]),
        );
        let b = canal_surface(&spine, &CanalOptions::default()).expect("build");
        let s = b.as_rational().expect("rational");
        assert!(b.all_hold(), "{:?}", b.certify());
        assert_eq!(s.degree(), (4, 2));
        let k = krasauskas_bound(&spine).expect("bound");
        assert_eq!(k.bidegree, (6, 2));
    }

    #[test]
    fn cone_of_revolution() {
        // m = (0, 0, t), r = t/2: D = 1 − 1/4 = 3/4 → needs Q(√3)
        let spine = CanalSpine::polynomial(
            [p(&[]), p(&[]), p(&[0, 1])],
            Poly::new(vec![q(0, 1), q(1, 2)]),
        );
        let b = canal_surface(&spine, &CanalOptions::default()).expect("build");
        assert_eq!(b.radicand(), Some(&Rational::from(3)));
        assert!(b.all_hold(), "{:?}", b.certify());
    }
}
