//! Parametrized line nets (linear congruences given by their axes) as input of the envelope
//! construction of two-parameter sphere families (D. Gruber, "Rationale Parametrisierungen
//! von Kugelhüllflächen", 2008, §1.1.5–1.1.6 and §3.3–3.5).
//!
//! The nets live in the ideal 3-space `ω` of the cyclographic model, with points
//! `y = (y₁, y₂, y₃, y₄)` (stored as 4-vectors, index 0 = `y₁`). A *point row* is a
//! linearly parametrized line `p(u) = p₀ + u·p₁`. The three regular net types are given as
//! in Gruber §3.3–3.5:
//!
//! * **hyperbolic**: two skew real axes `c(u) = c₀ + u c₁`, `d(v) = d₀ + v d₁`; the net lines
//!   are `h(u, v) = c(u) ∧ d(v)` (every line meeting both axes);
//! * **elliptic**: a complex axis `c(u) = c₀ + u c₁` (`c₀, c₁ ∈ C⁴`) and its conjugate
//!   `d = c̄`; with `u = m − i n`, `v = ū = m + i n` the line `c(u) ∧ c̄(ū) = −2i·(a ∧ b)` is
//!   real, `c(u) = a(m, n) + i b(m, n)`, so the real net line is `h(m, n) = a ∧ b`;
//! * **parabolic**: one axis `c(u) = c₀ + u c₁` and a second point row `d(u) = d₀ + u d₁`;
//!   the net lines through `c(u)` form the pencil in the plane `[c(u), c₁, d(u)]` with the
//!   points `d(u, v) = d(u) + v c₁` (Gruber (3.56), (3.61), (3.65), (3.69), with the plane
//!   point depending on `u`; the consistency condition `e_u = f_v` of (3.54) forces
//!   `d_v = c_u = c₁`). The map `u ↦ [axis, d(u)]` is a projectivity from the points of the
//!   axis to the planes through it.
//!
//! **Fibration** (Gruber §1.1.5, §3.2): a regular net has exactly one line through each
//! point off its axes. For a point `w` the parameters are rational in `w`
//! ([`LineNet::parameters_of_point`]):
//!
//! * hyperbolic: `u = −⟨Q, c₀⟩/⟨Q, c₁⟩` with `Q = [d₀, d₁, w]` the plane through the second
//!   axis and `w`, and `v = −⟨P, d₀⟩/⟨P, d₁⟩` with `P = [c₀, c₁, w]`;
//! * elliptic: `u` as in the hyperbolic case with `d = c̄` (complex), then `m = Re u`,
//!   `n = −Im u`;
//! * parabolic: `u = −⟨P, d₀⟩/⟨P, d₁⟩` with `P = [c₀, c₁, w]` (the plane of the pencil),
//!   then `v = −⟨Z, d(u)⟩/⟨Z, c₁⟩` with `Z = [c(u), w, e_k]` any plane through the net line
//!   other than the pencil plane.
//!
//! `[p, q, r]` is the plane through three points: the vector of signed 3×3 minors,
//! `⟨[p, q, r], x⟩ = det(p, q, r, x)`. The solution satisfies the incidence `M(h) w = 0` of
//! (1.7)/(3.16), which [`LineNet::certify`] checks as a polynomial identity on the
//! parametrized absolute quadric `Ω(s, t) = (2s, 2t, 1 − s² − t², 1 + s² + t²)` (3.4).

use super::congruence::{CongruenceKind, LinearCongruence};
use super::plucker::{incidence_matrix, reciprocal_product, wedge, Line};
use super::{complex::LinearComplex, LineError};
use super::{fmt_vec, is_small, scale_of};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Matrix, Scalar};
use rcagd_geom::certify::polynomial_is_zero_scaled;
use thiserror::Error;

/// Errors of parametrized line nets. Every variant names the violated precondition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum NetError {
    /// A point row `p₀ + u p₁` whose two points coincide projectively is no line.
    #[error("the point row {0} is not a line: its two points are proportional (p₀ ∧ p₁ = 0)")]
    DegenerateAxis(String),
    /// The two axes of a hyperbolic net meet (or coincide): `det(c₀, c₁, d₀, d₁) = 0`.
    #[error("the axes of the hyperbolic net meet: det(c₀, c₁, d₀, d₁) = 0 (they must be skew, Gruber §1.1.6)")]
    AxesMeet,
    /// The complex axis of an elliptic net meets its conjugate (in particular: it is real, or
    /// it lies on Ω — a line of the oval quadric Ω meets its conjugate, which belongs to the
    /// other ruling).
    #[error("the elliptic axis c meets its conjugate c̄: det(Re c₀, Im c₀, Re c₁, Im c₁) = 0 (c and c̄ must be skew, Gruber §3.4)")]
    ConjugateAxesMeet,
    /// The point-to-plane map of a parabolic net is degenerate: `det(c₀, c₁, d₀, d₁) = 0`.
    #[error("the parabolic net is degenerate: det(c₀, c₁, d₀, d₁) = 0 (the planes [c(u), c₁, d(u)] must form a pencil, Gruber §3.5)")]
    DegenerateProjectivity,
    /// The point lies on an axis (or on the pencil structure) where the net is no fibration.
    #[error("singular point of the net: {0} (infinitely many net lines pass through it)")]
    SingularPoint(String),
    /// A line-geometry failure underneath.
    #[error(transparent)]
    Line(#[from] LineError),
}

/// A linearly parametrized line (point row) `p(u) = p₀ + u p₁` of the ideal space `ω`.
#[derive(Debug, Clone, PartialEq)]
pub struct PointRow<F> {
    /// `p₀ = p(0)`.
    pub origin: [F; 4],
    /// `p₁` (the point `p(∞)`).
    pub direction: [F; 4],
}

impl<F: Scalar> PointRow<F> {
    /// The point row `p₀ + u p₁`.
    ///
    /// # Errors
    /// [`NetError::DegenerateAxis`] if `p₀ ∧ p₁ = 0`.
    pub fn new(origin: [F; 4], direction: [F; 4]) -> Result<Self, NetError> {
        let l = wedge(&origin, &direction);
        let s = scale_of(&origin) * scale_of(&direction);
        if l.iter().all(|x| is_small(x, s)) {
            return Err(NetError::DegenerateAxis(format!(
                "{} + u·{}",
                fmt_vec(&origin),
                fmt_vec(&direction)
            )));
        }
        Ok(PointRow { origin, direction })
    }

    /// The point `p₀ + u p₁`.
    pub fn at(&self, u: &F) -> [F; 4] {
        core::array::from_fn(|k| self.origin[k].clone() + u.clone() * self.direction[k].clone())
    }

    /// The axis as a line `p₀ ∧ p₁`.
    pub fn line(&self) -> Line<F> {
        Line::from_coords_unchecked(wedge(&self.origin, &self.direction))
    }

    fn map<G: Scalar>(&self, f: impl Fn(&F) -> G) -> PointRow<G> {
        PointRow {
            origin: core::array::from_fn(|k| f(&self.origin[k])),
            direction: core::array::from_fn(|k| f(&self.direction[k])),
        }
    }
}

/// A point row with complex points, `c(u) = c₀ + u c₁`, `c₀ = re₀ + i·im₀`, `c₁ = re₁ + i·im₁`.
#[derive(Debug, Clone, PartialEq)]
pub struct ComplexPointRow<F> {
    /// `Re c₀`.
    pub origin_re: [F; 4],
    /// `Im c₀`.
    pub origin_im: [F; 4],
    /// `Re c₁`.
    pub direction_re: [F; 4],
    /// `Im c₁`.
    pub direction_im: [F; 4],
}

/// Where an axis lies with respect to the absolute quadric `Ω: y₁² + y₂² + y₃² − y₄² = 0`:
/// the sign of the discriminant `B² − AC` of `Ω(c₀ + u c₁) = A u² + 2B u + C`
/// (Gruber §3.3: "Passante", "Sekante", "Tangente"). For a complex axis: secant unless the
/// discriminant vanishes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AxisPosition {
    /// No (real) common point with Ω (`B² − AC < 0`).
    Passant,
    /// Two distinct common points (`B² − AC > 0`, or `≠ 0` for complex axes).
    Secant,
    /// A double common point (`B² − AC = 0`).
    Tangent,
}

/// The type of a parametrized net.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NetKind {
    /// Two real skew axes.
    Hyperbolic,
    /// Two conjugate complex skew axes.
    Elliptic,
    /// One axis, a projectivity from its points to the planes through it.
    Parabolic,
}

/// A regular line net of `ω` given by its axes (module docs).
#[derive(Debug, Clone, PartialEq)]
pub enum LineNet<F> {
    /// Lines `c(u) ∧ d(v)` meeting two skew axes.
    Hyperbolic {
        /// First axis `c(u)`.
        c: PointRow<F>,
        /// Second axis `d(v)`.
        d: PointRow<F>,
    },
    /// Real lines meeting a complex axis `c(u)` and its conjugate.
    Elliptic {
        /// The complex axis `c(u)`.
        c: ComplexPointRow<F>,
    },
    /// Lines `c(u) ∧ (d(u) + v c₁)`.
    Parabolic {
        /// The axis `c(u)`.
        c: PointRow<F>,
        /// The plane-point row `d(u)`.
        d: PointRow<F>,
    },
}

/// A complex polynomial `re + i·im` (real and imaginary parts in [`MPoly`]).
#[derive(Debug, Clone)]
pub(crate) struct CPoly<F> {
    pub re: MPoly<F>,
    pub im: MPoly<F>,
}

impl<F: Scalar> CPoly<F> {
    pub fn real(re: MPoly<F>) -> Self {
        CPoly {
            re,
            im: MPoly::zero(2),
        }
    }
    pub fn add(&self, o: &Self) -> Self {
        CPoly {
            re: &self.re + &o.re,
            im: &self.im + &o.im,
        }
    }
    pub fn sub(&self, o: &Self) -> Self {
        CPoly {
            re: &self.re - &o.re,
            im: &self.im - &o.im,
        }
    }
    pub fn mul(&self, o: &Self) -> Self {
        CPoly {
            re: &(&self.re * &o.re) - &(&self.im * &o.im),
            im: &(&self.re * &o.im) + &(&self.im * &o.re),
        }
    }
    pub fn conj(&self) -> Self {
        CPoly {
            re: self.re.clone(),
            im: -&self.im,
        }
    }
    pub fn neg(&self) -> Self {
        CPoly {
            re: -&self.re,
            im: -&self.im,
        }
    }
}

/// The constant `c` as a polynomial in two variables.
pub(crate) fn cst2<F: Scalar>(c: &F) -> MPoly<F> {
    MPoly::constant(2, c.clone())
}

/// `p₀ + x·p₁` with `x` a polynomial.
pub(crate) fn row_at<F: Scalar>(p0: &[F; 4], p1: &[F; 4], x: &MPoly<F>) -> [MPoly<F>; 4] {
    core::array::from_fn(|k| &cst2(&p0[k]) + &x.scale(&p1[k]))
}

/// `Σ aₖ bₖ` over any ring.
pub(crate) fn dot4<R: rcagd_algebra::Ring>(a: &[R; 4], b: &[R; 4]) -> R {
    a.iter()
        .zip(b)
        .fold(R::zero(), |acc, (x, y)| acc + x.clone() * y.clone())
}

/// The plane `[p, q, r]` through three points: `⟨[p, q, r], x⟩ = det(p, q, r, x)`.
pub(crate) fn plane3<R: rcagd_algebra::Ring>(p: &[R; 4], q: &[R; 4], r: &[R; 4]) -> [R; 4] {
    let m3 = |i: usize, j: usize, k: usize| -> R {
        p[i].clone() * (q[j].clone() * r[k].clone() - q[k].clone() * r[j].clone())
            - p[j].clone() * (q[i].clone() * r[k].clone() - q[k].clone() * r[i].clone())
            + p[k].clone() * (q[i].clone() * r[j].clone() - q[j].clone() * r[i].clone())
    };
    // det(p, q, r, x) expanded along the last row x: Σ (−1)^{3+k} x_k M_k
    [-m3(1, 2, 3), m3(0, 2, 3), -m3(0, 1, 3), m3(0, 1, 2)]
}

/// `det(a, b, c, d)` of four 4-vectors.
pub(crate) fn det4v<R: rcagd_algebra::Ring>(a: &[R; 4], b: &[R; 4], c: &[R; 4], d: &[R; 4]) -> R {
    dot4(&plane3(a, b, c), d)
}

/// The Lorentz form `⟨x, y⟩_Ω = x₁y₁ + x₂y₂ + x₃y₃ − x₄y₄` of the absolute quadric.
pub(crate) fn omega_form<R: rcagd_algebra::Ring>(x: &[R; 4], y: &[R; 4]) -> R {
    x[0].clone() * y[0].clone() + x[1].clone() * y[1].clone() + x[2].clone() * y[2].clone()
        - x[3].clone() * y[3].clone()
}

/// The polar plane `D y = (y₁, y₂, y₃, −y₄)` of a point with respect to Ω (Gruber §3.2:
/// `e = D c`, `f = D d`).
pub(crate) fn polar<R: rcagd_algebra::Ring>(y: &[R; 4]) -> [R; 4] {
    [y[0].clone(), y[1].clone(), y[2].clone(), -y[3].clone()]
}

/// The parametrization `Ω(s, t) = (2s, 2t, 1 − s² − t², 1 + s² + t²)` of the absolute
/// quadric (Gruber (3.4)) as polynomials in `(s, t)`.
pub fn omega_parametrization<F: Scalar>() -> [MPoly<F>; 4] {
    let s = MPoly::var(2, 0);
    let t = MPoly::var(2, 1);
    let one = MPoly::constant(2, F::one());
    let two = F::from_i64(2);
    let q = &(&s * &s) + &(&t * &t);
    [s.scale(&two), t.scale(&two), &one - &q, &one + &q]
}

/// The parameters `(p, q) = (P/Wp, Q/Wq)` of the net line through a point, as rational
/// functions of the point's own parameters (see [`LineNet::parameters_of_point`]).
#[derive(Debug, Clone)]
pub struct NetParameters<F> {
    /// Numerator of the first parameter (`u`, or `m` for elliptic nets).
    pub first: MPoly<F>,
    /// Denominator of the first parameter.
    pub first_den: MPoly<F>,
    /// Numerator of the second parameter (`v`, or `n`).
    pub second: MPoly<F>,
    /// Denominator of the second parameter.
    pub second_den: MPoly<F>,
}

impl<F: Scalar> NetParameters<F> {
    /// The two parameters at the point `(s, t)`, or `None` where a denominator vanishes
    /// (or the point cannot be evaluated).
    pub fn at(&self, s: &F, t: &F) -> Option<(F, F)> {
        let x = [s.clone(), t.clone()];
        let ev = |p: &MPoly<F>| p.eval(&x).ok();
        let (a, b, c, d) = (
            ev(&self.first)?,
            ev(&self.first_den)?,
            ev(&self.second)?,
            ev(&self.second_den)?,
        );
        if b.is_zero() || d.is_zero() {
            return None;
        }
        Some((a / b, c / d))
    }

    /// The largest degrees `(dx, dy)` in the first and the second variable of `ps`.
    pub(crate) fn degree_bounds<'a>(ps: impl Iterator<Item = &'a MPoly<F>> + Clone) -> (u32, u32)
    where
        F: 'a,
    {
        let dx = ps.clone().filter_map(|p| p.degree_in(0)).max().unwrap_or(0);
        let dy = ps.filter_map(|p| p.degree_in(1)).max().unwrap_or(0);
        (dx, dy)
    }

    /// `p(first/first_den, second/second_den) · first_den^{dx} · second_den^{dy}`
    /// (see [`substitute_rational`]).
    pub(crate) fn substitute(&self, p: &MPoly<F>, (dx, dy): (u32, u32)) -> MPoly<F> {
        substitute_rational(
            p,
            (&self.first, &self.first_den),
            (&self.second, &self.second_den),
            dx,
            dy,
        )
    }
}

fn mag<F: Scalar>(p: &MPoly<F>) -> f64 {
    p.terms().map(|(_, c)| c.to_f64().abs()).fold(1.0, f64::max)
}

fn cvec<F: Scalar>(re: &[F; 4], im: &[F; 4]) -> [CPoly<F>; 4] {
    core::array::from_fn(|k| CPoly {
        re: cst2(&re[k]),
        im: cst2(&im[k]),
    })
}

fn cdot<F: Scalar>(a: &[CPoly<F>; 4], b: &[CPoly<F>; 4]) -> CPoly<F> {
    a.iter()
        .zip(b)
        .fold(CPoly::real(MPoly::zero(2)), |acc, (x, y)| {
            acc.add(&x.mul(y))
        })
}

fn cplane3<F: Scalar>(p: &[CPoly<F>; 4], q: &[CPoly<F>; 4], r: &[CPoly<F>; 4]) -> [CPoly<F>; 4] {
    let m3 = |i: usize, j: usize, k: usize| -> CPoly<F> {
        let a = p[i].mul(&q[j].mul(&r[k]).sub(&q[k].mul(&r[j])));
        let b = p[j].mul(&q[i].mul(&r[k]).sub(&q[k].mul(&r[i])));
        let c = p[k].mul(&q[i].mul(&r[j]).sub(&q[j].mul(&r[i])));
        a.sub(&b).add(&c)
    };
    [
        m3(1, 2, 3).neg(),
        m3(0, 2, 3),
        m3(0, 1, 3).neg(),
        m3(0, 1, 2),
    ]
}

impl<F: Scalar> LineNet<F> {
    /// The net of the given kind from four points: the axes `c₀ + u c₁`, `d₀ + v d₁`
    /// (hyperbolic, parabolic) or the complex axis `(Re c₀ + i Im c₀) + u (Re c₁ + i Im c₁)`
    /// (elliptic), as the recipes write them.
    ///
    /// # Errors
    /// As [`PointRow::new`], [`Self::hyperbolic`], [`Self::parabolic`], [`Self::elliptic`].
    pub fn from_points(kind: NetKind, p: &[[F; 4]; 4]) -> Result<Self, NetError> {
        let r = |k: usize| p[k].clone();
        match kind {
            NetKind::Hyperbolic => {
                LineNet::hyperbolic(PointRow::new(r(0), r(1))?, PointRow::new(r(2), r(3))?)
            }
            NetKind::Parabolic => {
                LineNet::parabolic(PointRow::new(r(0), r(1))?, PointRow::new(r(2), r(3))?)
            }
            NetKind::Elliptic => LineNet::elliptic(ComplexPointRow {
                origin_re: r(0),
                origin_im: r(1),
                direction_re: r(2),
                direction_im: r(3),
            }),
        }
    }

    /// The hyperbolic net of the lines meeting the skew axes `c(u)`, `d(v)`.
    ///
    /// # Errors
    /// [`NetError::AxesMeet`] if the axes meet or coincide.
    pub fn hyperbolic(c: PointRow<F>, d: PointRow<F>) -> Result<Self, NetError> {
        let det = det4v(&c.origin, &c.direction, &d.origin, &d.direction);
        let s = scale_of(&c.origin)
            * scale_of(&c.direction)
            * scale_of(&d.origin)
            * scale_of(&d.direction);
        if is_small(&det, s) {
            return Err(NetError::AxesMeet);
        }
        Ok(LineNet::Hyperbolic { c, d })
    }

    /// The elliptic net of the real lines meeting the complex axis `c(u)` and its conjugate.
    ///
    /// # Errors
    /// [`NetError::ConjugateAxesMeet`] if `c` and `c̄` meet (a real axis, or an axis on Ω).
    pub fn elliptic(c: ComplexPointRow<F>) -> Result<Self, NetError> {
        let det = det4v(&c.origin_re, &c.origin_im, &c.direction_re, &c.direction_im);
        let s = [&c.origin_re, &c.origin_im, &c.direction_re, &c.direction_im]
            .iter()
            .map(|v| scale_of(*v).max(1.0))
            .product::<f64>();
        if is_small(&det, s) {
            return Err(NetError::ConjugateAxesMeet);
        }
        Ok(LineNet::Elliptic { c })
    }

    /// The parabolic net with axis `c(u)` and plane-point row `d(u)`: the lines through
    /// `c(u)` in the plane `[c(u), c₁, d(u)]`.
    ///
    /// # Errors
    /// [`NetError::DegenerateProjectivity`] if `det(c₀, c₁, d₀, d₁) = 0`.
    pub fn parabolic(c: PointRow<F>, d: PointRow<F>) -> Result<Self, NetError> {
        let det = det4v(&c.origin, &c.direction, &d.origin, &d.direction);
        let s = scale_of(&c.origin)
            * scale_of(&c.direction)
            * scale_of(&d.origin)
            * scale_of(&d.direction);
        if is_small(&det, s) {
            return Err(NetError::DegenerateProjectivity);
        }
        Ok(LineNet::Parabolic { c, d })
    }

    /// The type of the net.
    pub fn kind(&self) -> NetKind {
        match self {
            LineNet::Hyperbolic { .. } => NetKind::Hyperbolic,
            LineNet::Elliptic { .. } => NetKind::Elliptic,
            LineNet::Parabolic { .. } => NetKind::Parabolic,
        }
    }

    /// The names of the two net parameters: `("u", "v")`, or `("m", "n")` for elliptic nets
    /// (`u = m − i n`, `v = m + i n`).
    pub fn parameter_names(&self) -> (&'static str, &'static str) {
        match self {
            LineNet::Elliptic { .. } => ("m", "n"),
            _ => ("u", "v"),
        }
    }

    /// The first axis as complex polynomial vectors in the net parameters: `c(u)` with
    /// `u = var 0` (real nets) or `u = m − i n` (elliptic nets).
    pub(crate) fn axis_c(&self) -> [CPoly<F>; 4] {
        match self {
            LineNet::Hyperbolic { c, .. } | LineNet::Parabolic { c, .. } => {
                row_at(&c.origin, &c.direction, &MPoly::var(2, 0)).map(CPoly::real)
            }
            LineNet::Elliptic { c } => {
                let u = CPoly {
                    re: MPoly::var(2, 0),
                    im: -&MPoly::var(2, 1),
                };
                let c0 = cvec(&c.origin_re, &c.origin_im);
                let c1 = cvec(&c.direction_re, &c.direction_im);
                core::array::from_fn(|k| c0[k].add(&u.mul(&c1[k])))
            }
        }
    }

    /// The second point of the net line: `d(v)` (hyperbolic), `c̄(ū)` (elliptic),
    /// `d(u) + v c₁` (parabolic), as complex polynomial vectors in the net parameters.
    pub(crate) fn axis_d(&self) -> [CPoly<F>; 4] {
        match self {
            LineNet::Hyperbolic { d, .. } => {
                row_at(&d.origin, &d.direction, &MPoly::var(2, 1)).map(CPoly::real)
            }
            LineNet::Elliptic { .. } => self.axis_c().map(|x| x.conj()),
            LineNet::Parabolic { c, d } => {
                let u = MPoly::var(2, 0);
                let v = MPoly::var(2, 1);
                core::array::from_fn(|k| {
                    CPoly::real(
                        &(&cst2(&d.origin[k]) + &u.scale(&d.direction[k]))
                            + &v.scale(&c.direction[k]),
                    )
                })
            }
        }
    }

    /// Two real points spanning the net line `h(p, q)`, polynomial in the net parameters:
    /// `(c(u), d)` (hyperbolic, parabolic) or `(a, b)` with `c(u) = a + i b` (elliptic).
    pub fn line_points(&self) -> ([MPoly<F>; 4], [MPoly<F>; 4]) {
        let c = self.axis_c();
        let a: [MPoly<F>; 4] = core::array::from_fn(|k| c[k].re.clone());
        match self {
            LineNet::Elliptic { .. } => (a, core::array::from_fn(|k| c[k].im.clone())),
            _ => {
                let d = self.axis_d();
                (a, core::array::from_fn(|k| d[k].re.clone()))
            }
        }
    }

    /// The real net line `h(p, q)` as Plücker coordinates polynomial in the net parameters
    /// (`c(u) ∧ d`, or `a ∧ b` with `c(u) = a + i b` for elliptic nets).
    pub fn line_polynomials(&self) -> [MPoly<F>; 6] {
        let c = self.axis_c();
        match self {
            LineNet::Elliptic { .. } => {
                let a: [MPoly<F>; 4] = core::array::from_fn(|k| c[k].re.clone());
                let b: [MPoly<F>; 4] = core::array::from_fn(|k| c[k].im.clone());
                wedge(&a, &b)
            }
            _ => {
                let d = self.axis_d();
                let a: [MPoly<F>; 4] = core::array::from_fn(|k| c[k].re.clone());
                let b: [MPoly<F>; 4] = core::array::from_fn(|k| d[k].re.clone());
                wedge(&a, &b)
            }
        }
    }

    /// The net line at the parameters `(p, q)` (`(u, v)` or `(m, n)`).
    ///
    /// # Errors
    /// [`NetError::SingularPoint`] where the two spanning points coincide.
    pub fn line_at(&self, p: &F, q: &F) -> Result<Line<F>, NetError> {
        let h = self.line_polynomials();
        let x = [p.clone(), q.clone()];
        let l: Vec<F> = h
            .iter()
            .map(|k| k.eval(&x).unwrap_or_else(|_| F::zero()))
            .collect();
        let arr: [F; 6] = core::array::from_fn(|k| l[k].clone());
        Line::from_coords(arr).map_err(|_| {
            NetError::SingularPoint(format!(
                "the net has no line at the parameters ({}, {})",
                crate::error::format_scalar(p),
                crate::error::format_scalar(q)
            ))
        })
    }

    /// `Ω(c(u)) = A u² + 2B u + C` as the complex coefficients `(A, B, C)` (constants).
    fn omega_restriction(&self) -> (CPoly<F>, CPoly<F>, CPoly<F>) {
        let (r0, i0, r1, i1) = match self {
            LineNet::Hyperbolic { c, .. } | LineNet::Parabolic { c, .. } => {
                let z = [F::zero(), F::zero(), F::zero(), F::zero()];
                (c.origin.clone(), z.clone(), c.direction.clone(), z)
            }
            LineNet::Elliptic { c } => (
                c.origin_re.clone(),
                c.origin_im.clone(),
                c.direction_re.clone(),
                c.direction_im.clone(),
            ),
        };
        let c0 = cvec(&r0, &i0);
        let c1 = cvec(&r1, &i1);
        let form = |x: &[CPoly<F>; 4], y: &[CPoly<F>; 4]| {
            x[0].mul(&y[0])
                .add(&x[1].mul(&y[1]))
                .add(&x[2].mul(&y[2]))
                .sub(&x[3].mul(&y[3]))
        };
        (form(&c1, &c1), form(&c0, &c1), form(&c0, &c0))
    }

    fn position_of(a: &[F; 4], b: &[F; 4]) -> AxisPosition {
        let (aa, ab, bb) = (omega_form(b, b), omega_form(a, b), omega_form(a, a));
        let disc = ab.clone() * ab - aa * bb;
        let s = (scale_of(a) * scale_of(b)).powi(2);
        if is_small(&disc, s) {
            AxisPosition::Tangent
        } else if disc > F::zero() {
            AxisPosition::Secant
        } else {
            AxisPosition::Passant
        }
    }

    /// The positions of the axes with respect to Ω (Gruber §3.3–3.5): two for hyperbolic
    /// nets, the (equal) position of `c` and `c̄` for elliptic nets, one for parabolic nets.
    pub fn axis_positions(&self) -> Vec<AxisPosition> {
        match self {
            LineNet::Hyperbolic { c, d } => vec![
                Self::position_of(&c.origin, &c.direction),
                Self::position_of(&d.origin, &d.direction),
            ],
            LineNet::Parabolic { c, .. } => vec![Self::position_of(&c.origin, &c.direction)],
            LineNet::Elliptic { .. } => {
                let (a, b, cc) = self.omega_restriction();
                // B² − AC, complex constant
                let d = b.mul(&b).sub(&a.mul(&cc));
                let re = d.re.coeff(&[0, 0]);
                let im = d.im.coeff(&[0, 0]);
                let s = 1.0
                    + mag(&a.re)
                    + mag(&a.im)
                    + mag(&b.re)
                    + mag(&b.im)
                    + mag(&cc.re)
                    + mag(&cc.im);
                let pos = if is_small(&re, s * s) && is_small(&im, s * s) {
                    AxisPosition::Tangent
                } else {
                    AxisPosition::Secant
                };
                vec![pos, pos]
            }
        }
    }

    /// `true` if the two axes of a hyperbolic net are polar with respect to Ω (the polar
    /// line of `c`, the intersection of the polar planes `D c₀`, `D c₁`, is `d`; Gruber
    /// §3.3.4, second example). `false` for the other net types.
    pub fn axes_polar(&self) -> bool {
        match self {
            LineNet::Hyperbolic { c, d } => {
                let Ok(p) = Line::from_planes(&polar(&c.origin), &polar(&c.direction)) else {
                    return false;
                };
                p.same_line(&d.line())
            }
            _ => false,
        }
    }

    /// For a parabolic net with a tangent axis: `Some(true)` if the pencil at the contact
    /// point lies in the tangent plane of Ω there (all its lines touch Ω: Gruber §3.5.3
    /// case a), `Some(false)` if its plane cuts Ω in a conic (case b); `None` otherwise.
    pub fn parabolic_tangent_case_a(&self) -> Option<bool> {
        let LineNet::Parabolic { c, d } = self else {
            return None;
        };
        if Self::position_of(&c.origin, &c.direction) != AxisPosition::Tangent {
            return None;
        }
        let a = omega_form(&c.direction, &c.direction);
        let b = omega_form(&c.origin, &c.direction);
        // contact point c(u₀), u₀ = −B/A, or c₁ for A = 0 (u₀ = ∞)
        let (touch, plane_point) = if a.is_zero() {
            (c.direction.clone(), d.direction.clone())
        } else {
            let u0 = -b / a;
            (c.at(&u0), d.at(&u0))
        };
        let pencil = plane3(&c.origin, &c.direction, &plane_point);
        let tangent = polar(&touch);
        Some(super::proportional(&pencil, &tangent))
    }

    /// The linear congruence of the net: the singular complexes of both axes (hyperbolic),
    /// the real and imaginary parts of the complex axis `c₀ ∧ c₁` (elliptic), or the axis
    /// and a second complex solving `Ω(k, h(u, v)) ≡ 0` (parabolic).
    ///
    /// # Errors
    /// [`NetError::Line`] if the complexes are dependent (not for validated nets).
    pub fn congruence(&self) -> Result<LinearCongruence<F>, NetError> {
        match self {
            LineNet::Hyperbolic { c, d } => {
                Ok(LinearCongruence::from_focal_lines(&c.line(), &d.line())?)
            }
            LineNet::Elliptic { c } => {
                // c₀ ∧ c₁ = (r₀ + i i₀) ∧ (r₁ + i i₁) = (r₀∧r₁ − i₀∧i₁) + i (r₀∧i₁ + i₀∧r₁)
                let a = wedge(&c.origin_re, &c.direction_re);
                let b = wedge(&c.origin_im, &c.direction_im);
                let x = wedge(&c.origin_re, &c.direction_im);
                let y = wedge(&c.origin_im, &c.direction_re);
                let re: [F; 6] = core::array::from_fn(|k| a[k].clone() - b[k].clone());
                let im: [F; 6] = core::array::from_fn(|k| x[k].clone() + y[k].clone());
                Ok(LinearCongruence::new(
                    LinearComplex::new(re)?,
                    LinearComplex::new(im)?,
                )?)
            }
            LineNet::Parabolic { c, d } => {
                let ks = [
                    wedge(&c.origin, &d.origin),
                    core::array::from_fn(|k| {
                        wedge(&c.origin, &d.direction)[k].clone()
                            + wedge(&c.direction, &d.origin)[k].clone()
                    }),
                    wedge(&c.direction, &d.direction),
                    wedge(&c.origin, &c.direction),
                ];
                // Ω(k, x) = k₁x₄ + k₂x₅ + k₃x₆ + k₄x₁ + k₅x₂ + k₆x₃: row = (x₄, x₅, x₆, x₁, x₂, x₃)
                let rows: Vec<Vec<F>> = ks
                    .iter()
                    .map(|x| {
                        vec![
                            x[3].clone(),
                            x[4].clone(),
                            x[5].clone(),
                            x[0].clone(),
                            x[1].clone(),
                            x[2].clone(),
                        ]
                    })
                    .collect();
                let m =
                    Matrix::from_rows(rows).map_err(|e| NetError::SingularPoint(e.to_string()))?;
                let axis = c.line();
                let second = m
                    .null_space()
                    .into_iter()
                    .filter_map(|v| {
                        let arr: [F; 6] =
                            core::array::from_fn(|k| v.get(k).cloned().unwrap_or_else(F::zero));
                        (!super::proportional(&arr, axis.coords())).then_some(arr)
                    })
                    .next()
                    .ok_or(NetError::DegenerateProjectivity)?;
                Ok(LinearCongruence::new(
                    LinearComplex::singular(&axis),
                    LinearComplex::new(second)?,
                )?)
            }
        }
    }

    /// The parameters of the net line through the point `w` (a vector of polynomials in two
    /// variables; constants for a single point), as rational functions (module docs,
    /// "Fibration").
    ///
    /// # Errors
    /// [`NetError::SingularPoint`] if a denominator vanishes identically (`w` on an axis).
    pub fn parameters_of_point(&self, w: &[MPoly<F>; 4]) -> Result<NetParameters<F>, NetError> {
        let sing = |what: &str| {
            NetError::SingularPoint(format!("{what}: the point lies on an axis of the net"))
        };
        let k4 = |v: &[F; 4]| -> [MPoly<F>; 4] { core::array::from_fn(|k| cst2(&v[k])) };
        match self {
            LineNet::Hyperbolic { c, d } => {
                let (c0, c1, d0, d1) = (
                    k4(&c.origin),
                    k4(&c.direction),
                    k4(&d.origin),
                    k4(&d.direction),
                );
                let q = plane3(&d0, &d1, w);
                let p = plane3(&c0, &c1, w);
                let (un, ud) = (-dot4(&q, &c0), dot4(&q, &c1));
                let (vn, vd) = (-dot4(&p, &d0), dot4(&p, &d1));
                if ud.is_zero() || vd.is_zero() {
                    return Err(sing("hyperbolic net"));
                }
                Ok(NetParameters {
                    first: un,
                    first_den: ud,
                    second: vn,
                    second_den: vd,
                })
            }
            LineNet::Elliptic { c } => {
                let c0 = cvec(&c.origin_re, &c.origin_im);
                let c1 = cvec(&c.direction_re, &c.direction_im);
                let wc: [CPoly<F>; 4] = core::array::from_fn(|k| CPoly::real(w[k].clone()));
                let conj =
                    |v: &[CPoly<F>; 4]| -> [CPoly<F>; 4] { core::array::from_fn(|k| v[k].conj()) };
                let q = cplane3(&conj(&c0), &conj(&c1), &wc);
                let num = cdot(&q, &c0).neg();
                let den = cdot(&q, &c1);
                let prod = num.mul(&den.conj());
                let norm = &(&den.re * &den.re) + &(&den.im * &den.im);
                if norm.is_zero() {
                    return Err(sing("elliptic net"));
                }
                Ok(NetParameters {
                    first: prod.re,
                    first_den: norm.clone(),
                    second: -&prod.im,
                    second_den: norm,
                })
            }
            LineNet::Parabolic { c, d } => {
                let (c0, c1, d0, d1) = (
                    k4(&c.origin),
                    k4(&c.direction),
                    k4(&d.origin),
                    k4(&d.direction),
                );
                let p = plane3(&c0, &c1, w);
                let (un, ud) = (-dot4(&p, &d0), dot4(&p, &d1));
                if ud.is_zero() {
                    return Err(sing("parabolic net"));
                }
                let ct: [MPoly<F>; 4] = core::array::from_fn(|k| &(&ud * &c0[k]) + &(&un * &c1[k]));
                let dt: [MPoly<F>; 4] = core::array::from_fn(|k| &(&ud * &d0[k]) + &(&un * &d1[k]));
                for k in 0..4 {
                    let e: [MPoly<F>; 4] = core::array::from_fn(|j| {
                        MPoly::constant(2, if j == k { F::one() } else { F::zero() })
                    });
                    let z = plane3(&ct, w, &e);
                    let zc = dot4(&z, &c1);
                    if zc.is_zero() {
                        continue;
                    }
                    return Ok(NetParameters {
                        first: un,
                        first_den: ud.clone(),
                        second: -dot4(&z, &dt),
                        second_den: &ud * &zc,
                    });
                }
                Err(sing("parabolic net"))
            }
        }
    }

    /// The parameters of the net line through one point `w` of `ω` (Gruber §1.1.5).
    ///
    /// # Errors
    /// [`NetError::SingularPoint`] for a point of an axis (no unique net line).
    pub fn line_through(&self, w: &[F; 4]) -> Result<(F, F), NetError> {
        let wp: [MPoly<F>; 4] = core::array::from_fn(|k| cst2(&w[k]));
        let sing = || NetError::SingularPoint(fmt_vec(w));
        let p = self.parameters_of_point(&wp).map_err(|_| sing())?;
        let z = [F::zero(), F::zero()];
        let ev = |x: &MPoly<F>| x.eval(&z).unwrap_or_else(|_| F::zero());
        let (a, b, c, d) = (
            ev(&p.first),
            ev(&p.first_den),
            ev(&p.second),
            ev(&p.second_den),
        );
        let s = scale_of(w).powi(4).max(1.0);
        if is_small(&b, s) || is_small(&d, s) {
            return Err(sing());
        }
        Ok((a / b, c / d))
    }

    /// The scalar type converted.
    pub fn map_scalar<G: Scalar>(&self, f: impl Fn(&F) -> G + Copy) -> LineNet<G> {
        match self {
            LineNet::Hyperbolic { c, d } => LineNet::Hyperbolic {
                c: c.map(f),
                d: d.map(f),
            },
            LineNet::Parabolic { c, d } => LineNet::Parabolic {
                c: c.map(f),
                d: d.map(f),
            },
            LineNet::Elliptic { c } => LineNet::Elliptic {
                c: ComplexPointRow {
                    origin_re: core::array::from_fn(|k| f(&c.origin_re[k])),
                    origin_im: core::array::from_fn(|k| f(&c.origin_im[k])),
                    direction_re: core::array::from_fn(|k| f(&c.direction_re[k])),
                    direction_im: core::array::from_fn(|k| f(&c.direction_im[k])),
                },
            },
        }
    }
}

/// `p(X/Wx, Y/Wy) · Wx^{dx} · Wy^{dy}` for a polynomial `p` in two variables of degree at
/// most `dx` in the first and `dy` in the second.
pub(crate) fn substitute_rational<F: Scalar>(
    p: &MPoly<F>,
    x: (&MPoly<F>, &MPoly<F>),
    y: (&MPoly<F>, &MPoly<F>),
    dx: u32,
    dy: u32,
) -> MPoly<F> {
    let mut cache: std::collections::BTreeMap<(u8, u32), MPoly<F>> = Default::default();
    let mut pw = |key: (u8, u32), base: &MPoly<F>| -> MPoly<F> {
        cache.entry(key).or_insert_with(|| base.pow(key.1)).clone()
    };
    let mut acc = MPoly::zero(2);
    for (e, c) in p.terms() {
        let i = e.first().copied().unwrap_or(0);
        let j = e.get(1).copied().unwrap_or(0);
        let t = MPoly::constant(2, c.clone());
        let t = &(&t * &pw((0, i), x.0)) * &pw((1, dx.saturating_sub(i)), x.1);
        let t = &(&t * &pw((2, j), y.0)) * &pw((3, dy.saturating_sub(j)), y.1);
        acc = &acc + &t;
    }
    acc
}

impl<F: Scalar> Certified for LineNet<F> {
    /// Every net line lies on the Klein quadric and in both complexes of the net (it meets
    /// both axes; polynomial identities in the net parameters); the congruence has the
    /// stated type; the fibration `M(h(p(w), q(w))) w ≡ 0` for the points `w(s, t)` of Ω.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        let h = self.line_polynomials();
        let scale = 16.0 * h.iter().map(mag).fold(1.0, f64::max).powi(2);
        let klein = &(&(&h[0] * &h[3]) + &(&h[1] * &h[4])) + &(&h[2] * &h[5]);
        let coeffs: Vec<F> = klein.terms().map(|(_, c)| c.clone()).collect();
        out.push(polynomial_is_zero_scaled(
            "net lines h(u, v) on the Klein quadric: h₁h₄ + h₂h₅ + h₃h₆ ≡ 0 (Gruber (1.3))",
            &coeffs,
            scale,
        ));
        match self.congruence() {
            Ok(cong) => {
                let (k1, k2) = cong.complexes();
                for (name, k) in [("first", k1), ("second", k2)] {
                    let kp: [MPoly<F>; 6] = core::array::from_fn(|i| cst2(&k.coords()[i]));
                    let r = reciprocal_product(&kp, &h);
                    let coeffs: Vec<F> = r.terms().map(|(_, c)| c.clone()).collect();
                    out.push(polynomial_is_zero_scaled(
                        &format!("every net line lies in the {name} complex of the net: Ω(k, h(u, v)) ≡ 0 (Gruber (1.11))"),
                        &coeffs,
                        scale * (1.0 + scale_of(k.coords())),
                    ));
                }
                let want = match self.kind() {
                    NetKind::Hyperbolic => CongruenceKind::Hyperbolic,
                    NetKind::Elliptic => CongruenceKind::Elliptic,
                    NetKind::Parabolic => CongruenceKind::Parabolic,
                };
                let got = cong.kind();
                out.push(Certificate::decide(
                    format!("the net is a {want:?} linear congruence (Gruber §1.1.6)"),
                    got == want,
                    F::EXACT,
                    || format!("the complexes span a {got:?} congruence"),
                ));
            }
            Err(e) => out.push(Certificate::fails(
                "the complexes of the net",
                e.to_string(),
                F::EXACT,
            )),
        }
        let w = omega_parametrization::<F>();
        match self.parameters_of_point(&w) {
            Ok(p) => out.push(fibration_certificate(self, &p, &w)),
            Err(e) => out.push(Certificate::fails(
                "the net is a fibration of Ω (one net line through each point)",
                e.to_string(),
                F::EXACT,
            )),
        }
        out
    }
}

/// The certificate `M(h(p, q)) w ≡ 0` (Gruber (3.16)) for the parameters `p` of the net line
/// through the points `w`.
pub(crate) fn fibration_certificate<F: Scalar>(
    net: &LineNet<F>,
    p: &NetParameters<F>,
    w: &[MPoly<F>; 4],
) -> Certificate {
    let h = net.line_polynomials();
    let d = NetParameters::degree_bounds(h.iter());
    let hs: [MPoly<F>; 6] = core::array::from_fn(|k| p.substitute(&h[k], d));
    let m = incidence_matrix(&hs);
    let r: Vec<MPoly<F>> = m.iter().map(|row| dot4(row, w)).collect();
    let coeffs: Vec<F> = r
        .iter()
        .flat_map(|x| x.terms().map(|(_, c)| c.clone()))
        .collect();
    let scale =
        16.0 * hs.iter().map(mag).fold(1.0, f64::max) * w.iter().map(mag).fold(1.0, f64::max);
    polynomial_is_zero_scaled(
        "fibration: the net line through w(s, t) contains it, M(h(u(s,t), v(s,t))) w(s,t) ≡ 0 (Gruber (3.16))",
        &coeffs,
        scale,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }
    fn v4(a: [i64; 4]) -> [Rational; 4] {
        a.map(q)
    }
    fn row(a: [i64; 4], b: [i64; 4]) -> PointRow<Rational> {
        PointRow::new(v4(a), v4(b)).expect("row")
    }

    #[test]
    fn hyperbolic_net_of_gruber_331() {
        // (3.12): c(u) = (1, u, 0, 0), d(v) = (0, 2, v, 1)
        let net = LineNet::hyperbolic(
            row([1, 0, 0, 0], [0, 1, 0, 0]),
            row([0, 2, 0, 1], [0, 0, 1, 0]),
        )
        .expect("net");
        assert!(net.all_hold(), "{:?}", net.certify());
        assert_eq!(
            net.axis_positions(),
            vec![AxisPosition::Passant, AxisPosition::Passant]
        );
        // (3.13): h(u, v) = (2, v, 1, 0, −u, uv)
        let l = net.line_at(&q(3), &q(5)).expect("line");
        assert_eq!(l.coords().to_vec(), [2, 5, 1, 0, -3, 15].map(q).to_vec());
        // the line through a point of the net line has the same parameters
        let p = l.point_at(&Rational::from_ratio(1, 3));
        assert_eq!(net.line_through(&p).expect("fibre"), (q(3), q(5)));
        assert!(matches!(
            net.line_through(&v4([1, 7, 0, 0])),
            Err(NetError::SingularPoint(_))
        ));
    }

    #[test]
    fn degenerate_nets_are_errors() {
        assert!(matches!(
            LineNet::hyperbolic(
                row([1, 0, 0, 0], [0, 1, 0, 0]),
                row([1, 0, 0, 0], [0, 0, 1, 0])
            ),
            Err(NetError::AxesMeet)
        ));
        assert!(matches!(
            PointRow::new(v4([1, 2, 3, 4]), v4([2, 4, 6, 8])),
            Err(NetError::DegenerateAxis(_))
        ));
        // a real axis given as "complex": meets its conjugate
        let c = ComplexPointRow {
            origin_re: v4([1, 0, 0, 0]),
            origin_im: v4([0, 0, 0, 0]),
            direction_re: v4([0, 1, 0, 0]),
            direction_im: v4([0, 0, 0, 0]),
        };
        assert!(matches!(
            LineNet::elliptic(c),
            Err(NetError::ConjugateAxesMeet)
        ));
        // an isotropic line of Ω: (1, i, 0, 0) + u (0, 0, 1, 1)
        let c = ComplexPointRow {
            origin_re: v4([1, 0, 0, 0]),
            origin_im: v4([0, 1, 0, 0]),
            direction_re: v4([0, 0, 1, 1]),
            direction_im: v4([0, 0, 0, 0]),
        };
        assert!(matches!(
            LineNet::elliptic(c),
            Err(NetError::ConjugateAxesMeet)
        ));
        assert!(matches!(
            LineNet::parabolic(
                row([1, 0, 0, 0], [0, 0, 1, 0]),
                row([0, 1, 0, 0], [1, 0, 1, 0])
            ),
            Err(NetError::DegenerateProjectivity)
        ));
    }

    #[test]
    fn elliptic_and_parabolic_nets() {
        // Gruber (3.50): c(u) = (1, i, u, u i)
        let c = ComplexPointRow {
            origin_re: v4([1, 0, 0, 0]),
            origin_im: v4([0, 1, 0, 0]),
            direction_re: v4([0, 0, 1, 0]),
            direction_im: v4([0, 0, 0, 1]),
        };
        let net = LineNet::elliptic(c).expect("net");
        assert!(net.all_hold(), "{:?}", net.certify());
        assert_eq!(net.axis_positions(), vec![AxisPosition::Tangent; 2]);
        // Gruber (3.56): c(u) = (1, 0, u, 0), d = (0, 1, v, u)
        let net = LineNet::parabolic(
            row([1, 0, 0, 0], [0, 0, 1, 0]),
            row([0, 1, 0, 0], [0, 0, 0, 1]),
        )
        .expect("net");
        assert!(net.all_hold(), "{:?}", net.certify());
        assert_eq!(net.axis_positions(), vec![AxisPosition::Passant]);
        let l = net.line_at(&q(2), &q(-1)).expect("line");
        let p = l.point_at(&Rational::from_ratio(2, 7));
        assert_eq!(net.line_through(&p).expect("fibre"), (q(2), q(-1)));
    }
}
