//! Bivariate polynomials `Σⱼ cⱼ(t) uʲ` (power basis; `cⱼ ∈ F[t]`) — the homogeneous
//! coordinate functions of the canal-surface parametrizations — with exact division by
//! `u² + 1`, removal of common factors in `t` and in `u`, and conversion to tensor-product
//! Bézier patches on any parameter rectangle.

use rcagd_algebra::bernstein::{tensor_bernstein_exact, tensor_sign_at, to_bernstein};
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{AlgebraError, Poly, Rational, Scalar};
use rcagd_geom::{BezierPatch, GeomError};

/// A polynomial `Σⱼ cⱼ(t) uʲ` in two variables (the first, `t`, inside the coefficients).
#[derive(Debug, Clone, PartialEq)]
pub struct BiPoly<F> {
    c: Vec<Poly<F>>,
}

impl<F: Scalar> BiPoly<F> {
    /// From the coefficients `c₀(t), c₁(t), …` of `u⁰, u¹, …` (trailing zeros removed).
    pub fn new(c: Vec<Poly<F>>) -> Self {
        let mut b = BiPoly { c };
        b.trim();
        b
    }

    fn trim(&mut self) {
        while self.c.last().is_some_and(Poly::is_zero) {
            self.c.pop();
        }
    }

    /// The zero polynomial.
    pub fn zero() -> Self {
        BiPoly { c: Vec::new() }
    }

    /// A polynomial in `t` only.
    pub fn from_t(p: Poly<F>) -> Self {
        BiPoly::new(vec![p])
    }

    /// A polynomial in `u` only.
    pub fn from_u(p: &Poly<F>) -> Self {
        BiPoly::new(
            p.coeffs()
                .iter()
                .map(|x| Poly::constant(x.clone()))
                .collect(),
        )
    }

    /// The coefficient polynomials in `t` (index = power of `u`).
    pub fn coeffs(&self) -> &[Poly<F>] {
        &self.c
    }

    /// `true` for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.c.is_empty()
    }

    /// The degree in `u` (`None` for zero).
    pub fn degree_u(&self) -> Option<usize> {
        self.c.len().checked_sub(1)
    }

    /// The least power of `u` with a non-zero coefficient (`None` for zero).
    pub fn low_degree_u(&self) -> Option<usize> {
        self.c.iter().position(|p| !p.is_zero())
    }

    /// The least power of `t` with a non-zero coefficient (`None` for zero).
    pub fn low_degree_t(&self) -> Option<usize> {
        self.c
            .iter()
            .filter_map(|p| p.coeffs().iter().position(|x| !x.is_zero()))
            .min()
    }

    /// The degree in `t` (`None` for zero).
    pub fn degree_t(&self) -> Option<usize> {
        self.c.iter().filter_map(Poly::degree).max()
    }

    /// All coefficients (for identity tests).
    pub fn all_coeffs(&self) -> Vec<F> {
        self.c
            .iter()
            .flat_map(|p| p.coeffs().iter().cloned())
            .collect()
    }

    /// The number of non-zero terms.
    pub fn num_terms(&self) -> usize {
        self.c
            .iter()
            .map(|p| p.coeffs().iter().filter(|x| !x.is_zero()).count())
            .sum()
    }

    /// The value at `(t, u)`.
    pub fn eval(&self, t: &F, u: &F) -> F {
        let mut acc = F::zero();
        for p in self.c.iter().rev() {
            acc = acc * u.clone() + p.eval(t);
        }
        acc
    }

    /// The polynomial in `u` for fixed `t`.
    pub fn at_t(&self, t: &F) -> Poly<F> {
        Poly::new(self.c.iter().map(|p| p.eval(t)).collect())
    }

    /// `self + other`.
    pub fn add(&self, other: &BiPoly<F>) -> BiPoly<F> {
        let n = self.c.len().max(other.c.len());
        BiPoly::new(
            (0..n)
                .map(|j| {
                    let a = self.c.get(j).cloned().unwrap_or_else(Poly::zero);
                    let b = other.c.get(j).cloned().unwrap_or_else(Poly::zero);
                    &a + &b
                })
                .collect(),
        )
    }

    /// `self − other`.
    pub fn sub(&self, other: &BiPoly<F>) -> BiPoly<F> {
        self.add(&other.neg())
    }

    /// `−self`.
    pub fn neg(&self) -> BiPoly<F> {
        BiPoly::new(self.c.iter().map(|p| -p).collect())
    }

    /// `self · other`. Over exact scalars by Kronecker substitution `u = t^K`,
    /// `K = deg_t(self) + deg_t(other) + 1` (no two products of terms land on the same
    /// power, so the coefficients of the univariate product are those of the bivariate one):
    /// one univariate product, for `Q` fraction-free ([`rcagd_algebra::Ring::poly_mul`]).
    pub fn mul(&self, other: &BiPoly<F>) -> BiPoly<F> {
        if self.is_zero() || other.is_zero() {
            return BiPoly::zero();
        }
        if F::EXACT {
            let k = self.degree_t().unwrap_or(0) + other.degree_t().unwrap_or(0) + 1;
            let pack = |b: &BiPoly<F>| {
                let mut v = vec![F::zero(); b.c.len() * k];
                for (j, p) in b.c.iter().enumerate() {
                    for (i, x) in p.coeffs().iter().enumerate() {
                        if let Some(slot) = v.get_mut(j * k + i) {
                            *slot = x.clone();
                        }
                    }
                }
                Poly::new(v)
            };
            let prod = &pack(self) * &pack(other);
            return BiPoly::new(
                prod.coeffs()
                    .chunks(k)
                    .map(|c| Poly::new(c.to_vec()))
                    .collect(),
            );
        }
        let mut out = vec![Poly::zero(); self.c.len() + other.c.len() - 1];
        for (i, a) in self.c.iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            for (j, b) in other.c.iter().enumerate() {
                out[i + j] = &out[i + j] + &(a * b);
            }
        }
        BiPoly::new(out)
    }

    /// `self · p(t)`.
    pub fn mul_t(&self, p: &Poly<F>) -> BiPoly<F> {
        BiPoly::new(self.c.iter().map(|c| c * p).collect())
    }

    /// `self · k` for a scalar.
    pub fn scale(&self, k: &F) -> BiPoly<F> {
        BiPoly::new(self.c.iter().map(|c| c.scale(k)).collect())
    }

    /// `∂/∂t`.
    pub fn partial_t(&self) -> BiPoly<F> {
        BiPoly::new(self.c.iter().map(Poly::derivative).collect())
    }

    /// `∂/∂u`.
    pub fn partial_u(&self) -> BiPoly<F> {
        BiPoly::new(
            self.c
                .iter()
                .enumerate()
                .skip(1)
                .map(|(j, p)| p.scale(&F::from_i64(j as i64)))
                .collect(),
        )
    }

    /// The exact quotient by `u² + 1`.
    ///
    /// # Errors
    /// [`AlgebraError::NotRepresentable`] if `u² + 1` does not divide `self`.
    pub fn div_u2_plus_1(&self) -> Result<BiPoly<F>, AlgebraError> {
        // synthetic division by the monic u² + 1: q_{j} = r_{j+2}, r_j -= q_j
        let n = self.c.len();
        if n < 3 {
            if self.is_zero() {
                return Ok(BiPoly::zero());
            }
            return Err(AlgebraError::NotRepresentable(
                "u² + 1 does not divide a polynomial of u-degree < 2".into(),
            ));
        }
        let mut r = self.c.clone();
        let mut q = vec![Poly::zero(); n - 2];
        for j in (0..n - 2).rev() {
            let c = r[j + 2].clone();
            r[j] = &r[j] - &c;
            q[j] = c;
        }
        let small = |p: &Poly<F>| {
            if F::EXACT {
                return p.is_zero();
            }
            // f64: the remainder is zero in exact arithmetic; accept rounding residue
            let scale = self
                .c
                .iter()
                .flat_map(|c| c.coeffs().iter())
                .map(|x| x.to_f64().abs())
                .fold(0.0, f64::max);
            p.coeffs()
                .iter()
                .all(|x| x.to_f64().abs() <= 1e-9 * scale.max(1.0))
        };
        if small(&r[0]) && small(&r[1]) {
            Ok(BiPoly::new(q))
        } else {
            Err(AlgebraError::NotRepresentable(
                "u² + 1 does not divide the polynomial".into(),
            ))
        }
    }

    /// The content in `t`: the monic gcd of all coefficient polynomials (exact scalars).
    pub fn content_t(&self) -> Poly<F> {
        self.c.iter().fold(Poly::zero(), |acc, p| acc.gcd(p))
    }

    /// The exact quotient by a polynomial in `t`.
    ///
    /// # Errors
    /// [`AlgebraError::NotRepresentable`] if `p` does not divide every coefficient.
    pub fn div_t(&self, p: &Poly<F>) -> Result<BiPoly<F>, AlgebraError> {
        Ok(BiPoly::new(
            self.c
                .iter()
                .map(|c| c.div_exact(p))
                .collect::<Result<Vec<_>, _>>()?,
        ))
    }

    /// `t ↔ u` (the coefficient polynomials become polynomials in `u`).
    pub fn transpose(&self) -> BiPoly<F> {
        let nt = self.degree_t().map_or(0, |d| d + 1);
        BiPoly::new(
            (0..nt)
                .map(|i| Poly::new(self.c.iter().map(|p| p.coeff(i)).collect()))
                .collect(),
        )
    }

    /// `uⁿ · self(t, 1/u)` for `n ≥ deg_u` (the chart at `u = ∞`).
    pub fn reverse_u(&self, n: usize) -> BiPoly<F> {
        let mut c = self.c.clone();
        c.resize(n + 1, Poly::zero());
        c.reverse();
        BiPoly::new(c)
    }

    /// As a sparse polynomial in the variables `(t, u)` (variable 0 is `t`).
    pub fn to_mpoly(&self) -> MPoly<F> {
        let mut out = MPoly::zero(2);
        for (j, p) in self.c.iter().enumerate() {
            for (i, x) in p.coeffs().iter().enumerate() {
                if !x.is_zero() {
                    out = &out + &MPoly::monomial(2, &[i as u32, j as u32], x.clone());
                }
            }
        }
        out
    }

    /// The scalar type converted.
    pub fn map_scalar<G: Scalar>(&self, f: impl Fn(&F) -> G + Copy) -> BiPoly<G> {
        BiPoly::new(self.c.iter().map(|p| p.map(f)).collect())
    }

    /// The coefficients over `Q`, row-major `(m + 1) × (n + 1)` in the `t` index (`None`
    /// when one is not rational or the bidegree exceeds `(m, n)`).
    fn power_rational(&self, m: usize, n: usize) -> Option<Vec<Rational>> {
        let mut power = vec![Rational::ZERO; (m + 1) * (n + 1)];
        for (j, p) in self.c.iter().enumerate() {
            for (i, x) in p.coeffs().iter().enumerate() {
                if j > n || i > m {
                    return None;
                }
                *power.get_mut(i * (n + 1) + j)? = x.to_rational()?;
            }
        }
        Some(power)
    }

    /// The sign of the value at a rational point `(t, u)` (`None` for coefficients not in
    /// `Q`), fraction-free ([`rcagd_algebra::bernstein::tensor_sign_at`]).
    pub fn sign_at(&self, t: &Rational, u: &Rational) -> Option<std::cmp::Ordering> {
        let (m, n) = (self.degree_t().unwrap_or(0), self.degree_u().unwrap_or(0));
        let power = self.power_rational(m, n)?;
        tensor_sign_at(&power, (m, n), t, u).ok()
    }

    /// [`Self::bernstein_on`] over `Q` (`None` when a coefficient or an end is not
    /// rational): the power coefficients over one common denominator, Taylor shifts and
    /// basis conversions in integers ([`rcagd_algebra::bernstein::tensor_bernstein_exact`];
    /// Farin, *Curves and Surfaces for CAGD*, 5th ed., §5.7), then one division per
    /// coefficient — the same values as the rational computation, without a gcd per
    /// operation.
    fn bernstein_on_rational(
        &self,
        (t0, t1): (&F, &F),
        (u0, u1): (&F, &F),
        m: usize,
        n: usize,
    ) -> Result<Option<Vec<F>>, AlgebraError> {
        if self.degree_t().is_some_and(|d| d > m) || self.degree_u().is_some_and(|d| d > n) {
            return Err(AlgebraError::InvalidArgument(format!(
                "bernstein_on: bidegree ({:?}, {:?}) exceeds ({m}, {n})",
                self.degree_t(),
                self.degree_u()
            )));
        }
        let q = |x: &F| x.to_rational();
        let (Some(a), Some(b), Some(c), Some(d)) = (q(t0), q(t1), q(u0), q(u1)) else {
            return Ok(None);
        };
        let Some(power) = self.power_rational(m, n) else {
            return Ok(None);
        };
        let (dt, du) = (b - a.clone(), d - c.clone());
        let out = tensor_bernstein_exact(&power, (m, n), (&a, &dt), (&c, &du))?;
        Ok(Some(out.iter().map(F::from_rational).collect()))
    }

    /// The tensor Bernstein coefficients of degree `(m, n)` on `[t₀, t₁] × [u₀, u₁]`
    /// (row-major in the `t` index).
    ///
    /// # Errors
    /// [`AlgebraError::InvalidArgument`] if a degree exceeds `(m, n)`.
    pub fn bernstein_on(
        &self,
        (t0, t1): (&F, &F),
        (u0, u1): (&F, &F),
        m: usize,
        n: usize,
    ) -> Result<Vec<F>, AlgebraError> {
        if F::EXACT {
            if let Some(c) = self.bernstein_on_rational((t0, t1), (u0, u1), m, n)? {
                return Ok(c);
            }
        }
        self.bernstein_on_generic((t0, t1), (u0, u1), m, n)
    }

    /// [`Self::bernstein_on`] by Taylor shifts and basis conversions in `F`.
    fn bernstein_on_generic(
        &self,
        (t0, t1): (&F, &F),
        (u0, u1): (&F, &F),
        m: usize,
        n: usize,
    ) -> Result<Vec<F>, AlgebraError> {
        let st = Poly::new(vec![t0.clone(), t1.clone() - t0.clone()]);
        let su = Poly::new(vec![u0.clone(), u1.clone() - u0.clone()]);
        // substitute t in every coefficient, then u as a polynomial with Poly coefficients
        let ct: Vec<Poly<F>> = self.c.iter().map(|p| p.compose(&st)).collect();
        let mut acc: Vec<Poly<F>> = Vec::new(); // coefficients in u (power of b)
        for p in ct.iter().rev() {
            // acc = acc * su + p
            let mut next = vec![Poly::zero(); acc.len() + 1];
            for (j, a) in acc.iter().enumerate() {
                next[j] = &next[j] + &a.scale(&su.coeff(0));
                next[j + 1] = &next[j + 1] + &a.scale(&su.coeff(1));
            }
            next[0] = &next[0] + p;
            acc = next;
        }
        // acc[j](a) b^j: Bernstein in a for each j, then in b
        let mut by_j: Vec<Vec<F>> = Vec::with_capacity(acc.len());
        for p in &acc {
            by_j.push(to_bernstein(p, m)?);
        }
        let mut out = vec![F::zero(); (m + 1) * (n + 1)];
        for i in 0..=m {
            let pu = Poly::new(by_j.iter().map(|v| v[i].clone()).collect());
            let b = to_bernstein(&pu, n)?;
            for (j, x) in b.into_iter().enumerate() {
                out[i * (n + 1) + j] = x;
            }
        }
        Ok(out)
    }
}

/// `(max deg_t, max deg_u)` of homogeneous components (the bidegree of a surface).
pub fn bidegree<F: Scalar>(x: &[BiPoly<F>]) -> (usize, usize) {
    (
        x.iter().filter_map(BiPoly::degree_t).max().unwrap_or(0),
        x.iter().filter_map(BiPoly::degree_u).max().unwrap_or(0),
    )
}

/// The rational tensor-product Bézier patch of the homogeneous coordinates `X` on
/// `[t₀, t₁] × [u₀, u₁]` (first patch parameter `t`, second `u`), of bidegree
/// `(deg_t, deg_u)` of `X`.
///
/// # Errors
/// [`GeomError`] for an empty coordinate list or an inconsistent layout.
pub fn patch_of<F: Scalar>(
    x: &[BiPoly<F>],
    t: (&F, &F),
    u: (&F, &F),
) -> Result<BezierPatch<F>, GeomError> {
    let m = x.iter().filter_map(BiPoly::degree_t).max().unwrap_or(0);
    let n = x.iter().filter_map(BiPoly::degree_u).max().unwrap_or(0);
    let comps: Vec<Vec<F>> = x
        .iter()
        .map(|c| c.bernstein_on(t, u, m, n))
        .collect::<Result<_, _>>()?;
    let s = x.len();
    let mut coords = vec![F::zero(); (m + 1) * (n + 1) * s];
    for (k, comp) in comps.iter().enumerate() {
        for (idx, v) in comp.iter().enumerate() {
            coords[idx * s + k] = v.clone();
        }
    }
    BezierPatch::from_flat(s - 1, m, n, coords)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn p(c: &[i64]) -> Poly<Rational> {
        Poly::from_ints(c)
    }

    #[test]
    fn division_and_bernstein() {
        // (t + u)(u² + 1)
        let a = BiPoly::new(vec![p(&[0, 1]), p(&[1])]);
        let b = BiPoly::from_u(&p(&[1, 0, 1]));
        let ab = a.mul(&b);
        assert_eq!(ab.div_u2_plus_1().expect("div"), a);
        assert!(a.div_u2_plus_1().is_err());
        let q = Rational::from_ratio(3, 7);
        let r = Rational::from(-2);
        assert_eq!(ab.eval(&q, &r), (q.clone() + r.clone()) * Rational::from(5));
        // patch evaluation agrees
        let one = BiPoly::from_t(p(&[1]));
        let patch = patch_of(
            &[one, ab.clone()],
            (&Rational::from(0), &Rational::from(2)),
            (&Rational::from(-1), &Rational::from(1)),
        )
        .expect("patch");
        let h = patch.eval_homogeneous(&Rational::from_ratio(1, 2), &Rational::from_ratio(1, 4));
        // t = 1, u = −1/2
        assert_eq!(
            h[1].clone() / h[0].clone(),
            ab.eval(&Rational::from(1), &Rational::from_ratio(-1, 2))
        );
        assert_eq!(ab.transpose().transpose(), ab);
        assert_eq!(ab.reverse_u(3).reverse_u(3), ab);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]

        /// The fraction-free tensor Bernstein coefficients over `Q` are those of the
        /// Taylor shifts in `Q` (also with degrees raised above the polynomial's).
        #[test]
        fn rational_bernstein_is_the_generic_one(
            raw in proptest::collection::vec((-9i64..10, 1i64..9), 12),
            dt in 0usize..4,
            du in 0usize..3,
            extra in (0usize..2, 0usize..2),
            ends in (-4i64..5, 1i64..5, 1i64..9, 1i64..5),
        ) {
            let mut it = raw.iter().cycle();
            let c: Vec<Poly<Rational>> = (0..=du)
                .map(|_| {
                    Poly::new(
                        (0..=dt)
                            .filter_map(|_| it.next())
                            .map(|&(a, b)| Rational::from_ratio(a, b))
                            .collect(),
                    )
                })
                .collect();
            let b = BiPoly::new(c);
            let t0 = Rational::from_ratio(ends.0, ends.1);
            let t1 = t0.clone() + Rational::from_ratio(ends.2, ends.3);
            let (u0, u1) = (Rational::from_ratio(-1, ends.1), Rational::from_ratio(ends.2, 3));
            let (m, n) = (dt + extra.0, du + extra.1);
            let fast = b.bernstein_on((&t0, &t1), (&u0, &u1), m, n).expect("degrees");
            let slow = b
                .bernstein_on_generic((&t0, &t1), (&u0, &u1), m, n)
                .expect("degrees");
            proptest::prop_assert_eq!(fast, slow);
            // the Kronecker product against the sum of products of the coefficients
            let b2 = BiPoly::new(b.c.iter().rev().cloned().collect());
            let mut naive = vec![Poly::zero(); (b.c.len() + b2.c.len()).saturating_sub(1)];
            for (i, x) in b.c.iter().enumerate() {
                for (j, y) in b2.c.iter().enumerate() {
                    naive[i + j] = &naive[i + j] + &(x * y);
                }
            }
            proptest::prop_assert_eq!(b.mul(&b2), BiPoly::new(naive));
            let want = b.eval(&t1, &u0).partial_cmp(&Rational::ZERO);
            proptest::prop_assert_eq!(b.sign_at(&t1, &u0), want);
        }
    }
}
