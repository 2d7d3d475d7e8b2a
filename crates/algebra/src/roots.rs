//! Exact real-root isolation for polynomials with rational coefficients.
//!
//! **Method** (Vincent–Collins–Akritas in the Bernstein basis). Let `p*` be the
//! square-free part `p / gcd(p, p′)` (same real roots as `p`, all simple), scaled to a
//! primitive integer polynomial of degree `n`. On an interval `[a, b]` write
//! `p*(a + (b − a)s) = Σᵢ bᵢ C(n,i) sⁱ(1 − s)ⁿ⁻ⁱ`. **Descartes' rule of signs in the
//! Bernstein basis**: the number `V` of sign changes of `b₀, …, bₙ` (zeros skipped)
//! bounds the number of roots in the open interval `(a, b)` (with multiplicity) and has
//! the same parity; so `V = 0` means no root and `V = 1` exactly one. Halving `[a, b]`
//! at its midpoint by de Casteljau's algorithm (done in integers: the `k`-th de
//! Casteljau row is kept multiplied by `2ᵏ`) gives the coefficients on both halves; by
//! the one- and two-circle theorems (Krandick, Mehlhorn; Alesina–Galuzzi) every
//! sufficiently small interval has `V ≤ 1`, so the subdivision terminates for a
//! square-free polynomial. The value at a midpoint is the shared coefficient of both
//! halves; a zero there is an exact rational root.
//!
//! The search starts on `(−2ᴱ, 2ᴱ)`, where `2ᴱ` strictly exceeds **Fujiwara's bound**
//! `|z| ≤ 2·maxᵢ |aₙ₋ᵢ / aₙ|^{1/i}` on every complex root `z` (computed from bit lengths,
//! so no root lies on the boundary).
//!
//! **Results** are [`RootInterval`]s: either `lo == hi`, an exact rational root, or
//! `lo < hi` with exactly one real root in the open interval `(lo, hi)`, none at the
//! endpoints, and `p*(lo)·p*(hi) < 0`. [`RootInterval::refine`] shrinks such an
//! interval to any width by quadratic interval refinement (Abbott 2006: a secant step
//! on a grid of `N` cells, `N ← N²` on success, bisection on failure), and
//! [`real_roots_f64`] refines until both endpoints round to the same `f64`, which then
//! is the correctly rounded root.
//!
//! Independent cross-checks (Sturm sequences) live in `tests/roots_resultants.rs`.
//! The Hermite interpolation of Besednjak ch. 9 (docs/math/ph-curves.md, "Hermite interpolation
//! by helical PH quintics") needs real-root isolation for a quartic.

use crate::error::AlgebraError;
use crate::poly::Poly;
use crate::rational::Rational;
use crate::scalar::{Field, Scalar};
use core::cmp::Ordering;
use dashu_base::{BitTest, Gcd, UnsignedAbs};
use dashu_int::{IBig, UBig};
use num_traits::{One, Zero};

/// An exact isolating interval of one real root of a polynomial `p`.
///
/// Invariant (as produced by [`isolate_real_roots`]): either `lo == hi` and `p(lo) = 0`
/// exactly, or `lo < hi`, `p` has exactly one real root in the open interval
/// `(lo, hi)`, no root at `lo` or `hi`, and the square-free part of `p` has opposite
/// non-zero signs at `lo` and `hi`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RootInterval {
    /// Lower endpoint.
    pub lo: Rational,
    /// Upper endpoint (`== lo` for an exact rational root).
    pub hi: Rational,
}

impl RootInterval {
    /// The exact root `r` (`lo = hi = r`).
    pub fn exact(r: Rational) -> Self {
        RootInterval {
            lo: r.clone(),
            hi: r,
        }
    }

    /// `true` if the root is known exactly (`lo == hi`).
    pub fn is_exact(&self) -> bool {
        self.lo == self.hi
    }

    /// The width `hi − lo`.
    pub fn width(&self) -> Rational {
        &self.hi - &self.lo
    }

    /// The exact midpoint `(lo + hi)/2`.
    pub fn midpoint(&self) -> Rational {
        (&self.lo + &self.hi) / Rational::from(2)
    }

    /// The midpoint rounded to `f64` (within `width/2` of the root, plus rounding).
    pub fn midpoint_f64(&self) -> f64 {
        Scalar::to_f64(&self.midpoint())
    }

    /// `true` if `lo ≤ x ≤ hi`.
    pub fn contains(&self, x: &Rational) -> bool {
        self.lo <= *x && *x <= self.hi
    }

    /// Shrinks the interval, keeping the root of `p` it isolates, until
    /// `hi − lo ≤ width` (or the root is found exactly, `lo == hi`).
    ///
    /// Quadratic interval refinement: the secant through `(lo, p*(lo))`, `(hi, p*(hi))`
    /// picks one of `N` grid cells, two exact sign evaluations confirm it (then
    /// `N ← N²`), otherwise the interval is bisected and `N ← √N`. Every step at least
    /// halves the width.
    ///
    /// # Errors
    /// [`AlgebraError::InvalidArgument`] if `width ≤ 0`, `p` is zero, `lo > hi`, `lo == hi`
    /// is not a root, or the square-free part of `p` does not change sign strictly
    /// between `lo` and `hi` (the interval does not isolate a root of `p`).
    pub fn refine(&mut self, p: &Poly<Rational>, width: &Rational) -> Result<(), AlgebraError> {
        if *width <= Rational::zero() {
            return Err(AlgebraError::InvalidArgument(
                "refine: the target width must be positive".into(),
            ));
        }
        let Some((q, s_lo)) = self.checked(p)? else {
            return Ok(());
        };
        let target = width.clone();
        refine_int(
            &q,
            &mut self.lo,
            &mut self.hi,
            s_lo,
            &|lo, hi| hi - lo <= target,
            &|_, _| log2_approx(&target),
            None,
        );
        Ok(())
    }

    /// The root as the nearest `f64` (correctly rounded unless the root lies within
    /// `2⁻²⁰⁰` relative of a rounding boundary, then within one ulp). The interval
    /// itself is not changed.
    ///
    /// # Errors
    /// As [`RootInterval::refine`] (the interval must isolate a root of `p`).
    pub fn root_f64(&self, p: &Poly<Rational>) -> Result<f64, AlgebraError> {
        let mut iv = self.clone();
        let Some((q, s_lo)) = iv.checked(p)? else {
            return Ok(Scalar::to_f64(&iv.lo));
        };
        Ok(polish_f64(&q, &mut iv, s_lo))
    }

    /// Checks the invariant against `p`; `None` for an exact root, otherwise the
    /// primitive square-free integer polynomial and its sign at `lo`.
    fn checked(&self, p: &Poly<Rational>) -> Result<Option<(IntPoly, i8)>, AlgebraError> {
        let Some(q) = IntPoly::square_free_of(p) else {
            return Err(AlgebraError::InvalidArgument(
                "the zero polynomial has no isolated roots".into(),
            ));
        };
        match self.lo.cmp(&self.hi) {
            Ordering::Greater => Err(AlgebraError::InvalidArgument(format!(
                "root interval is empty: lo = {} > hi = {}",
                self.lo, self.hi
            ))),
            Ordering::Equal => {
                if q.sign_at(&self.lo) == 0 {
                    Ok(None)
                } else {
                    Err(AlgebraError::InvalidArgument(format!(
                        "{} is not a root of the polynomial",
                        self.lo
                    )))
                }
            }
            Ordering::Less => {
                let s_lo = q.sign_at(&self.lo);
                let s_hi = q.sign_at(&self.hi);
                if s_lo == 0 || s_hi == 0 || s_lo == s_hi {
                    Err(AlgebraError::InvalidArgument(format!(
                        "[{}, {}] is not an isolating interval: the square-free part has \
                         signs {s_lo} and {s_hi} at its endpoints",
                        self.lo, self.hi
                    )))
                } else {
                    Ok(Some((q, s_lo)))
                }
            }
        }
    }
}

/// A polynomial with integer coefficients, low degree first, no trailing zeros.
#[derive(Debug, Clone)]
struct IntPoly {
    c: Vec<IBig>,
}

impl IntPoly {
    /// The primitive integer polynomial `λ·p` with `λ > 0` (`None` for zero).
    fn primitive_of(p: &Poly<Rational>) -> Option<IntPoly> {
        if p.is_zero() {
            return None;
        }
        let mut l = UBig::ONE;
        for a in p.coeffs() {
            let d = a.denominator();
            let g = (&l).gcd(d);
            l = &l / &g * d;
        }
        let lr = IBig::from(l.clone());
        let mut c: Vec<IBig> = p
            .coeffs()
            .iter()
            .map(|a| a.numerator() * (&lr / IBig::from(a.denominator().clone())))
            .collect();
        let mut g = UBig::ZERO;
        for x in &c {
            if !x.is_zero() {
                g = (&g).gcd(&x.unsigned_abs());
            }
        }
        if g > UBig::ONE {
            let gi = IBig::from(g);
            for x in &mut c {
                *x = &*x / &gi;
            }
        }
        Some(IntPoly { c })
    }

    /// The primitive integer form of the square-free part `p / gcd(p, p′)`, with the gcd
    /// computed over ℤ by the subresultant PRS (much faster than Euclid over ℚ, whose
    /// monic remainders carry large numerators and denominators).
    fn square_free_of(p: &Poly<Rational>) -> Option<IntPoly> {
        let c = IntPoly::primitive_of(p)?;
        if c.degree() == 0 {
            return Some(c);
        }
        let g = c.gcd(&c.derivative());
        if g.degree() == 0 {
            return Some(c);
        }
        Some(c.div_exact(&g).primitive())
    }

    fn from_vec(mut c: Vec<IBig>) -> IntPoly {
        while c.last().is_some_and(|x| x.is_zero()) {
            c.pop();
        }
        IntPoly { c }
    }

    fn is_zero(&self) -> bool {
        self.c.is_empty()
    }

    fn derivative(&self) -> IntPoly {
        IntPoly::from_vec(
            self.c
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, a)| a * IBig::from(k))
                .collect(),
        )
    }

    /// The content (gcd of the coefficients, 0 for zero).
    fn content(&self) -> UBig {
        let mut g = UBig::ZERO;
        for x in &self.c {
            if !x.is_zero() {
                g = (&g).gcd(&x.unsigned_abs());
                if g == UBig::ONE {
                    break;
                }
            }
        }
        g
    }

    /// The primitive part with positive leading coefficient.
    fn primitive(&self) -> IntPoly {
        let g = self.content();
        if g.is_zero() {
            return self.clone();
        }
        let mut gi = IBig::from(g);
        if self.leading() < IBig::ZERO {
            gi = -gi;
        }
        IntPoly::from_vec(self.c.iter().map(|x| x / &gi).collect())
    }

    /// The pseudo-remainder: `lc(b)^{deg a − deg b + 1}·a = Q·b + R`, `deg R < deg b`.
    fn prem(&self, b: &IntPoly) -> IntPoly {
        let db = b.degree();
        let lb = b.leading();
        if self.c.len() < b.c.len() || b.is_zero() {
            return self.clone();
        }
        let mut e = self.degree() - db + 1;
        let mut r = self.c.clone();
        while r.len() >= b.c.len() {
            crate::budget::checkpoint();
            let lr = r.last().cloned().unwrap_or(IBig::ZERO);
            let shift = r.len() - b.c.len();
            for x in r.iter_mut() {
                *x *= &lb;
            }
            for (j, bj) in b.c.iter().enumerate() {
                r[shift + j] -= &lr * bj;
            }
            r.pop();
            while r.last().is_some_and(|x| x.is_zero()) {
                r.pop();
            }
            e -= 1;
        }
        let f = lb.pow(e);
        IntPoly::from_vec(r.into_iter().map(|x| x * &f).collect())
    }

    /// Exact division by a divisor `d ≠ 0` over ℤ (the quotient has integer coefficients
    /// when `d` is primitive and divides `self` over ℚ, by Gauss's lemma).
    fn div_exact(&self, d: &IntPoly) -> IntPoly {
        if d.is_zero() || self.c.len() < d.c.len() {
            return IntPoly { c: Vec::new() };
        }
        let ld = d.leading();
        let mut r = self.c.clone();
        let mut q = vec![IBig::ZERO; self.c.len() - d.c.len() + 1];
        for k in (0..q.len()).rev() {
            let top = &r[k + d.c.len() - 1];
            if top.is_zero() {
                continue;
            }
            let qk = top / &ld;
            for (j, dj) in d.c.iter().enumerate() {
                r[k + j] -= &qk * dj;
            }
            q[k] = qk;
        }
        IntPoly::from_vec(q)
    }

    /// The primitive gcd over ℤ by the subresultant PRS (exact divisions
    /// `prem(A, B)/(g·h^δ)`, `g ← lc(A)`, `h ← g^δ / h^{δ−1}`).
    fn gcd(&self, other: &IntPoly) -> IntPoly {
        let (mut a, mut b) = if self.degree() >= other.degree() {
            (self.primitive(), other.primitive())
        } else {
            (other.primitive(), self.primitive())
        };
        if b.is_zero() {
            return a;
        }
        let mut g = IBig::ONE;
        let mut h = IBig::ONE;
        loop {
            crate::budget::checkpoint();
            let delta = a.degree() - b.degree();
            let r = a.prem(&b);
            if r.is_zero() {
                return b.primitive();
            }
            if r.degree() == 0 {
                return IntPoly { c: vec![IBig::ONE] };
            }
            let div = &g * h.pow(delta);
            a = b;
            b = IntPoly::from_vec(r.c.into_iter().map(|x| x / &div).collect());
            g = a.leading();
            h = match delta {
                0 => h,
                _ => g.pow(delta) / h.pow(delta - 1),
            };
        }
    }

    fn degree(&self) -> usize {
        self.c.len().saturating_sub(1)
    }

    fn leading(&self) -> IBig {
        self.c.last().cloned().unwrap_or(IBig::ZERO)
    }

    /// `bⁿ·p(a/b)` for `x = a/b`, `b > 0`: `Σ cₖ aᵏ bⁿ⁻ᵏ` (integer Horner).
    fn eval_scaled(&self, x: &Rational) -> IBig {
        let a = x.numerator();
        let b = IBig::from(x.denominator().clone());
        let mut it = self.c.iter().rev();
        let Some(first) = it.next() else {
            return IBig::ZERO;
        };
        let mut acc = first.clone();
        let mut bp = IBig::ONE;
        for ck in it {
            bp *= &b;
            acc = acc * a + ck * &bp;
        }
        acc
    }

    /// The sign (−1, 0, 1) of `p(x)`.
    fn sign_at(&self, x: &Rational) -> i8 {
        sign_of(&self.eval_scaled(x))
    }

    /// The exact value `p(x)`.
    fn eval(&self, x: &Rational) -> Rational {
        let d = x.denominator().pow(self.degree());
        Rational::from_parts(self.eval_scaled(x), d)
    }

    /// `E` with all complex roots strictly inside the disc of radius `2ᴱ` (Fujiwara's
    /// bound `2·maxᵢ |aₙ₋ᵢ/aₙ|^{1/i}`, with `|aₙ₋ᵢ/aₙ| < 2^{Lᵢ}`,
    /// `Lᵢ = bits(aₙ₋ᵢ) − bits(aₙ) + 1`); `None` if `p = aₙtⁿ` (all roots zero).
    fn root_bound_exp(&self) -> Option<i64> {
        let n = self.degree();
        let bits_n = self.leading().bit_len() as i64;
        let mut e: Option<i64> = None;
        for i in 1..=n {
            let a = &self.c[n - i];
            if a.is_zero() {
                continue;
            }
            let li = a.bit_len() as i64 - bits_n + 1;
            let ei = li.div_euclid(i as i64) + i64::from(li.rem_euclid(i as i64) != 0);
            e = Some(e.map_or(ei, |x: i64| x.max(ei)));
        }
        e.map(|x| x + 1)
    }

    /// Bernstein coefficients (up to a common positive factor) of `p` on `[lo, hi]`:
    /// `q(s) = p(lo + (hi−lo)s) = Σⱼ qⱼ sʲ`, `bᵢ = Σ_{j≤i} C(i,j)/C(n,j) qⱼ`.
    fn bernstein_on(&self, lo: &Rational, hi: &Rational) -> Vec<IBig> {
        let n = self.degree();
        let mut a: Vec<Rational> = self.c.iter().map(|x| Rational::from(x.clone())).collect();
        // Taylor shift a(t + lo).
        if !lo.is_zero() {
            for i in 0..n {
                crate::budget::checkpoint();
                for j in (i..n).rev() {
                    let add = lo * &a[j + 1];
                    a[j] += add;
                }
            }
        }
        // Scale t ← w·t.
        let w = hi - lo;
        let mut wp = Rational::one();
        for aj in a.iter_mut() {
            *aj *= wp.clone();
            wp *= w.clone();
        }
        // Binomial rows C(i, ·) and C(n, ·).
        let binom_row = |k: usize| -> Vec<UBig> {
            let mut row = vec![UBig::ONE; k + 1];
            for j in 1..=k {
                row[j] = &row[j - 1] * UBig::from(k + 1 - j) / UBig::from(j);
            }
            row
        };
        let cn = binom_row(n);
        let mut b: Vec<Rational> = Vec::with_capacity(n + 1);
        for i in 0..=n {
            let ci = binom_row(i);
            let mut s = Rational::zero();
            for j in 0..=i {
                if a[j].is_zero() {
                    continue;
                }
                s += &a[j] * Rational::from_parts(IBig::from(ci[j].clone()), cn[j].clone());
            }
            b.push(s);
        }
        // Clear denominators (positive factor).
        let mut l = UBig::ONE;
        for x in &b {
            let d = x.denominator();
            let g = (&l).gcd(d);
            l = &l / &g * d;
        }
        let lr = IBig::from(l);
        let ints = IntPoly {
            c: b.iter()
                .map(|x| x.numerator() * (&lr / IBig::from(x.denominator().clone())))
                .collect(),
        };
        // Remove the (positive) content.
        let g = ints.content();
        if g > UBig::ONE {
            let gi = IBig::from(g);
            ints.c.iter().map(|x| x / &gi).collect()
        } else {
            ints.c
        }
    }
}

fn sign_of(x: &IBig) -> i8 {
    if x.is_zero() {
        0
    } else if *x < IBig::ZERO {
        -1
    } else {
        1
    }
}

/// Number of sign changes in a sequence, zeros skipped.
fn sign_variations(b: &[IBig]) -> usize {
    let mut v = 0;
    let mut last = 0i8;
    for x in b {
        let s = sign_of(x);
        if s != 0 {
            if last != 0 && s != last {
                v += 1;
            }
            last = s;
        }
    }
    v
}

/// De Casteljau at `s = 1/2` in integers: Bernstein coefficients of the left and right
/// halves, both multiplied by `2ⁿ` (then the common power of two is removed). The
/// `k`-th row `dᵢᵏ = dᵢᵏ⁻¹ + dᵢ₊₁ᵏ⁻¹` is `2ᵏ` times the true row; left `Lᵢ = d₀ⁱ 2ⁿ⁻ⁱ`,
/// right `Rᵢ = dᵢⁿ⁻ⁱ 2ⁱ`.
fn split_half(b: &[IBig]) -> (Vec<IBig>, Vec<IBig>) {
    let n = b.len().saturating_sub(1);
    let mut d = b.to_vec();
    let mut left = vec![IBig::ZERO; n + 1];
    let mut right = vec![IBig::ZERO; n + 1];
    left[0] = &d[0] << n;
    right[n] = &d[n] << n;
    for k in 1..=n {
        for i in 0..=n - k {
            let s = &d[i] + &d[i + 1];
            d[i] = s;
        }
        left[k] = &d[0] << (n - k);
        right[n - k] = &d[n - k] << (n - k);
    }
    let tz = left
        .iter()
        .chain(right.iter())
        .filter_map(|x| x.trailing_zeros())
        .min()
        .unwrap_or(0);
    if tz > 0 {
        for x in left.iter_mut().chain(right.iter_mut()) {
            *x = &*x >> tz;
        }
    }
    (left, right)
}

/// `lo + w·k/2^depth`.
fn grid_point(lo: &Rational, w: &Rational, depth: usize, k: &UBig) -> Rational {
    lo + w * Rational::from_parts(IBig::from(k.clone()), UBig::ONE << depth)
}

/// Isolates the roots of the square-free `q` in the open interval `(lo, hi)`, `lo < hi`.
fn isolate_open(q: &IntPoly, lo: &Rational, hi: &Rational) -> Vec<RootInterval> {
    let n = q.degree();
    let mut out = Vec::new();
    if n == 0 || lo >= hi {
        return out;
    }
    if n == 1 {
        // a₀ + a₁t: the root −a₀/a₁ is rational.
        let r = Rational::from_parts_signed(-q.c[0].clone(), q.c[1].clone());
        if *lo < r && r < *hi {
            out.push(RootInterval::exact(r));
        }
        return out;
    }
    let w = hi - lo;
    let mut stack: Vec<(Vec<IBig>, usize, UBig)> = vec![(q.bernstein_on(lo, hi), 0, UBig::ZERO)];
    while let Some((b, depth, k)) = stack.pop() {
        crate::budget::checkpoint();
        let v = sign_variations(&b);
        if v == 0 {
            continue;
        }
        let ends_nonzero =
            b.first().is_some_and(|x| !x.is_zero()) && b.last().is_some_and(|x| !x.is_zero());
        if v == 1 && ends_nonzero {
            out.push(RootInterval {
                lo: grid_point(lo, &w, depth, &k),
                hi: grid_point(lo, &w, depth, &(&k + UBig::ONE)),
            });
            continue;
        }
        let (left, right) = split_half(&b);
        let kl = &k << 1;
        let kr = &kl + UBig::ONE;
        if left.last().is_some_and(|x| x.is_zero()) {
            out.push(RootInterval::exact(grid_point(lo, &w, depth + 1, &kr)));
        }
        stack.push((right, depth + 1, kr));
        stack.push((left, depth + 1, kl));
    }
    out.sort_by(|a, b| a.lo.cmp(&b.lo));
    out
}

/// Approximate `log₂|r|` from bit lengths (within ±1; `i64::MIN` for zero).
fn log2_approx(r: &Rational) -> i64 {
    if r.is_zero() {
        return i64::MIN;
    }
    r.numerator().bit_len() as i64 - r.denominator().bit_len() as i64
}

/// Quadratic interval refinement of the root of `q` in `(lo, hi)`, `sign q(lo) = s_lo`,
/// until `stop(lo, hi)` or the root is hit exactly, or `max_iter` steps. `target_log2`
/// estimates `log₂` of the wanted width (caps the grid size `N = 2ᵉ`).
fn refine_int(
    q: &IntPoly,
    lo: &mut Rational,
    hi: &mut Rational,
    s_lo: i8,
    stop: &dyn Fn(&Rational, &Rational) -> bool,
    target_log2: &dyn Fn(&Rational, &Rational) -> i64,
    max_iter: Option<usize>,
) {
    let two = Rational::from(2);
    let mut e: usize = 2;
    let mut iter = 0usize;
    while *lo < *hi && !stop(lo, hi) {
        crate::budget::checkpoint();
        if max_iter.is_some_and(|m| iter >= m) {
            return;
        }
        iter += 1;
        let w = &*hi - &*lo;
        // The grid never needs cells much narrower than the target.
        let useful = log2_approx(&w)
            .saturating_sub(target_log2(lo, hi))
            .saturating_add(2);
        let e_cap = usize::try_from(useful.clamp(1, 1 << 16)).unwrap_or(1);
        let e_now = e.min(e_cap);
        if e_now >= 2 {
            match qir_step(q, lo, hi, s_lo, e_now, &w) {
                Qir::Exact => return,
                Qir::Success => {
                    e = e_now.saturating_mul(2).min(1 << 16);
                    continue;
                }
                Qir::Failure => e = (e_now / 2).max(1),
            }
            if *lo >= *hi || stop(lo, hi) {
                return;
            }
        }
        let m = (&*lo + &*hi) / two.clone();
        match q.sign_at(&m) {
            0 => {
                *lo = m.clone();
                *hi = m;
                return;
            }
            s if s == s_lo => *lo = m,
            _ => *hi = m,
        }
    }
}

enum Qir {
    Exact,
    Success,
    Failure,
}

/// One QIR step with `N = 2ᵉ` cells; on failure the interval is still shrunk by the
/// evaluated signs.
fn qir_step(
    q: &IntPoly,
    lo: &mut Rational,
    hi: &mut Rational,
    s_lo: i8,
    e: usize,
    w: &Rational,
) -> Qir {
    let f_lo = q.eval(lo);
    let f_hi = q.eval(hi);
    let den = &f_lo - &f_hi;
    if den.is_zero() {
        return Qir::Failure;
    }
    let nn = UBig::ONE << e;
    let lambda = f_lo / den * Rational::from(IBig::from(nn.clone()));
    let nn_i = IBig::from(nn.clone());
    let m = lambda.round().clamp(IBig::ZERO, nn_i.clone());
    let at = |k: &IBig| -> Rational { &*lo + w * Rational::from_parts(k.clone(), nn.clone()) };
    let x = at(&m);
    let sx = q.sign_at(&x);
    if sx == 0 {
        *lo = x.clone();
        *hi = x;
        return Qir::Exact;
    }
    if sx == s_lo {
        // Root in (x, hi): confirm with the next grid point.
        if m >= nn_i {
            return Qir::Failure;
        }
        let y = at(&(&m + IBig::ONE));
        let sy = if m.clone() + IBig::ONE == nn_i {
            -s_lo
        } else {
            q.sign_at(&y)
        };
        if sy == 0 {
            *lo = y.clone();
            *hi = y;
            return Qir::Exact;
        }
        if sy != s_lo {
            *lo = x;
            *hi = y;
            Qir::Success
        } else {
            *lo = y;
            Qir::Failure
        }
    } else {
        // Root in (lo, x): confirm with the previous grid point.
        if m <= IBig::ZERO {
            return Qir::Failure;
        }
        let y = at(&(&m - IBig::ONE));
        let sy = if m == IBig::ONE { s_lo } else { q.sign_at(&y) };
        if sy == 0 {
            *lo = y.clone();
            *hi = y;
            return Qir::Exact;
        }
        if sy == s_lo {
            *lo = y;
            *hi = x;
            Qir::Success
        } else {
            *hi = y;
            Qir::Failure
        }
    }
}

/// Refines until `lo` and `hi` round to the same `f64` (then that is the correctly
/// rounded root) or the interval is `2⁻²⁰⁰` relative; returns the rounded root.
fn polish_f64(q: &IntPoly, iv: &mut RootInterval, s_lo: i8) -> f64 {
    let mag = |lo: &Rational, hi: &Rational| log2_approx(lo).max(log2_approx(hi));
    refine_int(
        q,
        &mut iv.lo,
        &mut iv.hi,
        s_lo,
        &|lo, hi| {
            if Scalar::to_f64(lo) == Scalar::to_f64(hi) {
                return true;
            }
            let w = hi - lo;
            log2_approx(&w) < mag(lo, hi).saturating_sub(200)
        },
        &|lo, hi| mag(lo, hi).saturating_sub(64),
        Some(100_000),
    );
    if iv.is_exact() || Scalar::to_f64(&iv.lo) == Scalar::to_f64(&iv.hi) {
        Scalar::to_f64(&iv.lo)
    } else {
        iv.midpoint_f64()
    }
}

fn zero_poly_err() -> AlgebraError {
    AlgebraError::InvalidArgument(
        "the zero polynomial vanishes everywhere: its roots are not isolated".into(),
    )
}

/// The monic greatest common divisor of two polynomials over ℚ (zero iff both are zero),
/// computed over ℤ by the subresultant pseudo-remainder sequence (Knuth, *The Art of
/// Computer Programming* vol. 2, §4.6.1, Algorithm C) on the primitive integer forms: the
/// same result as Euclid over ℚ ([`Poly::gcd_euclid`]), without the growth of the numerators
/// and denominators of its monic remainders (which made a degree-20 gcd of small
/// rationals run for minutes, issue 19).
pub fn gcd_rational(a: &Poly<Rational>, b: &Poly<Rational>) -> Poly<Rational> {
    let (pa, pb) = (IntPoly::primitive_of(a), IntPoly::primitive_of(b));
    let g = match (pa, pb) {
        (None, None) => return Poly::zero(),
        (Some(x), None) | (None, Some(x)) => x,
        (Some(x), Some(y)) => x.gcd(&y),
    };
    Poly::new(g.c.into_iter().map(Rational::from).collect()).monic()
}

/// All distinct real roots of `p`, sorted, as exact isolating intervals (see
/// [`RootInterval`]; the open intervals are pairwise disjoint, consecutive ones may share
/// an endpoint, which is then not a root). A non-zero constant has no roots. Multiple roots are reported once
/// (use [`isolate_real_roots_with_multiplicity`] for multiplicities).
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] for the zero polynomial.
pub fn isolate_real_roots(p: &Poly<Rational>) -> Result<Vec<RootInterval>, AlgebraError> {
    let q = IntPoly::square_free_of(p).ok_or_else(zero_poly_err)?;
    Ok(isolate_all(&q))
}

/// All real roots of the square-free integer polynomial `q`, on `(−2ᴱ, 2ᴱ)`.
fn isolate_all(q: &IntPoly) -> Vec<RootInterval> {
    if q.degree() == 0 {
        return Vec::new();
    }
    let (lo, hi) = match q.root_bound_exp() {
        None => (Rational::from(-1), Rational::from(1)),
        Some(e) => {
            let b = if e >= 0 {
                Rational::from(IBig::from(UBig::ONE << e.unsigned_abs() as usize))
            } else {
                Rational::from_parts(IBig::ONE, UBig::ONE << e.unsigned_abs() as usize)
            };
            (-b.clone(), b)
        }
    };
    isolate_open(q, &lo, &hi)
}

/// The distinct real roots of `p` in the closed interval `[lo, hi]`, sorted, as
/// isolating intervals contained in `[lo, hi]` (roots at `lo` or `hi` are exact).
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] for the zero polynomial or `lo > hi`.
pub fn isolate_real_roots_in(
    p: &Poly<Rational>,
    lo: &Rational,
    hi: &Rational,
) -> Result<Vec<RootInterval>, AlgebraError> {
    let q = IntPoly::square_free_of(p).ok_or_else(zero_poly_err)?;
    if lo > hi {
        return Err(AlgebraError::InvalidArgument(format!(
            "empty interval: lo = {lo} > hi = {hi}"
        )));
    }
    let mut out = Vec::new();
    if q.sign_at(lo) == 0 {
        out.push(RootInterval::exact(lo.clone()));
    }
    if lo == hi || q.degree() == 0 {
        return Ok(out);
    }
    out.extend(isolate_open(&q, lo, hi));
    if q.sign_at(hi) == 0 {
        out.push(RootInterval::exact(hi.clone()));
    }
    Ok(out)
}

/// The number of distinct real roots of `p` in the closed interval `[lo, hi]`.
///
/// # Errors
/// As [`isolate_real_roots_in`].
pub fn count_real_roots_in(
    p: &Poly<Rational>,
    lo: &Rational,
    hi: &Rational,
) -> Result<usize, AlgebraError> {
    isolate_real_roots_in(p, lo, hi).map(|v| v.len())
}

/// The distinct real roots of `p`, sorted, as `f64`s: each isolating interval is refined
/// exactly until both endpoints round to the same `f64`, so the result is the correctly
/// rounded root (within one ulp in pathological cases, see [`RootInterval::root_f64`]).
/// Roots beyond the `f64` range give `±∞`. The zero polynomial gives an empty vector
/// (use [`isolate_real_roots`] to have it reported as an error).
pub fn real_roots_f64(p: &Poly<Rational>) -> Vec<f64> {
    let Some(q) = IntPoly::square_free_of(p) else {
        return Vec::new();
    };
    isolate_all(&q)
        .into_iter()
        .map(|mut iv| {
            if iv.is_exact() {
                Scalar::to_f64(&iv.lo)
            } else {
                let s_lo = q.sign_at(&iv.lo);
                polish_f64(&q, &mut iv, s_lo)
            }
        })
        .collect()
}

/// [`real_roots_f64`] for a polynomial with `f64` coefficients: each coefficient is
/// converted to its exact binary value, so the roots are those of exactly the given
/// polynomial, correctly rounded.
///
/// # Errors
/// [`AlgebraError::NotRepresentable`] for a NaN or infinite coefficient;
/// [`AlgebraError::InvalidArgument`] for the zero polynomial.
pub fn real_roots_f64_of(p: &Poly<f64>) -> Result<Vec<f64>, AlgebraError> {
    let coeffs = p
        .coeffs()
        .iter()
        .enumerate()
        .map(|(k, c)| {
            c.to_rational().ok_or_else(|| {
                AlgebraError::NotRepresentable(format!("coefficient {k} is not finite: {c}"))
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    let pq = Poly::new(coeffs);
    if pq.is_zero() {
        return Err(zero_poly_err());
    }
    Ok(real_roots_f64(&pq))
}

/// The distinct rational roots of `p`, sorted. A rational root `a/b` (lowest terms) of the
/// primitive integer square-free part `p*` has `b | lc(p*)` (rational root theorem), so
/// `lc(p*)·r` is an integer: each isolating interval is refined below width `1/|lc(p*)|`,
/// where it contains at most one such candidate, which is tested exactly. The zero
/// polynomial gives an empty vector.
pub fn rational_roots(p: &Poly<Rational>) -> Vec<Rational> {
    let Some(q) = IntPoly::square_free_of(p) else {
        return Vec::new();
    };
    let ivs = isolate_all(&q);
    let lc = Rational::from(IBig::from(q.leading().unsigned_abs()));
    let Some(target) = (!lc.is_zero()).then(|| Rational::one() / (lc.clone() * Rational::from(2)))
    else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for mut iv in ivs {
        if iv.is_exact() {
            out.push(iv.lo);
            continue;
        }
        let s_lo = q.sign_at(&iv.lo);
        refine_int(
            &q,
            &mut iv.lo,
            &mut iv.hi,
            s_lo,
            &|lo, hi| hi - lo <= target,
            &|_, _| log2_approx(&target),
            None,
        );
        if iv.is_exact() {
            out.push(iv.lo);
            continue;
        }
        // The only candidate m/lc with lo < m/lc < hi.
        let m = (&lc * &iv.lo).floor() + IBig::ONE;
        let cand = Rational::from(m) / lc.clone();
        if cand < iv.hi && q.sign_at(&cand) == 0 {
            out.push(cand);
        }
    }
    out
}

/// The square-free decomposition (Yun's algorithm): `p = c·∏ₖ fₖᵏ` with monic,
/// square-free, pairwise coprime `fₖ`; returns the non-constant `(fₖ, k)`, `k`
/// increasing. Zero and constants give an empty vector. Exact over exact fields.
pub fn square_free_decomposition<F: Field>(p: &Poly<F>) -> Vec<(Poly<F>, usize)> {
    let mut out = Vec::new();
    let n = match p.degree() {
        Some(n) if n >= 1 => n,
        _ => return out,
    };
    let dp = p.derivative();
    let b = p.gcd(&dp);
    let (Ok((mut c, _)), Ok((mut d, _))) = (p.div_rem(&b), dp.div_rem(&b)) else {
        return out;
    };
    d = &d - &c.derivative();
    let mut k = 1;
    while c.degree().is_some_and(|dc| dc > 0) && k <= n {
        let a = c.gcd(&d);
        let (Ok((c_new, _)), Ok((d_div, _))) = (c.div_rem(&a), d.div_rem(&a)) else {
            break;
        };
        d = &d_div - &c_new.derivative();
        if a.degree().is_some_and(|da| da > 0) {
            out.push((a.monic(), k));
        }
        c = c_new;
        k += 1;
    }
    out
}

/// All complex roots of the `f64` polynomial `p` (degree ≥ 1; a constant has none), by the
/// Weierstrass–Durand–Kerner iteration (Durand 1960, Kerner 1966: `zᵢ ← zᵢ − p(zᵢ)/∏_{j≠i}(zᵢ − zⱼ)`
/// on the monic polynomial, simultaneous for all roots, started on a circle inside
/// Cauchy's bound `1 + max|aₖ/aₙ|`), then polished by a few Newton steps. Accurate for simple
/// roots; multiple roots converge only linearly (pass a square-free `p`). `None` for the
/// zero polynomial or if the iteration leaves the finite numbers.
pub fn complex_roots_f64(p: &Poly<f64>) -> Option<Vec<crate::complex::Complex<f64>>> {
    use crate::complex::Complex;
    type C = Complex<f64>;
    let n = p.degree()?;
    if n == 0 {
        return Some(Vec::new());
    }
    let lc = p.leading();
    let c: Vec<C> = p
        .coeffs()
        .iter()
        .map(|x| Complex::new(x / lc, 0.0))
        .collect();
    let horner = |coeffs: &[C], z: &C| {
        coeffs
            .iter()
            .rev()
            .fold(Complex::new(0.0, 0.0), |acc, a| acc * z.clone() + a.clone())
    };
    let radius = 1.0
        + c[..n]
            .iter()
            .map(|z| z.norm_sq().sqrt())
            .fold(0.0, f64::max);
    let mut z: Vec<C> = (0..n)
        .map(|k| {
            let a = 2.0 * core::f64::consts::PI * (k as f64 + 0.25) / n as f64;
            Complex::new(radius * 0.9 * a.cos(), radius * 0.9 * a.sin())
        })
        .collect();
    for _ in 0..2000 {
        let mut moved: f64 = 0.0;
        for i in 0..n {
            let mut den = Complex::new(1.0, 0.0);
            for j in 0..n {
                if i != j {
                    den *= z[i].clone() - z[j].clone();
                }
            }
            if den.norm_sq() == 0.0 {
                // two iterates coincide: nudge instead of dividing by zero
                den = Complex::new(1e-300, 0.0);
            }
            let step = horner(&c, &z[i]) / den;
            moved = moved.max(step.norm_sq().sqrt());
            z[i] = z[i].clone() - step;
        }
        if moved < 1e-15 * radius {
            break;
        }
    }
    let dc: Vec<C> = (1..=n).map(|k| c[k].scale(&(k as f64))).collect();
    for w in z.iter_mut() {
        for _ in 0..8 {
            let d = horner(&dc, w);
            if d.norm_sq() == 0.0 {
                break;
            }
            *w = w.clone() - horner(&c, w) / d;
        }
    }
    z.iter()
        .all(|w| w.re.is_finite() && w.im.is_finite())
        .then_some(z)
}

/// The distinct real roots of `p` with their multiplicities, sorted: the isolating
/// intervals of [`isolate_real_roots`], each paired with the `k` of the square-free
/// factor `fₖ` ([`square_free_decomposition`]) that vanishes inside it.
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] for the zero polynomial.
pub fn isolate_real_roots_with_multiplicity(
    p: &Poly<Rational>,
) -> Result<Vec<(RootInterval, usize)>, AlgebraError> {
    let ivs = isolate_real_roots(p)?;
    let factors: Vec<(IntPoly, usize)> = square_free_decomposition(p)
        .into_iter()
        .filter_map(|(f, k)| IntPoly::primitive_of(&f).map(|fi| (fi, k)))
        .collect();
    Ok(ivs
        .into_iter()
        .map(|iv| {
            let k = factors
                .iter()
                .find(|(f, _)| {
                    if iv.is_exact() {
                        f.sign_at(&iv.lo) == 0
                    } else {
                        f.sign_at(&iv.lo) * f.sign_at(&iv.hi) < 0
                    }
                })
                .map_or(1, |(_, k)| *k);
            (iv, k)
        })
        .collect())
}

#[cfg(test)]
mod complex_root_tests {
    use super::*;

    /// The roots of `(x² + 1)(x − 2)(x + 1/2)(x² − 2x + 5)` (±i, 2, −1/2, 1 ± 2i), and a
    /// Wilkinson-like product of 8 real roots, to 1e-10.
    #[test]
    fn complex_roots_of_products_of_known_factors() {
        type Case = (Vec<f64>, Vec<(f64, f64)>);
        let cases: Vec<Case> = vec![
            (
                // (x² + 1)(x − 2)(x + 1/2)(x² − 2x + 5)
                vec![-5.0, -5.5, 2.0, -9.0, 8.0, -3.5, 1.0],
                vec![
                    (0.0, 1.0),
                    (0.0, -1.0),
                    (2.0, 0.0),
                    (-0.5, 0.0),
                    (1.0, 2.0),
                    (1.0, -2.0),
                ],
            ),
            (
                (1..=8).fold(vec![1.0], |acc, r| {
                    let mut out = vec![0.0; acc.len() + 1];
                    for (k, a) in acc.iter().enumerate() {
                        out[k + 1] += a;
                        out[k] -= a * r as f64;
                    }
                    out
                }),
                (1..=8).map(|r| (r as f64, 0.0)).collect(),
            ),
        ];
        for (coeffs, want) in cases {
            let z = complex_roots_f64(&Poly::new(coeffs)).expect("roots");
            assert_eq!(z.len(), want.len());
            for (re, im) in want {
                assert!(
                    z.iter()
                        .any(|w| (w.re - re).abs() + (w.im - im).abs() < 1e-8),
                    "root {re} + {im}i not found in {z:?}"
                );
            }
        }
        assert_eq!(complex_roots_f64(&Poly::new(vec![3.0])), Some(Vec::new()));
        assert_eq!(complex_roots_f64(&Poly::new(vec![])), None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    type P = Poly<Rational>;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from_parts_signed(IBig::from(a), IBig::from(b))
    }

    fn from_roots(roots: &[Rational]) -> P {
        roots.iter().fold(P::constant(Rational::one()), |acc, r| {
            &acc * &P::new(vec![-r.clone(), Rational::one()])
        })
    }

    #[test]
    fn isolates_simple_integer_roots() {
        let p = P::from_ints(&[6, -11, 6, -1]); // −(t−1)(t−2)(t−3)
        let ivs = isolate_real_roots(&p).expect("nonzero");
        assert_eq!(ivs.len(), 3);
        for (iv, r) in ivs.iter().zip([1, 2, 3]) {
            assert!(iv.contains(&Rational::from(r)), "{iv:?}");
        }
        assert_eq!(real_roots_f64(&p), vec![1.0, 2.0, 3.0]);
        assert_eq!(rational_roots(&p), vec![q(1, 1), q(2, 1), q(3, 1)]);
    }

    #[test]
    fn irrational_roots_and_refinement() {
        let p = P::from_ints(&[-2, 0, 1]); // t² − 2
        let ivs = isolate_real_roots(&p).expect("nonzero");
        assert_eq!(ivs.len(), 2);
        let mut iv = ivs[1].clone();
        let w = q(1, 1_000_000_000_000);
        iv.refine(&p, &w).expect("isolating");
        assert!(iv.width() <= w);
        assert!(iv.lo.clone() * iv.lo.clone() < q(2, 1));
        assert!(iv.hi.clone() * iv.hi.clone() > q(2, 1));
        assert_eq!(
            real_roots_f64(&p),
            vec![-core::f64::consts::SQRT_2, core::f64::consts::SQRT_2]
        );
        assert!(rational_roots(&p).is_empty());
    }

    #[test]
    fn zero_and_constants() {
        assert!(isolate_real_roots(&P::zero()).is_err());
        assert!(isolate_real_roots_in(&P::zero(), &q(0, 1), &q(1, 1)).is_err());
        assert!(isolate_real_roots(&P::constant(q(3, 1)))
            .expect("constant")
            .is_empty());
        assert!(real_roots_f64(&P::zero()).is_empty());
        assert!(rational_roots(&P::zero()).is_empty());
        assert!(real_roots_f64_of(&Poly::<f64>::zero()).is_err());
        assert!(real_roots_f64_of(&Poly::new(vec![1.0, f64::NAN])).is_err());
        let mut iv = RootInterval {
            lo: q(0, 1),
            hi: q(1, 1),
        };
        assert!(iv.refine(&P::zero(), &q(1, 10)).is_err());
        assert!(iv.refine(&P::from_ints(&[1, 1]), &q(1, 10)).is_err()); // no sign change
        assert!(iv.refine(&P::from_ints(&[-1, 2]), &q(0, 1)).is_err()); // width 0
        let mut bad = RootInterval {
            lo: q(1, 1),
            hi: q(0, 1),
        };
        assert!(bad.refine(&P::from_ints(&[-1, 2]), &q(1, 10)).is_err());
    }

    #[test]
    fn roots_at_zero_midpoints_and_endpoints() {
        // t(t−1)(t+1/2)² (t−3/4): 0 is the first midpoint
        let p =
            &from_roots(&[q(0, 1), q(1, 1), q(-1, 2), q(-1, 2), q(3, 4)]) * &P::constant(q(7, 3));
        let ivs = isolate_real_roots(&p).expect("nonzero");
        assert_eq!(ivs.len(), 4);
        assert_eq!(
            rational_roots(&p),
            vec![q(-1, 2), q(0, 1), q(3, 4), q(1, 1)]
        );
        let mult = isolate_real_roots_with_multiplicity(&p).expect("nonzero");
        assert_eq!(
            mult.iter().map(|(_, k)| *k).collect::<Vec<_>>(),
            vec![2, 1, 1, 1]
        );
        // closed interval with roots at both endpoints
        let inside = isolate_real_roots_in(&p, &q(-1, 2), &q(3, 4)).expect("ok");
        assert_eq!(inside.len(), 3);
        assert!(inside[0].is_exact() && inside[0].lo == q(-1, 2));
        assert!(inside[2].is_exact() && inside[2].lo == q(3, 4));
        assert_eq!(count_real_roots_in(&p, &q(1, 1), &q(1, 1)).expect("ok"), 1);
        assert_eq!(count_real_roots_in(&p, &q(2, 1), &q(5, 1)).expect("ok"), 0);
        assert!(count_real_roots_in(&p, &q(2, 1), &q(1, 1)).is_err());
    }

    #[test]
    fn refine_exact_and_f64_roots() {
        let p = P::from_ints(&[-1, 0, 0, 1, 1]); // t⁴ + t³ − 1
        let ivs = isolate_real_roots(&p).expect("nonzero");
        let roots = real_roots_f64(&p);
        assert_eq!(roots.len(), ivs.len());
        for (r, iv) in roots.iter().zip(&ivs) {
            let val = r.powi(4) + r.powi(3) - 1.0;
            assert!(val.abs() < 1e-14, "{r} {val}");
            assert_eq!(iv.root_f64(&p).expect("isolating"), *r);
        }
        let pf = Poly::new(vec![-1.0, 0.0, 0.0, 1.0, 1.0]);
        assert_eq!(real_roots_f64_of(&pf).expect("finite"), roots);
    }

    #[test]
    fn huge_and_tiny_coefficients() {
        // (t − 10⁻³⁰)(t − 10³⁰)(t² + 1)
        let tiny = Rational::from_parts(IBig::ONE, UBig::from(10u8).pow(30));
        let huge = Rational::from(IBig::from(UBig::from(10u8).pow(30)));
        let p = &from_roots(&[tiny.clone(), huge.clone()]) * &P::from_ints(&[1, 0, 1]);
        assert_eq!(rational_roots(&p), vec![tiny, huge]);
        let r = real_roots_f64(&p);
        assert_eq!(r, vec![1e-30, 1e30]);
        // Mignotte-like: t⁵ − 2(50t − 1)² has two very close roots near 1/50
        let m = &P::monomial(Rational::one(), 5) - &P::from_ints(&[-1, 50]).pow(2).scale(&q(2, 1));
        let ivs = isolate_real_roots(&m).expect("nonzero");
        assert_eq!(ivs.len(), 3);
        for w in ivs.windows(2) {
            assert!(w[0].hi <= w[1].lo);
        }
    }

    #[test]
    fn non_dyadic_intervals_and_f64_extremes() {
        let p = P::from_ints(&[-2, 0, 1]);
        // a user interval with non-dyadic ends
        let mut iv = RootInterval {
            lo: q(1, 3),
            hi: q(7, 3),
        };
        let w = Rational::from_parts(IBig::ONE, UBig::from(10u8).pow(40));
        iv.refine(&p, &w).expect("isolating");
        assert!(iv.width() <= w);
        assert!(&iv.lo * &iv.lo < q(2, 1) && &iv.hi * &iv.hi > q(2, 1));
        assert_eq!(
            iv.root_f64(&p).expect("isolating"),
            core::f64::consts::SQRT_2
        );
        let inside = isolate_real_roots_in(&p, &q(-1, 3), &q(5, 3)).expect("ok");
        assert_eq!(inside.len(), 1);
        assert!(inside[0].lo >= q(-1, 3) && inside[0].hi <= q(5, 3));
        // an exact root interval refines to itself; a non-root point is rejected
        let mut ex = RootInterval::exact(q(1, 2));
        ex.refine(&P::from_ints(&[-1, 2]), &q(1, 10)).expect("root");
        assert!(ex.is_exact());
        assert!(ex.refine(&P::from_ints(&[-1, 3]), &q(1, 10)).is_err());
        // roots beyond the f64 range and subnormal roots
        // ±√(MAX/MIN_POSITIVE) = ±2¹⁰²³·√(1 − 2⁻⁵³) = ±2¹⁰²³(1 − 2⁻⁵⁴ − …): rounds down
        let big = Poly::new(vec![f64::MAX, 0.0, -f64::MIN_POSITIVE]);
        let r = real_roots_f64_of(&big).expect("finite");
        let below = f64::from_bits(2f64.powi(1023).to_bits() - 1);
        assert_eq!(r, vec![-below, below]);
        let lin = Poly::new(vec![f64::MAX, -f64::MIN_POSITIVE]);
        assert_eq!(
            real_roots_f64_of(&lin).expect("finite"),
            vec![f64::INFINITY]
        );
        let tiny = Poly::new(vec![-5e-324, 1.0]);
        assert_eq!(real_roots_f64_of(&tiny).expect("finite"), vec![5e-324]);
        let sub = Poly::new(vec![-1e-310, 0.0, 1e10]);
        let r = real_roots_f64_of(&sub).expect("finite");
        assert_eq!(r.len(), 2);
        // 1e-310 is subnormal (relative spacing ~5e-14)
        assert!((r[1] / 1e-160 - 1.0).abs() < 1e-13, "{}", r[1]);
    }

    #[test]
    fn square_free_decomposition_works() {
        let p = &(&P::from_ints(&[-1, 1]).pow(3) * &P::from_ints(&[2, 1]).pow(2))
            * &P::from_ints(&[1, 0, 1]);
        let d = square_free_decomposition(&p);
        assert_eq!(
            d,
            vec![
                (P::from_ints(&[1, 0, 1]), 1),
                (P::from_ints(&[2, 1]), 2),
                (P::from_ints(&[-1, 1]), 3)
            ]
        );
        assert!(square_free_decomposition(&P::constant(q(5, 1))).is_empty());
    }

    #[test]
    fn rational_gcd_agrees_with_euclid() {
        let q = |n: i64, d: i64| Rational::from(n) / Rational::from(d);
        // (x − 1/3)(x + 2/7)² and (x − 1/3)(x + 2/7)(x² + 5/11)
        let l1 = Poly::new(vec![q(-1, 3), q(1, 1)]);
        let l2 = Poly::new(vec![q(2, 7), q(1, 1)]);
        let l3 = Poly::new(vec![q(5, 11), q(0, 1), q(1, 1)]);
        let a = &(&l1 * &l2) * &l2;
        let b = &(&l1 * &l2) * &l3;
        let g = gcd_rational(&a, &b);
        assert_eq!(g, (&l1 * &l2).monic());
        assert_eq!(g, a.gcd_euclid(&b));
        assert_eq!(gcd_rational(&a, &Poly::zero()), a.monic());
        assert!(gcd_rational(&Poly::zero(), &Poly::zero()).is_zero());
        assert_eq!(gcd_rational(&l1, &l3), Poly::constant(q(1, 1)));
    }
}
