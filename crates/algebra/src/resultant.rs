//! Resultants, discriminants and Sylvester matrices.
//!
//! For `p = pₘ ∏ᵢ (t − αᵢ)` of degree `m` and `q = qₙ ∏ⱼ (t − βⱼ)` of degree `n`
//! (roots in an algebraic closure) the **resultant** is
//!
//! ```text
//! Res(p, q) = pₘⁿ qₙᵐ ∏ᵢⱼ (αᵢ − βⱼ) = pₘⁿ ∏ᵢ q(αᵢ) = (−1)^{mn} qₙᵐ ∏ⱼ p(βⱼ) = det Syl(p, q),
//! ```
//!
//! so `Res(p, q) = 0` iff `p` and `q` have a common root, i.e. iff `gcd(p, q)` is not
//! constant (for `pₘ, qₙ ≠ 0`). Conventions: `Res(p, c) = cᵐ` and `Res(c, q) = cⁿ`
//! for a non-zero constant `c` (so `Res(a, b) = 1` for two non-zero constants, the
//! determinant of the empty Sylvester matrix), and `Res(0, q) = Res(p, 0) = 0`.
//!
//! The **discriminant** of `p` of degree `n ≥ 1` is
//! `disc(p) = (−1)^{n(n−1)/2} Res(p, p′) / pₙ = pₙ^{2n−2} ∏_{i<j} (αᵢ − αⱼ)²`;
//! it vanishes iff `p` has a multiple root (`disc(at² + bt + c) = b² − 4ac`).
//!
//! [`resultant`] runs the subresultant pseudo-remainder sequence (Collins, Brown;
//! H. Cohen, *A Course in Computational Algebraic Number Theory*, Algorithm 3.3.7):
//! every division in it is exact in the coefficient domain, so over ℚ the
//! intermediate coefficients stay of the size of the subresultant minors instead of
//! growing like a plain pseudo-remainder sequence.
//!
//! [`resultant_poly`] eliminates the outer variable of two polynomials whose
//! coefficients are polynomials in `t`: it evaluates the formal Sylvester determinant
//! at enough integer points `t₀, t₁, …` (the degree bound `n·deg_t p + m·deg_t q`
//! plus one) and interpolates exactly.

use crate::error::AlgebraError;
use crate::poly::Poly;
use crate::rational::Rational;
use crate::scalar::{ring_pow, Field, Ring};

/// The Sylvester matrix of `p` (degree `m`) and `q` (degree `n`): the `(m+n)×(m+n)`
/// matrix whose first `n` rows are the shifted coefficient rows `pₘ … p₀` and whose
/// last `m` rows are the shifted rows `qₙ … q₀`; `det Syl(p, q) = Res(p, q)`.
/// Two constants give the empty matrix (determinant 1).
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] if `p` or `q` is the zero polynomial (its degree
/// is undefined; use [`sylvester_matrix_formal`] to fix the degrees).
pub fn sylvester_matrix<R: Ring>(p: &Poly<R>, q: &Poly<R>) -> Result<Vec<Vec<R>>, AlgebraError> {
    let (Some(m), Some(n)) = (p.degree(), q.degree()) else {
        return Err(AlgebraError::InvalidArgument(
            "sylvester_matrix: the zero polynomial has no degree".into(),
        ));
    };
    sylvester_matrix_formal(p, m, q, n)
}

/// The formal Sylvester matrix `Sylₘ,ₙ(p, q)` of `p` and `q` read as polynomials of
/// formal degrees `m ≥ deg p` and `n ≥ deg q` (leading coefficients may be zero).
/// Its determinant is the formal resultant [`resultant_formal`].
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] if `deg p > m` or `deg q > n`.
pub fn sylvester_matrix_formal<R: Ring>(
    p: &Poly<R>,
    m: usize,
    q: &Poly<R>,
    n: usize,
) -> Result<Vec<Vec<R>>, AlgebraError> {
    check_formal(p, m, q, n)?;
    let size = m + n;
    let mut rows = Vec::with_capacity(size);
    for i in 0..n {
        let mut row = vec![R::zero(); size];
        for k in 0..=m {
            row[i + k] = p.coeff(m - k);
        }
        rows.push(row);
    }
    for j in 0..m {
        let mut row = vec![R::zero(); size];
        for k in 0..=n {
            row[j + k] = q.coeff(n - k);
        }
        rows.push(row);
    }
    Ok(rows)
}

fn check_formal<R: Ring>(p: &Poly<R>, m: usize, q: &Poly<R>, n: usize) -> Result<(), AlgebraError> {
    if p.degree().is_some_and(|d| d > m) || q.degree().is_some_and(|d| d > n) {
        return Err(AlgebraError::InvalidArgument(format!(
            "formal degrees ({m}, {n}) are below the degrees ({:?}, {:?})",
            p.degree(),
            q.degree()
        )));
    }
    Ok(())
}

/// The resultant `Res(p, q) = pₘⁿ ∏_{p(α)=0} q(α) = det Syl(p, q)` (see the module
/// documentation for the conventions on zero and constant polynomials).
///
/// Subresultant PRS (Cohen, Algorithm 3.3.7) with `A ← B`,
/// `B ← prem(A, B) / (g·h^δ)`, `g ← lc(A)`, `h ← h^{1−δ} g^δ`, where `δ = deg A − deg B`,
/// and the sign `(−1)^{deg A·deg B}` collected at every step; all divisions are exact.
/// Over `f64` the same recurrence runs in floating point (no accuracy guarantee).
pub fn resultant<F: Field>(p: &Poly<F>, q: &Poly<F>) -> F {
    let (Some(m), Some(n)) = (p.degree(), q.degree()) else {
        return F::zero();
    };
    if n == 0 {
        return ring_pow(&q.leading(), m);
    }
    if m == 0 {
        return ring_pow(&p.leading(), n);
    }
    let mut negate = false;
    let (mut a, mut b) = if m < n {
        negate = m % 2 == 1 && n % 2 == 1;
        (q.clone(), p.clone())
    } else {
        (p.clone(), q.clone())
    };
    let mut g = F::one();
    let mut h = F::one();
    loop {
        crate::budget::checkpoint();
        let (Some(da), Some(db)) = (a.degree(), b.degree()) else {
            return F::zero();
        };
        let delta = da - db;
        if da % 2 == 1 && db % 2 == 1 {
            negate = !negate;
        }
        // prem(A, B) = lc(B)^{δ+1} · (A mod B), exact over a field.
        let r = match a.div_rem(&b) {
            Ok((_, r)) => r.scale(&ring_pow(&b.leading(), delta + 1)),
            Err(_) => return F::zero(),
        };
        let Some(div_inv) = (g.clone() * ring_pow(&h, delta)).inv() else {
            return F::zero();
        };
        a = b;
        b = r.scale(&div_inv);
        g = a.leading();
        // h ← h^{1−δ} g^δ = g^δ / h^{δ−1}
        h = if delta == 0 {
            h
        } else {
            match ring_pow(&h, delta - 1).inv() {
                Some(inv) => ring_pow(&g, delta) * inv,
                None => return F::zero(),
            }
        };
        match b.degree() {
            None => return F::zero(),
            Some(0) => {
                let da = a.degree().unwrap_or(0);
                // h ← lc(B)^{deg A} h^{1 − deg A}
                let Some(inv) = ring_pow(&h, da.saturating_sub(1)).inv() else {
                    return F::zero();
                };
                let res = ring_pow(&b.leading(), da) * inv;
                return if negate { -res } else { res };
            }
            Some(_) => {}
        }
    }
}

/// The formal resultant `Resₘ,ₙ(p, q) = det Sylₘ,ₙ(p, q)` of `p`, `q` read with formal
/// degrees `m ≥ deg p`, `n ≥ deg q`. With `m′ = deg p`, `n′ = deg q`:
/// `Resₘ,ₙ = (−1)^{n(m−m′)} qₙ^{m−m′} Res(p, q)` if `n′ = n`, `= pₘ^{n−n′} Res(p, q)` if
/// `m′ = m`, `= 0` if both degrees drop; `Res₀,ₙ(p₀, q) = p₀ⁿ`, `Resₘ,₀(p, q₀) = q₀ᵐ`.
/// This is the value of a resultant with parametric coefficients at a parameter value
/// where a leading coefficient vanishes.
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] if `deg p > m` or `deg q > n`.
pub fn resultant_formal<F: Field>(
    p: &Poly<F>,
    m: usize,
    q: &Poly<F>,
    n: usize,
) -> Result<F, AlgebraError> {
    check_formal(p, m, q, n)?;
    if n == 0 {
        return Ok(ring_pow(&q.coeff(0), m));
    }
    if m == 0 {
        return Ok(ring_pow(&p.coeff(0), n));
    }
    let (Some(dp), Some(dq)) = (p.degree(), q.degree()) else {
        return Ok(F::zero());
    };
    let res = resultant(p, q);
    Ok(match (dp == m, dq == n) {
        (true, true) => res,
        (false, true) => {
            let k = m - dp;
            let v = ring_pow(&q.leading(), k) * res;
            if (n * k) % 2 == 1 {
                -v
            } else {
                v
            }
        }
        (true, false) => ring_pow(&p.leading(), n - dq) * res,
        (false, false) => F::zero(),
    })
}

/// The discriminant `disc(p) = (−1)^{n(n−1)/2} Res(p, p′) / pₙ` of `p` of degree `n ≥ 1`
/// (`disc(at + b) = 1`, `disc(at² + bt + c) = b² − 4ac`); zero iff `p` has a multiple root.
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] for the zero polynomial and for constants.
pub fn discriminant<F: Field>(p: &Poly<F>) -> Result<F, AlgebraError> {
    let n = match p.degree() {
        Some(n) if n >= 1 => n,
        _ => {
            return Err(AlgebraError::InvalidArgument(
                "discriminant: the polynomial must have degree ≥ 1".into(),
            ))
        }
    };
    let lc_inv = p
        .leading()
        .inv()
        .ok_or_else(|| AlgebraError::DivisionByZero("discriminant: leading coefficient".into()))?;
    let r = resultant(p, &p.derivative()) * lc_inv;
    Ok(if (n * (n - 1) / 2) % 2 == 1 { -r } else { r })
}

/// The resultant with respect to the outer variable `x` of `p = Σᵢ pᵢ(t) xⁱ` and
/// `q = Σⱼ qⱼ(t) xʲ`: the polynomial `R(t) = det Sylₘ,ₙ(p, q)(t)` with `m = deg_x p`,
/// `n = deg_x q`. For every `t₀`, `R(t₀) = 0` iff `p(t₀, x)` and `q(t₀, x)` have a
/// common root `x` or both leading coefficients `pₘ(t₀)`, `qₙ(t₀)` vanish.
///
/// Computed by evaluation at the integers `0, 1, −1, 2, −2, …` (as many as
/// `n·maxᵢ deg pᵢ + m·maxⱼ deg qⱼ + 1`, the degree bound of the determinant), the
/// formal resultant [`resultant_formal`] at each point, and Newton interpolation,
/// all exact. A zero `p` or `q` gives the zero polynomial; if both have degree 0 in `x`
/// the resultant is the constant 1 (the empty Sylvester determinant).
pub fn resultant_poly(p: &Poly<Poly<Rational>>, q: &Poly<Poly<Rational>>) -> Poly<Rational> {
    let (Some(m), Some(n)) = (p.degree(), q.degree()) else {
        return Poly::zero();
    };
    let inner_deg = |f: &Poly<Poly<Rational>>| {
        f.coeffs()
            .iter()
            .filter_map(|c| c.degree())
            .max()
            .unwrap_or(0)
    };
    let bound = n
        .saturating_mul(inner_deg(p))
        .saturating_add(m.saturating_mul(inner_deg(q)));
    let npts = bound.saturating_add(1);
    let mut xs: Vec<Rational> = Vec::with_capacity(npts);
    let mut ys: Vec<Rational> = Vec::with_capacity(npts);
    for k in 0..npts {
        crate::budget::checkpoint();
        let half = (k as i64 + 1) / 2;
        let t = Rational::from(if k % 2 == 1 { half } else { -half });
        let pt = Poly::new(p.coeffs().iter().map(|c| c.eval(&t)).collect());
        let qt = Poly::new(q.coeffs().iter().map(|c| c.eval(&t)).collect());
        // The formal degrees are the degrees of p and q: no error is possible.
        let v = resultant_formal(&pt, m, &qt, n).unwrap_or_default();
        xs.push(t);
        ys.push(v);
    }
    interpolate(&xs, &ys)
}

/// Newton interpolation through `(xᵢ, yᵢ)` with distinct `xᵢ` (exact).
fn interpolate(xs: &[Rational], ys: &[Rational]) -> Poly<Rational> {
    let npts = xs.len().min(ys.len());
    let mut c: Vec<Rational> = ys[..npts].to_vec();
    for j in 1..npts {
        crate::budget::checkpoint();
        for i in (j..npts).rev() {
            let den = &xs[i] - &xs[i - j];
            let num = &c[i] - &c[i - 1];
            c[i] = num / den;
        }
    }
    let mut acc = Poly::zero();
    for i in (0..npts).rev() {
        let lin = Poly::new(vec![-xs[i].clone(), Rational::from(1)]);
        acc = &(&acc * &lin) + &Poly::constant(c[i].clone());
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::*;

    type P = Poly<Rational>;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    /// Determinant by Gaussian elimination with exact pivots.
    fn det(mut a: Vec<Vec<Rational>>) -> Rational {
        let n = a.len();
        let mut d = q(1);
        for col in 0..n {
            let Some(piv) = (col..n).find(|&r| a[r][col] != q(0)) else {
                return q(0);
            };
            if piv != col {
                a.swap(piv, col);
                d = -d;
            }
            let pv = a[col][col].clone();
            d *= pv.clone();
            let pivot_row = a[col].clone();
            for row in a.iter_mut().skip(col + 1) {
                let f = row[col].clone() / pv.clone();
                for (x, y) in row.iter_mut().zip(&pivot_row).skip(col) {
                    *x -= y.clone() * f.clone();
                }
            }
        }
        d
    }

    #[test]
    fn resultant_of_linear_factors() {
        // p = 2(t−1)(t−2), q = 3(t+1): Res = 2¹·3²·(1+1)(2+1) = 108
        let p = P::from_ints(&[4, -6, 2]);
        let qq = P::from_ints(&[3, 3]);
        assert_eq!(resultant(&p, &qq), q(108));
        // Res(q, p) = (−1)^{2·1} Res(p, q)
        assert_eq!(resultant(&qq, &p), q(108));
        let s = sylvester_matrix(&p, &qq).expect("nonzero");
        assert_eq!(det(s), q(108));
    }

    #[test]
    fn resultant_sign_convention() {
        // p = t − a, q = t − b: Res(p, q) = q(a) = a − b.
        let p = P::from_ints(&[-5, 1]);
        let qq = P::from_ints(&[-2, 1]);
        assert_eq!(resultant(&p, &qq), q(3));
        assert_eq!(resultant(&qq, &p), q(-3));
        // degrees 3 and 1 (odd·odd): Res(q, p) = −Res(p, q)
        let p3 = P::from_ints(&[1, 0, 2, 1]);
        assert_eq!(resultant(&p3, &qq), -resultant(&qq, &p3));
        // Res(t − b, p) = p(b), Res(p, t − b) = (−1)^{deg p} p(b)
        assert_eq!(resultant(&qq, &p3), p3.eval(&q(2)));
        assert_eq!(resultant(&p3, &qq), -p3.eval(&q(2)));
    }

    #[test]
    fn resultant_special_cases() {
        let p = P::from_ints(&[1, 2, 3]);
        assert_eq!(resultant(&p, &P::zero()), q(0));
        assert_eq!(resultant(&P::zero(), &P::zero()), q(0));
        assert_eq!(resultant(&p, &P::constant(q(2))), q(4));
        assert_eq!(resultant(&P::constant(q(2)), &p), q(4));
        assert_eq!(resultant(&P::constant(q(2)), &P::constant(q(7))), q(1));
        // common factor
        let a = &P::from_ints(&[-1, 1]) * &P::from_ints(&[1, 0, 1]);
        let b = &P::from_ints(&[-1, 1]) * &P::from_ints(&[5, 1]);
        assert_eq!(resultant(&a, &b), q(0));
        assert!(sylvester_matrix(&P::zero(), &p).is_err());
        assert_eq!(
            sylvester_matrix(&P::constant(q(1)), &P::constant(q(2)))
                .expect("constants")
                .len(),
            0
        );
    }

    #[test]
    fn resultant_matches_sylvester_determinant() {
        let cases = [
            (vec![1, -3, 0, 2, 5], vec![-2, 0, 7]),
            (vec![3, 1, 4, 1, 5, 9], vec![2, 6, 5, 3]),
            (vec![0, 0, 1], vec![0, 1, 1, 1, 1]),
            (vec![7, 0, 0, 0, 0, 0, 1], vec![1, 1]),
            (vec![1, 2, 3, 4], vec![4, 3, 2, 1]),
        ];
        for (a, b) in cases {
            let p = P::from_ints(&a);
            let r = P::from_ints(&b);
            let s = det(sylvester_matrix(&p, &r).expect("nonzero"));
            assert_eq!(resultant(&p, &r), s, "{a:?} {b:?}");
            let s2 = det(sylvester_matrix(&r, &p).expect("nonzero"));
            assert_eq!(resultant(&r, &p), s2, "{b:?} {a:?}");
        }
    }

    #[test]
    fn formal_resultant_matches_formal_sylvester() {
        let polys = [
            P::from_ints(&[1, -3, 2]),
            P::from_ints(&[4]),
            P::from_ints(&[0, 1]),
            P::zero(),
            P::from_ints(&[2, 0, 0, 1]),
        ];
        for p in &polys {
            for r in &polys {
                for m in p.degree().unwrap_or(0)..=4 {
                    for n in r.degree().unwrap_or(0)..=3 {
                        let s = det(sylvester_matrix_formal(p, m, r, n).expect("formal"));
                        let f = resultant_formal(p, m, r, n).expect("formal");
                        assert_eq!(f, s, "{p:?} {m} {r:?} {n}");
                    }
                }
            }
        }
        assert!(resultant_formal(&polys[0], 1, &polys[1], 0).is_err());
    }

    #[test]
    fn discriminants() {
        // b² − 4ac
        let p = P::from_ints(&[3, 5, 2]);
        assert_eq!(discriminant(&p).expect("deg 2"), q(25 - 24));
        // cubic t³ + a t + b: −4a³ − 27b²
        let c = P::from_ints(&[2, -3, 0, 1]);
        assert_eq!(discriminant(&c).expect("deg 3"), q(-4 * -27 - 27 * 4));
        assert_eq!(discriminant(&P::from_ints(&[5, 2])).expect("deg 1"), q(1));
        assert!(discriminant(&P::constant(q(3))).is_err());
        assert!(discriminant(&P::zero()).is_err());
        // double root
        let d = &P::from_ints(&[-1, 1]).pow(2) * &P::from_ints(&[3, 1]);
        assert_eq!(discriminant(&d).expect("deg 3"), q(0));
        // f64 works too
        let pf = Poly::<f64>::new(vec![3.0, 5.0, 2.0]);
        assert!((discriminant(&pf).expect("deg 2") - 1.0).abs() < 1e-12);
    }

    #[test]
    fn resultant_poly_eliminates_outer_variable() {
        // p = x² + t² − 1 (circle), q = x − t: Res_x = 2t² − 1
        let p: Poly<P> = Poly::new(vec![
            P::from_ints(&[-1, 0, 1]),
            P::zero(),
            P::from_ints(&[1]),
        ]);
        let r: Poly<P> = Poly::new(vec![P::from_ints(&[0, -1]), P::from_ints(&[1])]);
        assert_eq!(resultant_poly(&p, &r), P::from_ints(&[-1, 0, 2]));
        // leading coefficient depending on t: p = t·x − 1, q = x² − 2 → Res = 1 − 2t²
        let p2: Poly<P> = Poly::new(vec![P::from_ints(&[-1]), P::from_ints(&[0, 1])]);
        let q2: Poly<P> = Poly::new(vec![P::from_ints(&[-2]), P::zero(), P::from_ints(&[1])]);
        let res = resultant_poly(&p2, &q2);
        for k in -3..=3 {
            let t = q(k);
            let pt = Poly::new(p2.coeffs().iter().map(|c| c.eval(&t)).collect());
            let qt = Poly::new(q2.coeffs().iter().map(|c| c.eval(&t)).collect());
            let s = det(sylvester_matrix_formal(&pt, 1, &qt, 2).expect("formal"));
            assert_eq!(res.eval(&t), s);
        }
        assert_eq!(res, P::from_ints(&[1, 0, -2]));
        assert!(resultant_poly(&p, &Poly::zero()).is_zero());
    }
}
