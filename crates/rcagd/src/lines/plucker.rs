//! Plücker coordinates of lines (Gruber §1.1.1–1.1.2, docs/math/lines-and-canal.md, "Plücker coordinates").
//!
//! * `l = p ∧ q`, `l_ik = p_i q_k − p_k q_i`, `l = (l₀₁, l₀₂, l₀₃; l₂₃, l₃₁, l₁₂)` (1.1);
//!   `(λp + μq) ∧ (ρp + σq) = (λσ − μρ)(p ∧ q)` (1.2);
//! * Plücker identity `l₁l₄ + l₂l₅ + l₃l₆ = 0` (1.3), for affine points
//!   `⟨direction, moment⟩ = 0` (1.6);
//! * axis coordinates: the wedge `a = u ∧ v` of two planes is proportional to
//!   `(l₄, l₅, l₆; l₁, l₂, l₃)` (1.5), so `l = (a₄, a₅, a₆; a₁, a₂, a₃)`;
//! * the incidence matrix (1.7)
//!   `M(l) = [[0, l₄, l₅, l₆], [−l₄, 0, l₃, −l₂], [−l₅, −l₃, 0, l₁], [−l₆, l₂, −l₁, 0]]`:
//!   `p ∈ l ⇔ M(l)p = 0`, and for `p ∉ l` the vector `M(l)p` is the plane spanned by `l` and
//!   `p` (it is skew, so `pᵀM(l)p = 0`, and `qᵀM(l)p = −(M(l)q)ᵀp = 0` for `q ∈ l`); the
//!   same matrix built from the axis coordinates, `M(l*)`, tests planes (`u ⊃ l ⇔ M(l*)u = 0`)
//!   and maps a plane `u ⊅ l` to the point `l ∩ u`;
//! * the points `s₁ = (0, l₁, l₂, l₃)`, `s₂ = (−l₁, 0, l₆, −l₅)`, `s₃ = (−l₂, −l₆, 0, l₄)`,
//!   `s₄ = (−l₃, l₅, −l₄, 0)` of `l` in the coordinate planes; `sᵢ ∧ sⱼ` is `l` times
//!   `l₁, l₂, l₃, l₆, −l₅, l₄` for the pairs 12, 13, 14, 23, 24, 34 (docs/math/lines-and-canal.md, "Plücker coordinates",
//!   Errata G23: the factor may vanish, so a pair with a non-zero factor is chosen);
//! * two lines meet (or are parallel) iff `Ω(g, h) = ⟨ḡ, h⟩ + ⟨g, h̄⟩ = 0` (1.10; the text
//!   before (1.8) should read `q − p ⊥ g × h`, docs/math/lines-and-canal.md, Errata G1);
//! * the polarity with respect to `Ω: y₁² + y₂² + y₃² − y₄² = 0` (the absolute quadric of the
//!   cyclographic model, docs/math/lines-and-canal.md, "Complexes, congruences, reguli"): `h = E g`,
//!   `E = [[0, diag(−1, −1, 1)], [diag(1, 1, −1), 0]]`, `E² = −I` (1.19).

use super::{all_zero, dot, fmt_vec, is_small, proportional, scale_of, LineError};
use crate::Certified;
use rcagd_algebra::{Certificate, Ring, Scalar};

/// The wedge `p ∧ q = (p₀q₁ − p₁q₀, p₀q₂ − p₂q₀, p₀q₃ − p₃q₀; p₂q₃ − p₃q₂, p₃q₁ − p₁q₃,
/// p₁q₂ − p₂q₁)` of two homogeneous 4-vectors (Gruber (1.1)).
pub fn wedge<F: Ring>(p: &[F; 4], q: &[F; 4]) -> [F; 6] {
    let l = |i: usize, k: usize| p[i].clone() * q[k].clone() - p[k].clone() * q[i].clone();
    [l(0, 1), l(0, 2), l(0, 3), l(2, 3), l(3, 1), l(1, 2)]
}

/// The reciprocal product (polar form of the Klein quadric, Gruber (1.10)/(1.11)):
/// `Ω(g, h) = g₁h₄ + g₂h₅ + g₃h₆ + g₄h₁ + g₅h₂ + g₆h₃`.
pub fn reciprocal_product<F: Ring>(g: &[F; 6], h: &[F; 6]) -> F {
    g[0].clone() * h[3].clone()
        + g[1].clone() * h[4].clone()
        + g[2].clone() * h[5].clone()
        + g[3].clone() * h[0].clone()
        + g[4].clone() * h[1].clone()
        + g[5].clone() * h[2].clone()
}

/// The Plücker form `l₁l₄ + l₂l₅ + l₃l₆ = Ω(l, l)/2` (Gruber (1.3)).
pub fn klein_form<F: Ring>(l: &[F; 6]) -> F {
    l[0].clone() * l[3].clone() + l[1].clone() * l[4].clone() + l[2].clone() * l[5].clone()
}

/// The swap `(l₁, l₂, l₃; l₄, l₅, l₆) ↦ (l₄, l₅, l₆; l₁, l₂, l₃)` between Plücker and axis
/// coordinates (Gruber (1.5)).
pub fn swap<F: Clone>(l: &[F; 6]) -> [F; 6] {
    [
        l[3].clone(),
        l[4].clone(),
        l[5].clone(),
        l[0].clone(),
        l[1].clone(),
        l[2].clone(),
    ]
}

/// The incidence matrix (1.7) of a coordinate 6-vector `l`.
pub fn incidence_matrix<F: Ring>(l: &[F; 6]) -> [[F; 4]; 4] {
    let z = F::zero;
    let [l1, l2, l3, l4, l5, l6] = l.clone();
    [
        [z(), l4.clone(), l5.clone(), l6.clone()],
        [-l4, z(), l3.clone(), -l2.clone()],
        [-l5, -l3, z(), l1.clone()],
        [-l6, l2, -l1, z()],
    ]
}

/// `M v`.
pub(crate) fn mat_vec<F: Ring>(m: &[[F; 4]; 4], v: &[F; 4]) -> [F; 4] {
    [dot(&m[0], v), dot(&m[1], v), dot(&m[2], v), dot(&m[3], v)]
}

/// The unit vector `eᵢ` of `F⁴`.
pub(crate) fn unit4<F: Scalar>(i: usize) -> [F; 4] {
    let mut e = [F::zero(), F::zero(), F::zero(), F::zero()];
    if let Some(x) = e.get_mut(i) {
        *x = F::one();
    }
    e
}

/// Where a [`Line`] came from (for its incidence certificates).
#[derive(Debug, Clone, PartialEq)]
pub enum LineOrigin<F> {
    /// Given by its coordinates.
    Coordinates,
    /// `p ∧ q` of two points.
    Points([F; 4], [F; 4]),
    /// The intersection of two planes.
    Planes([F; 4], [F; 4]),
}

/// A line of projective 3-space in Plücker coordinates
/// `(l₁, l₂, l₃; l₄, l₅, l₆) = (l₀₁, l₀₂, l₀₃; l₂₃, l₃₁, l₁₂)` (Gruber (1.1)); the
/// coordinates are homogeneous (a line is a point of the Klein quadric).
#[derive(Debug, Clone, PartialEq)]
pub struct Line<F> {
    coords: [F; 6],
    origin: LineOrigin<F>,
}

/// The points `s₁ … s₄` of the line with Plücker coordinates `l` in the coordinate
/// planes `xᵢ = 0` (docs/math/lines-and-canal.md, "Plücker coordinates"), over any ring;
/// some may be zero.
pub(crate) fn coordinate_plane_points<R: rcagd_algebra::Ring>(l: &[R; 6]) -> [[R; 4]; 4] {
    let [l1, l2, l3, l4, l5, l6] = l.clone();
    let z = R::zero;
    [
        [z(), l1.clone(), l2.clone(), l3.clone()],
        [-l1, z(), l6.clone(), -l5.clone()],
        [-l2, -l6, z(), l4.clone()],
        [-l3, l5, -l4, z()],
    ]
}

/// The pairs `(i, j, k)` with `sᵢ ∧ sⱼ = ±l_k · l` for the points of
/// [`coordinate_plane_points`] (factors `l₁, l₂, l₃, l₆, −l₅, l₄` for the pairs 12, 13,
/// 14, 23, 24, 34).
pub(crate) const POINT_PAIRS: [(usize, usize, usize); 6] = [
    (0, 1, 0),
    (0, 2, 1),
    (0, 3, 2),
    (1, 2, 5),
    (1, 3, 4),
    (2, 3, 3),
];

impl<F: Scalar> Line<F> {
    /// The line `p ∧ q` through two homogeneous points (Gruber (1.1)).
    ///
    /// # Errors
    /// [`LineError::CoincidentPoints`] if `p ∧ q = 0` (the points coincide projectively,
    /// or one of them is zero).
    pub fn from_points(p: &[F; 4], q: &[F; 4]) -> Result<Self, LineError> {
        let l = wedge(p, q);
        let scale = scale_of(p) * scale_of(q);
        if l.iter().all(|x| is_small(x, scale)) {
            return Err(LineError::CoincidentPoints(fmt_vec(p), fmt_vec(q)));
        }
        Ok(Line {
            coords: l,
            origin: LineOrigin::Points(p.clone(), q.clone()),
        })
    }

    /// The line through two affine points `a, b ∈ R³` (weights one): direction `b − a`,
    /// moment `a × b`.
    ///
    /// # Errors
    /// [`LineError::CoincidentPoints`] if `a = b`.
    pub fn from_affine_points(a: &[F; 3], b: &[F; 3]) -> Result<Self, LineError> {
        Self::from_points(&affine(a), &affine(b))
    }

    /// The line through the affine point `p` with direction `d`: `(d; p × d)`.
    ///
    /// # Errors
    /// [`LineError::ZeroVector`] for `d = 0`.
    pub fn from_point_direction(p: &[F; 3], d: &[F; 3]) -> Result<Self, LineError> {
        if all_zero(d) {
            return Err(LineError::ZeroVector(
                "the direction of a line must be non-zero".into(),
            ));
        }
        let q = [F::zero(), d[0].clone(), d[1].clone(), d[2].clone()];
        Self::from_points(&affine(p), &q)
    }

    /// The intersection of two planes `u, v`: `l = (a₄, a₅, a₆; a₁, a₂, a₃)` for
    /// `a = u ∧ v` (axis coordinates, Gruber (1.5)).
    ///
    /// # Errors
    /// [`LineError::CoincidentPlanes`] if `u ∧ v = 0`.
    pub fn from_planes(u: &[F; 4], v: &[F; 4]) -> Result<Self, LineError> {
        let a = wedge(u, v);
        let scale = scale_of(u) * scale_of(v);
        if a.iter().all(|x| is_small(x, scale)) {
            return Err(LineError::CoincidentPlanes(fmt_vec(u), fmt_vec(v)));
        }
        Ok(Line {
            coords: swap(&a),
            origin: LineOrigin::Planes(u.clone(), v.clone()),
        })
    }

    /// A line from six coordinates on the Klein quadric (Gruber (1.3)/(1.4)).
    ///
    /// # Errors
    /// [`LineError::ZeroVector`] for the zero vector, [`LineError::NotOnKleinQuadric`] if
    /// `l₁l₄ + l₂l₅ + l₃l₆ ≠ 0` (exactly, or beyond the `f64` tolerance).
    pub fn from_coords(l: [F; 6]) -> Result<Self, LineError> {
        if all_zero(&l) {
            return Err(LineError::ZeroVector(
                "Plücker coordinates must not all vanish (Gruber (1.4))".into(),
            ));
        }
        let k = klein_form(&l);
        let s = scale_of(&l);
        if !is_small(&k, s * s) {
            return Err(LineError::NotOnKleinQuadric {
                residual: crate::error::format_scalar(&k),
            });
        }
        Ok(Line {
            coords: l,
            origin: LineOrigin::Coordinates,
        })
    }

    /// A line from coordinates that lie on the Klein quadric by construction (no check).
    pub(crate) fn from_coords_unchecked(l: [F; 6]) -> Self {
        Line {
            coords: l,
            origin: LineOrigin::Coordinates,
        }
    }

    /// The Plücker coordinates `(l₁, …, l₆)`.
    pub fn coords(&self) -> &[F; 6] {
        &self.coords
    }

    /// How the line was given.
    pub fn origin(&self) -> &LineOrigin<F> {
        &self.origin
    }

    /// The axis (plane) coordinates `(l₄, l₅, l₆; l₁, l₂, l₃)` (Gruber (1.5)).
    pub fn axis_coords(&self) -> [F; 6] {
        swap(&self.coords)
    }

    /// The direction vector `(l₁, l₂, l₃)` (zero for a line at infinity).
    pub fn direction(&self) -> [F; 3] {
        [
            self.coords[0].clone(),
            self.coords[1].clone(),
            self.coords[2].clone(),
        ]
    }

    /// The moment vector `(l₄, l₅, l₆) = p × direction` for any affine point `p` of the line.
    pub fn moment(&self) -> [F; 3] {
        [
            self.coords[3].clone(),
            self.coords[4].clone(),
            self.coords[5].clone(),
        ]
    }

    /// `true` for a line in the plane at infinity (direction zero).
    pub fn is_at_infinity(&self) -> bool {
        let d = self.direction();
        let s = scale_of(&self.coords);
        d.iter().all(|x| is_small(x, s))
    }

    /// `l₁l₄ + l₂l₅ + l₃l₆` (zero for every line, Gruber (1.3)).
    pub fn klein_form(&self) -> F {
        klein_form(&self.coords)
    }

    /// The reciprocal product `Ω(self, other)` (Gruber (1.10)).
    pub fn reciprocal_product(&self, other: &Line<F>) -> F {
        reciprocal_product(&self.coords, &other.coords)
    }

    /// The incidence matrix `M(l)` of (1.7): `p ∈ l ⇔ M(l)p = 0`.
    pub fn incidence_matrix(&self) -> [[F; 4]; 4] {
        incidence_matrix(&self.coords)
    }

    /// The dual incidence matrix `M(l*)` built from the axis coordinates:
    /// `u ⊃ l ⇔ M(l*)u = 0`.
    pub fn plane_incidence_matrix(&self) -> [[F; 4]; 4] {
        incidence_matrix(&self.axis_coords())
    }

    fn tol_scale(&self, v: &[F]) -> f64 {
        scale_of(&self.coords) * scale_of(v)
    }

    /// `true` if the point lies on the line (`M(l)p = 0`, (1.7)).
    pub fn contains_point(&self, p: &[F; 4]) -> bool {
        let s = self.tol_scale(p);
        mat_vec(&self.incidence_matrix(), p)
            .iter()
            .all(|x| is_small(x, s))
    }

    /// `true` if the line lies in the plane (`M(l*)u = 0`).
    pub fn lies_in_plane(&self, u: &[F; 4]) -> bool {
        let s = self.tol_scale(u);
        mat_vec(&self.plane_incidence_matrix(), u)
            .iter()
            .all(|x| is_small(x, s))
    }

    /// The points `s₁, …, s₄` of the line in the coordinate planes `xᵢ = 0` (docs/math/lines-and-canal.md, "Plücker coordinates"); some
    /// may be zero.
    pub fn coordinate_plane_points(&self) -> [[F; 4]; 4] {
        coordinate_plane_points(&self.coords)
    }

    /// Two distinct points spanning the line: the pair `sᵢ, sⱼ` of docs/math/lines-and-canal.md, "Plücker coordinates" whose factor
    /// (`l₁, l₂, l₃, l₆, −l₅, l₄` for the pairs 12, 13, 14, 23, 24, 34) is largest in
    /// absolute value (non-zero, docs/math/lines-and-canal.md, Errata G23), so `sᵢ ∧ sⱼ = factor · l`.
    pub fn points(&self) -> ([F; 4], [F; 4]) {
        let s = self.coordinate_plane_points();
        let best = POINT_PAIRS
            .iter()
            .max_by(|a, b| {
                let x = self.coords[a.2].abs();
                let y = self.coords[b.2].abs();
                x.partial_cmp(&y).unwrap_or(core::cmp::Ordering::Equal)
            })
            .copied()
            .unwrap_or((0, 1, 0));
        (s[best.0].clone(), s[best.1].clone())
    }

    /// Two distinct planes through the line (the dual construction on the axis
    /// coordinates).
    pub fn planes(&self) -> ([F; 4], [F; 4]) {
        Line::from_coords_unchecked(self.axis_coords()).points()
    }

    /// The plane `(1 − s)e + s f` of the pencil of planes through the line, `(e, f)` =
    /// [`Self::planes`] (Gruber §1.1.6: the pencils `ε(u)`, `φ(v)` about the focal lines).
    pub fn pencil_plane(&self, s: &F) -> [F; 4] {
        let (e, f) = self.planes();
        core::array::from_fn(|i| (F::one() - s.clone()) * e[i].clone() + s.clone() * f[i].clone())
    }

    /// The point `(1 − s)p + s q` of the line, `(p, q)` = [`Self::points`].
    pub fn point_at(&self, s: &F) -> [F; 4] {
        let (p, q) = self.points();
        core::array::from_fn(|i| (F::one() - s.clone()) * p[i].clone() + s.clone() * q[i].clone())
    }

    /// The plane spanned by the line and a point not on it: `M(l)p` ((1.7)).
    ///
    /// # Errors
    /// [`LineError::PointOnLine`] if `p` lies on the line.
    pub fn join_point(&self, p: &[F; 4]) -> Result<[F; 4], LineError> {
        let u = mat_vec(&self.incidence_matrix(), p);
        let s = self.tol_scale(p);
        if u.iter().all(|x| is_small(x, s)) {
            return Err(LineError::PointOnLine(fmt_vec(p), fmt_vec(&self.coords)));
        }
        Ok(u)
    }

    /// The intersection point of the line with a plane not containing it: `M(l*)u`.
    ///
    /// # Errors
    /// [`LineError::LineInPlane`] if the line lies in the plane.
    pub fn meet_plane(&self, u: &[F; 4]) -> Result<[F; 4], LineError> {
        let p = mat_vec(&self.plane_incidence_matrix(), u);
        let s = self.tol_scale(u);
        if p.iter().all(|x| is_small(x, s)) {
            return Err(LineError::LineInPlane(fmt_vec(&self.coords), fmt_vec(u)));
        }
        Ok(p)
    }

    /// `true` if both coordinate vectors are proportional (the same line).
    pub fn same_line(&self, other: &Line<F>) -> bool {
        proportional(&self.coords, &other.coords)
    }

    /// `true` if the lines meet or are parallel (`Ω(g, h) = 0`, Gruber (1.10)).
    pub fn meets(&self, other: &Line<F>) -> bool {
        let s = scale_of(&self.coords) * scale_of(&other.coords);
        is_small(&self.reciprocal_product(other), s)
    }

    fn check_meeting(&self, other: &Line<F>) -> Result<(), LineError> {
        if self.same_line(other) {
            return Err(LineError::SameLine(fmt_vec(&self.coords)));
        }
        if !self.meets(other) {
            return Err(LineError::Skew(crate::error::format_scalar(
                &self.reciprocal_product(other),
            )));
        }
        Ok(())
    }

    /// The common point of two distinct meeting lines (a point at infinity for parallel
    /// lines): `M(g*)u` for a plane `u ⊃ h` with `u ⊅ g`.
    ///
    /// # Errors
    /// [`LineError::SameLine`] for equal lines, [`LineError::Skew`] for skew lines.
    pub fn intersection(&self, other: &Line<F>) -> Result<[F; 4], LineError> {
        self.check_meeting(other)?;
        let m = other.incidence_matrix();
        // exactly, every plane through `other` that does not contain `self` gives the
        // point (the first is taken); in f64 the plane most transverse to `self` (the
        // largest |p| / |u|), so that a plane nearly containing `self` does not amplify
        // the rounding of the coordinates
        let mut best: Option<([F; 4], f64)> = None;
        for i in 0..4 {
            let u = mat_vec(&m, &unit4(i));
            if all_zero(&u) {
                continue;
            }
            if let Ok(p) = self.meet_plane(&u) {
                if F::EXACT {
                    return Ok(p);
                }
                let q = scale_of(&p) / scale_of(&u);
                if best.as_ref().is_none_or(|b| q > b.1) {
                    best = Some((p, q));
                }
            }
        }
        best.map(|b| b.0)
            .ok_or_else(|| LineError::SameLine(fmt_vec(&self.coords)))
    }

    /// The common plane of two distinct meeting lines: `M(g)p` for a point `p ∈ h`, `p ∉ g`.
    ///
    /// # Errors
    /// [`LineError::SameLine`] for equal lines, [`LineError::Skew`] for skew lines.
    pub fn joining_plane(&self, other: &Line<F>) -> Result<[F; 4], LineError> {
        self.check_meeting(other)?;
        let m = other.plane_incidence_matrix();
        for i in 0..4 {
            let p = mat_vec(&m, &unit4(i));
            if let Ok(u) = self.join_point(&p) {
                if !all_zero(&p) {
                    return Ok(u);
                }
            }
        }
        Err(LineError::SameLine(fmt_vec(&self.coords)))
    }

    /// The polar line with respect to the absolute quadric `Ω: y₁² + y₂² + y₃² − y₄² = 0`
    /// of the ideal space of the cyclographic model: `h = E g` with
    /// `E = [[0, diag(−1, −1, 1)], [diag(1, 1, −1), 0]]` (Gruber (1.19), docs/math/lines-and-canal.md, "Complexes, congruences, reguli").
    /// Coordinates here are those of lines of the 3-space `ω: y₀ = 0` with points
    /// `(y₁, y₂, y₃, y₄)`.
    pub fn polar_omega(&self) -> Line<F> {
        let g = &self.coords;
        Line::from_coords_unchecked([
            -g[3].clone(),
            -g[4].clone(),
            g[5].clone(),
            g[0].clone(),
            g[1].clone(),
            -g[2].clone(),
        ])
    }

    /// The line with scalar type converted (e.g. to `f64` or into an extension field).
    pub fn map_scalar<G: Scalar>(&self, f: impl Fn(&F) -> G) -> Line<G> {
        let m4 = |v: &[F; 4]| [f(&v[0]), f(&v[1]), f(&v[2]), f(&v[3])];
        let origin = match &self.origin {
            LineOrigin::Coordinates => LineOrigin::Coordinates,
            LineOrigin::Points(p, q) => LineOrigin::Points(m4(p), m4(q)),
            LineOrigin::Planes(u, v) => LineOrigin::Planes(m4(u), m4(v)),
        };
        Line {
            coords: [
                f(&self.coords[0]),
                f(&self.coords[1]),
                f(&self.coords[2]),
                f(&self.coords[3]),
                f(&self.coords[4]),
                f(&self.coords[5]),
            ],
            origin,
        }
    }
}

/// The homogeneous point `(1, a)` of an affine point.
pub(crate) fn affine<F: Scalar>(a: &[F; 3]) -> [F; 4] {
    [F::one(), a[0].clone(), a[1].clone(), a[2].clone()]
}

/// Certificate that `M v = 0` (a point on a line, a plane through a line).
pub(crate) fn zero_vector_cert<F: Scalar>(property: String, v: &[F; 4], scale: f64) -> Certificate {
    let ok = v.iter().all(|x| is_small(x, scale));
    Certificate::decide(property, ok, F::EXACT, || {
        format!("residual {}", fmt_vec(v))
    })
}

/// Certificate that a coordinate vector lies on the Klein quadric.
pub(crate) fn klein_cert<F: Scalar>(name: &str, l: &[F; 6]) -> Certificate {
    let k = klein_form(l);
    let s = scale_of(l);
    Certificate::decide(
        format!("{name}: l₁l₄ + l₂l₅ + l₃l₆ = 0 (Klein quadric, Gruber (1.3))"),
        is_small(&k, s * s),
        F::EXACT,
        || crate::error::format_scalar(&k),
    )
}

impl<F: Scalar> Certified for Line<F> {
    /// The Klein quadric identity and the incidences with the defining points or planes
    /// (`M(l)p = M(l)q = 0`, `M(l*)u = M(l*)v = 0`).
    fn certify(&self) -> Vec<Certificate> {
        let mut out = vec![klein_cert("line", &self.coords)];
        let m = self.incidence_matrix();
        let mp = self.plane_incidence_matrix();
        match &self.origin {
            LineOrigin::Coordinates => {}
            LineOrigin::Points(p, q) => {
                for (name, x) in [("p", p), ("q", q)] {
                    out.push(zero_vector_cert(
                        format!("{name} ∈ p ∧ q: M(l){name} = 0 (Gruber (1.7))"),
                        &mat_vec(&m, x),
                        self.tol_scale(x),
                    ));
                }
            }
            LineOrigin::Planes(u, v) => {
                for (name, x) in [("u", u), ("v", v)] {
                    out.push(zero_vector_cert(
                        format!("line ⊂ plane {name}: M(l*){name} = 0 (dual of (1.7))"),
                        &mat_vec(&mp, x),
                        self.tol_scale(x),
                    ));
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }
    fn p4(a: [i64; 4]) -> [Rational; 4] {
        a.map(q)
    }

    #[test]
    fn wedge_and_klein() {
        let l = Line::from_points(&p4([1, 1, 2, 3]), &p4([2, -1, 0, 5])).expect("line");
        assert!(l.klein_form().is_zero());
        assert!(l.all_hold());
        assert!(l.contains_point(&p4([1, 1, 2, 3])));
        assert!(l.contains_point(&p4([3, 0, 2, 8])));
        assert!(!l.contains_point(&p4([1, 0, 0, 0])));
        assert!(matches!(
            Line::from_points(&p4([1, 1, 2, 3]), &p4([2, 2, 4, 6])),
            Err(LineError::CoincidentPoints(..))
        ));
    }

    #[test]
    fn planes_and_points_agree() {
        let l = Line::from_affine_points(&[q(0), q(1), q(2)], &[q(3), q(-1), q(1)]).expect("l");
        let (u, v) = l.planes();
        assert!(l.lies_in_plane(&u) && l.lies_in_plane(&v));
        let l2 = Line::from_planes(&u, &v).expect("planes");
        assert!(l2.same_line(&l));
        assert!(l2.all_hold());
        let (a, b) = l.points();
        assert!(l.contains_point(&a) && l.contains_point(&b));
        assert!(Line::from_points(&a, &b).expect("pts").same_line(&l));
    }

    #[test]
    fn meeting_lines() {
        let g = Line::from_affine_points(&[q(0), q(0), q(0)], &[q(1), q(0), q(0)]).expect("g");
        let h = Line::from_affine_points(&[q(1), q(0), q(0)], &[q(1), q(1), q(0)]).expect("h");
        let k = Line::from_affine_points(&[q(0), q(0), q(1)], &[q(0), q(1), q(1)]).expect("k");
        assert!(g.meets(&h) && !g.meets(&k));
        let x = g.intersection(&h).expect("meet");
        assert_eq!(x[1].clone() / x[0].clone(), q(1));
        let e = g.joining_plane(&h).expect("plane");
        assert!(g.lies_in_plane(&e) && h.lies_in_plane(&e));
        assert!(matches!(g.intersection(&k), Err(LineError::Skew(_))));
        assert!(matches!(g.intersection(&g), Err(LineError::SameLine(_))));
    }

    #[test]
    fn polar_is_involution_up_to_sign() {
        let g = Line::from_points(&p4([1, 2, 0, 1]), &p4([0, 1, 1, 3])).expect("g");
        let h = g.polar_omega();
        assert!(h.klein_form().is_zero());
        let gg = h.polar_omega();
        let neg: Vec<Rational> = g.coords().iter().map(|x| -x.clone()).collect();
        assert_eq!(gg.coords().to_vec(), neg);
    }
}
