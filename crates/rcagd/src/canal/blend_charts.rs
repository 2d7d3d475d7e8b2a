//! The patches that cover a sphere–plane blend ([`super::blend::blend_sphere_plane`]).
//!
//! The blend is `x(t, u) = (X₁, X₂, X₃)/X₀` with `X` polynomial in `(t, u)`, `u` the
//! parameter of the characteristic circles (a rational parametrization of the circle: the
//! whole circle is `u ∈ R ∪ {∞}`). Two charts cover the circle: `u ∈ [−1, 1]` in `X(t, u)`
//! and, with `n = deg_u X`, `u ∈ [−1, 1]` in the reversal `uⁿ X(t, 1/u)` (homogeneous
//! coordinates of the same points, `|u| ≥ 1` of the first chart). When the spine was
//! reparametrized by `t = (a + b s²)/(1 + s²)` (module docs of [`super::blend`]) the
//! parameter `s` runs over `R ∪ {∞}` as well and `t(s) = t(−s)`: `s ∈ [0, 1]` in `X(s, u)` and
//! in `sᵐ X(1/s, u)` (`m = deg_s X`) cover it. Each chart is converted to a Bézier patch
//! on its rectangle ([`super::bipoly::patch_of`]); the charts are homogeneous
//! reparametrizations of one surface (Farin, *Curves and Surfaces for CAGD*, 5th ed.,
//! §13.2 on the projective reparametrization `u → 1/u` of rational Bézier forms).

use super::bipoly::{patch_of, BiPoly};
use super::blend::{InvertedCanal, SpherePlaneBlend};
use super::CanalError;
use rcagd_algebra::{QuadExt, Rational, Scalar};
use rcagd_geom::BezierPatch;

impl<F: Scalar> InvertedCanal<F> {
    /// The chart coordinate lists that cover the surface (module docs): two (`u` and
    /// `1/u`) or, when reparametrized, four (also `s → 1/s`), in the order
    /// `X`, `uⁿX(t, 1/u)`, `sᵐX(1/s, u)`, `uⁿsᵐX(1/s, 1/u)`.
    pub fn charts(&self) -> Vec<Vec<BiPoly<F>>> {
        charts(&self.x, self.reparametrized.is_some())
    }
}

/// The charts of homogeneous coordinates `x` (module docs); `reparametrized`: also `s → 1/s`.
pub fn charts<F: Scalar>(x: &[BiPoly<F>], reparametrized: bool) -> Vec<Vec<BiPoly<F>>> {
    let nu = x.iter().filter_map(BiPoly::degree_u).max().unwrap_or(0);
    let bases: Vec<Vec<BiPoly<F>>> = if reparametrized {
        let nt = x.iter().filter_map(BiPoly::degree_t).max().unwrap_or(0);
        vec![
            x.to_vec(),
            x.iter()
                .map(|c| c.transpose().reverse_u(nt).transpose())
                .collect(),
        ]
    } else {
        vec![x.to_vec()]
    };
    let mut out = Vec::with_capacity(2 * bases.len());
    for base in bases {
        let rev: Vec<BiPoly<F>> = base.iter().map(|c| c.reverse_u(nu)).collect();
        out.push(base);
        out.push(rev);
    }
    out
}

/// The Bézier patches of [`charts`] on `t ∈ [0, 1]`, `u ∈ [−1, 1]`.
///
/// # Errors
/// [`CanalError::InvalidArgument`] if a chart cannot be converted (no coordinates).
pub fn chart_patches<F: Scalar>(
    x: &[BiPoly<F>],
    reparametrized: bool,
) -> Result<Vec<BezierPatch<F>>, CanalError> {
    let (zero, one) = (F::zero(), F::one());
    let m1 = -F::one();
    charts(x, reparametrized)
        .iter()
        .map(|ch| {
            patch_of(ch, (&zero, &one), (&m1, &one))
                .map_err(|e| CanalError::InvalidArgument(e.to_string()))
        })
        .collect()
}

impl<F: Scalar> InvertedCanal<F> {
    /// The Bézier patches covering the whole surface ([`chart_patches`]).
    ///
    /// # Errors
    /// As [`chart_patches`].
    pub fn patches(&self) -> Result<Vec<BezierPatch<F>>, CanalError> {
        chart_patches(&self.x, self.reparametrized.is_some())
    }
}

impl SpherePlaneBlend<QuadExt> {
    /// The homogeneous coordinates over `Q`, when every coefficient is rational.
    pub fn rational_coordinates(&self) -> Option<Vec<BiPoly<Rational>>> {
        self.surface
            .x
            .iter()
            .map(|b| {
                let c = b.all_coeffs();
                c.iter()
                    .all(|c| c.to_rational().is_some())
                    .then(|| b.map_scalar(|c| c.to_rational().unwrap_or_else(|| Rational::from(0))))
            })
            .collect()
    }

    /// The Bézier patches over `Q` covering the blend ([`chart_patches`]), for the exchange
    /// formats (which carry rational geometry only).
    ///
    /// # Errors
    /// [`CanalError::IrrationalSplit`] if the blend has an irrational coefficient (it lives
    /// over `Q(√d)`); as [`chart_patches`].
    pub fn rational_patches(&self) -> Result<Vec<BezierPatch<Rational>>, CanalError> {
        let x = self
            .rational_coordinates()
            .ok_or_else(|| CanalError::IrrationalSplit {
                radicand: self
                    .radicand
                    .as_ref()
                    .map_or_else(|| "d".to_string(), rcagd_algebra::rational::format_rational),
            })?;
        chart_patches(&x, self.surface.reparametrized.is_some())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Poly;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    /// The unit circle `(1 + u², 1 − u², 2u)` (constant in `t`) plus `t` in the last
    /// coordinate: a cylinder chart.
    fn cylinder() -> Vec<BiPoly<Rational>> {
        let u = |c: &[i64]| BiPoly::from_u(&Poly::from_ints(c));
        let t = Poly::from_ints(&[0, 1]);
        vec![
            u(&[1, 0, 1]),
            u(&[1, 0, -1]),
            u(&[0, 2]),
            BiPoly::new(vec![t.clone(), Poly::zero(), t]),
        ]
    }

    #[test]
    fn two_or_four_charts() {
        let x = cylinder();
        assert_eq!(charts(&x, false).len(), 2);
        assert_eq!(charts(&x, true).len(), 4);
        let p = chart_patches(&x, false).unwrap();
        assert_eq!(p.len(), 2);
        // the reversed chart at u = 0 is the point u = ∞ of the first: (1, −1, 0)/1
        let rev = &charts(&x, false)[1];
        let at = |k: usize| rev[k].eval(&q(0), &q(0));
        assert_eq!((at(0), at(1), at(2)), (q(1), q(-1), q(0)));
    }
}
