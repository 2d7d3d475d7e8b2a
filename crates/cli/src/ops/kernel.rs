//! Kernel ops: exact circles, arcs and cylinder patches (`rcagd::conic`,
//! `rcagd::cylinder`), and inline rational Bézier curves and patches given by their
//! control points.

use super::arith::{self, OpScalar};
use super::{prefixed, OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use num_traits::{One, Zero};
use rcagd_algebra::rational::format_rational;
use rcagd_algebra::format_scalar;
use rcagd_algebra::{Certificate, Rational};
use rcagd::{full_circle, CircleArcs, Certified, CylinderPatch};
use rcagd_geom::certify::curves_agree;
use rcagd_geom::{BezierCurve, BezierPatch};

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[
    CIRCLE_ARC,
    CIRCLE,
    CYLINDER_PATCH,
    BEZIER_CURVE,
    BEZIER_PATCH,
    DEGREE_ELEVATE,
    SUBDIVIDE,
];

const CENTER: ParamSpec = ParamSpec::with_default(
    "center",
    ParamKind::Point2,
    "[0, 0]",
    "centre of the circle",
);
const RADIUS: ParamSpec = ParamSpec::required("radius", ParamKind::Number, "radius, > 0");
const FROM: ParamSpec = ParamSpec::required(
    "from",
    ParamKind::Point2,
    "start point, exactly on the circle (|from − center|² = radius²)",
);
const TO: ParamSpec = ParamSpec::required(
    "to",
    ParamKind::Point2,
    "end point, exactly on the circle, different from `from`",
);

const CIRCLE_ARC: OpSpec = OpSpec {
    name: "circle_arc",
    summary: "an exact rational arc of a circle between two rational points on it (one quadratic piece per < 180°)",
    params: &[
        CENTER,
        RADIUS,
        FROM,
        TO,
        ParamSpec::with_default(
            "clockwise",
            ParamKind::Bool,
            "false",
            "run clockwise from `from` to `to` (default counter-clockwise)",
        ),
    ],
    example: r#"[[object]]
name = "arc_3_4_5"
op = "circle_arc"
center = [0, 0]
radius = 5
from = [5, 0]
to = [3, 4]
"#,
    build: build_circle_arc::<Rational>,
};

const CIRCLE: OpSpec = OpSpec {
    name: "circle",
    summary: "a full circle as four exact rational quadratic quarter arcs",
    params: &[CENTER, RADIUS],
    example: r#"[[object]]
name = "unit_circle"
op = "circle"
center = [0, 0]
radius = 1
"#,
    build: build_circle::<Rational>,
};

const CYLINDER_PATCH: OpSpec = OpSpec {
    name: "cylinder_patch",
    summary: "rational biquadratic patches exactly on a circular cylinder (axis parallel to z) over an arc, between two heights",
    params: &[
        CENTER,
        RADIUS,
        FROM,
        TO,
        ParamSpec::required("z0", ParamKind::Number, "lower height"),
        ParamSpec::required("z1", ParamKind::Number, "upper height, > z0"),
    ],
    example: r#"[[object]]
name = "quarter_cylinder"
op = "cylinder_patch"
radius = 2
from = [2, 0]
to = [0, 2]
z0 = 0
z1 = 3
"#,
    build: build_cylinder_patch::<Rational>,
};

/// A declared `Point2` parameter as an array in `T`.
fn point2<T: OpScalar>(args: &OpArgs, param: &'static str) -> Result<[T; 2], OpError> {
    arith::point(args, param, &format!("internal error: `{param}` is not a 2D point"))
}

fn arcs<T: OpScalar>(args: &OpArgs, clockwise: bool) -> Result<CircleArcs<T>, OpError> {
    Ok(CircleArcs::new(
        point2(args, "center")?,
        arith::number(args, "radius")?,
        point2(args, "from")?,
        point2(args, "to")?,
        clockwise,
    )?)
}

/// `circle_arc` in `T` (one builder for the exact op and the float path).
pub(crate) fn build_circle_arc<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let arcs = arcs::<T>(args, args.bool("clockwise")?)?;
    let certs = arcs.certify();
    let geometry = arith::curves(arcs.into_curves())?;
    Ok(vec![arith::object::<T>(args, geometry, certs)])
}

/// `circle` in `T`.
pub(crate) fn build_circle<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let circle = full_circle(point2::<T>(args, "center")?, arith::number(args, "radius")?)?;
    let certs = circle.certify();
    let curves = arith::exact_curves(circle.into_curves())?;
    Ok(vec![arith::object::<T>(args, Geometry::Curves(curves), certs)])
}

/// `cylinder_patch` in `T`.
pub(crate) fn build_cylinder_patch<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let z0 = args.number("z0")?;
    let z1 = args.number("z1")?;
    if z0 >= z1 {
        return Err(OpError::param(
            "z1",
            format!(
                "the heights must satisfy z0 < z1, got z0 = {}, z1 = {}",
                format_rational(&z0),
                format_rational(&z1)
            ),
        ));
    }
    let arcs = arcs::<T>(args, false)?;
    let (z0, z1) = (arith::of::<T>(&z0), arith::of::<T>(&z1));
    let many = arcs.pieces().len() > 1;
    let mut certs = Vec::new();
    if many {
        certs.extend(prefixed("base arc: ", arcs.certify()));
    }
    let mut patches = Vec::with_capacity(arcs.pieces().len());
    for (k, arc) in arcs.pieces().iter().enumerate() {
        let p = CylinderPatch::from_arc(arc.clone(), z0.clone(), z1.clone())?;
        if many {
            certs.extend(prefixed(&format!("patch {k}: "), p.certify()));
        } else {
            certs.extend(p.certify());
        }
        patches.push(p.into_patch());
    }
    Ok(vec![arith::object::<T>(args, arith::patches(patches)?, certs)])
}

const POINTS_DOC: &str =
    "control points [x, y, …] (with `homogeneous = true`: [w, w·x, w·y, …], weight first)";

const BEZIER_CURVE: OpSpec = OpSpec {
    name: "bezier_curve",
    summary: "a rational Bézier curve from its control points and weights; one control point, or all control points equal, is accepted: the object is a point (a constant curve or patch of the given degree; STEP and IGES refuse degree 0) — the one rule of bezier_curve, bezier_patch and quadric_curve_image",
    params: &INLINE_CURVE_PARAMS,
    example: r#"[[object]]
name = "quarter_circle"
op = "bezier_curve"
points = [[1, 0], [1, 1], [0, 1]]
weights = [1, 1, 2]
"#,
    build: build_bezier_curve::<Rational>,
};

const INLINE_CURVE_PARAMS: [ParamSpec; 3] = [
    ParamSpec::required("points", ParamKind::Points, POINTS_DOC).degree(),
    ParamSpec::optional(
        "weights",
        ParamKind::Numbers,
        "one weight per control point (default: all 1, a polynomial curve)",
    ),
    ParamSpec::with_default(
        "homogeneous",
        ParamKind::Bool,
        "false",
        "the points are homogeneous (weight first); then `weights` must be absent",
    ),
];

const DEGREE_ELEVATE: OpSpec = OpSpec {
    name: "degree_elevate",
    summary: "the same rational curve in a higher degree (degree elevation of an inline curve)",
    params: &[
        INLINE_CURVE_PARAMS[0],
        INLINE_CURVE_PARAMS[1],
        INLINE_CURVE_PARAMS[2],
        ParamSpec::with_default("by", ParamKind::Int, "1", "degree increase, 1 to 32").degree(),
    ],
    example: r#"[[object]]
name = "quarter_circle_cubic"
op = "degree_elevate"
points = [[1, 0], [1, 1], [0, 1]]
weights = [1, 1, 2]
by = 1
"#,
    build: build_degree_elevate::<Rational>,
};

const SUBDIVIDE: OpSpec = OpSpec {
    name: "subdivide",
    summary: "an inline rational curve split at a parameter into two pieces (de Casteljau)",
    params: &[
        INLINE_CURVE_PARAMS[0],
        INLINE_CURVE_PARAMS[1],
        INLINE_CURVE_PARAMS[2],
        ParamSpec::with_default("at", ParamKind::Number, "\"1/2\"", "the parameter to split at, 0 < at < 1"),
    ],
    example: r#"[[object]]
name = "cubic_halves"
op = "subdivide"
points = [[0, 0], [1, 2], [3, 2], [4, 0]]
at = "1/3"
"#,
    build: build_subdivide::<Rational>,
};

const BEZIER_PATCH: OpSpec = OpSpec {
    name: "bezier_patch",
    summary: "a rational tensor-product Bézier patch from its control net and weights; one control point, or all control points equal, is accepted: the object is a point (a constant curve or patch of the given degree; STEP and IGES refuse degree 0) — the one rule of bezier_curve, bezier_patch and quadric_curve_image",
    params: &[
        ParamSpec::required(
            "net",
            ParamKind::Net,
            "control net: rows of control points, row i along u, entry j along v (with `homogeneous = true`: weight first)",
        ).degree(),
        ParamSpec::optional(
            "weights",
            ParamKind::Grid,
            "one weight per control point, rows like `net` (default: all 1)",
        ),
        ParamSpec::with_default(
            "homogeneous",
            ParamKind::Bool,
            "false",
            "the points are homogeneous (weight first); then `weights` must be absent",
        ),
    ],
    example: r#"[[object]]
name = "saddle"
op = "bezier_patch"
net = [
  [[0, 0, 0], [1, 0, "1/2"], [2, 0, 0]],
  [[0, 1, "1/2"], [1, 1, 0], [2, 1, "1/2"]],
  [[0, 2, 0], [1, 2, "1/2"], [2, 2, 0]],
]
weights = [[1, 1, 1], [1, 2, 1], [1, 1, 1]]
"#,
    build: build_bezier_patch::<Rational>,
};

/// The homogeneous point `(w, w·p)` of a Euclidean point `p` with weight `w ≠ 0`.
pub(super) fn homogenize(p: &[Rational], w: &Rational) -> Vec<Rational> {
    let mut h = Vec::with_capacity(p.len() + 1);
    h.push(w.clone());
    h.extend(p.iter().map(|x| x * w));
    h
}

/// Homogeneous control points from the `points`/`weights`/`homogeneous` parameters.
pub(super) fn homogeneous_points(
    points: Vec<Vec<Rational>>,
    weights: Option<Vec<Rational>>,
    homogeneous: bool,
    label: impl Fn(usize) -> String,
) -> Result<Vec<Vec<Rational>>, OpError> {
    if homogeneous {
        if weights.is_some() {
            return Err(OpError::param(
                "weights",
                "give the weights either in `weights` or as the first coordinate of homogeneous points, not both",
            ));
        }
        if let Some(i) = points.iter().position(|p| p.len() < 2) {
            return Err(OpError::param(
                "points",
                format!(
                    "homogeneous {} needs a weight and at least one coordinate",
                    label(i)
                ),
            ));
        }
        return Ok(points);
    }
    let weights = weights.unwrap_or_else(|| vec![Rational::one(); points.len()]);
    if weights.len() != points.len() {
        return Err(OpError::param(
            "weights",
            format!(
                "{} control points but {} weights",
                points.len(),
                weights.len()
            ),
        ));
    }
    if let Some(i) = weights.iter().position(Zero::is_zero) {
        return Err(OpError::param(
            "weights",
            format!(
                "the weight of {} is zero: a Euclidean point cannot have weight 0 (use homogeneous = true for points at infinity)",
                label(i)
            ),
        ));
    }
    Ok(points
        .iter()
        .zip(&weights)
        .map(|(p, w)| homogenize(p, w))
        .collect())
}

/// The certificate that a patch has no pole on `[0, 1]²` ([`OpScalar::patch_pole_free`]:
/// weights of one sign, or (mixed signs, exact) pieces of one sign after at most 5 + 5
/// bisections ([`rcagd_geom::weight_sign::split_patches_adaptive`]); otherwise an input
/// error on `param`.
fn patch_pole_certificate<T: OpScalar>(patch: &BezierPatch<T>, param: &'static str) -> Result<Certificate, OpError> {
    T::patch_pole_free(patch).ok_or_else(|| {
        OpError::param(
            param,
            if T::EXACT {
                "weights of mixed sign whose weight function Σ wᵢⱼ Bᵢ Bⱼ could not be shown to be non-zero on [0, 1]² (5 bisections per direction): the patch passes through or near points at infinity"
            } else {
                arith::MIXED_SIGNS_IN_F64
            },
        )
    })
}

/// The inline curve of the `points` / `weights` / `homogeneous` parameters (the products
/// `w·x` are formed exactly, then converted to `T` once).
fn inline_curve<T: OpScalar>(args: &OpArgs) -> Result<BezierCurve<T>, OpError> {
    let hom = homogeneous_points(
        args.points("points")?,
        args.opt_numbers("weights")?,
        args.bool("homogeneous")?,
        |i| format!("control point {i}"),
    )?;
    let hom: Vec<Vec<T>> = hom.iter().map(|p| arith::all_of(p)).collect();
    BezierCurve::from_homogeneous(hom).map_err(|e| OpError::param("points", e.to_string()))
}

/// The inline curve and its certificate of having no pole on `[0, 1]`
/// ([`rcagd_geom::weight_sign::curve_pole_free`]: the same rule for every op that takes
/// a user's weights; mixed signs are refused in `f64`); a weight function with a zero
/// there is an input error.
fn inline_curve_pole_free<T: OpScalar>(args: &OpArgs) -> Result<(BezierCurve<T>, Certificate), OpError> {
    let curve = inline_curve::<T>(args)?;
    let param = if args.bool("homogeneous")? { "points" } else { "weights" };
    let cert = T::curve_pole_free(&curve).map_err(|e| match e {
        Some(zeros) => OpError::param(param, zeros.to_string()),
        None => OpError::param(param, arith::MIXED_SIGNS_IN_F64),
    })?;
    Ok((curve, cert))
}

/// `bezier_curve` in `T`.
pub(crate) fn build_bezier_curve<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (curve, cert) = inline_curve_pole_free::<T>(args)?;
    Ok(vec![arith::object::<T>(args, Geometry::Curve(T::exact_curve(curve)?), vec![cert])])
}

/// The largest degree increase of `degree_elevate`.
const MAX_ELEVATION: i64 = 32;

/// `degree_elevate` in `T`.
pub(crate) fn build_degree_elevate<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (curve, pole_cert) = inline_curve_pole_free::<T>(args)?;
    let by = args.int("by")?;
    let r = usize::try_from(by)
        .ok()
        .filter(|r| (1..=MAX_ELEVATION as usize).contains(r))
        .ok_or_else(|| {
            OpError::param(
                "by",
                format!("the degree increase must be between 1 and {MAX_ELEVATION}, got {by}"),
            )
        })?;
    let elevated = curve.elevate(r);
    let mut certs = vec![curves_agree(&curve, &elevated)?];
    certs.push(pole_cert);
    Ok(vec![arith::object::<T>(args, Geometry::Curve(T::exact_curve(elevated)?), certs)])
}

/// `subdivide` in `T`.
pub(crate) fn build_subdivide<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (curve, pole_cert) = inline_curve_pole_free::<T>(args)?;
    let at = args.number("at")?;
    if at <= Rational::zero() || at >= Rational::one() {
        return Err(OpError::param(
            "at",
            format!("the subdivision parameter must satisfy 0 < at < 1, got {}", format_rational(&at)),
        ));
    }
    let at = arith::of::<T>(&at);
    let (left, right) = curve.subdivide(&at)?;
    // Cross-check de Casteljau against the blossom-based affine reparametrization.
    let mut certs = vec![pole_cert];
    let restricted_left = curve.restrict(&T::zero(), &at)?;
    let restricted_right = curve.restrict(&at, &T::one())?;
    certs.extend(prefixed(
        &format!("left piece = P on [0, {}]: ", format_scalar(&at)),
        vec![curves_agree(&left, &restricted_left)?],
    ));
    certs.extend(prefixed(
        &format!("right piece = P on [{}, 1]: ", format_scalar(&at)),
        vec![curves_agree(&right, &restricted_right)?],
    ));
    let joined = left.control_points().last() == right.control_points().next();
    certs.push(Certificate::decide(
        "left(1) = right(0): the pieces join (equal homogeneous end points)",
        joined,
        T::EXACT,
        || "the end points differ".to_string(),
    ));
    let geometry = Geometry::Curves(arith::exact_curves(vec![left, right])?);
    Ok(vec![arith::object::<T>(args, geometry, certs)])
}

/// `bezier_patch` in `T`.
pub(crate) fn build_bezier_patch<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let net = args.net("net")?;
    let weights = args.opt_grid("weights")?;
    let homogeneous = args.bool("homogeneous")?;
    if let Some(w) = &weights {
        let cols = net.first().map_or(0, Vec::len);
        if w.len() != net.len() || w.iter().any(|r| r.len() != cols) {
            return Err(OpError::param(
                "weights",
                format!(
                    "the net has {} rows of {cols} points, the weights do not have the same shape",
                    net.len()
                ),
            ));
        }
    }
    let mut rows = Vec::with_capacity(net.len());
    for (i, row) in net.into_iter().enumerate() {
        let w = weights.as_ref().and_then(|w| w.get(i)).cloned();
        let row = homogeneous_points(row, w, homogeneous, |j| {
            format!("control point ({i}, {j})")
        })
        .map_err(|mut e| {
            if e.param == Some("points") {
                e.param = Some("net");
            }
            e
        })?;
        rows.push(row.iter().map(|p| arith::all_of::<T>(p)).collect::<Vec<_>>());
    }
    let patch = BezierPatch::from_homogeneous(rows).map_err(|e| OpError::param("net", e.to_string()))?;
    let param = if homogeneous { "net" } else { "weights" };
    let cert = patch_pole_certificate(&patch, param)?;
    Ok(vec![arith::object::<T>(args, Geometry::Patch(T::exact_patch(patch)?), vec![cert])])
}
