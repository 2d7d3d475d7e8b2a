//! RRMF quintic interpolation of G¹ Hermite data with end frames (Farouki, Giannelli,
//! Manni, Sestini 2012, "Design of rational rotation-minimizing rigid body motions by
//! Hermite interpolation", Math. Comp. 81; our formulation in docs/math/rrmf.md, "Hermite
//! interpolation").
//!
//! Data: end points `p_i`, `p_f`, unit tangents `t_i`, `t_f` and normal-plane vectors `u_i`,
//! `u_f` (the first frame vector at each end). Unknowns: `A_0 = √λ_0 Q̂(t_i)`,
//! `A_2 = √λ_2 Q̂(t_f) e^{iφ}`, `A_1 = Q̂(c/2) e^{iψ}`, `c = A_0 i A_2* + A_2 i A_0*`
//! ([`solve_qiq`]), so the quintic RRMF condition holds by construction. Equations: the
//! displacement `(1/5)ΣH_k = p_f − p_i` (3) and the end frame (1): the RMF turns against
//! the ERF by `Δθ = −2∫₀¹ N/σ`, so `angle(u_f; e_2(1), e_3(1)) − angle(u_i; e_2(0), e_3(0))
//! ≡ Δθ (mod 2π)`. Four equations in `(ln λ_0, ln λ_2, φ, ψ)`, solved by Newton's method
//! from a grid of starts in `f64`; the shortest solution is kept.
//!
//! The solution is then made exact: `A_0`, `A_1` and the free part `x` of
//! `X = A_0⁻¹ A_2` are read as exact rationals and `A_2` is recomputed by
//! [`rrmf_quintic_class1`], so the curve is an exact RRMF quintic with an exact rational
//! RMF; the interpolation conditions then hold to rounding, and the residuals are reported.

use super::hodograph::{solve_qiq, PhCurve};
use super::planar::gauss7;
use super::rrmf::{erf_twist_numerator, rrmf_quintic_class1, RationalRmf};
use super::PhError;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Rational, Scalar};

type V3 = [f64; 3];

/// G¹ Hermite data with end frames.
#[derive(Debug, Clone, PartialEq)]
pub struct RrmfHermiteData {
    /// Start point.
    pub p_i: V3,
    /// Start tangent direction (any length `> 0`).
    pub t_i: V3,
    /// Start first normal-plane frame vector (orthogonal to `t_i`; any length `> 0`).
    pub u_i: V3,
    /// End point.
    pub p_f: V3,
    /// End tangent direction.
    pub t_f: V3,
    /// End first normal-plane frame vector.
    pub u_f: V3,
}

/// The interpolant: an exact RRMF quintic, its exact RMF, the constant angle `γ` that
/// turns the RMF `(f_1, f_2)` into the frame through `u_i` (`cos γ f_1 + sin γ f_2`), and
/// the interpolation residuals.
#[derive(Debug, Clone)]
pub struct RrmfHermite {
    /// The exact curve and frame.
    pub rmf: RationalRmf<Rational>,
    /// `γ` (radians).
    pub gamma: f64,
    /// `max |r(0) − p_i|, |r(1) − p_f|`.
    pub point_residual: f64,
    /// `max |r'/|r'| − t̂|` at both ends.
    pub tangent_residual: f64,
    /// `max |f(·) − û|` at both ends for the turned frame `f = cos γ f_1 + sin γ f_2`.
    pub frame_residual: f64,
}

fn sub(a: &V3, b: &V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: &V3, b: &V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn norm(a: &V3) -> f64 {
    dot(a, a).sqrt()
}
fn unit(a: &V3) -> V3 {
    let n = norm(a);
    [a[0] / n, a[1] / n, a[2] / n]
}
fn vq(q: &Quaternion<f64>) -> V3 {
    [q.x, q.y, q.z]
}
fn sandwich(a: &Quaternion<f64>, u: Quaternion<f64>) -> V3 {
    vq(&(a.clone() * u * a.conj()))
}
fn wrap(x: f64) -> f64 {
    let t = std::f64::consts::TAU;
    x - t * ((x + std::f64::consts::PI) / t).floor()
}

/// Angle of `u` in the ERF normal plane `(A j A*, A k A*)`.
fn erf_angle(a: &Quaternion<f64>, u: &V3) -> f64 {
    let e2 = sandwich(a, Quaternion::j());
    let e3 = sandwich(a, Quaternion::k());
    dot(u, &e3).atan2(dot(u, &e2))
}

impl RrmfHermiteData {
    fn check(&self) -> Result<(), PhError> {
        let all = [self.p_i, self.t_i, self.u_i, self.p_f, self.t_f, self.u_f];
        if all.iter().flatten().any(|x| !x.is_finite()) {
            return Err(PhError::OutOfRange("non-finite Hermite data".into()));
        }
        for (t, u, end) in [
            (&self.t_i, &self.u_i, "start"),
            (&self.t_f, &self.u_f, "end"),
        ] {
            if norm(t) == 0.0 {
                return Err(PhError::ZeroTangent(format!("the {end} tangent is zero")));
            }
            if norm(u) == 0.0 {
                return Err(PhError::Degenerate(format!(
                    "the {end} frame vector is zero"
                )));
            }
            if dot(&unit(t), &unit(u)).abs() > 1e-9 {
                return Err(PhError::Degenerate(format!(
                    "the {end} frame vector is not orthogonal to the {end} tangent"
                )));
            }
        }
        if norm(&sub(&self.p_f, &self.p_i)) == 0.0 {
            return Err(PhError::CoincidentEndPoints(
                "RRMF Hermite interpolation needs p_i ≠ p_f".into(),
            ));
        }
        Ok(())
    }

    /// The preimage for the unknowns `(ln λ_0, ln λ_2, φ, ψ)`.
    fn preimage(&self, x: &[f64; 4]) -> Result<[Quaternion<f64>; 3], PhError> {
        let a0 = solve_qiq(&unit(&self.t_i), None)?.scale(&(x[0].exp().sqrt()));
        let a2 = solve_qiq(&unit(&self.t_f), Some((x[2].cos(), x[2].sin())))?
            .scale(&(x[1].exp().sqrt()));
        let c = a0.clone() * Quaternion::i() * a2.conj() + a2.clone() * Quaternion::i() * a0.conj();
        let a1 = solve_qiq(
            &[c.x / 2.0, c.y / 2.0, c.z / 2.0],
            Some((x[3].cos(), x[3].sin())),
        )?;
        Ok([a0, a1, a2])
    }

    fn residual(&self, x: &[f64; 4]) -> Option<[f64; 4]> {
        let a = self.preimage(x).ok()?;
        let curve = PhCurve::new(a.to_vec(), self.p_i).ok()?;
        let pts = curve.control_points();
        let end = pts.last()?;
        let d = sub(end, &self.p_f);
        let n = erf_twist_numerator(&curve);
        let s = curve.speed();
        let f = |t: f64| n.eval(&t) / s.eval(&t);
        let dtheta = -2.0
            * (0..16)
                .map(|k| gauss7(&f, k as f64 / 16.0, (k + 1) as f64 / 16.0))
                .sum::<f64>();
        let ang = erf_angle(&a[2], &self.u_f) - erf_angle(&a[0], &self.u_i) - dtheta;
        let scale = norm(&sub(&self.p_f, &self.p_i));
        Some([d[0] / scale, d[1] / scale, d[2] / scale, wrap(ang)])
    }

    fn newton(&self, mut x: [f64; 4]) -> Option<([f64; 4], f64)> {
        for _ in 0..60 {
            let r = self.residual(&x)?;
            let rn = r.iter().map(|v| v.abs()).fold(0.0, f64::max);
            if rn < 1e-14 {
                return Some((x, rn));
            }
            let h = 1e-7;
            let mut j = [[0.0; 4]; 4];
            for k in 0..4 {
                let mut xp = x;
                let mut xm = x;
                xp[k] += h;
                xm[k] -= h;
                let (rp, rm) = (self.residual(&xp)?, self.residual(&xm)?);
                for i in 0..4 {
                    let mut dv = rp[i] - rm[i];
                    if i == 3 {
                        dv = wrap(dv);
                    }
                    j[i][k] = dv / (2.0 * h);
                }
            }
            let dx = solve4(j, r.map(|v| -v))?;
            let step = dx.iter().map(|v| v.abs()).fold(0.0, f64::max);
            let damp = if step > 1.0 { 1.0 / step } else { 1.0 };
            for k in 0..4 {
                x[k] += damp * dx[k];
            }
        }
        let r = self.residual(&x)?;
        let rn = r.iter().map(|v| v.abs()).fold(0.0, f64::max);
        (rn < 1e-11).then_some((x, rn))
    }

    /// The shortest RRMF quintic interpolant, made exact (see the module docs).
    ///
    /// # Errors
    /// [`PhError::ZeroTangent`], [`PhError::CoincidentEndPoints`], [`PhError::Degenerate`]
    /// (frame vector zero or not orthogonal to its tangent), [`PhError::OutOfRange`]
    /// (non-finite data), [`PhError::NoRealSolution`] if Newton's method converges from
    /// none of the starts.
    pub fn solve(&self) -> Result<RrmfHermite, PhError> {
        self.check()?;
        let l0 = norm(&sub(&self.p_f, &self.p_i)).ln();
        let mut best: Option<([f64; 4], f64)> = None;
        let n = 6;
        for a in 0..n {
            for b in 0..n {
                let phi = std::f64::consts::TAU * a as f64 / n as f64;
                let psi = std::f64::consts::TAU * b as f64 / n as f64;
                let Some((x, _)) = self.newton([l0, l0, phi, psi]) else {
                    continue;
                };
                let Ok(a3) = self.preimage(&x) else { continue };
                let Ok(c) = PhCurve::new(a3.to_vec(), self.p_i) else {
                    continue;
                };
                let len: f64 = c.speed_bernstein().iter().sum::<f64>() / 5.0;
                if best.as_ref().is_none_or(|(_, l)| len < *l) {
                    best = Some((x, len));
                }
            }
        }
        let Some((x, _)) = best else {
            return Err(PhError::NoRealSolution(
                "Newton's method on the RRMF Hermite equations converged from none of the 36 starts"
                    .into(),
            ));
        };
        let a = self.preimage(&x)?;
        self.exact(&a)
    }

    /// Exact RRMF quintic from an `f64` solution: `A_0`, `A_1`, `x` as exact rationals.
    fn exact(&self, a: &[Quaternion<f64>; 3]) -> Result<RrmfHermite, PhError> {
        let q = |v: f64| short_rational(v, 1e-15);
        let qq = |z: &Quaternion<f64>| -> Result<Quaternion<Rational>, PhError> {
            Ok(Quaternion::new(q(z.w)?, q(z.x)?, q(z.y)?, q(z.z)?))
        };
        let xq = a[0]
            .inverse()
            .map(|inv| inv * a[2].clone())
            .ok_or_else(|| PhError::Degenerate("A_0 = 0 in the Hermite solution".into()))?;
        let start = [q(self.p_i[0])?, q(self.p_i[1])?, q(self.p_i[2])?];
        let curve = rrmf_quintic_class1(qq(&a[0])?, qq(&a[1])?, q(xq.x)?, start)?;
        let rmf = RationalRmf::new(&curve)?;
        let f = rmf.to_f64();
        let pts = f.curve.control_points();
        let point_residual = norm(&sub(&pts[0], &self.p_i)).max(norm(&sub(&pts[5], &self.p_f)));
        let [t0, f10, f20] = f
            .eval(&0.0)
            .ok_or_else(|| PhError::Degenerate("σ(0) = 0".into()))?;
        let [t1, f11, f21] = f
            .eval(&1.0)
            .ok_or_else(|| PhError::Degenerate("σ(1) = 0".into()))?;
        let tangent_residual =
            norm(&sub(&t0, &unit(&self.t_i))).max(norm(&sub(&t1, &unit(&self.t_f))));
        let ui = unit(&self.u_i);
        let gamma = dot(&ui, &f20).atan2(dot(&ui, &f10));
        let turn = |a: &V3, b: &V3| {
            [
                gamma.cos() * a[0] + gamma.sin() * b[0],
                gamma.cos() * a[1] + gamma.sin() * b[1],
                gamma.cos() * a[2] + gamma.sin() * b[2],
            ]
        };
        let frame_residual =
            norm(&sub(&turn(&f10, &f20), &ui)).max(norm(&sub(&turn(&f11, &f21), &unit(&self.u_f))));
        Ok(RrmfHermite {
            rmf,
            gamma,
            point_residual,
            tangent_residual,
            frame_residual,
        })
    }
}

/// The continued-fraction convergent of `v` nearest in denominator with
/// `|p/q − v| ≤ tol·max(1, |v|)` (denominators up to `2³¹`), else the exact binary value
/// of `v`: short exact rationals for the made-exact coefficients.
fn short_rational(v: f64, tol: f64) -> Result<Rational, PhError> {
    if !v.is_finite() {
        return Err(PhError::NonFinite {
            what: format!("the value {v} of the f64 RRMF Hermite solve"),
        });
    }
    let bound = tol * v.abs().max(1.0);
    let (mut h0, mut h1, mut k0, mut k1) = (0i128, 1i128, 1i128, 0i128);
    let mut x = v;
    for _ in 0..40 {
        let a = x.floor();
        if a.abs() > 1e15 {
            break;
        }
        let ai = a as i128;
        let (h2, k2) = (ai * h1 + h0, ai * k1 + k0);
        if k2 > 1 << 31 || h2.abs() > i64::MAX as i128 {
            break;
        }
        (h0, h1, k0, k1) = (h1, h2, k1, k2);
        if (h1 as f64 / k1 as f64 - v).abs() <= bound {
            return Ok(Rational::from(h1 as i64) / Rational::from(k1 as i64));
        }
        let frac = x - a;
        if frac == 0.0 {
            break;
        }
        x = 1.0 / frac;
    }
    Rational::try_from(v).map_err(|_| PhError::NonFinite {
        what: format!("the value {v} of the f64 RRMF Hermite solve"),
    })
}

/// Solves the 4 × 4 system `J x = b` by Gaussian elimination with partial pivoting.
fn solve4(mut j: [[f64; 4]; 4], mut b: [f64; 4]) -> Option<[f64; 4]> {
    for c in 0..4 {
        let p = (c..4).max_by(|&r, &s| j[r][c].abs().total_cmp(&j[s][c].abs()))?;
        if j[p][c].abs() < 1e-300 {
            return None;
        }
        j.swap(c, p);
        b.swap(c, p);
        for r in c + 1..4 {
            let m = j[r][c] / j[c][c];
            let pivot_row = j[c];
            for (x, y) in j[r].iter_mut().zip(pivot_row.iter()).skip(c) {
                *x -= m * y;
            }
            b[r] -= m * b[c];
        }
    }
    let mut x = [0.0; 4];
    for c in (0..4).rev() {
        let s: f64 = (c + 1..4).map(|k| j[c][k] * x[k]).sum();
        x[c] = (b[c] - s) / j[c][c];
    }
    Some(x)
}
