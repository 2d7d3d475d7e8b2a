//! Linear line congruences (line nets, Gruber §1.1.4–1.1.6): the lines common to two
//! linear complexes `C(c₁) ∩ C(c₂)`.
//!
//! **Classification.** The complexes of the pencil `σc₁ + τc₂` are singular where
//! `σ²Ω₁₁ + 2στΩ₁₂ + τ²Ω₂₂ = 0`, `Ωᵢⱼ = Ω(cᵢ, cⱼ)` (the reciprocal product; a complex is
//! singular iff `Ω(c, c) = 2(c₁c₄ + c₂c₅ + c₃c₆) = 0`). With `Δ = Ω₁₂² − Ω₁₁Ω₂₂`:
//!
//! * `Δ > 0`: two real singular complexes; their axes are the two real skew **focal lines**
//!   and the congruence consists of the lines meeting both: **hyperbolic** net;
//! * `Δ < 0`: conjugate complex focal lines `a ± i b`: **elliptic** net (its real lines meet
//!   both, i.e. `Ω(a, x) = Ω(b, x) = 0`);
//! * `Δ = 0` (not all `Ωᵢⱼ` zero): one double focal line: **parabolic** net;
//! * `Ω₁₁ = Ω₁₂ = Ω₂₂ = 0`: every complex of the pencil is singular, the axes form a pencil of
//!   lines with vertex `V` in a plane `ε`, and the congruence is the bundle through `V`
//!   together with the field in `ε` (the **singular** net of Gruber §1.1.6).
//!
//! The focal lines `(−Ω₁₂ ± √Δ)/Ω₁₁ · c₁ + c₂` need `√Δ`; they are returned over
//! [`SqrtScalar::Ext`] ([`rcagd_algebra::QuadExt`] for exact input).
//!
//! **Fibration** (Gruber §1.1.5): through a point `p` that is not on a focal line (nor the
//! vertex/plane of a singular net) passes exactly one line of a regular net, the
//! intersection of the null planes of `p` in the two complexes — a rational construction,
//! also for elliptic nets.

use super::complex::LinearComplex;
use super::plucker::{klein_form, reciprocal_product, unit4, Line};
use super::{dot, fmt_vec, is_small, proportional, scale_of, LineError, SqrtScalar};
use crate::Certified;
use num_traits::{One, Zero};
use rcagd_algebra::{Certificate, Scalar};

/// The type of a linear congruence (Gruber §1.1.6).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CongruenceKind {
    /// Two real skew focal lines.
    Hyperbolic,
    /// Two conjugate complex skew focal lines.
    Elliptic,
    /// One (double) focal line.
    Parabolic,
    /// All complexes of the pencil singular: bundle and field (singular net).
    Degenerate,
}

/// The focal lines of a linear congruence. `F` is the input scalar, `E` its square-root
/// extension ([`SqrtScalar::Ext`]).
#[derive(Debug, Clone, PartialEq)]
pub enum FocalLines<F, E> {
    /// The two real focal lines (over the extension by `√Δ`).
    Hyperbolic([Line<E>; 2]),
    /// The conjugate complex focal lines `re ± i·im` (coordinate vectors over the extension).
    Elliptic {
        /// Real part of the focal lines' coordinates.
        re: [E; 6],
        /// Imaginary part of the focal lines' coordinates.
        im: [E; 6],
    },
    /// The single focal line (rational).
    Parabolic(Line<F>),
    /// The vertex and plane of a singular net.
    Degenerate {
        /// The common point of all axes (the bundle vertex).
        vertex: [F; 4],
        /// The common plane of all axes (the field carrier).
        plane: [F; 4],
    },
}

/// The linear congruence `C(c₁) ∩ C(c₂)` (a line net).
#[derive(Debug, Clone, PartialEq)]
pub struct LinearCongruence<F> {
    c1: LinearComplex<F>,
    c2: LinearComplex<F>,
}

fn lin<F: Scalar>(a: &F, x: &[F; 6], b: &F, y: &[F; 6]) -> [F; 6] {
    core::array::from_fn(|k| a.clone() * x[k].clone() + b.clone() * y[k].clone())
}

impl<F: Scalar> LinearCongruence<F> {
    /// The congruence of lines common to two complexes.
    ///
    /// # Errors
    /// [`LineError::DependentComplexes`] if `c₁ ∥ c₂` (one complex, not a congruence).
    pub fn new(c1: LinearComplex<F>, c2: LinearComplex<F>) -> Result<Self, LineError> {
        if proportional(c1.coords(), c2.coords()) {
            return Err(LineError::DependentComplexes(format!(
                "{} ∥ {}",
                fmt_vec(c1.coords()),
                fmt_vec(c2.coords())
            )));
        }
        Ok(LinearCongruence { c1, c2 })
    }

    /// The lines meeting two given lines (hyperbolic net for skew lines, singular net for
    /// meeting lines).
    ///
    /// # Errors
    /// [`LineError::DependentComplexes`] for equal lines.
    pub fn from_focal_lines(a1: &Line<F>, a2: &Line<F>) -> Result<Self, LineError> {
        Self::new(LinearComplex::singular(a1), LinearComplex::singular(a2))
    }

    /// The two complexes.
    pub fn complexes(&self) -> (&LinearComplex<F>, &LinearComplex<F>) {
        (&self.c1, &self.c2)
    }

    /// `(Ω₁₁, Ω₁₂, Ω₂₂)`.
    pub fn gram(&self) -> (F, F, F) {
        let (a, b) = (self.c1.coords(), self.c2.coords());
        (
            reciprocal_product(a, a),
            reciprocal_product(a, b),
            reciprocal_product(b, b),
        )
    }

    /// `Δ = Ω₁₂² − Ω₁₁Ω₂₂` (module docs).
    pub fn discriminant(&self) -> F {
        let (b11, b12, b22) = self.gram();
        b12.clone() * b12 - b11 * b22
    }

    fn scale(&self) -> f64 {
        scale_of(self.c1.coords()).max(scale_of(self.c2.coords()))
    }

    /// The type of the congruence (module docs).
    pub fn kind(&self) -> CongruenceKind {
        let (b11, b12, b22) = self.gram();
        let s2 = self.scale().powi(2);
        if [&b11, &b12, &b22].iter().all(|x| is_small(*x, s2)) {
            return CongruenceKind::Degenerate;
        }
        let d = self.discriminant();
        if is_small(&d, s2 * s2) {
            CongruenceKind::Parabolic
        } else if d > F::zero() {
            CongruenceKind::Hyperbolic
        } else {
            CongruenceKind::Elliptic
        }
    }

    /// `true` if the line belongs to both complexes.
    pub fn contains(&self, x: &Line<F>) -> bool {
        self.c1.contains(x) && self.c2.contains(x)
    }

    /// The unique line of the congruence through `p`: the intersection of the null planes of
    /// `p` in both complexes (Gruber §1.1.5, fibration).
    ///
    /// # Errors
    /// [`LineError::SingularPoint`] if `p` lies on a focal line (or an axis of a singular
    /// complex of the pencil, or is the vertex of a singular net): then the null planes
    /// coincide or vanish.
    pub fn line_through(&self, p: &[F; 4]) -> Result<Line<F>, LineError> {
        let sing = || {
            LineError::SingularPoint(format!(
                "{} lies on a focal line: infinitely many lines of the congruence pass through it",
                fmt_vec(p)
            ))
        };
        let u1 = self.c1.null_plane(p).map_err(|_| sing())?;
        let u2 = self.c2.null_plane(p).map_err(|_| sing())?;
        let l = Line::from_planes(&u1, &u2).map_err(|_| sing())?;
        Ok(Line::from_coords_unchecked(l.coords().clone()))
    }
}

/// The line `ε(u) ∩ φ(v)` of the hyperbolic net with focal lines `a₁, a₂`: the planes of
/// the pencils about `a₁` and `a₂` (Gruber §1.1.6, "Hyperbolisches Netz": all net lines are
/// obtained by intersecting the pencil `ε(u)` about `a₁` with the pencil `φ(v)` about `a₂`).
///
/// # Errors
/// [`LineError::CoincidentPlanes`] where `ε(u) = φ(v)` (not for skew focal lines).
pub fn net_line<F: Scalar>(a1: &Line<F>, a2: &Line<F>, u: &F, v: &F) -> Result<Line<F>, LineError> {
    let l = Line::from_planes(&a1.pencil_plane(u), &a2.pencil_plane(v))?;
    Ok(Line::from_coords_unchecked(l.coords().clone()))
}

impl<F: SqrtScalar> LinearCongruence<F> {
    /// The focal lines (module docs): two real lines over `F::Ext` (hyperbolic), the real and
    /// imaginary parts of the conjugate pair (elliptic), the double line (parabolic), or
    /// vertex and plane (degenerate).
    ///
    /// # Errors
    /// [`LineError::DependentComplexes`] only for inconsistent `f64` data (a degenerate
    /// pencil whose axes do not meet).
    pub fn focal_lines(&self) -> Result<FocalLines<F, F::Ext>, LineError> {
        let (b11, b12, b22) = self.gram();
        let (c1, c2) = (self.c1.coords(), self.c2.coords());
        let s2 = self.scale().powi(2);
        let e = |v: &[F; 6]| -> [F::Ext; 6] { core::array::from_fn(|k| v[k].embed()) };
        let (e1, e2) = (e(c1), e(c2));
        match self.kind() {
            CongruenceKind::Degenerate => {
                let a1 = Line::from_coords_unchecked(c1.clone());
                let a2 = Line::from_coords_unchecked(c2.clone());
                let vertex = a1.intersection(&a2).map_err(|err| {
                    LineError::DependentComplexes(format!("degenerate pencil: {err}"))
                })?;
                let plane = a1.joining_plane(&a2).map_err(|err| {
                    LineError::DependentComplexes(format!("degenerate pencil: {err}"))
                })?;
                Ok(FocalLines::Degenerate { vertex, plane })
            }
            CongruenceKind::Parabolic => {
                let a = if !is_small(&b11, s2) {
                    lin(&(-b12 / b11), c1, &F::one(), c2)
                } else if !is_small(&b22, s2) {
                    lin(&F::one(), c1, &(-b12 / b22), c2)
                } else {
                    c1.clone()
                };
                Ok(FocalLines::Parabolic(Line::from_coords_unchecked(a)))
            }
            CongruenceKind::Hyperbolic => {
                let d = self.discriminant();
                let r = d
                    .sqrt_ext()
                    .ok_or_else(|| LineError::DependentComplexes("negative discriminant".into()))?;
                let (x1, x2) = if !is_small(&b11, s2) {
                    let (b11e, b12e) = (b11.embed(), b12.embed());
                    let s_plus = (-b12e.clone() + r.clone()) / b11e.clone();
                    let s_minus = (-b12e - r) / b11e;
                    let one = F::Ext::one();
                    (lin(&s_plus, &e1, &one, &e2), lin(&s_minus, &e1, &one, &e2))
                } else if !is_small(&b22, s2) {
                    let (b22e, b12e) = (b22.embed(), b12.embed());
                    let t_plus = (-b12e.clone() + r.clone()) / b22e.clone();
                    let t_minus = (-b12e - r) / b22e;
                    let one = F::Ext::one();
                    (lin(&one, &e1, &t_plus, &e2), lin(&one, &e1, &t_minus, &e2))
                } else {
                    (e1, e2)
                };
                Ok(FocalLines::Hyperbolic([
                    Line::from_coords_unchecked(x1),
                    Line::from_coords_unchecked(x2),
                ]))
            }
            CongruenceKind::Elliptic => {
                let d = -self.discriminant();
                let r = d
                    .sqrt_ext()
                    .ok_or_else(|| LineError::DependentComplexes("positive discriminant".into()))?;
                let b11e = b11.embed();
                let re = lin(&(-b12.embed() / b11e.clone()), &e1, &F::Ext::one(), &e2);
                let im = lin(&(r / b11e), &e1, &F::Ext::zero(), &e2);
                Ok(FocalLines::Elliptic { re, im })
            }
        }
    }

    /// Sample lines of the congruence through the points `eᵢ`, `(1,1,1,1)`, `(1,2,3,5)`
    /// (singular points skipped).
    pub fn sample_lines(&self) -> Vec<Line<F>> {
        let mut pts: Vec<[F; 4]> = (0..4).map(unit4).collect();
        pts.push([F::one(), F::one(), F::one(), F::one()]);
        pts.push([F::one(), F::from_i64(2), F::from_i64(3), F::from_i64(5)]);
        pts.iter()
            .filter_map(|p| self.line_through(p).ok())
            .collect()
    }
}

fn ext_zero_cert<E: Scalar>(property: String, v: &E, scale: f64) -> Certificate {
    Certificate::decide(property, is_small(v, scale), E::EXACT, || {
        crate::error::format_scalar(v)
    })
}

impl<F: SqrtScalar> Certified for LinearCongruence<F> {
    /// Focal lines on the Klein quadric; hyperbolic focal lines skew; sample lines of the
    /// congruence (through the points of [`LinearCongruence::sample_lines`]) belong to both
    /// complexes and meet every focal line (exactly, over the extension).
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        let focal = match self.focal_lines() {
            Ok(f) => f,
            Err(e) => return vec![Certificate::fails("focal lines", e.to_string(), F::EXACT)],
        };
        let samples = self.sample_lines();
        out.push(Certificate::decide(
            "the congruence has lines through generic points (fibration)",
            !samples.is_empty(),
            F::EXACT,
            || "no sample line".into(),
        ));
        for x in &samples {
            let s = self.scale() * scale_of(x.coords());
            let (v1, v2) = (self.c1.evaluate(x), self.c2.evaluate(x));
            out.push(Certificate::decide(
                format!("line {} lies in both complexes", fmt_vec(x.coords())),
                is_small(&v1, s) && is_small(&v2, s),
                F::EXACT,
                || format!("Ω(c₁, x) = {v1:?}, Ω(c₂, x) = {v2:?}"),
            ));
        }
        let ext = |x: &Line<F>| -> [F::Ext; 6] { core::array::from_fn(|k| x.coords()[k].embed()) };
        match &focal {
            FocalLines::Hyperbolic([a1, a2]) => {
                for (name, a) in [("a₁", a1), ("a₂", a2)] {
                    out.push(super::plucker::klein_cert(
                        &format!("hyperbolic focal line {name}"),
                        a.coords(),
                    ));
                    for x in &samples {
                        let v = reciprocal_product(a.coords(), &ext(x));
                        out.push(ext_zero_cert(
                            format!("line {} meets focal line {name}", fmt_vec(x.coords())),
                            &v,
                            scale_of(a.coords()) * scale_of(x.coords()),
                        ));
                    }
                }
                let w = reciprocal_product(a1.coords(), a2.coords());
                out.push(Certificate::decide(
                    "the focal lines are skew: Ω(a₁, a₂) ≠ 0",
                    !is_small(&w, scale_of(a1.coords()) * scale_of(a2.coords())),
                    F::EXACT,
                    || "Ω(a₁, a₂) = 0".into(),
                ));
            }
            FocalLines::Elliptic { re, im } => {
                // a = re + i·im on the Klein quadric: Re: q(re) − q(im) = 0, Im: Ω(re, im) = 0.
                let qr = klein_form(re) - klein_form(im);
                let qi = reciprocal_product(re, im);
                let s = scale_of(re).max(scale_of(im)).powi(2);
                out.push(Certificate::decide(
                    "elliptic focal lines re ± i·im lie on the Klein quadric",
                    is_small(&qr, s) && is_small(&qi, s),
                    F::EXACT,
                    || format!("real part {qr:?}, imaginary part {qi:?}"),
                ));
                for x in &samples {
                    let (u, v) = (
                        reciprocal_product(re, &ext(x)),
                        reciprocal_product(im, &ext(x)),
                    );
                    let sc = scale_of(re).max(scale_of(im)) * scale_of(x.coords());
                    out.push(Certificate::decide(
                        format!(
                            "line {} meets both conjugate focal lines",
                            fmt_vec(x.coords())
                        ),
                        is_small(&u, sc) && is_small(&v, sc),
                        F::EXACT,
                        || format!("Ω(re, x) = {u:?}, Ω(im, x) = {v:?}"),
                    ));
                }
            }
            FocalLines::Parabolic(a) => {
                out.push(super::plucker::klein_cert(
                    "parabolic focal line",
                    a.coords(),
                ));
                for x in &samples {
                    let v = a.reciprocal_product(x);
                    out.push(ext_zero_cert(
                        format!("line {} meets the focal line", fmt_vec(x.coords())),
                        &v,
                        scale_of(a.coords()) * scale_of(x.coords()),
                    ));
                }
            }
            FocalLines::Degenerate { vertex, plane } => {
                for x in &samples {
                    let ok = x.contains_point(vertex) || x.lies_in_plane(plane);
                    out.push(Certificate::decide(
                        format!(
                            "line {} passes through the vertex or lies in the plane",
                            fmt_vec(x.coords())
                        ),
                        ok,
                        F::EXACT,
                        || "neither".into(),
                    ));
                }
                let inc = dot(vertex, plane);
                out.push(ext_zero_cert(
                    "the vertex lies in the plane of the singular net".into(),
                    &inc,
                    scale_of(vertex) * scale_of(plane),
                ));
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }
    fn aff(a: [i64; 3], b: [i64; 3]) -> Line<Rational> {
        Line::from_affine_points(&a.map(q), &b.map(q)).expect("line")
    }

    #[test]
    fn hyperbolic_from_two_skew_lines() {
        let a1 = aff([0, 0, 0], [1, 0, 0]);
        let a2 = aff([0, 0, 1], [0, 1, 1]);
        let c = LinearCongruence::from_focal_lines(&a1, &a2).expect("net");
        assert_eq!(c.kind(), CongruenceKind::Hyperbolic);
        assert!(c.all_hold(), "{:?}", c.certify());
        let l = c.line_through(&[q(1), q(2), q(3), q(1)]).expect("line");
        assert!(l.meets(&a1) && l.meets(&a2));
        assert!(matches!(
            c.line_through(&[q(1), q(5), q(0), q(0)]),
            Err(LineError::SingularPoint(_))
        ));
    }

    #[test]
    fn elliptic_and_parabolic() {
        // c₁ regular, c₂ regular with Δ < 0
        let c1 = LinearComplex::new([1, 0, 0, 1, 0, 0].map(q)).expect("c1");
        let c2 = LinearComplex::new([0, 1, 0, 0, 1, 0].map(q)).expect("c2");
        let e = LinearCongruence::new(c1.clone(), c2).expect("e");
        // Ω₁₁ = 2, Ω₂₂ = 2, Ω₁₂ = 0: Δ = −4
        assert_eq!(e.kind(), CongruenceKind::Elliptic);
        assert!(e.all_hold(), "{:?}", e.certify());
        // parabolic: regular complex + singular complex whose axis lies in it
        let axis = Line::from_coords([0, 1, 0, 0, 0, 0].map(q)).expect("axis");
        assert!(c1.contains(&axis));
        let p = LinearCongruence::new(c1, LinearComplex::singular(&axis)).expect("p");
        assert_eq!(p.kind(), CongruenceKind::Parabolic);
        assert!(p.all_hold(), "{:?}", p.certify());
    }

    #[test]
    fn net_lines_from_pencils() {
        let a1 = aff([0, 0, 0], [1, 0, 0]);
        let a2 = aff([0, 0, 1], [0, 1, 1]);
        let net = LinearCongruence::from_focal_lines(&a1, &a2).expect("net");
        for (u, v) in [(0, 0), (2, -1), (5, 3)] {
            let l = net_line(&a1, &a2, &q(u), &q(v)).expect("line");
            assert!(l.meets(&a1) && l.meets(&a2) && net.contains(&l));
        }
    }

    #[test]
    fn degenerate_net() {
        let a1 = aff([0, 0, 0], [1, 0, 0]);
        let a2 = aff([0, 0, 0], [0, 1, 0]);
        let c = LinearCongruence::from_focal_lines(&a1, &a2).expect("net");
        assert_eq!(c.kind(), CongruenceKind::Degenerate);
        assert!(c.all_hold(), "{:?}", c.certify());
    }
}
