//! STEP (ISO 10303-21) export of exact rational geometry, AP214 or AP242.
//!
//! # What is written
//!
//! Every [`Object`] becomes one part: `PRODUCT` (named after the object) →
//! `PRODUCT_DEFINITION_FORMATION` → `PRODUCT_DEFINITION` → `PRODUCT_DEFINITION_SHAPE` →
//! `SHAPE_DEFINITION_REPRESENTATION` → a shape representation in one shared
//! `GEOMETRIC_REPRESENTATION_CONTEXT(3)` with units (millimetre, radian, steradian) and
//! an uncertainty of `1.E-07`. Several objects are several root parts of one file.
//!
//! * **Curves** become `B_SPLINE_CURVE_WITH_KNOTS` in a `GEOMETRIC_CURVE_SET` of a
//!   `GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION`. Consecutive pieces of
//!   one degree that meet (exactly, as Euclidean points) are joined into one B-spline
//!   with the knots `0ᵖ⁺¹, 1ᵖ, 2ᵖ, …, kᵖ⁺¹` of
//!   [`NurbsCurve::from_bezier_pieces`] (piece `i` on `[i, i+1]`).
//! * **Patches** become `B_SPLINE_SURFACE_WITH_KNOTS` on `[0, 1]²` (knots
//!   `0ᵐ⁺¹ 1ᵐ⁺¹`, `0ⁿ⁺¹ 1ⁿ⁺¹`), each the geometry of an `ADVANCED_FACE` bounded by
//!   its boundary curves (`EDGE_CURVE`s on exact B-spline curves, `VERTEX_POINT`s at
//!   the corners). Every `EDGE_CURVE` is a `SURFACE_CURVE` carrying its parameter lines
//!   (`PCURVE`s) on its faces: the side of the parameter square, exact, a rational line
//!   with weights `1, 1/ρ` where the face's boundary is a Möbius reparametrization of
//!   the edge curve (see below). A boundary curve that collapses to a point (a sphere's
//!   pole; detected exactly: all Euclidean control points equal) is a degenerate edge of
//!   its face alone: an `EDGE_CURVE` from the pole's vertex to itself on the collapsed
//!   curve, with the side's parameter line, which OpenCascade reads as a degenerated
//!   edge (it does not count for the shell's closedness). Two patches share an edge when their boundary curves are the same
//!   curve exactly: the same rational parametrization
//!   ([`BezierCurve::same_parametrization`]) or one related to it by an
//!   end-point-preserving Möbius reparametrization `Qᵢ = λ ρⁱ Pᵢ`, `ρ > 0` (in either
//!   direction). Faces connected by shared edges form a shell; each shell is oriented
//!   consistently (adjacent faces traverse a shared edge in opposite directions, a face
//!   is flipped with `same_sense = .F.` and a reversed loop where needed). A shell whose
//!   every edge is used exactly twice is closed: it is oriented outward (positive
//!   signed volume of a tessellation) and becomes a `CLOSED_SHELL` of a
//!   `MANIFOLD_SOLID_BREP` in an `ADVANCED_BREP_SHAPE_REPRESENTATION`. Otherwise the
//!   shells (`OPEN_SHELL`, and `CLOSED_SHELL`s beside them) form a
//!   `SHELL_BASED_SURFACE_MODEL` in a `MANIFOLD_SURFACE_SHAPE_REPRESENTATION`.
//! * Rational geometry (weights not all equal) uses the complex-entity form
//!   `(BOUNDED_SURFACE() B_SPLINE_SURFACE(…) B_SPLINE_SURFACE_WITH_KNOTS(…)
//!   GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(…)
//!   REPRESENTATION_ITEM('') SURFACE())` (likewise for curves); polynomial geometry the
//!   simple entity.
//!
//! # Numbers
//!
//! STEP carries binary64 reals. Each exact rational (a Euclidean coordinate `wx/w`, a
//! weight, a knot) is rounded once, correctly, to `f64` and written as the shortest
//! decimal that reads back to that `f64` (Rust's `{:?}`), in the real syntax of
//! ISO 10303-21 (`1.`, `0.5`, `1.E-07`); see [`format_real`]. The exact values are kept
//! in a JSON sidecar ([`exact_sidecar`]), which the readers can apply
//! ([`crate::step_read::apply_sidecar`]).
//!
//! Weights must be positive (CAD kernels reject others): a piece whose weights are all
//! negative is negated (the same curve); a piece with zero or mixed-sign weights whose
//! weight function has no zero is split exactly into pieces of one sign
//! ([`crate::model::Geometry::drawable_curves`], `drawable_patches`); a weight function
//! with a zero on the domain (a point at infinity) is an error. Pieces whose
//! weights vary by more than 16× or leave `[2⁻⁸, 2⁸]` are balanced by an exact Möbius
//! reparametrization and a power-of-2 scale ([`crate::balance`]) before anything is
//! written, so the files and the sidecar carry the same, balanced, weights. Geometry in
//! E1 or E2 is embedded in E3 (`z = 0`); dimensions above 3 are an error.

use crate::json::rational_to_json;
use crate::model::Object;
use crate::IoError;
use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::grid::{linspace, PatchEvaluator3};
use rcagd_geom::nurbs::{NurbsCurve, NurbsSurface};
use rcagd_geom::{BezierCurve, BezierPatch};
use serde_json::{json, Value};
use std::collections::HashMap;
use std::fmt::Write as _;

// ---------------------------------------------------------------------------------
// Numbers and strings
// ---------------------------------------------------------------------------------

/// `1eN` (or `-1eN`), the decimal order of a non-zero rational, for messages about numbers
/// too large to print in full.
fn order_of(x: &Rational) -> String {
    let digits = |s: String| s.trim_start_matches('-').len() as i64;
    let e = digits(x.numerator().to_string()) - digits(x.denominator().to_string());
    let sign = if *x < Rational::ZERO { "-" } else { "" };
    format!("{sign}1e{e}")
}

/// The shortest decimal that reads back to `x`, in the real syntax of ISO 10303-21
/// (and of IGES): a mandatory decimal point, an upper-case exponent
/// (`1.`, `-0.5`, `1.E-07`, `1.5E+300`). Negative zero is written `0.`.
///
/// # Errors
/// [`IoError::Invalid`] for NaN or an infinity (e.g. a rational beyond `f64::MAX`).
pub fn format_real(x: f64) -> Result<String, IoError> {
    if !x.is_finite() {
        return Err(IoError::Invalid(format!(
            "the number {x} cannot be written: it is not a finite binary64 value"
        )));
    }
    if x == 0.0 {
        return Ok("0.".into());
    }
    let s = format!("{x:?}");
    let (mant, exp) = match s.split_once('e') {
        Some((m, e)) => (m, Some(e)),
        None => (s.as_str(), None),
    };
    let mut out = if let Some(stripped) = mant.strip_suffix(".0") {
        format!("{stripped}.")
    } else if mant.contains('.') {
        mant.to_string()
    } else {
        format!("{mant}.")
    };
    if let Some(e) = exp {
        let (sign, digits) = match e.strip_prefix('-') {
            Some(d) => ('-', d),
            None => ('+', e),
        };
        let _ = write!(out, "E{sign}{digits:0>2}");
    }
    Ok(out)
}

/// [`format_real`] of the correctly rounded value of an exact rational.
pub(crate) fn rational_real(q: &Rational) -> Result<String, IoError> {
    format_real(Scalar::to_f64(q))
}

/// A STEP string literal: `'` doubled, `\` doubled, characters outside printable
/// ASCII as `\X2\hhhh…\X0\` (UTF-16 code units, ISO 10303-21 §6.4.3.3).
pub fn step_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('\'');
    let mut wide: Vec<u16> = Vec::new();
    let flush = |wide: &mut Vec<u16>, out: &mut String| {
        if !wide.is_empty() {
            out.push_str("\\X2\\");
            for u in wide.iter() {
                let _ = write!(out, "{u:04X}");
            }
            out.push_str("\\X0\\");
            wide.clear();
        }
    };
    for c in s.chars() {
        if (' '..='~').contains(&c) {
            flush(&mut wide, &mut out);
            match c {
                '\'' => out.push_str("''"),
                '\\' => out.push_str("\\\\"),
                _ => out.push(c),
            }
        } else {
            let mut buf = [0u16; 2];
            wide.extend_from_slice(c.encode_utf16(&mut buf));
        }
    }
    flush(&mut wide, &mut out);
    out.push('\'');
    out
}

// ---------------------------------------------------------------------------------
// Exchange geometry: exact NURBS in E3 with positive weights
// ---------------------------------------------------------------------------------

/// An object's geometry as it is exchanged (STEP and IGES): exact, in E3, with
/// positive weights.
#[derive(Debug, Clone, PartialEq)]
pub struct ExchangeObject {
    /// The object's name.
    pub name: String,
    /// The curves, consecutive meeting pieces joined (see the module docs).
    pub curves: Vec<NurbsCurve<Rational>>,
    /// The patches (one face each), oriented consistently in their shells.
    pub patches: Vec<BezierPatch<Rational>>,
    /// For each patch, whether it was reversed in `u` to orient it (relative to the
    /// object's drawable pieces, [`crate::model::Geometry::drawable_patches`]).
    pub reversed: Vec<bool>,
    /// The boundary representation of `patches`, built once for every writer; `None` if
    /// the patches have none ([`Self::brep`] then reports why).
    pub topology: Option<Topology>,
}

impl ExchangeObject {
    /// Checks that every number a STEP or IGES file (named `format` in the message)
    /// holds of this object — weights, Euclidean control-point coordinates, knots — is
    /// a finite `f64` (those formats write binary64 reals).
    ///
    /// # Errors
    /// [`IoError::Invalid`] "input too large for f64: object NAME, curve/patch k, control
    /// point …, coordinate x ≈ 1eN: beyond the f64 range (±1.8e308) of FORMAT, it cannot
    /// be written", for the first such number.
    pub fn check_f64_range(&self, format: &str) -> Result<(), IoError> {
        let err = |place: String, x: &Rational| {
            IoError::Invalid(format!(
                "input too large for f64: object {:?}, {place} ≈ {}: beyond the f64 range \
                 (±1.8e308) of {format}, it cannot be written (rescale the data)",
                self.name,
                order_of(x)
            ))
        };
        let axis = ["x", "y", "z", "w"];
        let point = |what: String, h: &[Rational]| -> Result<(), IoError> {
            let w = h.first().cloned().unwrap_or(Rational::ONE);
            if !Scalar::to_f64(&w).is_finite() {
                return Err(err(format!("{what}, weight"), &w));
            }
            if w == Rational::ZERO {
                return Ok(());
            }
            for (k, c) in h.iter().skip(1).enumerate() {
                let x = c.clone() / w.clone();
                if !Scalar::to_f64(&x).is_finite() {
                    let name = axis.get(k).copied().unwrap_or("?");
                    return Err(err(format!("{what}, coordinate {name}"), &x));
                }
            }
            Ok(())
        };
        for (k, c) in self.curves.iter().enumerate() {
            if let Some(x) = c.knots().iter().find(|x| !Scalar::to_f64(*x).is_finite()) {
                return Err(err(format!("curve {k}, a knot"), x));
            }
            for (i, h) in c.control_points().enumerate() {
                point(format!("curve {k}, control point {i}"), h)?;
            }
        }
        for (k, p) in self.patches.iter().enumerate() {
            let (du, dv) = p.degree();
            for i in 0..=du {
                for j in 0..=dv {
                    if let Some(h) = p.get_control_point(i, j) {
                        point(format!("patch {k}, control point ({i}, {j})"), h)?;
                    }
                }
            }
        }
        Ok(())
    }

    /// The boundary representation of the patches ([`build_topology`]), computed once in
    /// [`exchange_object`].
    ///
    /// # Errors
    /// As [`build_topology`], when the patches have none.
    pub fn brep(&self) -> Result<std::borrow::Cow<'_, Topology>, IoError> {
        match &self.topology {
            Some(t) => Ok(std::borrow::Cow::Borrowed(t)),
            None => build_topology(&self.patches).map(std::borrow::Cow::Owned),
        }
    }

    /// The patches as NURBS surfaces on `[0, 1]²`.
    ///
    /// # Errors
    /// [`IoError::Geom`] for a patch of degree 0 in a direction.
    pub fn surfaces(&self) -> Result<Vec<NurbsSurface<Rational>>, IoError> {
        self.patches
            .iter()
            .enumerate()
            .map(|(k, p)| {
                NurbsSurface::from_bezier(p).map_err(|e| {
                    IoError::Invalid(format!(
                        "object {:?}, patch {k}: cannot be a B-spline surface: {e}",
                        self.name
                    ))
                })
            })
            .collect()
    }
}

/// Pads homogeneous points of length `s = dim + 1 ≤ 4` with zero coordinates to E3.
fn pad3(coords: &[Rational], dim: usize) -> Vec<Rational> {
    let s = dim + 1;
    let mut out = Vec::with_capacity(coords.len() / s * 4);
    for p in coords.chunks(s) {
        out.extend(p.iter().cloned());
        out.extend(std::iter::repeat_n(Rational::from(0), 3 - dim));
    }
    out
}

/// Makes all weights (every 4th coordinate) positive: unchanged if they are, negated
/// if all are negative; `Err(message)` for a zero weight or mixed signs.
fn positive_weights(coords: &mut [Rational]) -> Result<(), String> {
    let zero = Rational::from(0);
    let w: Vec<&Rational> = coords.iter().step_by(4).collect();
    if let Some(i) = w.iter().position(|x| **x == zero) {
        return Err(format!(
            "control point {i} has weight 0 (a point at infinity)"
        ));
    }
    let pos = w.iter().filter(|x| ***x > zero).count();
    if pos == w.len() {
        Ok(())
    } else if pos == 0 {
        for c in coords.iter_mut() {
            *c = -c.clone();
        }
        Ok(())
    } else {
        Err("its weights have mixed signs; STEP and IGES need positive weights".into())
    }
}

fn check_dim(dim: usize, what: &str) -> Result<(), IoError> {
    if (1..=3).contains(&dim) {
        Ok(())
    } else {
        Err(IoError::Invalid(format!(
            "{what} lies in E{dim}; STEP and IGES carry geometry in E1, E2 or E3 only"
        )))
    }
}

/// The curve in E3 with positive weights.
fn curve_e3(c: &BezierCurve<Rational>, what: &str) -> Result<BezierCurve<Rational>, IoError> {
    check_dim(c.dim(), what)?;
    if c.degree() == 0 {
        return Err(IoError::Invalid(format!(
            "{what} has degree 0 (a single point), which is not a B-spline curve"
        )));
    }
    let mut coords = pad3(c.coords(), c.dim());
    positive_weights(&mut coords).map_err(|m| IoError::Invalid(format!("{what}: {m}")))?;
    let b = crate::balance::balance_curve(&BezierCurve::from_flat(3, coords)?);
    Ok(BezierCurve::from_flat(3, unit_equal_weights(b.coords()))?)
}

/// The homogeneous coordinates divided by the common weight when every weight is the
/// same `w ≠ 1` (the same points): such a piece is written in the polynomial form,
/// whose implied weights are 1, so the sidecar must carry weight 1 too.
fn unit_equal_weights(coords: &[Rational]) -> Vec<Rational> {
    let w = coords.first().cloned().unwrap_or_else(|| Rational::from(1));
    let one = Rational::from(1);
    if w == one || w == Rational::from(0) || coords.iter().step_by(4).any(|x| *x != w) {
        return coords.to_vec();
    }
    coords.iter().map(|x| x.clone() / w.clone()).collect()
}

/// The patch in E3 with positive weights.
fn patch_e3(p: &BezierPatch<Rational>, what: &str) -> Result<BezierPatch<Rational>, IoError> {
    check_dim(p.dim(), what)?;
    let (m, n) = p.degree();
    if m == 0 || n == 0 {
        return Err(IoError::Invalid(format!(
            "{what} has bidegree ({m}, {n}); a B-spline surface needs degree ≥ 1 in both directions"
        )));
    }
    let b = crate::balance::balance_patch(&embed_e3(p, what)?);
    Ok(BezierPatch::from_flat(
        3,
        m,
        n,
        unit_equal_weights(b.coords()),
    )?)
}

/// A patch embedded in E3 (zero-padded from E1/E2) with positive weights (all-negative
/// weights negated), not balanced.
///
/// # Errors
/// [`IoError::Invalid`] beyond E3 or for weights of mixed sign or zero.
pub(crate) fn embed_e3(
    p: &BezierPatch<Rational>,
    what: &str,
) -> Result<BezierPatch<Rational>, IoError> {
    check_dim(p.dim(), what)?;
    let (m, n) = p.degree();
    let mut coords = pad3(p.coords(), p.dim());
    positive_weights(&mut coords).map_err(|m| IoError::Invalid(format!("{what}: {m}")))?;
    Ok(BezierPatch::from_flat(3, m, n, coords)?)
}

/// The Euclidean point of a homogeneous point with non-zero weight.
fn euclid(h: &[Rational]) -> Vec<Rational> {
    h[1..].iter().map(|x| x.clone() / h[0].clone()).collect()
}

/// Joins consecutive pieces of one degree whose Euclidean end and start points are
/// equal into one NURBS (piece `i` on `[i, i+1]` of its run).
fn join_curves(pieces: Vec<BezierCurve<Rational>>) -> Result<Vec<NurbsCurve<Rational>>, IoError> {
    let mut out = Vec::new();
    let mut run: Vec<BezierCurve<Rational>> = Vec::new();
    for c in pieces {
        let meets = run.last().is_some_and(|last| {
            last.degree() == c.degree()
                && euclid(last.control_point(last.degree())) == euclid(c.control_point(0))
        });
        if !meets && !run.is_empty() {
            out.push(NurbsCurve::from_bezier_pieces(&run)?);
            run.clear();
        }
        run.push(c);
    }
    if !run.is_empty() {
        out.push(NurbsCurve::from_bezier_pieces(&run)?);
    }
    Ok(out)
}

/// The patches with every face that is flipped in its shell ([`build_topology`])
/// reversed in `u` (the same surface with the opposite normal): consistent orientation
/// in every shell, outward in closed ones, in the patches themselves (IGES has no
/// `same_sense` flag; STEP's faces then all have `same_sense = .T.`); which patches were
/// reversed; and the topology of the result (rebuilt only if a patch was reversed, as
/// that changes its boundary curves). Unchanged, without topology, if the patches have
/// no boundary representation.
fn oriented(
    patches: Vec<BezierPatch<Rational>>,
) -> (Vec<BezierPatch<Rational>>, Vec<bool>, Option<Topology>) {
    let n = patches.len();
    match build_topology(&patches) {
        Ok(topo) if topo.faces.iter().any(|f| f.flipped) => {
            let mut out = patches;
            let mut reversed = vec![false; n];
            for f in &topo.faces {
                if f.flipped {
                    out[f.patch] = out[f.patch].reverse_u();
                    reversed[f.patch] = true;
                }
            }
            let topo = build_topology(&out).ok();
            (out, reversed, topo)
        }
        Ok(topo) => (patches, vec![false; n], Some(topo)),
        Err(_) => (patches, vec![false; n], None),
    }
}

/// [`exchange_object`] of each object, in order: what the STEP and IGES writers and the
/// exact sidecar write.
///
/// # Errors
/// The first object's error, as [`exchange_object`].
pub fn exchange_objects(objects: &[Object]) -> Result<Vec<ExchangeObject>, IoError> {
    objects.iter().map(exchange_object).collect()
}

/// The exchange form of an object (module docs): curves in E3 joined into NURBS,
/// patches in E3, weights positive, faces oriented consistently (outward in closed shells).
///
/// # Errors
/// [`IoError::Invalid`] for geometry beyond E3, degree 0, a zero weight or weights of
/// mixed sign (the message names the object and piece).
pub fn exchange_object(o: &Object) -> Result<ExchangeObject, IoError> {
    // pieces whose weights have mixed signs but whose weight function has no zero are
    // split exactly into pieces of one sign first (Geometry::drawable_curves/_patches)
    let located = |e: IoError| match e {
        IoError::Invalid(m) => IoError::Invalid(format!("object {:?}: {m}", o.name)),
        e => e,
    };
    let curves = o
        .geometry
        .drawable_curves()
        .map_err(located)?
        .iter()
        .enumerate()
        .map(|(k, c)| curve_e3(c, &format!("object {:?}, curve piece {k}", o.name)))
        .collect::<Result<Vec<_>, _>>()?;
    let patches = o
        .geometry
        .drawable_patches()
        .map_err(located)?
        .iter()
        .enumerate()
        .map(|(k, (_, p))| patch_e3(p, &format!("object {:?}, patch {k}", o.name)))
        .collect::<Result<Vec<_>, _>>()?;
    let (patches, reversed, topology) = oriented(patches);
    Ok(ExchangeObject {
        name: o.name.clone(),
        curves: join_curves(curves)?,
        patches,
        reversed,
        topology,
    })
}

// ---------------------------------------------------------------------------------
// Topology: vertices, shared edges, oriented shells
// ---------------------------------------------------------------------------------

/// An edge: an exact boundary curve from vertex `start` to vertex `end`.
#[derive(Debug, Clone, PartialEq)]
pub struct TopoEdge {
    /// The edge curve (E3, positive weights), oriented from `start` to `end`.
    pub curve: BezierCurve<Rational>,
    /// Index of the start vertex.
    pub start: usize,
    /// Index of the end vertex.
    pub end: usize,
}

/// A face: one patch, its boundary loop and its orientation in the shell.
#[derive(Debug, Clone, PartialEq)]
pub struct TopoFace {
    /// Index of the patch.
    pub patch: usize,
    /// The loop `v = 0, u = 1, v = 1, u = 0` (counter-clockwise about `∂ᵤx × ∂ᵥx`)
    /// without collapsed sides: `(edge, true)` if the loop runs along the edge curve.
    pub edges: Vec<(usize, bool)>,
    /// `true` if the face normal is `−∂ᵤx × ∂ᵥx` in its shell.
    pub flipped: bool,
    /// For each entry of `edges`, the side of the patch it bounds: 0 `v = 0`, 1 `u = 1`,
    /// 2 `v = 1`, 3 `u = 0` (the order of [`BezierPatch::boundary_curves`]).
    pub sides: Vec<usize>,
    /// For each entry of `edges`, [`mobius_ratio`] of the patch's side (in the loop's
    /// direction along the edge: reversed where the flag is `false`) against the edge
    /// curve: `Some(ρ)` if the side is the edge curve Möbius-reparametrized
    /// (`σ = ρs / ((1 − s) + ρs)`; `ρ = 1` on the face that defined the edge), `None`
    /// if it is the same curve in another parametrization.
    pub ratios: Vec<Option<Rational>>,
}

/// A connected set of faces.
#[derive(Debug, Clone, PartialEq)]
pub struct TopoShell {
    /// Face indices.
    pub faces: Vec<usize>,
    /// Every edge is used exactly twice and the faces are oriented consistently
    /// (and outward).
    pub closed: bool,
}

/// The boundary representation of a set of patches (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Topology {
    /// Exact Euclidean vertex positions.
    pub vertices: Vec<Vec<Rational>>,
    /// The edges.
    pub edges: Vec<TopoEdge>,
    /// One face per patch, in patch order.
    pub faces: Vec<TopoFace>,
    /// The shells.
    pub shells: Vec<TopoShell>,
}

/// `true` if all Euclidean control points are equal (the curve is one point).
pub(crate) fn collapsed(c: &BezierCurve<Rational>) -> bool {
    let first = euclid(c.control_point(0));
    c.control_points().all(|p| euclid(p) == first)
}

/// [`collapsed`] for a curve whose Euclidean end points are already known: ends that
/// differ decide it without dividing the inner control points.
fn collapsed_with_ends(c: &BezierCurve<Rational>, first: &[Rational], last: &[Rational]) -> bool {
    first == last && c.control_points().all(|p| euclid(p) == first)
}

/// `ρ` if `q` is `p` reparametrized by an end-point-preserving Möbius map:
/// `Qᵢ = λ ρⁱ Pᵢ` for some `λ ≠ 0`, `ρ > 0`; then `Q(s) = P(φ_ρ(s))` with
/// `φ_ρ(s) = ρs / ((1 − s) + ρs)` (projectively).
pub(crate) fn mobius_ratio(
    p: &BezierCurve<Rational>,
    q: &BezierCurve<Rational>,
) -> Option<Rational> {
    if p.degree() != q.degree() || p.dim() != q.dim() {
        return None;
    }
    let zero = Rational::from(0);
    if p.coords() == q.coords() {
        // Qᵢ = 1·Pᵢ: the general computation below gives ρ = 1 unless a control point
        // is all zero or there is only one
        let nonzero = p.control_points().all(|a| a.iter().any(|x| *x != zero));
        return (p.degree() >= 1 && nonzero).then(|| Rational::from(1));
    }
    // rᵢ with Qᵢ = rᵢ Pᵢ
    let mut ratios = Vec::with_capacity(p.degree() + 1);
    for (a, b) in p.control_points().zip(q.control_points()) {
        let k = a.iter().position(|x| *x != zero)?;
        let r = b[k].clone() / a[k].clone();
        if r == zero || a.iter().zip(b).any(|(x, y)| *y != r.clone() * x.clone()) {
            return None;
        }
        ratios.push(r);
    }
    if ratios.len() < 2 {
        return None;
    }
    let rho = ratios[1].clone() / ratios[0].clone();
    if rho <= zero {
        return None;
    }
    let mut expect = ratios[0].clone();
    for r in &ratios {
        if *r != expect {
            return None;
        }
        expect *= rho.clone();
    }
    Some(rho)
}

/// Whether `a` and `b` are the same edge curve (module docs), with the Möbius ratio:
/// `Some(Some(ρ))` if `b` is `a` reparametrized ([`mobius_ratio`]), `Some(None)` if
/// they are the same curve otherwise ([`BezierCurve::same_parametrization`]), `None`
/// if they differ.
fn same_curve_ratio(
    a: &BezierCurve<Rational>,
    b: &BezierCurve<Rational>,
) -> Option<Option<Rational>> {
    match mobius_ratio(a, b) {
        Some(r) => Some(Some(r)),
        None => a.same_parametrization(b).then_some(None),
    }
}

/// Signed volume `Σ a·(b×c)/6` of a coarse tessellation of the faces (flipped faces
/// reversed).
fn signed_volume(patches: &[BezierPatch<f64>], faces: &[TopoFace], which: &[usize]) -> f64 {
    const N: usize = 8;
    let ts = linspace(0.0, 1.0, N);
    let mut vol = 0.0;
    for &f in which {
        let face = &faces[f];
        let Some(p) = patches.get(face.patch) else {
            continue;
        };
        let Ok(mut ev) = PatchEvaluator3::new(p) else {
            continue;
        };
        // the points of eval_patch_f64, without its allocations
        let mut pts = Vec::with_capacity((N + 1) * (N + 1));
        for &u in &ts {
            for &v in &ts {
                pts.push(ev.point(u, v));
            }
        }
        let at = |i: usize, j: usize| pts[i * (N + 1) + j];
        for i in 0..N {
            for j in 0..N {
                for [a, b, c] in [
                    [at(i, j), at(i + 1, j), at(i + 1, j + 1)],
                    [at(i, j), at(i + 1, j + 1), at(i, j + 1)],
                ] {
                    let cr = [
                        b[1] * c[2] - b[2] * c[1],
                        b[2] * c[0] - b[0] * c[2],
                        b[0] * c[1] - b[1] * c[0],
                    ];
                    let d = (a[0] * cr[0] + a[1] * cr[1] + a[2] * cr[2]) / 6.0;
                    vol += if face.flipped { -d } else { d };
                }
            }
        }
    }
    vol
}

/// Builds the boundary representation of patches in E3 (module docs).
///
/// # Errors
/// [`IoError::Invalid`] for a patch outside E3 or with a zero weight at a corner.
pub fn build_topology(patches: &[BezierPatch<Rational>]) -> Result<Topology, IoError> {
    build_topology_with(patches, None)
}

/// [`build_topology`] with the `f64` images of the patches (`BezierPatch::to_f64`, for
/// the orientation of closed shells) when the caller has them already.
pub(crate) fn build_topology_with(
    patches: &[BezierPatch<Rational>],
    patches_f64: Option<&[BezierPatch<f64>]>,
) -> Result<Topology, IoError> {
    let mut vertices: Vec<Vec<Rational>> = Vec::new();
    let mut vertex_index: HashMap<Vec<Rational>, usize> = HashMap::new();
    let mut edges: Vec<TopoEdge> = Vec::new();
    let mut by_ends: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    let mut faces = Vec::with_capacity(patches.len());
    let zero = Rational::from(0);
    for (k, patch) in patches.iter().enumerate() {
        if patch.dim() != 3 {
            return Err(IoError::Invalid(format!(
                "patch {k} lies in E{}, topology needs E3",
                patch.dim()
            )));
        }
        if patch.coords().iter().step_by(4).any(|w| *w == zero) {
            return Err(IoError::Invalid(format!(
                "patch {k} has a control point with weight 0 (a point at infinity)"
            )));
        }
        let mut loop_edges = Vec::new();
        let mut sides = Vec::new();
        let mut ratios = Vec::new();
        // side s runs from corner s to corner s + 1 (loop order): each corner's
        // Euclidean point once
        let (m, n) = patch.degree();
        let corners = [(0, 0), (m, 0), (m, n), (0, n)].map(|(i, j)| patch.control_point(i, j));
        if corners.iter().any(|h| h[0] == zero) {
            return Err(IoError::Invalid(format!(
                "patch {k} has a corner at infinity (weight 0)"
            )));
        }
        let corner_points = corners.map(euclid);
        for (side, c) in patch.boundary_curves().into_iter().enumerate() {
            let (e0, e1) = (&corner_points[side], &corner_points[(side + 1) % 4]);
            if collapsed_with_ends(&c, e0, e1) {
                continue;
            }
            let (e0, e1) = (e0.clone(), e1.clone());
            let mut vid = |p: Vec<Rational>| {
                let n = vertices.len();
                *vertex_index.entry(p.clone()).or_insert_with(|| {
                    vertices.push(p);
                    n
                })
            };
            let a = vid(e0);
            let b = vid(e1);
            let key = (a.min(b), a.max(b));
            let mut found = None;
            if let Some(cands) = by_ends.get(&key) {
                for &e in cands {
                    let ed = &edges[e];
                    if ed.start == a && ed.end == b {
                        if let Some(r) = same_curve_ratio(&c, &ed.curve) {
                            found = Some(((e, true), r));
                        }
                    }
                    if found.is_none() && ed.start == b && ed.end == a {
                        if let Some(r) = same_curve_ratio(&c.reverse(), &ed.curve) {
                            found = Some(((e, false), r));
                        }
                    }
                    if found.is_some() {
                        break;
                    }
                }
            }
            let (use_, ratio) = match found {
                Some(u) => u,
                None => {
                    // the loop runs along the new edge's own curve: mobius_ratio(c, c),
                    // which is 1 (every weight is non-zero, checked above; a collapsed
                    // side of degree 0 never gets here)
                    let ratio = (c.degree() >= 1).then(|| Rational::from(1));
                    edges.push(TopoEdge {
                        curve: c,
                        start: a,
                        end: b,
                    });
                    by_ends.entry(key).or_default().push(edges.len() - 1);
                    ((edges.len() - 1, true), ratio)
                }
            };
            loop_edges.push(use_);
            sides.push(side);
            ratios.push(ratio);
        }
        faces.push(TopoFace {
            patch: k,
            edges: loop_edges,
            flipped: false,
            sides,
            ratios,
        });
    }
    // edge → uses (face, forward)
    let mut uses: Vec<Vec<(usize, bool)>> = vec![Vec::new(); edges.len()];
    for (f, face) in faces.iter().enumerate() {
        for &(e, fwd) in &face.edges {
            uses[e].push((f, fwd));
        }
    }
    // connected components with consistent orientation
    let mut comp = vec![usize::MAX; faces.len()];
    let mut shells = Vec::new();
    let mut converted: Option<Vec<BezierPatch<f64>>> = None;
    for start in 0..faces.len() {
        if comp[start] != usize::MAX {
            continue;
        }
        let id = shells.len();
        comp[start] = id;
        let mut flip = HashMap::from([(start, false)]);
        let mut orientable = true;
        let mut stack = vec![start];
        let mut members = vec![start];
        while let Some(f) = stack.pop() {
            let ff = flip[&f];
            for &(e, fwd) in &faces[f].edges {
                for &(g, gfwd) in &uses[e] {
                    if g == f {
                        continue;
                    }
                    // effective directions must be opposite: fwd^ff != gfwd^fg
                    let want = (fwd ^ ff) == gfwd;
                    match flip.get(&g) {
                        Some(&fg) => orientable &= fg == want,
                        None => {
                            flip.insert(g, want);
                            comp[g] = id;
                            members.push(g);
                            stack.push(g);
                        }
                    }
                }
            }
        }
        members.sort_unstable();
        let manifold_closed = members.iter().all(|&f| {
            faces[f]
                .edges
                .iter()
                .all(|&(e, _)| uses[e].len() == 2 && uses[e].iter().all(|&(g, _)| comp[g] == id))
        });
        if orientable {
            for &f in &members {
                faces[f].flipped = flip[&f];
            }
        }
        let closed = orientable && manifold_closed;
        if closed && {
            let pf: &[BezierPatch<f64>] = match patches_f64 {
                Some(pf) => pf,
                None => converted
                    .get_or_insert_with(|| patches.iter().map(BezierPatch::to_f64).collect()),
            };
            signed_volume(pf, &faces, &members) < 0.0
        } {
            for &f in &members {
                faces[f].flipped = !faces[f].flipped;
            }
        }
        shells.push(TopoShell {
            faces: members,
            closed,
        });
    }
    Ok(Topology {
        vertices,
        edges,
        faces,
        shells,
    })
}

// ---------------------------------------------------------------------------------
// The writer
// ---------------------------------------------------------------------------------

/// The application protocol named in `FILE_SCHEMA`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum StepSchema {
    /// AP214, `AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }`.
    #[default]
    Ap214,
    /// AP242, `AP242_MANAGED_MODEL_BASED_3D_ENGINEERING_MIM_LF { 1 0 10303 442 1 1 4 }`.
    Ap242,
}

/// Header fields of a STEP file.
#[derive(Debug, Clone, PartialEq)]
pub struct StepOptions {
    /// The schema.
    pub schema: StepSchema,
    /// `FILE_NAME.name`.
    pub file_name: String,
    /// `FILE_NAME.time_stamp`, ISO 8601 (`2024-05-01T12:00:00`). `None`: from
    /// `SOURCE_DATE_EPOCH` if set (reproducible builds), else the current UTC time.
    pub timestamp: Option<String>,
    /// `FILE_NAME.author`.
    pub author: String,
    /// `FILE_NAME.organization`.
    pub organization: String,
}

impl Default for StepOptions {
    fn default() -> Self {
        StepOptions {
            schema: StepSchema::Ap214,
            file_name: "rcagd.step".into(),
            timestamp: None,
            author: "rcagd".into(),
            organization: "rcagd".into(),
        }
    }
}

/// `(year, month, day, hour, minute, second)` UTC of a Unix time (proleptic Gregorian,
/// H. Hinnant's `civil_from_days`).
pub(crate) fn civil_time(secs: i64) -> (i64, u32, u32, u32, u32, u32) {
    let days = secs.div_euclid(86_400);
    let rem = secs.rem_euclid(86_400);
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let y = yoe + era * 400;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = if m <= 2 { y + 1 } else { y };
    (
        y,
        m,
        d,
        (rem / 3600) as u32,
        (rem % 3600 / 60) as u32,
        (rem % 60) as u32,
    )
}

/// Seconds since the Unix epoch: `SOURCE_DATE_EPOCH` if set and valid, else now.
pub(crate) fn export_time() -> i64 {
    if let Some(s) = std::env::var("SOURCE_DATE_EPOCH")
        .ok()
        .and_then(|v| v.trim().parse::<i64>().ok())
    {
        return s;
    }
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs() as i64)
}

fn iso_timestamp(secs: i64) -> String {
    let (y, mo, d, h, mi, s) = civil_time(secs);
    format!("{y:04}-{mo:02}-{d:02}T{h:02}:{mi:02}:{s:02}")
}

/// The entity list of a DATA section under construction.
struct Data {
    entities: Vec<String>,
    points: HashMap<String, usize>,
    /// The shared 2D context of the parameter-space curves, once written.
    param_ctx: Option<usize>,
}

impl Data {
    /// The `GEOMETRIC_REPRESENTATION_CONTEXT(2)` of the parameter lines (one per file).
    fn param_context(&mut self) -> usize {
        if let Some(id) = self.param_ctx {
            return id;
        }
        let id = self.add(
            "(GEOMETRIC_REPRESENTATION_CONTEXT(2) PARAMETRIC_REPRESENTATION_CONTEXT() \
             REPRESENTATION_CONTEXT('2D SPACE',''))"
                .into(),
        );
        self.param_ctx = Some(id);
        id
    }

    fn add(&mut self, body: String) -> usize {
        self.entities.push(body);
        self.entities.len()
    }

    /// A `CARTESIAN_POINT` (shared between equal coordinates).
    fn point(&mut self, xyz: &[String]) -> usize {
        let key = xyz.join(",");
        if let Some(&id) = self.points.get(&key) {
            return id;
        }
        let id = self.add(format!("CARTESIAN_POINT('',({key}))"));
        self.points.insert(key, id);
        id
    }

    fn euclid_point(&mut self, h: &[Rational]) -> Result<usize, IoError> {
        let xyz = euclid(h)
            .iter()
            .map(rational_real)
            .collect::<Result<Vec<_>, _>>()?;
        Ok(self.point(&xyz))
    }
}

fn refs(ids: &[usize]) -> String {
    let v: Vec<String> = ids.iter().map(|i| format!("#{i}")).collect();
    format!("({})", v.join(","))
}

fn reals(xs: &[Rational]) -> Result<String, IoError> {
    let v = xs
        .iter()
        .map(rational_real)
        .collect::<Result<Vec<_>, _>>()?;
    Ok(format!("({})", v.join(",")))
}

/// Distinct knots and their multiplicities.
fn knot_runs(knots: &[Rational]) -> (Vec<Rational>, Vec<usize>) {
    let mut vals: Vec<Rational> = Vec::new();
    let mut mults: Vec<usize> = Vec::new();
    for k in knots {
        if vals.last() == Some(k) {
            if let Some(m) = mults.last_mut() {
                *m += 1;
            }
        } else {
            vals.push(k.clone());
            mults.push(1);
        }
    }
    (vals, mults)
}

fn knot_spec(mults: &[usize], degree: usize) -> &'static str {
    let interior = mults.len().saturating_sub(2);
    if mults.iter().skip(1).take(interior).all(|&m| m == degree) {
        ".PIECEWISE_BEZIER_KNOTS."
    } else {
        ".UNSPECIFIED."
    }
}

fn mult_list(m: &[usize]) -> String {
    let v: Vec<String> = m.iter().map(usize::to_string).collect();
    format!("({})", v.join(","))
}

fn all_equal(w: &[Rational]) -> bool {
    w.iter().all(|x| *x == w[0])
}

/// A `B_SPLINE_CURVE_WITH_KNOTS` (complex rational form if the weights differ).
fn curve_entity(data: &mut Data, c: &NurbsCurve<Rational>, name: &str) -> Result<usize, IoError> {
    let mut pts = Vec::with_capacity(c.num_control_points());
    for h in c.control_points() {
        pts.push(data.euclid_point(h)?);
    }
    let p = c.degree();
    let (vals, mults) = knot_runs(c.knots());
    let knots = format!(
        "{},{},{}",
        mult_list(&mults),
        reals(&vals)?,
        knot_spec(&mults, p)
    );
    let w: Vec<Rational> = c.control_points().map(|h| h[0].clone()).collect();
    // closed_curve is informational; `.T.` makes OpenCascade convert the curve to a
    // periodic one, which changes a rational curve whose end weights differ.
    let closed = ".F.";
    let body = if all_equal(&w) {
        format!(
            "B_SPLINE_CURVE_WITH_KNOTS({},{p},{},.UNSPECIFIED.,{closed},.F.,{knots})",
            step_string(name),
            refs(&pts)
        )
    } else {
        format!(
            "(BOUNDED_CURVE() B_SPLINE_CURVE({p},{},.UNSPECIFIED.,{closed},.F.) \
             B_SPLINE_CURVE_WITH_KNOTS({knots}) CURVE() GEOMETRIC_REPRESENTATION_ITEM() \
             RATIONAL_B_SPLINE_CURVE({}) REPRESENTATION_ITEM({}))",
            refs(&pts),
            reals(&w)?,
            step_string(name)
        )
    };
    Ok(data.add(body))
}

/// A `B_SPLINE_SURFACE_WITH_KNOTS` (complex rational form if the weights differ).
fn surface_entity(
    data: &mut Data,
    s: &NurbsSurface<Rational>,
    name: &str,
) -> Result<usize, IoError> {
    let (nu, nv) = s.num_control_points();
    let (p, q) = s.degree();
    let mut rows = Vec::with_capacity(nu);
    let mut wrows = Vec::with_capacity(nu);
    let mut all_w = Vec::with_capacity(nu * nv);
    for i in 0..nu {
        let mut ids = Vec::with_capacity(nv);
        let mut ws = Vec::with_capacity(nv);
        for j in 0..nv {
            let h = s
                .control_point(i, j)
                .ok_or_else(|| IoError::Invalid(format!("control point ({i}, {j}) missing")))?;
            ids.push(data.euclid_point(h)?);
            ws.push(h[0].clone());
        }
        rows.push(refs(&ids));
        all_w.extend(ws.iter().cloned());
        wrows.push(reals(&ws)?);
    }
    let (vu, mu) = knot_runs(s.knots_u());
    let (vv, mv) = knot_runs(s.knots_v());
    let spec = if knot_spec(&mu, p) == knot_spec(&mv, q) {
        knot_spec(&mu, p)
    } else {
        ".UNSPECIFIED."
    };
    let knots = format!(
        "{},{},{},{},{spec}",
        mult_list(&mu),
        mult_list(&mv),
        reals(&vu)?,
        reals(&vv)?
    );
    let net = format!("({})", rows.join(","));
    let body = if all_equal(&all_w) {
        format!(
            "B_SPLINE_SURFACE_WITH_KNOTS({},{p},{q},{net},.UNSPECIFIED.,.F.,.F.,.F.,{knots})",
            step_string(name)
        )
    } else {
        format!(
            "(BOUNDED_SURFACE() B_SPLINE_SURFACE({p},{q},{net},.UNSPECIFIED.,.F.,.F.,.F.) \
             B_SPLINE_SURFACE_WITH_KNOTS({knots}) GEOMETRIC_REPRESENTATION_ITEM() \
             RATIONAL_B_SPLINE_SURFACE(({})) REPRESENTATION_ITEM({}) SURFACE())",
            wrows.join(","),
            step_string(name)
        )
    };
    Ok(data.add(body))
}

/// Unique product ids: the name, or `name (2)`, … for repeats.
fn unique_ids(objects: &[ExchangeObject]) -> Vec<String> {
    let mut seen: HashMap<String, usize> = HashMap::new();
    objects
        .iter()
        .map(|o| {
            let base = if o.name.is_empty() {
                "object".to_string()
            } else {
                o.name.clone()
            };
            let n = seen.entry(base.clone()).or_insert(0);
            *n += 1;
            if *n == 1 {
                base
            } else {
                format!("{base} ({n})")
            }
        })
        .collect()
}

/// The corner `(u, v)` where the parameter line of patch side `side` (the order of
/// [`BezierPatch::boundary_curves`]) is at its own parameter `s ∈ {0, 1}`.
fn side_point(side: usize, s: i64) -> [i64; 2] {
    match side {
        0 => [s, 0],
        1 => [1, s],
        2 => [1 - s, 1],
        _ => [0, 1 - s],
    }
}

/// The parameter line (pcurve) of an edge on a face: the edge curve `E` traverses the
/// patch side `side` (`fwd`: in the side's direction) as `along` (the side's boundary
/// curve, reversed if `!fwd`). With `along = E ∘ φ_ρ` ([`mobius_ratio`]; `ρ = 1` for the
/// same parametrization) the face parameter at the edge parameter `t` is the side's
/// corner-to-corner line at `φ_ρ⁻¹(t) = φ_{1/ρ}(t)`: the rational line with weights
/// `1, 1/ρ` (an exact degree-1 rational B-spline in the `(u, v)` plane).
pub(crate) fn pcurve(
    edge: &BezierCurve<Rational>,
    along: &BezierCurve<Rational>,
    side: usize,
    fwd: bool,
) -> Result<NurbsCurve<Rational>, IoError> {
    let sigma = match mobius_ratio(edge, along) {
        Some(rho) => Rational::from(1) / rho,
        None => Rational::from(1),
    };
    let (a, b) = if fwd {
        (side_point(side, 0), side_point(side, 1))
    } else {
        (side_point(side, 1), side_point(side, 0))
    };
    let h = |w: &Rational, p: [i64; 2]| {
        vec![
            w.clone(),
            w.clone() * Rational::from(p[0]),
            w.clone() * Rational::from(p[1]),
        ]
    };
    let line = BezierCurve::from_homogeneous(vec![h(&Rational::from(1), a), h(&sigma, b)])?;
    Ok(NurbsCurve::from_bezier(&line)?)
}

/// A degenerate edge for the collapsed side `side` (boundary curve `c`, one point) of a
/// face on the surface entity `surf`: an `EDGE_CURVE` from the point's vertex to itself
/// whose `SURFACE_CURVE` is the collapsed boundary curve with the side's parameter line
/// as `PCURVE`. OpenCascade reads it as a degenerated edge (`BRep_Tool::Degenerated`),
/// as its own writer's faces at a pole; without it the reader closes the loop itself,
/// straight across the parameter square where two adjacent sides collapse, and grows
/// the vertex tolerance to the gap.
fn degenerate_edge(
    data: &mut Data,
    c: &BezierCurve<Rational>,
    side: usize,
    surf: usize,
    vertices: &mut HashMap<Vec<Rational>, usize>,
) -> Result<usize, IoError> {
    let at = euclid(c.control_point(0));
    let vertex = match vertices.get(&at) {
        Some(&v) => v,
        None => {
            let xyz = at
                .iter()
                .map(rational_real)
                .collect::<Result<Vec<_>, _>>()?;
            let p = data.point(&xyz);
            let v = data.add(format!("VERTEX_POINT('',#{p})"));
            vertices.insert(at, v);
            v
        }
    };
    let c3 = curve_entity(data, &NurbsCurve::from_bezier(c)?, "")?;
    let pc = pcurve(c, c, side, true)?;
    let pc_id = curve_entity(data, &pc, "")?;
    let ctx = data.param_context();
    let rep = data.add(format!("DEFINITIONAL_REPRESENTATION('',(#{pc_id}),#{ctx})"));
    let pcurve_id = data.add(format!("PCURVE('',#{surf},#{rep})"));
    let geom = data.add(format!(
        "SURFACE_CURVE('',#{c3},(#{pcurve_id}),.PCURVE_S1.)"
    ));
    Ok(data.add(format!("EDGE_CURVE('',#{vertex},#{vertex},#{geom},.T.)")))
}

/// The representation items of one object and the representation's entity name.
fn object_items(
    data: &mut Data,
    o: &ExchangeObject,
) -> Result<(&'static str, Vec<usize>), IoError> {
    if o.patches.is_empty() {
        let mut ids = Vec::with_capacity(o.curves.len());
        for (k, c) in o.curves.iter().enumerate() {
            ids.push(curve_entity(data, c, &format!("curve {k}"))?);
        }
        let set = data.add(format!(
            "GEOMETRIC_CURVE_SET({},{})",
            step_string(&o.name),
            refs(&ids)
        ));
        return Ok((
            "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION",
            vec![set],
        ));
    }
    let topo = o.brep()?;
    let surfaces = o.surfaces()?;
    let mut vertex_ids = Vec::with_capacity(topo.vertices.len());
    for v in &topo.vertices {
        let xyz = v.iter().map(rational_real).collect::<Result<Vec<_>, _>>()?;
        let p = data.point(&xyz);
        vertex_ids.push(data.add(format!("VERTEX_POINT('',#{p})")));
    }
    let surface_ids = topo
        .faces
        .iter()
        .map(|f| surface_entity(data, &surfaces[f.patch], ""))
        .collect::<Result<Vec<_>, _>>()?;
    // the parameter lines of every edge on its faces (module docs)
    let mut pcurves: Vec<Vec<(usize, usize)>> = vec![Vec::new(); topo.edges.len()];
    for (fi, f) in topo.faces.iter().enumerate() {
        let boundary = o.patches[f.patch].boundary_curves();
        for (&(e, fwd), &side) in f.edges.iter().zip(&f.sides) {
            let c = &boundary[side];
            let along = if fwd { c.clone() } else { c.reverse() };
            let pc = pcurve(&topo.edges[e].curve, &along, side, fwd)?;
            let pc_id = curve_entity(data, &pc, "")?;
            let ctx = data.param_context();
            let rep = data.add(format!("DEFINITIONAL_REPRESENTATION('',(#{pc_id}),#{ctx})"));
            let id = data.add(format!("PCURVE('',#{},#{rep})", surface_ids[fi]));
            pcurves[e].push((fi, id));
        }
    }
    let mut edge_ids = Vec::with_capacity(topo.edges.len());
    for (e, pcs) in topo.edges.iter().zip(&pcurves) {
        let nc = NurbsCurve::from_bezier(&e.curve)?;
        let c = curve_entity(data, &nc, "")?;
        let ids: Vec<usize> = pcs.iter().map(|&(_, id)| id).collect();
        let seam = pcs.len() == 2 && pcs[0].0 == pcs[1].0;
        let geom = data.add(format!(
            "{}('',#{c},{},.PCURVE_S1.)",
            if seam { "SEAM_CURVE" } else { "SURFACE_CURVE" },
            refs(&ids)
        ));
        edge_ids.push(data.add(format!(
            "EDGE_CURVE('',#{},#{},#{geom},.T.)",
            vertex_ids[e.start], vertex_ids[e.end]
        )));
    }
    let mut face_ids = Vec::with_capacity(topo.faces.len());
    // VERTEX_POINTs by exact position (the topology's, and poles of collapsed sides)
    let mut pole_ids: HashMap<Vec<Rational>, usize> = topo
        .vertices
        .iter()
        .cloned()
        .zip(vertex_ids.iter().copied())
        .collect();
    for (fi, f) in topo.faces.iter().enumerate() {
        let surf = surface_ids[fi];
        // the loop in side order: shared edges, and a degenerate edge (a vertex of the
        // surface's pole, with its parameter line) for every collapsed side
        let boundary = o.patches[f.patch].boundary_curves();
        let mut loop_uses: Vec<(usize, bool)> = Vec::with_capacity(4);
        for (side, c) in boundary.iter().enumerate() {
            if let Some(i) = f.sides.iter().position(|&x| x == side) {
                loop_uses.push((edge_ids[f.edges[i].0], f.edges[i].1));
            } else if collapsed(c) {
                loop_uses.push((degenerate_edge(data, c, side, surf, &mut pole_ids)?, true));
            }
        }
        if f.flipped {
            loop_uses.reverse();
            for u in &mut loop_uses {
                u.1 = !u.1;
            }
        }
        let mut oe = Vec::with_capacity(loop_uses.len());
        for (e, fwd) in loop_uses {
            oe.push(data.add(format!(
                "ORIENTED_EDGE('',*,*,#{},{})",
                e,
                if fwd { ".T." } else { ".F." }
            )));
        }
        let mut bounds = Vec::new();
        if !oe.is_empty() {
            let lp = data.add(format!("EDGE_LOOP('',{})", refs(&oe)));
            bounds.push(data.add(format!("FACE_OUTER_BOUND('',#{lp},.T.)")));
        }
        face_ids.push(data.add(format!(
            "ADVANCED_FACE({},{},#{surf},{})",
            step_string(&format!("{} patch {}", o.name, f.patch)),
            refs(&bounds),
            if f.flipped { ".F." } else { ".T." }
        )));
    }
    let all_closed = topo.shells.iter().all(|s| s.closed);
    let mut shell_ids = Vec::with_capacity(topo.shells.len());
    for s in &topo.shells {
        let faces: Vec<usize> = s.faces.iter().map(|&f| face_ids[f]).collect();
        let kind = if s.closed {
            "CLOSED_SHELL"
        } else {
            "OPEN_SHELL"
        };
        shell_ids.push(data.add(format!("{kind}('',{})", refs(&faces))));
    }
    if all_closed {
        let solids = shell_ids
            .iter()
            .map(|&s| {
                data.add(format!(
                    "MANIFOLD_SOLID_BREP({},#{s})",
                    step_string(&o.name)
                ))
            })
            .collect();
        Ok(("ADVANCED_BREP_SHAPE_REPRESENTATION", solids))
    } else {
        let model = data.add(format!(
            "SHELL_BASED_SURFACE_MODEL({},{})",
            step_string(&o.name),
            refs(&shell_ids)
        ));
        Ok(("MANIFOLD_SURFACE_SHAPE_REPRESENTATION", vec![model]))
    }
}

/// STEP text of the objects with default header fields ([`StepOptions::default`]).
///
/// # Errors
/// As [`write_step_with`].
pub fn write_step(objects: &[Object]) -> Result<String, IoError> {
    write_step_with(objects, &StepOptions::default())
}

/// STEP text of the objects (module docs): one part per object.
///
/// # Errors
/// [`IoError::Invalid`] for no objects, an object without geometry, geometry beyond
/// E3, degree 0, zero or mixed-sign weights, or a coordinate beyond the `f64` range.
pub fn write_step_with(objects: &[Object], opts: &StepOptions) -> Result<String, IoError> {
    write_step_exchanged(&exchange_objects(objects)?, opts)
}

/// [`write_step_with`] of objects already in their exchange form ([`exchange_object`]):
/// a caller writing one object in several formats computes that form once.
///
/// # Errors
/// As [`write_step_with`].
pub fn write_step_exchanged(
    exch: &[ExchangeObject],
    opts: &StepOptions,
) -> Result<String, IoError> {
    if exch.is_empty() {
        return Err(IoError::Invalid("no objects to write to STEP".into()));
    }
    for o in exch {
        o.check_f64_range("STEP")?;
    }
    if let Some(o) = exch
        .iter()
        .find(|o| o.curves.is_empty() && o.patches.is_empty())
    {
        return Err(IoError::Invalid(format!(
            "object {:?} has no curves or patches to write",
            o.name
        )));
    }
    let mut data = Data {
        entities: Vec::new(),
        points: HashMap::new(),
        param_ctx: None,
    };
    let (schema, app_ctx, apd) = match opts.schema {
        StepSchema::Ap214 => (
            "AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }",
            "core data for automotive mechanical design processes",
            "'international standard','automotive_design',2000",
        ),
        StepSchema::Ap242 => (
            "AP242_MANAGED_MODEL_BASED_3D_ENGINEERING_MIM_LF { 1 0 10303 442 1 1 4 }",
            "managed model based 3d engineering",
            "'international standard','ap242_managed_model_based_3d_engineering',2014",
        ),
    };
    let ctx = data.add(format!("APPLICATION_CONTEXT('{app_ctx}')"));
    data.add(format!("APPLICATION_PROTOCOL_DEFINITION({apd},#{ctx})"));
    let prod_ctx = data.add(format!("PRODUCT_CONTEXT('',#{ctx},'mechanical')"));
    let pd_ctx = data.add(format!(
        "PRODUCT_DEFINITION_CONTEXT('part definition',#{ctx},'design')"
    ));
    let len_unit = data.add("(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.))".into());
    let angle_unit = data.add("(NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.))".into());
    let solid_unit = data.add("(NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT())".into());
    let unc = data.add(format!(
        "UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#{len_unit},\
         'distance_accuracy_value','confusion accuracy')"
    ));
    let geo_ctx = data.add(format!(
        "(GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#{unc})) \
         GLOBAL_UNIT_ASSIGNED_CONTEXT((#{len_unit},#{angle_unit},#{solid_unit})) \
         REPRESENTATION_CONTEXT('3D','3D context with units and uncertainty'))"
    ));
    let origin = data.point(&["0.".into(), "0.".into(), "0.".into()]);
    let ez = data.add("DIRECTION('',(0.,0.,1.))".into());
    let ex = data.add("DIRECTION('',(1.,0.,0.))".into());
    let axis = data.add(format!("AXIS2_PLACEMENT_3D('',#{origin},#{ez},#{ex})"));
    let ids = unique_ids(exch);
    let mut products = Vec::with_capacity(exch.len());
    for (o, id) in exch.iter().zip(&ids) {
        let product = data.add(format!(
            "PRODUCT({},{},'',(#{prod_ctx}))",
            step_string(id),
            step_string(&o.name)
        ));
        products.push(product);
        let pdf = data.add(format!("PRODUCT_DEFINITION_FORMATION('','',#{product})"));
        let pd = data.add(format!("PRODUCT_DEFINITION('design','',#{pdf},#{pd_ctx})"));
        let pds = data.add(format!("PRODUCT_DEFINITION_SHAPE('','',#{pd})"));
        let (rep_kind, mut items) = object_items(&mut data, o)?;
        items.insert(0, axis);
        let rep = data.add(format!(
            "{rep_kind}({},{},#{geo_ctx})",
            step_string(&o.name),
            refs(&items)
        ));
        data.add(format!("SHAPE_DEFINITION_REPRESENTATION(#{pds},#{rep})"));
    }
    data.add(format!(
        "PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,{})",
        refs(&products)
    ));

    let stamp = match &opts.timestamp {
        Some(t) => t.clone(),
        None => iso_timestamp(export_time()),
    };
    let version = env!("CARGO_PKG_VERSION");
    let mut out = String::with_capacity(data.entities.iter().map(|e| e.len() + 12).sum());
    out.push_str("ISO-10303-21;\nHEADER;\n");
    let _ = writeln!(
        out,
        "FILE_DESCRIPTION(({}),'2;1');",
        step_string(&format!(
            "rcagd exact rational geometry: {} object(s)",
            exch.len()
        ))
    );
    let _ = writeln!(
        out,
        "FILE_NAME({},{},({}),({}),{},{},'');",
        step_string(&opts.file_name),
        step_string(&stamp),
        step_string(&opts.author),
        step_string(&opts.organization),
        step_string(&format!("rcagd-io {version}")),
        step_string(&format!("rcagd {version}")),
    );
    let _ = writeln!(out, "FILE_SCHEMA(('{schema}'));");
    out.push_str("ENDSEC;\nDATA;\n");
    for (i, e) in data.entities.iter().enumerate() {
        let _ = writeln!(out, "#{} = {e};", i + 1);
    }
    out.push_str("ENDSEC;\nEND-ISO-10303-21;\n");
    Ok(out)
}

// ---------------------------------------------------------------------------------
// The exact sidecar
// ---------------------------------------------------------------------------------

fn hom_json(h: &[Rational]) -> Value {
    Value::Array(h.iter().map(rational_to_json).collect())
}

/// `{degree, knots, control_points}` of a curve, exact strings.
pub fn nurbs_curve_json(c: &NurbsCurve<Rational>) -> Value {
    json!({
        "degree": c.degree(),
        "knots": c.knots().iter().map(rational_to_json).collect::<Vec<_>>(),
        "control_points": c.control_points().map(hom_json).collect::<Vec<_>>(),
    })
}

/// `{degree: [p, q], knots_u, knots_v, control_points}` of a surface, exact strings;
/// `control_points[i][j]` is `Pᵢⱼ` (`i` along `u`).
pub fn nurbs_surface_json(s: &NurbsSurface<Rational>) -> Value {
    let (nu, nv) = s.num_control_points();
    let (p, q) = s.degree();
    let net: Vec<Value> = (0..nu)
        .map(|i| {
            Value::Array(
                (0..nv)
                    .filter_map(|j| s.control_point(i, j).map(hom_json))
                    .collect(),
            )
        })
        .collect();
    json!({
        "degree": [p, q],
        "knots_u": s.knots_u().iter().map(rational_to_json).collect::<Vec<_>>(),
        "knots_v": s.knots_v().iter().map(rational_to_json).collect::<Vec<_>>(),
        "control_points": net,
    })
}

/// The exact values behind a STEP or IGES file of the same objects (the files carry
/// correctly rounded `f64`s):
///
/// ```json
/// {"format": "rcagd-exact-nurbs", "version": 1,
///  "coordinates": ["w", "wx", "wy", "wz"],
///  "objects": [{"name": "…", "curves": [{"degree": 2, "knots": ["0", …],
///                "control_points": [["1", "1", "0", "0"], …]}],
///               "surfaces": [{"degree": [2, 2], "knots_u": […], "knots_v": […],
///                "control_points": [[[…], …], …]}],
///               "edges": [ curves: the STEP edge curves ]}]}
/// ```
///
/// Control points are homogeneous (weight first) exact strings, in E3, weights
/// positive; curves and surfaces in the order of the files.
///
/// # Errors
/// As [`write_step`].
pub fn exact_sidecar(objects: &[Object]) -> Result<Value, IoError> {
    exact_sidecar_exchanged(&exchange_objects(objects)?)
}

/// [`exact_sidecar`] of objects already in their exchange form ([`exchange_object`]).
///
/// # Errors
/// As [`exact_sidecar`].
pub fn exact_sidecar_exchanged(exch: &[ExchangeObject]) -> Result<Value, IoError> {
    let mut out = Vec::with_capacity(exch.len());
    for x in exch {
        let surfaces = x.surfaces()?;
        let edges = if x.patches.is_empty() {
            Vec::new()
        } else {
            x.brep()?
                .edges
                .iter()
                .map(|e| NurbsCurve::from_bezier(&e.curve).map(|c| nurbs_curve_json(&c)))
                .collect::<Result<Vec<_>, _>>()?
        };
        out.push(json!({
            "name": x.name,
            "curves": x.curves.iter().map(nurbs_curve_json).collect::<Vec<_>>(),
            "surfaces": surfaces.iter().map(nurbs_surface_json).collect::<Vec<_>>(),
            "edges": edges,
        }));
    }
    Ok(json!({
        "format": "rcagd-exact-nurbs",
        "version": 1,
        "coordinates": ["w", "wx", "wy", "wz"],
        "objects": out,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Geometry;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    #[test]
    fn reals_are_shortest_and_valid_step() {
        let cases = [
            (1.0, "1."),
            (0.5, "0.5"),
            (-0.0, "0."),
            (1e-7, "1.E-07"),
            (1.5e300, "1.5E+300"),
            (0.1, "0.1"),
            (-2.25, "-2.25"),
            (123456.0, "123456."),
            (1e16, "1.E+16"),
            (1.0 / 3.0, "0.3333333333333333"),
        ];
        for (x, want) in cases {
            assert_eq!(format_real(x).expect("finite"), want, "{x}");
            let back: f64 = want.replace('E', "e").parse().expect("parses");
            assert_eq!(back, if x == 0.0 { 0.0 } else { x });
        }
        assert!(format_real(f64::NAN).is_err());
        assert!(format_real(f64::INFINITY).is_err());
    }

    #[test]
    fn strings_are_escaped() {
        assert_eq!(step_string("a'b\\c"), "'a''b\\\\c'");
        assert_eq!(step_string("Möbius"), "'M\\X2\\00F6\\X0\\bius'");
        assert_eq!(step_string("𝄞"), "'\\X2\\D834DD1E\\X0\\'");
    }

    #[test]
    fn civil_time_matches_known_dates() {
        assert_eq!(civil_time(0), (1970, 1, 1, 0, 0, 0));
        assert_eq!(civil_time(951_782_400), (2000, 2, 29, 0, 0, 0));
        assert_eq!(civil_time(1_700_000_000), (2023, 11, 14, 22, 13, 20));
    }

    #[test]
    fn mobius_reparametrized_edges_are_shared() {
        let c = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(1, 1), q(0, 1), q(0, 1)],
            vec![q(1, 1), q(1, 1), q(1, 1), q(0, 1)],
            vec![q(2, 1), q(0, 1), q(2, 1), q(0, 1)],
        ])
        .expect("valid");
        // ρ = 3, λ = 2
        let d = BezierCurve::from_homogeneous(
            c.control_points()
                .enumerate()
                .map(|(i, p)| {
                    let f = q(2, 1) * q(3i64.pow(i as u32), 1);
                    p.iter().map(|x| x.clone() * f.clone()).collect()
                })
                .collect(),
        )
        .expect("valid");
        assert!(mobius_ratio(&c, &d).is_some());
        assert!(!c.same_parametrization(&d));
        assert!(mobius_ratio(&c, &d.reverse()).is_none());
        assert!(mobius_ratio(&c.reverse(), &d.reverse()).is_some());
    }

    /// The side curve of face `f`'s `k`-th loop entry, in the loop's direction along
    /// its edge (by the exact de Casteljau boundary of the geometry crate).
    fn loop_side(p: &BezierPatch<Rational>, f: &TopoFace, k: usize) -> BezierCurve<Rational> {
        let c = p.boundary_curves()[f.sides[k]].clone();
        if f.edges[k].1 {
            c
        } else {
            c.reverse()
        }
    }

    #[test]
    fn topology_records_the_mobius_ratio_of_every_side() {
        let c = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(1, 1), q(0, 1), q(0, 1)],
            vec![q(1, 1), q(1, 1), q(1, 1), q(0, 1)],
            vec![q(2, 1), q(0, 1), q(2, 1), q(0, 1)],
        ])
        .expect("valid");
        // the same arc with ρ = 3, λ = 2, and both arcs moved along z
        let scaled = |c: &BezierCurve<Rational>, rho: i64, dz: i64| {
            BezierCurve::from_homogeneous(
                c.control_points()
                    .enumerate()
                    .map(|(i, p)| {
                        let f = q(2, 1) * q(rho.pow(i as u32), 1);
                        let mut h: Vec<Rational> =
                            p.iter().map(|x| x.clone() * f.clone()).collect();
                        h[3] = h[3].clone() + h[0].clone() * q(dz, 1);
                        h
                    })
                    .collect(),
            )
            .expect("valid")
        };
        let a = BezierPatch::from_curves_ruled(&c, &scaled(&c, 1, 1)).expect("ruled");
        let b =
            BezierPatch::from_curves_ruled(&scaled(&c, 3, 0), &scaled(&c, 1, -1)).expect("ruled");
        let patches = [a, b];
        let topo = build_topology(&patches).expect("topology");
        let mut uses = vec![0; topo.edges.len()];
        for f in &topo.faces {
            assert_eq!(f.ratios.len(), f.edges.len());
            for k in 0..f.edges.len() {
                let (e, _) = f.edges[k];
                uses[e] += 1;
                let side = loop_side(&patches[f.patch], f, k);
                assert_eq!(f.ratios[k], mobius_ratio(&side, &topo.edges[e].curve));
            }
        }
        // one edge shared, reached through ρ = 3 (or 1/3 in the other direction)
        assert_eq!(uses.iter().filter(|&&n| n == 2).count(), 1);
        let shared: Vec<&Option<Rational>> = topo
            .faces
            .iter()
            .flat_map(|f| f.edges.iter().zip(&f.ratios))
            .filter(|((e, _), _)| uses[*e] == 2)
            .map(|(_, r)| r)
            .collect();
        assert_eq!(shared.len(), 2);
        assert!(shared.contains(&&Some(q(1, 1))));
        assert!(shared.contains(&&Some(q(3, 1))) || shared.contains(&&Some(q(1, 3))));
    }

    #[test]
    fn mixed_weights_are_rejected_and_negative_flipped() {
        let c = BezierCurve::from_homogeneous(vec![
            vec![q(-1, 1), q(0, 1), q(0, 1)],
            vec![q(-2, 1), q(-2, 1), q(0, 1)],
        ])
        .expect("valid");
        let o = Object::new(
            "n",
            "t",
            Value::Null,
            Geometry::Curve(c.clone()),
            Vec::new(),
        );
        let x = exchange_object(&o).expect("negated");
        assert_eq!(
            x.curves[0].control_point(1),
            Some(&[q(2, 1), q(2, 1), q(0, 1), q(0, 1)][..])
        );
        let bad = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(0, 1), q(0, 1)],
            vec![q(-2, 1), q(-2, 1), q(0, 1)],
        ])
        .expect("valid");
        let o = Object::new("m", "t", Value::Null, Geometry::Curve(bad), Vec::new());
        // w(t) = 1 − 3t vanishes at t = 1/3: a pole, no split helps
        let e = exchange_object(&o).expect_err("pole");
        assert!(e.to_string().contains("point at infinity"), "{e}");
        // weights 1, −1, 2 have mixed signs but w(t) = 5t² − 4t + 1 > 0: split exactly into
        // pieces with positive weights, joined into one B-spline
        let mixed = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(0, 1)],
            vec![q(-1, 1), q(-1, 1)],
            vec![q(2, 1), q(4, 1)],
        ])
        .expect("valid");
        let o = Object::new("s", "t", Value::Null, Geometry::Curve(mixed), Vec::new());
        let x = exchange_object(&o).expect("split into positive pieces");
        assert!(x.curves[0].control_points().all(|h| h[0] > q(0, 1)));
        assert!(x.curves[0].num_control_points() > 3);
    }
}
