//! Exact twist-free sweeps: a rational plane profile carried along an RRMF curve by its
//! rational rotation-minimizing frame (docs/math/rrmf.md, "Sweeps").
//!
//! With the frame `f_k = F_k/d` of [`RationalRmf`] and the profile
//! `(x(u), y(u)) = (X(u), Y(u))/W(u)` (a rational Bézier curve in the plane, weights
//! `ω_j > 0`), the swept surface
//!
//! `S(t, u) = r(t) + x(u) f_1(t) + y(u) f_2(t)
//!          = [r(t) d(t) W(u) + X(u) F_1(t) + Y(u) F_2(t)] / (d(t) W(u))`
//!
//! is a rational tensor-product Bézier patch of bidegree `(q, max(deg r + deg d, deg F))`
//! (profile degree `q` in `u`, curve parameter `t` in `v`) whose homogeneous control points
//! are sums of products of Bernstein coefficients. Its weights `d_k ω_j` are positive
//! where the Bernstein coefficients `d_k` of `d > 0` are; otherwise the patch is bisected
//! in `t` (exact restrictions) until they are ([`rcagd_geom::weight_sign`]). The profile
//! is not turned about the tangent anywhere (sweeps by rotation-minimizing frames: Wang,
//! Jüttler, Zheng, Liu 2008, "Computation of rotation minimizing frames", ACM Trans.
//! Graph. 27; Farouki, Sakkalis 2010, "Rational rotation-minimizing frames on polynomial
//! space curves of arbitrary degree", J. Symb. Comput. 45).

use super::rrmf::RationalRmf;
use super::util::*;
use super::PhError;
use rcagd_algebra::bernstein;
use rcagd_algebra::{Certificate, Poly, Scalar};
use rcagd_geom::weight_sign::{split_patches_adaptive, SignRule};
use rcagd_geom::BezierPatch;

/// A profile swept along an RRMF curve.
#[derive(Debug, Clone, PartialEq)]
pub struct RmfSweep<F> {
    /// The curve and its rational RMF.
    pub rmf: RationalRmf<F>,
    /// Profile control points `(x_j, y_j)` in the normal plane (`x` along `f_1`).
    pub profile: Vec<[F; 2]>,
    /// Profile weights `ω_j > 0`.
    pub weights: Vec<F>,
    /// The unsplit patch (`u`: profile, `v`: curve parameter `t ∈ [0, 1]`).
    pub patch: BezierPatch<F>,
    /// Pieces with all weights `> 0` (exact restrictions of `patch` to `t`-intervals).
    pub pieces: Vec<BezierPatch<F>>,
    /// `ρ·κ < 1` on `[0, 1]` for a rational `ρ ≥ max_j |(x_j, y_j)|` (no local
    /// self-intersection), decided exactly ([`check_sweep_regularity`]).
    pub regularity: Certificate,
}

/// The sweep is locally regular where `1 − κ⟨p(u), n⟩ ≠ 0` (`p` the profile point, `n` the
/// principal normal; `S_t = r′(1 − κ⟨p, n⟩)` up to a normal-plane term of the RMF, which
/// turns no profile point about the tangent); `|p(u)| ≤ ρ = max_j |(x_j, y_j)|` by the convex
/// hull of the profile (weights `> 0`), so `ρ·κ < 1` on `[0, 1]` suffices. That is the pipe
/// condition of radius `ρ`, decided exactly by [`crate::canal::check_pipe_regularity`]
/// (`F = |P|⁶ − ρ²W⁴|P × P′|² > 0`, docs/math/pipes.md, "Regularity"); `ρ` is a 3-digit
/// rational upper bound of the square root. An `f64` curve is checked through the exact
/// rationals its `f64` coefficients are.
///
/// # Errors
/// [`PhError::Degenerate`] naming the interval where `ρ·κ ≥ 1` or the tangent vanishes;
/// [`PhError::OutOfRange`] for a non-finite coefficient.
pub fn check_sweep_regularity<F: Scalar>(
    curve: &super::PhCurve<F>,
    profile: &[[F; 2]],
) -> Result<Certificate, PhError> {
    use rcagd_algebra::Rational;
    let bad = || PhError::OutOfRange("a non-finite curve or profile coefficient".into());
    let mut rho2 = Rational::ZERO;
    for p in profile {
        let (x, y) = (
            p[0].to_rational().ok_or_else(bad)?,
            p[1].to_rational().ok_or_else(bad)?,
        );
        let n = &x * &x + &y * &y;
        if n > rho2 {
            rho2 = n;
        }
    }
    let rho = super::approximation::sqrt_upper_decimal(&rho2);
    let pos = curve.position();
    let mut exact: Vec<Poly<Rational>> = Vec::with_capacity(3);
    for p in &pos {
        let c: Option<Vec<Rational>> = p.coeffs().iter().map(Scalar::to_rational).collect();
        exact.push(Poly::new(c.ok_or_else(bad)?));
    }
    let [x, y, z] = <[Poly<Rational>; 3]>::try_from(exact).map_err(|_| bad())?;
    let spine = crate::canal::CanalSpine::polynomial([x, y, z], Poly::constant(rho.clone()));
    let (zero, one) = (Rational::ZERO, Rational::ONE);
    crate::canal::check_pipe_regularity(&spine, (&zero, &one)).map_err(|e| {
        PhError::Degenerate(format!(
            "the profile reaches ρ = {} from the curve (the largest |(x_j, y_j)|, rounded up), so the sweep may intersect itself: {e}",
            rcagd_algebra::format_scalar(&rho)
        ))
    })
}

/// Sweeps the rational profile (control points `(x_j, y_j)`, weights `ω_j`) along the
/// curve of `rmf`.
///
/// # Errors
/// [`PhError::DegreeMismatch`] if there are fewer than 2 profile points or the weights do
/// not match them; [`PhError::OutOfRange`] for a weight `≤ 0`; [`PhError::Degenerate`] if
/// all profile points are equal (a point profile sweeps a curve), or if the frame's denominator `d` vanishes on `[0, 1]` (a singular point of the curve, where
/// no split gives positive weights), or if the profile reaches the curve's radius of
/// curvature ([`check_sweep_regularity`]); [`PhError::Geom`] from the patch constructor.
pub fn sweep_profile<F: Scalar>(
    rmf: &RationalRmf<F>,
    profile: &[[F; 2]],
    weights: &[F],
) -> Result<RmfSweep<F>, PhError> {
    if profile.len() < 2 {
        return Err(PhError::DegreeMismatch(format!(
            "a profile needs at least 2 control points, got {}",
            profile.len()
        )));
    }
    if weights.len() != profile.len() {
        return Err(PhError::DegreeMismatch(format!(
            "{} profile weights for {} profile points",
            weights.len(),
            profile.len()
        )));
    }
    if let Some(j) = weights.iter().position(|w| *w <= F::zero()) {
        return Err(PhError::OutOfRange(format!(
            "profile weight {j} is {} but every weight must be > 0",
            fmt_scalar(&weights[j])
        )));
    }
    if profile.iter().all(|p| *p == profile[0]) {
        return Err(PhError::Degenerate(
            "all profile control points are equal: the profile is a point, so the sweep \
             would be a curve (a translate of the spine), not a surface"
                .into(),
        ));
    }
    let r = rmf.curve.position();
    let rd: [Poly<F>; 3] = [&r[0] * &rmf.den, &r[1] * &rmf.den, &r[2] * &rmf.den];
    let deg = |p: &Poly<F>| p.degree().unwrap_or(0);
    let nt = rd
        .iter()
        .chain(rmf.f1.iter())
        .chain(rmf.f2.iter())
        .map(deg)
        .max()
        .unwrap_or(0)
        .max(deg(&rmf.den));
    let bz = |p: &Poly<F>| bernstein::to_bernstein(p, nt).map_err(PhError::Algebra);
    let db = bz(&rmf.den)?;
    let rdb = [bz(&rd[0])?, bz(&rd[1])?, bz(&rd[2])?];
    let f1b = [bz(&rmf.f1[0])?, bz(&rmf.f1[1])?, bz(&rmf.f1[2])?];
    let f2b = [bz(&rmf.f2[0])?, bz(&rmf.f2[1])?, bz(&rmf.f2[2])?];
    let net: Vec<Vec<Vec<F>>> = profile
        .iter()
        .zip(weights)
        .map(|(pt, w)| {
            let xw = pt[0].clone() * w.clone();
            let yw = pt[1].clone() * w.clone();
            (0..=nt)
                .map(|k| {
                    let mut h = vec![db[k].clone() * w.clone()];
                    for c in 0..3 {
                        h.push(
                            rdb[c][k].clone() * w.clone()
                                + f1b[c][k].clone() * xw.clone()
                                + f2b[c][k].clone() * yw.clone(),
                        );
                    }
                    h
                })
                .collect()
        })
        .collect();
    let mut regularity = check_sweep_regularity(&rmf.curve, profile)?;
    // for f64 the decision is exact about the binary values of the f64 curve, but it
    // certifies an f64 construction, whose certificates are tolerance checks: not a proof
    // about the exact input's sweep
    regularity.exact &= F::EXACT;
    let patch = BezierPatch::from_homogeneous(net)?;
    let split = split_patches_adaptive(vec![patch.clone()], SignRule::Positive, (6, 0))?;
    if split.failed > 0 {
        return Err(PhError::Degenerate(
            "the frame denominator d(t) = σ|w|²/g has a zero on [0, 1] (a singular point of the \
             curve): no split in t gives positive weights"
                .into(),
        ));
    }
    Ok(RmfSweep {
        rmf: rmf.clone(),
        profile: profile.to_vec(),
        weights: weights.to_vec(),
        patch,
        pieces: split.pieces,
        regularity,
    })
}

/// The magnitude polynomial of the power form of a Bernstein polynomial with coefficient
/// sizes `b`: coefficient `k` is `Σᵢ |bᵢ| C(n, i) C(n − i, k − i)`, the sum of the absolute
/// terms of `Σᵢ bᵢ C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ` at `tᵏ` (for [`identity_cert_within`]).
fn abs_power_of_bernstein(b: &[f64]) -> Poly<f64> {
    let n = b.len().saturating_sub(1);
    let binom = |n: usize, k: usize| -> f64 {
        (0..k).fold(1.0, |acc, j| acc * (n - j) as f64 / (j + 1) as f64)
    };
    Poly::new(
        (0..b.len())
            .map(|k| {
                (0..=k)
                    .map(|i| b[i] * binom(n, i) * binom(n - i, k - i))
                    .sum::<f64>()
            })
            .collect(),
    )
}

impl<F: Scalar> RmfSweep<F> {
    /// Certificates: the frame's ([`RationalRmf::certify`]); for every profile control
    /// point `j`, the column `G_j(t)` of the unsplit patch's homogeneous net satisfies
    /// `(G_j − r·G_{j,0})·r' ≡ 0` (each profile point stays in the normal plane, so
    /// `(S − r)·r' ≡ 0` after clearing `d(t)W(u)`) and `|G_j − r·G_{j,0}|² ≡ ω_j²(x_j² + y_j²)d²`
    /// (its distance from the curve is that of the profile point from the origin); and
    /// every weight of every piece `> 0`.
    pub fn certify(&self) -> Vec<Certificate> {
        let mut certs = self.rmf.certify();
        let h = self.rmf.curve.hodograph();
        let r = self.rmf.curve.position();
        let (nu, _) = self.patch.degree();
        let d2 = &self.rmf.den * &self.rmf.den;
        let mut normal_ok = true;
        let mut dist_ok = true;
        let mut worst = String::new();
        for j in 0..=nu {
            let (_, nv) = self.patch.degree();
            let bern: Vec<Vec<F>> = (0..4)
                .map(|c| {
                    (0..=nv)
                        .map(|k| self.patch.control_point(j, k)[c].clone())
                        .collect()
                })
                .collect();
            let col: Vec<Poly<F>> = bern.iter().map(|b| bernstein::from_bernstein(b)).collect();
            // the power form's coefficients are cancelled sums of the Bernstein ones: bound
            // them by the sums of the absolute terms
            let abs_col: Vec<Poly<f64>> = bern
                .iter()
                .map(|b| {
                    abs_power_of_bernstein(&b.iter().map(|x| x.to_f64().abs()).collect::<Vec<_>>())
                })
                .collect();
            let off: [Poly<F>; 3] = [
                &col[1] - &(&r[0] * &col[0]),
                &col[2] - &(&r[1] * &col[0]),
                &col[3] - &(&r[2] * &col[0]),
            ];
            // for f64, each residual coefficient is compared with the size of the terms
            // that cancel in it (`offₖ = Gₖ − rₖG₀` cancels the curve point against the
            // profile point's frame combination), not with the cancelled result
            let abs_off: Vec<Poly<f64>> = (0..3)
                .map(|c| &abs_col[c + 1] + &(&abs_poly(&r[c]) * &abs_col[0]))
                .collect();
            let normal_mag = (0..3).fold(Poly::zero(), |acc: Poly<f64>, c| {
                &acc + &(&abs_off[c] * &abs_poly(&h[c]))
            });
            let c1 = identity_cert_within(
                "normal",
                &pdot(&off, &h),
                &Poly::zero(),
                normal_mag.coeffs(),
            );
            let p = &self.profile[j];
            let w = &self.weights[j];
            let rr =
                w.clone() * w.clone() * (p[0].clone() * p[0].clone() + p[1].clone() * p[1].clone());
            let dist_mag = (0..3).fold(abs_poly(&d2.scale(&rr)), |acc: Poly<f64>, c| {
                &acc + &(&abs_off[c] * &abs_off[c])
            });
            let c2 =
                identity_cert_within("dist", &pdot(&off, &off), &d2.scale(&rr), dist_mag.coeffs());
            if !c1.holds {
                normal_ok = false;
                worst = format!(
                    "profile point {j}: {}; term magnitudes {:?}",
                    c1.residual.as_deref().unwrap_or(""),
                    normal_mag.coeffs()
                );
            }
            if !c2.holds {
                dist_ok = false;
                worst = format!(
                    "profile point {j}: {}; term magnitudes {:?}",
                    c2.residual.as_deref().unwrap_or(""),
                    dist_mag.coeffs()
                );
            }
        }
        let exact = F::EXACT;
        certs.push(Certificate::decide(
            "(S − r)·r' ≡ 0: every profile point stays in the normal plane of the curve",
            normal_ok,
            exact,
            || format!("residual polynomial at {worst}"),
        ));
        certs.push(Certificate::decide(
            "|S − r| ≡ |(x(u), y(u))| per profile control point: the profile is carried rigidly by the RMF",
            dist_ok,
            exact,
            || format!("residual polynomial at {worst}"),
        ));
        let pos = self
            .pieces
            .iter()
            .all(|p| SignRule::Positive.holds(p.coords(), p.dim() + 1));
        certs.push(Certificate::decide(
            format!(
                "every Bernstein weight of the {} piece(s) > 0 (STEP/IGES-ready)",
                self.pieces.len()
            ),
            pos,
            exact,
            || "a weight ≤ 0".to_string(),
        ));
        certs.push(self.regularity.clone());
        certs
    }

    /// The exported patches (all weights `> 0`).
    pub fn patches(&self) -> Vec<BezierPatch<F>> {
        self.pieces.clone()
    }
}

/// Certificates that consecutive pieces of a profile given piece by piece (control points
/// `(x_j, y_j)` and weights `ω_j > 0` per piece) meet: the end point of piece `k` is the
/// start point of piece `k + 1` (`G⁰`, so the swept pieces meet along the same curve); and,
/// when the last piece ends where the first starts, that the profile is closed.
pub fn profile_joints<F: Scalar>(pieces: &[(Vec<[F; 2]>, Vec<F>)]) -> Vec<Certificate> {
    // the control points are Euclidean (the weights are separate): a rational Bézier curve
    // starts at its first control point and ends at its last
    let end = |(pts, _): &(Vec<[F; 2]>, Vec<F>), last: bool| -> Option<[F; 2]> {
        if last {
            pts.last().cloned()
        } else {
            pts.first().cloned()
        }
    };
    let mut out = Vec::new();
    for (k, w) in pieces.windows(2).enumerate() {
        let (a, b) = (end(&w[0], true), end(&w[1], false));
        out.push(Certificate::decide(
            format!("profile pieces {k} and {} meet (G⁰: the end point of one is the start point of the next)", k + 1),
            a.is_some() && a == b,
            F::EXACT,
            || format!("the end point of piece {k} is not the start point of piece {}", k + 1),
        ));
    }
    if pieces.len() > 1 {
        if let (Some(first), Some(last)) = (pieces.first(), pieces.last()) {
            let (a, b) = (end(last, true), end(first, false));
            if a.is_some() && a == b {
                out.push(Certificate::holds(
                    "the profile is closed (the last piece ends where the first starts): the sweep is a closed tube",
                    F::EXACT,
                ));
            }
        }
    }
    out
}

impl<F: Scalar> crate::Certified for RmfSweep<F> {
    fn certify(&self) -> Vec<Certificate> {
        RmfSweep::certify(self)
    }
}

#[cfg(test)]
mod joint_tests {
    use super::*;
    use rcagd_algebra::Rational as Q;

    fn piece(pts: &[[i64; 2]]) -> (Vec<[Q; 2]>, Vec<Q>) {
        (
            pts.iter().map(|p| [Q::from(p[0]), Q::from(p[1])]).collect(),
            vec![Q::from(1); pts.len()],
        )
    }

    #[test]
    fn profile_pieces_meet_and_close() {
        let closed = [
            piece(&[[1, 0], [1, 1], [0, 1]]),
            piece(&[[0, 1], [-1, 0], [1, 0]]),
        ];
        let c = profile_joints(&closed);
        assert_eq!(c.len(), 2);
        assert!(c.iter().all(|x| x.holds && x.exact));
        assert!(c[1].property.contains("closed"));
        let open = [piece(&[[1, 0], [1, 1], [0, 1]]), piece(&[[0, 1], [-1, 0]])];
        let c = profile_joints(&open);
        assert_eq!(c.len(), 1);
        assert!(c[0].holds);
        let gap = [piece(&[[1, 0], [1, 1]]), piece(&[[0, 1], [-1, 0]])];
        let c = profile_joints(&gap);
        assert!(!c[0].holds, "{c:?}");
        assert!(profile_joints(&gap[..1]).is_empty());
    }
}
