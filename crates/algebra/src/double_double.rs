//! Double-double arithmetic: a real number as the unevaluated sum `hi + lo` of two `f64`s
//! with `hi = fl(hi + lo)`, about 106 significant bits (Dekker 1971, "A floating-point
//! technique for extending the available precision", Numer. Math. 18; Hida, Li, Bailey
//! 2001, "Algorithms for quad-double precision floating point arithmetic", ARITH-15).
//!
//! The error-free transformations are Knuth's TwoSum (The Art of Computer Programming,
//! vol. 2, §4.2.2, Theorem B), Dekker's Fast2Sum (`|a| ≥ |b|`) and the product
//! `a·b = p + e` with `e = fma(a, b, −p)` (`f64::mul_add`, exact for finite results
//! without underflow). The operations and their proven relative error bounds, with
//! `u = 2⁻⁵³` (Joldes, Muller, Popescu 2017, "Tight and rigorous error bounds for basic
//! building blocks of double-word arithmetic", ACM TOMS 44(2), Algorithms 6, 9, 12, 17):
//!
//! | operation | algorithm | relative error |
//! |---|---|---|
//! | `x ± y` | AccurateDWPlusDW (Alg. 6) | `3u²/(1 − 4u)` |
//! | `x · y` | DWTimesDW3 (Alg. 12, FMA) | `5u²` |
//! | `x / y` | DWDivDW2 (Alg. 17) | `15u² + 56u³` |
//! | `√x` | one Newton step on the `f64` root (Karp, Markstein 1997, "High-precision division and square root", ACM TOMS 23(4)) | `< 3u²` (below) |
//!
//! `√x`: with `s = fl(√hi)` and `x = s²(1 + δ)`, `|δ| ≤ 2u + u²`, the step
//! `s + r/(2s)`, `r = x − s²` (the square `s² = p + e` exact, the difference in
//! double-double), has the truncation error `s·δ²/8 ≤ s·u²/2`, plus `u·|r/(2s)| ≤ u²s` for
//! rounding `r` to its leading part and the same for the division: below `3u²` relative.
//! The unit tests check every bound against exact rationals on random operands.
//!
//! [`DoubleDouble`] is a [`Scalar`] with `EXACT = false`: the float path of `rcagd build
//! --float` runs the constructions whose `f64` builds lose digits to cancellation in it and
//! rounds the results once to `f64` (`crates/cli/src/ops/arith.rs`).

use crate::rational::Rational;
use crate::scalar::{Field, Ring, Scalar};
use core::cmp::Ordering;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use num_traits::{One, Zero};

/// A double-double number `hi + lo` (normalized: `hi = fl(hi + lo)`, so `|lo| ≤ ulp(hi)/2`).
#[derive(Clone, Copy, Debug, Default)]
pub struct DoubleDouble {
    hi: f64,
    lo: f64,
}

/// Knuth's TwoSum: `s + e = a + b` exactly, `s = fl(a + b)`.
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// Dekker's Fast2Sum for `|a| ≥ |b|` (or `a = 0`): `s + e = a + b` exactly.
#[inline]
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let e = b - (s - a);
    (s, e)
}

/// `p + e = a·b` exactly (`p = fl(a·b)`, `e` by one fused multiply-add).
#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let e = a.mul_add(b, -p);
    (p, e)
}

impl DoubleDouble {
    /// The double-double of one `f64` (exact).
    pub const fn from_f64(x: f64) -> Self {
        DoubleDouble { hi: x, lo: 0.0 }
    }

    /// The leading part `hi` (the `f64` nearest to the value).
    pub fn hi(&self) -> f64 {
        self.hi
    }

    /// The trailing part `lo`.
    pub fn lo(&self) -> f64 {
        self.lo
    }

    /// `hi + lo` normalized by Fast2Sum (`|hi| ≥ |lo|`).
    fn renorm(hi: f64, lo: f64) -> Self {
        let (h, l) = quick_two_sum(hi, lo);
        if h.is_finite() {
            DoubleDouble { hi: h, lo: l }
        } else {
            DoubleDouble { hi: h, lo: 0.0 }
        }
    }

    /// `true` if both parts are finite.
    pub fn is_finite(&self) -> bool {
        self.hi.is_finite() && self.lo.is_finite()
    }

    /// `self · b` for an `f64` `b` (DWTimesFP3, Joldes et al. 2017, Alg. 9: `2u²`).
    fn mul_f64(self, b: f64) -> Self {
        let (ch, cl1) = two_prod(self.hi, b);
        let cl3 = self.lo.mul_add(b, cl1);
        Self::renorm(ch, cl3)
    }

    /// `√self` for `self ≥ 0` (one Newton step on the `f64` root, module docs), `None` for
    /// a negative or non-finite value.
    pub fn sqrt(&self) -> Option<Self> {
        if !self.is_finite() || *self < Self::zero() {
            return None;
        }
        if self.hi == 0.0 {
            return Some(Self::zero());
        }
        let s = self.hi.sqrt();
        let (p, e) = two_prod(s, s);
        let r = *self - DoubleDouble { hi: p, lo: e };
        let corr = r.hi / (2.0 * s);
        Some(Self::renorm(s, corr))
    }
}

impl PartialEq for DoubleDouble {
    fn eq(&self, other: &Self) -> bool {
        self.hi == other.hi && self.lo == other.lo
    }
}

impl PartialOrd for DoubleDouble {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        match self.hi.partial_cmp(&other.hi)? {
            Ordering::Equal => self.lo.partial_cmp(&other.lo),
            o => Some(o),
        }
    }
}

impl Add for DoubleDouble {
    type Output = Self;
    /// AccurateDWPlusDW (Joldes et al. 2017, Alg. 6; Hida et al. 2001, IEEE add).
    fn add(self, b: Self) -> Self {
        let (sh, sl) = two_sum(self.hi, b.hi);
        let (th, tl) = two_sum(self.lo, b.lo);
        let c = sl + th;
        let (vh, vl) = quick_two_sum(sh, c);
        let w = tl + vl;
        Self::renorm(vh, w)
    }
}

impl Neg for DoubleDouble {
    type Output = Self;
    fn neg(self) -> Self {
        DoubleDouble {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Sub for DoubleDouble {
    type Output = Self;
    fn sub(self, b: Self) -> Self {
        self + (-b)
    }
}

impl Mul for DoubleDouble {
    type Output = Self;
    /// DWTimesDW3 (Joldes et al. 2017, Alg. 12).
    fn mul(self, b: Self) -> Self {
        let (ch, cl1) = two_prod(self.hi, b.hi);
        let tl0 = self.lo * b.lo;
        let tl1 = self.hi.mul_add(b.lo, tl0);
        let cl2 = self.lo.mul_add(b.hi, tl1);
        let cl3 = cl1 + cl2;
        Self::renorm(ch, cl3)
    }
}

impl Div for DoubleDouble {
    type Output = Self;
    /// DWDivDW2 (Joldes et al. 2017, Alg. 17). Division by zero gives a non-finite value
    /// (as `f64`); [`Field::inv`] refuses zero.
    fn div(self, b: Self) -> Self {
        let th = self.hi / b.hi;
        if !th.is_finite() {
            return DoubleDouble { hi: th, lo: 0.0 };
        }
        let r = b.mul_f64(th);
        let pi_h = self.hi - r.hi;
        let d_l = self.lo - r.lo;
        let d = pi_h + d_l;
        let tl = d / b.hi;
        Self::renorm(th, tl)
    }
}

impl AddAssign for DoubleDouble {
    fn add_assign(&mut self, b: Self) {
        *self = *self + b;
    }
}
impl SubAssign for DoubleDouble {
    fn sub_assign(&mut self, b: Self) {
        *self = *self - b;
    }
}
impl MulAssign for DoubleDouble {
    fn mul_assign(&mut self, b: Self) {
        *self = *self * b;
    }
}
impl DivAssign for DoubleDouble {
    fn div_assign(&mut self, b: Self) {
        *self = *self / b;
    }
}

impl Zero for DoubleDouble {
    fn zero() -> Self {
        DoubleDouble { hi: 0.0, lo: 0.0 }
    }
    fn is_zero(&self) -> bool {
        self.hi == 0.0 && self.lo == 0.0
    }
}

impl One for DoubleDouble {
    fn one() -> Self {
        DoubleDouble { hi: 1.0, lo: 0.0 }
    }
}

impl Ring for DoubleDouble {
    /// Exact for every `i64` (its high bits and the rest, each exact in `f64`).
    fn from_i64(n: i64) -> Self {
        let hi = n as f64;
        // |n − hi| ≤ 2¹⁰: exact in f64 (i128: `hi` may be 2⁶³)
        let rest = (i128::from(n) - hi as i128) as f64;
        Self::renorm(hi, rest)
    }
}

impl Field for DoubleDouble {
    fn pivot_size(&self) -> Option<f64> {
        Some(self.hi.abs())
    }
}

impl Scalar for DoubleDouble {
    const EXACT: bool = false;
    /// `u² = 2⁻¹⁰⁶` (Joldes, Muller, Popescu 2017: the relative error bounds of the
    /// operations are small multiples of it).
    const UNIT_ROUNDOFF: f64 = (f64::EPSILON / 2.0) * (f64::EPSILON / 2.0);
    /// `hi = RN(q)`, `lo = RN(q − hi)` (the difference exact over Q): the value is within
    /// `u²·|q|` of `q` (for `q` in the normal range of `f64`).
    fn from_rational(q: &Rational) -> Self {
        let hi = q.to_f64().value();
        if !hi.is_finite() || hi == 0.0 {
            return Self::from_f64(hi);
        }
        let lo = match Rational::try_from(hi) {
            Ok(h) => (q - &h).to_f64().value(),
            Err(_) => 0.0,
        };
        Self::renorm(hi, lo)
    }
    /// The leading part: the `f64` nearest to `hi + lo` (up to ties, which the
    /// normalization `hi = fl(hi + lo)` breaks to even).
    fn to_f64(&self) -> f64 {
        self.hi
    }
    fn abs(&self) -> Self {
        if self.hi < 0.0 || (self.hi == 0.0 && self.lo < 0.0) {
            -*self
        } else {
            *self
        }
    }
    /// The exact value `hi + lo` (`None` if not finite).
    fn to_rational(&self) -> Option<Rational> {
        let h = Rational::try_from(self.hi).ok()?;
        let l = Rational::try_from(self.lo).ok()?;
        Some(h + l)
    }
    fn sqrt_inexact(&self) -> Option<Self> {
        self.sqrt()
    }
}

impl core::fmt::Display for DoubleDouble {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "{}", self.hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// `u² = 2⁻¹⁰⁶`.
    fn u2() -> Rational {
        Rational::from_parts_signed(1.into(), dashu_int::IBig::from(1) << 106)
    }

    fn rel_err(got: &DoubleDouble, want: &Rational) -> Rational {
        let g = got.to_rational().expect("finite");
        let d = &g - want;
        let d = if d < Rational::zero() { -d } else { d };
        let w = if *want < Rational::zero() {
            -want.clone()
        } else {
            want.clone()
        };
        if w.is_zero() {
            d
        } else {
            d / w
        }
    }

    fn within(got: &DoubleDouble, want: &Rational, k: i64) -> bool {
        rel_err(got, want) <= u2() * Rational::from(k)
    }

    /// Random double-doubles: a rational `p/q` with large numerator and denominator
    /// rounded to ~106 bits, times a power of two.
    fn dd() -> impl Strategy<Value = DoubleDouble> {
        (any::<i64>(), 1i64..i64::MAX, -40i32..40).prop_map(|(p, q, e)| {
            let x = DoubleDouble::from_rational(&Rational::from_parts_signed(p.into(), q.into()));
            x.mul_f64(2f64.powi(e))
        })
    }

    fn q(x: &DoubleDouble) -> Rational {
        x.to_rational().expect("finite")
    }

    #[test]
    fn a_third_has_106_bits() {
        let third = DoubleDouble::from_rational(&Rational::from_parts_signed(1.into(), 3.into()));
        assert!(within(
            &third,
            &Rational::from_parts_signed(1.into(), 3.into()),
            1
        ));
        assert_eq!(third.to_f64(), 1.0 / 3.0);
        assert!(third.lo() != 0.0);
        let x = DoubleDouble::from_i64(i64::MAX);
        assert_eq!(q(&x), Rational::from(i64::MAX));
        let x = DoubleDouble::from_i64(i64::MIN + 1);
        assert_eq!(q(&x), Rational::from(i64::MIN + 1));
    }

    #[test]
    fn cancellation_keeps_the_second_word() {
        // (1 + 2⁻⁶⁰) − 1 = 2⁻⁶⁰: lost in f64, exact in double-double
        let a = DoubleDouble::from_f64(1.0) + DoubleDouble::from_f64(2f64.powi(-60));
        let d = a - DoubleDouble::one();
        assert_eq!(d.to_f64(), 2f64.powi(-60));
        let s = DoubleDouble::from_i64(2).sqrt().expect("non-negative");
        let sq = s * s - DoubleDouble::from_i64(2);
        assert!(sq.to_f64().abs() < 1e-30);
        assert!(DoubleDouble::from_i64(-1).sqrt().is_none());
        assert_eq!(DoubleDouble::zero().sqrt(), Some(DoubleDouble::zero()));
    }

    #[test]
    fn order_and_abs() {
        let a = DoubleDouble::from_f64(1.0) + DoubleDouble::from_f64(1e-20);
        let b = DoubleDouble::from_f64(1.0);
        assert!(a > b);
        assert!(-a < -b);
        assert_eq!(a.abs(), a);
        assert_eq!((-a).abs(), a);
        assert_eq!(Field::inv(&DoubleDouble::zero()), None);
    }

    proptest! {
        #[test]
        fn from_rational_is_within_u2(p in any::<i64>(), d in 1i64..i64::MAX) {
            let want = Rational::from_parts_signed(p.into(), d.into());
            let x = DoubleDouble::from_rational(&want);
            prop_assert!(within(&x, &want, 1), "{x:?}");
            prop_assert_eq!(x.to_f64(), want.to_f64().value());
        }

        #[test]
        fn sums_are_within_3u2(a in dd(), b in dd()) {
            let want = q(&a) + q(&b);
            prop_assert!(within(&(a + b), &want, 3), "{a:?} + {b:?}");
            let want = q(&a) - q(&b);
            prop_assert!(within(&(a - b), &want, 3), "{a:?} - {b:?}");
        }

        #[test]
        fn products_are_within_5u2(a in dd(), b in dd()) {
            let want = q(&a) * q(&b);
            prop_assert!(within(&(a * b), &want, 5), "{a:?} * {b:?}");
        }

        #[test]
        fn quotients_are_within_16u2(a in dd(), b in dd()) {
            prop_assume!(!b.is_zero());
            let want = q(&a) / q(&b);
            prop_assert!(within(&(a / b), &want, 16), "{a:?} / {b:?}");
        }

        #[test]
        fn square_roots_are_within_3u2(a in dd()) {
            let a = a.abs();
            let s = a.sqrt().expect("non-negative");
            // s = √a·(1 + ε), |ε| < 3u²: |s² − a| < 7u²·a (the square exact over Q)
            let sq = q(&s) * q(&s);
            prop_assert!(rel_err_q(&sq, &q(&a)) <= u2() * Rational::from(7), "√{a:?} = {s:?}");
        }

        #[test]
        fn exact_roundtrip_and_order(a in dd(), b in dd()) {
            prop_assert_eq!(DoubleDouble::from_rational(&q(&a)), a);
            prop_assert_eq!(a < b, q(&a) < q(&b));
            prop_assert_eq!(a == b, q(&a) == q(&b));
        }
    }

    fn rel_err_q(got: &Rational, want: &Rational) -> Rational {
        let d = got - want;
        let d = if d < Rational::zero() { -d } else { d };
        if want.is_zero() {
            d
        } else {
            d / want.clone()
        }
    }
}
