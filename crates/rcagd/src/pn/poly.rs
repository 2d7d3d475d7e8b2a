//! Bivariate rational functions and the polynomial helpers of the PN module.
//!
//! PN surfaces are rational maps of the plane `(u, v)`; their coordinates are kept as
//! sparse polynomials ([`MPoly`], variable 0 = `u`, variable 1 = `v`) and turned into
//! tensor-product Bézier patches on a parameter rectangle only for export. The helpers
//! here (substitution, exact multivariate division, cancellation of known common
//! factors, Bernstein conversion of a polynomial on a rectangle, sign decisions by
//! Bernstein coefficients and subdivision) are not in `rcagd-algebra`/`rcagd-geom`; they
//! are private to this module (see the report to the lead).

use super::PnError;
use crate::error::format_scalar;
use rcagd_algebra::bernstein;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Rational, Scalar};
use rcagd_geom::certify;
use rcagd_geom::BezierPatch;

/// A rational function `num/den` of several variables (for PN surfaces: `u`, `v`).
#[derive(Debug, Clone)]
pub struct RatFn<F> {
    /// Numerator.
    pub num: MPoly<F>,
    /// Denominator (not the zero polynomial).
    pub den: MPoly<F>,
}

impl<F: Scalar> RatFn<F> {
    /// `num/den`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] if `den` is the zero polynomial.
    pub fn new(num: MPoly<F>, den: MPoly<F>) -> Result<Self, PnError> {
        if den.is_zero() {
            return Err(PnError::InvalidInput(
                "a rational function needs a non-zero denominator".into(),
            ));
        }
        Ok(RatFn { num, den })
    }

    /// The polynomial `p` as `p/1`.
    pub fn poly(p: MPoly<F>) -> Self {
        RatFn {
            num: p,
            den: MPoly::constant(2, F::one()),
        }
    }

    /// The constant `c`.
    pub fn constant(c: F) -> Self {
        Self::poly(MPoly::constant(2, c))
    }

    /// The value at `x` (`None` where the denominator vanishes or `x` has the wrong length).
    pub fn eval(&self, x: &[F]) -> Option<F> {
        let n = pad_eval(&self.num, x)?;
        let d = pad_eval(&self.den, x)?;
        let inv = d.inv()?;
        Some(n * inv)
    }

    /// `self + other`.
    pub fn add(&self, other: &Self) -> Self {
        RatFn {
            num: &(&self.num * &other.den) + &(&other.num * &self.den),
            den: &self.den * &other.den,
        }
    }

    /// `self − other`.
    pub fn sub(&self, other: &Self) -> Self {
        RatFn {
            num: &(&self.num * &other.den) - &(&other.num * &self.den),
            den: &self.den * &other.den,
        }
    }

    /// `self · other`.
    pub fn mul(&self, other: &Self) -> Self {
        RatFn {
            num: &self.num * &other.num,
            den: &self.den * &other.den,
        }
    }

    /// `c · self`.
    pub fn scale(&self, c: &F) -> Self {
        RatFn {
            num: self.num.scale(c),
            den: self.den.clone(),
        }
    }

    /// `∂/∂xᵢ` by the quotient rule.
    pub fn partial(&self, i: usize) -> Self {
        RatFn {
            num: &(&self.num.partial(i) * &self.den) - &(&self.num * &self.den.partial(i)),
            den: &self.den * &self.den,
        }
    }
}

/// Evaluates `p` at `x`, padding `x` with zeros or truncating it to `p`'s variables when
/// the extra variables do not occur.
pub(crate) fn pad_eval<F: Scalar>(p: &MPoly<F>, x: &[F]) -> Option<F> {
    let n = p.nvars();
    if x.len() >= n {
        return p.eval(&x[..n]).ok();
    }
    if p.terms().any(|(e, _)| e[x.len()..].iter().any(|&k| k != 0)) {
        return None;
    }
    let mut xs = x.to_vec();
    xs.resize(n, F::zero());
    p.eval(&xs).ok()
}

/// The constant `c` in the two variables `u`, `v`.
pub(crate) fn cst<F: Scalar>(c: F) -> MPoly<F> {
    MPoly::constant(2, c)
}

/// The integer `k` as a constant polynomial.
pub(crate) fn int<F: Scalar>(k: i64) -> MPoly<F> {
    MPoly::constant(2, F::from_i64(k))
}

/// The variable `xᵢ` (`u` = 0, `v` = 1) among two variables.
pub(crate) fn var<F: Scalar>(i: usize) -> MPoly<F> {
    MPoly::var(2, i)
}

/// The largest absolute coefficient (at least 1), for `f64` tolerances.
pub(crate) fn mag<F: Scalar>(p: &MPoly<F>) -> f64 {
    p.terms().map(|(_, c)| c.to_f64().abs()).fold(1.0, f64::max)
}

/// `a·b` for 3-vectors of polynomials.
pub(crate) fn dot3<F: Scalar>(a: &[MPoly<F>], b: &[MPoly<F>]) -> MPoly<F> {
    a.iter()
        .zip(b)
        .fold(MPoly::zero(2), |s, (x, y)| &s + &(x * y))
}

/// `a × b` for 3-vectors of polynomials.
pub(crate) fn cross3<F: Scalar>(a: &[MPoly<F>; 3], b: &[MPoly<F>; 3]) -> [MPoly<F>; 3] {
    [
        &(&a[1] * &b[2]) - &(&a[2] * &b[1]),
        &(&a[2] * &b[0]) - &(&a[0] * &b[2]),
        &(&a[0] * &b[1]) - &(&a[1] * &b[0]),
    ]
}

/// The determinant of a 3×3 matrix of polynomials (rows).
pub(crate) fn det3<F: Scalar>(m: [&[MPoly<F>; 3]; 3]) -> MPoly<F> {
    dot3(m[0], &cross3(m[1], m[2]))
}

/// The determinant of a 4×4 matrix of polynomials (rows). For exact scalars by Laplace's
/// expansion along the first two rows, `det = Σ_{k<l} (−1)^{k+l+1} A_{kl} B_{k'l'}` with
/// the 2×2 minors `A_{kl}` of rows 0, 1 and `B_{k'l'}` of rows 2, 3 on the complementary
/// columns (27 products at most instead of 40, fewer with zero entries; the same
/// polynomial), fraction-free in integers when the entries are rational polynomials in
/// `(u, v)` ([`rcagd_algebra::mpoly::det4_rational`]: one common denominator per row, one
/// reduction per result coefficient); for `f64` (whose rounding depends on the order)
/// along the first row.
pub(crate) fn det4<F: Scalar>(m: [&[MPoly<F>; 4]; 4]) -> MPoly<F> {
    if F::EXACT {
        if m.iter().flat_map(|r| r.iter()).all(|p| p.nvars() == 2) {
            let rows: [[&MPoly<F>; 4]; 4] =
                std::array::from_fn(|r| std::array::from_fn(|k| &m[r][k]));
            if let Some(d) = rcagd_algebra::mpoly::det4_rational(rows, F::to_rational) {
                return d.map(F::from_rational);
            }
        }
        return det4_by_two_rows(m);
    }
    det4_by_first_row(m)
}

/// `a·d − b·c`, skipping zero products.
fn minor2<F: Scalar>(a: &MPoly<F>, b: &MPoly<F>, c: &MPoly<F>, d: &MPoly<F>) -> MPoly<F> {
    let ad = if a.is_zero() || d.is_zero() {
        MPoly::zero(2)
    } else {
        a * d
    };
    if b.is_zero() || c.is_zero() {
        return ad;
    }
    &ad - &(b * c)
}

/// [`det4`] by Laplace's expansion along rows 0 and 1 (2×2 minors).
fn det4_by_two_rows<F: Scalar>(m: [&[MPoly<F>; 4]; 4]) -> MPoly<F> {
    let mut acc = MPoly::zero(2);
    for ([k, l, kk, ll], plus) in rcagd_algebra::mpoly::LAPLACE_PAIRS_4 {
        let a = minor2(&m[0][k], &m[0][l], &m[1][k], &m[1][l]);
        if a.is_zero() {
            continue;
        }
        let b = minor2(&m[2][kk], &m[2][ll], &m[3][kk], &m[3][ll]);
        if b.is_zero() {
            continue;
        }
        let t = &a * &b;
        if plus {
            acc += &t;
        } else {
            acc -= &t;
        }
    }
    acc
}

/// [`det4`] by Laplace's expansion along the first row.
fn det4_by_first_row<F: Scalar>(m: [&[MPoly<F>; 4]; 4]) -> MPoly<F> {
    let mut acc = MPoly::zero(2);
    for c in 0..4 {
        if m[0][c].is_zero() {
            continue;
        }
        let minor: Vec<[MPoly<F>; 3]> = (1..4)
            .map(|r| {
                let cols: Vec<MPoly<F>> = (0..4)
                    .filter(|&k| k != c)
                    .map(|k| m[r][k].clone())
                    .collect();
                [cols[0].clone(), cols[1].clone(), cols[2].clone()]
            })
            .collect();
        let d = det3([&minor[0], &minor[1], &minor[2]]);
        let t = &m[0][c] * &d;
        acc = if c % 2 == 0 { &acc + &t } else { &acc - &t };
    }
    acc
}

/// The substitution `p(q₀, …, q_{n−1})` (`qs.len() ≥ nvars(p)`; the zero polynomial if a
/// variable without substitute occurs), by Horner's rule in `q₀` whose coefficients are
/// evaluated by Horner's rule in `q₁`, and so on: `p = Σₖ q₀ᵏ pₖ(q₁, …)` is
/// `(…(p_K q₀^{K−K'} + p_{K'}) q₀^{K'−K''} + …)`, so only products by powers of the
/// (small) substitutes occur, never products of two large powers.
pub(crate) fn compose<F: Scalar>(p: &MPoly<F>, qs: &[MPoly<F>]) -> MPoly<F> {
    let nv = qs.first().map_or(2, |q| q.nvars()).max(2);
    let terms: Vec<(&[u32], &F)> = p.terms().collect();
    let missing = terms
        .iter()
        .any(|(e, _)| e.iter().enumerate().any(|(i, &k)| k != 0 && i >= qs.len()));
    if missing {
        return MPoly::zero(2);
    }
    horner(&terms, 0, qs, nv)
}

/// Terms `(exponent vector, coefficient)` of a polynomial, borrowed.
type Terms<'a, F> = [(&'a [u32], &'a F)];

/// `Σ c ∏_{i ≥ var} qᵢ^{eᵢ}` over `terms` (lexicographically ascending exponent vectors
/// that agree below `var`), by Horner's rule in `q_var` (see [`compose`]).
fn horner<F: Scalar>(terms: &Terms<'_, F>, var: usize, qs: &[MPoly<F>], nv: usize) -> MPoly<F> {
    let exp = |e: &[u32]| e.get(var).copied().unwrap_or(0);
    if terms
        .iter()
        .all(|(e, _)| e.iter().skip(var).all(|&k| k == 0))
    {
        // no further variable occurs: the sum of the coefficients
        let c = terms
            .iter()
            .fold(F::zero(), |acc, (_, c)| acc + (*c).clone());
        return MPoly::constant(nv, c);
    }
    // `compose` checked that every occurring variable has its substitute
    let Some(q) = qs.get(var) else {
        return MPoly::zero(nv);
    };
    if terms.iter().all(|(e, _)| exp(e) == 0) {
        return horner(terms, var + 1, qs, nv);
    }
    // the terms grouped by their exponent of x_var (contiguous in lexicographic order)
    let mut groups: Vec<(u32, &Terms<'_, F>)> = Vec::new();
    let mut start = 0;
    for i in 1..=terms.len() {
        if i == terms.len() || exp(terms[i].0) != exp(terms[start].0) {
            groups.push((exp(terms[start].0), &terms[start..i]));
            start = i;
        }
    }
    let mut acc = MPoly::zero(nv);
    let mut prev: Option<u32> = None;
    for (k, g) in groups.iter().rev() {
        if let Some(pk) = prev {
            acc = &acc * &q.pow(pk - k);
        }
        acc += horner(g, var + 1, qs, nv);
        prev = Some(*k);
    }
    match prev {
        Some(k) if k > 0 => &acc * &q.pow(k),
        _ => acc,
    }
}

/// The exact quotient `p/d` if `d` divides `p` (lexicographic division; over `f64` a
/// remainder below `10⁻⁹` of the coefficients counts as zero). `None` if `d` does not
/// divide `p` or `d` is zero.
pub(crate) fn div_exact<F: Scalar>(p: &MPoly<F>, d: &MPoly<F>) -> Option<MPoly<F>> {
    if F::EXACT {
        // rational coefficients: the fraction-free division of the library (the same
        // quotient)
        if let (Some(pq), Some(dq)) = (rational_mpoly(p), rational_mpoly(d)) {
            let q = rcagd_algebra::mpoly::div_exact_rational(&pq, &dq, 2)?;
            return Some(q.map(F::from_rational));
        }
    }
    let nv = p.nvars().max(d.nvars()).max(2);
    let (lde, ldc) = d.terms().last().map(|(e, c)| (pad(e, nv), c.clone()))?;
    if p.is_zero() {
        return Some(MPoly::zero(nv));
    }
    let tol = if F::EXACT {
        0.0
    } else {
        1e-12 * mag(p) * mag(d)
    };
    let mut r = p.clone();
    let mut q = MPoly::zero(nv);
    let mut guard = 0usize;
    while let Some((le, lc)) = r.terms().last().map(|(e, c)| (pad(e, nv), c.clone())) {
        guard += 1;
        if guard > 1_000_000 {
            return None;
        }
        if !F::EXACT && lc.to_f64().abs() <= tol {
            r = &r - &MPoly::monomial(nv, &le, lc);
            continue;
        }
        if le.iter().zip(&lde).any(|(a, b)| a < b) {
            return None;
        }
        let e: Vec<u32> = le.iter().zip(&lde).map(|(a, b)| a - b).collect();
        let t = MPoly::monomial(nv, &e, lc / ldc.clone());
        r -= &t * d;
        q += t;
    }
    Some(q)
}

/// `p` with its coefficients in `ℚ` (`None` if one is not rational).
fn rational_mpoly<F: Scalar>(p: &MPoly<F>) -> Option<MPoly<Rational>> {
    let terms = p
        .terms()
        .map(|(e, c)| Some((e.to_vec(), c.to_rational()?)))
        .collect::<Option<Vec<_>>>()?;
    MPoly::from_terms(p.nvars(), terms).ok()
}

fn pad(e: &[u32], n: usize) -> Vec<u32> {
    let mut v = e.to_vec();
    v.resize(n.max(e.len()), 0);
    v
}

/// Divides every polynomial of `polys` by each candidate factor as often as the candidate
/// divides all of them (constants and zero candidates are skipped). Returns how many
/// divisions were made.
pub(crate) fn cancel_common<F: Scalar>(polys: &mut [MPoly<F>], candidates: &[MPoly<F>]) -> usize {
    let mut count = 0;
    for c in candidates {
        if c.total_degree().unwrap_or(0) == 0 {
            continue;
        }
        loop {
            let Some(qs) = polys
                .iter()
                .map(|p| div_exact(p, c))
                .collect::<Option<Vec<_>>>()
            else {
                break;
            };
            if qs.iter().all(|q| q.is_zero()) {
                break;
            }
            polys.clone_from_slice(&qs);
            count += 1;
        }
    }
    count
}

/// The greatest common divisor of two rationals (`gcd(p/q, r/s)` with Euclid on the
/// rationals themselves; exact).
fn rational_gcd<F: Scalar>(a: &F, b: &F) -> F {
    let (mut a, mut b) = (a.abs(), b.abs());
    let mut guard = 0;
    while !b.is_zero() && guard < 10_000 {
        guard += 1;
        let (Some(qa), Some(qb)) = (a.to_rational(), b.to_rational()) else {
            return F::one();
        };
        let quot = qa / qb.clone();
        let fl = rcagd_algebra::Rational::from(quot.floor());
        let r = a.clone() - F::from_rational(&fl) * b.clone();
        a = b;
        b = r;
    }
    a
}

/// Scales the polynomials by one common non-zero rational so that (for exact scalars) all
/// coefficients become integers without a common factor, the sign chosen to make the
/// first polynomial's last (lexicographically largest) coefficient positive. No-op for
/// `f64` and for all-zero input.
pub(crate) fn normalize_content<F: Scalar>(polys: &mut [MPoly<F>]) {
    if !F::EXACT {
        return;
    }
    // rational coefficients: gcd of the numerators over the lcm of the denominators
    // (`rcagd_algebra::mpoly::content_rational`, the number Euclid's algorithm on the
    // rationals gives)
    let exact: Option<Vec<Rational>> = polys
        .iter()
        .flat_map(|p| p.terms().map(|(_, c)| c.to_rational()))
        .collect();
    let g: Option<F> = match exact {
        Some(qs) if !qs.is_empty() => Some(F::from_rational(
            &rcagd_algebra::mpoly::content_rational(qs.iter()),
        )),
        Some(_) => None,
        None => {
            let mut g: Option<F> = None;
            for p in polys.iter() {
                for (_, c) in p.terms() {
                    g = Some(match g {
                        None => c.abs(),
                        Some(g) => rational_gcd(&g, c),
                    });
                }
            }
            g
        }
    };
    let Some(g) = g else { return };
    if g.is_zero() {
        return;
    }
    let sign = polys
        .iter()
        .find_map(|p| p.terms().last().map(|(_, c)| c.clone()))
        .map_or(
            F::one(),
            |c| if c < F::zero() { -F::one() } else { F::one() },
        );
    let f = sign / g;
    for p in polys.iter_mut() {
        *p = p.scale(&f);
    }
}

/// A parameter rectangle `[u₀, u₁] × [v₀, v₁]` (`u₀ < u₁`, `v₀ < v₁`).
#[derive(Debug, Clone, PartialEq)]
pub struct Domain<F> {
    /// `[u₀, u₁]`.
    pub u: (F, F),
    /// `[v₀, v₁]`.
    pub v: (F, F),
}

impl<F: Scalar> Domain<F> {
    /// The rectangle `[u₀, u₁] × [v₀, v₁]`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] unless `u₀ < u₁` and `v₀ < v₁`.
    pub fn new(u0: F, u1: F, v0: F, v1: F) -> Result<Self, PnError> {
        if !(u0 < u1 && v0 < v1) {
            return Err(PnError::InvalidInput(format!(
                "a parameter rectangle needs u0 < u1 and v0 < v1, got [{}, {}] × [{}, {}]",
                format_scalar(&u0),
                format_scalar(&u1),
                format_scalar(&v0),
                format_scalar(&v1)
            )));
        }
        Ok(Domain {
            u: (u0, u1),
            v: (v0, v1),
        })
    }

    /// `[0, 1]²`.
    pub fn unit() -> Self {
        Domain {
            u: (F::zero(), F::one()),
            v: (F::zero(), F::one()),
        }
    }

    /// The point `(u₀ + s(u₁ − u₀), v₀ + t(v₁ − v₀))` of local coordinates `(s, t) ∈ [0,1]²`.
    pub fn point(&self, s: &F, t: &F) -> [F; 2] {
        [
            self.u.0.clone() + s.clone() * (self.u.1.clone() - self.u.0.clone()),
            self.v.0.clone() + t.clone() * (self.v.1.clone() - self.v.0.clone()),
        ]
    }

    fn quarters(&self) -> [Domain<F>; 4] {
        let two = F::from_i64(2);
        let um = (self.u.0.clone() + self.u.1.clone()) / two.clone();
        let vm = (self.v.0.clone() + self.v.1.clone()) / two;
        [
            Domain {
                u: (self.u.0.clone(), um.clone()),
                v: (self.v.0.clone(), vm.clone()),
            },
            Domain {
                u: (um.clone(), self.u.1.clone()),
                v: (self.v.0.clone(), vm.clone()),
            },
            Domain {
                u: (self.u.0.clone(), um.clone()),
                v: (vm.clone(), self.v.1.clone()),
            },
            Domain {
                u: (um, self.u.1.clone()),
                v: (vm, self.v.1.clone()),
            },
        ]
    }

    fn corners(&self) -> [[F; 2]; 4] {
        [
            [self.u.0.clone(), self.v.0.clone()],
            [self.u.1.clone(), self.v.0.clone()],
            [self.u.0.clone(), self.v.1.clone()],
            [self.u.1.clone(), self.v.1.clone()],
        ]
    }
}

/// `p(u₀ + s Δu, v₀ + t Δv)` as a polynomial in the local coordinates `(s, t)`.
pub(crate) fn to_local<F: Scalar>(p: &MPoly<F>, d: &Domain<F>) -> MPoly<F> {
    if let Some(q) = affine_shift_2(p, d) {
        return q;
    }
    let su = &cst(d.u.0.clone()) + &var::<F>(0).scale(&(d.u.1.clone() - d.u.0.clone()));
    let sv = &cst(d.v.0.clone()) + &var::<F>(1).scale(&(d.v.1.clone() - d.v.0.clone()));
    compose(p, &[su, sv])
}

/// `Σᵢ cᵢ xⁱ ↦ Σᵢ cᵢ (a + h x)ⁱ` in place: Horner's shift by `a`, then `cᵢ ← hⁱ cᵢ`.
fn taylor_shift<F: Scalar>(c: &mut [F], a: &F, h: &F) {
    let deg = c.len().saturating_sub(1);
    for k in 0..deg {
        rcagd_algebra::budget::checkpoint();
        for i in (k..deg).rev() {
            let next = c[i + 1].clone();
            c[i] = c[i].clone() + a.clone() * next;
        }
    }
    let mut hp = F::one();
    for x in c.iter_mut() {
        *x = x.clone() * hp.clone();
        hp *= h.clone();
    }
}

/// `p(P₀ + s·(e₁ + t·e₂))` as a polynomial in `(s, t)`, for `p` in `u, v` only (`None`
/// otherwise: the caller composes). The same polynomial as [`compose`] with the map
/// `(s, t) ↦ P₀ + s e₁ + st e₂` (the collapse map of a triangle), computed as: the Taylor
/// shift `S(x, y) = p(P₀ + (x, y))` ([`shifted_dense`]), then for each homogeneous part
/// `S_k(x, y) = Σᵢ cᵢ xⁱ yᵏ⁻ⁱ` of `S` the univariate `h_k(t) = S_k(ℓ_x(t), ℓ_y(t))` with the
/// linear `ℓ = e₁ + t e₂` by Horner's rule in `ℓ_x` (`acc ← acc·ℓ_x + cᵢ ℓ_yᵏ⁻ⁱ`), so that
/// `p(P₀ + s ℓ(t)) = Σ_k sᵏ h_k(t)`: `O(d³)` scalar operations for total degree `d`, no
/// products of bivariate polynomials.
pub(crate) fn compose_fan<F: Scalar>(
    p: &MPoly<F>,
    p0: &[F; 2],
    e1: &[F; 2],
    e2: &[F; 2],
) -> Option<MPoly<F>> {
    if F::EXACT {
        // rational data: fraction-free in the library (the same polynomial)
        let r = |x: &[F; 2]| Some([x[0].to_rational()?, x[1].to_rational()?]);
        if let (Some(pq), Some(a), Some(b), Some(c)) = (rational_mpoly(p), r(p0), r(e1), r(e2)) {
            let out = rcagd_algebra::mpoly::compose_fan_rational(&pq, &a, &b, &c)?;
            return Some(out.map(F::from_rational));
        }
    }
    let c = shifted_dense(p, (&p0[0], &F::one()), (&p0[1], &F::one()))?;
    let m = c.len().saturating_sub(1);
    let n = c.first().map_or(0, |r| r.len().saturating_sub(1));
    // ℓ_y(t)ʲ, j ≤ n (constant term first)
    let ly = [e1[1].clone(), e2[1].clone()];
    let mut ly_pow: Vec<Vec<F>> = vec![vec![F::one()]];
    for j in 1..=n {
        let prev = &ly_pow[j - 1];
        let mut next = vec![F::zero(); j + 1];
        for (k, x) in prev.iter().enumerate() {
            next[k] += x.clone() * ly[0].clone();
            next[k + 1] += x.clone() * ly[1].clone();
        }
        ly_pow.push(next);
    }
    let lx = [e1[0].clone(), e2[0].clone()];
    let mut terms: Vec<(Vec<u32>, F)> = Vec::new();
    for k in 0..=m + n {
        rcagd_algebra::budget::checkpoint();
        // i from min(k, m) down to max(0, k − n): acc ← acc·ℓ_x + c_{i, k−i} ℓ_y^{k−i}
        let hi = k.min(m);
        let lo = k.saturating_sub(n);
        let mut acc: Vec<F> = Vec::new();
        for i in (lo..=hi).rev() {
            if !acc.is_empty() {
                let mut next = vec![F::zero(); acc.len() + 1];
                for (q, x) in acc.iter().enumerate() {
                    if x.is_zero() {
                        continue;
                    }
                    next[q] += x.clone() * lx[0].clone();
                    next[q + 1] += x.clone() * lx[1].clone();
                }
                acc = next;
            }
            let cij = &c[i][k - i];
            if !cij.is_zero() {
                let pw = &ly_pow[k - i];
                if acc.len() < pw.len() {
                    acc.resize(pw.len(), F::zero());
                }
                for (q, y) in pw.iter().enumerate() {
                    acc[q] += cij.clone() * y.clone();
                }
            }
        }
        // multiply by ℓ_x^lo (the parts with i < lo do not exist)
        for _ in 0..lo {
            if acc.is_empty() {
                break;
            }
            let mut next = vec![F::zero(); acc.len() + 1];
            for (q, x) in acc.iter().enumerate() {
                next[q] += x.clone() * lx[0].clone();
                next[q + 1] += x.clone() * lx[1].clone();
            }
            acc = next;
        }
        for (q, x) in acc.into_iter().enumerate() {
            if !x.is_zero() {
                terms.push((vec![k as u32, q as u32], x));
            }
        }
    }
    MPoly::from_terms(2, terms).ok()
}

/// The dense coefficients `c[i][j]` of `p(a_u + h_u x, a_v + h_v y)` for `p` in `u, v`
/// only (`None` otherwise), by the Taylor shifts of [`affine_shift_2`].
fn shifted_dense<F: Scalar>(p: &MPoly<F>, u: (&F, &F), v: (&F, &F)) -> Option<Vec<Vec<F>>> {
    if p.nvars() != 2 {
        return None;
    }
    let m = p.degree_in(0).unwrap_or(0) as usize;
    let n = p.degree_in(1).unwrap_or(0) as usize;
    let mut c = vec![vec![F::zero(); n + 1]; m + 1];
    for (e, x) in p.terms() {
        c[e[0] as usize][e[1] as usize] = x.clone();
    }
    for j in 0..=n {
        let mut col: Vec<F> = c.iter().map(|row| row[j].clone()).collect();
        taylor_shift(&mut col, u.0, u.1);
        for (row, x) in c.iter_mut().zip(col) {
            row[j] = x;
        }
    }
    for row in c.iter_mut() {
        taylor_shift(row, v.0, v.1);
    }
    Some(c)
}

/// [`to_local`] for a polynomial in `u, v` only, by Taylor shifts: each column
/// `Σᵢ cᵢ uⁱ` becomes `Σᵢ cᵢ (a + h s)ⁱ` by the Horner shift `cᵢ += a·cᵢ₊₁` (descending,
/// `O(m²)` operations) and the scaling `cᵢ ← hⁱ cᵢ`, then the same for the rows in `v`.
/// The general composition multiplies powers of `a + h s` as polynomials, far slower for
/// big coefficients. `None` for other variables (the caller composes).
fn affine_shift_2<F: Scalar>(p: &MPoly<F>, d: &Domain<F>) -> Option<MPoly<F>> {
    let (hu, hv) = (d.u.1.clone() - d.u.0.clone(), d.v.1.clone() - d.v.0.clone());
    let c = shifted_dense(p, (&d.u.0, &hu), (&d.v.0, &hv))?;
    let terms = c
        .into_iter()
        .enumerate()
        .flat_map(|(i, row)| {
            row.into_iter()
                .enumerate()
                .filter(|(_, x)| !x.is_zero())
                .map(move |(j, x)| (vec![i as u32, j as u32], x))
        })
        .collect();
    MPoly::from_terms(2, terms).ok()
}

/// `(deg_u, deg_v)` of a polynomial in `u, v` (0 for the zero polynomial).
pub(crate) fn bidegree<F: Scalar>(p: &MPoly<F>) -> (usize, usize) {
    (
        p.degree_in(0).unwrap_or(0) as usize,
        p.degree_in(1).unwrap_or(0) as usize,
    )
}

/// The tensor Bernstein coefficients (row-major in `s`) of bidegree `(m, n)` of a
/// polynomial in `(s, t)`.
pub(crate) fn tensor_bernstein<F: Scalar>(
    p: &MPoly<F>,
    m: usize,
    n: usize,
) -> Result<Vec<F>, PnError> {
    let mut power = vec![F::zero(); (m + 1) * (n + 1)];
    for (e, c) in p.terms() {
        let i = e.first().copied().unwrap_or(0) as usize;
        let j = e.get(1).copied().unwrap_or(0) as usize;
        if i > m || j > n || e.iter().skip(2).any(|&k| k != 0) {
            return Err(PnError::InvalidInput(format!(
                "polynomial term of bidegree ({i}, {j}) exceeds ({m}, {n})"
            )));
        }
        power[i * (n + 1) + j] = c.clone();
    }
    let mut rows = Vec::with_capacity((m + 1) * (n + 1));
    for row in power.chunks(n + 1) {
        rows.extend(bernstein::to_bernstein_blocks(row, 1, n)?);
    }
    Ok(bernstein::to_bernstein_blocks(&rows, n + 1, m)?)
}

/// The rational tensor-product Bézier patch of the homogeneous polynomial map
/// `(W, X₁, …, X_d)(u, v)` on the rectangle `domain` (local parameters `(s, t) ∈ [0,1]²`);
/// its bidegree is the largest bidegree of the coordinates.
pub(crate) fn patch_of<F: Scalar>(
    coords: &[MPoly<F>],
    domain: &Domain<F>,
) -> Result<BezierPatch<F>, PnError> {
    let (m, n, bern) = match exact_bernstein_on(coords, domain) {
        Some(b) => b,
        None => {
            let local: Vec<MPoly<F>> = coords.iter().map(|p| to_local(p, domain)).collect();
            let (m, n) = local
                .iter()
                .map(bidegree)
                .fold((0, 0), |(a, b), (c, d)| (a.max(c), b.max(d)));
            let bern: Vec<Vec<F>> = local
                .iter()
                .map(|p| tensor_bernstein(p, m, n))
                .collect::<Result<_, _>>()?;
            (m, n, bern)
        }
    };
    let dim = coords.len().saturating_sub(1);
    let mut flat = Vec::with_capacity((m + 1) * (n + 1) * (dim + 1));
    for k in 0..(m + 1) * (n + 1) {
        for b in &bern {
            flat.push(b[k].clone());
        }
    }
    Ok(BezierPatch::from_flat(dim, m, n, flat)?)
}

/// For exact scalars and polynomials in `(u, v)`: the tensor Bernstein coefficients of
/// bidegree `(m, n)` (the largest bidegree of the coordinates) of every coordinate on the
/// rectangle, computed fraction-free from the power coefficients and the rectangle's
/// shifts ([`bernstein::tensor_bernstein_exact`]: integer Taylor shifts and conversions,
/// one reduction per coefficient) — the same coefficients as [`to_local`] followed by
/// [`tensor_bernstein`] (an affine substitution with `Δu, Δv ≠ 0` keeps the bidegree).
/// `None` for `f64`, a degenerate rectangle or a polynomial in other variables.
fn exact_bernstein_on<F: Scalar>(
    coords: &[MPoly<F>],
    domain: &Domain<F>,
) -> Option<(usize, usize, Vec<Vec<F>>)> {
    if !F::EXACT {
        return None;
    }
    let (u0, v0) = (domain.u.0.to_rational()?, domain.v.0.to_rational()?);
    let du = domain.u.1.to_rational()? - u0.clone();
    let dv = domain.v.1.to_rational()? - v0.clone();
    if du == Rational::ZERO || dv == Rational::ZERO {
        return None;
    }
    let (m, n) = coords
        .iter()
        .map(bidegree)
        .fold((0, 0), |(a, b), (c, d)| (a.max(c), b.max(d)));
    let bern = coords
        .iter()
        .map(|p| {
            let mut power = vec![Rational::ZERO; (m + 1) * (n + 1)];
            for (e, c) in p.terms() {
                if e.iter().skip(2).any(|&k| k != 0) {
                    return None;
                }
                let i = e.first().copied().unwrap_or(0) as usize;
                let j = e.get(1).copied().unwrap_or(0) as usize;
                *power.get_mut(i * (n + 1) + j)? = c.to_rational()?;
            }
            let b =
                bernstein::tensor_bernstein_exact(&power, (m, n), (&u0, &du), (&v0, &dv)).ok()?;
            Some(b.iter().map(F::from_rational).collect())
        })
        .collect::<Option<Vec<Vec<F>>>>()?;
    Some((m, n, bern))
}

/// The verdict of [`sign_on_domain`].
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Sign<F> {
    /// Strictly positive on the closed rectangle (Bernstein coefficients of every piece
    /// positive).
    Positive,
    /// Strictly negative on the closed rectangle.
    Negative,
    /// The polynomial vanishes at this (exact) point.
    ZeroAt([F; 2]),
    /// The polynomial takes opposite signs at these two points (so it vanishes between).
    Changes([F; 2], [F; 2]),
    /// Not decided within the subdivision budget; the polynomial may vanish near here.
    Undecided([F; 2]),
}

/// Decides whether `p` vanishes on the closed rectangle, by Bernstein coefficients and
/// subdivision (at most `budget` pieces): exact for exact scalars, with the relative
/// tolerance `10⁻⁹` for `f64` and `10⁻⁹` times the precision ratio for wider inexact
/// scalars (`rcagd_algebra::scalar::precision_ratio`: about `10⁻²⁵` in double-double,
/// which then decides a weight of `10⁻¹⁰` of its size as the exact signs do).
pub(crate) fn sign_on_domain<F: Scalar>(
    p: &MPoly<F>,
    domain: &Domain<F>,
    budget: usize,
) -> Sign<F> {
    let scale = mag(p);
    let tol = if F::EXACT {
        0.0
    } else {
        1e-9 * rcagd_algebra::scalar::precision_ratio::<F>() * scale
    };
    let is_pos = |x: &F| x.to_f64() > tol && (!F::EXACT || *x > F::zero());
    let is_neg = |x: &F| x.to_f64() < -tol && (!F::EXACT || *x < F::zero());
    // exact scalars in `u, v` only: the power coefficients in `ℚ` (row-major in `u`) and
    // the bidegree, for the fraction-free Bernstein signs
    let exact = F::EXACT.then(|| exact_power_coefficients(p)).flatten();
    // exact corner signs from the integer form (no rational evaluation)
    let signs = exact
        .as_ref()
        .and_then(|(power, (m, n))| rcagd_algebra::mpoly::BivariateSigns::new(power, *m, *n));
    let corner_value = |c: &[F; 2]| -> F {
        if let (Some(sg), Some(u), Some(v)) = (&signs, c[0].to_rational(), c[1].to_rational()) {
            return match sg.sign_at(&u, &v) {
                core::cmp::Ordering::Greater => F::one(),
                core::cmp::Ordering::Less => -F::one(),
                core::cmp::Ordering::Equal => F::zero(),
            };
        }
        pad_eval(p, c).unwrap_or_else(F::zero)
    };
    let mut stack = vec![domain.clone()];
    let mut pos: Option<[F; 2]> = None;
    let mut neg: Option<[F; 2]> = None;
    let mut processed = 0usize;
    while let Some(d) = stack.pop() {
        processed += 1;
        // corner values first: an exact zero or a sign change is a witness
        for c in d.corners() {
            let val = corner_value(&c);
            if !is_pos(&val) && !is_neg(&val) {
                return Sign::ZeroAt(c);
            }
            if is_pos(&val) {
                pos.get_or_insert(c);
            } else {
                neg.get_or_insert(c);
            }
            if let (Some(a), Some(b)) = (&pos, &neg) {
                return Sign::Changes(a.clone(), b.clone());
            }
        }
        let decided = match &exact {
            // exact: the signs of positive multiples of the Bernstein coefficients,
            // fraction-free (`rcagd_algebra::bernstein::tensor_bernstein_sign`)
            Some((power, mn)) => {
                let q = |x: &F| x.to_rational().unwrap_or_default();
                let (u0, v0) = (q(&d.u.0), q(&d.v.0));
                let (du, dv) = (q(&d.u.1) - u0.clone(), q(&d.v.1) - v0.clone());
                let Ok(sign) = bernstein::tensor_bernstein_sign(power, *mn, (&u0, &du), (&v0, &dv))
                else {
                    return Sign::Undecided(d.point(&F::from_ratio(1, 2), &F::from_ratio(1, 2)));
                };
                sign.is_some()
            }
            None => {
                let local = to_local(p, &d);
                let (m, n) = bidegree(&local);
                let Ok(b) = tensor_bernstein(&local, m, n) else {
                    return Sign::Undecided(d.point(&F::from_ratio(1, 2), &F::from_ratio(1, 2)));
                };
                b.iter().all(is_pos) || b.iter().all(is_neg)
            }
        };
        if decided {
            continue;
        }
        if processed + stack.len() + 4 > budget {
            return Sign::Undecided(d.point(&F::from_ratio(1, 2), &F::from_ratio(1, 2)));
        }
        stack.extend(d.quarters());
    }
    if neg.is_some() {
        Sign::Negative
    } else {
        Sign::Positive
    }
}

/// The power coefficients in `ℚ` of a polynomial in `u, v` only (row-major in `u`, the
/// bidegree's `(m + 1)(n + 1)` entries) and its bidegree; `None` if another variable occurs
/// or a coefficient is not rational.
fn exact_power_coefficients<F: Scalar>(
    p: &MPoly<F>,
) -> Option<(Vec<rcagd_algebra::Rational>, (usize, usize))> {
    let (m, n) = bidegree(p);
    let mut power = vec![rcagd_algebra::Rational::ZERO; (m + 1) * (n + 1)];
    for (e, c) in p.terms() {
        if e.iter().skip(2).any(|&k| k != 0) {
            return None;
        }
        let i = e.first().copied().unwrap_or(0) as usize;
        let j = e.get(1).copied().unwrap_or(0) as usize;
        *power.get_mut(i * (n + 1) + j)? = c.to_rational()?;
    }
    Some((power, (m, n)))
}

/// The certificate `p ≡ 0` (every coefficient zero; for `f64` below `10⁻⁹ · scale`).
pub(crate) fn zero_cert<F: Scalar>(property: &str, p: &MPoly<F>, scale: f64) -> Certificate {
    let coeffs: Vec<F> = p.terms().map(|(_, c)| c.clone()).collect();
    certify::polynomial_is_zero_scaled(property, &coeffs, scale)
}

/// The entrywise absolute values of `p` in `f64`: the magnitude polynomial of `p` for
/// [`identity_cert_within`] (products and sums of magnitude polynomials bound the terms
/// that make up each coefficient of the corresponding products and sums).
pub(crate) fn abs_mpoly<F: Scalar>(p: &MPoly<F>) -> MPoly<f64> {
    p.map(|c| c.to_f64().abs())
}

/// The certificate `lhs ≡ rhs`; for `f64` the coefficient of each monomial of the residual
/// is compared with `10⁻⁹ ·` that monomial's coefficient in `magnitude` (a bound of the
/// sum of the absolute values of the terms that make it up, built by [`abs_mpoly`] and
/// the same products and sums), not with the largest coefficient: cancellation in a
/// coefficient does not make its rounding residue look large. Exact scalars need the
/// residual to vanish.
pub(crate) fn identity_cert_within<F: Scalar>(
    property: &str,
    lhs: &MPoly<F>,
    rhs: &MPoly<F>,
    magnitude: &MPoly<f64>,
) -> Certificate {
    let diff = lhs - rhs;
    if F::EXACT {
        return zero_cert(property, &diff, 1.0);
    }
    let tol = crate::certs::TOL;
    let worst = diff
        .terms()
        .map(|(e, c)| {
            let v = c.to_f64().abs();
            let m = magnitude.coeff(e).max(f64::MIN_POSITIVE);
            (v / m, v, m, e.to_vec())
        })
        .fold(None::<(f64, f64, f64, Vec<u32>)>, |best, x| match best {
            Some(b) if !(x.0 > b.0 || x.0.is_nan()) => Some(b),
            _ => Some(x),
        });
    let ok = match &worst {
        None => true,
        Some((r, v, _, _)) => v.is_finite() && *r <= tol,
    };
    Certificate::decide(property, ok, false, || {
        match &worst {
        Some((_, v, m, e)) => format!(
            "residual coefficient {v:e} of the monomial with exponents {e:?} exceeds {tol:e} × the magnitude {m:e} of its terms"
        ),
        None => String::new(),
    }
    })
}

/// For exact scalars: whether `Σₖ ±∏ⱼ f_{kj} ≡ 0` holds, decided fraction-free in
/// integers ([`rcagd_algebra::mpoly::sum_of_products_is_zero`]; the same decision as
/// expanding the products over `ℚ`). `None` for `f64` or when the integer form does not
/// apply; callers then expand over the scalars (which also formats the residual).
pub(crate) fn exact_identity_holds<F: Scalar>(terms: &[(bool, &[&MPoly<F>])]) -> Option<bool> {
    if !F::EXACT {
        return None;
    }
    rcagd_algebra::mpoly::sum_of_products_is_zero(terms, F::to_rational)
}

/// The certificate of an exact identity that [`exact_identity_holds`] proved (`None`
/// unless proved: a failing identity is expanded by the caller for its residual).
pub(crate) fn proved<F: Scalar>(
    property: &str,
    terms: &[(bool, &[&MPoly<F>])],
) -> Option<Certificate> {
    (exact_identity_holds(terms) == Some(true)).then(|| Certificate::holds(property, true))
}

/// The certificate `lhs ≡ rhs`.
pub(crate) fn identity_cert<F: Scalar>(
    property: &str,
    lhs: &MPoly<F>,
    rhs: &MPoly<F>,
) -> Certificate {
    let scale = 16.0 * (mag(lhs) + mag(rhs)) * (1 + lhs.num_terms() + rhs.num_terms()) as f64;
    zero_cert(property, &(lhs - rhs), scale)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    type Q = Rational;

    fn q(p: i64, d: i64) -> Q {
        Q::from_ratio(p, d)
    }

    fn u() -> MPoly<Q> {
        var(0)
    }
    fn v() -> MPoly<Q> {
        var(1)
    }

    /// The substitution by its definition, `Σ c ∏ qᵢ^{eᵢ}` (the reference for the Horner
    /// scheme of [`compose`]).
    fn compose_by_definition(p: &MPoly<Q>, qs: &[MPoly<Q>]) -> MPoly<Q> {
        let mut acc = MPoly::zero(2);
        for (e, c) in p.terms() {
            let mut t = MPoly::constant(2, c.clone());
            for (i, &k) in e.iter().enumerate() {
                t = &t * &qs[i].pow(k);
            }
            acc = &acc + &t;
        }
        acc
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(32))]
        /// Horner's `compose` equals the substitution term by term, for random bivariate
        /// polynomials and random substitutes of degree ≤ 2 (in two variables).
        #[test]
        fn compose_by_horner_equals_the_definition(
            tp in proptest::collection::vec((0u32..5, 0u32..5, -9i64..10, 1i64..7), 0..10),
            tq in proptest::collection::vec((0u32..3, 0u32..3, -5i64..6, 1i64..5), 0..8),
            tr in proptest::collection::vec((0u32..3, 0u32..3, -5i64..6, 1i64..5), 0..8),
        ) {
            let mk = |t: &Vec<(u32, u32, i64, i64)>| {
                MPoly::from_terms(2, t.iter().map(|(a, b, n, d)| (vec![*a, *b], q(*n, *d))).collect())
                    .expect("two exponents")
            };
            let (p, qu, qv) = (mk(&tp), mk(&tq), mk(&tr));
            let qs = [qu, qv];
            proptest::prop_assert_eq!(compose(&p, &qs), compose_by_definition(&p, &qs));
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(32))]
        /// `compose_fan` equals the composition with the collapse map
        /// `(s, t) ↦ P₀ + s e₁ + st e₂`, for random polynomials and points (zero
        /// components included).
        #[test]
        fn compose_fan_equals_the_composition_with_the_collapse_map(
            tp in proptest::collection::vec((0u32..6, 0u32..5, -9i64..10, 1i64..7), 0..12),
            pts in proptest::collection::vec((-4i64..5, 1i64..4), 6),
        ) {
            let p = MPoly::from_terms(2, tp.iter().map(|(a, b, n, d)| (vec![*a, *b], q(*n, *d))).collect())
                .expect("two exponents");
            let r: Vec<Q> = pts.iter().map(|(n, d)| q(*n, *d)).collect();
            let (p0, e1, e2) = ([r[0].clone(), r[1].clone()], [r[2].clone(), r[3].clone()], [r[4].clone(), r[5].clone()]);
            let (s, t) = (var::<Q>(0), var::<Q>(1));
            let st = &s * &t;
            let map: Vec<MPoly<Q>> = (0..2)
                .map(|k| &(&cst(p0[k].clone()) + &s.scale(&e1[k])) + &st.scale(&e2[k]))
                .collect();
            proptest::prop_assert_eq!(compose_fan(&p, &p0, &e1, &e2), Some(compose_by_definition(&p, &map)));
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(32))]
        /// The determinant by 2×2 minors, over `ℚ` and fraction-free in integers, equals
        /// the expansion along the first row, for random 4×4 matrices of polynomials
        /// (zero entries and different denominators per row included).
        #[test]
        fn det4_by_minors_equals_the_first_row_expansion(
            entries in proptest::collection::vec(
                proptest::collection::vec((0u32..4, 0u32..3, -4i64..5, 1i64..6), 0..4), 16),
        ) {
            let e: Vec<MPoly<Q>> = entries
                .iter()
                .map(|t| MPoly::from_terms(2, t.iter().map(|(a, b, n, d)| (vec![*a, *b], q(*n, *d))).collect())
                    .expect("two exponents"))
                .collect();
            let row = |r: usize| -> [MPoly<Q>; 4] { std::array::from_fn(|c| e[4 * r + c].clone()) };
            let (r0, r1, r2, r3) = (row(0), row(1), row(2), row(3));
            let by_first_row = det4_by_first_row([&r0, &r1, &r2, &r3]);
            proptest::prop_assert_eq!(det4_by_two_rows([&r0, &r1, &r2, &r3]), by_first_row.clone());
            // the fraction-free integer expansion (`det4` for exact scalars)
            proptest::prop_assert_eq!(det4([&r0, &r1, &r2, &r3]), by_first_row);
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(32))]
        /// The fraction-free Bernstein coefficients of the export patches equal those of
        /// the local polynomial (`to_local`, then `tensor_bernstein` over `ℚ`), on random
        /// coordinates and rectangles.
        #[test]
        fn exact_bernstein_on_a_rectangle_equals_the_local_conversion(
            coords in proptest::collection::vec(
                proptest::collection::vec((0u32..4, 0u32..3, -6i64..7, 1i64..5), 0..6), 1..4),
            (a, b, c, d) in (-5i64..5, 1i64..6, -5i64..5, 1i64..6),
        ) {
            let ps: Vec<MPoly<Q>> = coords
                .iter()
                .map(|t| MPoly::from_terms(2, t.iter().map(|(i, j, n, d)| (vec![*i, *j], q(*n, *d))).collect())
                    .expect("two exponents"))
                .collect();
            let dom = Domain { u: (q(a, 3), q(a + b, 3)), v: (q(c, 4), q(c + d, 7)) };
            let (m, n, bern) = exact_bernstein_on(&ps, &dom).expect("exact");
            let local: Vec<MPoly<Q>> = ps.iter().map(|p| to_local(p, &dom)).collect();
            let (lm, ln) = local.iter().map(bidegree).fold((0, 0), |(x, y), (z, w)| (x.max(z), y.max(w)));
            proptest::prop_assert_eq!((m, n), (lm, ln));
            for (p, b) in local.iter().zip(&bern) {
                proptest::prop_assert_eq!(&tensor_bernstein(p, m, n).expect("bidegree"), b);
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// The content by integer gcds of numerators and denominators equals Euclid's
        /// algorithm on the rationals (zeros and a single entry included).
        #[test]
        fn content_of_rationals_equals_euclid_on_the_rationals(
            cs in proptest::collection::vec((-40i64..41, 1i64..30), 1..7),
        ) {
            let qs: Vec<Q> = cs.iter().map(|(n, d)| q(*n, *d)).collect();
            let euclid = qs[1..].iter().fold(qs[0].abs(), |g, c| rational_gcd(&g, c));
            proptest::prop_assert_eq!(rcagd_algebra::mpoly::content_rational(qs.iter()), euclid);
        }
    }

    /// A variable without substitute gives zero; a constant stays a constant.
    #[test]
    fn compose_without_substitute_and_of_constants() {
        let p = &(&u() * &v()) + &int(3);
        assert!(compose(&p, &[var(1)]).is_zero());
        assert_eq!(compose(&int::<Q>(7), &[]), int(7));
        assert_eq!(compose(&p, &[int(2), int(5)]), int(13));
    }

    /// The Taylor-shift `to_local` equals the composition with `(a + h s, b + k t)`.
    #[test]
    fn to_local_by_taylor_shifts_equals_the_composition() {
        let p = &(&(&(&u() * &u()) * &v()) - &v().pow(3).scale(&q(7, 3)))
            + &(&(&u() * &int(5)) + &int(-2));
        let d = Domain {
            u: (q(1, 4), q(3, 2)),
            v: (q(-2, 3), q(5, 7)),
        };
        let su = &cst(d.u.0.clone()) + &var::<Q>(0).scale(&(d.u.1.clone() - d.u.0.clone()));
        let sv = &cst(d.v.0.clone()) + &var::<Q>(1).scale(&(d.v.1.clone() - d.v.0.clone()));
        assert_eq!(to_local(&p, &d), compose(&p, &[su, sv]));
        assert_eq!(affine_shift_2(&p, &d), Some(to_local(&p, &d)));
    }

    #[test]
    fn exact_division() {
        let a = &(&u() * &u()) + &(&v() * &v()) + int(1);
        let b = &(&u() * &v()) - &int(3);
        let p = &a * &b;
        assert_eq!(div_exact(&p, &a), Some(b.clone()));
        assert_eq!(div_exact(&p, &b), Some(a.clone()));
        assert_eq!(div_exact(&(&p + &int(1)), &a), None);
        assert_eq!(div_exact(&p, &MPoly::zero(2)), None);
        let mut polys = vec![&p * &b, &a * &(&b * &b), &b * &b];
        assert_eq!(cancel_common(&mut polys, &[b.clone(), a.clone()]), 2);
        assert_eq!(polys[2], int(1));
        // f64 division with rounding noise
        let pf = p.map(Scalar::to_f64);
        let af = a.map(Scalar::to_f64);
        let qf = div_exact(&pf, &af).expect("divisible");
        assert!((qf.coeff(&[1, 1]) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn content_and_composition() {
        let mut polys = vec![u().scale(&q(4, 6)), v().scale(&q(-2, 9))];
        normalize_content(&mut polys);
        assert_eq!(polys[0], u().scale(&q(3, 1)));
        assert_eq!(polys[1], v().scale(&q(-1, 1)));
        let p = &(&u() * &u()) - &v();
        let c = compose(&p, &[&v() + &int(1), u()]);
        assert_eq!(
            c,
            &(&(&v() * &v()) + &v().scale(&q(2, 1))) + &(&int(1) - &u())
        );
    }

    #[test]
    fn bernstein_patch_and_signs() {
        // W = u² + v² + 1 on [−1, 2] × [0, 3]: positive
        let w = &(&(&u() * &u()) + &(&v() * &v())) + &int(1);
        let d = Domain::new(q(-1, 1), q(2, 1), q(0, 1), q(3, 1)).expect("rect");
        assert_eq!(sign_on_domain(&w, &d, 64), Sign::Positive);
        assert_eq!(sign_on_domain(&(-w.clone()), &d, 64), Sign::Negative);
        // u − v vanishes on the diagonal
        let l = &u() - &v();
        assert!(matches!(
            sign_on_domain(&l, &d, 64),
            Sign::ZeroAt(_) | Sign::Changes(..)
        ));
        // u² − 1/4 − v² · 0: zero inside
        let z = &(&u() * &u()) - &cst(q(1, 4));
        assert!(matches!(
            sign_on_domain(&z, &Domain::unit(), 64),
            Sign::Changes(..) | Sign::ZeroAt(_)
        ));
        // the patch reproduces the map
        let x = &(&u() * &v()) + &int(2);
        let patch = patch_of(&[w.clone(), x.clone()], &d).expect("patch");
        let p = patch.eval(&q(1, 3), &q(1, 2)).expect("finite");
        let (uu, vv) = (q(-1, 1) + q(1, 1), q(3, 2));
        let want =
            (uu.clone() * vv.clone() + q(2, 1)) / (uu.clone() * uu + vv.clone() * vv + q(1, 1));
        assert_eq!(p[0], want);
        assert!(Domain::new(q(1, 1), q(0, 1), q(0, 1), q(1, 1)).is_err());
    }
}

impl<F: Scalar> PartialEq for RatFn<F> {
    fn eq(&self, other: &Self) -> bool {
        self.num == other.num && self.den == other.den
    }
}

pub(crate) use rcagd_algebra::sqrt_in_field as scalar_sqrt;

/// A polynomial in `t` only (variable 0 of the two-variable ring) as a polynomial over
/// `Q` (for `f64`, the exact binary values of its coefficients); `None` if it involves the
/// second variable or a coefficient is not finite.
pub(crate) fn univariate_to_q<F: Scalar>(p: &MPoly<F>) -> Option<Poly<Rational>> {
    if p.terms().any(|(e, _)| e.get(1).is_some_and(|&k| k > 0)) {
        return None;
    }
    let n = p.degree_in(0).unwrap_or(0) as usize;
    (0..=n)
        .map(|i| p.coeff(&[i as u32, 0]).to_rational())
        .collect::<Option<Vec<_>>>()
        .map(Poly::new)
}

/// A polynomial over `Q` as a polynomial in `t` (variable 0 of the two-variable ring).
pub(crate) fn univariate_from_q<F: Scalar>(p: &Poly<Rational>) -> MPoly<F> {
    MPoly::from_terms(
        2,
        p.coeffs()
            .iter()
            .enumerate()
            .map(|(i, c)| (vec![i as u32, 0], F::from_rational(c)))
            .collect(),
    )
    .unwrap_or_else(|_| MPoly::zero(2))
}

/// The square root of a polynomial in the single variable `x₀` (`None` if it is not the
/// square of a polynomial with coefficients in the scalar field, or involves `x₁`).
pub(crate) fn univariate_sqrt<F: Scalar>(p: &MPoly<F>) -> Option<MPoly<F>> {
    if p.is_zero() {
        return Some(MPoly::zero(2));
    }
    if p.terms().any(|(e, _)| e.iter().skip(1).any(|&k| k != 0)) {
        return None;
    }
    let deg = p.degree_in(0)? as usize;
    if deg % 2 == 1 {
        return None;
    }
    let k = deg / 2;
    let coef = |i: usize| p.coeff(&[i as u32, 0]);
    let mut s = vec![F::zero(); k + 1];
    s[k] = scalar_sqrt(&coef(deg))?;
    let two_lead = F::from_i64(2) * s[k].clone();
    let inv = two_lead.inv()?;
    for j in 1..=k {
        // coefficient of t^{2k−j}: Σ_{i+l = 2k−j} s_i s_l, unknown s_{k−j} appears twice
        let target = 2 * k - j;
        let mut acc = F::zero();
        for i in (k - j + 1)..=k {
            let l = target - i;
            if l > k - j && l <= k {
                acc += s[i].clone() * s[l].clone();
            }
        }
        s[k - j] = (coef(target) - acc) * inv.clone();
    }
    let root = MPoly::from_terms(
        2,
        s.into_iter()
            .enumerate()
            .map(|(i, c)| (vec![i as u32, 0], c))
            .collect(),
    )
    .ok()?;
    let diff = &(&root * &root) - p;
    let ok = if F::EXACT {
        diff.is_zero()
    } else {
        diff.terms().all(|(_, c)| c.to_f64().abs() <= 1e-9 * mag(p))
    };
    ok.then_some(root)
}

// -------------------------------------------------------------------------------------
// Greatest common divisors in Q[u, v] (exact scalars only)
// -------------------------------------------------------------------------------------

use rcagd_algebra::Poly;

/// `p` as a polynomial in `v` (variable 1) with coefficients in `Q[u]`, low degree first,
/// trimmed.
fn to_bi<F: Scalar>(p: &MPoly<F>) -> Vec<Poly<F>> {
    let dv = p.degree_in(1).unwrap_or(0) as usize;
    let du = p.degree_in(0).unwrap_or(0) as usize;
    let mut rows = vec![vec![F::zero(); du + 1]; dv + 1];
    for (e, c) in p.terms() {
        let i = e.first().copied().unwrap_or(0) as usize;
        let j = e.get(1).copied().unwrap_or(0) as usize;
        rows[j][i] = c.clone();
    }
    let mut out: Vec<Poly<F>> = rows.into_iter().map(Poly::new).collect();
    while out.last().is_some_and(|c| c.is_zero()) {
        out.pop();
    }
    out
}

fn from_bi<F: Scalar>(c: &[Poly<F>]) -> MPoly<F> {
    let mut terms = Vec::new();
    for (j, p) in c.iter().enumerate() {
        for (i, a) in p.coeffs().iter().enumerate() {
            terms.push((vec![i as u32, j as u32], a.clone()));
        }
    }
    MPoly::from_terms(2, terms).unwrap_or_else(|_| MPoly::zero(2))
}

/// The coefficients of a polynomial over an exact field as rationals (`None` otherwise).
fn rational_coeffs<F: Scalar>(p: &Poly<F>) -> Option<Vec<Rational>> {
    p.coeffs().iter().map(Scalar::to_rational).collect()
}

/// `true` if the non-zero `a`, `b` are proven coprime by a modular image
/// ([`rcagd_algebra::mpoly::coprime_by_modular_image`]; exact scalars only).
fn proven_coprime<F: Scalar>(a: &Poly<F>, b: &Poly<F>) -> bool {
    if !F::EXACT {
        return false;
    }
    match (rational_coeffs(a), rational_coeffs(b)) {
        (Some(x), Some(y)) => rcagd_algebra::mpoly::coprime_by_modular_image(&x, &y),
        _ => false,
    }
}

/// The monic gcd of the coefficients (the content in `Q[u]`; zero if all are zero). The
/// same polynomial as the fold `gcd(…gcd(gcd(0, c₀), c₁)…)`, computed lowest degree
/// first and ended as soon as it is 1: a constant coefficient, a modular image proving
/// two coefficients coprime, or an exact gcd of degree 0.
fn bi_content<F: Scalar>(c: &[Poly<F>]) -> Poly<F> {
    let mut nz: Vec<&Poly<F>> = c.iter().filter(|p| !p.is_zero()).collect();
    nz.sort_by_key(|p| p.degree().unwrap_or(0));
    let Some(first) = nz.first() else {
        return Poly::zero();
    };
    if first.degree().unwrap_or(0) == 0 {
        return Poly::constant(F::one());
    }
    let mut g = Poly::zero().gcd(first);
    for p in &nz[1..] {
        if proven_coprime(&g, p) {
            return Poly::constant(F::one());
        }
        g = g.gcd(p);
        if g.degree().unwrap_or(0) == 0 {
            return Poly::constant(F::one());
        }
    }
    g
}

fn bi_primitive<F: Scalar>(c: &[Poly<F>]) -> Vec<Poly<F>> {
    primitive_by(c, &bi_content(c))
}

/// The coefficients divided by their content `g` (from [`bi_content`]).
fn primitive_by<F: Scalar>(c: &[Poly<F>], g: &Poly<F>) -> Vec<Poly<F>> {
    if g.is_zero() || (g.degree() == Some(0) && g.coeffs().first().is_some_and(|x| *x == F::one()))
    {
        return c.to_vec();
    }
    c.iter()
        .map(|p| p.div_exact(g).unwrap_or_else(|_| p.clone()))
        .collect()
}

/// `true` if `a`, `b` (as from [`to_bi`], non-empty) are proven to have no common factor
/// of positive degree in `v` by a modular image
/// ([`rcagd_algebra::mpoly::coprime_in_last_variable_by_modular_image`]; exact scalars).
fn proven_coprime_in_v<F: Scalar>(a: &[Poly<F>], b: &[Poly<F>]) -> bool {
    if !F::EXACT || a.is_empty() || b.is_empty() {
        return false;
    }
    let conv =
        |c: &[Poly<F>]| -> Option<Vec<Vec<Rational>>> { c.iter().map(rational_coeffs).collect() };
    match (conv(a), conv(b)) {
        (Some(x), Some(y)) => {
            rcagd_algebra::mpoly::coprime_in_last_variable_by_modular_image(&x, &y)
        }
        _ => false,
    }
}

/// Reads the clock now (not every [`rcagd_algebra::budget::STRIDE`]-th time) and ends the
/// computation when the work budget is spent: for loops whose single steps can take long
/// (products of polynomials whose coefficients have grown to thousands of digits).
fn checkpoint_now() {
    if let Err(e) = rcagd_algebra::budget::check() {
        std::panic::resume_unwind(Box::new(e));
    }
}

/// The pseudo-remainder of `a` by `b` in `v` (coefficients in `Q[u]`). The coefficients
/// of a pseudo-remainder sequence can grow to many thousand digits, so the budget's
/// clock is read before every product of coefficients (issue 19: a fuzz case ran many
/// seconds past its budget here).
fn bi_prem<F: Scalar>(a: &[Poly<F>], b: &[Poly<F>]) -> Vec<Poly<F>> {
    let n = b.len() - 1;
    let lc = b[n].clone();
    let mut r: Vec<Poly<F>> = a.to_vec();
    while r.len() > n && !r.is_empty() {
        let d = r.len() - 1;
        let c = r[d].clone();
        let shift = d - n;
        let mut next: Vec<Poly<F>> = r
            .iter()
            .map(|x| {
                checkpoint_now();
                &lc * x
            })
            .collect();
        for (k, bk) in b.iter().enumerate() {
            checkpoint_now();
            next[k + shift] = &next[k + shift] - &(&c * bk);
        }
        next.pop();
        while next.last().is_some_and(|x| x.is_zero()) {
            next.pop();
        }
        r = next;
    }
    r
}

/// The greatest common divisor of two polynomials in `Q[u, v]` (up to a constant factor):
/// contents in `Q[u]` by Euclid, primitive parts by the primitive pseudo-remainder
/// sequence in `v`. For `f64` it returns the constant 1 (no cancellation).
pub(crate) fn gcd2<F: Scalar>(p: &MPoly<F>, q: &MPoly<F>) -> MPoly<F> {
    if !F::EXACT {
        return int(1);
    }
    if p.total_degree() == Some(0) || q.total_degree() == Some(0) {
        // a non-zero constant: a unit
        return int(1);
    }
    if p.is_zero() {
        return q.clone();
    }
    if q.is_zero() {
        return p.clone();
    }
    let (a, b) = (to_bi(p), to_bi(q));
    let (ca, cb) = (bi_content(&a), bi_content(&b));
    let cont = if ca.degree().unwrap_or(0) == 0
        || cb.degree().unwrap_or(0) == 0
        || proven_coprime(&ca, &cb)
    {
        Poly::constant(F::one())
    } else {
        ca.gcd(&cb)
    };
    // no common factor of positive degree in v (the usual case), proven by a modular
    // image: the gcd is the content's (the pseudo-remainder sequence would end with a
    // constant in v)
    if proven_coprime_in_v(&a, &b) {
        return from_bi(&[cont]);
    }
    let (mut a, mut b) = (primitive_by(&a, &ca), primitive_by(&b, &cb));
    if a.len() < b.len() {
        std::mem::swap(&mut a, &mut b);
    }
    let pp = loop {
        rcagd_algebra::budget::checkpoint();
        if b.is_empty() {
            break a;
        }
        if b.len() == 1 {
            // b is constant in v and primitive: a unit of Q[u][v]
            break vec![Poly::constant(F::one())];
        }
        let r = bi_prem(&a, &b);
        if r.is_empty() {
            break b;
        }
        a = b;
        b = bi_primitive(&r);
    };
    let g: Vec<Poly<F>> = pp.iter().map(|c| c * &cont).collect();
    from_bi(&g)
}

/// Divides all polynomials by their greatest common divisor (exact scalars; a no-op for
/// `f64`). Returns the divisor.
pub(crate) fn cancel_gcd<F: Scalar>(polys: &mut [MPoly<F>]) -> MPoly<F> {
    let g = polys.iter().fold(MPoly::zero(2), |g, p| gcd2(&g, p));
    if g.total_degree().unwrap_or(0) == 0 {
        return int(1);
    }
    match polys
        .iter()
        .map(|p| div_exact(p, &g))
        .collect::<Option<Vec<_>>>()
    {
        Some(qs) => {
            polys.clone_from_slice(&qs);
            g
        }
        None => int(1),
    }
}

#[cfg(test)]
mod gcd_tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(n: i64, d: i64) -> Rational {
        Rational::from_ratio(n, d)
    }

    /// The gcd of the old definition: contents by the fold `gcd(…gcd(0, c₀)…, cₙ)`, the
    /// primitive pseudo-remainder sequence in `v` without modular shortcuts.
    fn gcd2_by_definition(p: &MPoly<Rational>, q: &MPoly<Rational>) -> MPoly<Rational> {
        let content = |c: &[Poly<Rational>]| c.iter().fold(Poly::zero(), |g, p| g.gcd(p));
        let primitive = |c: &[Poly<Rational>]| -> Vec<Poly<Rational>> {
            let g = content(c);
            c.iter()
                .map(|p| p.div_exact(&g).expect("the content divides"))
                .collect()
        };
        if p.is_zero() {
            return q.clone();
        }
        if q.is_zero() {
            return p.clone();
        }
        let (a, b) = (to_bi(p), to_bi(q));
        let cont = content(&a).gcd(&content(&b));
        let (mut a, mut b) = (primitive(&a), primitive(&b));
        if a.len() < b.len() {
            std::mem::swap(&mut a, &mut b);
        }
        let pp = loop {
            if b.is_empty() {
                break a;
            }
            if b.len() == 1 {
                break vec![Poly::constant(Rational::ONE)];
            }
            let r = bi_prem(&a, &b);
            if r.is_empty() {
                break b;
            }
            a = b;
            b = primitive(&r);
        };
        from_bi(&pp.iter().map(|c| c * &cont).collect::<Vec<_>>())
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(32))]
        /// `gcd2` (contents lowest degree first with early ends, modular coprimality
        /// proofs) is the same polynomial as the plain definition, for products with a
        /// random common factor (of positive degree or a polynomial in `u` alone) and
        /// random coprime parts.
        #[test]
        fn gcd2_equals_the_definition(
            tg in proptest::collection::vec((0u32..3, 0u32..3, -5i64..6, 1i64..4), 0..5),
            ta in proptest::collection::vec((0u32..3, 0u32..3, -5i64..6, 1i64..4), 1..5),
            tb in proptest::collection::vec((0u32..3, 0u32..3, -5i64..6, 1i64..4), 1..5),
            only_u in proptest::bool::ANY,
        ) {
            let mk = |t: &Vec<(u32, u32, i64, i64)>, u_only: bool| {
                MPoly::from_terms(2, t.iter().map(|(a, b, n, d)| (vec![*a, if u_only { 0 } else { *b }], q(*n, *d))).collect())
                    .expect("two exponents")
            };
            let g = &mk(&tg, only_u) + &int(1);
            let (a, b) = (mk(&ta, false), mk(&tb, false));
            let (p, r) = (&g * &a, &g * &b);
            proptest::prop_assert_eq!(gcd2(&p, &r), gcd2_by_definition(&p, &r));
            proptest::prop_assert_eq!(gcd2(&a, &b), gcd2_by_definition(&a, &b));
        }
    }

    #[test]
    fn bivariate_gcd() {
        let (u, v) = (var::<Rational>(0), var::<Rational>(1));
        let a = &(&(&u * &u) + &(&v * &v)) + &int(1);
        let b = &(&u * &v) - &int(3);
        let c = &u + &int(2);
        let p = &(&a * &b) * &c;
        let q = &(&a * &c) * &(&v + &int(5));
        let g = gcd2(&p, &q);
        assert!(div_exact(&g, &(&a * &c)).is_some_and(|k| k.total_degree() == Some(0)));
        let mut polys = vec![p.clone(), q.clone()];
        cancel_gcd(&mut polys);
        assert_eq!(polys[0].total_degree(), Some(2));
        assert_eq!(gcd2(&u, &v).total_degree(), Some(0));
    }
}
