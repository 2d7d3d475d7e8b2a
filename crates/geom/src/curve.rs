//! Rational Bézier curves in homogeneous form.
//!
//! A curve of degree `n` in `Eᵈ` has `n + 1` homogeneous control points
//! `Pᵢ = (wᵢ, wᵢxᵢ, …)` of length `d + 1` (weight first) and is
//! `P(t) = Σ Bᵢⁿ(t) Pᵢ`, `Bᵢⁿ(t) = C(n,i) (1−t)ⁿ⁻ⁱ tⁱ`, on `t ∈ [0, 1]`;
//! its Euclidean point is `(P₁/P₀, …, P_d/P₀)`.
//! Storage is flat: control point `i` occupies `coords[i(d+1) .. (i+1)(d+1)]`.

use crate::error::GeomError;
use rcagd_algebra::Scalar;

/// A rational Bézier curve with homogeneous control points (weight first).
#[derive(Debug, Clone, PartialEq)]
pub struct BezierCurve<F> {
    /// Euclidean dimension `d` (homogeneous points have `d + 1` coordinates).
    dim: usize,
    /// Flat homogeneous control points, `(degree + 1) · (dim + 1)` entries.
    coords: Vec<F>,
}

impl<F: Scalar> BezierCurve<F> {
    /// From homogeneous control points `(w, wx, wy, …)`.
    ///
    /// # Errors
    /// [`GeomError::Empty`] for no points or zero-length points, [`GeomError::Dimension`]
    /// when the points differ in length.
    pub fn from_homogeneous(points: Vec<Vec<F>>) -> Result<Self, GeomError> {
        let first = points
            .first()
            .ok_or_else(|| GeomError::Empty("a Bézier curve needs at least one control point".into()))?;
        let len = first.len();
        if len < 2 {
            return Err(GeomError::Dimension(
                "homogeneous points need a weight and at least one coordinate".into(),
            ));
        }
        if let Some((i, p)) = points.iter().enumerate().find(|(_, p)| p.len() != len) {
            return Err(GeomError::Dimension(format!(
                "control point {i} has {} coordinates, point 0 has {len}",
                p.len()
            )));
        }
        Ok(BezierCurve {
            dim: len - 1,
            coords: points.into_iter().flatten().collect(),
        })
    }

    /// From Euclidean control points and weights: `Pᵢ = (wᵢ, wᵢ·pᵢ)`.
    ///
    /// # Errors
    /// As [`Self::from_homogeneous`], and [`GeomError::Dimension`] when the number of
    /// weights differs from the number of points.
    pub fn from_points_weights(points: &[Vec<F>], weights: &[F]) -> Result<Self, GeomError> {
        if points.len() != weights.len() {
            return Err(GeomError::Dimension(format!(
                "{} points but {} weights",
                points.len(),
                weights.len()
            )));
        }
        let hom = points
            .iter()
            .zip(weights)
            .map(|(p, w)| {
                let mut h = Vec::with_capacity(p.len() + 1);
                h.push(w.clone());
                h.extend(p.iter().map(|x| x.clone() * w.clone()));
                h
            })
            .collect();
        Self::from_homogeneous(hom)
    }

    /// A polynomial (integral) curve: all weights one.
    pub fn from_points(points: &[Vec<F>]) -> Result<Self, GeomError> {
        let w = vec![F::one(); points.len()];
        Self::from_points_weights(points, &w)
    }

    /// From a flat array of homogeneous coordinates with the given Euclidean dimension.
    pub fn from_flat(dim: usize, coords: Vec<F>) -> Result<Self, GeomError> {
        if dim == 0 {
            return Err(GeomError::Dimension("dimension must be at least 1".into()));
        }
        if coords.is_empty() || coords.len() % (dim + 1) != 0 {
            return Err(GeomError::Dimension(format!(
                "{} coordinates do not form points of length {}",
                coords.len(),
                dim + 1
            )));
        }
        Ok(BezierCurve { dim, coords })
    }

    /// Euclidean dimension.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Degree (number of control points − 1).
    pub fn degree(&self) -> usize {
        self.coords.len() / (self.dim + 1) - 1
    }

    /// Homogeneous control point `i` (weight first). Panics if `i > degree`.
    pub fn control_point(&self, i: usize) -> &[F] {
        let s = self.dim + 1;
        &self.coords[i * s..(i + 1) * s]
    }

    /// All homogeneous control points.
    pub fn control_points(&self) -> impl Iterator<Item = &[F]> {
        self.coords.chunks(self.dim + 1)
    }

    /// The flat homogeneous coordinates.
    pub fn coords(&self) -> &[F] {
        &self.coords
    }
}
