//! Fast `f64` evaluation of rational Bézier curves and patches, one point or whole grids.
//!
//! This is the speed path next to the exact (generic) evaluation: everything here is
//! plain `f64` arithmetic on the homogeneous control points.
//!
//! # Formulas
//!
//! * Bernstein values `Bᵢⁿ(t) = C(n,i) (1−t)ⁿ⁻ⁱ tⁱ` are computed with the triangular
//!   scheme of *The NURBS Book* (Piegl & Tiller, 2nd ed.), **A1.3 AllBernstein**:
//!   `Bᵢʲ = (1−t) Bᵢʲ⁻¹ + t Bᵢ₋₁ʲ⁻¹`, which only forms convex combinations and is
//!   stable on `[0, 1]`. Their derivatives are `d/dt Bᵢⁿ = n (Bᵢ₋₁ⁿ⁻¹ − Bᵢⁿ⁻¹)`
//!   (NURBS Book (1.9)).
//! * A curve is `P(t) = Σᵢ Bᵢⁿ(t) Pᵢ` in homogeneous coordinates `(w, wx, …)`; the
//!   Euclidean point is `x = P₁..d / P₀` and its derivative is
//!   `x' = (P'₁..d − P'₀ x) / P₀` (quotient rule, NURBS Book (4.8)).
//! * A patch `P(u, v) = Σᵢ Σⱼ Bᵢᵐ(u) Bⱼⁿ(v) Pᵢⱼ` is evaluated on a grid `us × vs` by
//!   collapsing the net along `u` **once per grid row**:
//!   `Qⱼ(u) = Σᵢ Bᵢᵐ(u) Pᵢⱼ` (homogeneous, `n + 1` points), and then for every `v` a
//!   short dot product `P(u, v) = Σⱼ Bⱼⁿ(v) Qⱼ(u)` and one reciprocal `1 / P₀`. The
//!   Bernstein values of every `u` and every `v` are computed once per call. Per grid
//!   point this costs `(n + 1)(d + 1)` multiply-adds instead of the `(m + 1)(n + 1)(d + 1)`
//!   of the naive tensor loop. Partial derivatives use
//!   `∂ᵤP = Σⱼ Bⱼⁿ(v) Q'ⱼ(u)`, `∂ᵥP = Σⱼ (Bⱼⁿ)'(v) Qⱼ(u)` and the quotient rule above;
//!   normals are `∂ᵤx × ∂ᵥx`, normalised.
//!
//! Grids are returned row-major in `u`: the point for `(us[i], vs[j])` is
//! `out[i · vs.len() + j]`. Parameters outside `[0, 1]` extrapolate the polynomial; a
//! zero weight (a point at infinity) yields infinite or NaN coordinates, never a panic.
//! For `v`-degrees 1 to 7 of 3-D patches the inner loop is instantiated for the fixed
//! size (const generics), so it is fully unrolled and allocation free.

use crate::curve::BezierCurve;
use crate::error::GeomError;
use crate::patch::BezierPatch;

/// Fills `b[..=n]` with `Bᵢⁿ(t)` (NURBS Book A1.3 AllBernstein). `b.len() > n` is an
/// internal invariant of every caller.
#[inline]
fn bernstein_into(n: usize, t: f64, b: &mut [f64]) {
    let s = 1.0 - t;
    b[0] = 1.0;
    for j in 1..=n {
        let mut saved = 0.0;
        for bk in b.iter_mut().take(j) {
            let temp = *bk;
            *bk = saved + s * temp;
            saved = t * temp;
        }
        b[j] = saved;
    }
}

/// Fills `b[..=n]` with `Bᵢⁿ(t)` and `db[..=n]` with their derivatives
/// `n (Bᵢ₋₁ⁿ⁻¹(t) − Bᵢⁿ⁻¹(t))` (terms with out-of-range indices are zero).
#[inline]
fn bernstein_with_derivative_into(n: usize, t: f64, b: &mut [f64], db: &mut [f64]) {
    if n == 0 {
        b[0] = 1.0;
        db[0] = 0.0;
        return;
    }
    bernstein_into(n - 1, t, b);
    let nf = n as f64;
    for i in 0..=n {
        let prev = if i > 0 { b[i - 1] } else { 0.0 };
        let cur = if i < n { b[i] } else { 0.0 };
        db[i] = nf * (prev - cur);
    }
    // one more step of A1.3 raises b from degree n − 1 to n
    let s = 1.0 - t;
    let mut saved = 0.0;
    for bk in b.iter_mut().take(n) {
        let temp = *bk;
        *bk = saved + s * temp;
        saved = t * temp;
    }
    b[n] = saved;
}

/// The Bernstein values `B₀ⁿ(t), …, Bₙⁿ(t)` (NURBS Book A1.3).
pub fn bernstein_values(n: usize, t: f64) -> Vec<f64> {
    let mut b = vec![0.0; n + 1];
    bernstein_into(n, t, &mut b);
    b
}

/// The derivatives `d/dt Bᵢⁿ(t) = n (Bᵢ₋₁ⁿ⁻¹(t) − Bᵢⁿ⁻¹(t))`, `i = 0..=n`.
pub fn bernstein_derivatives(n: usize, t: f64) -> Vec<f64> {
    let mut b = vec![0.0; n + 1];
    let mut db = vec![0.0; n + 1];
    bernstein_with_derivative_into(n, t, &mut b, &mut db);
    db
}

/// `Σᵢ bᵢ Pᵢ` over flat homogeneous points of stride `s`, into `acc[..s]` (overwritten).
#[inline]
fn combine(points: &[f64], s: usize, b: &[f64], acc: &mut [f64]) {
    acc.iter_mut().for_each(|a| *a = 0.0);
    for (p, &bi) in points.chunks_exact(s).zip(b) {
        for (a, &c) in acc.iter_mut().zip(p) {
            *a += bi * c;
        }
    }
}

/// The homogeneous point `P(t) = Σᵢ Bᵢⁿ(t) Pᵢ` (length `dim + 1`, weight first).
pub fn eval_curve_homogeneous_f64(curve: &BezierCurve<f64>, t: f64) -> Vec<f64> {
    let s = curve.dim() + 1;
    let b = bernstein_values(curve.degree(), t);
    let mut acc = vec![0.0; s];
    combine(curve.coords(), s, &b, &mut acc);
    acc
}

/// The Euclidean point `x(t) = P₁..d(t) / P₀(t)` of a rational Bézier curve (length
/// `dim`). A zero weight gives non-finite coordinates.
pub fn eval_curve_f64(curve: &BezierCurve<f64>, t: f64) -> Vec<f64> {
    let h = eval_curve_homogeneous_f64(curve, t);
    let r = 1.0 / h[0];
    h[1..].iter().map(|c| c * r).collect()
}

/// The Euclidean point and first derivative `(x(t), x'(t))` of a rational Bézier curve,
/// `x' = (P'₁..d − P'₀ x) / P₀` with `P' = Σᵢ (Bᵢⁿ)' Pᵢ` (NURBS Book (4.8)).
pub fn eval_curve_derivative_f64(curve: &BezierCurve<f64>, t: f64) -> (Vec<f64>, Vec<f64>) {
    let n = curve.degree();
    let s = curve.dim() + 1;
    let mut b = vec![0.0; n + 1];
    let mut db = vec![0.0; n + 1];
    bernstein_with_derivative_into(n, t, &mut b, &mut db);
    let mut h = vec![0.0; s];
    let mut dh = vec![0.0; s];
    combine(curve.coords(), s, &b, &mut h);
    combine(curve.coords(), s, &db, &mut dh);
    let r = 1.0 / h[0];
    let x: Vec<f64> = h[1..].iter().map(|c| c * r).collect();
    let dx = dh[1..]
        .iter()
        .zip(&x)
        .map(|(dc, xc)| (dc - dh[0] * xc) * r)
        .collect();
    (x, dx)
}

/// The homogeneous point `P(u, v)` of a patch (length `dim + 1`, weight first).
pub fn eval_patch_homogeneous_f64(patch: &BezierPatch<f64>, u: f64, v: f64) -> Vec<f64> {
    // the exporters' tessellations run under the caller's work budget
    rcagd_algebra::budget::checkpoint();
    let (m, n) = patch.degree();
    let s = patch.dim() + 1;
    let bu = bernstein_values(m, u);
    let bv = bernstein_values(n, v);
    let mut q = vec![0.0; s];
    let mut acc = vec![0.0; s];
    for (row, &bi) in patch.coords().chunks_exact((n + 1) * s).zip(&bu) {
        combine(row, s, &bv, &mut q);
        for (a, c) in acc.iter_mut().zip(&q) {
            *a += bi * c;
        }
    }
    acc
}

/// The Euclidean point `x(u, v) = P₁..d / P₀` of a patch (length `dim`).
pub fn eval_patch_f64(patch: &BezierPatch<f64>, u: f64, v: f64) -> Vec<f64> {
    let h = eval_patch_homogeneous_f64(patch, u, v);
    let r = 1.0 / h[0];
    h[1..].iter().map(|c| c * r).collect()
}

/// A Euclidean point with its first partial derivatives, general dimension.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchDerivatives {
    /// `x(u, v)`.
    pub point: Vec<f64>,
    /// `∂x/∂u`.
    pub du: Vec<f64>,
    /// `∂x/∂v`.
    pub dv: Vec<f64>,
}

/// The point and first partials of a patch at `(u, v)`:
/// `∂ᵤx = (∂ᵤP₁..d − ∂ᵤP₀ x) / P₀`, likewise for `v` (NURBS Book (4.20)).
pub fn eval_patch_derivatives_f64(patch: &BezierPatch<f64>, u: f64, v: f64) -> PatchDerivatives {
    // the exporters' tessellations run under the caller's work budget
    rcagd_algebra::budget::checkpoint();
    let (m, n) = patch.degree();
    let s = patch.dim() + 1;
    let (mut bu, mut dbu) = (vec![0.0; m + 1], vec![0.0; m + 1]);
    let (mut bv, mut dbv) = (vec![0.0; n + 1], vec![0.0; n + 1]);
    bernstein_with_derivative_into(m, u, &mut bu, &mut dbu);
    bernstein_with_derivative_into(n, v, &mut bv, &mut dbv);
    let mut h = vec![0.0; s];
    let mut hu = vec![0.0; s];
    let mut hv = vec![0.0; s];
    let mut q = vec![0.0; s];
    let mut qv = vec![0.0; s];
    for ((row, &bi), &dbi) in patch.coords().chunks_exact((n + 1) * s).zip(&bu).zip(&dbu) {
        combine(row, s, &bv, &mut q);
        combine(row, s, &dbv, &mut qv);
        for c in 0..s {
            h[c] += bi * q[c];
            hu[c] += dbi * q[c];
            hv[c] += bi * qv[c];
        }
    }
    let r = 1.0 / h[0];
    let point: Vec<f64> = h[1..].iter().map(|c| c * r).collect();
    let du = hu[1..]
        .iter()
        .zip(&point)
        .map(|(d, x)| (d - hu[0] * x) * r)
        .collect();
    let dv = hv[1..]
        .iter()
        .zip(&point)
        .map(|(d, x)| (d - hv[0] * x) * r)
        .collect();
    PatchDerivatives { point, du, dv }
}

/// Clears `out` and reserves room for `us.len() · vs.len() · per_point` values.
fn prepare_output<T>(
    out: &mut Vec<T>,
    us: &[f64],
    vs: &[f64],
    per_point: usize,
) -> Result<(), GeomError> {
    out.clear();
    let n = us
        .len()
        .checked_mul(vs.len())
        .and_then(|k| k.checked_mul(per_point));
    match n {
        Some(n) if out.try_reserve(n).is_ok() => Ok(()),
        _ => Err(GeomError::Parameter(format!(
            "a {} × {} grid is too large to allocate",
            us.len(),
            vs.len()
        ))),
    }
}

fn require_dim3(dim: usize, what: &str) -> Result<(), GeomError> {
    if dim == 3 {
        Ok(())
    } else {
        Err(GeomError::Dimension(format!(
            "{what} needs a patch in E3, this one lies in E{dim}"
        )))
    }
}

/// The control net as `[w, wx, wy, wz]` quadruples, row-major in `u`.
fn net4(patch: &BezierPatch<f64>) -> Vec<[f64; 4]> {
    patch
        .coords()
        .chunks_exact(4)
        .map(|c| [c[0], c[1], c[2], c[3]])
        .collect()
}

/// Inner grid kernel for a 3-D patch with `v`-degree `NV − 1`.
fn grid3_fixed<const NV: usize>(
    net: &[[f64; 4]],
    m: usize,
    us: &[f64],
    vs: &[f64],
    out: &mut Vec<[f64; 3]>,
) {
    let bv: Vec<[f64; NV]> = vs
        .iter()
        .map(|&v| {
            let mut b = [0.0; NV];
            bernstein_into(NV - 1, v, &mut b);
            b
        })
        .collect();
    let mut bu = vec![0.0; m + 1];
    for &u in us {
        rcagd_algebra::budget::checkpoint();
        bernstein_into(m, u, &mut bu);
        // Qⱼ(u) = Σᵢ Bᵢᵐ(u) Pᵢⱼ
        let mut q = [[0.0f64; 4]; NV];
        for (row, &bi) in net.chunks_exact(NV).zip(&bu) {
            for (qj, p) in q.iter_mut().zip(row) {
                for c in 0..4 {
                    qj[c] += bi * p[c];
                }
            }
        }
        out.extend(bv.iter().map(|b| {
            let mut h = [0.0f64; 4];
            for j in 0..NV {
                for c in 0..4 {
                    h[c] += b[j] * q[j][c];
                }
            }
            let r = 1.0 / h[0];
            [h[1] * r, h[2] * r, h[3] * r]
        }));
    }
}

/// Inner grid kernel for a 3-D patch of any `v`-degree `n`.
fn grid3_dyn(
    net: &[[f64; 4]],
    m: usize,
    n: usize,
    us: &[f64],
    vs: &[f64],
    out: &mut Vec<[f64; 3]>,
) {
    let nv = n + 1;
    let mut bv = vec![0.0; vs.len() * nv];
    for (b, &v) in bv.chunks_exact_mut(nv).zip(vs) {
        bernstein_into(n, v, b);
    }
    let mut bu = vec![0.0; m + 1];
    let mut q = vec![[0.0f64; 4]; nv];
    for &u in us {
        rcagd_algebra::budget::checkpoint();
        bernstein_into(m, u, &mut bu);
        q.iter_mut().for_each(|x| *x = [0.0; 4]);
        for (row, &bi) in net.chunks_exact(nv).zip(&bu) {
            for (qj, p) in q.iter_mut().zip(row) {
                for c in 0..4 {
                    qj[c] += bi * p[c];
                }
            }
        }
        out.extend(bv.chunks_exact(nv).map(|b| {
            let mut h = [0.0f64; 4];
            for (bj, qj) in b.iter().zip(&q) {
                for c in 0..4 {
                    h[c] += bj * qj[c];
                }
            }
            let r = 1.0 / h[0];
            [h[1] * r, h[2] * r, h[3] * r]
        }));
    }
}

/// Evaluates a 3-D patch on the grid `us × vs` into `out` (cleared first; its capacity
/// is reused). `out[i · vs.len() + j] = x(us[i], vs[j])`. See the module docs for the
/// row-collapse scheme; no allocation happens inside the loops over the grid.
///
/// # Errors
/// [`GeomError::Dimension`] if the patch is not in E3 (use [`eval_patch_grid_flat`]),
/// [`GeomError::Parameter`] if the output cannot be allocated.
pub fn eval_patch_grid(
    patch: &BezierPatch<f64>,
    us: &[f64],
    vs: &[f64],
    out: &mut Vec<[f64; 3]>,
) -> Result<(), GeomError> {
    require_dim3(patch.dim(), "eval_patch_grid")?;
    prepare_output(out, us, vs, 1)?;
    let (m, n) = patch.degree();
    let net = net4(patch);
    match n {
        1 => grid3_fixed::<2>(&net, m, us, vs, out),
        2 => grid3_fixed::<3>(&net, m, us, vs, out),
        3 => grid3_fixed::<4>(&net, m, us, vs, out),
        4 => grid3_fixed::<5>(&net, m, us, vs, out),
        5 => grid3_fixed::<6>(&net, m, us, vs, out),
        6 => grid3_fixed::<7>(&net, m, us, vs, out),
        7 => grid3_fixed::<8>(&net, m, us, vs, out),
        _ => grid3_dyn(&net, m, n, us, vs, out),
    }
    Ok(())
}

/// Evaluates a patch of any dimension `d` on the grid `us × vs`: `out` (cleared first)
/// receives `d` coordinates per point, points row-major in `u`
/// (`out[(i · vs.len() + j) · d ..][..d]`). Same scheme as [`eval_patch_grid`].
///
/// # Errors
/// [`GeomError::Parameter`] if the output cannot be allocated.
pub fn eval_patch_grid_flat(
    patch: &BezierPatch<f64>,
    us: &[f64],
    vs: &[f64],
    out: &mut Vec<f64>,
) -> Result<(), GeomError> {
    let (m, n) = patch.degree();
    let d = patch.dim();
    let s = d + 1;
    let nv = n + 1;
    prepare_output(out, us, vs, d)?;
    let mut bv = vec![0.0; vs.len() * nv];
    for (b, &v) in bv.chunks_exact_mut(nv).zip(vs) {
        bernstein_into(n, v, b);
    }
    let mut bu = vec![0.0; m + 1];
    let mut q = vec![0.0; nv * s];
    let mut h = vec![0.0; s];
    for &u in us {
        rcagd_algebra::budget::checkpoint();
        bernstein_into(m, u, &mut bu);
        q.iter_mut().for_each(|x| *x = 0.0);
        for (row, &bi) in patch.coords().chunks_exact(nv * s).zip(&bu) {
            for (qc, pc) in q.iter_mut().zip(row) {
                *qc += bi * pc;
            }
        }
        for b in bv.chunks_exact(nv) {
            combine(&q, s, b, &mut h);
            let r = 1.0 / h[0];
            out.extend(h[1..].iter().map(|c| c * r));
        }
    }
    Ok(())
}

/// A point of a 3-D patch with its first partial derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SurfacePoint3 {
    /// `x(u, v)`.
    pub point: [f64; 3],
    /// `∂x/∂u`.
    pub du: [f64; 3],
    /// `∂x/∂v`.
    pub dv: [f64; 3],
}

/// Evaluates points and exact first partials of a 3-D patch on the grid `us × vs`
/// (row-major in `u`, `out` cleared first). Per row `Qⱼ(u)` and `Q'ⱼ(u)` are formed once;
/// per point `P = Σⱼ BⱼQⱼ`, `∂ᵤP = Σⱼ BⱼQ'ⱼ`, `∂ᵥP = Σⱼ B'ⱼQⱼ`, then the quotient rule.
///
/// # Errors
/// [`GeomError::Dimension`] if the patch is not in E3.
pub fn eval_patch_grid_derivatives(
    patch: &BezierPatch<f64>,
    us: &[f64],
    vs: &[f64],
    out: &mut Vec<SurfacePoint3>,
) -> Result<(), GeomError> {
    require_dim3(patch.dim(), "eval_patch_grid_derivatives")?;
    let (m, n) = patch.degree();
    let nv = n + 1;
    let net = net4(patch);
    prepare_output(out, us, vs, 1)?;
    let mut bv = vec![0.0; vs.len() * nv];
    let mut dbv = vec![0.0; vs.len() * nv];
    for ((b, db), &v) in bv
        .chunks_exact_mut(nv)
        .zip(dbv.chunks_exact_mut(nv))
        .zip(vs)
    {
        bernstein_with_derivative_into(n, v, b, db);
    }
    let (mut bu, mut dbu) = (vec![0.0; m + 1], vec![0.0; m + 1]);
    let mut q = vec![[0.0f64; 4]; nv];
    let mut dq = vec![[0.0f64; 4]; nv];
    for &u in us {
        rcagd_algebra::budget::checkpoint();
        bernstein_with_derivative_into(m, u, &mut bu, &mut dbu);
        q.iter_mut().for_each(|x| *x = [0.0; 4]);
        dq.iter_mut().for_each(|x| *x = [0.0; 4]);
        for ((row, &bi), &dbi) in net.chunks_exact(nv).zip(&bu).zip(&dbu) {
            for ((qj, dqj), p) in q.iter_mut().zip(dq.iter_mut()).zip(row) {
                for c in 0..4 {
                    qj[c] += bi * p[c];
                    dqj[c] += dbi * p[c];
                }
            }
        }
        out.extend(
            bv.chunks_exact(nv)
                .zip(dbv.chunks_exact(nv))
                .map(|(b, db)| {
                    let mut h = [0.0f64; 4];
                    let mut hu = [0.0f64; 4];
                    let mut hv = [0.0f64; 4];
                    for (((bj, dbj), qj), dqj) in b.iter().zip(db).zip(&q).zip(&dq) {
                        for c in 0..4 {
                            h[c] += bj * qj[c];
                            hu[c] += bj * dqj[c];
                            hv[c] += dbj * qj[c];
                        }
                    }
                    let r = 1.0 / h[0];
                    let x = [h[1] * r, h[2] * r, h[3] * r];
                    let du = [
                        (hu[1] - hu[0] * x[0]) * r,
                        (hu[2] - hu[0] * x[1]) * r,
                        (hu[3] - hu[0] * x[2]) * r,
                    ];
                    let dv = [
                        (hv[1] - hv[0] * x[0]) * r,
                        (hv[2] - hv[0] * x[1]) * r,
                        (hv[3] - hv[0] * x[2]) * r,
                    ];
                    SurfacePoint3 { point: x, du, dv }
                }),
        );
    }
    Ok(())
}

/// `a − b`.
#[inline]
pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// The cross product `a × b`.
#[inline]
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Euclidean length of a 3-vector.
#[inline]
pub fn norm(a: [f64; 3]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

/// The diagonal of the bounding box of the finite Euclidean control points (`0` if there
/// are none): the length scale against which degenerate normals are judged.
pub fn control_net_scale(patch: &BezierPatch<f64>) -> f64 {
    let d = patch.dim();
    let mut lo = vec![f64::INFINITY; d];
    let mut hi = vec![f64::NEG_INFINITY; d];
    let mut any = false;
    for p in patch.coords().chunks_exact(d + 1) {
        if p[0] == 0.0 {
            continue;
        }
        let r = 1.0 / p[0];
        let x: Vec<f64> = p[1..].iter().map(|c| c * r).collect();
        if x.iter().all(|c| c.is_finite()) {
            any = true;
            for ((l, h), c) in lo.iter_mut().zip(hi.iter_mut()).zip(&x) {
                *l = l.min(*c);
                *h = h.max(*c);
            }
        }
    }
    if !any {
        return 0.0;
    }
    lo.iter()
        .zip(&hi)
        .map(|(l, h)| (h - l) * (h - l))
        .sum::<f64>()
        .sqrt()
}

/// Relative size below which `|∂ᵤx × ∂ᵥx|` counts as zero: `1e-10 · L²`, `L` the control
/// net scale ([`control_net_scale`]).
pub const DEGENERATE_NORMAL_RELATIVE: f64 = 1e-10;

/// Evaluates points and unit normals `n = (∂ᵤx × ∂ᵥx) / |∂ᵤx × ∂ᵥx|` of a 3-D patch on
/// the grid `us × vs` (row-major in `u`; both outputs cleared first). Where the normal
/// is degenerate (`|∂ᵤx × ∂ᵥx| ≤ 1e-10 · L²`, e.g. at the pole of a sphere patch, or not
/// finite) the normal is `[0, 0, 0]`; [`crate::tessellate`] repairs those from
/// neighbouring parameters.
///
/// # Errors
/// [`GeomError::Dimension`] if the patch is not in E3.
pub fn eval_patch_grid_with_normals(
    patch: &BezierPatch<f64>,
    us: &[f64],
    vs: &[f64],
    points: &mut Vec<[f64; 3]>,
    normals: &mut Vec<[f64; 3]>,
) -> Result<(), GeomError> {
    let mut ders = Vec::new();
    eval_patch_grid_derivatives(patch, us, vs, &mut ders)?;
    let scale = control_net_scale(patch);
    let thresh = DEGENERATE_NORMAL_RELATIVE * scale * scale;
    points.clear();
    normals.clear();
    points.extend(ders.iter().map(|d| d.point));
    normals.extend(ders.iter().map(|d| unit_normal(d.du, d.dv, thresh)));
    Ok(())
}

/// `(a × b) / |a × b|`, or `[0, 0, 0]` when `|a × b| ≤ thresh` or it is not finite.
#[inline]
pub(crate) fn unit_normal(a: [f64; 3], b: [f64; 3], thresh: f64) -> [f64; 3] {
    let n = cross(a, b);
    let l = norm(n);
    if l.is_finite() && l > thresh && l > 0.0 {
        [n[0] / l, n[1] / l, n[2] / l]
    } else {
        [0.0; 3]
    }
}

/// A 3-D patch prepared for many single-point evaluations (a mesher's scattered
/// boundary parameters, interior grids): the control net as `[w, wx, wy, wz]` and
/// reusable Bernstein buffers, so no evaluation allocates.
///
/// Every value is computed with the same operations in the same order as
/// [`eval_patch_f64`] and [`eval_patch_derivatives_f64`] (collapse each row in `v`,
/// `Qᵢ(v) = Σⱼ Bⱼⁿ(v) Pᵢⱼ`, then `P = Σᵢ Bᵢᵐ(u) Qᵢ(v)`; quotient rule, NURBS Book
/// (4.20)), so the results are equal to theirs bit for bit; only the allocations and,
/// on grids, the repeated row collapses are saved.
#[derive(Debug, Clone)]
pub struct PatchEvaluator3 {
    m: usize,
    n: usize,
    net: Vec<[f64; 4]>,
    bu: Vec<f64>,
    dbu: Vec<f64>,
    bv: Vec<f64>,
    dbv: Vec<f64>,
}

impl PatchEvaluator3 {
    /// Prepares a 3-D patch.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if the patch is not in E3.
    pub fn new(patch: &BezierPatch<f64>) -> Result<Self, GeomError> {
        require_dim3(patch.dim(), "PatchEvaluator3")?;
        let (m, n) = patch.degree();
        Ok(PatchEvaluator3 {
            m,
            n,
            net: net4(patch),
            bu: vec![0.0; m + 1],
            dbu: vec![0.0; m + 1],
            bv: vec![0.0; n + 1],
            dbv: vec![0.0; n + 1],
        })
    }

    /// `Qᵢ = Σⱼ bⱼ Pᵢⱼ` of row `i` (the order of `combine`).
    #[inline]
    fn collapse(&self, i: usize, b: &[f64]) -> [f64; 4] {
        let nv = self.n + 1;
        let mut q = [0.0f64; 4];
        for (p, &bj) in self.net[i * nv..(i + 1) * nv].iter().zip(b) {
            for c in 0..4 {
                q[c] += bj * p[c];
            }
        }
        q
    }

    /// The Euclidean point `x(u, v)`, equal to [`eval_patch_f64`] bit for bit.
    pub fn point(&mut self, u: f64, v: f64) -> [f64; 3] {
        // the exporters' meshes run under the caller's work budget
        rcagd_algebra::budget::checkpoint();
        bernstein_into(self.m, u, &mut self.bu);
        bernstein_into(self.n, v, &mut self.bv);
        let mut h = [0.0f64; 4];
        for i in 0..=self.m {
            let q = self.collapse(i, &self.bv);
            let bi = self.bu[i];
            for c in 0..4 {
                h[c] += bi * q[c];
            }
        }
        let r = 1.0 / h[0];
        [h[1] * r, h[2] * r, h[3] * r]
    }

    /// The point and first partials at `(u, v)`, equal to
    /// [`eval_patch_derivatives_f64`] bit for bit.
    pub fn derivatives(&mut self, u: f64, v: f64) -> SurfacePoint3 {
        // the exporters' meshes run under the caller's work budget
        rcagd_algebra::budget::checkpoint();
        bernstein_with_derivative_into(self.m, u, &mut self.bu, &mut self.dbu);
        bernstein_with_derivative_into(self.n, v, &mut self.bv, &mut self.dbv);
        let mut h = [0.0f64; 4];
        let mut hu = [0.0f64; 4];
        let mut hv = [0.0f64; 4];
        for i in 0..=self.m {
            let q = self.collapse(i, &self.bv);
            let qv = self.collapse(i, &self.dbv);
            let (bi, dbi) = (self.bu[i], self.dbu[i]);
            for c in 0..4 {
                h[c] += bi * q[c];
                hu[c] += dbi * q[c];
                hv[c] += bi * qv[c];
            }
        }
        quotient(h, hu, hv)
    }

    /// [`Self::derivatives`] at every `(us[i], vs[j])`, row-major in `u`
    /// (`out[i · vs.len() + j]`, `out` cleared first), the same values bit for bit; the
    /// row collapses `Qᵢ(v)`, `∂ᵥQᵢ(v)` are formed once per `v`.
    ///
    /// # Errors
    /// [`GeomError::Parameter`] if the output cannot be allocated.
    pub fn grid_derivatives(
        &mut self,
        us: &[f64],
        vs: &[f64],
        out: &mut Vec<SurfacePoint3>,
    ) -> Result<(), GeomError> {
        prepare_output(out, us, vs, 1)?;
        let rows = self.m + 1;
        // per v: (Qᵢ, ∂ᵥQᵢ) for every row i
        let mut table: Vec<([f64; 4], [f64; 4])> = Vec::new();
        if table.try_reserve(vs.len().saturating_mul(rows)).is_err() {
            return Err(GeomError::Parameter(format!(
                "a {} × {} grid is too large to allocate",
                us.len(),
                vs.len()
            )));
        }
        for &v in vs {
            bernstein_with_derivative_into(self.n, v, &mut self.bv, &mut self.dbv);
            for i in 0..rows {
                table.push((self.collapse(i, &self.bv), self.collapse(i, &self.dbv)));
            }
        }
        for &u in us {
            rcagd_algebra::budget::checkpoint();
            bernstein_with_derivative_into(self.m, u, &mut self.bu, &mut self.dbu);
            for col in table.chunks_exact(rows) {
                let mut h = [0.0f64; 4];
                let mut hu = [0.0f64; 4];
                let mut hv = [0.0f64; 4];
                for ((q, qv), (&bi, &dbi)) in col.iter().zip(self.bu.iter().zip(&self.dbu)) {
                    for c in 0..4 {
                        h[c] += bi * q[c];
                        hu[c] += dbi * q[c];
                        hv[c] += bi * qv[c];
                    }
                }
                out.push(quotient(h, hu, hv));
            }
        }
        Ok(())
    }
}

/// The rows `u ↦ (x(u, vs[0]), …, x(u, vs[k]))` of a grid over fixed `vs`, one `u` at a
/// time (a strip-wise error check needs a few rows at once, never the whole grid): the
/// Bernstein values of `vs` are formed once. Each point is computed with the operations
/// of [`eval_patch_grid`] in the same order, so the values are equal bit for bit.
#[derive(Debug, Clone)]
pub struct PatchGridRows3 {
    m: usize,
    n: usize,
    net: Vec<[f64; 4]>,
    /// `Bⱼⁿ(vs[k])` at `k · (n + 1) + j`.
    bv: Vec<f64>,
    bu: Vec<f64>,
    q: Vec<[f64; 4]>,
}

impl PatchGridRows3 {
    /// Prepares the rows of a 3-D patch over `vs`.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if the patch is not in E3.
    pub fn new(patch: &BezierPatch<f64>, vs: &[f64]) -> Result<Self, GeomError> {
        require_dim3(patch.dim(), "PatchGridRows3")?;
        let (m, n) = patch.degree();
        let nv = n + 1;
        let mut bv = vec![0.0; vs.len() * nv];
        for (b, &v) in bv.chunks_exact_mut(nv).zip(vs) {
            bernstein_into(n, v, b);
        }
        Ok(PatchGridRows3 {
            m,
            n,
            net: net4(patch),
            bv,
            bu: vec![0.0; m + 1],
            q: vec![[0.0; 4]; nv],
        })
    }

    /// The points `x(u, vs[k])` into `out` (cleared first).
    pub fn row(&mut self, u: f64, out: &mut Vec<[f64; 3]>) {
        // the exporters' meshes run under the caller's work budget
        rcagd_algebra::budget::checkpoint();
        out.clear();
        let nv = self.n + 1;
        bernstein_into(self.m, u, &mut self.bu);
        // Qⱼ(u) = Σᵢ Bᵢᵐ(u) Pᵢⱼ
        self.q.iter_mut().for_each(|x| *x = [0.0; 4]);
        for (row, &bi) in self.net.chunks_exact(nv).zip(&self.bu) {
            for (qj, p) in self.q.iter_mut().zip(row) {
                for c in 0..4 {
                    qj[c] += bi * p[c];
                }
            }
        }
        let q = &self.q;
        out.extend(self.bv.chunks_exact(nv).map(|b| {
            let mut h = [0.0f64; 4];
            for (bj, qj) in b.iter().zip(q) {
                for c in 0..4 {
                    h[c] += bj * qj[c];
                }
            }
            let r = 1.0 / h[0];
            [h[1] * r, h[2] * r, h[3] * r]
        }));
    }
}

/// The Euclidean point and partials from the homogeneous `P`, `∂ᵤP`, `∂ᵥP` (quotient
/// rule; the operations of [`eval_patch_derivatives_f64`]).
#[inline]
fn quotient(h: [f64; 4], hu: [f64; 4], hv: [f64; 4]) -> SurfacePoint3 {
    let r = 1.0 / h[0];
    let x = [h[1] * r, h[2] * r, h[3] * r];
    let du = [
        (hu[1] - hu[0] * x[0]) * r,
        (hu[2] - hu[0] * x[1]) * r,
        (hu[3] - hu[0] * x[2]) * r,
    ];
    let dv = [
        (hv[1] - hv[0] * x[0]) * r,
        (hv[2] - hv[0] * x[1]) * r,
        (hv[3] - hv[0] * x[2]) * r,
    ];
    SurfacePoint3 { point: x, du, dv }
}

/// Degrees below this are evaluated by [`eval_curve3_f64`] with Bernstein values on
/// the stack.
const STACK_BASIS: usize = 32;

/// The Euclidean point of a curve in E3 at `t`, equal to [`eval_curve_f64`] bit for bit
/// (the same operations in the same order) but without heap allocation for degrees
/// below 32. A curve of another dimension gives its first three coordinates
/// (zero-padded).
pub fn eval_curve3_f64(curve: &BezierCurve<f64>, t: f64) -> [f64; 3] {
    let n = curve.degree();
    if curve.dim() != 3 || n >= STACK_BASIS {
        let x = eval_curve_f64(curve, t);
        return [0, 1, 2].map(|k| x.get(k).copied().unwrap_or(0.0));
    }
    let mut b = [0.0f64; STACK_BASIS];
    bernstein_into(n, t, &mut b);
    let mut h = [0.0f64; 4];
    combine(curve.coords(), 4, &b[..=n], &mut h);
    let r = 1.0 / h[0];
    [h[1] * r, h[2] * r, h[3] * r]
}

/// `k + 1` equally spaced parameters `a + (b − a) i / k`, `i = 0..=k`, with both ends
/// exact (`k = 0` gives `[a]`).
pub fn linspace(a: f64, b: f64, k: usize) -> Vec<f64> {
    if k == 0 {
        return vec![a];
    }
    (0..=k)
        .map(|i| {
            if i == k {
                b
            } else {
                a + (b - a) * (i as f64 / k as f64)
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn binom(n: usize, k: usize) -> f64 {
        (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
    }

    #[test]
    fn bernstein_matches_closed_form() {
        for n in 0..9 {
            for &t in &[0.0, 0.13, 0.5, 0.77, 1.0, 1.3] {
                let b = bernstein_values(n, t);
                let db = bernstein_derivatives(n, t);
                for i in 0..=n {
                    let exact = binom(n, i) * (1.0 - t).powi((n - i) as i32) * t.powi(i as i32);
                    assert!((b[i] - exact).abs() < 1e-13, "n={n} i={i} t={t}");
                    // derivative by central difference
                    let h = 1e-6;
                    let fd = (binom(n, i)
                        * ((1.0 - t - h).powi((n - i) as i32) * (t + h).powi(i as i32)
                            - (1.0 - t + h).powi((n - i) as i32) * (t - h).powi(i as i32)))
                        / (2.0 * h);
                    assert!((db[i] - fd).abs() < 1e-6, "n={n} i={i} t={t}");
                }
            }
        }
    }

    fn quarter_circle() -> BezierCurve<f64> {
        // x = (1−t²)/(1+t²), y = 2t/(1+t²): w = 1 + t², in the Bernstein basis of degree 2
        // the homogeneous points are (1,1,0), (1,1,1), (2,0,2).
        BezierCurve::from_homogeneous(vec![
            vec![1.0, 1.0, 0.0],
            vec![1.0, 1.0, 1.0],
            vec![2.0, 0.0, 2.0],
        ])
        .expect("valid")
    }

    #[test]
    fn curve_points_on_circle_and_derivative() {
        let c = quarter_circle();
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            let x = eval_curve_f64(&c, t);
            assert!((x[0] * x[0] + x[1] * x[1] - 1.0).abs() < 1e-14);
            let (p, d) = eval_curve_derivative_f64(&c, t);
            assert_eq!(p, x);
            // tangent ⟂ radius on a circle
            assert!((p[0] * d[0] + p[1] * d[1]).abs() < 1e-13);
            let h = 1e-6;
            let a = eval_curve_f64(&c, t + h);
            let b = eval_curve_f64(&c, t - h);
            for i in 0..2 {
                assert!(((a[i] - b[i]) / (2.0 * h) - d[i]).abs() < 1e-6);
            }
        }
    }

    fn test_patch(m: usize, n: usize) -> BezierPatch<f64> {
        let mut net = Vec::new();
        for i in 0..=m {
            let mut row = Vec::new();
            for j in 0..=n {
                let w = 1.0 + 0.25 * ((i * 7 + j * 3) % 5) as f64;
                let x = i as f64 + 0.1 * j as f64;
                let y = j as f64 - 0.2 * i as f64;
                let z = ((i * j) % 3) as f64 - 0.5;
                row.push(vec![w, w * x, w * y, w * z]);
            }
            net.push(row);
        }
        BezierPatch::from_homogeneous(net).expect("valid")
    }

    #[test]
    fn grid_matches_pointwise_for_all_degrees() {
        let us = linspace(0.0, 1.0, 6);
        let vs = linspace(-0.1, 1.1, 7);
        for m in 0..=4 {
            for n in 0..=9 {
                let p = test_patch(m, n);
                let mut out = Vec::new();
                eval_patch_grid(&p, &us, &vs, &mut out).expect("3-D");
                let mut flat = Vec::new();
                eval_patch_grid_flat(&p, &us, &vs, &mut flat).expect("small");
                let mut ders = Vec::new();
                eval_patch_grid_derivatives(&p, &us, &vs, &mut ders).expect("3-D");
                assert_eq!(out.len(), us.len() * vs.len());
                for (i, &u) in us.iter().enumerate() {
                    for (j, &v) in vs.iter().enumerate() {
                        let k = i * vs.len() + j;
                        let x = eval_patch_f64(&p, u, v);
                        let dd = eval_patch_derivatives_f64(&p, u, v);
                        for c in 0..3 {
                            assert!((out[k][c] - x[c]).abs() < 1e-12, "m={m} n={n}");
                            assert!((flat[3 * k + c] - x[c]).abs() < 1e-12);
                            assert!((ders[k].point[c] - x[c]).abs() < 1e-12);
                            assert!((ders[k].du[c] - dd.du[c]).abs() < 1e-10);
                            assert!((ders[k].dv[c] - dd.dv[c]).abs() < 1e-10);
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn partials_match_finite_differences() {
        let p = test_patch(3, 2);
        let h = 1e-6;
        for &(u, v) in &[(0.3, 0.6), (0.0, 1.0), (0.9, 0.1)] {
            let d = eval_patch_derivatives_f64(&p, u, v);
            let pu = eval_patch_f64(&p, u + h, v);
            let mu = eval_patch_f64(&p, u - h, v);
            let pv = eval_patch_f64(&p, u, v + h);
            let mv = eval_patch_f64(&p, u, v - h);
            for c in 0..3 {
                assert!(((pu[c] - mu[c]) / (2.0 * h) - d.du[c]).abs() < 1e-5);
                assert!(((pv[c] - mv[c]) / (2.0 * h) - d.dv[c]).abs() < 1e-5);
            }
        }
    }

    #[test]
    fn normals_unit_or_flagged() {
        // a patch degenerate along u = 0 (all P₀ⱼ equal): normals there are flagged zero
        let mut net = Vec::new();
        for i in 0..=2 {
            let mut row = Vec::new();
            for j in 0..=2 {
                if i == 0 {
                    row.push(vec![1.0, 0.0, 0.0, 1.0]);
                } else {
                    row.push(vec![1.0, i as f64, j as f64 - 1.0, 1.0 - i as f64 * 0.3]);
                }
            }
            net.push(row);
        }
        let p = BezierPatch::from_homogeneous(net).expect("valid");
        let us = linspace(0.0, 1.0, 4);
        let vs = linspace(0.0, 1.0, 4);
        let (mut pts, mut nrm) = (Vec::new(), Vec::new());
        eval_patch_grid_with_normals(&p, &us, &vs, &mut pts, &mut nrm).expect("3-D");
        for (k, n) in nrm.iter().enumerate() {
            if k < vs.len() {
                assert_eq!(*n, [0.0; 3]);
            } else {
                assert!((norm(*n) - 1.0).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn wrong_dimension_is_an_error() {
        let p = BezierPatch::from_flat(2, 1, 1, vec![1.0; 12]).expect("valid");
        let mut out = Vec::new();
        assert!(matches!(
            eval_patch_grid(&p, &[0.5], &[0.5], &mut out),
            Err(GeomError::Dimension(_))
        ));
        let mut flat = Vec::new();
        eval_patch_grid_flat(&p, &[0.5], &[0.5], &mut flat).expect("small");
        assert_eq!(flat, vec![1.0, 1.0]);
    }

    /// Bit patterns (so `-0.0 ≠ 0.0` and NaNs compare by payload).
    fn bits<const N: usize>(x: [f64; N]) -> [u64; N] {
        x.map(f64::to_bits)
    }

    fn vec_bits(x: &[f64]) -> Vec<u64> {
        x.iter().map(|c| c.to_bits()).collect()
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// The evaluator's point, partials and grid are those of `eval_patch_f64` and
        /// `eval_patch_derivatives_f64`, bit for bit, on random rational patches
        /// (weights of either sign) and parameters inside and outside `[0, 1]`.
        #[test]
        fn patch_evaluator_is_bit_identical(
            m in 0usize..5,
            n in 0usize..5,
            seed in proptest::collection::vec(-4.0f64..4.0, 4 * 25),
            us in proptest::collection::vec(-0.25f64..1.25, 1..5),
            vs in proptest::collection::vec(-0.25f64..1.25, 1..5),
        ) {
            let coords = seed[..4 * (m + 1) * (n + 1)].to_vec();
            let p = BezierPatch::from_flat(3, m, n, coords).expect("valid");
            let mut ev = PatchEvaluator3::new(&p).expect("3-D");
            let mut grid = Vec::new();
            ev.grid_derivatives(&us, &vs, &mut grid).expect("small");
            proptest::prop_assert_eq!(grid.len(), us.len() * vs.len());
            for (i, &u) in us.iter().enumerate() {
                for (j, &v) in vs.iter().enumerate() {
                    let want = eval_patch_derivatives_f64(&p, u, v);
                    let got = ev.derivatives(u, v);
                    for d in [got, grid[i * vs.len() + j]] {
                        proptest::prop_assert_eq!(vec_bits(&d.point), vec_bits(&want.point));
                        proptest::prop_assert_eq!(vec_bits(&d.du), vec_bits(&want.du));
                        proptest::prop_assert_eq!(vec_bits(&d.dv), vec_bits(&want.dv));
                    }
                    proptest::prop_assert_eq!(
                        bits(ev.point(u, v)).to_vec(),
                        vec_bits(&eval_patch_f64(&p, u, v))
                    );
                }
            }
        }

        /// `eval_curve3_f64` is `eval_curve_f64` bit for bit (3-D curves on the stack,
        /// other dimensions and high degrees through the general path).
        #[test]
        fn curve3_is_bit_identical(
            deg in 0usize..40,
            dim in 1usize..5,
            seed in proptest::collection::vec(-4.0f64..4.0, 5 * 41),
            t in -0.25f64..1.25,
        ) {
            let coords = seed[..(dim + 1) * (deg + 1)].to_vec();
            let c = BezierCurve::from_flat(dim, coords).expect("valid");
            let want = eval_curve_f64(&c, t);
            let got = eval_curve3_f64(&c, t);
            for (k, g) in got.iter().enumerate() {
                let w = want.get(k).copied().unwrap_or(0.0);
                proptest::prop_assert_eq!(g.to_bits(), w.to_bits());
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// The rows are the points of `eval_patch_grid` bit for bit (fixed-size kernels
        /// for `v`-degrees 1 to 7, the general one above).
        #[test]
        fn grid_rows_are_bit_identical(
            m in 0usize..4,
            n in 0usize..10,
            seed in proptest::collection::vec(-4.0f64..4.0, 4 * 44),
            us in proptest::collection::vec(-0.25f64..1.25, 1..4),
            vs in proptest::collection::vec(-0.25f64..1.25, 1..6),
        ) {
            let coords = seed[..4 * (m + 1) * (n + 1)].to_vec();
            let p = BezierPatch::from_flat(3, m, n, coords).expect("valid");
            let mut want = Vec::new();
            eval_patch_grid(&p, &us, &vs, &mut want).expect("3-D");
            let mut rows = PatchGridRows3::new(&p, &vs).expect("3-D");
            let mut row = Vec::new();
            for (i, &u) in us.iter().enumerate() {
                rows.row(u, &mut row);
                let got: Vec<[u64; 3]> = row.iter().map(|x| bits(*x)).collect();
                let exp: Vec<[u64; 3]> =
                    want[i * vs.len()..(i + 1) * vs.len()].iter().map(|x| bits(*x)).collect();
                proptest::prop_assert_eq!(got, exp);
            }
        }
    }

    #[test]
    fn patch_evaluator_needs_e3() {
        let p = BezierPatch::from_flat(2, 1, 1, vec![1.0; 12]).expect("valid");
        assert!(matches!(
            PatchEvaluator3::new(&p),
            Err(GeomError::Dimension(_))
        ));
        assert!(matches!(
            PatchGridRows3::new(&p, &[0.5]),
            Err(GeomError::Dimension(_))
        ));
    }
}
