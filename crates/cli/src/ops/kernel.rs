//! Kernel ops: exact circles, arcs and cylinder patches (`rcagd::conic`,
//! `rcagd::cylinder`), and inline rational Bézier curves and patches given by their
//! control points.

use super::{prefixed, OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use num_traits::{One, Zero};
use rcagd_algebra::rational::format_rational;
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
    build: build_circle_arc,
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
    build: build_circle,
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
    build: build_cylinder_patch,
};

/// A declared `Point2` parameter as an array.
fn point2(args: &OpArgs, param: &'static str) -> Result<[Rational; 2], OpError> {
    let p = args.point(param)?;
    <[Rational; 2]>::try_from(p).map_err(|_| {
        OpError::param(param, format!("internal error: `{param}` is not a 2D point"))
    })
}

fn build_circle_arc(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let arcs = CircleArcs::new(
        point2(args, "center")?,
        args.number("radius")?,
        point2(args, "from")?,
        point2(args, "to")?,
        args.bool("clockwise")?,
    )?;
    let certs = arcs.certify();
    let mut curves = arcs.into_curves();
    let geometry = if curves.len() == 1 {
        Geometry::Curve(curves.remove(0))
    } else {
        Geometry::Curves(curves)
    };
    Ok(vec![args.object(geometry, certs)])
}

fn build_circle(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let circle = full_circle(point2(args, "center")?, args.number("radius")?)?;
    let certs = circle.certify();
    Ok(vec![args.object(Geometry::Curves(circle.into_curves()), certs)])
}

fn build_cylinder_patch(args: &OpArgs) -> Result<Vec<Object>, OpError> {
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
    let arcs = CircleArcs::new(
        point2(args, "center")?,
        args.number("radius")?,
        point2(args, "from")?,
        point2(args, "to")?,
        false,
    )?;
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
    let geometry = if patches.len() == 1 {
        Geometry::Patch(patches.remove(0))
    } else {
        Geometry::Patches(patches)
    };
    Ok(vec![args.object(geometry, certs)])
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
    build: build_bezier_curve,
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
    build: build_degree_elevate,
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
    build: build_subdivide,
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
    build: build_bezier_patch,
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

/// The certificate that a patch has no pole on `[0, 1]²`: weights of one sign, or (mixed
/// signs) pieces of one sign after at most 5 + 5 bisections
/// ([`rcagd_geom::weight_sign::split_patches_adaptive`]); otherwise an input error on
/// `param`.
fn patch_pole_certificate(patch: &BezierPatch<Rational>, param: &'static str) -> Result<Certificate, OpError> {
    rcagd_geom::weight_sign::patch_pole_free(patch).ok_or_else(|| {
        OpError::param(
            param,
            "weights of mixed sign whose weight function Σ wᵢⱼ Bᵢ Bⱼ could not be shown to be non-zero on [0, 1]² (5 bisections per direction): the patch passes through or near points at infinity",
        )
    })
}

/// The inline curve of the `points` / `weights` / `homogeneous` parameters.
fn inline_curve(args: &OpArgs) -> Result<BezierCurve<Rational>, OpError> {
    let hom = homogeneous_points(
        args.points("points")?,
        args.opt_numbers("weights")?,
        args.bool("homogeneous")?,
        |i| format!("control point {i}"),
    )?;
    BezierCurve::from_homogeneous(hom).map_err(|e| OpError::param("points", e.to_string()))
}

/// The inline curve and its certificate of having no pole on `[0, 1]`
/// ([`rcagd_geom::weight_sign::curve_pole_free`]: the same rule for every op that takes
/// a user's weights); a weight function with a zero there is an input error.
fn inline_curve_pole_free(args: &OpArgs) -> Result<(BezierCurve<Rational>, Certificate), OpError> {
    let curve = inline_curve(args)?;
    let param = if args.bool("homogeneous")? { "points" } else { "weights" };
    let cert = rcagd_geom::weight_sign::curve_pole_free(&curve).map_err(|e| OpError::param(param, e.to_string()))?;
    Ok((curve, cert))
}

fn build_bezier_curve(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (curve, cert) = inline_curve_pole_free(args)?;
    Ok(vec![args.object(Geometry::Curve(curve), vec![cert])])
}

/// The largest degree increase of `degree_elevate`.
const MAX_ELEVATION: i64 = 32;

fn build_degree_elevate(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (curve, pole_cert) = inline_curve_pole_free(args)?;
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
    Ok(vec![args.object(Geometry::Curve(elevated), certs)])
}

fn build_subdivide(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (curve, pole_cert) = inline_curve_pole_free(args)?;
    let at = args.number("at")?;
    if at <= Rational::zero() || at >= Rational::one() {
        return Err(OpError::param(
            "at",
            format!("the subdivision parameter must satisfy 0 < at < 1, got {}", format_rational(&at)),
        ));
    }
    let (left, right) = curve.subdivide(&at)?;
    // Cross-check de Casteljau against the blossom-based affine reparametrization.
    let mut certs = vec![pole_cert];
    let restricted_left = curve.restrict(&Rational::zero(), &at)?;
    let restricted_right = curve.restrict(&at, &Rational::one())?;
    certs.extend(prefixed(
        &format!("left piece = P on [0, {}]: ", format_rational(&at)),
        vec![curves_agree(&left, &restricted_left)?],
    ));
    certs.extend(prefixed(
        &format!("right piece = P on [{}, 1]: ", format_rational(&at)),
        vec![curves_agree(&right, &restricted_right)?],
    ));
    let joined = left.control_points().last() == right.control_points().next();
    certs.push(Certificate::decide(
        "left(1) = right(0): the pieces join (equal homogeneous end points)",
        joined,
        true,
        || "the end points differ".to_string(),
    ));
    Ok(vec![args.object(Geometry::Curves(vec![left, right]), certs)])
}

fn build_bezier_patch(args: &OpArgs) -> Result<Vec<Object>, OpError> {
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
        rows.push(homogeneous_points(row, w, homogeneous, |j| {
            format!("control point ({i}, {j})")
        })
        .map_err(|mut e| {
            if e.param == Some("points") {
                e.param = Some("net");
            }
            e
        })?);
    }
    let patch = BezierPatch::from_homogeneous(rows).map_err(|e| OpError::param("net", e.to_string()))?;
    let param = if homogeneous { "net" } else { "weights" };
    let cert = patch_pole_certificate(&patch, param)?;
    Ok(vec![args.object(Geometry::Patch(patch), vec![cert])])
}
