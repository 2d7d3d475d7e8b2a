//! Guaranteed-accuracy Hermite interpolants: the control points and the bending energy of
//! a helical PH quintic interpolant (see [`super::hermite`]) enclosed in intervals computed
//! from the *exact* isolating interval of its root.
//!
//! The `f64` interpolants of [`super::hermite`] are computed from a root polished in
//! floating point. When `σ = |r'|` nearly vanishes somewhere on `[0, 1]` the bending energy
//! `E = ∫₀¹ |r'×r''|²/σ⁵ dt` is ill-conditioned: a relative change of the control points of
//! `10⁻⁷` can change `E` by several per cent. Here instead:
//!
//! 1. the root `s* = r_1` of the elimination quartic is refined by exact bisection (signs of
//!    the square-free quartic over `Q(√m²)`) to an interval `S` of width `2^−b`;
//! 2. `r_2 = e_0 + e_1 S`, `r_3 = L(S)`, `k_0 = ε√r_1/4`, `k_2 = ε·sgn(r_3 + 5)√r_2/4`,
//!    `X = (Y_0 + Y_1 S)/r_3` and the control points (Besednjak (9.4)) are evaluated in
//!    interval arithmetic ([`rcagd_algebra::interval`]; Moore 1966), so each box contains
//!    the exact control point; `b` is doubled until every box is narrower than the
//!    requested tolerance;
//! 3. the energy is enclosed by a validated quadrature: on a sub-interval `[a, b]` a
//!    polynomial `p` (Chebyshev interpolant of the integrand, computed in `f64` and then
//!    taken as exact) has the remainder `f − p = (N − pσ⁵)/σ⁵`, bounded by the Bernstein
//!    coefficients of `N − pσ⁵` and of `σ` on `[a, b]` (range enclosure property of the
//!    Bernstein form; Farin, *Curves and Surfaces for CAGD*, §5.3), so
//!    `∫_a^b f ∈ ∫_a^b p ± (b − a)·max|N − pσ⁵|/min σ⁵`; the sub-interval with the widest
//!    enclosure is bisected until the total width is below the relative tolerance.
//!    `σ` itself is the polynomial square root of `|r'|²` (`σ(0) = |d_s| > 0`), evaluated
//!    from the low coefficients by the same interval arithmetic. Each piece is enclosed
//!    first in `f64` interval arithmetic with outward rounding
//!    ([`rcagd_algebra::interval::F64Interval`]: every end point moved one `f64` outward
//!    after each correctly rounded operation), from `f64` enclosures of the 256-bit
//!    coefficients of `N` and `σ`; in 256-bit fixed point only where that pass cannot
//!    prove `σ > 0`, and the whole quadrature again in 256-bit fixed point if the `f64`
//!    roundings keep the total wider than the tolerance when the piece budget is spent.
//!    Both are enclosures of the exact energy; the `f64` pass's end points are wider by
//!    its roundings (≈ 10⁻¹⁶ relative per operation, far below the tolerance).
//!
//! Derivation and the error model: docs/math/ph-curves.md, "Guaranteed-accuracy Hermite
//! interpolants".

use super::hermite::{
    control_points_from, refine_once, square_free, HermiteInterpolant, HermiteSolution,
};
use super::util::{add3, scale3};
use super::PhError;
use rcagd_algebra::bernstein::from_bernstein;
use rcagd_algebra::interval::{pow2, F64Interval, Interval};
use rcagd_algebra::{Certificate, Poly, QuadExt, Rational, Scalar};
use std::cmp::Ordering;

/// One interpolant with every control point and its bending energy enclosed.
#[derive(Debug, Clone, PartialEq)]
pub struct EnclosedInterpolant {
    /// Index in [`HermiteSolution::interpolants`].
    pub index: usize,
    /// The isolating interval of the root `s = 16k_0²` used.
    pub root: Interval,
    /// A box containing each exact control point `p_0 … p_5`.
    pub control_points: Vec<[Interval; 3]>,
    /// The largest box width: every exact coordinate is within this of the box midpoint.
    pub control_point_width: Rational,
    /// An interval containing the exact bending energy `∫₀¹ κ²σ dt`.
    pub bending_energy: Interval,
    /// Sub-intervals of `[0, 1]` used by the validated quadrature.
    pub quadrature_pieces: usize,
    /// The exact end data, to certify the boxes against.
    p_s: [Rational; 3],
    p_f: [Rational; 3],
    d_s: [Rational; 3],
    d_f: [Rational; 3],
}

/// Rational version of a `QuadExt` that the data consist of.
fn rat3(v: &[QuadExt; 3]) -> Result<[Rational; 3], PhError> {
    let f = |x: &QuadExt| {
        x.to_rational().ok_or_else(|| {
            PhError::Irrational("the Hermite data must be rational for the enclosure".into())
        })
    };
    Ok([f(&v[0])?, f(&v[1])?, f(&v[2])?])
}

fn iv(q: &Rational) -> Interval {
    Interval::point(q)
}

fn iv3(v: &[Rational; 3]) -> [Interval; 3] {
    [iv(&v[0]), iv(&v[1]), iv(&v[2])]
}

fn frac(p: i64, q: i64) -> Interval {
    iv(&(Rational::from(p) / Rational::from(q)))
}

use rcagd_algebra::Ring;

fn poly_iv(p: &Poly<QuadExt>) -> Poly<Interval> {
    p.map(Interval::from_quad)
}

fn max_width(pts: &[[Interval; 3]]) -> Rational {
    let mut w = Rational::ZERO;
    for p in pts {
        for c in p {
            let cw = c.width();
            if cw > w {
                w = cw;
            }
        }
    }
    w
}

impl HermiteSolution<QuadExt> {
    /// Encloses interpolant `index`: control-point boxes narrower than `tolerance` and the
    /// bending energy to the relative width `energy_tolerance` (module docs).
    ///
    /// # Errors
    /// [`PhError::OutOfRange`] for an unknown index or non-positive tolerances;
    /// [`PhError::Irrational`] for non-rational data; [`PhError::Degenerate`] if `σ`
    /// cannot be proven positive on `[0, 1]` (the energy diverges or is too close to
    /// diverging for the quadrature budget).
    pub fn enclose(
        &self,
        index: usize,
        tolerance: &Rational,
        energy_tolerance: &Rational,
    ) -> Result<EnclosedInterpolant, PhError> {
        let interp: &HermiteInterpolant = self.interpolants.get(index).ok_or_else(|| {
            PhError::OutOfRange(format!(
                "interpolant {index} does not exist ({} interpolants)",
                self.interpolants.len()
            ))
        })?;
        if *tolerance <= Rational::ZERO || *energy_tolerance <= Rational::ZERO {
            return Err(PhError::OutOfRange(
                "the enclosure tolerances must be positive".into(),
            ));
        }
        let root = &self.roots[interp.root_index];
        let d = &self.data;
        let (p_s, d_s, p_f, d_f) = (rat3(&d.p_s)?, rat3(&d.d_s)?, rat3(&d.p_f)?, rat3(&d.d_f)?);
        let h = rat3(&d.h())?;
        let e0 = Interval::from_quad(&self.e[0]);
        let e1 = Interval::from_quad(&self.e[1]);
        let l = poly_iv(&self.r3_poly);
        // Y(s) = h − s d_s − (e0 + e1 s) d_f = Y0 + s Y1 (as in the solver)
        let dsi = iv3(&d_s);
        let dfi = iv3(&d_f);
        let y0 = add3(&iv3(&h), &scale3(&dfi, &-e0.clone()));
        let y1 = scale3(&add3(&dsi, &scale3(&dfi, &e1)), &-Interval::one());
        let sf = square_free(&self.quartic);
        let (mut lo, mut hi) = match &root.exact {
            Some(x) => (x.clone(), x.clone()),
            None => (root.lo.clone(), root.hi.clone()),
        };
        let mut bits = 64usize;
        loop {
            let target = pow2(-(bits as isize));
            let width = |a: &QuadExt, b: &QuadExt| (b.clone() - a.clone()).abs();
            let mut guard = 0;
            while root.exact.is_none() && width(&lo, &hi) > QuadExt::from(target.clone()) {
                let (a, b) = refine_once(&sf, lo, hi);
                lo = a;
                hi = b;
                guard += 1;
                if guard > 4 * bits + 200 {
                    break;
                }
            }
            let s = Interval::from_quad(&lo).hull(&Interval::from_quad(&hi));
            if let Some(pts) = self.boxes(interp, &s, &e0, &e1, &l, &y0, &y1, &p_s, &dsi, &dfi)? {
                let w = max_width(&pts);
                if w <= *tolerance || bits >= 1024 {
                    let (energy, pieces) = enclose_energy(&pts, energy_tolerance)?;
                    return Ok(EnclosedInterpolant {
                        index,
                        root: s,
                        control_point_width: w,
                        control_points: pts,
                        bending_energy: energy,
                        quadrature_pieces: pieces,
                        p_s,
                        p_f,
                        d_s,
                        d_f,
                    });
                }
            } else if bits >= 1024 {
                return Err(PhError::Degenerate(
                    "the sign of 16k_0k_2 − 5 at the root could not be decided".into(),
                ));
            }
            bits *= 2;
        }
    }

    /// The control-point boxes for the root enclosure `s`; `None` while `r_3` is not yet
    /// bounded away from 0.
    #[allow(clippy::too_many_arguments)]
    fn boxes(
        &self,
        interp: &HermiteInterpolant,
        s: &Interval,
        e0: &Interval,
        e1: &Interval,
        l: &Poly<Interval>,
        y0: &[Interval; 3],
        y1: &[Interval; 3],
        p_s: &[Rational; 3],
        d_s: &[Interval; 3],
        d_f: &[Interval; 3],
    ) -> Result<Option<Vec<[Interval; 3]>>, PhError> {
        let r2 = e0.clone() + e1.clone() * s.clone();
        let r3 = l.eval(s);
        let Some(inv_r3) = r3.recip() else {
            return Ok(None);
        };
        let sg = match (r3.clone() + Interval::from_i64(5)).sign() {
            Some(Ordering::Less) => -1,
            Some(_) => 1,
            // undecided only when r_1·r_2 = (r_3 + 5)² ≈ 0: follow the f64 branch
            None => {
                if interp.k2 * f64::from(interp.eps) >= 0.0 {
                    1
                } else {
                    -1
                }
            }
        };
        let sq1 = s
            .sqrt()
            .ok_or_else(|| PhError::Degenerate("16k_0² < 0 at the root".into()))?;
        let sq2 = r2
            .sqrt()
            .ok_or_else(|| PhError::Degenerate("16k_2² < 0 at the root".into()))?;
        let eps = Interval::from_i64(i64::from(interp.eps));
        let quarter = frac(1, 4);
        let three_q = frac(3, 4);
        let k0 = eps.clone() * sq1 * quarter.clone();
        let k2 = eps * Interval::from_i64(sg.into()) * sq2 * quarter;
        let c0 = k0 - three_q.clone();
        let c2 = k2 - three_q;
        let x = scale3(&add3(y0, &scale3(y1, s)), &inv_r3);
        Ok(Some(control_points_from(
            &iv3(p_s),
            d_s,
            d_f,
            &x,
            &c0,
            &c2,
            &frac,
        )))
    }
}

/// Power → Bernstein coefficients of degree `n = deg p` in interval arithmetic:
/// `c_j = a_j/C(n, j)`, then `b_k = Σ_{j ≤ k} C(k, j) c_j` by `n` passes of prefix sums
/// (only additions after the `n + 1` scalings).
fn to_bernstein_iv(p: &Poly<Interval>) -> Vec<Interval> {
    let a = p.coeffs();
    let n = a.len().saturating_sub(1);
    let mut binom = Rational::ONE; // C(n, j)
    let mut c: Vec<Interval> = Vec::with_capacity(n + 1);
    for (j, aj) in a.iter().enumerate() {
        c.push(aj.clone() * iv(&(Rational::ONE / &binom)));
        binom = binom * Rational::from(n - j) / Rational::from(j + 1);
    }
    for r in 1..=n {
        for k in (r..=n).rev() {
            let prev = c[k - 1].clone();
            c[k] += prev;
        }
    }
    c
}

/// The range enclosure of `p` on `[0, 1]` from its Bernstein coefficients.
fn range(p: &Poly<Interval>) -> Interval {
    let b = to_bernstein_iv(p);
    let mut r = b.first().cloned().unwrap_or_else(Interval::zero);
    for c in b.iter().skip(1) {
        r = r.hull(c);
    }
    r
}

use num_traits::{One, Zero};

/// `σ` from `σ² = |r'|²` by the power-series square root from the constant term
/// (`σ(0) > 0`), degree `deg σ² / 2`.
fn sigma_from_square(sq: &Poly<Interval>) -> Result<Poly<Interval>, PhError> {
    let c = sq.coeffs();
    let n = (c.len().saturating_sub(1)) / 2;
    let s0 = c
        .first()
        .and_then(|c0| c0.sqrt())
        .ok_or_else(|| PhError::Degenerate("σ(0) = 0".into()))?;
    let inv = (Interval::from_i64(2) * s0.clone())
        .recip()
        .ok_or_else(|| PhError::Degenerate("σ(0) = 0".into()))?;
    let mut s = vec![s0];
    for k in 1..=n {
        let mut acc = c.get(k).cloned().unwrap_or_else(Interval::zero);
        for j in 1..k {
            acc -= s[j].clone() * s[k - j].clone();
        }
        s.push(acc * inv.clone());
    }
    Ok(Poly::new(s))
}

fn poly_mid_f64(p: &Poly<Interval>) -> Vec<f64> {
    p.coeffs().iter().map(|c| c.to_f64()).collect()
}

fn eval_f64(c: &[f64], t: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, x| acc * t + x)
}

/// Chebyshev interpolant of degree `k` of `f` on `u ∈ [0, 1]`, power coefficients in `u`.
fn chebyshev_fit(f: &dyn Fn(f64) -> f64, k: usize) -> Vec<f64> {
    let nodes: Vec<f64> = (0..=k)
        .map(|j| {
            let th = (2 * j + 1) as f64 * std::f64::consts::PI / (2 * (k + 1)) as f64;
            0.5 * (1.0 - th.cos())
        })
        .collect();
    let mut dd: Vec<f64> = nodes.iter().map(|&u| f(u)).collect();
    for lvl in 1..=k {
        for i in (lvl..=k).rev() {
            dd[i] = (dd[i] - dd[i - 1]) / (nodes[i] - nodes[i - lvl]);
        }
    }
    // Newton form → power form
    let mut coef = vec![0.0; k + 1];
    coef[0] = dd[k];
    for (deg, i) in (0..k).rev().enumerate() {
        // coef = coef·(u − nodes[i]) + dd[i]
        let mut next = vec![0.0; k + 1];
        for j in 0..=deg {
            next[j + 1] += coef[j];
            next[j] -= coef[j] * nodes[i];
        }
        next[0] += dd[i];
        coef = next;
    }
    coef
}

/// The degree-10 Chebyshev interpolant (power form in `u`) of the integrand `N/σ⁵` with
/// the `f64` coefficients `nf`, `sf` (midpoints of the enclosures), or `None` if it is not
/// finite. Any polynomial serves (it only sets the enclosure's width, never its validity).
fn integrand_fit(nf: &[f64], sf: &[f64]) -> Option<Vec<f64>> {
    let f = |u: f64| {
        let s = eval_f64(sf, u);
        eval_f64(nf, u) / (s * s * s * s * s)
    };
    let pc = chebyshev_fit(&f, 10);
    pc.iter().all(|c| c.is_finite()).then_some(pc)
}

/// The integrand data on `[a, b]` (in `u ∈ [0, 1]`, `t = a + (b − a)u`).
struct Piece {
    a: Rational,
    b: Rational,
    enclosure: Option<Interval>,
}

fn enclose_piece(
    n: &Poly<Interval>,
    sigma: &Poly<Interval>,
    a: &Rational,
    b: &Rational,
) -> Option<Interval> {
    let lin = Poly::new(vec![iv(a), iv(&(b - a))]);
    let nu = n.compose(&lin);
    let su = sigma.compose(&lin);
    let smin = range(&su);
    if smin.sign() != Some(Ordering::Greater) {
        return None;
    }
    let s5 = {
        let s2 = &su * &su;
        &(&s2 * &s2) * &su
    };
    let pc = integrand_fit(&poly_mid_f64(&nu), &poly_mid_f64(&su))?;
    let p = Poly::new(
        pc.iter()
            .map(|c| Rational::try_from(*c).map(|q| iv(&q)))
            .collect::<Result<Vec<_>, _>>()
            .ok()?,
    );
    let rem = &nu - &(&p * &s5);
    let r = range(&rem).mag();
    let smin5 = {
        let lo = smin.lo();
        let l2 = &lo * &lo;
        &l2 * &l2 * lo
    };
    let bound = r / smin5;
    let integral = p
        .coeffs()
        .iter()
        .enumerate()
        .fold(Interval::zero(), |acc, (j, c)| {
            acc + c.clone() * frac(1, j as i64 + 1)
        });
    let e = integral + Interval::new(&-bound.clone(), &bound)?;
    Some(e * iv(&(b - a)))
}

/// `p(a + h u)` by Horner's rule in the linear substitute (two interval products per
/// coefficient and step).
fn compose_linear(p: &[Interval], a: &Interval, h: &Interval) -> Vec<Interval> {
    let mut r: Vec<Interval> = Vec::with_capacity(p.len());
    for c in p.iter().rev() {
        // r ← r·(a + h u) + c
        r.push(Interval::zero());
        for j in (0..r.len()).rev() {
            let mut x = &r[j] * a;
            if j > 0 {
                x += &r[j - 1] * h;
            }
            r[j] = x;
        }
        r[0] += c.clone();
    }
    r
}

fn mul_f64(a: &[F64Interval], b: &[F64Interval]) -> Vec<F64Interval> {
    let mut out = vec![F64Interval::zero(); (a.len() + b.len()).saturating_sub(1)];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += *x * *y;
        }
    }
    out
}

/// [`range`] in `f64` interval arithmetic: Bernstein coefficients `c_j = a_j/C(n, j)`
/// (binomials exact in `f64` for `n ≤ 56`), then prefix sums.
fn range_f64(a: &[F64Interval]) -> F64Interval {
    let n = a.len().saturating_sub(1);
    if n > 56 {
        return F64Interval::ENTIRE;
    }
    let mut binom = 1.0f64; // C(n, j), exact
    let mut c: Vec<F64Interval> = Vec::with_capacity(n + 1);
    for (j, aj) in a.iter().enumerate() {
        c.push(aj.div_positive(binom));
        binom = binom * (n - j) as f64 / (j + 1) as f64;
    }
    for r in 1..=n {
        for k in (r..=n).rev() {
            let prev = c[k - 1];
            c[k] += prev;
        }
    }
    c.iter().skip(1).fold(
        c.first().copied().unwrap_or_else(F64Interval::zero),
        |r, x| r.hull(x),
    )
}

/// The first pass of [`enclose_piece`] in `f64` interval arithmetic with outward rounding
/// ([`F64Interval`]): the same validated bound, the same Chebyshev interpolant, every
/// operation of the remainder bound and the integral rounded outward, so the result is an
/// enclosure of `∫_a^b N/σ⁵` as rigorous as the 256-bit one, only wider by the `f64`
/// roundings (≈ 10⁻¹⁶ relative per operation). `None` where `σ` is not proven positive
/// or a value is not finite (the caller then takes the 256-bit pass).
fn enclose_piece_f64(
    n: &Poly<Interval>,
    sigma: &Poly<Interval>,
    a: &Rational,
    b: &Rational,
) -> Option<Interval> {
    // the piece ends are dyadic (bisections of [0, 1]): exact in f64 down to 2^−1074
    let (af, bf) = (a.to_f64().value(), b.to_f64().value());
    let hf = bf - af;
    if Rational::try_from(af).ok()? != *a || Rational::try_from(hf).ok()? != b - a {
        return None;
    }
    // The substitution t = a + h u in 256-bit fixed point (the power coefficients in t
    // cancel on a short piece: in f64 their roundings would dominate the enclosure),
    // then everything else in f64.
    let (ai, hi) = (iv(a), iv(&(b - a)));
    let to_f64 = |p: &Poly<Interval>| -> Vec<F64Interval> {
        compose_linear(p.coeffs(), &ai, &hi)
            .iter()
            .map(F64Interval::from_interval)
            .collect()
    };
    let nu = to_f64(n);
    let su = to_f64(sigma);
    let smin = range_f64(&su);
    if smin.sign() != Some(Ordering::Greater) || !smin.is_finite() {
        return None;
    }
    let s5 = {
        let s2 = mul_f64(&su, &su);
        mul_f64(&mul_f64(&s2, &s2), &su)
    };
    let mids = |p: &[F64Interval]| p.iter().map(F64Interval::mid).collect::<Vec<f64>>();
    let pc = integrand_fit(&mids(&nu), &mids(&su))?;
    let p: Vec<F64Interval> = pc.iter().map(|c| F64Interval::point(*c)).collect();
    let ps5 = mul_f64(&p, &s5);
    let rem: Vec<F64Interval> = (0..nu.len().max(ps5.len()))
        .map(|k| {
            let x = nu.get(k).copied().unwrap_or_else(F64Interval::zero);
            let y = ps5.get(k).copied().unwrap_or_else(F64Interval::zero);
            x - y
        })
        .collect();
    let r = range_f64(&rem);
    if !r.is_finite() {
        return None;
    }
    // a lower bound of smin⁵ (smin > 0) and an upper bound of r/smin⁵
    let lo = F64Interval::point(smin.lo());
    let smin5 = (lo * lo * lo * lo * lo).lo();
    if smin5 <= 0.0 {
        return None;
    }
    let bound = F64Interval::point(r.mag()).div_positive(smin5).hi();
    let integral = p
        .iter()
        .enumerate()
        .fold(F64Interval::zero(), |acc, (j, c)| {
            acc + c.div_positive((j + 1) as f64)
        });
    let e = (integral + F64Interval::new(-bound, bound)?) * F64Interval::point(hf);
    if !e.is_finite() {
        return None;
    }
    e.to_interval()
}

/// Validated quadrature of `∫₀¹ |r'×r''|²/σ⁵` for the quintic with control-point boxes `pts`.
///
/// Two passes: each piece is first enclosed in `f64` interval arithmetic with outward
/// rounding ([`enclose_piece_f64`]; where it cannot prove `σ > 0`, in 256-bit fixed point,
/// [`enclose_piece`]). Only if the `f64` roundings keep the total wider than the relative
/// tolerance when the piece budget is spent is the whole quadrature repeated in 256-bit
/// fixed point. Both are enclosures of the exact energy; the first pass's end points are
/// wider by the `f64` roundings.
fn enclose_energy(pts: &[[Interval; 3]], rel_tol: &Rational) -> Result<(Interval, usize), PhError> {
    let (num, sigma) = energy_integrand(pts)?;
    let first = quadrature(rel_tol, |a, b| {
        enclose_piece_f64(&num, &sigma, a, b).or_else(|| enclose_piece(&num, &sigma, a, b))
    })?;
    if first.0.width() <= rel_tol.clone() * first.0.mag() {
        return Ok(first);
    }
    quadrature(rel_tol, |a, b| enclose_piece(&num, &sigma, a, b))
}

/// The numerator `N = |r'×r''|²` and `σ` (the square root of `|r'|²`) of the energy
/// integrand `N/σ⁵` for the control-point boxes `pts`.
fn energy_integrand(pts: &[[Interval; 3]]) -> Result<(Poly<Interval>, Poly<Interval>), PhError> {
    // hodograph r'(t) = 5 Σ Δp_i B⁴_i(t)
    let comp = |k: usize| -> Poly<Interval> {
        let b: Vec<Interval> = (0..5)
            .map(|i| (pts[i + 1][k].clone() - pts[i][k].clone()) * Interval::from_i64(5))
            .collect();
        from_bernstein(&b)
    };
    let d1 = [comp(0), comp(1), comp(2)];
    let d2 = [d1[0].derivative(), d1[1].derivative(), d1[2].derivative()];
    let cross = [
        &(&d1[1] * &d2[2]) - &(&d1[2] * &d2[1]),
        &(&d1[2] * &d2[0]) - &(&d1[0] * &d2[2]),
        &(&d1[0] * &d2[1]) - &(&d1[1] * &d2[0]),
    ];
    let num = &(&(&cross[0] * &cross[0]) + &(&cross[1] * &cross[1])) + &(&cross[2] * &cross[2]);
    let sq = &(&(&d1[0] * &d1[0]) + &(&d1[1] * &d1[1])) + &(&d1[2] * &d1[2]);
    let sigma = sigma_from_square(&sq)?;
    Ok((num, sigma))
}

/// The adaptive quadrature: `piece(a, b)` encloses `∫_a^b` (or `None` where `σ` is not
/// proven positive); the widest piece is bisected until the total's relative width is at
/// most `rel_tol` or the piece budget is spent.
fn quadrature(
    rel_tol: &Rational,
    piece: impl Fn(&Rational, &Rational) -> Option<Interval>,
) -> Result<(Interval, usize), PhError> {
    // Each piece's width is computed once, and the total kept as exact sums of the
    // pieces' ends (the enclosures are on one fixed-point grid, so the sums are exact):
    // an iteration costs one scan of cached widths instead of recomputing every width
    // (a gcd each) and every sum — the quadratic cost that made data of very different
    // scales run for minutes before the budget ended it (issue 19).
    let mut set = PieceSet::default();
    let n0 = 8;
    for i in 0..n0 {
        let a = Rational::from(i) / Rational::from(n0);
        let b = Rational::from(i + 1) / Rational::from(n0);
        set.push(Piece {
            enclosure: piece(&a, &b),
            a,
            b,
        });
    }
    const BUDGET: usize = 4000;
    loop {
        if set.unproven == 0 {
            let total = set.total();
            if total.width() <= rel_tol.clone() * total.mag() || set.pieces.len() >= BUDGET {
                return Ok((total, set.pieces.len()));
            }
        }
        if set.pieces.len() >= BUDGET {
            return Err(PhError::Degenerate(
                "σ could not be proven positive on [0, 1]: the bending energy diverges or is \
                 too close to diverging"
                    .into(),
            ));
        }
        let p = set.take_widest();
        if p.enclosure.is_none() && &p.b - &p.a < pow2(-40) {
            return Err(PhError::Degenerate(format!(
                "σ could not be proven positive near t = {:.12}: the bending energy diverges or \
                 is too close to diverging",
                p.a.to_f64().value()
            )));
        }
        let mid = (&p.a + &p.b) / Rational::from(2);
        for (a, b) in [(p.a.clone(), mid.clone()), (mid, p.b.clone())] {
            set.push(Piece {
                enclosure: piece(&a, &b),
                a,
                b,
            });
        }
    }
}

/// The pieces of the quadrature with each piece's width computed once and the total kept
/// as exact sums of the pieces' ends (the enclosures are on one fixed-point grid, so the
/// sums are exact): an iteration costs one scan of cached widths instead of recomputing
/// every width (a gcd each) and every sum — the quadratic cost that made Hermite data of
/// very different scales run for minutes before the budget ended it (issue 19).
#[derive(Default)]
struct PieceSet {
    pieces: Vec<Piece>,
    widths: Vec<Option<Rational>>,
    sum_lo: Rational,
    sum_hi: Rational,
    /// Pieces on which σ is not proven positive (no enclosure).
    unproven: usize,
}

impl PieceSet {
    fn push(&mut self, p: Piece) {
        match &p.enclosure {
            Some(e) => {
                self.sum_lo += e.lo();
                self.sum_hi += e.hi();
                self.widths.push(Some(e.width()));
            }
            None => {
                self.unproven += 1;
                self.widths.push(None);
            }
        }
        self.pieces.push(p);
    }

    /// The sum of the enclosures (all pieces enclosed).
    fn total(&self) -> Interval {
        Interval::new(&self.sum_lo, &self.sum_hi).unwrap_or_else(Interval::zero)
    }

    /// Removes the piece to bisect: one without enclosure first, else the widest.
    fn take_widest(&mut self) -> Piece {
        let wi = match self.widths.iter().position(Option::is_none) {
            Some(i) => i,
            None => {
                self.widths
                    .iter()
                    .enumerate()
                    .fold((0, None::<&Rational>), |best, (i, w)| match (best.1, w) {
                        (Some(b), Some(w)) if w <= b => best,
                        (_, Some(w)) => (i, Some(w)),
                        _ => best,
                    })
                    .0
            }
        };
        self.widths.swap_remove(wi);
        let p = self.pieces.swap_remove(wi);
        match &p.enclosure {
            Some(e) => {
                self.sum_lo -= e.lo();
                self.sum_hi -= e.hi();
            }
            None => self.unproven -= 1,
        }
        p
    }
}

impl EnclosedInterpolant {
    /// The box midpoints rounded to `f64`.
    pub fn control_points_f64(&self) -> Vec<[f64; 3]> {
        self.control_points
            .iter()
            .map(|p| [p[0].to_f64(), p[1].to_f64(), p[2].to_f64()])
            .collect()
    }

    /// The largest coordinate distance between a box and the given points: every exact
    /// control point is within it of `written` (e.g. the rounded box midpoints).
    pub fn distance_bound(&self, written: &[[Rational; 3]]) -> Rational {
        let mut d = Rational::ZERO;
        for (b, w) in self.control_points.iter().zip(written) {
            for k in 0..3 {
                for x in [&w[k] - b[k].lo(), b[k].hi() - &w[k]] {
                    let x = x.abs();
                    if x > d {
                        d = x;
                    }
                }
            }
        }
        d
    }

    /// Certificates: the boxes are consistent with the exact end conditions (`p_0 = p_s`,
    /// `p_5 ∋ p_f`, `5(p_1 − p_0) ∋ d_s`, `5(p_5 − p_4) ∋ d_f`); the stated widths; the
    /// energy enclosure is positive. The enclosure itself is a proof by
    /// interval arithmetic (module docs); these checks would catch a wrong branch or root.
    pub fn certify(&self) -> Vec<Certificate> {
        let i = self.index;
        let pts = &self.control_points;
        let inside = |b: &[Interval; 3], v: &[Rational; 3]| (0..3).all(|k| b[k].contains(&v[k]));
        let diff = |a: &[Interval; 3], b: &[Interval; 3]| -> [Interval; 3] {
            let f = Interval::from_i64(5);
            [
                (a[0].clone() - b[0].clone()) * f.clone(),
                (a[1].clone() - b[1].clone()) * f.clone(),
                (a[2].clone() - b[2].clone()) * f,
            ]
        };
        let w = self.control_point_width.to_f64().value();
        let (elo, ehi) = self.bending_energy.to_f64_bounds();
        vec![
            Certificate::decide(
                format!(
                    "interpolant {i}: the box of p_0 contains p_s and the box of p_5 contains p_f"
                ),
                pts.len() == 6 && inside(&pts[0], &self.p_s) && inside(&pts[5], &self.p_f),
                true,
                || "an end point lies outside its box".into(),
            ),
            Certificate::decide(
                format!("interpolant {i}: 5(p_1 − p_0) ∋ d_s and 5(p_5 − p_4) ∋ d_f"),
                pts.len() == 6
                    && inside(&diff(&pts[1], &pts[0]), &self.d_s)
                    && inside(&diff(&pts[5], &pts[4]), &self.d_f),
                true,
                || "an end tangent lies outside its box".into(),
            ),
            Certificate::decide(
                format!(
                    "interpolant {i}: every exact control point lies in a box of width ≤ {w:.3e} \
                     (interval arithmetic from the exact isolating interval of the root)"
                ),
                pts.iter()
                    .flatten()
                    .all(|c| c.width() <= self.control_point_width),
                true,
                || "a box is wider than stated".into(),
            ),
            Certificate::decide(
                format!(
                    "interpolant {i}: the bending energy lies in [{elo:.15e}, {ehi:.15e}] \
                     (validated quadrature, {} pieces)",
                    self.quadrature_pieces
                ),
                self.bending_energy.sign() == Some(Ordering::Greater),
                true,
                || "the energy enclosure is not positive".into(),
            ),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from(p) / Rational::from(d)
    }

    /// An integrand with an exact rational integral: `N/σ⁵` with `N = g′σ − 4gσ′` is the
    /// derivative of `g/σ⁴`, so `∫_a^b N/σ⁵ = g(b)/σ(b)⁴ − g(a)/σ(a)⁴` (an independent
    /// check of the enclosures). `σ` has Bernstein coefficients in `[1, 4]`, so `σ ≥ 1` on
    /// `[0, 1]`.
    fn integrand(
        g: &[i64],
        sb: &[i64],
        den: i64,
    ) -> (
        Poly<Rational>,
        Poly<Rational>,
        Poly<Interval>,
        Poly<Interval>,
    ) {
        let g = Poly::new(g.iter().map(|c| q(*c, den)).collect());
        let bern: Vec<Rational> = sb.iter().map(|c| q(*c, 2)).collect();
        let s = from_bernstein(&bern);
        let n = &(&g.derivative() * &s) - &(&(&g * &s.derivative()) * &Poly::new(vec![q(4, 1)]));
        let (ni, si) = (n.map(Interval::point), s.map(Interval::point));
        (g, s, ni, si)
    }

    fn exact_integral(
        g: &Poly<Rational>,
        s: &Poly<Rational>,
        a: &Rational,
        b: &Rational,
    ) -> Rational {
        let f = |t: &Rational| {
            let st = s.eval(t);
            let s2 = &st * &st;
            g.eval(t) / (&s2 * &s2)
        };
        f(b) - f(a)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// Both passes enclose the exact integral on random dyadic pieces, and the `f64`
        /// pass decides every piece of a positive `σ`.
        #[test]
        fn piece_enclosures_contain_the_exact_integral(
            g in proptest::collection::vec(-40i64..40, 1..7),
            sb in proptest::collection::vec(2i64..9, 2..5),
            den in 1i64..9,
            k in 0i64..16,
            level in 0u32..5,
        ) {
            let (g, s, ni, si) = integrand(&g, &sb, den);
            let m = 1i64 << level;
            let (k, m) = (k % m, m);
            let (a, b) = (q(k, m), q(k + 1, m));
            let exact = exact_integral(&g, &s, &a, &b);
            let fast = enclose_piece_f64(&ni, &si, &a, &b);
            let fast = fast.expect("σ ≥ 1: the f64 pass decides");
            prop_assert!(fast.contains(&exact), "f64 pass {:?} misses {}", fast.to_f64_bounds(), exact.to_f64().value());
            let slow = enclose_piece(&ni, &si, &a, &b).expect("σ ≥ 1");
            prop_assert!(slow.contains(&exact));
        }

        /// The two-pass quadrature encloses the exact integral over `[0, 1]` to the
        /// relative tolerance.
        #[test]
        fn quadrature_encloses_the_exact_integral(
            g in proptest::collection::vec(-40i64..40, 2..7),
            sb in proptest::collection::vec(1i64..9, 2..5),
        ) {
            let (g, s, ni, si) = integrand(&g, &sb, 3);
            let exact = exact_integral(&g, &s, &Rational::ZERO, &Rational::ONE);
            let tol = pow2(-30);
            let (total, _) = quadrature(&tol, |a, b| {
                enclose_piece_f64(&ni, &si, a, b).or_else(|| enclose_piece(&ni, &si, a, b))
            })
            .expect("σ ≥ 1/2");
            prop_assert!(total.contains(&exact));
            prop_assert!(total.width() <= tol * total.mag() + pow2(-200));
        }
    }

    /// A planted error: the enclosure of a shifted integrand misses the exact value of the
    /// original one (the check above can fail).
    #[test]
    fn a_wrong_integrand_is_not_enclosed() {
        let (g, s, ni, si) = integrand(&[1, -3, 2, 5], &[2, 3, 5], 1);
        let exact = exact_integral(&g, &s, &Rational::ZERO, &q(1, 2));
        let shifted = &ni + &Poly::new(vec![Interval::point(&q(1, 1000))]);
        let good = enclose_piece_f64(&ni, &si, &Rational::ZERO, &q(1, 2)).expect("decided");
        let bad = enclose_piece_f64(&shifted, &si, &Rational::ZERO, &q(1, 2)).expect("decided");
        assert!(good.contains(&exact));
        assert!(
            !bad.contains(&exact),
            "{:?} {:?}",
            good.to_f64_bounds(),
            bad.to_f64_bounds()
        );
    }

    /// Besednjak Example 9.1 (the gallery's `hermite_9_1`): the first pass reaches the
    /// gallery's tolerance `2⁻⁴⁰` well within the piece budget, and its enclosure of each
    /// energy meets the 256-bit one.
    #[test]
    fn example_9_1_first_pass_reaches_the_tolerance() {
        use super::super::hermite::HermiteData;
        let z = Rational::ZERO;
        let o = Rational::ONE;
        let data = HermiteData::new(
            [z.clone(), z.clone(), z.clone()],
            [o.clone(), z.clone(), o.clone()],
            [o.clone(), o.clone(), o.clone()],
            [z.clone(), o.clone(), o.clone()],
        );
        let sol = data.solve_exact().expect("solutions");
        let tol = pow2(-40);
        for i in 0..sol.interpolants.len() {
            let e = sol.enclose(i, &pow2(-80), &tol).expect("enclosed");
            let (num, sigma) = energy_integrand(&e.control_points).expect("σ(0) > 0");
            let (fast, pieces) = quadrature(&tol, |a, b| {
                enclose_piece_f64(&num, &sigma, a, b).or_else(|| enclose_piece(&num, &sigma, a, b))
            })
            .expect("first pass");
            assert!(
                fast.width() <= tol.clone() * fast.mag(),
                "interpolant {i}: {pieces} pieces"
            );
            assert!(pieces < 1000, "interpolant {i}: {pieces} pieces");
            let (slow, _) =
                quadrature(&tol, |a, b| enclose_piece(&num, &sigma, a, b)).expect("256");
            assert!(fast.lo() <= slow.hi() && slow.lo() <= fast.hi());
        }
    }
}
