//! Offsets of PN surfaces at rational distances, with certificates, and where they
//! degenerate (Peternell §4.1, (3.4), (3.15) and (4.2) corrected: docs/math/laguerre-pn.md#conventions: `x_d = x + d n` ⇔ `e0 ↦ e0 − d` ⇔ `r ↦ r + d` ⇔ `y₃ ↦ y₃ − (d/2)(S + 1)`).
//!
//! The offset of a [`PnSurface`] `x = X/W`, `n = N/N₀`, `W = N₀K` is
//! `x_d = (X + d K N)/W` — exact, of the same denominator. It is singular where `d` is a
//! principal radius of curvature: with `R(d) = det(X̂_d, ∂_uX̂_d, ∂_vX̂_d, (0, N))`
//! (`X̂_d = (W, X + dKN)`), `det((x_d)_u, (x_d)_v, n) = R(d)/(W³N₀)` and `R(d)` is a
//! quadratic polynomial in `d` at every parameter point whose roots are the two principal
//! radii there ([`PnOffset::principal_radii_at`]).

use super::poly::{abs_mpoly, identity_cert_within, proved, Domain};
use super::surface::{check_nonzero, PnSurface};
use super::PnError;
use crate::error::{format_point, format_scalar};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::BezierPatch;

/// The offset of a PN surface at oriented distance `d`, with its base surface.
#[derive(Debug, Clone)]
pub struct PnOffset<F> {
    base: PnSurface<F>,
    surface: PnSurface<F>,
    distance: F,
}

impl<F: Scalar> PnOffset<F> {
    pub(crate) fn new(base: &PnSurface<F>, d: F) -> Self {
        PnOffset {
            base: base.clone(),
            surface: base.offset_surface(&d),
            distance: d,
        }
    }

    /// The offset surface (a PN surface with the same normal field).
    pub fn surface(&self) -> &PnSurface<F> {
        &self.surface
    }

    /// The surface it is the offset of.
    pub fn base(&self) -> &PnSurface<F> {
        &self.base
    }

    /// The oriented distance `d`.
    pub fn distance(&self) -> &F {
        &self.distance
    }

    /// The rational Bézier patch of the offset on a parameter rectangle.
    ///
    /// # Errors
    /// [`PnError::Singular`] if `W` vanishes on the rectangle.
    pub fn patch(&self, domain: &Domain<F>) -> Result<BezierPatch<F>, PnError> {
        self.surface.patch(domain)
    }

    /// The regularity polynomial `R(d)(u, v)` of the offset (module docs).
    pub fn regularity_poly(&self) -> MPoly<F> {
        self.surface.regularity_poly()
    }

    /// The coefficients `(c₀, c₁, c₂)` of `R(δ) = c₀ + c₁δ + c₂δ²` at `(u, v)` for the
    /// offsets of the base surface: the offset at distance `δ` is singular at `(u, v)` iff
    /// `R(δ) = 0`; the roots are the principal radii of curvature of the base surface there
    /// (infinite where `c₂ = 0`, e.g. at parabolic points).
    pub fn principal_radii_at(&self, u: &F, v: &F) -> [F; 3] {
        principal_radii_at(&self.base, u, v)
    }

    /// Checks that the offset is defined and regular on the rectangle.
    ///
    /// # Errors
    /// [`PnError::Singular`] where `W` vanishes; [`PnError::OffsetDegenerates`] naming a
    /// parameter point where the offset is (or may be) singular, with the principal radii
    /// there.
    pub fn check_regular(&self, domain: &Domain<F>) -> Result<Certificate, PnError> {
        self.surface.check_defined(domain)?;
        match check_nonzero(&self.regularity_poly(), domain, "singular offset point") {
            Ok(()) => Ok(Certificate::holds(
                format!(
                    "offset at distance {} is regular on [{}, {}] × [{}, {}] (Bernstein signs of det(x_u, x_v, n))",
                    format_scalar(&self.distance),
                    format_scalar(&domain.u.0),
                    format_scalar(&domain.u.1),
                    format_scalar(&domain.v.0),
                    format_scalar(&domain.v.1)
                ),
                F::EXACT,
            )),
            Err(PnError::Singular { what, at }) => Err(PnError::OffsetDegenerates {
                distance: format_scalar(&self.distance),
                at,
                detail: format!(
                    "{what}; the distance equals a principal radius of curvature of {} there",
                    self.base.name()
                ),
            }),
            Err(e) => Err(e),
        }
    }
}

/// `(c₀, c₁, c₂)` of the quadratic `R(δ)` at `(u, v)` (see [`PnOffset::principal_radii_at`]).
pub fn principal_radii_at<F: Scalar>(surface: &PnSurface<F>, u: &F, v: &F) -> [F; 3] {
    let r = |d: F| {
        let s = surface.offset_surface(&d);
        super::poly::pad_eval(&s.regularity_poly(), &[u.clone(), v.clone()]).unwrap_or_else(F::zero)
    };
    let r0 = r(F::zero());
    let rp = r(F::one());
    let rm = r(-F::one());
    let half = F::one() / F::from_i64(2);
    let c1 = (rp.clone() - rm.clone()) * half.clone();
    let c2 = (rp + rm) * half - r0.clone();
    [r0, c1, c2]
}

/// The real roots (as `f64`) of `c₀ + c₁δ + c₂δ²`: the principal radii of curvature; an
/// empty vector if there is none (umbilic-free elliptic points always have two).
pub fn quadratic_roots_f64<F: Scalar>(c: &[F; 3]) -> Vec<f64> {
    let (c0, c1, c2) = (c[0].to_f64(), c[1].to_f64(), c[2].to_f64());
    if c2 == 0.0 {
        return if c1 == 0.0 { vec![] } else { vec![-c0 / c1] };
    }
    let disc = c1 * c1 - 4.0 * c2 * c0;
    if disc < 0.0 {
        return vec![];
    }
    let s = disc.sqrt();
    let mut r = vec![(-c1 - s) / (2.0 * c2), (-c1 + s) / (2.0 * c2)];
    r.sort_by(f64::total_cmp);
    r
}

impl<F: Scalar> Certified for PnOffset<F> {
    /// The PN identities of the offset surface and `x_d − x ≡ d n`:
    /// `(X_d W − X W_d)·N₀ − d·W·W_d·N ≡ 0` componentwise.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.surface.certify();
        let b = self.base.point_polys();
        let o = self.surface.point_polys();
        let n = self.base.normal_polys();
        // magnitudes only for f64 (an exact residual must vanish)
        let mags = (!F::EXACT).then(|| {
            (
                b.each_ref().map(abs_mpoly),
                o.each_ref().map(abs_mpoly),
                n.each_ref().map(abs_mpoly),
            )
        });
        let dabs = self.distance.to_f64().abs();
        let d = MPoly::constant(2, self.distance.clone());
        for (i, name) in [(1usize, "x"), (2, "y"), (3, "z")] {
            let property = format!(
                "offset point at distance {} along the unit normal ({name}): (x_d − x) ≡ d·n",
                format_scalar(&self.distance)
            );
            // exact: O_i B₀ N₀ − B_i O₀ N₀ − d B₀ O₀ N_i ≡ 0 decided in integers
            let terms: [(bool, &[&MPoly<F>]); 3] = [
                (false, &[&o[i], &b[0], &n[0]]),
                (true, &[&b[i], &o[0], &n[0]]),
                (true, &[&d, &b[0], &o[0], &n[i]]),
            ];
            if let Some(c) = proved(&property, &terms) {
                out.push(c);
                continue;
            }
            let lhs = &(&(&o[i] * &b[0]) - &(&b[i] * &o[0])) * &n[0];
            let rhs = (&(&b[0] * &o[0]) * &n[i]).scale(&self.distance);
            // the terms' magnitudes: (|O_i||B₀| + |B_i||O₀|)|N₀| + |d||B₀||O₀||N_i|
            let mag = match &mags {
                Some((ba, oa, na)) => {
                    &(&(&(&oa[i] * &ba[0]) + &(&ba[i] * &oa[0])) * &na[0])
                        + &(&(&ba[0] * &oa[0]) * &na[i]).scale(&dabs)
                }
                None => MPoly::zero(o[i].nvars()),
            };
            out.push(identity_cert_within(&property, &lhs, &rhs, &mag));
        }
        let sn = self.surface.normal_polys();
        out.push(Certificate::decide(
            "the offset has the same rational unit normal field",
            sn == n,
            F::EXACT,
            || format!("normal {} differs", format_point(&[F::zero()])),
        ));
        out
    }
}

impl<F: Scalar> PartialEq for PnOffset<F> {
    fn eq(&self, other: &Self) -> bool {
        self.base == other.base && self.surface == other.surface && self.distance == other.distance
    }
}
