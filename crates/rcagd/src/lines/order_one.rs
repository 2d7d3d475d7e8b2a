//! Line congruences of order one beyond the nets (Gruber 2008 §1.1.4, §1.1.7, §1.1.8;
//! E. Kummer's classification as presented in Pottmann and Wallner, "Computational Line
//! Geometry", 2001, §3.2; docs/math/lines-and-canal.md, "Congruences of order one").
//!
//! A congruence has **order** `m` (lines through a generic point) and **class** `n` (lines in
//! a generic plane). Its **focal points** on a line `l(u, v) = p ∨ q` are the points
//! `x = p + λq` where neighbouring lines meet `l`:
//! `det(p, q, p_u + λ q_u, p_v + λ q_v) = A₀ + λA₁ + λ²A₂ = 0` ([`focal_coefficients`]);
//! the two roots trace the two sheets of the focal surface.
//!
//! * **Chord congruence of a twisted cubic** `k(t) = a₀ + t a₁ + t² a₂ + t³ a₃`
//!   ([`CubicChordCongruence`], order 1, class 3): the chord through `k(s), k(t)` depends on
//!   `e = (e₀ : e₁ : e₂) = (1 : s + t : st)` only; for the normal cubic `(1, t, t², t³)` it is
//!   `σ(e) = k(s) ∧ k(t)/(t − s) = (e₀², e₀e₁, e₁² − e₀e₂; e₂², −e₁e₂, e₀e₂)` (tangents for
//!   `e₁² = 4e₀e₂`, real chords with conjugate end points for `e₁² < 4e₀e₂`). The points of the
//!   chord satisfy `e₀x_{i+2} − e₁x_{i+1} + e₂xᵢ = 0` (`i = 0, 1`), so the chord through `x`
//!   is `e = (x₀x₂ − x₁², x₀x₃ − x₁x₂, x₁x₃ − x₂²)` — rational: the congruence is a
//!   fibration off the cubic. A plane meets the cubic in 3 points: 3 chords (class 3). Both
//!   focal sheets are the cubic itself (`A₀ ≡ A₂ ≡ 0`).
//! * **(1, n)-congruence** ([`OneNCongruence`], Gruber §1.1.8): the lines meeting a line `g`
//!   and a curve `k` of order `n` that meets `g` in `n − 1` points. A plane through `g` and a
//!   point `P` meets `k` in the `n − 1` fixed points on `g` and one residual point `Q(P)`,
//!   rational in `P`: `P ∨ Q` is the unique congruence line through `P` (order 1). A plane
//!   meets `g` in one point and `k` in `n` points: class `n`. The focal sheets are `k` and `g`.

use super::net::{det4v, dot4, plane3};
use super::plucker::{incidence_matrix, klein_form, reciprocal_product, wedge, Line};
use super::{fmt_vec, is_small, scale_of, LineError};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Matrix, Poly, Rational, Scalar};
use rcagd_geom::certify::polynomial_is_zero_scaled;
use thiserror::Error;

/// Errors of the congruences of order one.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum OrderOneError {
    /// The four coefficient points of a cubic are dependent: not a twisted cubic.
    #[error("not a twisted cubic: det(a₀, a₁, a₂, a₃) = 0 (the curve lies in a plane)")]
    NotATwistedCubic,
    /// The curve does not meet the focal line in `n − 1` points.
    #[error("the curve of order {order} meets the line in {meets} points (counted with multiplicity), a (1, n)-congruence needs {needed} (Gruber §1.1.8)")]
    NotOrderOne {
        /// The order `n` of the curve.
        order: usize,
        /// The number of common points found (`deg gcd`).
        meets: usize,
        /// `n − 1`.
        needed: usize,
    },
    /// The curve lies in a plane through the line (or is constant).
    #[error("the curve lies in a plane through the line: no congruence")]
    CurveInPlane,
    /// A point on a focal curve or line (infinitely many lines pass through it).
    #[error("singular point of the congruence: {0}")]
    SingularPoint(String),
    /// The elimination of [`order_and_class`] failed (degrees beyond the dense resultant
    /// limit) or the congruence is degenerate.
    #[error("order and class by elimination: {0}")]
    Elimination(String),
    /// A line-geometry failure underneath.
    #[error(transparent)]
    Line(#[from] LineError),
}

/// The focal coefficients `[A₀, A₁, A₂]` of the congruence `p(u, v) ∨ q(u, v)`:
/// `det(p, q, p_u + λq_u, p_v + λq_v) = A₀ + λA₁ + λ²A₂` (module docs; Pottmann and Wallner
/// 2001, §3.2). `λ` is the focal point `p + λq` (`A₂ = 0`: `q` itself is focal).
pub fn focal_coefficients<F: Scalar>(p: &[MPoly<F>; 4], q: &[MPoly<F>; 4]) -> [MPoly<F>; 3] {
    let d = |x: &[MPoly<F>; 4], i: usize| -> [MPoly<F>; 4] {
        core::array::from_fn(|k| x[k].partial(i))
    };
    let (pu, pv, qu, qv) = (d(p, 0), d(p, 1), d(q, 0), d(q, 1));
    [
        det4v(p, q, &pu, &pv),
        &det4v(p, q, &qu, &pv) + &det4v(p, q, &pu, &qv),
        det4v(p, q, &qu, &qv),
    ]
}

/// The focal points of the line `p(u₀, v₀) ∨ q(u₀, v₀)` of the congruence `p ∨ q`: the
/// roots `λ` of `A₀ + λA₁ + λ²A₂` ([`focal_coefficients`]) as points `p + λq` (`λ = ∞`: `q`),
/// over the square-root extension; an empty list if the two focal points are conjugate
/// complex (an elliptic line of the congruence), one point for a double root.
///
/// # Errors
/// [`OrderOneError::SingularPoint`] if `A₀ = A₁ = A₂ = 0` at the parameters (every point of
/// the line is focal: a torsal line or a singular parameter).
pub fn focal_points<F: super::SqrtScalar>(
    p: &[MPoly<F>; 4],
    q: &[MPoly<F>; 4],
    u: &F,
    v: &F,
) -> Result<Vec<[F::Ext; 4]>, OrderOneError> {
    let x = [u.clone(), v.clone()];
    let ev = |m: &MPoly<F>| m.eval(&x).unwrap_or_else(|_| F::zero());
    let [a0, a1, a2] = focal_coefficients(p, q).map(|c| ev(&c));
    let (pp, qq): ([F; 4], [F; 4]) = (p.clone().map(|c| ev(&c)), q.clone().map(|c| ev(&c)));
    let emb = |w: &[F; 4]| -> [F::Ext; 4] { core::array::from_fn(|k| w[k].embed()) };
    let at = |l: &F::Ext| -> [F::Ext; 4] {
        core::array::from_fn(|k| pp[k].embed() + l.clone() * qq[k].embed())
    };
    if a2.is_zero() {
        if a1.is_zero() {
            if a0.is_zero() {
                return Err(OrderOneError::SingularPoint(format!(
                    "every point of the line at ({}, {}) is focal",
                    crate::error::format_scalar(u),
                    crate::error::format_scalar(v)
                )));
            }
            // a double root at λ = ∞
            return Ok(vec![emb(&qq)]);
        }
        let l = (-a0 / a1).embed();
        return Ok(vec![at(&l), emb(&qq)]);
    }
    let four = F::from_i64(4);
    let disc = a1.clone() * a1.clone() - four * a0 * a2.clone();
    let two_a2 = (a2.clone() + a2).embed();
    if disc.is_zero() {
        return Ok(vec![at(&(-a1.embed() / two_a2))]);
    }
    let Some(r) = disc.sqrt_ext() else {
        return Ok(Vec::new());
    };
    let l1 = (-a1.embed() + r.clone()) / two_a2.clone();
    let l2 = (-a1.embed() - r) / two_a2;
    Ok(vec![at(&l1), at(&l2)])
}

/// Order, class and parametrization degree `(m, n, μ)` of the congruence `p(u, v) ∨ q(u, v)`
/// (exact, Schubert conditions;
/// docs/math/lines-and-canal.md, "Congruences of order one"): a line passes through a point
/// `P` iff it meets three non-coplanar lines through `P`, and lies in a plane iff it meets
/// three non-concurrent lines of the plane. Each condition `Ω(gᵢ, l(u, v)) = 0` is a
/// polynomial in `(u, v)`; after a shear of the parameters the common zeros of three of
/// them are the roots of `gcd(Res_v(f₁, f₂), Res_v(f₁, f₃))`, from which the base points (the
/// zeros shared by every choice of `P` resp. the plane: `p ∧ q = 0`) are removed. The counts
/// are divided by the degree `μ` of the parametrization (parameter points per line, counted
/// with the lines through two points of a generic congruence line). Fixed pseudo-random
/// choices of points, lines and shear make the result exact for generic data; a
/// non-generic coincidence can only lower a count (the conic `(1 + 2t², t, −2t², −5t)` with
/// the x-axis, a (1, 2)-congruence, counts order 0), so the count is a measurement, not a
/// certificate.
///
/// # Errors
/// [`OrderOneError::Elimination`] if a resultant fails (degrees beyond the dense limit,
/// more than two parameters) or the congruence is degenerate (`μ = 0`).
pub fn order_and_class(
    p: &[MPoly<Rational>; 4],
    q: &[MPoly<Rational>; 4],
) -> Result<(usize, usize, usize), OrderOneError> {
    let c = raw_counts(p, q, &Choices::fixed()).map_err(OrderOneError::Elimination)?;
    Ok((c.0 / c.2, c.1 / c.2, c.2))
}

/// The result of [`order_and_class_decided`]: order, class and parametrization degree with
/// the raw counts at every choice (`None`: the choice was rejected as non-generic, e.g. a
/// zero resultant).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OrderClass {
    /// Lines through a generic point.
    pub order: usize,
    /// Lines in a generic plane.
    pub class: usize,
    /// Parameter points per generic line.
    pub mu: usize,
    /// The raw counts `(m·μ, n·μ, μ)` per independent choice.
    pub counts: Vec<Option<(usize, usize, usize)>>,
    /// The upper bound of `(m + n)·μ` by Bézout minus the base points found (rational
    /// finite ones, every one at infinity; [`super::order_bound`]); `None` if it could not
    /// be computed.
    pub upper: Option<super::order_bound::BezoutBound>,
}

impl OrderClass {
    /// `true` if the proved lower bounds meet the upper bound: `m·μ + n·μ` (the counts,
    /// lower bounds of the generic ones) equals the Bézout bound of `(m + n)·μ`, so both
    /// counts are the generic ones ([`super::order_bound`]).
    pub fn exact(&self) -> bool {
        self.upper
            .as_ref()
            .is_some_and(|u| u.bound == (self.order + self.class) * self.mu)
    }

    /// The largest order and class the bounds allow: `m ≤ (U − n·μ)/μ`, `n ≤ (U − m·μ)/μ`
    /// for the upper bound `U` of `(m + n)·μ` (`None` without a bound).
    pub fn at_most(&self) -> Option<(usize, usize)> {
        let u = self.upper.as_ref()?.bound;
        let mu = self.mu.max(1);
        Some((
            u.saturating_sub(self.class * mu) / mu,
            u.saturating_sub(self.order * mu) / mu,
        ))
    }

    /// A sentence: `order m, class n (exact)` when the bounds meet, else
    /// `order at least m (at most m'), class at least n (at most n')`.
    pub fn describe(&self) -> String {
        match (self.exact(), self.at_most()) {
            (true, _) => format!(
                "order {}, class {} (exact: the lower bounds meet the Bézout bound (m + n)·μ ≤ {})",
                self.order,
                self.class,
                (self.order + self.class) * self.mu
            ),
            (false, Some((m, n))) => format!(
                "order at least {} (at most {m}), class at least {} (at most {n})",
                self.order, self.class
            ),
            (false, None) => format!(
                "order at least {}, class at least {} (no upper bound)",
                self.order, self.class
            ),
        }
    }

    /// The certificate that order and class are exact: the counts (proved lower bounds)
    /// reach the Bézout upper bound of `(m + n)·μ`.
    pub fn exact_certificate(&self) -> Certificate {
        Certificate::decide(
            format!(
                "order {} and class {} exact: (m + n)·μ = {} reaches the upper bound Bézout − Σ base-point multiplicities²",
                self.order,
                self.class,
                (self.order + self.class) * self.mu
            ),
            self.exact(),
            true,
            || match &self.upper {
                Some(u) => format!(
                    "upper bound {} in {} (Bézout {}, base points {:?}): {}",
                    u.bound,
                    u.compactification,
                    u.bezout,
                    u.base_points,
                    self.describe()
                ),
                None => "no upper bound computed".into(),
            },
        )
    }

    /// How many choices reached the stated `(m·μ, n·μ, μ)`.
    pub fn agreeing(&self) -> usize {
        let want = (self.order * self.mu, self.class * self.mu, self.mu);
        self.counts.iter().filter(|c| **c == Some(want)).count()
    }

    /// The certificate: the stated counts are the componentwise maximum over the choices,
    /// reached by at least two independent choices, and `μ` divides both (a count at a
    /// non-generic choice can only drop, see [`order_and_class_decided`]).
    pub fn certificate(&self) -> Certificate {
        let k = self.agreeing();
        let n = self.counts.len();
        Certificate::decide(
            format!(
                "order {} and class {} (μ = {}): exact elimination counts at {n} independent choices of point and plane, the maximum reached by {k} ≥ 2 of them and divisible by μ",
                self.order, self.class, self.mu
            ),
            k >= 2,
            true,
            || format!("counts per choice {:?}", self.counts),
        )
    }
}

/// Order, class and `μ` of the congruence `p ∨ q` decided over `trials` independent choices
/// of points, lines and planes ([`order_and_class`] is the first of them): each count is
/// exact for its choice and can only drop at a non-generic one (a solution moving to a base
/// point or to parameter infinity, two solutions merging), so the componentwise maximum of
/// the counts is taken, and [`OrderClass::certificate`] holds when at least two choices
/// reach it with `μ` dividing both counts. Choices whose resultants vanish identically or
/// whose counts are not divisible by their `μ` are rejected.
///
/// # Errors
/// [`OrderOneError::Elimination`] if no choice succeeds (degrees beyond the dense
/// resultant limit, a degenerate congruence).
pub fn order_and_class_decided(
    p: &[MPoly<Rational>; 4],
    q: &[MPoly<Rational>; 4],
    trials: usize,
) -> Result<OrderClass, OrderOneError> {
    let mut counts = Vec::with_capacity(trials.max(1));
    let mut last_err = String::new();
    for k in 0..trials.max(1) {
        let ch = if k == 0 {
            Choices::fixed()
        } else {
            Choices::seeded(k as u64)
        };
        match raw_counts(p, q, &ch) {
            Ok(c) if c.2 > 0 && c.0 % c.2 == 0 && c.1 % c.2 == 0 => counts.push(Some(c)),
            Ok(c) => {
                last_err = format!("counts {c:?} not divisible by μ");
                counts.push(None);
            }
            Err(e) => {
                last_err = e;
                counts.push(None);
            }
        }
    }
    let best = counts
        .iter()
        .flatten()
        .fold(None, |acc: Option<(usize, usize, usize)>, c| {
            Some(match acc {
                None => *c,
                Some(a) => (a.0.max(c.0), a.1.max(c.1), a.2.max(c.2)),
            })
        })
        .ok_or(OrderOneError::Elimination(last_err))?;
    if best.0 % best.2 != 0 || best.1 % best.2 != 0 {
        return Err(OrderOneError::Elimination(format!(
            "the largest counts {best:?} are not divisible by μ: no consistent generic choice"
        )));
    }
    Ok(OrderClass {
        order: best.0 / best.2,
        class: best.1 / best.2,
        mu: best.2,
        counts,
        upper: super::order_bound::degree_upper_bound(p, q).ok(),
    })
}

/// The points, line directions, planes and parameter shear of one elimination.
struct Choices {
    shear: (i64, i64),
    points: [[i64; 4]; 3],
    dirs: [[i64; 4]; 3],
    planes: [[[i64; 4]; 3]; 3],
    line_param: ((i64, i64), (i64, i64)),
}

impl Choices {
    /// The original fixed choices.
    fn fixed() -> Self {
        Choices {
            shear: (2, 5),
            points: [[3, 1, -2, 5], [2, -5, 3, 1], [5, 2, 7, -3]],
            dirs: [[0, 1, 2, -1], [0, -3, 1, 2], [0, 2, -1, 5]],
            planes: [
                [[1, 2, -1, 3], [2, -1, 4, 1], [3, 5, 2, -2]],
                [[2, 3, 1, -4], [1, -2, -3, 5], [4, 1, 6, 2]],
                [[3, -4, 2, 1], [5, 3, -1, 2], [1, 6, 5, -3]],
            ],
            line_param: ((3, 7), (-5, 4)),
        }
    }

    /// Pseudo-random small integers (a linear congruential generator seeded by `seed`).
    fn seeded(seed: u64) -> Self {
        let mut state = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let mut next = |lo: i64, hi: i64| -> i64 {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let span = (hi - lo + 1) as u64;
            lo + ((state >> 33) % span) as i64
        };
        let mut pt = |w0: bool| -> [i64; 4] {
            let mut a = [0i64; 4];
            for (i, x) in a.iter_mut().enumerate() {
                *x = if i == 0 && w0 {
                    0
                } else if i == 0 {
                    next(1, 9)
                } else {
                    next(-9, 9)
                };
            }
            a
        };
        let points = [pt(false), pt(false), pt(false)];
        let dirs = [pt(true), pt(true), pt(true)];
        let planes = [
            [pt(false), pt(false), pt(false)],
            [pt(false), pt(false), pt(false)],
            [pt(false), pt(false), pt(false)],
        ];
        let shear = (next(1, 9), next(3, 11));
        let line_param = ((next(-9, 9), next(2, 11)), (next(-9, 9), next(2, 11)));
        Choices {
            shear,
            points,
            dirs,
            planes,
            line_param,
        }
    }
}

/// The raw counts `(m·μ, n·μ, μ)` at one choice.
fn raw_counts(
    p: &[MPoly<Rational>; 4],
    q: &[MPoly<Rational>; 4],
    ch: &Choices,
) -> Result<(usize, usize, usize), String> {
    use rcagd_algebra::mpoly::resultant_in;
    let r = |a: i64, b: i64| Rational::from_ratio(a, b);
    // shear (u, v) ↦ (u + 2v/5, v) against coincident u-coordinates
    let shear = |m: &MPoly<Rational>| -> MPoly<Rational> {
        let s = &MPoly::var(2, 0) + &MPoly::var(2, 1).scale(&r(ch.shear.0, ch.shear.1));
        let t = MPoly::var(2, 1);
        m.terms().fold(MPoly::zero(2), |acc, (e, c)| {
            &acc + &(&s.pow(e.first().copied().unwrap_or(0))
                * &t.pow(e.get(1).copied().unwrap_or(0)))
                .scale(c)
        })
    };
    let l: [MPoly<Rational>; 6] =
        wedge(&p.clone().map(|c| shear(&c)), &q.clone().map(|c| shear(&c)));
    // a common factor of the Plücker coordinates (a curve of parameters where p ∧ q = 0, e.g.
    // the diagonal of the chord parametrization) is divided out
    let l = without_common_factor(l);
    let cond = |g: &[Rational; 6]| -> MPoly<Rational> {
        let gp: [MPoly<Rational>; 6] = core::array::from_fn(|k| MPoly::constant(2, g[k].clone()));
        reciprocal_product(&gp, &l)
    };
    let line = |a: [i64; 4], b: [i64; 4]| wedge(&a.map(Rational::from), &b.map(Rational::from));
    // the u-coordinates of the common zeros of three conditions: gcd(Res_v(f₁, f₂),
    // Res_v(f₁, f₃)); verified to be genuine (every root u₀ has one v₀ with
    // f₁ = f₂ = f₃ = 0, not a root of (f₁, f₂) paired with another of (f₁, f₃)) by
    // `common_zeros_verified`, else the choice is rejected as special
    let gcd_count = |fs: [MPoly<Rational>; 3]| -> Result<Poly<Rational>, String> {
        let r12 = resultant_in(&fs[0], &fs[1], 1).map_err(|e| e.to_string())?;
        let r13 = resultant_in(&fs[0], &fs[2], 1).map_err(|e| e.to_string())?;
        let g = r12.gcd(&r13);
        if !g.is_zero() && !common_zeros_verified(&fs, &g)? {
            return Err(
                "the gcd of the resultants pairs different roots (a special choice)".into(),
            );
        }
        Ok(g)
    };
    // three lines through a point P (directions d₁, d₂, d₃)
    let through = |pt: [i64; 4]| -> Result<Poly<Rational>, String> {
        gcd_count(ch.dirs.map(|d| cond(&line(pt, d))))
    };
    // three lines of the plane through three points
    let inplane = |a: [i64; 4], b: [i64; 4], c: [i64; 4]| -> Result<Poly<Rational>, String> {
        gcd_count([cond(&line(a, b)), cond(&line(b, c)), cond(&line(c, a))])
    };
    let pts = [
        through(ch.points[0])?,
        through(ch.points[1])?,
        through(ch.points[2])?,
    ];
    let [a0, a1, a2] = ch.planes;
    let pls = [
        inplane(a0[0], a0[1], a0[2])?,
        inplane(a1[0], a1[1], a1[2])?,
        inplane(a2[0], a2[1], a2[2])?,
    ];
    // base points: common to every choice
    let strip = |x: &Poly<Rational>, base: &Poly<Rational>| -> usize {
        let mut y = x.clone();
        loop {
            let c = y.gcd(base);
            if c.degree().unwrap_or(0) == 0 || y.degree().unwrap_or(0) == 0 {
                break;
            }
            match y.div_exact(&c) {
                Ok(z) => y = z,
                Err(_) => break,
            }
        }
        y.degree().unwrap_or(0)
    };
    // a zero polynomial (the three conditions share a factor: a non-generic choice) is
    // skipped in favour of the next point or plane
    let all = pts.iter().chain(&pls).filter(|x| !x.is_zero()).fold(
        Poly::zero(),
        |acc: Poly<Rational>, x| {
            if acc.is_zero() {
                x.clone()
            } else {
                acc.gcd(x)
            }
        },
    );
    let base = if all.degree().unwrap_or(0) == 0 {
        Poly::constant(r(1, 1))
    } else {
        all
    };
    let first = |xs: &[Poly<Rational>; 3], what: &str| -> Result<Poly<Rational>, String> {
        xs.iter()
            .find(|x| !x.is_zero())
            .cloned()
            .ok_or_else(|| format!("no generic {what} among the three tried"))
    };
    let count_pt = strip(&first(&pts, "point")?, &base);
    let count_pl = strip(&first(&pls, "plane")?, &base);
    // μ: parameter points of a generic congruence line l(u₀, v₀): lines through two of its
    // points
    let ((un, ud), (vn, vd)) = ch.line_param;
    let (u0, v0) = (r(un, ud), r(vn, vd));
    let pv: [Rational; 4] = p.clone().map(|c| {
        c.eval(&[u0.clone(), v0.clone()])
            .unwrap_or_else(|_| r(0, 1))
    });
    let qv: [Rational; 4] = q.clone().map(|c| {
        c.eval(&[u0.clone(), v0.clone()])
            .unwrap_or_else(|_| r(0, 1))
    });
    let on = |k: i64| -> [Rational; 4] {
        core::array::from_fn(|i| pv[i].clone() + Rational::from(k) * qv[i].clone())
    };
    let ds: [[i64; 4]; 3] = ch.dirs;
    let dq = |d: [i64; 4]| -> [Rational; 4] { d.map(Rational::from) };
    let (a, b) = (on(1), on(-2));
    let fs: Vec<MPoly<Rational>> = [&a, &b]
        .iter()
        .flat_map(|pt| {
            ds.iter()
                .map(|d| cond(&wedge(pt, &dq(*d))))
                .collect::<Vec<_>>()
        })
        .collect();
    let mut g = resultant_in(&fs[0], &fs[1], 1).map_err(|e| e.to_string())?;
    for f in &fs[2..] {
        g = g.gcd(&resultant_in(&fs[0], f, 1).map_err(|e| e.to_string())?);
    }
    let mu = strip(&g, &base);
    if mu == 0 {
        return Err("degenerate congruence: no parameter point on a generic line (μ = 0)".into());
    }
    Ok((count_pt, count_pl, mu))
}

/// `true` if every root `u₀` of `g` (a divisor of `gcd(Res_v(f₁, f₂), Res_v(f₁, f₃))`)
/// is the `u` of a common zero of `f₁, f₂, f₃`: the square-free part of `g` divides
/// `Res_v(f₁, f₂ + c f₃)` for `c = 1, …, deg_v f₁ + 1`. (If at `u₀` no root `v_i` of
/// `f₁(u₀, ·)` is a common root of `f₂` and `f₃`, then `f₂ + c f₃` vanishes at some `v_i`
/// for at most one `c` per root, i.e. for at most `deg_v f₁` values of `c`; a vanishing
/// leading coefficient of `f₁` at `u₀` makes every resultant vanish there and is a base
/// point or a special choice either way.)
fn common_zeros_verified(fs: &[MPoly<Rational>; 3], g: &Poly<Rational>) -> Result<bool, String> {
    use rcagd_algebra::mpoly::resultant_in;
    if g.degree().unwrap_or(0) == 0 {
        return Ok(true);
    }
    let sf = g.square_free();
    let n = fs[0].degree_in(1).unwrap_or(0) as i64;
    for c in 1..=n + 1 {
        let h = &fs[1] + &fs[2].scale(&Rational::from(c));
        let r = resultant_in(&fs[0], &h, 1).map_err(|e| e.to_string())?;
        if r.is_zero() {
            continue;
        }
        let (_, rem) = r.div_rem(&sf).map_err(|e| e.to_string())?;
        if !rem.is_zero() {
            return Ok(false);
        }
    }
    Ok(true)
}

fn mag<F: Scalar>(p: &MPoly<F>) -> f64 {
    p.terms().map(|(_, c)| c.to_f64().abs()).fold(1.0, f64::max)
}

fn coeffs_of<F: Scalar>(ps: &[MPoly<F>]) -> Vec<F> {
    ps.iter()
        .flat_map(|p| p.terms().map(|(_, c)| c.clone()).collect::<Vec<_>>())
        .collect()
}

fn zero_cert<F: Scalar>(name: &str, ps: &[MPoly<F>]) -> Certificate {
    let scale = 16.0 * ps.iter().map(mag).fold(1.0, f64::max);
    polynomial_is_zero_scaled(name, &coeffs_of(ps), scale)
}

/// The focal certificates: `A₀ ≡ 0`, `A₂ ≡ 0`, `A₁ ≢ 0`, i.e. the focal points of every line
/// are its generating points `p` (`λ = 0`) and `q` (`λ = ∞`).
fn focal_certs<F: Scalar>(p: &[MPoly<F>; 4], q: &[MPoly<F>; 4], what: &str) -> Vec<Certificate> {
    let [a0, a1, a2] = focal_coefficients(p, q);
    vec![
        zero_cert(&format!("focal sheet 1 is {what}: A₀ ≡ 0 in det(p, q, p_u + λq_u, p_v + λq_v)"), &[a0]),
        zero_cert(&format!("focal sheet 2 is {what}: A₂ ≡ 0"), &[a2]),
        Certificate::decide(
            "the focal polynomial does not vanish identically (the lines are no pencil or bundle): A₁ ≢ 0",
            !a1.is_zero(),
            F::EXACT,
            || "A₁ ≡ 0".into(),
        ),
    ]
}

/// `Σ xᵢ vᵢ` for polynomial weights.
fn combo<F: Scalar>(w: &[MPoly<F>], v: &[[F; 4]]) -> [MPoly<F>; 4] {
    core::array::from_fn(|k| {
        w.iter()
            .zip(v)
            .fold(MPoly::zero(w[0].nvars()), |acc, (x, p)| {
                &acc + &x.scale(&p[k])
            })
    })
}

/// The chord congruence of a twisted cubic (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct CubicChordCongruence<F> {
    a: [[F; 4]; 4],
}

/// Index pairs of the Plücker coordinates `(01, 02, 03, 23, 31, 12)`.
const PAIRS: [(usize, usize); 6] = [(0, 1), (0, 2), (0, 3), (2, 3), (3, 1), (1, 2)];

impl<F: Scalar> CubicChordCongruence<F> {
    /// The cubic `k(t) = a₀ + t a₁ + t² a₂ + t³ a₃` (homogeneous points).
    ///
    /// # Errors
    /// [`OrderOneError::NotATwistedCubic`] if `det(a₀, a₁, a₂, a₃) = 0`.
    pub fn new(a: [[F; 4]; 4]) -> Result<Self, OrderOneError> {
        let det = det4v(&a[0], &a[1], &a[2], &a[3]);
        let s = a.iter().map(|v| scale_of(v)).product::<f64>();
        if is_small(&det, s) {
            return Err(OrderOneError::NotATwistedCubic);
        }
        Ok(CubicChordCongruence { a })
    }

    /// The normal cubic `(1, t, t², t³)`.
    pub fn normal() -> Self {
        CubicChordCongruence {
            a: core::array::from_fn(|i| {
                core::array::from_fn(|k| if i == k { F::one() } else { F::zero() })
            }),
        }
    }

    /// The coefficient points `a₀, …, a₃`.
    pub fn coefficients(&self) -> &[[F; 4]; 4] {
        &self.a
    }

    /// The point `k(t)`.
    pub fn point(&self, t: &F) -> [F; 4] {
        let mut out: [F; 4] = core::array::from_fn(|_| F::zero());
        let mut w = F::one();
        for ak in &self.a {
            for k in 0..4 {
                out[k] = out[k].clone() + w.clone() * ak[k].clone();
            }
            w *= t.clone();
        }
        out
    }

    /// Order and class `(1, 3)` (Gruber §1.1.7; certified by [`Certified::certify`]).
    pub fn order_class(&self) -> (usize, usize) {
        (1, 3)
    }

    /// The chord coordinates of the normal cubic `σ(e)` mapped by the cubic's frame:
    /// `Σ σ_ij(e) aᵢ ∧ aⱼ` (any ring, for polynomial `e`).
    fn chord_from<R: rcagd_algebra::Ring>(&self, e: &[R; 3], lift: impl Fn(&F) -> R) -> [R; 6] {
        let [e0, e1, e2] = e;
        let sigma = [
            e0.clone() * e0.clone(),
            e0.clone() * e1.clone(),
            e1.clone() * e1.clone() - e0.clone() * e2.clone(),
            e2.clone() * e2.clone(),
            -(e1.clone() * e2.clone()),
            e0.clone() * e2.clone(),
        ];
        let basis: Vec<[F; 6]> = PAIRS
            .iter()
            .map(|&(i, j)| wedge(&self.a[i], &self.a[j]))
            .collect();
        core::array::from_fn(|k| {
            sigma
                .iter()
                .zip(&basis)
                .fold(R::zero(), |acc, (s, b)| acc + s.clone() * lift(&b[k]))
        })
    }

    /// The chord with symmetric coordinates `e = (e₀ : e₁ : e₂)` (`(1 : s + t : st)` joins
    /// `k(s)` and `k(t)`; `e₁² = 4e₀e₂` gives the tangents).
    ///
    /// # Errors
    /// [`LineError::ZeroVector`] for `e = 0`.
    pub fn chord(&self, e: &[F; 3]) -> Result<Line<F>, LineError> {
        if e.iter().all(|x| x.is_zero()) {
            return Err(LineError::ZeroVector("chord coordinates e".into()));
        }
        Ok(Line::from_coords_unchecked(
            self.chord_from(e, |x| x.clone()),
        ))
    }

    /// The chord coordinates `e` of the unique chord through `p` (module docs).
    ///
    /// # Errors
    /// [`OrderOneError::SingularPoint`] for a point of the cubic (every chord through it).
    pub fn chord_through(&self, p: &[F; 4]) -> Result<[F; 3], OrderOneError> {
        let m = Matrix::from_fn(4, 4, |r, c| self.a[c][r].clone());
        let sing = || OrderOneError::SingularPoint(format!("{} lies on the cubic", fmt_vec(p)));
        let x = m.solve_unique(p).map_err(|_| sing())?;
        let e = [
            x[0].clone() * x[2].clone() - x[1].clone() * x[1].clone(),
            x[0].clone() * x[3].clone() - x[1].clone() * x[2].clone(),
            x[1].clone() * x[3].clone() - x[2].clone() * x[2].clone(),
        ];
        let s = scale_of(&x).powi(2);
        if e.iter().all(|v| is_small(v, s)) {
            return Err(sing());
        }
        Ok(e)
    }

    /// The chords lying in the plane `u` through three distinct points `k(t₁), k(t₂),
    /// k(t₃)` of the cubic, i.e. the chords `e = (1 : tᵢ + tⱼ : tᵢtⱼ)` of the three pairs
    /// (a generic plane meets the cubic in three points: class 3).
    pub fn chords_in_plane_through(&self, t: &[F; 3]) -> Result<([F; 4], Vec<Line<F>>), LineError> {
        let pts: Vec<[F; 4]> = t.iter().map(|x| self.point(x)).collect();
        let u = plane3(&pts[0], &pts[1], &pts[2]);
        let lines = [(0, 1), (0, 2), (1, 2)]
            .iter()
            .map(|&(i, j)| {
                self.chord(&[
                    F::one(),
                    t[i].clone() + t[j].clone(),
                    t[i].clone() * t[j].clone(),
                ])
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok((u, lines))
    }
}

impl<F: Scalar> Certified for CubicChordCongruence<F> {
    /// Chords on the Klein quadric; the chord `e(s, t)` contains `k(s)` and `k(t)`; the
    /// fibration `p ∈ chord(e(p))` as an identity in `p` (order 1); the focal sheets are the
    /// cubic; the class: the plane section polynomial `⟨u, k(t)⟩` has degree 3 and the three
    /// chords of a plane through `k(0), k(1), k(−1)` lie in it.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        let (s, t) = (MPoly::<F>::var(2, 0), MPoly::<F>::var(2, 1));
        let one = MPoly::constant(2, F::one());
        let e = [one.clone(), &s + &t, &s * &t];
        let h = self.chord_from(&e, |x| MPoly::constant(2, x.clone()));
        out.push(zero_cert(
            "chords on the Klein quadric (Gruber (1.3))",
            &[klein_form(&h)],
        ));
        let pow = |x: &MPoly<F>| -> Vec<MPoly<F>> {
            let mut v = vec![one.clone()];
            for k in 1..4 {
                let n = &v[k - 1] * x;
                v.push(n);
            }
            v
        };
        let ks = combo(&pow(&s), &self.a);
        let kt = combo(&pow(&t), &self.a);
        let m = incidence_matrix(&h);
        for (name, k) in [("k(s)", &ks), ("k(t)", &kt)] {
            let r: Vec<MPoly<F>> = m.iter().map(|row| dot4(row, k)).collect();
            out.push(zero_cert(
                &format!(
                    "the chord e = (1, s + t, st) contains {name}: M(h)·{name} ≡ 0 (Gruber (1.7))"
                ),
                &r,
            ));
        }
        out.extend(focal_certs(&ks, &kt, "the cubic"));
        // fibration in four variables: x = A⁻¹p is linear in p
        let inv = Matrix::from_fn(4, 4, |r, c| self.a[c][r].clone()).inverse();
        match inv {
            Ok(inv) => {
                let p: [MPoly<F>; 4] = core::array::from_fn(|i| MPoly::var(4, i));
                let x: [MPoly<F>; 4] = core::array::from_fn(|r| {
                    (0..4).fold(MPoly::zero(4), |acc, c| {
                        &acc + &p[c].scale(inv.get(r, c).unwrap_or(&F::zero()))
                    })
                });
                let e = [
                    &(&x[0] * &x[2]) - &(&x[1] * &x[1]),
                    &(&x[0] * &x[3]) - &(&x[1] * &x[2]),
                    &(&x[1] * &x[3]) - &(&x[2] * &x[2]),
                ];
                let h = self.chord_from(&e, |c| MPoly::constant(4, c.clone()));
                let m = incidence_matrix(&h);
                let r: Vec<MPoly<F>> = m.iter().map(|row| dot4(row, &p)).collect();
                out.push(zero_cert(
                    "order 1: the chord e(p) = (x₀x₂ − x₁², x₀x₃ − x₁x₂, x₁x₃ − x₂²), x = A⁻¹p, contains p: M(h(e(p)))·p ≡ 0",
                    &r,
                ));
            }
            Err(e) => out.push(Certificate::fails("order 1", e.to_string(), F::EXACT)),
        }
        // class 3
        let deg3 = !self.a[3].iter().all(|x| x.is_zero());
        out.push(Certificate::decide(
            "class 3: a generic plane section ⟨u, k(t)⟩ has degree 3 (a₃ ≠ 0)",
            deg3,
            F::EXACT,
            || "a₃ = 0".into(),
        ));
        let ts = [F::zero(), F::one(), -F::one()];
        match self.chords_in_plane_through(&ts) {
            Ok((u, lines)) => {
                let ok = lines.iter().all(|l| l.lies_in_plane(&u));
                out.push(Certificate::decide(
                    "class 3: the three chords of the points k(0), k(1), k(−1) lie in their plane",
                    ok,
                    F::EXACT,
                    || "a chord leaves the plane".into(),
                ));
            }
            Err(e) => out.push(Certificate::fails("class 3", e.to_string(), F::EXACT)),
        }
        out
    }
}

/// A (1, n)-congruence: the lines meeting a line `g` and a rational curve `k` of order `n`
/// with `n − 1` points on `g` (module docs, Gruber §1.1.8).
#[derive(Debug, Clone, PartialEq)]
pub struct OneNCongruence<F> {
    g: [[F; 4]; 2],
    k: [Poly<F>; 4],
    n: usize,
    common: Poly<F>,
}

fn to_q<F: Scalar>(p: &Poly<F>) -> Poly<Rational> {
    p.map(|c| c.to_rational().unwrap_or_else(|| Rational::from(0)))
}

impl<F: Scalar> OneNCongruence<F> {
    /// The congruence of the line `g = g₀ ∨ g₁` and the curve `k(t)` (homogeneous polynomial
    /// points).
    ///
    /// # Errors
    /// [`LineError::CoincidentPoints`] for `g₀ ∧ g₁ = 0`, [`OrderOneError::CurveInPlane`],
    /// [`OrderOneError::NotOrderOne`] unless `k` meets `g` in exactly `n − 1` points (the
    /// common factor of `⟨ε, k(t)⟩` over the planes `ε ⊃ g` is computed exactly).
    pub fn new(g0: [F; 4], g1: [F; 4], k: [Poly<F>; 4]) -> Result<Self, OrderOneError> {
        let line = Line::from_points(&g0, &g1)?;
        let n = k.iter().filter_map(|p| p.degree()).max().unwrap_or(0);
        let (e1, e2) = line.planes();
        let sect = |e: &[F; 4]| -> Poly<F> {
            (0..4).fold(Poly::zero(), |acc, j| &acc + &k[j].scale(&e[j]))
        };
        let (f1, f2) = (sect(&e1), sect(&e2));
        if n == 0 {
            return Err(OrderOneError::CurveInPlane);
        }
        // exact gcd over Q (f64 inputs are exact binary rationals)
        let (q1, q2) = (to_q(&f1), to_q(&f2));
        // dependent sections: some plane through g contains the whole curve
        let cross = &q1.scale(&q2.leading()) - &q2.scale(&q1.leading());
        if q1.is_zero() || q2.is_zero() || cross.is_zero() {
            return Err(OrderOneError::CurveInPlane);
        }
        let gq = q1.gcd(&q2);
        let meets = gq.degree().unwrap_or(0);
        // the residual factor must be linear for every plane through g
        let lin = |f: &Poly<Rational>| f.is_zero() || f.degree().unwrap_or(0) <= meets + 1;
        if meets + 1 != n || !lin(&q1) || !lin(&q2) {
            return Err(OrderOneError::NotOrderOne {
                order: n,
                meets,
                needed: n.saturating_sub(1),
            });
        }
        let common = gq.map(F::from_rational);
        Ok(OneNCongruence {
            g: [g0, g1],
            k,
            n,
            common,
        })
    }

    /// Order and class `(1, n)` (certified by [`Certified::certify`]).
    pub fn order_class(&self) -> (usize, usize) {
        (1, self.n)
    }

    /// The polynomial whose roots are the parameters of the `n − 1` points of `k` on `g`.
    pub fn common_points(&self) -> &Poly<F> {
        &self.common
    }

    /// The congruence lines `k(t) ∧ (g₀ + λg₁)` as polynomials in `(t, λ)`.
    pub fn line_polynomials(&self) -> [MPoly<F>; 6] {
        let (p, q) = self.generating_points();
        wedge(&p, &q)
    }

    fn generating_points(&self) -> ([MPoly<F>; 4], [MPoly<F>; 4]) {
        let p: [MPoly<F>; 4] = core::array::from_fn(|j| MPoly::from_poly(&self.k[j], 2, 0));
        let l = MPoly::var(2, 1);
        let q: [MPoly<F>; 4] = core::array::from_fn(|j| {
            &MPoly::constant(2, self.g[0][j].clone()) + &l.scale(&self.g[1][j])
        });
        (p, q)
    }

    /// The residual point `Q(P)` (homogeneous in the plane coefficients): the plane
    /// `ε = [g₀, g₁, P]` gives `⟨ε, k(t)⟩ = G(t)·(r₀ + r₁t)`, `Q = k(−r₀ : r₁)` (works for
    /// polynomial `P` too). Returns the remainder of the division as well (must vanish).
    fn residual<R>(&self, p: &[R; 4], lift: impl Fn(&F) -> R) -> ([R; 4], Vec<R>)
    where
        R: rcagd_algebra::Ring,
    {
        let g0: [R; 4] = core::array::from_fn(|k| lift(&self.g[0][k]));
        let g1: [R; 4] = core::array::from_fn(|k| lift(&self.g[1][k]));
        let e = plane3(&g0, &g1, p);
        // f(t) = Σ_m f_m t^m with f_m = ⟨e, coefficient m of k⟩
        let mut f: Vec<R> = (0..=self.n)
            .map(|m| dot4(&e, &core::array::from_fn(|j| lift(&self.k[j].coeff(m)))))
            .collect();
        // exact division by the monic-scaled G (field coefficients)
        let gd = self.common.degree().unwrap_or(0);
        let glead = self.common.leading();
        let ginv = lift(&(F::one() / glead));
        let mut quot: Vec<R> = vec![R::zero(); self.n + 1 - gd];
        for m in (gd..=self.n).rev() {
            let c = f[m].clone() * ginv.clone();
            for i in 0..=gd {
                f[m - gd + i] = f[m - gd + i].clone() - c.clone() * lift(&self.common.coeff(i));
            }
            quot[m - gd] = c;
        }
        let rem: Vec<R> = f.into_iter().take(gd).collect();
        let r0 = quot.first().cloned().unwrap_or_else(R::zero);
        let r1 = quot.get(1).cloned().unwrap_or_else(R::zero);
        // Q = Σ_m k_m (−r₀)^m r₁^{n−m}
        let mut q: [R; 4] = core::array::from_fn(|_| R::zero());
        for m in 0..=self.n {
            let mut w = R::one();
            for _ in 0..m {
                w *= -r0.clone();
            }
            for _ in m..self.n {
                w *= r1.clone();
            }
            for (qj, kj) in q.iter_mut().zip(&self.k) {
                *qj = qj.clone() + w.clone() * lift(&kj.coeff(m));
            }
        }
        (q, rem)
    }

    /// The unique congruence line through `p` (the fibration).
    ///
    /// # Errors
    /// [`OrderOneError::SingularPoint`] for points of `g` or `k`.
    pub fn line_through(&self, p: &[F; 4]) -> Result<Line<F>, OrderOneError> {
        let (q, _) = self.residual(p, |x| x.clone());
        Line::from_points(p, &q).map_err(|_| {
            OrderOneError::SingularPoint(format!("{} lies on a focal curve", fmt_vec(p)))
        })
    }
}

impl<F: Scalar> Certified for OneNCongruence<F> {
    /// Lines on the Klein quadric; the plane through `g` and `P` meets `k` in the `n − 1`
    /// fixed points plus `Q(P)` (the division remainder vanishes identically in `P`); the
    /// fibration line `P ∨ Q(P)` meets `g` (identity in `P`: order 1); the focal sheets are
    /// `k` and `g`; class `n`: the plane section `⟨u, k(t)⟩` of a generic plane has degree `n`.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        let h = self.line_polynomials();
        out.push(zero_cert(
            "congruence lines on the Klein quadric (Gruber (1.3))",
            &[klein_form(&h)],
        ));
        let gl: [MPoly<F>; 6] = wedge(&self.g[0], &self.g[1]).map(|c| MPoly::constant(2, c));
        out.push(zero_cert(
            "every congruence line k(t) ∧ g(λ) meets g: Ω(g, l) ≡ 0 (Gruber (1.10))",
            &[reciprocal_product(&gl, &h)],
        ));
        let p: [MPoly<F>; 4] = core::array::from_fn(|i| MPoly::var(4, i));
        let (q, rem) = self.residual(&p, |c| MPoly::constant(4, c.clone()));
        out.push(zero_cert(
            "every plane [g, P] meets k in the n − 1 points on g: G(t) divides ⟨[g₀, g₁, P], k(t)⟩ identically in P",
            &rem,
        ));
        let g4: [MPoly<F>; 6] = wedge(&self.g[0], &self.g[1]).map(|c| MPoly::constant(4, c));
        out.push(zero_cert(
            "order 1: the line P ∨ Q(P) through the residual point meets g, Ω(g, P ∧ Q(P)) ≡ 0",
            &[reciprocal_product(&g4, &wedge(&p, &q))],
        ));
        let (pp, qq) = self.generating_points();
        out.extend(focal_certs(&pp, &qq, "the curve k resp. the line g"));
        let lead: [F; 4] = core::array::from_fn(|j| self.k[j].coeff(self.n));
        out.push(Certificate::decide(
            format!(
                "class {}: a generic plane meets k in n = {} points (leading coefficient ≠ 0)",
                self.n, self.n
            ),
            !lead.iter().all(|x| x.is_zero()),
            F::EXACT,
            || "the leading coefficient vanishes".into(),
        ));
        out
    }
}

/// The six Plücker polynomials with their common factor (a curve of parameters where
/// `p ∧ q = 0`) divided out.
pub(super) fn without_common_factor(l: [MPoly<Rational>; 6]) -> [MPoly<Rational>; 6] {
    let common = l.iter().fold(MPoly::zero(2), |acc: MPoly<Rational>, x| {
        if acc.is_zero() {
            x.clone()
        } else if x.is_zero() {
            acc
        } else {
            crate::pn::poly::gcd2(&acc, x)
        }
    });
    if common.total_degree().unwrap_or(0) > 0 {
        l.map(|x| crate::pn::poly::div_exact(&x, &common).unwrap_or(x))
    } else {
        l
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn focal_points_of_a_quadratic_congruence() {
        use rcagd_algebra::QuadExt;
        // p = (1, u, v, uv), q = (0, 1, u + v, u²): a congruence with irrational focal points
        let (u, v) = (MPoly::<Rational>::var(2, 0), MPoly::var(2, 1));
        let one = MPoly::constant(2, q(1));
        let p = [one.clone(), u.clone(), v.clone(), &u * &v];
        let qq = [MPoly::zero(2), one, &u + &v, &u * &u];
        let pts = focal_points(&p, &qq, &q(3), &q(-1)).expect("focal");
        // −2uλ² + (u² − u − v)λ − (u + 1)v: discriminant 145 at (3, −1), two points in Q(√145)
        assert_eq!(pts.len(), 2);
        // conjugate complex focal points at (1, 2) (discriminant −28)
        assert!(focal_points(&p, &qq, &q(1), &q(2))
            .expect("complex")
            .is_empty());
        // each focal point x = p + λq: det(p, q, x_u, x_v) = 0 exactly over the extension,
        // i.e. the neighbouring lines meet the line there
        let e =
            |m: &MPoly<Rational>, x: &[Rational; 2]| QuadExt::rational(m.eval(x).expect("eval"));
        let xy = [q(3), q(-1)];
        let pv: [QuadExt; 4] = core::array::from_fn(|k| e(&p[k], &xy));
        let qv: [QuadExt; 4] = core::array::from_fn(|k| e(&qq[k], &xy));
        let d = |m: &[MPoly<Rational>; 4], i: usize| -> [QuadExt; 4] {
            core::array::from_fn(|k| e(&m[k].partial(i), &xy))
        };
        let (pu, pvv, qu, qvv) = (d(&p, 0), d(&p, 1), d(&qq, 0), d(&qq, 1));
        for x in &pts {
            // λ from x = p + λq (q₀ = 0, p₀ = 1 ⇒ x₀ = 1; λ = x₁ − p₁)
            let l = x[1].clone() - pv[1].clone();
            let xu: [QuadExt; 4] =
                core::array::from_fn(|k| pu[k].clone() + l.clone() * qu[k].clone());
            let xv: [QuadExt; 4] =
                core::array::from_fn(|k| pvv[k].clone() + l.clone() * qvv[k].clone());
            assert_eq!(det4v(&pv, &qv, &xu, &xv), QuadExt::rational(q(0)));
        }
        // a hyperbolic net c(u) ∨ d(v): the focal points are the points on the axes
        let c = [
            MPoly::constant(2, q(1)),
            u.clone(),
            MPoly::zero(2),
            MPoly::zero(2),
        ];
        let dd = [
            MPoly::zero(2),
            MPoly::constant(2, q(2)),
            v.clone(),
            MPoly::constant(2, q(1)),
        ];
        let pts = focal_points(&c, &dd, &q(3), &q(5)).expect("net");
        assert_eq!(pts.len(), 2);
        assert_eq!(pts[0], [1, 3, 0, 0].map(|k| QuadExt::rational(q(k))));
        assert_eq!(pts[1], [0, 2, 5, 1].map(|k| QuadExt::rational(q(k))));
    }

    #[test]
    fn order_and_class_by_elimination() {
        let (u, v) = (MPoly::<Rational>::var(2, 0), MPoly::var(2, 1));
        let one = MPoly::constant(2, q(1));
        let zero = MPoly::zero(2);
        let pw = |x: &MPoly<Rational>, k: u32| x.pow(k);
        // a hyperbolic net c(u) ∨ d(v): (1, 1), μ = 1
        let c = [one.clone(), u.clone(), zero.clone(), zero.clone()];
        let d = [
            zero.clone(),
            MPoly::constant(2, q(2)),
            v.clone(),
            one.clone(),
        ];
        assert_eq!(order_and_class(&c, &d).expect("net"), (1, 1, 1));
        // chords k(u) ∨ k(v) of the normal cubic: (1, 3), covered twice (u ↔ v)
        let ku = [one.clone(), u.clone(), pw(&u, 2), pw(&u, 3)];
        let kv = [one.clone(), v.clone(), pw(&v, 2), pw(&v, 3)];
        assert_eq!(order_and_class(&ku, &kv).expect("chords"), (1, 3, 2));
        // the (1, 4)-congruence of Gruber §1.1.8: β(u) ∨ (v, 0, 0)
        let b = [
            one.clone(),
            &u.scale(&q(3)) + &pw(&u, 4),
            &pw(&u, 2).scale(&q(4)) - &pw(&u, 4),
            &u.scale(&q(4)) - &pw(&u, 3),
        ];
        let g = [one.clone(), v.clone(), zero.clone(), zero];
        assert_eq!(order_and_class(&b, &g).expect("(1,4)"), (1, 4, 1));
        // a conic meeting the x-axis once: (1, 2)
        let k2 = [
            &one + &pw(&u, 2).scale(&q(2)),
            u.clone(),
            pw(&u, 2).scale(&q(-2)),
            u.scale(&q(5)),
        ];
        assert_eq!(order_and_class(&k2, &g).expect("(1,2)"), (1, 2, 1));
    }

    #[test]
    fn normal_cubic_chords() {
        let c = CubicChordCongruence::<Rational>::normal();
        assert!(c.all_hold(), "{:?}", c.certify());
        // the chord of k(1), k(2): e = (1, 3, 2); through the midpoint-like point k(1) + k(2)
        let p: [Rational; 4] =
            core::array::from_fn(|k| c.point(&q(1))[k].clone() + c.point(&q(2))[k].clone());
        let e = c.chord_through(&p).expect("chord");
        let l = c.chord(&e).expect("line");
        assert!(l.contains_point(&c.point(&q(1))) && l.contains_point(&c.point(&q(2))));
        assert!(matches!(
            c.chord_through(&c.point(&q(3))),
            Err(OrderOneError::SingularPoint(_))
        ));
    }

    #[test]
    fn gruber_one_four_congruence() {
        // Gruber §1.1.8: β(t) = (3t + t⁴, t²(4 − t²), t(4 − t²)) and the x-axis
        let k = [
            Poly::from_ints(&[1]),
            Poly::from_ints(&[0, 3, 0, 0, 1]),
            Poly::from_ints(&[0, 0, 4, 0, -1]),
            Poly::from_ints(&[0, 4, 0, -1]),
        ];
        let g0 = [1, 0, 0, 0].map(q);
        let g1 = [0, 1, 0, 0].map(q);
        let c = OneNCongruence::new(g0, g1, k).expect("(1,4)");
        assert_eq!(c.order_class(), (1, 4));
        assert_eq!(c.common_points().degree(), Some(3));
        assert!(c.all_hold(), "{:?}", c.certify());
        let p = [1, 2, 3, 5].map(q);
        let l = c.line_through(&p).expect("fibre");
        assert!(l.contains_point(&p));
    }
}
