//! PN hypersurfaces of `Rⁿ` from their tangent hyperplanes (Peternell §5.2, (5.3)/(5.4);
//! offset sign corrected: docs/math/n-dimensional.md#pn-hypersurfaces).
//!
//! A [`PnHypersurface`] is a rational field of oriented hyperplanes
//! `E₀ + E₁x₁ + … + Eₙxₙ = 0` in the `n − 1` parameters `u = (u₁, …, u_{n−1})` (polynomials
//! `Eᵢ`, variables `0, …, n − 2`) with a **Pythagorean normal**: a polynomial `L` with
//! `E₁² + … + Eₙ² ≡ L²`, so the unit normal `n = (E₁, …, Eₙ)/L` and the support function
//! `h = E₀/L` are rational. Its points are the envelope `e ∩ e_{u₁} ∩ … ∩ e_{u_{n−1}}`, the
//! generalized cross product `X̂ = (X₀, X₁, …, Xₙ)` of the rows `E, ∂_{u₁}E, …` (signed
//! maximal minors), `x = (X₁, …, Xₙ)/X₀`. The offset at distance `d`, `x_d = x + d n`, is the
//! envelope of `E₀ ↦ E₀ − d L` (`h ↦ h − d`; the printed `h + d` of (5.4) gives `x − d n`).
//!
//! Certificates (exact polynomial identities for `Rational`): `Σ Eᵢ² ≡ L²`, `E·X̂ ≡ 0` (the
//! point on its hyperplane), `n ⟂ ∂_{u_j} x` for every `j`, and for offsets `x_d − x ≡ d n`;
//! and that the point map has rank `n − 1` (exact rank of the tangent vectors at a sample
//! parameter point, which bounds the generic rank from below).

use super::poly::{clean, compose, cross, dot, dot_scale, mag, relabel};
use super::NdimError;
use crate::error::format_scalar;
use crate::pn::poly::{cancel_common, div_exact, patch_of, zero_cert};
use crate::pn::{Domain, RatFn};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::BezierPatch;

/// A PN hypersurface of `Rⁿ` (module docs).
#[derive(Debug, Clone)]
pub struct PnHypersurface<F> {
    name: String,
    plane: Vec<MPoly<F>>,
    norm: MPoly<F>,
    point: Vec<MPoly<F>>,
}

impl<F: Scalar> PnHypersurface<F> {
    /// The envelope of the hyperplane field `E₀ + E·x = 0` with `E₁² + … + Eₙ² ≡ L²`
    /// (`plane = [E₀, …, Eₙ]`, `norm = L`; polynomials in `n − 1` parameters).
    ///
    /// # Errors
    /// [`NdimError::InvalidInput`] for `n < 2`, `L ≡ 0` or a polynomial in more than `n − 1`
    /// variables; [`NdimError::NotUnitNormal`] unless `Σ Eᵢ² ≡ L²`; [`NdimError::Degenerate`]
    /// if the hyperplanes do not envelope a hypersurface (`X₀ ≡ 0`: the analogue of a
    /// developable, §5.2; or a point map of rank < n − 1, e.g. all hyperplanes through one
    /// point).
    pub fn from_plane_field(plane: Vec<MPoly<F>>, norm: MPoly<F>) -> Result<Self, NdimError> {
        let n = plane.len().saturating_sub(1);
        if n < 2 {
            return Err(NdimError::InvalidInput(format!(
                "a hyperplane field of Rⁿ needs n + 1 ≥ 3 coordinates, got {}",
                plane.len()
            )));
        }
        let params = n - 1;
        if let Some(p) = plane.iter().chain(std::iter::once(&norm)).find(|p| {
            p.terms()
                .any(|(e, _)| e.iter().skip(params).any(|&k| k > 0))
        }) {
            return Err(NdimError::InvalidInput(format!(
                "the hyperplane field of R^{n} must depend on the {params} parameters u₁…u_{params} only, got a polynomial in {} variables",
                p.nvars()
            )));
        }
        if norm.is_zero() {
            return Err(NdimError::InvalidInput(
                "the normal length L is the zero polynomial".into(),
            ));
        }
        let plane: Vec<MPoly<F>> = plane.iter().map(|p| pad(p, params)).collect();
        let norm = pad(&norm, params);
        let res = clean(&(&dot(&plane[1..], &plane[1..]) - &(&norm * &norm)));
        if !res.is_zero() {
            return Err(NdimError::NotUnitNormal(format!(
                "E₁² + … + Eₙ² − L² ≢ 0 ({} non-zero terms)",
                res.num_terms()
            )));
        }
        let mut rows = vec![plane.clone()];
        rows.extend((0..params).map(|j| plane.iter().map(|p| p.partial(j)).collect()));
        let mut point: Vec<MPoly<F>> = cross(&rows).iter().map(clean).collect();
        if point[0].is_zero() {
            return Err(NdimError::Degenerate(
                "X₀ ≡ 0: the hyperplanes e, e_u₁, …, e_uₙ₋₁ do not meet in a point (a developable analogue, §5.2)".into(),
            ));
        }
        cancel_common(&mut point, std::slice::from_ref(&norm));
        PnHypersurface {
            name: format!("PN hypersurface of R^{n}"),
            plane,
            norm,
            point,
        }
        .ensure_hypersurface()
    }

    /// The dual form (5.3): `E = (g, 2a₁cf, …, 2a_{n−1}cf, (a₁² + … + a_{n−1}² − c²) f)`,
    /// `L = (a₁² + … + a_{n−1}² + c²) f` (polynomials `aᵢ, c, g, f` in the `n − 1`
    /// parameters, `n = a.len() + 1`).
    ///
    /// # Errors
    /// As [`PnHypersurface::from_plane_field`]; [`NdimError::InvalidInput`] for `c ≡ 0` or
    /// `f ≡ 0`.
    pub fn from_dual(
        a: &[MPoly<F>],
        c: &MPoly<F>,
        g: &MPoly<F>,
        f: &MPoly<F>,
    ) -> Result<Self, NdimError> {
        if c.is_zero() || f.is_zero() {
            return Err(NdimError::InvalidInput(
                "the dual form (5.3) needs c ≢ 0 and f ≢ 0".into(),
            ));
        }
        let s = dot(a, a);
        let cc = c * c;
        let mut plane = vec![g.clone()];
        let two = F::from_i64(2);
        plane.extend(a.iter().map(|ai| (&(ai * c) * f).scale(&two)));
        plane.push(&(&s - &cc) * f);
        Ok(
            Self::from_plane_field(plane, &(&s + &cc) * f)?.named(format!(
                "PN hypersurface of R^{} (dual form (5.3))",
                a.len() + 1
            )),
        )
    }

    /// The normalized form (5.4): unit normal
    /// `(2a₁c, …, 2a_{n−1}c, a₁² + … − c²)/(a₁² + … + c²)` and a rational support
    /// function `h = H/D` (the hyperplanes `h + n·x = 0`).
    ///
    /// # Errors
    /// As [`PnHypersurface::from_dual`].
    pub fn from_support(a: &[MPoly<F>], c: &MPoly<F>, h: &RatFn<F>) -> Result<Self, NdimError> {
        let s = &dot(a, a) + &(c * c);
        Ok(
            Self::from_dual(a, c, &(&h.num * &s), &h.den)?.named(format!(
                "PN hypersurface of R^{} (support function (5.4))",
                a.len() + 1
            )),
        )
    }

    /// The hypersurface `Λ⁻¹(y)` of a rational hypersurface `y = (Y₁/Q, …, Y_{n−1}/Q, Yₙ/Qₙ)`
    /// of the isotropic model `Iⁿ` (Peternell (3.13) in `n` dimensions): the hyperplanes
    /// `(2yₙ, 2y₁, …, 2y_{n−1}, S − 1)/(S + 1)`, `S = y₁² + … + y_{n−1}²`, i.e.
    /// `E = (2YₙQ², 2Y₁QQₙ, …, (ΣY² − Q²)Qₙ)`, `L = (ΣY² + Q²)Qₙ`. The point comes from the
    /// closed formula of docs/math/n-dimensional.md#isotropic-points (an `(n−1)×(n−1)` solve
    /// with the Jacobian of `(y₁, …, y_{n−1})`, cheaper than the general envelope).
    ///
    /// # Errors
    /// [`NdimError::InvalidInput`] for `n < 2` or a zero denominator;
    /// [`NdimError::Degenerate`] if `(y₁, …, y_{n−1})` is not a local coordinate system
    /// (the Gauss image is not `(n−1)`-dimensional); [`NdimError::NotUnitNormal`] cannot
    /// occur.
    pub fn from_isotropic(y: &[MPoly<F>], q: &MPoly<F>, qn: &MPoly<F>) -> Result<Self, NdimError> {
        if q.is_zero() || qn.is_zero() || y.len() < 2 {
            return Err(NdimError::InvalidInput(
                "an isotropic hypersurface needs n ≥ 2 coordinates and non-zero denominators"
                    .into(),
            ));
        }
        let n = y.len();
        let p = n - 1;
        let two = F::from_i64(2);
        let yp = &y[..p];
        let yn = &y[p];
        let s = dot(yp, yp);
        let qq = q * q;
        let sig = &s + &qq;
        let mut plane = vec![(yn * &qq).scale(&two)];
        plane.extend(yp.iter().map(|yi| (&(yi * q) * qn).scale(&two)));
        plane.push(&(&s - &qq) * qn);
        let norm = &sig * qn;
        // J'[i][k] = ∂ᵢY_k Q − Y_k ∂ᵢQ, g_i = ∂ᵢYₙ Qₙ − Yₙ ∂ᵢQₙ
        let jac: Vec<Vec<MPoly<F>>> = (0..p)
            .map(|i| {
                yp.iter()
                    .map(|yk| clean(&(&(&yk.partial(i) * q) - &(yk * &q.partial(i)))))
                    .collect()
            })
            .collect();
        let g: Vec<MPoly<F>> = (0..p)
            .map(|i| clean(&(&(&yn.partial(i) * qn) - &(yn * &qn.partial(i)))))
            .collect();
        let d = clean(&super::poly::det(&jac));
        if d.is_zero() {
            return Err(NdimError::Degenerate(
                "the isotropic coordinates (y₁, …, yₙ₋₁) are not a local coordinate system: the Gauss image is lower-dimensional".into(),
            ));
        }
        let dk: Vec<MPoly<F>> = (0..p)
            .map(|k| {
                let mut m = jac.clone();
                for (i, row) in m.iter_mut().enumerate() {
                    row[k] = -g[i].clone();
                }
                super::poly::det(&m)
            })
            .collect();
        let a = &(&(yn * qn) * &d) + &(q * &dot(yp, &dk));
        let mut point = vec![&(&(qn * qn) * &d) * &sig];
        point.extend(
            (0..p).map(|k| clean(&(&(&(&qq * &dk[k]) * &sig) - &(&(q * &yp[k]) * &a).scale(&two)))),
        );
        point.push(clean(&(&qq * &a).scale(&two)));
        cancel_common(&mut point, &[q.clone(), qn.clone(), d.clone(), sig.clone()]);
        PnHypersurface {
            name: format!("PN hypersurface of R^{n} (isotropic model)"),
            plane,
            norm,
            point,
        }
        .ensure_hypersurface()
    }

    /// A hypersurface from its parts, unchecked (the constructions that know their point map
    /// in closed form; `certify` decides the identities).
    pub(crate) fn from_parts(
        name: String,
        plane: Vec<MPoly<F>>,
        norm: MPoly<F>,
        point: Vec<MPoly<F>>,
    ) -> Self {
        PnHypersurface {
            name,
            plane,
            norm,
            point,
        }
    }

    /// `Ok(self)` if the point map has rank `n − 1` ([`PnHypersurface::rank_certificate`]),
    /// else [`NdimError::Degenerate`] (e.g. all hyperplanes through one point).
    pub(crate) fn ensure_hypersurface(self) -> Result<Self, NdimError> {
        let c = self.rank_certificate();
        if c.holds {
            Ok(self)
        } else {
            Err(NdimError::Degenerate(format!(
                "the envelope is not a hypersurface: {} fails ({})",
                c.property,
                c.residual.unwrap_or_default()
            )))
        }
    }

    /// The same hypersurface under another name.
    #[must_use]
    pub fn named(mut self, name: impl Into<String>) -> Self {
        self.name = name.into();
        self
    }

    /// Its name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The ambient dimension `n`.
    pub fn dim(&self) -> usize {
        self.plane.len() - 1
    }

    /// The number of parameters, `n − 1`.
    pub fn num_params(&self) -> usize {
        self.dim() - 1
    }

    /// The hyperplane coordinates `(E₀, …, Eₙ)`.
    pub fn plane_polys(&self) -> &[MPoly<F>] {
        &self.plane
    }

    /// The normal length `L` (`Σ Eᵢ² ≡ L²`).
    pub fn norm_poly(&self) -> &MPoly<F> {
        &self.norm
    }

    /// The homogeneous point `(X₀, X₁, …, Xₙ)`.
    pub fn point_polys(&self) -> &[MPoly<F>] {
        &self.point
    }

    /// The support function `h = E₀/L` (`h + n·x = 0`).
    pub fn support(&self) -> RatFn<F> {
        RatFn {
            num: self.plane[0].clone(),
            den: self.norm.clone(),
        }
    }

    /// The point at the parameters `u` (`None` where `X₀ = 0`).
    pub fn eval_point(&self, u: &[F]) -> Option<Vec<F>> {
        let v: Vec<F> = self
            .point
            .iter()
            .map(|p| eval(p, u))
            .collect::<Option<_>>()?;
        let inv = v[0].inv()?;
        Some(v[1..].iter().map(|x| x.clone() * inv.clone()).collect())
    }

    /// The unit normal at `u` (`None` where `L = 0`).
    pub fn eval_normal(&self, u: &[F]) -> Option<Vec<F>> {
        let inv = eval(&self.norm, u)?.inv()?;
        self.plane[1..]
            .iter()
            .map(|p| eval(p, u).map(|x| x * inv.clone()))
            .collect()
    }

    /// The offset at oriented distance `d`: the points `x_d = x + d n =
    /// (X L + d X₀ E)/(X₀ L)` (the degree grows by `deg L` only) with the hyperplanes
    /// `E₀ − dL` (`h ↦ h − d`); its certificates check that these points are the envelope of
    /// those hyperplanes (`E_d·X̂_d ≡ 0`, `n ⟂ ∂ⱼx_d`) and `x_d − x ≡ d n`.
    ///
    /// # Errors
    /// None at present (the `Result` is kept for degenerate offsets).
    pub fn offset(&self, d: &F) -> Result<PnHypersurfaceOffset<F>, NdimError> {
        let mut plane = self.plane.clone();
        plane[0] = &plane[0] - &self.norm.scale(d);
        let (x0, l) = (&self.point[0], &self.norm);
        // L | X₀ (X₀ = K L, e.g. an anticaustic): the first division of
        // (X₀L, XᵢL + dX₀Eᵢ) by L is (X₀, Xᵢ + dKEᵢ), formed without dividing the offset's
        // numerators (the same quotient over Q; in f64 a long division by an L of positive
        // degree loses digits: 3.2e-13 relative for an anticaustic of R⁴ with deg L = 10,
        // docs/plans/float.md, session 17); then further factors L as before
        let cofactor = if l.total_degree().unwrap_or(0) > 0 {
            div_exact(x0, l).filter(|k| !k.is_zero())
        } else {
            None
        };
        let mut point = match &cofactor {
            Some(k) => {
                let mut p = vec![x0.clone()];
                p.extend(
                    (1..=self.dim())
                        .map(|i| clean(&(&self.point[i] + &(k * &self.plane[i]).scale(d)))),
                );
                p
            }
            None => {
                let mut p = vec![x0 * l];
                p.extend(
                    (1..=self.dim())
                        .map(|i| clean(&(&(&self.point[i] * l) + &(x0 * &self.plane[i]).scale(d)))),
                );
                p
            }
        };
        cancel_common(&mut point, std::slice::from_ref(l));
        let surface = PnHypersurface {
            name: format!("offset of {} at distance {}", self.name, format_scalar(d)),
            plane,
            norm: self.norm.clone(),
            point,
        };
        Ok(PnHypersurfaceOffset {
            base: self.clone(),
            surface,
            distance: d.clone(),
        })
    }

    /// The 2-parameter slice `u_{free₀}, u_{free₁}` free, every other parameter fixed to
    /// `fixed[i]`, projected orthogonally onto the coordinates `coords` of `Rⁿ`: a
    /// homogeneous map `(X₀, X_{c₀}, X_{c₁}, X_{c₂})(s, t)` in two variables, as a rational
    /// Bézier patch on `domain` — the 3-dimensional picture of a hypersurface of `Rⁿ`.
    ///
    /// # Errors
    /// [`NdimError::InvalidInput`] for out-of-range indices or a `fixed` of the wrong
    /// length; [`NdimError::Degenerate`] if `X₀` vanishes on the domain (decided exactly by
    /// Bernstein signs); a failure of the patch conversion.
    pub fn projected_slice(
        &self,
        free: [usize; 2],
        fixed: &[F],
        coords: [usize; 3],
        domain: &Domain<F>,
    ) -> Result<BezierPatch<F>, NdimError> {
        slice_patch(&self.point, free, fixed, coords, domain)
    }
}

impl<F: Scalar> PnHypersurface<F> {
    /// The point map has rank `n − 1` (it is a hypersurface, not a lower-dimensional set):
    /// the tangent vectors `X₀∂ⱼX − X∂ⱼX₀` evaluated exactly at a parameter point are
    /// independent there (then they are independent generically). Up to eight sample points
    /// are tried; the certificate names the one that proves it.
    pub fn rank_certificate(&self) -> Certificate {
        let (n, p) = (self.dim(), self.num_params());
        let x = &self.point;
        let tangents: Vec<Vec<MPoly<F>>> = (0..p)
            .map(|j| {
                (1..=n)
                    .map(|i| &(&x[i].partial(j) * &x[0]) - &(&x[i] * &x[0].partial(j)))
                    .collect()
            })
            .collect();
        let property = format!("the point map has rank {p} (a hypersurface of R^{n})");
        for s in 0..8i64 {
            let u: Vec<F> = (0..p)
                .map(|j| F::from_ratio(2 * s + 1 + j as i64 * (s + 3), 3 + s + 2 * j as i64))
                .collect();
            let Some(rows) = tangents
                .iter()
                .map(|t| t.iter().map(|c| eval(c, &u)).collect::<Option<Vec<F>>>())
                .collect::<Option<Vec<Vec<F>>>>()
            else {
                continue;
            };
            if numeric_rank(rows) == p {
                return Certificate::holds(
                    format!("{property}, at u = {}", crate::error::format_point(&u)),
                    F::EXACT,
                );
            }
        }
        Certificate::fails(
            property,
            "rank < n − 1 at eight sample parameter points",
            F::EXACT,
        )
    }
}

/// The rank of a matrix of scalars (Gaussian elimination; `f64` pivots below `10⁻⁹` of the
/// largest entry count as zero).
fn numeric_rank<F: Scalar>(mut m: Vec<Vec<F>>) -> usize {
    let tiny = crate::pivot::pivot_zero_test(&m, 1e-9);
    let cols = m.first().map_or(0, Vec::len);
    let mut r = 0;
    for c in 0..cols {
        let Some(piv) = (r..m.len()).find(|&i| !tiny(&m[i][c])) else {
            continue;
        };
        m.swap(r, piv);
        let inv = match m[r][c].inv() {
            Some(v) => v,
            None => continue,
        };
        let pivot_row = m[r].clone();
        for row in m.iter_mut().skip(r + 1) {
            let f = row[c].clone() * inv.clone();
            for (x, p) in row.iter_mut().zip(&pivot_row).skip(c) {
                *x = x.clone() - p.clone() * f.clone();
            }
        }
        r += 1;
    }
    r
}

/// The parameter slice and coordinate projection of a homogeneous point map as a patch
/// (see [`PnHypersurface::projected_slice`]).
pub(crate) fn slice_patch<F: Scalar>(
    point: &[MPoly<F>],
    free: [usize; 2],
    fixed: &[F],
    coords: [usize; 3],
    domain: &Domain<F>,
) -> Result<BezierPatch<F>, NdimError> {
    let n = point.len() - 1;
    let params = point.iter().map(MPoly::nvars).max().unwrap_or(0);
    if free[0] == free[1] || free.iter().any(|&f| f >= params.max(2)) {
        return Err(NdimError::InvalidInput(format!(
            "the two free parameters {free:?} must be distinct indices below {}",
            params.max(2)
        )));
    }
    if fixed.len() != params {
        return Err(NdimError::InvalidInput(format!(
            "the slice needs a value for each of the {params} parameters (the free ones are ignored), got {}",
            fixed.len()
        )));
    }
    if coords.iter().any(|&c| c == 0 || c > n) {
        return Err(NdimError::InvalidInput(format!(
            "the projection coordinates {coords:?} must lie in 1..={n}"
        )));
    }
    let subs: Vec<MPoly<F>> = (0..params)
        .map(|i| {
            if i == free[0] {
                MPoly::var(2, 0)
            } else if i == free[1] {
                MPoly::var(2, 1)
            } else {
                MPoly::constant(2, fixed[i].clone())
            }
        })
        .collect();
    let pick = |i: usize| relabel(&compose(&point[i], &subs), &[0, 1], 2);
    let map = [pick(0), pick(coords[0]), pick(coords[1]), pick(coords[2])];
    match crate::pn::poly::sign_on_domain(&map[0], domain, 256) {
        crate::pn::poly::Sign::Positive | crate::pn::poly::Sign::Negative => {}
        crate::pn::poly::Sign::ZeroAt(p)
        | crate::pn::poly::Sign::Changes(p, _)
        | crate::pn::poly::Sign::Undecided(p) => {
            return Err(NdimError::Degenerate(format!(
                "the slice reaches infinity (X₀ = 0 or undecided) near (s, t) = {} of the domain",
                crate::error::format_point(&p)
            )))
        }
    }
    Ok(patch_of(&map, domain)?)
}

fn pad<F: Scalar>(p: &MPoly<F>, nvars: usize) -> MPoly<F> {
    &MPoly::zero(nvars) + p
}

fn eval<F: Scalar>(p: &MPoly<F>, u: &[F]) -> Option<F> {
    crate::pn::poly::pad_eval(p, u)
}

impl<F: Scalar> Certified for PnHypersurface<F> {
    /// `Σ Eᵢ² ≡ L²`, `E·X̂ ≡ 0` and `Σᵢ Eᵢ (∂ⱼXᵢ X₀ − Xᵢ ∂ⱼX₀) ≡ 0` for every parameter `j`.
    fn certify(&self) -> Vec<Certificate> {
        let n = self.dim();
        let e = &self.plane;
        let x = &self.point;
        let mut out = Vec::new();
        let unit = &dot(&e[1..], &e[1..]) - &(&self.norm * &self.norm);
        out.push(zero_cert(
            &format!("rational unit normal of a hypersurface of R^{n}: E₁² + … + Eₙ² ≡ L²"),
            &unit,
            dot_scale(&e[1..], &e[1..])
                + dot_scale(
                    std::slice::from_ref(&self.norm),
                    std::slice::from_ref(&self.norm),
                ),
        ));
        let on = dot(e, x);
        out.push(zero_cert(
            "point on its tangent hyperplane: E₀X₀ + E₁X₁ + … + EₙXₙ ≡ 0",
            &on,
            dot_scale(e, x),
        ));
        out.push(self.rank_certificate());
        for j in 0..self.num_params() {
            let dx: Vec<MPoly<F>> = (1..=n)
                .map(|i| &(&x[i].partial(j) * &x[0]) - &(&x[i] * &x[0].partial(j)))
                .collect();
            let r = dot(&e[1..], &dx);
            out.push(zero_cert(
                &format!("unit normal ⟂ ∂x/∂u{} (E·(∂X X₀ − X ∂X₀) ≡ 0)", j + 1),
                &r,
                dot_scale(&e[1..], &dx),
            ));
        }
        out
    }
}

/// The offset of a [`PnHypersurface`] at oriented distance `d`, with its base.
#[derive(Debug, Clone)]
pub struct PnHypersurfaceOffset<F> {
    base: PnHypersurface<F>,
    surface: PnHypersurface<F>,
    distance: F,
}

impl<F: Scalar> PnHypersurfaceOffset<F> {
    /// The offset hypersurface (a PN hypersurface with the same normal field).
    pub fn surface(&self) -> &PnHypersurface<F> {
        &self.surface
    }

    /// The base hypersurface.
    pub fn base(&self) -> &PnHypersurface<F> {
        &self.base
    }

    /// The distance `d`.
    pub fn distance(&self) -> &F {
        &self.distance
    }
}

impl<F: Scalar> Certified for PnHypersurfaceOffset<F> {
    /// The PN identities of the offset and `(x_d − x)·L ≡ d·(E₁, …, Eₙ)` componentwise:
    /// `(Xd,ᵢ X₀ − Xᵢ Xd,₀) L ≡ d X₀ Xd,₀ Eᵢ`.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.surface.certify();
        let (b, o) = (&self.base.point, &self.surface.point);
        let e = &self.base.plane;
        let l = &self.base.norm;
        for i in 1..=self.base.dim() {
            let lhs = &(&(&o[i] * &b[0]) - &(&b[i] * &o[0])) * l;
            let rhs = (&(&b[0] * &o[0]) * &e[i]).scale(&self.distance);
            let r = &lhs - &rhs;
            out.push(zero_cert(
                &format!(
                    "offset at distance {}: (x_d − x)_{i} ≡ d·n_{i}",
                    format_scalar(&self.distance)
                ),
                &r,
                16.0 * (mag(&lhs) * (lhs.num_terms().max(1) as f64) + mag(&rhs)),
            ));
        }
        out
    }
}
