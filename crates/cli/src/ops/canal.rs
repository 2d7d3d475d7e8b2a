//! Ops of the `canal` topic: line geometry in Plücker coordinates (`rcagd::lines`, Gruber
//! §1.1) and rational canal and pipe surfaces (`rcagd::canal`, Gruber ch. 2, Peternell
//! §2.5): lines from points or planes, common transversals, reguli, canal surfaces from a
//! spine and a radius, pipes (around PH curves and other rational spines), sphere–sphere
//! and sphere–plane blends, tori and Dupin-like canal surfaces.
//!
//! Every canal object is exact over `Q`: when the sum-of-two-squares step needs a quadratic
//! field `Q(√d)` the op fails and says which field (the exchange model holds rational
//! geometry only; `rcagd::canal` builds such surfaces over `Q(√d)` in the library).

use super::arith::{self, OpScalar};
use super::{poly_io, prefixed, OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use num_traits::{One, Zero};
use rcagd::canal::blend::PlaneEnd;
use rcagd::canal::{
    pipe_along_spine, ApproximationPolicy,
    blend_sphere_plane, blend_spheres, canal_chain_rational, canal_surface_rational,
    pipe_around_ph_exportable, BlendEnd, BlendSpine, CanalBuild, CanalError, CanalOptions, CanalSpine,
    CanalSurface, Method, Orientation, RationalCanal,
};
use rcagd::lines::regulus_patch::RegulusPatchError;
use rcagd::lines::{
    common_transversals_along, common_transversals_recorded, CommonTransversals, Line, Regulus,
    SqrtScalar,
};
use rcagd::ph::{PhCurve, PhError};
use rcagd::Certified;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::rational::format_rational;
use rcagd_algebra::{format_scalar, format_vector, Certificate, QuadExt, Rational, Scalar};
use rcagd_geom::weight_sign::{split_patches_adaptive, SignRule};
use rcagd_geom::{BezierCurve, BezierPatch};

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[
    LINE_THROUGH_POINTS,
    LINE_OF_PLANES,
    COMMON_TRANSVERSALS,
    REGULUS,
    CANAL_SURFACE,
    CANAL_CHAIN,
    CANAL_NORMAL_FIELD,
    PIPE_PH,
    PIPE,
    CANAL_BLEND_SPHERES,
    CANAL_BLEND_SPHERE_PLANE,
    TORUS,
    DUPIN_CANAL,
];

// ----------------------------------------------------------------------------------------
// helpers
// ----------------------------------------------------------------------------------------


fn point3(args: &OpArgs, param: &'static str) -> Result<[Rational; 3], OpError> {
    let p = args.point(param)?;
    <[Rational; 3]>::try_from(p)
        .map_err(|_| OpError::param(param, format!("`{param}` must be a point [x, y, z]")))
}

fn vec4(p: Vec<Rational>, param: &'static str, what: &str) -> Result<[Rational; 4], OpError> {
    <[Rational; 4]>::try_from(p).map_err(|v| {
        OpError::param(
            param,
            format!("{what} needs exactly 4 numbers, got {}", v.len()),
        )
    })
}

/// The segment between two homogeneous points (a degree-1 rational Bézier curve).
fn segment<T: Scalar>(p: &[T; 4], q: &[T; 4]) -> Result<BezierCurve<T>, OpError> {
    BezierCurve::from_homogeneous(vec![p.to_vec(), q.to_vec()])
        .map_err(|e| OpError::new(e.to_string()))
}

fn affine<T: Scalar>(p: &[T; 3]) -> [T; 4] {
    [T::one(), p[0].clone(), p[1].clone(), p[2].clone()]
}

/// Lines given as rows of two affine points `[[p, q], …]` (exactly `n` rows).
fn lines_param<T: Scalar>(args: &OpArgs, param: &'static str, n: usize) -> Result<Vec<Line<T>>, OpError> {
    let net = args.net(param)?;
    if net.len() != n || net.iter().any(|r| r.len() != 2) {
        return Err(OpError::param(
            param,
            format!("give exactly {n} lines, each as two points [[x, y, z], [x, y, z]]"),
        ));
    }
    let mut out = Vec::with_capacity(n);
    for (i, row) in net.iter().enumerate() {
        let pts: Vec<[T; 3]> = row
            .iter()
            .map(|p| {
                <[T; 3]>::try_from(arith::all_of::<T>(p)).map_err(|_| {
                    OpError::param(param, format!("line {i}: points must be [x, y, z]"))
                })
            })
            .collect::<Result<_, _>>()?;
        let l = Line::from_affine_points(&pts[0], &pts[1])
            .map_err(|e| OpError::param(param, format!("line {i}: {e}")))?;
        out.push(l);
    }
    Ok(out)
}

/// The Plücker coordinates in a certificate's property (the "output" of a line op).
fn line_certs<T: Scalar>(name: &str, l: &Line<T>) -> Vec<Certificate> {
    let parts: Vec<String> = l.coords().iter().map(format_scalar).collect();
    let coords = format!("({})", parts.join(", "));
    prefixed(&format!("{name} l = {coords}: "), l.certify())
}

/// Blames a canal error on the parameter that controls it.
fn canal_err(e: CanalError, spine_param: &'static str, radius_param: &'static str) -> OpError {
    match &e {
        CanalError::NoRealEnvelope { .. }
        | CanalError::ZeroRadius
        | CanalError::SingularCanal { .. }
        | CanalError::CanalSelfIntersects { .. }
        | CanalError::CyclographicDiscsMeet { .. }
        | CanalError::CanalPartsNotApart { .. } => OpError::param(radius_param, e.to_string()),
        CanalError::DegenerateSpine(_) => OpError::param(spine_param, e.to_string()),
        _ => OpError::new(e.to_string()),
    }
}

/// The exact rational surface of a build, or an error naming the quadratic field.
fn rational_build<'a>(
    b: &'a CanalBuild,
    param: &'static str,
) -> Result<&'a CanalSurface<Rational>, OpError> {
    match b {
        CanalBuild::Rational(s) => Ok(s),
        CanalBuild::Extension { radicand, .. } => Err(OpError::param(
            param,
            format!(
                "|ṁ|² − ṙ² is not a sum of two squares over Q: the exact canal surface needs the field Q(√{}) (the library builds it there, rcagd::canal::canal_surface); recipes export rational geometry only — change the data so that the discriminant splits over Q (e.g. a PH spine for a pipe)",
                format_rational(radicand)
            ),
        )),
    }
}

fn orientation(args: &OpArgs) -> Result<Orientation, OpError> {
    Ok(match args.string("orientation")? {
        "negative" => Orientation::Negative,
        _ => Orientation::Positive,
    })
}

/// The largest number of halvings of [`positive_pieces`] in the circle direction (second
/// patch parameter) and in the spine direction: the limit the library's pole-free builder
/// assumes when it compares exported sizes.
const MAX_SPLITS: (usize, usize) = rcagd::canal::EXPORT_SPLITS;

/// Splits every patch with a Bernstein weight ≤ 0 at parameter 1/2 — first in the circle
/// direction (a characteristic circle over `u ∈ [−1, 1]` may cover more than a half circle,
/// whose quadratic Bézier form has a weight ≤ 0 in the middle), then along the spine — until
/// all weights are positive ([`split_patches_adaptive`]), and certifies the result: all
/// weights positive ⇒ the weight function has no zero on the patches (no pole, no base
/// point).
pub(super) fn positive_pieces<T: Scalar>(
    patches: Vec<BezierPatch<T>>,
    blame: Option<&'static str>,
) -> Result<(Vec<BezierPatch<T>>, Certificate), OpError> {
    let split = split_patches_adaptive(patches, SignRule::Positive, MAX_SPLITS)
        .map_err(|e| OpError::new(e.to_string()))?;
    let (out, bad) = (split.pieces, split.failed);
    let n = out.len();
    // one rule for a weight that is not positive on the whole domain (as for curves,
    // `rcagd_geom::weight_sign`): an input error naming the parameter that chose it
    // (the domain, a tangent magnitude), not a failing certificate
    if bad > 0 {
        let message = format!(
            "the surface's weight is not positive on the whole domain ({bad} of {n} pieces keep a weight ≤ 0 after {} + {} bisections): it passes through or near a point at infinity (a pole){}",
            MAX_SPLITS.0,
            MAX_SPLITS.1,
            blame.map_or(String::new(), |b| format!("; choose `{b}` so that the surface stays finite"))
        );
        return Err(match blame {
            Some(b) => OpError::param(b, message),
            None => OpError::new(message),
        });
    }
    let cert = Certificate::holds(
        format!("every Bernstein weight of the {n} patches is > 0 (the weight has no zero: no pole, no base point)"),
        T::EXACT,
    );
    Ok((out, cert))
}

fn canal_err_plain(e: CanalError) -> OpError {
    OpError::new(e.to_string())
}

/// The bidegree of a canal surface against its construction's bound
/// ([`rcagd::canal::degree_certificate`]).
fn degree_cert(s: &CanalSurface<Rational>) -> Certificate {
    rcagd::canal::degree_certificate(s)
}

// ----------------------------------------------------------------------------------------
// lines
// ----------------------------------------------------------------------------------------

const LINE_THROUGH_POINTS: OpSpec = OpSpec {
    name: "line_through_points",
    summary: "the line p ∧ q through two points in Plücker coordinates (given in the certificates) and the segment pq",
    params: &[
        ParamSpec::required("p", ParamKind::Point3, "first point"),
        ParamSpec::required("q", ParamKind::Point3, "second point, different from p"),
    ],
    example: r#"[[object]]
name = "line_pq"
op = "line_through_points"
p = [0, 1, 2]
q = [3, -1, 1]
"#,
    build: build_line_through_points::<Rational>,
};

/// A point parameter `[x, y, z]` in `T`.
fn point3_in<T: Scalar>(args: &OpArgs, param: &'static str) -> Result<[T; 3], OpError> {
    arith::point(args, param, &format!("`{param}` must be a point [x, y, z]"))
}

/// `line_through_points` in `T` (one builder for the exact op and the float path).
pub(crate) fn build_line_through_points<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (p, q) = (point3_in::<T>(args, "p")?, point3_in::<T>(args, "q")?);
    let l = Line::from_affine_points(&p, &q).map_err(|e| OpError::param("q", e.to_string()))?;
    let curve = segment(&affine(&p), &affine(&q))?;
    Ok(vec![arith::object::<T>(args, arith::curves(vec![curve])?, line_certs("line", &l))])
}

const LINE_OF_PLANES: OpSpec = OpSpec {
    name: "line_of_planes",
    summary: "the line u ∩ v of two planes (u₀ + u₁x + u₂y + u₃z = 0) in Plücker coordinates and a segment of it around the foot point of the origin",
    params: &[
        ParamSpec::required("u", ParamKind::Point, "first plane [u0, u1, u2, u3]"),
        ParamSpec::required("v", ParamKind::Point, "second plane [v0, v1, v2, v3], not parallel to u"),
        ParamSpec::with_default("extent", ParamKind::Number, "1", "the segment is F ± extent·d (F the point nearest to the origin, d = l₁₂₃ the direction), > 0"),
    ],
    example: r#"[[object]]
name = "line_uv"
op = "line_of_planes"
u = [-1, 1, 0, 0]
v = [-2, 0, 1, 1]
extent = "1/2"
"#,
    build: build_line_of_planes::<Rational>,
};

/// `line_of_planes` in `T`.
pub(crate) fn build_line_of_planes<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let u = vec4(args.point("u")?, "u", "a plane [u0, u1, u2, u3]")?;
    let v = vec4(args.point("v")?, "v", "a plane [v0, v1, v2, v3]")?;
    let extent = args.number("extent")?;
    if extent <= Rational::zero() {
        return Err(OpError::param("extent", "the extent must be positive"));
    }
    let (u, v): ([T; 4], [T; 4]) = (u.each_ref().map(arith::of), v.each_ref().map(arith::of));
    let extent: T = arith::of(&extent);
    let l = Line::from_planes(&u, &v).map_err(|e| OpError::param("v", e.to_string()))?;
    if l.is_at_infinity() {
        return Err(OpError::param(
            "v",
            "the planes are parallel: their line is at infinity (no segment)",
        ));
    }
    let d = l.direction();
    let m = l.moment();
    let dd = d.iter().fold(T::zero(), |a, x| a + x.clone() * x.clone());
    // foot point F = (d × m)/|d|²
    let f = [
        (d[1].clone() * m[2].clone() - d[2].clone() * m[1].clone()) / dd.clone(),
        (d[2].clone() * m[0].clone() - d[0].clone() * m[2].clone()) / dd.clone(),
        (d[0].clone() * m[1].clone() - d[1].clone() * m[0].clone()) / dd,
    ];
    let a: [T; 3] = core::array::from_fn(|i| f[i].clone() - extent.clone() * d[i].clone());
    let b: [T; 3] = core::array::from_fn(|i| f[i].clone() + extent.clone() * d[i].clone());
    let mut certs = line_certs("line", &l);
    for (name, x) in [("F − e·d", &a), ("F + e·d", &b)] {
        let h = affine(x);
        certs.push(Certificate::decide(
            format!("segment end {name} lies on the line: M(l)·X = 0 (Gruber (1.7))"),
            l.contains_point(&h),
            T::EXACT,
            || format_vector(x),
        ));
    }
    let curve = segment(&affine(&a), &affine(&b))?;
    Ok(vec![arith::object::<T>(args, arith::curves(vec![curve])?, certs)])
}

const COMMON_TRANSVERSALS: OpSpec = OpSpec {
    name: "common_transversals",
    summary: "the real common transversals of four lines (lines meeting all four, Gruber §1.1), as segments between their outermost meeting points",
    params: &[ParamSpec::required(
        "lines",
        ParamKind::Net,
        "four lines, each as two points: [[p, q], [p, q], [p, q], [p, q]]",
    )],
    example: r#"[[object]]
name = "transversals"
op = "common_transversals"
lines = [
  [[0, 0, 0], [1, 0, 0]],
  [[0, 0, 1], [0, 1, 1]],
  [[0, 1, 2], [1, 1, 2]],
  [[1, 0, 3], [1, 1, 3]],
]
"#,
    build: build_common_transversals::<Rational>,
};

/// The affine meeting points of `t` with `lines` (by the index of the line; a line met at
/// infinity or not met is left out).
fn meeting_points<T: Scalar>(t: &Line<T>, lines: &[Line<T>]) -> Vec<(usize, [T; 3])> {
    let mut pts = Vec::new();
    for (i, l) in lines.iter().enumerate() {
        if let Ok(x) = t.intersection(l) {
            if !x[0].is_zero() {
                let w = x[0].clone();
                pts.push((
                    i,
                    [x[1].clone() / w.clone(), x[2].clone() / w.clone(), x[3].clone() / w],
                ));
            }
        }
    }
    pts
}

/// The indices of the two given lines whose meeting points with `t` are farthest apart
/// (an exact comparison: the first pair of the largest distance), `None` if all meeting
/// points coincide or lie at infinity.
fn farthest_pair(t: &Line<Rational>, lines: &[Line<Rational>]) -> Option<(usize, usize)> {
    let pts = meeting_points(t, lines);
    let mut best: Option<(Rational, usize, usize)> = None;
    for i in 0..pts.len() {
        for j in i + 1..pts.len() {
            let d2 = (0..3).fold(Rational::zero(), |a, k| {
                let d = pts[i].1[k].clone() - pts[j].1[k].clone();
                a + d.clone() * d
            });
            if best.as_ref().is_none_or(|b| d2 > b.0) {
                best = Some((d2, pts[i].0, pts[j].0));
            }
        }
    }
    best.filter(|b| !b.0.is_zero()).map(|(_, i, j)| (i, j))
}

/// The segment of `t` between its meeting points with the lines of `pair` (the exact
/// farthest pair, [`farthest_pair`]); without a pair a unit piece along `t`.
fn transversal_segment<T: Scalar>(
    t: &Line<T>,
    lines: &[Line<T>],
    pair: Option<(usize, usize)>,
) -> Result<BezierCurve<T>, OpError> {
    let pts = meeting_points(t, lines);
    let at = |i: usize| pts.iter().find(|(k, _)| *k == i).map(|(_, p)| affine(p));
    match pair {
        Some((i, j)) => match (at(i), at(j)) {
            (Some(p), Some(q)) => segment(&p, &q),
            _ => Err(OpError::param(
                "lines",
                format!("the transversal meets line {i} or {j} at infinity in this arithmetic but not exactly (an ill-conditioned input): build it without --float"),
            )),
        },
        None => {
            // all meeting points coincide or lie at infinity: a unit piece along the direction
            let (p, q) = t.points();
            segment(&p, &q)
        }
    }
}

/// `Ω(g, h) = 0` for a pair (transversal, given line): exactly, or in `f64` to the
/// relative tolerance of `|g|·|h|` (largest coordinates, the scale of
/// [`Line::meets`]: a transversal's coordinates carry the rounding of the kernel and the
/// root, relative to the whole vector, so a sum of terms whose coordinates are 0 over Q
/// is no scale).
fn meets_cert<T: Scalar>(name: &str, g: &Line<T>, h: &Line<T>, hname: &str) -> Certificate {
    let w = g.reciprocal_product(h);
    let holds = if T::EXACT {
        w.is_zero()
    } else {
        let size = |l: &Line<T>| l.coords().iter().map(|x| x.to_f64().abs()).fold(0.0, f64::max);
        w.to_f64().abs() <= rcagd_geom::certify::F64_RELATIVE_TOLERANCE * size(g) * size(h)
    };
    Certificate::decide(
        format!("{name} meets {hname}: Ω(g, h) = 0 (Gruber (1.10))"),
        holds,
        T::EXACT,
        || format_scalar(&w),
    )
}

/// The exact transversals of the four lines as rational lines, or the exact op's refusal
/// (irrational, complex, infinitely many).
fn rational_transversals(
    res: CommonTransversals<Rational, QuadExt>,
) -> Result<Vec<Line<Rational>>, OpError> {
    match res {
        CommonTransversals::One(l) => Ok(vec![l]),
        CommonTransversals::Two(ls) => {
            let mut out = Vec::new();
            for l in &ls {
                let c: Option<Vec<Rational>> = l.coords().iter().map(QuadExt::to_rational).collect();
                let Some(c) = c else {
                    let d = l
                        .coords()
                        .iter()
                        .find(|x| !x.is_rational())
                        .map(|x| format_rational(x.d()))
                        .unwrap_or_default();
                    return Err(OpError::param(
                        "lines",
                        format!(
                            "the two real transversals are defined over Q(√{d}) only, not over Q (≈ ({})); recipes export rational geometry",
                            l.coords()
                                .iter()
                                .map(|x| format!("{:.6}", x.to_f64()))
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    ));
                };
                let arr: [Rational; 6] = core::array::from_fn(|k| c[k].clone());
                out.push(Line::from_coords(arr).map_err(|e| OpError::new(e.to_string()))?);
            }
            Ok(out)
        }
        CommonTransversals::ComplexPair { .. } => Err(OpError::param(
            "lines",
            "the four lines have no real common transversal (a conjugate complex pair)",
        )),
        CommonTransversals::Infinitely(_) => Err(OpError::param(
            "lines",
            "the four lines have infinitely many common transversals (they lie in one regulus or a special position)",
        )),
    }
}

/// `common_transversals` in `T`. The exact op decides everything on the exact lines;
/// `f64` takes the same decisions from the exact input — the kernel's pivot columns, the
/// number of transversals and the root formula ([`rcagd::lines::TransversalRoute`]),
/// rationality (the exact op's refusal of Q(√d)) and the farthest pair of meeting points —
/// and computes the transversals and their segments in `f64`.
pub(crate) fn build_common_transversals<T>(args: &OpArgs) -> Result<Vec<Object>, OpError>
where
    T: OpScalar + SqrtScalar,
    T::Ext: 'static,
{
    let exact_lines = lines_param::<Rational>(args, "lines", 4)?;
    let (res, route) = common_transversals_recorded([
        &exact_lines[0],
        &exact_lines[1],
        &exact_lines[2],
        &exact_lines[3],
    ])
        .map_err(|e| OpError::param("lines", e.to_string()))?;
    let exact = rational_transversals(res)?;
    let pairs: Vec<Option<(usize, usize)>> =
        exact.iter().map(|t| farthest_pair(t, &exact_lines)).collect();
    let (found, lines): (Vec<Line<T>>, Vec<Line<T>>) =
        match arith::same::<_, Vec<Line<T>>>(exact) {
            Ok(found) => (
                found,
                arith::same::<_, Vec<Line<T>>>(exact_lines)
                    .map_err(|_| OpError::new("the exact lines are exact"))?,
            ),
            Err(_) => {
                let lines = lines_param::<T>(args, "lines", 4)?;
                let res = common_transversals_along([&lines[0], &lines[1], &lines[2], &lines[3]], &route)
                    .map_err(|e| OpError::param("lines", e.to_string()))?;
                let back = |l: &Line<T::Ext>| -> Option<Line<T>> {
                    let c: Vec<T> = l
                        .coords()
                        .iter()
                        .map(|x| Scalar::to_rational(x).map(|q| T::from_rational(&q)))
                        .collect::<Option<_>>()?;
                    Line::from_coords(core::array::from_fn(|k| c[k].clone())).ok()
                };
                let found = match res {
                    CommonTransversals::One(l) => vec![l],
                    CommonTransversals::Two(ls) => ls
                        .iter()
                        .map(back)
                        .collect::<Option<Vec<_>>>()
                        .ok_or_else(|| {
                            OpError::param("lines", "the f64 construction produced a non-finite transversal (an ill-conditioned input): build it without --float")
                        })?,
                    _ => {
                        return Err(OpError::new(
                            "the replayed exact decisions gave no real transversal (not the exact input)",
                        ))
                    }
                };
                (found, lines)
            }
        };
    let mut certs = Vec::new();
    let mut curves = Vec::new();
    for (k, (t, pair)) in found.iter().zip(pairs).enumerate() {
        let name = format!("transversal {k}");
        certs.extend(line_certs(&name, t));
        for (i, l) in lines.iter().enumerate() {
            certs.push(meets_cert(&name, t, l, &format!("line {i}")));
        }
        curves.push(transversal_segment(t, &lines, pair)?);
    }
    Ok(vec![arith::object::<T>(args, arith::curves(curves)?, certs)])
}

const REGULUS: OpSpec = OpSpec {
    name: "regulus",
    summary: "the regulus through three pairwise skew lines a, b, c as a bilinear rational patch of its carrier quadric (rulings: transversals from a to c)",
    params: &[ParamSpec::required(
        "lines",
        ParamKind::Net,
        "three pairwise skew lines, each as two points: [[p, q], [p, q], [p, q]]; the patch spans the segment pq of the first line",
    )],
    example: r#"[[object]]
name = "hyperboloid_piece"
op = "regulus"
lines = [
  [[1, 0, 0], [1, 2, 2]],
  [[-1, -1, 1], [-1, 1, -1]],
  [[-1, 1, 1], [1, 1, -1]],
]
"#,
    build: build_regulus::<Rational>,
};

/// `regulus` in `T`.
pub(crate) fn build_regulus<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let net = args.net("lines")?;
    let lines = lines_param::<T>(args, "lines", 3)?;
    let reg = Regulus::from_lines(&lines[0], &lines[1], &lines[2])
        .map_err(|e| OpError::param("lines", e.to_string()))?;
    // P(s) on a between the given points; Q(s) = c ∩ plane(P(s), b), linear in s
    let pa: Vec<[T; 4]> = net
        .first()
        .map(|r| {
            r.iter()
                .map(|p| {
                    let a: [T; 3] = core::array::from_fn(|k| p.get(k).map_or_else(T::zero, arith::of));
                    affine(&a)
                })
                .collect()
        })
        .unwrap_or_default();
    let (Some(p0), Some(p1)) = (pa.first(), pa.get(1)) else {
        return Err(OpError::param("lines", "the first line needs two points"));
    };
    let patch = reg.segment_patch(p0, p1).map_err(|e| match e {
        RegulusPatchError::Geom(g) => OpError::new(g.to_string()),
        e => OpError::param("lines", e.to_string()),
    })?;
    let mut certs = prefixed("regulus: ", reg.certify());
    certs.extend(reg.segment_patch_certificates(&patch));
    Ok(vec![arith::object::<T>(args, arith::patches(vec![patch])?, certs)])
}

// ----------------------------------------------------------------------------------------
// canal surfaces
// ----------------------------------------------------------------------------------------

const ORIENTATION: ParamSpec = ParamSpec::with_default(
    "orientation",
    ParamKind::Choice(&["positive", "negative"]),
    "\"positive\"",
    "envelope the oriented family (m; r) or (m; −r): the same surface with the opposite unit normal and the other choice of rational parametrization",
);

const CANAL_SURFACE: OpSpec = OpSpec {
    name: "canal_surface",
    summary: "the rational canal surface (envelope of spheres) of a rational spine and a polynomial radius on t ∈ [0, 1], exact over Q, by Peternell–Pottmann (Gruber §2.1) or Krasauskas' reduced pencil (§2.4), by default whichever exports with fewer control points; no local self-intersection and that no two characteristic discs meet (no global self-intersection) are certified exactly",
    params: &[
        ParamSpec::required("points", ParamKind::Points, "control points [x, y, z] of the spine m(t), t ∈ [0, 1]").degree(),
        ParamSpec::optional("weights", ParamKind::Numbers, "spine weights (default all 1)"),
        ParamSpec::required("radius", ParamKind::Numbers, "Bernstein control values of the radius r(t) (any degree)").degree(),
        ORIENTATION,
        METHOD,
        ParamSpec::optional(
            "cyclographic_domain",
            ParamKind::Numbers,
            "[s0, s1, t0, t1]: when |ṁ|² − ṙ² splits only over Q(√d) and the family is polynomial of degree ≤ 2, the surface is built over Q by the cyclographic parametrization Γ(s, t) of Gruber §2.3 on this rectangle of Ω(s, t) = (2s, 2t, 1 − s² − t², 1 + s² + t²) (not a spine interval); no local self-intersection on the rectangle is certified exactly, and no global one (no two characteristic discs over the spine parameters the rectangle reaches meet); a rectangle where the surface is singular is refused at a point of it, one whose far parts meet at the radius with the two spine-parameter intervals and an exact witness pair",
        ),
    ],
    example: r#"[[object]]
name = "canal_parabola"
op = "canal_surface"
points = [[0, 0, 0], [0, 2, 0], [4, 4, 0]]
radius = ["1/2", "81/50"]
"#,
    build: build_canal_surface,
};

fn spine_curve(args: &OpArgs) -> Result<BezierCurve<Rational>, OpError> {
    let pts = args.points("points")?;
    if pts.iter().any(|p| p.len() != 3) {
        return Err(OpError::param("points", "spine control points must be [x, y, z]"));
    }
    let weights = args
        .opt_numbers("weights")?
        .unwrap_or_else(|| vec![Rational::one(); pts.len()]);
    if weights.len() != pts.len() {
        return Err(OpError::param(
            "weights",
            format!("{} control points but {} weights", pts.len(), weights.len()),
        ));
    }
    if let Some(i) = weights.iter().position(|w| *w <= Rational::zero()) {
        return Err(OpError::param(
            "weights",
            format!("weight {i} is not positive: the spine would have a pole on [0, 1]"),
        ));
    }
    let hom: Vec<Vec<Rational>> = pts
        .iter()
        .zip(&weights)
        .map(|(p, w)| {
            let mut h = vec![w.clone()];
            h.extend(p.iter().map(|x| x * w));
            h
        })
        .collect();
    BezierCurve::from_homogeneous(hom).map_err(|e| OpError::param("points", e.to_string()))
}

/// The surface patches on the domain and the certificates of a rational canal build.
fn canal_object(
    args: &OpArgs,
    s: &CanalSurface<Rational>,
    extra: Vec<Certificate>,
) -> Result<Object, OpError> {
    let (patches, wcert) = positive_pieces(s.domain_patches().map_err(canal_err_plain)?, None)?;
    let mut certs = s.certify();
    certs.push(degree_cert(s));
    certs.push(wcert);
    certs.extend(extra);
    Ok(args.object(Geometry::Patches(patches), certs))
}

fn build_canal_surface(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let spine = spine_curve(args)?;
    let radius = args.opt_numbers("radius")?.unwrap_or_default();
    if radius.is_empty() {
        return Err(OpError::param("radius", "give at least one radius control value"));
    }
    let rc = BezierCurve::from_homogeneous(
        radius
            .iter()
            .map(|r| vec![Rational::one(), r.clone()])
            .collect(),
    )
    .map_err(|e| OpError::param("radius", e.to_string()))?;
    let family = CanalSpine::from_spine_and_radius(&spine, &rc)
        .map_err(|e| canal_err(e, "points", "radius"))?;
    let method = match args.string("method")? {
        "peternell-pottmann" => Method::PeternellPottmann,
        "krasauskas" => Method::Krasauskas,
        _ => Method::Lowest,
    };
    let options = CanalOptions {
        orientation: orientation(args)?,
        domain: Some((Rational::zero(), Rational::one())),
        method,
        ..CanalOptions::default()
    };
    let dom = match args.opt_numbers("cyclographic_domain")? {
        None => None,
        Some(d) => Some(<[Rational; 4]>::try_from(d.clone()).map_err(|_| {
            OpError::param(
                "cyclographic_domain",
                format!("four numbers [s0, s1, t0, t1], got {}", d.len()),
            )
        })?),
    };
    let built = canal_surface_rational(&family, &options, dom.as_ref()).map_err(|e| match e {
        CanalError::IrrationalSplit { .. }
        | CanalError::CyclographicDomainNeeded { .. }
        | CanalError::ZeroRadius => OpError::param("radius", e.to_string()),
        CanalError::InvalidArgument(_) | CanalError::SingularCyclographic { .. }
            if dom.is_some() =>
        {
            OpError::param("cyclographic_domain", e.to_string())
        }
        e => canal_err(e, "points", "radius"),
    })?;
    match built {
        RationalCanal::Spine(s, regular) => Ok(vec![canal_object(args, &s, regular)?]),
        RationalCanal::Cyclographic(c) => Ok(vec![args.object(
            Geometry::Patches(c.patches().to_vec()),
            c.certify(),
        )]),
    }
}

const METHOD: ParamSpec = ParamSpec::with_default(
    "method",
    ParamKind::Choice(&["lowest", "peternell-pottmann", "krasauskas"]),
    "\"lowest\"",
    "the construction: \"lowest\" builds both and keeps the one with fewer control points once split into pieces with positive weights (on a tie the lower bidegree), or exactly the one named (Krasauskas' pencil is built over Q only)",
);

const CANAL_CHAIN: OpSpec = OpSpec {
    name: "canal_chain",
    summary: "the rational canal surface along a chain of spine pieces, each a rational Bézier curve with its own polynomial radius on t ∈ [0, 1], joined end to start with the same sphere, tangent direction and r·dr/dσ (checked exactly; a corner or a jump is refused naming the joint), exact over Q piece by piece; per piece no local self-intersection, and that no two characteristic discs anywhere on the chain meet (across the joints and, when the last end joins the first start so, through the seam) are certified exactly",
    params: &[
        ParamSpec::required("pieces", ParamKind::Net, "one row per spine piece: its control points [x, y, z] (every piece of one degree; the last point of a row is the first of the next)").degree(),
        ParamSpec::optional("weights", ParamKind::Grid, "one row of spine weights per piece (default all 1)"),
        ParamSpec::required("radius", ParamKind::Grid, "one row per piece: the Bernstein control values of its radius r(t) (every row of one length)").degree(),
        ORIENTATION,
        METHOD,
    ],
    example: r#"[[object]]
name = "canal_chain_cubic"
op = "canal_chain"
pieces = [[["403/600", 4, "1/4"], ["-1193/1800", "20/9", "7/36"], ["-877/1080", "28/27", "5/36"], ["-9173/16200", "4/9", "1/12"]], [["-9173/16200", "4/9", "1/12"], ["-5191/16200", "-4/27", "1/36"], ["5191/16200", "-4/27", "-1/36"], ["9173/16200", "4/9", "-1/12"]], [["9173/16200", "4/9", "-1/12"], ["877/1080", "28/27", "-5/36"], ["1193/1800", "20/9", "-7/36"], ["-403/600", 4, "-1/4"]]]
radius = [["7/20", "1/4"], ["1/4", "3/20"], ["3/20", "1/20"]]
"#,
    build: build_canal_chain,
};

/// The canal family of one piece of `canal_chain`: the spine of control points `pts` with
/// `weights` and the polynomial radius of Bernstein values `radius`.
fn chain_piece(
    k: usize,
    pts: &[Vec<Rational>],
    weights: Option<&Vec<Rational>>,
    radius: &[Rational],
) -> Result<CanalSpine<Rational>, OpError> {
    let at = |param: &'static str, msg: String| OpError::param(param, format!("spine piece {k} (counted from 0): {msg}"));
    if pts.iter().any(|p| p.len() != 3) {
        return Err(at("pieces", "spine control points must be [x, y, z]".into()));
    }
    let ones = vec![Rational::one(); pts.len()];
    let w = weights.unwrap_or(&ones);
    if w.len() != pts.len() {
        return Err(at("weights", format!("{} control points but {} weights", pts.len(), w.len())));
    }
    if let Some(i) = w.iter().position(|w| *w <= Rational::zero()) {
        return Err(at("weights", format!("weight {i} is not positive: the spine would have a pole on [0, 1]")));
    }
    if radius.is_empty() {
        return Err(at("radius", "give at least one radius control value".into()));
    }
    let hom: Vec<Vec<Rational>> = pts
        .iter()
        .zip(w)
        .map(|(p, w)| {
            let mut h = vec![w.clone()];
            h.extend(p.iter().map(|x| x * w));
            h
        })
        .collect();
    let spine = BezierCurve::from_homogeneous(hom).map_err(|e| at("pieces", e.to_string()))?;
    let rc = BezierCurve::from_homogeneous(
        radius.iter().map(|r| vec![Rational::one(), r.clone()]).collect(),
    )
    .map_err(|e| at("radius", e.to_string()))?;
    CanalSpine::from_spine_and_radius(&spine, &rc).map_err(|e| {
        let o = canal_err(e, "pieces", "radius");
        OpError {
            message: format!("spine piece {k} (counted from 0): {}", o.message),
            ..o
        }
    })
}

/// Blames an error of [`canal_chain_rational`] on the parameter that controls it.
fn chain_err(e: CanalError) -> OpError {
    match e {
        CanalError::SpinePiece { index, source } => {
            let inner = chain_err(*source);
            OpError {
                message: format!("spine piece {index} (counted from 0): {}", inner.message),
                ..inner
            }
        }
        // a joint where the radius or its slope jumps (the library names the joint)
        CanalError::InvalidArgument(_) => OpError::param("radius", e.to_string()),
        CanalError::IrrationalSplit { .. } => OpError::param("radius", e.to_string()),
        e => canal_err(e, "pieces", "radius"),
    }
}

fn build_canal_chain(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let net = args.net("pieces")?;
    let radius = args.opt_grid("radius")?.unwrap_or_default();
    if radius.len() != net.len() {
        return Err(OpError::param(
            "radius",
            format!("{} spine pieces but {} rows of radius values", net.len(), radius.len()),
        ));
    }
    let weights = args.opt_grid("weights")?;
    if let Some(w) = &weights {
        if w.len() != net.len() {
            return Err(OpError::param(
                "weights",
                format!("{} spine pieces but {} rows of weights", net.len(), w.len()),
            ));
        }
    }
    let (zero, one) = (Rational::zero(), Rational::one());
    let chain = net
        .iter()
        .enumerate()
        .map(|(k, pts)| {
            let w = weights.as_ref().and_then(|w| w.get(k));
            Ok((chain_piece(k, pts, w, &radius[k])?, (zero.clone(), one.clone())))
        })
        .collect::<Result<Vec<_>, OpError>>()?;
    let method = match args.string("method")? {
        "peternell-pottmann" => Method::PeternellPottmann,
        "krasauskas" => Method::Krasauskas,
        _ => Method::Lowest,
    };
    let options = CanalOptions {
        orientation: orientation(args)?,
        method,
        ..CanalOptions::default()
    };
    let built = canal_chain_rational(&chain, &options).map_err(chain_err)?;
    let mut patches = Vec::new();
    let mut certs = Vec::new();
    for (k, s) in built.pieces.iter().enumerate() {
        let (p, wcert) = positive_pieces(s.domain_patches().map_err(canal_err_plain)?, None)?;
        patches.extend(p);
        certs.extend(prefixed(&format!("spine piece {k}: "), vec![degree_cert(s), wcert]));
    }
    certs.extend(built.certify());
    Ok(vec![args
        .object(Geometry::Patches(patches), certs)
        .with_values(vec![rcagd_io::quantity::NamedQuantity::new(
            SPINE_CLOSED,
            "the chain's last end joins its first start with the same sphere, tangent direction and r·dr/dσ: the canal surface is a closed tube",
            rcagd_io::quantity::Quantity::Bool(built.closed),
        )])])
}

const PIPE_PH: OpSpec = OpSpec {
    name: "pipe_ph",
    summary: "the exact rational pipe surface of constant radius around a spatial PH curve in quaternion form, t ∈ [0, 1]: every exact construction (split D = σ² and the Gaussian splits, Peternell–Pottmann and Krasauskas, every frame, interval splits) is tried and the smallest with positive weights kept; r·κ < 1 and that no two normal discs of radius |r| meet are certified",
    params: &[
        ParamSpec::required("coefficients", ParamKind::Points, "Bernstein coefficients A₀ … A_m of the quaternion preimage, each [a, b, c, d] = a + b i + c j + d k (curve degree 2m + 1)").degree(),
        ParamSpec::with_default("start", ParamKind::Point3, "[0, 0, 0]", "start point r(0)"),
        ParamSpec::required("radius", ParamKind::Number, "pipe radius, ≠ 0"),
        ORIENTATION,
    ],
    example: r#"[[object]]
name = "pipe_ph_quintic"
op = "pipe_ph"
coefficients = [[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]]
radius = "1/8"
"#,
    build: build_pipe_ph,
};

fn build_pipe_ph(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let coeffs = args
        .points("coefficients")?
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            let [a, b, c, d] = vec4(p, "coefficients", &format!("quaternion A_{i}"))?;
            Ok(Quaternion::new(a, b, c, d))
        })
        .collect::<Result<Vec<_>, OpError>>()?;
    let curve = PhCurve::new(coeffs, point3(args, "start")?)
        .map_err(|e| OpError::param("coefficients", e.to_string()))?;
    let radius = args.number("radius")?;
    let (zero, one) = (Rational::zero(), Rational::one());
    let s = pipe_around_ph_exportable(&curve, &radius, (&zero, &one), orientation(args)?)
        .map_err(|e| pipe_err(e, "coefficients"))?;
    let mut certs = s.certify();
    certs.extend(prefixed("spine: ", curve.certify()));
    Ok(vec![args.object(Geometry::Patches(s.patches()), certs)])
}

/// Blames a pipe error on the parameter that controls it.
fn pipe_err(e: CanalError, spine_param: &'static str) -> OpError {
    let e = match e {
        CanalError::SpinePiece { index, source } => {
            let inner = pipe_err(*source, spine_param);
            return OpError {
                message: format!("spine piece {index} (counted from 0): {}", inner.message),
                ..inner
            };
        }
        e => e,
    };
    match e {
        CanalError::InvalidArgument(_)
        | CanalError::RadiusNotBelowCurvatureRadius { .. }
        | CanalError::TubePartsNotApart { .. }
        | CanalError::PipeSelfIntersects { .. } => {
            OpError::param("radius", e.to_string())
        }
        CanalError::IrrationalSplit { .. }
        | CanalError::NeedsLargerExtension(_)
        | CanalError::ZeroTangent { .. }
        | CanalError::SpineApproximation(_) => OpError::param(spine_param, e.to_string()),
        other => canal_err(other, spine_param, "radius"),
    }
}

const PIPE: OpSpec = OpSpec {
    name: "pipe",
    summary: "the pipe surface of constant radius around a rational spine on t ∈ [0, 1] (control points, or every curve of a STEP, IGES or exact JSON file chained end to end, each piece on t ∈ [0, 1]), exact over Q when |m'|² is a sum of two rational squares (planar and PH spines always); the smallest exact construction with positive weights is kept; r·κ < 1 and that no two normal discs of radius |r| meet (no self-intersection) are certified",
    params: &[
        ParamSpec::optional("points", ParamKind::Points, "control points [x, y, z] of the spine (or give spine_file)").degree(),
        ParamSpec::optional("weights", ParamKind::Numbers, "spine weights (default all 1)"),
        ParamSpec::optional("spine_file", ParamKind::String, "a STEP (.step, .stp), IGES (.igs, .iges) or rcagd JSON (.json) file whose curves form the spine (a relative path is taken relative to the recipe's directory; instead of points)"),
        ParamSpec::required("radius", ParamKind::Number, "pipe radius, ≠ 0, below the spine's least radius of curvature"),
        ORIENTATION,
        ParamSpec::with_default("approximate", ParamKind::Choice(&["auto", "never", "always"]), "\"auto\"", "auto: exact around the spine where |m'|² is a sum of two rational squares, else exact around a G¹ spline of PH quintics within a certified distance (tolerance) of the spine; never: exact around the spine or an error; always: around the PH spline"),
        ParamSpec::optional("tolerance", ParamKind::Number, "the largest distance allowed between the PH spline and the spine (default 10⁻⁶ of the diagonal of the spine's control-point box); certified").tolerance(),
    ],
    example: r#"[[object]]
name = "pipe_quarter_circle"
op = "pipe"
points = [[1, 0, 0], [1, 1, 0], [0, 1, 0]]
weights = [1, 1, 2]
radius = "1/5"
"#,
    build: build_pipe,
};

fn approximation_policy(args: &OpArgs) -> Result<ApproximationPolicy, OpError> {
    match args.string("approximate")? {
        "auto" => Ok(ApproximationPolicy::Auto),
        "never" => Ok(ApproximationPolicy::Never),
        _ => Ok(ApproximationPolicy::Always),
    }
}

fn build_pipe(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let radius = args.number("radius")?;
    let orient = orientation(args)?;
    let policy = approximation_policy(args)?;
    let tolerance = match args.get("tolerance") {
        Some(_) => Some(args.number("tolerance")?),
        None => None,
    };
    let (spines, spine_param) = if let Some(file) = args.path("spine_file") {
        if args.get("points").is_some() {
            return Err(OpError::param(
                "spine_file",
                "give either points or spine_file, not both",
            ));
        }
        let spines = match crate::gallery::embedded_input(&file).filter(|_| !file.exists()) {
            // the gallery's own input, compiled in (the gallery builds anywhere)
            Some(text) => rcagd_io::spine::SpineFormat::of_path(&file)
                .ok_or_else(|| OpError::param("spine_file", "unknown spine file extension"))
                .and_then(|format| {
                    rcagd_io::spine::spine_from_text(text, format, None)
                        .map_err(|e| OpError::param("spine_file", e.to_string()))
                })?,
            None => rcagd_io::spine::read_spine(&file)
                .map_err(|e| OpError::param("spine_file", e.to_string()))?,
        };
        (spines, "spine_file")
    } else {
        if args.get("points").is_none() {
            return Err(OpError::new("give the spine as points or as spine_file"));
        }
        (vec![spine_curve(args)?], "points")
    };
    let pipe = pipe_along_spine(&spines, &radius, orient, policy, tolerance.as_ref())
        .map_err(|e| match e {
            CanalError::SpineApproximation(PhError::ToleranceNotMet(_)) | CanalError::SpineApproximation(PhError::OutOfRange(_)) if tolerance.is_some() => {
                OpError::param("tolerance", e.to_string())
            }
            e => pipe_err(e, spine_param),
        })?;
    // whether the spine closes with G¹ (a closed tube), decided exactly by the library;
    // the closure check (crate::closure) reads it for both `points` and `spine_file`
    let closed = rcagd::canal::chain_is_g1_closed(&spines);
    Ok(vec![args
        .object(Geometry::Patches(pipe.patches()), pipe.certify())
        .with_values(vec![rcagd_io::quantity::NamedQuantity::new(
            SPINE_CLOSED,
            "the spine ends where it starts with the same tangent direction (G¹): the pipe is a closed tube",
            rcagd_io::quantity::Quantity::Bool(closed),
        )])])
}

/// The name of the `pipe` op's value saying whether its spine is `G¹`-closed.
pub const SPINE_CLOSED: &str = "spine_closed";

const BLEND_PARAMS_SPHERE0: [ParamSpec; 4] = [
    ParamSpec::required("center0", ParamKind::Point3, "centre of the first sphere"),
    ParamSpec::required("radius0", ParamKind::Number, "radius of the first sphere (signed: the orientation)"),
    ParamSpec::required("normal0", ParamKind::Point3, "normal n₀ of the contact plane (y − c₀)·n₀ = h₀; also the spine direction leaving the sphere"),
    ParamSpec::with_default("offset0", ParamKind::Number, "0", "h₀, with h₀² < r₀²|n₀|² (a real contact circle)"),
];

const CANAL_BLEND_SPHERES: OpSpec = OpSpec {
    name: "canal_blend_spheres",
    summary: "a canal-surface blend between two spheres touching each along a prescribed circle (cubic Hermite spine/radius in R^{3,1}, t ∈ [0, 1]), exact over Q",
    params: &[
        BLEND_PARAMS_SPHERE0[0],
        BLEND_PARAMS_SPHERE0[1],
        BLEND_PARAMS_SPHERE0[2],
        BLEND_PARAMS_SPHERE0[3],
        ParamSpec::required("center1", ParamKind::Point3, "centre of the second sphere"),
        ParamSpec::required("radius1", ParamKind::Number, "radius of the second sphere"),
        ParamSpec::required("normal1", ParamKind::Point3, "normal of its contact plane; the spine direction arriving there"),
        ParamSpec::with_default("offset1", ParamKind::Number, "0", "h₁ of the second contact plane"),
        ParamSpec::optional("lambda0", ParamKind::Number, "tangent magnitude at the start, ≠ 0 (default ≈ chord/|n₀|); a negative value reverses the spine's tangent there (the sphere family starts in the opposite direction): built when the patches stay pole-free, else refused at `lambda0` (weight not positive) — the rule of every canal blend"),
        ParamSpec::optional("lambda1", ParamKind::Number, "tangent magnitude at the end, ≠ 0 (default ≈ chord/|n₁|); negative: reversed tangent, same rule as `lambda0`"),
    ],
    example: r#"[[object]]
name = "blend_two_spheres"
op = "canal_blend_spheres"
center0 = [0, 0, 0]
radius0 = 1
normal0 = ["29/10", "14/5", 0]
offset0 = "1/2"
center1 = ["21/10", "11/5", 0]
radius1 = "1/2"
normal1 = ["29/10", "14/5", 0]
offset1 = "1/4"
lambda0 = 1
lambda1 = 1
"#,
    build: build_blend_spheres,
};

fn blend_end(args: &OpArgs, k: usize) -> Result<BlendEnd<Rational>, OpError> {
    let names: [[&'static str; 4]; 2] = [
        ["center0", "radius0", "normal0", "offset0"],
        ["center1", "radius1", "normal1", "offset1"],
    ];
    let n = names.get(k).ok_or_else(|| OpError::new("internal: blend end index"))?;
    BlendEnd::new(
        point3(args, n[0])?,
        args.number(n[1])?,
        point3(args, n[2])?,
        args.number(n[3])?,
    )
    .map_err(|e| {
        let m = e.to_string();
        // a zero normal is the normal's fault; the rest (the plane misses the sphere) the offset's
        OpError::param(if m.contains("normal must be non-zero") { n[2] } else { n[3] }, m)
    })
}

fn blend_spine(args: &OpArgs) -> Result<BlendSpine<Rational>, OpError> {
    Ok(match (args.opt_number("lambda0")?, args.opt_number("lambda1")?) {
        (None, None) => BlendSpine::Default,
        (l0, l1) => {
            let l0 = l0.unwrap_or_else(Rational::one);
            let l1 = l1.unwrap_or_else(Rational::one);
            if l0.is_zero() {
                return Err(OpError::param("lambda0", "λ₀ must be non-zero"));
            }
            if l1.is_zero() {
                return Err(OpError::param("lambda1", "λ₁ must be non-zero"));
            }
            BlendSpine::Hermite {
                lambda0: l0,
                lambda1: l1,
            }
        }
    })
}

fn build_blend_spheres(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let a = blend_end(args, 0)?;
    let b = blend_end(args, 1)?;
    let blend = blend_spheres(&a, &b, &blend_spine(args)?)
        .map_err(|e| canal_err(e, "center1", "lambda0"))?;
    let s = rational_build(&blend.build, "lambda0")?;
    let (patches, wcert) = positive_pieces(s.domain_patches().map_err(canal_err_plain)?, Some("lambda0"))?;
    let mut certs = blend.certify();
    certs.push(degree_cert(s));
    certs.push(wcert);
    Ok(vec![args.object(Geometry::Patches(patches), certs)])
}

const CANAL_BLEND_SPHERE_PLANE: OpSpec = OpSpec {
    name: "canal_blend_sphere_plane",
    summary: "a canal-surface blend between a sphere (prescribed contact circle) and a plane (prescribed circle in it), by a Möbius inversion of a sphere–sphere blend, exact over Q when the inverted family's |ṁ|² − ṙ² splits over Q (e.g. when the inverted blend is a cone: the example)",
    params: &[
        BLEND_PARAMS_SPHERE0[0],
        BLEND_PARAMS_SPHERE0[1],
        BLEND_PARAMS_SPHERE0[2],
        BLEND_PARAMS_SPHERE0[3],
        ParamSpec::required("plane_normal", ParamKind::Point3, "normal n of the plane n·y = e; |n| must be rational"),
        ParamSpec::required("plane_offset", ParamKind::Number, "e of the plane n·y = e"),
        ParamSpec::required("circle_center", ParamKind::Point3, "centre of the contact circle, on the plane"),
        ParamSpec::required("circle_radius", ParamKind::Number, "radius of the contact circle, > 0"),
        ParamSpec::optional("lambda0", ParamKind::Number, "tangent magnitude at the sphere (inverted space), ≠ 0; a negative value reverses the inverted spine's tangent there (the sphere family starts in the opposite direction): built when the patches stay pole-free, else refused at `lambda0` (weight not positive) — the rule of `canal_blend_spheres`"),
        ParamSpec::optional("lambda1", ParamKind::Number, "tangent magnitude at the plane (inverted space), ≠ 0; negative: reversed tangent, same rule as `lambda0`"),
    ],
    example: r#"[[object]]
name = "blend_sphere_plane"
op = "canal_blend_sphere_plane"
center0 = [0, 0, 5]
radius0 = -2
normal0 = [0, 0, -1]
offset0 = 0
plane_normal = [0, 0, 1]
plane_offset = 0
circle_center = [0, 0, 0]
circle_radius = 3
lambda0 = 2
lambda1 = "2/3"
"#,
    build: build_blend_sphere_plane,
};

fn build_blend_sphere_plane(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let a = blend_end(args, 0)?;
    let plane = PlaneEnd {
        normal: point3(args, "plane_normal")?,
        offset: args.number("plane_offset")?,
        center: point3(args, "circle_center")?,
        radius: args.number("circle_radius")?,
    };
    let blend = blend_sphere_plane(&a, &plane, &blend_spine(args)?).map_err(|e| match e {
        CanalError::InvalidArgument(ref m) if m.contains("contact circle radius") => {
            OpError::param("circle_radius", e.to_string())
        }
        CanalError::InvalidArgument(_) => OpError::param("plane_normal", e.to_string()),
        other => canal_err(other, "center0", "lambda0"),
    })?;
    let patches = blend.rational_patches().map_err(|e| match e {
        CanalError::IrrationalSplit { .. } => OpError::param(
            "lambda0",
            "the blend needs a quadratic field Q(√d) (|ṁ|² − ṙ² of the inverted family is no sum of two rational squares); recipes export rational geometry — try other λ₀, λ₁",
        ),
        other => OpError::new(other.to_string()),
    })?;
    let (patches, wcert) = positive_pieces(patches, Some("lambda0"))?;
    let mut certs = blend.certify();
    certs.push(wcert);
    Ok(vec![args.object(Geometry::Patches(patches), certs)])
}

const CANAL_NORMAL_FIELD: OpSpec = OpSpec {
    name: "canal_surface_normal_field",
    summary: "the canal surface of a polynomial spine and radius from a rational unit normal field n₀(t) on its circles of normals (Gruber (2.10) with a given rational point on every circle instead of a split of |ṁ|² − ṙ²): n = n₀ − 2⟨n₀, v⟩ v/|v|², x = m + r n, v = e₁ + u e₂ ⊥ ṁ",
    params: &[
        ParamSpec::required(
            "spine",
            ParamKind::Points,
            "power coefficients [x, y, z] of the spine m(t) = Σ spine[k] tᵏ",
        ).degree(),
        ParamSpec::required(
            "radius",
            ParamKind::Numbers,
            "power coefficients of the radius r(t) = Σ radius[k] tᵏ",
        ).degree(),
        ParamSpec::required(
            "normal",
            ParamKind::Points,
            "power coefficients [x, y, z] of the numerator N(t) of the normal field n₀ = N/d; needs |N|² ≡ d² and ⟨N, ṁ⟩ + d ṙ ≡ 0",
        ).degree(),
        ParamSpec::with_default(
            "denominator",
            ParamKind::Numbers,
            "[1]",
            "power coefficients of the denominator d(t) of the normal field",
        ).degree(),
        ParamSpec::with_default(
            "domain",
            ParamKind::Numbers,
            "[0, 1, -1, 1]",
            "parameter rectangle [t0, t1, u0, u1] (t along the spine, u along the characteristic circles)",
        ),
    ],
    example: r#"[[object]]
name = "canal_normal_field_parabola"
op = "canal_surface_normal_field"
# m(t) = (t, t²/2, 0), r(t) = t: ṁ = (1, t, 0), ṙ = 1, and n₀ = (−1, 0, 0) is a unit normal
# on every circle of normals (⟨n₀, ṁ⟩ + ṙ = 0); |ṁ|² − ṙ² = t² is a square, the field is
# given directly instead
spine = [[0, 0, 0], [1, 0, 0], [0, "1/2", 0]]
radius = [0, 1]
normal = [[-1, 0, 0]]
domain = ["1/4", 1, -1, 1]
"#,
    build: build_canal_normal_field::<Rational>,
};

/// `canal_surface_normal_field` in `T` (one builder for the exact op and the float path:
/// the normal field is the user's, so the construction takes no exact-only decision; the
/// axis of `e₁ = ṁ × a` is the first with a non-zero cross product, which is the same in
/// `f64` because that product only permutes the exact input's coefficients).
pub(crate) fn build_canal_normal_field<T: super::arith::OpScalar>(
    args: &OpArgs,
) -> Result<Vec<Object>, OpError> {
    let spine = args.points("spine")?;
    let normal = args.points("normal")?;
    for (name, pts) in [("spine", &spine), ("normal", &normal)] {
        if pts.iter().any(|p| p.len() != 3) {
            return Err(OpError::param(
                name,
                format!("`{name}` holds power coefficients [x, y, z]"),
            ));
        }
    }
    let radius = args.opt_numbers("radius")?.unwrap_or_default();
    if radius.is_empty() {
        return Err(OpError::param("radius", "give at least one radius coefficient"));
    }
    let den = args
        .opt_numbers("denominator")?
        .unwrap_or_else(|| vec![Rational::one()]);
    let dom = args.opt_numbers("domain")?.unwrap_or_default();
    let [t0, t1, u0, u1] = <[Rational; 4]>::try_from(dom.clone()).map_err(|_| {
        OpError::param(
            "domain",
            format!("four numbers [t0, t1, u0, u1], got {}", dom.len()),
        )
    })?;
    let conv = poly_io::poly_in::<T>;
    let [sx, sy, sz] = poly_io::coordinate_polys(&spine);
    let family = CanalSpine::polynomial(
        [conv(&sx), conv(&sy), conv(&sz)],
        conv(&poly_io::poly(radius)),
    );
    let [nx, ny, nz] = poly_io::coordinate_polys(&normal);
    let n = [conv(&nx), conv(&ny), conv(&nz)];
    let d = conv(&poly_io::poly(den));
    let built = rcagd::canal::canal_surface_from_normal_field(&family, &n, &d).map_err(|e| {
        let m = e.to_string();
        if m.contains("denominator") {
            OpError::param("denominator", m)
        } else if m.contains("ṁ ≡ 0") {
            OpError::param("spine", m)
        } else {
            OpError::param("normal", m)
        }
    })?;
    let of = |q: &Rational| T::from_rational(q);
    let patch = built
        .patch((of(&t0), of(&t1)), (of(&u0), of(&u1)))
        .map_err(|e| OpError::param("domain", e.to_string()))?;
    let (patches, wcert) = positive_pieces(vec![patch], Some("domain"))?;
    let mut certs = built.certify();
    certs.push(wcert);
    Ok(vec![super::arith::object::<T>(
        args,
        Geometry::Patches(super::arith::exact_patches(patches)?),
        certs,
    )])
}

const TORUS: OpSpec = OpSpec {
    name: "torus",
    summary: "a ring torus (axis ∥ z): the canal surface of the circle of radius R with constant radius ρ, as the Dupin cyclide of an untilted pe circle (rcagd::cyclide::DupinCyclide::tilted with s = 0): 16 biquadratic patches with positive weights, one closed shell, implicit quartic (|x − c|² + R² − ρ²)² − 4R²((x − c₁)² + (y − c₂)²) certified",
    params: &[
        ParamSpec::with_default("center", ParamKind::Point3, "[0, 0, 0]", "centre"),
        ParamSpec::required("major_radius", ParamKind::Number, "radius R of the spine circle, > 0"),
        ParamSpec::required("minor_radius", ParamKind::Number, "tube radius ρ, 0 < ρ < R"),
    ],
    example: r#"[[object]]
name = "ring_torus"
op = "torus"
major_radius = 2
minor_radius = "1/2"
"#,
    build: build_torus::<Rational>,
};

/// `torus` in `T` (one builder for the exact op and the float path).
pub(crate) fn build_torus<T: super::arith::OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let c = point3(args, "center")?.each_ref().map(super::arith::of::<T>);
    let big = args.number("major_radius")?;
    let rho = args.number("minor_radius")?;
    if big <= Rational::zero() {
        return Err(OpError::param("major_radius", "R must be positive"));
    }
    if rho <= Rational::zero() || rho >= big {
        return Err(OpError::param(
            "minor_radius",
            format!(
                "a ring torus needs 0 < ρ < R = {}, got ρ = {}",
                format_rational(&big),
                format_rational(&rho)
            ),
        ));
    }
    // the torus is the Dupin cyclide of the untilted pe circle (s = 0): spine circle of
    // radius R, constant radius ρ; one global parametrization, so the 16 patches share
    // their edges exactly and the surface is one closed shell
    let cy = rcagd::cyclide::DupinCyclide::tilted(c, super::arith::of::<T>(&big), super::arith::of::<T>(&rho), T::zero()).map_err(|e| OpError::new(e.to_string()))?;
    let patches = cy.covering_patches().map_err(|e| OpError::new(e.to_string()))?;
    super::cyclide::cyclide_object(args, &cy, patches, Vec::new())
}

const DUPIN_CANAL: OpSpec = OpSpec {
    name: "dupin_canal",
    summary: "a Dupin cyclide as the canal surface of a pe-circle of R^{3,1}: spine (ρ cos θ, ρ a sin θ, 0), radius r₀ + ρ b sin θ with a = (1 + s²)/(1 − s²), b = 2s/(1 − s²) (rcagd::cyclide::DupinCyclide::tilted; 16 biquadratic patches)",
    params: &[
        ParamSpec::with_default("center", ParamKind::Point3, "[0, 0, 0]", "centre"),
        ParamSpec::required("rho", ParamKind::Number, "ρ ≠ 0 (size of the pe-circle)"),
        ParamSpec::required("r0", ParamKind::Number, "radius of the middle sphere r₀"),
        ParamSpec::with_default("s", ParamKind::Number, "\"1/3\"", "tilt of the pe-circle, |s| < 1 (s = 1/3: a = 5/4, b = 3/4; s = 0: a torus)"),
    ],
    example: r#"[[object]]
name = "dupin_cyclide"
op = "dupin_canal"
rho = 2
r0 = 3
s = "1/3"
"#,
    build: build_dupin_canal::<Rational>,
};

/// `dupin_canal` in `T`.
pub(crate) fn build_dupin_canal<T: super::arith::OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let c = point3(args, "center")?.each_ref().map(super::arith::of::<T>);
    let rho = super::arith::number::<T>(args, "rho")?;
    let r0 = super::arith::number::<T>(args, "r0")?;
    let s = super::arith::number::<T>(args, "s")?;
    let cy = rcagd::cyclide::DupinCyclide::tilted(c, rho, r0, s).map_err(|e| match e {
        rcagd::cyclide::CyclideError::IsotropicTangents(m) => OpError::param("s", m),
        rcagd::cyclide::CyclideError::ZeroRadius(m) => OpError::param("rho", m),
        e => OpError::new(e.to_string()),
    })?;
    let patches = cy.covering_patches().map_err(|e| OpError::new(e.to_string()))?;
    super::cyclide::cyclide_object(args, &cy, patches, Vec::new())
}
