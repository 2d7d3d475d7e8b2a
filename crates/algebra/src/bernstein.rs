//! Polynomials in the Bernstein basis: conversion to and from the power basis,
//! products, degree elevation, de Casteljau evaluation, subdivision, blossoms and
//! derivatives of Bernstein coefficient vectors.
//!
//! A coefficient vector `b = (b₀, …, bₙ)` of degree `n` stands for
//! `p(t) = Σᵢ bᵢ Bᵢⁿ(t)`, `Bᵢⁿ(t) = C(n,i) (1−t)ⁿ⁻ⁱ tⁱ`
//! (Besednjak, docs/math/ph-curves.md, "Control points from the quaternion coefficients"; Jüttler, docs/math/quadrics.md).
//! The degree is `b.len() − 1`; an empty vector is the zero polynomial without a degree.
//!
//! Every operation that is used on control points comes in two forms:
//!
//! * a scalar form (`eval`, `subdivide`, …) on `&[R]`;
//! * a *block* form (`eval_blocks`, `subdivide_blocks`, …) on a flat array whose
//!   coefficients are consecutive blocks of `width` ring elements — the homogeneous
//!   control points `(w, wx, wy, …)` of a curve (`width = d + 1`) or whole rows of a
//!   tensor-product patch (`width = (n + 1)(d + 1)`). The coefficients are
//!   vector-valued and every operation acts on each component alike. The number of
//!   coefficients is `b.len() / width`; `width` should divide `b.len()` (a trailing
//!   partial block is ignored) and `width = 0` gives an empty result.
//!
//! Operations that only add, subtract and multiply by the parameter work over any
//! [`Ring`] (the parameter multiplies from the left, so quaternion coefficients are
//! fine); those that divide by binomial coefficients (products, elevation, conversion
//! to Bernstein form) need a [`Field`]. All of them are exact over exact fields.

use crate::error::AlgebraError;
use crate::poly::Poly;
use crate::scalar::{Field, Ring};

// ---------------------------------------------------------------------------------
// Binomial coefficients
// ---------------------------------------------------------------------------------

/// The image of an unsigned integer in the ring (exact for any size).
fn ring_from_u128<R: Ring>(v: u128) -> R {
    if let Ok(small) = i64::try_from(v) {
        return R::from_i64(small);
    }
    // v = hi·2⁶² + lo with hi, lo < 2⁶³ … 2⁶⁶: split once more if needed.
    let base = 1u128 << 62;
    let hi = v >> 62;
    let lo = (v & (base - 1)) as i64;
    ring_from_u128::<R>(hi) * R::from_i64(base as i64) + R::from_i64(lo)
}

/// The row `C(n,0), …, C(n,n)` of Pascal's triangle as machine integers, or `None`
/// on overflow of `u128`.
fn binomial_row_u128(n: usize) -> Option<Vec<u128>> {
    let mut row = Vec::with_capacity(n + 1);
    let mut c: u128 = 1;
    row.push(c);
    for k in 0..n {
        // C(n, k+1) = C(n, k) (n − k) / (k + 1), exact at every step.
        c = c.checked_mul((n - k) as u128)? / (k as u128 + 1);
        row.push(c);
    }
    Some(row)
}

/// The binomial coefficients `C(n,0), …, C(n,n)` as ring elements.
///
/// Exact for every `n`: machine integers while they fit in `u128`, Pascal's rule
/// `C(n,k) = C(n−1,k−1) + C(n−1,k)` in the ring beyond.
pub fn binomial_row<R: Ring>(n: usize) -> Vec<R> {
    if let Some(row) = binomial_row_u128(n) {
        return row.into_iter().map(ring_from_u128).collect();
    }
    let mut row: Vec<R> = vec![R::one()];
    for _ in 0..n {
        let mut next = Vec::with_capacity(row.len() + 1);
        next.push(R::one());
        next.extend(row.windows(2).map(|w| w[0].clone() + w[1].clone()));
        next.push(R::one());
        row = next;
    }
    row
}

/// The binomial coefficient `C(n, k)` (zero for `k > n`).
pub fn binomial<R: Ring>(n: usize, k: usize) -> R {
    if k > n {
        return R::zero();
    }
    let k = k.min(n - k);
    let mut c: u128 = 1;
    for i in 0..k {
        match c.checked_mul((n - i) as u128) {
            Some(v) => c = v / (i as u128 + 1),
            None => return binomial_row::<R>(n).swap_remove(k),
        }
    }
    ring_from_u128(c)
}

// ---------------------------------------------------------------------------------
// Basis conversion
// ---------------------------------------------------------------------------------

/// The Bernstein coefficients of degree `n` of a power-basis polynomial:
/// `bₖ = Σ_{i ≤ k} C(k,i)/C(n,i) · aᵢ`, `k = 0, …, n`.
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] if `deg p > n`.
pub fn to_bernstein<F: Field>(p: &Poly<F>, n: usize) -> Result<Vec<F>, AlgebraError> {
    to_bernstein_blocks(p.coeffs(), 1, n)
}

/// Block form of [`to_bernstein`]: `power` holds the vector-valued power coefficients
/// `a₀, a₁, …` (each `width` long, fewer than `n + 1` allowed).
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] if there are more than `n + 1` coefficients.
pub fn to_bernstein_blocks<F: Field>(
    power: &[F],
    width: usize,
    n: usize,
) -> Result<Vec<F>, AlgebraError> {
    if width == 0 {
        return Ok(Vec::new());
    }
    let count = power.len() / width;
    if count > n + 1 {
        return Err(AlgebraError::InvalidArgument(format!(
            "polynomial of degree {} has no Bernstein form of degree {n}",
            count - 1
        )));
    }
    let cn: Vec<F> = binomial_row(n);
    // a'ᵢ = aᵢ / C(n,i)
    let scaled: Vec<F> = power[..count * width]
        .chunks(width)
        .enumerate()
        .flat_map(|(i, a)| {
            let inv = F::one() / cn[i].clone();
            a.iter().map(move |x| x.clone() * inv.clone())
        })
        .collect();
    let mut out = vec![F::zero(); (n + 1) * width];
    for k in 0..=n {
        crate::budget::checkpoint();
        let ck: Vec<F> = binomial_row(k);
        let dst = &mut out[k * width..(k + 1) * width];
        for (i, cki) in ck.iter().enumerate().take(count.min(k + 1)) {
            for (o, a) in dst.iter_mut().zip(&scaled[i * width..(i + 1) * width]) {
                *o += cki.clone() * a.clone();
            }
        }
    }
    Ok(out)
}

/// The power-basis polynomial of a Bernstein coefficient vector:
/// `aᵢ = C(n,i) Δⁱb₀` with the forward differences `Δⁱb₀ = Σ_{k ≤ i} (−1)ⁱ⁻ᵏ C(i,k) bₖ`.
/// The empty vector gives the zero polynomial.
pub fn from_bernstein<R: Ring>(b: &[R]) -> Poly<R> {
    Poly::new(from_bernstein_blocks(b, 1))
}

/// Block form of [`from_bernstein`]: returns the `n + 1` vector-valued power
/// coefficients `a₀, …, aₙ` (untrimmed, each `width` long).
pub fn from_bernstein_blocks<R: Ring>(b: &[R], width: usize) -> Vec<R> {
    let Some(n) = count(b, width).checked_sub(1) else {
        return Vec::new();
    };
    let cn: Vec<R> = binomial_row(n);
    let mut diff: Vec<R> = b[..(n + 1) * width].to_vec();
    let mut out = Vec::with_capacity((n + 1) * width);
    for (i, c) in cn.iter().enumerate() {
        // diff[0..n−i+1] holds Δⁱb₀, …, Δⁱbₙ₋ᵢ.
        out.extend(diff[..width].iter().map(|x| c.clone() * x.clone()));
        crate::budget::checkpoint();
        for k in 0..n - i {
            for q in 0..width {
                let next = diff[(k + 1) * width + q].clone();
                let here = diff[k * width + q].clone();
                diff[k * width + q] = next - here;
            }
        }
    }
    out
}

// ---------------------------------------------------------------------------------
// Evaluation, blossoms, subdivision
// ---------------------------------------------------------------------------------

fn count<R>(b: &[R], width: usize) -> usize {
    b.len().checked_div(width).unwrap_or(0)
}

/// One homogeneous de Casteljau step in place: `vᵢ ← σ₀ vᵢ + σ₁ vᵢ₊₁` for the first
/// `points − 1` blocks.
fn casteljau_step<R: Ring>(v: &mut [R], width: usize, points: usize, s0: &R, s1: &R) {
    // the exporters' exact boundary curves and subdivisions spend their time here
    crate::budget::checkpoint();
    for i in 0..points.saturating_sub(1) {
        for q in 0..width {
            let a = v[i * width + q].clone();
            let b = v[(i + 1) * width + q].clone();
            v[i * width + q] = s0.clone() * a + s1.clone() * b;
        }
    }
}

/// The values `B₀ⁿ(t), …, Bₙⁿ(t)` of all Bernstein polynomials of degree `n`
/// (by the triangle `Bᵢʳ = (1−t)Bᵢʳ⁻¹ + t Bᵢ₋₁ʳ⁻¹`).
pub fn basis<R: Ring>(n: usize, t: &R) -> Vec<R> {
    let s = R::one() - t.clone();
    let mut v = vec![R::zero(); n + 1];
    v[0] = R::one();
    for r in 1..=n {
        for i in (1..=r).rev() {
            v[i] = s.clone() * v[i].clone() + t.clone() * v[i - 1].clone();
        }
        v[0] = s.clone() * v[0].clone();
    }
    v
}

/// De Casteljau evaluation `p(t) = Σ bᵢ Bᵢⁿ(t)` by repeated linear interpolation
/// `bᵢʳ = (1−t) bᵢʳ⁻¹ + t bᵢ₊₁ʳ⁻¹`, `p(t) = b₀ⁿ`. Any `t` (extrapolation outside
/// `[0, 1]`); zero for the empty vector.
pub fn eval<R: Ring>(b: &[R], t: &R) -> R {
    eval_blocks(b, 1, t).pop().unwrap_or_else(R::zero)
}

/// Block form of [`eval`]: the vector-valued `p(t)` (`width` entries; empty if there
/// are no coefficients).
pub fn eval_blocks<R: Ring>(b: &[R], width: usize, t: &R) -> Vec<R> {
    // at the end points de Casteljau returns the end blocks (`1·bᵢ + 0·bᵢ₊₁`): take them
    // without its `n²/2` products (the exporters' boundary curves of large exact patches)
    let points = count(b, width);
    if points > 0 {
        if t.is_zero() {
            return b[..width].to_vec();
        }
        if *t == R::one() {
            return b[(points - 1) * width..points * width].to_vec();
        }
    }
    let s = R::one() - t.clone();
    eval_homogeneous_blocks(b, width, &s, t)
}

/// Homogeneous de Casteljau evaluation at the homogeneous parameter `(σ₀, σ₁)`:
/// `Σ C(n,i) σ₀ⁿ⁻ⁱ σ₁ⁱ bᵢ` (equal to `p(t)` for `(σ₀, σ₁) = (1−t, t)`).
pub fn eval_homogeneous_blocks<R: Ring>(b: &[R], width: usize, s0: &R, s1: &R) -> Vec<R> {
    let points = count(b, width);
    if points == 0 {
        return Vec::new();
    }
    let mut v = b[..points * width].to_vec();
    for r in 1..points {
        casteljau_step(&mut v, width, points - r + 1, s0, s1);
    }
    v.truncate(width);
    v
}

/// The blossom (polar form) `p[t₁, …, tₙ]`: the symmetric multi-affine function with
/// `p[t, …, t] = p(t)`, computed by de Casteljau with parameter `tᵣ` at step `r`.
///
/// # Errors
/// [`AlgebraError::Mismatch`] unless exactly `n = b.len() − 1` arguments are given.
pub fn blossom<R: Ring>(b: &[R], ts: &[R]) -> Result<Vec<R>, AlgebraError> {
    let args: Vec<(R, R)> = ts
        .iter()
        .map(|t| (R::one() - t.clone(), t.clone()))
        .collect();
    blossom_homogeneous_blocks(b, 1, &args)
}

/// Block form of the homogeneous blossom `p[(σ₀,σ₁)₁, …, (σ₀,σ₁)ₙ]`: de Casteljau
/// with step `r` `bᵢʳ = σ₀ bᵢʳ⁻¹ + σ₁ bᵢ₊₁ʳ⁻¹` using the `r`-th argument. It is
/// symmetric and multilinear; `(1−t, t)` gives the affine blossom.
///
/// # Errors
/// [`AlgebraError::Mismatch`] unless the number of arguments is the degree.
pub fn blossom_homogeneous_blocks<R: Ring>(
    b: &[R],
    width: usize,
    args: &[(R, R)],
) -> Result<Vec<R>, AlgebraError> {
    let points = count(b, width);
    if points == 0 || args.len() != points - 1 {
        return Err(AlgebraError::Mismatch(format!(
            "blossom of a polynomial with {points} coefficients needs {} arguments, got {}",
            points.saturating_sub(1),
            args.len()
        )));
    }
    let mut v = b[..points * width].to_vec();
    for (r, (s0, s1)) in args.iter().enumerate() {
        casteljau_step(&mut v, width, points - r, s0, s1);
    }
    v.truncate(width);
    Ok(v)
}

/// De Casteljau subdivision at `t`: the coefficient vectors of `p` on `[0, t]` and on
/// `[t, 1]`, each reparametrized to `[0, 1]`: `left(s) = p(t s)`,
/// `right(s) = p(t + (1−t) s)`. `left = (b₀⁰, b₀¹, …, b₀ⁿ)`,
/// `right = (b₀ⁿ, b₁ⁿ⁻¹, …, bₙ⁰)`. Any `t` (outside `[0, 1]` it extrapolates).
pub fn subdivide<R: Ring>(b: &[R], t: &R) -> (Vec<R>, Vec<R>) {
    subdivide_blocks(b, 1, t)
}

/// Block form of [`subdivide`].
pub fn subdivide_blocks<R: Ring>(b: &[R], width: usize, t: &R) -> (Vec<R>, Vec<R>) {
    let points = count(b, width);
    if points == 0 {
        return (Vec::new(), Vec::new());
    }
    let s = R::one() - t.clone();
    let mut v = b[..points * width].to_vec();
    let mut left = Vec::with_capacity(points * width);
    let mut right = vec![R::zero(); points * width];
    let last = points - 1;
    left.extend_from_slice(&v[..width]);
    right[last * width..].clone_from_slice(&v[last * width..points * width]);
    for r in 1..points {
        casteljau_step(&mut v, width, points - r + 1, &s, t);
        left.extend_from_slice(&v[..width]);
        let k = points - 1 - r; // last live block at level r
        right[k * width..(k + 1) * width].clone_from_slice(&v[k * width..(k + 1) * width]);
    }
    (left, right)
}

// ---------------------------------------------------------------------------------
// Derivatives, elevation, products
// ---------------------------------------------------------------------------------

/// The Bernstein coefficients of the derivative (the hodograph):
/// `p'(t) = Σ n (bᵢ₊₁ − bᵢ) Bᵢⁿ⁻¹(t)`, degree `n − 1`. A constant (`n = 0`) gives
/// the zero constant `[0]`; the empty vector gives the empty vector.
pub fn derivative<R: Ring>(b: &[R]) -> Vec<R> {
    derivative_blocks(b, 1)
}

/// Block form of [`derivative`] (a constant gives one zero block).
pub fn derivative_blocks<R: Ring>(b: &[R], width: usize) -> Vec<R> {
    let points = count(b, width);
    match points {
        0 => Vec::new(),
        1 => vec![R::zero(); width],
        _ => {
            let n = R::from_i64((points - 1) as i64);
            (0..(points - 1) * width)
                .map(|k| n.clone() * (b[k + width].clone() - b[k].clone()))
                .collect()
        }
    }
}

/// Degree elevation by `r`: the coefficients of the same polynomial in degree `n + r`,
/// `cₖ = Σᵢ C(n,i) C(r,k−i) / C(n+r,k) · bᵢ` (the Bernstein product with the constant 1
/// of degree `r`).
pub fn elevate<F: Field>(b: &[F], r: usize) -> Vec<F> {
    elevate_blocks(b, 1, r)
}

/// Block form of [`elevate`].
pub fn elevate_blocks<F: Field>(b: &[F], width: usize, r: usize) -> Vec<F> {
    let points = count(b, width);
    if points == 0 || r == 0 {
        return b[..points * width].to_vec();
    }
    let n = points - 1;
    let cn: Vec<F> = binomial_row(n);
    let cr: Vec<F> = binomial_row(r);
    let cnr: Vec<F> = binomial_row(n + r);
    let mut out = vec![F::zero(); (n + r + 1) * width];
    for (k, cnrk) in cnr.iter().enumerate() {
        crate::budget::checkpoint();
        let inv = F::one() / cnrk.clone();
        let lo = k.saturating_sub(r);
        for i in lo..=n.min(k) {
            let f = cn[i].clone() * cr[k - i].clone() * inv.clone();
            for q in 0..width {
                out[k * width + q] += f.clone() * b[i * width + q].clone();
            }
        }
    }
    out
}

/// Bernstein product: the coefficients of `p·q` in degree `m + n`,
/// `cₖ = Σ_{i+j=k} C(m,i) C(n,j) / C(m+n,k) · aᵢ bⱼ` (docs/math/ph-curves.md, "Control points from the quaternion coefficients"; the order of
/// factors is kept). An empty factor gives the empty vector.
pub fn product<F: Field>(a: &[F], b: &[F]) -> Vec<F> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let (m, n) = (a.len() - 1, b.len() - 1);
    let sa = scale_by_binomials(a);
    let sb = scale_by_binomials(b);
    let mut out = vec![F::zero(); m + n + 1];
    for (i, x) in sa.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        crate::budget::checkpoint();
        for (j, y) in sb.iter().enumerate() {
            out[i + j] += x.clone() * y.clone();
        }
    }
    divide_by_binomials(&mut out);
    out
}

/// `aᵢ ↦ C(n,i) aᵢ` (the "scaled Bernstein" form in which products are convolutions).
fn scale_by_binomials<F: Field>(a: &[F]) -> Vec<F> {
    let c: Vec<F> = binomial_row(a.len().saturating_sub(1));
    a.iter().zip(c).map(|(x, c)| c * x.clone()).collect()
}

/// `cₖ ↦ cₖ / C(N,k)`, `N = len − 1`.
fn divide_by_binomials<F: Field>(c: &mut [F]) {
    let row: Vec<F> = binomial_row(c.len().saturating_sub(1));
    for (x, b) in c.iter_mut().zip(row) {
        *x = x.clone() / b;
    }
}

/// Tensor-product Bernstein product of two bivariate coefficient arrays (row-major,
/// `a` of bidegree `(m₁, n₁)` has `(m₁+1)(n₁+1)` entries, index `i(n₁+1) + j`):
/// `c_{kl} = Σ_{i+i'=k, j+j'=l} [C(m₁,i)C(m₂,i')/C(m₁+m₂,k)]·[C(n₁,j)C(n₂,j')/C(n₁+n₂,l)] a_{ij} b_{i'j'}`
/// (Jüttler, docs/math/quadrics.md, "Curves and patches under δ"), bidegree `(m₁+m₂, n₁+n₂)`.
///
/// # Errors
/// [`AlgebraError::Mismatch`] if an array's length does not fit its bidegree.
pub fn product_tensor<F: Field>(
    a: &[F],
    (m1, n1): (usize, usize),
    b: &[F],
    (m2, n2): (usize, usize),
) -> Result<Vec<F>, AlgebraError> {
    check_tensor_lengths(a.len(), (m1, n1), b.len(), (m2, n2))?;
    let scale2 = |arr: &[F], m: usize, n: usize| -> Vec<F> {
        let cm: Vec<F> = binomial_row(m);
        let cn: Vec<F> = binomial_row(n);
        arr.iter()
            .enumerate()
            .map(|(k, x)| cm[k / (n + 1)].clone() * cn[k % (n + 1)].clone() * x.clone())
            .collect()
    };
    let sa = scale2(a, m1, n1);
    let sb = scale2(b, m2, n2);
    let (m, n) = (m1 + m2, n1 + n2);
    let mut out = vec![F::zero(); (m + 1) * (n + 1)];
    for (ia, x) in sa.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        let (i, j) = (ia / (n1 + 1), ia % (n1 + 1));
        for (ib, y) in sb.iter().enumerate() {
            let (i2, j2) = (ib / (n2 + 1), ib % (n2 + 1));
            out[(i + i2) * (n + 1) + j + j2] += x.clone() * y.clone();
        }
    }
    let cm: Vec<F> = binomial_row(m);
    let cn: Vec<F> = binomial_row(n);
    for (k, x) in out.iter_mut().enumerate() {
        *x = x.clone() / (cm[k / (n + 1)].clone() * cn[k % (n + 1)].clone());
    }
    Ok(out)
}

/// [`product_tensor`] for exact scalars, fraction-free: each factor is brought to integer
/// coefficients over one common denominator (`a = A/d_a`), the products of the
/// binomial-scaled integer coefficients are summed in integers, and each coefficient of the
/// result is normalized once, `Σ (C·A)(C·B) / (d_a d_b C(m, i) C(n, j))`. The same numbers as
/// [`product_tensor`] (which normalizes a rational after every product and sum); for `f64`
/// (or any inexact scalar) it is [`product_tensor`].
///
/// # Errors
/// As [`product_tensor`].
pub fn product_tensor_scalar<F: crate::scalar::Scalar>(
    a: &[F],
    da: (usize, usize),
    b: &[F],
    db: (usize, usize),
) -> Result<Vec<F>, AlgebraError> {
    use crate::rational::Rational;
    use dashu_int::{IBig, UBig};
    if !F::EXACT {
        return product_tensor(a, da, b, db);
    }
    let to_q = |v: &[F]| -> Option<Vec<Rational>> { v.iter().map(|x| x.to_rational()).collect() };
    let (Some(qa), Some(qb)) = (to_q(a), to_q(b)) else {
        return product_tensor(a, da, b, db);
    };
    check_tensor_lengths(qa.len(), da, qb.len(), db)?;
    // integers over a common denominator, scaled by the binomials of the degree
    let ints = |v: &[Rational], (m, n): (usize, usize)| -> (Vec<IBig>, UBig) {
        let mut l = UBig::ONE;
        for x in v {
            let d = x.denominator();
            if d != &UBig::ONE {
                let g = dashu_base::Gcd::gcd(&l, d);
                l = &l / &g * d;
            }
        }
        let cm = binomials_int(m);
        let cn = binomials_int(n);
        let out = v
            .iter()
            .enumerate()
            .map(|(k, x)| {
                x.numerator()
                    * IBig::from(&l / x.denominator())
                    * IBig::from(cm[k / (n + 1)].clone())
                    * IBig::from(cn[k % (n + 1)].clone())
            })
            .collect();
        (out, l)
    };
    let (ia, la) = ints(&qa, da);
    let (ib, lb) = ints(&qb, db);
    let ((m1, n1), (m2, n2)) = (da, db);
    let (m, n) = (m1 + m2, n1 + n2);
    let mut out = vec![IBig::ZERO; (m + 1) * (n + 1)];
    for (ka, x) in ia.iter().enumerate() {
        if x == &IBig::ZERO {
            continue;
        }
        let (i, j) = (ka / (n1 + 1), ka % (n1 + 1));
        for (kb, y) in ib.iter().enumerate() {
            let (i2, j2) = (kb / (n2 + 1), kb % (n2 + 1));
            out[(i + i2) * (n + 1) + j + j2] += x * y;
        }
    }
    let cm = binomials_int(m);
    let cn = binomials_int(n);
    let l = &la * &lb;
    Ok(out
        .into_iter()
        .enumerate()
        .map(|(k, x)| {
            let d = &l * &cm[k / (n + 1)] * &cn[k % (n + 1)];
            F::from_rational(&Rational::from_parts(x, d))
        })
        .collect())
}

/// Both factors of a tensor product have `(m + 1)(n + 1)` coefficients for their bidegree.
fn check_tensor_lengths(
    la: usize,
    da: (usize, usize),
    lb: usize,
    db: (usize, usize),
) -> Result<(), AlgebraError> {
    for (name, len, (m, n)) in [("first", la, da), ("second", lb, db)] {
        if len != (m + 1) * (n + 1) {
            return Err(AlgebraError::Mismatch(format!(
                "{name} factor has {len} coefficients, bidegree ({m}, {n}) needs {}",
                (m + 1) * (n + 1)
            )));
        }
    }
    Ok(())
}

/// `C(n, 0), …, C(n, n)` as integers.
fn binomials_int(n: usize) -> Vec<dashu_int::UBig> {
    let mut row = vec![dashu_int::UBig::ONE];
    for k in 0..n {
        let next = row[k].clone() * dashu_int::UBig::from(n - k) / dashu_int::UBig::from(k + 1);
        row.push(next);
    }
    row
}

/// `p(a + h·x)` for the power coefficients `p` of one line of `c` (entries
/// `c[start + i·stride]`, `i = 0, …, deg`), fraction-free: with `D` the common denominator
/// of `a` and `h`, `A = aD`, `H = hD`, the line becomes the coefficients of
/// `Dᵈᵉᵍ·p(a + h x) = Σᵢ (pᵢ Dᵈᵉᵍ⁻ⁱ)(A + H x)ⁱ`: Horner's Taylor shift by the integer `A`,
/// then the scaling by `Hⁱ` (integers only; the positive factor `Dᵈᵉᵍ`).
fn shift_line_int(
    c: &mut [dashu_int::IBig],
    start: usize,
    stride: usize,
    deg: usize,
    a: &crate::rational::Rational,
    h: &crate::rational::Rational,
) {
    use dashu_int::IBig;
    let d = shift_denominator(a, h);
    let big_a = a.numerator() * IBig::from(&d / a.denominator());
    let big_h = h.numerator() * IBig::from(&d / h.denominator());
    let d = IBig::from(d);
    let idx = |i: usize| start + i * stride;
    let mut dp = IBig::ONE;
    for i in (0..=deg).rev() {
        c[idx(i)] *= &dp;
        if i > 0 {
            dp *= &d;
        }
    }
    for k in 0..deg {
        crate::budget::checkpoint();
        for i in (k..deg).rev() {
            let next = &big_a * &c[idx(i + 1)];
            c[idx(i)] += next;
        }
    }
    let mut hp = IBig::ONE;
    for i in 0..=deg {
        c[idx(i)] *= &hp;
        hp *= &big_h;
    }
}

/// The Bernstein coefficients of degree `deg` of one line of power coefficients, times the
/// positive integer `deg!`: `deg!·bᵣ = Σ_{i ≤ r} C(r, i)·i!·(deg − i)!·aᵢ` (from
/// `bᵣ = Σ_{i ≤ r} C(r, i)/C(deg, i)·aᵢ`; Farin, *Curves and Surfaces for CAGD*, 5th ed.,
/// §5.7, the power-to-Bernstein conversion). `weights[i] = i!·(deg − i)!` (computed once
/// per degree by the caller); the sums `Σ_{i ≤ r} C(r, i)·xᵢ` by `deg` passes of prefix
/// sums (pass `k` adds `x_{r−1}` to `x_r` for `r = deg, …, k`), which leave
/// `Σ_{i ≤ r} C(r, i) xᵢ` in `x_r` (Pascal's rule) — additions only, the same integers.
fn bernstein_line_int(
    c: &mut [dashu_int::IBig],
    start: usize,
    stride: usize,
    deg: usize,
    weights: &[dashu_int::IBig],
) {
    let idx = |i: usize| start + i * stride;
    for (i, w) in weights.iter().enumerate().take(deg + 1) {
        c[idx(i)] *= w;
    }
    for pass in 1..=deg {
        for r in (pass..=deg).rev() {
            let prev = c[idx(r - 1)].clone();
            c[idx(r)] += prev;
        }
    }
}

/// `i!·(deg − i)!` for `i = 0, …, deg` (the weights of [`bernstein_line_int`]).
fn factorial_weights(deg: usize) -> Vec<dashu_int::IBig> {
    use dashu_int::IBig;
    let mut fact = vec![IBig::ONE; deg + 1];
    for i in 1..=deg {
        fact[i] = &fact[i - 1] * IBig::from(i);
    }
    (0..=deg).map(|i| &fact[i] * &fact[deg - i]).collect()
}

/// Positive multiples of the tensor Bernstein coefficients of bidegree `(m, n)` (row-major
/// in `s`) of `p(u₀ + s·Δu, v₀ + t·Δv)` on `[0, 1]²`, for `p = Σ power[i(n+1) + j] uⁱvʲ`
/// over `ℚ`, computed fraction-free (one common multiple `λ > 0` for all of them, so
/// their signs are the signs of the Bernstein coefficients): the coefficients over one
/// common denominator, the Taylor shifts of the columns and rows in integers
/// (`shift_line_int`), the conversions to Bernstein form times `m!`, `n!`
/// (`bernstein_line_int`). Integer products and sums only — no gcd per operation.
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] if `power` does not have `(m + 1)(n + 1)` entries.
pub fn tensor_bernstein_scaled(
    power: &[crate::rational::Rational],
    (m, n): (usize, usize),
    (u0, du): (&crate::rational::Rational, &crate::rational::Rational),
    (v0, dv): (&crate::rational::Rational, &crate::rational::Rational),
) -> Result<Vec<dashu_int::IBig>, AlgebraError> {
    tensor_bernstein_with_multiple(power, (m, n), (u0, du), (v0, dv)).map(|(c, _)| c)
}

/// The exact tensor Bernstein coefficients of bidegree `(m, n)` (row-major in `s`) of
/// `p(u₀ + s·Δu, v₀ + t·Δv)` on `[0, 1]²`: the integers of [`tensor_bernstein_scaled`]
/// divided by their common multiple `λ = L·D_uᵐ·D_vⁿ·m!·n!` (`L` the common denominator of
/// the coefficients, `D_u`, `D_v` those of the shifts), one reduction per coefficient.
///
/// # Errors
/// As [`tensor_bernstein_scaled`].
pub fn tensor_bernstein_exact(
    power: &[crate::rational::Rational],
    mn: (usize, usize),
    u: (&crate::rational::Rational, &crate::rational::Rational),
    v: (&crate::rational::Rational, &crate::rational::Rational),
) -> Result<Vec<crate::rational::Rational>, AlgebraError> {
    let (c, lambda) = tensor_bernstein_with_multiple(power, mn, u, v)?;
    Ok(c.into_iter()
        .map(|x| crate::rational::Rational::from_parts(x, lambda.clone()))
        .collect())
}

/// The common denominator `D` of a shift `(a, h)` in [`shift_line_int`].
fn shift_denominator(
    a: &crate::rational::Rational,
    h: &crate::rational::Rational,
) -> dashu_int::UBig {
    let g = dashu_base::Gcd::gcd(a.denominator(), h.denominator());
    a.denominator() / &g * h.denominator()
}

/// [`tensor_bernstein_scaled`] and its multiple `λ` ([`tensor_bernstein_exact`]).
fn tensor_bernstein_with_multiple(
    power: &[crate::rational::Rational],
    (m, n): (usize, usize),
    (u0, du): (&crate::rational::Rational, &crate::rational::Rational),
    (v0, dv): (&crate::rational::Rational, &crate::rational::Rational),
) -> Result<(Vec<dashu_int::IBig>, dashu_int::UBig), AlgebraError> {
    use dashu_int::{IBig, UBig};
    if power.len() != (m + 1) * (n + 1) {
        return Err(AlgebraError::InvalidArgument(format!(
            "tensor_bernstein_scaled: {} coefficients for bidegree ({m}, {n})",
            power.len()
        )));
    }
    let mut l = UBig::ONE;
    for x in power {
        let d = x.denominator();
        if d != &UBig::ONE && d != &l {
            let g = dashu_base::Gcd::gcd(&l, d);
            l = &l / &g * d;
        }
    }
    let mut c: Vec<IBig> = power
        .iter()
        .map(|x| x.numerator() * IBig::from(&l / x.denominator()))
        .collect();
    let w = n + 1;
    for j in 0..=n {
        shift_line_int(&mut c, j, w, m, u0, du);
    }
    for i in 0..=m {
        shift_line_int(&mut c, i * w, 1, n, v0, dv);
    }
    let (wm, wn) = (factorial_weights(m), factorial_weights(n));
    for j in 0..=n {
        bernstein_line_int(&mut c, j, w, m, &wm);
    }
    for i in 0..=m {
        bernstein_line_int(&mut c, i * w, 1, n, &wn);
    }
    // λ = L·D_uᵐ·D_vⁿ·m!·n! (the shifts multiply by Dᵈᵉᵍ, the conversions by deg!)
    let fact = |k: usize| (1..=k).fold(UBig::ONE, |f, i| f * UBig::from(i));
    let lambda =
        l * shift_denominator(u0, du).pow(m) * shift_denominator(v0, dv).pow(n) * fact(m) * fact(n);
    Ok((c, lambda))
}

/// The sign of `p(u, v) = Σ power[i(n+1) + j] uⁱvʲ` at a rational point, fraction-free:
/// with `L` the common denominator of the coefficients `power = C/L` and `u = a/b`,
/// `v = c/d` (`b, d > 0`), the integer `L·bᵐ·dⁿ·p(u, v) = Σ Cᵢⱼ aⁱbᵐ⁻ⁱ cʲdⁿ⁻ʲ` (homogeneous
/// Horner in both variables) has the sign of `p(u, v)`. Integer products and sums only.
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] if `power` does not have `(m + 1)(n + 1)` entries.
pub fn tensor_sign_at(
    power: &[crate::rational::Rational],
    (m, n): (usize, usize),
    u: &crate::rational::Rational,
    v: &crate::rational::Rational,
) -> Result<core::cmp::Ordering, AlgebraError> {
    use dashu_int::{IBig, UBig};
    if power.len() != (m + 1) * (n + 1) {
        return Err(AlgebraError::InvalidArgument(format!(
            "tensor_sign_at: {} coefficients for bidegree ({m}, {n})",
            power.len()
        )));
    }
    let mut l = UBig::ONE;
    for x in power {
        let d = x.denominator();
        if d != &UBig::ONE && d != &l {
            let g = dashu_base::Gcd::gcd(&l, d);
            l = &l / &g * d;
        }
    }
    let pows = |x: &UBig, k: usize| -> Vec<IBig> {
        let mut out = vec![IBig::ONE];
        for _ in 0..k {
            let next = out
                .last()
                .map(|p| p * IBig::from(x.clone()))
                .unwrap_or(IBig::ONE);
            out.push(next);
        }
        out
    };
    let (bp, dp) = (pows(u.denominator(), m), pows(v.denominator(), n));
    let (a, c) = (u.numerator(), v.numerator());
    let mut acc = IBig::ZERO;
    for j in (0..=n).rev() {
        let mut h = IBig::ZERO;
        for i in (0..=m).rev() {
            let x = &power[i * (n + 1) + j];
            h *= a;
            if !x.is_zero() {
                h += x.numerator() * IBig::from(&l / x.denominator()) * &bp[m - i];
            }
        }
        acc = acc * c + h * &dp[n - j];
    }
    Ok(acc.cmp(&IBig::ZERO))
}

/// The common sign of the tensor Bernstein coefficients of bidegree `(m, n)` of
/// `p(u₀ + s·Δu, v₀ + t·Δv)` on `[0, 1]²` (see [`tensor_bernstein_scaled`]):
/// `Some(Greater)` if all are positive, `Some(Less)` if all are negative, else `None`.
/// All positive implies `p > 0` on the rectangle (Bernstein coefficients enclose the
/// range: Farin, *Curves and Surfaces for CAGD*, 5th ed., §5.2, convex hull property).
///
/// # Errors
/// As [`tensor_bernstein_scaled`].
pub fn tensor_bernstein_sign(
    power: &[crate::rational::Rational],
    mn: (usize, usize),
    u: (&crate::rational::Rational, &crate::rational::Rational),
    v: (&crate::rational::Rational, &crate::rational::Rational),
) -> Result<Option<core::cmp::Ordering>, AlgebraError> {
    let b = tensor_bernstein_scaled(power, mn, u, v)?;
    let zero = dashu_int::IBig::ZERO;
    Ok(if b.iter().all(|x| x > &zero) {
        Some(core::cmp::Ordering::Greater)
    } else if b.iter().all(|x| x < &zero) {
        Some(core::cmp::Ordering::Less)
    } else {
        None
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rational::Rational;
    use crate::scalar::Scalar;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }
    fn qs(v: &[i64]) -> Vec<Rational> {
        v.iter().map(|&x| Rational::from(x)).collect()
    }

    #[test]
    fn binomials() {
        assert_eq!(binomial_row::<Rational>(4), qs(&[1, 4, 6, 4, 1]));
        assert_eq!(binomial::<Rational>(10, 3), Rational::from(120));
        assert_eq!(binomial::<Rational>(3, 5), Rational::from(0));
        // Beyond u128: C(200, 100) by Pascal's rule agrees with the multiplicative formula.
        let row: Vec<Rational> = binomial_row(200);
        let mut c = Rational::from(1);
        for i in 0..100 {
            c = c * Rational::from(200 - i) / Rational::from(i + 1);
        }
        assert_eq!(row[100], c);
        assert_eq!(binomial::<Rational>(200, 100), c);
        assert_eq!(binomial::<f64>(5, 2), 10.0);
    }

    #[test]
    fn power_bernstein_round_trip() {
        let p = Poly::new(vec![q(1, 2), q(-3, 1), q(0, 1), q(5, 7)]);
        for n in 3..7 {
            let b = to_bernstein(&p, n).expect("degree fits");
            assert_eq!(b.len(), n + 1);
            assert_eq!(from_bernstein(&b), p);
            for t in [q(0, 1), q(1, 3), q(5, 4), q(-2, 1)] {
                assert_eq!(eval(&b, &t), p.eval(&t));
            }
        }
        assert!(to_bernstein(&p, 2).is_err());
        assert_eq!(
            to_bernstein(&Poly::<Rational>::zero(), 2).ok(),
            Some(qs(&[0, 0, 0]))
        );
        assert!(from_bernstein::<Rational>(&[]).is_zero());
        // t = Σ i/n Bᵢⁿ
        assert_eq!(
            to_bernstein(&Poly::<Rational>::x(), 3).ok(),
            Some(vec![q(0, 1), q(1, 3), q(2, 3), q(1, 1)])
        );
    }

    #[test]
    fn basis_is_a_partition_of_unity_and_matches_eval() {
        let t = q(2, 7);
        let bas = basis(4, &t);
        let sum = bas.iter().cloned().fold(Rational::from(0), |a, b| a + b);
        assert_eq!(sum, Rational::from(1));
        let b = qs(&[3, -1, 4, 1, -5]);
        let direct = b
            .iter()
            .zip(&bas)
            .fold(Rational::from(0), |a, (x, y)| a + x.clone() * y.clone());
        assert_eq!(direct, eval(&b, &t));
    }

    #[test]
    fn product_and_elevation() {
        let a = qs(&[1, 2, -1]);
        let b = qs(&[3, 0]);
        let c = product(&a, &b);
        let pa = from_bernstein(&a);
        let pb = from_bernstein(&b);
        assert_eq!(from_bernstein(&c), &pa * &pb);
        let e = elevate(&a, 3);
        assert_eq!(e.len(), 6);
        assert_eq!(from_bernstein(&e), pa);
        assert!(product::<Rational>(&[], &a).is_empty());
    }

    #[test]
    fn tensor_product_matches_separate_products() {
        // (a(u) b(v)) · (c(u) d(v)) = (ac)(u) (bd)(v)
        let (a, b, c, d) = (qs(&[1, 2]), qs(&[3, -1, 2]), qs(&[0, 5, 1]), qs(&[2, 7]));
        let outer = |x: &[Rational], y: &[Rational]| -> Vec<Rational> {
            x.iter()
                .flat_map(|p| y.iter().map(move |r| p.clone() * r.clone()))
                .collect()
        };
        let lhs = product_tensor(&outer(&a, &b), (1, 2), &outer(&c, &d), (2, 1)).expect("sizes");
        assert_eq!(lhs, outer(&product(&a, &c), &product(&b, &d)));
        assert!(product_tensor(&a, (1, 1), &c, (2, 0)).is_err());
    }

    #[test]
    fn subdivision_and_blossom() {
        let b = qs(&[2, -3, 7, 1]);
        let t = q(1, 3);
        let (l, r) = subdivide(&b, &t);
        for s in [q(0, 1), q(1, 2), q(3, 5), q(1, 1)] {
            assert_eq!(eval(&l, &s), eval(&b, &(t.clone() * s.clone())));
            let mapped = t.clone() + (Rational::from(1) - t.clone()) * s.clone();
            assert_eq!(eval(&r, &s), eval(&b, &mapped));
        }
        // Blossom on the diagonal is the value; at (0,…,0,1,…,1) the control points.
        assert_eq!(
            blossom(&b, &[t.clone(), t.clone(), t.clone()]).ok(),
            Some(vec![eval(&b, &t)])
        );
        assert_eq!(
            blossom(&b, &[q(0, 1), q(1, 1), q(1, 1)]).ok(),
            Some(vec![b[2].clone()])
        );
        assert!(blossom(&b, std::slice::from_ref(&t)).is_err());
        // Extrapolation.
        let (l2, _) = subdivide(&b, &q(3, 2));
        assert_eq!(eval(&l2, &q(1, 1)), eval(&b, &q(3, 2)));
    }

    #[test]
    fn derivative_matches_power_form() {
        let b = qs(&[1, 4, -2, 3, 0]);
        let d = derivative(&b);
        assert_eq!(from_bernstein(&d), from_bernstein(&b).derivative());
        assert_eq!(derivative(&qs(&[5])), qs(&[0]));
        assert!(derivative::<Rational>(&[]).is_empty());
    }

    #[test]
    fn blocks_act_componentwise() {
        // Two components interleaved: (1, 10), (2, 20), (4, 40).
        let b = qs(&[1, 10, 2, 20, 4, 40]);
        let t = q(1, 4);
        let v = eval_blocks(&b, 2, &t);
        assert_eq!(v[1], v[0].clone() * Rational::from(10));
        let e = elevate_blocks(&b, 2, 1);
        assert_eq!(e.len(), 8);
        assert_eq!(eval_blocks(&e, 2, &t), v);
        let p = from_bernstein_blocks(&b, 2);
        assert_eq!(to_bernstein_blocks(&p, 2, 2).ok(), Some(b.clone()));
        assert!(eval_blocks(&b, 0, &t).is_empty());
    }

    #[test]
    fn f64_agrees() {
        let b = [1.0, -2.0, 0.5, 3.0];
        let p = from_bernstein(&b);
        assert!((eval(&b, &0.3) - p.eval(&0.3)).abs() < 1e-14);
    }
}

#[cfg(test)]
mod fraction_free_tests {
    use super::*;
    use crate::rational::Rational;
    use crate::scalar::Scalar;

    /// The fraction-free product equals the rational one coefficient for coefficient, on
    /// factors with mixed denominators, zeros and signs, for several bidegrees.
    #[test]
    fn fraction_free_product_equals_the_rational_product() {
        let mut seed = 7u64;
        let mut next = || {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
            let p = ((seed >> 33) % 41) as i64 - 20;
            let q = ((seed >> 20) % 17) as i64 + 1;
            Rational::from_ratio(if p % 5 == 0 { 0 } else { p }, q)
        };
        for (da, db) in [
            ((1, 2), (3, 1)),
            ((0, 0), (2, 2)),
            ((3, 3), (3, 3)),
            ((6, 1), (0, 4)),
        ] {
            let a: Vec<Rational> = (0..(da.0 + 1) * (da.1 + 1)).map(|_| next()).collect();
            let b: Vec<Rational> = (0..(db.0 + 1) * (db.1 + 1)).map(|_| next()).collect();
            let slow = product_tensor(&a, da, &b, db).expect("slow");
            let fast = product_tensor_scalar(&a, da, &b, db).expect("fast");
            assert_eq!(slow, fast, "{da:?} × {db:?}");
            let af: Vec<f64> = a.iter().map(Scalar::to_f64).collect();
            let bf: Vec<f64> = b.iter().map(Scalar::to_f64).collect();
            let ff = product_tensor_scalar(&af, da, &bf, db).expect("f64");
            for (x, y) in slow.iter().zip(&ff) {
                assert!((Scalar::to_f64(x) - y).abs() <= 1e-12 * (1.0 + y.abs()));
            }
        }
        assert!(product_tensor_scalar(&[Rational::from(1)], (1, 0), &[], (0, 0)).is_err());
    }

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    /// `p(a + h s)`, `p(·, b + k t)` and the Bernstein forms in `ℚ` (the reference of the
    /// fraction-free `tensor_bernstein_scaled`).
    fn tensor_bernstein_rational(
        power: &[Rational],
        (m, n): (usize, usize),
        u: (&Rational, &Rational),
        v: (&Rational, &Rational),
    ) -> Vec<Rational> {
        let w = n + 1;
        let mut c = power.to_vec();
        let shift = |line: Vec<Rational>, (a, h): (&Rational, &Rational), deg: usize| {
            let s = Poly::new(line).compose(&Poly::new(vec![a.clone(), h.clone()]));
            (0..=deg)
                .map(|i| s.coeffs().get(i).cloned().unwrap_or(Rational::ZERO))
                .collect::<Vec<_>>()
        };
        for j in 0..=n {
            let col = shift((0..=m).map(|i| c[i * w + j].clone()).collect(), u, m);
            for (i, x) in col.into_iter().enumerate() {
                c[i * w + j] = x;
            }
        }
        for i in 0..=m {
            let row = shift(c[i * w..(i + 1) * w].to_vec(), v, n);
            c[i * w..(i + 1) * w].clone_from_slice(&row);
        }
        let mut rows = Vec::new();
        for row in c.chunks(w) {
            rows.extend(to_bernstein_blocks(row, 1, n).expect("degree n"));
        }
        to_bernstein_blocks(&rows, w, m).expect("degree m")
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// The fraction-free tensor Bernstein coefficients are one positive multiple of the
        /// rational ones (so the same signs), on random rectangles.
        #[test]
        fn scaled_tensor_bernstein_is_a_positive_multiple(
            m in 0usize..4,
            n in 0usize..4,
            raw in proptest::collection::vec((-9i64..10, 1i64..6), 16),
            u in (-5i64..6, 1i64..5, 1i64..7, 1i64..5),
            v in (-5i64..6, 1i64..5, 1i64..7, 1i64..5),
        ) {
            let power: Vec<Rational> = raw[..(m + 1) * (n + 1)].iter().map(|&(p, d)| q(p, d)).collect();
            let (u0, du) = (q(u.0, u.1), q(u.2, u.3));
            let (v0, dv) = (q(v.0, v.1), q(v.2, v.3));
            let got = tensor_bernstein_scaled(&power, (m, n), (&u0, &du), (&v0, &dv)).expect("lengths");
            let want = tensor_bernstein_rational(&power, (m, n), (&u0, &du), (&v0, &dv));
            proptest::prop_assert_eq!(got.len(), want.len());
            let lambda = got
                .iter()
                .zip(&want)
                .find(|(_, w)| !w.is_zero())
                .map(|(g, w)| Rational::from(g.clone()) / w.clone());
            match lambda {
                None => proptest::prop_assert!(got.iter().all(|g| g == &dashu_int::IBig::ZERO)),
                Some(l) => {
                    proptest::prop_assert!(l > Rational::ZERO);
                    for (g, w) in got.iter().zip(&want) {
                        proptest::prop_assert_eq!(Rational::from(g.clone()), l.clone() * w.clone());
                    }
                }
            }
        }

        /// At `t = 0` and `t = 1` the evaluation takes the end blocks; they are what the
        /// full de Casteljau scheme computes (in `Q` and in `f64`).
        #[test]
        fn end_points_are_the_end_blocks(
            width in 1usize..4,
            raw in proptest::collection::vec((-9i64..10, 1i64..6), 1..13),
        ) {
            let points = raw.len() / width;
            proptest::prop_assume!(points > 0);
            let b: Vec<Rational> = raw[..points * width].iter().map(|&(p, d)| q(p, d)).collect();
            let (zero, one) = (Rational::ZERO, Rational::ONE);
            proptest::prop_assert_eq!(eval_blocks(&b, width, &zero), eval_homogeneous_blocks(&b, width, &one, &zero));
            proptest::prop_assert_eq!(eval_blocks(&b, width, &one), eval_homogeneous_blocks(&b, width, &zero, &one));
            let f: Vec<f64> = b.iter().map(Scalar::to_f64).collect();
            proptest::prop_assert_eq!(eval_blocks(&f, width, &0.0), eval_homogeneous_blocks(&f, width, &1.0, &0.0));
            proptest::prop_assert_eq!(eval_blocks(&f, width, &1.0), eval_homogeneous_blocks(&f, width, &0.0, &1.0));
        }

        /// The fraction-free sign at a point is the sign of the rational value.
        #[test]
        fn tensor_sign_is_the_sign_of_the_value(
            m in 0usize..5,
            n in 0usize..4,
            raw in proptest::collection::vec((-9i64..10, 1i64..9), 20),
            at in (-9i64..10, 1i64..9, -9i64..10, 1i64..9),
        ) {
            let power: Vec<Rational> = raw[..(m + 1) * (n + 1)].iter().map(|&(p, d)| q(p, d)).collect();
            let (u, v) = (q(at.0, at.1), q(at.2, at.3));
            let mut value = Rational::ZERO;
            for i in 0..=m {
                for j in 0..=n {
                    value += power[i * (n + 1) + j].clone()
                        * crate::scalar::ring_pow(&u, i)
                        * crate::scalar::ring_pow(&v, j);
                }
            }
            let got = tensor_sign_at(&power, (m, n), &u, &v).expect("lengths");
            proptest::prop_assert_eq!(got, value.partial_cmp(&Rational::ZERO).expect("ordered"));
        }

        /// The exact tensor Bernstein coefficients (the scaled integers over their multiple
        /// `λ`) are those of the rational computation.
        #[test]
        fn exact_tensor_bernstein_is_the_rational_one(
            m in 0usize..5,
            n in 0usize..4,
            raw in proptest::collection::vec((-9i64..10, 1i64..9), 20),
            u in (-5i64..6, 1i64..9, 1i64..7, 1i64..9),
            v in (-5i64..6, 1i64..9, 1i64..7, 1i64..9),
        ) {
            let power: Vec<Rational> = raw[..(m + 1) * (n + 1)].iter().map(|&(p, d)| q(p, d)).collect();
            let (u0, du) = (q(u.0, u.1), q(u.2, u.3));
            let (v0, dv) = (q(v.0, v.1), q(v.2, v.3));
            let got = tensor_bernstein_exact(&power, (m, n), (&u0, &du), (&v0, &dv)).expect("lengths");
            let want = tensor_bernstein_rational(&power, (m, n), (&u0, &du), (&v0, &dv));
            proptest::prop_assert_eq!(got, want);
        }
    }
}
