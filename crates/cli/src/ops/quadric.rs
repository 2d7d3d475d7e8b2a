//! Quadric ops (`rcagd::quadric`, Jüttler): rational curves and patches exactly on the
//! sphere and on any quadric with a rational point, by the generalized stereographic
//! projection — interpolation, images of Bézier curves and patches, biquadratic patches
//! from a Miquel configuration, and an exact cover of the whole sphere.
//!
//! Every op takes the same quadric parameters: `quadric` (a name, default the unit sphere
//! with Jüttler's δ; `"hyperbolic_paraboloid_xy"` (z = xy, formerly `"seed_paraboloid"`,
//! still accepted) uses Jüttler's ψ; every other quadric its
//! rational normal form `B∘N_{a,e}`), `coefficients` (the named quadric's numbers),
//! `matrix` (a symmetric 4×4 matrix, with `quadric = "matrix"`) and `rational_point`.

use super::arith::{self, OpScalar};
use super::{prefixed, OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use num_traits::{One, Zero};
use rcagd::quadric::interpolation::{HermiteDatum, Interpolant};
use rcagd::quadric::{
    curve_image, interpolate_hermite, interpolate_hermite_along, interpolate_lowest_degree,
    interpolation_route, patch_image, sphere_cover,
    BiquadraticPatch, Delta, GeneralizedProjection, Hom, Psi, Quadric, QuadricError,
};
use rcagd::Certified;
use rcagd_algebra::rational::format_rational;
use rcagd_algebra::{Certificate, Rational};
use rcagd_geom::weight_sign::SignRule;
use rcagd_geom::{BezierCurve, BezierPatch};
use rcagd_io::quantity::{NamedQuantity, Quantity};

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[
    QUADRIC_INTERPOLATE,
    QUADRIC_CURVE_IMAGE,
    QUADRIC_PATCH_IMAGE,
    QUADRIC_MIQUEL_PATCH,
    SPHERE_COVER,
];

/// The quadric names of the `quadric` parameter.
const QUADRIC_NAMES: &[&str] = &[
    "unit_sphere",
    "sphere",
    "ellipsoid",
    "hyperboloid_one_sheet",
    "hyperboloid_two_sheets",
    "elliptic_paraboloid",
    "hyperbolic_paraboloid",
    "hyperbolic_paraboloid_xy",
    "seed_paraboloid",
    "cone",
    "elliptic_cylinder",
    "hyperbolic_cylinder",
    "parabolic_cylinder",
    "matrix",
];

pub(super) const QUADRIC: ParamSpec = ParamSpec::with_default(
    "quadric",
    ParamKind::Choice(QUADRIC_NAMES),
    "\"unit_sphere\"",
    "the quadric: unit_sphere (Jüttler's δ), hyperbolic_paraboloid_xy z = xy, i.e. h0h3 = h1h2 (Jüttler's ψ; \"seed_paraboloid\" is a deprecated alias), a named quadric with `coefficients`, or \"matrix\"",
);
pub(super) const COEFFICIENTS: ParamSpec = ParamSpec::with_default(
    "coefficients",
    ParamKind::Numbers,
    "[]",
    "the named quadric's numbers: sphere [cx, cy, cz, r]; ellipsoid, hyperboloids, cone [a, b, c]; paraboloids, elliptic/hyperbolic cylinder [a, b]; parabolic_cylinder [a]",
);
pub(super) const MATRIX: ParamSpec = ParamSpec::optional(
    "matrix",
    ParamKind::Grid,
    "with quadric = \"matrix\": the symmetric 4×4 matrix Q of Xᵀ Q X = 0, X = (w, x, y, z)",
);
pub(super) const RATIONAL_POINT: ParamSpec = ParamSpec::optional(
    "rational_point",
    ParamKind::Point,
    "a rational point of the quadric, [x, y, z] or homogeneous [w, x, y, z] (default: the named quadric's, or one found exactly)",
);

const POINTS_DOC: &str = "points on the quadric, [x, y, z] or homogeneous [w, w·x, w·y, w·z]";

const QUADRIC_INTERPOLATE: OpSpec = OpSpec {
    name: "quadric_interpolate",
    summary: "a rational curve exactly on a quadric (default the unit sphere) through given points, optionally with tangents, of the lowest possible degree (Jüttler §2: a linear problem)",
    params: &[
        ParamSpec::required("points", ParamKind::Points, POINTS_DOC).degree(),
        ParamSpec::optional(
            "params",
            ParamKind::Numbers,
            "one parameter per point, pairwise distinct (default 0, 1/(N−1), …, 1)",
        ),
        ParamSpec::optional(
            "tangents",
            ParamKind::Points,
            "one tangent direction [vx, vy, vz] per point, in the tangent plane there; [0, 0, 0] for none. The curve touches the tangent line; whether it runs along or against v is returned as the value `tangent_senses`",
        ),
        ParamSpec::optional(
            "degree",
            ParamKind::Int,
            "the preimage degree n (the curve has degree 2n); default the lowest that works",
        ).degree(),
        QUADRIC,
        COEFFICIENTS,
        MATRIX,
        RATIONAL_POINT,
    ],
    example: r#"[[object]]
name = "spherical_quartic"
op = "quadric_interpolate"
points = [[1, 0, 0], [0, 1, 0], [0, 0, 1], ["3/5", 0, "-4/5"], ["2/3", "-2/3", "1/3"]]
"#,
    build: build_interpolate::<Rational>,
};

const CURVE_DOC: &str =
    "control points [x, y, z] of the preimage curve in 3-space (with `homogeneous = true`: [w, w·x, w·y, w·z])";

const QUADRIC_CURVE_IMAGE: OpSpec = OpSpec {
    name: "quadric_curve_image",
    summary: "the image of a rational Bézier curve of degree n under the generalized stereographic projection: a curve of degree 2n exactly on the quadric; one control point, or all control points equal, is accepted: the object is a point (a constant curve or patch of the given degree; STEP and IGES refuse degree 0) — the one rule of bezier_curve, bezier_patch and quadric_curve_image",
    params: &[
        ParamSpec::required("points", ParamKind::Points, CURVE_DOC).degree(),
        ParamSpec::optional("weights", ParamKind::Numbers, "one weight per control point (default all 1)"),
        ParamSpec::with_default(
            "homogeneous",
            ParamKind::Bool,
            "false",
            "the points are homogeneous (weight first); then `weights` must be absent",
        ),
        QUADRIC,
        COEFFICIENTS,
        MATRIX,
        RATIONAL_POINT,
    ],
    example: r#"[[object]]
name = "delta_of_a_cubic"
op = "quadric_curve_image"
points = [[0, 0, 0], [1, 2, 0], [2, -1, 1], [3, 1, 2]]
"#,
    build: build_curve_image::<Rational>,
};

const QUADRIC_PATCH_IMAGE: OpSpec = OpSpec {
    name: "quadric_patch_image",
    summary: "the image of a rational tensor-product patch of bidegree (m, n): a patch of bidegree (2m, 2n) exactly on the quadric",
    params: &[
        ParamSpec::required(
            "net",
            ParamKind::Net,
            "control net of the preimage patch in 3-space: rows of [x, y, z] (with `homogeneous = true`: [w, w·x, w·y, w·z])",
        ).degree(),
        ParamSpec::optional(
            "weights",
            ParamKind::Grid,
            "one weight per control point, rows like `net` (default all 1)",
        ),
        ParamSpec::with_default(
            "homogeneous",
            ParamKind::Bool,
            "false",
            "the points are homogeneous (weight first); then `weights` must be absent",
        ),
        QUADRIC,
        COEFFICIENTS,
        MATRIX,
        RATIONAL_POINT,
    ],
    example: r#"[[object]]
name = "ellipsoid_patch"
op = "quadric_patch_image"
net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, "1/2"]]]
quadric = "ellipsoid"
coefficients = [3, 2, 1]
"#,
    build: build_patch_image::<Rational>,
};

const QUADRIC_MIQUEL_PATCH: OpSpec = OpSpec {
    name: "quadric_miquel_patch",
    summary: "a biquadratic patch on the sphere (or an oval quadric) with four given corners and boundary circles, which exists iff the corners are in Miquel position (Jüttler Satz 7)",
    params: &[
        ParamSpec::required(
            "corners",
            ParamKind::Points,
            "the 4 corners p1 = y(0,0), p2 = y(1,0), p3 = y(1,1), p4 = y(0,1) on the quadric",
        ),
        ParamSpec::required(
            "circle_points",
            ParamKind::Points,
            "a third point on each boundary circle C12 (v = 0), C23 (u = 1), C34 (v = 1), C41 (u = 0)",
        ),
        ParamSpec::with_default(
            "weight",
            ParamKind::Number,
            "1",
            "the essential weight (of the corner c11 of the bilinear preimage), ≠ 0",
        ),
        QUADRIC,
        COEFFICIENTS,
        MATRIX,
        RATIONAL_POINT,
    ],
    example: r#"[[object]]
name = "miquel_patch"
op = "quadric_miquel_patch"
corners = [[0, 0, -1], [1, 0, 0], ["2/3", "2/3", "1/3"], [0, 1, 0]]
circle_points = [["4/5", 0, "-3/5"], ["8/9", "4/9", "1/9"], ["4/9", "8/9", "1/9"], [0, "4/5", "-3/5"]]
"#,
    build: build_miquel_patch::<Rational>,
};

const SPHERE_COVER: OpSpec = OpSpec {
    name: "sphere_cover",
    summary: "an exact cover of the whole sphere or ellipsoid by four rational biquadratic patches (δ of the four sign quadrants of the plane p3 = 0)",
    params: &[
        ParamSpec::with_default("center", ParamKind::Point3, "[0, 0, 0]", "the centre"),
        ParamSpec::with_default(
            "radii",
            ParamKind::Point3,
            "[1, 1, 1]",
            "the semi-axes [a, b, c] along x, y, z (all equal: a sphere), each ≠ 0",
        ),
    ],
    example: r#"[[object]]
name = "unit_sphere_cover"
op = "sphere_cover"
"#,
    build: build_sphere_cover::<Rational>,
};

/// A projection chosen from the quadric parameters, with the certificates of the
/// projection itself (empty for Jüttler's δ and ψ, which the image certificates cover).
pub(super) struct TargetIn<T> {
    pub(super) proj: Box<dyn GeneralizedProjection<T>>,
    pub(super) certs: Vec<Certificate>,
}

/// The exact [`TargetIn`].
pub(super) type Target = TargetIn<Rational>;

/// Which parameter to blame for an error of the quadric itself.
fn quadric_param(args: &OpArgs) -> &'static str {
    match args.string("quadric") {
        Ok("matrix") => "matrix",
        Ok(_) if args.get("coefficients").is_some_and(|v| v != &crate::value::Value::Numbers(Vec::new())) => {
            "coefficients"
        }
        _ => "quadric",
    }
}

/// A homogeneous point from `[x, y, z]` or `[w, x, y, z]`.
pub(super) fn hom(p: &[Rational], param: &'static str, what: &str) -> Result<Hom<Rational>, OpError> {
    match p {
        [x, y, z] => Ok([Rational::one(), x.clone(), y.clone(), z.clone()]),
        [w, x, y, z] => Ok([w.clone(), x.clone(), y.clone(), z.clone()]),
        _ => Err(OpError::param(
            param,
            format!(
                "{what} must be [x, y, z] or homogeneous [w, w·x, w·y, w·z], it has {} coordinates",
                p.len()
            ),
        )),
    }
}

pub(super) fn target(args: &OpArgs) -> Result<Target, OpError> {
    target_in(args)
}

/// The quadric with its matrix and rational point in `T`. The quadric and its rational
/// point are found exactly (a rational point of a quadratic form over ℚ is exact-only
/// algebra); for `f64` the projection is then set up from the rounded matrix and point.
fn in_scalar<T: OpScalar>(q: Quadric<Rational>, blame: &'static str) -> Result<Quadric<T>, OpError> {
    arith::same::<_, Quadric<T>>(q).or_else(|q| {
        let c = q.rational_point().map_err(|e| OpError::param(blame, e.to_string()))?;
        let rows: Vec<Vec<T>> = q.matrix().iter().map(|r| arith::all_of(r)).collect();
        Quadric::from_rows(&rows)
            .and_then(|x| x.with_point(c.map(|x| arith::of(&x))))
            .map(|x| x.named(q.name()))
            .map_err(|e| OpError::param(blame, e.to_string()))
    })
}

/// [`target`] in `T` (see [`in_scalar`]).
pub(super) fn target_in<T: OpScalar>(args: &OpArgs) -> Result<TargetIn<T>, OpError> {
    let name = args.string("quadric")?;
    let coefficients = args.opt_numbers("coefficients")?.unwrap_or_default();
    let matrix = args.opt_grid("matrix")?;
    let point = args
        .opt_point("rational_point")?
        .map(|p| hom(&p, "rational_point", "the rational point"))
        .transpose()?;
    let blame = quadric_param(args);
    if name != "matrix" && matrix.is_some() {
        return Err(OpError::param(
            "matrix",
            format!("a `matrix` is given but quadric = \"{name}\": set quadric = \"matrix\" to use it"),
        ));
    }
    if name == "matrix" && !coefficients.is_empty() {
        return Err(OpError::param(
            "coefficients",
            "quadric = \"matrix\" takes no `coefficients` (the matrix defines it)",
        ));
    }
    if point.is_none() {
        match name {
            "unit_sphere" if coefficients.is_empty() => {
                return Ok(TargetIn {
                    proj: Box::new(Delta),
                    certs: Vec::new(),
                })
            }
            "hyperbolic_paraboloid_xy" | "seed_paraboloid" if coefficients.is_empty() => {
                return Ok(TargetIn {
                    proj: Box::new(Psi),
                    certs: Vec::new(),
                })
            }
            _ => {}
        }
    }
    let quadric = if name == "matrix" {
        let rows = matrix.ok_or_else(|| {
            OpError::param("quadric", "quadric = \"matrix\" needs the `matrix` parameter (a symmetric 4×4 grid)")
        })?;
        Quadric::from_rows(&rows)
            .map_err(|e| OpError::param("matrix", e.to_string()))?
            .named("the quadric of `matrix`")
    } else {
        Quadric::by_name(name, &coefficients).map_err(|e| OpError::param(blame, e.to_string()))?
    };
    let quadric = match point {
        Some(p) => quadric
            .with_point(p)
            .map_err(|e| OpError::param("rational_point", e.to_string()))?,
        None => quadric,
    };
    let quadric = in_scalar::<T>(quadric, blame)?;
    let proj = quadric.projection().map_err(|e| {
        let param = match e {
            QuadricError::Exceptional { .. } if args.get("rational_point").is_some() => {
                "rational_point"
            }
            _ => blame,
        };
        OpError::param(param, e.to_string())
    })?;
    let certs = prefixed("projection: ", proj.certify());
    Ok(TargetIn {
        proj: Box::new(proj),
        certs,
    })
}

/// The index in messages like `"point 3"`, `"corner p2"`, `"tangent 1"`.
fn mentions(msg: &str, word: &str) -> bool {
    msg.contains(word)
}

/// Maps a construction error to the parameter that caused it.
pub(super) fn located(e: QuadricError, point_param: &'static str) -> OpError {
    let msg = e.to_string();
    let param = match &e {
        QuadricError::NotOnQuadric { what, .. } | QuadricError::ZeroPoint(what) => {
            if mentions(what, "tangent") {
                Some("tangents")
            } else if mentions(what, "circle point") {
                Some("circle_points")
            } else if mentions(what, "corner") {
                Some("corners")
            } else if mentions(what, "given point") {
                Some("rational_point")
            } else {
                Some(point_param)
            }
        }
        QuadricError::NotFinite(_) | QuadricError::RepeatedPoints(..) => Some(point_param),
        QuadricError::RepeatedParameters(..) => Some("params"),
        QuadricError::NotTangent { .. } => Some("tangents"),
        QuadricError::MiquelFails { .. } => Some("circle_points"),
        QuadricError::InvalidArgument(m) if m.contains("weight") => Some("weight"),
        _ => None,
    };
    OpError {
        message: msg,
        param,
    }
}

/// The most interpolation points (the linear system has `4(n+1)` unknowns for degree `2n`).
const MAX_POINTS: usize = 64;

/// `quadric_interpolate` in `T`. The exact op decides everything on the exact data; `f64`
/// takes the exact build's decisions ([`rcagd::quadric::InterpolationRoute`]: the lowest
/// degree, the kernel's pivot columns, the admissible member) and solves the same linear
/// problem, builds the image and checks the certificates in `f64` (the lowest-degree
/// certificate by the `f64` solve of degree `n − 1`).
pub(crate) fn build_interpolate<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let t = target(args)?;
    let raw = args.points("points")?;
    let pts = raw
        .iter()
        .enumerate()
        .map(|(i, p)| hom(p, "points", &format!("point {i}")))
        .collect::<Result<Vec<_>, _>>()?;
    let n = pts.len();
    if n > MAX_POINTS {
        return Err(OpError::param(
            "points",
            format!("at most {MAX_POINTS} interpolation points, got {n}"),
        ));
    }
    let params = match args.opt_numbers("params")? {
        Some(ps) => {
            if ps.len() != n {
                return Err(OpError::param(
                    "params",
                    format!("{n} points but {} parameters", ps.len()),
                ));
            }
            ps
        }
        None => (0..n)
            .map(|i| {
                if n == 1 {
                    Rational::zero()
                } else {
                    Rational::from(i) / Rational::from(n - 1)
                }
            })
            .collect(),
    };
    let tangents = match args.get("tangents") {
        None => vec![None; n],
        Some(_) => {
            let ts = args.points("tangents")?;
            if ts.len() != n {
                return Err(OpError::param(
                    "tangents",
                    format!("{n} points but {} tangents (use [0, 0, 0] for none)", ts.len()),
                ));
            }
            ts.into_iter()
                .enumerate()
                .map(|(i, v)| match v.as_slice() {
                    [x, y, z] => Ok((!(x.is_zero() && y.is_zero() && z.is_zero()))
                        .then(|| [Rational::zero(), x.clone(), y.clone(), z.clone()])),
                    _ => Err(OpError::param(
                        "tangents",
                        format!("tangent {i} must be a direction [vx, vy, vz], it has {} coordinates", v.len()),
                    )),
                })
                .collect::<Result<Vec<_>, _>>()?
        }
    };
    let data: Vec<HermiteDatum<Rational>> = pts
        .into_iter()
        .zip(params)
        .zip(tangents)
        .map(|((k, t), tan)| match tan {
            // the direction (0, v) is a second point of the tangent line
            Some(v) => HermiteDatum::with_tangent(t, k, v),
            None => HermiteDatum::point(t, k),
        })
        .collect();
    let proj = t.proj.as_ref();
    let degree = args.get("degree").map(|_| args.int("degree")).transpose()?;
    let exact = match degree {
        Some(d) => {
            let n = usize::try_from(d)
                .ok()
                .filter(|d| *d <= 32)
                .ok_or_else(|| OpError::param("degree", format!("the preimage degree must be between 0 and 32, got {d}")))?;
            interpolate_hermite(proj, &data, n).map_err(|e| match e {
                QuadricError::NoInterpolant { .. } => OpError::param("degree", e.to_string()),
                e => located(e, "points"),
            })?
        }
        None => interpolate_lowest_degree(proj, &data).map_err(|e| located(e, "points"))?,
    };
    let (t, data, interpolant, level) = match arith::same::<_, Interpolant<T>>(exact) {
        Ok(i) => (
            arith::same::<_, TargetIn<T>>(t).map_err(|_| OpError::new("an exact target is exact"))?,
            arith::same::<_, Vec<HermiteDatum<T>>>(data)
                .map_err(|_| OpError::new("exact data are exact"))?,
            i,
            None,
        ),
        Err(exact) => {
            let route = interpolation_route(proj, &data, exact.preimage_degree())
                .map_err(|e| located(e, "points"))?;
            // the exact build's export split (a weight that is 0 over Q is ±ε in f64)
            let pieces = rcagd::quadric::exportable::exportable_curve(exact.curve().clone(), &proj.quadric())
                .map_err(|e| OpError::new(e.to_string()))?
                .pieces
                .len();
            let level = pieces.trailing_zeros();
            let tt = target_in::<T>(args)?;
            let data_t: Vec<HermiteDatum<T>> = data.iter().map(datum_in).collect();
            let i = interpolate_hermite_along(tt.proj.as_ref(), &data_t, &route)
                .map_err(|e| located(e, "points"))?;
            (tt, data_t, i, Some(level))
        }
    };
    let proj = t.proj.as_ref();
    let mut certs = t.certs;
    certs.extend(interpolant.certify());
    let n = interpolant.preimage_degree();
    if degree.is_none() && n > 0 {
        // the lowest degree: the linear problem of preimage degree n − 1 has no admissible
        // solution (decided exactly; in f64 by the f64 solve)
        let lower = interpolate_hermite(proj, &data, n - 1);
        certs.push(Certificate::decide(
            format!(
                "lowest degree: no interpolant of degree {} (preimage degree {}) exists",
                2 * (n - 1),
                n - 1
            ),
            matches!(lower, Err(QuadricError::NoInterpolant { .. })),
            T::EXACT,
            || "an interpolant of lower degree exists".to_string(),
        ));
    }
    let senses = interpolant.tangent_senses().map_err(|e| located(e, "tangents"))?;
    let (geometry, extra) = match level {
        None => exportable_curve(interpolant.curve().clone(), &proj.quadric())?,
        Some(level) => {
            let e = rcagd::quadric::exportable::exportable_curve_at(interpolant.curve().clone(), &proj.quadric(), level)
                .map_err(|e| OpError::new(e.to_string()))?;
            (arith::curves(e.pieces)?, e.certificates)
        }
    };
    certs.extend(extra);
    let mut object = args.object(geometry, certs);
    if senses.iter().any(Option::is_some) {
        let items = senses
            .iter()
            .map(|s| {
                Quantity::Integer(match s {
                    Some(std::cmp::Ordering::Greater) => 1,
                    Some(std::cmp::Ordering::Less) => -1,
                    _ => 0,
                })
            })
            .collect();
        object = object.with_values(vec![NamedQuantity::new(
            "tangent_senses",
            "per point: 1 if the curve runs along the given tangent direction, −1 if against it (the interpolation fixes the tangent line; the sense follows), 0 without a tangent",
            Quantity::Vector(items),
        )]);
    }
    Ok(vec![T::finish(object)])
}

/// An exact interpolation datum in `T`.
fn datum_in<T: OpScalar>(d: &HermiteDatum<Rational>) -> HermiteDatum<T> {
    let h = |p: &Hom<Rational>| -> Hom<T> { core::array::from_fn(|k| arith::of(&p[k])) };
    HermiteDatum {
        t: arith::of(&d.t),
        point: h(&d.point),
        tangent: d.tangent.as_ref().map(h),
        fibre_position: core::array::from_fn(|k| arith::of(&d.fibre_position[k])),
    }
}

/// Homogeneous control points in 3-space from points / weights / homogeneous.
pub(super) fn control_points(
    points: Vec<Vec<Rational>>,
    weights: Option<Vec<Rational>>,
    homogeneous: bool,
    points_param: &'static str,
    label: impl Fn(usize) -> String,
) -> Result<Vec<Vec<Rational>>, OpError> {
    let want = if homogeneous { 4 } else { 3 };
    if let Some(i) = points.iter().position(|p| p.len() != want) {
        return Err(OpError::param(
            points_param,
            format!(
                "{} must be {} (the preimage lives in 3-space), it has {} coordinates",
                label(i),
                if homogeneous { "homogeneous [w, w·x, w·y, w·z]" } else { "[x, y, z]" },
                points.get(i).map_or(0, Vec::len)
            ),
        ));
    }
    super::kernel::homogeneous_points(points, weights, homogeneous, label)
}

/// Exact homogeneous control points in `T`.
fn in_t<T: OpScalar>(hom: Vec<Vec<Rational>>) -> Vec<Vec<T>> {
    hom.iter().map(|p| arith::all_of(p)).collect()
}

/// `quadric_curve_image` in `T` (one builder for the exact op and the float path).
pub(crate) fn build_curve_image<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let t = target_in::<T>(args)?;
    let hom = control_points(
        args.points("points")?,
        args.opt_numbers("weights")?,
        args.bool("homogeneous")?,
        "points",
        |i| format!("control point {i}"),
    )?;
    let curve = BezierCurve::from_homogeneous(in_t::<T>(hom)).map_err(|e| OpError::param("points", e.to_string()))?;
    let img = curve_image(t.proj.as_ref(), &curve).map_err(|e| located(e, "points"))?;
    let mut certs = t.certs;
    certs.extend(img.certify());
    let (geometry, extra) = exportable_curve(img.into_image(), &t.proj.quadric())?;
    certs.extend(extra);
    Ok(vec![arith::object::<T>(args, geometry, certs)])
}

/// `quadric_patch_image` in `T`.
pub(crate) fn build_patch_image<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let t = target_in::<T>(args)?;
    let net = args.net("net")?;
    let weights = args.opt_grid("weights")?;
    let homogeneous = args.bool("homogeneous")?;
    if let Some(w) = &weights {
        let cols = net.first().map_or(0, Vec::len);
        if w.len() != net.len() || w.iter().any(|r| r.len() != cols) {
            return Err(OpError::param(
                "weights",
                format!("the net has {} rows of {cols} points, the weights do not have the same shape", net.len()),
            ));
        }
    }
    let mut rows = Vec::with_capacity(net.len());
    for (i, row) in net.into_iter().enumerate() {
        let w = weights.as_ref().and_then(|w| w.get(i)).cloned();
        rows.push(in_t::<T>(control_points(row, w, homogeneous, "net", |j| format!("control point ({i}, {j})"))?));
    }
    let patch = BezierPatch::from_homogeneous(rows).map_err(|e| OpError::param("net", e.to_string()))?;
    let img = patch_image(t.proj.as_ref(), &patch).map_err(|e| located(e, "net"))?;
    let mut certs = t.certs;
    certs.extend(img.certify());
    let (geometry, extra) = exportable_patch(img.into_image(), &t.proj.quadric())?;
    certs.extend(extra);
    Ok(vec![arith::object::<T>(args, geometry, certs)])
}

/// Exactly four homogeneous points from a `Points` parameter.
fn four(args: &OpArgs, param: &'static str, what: &str) -> Result<[Hom<Rational>; 4], OpError> {
    let pts = args.points(param)?;
    if pts.len() != 4 {
        return Err(OpError::param(param, format!("give exactly 4 {what}, got {}", pts.len())));
    }
    let v = pts
        .iter()
        .enumerate()
        .map(|(i, p)| hom(p, param, &format!("{what} {}", i + 1)))
        .collect::<Result<Vec<_>, _>>()?;
    <[Hom<Rational>; 4]>::try_from(v).map_err(|_| OpError::param(param, format!("give exactly 4 {what}")))
}

/// `quadric_miquel_patch` in `T` (one builder for the exact op and the float path).
///
/// `F(−x) = F(x)`: the bilinear corners may be negated without moving the image corners;
/// the exact op picks, among the 8 sign choices, the first whose boundary arcs give
/// weights of one sign (arcs under 180° on the quadric), else keeps the construction. That
/// choice is an exact sign decision. In `f64` the bilinear preimage (corners, chain,
/// closure and Miquel tests, sign choice) is the exact op's, taken on the exact input, and
/// its biquadratic image and the certificates are built in `f64`.
pub(crate) fn build_miquel_patch<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let t = target(args)?;
    let corners = four(args, "corners", "corners")?;
    let circle = four(args, "circle_points", "circle points")?;
    let weight = args.number("weight")?;
    if weight.is_zero() {
        return Err(OpError::param("weight", "the weight must be non-zero"));
    }
    let p = BiquadraticPatch::from_corners(t.proj.as_ref(), corners.clone(), circle.clone(), weight.clone())
        .map_err(|e| located(e, "corners"))?;
    let p = {
        let stride = p.patch().dim() + 1;
        let mut chosen = None;
        if !one_sign(p.patch().coords(), stride) {
            for flips in 1u8..8 {
                if let Ok(c) = flipped(t.proj.as_ref(), &p, flips) {
                    if one_sign(c.patch().coords(), stride) {
                        chosen = Some(c);
                        break;
                    }
                }
            }
        }
        chosen.unwrap_or(p)
    };
    let mut level = None;
    let (certs, p, q) = match arith::same::<_, BiquadraticPatch<T>>(p) {
        Ok(p) => {
            let q = arith::same::<_, rcagd::quadric::Mat4<T>>(t.proj.quadric())
                .map_err(|_| OpError::new("internal error: the exact quadric is not exact"))?;
            (t.certs, p, q)
        }
        Err(p) => {
            let exact_q = t.proj.quadric();
            let pieces = rcagd::quadric::exportable::exportable_patch(p.patch().clone(), &exact_q)?
                .pieces
                .len();
            level = (0..=3u32).find(|l| 1usize << (2 * l) == pieces);
            // the bilinear preimage is the exact one: the chain's fibre bases are chosen by
            // zero tests over Q (δ: k0 − k3 ≠ 0), by magnitudes in f64, and fix the scale
            // of every bilinear corner (another scale: another parametrization)
            let tt = target_in::<T>(args)?;
            let hom_in = |h: &Hom<Rational>| -> Hom<T> { core::array::from_fn(|k| arith::of(&h[k])) };
            let [c00, c10, c11, c01] = p.bilinear().each_ref().map(hom_in);
            let pf = BiquadraticPatch::from_bilinear(tt.proj.as_ref(), c00, c10, c11, c01)
                .map_err(|e| located(e, "corners"))?;
            let q = tt.proj.quadric();
            (tt.certs, pf, q)
        }
    };
    let mut certs = certs;
    certs.extend(p.certify());
    let (geometry, extra) = match level {
        // the exact build's export split, replayed (a weight that is 0 over Q is ±ε in f64)
        Some(level) => {
            let e = rcagd::quadric::exportable::exportable_patch_at(p.patch().clone(), &q, level)?;
            let mut pieces = arith::exact_patches(e.pieces)?;
            let g = match pieces.len() {
                1 => Geometry::Patch(pieces.remove(0)),
                _ => Geometry::Patches(pieces),
            };
            (g, e.certificates)
        }
        None => exportable_patch(p.patch().clone(), &q)?,
    };
    certs.extend(extra);
    Ok(vec![arith::object::<T>(args, geometry, certs)])
}

/// The patch of `p`'s bilinear corners with `c10`, `c11`, `c01` negated where bits 0, 1, 2
/// of `flips` are set.
fn flipped<T: OpScalar>(
    proj: &dyn GeneralizedProjection<T>,
    p: &BiquadraticPatch<T>,
    flips: u8,
) -> Result<BiquadraticPatch<T>, rcagd::quadric::QuadricError> {
    let [c00, c10, c11, c01] = p.bilinear().clone();
    let neg = |c: &Hom<T>, f: bool| if f { c.clone().map(|x| -x) } else { c.clone() };
    BiquadraticPatch::from_bilinear(
        proj,
        c00,
        neg(&c10, flips & 1 != 0),
        neg(&c11, flips & 2 != 0),
        neg(&c01, flips & 4 != 0),
    )
}

/// `sphere_cover` in `T`.
pub(crate) fn build_sphere_cover<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let c = args.point("center")?;
    let r = args.point("radii")?;
    let (Ok(c), Ok(r)) = (<[Rational; 3]>::try_from(c), <[Rational; 3]>::try_from(r)) else {
        return Err(OpError::new("internal error: `center`/`radii` are not 3D points"));
    };
    if let Some(i) = r.iter().position(Zero::is_zero) {
        return Err(OpError::param(
            "radii",
            format!("the semi-axis {} is {}: it must be non-zero", ["a", "b", "c"][i], format_rational(&r[i])),
        ));
    }
    let cover = sphere_cover(c.each_ref().map(arith::of::<T>), r.each_ref().map(arith::of::<T>))
        .map_err(|e| OpError::param("radii", e.to_string()))?;
    let certs = cover.certify();
    let patches = arith::exact_patches(cover.into_patches())?;
    Ok(vec![arith::object::<T>(args, Geometry::Patches(patches), certs)])
}

/// `true` if the weights (every `stride`-th coordinate) are all > 0 or all < 0 (an
/// all-negative piece is the same projective object; exporters negate it).
fn one_sign(coords: &[Rational], stride: usize) -> bool {
    SignRule::OneSign.holds(coords, stride)
}

/// The curve, or its pieces with weights of one sign and their certificates
/// ([`rcagd::quadric::exportable::exportable_curve`]).
pub(super) fn exportable_curve<T: OpScalar>(
    curve: BezierCurve<T>,
    q: &rcagd::quadric::Mat4<T>,
) -> Result<(Geometry, Vec<Certificate>), OpError> {
    let e = rcagd::quadric::exportable::exportable_curve(curve, q)?;
    let mut pieces = arith::exact_curves(e.pieces)?;
    let geometry = match pieces.len() {
        1 => match pieces.pop() {
            Some(c) => Geometry::Curve(c),
            None => Geometry::Curves(Vec::new()),
        },
        _ => Geometry::Curves(pieces),
    };
    Ok((geometry, e.certificates))
}

/// As [`exportable_curve`] for a patch ([`rcagd::quadric::exportable::exportable_patch`]).
pub(super) fn exportable_patch<T: OpScalar>(
    patch: BezierPatch<T>,
    q: &rcagd::quadric::Mat4<T>,
) -> Result<(Geometry, Vec<Certificate>), OpError> {
    let e = rcagd::quadric::exportable::exportable_patch(patch, q)?;
    let mut pieces = arith::exact_patches(e.pieces)?;
    let geometry = match pieces.len() {
        1 => match pieces.pop() {
            Some(p) => Geometry::Patch(p),
            None => Geometry::Patches(Vec::new()),
        },
        _ => Geometry::Patches(pieces),
    };
    Ok((geometry, e.certificates))
}
