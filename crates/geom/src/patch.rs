//! Rational tensor-product Bézier patches in homogeneous form.
//!
//! A patch of bidegree `(m, n)` in `Eᵈ` has `(m + 1)(n + 1)` homogeneous control
//! points `Pᵢⱼ` (weight first) and is `P(u, v) = Σᵢ Σⱼ Bᵢᵐ(u) Bⱼⁿ(v) Pᵢⱼ` on
//! `[0, 1]²`. Storage is flat, row-major in `i` (the `u` index):
//! `Pᵢⱼ` occupies `coords[(i(n+1) + j)(d+1) ..][.. d+1]`.

use crate::error::GeomError;
use rcagd_algebra::Scalar;

/// A rational tensor-product Bézier patch with homogeneous control points.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierPatch<F> {
    dim: usize,
    deg_u: usize,
    deg_v: usize,
    coords: Vec<F>,
}

impl<F: Scalar> BezierPatch<F> {
    /// From a net of homogeneous control points: `net[i][j]` is `Pᵢⱼ`
    /// (`i` along `u`, `j` along `v`).
    ///
    /// # Errors
    /// [`GeomError::Empty`] for an empty net or row, [`GeomError::Dimension`] when rows
    /// differ in length or points differ in dimension.
    pub fn from_homogeneous(net: Vec<Vec<Vec<F>>>) -> Result<Self, GeomError> {
        let first_row = net
            .first()
            .ok_or_else(|| GeomError::Empty("a Bézier patch needs at least one row".into()))?;
        let cols = first_row.len();
        if cols == 0 {
            return Err(GeomError::Empty("row 0 of the control net is empty".into()));
        }
        let len = first_row[0].len();
        if len < 2 {
            return Err(GeomError::Dimension(
                "homogeneous points need a weight and at least one coordinate".into(),
            ));
        }
        for (i, row) in net.iter().enumerate() {
            if row.len() != cols {
                return Err(GeomError::Dimension(format!(
                    "row {i} has {} points, row 0 has {cols}",
                    row.len()
                )));
            }
            if let Some((j, p)) = row.iter().enumerate().find(|(_, p)| p.len() != len) {
                return Err(GeomError::Dimension(format!(
                    "control point ({i}, {j}) has {} coordinates, point (0, 0) has {len}",
                    p.len()
                )));
            }
        }
        Ok(BezierPatch {
            dim: len - 1,
            deg_u: net.len() - 1,
            deg_v: cols - 1,
            coords: net.into_iter().flatten().flatten().collect(),
        })
    }

    /// From a flat array (layout as in the module docs).
    pub fn from_flat(
        dim: usize,
        deg_u: usize,
        deg_v: usize,
        coords: Vec<F>,
    ) -> Result<Self, GeomError> {
        if dim == 0 {
            return Err(GeomError::Dimension("dimension must be at least 1".into()));
        }
        let want = (deg_u + 1) * (deg_v + 1) * (dim + 1);
        if coords.len() != want {
            return Err(GeomError::Dimension(format!(
                "bidegree ({deg_u}, {deg_v}) in dimension {dim} needs {want} coordinates, got {}",
                coords.len()
            )));
        }
        Ok(BezierPatch {
            dim,
            deg_u,
            deg_v,
            coords,
        })
    }

    /// Euclidean dimension.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Bidegree `(m, n)`.
    pub fn degree(&self) -> (usize, usize) {
        (self.deg_u, self.deg_v)
    }

    /// Homogeneous control point `Pᵢⱼ`. Panics if out of range.
    pub fn control_point(&self, i: usize, j: usize) -> &[F] {
        let s = self.dim + 1;
        let k = (i * (self.deg_v + 1) + j) * s;
        &self.coords[k..k + s]
    }

    /// The flat homogeneous coordinates.
    pub fn coords(&self) -> &[F] {
        &self.coords
    }
}
