//! Drawable pieces of the Laguerre models' objects: a square of an oriented plane and an
//! isotropic sphere over a square (docs/math/laguerre-pn.md, "Isotropic model (Theorem 4.3, (3.11)–(3.15))").
//!
//! * The square `[−1, 1]²` of the plane `e0 + n·x = 0` around its foot point `f = −e0·n`,
//!   spanned by `u = n × e_k` and `v = n × u` (`e_k` the unit vector of the smallest
//!   `|n_k|`, so that `u ≠ 0`): the bilinear patch with corners `f ± u ± v`.
//! * The isotropic sphere `y₃ = α(y₁² + y₂²) + β·y + γ` (Pottmann–Peternell, *Applications
//!   of Laguerre geometry in CAGD*, §3, the isotropic model) over `[−1, 1]²` as a polynomial
//!   patch of bidegree `(2, 2)`: the degree-2 Bernstein coefficients on `[−1, 1]` of `y` are
//!   `(−1, 0, 1)` and of `y²` are `(1, −1, 1)` (Farin, *Curves and Surfaces for CAGD*,
//!   §5.1, the Bernstein form of a power), so those of `y₃` follow by linearity.

use super::models::{IsotropicSphere, OrientedPlane};
use rcagd_algebra::Scalar;
use rcagd_geom::{BezierPatch, GeomError};

impl<F: Scalar> OrientedPlane<F> {
    /// The square `[−1, 1]²` of the plane around its foot point (module docs).
    ///
    /// # Errors
    /// [`GeomError`] if the patch cannot be formed (never for a unit normal).
    pub fn square_patch(&self) -> Result<BezierPatch<F>, GeomError> {
        let n = &self.n;
        let mut k = 0;
        for i in 1..3 {
            if n[i].abs() < n[k].abs() {
                k = i;
            }
        }
        let mut ek = [F::zero(), F::zero(), F::zero()];
        ek[k] = F::one();
        let cross = |a: &[F; 3], b: &[F; 3]| -> [F; 3] {
            [
                a[1].clone() * b[2].clone() - a[2].clone() * b[1].clone(),
                a[2].clone() * b[0].clone() - a[0].clone() * b[2].clone(),
                a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone(),
            ]
        };
        let u = cross(n, &ek);
        let v = cross(n, &u);
        let f: [F; 3] = core::array::from_fn(|i| -self.e0.clone() * n[i].clone());
        let pt = |a: i64, b: i64| -> Vec<F> {
            let mut p = vec![F::one()];
            p.extend((0..3).map(|i| {
                f[i].clone() + F::from_i64(a) * u[i].clone() + F::from_i64(b) * v[i].clone()
            }));
            p
        };
        BezierPatch::from_homogeneous(vec![vec![pt(-1, -1), pt(-1, 1)], vec![pt(1, -1), pt(1, 1)]])
    }
}

impl<F: Scalar> IsotropicSphere<F> {
    /// The sphere over `[−1, 1]²` as a polynomial patch of bidegree `(2, 2)` (module docs).
    ///
    /// # Errors
    /// [`GeomError`] if the patch cannot be formed (never).
    pub fn square_patch(&self) -> Result<BezierPatch<F>, GeomError> {
        let lin = [F::from_i64(-1), F::zero(), F::one()];
        let sq = [F::one(), F::from_i64(-1), F::one()];
        let mut net = Vec::with_capacity(3);
        for i in 0..3 {
            let mut row = Vec::with_capacity(3);
            for j in 0..3 {
                let z = self.alpha.clone() * (sq[i].clone() + sq[j].clone())
                    + self.beta[0].clone() * lin[i].clone()
                    + self.beta[1].clone() * lin[j].clone()
                    + self.gamma.clone();
                row.push(vec![F::one(), lin[i].clone(), lin[j].clone(), z]);
            }
            net.push(row);
        }
        BezierPatch::from_homogeneous(net)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn isotropic_patch_is_the_graph() {
        let s = IsotropicSphere {
            alpha: q(2),
            beta: [q(1), q(-3)],
            gamma: q(5),
        };
        let p = s.square_patch().unwrap();
        let h = Rational::from(1) / Rational::from(3);
        for (a, b) in [(q(0), q(0)), (h.clone(), q(1)), (q(1), h)] {
            let x = p.eval(&a, &b).unwrap();
            // parameter (a, b) ∈ [0, 1]² ↦ y = (2a − 1, 2b − 1)
            let (y1, y2) = (q(2) * a - q(1), q(2) * b - q(1));
            let z = q(2) * (y1.clone() * y1.clone() + y2.clone() * y2.clone()) + y1.clone()
                - q(3) * y2.clone()
                + q(5);
            assert_eq!(x, vec![y1, y2, z]);
        }
    }

    #[test]
    fn plane_square_lies_in_the_plane() {
        let e = OrientedPlane {
            e0: q(-2),
            n: [q(0), q(0), q(1)],
        };
        let p = e.square_patch().unwrap();
        let x = p.eval(&q(0), &q(1)).unwrap();
        assert_eq!(x[2], q(2));
    }
}
