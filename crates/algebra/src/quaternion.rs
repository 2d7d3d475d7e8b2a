//! Quaternions `w + x i + y j + z k` over a commutative ring, and quaternion polynomials.
//!
//! Conventions of Besednjak (docs/math/ph-curves.md, "Conventions"): `i² = j² = k² = ijk = −1`, so `ij = k`,
//! `jk = i`, `ki = j` and `ji = −k`, `kj = −i`, `ik = −j`. Writing `A = (a, a⃗)` with scalar
//! part `a` and vector part `a⃗`, the Hamilton product is
//!
//! `(a, a⃗)(b, b⃗) = (ab − a⃗·b⃗, a b⃗ + b a⃗ + a⃗ × b⃗)` (not commutative),
//!
//! the conjugate `A* = (a, −a⃗)` reverses products, `(AB)* = B*A*`, and
//! `|A|² = A A* = a² + |a⃗|²` is multiplicative, `|AB|² = |A|²|B|²`.
//!
//! **PH curves** (Besednjak §2, docs/math/ph-curves.md, "The hodograph and the speed"): for a quaternion polynomial
//! `A(t) = u + v i + p j + q k` the hodograph `r'(t) = A(t) i A*(t)` is a pure vector
//! `(u²+v²−p²−q², 2(uq+vp), 2(vq−up))` with `|r'| = |A|² = u²+v²+p²+q²` ([`sandwich_i`],
//! [`norm_sq_poly`]). In general `A u A*` is a pure vector of length `|A|²|u|` for a pure
//! vector `u` ([`sandwich`]).
//!
//! Polynomials in a real parameter `t` are [`Poly<Quaternion<F>>`](Poly); their product
//! keeps the order of the factors, and `A*(t) = Σ Aₖ* tᵏ` ([`conj_poly`]).

use crate::poly::Poly;
use crate::scalar::{Field, Ring, Scalar};
use core::fmt;
use core::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use num_traits::{One, Zero};

/// The quaternion `w + x i + y j + z k` (`w` the scalar part, `(x, y, z)` the vector part).
#[derive(Clone, Debug, PartialEq, Eq, Hash, Default)]
pub struct Quaternion<F> {
    /// Scalar (real) part.
    pub w: F,
    /// Coefficient of `i`.
    pub x: F,
    /// Coefficient of `j`.
    pub y: F,
    /// Coefficient of `k`.
    pub z: F,
}

impl<F> Quaternion<F> {
    /// `w + x i + y j + z k`.
    pub const fn new(w: F, x: F, y: F, z: F) -> Self {
        Quaternion { w, x, y, z }
    }
}

impl<F: Ring> Quaternion<F> {
    /// The real quaternion `w`.
    pub fn from_real(w: F) -> Self {
        Quaternion {
            w,
            x: F::zero(),
            y: F::zero(),
            z: F::zero(),
        }
    }

    /// The pure quaternion `x i + y j + z k` of a vector `[x, y, z]`.
    pub fn from_vector(v: [F; 3]) -> Self {
        let [x, y, z] = v;
        Quaternion {
            w: F::zero(),
            x,
            y,
            z,
        }
    }

    /// The unit `i`.
    pub fn i() -> Self {
        Self::from_vector([F::one(), F::zero(), F::zero()])
    }

    /// The unit `j`.
    pub fn j() -> Self {
        Self::from_vector([F::zero(), F::one(), F::zero()])
    }

    /// The unit `k`.
    pub fn k() -> Self {
        Self::from_vector([F::zero(), F::zero(), F::one()])
    }

    /// The scalar part `w`.
    pub fn scalar_part(&self) -> F {
        self.w.clone()
    }

    /// The vector part `[x, y, z]`.
    pub fn vector_part(&self) -> [F; 3] {
        [self.x.clone(), self.y.clone(), self.z.clone()]
    }

    /// `true` if the scalar part is zero (a pure vector).
    pub fn is_pure(&self) -> bool {
        self.w.is_zero()
    }

    /// The conjugate `A* = w − x i − y j − z k`; `(AB)* = B* A*`.
    pub fn conj(&self) -> Self {
        Quaternion {
            w: self.w.clone(),
            x: -self.x.clone(),
            y: -self.y.clone(),
            z: -self.z.clone(),
        }
    }

    /// `|A|² = A A* = w² + x² + y² + z²`.
    pub fn norm_sq(&self) -> F {
        self.w.clone() * self.w.clone()
            + self.x.clone() * self.x.clone()
            + self.y.clone() * self.y.clone()
            + self.z.clone() * self.z.clone()
    }

    /// The Euclidean inner product `w w' + x x' + y y' + z z'` of the coefficient vectors
    /// (`= Re(A B*)`).
    pub fn dot(&self, other: &Self) -> F {
        self.w.clone() * other.w.clone()
            + self.x.clone() * other.x.clone()
            + self.y.clone() * other.y.clone()
            + self.z.clone() * other.z.clone()
    }

    /// Multiplication by the real scalar `c` (which commutes with every quaternion).
    pub fn scale(&self, c: &F) -> Self {
        Quaternion {
            w: c.clone() * self.w.clone(),
            x: c.clone() * self.x.clone(),
            y: c.clone() * self.y.clone(),
            z: c.clone() * self.z.clone(),
        }
    }

    /// Applies `f` to all four coefficients.
    pub fn map<G>(&self, f: impl Fn(&F) -> G) -> Quaternion<G> {
        Quaternion {
            w: f(&self.w),
            x: f(&self.x),
            y: f(&self.y),
            z: f(&self.z),
        }
    }
}

impl<F: Field> Quaternion<F> {
    /// `A⁻¹ = A* / |A|²` (two-sided inverse), `None` if `|A|² = 0`.
    pub fn inverse(&self) -> Option<Self> {
        let inv = self.norm_sq().inv()?;
        Some(self.conj().scale(&inv))
    }
}

impl<S: Scalar> Quaternion<S> {
    /// The nearest `f64` coefficients.
    pub fn to_f64(&self) -> Quaternion<f64> {
        self.map(|c| c.to_f64())
    }
}

impl<F: Ring> Add for Quaternion<F> {
    type Output = Self;
    fn add(self, r: Self) -> Self {
        Quaternion {
            w: self.w + r.w,
            x: self.x + r.x,
            y: self.y + r.y,
            z: self.z + r.z,
        }
    }
}

impl<F: Ring> Sub for Quaternion<F> {
    type Output = Self;
    fn sub(self, r: Self) -> Self {
        Quaternion {
            w: self.w - r.w,
            x: self.x - r.x,
            y: self.y - r.y,
            z: self.z - r.z,
        }
    }
}

/// The Hamilton product `(a, a⃗)(b, b⃗) = (ab − a⃗·b⃗, a b⃗ + b a⃗ + a⃗ × b⃗)`, i.e.
/// `w = w₁w₂ − x₁x₂ − y₁y₂ − z₁z₂`, `x = w₁x₂ + x₁w₂ + y₁z₂ − z₁y₂`,
/// `y = w₁y₂ − x₁z₂ + y₁w₂ + z₁x₂`, `z = w₁z₂ + x₁y₂ − y₁x₂ + z₁w₂`.
impl<F: Ring> Mul for Quaternion<F> {
    type Output = Self;
    fn mul(self, r: Self) -> Self {
        let (w1, x1, y1, z1) = (self.w, self.x, self.y, self.z);
        let (w2, x2, y2, z2) = (r.w, r.x, r.y, r.z);
        Quaternion {
            w: w1.clone() * w2.clone()
                - x1.clone() * x2.clone()
                - y1.clone() * y2.clone()
                - z1.clone() * z2.clone(),
            x: w1.clone() * x2.clone() + x1.clone() * w2.clone() + y1.clone() * z2.clone()
                - z1.clone() * y2.clone(),
            y: w1.clone() * y2.clone() - x1.clone() * z2.clone()
                + y1.clone() * w2.clone()
                + z1.clone() * x2.clone(),
            z: w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
        }
    }
}

impl<F: Ring> Neg for Quaternion<F> {
    type Output = Self;
    fn neg(self) -> Self {
        Quaternion {
            w: -self.w,
            x: -self.x,
            y: -self.y,
            z: -self.z,
        }
    }
}

impl<F: Ring> AddAssign for Quaternion<F> {
    fn add_assign(&mut self, r: Self) {
        self.w += r.w;
        self.x += r.x;
        self.y += r.y;
        self.z += r.z;
    }
}

impl<F: Ring> SubAssign for Quaternion<F> {
    fn sub_assign(&mut self, r: Self) {
        self.w -= r.w;
        self.x -= r.x;
        self.y -= r.y;
        self.z -= r.z;
    }
}

/// `a *= b` is `a = a·b` (right multiplication).
impl<F: Ring> MulAssign for Quaternion<F> {
    fn mul_assign(&mut self, r: Self) {
        *self = self.clone() * r;
    }
}

impl<F: Ring> Zero for Quaternion<F> {
    fn zero() -> Self {
        Quaternion::from_real(F::zero())
    }
    fn is_zero(&self) -> bool {
        self.w.is_zero() && self.x.is_zero() && self.y.is_zero() && self.z.is_zero()
    }
}

impl<F: Ring> One for Quaternion<F> {
    fn one() -> Self {
        Quaternion::from_real(F::one())
    }
}

/// Quaternions form a non-commutative ring (a division ring over an ordered field).
impl<F: Ring> Ring for Quaternion<F> {
    fn from_i64(n: i64) -> Self {
        Quaternion::from_real(F::from_i64(n))
    }
}

fn write_term<F: fmt::Display>(
    f: &mut fmt::Formatter<'_>,
    c: &F,
    unit: &str,
    first: bool,
) -> fmt::Result {
    let s = c.to_string();
    let s = if s
        .chars()
        .skip(1)
        .any(|ch| ch == ' ' || ch == '+' || ch == '-')
    {
        format!("({s})")
    } else {
        s
    };
    if first {
        return write!(f, "{s}{unit}");
    }
    match s.strip_prefix('-') {
        Some(rest) => write!(f, " - {rest}{unit}"),
        None => write!(f, " + {s}{unit}"),
    }
}

/// `w + xi + yj + zk`, e.g. `1 - 2i + 0j + 1/2k`.
impl<F: fmt::Display> fmt::Display for Quaternion<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_term(f, &self.w, "", true)?;
        write_term(f, &self.x, "i", false)?;
        write_term(f, &self.y, "j", false)?;
        write_term(f, &self.z, "k", false)
    }
}

/// The conjugate polynomial `A*(t) = Σ Aₖ* tᵏ`.
pub fn conj_poly<F: Ring>(a: &Poly<Quaternion<F>>) -> Poly<Quaternion<F>> {
    a.map(Quaternion::conj)
}

/// The four coefficient polynomials `[w(t), x(t), y(t), z(t)]` of `A(t)`.
pub fn component_polys<F: Ring>(a: &Poly<Quaternion<F>>) -> [Poly<F>; 4] {
    [
        a.map(|c| c.w.clone()),
        a.map(|c| c.x.clone()),
        a.map(|c| c.y.clone()),
        a.map(|c| c.z.clone()),
    ]
}

/// The quaternion polynomial `w + x i + y j + z k` of four real polynomials.
pub fn from_component_polys<F: Ring>(c: &[Poly<F>; 4]) -> Poly<Quaternion<F>> {
    let n = c.iter().map(|p| p.coeffs().len()).max().unwrap_or(0);
    Poly::new(
        (0..n)
            .map(|k| Quaternion::new(c[0].coeff(k), c[1].coeff(k), c[2].coeff(k), c[3].coeff(k)))
            .collect(),
    )
}

/// The vector-part polynomials `[x(t), y(t), z(t)]` (e.g. the hodograph components of
/// `A i A*`).
pub fn vector_polys<F: Ring>(p: &Poly<Quaternion<F>>) -> [Poly<F>; 3] {
    [
        p.map(|c| c.x.clone()),
        p.map(|c| c.y.clone()),
        p.map(|c| c.z.clone()),
    ]
}

/// The scalar-part polynomial `w(t)`.
pub fn scalar_poly<F: Ring>(p: &Poly<Quaternion<F>>) -> Poly<F> {
    p.map(|c| c.w.clone())
}

/// The pure quaternion polynomial `x i + y j + z k` of three real polynomials.
pub fn from_vector_polys<F: Ring>(v: &[Poly<F>; 3]) -> Poly<Quaternion<F>> {
    from_component_polys(&[Poly::zero(), v[0].clone(), v[1].clone(), v[2].clone()])
}

/// `|A(t)|² = A(t)A*(t) = w² + x² + y² + z²`, a real polynomial: the parametric speed
/// `σ` of the PH curve with hodograph `A i A*` (docs/math/ph-curves.md, "The hodograph and the speed").
pub fn norm_sq_poly<F: Ring>(a: &Poly<Quaternion<F>>) -> Poly<F> {
    let [w, x, y, z] = component_polys(a);
    &(&(&(&w * &w) + &(&x * &x)) + &(&y * &y)) + &(&z * &z)
}

/// The sandwich product `A(t) u A*(t)` for a constant quaternion `u`, computed as a
/// product of polynomials (order kept). For a pure vector `u` the result is a pure
/// vector with `|A u A*| = |A|²|u|`; for a unit `u` it is the hodograph of a PH curve
/// (`u = i` is [`sandwich_i`]).
pub fn sandwich<F: Ring>(a: &Poly<Quaternion<F>>, u: &Quaternion<F>) -> Poly<Quaternion<F>> {
    &a.scale(u) * &conj_poly(a)
}

/// The PH hodograph `r'(t) = A(t) i A*(t)` (Besednjak §2, docs/math/ph-curves.md, "The hodograph and the speed") as a pure quaternion
/// polynomial, by the closed form for `A = u + v i + p j + q k`:
/// `A i A* = (u² + v² − p² − q²) i + 2(uq + vp) j + 2(vq − up) k`.
pub fn sandwich_i<F: Ring>(a: &Poly<Quaternion<F>>) -> Poly<Quaternion<F>> {
    let [u, v, p, q] = component_polys(a);
    let two = Poly::constant(F::from_i64(2));
    let x = &(&(&u * &u) + &(&v * &v)) - &(&(&p * &p) + &(&q * &q));
    let y = &two * &(&(&u * &q) + &(&v * &p));
    let z = &two * &(&(&v * &q) - &(&u * &p));
    from_vector_polys(&[x, y, z])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rational::Rational;

    type Q = Quaternion<Rational>;

    fn h(w: i64, x: i64, y: i64, z: i64) -> Q {
        Quaternion::new(
            Rational::from(w),
            Rational::from(x),
            Rational::from(y),
            Rational::from(z),
        )
    }

    #[test]
    fn units_multiply_by_hamilton_rules() {
        let (i, j, k) = (Q::i(), Q::j(), Q::k());
        let m1 = Q::from_i64(-1);
        assert_eq!(i.clone() * i.clone(), m1);
        assert_eq!(j.clone() * j.clone(), m1);
        assert_eq!(k.clone() * k.clone(), m1);
        assert_eq!(i.clone() * j.clone(), k);
        assert_eq!(j.clone() * k.clone(), i);
        assert_eq!(k.clone() * i.clone(), j);
        assert_eq!(j.clone() * i.clone(), -k.clone());
        assert_eq!(i.clone() * j.clone() * k, m1);
    }

    #[test]
    fn conj_norm_inverse() {
        let a = h(1, 2, -3, 4);
        assert_eq!(a.norm_sq(), Rational::from(30));
        assert_eq!(a.clone() * a.conj(), Q::from_i64(30));
        let inv = a.inverse().expect("nonzero");
        assert_eq!(a.clone() * inv.clone(), Q::one());
        assert_eq!(inv * a.clone(), Q::one());
        assert!(Q::zero().inverse().is_none());
        assert_eq!(a.vector_part(), [2, -3, 4].map(Rational::from));
        assert_eq!(Q::from_vector(a.vector_part()), h(0, 2, -3, 4));
        assert_eq!(a.to_f64(), Quaternion::new(1.0, 2.0, -3.0, 4.0));
        assert_eq!(a.to_string(), "1 + 2i - 3j + 4k");
    }

    #[test]
    fn hodograph_of_lemma_2_1_example() {
        // docs/math/ph-curves.md, "Prescribed tangents (Lemma 2.1)": c = (−1, 2, 2) is solved by Q = i + j + k.
        let a = Poly::constant(h(0, 1, 1, 1));
        let r = sandwich_i(&a);
        assert_eq!(r, Poly::constant(h(0, -1, 2, 2)));
        assert_eq!(sandwich(&a, &Q::i()), r);
    }

    #[test]
    fn ph_cubic_hodograph() {
        // A(t) = 1 + t i  → A i A* = (1 + t², 0, 0)... with a j-part: A = 1 + t·j
        let a = Poly::new(vec![h(1, 0, 0, 0), h(0, 0, 1, 0)]);
        let r = sandwich_i(&a);
        // u = 1, p = t: (1 − t², 0, −2t)
        let [x, y, z] = vector_polys(&r);
        assert_eq!(x, Poly::from_ints(&[1, 0, -1]));
        assert!(y.is_zero());
        assert_eq!(z, Poly::from_ints(&[0, -2]));
        assert!(scalar_poly(&r).is_zero());
        assert_eq!(sandwich(&a, &Q::i()), r);
        let sigma = norm_sq_poly(&a);
        assert_eq!(sigma, Poly::from_ints(&[1, 0, 1]));
        assert_eq!(&(&(&x * &x) + &(&y * &y)) + &(&z * &z), &sigma * &sigma);
    }
}
