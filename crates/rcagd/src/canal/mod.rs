//! Rational canal and pipe surfaces: envelopes of one-parameter families of spheres with a
//! rational spine `m(t)` and a rational radius `r(t)` (Gruber ch. 2; Peternell §2.5, §4.5;
//! docs/math/lines-and-canal.md, "Canal surfaces").
//!
//! The sphere family `K(t): |x − m|² − r² = 0` envelops the canal surface `Γ = K ∩ K̇` with
//! `K̇: (x − m)·ṁ + r ṙ = 0` (Gruber (2.2), sign corrected: docs/math/lines-and-canal.md, Errata G3); the
//! characteristic circles are real iff `D = |ṁ|² − ṙ² ≥ 0` (2.8)/(2.18).
//!
//! Map of the module:
//!
//! * [`CanalSpine`]: the curve `k(t) = (m(t), r(t))` of the cyclographic model as
//!   homogeneous polynomials `(W, M₁, M₂, M₃, R)`, `m = M/W`, `r = R/W`; the derivative
//!   numerators `P = W X' − W' X` (content removed, docs/math/lines-and-canal.md, Errata G8), the discriminant
//!   `D = P₁² + P₂² + P₃² − P₄²`, and the reality check that names the parameter interval
//!   where `|ṁ| < |ṙ|` ([`CanalError::NoRealEnvelope`]);
//! * [`factor`]: exact factorization over `Q` and `Q(i)`;
//! * [`sum_of_squares`]: `D = g₁² + g₂²` exactly over `Q` when possible, else over the
//!   quadratic extension it needs (stated in the result), else an error; an explicit `f64`
//!   path;
//! * [`envelope`]: the Peternell–Pottmann construction (docs/math/lines-and-canal.md, "Canal surfaces") producing the rational
//!   parametrization `x(t, u)` with its certificates, the degree choice and the Krasauskas
//!   bound (Gruber §2.4), the characteristic circles, both orientations; and the
//!   cyclographic construction for quadratic `k` (docs/math/lines-and-canal.md, "Canal surfaces", Gruber §2.3);
//! * [`frame`]: the choice of the stereographic frame (a rational Householder reflection)
//!   that makes the parametrization free of base points on a parameter interval;
//! * [`pipe`]: pipe surfaces (constant radius), in particular around PH curves where
//!   `D = σ²` is a perfect square;
//! * [`blend`]: canal-surface blends between two spheres (or a sphere and a plane) with
//!   prescribed contact circles.
//!
//! * [`canal_global`]: the global check of any canal surface (no two characteristic discs
//!   meet), by exact subdivision of parameter pairs;
//! * [`cyclographic_param`]: the cyclographic parametrization `Γ(s, t)` (Gruber §2.3) of a
//!   quadratic family as the rational fallback when the spine-parameter constructions need
//!   `Q(√d)` ([`canal_surface_rational`]);
//! * [`normal_field`]: the canal surface from any rational unit normal field along the
//!   spine (a rational point on every circle of normals, Gruber (2.10) ff.);
//! * [`krasauskas`]: Krasauskas' construction (Gruber §2.4): the circles of normals as
//!   `f_s(a(t) + u b(t))` of a real pencil in `C²`, reduced by the operations (2.36) (and
//!   their combination, which also removes collapsed circles). [`canal_surface`] tries it
//!   beside Peternell–Pottmann for every axis and split ([`Method`]) and keeps the lowest
//!   bidegree: the ring torus and the Dupin cyclide from rational circle spines come out
//!   biquadratic `(2, 2)` (Peternell–Pottmann: `(4, 2)`; bound (2.37): `(4, 2)`), and a
//!   polynomial quintic family tangent to a plane `(9, 2)` (Peternell–Pottmann and (2.37):
//!   `(13, 2)`).
//!
//! **Limits of the degree reduction.** The bound of Satz 2 (2.37) ([`krasauskas_bound`]) is
//! over `C`; the reduction works over the field of the data with `i` (`Q(i)`, or
//! `Q(√d)(i)` when the split of `D` needs `√d`: [`krasauskas`], factors by Trager's norm
//! method in [`rcagd_algebra::factor_ext`]), so when the factors of `det(a, b)` are
//! irreducible over that field of degree > 1 it can stop above the bound (test
//! `seed003_examples::s003_2_4_krasauskas_reduction`: `(6, 2)` against `(4, 2)`; over
//! `Q(√3)` the bound is reached: `canal_krasauskas_ext`). docs/math/lines-and-canal.md,
//! Errata G9: for polynomial data the bound can be *above* what the constructions reach.

pub mod approximate_pipe;
pub mod bipoly;
pub mod blend;
pub mod blend_charts;
pub mod canal_global;
pub mod cyclographic_param;
pub mod envelope;
pub mod exportable;
pub mod factor;
mod float_bernstein;
pub mod frame;
pub mod krasauskas;
pub(crate) mod normal_degree;
pub mod normal_field;
pub mod pipe;
pub mod regularity;
pub mod seam;
pub mod self_intersection;
pub mod sum_of_squares;

pub use approximate_pipe::{pipe_along_spine, ApproximatePipe, ApproximationPolicy, SpinePipe};
pub use bipoly::BiPoly;
pub use blend::{
    blend_sphere_plane, blend_sphere_plane_f64, blend_spheres, blend_spheres_f64, BlendEnd,
    BlendSpine, PlaneEnd, SphereBlend, SpherePlaneBlend,
};
pub use canal_global::{
    canal_joint_defect, check_canal_chain_embedded, check_canal_chain_embedded_within,
    check_canal_embedded, check_canal_embedded_within, check_cyclographic_embedded,
    check_cyclographic_embedded_within, discs_meet, JointDefect, CANAL_GLOBAL_BOXES,
    CANAL_GLOBAL_DEPTH,
};
pub use cyclographic_param::{
    canal_chain_rational, canal_surface_rational, CanalChain, CyclographicCanal, RationalCanal,
};
pub use envelope::{
    canal_surface, canal_surface_approx, canal_surface_f64, canal_surface_with_split,
    krasauskas_bound, AxisChoice, CanalBuild, CanalOptions, CanalSurface, CharacteristicCircle,
    Construction, KrasauskasBound, Method, Orientation, QuadraticCanal,
};
pub use exportable::{
    canal_surface_exportable, chain_is_g1_closed, check_ph_chain_embedded, degree_certificate,
    pipe_along_chain, pipe_around_ph_exportable, pipe_around_ph_with, pipe_exportable,
    positive_weight_certificate, ExportPiece, ExportableCanal, Frame, PipeChain,
};
pub use frame::{
    canal_surface_pole_free, pipe_around_ph_pole_free, pole_free_direction, EXPORT_SPLITS,
};
pub use normal_field::{canal_surface_from_normal_field, NormalFieldCanal};
pub use pipe::{pipe_around_ph, pipe_around_ph_poly, pipe_around_planar, pipe_surface};
pub use regularity::{
    canal_regularity_polynomial, check_canal_regularity, check_cyclographic_regularity,
    check_pipe_global, check_pipe_regularity, pipe_regularity_polynomials,
};
pub use self_intersection::{check_chain_embedded, check_pipe_embedded};
pub use sum_of_squares::{
    sum_of_two_squares, sum_of_two_squares_approx, sum_of_two_squares_f64, GaussianSplit,
    SumOfSquares,
};

use crate::error::format_scalar;
use rcagd_algebra::roots::isolate_real_roots_in;
use rcagd_algebra::{AlgebraError, Poly, Rational, Scalar};
use rcagd_geom::{BezierCurve, GeomError};
use thiserror::Error;

/// Errors of the canal-surface module. Every variant names the violated precondition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum CanalError {
    /// `|ṁ|² − ṙ² < 0` on a parameter interval: the spheres there have no real envelope
    /// (Gruber (2.8)/(2.18)).
    #[error("no real envelope: |m'|² − r'² < 0 for t in ({from}, {to}) (e.g. at t = {witness}, where it is {value}); the sphere family is not enveloped there (Gruber (2.18))")]
    NoRealEnvelope {
        /// Lower end of the interval (a root of `D`, or the domain end, or `−∞`).
        from: String,
        /// Upper end of the interval.
        to: String,
        /// A rational parameter inside the interval.
        witness: String,
        /// The value of `|m'|² − r'²` (times the positive factor `W⁴/d²`) there.
        value: String,
    },
    /// The spine is degenerate (constant family, zero weight, isotropic tangents
    /// everywhere, …).
    #[error("degenerate spine: {0}")]
    DegenerateSpine(String),
    /// A given split `g₁² + g₂²` does not equal the discriminant.
    #[error("not a sum of two squares of the discriminant: {0}")]
    NotASplit(String),
    /// `D` is not a sum of two squares over `Q` and no single quadratic extension suffices
    /// (the construction would need a larger algebraic extension; use the `f64` path).
    #[error("the discriminant needs more than one quadratic extension: {0}")]
    NeedsLargerExtension(String),
    /// The exact factorization gave up (too many modular factors).
    #[error("factorization: {0}")]
    Factorization(String),
    /// Any other invalid argument; the message names the precondition.
    #[error("invalid argument: {0}")]
    InvalidArgument(String),
    /// The radius vanishes identically: the spheres are points, their envelope is the
    /// spine curve, not a surface.
    #[error("the radius r(t) vanishes identically: the spheres are points and their envelope is the spine curve, not a surface; give a radius that is not zero everywhere")]
    ZeroRadius,
    /// Every exact build of the surface needs a quadratic field `Q(√d)`: exchange files
    /// carry rational geometry only.
    #[error("|ṁ|² − ṙ² is not a sum of two squares over Q: the exact surface needs the field Q(√{radicand}) (rcagd::canal::canal_surface builds it there); STEP and IGES carry rational geometry only — change the data so that it splits over Q (e.g. a PH spine for a pipe)")]
    IrrationalSplit {
        /// The square-free radicand `d`.
        radicand: String,
    },
    /// The spine-parameter constructions need `Q(√d)`, but the family is quadratic: its
    /// cyclographic parametrization `Γ(s, t)` (Gruber §2.3) is rational over `Q` on a
    /// rectangle of Ω(s, t), which must be given ([`canal_surface_rational`]).
    #[error("|ṁ|² − ṙ² is not a sum of two squares over Q (the constructions in the spine parameter need Q(√{radicand})), but the family is quadratic, so its cyclographic parametrization Γ(s, t) (Gruber §2.3) is rational over Q: give a rectangle [s0, s1, t0, t1] of Ω(s, t) = (2s, 2t, 1 − s² − t², 1 + s² + t²) for it")]
    CyclographicDomainNeeded {
        /// The square-free radicand `d`.
        radicand: String,
    },
    /// No exact construction, frame or interval split gives Bézier patches with positive
    /// weights on a parameter interval (the weight of every candidate vanishes there).
    #[error("no exact construction gives patches with positive weights for t in [{from}, {to}] ({tried} candidates tried, after splitting the interval): the weight of every parametrization vanishes there")]
    NotExportable {
        /// Lower end of the interval.
        from: String,
        /// Upper end of the interval.
        to: String,
        /// How many candidates were built on it.
        tried: usize,
    },
    /// The pipe radius is not below the radius of curvature `1/κ` of the spine somewhere
    /// on the domain: `r·κ ≥ 1` there, the pipe intersects itself locally.
    #[error("the pipe radius |r| = |{radius}| is not below the radius of curvature 1/κ of the spine for t in [{from}, {to}] (e.g. at t = {witness}, where 1/κ ≈ {curvature_radius}): r·κ ≥ 1 there, so the pipe intersects itself locally")]
    RadiusNotBelowCurvatureRadius {
        /// The radius.
        radius: String,
        /// Lower end of the interval (a root of `|P|⁶ − r²W⁴|P × P′|²` or the domain end).
        from: String,
        /// Upper end of the interval.
        to: String,
        /// A rational parameter inside the interval.
        witness: String,
        /// `1/κ` there, rounded.
        curvature_radius: String,
    },
    /// Two parts of a pipe could not be shown apart by the exact subdivision bounds
    /// (undecided: no witness of a meeting was found either).
    #[error("the pipe parts over t in {first} and t in {second} may meet: their spine pieces come within ≈ {distance} of each other (the tube diameter 2|r| is {diameter}), and the exact subdivision bounds cannot separate them (undecided)")]
    TubePartsNotApart {
        /// The first parameter interval.
        first: String,
        /// The second parameter interval.
        second: String,
        /// The sampled distance of the two spine pieces.
        distance: String,
        /// `2|r|`.
        diameter: String,
    },
    /// The pipe intersects itself: the normal discs of radius `|r|` at two distinct spine
    /// points meet (an exact witness: a point in both discs).
    #[error("the pipe intersects itself: the normal discs of radius |r| at t ≈ {first} and t ≈ {second} meet (the spine points are {distance} apart, the tube diameter 2|r| is {diameter}): use a smaller radius or change the spine")]
    PipeSelfIntersects {
        /// The first spine parameter (rounded; with the piece of a chain).
        first: String,
        /// The second spine parameter.
        second: String,
        /// `|m(t) − m(s)|`, rounded.
        distance: String,
        /// `2|r|`.
        diameter: String,
    },
    /// The error of one piece of a chain of spine curves.
    #[error("spine piece {index} (counted from 0): {source}")]
    SpinePiece {
        /// The index of the piece in the chain.
        index: usize,
        /// Its error.
        source: Box<CanalError>,
    },
    /// The canal surface is singular: its characteristic circles meet the characteristic
    /// points of the family (the edge of regression) for these parameters.
    #[error("the canal surface is singular for t in [{from}, {to}] (e.g. at t = {witness}): there the characteristic circle of the sphere family meets its neighbours (F = (H|A|² + RB(A·C))² − R²(|A|² − B²)|A × C|² ≤ 0, docs/math/pipes.md#canal-regularity), so the surface intersects itself locally or has a cusp — change the radii or shrink the domain")]
    SingularCanal {
        /// Lower end of the interval (a root of `F` or the domain end).
        from: String,
        /// Upper end of the interval.
        to: String,
        /// A rational parameter inside the interval.
        witness: String,
    },
    /// Two characteristic circles of a canal surface (any radius) bound discs that meet: the
    /// surface intersects itself ([`canal_global::check_canal_embedded`], exact witness).
    #[error("the canal surface intersects itself: the characteristic circles over t in {first} and over t in {second} come too close — the discs they bound meet at t = {t} and t = {s} (decided exactly, docs/math/pipes.md#canal-global); change the radius or the spine, or shrink the domain")]
    CanalSelfIntersects {
        /// The first parameter interval.
        first: String,
        /// The second parameter interval.
        second: String,
        /// A parameter in `first` (exact rational).
        t: String,
        /// A parameter in `second` whose disc meets the disc at `t` (exact rational).
        s: String,
    },
    /// Two characteristic discs over spine parameters reached by the rectangle of the
    /// cyclographic parametrization `Γ(s, t)` meet
    /// ([`canal_global::check_cyclographic_embedded`], exact witness): the canal surface over
    /// those spine parameters intersects itself. `Γ` covers arcs of these circles only, so it
    /// is not certified — it may still be free of self-intersection on the rectangle.
    #[error("Γ(s, t) cannot be certified free of self-intersection on its rectangle: the characteristic circles over the spine parameters p in {first} and p in {second} (both reached by the rectangle) bound discs that meet at p = {t} and p = {s} (decided exactly), so the full canal surface over these parameters intersects itself; Γ covers arcs of these circles only and may still miss the intersection (docs/math/pipes.md#canal-global-cyclographic) — shrink the rectangle, or change the radius or the spine")]
    CyclographicDiscsMeet {
        /// The first spine-parameter interval (with what the rectangle reaches).
        first: String,
        /// The second spine-parameter interval.
        second: String,
        /// A spine parameter in `first` (exact rational).
        t: String,
        /// A spine parameter in `second` whose disc meets the disc at `t` (exact rational).
        s: String,
    },
    /// The characteristic discs over two parameter intervals could be shown neither disjoint
    /// nor meeting within the subdivision limits ([`canal_global::check_canal_embedded`]).
    #[error("the parts of the canal surface over t in {first} and over t in {second} could not be shown apart: after {boxes} boxes of exact subdivision their characteristic discs are neither shown disjoint nor found to meet (undecided: they nearly touch there, docs/math/pipes.md#canal-global)")]
    CanalPartsNotApart {
        /// The first parameter interval.
        first: String,
        /// The second parameter interval.
        second: String,
        /// How many boxes were examined.
        boxes: usize,
    },
    /// The cyclographic parametrization `Γ(s, t)` of a canal surface is singular at a point
    /// of its rectangle ([`regularity::check_cyclographic_regularity`]).
    #[error("the canal surface Γ(s, t) is singular at (s, t) = ({s}, {t}) of the rectangle (spine parameter p = {p}): {reason} — choose a rectangle of Ω(s, t) away from it (docs/math/pipes.md#canal-regularity)")]
    SingularCyclographic {
        /// The point's `s`.
        s: String,
        /// The point's `t`.
        t: String,
        /// The spine parameter there.
        p: String,
        /// What fails there.
        reason: String,
    },
    /// The spine's tangent `m′` vanishes at a parameter of the domain.
    #[error("the spine has a zero-length tangent m′ = 0 at t = {at}: the pipe is singular there")]
    ZeroTangent {
        /// The parameter (exact, or a rounded root).
        at: String,
    },
    /// The PH spline approximation of a spine failed (a tolerance that cannot be met, a
    /// zero tangent, a weight ≤ 0).
    #[error("approximating the spine by PH quintics: {0}")]
    SpineApproximation(#[from] crate::ph::PhError),
    /// A failure of the geometry layer.
    #[error(transparent)]
    Geom(#[from] GeomError),
    /// A failure of the algebra layer.
    #[error(transparent)]
    Algebra(#[from] AlgebraError),
}

/// The curve `k(t) = (m(t), r(t))` of the cyclographic model of a rational sphere family:
/// homogeneous polynomials `(W, M₁, M₂, M₃, R)` with `m = M/W` and `r = R/W` (Gruber
/// §2.2 (2.19)).
#[derive(Clone, PartialEq)]
pub struct CanalSpine<F> {
    w: Poly<F>,
    m: [Poly<F>; 3],
    r: Poly<F>,
    /// [`CanalSpine::derivative_numerators`] and [`CanalSpine::discriminant`] once
    /// computed (the fields never change after
    /// construction: a value of the data, not part of it).
    numerators: NumeratorCache<F>,
}

/// The data `(W, M, R)` only (the cache is not part of the value).
impl<F: std::fmt::Debug> std::fmt::Debug for CanalSpine<F> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CanalSpine")
            .field("w", &self.w)
            .field("m", &self.m)
            .field("r", &self.r)
            .finish()
    }
}

/// The derivative numerators and the discriminant of a [`CanalSpine`], computed on first use (the candidate
/// search asks for them once per frame, method and split). Always equal: two spines with
/// the same data are equal whether or not one has computed them.
/// Shared by clones (the data of a clone is the same, so are its numerators).
#[derive(Clone)]
struct NumeratorCache<F>(std::sync::Arc<Derived<F>>);

/// The numerators and the discriminant, each set at most once.
struct Derived<F> {
    numerators: std::sync::OnceLock<[Poly<F>; 4]>,
    discriminant: std::sync::OnceLock<Poly<F>>,
}

impl<F> NumeratorCache<F> {
    fn new() -> Self {
        NumeratorCache(std::sync::Arc::new(Derived {
            numerators: std::sync::OnceLock::new(),
            discriminant: std::sync::OnceLock::new(),
        }))
    }
}

impl<F> PartialEq for NumeratorCache<F> {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl<F: Scalar> CanalSpine<F> {
    /// The family `m = M/W`, `r = R/W`.
    ///
    /// # Errors
    /// [`CanalError::DegenerateSpine`] for `W ≡ 0`.
    pub fn new(w: Poly<F>, m: [Poly<F>; 3], r: Poly<F>) -> Result<Self, CanalError> {
        if w.is_zero() {
            return Err(CanalError::DegenerateSpine(
                "the weight polynomial W vanishes identically".into(),
            ));
        }
        Ok(CanalSpine {
            w,
            m,
            r,
            numerators: NumeratorCache::new(),
        })
    }

    /// A polynomial spine `m(t)` with polynomial radius `r(t)` (`W = 1`).
    pub fn polynomial(m: [Poly<F>; 3], r: Poly<F>) -> Self {
        CanalSpine {
            w: Poly::constant(F::one()),
            m,
            r,
            numerators: NumeratorCache::new(),
        }
    }

    /// From a rational Bézier curve in `R⁴ = R^{3,1}` (points `(x, y, z, r)`), the
    /// cyclographic preimage of the family (parameter `t ∈ R`, power basis).
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] unless the curve has dimension 4;
    /// [`CanalError::DegenerateSpine`] for a zero weight.
    pub fn from_curve(curve: &BezierCurve<F>) -> Result<Self, CanalError> {
        if curve.dim() != 4 {
            return Err(CanalError::InvalidArgument(format!(
                "the cyclographic preimage of a sphere family is a curve in R⁴ = (x, y, z, r), got dimension {}",
                curve.dim()
            )));
        }
        let p = curve.coordinate_polys();
        Self::new(
            p[0].clone(),
            [p[1].clone(), p[2].clone(), p[3].clone()],
            p[4].clone(),
        )
    }

    /// From a rational spine curve (dimension 3) and a rational radius function given as a
    /// Bézier curve of dimension 1 (`(w, w·r)`), on the same parameter: common weight
    /// `W = w_m w_r / gcd(w_m, w_r)` (the gcd only for exact scalars).
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] for wrong dimensions.
    pub fn from_spine_and_radius(
        spine: &BezierCurve<F>,
        radius: &BezierCurve<F>,
    ) -> Result<Self, CanalError> {
        if spine.dim() != 3 || radius.dim() != 1 {
            return Err(CanalError::InvalidArgument(format!(
                "spine must have dimension 3 and radius dimension 1, got {} and {}",
                spine.dim(),
                radius.dim()
            )));
        }
        let sp = spine.coordinate_polys();
        let rp = radius.coordinate_polys();
        let (wm, wr) = (sp[0].clone(), rp[0].clone());
        let g = if F::EXACT {
            wm.gcd(&wr)
        } else {
            Poly::constant(F::one())
        };
        let (fm, fr) = if F::EXACT && g.degree().is_some_and(|d| d > 0) {
            (
                wr.div_exact(&g).map_err(CanalError::Algebra)?,
                wm.div_exact(&g).map_err(CanalError::Algebra)?,
            )
        } else {
            (wr.clone(), wm.clone())
        };
        Self::new(
            &wm * &fm,
            [&sp[1] * &fm, &sp[2] * &fm, &sp[3] * &fm],
            &rp[1] * &fr,
        )
    }

    /// A constant radius `r` around a rational spine curve (a pipe family).
    ///
    /// # Errors
    /// [`CanalError::InvalidArgument`] unless the spine has dimension 3.
    pub fn constant_radius(spine: &BezierCurve<F>, r: &F) -> Result<Self, CanalError> {
        if spine.dim() != 3 {
            return Err(CanalError::InvalidArgument(format!(
                "a spine curve must have dimension 3, got {}",
                spine.dim()
            )));
        }
        let p = spine.coordinate_polys();
        let r = p[0].scale(r);
        Self::new(p[0].clone(), [p[1].clone(), p[2].clone(), p[3].clone()], r)
    }

    /// The weight `W`.
    pub fn weight(&self) -> &Poly<F> {
        &self.w
    }

    /// The centre numerators `M₁, M₂, M₃`.
    pub fn center_polys(&self) -> &[Poly<F>; 3] {
        &self.m
    }

    /// The radius numerator `R`.
    pub fn radius_poly(&self) -> &Poly<F> {
        &self.r
    }

    /// `[W, M₁, M₂, M₃, R]`.
    pub fn homogeneous(&self) -> [Poly<F>; 5] {
        [
            self.w.clone(),
            self.m[0].clone(),
            self.m[1].clone(),
            self.m[2].clone(),
            self.r.clone(),
        ]
    }

    /// The degree `k` of the curve `k(t)` (largest degree of `W, M, R`).
    pub fn degree(&self) -> usize {
        self.homogeneous()
            .iter()
            .filter_map(Poly::degree)
            .max()
            .unwrap_or(0)
    }

    /// The same family with the opposite orientation, `r ↦ −r` (the same canal surface,
    /// opposite unit normal).
    pub fn reversed(&self) -> Self {
        CanalSpine {
            w: self.w.clone(),
            m: self.m.clone(),
            r: -&self.r,
            numerators: NumeratorCache::new(),
        }
    }

    /// The centre and radius at `t`.
    ///
    /// # Errors
    /// [`CanalError::DegenerateSpine`] where `W(t) = 0` (the sphere is at infinity).
    pub fn eval(&self, t: &F) -> Result<([F; 3], F), CanalError> {
        let w = self.w.eval(t);
        let inv = w.inv().ok_or_else(|| {
            CanalError::DegenerateSpine(format!(
                "W({}) = 0: the sphere is at infinity",
                format_scalar(t)
            ))
        })?;
        Ok((
            core::array::from_fn(|i| self.m[i].eval(t) * inv.clone()),
            self.r.eval(t) * inv,
        ))
    }

    /// The curve as a rational Bézier curve in `R⁴` (points `(x, y, z, r)`), degree `k`.
    ///
    /// # Errors
    /// Only a geometry failure underneath.
    pub fn to_curve(&self) -> Result<BezierCurve<F>, CanalError> {
        Ok(BezierCurve::from_coordinate_polys(
            &self.homogeneous(),
            self.degree(),
        )?)
    }

    /// The scalar type converted (into an extension field or `f64`).
    pub fn map_scalar<G: Scalar>(&self, f: impl Fn(&F) -> G + Copy) -> CanalSpine<G> {
        CanalSpine {
            w: self.w.map(f),
            m: [self.m[0].map(f), self.m[1].map(f), self.m[2].map(f)],
            r: self.r.map(f),
            numerators: NumeratorCache::new(),
        }
    }

    /// The derivative numerators `P = W X' − W' X` for `X = (M₁, M₂, M₃, R)` (so
    /// `(ṁ, ṙ) = P/W²`), divided by their common divisor `d` for exact scalars (the
    /// direction `B = (ṙ, ṁ)/d` of Gruber (2.31), corrected: docs/math/lines-and-canal.md, Errata G8).
    ///
    /// # Errors
    /// [`CanalError::DegenerateSpine`] if all four vanish (a constant sphere).
    pub fn derivative_numerators(&self) -> Result<[Poly<F>; 4], CanalError> {
        if let Some(p) = self.numerators.0.numerators.get() {
            return Ok(p.clone());
        }
        let p = self.derivative_numerators_uncached()?;
        Ok(self.numerators.0.numerators.get_or_init(|| p).clone())
    }

    fn derivative_numerators_uncached(&self) -> Result<[Poly<F>; 4], CanalError> {
        let wd = self.w.derivative();
        let x = [&self.m[0], &self.m[1], &self.m[2], &self.r];
        let p: [Poly<F>; 4] =
            core::array::from_fn(|i| &(&self.w * &x[i].derivative()) - &(&wd * x[i]));
        if p.iter().all(Poly::is_zero) {
            return Err(CanalError::DegenerateSpine(
                "ṁ ≡ 0 and ṙ ≡ 0: the family is a single sphere".into(),
            ));
        }
        if !F::EXACT {
            return Ok(p);
        }
        let g = p.iter().fold(Poly::zero(), |acc: Poly<F>, q| acc.gcd(q));
        if g.degree().is_some_and(|d| d > 0) {
            let mut out = p.clone();
            for (o, q) in out.iter_mut().zip(&p) {
                *o = q.div_exact(&g).map_err(CanalError::Algebra)?;
            }
            return Ok(out);
        }
        Ok(p)
    }

    /// The discriminant `D = P₁² + P₂² + P₃² − P₄²` (`= (|ṁ|² − ṙ²)·W⁴/d²`, Gruber (2.34)
    /// corrected: docs/math/lines-and-canal.md, Errata G8). Real characteristic circles iff `D ≥ 0`.
    ///
    /// # Errors
    /// As [`Self::derivative_numerators`].
    pub fn discriminant(&self) -> Result<Poly<F>, CanalError> {
        if let Some(d) = self.numerators.0.discriminant.get() {
            return Ok(d.clone());
        }
        let p = self.derivative_numerators()?;
        let d = &(&(&(&p[0] * &p[0]) + &(&p[1] * &p[1])) + &(&p[2] * &p[2])) - &(&p[3] * &p[3]);
        Ok(self.numerators.0.discriminant.get_or_init(|| d).clone())
    }

    /// Checks that the envelope is real on the domain (`None`: all of `R`): `D ≥ 0` there.
    ///
    /// # Errors
    /// [`CanalError::NoRealEnvelope`] naming an interval (between consecutive real roots of
    /// `D`, exact or isolated) where `D < 0`; [`CanalError::DegenerateSpine`] for `D ≡ 0`
    /// (all tangents of `k` isotropic: the characteristic circles are points) or a
    /// constant family.
    pub fn check_real_envelope(&self, domain: Option<(&F, &F)>) -> Result<(), CanalError> {
        let d = self.discriminant()?;
        let dq = to_rational_poly(&d).ok_or_else(|| {
            CanalError::InvalidArgument(
                "the discriminant has irrational coefficients: the reality check needs a rational spine".into(),
            )
        })?;
        let dom = match domain {
            Some((a, b)) => {
                let (Some(a), Some(b)) = (a.to_rational(), b.to_rational()) else {
                    return Err(CanalError::InvalidArgument(
                        "the parameter domain must be finite".into(),
                    ));
                };
                Some((a, b))
            }
            None => None,
        };
        if let Some(neg) = negative_interval(&dq, dom.as_ref())? {
            return Err(neg);
        }
        Ok(())
    }
}

impl CanalSpine<Rational> {
    /// The sphere family `μ(c(t))` of a rational curve `c(t) = (c₀, …, c₄)` of the Möbius
    /// model `P⁴` (Peternell §2.4–2.5, (2.13), Thm 2.3): centres `cᵢ/(c₀ − c₄)`, squared
    /// radius `N/(c₀ − c₄)²` with `N = c₁² + c₂² + c₃² + c₄² − c₀²`. The family has a rational
    /// radius (the setting of this module) iff `N` is the square of a polynomial; then
    /// `W = c₀ − c₄`, `M = (c₁, c₂, c₃)`, `R = √N`.
    ///
    /// # Errors
    /// [`CanalError::DegenerateSpine`] for `c₀ ≡ c₄` (a family of planes);
    /// [`CanalError::InvalidArgument`] if `N` is not a perfect square (only `r²` is rational:
    /// such canal surfaces are rational by Thm 2.3 but need a rational point on the
    /// characteristic conic, which this module does not construct).
    pub fn from_mobius_curve(c: &[Poly<Rational>; 5]) -> Result<Self, CanalError> {
        let w = &c[0] - &c[4];
        if w.is_zero() {
            return Err(CanalError::DegenerateSpine(
                "c₀ ≡ c₄: every member of the family is a plane".into(),
            ));
        }
        let n = &(&(&(&(&c[1] * &c[1]) + &(&c[2] * &c[2])) + &(&c[3] * &c[3])) + &(&c[4] * &c[4]))
            - &(&c[0] * &c[0]);
        let r = poly_sqrt(&n).ok_or_else(|| {
            CanalError::InvalidArgument(
                "c₁² + c₂² + c₃² + c₄² − c₀² is not the square of a polynomial: the radius is not rational (Peternell Thm 2.3 families with rational r² only)".into(),
            )
        })?;
        Self::new(w, [c[1].clone(), c[2].clone(), c[3].clone()], r)
    }
}

/// The polynomial square root (`None` if `p` is not a square of a rational polynomial).
pub(crate) fn poly_sqrt(p: &Poly<Rational>) -> Option<Poly<Rational>> {
    if p.is_zero() {
        return Some(Poly::zero());
    }
    let lc = p.leading();
    let c = rcagd_algebra::rational::rational_sqrt(&lc)?;
    let mut root = Poly::constant(c);
    for (f, k) in rcagd_algebra::roots::square_free_decomposition(p) {
        if k % 2 == 1 {
            return None;
        }
        root = &root * &f.pow((k / 2) as u32);
    }
    (&root * &root == *p).then_some(root)
}

/// The exact rational coefficients of a polynomial (`None` if one is irrational).
pub(crate) fn to_rational_poly<F: Scalar>(p: &Poly<F>) -> Option<Poly<Rational>> {
    let c: Option<Vec<Rational>> = p.coeffs().iter().map(Scalar::to_rational).collect();
    c.map(Poly::new)
}

/// A root of `d` for messages: exact when rational, else its isolating interval (refined to
/// width ≤ 2⁻²⁰ by the caller) and the correctly rounded `f64` value of the root.
fn describe_root(
    iv: &rcagd_algebra::roots::RootInterval,
    rational: &[Rational],
    d: &Poly<Rational>,
) -> String {
    if iv.is_exact() {
        format_scalar(&iv.lo)
    } else if let Some(r) = rational.iter().find(|r| iv.contains(r)) {
        format_scalar(r)
    } else {
        let approx = iv.root_f64(d).unwrap_or_else(|_| iv.midpoint_f64());
        format!(
            "the root of D in ({}, {}) ≈ {:.6}",
            format_scalar(&iv.lo),
            format_scalar(&iv.hi),
            approx
        )
    }
}

/// An interval of `domain` (default `R`) where `d < 0`, as a [`CanalError::NoRealEnvelope`].
///
/// # Errors
/// [`CanalError::DegenerateSpine`] for `d ≡ 0`.
pub(crate) fn negative_interval(
    d: &Poly<Rational>,
    domain: Option<&(Rational, Rational)>,
) -> Result<Option<CanalError>, CanalError> {
    if d.is_zero() {
        return Err(CanalError::DegenerateSpine(
            "|ṁ|² − ṙ² ≡ 0: every tangent of the cyclographic preimage is isotropic, the characteristic circles degenerate to points".into(),
        ));
    }
    // Cauchy bound for an unbounded domain
    let lc = d.leading();
    let cb = d
        .coeffs()
        .iter()
        .map(|c| {
            let q = c.clone() / lc.clone();
            if q < Rational::ZERO {
                -q
            } else {
                q
            }
        })
        .fold(Rational::ZERO, |a, b| if b > a { b } else { a })
        + Rational::ONE;
    let (a, b, unbounded) = match domain {
        Some((a, b)) => (a.clone(), b.clone(), false),
        None => (-cb.clone(), cb, true),
    };
    if a > b {
        return Err(CanalError::InvalidArgument(format!(
            "empty parameter domain [{}, {}]",
            format_scalar(&a),
            format_scalar(&b)
        )));
    }
    let mut roots = isolate_real_roots_in(d, &a, &b)?;
    let rational = rcagd_algebra::roots::rational_roots(d);
    // tight isolating intervals for the message (the root's value, not the midpoint of a
    // coarse interval)
    let width = Rational::from_ratio(1, 1 << 20);
    for iv in &mut roots {
        if !iv.is_exact() && !rational.iter().any(|r| iv.contains(r)) {
            iv.refine(d, &width)?;
        }
    }
    // gaps: (left, left description) .. (right, right description)
    let mut bounds: Vec<(Rational, Rational, String)> = Vec::new(); // (lo, hi, text)
    let start_txt = if unbounded {
        "−∞".to_string()
    } else {
        format_scalar(&a)
    };
    let end_txt = if unbounded {
        "+∞".to_string()
    } else {
        format_scalar(&b)
    };
    bounds.push((a.clone(), a.clone(), start_txt));
    for iv in &roots {
        bounds.push((
            iv.lo.clone(),
            iv.hi.clone(),
            describe_root(iv, &rational, d),
        ));
    }
    bounds.push((b.clone(), b.clone(), end_txt));
    for w in bounds.windows(2) {
        let (left, right) = (&w[0], &w[1]);
        let s = if left.1 < right.0 {
            (left.1.clone() + right.0.clone()) / Rational::from(2)
        } else {
            left.1.clone()
        };
        let v = d.eval(&s);
        if v < Rational::ZERO {
            return Ok(Some(CanalError::NoRealEnvelope {
                from: left.2.clone(),
                to: right.2.clone(),
                witness: format_scalar(&s),
                value: format_scalar(&v),
            }));
        }
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }
    fn p(c: &[i64]) -> Poly<Rational> {
        Poly::from_ints(c)
    }

    #[test]
    fn discriminant_and_reality() {
        // m = (t, 0, 0), r = t²: D = 1 − 4t² < 0 for |t| > 1/2
        let s = CanalSpine::polynomial([p(&[0, 1]), p(&[]), p(&[])], p(&[0, 0, 1]));
        assert_eq!(s.discriminant().expect("d"), p(&[1, 0, -4]));
        let e = s.check_real_envelope(None).expect_err("not real");
        match &e {
            CanalError::NoRealEnvelope { from, to, .. } => {
                assert_eq!(from, "−∞");
                assert_eq!(to, "-1/2");
            }
            other => panic!("{other:?}"),
        }
        assert!(s
            .check_real_envelope(Some((
                &Rational::from_ratio(-1, 2),
                &Rational::from_ratio(1, 2)
            )))
            .is_ok());
        assert!(matches!(
            s.check_real_envelope(Some((&q(0), &q(1)))),
            Err(CanalError::NoRealEnvelope { .. })
        ));
        // constant family
        let c = CanalSpine::polynomial([p(&[1]), p(&[2]), p(&[3])], p(&[1]));
        assert!(matches!(
            c.discriminant(),
            Err(CanalError::DegenerateSpine(_))
        ));
        // isotropic everywhere: m = (t, 0, 0), r = t
        let iso = CanalSpine::polynomial([p(&[0, 1]), p(&[]), p(&[])], p(&[0, 1]));
        assert!(matches!(
            iso.check_real_envelope(None),
            Err(CanalError::DegenerateSpine(_))
        ));
    }
}
