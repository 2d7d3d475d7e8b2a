//! Exact rational circle arcs and full circles.
//!
//! **The rational parametrization.** The stereographic projection from the point
//! `(−1, 0)` parametrizes the unit circle by
//! `u(s) = ((1 − s²)/(1 + s²), 2s/(1 + s²))`, `s = tan(θ/2)`, homogeneously
//! `(1 + s², 1 − s², 2s)`. Rational parameters give exactly the rational points
//! (`s = y/(1 + x)`), so an arc between two rational points of a circle with
//! rational centre `c` and radius `r` has rational control points; no `cos(θ/2)`
//! is needed. (Standard; e.g. Farin, *NURBS*, §5 on conics; the same map is the
//! `n = 1` case of Jüttler's generalized stereographic projection, docs/math/quadrics.md, "The map δ onto the sphere".)
//!
//! **One arc piece.** Let `d₀ = p₀ − c`, `d₁ = p₁ − c` and let `φ ∈ (−π, π)` be the signed
//! angle from `d₀` to `d₁` (positive counter-clockwise). In the frame rotated by the
//! rational rotation `d₀/r` the arc is `s ↦ u(s)`, `s ∈ [0, σ]` with
//! `σ = tan(φ/2) = (d₀ × d₁)/(r² + d₀·d₁)` (rational). The linear reparametrization
//! `s = σt` gives the quadratic `(1 + σ²t², 1 − σ²t², 2σt)`; in the Bernstein basis
//! on `[0, 1]` and rotated back, the homogeneous control points `(w, wx, wy)` are
//!
//! ```text
//! P₀ = (1, p₀),   P₁ = (1, p₀ + σ·J d₀),   P₂ = (1 + σ², (1 + σ²)·p₁),   J(x, y) = (−y, x).
//! ```
//!
//! `P₁` is the intersection of the end tangents. The weights `1, 1, 1 + σ²` are
//! rational but not in standard form (`w₀ ≠ w₂`); the arc is a Möbius
//! reparametrization of the standard one. For the unit quarter from `(1, 0)` to
//! `(0, 1)`: `σ = 1`, control points `(1, 1, 0), (1, 1, 1), (2, 0, 2)`.
//!
//! Every piece satisfies `(X − c_x W)² + (Y − c_y W)² − r²W² ≡ 0`, the quadric with
//! matrix [`circle_matrix`] in homogeneous coordinates `(W, X, Y)`; this is the
//! main certificate.
//!
//! **Long arcs.** A single piece must turn by less than 180° (`1 + cos φ > 0`); longer
//! arcs are split at rational points of the circle ([`CircleArcs`], [`circle_arcs`]), the
//! full circle is four quarter pieces ([`full_circle`]).

use crate::certs;
use crate::error::{check_finite, check_radius, format_point, format_scalar, ConstructionError};
use crate::Certified;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::BezierCurve;

/// A point of the plane.
pub type Point2<F> = [F; 2];

/// The symmetric 3×3 matrix `Q` of the circle `|x − c|² = r²` in homogeneous
/// coordinates `X = (W, X, Y)`: `(X − c_x W)² + (Y − c_y W)² − r²W² = Xᵀ Q X`,
///
/// ```text
/// Q = [ c_x² + c_y² − r²   −c_x   −c_y ]
///     [ −c_x                 1      0   ]
///     [ −c_y                 0      1   ]
/// ```
pub fn circle_matrix<F: Scalar>(center: &Point2<F>, radius: &F) -> Vec<Vec<F>> {
    let [cx, cy] = center.clone();
    let w2 = cx.clone() * cx.clone() + cy.clone() * cy.clone() - radius.clone() * radius.clone();
    vec![
        vec![w2, -cx.clone(), -cy.clone()],
        vec![-cx, F::one(), F::zero()],
        vec![-cy, F::zero(), F::one()],
    ]
}

/// The residual `|p − c|² − r²` (zero iff `p` is on the circle).
pub fn circle_residual<F: Scalar>(center: &Point2<F>, radius: &F, p: &Point2<F>) -> F {
    let dx = p[0].clone() - center[0].clone();
    let dy = p[1].clone() - center[1].clone();
    dx.clone() * dx + dy.clone() * dy - radius.clone() * radius.clone()
}

/// Checks that `p` lies on the circle: exactly for exact scalars, up to the relative
/// tolerance `1e-9 · max(r², 1)` for `f64`.
///
/// # Errors
/// [`ConstructionError::PointNotOnCircle`] with the residual `|p − c|² − r²`, or
/// [`ConstructionError::NotFinite`] for a NaN/infinite `f64` coordinate.
pub fn check_on_circle<F: Scalar>(
    center: &Point2<F>,
    radius: &F,
    p: &Point2<F>,
    name: &str,
) -> Result<(), ConstructionError> {
    check_finite(name, &[&p[0], &p[1]])?;
    let res = circle_residual(center, radius, p);
    let scale = radius.to_f64() * radius.to_f64();
    if certs::is_negligible(&res, scale) {
        Ok(())
    } else {
        Err(ConstructionError::PointNotOnCircle {
            point: name.to_string(),
            coords: format_point(p),
            residual: format_scalar(&res),
        })
    }
}

/// The rational point `c + r·u(s)`, `u(s) = ((1 − s²)/(1 + s²), 2s/(1 + s²))`, of the
/// circle: the stereographic parametrization (`s = tan(θ/2)`). Every rational point
/// except `c + (−r, 0)` (`s = ∞`) is of this form.
pub fn circle_point<F: Scalar>(center: &Point2<F>, radius: &F, s: &F) -> Point2<F> {
    let s2 = s.clone() * s.clone();
    let den = F::one() + s2.clone();
    let two = F::from_i64(2);
    [
        center[0].clone() + radius.clone() * (F::one() - s2) / den.clone(),
        center[1].clone() + radius.clone() * two * s.clone() / den,
    ]
}

fn sub<F: Scalar>(a: &Point2<F>, b: &Point2<F>) -> Point2<F> {
    [a[0].clone() - b[0].clone(), a[1].clone() - b[1].clone()]
}

fn cross<F: Scalar>(a: &Point2<F>, b: &Point2<F>) -> F {
    a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone()
}

fn dot<F: Scalar>(a: &Point2<F>, b: &Point2<F>) -> F {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone()
}

/// Validates the input of an arc (centre, radius `> 0`, both end points exactly on the
/// circle and different) and returns `(from − center, to − center)`.
fn check_arc_input<F: Scalar>(
    center: &Point2<F>,
    radius: &F,
    from: &Point2<F>,
    to: &Point2<F>,
) -> Result<(Point2<F>, Point2<F>), ConstructionError> {
    check_center(center)?;
    check_radius(radius)?;
    check_on_circle(center, radius, from, "from")?;
    check_on_circle(center, radius, to, "to")?;
    if from == to {
        return Err(ConstructionError::CoincidentPoints(format!(
            "the end points of an arc must differ, from = to = {} (use full_circle for a whole circle)",
            format_point(from)
        )));
    }
    Ok((sub(from, center), sub(to, center)))
}

fn check_center<F: Scalar>(center: &Point2<F>) -> Result<(), ConstructionError> {
    check_finite("center", &[&center[0], &center[1]])
}

/// One rational quadratic arc of a circle, turning by less than 180°.
///
/// See the module documentation for the construction and its control points.
#[derive(Debug, Clone, PartialEq)]
pub struct CircleArc<F> {
    center: Point2<F>,
    radius: F,
    from: Point2<F>,
    to: Point2<F>,
    clockwise: bool,
    half_angle_tangent: F,
    curve: BezierCurve<F>,
}

impl<F: Scalar> CircleArc<F> {
    /// The arc of the circle with centre `center` and radius `radius` from `from` to
    /// `to`, counter-clockwise (or clockwise if `clockwise`), as one rational quadratic
    /// with control points `(1, p₀), (1, p₀ + σ·J d₀), (1 + σ², (1 + σ²)p₁)`,
    /// `σ = (d₀ × d₁)/(r² + d₀·d₁) = tan(φ/2)`.
    ///
    /// # Errors
    /// * [`ConstructionError::NonPositiveRadius`] for `radius ≤ 0`;
    /// * [`ConstructionError::PointNotOnCircle`] if `from` or `to` is not exactly on the
    ///   circle (residual `|p − c|² − r²`);
    /// * [`ConstructionError::CoincidentPoints`] if `from = to`;
    /// * [`ConstructionError::ArcTooLarge`] if the arc turns by 180° or more in the
    ///   requested sense (use [`CircleArcs`] / [`circle_arcs`]);
    /// * [`ConstructionError::NotFinite`] for NaN/infinite `f64` input.
    pub fn new(
        center: Point2<F>,
        radius: F,
        from: Point2<F>,
        to: Point2<F>,
        clockwise: bool,
    ) -> Result<Self, ConstructionError> {
        let (d0, d1) = check_arc_input(&center, &radius, &from, &to)?;
        let turn = cross(&d0, &d1);
        let oriented = if clockwise {
            -turn.clone()
        } else {
            turn.clone()
        };
        if oriented <= F::zero() || half_turn_within_rounding(&oriented, &dot(&d0, &d1), &radius) {
            return Err(ConstructionError::ArcTooLarge(format!(
                "the {} arc from {} to {} turns by ≥ 180° (oriented d₀ × d₁ = {})",
                if clockwise {
                    "clockwise"
                } else {
                    "counter-clockwise"
                },
                format_point(&from),
                format_point(&to),
                format_scalar(&oriented)
            )));
        }
        let den = radius.clone() * radius.clone() + dot(&d0, &d1);
        let sigma = turn / den;
        let curve = arc_curve(&from, &to, &d0, &sigma)?;
        Ok(CircleArc {
            center,
            radius,
            from,
            to,
            clockwise,
            half_angle_tangent: sigma,
            curve,
        })
    }

    /// The rational quadratic Bézier curve (homogeneous `(w, wx, wy)`).
    pub fn curve(&self) -> &BezierCurve<F> {
        &self.curve
    }

    /// Consumes the arc, returning its curve.
    pub fn into_curve(self) -> BezierCurve<F> {
        self.curve
    }

    /// The centre.
    pub fn center(&self) -> &Point2<F> {
        &self.center
    }

    /// The radius.
    pub fn radius(&self) -> &F {
        &self.radius
    }

    /// The start point `P(0)`.
    pub fn from(&self) -> &Point2<F> {
        &self.from
    }

    /// The end point `P(1)`.
    pub fn to(&self) -> &Point2<F> {
        &self.to
    }

    /// `true` for a clockwise arc.
    pub fn clockwise(&self) -> bool {
        self.clockwise
    }

    /// `σ = tan(φ/2)`, `φ` the signed turning angle (positive counter-clockwise).
    pub fn half_angle_tangent(&self) -> &F {
        &self.half_angle_tangent
    }

    /// The certificates with every property prefixed by `prefix`.
    fn certify_prefixed(&self, prefix: &str) -> Vec<Certificate> {
        let mut out = Vec::with_capacity(4);
        let q = circle_matrix(&self.center, &self.radius);
        let property = format!(
            "{prefix}on the circle: (x − cx)² + (y − cy)² − r² ≡ 0, c = {}, r = {}",
            format_point(&self.center),
            format_scalar(&self.radius)
        );
        out.push(
            certs::curve_on_quadric(&self.curve, &q, &property)
                .unwrap_or_else(|e| Certificate::fails(property.clone(), e.to_string(), F::EXACT)),
        );
        out.push(certs::interpolates(
            &self.curve,
            &F::zero(),
            &self.from,
            &format!("{prefix}P(0) = from = {}", format_point(&self.from)),
        ));
        out.push(certs::interpolates(
            &self.curve,
            &F::one(),
            &self.to,
            &format!("{prefix}P(1) = to = {}", format_point(&self.to)),
        ));
        out.push(self.sense_certificate(prefix));
        out
    }

    /// Positive weights and a start tangent `P₁ − P₀` turning in the stated sense about
    /// the centre: then the curve is the short (< 180°) arc in that sense.
    fn sense_certificate(&self, prefix: &str) -> Certificate {
        let sense = if self.clockwise {
            "clockwise"
        } else {
            "counter-clockwise"
        };
        let property = format!("{prefix}weights > 0 and the arc runs {sense}");
        let weights_positive = self.curve.control_points().all(|p| p[0] > F::zero());
        let p0 = certs::euclidean(self.curve.control_point(0));
        let p1 = certs::euclidean(self.curve.control_point(1));
        let (Some(p0), Some(p1)) = (p0, p1) else {
            return Certificate::fails(property, "control point at infinity", F::EXACT);
        };
        let (Some(a), Some(b)) = (p0.first().zip(p0.get(1)), p1.first().zip(p1.get(1))) else {
            return Certificate::fails(property, "not a planar curve", F::EXACT);
        };
        let d0 = [
            a.0.clone() - self.center[0].clone(),
            a.1.clone() - self.center[1].clone(),
        ];
        let tangent = [b.0.clone() - a.0.clone(), b.1.clone() - a.1.clone()];
        let turn = cross(&d0, &tangent);
        let ok = if self.clockwise {
            turn < F::zero()
        } else {
            turn > F::zero()
        };
        Certificate::decide(property, ok && weights_positive, F::EXACT, || {
            format!(
                "weights positive: {weights_positive}, (P₀ − c) × (P₁ − P₀) = {}",
                format_scalar(&turn)
            )
        })
    }
}

/// The control points of one piece (module docs).
fn arc_curve<F: Scalar>(
    from: &Point2<F>,
    to: &Point2<F>,
    d0: &Point2<F>,
    sigma: &F,
) -> Result<BezierCurve<F>, ConstructionError> {
    let w2 = F::one() + sigma.clone() * sigma.clone();
    let p0 = vec![F::one(), from[0].clone(), from[1].clone()];
    let p1 = vec![
        F::one(),
        from[0].clone() - sigma.clone() * d0[1].clone(),
        from[1].clone() + sigma.clone() * d0[0].clone(),
    ];
    let p2 = vec![w2.clone(), w2.clone() * to[0].clone(), w2 * to[1].clone()];
    Ok(BezierCurve::from_homogeneous(vec![p0, p1, p2])?)
}

impl<F: Scalar> Certified for CircleArc<F> {
    /// On the circle (exact identity), `P(0) = from`, `P(1) = to`, and the sense.
    fn certify(&self) -> Vec<Certificate> {
        self.certify_prefixed("")
    }
}

/// Certificates of a chain of pieces: each piece's, then C0 and G1 at every join
/// (including the closing join for a closed chain).
fn certify_chain<F: Scalar>(pieces: &[CircleArc<F>], closed: bool) -> Vec<Certificate> {
    let mut out = Vec::new();
    for (k, piece) in pieces.iter().enumerate() {
        out.extend(piece.certify_prefixed(&format!("piece {k}: ")));
    }
    let n = pieces.len();
    let joins = if closed { n } else { n.saturating_sub(1) };
    for k in 0..joins {
        let (Some(a), Some(b)) = (pieces.get(k), pieces.get((k + 1) % n)) else {
            continue;
        };
        let label = format!("piece {k} → piece {}", (k + 1) % n);
        out.push(certs::c0_join(a.curve(), b.curve(), &label));
        out.push(certs::g1_join(a.curve(), b.curve(), &label));
    }
    out
}

/// A circle arc of any extent (below 360°) as a chain of rational quadratic pieces,
/// each turning by less than 180°.
///
/// Arcs below 180° are one piece. Longer arcs (turning angle `φ`) are cut into
/// `n = ⌈φ/90°⌉` pieces (`n` decided exactly from the signs of `d₀ × d₁` and `d₀·d₁`)
/// at rational points near the equally spaced angles `kφ/n`: the point at angle `ψ`
/// from `from` is `c + d₀ ⊗ u(s)` (complex product) with `s` a small-denominator
/// rational approximation of `tan(ψ/2)` (or `−(d₀ ⊗ u(s))`, `s ≈ tan((ψ − π)/2)`, for
/// `ψ` near 180°). The approximation only moves the cut points; they are exactly on the
/// circle, and every piece is certified.
#[derive(Debug, Clone, PartialEq)]
pub struct CircleArcs<F> {
    pieces: Vec<CircleArc<F>>,
}

impl<F: Scalar> CircleArcs<F> {
    /// The arc from `from` to `to` (counter-clockwise unless `clockwise`).
    ///
    /// # Errors
    /// As [`CircleArc::new`], except that long arcs are split instead of rejected.
    pub fn new(
        center: Point2<F>,
        radius: F,
        from: Point2<F>,
        to: Point2<F>,
        clockwise: bool,
    ) -> Result<Self, ConstructionError> {
        let (d0, d1) = check_arc_input(&center, &radius, &from, &to)?;
        let turn = cross(&d0, &d1);
        let oriented = if clockwise { -turn } else { turn };
        let cosine = dot(&d0, &d1);
        let zero = F::zero();
        let straight = oriented == zero || half_turn_within_rounding(&oriented, &cosine, &radius);
        let n: usize = if oriented > zero && !straight {
            1
        } else if straight {
            if cosine < zero {
                2
            } else {
                return Err(ConstructionError::CoincidentPoints(format!(
                    "the end points {} and {} coincide to working precision",
                    format_point(&from),
                    format_point(&to)
                )));
            }
        } else if cosine <= zero {
            3
        } else {
            4
        };
        let mut points = vec![from.clone()];
        if n > 1 {
            // φ ∈ [π, 2π) in f64, only to place the cuts.
            let r2 = radius.clone() * radius.clone();
            let sin_phi = (oriented / r2.clone()).to_f64();
            let cos_phi = (cosine / r2).to_f64();
            let mut phi = sin_phi.atan2(cos_phi);
            if phi <= 0.0 {
                phi += 2.0 * core::f64::consts::PI;
            }
            for k in 1..n {
                let psi = phi * k as f64 / n as f64;
                points.push(cut_point(&center, &d0, psi, clockwise));
            }
        }
        points.push(to);
        let mut pieces = Vec::with_capacity(n);
        for w in points.windows(2) {
            let [a, b] = w else { continue };
            pieces.push(CircleArc::new(
                center.clone(),
                radius.clone(),
                a.clone(),
                b.clone(),
                clockwise,
            )?);
        }
        Ok(CircleArcs { pieces })
    }

    /// The pieces, in order from `from` to `to`.
    pub fn pieces(&self) -> &[CircleArc<F>] {
        &self.pieces
    }

    /// The pieces' curves (cloned).
    pub fn curves(&self) -> Vec<BezierCurve<F>> {
        self.pieces.iter().map(|p| p.curve().clone()).collect()
    }

    /// Consumes the chain, returning the pieces' curves.
    pub fn into_curves(self) -> Vec<BezierCurve<F>> {
        self.pieces.into_iter().map(CircleArc::into_curve).collect()
    }
}

impl<F: Scalar> Certified for CircleArcs<F> {
    /// Every piece's certificates, then C0 and G1 at every join.
    fn certify(&self) -> Vec<Certificate> {
        certify_chain(&self.pieces, false)
    }
}

/// Whether an `f64` arc with `oriented = ±d₀ × d₁` and `cosine = d₀·d₁` is a half circle
/// up to rounding: the rounded end points of a half circle leave a residue `±ε` instead of
/// `d₀ × d₁ = 0`, and one piece through it would have `σ = turn/(r² + d₀·d₁) ≈ ±1/0`.
/// Within `64ε·r²` of 0 it is taken as the half circle it is exactly (never for exact
/// scalars).
fn half_turn_within_rounding<F: Scalar>(oriented: &F, cosine: &F, radius: &F) -> bool {
    let r2 = (radius.clone() * radius.clone()).to_f64();
    !F::EXACT && *cosine < F::zero() && oriented.to_f64().abs() <= 64.0 * f64::EPSILON * r2
}

/// The best rational approximation `p/q` of `x` with `q ≤ max_den` among the
/// continued-fraction convergents (`x` finite, `|x| ≤ 2`).
fn approx_ratio(x: f64, max_den: i64) -> (i64, i64) {
    if !x.is_finite() {
        return (0, 1);
    }
    let (mut p0, mut q0, mut p1, mut q1) = (0i64, 1i64, 1i64, 0i64);
    let mut y = x;
    for _ in 0..32 {
        let a = y.floor();
        if a.abs() > 1e6 {
            break;
        }
        let a = a as i64;
        let (p2, q2) = (a * p1 + p0, a * q1 + q0);
        if q2 > max_den {
            break;
        }
        (p0, q0, p1, q1) = (p1, q1, p2, q2);
        let frac = y - a as f64;
        if frac.abs() < 1e-12 {
            break;
        }
        y = 1.0 / frac;
    }
    if q1 == 0 {
        (x.round() as i64, 1)
    } else {
        (p1, q1)
    }
}

/// The rational point of the circle at angle ≈ `psi` ∈ (0, 2π) from `c + d₀`, in the
/// sense of the arc.
fn cut_point<F: Scalar>(
    center: &Point2<F>,
    d0: &Point2<F>,
    psi: f64,
    clockwise: bool,
) -> Point2<F> {
    use core::f64::consts::{FRAC_PI_2, PI};
    let (half, antipode) = if psi <= FRAC_PI_2 {
        (psi / 2.0, false)
    } else if psi >= 3.0 * FRAC_PI_2 {
        (psi / 2.0 - PI, false)
    } else {
        ((psi - PI) / 2.0, true)
    };
    let (p, q) = approx_ratio(half.tan(), 32);
    let mut s = F::from_ratio(p, q);
    if clockwise {
        s = -s;
    }
    let s2 = s.clone() * s.clone();
    let den = F::one() + s2.clone();
    let mut ux = (F::one() - s2) / den.clone();
    let mut uy = F::from_i64(2) * s / den;
    if antipode {
        ux = -ux;
        uy = -uy;
    }
    [
        center[0].clone() + d0[0].clone() * ux.clone() - d0[1].clone() * uy.clone(),
        center[1].clone() + d0[0].clone() * uy + d0[1].clone() * ux,
    ]
}

/// The arc from `from` to `to` on the circle `(center, radius)` as rational quadratic
/// pieces, each turning by less than 180° (see [`CircleArcs`]).
///
/// # Errors
/// As [`CircleArcs::new`].
pub fn circle_arcs<F: Scalar>(
    center: Point2<F>,
    radius: F,
    from: Point2<F>,
    to: Point2<F>,
    clockwise: bool,
) -> Result<Vec<BezierCurve<F>>, ConstructionError> {
    Ok(CircleArcs::new(center, radius, from, to, clockwise)?.into_curves())
}

/// A full circle as four rational quadratic quarter arcs, counter-clockwise from
/// `c + (r, 0)` through `c + (0, r)`, `c + (−r, 0)`, `c + (0, −r)`.
///
/// Each quarter has `σ = tan(45°) = 1`: control points
/// `(1, pₖ), (1, pₖ + J(pₖ − c)), (2, 2pₖ₊₁)`; for the unit circle the first is
/// `(1, 1, 0), (1, 1, 1), (2, 0, 2)`.
#[derive(Debug, Clone, PartialEq)]
pub struct FullCircle<F> {
    center: Point2<F>,
    radius: F,
    pieces: Vec<CircleArc<F>>,
}

impl<F: Scalar> FullCircle<F> {
    /// The centre.
    pub fn center(&self) -> &Point2<F> {
        &self.center
    }

    /// The radius.
    pub fn radius(&self) -> &F {
        &self.radius
    }

    /// The four quarter arcs.
    pub fn pieces(&self) -> &[CircleArc<F>] {
        &self.pieces
    }

    /// The four curves (cloned).
    pub fn curves(&self) -> Vec<BezierCurve<F>> {
        self.pieces.iter().map(|p| p.curve().clone()).collect()
    }

    /// Consumes the circle, returning its four curves.
    pub fn into_curves(self) -> Vec<BezierCurve<F>> {
        self.pieces.into_iter().map(CircleArc::into_curve).collect()
    }
}

impl<F: Scalar> Certified for FullCircle<F> {
    /// Every quarter's certificates, then C0 and G1 at all four joins (closed).
    fn certify(&self) -> Vec<Certificate> {
        certify_chain(&self.pieces, true)
    }
}

/// The full circle with centre `center` and radius `radius` (see [`FullCircle`]).
///
/// # Errors
/// [`ConstructionError::NonPositiveRadius`] for `radius ≤ 0`,
/// [`ConstructionError::NotFinite`] for NaN/infinite `f64` input.
pub fn full_circle<F: Scalar>(
    center: Point2<F>,
    radius: F,
) -> Result<FullCircle<F>, ConstructionError> {
    check_center(&center)?;
    check_radius(&radius)?;
    let [cx, cy] = center.clone();
    let r = radius.clone();
    let quarter = [
        [cx.clone() + r.clone(), cy.clone()],
        [cx.clone(), cy.clone() + r.clone()],
        [cx.clone() - r.clone(), cy.clone()],
        [cx, cy - r],
    ];
    let mut pieces = Vec::with_capacity(4);
    for k in 0..4 {
        pieces.push(CircleArc::new(
            center.clone(),
            radius.clone(),
            quarter[k].clone(),
            quarter[(k + 1) % 4].clone(),
            false,
        )?);
    }
    Ok(FullCircle {
        center,
        radius,
        pieces,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    /// A half circle between rational antipodal points, centre (0, 8), radius 9, from
    /// `c + 9·(45, −108)/117` to `c − 9·(45, −108)/117`: exactly `d₀ × d₁ = 0` (two pieces);
    /// in f64 the rounded end points leave a residue, which must not become one piece with
    /// `σ ≈ 1/0` (a random draw of the float tests overflowed to inf).
    #[test]
    fn half_circle_in_f64_is_two_pieces_as_exactly() {
        let from = [q(9 * 45, 117), q(8 * 117 - 9 * 108, 117)];
        let to = [q(-9 * 45, 117), q(8 * 117 + 9 * 108, 117)];
        let exact = CircleArcs::new([q(0, 1), q(8, 1)], q(9, 1), from.clone(), to.clone(), false)
            .expect("exact");
        assert_eq!(exact.pieces().len(), 2);
        let f = |p: &[Rational; 2]| [Scalar::to_f64(&p[0]), Scalar::to_f64(&p[1])];
        let float = CircleArcs::new([0.0, 8.0], 9.0, f(&from), f(&to), false).expect("f64");
        assert_eq!(float.pieces().len(), 2);
        for c in float.curves() {
            assert!(c.coords().iter().all(|x| x.is_finite()), "{c:?}");
        }
        // one piece is refused as exactly (≥ 180°), not built with σ ≈ 1/0
        assert!(matches!(
            CircleArc::new([q(0, 1), q(8, 1)], q(9, 1), from.clone(), to.clone(), false),
            Err(ConstructionError::ArcTooLarge(_))
        ));
        for clockwise in [false, true] {
            assert!(matches!(
                CircleArc::new([0.0, 8.0], 9.0, f(&from), f(&to), clockwise),
                Err(ConstructionError::ArcTooLarge(_))
            ));
        }
    }

    fn hom(c: &BezierCurve<Rational>) -> Vec<Vec<Rational>> {
        c.control_points().map(|p| p.to_vec()).collect()
    }

    #[test]
    fn unit_quarter_control_points() {
        let arc = CircleArc::new(
            [q(0, 1), q(0, 1)],
            q(1, 1),
            [q(1, 1), q(0, 1)],
            [q(0, 1), q(1, 1)],
            false,
        )
        .expect("valid arc");
        assert_eq!(
            hom(arc.curve()),
            vec![
                vec![q(1, 1), q(1, 1), q(0, 1)],
                vec![q(1, 1), q(1, 1), q(1, 1)],
                vec![q(2, 1), q(0, 1), q(2, 1)],
            ]
        );
        assert_eq!(arc.half_angle_tangent(), &q(1, 1));
        let certs = arc.certify();
        assert_eq!(certs.len(), 4);
        assert!(Certificate::all_hold(&certs), "{certs:?}");
        assert!(certs.iter().all(|c| c.exact));
    }

    #[test]
    fn clockwise_quarter() {
        let arc = CircleArc::new(
            [q(0, 1), q(0, 1)],
            q(1, 1),
            [q(0, 1), q(1, 1)],
            [q(1, 1), q(0, 1)],
            true,
        )
        .expect("valid arc");
        assert_eq!(arc.half_angle_tangent(), &q(-1, 1));
        assert!(arc.all_hold());
        // The same points counter-clockwise turn by 270°.
        assert!(matches!(
            CircleArc::new(
                [q(0, 1), q(0, 1)],
                q(1, 1),
                [q(0, 1), q(1, 1)],
                [q(1, 1), q(0, 1)],
                false
            ),
            Err(ConstructionError::ArcTooLarge(_))
        ));
    }

    #[test]
    fn full_circle_has_four_certified_quarters() {
        let c = full_circle([q(1, 2), q(-3, 1)], q(5, 3)).expect("valid");
        assert_eq!(c.pieces().len(), 4);
        let certs = c.certify();
        assert_eq!(certs.len(), 4 * 4 + 2 * 4);
        assert!(Certificate::all_hold(&certs), "{certs:?}");
    }

    #[test]
    fn long_arcs_are_split() {
        let c = [q(0, 1), q(0, 1)];
        let r = q(1, 1);
        // 180°: two exact quarters.
        let half = CircleArcs::new(
            c.clone(),
            r.clone(),
            [q(1, 1), q(0, 1)],
            [q(-1, 1), q(0, 1)],
            false,
        )
        .expect("valid");
        assert_eq!(half.pieces().len(), 2);
        assert_eq!(half.pieces()[0].to(), &[q(0, 1), q(1, 1)]);
        assert!(half.all_hold());
        // 270°, three pieces; and a 350°-ish arc, four pieces.
        let three = CircleArcs::new(
            c.clone(),
            r.clone(),
            [q(1, 1), q(0, 1)],
            [q(0, 1), q(-1, 1)],
            false,
        )
        .expect("valid");
        assert_eq!(three.pieces().len(), 3);
        assert!(three.all_hold());
        let to = circle_point(&c, &r, &q(-1, 20));
        let four =
            CircleArcs::new(c.clone(), r.clone(), [q(1, 1), q(0, 1)], to, false).expect("valid");
        assert_eq!(four.pieces().len(), 4);
        assert!(four.all_hold(), "{:?}", four.certify());
        let cw =
            CircleArcs::new(c, r, [q(1, 1), q(0, 1)], [q(0, 1), q(1, 1)], true).expect("valid");
        assert_eq!(cw.pieces().len(), 3);
        assert!(cw.all_hold());
    }

    #[test]
    fn approximations() {
        assert_eq!(approx_ratio(1.0 - 1e-16, 32), (1, 1));
        assert_eq!(approx_ratio(0.0, 32), (0, 1));
        assert_eq!(approx_ratio(-1.0, 32), (-1, 1));
        assert_eq!(approx_ratio(0.5, 32), (1, 2));
        let (p, q) = approx_ratio(0.414_213_562, 32);
        assert!((p as f64 / q as f64 - 0.414_213_562).abs() < 1e-2 && q <= 32);
    }

    #[test]
    fn typed_errors() {
        let c = [q(0, 1), q(0, 1)];
        let e = CircleArc::new(
            c.clone(),
            q(1, 1),
            [q(1, 1), q(1, 1)],
            [q(0, 1), q(1, 1)],
            false,
        );
        assert!(
            matches!(&e, Err(ConstructionError::PointNotOnCircle { point, residual, .. }) if point == "from" && residual == "1")
        );
        assert!(matches!(
            CircleArc::new(
                c.clone(),
                q(0, 1),
                [q(1, 1), q(0, 1)],
                [q(0, 1), q(1, 1)],
                false
            ),
            Err(ConstructionError::NonPositiveRadius { .. })
        ));
        assert!(matches!(
            CircleArcs::new(
                c.clone(),
                q(1, 1),
                [q(1, 1), q(0, 1)],
                [q(1, 1), q(0, 1)],
                false
            ),
            Err(ConstructionError::CoincidentPoints(_))
        ));
        assert!(matches!(
            full_circle(c, q(-1, 1)),
            Err(ConstructionError::NonPositiveRadius { .. })
        ));
        assert!(matches!(
            full_circle([f64::NAN, 0.0], 1.0),
            Err(ConstructionError::NotFinite(_))
        ));
    }
}
