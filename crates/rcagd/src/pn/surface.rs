//! The PN surface type: point, rational unit normal, support function and cofactor as
//! polynomials in `(u, v)`, with evaluation, Bézier export, certificates and regularity
//! checks (Peternell §4.1; docs/math/laguerre-pn.md).

use super::offset::PnOffset;
use super::poly::{
    self, cancel_common, cancel_gcd, det4, div_exact, dot3, gcd2, identity_cert, mag,
    normalize_content, pad_eval, patch_of, proved, sign_on_domain, zero_cert, Domain, RatFn, Sign,
};
use super::PnError;
use crate::error::{format_point, format_scalar};
use crate::laguerre::OrientedPlane;
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::BezierPatch;

/// A PN surface (Peternell §4.1): the rational point `x = (X₁, X₂, X₃)/W`, the rational
/// unit normal `n = (N₁, N₂, N₃)/N₀` with `N₁² + N₂² + N₃² ≡ N₀²`, the support function
/// `h` of the oriented tangent plane `h + n·x = 0` (docs/math/laguerre-pn.md#conventions), and the
/// cofactor `K` with `W = N₀ K`, all polynomials (or, for `h`, a rational function) in the
/// parameters `(u, v)`.
///
/// The offset at oriented distance `d` is `x_d = x + d n = (X + d K N)/W` with support
/// function `h − d` ([`Self::offset`]; docs/math/laguerre-pn.md#conventions).
#[derive(Debug, Clone)]
pub struct PnSurface<F> {
    point: [MPoly<F>; 4],
    normal: [MPoly<F>; 4],
    support: RatFn<F>,
    cofactor: Option<MPoly<F>>,
    distance: F,
    name: String,
}

impl<F: Scalar> PnSurface<F> {
    /// Assembles a PN surface from its parts, cancelling the given candidate common
    /// factors and normalizing the rational content (exact scalars). `cofactor` must
    /// satisfy `W = N₀·K`; if `None`, `K = W/N₀` is computed (and if `N₀` does not divide
    /// `W`, the point is multiplied through by `N₀`).
    ///
    /// # Errors
    /// [`PnError::NotUnitNormal`] unless `N₁² + N₂² + N₃² ≡ N₀²`;
    /// [`PnError::InvalidInput`] if `W` or `N₀` is the zero polynomial.
    pub(crate) fn assemble(
        name: impl Into<String>,
        point: [MPoly<F>; 4],
        normal: [MPoly<F>; 4],
        support: RatFn<F>,
        cofactor: Option<MPoly<F>>,
        candidates: &[MPoly<F>],
    ) -> Result<Self, PnError> {
        let name = name.into();
        if point[0].is_zero() {
            return Err(PnError::InvalidInput(format!(
                "{name}: the weight W of the point representation is identically zero"
            )));
        }
        if normal[0].is_zero() {
            return Err(PnError::InvalidInput(format!(
                "{name}: the normal denominator N₀ is identically zero"
            )));
        }
        let cert = unit_normal_cert(&normal);
        if !cert.holds {
            return Err(PnError::NotUnitNormal(format!(
                "{name}: N₁² + N₂² + N₃² − N₀² ≢ 0 ({})",
                cert.residual.unwrap_or_default()
            )));
        }
        // normal: cancel common factors, normalize content
        let mut nn: Vec<MPoly<F>> = normal.to_vec();
        cancel_common(&mut nn, candidates);
        cancel_gcd(&mut nn);
        normalize_content(&mut nn);
        if nn[0].terms().last().is_some_and(|(_, c)| *c < F::zero()) {
            // keep N₀ with a positive leading coefficient (N₀ > 0 away from its zeros)
            for p in nn.iter_mut() {
                *p = -p.clone();
            }
        }
        let normal = [nn[0].clone(), nn[1].clone(), nn[2].clone(), nn[3].clone()];
        // point (with cofactor): cancel common factors
        let mut pk: Vec<MPoly<F>> = point.to_vec();
        let k = match cofactor {
            Some(k) => k,
            None => MPoly::zero(2),
        };
        pk.push(k);
        cancel_common(&mut pk, candidates);
        normalize_content(&mut pk[..4]);
        let point = [pk[0].clone(), pk[1].clone(), pk[2].clone(), pk[3].clone()];
        // the candidates once more on the point alone (the cofactor may have lost a factor
        // the four coordinates still share), keeping N₀ | W where it holds: the same
        // cancellation as the gcd below, but also for f64, which has no polynomial gcd
        let mut point = point;
        let keep = div_exact(&point[0], &normal[0]).is_some();
        for c in candidates {
            if c.total_degree().unwrap_or(0) == 0 {
                continue;
            }
            while let Some(qs) = point
                .iter()
                .map(|p| div_exact(p, c))
                .collect::<Option<Vec<_>>>()
            {
                if qs.iter().all(|q| q.is_zero())
                    || (keep && div_exact(&qs[0], &normal[0]).is_none())
                {
                    break;
                }
                point = [qs[0].clone(), qs[1].clone(), qs[2].clone(), qs[3].clone()];
            }
        }
        normalize_content(&mut point);
        // the remaining common factor: all of it if N₀ ∤ W, else only the part that keeps
        // N₀ | W (so that the offsets keep the denominator W)
        let mut g = point.iter().fold(MPoly::zero(2), |g, p| gcd2(&g, p));
        if let Some(k) = div_exact(&point[0], &normal[0]) {
            g = gcd2(&g, &k);
        }
        if g.total_degree().unwrap_or(0) > 0 {
            if let Some(qs) = point
                .iter()
                .map(|p| div_exact(p, &g))
                .collect::<Option<Vec<_>>>()
            {
                point = [qs[0].clone(), qs[1].clone(), qs[2].clone(), qs[3].clone()];
                normalize_content(&mut point);
            }
        }
        // W = N₀·K when N₀ divides W (then offsets keep the denominator W)
        let cofactor = div_exact(&point[0], &normal[0]);
        Ok(PnSurface {
            point,
            normal,
            support,
            cofactor,
            distance: F::zero(),
            name,
        })
    }

    /// A PN surface from a rational point `(W, X₁, X₂, X₃)` and a rational unit normal
    /// `(N₀, N₁, N₂, N₃)` (both homogeneous polynomials in `(u, v)`); the support function
    /// is `h = −n·x`. The normal must be orthogonal to the surface (see [`Certified`]).
    ///
    /// # Errors
    /// As the constructions: [`PnError::NotUnitNormal`] unless `N·N ≡ N₀²`,
    /// [`PnError::InvalidInput`] for zero `W` or `N₀`.
    pub fn from_point_normal(point: [MPoly<F>; 4], normal: [MPoly<F>; 4]) -> Result<Self, PnError> {
        let nx = dot3(&normal[1..], &point[1..]);
        let support = RatFn::new(-nx, &normal[0] * &point[0])?;
        Self::assemble("PN surface", point, normal, support, None, &[])
    }

    /// A copy with another name (used in certificate texts).
    pub fn named(mut self, name: impl Into<String>) -> Self {
        self.name = name.into();
        self
    }

    /// The name used in certificate texts.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The homogeneous point polynomials `(W, X₁, X₂, X₃)`.
    pub fn point_polys(&self) -> &[MPoly<F>; 4] {
        &self.point
    }

    /// The unit normal polynomials `(N₀, N₁, N₂, N₃)`, `n = (N₁, N₂, N₃)/N₀`.
    pub fn normal_polys(&self) -> &[MPoly<F>; 4] {
        &self.normal
    }

    /// The support function `h` (tangent plane `h + n·x = 0`).
    pub fn support(&self) -> &RatFn<F> {
        &self.support
    }

    /// The cofactor `K = W/N₀` when `N₀` divides `W` (then the offsets have the same
    /// denominator `W`; otherwise their denominator is `W N₀`).
    pub fn cofactor(&self) -> Option<&MPoly<F>> {
        self.cofactor.as_ref()
    }

    /// The oriented distance from the surface this one was offset from (0 for a base
    /// surface).
    pub fn distance(&self) -> &F {
        &self.distance
    }

    /// The bidegree `(deg_u, deg_v)` of the point representation.
    pub fn degree(&self) -> (usize, usize) {
        self.point
            .iter()
            .map(poly::bidegree)
            .fold((0, 0), |(a, b), (c, d)| (a.max(c), b.max(d)))
    }

    /// The bidegree of the normal representation.
    pub fn normal_degree(&self) -> (usize, usize) {
        self.normal
            .iter()
            .map(poly::bidegree)
            .fold((0, 0), |(a, b), (c, d)| (a.max(c), b.max(d)))
    }

    fn at(u: &F, v: &F) -> String {
        format_point(&[u.clone(), v.clone()])
    }

    /// The homogeneous point `(W, X₁, X₂, X₃)(u, v)`.
    pub fn eval_homogeneous(&self, u: &F, v: &F) -> [F; 4] {
        let x = [u.clone(), v.clone()];
        std::array::from_fn(|i| pad_eval(&self.point[i], &x).unwrap_or_else(F::zero))
    }

    /// The point `x(u, v)`.
    ///
    /// # Errors
    /// [`PnError::Singular`] where `W(u, v) = 0` (a point at infinity or an undefined
    /// point of the parametrization).
    pub fn eval(&self, u: &F, v: &F) -> Result<[F; 3], PnError> {
        let h = self.eval_homogeneous(u, v);
        let inv = h[0].inv().ok_or_else(|| PnError::Singular {
            what: format!(
                "{}: W = 0 (the point is at infinity or undefined)",
                self.name
            ),
            at: Self::at(u, v),
        })?;
        Ok([1, 2, 3].map(|i| h[i].clone() * inv.clone()))
    }

    /// The unit normal `n(u, v)`.
    ///
    /// # Errors
    /// [`PnError::Singular`] where `N₀(u, v) = 0`.
    pub fn normal_at(&self, u: &F, v: &F) -> Result<[F; 3], PnError> {
        let x = [u.clone(), v.clone()];
        let n: [F; 4] =
            std::array::from_fn(|i| pad_eval(&self.normal[i], &x).unwrap_or_else(F::zero));
        let inv = n[0].inv().ok_or_else(|| PnError::Singular {
            what: format!("{}: N₀ = 0 (the normal is undefined)", self.name),
            at: Self::at(u, v),
        })?;
        Ok([1, 2, 3].map(|i| n[i].clone() * inv.clone()))
    }

    /// The oriented tangent plane `h + n·x = 0` at `(u, v)`.
    ///
    /// # Errors
    /// [`PnError::Singular`] where `N₀` or the denominator of `h` vanishes.
    pub fn tangent_plane(&self, u: &F, v: &F) -> Result<OrientedPlane<F>, PnError> {
        let n = self.normal_at(u, v)?;
        let h = self
            .support
            .eval(&[u.clone(), v.clone()])
            .ok_or_else(|| PnError::Singular {
                what: format!("{}: the support function is undefined", self.name),
                at: Self::at(u, v),
            })?;
        Ok(OrientedPlane::new(h, n)?)
    }

    /// Checks that `W` has no zero on the closed rectangle (so the Bézier patch has
    /// weights of one sign and no point at infinity).
    ///
    /// # Errors
    /// [`PnError::Singular`] naming a parameter point where `W` vanishes, changes sign, or
    /// may vanish (undecided after 256 subdivisions).
    pub fn check_defined(&self, domain: &Domain<F>) -> Result<(), PnError> {
        check_nonzero(
            &self.point[0],
            domain,
            &format!("{}: W = 0 (point at infinity)", self.name),
        )
    }

    /// The rational tensor-product Bézier patch of the point representation on the
    /// rectangle `domain` (local parameters `[0,1]²`), homogeneous control points
    /// `(w, wx, wy, wz)`.
    ///
    /// # Errors
    /// [`PnError::Singular`] if `W` vanishes on the rectangle ([`Self::check_defined`]).
    pub fn patch(&self, domain: &Domain<F>) -> Result<BezierPatch<F>, PnError> {
        self.check_defined(domain)?;
        patch_of(&self.point, domain)
    }

    /// The unit normal as a rational Bézier patch on the unit sphere (homogeneous
    /// `(N₀, N₁, N₂, N₃)`): the Gauss image on the rectangle.
    ///
    /// # Errors
    /// [`PnError::Singular`] if `N₀` vanishes on the rectangle.
    pub fn normal_patch(&self, domain: &Domain<F>) -> Result<BezierPatch<F>, PnError> {
        check_nonzero(&self.normal[0], domain, &format!("{}: N₀ = 0", self.name))?;
        patch_of(&self.normal, domain)
    }

    /// The offset at oriented distance `d`: `x + d n = (X + d K N)/W`, support `h − d`
    /// (docs/math/laguerre-pn.md#conventions; Peternell (4.2) with `h ↦ h − d`). The result has the same
    /// weight `W`, normal and bidegree (up to the degree of `K N`).
    pub fn offset(&self, d: F) -> PnOffset<F> {
        PnOffset::new(self, d)
    }

    /// The same point set with the opposite orientation: unit normal `−n`, support
    /// function `−h` (the oriented plane `h + n·x = 0` with both signs flipped), the same
    /// point polynomials and cofactor. Its offset at distance `d` is the offset of `self`
    /// at `−d`: `x + d(−n) = x − d n` (Peternell §3.1: an oriented plane and its opposite
    /// are distinct elements of Laguerre geometry; docs/math/laguerre-pn.md#orientation).
    pub fn opposite(&self) -> PnSurface<F> {
        let n = &self.normal;
        PnSurface {
            point: self.point.clone(),
            normal: [n[0].clone(), -n[1].clone(), -n[2].clone(), -n[3].clone()],
            support: RatFn {
                num: -self.support.num.clone(),
                den: self.support.den.clone(),
            },
            cofactor: self.cofactor.clone(),
            distance: -self.distance.clone(),
            name: format!("{} (opposite orientation)", self.name),
        }
    }

    /// The surface at offset `d` as a plain PN surface.
    pub(crate) fn offset_surface(&self, d: &F) -> PnSurface<F> {
        // x + d n = (X + dKN)/W if W = N₀K, else (X N₀ + d W N)/(W N₀)
        let (point, cofactor) = match &self.cofactor {
            Some(k) => {
                let kn: Vec<MPoly<F>> = self.normal[1..].iter().map(|n| (k * n).scale(d)).collect();
                (
                    [
                        self.point[0].clone(),
                        &self.point[1] + &kn[0],
                        &self.point[2] + &kn[1],
                        &self.point[3] + &kn[2],
                    ],
                    Some(k.clone()),
                )
            }
            None => {
                let n0 = &self.normal[0];
                let w = &self.point[0];
                let p: [MPoly<F>; 4] = std::array::from_fn(|i| {
                    if i == 0 {
                        w * n0
                    } else {
                        &(&self.point[i] * n0) + &(w * &self.normal[i]).scale(d)
                    }
                });
                (p, Some(w.clone()))
            }
        };
        let support = self.support.sub(&RatFn::constant(d.clone()));
        PnSurface {
            point,
            normal: self.normal.clone(),
            support,
            cofactor,
            distance: self.distance.clone() + d.clone(),
            name: format!("{} offset by {}", self.name, format_scalar(d)),
        }
    }

    /// The regularity polynomial `R = det(X̂, X̂_u, X̂_v, (0, N))` with `X̂ = (W, X)`:
    /// `det(x_u, x_v, n) = R/(W³ N₀)`, so the point map is singular exactly where
    /// `R = 0` (for `W ≠ 0`).
    pub fn regularity_poly(&self) -> MPoly<F> {
        let xu: [MPoly<F>; 4] = std::array::from_fn(|i| self.point[i].partial(0));
        let xv: [MPoly<F>; 4] = std::array::from_fn(|i| self.point[i].partial(1));
        let n = [
            MPoly::zero(2),
            self.normal[1].clone(),
            self.normal[2].clone(),
            self.normal[3].clone(),
        ];
        det4([&self.point, &xu, &xv, &n])
    }

    /// `true` if the point map has rank < 2 everywhere (`det(x_u, x_v, n) ≡ 0`): the
    /// planes envelope a curve or a point, not a surface (e.g. the pencils through the
    /// rulings of a developable surface envelope its edge of regression). Decided by the
    /// regularity determinant at a few exact sample points, and exactly if all vanish.
    pub fn point_map_degenerate(&self) -> bool {
        let samples = [(3i64, 7i64, -2i64, 5i64), (-5, 11, 13, 3), (17, 4, 1, 9)];
        for (a, b, c, d) in samples {
            let (u, v) = (F::from_ratio(a, b), F::from_ratio(c, d));
            let x = [u, v];
            let ev = |p: &MPoly<F>| pad_eval(p, &x).unwrap_or_else(F::zero);
            let row = |f: &dyn Fn(&MPoly<F>) -> MPoly<F>| -> [MPoly<F>; 4] {
                std::array::from_fn(|i| MPoly::constant(2, ev(&f(&self.point[i]))))
            };
            let r0 = row(&|p| p.clone());
            let r1 = row(&|p| p.partial(0));
            let r2 = row(&|p| p.partial(1));
            let r3: [MPoly<F>; 4] = std::array::from_fn(|i| {
                if i == 0 {
                    MPoly::zero(2)
                } else {
                    MPoly::constant(2, ev(&self.normal[i]))
                }
            });
            let d = det4([&r0, &r1, &r2, &r3]);
            let val = d.coeff(&[0, 0]);
            let scale = 1e-9 * mag(&MPoly::constant(2, val.clone())).max(1.0);
            if F::EXACT && !val.is_zero() || !F::EXACT && val.to_f64().abs() > scale * 1e-3 {
                return false;
            }
        }
        self.regularity_poly().is_zero()
    }

    /// Checks that the surface is defined and regular (`W ≠ 0`, `x_u × x_v ≠ 0`) on the
    /// closed rectangle, and returns the certificate of that decision.
    ///
    /// # Errors
    /// [`PnError::Singular`] naming a parameter point where `W` or the regularity
    /// polynomial vanishes (or may vanish).
    pub fn check_regular(&self, domain: &Domain<F>) -> Result<Certificate, PnError> {
        self.check_defined(domain)?;
        check_nonzero(
            &self.regularity_poly(),
            domain,
            &format!("{}: singular point (x_u × x_v = 0)", self.name),
        )?;
        Ok(Certificate::holds(
            format!(
                "{}: W ≠ 0 and det(x_u, x_v, n) ≠ 0 on [{}, {}] × [{}, {}] (Bernstein signs)",
                self.name,
                format_scalar(&domain.u.0),
                format_scalar(&domain.u.1),
                format_scalar(&domain.v.0),
                format_scalar(&domain.v.1)
            ),
            F::EXACT,
        ))
    }

    /// Converts the scalar type (e.g. exact → `f64`).
    pub fn map_scalar<G: Scalar>(&self, f: impl Fn(&F) -> G + Copy) -> PnSurface<G> {
        PnSurface {
            point: std::array::from_fn(|i| self.point[i].map(f)),
            normal: std::array::from_fn(|i| self.normal[i].map(f)),
            support: RatFn {
                num: self.support.num.map(f),
                den: self.support.den.map(f),
            },
            cofactor: self.cofactor.as_ref().map(|k| k.map(f)),
            distance: f(&self.distance),
            name: self.name.clone(),
        }
    }
}

/// Fails with [`PnError::Singular`] unless `p` has no zero on the closed rectangle.
pub(crate) fn check_nonzero<F: Scalar>(
    p: &MPoly<F>,
    domain: &Domain<F>,
    what: &str,
) -> Result<(), PnError> {
    match sign_on_domain(p, domain, 256) {
        Sign::Positive | Sign::Negative => Ok(()),
        Sign::ZeroAt(x) => Err(PnError::Singular {
            what: what.to_string(),
            at: format_point(&x),
        }),
        Sign::Changes(a, b) => Err(PnError::Singular {
            what: format!("{what} (sign change)"),
            at: format!(
                "a point between {} and {}",
                format_point(&a),
                format_point(&b)
            ),
        }),
        Sign::Undecided(x) => Err(PnError::Singular {
            what: format!("{what} (possibly; undecided after subdivision)"),
            at: format!("near {}", format_point(&x)),
        }),
    }
}

/// `N₁² + N₂² + N₃² − N₀² ≡ 0`.
pub(crate) fn unit_normal_cert<F: Scalar>(normal: &[MPoly<F>; 4]) -> Certificate {
    const PROPERTY: &str = "rational unit normal: N₁² + N₂² + N₃² ≡ N₀² (n·n ≡ 1)";
    let [n0, n1, n2, n3] = normal;
    if let Some(c) = proved(
        PROPERTY,
        &[
            (false, &[n1, n1]),
            (false, &[n2, n2]),
            (false, &[n3, n3]),
            (true, &[n0, n0]),
        ],
    ) {
        return c;
    }
    let lhs = dot3(&normal[1..], &normal[1..]);
    let rhs = &normal[0] * &normal[0];
    identity_cert(PROPERTY, &lhs, &rhs)
}

impl<F: Scalar> PnSurface<F> {
    /// The defining identities of a PN surface, as exact polynomial identities in `(u, v)`.
    pub(crate) fn base_certificates(&self) -> Vec<Certificate> {
        let [w, x1, x2, x3] = &self.point;
        let x = [x1.clone(), x2.clone(), x3.clone()];
        let nvec = &self.normal[1..];
        let mut out = vec![unit_normal_cert(&self.normal)];
        if let Some(k) = &self.cofactor {
            const PROPERTY: &str = "W ≡ N₀·K (common denominator of point and offsets)";
            let mut c = proved(PROPERTY, &[(false, &[w]), (true, &[&self.normal[0], k])])
                .unwrap_or_else(|| identity_cert(PROPERTY, w, &(&self.normal[0] * k)));
            c.property = format!("{}: {}", self.name, c.property);
            out.push(c);
        }
        for (k, var) in [(0usize, "u"), (1, "v")] {
            // x_s ∝ X_s W − X W_s
            let ws = w.partial(k);
            let property = format!("{}: n ⟂ x_{var}: N·(X_{var}W − X W_{var}) ≡ 0", self.name);
            let xis: Vec<MPoly<F>> = x.iter().map(|xi| xi.partial(k)).collect();
            let sum: Vec<(bool, [&MPoly<F>; 3])> = (0..3)
                .flat_map(|i| {
                    [
                        (false, [&nvec[i], &xis[i], w]),
                        (true, [&nvec[i], &x[i], &ws]),
                    ]
                })
                .collect();
            let sum: Vec<(bool, &[&MPoly<F>])> = sum.iter().map(|(s, f)| (*s, &f[..])).collect();
            if let Some(c) = proved(&property, &sum) {
                out.push(c);
                continue;
            }
            let xs: Vec<MPoly<F>> = x
                .iter()
                .map(|xi| &(&xi.partial(k) * w) - &(xi * &ws))
                .collect();
            let dotp = dot3(nvec, &xs);
            let scale = 16.0
                * mag(w)
                * mag(w)
                * nvec.iter().map(mag).fold(1.0, f64::max)
                * (1 + dotp.num_terms()) as f64
                * x.iter().map(mag).fold(1.0, f64::max);
            out.push(zero_cert(&property, &dotp, scale));
        }
        // h + n·x = 0  ⇔  h_num N₀ W + h_den N·X ≡ 0
        let property = format!("{}: x on its tangent plane: h + n·x ≡ 0", self.name);
        let (hn, hd) = (&self.support.num, &self.support.den);
        let tangent = proved(
            &property,
            &[
                (false, &[hn, &self.normal[0], w]),
                (false, &[hd, &nvec[0], &x[0]]),
                (false, &[hd, &nvec[1], &x[1]]),
                (false, &[hd, &nvec[2], &x[2]]),
            ],
        );
        out.push(tangent.unwrap_or_else(|| {
            let lhs = &(&self.support.num * &self.normal[0]) * w;
            let rhs = -(&self.support.den * &dot3(nvec, &x));
            identity_cert(&property, &lhs, &rhs)
        }));
        if let Some(first) = out.first_mut() {
            first.property = format!("{}: {}", self.name, first.property);
        }
        out
    }
}

impl<F: Scalar> Certified for PnSurface<F> {
    /// `N·N ≡ N₀²`, `W ≡ N₀K`, `n ⟂ x_u`, `n ⟂ x_v`, `h + n·x ≡ 0`.
    fn certify(&self) -> Vec<Certificate> {
        self.base_certificates()
    }
}

impl<F: Scalar> PartialEq for PnSurface<F> {
    fn eq(&self, other: &Self) -> bool {
        self.point == other.point
            && self.normal == other.normal
            && self.support == other.support
            && self.cofactor == other.cofactor
            && self.distance == other.distance
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pn::poly::{int, var};
    use rcagd_algebra::Rational;

    type Q = Rational;

    /// `x = n = (2u, 2v, S − 1)/(S + 1)`: the unit sphere with its outward normal.
    fn unit_sphere() -> PnSurface<Q> {
        let (u, v) = (var::<Q>(0), var::<Q>(1));
        let s = &(&u * &u) + &(&v * &v);
        let w = &s + &int(1);
        let n = [
            w.clone(),
            u.scale(&Q::from(2)),
            v.scale(&Q::from(2)),
            &s - &int(1),
        ];
        PnSurface::from_point_normal(n.clone(), n).expect("pn")
    }

    #[test]
    fn unit_sphere_as_pn_surface() {
        let surf = unit_sphere();
        assert!(surf.all_hold(), "{:?}", surf.certify());
        assert_eq!(surf.cofactor(), Some(&int(1)));
        let off = surf.offset(Q::from(2));
        assert!(off.all_hold());
        // the offset of the unit sphere by 2 is the sphere of radius 3
        let p = off
            .surface()
            .eval(&Q::from_ratio(1, 3), &Q::from(2))
            .expect("point");
        let r2: Q = p
            .iter()
            .map(|x| x.clone() * x.clone())
            .fold(Q::from(0), |a, b| a + b);
        assert_eq!(r2, Q::from(9));
        let d = Domain::new(Q::from(-1), Q::from(1), Q::from(-1), Q::from(1)).expect("rect");
        assert!(surf.check_regular(&d).is_ok());
        let patch = surf.patch(&d).expect("patch");
        assert_eq!(patch.degree(), (2, 2));
    }

    /// The opposite orientation negates the normal and the support function, keeps the
    /// point, and its offset at `d` is the offset of the original at `−d`.
    #[test]
    fn opposite_orientation_flips_the_normal() {
        let surf = unit_sphere();
        let opp = surf.opposite();
        assert!(opp.all_hold(), "{:?}", opp.certify());
        let (a, b) = (Q::from_ratio(1, 3), Q::from_ratio(-2, 5));
        let n0 = surf.normal_at(&a, &b).expect("normal");
        let n1 = opp.normal_at(&a, &b).expect("normal");
        for k in 0..3 {
            assert_eq!(n1[k], -n0[k].clone());
        }
        assert_eq!(surf.eval(&a, &b).expect("x"), opp.eval(&a, &b).expect("x"));
        let d = Q::from_ratio(1, 2);
        let p = opp.offset(d.clone()).surface().eval(&a, &b).expect("x");
        let q = surf.offset(-d).surface().eval(&a, &b).expect("x");
        assert_eq!(p, q);
        assert!(opp.offset(Q::from(1)).all_hold());
        assert_eq!(opp.opposite(), surf);
    }

    #[test]
    fn non_pythagorean_normal_is_rejected() {
        let (u, v) = (var::<Q>(0), var::<Q>(1));
        let n = [int(1), u.clone(), v.clone(), int(1)];
        assert!(matches!(
            PnSurface::from_point_normal(n.clone(), n),
            Err(PnError::NotUnitNormal(_))
        ));
    }
}
