//! Alternative generations of line nets (Gruber 2008 §1.1.6; H. Pottmann and J. Wallner,
//! "Computational Line Geometry", 2001, §3.2; docs/math/lines-and-canal.md, "Generations of
//! line nets").
//!
//! A line net (linear congruence) is the set of lines common to two linear complexes. Besides
//! "the lines meeting two axes" ([`super::LineNet`]) it arises as
//!
//! * the **joins of corresponding points of a collineation** `κ: α → β` between two planes
//!   that maps the common line `s = α ∩ β` onto itself without fixing it pointwise
//!   ([`GeneratedNet::from_plane_collineation`]): the lines `x ∨ κ(x)` of a general
//!   collineation form a congruence of order 3 and class 1; when `κ(s) = s` two of the three
//!   fixed points of the induced collineation of `α` (used to count the lines through a point)
//!   lie on `s` and give no line, so the order drops to one;
//! * the **union of a one-parameter family of reguli**: two reguli whose carrier planes in
//!   the Klein model meet in a line (they share two lines, real or conjugate complex) span a
//!   3-space of `P⁵`, i.e. a net ([`GeneratedNet::from_reguli`]); conversely the net lines
//!   meeting a line `g` outside the net form the regulus `N ∩ C(g)`
//!   ([`regulus_meeting`]);
//! * a **pencil of planes with a projectivity**: the points `c(u)` of a line `a` are mapped
//!   projectively to the planes `ε(u)` through `a`; the pencils of lines about `c(u)` in
//!   `ε(u)` form a parabolic net with focal line `a`
//!   ([`GeneratedNet::from_pencil_projectivity`]);
//! * a **pencil of planes cut with a bundle of planes**: the planes `ε(u) = ε₀ + u ε₁` about
//!   the axis `a` and the planes `φ(u, v) = φ₀ + u φ₁ + v φ₂` through a point `P ∉ a` with
//!   `φ₂ ⊃ a` (the plane `[a, P]`); the lines `ε(u) ∩ φ(u, v)` form the parabolic net whose
//!   pencil about the vertex `c(u) = ε₀ ∩ ε₁ ∩ (φ₀ + u φ₁)` lies in `ε(u)` (Gruber 2008 §1.1.6,
//!   "Parabolisches Netz": the dual of the lines `c(u) ∨ d(u, v)` joining the points of the
//!   axis with the points of a plane; [`GeneratedNet::from_pencil_and_bundle`]);
//! * the **tangents of a ruled surface along a non-torsal generator** `g`: the tangent plane
//!   `T(v) = [X, X_u, X_v]` at `X(u₀, v) = p(u₀) + v q(u₀)` is a projective image of the
//!   point, the tangent lines form the parabolic net of that projectivity
//!   ([`GeneratedNet::from_ruled_surface_tangents`]).
//!
//! The net is found by linear algebra: a complex `c` contains the generated lines
//! `l(u, v)` (polynomials) iff every coefficient of `Ω(c, l(u, v))` vanishes, a linear
//! system in `c`; the generation is a net iff its kernel has dimension exactly 2.
//! [`GeneratedNet::certify`] proves `l ∈ Klein quadric` and `Ω(kᵢ, l(u, v)) ≡ 0` for both
//! complexes as polynomial identities.

use super::congruence::{CongruenceKind, LinearCongruence};
use super::net::{det4v, dot4, plane3, LineNet, NetError, PointRow};
use super::plucker::{klein_form, reciprocal_product, wedge, Line};
use super::regulus::Regulus;
use super::{complex::LinearComplex, fmt_vec, is_small, proportional, scale_of, LineError};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Matrix, Poly, Scalar};
use rcagd_geom::certify::polynomial_is_zero_scaled;
use thiserror::Error;

/// Errors of the alternative net generations. Every variant names the violated precondition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum GenerationError {
    /// Three points that must span a plane are collinear.
    #[error("the points {0} are collinear: they span no plane")]
    NotAPlane(String),
    /// The two planes of a collineation coincide.
    #[error("the planes α and β of the collineation coincide")]
    SamePlane,
    /// The generated lines do not lie in exactly two independent linear complexes.
    #[error("the generated lines lie in {complexes} independent linear complexes, a net in exactly 2: {hint}")]
    NotANet {
        /// The dimension of the space of complexes containing every generated line.
        complexes: usize,
        /// What the generation requires.
        hint: String,
    },
    /// A plane of the pencil does not contain the axis.
    #[error("the plane {0} does not contain the axis of the pencil")]
    PlaneNotThroughAxis(String),
    /// The planes of a pencil projectivity coincide (a constant map, no projectivity).
    #[error("the planes ε₀ and ε₁ coincide: u ↦ ε₀ + u ε₁ is no projectivity")]
    DegeneratePencil,
    /// The planes of a bundle are dependent (no carrier point) or the carrier point lies
    /// on the axis of the pencil.
    #[error("degenerate bundle of planes: {0}")]
    DegenerateBundle(String),
    /// The generator of a ruled surface is torsal: the tangent plane is the same along it.
    #[error("the generator at u = {0} is torsal: det(p, q, p', q') = 0, all its points have one tangent plane (no parabolic net)")]
    TorsalGenerator(String),
    /// A line-net failure underneath.
    #[error(transparent)]
    Net(#[from] NetError),
    /// A line-geometry failure underneath.
    #[error(transparent)]
    Line(#[from] LineError),
}

/// Which generation produced a [`GeneratedNet`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Generation {
    /// Joins of corresponding points of a collineation between two planes.
    PlaneCollineation,
    /// Union of two reguli of the net.
    Reguli,
    /// A pencil of planes with a projectivity from the points of its axis.
    PencilProjectivity,
    /// Tangents of a ruled surface along a non-torsal generator.
    RuledSurfaceTangents,
    /// A pencil of planes cut with a bundle of planes.
    PencilBundle,
}

/// A two-parameter family of lines with polynomial Plücker coordinates in `(u, v)`.
#[derive(Debug, Clone)]
pub struct LineFamily<F> {
    /// What the family is.
    pub name: String,
    /// `l(u, v)` (variables 0 and 1).
    pub lines: [MPoly<F>; 6],
}

/// A net obtained by one of the alternative generations (module docs), with the generating
/// line families, the net (two complexes) and, for the parabolic generations, the net as a
/// [`LineNet`] usable for sphere-family envelopes.
#[derive(Debug, Clone)]
pub struct GeneratedNet<F> {
    generation: Generation,
    families: Vec<LineFamily<F>>,
    congruence: LinearCongruence<F>,
    net: Option<LineNet<F>>,
    identities: Vec<(String, Vec<MPoly<F>>)>,
}

fn mag<F: Scalar>(p: &MPoly<F>) -> f64 {
    p.terms().map(|(_, c)| c.to_f64().abs()).fold(1.0, f64::max)
}

fn cst<F: Scalar>(c: &F) -> MPoly<F> {
    MPoly::constant(2, c.clone())
}

/// `a + u b + v c` with `u, v` the variables 0 and 1.
fn affine_plane_point<F: Scalar>(a: &[F; 4], b: &[F; 4], c: &[F; 4]) -> [MPoly<F>; 4] {
    let u = MPoly::var(2, 0);
    let v = MPoly::var(2, 1);
    core::array::from_fn(|k| &(&cst(&a[k]) + &u.scale(&b[k])) + &v.scale(&c[k]))
}

/// The kernel of `m` (exact Gauss–Jordan for exact scalars, SVD with a relative tolerance
/// for `f64`).
fn kernel<F: Scalar>(m: &Matrix<F>) -> Vec<Vec<F>> {
    if F::EXACT {
        m.null_space()
    } else {
        rcagd_algebra::linalg::null_space_f64(&m.to_f64(), 1e-9)
            .map(|vs| {
                vs.into_iter()
                    .map(|v| {
                        v.into_iter()
                            .map(|x| {
                                x.to_rational()
                                    .map(|q| F::from_rational(&q))
                                    .unwrap_or_else(F::zero)
                            })
                            .collect()
                    })
                    .collect()
            })
            .unwrap_or_default()
    }
}

/// The linear complexes containing every line of the families: the kernel of the system
/// "every coefficient of `Ω(c, l(u, v))` vanishes" (`Ω(c, l) = c₁l₄ + c₂l₅ + c₃l₆ + c₄l₁ +
/// c₅l₂ + c₆l₃`, Gruber (1.11)).
pub fn complexes_containing<F: Scalar>(families: &[&[MPoly<F>; 6]]) -> Vec<[F; 6]> {
    let mut rows: Vec<Vec<F>> = Vec::new();
    for l in families {
        let mut monos: Vec<Vec<u32>> = l
            .iter()
            .flat_map(|p| p.terms().map(|(e, _)| e.to_vec()).collect::<Vec<_>>())
            .collect();
        monos.sort();
        monos.dedup();
        for e in monos {
            // c_k multiplies l_{k+3} (k < 3) and l_{k−3} (k ≥ 3)
            rows.push((0..6).map(|k| l[(k + 3) % 6].coeff(&e)).collect());
        }
    }
    if rows.is_empty() {
        return Vec::new();
    }
    let Ok(m) = Matrix::from_rows(rows) else {
        return Vec::new();
    };
    kernel(&m)
        .into_iter()
        .map(|v| core::array::from_fn(|k| v.get(k).cloned().unwrap_or_else(F::zero)))
        .collect()
}

/// `Poly` → `MPoly` in variable `var` of two.
fn lift<F: Scalar>(p: &Poly<F>, var: usize) -> MPoly<F> {
    MPoly::from_poly(p, 2, var)
}

impl<F: Scalar> GeneratedNet<F> {
    fn build(
        generation: Generation,
        families: Vec<LineFamily<F>>,
        hint: &str,
        net: Option<LineNet<F>>,
        identities: Vec<(String, Vec<MPoly<F>>)>,
    ) -> Result<Self, GenerationError> {
        let refs: Vec<&[MPoly<F>; 6]> = families.iter().map(|f| &f.lines).collect();
        let ks = complexes_containing(&refs);
        if ks.len() != 2 {
            return Err(GenerationError::NotANet {
                complexes: ks.len(),
                hint: hint.into(),
            });
        }
        let congruence = LinearCongruence::new(
            LinearComplex::new(ks[0].clone())?,
            LinearComplex::new(ks[1].clone())?,
        )?;
        Ok(GeneratedNet {
            generation,
            families,
            congruence,
            net,
            identities,
        })
    }

    /// The net of the joins `x ∨ κ(x)` of a collineation `κ: α → β` given by the images of
    /// a frame: `κ(x₀a₀ + x₁a₁ + x₂a₂) = x₀b₀ + x₁b₁ + x₂b₂` (Gruber 2008 §1.1.6,
    /// "Elliptisches Netz"; module docs). The generated family is
    /// `l(u, v) = (a₀ + u a₁ + v a₂) ∧ (b₀ + u b₁ + v b₂)`.
    ///
    /// # Errors
    /// [`GenerationError::NotAPlane`] for collinear `aᵢ` or `bᵢ`,
    /// [`GenerationError::SamePlane`] for `α = β`, [`GenerationError::NotANet`] unless `κ`
    /// maps `s = α ∩ β` onto itself without fixing every point of `s` (a general
    /// collineation gives a congruence of order 3, a pointwise fixed `s` a bundle).
    pub fn from_plane_collineation(
        a: &[[F; 4]; 3],
        b: &[[F; 4]; 3],
    ) -> Result<Self, GenerationError> {
        let pa = plane3(&a[0], &a[1], &a[2]);
        let pb = plane3(&b[0], &b[1], &b[2]);
        for (pts, pl) in [(a, &pa), (b, &pb)] {
            let s = pts.iter().map(|p| scale_of(p)).product::<f64>();
            if pl.iter().all(|x| is_small(x, s)) {
                let v: Vec<String> = pts.iter().map(|p| fmt_vec(p)).collect();
                return Err(GenerationError::NotAPlane(v.join(", ")));
            }
        }
        if proportional(&pa, &pb) {
            return Err(GenerationError::SamePlane);
        }
        let x = affine_plane_point(&a[0], &a[1], &a[2]);
        let y = affine_plane_point(&b[0], &b[1], &b[2]);
        let fam = LineFamily {
            name: "joins x(u, v) ∨ κ(x(u, v)) of the collineation".into(),
            lines: wedge(&x, &y),
        };
        Self::build(
            Generation::PlaneCollineation,
            vec![fam],
            "the collineation must map the common line α ∩ β onto itself without fixing it pointwise",
            None,
            Vec::new(),
        )
    }

    /// The net spanned by two reguli (module docs): the union of the one-parameter family
    /// of reguli through their two common lines.
    ///
    /// # Errors
    /// [`GenerationError::NotANet`] unless the six defining lines span exactly a net (the
    /// reguli share two lines, real or conjugate complex).
    pub fn from_reguli(r1: &Regulus<F>, r2: &Regulus<F>) -> Result<Self, GenerationError> {
        let fams: Vec<LineFamily<F>> = [r1, r2]
            .iter()
            .enumerate()
            .map(|(i, r)| LineFamily {
                name: format!("generators of regulus {}", i + 1),
                lines: r.generator_polys().map(|p| lift(&p, 0)),
            })
            .collect();
        Self::build(
            Generation::Reguli,
            fams,
            "the two reguli must share two lines (their carrier planes in the Klein model meet in a line)",
            None,
            Vec::new(),
        )
    }

    /// The parabolic net of a pencil of planes with a projectivity: the point
    /// `c(u) = c₀ + u c₁` of the axis is mapped to the plane `ε(u) = ε₀ + u ε₁` through the
    /// axis, the net lines are the lines through `c(u)` in `ε(u)` (Gruber 2008 §1.1.6,
    /// "Parabolisches Netz"). A general projectivity is obtained by choosing the
    /// representatives `ε₀, ε₁`. The result carries the net as
    /// [`LineNet::Parabolic`] with `d(u) = ε(u) ∩ m` for a coordinate line `m` skew to the axis.
    ///
    /// # Errors
    /// [`NetError::DegenerateAxis`] for `c₀ ∧ c₁ = 0`, [`GenerationError::PlaneNotThroughAxis`],
    /// [`GenerationError::DegeneratePencil`] for `ε₀ ∥ ε₁`.
    pub fn from_pencil_projectivity(
        c: PointRow<F>,
        e0: &[F; 4],
        e1: &[F; 4],
    ) -> Result<Self, GenerationError> {
        let c = PointRow::new(c.origin, c.direction)?;
        for e in [e0, e1] {
            let s = scale_of(e) * scale_of(&c.origin).max(scale_of(&c.direction));
            if !(is_small(&dot4(e, &c.origin), s) && is_small(&dot4(e, &c.direction), s)) {
                return Err(GenerationError::PlaneNotThroughAxis(fmt_vec(e)));
            }
        }
        if proportional(e0, e1) {
            return Err(GenerationError::DegeneratePencil);
        }
        // a coordinate line m = e_i ∧ e_j skew to the axis
        let unit = |i: usize| -> [F; 4] {
            core::array::from_fn(|k| if k == i { F::one() } else { F::zero() })
        };
        let mut m = None;
        'outer: for i in 0..4 {
            for j in i + 1..4 {
                let d = det4v(&c.origin, &c.direction, &unit(i), &unit(j));
                if !is_small(&d, scale_of(&c.origin) * scale_of(&c.direction)) {
                    m = Some((unit(i), unit(j)));
                    break 'outer;
                }
            }
        }
        let (q0, q1) = m.ok_or(GenerationError::Net(NetError::DegenerateProjectivity))?;
        // ε ∩ (q₀ ∧ q₁) = ⟨ε, q₁⟩ q₀ − ⟨ε, q₀⟩ q₁, linear in u
        let meet = |e: &[F; 4]| -> [F; 4] {
            let (a, b) = (dot4(e, &q1), dot4(e, &q0));
            core::array::from_fn(|k| a.clone() * q0[k].clone() - b.clone() * q1[k].clone())
        };
        let d = PointRow::new(meet(e0), meet(e1))?;
        let net = LineNet::parabolic(c.clone(), d)?;
        // identity: every net line lies in its plane ε(u): ⟨ε(u), c(u)⟩ ≡ 0 is the axis
        // condition, ⟨ε(u), d(u) + v c₁⟩ ≡ 0 the pencil condition
        let h = net.line_polynomials();
        let u = MPoly::var(2, 0);
        let eps: [MPoly<F>; 4] = core::array::from_fn(|k| &cst(&e0[k]) + &u.scale(&e1[k]));
        let inc = plane_contains_line(&eps, &h);
        Self::build(
            Generation::PencilProjectivity,
            vec![LineFamily {
                name: "lines c(u) ∧ (d(u) + v c₁) of the pencils".into(),
                lines: h,
            }],
            "a pencil with a projectivity always gives a parabolic net",
            Some(net),
            vec![(
                "every net line through c(u) lies in the plane ε(u) of the projectivity".into(),
                inc,
            )],
        )
    }

    /// The parabolic net cut by the pencil of planes `ε(u) = ε₀ + u ε₁` from the bundle of
    /// planes `φ(u, v) = φ₀ + u φ₁ + v φ₂` (module docs; Gruber 2008 §1.1.6): the lines
    /// `l(u, v) = ε(u) ∩ φ(u, v)` (axis coordinates `ε(u) ∧ φ(u, v)`, Gruber (1.1) for
    /// planes). For fixed `u` they pass through the vertex `c(u) = ε₀ ∩ ε₁ ∩ (φ₀ + uφ₁)` (the
    /// pencil of `φ(u, ·)` has its axis in `φ₂`, which meets `ε(u)` in `a`), so the net is the
    /// pencil projectivity `c(u) ↦ ε(u)` ([`Self::from_pencil_projectivity`]). Certified:
    /// Klein and both complexes for the generated lines and for the net's own lines, and
    /// `c(u) ∈ l(u, v)` identically.
    ///
    /// # Errors
    /// [`GenerationError::DegeneratePencil`] for `ε₀ ∥ ε₁`;
    /// [`GenerationError::DegenerateBundle`] if `φ₀, φ₁, φ₂` have no single common point `P`
    /// or `P` lies on the axis; [`GenerationError::NotANet`] if `φ₂` does not contain the axis
    /// (then all vertices coincide: the lines form a bundle), or if `u ↦ c(u)` is constant.
    pub fn from_pencil_and_bundle(
        e0: &[F; 4],
        e1: &[F; 4],
        f: &[[F; 4]; 3],
    ) -> Result<Self, GenerationError> {
        if proportional(e0, e1) {
            return Err(GenerationError::DegeneratePencil);
        }
        let p = plane3(&f[0], &f[1], &f[2]);
        let sp = scale_of(&f[0]) * scale_of(&f[1]) * scale_of(&f[2]);
        if p.iter().all(|x| is_small(x, sp)) {
            return Err(GenerationError::DegenerateBundle(format!(
                "the planes {}, {}, {} share a line (no single carrier point)",
                fmt_vec(&f[0]),
                fmt_vec(&f[1]),
                fmt_vec(&f[2])
            )));
        }
        let se = scale_of(&p) * scale_of(e0).max(scale_of(e1));
        if is_small(&dot4(e0, &p), se) && is_small(&dot4(e1, &p), se) {
            return Err(GenerationError::DegenerateBundle(format!(
                "the carrier point {} lies on the axis of the pencil",
                fmt_vec(&p)
            )));
        }
        let hint = "the plane φ₂ must contain the axis of the pencil (φ₂ = [a, P]) and u ↦ φ₀ + uφ₁ must move the vertex along the axis";
        let not_a_net = |complexes: usize| GenerationError::NotANet {
            complexes,
            hint: hint.into(),
        };
        // the vertex c(u) = ε₀ ∩ ε₁ ∩ (φ₀ + u φ₁), linear in u
        let c0 = plane3(e0, e1, &f[0]);
        let c1 = plane3(e0, e1, &f[1]);
        let row = PointRow::new(c0.clone(), c1.clone()).map_err(|_| not_a_net(3))?;
        let projective = Self::from_pencil_projectivity(row, e0, e1)?;
        let net = projective.net.clone();
        // the generated lines ε(u) ∩ φ(u, v): axis coordinates ε ∧ φ
        let (u, v) = (MPoly::var(2, 0), MPoly::var(2, 1));
        let eps: [MPoly<F>; 4] = core::array::from_fn(|k| &cst(&e0[k]) + &u.scale(&e1[k]));
        let phi: [MPoly<F>; 4] =
            core::array::from_fn(|k| &(&cst(&f[0][k]) + &u.scale(&f[1][k])) + &v.scale(&f[2][k]));
        let lines = super::plucker::swap(&wedge(&eps, &phi));
        let cu: [MPoly<F>; 4] = core::array::from_fn(|k| &cst(&c0[k]) + &u.scale(&c1[k]));
        let m = super::plucker::incidence_matrix(&lines);
        let through: Vec<MPoly<F>> = m.iter().map(|r| dot4(r, &cu)).collect();
        let mut families = vec![LineFamily {
            name: "lines ε(u) ∩ φ(u, v) of the pencil and the bundle".into(),
            lines,
        }];
        families.extend(projective.families.iter().cloned());
        let mut identities = vec![(
            "every line ε(u) ∩ φ(u, v) passes through the vertex c(u) = ε₀ ∩ ε₁ ∩ (φ₀ + uφ₁) of the net's pencil".into(),
            through,
        )];
        identities.extend(projective.identities.iter().cloned());
        Self::build(Generation::PencilBundle, families, hint, net, identities).map_err(
            |e| match e {
                GenerationError::NotANet { complexes, .. } => not_a_net(complexes),
                other => other,
            },
        )
    }

    /// The parabolic net of the tangents of the ruled surface `X(u, v) = p(u) + v q(u)`
    /// (homogeneous points) along the generator `u = u₀` (Gruber 2008 §1.1.6; Pottmann and
    /// Wallner 2001, §5.1): axis `c(v) = p(u₀) + v q(u₀)`, tangent plane
    /// `T(v) = [c(v), q(u₀), p'(u₀) + v q'(u₀)]`, i.e. [`LineNet::Parabolic`] with
    /// `d(v) = p'(u₀) + v q'(u₀)`.
    ///
    /// # Errors
    /// [`GenerationError::TorsalGenerator`] if `det(p, q, p', q')(u₀) = 0`;
    /// [`NetError::DegenerateAxis`] if `p(u₀) ∧ q(u₀) = 0`.
    pub fn from_ruled_surface_tangents(
        p: &[Poly<F>; 4],
        q: &[Poly<F>; 4],
        u0: &F,
    ) -> Result<Self, GenerationError> {
        let ev = |x: &[Poly<F>; 4]| -> [F; 4] { core::array::from_fn(|k| x[k].eval(u0)) };
        let dv =
            |x: &[Poly<F>; 4]| -> [F; 4] { core::array::from_fn(|k| x[k].derivative().eval(u0)) };
        let (c0, c1, d0, d1) = (ev(p), ev(q), dv(p), dv(q));
        let c = PointRow::new(c0.clone(), c1.clone())?;
        let det = det4v(&c0, &c1, &d0, &d1);
        let s = scale_of(&c0) * scale_of(&c1) * scale_of(&d0).max(1.0) * scale_of(&d1).max(1.0);
        if is_small(&det, s) {
            return Err(GenerationError::TorsalGenerator(
                crate::error::format_scalar(u0),
            ));
        }
        let d = PointRow::new(d0, d1)?;
        let net = LineNet::parabolic(c, d)?;
        let h = net.line_polynomials();
        // the tangent plane from the surface's own partial derivatives: X(u, v) with the
        // surface parameter u as variable 1 and v as variable 0, then u = u₀
        let x: [MPoly<F>; 4] =
            core::array::from_fn(|k| &lift(&p[k], 1) + &(&MPoly::var(2, 0) * &lift(&q[k], 1)));
        let xu: [MPoly<F>; 4] = core::array::from_fn(|k| x[k].partial(1));
        let xv: [MPoly<F>; 4] = core::array::from_fn(|k| x[k].partial(0));
        let t: [MPoly<F>; 4] = plane3(&x, &xu, &xv).map(|c| c.specialize(1, u0));
        let inc = plane_contains_line(&t, &h);
        Self::build(
            Generation::RuledSurfaceTangents,
            vec![LineFamily {
                name: "tangent lines along the generator".into(),
                lines: h,
            }],
            "the tangents along a non-torsal generator always form a parabolic net",
            Some(net),
            vec![(
                "every net line through X(u₀, v) lies in the tangent plane [X, X_u, X_v](u₀, v)"
                    .into(),
                inc,
            )],
        )
    }

    /// The generation.
    pub fn generation(&self) -> Generation {
        self.generation
    }

    /// The generated line families.
    pub fn families(&self) -> &[LineFamily<F>] {
        &self.families
    }

    /// The net as the intersection of two linear complexes.
    pub fn congruence(&self) -> &LinearCongruence<F> {
        &self.congruence
    }

    /// The net as a [`LineNet`] (parabolic generations only).
    pub fn line_net(&self) -> Option<&LineNet<F>> {
        self.net.as_ref()
    }
}

/// The incidence conditions "the line `h` lies in the plane `e`": the plane incidence
/// matrix `M̃(h)` of Gruber (1.7) (axis coordinates) applied to `e` (all four entries vanish).
fn plane_contains_line<F: Scalar>(e: &[MPoly<F>; 4], h: &[MPoly<F>; 6]) -> Vec<MPoly<F>> {
    let axis = super::plucker::swap(h);
    let m = super::plucker::incidence_matrix(&axis);
    m.iter().map(|row| dot4(row, e)).collect()
}

/// The regulus of the net lines meeting the line `g` (not a line of the net): the net lines
/// through three points of `g` (the fibration, Gruber §1.1.5); all net lines meeting `g`
/// form the regulus `N ∩ C(g)` (module docs).
///
/// # Errors
/// [`LineError::SingularPoint`] if one of the points `g(0), g(1), g(−1)` lies on a focal
/// line, [`LineError::NotSkew`] if the three net lines are not pairwise skew (`g` meets a
/// focal line or lies in the net).
pub fn regulus_meeting<F: Scalar>(
    net: &LinearCongruence<F>,
    g: &Line<F>,
) -> Result<Regulus<F>, LineError> {
    let lines: Vec<Line<F>> = [F::zero(), F::one(), -F::one()]
        .iter()
        .map(|s| net.line_through(&g.point_at(s)))
        .collect::<Result<_, _>>()?;
    Regulus::from_lines(&lines[0], &lines[1], &lines[2])
}

fn coeffs_of<F: Scalar>(ps: &[MPoly<F>]) -> Vec<F> {
    ps.iter()
        .flat_map(|p| p.terms().map(|(_, c)| c.clone()).collect::<Vec<_>>())
        .collect()
}

impl<F: Scalar> Certified for GeneratedNet<F> {
    /// For every generated family: the lines lie on the Klein quadric and in both complexes
    /// of the net (polynomial identities in the parameters); the families span exactly a
    /// net (rank 4 of the coefficient system); the generation's own incidences (plane of the
    /// pencil, tangent plane); for the parabolic generations the congruence is parabolic and
    /// the [`LineNet`] certificates.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        let (k1, k2) = self.congruence.complexes();
        for fam in &self.families {
            let h = &fam.lines;
            let scale = 16.0 * h.iter().map(mag).fold(1.0, f64::max).powi(2);
            out.push(polynomial_is_zero_scaled(
                &format!(
                    "{}: on the Klein quadric, l₁l₄ + l₂l₅ + l₃l₆ ≡ 0 (Gruber (1.3))",
                    fam.name
                ),
                &coeffs_of(&[klein_form(h)]),
                scale,
            ));
            for (name, k) in [("first", k1), ("second", k2)] {
                let kp: [MPoly<F>; 6] = core::array::from_fn(|i| cst(&k.coords()[i]));
                out.push(polynomial_is_zero_scaled(
                    &format!(
                        "{}: in the {name} complex of the net, Ω(k, l(u, v)) ≡ 0 (Gruber (1.11))",
                        fam.name
                    ),
                    &coeffs_of(&[reciprocal_product(&kp, h)]),
                    scale * (1.0 + scale_of(k.coords())),
                ));
            }
        }
        let refs: Vec<&[MPoly<F>; 6]> = self.families.iter().map(|f| &f.lines).collect();
        let dim = complexes_containing(&refs).len();
        out.push(Certificate::decide(
            "the generated lines lie in exactly two independent complexes (a net, Gruber §1.1.6)",
            dim == 2,
            F::EXACT,
            || format!("{dim} independent complexes"),
        ));
        for (name, ps) in &self.identities {
            let scale = 16.0 * ps.iter().map(mag).fold(1.0, f64::max);
            out.push(polynomial_is_zero_scaled(name, &coeffs_of(ps), scale));
        }
        if let Some(net) = &self.net {
            let kind = self.congruence.kind();
            out.push(Certificate::decide(
                "the generated net is parabolic (Gruber §1.1.6)",
                kind == CongruenceKind::Parabolic,
                F::EXACT,
                || format!("{kind:?}"),
            ));
            out.extend(net.certify());
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn v4(a: [i64; 4]) -> [Rational; 4] {
        a.map(Rational::from)
    }

    #[test]
    fn collineation_fixing_the_common_line() {
        // α: x₃ = 0, β: x₂ = 0, s = {x₂ = x₃ = 0}; b₀, b₁ ∈ s ⇒ κ(s) = s
        let a = [v4([1, 0, 0, 0]), v4([0, 1, 0, 0]), v4([0, 0, 1, 0])];
        let b = [v4([1, 1, 0, 0]), v4([0, 2, 0, 0]), v4([3, 1, 0, 1])];
        let g = GeneratedNet::from_plane_collineation(&a, &b).expect("net");
        assert!(g.all_hold(), "{:?}", g.certify());
        // a general collineation: order 3, one complex only
        let b = [v4([1, 1, 0, 1]), v4([0, 2, 0, 0]), v4([3, 1, 0, 1])];
        assert!(matches!(
            GeneratedNet::from_plane_collineation(&a, &b),
            Err(GenerationError::NotANet { complexes: 1, .. })
        ));
        // s fixed pointwise: a bundle (three complexes)
        let b = [v4([1, 0, 0, 0]), v4([0, 1, 0, 0]), v4([3, 1, 0, 1])];
        assert!(matches!(
            GeneratedNet::from_plane_collineation(&a, &b),
            Err(GenerationError::NotANet { complexes: 3, .. })
        ));
    }

    #[test]
    fn net_from_two_reguli_of_an_elliptic_net() {
        let q = |a: [i64; 6]| a.map(Rational::from);
        let net = LinearCongruence::new(
            LinearComplex::new(q([1, 0, 0, 1, 0, 0])).expect("c1"),
            LinearComplex::new(q([0, 1, 0, 0, 1, 0])).expect("c2"),
        )
        .expect("net");
        assert_eq!(net.kind(), CongruenceKind::Elliptic);
        let g1 = Line::from_affine_points(
            &[3, 1, 2].map(Rational::from),
            &[1, -2, 5].map(Rational::from),
        )
        .expect("g1");
        let g2 = Line::from_affine_points(
            &[0, 4, -1].map(Rational::from),
            &[2, 2, 7].map(Rational::from),
        )
        .expect("g2");
        let r1 = regulus_meeting(&net, &g1).expect("r1");
        let r2 = regulus_meeting(&net, &g2).expect("r2");
        for l in r1.lines().iter().chain(r2.lines()) {
            assert!(net.contains(l) && (l.meets(&g1) || l.meets(&g2)));
        }
        let g = GeneratedNet::from_reguli(&r1, &r2).expect("generated");
        assert!(g.all_hold(), "{:?}", g.certify());
        assert_eq!(g.congruence().kind(), CongruenceKind::Elliptic);
        // the generated net is the given one: its sample lines lie in the original complexes
        for l in g.congruence().sample_lines() {
            assert!(net.contains(&l));
        }
        // two reguli of different nets
        let other = LinearCongruence::new(
            LinearComplex::new(q([1, 2, 0, 1, 0, 3])).expect("c1"),
            LinearComplex::new(q([0, 1, 5, 0, 1, 0])).expect("c2"),
        )
        .expect("other");
        let r3 = regulus_meeting(&other, &g2).expect("r3");
        assert!(matches!(
            GeneratedNet::from_reguli(&r1, &r3),
            Err(GenerationError::NotANet { .. })
        ));
    }

    #[test]
    fn pencil_projectivity_and_ruled_surface_tangents() {
        let c = PointRow::new(v4([1, 0, 0, 0]), v4([0, 0, 1, 0])).expect("axis");
        let g =
            GeneratedNet::from_pencil_projectivity(c.clone(), &v4([0, 1, 0, 0]), &v4([0, 2, 0, 1]))
                .expect("net");
        assert!(g.all_hold(), "{:?}", g.certify());
        assert!(matches!(
            GeneratedNet::from_pencil_projectivity(c.clone(), &v4([1, 1, 0, 0]), &v4([0, 0, 0, 1])),
            Err(GenerationError::PlaneNotThroughAxis(_))
        ));
        assert!(matches!(
            GeneratedNet::from_pencil_projectivity(c, &v4([0, 1, 0, 0]), &v4([0, 2, 0, 0])),
            Err(GenerationError::DegeneratePencil)
        ));
        // hyperbolic paraboloid X(u, v) = (1, u, v, uv)
        let pp = |a: [&[i64]; 4]| a.map(Poly::from_ints);
        let p = pp([&[1], &[0, 1], &[0], &[0]]);
        let qq = pp([&[0], &[0], &[1], &[0, 1]]);
        let g =
            GeneratedNet::from_ruled_surface_tangents(&p, &qq, &Rational::from(2)).expect("net");
        assert!(g.all_hold(), "{:?}", g.certify());
        assert_eq!(g.generation(), Generation::RuledSurfaceTangents);
        // a cone: every generator is torsal
        let p = pp([&[1], &[0], &[0], &[0]]);
        let qq = pp([&[0], &[1], &[0, 1], &[0, 0, 1]]);
        assert!(matches!(
            GeneratedNet::from_ruled_surface_tangents(&p, &qq, &Rational::from(1)),
            Err(GenerationError::TorsalGenerator(_))
        ));
    }
}
