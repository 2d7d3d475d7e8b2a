//! Certified local regularity of pipe surfaces: `r·κ < 1` on the whole parameter interval,
//! decided exactly by polynomial positivity (see `docs/math/pipes.md#regularity`).
//!
//! The pipe `x = m + r q` of radius `r` around a spine `m(t)` (the envelope of the spheres of
//! radius `r` centred on the spine; D. Gruber, "Rationale Parametrisierungen von
//! Kugelhüllflächen", 2008, §2.1 "Rohrfläche") is free of local self-intersections iff
//! `r·κ(t) < 1` for the curvature `κ` of the spine and `m′(t) ≠ 0`: the normal-plane circle
//! of radius `r` then lies inside the osculating-circle region, and `x_t` never vanishes
//! (`|x_t| = |m′|(1 − r κ cos θ)`).
//!
//! For a rational spine `m = M/W` let `P = W M′ − W′ M` (so `m′ = P/W²`). Then
//! `m′ × m″ = (P × P′)/W⁴` and `κ = |m′ × m″|/|m′|³ = W²|P × P′|/|P|³`, so on an interval
//! where `W ≠ 0` and `P ≠ 0`
//!
//! ```text
//! r κ < 1   ⇔   F(t) = |P|⁶ − r² W⁴ |P × P′|² > 0,
//! ```
//!
//! a polynomial inequality. `F > 0` on `[a, b]` iff `F(a) > 0` and `F` has no real root in
//! `[a, b]` (exact root counting by Descartes' rule on Bernstein coefficients,
//! `rcagd_algebra::roots`). Where it fails, the roots of `F` bound the parameter intervals
//! with `r κ ≥ 1`, and the error names one ([`CanalError::RadiusNotBelowCurvatureRadius`]).
//! A root of `|P|²` in `[a, b]` is a zero-length tangent ([`CanalError::ZeroTangent`]).
//!
//! **Canal surfaces of varying radius** ([`check_canal_regularity`]). The envelope of the
//! spheres `|x − m(t)|² = r(t)²` meets its neighbours' characteristic circles where a point
//! of the characteristic circle `C(t)` (on the plane `(x − m)·ṁ + r ṙ = 0`) also satisfies
//! the derivative condition `(x − m)·m̈ = |ṁ|² − ṙ² − r r̈` (the characteristic points of the
//! family, the classical condition for a singular point of an envelope). In the plane of
//! `C(t)` this is the distance of a line from the circle's centre compared with its radius;
//! with `A = W M′ − W′ M`, `B = W R′ − W′ R` (`ṁ = A/W²`, `ṙ = B/W²`), `C = W A′ − 2W′A`,
//! `H = |A|² − B² − R (W B′ − 2W′B)` the circles keep off those points iff
//!
//! ```text
//! F(t) = (H|A|² + R B (A·C))² − R² (|A|² − B²) |A × C|² > 0
//! ```
//!
//! (times `W¹⁶ > 0`; derivation in `docs/math/pipes.md#canal-regularity`). For constant
//! radius `F = |A|²·(|A|⁶ − r²W⁴|A × A′|²)`, the pipe condition above. A sphere of radius 0
//! (`R = 0`, a vertex) is singular as well; a circle that collapses to a point because
//! `|ṁ| = |ṙ|` (a pole of a closed surface) is not excluded by `F`.

use super::bipoly::BiPoly;
use super::{CanalError, CanalSpine};
use crate::error::format_scalar;
use rcagd_algebra::roots::{isolate_real_roots_in, rational_roots, RootInterval};
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};

type P = Poly<Rational>;

/// `a × b` of polynomial vectors.
pub(super) fn cross(a: &[P; 3], b: &[P; 3]) -> [P; 3] {
    [
        &(&a[1] * &b[2]) - &(&a[2] * &b[1]),
        &(&a[2] * &b[0]) - &(&a[0] * &b[2]),
        &(&a[0] * &b[1]) - &(&a[1] * &b[0]),
    ]
}

/// `a · b` of polynomial vectors.
pub(super) fn dot(a: &[P; 3], b: &[P; 3]) -> P {
    &(&(&a[0] * &b[0]) + &(&a[1] * &b[1])) + &(&a[2] * &b[2])
}

fn norm_sq(a: &[P; 3]) -> P {
    dot(a, a)
}

/// Where `f > 0` fails on `[a, b]`: `None` if `f > 0` on the whole interval, else the ends
/// of an interval where `f < 0` (roots or domain ends, as text) with a rational witness in
/// it, or a root of `f` (`from = to`, the witness its isolating interval's midpoint).
fn where_not_positive(
    f: &P,
    a: &Rational,
    b: &Rational,
) -> Result<Option<(String, String, Rational)>, CanalError> {
    if f.is_zero() {
        return Ok(Some((format_scalar(a), format_scalar(b), a.clone())));
    }
    let mut roots = isolate_real_roots_in(f, a, b)?;
    if roots.is_empty() && f.eval(a) > Rational::ZERO {
        return Ok(None);
    }
    // the gaps between the roots (and the ends) where f < 0, else a root where f = 0;
    // isolating intervals may share an endpoint (not a root): refine them first
    let width = Rational::from_ratio(1, 1 << 20);
    for iv in &mut roots {
        if !iv.is_exact() {
            iv.refine(f, &width)?;
        }
    }
    let mut cuts: Vec<(Rational, Rational, String)> =
        vec![(a.clone(), a.clone(), format_scalar(a))];
    for iv in &roots {
        cuts.push((iv.lo.clone(), iv.hi.clone(), describe(iv, f)));
    }
    cuts.push((b.clone(), b.clone(), format_scalar(b)));
    for w in cuts.windows(2) {
        let (left, right) = (&w[0], &w[1]);
        if left.1 <= right.0 {
            let s = (left.1.clone() + right.0.clone()) / Rational::from(2);
            if f.eval(&s) < Rational::ZERO {
                return Ok(Some((left.2.clone(), right.2.clone(), s)));
            }
        }
    }
    // f ≥ 0 with a root
    let iv = roots
        .first()
        .cloned()
        .unwrap_or_else(|| RootInterval::exact(a.clone()));
    let t = describe(&iv, f);
    Ok(Some((t.clone(), t, iv.midpoint())))
}

/// Refuses a weight `W` with a root in `[a, b]` (a point of the spine at infinity) and
/// `a > b`.
fn check_interval_and_weight(
    spine: &CanalSpine<Rational>,
    a: &Rational,
    b: &Rational,
) -> Result<(), CanalError> {
    if a > b {
        return Err(CanalError::InvalidArgument(format!(
            "empty parameter interval [{}, {}]",
            format_scalar(a),
            format_scalar(b)
        )));
    }
    if let Some(iv) = isolate_real_roots_in(spine.weight(), a, b)?.first() {
        return Err(CanalError::DegenerateSpine(format!(
            "the spine weight W vanishes at t = {} in [{}, {}] (a point at infinity)",
            describe(iv, spine.weight()),
            format_scalar(a),
            format_scalar(b)
        )));
    }
    Ok(())
}

/// The polynomial `F` of the module docs for a canal surface of any (rational) radius:
/// `F(t) > 0` iff the characteristic circle at `t` keeps off the characteristic points of
/// the sphere family (no local self-intersection there), for `W(t) ≠ 0`.
pub fn canal_regularity_polynomial(spine: &CanalSpine<Rational>) -> P {
    let w = spine.weight();
    let wd = w.derivative();
    let m = spine.center_polys();
    let r = spine.radius_poly();
    let two = Rational::from(2);
    let a: [P; 3] = core::array::from_fn(|i| &(w * &m[i].derivative()) - &(&wd * &m[i]));
    let b = &(w * &r.derivative()) - &(&wd * r);
    let c: [P; 3] =
        core::array::from_fn(|i| &(w * &a[i].derivative()) - &(&wd * &a[i]).scale(&two));
    let d = &(w * &b.derivative()) - &(&wd * &b).scale(&two);
    let aa = norm_sq(&a);
    let g = &aa - &(&b * &b);
    let h = &g - &(r * &d);
    let k = &(&h * &aa) + &(&(r * &b) * &dot(&a, &c));
    &(&k * &k) - &(&(&(r * r) * &g) * &norm_sq(&cross(&a, &c)))
}

/// Decides exactly that the canal surface of `spine` has no local self-intersection for
/// `t ∈ [a, b]`: `F > 0` (module docs, [`canal_regularity_polynomial`]) and `R ≠ 0` (no
/// sphere of radius 0) there, and returns the certificate. For pipes (constant radius)
/// [`check_pipe_regularity`] states the same as `r·κ < 1`.
///
/// # Errors
/// [`CanalError::SingularCanal`] naming an interval (or point) of `[a, b]` where `F ≤ 0`
/// or `R = 0`; [`CanalError::DegenerateSpine`] where `W = 0` on `[a, b]`;
/// [`CanalError::InvalidArgument`] for `a > b`.
pub fn check_canal_regularity(
    spine: &CanalSpine<Rational>,
    domain: (&Rational, &Rational),
) -> Result<Certificate, CanalError> {
    let (a, b) = domain;
    check_interval_and_weight(spine, a, b)?;
    let singular = |(from, to, witness): (String, String, Rational)| CanalError::SingularCanal {
        from,
        to,
        witness: format_scalar(&witness),
    };
    let r = spine.radius_poly();
    if r.is_zero() {
        return Err(CanalError::ZeroRadius);
    }
    if let Some(iv) = isolate_real_roots_in(r, a, b)?.first() {
        let t = describe(iv, r);
        return Err(singular((t.clone(), t, iv.midpoint())));
    }
    let f = canal_regularity_polynomial(spine);
    if let Some(place) = where_not_positive(&f, a, b)? {
        return Err(singular(place));
    }
    Ok(Certificate::holds(
        format!(
            "no local self-intersection for t ∈ [{}, {}]: F = (H|A|² + RB(A·C))² − R²(|A|² − B²)|A × C|² > 0 there (no real root, F({}) > 0; A = WM′ − W′M, B = WR′ − W′R, C = WA′ − 2W′A, H = |A|² − B² − R(WB′ − 2W′B)) — the characteristic circles keep off the characteristic points of the sphere family — and R ≠ 0 (no sphere of radius 0)",
            format_scalar(a),
            format_scalar(b),
            format_scalar(a)
        ),
        true,
    ))
}

/// The polynomials of the module docs for a pipe family (`R = r W`): `(|P|², F)` and `r`.
///
/// # Errors
/// [`CanalError::InvalidArgument`] if the radius is not constant (`R W′ − R′ W ≢ 0`) or
/// zero.
pub fn pipe_regularity_polynomials(
    spine: &CanalSpine<Rational>,
) -> Result<(P, P, Rational), CanalError> {
    let w = spine.weight();
    let r_poly = spine.radius_poly();
    let wd = w.derivative();
    if !(&(r_poly * &wd) - &(&r_poly.derivative() * w)).is_zero() {
        return Err(CanalError::InvalidArgument(
            "the regularity test r·κ < 1 is for pipes (constant radius)".into(),
        ));
    }
    // r = R/W with W ≢ 0: the ratio of leading coefficients
    let r = match (r_poly.degree(), w.degree()) {
        (Some(dr), Some(dw)) if dr == dw => r_poly.leading() / w.leading(),
        _ => {
            return Err(CanalError::InvalidArgument(
                "the pipe radius must be non-zero".into(),
            ))
        }
    };
    let m = spine.center_polys();
    let p: [P; 3] = core::array::from_fn(|i| &(w * &m[i].derivative()) - &(&wd * &m[i]));
    let pd: [P; 3] = core::array::from_fn(|i| p[i].derivative());
    let pp = norm_sq(&p);
    let w2 = w * w;
    let f = &(&(&pp * &pp) * &pp)
        - &(&(&w2 * &w2) * &norm_sq(&cross(&p, &pd))).scale(&(r.clone() * r.clone()));
    Ok((pp, f, r))
}

/// A root for messages: exact when rational, else `≈ x` with its isolating interval.
fn describe(iv: &RootInterval, p: &P) -> String {
    if iv.is_exact() {
        return format_scalar(&iv.lo);
    }
    if let Some(r) = rational_roots(p).into_iter().find(|r| iv.contains(r)) {
        return format_scalar(&r);
    }
    let mut iv = iv.clone();
    let _ = iv.refine(p, &Rational::from_ratio(1, 1 << 30));
    let approx = iv.root_f64(p).unwrap_or_else(|_| iv.midpoint_f64());
    format!("{approx:.6}")
}

/// Decides `r·κ < 1` and `m′ ≠ 0` on `[a, b]` for a pipe family exactly (module docs) and
/// returns the certificate.
///
/// # Errors
/// [`CanalError::ZeroTangent`] where `m′ = 0` on `[a, b]`;
/// [`CanalError::RadiusNotBelowCurvatureRadius`] naming an interval (or point) of `[a, b]`
/// where `r κ ≥ 1`; [`CanalError::DegenerateSpine`] where `W = 0` on `[a, b]`;
/// [`CanalError::InvalidArgument`] as [`pipe_regularity_polynomials`] or for `a > b`.
pub fn check_pipe_regularity(
    spine: &CanalSpine<Rational>,
    domain: (&Rational, &Rational),
) -> Result<Certificate, CanalError> {
    let (a, b) = domain;
    check_interval_and_weight(spine, a, b)?;
    let (pp, f, r) = pipe_regularity_polynomials(spine)?;
    if pp.is_zero() {
        return Err(CanalError::ZeroTangent {
            at: format!(
                "every t (the spine is a point on [{}, {}])",
                format_scalar(a),
                format_scalar(b)
            ),
        });
    }
    if let Some(iv) = isolate_real_roots_in(&pp, a, b)?.first() {
        return Err(CanalError::ZeroTangent {
            at: describe(iv, &pp),
        });
    }
    let Some((from, to, witness)) = where_not_positive(&f, a, b)? else {
        return Ok(Certificate::holds(
            format!(
                "r·κ < 1 and m′ ≠ 0 for t ∈ [{}, {}] (r = {}): F = |P|⁶ − r²W⁴|P × P′|² > 0 there (no real root, F({}) > 0), P = W M′ − W′ M — no local self-intersection",
                format_scalar(a),
                format_scalar(b),
                format_scalar(&r),
                format_scalar(a)
            ),
            true,
        ));
    };
    // 1/κ = r·(|P|⁶/(r²W⁴|P × P′|²))^{1/2} at the witness (∞ where F ≡ |P|⁶)
    let curvature_radius = if f.is_zero() {
        format!("{:.6}", Scalar::to_f64(&r).abs())
    } else {
        let fv = Scalar::to_f64(&f.eval(&witness));
        let ppv = Scalar::to_f64(&pp.eval(&witness));
        let num = ppv * ppv * ppv;
        let den = num - fv; // r²W⁴|P × P′|²
        if den <= 0.0 {
            "∞".into()
        } else {
            format!("{:.6}", Scalar::to_f64(&r).abs() * (num / den).sqrt())
        }
    };
    Err(CanalError::RadiusNotBelowCurvatureRadius {
        radius: format_scalar(&r),
        from,
        to,
        witness: format_scalar(&witness),
        curvature_radius,
    })
}

/// `Dnᵉ·f(N/Dn) = Σ_k f_k N^k Dn^{e−k}` for `deg f ≤ e` (the homogeneous substitution of
/// the spine parameter `p = N/Dn` of the cyclographic parametrization).
fn substitute_ratio(
    f: &P,
    num: &BiPoly<Rational>,
    den: &BiPoly<Rational>,
    e: usize,
) -> BiPoly<Rational> {
    let one = BiPoly::from_t(Poly::constant(Rational::ONE));
    let mut num_pows = vec![one.clone()];
    let mut den_pows = vec![one];
    for k in 1..=e {
        num_pows.push(num_pows[k - 1].mul(num));
        den_pows.push(den_pows[k - 1].mul(den));
    }
    (0..=e).fold(BiPoly::zero(), |acc, k| {
        let c = f.coeff(k);
        if c.is_zero() {
            acc
        } else {
            acc.add(&num_pows[k].mul(&den_pows[e - k]).scale(&c))
        }
    })
}

/// The outcome of [`positive_on_rectangle`].
enum RectangleSign {
    /// `g > 0` on the rectangle, shown with this many boxes.
    Positive(usize),
    /// `g(s, t) ≤ 0` at this point of the rectangle (exact).
    NotPositive(Rational, Rational),
    /// Neither shown after the largest number of boxes: the centre of an undecided box.
    Undecided(Rational, Rational),
}

/// Most boxes [`positive_on_rectangle`] examines before it gives up.
const MAX_RECTANGLE_BOXES: usize = 4096;

/// Decides `g > 0` on `[s₀, s₁] × [t₀, t₁]` exactly: a box whose tensor Bernstein
/// coefficients are all positive is done (convex hull), a corner coefficient `≤ 0` is a value
/// of `g` there (a witness), anything else is bisected in both directions.
fn positive_on_rectangle(
    g: &BiPoly<Rational>,
    rect: &[Rational; 4],
) -> Result<RectangleSign, CanalError> {
    let (m, n) = (g.degree_t().unwrap_or(0), g.degree_u().unwrap_or(0));
    if g.is_zero() {
        return Ok(RectangleSign::NotPositive(rect[0].clone(), rect[2].clone()));
    }
    let two = Rational::from(2);
    let mut todo = vec![rect.clone()];
    let mut boxes = 0;
    while let Some([s0, s1, t0, t1]) = todo.pop() {
        boxes += 1;
        let c = g.bernstein_on((&s0, &s1), (&t0, &t1), m, n)?;
        let corners = [
            (0, &s0, &t0),
            (n, &s0, &t1),
            (m * (n + 1), &s1, &t0),
            (m * (n + 1) + n, &s1, &t1),
        ];
        if let Some((_, s, t)) = corners.iter().find(|(k, _, _)| c[*k] <= Rational::ZERO) {
            return Ok(RectangleSign::NotPositive((*s).clone(), (*t).clone()));
        }
        if c.iter().all(|x| *x > Rational::ZERO) {
            continue;
        }
        let (sm, tm) = (
            (s0.clone() + s1.clone()) / two.clone(),
            (t0.clone() + t1.clone()) / two.clone(),
        );
        if boxes + todo.len() >= MAX_RECTANGLE_BOXES {
            return Ok(RectangleSign::Undecided(sm, tm));
        }
        todo.push([s0.clone(), sm.clone(), t0.clone(), tm.clone()]);
        todo.push([s0, sm.clone(), tm.clone(), t1.clone()]);
        todo.push([sm.clone(), s1.clone(), t0, tm.clone()]);
        todo.push([sm, s1, tm, t1]);
    }
    Ok(RectangleSign::Positive(boxes))
}

/// Decides exactly that the canal surface of the polynomial family `spine`, parametrized by
/// the cyclographic map on the rectangle `[s₀, s₁] × [t₀, t₁]` of Ω(s, t) with the spine
/// parameter `p = N(s, t)/Dn(s, t)` (`param = (N, Dn)`, `Dn ≠ 0` on the rectangle), has no
/// local self-intersection there: the condition of [`check_canal_regularity`], `F(p) > 0` and
/// `R(p) ≠ 0`, for every `p` the rectangle reaches. With `e` the even number `≥ deg F`,
/// `G(s, t) = Dnᵉ·F(N/Dn)` has the sign of `F(p(s, t))`, so the condition is `G > 0` and
/// `Dn^{deg R}·R(N/Dn)` of one sign on the rectangle, both decided by tensor Bernstein
/// coefficients and exact bisection (docs/math/pipes.md#canal-regularity).
///
/// # Errors
/// [`CanalError::SingularCyclographic`] naming a point of the rectangle where `F ≤ 0` or
/// `R = 0`, or where neither sign could be shown after [`MAX_RECTANGLE_BOXES`] boxes (the
/// surface is singular or nearly so there).
pub fn check_cyclographic_regularity(
    spine: &CanalSpine<Rational>,
    param: (&BiPoly<Rational>, &BiPoly<Rational>),
    rect: &[Rational; 4],
) -> Result<Certificate, CanalError> {
    let (num, den) = param;
    let p_at = |s: &Rational, t: &Rational| -> String {
        let d = den.eval(s, t);
        if d.is_zero() {
            "∞".into()
        } else {
            format_scalar(&(num.eval(s, t) / d))
        }
    };
    let singular = |s: Rational, t: Rational, reason: &str| CanalError::SingularCyclographic {
        s: format_scalar(&s),
        t: format_scalar(&t),
        p: p_at(&s, &t),
        reason: reason.to_string(),
    };
    let undecided = "neither sign could be shown after exact bisection into boxes (the surface is singular or nearly so near there)";
    // R ≠ 0: Dn^{deg R}·R(N/Dn) of one sign
    let r = spine.radius_poly();
    if r.is_zero() {
        return Err(CanalError::ZeroRadius);
    }
    let rh = substitute_ratio(r, num, den, r.degree().unwrap_or(0));
    let rh = if rh.eval(&rect[0], &rect[2]) < Rational::ZERO {
        rh.neg()
    } else {
        rh
    };
    let r_boxes = match positive_on_rectangle(&rh, rect)? {
        RectangleSign::Positive(k) => k,
        RectangleSign::NotPositive(s, t) => {
            return Err(singular(s, t, "the sphere radius R(p) changes sign or vanishes there (a sphere of radius 0 is a vertex of the surface)"))
        }
        RectangleSign::Undecided(s, t) => return Err(singular(s, t, undecided)),
    };
    let f = canal_regularity_polynomial(spine);
    let e = f.degree().unwrap_or(0).div_ceil(2) * 2;
    let g = substitute_ratio(&f, num, den, e);
    let f_boxes = match positive_on_rectangle(&g, rect)? {
        RectangleSign::Positive(k) => k,
        RectangleSign::NotPositive(s, t) => {
            return Err(singular(s, t, "F = (H|A|² + RB(A·C))² − R²(|A|² − B²)|A × C|² ≤ 0 there: the characteristic circle meets its neighbours"))
        }
        RectangleSign::Undecided(s, t) => return Err(singular(s, t, undecided)),
    };
    Ok(Certificate::holds(
        format!(
            "no local self-intersection of Γ(s, t) on [{}, {}] × [{}, {}]: with p = N/Dn, Dn^{e}·F(N/Dn) > 0 (F = (H|A|² + RB(A·C))² − R²(|A|² − B²)|A × C|², the characteristic circles keep off the characteristic points; {f_boxes} boxes of exact bisection, all tensor Bernstein coefficients positive) and R(N/Dn) ≠ 0 ({r_boxes} boxes)",
            format_scalar(&rect[0]),
            format_scalar(&rect[1]),
            format_scalar(&rect[2]),
            format_scalar(&rect[3]),
        ),
        true,
    ))
}

/// A rational `s ≥ √x` (an `f64` guess made safe, checked exactly).
pub(crate) fn sqrt_upper(x: &Rational) -> Rational {
    let guess = Scalar::to_f64(x).sqrt() * (1.0 + 1e-12) + f64::MIN_POSITIVE;
    let mut s = Scalar::to_rational(&guess).unwrap_or(Rational::ONE);
    while s.clone() * s.clone() < *x {
        s = s.clone() * Rational::from(2) + Rational::ONE;
    }
    s
}

/// Certifies that no two parts of the pipe of radius `r` around the spine meet: since
/// session 10 the decisive check [`super::check_pipe_embedded`] (exact subdivision of the
/// double-critical pairs, `docs/math/pipes.md#global`); kept under its old name.
///
/// # Errors
/// As [`super::check_pipe_embedded`].
pub fn check_pipe_global(
    spine: &CanalSpine<Rational>,
    domain: (&Rational, &Rational),
) -> Result<Certificate, CanalError> {
    super::self_intersection::check_pipe_embedded(spine, domain)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    fn parabola(r: Rational) -> CanalSpine<Rational> {
        // m = (t, t², 0): κ(0) = 2, the least radius of curvature is 1/2 (at t = 0)
        CanalSpine::polynomial(
            [
                Poly::from_ints(&[0, 1]),
                Poly::from_ints(&[0, 0, 1]),
                Poly::zero(),
            ],
            Poly::constant(r),
        )
    }

    #[test]
    fn parabola_pipe_is_regular_below_the_least_curvature_radius() {
        let (a, b) = (q(-1, 1), q(1, 1));
        let c = check_pipe_regularity(&parabola(q(49, 100)), (&a, &b)).expect("regular");
        assert!(c.holds && c.exact, "{c:?}");
        // F = (1 + 4t²)³ − 4r²
        let (pp, f, r) = pipe_regularity_polynomials(&parabola(q(1, 4))).expect("polys");
        assert_eq!(r, q(1, 4));
        assert_eq!(pp, Poly::from_ints(&[1, 0, 4]));
        assert_eq!(f, &pp.pow(3) - &Poly::constant(q(1, 4)));
    }

    #[test]
    fn parabola_pipe_too_thick_names_the_interval() {
        let (a, b) = (q(-1, 1), q(1, 1));
        // r = 1: r κ ≥ 1 for |t| ≤ √((4^{1/3} − 1)/4) ≈ 0.383210
        match check_pipe_regularity(&parabola(q(1, 1)), (&a, &b)) {
            Err(CanalError::RadiusNotBelowCurvatureRadius {
                from,
                to,
                witness,
                curvature_radius,
                ..
            }) => {
                assert_eq!(from, "-0.383210");
                assert_eq!(to, "0.383210");
                assert_eq!(witness, "0");
                assert_eq!(curvature_radius, "0.500000");
            }
            other => panic!("{other:?}"),
        }
        // r = 1/2 touches: r κ = 1 exactly at t = 0
        match check_pipe_regularity(&parabola(q(1, 2)), (&a, &b)) {
            Err(CanalError::RadiusNotBelowCurvatureRadius { from, to, .. }) => {
                assert_eq!((from.as_str(), to.as_str()), ("0", "0"));
            }
            other => panic!("{other:?}"),
        }
        // away from the vertex the same radius is fine
        let c = check_pipe_regularity(&parabola(q(1, 2)), (&q(1, 10), &b)).expect("regular");
        assert!(c.holds);
    }

    #[test]
    fn canal_condition_is_the_pipe_condition_for_constant_radius() {
        // F_canal = |A|²·F_pipe with |A|² = 1 + 4t² for the parabola (W = 1)
        for r in [q(1, 4), q(1, 2), q(3, 1)] {
            let s = parabola(r.clone());
            let (pp, f_pipe, _) = pipe_regularity_polynomials(&s).expect("pipe");
            assert_eq!(canal_regularity_polynomial(&s), &pp * &f_pipe);
        }
        let (a, b) = (q(-1, 1), q(1, 1));
        let c = check_canal_regularity(&parabola(q(49, 100)), (&a, &b)).expect("regular");
        assert!(c.holds && c.exact, "{c:?}");
        assert!(matches!(
            check_canal_regularity(&parabola(q(1, 1)), (&a, &b)),
            Err(CanalError::SingularCanal { .. })
        ));
    }

    fn on_z_axis(r: Poly<Rational>) -> CanalSpine<Rational> {
        CanalSpine::polynomial([Poly::zero(), Poly::zero(), Poly::from_ints(&[0, 1])], r)
    }

    #[test]
    fn cone_of_revolution_is_regular_away_from_its_vertex() {
        // spheres of radius 1 + t/2 centred at (0, 0, t): a cone, vertex at t = −2
        let s = on_z_axis(Poly::new(vec![q(1, 1), q(1, 2)]));
        // F = (1 − ṙ²)² = 9/16 (m̈ = 0)
        assert_eq!(canal_regularity_polynomial(&s), Poly::constant(q(9, 16)));
        let c = check_canal_regularity(&s, (&q(0, 1), &q(1, 1))).expect("regular");
        assert!(c.holds && c.exact);
        match check_canal_regularity(&s, (&q(-3, 1), &q(0, 1))) {
            Err(CanalError::SingularCanal { from, to, .. }) => {
                assert_eq!((from.as_str(), to.as_str()), ("-2", "-2"));
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn surface_of_revolution_with_a_cusp_is_refused() {
        // r = t²/2 on the z-axis: H = 1 − ṙ² − r r̈ = 1 − 3t²/2 vanishes at t = √(2/3), where
        // the meridian of the envelope has a cusp (|ṁ| > |ṙ| there: the envelope is real)
        let s = on_z_axis(Poly::new(vec![q(0, 1), q(0, 1), q(1, 2)]));
        assert_eq!(
            canal_regularity_polynomial(&s),
            Poly::new(vec![q(1, 1), q(0, 1), q(-3, 2)]).pow(2)
        );
        match check_canal_regularity(&s, (&q(1, 2), &q(9, 10))) {
            Err(CanalError::SingularCanal { from, to, .. }) => {
                assert_eq!((from.as_str(), to.as_str()), ("0.816497", "0.816497"));
            }
            other => panic!("{other:?}"),
        }
        assert!(check_canal_regularity(&s, (&q(1, 2), &q(4, 5))).is_ok());
    }

    #[test]
    fn cusp_is_a_zero_tangent() {
        let s = CanalSpine::polynomial(
            [
                Poly::from_ints(&[0, 0, 1]),
                Poly::from_ints(&[0, 0, 0, 1]),
                Poly::zero(),
            ],
            Poly::constant(q(1, 10)),
        );
        match check_pipe_regularity(&s, (&q(-1, 1), &q(1, 1))) {
            Err(CanalError::ZeroTangent { at }) => assert_eq!(at, "0"),
            other => panic!("{other:?}"),
        }
        // on [1/2, 1] the cusp is outside
        assert!(check_pipe_regularity(&s, (&q(1, 2), &q(1, 1))).is_ok());
    }

    #[test]
    fn rational_spine_circle_has_constant_curvature() {
        // the circle (1 − t², 2t, 0)/(1 + t²) of radius 1: r κ < 1 iff |r| < 1
        let w = Poly::from_ints(&[1, 0, 1]);
        let fam = |r: Rational| {
            CanalSpine::new(
                w.clone(),
                [
                    Poly::from_ints(&[1, 0, -1]),
                    Poly::from_ints(&[0, 2]),
                    Poly::zero(),
                ],
                w.scale(&r),
            )
            .expect("family")
        };
        let (a, b) = (q(0, 1), q(1, 1));
        assert!(check_pipe_regularity(&fam(q(99, 100)), (&a, &b)).is_ok());
        assert!(matches!(
            check_pipe_regularity(&fam(q(-1, 1)), (&a, &b)),
            Err(CanalError::RadiusNotBelowCurvatureRadius { .. })
        ));
        assert!(matches!(
            check_pipe_regularity(&fam(q(3, 2)), (&a, &b)),
            Err(CanalError::RadiusNotBelowCurvatureRadius { .. })
        ));
    }

    #[test]
    fn global_check_separates_far_parts_and_refuses_a_near_loop() {
        // the parabola is far from itself: certified for a thin pipe
        let (a, b) = (q(-1, 1), q(1, 1));
        let c = check_pipe_global(&parabola(q(1, 20)), (&a, &b)).expect("apart");
        assert!(c.holds && c.exact, "{c:?}");
        // a loop: m = (t² − 1, t³ − t, 0) crosses itself at t = ±1 (the point (0, 0))
        let s = CanalSpine::polynomial(
            [
                Poly::from_ints(&[-1, 0, 1]),
                Poly::from_ints(&[0, -1, 0, 1]),
                Poly::zero(),
            ],
            Poly::constant(q(1, 50)),
        );
        let (a, b) = (q(-3, 2), q(3, 2));
        assert!(check_pipe_regularity(&s, (&a, &b)).is_ok());
        match check_pipe_global(&s, (&a, &b)) {
            Err(CanalError::PipeSelfIntersects { distance, .. }) => {
                let d: f64 = distance.parse().expect("number");
                assert!(d < 1e-6, "{distance}");
            }
            other => panic!("{other:?}"),
        }
        // the same loop on [−1/2, 3/2] (one crossing parameter only): apart
        let c = check_pipe_global(&s, (&q(-1, 2), &b)).expect("apart");
        assert!(c.holds);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(16))]
        /// For a random rational spine of constant radius the canal condition is the pipe
        /// condition times `|A|²` (`A = WM′ − W′M`), as an exact polynomial identity, and the
        /// two checks agree on `[0, 1]`.
        #[test]
        fn canal_and_pipe_conditions_agree_on_random_spines(
            c in proptest::collection::vec(-4i64..=4, 9),
            w in proptest::collection::vec(1i64..=3, 3),
            r in 1i64..=8,
        ) {
            let m: [Poly<Rational>; 3] =
                core::array::from_fn(|i| Poly::from_ints(&c[3 * i..3 * i + 3]));
            let w = Poly::from_ints(&w);
            let rr = q(r, 10);
            let s = CanalSpine::new(w.clone(), m, w.scale(&rr));
            proptest::prop_assume!(s.is_ok());
            let s = s.expect("checked");
            let (pp, f_pipe, _) = pipe_regularity_polynomials(&s).expect("pipe");
            proptest::prop_assert_eq!(canal_regularity_polynomial(&s), &pp * &f_pipe);
            let (a, b) = (q(0, 1), q(1, 1));
            let pipe = check_pipe_regularity(&s, (&a, &b));
            let canal = check_canal_regularity(&s, (&a, &b));
            proptest::prop_assert_eq!(pipe.is_ok(), canal.is_ok(), "{:?} / {:?}", pipe, canal);
        }
    }
}
