//! C2 planar PH quintic splines through a sequence of points (Albrecht–Farouki 1996;
//! Farouki–Kuspa–Manni–Sestini 2001, "Efficient solution of the complex quadratic
//! tridiagonal system for C2 PH quintic splines"; Farouki 2008 ch. 26; issue 5 part B).
//!
//! Points `p_0..p_N`; segment `i = 1..N` is the planar PH quintic on `[0, 1]` with
//! quadratic preimage (Bernstein) `w_i = (½(z_{i−1} + z_i), z_i, ½(z_i + z_{i+1}))`. This
//! choice makes the spline C2 for any `z` (with uniform parameter steps):
//! `w_i(1) = w_{i+1}(0)` and `w_i'(1) = z_{i+1} − z_i = w_{i+1}'(0)`, hence
//! `r' = w²`, `r'' = 2ww'` agree. Interpolation `r_i(1) − r_i(0) = Δp_i = p_i − p_{i−1}`
//! gives (`∫₀¹ w²`, checked with sympy) the complex quadratic system
//!
//! `f_i = 3z_{i−1}² + 27z_i² + 3z_{i+1}² + z_{i−1}z_{i+1} + 13z_{i−1}z_i + 13z_iz_{i+1} − 60Δp_i = 0`,
//!
//! `i = 1..N`, in `N + 2` unknowns; the ends close it:
//!
//! * given end derivatives `d_0`, `d_N`: `½(z_0 + z_1) = √d_0`, `½(z_N + z_{N+1}) = √d_N`;
//! * natural-like ends (`r'' = 0`, i.e. `w' = 0`): `z_0 = z_1`, `z_{N+1} = z_N`;
//! * closed (`p_N = p_0`): `z_0 = ε z_N`, `z_{N+1} = ε z_1` with `ε = ±1` — `ε = −1` when
//!   the preimage turns by an odd multiple of `π` around the loop (a simple loop: the
//!   tangent turns by `±2π`, so `w` by `±π`); `ε` is read off the starting approximation.
//!
//! The system is solved by Newton–Raphson in complex `f64` (the Jacobian is holomorphic:
//! tridiagonal for open splines, solved by the Thomas algorithm; cyclic for closed ones,
//! solved by two Thomas solves and a Sherman–Morrison correction), started from `z_i = √Δp_i` with the branch chosen
//! continuously (`Re(z_i z̄_{i−1}) ≥ 0`) — the "good" solution of Farouki et al.
//!
//! For an exact scalar the solution `z_i` is rounded to rationals (the exact binary
//! values of the `f64`s); each segment is then an exact PH quintic (certified), the
//! spline is exactly C1 and C2 at every junction (certified: each segment starts at the
//! exact end of the previous one), and the interpolation holds to the reported rounding
//! error `max_i |r(t_i) − p_i|`.

use super::planar::{complex_sqrt, from_f64, identity_cert, PlanarPhCurve, C};
use super::PhError;
use rcagd_algebra::{Certificate, Poly, Scalar};

/// End conditions of a C2 PH quintic spline.
#[derive(Debug, Clone, PartialEq)]
pub enum SplineEnds<F> {
    /// Given end derivatives `r'(0) = d_0` (first segment) and `r'(1) = d_N` (last).
    Derivatives([F; 2], [F; 2]),
    /// Natural-like ends: `r'' = 0` at both ends (`z_0 = z_1`, `z_{N+1} = z_N`).
    Natural,
    /// A closed spline through the points (the first point is repeated at the end).
    Closed,
}

/// A C2 PH quintic spline.
#[derive(Debug, Clone, PartialEq)]
pub struct PhQuinticSpline<F> {
    /// The points `p_0..p_N` (for a closed spline `p_N = p_0` is appended).
    pub points: Vec<[F; 2]>,
    /// `z_0..z_{N+1}` (rounded to `F`).
    pub z: Vec<C<F>>,
    /// The `N` quintic segments, each on `[0, 1]`; segment `i + 1` starts at the exact end
    /// of segment `i`.
    pub segments: Vec<PlanarPhCurve<F>>,
    /// `true` for a closed spline.
    pub closed: bool,
    /// `ε` of the closed end condition (`1` for open splines).
    pub closure_sign: i8,
    /// Newton–Raphson iterations used.
    pub iterations: usize,
    /// `max_i |f_i(z)|/60` at the `f64` solution (the Newton residual, in length units).
    pub newton_residual: f64,
    /// `max_i |r_i(1) − p_i|` of the built spline (computed in `F`, reported in `f64`):
    /// the interpolation error caused by rounding (zero up to round-off in `f64`).
    pub interpolation_error: f64,
}

fn cz(re: f64, im: f64) -> C<f64> {
    C::new(re, im)
}
fn cabs(z: &C<f64>) -> f64 {
    z.norm_sq().sqrt()
}

/// Solves `J x = b` for a complex tridiagonal `J` (sub-diagonal `a`, diagonal `b`,
/// super-diagonal `c`) by the Thomas algorithm; `None` on a zero pivot.
fn thomas(a: &[C<f64>], b: &[C<f64>], c: &[C<f64>], rhs: &[C<f64>]) -> Option<Vec<C<f64>>> {
    let n = b.len();
    let mut cp = vec![cz(0.0, 0.0); n];
    let mut dp = vec![cz(0.0, 0.0); n];
    for i in 0..n {
        let sub = if i > 0 { a[i].clone() } else { cz(0.0, 0.0) };
        let prev_c = if i > 0 {
            cp[i - 1].clone()
        } else {
            cz(0.0, 0.0)
        };
        let prev_d = if i > 0 {
            dp[i - 1].clone()
        } else {
            cz(0.0, 0.0)
        };
        let den = b[i].clone() - sub.clone() * prev_c;
        let inv = den.inverse()?;
        if !inv.re.is_finite() || !inv.im.is_finite() {
            return None;
        }
        cp[i] = c[i].clone() * inv.clone();
        dp[i] = (rhs[i].clone() - sub * prev_d) * inv;
    }
    let mut x = vec![cz(0.0, 0.0); n];
    for i in (0..n).rev() {
        let next = if i + 1 < n {
            x[i + 1].clone()
        } else {
            cz(0.0, 0.0)
        };
        x[i] = dp[i].clone() - cp[i].clone() * next;
    }
    Some(x)
}

/// Solves a cyclic tridiagonal complex system (sub-diagonal `a`, diagonal `b`,
/// super-diagonal `c`, corners `A[0][n−1] = beta`, `A[n−1][0] = alpha`, `n ≥ 3`) by the
/// Sherman–Morrison correction of two Thomas solves; `None` on a zero pivot.
fn cyclic_thomas(
    a: &[C<f64>],
    b: &[C<f64>],
    c: &[C<f64>],
    alpha: &C<f64>,
    beta: &C<f64>,
    rhs: &[C<f64>],
) -> Option<Vec<C<f64>>> {
    let n = b.len();
    let first = b.first()?;
    let gamma = if first.norm_sq() > 0.0 {
        -first.clone()
    } else {
        cz(-1.0, 0.0)
    };
    let ginv = gamma.inverse()?;
    let mut bb = b.to_vec();
    bb[0] -= gamma.clone();
    bb[n - 1] -= alpha.clone() * beta.clone() * ginv.clone();
    let x = thomas(a, &bb, c, rhs)?;
    let mut u = vec![cz(0.0, 0.0); n];
    u[0] = gamma;
    u[n - 1] = alpha.clone();
    let z = thomas(a, &bb, c, &u)?;
    let num = x[0].clone() + beta.clone() * x[n - 1].clone() * ginv.clone();
    let den = cz(1.0, 0.0) + z[0].clone() + beta.clone() * z[n - 1].clone() * ginv;
    let fact = num * den.inverse()?;
    Some(
        x.into_iter()
            .zip(z)
            .map(|(xi, zi)| xi - fact.clone() * zi)
            .collect(),
    )
}

/// The interior system in `f64`: `dp[i]` = Δp_{i+1}, unknowns `z_1..z_N` (stored
/// `u[0..N]`), `z_0 = s0 + e0 z_1`, `z_{N+1} = s1 + e1 z_N` (open) or cyclic (closed).
struct System {
    dp: Vec<C<f64>>,
    closed: bool,
    eps: f64,
    s0: C<f64>,
    e0: f64,
    s1: C<f64>,
    e1: f64,
}

impl System {
    fn full(&self, u: &[C<f64>]) -> Vec<C<f64>> {
        let n = u.len();
        let mut z = Vec::with_capacity(n + 2);
        if self.closed {
            z.push(u[n - 1].scale(&self.eps));
            z.extend(u.iter().cloned());
            z.push(u[0].scale(&self.eps));
        } else {
            z.push(self.s0.clone() + u[0].scale(&self.e0));
            z.extend(u.iter().cloned());
            z.push(self.s1.clone() + u[n - 1].scale(&self.e1));
        }
        z
    }

    fn residual(&self, z: &[C<f64>]) -> Vec<C<f64>> {
        (1..z.len() - 1)
            .map(|i| {
                let (a, b, c) = (z[i - 1].clone(), z[i].clone(), z[i + 1].clone());
                (a.clone() * a.clone()).scale(&3.0)
                    + (b.clone() * b.clone()).scale(&27.0)
                    + (c.clone() * c.clone()).scale(&3.0)
                    + a.clone() * c.clone()
                    + (a * b.clone()).scale(&13.0)
                    + (b * c).scale(&13.0)
                    - self.dp[i - 1].scale(&60.0)
            })
            .collect()
    }

    /// One Newton step; returns the correction.
    fn step(&self, u: &[C<f64>]) -> Option<Vec<C<f64>>> {
        let n = u.len();
        let z = self.full(u);
        let f = self.residual(&z);
        let rhs: Vec<C<f64>> = f.iter().map(|x| -x.clone()).collect();
        // partials of f_i (i = 1..N) w.r.t. z_{i−1}, z_i, z_{i+1}
        let mut lo = Vec::with_capacity(n);
        let mut di = Vec::with_capacity(n);
        let mut up = Vec::with_capacity(n);
        for i in 1..=n {
            let (a, b, c) = (z[i - 1].clone(), z[i].clone(), z[i + 1].clone());
            lo.push(a.scale(&6.0) + c.clone() + b.scale(&13.0));
            di.push(b.scale(&54.0) + a.scale(&13.0) + c.scale(&13.0));
            up.push(c.scale(&6.0) + a + b.scale(&13.0));
        }
        if self.closed {
            let beta = lo[0].scale(&self.eps);
            let alpha = up[n - 1].scale(&self.eps);
            cyclic_thomas(&lo, &di, &up, &alpha, &beta, &rhs)
        } else {
            di[0] += lo[0].scale(&self.e0);
            di[n - 1] += up[n - 1].scale(&self.e1);
            thomas(&lo, &di, &up, &rhs)
        }
    }
}

impl<F: Scalar> PhQuinticSpline<F> {
    /// The C2 PH quintic spline through `points` with the given end conditions.
    ///
    /// # Errors
    /// [`PhError::Degenerate`] for fewer than 2 points (3 for a closed spline);
    /// [`PhError::NonFinite`] for data or a Newton solution beyond `f64`'s range;
    /// [`PhError::CoincidentEndPoints`] if two consecutive points
    /// coincide; [`PhError::ZeroTangent`] for a zero end derivative;
    /// [`PhError::NoRealSolution`] if Newton–Raphson does not converge (50 iterations).
    pub fn interpolate(points: &[[F; 2]], ends: &SplineEnds<F>) -> Result<Self, PhError> {
        let closed = matches!(ends, SplineEnds::Closed);
        let mut pts: Vec<[F; 2]> = points.to_vec();
        if closed && pts.len() > 1 && pts.first() == pts.last() {
            pts.pop();
        }
        if closed {
            if pts.len() < 3 {
                return Err(PhError::Degenerate(
                    "a closed PH spline needs at least 3 distinct points".into(),
                ));
            }
            let first = pts[0].clone();
            pts.push(first);
        } else if pts.len() < 2 {
            return Err(PhError::Degenerate(
                "a PH spline needs at least 2 points".into(),
            ));
        }
        let pf: Vec<C<f64>> = pts
            .iter()
            .map(|p| cz(p[0].to_f64(), p[1].to_f64()))
            .collect();
        if pf.iter().any(|p| !p.re.is_finite() || !p.im.is_finite()) {
            return Err(PhError::NonFinite {
                what: "the spline points in f64".into(),
            });
        }
        for (i, w) in pts.windows(2).enumerate() {
            if w[0] == w[1] {
                return Err(PhError::CoincidentEndPoints(format!(
                    "points {i} and {} coincide: every span needs p_i ≠ p_(i+1)",
                    i + 1
                )));
            }
        }
        let dp: Vec<C<f64>> = pf.windows(2).map(|w| w[1].clone() - w[0].clone()).collect();
        let n = dp.len();
        // starting approximation z_i = √Δp_i, branch continuous
        let mut u: Vec<C<f64>> = Vec::with_capacity(n);
        for d in &dp {
            let mut s = complex_sqrt(d).unwrap_or_else(|| cz(0.0, 0.0));
            if let Some(prev) = u.last() {
                if (s.clone() * prev.conj()).re < 0.0 {
                    s = -s;
                }
            }
            u.push(s);
        }
        let mut sys = System {
            dp: dp.clone(),
            closed,
            eps: 1.0,
            s0: cz(0.0, 0.0),
            e0: 1.0,
            s1: cz(0.0, 0.0),
            e1: 1.0,
        };
        match ends {
            SplineEnds::Closed => {
                if (u[n - 1].clone() * u[0].conj()).re < 0.0 {
                    sys.eps = -1.0;
                }
            }
            SplineEnds::Natural => {}
            SplineEnds::Derivatives(d0, d1) => {
                let d0 = cz(d0[0].to_f64(), d0[1].to_f64());
                let d1 = cz(d1[0].to_f64(), d1[1].to_f64());
                if d0.norm_sq() == 0.0 {
                    return Err(PhError::ZeroTangent(
                        "the start derivative d_0 is zero".into(),
                    ));
                }
                if d1.norm_sq() == 0.0 {
                    return Err(PhError::ZeroTangent(
                        "the end derivative d_N is zero".into(),
                    ));
                }
                let mut a = complex_sqrt(&d0).unwrap_or_else(|| cz(0.0, 0.0));
                if (a.clone() * u[0].conj()).re < 0.0 {
                    a = -a;
                }
                let mut b = complex_sqrt(&d1).unwrap_or_else(|| cz(0.0, 0.0));
                if (b.clone() * u[n - 1].conj()).re < 0.0 {
                    b = -b;
                }
                // ½(z_0 + z_1) = a ⇒ z_0 = 2a − z_1
                sys.s0 = a.scale(&2.0);
                sys.e0 = -1.0;
                sys.s1 = b.scale(&2.0);
                sys.e1 = -1.0;
            }
        }
        let scale = dp.iter().map(cabs).fold(0.0, f64::max).max(1e-300);
        let mut iterations = 0;
        let mut converged = false;
        for _ in 0..50 {
            iterations += 1;
            let delta = sys.step(&u).ok_or_else(|| {
                PhError::NoRealSolution("singular Newton–Raphson Jacobian".into())
            })?;
            let mut big = 0.0_f64;
            for (x, d) in u.iter_mut().zip(&delta) {
                *x += d.clone();
                big = big.max(cabs(d));
            }
            let usize_ = u.iter().map(cabs).fold(0.0, f64::max).max(1e-300);
            if !big.is_finite() {
                break;
            }
            if big <= 1e-15 * usize_ {
                converged = true;
                break;
            }
        }
        let zf = sys.full(&u);
        let newton_residual = sys
            .residual(&zf)
            .iter()
            .map(|r| cabs(r) / 60.0)
            .fold(0.0, f64::max);
        if !converged && newton_residual > 1e-10 * scale {
            return Err(PhError::NoRealSolution(format!(
                "Newton–Raphson did not converge in 50 iterations (residual {newton_residual:e})"
            )));
        }
        // round the solution into F
        let conv = |x: f64| -> Result<F, PhError> {
            from_f64(x).ok_or_else(|| PhError::NonFinite {
                what: "the spline's Newton solution (from the points and end conditions)".into(),
            })
        };
        let z: Vec<C<F>> = zf
            .iter()
            .map(|c| Ok(C::new(conv(c.re)?, conv(c.im)?)))
            .collect::<Result<_, PhError>>()?;
        let half = F::one() / F::from_i64(2);
        let mut segments: Vec<PlanarPhCurve<F>> = Vec::with_capacity(n);
        let mut start = pts[0].clone();
        for i in 1..=n {
            let w0 = (z[i - 1].clone() + z[i].clone()).scale(&half);
            let w2 = (z[i].clone() + z[i + 1].clone()).scale(&half);
            let seg = PlanarPhCurve::new(vec![w0, z[i].clone(), w2], start.clone())?;
            start = seg.end();
            segments.push(seg);
        }
        let mut err = 0.0_f64;
        for (seg, p) in segments.iter().zip(pts.iter().skip(1)) {
            let e = seg.end();
            let dx = (e[0].clone() - p[0].clone()).to_f64();
            let dy = (e[1].clone() - p[1].clone()).to_f64();
            err = err.max(dx.hypot(dy));
        }
        Ok(PhQuinticSpline {
            points: pts,
            z,
            segments,
            closed,
            closure_sign: if sys.eps < 0.0 { -1 } else { 1 },
            iterations,
            newton_residual,
            interpolation_error: err,
        })
    }

    /// The junction derivatives `(r'(0), r''(0), r'(1), r''(1))` of segment `s` from its
    /// hodograph Bernstein coefficients: `r'(0) = H_0`, `r''(0) = 4(H_1 − H_0)`, …
    fn end_derivatives(s: &PlanarPhCurve<F>) -> [C<F>; 4] {
        let h = s.hodograph_bernstein();
        let four = F::from_i64(4);
        let k = h.len() - 1;
        [
            h[0].clone(),
            (h[1].clone() - h[0].clone()).scale(&four),
            h[k].clone(),
            (h[k].clone() - h[k - 1].clone()).scale(&four),
        ]
    }

    /// Certificates: every segment is PH ([`PlanarPhCurve::certify`]); at every junction
    /// (including the closing one of a closed spline) position, first and second
    /// derivatives agree (C0, C1, C2; exact for exact scalars); the interpolation error
    /// is at most `tol` (a tolerance check, also for exact scalars — the `z` are rounded).
    pub fn certify_with(&self, tol: f64) -> Vec<Certificate> {
        let mut out = Vec::new();
        for (i, s) in self.segments.iter().enumerate() {
            for mut c in s.certify() {
                c.property = format!("segment {}: {}", i + 1, c.property);
                out.push(c);
            }
        }
        let n = self.segments.len();
        let pairs: Vec<(usize, usize)> = if self.closed {
            (0..n).map(|i| (i, (i + 1) % n)).collect()
        } else {
            (0..n.saturating_sub(1)).map(|i| (i, i + 1)).collect()
        };
        for (a, b) in pairs {
            let (sa, sb) = (&self.segments[a], &self.segments[b]);
            let da = Self::end_derivatives(sa);
            let db = Self::end_derivatives(sb);
            let as_poly = |c: &C<F>| Poly::new(vec![c.re.clone(), c.im.clone()]);
            let closing = self.closed && b == 0;
            let ea = sa.end();
            let sb0 = sb.start();
            if !closing {
                out.push(identity_cert(
                    format!("C0 at junction {}→{}", a + 1, b + 1),
                    &Poly::new(ea.to_vec()),
                    &Poly::new(sb0.to_vec()),
                ));
            } else {
                // each segment starts where the previous one ends by construction; the
                // last one ends at p_0 only up to the rounding of the z's
                let gap = ea
                    .iter()
                    .zip(sb0.iter())
                    .map(|(x, y)| (x.clone() - y.clone()).to_f64().abs())
                    .fold(0.0, f64::max);
                out.push(Certificate::decide(
                    format!(
                        "C0 at the closing junction {}→1: |r_{}(1) − r_1(0)| ≤ {tol:e} (rounded preimage)",
                        a + 1,
                        a + 1
                    ),
                    gap <= tol,
                    false,
                    || format!("{gap:e}"),
                ));
            }
            out.push(identity_cert(
                format!("C1: r'_{}(1) = r'_{}(0)", a + 1, b + 1),
                &as_poly(&da[2]),
                &as_poly(&db[0]),
            ));
            out.push(identity_cert(
                format!("C2: r''_{}(1) = r''_{}(0)", a + 1, b + 1),
                &as_poly(&da[3]),
                &as_poly(&db[1]),
            ));
        }
        out.push(Certificate::decide(
            format!("interpolation: max |r_i(1) − p_i| ≤ {tol:e} (rounded preimage)"),
            self.interpolation_error <= tol,
            false,
            || format!("{:e}", self.interpolation_error),
        ));
        out
    }

    /// [`Self::certify_with`] with `tol = 1e-9 · (1 + max |p_i|)`.
    pub fn certify(&self) -> Vec<Certificate> {
        let scale = self
            .points
            .iter()
            .map(|p| p[0].to_f64().abs().max(p[1].to_f64().abs()))
            .fold(0.0, f64::max);
        self.certify_with(1e-9 * (1.0 + scale))
    }

    /// Total arc length (exact sum of the segments' Bernstein arc lengths).
    pub fn arc_length(&self) -> F {
        self.segments
            .iter()
            .fold(F::zero(), |a, s| a + s.arc_length())
    }
}

impl<F: Scalar> crate::Certified for PhQuinticSpline<F> {
    fn certify(&self) -> Vec<Certificate> {
        PhQuinticSpline::certify(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn open_and_closed_splines() {
        let pts = vec![
            [q(0), q(0)],
            [q(1), q(1)],
            [q(2), q(0)],
            [q(3), q(1)],
            [q(4), q(0)],
        ];
        for ends in [
            SplineEnds::Natural,
            SplineEnds::Derivatives([q(1), q(1)], [q(1), q(-1)]),
        ] {
            let s = PhQuinticSpline::interpolate(&pts, &ends).unwrap();
            assert_eq!(s.segments.len(), 4);
            assert!(s.interpolation_error < 1e-12, "{}", s.interpolation_error);
            let certs = s.certify();
            assert!(Certificate::all_hold(&certs), "{certs:?}");
            assert!(certs.iter().filter(|c| c.exact).count() > 10);
        }
        let square = vec![[q(0), q(0)], [q(2), q(0)], [q(2), q(2)], [q(0), q(2)]];
        let s = PhQuinticSpline::interpolate(&square, &SplineEnds::Closed).unwrap();
        assert_eq!(s.segments.len(), 4);
        assert_eq!(s.closure_sign, -1);
        let certs = s.certify();
        assert!(Certificate::all_hold(&certs));
        // the closing junction has its C0 certificate too (a tolerance check)
        assert!(certs
            .iter()
            .any(|c| c.property.starts_with("C0 at the closing junction 4→1") && !c.exact));
        assert_eq!(
            certs
                .iter()
                .filter(|c| c.property.starts_with("C0"))
                .count(),
            4
        );
        let f = PhQuinticSpline::interpolate(
            &[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
            &SplineEnds::Closed,
        )
        .unwrap();
        assert!(Certificate::all_hold(&f.certify()));
        assert!((f.arc_length() - Scalar::to_f64(&s.arc_length())).abs() < 1e-12);
    }

    #[test]
    fn errors() {
        assert!(matches!(
            PhQuinticSpline::interpolate(&[[q(0), q(0)]], &SplineEnds::Natural),
            Err(PhError::Degenerate(_))
        ));
        assert!(matches!(
            PhQuinticSpline::interpolate(
                &[[q(0), q(0)], [q(0), q(0)], [q(1), q(0)]],
                &SplineEnds::Natural
            ),
            Err(PhError::CoincidentEndPoints(_))
        ));
    }
}
