//! Complex numbers `re + im·i` over any ring, and polynomials with complex coefficients.
//!
//! `Complex<F>` is `F[i]/(i² + 1)`: over a field `F` in which `−1` is not a sum of two
//! squares (`Q`, `Q(√d)`, `f64`) it is a field, with
//!
//! * `(a + bi)(c + di) = (ac − bd) + (ad + bc)i`,
//! * conjugate `z̄ = a − bi`, `|z|² = z z̄ = a² + b²`,
//! * `z⁻¹ = z̄ / |z|²`.
//!
//! The Gaussian rationals `Q(i) = Complex<Rational>` carry the Hopf form of spatial
//! PH curves: `A = α + kβ` with `α = u + iv`, `β = q + ip`, hodograph
//! `r' = (|α|² − |β|², 2 Re(αβ̄), 2 Im(αβ̄))` (docs/math/ph-curves.md, "Conventions").
//! For polynomials `p(t) = Σ cₖtᵏ` (real parameter `t`), `p̄(t) = Σ c̄ₖtᵏ` and
//! `|p(t)|² = p(t)·p̄(t) = Re(p)² + Im(p)²` ([`norm_sq_poly`]).
//!
//! `F` is assumed commutative (every scalar type of rcagd is).

use crate::poly::Poly;
use crate::scalar::{Field, Ring, Scalar};
use core::fmt;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use num_traits::{One, Zero};

/// The complex number `re + im·i`.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Default)]
pub struct Complex<F> {
    /// Real part.
    pub re: F,
    /// Imaginary part.
    pub im: F,
}

impl<F> Complex<F> {
    /// `re + im·i`.
    pub const fn new(re: F, im: F) -> Self {
        Complex { re, im }
    }
}

impl<F: Ring> Complex<F> {
    /// The real number `re` (imaginary part zero).
    pub fn from_real(re: F) -> Self {
        Complex { re, im: F::zero() }
    }

    /// The imaginary unit `i`, `i² = −1`.
    pub fn i() -> Self {
        Complex {
            re: F::zero(),
            im: F::one(),
        }
    }

    /// The conjugate `re − im·i`.
    pub fn conj(&self) -> Self {
        Complex {
            re: self.re.clone(),
            im: -self.im.clone(),
        }
    }

    /// `|z|² = z z̄ = re² + im²`.
    pub fn norm_sq(&self) -> F {
        self.re.clone() * self.re.clone() + self.im.clone() * self.im.clone()
    }

    /// `true` if the imaginary part is zero.
    pub fn is_real(&self) -> bool {
        self.im.is_zero()
    }

    /// Multiplication by the real scalar `c`: `(c·re) + (c·im)i`.
    pub fn scale(&self, c: &F) -> Self {
        Complex {
            re: c.clone() * self.re.clone(),
            im: c.clone() * self.im.clone(),
        }
    }

    /// Applies `f` to both parts (e.g. a conversion to `f64`).
    pub fn map<G>(&self, f: impl Fn(&F) -> G) -> Complex<G> {
        Complex {
            re: f(&self.re),
            im: f(&self.im),
        }
    }
}

impl<F: Field> Complex<F> {
    /// `z⁻¹ = z̄ / |z|²`; `None` if `|z|² = 0` (for the field types of rcagd: `z = 0`).
    pub fn inverse(&self) -> Option<Self> {
        let n = self.norm_sq();
        let inv = n.inv()?;
        Some(Complex {
            re: self.re.clone() * inv.clone(),
            im: -self.im.clone() * inv,
        })
    }
}

impl<S: Scalar> Complex<S> {
    /// The nearest `f64` parts.
    pub fn to_f64(&self) -> Complex<f64> {
        Complex {
            re: self.re.to_f64(),
            im: self.im.to_f64(),
        }
    }
}

impl<F: Ring> Add for Complex<F> {
    type Output = Self;
    fn add(self, rhs: Self) -> Self {
        Complex {
            re: self.re + rhs.re,
            im: self.im + rhs.im,
        }
    }
}

impl<F: Ring> Sub for Complex<F> {
    type Output = Self;
    fn sub(self, rhs: Self) -> Self {
        Complex {
            re: self.re - rhs.re,
            im: self.im - rhs.im,
        }
    }
}

/// `(a + bi)(c + di) = (ac − bd) + (ad + bc)i`.
impl<F: Ring> Mul for Complex<F> {
    type Output = Self;
    fn mul(self, rhs: Self) -> Self {
        // a real factor: (a + bi)c = ac + bci (the same value, two products instead of four)
        if rhs.im.is_zero() {
            return Complex {
                re: self.re * rhs.re.clone(),
                im: self.im * rhs.re,
            };
        }
        if self.im.is_zero() {
            return Complex {
                re: self.re.clone() * rhs.re,
                im: self.re * rhs.im,
            };
        }
        Complex {
            re: self.re.clone() * rhs.re.clone() - self.im.clone() * rhs.im.clone(),
            im: self.re * rhs.im + self.im * rhs.re,
        }
    }
}

/// `(a + bi)/(c + di) = ((ac + bd) + (bc − ad)i) / (c² + d²)`.
///
/// # Panics
/// Division by zero behaves as division by zero in `F` (panics for [`crate::Rational`],
/// gives non-finite values for `f64`); use [`Field::inv`] / [`Complex::inverse`] to
/// get `None` instead.
impl<F: Field> Div for Complex<F> {
    type Output = Self;
    fn div(self, rhs: Self) -> Self {
        let n = rhs.norm_sq();
        let re = self.re.clone() * rhs.re.clone() + self.im.clone() * rhs.im.clone();
        let im = self.im * rhs.re - self.re * rhs.im;
        Complex {
            re: re / n.clone(),
            im: im / n,
        }
    }
}

impl<F: Ring> Neg for Complex<F> {
    type Output = Self;
    fn neg(self) -> Self {
        Complex {
            re: -self.re,
            im: -self.im,
        }
    }
}

impl<F: Ring> AddAssign for Complex<F> {
    fn add_assign(&mut self, rhs: Self) {
        self.re += rhs.re;
        self.im += rhs.im;
    }
}

impl<F: Ring> SubAssign for Complex<F> {
    fn sub_assign(&mut self, rhs: Self) {
        self.re -= rhs.re;
        self.im -= rhs.im;
    }
}

impl<F: Ring> MulAssign for Complex<F> {
    fn mul_assign(&mut self, rhs: Self) {
        *self = self.clone() * rhs;
    }
}

impl<F: Field> DivAssign for Complex<F> {
    fn div_assign(&mut self, rhs: Self) {
        *self = self.clone() / rhs;
    }
}

impl<F: Ring> Zero for Complex<F> {
    fn zero() -> Self {
        Complex {
            re: F::zero(),
            im: F::zero(),
        }
    }
    fn is_zero(&self) -> bool {
        self.re.is_zero() && self.im.is_zero()
    }
}

impl<F: Ring> One for Complex<F> {
    fn one() -> Self {
        Complex::from_real(F::one())
    }
}

impl<F: Ring> Ring for Complex<F> {
    fn from_i64(n: i64) -> Self {
        Complex::from_real(F::from_i64(n))
    }

    /// `(A + iB)(C + iD) = (AC − BD) + i((A + B)(C + D) − AC − BD)` with the three real
    /// products by `F`'s own product ([`Ring::poly_mul`]; for [`crate::Rational`]
    /// fraction-free), one product per real part when a factor is real. `None` (the
    /// generic product) when `F` has no faster product. Exact: the same polynomial.
    fn poly_mul(a: &[Self], b: &[Self]) -> Option<Vec<Self>> {
        let part = |v: &[Self], im: bool| -> Vec<F> {
            v.iter()
                .map(|z| if im { z.im.clone() } else { z.re.clone() })
                .collect()
        };
        let (ar, ai, br, bi) = (part(a, false), part(a, true), part(b, false), part(b, true));
        let real = |v: &[F]| v.iter().all(Zero::is_zero);
        let n = (a.len() + b.len()).saturating_sub(1);
        let pad = |mut v: Vec<F>| {
            v.resize(n, F::zero());
            v
        };
        let (re, im) = match (real(&ai), real(&bi)) {
            (true, true) => (F::poly_mul(&ar, &br)?, vec![F::zero(); n]),
            (false, true) => (F::poly_mul(&ar, &br)?, F::poly_mul(&ai, &br)?),
            (true, false) => (F::poly_mul(&ar, &br)?, F::poly_mul(&ar, &bi)?),
            (false, false) => {
                let ac = pad(F::poly_mul(&ar, &br)?);
                let bd = pad(F::poly_mul(&ai, &bi)?);
                let sa: Vec<F> = ar
                    .iter()
                    .zip(&ai)
                    .map(|(x, y)| x.clone() + y.clone())
                    .collect();
                let sb: Vec<F> = br
                    .iter()
                    .zip(&bi)
                    .map(|(x, y)| x.clone() + y.clone())
                    .collect();
                let s = pad(F::poly_mul(&sa, &sb)?);
                let im = s
                    .into_iter()
                    .zip(ac.iter().zip(&bd))
                    .map(|(x, (p, q))| x - p.clone() - q.clone())
                    .collect();
                let re = ac.into_iter().zip(bd).map(|(p, q)| p - q).collect();
                (re, im)
            }
        };
        Some(
            pad(re)
                .into_iter()
                .zip(pad(im))
                .map(|(re, im)| Complex { re, im })
                .collect(),
        )
    }
}

impl<F: Field> Field for Complex<F> {
    fn inv(&self) -> Option<Self> {
        self.inverse()
    }

    /// A common factor `h` of `p` and `q` over `F(i)` gives the common factor `h h̄` of
    /// the norms `p p̄` and `q q̄` over `F` ([`norm_sq_poly`]): when `F` has a fast `gcd`
    /// ([`Field::fast_poly_gcd`]) and the norms are coprime, the monic `gcd` is `1`
    /// (the usual case, decided without Euclid over `F(i)`); otherwise `None` (Euclid).
    fn fast_poly_gcd(a: &Poly<Self>, b: &Poly<Self>) -> Option<Poly<Self>> {
        let (da, db) = (a.degree()?, b.degree()?);
        if da == 0 || db == 0 {
            return Some(Poly::constant(Complex::one()));
        }
        let g = F::fast_poly_gcd(&norm_sq_poly(a), &norm_sq_poly(b))?;
        (g.degree() == Some(0)).then(|| Poly::constant(Complex::one()))
    }
}

fn needs_parens(s: &str) -> bool {
    s.chars().skip(1).any(|c| c == ' ' || c == '+' || c == '-')
}

/// `re + im i` (e.g. `1/2 - 3i`, `(1 + √2) + (2 - √2)i`); parts that are sums are
/// parenthesised.
impl<F: Ring + fmt::Display> fmt::Display for Complex<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let re = self.re.to_string();
        let im = self.im.to_string();
        let re = if needs_parens(&re) {
            format!("({re})")
        } else {
            re
        };
        if needs_parens(&im) {
            return write!(f, "{re} + ({im})i");
        }
        match im.strip_prefix('-') {
            Some(rest) => write!(f, "{re} - {rest}i"),
            None => write!(f, "{re} + {im}i"),
        }
    }
}

/// The conjugate polynomial `p̄(t) = Σ c̄ₖ tᵏ` (conjugation of the coefficients; the
/// parameter `t` is real).
pub fn conj_poly<F: Ring>(p: &Poly<Complex<F>>) -> Poly<Complex<F>> {
    p.map(Complex::conj)
}

/// The real and imaginary parts `(Re p, Im p)`, so that `p = Re p + i·Im p`.
pub fn re_im_polys<F: Ring>(p: &Poly<Complex<F>>) -> (Poly<F>, Poly<F>) {
    (p.map(|c| c.re.clone()), p.map(|c| c.im.clone()))
}

/// The complex polynomial `re + i·im`.
pub fn from_re_im_polys<F: Ring>(re: &Poly<F>, im: &Poly<F>) -> Poly<Complex<F>> {
    let n = re.coeffs().len().max(im.coeffs().len());
    Poly::new(
        (0..n)
            .map(|k| Complex::new(re.coeff(k), im.coeff(k)))
            .collect(),
    )
}

/// `|p(t)|² = p(t)·p̄(t) = (Re p)² + (Im p)²`, a real polynomial (for real `t`).
/// This is the parametric-speed building block `|α|² + |β|²` (docs/math/ph-curves.md,
/// "The hodograph and the speed").
pub fn norm_sq_poly<F: Ring>(p: &Poly<Complex<F>>) -> Poly<F> {
    let (re, im) = re_im_polys(p);
    &(&re * &re) + &(&im * &im)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rational::Rational;
    use dashu_int::IBig;

    type C = Complex<Rational>;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_parts_signed(IBig::from(p), IBig::from(d))
    }
    fn c(a: i64, b: i64) -> C {
        Complex::new(q(a, 1), q(b, 1))
    }

    #[test]
    fn field_operations() {
        let i = C::i();
        assert_eq!(i.clone() * i, c(-1, 0));
        let z = c(3, 4);
        assert_eq!(z.norm_sq(), q(25, 1));
        assert_eq!(z.clone() * z.conj(), c(25, 0));
        let zi = z.inv().expect("nonzero");
        assert_eq!(zi, Complex::new(q(3, 25), q(-4, 25)));
        assert_eq!(z.clone() * zi, C::one());
        assert_eq!(c(1, 2) / c(3, 4), Complex::new(q(11, 25), q(2, 25)));
        assert!(C::zero().inv().is_none());
        let mut w = c(1, 1);
        w *= c(1, -1);
        assert_eq!(w, c(2, 0));
        w /= c(0, 2);
        assert_eq!(w, c(0, -1));
        assert_eq!(C::from_i64(5), c(5, 0));
        assert_eq!(z.to_f64(), Complex::new(3.0, 4.0));
    }

    #[test]
    fn display() {
        assert_eq!(c(1, -2).to_string(), "1 - 2i");
        assert_eq!(Complex::new(q(1, 2), q(3, 4)).to_string(), "1/2 + 3/4i");
        assert_eq!(c(-1, 0).to_string(), "-1 + 0i");
    }

    #[test]
    fn polynomials() {
        // p = (1 + i) + (2 − i)t
        let p = Poly::new(vec![c(1, 1), c(2, -1)]);
        let (re, im) = re_im_polys(&p);
        assert_eq!(re, Poly::from_ints(&[1, 2]));
        assert_eq!(im, Poly::from_ints(&[1, -1]));
        assert_eq!(from_re_im_polys(&re, &im), p);
        // |p|² = (1+2t)² + (1−t)² = 2 + 2t + 5t²
        let n = norm_sq_poly(&p);
        assert_eq!(n, Poly::from_ints(&[2, 2, 5]));
        // p·p̄ is the real polynomial |p|²
        let prod = &p * &conj_poly(&p);
        assert_eq!(prod, n.map(|x| Complex::from_real(x.clone())));
    }

    /// The generic product of two polynomials (sum of coefficient products), for comparison.
    fn schoolbook(a: &Poly<C>, b: &Poly<C>) -> Poly<C> {
        let mut out = vec![C::zero(); a.coeffs().len() + b.coeffs().len() - 1];
        for (i, x) in a.coeffs().iter().enumerate() {
            for (j, y) in b.coeffs().iter().enumerate() {
                out[i + j] += x.clone() * y.clone();
            }
        }
        Poly::new(out)
    }

    fn cpoly(raw: &[(i64, i64, i64)]) -> Poly<C> {
        Poly::new(
            raw.iter()
                .map(|&(a, b, d)| Complex::new(q(a, d), q(b, d)))
                .collect(),
        )
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]

        /// The fraction-free product over `Q(i)` (`Ring::poly_mul`) is the generic product,
        /// for complex, real and purely imaginary factors.
        #[test]
        fn fast_product_is_the_generic_product(
            a in proptest::collection::vec((-9i64..10, -9i64..10, 1i64..7), 1..7),
            b in proptest::collection::vec((-9i64..10, -9i64..10, 1i64..7), 1..7),
            kind in 0usize..4,
        ) {
            let mut pa = cpoly(&a);
            let mut pb = cpoly(&b);
            if kind & 1 == 1 {
                pa = pa.map(|z| Complex::from_real(z.re.clone()));
            }
            if kind & 2 == 2 {
                pb = pb.map(|z| Complex::new(Rational::ZERO, z.im.clone()));
            }
            proptest::prop_assume!(!pa.is_zero() && !pb.is_zero());
            proptest::prop_assert_eq!(&pa * &pb, schoolbook(&pa, &pb));
        }

        /// The `gcd` over `Q(i)` with the norm test (`Field::fast_poly_gcd`) is Euclid's,
        /// with and without a planted common factor.
        #[test]
        fn norm_test_gcd_is_euclids(
            a in proptest::collection::vec((-9i64..10, -9i64..10, 1i64..7), 1..5),
            b in proptest::collection::vec((-9i64..10, -9i64..10, 1i64..7), 1..5),
            h in proptest::collection::vec((-5i64..6, -5i64..6, 1i64..4), 1..3),
            plant in proptest::bool::ANY,
        ) {
            let (mut pa, mut pb) = (cpoly(&a), cpoly(&b));
            if plant {
                let ph = cpoly(&h);
                pa = &pa * &ph;
                pb = &pb * &ph;
            }
            proptest::prop_assume!(!pa.is_zero() && !pb.is_zero());
            proptest::prop_assert_eq!(pa.gcd(&pb), pa.gcd_euclid(&pb));
        }
    }
}
