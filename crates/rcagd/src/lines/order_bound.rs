//! An upper bound of `(m + n)·μ` for a parametrized congruence `l(u, v) = p(u, v) ∧ q(u, v)`
//! (order `m`, class `n`, `μ` parameter points per generic line), by Bézout's theorem minus
//! the base points of the linear system of line conditions (docs/math/lines-and-canal.md,
//! "Order and class decided over independent choices", and "An upper bound by Bézout").
//!
//! **The count.** A line `g` gives the condition `f_g(u, v) = Ω(g, l(u, v))` (the
//! congruence line meets `g`), a member of the linear system spanned by the six Plücker
//! polynomials `lᵢⱼ`. Two generic lines `g, h` are met by exactly `m + n` lines of the
//! congruence (the degree of the congruence surface in the Klein quadric: Pottmann and
//! Wallner, "Computational Line Geometry", 2001, §3.2 — two lines through a point `P` meet
//! the lines through `P` and the lines in their plane), each hit by `μ` parameter points,
//! and for generic `g, h` these are distinct from the base points (common zeros of all
//! `lᵢⱼ`). In a compactification `X` of the parameter plane in which `f_g, f_h` are curves
//! of class `c`, Bézout gives `Σ I_x(f_g, f_h) = c²` (`X = P²`, `c = e` the total degree:
//! `e²`; `X = P¹ × P¹`, bidegree `(a, b)`: `2ab`). At a base point `x` where every `lᵢⱼ`
//! vanishes to order `≥ m_x`, both curves have multiplicity `≥ m_x`, so
//! `I_x ≥ m_x²` (Fulton, "Algebraic Curves", §3.3, property (5)). Hence
//!
//! ```text
//! (m + n)·μ ≤ c² − Σ_x m_x²      (x over any set of base points, finite or at infinity)
//! ```
//!
//! with equality when the base points found are all of them and ordinary (no common tangent
//! of generic members). The base points used are the **rational** ones (finite: the rational
//! roots `u₀` of `gcd_k Res_v(l₁, l_k)` and then of `gcd_k l_k(u₀, v)`); at infinity every
//! base point on the line at infinity of each chart, rational or not: an irreducible factor
//! `φ` of the common restriction gives `deg φ` conjugate points of one multiplicity, the
//! least `i + j` with `φ ∤ ∂ₓⁱ c_j` (`c_j` the coefficient of `yʲ`). Irrational finite base
//! points and the excess `I_x − m_x²` at non-ordinary base points are not subtracted, so
//! the bound stays valid but may not be reached. The common factor of
//! the `lᵢⱼ` (a curve of parameters with `p ∧ q = 0`) is divided out first.

use super::plucker::wedge;
use rcagd_algebra::mpoly::{resultant_in, MPoly};
use rcagd_algebra::roots::rational_roots;
use rcagd_algebra::{Poly, Rational};

/// A base point of the line conditions with the multiplicity `m_x` subtracted as `m_x²`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BasePoint {
    /// Where: `(u, v)` finite, or a point at infinity of the compactification.
    pub location: String,
    /// The least order of vanishing of the six Plücker polynomials there.
    pub multiplicity: usize,
}

/// The upper bound of `(m + n)·μ` in one compactification of the parameter plane.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BezoutBound {
    /// `"P²"` or `"P¹×P¹"`.
    pub compactification: &'static str,
    /// The Bézout number `e²` or `2ab`.
    pub bezout: usize,
    /// The rational base points found, with multiplicities.
    pub base_points: Vec<BasePoint>,
    /// `bezout − Σ m_x²`.
    pub bound: usize,
}

/// The Plücker polynomials of `p ∧ q` with their common factor divided out.
fn plucker(p: &[MPoly<Rational>; 4], q: &[MPoly<Rational>; 4]) -> Vec<MPoly<Rational>> {
    super::order_one::without_common_factor(wedge(p, q))
        .into_iter()
        .filter(|x| !x.is_zero())
        .collect()
}

fn exps(e: &[u32]) -> (u32, u32) {
    (
        e.first().copied().unwrap_or(0),
        e.get(1).copied().unwrap_or(0),
    )
}

/// The polynomial with every term `c uⁱ vʲ` replaced by `c x^{f(i, j).0} y^{f(i, j).1}` (a
/// chart of the compactification).
fn chart(p: &MPoly<Rational>, f: impl Fn(u32, u32) -> (u32, u32)) -> MPoly<Rational> {
    p.terms().fold(MPoly::zero(2), |acc, (e, c)| {
        let (i, j) = exps(e);
        let (a, b) = f(i, j);
        &acc + &MPoly::monomial(2, &[a, b], c.clone())
    })
}

/// The order of vanishing of `p` at `(x₀, y₀)` (the least total degree of `p(x₀ + x, y₀ + y)`).
fn order_at(p: &MPoly<Rational>, x0: &Rational, y0: &Rational) -> usize {
    let sx = &MPoly::var(2, 0) + &MPoly::constant(2, x0.clone());
    let sy = &MPoly::var(2, 1) + &MPoly::constant(2, y0.clone());
    let shifted = p.terms().fold(MPoly::zero(2), |acc, (e, c)| {
        let (i, j) = exps(e);
        &acc + &(&sx.pow(i) * &sy.pow(j)).scale(c)
    });
    shifted
        .terms()
        .map(|(e, _)| {
            let (i, j) = exps(e);
            (i + j) as usize
        })
        .min()
        .unwrap_or(usize::MAX)
}

fn min_order(ls: &[MPoly<Rational>], x0: &Rational, y0: &Rational) -> usize {
    ls.iter().map(|l| order_at(l, x0, y0)).min().unwrap_or(0)
}

/// `p(x, y₀)` for the chart variable `y` fixed (`var = 1`) or `p(x₀, y)` (`var = 0`) as a
/// univariate polynomial in the other variable.
fn restrict(p: &MPoly<Rational>, var: usize, value: &Rational) -> Poly<Rational> {
    let mut c: Vec<Rational> = Vec::new();
    for (e, k) in p.terms() {
        let (i, j) = exps(e);
        let (fixed, free) = if var == 1 { (j, i) } else { (i, j) };
        let idx = free as usize;
        if c.len() <= idx {
            c.resize(idx + 1, Rational::ZERO);
        }
        let mut x = k.clone();
        for _ in 0..fixed {
            x *= value.clone();
        }
        c[idx] += x;
    }
    Poly::new(c)
}

/// The rational finite base points `(u₀, v₀)` with their multiplicities.
fn finite_base_points(ls: &[MPoly<Rational>]) -> Result<Vec<BasePoint>, String> {
    let Some(first) = ls.first() else {
        return Ok(Vec::new());
    };
    let mut g = Poly::zero();
    for l in &ls[1..] {
        let r = resultant_in(first, l, 1).map_err(|e| e.to_string())?;
        g = g.gcd(&r);
    }
    if ls.len() == 1 {
        // a single condition: every zero of it is a base point (not a congruence)
        return Err("only one non-zero Plücker coordinate".into());
    }
    if g.is_zero() {
        // the first coordinate shares a factor with every other one after the common
        // factor was removed: cannot happen for a gcd of all; no finite base points found
        return Ok(Vec::new());
    }
    let mut out = Vec::new();
    for u0 in rational_roots(&g) {
        let h = ls.iter().fold(Poly::zero(), |acc: Poly<Rational>, l| {
            acc.gcd(&restrict(l, 0, &u0))
        });
        if h.is_zero() || h.degree().is_none_or(|d| d == 0) {
            continue;
        }
        for v0 in rational_roots(&h) {
            let m = min_order(ls, &u0, &v0);
            if m > 0 && m != usize::MAX {
                out.push(BasePoint {
                    location: format!("(u, v) = ({u0}, {v0})"),
                    multiplicity: m,
                });
            }
        }
    }
    Ok(out)
}

fn total(ls: &[MPoly<Rational>], f: impl Fn(&MPoly<Rational>) -> Option<u32>) -> u32 {
    ls.iter().filter_map(f).max().unwrap_or(0)
}

/// The coefficient of `yʲ` of a chart polynomial as a polynomial in `x`.
fn y_coefficient(p: &MPoly<Rational>, j: u32) -> Poly<Rational> {
    let mut c: Vec<Rational> = Vec::new();
    for (e, k) in p.terms() {
        let (i, jj) = exps(e);
        if jj == j {
            let idx = i as usize;
            if c.len() <= idx {
                c.resize(idx + 1, Rational::ZERO);
            }
            c[idx] += k.clone();
        }
    }
    Poly::new(c)
}

/// The order of vanishing of `p` at `(x₀, 0)` for every root `x₀` of the irreducible `φ`
/// (the same at all conjugate roots): the least `i + j` with `φ ∤ ∂ₓⁱ c_j`, `c_j` the
/// coefficient of `yʲ` (a Taylor coefficient of `p(x₀ + x, y)` is zero iff `φ` divides the
/// corresponding derivative).
fn order_on_line(p: &MPoly<Rational>, phi: &Poly<Rational>) -> usize {
    let dy = p.degree_in(1).unwrap_or(0);
    let mut best = usize::MAX;
    for j in 0..=dy {
        let c = y_coefficient(p, j);
        let Some(dc) = c.degree() else { continue };
        for i in 0..=dc {
            if (i + j as usize) >= best {
                break;
            }
            let di = c.derivative_n(i);
            let nonzero = di.div_rem(phi).map_or(true, |(_, r)| !r.is_zero());
            if nonzero {
                best = best.min(i + j as usize);
                break;
            }
        }
    }
    best
}

/// Base points on the line `y = 0` of a chart (the line at infinity): every irreducible
/// factor `φ` of `gcd_k p_k(x, 0)` gives `deg φ` conjugate base points of one multiplicity
/// (counted `deg φ` times).
fn base_points_on_chart_line(
    charts: &[MPoly<Rational>],
    name: &dyn Fn(&Poly<Rational>) -> String,
) -> Vec<BasePoint> {
    let zero = Rational::ZERO;
    let g = charts.iter().fold(Poly::zero(), |acc: Poly<Rational>, l| {
        acc.gcd(&restrict(l, 1, &zero))
    });
    if g.is_zero() || g.degree().is_none_or(|d| d == 0) {
        return Vec::new();
    }
    let Ok((_, factors)) = rcagd_algebra::factor::factor_rational(&g) else {
        // not factored: the rational roots only
        return rational_roots(&g)
            .into_iter()
            .filter_map(|x0| {
                let m = min_order(charts, &x0, &zero);
                let phi = Poly::new(vec![-x0, Rational::ONE]);
                (m > 0 && m != usize::MAX).then(|| BasePoint {
                    location: name(&phi),
                    multiplicity: m,
                })
            })
            .collect();
    };
    let mut out = Vec::new();
    for (phi, _) in factors {
        let m = charts
            .iter()
            .map(|c| order_on_line(c, &phi))
            .min()
            .unwrap_or(0);
        if m == 0 || m == usize::MAX {
            continue;
        }
        for _ in 0..phi.degree().unwrap_or(1) {
            out.push(BasePoint {
                location: name(&phi),
                multiplicity: m,
            });
        }
    }
    out
}

fn fmt_poly(p: &Poly<Rational>, var: &str) -> String {
    rcagd_algebra::format_poly(p, var)
}

fn finish(
    compactification: &'static str,
    bezout: usize,
    base_points: Vec<BasePoint>,
) -> BezoutBound {
    let sub: usize = base_points
        .iter()
        .map(|b| b.multiplicity * b.multiplicity)
        .sum();
    BezoutBound {
        compactification,
        bezout,
        base_points,
        bound: bezout.saturating_sub(sub),
    }
}

/// The bound in `P²` (total degree `e`, base points at infinity `[1 : s : 0]` and
/// `[0 : 1 : 0]`) and in `P¹ × P¹` (bidegree `(a, b)`, base points at `u = ∞`, `v = ∞` and
/// the corner), both with the same finite base points (module docs).
///
/// # Errors
/// A message if a resultant fails (degrees beyond the dense limit) or the Plücker
/// polynomials span less than a net.
pub fn bezout_bounds(
    p: &[MPoly<Rational>; 4],
    q: &[MPoly<Rational>; 4],
) -> Result<[BezoutBound; 2], String> {
    let ls = plucker(p, q);
    if ls.len() < 2 {
        return Err("fewer than two non-zero Plücker coordinates: not a congruence".into());
    }
    let finite = finite_base_points(&ls)?;
    // P²: e = total degree; chart u = 1: (y, w) = (v/u, 1/u), term uⁱvʲ ↦ yʲ w^{e−i−j}
    let e = total(&ls, |l| l.total_degree().map(|d| d as u32));
    let c1: Vec<MPoly<Rational>> = ls.iter().map(|l| chart(l, |i, j| (j, e - i - j))).collect();
    let mut p2 = finite.clone();
    p2.extend(base_points_on_chart_line(&c1, &|phi| {
        format!("[u : v : w] = [1 : s : 0], {} = 0", fmt_poly(phi, "s"))
    }));
    // [0 : 1 : 0]: chart v = 1, (x, w) = (u/v, 1/v), uⁱvʲ ↦ xⁱ w^{e−i−j}, at (0, 0)
    let c2: Vec<MPoly<Rational>> = ls.iter().map(|l| chart(l, |i, j| (i, e - i - j))).collect();
    let m = min_order(&c2, &Rational::ZERO, &Rational::ZERO);
    if m > 0 && m != usize::MAX {
        p2.push(BasePoint {
            location: "[u : v : w] = [0 : 1 : 0]".into(),
            multiplicity: m,
        });
    }
    let b_p2 = finish("P²", (e * e) as usize, p2);
    // P¹ × P¹: a = deg_u, b = deg_v
    let a = total(&ls, |l| l.degree_in(0));
    let b = total(&ls, |l| l.degree_in(1));
    let mut pp = finite;
    // u = ∞: (u', v) = (1/u, v), uⁱvʲ ↦ u'^{a−i} vʲ; points (0, v₀): the line u' = 0 as
    // "y = 0" after swapping the chart variables
    let cu: Vec<MPoly<Rational>> = ls.iter().map(|l| chart(l, |i, j| (j, a - i))).collect();
    pp.extend(base_points_on_chart_line(&cu, &|phi| {
        format!("(u, v) = (∞, v), {} = 0", fmt_poly(phi, "v"))
    }));
    // v = ∞: (u, v') = (u, 1/v), uⁱvʲ ↦ uⁱ v'^{b−j}; points (u₀, 0)
    let cv: Vec<MPoly<Rational>> = ls.iter().map(|l| chart(l, |i, j| (i, b - j))).collect();
    pp.extend(base_points_on_chart_line(&cv, &|phi| {
        format!("(u, v) = (u, ∞), {} = 0", fmt_poly(phi, "u"))
    }));
    // the corner (∞, ∞)
    let cc: Vec<MPoly<Rational>> = ls.iter().map(|l| chart(l, |i, j| (a - i, b - j))).collect();
    let m = min_order(&cc, &Rational::ZERO, &Rational::ZERO);
    if m > 0 && m != usize::MAX {
        pp.push(BasePoint {
            location: "(u, v) = (∞, ∞)".into(),
            multiplicity: m,
        });
    }
    let b_pp = finish("P¹×P¹", (2 * a * b) as usize, pp);
    Ok([b_p2, b_pp])
}

/// The smaller of the two bounds of [`bezout_bounds`].
///
/// # Errors
/// As [`bezout_bounds`].
pub fn degree_upper_bound(
    p: &[MPoly<Rational>; 4],
    q: &[MPoly<Rational>; 4],
) -> Result<BezoutBound, String> {
    let [a, b] = bezout_bounds(p, q)?;
    Ok(if b.bound < a.bound { b } else { a })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(terms: &[(i64, u32, u32)]) -> MPoly<Rational> {
        terms.iter().fold(MPoly::zero(2), |acc, &(c, i, j)| {
            &acc + &MPoly::monomial(2, &[i, j], Rational::from(c))
        })
    }

    #[test]
    fn a_line_and_a_conic() {
        // lines meeting the conic (1 + u², 2u, 0, 1 − u²) and the line (1, 5, v, 0): a
        // (2, 2)-congruence with μ = 1, bidegree (2, 1): 2·2·1 = 4 = m + n
        let p = [
            m(&[(1, 0, 0), (1, 2, 0)]),
            m(&[(2, 1, 0)]),
            m(&[]),
            m(&[(1, 0, 0), (-1, 2, 0)]),
        ];
        let q = [m(&[(1, 0, 0)]), m(&[(5, 0, 0)]), m(&[(1, 0, 1)]), m(&[])];
        let b = degree_upper_bound(&p, &q).expect("bound");
        assert_eq!(b.bound, 4, "{b:?}");
    }

    #[test]
    fn order_at_counts_the_lowest_terms() {
        // (u − 1)²(v + 2) + (u − 1)³ at (1, −2): order 3? no: (u−1)²(v+2) has order 3,
        // (u − 1)³ order 3
        let x = &m(&[(1, 0, 0), (-2, 1, 0), (1, 2, 0)]) * &m(&[(2, 0, 0), (1, 0, 1)]);
        assert_eq!(order_at(&x, &Rational::ONE, &Rational::from(-2)), 3);
        assert_eq!(order_at(&x, &Rational::ZERO, &Rational::ZERO), 0);
    }
}
