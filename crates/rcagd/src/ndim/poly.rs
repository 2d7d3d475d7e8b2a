//! Polynomial linear algebra over `F[x₀, …]` for the n-dimensional constructions:
//! determinants, the generalized cross product (signed maximal minors), rank over the
//! fraction field (fraction-free Gaussian elimination), dot products and substitution.

use crate::pn::poly::div_exact;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::Scalar;

/// `Σ aᵢ bᵢ`.
pub(crate) fn dot<F: Scalar>(a: &[MPoly<F>], b: &[MPoly<F>]) -> MPoly<F> {
    a.iter()
        .zip(b)
        .fold(MPoly::zero(0), |acc, (x, y)| &acc + &(x * y))
}

/// The determinant of a square matrix of polynomials (Laplace expansion along the first
/// row; the matrices here have at most seven rows).
pub(crate) fn det<F: Scalar>(m: &[Vec<MPoly<F>>]) -> MPoly<F> {
    let cols: Vec<usize> = (0..m.len()).collect();
    det_cols(m, 0, &cols)
}

fn det_cols<F: Scalar>(m: &[Vec<MPoly<F>>], row: usize, cols: &[usize]) -> MPoly<F> {
    if cols.is_empty() {
        return MPoly::constant(0, F::one());
    }
    if cols.len() == 1 {
        return m[row][cols[0]].clone();
    }
    let mut acc = MPoly::zero(0);
    for (k, &c) in cols.iter().enumerate() {
        if m[row][c].is_zero() {
            continue;
        }
        let rest: Vec<usize> = cols.iter().copied().filter(|&x| x != c).collect();
        let minor = &m[row][c] * &det_cols(m, row + 1, &rest);
        acc = if k % 2 == 0 {
            &acc + &minor
        } else {
            &acc - &minor
        };
    }
    acc
}

/// The generalized cross product of `r` rows of length `r + 1`: the vector `X` with
/// `Xᵢ = (−1)ⁱ det(rows without column i)`, orthogonal to every row (`row·X` is the
/// determinant of a matrix with a repeated row).
pub(crate) fn cross<F: Scalar>(rows: &[Vec<MPoly<F>>]) -> Vec<MPoly<F>> {
    let n = rows.len() + 1;
    (0..n)
        .map(|i| {
            let cols: Vec<usize> = (0..n).filter(|&c| c != i).collect();
            let d = det_cols(rows, 0, &cols);
            if i % 2 == 0 {
                d
            } else {
                -d
            }
        })
        .collect()
}

/// The rank over the fraction field of the vectors `rows` (fraction-free elimination,
/// exact divisions by the previous pivot; for `f64` a coefficient below `10⁻⁹` of the
/// largest counts as zero).
pub(crate) fn rank<F: Scalar>(rows: &[Vec<MPoly<F>>]) -> usize {
    let mut m: Vec<Vec<MPoly<F>>> = rows.iter().map(|r| r.iter().map(clean).collect()).collect();
    let ncols = m.first().map_or(0, Vec::len);
    let mut prev = MPoly::constant(0, F::one());
    let mut r = 0;
    for c in 0..ncols {
        let Some(p) = (r..m.len()).find(|&i| !m[i][c].is_zero()) else {
            continue;
        };
        m.swap(r, p);
        for i in r + 1..m.len() {
            for j in c + 1..ncols {
                let num = &(&m[r][c] * &m[i][j]) - &(&m[i][c] * &m[r][j]);
                m[i][j] = clean(&div_exact(&num, &prev).unwrap_or(num));
            }
            m[i][c] = MPoly::zero(0);
        }
        prev = m[r][c].clone();
        r += 1;
        if r == m.len() {
            break;
        }
    }
    r
}

/// Drops `f64` coefficients below `10⁻⁹` of the largest (a no-op for exact scalars).
pub(crate) fn clean<F: Scalar>(p: &MPoly<F>) -> MPoly<F> {
    if F::EXACT {
        return p.clone();
    }
    let big = p.terms().map(|(_, c)| c.to_f64().abs()).fold(0.0, f64::max);
    let terms: Vec<(Vec<u32>, F)> = p
        .terms()
        .filter(|(_, c)| c.to_f64().abs() > 1e-9 * big)
        .map(|(e, c)| (e.to_vec(), c.clone()))
        .collect();
    MPoly::from_terms(p.nvars(), terms).unwrap_or_else(|_| p.clone())
}

/// `p` with the variables relabelled: variable `i` of `p` becomes `map[i]` (`None`: `p`
/// must not contain it) among `nvars` variables.
pub(crate) fn relabel<F: Scalar>(p: &MPoly<F>, map: &[usize], nvars: usize) -> MPoly<F> {
    let terms: Vec<(Vec<u32>, F)> = p
        .terms()
        .map(|(e, c)| {
            let mut f = vec![0u32; nvars];
            for (i, &k) in e.iter().enumerate() {
                if k > 0 {
                    f[map[i]] += k;
                }
            }
            (f, c.clone())
        })
        .collect();
    terms.into_iter().fold(MPoly::zero(nvars), |acc, (e, c)| {
        &acc + &MPoly::monomial(nvars, &e, c)
    })
}

/// Substitutes polynomials for the variables: `p(q₀, q₁, …)` (variables of `p` beyond
/// `qs` are kept).
pub(crate) fn compose<F: Scalar>(p: &MPoly<F>, qs: &[MPoly<F>]) -> MPoly<F> {
    let mut acc = MPoly::zero(0);
    for (e, c) in p.terms() {
        let mut t = MPoly::constant(0, c.clone());
        for (i, &k) in e.iter().enumerate() {
            if k == 0 {
                continue;
            }
            let base = match qs.get(i) {
                Some(q) => q.clone(),
                None => MPoly::var(e.len(), i),
            };
            t = &t * &base.pow(k);
        }
        acc = &acc + &t;
    }
    acc
}

/// The largest absolute coefficient (at least 1), for `f64` tolerances.
pub(crate) fn mag<F: Scalar>(p: &MPoly<F>) -> f64 {
    p.terms().map(|(_, c)| c.to_f64().abs()).fold(1.0, f64::max)
}

/// A bound for the coefficients of `a·b` without cancellation (for `f64` tolerances).
pub(crate) fn dot_scale<F: Scalar>(a: &[MPoly<F>], b: &[MPoly<F>]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| mag(x) * mag(y) * (x.num_terms().max(1) * y.num_terms().max(1)) as f64)
        .sum::<f64>()
        .max(1.0)
}

/// `true` if `p` involves only variable 0.
pub(crate) fn only_var0<F: Scalar>(p: &MPoly<F>) -> bool {
    p.terms().all(|(e, _)| e.iter().skip(1).all(|&k| k == 0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn x(i: usize) -> MPoly<Rational> {
        MPoly::var(3, i)
    }
    fn c(k: i64) -> MPoly<Rational> {
        MPoly::constant(3, Rational::from(k))
    }

    #[test]
    fn determinant_cross_and_rank() {
        let m = vec![vec![x(0), c(1)], vec![c(2), x(1)]];
        assert_eq!(det(&m), &(&x(0) * &x(1)) - &c(2));
        let rows = vec![vec![c(1), c(0), x(0)], vec![c(0), c(1), x(1)]];
        let z = cross(&rows);
        for r in &rows {
            assert!(dot(r, &z).is_zero());
        }
        assert_eq!(rank(&rows), 2);
        let dep = vec![rows[0].clone(), rows[0].iter().map(|p| p * &x(2)).collect()];
        assert_eq!(rank(&dep), 1);
        let p = &x(0) * &x(1);
        assert_eq!(relabel(&p, &[2, 0], 3), &x(2) * &x(0));
        assert_eq!(
            compose(&p, &[c(2), &x(0) + &c(1)]),
            (&x(0) + &c(1)).scale(&Rational::from(2))
        );
    }
}
