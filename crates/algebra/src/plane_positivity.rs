//! Deciding whether a polynomial `G(x, y)` with rational coefficients is positive on the
//! whole real plane, with a proof or a witness.
//!
//! **Method** (a two-level cylindrical decomposition, Collins 1975, specialised to one
//! question; Basu–Pollack–Roy, *Algorithms in Real Algebraic Geometry*, 2006, §5.1–5.2 and
//! §11.1). Write `G` as a polynomial in the fibre variable `y` with coefficients in `ℚ[x]`
//! and let `C(x) = Res_y(G, G_y)` (the leading coefficient times the discriminant). On each
//! open interval `I` between consecutive real roots of `C`, the leading coefficient and
//! the discriminant do not vanish, so the number of distinct real roots of `G(x, ·)` is the
//! same for every `x ∈ I`: if `G(x₀, ·)` has no real root and `G(x₀, 0) > 0` at one
//! rational `x₀ ∈ I`, then `G > 0` on `I × ℝ` (connected, no zero). If this holds on
//! every open interval, a zero of `G` can lie only on a critical line `x = α`, `C(α) = 0`;
//! there `G ≥ 0` by continuity, so the zero is a local minimum and
//! `G = G_x = G_y = 0`. Hence `α` is a root of `c(x) = gcd(C, Res_y(G, G_x))` and its
//! `y`-coordinate a root of `d(y) = gcd(Res_x(G, G_x), Res_x(G, G_y))`: when `c` or `d` has no
//! real root, `G > 0` on ℝ² (proved); otherwise each candidate box `[α] × [β]` (isolating
//! intervals, refined) is excluded by an interval evaluation of `G` (Moore 1966), or the
//! question stays open (`Undecided`, naming the candidates: a zero at an irrational point
//! where `G` touches 0, such as `(x² − 2)² + (y² − 3)²` at `(√2, √3)`, needs arithmetic in
//! an algebraic extension).
//!
//! A negative answer always carries a witness: a rational point where `G ≤ 0`, or a
//! rational `x₀` and an isolating interval of a real root of `G(x₀, ·)` (a real zero).
//! Odd degree in either variable is decided by such a witness directly.
//!
//! Used by the recognition of sphere families (no real envelope iff the Lorentz Gram
//! determinant of the tangent planes is negative on the whole plane; docs/math/
//! sphere-families.md, "Recognition").

use crate::error::AlgebraError;
use crate::interval::{pow2, Interval};
use crate::mpoly::{resultant_in, MPoly};
use crate::poly::Poly;
use crate::rational::Rational;
use crate::roots::{isolate_real_roots, RootInterval};
use core::cmp::Ordering;
use num_traits::{One, Zero};

/// The answer of [`plane_positivity`].
#[derive(Debug, Clone, PartialEq)]
pub enum PlanePositivity {
    /// `G(x, y) > 0` for every real `(x, y)`; the proof's summary.
    Positive(PositivityProof),
    /// A rational point where `G ≤ 0` (the value is given).
    NotPositive {
        /// The point `(x, y)`.
        point: [Rational; 2],
        /// `G(x, y) ≤ 0`.
        value: Rational,
    },
    /// `G(x₀, ·)` has a real root in the open interval `(lo, hi)` (isolated exactly), at
    /// which `G` touches zero.
    Zero {
        /// The rational `x₀` (for the first variable; see `fibre`).
        at: Rational,
        /// The variable that is fixed at `at` (0 or 1); the root lies in the other one.
        fixed: usize,
        /// The isolating interval of the root in the other variable.
        root: RootInterval,
    },
    /// Neither proved nor refuted; the reason (candidate points of a zero, approximately).
    Undecided(String),
}

/// What was checked to prove `G > 0` on ℝ².
#[derive(Debug, Clone, PartialEq)]
pub struct PositivityProof {
    /// The variable of the base (the other one is the fibre variable).
    pub base: usize,
    /// The number of open base intervals checked at a sample point.
    pub cells: usize,
    /// The number of real critical values `C(α) = 0` of the base.
    pub critical_values: usize,
    /// A one-line description of the argument.
    pub summary: String,
}

/// Decides whether `g ∈ ℚ[x₀, x₁]` is positive on ℝ² (module docs).
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] if a variable other than `x₀`, `x₁` occurs (or a
/// degree exceeds the dense limits of [`resultant_in`]).
pub fn plane_positivity(g: &MPoly<Rational>) -> Result<PlanePositivity, AlgebraError> {
    if g.terms().any(|(e, _)| e.iter().skip(2).any(|&k| k != 0)) {
        return Err(AlgebraError::InvalidArgument(
            "plane_positivity: the polynomial must be in two variables x₀, x₁".into(),
        ));
    }
    let g = to_two_vars(g);
    if let Some(w) = grid_witness(&g)? {
        return Ok(w);
    }
    let dx = g.degree_in(0).unwrap_or(0);
    let dy = g.degree_in(1).unwrap_or(0);
    if dx == 0 && dy == 0 {
        // a constant, positive by the grid check
        return Ok(PlanePositivity::Positive(PositivityProof {
            base: 0,
            cells: 1,
            critical_values: 0,
            summary: "a positive constant".into(),
        }));
    }
    // odd degree in a variable: G takes both signs along a line
    for (fibre, d) in [(1usize, dy), (0, dx)] {
        if d % 2 == 1 {
            return odd_degree_witness(&g, 1 - fibre);
        }
    }
    // one variable only: the univariate decision
    if dy == 0 || dx == 0 {
        let fibre = if dy == 0 { 0 } else { 1 };
        let zero = Rational::zero();
        let h = fibre_poly(&g, 1 - fibre, &zero)?;
        if let Some(w) = line_witness(&h, 1 - fibre, &zero)? {
            return Ok(w);
        }
        return Ok(PlanePositivity::Positive(PositivityProof {
            base: 1 - fibre,
            cells: 1,
            critical_values: 0,
            summary: format!("G depends on x{fibre} only and has no real root, positive at 0"),
        }));
    }
    decide(&g, 0)
}

fn to_two_vars(g: &MPoly<Rational>) -> MPoly<Rational> {
    let terms: Vec<(Vec<u32>, Rational)> = g
        .terms()
        .map(|(e, c)| {
            (
                vec![
                    e.first().copied().unwrap_or(0),
                    e.get(1).copied().unwrap_or(0),
                ],
                c.clone(),
            )
        })
        .collect();
    let mut out = MPoly::zero(2);
    for (e, c) in terms {
        out = &out + &MPoly::monomial(2, &e, c);
    }
    out
}

/// `G` at the fixed value `at` of variable `fixed`, as a polynomial in the other one.
fn fibre_poly(
    g: &MPoly<Rational>,
    fixed: usize,
    at: &Rational,
) -> Result<Poly<Rational>, AlgebraError> {
    let fibre = 1 - fixed;
    let s = g.specialize(fixed, at);
    let mut c: Vec<Rational> = Vec::new();
    for (e, v) in s.terms() {
        let k = e.get(fibre).copied().unwrap_or(0) as usize;
        if k >= c.len() {
            c.resize(k + 1, Rational::zero());
        }
        c[k] = &c[k] + v;
    }
    Ok(Poly::new(c))
}

fn point(fixed: usize, at: &Rational, y: Rational) -> [Rational; 2] {
    if fixed == 0 {
        [at.clone(), y]
    } else {
        [y, at.clone()]
    }
}

/// Rational values of both coordinates tried first for a witness `G ≤ 0`.
fn grid_values() -> Vec<Rational> {
    let mut v = vec![Rational::zero()];
    for (p, q) in [(1, 2), (1, 1), (2, 1), (4, 1), (1, 4), (3, 2), (8, 1)] {
        let r = Rational::from(p) / Rational::from(q);
        v.push(r.clone());
        v.push(-r);
    }
    v
}

fn grid_witness(g: &MPoly<Rational>) -> Result<Option<PlanePositivity>, AlgebraError> {
    let vals = grid_values();
    for x in &vals {
        for y in &vals {
            let value = g.eval(&[x.clone(), y.clone()])?;
            if value <= Rational::zero() {
                return Ok(Some(PlanePositivity::NotPositive {
                    point: [x.clone(), y.clone()],
                    value,
                }));
            }
        }
    }
    Ok(None)
}

/// A witness that the univariate `h` (the fibre of `G` at `fixed = at`) is not positive
/// on ℝ, or `None` if it is (no real root, positive leading coefficient).
fn line_witness(
    h: &Poly<Rational>,
    fixed: usize,
    at: &Rational,
) -> Result<Option<PlanePositivity>, AlgebraError> {
    if h.is_zero() {
        return Ok(Some(PlanePositivity::NotPositive {
            point: point(fixed, at, Rational::zero()),
            value: Rational::zero(),
        }));
    }
    let roots = isolate_real_roots(h)?;
    if roots.is_empty() {
        let v0 = h.eval(&Rational::zero());
        if v0 > Rational::zero() {
            return Ok(None);
        }
        return Ok(Some(PlanePositivity::NotPositive {
            point: point(fixed, at, Rational::zero()),
            value: v0,
        }));
    }
    if let Some(r) = roots.iter().find(|r| r.is_exact()) {
        return Ok(Some(PlanePositivity::NotPositive {
            point: point(fixed, at, r.lo.clone()),
            value: Rational::zero(),
        }));
    }
    // between and beside the isolating intervals (open, disjoint, sorted)
    for y in samples_between(&roots) {
        let value = h.eval(&y);
        if value <= Rational::zero() {
            return Ok(Some(PlanePositivity::NotPositive {
                point: point(fixed, at, y),
                value,
            }));
        }
    }
    // every root of even multiplicity: G touches zero there
    Ok(Some(PlanePositivity::Zero {
        at: at.clone(),
        fixed,
        root: roots[0].clone(),
    }))
}

/// `G` has odd degree in the fibre variable `1 − base`: along a base value where the
/// leading coefficient does not vanish, `G` changes sign.
fn odd_degree_witness(g: &MPoly<Rational>, base: usize) -> Result<PlanePositivity, AlgebraError> {
    for k in 0..64i64 {
        let at = Rational::from(k);
        let h = fibre_poly(g, base, &at)?;
        if h.degree().is_some_and(|d| d % 2 == 1) {
            if let Some(w) = line_witness(&h, base, &at)? {
                return Ok(w);
            }
        }
    }
    Ok(PlanePositivity::Undecided(
        "odd degree, but no base value 0..63 keeps the leading coefficient".into(),
    ))
}

/// A rational strictly between two consecutive isolating intervals (or beside them).
fn samples_between(roots: &[RootInterval]) -> Vec<Rational> {
    let two = Rational::from(2);
    let mut s = Vec::new();
    match (roots.first(), roots.last()) {
        (Some(f), Some(l)) => {
            s.push(&f.lo - &Rational::one());
            for w in roots.windows(2) {
                s.push((&w[0].hi + &w[1].lo) / two.clone());
            }
            s.push(&l.hi + &Rational::one());
        }
        _ => s.push(Rational::zero()),
    }
    s
}

fn decide(g: &MPoly<Rational>, base: usize) -> Result<PlanePositivity, AlgebraError> {
    let fibre = 1 - base;
    let g_fibre = g.partial(fibre);
    let g_base = g.partial(base);
    let crit = resultant_in(g, &g_fibre, fibre)?;
    if crit.is_zero() {
        return Ok(PlanePositivity::Undecided(format!(
            "Res_x{fibre}(G, ∂G/∂x{fibre}) vanishes identically: G has a repeated factor"
        )));
    }
    let crit_roots = isolate_real_roots(&crit)?;
    let samples = samples_between(&crit_roots);
    for at in &samples {
        // the sample must not be a critical value (intervals are open and disjoint)
        if crit.eval(at).is_zero() {
            return Ok(PlanePositivity::Undecided(format!(
                "sample x{base} = {at} is a critical value"
            )));
        }
        let h = fibre_poly(g, base, at)?;
        if let Some(w) = line_witness(&h, base, at)? {
            return Ok(w);
        }
    }
    let cells = samples.len();
    let proved = |summary: String| {
        Ok(PlanePositivity::Positive(PositivityProof {
            base,
            cells,
            critical_values: crit_roots.len(),
            summary,
        }))
    };
    if crit_roots.is_empty() {
        return proved(format!(
            "Res_x{fibre}(G, ∂G/∂x{fibre}) has no real root; G > 0 on the line x{base} = {}",
            samples[0]
        ));
    }
    // a zero on a critical line is a local minimum: G = G_x = G_y = 0 there
    let second = resultant_in(g, &g_base, fibre)?;
    if second.is_zero() {
        return Ok(PlanePositivity::Undecided(format!(
            "Res_x{fibre}(G, ∂G/∂x{base}) vanishes identically"
        )));
    }
    let c = crit.gcd(&second);
    let alphas = if c.degree().unwrap_or(0) == 0 {
        Vec::new()
    } else {
        isolate_real_roots(&c)?
    };
    if alphas.is_empty() {
        return proved(format!(
            "G > 0 at a sample of each of the {cells} open cells, and no critical value of x{base} \
             is a root of Res_x{fibre}(G, ∂G/∂x{base}) (no minimum of G can be 0)"
        ));
    }
    let d1 = resultant_in(g, &g_base, base)?;
    let d2 = resultant_in(g, &g_fibre, base)?;
    if d1.is_zero() || d2.is_zero() {
        return Ok(PlanePositivity::Undecided(format!(
            "a resultant in x{base} vanishes identically"
        )));
    }
    let d = d1.gcd(&d2);
    let betas = if d.degree().unwrap_or(0) == 0 {
        Vec::new()
    } else {
        isolate_real_roots(&d)?
    };
    if betas.is_empty() {
        return proved(format!(
            "G > 0 on the {cells} open cells; the candidate minima have no real x{fibre}"
        ));
    }
    let gi = g.map(Interval::point);
    let mut open: Vec<String> = Vec::new();
    for a in &alphas {
        for b in &betas {
            if a.is_exact() && b.is_exact() {
                let pt = point(base, &a.lo, b.lo.clone());
                let value = g.eval(&pt)?;
                if value <= Rational::zero() {
                    return Ok(PlanePositivity::NotPositive { point: pt, value });
                }
                continue;
            }
            if !box_excluded(&gi, &c, a, &d, b, base)? {
                open.push(format!(
                    "x{base} ≈ {:.6}, x{fibre} ≈ {:.6}",
                    a.midpoint_f64(),
                    b.midpoint_f64()
                ));
            }
        }
    }
    if open.is_empty() {
        return proved(format!(
            "G > 0 on the {cells} open cells, and interval bounds exclude a zero at each of the \
             {} candidate minima",
            alphas.len() * betas.len()
        ));
    }
    Ok(PlanePositivity::Undecided(format!(
        "G > 0 off the critical lines, but a zero (a minimum touching 0) is not excluded near: {}",
        open.join("; ")
    )))
}

/// `G > 0` on the box `[a] × [b]` (refined up to `2⁻⁹⁶` wide), by interval evaluation.
fn box_excluded(
    gi: &MPoly<Interval>,
    c: &Poly<Rational>,
    a: &RootInterval,
    d: &Poly<Rational>,
    b: &RootInterval,
    base: usize,
) -> Result<bool, AlgebraError> {
    let (mut a, mut b) = (a.clone(), b.clone());
    for bits in [8isize, 24, 48, 96] {
        let w = pow2(-bits);
        if !a.is_exact() {
            a.refine(c, &w)?;
        }
        if !b.is_exact() {
            b.refine(d, &w)?;
        }
        let (ia, ib) = match (Interval::new(&a.lo, &a.hi), Interval::new(&b.lo, &b.hi)) {
            (Some(x), Some(y)) => (x, y),
            _ => return Ok(false),
        };
        let args = if base == 0 { [ia, ib] } else { [ib, ia] };
        if gi.eval(&args)?.sign() == Some(Ordering::Greater) {
            return Ok(true);
        }
    }
    Ok(false)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from(p) / Rational::from(d)
    }

    /// `Σ c x^i y^j` from `(c, i, j)`.
    fn mp(terms: &[(Rational, u32, u32)]) -> MPoly<Rational> {
        let mut g = MPoly::zero(2);
        for (c, i, j) in terms {
            g = &g + &MPoly::monomial(2, &[*i, *j], c.clone());
        }
        g
    }

    fn x() -> MPoly<Rational> {
        MPoly::var(2, 0)
    }
    fn y() -> MPoly<Rational> {
        MPoly::var(2, 1)
    }
    fn c(p: i64, d: i64) -> MPoly<Rational> {
        MPoly::constant(2, q(p, d))
    }

    #[test]
    fn sums_of_squares_plus_a_constant_are_proved_positive() {
        let g = mp(&[(q(1, 1), 0, 0), (q(1, 1), 2, 0), (q(1, 1), 0, 2)]);
        assert!(matches!(
            plane_positivity(&g),
            Ok(PlanePositivity::Positive(_))
        ));
        // (x² − 1)² + (y − x)² + 1/100: critical values exist, no minimum is 0
        let a = &(&x() * &x()) - &c(1, 1);
        let b = &y() - &x();
        let g = &(&(&a * &a) + &(&b * &b)) + &c(1, 100);
        assert!(matches!(
            plane_positivity(&g),
            Ok(PlanePositivity::Positive(_))
        ));
    }

    #[test]
    fn a_negative_value_is_a_witness() {
        // (x² + y² − 10)² − 1 is negative near the circle of radius √10 (off the grid)
        let r = &(&(&x() * &x()) + &(&y() * &y())) - &c(10, 1);
        let g = &(&r * &r) - &c(1, 1);
        match plane_positivity(&g).unwrap() {
            PlanePositivity::NotPositive { point, value } => {
                assert!(value <= Rational::zero());
                assert_eq!(g.eval(&point).unwrap(), value);
            }
            other => panic!("{other:?}"),
        }
        // odd degree
        let g = &(&x() * &(&x() * &x())) + &c(1000, 1);
        assert!(matches!(
            plane_positivity(&g),
            Ok(PlanePositivity::NotPositive { .. })
        ));
    }

    #[test]
    fn an_irrational_touching_zero_is_found_or_left_open() {
        // (x² − 2)² + y²: zero at (±√2, 0), seen on the line y = 0... as a fibre root
        let a = &(&x() * &x()) - &c(2, 1);
        let g = &(&a * &a) + &(&y() * &y());
        let r = plane_positivity(&g).unwrap();
        assert!(
            !matches!(r, PlanePositivity::Positive(_)),
            "a polynomial with a real zero was called positive: {r:?}"
        );
        // (x² − 2)² + (y² − 3)²: zero at (√2, √3)
        let b = &(&y() * &y()) - &c(3, 1);
        let g = &(&a * &a) + &(&b * &b);
        let r = plane_positivity(&g).unwrap();
        assert!(!matches!(r, PlanePositivity::Positive(_)), "{r:?}");
    }

    #[test]
    fn a_minimum_close_to_zero_is_excluded_by_interval_bounds() {
        // (x² − 2)² + (y² − 3)² + 2⁻⁴⁰: positive, the minima at (±√2, ±√3) are tiny
        let a = &(&x() * &x()) - &c(2, 1);
        let b = &(&y() * &y()) - &c(3, 1);
        let eps = MPoly::constant(2, pow2(-40));
        let g = &(&(&a * &a) + &(&b * &b)) + &eps;
        assert!(
            matches!(plane_positivity(&g), Ok(PlanePositivity::Positive(_))),
            "{:?}",
            plane_positivity(&g)
        );
    }

    #[test]
    fn univariate_and_constant_cases() {
        assert!(matches!(
            plane_positivity(&c(3, 1)),
            Ok(PlanePositivity::Positive(_))
        ));
        assert!(matches!(
            plane_positivity(&c(-3, 1)),
            Ok(PlanePositivity::NotPositive { .. })
        ));
        let g = &(&y() * &y()) + &c(1, 1000);
        assert!(matches!(
            plane_positivity(&g),
            Ok(PlanePositivity::Positive(_))
        ));
        let g = &(&y() * &y()) - &(&y() * &c(1, 1000));
        assert!(!matches!(
            plane_positivity(&g),
            Ok(PlanePositivity::Positive(_))
        ));
        let three = MPoly::var(3, 2);
        assert!(plane_positivity(&three).is_err());
    }
}
