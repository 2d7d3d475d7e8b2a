//! NURBS curves and surfaces with exact knots and homogeneous control points.
//!
//! A NURBS curve of degree `p` with control points `P₀ … Pₙ` (homogeneous, weight first,
//! like [`BezierCurve`]) and knots `u₀ ≤ … ≤ u_{n+p+1}` is
//! `P(t) = Σᵢ Nᵢ,ₚ(t) Pᵢ` with the B-spline basis `Nᵢ,ₚ` (*The NURBS Book*, Piegl &
//! Tiller, 2nd ed., (2.5) and (4.2)); the Euclidean point is `P₁..d / P₀`. Everything
//! is generic over [`Scalar`]: with [`rcagd_algebra::Rational`] all operations are exact.
//!
//! Knot vectors are **clamped**: the first and the last knot have multiplicity exactly
//! `p + 1`, interior knots multiplicity at most `p` (so every curve is at least C0), the
//! domain `[u_p, u_{n+1}]` is non-empty, and `len = n + p + 2`
//! ([`validate_knots`]). Algorithms used:
//!
//! * span search: A2.1 *FindSpan* (as a binary search for the last knot `≤ t`);
//! * evaluation: de Boor's algorithm, i.e. repeated corner cutting
//!   `Pᵢʳ = (1 − αᵢʳ) Pᵢ₋₁ʳ⁻¹ + αᵢʳ Pᵢʳ⁻¹`, `αᵢʳ = (t − uᵢ)/(u_{i+p+1−r} − uᵢ)`
//!   (NURBS Book §5.2, A5.2 *CurvePntByCornerCut*: evaluation by repeated knot
//!   insertion), applied to homogeneous points (§4.2, A4.1: a rational curve is a
//!   polynomial one in homogeneous space);
//! * knot insertion: Boehm's algorithm, A5.1 *CurveKnotIns*
//!   (`Qᵢ = αᵢ Pᵢ + (1 − αᵢ) Pᵢ₋₁`, `αᵢ = (t − uᵢ)/(u_{i+p} − uᵢ)`, (5.15)); surfaces
//!   insert row- or column-wise (A5.3 *SurfaceKnotIns*);
//! * decomposition into Bézier pieces: insert every interior knot up to multiplicity `p`
//!   (A5.6 *DecomposeCurve*, A5.7 *DecomposeSurface*, done here by repeated A5.1); the
//!   piece on `[uₖ, uₖ₊₁]` then has the `p + 1` consecutive control points as its
//!   Bézier points (the Bézier form is invariant under the affine map to `[0, 1]`).
//!
//! Joining Bézier pieces gives interior knots of multiplicity `p`; C0 continuity is
//! checked exactly and the pieces' homogeneous coordinates are rescaled (which does not
//! change the curve) so that adjacent end points coincide as homogeneous vectors.

use crate::curve::BezierCurve;
use crate::error::GeomError;
use crate::patch::BezierPatch;
use rcagd_algebra::Scalar;
use rcagd_algebra::{format_scalar, format_vector};
use std::cmp::Ordering;

/// Checks a clamped knot vector for degree `degree` and `num_ctrl` control points:
/// `degree ≥ 1`, `num_ctrl ≥ degree + 1`, `len = num_ctrl + degree + 1` (`= n + p + 2`),
/// knots non-decreasing (NaN rejected), the first and last knot of multiplicity exactly
/// `p + 1`, interior knots of multiplicity at most `p`.
///
/// # Errors
/// [`GeomError::Degree`] for degree 0, [`GeomError::Dimension`] for too few control
/// points, [`GeomError::Knots`] naming the violated condition otherwise.
pub fn validate_knots<F: Scalar>(
    knots: &[F],
    degree: usize,
    num_ctrl: usize,
) -> Result<(), GeomError> {
    let p = degree;
    if p == 0 {
        return Err(GeomError::Degree(
            "a NURBS needs degree at least 1".to_string(),
        ));
    }
    if num_ctrl < p + 1 {
        return Err(GeomError::Dimension(format!(
            "degree {p} needs at least {} control points, got {num_ctrl}",
            p + 1
        )));
    }
    let want = num_ctrl + p + 1;
    if knots.len() != want {
        return Err(GeomError::Knots(format!(
            "length {} but n + p + 2 = {want} for {num_ctrl} control points of degree {p}",
            knots.len()
        )));
    }
    for (i, w) in knots.windows(2).enumerate() {
        match w[0].partial_cmp(&w[1]) {
            Some(Ordering::Less | Ordering::Equal) => {}
            _ => {
                return Err(GeomError::Knots(format!(
                    "not non-decreasing: knot {} = {} is followed by knot {} = {}",
                    i,
                    format_scalar(&w[0]),
                    i + 1,
                    format_scalar(&w[1])
                )))
            }
        }
    }
    let runs = knot_runs(knots);
    let (first, last) = match (runs.first(), runs.last()) {
        (Some(f), Some(l)) if runs.len() >= 2 => (f, l),
        _ => {
            return Err(GeomError::Knots(
                "empty parameter domain: first knot equals last knot".to_string(),
            ))
        }
    };
    if first.1 != p + 1 {
        return Err(GeomError::Knots(format!(
            "not clamped: first knot {} has multiplicity {}, needs p + 1 = {}",
            format_scalar(&first.0),
            first.1,
            p + 1
        )));
    }
    if last.1 != p + 1 {
        return Err(GeomError::Knots(format!(
            "not clamped: last knot {} has multiplicity {}, needs p + 1 = {}",
            format_scalar(&last.0),
            last.1,
            p + 1
        )));
    }
    if let Some((k, m)) = runs[1..runs.len() - 1].iter().find(|(_, m)| *m > p) {
        return Err(GeomError::Knots(format!(
            "interior knot {} has multiplicity {m} > degree {p} (the curve would be discontinuous)",
            format_scalar(k)
        )));
    }
    Ok(())
}

/// Distinct knot values with their multiplicities, in order.
fn knot_runs<F: Scalar>(knots: &[F]) -> Vec<(F, usize)> {
    let mut runs: Vec<(F, usize)> = Vec::new();
    for k in knots {
        match runs.last_mut() {
            Some((v, m)) if v == k => *m += 1,
            _ => runs.push((k.clone(), 1)),
        }
    }
    runs
}

/// A2.1 FindSpan for a valid clamped knot vector: the index `k ∈ [p, n]` with
/// `u_k ≤ t < u_{k+1}`, and `k = n` for `t = u_{n+1}`. `t` must lie in the domain.
fn find_span<F: Scalar>(knots: &[F], p: usize, num_ctrl: usize, t: &F) -> usize {
    let n = num_ctrl - 1;
    // knots[p+1 ..= n] sorted: count the ones ≤ t
    p + knots[p + 1..=n].partition_point(|x| x <= t)
}

fn check_domain<F: Scalar>(knots: &[F], p: usize, num_ctrl: usize, t: &F) -> Result<(), GeomError> {
    let a = &knots[p];
    let b = &knots[num_ctrl];
    if t < a || t > b || t.partial_cmp(a).is_none() {
        return Err(GeomError::Parameter(format!(
            "parameter {} outside the domain [{}, {}]",
            format_scalar(t),
            format_scalar(a),
            format_scalar(b)
        )));
    }
    Ok(())
}

/// de Boor's algorithm on the `p + 1` local homogeneous points `d` (flat, stride `s`) of
/// span `k`: `dⱼ ← (1 − α) dⱼ₋₁ + α dⱼ`, `α = (t − u_{j+k−p}) / (u_{j+1+k−r} − u_{j+k−p})`,
/// `r = 1..p`, `j = p..r` (NURBS Book A5.2). Returns `d_p = P(t)`.
fn de_boor<F: Scalar>(knots: &[F], p: usize, k: usize, mut d: Vec<F>, s: usize, t: &F) -> Vec<F> {
    for r in 1..=p {
        for j in (r..=p).rev() {
            let lo = knots[j + k - p].clone();
            let hi = knots[j + 1 + k - r].clone();
            let alpha = (t.clone() - lo.clone()) / (hi - lo);
            for c in 0..s {
                let prev = d[(j - 1) * s + c].clone();
                let cur = d[j * s + c].clone();
                d[j * s + c] = prev.clone() + alpha.clone() * (cur - prev);
            }
        }
    }
    d.split_off(p * s)
}

fn dehomogenize<F: Scalar>(h: &[F], t_desc: impl FnOnce() -> String) -> Result<Vec<F>, GeomError> {
    let w = h[0].clone();
    if w.is_zero() {
        return Err(GeomError::Weight(format!(
            "the curve passes through a point at infinity (weight 0) at {}",
            t_desc()
        )));
    }
    let inv = F::one() / w;
    Ok(h[1..].iter().map(|c| c.clone() * inv.clone()).collect())
}

/// Boehm knot insertion (NURBS Book A5.1 CurveKnotIns) on homogeneous points `pts`
/// (flat, stride `s`): inserts `t` `r` times. Needs an interior `t` with
/// `multiplicity(t) + r ≤ p`. Returns the new knots and points.
fn insert_knot_flat<F: Scalar>(
    knots: &[F],
    p: usize,
    pts: &[F],
    s: usize,
    t: &F,
    r: usize,
) -> Result<(Vec<F>, Vec<F>), GeomError> {
    let num_ctrl = pts.len() / s;
    let (a, b) = (&knots[p], &knots[num_ctrl]);
    if !(t > a && t < b) {
        return Err(GeomError::Parameter(format!(
            "knot insertion needs a parameter strictly inside the domain ({}, {}), got {}",
            format_scalar(a),
            format_scalar(b),
            format_scalar(t)
        )));
    }
    let mult = knots.iter().filter(|x| *x == t).count();
    if mult + r > p {
        return Err(GeomError::Knots(format!(
            "inserting {} {r} time(s) would give multiplicity {} > degree {p}",
            format_scalar(t),
            mult + r
        )));
    }
    if r == 0 {
        return Ok((knots.to_vec(), pts.to_vec()));
    }
    let n = num_ctrl - 1;
    let k = find_span(knots, p, num_ctrl, t);
    let sm = mult;
    // new knot vector
    let mut uq = Vec::with_capacity(knots.len() + r);
    uq.extend_from_slice(&knots[..=k]);
    uq.extend(std::iter::repeat_n(t.clone(), r));
    uq.extend_from_slice(&knots[k + 1..]);
    // unchanged control points
    let mut q: Vec<F> = vec![F::zero(); (num_ctrl + r) * s];
    q[..(k - p + 1) * s].clone_from_slice(&pts[..(k - p + 1) * s]);
    q[(k - sm + r) * s..].clone_from_slice(&pts[(k - sm) * s..(n + 1) * s]);
    // the p − s affected points
    let mut rw: Vec<F> = pts[(k - p) * s..(k - sm + 1) * s].to_vec();
    let mut l = k - p;
    for j in 1..=r {
        l = k - p + j;
        for i in 0..=(p - j - sm) {
            let lo = knots[l + i].clone();
            let hi = knots[i + k + 1].clone();
            let alpha = (t.clone() - lo.clone()) / (hi - lo);
            let one_minus = F::one() - alpha.clone();
            for c in 0..s {
                let v = alpha.clone() * rw[(i + 1) * s + c].clone()
                    + one_minus.clone() * rw[i * s + c].clone();
                rw[i * s + c] = v;
            }
        }
        q[l * s..(l + 1) * s].clone_from_slice(&rw[..s]);
        let last = k + r - j - sm;
        let src = p - j - sm;
        q[last * s..(last + 1) * s].clone_from_slice(&rw[src * s..(src + 1) * s]);
    }
    for i in (l + 1)..(k - sm) {
        q[i * s..(i + 1) * s].clone_from_slice(&rw[(i - l) * s..(i - l + 1) * s]);
    }
    Ok((uq, q))
}

/// A Bézier piece of a NURBS curve: its parameter interval and its control points.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierPiece<F> {
    /// The knot interval `[start, end]` the piece covers (mapped to `[0, 1]`).
    pub interval: (F, F),
    /// The piece as a rational Bézier curve on `[0, 1]`.
    pub curve: BezierCurve<F>,
}

/// A NURBS curve: degree, clamped knot vector, homogeneous control points (weight first).
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsCurve<F> {
    degree: usize,
    dim: usize,
    knots: Vec<F>,
    /// flat homogeneous control points, `num_ctrl · (dim + 1)` entries
    coords: Vec<F>,
}

impl<F: Scalar> NurbsCurve<F> {
    /// From degree, knots and homogeneous control points `(w, wx, …)`.
    ///
    /// # Errors
    /// [`GeomError::Empty`]/[`GeomError::Dimension`] for bad points (as
    /// [`BezierCurve::from_homogeneous`]), knot errors from [`validate_knots`].
    pub fn new(degree: usize, knots: Vec<F>, points: Vec<Vec<F>>) -> Result<Self, GeomError> {
        let as_curve = BezierCurve::from_homogeneous(points)?;
        Self::from_flat(degree, as_curve.dim(), knots, as_curve.coords().to_vec())
    }

    /// From a flat array of homogeneous coordinates (`dim + 1` per control point).
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if the length does not fit, knot errors from
    /// [`validate_knots`].
    pub fn from_flat(
        degree: usize,
        dim: usize,
        knots: Vec<F>,
        coords: Vec<F>,
    ) -> Result<Self, GeomError> {
        let as_curve = BezierCurve::from_flat(dim, coords)?;
        let num_ctrl = as_curve.degree() + 1;
        validate_knots(&knots, degree, num_ctrl)?;
        Ok(NurbsCurve {
            degree,
            dim,
            knots,
            coords: as_curve.coords().to_vec(),
        })
    }

    /// One Bézier curve as a NURBS on `[0, 1]`: knots `[0^{p+1}, 1^{p+1}]`, same points.
    ///
    /// # Errors
    /// [`GeomError::Degree`] for degree 0.
    pub fn from_bezier(curve: &BezierCurve<F>) -> Result<Self, GeomError> {
        Self::from_bezier_on(curve, F::zero(), F::one())
    }

    /// One Bézier curve as a NURBS on `[a, b]`: knots `[a^{p+1}, b^{p+1}]` (the curve is
    /// reparametrised affinely, the control points are unchanged).
    ///
    /// # Errors
    /// [`GeomError::Degree`] for degree 0, [`GeomError::Knots`] unless `a < b`.
    pub fn from_bezier_on(curve: &BezierCurve<F>, a: F, b: F) -> Result<Self, GeomError> {
        let p = curve.degree();
        let mut knots = vec![a; p + 1];
        knots.extend(std::iter::repeat_n(b, p + 1));
        Self::from_flat(p, curve.dim(), knots, curve.coords().to_vec())
    }

    /// Joins Bézier pieces at the integer parameters `0, 1, …, k` (`k` pieces).
    /// See [`Self::from_bezier_pieces_at`].
    ///
    /// # Errors
    /// As [`Self::from_bezier_pieces_at`].
    pub fn from_bezier_pieces(pieces: &[BezierCurve<F>]) -> Result<Self, GeomError> {
        let breaks: Vec<F> = (0..=pieces.len()).map(|i| F::from_i64(i as i64)).collect();
        Self::from_bezier_pieces_at(pieces, &breaks)
    }

    /// Joins Bézier pieces of one degree `p`; piece `k` covers `[breaks[k], breaks[k+1]]`.
    /// Interior knots get multiplicity `p`: knots
    /// `[t₀^{p+1}, t₁^p, …, t_{k−1}^p, t_k^{p+1}]`, control points the pieces' points with
    /// each junction point shared.
    ///
    /// C0 continuity is checked exactly: the end point `E` of piece `k` must equal
    /// `λ S` for the start point `S` of piece `k + 1` and some `λ ≠ 0` (the same
    /// projective point). Piece `k + 1` is then multiplied by `λ` (all its homogeneous
    /// points; the curve is unchanged) so that the junction points coincide.
    ///
    /// # Errors
    /// [`GeomError::Empty`] for no pieces, [`GeomError::Degree`] for differing degrees
    /// or degree 0, [`GeomError::Dimension`] for differing dimensions,
    /// [`GeomError::Knots`] if `breaks` does not have `k + 1` strictly increasing values
    /// or if two consecutive pieces do not meet (no C0 continuity; the message names the
    /// pieces and both points).
    pub fn from_bezier_pieces_at(
        pieces: &[BezierCurve<F>],
        breaks: &[F],
    ) -> Result<Self, GeomError> {
        let first = pieces
            .first()
            .ok_or_else(|| GeomError::Empty("joining needs at least one Bézier piece".into()))?;
        let p = first.degree();
        let dim = first.dim();
        let s = dim + 1;
        if p == 0 {
            return Err(GeomError::Degree(
                "joining needs pieces of degree at least 1".into(),
            ));
        }
        for (k, c) in pieces.iter().enumerate() {
            if c.degree() != p {
                return Err(GeomError::Degree(format!(
                    "piece {k} has degree {}, piece 0 has degree {p}",
                    c.degree()
                )));
            }
            if c.dim() != dim {
                return Err(GeomError::Dimension(format!(
                    "piece {k} lies in E{}, piece 0 in E{dim}",
                    c.dim()
                )));
            }
        }
        if breaks.len() != pieces.len() + 1 {
            return Err(GeomError::Knots(format!(
                "{} pieces need {} breakpoints, got {}",
                pieces.len(),
                pieces.len() + 1,
                breaks.len()
            )));
        }
        if let Some(i) = breaks
            .windows(2)
            .position(|w| w[0].partial_cmp(&w[1]) != Some(Ordering::Less))
        {
            return Err(GeomError::Knots(format!(
                "breakpoints must increase strictly: breakpoint {} = {} is followed by {}",
                i,
                format_scalar(&breaks[i]),
                format_scalar(&breaks[i + 1])
            )));
        }
        let mut coords: Vec<F> = first.coords().to_vec();
        for (k, piece) in pieces.iter().enumerate().skip(1) {
            let end: Vec<F> = coords[coords.len() - s..].to_vec();
            let start = piece.control_point(0);
            let lambda = projective_factor(&end, start).ok_or_else(|| {
                GeomError::Knots(format!(
                    "pieces {} and {k} do not meet at breakpoint {} (C0 needs the end point of \
                     one to equal the start point of the next projectively): end {} vs start {}",
                    k - 1,
                    format_scalar(&breaks[k]),
                    format_vector(&end),
                    format_vector(start)
                ))
            })?;
            for pt in piece.control_points().skip(1) {
                coords.extend(pt.iter().map(|c| lambda.clone() * c.clone()));
            }
        }
        let mut knots = vec![breaks[0].clone(); p + 1];
        for b in &breaks[1..breaks.len() - 1] {
            knots.extend(std::iter::repeat_n(b.clone(), p));
        }
        knots.extend(std::iter::repeat_n(breaks[breaks.len() - 1].clone(), p + 1));
        Self::from_flat(p, dim, knots, coords)
    }

    /// Degree `p`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// Euclidean dimension.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The knot vector.
    pub fn knots(&self) -> &[F] {
        &self.knots
    }

    /// Number of control points `n + 1`.
    pub fn num_control_points(&self) -> usize {
        self.coords.len() / (self.dim + 1)
    }

    /// Homogeneous control point `i`, `None` if out of range.
    pub fn control_point(&self, i: usize) -> Option<&[F]> {
        let s = self.dim + 1;
        self.coords.get(i * s..(i + 1) * s)
    }

    /// All homogeneous control points.
    pub fn control_points(&self) -> impl Iterator<Item = &[F]> {
        self.coords.chunks(self.dim + 1)
    }

    /// The flat homogeneous coordinates.
    pub fn coords(&self) -> &[F] {
        &self.coords
    }

    /// The parameter domain `[u_p, u_{n+1}]`.
    pub fn domain(&self) -> (F, F) {
        (
            self.knots[self.degree].clone(),
            self.knots[self.num_control_points()].clone(),
        )
    }

    /// Multiplicity of the value `t` in the knot vector.
    pub fn knot_multiplicity(&self, t: &F) -> usize {
        self.knots.iter().filter(|k| *k == t).count()
    }

    /// The homogeneous point `P(t)` by de Boor's algorithm (exact for exact `F`).
    ///
    /// # Errors
    /// [`GeomError::Parameter`] if `t` is outside the domain.
    pub fn eval_homogeneous(&self, t: &F) -> Result<Vec<F>, GeomError> {
        let nc = self.num_control_points();
        let p = self.degree;
        let s = self.dim + 1;
        check_domain(&self.knots, p, nc, t)?;
        let k = find_span(&self.knots, p, nc, t);
        let local = self.coords[(k - p) * s..(k + 1) * s].to_vec();
        Ok(de_boor(&self.knots, p, k, local, s, t))
    }

    /// The Euclidean point `P₁..d(t) / P₀(t)`.
    ///
    /// # Errors
    /// [`GeomError::Parameter`] outside the domain, [`GeomError::Weight`] at a point at
    /// infinity.
    pub fn eval(&self, t: &F) -> Result<Vec<F>, GeomError> {
        let h = self.eval_homogeneous(t)?;
        dehomogenize(&h, || format_scalar(t))
    }

    /// The Euclidean point at an `f64` parameter, computed in `f64` (de Boor on the
    /// local knots and points converted to `f64`).
    ///
    /// # Errors
    /// As [`Self::eval`].
    pub fn eval_f64(&self, t: f64) -> Result<Vec<f64>, GeomError> {
        let knots: Vec<f64> = self.knots.iter().map(Scalar::to_f64).collect();
        let nc = self.num_control_points();
        let p = self.degree;
        let s = self.dim + 1;
        check_domain(&knots, p, nc, &t)?;
        let k = find_span(&knots, p, nc, &t);
        let local: Vec<f64> = self.coords[(k - p) * s..(k + 1) * s]
            .iter()
            .map(Scalar::to_f64)
            .collect();
        let h = de_boor(&knots, p, k, local, s, &t);
        dehomogenize(&h, || format!("{t}"))
    }

    /// The same curve with `f64` knots and control points.
    pub fn to_f64(&self) -> NurbsCurve<f64> {
        NurbsCurve {
            degree: self.degree,
            dim: self.dim,
            knots: self.knots.iter().map(Scalar::to_f64).collect(),
            coords: self.coords.iter().map(Scalar::to_f64).collect(),
        }
    }

    /// Inserts the knot `t` `times` times (Boehm, NURBS Book A5.1); the curve is
    /// unchanged (exactly, for exact `F`).
    ///
    /// # Errors
    /// [`GeomError::Parameter`] unless `t` lies strictly inside the domain,
    /// [`GeomError::Knots`] if the multiplicity would exceed the degree.
    pub fn insert_knot(&self, t: &F, times: usize) -> Result<Self, GeomError> {
        let (knots, coords) = insert_knot_flat(
            &self.knots,
            self.degree,
            &self.coords,
            self.dim + 1,
            t,
            times,
        )?;
        Ok(NurbsCurve {
            degree: self.degree,
            dim: self.dim,
            knots,
            coords,
        })
    }

    /// Splits the curve into its Bézier pieces, one per non-empty knot span (NURBS Book
    /// A5.6, by inserting every interior knot up to multiplicity `p`). For a curve made by
    /// [`Self::from_bezier_pieces_at`] this returns the (rescaled) pieces exactly.
    ///
    /// # Errors
    /// None for a valid curve; knot-insertion errors are propagated.
    pub fn to_bezier_pieces(&self) -> Result<Vec<BezierPiece<F>>, GeomError> {
        let p = self.degree;
        let s = self.dim + 1;
        let runs = knot_runs(&self.knots);
        let mut cur = self.clone();
        for (t, m) in &runs[1..runs.len() - 1] {
            if *m < p {
                cur = cur.insert_knot(t, p - m)?;
            }
        }
        let mut out = Vec::with_capacity(runs.len() - 1);
        for (k, w) in runs.windows(2).enumerate() {
            let pts = cur.coords[k * p * s..(k * p + p + 1) * s].to_vec();
            out.push(BezierPiece {
                interval: (w[0].0.clone(), w[1].0.clone()),
                curve: BezierCurve::from_flat(self.dim, pts)?,
            });
        }
        Ok(out)
    }
}

/// `λ` with `e = λ·s`, `λ ≠ 0`, if it exists (exact comparison).
fn projective_factor<F: Scalar>(e: &[F], s: &[F]) -> Option<F> {
    let c = s.iter().position(|x| !x.is_zero())?;
    let lambda = e[c].clone() / s[c].clone();
    if lambda.is_zero() {
        return None;
    }
    let ok = e
        .iter()
        .zip(s)
        .all(|(ei, si)| *ei == lambda.clone() * si.clone());
    ok.then_some(lambda)
}

/// A Bézier patch of a NURBS surface with the knot rectangle it covers.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierPatchPiece<F> {
    /// `u` interval.
    pub u_interval: (F, F),
    /// `v` interval.
    pub v_interval: (F, F),
    /// The patch on `[0, 1]²`.
    pub patch: BezierPatch<F>,
}

/// A tensor-product NURBS surface: bidegree, clamped knot vectors in `u` and `v`,
/// homogeneous control net `Pᵢⱼ` (`i` along `u`, row-major in `i` like [`BezierPatch`]).
/// `P(u, v) = Σᵢ Σⱼ Nᵢ,ₚ(u) Nⱼ,q(v) Pᵢⱼ` (NURBS Book (4.15)).
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsSurface<F> {
    deg_u: usize,
    deg_v: usize,
    dim: usize,
    knots_u: Vec<F>,
    knots_v: Vec<F>,
    n_u: usize,
    n_v: usize,
    coords: Vec<F>,
}

impl<F: Scalar> NurbsSurface<F> {
    /// From bidegree, knot vectors and a control net `net[i][j] = Pᵢⱼ` (homogeneous).
    ///
    /// # Errors
    /// Net errors as [`BezierPatch::from_homogeneous`], knot errors from
    /// [`validate_knots`] for each direction.
    pub fn new(
        degree: (usize, usize),
        knots_u: Vec<F>,
        knots_v: Vec<F>,
        net: Vec<Vec<Vec<F>>>,
    ) -> Result<Self, GeomError> {
        let as_patch = BezierPatch::from_homogeneous(net)?;
        let (mu, mv) = as_patch.degree();
        Self::from_parts(degree, knots_u, knots_v, (mu + 1, mv + 1), as_patch)
    }

    fn from_parts(
        degree: (usize, usize),
        knots_u: Vec<F>,
        knots_v: Vec<F>,
        counts: (usize, usize),
        net: BezierPatch<F>,
    ) -> Result<Self, GeomError> {
        validate_knots(&knots_u, degree.0, counts.0).map_err(|e| prefix_error(e, "u direction"))?;
        validate_knots(&knots_v, degree.1, counts.1).map_err(|e| prefix_error(e, "v direction"))?;
        Ok(NurbsSurface {
            deg_u: degree.0,
            deg_v: degree.1,
            dim: net.dim(),
            knots_u,
            knots_v,
            n_u: counts.0,
            n_v: counts.1,
            coords: net.coords().to_vec(),
        })
    }

    /// One Bézier patch as a NURBS on `[0, 1]²`.
    ///
    /// # Errors
    /// [`GeomError::Degree`] if a degree is 0.
    pub fn from_bezier(patch: &BezierPatch<F>) -> Result<Self, GeomError> {
        Self::from_bezier_on(patch, (F::zero(), F::one()), (F::zero(), F::one()))
    }

    /// One Bézier patch as a NURBS on `[u₀, u₁] × [v₀, v₁]` (clamped knots
    /// `[u₀^{m+1}, u₁^{m+1}]`, `[v₀^{n+1}, v₁^{n+1}]`).
    ///
    /// # Errors
    /// [`GeomError::Degree`] if a degree is 0, [`GeomError::Knots`] for empty intervals.
    pub fn from_bezier_on(
        patch: &BezierPatch<F>,
        u_interval: (F, F),
        v_interval: (F, F),
    ) -> Result<Self, GeomError> {
        let (m, n) = patch.degree();
        let mut ku = vec![u_interval.0; m + 1];
        ku.extend(std::iter::repeat_n(u_interval.1, m + 1));
        let mut kv = vec![v_interval.0; n + 1];
        kv.extend(std::iter::repeat_n(v_interval.1, n + 1));
        Self::from_parts((m, n), ku, kv, (m + 1, n + 1), patch.clone())
    }

    /// Bidegree `(p, q)`.
    pub fn degree(&self) -> (usize, usize) {
        (self.deg_u, self.deg_v)
    }

    /// Euclidean dimension.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Knot vector in `u`.
    pub fn knots_u(&self) -> &[F] {
        &self.knots_u
    }

    /// Knot vector in `v`.
    pub fn knots_v(&self) -> &[F] {
        &self.knots_v
    }

    /// Number of control points in `u` and in `v`.
    pub fn num_control_points(&self) -> (usize, usize) {
        (self.n_u, self.n_v)
    }

    /// Homogeneous control point `Pᵢⱼ`, `None` if out of range.
    pub fn control_point(&self, i: usize, j: usize) -> Option<&[F]> {
        if i >= self.n_u || j >= self.n_v {
            return None;
        }
        let s = self.dim + 1;
        let k = (i * self.n_v + j) * s;
        self.coords.get(k..k + s)
    }

    /// The flat homogeneous coordinates (row-major in `i`).
    pub fn coords(&self) -> &[F] {
        &self.coords
    }

    /// The domain `([u_p, u_{n+1}], [v_q, v_{m+1}])`.
    pub fn domain(&self) -> ((F, F), (F, F)) {
        (
            (
                self.knots_u[self.deg_u].clone(),
                self.knots_u[self.n_u].clone(),
            ),
            (
                self.knots_v[self.deg_v].clone(),
                self.knots_v[self.n_v].clone(),
            ),
        )
    }

    /// The homogeneous point `P(u, v)`: de Boor in `v` on the `p + 1` rows of the `u`
    /// span, then de Boor in `u` on the results (NURBS Book A4.3, with de Boor in place
    /// of the basis functions). Exact for exact `F`.
    ///
    /// # Errors
    /// [`GeomError::Parameter`] outside the domain.
    pub fn eval_homogeneous(&self, u: &F, v: &F) -> Result<Vec<F>, GeomError> {
        eval_surface_generic(
            &self.knots_u,
            &self.knots_v,
            (self.deg_u, self.deg_v),
            (self.n_u, self.n_v),
            self.dim + 1,
            |k| self.coords[k].clone(),
            u,
            v,
        )
    }

    /// The Euclidean point `P₁..d(u, v) / P₀(u, v)`.
    ///
    /// # Errors
    /// [`GeomError::Parameter`] outside the domain, [`GeomError::Weight`] at a point at
    /// infinity.
    pub fn eval(&self, u: &F, v: &F) -> Result<Vec<F>, GeomError> {
        let h = self.eval_homogeneous(u, v)?;
        dehomogenize(&h, || {
            format!("({}, {})", format_scalar(u), format_scalar(v))
        })
    }

    /// The Euclidean point at `f64` parameters, computed in `f64`.
    ///
    /// # Errors
    /// As [`Self::eval`].
    pub fn eval_f64(&self, u: f64, v: f64) -> Result<Vec<f64>, GeomError> {
        let ku: Vec<f64> = self.knots_u.iter().map(Scalar::to_f64).collect();
        let kv: Vec<f64> = self.knots_v.iter().map(Scalar::to_f64).collect();
        let h = eval_surface_generic(
            &ku,
            &kv,
            (self.deg_u, self.deg_v),
            (self.n_u, self.n_v),
            self.dim + 1,
            |k| self.coords[k].to_f64(),
            &u,
            &v,
        )?;
        dehomogenize(&h, || format!("({u}, {v})"))
    }

    /// The same surface with `f64` knots and control points.
    pub fn to_f64(&self) -> NurbsSurface<f64> {
        NurbsSurface {
            deg_u: self.deg_u,
            deg_v: self.deg_v,
            dim: self.dim,
            knots_u: self.knots_u.iter().map(Scalar::to_f64).collect(),
            knots_v: self.knots_v.iter().map(Scalar::to_f64).collect(),
            n_u: self.n_u,
            n_v: self.n_v,
            coords: self.coords.iter().map(Scalar::to_f64).collect(),
        }
    }

    /// Inserts `t` into the `u` knots `times` times (NURBS Book A5.3: A5.1 on every
    /// column `P₀ⱼ … Pₙⱼ`). The surface is unchanged.
    ///
    /// # Errors
    /// As [`NurbsCurve::insert_knot`].
    pub fn insert_knot_u(&self, t: &F, times: usize) -> Result<Self, GeomError> {
        let s = self.dim + 1;
        let mut new_knots = self.knots_u.clone();
        let mut columns = Vec::with_capacity(self.n_v);
        for j in 0..self.n_v {
            let col: Vec<F> = (0..self.n_u)
                .flat_map(|i| {
                    let k = (i * self.n_v + j) * s;
                    self.coords[k..k + s].iter().cloned()
                })
                .collect();
            let (kn, q) = insert_knot_flat(&self.knots_u, self.deg_u, &col, s, t, times)
                .map_err(|e| prefix_error(e, "u direction"))?;
            new_knots = kn;
            columns.push(q);
        }
        let n_u = self.n_u + times;
        let mut coords = Vec::with_capacity(n_u * self.n_v * s);
        for i in 0..n_u {
            for col in &columns {
                coords.extend_from_slice(&col[i * s..(i + 1) * s]);
            }
        }
        Ok(NurbsSurface {
            knots_u: new_knots,
            n_u,
            coords,
            ..self.clone()
        })
    }

    /// Inserts `t` into the `v` knots `times` times (A5.1 on every row `Pᵢ₀ … Pᵢₘ`).
    ///
    /// # Errors
    /// As [`NurbsCurve::insert_knot`].
    pub fn insert_knot_v(&self, t: &F, times: usize) -> Result<Self, GeomError> {
        let s = self.dim + 1;
        let mut new_knots = self.knots_v.clone();
        let mut coords = Vec::with_capacity(self.n_u * (self.n_v + times) * s);
        for row in self.coords.chunks(self.n_v * s) {
            let (kn, q) = insert_knot_flat(&self.knots_v, self.deg_v, row, s, t, times)
                .map_err(|e| prefix_error(e, "v direction"))?;
            new_knots = kn;
            coords.extend(q);
        }
        Ok(NurbsSurface {
            knots_v: new_knots,
            n_v: self.n_v + times,
            coords,
            ..self.clone()
        })
    }

    /// Splits the surface into Bézier patches, one per non-empty knot rectangle, ordered
    /// row-major in `u` (NURBS Book A5.7, by repeated knot insertion).
    ///
    /// # Errors
    /// None for a valid surface; knot-insertion errors are propagated.
    pub fn to_bezier_patches(&self) -> Result<Vec<BezierPatchPiece<F>>, GeomError> {
        let (p, q) = (self.deg_u, self.deg_v);
        let s = self.dim + 1;
        let runs_u = knot_runs(&self.knots_u);
        let runs_v = knot_runs(&self.knots_v);
        let mut cur = self.clone();
        for (t, m) in &runs_u[1..runs_u.len() - 1] {
            if *m < p {
                cur = cur.insert_knot_u(t, p - m)?;
            }
        }
        for (t, m) in &runs_v[1..runs_v.len() - 1] {
            if *m < q {
                cur = cur.insert_knot_v(t, q - m)?;
            }
        }
        let mut out = Vec::new();
        for (a, wu) in runs_u.windows(2).enumerate() {
            for (b, wv) in runs_v.windows(2).enumerate() {
                let mut coords = Vec::with_capacity((p + 1) * (q + 1) * s);
                for i in a * p..=a * p + p {
                    let k = (i * cur.n_v + b * q) * s;
                    coords.extend_from_slice(&cur.coords[k..k + (q + 1) * s]);
                }
                out.push(BezierPatchPiece {
                    u_interval: (wu[0].0.clone(), wu[1].0.clone()),
                    v_interval: (wv[0].0.clone(), wv[1].0.clone()),
                    patch: BezierPatch::from_flat(self.dim, p, q, coords)?,
                });
            }
        }
        Ok(out)
    }
}

fn prefix_error(e: GeomError, what: &str) -> GeomError {
    match e {
        GeomError::Knots(m) => GeomError::Knots(format!("{what}: {m}")),
        GeomError::Degree(m) => GeomError::Degree(format!("{what}: {m}")),
        GeomError::Dimension(m) => GeomError::Dimension(format!("{what}: {m}")),
        GeomError::Parameter(m) => GeomError::Parameter(format!("{what}: {m}")),
        other => other,
    }
}

#[allow(clippy::too_many_arguments)]
fn eval_surface_generic<T: Scalar>(
    knots_u: &[T],
    knots_v: &[T],
    (p, q): (usize, usize),
    (n_u, n_v): (usize, usize),
    s: usize,
    coord: impl Fn(usize) -> T,
    u: &T,
    v: &T,
) -> Result<Vec<T>, GeomError> {
    check_domain(knots_u, p, n_u, u).map_err(|e| prefix_error(e, "u"))?;
    check_domain(knots_v, q, n_v, v).map_err(|e| prefix_error(e, "v"))?;
    let ku = find_span(knots_u, p, n_u, u);
    let kv = find_span(knots_v, q, n_v, v);
    let mut rows = Vec::with_capacity((p + 1) * s);
    for i in ku - p..=ku {
        let local: Vec<T> = (kv - q..=kv)
            .flat_map(|j| (0..s).map(move |c| (i * n_v + j) * s + c))
            .map(&coord)
            .collect();
        rows.extend(de_boor(knots_v, q, kv, local, s, v));
    }
    Ok(de_boor(knots_u, p, ku, rows, s, u))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    fn cubic() -> BezierCurve<Rational> {
        BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(0, 1), q(0, 1)],
            vec![q(2, 1), q(2, 1), q(4, 1)],
            vec![q(1, 2), q(3, 2), q(1, 3)],
            vec![q(1, 1), q(4, 1), q(-1, 1)],
        ])
        .expect("valid")
    }

    /// Direct Bernstein sum, exact.
    fn bezier_exact(c: &BezierCurve<Rational>, t: &Rational) -> Vec<Rational> {
        let n = c.degree();
        let s = c.dim() + 1;
        let one_t = Rational::from(1) - t.clone();
        let mut acc = vec![Rational::from(0); s];
        for i in 0..=n {
            let mut b = Rational::from(1);
            for k in 0..i {
                b = b * Rational::from((n - k) as i64) / Rational::from((k + 1) as i64);
            }
            for _ in 0..i {
                b *= t.clone();
            }
            for _ in 0..n - i {
                b *= one_t.clone();
            }
            for (a, p) in acc.iter_mut().zip(c.control_point(i)) {
                *a += b.clone() * p.clone();
            }
        }
        acc
    }

    #[test]
    fn from_bezier_evaluates_like_bernstein() {
        let c = cubic();
        let nc = NurbsCurve::from_bezier(&c).expect("valid");
        for k in 0..=7 {
            let t = q(k, 7);
            assert_eq!(
                nc.eval_homogeneous(&t).expect("in domain"),
                bezier_exact(&c, &t)
            );
        }
        assert!(matches!(nc.eval(&q(8, 7)), Err(GeomError::Parameter(_))));
    }

    #[test]
    fn knot_insertion_and_decomposition_round_trip() {
        let c = cubic();
        let nc = NurbsCurve::from_bezier_on(&c, q(-1, 1), q(2, 1)).expect("valid");
        let ins = nc.insert_knot(&q(1, 3), 2).expect("insertable");
        assert_eq!(ins.num_control_points(), 6);
        for k in -6..=12 {
            let t = q(k, 6);
            assert_eq!(ins.eval(&t).ok(), nc.eval(&t).ok());
        }
        assert!(matches!(
            ins.insert_knot(&q(1, 3), 2),
            Err(GeomError::Knots(_))
        ));
        assert!(matches!(
            ins.insert_knot(&q(2, 1), 1),
            Err(GeomError::Parameter(_))
        ));
        let pieces = ins.to_bezier_pieces().expect("valid");
        assert_eq!(pieces.len(), 2);
        let joined = NurbsCurve::from_bezier_pieces_at(
            &[pieces[0].curve.clone(), pieces[1].curve.clone()],
            &[q(-1, 1), q(1, 3), q(2, 1)],
        )
        .expect("C0");
        for k in -6..=12 {
            let t = q(k, 6);
            assert_eq!(joined.eval(&t).ok(), nc.eval(&t).ok());
        }
    }

    #[test]
    fn bad_knots_are_typed_errors() {
        let pts = cubic();
        let pts: Vec<Vec<Rational>> = pts.control_points().map(|p| p.to_vec()).collect();
        let k = |v: &[i64]| v.iter().map(|&x| q(x, 1)).collect::<Vec<_>>();
        let bad = [
            k(&[0, 0, 0, 0, 1, 1, 1]),    // too short
            k(&[0, 0, 0, 1, 1, 1, 1, 1]), // not clamped at start
            k(&[0, 0, 0, 0, 1, 1, 1, 0]), // decreasing
            k(&[1, 1, 1, 1, 1, 1, 1, 1]), // empty domain
        ];
        for kv in bad {
            assert!(
                matches!(
                    NurbsCurve::new(3, kv, pts.clone()),
                    Err(GeomError::Knots(_))
                ),
                "should be rejected"
            );
        }
        assert!(matches!(
            NurbsCurve::new(0, k(&[0, 1, 1, 1, 1]), pts.clone()),
            Err(GeomError::Degree(_))
        ));
        // interior multiplicity p + 1
        let mut five = pts.clone();
        five.extend(pts.clone());
        assert!(matches!(
            NurbsCurve::new(3, k(&[0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2]), five.clone()),
            Err(GeomError::Knots(_))
        ));
        let nan = vec![0.0, 0.0, f64::NAN, 1.0, 1.0, 1.0];
        let pts_f = vec![vec![1.0, 0.0], vec![1.0, 1.0], vec![1.0, 2.0]];
        assert!(matches!(
            NurbsCurve::new(2, nan, pts_f),
            Err(GeomError::Knots(_))
        ));
    }

    #[test]
    fn joining_rescales_and_rejects_gaps() {
        let a = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(0, 1)],
            vec![q(1, 1), q(1, 1)],
            vec![q(2, 1), q(4, 1)],
        ])
        .expect("valid");
        // starts at the same projective point (2, 4) ~ (1, 2), scaled by 1/2
        let b = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(2, 1)],
            vec![q(3, 1), q(3, 1)],
            vec![q(1, 1), q(5, 1)],
        ])
        .expect("valid");
        let j = NurbsCurve::from_bezier_pieces(&[a.clone(), b.clone()]).expect("C0");
        assert_eq!(j.knots(), &[0, 0, 0, 1, 1, 2, 2, 2].map(|x| q(x, 1))[..]);
        assert_eq!(j.eval(&q(1, 1)).expect("ok"), vec![q(2, 1)]);
        let pieces = j.to_bezier_pieces().expect("valid");
        assert_eq!(pieces[0].curve, a);
        assert_eq!(pieces[1].curve.control_point(2), &[q(2, 1), q(10, 1)]);
        let c = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(3, 1)],
            vec![q(1, 1), q(3, 1)],
            vec![q(1, 1), q(5, 1)],
        ])
        .expect("valid");
        assert!(matches!(
            NurbsCurve::from_bezier_pieces(&[a.clone(), c]),
            Err(GeomError::Knots(_))
        ));
        assert!(matches!(
            NurbsCurve::<Rational>::from_bezier_pieces(&[]),
            Err(GeomError::Empty(_))
        ));
        assert!(matches!(
            NurbsCurve::from_bezier_pieces_at(
                &[a.clone(), b.clone()],
                &[q(0, 1), q(0, 1), q(1, 1)]
            ),
            Err(GeomError::Knots(_))
        ));
    }

    #[test]
    fn surface_round_trip() {
        let mut net = Vec::new();
        for i in 0..3 {
            let mut row = Vec::new();
            for j in 0..4 {
                let w = q(1 + ((i + 2 * j) % 3) as i64, 2);
                row.push(vec![
                    w.clone(),
                    w.clone() * q(i as i64, 1),
                    w.clone() * q(j as i64, 3),
                    w * q((i * j) as i64 % 5, 7),
                ]);
            }
            net.push(row);
        }
        let patch = BezierPatch::from_homogeneous(net).expect("valid");
        let s = NurbsSurface::from_bezier(&patch).expect("valid");
        let r = s
            .insert_knot_u(&q(1, 3), 1)
            .and_then(|s| s.insert_knot_v(&q(2, 5), 2))
            .expect("insertable");
        for (a, b) in [(0, 0), (1, 7), (3, 5), (7, 7), (2, 3)] {
            let (u, v) = (q(a, 7), q(b, 7));
            assert_eq!(r.eval(&u, &v).ok(), s.eval(&u, &v).ok());
        }
        let pieces = r.to_bezier_patches().expect("valid");
        assert_eq!(pieces.len(), 4);
        // each piece agrees with the surface at its reparametrised points
        for pc in &pieces {
            let one = NurbsSurface::from_bezier_on(
                &pc.patch,
                pc.u_interval.clone(),
                pc.v_interval.clone(),
            )
            .expect("valid");
            let (u0, u1) = pc.u_interval.clone();
            let (v0, v1) = pc.v_interval.clone();
            let u = (u0 + u1) / q(2, 1);
            let v = (v0 * q(1, 3)) + v1 * q(2, 3);
            assert_eq!(one.eval(&u, &v).ok(), s.eval(&u, &v).ok());
        }
        let f = s.eval_f64(0.25, 0.75).expect("ok");
        let e = s.eval(&q(1, 4), &q(3, 4)).expect("ok");
        for (a, b) in f.iter().zip(&e) {
            assert!((a - Scalar::to_f64(b)).abs() < 1e-14);
        }
    }
}
