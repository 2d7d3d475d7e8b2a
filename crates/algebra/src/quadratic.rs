//! Exact real quadratic extensions `Q(√d)`.
//!
//! A [`QuadExt`] is a number `a + b√d` with `a, b ∈ Q` and `d` a positive rational
//! non-square, so `Q(√d) = {a + b√d}` is a field of degree 2 over `Q` embedded in
//! the reals by `√d > 0`. This is the number type of the few irrational quantities
//! that exact constructions meet: the speed of a DPH curve `ω = √c·ω̃`, `|κ/τ|`,
//! `cos ψ` of a helix (docs/math/ph-curves.md, "DPH test and the rational Frenet frame": "store as (rational
//! part, squarefree radicand)").
//!
//! # The arithmetic (exact)
//!
//! * `(a₁ + b₁√d) ± (a₂ + b₂√d) = (a₁ ± a₂) + (b₁ ± b₂)√d`
//! * `(a₁ + b₁√d)(a₂ + b₂√d) = (a₁a₂ + d·b₁b₂) + (a₁b₂ + b₁a₂)√d`
//! * conjugate `x̄ = a − b√d`, norm `N(x) = x·x̄ = a² − d·b² ∈ Q`, which vanishes only
//!   for `x = 0` because `d` is not a square; hence `x⁻¹ = x̄ / N(x)`.
//! * sign: `sign(a + b√d)` is `sign(a)` or `sign(b)` when they agree (or one is 0);
//!   otherwise it is `sign(a)` if `a² > b²d` and `sign(b)` if `a² < b²d`.
//!
//! # Normal form of `d`
//!
//! The radicand is stored as an integer with its square factors removed:
//! `√(p/q) = √(pq)/q` and `√(f²s) = f√s`, so `√34` and `√(34/9) = (1/3)√34` live in the
//! same field and compare equal field tags. Square factors are found by trial
//! division by all primes below 2¹⁶; the cofactor left over is checked for being a
//! perfect square, so the reduction is complete for radicands below 2⁴⁸ (times
//! squares of small primes). Above that, two radicands of the same field may stay
//! different (e.g. `p²·q` with two huge primes); arithmetic still recognises them as
//! the same field because `Q(√d₁) = Q(√d₂)` iff `d₁d₂` is a rational square, which is
//! decided exactly.
//!
//! # Rationals and mixed fields
//!
//! [`QuadExt::rational`] (and `zero`, `one`, [`Scalar::from_rational`]) embeds `Q`
//! with the field tag `d = 0` ("no extension yet"); such an element combines with an
//! element of any `Q(√d)` and the result adopts that `d`. An element whose `b` is
//! zero is rational too and also combines with every field.
//!
//! Combining two *irrational* elements of different fields (`√2 + √3`) is a
//! programming error: the result does not lie in any `Q(√d)`. The operators
//! (`+ − × ÷`) then trip a `debug_assert!` in debug builds; in release builds they do
//! not panic but compute with the left operand's `d` (a wrong value, documented). Use
//! [`QuadExt::checked_add`], [`QuadExt::checked_sub`], [`QuadExt::checked_mul`] and
//! [`QuadExt::checked_div`] when the fields are not known to agree. Comparison and
//! equality are exact for *any* two elements, also from different fields.

use crate::error::AlgebraError;
use crate::rational::{format_rational, rational_sqrt, Rational};
use crate::scalar::{Field, Ring, Scalar};
use core::cmp::Ordering;
use core::fmt;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use dashu_base::{BitTest, SquareRoot, UnsignedAbs};
use dashu_int::{IBig, UBig};
use num_traits::{One, Zero};

/// Trial division bound for removing square factors from a radicand.
const TRIAL_BOUND: u64 = 1 << 16;

/// Bits of relative precision of the first enclosure in [`QuadExt`]'s `to_f64`.
const F64_GUARD_BITS: i64 = 72;

/// Maximum number of refinements of the enclosure in `to_f64` (each adds 64 bits).
const F64_MAX_REFINE: usize = 64;

/// An element `a + b√d` of the real quadratic field `Q(√d)`, exact.
///
/// Invariants: either `d = 0` and `b = 0` (a rational with no field chosen yet), or
/// `d` is a positive integer that is not a perfect square, stored with its square
/// factors removed (see the module documentation).
#[derive(Clone, Debug)]
pub struct QuadExt {
    a: Rational,
    b: Rational,
    d: Rational,
}

fn sign(q: &Rational) -> Ordering {
    q.cmp(&Rational::ZERO)
}

/// `floor(√n)` for a `u64`.
fn isqrt_u64(n: u64) -> u64 {
    let r = UBig::from(n).sqrt();
    u64::try_from(&r).unwrap_or(u64::MAX)
}

/// `n = f²·s` for a `u64`, removing square factors by trial division (see module doc).
fn split_square_u64(n: u64) -> (u64, u64) {
    let mut r = n;
    let mut f: u64 = 1;
    let mut s: u64 = 1;
    let mut p: u64 = 2;
    while p <= TRIAL_BOUND && p * p <= r {
        if r.checked_rem(p) == Some(0) {
            let mut e = 0u32;
            while r.checked_rem(p) == Some(0) {
                r /= p;
                e += 1;
            }
            for _ in 0..e / 2 {
                f *= p;
            }
            if e % 2 == 1 {
                s *= p;
            }
        }
        p += if p == 2 { 1 } else { 2 };
    }
    if r > 1 {
        let t = isqrt_u64(r);
        if t * t == r {
            f *= t;
        } else {
            s *= r;
        }
    }
    (f, s)
}

/// `n = f²·s` for a big integer (same algorithm as [`split_square_u64`]).
fn split_square_ubig(n: &UBig) -> (UBig, UBig) {
    if let Ok(small) = u64::try_from(n) {
        let (f, s) = split_square_u64(small);
        return (UBig::from(f), UBig::from(s));
    }
    let mut r = n.clone();
    let mut f = UBig::ONE;
    let mut s = UBig::ONE;
    let mut p: u64 = 2;
    while p <= TRIAL_BOUND {
        let pb = UBig::from(p);
        if &pb * &pb > r {
            break;
        }
        if (&r % &pb).is_zero() {
            let mut e = 0u32;
            while (&r % &pb).is_zero() {
                r /= &pb;
                e += 1;
            }
            for _ in 0..e / 2 {
                f *= &pb;
            }
            if e % 2 == 1 {
                s *= &pb;
            }
        }
        p += if p == 2 { 1 } else { 2 };
    }
    if r > UBig::ONE {
        let t = r.sqrt();
        if &t * &t == r {
            f *= t;
        } else {
            s *= r;
        }
    }
    (f, s)
}

/// Splits a rational into a square and a square-free integer: `q = c²·s` with
/// `c > 0` rational and `s` an integer free of square factors (as far as trial
/// division by primes below 2¹⁶ decides; see the module documentation), `sign(s) =
/// sign(q)`. For `q = 0` returns `(1, 0)`.
///
/// Method: `q = n/m` in lowest terms gives `q = (nm)/m²`; the integer `nm = f²s`
/// then yields `c = f/m`. Example: `34/9 = (1/3)²·34`, `8 = 2²·2`.
pub fn split_square(q: &Rational) -> (Rational, Rational) {
    if q.is_zero() {
        return (Rational::ONE, Rational::ZERO);
    }
    let n = q.numerator().clone().unsigned_abs();
    let m = q.denominator().clone();
    let (f, s) = split_square_ubig(&(&n * &m));
    let c = Rational::from_parts(IBig::from(f), m);
    let s = IBig::from(s);
    let s = if sign(q) == Ordering::Less { -s } else { s };
    (c, Rational::from(s))
}

/// The exact square root of a non-negative rational: rational when `q` is a square,
/// otherwise `c·√s` in `Q(√s)` with `q = c²s`, `s` the square-free part of `q` (see
/// [`split_square`]); so `√34` and `√(34/9)` are elements of the same field.
///
/// # Errors
/// [`AlgebraError::NotRepresentable`] for `q < 0` (no real square root).
pub fn sqrt_in_extension(q: &Rational) -> Result<QuadExt, AlgebraError> {
    if sign(q) == Ordering::Less {
        return Err(AlgebraError::NotRepresentable(format!(
            "square root of the negative rational {}",
            format_rational(q)
        )));
    }
    if let Some(r) = rational_sqrt(q) {
        return Ok(QuadExt::rational(r));
    }
    let (c, s) = split_square(q);
    Ok(QuadExt {
        a: Rational::ZERO,
        b: c,
        d: s,
    })
}

/// `sign(a + b√d)` for `d ≥ 0` (`d = 0` ignores `b`). See the module documentation.
fn sign_ab(a: &Rational, b: &Rational, d: &Rational) -> Ordering {
    let sa = sign(a);
    let sb = sign(b);
    if sb == Ordering::Equal || d.is_zero() {
        return sa;
    }
    if sa == Ordering::Equal || sa == sb {
        return sb;
    }
    match (a * a).cmp(&(b * b * d)) {
        Ordering::Greater => sa,
        Ordering::Less => sb,
        Ordering::Equal => Ordering::Equal,
    }
}

/// Rational bounds `lo ≤ √t ≤ hi` with `hi − lo = 2^(−k)`, for `t ≥ 0`.
/// `s = ⌊√⌊t·4ᵏ⌋⌋ = ⌊2ᵏ√t⌋`, `lo = s/2ᵏ`, `hi = (s+1)/2ᵏ`.
fn sqrt_bounds(t: &Rational, k: i64) -> (Rational, Rational) {
    let num = t.numerator().clone().unsigned_abs();
    let den = t.denominator().clone();
    let shift = k.unsigned_abs() as usize;
    let floor = if k >= 0 {
        (num << (2 * shift)) / den
    } else {
        num / (den << (2 * shift))
    };
    let s = floor.sqrt();
    let s1 = &s + UBig::ONE;
    if k >= 0 {
        let scale = UBig::ONE << shift;
        (
            Rational::from_parts(IBig::from(s), scale.clone()),
            Rational::from_parts(IBig::from(s1), scale),
        )
    } else {
        (
            Rational::from(IBig::from(s << shift)),
            Rational::from(IBig::from(s1 << shift)),
        )
    }
}

fn ratio_bits(q: &Rational) -> i64 {
    let n = q.numerator().clone().unsigned_abs().bit_len() as i64;
    let d = q.denominator().bit_len() as i64;
    n - d
}

fn rat_to_f64(q: &Rational) -> f64 {
    q.to_f64().value()
}

impl QuadExt {
    /// The element `a + b√d` of `Q(√d)`. The radicand is normalised (square factors
    /// moved into `b`): `new(a, b, 8) = a + 2b√2`, `new(a, b, 34/9) = a + (b/3)√34`.
    ///
    /// # Errors
    /// [`AlgebraError::InvalidArgument`] if `d ≤ 0` or `d` is the square of a rational
    /// (then `Q(√d) = Q`; use [`QuadExt::rational`] or [`sqrt_in_extension`]).
    pub fn new(a: Rational, b: Rational, d: Rational) -> Result<Self, AlgebraError> {
        if sign(&d) != Ordering::Greater {
            return Err(AlgebraError::InvalidArgument(format!(
                "quadratic extension Q(√d) needs d > 0, got d = {}",
                format_rational(&d)
            )));
        }
        let (c, s) = split_square(&d);
        if s.is_one() {
            return Err(AlgebraError::InvalidArgument(format!(
                "quadratic extension Q(√d) needs a non-square d, got d = {} = ({})²",
                format_rational(&d),
                format_rational(&c)
            )));
        }
        Ok(QuadExt { a, b: b * c, d: s })
    }

    /// `√d` itself, in `Q(√d)` (after normalisation `√8 = 2√2`).
    ///
    /// # Errors
    /// As [`QuadExt::new`]: `d ≤ 0` or `d` a rational square.
    pub fn sqrt_d(d: &Rational) -> Result<Self, AlgebraError> {
        QuadExt::new(Rational::ZERO, Rational::ONE, d.clone())
    }

    /// The rational `a`, not yet in any particular extension (field tag `d = 0`); it
    /// combines with elements of any `Q(√d)`.
    pub fn rational(a: Rational) -> Self {
        QuadExt {
            a,
            b: Rational::ZERO,
            d: Rational::ZERO,
        }
    }

    /// The rational part `a`.
    pub fn a(&self) -> &Rational {
        &self.a
    }

    /// The irrational coefficient `b` (zero for a rational element).
    pub fn b(&self) -> &Rational {
        &self.b
    }

    /// The normalised radicand `d` (a square-free positive integer), or `0` for the
    /// rationals without a chosen field.
    pub fn d(&self) -> &Rational {
        &self.d
    }

    /// `true` if `b = 0`, i.e. the element is rational.
    pub fn is_rational(&self) -> bool {
        self.b.is_zero()
    }

    /// The rational value if `b = 0`.
    pub fn to_rational(&self) -> Option<Rational> {
        if self.b.is_zero() {
            Some(self.a.clone())
        } else {
            None
        }
    }

    /// The conjugate `a − b√d` (the other embedding `√d ↦ −√d`).
    pub fn conj(&self) -> Self {
        QuadExt {
            a: self.a.clone(),
            b: -self.b.clone(),
            d: self.d.clone(),
        }
    }

    /// The field norm `N(a + b√d) = (a + b√d)(a − b√d) = a² − d·b² ∈ Q`; zero only for 0.
    pub fn norm(&self) -> Rational {
        &self.a * &self.a - &self.b * &self.b * &self.d
    }

    /// The exact sign of the real number `a + b√d` (see the module documentation).
    pub fn sign(&self) -> Ordering {
        sign_ab(&self.a, &self.b, &self.d)
    }

    /// `true` if both elements lie in a common field `Q(√d)` (always true when one
    /// of them is rational). `Q(√d₁) = Q(√d₂)` iff `d₁d₂` is a rational square.
    pub fn same_field(&self, other: &Self) -> bool {
        self.unify(other).is_ok()
    }

    /// Expresses `rhs` in the field of `self`: returns the common radicand and `rhs`'s
    /// `b` coefficient relative to it. If `d₁d₂ = s²` then `√d₂ = (s/d₁)√d₁`.
    fn unify(&self, rhs: &Self) -> Result<(Rational, Rational), AlgebraError> {
        if rhs.b.is_zero() {
            let d = if self.d.is_zero() { &rhs.d } else { &self.d };
            return Ok((d.clone(), Rational::ZERO));
        }
        if self.b.is_zero() || self.d == rhs.d {
            let d = if self.b.is_zero() { &rhs.d } else { &self.d };
            return Ok((d.clone(), rhs.b.clone()));
        }
        match rational_sqrt(&(&self.d * &rhs.d)) {
            Some(s) => Ok((self.d.clone(), &rhs.b * s / &self.d)),
            None => Err(AlgebraError::Mismatch(format!(
                "elements of different quadratic fields Q(√{}) and Q(√{})",
                format_rational(&self.d),
                format_rational(&rhs.d)
            ))),
        }
    }

    /// [`QuadExt::unify`] for the operators: a field mismatch is a programming error
    /// (debug assertion); release builds keep the left operand's `d`.
    fn unify_lossy(&self, rhs: &Self) -> (Rational, Rational) {
        let r = self.unify(rhs);
        debug_assert!(
            r.is_ok(),
            "QuadExt: arithmetic between different quadratic fields Q(√{}) and Q(√{}); use checked_* ops",
            self.d,
            rhs.d
        );
        match r {
            Ok(x) => x,
            Err(_) => (self.d.clone(), rhs.b.clone()),
        }
    }

    fn add_in(&self, d: Rational, rb: &Rational, rhs: &Self) -> Self {
        QuadExt {
            a: &self.a + &rhs.a,
            b: &self.b + rb,
            d,
        }
    }

    fn sub_in(&self, d: Rational, rb: &Rational, rhs: &Self) -> Self {
        QuadExt {
            a: &self.a - &rhs.a,
            b: &self.b - rb,
            d,
        }
    }

    fn mul_in(&self, d: Rational, rb: &Rational, rhs: &Self) -> Self {
        QuadExt {
            a: &self.a * &rhs.a + &self.b * rb * &d,
            b: &self.a * rb + &self.b * &rhs.a,
            d,
        }
    }

    /// The inverse `x̄ / N(x)`, `None` for zero.
    pub fn inverse(&self) -> Option<Self> {
        let n = self.norm();
        if n.is_zero() {
            return None;
        }
        Some(QuadExt {
            a: &self.a / &n,
            b: -(&self.b / &n),
            d: self.d.clone(),
        })
    }

    /// `self + rhs`.
    ///
    /// # Errors
    /// [`AlgebraError::Mismatch`] if both are irrational elements of different fields.
    pub fn checked_add(&self, rhs: &Self) -> Result<Self, AlgebraError> {
        let (d, rb) = self.unify(rhs)?;
        Ok(self.add_in(d, &rb, rhs))
    }

    /// `self − rhs`.
    ///
    /// # Errors
    /// [`AlgebraError::Mismatch`] if both are irrational elements of different fields.
    pub fn checked_sub(&self, rhs: &Self) -> Result<Self, AlgebraError> {
        let (d, rb) = self.unify(rhs)?;
        Ok(self.sub_in(d, &rb, rhs))
    }

    /// `self · rhs`.
    ///
    /// # Errors
    /// [`AlgebraError::Mismatch`] if both are irrational elements of different fields.
    pub fn checked_mul(&self, rhs: &Self) -> Result<Self, AlgebraError> {
        let (d, rb) = self.unify(rhs)?;
        Ok(self.mul_in(d, &rb, rhs))
    }

    /// `self / rhs = self · r̄hs / N(rhs)`.
    ///
    /// # Errors
    /// [`AlgebraError::DivisionByZero`] if `rhs = 0`, [`AlgebraError::Mismatch`] if both
    /// are irrational elements of different fields.
    pub fn checked_div(&self, rhs: &Self) -> Result<Self, AlgebraError> {
        let inv = rhs.inverse().ok_or_else(|| {
            AlgebraError::DivisionByZero("quadratic-extension division by zero".into())
        })?;
        self.checked_mul(&inv)
    }

    /// Nearest `f64` to `a + b√d`, correct to within rounding of an enclosure of
    /// relative width `< 2⁻⁷⁰` (in practice correctly rounded).
    ///
    /// Method: with `T = |b|√d`, exact integer square roots give rational bounds
    /// `T ∈ [s/2ᵏ, (s+1)/2ᵏ]`. If `a` and `b` have the same sign (or `a = 0`) then
    /// `x = a ± T` has no cancellation; otherwise `x = N(x)/x̄` with `x̄ = a ∓ T`, whose
    /// two terms have the same sign. Both ends of the resulting rational enclosure of
    /// `x` are rounded (correctly); when they round to the same `f64` that is the
    /// correctly rounded `x`, else the enclosure is refined by 64 more bits.
    fn to_f64_enclosure(&self) -> f64 {
        if self.b.is_zero() || self.d.is_zero() {
            return rat_to_f64(&self.a);
        }
        let a = &self.a;
        let t2 = &self.b * &self.b * &self.d;
        let sa = sign(a);
        let sb = sign(&self.b);
        let cancel = sa != Ordering::Equal && sa != sb;
        let norm = if cancel { a * a - &t2 } else { Rational::ZERO };
        let mut k = F64_GUARD_BITS - ratio_bits(&t2) / 2;
        let mut last = (Rational::ZERO, Rational::ZERO);
        for _ in 0..F64_MAX_REFINE {
            let (tlo, thi) = sqrt_bounds(&t2, k);
            let (lo, hi) = if !cancel {
                if sb == Ordering::Greater {
                    (a + &tlo, a + &thi)
                } else {
                    (a - &thi, a - &tlo)
                }
            } else {
                let (dlo, dhi) = if sb == Ordering::Greater {
                    (a - &thi, a - &tlo)
                } else {
                    (a + &tlo, a + &thi)
                };
                let q1 = &norm / &dlo;
                let q2 = &norm / &dhi;
                if q1 <= q2 {
                    (q1, q2)
                } else {
                    (q2, q1)
                }
            };
            let flo = rat_to_f64(&lo);
            let fhi = rat_to_f64(&hi);
            if flo == fhi {
                return flo;
            }
            last = (lo, hi);
            k += 64;
        }
        let mid = (last.0 + last.1) / Rational::from(2);
        rat_to_f64(&mid)
    }
}

impl From<Rational> for QuadExt {
    fn from(a: Rational) -> Self {
        QuadExt::rational(a)
    }
}

impl From<i64> for QuadExt {
    fn from(n: i64) -> Self {
        QuadExt::rational(Rational::from(n))
    }
}

/// Value equality: `a₁ + b₁√d₁ = a₂ + b₂√d₂` iff `a₁ = a₂`, `sign b₁ = sign b₂` and
/// `b₁²d₁ = b₂²d₂` (exact for any two elements; the field tag of a rational is ignored).
impl PartialEq for QuadExt {
    fn eq(&self, other: &Self) -> bool {
        if self.a != other.a {
            return false;
        }
        match (self.b.is_zero(), other.b.is_zero()) {
            (true, true) => true,
            (false, false) => {
                if self.d == other.d {
                    self.b == other.b
                } else {
                    sign(&self.b) == sign(&other.b)
                        && &self.b * &self.b * &self.d == &other.b * &other.b * &other.d
                }
            }
            _ => false,
        }
    }
}

impl Eq for QuadExt {}

/// The exact order of the reals, for any two elements (also of different fields).
///
/// Same field: `sign(x − y)`. Different fields: `x − y = A + B` with
/// `A = (a₁ − a₂) + b₁√d₁`, `B = −b₂√d₂`; if the signs of `A` and `B` differ, the one
/// of larger magnitude wins, decided by `sign(A² − B²)` with
/// `A² − B² = ((a₁−a₂)² + b₁²d₁ − b₂²d₂) + 2(a₁−a₂)b₁√d₁ ∈ Q(√d₁)`.
impl Ord for QuadExt {
    fn cmp(&self, other: &Self) -> Ordering {
        match self.unify(other) {
            Ok((d, rb)) => sign_ab(&(&self.a - &other.a), &(&self.b - &rb), &d),
            Err(_) => {
                let p = &self.a - &other.a;
                let s_a = sign_ab(&p, &self.b, &self.d);
                let s_b = sign(&other.b).reverse();
                if s_a == Ordering::Equal {
                    return s_b;
                }
                if s_a == s_b {
                    return s_a;
                }
                let r = &p * &p + &self.b * &self.b * &self.d - &other.b * &other.b * &other.d;
                let t = Rational::from(2) * &p * &self.b;
                match sign_ab(&r, &t, &self.d) {
                    Ordering::Greater => s_a,
                    Ordering::Less => s_b,
                    Ordering::Equal => Ordering::Equal,
                }
            }
        }
    }
}

impl PartialOrd for QuadExt {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// `a + b√d`, e.g. `1/2 + 3√5`, `-√2`, `1 - (2/3)√7`; a rational prints as `p/q`.
impl fmt::Display for QuadExt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.b.is_zero() {
            return f.write_str(&format_rational(&self.a));
        }
        let neg = sign(&self.b) == Ordering::Less;
        let babs = if neg { -self.b.clone() } else { self.b.clone() };
        let coef = if babs.is_one() {
            String::new()
        } else if babs.denominator() == &UBig::ONE {
            format_rational(&babs)
        } else {
            format!("({})", format_rational(&babs))
        };
        let term = format!("{coef}√{}", format_rational(&self.d));
        if self.a.is_zero() {
            if neg {
                write!(f, "-{term}")
            } else {
                f.write_str(&term)
            }
        } else {
            let op = if neg { '-' } else { '+' };
            write!(f, "{} {op} {term}", format_rational(&self.a))
        }
    }
}

impl Add<&QuadExt> for &QuadExt {
    type Output = QuadExt;
    fn add(self, rhs: &QuadExt) -> QuadExt {
        let (d, rb) = self.unify_lossy(rhs);
        self.add_in(d, &rb, rhs)
    }
}

impl Sub<&QuadExt> for &QuadExt {
    type Output = QuadExt;
    fn sub(self, rhs: &QuadExt) -> QuadExt {
        let (d, rb) = self.unify_lossy(rhs);
        self.sub_in(d, &rb, rhs)
    }
}

impl Mul<&QuadExt> for &QuadExt {
    type Output = QuadExt;
    fn mul(self, rhs: &QuadExt) -> QuadExt {
        let (d, rb) = self.unify_lossy(rhs);
        self.mul_in(d, &rb, rhs)
    }
}

/// Division `x / y = x · ȳ / N(y)`.
///
/// # Panics
/// On division by zero, like [`Rational`]'s division. Use [`Field::inv`] or
/// [`QuadExt::checked_div`] to get `None`/an error instead.
impl Div<&QuadExt> for &QuadExt {
    type Output = QuadExt;
    fn div(self, rhs: &QuadExt) -> QuadExt {
        match rhs.inverse() {
            Some(inv) => {
                let (d, rb) = self.unify_lossy(&inv);
                self.mul_in(d, &rb, &inv)
            }
            None => panic!("QuadExt: division by zero"),
        }
    }
}

impl Neg for &QuadExt {
    type Output = QuadExt;
    fn neg(self) -> QuadExt {
        QuadExt {
            a: -self.a.clone(),
            b: -self.b.clone(),
            d: self.d.clone(),
        }
    }
}

impl Neg for QuadExt {
    type Output = QuadExt;
    fn neg(self) -> QuadExt {
        QuadExt {
            a: -self.a,
            b: -self.b,
            d: self.d,
        }
    }
}

macro_rules! forward_binop {
    ($tr:ident, $m:ident, $tra:ident, $ma:ident) => {
        impl $tr<QuadExt> for QuadExt {
            type Output = QuadExt;
            fn $m(self, rhs: QuadExt) -> QuadExt {
                (&self).$m(&rhs)
            }
        }
        impl $tr<&QuadExt> for QuadExt {
            type Output = QuadExt;
            fn $m(self, rhs: &QuadExt) -> QuadExt {
                (&self).$m(rhs)
            }
        }
        impl $tr<QuadExt> for &QuadExt {
            type Output = QuadExt;
            fn $m(self, rhs: QuadExt) -> QuadExt {
                self.$m(&rhs)
            }
        }
        impl $tra<QuadExt> for QuadExt {
            fn $ma(&mut self, rhs: QuadExt) {
                *self = (&*self).$m(&rhs);
            }
        }
        impl $tra<&QuadExt> for QuadExt {
            fn $ma(&mut self, rhs: &QuadExt) {
                *self = (&*self).$m(rhs);
            }
        }
    };
}

forward_binop!(Add, add, AddAssign, add_assign);
forward_binop!(Sub, sub, SubAssign, sub_assign);
forward_binop!(Mul, mul, MulAssign, mul_assign);
forward_binop!(Div, div, DivAssign, div_assign);

impl Zero for QuadExt {
    fn zero() -> Self {
        QuadExt::rational(Rational::ZERO)
    }
    fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
}

impl One for QuadExt {
    fn one() -> Self {
        QuadExt::rational(Rational::ONE)
    }
}

impl Ring for QuadExt {
    fn from_i64(n: i64) -> Self {
        QuadExt::from(n)
    }
}

impl Field for QuadExt {
    fn inv(&self) -> Option<Self> {
        self.inverse()
    }
}

impl Scalar for QuadExt {
    const EXACT: bool = true;
    const UNIT_ROUNDOFF: f64 = 0.0;
    fn from_rational(q: &Rational) -> Self {
        QuadExt::rational(q.clone())
    }
    fn to_f64(&self) -> f64 {
        self.to_f64_enclosure()
    }
    fn abs(&self) -> Self {
        if self.sign() == Ordering::Less {
            -self
        } else {
            self.clone()
        }
    }
    fn to_rational(&self) -> Option<Rational> {
        QuadExt::to_rational(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_parts_signed(IBig::from(p), IBig::from(d))
    }

    fn qe(a: i64, b: i64, d: i64) -> QuadExt {
        QuadExt::new(q(a, 1), q(b, 1), q(d, 1)).expect("valid")
    }

    #[test]
    fn rejects_bad_radicands() {
        assert!(QuadExt::new(q(1, 1), q(1, 1), q(0, 1)).is_err());
        assert!(QuadExt::new(q(1, 1), q(1, 1), q(-2, 1)).is_err());
        assert!(QuadExt::new(q(1, 1), q(1, 1), q(9, 4)).is_err());
        assert!(QuadExt::sqrt_d(&q(4, 1)).is_err());
        assert!(QuadExt::sqrt_d(&q(2, 1)).is_ok());
    }

    #[test]
    fn normalises_radicand() {
        let x = QuadExt::sqrt_d(&q(8, 1)).expect("valid");
        assert_eq!(x.d(), &q(2, 1));
        assert_eq!(x.b(), &q(2, 1));
        let y = sqrt_in_extension(&q(34, 9)).expect("non-negative");
        let z = sqrt_in_extension(&q(34, 1)).expect("non-negative");
        assert_eq!(y.d(), z.d());
        assert_eq!(&y * &q_ext(3), z);
        assert_eq!(
            sqrt_in_extension(&q(9, 4)).expect("square"),
            QuadExt::rational(q(3, 2))
        );
        assert!(sqrt_in_extension(&q(-1, 1)).is_err());
        assert_eq!(split_square(&q(12, 5)), (q(2, 5), q(15, 1)));
        assert_eq!(split_square(&q(-18, 1)), (q(3, 1), q(-2, 1)));
        // A large radicand: 2⁶⁴ · 3 · 10007²
        let big = Rational::from(IBig::from(UBig::ONE << 64) * IBig::from(3 * 10007u64 * 10007));
        let (c, s) = split_square(&big);
        assert_eq!(s, q(3, 1));
        assert_eq!(&c * &c * &s, big);
    }

    fn q_ext(n: i64) -> QuadExt {
        QuadExt::from(n)
    }

    #[test]
    fn arithmetic() {
        let s2 = qe(0, 1, 2);
        assert_eq!(&s2 * &s2, q_ext(2));
        let x = qe(1, 1, 2); // 1 + √2
        let y = qe(1, -1, 2); // 1 − √2
        assert_eq!(&x * &y, q_ext(-1));
        assert_eq!(x.norm(), q(-1, 1));
        assert_eq!(x.conj(), y);
        assert_eq!(x.inv().expect("nonzero"), -&y);
        assert_eq!(&x / &x, q_ext(1));
        assert!(q_ext(0).inv().is_none());
        assert!(x.checked_div(&QuadExt::zero()).is_err());
        // rational embedding adopts the other field
        let r = q_ext(3) + x.clone();
        assert_eq!(r.d(), &q(2, 1));
        assert_eq!(r, qe(4, 1, 2));
        // compatible but different radicands are unified
        assert_eq!((&s2 - &s2).to_rational(), Some(q(0, 1)));
    }

    #[test]
    fn mixed_fields_checked() {
        let s2 = qe(0, 1, 2);
        let s3 = qe(0, 1, 3);
        assert!(s2.checked_add(&s3).is_err());
        assert!(s2.checked_mul(&s3).is_err());
        assert!(!s2.same_field(&s3));
        assert!(s2.same_field(&q_ext(5)));
        // comparison works across fields: √2 < √3, 1 + √2 > √3 (2.414 > 1.732)
        assert!(s2 < s3);
        assert!(qe(1, 1, 2) > s3);
        assert!(qe(-1, 1, 2) < qe(0, 1, 3) - q_ext(1)); // 0.414 < 0.732
        assert_ne!(s2, s3);
        // same field with unreduced radicands (built directly): 2√3 vs √12
        let a = QuadExt {
            a: q(0, 1),
            b: q(1, 1),
            d: q(12, 1),
        };
        let b = qe(0, 2, 3);
        assert_eq!(a, b);
        assert_eq!(a.cmp(&b), Ordering::Equal);
        assert_eq!(a.checked_sub(&b).expect("same field"), q_ext(0));
    }

    #[test]
    #[cfg(debug_assertions)]
    #[should_panic(expected = "different quadratic fields")]
    fn mixing_fields_with_operators_is_a_debug_assertion() {
        let _ = qe(0, 1, 2) + qe(0, 1, 3);
    }

    #[test]
    fn ordering_and_sign() {
        // 3 − 2√2 = 0.1716 > 0, 1 − √2 < 0, 7 − 5√2 = −0.0711 < 0
        assert_eq!(qe(3, -2, 2).sign(), Ordering::Greater);
        assert_eq!(qe(1, -1, 2).sign(), Ordering::Less);
        assert_eq!(qe(7, -5, 2).sign(), Ordering::Less);
        assert!(qe(1, 1, 2) > q_ext(2));
        assert!(qe(1, 1, 2) < q_ext(3));
        assert_eq!(Scalar::abs(&qe(1, -1, 2)), qe(-1, 1, 2));
    }

    #[test]
    fn to_f64_is_accurate_under_cancellation() {
        // 1393 − 985√2 ≈ −3.5894e−4 (a Pell-type near cancellation)
        let x = qe(1393, -985, 2);
        let exact = -0.000_358_937_498_623_069_7_f64;
        assert!((Scalar::to_f64(&x) - exact).abs() <= exact.abs() * 4.0 * f64::EPSILON);
        assert_eq!(Scalar::to_f64(&qe(0, 1, 2)), std::f64::consts::SQRT_2);
        assert_eq!(Scalar::to_f64(&qe(1, 1, 2)), 1.0 + std::f64::consts::SQRT_2);
        assert_eq!(Scalar::to_f64(&q_ext(-3)), -3.0);
        // (√2 − 1)^40 is tiny; the naive formula would lose every digit
        let mut p = q_ext(1);
        for _ in 0..40 {
            p *= qe(-1, 1, 2);
        }
        let v = Scalar::to_f64(&p);
        let expect = (std::f64::consts::SQRT_2 - 1.0).powi(40);
        assert!((v - expect).abs() <= expect * 1e-12, "{v} vs {expect}");
    }

    #[test]
    fn display() {
        assert_eq!(qe(1, 3, 5).to_string(), "1 + 3√5");
        assert_eq!(qe(0, -1, 2).to_string(), "-√2");
        assert_eq!(qe(2, -1, 7).to_string(), "2 - √7");
        let x = QuadExt::new(q(1, 2), q(2, 3), q(7, 1)).expect("valid");
        assert_eq!(x.to_string(), "1/2 + (2/3)√7");
        assert_eq!(q_ext(-4).to_string(), "-4");
    }
}
