//! Canal and pipe surfaces ready for exchange: every exact construction this module has,
//! in every frame, on the whole parameter interval or on pieces of it, and the one that
//! exports smallest (see `docs/math/pipes.md#choice`).
//!
//! STEP and IGES carry rational B-splines with positive weights. An exact parametrization
//! `x(t, u)` of a canal surface has the weight `X₀(t, u)`; where it vanishes on the
//! parameter domain (a base point or a pole of the stereographic frame, D. Gruber,
//! "Rationale Parametrisierungen von Kugelhüllflächen", 2008, §2.1 "rotate coordinates if
//! necessary") no subdivision gives pieces with positive weights. Which constructions have
//! such a zero depends on the frame, on the construction and on the interval, so the
//! builder here treats a vanishing weight as a reason to choose differently, never as a
//! failure:
//!
//! * **constructions**: Peternell–Pottmann (Gruber (2.10)–(2.17)) and Krasauskas' reduced
//!   pencil (Gruber §2.4, (2.36)), for every choice of Gaussian factors of `D` (Gruber
//!   (2.35)) and, where the caller knows one (the parametric speed of a PH spine, the two
//!   tangent components of a planar spine), for that split too;
//! * **frames**: the six coordinate axes as the pole of the stereographic projection, and
//!   up to [`TILTED_FRAMES`] rational unit directions `e` for which the pole polynomial
//!   `P₄ + e·Pₘ` has no real root on the interval ([`super::frame`]);
//! * **splits of the interval**: if no candidate exports on `[a, b]`, the interval is
//!   bisected (at most [`MAX_INTERVAL_SPLITS`] times) and each half is built on its own.
//!
//! A candidate *exports* if its Bézier patches over the interval
//! ([`CanalSurface::domain_patches`]) split into pieces whose Bernstein weights are all
//! positive within [`EXPORT_SPLITS`] bisections (the convex-hull property then proves that
//! the weight has no zero: no pole, no base point). Among the candidates that export the
//! one with the fewest control points after that split wins; ties go to the lower bidegree,
//! then to the earlier candidate (coordinate axes before tilted frames, Krasauskas before
//! Peternell–Pottmann, general splits before the caller's split). For a pipe around a
//! polynomial spine with a proven lower bound of the degree of its unit normal fields
//! (docs/math/pipes.md, "The degree of a unit normal field"), the builds of a method that
//! can at best tie with a candidate already built are skipped; the choice stays the same.

use super::envelope::{
    build_krasauskas, canal_surface_memo, CanalBuild, CanalOptions, CanalSurface,
};
use super::envelope::{AxisChoice, Construction, Method, Orientation, WeightPatchKey};
use super::frame::{
    coordinate_axis, householder, oriented, pole_free_directions, transform_spine, EXPORT_SPLITS,
};
use super::krasauskas::FactorMemo;
use super::normal_degree::{candidate_size_bound, unit_normal_degree_bound};
use super::regularity::check_pipe_regularity;
use super::self_intersection::{check_chain_embedded, check_pipe_embedded};
use super::{CanalError, CanalSpine};
use crate::error::format_scalar;
use crate::ph::approximation::{cross_dot, joint_tangents};
use crate::ph::PhCurve;
use crate::Certified;
use rayon::prelude::*;
use rcagd_algebra::roots::count_real_roots_in;
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};
use rcagd_geom::weight_sign::{split_patches_adaptive, SignRule};
use rcagd_geom::{BezierCurve, BezierPatch};

/// The most tilted (non-coordinate) stereographic frames tried per interval.
pub const TILTED_FRAMES: usize = 2;

/// The most bisections of the parameter interval (at most `2^3 = 8` pieces).
pub const MAX_INTERVAL_SPLITS: usize = 3;

/// The stereographic frame of a candidate.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Frame {
    /// A coordinate axis (and sign) is the pole axis.
    Axis(AxisChoice),
    /// The rational unit direction `e` is the pole axis (the family is reflected by the
    /// Householder map `H` with `He = e₃`, built there, and mapped back).
    Direction([Rational; 3]),
}

impl std::fmt::Display for Frame {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Frame::Axis(a) => write!(
                f,
                "pole {}{}",
                if a.positive { "+" } else { "−" },
                ["x", "y", "z"].get(a.axis).copied().unwrap_or("?")
            ),
            Frame::Direction(e) => write!(
                f,
                "pole ({}, {}, {})",
                format_scalar(&e[0]),
                format_scalar(&e[1]),
                format_scalar(&e[2])
            ),
        }
    }
}

/// One exact piece of an [`ExportableCanal`]: the surface over a parameter interval and its
/// Bézier patches with positive weights.
#[derive(Debug, Clone, PartialEq)]
pub struct ExportPiece {
    pub(super) interval: (Rational, Rational),
    pub(super) surface: CanalSurface<Rational>,
    pub(super) frame: Frame,
    pub(super) patches: Vec<BezierPatch<Rational>>,
    /// `true` when the surface was reparametrized in `u` by a Möbius map that varies
    /// linearly with `t` to close the seam of a closed pipe ([`super::seam`]): its
    /// `t`-degree is that of the construction plus 2.
    pub(super) seam_blend: bool,
}

impl ExportPiece {
    /// The parameter interval `[a, b]` of the spine covered by this piece.
    pub fn interval(&self) -> (&Rational, &Rational) {
        (&self.interval.0, &self.interval.1)
    }

    /// The exact surface (on all of `R`; its domain is [`Self::interval`]).
    pub fn surface(&self) -> &CanalSurface<Rational> {
        &self.surface
    }

    /// The stereographic frame used.
    pub fn frame(&self) -> &Frame {
        &self.frame
    }

    /// The Bézier patches over the interval, every Bernstein weight `> 0`.
    pub fn patches(&self) -> &[BezierPatch<Rational>] {
        &self.patches
    }

    /// The number of control points of the patches.
    pub fn control_points(&self) -> usize {
        control_points(&self.patches)
    }
}

/// An exact canal or pipe surface over a parameter interval as pieces that export (module
/// docs), with the number of candidates tried.
#[derive(Debug, Clone, PartialEq)]
pub struct ExportableCanal {
    pub(super) pieces: Vec<ExportPiece>,
    tried: usize,
    exporting: usize,
    regularity: Vec<Certificate>,
}

impl ExportableCanal {
    /// The pieces, in parameter order.
    pub fn pieces(&self) -> &[ExportPiece] {
        &self.pieces
    }

    /// All patches (every Bernstein weight `> 0`), in parameter order.
    pub fn patches(&self) -> Vec<BezierPatch<Rational>> {
        self.pieces
            .iter()
            .flat_map(|p| p.patches.iter().cloned())
            .collect()
    }

    /// The total number of control points.
    pub fn control_points(&self) -> usize {
        self.pieces.iter().map(ExportPiece::control_points).sum()
    }

    /// How many candidate constructions were built, and how many of them exported.
    pub fn candidates(&self) -> (usize, usize) {
        (self.tried, self.exporting)
    }

    /// A one-line description of the choice: per piece the interval, construction, frame
    /// and bidegree.
    pub fn summary(&self) -> String {
        let parts: Vec<String> = self
            .pieces
            .iter()
            .map(|p| {
                let (dt, du) = p.surface.degree();
                format!(
                    "t ∈ [{}, {}]: {}, {}, bidegree ({dt}, {du}), {} patches",
                    format_scalar(&p.interval.0),
                    format_scalar(&p.interval.1),
                    construction_name(p.surface.construction()),
                    p.frame,
                    p.patches.len()
                )
            })
            .collect();
        format!(
            "{}; chosen among {} exact candidates ({} export)",
            parts.join("; "),
            self.tried,
            self.exporting
        )
    }
}

fn construction_name(c: Construction) -> &'static str {
    match c {
        Construction::PeternellPottmann => "Peternell–Pottmann",
        Construction::Krasauskas { .. } => "Krasauskas pencil",
    }
}

fn control_points_f64(patches: &[BezierPatch<f64>]) -> usize {
    patches
        .iter()
        .map(|p| (p.degree().0 + 1) * (p.degree().1 + 1))
        .sum()
}

fn control_points(patches: &[BezierPatch<Rational>]) -> usize {
    patches
        .iter()
        .map(|p| (p.degree().0 + 1) * (p.degree().1 + 1))
        .sum()
}

/// `every Bernstein weight > 0` of a set of patches, decided exactly.
pub fn positive_weight_certificate(patches: &[BezierPatch<Rational>]) -> Certificate {
    let zero = Rational::ZERO;
    let bad = patches
        .iter()
        .filter(|p| p.coords().iter().step_by(p.dim() + 1).any(|w| *w <= zero))
        .count();
    let n = patches.len();
    Certificate::decide(
        format!("every Bernstein weight of the {n} patches is > 0 (the weight has no zero: no pole, no base point)"),
        bad == 0,
        true,
        || format!("{bad} patches have a weight ≤ 0"),
    )
}

/// The bidegree of a canal surface against the bound of its construction, with the
/// Krasauskas bound (Gruber, "Rationale Parametrisierungen von Kugelhüllflächen", Satz 2
/// (2.37)) for comparison: Peternell–Pottmann gives `deg_t ≤ 2·deg P + k`, the Krasauskas
/// pencil of degree `n` gives `deg_t ≤ 2n + k` (`k` the degree of the family, `P` its
/// derivative numerators), and `deg_u ≤ 2` (the characteristic circles are conics).
pub fn degree_certificate(s: &CanalSurface<Rational>) -> Certificate {
    degree_certificate_plus(s, 0)
}

/// [`degree_certificate`] for a surface reparametrized in `u` by a Möbius map whose
/// coefficients are polynomials of degree `extra / 2` in `t` (the seam of a closed pipe,
/// [`super::seam`]): the bound in `t` grows by `extra`.
pub(super) fn degree_certificate_plus(s: &CanalSurface<Rational>, extra: usize) -> Certificate {
    let (dt, du) = s.degree();
    let k = s.spine().degree();
    let dp = s
        .spine()
        .derivative_numerators()
        .map(|p| p.iter().filter_map(Poly::degree).max().unwrap_or(0))
        .unwrap_or(0);
    let kras = super::krasauskas_bound(s.spine())
        .map(|b| {
            format!(
                "; Krasauskas bound (Gruber 2008, Satz 2 (2.37)) for this family: ({}, {}), an overestimate for polynomial data (docs/math/pipes.md#degree)",
                b.bidegree.0, b.bidegree.1
            )
        })
        .unwrap_or_default();
    let (bound, method) = match s.construction() {
        Construction::PeternellPottmann => (
            2 * dp + k,
            "; construction: Peternell–Pottmann (Gruber 2008, (2.10)–(2.17))".to_string(),
        ),
        Construction::Krasauskas {
            initial_degree,
            reduced_degree,
            steps,
        } => (
            2 * reduced_degree + k,
            format!("; construction: Krasauskas pencil, degree {initial_degree} reduced to {reduced_degree} in {steps} steps (Gruber 2008, (2.36))"),
        ),
    };
    let (bound, seam) = if extra > 0 {
        (
            bound + extra,
            format!(
                " (+{extra} in t: the seam's Möbius blend in u, docs/math/pipes.md#closed-pipes)"
            ),
        )
    } else {
        (bound, String::new())
    };
    Certificate::decide(
        format!("bidegree (deg_t, deg_u) = ({dt}, {du}) ≤ ({bound}, 2) of the construction{seam}{kras}{method}"),
        du <= 2 && dt <= bound,
        true,
        || format!("({dt}, {du})"),
    )
}

impl Certified for ExportableCanal {
    /// Per piece (prefixed by its interval when there are several): the canal identities
    /// of [`CanalSurface`], the bidegree against its construction's bound, and the
    /// positivity of every exported weight; for pipes the regularity `r·κ < 1`
    /// ([`super::regularity`]).
    fn certify(&self) -> Vec<Certificate> {
        let many = self.pieces.len() > 1;
        let mut out = Vec::new();
        for p in &self.pieces {
            let prefix = if many {
                format!(
                    "t ∈ [{}, {}]: ",
                    format_scalar(&p.interval.0),
                    format_scalar(&p.interval.1)
                )
            } else {
                String::new()
            };
            let mut certs = p.surface.certify();
            certs.push(degree_certificate_plus(
                &p.surface,
                if p.seam_blend { 2 } else { 0 },
            ));
            certs.push(positive_weight_certificate(&p.patches));
            out.extend(certs.into_iter().map(|mut c| {
                c.property = format!("{prefix}{}", c.property);
                c
            }));
        }
        out.extend(self.regularity.iter().cloned());
        out
    }
}

/// The patch with all homogeneous coordinates negated when its corner weight is negative
/// (the same projective points; a weight without zero on the patch has one sign).
fn with_positive_corner<F: Scalar>(p: BezierPatch<F>) -> BezierPatch<F> {
    if p.coords().first().is_some_and(|w| *w < F::zero()) {
        let (du, dv) = p.degree();
        let coords: Vec<F> = p.coords().iter().map(|x| -x.clone()).collect();
        BezierPatch::from_flat(p.dim(), du, dv, coords).unwrap_or(p)
    } else {
        p
    }
}

/// The patches of a candidate over its domain split into pieces with positive weights
/// (after the sign of each patch is normalized), or `None` if that needs more than
/// [`EXPORT_SPLITS`] bisections (or the weight vanishes).
fn exported_patches<F: Scalar>(s: &CanalSurface<F>) -> Option<Vec<BezierPatch<F>>> {
    let patches: Vec<BezierPatch<F>> = s
        .domain_patches()
        .ok()?
        .into_iter()
        .map(with_positive_corner)
        .collect();
    let split = split_patches_adaptive(patches, SignRule::Positive, EXPORT_SPLITS).ok()?;
    if split.failed > 0 {
        return None;
    }
    if !F::EXACT {
        // the estimate must not rest on weights that are zero up to rounding
        let ws: Vec<f64> = split
            .pieces
            .iter()
            .flat_map(|p| p.coords().iter().step_by(p.dim() + 1).map(Scalar::to_f64))
            .collect();
        let hi = ws.iter().copied().fold(0.0, f64::max);
        if ws.iter().any(|w| *w <= 1e-12 * hi) {
            return None;
        }
    }
    Some(split.pieces)
}

/// The number of control points of [`exported_patches`] of `s` in `f64`
/// (`exported_patches(&s.map_scalar(Scalar::to_f64))`), from the weights alone
/// ([`CanalSurface::domain_weight_patches_f64`]: the split into pieces with positive
/// weights and the test against weights within rounding of zero look at the weights only,
/// and a piece keeps the bidegree of its patch), or `None` where that gives `None`.
fn exported_size_f64(s: &CanalSurface<Rational>) -> Option<usize> {
    let patches: Vec<BezierPatch<f64>> = s
        .domain_weight_patches_f64()
        .ok()?
        .into_iter()
        .map(with_positive_corner)
        .collect();
    let split = split_patches_adaptive(patches, SignRule::Positive, EXPORT_SPLITS).ok()?;
    if split.failed > 0 {
        return None;
    }
    let ws: Vec<f64> = split
        .pieces
        .iter()
        .flat_map(|p| p.coords().iter().step_by(p.dim() + 1).copied())
        .collect();
    let hi = ws.iter().copied().fold(0.0, f64::max);
    if ws.iter().any(|w| *w <= 1e-12 * hi) {
        return None;
    }
    Some(control_points_f64(&split.pieces))
}

/// What the candidates on one interval gave.
#[derive(Default)]
struct IntervalResult {
    best: Option<ExportPiece>,
    tried: usize,
    exporting: usize,
    /// The first error of a construction (reported if nothing builds at all).
    error: Option<CanalError>,
    /// A field `Q(√d)` a build needed.
    radicand: Option<Rational>,
}

/// The number of patches [`CanalSurface::domain_patches`] gives for a construction by
/// `method` without reparametrization (two charts × the `u` ranges): every export of such a
/// candidate has at least that many pieces.
fn least_patches(method: Method) -> usize {
    match method {
        Method::Krasauskas => 4,
        _ => 2,
    }
}

/// For a pipe of constant radius `r ≠ 0` around a polynomial spine of degree `k ≥ 1` (the
/// oriented family `so`, without reparametrization: `global`), `(δ, k)` with `δ > 0` a lower
/// bound of the degree of every unit normal field of the spine
/// ([`unit_normal_degree_bound`]); then every candidate by `method` has a size key
/// `≥ candidate_size_bound(δ, k, least_patches(method))` (docs/math/pipes.md, "The degree
/// of a unit normal field"). `None` otherwise.
fn pipe_size_floor(so: &CanalSpine<Rational>, global: bool) -> Option<(usize, usize)> {
    let constant = |p: &Poly<Rational>| p.degree() == Some(0);
    if !global || !constant(so.weight()) || !constant(so.radius_poly()) {
        return None;
    }
    let m = so.center_polys();
    let k = m.iter().filter_map(Poly::degree).max()?;
    if k == 0 {
        return None;
    }
    let h: [Poly<Rational>; 3] = core::array::from_fn(|i| m[i].derivative());
    let delta = unit_normal_degree_bound(&h);
    (delta > 0).then_some((delta, k))
}

/// Every candidate on `[a, b]` (module docs); keeps the smallest export.
///
/// With `prune`, a method is no longer built in the frames that follow once a candidate
/// has a size key (control points, `deg_t + deg_u`) at most the proven least key of every
/// candidate of that method ([`pipe_size_floor`]): a skipped candidate could only tie with
/// it and come later, and ties keep the earlier candidate. The choice is the one of the
/// search without pruning; if the winner could depend on a skipped candidate (the winner
/// was built after the first skip, or its key exceeds a skipped method's least key, or
/// nothing exported exactly) the interval is searched again without pruning. Only the
/// counts of candidates tried and exporting are smaller.
fn candidates_on(
    spine: &CanalSpine<Rational>,
    split: Option<&[Poly<Rational>; 2]>,
    options: &CanalOptions,
    (a, b): (&Rational, &Rational),
    memo: &FactorMemo,
    prune: bool,
) -> Result<IntervalResult, CanalError> {
    let so = oriented(spine, options.orientation);
    // the reality of the envelope on the interval is a property of the data, not of a
    // candidate: report it as it is
    memo.check_real_envelope(&so, Some((a, b)))?;
    let mut res = IntervalResult::default();
    let methods: Vec<Method> = match options.method {
        Method::Lowest => vec![Method::Krasauskas, Method::PeternellPottmann],
        m => vec![m],
    };
    let global = memo.check_real_envelope(&so, None).is_ok();
    let floor = if prune {
        pipe_size_floor(&so, global)
    } else {
        None
    };
    let bound = |method: Method| {
        floor.map(|(delta, k)| candidate_size_bound(delta, k, least_patches(method)))
    };
    let frames = frames_on(&so, (a, b), global)?;
    let search = Search {
        spine,
        split,
        options,
        methods: &methods,
        global,
        domain: (a, b),
        mid: (a.clone() + b.clone()) / Rational::from(2),
        memo,
    };
    type Built = ((usize, usize), usize, CanalSurface<Rational>, Frame);
    let mut built_ok: Vec<Built> = Vec::new();
    // the estimates computed so far, by what they depend on (none for the memo without
    // memory, the tests' reference: it estimates every candidate)
    let mut estimates: Vec<(WeightPatchKey<Rational>, Option<usize>)> = Vec::new();
    let mut order = 0usize;
    // the candidates of the last `+` coordinate frame: for a pipe those of the `−` frame of
    // the same axis follow from them (`CanalSurface::mirrored`)
    let mut last_plus: Option<(usize, Candidates)> = None;
    // the least size key so far; the build order at the first skip and the least of the
    // skipped methods' least keys
    let mut best_key: Option<(usize, usize)> = None;
    let mut first_skip: Option<usize> = None;
    let mut skip_floor: Option<(usize, usize)> = None;
    for frame in frames {
        let mirror = match (&frame, last_plus.take()) {
            (Frame::Axis(ax), Some((j, list))) if !ax.positive && ax.axis == j => {
                mirrored_candidates(&list)
            }
            _ => None,
        };
        let built = match mirror {
            Some(built) => built,
            None => {
                let skip: Vec<Method> = methods
                    .iter()
                    .copied()
                    .filter(|&m| matches!((best_key, bound(m)), (Some(k), Some(f)) if k <= f))
                    .collect();
                for &m in &skip {
                    first_skip.get_or_insert(order);
                    if let Some(f) = bound(m) {
                        skip_floor = Some(skip_floor.map_or(f, |g: (usize, usize)| g.min(f)));
                    }
                }
                let built = search.frame_candidates(&frame, &mut res, &skip);
                if let (Frame::Axis(ax), true) = (&frame, memo.derives()) {
                    if ax.positive {
                        last_plus = Some((ax.axis, built.clone()));
                    }
                }
                built
            }
        };
        let h = match &frame {
            Frame::Axis(_) => None,
            Frame::Direction(e) => Some(householder(e)),
        };
        for s in built {
            let s = match s {
                Ok(s) => s,
                Err(e) => {
                    res.error.get_or_insert(e);
                    continue;
                }
            };
            let s = match &h {
                None => s,
                Some(h) => match s.transformed(h, &so) {
                    Ok(s) => s,
                    Err(e) => {
                        res.error.get_or_insert(e);
                        continue;
                    }
                },
            };
            res.tried += 1;
            if built_ok
                .iter()
                .any(|(_, _, old, _)| old.homogeneous() == s.homogeneous())
            {
                continue;
            }
            // the size after the positive-weight split, estimated in f64 (exact below), once
            // per weight-patch key (the estimate is a function of the key)
            let key = memo.derives().then(|| s.weight_patch_key());
            let known = key
                .as_ref()
                .and_then(|k| estimates.iter().find(|(old, _)| old == k))
                .map(|(_, est)| *est);
            let est = match known {
                Some(est) => est,
                None => {
                    let est = exported_size_f64(&s);
                    if let Some(k) = key {
                        estimates.push((k, est));
                    }
                    est
                }
            };
            let Some(est) = est else {
                continue;
            };
            let (dt, du) = s.degree();
            let key = (est, dt + du);
            best_key = Some(best_key.map_or(key, |k| k.min(key)));
            built_ok.push((key, order, s, frame.clone()));
            order += 1;
        }
    }
    res.exporting = built_ok.len();
    built_ok.sort_by_key(|x| (x.0, x.1));
    // the best estimate that exports exactly wins (the exact split of a candidate whose f64
    // estimate succeeded fails only for weights within rounding of zero)
    for (key, order, s, frame) in built_ok {
        if let Some(patches) = exported_patches(&s) {
            if let Some(first) = first_skip {
                // a skipped candidate sorts after this one only if it was skipped after this
                // one was built and its least key is at least this key
                if order >= first || skip_floor.is_some_and(|f| key > f) {
                    return candidates_on(spine, split, options, (a, b), memo, false);
                }
            }
            res.best = Some(ExportPiece {
                interval: (a.clone(), b.clone()),
                surface: s,
                frame,
                patches,
                seam_blend: false,
            });
            break;
        }
    }
    if res.best.is_none() && first_skip.is_some() {
        return candidates_on(spine, split, options, (a, b), memo, false);
    }
    Ok(res)
}

/// The frames tried on `[a, b]` for the oriented family `so`: the six coordinate axes, then
/// up to [`TILTED_FRAMES`] tilted directions — a family without reparametrization
/// (`global`) and with `W ≠ 0` on `[a, b]` may be built in a tilted frame (the built
/// surface is mapped back by an orthogonal map).
fn frames_on(
    so: &CanalSpine<Rational>,
    (a, b): (&Rational, &Rational),
    global: bool,
) -> Result<Vec<Frame>, CanalError> {
    let tilted = if global && count_real_roots_in(so.weight(), a, b)? == 0 {
        pole_free_directions(so, a, b, TILTED_FRAMES + 6)?
            .into_iter()
            .filter(|e| coordinate_axis(e).is_none())
            .take(TILTED_FRAMES)
            .collect()
    } else {
        Vec::new()
    };
    let mut frames: Vec<Frame> = AxisChoice::all().into_iter().map(Frame::Axis).collect();
    frames.extend(tilted.into_iter().map(Frame::Direction));
    Ok(frames)
}

/// The candidates of one frame: the built surfaces and the failed builds, in order.
type Candidates = Vec<Result<CanalSurface<Rational>, CanalError>>;

/// The data of the candidate search on one interval.
struct Search<'a> {
    spine: &'a CanalSpine<Rational>,
    split: Option<&'a [Poly<Rational>; 2]>,
    options: &'a CanalOptions,
    methods: &'a [Method],
    /// Whether the family has a real envelope on all of `R` (the caller's split is tried).
    global: bool,
    domain: (&'a Rational, &'a Rational),
    /// The middle of the domain (where the Krasauskas pencil is balanced).
    mid: Rational,
    memo: &'a FactorMemo,
}

impl Search<'_> {
    /// The candidates of one frame, in the frame's coordinates (a tilted frame's are mapped
    /// back by the caller): per method the general builder's and the caller's split's.
    /// The methods in `skip` are not built.
    fn frame_candidates(
        &self,
        frame: &Frame,
        res: &mut IntervalResult,
        skip: &[Method],
    ) -> Candidates {
        let (a, b) = self.domain;
        let fam = match frame {
            Frame::Axis(_) => self.spine.clone(),
            Frame::Direction(e) => transform_spine(self.spine, &householder(e)),
        };
        let axis = match frame {
            Frame::Axis(ax) => *ax,
            Frame::Direction(_) => AxisChoice {
                axis: 2,
                positive: true,
            },
        };
        let mut built: Candidates = Vec::new();
        let fo = oriented(&fam, self.options.orientation);
        for &method in self.methods.iter().filter(|m| !skip.contains(m)) {
            let opts = CanalOptions {
                orientation: self.options.orientation,
                choice: self.options.choice,
                axis: Some(axis),
                domain: Some((a.clone(), b.clone())),
                method,
            };
            let general = match canal_surface_memo(&fam, &opts, self.memo) {
                Ok(CanalBuild::Rational(s)) => Some(Ok(s)),
                Ok(CanalBuild::Extension { radicand, .. }) => {
                    res.radicand.get_or_insert(radicand);
                    None
                }
                Err(e) => Some(Err(e)),
            };
            // the caller's split, unless the general builder used it already
            let same = |s: &CanalSurface<Rational>| {
                self.split.is_some_and(|g| {
                    let (g1, g2) = s.split();
                    let sq = |p: &Poly<Rational>| p * p;
                    (sq(g1) == sq(&g[0]) && sq(g2) == sq(&g[1]))
                        || (sq(g1) == sq(&g[1]) && sq(g2) == sq(&g[0]))
                })
            };
            let used = matches!(&general, Some(Ok(s)) if same(s));
            built.extend(general);
            if let (Some(g), true, false) = (self.split, self.global, used) {
                built.push(
                    with_split(&fo, g, axis, method, &self.mid, self.memo)
                        .map(|s| s.on_domain(a, b)),
                );
            }
        }
        built
    }
}

/// The candidates of the frame `(j, −σ)` from those of `(j, σ)` (same methods and splits,
/// in the same order), for a pipe ([`CanalSurface::mirrored`]: the construction in the
/// opposite frame gives the envelope of the opposite normal); `None` if one of them cannot
/// be derived. A construction that failed in `(j, σ)` fails in `(j, −σ)` too (every step
/// is the same up to the signs of `mirrored`), and an extension field it needed is needed
/// there too (already recorded).
fn mirrored_candidates(list: &[Result<CanalSurface<Rational>, CanalError>]) -> Option<Candidates> {
    list.iter()
        .map(|s| match s {
            Ok(s) => s.mirrored(),
            Err(e) => Some(Err(e.clone())),
        })
        .collect()
}

/// The surface of the oriented family `fo` from a known split, in the frame `axis`.
fn with_split(
    fo: &CanalSpine<Rational>,
    g: &[Poly<Rational>; 2],
    axis: AxisChoice,
    method: Method,
    mid: &Rational,
    memo: &FactorMemo,
) -> Result<CanalSurface<Rational>, CanalError> {
    let d = fo.discriminant()?;
    if &(&g[0] * &g[0]) + &(&g[1] * &g[1]) != d {
        return Err(CanalError::NotASplit(
            "the given split does not square to |ṁ|² − ṙ²".into(),
        ));
    }
    match method {
        Method::Krasauskas => {
            let p = fo.derivative_numerators()?;
            build_krasauskas(fo, &p, g, axis, mid, memo)
        }
        _ => super::canal_surface_with_split(
            fo,
            &g[0],
            &g[1],
            &CanalOptions {
                axis: Some(axis),
                ..CanalOptions::default()
            },
        ),
    }
}

fn pieces_on(
    spine: &CanalSpine<Rational>,
    split: Option<&[Poly<Rational>; 2]>,
    options: &CanalOptions,
    interval: (&Rational, &Rational),
    depth: usize,
    acc: &mut ExportableCanal,
    (memo, prune): (&FactorMemo, bool),
) -> Result<(), CanalError> {
    let (a, b) = interval;
    let res = candidates_on(spine, split, options, (a, b), memo, prune)?;
    acc.tried += res.tried;
    acc.exporting += res.exporting;
    if let Some(p) = res.best {
        acc.pieces.push(p);
        return Ok(());
    }
    if res.tried == 0 {
        // nothing built at all: the data, not the frame, is the problem
        if let Some(d) = res.radicand {
            return Err(CanalError::IrrationalSplit {
                radicand: format_scalar(&d),
            });
        }
        return Err(res.error.unwrap_or_else(|| {
            CanalError::DegenerateSpine("no exact construction applies".into())
        }));
    }
    if depth >= MAX_INTERVAL_SPLITS {
        return Err(CanalError::NotExportable {
            from: format_scalar(a),
            to: format_scalar(b),
            tried: res.tried,
        });
    }
    let m = (a.clone() + b.clone()) / Rational::from(2);
    pieces_on(
        spine,
        split,
        options,
        (a, &m),
        depth + 1,
        acc,
        (memo, prune),
    )?;
    pieces_on(
        spine,
        split,
        options,
        (&m, b),
        depth + 1,
        acc,
        (memo, prune),
    )
}

/// The canal surface of `spine` on the domain of `options` (required) as exact pieces that
/// export, from every construction, frame and interval split of the module docs;
/// `split` is an optional known `D = g₁² + g₂²` (for the family as given; `D` does not
/// depend on the orientation). The method, orientation and choice of `options` apply; its
/// axis is ignored (every frame is tried).
///
/// # Errors
/// [`CanalError::InvalidArgument`] without a domain or for `a > b`;
/// [`CanalError::NoRealEnvelope`] where `|ṁ| < |ṙ|` on the domain;
/// [`CanalError::IrrationalSplit`] if every build needs a quadratic field;
/// [`CanalError::NotExportable`] if no candidate exports on an interval after
/// [`MAX_INTERVAL_SPLITS`] bisections; the errors of the constructions if none builds.
pub fn canal_surface_exportable(
    spine: &CanalSpine<Rational>,
    split: Option<&[Poly<Rational>; 2]>,
    options: &CanalOptions,
) -> Result<ExportableCanal, CanalError> {
    // the factorizations repeat across frames, methods and intervals: computed once
    canal_surface_exportable_memo(spine, split, options, &FactorMemo::default())
}

/// [`canal_surface_exportable`] with the exact factorizations taken from (and added to)
/// `memo`.
fn canal_surface_exportable_memo(
    spine: &CanalSpine<Rational>,
    split: Option<&[Poly<Rational>; 2]>,
    options: &CanalOptions,
    memo: &FactorMemo,
) -> Result<ExportableCanal, CanalError> {
    canal_surface_exportable_search(spine, split, options, memo, true)
}

/// [`canal_surface_exportable_memo`], with or without pruning ([`candidates_on`]).
fn canal_surface_exportable_search(
    spine: &CanalSpine<Rational>,
    split: Option<&[Poly<Rational>; 2]>,
    options: &CanalOptions,
    memo: &FactorMemo,
    prune: bool,
) -> Result<ExportableCanal, CanalError> {
    let (a, b) = options.domain.clone().ok_or_else(|| {
        CanalError::InvalidArgument("an exported canal surface needs a parameter domain".into())
    })?;
    if a >= b {
        return Err(CanalError::InvalidArgument(format!(
            "empty parameter domain [{}, {}]",
            format_scalar(&a),
            format_scalar(&b)
        )));
    }
    let mut acc = ExportableCanal {
        pieces: Vec::new(),
        tried: 0,
        exporting: 0,
        regularity: Vec::new(),
    };
    pieces_on(spine, split, options, (&a, &b), 0, &mut acc, (memo, prune))?;
    Ok(acc)
}

fn check_radius(r: &Rational) -> Result<(), CanalError> {
    if r.is_zero() {
        return Err(CanalError::InvalidArgument(
            "the pipe radius must be non-zero".into(),
        ));
    }
    Ok(())
}

/// The split `(√D, 0)` when `D` is a perfect square (a PH spine: `D = σ²/d²`), else the
/// split `(P_a, P_b)` of a spine planar in a coordinate plane (`P_j ≡ 0`, `P₄ ≡ 0`), else
/// `None`.
fn known_pipe_split(s: &CanalSpine<Rational>) -> Result<Option<[Poly<Rational>; 2]>, CanalError> {
    let p = s.derivative_numerators()?;
    if !p[3].is_zero() {
        return Ok(None);
    }
    let d = s.discriminant()?;
    if let Some(root) = super::poly_sqrt(&d) {
        return Ok(Some([root, Poly::zero()]));
    }
    if let Some(j) = (0..3).find(|&j| p[j].is_zero()) {
        let o: Vec<usize> = (0..3).filter(|&i| i != j).collect();
        if let (Some(&i0), Some(&i1)) = (o.first(), o.get(1)) {
            return Ok(Some([p[i0].clone(), p[i1].clone()]));
        }
    }
    Ok(None)
}

/// The pipe of radius `r` around a rational spine on `domain`, as exact pieces that export
/// ([`canal_surface_exportable`]; a PH or planar spine also gets its split `(σ, 0)` or
/// `(ṁ_a, ṁ_b)`, which needs no factorization).
///
/// # Errors
/// [`CanalError::InvalidArgument`] for `r = 0` or a spine not in E3;
/// [`CanalError::ZeroTangent`] and [`CanalError::RadiusNotBelowCurvatureRadius`] where the
/// pipe would not be regular ([`check_pipe_regularity`]); as [`canal_surface_exportable`].
pub fn pipe_exportable(
    spine: &BezierCurve<Rational>,
    radius: &Rational,
    domain: (&Rational, &Rational),
    orientation: Orientation,
) -> Result<ExportableCanal, CanalError> {
    pipe_exportable_checked(spine, radius, domain, orientation, true)
}

/// [`pipe_exportable`], with the global check only if `global` (a chain checks its pieces
/// together).
fn pipe_exportable_checked(
    spine: &BezierCurve<Rational>,
    radius: &Rational,
    domain: (&Rational, &Rational),
    orientation: Orientation,
    global: bool,
) -> Result<ExportableCanal, CanalError> {
    check_radius(radius)?;
    let s = CanalSpine::constant_radius(spine, radius)?;
    // a constant spine is a degenerate family before it is a zero tangent
    s.derivative_numerators()?;
    let mut regular = vec![check_pipe_regularity(&s, domain)?];
    if global {
        regular.push(check_pipe_embedded(&s, domain)?);
    }
    let split = known_pipe_split(&s)?;
    let options = CanalOptions {
        orientation,
        domain: Some((domain.0.clone(), domain.1.clone())),
        ..CanalOptions::default()
    };
    let mut out = canal_surface_exportable(&s, split.as_ref(), &options)?;
    out.regularity.extend(regular);
    Ok(out)
}

/// The pipe of radius `r` around a spatial PH curve on `domain` (split `(σ/d, 0)`, `d` the
/// content of the hodograph), as exact pieces that export ([`canal_surface_exportable`]):
/// the same candidates as [`pipe_exportable`] of the curve's Bézier form, so never a larger
/// export.
///
/// # Errors
/// As [`pipe_exportable`].
pub fn pipe_around_ph_exportable(
    curve: &PhCurve<Rational>,
    radius: &Rational,
    domain: (&Rational, &Rational),
    orientation: Orientation,
) -> Result<ExportableCanal, CanalError> {
    pipe_around_ph_with(curve, radius, domain, orientation, Method::Lowest)
}

/// [`pipe_around_ph_exportable`] with the candidate constructions restricted to `method`
/// ([`Method::Lowest`]: all of them).
///
/// # Errors
/// As [`pipe_around_ph_exportable`].
pub fn pipe_around_ph_with(
    curve: &PhCurve<Rational>,
    radius: &Rational,
    domain: (&Rational, &Rational),
    orientation: Orientation,
    method: Method,
) -> Result<ExportableCanal, CanalError> {
    pipe_around_ph_checked(curve, radius, domain, orientation, method, true)
}

/// [`pipe_around_ph_with`], with the global check only if `global` (the pieces of a PH
/// spline are checked together, [`check_ph_chain_embedded`]).
pub(crate) fn pipe_around_ph_checked(
    curve: &PhCurve<Rational>,
    radius: &Rational,
    domain: (&Rational, &Rational),
    orientation: Orientation,
    method: Method,
    global: bool,
) -> Result<ExportableCanal, CanalError> {
    check_radius(radius)?;
    let position = curve.position();
    let s = CanalSpine::polynomial(position.clone(), Poly::constant(radius.clone()));
    // a constant spine is a degenerate family before it is a zero tangent
    s.derivative_numerators()?;
    let mut regular = vec![check_pipe_regularity(&s, domain)?];
    if global {
        regular.push(check_pipe_embedded(&s, domain)?);
    }
    let h: [Poly<Rational>; 3] = core::array::from_fn(|i| position[i].derivative());
    let d = h
        .iter()
        .fold(Poly::zero(), |acc: Poly<Rational>, p| acc.gcd(p));
    let sigma = curve.speed();
    let g1 = if d.degree().is_some_and(|k| k > 0) {
        sigma.div_exact(&d)?
    } else {
        sigma
    };
    let split = [g1, Poly::zero()];
    // the derivative numerators are divided by the monic gcd; σ/d then squares to D up to
    // the constant that normalizes the gcd: fall back to the detected split if not
    let split = if s.discriminant()? == &split[0] * &split[0] {
        Some(split)
    } else {
        known_pipe_split(&s)?
    };
    let options = CanalOptions {
        orientation,
        domain: Some((domain.0.clone(), domain.1.clone())),
        method,
        ..CanalOptions::default()
    };
    let mut out = canal_surface_exportable(&s, split.as_ref(), &options)?;
    out.regularity.extend(regular);
    Ok(out)
}

/// The global check ([`check_chain_embedded`]) of the pipe of radius `r` around a chain of
/// PH curves, each on `t ∈ [0, 1]` (the pieces of a PH spline).
///
/// # Errors
/// As [`check_chain_embedded`].
pub fn check_ph_chain_embedded(
    curves: &[&PhCurve<Rational>],
    radius: &Rational,
) -> Result<Certificate, CanalError> {
    check_radius(radius)?;
    let chain: Vec<_> = curves
        .iter()
        .map(|c| {
            (
                CanalSpine::polynomial(c.position().clone(), Poly::constant(radius.clone())),
                (Rational::ZERO, Rational::ONE),
            )
        })
        .collect();
    check_chain_embedded(&chain)
}

/// A pipe around a chain of spine curves (for example the Bézier pieces of B-spline curves
/// read from a STEP or IGES file), one [`ExportableCanal`] per piece on `t ∈ [0, 1]`, with
/// certificates of how consecutive pieces meet.
#[derive(Debug, Clone, PartialEq)]
pub struct PipeChain {
    pieces: Vec<ExportableCanal>,
    joins: Vec<Certificate>,
    /// What a piece is called in the certificates (`spine piece`).
    label: &'static str,
}

impl PipeChain {
    /// Pieces built elsewhere, without join certificates, called `label` in the
    /// certificates (the pipes around the pieces of a PH spline).
    pub(crate) fn from_pieces(
        pieces: Vec<ExportableCanal>,
        label: &'static str,
        global: Certificate,
    ) -> Self {
        PipeChain {
            pieces,
            joins: vec![global],
            label,
        }
    }

    /// More join certificates (the seam of a closed chain built elsewhere).
    pub(crate) fn add_joins(&mut self, certs: Vec<Certificate>) {
        self.joins.extend(certs);
    }

    /// The pipe of each spine piece.
    pub fn pieces(&self) -> &[ExportableCanal] {
        &self.pieces
    }

    /// All patches (every Bernstein weight `> 0`), piece after piece.
    pub fn patches(&self) -> Vec<BezierPatch<Rational>> {
        self.pieces
            .iter()
            .flat_map(ExportableCanal::patches)
            .collect()
    }

    /// The total number of control points.
    pub fn control_points(&self) -> usize {
        self.pieces
            .iter()
            .map(ExportableCanal::control_points)
            .sum()
    }
}

impl Certified for PipeChain {
    /// Every piece's certificates (prefixed `spine piece k:` when there are several), and
    /// per join whether the spine pieces meet (`G⁰`) and with the same tangent direction
    /// (`G¹`, so the pipes meet along the same characteristic circle).
    fn certify(&self) -> Vec<Certificate> {
        let many = self.pieces.len() > 1;
        let mut out = Vec::new();
        for (k, p) in self.pieces.iter().enumerate() {
            out.extend(p.certify().into_iter().map(|mut c| {
                if many {
                    c.property = format!("{} {k}: {}", self.label, c.property);
                }
                c
            }));
        }
        out.extend(self.joins.iter().cloned());
        out
    }
}

/// `true` if the chain is closed with a `G¹` seam: the last piece ends where the first
/// starts, with the same tangent direction (a corner is two ends whose discs meet).
pub fn chain_is_g1_closed(spines: &[BezierCurve<Rational>]) -> bool {
    let (Some(first), Some(last)) = (spines.first(), spines.last()) else {
        return false;
    };
    let Some([pe, ps, te, ts]) = joint_tangents(last, first) else {
        return false;
    };
    let (cross, dot) = cross_dot(&te, &ts);
    pe == ps && cross.iter().all(Rational::is_zero) && dot > Rational::ZERO
}

fn join_certificates(
    k: usize,
    next: usize,
    a: &BezierCurve<Rational>,
    b: &BezierCurve<Rational>,
) -> Vec<Certificate> {
    let Some([pe, ps, te, ts]) = joint_tangents(a, b) else {
        return vec![Certificate::fails(
            format!("spine pieces {k} and {next} meet (G⁰)"),
            "an end control point has weight 0",
            true,
        )];
    };
    let gap: Vec<Rational> = (0..3).map(|i| ps[i].clone() - pe[i].clone()).collect();
    let g0 = Certificate::decide(
        format!(
            "spine pieces {k} and {next} meet: end point of piece {k} = start point of piece {next} (G⁰)"
        ),
        gap.iter().all(Rational::is_zero),
        true,
        || {
            format!(
                "gap ({}, {}, {})",
                format_scalar(&gap[0]),
                format_scalar(&gap[1]),
                format_scalar(&gap[2])
            )
        },
    );
    // end tangent ∝ p_n − p_{n−1}, start tangent ∝ p_1 − p_0 (positive weights)
    let (cross, dot) = cross_dot(&te, &ts);
    let g1 = Certificate::decide(
        format!("spine pieces {k} and {next} have the same tangent direction at the joint (G¹: the pipes share the characteristic circle there)"),
        cross.iter().all(Rational::is_zero) && dot > Rational::ZERO,
        true,
        || format!("end tangent ∝ ({}, {}, {}), start tangent ∝ ({}, {}, {})", format_scalar(&te[0]), format_scalar(&te[1]), format_scalar(&te[2]), format_scalar(&ts[0]), format_scalar(&ts[1]), format_scalar(&ts[2])),
    );
    vec![g0, g1]
}

/// The pipe of radius `r` around a chain of spine curves, each on `t ∈ [0, 1]`
/// ([`pipe_exportable`] per piece), with the `G⁰`/`G¹` certificates of the joints and the
/// global check of the whole chain ([`check_chain_embedded`]: no two normal discs meet).
///
/// # Errors
/// [`CanalError::InvalidArgument`] for an empty chain; [`CanalError::SpinePiece`] wrapping
/// the error of a piece (as [`pipe_exportable`]); [`CanalError::PipeSelfIntersects`] and
/// [`CanalError::TubePartsNotApart`] of the global check.
pub fn pipe_along_chain(
    spines: &[BezierCurve<Rational>],
    radius: &Rational,
    orientation: Orientation,
) -> Result<PipeChain, CanalError> {
    if spines.is_empty() {
        return Err(CanalError::InvalidArgument("no spine curve".into()));
    }
    let (zero, one) = (Rational::ZERO, Rational::ONE);
    // the pieces are independent: built in parallel, kept in order (the first failing
    // piece's error is reported)
    let mut pieces = spines
        .par_iter()
        .enumerate()
        .map(rcagd_algebra::budget::inherit(
            |(k, s): (usize, &BezierCurve<Rational>)| {
                pipe_exportable_checked(s, radius, (&zero, &one), orientation, false).map_err(|e| {
                    if spines.len() == 1 {
                        e
                    } else {
                        CanalError::SpinePiece {
                            index: k,
                            source: Box::new(e),
                        }
                    }
                })
            },
        ))
        .collect::<Vec<_>>()
        .into_iter()
        .collect::<Result<Vec<_>, _>>()?;
    let mut joins: Vec<Certificate> = spines
        .windows(2)
        .enumerate()
        .flat_map(|(k, w)| join_certificates(k, k + 1, &w[0], &w[1]))
        .collect();
    let closed = chain_is_g1_closed(spines);
    if closed {
        // the seam: the last piece joins the first (certified like the other joints)
        if let (Some(first), Some(last)) = (spines.first(), spines.last()) {
            joins.extend(join_certificates(spines.len() - 1, 0, last, first));
        }
    }
    // after the pieces (whose local regularity the global check assumes)
    let chain = spines
        .iter()
        .map(|c| {
            Ok((
                CanalSpine::constant_radius(c, radius)?,
                (zero.clone(), one.clone()),
            ))
        })
        .collect::<Result<Vec<_>, CanalError>>()?;
    joins.push(check_chain_embedded(&chain)?);
    if closed {
        // after the global check (a closed spine that meets itself is refused first); if
        // the seam cannot be closed (no tiling with positive weights within the limits),
        // the pipe stays as built: exact and certified, with open seams (the CLI's closure
        // check reports them)
        let mut closing = pieces.clone();
        match super::seam::close_rings(&mut closing) {
            Ok(certs) => {
                pieces = closing;
                joins.extend(certs);
            }
            Err(CanalError::InvalidArgument(_)) => {}
            Err(e) => return Err(e),
        }
    }
    Ok(PipeChain {
        pieces,
        joins,
        label: "spine piece",
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::canal::BiPoly;
    use rcagd_algebra::quaternion::Quaternion;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    /// The search with the memo of factorizations ([`FactorMemo`]) and without it
    /// (every factorization and reality check computed where it is needed, as before the
    /// memo) on the family `s` with the split `split`: the same pieces, candidates and
    /// certificates, or the same error.
    fn memo_agrees(s: &CanalSpine<Rational>, split: Option<&[Poly<Rational>; 2]>) {
        let options = CanalOptions {
            domain: Some((q(0), q(1))),
            ..CanalOptions::default()
        };
        // without pruning: a memo without memory builds the frames `(j, −)` a memo derives,
        // and pruning skips different builds in them (pruning is compared on its own by
        // `pruning_agrees`)
        let search = |memo| canal_surface_exportable_search(s, split, &options, memo, false);
        let (with, without) = (search(&FactorMemo::default()), search(&FactorMemo::off()));
        match (&with, &without) {
            (Ok(x), Ok(y)) => {
                assert_eq!(x, y, "{} against {}", x.summary(), y.summary());
                assert_eq!(x.certify(), y.certify());
            }
            (Err(x), Err(y)) => assert_eq!(format!("{x:?}"), format!("{y:?}")),
            _ => panic!("{with:?} against {without:?}"),
        }
    }

    #[test]
    fn memo_keeps_the_choice_of_the_seed_pipes() {
        // the gallery quintic (preimage 1, i + k, 1 + j) and issue 17's quintic
        for (a, r) in [
            ([[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]], (1, 10)),
            ([[1, 0, 0, 0], [1, 1, 0, 1], [0, 0, 1, 1]], (1, 8)),
        ] {
            let a: Vec<Quaternion<Rational>> = a
                .iter()
                .map(|c| Quaternion::new(q(c[0]), q(c[1]), q(c[2]), q(c[3])))
                .collect();
            let c = PhCurve::new(a, [q(0), q(0), q(0)]).expect("ph");
            let s = CanalSpine::polynomial(
                c.position().clone(),
                Poly::constant(Rational::from_ratio(r.0, r.1)),
            );
            let split = known_pipe_split(&s).expect("split");
            memo_agrees(&s, split.as_ref());
            memo_agrees(&s, None);
        }
    }

    /// The search with pruning against the search without it on `[0, 1]`: the same pieces
    /// (interval, frame, surface, patches) and certificates, or the same error. Returns the
    /// candidates tried with and without pruning.
    fn pruning_agrees(
        s: &CanalSpine<Rational>,
        split: Option<&[Poly<Rational>; 2]>,
    ) -> Option<(usize, usize)> {
        let options = CanalOptions {
            domain: Some((q(0), q(1))),
            ..CanalOptions::default()
        };
        let search = |prune| {
            canal_surface_exportable_search(s, split, &options, &FactorMemo::default(), prune)
        };
        let (pruned, full) = (search(true), search(false));
        match (&pruned, &full) {
            (Ok(x), Ok(y)) => {
                assert_eq!(
                    x.pieces(),
                    y.pieces(),
                    "{} against {}",
                    x.summary(),
                    y.summary()
                );
                assert_eq!(x.certify(), y.certify());
                assert!(x.tried <= y.tried && x.exporting <= y.exporting);
                Some((x.tried, y.tried))
            }
            (Err(x), Err(y)) => {
                assert_eq!(format!("{x:?}"), format!("{y:?}"));
                None
            }
            _ => panic!("{pruned:?} against {full:?}"),
        }
    }

    /// The polynomial `x(t, u₀)` in `t`.
    fn at_u(x: &BiPoly<Rational>, u: &Rational) -> Poly<Rational> {
        x.coeffs()
            .iter()
            .rev()
            .fold(Poly::zero(), |acc, c| &acc.scale(u) + c)
    }

    /// Every candidate of every frame of the search on `[a, b]` (both methods, general
    /// splits and `split`, nothing skipped) of a pipe whose spine has a size floor
    /// `(δ, k)` ([`pipe_size_floor`]): the unit normals `N(t, u₀) = (W x − x₀ m)/(R x₀)` at
    /// `u₀ ∈ {0, 1/3, −2}` have reduced denominators of degree `≥ δ`,
    /// `deg_t x = deg_t x₀ + k`, every chart has a bidegree `≥ (δ + k, 2)` and the size key
    /// of the estimate is at least the floor of the candidate's method. Returns the number
    /// of candidates checked (0 without a floor).
    fn floor_holds(
        s: &CanalSpine<Rational>,
        split: Option<&[Poly<Rational>; 2]>,
        (a, b): (Rational, Rational),
    ) -> usize {
        let memo = FactorMemo::default();
        let options = CanalOptions {
            domain: Some((a.clone(), b.clone())),
            ..CanalOptions::default()
        };
        let so = oriented(s, options.orientation);
        let global = memo.check_real_envelope(&so, None).is_ok();
        let Some((delta, k)) = pipe_size_floor(&so, global) else {
            return 0;
        };
        let methods = [Method::Krasauskas, Method::PeternellPottmann];
        let search = Search {
            spine: s,
            split,
            options: &options,
            methods: &methods,
            global,
            domain: (&a, &b),
            mid: (a.clone() + b.clone()) / q(2),
            memo: &memo,
        };
        let mut res = IntervalResult::default();
        let w = so.weight().clone();
        let m = so.center_polys();
        let mut checked = 0;
        for frame in frames_on(&so, (&a, &b), global).expect("frames") {
            for c in search.frame_candidates(&frame, &mut res, &[]) {
                let Ok(c) = c else { continue };
                let c = match &frame {
                    Frame::Axis(_) => c,
                    Frame::Direction(e) => c.transformed(&householder(e), &so).expect("mapped"),
                };
                let x = c.homogeneous();
                let dt0 = x[0].degree_t().expect("a weight");
                let (dt, du) = c.degree();
                assert!(
                    dt0 >= delta && dt == dt0 + k && du >= 2,
                    "{frame}: {dt0} {dt} {du}"
                );
                for (ct, cu) in c.chart_bidegrees() {
                    assert!(ct >= delta + k && cu >= 2, "{frame}: chart ({ct}, {cu})");
                }
                for u0 in [q(0), Rational::from_ratio(1, 3), q(-2)] {
                    let x0 = at_u(&x[0], &u0);
                    if x0.is_zero() {
                        continue;
                    }
                    let g = (0..3).fold(x0.clone(), |g, i| {
                        let d = &at_u(&x[i + 1], &u0).scale(&w.coeff(0)) - &(&x0 * &m[i]);
                        g.gcd(&d)
                    });
                    let den = x0.div_exact(&g).expect("a divisor");
                    assert!(den.degree().is_some_and(|d| d >= delta), "{frame}: {den:?}");
                }
                let method = match c.construction() {
                    Construction::Krasauskas { .. } => Method::Krasauskas,
                    Construction::PeternellPottmann => Method::PeternellPottmann,
                };
                if let Some(est) = exported_size_f64(&c) {
                    let floor = candidate_size_bound(delta, k, least_patches(method));
                    assert!((est, dt + du) >= floor, "{frame}: {est} < {floor:?}");
                }
                checked += 1;
            }
        }
        checked
    }

    #[test]
    fn pruning_keeps_the_choice_of_the_seed_pipes() {
        for s in seed_pipe_spines() {
            let split = known_pipe_split(&s).expect("split");
            for split in [split.as_ref(), None] {
                let (pruned, full) = pruning_agrees(&s, split).expect("builds");
                // the floor is reached by the first candidate: later Krasauskas builds skipped
                assert!(pruned < full, "{pruned} {full}");
            }
        }
    }

    #[test]
    fn size_floor_holds_for_every_candidate_of_the_seed_pipes() {
        for s in seed_pipe_spines() {
            let split = known_pipe_split(&s).expect("split");
            // every candidate the search without pruning tries on [0, 1] (one piece)
            let options = CanalOptions {
                domain: Some((q(0), q(1))),
                ..CanalOptions::default()
            };
            let full = canal_surface_exportable_search(
                &s,
                split.as_ref(),
                &options,
                &FactorMemo::default(),
                false,
            )
            .expect("builds");
            assert_eq!(full.pieces().len(), 1);
            assert_eq!(floor_holds(&s, split.as_ref(), (q(0), q(1))), full.tried);
            assert!(floor_holds(&s, split.as_ref(), (q(0), Rational::from_ratio(1, 2))) > 0);
        }
    }

    /// The PH quintic starting at the origin with the preimage coefficients `a` (integer
    /// quaternions), if it is one (not all zero).
    fn ph_of_preimage(a: &[[i64; 4]]) -> Option<PhCurve<Rational>> {
        let quats: Vec<Quaternion<Rational>> = a
            .iter()
            .map(|c| Quaternion::new(q(c[0]), q(c[1]), q(c[2]), q(c[3])))
            .collect();
        PhCurve::new(quats, [q(0), q(0), q(0)]).ok()
    }

    /// Pipes of radius 1/10 around the two seed PH quintics (the gallery quintic, preimage
    /// `1`, `i + k`, `1 + j`, and issue 17's, `1`, `1 + i + k`, `j + k`).
    fn seed_pipe_spines() -> Vec<CanalSpine<Rational>> {
        [
            [[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]],
            [[1, 0, 0, 0], [1, 1, 0, 1], [0, 0, 1, 1]],
        ]
        .iter()
        .map(|a| {
            let c = ph_of_preimage(a).expect("ph");
            CanalSpine::polynomial(
                c.position().clone(),
                Poly::constant(Rational::from_ratio(1, 10)),
            )
        })
        .collect()
    }

    /// The spine whose coordinate `k` has the power coefficients `cubic[4k..4k + 4]`.
    fn cubic_spine(cubic: &[i64], radius: Poly<Rational>) -> CanalSpine<Rational> {
        let m: [Poly<Rational>; 3] =
            core::array::from_fn(|k| Poly::from_ints(&cubic[4 * k..4 * k + 4]));
        CanalSpine::polynomial(m, radius)
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(16))]

        /// Random PH quintics with and without their split `(σ, 0)`: every candidate
        /// built respects the size floor, and pruning changes no choice.
        #[test]
        fn pruning_keeps_the_choice_on_random_spines(
            a in proptest::collection::vec(proptest::array::uniform4(-3i64..4), 3),
            r in 1i64..20,
        ) {
            if let Some(c) = ph_of_preimage(&a) {
                let s = CanalSpine::polynomial(
                    c.position().clone(),
                    Poly::constant(Rational::from_ratio(r, 40)),
                );
                if let Ok(split) = known_pipe_split(&s) {
                    floor_holds(&s, split.as_ref(), (q(0), q(1)));
                    pruning_agrees(&s, split.as_ref());
                    pruning_agrees(&s, None);
                }
            }
        }

        /// Random PH quintics (with their split `(σ, 0)`) and pipes around random planar
        /// cubics (the general splits of `D`): the memo changes nothing.
        #[test]
        fn memo_keeps_the_choice_on_random_spines(
            a in proptest::collection::vec(proptest::array::uniform4(-3i64..4), 3),
            cubic in proptest::collection::vec(-4i64..5, 12),
            r in 1i64..20,
            planar in proptest::prelude::any::<bool>(),
        ) {
            if let Some(c) = ph_of_preimage(&a) {
                let s = CanalSpine::polynomial(
                    c.position().clone(),
                    Poly::constant(Rational::from_ratio(r, 40)),
                );
                if let Ok(split) = known_pipe_split(&s) {
                    memo_agrees(&s, split.as_ref());
                }
            }
            // a planar cubic (D = ẋ² + ẏ², split over Q(i) by the general builder) in the
            // plane z = 0 or z = x
            let m: [Poly<Rational>; 3] = core::array::from_fn(|k| match k {
                2 if planar => Poly::zero(),
                2 => Poly::from_ints(&cubic[..4]),
                _ => Poly::from_ints(&cubic[4 * k..4 * k + 4]),
            });
            let radius = Poly::constant(Rational::from_ratio(r, 40));
            memo_agrees(&CanalSpine::polynomial(m, radius), None);
        }
    }

    /// Every candidate of the frame `(j, −)` built (general splits and the caller's split,
    /// both methods, on `[0, 1]` and `[0, 1/2]`) against [`CanalSurface::mirrored`] of the
    /// candidate of `(j, +)`: the same surface (compared with its `Debug` text too), or
    /// both fail. Returns the number of surfaces compared.
    fn mirror_agrees(s: &CanalSpine<Rational>, split: Option<&[Poly<Rational>; 2]>) -> usize {
        let memo = FactorMemo::default();
        let mut compared = 0;
        for (a, b) in [(q(0), q(1)), (q(0), Rational::from_ratio(1, 2))] {
            let mid = (a.clone() + b.clone()) / q(2);
            for j in 0..3 {
                let plus = AxisChoice {
                    axis: j,
                    positive: true,
                };
                let minus = AxisChoice {
                    axis: j,
                    positive: false,
                };
                for method in [Method::Krasauskas, Method::PeternellPottmann] {
                    let general = |axis| {
                        let opts = CanalOptions {
                            axis: Some(axis),
                            domain: Some((a.clone(), b.clone())),
                            method,
                            ..CanalOptions::default()
                        };
                        match canal_surface_memo(s, &opts, &memo) {
                            Ok(CanalBuild::Rational(x)) => Some(Ok(x)),
                            Ok(CanalBuild::Extension { .. }) => None,
                            Err(e) => Some(Err(e)),
                        }
                    };
                    let mut pairs = vec![(general(plus), general(minus))];
                    if let Some(g) = split {
                        let given = |axis| Some(with_split(s, g, axis, method, &mid, &memo));
                        pairs.push((given(plus), given(minus)));
                    }
                    for pair in pairs {
                        match pair {
                            (Some(Ok(p)), Some(Ok(m))) => {
                                let derived = p.mirrored().expect("a pipe").expect("mirrored");
                                assert_eq!(derived, m, "{j} {method:?}");
                                assert_eq!(format!("{derived:?}"), format!("{m:?}"));
                                assert_eq!(derived.axis(), minus);
                                compared += 1;
                            }
                            (Some(Err(_)), Some(Err(_))) | (None, None) => {}
                            (p, m) => panic!("{j} {method:?}: {p:?} against {m:?}"),
                        }
                    }
                }
            }
        }
        compared
    }

    /// Every candidate of the six coordinate frames (general splits and the caller's split,
    /// both methods, on `[0, 1]` and `[0, 1/2]`): the bidegrees of its charts from the
    /// supports are those of the charts built, and candidates with equal
    /// [`CanalSurface::weight_patch_key`]s have equal export estimates (the key holds all
    /// the estimate reads). Returns how many `(j, −)` candidates share the key of their
    /// `(j, +)` candidate (the estimates the search saves).
    fn estimate_follows_the_key(
        s: &CanalSpine<Rational>,
        split: Option<&[Poly<Rational>; 2]>,
    ) -> usize {
        use crate::canal::bipoly::bidegree;
        let memo = FactorMemo::default();
        let mut shared = 0;
        for (a, b) in [(q(0), q(1)), (q(0), Rational::from_ratio(1, 2))] {
            let mid = (a.clone() + b.clone()) / q(2);
            let mut seen: Vec<(super::WeightPatchKey<Rational>, Option<usize>)> = Vec::new();
            for axis in AxisChoice::all() {
                for method in [Method::Krasauskas, Method::PeternellPottmann] {
                    let opts = CanalOptions {
                        axis: Some(axis),
                        domain: Some((a.clone(), b.clone())),
                        method,
                        ..CanalOptions::default()
                    };
                    let mut built = Vec::new();
                    if let Ok(CanalBuild::Rational(x)) = canal_surface_memo(s, &opts, &memo) {
                        built.push(x);
                    }
                    if let Some(g) = split {
                        if let Ok(x) = with_split(s, g, axis, method, &mid, &memo) {
                            built.push(x.on_domain(&a, &b));
                        }
                    }
                    for x in built {
                        let charts: Vec<(usize, usize)> = x
                            .charts(x.homogeneous())
                            .iter()
                            .map(|c| bidegree(c))
                            .collect();
                        assert_eq!(x.chart_bidegrees(), charts);
                        let key = x.weight_patch_key();
                        let est = exported_size_f64(&x);
                        if let Some((_, old)) = seen.iter().find(|(k, _)| *k == key) {
                            assert_eq!(*old, est, "{axis:?} {method:?}");
                            if !axis.positive {
                                shared += 1;
                            }
                        }
                        seen.push((key, est));
                    }
                }
            }
        }
        shared
    }

    #[test]
    fn equal_weight_keys_give_equal_estimates_on_the_seed_pipes() {
        for s in seed_pipe_spines() {
            let split = known_pipe_split(&s).expect("split");
            // the mirrored candidates share their weight with the candidates they come
            // from: at least the Krasauskas ones of the three axes on both intervals
            assert!(estimate_follows_the_key(&s, split.as_ref()) >= 6);
            estimate_follows_the_key(&s, None);
        }
    }

    #[test]
    fn mirrored_frame_is_the_built_frame_on_the_seed_pipes() {
        for s in seed_pipe_spines() {
            let split = known_pipe_split(&s).expect("split");
            assert!(split.is_some());
            assert!(mirror_agrees(&s, split.as_ref()) >= 12);
            assert!(mirror_agrees(&s, None) >= 12);
        }
    }

    #[test]
    fn mirrored_needs_a_constant_radius() {
        // the cone r = 3t/5 around the x axis (D = 1 − 9/25 = (4/5)²): P₄ ≢ 0, no
        // mirrored candidate
        let m = [Poly::from_ints(&[0, 1]), Poly::zero(), Poly::zero()];
        let s = CanalSpine::polynomial(m, Poly::new(vec![q(0), Rational::from_ratio(3, 5)]));
        let opts = CanalOptions {
            axis: Some(AxisChoice::all()[0]),
            domain: Some((q(1), q(2))),
            method: Method::PeternellPottmann,
            ..CanalOptions::default()
        };
        let built = canal_surface_memo(&s, &opts, &FactorMemo::default());
        let Ok(CanalBuild::Rational(x)) = built else {
            panic!("the cone builds over Q: {built:?}");
        };
        assert!(x.mirrored().is_none());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(12))]

        /// Pipes around random PH quintics with their split `(σ, 0)` and random cubics:
        /// candidates with equal weight-patch keys have equal export estimates.
        #[test]
        fn equal_weight_keys_give_equal_estimates_on_random_spines(
            a in proptest::collection::vec(proptest::array::uniform4(-3i64..4), 3),
            cubic in proptest::collection::vec(-4i64..5, 12),
            r in 1i64..20,
        ) {
            let radius = Poly::constant(Rational::from_ratio(r, 40));
            if let Some(c) = ph_of_preimage(&a) {
                let s = CanalSpine::polynomial(c.position().clone(), radius.clone());
                if let Ok(split) = known_pipe_split(&s) {
                    estimate_follows_the_key(&s, split.as_ref());
                }
            }
            estimate_follows_the_key(&cubic_spine(&cubic, radius), None);
        }

        /// Pipes around random PH quintics (with and without their split `(σ, 0)`) and
        /// random cubics: the candidates of the frames `(j, −)` are the mirrored ones of
        /// `(j, +)`.
        #[test]
        fn mirrored_frame_is_the_built_frame_on_random_spines(
            a in proptest::collection::vec(proptest::array::uniform4(-3i64..4), 3),
            cubic in proptest::collection::vec(-4i64..5, 12),
            r in 1i64..20,
        ) {
            let radius = Poly::constant(Rational::from_ratio(r, 40));
            if let Some(c) = ph_of_preimage(&a) {
                let s = CanalSpine::polynomial(c.position().clone(), radius.clone());
                if let Ok(split) = known_pipe_split(&s) {
                    mirror_agrees(&s, split.as_ref());
                }
                mirror_agrees(&s, None);
            }
            mirror_agrees(&cubic_spine(&cubic, radius), None);
        }
    }

    /// [`exported_size_f64`] (weights only) against the size of [`exported_patches`] of
    /// the whole surface in `f64`, for every frame axis and both methods on `[0, 1]` and on
    /// `[0, 1/2]`: the same number of control points, or `None` for both.
    fn weight_estimate_agrees(s: &CanalSpine<Rational>) -> usize {
        let memo = FactorMemo::default();
        let mut compared = 0;
        for (a, b) in [(q(0), q(1)), (q(0), Rational::from_ratio(1, 2))] {
            for axis in AxisChoice::all() {
                for method in [Method::Krasauskas, Method::PeternellPottmann] {
                    let opts = CanalOptions {
                        axis: Some(axis),
                        domain: Some((a.clone(), b.clone())),
                        method,
                        ..CanalOptions::default()
                    };
                    let Ok(CanalBuild::Rational(x)) = canal_surface_memo(s, &opts, &memo) else {
                        continue;
                    };
                    let full = exported_patches(&x.map_scalar(Scalar::to_f64))
                        .map(|p| control_points_f64(&p));
                    assert_eq!(exported_size_f64(&x), full, "{axis:?} {method:?}");
                    compared += 1;
                }
            }
        }
        compared
    }

    #[test]
    fn weight_estimate_is_the_full_estimate_on_the_seed_pipes() {
        for s in seed_pipe_spines() {
            assert!(weight_estimate_agrees(&s) >= 8);
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(12))]

        /// Pipes around random PH quintics and random cubics: the `f64` size estimate from
        /// the weights alone is the one from the whole surface.
        #[test]
        fn weight_estimate_is_the_full_estimate_on_random_spines(
            a in proptest::collection::vec(proptest::array::uniform4(-3i64..4), 3),
            cubic in proptest::collection::vec(-4i64..5, 12),
            r in 1i64..20,
        ) {
            let radius = Poly::constant(Rational::from_ratio(r, 40));
            if let Some(c) = ph_of_preimage(&a) {
                weight_estimate_agrees(&CanalSpine::polynomial(c.position().clone(), radius.clone()));
            }
            weight_estimate_agrees(&cubic_spine(&cubic, radius));
        }
    }

    /// The PH quintic of issue 17 (preimage `1`, `1 + i + k`, `j + k`): no single frame
    /// keeps the Peternell–Pottmann weight free of zeros on `[0, 1]` with the split `(σ, 0)`,
    /// Krasauskas' pencil does.
    #[test]
    fn ph_quintic_pipe_exports_as_small_as_the_general_pipe() {
        let a = vec![
            Quaternion::new(q(1), q(0), q(0), q(0)),
            Quaternion::new(q(1), q(1), q(0), q(1)),
            Quaternion::new(q(0), q(0), q(1), q(1)),
        ];
        let c = PhCurve::new(a, [q(0), q(0), q(0)]).expect("ph");
        let r = Rational::from_ratio(1, 8);
        let (zero, one) = (q(0), q(1));
        let ph = pipe_around_ph_exportable(&c, &r, (&zero, &one), Orientation::Positive)
            .expect("pipe_ph");
        assert!(ph.all_hold(), "{:?}", ph.certify());
        let bez = c.to_bezier().expect("bezier");
        let gen = pipe_exportable(&bez, &r, (&zero, &one), Orientation::Positive).expect("pipe");
        assert!(gen.all_hold());
        assert!(ph.control_points() <= gen.control_points());
        assert!(ph.control_points() <= 120, "{}", ph.summary());
        for p in ph.patches() {
            assert!(p.coords().iter().step_by(4).all(|w| *w > Rational::ZERO));
        }
    }
}
