//! Closed real intervals with exact rational end points, rounded outward to a dyadic grid:
//! rigorous enclosures for quantities that are not rational (square roots, real roots of
//! polynomials) and everything computed from them.
//!
//! Every operation returns an interval that contains `x ∘ y` for all `x ∈ X`, `y ∈ Y`
//! (Moore, *Interval Analysis*, 1966): sums exactly, products as the hull of the four end
//! point products, square roots and reciprocals from the monotone end points. The end
//! points live on the grid `2^−GRID_BITS ℤ` (fixed point); after each product, reciprocal
//! or square root they are rounded *outward* to it, so the sizes of the numbers stay
//! bounded (the price is an absolute widening of at most `2^−GRID_BITS ≈ 10^−77` per
//! operation; the enclosure property is kept). Intervals implement [`Ring`], so `Poly<Interval>` and the Bernstein routines
//! work on them.

use crate::quadratic::QuadExt;
use crate::rational::Rational;
use crate::scalar::Ring;
use core::cmp::Ordering;
use core::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use dashu_base::{Abs, Approximation, BitTest, Sign, SquareRoot, UnsignedAbs};
use dashu_int::{IBig, UBig};
use num_traits::{One, Zero};

/// Fractional bits of the outward-rounding grid.
pub const GRID_BITS: usize = 256;

/// `2^e` as an exact rational.
pub fn pow2(e: isize) -> Rational {
    if e >= 0 {
        Rational::from(UBig::ONE << e.unsigned_abs())
    } else {
        Rational::from_parts(IBig::ONE, UBig::ONE << e.unsigned_abs())
    }
}

/// A closed interval `[lo, hi]`, `lo ≤ hi`, with end points on the grid `2^−GRID_BITS ℤ`,
/// stored as the integers `lo·2^GRID_BITS`, `hi·2^GRID_BITS` (fixed point: no gcd per
/// operation).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Interval {
    lo: IBig,
    hi: IBig,
}

/// `⌊a/b⌋` for `b > 0`.
fn floor_div(a: &IBig, b: &IBig) -> IBig {
    let (q, r) = (a / b, a % b);
    if r < IBig::ZERO {
        q - IBig::ONE
    } else {
        q
    }
}

/// `⌈a/b⌉` for `b > 0`.
fn ceil_div(a: &IBig, b: &IBig) -> IBig {
    let (q, r) = (a / b, a % b);
    if r > IBig::ZERO {
        q + IBig::ONE
    } else {
        q
    }
}

/// `⌊q·2^B⌋`.
fn fix_down(q: &Rational) -> IBig {
    floor_div(
        &(q.numerator() << GRID_BITS),
        &IBig::from(q.denominator().clone()),
    )
}

/// `⌈q·2^B⌉`.
fn fix_up(q: &Rational) -> IBig {
    ceil_div(
        &(q.numerator() << GRID_BITS),
        &IBig::from(q.denominator().clone()),
    )
}

fn unfix(n: &IBig) -> Rational {
    Rational::from_parts(n.clone(), UBig::ONE << GRID_BITS)
}

/// `⌊n·2^−B⌋` (floor shift).
fn shr_down(n: &IBig) -> IBig {
    n >> GRID_BITS
}

/// `⌈n·2^−B⌉`.
fn shr_up(n: &IBig) -> IBig {
    -((-n) >> GRID_BITS)
}

/// `n·2^−B` rounded to the nearest `f64` (ties to even), with the sign of the rounding
/// error (`Positive`: the `f64` is above); `None` for more than 960 bits. The integer's
/// correctly rounded image ([`IBig::to_f64`]) times `2^−B` is exact: the image is 0 or at
/// least 1 in magnitude and below `2^960`, so the product is a normal `f64` and rounding
/// commutes with the power-of-two scaling.
fn fixed_to_f64(n: &IBig) -> Option<Approximation<f64, Sign>> {
    if n.unsigned_abs().bit_len() > 960 {
        return None;
    }
    // 2^−B, exact (B = 256 ≪ 1022)
    let scale = f64::from_bits(((1023 - GRID_BITS) as u64) << 52);
    Some(match n.to_f64() {
        Approximation::Exact(x) => Approximation::Exact(x * scale),
        Approximation::Inexact(x, s) => Approximation::Inexact(x * scale, s),
    })
}

/// `⌊√m⌋` for `m ≥ 0`.
fn isqrt_down(m: &IBig) -> IBig {
    IBig::from(m.unsigned_abs().sqrt())
}

/// `⌈√m⌉` for `m ≥ 0`.
fn isqrt_up(m: &IBig) -> IBig {
    let u = m.unsigned_abs();
    let r = u.sqrt();
    IBig::from(if &r * &r == u { r } else { r + UBig::ONE })
}

impl Interval {
    /// `[lo, hi]`, rounded outward to the grid; `None` unless `lo ≤ hi`.
    pub fn new(lo: &Rational, hi: &Rational) -> Option<Self> {
        (lo <= hi).then(|| Interval {
            lo: fix_down(lo),
            hi: fix_up(hi),
        })
    }

    /// The smallest grid interval containing `q` (the point itself when `q` is on the grid).
    pub fn point(q: &Rational) -> Self {
        Interval {
            lo: fix_down(q),
            hi: fix_up(q),
        }
    }

    /// An enclosure of `a + b√d`.
    pub fn from_quad(x: &QuadExt) -> Self {
        let a = Interval::point(x.a());
        if x.b() == &Rational::ZERO {
            return a;
        }
        // √d ∈ [⌊√⌊d·4^B⌋⌋, ⌈√⌈d·4^B⌉⌉]·2^−B
        let d = x.d();
        let den = IBig::from(d.denominator().clone());
        let scaled = d.numerator() << (2 * GRID_BITS);
        let root = Interval {
            lo: isqrt_down(&floor_div(&scaled, &den)),
            hi: isqrt_up(&ceil_div(&scaled, &den)),
        };
        a + Interval::point(x.b()) * root
    }

    /// Lower end.
    pub fn lo(&self) -> Rational {
        unfix(&self.lo)
    }

    /// Upper end.
    pub fn hi(&self) -> Rational {
        unfix(&self.hi)
    }

    /// `hi − lo`.
    pub fn width(&self) -> Rational {
        unfix(&(&self.hi - &self.lo))
    }

    /// The midpoint.
    pub fn mid(&self) -> Rational {
        unfix(&(&self.lo + &self.hi)) / Rational::from(2)
    }

    /// `max(|lo|, |hi|)`.
    pub fn mag(&self) -> Rational {
        let (a, b) = (self.lo.clone().abs(), self.hi.clone().abs());
        unfix(if a > b { &a } else { &b })
    }

    /// `true` if `q ∈ [lo, hi]`.
    pub fn contains(&self, q: &Rational) -> bool {
        self.lo <= fix_down(q) && fix_up(q) <= self.hi
    }

    /// `true` if `other ⊆ self`.
    pub fn encloses(&self, other: &Interval) -> bool {
        self.lo <= other.lo && other.hi <= self.hi
    }

    /// The sign of every element, when it is the same for all (`Equal` only for `[0, 0]`).
    pub fn sign(&self) -> Option<Ordering> {
        if self.lo > IBig::ZERO {
            Some(Ordering::Greater)
        } else if self.hi < IBig::ZERO {
            Some(Ordering::Less)
        } else if self.lo == IBig::ZERO && self.hi == IBig::ZERO {
            Some(Ordering::Equal)
        } else {
            None
        }
    }

    /// The smallest interval containing both.
    pub fn hull(&self, other: &Interval) -> Interval {
        Interval {
            lo: self.lo.clone().min(other.lo.clone()),
            hi: self.hi.clone().max(other.hi.clone()),
        }
    }

    /// `1/x` for every `x` of the interval; `None` if it contains 0.
    pub fn recip(&self) -> Option<Interval> {
        if self.sign().is_none_or(|s| s == Ordering::Equal) {
            return None;
        }
        // 1/(n·2^−B) = 2^{2B}/n · 2^−B
        let one = IBig::ONE << (2 * GRID_BITS);
        let (lo, hi) = if self.lo > IBig::ZERO {
            (floor_div(&one, &self.hi), ceil_div(&one, &self.lo))
        } else {
            // both negative: 1/hi ≤ 1/x ≤ 1/lo; divide by the positive −n
            let (nh, nl) = (-self.hi.clone(), -self.lo.clone());
            (-ceil_div(&one, &nh), -floor_div(&one, &nl))
        };
        Some(Interval { lo, hi })
    }

    /// `x/y`; `None` if `y` contains 0.
    pub fn checked_div(&self, y: &Interval) -> Option<Interval> {
        Some(self.clone() * y.recip()?)
    }

    /// `√x` for every `x ≥ 0` of the interval; `None` if `hi < 0`. A negative lower end is
    /// clipped to 0 (the square root of the non-negative part).
    pub fn sqrt(&self) -> Option<Interval> {
        if self.hi < IBig::ZERO {
            return None;
        }
        let lo = if self.lo < IBig::ZERO {
            IBig::ZERO
        } else {
            isqrt_down(&(&self.lo << GRID_BITS))
        };
        Some(Interval {
            lo,
            hi: isqrt_up(&(&self.hi << GRID_BITS)),
        })
    }

    /// The midpoint rounded to `f64`.
    pub fn to_f64(&self) -> f64 {
        self.mid().to_f64().value()
    }

    /// `[lo, hi]` as the two nearest `f64`s outward (for display): each end point rounded
    /// to the nearest `f64` (ties to even), then moved one `f64` outward if that rounding
    /// went inward. Converted straight from the fixed-point integer `n` of `n·2^−B`: its
    /// correctly rounded `f64` image and the direction of the rounding come from the
    /// integer ([`IBig::to_f64`]), and the scaling by `2^−B` is exact (every non-zero grid
    /// point is at least `2^−B`, far above the subnormal range), so this is the same pair
    /// as rounding the rational end points; end points of more than 960 bits (values
    /// above `2^704`) take the rational path.
    pub fn to_f64_bounds(&self) -> (f64, f64) {
        if let (Some(lo), Some(hi)) = (fixed_to_f64(&self.lo), fixed_to_f64(&self.hi)) {
            let lo = match lo {
                Approximation::Inexact(x, Sign::Positive) => x.next_down(),
                a => a.value(),
            };
            let hi = match hi {
                Approximation::Inexact(x, Sign::Negative) => x.next_up(),
                a => a.value(),
            };
            return (lo, hi);
        }
        self.to_f64_bounds_by_rationals()
    }

    /// [`Interval::to_f64_bounds`] through the reduced rational end points.
    fn to_f64_bounds_by_rationals(&self) -> (f64, f64) {
        let (lq, hq) = (self.lo(), self.hi());
        let lo = lq.to_f64().value();
        let hi = hq.to_f64().value();
        let lo = if Rational::try_from(lo).is_ok_and(|l| l > lq) {
            lo.next_down()
        } else {
            lo
        };
        let hi = if Rational::try_from(hi).is_ok_and(|h| h < hq) {
            hi.next_up()
        } else {
            hi
        };
        (lo, hi)
    }
}

impl Add for Interval {
    type Output = Interval;
    fn add(self, rhs: Interval) -> Interval {
        Interval {
            lo: self.lo + rhs.lo,
            hi: self.hi + rhs.hi,
        }
    }
}

impl Sub for Interval {
    type Output = Interval;
    fn sub(self, rhs: Interval) -> Interval {
        Interval {
            lo: self.lo - rhs.hi,
            hi: self.hi - rhs.lo,
        }
    }
}

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Interval {
    type Output = Interval;
    fn mul(self, rhs: Interval) -> Interval {
        &self * &rhs
    }
}

impl Mul<&Interval> for &Interval {
    type Output = Interval;
    /// The hull of the four end point products, computed by the signs of the end points
    /// (Moore, *Interval Analysis*, 1966, §2.2, the nine cases): two products unless both
    /// factors contain zero in their interior, the same end points as the four-product
    /// hull.
    fn mul(self, rhs: &Interval) -> Interval {
        let (a, b) = (self, rhs);
        let z = IBig::ZERO;
        let (a_nonneg, a_nonpos) = (a.lo >= z, a.hi <= z);
        let (b_nonneg, b_nonpos) = (b.lo >= z, b.hi <= z);
        let (lo, hi) = if a_nonneg {
            if b_nonneg {
                (&a.lo * &b.lo, &a.hi * &b.hi)
            } else if b_nonpos {
                (&a.hi * &b.lo, &a.lo * &b.hi)
            } else {
                (&a.hi * &b.lo, &a.hi * &b.hi)
            }
        } else if a_nonpos {
            if b_nonneg {
                (&a.lo * &b.hi, &a.hi * &b.lo)
            } else if b_nonpos {
                (&a.hi * &b.hi, &a.lo * &b.lo)
            } else {
                (&a.lo * &b.hi, &a.lo * &b.lo)
            }
        } else if b_nonneg {
            (&a.lo * &b.hi, &a.hi * &b.hi)
        } else if b_nonpos {
            (&a.hi * &b.lo, &a.lo * &b.lo)
        } else {
            let (p, q) = (&a.lo * &b.hi, &a.hi * &b.lo);
            let (r, s) = (&a.lo * &b.lo, &a.hi * &b.hi);
            (p.min(q), r.max(s))
        };
        Interval {
            lo: shr_down(&lo),
            hi: shr_up(&hi),
        }
    }
}

impl AddAssign for Interval {
    fn add_assign(&mut self, rhs: Interval) {
        self.lo += rhs.lo;
        self.hi += rhs.hi;
    }
}

impl SubAssign for Interval {
    fn sub_assign(&mut self, rhs: Interval) {
        self.lo -= rhs.hi;
        self.hi -= rhs.lo;
    }
}

impl MulAssign for Interval {
    fn mul_assign(&mut self, rhs: Interval) {
        *self = self.clone() * rhs;
    }
}

impl Zero for Interval {
    fn zero() -> Self {
        Interval {
            lo: IBig::ZERO,
            hi: IBig::ZERO,
        }
    }
    fn is_zero(&self) -> bool {
        self.lo == IBig::ZERO && self.hi == IBig::ZERO
    }
}

impl One for Interval {
    fn one() -> Self {
        let one = IBig::ONE << GRID_BITS;
        Interval {
            lo: one.clone(),
            hi: one,
        }
    }
}

impl Ring for Interval {
    fn from_i64(n: i64) -> Self {
        let v = IBig::from(n) << GRID_BITS;
        Interval {
            lo: v.clone(),
            hi: v,
        }
    }
    /// The product of coefficient vectors with the interval products taken by reference
    /// (no copies of the end points).
    fn poly_mul(a: &[Self], b: &[Self]) -> Option<Vec<Self>> {
        let mut out = vec![Interval::zero(); (a.len() + b.len()).saturating_sub(1)];
        for (i, x) in a.iter().enumerate() {
            crate::budget::checkpoint();
            for (j, y) in b.iter().enumerate() {
                out[i + j] += x * y;
            }
        }
        Some(out)
    }
}

/// A closed interval `[lo, hi]` of `f64`s with *outward rounding*: every operation computes
/// its end points in round-to-nearest (IEEE 754, the only mode Rust uses) and then moves
/// the lower end one `f64` down and the upper end one `f64` up. A correctly rounded result
/// is within half a unit in the last place of the exact one, so the moved end points
/// bracket it (IEEE 754-2008, §4.3 on roundTiesToEven; outward rounding as in Moore,
/// Kearfott, Cloud, *Introduction to Interval Analysis*, SIAM 2009, on machine interval
/// arithmetic, here by one `f64` step instead of a directed rounding mode, which Rust does
/// not expose). The enclosure property of [`Interval`]
/// holds: the result contains `x ∘ y` for all `x ∈ X`, `y ∈ Y`. Overflow gives infinite
/// ends (still an enclosure); an operation on a non-finite end gives `[−∞, ∞]`, so a result
/// with a non-finite end is only "not decided" ([`F64Interval::is_finite`]).
///
/// A cheap first pass for [`Interval`] computations: about a hundred times faster than the
/// 256-bit fixed point, at a relative width of about `10⁻¹⁶` per operation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct F64Interval {
    lo: f64,
    hi: f64,
}

impl F64Interval {
    /// Everything (the result of an operation on a non-finite end).
    pub const ENTIRE: F64Interval = F64Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// The point `x` (exact: an `f64` is a rational number).
    pub fn point(x: f64) -> Self {
        F64Interval { lo: x, hi: x }
    }

    /// `[lo, hi]` for `lo ≤ hi` (both finite or infinite), else `None`.
    pub fn new(lo: f64, hi: f64) -> Option<Self> {
        (lo <= hi).then_some(F64Interval { lo, hi })
    }

    /// The nearest `f64` interval containing `x` (its end points rounded outward).
    pub fn from_interval(x: &Interval) -> Self {
        let (lo, hi) = x.to_f64_bounds();
        F64Interval { lo, hi }
    }

    /// The exact enclosure as an [`Interval`] (rounded outward to its grid); `None` if an
    /// end is not finite.
    pub fn to_interval(&self) -> Option<Interval> {
        let lo = Rational::try_from(self.lo).ok()?;
        let hi = Rational::try_from(self.hi).ok()?;
        Interval::new(&lo, &hi)
    }

    /// Lower end.
    pub fn lo(&self) -> f64 {
        self.lo
    }

    /// Upper end.
    pub fn hi(&self) -> f64 {
        self.hi
    }

    /// Both ends finite.
    pub fn is_finite(&self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    /// The midpoint, rounded (not an enclosure: for approximations).
    pub fn mid(&self) -> f64 {
        0.5 * self.lo + 0.5 * self.hi
    }

    /// An upper bound of `max(|lo|, |hi|)`.
    pub fn mag(&self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }

    /// The sign of every element, when it is the same for all (`Equal` only for `[0, 0]`).
    pub fn sign(&self) -> Option<Ordering> {
        if self.lo > 0.0 {
            Some(Ordering::Greater)
        } else if self.hi < 0.0 {
            Some(Ordering::Less)
        } else if self.lo == 0.0 && self.hi == 0.0 {
            Some(Ordering::Equal)
        } else {
            None
        }
    }

    /// The smallest interval containing both.
    pub fn hull(&self, other: &F64Interval) -> F64Interval {
        if !(self.is_finite() && other.is_finite()) {
            return F64Interval::ENTIRE;
        }
        F64Interval {
            lo: self.lo.min(other.lo),
            hi: self.hi.max(other.hi),
        }
    }

    /// `x/d` for every `x` of the interval and an `f64` `d > 0`; `[−∞, ∞]` otherwise.
    pub fn div_positive(&self, d: f64) -> F64Interval {
        if !(self.is_finite() && d.is_finite() && d > 0.0) {
            return F64Interval::ENTIRE;
        }
        F64Interval {
            lo: (self.lo / d).next_down(),
            hi: (self.hi / d).next_up(),
        }
    }
}

/// The interval of a correctly rounded sum, difference or product: one `f64` outward.
fn outward(lo: f64, hi: f64) -> F64Interval {
    if lo.is_nan() || hi.is_nan() {
        return F64Interval::ENTIRE;
    }
    F64Interval {
        lo: lo.next_down(),
        hi: hi.next_up(),
    }
}

impl Add for F64Interval {
    type Output = F64Interval;
    fn add(self, rhs: F64Interval) -> F64Interval {
        if !(self.is_finite() && rhs.is_finite()) {
            return F64Interval::ENTIRE;
        }
        outward(self.lo + rhs.lo, self.hi + rhs.hi)
    }
}

impl Sub for F64Interval {
    type Output = F64Interval;
    fn sub(self, rhs: F64Interval) -> F64Interval {
        if !(self.is_finite() && rhs.is_finite()) {
            return F64Interval::ENTIRE;
        }
        outward(self.lo - rhs.hi, self.hi - rhs.lo)
    }
}

impl Neg for F64Interval {
    type Output = F64Interval;
    fn neg(self) -> F64Interval {
        F64Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for F64Interval {
    type Output = F64Interval;
    /// The hull of the four end point products, each rounded outward.
    fn mul(self, rhs: F64Interval) -> F64Interval {
        if !(self.is_finite() && rhs.is_finite()) {
            return F64Interval::ENTIRE;
        }
        let p = [
            self.lo * rhs.lo,
            self.lo * rhs.hi,
            self.hi * rhs.lo,
            self.hi * rhs.hi,
        ];
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        outward(lo, hi)
    }
}

impl AddAssign for F64Interval {
    fn add_assign(&mut self, rhs: F64Interval) {
        *self = *self + rhs;
    }
}

impl SubAssign for F64Interval {
    fn sub_assign(&mut self, rhs: F64Interval) {
        *self = *self - rhs;
    }
}

impl MulAssign for F64Interval {
    fn mul_assign(&mut self, rhs: F64Interval) {
        *self = *self * rhs;
    }
}

impl Zero for F64Interval {
    fn zero() -> Self {
        F64Interval::point(0.0)
    }
    fn is_zero(&self) -> bool {
        self.lo == 0.0 && self.hi == 0.0
    }
}

impl One for F64Interval {
    fn one() -> Self {
        F64Interval::point(1.0)
    }
}

impl Ring for F64Interval {
    fn from_i64(n: i64) -> Self {
        // exact below 2^53; otherwise the two neighbours of the rounded value
        let x = n as f64;
        if x.abs() < 9_007_199_254_740_992.0 {
            F64Interval::point(x)
        } else {
            outward(x, x)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from(p) / Rational::from(d)
    }

    #[test]
    fn sqrt_two_is_enclosed_tightly() {
        let r = Interval::point(&q(2, 1)).sqrt().expect("sqrt");
        assert!(r.lo() * r.lo() <= q(2, 1));
        assert!(r.hi() * r.hi() >= q(2, 1));
        assert!(r.width() <= pow2(-(GRID_BITS as isize)) * Rational::from(2));
        let (lo, hi) = r.to_f64_bounds();
        assert!(lo <= std::f64::consts::SQRT_2 && std::f64::consts::SQRT_2 <= hi);
    }

    #[test]
    fn thirds_are_rounded_outward() {
        let t = Interval::point(&q(1, 3));
        assert!(t.contains(&q(1, 3)));
        assert!(t.lo() < q(1, 3) && q(1, 3) < t.hi());
        let three = (t.clone() + t.clone() + t) - Interval::one();
        assert!(three.contains(&Rational::ZERO));
    }

    #[test]
    fn products_and_reciprocals_enclose_every_pair() {
        let a = Interval::new(&q(-2, 1), &q(3, 1)).expect("a");
        let b = Interval::new(&q(-5, 1), &q(1, 7)).expect("b");
        let p = a.clone() * b.clone();
        for x in [q(-2, 1), q(0, 1), q(3, 1)] {
            for y in [q(-5, 1), q(1, 7), q(-1, 2)] {
                assert!(p.contains(&(&x * &y)));
            }
        }
        assert!(a.recip().is_none());
        let c = Interval::new(&q(1, 3), &q(1, 2)).expect("c");
        let r = c.recip().expect("recip");
        assert!(r.contains(&q(2, 1)) && r.contains(&q(3, 1)));
        assert_eq!(c.sign(), Some(Ordering::Greater));
        assert_eq!(a.sign(), None);
    }

    /// The hull of the four end point products (the definition the sign cases of `Mul`
    /// implement), rounded outward.
    fn hull_of_four(a: &Interval, b: &Interval) -> Interval {
        let p = [&a.lo * &b.lo, &a.lo * &b.hi, &a.hi * &b.lo, &a.hi * &b.hi];
        let lo = p.iter().min().expect("four");
        let hi = p.iter().max().expect("four");
        Interval {
            lo: shr_down(lo),
            hi: shr_up(hi),
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// The sign cases give exactly the hull of the four end point products, for end
        /// points of every sign (zero included).
        #[test]
        fn sign_cases_equal_the_hull_of_four_products(
            a in (-6i64..7, 0i64..7, 1i64..5),
            b in (-6i64..7, 0i64..7, 1i64..5),
        ) {
            let mk = |(lo, w, d): (i64, i64, i64)| Interval::new(&q(lo, d), &q(lo + w, d)).expect("lo ≤ hi");
            let (x, y) = (mk(a), mk(b));
            proptest::prop_assert_eq!(x.clone() * y.clone(), hull_of_four(&x, &y));
        }
    }

    /// An `f64` of varied magnitude and sign (subnormals, zero and large exponents included).
    fn any_f64() -> impl proptest::strategy::Strategy<Value = f64> {
        use proptest::prelude::*;
        prop_oneof![
            (-1000i64..1000, -60i32..60).prop_map(|(m, e)| m as f64 * 2f64.powi(e)),
            (-1e6f64..1e6).prop_map(|x| x),
            (1u64..1000, any::<bool>()).prop_map(|(k, s)| {
                let x = f64::from_bits(k); // subnormal
                if s {
                    -x
                } else {
                    x
                }
            }),
            Just(0.0),
        ]
    }

    fn q64(x: f64) -> Rational {
        Rational::try_from(x).expect("finite")
    }

    /// `v ∈ i`, an infinite end unbounded (overflow).
    fn f64_contains(i: &F64Interval, v: &Rational) -> bool {
        let above_lo = i.lo() == f64::NEG_INFINITY || (i.lo().is_finite() && q64(i.lo()) <= *v);
        let below_hi = i.hi() == f64::INFINITY || (i.hi().is_finite() && *v <= q64(i.hi()));
        above_lo && below_hi
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// Outward rounding: the exact sum, difference and product of every pair of end
        /// points (and of an interior point) lie in the `f64` result, checked in exact
        /// rationals; so do the quotients by a positive `f64`.
        #[test]
        fn f64_intervals_enclose_the_exact_results(
            a in any_f64(), b in any_f64(), c in any_f64(), d in any_f64(),
        ) {
            let x = F64Interval::new(a.min(b), a.max(b)).expect("ordered");
            let y = F64Interval::new(c.min(d), c.max(d)).expect("ordered");
            let xs = [q64(x.lo()), q64(x.hi()), (q64(x.lo()) + q64(x.hi())) / Rational::from(2)];
            let ys = [q64(y.lo()), q64(y.hi()), (q64(y.lo()) + q64(y.hi())) / Rational::from(2)];
            let (s, t, p) = (x + y, x - y, x * y);
            for u in &xs {
                for v in &ys {
                    proptest::prop_assert!(f64_contains(&s, &(u + v)));
                    proptest::prop_assert!(f64_contains(&t, &(u - v)));
                    proptest::prop_assert!(f64_contains(&p, &(u * v)));
                }
                let dv = c.abs().max(1e-300);
                proptest::prop_assert!(f64_contains(&x.div_positive(dv), &(u / q64(dv))));
            }
        }
    }

    /// A grid integer of varied size (a few bits up to 1100, beyond the 960-bit fast path),
    /// sign and shape: 64 random bits, or an exact tie between two `f64`s (54 significant
    /// bits ending in 1), shifted left.
    fn any_grid_integer() -> impl proptest::strategy::Strategy<Value = IBig> {
        use proptest::prelude::*;
        (any::<u64>(), 0u32..3, 0usize..1040, any::<bool>()).prop_map(|(m, kind, shift, neg)| {
            let base = match kind {
                0 => IBig::from(m),
                1 => IBig::from((1u64 << 53) | (m & ((1 << 53) - 1)) | 1),
                _ => IBig::from(m >> 40),
            };
            let n = base << shift;
            if neg {
                -n
            } else {
                n
            }
        })
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// The end points converted straight from the fixed-point integers are the same
        /// `f64`s as through the reduced rationals (nearest, then one step outward if the
        /// rounding went inward), and they enclose the exact end points.
        #[test]
        fn f64_bounds_from_the_integers_equal_those_from_the_rationals(
            a in any_grid_integer(),
            b in any_grid_integer(),
        ) {
            let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
            let x = Interval { lo, hi };
            let fast = x.to_f64_bounds();
            proptest::prop_assert_eq!(fast, x.to_f64_bounds_by_rationals());
            if let (Ok(l), Ok(h)) = (Rational::try_from(fast.0), Rational::try_from(fast.1)) {
                proptest::prop_assert!(l <= x.lo() && x.hi() <= h);
            }
        }
    }

    #[test]
    fn f64_intervals_from_grid_intervals_and_back_enclose() {
        let third = Interval::point(&q(1, 3));
        let f = F64Interval::from_interval(&third);
        assert!(f64_contains(&f, &q(1, 3)));
        assert!(f.hi() - f.lo() <= 2.0 * f64::EPSILON);
        let back = f.to_interval().expect("finite");
        assert!(back.encloses(&third));
        // overflow is an infinite end, never a false finite one
        let big = F64Interval::point(f64::MAX);
        let o = big * big;
        assert!(!o.is_finite() && o.sign() == Some(Ordering::Greater));
        assert!((o - o).lo() == f64::NEG_INFINITY && (o - o).hi() == f64::INFINITY);
        assert!((o - o).to_interval().is_none());
    }

    #[test]
    fn quadratic_extension_elements_are_enclosed() {
        let x = QuadExt::new(q(1, 2), q(3, 4), q(5, 1)).expect("quad");
        let e = Interval::from_quad(&x);
        let v = 0.5 + 0.75 * 5f64.sqrt();
        let (lo, hi) = e.to_f64_bounds();
        assert!(lo <= v && v <= hi && hi - lo < 1e-15);
        // (x − 1/2)² = 45/16 lies in the square of the enclosure's shift
        let s = e - Interval::point(&q(1, 2));
        assert!((s.clone() * s).contains(&q(45, 16)));
    }
}
