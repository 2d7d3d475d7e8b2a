//! Interpolation on a quadric as a linear problem (Jüttler §2, docs/math/quadrics.md, "Interpolation on the sphere").
//!
//! Given points `k₁ … k_N` on the quadric, parameters `t₁ … t_N` and a preimage degree
//! `n`, the curve `x(t) = Σ Bⱼⁿ(t) xⱼ` in `E³` must meet the projecting line over each
//! `kᵢ` at `tᵢ`: with two covectors `νᵢ¹, νᵢ²` annihilating the fibre,
//! `νᵢʳ · Σⱼ Bⱼⁿ(tᵢ) xⱼ = 0` (`2N` homogeneous linear equations in `4(n+1)` unknowns).
//! Every admissible solution (`F(x(tᵢ)) ≠ 0` for all `i`) gives the interpolant
//! `y = F(x)` of degree `2n` (docs/math/quadrics.md, "Curves and patches under δ"). The solution space is invariant under the
//! fibre symmetry (δ: `aI+bJ`; ψ: `diag(s,s,1,1)`), which does not change the image; for
//! `N = 2n+1` points in general position on the sphere it has dimension exactly 2, so the
//! interpolant is unique (docs/math/quadrics.md, "Interpolation on the sphere"). On the sphere every irreducible rational curve has
//! even degree `2n` and is a δ-image (Satz 1), so the lowest `n` found by
//! [`interpolate_lowest_degree`] gives the lowest-degree rational interpolant on `K` with
//! the given parameters.
//!
//! **Hermite data** (tangent lines) are linear only once the position of `x(tᵢ)` on its
//! fibre is fixed: `x(tᵢ) ∥ cᵢ = λᵢaᵢ + μᵢbᵢ` (3 equations) and
//! `F̂(cᵢ, x'(tᵢ)) ∈ span(kᵢ, Tᵢ)` (the tangent of `y = F(x)` is `2F̂(x, x')`). The fibre
//! position `(λᵢ : μᵢ)` is therefore a free parameter of the problem ([`HermiteDatum`]);
//! at one point it only fixes the fibre symmetry, at further points it is a genuine shape
//! parameter. (Jüttler announces the linear problem for points only; this is the
//! extension that keeps it linear.)

use super::helpers::{self, fmt_scalar, fmt_vec, to_hom};
use super::image::{
    curve_image, member_candidate, pick_member, pick_member_indexed, rows_for, ImageCurve,
};
use super::{check_on_quadric, GeneralizedProjection, Hom, Mat4, QuadricError};
use crate::Certified;
use rcagd_algebra::{Certificate, Rational, Scalar};
use rcagd_geom::BezierCurve;

/// One interpolation condition: the curve passes through `point` at parameter `t`, and,
/// if `tangent` is given, touches the line through `point` and `tangent` there.
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteDatum<F> {
    /// The parameter.
    pub t: F,
    /// The point on the quadric (homogeneous).
    pub point: Hom<F>,
    /// A second point of the tangent line (e.g. the direction `(0, vx, vy, vz)`); it must
    /// lie in the tangent plane `kᵀ Q T = 0`.
    pub tangent: Option<Hom<F>>,
    /// For a datum with tangent: the position `(λ, μ)` of `x(t) ∥ λa + μb` on the fibre
    /// `[a, b]` ([`GeneralizedProjection::fibre`]). Ignored without tangent.
    pub fibre_position: [F; 2],
}

impl<F: Scalar> HermiteDatum<F> {
    /// A point condition.
    pub fn point(t: F, point: Hom<F>) -> Self {
        HermiteDatum {
            t,
            point,
            tangent: None,
            fibre_position: [F::one(), F::one()],
        }
    }
    /// A point with tangent, fibre position `(1, 1)`.
    pub fn with_tangent(t: F, point: Hom<F>, tangent: Hom<F>) -> Self {
        HermiteDatum {
            t,
            point,
            tangent: Some(tangent),
            fibre_position: [F::one(), F::one()],
        }
    }
}

/// An interpolating curve on the quadric together with the family it was chosen from.
#[derive(Debug, Clone, PartialEq)]
pub struct Interpolant<F> {
    data: Vec<HermiteDatum<F>>,
    degree: usize,
    basis: Vec<BezierCurve<F>>,
    curve: ImageCurve<F>,
    map: Vec<Mat4<F>>,
    name: String,
}

impl<F: Scalar> Interpolant<F> {
    /// The interpolating curve `y = F(x)` on the quadric (degree `2n`).
    pub fn curve(&self) -> &BezierCurve<F> {
        self.curve.image()
    }
    /// The preimage `x` (degree `n`).
    pub fn preimage(&self) -> &BezierCurve<F> {
        self.curve.preimage()
    }
    /// The image construction (with its own certificates).
    pub fn image(&self) -> &ImageCurve<F> {
        &self.curve
    }
    /// The preimage degree `n`.
    pub fn preimage_degree(&self) -> usize {
        self.degree
    }
    /// The degree `2n` of the curve on the quadric.
    pub fn degree(&self) -> usize {
        2 * self.degree
    }
    /// For each datum, the sense of the curve at a given tangent: `Some(Greater)` if
    /// `y'(tᵢ)` points from the point towards the tangent's second point (along the
    /// direction `v` of a tangent `(0, v)`), `Some(Less)` if against, `None` without a
    /// tangent. The interpolation conditions are linear and fix the tangent *line* only; the
    /// sense is an outcome, decided exactly here.
    ///
    /// # Errors
    /// [`QuadricError::Geom`] if the curve has a pole at a datum's parameter.
    pub fn tangent_senses(&self) -> Result<Vec<Option<std::cmp::Ordering>>, QuadricError> {
        self.data
            .iter()
            .map(|d| {
                let Some(tan) = &d.tangent else {
                    return Ok(None);
                };
                let v: Vec<F> = if tan[0].is_zero() {
                    tan[1..].to_vec()
                } else {
                    (1..4)
                        .map(|i| {
                            tan[i].clone() / tan[0].clone()
                                - d.point[i].clone() / d.point[0].clone()
                        })
                        .collect()
                };
                let dy = self.curve().derivative_euclidean(&d.t, 1)?;
                let dot = dy
                    .iter()
                    .zip(&v)
                    .fold(F::zero(), |acc, (a, b)| acc + a.clone() * b.clone());
                Ok(dot.partial_cmp(&F::zero()))
            })
            .collect()
    }

    /// The interpolation data.
    pub fn data(&self) -> &[HermiteDatum<F>] {
        &self.data
    }
    /// A basis of the solution space of the linear problem (preimage curves).
    pub fn solution_basis(&self) -> &[BezierCurve<F>] {
        &self.basis
    }
    /// The dimension of the solution space.
    pub fn dimension(&self) -> usize {
        self.basis.len()
    }
    /// The number of free parameters of the family of interpolants on the quadric: the
    /// projective dimension `dim − 1` of the solution space, minus one for the fibre
    /// symmetry when no fibre position is fixed (pure point data), i.e. `dim − 2`.
    pub fn free_parameters(&self) -> usize {
        let fixed = self.data.iter().any(|d| d.tangent.is_some());
        self.basis.len().saturating_sub(if fixed { 1 } else { 2 })
    }
    /// The member `x = Σ cⱼ·basisⱼ` of the family and its image.
    ///
    /// # Errors
    /// [`QuadricError::Dimension`] for a wrong number of coefficients;
    /// [`QuadricError::NoInterpolant`] if that member is inadmissible (`F(x(tᵢ)) = 0`).
    pub fn member<P: GeneralizedProjection<F> + ?Sized>(
        &self,
        proj: &P,
        coeffs: &[F],
    ) -> Result<ImageCurve<F>, QuadricError> {
        if coeffs.len() != self.basis.len() {
            return Err(QuadricError::Dimension(format!(
                "{} coefficients for a solution space of dimension {}",
                coeffs.len(),
                self.basis.len()
            )));
        }
        let mut v = vec![F::zero(); 4 * (self.degree + 1)];
        for (c, b) in coeffs.iter().zip(&self.basis) {
            for (o, x) in v.iter_mut().zip(b.coords()) {
                *o += c.clone() * x.clone();
            }
        }
        if let Err(why) = admissible(proj, &self.data, self.degree, &v) {
            return Err(QuadricError::NoInterpolant {
                degree: self.degree,
                reason: why,
            });
        }
        let x = BezierCurve::from_flat(3, v)?;
        curve_image(proj, &x)
    }
}

impl<F: Scalar> Certified for Interpolant<F> {
    /// The curve lies on the quadric and equals `F(x)`; `y(tᵢ) ∥ kᵢ` (and `≠ 0`) for every
    /// datum; with a tangent, `y'(tᵢ) ∈ span(kᵢ, Tᵢ)` and `rank[y(tᵢ), y'(tᵢ)] = 2`.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.curve.certify();
        let y = self.curve.image();
        for (i, d) in self.data.iter().enumerate() {
            let yt = helpers::eval_curve(y, &d.t);
            let ok = !helpers::all_negligible(&yt, helpers::magnitude(&yt))
                && helpers::parallel(&yt, &d.point);
            out.push(Certificate::decide(
                format!("y(t{i}) ∥ k{i} at t{i} = {}", fmt_scalar(&d.t)),
                ok,
                F::EXACT,
                || format!("y(t) = {} vs k = {}", fmt_vec(&yt), fmt_vec(&d.point)),
            ));
            if let Some(tan) = &d.tangent {
                let dy = helpers::eval_curve_derivative(y, &d.t);
                let in_span = helpers::rank(&[d.point.to_vec(), tan.to_vec(), dy.to_vec()]) <= 2;
                let regular = helpers::rank(&[yt.to_vec(), dy.to_vec()]) == 2;
                out.push(Certificate::decide(
                    format!("y'(t{i}) lies on the tangent line through k{i} and T{i}, y(t{i}) ∧ y'(t{i}) ≠ 0"),
                    in_span && regular,
                    F::EXACT,
                    || format!("y'(t) = {}", fmt_vec(&dy)),
                ));
            }
        }
        let _ = (&self.map, &self.name);
        out
    }
}

/// Checks that a solution vector is admissible: `F(x(tᵢ)) ≠ 0`, and a regular tangent at
/// Hermite data.
fn admissible<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    data: &[HermiteDatum<F>],
    n: usize,
    v: &[F],
) -> Result<(), String> {
    let x = BezierCurve::from_flat(3, v.to_vec()).map_err(|e| e.to_string())?;
    let scale = helpers::magnitude(v).powi(2);
    for (i, d) in data.iter().enumerate() {
        let xt = helpers::eval_curve(&x, &d.t);
        let yt = proj.apply(&xt);
        if helpers::all_negligible(&yt, scale) {
            return Err(format!(
                "every solution has F(x(t{i})) = 0 (x(t{i}) = 0 or on the exceptional set)"
            ));
        }
        if d.tangent.is_some() {
            let dx = helpers::eval_curve_derivative(&x, &d.t);
            let dy = proj.polar(&xt, &dx);
            if helpers::rank(&[yt.to_vec(), dy.to_vec()]) < 2 {
                return Err(format!("the tangent at t{i} degenerates (y' ∥ y)"));
            }
        }
    }
    let _ = n;
    Ok(())
}

/// Validates the data: finite, on the quadric, distinct parameters, distinct points,
/// tangents in the tangent planes.
fn validate<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    data: &[HermiteDatum<F>],
) -> Result<(), QuadricError> {
    if data.is_empty() {
        return Err(QuadricError::InvalidArgument(
            "no interpolation data".into(),
        ));
    }
    let q = proj.quadric();
    let name = proj.name();
    for (i, d) in data.iter().enumerate() {
        if !helpers::all_finite(std::slice::from_ref(&d.t)) {
            return Err(QuadricError::NotFinite(format!("parameter {i}")));
        }
        check_on_quadric(&q, &d.point, &format!("point {i}"), &name)?;
        for (j, e) in data.iter().enumerate().take(i) {
            if helpers::negligible(
                &(d.t.clone() - e.t.clone()),
                helpers::magnitude(std::slice::from_ref(&d.t)),
            ) {
                return Err(QuadricError::RepeatedParameters(j, i));
            }
            if helpers::parallel(&d.point, &e.point) {
                return Err(QuadricError::RepeatedPoints(j, i));
            }
        }
        if let Some(tan) = &d.tangent {
            super::check_point(tan, &format!("tangent {i}"))?;
            let r = helpers::bilinear(&q, &d.point, tan);
            if !helpers::negligible(
                &r,
                helpers::magnitude(&d.point)
                    * helpers::magnitude(tan)
                    * helpers::magnitude(&q.concat()),
            ) {
                return Err(QuadricError::NotTangent {
                    index: i,
                    residual: fmt_scalar(&r),
                });
            }
            if helpers::parallel(tan, &d.point) {
                return Err(QuadricError::Degenerate(format!(
                    "tangent {i} coincides with its point: give a second point of the tangent line"
                )));
            }
            if !helpers::all_finite(&d.fibre_position)
                || d.fibre_position.iter().all(|x| x.is_zero())
            {
                return Err(QuadricError::InvalidArgument(format!(
                    "fibre position {i} must be a non-zero pair (λ, μ)"
                )));
            }
        }
    }
    Ok(())
}

/// The linear system of the interpolation problem (rows over the `4(n+1)` unknowns).
fn system<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    data: &[HermiteDatum<F>],
    n: usize,
    planes: &[Hom<F>],
    fibres: Option<&[[Hom<Rational>; 2]]>,
) -> Result<Vec<Vec<F>>, QuadricError> {
    let mut rows = Vec::new();
    for (i, d) in data.iter().enumerate() {
        let [a, b] = match fibres {
            None => proj.fibre(&d.point)?,
            Some(f) => {
                let [a, b] = f.get(i).ok_or_else(|| {
                    QuadricError::InvalidArgument(
                        "the recorded fibres do not fit the interpolation data".into(),
                    )
                })?;
                let h = |v: &Hom<Rational>| -> Hom<F> {
                    core::array::from_fn(|k| F::from_rational(&v[k]))
                };
                [h(a), h(b)]
            }
        };
        let w = helpers::bernstein(n, &d.t);
        match &d.tangent {
            None => rows.extend(rows_for(&w, &helpers::annihilator(&[a, b]))),
            Some(tan) => {
                let [l, m] = &d.fibre_position;
                let c = helpers::add4(&helpers::scale4(l, &a), &helpers::scale4(m, &b));
                if helpers::all_negligible(&proj.apply(&c), helpers::magnitude(&c).powi(2)) {
                    return Err(QuadricError::Exceptional {
                        map: proj.name(),
                        point: fmt_vec(&c),
                        reason: format!(
                            "fibre position {i} lies on the exceptional set; choose another (λ, μ)"
                        ),
                    });
                }
                rows.extend(rows_for(
                    &w,
                    &helpers::annihilator(std::slice::from_ref(&c)),
                ));
                let lmat = proj.quadratic_map().polar_matrix(&c);
                let eta = helpers::annihilator(&[d.point.clone(), tan.clone()]);
                let cov: Vec<Hom<F>> = eta
                    .iter()
                    .map(|e| {
                        let lt = helpers::transpose(&lmat);
                        helpers::mat_vec(&lt, e)
                    })
                    .collect();
                let dw = helpers::bernstein_derivative(n, &d.t);
                rows.extend(rows_for(&dw, &cov));
            }
        }
    }
    for pl in planes {
        for j in 0..=n {
            let mut row = vec![F::zero(); 4 * (n + 1)];
            for c in 0..4 {
                row[4 * j + c] = pl[c].clone();
            }
            rows.push(row);
        }
    }
    Ok(rows)
}

fn solve_with<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    data: &[HermiteDatum<F>],
    n: usize,
    planes: &[Hom<F>],
) -> Result<Interpolant<F>, QuadricError> {
    solve_along(proj, data, n, planes, None)
}

/// The decisions of an interpolation of exact data, recorded by [`interpolation_route`]
/// and replayed in another scalar by [`interpolate_hermite_along`], so that an `f64` build
/// solves the same linear problem and takes the same member: the preimage degree `n` (the
/// lowest one is decided exactly: a linear problem without admissible solution), the pivot
/// columns of the interpolation system (its reduced-row-echelon kernel basis: an `f64`
/// rounding residue of an exact 0 is not a pivot, [`crate::cyclide::route::Route::null_space`])
/// and the member of the solution space (the first candidate of the exact admissibility
/// tests, `F(x(tᵢ)) ≠ 0` and regular tangents); and the fibre bases `[a, b]` of the data
/// points (δ chooses between two formulas by an exact zero test, `f64` by magnitude,
/// [`super::stereographic::delta_fibre`]; the fibre position `(λ, μ)` of a tangent datum
/// refers to this basis).
#[derive(Debug, Clone)]
pub struct InterpolationRoute {
    degree: usize,
    fibres: Vec<[Hom<Rational>; 2]>,
    kernel: crate::cyclide::route::Route,
    member: usize,
}

impl InterpolationRoute {
    /// The preimage degree decided.
    pub fn degree(&self) -> usize {
        self.degree
    }
}

fn route_error(e: crate::cyclide::CyclideError) -> QuadricError {
    QuadricError::InvalidArgument(e.to_string())
}

/// The decisions of [`interpolate_hermite`] of exact data at preimage degree `n`
/// ([`InterpolationRoute`]).
///
/// # Errors
/// As [`interpolate_hermite`].
pub fn interpolation_route<P: GeneralizedProjection<Rational> + ?Sized>(
    proj: &P,
    data: &[HermiteDatum<Rational>],
    n: usize,
) -> Result<InterpolationRoute, QuadricError> {
    validate(proj, data)?;
    let fibres = data
        .iter()
        .map(|d| proj.fibre(&d.point))
        .collect::<Result<Vec<_>, _>>()?;
    let rows = system(proj, data, n, &[], Some(&fibres))?;
    let mut kernel = crate::cyclide::route::Route::record();
    let basis = kernel
        .null_space(&pad(rows, 4 * (n + 1)))
        .map_err(route_error)?;
    let (member, _) = pick_member_indexed(&basis, 4, |v| admissible(proj, data, n, v).is_ok())
        .ok_or_else(|| QuadricError::NoInterpolant {
            degree: n,
            reason: "no admissible member".into(),
        })?;
    Ok(InterpolationRoute {
        degree: n,
        fibres,
        kernel,
        member,
    })
}

/// [`interpolate_hermite`] taking the decisions of the exact build (`route`): the degree,
/// the kernel's pivot columns and the member are replayed, every number is computed in `F`,
/// and the member must be admissible in `F` too.
///
/// # Errors
/// As [`interpolate_hermite`]; [`QuadricError::NoInterpolant`] if the replayed member is not
/// admissible in `F`, [`QuadricError::InvalidArgument`] if the route does not fit the data.
pub fn interpolate_hermite_along<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    data: &[HermiteDatum<F>],
    route: &InterpolationRoute,
) -> Result<Interpolant<F>, QuadricError> {
    solve_along(proj, data, route.degree, &[], Some(route))
}

/// Rows padded with zeros to `ncols` entries.
fn pad<F: Scalar>(rows: Vec<Vec<F>>, ncols: usize) -> Vec<Vec<F>> {
    rows.into_iter()
        .map(|mut r| {
            r.resize(ncols, F::zero());
            r
        })
        .collect()
}

fn solve_along<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    data: &[HermiteDatum<F>],
    n: usize,
    planes: &[Hom<F>],
    route: Option<&InterpolationRoute>,
) -> Result<Interpolant<F>, QuadricError> {
    validate(proj, data)?;
    let rows = system(proj, data, n, planes, route.map(|r| r.fibres.as_slice()))?;
    let basis = match route {
        None => helpers::null_space(&rows, 4 * (n + 1)),
        Some(r) => r
            .kernel
            .replay()
            .null_space(&pad(rows.clone(), 4 * (n + 1)))
            .map_err(route_error)?,
    };
    if basis.is_empty() {
        return Err(QuadricError::NoInterpolant {
            degree: n,
            reason: format!(
                "the linear system ({} equations, {} unknowns) has only the zero solution",
                rows.len(),
                4 * (n + 1)
            ),
        });
    }
    let mut last_reason = String::new();
    let v = match route {
        None => pick_member(&basis, 4, |v| match admissible(proj, data, n, v) {
            Ok(()) => true,
            Err(r) => {
                last_reason = r;
                false
            }
        }),
        Some(r) => {
            let v = member_candidate(&basis, 4, r.member).ok_or_else(|| {
                QuadricError::InvalidArgument(
                    "the recorded member is not a candidate of this solution space".into(),
                )
            })?;
            match admissible(proj, data, n, &v) {
                Ok(()) => Some(v),
                Err(why) => {
                    last_reason = format!(
                        "the exact build's member is not admissible in this arithmetic: {why}"
                    );
                    None
                }
            }
        }
    };
    let Some(v) = v else {
        return Err(QuadricError::NoInterpolant {
            degree: n,
            reason: last_reason,
        });
    };
    let x = BezierCurve::from_flat(3, v)?;
    let curve = curve_image(proj, &x)?;
    let basis = basis
        .into_iter()
        .map(|b| BezierCurve::from_flat(3, b))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Interpolant {
        data: data.to_vec(),
        degree: n,
        basis,
        curve,
        map: proj.quadratic_map().matrices().to_vec(),
        name: proj.name(),
    })
}

/// Interpolates the points `kᵢ` at the parameters `tᵢ` by a curve `F(x)` of degree `2n`
/// on the quadric of `proj` (docs/math/quadrics.md, "Interpolation on the sphere"). The returned [`Interpolant`] exposes the
/// solution space (the free parameters) and one admissible member.
///
/// # Errors
/// [`QuadricError::Dimension`] (lengths differ), [`QuadricError::NotOnQuadric`],
/// [`QuadricError::RepeatedParameters`], [`QuadricError::RepeatedPoints`],
/// [`QuadricError::NoInterpolant`] (no admissible solution of this degree).
pub fn interpolate<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    points: &[Hom<F>],
    params: &[F],
    n: usize,
) -> Result<Interpolant<F>, QuadricError> {
    let data = point_data(points, params)?;
    solve_with(proj, &data, n, &[])
}

/// As [`interpolate`], with the preimage restricted to the plane `planeᵀ x = 0`. With δ
/// and the plane `P: p3 = 0` this is interpolation by the ordinary stereographic
/// projection σ (docs/math/quadrics.md, "Interpolation on the sphere", degree comparison: only `3(n+1)` unknowns, so fewer points
/// can be met at the same degree).
///
/// # Errors
/// As [`interpolate`].
pub fn interpolate_in_plane<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    points: &[Hom<F>],
    params: &[F],
    n: usize,
    plane: &Hom<F>,
) -> Result<Interpolant<F>, QuadricError> {
    let data = point_data(points, params)?;
    solve_with(proj, &data, n, std::slice::from_ref(plane))
}

fn point_data<F: Scalar>(
    points: &[Hom<F>],
    params: &[F],
) -> Result<Vec<HermiteDatum<F>>, QuadricError> {
    if points.len() != params.len() {
        return Err(QuadricError::Dimension(format!(
            "{} points but {} parameters",
            points.len(),
            params.len()
        )));
    }
    Ok(points
        .iter()
        .zip(params)
        .map(|(k, t)| HermiteDatum::point(t.clone(), k.clone()))
        .collect())
}

/// Hermite interpolation: points, and tangents where given, with the fibre positions of
/// the tangent data as free parameters (module docs). Preimage degree `n`.
///
/// # Errors
/// As [`interpolate`], and [`QuadricError::NotTangent`] for a tangent outside the tangent
/// plane, [`QuadricError::Exceptional`] for a fibre position where `F` vanishes.
pub fn interpolate_hermite<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    data: &[HermiteDatum<F>],
    n: usize,
) -> Result<Interpolant<F>, QuadricError> {
    solve_with(proj, data, n, &[])
}

/// The interpolant of lowest degree: tries `n = 0, 1, 2, …` up to
/// `⌈(equations)/4⌉ + 2` and returns the first admissible one (for `N` points in general
/// position on the sphere this is `n = ⌈(N−1)/2⌉`, degree `2n`).
///
/// # Errors
/// As [`interpolate_hermite`]; [`QuadricError::NoInterpolant`] if no degree up to the
/// bound works.
pub fn interpolate_lowest_degree<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    data: &[HermiteDatum<F>],
) -> Result<Interpolant<F>, QuadricError> {
    validate(proj, data)?;
    let eqs: usize = data
        .iter()
        .map(|d| if d.tangent.is_some() { 4 } else { 2 })
        .sum();
    let max = eqs.div_ceil(4) + 2;
    let mut last = None;
    for n in 0..=max {
        match solve_with(proj, data, n, &[]) {
            Ok(i) => return Ok(i),
            Err(e @ QuadricError::NoInterpolant { .. }) => last = Some(e),
            Err(e) => return Err(e),
        }
    }
    Err(last.unwrap_or(QuadricError::NoInterpolant {
        degree: max,
        reason: "no degree up to the bound".into(),
    }))
}

/// The points of a curve at the given parameters (convenience for tests and recipes).
pub fn sample_points<F: Scalar>(curve: &BezierCurve<F>, params: &[F]) -> Vec<Hom<F>> {
    params
        .iter()
        .map(|t| to_hom(&helpers::eval_curve(curve, t)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::super::Delta;
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from(p) / Rational::from(d)
    }

    /// The finding of the float path's property test: two points with tangents on the unit
    /// sphere, one of them the south pole (where δ's fibre formula is chosen by the exact
    /// test `k₀ − k₃ ≠ 0`, in `f64` by magnitude). Replaying the exact route (fibres,
    /// pivots, member) gives the exact curve to rounding; the plain `f64` solve gives
    /// another interpolant (another fibre basis, so the fibre position `(1, 1)` is another
    /// point of the fibre).
    #[test]
    fn the_replayed_route_gives_the_exact_interpolant() {
        let zero = Rational::from(0);
        let one = Rational::from(1);
        let data: Vec<HermiteDatum<Rational>> = vec![
            HermiteDatum::with_tangent(
                zero.clone(),
                [one.clone(), zero.clone(), zero.clone(), -one.clone()],
                [zero.clone(), -one.clone(), zero.clone(), zero.clone()],
            ),
            HermiteDatum::with_tangent(
                one.clone(),
                [one.clone(), q(-2, 3), q(-2, 3), q(1, 3)],
                [zero.clone(), q(-1, 3), zero.clone(), q(-2, 3)],
            ),
        ];
        let exact = interpolate_lowest_degree(&Delta, &data).expect("exact");
        let route = interpolation_route(&Delta, &data, exact.preimage_degree()).expect("route");
        let g = |x: Rational| Scalar::to_f64(&x);
        let f = |d: &HermiteDatum<Rational>| HermiteDatum {
            t: Scalar::to_f64(&d.t),
            point: d.point.clone().map(g),
            tangent: d.tangent.clone().map(|v| v.map(g)),
            fibre_position: d.fibre_position.clone().map(g),
        };
        let fdata: Vec<HermiteDatum<f64>> = data.iter().map(f).collect();
        let replayed = interpolate_hermite_along(&Delta, &fdata, &route).expect("f64");
        let plain =
            interpolate_hermite(&Delta, &fdata, exact.preimage_degree()).expect("plain f64");
        // compare up to a common factor: divide by the coordinate of the exact curve's
        // largest |entry|
        let close = |c: &BezierCurve<f64>| {
            let e: Vec<f64> = exact.curve().coords().iter().map(Scalar::to_f64).collect();
            let k = (0..e.len())
                .max_by(|&a, &b| e[a].abs().total_cmp(&e[b].abs()))
                .expect("coordinates");
            let (se, sf) = (e[k], c.coords()[k]);
            e.iter()
                .zip(c.coords())
                .all(|(a, b)| (a / se - b / sf).abs() <= 1e-13)
        };
        assert!(close(replayed.curve()), "{:?}", replayed.curve());
        assert!(
            !close(plain.curve()),
            "the plain f64 solve took the exact route too"
        );
    }
}
