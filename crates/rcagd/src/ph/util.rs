//! Private helpers of the PH module: 3-vectors of scalars and of polynomials,
//! quaternion and complex arithmetic on the public structs of `rcagd-algebra`,
//! square roots in a [`Scalar`], exact polynomial square roots, Gaussian elimination,
//! formatting and certificate helpers.
//!
//! (Some of these duplicate helpers that `rcagd-algebra` may grow; they are kept private
//! so that the lead can dedup them without touching the public API.)

use num_traits::{One, Zero};
use rcagd_algebra::complex::Complex;
use rcagd_algebra::quaternion::Quaternion;
pub(crate) use rcagd_algebra::{format_poly, format_scalar as fmt_scalar};
use rcagd_algebra::{Certificate, Poly, Ring, Scalar};

/// A 3-vector of scalars.
pub(crate) type V3<F> = [F; 3];
/// A 3-vector of polynomials (a polynomial space curve or hodograph).
pub(crate) type PV3<F> = [Poly<F>; 3];

// ------------------------------------------------------------------ scalars

/// `C(n, k)` in `F`.
/// [`PhError::NonFinite`] naming `what` when an `f64` intermediate is not finite (an
/// overflow of the floating-point path); always `Ok` for exact scalars.
///
/// # Errors
/// [`PhError::NonFinite`] for a non-finite value among `values`.
pub(crate) fn check_finite<'a, F: Scalar + 'a>(
    what: impl FnOnce() -> String,
    values: impl IntoIterator<Item = &'a F>,
) -> Result<(), super::PhError> {
    if F::EXACT || values.into_iter().all(|x| x.to_f64().is_finite()) {
        Ok(())
    } else {
        Err(super::PhError::NonFinite { what: what() })
    }
}

pub(crate) fn binom<F: Scalar>(n: usize, k: usize) -> F {
    if k > n {
        return F::zero();
    }
    let mut acc = F::one();
    for i in 0..k {
        acc = acc * F::from_i64((n - i) as i64) / F::from_i64((i + 1) as i64);
    }
    acc
}

pub(crate) use rcagd_algebra::sqrt_in_field as sqrt_scalar;

/// Formats a 3-vector.
pub(crate) fn fmt_v3<F: Scalar>(v: &V3<F>) -> String {
    format!(
        "({}, {}, {})",
        fmt_scalar(&v[0]),
        fmt_scalar(&v[1]),
        fmt_scalar(&v[2])
    )
}

/// Relative tolerance of the `f64` certificates.
pub(crate) const F64_TOL: f64 = 1e-8;

/// `true` if `x` is zero: exactly for exact scalars, `|x| ≤ tol·max(scale, 1)` for `f64`.
pub(crate) fn is_negligible<F: Scalar>(x: &F, scale: f64) -> bool {
    if F::EXACT {
        x.is_zero()
    } else {
        x.to_f64().abs() <= F64_TOL * scale.max(1.0)
    }
}

/// Largest absolute coefficient of a polynomial, as `f64`.
pub(crate) fn poly_scale<F: Scalar>(p: &Poly<F>) -> f64 {
    p.coeffs()
        .iter()
        .map(|c| c.to_f64().abs())
        .fold(0.0, f64::max)
}

/// `true` if the polynomial is (negligibly, for `f64`) zero relative to `scale`.
pub(crate) fn poly_negligible<F: Scalar>(p: &Poly<F>, scale: f64) -> bool {
    p.coeffs().iter().all(|c| is_negligible(c, scale))
}

/// A certificate for the polynomial identity `lhs ≡ rhs` (`property` names it).
pub(crate) fn identity_cert<F: Scalar>(
    property: impl Into<String>,
    lhs: &Poly<F>,
    rhs: &Poly<F>,
) -> Certificate {
    let diff = lhs - rhs;
    let scale = poly_scale(lhs).max(poly_scale(rhs));
    Certificate::decide(property, poly_negligible(&diff, scale), F::EXACT, || {
        format!("residual polynomial {}", format_poly(&diff, "t"))
    })
}

/// A certificate for the polynomial identity `lhs ≡ rhs`; for `f64`, coefficient `k` of
/// the residual is compared with [`F64_TOL`]` · magnitude[k]` (a bound of the sum of the
/// absolute values of the terms that make up that coefficient) instead of the largest
/// coefficient. Exact scalars need the residual to vanish.
pub(crate) fn identity_cert_within<F: Scalar>(
    property: impl Into<String>,
    lhs: &Poly<F>,
    rhs: &Poly<F>,
    magnitude: &[f64],
) -> Certificate {
    let diff = lhs - rhs;
    let ok = diff.coeffs().iter().enumerate().all(|(k, c)| {
        if F::EXACT {
            c.is_zero()
        } else {
            let v = c.to_f64().abs();
            v.is_finite() && v <= F64_TOL * magnitude.get(k).copied().unwrap_or(0.0)
        }
    });
    Certificate::decide(property, ok, F::EXACT, || {
        format!("residual polynomial {}", format_poly(&diff, "t"))
    })
}

/// The coefficients of `p` by absolute value, in `f64`: the magnitude polynomial of `p`
/// for [`identity_cert_within`] (products and sums of magnitude polynomials bound the
/// terms that make up each coefficient of the corresponding products and sums).
pub(crate) fn abs_poly<F: Scalar>(p: &Poly<F>) -> Poly<f64> {
    p.map(|c| c.to_f64().abs())
}

/// A certificate for the scalar identity `lhs = rhs`.
pub(crate) fn scalar_cert<F: Scalar>(property: impl Into<String>, lhs: &F, rhs: &F) -> Certificate {
    let diff = lhs.clone() - rhs.clone();
    let scale = lhs.to_f64().abs().max(rhs.to_f64().abs());
    Certificate::decide(property, is_negligible(&diff, scale), F::EXACT, || {
        format!("residual {}", fmt_scalar(&diff))
    })
}

/// A certificate for the vector identity `lhs = rhs`.
pub(crate) fn v3_cert<F: Scalar>(
    property: impl Into<String>,
    lhs: &V3<F>,
    rhs: &V3<F>,
) -> Certificate {
    let diff = sub3(lhs, rhs);
    let scale = (0..3)
        .map(|i| lhs[i].to_f64().abs().max(rhs[i].to_f64().abs()))
        .fold(0.0, f64::max);
    let ok = diff.iter().all(|d| is_negligible(d, scale));
    Certificate::decide(property, ok, F::EXACT, || {
        format!("residual {}", fmt_v3(&diff))
    })
}

// ------------------------------------------------------------------ 3-vectors

pub(crate) fn zero3<F: Scalar>() -> V3<F> {
    [F::zero(), F::zero(), F::zero()]
}
pub(crate) fn add3<F: Ring>(a: &V3<F>, b: &V3<F>) -> V3<F> {
    [
        a[0].clone() + b[0].clone(),
        a[1].clone() + b[1].clone(),
        a[2].clone() + b[2].clone(),
    ]
}
pub(crate) fn sub3<F: Scalar>(a: &V3<F>, b: &V3<F>) -> V3<F> {
    [
        a[0].clone() - b[0].clone(),
        a[1].clone() - b[1].clone(),
        a[2].clone() - b[2].clone(),
    ]
}
pub(crate) fn scale3<F: Ring>(a: &V3<F>, c: &F) -> V3<F> {
    [
        a[0].clone() * c.clone(),
        a[1].clone() * c.clone(),
        a[2].clone() * c.clone(),
    ]
}
pub(crate) fn dot3<F: Scalar>(a: &V3<F>, b: &V3<F>) -> F {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
}
pub(crate) fn cross3<F: Scalar>(a: &V3<F>, b: &V3<F>) -> V3<F> {
    [
        a[1].clone() * b[2].clone() - a[2].clone() * b[1].clone(),
        a[2].clone() * b[0].clone() - a[0].clone() * b[2].clone(),
        a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone(),
    ]
}
/// The determinant `[a, b, c] = a · (b × c)`.
pub(crate) fn det3<F: Scalar>(a: &V3<F>, b: &V3<F>, c: &V3<F>) -> F {
    dot3(a, &cross3(b, c))
}
pub(crate) fn is_zero3<F: Scalar>(a: &V3<F>) -> bool {
    a.iter().all(|x| x.is_zero())
}
pub(crate) fn to_f64_3<F: Scalar>(a: &V3<F>) -> [f64; 3] {
    [a[0].to_f64(), a[1].to_f64(), a[2].to_f64()]
}

// ------------------------------------------------------------------ polynomial 3-vectors

pub(crate) fn pdot<F: Scalar>(a: &PV3<F>, b: &PV3<F>) -> Poly<F> {
    &(&(&a[0] * &b[0]) + &(&a[1] * &b[1])) + &(&a[2] * &b[2])
}
pub(crate) fn pcross<F: Scalar>(a: &PV3<F>, b: &PV3<F>) -> PV3<F> {
    [
        &(&a[1] * &b[2]) - &(&a[2] * &b[1]),
        &(&a[2] * &b[0]) - &(&a[0] * &b[2]),
        &(&a[0] * &b[1]) - &(&a[1] * &b[0]),
    ]
}
pub(crate) fn pderiv<F: Scalar>(a: &PV3<F>) -> PV3<F> {
    [a[0].derivative(), a[1].derivative(), a[2].derivative()]
}
pub(crate) fn peval<F: Scalar>(a: &PV3<F>, t: &F) -> V3<F> {
    [a[0].eval(t), a[1].eval(t), a[2].eval(t)]
}
/// `Σ aᵢ · pᵢ` for a constant vector `a`.
pub(crate) fn pdot_const<F: Scalar>(a: &V3<F>, p: &PV3<F>) -> Poly<F> {
    &(&p[0].scale(&a[0]) + &p[1].scale(&a[1])) + &p[2].scale(&a[2])
}
pub(crate) fn pscale_poly<F: Scalar>(a: &PV3<F>, s: &Poly<F>) -> PV3<F> {
    [&a[0] * s, &a[1] * s, &a[2] * s]
}
pub(crate) fn psub<F: Scalar>(a: &PV3<F>, b: &PV3<F>) -> PV3<F> {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

/// `∫₀ᵗ p`.
pub(crate) fn integrate<F: Scalar>(p: &Poly<F>) -> Poly<F> {
    let mut c = vec![F::zero()];
    c.extend(
        p.coeffs()
            .iter()
            .enumerate()
            .map(|(k, a)| a.clone() / F::from_i64(k as i64 + 1)),
    );
    Poly::new(c)
}

/// Maps a polynomial to `f64`.
pub(crate) fn poly_f64<F: Scalar>(p: &Poly<F>) -> Poly<f64> {
    p.map(|c| c.to_f64())
}

/// The exact rational coefficients of a polynomial (`None` for a non-finite `f64`).
pub(crate) fn poly_rational<F: Scalar>(p: &Poly<F>) -> Option<Poly<rcagd_algebra::Rational>> {
    let c = p
        .coeffs()
        .iter()
        .map(|c| c.to_rational())
        .collect::<Option<Vec<_>>>()?;
    Some(Poly::new(c))
}

// ------------------------------------------------------------------ polynomial square roots

/// The square root with positive leading coefficient of a polynomial, if `p` is the
/// square of a polynomial over `F` (exactly; within [`F64_TOL`] for `f64`).
/// The zero polynomial is its own root.
pub(crate) fn poly_sqrt<F: Scalar>(p: &Poly<F>) -> Option<Poly<F>> {
    let Some(deg) = p.degree() else {
        return Some(Poly::zero());
    };
    if deg % 2 == 1 {
        return None;
    }
    let lc = sqrt_scalar(&p.leading())?;
    let monic = monic_sqrt(&p.scale(&(F::one() / p.leading())))?;
    let r = monic.scale(&lc);
    let check = &(&r * &r) - p;
    if poly_negligible(&check, poly_scale(p)) {
        Some(r)
    } else {
        None
    }
}

/// For a monic polynomial `p` of even degree `2d`, the monic `r` of degree `d` whose
/// square agrees with `p` in the top `d + 1` coefficients (no check that `r² = p`).
pub(crate) fn monic_sqrt<F: Scalar>(p: &Poly<F>) -> Option<Poly<F>> {
    let deg = p.degree()?;
    if deg % 2 == 1 {
        return None;
    }
    let d = deg / 2;
    // r = Σ r_k t^k, r_d = 1; coefficient of t^{2d-j}: 2 r_d r_{d-j} + Σ_{i+k = 2d-j, i,k in (d-j, d)} r_i r_k
    let mut r = vec![F::zero(); d + 1];
    r[d] = F::one();
    let two = F::from_i64(2);
    for j in 1..=d {
        let target = p.coeff(2 * d - j);
        let mut s = F::zero();
        for i in (d - j + 1)..=d {
            let k = 2 * d - j - i;
            if k > d - j && k <= d {
                s += r[i].clone() * r[k].clone();
            }
        }
        r[d - j] = (target - s) / two.clone();
    }
    Some(Poly::new(r))
}

/// `p = c·ω̃²` with `ω̃` monic and `c` the leading coefficient of `p`, if the monic
/// associate of `p` is a perfect square. For a rational square `c`, the factor is
/// absorbed: `c = 1`, `ω̃ = √c·ω̃`.
pub(crate) fn scaled_square<F: Scalar>(p: &Poly<F>, noise: f64) -> Option<(F, Poly<F>)> {
    // f64: leading coefficients at the round-off level `noise` are dropped first
    let p = if F::EXACT {
        p.clone()
    } else {
        let mut c = p.coeffs().to_vec();
        while c.last().is_some_and(|x| x.to_f64().abs() <= noise) {
            c.pop();
        }
        Poly::new(c)
    };
    let deg = p.degree()?;
    if deg % 2 == 1 || p.leading() < F::zero() {
        return None;
    }
    let lc = p.leading();
    let monic = p.scale(&(F::one() / lc.clone()));
    let r = monic_sqrt(&monic)?;
    if !F::EXACT {
        // the top-down recursion is unstable when the low coefficients dominate: polish
        // r·√lc by Gauss–Newton on r² = p (normal equations), then check
        let s = sqrt_scalar(&lc)?;
        let mut rs = r.scale(&s);
        let d = rs.degree().unwrap_or(0);
        for _ in 0..4 {
            let res = p.clone() - &rs * &rs;
            let jac: Vec<Vec<F>> = (0..=2 * d)
                .map(|i| {
                    (0..=d)
                        .map(|j| {
                            if i >= j {
                                F::from_i64(2) * rs.coeff(i - j)
                            } else {
                                F::zero()
                            }
                        })
                        .collect()
                })
                .collect();
            let jtj: Vec<Vec<F>> = (0..=d)
                .map(|a| {
                    (0..=d)
                        .map(|b| {
                            jac.iter()
                                .fold(F::zero(), |acc, row| acc + row[a].clone() * row[b].clone())
                        })
                        .collect()
                })
                .collect();
            let jtr: Vec<F> = (0..=d)
                .map(|a| {
                    jac.iter().enumerate().fold(F::zero(), |acc, (i, row)| {
                        acc + row[a].clone() * res.coeff(i)
                    })
                })
                .collect();
            let Some((delta, _)) = solve_linear(&jtj, &jtr, d + 1) else {
                break;
            };
            rs += Poly::new(delta);
        }
        let check = p.clone() - &rs * &rs;
        let ok = check
            .coeffs()
            .iter()
            .all(|c| c.to_f64().abs() <= noise + F64_TOL * poly_scale(&p));
        return if ok { Some((F::one(), rs)) } else { None };
    }
    let check = &(&(&r * &r) - &monic).scale(&lc);
    let ok = if F::EXACT {
        check.is_zero()
    } else {
        check
            .coeffs()
            .iter()
            .all(|c| c.to_f64().abs() <= noise + F64_TOL * poly_scale(&p))
    };
    if !ok {
        return None;
    }
    match sqrt_scalar(&lc) {
        Some(s) => Some((F::one(), r.scale(&s))),
        None => Some((lc, r)),
    }
}

// ------------------------------------------------------------------ quaternions

pub(crate) fn quat<F: Scalar>(w: F, x: F, y: F, z: F) -> Quaternion<F> {
    Quaternion { w, x, y, z }
}
pub(crate) fn qmul<F: Scalar>(a: &Quaternion<F>, b: &Quaternion<F>) -> Quaternion<F> {
    let (a0, a1, a2, a3) = (a.w.clone(), a.x.clone(), a.y.clone(), a.z.clone());
    let (b0, b1, b2, b3) = (b.w.clone(), b.x.clone(), b.y.clone(), b.z.clone());
    quat(
        a0.clone() * b0.clone()
            - a1.clone() * b1.clone()
            - a2.clone() * b2.clone()
            - a3.clone() * b3.clone(),
        a0.clone() * b1.clone() + b0.clone() * a1.clone() + a2.clone() * b3.clone()
            - a3.clone() * b2.clone(),
        a0.clone() * b2.clone() + b0.clone() * a2.clone() + a3.clone() * b1.clone()
            - a1.clone() * b3.clone(),
        a0 * b3 + b0 * a3 + a1 * b2 - a2 * b1,
    )
}
pub(crate) fn qconj<F: Scalar>(a: &Quaternion<F>) -> Quaternion<F> {
    quat(a.w.clone(), -a.x.clone(), -a.y.clone(), -a.z.clone())
}
pub(crate) fn qadd<F: Scalar>(a: &Quaternion<F>, b: &Quaternion<F>) -> Quaternion<F> {
    quat(
        a.w.clone() + b.w.clone(),
        a.x.clone() + b.x.clone(),
        a.y.clone() + b.y.clone(),
        a.z.clone() + b.z.clone(),
    )
}
pub(crate) fn qsub<F: Scalar>(a: &Quaternion<F>, b: &Quaternion<F>) -> Quaternion<F> {
    quat(
        a.w.clone() - b.w.clone(),
        a.x.clone() - b.x.clone(),
        a.y.clone() - b.y.clone(),
        a.z.clone() - b.z.clone(),
    )
}
pub(crate) fn qscale<F: Scalar>(a: &Quaternion<F>, c: &F) -> Quaternion<F> {
    quat(
        a.w.clone() * c.clone(),
        a.x.clone() * c.clone(),
        a.y.clone() * c.clone(),
        a.z.clone() * c.clone(),
    )
}
pub(crate) fn qis_zero<F: Scalar>(a: &Quaternion<F>) -> bool {
    a.w.is_zero() && a.x.is_zero() && a.y.is_zero() && a.z.is_zero()
}
pub(crate) fn qvec<F: Scalar>(a: &Quaternion<F>) -> V3<F> {
    [a.x.clone(), a.y.clone(), a.z.clone()]
}
/// The unit quaternions `1, i, j, k` by index `0..4`.
pub(crate) fn qunit<F: Scalar>(idx: usize) -> Quaternion<F> {
    let mut c = [F::zero(), F::zero(), F::zero(), F::zero()];
    if let Some(x) = c.get_mut(idx) {
        *x = F::one();
    }
    let [w, x, y, z] = c;
    quat(w, x, y, z)
}
/// `A e B*` for a unit `e ∈ {1, i, j, k}` (index `0..4`).
pub(crate) fn sandwich<F: Scalar>(a: &Quaternion<F>, e: usize, b: &Quaternion<F>) -> Quaternion<F> {
    qmul(&qmul(a, &qunit(e)), &qconj(b))
}
pub(crate) fn qmap<F: Scalar, G: Scalar>(a: &Quaternion<F>, f: impl Fn(&F) -> G) -> Quaternion<G> {
    quat(f(&a.w), f(&a.x), f(&a.y), f(&a.z))
}
pub(crate) fn qcomponents<F: Scalar>(a: &Quaternion<F>) -> [F; 4] {
    [a.w.clone(), a.x.clone(), a.y.clone(), a.z.clone()]
}

// ------------------------------------------------------------------ complex helpers

pub(crate) fn cx<F: Scalar>(re: F, im: F) -> Complex<F> {
    Complex { re, im }
}
pub(crate) fn cmul<F: Scalar>(a: &Complex<F>, b: &Complex<F>) -> Complex<F> {
    cx(
        a.re.clone() * b.re.clone() - a.im.clone() * b.im.clone(),
        a.re.clone() * b.im.clone() + a.im.clone() * b.re.clone(),
    )
}
pub(crate) fn cadd<F: Scalar>(a: &Complex<F>, b: &Complex<F>) -> Complex<F> {
    cx(a.re.clone() + b.re.clone(), a.im.clone() + b.im.clone())
}
pub(crate) fn csub<F: Scalar>(a: &Complex<F>, b: &Complex<F>) -> Complex<F> {
    cx(a.re.clone() - b.re.clone(), a.im.clone() - b.im.clone())
}
pub(crate) fn cscale<F: Scalar>(a: &Complex<F>, c: &F) -> Complex<F> {
    cx(a.re.clone() * c.clone(), a.im.clone() * c.clone())
}
pub(crate) fn cnorm_sq<F: Scalar>(a: &Complex<F>) -> F {
    a.re.clone() * a.re.clone() + a.im.clone() * a.im.clone()
}
pub(crate) fn cis_zero<F: Scalar>(a: &Complex<F>) -> bool {
    a.re.is_zero() && a.im.is_zero()
}
/// `a / b`, `None` for `b = 0`.
pub(crate) fn cdiv<F: Scalar>(a: &Complex<F>, b: &Complex<F>) -> Option<Complex<F>> {
    let n = cnorm_sq(b);
    if n.is_zero() {
        return None;
    }
    let num = cmul(a, &cx(b.re.clone(), -b.im.clone()));
    Some(cx(num.re / n.clone(), num.im / n))
}
pub(crate) fn fmt_complex<F: Scalar>(a: &Complex<F>) -> String {
    format!("{} + {}i", fmt_scalar(&a.re), fmt_scalar(&a.im))
}
/// `√z` in `F(i)` if it exists there (exact Gaussian-rational roots; `f64` always).
/// The root with non-negative real part (and non-negative imaginary part on the
/// negative real axis) is returned.
pub(crate) fn csqrt<F: Scalar>(z: &Complex<F>) -> Option<Complex<F>> {
    let n = sqrt_scalar(&cnorm_sq(z))?;
    let two = F::from_i64(2);
    let x2 = (n.clone() + z.re.clone()) / two.clone();
    let y2 = (n - z.re.clone()) / two.clone();
    let x = sqrt_scalar(&x2)?;
    let mut y = sqrt_scalar(&y2)?;
    if z.im < F::zero() {
        y = -y;
    }
    // 2xy must equal Im z (fails only if x = 0 and the root is purely imaginary: fine)
    Some(cx(x, y))
}

// ------------------------------------------------------------------ linear algebra

/// Solves `M x = b` (rows of `M`, any number of rows ≥ columns) by Gaussian elimination
/// with exact pivoting for exact scalars (largest pivot for `f64`).
/// Returns the particular solution (free variables set to zero) and a basis of the null
/// space, or `None` if the system is inconsistent.
#[allow(clippy::type_complexity)]
pub(crate) fn solve_linear<F: Scalar>(
    m: &[Vec<F>],
    b: &[F],
    cols: usize,
) -> Option<(Vec<F>, Vec<Vec<F>>)> {
    let rows = m.len();
    let mut a: Vec<Vec<F>> = m
        .iter()
        .zip(b)
        .map(|(r, bi)| {
            let mut row: Vec<F> = (0..cols)
                .map(|j| r.get(j).cloned().unwrap_or_else(F::zero))
                .collect();
            row.push(bi.clone());
            row
        })
        .collect();
    let scale = a
        .iter()
        .flat_map(|r| r.iter())
        .map(|x| x.to_f64().abs())
        .fold(0.0, f64::max);
    let mut pivots = Vec::new();
    let mut r = 0;
    for c in 0..cols {
        if r >= rows {
            break;
        }
        // choose pivot
        let mut best: Option<usize> = None;
        for i in r..rows {
            if is_negligible(&a[i][c], scale) {
                continue;
            }
            match best {
                None => best = Some(i),
                Some(bi) => {
                    if !F::EXACT && a[i][c].to_f64().abs() > a[bi][c].to_f64().abs() {
                        best = Some(i)
                    }
                }
            }
        }
        let Some(p) = best else { continue };
        a.swap(r, p);
        let inv = F::one() / a[r][c].clone();
        for x in a[r].iter_mut() {
            *x = x.clone() * inv.clone();
        }
        let pivot_row = a[r].clone();
        for (i, row) in a.iter_mut().enumerate() {
            if i != r && !row[c].is_zero() {
                let f = row[c].clone();
                for (x, p) in row.iter_mut().zip(&pivot_row) {
                    *x -= p.clone() * f.clone();
                }
            }
        }
        pivots.push(c);
        r += 1;
    }
    // consistency
    for row in a.iter().skip(r) {
        if !is_negligible(&row[cols], scale) {
            return None;
        }
    }
    let mut x = vec![F::zero(); cols];
    for (i, &c) in pivots.iter().enumerate() {
        x[c] = a[i][cols].clone();
    }
    let free: Vec<usize> = (0..cols).filter(|c| !pivots.contains(c)).collect();
    let null = free
        .iter()
        .map(|&f| {
            let mut v = vec![F::zero(); cols];
            v[f] = F::one();
            for (i, &c) in pivots.iter().enumerate() {
                v[c] = -a[i][f].clone();
            }
            v
        })
        .collect();
    Some((x, null))
}

/// Monic gcd; for `f64` Euclid's algorithm with remainders below a relative tolerance
/// treated as zero (exact Euclid for exact scalars).
pub(crate) fn gcd_tol<F: Scalar>(a: &Poly<F>, b: &Poly<F>) -> Poly<F> {
    if F::EXACT {
        return a.gcd(b);
    }
    let mut x = a.monic();
    let mut y = b.monic();
    if x.is_zero() {
        return y;
    }
    for _ in 0..64 {
        if y.is_zero() {
            return x.monic();
        }
        let Ok((_, r)) = x.div_rem(&y) else {
            return x.monic();
        };
        let scale = poly_scale(&x).max(poly_scale(&y));
        let tiny = r
            .coeffs()
            .iter()
            .all(|c| c.to_f64().abs() <= 1e-7 * scale.max(1.0));
        x = y;
        y = if tiny { Poly::zero() } else { r.monic() };
    }
    x.monic()
}

/// Complex polynomial from Bernstein coefficients (power form).
pub(crate) fn cpoly_from_bernstein<F: Scalar>(b: &[Complex<F>]) -> Poly<Complex<F>> {
    rcagd_algebra::bernstein::from_bernstein(b)
}

/// `true` if every coefficient of a complex polynomial is negligible relative to `scale`.
pub(crate) fn cpoly_negligible<F: Scalar>(p: &Poly<Complex<F>>, scale: f64) -> bool {
    p.coeffs()
        .iter()
        .all(|c| is_negligible(&c.re, scale) && is_negligible(&c.im, scale))
}

/// Largest absolute real or imaginary part of the coefficients.
pub(crate) fn cpoly_scale<F: Scalar>(p: &Poly<Complex<F>>) -> f64 {
    p.coeffs()
        .iter()
        .map(|c| c.re.to_f64().abs().max(c.im.to_f64().abs()))
        .fold(0.0, f64::max)
}

/// The monic square root of a monic complex polynomial of even degree, if it is a
/// perfect square (exact; within tolerance for `f64`).
pub(crate) fn cpoly_monic_sqrt<F: Scalar>(p: &Poly<Complex<F>>) -> Option<Poly<Complex<F>>> {
    let deg = p.degree()?;
    if deg % 2 == 1 {
        return None;
    }
    let d = deg / 2;
    let mut r = vec![Complex::<F>::zero(); d + 1];
    r[d] = Complex::one();
    let half = F::one() / F::from_i64(2);
    for j in 1..=d {
        let target = p.coeff(2 * d - j);
        let mut s = Complex::<F>::zero();
        for i in (d - j + 1)..=d {
            let k = 2 * d - j - i;
            if k > d - j && k <= d {
                s = cadd(&s, &cmul(&r[i], &r[k]));
            }
        }
        r[d - j] = cscale(&csub(&target, &s), &half);
    }
    let root = Poly::new(r);
    let check = &(&root * &root) - p;
    if cpoly_negligible(&check, cpoly_scale(p)) {
        Some(root)
    } else {
        None
    }
}

/// For `f64`, drops leading coefficients that are round-off noise (`≤ 1e-9·max|cᵢ|`);
/// exact polynomials are returned unchanged.
pub(crate) fn trim_noise<F: Scalar>(p: Poly<F>) -> Poly<F> {
    if F::EXACT {
        return p;
    }
    let scale = poly_scale(&p);
    let mut c = p.into_coeffs();
    while c.last().is_some_and(|x| x.to_f64().abs() <= 1e-9 * scale) {
        c.pop();
    }
    Poly::new(c)
}

/// The result of a solver that is exact when every square root it meets is rational and
/// falls back to `f64` otherwise (the PH Hermite solvers' `solve_auto`): the exact solution
/// `E` or the floating-point one `F`, said in the type, never silently.
#[derive(Debug, Clone, PartialEq)]
pub enum ExactOrFloat<E, F> {
    /// Every square root was rational: the exact solution.
    Exact(Box<E>),
    /// Some square root was irrational: solved in `f64`.
    Float(Box<F>),
}

impl<E: crate::Certified, F: crate::Certified> ExactOrFloat<E, F> {
    /// `true` for an exact solution.
    pub fn is_exact(&self) -> bool {
        matches!(self, ExactOrFloat::Exact(_))
    }

    /// The certificates of the solution.
    pub fn certify(&self) -> Vec<Certificate> {
        match self {
            ExactOrFloat::Exact(s) => s.certify(),
            ExactOrFloat::Float(s) => s.certify(),
        }
    }
}

/// The preconditions of a first-order Hermite problem (planar or spatial): non-zero end
/// derivatives, distinct end points, finite data.
pub(crate) fn check_hermite_ends<F: Scalar>(
    p0: &[F],
    d0: &[F],
    p1: &[F],
    d1: &[F],
) -> Result<(), super::PhError> {
    use super::PhError;
    if d0.iter().all(|x| x.is_zero()) {
        return Err(PhError::ZeroTangent(
            "the start derivative d0 is zero".into(),
        ));
    }
    if d1.iter().all(|x| x.is_zero()) {
        return Err(PhError::ZeroTangent("the end derivative d1 is zero".into()));
    }
    if p0 == p1 {
        return Err(PhError::CoincidentEndPoints(
            "p0 = p1: the Hermite problem needs distinct end points".into(),
        ));
    }
    if [p0, d0, p1, d1]
        .iter()
        .any(|v| v.iter().any(|x| !x.to_f64().is_finite()))
    {
        return Err(PhError::OutOfRange("non-finite Hermite data".into()));
    }
    Ok(())
}

/// `a i b*` (the quaternion product of the PH hodograph `r′ = A i A*`).
pub(crate) fn aib<F: Scalar>(
    a: &rcagd_algebra::Quaternion<F>,
    b: &rcagd_algebra::Quaternion<F>,
) -> rcagd_algebra::Quaternion<F> {
    a.clone() * rcagd_algebra::Quaternion::i() * b.conj()
}
