//! Rational Bézier curves in homogeneous form.
//!
//! A curve of degree `n` in `Eᵈ` has `n + 1` homogeneous control points
//! `Pᵢ = (wᵢ, wᵢxᵢ, …)` of length `d + 1` (weight first) and is
//! `P(t) = Σ Bᵢⁿ(t) Pᵢ`, `Bᵢⁿ(t) = C(n,i) (1−t)ⁿ⁻ⁱ tⁱ`, on `t ∈ [0, 1]`;
//! its Euclidean point is `(P₁/P₀, …, P_d/P₀)`.
//! Storage is flat: control point `i` occupies `coords[i(d+1) .. (i+1)(d+1)]`.
//!
//! Every operation here is exact over an exact [`Scalar`]: evaluation, derivatives,
//! degree elevation, subdivision, affine and Möbius reparametrization, projective
//! maps and homogeneous polynomial maps all act on the homogeneous control points
//! with the Bernstein algorithms of [`rcagd_algebra::bernstein`]. `BezierCurve<f64>`
//! additionally has allocation-free evaluation ([`BezierCurve::eval_into`]).
//!
//! Two curves are *the same parametrization* when their homogeneous coordinate
//! vectors are proportional as polynomial vectors, `P(t) ∥ Q(t)`, i.e. all cross
//! terms `PᵢQⱼ − PⱼQᵢ` vanish identically (see [`BezierCurve::same_parametrization`]).

use crate::certify;
use crate::error::GeomError;
use crate::polymap;
use rcagd_algebra::bernstein;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Poly, Scalar};

/// A rational Bézier curve with homogeneous control points (weight first).
#[derive(Debug, Clone, PartialEq)]
pub struct BezierCurve<F> {
    /// Euclidean dimension `d` (homogeneous points have `d + 1` coordinates).
    dim: usize,
    /// Flat homogeneous control points, `(degree + 1) · (dim + 1)` entries.
    coords: Vec<F>,
}

/// `Err(Parameter)` for a non-finite `f64` parameter (exact scalars are always finite).
pub(crate) fn check_finite<F: Scalar>(t: &F, what: &str) -> Result<(), GeomError> {
    if F::EXACT || t.to_f64().is_finite() {
        Ok(())
    } else {
        Err(GeomError::Parameter(format!(
            "{what} is not a finite number"
        )))
    }
}

/// The Euclidean point of a homogeneous point, `(X₁/X₀, …, X_d/X₀)`.
pub(crate) fn dehomogenize<F: Scalar>(
    h: &[F],
    at: impl FnOnce() -> String,
) -> Result<Vec<F>, GeomError> {
    let w = h.first().cloned().unwrap_or_else(F::zero);
    if w.is_zero() || !(F::EXACT || w.to_f64().is_finite()) {
        return Err(GeomError::Weight(format!(
            "point at infinity (weight 0) at {}",
            at()
        )));
    }
    let inv = F::one() / w;
    Ok(h[1..].iter().map(|x| x.clone() * inv.clone()).collect())
}

/// The Euclidean derivatives `x, x', …, x⁽ᵏ⁾` of `x = X/w` from the homogeneous
/// derivatives `H[j] = (w⁽ʲ⁾, X⁽ʲ⁾)`, by the Leibniz rule for `X = w·x`:
/// `x⁽ᵏ⁾ = (X⁽ᵏ⁾ − Σ_{j=1..k} C(k,j) w⁽ʲ⁾ x⁽ᵏ⁻ʲ⁾) / w`.
pub(crate) fn quotient_rule<F: Scalar>(
    hom: &[Vec<F>],
    at: impl Fn() -> String,
) -> Result<Vec<Vec<F>>, GeomError> {
    let first = hom
        .first()
        .ok_or_else(|| GeomError::Empty("no derivatives".into()))?;
    let mut out: Vec<Vec<F>> = vec![dehomogenize(first, &at)?];
    let inv = F::one() / first[0].clone();
    for k in 1..hom.len() {
        let binom: Vec<F> = bernstein::binomial_row(k);
        let mut v: Vec<F> = hom[k][1..].to_vec();
        for j in 1..=k {
            let f = binom[j].clone() * hom[j][0].clone();
            if f.is_zero() {
                continue;
            }
            for (x, y) in v.iter_mut().zip(&out[k - j]) {
                *x -= f.clone() * y.clone();
            }
        }
        out.push(v.into_iter().map(|x| x * inv.clone()).collect());
    }
    Ok(out)
}

/// The homogeneous control points of `P(φ(s))·(cs+d)ⁿ` for the Möbius transformation
/// `φ(s) = (as + b)/(cs + d)`: `Qⱼ = P[u₀ⁿ⁻ʲ, u₁ʲ]`, the homogeneous blossom at
/// `u₀ = (d−b, b)` (the parameter `φ(0)` as `(1−t, t)` up to scale) and
/// `u₁ = (c+d−a−b, a+b)` (`φ(1)`). Multilinearity gives
/// `Σ Bⱼⁿ(s) Qⱼ = Σ C(n,i) ((c−a)s + d−b)ⁿ⁻ⁱ (as+b)ⁱ Pᵢ`, of the same degree `n`.
pub(crate) fn mobius_blocks<F: Scalar>(
    coords: &[F],
    width: usize,
    [a, b, c, d]: [&F; 4],
) -> Result<Vec<F>, GeomError> {
    for (x, name) in [(a, "a"), (b, "b"), (c, "c"), (d, "d")] {
        check_finite(x, name)?;
    }
    let det = a.clone() * d.clone() - b.clone() * c.clone();
    if det.is_zero() {
        return Err(GeomError::Parameter(
            "degenerate Möbius reparametrization t ↦ (at+b)/(ct+d): ad − bc = 0".into(),
        ));
    }
    let points = coords.len().checked_div(width).unwrap_or(0);
    let Some(n) = points.checked_sub(1) else {
        return Ok(Vec::new());
    };
    let u0 = (d.clone() - b.clone(), b.clone());
    let u1 = (
        c.clone() + d.clone() - a.clone() - b.clone(),
        a.clone() + b.clone(),
    );
    let mut out = Vec::with_capacity(coords.len());
    for j in 0..=n {
        let args: Vec<(F, F)> = (0..n)
            .map(|r| if r < n - j { u0.clone() } else { u1.clone() })
            .collect();
        out.extend(bernstein::blossom_homogeneous_blocks(coords, width, &args)?);
    }
    Ok(out)
}

/// Farin's `hornbez`: `Σ C(n,i) (1−t)ⁿ⁻ⁱ tⁱ Pᵢ` by nested multiplication, without
/// allocation, for `points` control points of `out.len()` coordinates each.
pub(crate) fn hornbez(coords: &[f64], points: usize, t: f64, out: &mut [f64]) {
    let s = out.len();
    if points == 0 || coords.len() < points * s {
        out.fill(0.0);
        return;
    }
    let n = points - 1;
    if n == 0 {
        out.copy_from_slice(&coords[..s]);
        return;
    }
    let u = 1.0 - t;
    for (o, &p) in out.iter_mut().zip(&coords[..s]) {
        *o = p * u;
    }
    let mut fact = 1.0;
    let mut binom = 1.0;
    for i in 1..n {
        fact *= t;
        binom = binom * (n - i + 1) as f64 / i as f64;
        let f = fact * binom;
        for (o, &p) in out.iter_mut().zip(&coords[i * s..(i + 1) * s]) {
            *o = (*o + f * p) * u;
        }
    }
    fact *= t;
    for (o, &p) in out.iter_mut().zip(&coords[n * s..(n + 1) * s]) {
        *o += fact * p;
    }
}

impl<F: Scalar> BezierCurve<F> {
    // -----------------------------------------------------------------------------
    // Construction and access
    // -----------------------------------------------------------------------------

    /// From homogeneous control points `(w, wx, wy, …)`.
    ///
    /// # Errors
    /// [`GeomError::Empty`] for no points or zero-length points, [`GeomError::Dimension`]
    /// when the points differ in length.
    pub fn from_homogeneous(points: Vec<Vec<F>>) -> Result<Self, GeomError> {
        let first = points.first().ok_or_else(|| {
            GeomError::Empty("a Bézier curve needs at least one control point".into())
        })?;
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
        if coords.is_empty() || !coords.chunks_exact(dim + 1).remainder().is_empty() {
            return Err(GeomError::Dimension(format!(
                "{} coordinates do not form points of length {}",
                coords.len(),
                dim + 1
            )));
        }
        Ok(BezierCurve { dim, coords })
    }

    /// From the homogeneous coordinate polynomials `X₀ = w, X₁, …, X_d` in the power
    /// basis, written in the Bernstein basis of the given degree
    /// (`bₖ = Σ_{i≤k} C(k,i)/C(n,i) aᵢ`, [`bernstein::to_bernstein`]).
    ///
    /// # Errors
    /// [`GeomError::Dimension`] for fewer than two polynomials, [`GeomError::Degree`] if a
    /// polynomial's degree exceeds `degree`.
    pub fn from_coordinate_polys(polys: &[Poly<F>], degree: usize) -> Result<Self, GeomError> {
        if polys.len() < 2 {
            return Err(GeomError::Dimension(format!(
                "need the weight and at least one coordinate polynomial, got {}",
                polys.len()
            )));
        }
        let s = polys.len();
        let mut coords = vec![F::zero(); (degree + 1) * s];
        for (k, p) in polys.iter().enumerate() {
            let b = bernstein::to_bernstein(p, degree).map_err(|_| {
                GeomError::Degree(format!(
                    "coordinate polynomial {k} has degree {} > {degree}",
                    p.degree().unwrap_or(0)
                ))
            })?;
            for (i, x) in b.into_iter().enumerate() {
                coords[i * s + k] = x;
            }
        }
        Ok(BezierCurve { dim: s - 1, coords })
    }

    /// From whole homogeneous points produced inside the crate (the invariants hold
    /// by construction: `dim ≥ 1`, a non-empty whole number of points).
    pub(crate) fn from_flat_unchecked(dim: usize, coords: Vec<F>) -> Self {
        BezierCurve { dim, coords }
    }

    /// Euclidean dimension.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Degree (number of control points − 1).
    pub fn degree(&self) -> usize {
        self.coords.len() / (self.dim + 1) - 1
    }

    /// Homogeneous control point `i` (weight first). Panics if `i > degree`; see
    /// [`Self::get_control_point`] for the checked form.
    pub fn control_point(&self, i: usize) -> &[F] {
        let s = self.dim + 1;
        &self.coords[i * s..(i + 1) * s]
    }

    /// Homogeneous control point `i`, `None` if `i > degree`.
    pub fn get_control_point(&self, i: usize) -> Option<&[F]> {
        let s = self.dim + 1;
        self.coords.get(i * s..(i + 1) * s)
    }

    /// All homogeneous control points.
    pub fn control_points(&self) -> impl DoubleEndedIterator<Item = &[F]> + ExactSizeIterator {
        self.coords.chunks(self.dim + 1)
    }

    /// The flat homogeneous coordinates.
    pub fn coords(&self) -> &[F] {
        &self.coords
    }

    /// The weights `w₀, …, wₙ`.
    pub fn weights(&self) -> Vec<F> {
        self.coordinate_bernstein(0)
    }

    /// The Euclidean control points `Pᵢ/wᵢ`.
    ///
    /// # Errors
    /// [`GeomError::Weight`] if a weight is zero (a control point at infinity).
    pub fn euclidean_control_points(&self) -> Result<Vec<Vec<F>>, GeomError> {
        self.control_points()
            .enumerate()
            .map(|(i, p)| dehomogenize(p, || format!("control point {i}")))
            .collect()
    }

    /// `true` if all weights are equal (the curve is polynomial after scaling).
    pub fn is_polynomial(&self) -> bool {
        self.weights().windows(2).all(|w| w[0] == w[1])
    }

    /// The Bernstein coefficients of homogeneous coordinate `k` (`0` = weight);
    /// empty if `k > dim`.
    pub fn coordinate_bernstein(&self, k: usize) -> Vec<F> {
        if k > self.dim {
            return Vec::new();
        }
        self.control_points().map(|p| p[k].clone()).collect()
    }

    /// The homogeneous coordinates `X₀ = w, X₁, …, X_d` as power-basis polynomials
    /// (`aᵢ = C(n,i) Δⁱb₀`, [`bernstein::from_bernstein`]).
    pub fn coordinate_polys(&self) -> Vec<Poly<F>> {
        (0..=self.dim)
            .map(|k| bernstein::from_bernstein(&self.coordinate_bernstein(k)))
            .collect()
    }

    /// The weight polynomial `w(t) = X₀(t)` in the power basis.
    pub fn weight_poly(&self) -> Poly<F> {
        bernstein::from_bernstein(&self.weights())
    }

    // -----------------------------------------------------------------------------
    // Evaluation and derivatives
    // -----------------------------------------------------------------------------

    /// The homogeneous point `P(t) = Σ Bᵢⁿ(t) Pᵢ` by de Casteljau's algorithm
    /// (`Pᵢʳ = (1−t) Pᵢʳ⁻¹ + t Pᵢ₊₁ʳ⁻¹`); exact over exact scalars. Any `t`.
    pub fn eval_homogeneous(&self, t: &F) -> Vec<F> {
        bernstein::eval_blocks(&self.coords, self.dim + 1, t)
    }

    /// The Euclidean point `(P₁(t), …, P_d(t)) / P₀(t)`.
    ///
    /// # Errors
    /// [`GeomError::Weight`] where the weight vanishes (a point at infinity),
    /// [`GeomError::Parameter`] for a non-finite `t`.
    pub fn eval(&self, t: &F) -> Result<Vec<F>, GeomError> {
        check_finite(t, "t")?;
        dehomogenize(&self.eval_homogeneous(t), || {
            format!("t = {}", certify::format_scalar(t))
        })
    }

    /// The hodograph in homogeneous coordinates: `P'(t) = Σ n (Pᵢ₊₁ − Pᵢ) Bᵢⁿ⁻¹(t)`,
    /// a curve of degree `n − 1` (a constant curve gives the zero point in degree 0).
    /// Its control points are vectors, not points: weights may vanish.
    pub fn hodograph(&self) -> Self {
        BezierCurve {
            dim: self.dim,
            coords: bernstein::derivative_blocks(&self.coords, self.dim + 1),
        }
    }

    /// The `k`-th homogeneous derivative curve `P⁽ᵏ⁾`, degree `max(n − k, 0)`
    /// (identically zero for `k > n`).
    pub fn derivative(&self, k: usize) -> Self {
        (0..k).fold(self.clone(), |c, _| c.hodograph())
    }

    /// The homogeneous derivative vector `P⁽ᵏ⁾(t)`.
    pub fn derivative_homogeneous(&self, t: &F, k: usize) -> Vec<F> {
        self.derivative(k).eval_homogeneous(t)
    }

    /// The Euclidean derivatives `x(t), x'(t), …, x⁽ᵏ⁾(t)` of `x = X/w` by the quotient
    /// (Leibniz) rule `x⁽ʲ⁾ = (X⁽ʲ⁾ − Σ_{i=1..j} C(j,i) w⁽ⁱ⁾ x⁽ʲ⁻ⁱ⁾) / w`.
    ///
    /// # Errors
    /// [`GeomError::Weight`] where the weight vanishes, [`GeomError::Parameter`] for a
    /// non-finite `t`.
    pub fn derivatives_euclidean(&self, t: &F, k: usize) -> Result<Vec<Vec<F>>, GeomError> {
        check_finite(t, "t")?;
        let mut hom = Vec::with_capacity(k + 1);
        let mut c = self.clone();
        for j in 0..=k {
            hom.push(c.eval_homogeneous(t));
            if j < k {
                c = c.hodograph();
            }
        }
        quotient_rule(&hom, || format!("t = {}", certify::format_scalar(t)))
    }

    /// The `k`-th Euclidean derivative `x⁽ᵏ⁾(t)` (see [`Self::derivatives_euclidean`]).
    ///
    /// # Errors
    /// As [`Self::derivatives_euclidean`].
    pub fn derivative_euclidean(&self, t: &F, k: usize) -> Result<Vec<F>, GeomError> {
        let mut all = self.derivatives_euclidean(t, k)?;
        all.pop()
            .ok_or_else(|| GeomError::Empty("no derivatives".into()))
    }

    // -----------------------------------------------------------------------------
    // Representation changes that keep the curve
    // -----------------------------------------------------------------------------

    /// Degree elevation by `r`: the same parametrization in degree `n + r`,
    /// `Qₖ = Σᵢ C(n,i) C(r,k−i) / C(n+r,k) · Pᵢ`.
    pub fn elevate(&self, r: usize) -> Self {
        BezierCurve {
            dim: self.dim,
            coords: bernstein::elevate_blocks(&self.coords, self.dim + 1, r),
        }
    }

    /// Elevates to degree `n` (unchanged if `n ≤ degree`).
    pub fn elevate_to(&self, n: usize) -> Self {
        self.elevate(n.saturating_sub(self.degree()))
    }

    /// De Casteljau subdivision at `t`: the pieces on `[0, t]` and `[t, 1]`, each
    /// reparametrized to `[0, 1]` (`left(s) = P(ts)`, `right(s) = P(t + (1−t)s)`).
    /// `t` outside `[0, 1]` extrapolates (one piece then covers the other's
    /// interval too); `t = 0` or `1` gives a constant piece.
    ///
    /// # Errors
    /// [`GeomError::Parameter`] for a non-finite `t`.
    pub fn subdivide(&self, t: &F) -> Result<(Self, Self), GeomError> {
        check_finite(t, "subdivision parameter")?;
        let (l, r) = bernstein::subdivide_blocks(&self.coords, self.dim + 1, t);
        Ok((
            BezierCurve {
                dim: self.dim,
                coords: l,
            },
            BezierCurve {
                dim: self.dim,
                coords: r,
            },
        ))
    }

    /// The affine reparametrization to `[a, b]`: `Q(s) = P(a + (b−a)s)`, with control
    /// points the blossom values `Qⱼ = P[aⁿ⁻ʲ, bʲ]`. `b < a` reverses the direction;
    /// any real `a, b` (extrapolation).
    ///
    /// # Errors
    /// [`GeomError::Parameter`] if `a = b` (an empty interval) or an end is not finite.
    pub fn restrict(&self, a: &F, b: &F) -> Result<Self, GeomError> {
        if a == b {
            return Err(GeomError::Parameter(format!(
                "cannot restrict to the empty interval [{0}, {0}]",
                certify::format_scalar(a)
            )));
        }
        let width = b.clone() - a.clone();
        self.reparametrize_mobius(&width, a, &F::zero(), &F::one())
    }

    /// Möbius (rational linear) reparametrization `t = φ(s) = (as + b)/(cs + d)` in
    /// homogeneous Bernstein form, keeping the degree: the control points of
    /// `Q(s) = (cs + d)ⁿ P(φ(s))` are the homogeneous blossom values
    /// `Qⱼ = P[(d−b, b)ⁿ⁻ʲ, (c+d−a−b, a+b)ʲ]` (de Casteljau with `(1−t, t)` replaced by
    /// homogeneous parameters). `Q(s)` and `P(φ(s))` are the same projective point; the
    /// new curve on `s ∈ [0, 1]` traces `P` on `[φ(0), φ(1)]` (through `t = ∞` if
    /// `cs + d` vanishes in between). `c = 0, d = 1` is an affine reparametrization.
    ///
    /// # Errors
    /// [`GeomError::Parameter`] if `ad − bc = 0` (not invertible) or a coefficient is
    /// not finite.
    pub fn reparametrize_mobius(&self, a: &F, b: &F, c: &F, d: &F) -> Result<Self, GeomError> {
        let coords = mobius_blocks(&self.coords, self.dim + 1, [a, b, c, d])?;
        Ok(BezierCurve {
            dim: self.dim,
            coords,
        })
    }

    /// The reversed curve `Q(t) = P(1 − t)` (control points in reverse order).
    pub fn reverse(&self) -> Self {
        BezierCurve {
            dim: self.dim,
            coords: self.control_points().rev().flatten().cloned().collect(),
        }
    }

    /// Maps every coordinate through `f` (e.g. to another scalar type).
    pub fn map_scalar<G: Scalar>(&self, f: impl Fn(&F) -> G) -> BezierCurve<G> {
        BezierCurve {
            dim: self.dim,
            coords: self.coords.iter().map(f).collect(),
        }
    }

    /// The nearest `f64` curve (for fast evaluation and tessellation).
    pub fn to_f64(&self) -> BezierCurve<f64> {
        self.map_scalar(Scalar::to_f64)
    }

    // -----------------------------------------------------------------------------
    // Maps
    // -----------------------------------------------------------------------------

    /// The image under the projective map `X ↦ M X` (`M` has `d' + 1` rows of length
    /// `d + 1`, weight first; a square non-singular `M` is a projective transformation,
    /// a rectangular one a projection). The degree is unchanged: `Qᵢ = M Pᵢ`.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if a row's length is not `d + 1` or there are fewer than
    /// two rows.
    pub fn apply_projective(&self, matrix: &[Vec<F>]) -> Result<Self, GeomError> {
        check_matrix(matrix, self.dim + 1, false)?;
        let coords = self
            .control_points()
            .flat_map(|p| matrix.iter().map(move |row| dot(row, p)))
            .collect();
        Ok(BezierCurve {
            dim: matrix.len() - 1,
            coords,
        })
    }

    /// The image under a homogeneous polynomial map `F = (F₀, …, F_{d'})`, each `Fⱼ`
    /// homogeneous of the same degree `k` in the `d + 1` homogeneous coordinates
    /// `(w, x₁, …, x_d)`: the curve `F(P(t))` of degree exactly `k·n`, computed by
    /// Bernstein products of the coordinate vectors (not by sampling), so
    /// `image.eval_homogeneous(t) = F(P(t))` identically (Jüttler;
    /// docs/math/quadrics.md, "Curves and patches under δ": `d_k = Σ_{i+j=k} C(n,i)C(n,j)/C(2n,k) F̂(bᵢ, bⱼ)` for quadratic maps).
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if a component has more than `d + 1` variables (fewer
    /// are padded, as in [`MPoly`]) or there are fewer than two components, [`GeomError::Degree`] if a component is not
    /// homogeneous, the degrees differ, or the map is identically zero.
    pub fn apply_polymap(&self, map: &[MPoly<F>]) -> Result<Self, GeomError> {
        let k = polymap::homogeneous_degree(map, self.dim + 1)?;
        let images = polymap::apply_to_bernstein(map, k, self.coordinate_columns())?;
        Ok(Self::from_coordinate_columns(&images))
    }

    /// The Bernstein coefficients (degree `2n`) of the quadratic form `Xᵀ Q X` along the
    /// curve, `Σ_{a,b} Q_ab X_a(t) X_b(t)` (`Q` is `(d+1)×(d+1)`, weight first; only its
    /// symmetric part matters).
    ///
    /// # Errors
    /// [`GeomError::Dimension`] unless `Q` is `(d+1)×(d+1)`.
    pub fn quadratic_form(&self, q: &[Vec<F>]) -> Result<Vec<F>, GeomError> {
        check_matrix(q, self.dim + 1, true)?;
        polymap::quadratic_form_bernstein(q, &self.coordinate_columns())
    }

    /// The homogeneous coordinates as Bernstein polynomials of bidegree `(n, 0)`.
    pub(crate) fn coordinate_columns(&self) -> Vec<polymap::Bernstein2<F>> {
        (0..=self.dim)
            .map(|a| polymap::Bernstein2 {
                coeffs: self.coordinate_bernstein(a),
                degree: (self.degree(), 0),
            })
            .collect()
    }

    /// Assembles a curve from per-coordinate Bernstein vectors of equal length.
    fn from_coordinate_columns(columns: &[Vec<F>]) -> Self {
        let s = columns.len();
        let points = columns.first().map_or(0, Vec::len);
        let mut coords = Vec::with_capacity(s * points);
        for i in 0..points {
            coords.extend(columns.iter().map(|c| c[i].clone()));
        }
        BezierCurve { dim: s - 1, coords }
    }

    // -----------------------------------------------------------------------------
    // Comparison
    // -----------------------------------------------------------------------------

    /// `true` if `self` and `other` are the same rational parametrization: their
    /// homogeneous coordinate vectors are proportional as polynomials,
    /// `P(t) ∥ Q(t)`, i.e. every cross term `PᵢQⱼ − PⱼQᵢ` vanishes identically
    /// (checked as Bernstein products, degree `m + n`, against a pivot coordinate of
    /// `Q`). This covers degree elevation, scaling of the homogeneous coordinates and
    /// common polynomial factors. Exact for exact scalars; for `f64` relative to the
    /// tolerance of [`certify`]. Curves of different dimension, or identically zero
    /// ones, are never the same.
    pub fn same_parametrization(&self, other: &Self) -> bool {
        certify::curves_agree(self, other).is_ok_and(|c| c.holds)
    }
}

/// `Σ rowᵢ pᵢ`.
pub(crate) fn dot<F: Scalar>(row: &[F], p: &[F]) -> F {
    row.iter()
        .zip(p)
        .fold(F::zero(), |acc, (a, b)| acc + a.clone() * b.clone())
}

/// Checks that `m` has rows of length `cols` (and, if `square`, exactly `cols` rows;
/// otherwise at least two rows).
pub(crate) fn check_matrix<F>(m: &[Vec<F>], cols: usize, square: bool) -> Result<(), GeomError> {
    if square && m.len() != cols {
        return Err(GeomError::Dimension(format!(
            "the matrix must be {cols}×{cols} (homogeneous, weight first), it has {} rows",
            m.len()
        )));
    }
    if m.len() < 2 {
        return Err(GeomError::Dimension(format!(
            "a projective map needs at least two rows, got {}",
            m.len()
        )));
    }
    if let Some((i, r)) = m.iter().enumerate().find(|(_, r)| r.len() != cols) {
        return Err(GeomError::Dimension(format!(
            "matrix row {i} has {} entries, the points have {cols} homogeneous coordinates",
            r.len()
        )));
    }
    Ok(())
}

impl BezierCurve<f64> {
    /// Writes the homogeneous point `P(t)` into `out` (length `d + 1`) without
    /// allocating, by nested multiplication (Farin's `hornbez`,
    /// `Σ C(n,i) (1−t)ⁿ⁻ⁱ tⁱ Pᵢ`), `O(n·d)` operations.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if `out.len() ≠ d + 1`.
    pub fn eval_homogeneous_into(&self, t: f64, out: &mut [f64]) -> Result<(), GeomError> {
        let s = self.dim + 1;
        if out.len() != s {
            return Err(GeomError::Dimension(format!(
                "output buffer has {} entries, the curve has {s} homogeneous coordinates",
                out.len()
            )));
        }
        hornbez(&self.coords, self.degree() + 1, t, out);
        Ok(())
    }

    /// Writes the Euclidean point `x(t)` into `out` (length `d`) without allocating.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if `out.len() ≠ d`, [`GeomError::Weight`] where the
    /// weight vanishes (or the result is not finite).
    pub fn eval_into(&self, t: f64, out: &mut [f64]) -> Result<(), GeomError> {
        if out.len() != self.dim {
            return Err(GeomError::Dimension(format!(
                "output buffer has {} entries, the curve has dimension {}",
                out.len(),
                self.dim
            )));
        }
        let (n, s) = (self.degree(), self.dim + 1);
        // Each coordinate by the same nested scheme: no buffer for the homogeneous point.
        let w = hornbez_column(&self.coords, s, 0, n, t);
        if w == 0.0 || !w.is_finite() {
            return Err(GeomError::Weight(format!(
                "point at infinity (weight 0) at t = {t}"
            )));
        }
        for (k, o) in out.iter_mut().enumerate() {
            *o = hornbez_column(&self.coords, s, k + 1, n, t) / w;
        }
        Ok(())
    }
}

/// `hornbez` on coordinate `k` of the points `0..=n` with stride `s`.
fn hornbez_column(coords: &[f64], s: usize, k: usize, n: usize, t: f64) -> f64 {
    let at = |i: usize| coords.get(i * s + k).copied().unwrap_or(0.0);
    if n == 0 {
        return at(0);
    }
    let u = 1.0 - t;
    let mut acc = at(0) * u;
    let mut fact = 1.0;
    let mut binom = 1.0;
    for i in 1..n {
        fact *= t;
        binom = binom * (n - i + 1) as f64 / i as f64;
        acc = (acc + fact * binom * at(i)) * u;
    }
    acc + fact * t * at(n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }
    fn pt(v: &[i64]) -> Vec<Rational> {
        v.iter().map(|&x| Rational::from(x)).collect()
    }

    /// The quarter circle `(1−t², 2t)/(1+t²)` on `[0, 1]`: weights 1, 1, 2.
    fn quarter_circle() -> BezierCurve<Rational> {
        BezierCurve::from_homogeneous(vec![pt(&[1, 1, 0]), pt(&[1, 1, 1]), pt(&[2, 0, 2])])
            .expect("valid")
    }

    fn cubic() -> BezierCurve<Rational> {
        BezierCurve::from_homogeneous(vec![
            pt(&[1, 0, 0, 1]),
            pt(&[2, 1, 3, 0]),
            pt(&[3, 4, -1, 2]),
            pt(&[1, 2, 2, 2]),
        ])
        .expect("valid")
    }

    #[test]
    fn evaluates_the_circle_exactly() {
        let c = quarter_circle();
        let t = q(1, 3);
        // (1−t², 2t)/(1+t²) = (8/10, 6/10)
        assert_eq!(c.eval(&t).ok(), Some(vec![q(4, 5), q(3, 5)]));
        assert_eq!(c.eval(&q(1, 1)).ok(), Some(vec![q(0, 1), q(1, 1)]));
        let w = c.weight_poly();
        assert_eq!(w, Poly::new(vec![q(1, 1), q(0, 1), q(1, 1)]));
    }

    #[test]
    fn point_at_infinity_is_an_error() {
        // w(t) = 1 − 2t vanishes at t = 1/2.
        let c = BezierCurve::from_homogeneous(vec![pt(&[1, 0]), pt(&[-1, 1])]).expect("valid");
        assert!(matches!(c.eval(&q(1, 2)), Err(GeomError::Weight(_))));
        assert!(c.derivatives_euclidean(&q(1, 2), 1).is_err());
        let f = c.to_f64();
        let mut out = [0.0];
        assert!(f.eval_into(0.5, &mut out).is_err());
        assert!(f.eval(&f64::NAN).is_err());
    }

    #[test]
    fn coordinate_polys_round_trip() {
        let c = cubic();
        let polys = c.coordinate_polys();
        assert_eq!(polys.len(), 4);
        let back = BezierCurve::from_coordinate_polys(&polys, 3).expect("fits");
        assert_eq!(back, c);
        let up = BezierCurve::from_coordinate_polys(&polys, 5).expect("fits");
        assert_eq!(up, c.elevate(2));
        assert!(BezierCurve::from_coordinate_polys(&polys, 2).is_err());
        assert!(BezierCurve::<Rational>::from_coordinate_polys(&polys[..1], 3).is_err());
        let t = q(2, 7);
        let h = c.eval_homogeneous(&t);
        for (p, x) in polys.iter().zip(&h) {
            assert_eq!(&p.eval(&t), x);
        }
    }

    #[test]
    fn derivatives_follow_the_quotient_rule() {
        let c = quarter_circle();
        let t = q(1, 2);
        // x = (1−t²)/(1+t²), y = 2t/(1+t²):  x' = −4t/(1+t²)², y' = 2(1−t²)/(1+t²)²
        let d = c.derivative_euclidean(&t, 1).expect("finite");
        assert_eq!(d, vec![q(-32, 25), q(24, 25)]);
        // second derivative against the power-basis quotient.
        let polys = c.coordinate_polys();
        let (w, x) = (&polys[0], &polys[1]);
        let (w1, x1) = (w.derivative(), x.derivative());
        let (w2, x2) = (w1.derivative(), x1.derivative());
        let wt = w.eval(&t);
        let xv = x.eval(&t) / wt.clone();
        let xd = (x1.eval(&t) - w1.eval(&t) * xv.clone()) / wt.clone();
        let xdd = (x2.eval(&t) - w2.eval(&t) * xv - Rational::from(2) * w1.eval(&t) * xd) / wt;
        let all = c.derivatives_euclidean(&t, 2).expect("finite");
        assert_eq!(all[2][0], xdd);
        assert_eq!(c.derivative(3).degree(), 0);
        assert!(c.derivative(3).coords().iter().all(|x| x == &q(0, 1)));
    }

    #[test]
    fn subdivision_restriction_and_reversal() {
        let c = cubic();
        let t = q(2, 5);
        let (l, r) = c.subdivide(&t).expect("finite");
        assert_eq!(l, c.restrict(&q(0, 1), &t).expect("non-empty"));
        assert_eq!(r, c.restrict(&t, &q(1, 1)).expect("non-empty"));
        assert_eq!(c.reverse().reverse(), c);
        assert_eq!(
            c.reverse(),
            c.restrict(&q(1, 1), &q(0, 1)).expect("non-empty")
        );
        assert!(c.restrict(&t, &t).is_err());
        assert!(c.to_f64().subdivide(&f64::INFINITY).is_err());
        // Extrapolated restriction.
        let e = c.restrict(&q(-1, 2), &q(3, 2)).expect("non-empty");
        assert_eq!(e.eval_homogeneous(&q(1, 4)), c.eval_homogeneous(&q(0, 1)));
    }

    #[test]
    fn mobius_reparametrization() {
        let c = quarter_circle();
        // t = (s + 1)/(2s + 3)
        let (a, b, cc, d) = (q(1, 1), q(1, 1), q(2, 1), q(3, 1));
        let m = c.reparametrize_mobius(&a, &b, &cc, &d).expect("invertible");
        assert_eq!(m.degree(), 2);
        for s in [q(0, 1), q(1, 3), q(1, 1), q(5, 2)] {
            let phi = (a.clone() * s.clone() + b.clone()) / (cc.clone() * s.clone() + d.clone());
            assert_eq!(m.eval(&s).ok(), c.eval(&phi).ok());
        }
        assert!(c
            .reparametrize_mobius(&q(1, 1), &q(2, 1), &q(2, 1), &q(4, 1))
            .is_err());
    }

    #[test]
    fn elevation_and_same_parametrization() {
        let c = cubic();
        let e = c.elevate(2);
        assert_eq!(e.degree(), 5);
        assert!(e.same_parametrization(&c));
        assert!(c.same_parametrization(&e));
        let scaled = c.map_scalar(|x| x.clone() * q(-3, 2));
        assert!(scaled.same_parametrization(&c));
        assert!(!c.same_parametrization(&c.reverse()));
        assert_eq!(c.elevate_to(2), c);
    }

    #[test]
    fn projective_map_and_quadratic_form() {
        let c = quarter_circle();
        // Scale by 2: (w, x, y) ↦ (w, 2x, 2y).
        let m = vec![pt(&[1, 0, 0]), pt(&[0, 2, 0]), pt(&[0, 0, 2])];
        let s = c.apply_projective(&m).expect("3×3");
        assert_eq!(s.eval(&q(1, 3)).ok(), Some(vec![q(8, 5), q(6, 5)]));
        assert!(c.apply_projective(&[pt(&[1, 0])]).is_err());
        // x² + y² − w² vanishes along the circle.
        let qf = vec![pt(&[-1, 0, 0]), pt(&[0, 1, 0]), pt(&[0, 0, 1])];
        let f = c.quadratic_form(&qf).expect("3×3");
        assert_eq!(f.len(), 5);
        assert!(f.iter().all(|x| x == &q(0, 1)));
        assert!(c.quadratic_form(&m[..2]).is_err());
    }

    #[test]
    fn f64_fast_path_agrees_with_exact() {
        let c = cubic();
        let f = c.to_f64();
        let mut h = [0.0; 4];
        let mut e = [0.0; 3];
        for k in 0..=10 {
            let t = q(k, 10);
            f.eval_homogeneous_into(Scalar::to_f64(&t), &mut h)
                .expect("sized");
            let exact = c.eval_homogeneous(&t);
            for (a, b) in h.iter().zip(&exact) {
                assert!((a - Scalar::to_f64(b)).abs() < 1e-12);
            }
            f.eval_into(Scalar::to_f64(&t), &mut e).expect("finite");
            let exact = c.eval(&t).expect("finite");
            for (a, b) in e.iter().zip(&exact) {
                assert!((a - Scalar::to_f64(b)).abs() < 1e-12);
            }
        }
        assert!(f.eval_into(0.5, &mut [0.0; 2]).is_err());
        assert!(f.eval_homogeneous_into(0.5, &mut [0.0; 3]).is_err());
    }

    #[test]
    fn constructors_reject_bad_input() {
        assert!(matches!(
            BezierCurve::<Rational>::from_homogeneous(vec![]),
            Err(GeomError::Empty(_))
        ));
        assert!(BezierCurve::from_homogeneous(vec![pt(&[1, 0]), pt(&[1, 0, 0])]).is_err());
        assert!(BezierCurve::from_points_weights(&[pt(&[1, 2])], &[]).is_err());
        assert!(BezierCurve::from_flat(2, pt(&[1, 2])).is_err());
        assert!(quarter_circle().get_control_point(3).is_none());
        let z = BezierCurve::from_homogeneous(vec![pt(&[0, 1]), pt(&[1, 1])]).expect("valid");
        assert!(z.euclidean_control_points().is_err());
    }
}
