//! Congruences given by a rational two-parameter line family `p(u, v) ∨ q(u, v)`, in
//! particular the normal congruence of a rational surface, with order, class and focal
//! coefficients (Pottmann and Wallner, "Computational Line Geometry", 2001, §3.2 (focal
//! points, `det(p, q, p_u + λq_u, p_v + λq_v) = 0`) and §5.1 (normal congruences);
//! docs/math/lines-and-canal.md, "Congruences of order one" for the elimination).
//!
//! **Normal congruence.** For a rational surface `X(u, v) = (W, X₁, X₂, X₃)` the tangent
//! plane is `e = [X, X_u, X_v]` (the plane through the three points, `plane3`), its normal
//! direction the ideal point `(0, e₁, e₂, e₃)`; the normal line is `X ∨ (0, e₁, e₂, e₃)`.
//! Certified: the normal direction is orthogonal to both affine tangent vectors
//! `W ∂X_i − X_i ∂W` (`∂ = ∂_u, ∂_v`), as polynomial identities, and `p ∧ q ≢ 0`.
//!
//! **Order and class** (`order_and_class`): the number of congruence lines through a generic
//! point and in a generic plane, by Schubert conditions and resultants over `Q` at fixed
//! pseudo-random choices. The count is exact for generic choices and can only drop for a
//! non-generic coincidence; `order_class(trials)` repeats it at independent pseudo-random
//! choices, takes the maximum and certifies that two choices reach it
//! ([`OrderClass::certificate`]); the maxima are proved lower bounds, and the Bézout bound
//! of `(m + n)·μ` minus the base points ([`super::order_bound`]) is the upper bound: when
//! they meet, order and class are exact ([`OrderClass::exact`],
//! [`OrderClass::exact_certificate`]), otherwise [`OrderClass::describe`] says "at least".

use super::net::plane3;
use super::order_one::{
    focal_coefficients, order_and_class, order_and_class_decided, OrderClass, OrderOneError,
};
use super::plucker::wedge;
use crate::pn::poly::zero_cert;
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Rational, Scalar};

/// A congruence `p(u, v) ∨ q(u, v)` (homogeneous points, polynomial in two parameters).
#[derive(Debug, Clone)]
pub struct ParametrizedCongruence<F> {
    p: [MPoly<F>; 4],
    q: [MPoly<F>; 4],
    /// For a normal congruence: the surface `X = p`.
    normal_of: bool,
}

impl<F: Scalar> ParametrizedCongruence<F> {
    /// The congruence of the lines `p(u, v) ∨ q(u, v)`.
    ///
    /// # Errors
    /// [`OrderOneError::Elimination`] if `p ∧ q ≡ 0` (no lines) or the lines depend on fewer
    /// than two parameters (the Plücker coordinates and their partial derivatives span at
    /// most a pencil: checked by `l ∧ l_u ∧ l_v ≢ 0` at the level of `p, q`: the focal
    /// coefficients all vanish).
    pub fn new(p: [MPoly<F>; 4], q: [MPoly<F>; 4]) -> Result<Self, OrderOneError> {
        let c = ParametrizedCongruence {
            p,
            q,
            normal_of: false,
        };
        c.check()?;
        Ok(c)
    }

    /// The normal congruence of the rational surface `X(u, v)` (homogeneous `(W, X₁, X₂,
    /// X₃)`, module docs).
    ///
    /// # Errors
    /// As [`Self::new`]; in particular a degenerate surface (`[X, X_u, X_v] ≡ 0`: a curve or
    /// a point) has no normal lines.
    pub fn normals(x: [MPoly<F>; 4]) -> Result<Self, OrderOneError> {
        let xu: [MPoly<F>; 4] = core::array::from_fn(|k| x[k].partial(0));
        let xv: [MPoly<F>; 4] = core::array::from_fn(|k| x[k].partial(1));
        let e = plane3(&x, &xu, &xv);
        if e[1..].iter().all(MPoly::is_zero) {
            return Err(OrderOneError::Elimination(
                "the surface has no tangent plane ([X, X_u, X_v] ≡ 0 or a plane at infinity): no normal congruence".into(),
            ));
        }
        let q = [MPoly::zero(2), e[1].clone(), e[2].clone(), e[3].clone()];
        let c = ParametrizedCongruence {
            p: x,
            q,
            normal_of: true,
        };
        c.check()?;
        Ok(c)
    }

    fn check(&self) -> Result<(), OrderOneError> {
        if wedge(&self.p, &self.q).iter().all(MPoly::is_zero) {
            return Err(OrderOneError::Elimination(
                "p ∧ q ≡ 0: the points do not span lines".into(),
            ));
        }
        if self.focal().iter().all(MPoly::is_zero) {
            return Err(OrderOneError::Elimination(
                "every point of every line is focal: the family is at most one-parametric (a ruled surface) or degenerate".into(),
            ));
        }
        Ok(())
    }

    /// The two points spanning the lines.
    pub fn points(&self) -> (&[MPoly<F>; 4], &[MPoly<F>; 4]) {
        (&self.p, &self.q)
    }

    /// The Plücker coordinates `p ∧ q` of the lines.
    pub fn lines(&self) -> [MPoly<F>; 6] {
        wedge(&self.p, &self.q)
    }

    /// The focal coefficients `[A₀, A₁, A₂]`: the focal points of the line at `(u, v)` are
    /// `p + λq` for the roots of `A₀ + λA₁ + λ²A₂` (Pottmann and Wallner 2001, §3.2).
    pub fn focal(&self) -> [MPoly<F>; 3] {
        focal_coefficients(&self.p, &self.q)
    }

    /// The two focal sheets as rational point families `α p + β q` where they are rational
    /// without a square root: `A₀ ≡ 0` (`p` is focal; the other root `λ = −A₁/A₂` gives
    /// `A₂ p − A₁ q`), `A₂ ≡ 0` (`q` is focal; the other `A₁ p − A₀ q`), both (`p` and `q`:
    /// focal curves or surfaces generating the congruence). `None` otherwise: the focal
    /// points are `p + λq` with `λ` a root of `A₀ + λA₁ + λ²A₂`, over `Q(√(A₁² − 4A₀A₂))` in
    /// general (pointwise: `focal_points`).
    ///
    /// Exact scalars also cover a square discriminant: if `A₁² − 4A₀A₂ = g²` for a
    /// polynomial `g` over `Q`, the roots `λ = (−A₁ ± g)/(2A₂)` are rational functions and
    /// the sheets are `2A₂ p + (−A₁ ± g) q` (common polynomial factors of the four
    /// coordinates cancelled). This is the case of the normal congruence of a surface with
    /// rational principal curvatures (e.g. the paraboloid of revolution: the axis and the
    /// evolute surface).
    pub fn rational_focal_sheets(&self) -> Option<[[MPoly<F>; 4]; 2]> {
        let [a0, a1, a2] = self.focal();
        let comb = |a: &MPoly<F>, b: &MPoly<F>| -> [MPoly<F>; 4] {
            core::array::from_fn(|k| &(a * &self.p[k]) - &(b * &self.q[k]))
        };
        match (a0.is_zero(), a2.is_zero()) {
            (true, true) => Some([self.p.clone(), self.q.clone()]),
            (true, false) => Some([self.p.clone(), comb(&a2, &a1)]),
            (false, true) => Some([self.q.clone(), comb(&a1, &a0)]),
            (false, false) => {
                if !F::EXACT {
                    return None;
                }
                let disc = &(&a1 * &a1) - &(&a0 * &a2).scale(&F::from_i64(4));
                let dq = disc.map(|c| c.to_rational().unwrap_or_else(|| Rational::from(0)));
                let g = crate::pn::hypercyclide::mpoly_sqrt(&dq)?;
                let g: MPoly<F> = g.map(F::from_rational);
                let two_a2 = a2.scale(&F::from_i64(2));
                let sheet = |sign: i64| -> [MPoly<F>; 4] {
                    let b = &(-&a1) + &g.scale(&F::from_i64(sign));
                    let mut f: [MPoly<F>; 4] =
                        core::array::from_fn(|k| &(&two_a2 * &self.p[k]) + &(&b * &self.q[k]));
                    crate::pn::poly::cancel_gcd(&mut f);
                    f
                };
                Some([sheet(1), sheet(-1)])
            }
        }
    }

    /// `true` if the point family `f(u, v)` is a surface (`[f, f_u, f_v] ≢ 0`), `false` for a
    /// curve or a point (a focal sheet that degenerates, e.g. the axis of a surface of
    /// revolution or the centre of a sphere).
    pub fn is_surface(f: &[MPoly<F>; 4]) -> bool {
        let fu: [MPoly<F>; 4] = core::array::from_fn(|k| f[k].partial(0));
        let fv: [MPoly<F>; 4] = core::array::from_fn(|k| f[k].partial(1));
        plane3(f, &fu, &fv).iter().any(|x| !x.is_zero())
    }

    /// Two points per line for drawing segments: `(p, q)`, or `(p, p + q)` when `q` is an
    /// ideal point (`q₀ ≡ 0`, e.g. the normal direction of a normal congruence), so that the
    /// segment `(1 − λ)p + λ(p + q) = p + λq` stays finite.
    pub fn segment_points(&self) -> ([MPoly<F>; 4], [MPoly<F>; 4]) {
        if self.q[0].is_zero() {
            let pq: [MPoly<F>; 4] = core::array::from_fn(|k| &self.p[k] + &self.q[k]);
            (self.p.clone(), pq)
        } else {
            (self.p.clone(), self.q.clone())
        }
    }

    /// `true` for a normal congruence built by [`Self::normals`].
    pub fn is_normal_congruence(&self) -> bool {
        self.normal_of
    }
}

impl ParametrizedCongruence<Rational> {
    /// `(order, class, μ)`: lines through a generic point, lines in a generic plane, and the
    /// parameter points per line (module docs; a measurement at fixed generic choices).
    ///
    /// # Errors
    /// [`OrderOneError::Elimination`] when the resultants exceed the dense limit.
    pub fn order_and_class(&self) -> Result<(usize, usize, usize), OrderOneError> {
        order_and_class(&self.p, &self.q)
    }

    /// Order, class and `μ` decided over `trials` independent choices (at least two must
    /// reach the maximum; [`order_and_class_decided`], [`OrderClass::certificate`]).
    ///
    /// # Errors
    /// [`OrderOneError::Elimination`] if no choice succeeds.
    pub fn order_class(&self, trials: usize) -> Result<OrderClass, OrderOneError> {
        order_and_class_decided(&self.p, &self.q, trials)
    }
}

impl<F: Scalar> Certified for ParametrizedCongruence<F> {
    /// `p ∧ q ≢ 0` and the Klein identity of `p ∧ q`; for a normal congruence the normal
    /// direction orthogonal to both tangent vectors `W ∂X − X ∂W` (exact identities).
    fn certify(&self) -> Vec<Certificate> {
        let l = self.lines();
        let mut out = vec![
            Certificate::decide(
                "the congruence lines p ∨ q are lines: p ∧ q ≢ 0",
                l.iter().any(|x| !x.is_zero()),
                F::EXACT,
                || "p ∧ q ≡ 0".into(),
            ),
            zero_cert(
                "the lines lie on the Klein quadric: l₁l₄ + l₂l₅ + l₃l₆ ≡ 0",
                &(&(&(&l[0] * &l[3]) + &(&l[1] * &l[4])) + &(&l[2] * &l[5])),
                1.0,
            ),
        ];
        if let Some(sheets) = self.rational_focal_sheets() {
            for (k, f) in sheets.iter().enumerate() {
                // the sheet is on the line: f ∧ p ∧ q ≡ 0 (all four 3×3 minors)
                let on = plane3(f, &self.p, &self.q)
                    .iter()
                    .fold(MPoly::zero(2), |acc, x| &acc + &(x * x));
                out.push(zero_cert(
                    &format!(
                        "focal sheet {}: its points lie on the congruence lines",
                        k + 1
                    ),
                    &on,
                    1.0,
                ));
                // focal: for f = αp + βq, det(p, q, f_u, f_v) = α²(A₀ + λA₁ + λ²A₂) with
                // λ = β/α, so ≡ 0 iff f is a focal point of its line (Pottmann and Wallner
                // 2001, §3.2)
                let fu: [MPoly<F>; 4] = core::array::from_fn(|j| f[j].partial(0));
                let fv: [MPoly<F>; 4] = core::array::from_fn(|j| f[j].partial(1));
                let det = super::net::det4v(&self.p, &self.q, &fu, &fv);
                out.push(zero_cert(
                    &format!(
                        "focal sheet {}: det(p, q, f_u, f_v) ≡ 0 (the line touches the sheet)",
                        k + 1
                    ),
                    &det,
                    1.0,
                ));
            }
        }
        if self.normal_of {
            let x = &self.p;
            for (i, name) in [(0usize, "u"), (1, "v")] {
                let dot = (1..4).fold(MPoly::zero(2), |acc, k| {
                    let t = &(&x[0] * &x[k].partial(i)) - &(&x[k] * &x[0].partial(i));
                    &acc + &(&self.q[k] * &t)
                });
                out.push(zero_cert(
                    &format!("the normal line is orthogonal to the surface: ⟨n, W X_{name} − X W_{name}⟩ ≡ 0"),
                    &dot,
                    1.0,
                ));
            }
        }
        out
    }
}
