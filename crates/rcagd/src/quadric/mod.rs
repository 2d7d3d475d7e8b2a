//! Curves and surfaces on quadrics: the generalized stereographic projection
//! (B. Jüttler, *Zur Konstruktion rationaler Kurven und Flächen auf Quadriken*; the
//! formulas in our words, with the corrections J1–J3, in docs/math/quadrics.md).
//!
//! The idea of Jüttler's paper: every coprime polynomial solution of `k0² = k1²+k2²+k3²`
//! (unit sphere `K`) or `h0h3 = h1h2` (hyperbolic paraboloid `H`) is the image of
//! polynomials `p` under a *quadratic* map of homogeneous coordinates, (7)/(8). Read as
//! maps `P³ → K` and `P³ → H` they are net projections along a linear line congruence
//! followed by an ordinary stereographic projection:
//!
//! * [`stereographic`]: `δ = σ∘ϑ` onto the sphere (the Hopf map), its fibre rotation
//!   `J`, the projecting lines (fibres) of an elliptic congruence;
//! * [`paraboloid`]: `ψ = τ∘α` onto `H`, the fibres of a hyperbolic congruence, and
//!   interpolation on `H` of lowest (also odd) degree through the Segre factors;
//! * [`quadratic_map`]: quadratic maps as four symmetric matrices, polar forms, exact
//!   identity certificates of the maps themselves;
//! * [`image`]: images of rational Bézier curves (degree `n → 2n`) and tensor-product
//!   patches (`(m,n) → (2m,2n)`) by the polar-form rule, and preimages of half degree;
//! * [`interpolation`]: interpolation on a quadric as Jüttler's linear problem (a curve
//!   in `E³` meeting the projecting lines), lowest degree, free parameters, Hermite data;
//! * [`sphere_patch`]: biquadratic patches from bilinear ones, the Miquel condition
//!   (Satz 7) and its converse;
//! * [`cover`]: an exact, watertight cover of the whole sphere (and of any axis-parallel
//!   ellipsoid) by sixteen biquadratic patches with positive weights;
//! * [`general`]: any quadric `Xᵀ Q X = 0` (symmetric 4×4 rational matrix, or by name):
//!   classification, a rational normal form from a rational point, the generalized
//!   stereographic projection onto it, and the degenerate quadrics (cones, cylinders)
//!   through a parabolic congruence;
//! * [`rational_points`]: exact decision whether a quadric has a rational point
//!   (Hasse–Minkowski), and a search for one;
//! * [`query`]: questions answered exactly — the fibre and stereographic inverse at a
//!   point, the preimage quadric of a plane section, images under a collineation, the
//!   Miquel points of a biquadratic patch, ψ interpolation of any degree on `H`.
//!
//! Every map implements [`GeneralizedProjection`]; the constructions are generic over it
//! and over the scalar ([`Scalar`]: exact [`rcagd_algebra::Rational`] or `f64`).

pub mod cover;
pub mod exportable;
pub mod general;
pub(crate) mod helpers;
pub mod image;
pub mod interpolation;
pub mod paraboloid;
pub mod quadratic_map;
pub mod query;
pub mod rational_points;
pub mod sphere_patch;
pub mod stereographic;

pub use cover::{sphere_cover, SphereCover};
pub use general::{AnyProjection, ConeProjection, Quadric, QuadricKind, QuadricProjection};
pub use image::{
    curve_image, curve_preimage, patch_image, patch_preimage, ImageCurve, ImagePatch, Preimage,
};
pub use interpolation::{
    interpolate, interpolate_hermite, interpolate_hermite_along, interpolate_lowest_degree,
    interpolation_route, HermiteDatum, Interpolant, InterpolationRoute,
};
pub use paraboloid::Psi;
pub use quadratic_map::QuadraticMap;
pub use sphere_patch::BiquadraticPatch;
pub use stereographic::Delta;

use rcagd_algebra::{AlgebraError, Scalar};
use rcagd_geom::GeomError;
use thiserror::Error;

/// A homogeneous point of real projective 3-space, `(p0, p1, p2, p3)`, Cartesian point
/// `(p1, p2, p3)/p0` (Jüttler (1)).
pub type Hom<F> = [F; 4];

/// A symmetric 4×4 matrix `Q` of a quadric `Xᵀ Q X = 0`.
pub type Mat4<F> = [[F; 4]; 4];

/// Errors of the quadric constructions. Every variant names the violated precondition;
/// residuals are formatted exactly (`"p/q"`) for exact scalars.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum QuadricError {
    /// A point that must lie on the quadric does not: `residual = Xᵀ Q X`.
    #[error("{what} {point} is not on the quadric {quadric}: Xᵀ Q X = {residual}")]
    NotOnQuadric {
        /// Which input (`"point 2"`, `"corner p3"`).
        what: String,
        /// The point, formatted.
        point: String,
        /// The quadric's name.
        quadric: String,
        /// `Xᵀ Q X`, formatted.
        residual: String,
    },
    /// The zero vector was given where a projective point is needed.
    #[error("{0} is the zero vector, which is no projective point")]
    ZeroPoint(String),
    /// An input number is NaN or infinite (only possible for `f64`).
    #[error("{0} is not finite")]
    NotFinite(String),
    /// A point must lie in the plane on which a map is defined (σ: `p3 = 0`; τ: `q3 = q0`).
    #[error("{map} is defined on the plane {plane} only, but {point} is not on it")]
    NotInPlane {
        /// The map (`"σ"`).
        map: String,
        /// The plane, as an equation.
        plane: String,
        /// The point, formatted.
        point: String,
    },
    /// The map is undefined at the point: it lies on an exceptional (focal) line of the
    /// congruence, is the centre of a stereographic projection, or is the vertex of a cone.
    #[error("{map} is undefined at {point}: {reason}")]
    Exceptional {
        /// The map.
        map: String,
        /// The point, formatted.
        point: String,
        /// Why (`"it lies on the exceptional line p1 = p2 = 0 of the congruence"`).
        reason: String,
    },
    /// Two interpolation points coincide (projectively).
    #[error("points {0} and {1} coincide")]
    RepeatedPoints(usize, usize),
    /// Two interpolation parameters coincide.
    #[error("parameters {0} and {1} coincide")]
    RepeatedParameters(usize, usize),
    /// Lengths or dimensions that do not fit (a curve not in 3-space, `k` points but
    /// `k'` parameters).
    #[error("dimension mismatch: {0}")]
    Dimension(String),
    /// The curve or patch is not the image of one of half its degree.
    #[error("no preimage of half degree: {0}")]
    NoPreimage(String),
    /// The linear interpolation problem has no admissible solution.
    #[error("no interpolant of preimage degree {degree}: {reason}")]
    NoInterpolant {
        /// The preimage degree `n` (the curve on the quadric has degree `2n`).
        degree: usize,
        /// Why.
        reason: String,
    },
    /// A tangent given for Hermite interpolation is not tangent to the quadric at its
    /// point: `residual = kᵀ Q T`.
    #[error("tangent {index} is not tangent to the quadric at its point: kᵀ Q T = {residual}")]
    NotTangent {
        /// The datum.
        index: usize,
        /// `kᵀ Q T`, formatted.
        residual: String,
    },
    /// The four corners and boundary circles are not a Miquel configuration, so no
    /// biquadratic patch on the sphere has them (Jüttler Satz 7, docs/math/quadrics.md, "Biquadratic sphere patches and the Miquel configuration").
    #[error("the corners are not in Miquel position: det[p1, q2, p3, q4] = {residual} (must be 0){detail}")]
    MiquelFails {
        /// `det[p1, q2, p3, q4]` with the points normalized to `k0 = 1`, formatted.
        residual: String,
        /// More on the configuration.
        detail: String,
    },
    /// A degenerate configuration (collinear control points, a circle through fewer than
    /// three distinct points, a patch whose corners coincide …).
    #[error("degenerate configuration: {0}")]
    Degenerate(String),
    /// The quadric has no real point (definite form), or only one (imaginary cone).
    #[error("the quadric has no real curves: {0}")]
    NoRealPoint(String),
    /// The quadric has real points but no rational point (decided exactly by
    /// Hasse–Minkowski), or no rational point is known.
    #[error("no rational point: {0}")]
    NoRationalPoint(String),
    /// The matrix is not a symmetric 4×4 matrix, or the quadric is of a kind that is not
    /// supported (rank ≤ 2: plane pairs).
    #[error("unsupported quadric: {0}")]
    Unsupported(String),
    /// Any other invalid argument.
    #[error("invalid argument: {0}")]
    InvalidArgument(String),
    /// A failure of the geometry layer.
    #[error(transparent)]
    Geom(#[from] GeomError),
    /// A failure of the algebra layer.
    #[error(transparent)]
    Algebra(#[from] AlgebraError),
}

/// A generalized stereographic projection: a quadratic map `F: P³ → Φ` onto a quadric
/// `Φ: Xᵀ Q X = 0` whose fibres are the lines of a linear congruence (Jüttler §2, §3,
/// Schlussbemerkung). Implemented by [`Delta`] (sphere), [`Psi`] (hyperbolic paraboloid),
/// [`QuadricProjection`] (any non-degenerate quadric with a rational point) and
/// [`ConeProjection`] (cones and cylinders).
pub trait GeneralizedProjection<F: Scalar> {
    /// A name for messages (`"δ (unit sphere)"`).
    fn name(&self) -> String;
    /// The symmetric matrix `Q` of the target quadric.
    fn quadric(&self) -> Mat4<F>;
    /// The quadratic map as four symmetric matrices.
    fn quadratic_map(&self) -> QuadraticMap<F>;
    /// `F(p)`, zero on the exceptional set of the congruence.
    fn apply(&self, p: &Hom<F>) -> Hom<F> {
        self.quadratic_map().apply(p)
    }
    /// The polar form `F̂(a, b) = (F(a+b) − F(a−b))/4`, symmetric bilinear with
    /// `F̂(p, p) = F(p)` (docs/math/quadrics.md, conventions).
    fn polar(&self, a: &Hom<F>, b: &Hom<F>) -> Hom<F> {
        self.quadratic_map().polar(a, b)
    }
    /// Two points spanning the fibre (projecting line) over `k`: every point `x` of the
    /// line with `F(x) ≠ 0` has `F(x) ∥ k`.
    ///
    /// # Errors
    /// [`QuadricError::NotOnQuadric`], [`QuadricError::ZeroPoint`], and
    /// [`QuadricError::Exceptional`] where `k` has no preimage (the vertex of a cone).
    fn fibre(&self, k: &Hom<F>) -> Result<[Hom<F>; 2], QuadricError>;
    /// A matrix `G` generating the fibre symmetry: the projecting line through a point
    /// `x` off the exceptional set is `span{x, Gx}` (δ: `J`, `J² = −I`; ψ: `diag(1,1,0,0)`;
    /// cones: a nilpotent `N`).
    fn fibre_generator(&self) -> Mat4<F>;
    /// The projecting line contained in the plane `πᵀx = 0`: `ker[π; πG]`, a `G`-invariant
    /// line (Jüttler §2: every plane contains exactly one projecting line, for the
    /// elliptic congruence of δ).
    ///
    /// # Errors
    /// [`QuadricError::Degenerate`] if the plane contains more than one projecting line
    /// (a plane through a focal line of a hyperbolic or parabolic congruence).
    fn fibre_in_plane(&self, plane: &Hom<F>) -> Result<[Hom<F>; 2], QuadricError> {
        check_point(plane, "the plane")?;
        let g = self.fibre_generator();
        let pg = helpers::mat_vec(&helpers::transpose(&g), plane);
        let rows = vec![plane.to_vec(), pg.to_vec()];
        let ns = helpers::null_space(&rows, 4);
        if ns.len() != 2 {
            return Err(QuadricError::Degenerate(format!(
                "the plane {} contains infinitely many projecting lines of {}",
                helpers::fmt_vec(plane),
                self.name()
            )));
        }
        Ok([helpers::to_hom(&ns[0]), helpers::to_hom(&ns[1])])
    }
}

/// Checks that `k` is a finite non-zero point on `Xᵀ Q X = 0`.
pub(crate) fn check_on_quadric<F: Scalar>(
    q: &Mat4<F>,
    k: &Hom<F>,
    what: &str,
    quadric: &str,
) -> Result<(), QuadricError> {
    check_point(k, what)?;
    let (r, mag) = helpers::quad_form(q, k);
    if !helpers::negligible(&r, mag) {
        return Err(QuadricError::NotOnQuadric {
            what: what.to_string(),
            point: helpers::fmt_vec(k),
            quadric: quadric.to_string(),
            residual: helpers::fmt_scalar(&r),
        });
    }
    Ok(())
}

/// Checks that `p` is finite and non-zero.
pub(crate) fn check_point<F: Scalar>(p: &[F], what: &str) -> Result<(), QuadricError> {
    if !helpers::all_finite(p) {
        return Err(QuadricError::NotFinite(what.to_string()));
    }
    if helpers::is_zero_vec(p) {
        return Err(QuadricError::ZeroPoint(what.to_string()));
    }
    Ok(())
}
