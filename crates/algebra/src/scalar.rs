//! The scalar traits: every construction in rcagd is generic over them.
//!
//! * [`Ring`]: commutative-or-not ring operations (polynomials with quaternion
//!   coefficients only need this);
//! * [`Field`]: a commutative field (division by non-zero elements);
//! * [`Scalar`]: an ordered field that approximates the reals, with conversions
//!   from exact rationals and to `f64`. Implemented for `f64` (fast, inexact) and
//!   [`Rational`] (exact). Quadratic extensions implement it as well.
//!
//! Operations take their operands by value; exact numbers are cloned where needed.
//! This keeps the bounds short; the f64 paths that need speed use `f64` directly.

use crate::rational::Rational;
use core::fmt::Debug;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use num_traits::{One, Zero};

/// A ring with unit. Multiplication need not commute (quaternions).
pub trait Ring:
    Clone
    + Debug
    + PartialEq
    + Zero
    + One
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
{
    /// The image of an integer.
    fn from_i64(n: i64) -> Self;

    /// The product of two sparse polynomials over this ring when the ring has a faster
    /// exact way than summing the coefficient products in `Self` (the default, `None`,
    /// uses that generic product of [`crate::mpoly::MPoly`]). [`Rational`] multiplies
    /// integer numerators over one common denominator per factor.
    fn mpoly_mul(
        _a: &crate::mpoly::MPoly<Self>,
        _b: &crate::mpoly::MPoly<Self>,
    ) -> Option<crate::mpoly::MPoly<Self>> {
        None
    }

    /// The coefficient vector of the product of two univariate polynomials (non-empty
    /// coefficient vectors, constant term first) when the ring has a faster exact way
    /// than the generic sum of coefficient products (the default, `None`).
    fn poly_mul(_a: &[Self], _b: &[Self]) -> Option<Vec<Self>> {
        None
    }
}

/// `xᵏ` in any ring, by repeated squaring (`x⁰ = 1`).
pub fn ring_pow<R: Ring>(x: &R, k: usize) -> R {
    let mut result = R::one();
    let mut base = x.clone();
    let mut e = k;
    while e > 0 {
        if e & 1 == 1 {
            result *= base.clone();
        }
        e >>= 1;
        if e > 0 {
            base = base.clone() * base;
        }
    }
    result
}

/// A commutative field.
pub trait Field: Ring + Div<Output = Self> + DivAssign {
    /// The size of the element as a pivot of Gaussian elimination: `None` for exact fields
    /// (any non-zero pivot is exact), `|x|` for floating point, where elimination picks the
    /// largest pivot of the column (partial pivoting; without it a rounding residue such as
    /// `3 − 5·0.6000000000000001 ≈ −4·10⁻¹⁶` would be taken as a pivot).
    fn pivot_size(&self) -> Option<f64> {
        None
    }

    /// The multiplicative inverse, `None` for zero.
    fn inv(&self) -> Option<Self> {
        if self.is_zero() {
            None
        } else {
            Some(Self::one() / self.clone())
        }
    }

    /// The monic gcd of two polynomials by a method faster than Euclid's algorithm, if the
    /// field has one ([`crate::Poly::gcd`] falls back to Euclid on `None`). ℚ uses the
    /// subresultant sequence over ℤ ([`crate::roots::gcd_rational`]).
    fn fast_poly_gcd(_a: &crate::Poly<Self>, _b: &crate::Poly<Self>) -> Option<crate::Poly<Self>> {
        None
    }
}

/// An ordered field approximating the real numbers: `f64` or an exact type.
pub trait Scalar: Field + PartialOrd {
    /// `true` for exact types: equality is decided exactly and certificates are proofs.
    const EXACT: bool;
    /// The unit roundoff of the arithmetic: `2⁻⁵³` for `f64` (the default),
    /// `2⁻¹⁰⁶` for [`crate::double_double::DoubleDouble`], `0` for exact types. Tolerances
    /// of inexact decisions written for `f64` scale by `UNIT_ROUNDOFF / 2⁻⁵³`
    /// ([`precision_ratio`]), so that a wider type decides more of them as the exact signs do.
    const UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;
    /// The (correctly rounded, for `f64`) image of an exact rational.
    fn from_rational(q: &Rational) -> Self;
    /// Nearest `f64` (correctly rounded for [`Rational`]).
    fn to_f64(&self) -> f64;
    /// Absolute value.
    fn abs(&self) -> Self {
        if *self < Self::zero() {
            -self.clone()
        } else {
            self.clone()
        }
    }
    /// The exact rational value, if the element is rational (`f64`s are rational too:
    /// their exact binary value is returned; NaN and infinities give `None`).
    fn to_rational(&self) -> Option<Rational>;
    /// Ratio of two integers.
    fn from_ratio(p: i64, q: i64) -> Self {
        Self::from_i64(p) / Self::from_i64(q)
    }
    /// `√self` for an inexact scalar and `self ≥ 0` (the square root of
    /// [`sqrt_in_field`]'s inexact branch): by default the `f64` root of the nearest
    /// `f64`; a wider type ([`crate::double_double::DoubleDouble`]) keeps its precision.
    fn sqrt_inexact(&self) -> Option<Self> {
        let r = Rational::try_from(self.to_f64().sqrt()).ok()?;
        Some(Self::from_rational(&r))
    }
}

impl Ring for f64 {
    fn from_i64(n: i64) -> Self {
        n as f64
    }
}
impl Field for f64 {
    fn pivot_size(&self) -> Option<f64> {
        Some(self.abs())
    }
}
impl Scalar for f64 {
    const EXACT: bool = false;
    fn from_rational(q: &Rational) -> Self {
        q.to_f64().value()
    }
    fn to_f64(&self) -> f64 {
        *self
    }
    fn abs(&self) -> Self {
        f64::abs(*self)
    }
    fn to_rational(&self) -> Option<Rational> {
        Rational::try_from(*self).ok()
    }
}

impl Ring for Rational {
    fn from_i64(n: i64) -> Self {
        Rational::from(n)
    }
    fn mpoly_mul(
        a: &crate::mpoly::MPoly<Self>,
        b: &crate::mpoly::MPoly<Self>,
    ) -> Option<crate::mpoly::MPoly<Self>> {
        Some(crate::mpoly::mul_rational(a, b))
    }
    fn poly_mul(a: &[Self], b: &[Self]) -> Option<Vec<Self>> {
        Some(crate::mpoly::poly_mul_rational(a, b))
    }
}
impl Field for Rational {
    fn fast_poly_gcd(a: &crate::Poly<Self>, b: &crate::Poly<Self>) -> Option<crate::Poly<Self>> {
        Some(crate::roots::gcd_rational(a, b))
    }
}
impl Scalar for Rational {
    const EXACT: bool = true;
    const UNIT_ROUNDOFF: f64 = 0.0;
    fn from_rational(q: &Rational) -> Self {
        q.clone()
    }
    fn to_f64(&self) -> f64 {
        Rational::to_f64(self).value()
    }
    fn to_rational(&self) -> Option<Rational> {
        Some(self.clone())
    }
}

/// `UNIT_ROUNDOFF / 2⁻⁵³`: `1` for `f64`, `2⁻⁵³` for double-double, `0` for exact
/// types — the factor by which a tolerance calibrated for `f64` shrinks in `F`.
pub fn precision_ratio<F: Scalar>() -> f64 {
    F::UNIT_ROUNDOFF / (f64::EPSILON / 2.0)
}

/// A scalar as text for messages and certificates: the exact fraction `"p/q"` for exact
/// scalars, the shortest round-tripping decimal for `f64`.
pub fn format_scalar<F: Scalar>(x: &F) -> String {
    if F::EXACT {
        match x.to_rational() {
            Some(q) => crate::rational::format_rational(&q),
            None => format!("{x:?}"),
        }
    } else {
        format!("{}", x.to_f64())
    }
}

/// A vector as text, `(x₁, …, x_k)`, each entry by [`format_scalar`].
pub fn format_vector<F: Scalar>(v: &[F]) -> String {
    let parts: Vec<String> = v.iter().map(format_scalar).collect();
    format!("({})", parts.join(", "))
}

/// `√x` if it lies in the scalar field: for exact scalars the rational square root of a
/// rational square, for `f64` the floating-point root; `None` for a negative `x` or an
/// irrational root. The one square root of the constructions.
pub fn sqrt_in_field<F: Scalar>(x: &F) -> Option<F> {
    if *x < F::zero() {
        return None;
    }
    if F::EXACT {
        let q = x.to_rational()?;
        crate::rational::rational_sqrt(&q).map(|r| F::from_rational(&r))
    } else {
        x.sqrt_inexact()
    }
}

/// A polynomial as text in the variable `var`, highest degree first, with signs:
/// `2·t^2 - 1`, `t^3 + (1/2)·t`, `0`. Coefficients by [`format_scalar`]; a coefficient ±1 is
/// left out, a fraction is parenthesised. The one formatter for polynomials in messages,
/// certificates and reports.
pub fn format_poly<F: Scalar>(p: &crate::Poly<F>, var: &str) -> String {
    let mut out = String::new();
    for (k, c) in p.coeffs().iter().enumerate().rev() {
        if c.is_zero() {
            continue;
        }
        let neg = *c < F::zero();
        let a = if neg { -c.clone() } else { c.clone() };
        out.push_str(match (out.is_empty(), neg) {
            (true, true) => "-",
            (true, false) => "",
            (false, true) => " - ",
            (false, false) => " + ",
        });
        let coef = format_scalar(&a);
        if k == 0 {
            out.push_str(&coef);
            continue;
        }
        let pow = if k == 1 {
            var.to_string()
        } else {
            format!("{var}^{k}")
        };
        if a.is_one() {
            out.push_str(&pow);
        } else if coef.contains('/') {
            out.push_str(&format!("({coef})·{pow}"));
        } else {
            out.push_str(&format!("{coef}·{pow}"));
        }
    }
    if out.is_empty() {
        out.push('0');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polynomials_print_highest_degree_first_with_signs() {
        let q = |n: i64, d: i64| Rational::from_parts_signed(n.into(), d.into());
        let p = crate::Poly::new(vec![q(-1, 1), q(1, 2), q(0, 1), q(1, 1)]);
        assert_eq!(format_poly(&p, "t"), "t^3 + (1/2)·t - 1");
        let p = crate::Poly::new(vec![q(0, 1), q(-3, 1)]);
        assert_eq!(format_poly(&p, "u"), "-3·u");
        assert_eq!(format_poly(&crate::Poly::<Rational>::zero(), "t"), "0");
        let p = crate::Poly::new(vec![2.5f64, -1.0]);
        assert_eq!(format_poly(&p, "t"), "-t + 2.5");
    }

    #[test]
    fn rational_to_f64_is_correctly_rounded() {
        let third = Rational::from_ratio(1, 3);
        assert_eq!(Scalar::to_f64(&third), 1.0 / 3.0);
        let tenth = Rational::from_ratio(1, 10);
        assert_eq!(Scalar::to_f64(&tenth), 0.1);
    }

    #[test]
    fn f64_round_trips_through_rational() {
        for x in [0.1, -3.75, 1e-300, 12345.678] {
            let q = x.to_rational().expect("finite");
            assert_eq!(Scalar::to_f64(&q), x);
        }
        assert!(f64::NAN.to_rational().is_none());
    }
}
