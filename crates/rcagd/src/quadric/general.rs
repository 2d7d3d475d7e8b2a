//! Any quadric: classification, named quadrics, the generalized stereographic projection
//! onto a quadric with a rational point, and the degenerate quadrics (cones, cylinders).
//!
//! **Normal form** (Jüttler Schlussbemerkung, made rational). Let `Φ: Xᵀ Q X = 0` be
//! non-degenerate with a rational point `c`. Choose `d` with `cᵀQd = 1` and make it
//! isotropic (`d ← d − ½(dᵀQd)·c`); let `w₁, w₂` be a Q-orthogonal basis of
//! `{x : cᵀQx = dᵀQx = 0}` with `α = w₁ᵀQw₁`, `β = w₂ᵀQw₂`. In the basis
//! `B = [c, w₁, w₂, d]` the quadric is `x0x3 = a x1² + b x2²` with `a = −α/2`, `b = −β/2`.
//! With `e = −b/a`, `z = p0 + p3√e`, `w = p1 + p2√e` and the norm `N(x + y√e) = x² − e y²`,
//! the map
//!
//! `N_{a,e}(p) = (a(p0² − e p3²), p0p1 + e p2p3, p0p2 + p1p3, p1² − e p2²)`
//!
//! (`x0 = aN(z)`, `x1 + x2√e = zw`, `x3 = N(w)`) lands on the normal form because the norm
//! is multiplicative; `δ_Φ = B∘N_{a,e}` is a rational quadratic map onto `Φ`. For the
//! unit sphere (`e = −1`, `a = b = ½`) it is `δ/2` (Jüttler (9)): Jüttler's δ is the case
//! `z·w` over the Gaussian numbers. Its fibres are the lines `span{p, J_e p}`,
//! `J_e p = (e p3, −e p2, −p1, p0)`, `J_e² = e·I`: an elliptic congruence for oval
//! quadrics (`e < 0`), a hyperbolic one for ruled quadrics (`e > 0`; its focal lines are
//! rational exactly when `e` is a square). All constructions of this module
//! (images, preimages, interpolation, biquadratic patches) work through it, so they are
//! transferred to every quadric with a rational point.
//!
//! **Transfer by projective maps** (docs/math/quadrics.md, "Other quadrics"): Jüttler's maps from `K` to the
//! ellipsoid, the two-sheet hyperboloid and the elliptic paraboloid, and from `H` to the
//! one-sheet hyperboloid, are [`seed_transfer`] matrices; [`transfer_curve`] and
//! [`transfer_patch`] apply any projective map to control points (exact, degree kept).
//! A rational projective map between two quadrics exists only if their forms are
//! similar over Q (e.g. not from `K` to `x²+y²+3z² = 1`); the normal form above needs no
//! such map.
//!
//! **Degenerate quadrics** (cones and cylinders, rank 3; Jüttler only announces "a net
//! projection along a parabolic linear congruence followed by a stereographic
//! projection"). With the vertex `v`, a rational point `c ≠ v`, `d` as above and
//! `w ⊥_Q c, d` with `α = wᵀQw`, the basis `B = [v, c, w, d]` gives `x1x3 = a x2²`,
//! `a = −α/2`, and
//!
//! `γ_a(p) = (p0p1 + p3p2, a p1², p1p2, p2²)`
//!
//! maps onto it. Its fibres are the lines through the point `(u2, 0, 0, −u1)` of the axis
//! `p1 = p2 = 0` in the plane `u2p1 − u1p2 = 0` — a parabolic linear congruence with the
//! exceptional line `p1 = p2 = 0` (mapped to nothing) — and `γ(p + tNp) = γ(p)` with the
//! nilpotent `N p = (p2, 0, 0, −p1)`. The vertex has no preimage.

// Index loops mirror the matrix formulas (Q_ij, M_k[i][j]) of docs/math/quadrics.md.
#![allow(clippy::needless_range_loop)]

use super::helpers::{self, fmt_vec, mat4_i};
use super::quadratic_map::QuadraticMap;
use super::rational_points::find_rational_point;
use super::{check_on_quadric, check_point, GeneralizedProjection, Hom, Mat4, QuadricError};
use crate::Certified;
use rcagd_algebra::{Certificate, Rational, Scalar};
use rcagd_geom::{BezierCurve, BezierPatch};

/// The projective-affine type of a real quadric.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum QuadricKind {
    /// Oval, the plane at infinity misses it (sphere included).
    Ellipsoid,
    /// Oval, cut by the plane at infinity in a real conic.
    HyperboloidTwoSheets,
    /// Oval, touched by the plane at infinity.
    EllipticParaboloid,
    /// Ruled, cut by the plane at infinity in a real conic.
    HyperboloidOneSheet,
    /// Ruled, touched by the plane at infinity.
    HyperbolicParaboloid,
    /// Rank 3 with a finite vertex and real base conic.
    Cone,
    /// Rank 3, vertex at infinity, elliptic section.
    EllipticCylinder,
    /// Rank 3, vertex at infinity, hyperbolic section.
    HyperbolicCylinder,
    /// Rank 3, vertex at infinity, parabolic section.
    ParabolicCylinder,
    /// Definite form: no real point.
    Imaginary,
    /// Rank 3 with a definite base: only the vertex is real.
    ImaginaryCone,
    /// Rank ≤ 2: a pair of planes or a double plane.
    PlanePair,
}

impl QuadricKind {
    /// `true` for the rank-3 kinds with real points (cones and cylinders).
    pub fn is_cone(self) -> bool {
        matches!(
            self,
            QuadricKind::Cone
                | QuadricKind::EllipticCylinder
                | QuadricKind::HyperbolicCylinder
                | QuadricKind::ParabolicCylinder
        )
    }
    /// `true` for the doubly ruled non-degenerate quadrics.
    pub fn is_ruled(self) -> bool {
        matches!(
            self,
            QuadricKind::HyperboloidOneSheet | QuadricKind::HyperbolicParaboloid
        )
    }
}

/// A quadric `Xᵀ Q X = 0` in homogeneous coordinates `X = (x0, x1, x2, x3)`
/// (Cartesian point `(x1, x2, x3)/x0`), with an optional known rational point.
#[derive(Debug, Clone, PartialEq)]
pub struct Quadric<F> {
    matrix: Mat4<F>,
    name: String,
    point: Option<Hom<F>>,
}

fn inv2<F: Scalar>(a: &F, what: &str) -> Result<F, QuadricError> {
    if a.is_zero() || !helpers::all_finite(std::slice::from_ref(a)) {
        return Err(QuadricError::InvalidArgument(format!(
            "{what} must be finite and non-zero"
        )));
    }
    Ok(F::one() / (a.clone() * a.clone()))
}

fn diag<F: Scalar>(d: [F; 4]) -> Mat4<F> {
    let mut m = [
        helpers::zero4::<F>(),
        helpers::zero4(),
        helpers::zero4(),
        helpers::zero4(),
    ];
    for (i, x) in d.into_iter().enumerate() {
        m[i][i] = x;
    }
    m
}

impl<F: Scalar> Quadric<F> {
    /// From a symmetric 4×4 matrix.
    ///
    /// # Errors
    /// [`QuadricError::Unsupported`] if the matrix is not symmetric or is zero;
    /// [`QuadricError::NotFinite`].
    pub fn from_matrix(matrix: Mat4<F>) -> Result<Self, QuadricError> {
        if !helpers::all_finite(&matrix.concat()) {
            return Err(QuadricError::NotFinite("the quadric's matrix".into()));
        }
        let scale = helpers::magnitude(&matrix.concat());
        for i in 0..4 {
            for j in i + 1..4 {
                if !helpers::negligible(&(matrix[i][j].clone() - matrix[j][i].clone()), scale) {
                    return Err(QuadricError::Unsupported(format!(
                        "the matrix is not symmetric (entry ({i}, {j}))"
                    )));
                }
            }
        }
        if helpers::is_zero_vec(&matrix.concat()) {
            return Err(QuadricError::Unsupported(
                "the zero matrix is no quadric".into(),
            ));
        }
        Ok(Quadric {
            matrix,
            name: "quadric".into(),
            point: None,
        })
    }

    /// From a matrix given as rows (e.g. parsed from a recipe).
    ///
    /// # Errors
    /// [`QuadricError::Dimension`] unless 4×4; as [`Self::from_matrix`].
    pub fn from_rows(rows: &[Vec<F>]) -> Result<Self, QuadricError> {
        if rows.len() != 4 || rows.iter().any(|r| r.len() != 4) {
            return Err(QuadricError::Dimension(
                "a quadric needs a 4×4 matrix".into(),
            ));
        }
        Self::from_matrix([0, 1, 2, 3].map(|i| helpers::to_hom(&rows[i])))
    }

    /// Attaches a known rational point (used by [`Self::projection`]).
    ///
    /// # Errors
    /// [`QuadricError::NotOnQuadric`], [`QuadricError::ZeroPoint`].
    pub fn with_point(mut self, p: Hom<F>) -> Result<Self, QuadricError> {
        check_on_quadric(&self.matrix, &p, "the given point", &self.name)?;
        self.point = Some(p);
        Ok(self)
    }

    /// Renames the quadric (for messages and reports).
    pub fn named(mut self, name: impl Into<String>) -> Self {
        self.name = name.into();
        self
    }

    fn make(matrix: Mat4<F>, name: String, point: Hom<F>) -> Self {
        Quadric {
            matrix,
            name,
            point: Some(point),
        }
    }

    /// The unit sphere `K: k0² = k1² + k2² + k3²` (Jüttler (5)), with the rational point
    /// `(1, 0, 0, −1)`; its projection is `δ/2`.
    pub fn unit_sphere() -> Self {
        let o = F::one;
        Self::make(
            diag([o(), -o(), -o(), -o()]),
            "unit sphere K".into(),
            [o(), F::zero(), F::zero(), -o()],
        )
    }

    /// The sphere with centre `m` and radius `r`: `|x − m|² = r²`.
    ///
    /// # Errors
    /// [`QuadricError::InvalidArgument`] for `r = 0`.
    pub fn sphere(m: [F; 3], r: F) -> Result<Self, QuadricError> {
        let _ = inv2(&r, "the radius")?;
        let mm = m.iter().fold(F::zero(), |s, x| s + x.clone() * x.clone());
        let mut q = diag([mm - r.clone() * r.clone(), F::one(), F::one(), F::one()]);
        for i in 0..3 {
            q[0][i + 1] = -m[i].clone();
            q[i + 1][0] = -m[i].clone();
        }
        let p = [F::one(), m[0].clone() + r, m[1].clone(), m[2].clone()];
        Ok(Self::make(q, "sphere".into(), p))
    }

    /// The ellipsoid `x²/a² + y²/b² + z²/c² = 1`.
    ///
    /// # Errors
    /// [`QuadricError::InvalidArgument`] for a zero semi-axis.
    pub fn ellipsoid(a: F, b: F, c: F) -> Result<Self, QuadricError> {
        let q = diag([-F::one(), inv2(&a, "a")?, inv2(&b, "b")?, inv2(&c, "c")?]);
        Ok(Self::make(
            q,
            "ellipsoid".into(),
            [F::one(), a, F::zero(), F::zero()],
        ))
    }

    /// The one-sheet hyperboloid `x²/a² + y²/b² − z²/c² = 1`.
    ///
    /// # Errors
    /// As [`Self::ellipsoid`].
    pub fn hyperboloid_one_sheet(a: F, b: F, c: F) -> Result<Self, QuadricError> {
        let q = diag([-F::one(), inv2(&a, "a")?, inv2(&b, "b")?, -inv2(&c, "c")?]);
        Ok(Self::make(
            q,
            "one-sheet hyperboloid".into(),
            [F::one(), a, F::zero(), F::zero()],
        ))
    }

    /// The two-sheet hyperboloid `z²/c² − x²/a² − y²/b² = 1`.
    ///
    /// # Errors
    /// As [`Self::ellipsoid`].
    pub fn hyperboloid_two_sheets(a: F, b: F, c: F) -> Result<Self, QuadricError> {
        let q = diag([F::one(), inv2(&a, "a")?, inv2(&b, "b")?, -inv2(&c, "c")?]);
        Ok(Self::make(
            q,
            "two-sheet hyperboloid".into(),
            [F::one(), F::zero(), F::zero(), c],
        ))
    }

    /// The elliptic paraboloid `z = x²/a² + y²/b²`.
    ///
    /// # Errors
    /// As [`Self::ellipsoid`].
    pub fn elliptic_paraboloid(a: F, b: F) -> Result<Self, QuadricError> {
        let mut q = diag([F::zero(), inv2(&a, "a")?, inv2(&b, "b")?, F::zero()]);
        let h = -(F::one() / F::from_i64(2));
        q[0][3] = h.clone();
        q[3][0] = h;
        Ok(Self::make(
            q,
            "elliptic paraboloid".into(),
            [F::one(), F::zero(), F::zero(), F::zero()],
        ))
    }

    /// The hyperbolic paraboloid `z = x²/a² − y²/b²`.
    ///
    /// # Errors
    /// As [`Self::ellipsoid`].
    pub fn hyperbolic_paraboloid(a: F, b: F) -> Result<Self, QuadricError> {
        let mut q = diag([F::zero(), inv2(&a, "a")?, -inv2(&b, "b")?, F::zero()]);
        let h = -(F::one() / F::from_i64(2));
        q[0][3] = h.clone();
        q[3][0] = h;
        Ok(Self::make(
            q,
            "hyperbolic paraboloid".into(),
            [F::one(), F::zero(), F::zero(), F::zero()],
        ))
    }

    /// Jüttler's hyperbolic paraboloid `H: h0h3 = h1h2` (Jüttler (6)).
    pub fn seed_paraboloid() -> Self {
        Self::make(
            super::paraboloid::paraboloid_matrix(),
            "hyperbolic paraboloid H".into(),
            [F::one(), F::zero(), F::zero(), F::zero()],
        )
    }

    /// The cone `x²/a² + y²/b² = z²/c²` (vertex at the origin).
    ///
    /// # Errors
    /// As [`Self::ellipsoid`].
    pub fn cone(a: F, b: F, c: F) -> Result<Self, QuadricError> {
        let q = diag([F::zero(), inv2(&a, "a")?, inv2(&b, "b")?, -inv2(&c, "c")?]);
        Ok(Self::make(q, "cone".into(), [F::one(), a, F::zero(), c]))
    }

    /// The elliptic cylinder `x²/a² + y²/b² = 1` (axis z).
    ///
    /// # Errors
    /// As [`Self::ellipsoid`].
    pub fn elliptic_cylinder(a: F, b: F) -> Result<Self, QuadricError> {
        let q = diag([-F::one(), inv2(&a, "a")?, inv2(&b, "b")?, F::zero()]);
        Ok(Self::make(
            q,
            "elliptic cylinder".into(),
            [F::one(), a, F::zero(), F::zero()],
        ))
    }

    /// The hyperbolic cylinder `x²/a² − y²/b² = 1` (axis z).
    ///
    /// # Errors
    /// As [`Self::ellipsoid`].
    pub fn hyperbolic_cylinder(a: F, b: F) -> Result<Self, QuadricError> {
        let q = diag([-F::one(), inv2(&a, "a")?, -inv2(&b, "b")?, F::zero()]);
        Ok(Self::make(
            q,
            "hyperbolic cylinder".into(),
            [F::one(), a, F::zero(), F::zero()],
        ))
    }

    /// The parabolic cylinder `z = x²/a²` (axis y).
    ///
    /// # Errors
    /// As [`Self::ellipsoid`].
    pub fn parabolic_cylinder(a: F) -> Result<Self, QuadricError> {
        let mut q = diag([F::zero(), inv2(&a, "a")?, F::zero(), F::zero()]);
        let h = -(F::one() / F::from_i64(2));
        q[0][3] = h.clone();
        q[3][0] = h;
        Ok(Self::make(
            q,
            "parabolic cylinder".into(),
            [F::one(), F::zero(), F::zero(), F::zero()],
        ))
    }

    /// A named quadric with parameters, for recipes: `"unit_sphere"`, `"sphere"`
    /// (`cx, cy, cz, r`), `"ellipsoid"` (`a, b, c`), `"hyperboloid_one_sheet"` (`a, b, c`),
    /// `"hyperboloid_two_sheets"` (`a, b, c`), `"elliptic_paraboloid"` (`a, b`),
    /// `"hyperbolic_paraboloid"` (`a, b`), `"hyperbolic_paraboloid_xy"` (`z = xy`, i.e.
    /// `h0h3 = h1h2`; deprecated alias `"seed_paraboloid"`), `"cone"` (`a, b, c`),
    /// `"elliptic_cylinder"` (`a, b`), `"hyperbolic_cylinder"` (`a, b`),
    /// `"parabolic_cylinder"` (`a`).
    ///
    /// # Errors
    /// [`QuadricError::InvalidArgument`] for an unknown name or a wrong number of
    /// parameters; the constructors' errors.
    pub fn by_name(name: &str, params: &[F]) -> Result<Self, QuadricError> {
        let want = |k: usize| -> Result<(), QuadricError> {
            if params.len() == k {
                Ok(())
            } else {
                Err(QuadricError::InvalidArgument(format!(
                    "quadric `{name}` takes {k} parameters, got {}",
                    params.len()
                )))
            }
        };
        let p = |i: usize| params[i].clone();
        match name {
            "unit_sphere" => want(0).map(|_| Self::unit_sphere()),
            "sphere" => want(4).and_then(|_| Self::sphere([p(0), p(1), p(2)], p(3))),
            "ellipsoid" => want(3).and_then(|_| Self::ellipsoid(p(0), p(1), p(2))),
            "hyperboloid_one_sheet" => {
                want(3).and_then(|_| Self::hyperboloid_one_sheet(p(0), p(1), p(2)))
            }
            "hyperboloid_two_sheets" => {
                want(3).and_then(|_| Self::hyperboloid_two_sheets(p(0), p(1), p(2)))
            }
            "elliptic_paraboloid" => want(2).and_then(|_| Self::elliptic_paraboloid(p(0), p(1))),
            "hyperbolic_paraboloid" => {
                want(2).and_then(|_| Self::hyperbolic_paraboloid(p(0), p(1)))
            }
            // "seed_paraboloid": the deprecated name of "hyperbolic_paraboloid_xy"
            "hyperbolic_paraboloid_xy" | "seed_paraboloid" => {
                want(0).map(|_| Self::seed_paraboloid())
            }
            "cone" => want(3).and_then(|_| Self::cone(p(0), p(1), p(2))),
            "elliptic_cylinder" => want(2).and_then(|_| Self::elliptic_cylinder(p(0), p(1))),
            "hyperbolic_cylinder" => want(2).and_then(|_| Self::hyperbolic_cylinder(p(0), p(1))),
            "parabolic_cylinder" => want(1).and_then(|_| Self::parabolic_cylinder(p(0))),
            _ => Err(QuadricError::InvalidArgument(format!(
                "unknown quadric `{name}`"
            ))),
        }
        .map(|q| q.named(name))
    }

    /// The symmetric matrix.
    pub fn matrix(&self) -> &Mat4<F> {
        &self.matrix
    }
    /// The name.
    pub fn name(&self) -> &str {
        &self.name
    }
    /// The known rational point, if any.
    pub fn point(&self) -> Option<&Hom<F>> {
        self.point.as_ref()
    }

    /// `Xᵀ Q X`.
    pub fn residual(&self, x: &Hom<F>) -> F {
        helpers::quad_form(&self.matrix, x).0
    }

    /// Rank and signature `(rank, positive, negative)` (exact congruence diagonalization).
    pub fn signature(&self) -> (usize, usize, usize) {
        super::rational_points::signature(&self.matrix)
    }

    /// The type of the quadric, from the signature of `Q` and of its quadratic part
    /// `A = Q[1..4][1..4]` (whose determinant vanishes iff the plane at infinity touches).
    pub fn kind(&self) -> QuadricKind {
        let (rank, pos, neg) = self.signature();
        let a: Mat4<F> = {
            let mut a = self.matrix.clone();
            for i in 0..4 {
                a[0][i] = F::zero();
                a[i][0] = F::zero();
            }
            a
        };
        let (ra, pa, na) = super::rational_points::signature(&a);
        match rank {
            4 => {
                if pos == 4 || neg == 4 {
                    QuadricKind::Imaginary
                } else if pos == 2 {
                    if ra == 3 {
                        QuadricKind::HyperboloidOneSheet
                    } else {
                        QuadricKind::HyperbolicParaboloid
                    }
                } else if ra < 3 {
                    QuadricKind::EllipticParaboloid
                } else if pa == 3 || na == 3 {
                    QuadricKind::Ellipsoid
                } else {
                    QuadricKind::HyperboloidTwoSheets
                }
            }
            3 => {
                if pos == 3 || neg == 3 {
                    return QuadricKind::ImaginaryCone;
                }
                let v = self.vertex();
                let finite = v
                    .as_ref()
                    .is_some_and(|v| !helpers::negligible(&v[0], helpers::magnitude(v)));
                if finite {
                    QuadricKind::Cone
                } else if ra == 1 {
                    QuadricKind::ParabolicCylinder
                } else if pa == 2 || na == 2 {
                    QuadricKind::EllipticCylinder
                } else {
                    QuadricKind::HyperbolicCylinder
                }
            }
            _ => QuadricKind::PlanePair,
        }
    }

    /// The vertex (kernel of `Q`) of a rank-3 quadric.
    pub fn vertex(&self) -> Option<Hom<F>> {
        let rows: Vec<Vec<F>> = self.matrix.iter().map(|r| r.to_vec()).collect();
        let ns = helpers::null_space(&rows, 4);
        (ns.len() == 1).then(|| helpers::to_hom(&ns[0]))
    }

    /// A rational point: the known one, or one found by [`find_rational_point`] (exact
    /// decision, then search; for `f64` the matrix is read exactly as rationals).
    ///
    /// # Errors
    /// [`QuadricError::NoRealPoint`], [`QuadricError::NoRationalPoint`],
    /// [`QuadricError::Unsupported`].
    pub fn rational_point(&self) -> Result<Hom<F>, QuadricError> {
        if let Some(p) = &self.point {
            return Ok(p.clone());
        }
        let exact: Option<Vec<Rational>> = self
            .matrix
            .concat()
            .iter()
            .map(|x| x.to_rational())
            .collect();
        let Some(exact) = exact else {
            return Err(QuadricError::NotFinite("the quadric's matrix".into()));
        };
        let m: Mat4<Rational> = [0, 1, 2, 3].map(|i| helpers::to_hom(&exact[4 * i..4 * i + 4]));
        let p = find_rational_point(&m)?;
        Ok(p.map(|x| F::from_rational(&x)))
    }

    /// The generalized stereographic projection onto this quadric (module docs):
    /// [`QuadricProjection`] for rank 4, [`ConeProjection`] for cones and cylinders.
    ///
    /// # Errors
    /// [`QuadricError::NoRealPoint`] (definite form, imaginary cone),
    /// [`QuadricError::NoRationalPoint`], [`QuadricError::Unsupported`] (rank ≤ 2),
    /// [`QuadricError::Exceptional`] if the given point is the vertex of a cone.
    pub fn projection(&self) -> Result<AnyProjection<F>, QuadricError> {
        match self.kind() {
            QuadricKind::Imaginary => {
                return Err(QuadricError::NoRealPoint(format!(
                    "{} has a definite form",
                    self.name
                )))
            }
            QuadricKind::ImaginaryCone => {
                return Err(QuadricError::NoRealPoint(format!(
                    "{} is an imaginary cone: its only real point is the vertex",
                    self.name
                )))
            }
            QuadricKind::PlanePair => {
                return Err(QuadricError::Unsupported(format!(
                    "{} has rank ≤ 2 (plane pair or double plane)",
                    self.name
                )))
            }
            _ => {}
        }
        let c = self.rational_point()?;
        if self.kind().is_cone() {
            Ok(AnyProjection::Cone(ConeProjection::new(self, &c)?))
        } else {
            Ok(AnyProjection::General(QuadricProjection::new(self, &c)?))
        }
    }
}

/// `(d, w-space)`: a partner `d` of the isotropic point `c` (`cᵀQd = 1`, `dᵀQd = 0`).
fn hyperbolic_partner<F: Scalar>(q: &Mat4<F>, c: &Hom<F>) -> Result<Hom<F>, QuadricError> {
    let qc = helpers::mat_vec(q, c);
    // the basis vector with the largest |(Qc)_i|
    let (i, _) = qc
        .iter()
        .enumerate()
        .map(|(i, x)| (i, x.to_f64().abs()))
        .filter(|(_, v)| *v > 0.0 || F::EXACT)
        .filter(|(i, _)| !qc[*i].is_zero())
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .ok_or_else(|| QuadricError::Exceptional {
            map: "the projection".into(),
            point: fmt_vec(c),
            reason: "it is the vertex (Qc = 0)".into(),
        })?;
    let mut d = helpers::zero4::<F>();
    d[i] = F::one() / qc[i].clone();
    let dqd = helpers::bilinear(q, &d, &d);
    let half = F::one() / F::from_i64(2);
    Ok(helpers::sub4(&d, &helpers::scale4(&(dqd * half), c)))
}

/// The generalized stereographic projection onto a non-degenerate quadric with a rational
/// point: `δ_Φ = B∘N_{a,e}` (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct QuadricProjection<F> {
    name: String,
    quadric: Mat4<F>,
    basis: Mat4<F>,
    basis_inv: Mat4<F>,
    a: F,
    e: F,
    map: QuadraticMap<F>,
}

/// `N_{a,e}(p) = (a(p0² − e p3²), p0p1 + e p2p3, p0p2 + p1p3, p1² − e p2²)`.
pub fn norm_form_map<F: Scalar>(a: &F, e: &F) -> QuadraticMap<F> {
    let (a, e) = (a.clone(), e.clone());
    QuadraticMap::from_fn(move |p: &Hom<F>| {
        let [p0, p1, p2, p3] = p.clone();
        [
            a.clone() * (p0.clone() * p0.clone() - e.clone() * p3.clone() * p3.clone()),
            p0.clone() * p1.clone() + e.clone() * p2.clone() * p3.clone(),
            p0 * p2.clone() + p1.clone() * p3,
            p1.clone() * p1 - e.clone() * p2.clone() * p2,
        ]
    })
}

impl<F: Scalar> QuadricProjection<F> {
    /// Builds the projection from the quadric and a rational point `c` on it.
    ///
    /// # Errors
    /// [`QuadricError::NotOnQuadric`]; [`QuadricError::Unsupported`] if the quadric is
    /// degenerate (use [`ConeProjection`]).
    pub fn new(quadric: &Quadric<F>, c: &Hom<F>) -> Result<Self, QuadricError> {
        let q = quadric.matrix.clone();
        check_on_quadric(&q, c, "the rational point", &quadric.name)?;
        let d = hyperbolic_partner(&q, c)?;
        let qc = helpers::mat_vec(&q, c);
        let qd = helpers::mat_vec(&q, &d);
        let w = helpers::null_space(&[qc.to_vec(), qd.to_vec()], 4);
        if w.len() != 2 {
            return Err(QuadricError::Unsupported("degenerate quadric".into()));
        }
        let mut w1 = helpers::to_hom(&w[0]);
        let mut w2 = helpers::to_hom(&w[1]);
        let scale = helpers::magnitude(&q.concat());
        if helpers::negligible(&helpers::bilinear(&q, &w1, &w1), scale) {
            if !helpers::negligible(&helpers::bilinear(&q, &w2, &w2), scale) {
                std::mem::swap(&mut w1, &mut w2);
            } else {
                w1 = helpers::add4(&w1, &w2);
            }
        }
        let alpha = helpers::bilinear(&q, &w1, &w1);
        if helpers::negligible(&alpha, scale) {
            return Err(QuadricError::Unsupported(format!(
                "{} is degenerate (rank < 4): use ConeProjection",
                quadric.name
            )));
        }
        let t = helpers::bilinear(&q, &w1, &w2) / alpha.clone();
        w2 = helpers::sub4(&w2, &helpers::scale4(&t, &w1));
        let beta = helpers::bilinear(&q, &w2, &w2);
        if helpers::negligible(&beta, scale) {
            return Err(QuadricError::Unsupported(format!(
                "{} is degenerate (rank < 4): use ConeProjection",
                quadric.name
            )));
        }
        let half = F::one() / F::from_i64(2);
        let a = -(alpha.clone() * half.clone());
        let e = -(beta / alpha);
        let basis = columns([c.clone(), w1, w2, d]);
        let basis_inv = helpers::inverse4(&basis)
            .ok_or_else(|| QuadricError::Unsupported("singular normal-form basis".into()))?;
        let map = norm_form_map(&a, &e).then(&basis);
        Ok(QuadricProjection {
            name: format!("δ ({})", quadric.name),
            quadric: q,
            basis,
            basis_inv,
            a,
            e,
            map,
        })
    }

    /// The basis `B = [c, w₁, w₂, d]` (columns): `X = B x` maps the normal form
    /// `x0x3 = a x1² + b x2²` onto the quadric.
    pub fn normal_form_basis(&self) -> &Mat4<F> {
        &self.basis
    }
    /// `(a, e)` of the normal form `x0x3 = a(x1² − e x2²)`.
    pub fn normal_form(&self) -> (&F, &F) {
        (&self.a, &self.e)
    }
    /// `J_e p = (e p3, −e p2, −p1, p0)`, `J_e² = e·I`.
    pub fn fibre_rotation_matrix(&self) -> Mat4<F> {
        let e = self.e.clone();
        let z = F::zero;
        let o = F::one;
        [
            [z(), z(), z(), e.clone()],
            [z(), z(), -e, z()],
            [z(), -o(), z(), z()],
            [o(), z(), z(), z()],
        ]
    }
    /// The certificates of the construction: the map lands on the quadric
    /// (`F(p)ᵀ Q F(p) ≡ 0`), `BᵀQB` is the normal form, `F∘J_e = −e·F`.
    fn construction_certificates(&self) -> Vec<Certificate> {
        let mut out = vec![self
            .map
            .certify_on_quadric(&self.quadric, &format!("{}: F(p)ᵀ Q F(p) ≡ 0", self.name))];
        let bt = helpers::transpose(&self.basis);
        let nf = helpers::mat_mul(&bt, &helpers::mat_mul(&self.quadric, &self.basis));
        let two_a = F::from_i64(2) * self.a.clone();
        let z = F::zero;
        let want: Mat4<F> = [
            [z(), z(), z(), F::one()],
            [z(), -two_a.clone(), z(), z()],
            [z(), z(), two_a * self.e.clone(), z()],
            [F::one(), z(), z(), z()],
        ];
        out.push(Certificate::decide(
            "Bᵀ Q B is the normal form 2x0x3 − 2a x1² + 2ae x2²",
            helpers::mats_close(&nf, &want),
            F::EXACT,
            || format!("Bᵀ Q B = {:?}", nf.clone().map(|r| fmt_vec(&r))),
        ));
        out.push(self.map.certify_invariance(
            &self.fibre_rotation_matrix(),
            &(-self.e.clone()),
            "F(J_e p) ≡ −e·F(p) (fibre symmetry)",
        ));
        out
    }
}

fn columns<F: Scalar>(cols: [Hom<F>; 4]) -> Mat4<F> {
    let mut m = [
        helpers::zero4::<F>(),
        helpers::zero4(),
        helpers::zero4(),
        helpers::zero4(),
    ];
    for (j, c) in cols.iter().enumerate() {
        for i in 0..4 {
            m[i][j] = c[i].clone();
        }
    }
    m
}

impl<F: Scalar> GeneralizedProjection<F> for QuadricProjection<F> {
    fn name(&self) -> String {
        self.name.clone()
    }
    fn quadric(&self) -> Mat4<F> {
        self.quadric.clone()
    }
    fn quadratic_map(&self) -> QuadraticMap<F> {
        self.map.clone()
    }
    fn apply(&self, p: &Hom<F>) -> Hom<F> {
        self.map.apply(p)
    }
    fn polar(&self, a: &Hom<F>, b: &Hom<F>) -> Hom<F> {
        self.map.polar(a, b)
    }
    fn fibre_generator(&self) -> Mat4<F> {
        self.fibre_rotation_matrix()
    }
    /// Over `X` with model coordinates `x = B⁻¹X`: `p = (x0, a x1, a x2, 0)` if `x0 ≠ 0`,
    /// `p = (x1, x3, 0, x2)` if `x3 ≠ 0`; the fibre is `span{p, J_e p}`. If
    /// `x0 = x3 = 0` (only for a square `e = s²`, `s = x1/x2`): `span{(s,0,0,1), (0,s,1,0)}`.
    fn fibre(&self, k: &Hom<F>) -> Result<[Hom<F>; 2], QuadricError> {
        check_on_quadric(&self.quadric, k, "the point", &self.name)?;
        let x = helpers::mat_vec(&self.basis_inv, k);
        let scale = helpers::magnitude(&x);
        let (m0, m3) = (x[0].to_f64().abs(), x[3].to_f64().abs());
        let use0 = if F::EXACT {
            !x[0].is_zero()
        } else {
            m0 >= m3 && !helpers::negligible(&x[0], scale)
        };
        let use3 = if F::EXACT {
            !x[3].is_zero()
        } else {
            !helpers::negligible(&x[3], scale)
        };
        let j = self.fibre_rotation_matrix();
        if use0 || use3 {
            let p = if use0 {
                [
                    x[0].clone(),
                    self.a.clone() * x[1].clone(),
                    self.a.clone() * x[2].clone(),
                    F::zero(),
                ]
            } else {
                [x[1].clone(), x[3].clone(), F::zero(), x[2].clone()]
            };
            let jp = helpers::mat_vec(&j, &p);
            return Ok([p, jp]);
        }
        if helpers::negligible(&x[2], scale) {
            return Err(QuadricError::ZeroPoint("the point".into()));
        }
        let s = x[1].clone() / x[2].clone();
        let z = F::zero;
        Ok([[s.clone(), z(), z(), F::one()], [z(), s, F::one(), z()]])
    }
}

/// The projection onto a cone or cylinder along a parabolic congruence (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct ConeProjection<F> {
    name: String,
    quadric: Mat4<F>,
    basis: Mat4<F>,
    basis_inv: Mat4<F>,
    a: F,
    map: QuadraticMap<F>,
}

/// `γ_a(p) = (p0p1 + p3p2, a p1², p1p2, p2²)` onto `x1x3 = a x2²` (vertex `(1,0,0,0)`).
pub fn cone_model_map<F: Scalar>(a: &F) -> QuadraticMap<F> {
    let a = a.clone();
    QuadraticMap::from_fn(move |p: &Hom<F>| {
        let [p0, p1, p2, p3] = p.clone();
        [
            p0 * p1.clone() + p3 * p2.clone(),
            a.clone() * p1.clone() * p1.clone(),
            p1 * p2.clone(),
            p2.clone() * p2,
        ]
    })
}

/// The nilpotent fibre generator `N p = (p2, 0, 0, −p1)` of the cone map.
pub fn cone_fibre_generator<F: Scalar>() -> Mat4<F> {
    mat4_i([[0, 0, 1, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, -1, 0, 0]])
}

impl<F: Scalar> ConeProjection<F> {
    /// Builds the projection from a rank-3 quadric and a rational point `c ≠` vertex.
    ///
    /// # Errors
    /// [`QuadricError::NotOnQuadric`]; [`QuadricError::Exceptional`] if `c` is the vertex;
    /// [`QuadricError::Unsupported`] unless the rank is 3.
    pub fn new(quadric: &Quadric<F>, c: &Hom<F>) -> Result<Self, QuadricError> {
        let q = quadric.matrix.clone();
        check_on_quadric(&q, c, "the rational point", &quadric.name)?;
        let v = quadric.vertex().ok_or_else(|| {
            QuadricError::Unsupported(format!("{} does not have rank 3", quadric.name))
        })?;
        if helpers::parallel(&v, c) {
            return Err(QuadricError::Exceptional {
                map: "the cone projection".into(),
                point: fmt_vec(c),
                reason: "the rational point is the vertex; give another one".into(),
            });
        }
        let d = hyperbolic_partner(&q, c)?;
        let qc = helpers::mat_vec(&q, c);
        let qd = helpers::mat_vec(&q, &d);
        let ws = helpers::null_space(&[qc.to_vec(), qd.to_vec()], 4);
        let w = ws
            .iter()
            .map(|w| helpers::to_hom(w))
            .filter(|w| !helpers::parallel(w, &v))
            .max_by(|x, y| {
                let qx = helpers::bilinear(&q, x, x).to_f64().abs();
                let qy = helpers::bilinear(&q, y, y).to_f64().abs();
                qx.total_cmp(&qy)
            })
            .ok_or_else(|| QuadricError::Unsupported("degenerate cone".into()))?;
        let alpha = helpers::bilinear(&q, &w, &w);
        if helpers::negligible(&alpha, helpers::magnitude(&q.concat())) {
            return Err(QuadricError::Unsupported(format!(
                "{} has rank < 3",
                quadric.name
            )));
        }
        let a = -(alpha / F::from_i64(2));
        let basis = columns([v, c.clone(), w, d]);
        let basis_inv = helpers::inverse4(&basis)
            .ok_or_else(|| QuadricError::Unsupported("singular basis".into()))?;
        let map = cone_model_map(&a).then(&basis);
        Ok(ConeProjection {
            name: format!("γ ({})", quadric.name),
            quadric: q,
            basis,
            basis_inv,
            a,
            map,
        })
    }

    /// The basis `B = [v, c, w, d]` of the normal form `x1x3 = a x2²`.
    pub fn normal_form_basis(&self) -> &Mat4<F> {
        &self.basis
    }

    /// The certificates: the map lands on the quadric, the fibre symmetry
    /// `γ(p + Np) ≡ γ(p)`, and the exceptional line `p1 = p2 = 0` maps to zero.
    fn construction_certificates(&self) -> Vec<Certificate> {
        let mut out = vec![self
            .map
            .certify_on_quadric(&self.quadric, &format!("{}: F(p)ᵀ Q F(p) ≡ 0", self.name))];
        let n = cone_fibre_generator::<F>();
        let i_plus_n = {
            let mut m = helpers::identity4::<F>();
            for i in 0..4 {
                for j in 0..4 {
                    m[i][j] += n[i][j].clone();
                }
            }
            m
        };
        let i_plus_2n = {
            let mut m = helpers::identity4::<F>();
            for i in 0..4 {
                for j in 0..4 {
                    m[i][j] += F::from_i64(2) * n[i][j].clone();
                }
            }
            m
        };
        out.push(self.map.certify_invariance(
            &i_plus_n,
            &F::one(),
            "γ(p + Np) ≡ γ(p) (parabolic fibre symmetry)",
        ));
        out.push(
            self.map
                .certify_invariance(&i_plus_2n, &F::one(), "γ(p + 2Np) ≡ γ(p)"),
        );
        let axis: Mat4<F> = mat4_i([[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]);
        let zero = QuadraticMap::from_fn(|_: &Hom<F>| helpers::zero4());
        out.push(
            self.map
                .after(&axis)
                .certify_equals(&zero, "γ vanishes on the exceptional line p1 = p2 = 0"),
        );
        out
    }
}

impl<F: Scalar> GeneralizedProjection<F> for ConeProjection<F> {
    fn name(&self) -> String {
        self.name.clone()
    }
    fn quadric(&self) -> Mat4<F> {
        self.quadric.clone()
    }
    fn quadratic_map(&self) -> QuadraticMap<F> {
        self.map.clone()
    }
    fn apply(&self, p: &Hom<F>) -> Hom<F> {
        self.map.apply(p)
    }
    fn polar(&self, a: &Hom<F>, b: &Hom<F>) -> Hom<F> {
        self.map.polar(a, b)
    }
    fn fibre_generator(&self) -> Mat4<F> {
        cone_fibre_generator()
    }
    /// Over `X` with `x = B⁻¹X`, `(x1, x2, x3) = μ(a u1², u1u2, u2²)`: the line through
    /// the axis point `(u2, 0, 0, −u1)` and `(p0, μu1, μu2, p3)` with `u1p0 + u2p3 = x0`.
    fn fibre(&self, k: &Hom<F>) -> Result<[Hom<F>; 2], QuadricError> {
        check_on_quadric(&self.quadric, k, "the point", &self.name)?;
        let x = helpers::mat_vec(&self.basis_inv, k);
        let scale = helpers::magnitude(&x);
        if helpers::all_negligible(&x[1..], scale) {
            return Err(QuadricError::Exceptional {
                map: self.name.clone(),
                point: fmt_vec(k),
                reason: "it is the vertex of the cone, which has no preimage".into(),
            });
        }
        let (u, mu) = if !helpers::negligible(&x[3], scale) {
            ([x[2].clone(), x[3].clone()], F::one() / x[3].clone())
        } else {
            ([F::one(), F::zero()], x[1].clone() / self.a.clone())
        };
        let z = F::zero;
        let axis_point = [u[1].clone(), z(), z(), -u[0].clone()];
        let (p0, p3) = if !helpers::negligible(&u[0], scale) {
            (x[0].clone() / u[0].clone(), z())
        } else {
            (z(), x[0].clone() / u[1].clone())
        };
        let other = [p0, mu.clone() * u[0].clone(), mu * u[1].clone(), p3];
        Ok([other, axis_point])
    }
}

impl<F: Scalar> Certified for QuadricProjection<F> {
    /// The map lands on the quadric (`F(p)ᵀ Q F(p) ≡ 0`), `BᵀQB` is the normal form,
    /// `F∘J_e ≡ −e·F`.
    fn certify(&self) -> Vec<Certificate> {
        self.construction_certificates()
    }
}

impl<F: Scalar> Certified for ConeProjection<F> {
    /// The map lands on the quadric, `γ(p + Np) ≡ γ(p)`, `γ ≡ 0` on `p1 = p2 = 0`.
    fn certify(&self) -> Vec<Certificate> {
        self.construction_certificates()
    }
}

impl<F: Scalar> Certified for AnyProjection<F> {
    /// The certificates of the underlying projection.
    fn certify(&self) -> Vec<Certificate> {
        self.construction_certificates()
    }
}

/// A projection onto any supported quadric (the result of [`Quadric::projection`]).
#[derive(Debug, Clone, PartialEq)]
pub enum AnyProjection<F> {
    /// Non-degenerate quadric.
    General(QuadricProjection<F>),
    /// Cone or cylinder.
    Cone(ConeProjection<F>),
}

impl<F: Scalar> AnyProjection<F> {
    /// The construction's certificates.
    fn construction_certificates(&self) -> Vec<Certificate> {
        match self {
            AnyProjection::General(p) => p.construction_certificates(),
            AnyProjection::Cone(p) => p.construction_certificates(),
        }
    }
}

macro_rules! delegate {
    ($self:ident, $p:ident => $e:expr) => {
        match $self {
            AnyProjection::General($p) => $e,
            AnyProjection::Cone($p) => $e,
        }
    };
}

impl<F: Scalar> GeneralizedProjection<F> for AnyProjection<F> {
    fn name(&self) -> String {
        delegate!(self, p => p.name())
    }
    fn quadric(&self) -> Mat4<F> {
        delegate!(self, p => p.quadric())
    }
    fn quadratic_map(&self) -> QuadraticMap<F> {
        delegate!(self, p => p.quadratic_map())
    }
    fn apply(&self, x: &Hom<F>) -> Hom<F> {
        delegate!(self, p => p.apply(x))
    }
    fn polar(&self, a: &Hom<F>, b: &Hom<F>) -> Hom<F> {
        delegate!(self, p => p.polar(a, b))
    }
    fn fibre(&self, k: &Hom<F>) -> Result<[Hom<F>; 2], QuadricError> {
        delegate!(self, p => p.fibre(k))
    }
    fn fibre_generator(&self) -> Mat4<F> {
        delegate!(self, p => p.fibre_generator())
    }
}

/// A projective map with its source and target quadrics.
pub type SeedTransfer<F> = (Mat4<F>, Quadric<F>, Quadric<F>);

/// The projective maps of docs/math/quadrics.md, "Other quadrics" (Jüttler's Schlussbemerkung), as matrices `A` with
/// `X = A k`:
/// * `"ellipsoid"` (`a, b, c`): `diag(1, a, b, c)` from `K` onto `x²/a²+y²/b²+z²/c² = 1`;
/// * `"hyperboloid_two_sheets"`: swap `k0 ↔ k3`, from `K` onto `x3² = x0²+x1²+x2²`;
/// * `"elliptic_paraboloid"`: `(x0, x3) = (k0−k3, k0+k3)`, from `K` onto `x0x3 = x1²+x2²`;
/// * `"hyperboloid_one_sheet"`: `x0 = (h3−h0)/2`, `x1 = (h0+h3)/2`, `x2 = (h2−h1)/2`,
///   `x3 = (h1+h2)/2`, from `H` onto `x1²+x2²−x3² = x0²`.
///
/// Returns `(A, source quadric, target quadric)`.
///
/// # Errors
/// [`QuadricError::InvalidArgument`] for an unknown name or wrong parameters.
pub fn seed_transfer<F: Scalar>(name: &str, params: &[F]) -> Result<SeedTransfer<F>, QuadricError> {
    let h = F::one() / F::from_i64(2);
    let z = F::zero;
    let o = F::one;
    let k = Quadric::<F>::unit_sphere();
    match (name, params.len()) {
        ("ellipsoid", 3) => {
            let a = diag([o(), params[0].clone(), params[1].clone(), params[2].clone()]);
            Ok((
                a,
                k,
                Quadric::ellipsoid(params[0].clone(), params[1].clone(), params[2].clone())?,
            ))
        }
        ("hyperboloid_two_sheets", 0) => Ok((
            mat4_i([[0, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [1, 0, 0, 0]]),
            k,
            Quadric::from_matrix(diag([o(), o(), o(), -o()]))?.named("x3² = x0² + x1² + x2²"),
        )),
        ("elliptic_paraboloid", 0) => {
            // x0x3 − x1² − x2² as a symmetric matrix
            let t = [
                [z(), z(), z(), h.clone()],
                [z(), -o(), z(), z()],
                [z(), z(), -o(), z()],
                [h.clone(), z(), z(), z()],
            ];
            let target = Quadric::from_matrix(t)?.named("x0x3 = x1² + x2²");
            Ok((
                mat4_i([[1, 0, 0, -1], [0, 1, 0, 0], [0, 0, 1, 0], [1, 0, 0, 1]]),
                k,
                target,
            ))
        }
        ("hyperboloid_one_sheet", 0) => {
            let a = [
                [-h.clone(), z(), z(), h.clone()],
                [h.clone(), z(), z(), h.clone()],
                [z(), -h.clone(), h.clone(), z()],
                [z(), h.clone(), h.clone(), z()],
            ];
            let target =
                Quadric::from_matrix(diag([-o(), o(), o(), -o()]))?.named("x1² + x2² − x3² = x0²");
            Ok((a, Quadric::seed_paraboloid(), target))
        }
        _ => Err(QuadricError::InvalidArgument(format!(
            "unknown seed transfer `{name}` with {} parameters",
            params.len()
        ))),
    }
}

/// Applies the projective map `A` to every control point (exact; degree unchanged).
///
/// # Errors
/// [`QuadricError::Dimension`] unless the curve is in 3-space.
pub fn transfer_curve<F: Scalar>(
    a: &Mat4<F>,
    curve: &BezierCurve<F>,
) -> Result<BezierCurve<F>, QuadricError> {
    let pts = super::image::curve_points(curve)?;
    Ok(BezierCurve::from_homogeneous(
        pts.iter()
            .map(|p| helpers::mat_vec(a, p).to_vec())
            .collect(),
    )?)
}

/// Applies the projective map `A` to every control point of a patch.
///
/// # Errors
/// [`QuadricError::Dimension`] unless the patch is in 3-space.
pub fn transfer_patch<F: Scalar>(
    a: &Mat4<F>,
    patch: &BezierPatch<F>,
) -> Result<BezierPatch<F>, QuadricError> {
    let net = super::image::patch_net(patch)?;
    Ok(BezierPatch::from_homogeneous(
        net.iter()
            .map(|r| r.iter().map(|p| helpers::mat_vec(a, p).to_vec()).collect())
            .collect(),
    )?)
}

/// Certifies that `A` maps the source quadric onto the target: `Aᵀ Q_target A = λ·Q_source`
/// for a non-zero constant `λ` (exactly).
pub fn certify_transfer<F: Scalar>(
    a: &Mat4<F>,
    source: &Quadric<F>,
    target: &Quadric<F>,
) -> Certificate {
    let at = helpers::transpose(a);
    let pulled = helpers::mat_mul(&at, &helpers::mat_mul(target.matrix(), a));
    let src = source.matrix();
    let flat_p = pulled.concat();
    let flat_s = src.concat();
    let ok = !helpers::is_zero_vec(&flat_p) && helpers::parallel(&flat_p, &flat_s);
    Certificate::decide(
        format!("Aᵀ Q({}) A ∥ Q({})", target.name(), source.name()),
        ok,
        F::EXACT,
        || format!("Aᵀ Q A = {}", fmt_vec(&flat_p)),
    )
}

/// Checks a point of a quadric, for users that build their own data.
///
/// # Errors
/// [`QuadricError::NotOnQuadric`], [`QuadricError::ZeroPoint`].
pub fn check_point_on<F: Scalar>(quadric: &Quadric<F>, p: &Hom<F>) -> Result<(), QuadricError> {
    check_point(p, "the point")?;
    check_on_quadric(&quadric.matrix, p, "the point", &quadric.name)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quadric::image::curve_image;
    use crate::quadric::interpolation::{interpolate, sample_points};
    use crate::Certified;

    fn r(n: i64) -> Rational {
        Rational::from(n)
    }

    fn named() -> Vec<(Quadric<Rational>, QuadricKind)> {
        vec![
            (Quadric::unit_sphere(), QuadricKind::Ellipsoid),
            (
                Quadric::sphere([r(1), r(2), r(-1)], r(3)).unwrap(),
                QuadricKind::Ellipsoid,
            ),
            (
                Quadric::ellipsoid(r(1), r(2), r(3)).unwrap(),
                QuadricKind::Ellipsoid,
            ),
            (
                Quadric::hyperboloid_one_sheet(r(1), r(2), r(3)).unwrap(),
                QuadricKind::HyperboloidOneSheet,
            ),
            (
                Quadric::hyperboloid_two_sheets(r(1), r(2), r(3)).unwrap(),
                QuadricKind::HyperboloidTwoSheets,
            ),
            (
                Quadric::elliptic_paraboloid(r(1), r(2)).unwrap(),
                QuadricKind::EllipticParaboloid,
            ),
            (
                Quadric::hyperbolic_paraboloid(r(1), r(2)).unwrap(),
                QuadricKind::HyperbolicParaboloid,
            ),
            (
                Quadric::seed_paraboloid(),
                QuadricKind::HyperbolicParaboloid,
            ),
            (Quadric::cone(r(1), r(2), r(3)).unwrap(), QuadricKind::Cone),
            (
                Quadric::elliptic_cylinder(r(1), r(2)).unwrap(),
                QuadricKind::EllipticCylinder,
            ),
            (
                Quadric::hyperbolic_cylinder(r(1), r(2)).unwrap(),
                QuadricKind::HyperbolicCylinder,
            ),
            (
                Quadric::parabolic_cylinder(r(2)).unwrap(),
                QuadricKind::ParabolicCylinder,
            ),
        ]
    }

    #[test]
    fn named_quadrics_classify_and_project() {
        for (q, kind) in named() {
            assert_eq!(q.kind(), kind, "{}", q.name());
            let proj = q.projection().unwrap();
            for c in proj.certify() {
                assert!(c.holds, "{}: {c}", q.name());
            }
            let x = BezierCurve::from_homogeneous(vec![
                vec![r(1), r(2), r(-1), r(3)],
                vec![r(2), r(0), r(1), r(-1)],
                vec![r(-1), r(1), r(2), r(1)],
            ])
            .unwrap();
            let img = curve_image(&proj, &x).unwrap();
            for c in img.certify() {
                assert!(c.holds, "{}: {c}", q.name());
            }
            let params: Vec<Rational> = (0..5).map(|i| r(i) / r(4)).collect();
            let pts = sample_points(img.image(), &params);
            let it = interpolate(&proj, &pts, &params, 2).unwrap();
            for c in it.certify() {
                assert!(c.holds, "{}: {c}", q.name());
            }
            for p in &pts {
                if let Ok([a, b]) = proj.fibre(p) {
                    let s = helpers::add4(&a, &helpers::scale4(&r(3), &b));
                    assert!(helpers::parallel(&proj.apply(&s), p), "{}", q.name());
                }
            }
        }
    }

    #[test]
    fn unit_sphere_projection_is_half_delta() {
        let AnyProjection::General(p) = Quadric::<Rational>::unit_sphere().projection().unwrap()
        else {
            panic!("general expected")
        };
        let half = crate::quadric::stereographic::delta_map::<Rational>()
            .then(&helpers::scale_mat(&(r(1) / r(2)), &helpers::identity4()));
        assert!(p.quadratic_map().certify_equals(&half, "δ_K = δ/2").holds);
    }

    #[test]
    fn errors() {
        let imag = Quadric::from_matrix(diag([r(1), r(1), r(1), r(1)])).unwrap();
        assert_eq!(imag.kind(), QuadricKind::Imaginary);
        assert!(matches!(
            imag.projection(),
            Err(QuadricError::NoRealPoint(_))
        ));
        let seven = Quadric::sphere([r(0), r(0), r(0)], r(1)).unwrap();
        let _ = seven;
        let s7 = Quadric::from_matrix(diag([r(-7), r(1), r(1), r(1)])).unwrap();
        assert!(matches!(
            s7.projection(),
            Err(QuadricError::NoRationalPoint(_))
        ));
        let icone = Quadric::from_matrix(diag([r(0), r(1), r(1), r(1)])).unwrap();
        assert_eq!(icone.kind(), QuadricKind::ImaginaryCone);
        assert!(matches!(
            icone.projection(),
            Err(QuadricError::NoRealPoint(_))
        ));
        let planes = Quadric::from_matrix(diag([r(0), r(1), r(-1), r(0)])).unwrap();
        assert!(matches!(
            planes.projection(),
            Err(QuadricError::Unsupported(_))
        ));
        let cone = Quadric::cone(r(1), r(1), r(1)).unwrap();
        let v = cone.vertex().unwrap();
        let proj = cone.projection().unwrap();
        assert!(matches!(
            proj.fibre(&v),
            Err(QuadricError::Exceptional { .. })
        ));
        assert!(matches!(
            Quadric::cone(r(1), r(1), r(1))
                .unwrap()
                .with_point(v)
                .unwrap()
                .projection(),
            Err(QuadricError::Exceptional { .. })
        ));
        // a sphere without a given point: found by search
        let s3 = Quadric::from_matrix(diag([r(-3), r(1), r(1), r(1)])).unwrap();
        let p = s3.projection().unwrap();
        assert!(p.certify().iter().all(|c| c.holds));
    }

    #[test]
    fn seed_transfers() {
        for (name, params) in [
            ("ellipsoid", vec![r(2), r(3), r(5)]),
            ("hyperboloid_two_sheets", vec![]),
            ("elliptic_paraboloid", vec![]),
            ("hyperboloid_one_sheet", vec![]),
        ] {
            let (a, src, dst) = seed_transfer(name, &params).unwrap();
            assert!(certify_transfer(&a, &src, &dst).holds, "{name}");
        }
    }
}
