//! Approximation of any rational space curve by a `G¹` spline of spatial PH quintics with a
//! certified bound on the distance (docs/math/pipes.md, "Pipes around any spine").
//!
//! A spine whose `|m′|²` is not a sum of two squares over `Q` has no exact rational pipe
//! (Peternell–Pottmann 1997, "Computing rational parametrizations of canal surfaces"); a
//! PH curve always has one. So the spine `c(t) = X(t)/W(t)` (rational Bézier pieces, every
//! weight `> 0`) is replaced by spatial PH quintics `r_k(s)`, `s ∈ [0, 1]`, each the
//! Hermite interpolant (Farouki, al-Kandari, Sakkalis 2002; Farouki 2008, *Pythagorean-
//! Hodograph Curves*, §25.2) of the spine's points and scaled tangents at the ends of a
//! parameter interval `[t₀, t₁]`, `h = t₁ − t₀`:
//!
//! `A(s) = A₀b₀² + A₁b₁² + A₂b₂²`, `r′ = A i A*`, `A₂ = Q̂(c′(t₁)h)e^{iφ₂}`,
//! `(4A₁ + 3(A₀ + A₂)) i (4A₁ + 3(A₀ + A₂))* = 120Δp − 15(d₀ + d₁) + 5(A₀ i A₂* + A₂ i A₀*)`.
//!
//! Consecutive pieces share their quaternion up to a positive rational factor,
//! `A₀⁽ᵏ⁺¹⁾ = λ A₂⁽ᵏ⁾`, and each piece starts at the exact end point of the previous one, so
//! the spline is exactly `G¹` (exactly `C¹` for `λ = 1`) whatever the rounding: the
//! coefficients are solved in `f64` (the free angles `φ₁`, `φ₂` chosen by the least sampled
//! distance) and rounded to dyadic rationals; the exact PH quintic that results is what is
//! certified.
//!
//! **The distance bound.** On `[t₀, t₁]` the spine is matched to the piece by the monotone
//! cubic correspondence `t = t₀ + hφ(s)`, `φ` with Bernstein coefficients
//! `(0, m₀/3, 2/3, 1)` (`φ′(0) = m₀`, the ratio of the piece's start speed to the spine's,
//! `φ′(1) = 1`; `φ′ > 0` on `[0, 1]` for `0 < m₀ < 2`, its Bernstein coefficients being
//! `m₀, 3 − m₀ − 1, 1`). Then for every `s`
//!
//! `|r(s) − c(t₀ + hφ(s))|² = N(s)/W̃(s)²`, `N = |r W̃ − X̃|²`, `W̃ = W∘(t₀ + hφ)`,
//! `X̃ = X∘(t₀ + hφ)`,
//!
//! and the convex-hull property of the Bernstein form bounds it by
//! `max_j N_j / (min_j W̃_j)²` (subdividing `N` and `W̃` at `½` where that is not tight
//! enough). As `φ` is a bijection of `[0, 1]`, the bound `ε` bounds the Fréchet distance of
//! the two curves, hence their Hausdorff distance. All of it is exact rational arithmetic.
//!
//! **Closed spines.** When the spine ends where it starts with the same tangent direction
//! (`G¹`-closed), the spline is fitted a little below the tolerance and its last two pieces
//! are re-solved with [`super::closure::close_two_pieces`] so that it ends exactly at its
//! start with its start tangent direction; their bounds are re-derived, and the certificates
//! include the seam joint. If that fails within three margins (`3/4`, `1/2`, `1/8` of the
//! tolerance) the open spline is returned ([`PhSplineApproximation::is_closed`] says which;
//! [`PhApproximationOptions::close`] turns the closing off).

use super::hodograph::{solve_qiq, PhCurve};
use super::spatial_hermite::{golden_min, middle_coefficient};
use super::util::aib;
use super::PhError;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::rational::round_decimal;
use rcagd_algebra::{bernstein, format_scalar, Certificate, Poly, Rational, Scalar};
use rcagd_geom::BezierCurve;

/// Pieces at most (a tolerance that would need more is refused).
pub const DEFAULT_MAX_PIECES: usize = 1024;

/// The smallest parameter step tried, as a power of two (`2⁻³⁰` of a spine piece).
const MIN_STEP_LOG2: u32 = 30;

/// Options of [`approximate_by_ph_quintics`].
#[derive(Debug, Clone, PartialEq)]
pub struct PhApproximationOptions {
    /// The bound to reach on the distance between the spline and the spine (absolute, `> 0`).
    pub tolerance: Rational,
    /// The most pieces allowed.
    pub max_pieces: usize,
    /// Close the spline exactly when the spine is `G¹`-closed (default `true`; module docs,
    /// "Closed spines").
    pub close: bool,
}

impl PhApproximationOptions {
    /// The tolerance `tolerance` with at most [`DEFAULT_MAX_PIECES`] pieces.
    pub fn new(tolerance: Rational) -> Self {
        PhApproximationOptions {
            tolerance,
            max_pieces: DEFAULT_MAX_PIECES,
            close: true,
        }
    }

    /// The default tolerance: `10⁻⁶` of the diagonal of the box around the spine's control
    /// points (rounded up to two significant digits).
    pub fn relative(spine: &[BezierCurve<Rational>]) -> Self {
        let diag = spine_size(spine);
        let tol = round_decimal(
            &Rational::try_from(diag * 1e-6).unwrap_or(Rational::ONE),
            2,
            true,
        );
        let tol = if tol > Rational::ZERO {
            tol
        } else {
            Rational::from_ratio(1, 1_000_000)
        };
        Self::new(tol)
    }
}

/// The diagonal of the box around the Euclidean control points of the spine (`f64`).
pub fn spine_size(spine: &[BezierCurve<Rational>]) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for c in spine {
        for p in c.control_points() {
            let w = p.first().map_or(0.0, Scalar::to_f64);
            if w == 0.0 {
                continue;
            }
            for k in 0..3 {
                let x = p.get(k + 1).map_or(0.0, Scalar::to_f64) / w;
                lo[k] = lo[k].min(x);
                hi[k] = hi[k].max(x);
            }
        }
    }
    let d2: f64 = (0..3)
        .map(|k| {
            let d = hi[k] - lo[k];
            if d.is_finite() {
                d * d
            } else {
                0.0
            }
        })
        .sum();
    d2.sqrt()
}

/// One piece of the approximating spline.
#[derive(Debug, Clone, PartialEq)]
pub struct ApproximationPiece {
    /// The exact PH quintic on `s ∈ [0, 1]`.
    pub curve: PhCurve<Rational>,
    /// The index of the spine curve it approximates.
    pub spine_piece: usize,
    /// The interval `[t₀, t₁]` of that spine curve's parameter.
    pub interval: (Rational, Rational),
    /// `m₀ = φ′(0)` of the correspondence `t = t₀ + hφ(s)`.
    pub start_slope: Rational,
    /// The certified bound `ε` on `|r(s) − c(t₀ + hφ(s))|`.
    pub deviation: Rational,
}

/// A `G¹` spline of exact spatial PH quintics within a certified distance of a rational
/// spine ([`approximate_by_ph_quintics`]).
#[derive(Debug, Clone, PartialEq)]
pub struct PhSplineApproximation {
    spine: Vec<BezierCurve<Rational>>,
    pieces: Vec<ApproximationPiece>,
    tolerance: Rational,
    /// The spline ends exactly where it starts, with its start tangent direction.
    closed: bool,
}

impl PhSplineApproximation {
    /// The pieces, in order along the spine.
    pub fn pieces(&self) -> &[ApproximationPiece] {
        &self.pieces
    }

    /// The PH quintics, in order.
    pub fn curves(&self) -> Vec<PhCurve<Rational>> {
        self.pieces.iter().map(|p| p.curve.clone()).collect()
    }

    /// `true` if the spline is closed: its last piece ends exactly at the first piece's start
    /// with the first piece's start tangent direction (`G¹`). A `G¹`-closed spine gives a
    /// closed spline (module docs, "Closed spines").
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The tolerance asked for.
    pub fn tolerance(&self) -> &Rational {
        &self.tolerance
    }

    /// The spine approximated.
    pub fn spine(&self) -> &[BezierCurve<Rational>] {
        &self.spine
    }

    /// The certified bound on the distance between the spline and the spine: the largest
    /// piece bound.
    pub fn deviation(&self) -> Rational {
        self.pieces
            .iter()
            .map(|p| p.deviation.clone())
            .max()
            .unwrap_or(Rational::ZERO)
    }

    /// The spline with `f64` coefficients (for fast evaluation; the exact one is certified).
    pub fn to_f64(&self) -> Vec<PhCurve<f64>> {
        self.pieces.iter().map(|p| p.curve.to_f64()).collect()
    }

    /// The certificates: every piece is a PH curve (hodograph identities), lies within its
    /// bound `ε_k ≤` tolerance of the spine (re-derived exactly: `max N_j ≤ ε² (min W̃_j)²`
    /// on each leaf of the subdivision, `0 < m₀ < 2`), and consecutive pieces meet with the
    /// same tangent direction (`G¹`) where the spine does.
    pub fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        let many = self.pieces.len() > 1;
        for (k, p) in self.pieces.iter().enumerate() {
            let tag = |s: String| {
                if many {
                    format!("PH piece {k}: {s}")
                } else {
                    s
                }
            };
            for mut c in p.curve.certify() {
                c.property = tag(c.property);
                out.push(c);
            }
            out.push(self.deviation_certificate(k, p));
        }
        for (k, w) in self.pieces.windows(2).enumerate() {
            out.extend(joint_certificates(k, &w[0].curve, &w[1].curve));
        }
        if self.closed {
            if let (Some(last), Some(first)) = (self.pieces.last(), self.pieces.first()) {
                out.extend(joint_certificates_to(
                    self.pieces.len() - 1,
                    0,
                    &last.curve,
                    &first.curve,
                ));
            }
        }
        out.push(Certificate::decide(
            format!(
                "the PH spline lies within {} of the spine (certified Fréchet, hence Hausdorff, distance bound; tolerance {})",
                format_scalar(&self.deviation()),
                format_scalar(&self.tolerance)
            ),
            self.deviation() <= self.tolerance,
            true,
            || {
                format!(
                    "bound {} exceeds the tolerance",
                    format_scalar(&self.deviation())
                )
            },
        ));
        out
    }

    fn deviation_certificate(&self, k: usize, p: &ApproximationPiece) -> Certificate {
        let property = format!(
            "PH piece {k} lies within ε = {} of spine curve {} on t ∈ [{}, {}] (|r(s) − c(t₀ + hφ(s))|² ≤ max N_j/(min W̃_j)² ≤ ε², Bernstein bounds of N = |r W̃ − X̃|² and W̃ > 0, φ monotone with φ′(0) = {})",
            format_scalar(&p.deviation),
            p.spine_piece,
            format_scalar(&p.interval.0),
            format_scalar(&p.interval.1),
            format_scalar(&p.start_slope)
        );
        let Some(spine) = self.spine.get(p.spine_piece) else {
            return Certificate::fails(property, "no such spine curve", true);
        };
        let two = Rational::from(2);
        if p.start_slope <= Rational::ZERO || p.start_slope >= two {
            return Certificate::fails(
                property,
                "φ′(0) not in (0, 2): φ may not be monotone",
                true,
            );
        }
        let eps2 = &p.deviation * &p.deviation;
        match distance_bound_squared(&p.curve, spine, &p.interval, &p.start_slope, &eps2) {
            Ok(b) if b <= eps2 => Certificate::holds(property, true),
            Ok(b) => Certificate::fails(
                property,
                format!(
                    "the Bernstein bound of the squared distance is {}",
                    format_scalar(&b)
                ),
                true,
            ),
            Err(e) => Certificate::fails(property, e.to_string(), true),
        }
    }
}

impl crate::Certified for PhSplineApproximation {
    fn certify(&self) -> Vec<Certificate> {
        PhSplineApproximation::certify(self)
    }
}

/// `G⁰` (the next piece starts at the end point) and `G¹` (the end and start hodographs are
/// positive multiples) between two consecutive PH pieces.
fn joint_certificates(k: usize, a: &PhCurve<Rational>, b: &PhCurve<Rational>) -> Vec<Certificate> {
    joint_certificates_to(k, k + 1, a, b)
}

/// [`joint_certificates`] between piece `k` and piece `next` (the seam of a closed spline:
/// `next = 0`).
fn joint_certificates_to(
    k: usize,
    next: usize,
    a: &PhCurve<Rational>,
    b: &PhCurve<Rational>,
) -> Vec<Certificate> {
    let end = a.eval(&Rational::ONE);
    let start = b.start();
    let g0 = Certificate::decide(
        format!("PH pieces {k} and {next} meet (G⁰: r_{k}(1) = r_{next}(0))"),
        end == *start,
        true,
        || "the end point differs from the next start point".into(),
    );
    let (ha, hb) = (a.hodograph_bernstein(), b.hodograph_bernstein());
    let (Some(te), Some(ts)) = (ha.last(), hb.first()) else {
        return vec![g0];
    };
    let (cross, dot) = cross_dot(te, ts);
    let g1 = Certificate::decide(
        format!(
            "PH pieces {k} and {next} have the same tangent direction at the joint (G¹: r_{k}′(1) × r_{next}′(0) = 0, r_{k}′(1)·r_{next}′(0) > 0)"
        ),
        cross.iter().all(Rational::is_zero) && dot > Rational::ZERO,
        true,
        || "the spine has a corner here (its tangent directions differ), so the spline has one too".into(),
    );
    vec![g0, g1]
}

/// `max_j N_j / (min_j W̃_j)²` over the leaves of a subdivision of `[0, 1]` (a leaf is split
/// at `½` while its bound exceeds `target` or its `W̃` coefficients are not all positive, at
/// most `depth` times).
fn bernstein_ratio_bound(
    n: &[Rational],
    w: &[Rational],
    target: &Rational,
    depth: u32,
) -> Result<Rational, PhError> {
    let min_w = w.iter().min().cloned().unwrap_or(Rational::ZERO);
    let max_n = n.iter().max().cloned().unwrap_or(Rational::ZERO);
    let bound = (min_w > Rational::ZERO).then(|| &max_n / (&min_w * &min_w));
    match bound {
        Some(b) if b <= *target || depth == 0 => Ok(b),
        None if depth == 0 => Err(PhError::Degenerate(
            "the spine's weight is not positive on the interval".into(),
        )),
        _ => {
            let half = Rational::from_ratio(1, 2);
            let (n0, n1) = bernstein::subdivide(n, &half);
            let (w0, w1) = bernstein::subdivide(w, &half);
            let b0 = bernstein_ratio_bound(&n0, &w0, target, depth - 1)?;
            let b1 = bernstein_ratio_bound(&n1, &w1, target, depth - 1)?;
            Ok(b0.max(b1))
        }
    }
}

/// The certified bound on `max_s |r(s) − c(t₀ + hφ(s))|²` (see the module doc).
fn distance_bound_squared(
    curve: &PhCurve<Rational>,
    spine: &BezierCurve<Rational>,
    (t0, t1): &(Rational, Rational),
    m0: &Rational,
    target: &Rational,
) -> Result<Rational, PhError> {
    let piece = spine.restrict(t0, t1)?;
    // φ(s) with Bernstein coefficients (0, m₀/3, 2/3, 1)
    let three = Rational::from(3);
    let phi = bernstein::from_bernstein(&[
        Rational::ZERO,
        m0 / &three,
        Rational::from(2) / &three,
        Rational::ONE,
    ]);
    let homogeneous: Vec<Poly<Rational>> = piece
        .coordinate_polys()
        .iter()
        .map(|p| p.compose(&phi))
        .collect();
    let [w, x @ ..] = homogeneous.as_slice() else {
        return Err(PhError::Degenerate(
            "a spine curve without coordinates".into(),
        ));
    };
    if x.len() != 3 {
        return Err(PhError::DegreeMismatch(format!(
            "the spine must lie in 3-space, not {}-space",
            x.len()
        )));
    }
    let r = curve.position();
    let mut n = Poly::zero();
    for (rk, xk) in r.iter().zip(x) {
        let d = &(rk * w) - xk;
        n = &n + &(&d * &d);
    }
    let deg_n = n.degree().unwrap_or(0);
    let deg_w = w.degree().unwrap_or(0);
    let nb = bernstein::to_bernstein(&n, deg_n)?;
    let wb = bernstein::to_bernstein(w, deg_w)?;
    bernstein_ratio_bound(&nb, &wb, target, 5)
}

/// A rational `ε ≥ √b` with few digits: the exact upper bound of
/// [`crate::canal::regularity::sqrt_upper`] rounded up to 3 significant decimals.
pub(crate) fn sqrt_upper_decimal(b: &Rational) -> Rational {
    if *b <= Rational::ZERO {
        return Rational::ZERO;
    }
    round_decimal(&crate::canal::regularity::sqrt_upper(b), 3, true)
}

/// `x` rounded to the grid `2⁻ᵏ`.
/// The bits `k` of the grid `2⁻ᵏ` the quaternion coefficients (of size `≤ amax`) are rounded
/// to for a tolerance `tol`: a change `δ` of `A` moves `r` by at most `≈ 2|A|δ`, so
/// `2⁻ᵏ ≤ tol/(512·amax)` (at least 8, at most 200 bits).
fn rounding_bits(amax: f64, tol: f64) -> u32 {
    let amax = amax.max(1e-300);
    ((512.0 * amax / tol).log2().ceil().max(8.0) as u32).min(200)
}

/// `x` rounded to a multiple of `2⁻ᵏ` (`None` if not finite or `k` too large).
pub(crate) fn dyadic(x: f64, k: u32) -> Option<Rational> {
    let scale = 2f64.powi(i32::try_from(k).ok()?);
    let n = Rational::try_from((x * scale).round()).ok()?;
    // 2ᵏ is exact in f64 for k ≤ 1023
    let den = Rational::try_from(scale).ok()?;
    Some(n / den)
}

fn q_rational(q: &Quaternion<f64>, k: u32) -> Option<Quaternion<Rational>> {
    Some(Quaternion::new(
        dyadic(q.w, k)?,
        dyadic(q.x, k)?,
        dyadic(q.y, k)?,
        dyadic(q.z, k)?,
    ))
}

fn norm3(v: &[f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// Point and derivative of the spine curve at `t` (`f64`).
fn spine_eval(c: &BezierCurve<f64>, t: f64) -> Option<([f64; 3], [f64; 3])> {
    let d = c.derivatives_euclidean(&t, 1).ok()?;
    let p = d.first()?;
    let v = d.get(1)?;
    Some((
        [*p.first()?, *p.get(1)?, *p.get(2)?],
        [*v.first()?, *v.get(1)?, *v.get(2)?],
    ))
}

/// The `f64` quintic with `A₀` fixed and free angles `φ₁`, `φ₂` (or `None` where the
/// construction degenerates).
fn hermite_f64(
    p0: &[f64; 3],
    a0: &Quaternion<f64>,
    p1: &[f64; 3],
    d1: &[f64; 3],
    phi1: f64,
    phi2: f64,
) -> Option<PhCurve<f64>> {
    let a2 = solve_qiq(d1, Some((phi2.cos(), phi2.sin()))).ok()?;
    let d = aib(a0, a0);
    let d0 = [d.x, d.y, d.z];
    let a1 =
        middle_coefficient((p0, &d0), (p1, d1), a0, &a2, Some((phi1.cos(), phi1.sin()))).ok()?;
    PhCurve::new(vec![a0.clone(), a1, a2], *p0).ok()
}

/// The sampled distance `max_s |r(s) − c(t₀ + hφ(s))|` (`f64`, 17 samples).
fn sampled_distance(
    curve: &PhCurve<f64>,
    spine: &BezierCurve<f64>,
    t0: f64,
    h: f64,
    m0: f64,
) -> f64 {
    let pts: Vec<f64> = curve.control_points().into_iter().flatten().collect();
    let mut worst: f64 = 0.0;
    for j in 0..=16 {
        let s = f64::from(j) / 16.0;
        // φ(s) = m₀ s(1−s)² + 2 s²(1−s) + s³ (Bernstein (0, m₀/3, 2/3, 1))
        let phi = m0 * s * (1.0 - s) * (1.0 - s) + 2.0 * s * s * (1.0 - s) + s * s * s;
        let r = bernstein::eval_blocks(&pts, 3, &s);
        let Ok(c) = spine.eval(&(t0 + h * phi)) else {
            return f64::INFINITY;
        };
        let d: Vec<f64> = r.iter().zip(&c).map(|(a, b)| a - b).collect();
        let n = d.iter().map(|x| x * x).sum::<f64>().sqrt();
        if !n.is_finite() || d.len() != 3 {
            return f64::INFINITY;
        }
        worst = worst.max(n);
    }
    worst
}

/// The best `(φ₁, φ₂)` by sampled distance: a 12 × 12 grid, then cyclic golden-section
/// refinement.
fn best_angles(dist: impl Fn(f64, f64) -> f64) -> (f64, f64, f64) {
    use core::f64::consts::PI;
    let mut best = (0.0, 0.0, f64::INFINITY);
    for i in 0..12 {
        for j in 0..12 {
            let (a, b) = (f64::from(i) * PI / 6.0, f64::from(j) * PI / 6.0);
            let d = dist(a, b);
            if d < best.2 {
                best = (a, b, d);
            }
        }
    }
    let mut half = PI / 6.0;
    for _ in 0..3 {
        let (a, b, _) = best;
        let (na, da) = golden_min(|x| dist(x, b), a - half, a + half, 14);
        if da < best.2 {
            best = (na, b, da);
        }
        let (a, b, _) = best;
        let (nb, db) = golden_min(|x| dist(a, x), b - half, b + half, 14);
        if db < best.2 {
            best = (a, nb, db);
        }
        half *= 0.5;
    }
    best
}

/// The rational `λ > 0` with small numerator and denominator nearest to `x > 0` (best
/// approximation with denominator ≤ 1024).
fn small_rational(x: f64) -> Rational {
    let mut best = (Rational::ONE, f64::INFINITY);
    for den in 1..=1024i64 {
        let num = (x * den as f64).round();
        if num < 1.0 {
            continue;
        }
        let err = (num / den as f64 - x).abs();
        if err < best.1 * 0.999 {
            best = (Rational::from_ratio(num as i64, den), err);
        }
        if err < 1e-12 * x {
            break;
        }
    }
    best.0
}

struct Fit {
    piece: ApproximationPiece,
    end_point: [Rational; 3],
    end_quaternion: Quaternion<Rational>,
}

/// State carried from one piece to the next.
struct Carry {
    point: [Rational; 3],
    /// `A₂` of the previous piece (`None` at the start).
    quaternion: Option<Quaternion<Rational>>,
    /// `true` if the spine is `G¹` where the next piece starts (inside a spine curve, or at
    /// a joint of two curves with the same tangent direction).
    smooth: bool,
}

/// The affine point of a homogeneous control point (`None` for weight 0).
fn affine(h: &[Rational]) -> Option<[Rational; 3]> {
    let w = h.first()?;
    if w.is_zero() {
        return None;
    }
    Some(core::array::from_fn(|k| {
        h.get(k + 1).cloned().unwrap_or(Rational::ZERO) / w.clone()
    }))
}

/// Where Bézier curve `a` ends and `b` starts: `(end point of a, start point of b, end
/// tangent of a, start tangent of b)`, the tangents as `p_n − p_{n−1}` and `p_1 − p_0` of the
/// affine control points (positive multiples of the true tangents when the weights are
/// positive); `None` if one of those control points has weight 0.
pub(crate) fn joint_tangents(
    a: &BezierCurve<Rational>,
    b: &BezierCurve<Rational>,
) -> Option<[[Rational; 3]; 4]> {
    let n = a.degree();
    let pe = affine(a.control_point(n))?;
    let pe1 = affine(a.control_point(n.saturating_sub(1)))?;
    let ps = affine(b.control_point(0))?;
    let ps1 = affine(b.control_point(1.min(b.degree())))?;
    let te = core::array::from_fn(|i| &pe[i] - &pe1[i]);
    let ts = core::array::from_fn(|i| &ps1[i] - &ps[i]);
    Some([pe, ps, te, ts])
}

/// `(u × v, u·v)`.
pub(crate) fn cross_dot(u: &[Rational; 3], v: &[Rational; 3]) -> ([Rational; 3], Rational) {
    let cross = [
        &u[1] * &v[2] - &u[2] * &v[1],
        &u[2] * &v[0] - &u[0] * &v[2],
        &u[0] * &v[1] - &u[1] * &v[0],
    ];
    let dot = (0..3).fold(Rational::ZERO, |acc, i| acc + &u[i] * &v[i]);
    (cross, dot)
}

/// `true` if `a` ends where `b` starts, with the same tangent direction (exact).
fn same_tangent_direction(a: &BezierCurve<Rational>, b: &BezierCurve<Rational>) -> bool {
    let Some([pe, ps, te, ts]) = joint_tangents(a, b) else {
        return false;
    };
    let (cross, dot) = cross_dot(&te, &ts);
    cross.iter().all(Rational::is_zero) && dot > Rational::ZERO && pe == ps
}

#[allow(clippy::too_many_arguments)]
fn fit_piece(
    spine: &BezierCurve<Rational>,
    spine_f: &BezierCurve<f64>,
    index: usize,
    (t0, t1): (&Rational, &Rational),
    carry: &Carry,
    tolerance: &Rational,
) -> Result<Option<Fit>, PhError> {
    let (t0f, t1f) = (Scalar::to_f64(t0), Scalar::to_f64(t1));
    let h = t1f - t0f;
    let (Some((_, v0)), Some((p1, v1))) = (spine_eval(spine_f, t0f), spine_eval(spine_f, t1f))
    else {
        return Ok(None);
    };
    let d0_target = [v0[0] * h, v0[1] * h, v0[2] * h];
    let d1 = [v1[0] * h, v1[1] * h, v1[2] * h];
    let (n0, n1) = (norm3(&d0_target), norm3(&d1));
    if !(n0 > 0.0 && n1 > 0.0 && n0.is_finite() && n1.is_finite()) {
        return Err(PhError::ZeroTangent(format!(
            "the spine's tangent vanishes (or is not finite) near t ∈ [{}, {}] of spine curve {index}",
            format_scalar(t0),
            format_scalar(t1)
        )));
    }
    let p0: [f64; 3] = core::array::from_fn(|k| Scalar::to_f64(&carry.point[k]));
    let tol = Scalar::to_f64(tolerance);
    let grid = rounding_bits(n0.max(n1).sqrt(), tol);
    // A₀: λA₂ of the previous piece where the spine turns smoothly, else new
    let continued = carry
        .quaternion
        .as_ref()
        .filter(|_| carry.smooth)
        .map(|prev| {
            let pf = prev.to_f64();
            let dprev = aib(&pf, &pf);
            let lambda = small_rational((n0 / norm3(&[dprev.x, dprev.y, dprev.z])).sqrt());
            prev.scale(&lambda)
        });
    let fixed_a0 = continued.clone();
    let mut best: Option<(f64, PhCurve<f64>)> = None;
    let starts: Vec<Quaternion<f64>> = match &fixed_a0 {
        Some(a0) => vec![a0.to_f64()],
        None => (0..12)
            .filter_map(|i| {
                let phi = f64::from(i) * core::f64::consts::PI / 6.0;
                solve_qiq(&d0_target, Some((phi.cos(), phi.sin()))).ok()
            })
            .collect(),
    };
    for a0 in &starts {
        let d0 = aib(a0, a0);
        let m0 = norm3(&[d0.x, d0.y, d0.z]) / n0;
        let dist = |a: f64, b: f64| {
            hermite_f64(&p0, a0, &p1, &d1, a, b)
                .map_or(f64::INFINITY, |q| sampled_distance(&q, spine_f, t0f, h, m0))
        };
        let (a, b, d) = best_angles(dist);
        if best.as_ref().is_none_or(|x| d < x.0) {
            if let Some(q) = hermite_f64(&p0, a0, &p1, &d1, a, b) {
                best = Some((d, q));
            }
        }
    }
    let Some((estimate, fitted)) = best else {
        return Ok(None);
    };
    if !estimate.is_finite() || estimate > tol {
        return Ok(None);
    }
    let (Some(q0), Some(q1), Some(q2)) = (
        fitted.coefficients().first(),
        fitted.coefficients().get(1),
        fitted.coefficients().get(2),
    ) else {
        return Ok(None);
    };
    let a0 = match fixed_a0 {
        Some(a) => a,
        None => q_rational(q0, grid)
            .ok_or_else(|| PhError::OutOfRange("a preimage coefficient is not finite".into()))?,
    };
    let (Some(a1), Some(a2)) = (q_rational(q1, grid), q_rational(q2, grid)) else {
        return Err(PhError::OutOfRange(
            "a preimage coefficient is not finite".into(),
        ));
    };
    let curve = PhCurve::new(vec![a0.clone(), a1, a2.clone()], carry.point.clone())?;
    let a0f = a0.to_f64();
    let d0 = aib(&a0f, &a0f);
    let m0f = norm3(&[d0.x, d0.y, d0.z]) / n0;
    let m0 = dyadic(m0f, 30).unwrap_or(Rational::ONE);
    if m0 <= Rational::ZERO || m0 >= Rational::from(2) {
        return Ok(None);
    }
    let tol2 = tolerance * tolerance;
    let interval = (t0.clone(), t1.clone());
    let b = distance_bound_squared(&curve, spine, &interval, &m0, &tol2)?;
    let eps = sqrt_upper_decimal(&b);
    if eps > *tolerance {
        return Ok(None);
    }
    let end_point = curve.eval(&Rational::ONE);
    Ok(Some(Fit {
        piece: ApproximationPiece {
            curve,
            spine_piece: index,
            interval,
            start_slope: m0,
            deviation: eps,
        },
        end_point,
        end_quaternion: a2,
    }))
}

/// A `G¹` spline of exact spatial PH quintics within `options.tolerance` of the spine (a
/// chain of rational Bézier curves in 3-space on `t ∈ [0, 1]`, every weight `> 0`): each
/// spine curve is cut into parameter intervals, adaptively (an interval whose certified
/// bound exceeds the tolerance is halved, an accepted step is doubled for the next one).
///
/// # Errors
/// [`PhError::OutOfRange`] for an empty spine, a tolerance `≤ 0`, a weight `≤ 0`, or
/// [`PhError::ToleranceNotMet`] when an interval shorter than `2⁻³⁰` still misses the
/// tolerance or more than `options.max_pieces` pieces would be needed;
/// [`PhError::ZeroTangent`] where the spine's tangent vanishes; [`PhError::DegreeMismatch`]
/// for a spine not in 3-space.
pub fn approximate_by_ph_quintics(
    spine: &[BezierCurve<Rational>],
    options: &PhApproximationOptions,
) -> Result<PhSplineApproximation, PhError> {
    let tolerance = &options.tolerance;
    if *tolerance <= Rational::ZERO {
        return Err(PhError::OutOfRange(format!(
            "the tolerance must be positive, not {}",
            format_scalar(tolerance)
        )));
    }
    let Some(first) = spine.first() else {
        return Err(PhError::OutOfRange("no spine curve to approximate".into()));
    };
    for (k, c) in spine.iter().enumerate() {
        if c.dim() != 3 {
            return Err(PhError::DegreeMismatch(format!(
                "spine curve {k} lies in {}-space; a pipe spine must lie in 3-space",
                c.dim()
            )));
        }
        if c.degree() == 0 {
            return Err(PhError::ZeroTangent(format!(
                "spine curve {k} is a single point"
            )));
        }
        if let Some(w) = c.weights().iter().find(|w| **w <= Rational::ZERO) {
            return Err(PhError::OutOfRange(format!(
                "spine curve {k} has the weight {} (every weight must be > 0)",
                format_scalar(w)
            )));
        }
    }
    let closed = spine
        .last()
        .is_some_and(|last| same_tangent_direction(last, first));
    if !closed || !options.close {
        return fit_open(spine, options);
    }
    // a G¹-closed spine: fit with a margin below the tolerance, then re-solve the last two
    // pieces so that the spline closes exactly (module docs, "Closed spines"); a tighter
    // fit leaves a smaller gap to close
    for margin in [(3, 4), (1, 2), (1, 8)] {
        let fit = PhApproximationOptions {
            tolerance: tolerance * Rational::from_ratio(margin.0, margin.1),
            ..options.clone()
        };
        let Ok(open) = fit_open(spine, &fit) else {
            break;
        };
        if let Some(closed) = close_spline(open, tolerance) {
            return Ok(closed);
        }
    }
    // not closed within the limits: the open spline, as for an open spine (its seam is
    // reported open by `is_closed` and the certificates carry no seam joint)
    fit_open(spine, options)
}

/// The spline `open` (fitted below `tolerance`) with its last two pieces re-solved so that
/// it ends at its start with its start tangent direction ([`super::closure`]), every piece
/// still within `tolerance` of the spine; `None` if that fails.
fn close_spline(
    open: PhSplineApproximation,
    tolerance: &Rational,
) -> Option<PhSplineApproximation> {
    let n = open.pieces.len();
    if n < 2 {
        return None;
    }
    let (first, pen, last) = (
        open.pieces.first()?,
        open.pieces.get(n - 2)?,
        open.pieces.get(n - 1)?,
    );
    let amax = [&pen.curve, &last.curve]
        .iter()
        .flat_map(|c| c.coefficients().iter())
        .map(|a| a.to_f64().norm_sq().sqrt())
        .fold(0.0, f64::max);
    let bits = rounding_bits(amax, Scalar::to_f64(tolerance));
    let (pen_curve, last_curve) =
        super::closure::close_two_pieces(&first.curve, &pen.curve, &last.curve, bits)?;
    let tol2 = tolerance * tolerance;
    let redo = |p: &ApproximationPiece, curve: PhCurve<Rational>| -> Option<ApproximationPiece> {
        let c = open.spine.get(p.spine_piece)?;
        let b = distance_bound_squared(&curve, c, &p.interval, &p.start_slope, &tol2).ok()?;
        let eps = sqrt_upper_decimal(&b);
        (eps <= *tolerance).then(|| ApproximationPiece {
            curve,
            deviation: eps,
            ..p.clone()
        })
    };
    let (new_pen, new_last) = (redo(pen, pen_curve)?, redo(last, last_curve)?);
    let mut pieces = open.pieces.clone();
    pieces.truncate(n - 2);
    pieces.push(new_pen);
    pieces.push(new_last);
    Some(PhSplineApproximation {
        spine: open.spine,
        pieces,
        tolerance: tolerance.clone(),
        closed: true,
    })
}

/// The spline of [`approximate_by_ph_quintics`] without closing it (the spine is checked).
fn fit_open(
    spine: &[BezierCurve<Rational>],
    options: &PhApproximationOptions,
) -> Result<PhSplineApproximation, PhError> {
    let tolerance = &options.tolerance;
    let Some(first) = spine.first() else {
        return Err(PhError::OutOfRange("no spine curve to approximate".into()));
    };
    let start = first.eval(&Rational::ZERO)?;
    let mut carry = Carry {
        point: core::array::from_fn(|k| start.get(k).cloned().unwrap_or(Rational::ZERO)),
        quaternion: None,
        smooth: false,
    };
    let mut pieces: Vec<ApproximationPiece> = Vec::new();
    let min_step = Rational::try_from(2f64.powi(-(MIN_STEP_LOG2 as i32))).unwrap_or(Rational::ZERO);
    for (index, c) in spine.iter().enumerate() {
        if let Some(prev) = index.checked_sub(1).and_then(|i| spine.get(i)) {
            carry.smooth = same_tangent_direction(prev, c);
        }
        let cf = c.to_f64();
        let mut t0 = Rational::ZERO;
        let mut step = Rational::from_ratio(1, 4);
        while t0 < Rational::ONE {
            let rest = Rational::ONE - &t0;
            if step > rest {
                step = rest.clone();
            }
            let fit = loop {
                let t1 = &t0 + &step;
                if let Some(f) = fit_piece(c, &cf, index, (&t0, &t1), &carry, tolerance)? {
                    break f;
                }
                step = &step / Rational::from(2);
                if step < min_step {
                    return Err(PhError::ToleranceNotMet(format!(
                        "spine curve {index} near t = {}: no PH quintic on an interval of length 2⁻{MIN_STEP_LOG2} stays within the tolerance {} (the spine may have a cusp or a non-smooth point there, or the tolerance is below what the rounding to rationals allows)",
                        format_scalar(&t0),
                        format_scalar(tolerance)
                    )));
                }
            };
            t0 = fit.piece.interval.1.clone();
            carry = Carry {
                point: fit.end_point,
                quaternion: Some(fit.end_quaternion),
                smooth: true,
            };
            pieces.push(fit.piece);
            if pieces.len() > options.max_pieces {
                return Err(PhError::ToleranceNotMet(format!(
                    "the tolerance {} needs more than {} PH pieces (raise the tolerance or the piece limit)",
                    format_scalar(tolerance),
                    options.max_pieces
                )));
            }
            step = &step * Rational::from(2);
        }
    }
    Ok(PhSplineApproximation {
        spine: spine.to_vec(),
        pieces,
        tolerance: tolerance.clone(),
        closed: false,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    /// The twisted cubic `(t, t², t³)` (its `|m′|² = 1 + 4t² + 9t⁴` is no sum of two
    /// rational squares) and a rational cubic.
    fn cubic() -> BezierCurve<Rational> {
        let pts = vec![
            vec![q(0), q(0), q(0)],
            vec![Rational::from_ratio(1, 3), q(0), q(0)],
            vec![Rational::from_ratio(2, 3), Rational::from_ratio(1, 3), q(0)],
            vec![q(1), q(1), q(1)],
        ];
        BezierCurve::from_points(&pts).expect("cubic")
    }

    #[test]
    fn twisted_cubic_within_tolerance() {
        let spine = vec![cubic()];
        let tol = Rational::from_ratio(1, 1_000_000);
        let t = std::time::Instant::now();
        let a = approximate_by_ph_quintics(&spine, &PhApproximationOptions::new(tol.clone()))
            .expect("approximation");
        eprintln!(
            "{} pieces, deviation {}, {:?}",
            a.pieces().len(),
            format_scalar(&a.deviation()),
            t.elapsed()
        );
        assert!(a.deviation() <= tol);
        let certs = a.certify();
        assert!(Certificate::all_hold(&certs), "{certs:#?}");
    }
}
