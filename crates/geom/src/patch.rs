//! Rational tensor-product Bézier patches in homogeneous form.
//!
//! A patch of bidegree `(m, n)` in `Eᵈ` has `(m + 1)(n + 1)` homogeneous control
//! points `Pᵢⱼ` (weight first) and is `P(u, v) = Σᵢ Σⱼ Bᵢᵐ(u) Bⱼⁿ(v) Pᵢⱼ` on
//! `[0, 1]²`. Storage is flat, row-major in `i` (the `u` index):
//! `Pᵢⱼ` occupies `coords[(i(n+1) + j)(d+1) ..][.. d+1]`.
//!
//! Every curve algorithm applies in each direction: in `u` to whole rows (blocks of
//! `(n+1)(d+1)` coordinates, the control points of a curve whose "points" are rows),
//! in `v` to each row separately. All operations are exact over exact scalars;
//! `BezierPatch<f64>` additionally has allocation-free evaluation
//! ([`BezierPatch::eval_into`]).

use crate::certify;
use crate::curve::{
    check_finite, check_matrix, dehomogenize, dot, hornbez, mobius_blocks, BezierCurve,
};
use crate::error::GeomError;
use crate::polymap::{self, Bernstein2};
use rcagd_algebra::bernstein;
use rcagd_algebra::mpoly::MPoly;
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
    // -----------------------------------------------------------------------------
    // Construction and access
    // -----------------------------------------------------------------------------

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
        let Some(first) = first_row.first() else {
            return Err(GeomError::Empty("row 0 of the control net is empty".into()));
        };
        let len = first.len();
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

    /// From a net of Euclidean points and weights: `Pᵢⱼ = (wᵢⱼ, wᵢⱼ·pᵢⱼ)`.
    ///
    /// # Errors
    /// As [`Self::from_homogeneous`], and [`GeomError::Dimension`] if the weights do
    /// not have the shape of the net.
    pub fn from_points_weights(net: &[Vec<Vec<F>>], weights: &[Vec<F>]) -> Result<Self, GeomError> {
        if net.len() != weights.len() || net.iter().zip(weights).any(|(r, w)| r.len() != w.len()) {
            return Err(GeomError::Dimension(
                "the weights do not have the shape of the control net".into(),
            ));
        }
        let hom = net
            .iter()
            .zip(weights)
            .map(|(row, ws)| {
                row.iter()
                    .zip(ws)
                    .map(|(p, w)| {
                        let mut h = Vec::with_capacity(p.len() + 1);
                        h.push(w.clone());
                        h.extend(p.iter().map(|x| x.clone() * w.clone()));
                        h
                    })
                    .collect()
            })
            .collect();
        Self::from_homogeneous(hom)
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

    /// The ruled patch `P(u, v) = (1 − v) C₀(u) + v C₁(u)` of bidegree `(n, 1)` between
    /// two curves (the homogeneous blend: each `v`-line is the straight segment from
    /// `C₀(u)` to `C₁(u)`). Curves of different degree are elevated to the larger one.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if the curves have different dimensions.
    pub fn from_curves_ruled(c0: &BezierCurve<F>, c1: &BezierCurve<F>) -> Result<Self, GeomError> {
        if c0.dim() != c1.dim() {
            return Err(GeomError::Dimension(format!(
                "ruled patch between curves in dimensions {} and {}",
                c0.dim(),
                c1.dim()
            )));
        }
        let n = c0.degree().max(c1.degree());
        let (a, b) = (c0.elevate_to(n), c1.elevate_to(n));
        let coords = a
            .control_points()
            .zip(b.control_points())
            .flat_map(|(p, q)| p.iter().chain(q).cloned())
            .collect();
        Ok(BezierPatch {
            dim: c0.dim(),
            deg_u: n,
            deg_v: 1,
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

    /// Homogeneous control point `Pᵢⱼ`. Panics if out of range; see
    /// [`Self::get_control_point`] for the checked form.
    pub fn control_point(&self, i: usize, j: usize) -> &[F] {
        let s = self.dim + 1;
        let k = (i * (self.deg_v + 1) + j) * s;
        &self.coords[k..k + s]
    }

    /// Homogeneous control point `Pᵢⱼ`, `None` if out of range.
    pub fn get_control_point(&self, i: usize, j: usize) -> Option<&[F]> {
        if i > self.deg_u || j > self.deg_v {
            return None;
        }
        let s = self.dim + 1;
        let k = (i * (self.deg_v + 1) + j) * s;
        self.coords.get(k..k + s)
    }

    /// The flat homogeneous coordinates.
    pub fn coords(&self) -> &[F] {
        &self.coords
    }

    /// Number of coordinates in one row `Pᵢ₀, …, Pᵢₙ` (a block for `u`-operations).
    fn row_len(&self) -> usize {
        (self.deg_v + 1) * (self.dim + 1)
    }

    fn rows(&self) -> impl DoubleEndedIterator<Item = &[F]> {
        self.coords.chunks(self.row_len())
    }

    /// The weights, row-major (`(m+1)(n+1)` entries).
    pub fn weights(&self) -> Vec<F> {
        self.coordinate_bernstein(0)
    }

    /// The tensor Bernstein coefficients (row-major, `(m+1)(n+1)` entries) of
    /// homogeneous coordinate `k` (`0` = weight); empty if `k > dim`.
    pub fn coordinate_bernstein(&self, k: usize) -> Vec<F> {
        if k > self.dim {
            return Vec::new();
        }
        self.coords
            .chunks(self.dim + 1)
            .map(|p| p[k].clone())
            .collect()
    }

    /// The homogeneous coordinates as bivariate power-basis polynomials in `(u, v)`
    /// (variable 0 is `u`, variable 1 is `v`): the conversion `aᵢ = C(n,i) Δⁱb₀` of
    /// [`bernstein::from_bernstein`] in each direction.
    ///
    /// # Errors
    /// Only an algebra failure underneath ([`GeomError::Algebra`]).
    pub fn coordinate_polys(&self) -> Result<Vec<MPoly<F>>, GeomError> {
        let n = self.deg_v;
        (0..=self.dim)
            .map(|k| {
                let b = self.coordinate_bernstein(k);
                let in_u = bernstein::from_bernstein_blocks(&b, n + 1);
                let terms = in_u
                    .chunks(n + 1)
                    .enumerate()
                    .flat_map(|(i, row)| {
                        bernstein::from_bernstein_blocks(row, 1)
                            .into_iter()
                            .enumerate()
                            .map(move |(j, c)| (vec![i as u32, j as u32], c))
                    })
                    .filter(|(_, c)| !c.is_zero())
                    .collect();
                Ok(MPoly::from_terms(2, terms)?)
            })
            .collect()
    }

    // -----------------------------------------------------------------------------
    // Evaluation, iso-curves, derivatives
    // -----------------------------------------------------------------------------

    /// The iso-parameter curve `u = const`, `v ↦ P(u, v)` (degree `n`): de Casteljau in
    /// `u` on whole rows.
    pub fn iso_u(&self, u: &F) -> BezierCurve<F> {
        let coords = bernstein::eval_blocks(&self.coords, self.row_len(), u);
        self.curve(coords)
    }

    /// The iso-parameter curve `v = const`, `u ↦ P(u, v)` (degree `m`): de Casteljau in
    /// `v` on each row.
    pub fn iso_v(&self, v: &F) -> BezierCurve<F> {
        let s = self.dim + 1;
        let coords = self
            .rows()
            .flat_map(|row| bernstein::eval_blocks(row, s, v))
            .collect();
        self.curve(coords)
    }

    /// A curve from whole points of this patch.
    fn curve(&self, coords: Vec<F>) -> BezierCurve<F> {
        BezierCurve::from_flat_unchecked(self.dim, coords)
    }

    /// The four boundary curves as a closed loop: `v = 0` (`u` from 0 to 1), `u = 1`
    /// (`v` from 0 to 1), `v = 1` (`u` from 1 to 0), `u = 0` (`v` from 1 to 0).
    /// Their control points are the boundary rows and columns of the net.
    pub fn boundary_curves(&self) -> [BezierCurve<F>; 4] {
        let (zero, one) = (F::zero(), F::one());
        [
            self.iso_v(&zero),
            self.iso_u(&one),
            self.iso_v(&one).reverse(),
            self.iso_u(&zero).reverse(),
        ]
    }

    /// The homogeneous point `P(u, v)` (de Casteljau in `u` on rows, then in `v`).
    pub fn eval_homogeneous(&self, u: &F, v: &F) -> Vec<F> {
        self.iso_u(u).eval_homogeneous(v)
    }

    /// The Euclidean point `P(u, v)`.
    ///
    /// # Errors
    /// [`GeomError::Weight`] where the weight vanishes, [`GeomError::Parameter`] for a
    /// non-finite parameter.
    pub fn eval(&self, u: &F, v: &F) -> Result<Vec<F>, GeomError> {
        check_finite(u, "u")?;
        check_finite(v, "v")?;
        dehomogenize(&self.eval_homogeneous(u, v), || self.at(u, v))
    }

    fn at(&self, u: &F, v: &F) -> String {
        format!(
            "(u, v) = ({}, {})",
            certify::format_scalar(u),
            certify::format_scalar(v)
        )
    }

    /// The homogeneous partial derivative patch `∂ᵏP/∂uᵏ`, bidegree `(max(m−k, 0), n)`:
    /// `k` times `m (Pᵢ₊₁ⱼ − Pᵢⱼ)`.
    pub fn derivative_u(&self, k: usize) -> Self {
        (0..k).fold(self.clone(), |p, _| BezierPatch {
            dim: p.dim,
            deg_u: p.deg_u.saturating_sub(1),
            deg_v: p.deg_v,
            coords: bernstein::derivative_blocks(&p.coords, p.row_len()),
        })
    }

    /// The homogeneous partial derivative patch `∂ᵏP/∂vᵏ`, bidegree `(m, max(n−k, 0))`.
    pub fn derivative_v(&self, k: usize) -> Self {
        let s = self.dim + 1;
        (0..k).fold(self.clone(), |p, _| {
            let coords = p
                .rows()
                .flat_map(|row| bernstein::derivative_blocks(row, s))
                .collect();
            BezierPatch {
                dim: p.dim,
                deg_u: p.deg_u,
                deg_v: p.deg_v.saturating_sub(1),
                coords,
            }
        })
    }

    /// The homogeneous partial derivative `∂^{ku+kv} P / ∂u^{ku} ∂v^{kv}` at `(u, v)`.
    pub fn partial_homogeneous(&self, u: &F, v: &F, ku: usize, kv: usize) -> Vec<F> {
        self.derivative_u(ku)
            .derivative_v(kv)
            .eval_homogeneous(u, v)
    }

    /// The table `x^{(a,b)}(u, v)`, `a ≤ ku`, `b ≤ kv`, of Euclidean partial derivatives
    /// of `x = X/w` by the bivariate Leibniz rule for `X = w·x`:
    /// `x^{(a,b)} = (X^{(a,b)} − Σ_{(i,j) ≠ (0,0)} C(a,i) C(b,j) w^{(i,j)} x^{(a−i,b−j)}) / w`.
    /// `table[a][b]` is `∂^{a+b}x/∂uᵃ∂vᵇ`.
    ///
    /// # Errors
    /// [`GeomError::Weight`] where the weight vanishes, [`GeomError::Parameter`] for a
    /// non-finite parameter.
    pub fn partials_euclidean(
        &self,
        u: &F,
        v: &F,
        ku: usize,
        kv: usize,
    ) -> Result<Vec<Vec<Vec<F>>>, GeomError> {
        check_finite(u, "u")?;
        check_finite(v, "v")?;
        let mut hom: Vec<Vec<Vec<F>>> = Vec::with_capacity(ku + 1);
        let mut pu = self.clone();
        for a in 0..=ku {
            let mut row = Vec::with_capacity(kv + 1);
            let mut puv = pu.clone();
            for b in 0..=kv {
                row.push(puv.eval_homogeneous(u, v));
                if b < kv {
                    puv = puv.derivative_v(1);
                }
            }
            hom.push(row);
            if a < ku {
                pu = pu.derivative_u(1);
            }
        }
        let x00 = dehomogenize(&hom[0][0], || self.at(u, v))?;
        let inv_w = F::one() / hom[0][0][0].clone();
        let mut table: Vec<Vec<Vec<F>>> = vec![vec![Vec::new(); kv + 1]; ku + 1];
        table[0][0] = x00;
        for a in 0..=ku {
            let ca: Vec<F> = bernstein::binomial_row(a);
            for b in 0..=kv {
                if a == 0 && b == 0 {
                    continue;
                }
                let cb: Vec<F> = bernstein::binomial_row(b);
                let mut x: Vec<F> = hom[a][b][1..].to_vec();
                for i in 0..=a {
                    for j in 0..=b {
                        if i == 0 && j == 0 {
                            continue;
                        }
                        let f = ca[i].clone() * cb[j].clone() * hom[i][j][0].clone();
                        if f.is_zero() {
                            continue;
                        }
                        for (xq, yq) in x.iter_mut().zip(&table[a - i][b - j]) {
                            *xq -= f.clone() * yq.clone();
                        }
                    }
                }
                table[a][b] = x.into_iter().map(|c| c * inv_w.clone()).collect();
            }
        }
        Ok(table)
    }

    /// The Euclidean partial derivative `∂^{ku+kv} x / ∂u^{ku} ∂v^{kv}` at `(u, v)`.
    ///
    /// # Errors
    /// As [`Self::partials_euclidean`].
    pub fn partial_euclidean(
        &self,
        u: &F,
        v: &F,
        ku: usize,
        kv: usize,
    ) -> Result<Vec<F>, GeomError> {
        let mut table = self.partials_euclidean(u, v, ku, kv)?;
        table
            .pop()
            .and_then(|mut row| row.pop())
            .ok_or_else(|| GeomError::Empty("no derivatives".into()))
    }

    // -----------------------------------------------------------------------------
    // Representation changes that keep the patch
    // -----------------------------------------------------------------------------

    /// Degree elevation in `u` by `r` (rows are combined as in curve elevation).
    pub fn elevate_u(&self, r: usize) -> Self {
        BezierPatch {
            dim: self.dim,
            deg_u: self.deg_u + r,
            deg_v: self.deg_v,
            coords: bernstein::elevate_blocks(&self.coords, self.row_len(), r),
        }
    }

    /// Degree elevation in `v` by `r` (each row elevated as a curve).
    pub fn elevate_v(&self, r: usize) -> Self {
        let s = self.dim + 1;
        self.map_rows(self.deg_v + r, |row| bernstein::elevate_blocks(row, s, r))
    }

    /// Degree elevation by `(ru, rv)`.
    pub fn elevate(&self, ru: usize, rv: usize) -> Self {
        self.elevate_u(ru).elevate_v(rv)
    }

    /// Applies a per-row operation producing rows of `new_deg_v + 1` points.
    fn map_rows(&self, new_deg_v: usize, f: impl Fn(&[F]) -> Vec<F>) -> Self {
        BezierPatch {
            dim: self.dim,
            deg_u: self.deg_u,
            deg_v: new_deg_v,
            coords: self.rows().flat_map(f).collect(),
        }
    }

    /// Fallible form of [`Self::map_rows`].
    fn try_map_rows(
        &self,
        f: impl Fn(&[F]) -> Result<Vec<F>, GeomError>,
    ) -> Result<Self, GeomError> {
        let mut coords = Vec::with_capacity(self.coords.len());
        for row in self.rows() {
            coords.extend(f(row)?);
        }
        Ok(BezierPatch {
            dim: self.dim,
            deg_u: self.deg_u,
            deg_v: self.deg_v,
            coords,
        })
    }

    /// Subdivision at `u = t`: the patches on `[0, t] × [0, 1]` and `[t, 1] × [0, 1]`,
    /// reparametrized to `[0, 1]²`. Any finite `t` (extrapolation outside `[0, 1]`).
    ///
    /// # Errors
    /// [`GeomError::Parameter`] for a non-finite `t`.
    pub fn subdivide_u(&self, t: &F) -> Result<(Self, Self), GeomError> {
        check_finite(t, "subdivision parameter")?;
        let (l, r) = bernstein::subdivide_blocks(&self.coords, self.row_len(), t);
        Ok((self.with_coords(l), self.with_coords(r)))
    }

    /// Subdivision at `v = t`: the patches on `[0, 1] × [0, t]` and `[0, 1] × [t, 1]`.
    ///
    /// # Errors
    /// [`GeomError::Parameter`] for a non-finite `t`.
    pub fn subdivide_v(&self, t: &F) -> Result<(Self, Self), GeomError> {
        check_finite(t, "subdivision parameter")?;
        let s = self.dim + 1;
        let (mut l, mut r) = (Vec::new(), Vec::new());
        for row in self.rows() {
            let (a, b) = bernstein::subdivide_blocks(row, s, t);
            l.extend(a);
            r.extend(b);
        }
        Ok((self.with_coords(l), self.with_coords(r)))
    }

    fn with_coords(&self, coords: Vec<F>) -> Self {
        BezierPatch {
            dim: self.dim,
            deg_u: self.deg_u,
            deg_v: self.deg_v,
            coords,
        }
    }

    /// Möbius reparametrization in `u`, `u = (as + b)/(cs + d)`, keeping the degree
    /// (see [`BezierCurve::reparametrize_mobius`]).
    ///
    /// # Errors
    /// [`GeomError::Parameter`] if `ad − bc = 0` or a coefficient is not finite.
    pub fn reparametrize_mobius_u(&self, a: &F, b: &F, c: &F, d: &F) -> Result<Self, GeomError> {
        Ok(self.with_coords(mobius_blocks(&self.coords, self.row_len(), [a, b, c, d])?))
    }

    /// Möbius reparametrization in `v`, `v = (as + b)/(cs + d)`, keeping the degree.
    ///
    /// # Errors
    /// [`GeomError::Parameter`] if `ad − bc = 0` or a coefficient is not finite.
    pub fn reparametrize_mobius_v(&self, a: &F, b: &F, c: &F, d: &F) -> Result<Self, GeomError> {
        let s = self.dim + 1;
        self.try_map_rows(|row| mobius_blocks(row, s, [a, b, c, d]))
    }

    /// The affine reparametrization of `u` to `[a, b]`: `Q(s, v) = P(a + (b−a)s, v)`.
    ///
    /// # Errors
    /// [`GeomError::Parameter`] if `a = b` or an end is not finite.
    pub fn restrict_u(&self, a: &F, b: &F) -> Result<Self, GeomError> {
        check_interval(a, b)?;
        self.reparametrize_mobius_u(&(b.clone() - a.clone()), a, &F::zero(), &F::one())
    }

    /// The affine reparametrization of `v` to `[c, d]`.
    ///
    /// # Errors
    /// [`GeomError::Parameter`] if `c = d` or an end is not finite.
    pub fn restrict_v(&self, c: &F, d: &F) -> Result<Self, GeomError> {
        check_interval(c, d)?;
        self.reparametrize_mobius_v(&(d.clone() - c.clone()), c, &F::zero(), &F::one())
    }

    /// The restriction to `[a, b] × [c, d]`, reparametrized to `[0, 1]²`.
    ///
    /// # Errors
    /// [`GeomError::Parameter`] for an empty interval or a non-finite end.
    pub fn restrict(&self, a: &F, b: &F, c: &F, d: &F) -> Result<Self, GeomError> {
        self.restrict_u(a, b)?.restrict_v(c, d)
    }

    /// `Q(u, v) = P(1 − u, v)` (rows in reverse order).
    pub fn reverse_u(&self) -> Self {
        self.with_coords(self.rows().rev().flatten().cloned().collect())
    }

    /// `Q(u, v) = P(u, 1 − v)` (each row reversed).
    pub fn reverse_v(&self) -> Self {
        let s = self.dim + 1;
        self.map_rows(self.deg_v, |row| {
            row.chunks(s).rev().flatten().cloned().collect()
        })
    }

    /// `Q(u, v) = P(v, u)`: the net transposed, bidegree `(n, m)`.
    pub fn transpose(&self) -> Self {
        let s = self.dim + 1;
        let (m, n) = (self.deg_u, self.deg_v);
        let mut coords = Vec::with_capacity(self.coords.len());
        for j in 0..=n {
            for i in 0..=m {
                let k = (i * (n + 1) + j) * s;
                coords.extend_from_slice(&self.coords[k..k + s]);
            }
        }
        BezierPatch {
            dim: self.dim,
            deg_u: n,
            deg_v: m,
            coords,
        }
    }

    /// Maps every coordinate through `f`.
    pub fn map_scalar<G: Scalar>(&self, f: impl Fn(&F) -> G) -> BezierPatch<G> {
        BezierPatch {
            dim: self.dim,
            deg_u: self.deg_u,
            deg_v: self.deg_v,
            coords: self.coords.iter().map(f).collect(),
        }
    }

    /// The nearest `f64` patch.
    pub fn to_f64(&self) -> BezierPatch<f64> {
        self.map_scalar(Scalar::to_f64)
    }

    // -----------------------------------------------------------------------------
    // Maps
    // -----------------------------------------------------------------------------

    /// The image under `X ↦ M X` (`d' + 1` rows of length `d + 1`); bidegree unchanged.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] for rows of the wrong length or fewer than two rows.
    pub fn apply_projective(&self, matrix: &[Vec<F>]) -> Result<Self, GeomError> {
        check_matrix(matrix, self.dim + 1, false)?;
        let coords = self
            .coords
            .chunks(self.dim + 1)
            .flat_map(|p| matrix.iter().map(move |row| dot(row, p)))
            .collect();
        Ok(BezierPatch {
            dim: matrix.len() - 1,
            deg_u: self.deg_u,
            deg_v: self.deg_v,
            coords,
        })
    }

    /// The image under a homogeneous polynomial map of degree `k`, bidegree
    /// `(k·m, k·n)` exactly, by tensor Bernstein products (Jüttler;
    /// docs/math/quadrics.md, "Curves and patches under δ"); `image.eval_homogeneous(u, v) = F(P(u, v))` identically.
    ///
    /// # Errors
    /// As [`BezierCurve::apply_polymap`].
    pub fn apply_polymap(&self, map: &[MPoly<F>]) -> Result<Self, GeomError> {
        let k = polymap::homogeneous_degree(map, self.dim + 1)?;
        let images = polymap::apply_to_bernstein(map, k, self.coordinate_columns())?;
        Ok(Self::from_coordinate_columns(
            &images,
            (k * self.deg_u, k * self.deg_v),
        ))
    }

    /// The tensor Bernstein coefficients (bidegree `(2m, 2n)`, row-major) of the
    /// quadratic form `Xᵀ Q X` on the patch (`Q` is `(d+1)×(d+1)`, weight first).
    ///
    /// # Errors
    /// [`GeomError::Dimension`] unless `Q` is `(d+1)×(d+1)`.
    pub fn quadratic_form(&self, q: &[Vec<F>]) -> Result<Vec<F>, GeomError> {
        check_matrix(q, self.dim + 1, true)?;
        polymap::quadratic_form_bernstein(q, &self.coordinate_columns())
    }

    /// The homogeneous coordinates as tensor Bernstein polynomials.
    pub(crate) fn coordinate_columns(&self) -> Vec<Bernstein2<F>> {
        (0..=self.dim)
            .map(|a| Bernstein2 {
                coeffs: self.coordinate_bernstein(a),
                degree: (self.deg_u, self.deg_v),
            })
            .collect()
    }

    fn from_coordinate_columns(columns: &[Vec<F>], (m, n): (usize, usize)) -> Self {
        let s = columns.len();
        let points = (m + 1) * (n + 1);
        let mut coords = Vec::with_capacity(s * points);
        for i in 0..points {
            coords.extend(
                columns
                    .iter()
                    .map(|c| c.get(i).cloned().unwrap_or_else(F::zero)),
            );
        }
        BezierPatch {
            dim: s.saturating_sub(1).max(1),
            deg_u: m,
            deg_v: n,
            coords,
        }
    }

    /// `true` if both patches are the same rational parametrization: `P(u,v) ∥ Q(u,v)`
    /// as polynomial vectors (all cross terms vanish; see
    /// [`BezierCurve::same_parametrization`]). Covers degree elevation and scaling.
    pub fn same_parametrization(&self, other: &Self) -> bool {
        certify::patches_agree(self, other).is_ok_and(|c| c.holds)
    }
}

/// `Err` unless `[a, b]` is a non-empty interval.
fn check_interval<F: Scalar>(a: &F, b: &F) -> Result<(), GeomError> {
    if a == b {
        Err(GeomError::Parameter(format!(
            "cannot restrict to the empty interval [{0}, {0}]",
            certify::format_scalar(a)
        )))
    } else {
        Ok(())
    }
}

impl BezierPatch<f64> {
    /// Writes the homogeneous point `P(u, v)` into `out` (length `d + 1`): `hornbez` in
    /// `v` on each row and, nested, in `u` over the rows. No heap allocation for
    /// `d ≤ 7`.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if `out.len() ≠ d + 1`.
    pub fn eval_homogeneous_into(&self, u: f64, v: f64, out: &mut [f64]) -> Result<(), GeomError> {
        let s = self.dim + 1;
        if out.len() != s {
            return Err(GeomError::Dimension(format!(
                "output buffer has {} entries, the patch has {s} homogeneous coordinates",
                out.len()
            )));
        }
        let mut stack = [0.0; 8];
        let mut heap = Vec::new();
        let tmp: &mut [f64] = if s <= stack.len() {
            &mut stack[..s]
        } else {
            heap.resize(s, 0.0);
            &mut heap
        };
        let (m, n, len) = (self.deg_u, self.deg_v, self.row_len());
        let row = |i: usize| self.coords.get(i * len..(i + 1) * len).unwrap_or(&[]);
        hornbez(row(0), n + 1, v, out);
        if m == 0 {
            return Ok(());
        }
        let w = 1.0 - u;
        out.iter_mut().for_each(|o| *o *= w);
        let (mut fact, mut binom) = (1.0, 1.0);
        for i in 1..m {
            fact *= u;
            binom = binom * (m - i + 1) as f64 / i as f64;
            hornbez(row(i), n + 1, v, tmp);
            for (o, x) in out.iter_mut().zip(tmp.iter()) {
                *o = (*o + fact * binom * x) * w;
            }
        }
        fact *= u;
        hornbez(row(m), n + 1, v, tmp);
        for (o, x) in out.iter_mut().zip(tmp.iter()) {
            *o += fact * x;
        }
        Ok(())
    }

    /// Writes the Euclidean point `P(u, v)` into `out` (length `d`).
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if `out.len() ≠ d`, [`GeomError::Weight`] where the
    /// weight vanishes.
    pub fn eval_into(&self, u: f64, v: f64, out: &mut [f64]) -> Result<(), GeomError> {
        if out.len() != self.dim {
            return Err(GeomError::Dimension(format!(
                "output buffer has {} entries, the patch has dimension {}",
                out.len(),
                self.dim
            )));
        }
        let s = self.dim + 1;
        let mut stack = [0.0; 8];
        let mut heap = Vec::new();
        let h: &mut [f64] = if s <= stack.len() {
            &mut stack[..s]
        } else {
            heap.resize(s, 0.0);
            &mut heap
        };
        self.eval_homogeneous_into(u, v, h)?;
        let w = h[0];
        if w == 0.0 || !w.is_finite() {
            return Err(GeomError::Weight(format!(
                "point at infinity (weight 0) at (u, v) = ({u}, {v})"
            )));
        }
        for (o, x) in out.iter_mut().zip(&h[1..]) {
            *o = x / w;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }
    fn pts(v: &[&[i64]]) -> Vec<Vec<Rational>> {
        v.iter()
            .map(|p| p.iter().map(|&x| Rational::from(x)).collect())
            .collect()
    }

    /// A rational biquadratic-by-linear patch in E³.
    fn sample() -> BezierPatch<Rational> {
        BezierPatch::from_homogeneous(vec![
            pts(&[&[1, 0, 0, 0], &[2, 0, 2, 2]]),
            pts(&[&[1, 1, 0, 1], &[1, 1, 1, 0]]),
            pts(&[&[2, 4, 0, 2], &[1, 1, 1, 1]]),
        ])
        .expect("valid")
    }

    #[test]
    fn evaluation_through_iso_curves() {
        let p = sample();
        assert_eq!(p.degree(), (2, 1));
        let (u, v) = (q(1, 3), q(3, 4));
        // Direct tensor sum Σ Bᵢ²(u) Bⱼ¹(v) Pᵢⱼ.
        let bu = bernstein::basis(2, &u);
        let bv = bernstein::basis(1, &v);
        let mut direct = vec![q(0, 1); 4];
        for (i, bi) in bu.iter().enumerate() {
            for (j, bj) in bv.iter().enumerate() {
                let f = bi.clone() * bj.clone();
                for (d, x) in direct.iter_mut().zip(p.control_point(i, j)) {
                    *d += f.clone() * x.clone();
                }
            }
        }
        assert_eq!(p.eval_homogeneous(&u, &v), direct);
        assert_eq!(p.iso_v(&v).eval_homogeneous(&u), direct);
        assert_eq!(p.get_control_point(3, 0), None);
        assert_eq!(p.get_control_point(2, 1), Some(p.control_point(2, 1)));
    }

    #[test]
    fn derivatives_and_leibniz_table() {
        let p = sample();
        let (u, v) = (q(1, 2), q(1, 5));
        // ∂/∂u by the hodograph equals the power-basis partial.
        let polys = p.coordinate_polys().expect("converts");
        let at = [u.clone(), v.clone()];
        let du: Vec<Rational> = polys
            .iter()
            .map(|f| f.partial(0).eval(&at).expect("2 vars"))
            .collect();
        assert_eq!(p.partial_homogeneous(&u, &v, 1, 0), du);
        assert_eq!(p.derivative_u(3).degree(), (0, 1));
        let table = p.partials_euclidean(&u, &v, 2, 1).expect("w ≠ 0");
        assert_eq!(table.len(), 3);
        assert_eq!(table[0][0], p.eval(&u, &v).expect("w ≠ 0"));
        // x_v by the quotient rule.
        let h = p.eval_homogeneous(&u, &v);
        let hv = p.partial_homogeneous(&u, &v, 0, 1);
        let xv: Vec<Rational> = (1..4)
            .map(|k| {
                (hv[k].clone() * h[0].clone() - h[k].clone() * hv[0].clone())
                    / (h[0].clone() * h[0].clone())
            })
            .collect();
        assert_eq!(table[0][1], xv);
    }

    #[test]
    fn ruled_patch_and_boundaries() {
        let c0 = BezierCurve::from_homogeneous(pts(&[&[1, 0, 0], &[1, 1, 1], &[2, 4, 0]]))
            .expect("valid");
        let c1 = BezierCurve::from_homogeneous(pts(&[&[1, 0, 3], &[3, 6, 3]])).expect("valid");
        let r = BezierPatch::from_curves_ruled(&c0, &c1).expect("same dim");
        assert_eq!(r.degree(), (2, 1));
        assert!(r.iso_v(&q(0, 1)).same_parametrization(&c0));
        assert!(r.iso_v(&q(1, 1)).same_parametrization(&c1));
        let [b0, b1, b2, b3] = r.boundary_curves();
        assert_eq!(b0, c0);
        assert_eq!(b1.control_point(0), c0.control_point(2));
        assert_eq!(b2, c1.elevate(1).reverse());
        assert_eq!(b3.control_point(1), c0.control_point(0));
        let c3 = BezierCurve::from_homogeneous(pts(&[&[1, 0, 0, 0]])).expect("valid");
        assert!(BezierPatch::from_curves_ruled(&c0, &c3).is_err());
    }

    #[test]
    fn subdivision_elevation_and_same_parametrization() {
        let p = sample();
        let (a, b) = p.subdivide_v(&q(1, 3)).expect("finite");
        assert_eq!(a, p.restrict_v(&q(0, 1), &q(1, 3)).expect("non-empty"));
        assert_eq!(
            b.eval_homogeneous(&q(0, 1), &q(0, 1)),
            p.eval_homogeneous(&q(0, 1), &q(1, 3))
        );
        let e = p.elevate(1, 2);
        assert_eq!(e.degree(), (3, 3));
        assert!(e.same_parametrization(&p));
        assert!(!p.same_parametrization(&p.reverse_u()));
        assert_eq!(p.transpose().transpose(), p);
        let m = p
            .reparametrize_mobius_u(&q(1, 1), &q(0, 1), &q(1, 1), &q(1, 1))
            .expect("invertible");
        // u = s/(s + 1): s = 1 ↦ u = 1/2.
        assert_eq!(
            m.eval(&q(1, 1), &q(1, 4)).ok(),
            p.eval(&q(1, 2), &q(1, 4)).ok()
        );
    }

    #[test]
    fn f64_fast_path_and_maps() {
        let p = sample();
        let f = p.to_f64();
        let mut h = [0.0; 4];
        f.eval_homogeneous_into(0.25, 0.5, &mut h).expect("sized");
        let exact = p.eval_homogeneous(&q(1, 4), &q(1, 2));
        for (a, b) in h.iter().zip(&exact) {
            assert!((a - Scalar::to_f64(b)).abs() < 1e-12);
        }
        assert!(f.eval_homogeneous_into(0.25, 0.5, &mut [0.0; 3]).is_err());
        let swap = pts(&[&[1, 0, 0, 0], &[0, 0, 1, 0], &[0, 1, 0, 0], &[0, 0, 0, 1]]);
        let s = p.apply_projective(&swap).expect("4×4");
        let e = p.eval(&q(1, 4), &q(1, 2)).expect("w ≠ 0");
        assert_eq!(
            s.eval(&q(1, 4), &q(1, 2)).ok(),
            Some(vec![e[1].clone(), e[0].clone(), e[2].clone()])
        );
        let sphere = pts(&[&[-1, 0, 0, 0], &[0, 1, 0, 0], &[0, 0, 1, 0], &[0, 0, 0, 1]]);
        assert_eq!(p.quadratic_form(&sphere).expect("4×4").len(), 5 * 3);
        assert!(p.quadratic_form(&sphere[..3]).is_err());
    }
}
