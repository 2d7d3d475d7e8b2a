//! Small private helpers of the quadric module: formatting, `f64` tolerances, Bernstein
//! bases, 4×4 and general exact linear algebra, and homogeneous polynomials in four
//! variables (for the identity certificates of the maps themselves).
//!
//! What the algebra and geometry crates provide is used from there: number formatting
//! (`rcagd_geom::certify::format_scalar`), binomials and the Bernstein basis
//! (`rcagd_algebra::bernstein`), evaluation (`BezierCurve`/`BezierPatch`), exact
//! elimination, kernels, determinants and inverses (`rcagd_algebra::linalg::Matrix`) and
//! polynomials in `p0..p3` (`rcagd_algebra::mpoly::MPoly`). What stays here is
//! quadric-specific: fixed-size 4-vector/4×4 arithmetic, the `f64` tolerance policy of
//! this module, and elimination with that tolerance for `f64` (linalg's generic
//! elimination tests pivots for exact zero, and its `f64` kernel is an SVD with an
//! orthonormal basis, not the free-variable basis the interpolation code uses).

// Index loops mirror the matrix formulas (Q_ij, M_k[i][j]) of docs/math/quadrics.md.
#![allow(clippy::needless_range_loop)]

use super::Hom;
use rcagd_algebra::linalg::Matrix;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::Scalar;
use rcagd_geom::{BezierCurve, BezierPatch};

pub(crate) use rcagd_algebra::bernstein::{basis as bernstein, binomial as binom};
pub(crate) use rcagd_geom::certify::format_scalar as fmt_scalar;

/// `x == 0` exactly for exact scalars; `|x| ≤ TOL · max(scale, 1)` for `f64` (the
/// relative tolerance `1e-9` of `rcagd_geom::certify`).
pub(crate) use crate::certs::is_negligible as negligible;

/// A vector as text `(a, b, …)`.
pub(crate) fn fmt_vec<F: Scalar>(v: &[F]) -> String {
    let parts: Vec<String> = v.iter().map(fmt_scalar).collect();
    format!("({})", parts.join(", "))
}

/// Largest absolute value (as `f64`) of a slice, at least 1.
pub(crate) fn magnitude<F: Scalar>(v: &[F]) -> f64 {
    v.iter().map(|x| x.to_f64().abs()).fold(1.0, f64::max)
}

/// All entries negligible relative to `scale`.
pub(crate) fn all_negligible<F: Scalar>(v: &[F], scale: f64) -> bool {
    v.iter().all(|x| negligible(x, scale))
}

/// `true` if every entry is finite (always for exact scalars).
pub(crate) fn all_finite<F: Scalar>(v: &[F]) -> bool {
    F::EXACT || v.iter().all(|x| x.to_f64().is_finite())
}

/// Derivatives of the Bernstein basis: `Bⱼⁿ'(t) = n (Bⱼ₋₁ⁿ⁻¹(t) − Bⱼⁿ⁻¹(t))`.
pub(crate) fn bernstein_derivative<F: Scalar>(n: usize, t: &F) -> Vec<F> {
    if n == 0 {
        return vec![F::zero()];
    }
    let b = bernstein::<F>(n - 1, t);
    let nn = F::from_i64(n as i64);
    (0..=n)
        .map(|j| {
            let left = if j >= 1 { b[j - 1].clone() } else { F::zero() };
            let right = if j < n { b[j].clone() } else { F::zero() };
            nn.clone() * (left - right)
        })
        .collect()
}

/// `N + 1` distinct parameters `0, 1/N, …, 1` (`N ≥ 1`).
pub(crate) fn nodes<F: Scalar>(n: usize) -> Vec<F> {
    let n = n.max(1);
    (0..=n)
        .map(|k| F::from_i64(k as i64) / F::from_i64(n as i64))
        .collect()
}

/// Copies a slice of length 4 into a `[F; 4]` (missing entries are zero).
pub(crate) fn to_hom<F: Scalar>(p: &[F]) -> Hom<F> {
    let g = |i: usize| p.get(i).cloned().unwrap_or_else(F::zero);
    [g(0), g(1), g(2), g(3)]
}

/// `Σ cⱼ Pⱼ` for 4-vectors `Pⱼ`.
fn combine<'a, F: Scalar + 'a>(c: &[F], pts: impl Iterator<Item = &'a [F]>) -> Hom<F> {
    let mut out = zero4::<F>();
    for (cj, p) in c.iter().zip(pts) {
        for (o, x) in out.iter_mut().zip(p) {
            *o += cj.clone() * x.clone();
        }
    }
    out
}

/// The homogeneous point of a curve at `t`: the Bernstein sum with the basis values of
/// `rcagd_algebra::bernstein::basis` (for exact scalars about 5× cheaper than de
/// Casteljau's `BezierCurve::eval_homogeneous` at degree 6, which matters for the
/// certificates that evaluate on `(2n+1)²` nodes).
pub(crate) fn eval_curve<F: Scalar>(curve: &BezierCurve<F>, t: &F) -> Hom<F> {
    combine(&bernstein(curve.degree(), t), curve.control_points())
}

/// The homogeneous derivative of a curve at `t`.
pub(crate) fn eval_curve_derivative<F: Scalar>(curve: &BezierCurve<F>, t: &F) -> Hom<F> {
    combine(
        &bernstein_derivative(curve.degree(), t),
        curve.control_points(),
    )
}

/// The homogeneous point of a patch at `(u, v)` (Bernstein sums, as [`eval_curve`]).
pub(crate) fn eval_patch<F: Scalar>(patch: &BezierPatch<F>, u: &F, v: &F) -> Hom<F> {
    let (m, n) = patch.degree();
    let bu = bernstein::<F>(m, u);
    let bv = bernstein::<F>(n, v);
    let weights: Vec<F> = bu
        .iter()
        .flat_map(|bi| bv.iter().map(move |bj| bi.clone() * bj.clone()))
        .collect();
    let pts = (0..=m).flat_map(|i| (0..=n).map(move |j| (i, j)));
    combine(&weights, pts.map(|(i, j)| patch.control_point(i, j)))
}

/// `[0, 0, 0, 0]`.
pub(crate) fn zero4<F: Scalar>() -> Hom<F> {
    [F::zero(), F::zero(), F::zero(), F::zero()]
}

/// The 4×4 identity.
pub(crate) fn identity4<F: Scalar>() -> [[F; 4]; 4] {
    let mut m = [zero4::<F>(), zero4(), zero4(), zero4()];
    for (i, row) in m.iter_mut().enumerate() {
        row[i] = F::one();
    }
    m
}

/// A 4×4 matrix from integers.
pub(crate) fn mat4_i<F: Scalar>(m: [[i64; 4]; 4]) -> [[F; 4]; 4] {
    m.map(|r| r.map(F::from_i64))
}

/// `A x`.
pub(crate) fn mat_vec<F: Scalar>(a: &[[F; 4]; 4], x: &Hom<F>) -> Hom<F> {
    let row = |r: &[F; 4]| dot(r, x);
    [row(&a[0]), row(&a[1]), row(&a[2]), row(&a[3])]
}

/// `A B`.
pub(crate) fn mat_mul<F: Scalar>(a: &[[F; 4]; 4], b: &[[F; 4]; 4]) -> [[F; 4]; 4] {
    let mut out = [zero4::<F>(), zero4(), zero4(), zero4()];
    for i in 0..4 {
        for j in 0..4 {
            let mut s = F::zero();
            for k in 0..4 {
                s += a[i][k].clone() * b[k][j].clone();
            }
            out[i][j] = s;
        }
    }
    out
}

/// `Aᵀ`.
pub(crate) fn transpose<F: Scalar>(a: &[[F; 4]; 4]) -> [[F; 4]; 4] {
    let mut out = [zero4::<F>(), zero4(), zero4(), zero4()];
    for i in 0..4 {
        for j in 0..4 {
            out[i][j] = a[j][i].clone();
        }
    }
    out
}

/// `Σ aᵢ bᵢ`.
pub(crate) fn dot<F: Scalar>(a: &[F], b: &[F]) -> F {
    a.iter()
        .zip(b)
        .fold(F::zero(), |s, (x, y)| s + x.clone() * y.clone())
}

/// `xᵀ Q y`.
pub(crate) fn bilinear<F: Scalar>(q: &[[F; 4]; 4], x: &Hom<F>, y: &Hom<F>) -> F {
    dot(x, &mat_vec(q, y))
}

/// `xᵀ Q x` and the magnitude `Σ |qᵢⱼ xᵢ xⱼ|` (for the `f64` tolerance).
pub(crate) fn quad_form<F: Scalar>(q: &[[F; 4]; 4], x: &[F]) -> (F, f64) {
    let mut s = F::zero();
    let mut mag = 0.0;
    for (i, row) in q.iter().enumerate() {
        for (j, qij) in row.iter().enumerate() {
            if qij.is_zero() {
                continue;
            }
            let term = qij.clone() * x[i].clone() * x[j].clone();
            if !F::EXACT {
                mag += term.to_f64().abs();
            }
            s += term;
        }
    }
    (s, mag)
}

/// `a + b`, `a − b`, `c·a` on 4-vectors.
pub(crate) fn add4<F: Scalar>(a: &Hom<F>, b: &Hom<F>) -> Hom<F> {
    [0, 1, 2, 3].map(|i| a[i].clone() + b[i].clone())
}
pub(crate) fn sub4<F: Scalar>(a: &Hom<F>, b: &Hom<F>) -> Hom<F> {
    [0, 1, 2, 3].map(|i| a[i].clone() - b[i].clone())
}
pub(crate) fn scale4<F: Scalar>(c: &F, a: &Hom<F>) -> Hom<F> {
    [0, 1, 2, 3].map(|i| c.clone() * a[i].clone())
}

/// `true` if the vector is (negligibly close to) zero.
pub(crate) fn is_zero_vec<F: Scalar>(v: &[F]) -> bool {
    if F::EXACT {
        v.iter().all(|x| x.is_zero())
    } else {
        v.iter().all(|x| x.to_f64() == 0.0)
    }
}

/// The rows as a [`Matrix`] with `ncols` columns (short rows padded with zeros).
fn matrix<F: Scalar>(rows: &[Vec<F>], ncols: usize) -> Matrix<F> {
    Matrix::from_fn(rows.len(), ncols, |i, j| {
        rows.get(i)
            .and_then(|r| r.get(j))
            .cloned()
            .unwrap_or_else(F::zero)
    })
}

/// The rank of a list of row vectors (exact: [`Matrix::rank`]; `f64`: elimination with
/// the relative tolerance of this module).
pub(crate) fn rank<F: Scalar>(rows: &[Vec<F>]) -> usize {
    let ncols = rows.iter().map(|r| r.len()).max().unwrap_or(0);
    if F::EXACT {
        return matrix(rows, ncols).rank();
    }
    let (_, pivots) = rref(rows, ncols);
    pivots.len()
}

/// `true` if `a` and `b` are proportional (rank of `[a, b]` ≤ 1).
pub(crate) fn parallel<F: Scalar>(a: &[F], b: &[F]) -> bool {
    if F::EXACT {
        for i in 0..a.len() {
            for j in i + 1..a.len() {
                let m = a[i].clone() * b[j].clone() - a[j].clone() * b[i].clone();
                if !m.is_zero() {
                    return false;
                }
            }
        }
        true
    } else {
        rank(&[a.to_vec(), b.to_vec()]) <= 1
    }
}

/// Reduced row echelon form of the rows (`ncols` columns), `f64` path: partial
/// pivoting, entries below `TOL · max|entry|` are zero; returns the non-zero rows and
/// the pivot columns. Exact scalars use [`Matrix::rref`] (see [`null_space`]).
pub(crate) fn rref<F: Scalar>(rows: &[Vec<F>], ncols: usize) -> (Vec<Vec<F>>, Vec<usize>) {
    let mut a: Vec<Vec<F>> = rows
        .iter()
        .map(|r| {
            let mut r = r.clone();
            r.resize(ncols, F::zero());
            r
        })
        .collect();
    let scale = if F::EXACT {
        1.0
    } else {
        a.iter().map(|r| magnitude(r)).fold(1.0, f64::max)
    };
    let mut pivots = Vec::new();
    let mut row = 0;
    for col in 0..ncols {
        if row >= a.len() {
            break;
        }
        // choose pivot
        let mut best: Option<usize> = None;
        for r in row..a.len() {
            if negligible(&a[r][col], scale) {
                continue;
            }
            if F::EXACT {
                best = Some(r);
                break;
            }
            match best {
                Some(b) if a[b][col].to_f64().abs() >= a[r][col].to_f64().abs() => {}
                _ => best = Some(r),
            }
        }
        let Some(p) = best else {
            for r in a.iter_mut().skip(row) {
                r[col] = F::zero();
            }
            continue;
        };
        a.swap(row, p);
        let piv = a[row][col].clone();
        for x in a[row].iter_mut() {
            *x = x.clone() / piv.clone();
        }
        let prow = a[row].clone();
        for (r, other) in a.iter_mut().enumerate() {
            if r == row || other[col].is_zero() {
                continue;
            }
            let f = other[col].clone();
            for (x, y) in other.iter_mut().zip(&prow) {
                if !y.is_zero() {
                    *x = x.clone() - f.clone() * y.clone();
                }
            }
            other[col] = F::zero();
        }
        pivots.push(col);
        row += 1;
    }
    a.truncate(row);
    (a, pivots)
}

/// A basis of the null space `{x : rows · x = 0}` (`ncols` unknowns), one vector per free
/// column (free variable = 1, others 0): [`Matrix::null_space`] for exact scalars, the
/// same construction on the tolerant [`rref`] for `f64`.
pub(crate) fn null_space<F: Scalar>(rows: &[Vec<F>], ncols: usize) -> Vec<Vec<F>> {
    if F::EXACT {
        return matrix(rows, ncols).null_space();
    }
    let (r, pivots) = rref(rows, ncols);
    let mut basis = Vec::new();
    for free in 0..ncols {
        if pivots.contains(&free) {
            continue;
        }
        let mut v = vec![F::zero(); ncols];
        v[free] = F::one();
        for (row, &pc) in r.iter().zip(&pivots) {
            v[pc] = -row[free].clone();
        }
        basis.push(v);
    }
    basis
}

/// The inverse of a 4×4 matrix (`None` if singular), by [`Matrix::inverse`].
pub(crate) fn inverse4<F: Scalar>(a: &[[F; 4]; 4]) -> Option<[[F; 4]; 4]> {
    let inv = Matrix::from_fn(4, 4, |i, j| a[i][j].clone())
        .inverse()
        .ok()?;
    let rows: Vec<Vec<F>> = inv.row_iter().map(<[F]>::to_vec).collect();
    Some([0, 1, 2, 3].map(|i| to_hom(rows.get(i).map_or(&[][..], Vec::as_slice))))
}

/// Determinant of a square matrix ([`Matrix::determinant`], fraction-free Bareiss).
pub(crate) fn det<F: Scalar>(a: &[Vec<F>]) -> F {
    matrix(a, a.len())
        .determinant()
        .unwrap_or_else(|_| F::zero())
}

/// Covectors spanning the annihilator of the given vectors (a basis of
/// `{ν : ν·v = 0 for all v}`).
pub(crate) fn annihilator<F: Scalar>(vectors: &[Hom<F>]) -> Vec<Hom<F>> {
    let rows: Vec<Vec<F>> = vectors.iter().map(|v| v.to_vec()).collect();
    null_space(&rows, 4)
        .into_iter()
        .map(|v| to_hom(&v))
        .collect()
}

/// The variable `pᵢ` as a polynomial in `p0..p3`.
pub(crate) fn poly_var<F: Scalar>(i: usize) -> MPoly<F> {
    MPoly::var(4, i)
}

/// `true` if every coefficient is negligible relative to `scale`.
pub(crate) fn poly_negligible<F: Scalar>(p: &MPoly<F>, scale: f64) -> bool {
    p.terms().all(|(_, c)| negligible(c, scale))
}

/// The first non-negligible terms of a polynomial in `p0..p3`, formatted (for a failing
/// certificate).
pub(crate) fn poly_describe<F: Scalar>(p: &MPoly<F>, scale: f64) -> String {
    const NAMES: [&str; 4] = ["p0", "p1", "p2", "p3"];
    let mut parts = Vec::new();
    for (e, c) in p.terms() {
        if negligible(c, scale) {
            continue;
        }
        let mut mono = String::new();
        for (name, &k) in NAMES.iter().zip(e) {
            if k == 1 {
                mono.push_str(name);
            } else if k > 1 {
                mono.push_str(&format!("{name}^{k}"));
            }
        }
        parts.push(format!("{}·{}", fmt_scalar(c), mono));
        if parts.len() == 4 {
            parts.push("…".into());
            break;
        }
    }
    if parts.is_empty() {
        "0".into()
    } else {
        parts.join(" + ")
    }
}

/// `c · A`.
pub(crate) fn scale_mat<F: Scalar>(c: &F, a: &[[F; 4]; 4]) -> [[F; 4]; 4] {
    a.clone().map(|r| r.map(|x| c.clone() * x))
}

/// Entries agree up to the `f64` tolerance (exact equality for exact scalars).
pub(crate) fn mats_close<F: Scalar>(a: &[[F; 4]; 4], b: &[[F; 4]; 4]) -> bool {
    let scale = a
        .iter()
        .chain(b.iter())
        .map(|r| magnitude(r))
        .fold(1.0, f64::max);
    (0..4).all(|i| (0..4).all(|j| negligible(&(a[i][j].clone() - b[i][j].clone()), scale)))
}
