//! Small private helpers of the quadric module: formatting, `f64` tolerances, Bernstein
//! bases, 4×4 and general exact linear algebra, and homogeneous polynomials in four
//! variables (for the identity certificates of the maps themselves).
//!
//! Note for the lead: these duplicate pieces of `rcagd_algebra::{linalg, mpoly, bernstein}`
//! and of `rcagd_geom` evaluation, written here because those files were still in
//! progress when this module was written. They can be replaced one by one.

// Index loops mirror the matrix formulas (Q_ij, M_k[i][j]) of the notes.
#![allow(clippy::needless_range_loop)]

use super::Hom;
use rcagd_algebra::rational::format_rational;
use rcagd_algebra::Scalar;
use rcagd_geom::{BezierCurve, BezierPatch};
use std::collections::BTreeMap;

/// Relative tolerance of the `f64` decisions.
pub(crate) const TOL: f64 = 1e-9;

/// A scalar as text: `"p/q"` for exact scalars, a decimal for `f64`.
pub(crate) fn fmt_scalar<F: Scalar>(x: &F) -> String {
    if F::EXACT {
        match x.to_rational() {
            Some(q) => format_rational(&q),
            None => format!("{:?}", x),
        }
    } else {
        format!("{}", x.to_f64())
    }
}

/// A vector as text `(a, b, …)`.
pub(crate) fn fmt_vec<F: Scalar>(v: &[F]) -> String {
    let parts: Vec<String> = v.iter().map(fmt_scalar).collect();
    format!("({})", parts.join(", "))
}

/// Largest absolute value (as `f64`) of a slice, at least 1.
pub(crate) fn magnitude<F: Scalar>(v: &[F]) -> f64 {
    v.iter().map(|x| x.to_f64().abs()).fold(1.0, f64::max)
}

/// `x == 0` exactly for exact scalars; `|x| ≤ TOL · max(scale, 1)` for `f64`.
pub(crate) fn negligible<F: Scalar>(x: &F, scale: f64) -> bool {
    if F::EXACT {
        x.is_zero()
    } else {
        let v = x.to_f64();
        v.is_finite() && v.abs() <= TOL * scale.max(1.0)
    }
}

/// All entries negligible relative to `scale`.
pub(crate) fn all_negligible<F: Scalar>(v: &[F], scale: f64) -> bool {
    v.iter().all(|x| negligible(x, scale))
}

/// `true` if every entry is finite (always for exact scalars).
pub(crate) fn all_finite<F: Scalar>(v: &[F]) -> bool {
    F::EXACT || v.iter().all(|x| x.to_f64().is_finite())
}

/// Binomial coefficient as a scalar (exact for exact scalars).
pub(crate) fn binom<F: Scalar>(n: usize, k: usize) -> F {
    if k > n {
        return F::zero();
    }
    let k = k.min(n - k);
    let mut r = F::one();
    for i in 0..k {
        r = r * F::from_i64((n - i) as i64) / F::from_i64((i + 1) as i64);
    }
    r
}

/// The Bernstein basis `Bⱼⁿ(t) = C(n,j) tʲ (1−t)ⁿ⁻ʲ`, `j = 0..=n`.
pub(crate) fn bernstein<F: Scalar>(n: usize, t: &F) -> Vec<F> {
    let s = F::one() - t.clone();
    (0..=n)
        .map(|j| {
            let mut v = binom::<F>(n, j);
            for _ in 0..j {
                v *= t.clone();
            }
            for _ in j..n {
                v *= s.clone();
            }
            v
        })
        .collect()
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

/// The homogeneous point of a curve at `t` (Bernstein sum).
pub(crate) fn eval_curve<F: Scalar>(curve: &BezierCurve<F>, t: &F) -> Hom<F> {
    let b = bernstein::<F>(curve.degree(), t);
    let mut out = zero4::<F>();
    for (bj, p) in b.iter().zip(curve.control_points()) {
        for (o, x) in out.iter_mut().zip(p) {
            *o += bj.clone() * x.clone();
        }
    }
    out
}

/// The homogeneous derivative of a curve at `t`.
pub(crate) fn eval_curve_derivative<F: Scalar>(curve: &BezierCurve<F>, t: &F) -> Hom<F> {
    let b = bernstein_derivative::<F>(curve.degree(), t);
    let mut out = zero4::<F>();
    for (bj, p) in b.iter().zip(curve.control_points()) {
        for (o, x) in out.iter_mut().zip(p) {
            *o += bj.clone() * x.clone();
        }
    }
    out
}

/// The homogeneous point of a patch at `(u, v)`.
pub(crate) fn eval_patch<F: Scalar>(patch: &BezierPatch<F>, u: &F, v: &F) -> Hom<F> {
    let (m, n) = patch.degree();
    let bu = bernstein::<F>(m, u);
    let bv = bernstein::<F>(n, v);
    let mut out = zero4::<F>();
    for (i, bi) in bu.iter().enumerate() {
        for (j, bj) in bv.iter().enumerate() {
            let w = bi.clone() * bj.clone();
            for (o, x) in out.iter_mut().zip(patch.control_point(i, j)) {
                *o += w.clone() * x.clone();
            }
        }
    }
    out
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

/// The rank of a list of row vectors (Gaussian elimination; `f64` with a relative tolerance).
pub(crate) fn rank<F: Scalar>(rows: &[Vec<F>]) -> usize {
    let ncols = rows.iter().map(|r| r.len()).max().unwrap_or(0);
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

/// Reduced row echelon form of the rows (`ncols` columns); returns the reduced rows and
/// the pivot columns. `f64`: partial pivoting, entries below `TOL · max|entry|` are zero.
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
/// column (free variable = 1, others 0).
pub(crate) fn null_space<F: Scalar>(rows: &[Vec<F>], ncols: usize) -> Vec<Vec<F>> {
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

/// The inverse of a 4×4 matrix (`None` if singular).
pub(crate) fn inverse4<F: Scalar>(a: &[[F; 4]; 4]) -> Option<[[F; 4]; 4]> {
    let rows: Vec<Vec<F>> = (0..4)
        .map(|i| {
            let mut r = a[i].to_vec();
            r.extend((0..4).map(|j| if i == j { F::one() } else { F::zero() }));
            r
        })
        .collect();
    let (red, pivots) = rref(&rows, 8);
    if pivots.len() < 4 || pivots[..4] != [0, 1, 2, 3] {
        return None;
    }
    let mut out = [zero4::<F>(), zero4(), zero4(), zero4()];
    for i in 0..4 {
        for j in 0..4 {
            out[i][j] = red[i][4 + j].clone();
        }
    }
    Some(out)
}

/// Determinant of a square matrix (Gaussian elimination).
pub(crate) fn det<F: Scalar>(a: &[Vec<F>]) -> F {
    let n = a.len();
    let mut m: Vec<Vec<F>> = a.to_vec();
    let mut d = F::one();
    for col in 0..n {
        let p = if F::EXACT {
            (col..n).find(|&r| !m[r][col].is_zero())
        } else {
            (col..n)
                .filter(|&r| m[r][col].to_f64() != 0.0)
                .max_by(|&x, &y| {
                    m[x][col]
                        .to_f64()
                        .abs()
                        .total_cmp(&m[y][col].to_f64().abs())
                })
        };
        let Some(p) = p else {
            return F::zero();
        };
        if p != col {
            m.swap(p, col);
            d = -d;
        }
        let piv = m[col][col].clone();
        d *= piv.clone();
        for r in col + 1..n {
            if m[r][col].is_zero() {
                continue;
            }
            let f = m[r][col].clone() / piv.clone();
            for c in col..n {
                let v = m[col][c].clone();
                m[r][c] = m[r][c].clone() - f.clone() * v;
            }
        }
    }
    d
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

/// A homogeneous polynomial (or any polynomial) in the four variables `p0..p3`, stored
/// sparsely by exponent vector. Only what the identity certificates of the maps need.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Poly4<F> {
    terms: BTreeMap<[u8; 4], F>,
}

impl<F: Scalar> Poly4<F> {
    pub(crate) fn zero() -> Self {
        Poly4 {
            terms: BTreeMap::new(),
        }
    }
    pub(crate) fn var(i: usize) -> Self {
        let mut e = [0u8; 4];
        e[i] = 1;
        let mut terms = BTreeMap::new();
        terms.insert(e, F::one());
        Poly4 { terms }
    }
    fn insert(&mut self, e: [u8; 4], c: F) {
        let entry = self.terms.entry(e).or_insert_with(F::zero);
        *entry = entry.clone() + c;
        if F::EXACT && entry.is_zero() {
            self.terms.remove(&e);
        }
    }
    pub(crate) fn add(&self, o: &Self) -> Self {
        let mut r = self.clone();
        for (e, c) in &o.terms {
            r.insert(*e, c.clone());
        }
        r
    }
    pub(crate) fn sub(&self, o: &Self) -> Self {
        let mut r = self.clone();
        for (e, c) in &o.terms {
            r.insert(*e, -c.clone());
        }
        r
    }
    pub(crate) fn scale(&self, c: &F) -> Self {
        let mut r = Self::zero();
        for (e, x) in &self.terms {
            r.insert(*e, c.clone() * x.clone());
        }
        r
    }
    pub(crate) fn mul(&self, o: &Self) -> Self {
        let mut r = Self::zero();
        for (e1, c1) in &self.terms {
            for (e2, c2) in &o.terms {
                let e = [0, 1, 2, 3].map(|i| e1[i] + e2[i]);
                r.insert(e, c1.clone() * c2.clone());
            }
        }
        r
    }
    /// `true` if every coefficient is negligible relative to `scale`.
    pub(crate) fn is_negligible(&self, scale: f64) -> bool {
        self.terms.values().all(|c| negligible(c, scale))
    }
    /// The first non-negligible term, formatted (for a failing certificate).
    pub(crate) fn describe(&self, scale: f64) -> String {
        const NAMES: [&str; 4] = ["p0", "p1", "p2", "p3"];
        let mut parts = Vec::new();
        for (e, c) in &self.terms {
            if negligible(c, scale) {
                continue;
            }
            let mut mono = String::new();
            for (i, &k) in e.iter().enumerate() {
                if k == 1 {
                    mono.push_str(NAMES[i]);
                } else if k > 1 {
                    mono.push_str(&format!("{}^{}", NAMES[i], k));
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
