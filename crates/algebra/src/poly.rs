//! Univariate polynomials in the power basis over any [`Ring`].
//!
//! `Poly { coeffs }` stores `c₀ + c₁t + … + cₙtⁿ` low degree first, with no trailing
//! zeros (the zero polynomial has no coefficients). Multiplication keeps the order of
//! factors, so non-commutative coefficients (quaternions) are supported:
//! `(Σ aᵢtⁱ)(Σ bⱼtʲ) = Σ (aᵢbⱼ) tⁱ⁺ʲ`. Division, gcd and the like need a [`Field`].

use crate::error::AlgebraError;
use crate::scalar::{ring_pow, Field, Ring};
use core::ops::{Add, Mul, Neg, Sub};

/// A univariate polynomial, coefficients low degree first, trimmed.
#[derive(Debug, Clone, PartialEq)]
pub struct Poly<R> {
    coeffs: Vec<R>,
}

impl<R: Ring> Poly<R> {
    /// From coefficients `c₀, c₁, …` (trailing zeros are removed).
    pub fn new(coeffs: Vec<R>) -> Self {
        let mut p = Poly { coeffs };
        p.trim();
        p
    }

    /// The zero polynomial.
    pub fn zero() -> Self {
        Poly { coeffs: Vec::new() }
    }

    /// The constant `c`.
    pub fn constant(c: R) -> Self {
        Poly::new(vec![c])
    }

    /// The polynomial `t`.
    pub fn x() -> Self {
        Poly::new(vec![R::zero(), R::one()])
    }

    /// The monomial `c·tᵏ`.
    pub fn monomial(c: R, k: usize) -> Self {
        let mut v = vec![R::zero(); k + 1];
        v[k] = c;
        Poly::new(v)
    }

    /// From integer coefficients, low degree first.
    pub fn from_ints(c: &[i64]) -> Self {
        Poly::new(c.iter().map(|&k| R::from_i64(k)).collect())
    }

    fn trim(&mut self) {
        while self.coeffs.last().is_some_and(|c| c.is_zero()) {
            self.coeffs.pop();
        }
    }

    /// Coefficients, low degree first (empty for zero).
    pub fn coeffs(&self) -> &[R] {
        &self.coeffs
    }

    /// Consumes the polynomial, returning its coefficients.
    pub fn into_coeffs(self) -> Vec<R> {
        self.coeffs
    }

    /// The coefficient of `tᵏ` (zero beyond the degree).
    pub fn coeff(&self, k: usize) -> R {
        self.coeffs.get(k).cloned().unwrap_or_else(R::zero)
    }

    /// `true` for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// The degree, `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.coeffs.len().checked_sub(1)
    }

    /// The leading coefficient (zero for the zero polynomial).
    pub fn leading(&self) -> R {
        self.coeffs.last().cloned().unwrap_or_else(R::zero)
    }

    /// Value at `t` (Horner).
    pub fn eval(&self, t: &R) -> R {
        let mut acc = R::zero();
        for c in self.coeffs.iter().rev() {
            acc = acc * t.clone() + c.clone();
        }
        acc
    }

    /// The derivative.
    pub fn derivative(&self) -> Self {
        Poly::new(
            self.coeffs
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, c)| R::from_i64(k as i64) * c.clone())
                .collect(),
        )
    }

    /// The `k`-th derivative.
    pub fn derivative_n(&self, k: usize) -> Self {
        (0..k).fold(self.clone(), |p, _| p.derivative())
    }

    /// Multiplies every coefficient by `c` on the right.
    pub fn scale(&self, c: &R) -> Self {
        Poly::new(self.coeffs.iter().map(|a| a.clone() * c.clone()).collect())
    }

    /// Multiplies every coefficient by `c` on the left.
    pub fn scale_left(&self, c: &R) -> Self {
        Poly::new(self.coeffs.iter().map(|a| c.clone() * a.clone()).collect())
    }

    /// Applies `f` to every coefficient (e.g. conjugation, conversion to `f64`).
    pub fn map<S: Ring>(&self, f: impl Fn(&R) -> S) -> Poly<S> {
        Poly::new(self.coeffs.iter().map(f).collect())
    }

    /// `self ∘ q`, i.e. `self(q(t))` (Horner in `q`).
    pub fn compose(&self, q: &Poly<R>) -> Self {
        let mut acc = Poly::zero();
        for c in self.coeffs.iter().rev() {
            acc = &(&acc * q) + &Poly::constant(c.clone());
        }
        acc
    }

    /// `selfᵏ`.
    pub fn pow(&self, k: u32) -> Self {
        ring_pow(self, k as usize)
    }

    /// Reverses the coefficient order with respect to degree `n`: `tⁿ p(1/t)`.
    /// Requires `n ≥ deg p` (coefficients beyond `n` are an error).
    pub fn reverse(&self, n: usize) -> Result<Self, AlgebraError> {
        if self.coeffs.len() > n + 1 {
            return Err(AlgebraError::InvalidArgument(format!(
                "reverse: degree {} exceeds {n}",
                self.coeffs.len() - 1
            )));
        }
        let mut v = self.coeffs.clone();
        v.resize(n + 1, R::zero());
        v.reverse();
        Ok(Poly::new(v))
    }
}

impl<F: Field> Poly<F> {
    /// Division with remainder: `self = q·d + r`, `deg r < deg d`.
    ///
    /// # Errors
    /// [`AlgebraError::DivisionByZero`] if `d` is the zero polynomial.
    pub fn div_rem(&self, d: &Poly<F>) -> Result<(Poly<F>, Poly<F>), AlgebraError> {
        let Some(dd) = d.degree() else {
            return Err(AlgebraError::DivisionByZero(
                "polynomial division by zero".into(),
            ));
        };
        let lc_inv = d
            .leading()
            .inv()
            .ok_or_else(|| AlgebraError::DivisionByZero("leading coefficient".into()))?;
        let mut r = self.coeffs.clone();
        let n = self.coeffs.len();
        if n <= dd {
            return Ok((Poly::zero(), self.clone()));
        }
        let mut q = vec![F::zero(); n - dd];
        for k in (0..n - dd).rev() {
            crate::budget::checkpoint();
            let c = r[k + dd].clone() * lc_inv.clone();
            if !c.is_zero() {
                for (j, dc) in d.coeffs.iter().enumerate() {
                    r[k + j] -= c.clone() * dc.clone();
                }
            }
            q[k] = c;
        }
        r.truncate(dd);
        Ok((Poly::new(q), Poly::new(r)))
    }

    /// Exact quotient `self / d`.
    ///
    /// # Errors
    /// Division by zero, or [`AlgebraError::NotRepresentable`] if `d` does not divide `self`.
    pub fn div_exact(&self, d: &Poly<F>) -> Result<Poly<F>, AlgebraError> {
        let (q, r) = self.div_rem(d)?;
        if r.is_zero() {
            Ok(q)
        } else {
            Err(AlgebraError::NotRepresentable(
                "polynomial division leaves a remainder".into(),
            ))
        }
    }

    /// The monic associate (zero stays zero).
    pub fn monic(&self) -> Self {
        match self.leading().inv() {
            Some(inv) => self.scale(&inv),
            None => self.clone(),
        }
    }

    /// The monic greatest common divisor (zero iff both are zero). Exact over exact
    /// fields: over ℚ by the subresultant sequence over ℤ ([`Field::fast_poly_gcd`]; the
    /// monic remainders of Euclid over ℚ grow until small inputs take minutes, issue 19),
    /// otherwise Euclid's algorithm ([`Self::gcd_euclid`]).
    pub fn gcd(&self, other: &Poly<F>) -> Poly<F> {
        F::fast_poly_gcd(self, other).unwrap_or_else(|| self.gcd_euclid(other))
    }

    /// The monic greatest common divisor by Euclid's algorithm.
    pub fn gcd_euclid(&self, other: &Poly<F>) -> Poly<F> {
        let mut a = self.clone();
        let mut b = other.clone();
        while !b.is_zero() {
            crate::budget::checkpoint();
            let r = match a.div_rem(&b) {
                Ok((_, r)) => r,
                Err(_) => break,
            };
            a = b;
            b = r.monic();
        }
        a.monic()
    }

    /// The square-free part `p / gcd(p, p')`, monic.
    pub fn square_free(&self) -> Poly<F> {
        if self.is_zero() {
            return Poly::zero();
        }
        let g = self.gcd(&self.derivative());
        self.div_rem(&g)
            .map(|(q, _)| q.monic())
            .unwrap_or_else(|_| self.monic())
    }
}

impl<R: Ring> Add for &Poly<R> {
    type Output = Poly<R>;
    fn add(self, rhs: &Poly<R>) -> Poly<R> {
        let n = self.coeffs.len().max(rhs.coeffs.len());
        Poly::new((0..n).map(|k| self.coeff(k) + rhs.coeff(k)).collect())
    }
}
impl<R: Ring> Sub for &Poly<R> {
    type Output = Poly<R>;
    fn sub(self, rhs: &Poly<R>) -> Poly<R> {
        let n = self.coeffs.len().max(rhs.coeffs.len());
        Poly::new((0..n).map(|k| self.coeff(k) - rhs.coeff(k)).collect())
    }
}
impl<R: Ring> Mul for &Poly<R> {
    type Output = Poly<R>;
    fn mul(self, rhs: &Poly<R>) -> Poly<R> {
        if self.is_zero() || rhs.is_zero() {
            return Poly::zero();
        }
        if let Some(out) = R::poly_mul(&self.coeffs, &rhs.coeffs) {
            return Poly::new(out);
        }
        let mut out = vec![R::zero(); self.coeffs.len() + rhs.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            crate::budget::checkpoint();
            for (j, b) in rhs.coeffs.iter().enumerate() {
                out[i + j] += a.clone() * b.clone();
            }
        }
        Poly::new(out)
    }
}
impl<R: Ring> Neg for &Poly<R> {
    type Output = Poly<R>;
    fn neg(self) -> Poly<R> {
        Poly::new(self.coeffs.iter().map(|c| -c.clone()).collect())
    }
}
impl<R: Ring> Add for Poly<R> {
    type Output = Poly<R>;
    fn add(self, rhs: Poly<R>) -> Poly<R> {
        &self + &rhs
    }
}
impl<R: Ring> Sub for Poly<R> {
    type Output = Poly<R>;
    fn sub(self, rhs: Poly<R>) -> Poly<R> {
        &self - &rhs
    }
}
impl<R: Ring> Mul for Poly<R> {
    type Output = Poly<R>;
    fn mul(self, rhs: Poly<R>) -> Poly<R> {
        &self * &rhs
    }
}
impl<R: Ring> Neg for Poly<R> {
    type Output = Poly<R>;
    fn neg(self) -> Poly<R> {
        -&self
    }
}

/// `Poly<R>` is itself a ring (`R[t]`), so polynomials with polynomial coefficients
/// (`Poly<Poly<Rational>>`, used by [`crate::resultant::resultant_poly`]) can be built.
impl<R: Ring> num_traits::Zero for Poly<R> {
    fn zero() -> Self {
        Poly { coeffs: Vec::new() }
    }
    fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }
}
impl<R: Ring> num_traits::One for Poly<R> {
    fn one() -> Self {
        Poly::constant(R::one())
    }
}
impl<R: Ring> core::ops::AddAssign for Poly<R> {
    fn add_assign(&mut self, rhs: Poly<R>) {
        *self = &*self + &rhs;
    }
}
impl<R: Ring> core::ops::SubAssign for Poly<R> {
    fn sub_assign(&mut self, rhs: Poly<R>) {
        *self = &*self - &rhs;
    }
}
impl<R: Ring> core::ops::MulAssign for Poly<R> {
    fn mul_assign(&mut self, rhs: Poly<R>) {
        *self = &*self * &rhs;
    }
}
impl<R: Ring> Ring for Poly<R> {
    fn from_i64(n: i64) -> Self {
        Poly::constant(R::from_i64(n))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rational::Rational;

    type P = Poly<Rational>;

    #[test]
    fn arithmetic_and_eval() {
        let p = P::from_ints(&[1, 2, 3]); // 1 + 2t + 3t²
        let q = P::from_ints(&[-1, 1]); // t − 1
        assert_eq!((&p * &q).coeffs(), P::from_ints(&[-1, -1, -1, 3]).coeffs());
        assert_eq!(p.eval(&Rational::from(2)), Rational::from(17));
        assert_eq!(p.derivative(), P::from_ints(&[2, 6]));
        assert_eq!(p.compose(&q), P::from_ints(&[2, -4, 3]));
        assert_eq!(q.pow(3), P::from_ints(&[-1, 3, -3, 1]));
        assert!((&p - &p).is_zero());
    }

    #[test]
    fn division_and_gcd() {
        let a = P::from_ints(&[-1, 0, 1]); // t² − 1
        let b = P::from_ints(&[1, 2, 1]); // (t + 1)²
        let (q, r) = a.div_rem(&b).expect("nonzero divisor");
        assert_eq!(&(&q * &b) + &r, a);
        assert_eq!(a.gcd(&b), P::from_ints(&[1, 1]));
        assert!(a.div_rem(&P::zero()).is_err());
        let sq = (&b * &P::from_ints(&[0, 1])).square_free();
        assert_eq!(sq, P::from_ints(&[0, 1, 1]));
    }
}
