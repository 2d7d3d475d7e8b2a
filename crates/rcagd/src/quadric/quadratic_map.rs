//! Quadratic maps of homogeneous coordinates, their polar forms, and exact identity
//! certificates of the maps themselves.
//!
//! A quadratic map `F: P³ → P³` is stored as four symmetric matrices `M_k` with
//! `F_k(p) = pᵀ M_k p`. Its polar form is `F̂_k(a, b) = aᵀ M_k b`
//! `= (F(a+b) − F(a−b))/4` (docs/math/quadrics.md, conventions); it is what the curve and patch images
//! use (docs/math/quadrics.md, "Curves and patches under δ"). Composition with projective maps stays quadratic:
//! `(A∘F)_k = Σ_l A_kl F_l` and `(F∘B)_k = pᵀ (Bᵀ M_k B) p`; this is how constructions
//! are transferred between quadrics (docs/math/quadrics.md, "Other quadrics").

// Index loops mirror the matrix formulas (Q_ij, M_k[i][j]) of docs/math/quadrics.md.
#![allow(clippy::needless_range_loop)]

use super::helpers::{self, poly_describe, poly_negligible, poly_var};
use super::{Hom, Mat4, QuadricError};
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};

/// A quadratic map `p ↦ (pᵀ M₀ p, …, pᵀ M₃ p)` of homogeneous coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct QuadraticMap<F> {
    m: [Mat4<F>; 4],
}

impl<F: Scalar> QuadraticMap<F> {
    /// From four symmetric matrices.
    ///
    /// # Errors
    /// [`QuadricError::InvalidArgument`] if a matrix is not symmetric.
    pub fn from_matrices(m: [Mat4<F>; 4]) -> Result<Self, QuadricError> {
        for (k, mk) in m.iter().enumerate() {
            for i in 0..4 {
                for j in i + 1..4 {
                    let d = mk[i][j].clone() - mk[j][i].clone();
                    if !helpers::negligible(&d, helpers::magnitude(&[mk[i][j].clone()])) {
                        return Err(QuadricError::InvalidArgument(format!(
                            "matrix {k} of a quadratic map must be symmetric (entry ({i},{j}))"
                        )));
                    }
                }
            }
        }
        Ok(QuadraticMap { m })
    }

    /// The quadratic map that agrees with `f`, recovered by polarization:
    /// `M_k[i][i] = f(eᵢ)_k`, `M_k[i][j] = (f(eᵢ+eⱼ) − f(eᵢ) − f(eⱼ))_k / 2`.
    /// (If `f` is not quadratic the result is the quadratic map through these values.)
    pub fn from_fn(f: impl Fn(&Hom<F>) -> Hom<F>) -> Self {
        let e = |i: usize| {
            let mut v = helpers::zero4::<F>();
            v[i] = F::one();
            v
        };
        let fe: Vec<Hom<F>> = (0..4).map(|i| f(&e(i))).collect();
        let half = F::one() / F::from_i64(2);
        let mut m = [
            helpers::identity4::<F>(),
            helpers::identity4(),
            helpers::identity4(),
            helpers::identity4(),
        ];
        for i in 0..4 {
            for j in i..4 {
                let v = if i == j {
                    fe[i].clone()
                } else {
                    let s = f(&helpers::add4(&e(i), &e(j)));
                    [0, 1, 2, 3].map(|k| {
                        (s[k].clone() - fe[i][k].clone() - fe[j][k].clone()) * half.clone()
                    })
                };
                for (k, mk) in m.iter_mut().enumerate() {
                    mk[i][j] = v[k].clone();
                    mk[j][i] = v[k].clone();
                }
            }
        }
        QuadraticMap { m }
    }

    /// The matrices `M_k`.
    pub fn matrices(&self) -> &[Mat4<F>; 4] {
        &self.m
    }

    /// `F(p)`.
    pub fn apply(&self, p: &Hom<F>) -> Hom<F> {
        self.polar(p, p)
    }

    /// The polar form `F̂(a, b)_k = aᵀ M_k b`.
    pub fn polar(&self, a: &Hom<F>, b: &Hom<F>) -> Hom<F> {
        [0, 1, 2, 3].map(|k| helpers::bilinear(&self.m[k], a, b))
    }

    /// The linear map `v ↦ F̂(c, v)` as a matrix (row `k` is `cᵀ M_k`).
    pub fn polar_matrix(&self, c: &Hom<F>) -> Mat4<F> {
        [0, 1, 2, 3].map(|k| {
            let t = helpers::transpose(&self.m[k]);
            helpers::mat_vec(&t, c)
        })
    }

    /// `A∘F`: the projective map `A` applied after `F`.
    pub fn then(&self, a: &Mat4<F>) -> Self {
        let mut out = [
            helpers::identity4::<F>(),
            helpers::identity4(),
            helpers::identity4(),
            helpers::identity4(),
        ];
        for (k, ok) in out.iter_mut().enumerate() {
            for i in 0..4 {
                for j in 0..4 {
                    let mut s = F::zero();
                    for l in 0..4 {
                        s += a[k][l].clone() * self.m[l][i][j].clone();
                    }
                    ok[i][j] = s;
                }
            }
        }
        QuadraticMap { m: out }
    }

    /// `F∘B`: the projective map `B` applied before `F` (`M_k ↦ Bᵀ M_k B`).
    pub fn after(&self, b: &Mat4<F>) -> Self {
        let bt = helpers::transpose(b);
        QuadraticMap {
            m: [0, 1, 2, 3].map(|k| helpers::mat_mul(&bt, &helpers::mat_mul(&self.m[k], b))),
        }
    }

    /// The components as polynomials in `p0..p3`.
    pub(crate) fn components(&self) -> [MPoly<F>; 4] {
        [0, 1, 2, 3].map(|k| {
            let mut f = MPoly::zero(4);
            for i in 0..4 {
                for j in 0..4 {
                    if self.m[k][i][j].is_zero() {
                        continue;
                    }
                    f = &f + &(poly_var(i) * poly_var(j)).scale(&self.m[k][i][j]);
                }
            }
            f
        })
    }

    /// Certifies `F(p)ᵀ Q F(p) ≡ 0` as a polynomial identity in `p0..p3` (quartic): the
    /// map lands on the quadric (Jüttler (5)/(6) with (7)/(8)).
    pub fn certify_on_quadric(&self, q: &Mat4<F>, property: &str) -> Certificate {
        let c = self.components();
        let mut s = MPoly::zero(4);
        for k in 0..4 {
            for l in 0..4 {
                if q[k][l].is_zero() {
                    continue;
                }
                s = &s + &(&c[k] * &c[l]).scale(&q[k][l]);
            }
        }
        decide_poly(
            property,
            &s,
            self.magnitude().powi(2) * helpers::magnitude(&q.concat()),
        )
    }

    /// Certifies `F(p)ᵀ C F(p) ≡ (pᵀ A p)·(pᵀ B p)`: the pullback of the quadric `C` is the
    /// quadric `B` times the factor `A` (docs/math/quadrics.md, "Preimage quadrics": preimages of circles and conics).
    pub fn certify_pullback(
        &self,
        c: &Mat4<F>,
        factor: &Mat4<F>,
        target: &Mat4<F>,
        property: &str,
    ) -> Certificate {
        let comp = self.components();
        let mut s = MPoly::zero(4);
        for k in 0..4 {
            for l in 0..4 {
                if c[k][l].is_zero() {
                    continue;
                }
                s = &s + &(&comp[k] * &comp[l]).scale(&c[k][l]);
            }
        }
        let rhs = quad_poly(factor) * quad_poly(target);
        let d = &s - &rhs;
        let scale = self.magnitude().powi(2) * helpers::magnitude(&c.concat())
            + helpers::magnitude(&factor.concat()) * helpers::magnitude(&target.concat());
        decide_poly(property, &d, scale)
    }

    /// Certifies `self(p) ≡ other(p)` as a polynomial identity (equal matrices).
    pub fn certify_equals(&self, other: &QuadraticMap<F>, property: &str) -> Certificate {
        let a = self.components();
        let b = other.components();
        let diff: Vec<MPoly<F>> = (0..4).map(|k| &a[k] - &b[k]).collect();
        let scale = self.magnitude().max(other.magnitude());
        match diff.iter().position(|d| !poly_negligible(d, scale)) {
            None => Certificate::holds(property, F::EXACT),
            Some(k) => Certificate::fails(
                property,
                format!(
                    "component {k} differs by {}",
                    poly_describe(&diff[k], scale)
                ),
                F::EXACT,
            ),
        }
    }

    /// Certifies `outer(inner(p)) ≡ factor(p) · target(p)` as a quartic identity, where
    /// `factor` is the quadratic form with symmetric matrix `factor` (e.g. Satz 3:
    /// `σ(ϑ(p)) = (p0²+p3²)·δ(p)`, docs/math/quadrics.md, "The map δ onto the sphere").
    pub fn certify_composition(
        outer: &QuadraticMap<F>,
        inner: &QuadraticMap<F>,
        factor: &Mat4<F>,
        target: &QuadraticMap<F>,
        property: &str,
    ) -> Certificate {
        let ci = inner.components();
        let co = outer.m.clone();
        let ct = target.components();
        let f = quad_poly(factor);
        let mut worst: Option<(usize, MPoly<F>)> = None;
        let scale = outer.magnitude() * inner.magnitude().powi(2) + target.magnitude();
        for k in 0..4 {
            let mut lhs = MPoly::zero(4);
            for i in 0..4 {
                for j in 0..4 {
                    if co[k][i][j].is_zero() {
                        continue;
                    }
                    lhs = &lhs + &(&ci[i] * &ci[j]).scale(&co[k][i][j]);
                }
            }
            let d = &lhs - &(&f * &ct[k]);
            if !poly_negligible(&d, scale) && worst.is_none() {
                worst = Some((k, d));
            }
        }
        match worst {
            None => Certificate::holds(property, F::EXACT),
            Some((k, d)) => Certificate::fails(
                property,
                format!("component {k}: residual {}", poly_describe(&d, scale)),
                F::EXACT,
            ),
        }
    }

    /// Certifies `F(A p) ≡ c · F(p)` (invariance under a projective map of the domain,
    /// e.g. the fibre rotation `J` of δ, docs/math/quadrics.md, "The map δ onto the sphere").
    pub fn certify_invariance(&self, a: &Mat4<F>, c: &F, property: &str) -> Certificate {
        let moved = self.after(a);
        let scaled = QuadraticMap {
            m: self
                .m
                .clone()
                .map(|mk| mk.map(|r| r.map(|x| x * c.clone()))),
        };
        moved.certify_equals(&scaled, property)
    }

    /// Certifies `F̂(p, A p) ≡ 0` (the polar form vanishes along the fibre direction `A p`,
    /// e.g. `δ̂(p, Jp) = 0`, so that `δ((aI+bJ)p) = (a²+b²)δ(p)`).
    pub fn certify_polar_vanishes(&self, a: &Mat4<F>, property: &str) -> Certificate {
        // F̂(p, Ap)_k = pᵀ M_k A p = pᵀ sym(M_k A) p
        let half = F::one() / F::from_i64(2);
        let m = self.m.clone().map(|mk| {
            let ma = helpers::mat_mul(&mk, a);
            let mut s = ma.clone();
            for i in 0..4 {
                for j in 0..4 {
                    s[i][j] = (ma[i][j].clone() + ma[j][i].clone()) * half.clone();
                }
            }
            s
        });
        let zero = QuadraticMap {
            m: [0, 1, 2, 3].map(|_| [0, 1, 2, 3].map(|_| helpers::zero4::<F>())),
        };
        QuadraticMap { m }.certify_equals(&zero, property)
    }

    /// The largest matrix entry in magnitude (at least 1), for `f64` tolerances.
    fn magnitude(&self) -> f64 {
        self.m
            .iter()
            .flat_map(|mk| mk.iter().flat_map(|r| r.iter()))
            .map(|x| x.to_f64().abs())
            .fold(1.0, f64::max)
    }
}

/// The quadratic form `pᵀ M p` as a polynomial.
fn quad_poly<F: Scalar>(m: &Mat4<F>) -> MPoly<F> {
    let mut f = MPoly::zero(4);
    for i in 0..4 {
        for j in 0..4 {
            if !m[i][j].is_zero() {
                f = &f + &(poly_var(i) * poly_var(j)).scale(&m[i][j]);
            }
        }
    }
    f
}

fn decide_poly<F: Scalar>(property: &str, s: &MPoly<F>, scale: f64) -> Certificate {
    Certificate::decide(property, poly_negligible(s, scale), F::EXACT, || {
        format!("residual {}", poly_describe(s, scale))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn r(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn polarization_recovers_a_quadratic_map() {
        let f = |p: &Hom<Rational>| {
            [
                p[0].clone() * p[1].clone(),
                p[2].clone() * p[2].clone(),
                p[3].clone() * p[0].clone() - p[1].clone() * p[1].clone(),
                r(3) * p[0].clone() * p[0].clone(),
            ]
        };
        let m = QuadraticMap::from_fn(f);
        let p = [r(2), r(-3), r(5), r(7)];
        assert_eq!(m.apply(&p), f(&p));
        // polar form: (F(a+b) − F(a−b))/4
        let a = [r(1), r(2), r(0), r(-1)];
        let b = [r(3), r(-1), r(2), r(1)];
        let lhs = m.polar(&a, &b);
        let fp = m.apply(&helpers::add4(&a, &b));
        let fm = m.apply(&helpers::sub4(&a, &b));
        for k in 0..4 {
            assert_eq!(lhs[k], (fp[k].clone() - fm[k].clone()) / r(4));
        }
    }

    #[test]
    fn composition_with_projective_maps() {
        let m = QuadraticMap::from_fn(|p: &Hom<Rational>| {
            [
                p[0].clone() * p[0].clone(),
                p[0].clone() * p[1].clone(),
                p[2].clone() * p[3].clone(),
                p[1].clone() * p[3].clone(),
            ]
        });
        let a: Mat4<Rational> =
            helpers::mat4_i([[1, 2, 0, 0], [0, 1, 0, 3], [1, 0, 1, 0], [0, 0, 0, 2]]);
        let p = [r(1), r(-2), r(3), r(4)];
        assert_eq!(m.then(&a).apply(&p), helpers::mat_vec(&a, &m.apply(&p)));
        assert_eq!(m.after(&a).apply(&p), m.apply(&helpers::mat_vec(&a, &p)));
    }
}
