//! Closed pipes that arrive closed: the rings of a pipe around a `G¹`-closed spine
//! reparametrized in `u` so that neighbouring rings, and the last ring and the first,
//! meet along the *same* parametrized characteristic circle, and tiled so that every
//! patch boundary is shared exactly (docs/math/pipes.md, "Closed pipes").
//!
//! A ring is one exact piece of the pipe, `X(t, u)` over `[a, b] × (R ∪ {∞})`
//! ([`super::ExportPiece`]). Two rational parametrizations of degree 2 of the same circle
//! differ by a Möbius map of the parameter: `E(M(u)) ∝ S(u)` with `M ∈ PGL₂(Q)` (both
//! are birational onto the conic, so `M = E⁻¹ ∘ S` is rational over the field of the
//! data). Ring `j` is reparametrized by the constant `M` that makes its start circle the
//! end circle of ring `j − 1`. Around the closed spine the maps compose to a holonomy
//! that a constant map cannot remove; the last ring is reparametrized by
//! `M(t) = (1 − s) A + s B`, `s = (t − a)/(b − a)`, linear in `t`, from the map `A` that
//! matches its start to the map `B` that matches its end to the first ring's start
//! (sign of `B` chosen so that `det M(t)` has no root on `[a, b]`: a Möbius map for every
//! `t`). The canal identities hold for every reparametrization `x(t, M_t(u))` (sphere and
//! contact pointwise; `x̃_u = x_u·∂_u M`, `x̃_t = x_t + x_u·∂_t M`, both orthogonal to
//! `x − m`) and are certified again for the new coordinates; the `t`-degree grows by 2.
//! The weight has no zero on the ring (a Möbius map permutes `R ∪ {∞}`), so it keeps its
//! sign, and a fine enough tiling has positive Bernstein weights.

use super::bipoly::{patch_of, BiPoly};
use super::exportable::{ExportPiece, ExportableCanal};
use super::CanalError;
use crate::error::format_scalar;
use rcagd_algebra::roots::count_real_roots_in;
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};
use rcagd_geom::{BezierCurve, BezierPatch};
use std::collections::HashMap;

/// The most bisections of a ring in `t` when it is tiled with positive weights.
const MAX_T_SPLITS: usize = 5;
/// The most `u`-cells of the tiling (the same cells for every ring; four to start with).
const MAX_U_CELLS: usize = 64;

/// A 2×2 matrix `[[α, β], [γ, δ]]`: the Möbius map `u ↦ (αu + β)/(γu + δ)`.
type Mat = [[Rational; 2]; 2];

/// The characteristic circle `X(t₀, u)` as a polynomial in `u` (constant in `t`).
fn circle(x: &[BiPoly<Rational>; 4], t0: &Rational) -> [BiPoly<Rational>; 4] {
    core::array::from_fn(|k| {
        BiPoly::new(
            x[k].coeffs()
                .iter()
                .map(|c| Poly::constant(c.eval(t0)))
                .collect(),
        )
    })
}

/// `Σₖ cₖ(t) pᵏ q²⁻ᵏ` with `p = m₀₀ u + m₀₁`, `q = m₁₀ u + m₁₁` (entries polynomials in
/// `t`): `x(t, M_t(u))` homogenized with the degree 2 in `u`.
fn substitute(x: &BiPoly<Rational>, m: &[[Poly<Rational>; 2]; 2]) -> BiPoly<Rational> {
    let p = BiPoly::new(vec![m[0][1].clone(), m[0][0].clone()]);
    let q = BiPoly::new(vec![m[1][1].clone(), m[1][0].clone()]);
    let one = BiPoly::from_t(Poly::constant(Rational::ONE));
    let pw = |b: &BiPoly<Rational>, k: usize| (0..k).fold(one.clone(), |acc, _| acc.mul(b));
    (0..=2).fold(BiPoly::zero(), |acc, k| match x.coeffs().get(k) {
        Some(c) if !c.is_zero() => acc.add(&pw(&p, k).mul(&pw(&q, 2 - k)).mul_t(c)),
        _ => acc,
    })
}

fn constant(m: &Mat) -> [[Poly<Rational>; 2]; 2] {
    core::array::from_fn(|i| core::array::from_fn(|j| Poly::constant(m[i][j].clone())))
}

/// `λ` with `a = λ b` (all four coordinates), if there is one.
fn proportional(a: &[BiPoly<Rational>; 4], b: &[BiPoly<Rational>; 4]) -> bool {
    let ca: Vec<Rational> = a.iter().flat_map(coeffs_padded).collect();
    let cb: Vec<Rational> = b.iter().flat_map(coeffs_padded).collect();
    let Some(k) = cb.iter().position(|x| !x.is_zero()) else {
        return false;
    };
    let lambda = ca[k].clone() / cb[k].clone();
    !lambda.is_zero()
        && ca
            .iter()
            .zip(&cb)
            .all(|(x, y)| *x == lambda.clone() * y.clone())
}

/// The coefficients of a circle (constant in `t`) of `u⁰, u¹, u²`.
fn coeffs_padded(b: &BiPoly<Rational>) -> Vec<Rational> {
    (0..=2)
        .map(|k| b.coeffs().get(k).map_or(Rational::ZERO, |c| c.coeff(0)))
        .collect()
}

/// The finite parameter `v` with `E(v) ∝ p` on the circle `E`, if there is one: the common
/// root of the minors `pᵢ Eⱼ(v) − pⱼ Eᵢ(v)`.
fn parameter_of(e: &[BiPoly<Rational>; 4], p: &[Rational; 4]) -> Option<Rational> {
    let polys: Vec<Poly<Rational>> = e.iter().map(|b| Poly::new(coeffs_padded(b))).collect();
    let mut g = Poly::zero();
    for i in 0..4 {
        for j in i + 1..4 {
            let minor = &polys[j].scale(&p[i]) - &polys[i].scale(&p[j]);
            g = g.gcd(&minor);
        }
    }
    if g.degree() != Some(1) {
        return None;
    }
    let v = -g.coeff(0) / g.coeff(1);
    let on: Vec<Rational> = polys.iter().map(|q| q.eval(&v)).collect();
    on.iter().any(|x| !x.is_zero()).then_some(v)
}

/// The map `z ↦ (z − z₁)(z₂ − z₃) / ((z − z₃)(z₂ − z₁))` sending `z₁, z₂, z₃` to `0, 1, ∞`.
fn to_zero_one_inf(z: &[Rational; 3]) -> Mat {
    let [z1, z2, z3] = z;
    let a = z2.clone() - z3.clone();
    let c = z2.clone() - z1.clone();
    [
        [a.clone(), -(z1.clone() * a)],
        [c.clone(), -(z3.clone() * c)],
    ]
}

fn mul(a: &Mat, b: &Mat) -> Mat {
    core::array::from_fn(|i| {
        core::array::from_fn(|j| {
            a[i][0].clone() * b[0][j].clone() + a[i][1].clone() * b[1][j].clone()
        })
    })
}

fn adjugate(a: &Mat) -> Mat {
    [
        [a[1][1].clone(), -a[0][1].clone()],
        [-a[1][0].clone(), a[0][0].clone()],
    ]
}

/// The Möbius map `M` with `E(M(u)) ∝ S(u)` identically in `u` (the two parametrizations
/// of one circle compared), from three parameters of `S` and their parameters on `E`,
/// checked as a polynomial identity.
fn mobius_between(e: &[BiPoly<Rational>; 4], s: &[BiPoly<Rational>; 4]) -> Option<Mat> {
    let zero = Rational::ZERO;
    let mut us: Vec<Rational> = Vec::new();
    let mut vs: Vec<Rational> = Vec::new();
    for (n, d) in [
        (0, 1),
        (1, 1),
        (-1, 1),
        (2, 1),
        (-2, 1),
        (1, 2),
        (-1, 2),
        (3, 1),
    ] {
        if us.len() == 3 {
            break;
        }
        let u = Rational::from_ratio(n, d);
        let p: [Rational; 4] = core::array::from_fn(|k| s[k].eval(&zero, &u));
        if let Some(v) = parameter_of(e, &p) {
            if !vs.contains(&v) {
                us.push(u);
                vs.push(v);
            }
        }
    }
    let (Ok(u3), Ok(v3)) = (<[Rational; 3]>::try_from(us), <[Rational; 3]>::try_from(vs)) else {
        return None;
    };
    let m = mul(&adjugate(&to_zero_one_inf(&v3)), &to_zero_one_inf(&u3));
    let moved: [BiPoly<Rational>; 4] = core::array::from_fn(|k| substitute(&e[k], &constant(&m)));
    proportional(&moved, s).then_some(m)
}

/// `det M(t)` of the linear blend `M(t) = (1 − s) A + s B`, `s = (t − a)/(b − a)`, and the
/// blend's entries.
fn blend(a_map: &Mat, b_map: &Mat, a: &Rational, b: &Rational) -> [[Poly<Rational>; 2]; 2] {
    let len = b.clone() - a.clone();
    core::array::from_fn(|i| {
        core::array::from_fn(|j| {
            let slope = (b_map[i][j].clone() - a_map[i][j].clone()) / len.clone();
            Poly::new(vec![a_map[i][j].clone() - slope.clone() * a.clone(), slope])
        })
    })
}

/// `true` if `a` and `b` are the same Möbius map (proportional matrices).
fn same_map(a: &Mat, b: &Mat) -> bool {
    let (fa, fb): (Vec<&Rational>, Vec<&Rational>) =
        (a.iter().flatten().collect(), b.iter().flatten().collect());
    let Some(k) = fb.iter().position(|x| !x.is_zero()) else {
        return false;
    };
    let l = fa[k].clone() / fb[k].clone();
    fa.iter()
        .zip(&fb)
        .all(|(x, y)| **x == l.clone() * (*y).clone())
}

/// A positive rational `c ≈ √(|det a| / |det b|)` (a power of 2 of it, at least).
fn balance(a: &Mat, b: &Mat) -> Rational {
    let d = |m: &Mat| {
        Scalar::to_f64(&(m[0][0].clone() * m[1][1].clone() - m[0][1].clone() * m[1][0].clone()))
            .abs()
    };
    let r = (d(a) / d(b)).sqrt();
    if !r.is_finite() || r <= 0.0 {
        return Rational::ONE;
    }
    // the nearest power of two (exact, positive)
    let e = r.log2().round().clamp(-60.0, 60.0) as i32;
    if e >= 0 {
        Rational::from(1i64 << e)
    } else {
        Rational::from_ratio(1, 1i64 << (-e))
    }
}

fn det(m: &[[Poly<Rational>; 2]; 2]) -> Poly<Rational> {
    &(&m[0][0] * &m[1][1]) - &(&m[0][1] * &m[1][0])
}

/// The four quarters of the circle: `u ∈ [−1, 0], [0, 1]` and, in the chart `u = 1/v`,
/// `v ∈ [−1, 0], [0, 1]` (chart flag, start, end).
fn quarters() -> Vec<(bool, Rational, Rational)> {
    let mut out = Vec::new();
    for chart in [false, true] {
        for k in -1..1 {
            out.push((chart, Rational::from(k), Rational::from(k + 1)));
        }
    }
    out
}

/// The patch with its homogeneous coordinates negated when its weights are negative;
/// `None` unless every Bernstein weight has one strict sign.
fn one_signed(p: BezierPatch<Rational>) -> Option<BezierPatch<Rational>> {
    let zero = Rational::ZERO;
    let w: Vec<&Rational> = p.coords().iter().step_by(p.dim() + 1).collect();
    if w.iter().all(|x| **x > zero) {
        Some(p)
    } else if w.iter().all(|x| **x < zero) {
        let (m, n) = p.degree();
        let c: Vec<Rational> = p.coords().iter().map(|x| -x.clone()).collect();
        BezierPatch::from_flat(p.dim(), m, n, c).ok()
    } else {
        None
    }
}

/// The patches of one `t`-column `[t₀, t₁]` over every cell in `u`, or the indices of the
/// cells whose weights are not all of one sign.
fn column(
    charts: &[[BiPoly<Rational>; 4]; 2],
    t: (&Rational, &Rational),
    cells: &[(bool, Rational, Rational)],
) -> Result<Result<Vec<BezierPatch<Rational>>, Vec<usize>>, CanalError> {
    let mut out = Vec::with_capacity(cells.len());
    let mut bad = Vec::new();
    for (k, (chart, u0, u1)) in cells.iter().enumerate() {
        rcagd_algebra::budget::checkpoint();
        let x = &charts[usize::from(*chart)];
        match one_signed(patch_of(x, t, (u0, u1))?) {
            Some(p) => out.push(p),
            None => bad.push(k),
        }
    }
    Ok(if bad.is_empty() { Ok(out) } else { Err(bad) })
}

/// The ring on `[a, b]` tiled into `t`-columns (bisected where a weight is not of one
/// sign, at most [`MAX_T_SPLITS`] deep) times the `u`-cells; else the cells that still
/// fail at that depth.
fn tile_ring(
    x: &[BiPoly<Rational>; 4],
    (a, b): (&Rational, &Rational),
    cells: &[(bool, Rational, Rational)],
) -> Result<Result<Vec<BezierPatch<Rational>>, Vec<usize>>, CanalError> {
    let charts = [x.clone(), core::array::from_fn(|k| x[k].reverse_u(2))];
    let mut out = Vec::new();
    let mut stack = vec![(a.clone(), b.clone(), 0usize)];
    // depth-first, the left half first: the columns come out in parameter order
    while let Some((t0, t1, depth)) = stack.pop() {
        match column(&charts, (&t0, &t1), cells)? {
            Ok(ps) => out.extend(ps),
            Err(_) if depth < MAX_T_SPLITS => {
                let m = (t0.clone() + t1.clone()) / Rational::from(2);
                stack.push((m.clone(), t1, depth + 1));
                stack.push((t0, m, depth + 1));
            }
            Err(bad) => return Ok(Err(bad)),
        }
    }
    Ok(Ok(out))
}

/// Every ring tiled over one common list of `u`-cells: the four quarters, a cell bisected
/// (for every ring) where some ring's column still fails after [`MAX_T_SPLITS`]
/// bisections in `t`, up to [`MAX_U_CELLS`] cells; `None` if that is not enough.
fn tile_rings(
    rings: &[([BiPoly<Rational>; 4], Rational, Rational)],
) -> Result<Option<Vec<Vec<BezierPatch<Rational>>>>, CanalError> {
    let mut cells = quarters();
    while cells.len() <= MAX_U_CELLS {
        let mut all = Vec::with_capacity(rings.len());
        let mut bad: Vec<usize> = Vec::new();
        for (x, a, b) in rings {
            match tile_ring(x, (a, b), &cells)? {
                Ok(ps) => all.push(ps),
                Err(cs) => {
                    bad = cs;
                    break;
                }
            }
        }
        if bad.is_empty() {
            return Ok(Some(all));
        }
        // bisect the failing cells (in u, for every ring), keeping the cells in order
        let mut next = Vec::with_capacity(cells.len() + bad.len());
        for (k, (chart, u0, u1)) in cells.into_iter().enumerate() {
            if bad.contains(&k) {
                let m = (u0.clone() + u1.clone()) / Rational::from(2);
                next.push((chart, u0, m.clone()));
                next.push((chart, m, u1));
            } else {
                next.push((chart, u0, u1));
            }
        }
        cells = next;
    }
    Ok(None)
}

/// A boundary curve up to orientation and a constant factor: the control points divided
/// by the first weight, forwards or backwards, whichever is smaller.
fn curve_key(c: &BezierCurve<Rational>) -> Option<Vec<Rational>> {
    let norm = |c: &BezierCurve<Rational>| -> Option<Vec<Rational>> {
        let w = c.control_point(0).first()?.clone();
        if w.is_zero() {
            return None;
        }
        Some(
            c.control_points()
                .flat_map(|p| p.iter().map(|x| x.clone() / w.clone()))
                .collect(),
        )
    };
    let (f, r) = (norm(c)?, norm(&c.reverse())?);
    Some(if f <= r { f } else { r })
}

/// "Every boundary curve of the patches is the boundary curve of exactly one other patch
/// (up to orientation and a constant factor of the homogeneous control points)": the
/// patches form closed surfaces without a free edge, decided exactly.
pub fn closed_shell_certificate(patches: &[BezierPatch<Rational>]) -> Certificate {
    let mut count: HashMap<Vec<Rational>, usize> = HashMap::new();
    let mut bad = 0usize;
    for p in patches {
        for c in p.boundary_curves() {
            match curve_key(&c) {
                Some(k) => *count.entry(k).or_default() += 1,
                None => bad += 1,
            }
        }
    }
    let unpaired = count.values().filter(|&&n| n != 2).count() + bad;
    Certificate::decide(
        format!(
            "the pipe is closed: each of the {} boundary curves of the {} patches is shared with exactly one other patch (identical control points up to a constant factor and orientation; no free edge)",
            4 * patches.len(),
            patches.len()
        ),
        unpaired == 0,
        true,
        || format!("{unpaired} boundary curves are not shared by exactly two patches"),
    )
}

/// Reparametrizes and re-tiles the rings of a pipe around a `G¹`-closed chain of spines
/// (module docs), in place; returns the certificates of the seams (the characteristic
/// circles at every ring joint, the closing one included, are the same parametrized circle
/// from both sides) and of the closed shell.
///
/// # Errors
/// [`CanalError::InvalidArgument`] if a ring is reparametrized in `t`, two neighbouring
/// rings do not share their circle, the blend of the last ring degenerates, or no tiling
/// within [`MAX_T_SPLITS`] bisections and [`MAX_U_CELLS`] cells has positive weights.
pub(crate) fn close_rings(chain: &mut [ExportableCanal]) -> Result<Vec<Certificate>, CanalError> {
    let mut rings: Vec<&mut ExportPiece> =
        chain.iter_mut().flat_map(|c| c.pieces.iter_mut()).collect();
    let n = rings.len();
    if n == 0 {
        return Err(CanalError::InvalidArgument(
            "a closed pipe without rings".into(),
        ));
    }
    if rings
        .iter()
        .any(|r| r.surface.reparametrization().is_some())
    {
        return Err(CanalError::InvalidArgument(
            "a ring of the closed pipe is reparametrized in t; its seam cannot be closed".into(),
        ));
    }
    let err = |what: String| CanalError::InvalidArgument(format!("closing the pipe: {what}"));
    let identity: Mat = [
        [Rational::ONE, Rational::ZERO],
        [Rational::ZERO, Rational::ONE],
    ];
    let first_start = circle(rings[0].surface.homogeneous(), &rings[0].interval.0);
    // the end circle of the ring before, as reparametrized
    let mut prev_end: Option<[BiPoly<Rational>; 4]> = None;
    for (j, ring) in rings.iter_mut().enumerate() {
        let mut blended = false;
        let (a, b) = ring.interval.clone();
        let x = ring.surface.homogeneous().clone();
        let start = match &prev_end {
            None => identity.clone(),
            Some(pe) => mobius_between(&circle(&x, &a), pe).ok_or_else(|| {
                err(format!(
                    "rings {} and {j} do not meet along the same circle at t = {}",
                    j - 1,
                    format_scalar(&a)
                ))
            })?,
        };
        let map = if j + 1 == n {
            let end = mobius_between(&circle(&x, &b), &first_start).ok_or_else(|| {
                err(format!(
                    "the last ring (t = {}) and the first do not meet along the same circle",
                    format_scalar(&b)
                ))
            })?;
            if same_map(&start, &end) {
                // no holonomy: one constant map matches both ends
                (start != identity).then(|| constant(&start))
            } else {
                // B scaled to |det B| ≈ |det A| (any positive factor is the same map; this
                // one keeps the path of maps away from degenerate ones), either sign
                let c = balance(&start, &end);
                let plus: Mat = core::array::from_fn(|i| {
                    core::array::from_fn(|k| c.clone() * end[i][k].clone())
                });
                let minus: Mat =
                    core::array::from_fn(|i| core::array::from_fn(|k| -plus[i][k].clone()));
                let mut chosen = None;
                for e in [plus, minus] {
                    let m = blend(&start, &e, &a, &b);
                    let d = det(&m);
                    if !d.is_zero() && count_real_roots_in(&d, &a, &b)? == 0 {
                        chosen = Some(m);
                        break;
                    }
                }
                blended = true;
                Some(chosen.ok_or_else(|| {
                    err("the Möbius maps at the two ends of the last ring cannot be joined (the seam reverses the circle)".into())
                })?)
            }
        } else if start == identity {
            None
        } else {
            Some(constant(&start))
        };
        if let Some(m) = map {
            let xt: [BiPoly<Rational>; 4] = core::array::from_fn(|k| substitute(&x[k], &m));
            ring.surface = ring.surface.with_homogeneous(xt);
            ring.seam_blend = blended;
        }
        prev_end = Some(circle(ring.surface.homogeneous(), &b));
    }
    // the tiling: one list of u-cells for every ring, t-columns per ring
    let xs: Vec<([BiPoly<Rational>; 4], Rational, Rational)> = rings
        .iter()
        .map(|r| {
            (
                r.surface.homogeneous().clone(),
                r.interval.0.clone(),
                r.interval.1.clone(),
            )
        })
        .collect();
    let tiled = tile_rings(&xs)?.ok_or_else(|| {
        err(format!(
            "no tiling with positive weights within {MAX_T_SPLITS} bisections in t and {MAX_U_CELLS} cells in u"
        ))
    })?;
    for (ring, ps) in rings.iter_mut().zip(tiled) {
        ring.patches = ps;
    }
    // the certificates: the circles at the joints, then the closed shell
    let mut bad = Vec::new();
    for j in 0..n {
        let k = (j + 1) % n;
        let end = circle(rings[j].surface.homogeneous(), &rings[j].interval.1);
        let start = circle(rings[k].surface.homogeneous(), &rings[k].interval.0);
        if !proportional(&end, &start) {
            bad.push(j);
        }
    }
    let patches: Vec<BezierPatch<Rational>> = rings
        .iter()
        .flat_map(|r| r.patches.iter().cloned())
        .collect();
    Ok(vec![
        Certificate::decide(
            format!(
                "the seams are exact: at each of the {n} joints of the pipe's rings (the closing one, last ring at its end to the first at its start, included) the two rings give the same parametrized characteristic circle, X_j(b_j, u) ≡ λ_j X_(j+1)(a_(j+1), u) identically in u"
            ),
            bad.is_empty(),
            true,
            || format!("the circles differ after ring(s) {bad:?}"),
        ),
        closed_shell_certificate(&patches),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    /// The unit circle `((1 + u²), 1 − u², 2u, 0)` and the same circle rotated by a
    /// Möbius map: the map is recovered and the identity holds; a different circle has
    /// none.
    #[test]
    fn mobius_between_two_parametrizations_of_a_circle() {
        let c = |p: &[i64]| BiPoly::from_u(&Poly::from_ints(p));
        let s = [c(&[1, 0, 1]), c(&[1, 0, -1]), c(&[0, 2]), c(&[0])];
        let m: Mat = [[q(2), q(1)], [q(-1), q(3)]];
        let e: [BiPoly<Rational>; 4] = core::array::from_fn(|k| substitute(&s[k], &constant(&m)));
        // E(u) = S(M(u)); so E(M⁻¹(u)) ∝ S(u)
        let back = mobius_between(&e, &s).expect("a map");
        let moved: [BiPoly<Rational>; 4] =
            core::array::from_fn(|k| substitute(&e[k], &constant(&back)));
        assert!(proportional(&moved, &s));
        assert!(proportional(&circle(&moved, &q(0)), &s));
        // composing with m gives a multiple of the identity
        let id = mul(&m, &back);
        assert!(id[0][1].is_zero() && id[1][0].is_zero() && id[0][0] == id[1][1]);
        // a circle of radius 2 is another circle
        let big = [c(&[1, 0, 1]), c(&[2, 0, -2]), c(&[0, 4]), c(&[0])];
        assert!(mobius_between(&big, &s).is_none());
    }

    /// The planar quartic loop `(0, 0), (2, 0), (0, 4), (−2, 0), (0, 0)` (`G¹` at the
    /// seam: both end tangents point along `+x`).
    fn quartic_loop() -> BezierCurve<Rational> {
        let pts: Vec<Vec<Rational>> = [[0, 0], [2, 0], [0, 4], [-2, 0], [0, 0]]
            .iter()
            .map(|p| vec![q(p[0]), q(p[1]), q(0)])
            .collect();
        BezierCurve::from_points(&pts).expect("quartic")
    }

    fn seam_certificates(certs: &[Certificate]) -> Vec<&Certificate> {
        certs
            .iter()
            .filter(|c| {
                c.property.starts_with("the seams are exact")
                    || c.property.starts_with("the pipe is closed")
            })
            .collect()
    }

    /// One spine closed with `G¹`: the pipe's rings meet along identical circles, the
    /// closing one included, and every boundary curve is shared; the seam certificates
    /// are the ones of this module, and they would fail for the pipe with a ring missing.
    #[test]
    fn a_pipe_around_a_closed_quartic_is_closed() {
        use crate::Certified;
        let spine = vec![quartic_loop()];
        assert!(super::super::chain_is_g1_closed(&spine));
        let r = Rational::from_ratio(1, 20);
        let pipe = super::super::pipe_along_chain(&spine, &r, super::super::Orientation::Positive)
            .expect("pipe");
        let certs = pipe.certify();
        assert!(Certificate::all_hold(&certs), "{certs:#?}");
        let seam = seam_certificates(&certs);
        assert_eq!(seam.len(), 2, "{certs:#?}");
        let patches = pipe.patches();
        assert!(closed_shell_certificate(&patches).holds);
        // the first and last t-columns of patches touch along the seam; without the last
        // column the shell is open
        let rings: Vec<&ExportPiece> = pipe.pieces().iter().flat_map(|c| c.pieces()).collect();
        let last = rings.last().expect("a ring");
        let cells = quarters().len();
        assert!(last.patches.len() >= cells);
        let open = &patches[..patches.len() - cells];
        assert!(!closed_shell_certificate(open).holds);
    }

    /// The same loop as two spine pieces (split at `t = 1/3`): at least two rings, aligned
    /// by constant Möbius maps, and the seam blended; the same certificates hold.
    #[test]
    fn a_closed_chain_of_two_pieces_is_closed() {
        use crate::Certified;
        let (a, b) = quartic_loop()
            .subdivide(&Rational::from_ratio(1, 3))
            .expect("split");
        let spine = vec![a, b];
        assert!(super::super::chain_is_g1_closed(&spine));
        let r = Rational::from_ratio(1, 20);
        let pipe = super::super::pipe_along_chain(&spine, &r, super::super::Orientation::Positive)
            .expect("pipe");
        let certs = pipe.certify();
        assert!(Certificate::all_hold(&certs), "{certs:#?}");
        assert_eq!(seam_certificates(&certs).len(), 2);
        let rings: Vec<&ExportPiece> = pipe.pieces().iter().flat_map(|c| c.pieces()).collect();
        assert!(rings.len() >= 2);
        eprintln!(
            "{} rings, {} patches, seam blended: {}",
            rings.len(),
            pipe.patches().len(),
            rings.iter().any(|r| r.seam_blend)
        );
        // an open piece of the loop is not closed and gets no seam certificates
        let open =
            super::super::pipe_along_chain(&spine[..1], &r, super::super::Orientation::Positive)
                .expect("open pipe");
        assert!(seam_certificates(&open.certify()).is_empty());
        assert!(!closed_shell_certificate(&open.patches()).holds);
    }

    #[test]
    fn closed_shell_needs_every_edge_twice() {
        // a cube's worth of bilinear faces is closed only with all six faces
        let face = |pts: [[i64; 3]; 4]| {
            let mut c = Vec::new();
            for p in [pts[0], pts[1], pts[3], pts[2]] {
                c.push(q(1));
                c.extend(p.iter().map(|&x| q(x)));
            }
            BezierPatch::from_flat(3, 1, 1, c).expect("patch")
        };
        let f = [
            face([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]),
            face([[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]),
            face([[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]),
            face([[0, 1, 0], [1, 1, 0], [1, 1, 1], [0, 1, 1]]),
            face([[0, 0, 0], [0, 1, 0], [0, 1, 1], [0, 0, 1]]),
            face([[1, 0, 0], [1, 1, 0], [1, 1, 1], [1, 0, 1]]),
        ];
        assert!(closed_shell_certificate(&f).holds);
        assert!(!closed_shell_certificate(&f[..5]).holds);
    }
}
