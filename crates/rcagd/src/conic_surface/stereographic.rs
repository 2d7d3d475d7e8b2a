//! Stereographic parametrizations of conics and quadrics from one of their points
//! (M. Peternell, "Rational Parametrizations for Envelopes of Quadric Families", §1.4).
//!
//! * **Conic from a point** (1.28)/(1.29): for the conic `xᵀAx = 0` and a point `f` on it,
//!   the line through `f` and `q(u) = a + u·b` meets the conic again in
//!   `y(u) = (qᵀAq)·f − 2(fᵀAq)·q(u)` (the factor `λ` of `λf + μq` is `qᵀAq`, `μ = −2fᵀAq`,
//!   because `fᵀAf = 0`). For the diagonal conic `c₀x₀² + c₁x₁² + c₂x₂² = 0` and
//!   `q(u) = (0, 1, u)` this is `λ₀ = c₁ + c₂u²`, `μ₀ = −2(c₁f₁ + c₂f₂u)` (1.29). Degree 2
//!   in `u`; every point except `f` once (`f` itself at `u = ∞` or where the line is tangent).
//! * **Dual** (1.33)/(1.34): the same formula with line coordinates: for a line conic
//!   `XᵀAX = 0` (its tangent lines) and one tangent line `y`, the second tangent through
//!   the point `y ∩ g(u)` is `(gᵀAg)·y − 2(yᵀAg)·g(u)`.
//! * **n-dimensional quadric** (1.30)–(1.32): `x₀² + … + x_p² − x_{p+1}² − … − x_r² = 0`
//!   from the north pole `(1, 0, …, 0, 1)`, written in the index convention of (1.32):
//!   `x = (S(u) − 1, −2u₁, …, −2u_{r−1}, S(u) + 1)` with `S = u₁² + … + u_p² − u_{p+1}² − …`;
//!   indeed `(S − 1)² − (S + 1)² = −4S` cancels `4(u₁² + … + u_p² − u_{p+1}² − …)`.

use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Poly, Ring, Scalar};

/// The second intersection `y = (qᵀAq)·f − 2(fᵀAq)·q` of the line `f ∨ q` with the conic
/// `xᵀAx = 0` through `f` (module docs). Works for points and, dually, for lines.
pub fn second_intersection<R: Ring>(a: &[[R; 3]; 3], f: &[R; 3], q: &[R; 3]) -> [R; 3] {
    let form = |x: &[R; 3], y: &[R; 3]| {
        let mut s = R::zero();
        for i in 0..3 {
            for j in 0..3 {
                s += x[i].clone() * a[i][j].clone() * y[j].clone();
            }
        }
        s
    };
    let qaq = form(q, q);
    let faq = form(f, q);
    let two = R::one() + R::one();
    core::array::from_fn(|i| qaq.clone() * f[i].clone() - two.clone() * faq.clone() * q[i].clone())
}

/// (1.29): the diagonal conic `c₀x₀² + c₁x₁² + c₂x₂² = 0` parametrized from its point `f`
/// with `q(u) = (0, 1, u)`: `y(u) = (c₁ + c₂u²)·f − 2(c₁f₁ + c₂f₂u)·q(u)`, polynomials in `u`.
pub fn conic_from_point<F: Scalar>(c: &[F; 3], f: &[F; 3]) -> [Poly<F>; 3] {
    let lam = Poly::new(vec![c[1].clone(), F::zero(), c[2].clone()]);
    let two = F::from_i64(2);
    let mu = Poly::new(vec![
        -(two.clone() * c[1].clone() * f[1].clone()),
        -(two * c[2].clone() * f[2].clone()),
    ]);
    let q = [
        Poly::zero(),
        Poly::constant(F::one()),
        Poly::new(vec![F::zero(), F::one()]),
    ];
    core::array::from_fn(|i| &lam.scale(&f[i]) + &(&mu * &q[i]))
}

/// (1.32): the stereographic parametrization of the regular quadric of `Pʳ` in the
/// variables `u₁ … u_{r−1}` (an `MPoly` in `r − 1` variables), `p` = the number of positive
/// squares among `u`: `(S − 1, −2u₁, …, −2u_{r−1}, S + 1)`,
/// `S = u₁² + … + u_p² − u_{p+1}² − … − u_{r−1}²`. Returns the point and the diagonal
/// `(δ₀, …, δ_r)` of the quadric (1.30) `Σ δᵢxᵢ² = 0` it lies on: `δᵢ = +1` for `i ≤ p`,
/// `−1` for `i > p`.
pub fn quadric_from_pole<F: Scalar>(r: usize, p: usize) -> (Vec<MPoly<F>>, Vec<F>) {
    let nv = r.saturating_sub(1);
    let one = MPoly::constant(nv, F::one());
    let mut s = MPoly::zero(nv);
    for i in 0..nv {
        let ui = MPoly::var(nv, i);
        let sq = &ui * &ui;
        s = if i < p { &s + &sq } else { &s - &sq };
    }
    let mut x = vec![&s - &one];
    for i in 0..nv {
        x.push(MPoly::var(nv, i).scale(&F::from_i64(-2)));
    }
    x.push(&s + &one);
    let delta = (0..=r)
        .map(|i| if i <= p { F::one() } else { -F::one() })
        .collect();
    (x, delta)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    #[test]
    fn conic_1_29_and_dual() {
        // x₀² + x₁² − x₂² = 0 from f = (1, 0, 1)... in the diagonal form c = (1, 1, −1)
        let c = [Rational::from(1), Rational::from(1), Rational::from(-1)];
        let f = [Rational::from(0), Rational::from(1), Rational::from(1)];
        let y = conic_from_point(&c, &f);
        let s = (0..3).fold(Poly::zero(), |acc, i| &acc + &(&y[i] * &y[i]).scale(&c[i]));
        assert!(s.is_zero());
        assert_eq!(y.iter().filter_map(|p| p.degree()).max(), Some(2));
        // the general formula on numbers
        let a = [
            [c[0].clone(), Rational::ZERO, Rational::ZERO],
            [Rational::ZERO, c[1].clone(), Rational::ZERO],
            [Rational::ZERO, Rational::ZERO, c[2].clone()],
        ];
        let q = [Rational::from(1), Rational::from(2), Rational::from(5)];
        let z = second_intersection(&a, &f, &q);
        let v = (0..3).fold(Rational::ZERO, |acc, i| {
            acc + c[i].clone() * z[i].clone() * z[i].clone()
        });
        assert!(v.is_zero());
    }

    #[test]
    fn quadric_1_32() {
        for (r, p) in [(3usize, 2usize), (4, 3), (4, 1), (5, 2)] {
            let (x, d) = quadric_from_pole::<Rational>(r, p);
            assert_eq!(x.len(), r + 1);
            let nv = r - 1;
            let s = x
                .iter()
                .zip(&d)
                .fold(MPoly::zero(nv), |acc, (xi, di)| &acc + &(xi * xi).scale(di));
            assert!(s.is_zero(), "r = {r}, p = {p}");
        }
    }
}
