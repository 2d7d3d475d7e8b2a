//! Ops of the `quadric_query` topic: questions about Jüttler's generalized stereographic
//! projections answered exactly as named values (`rcagd_io::quantity`) beside geometry
//! (library `rcagd::quadric::query`):
//!
//! * `quadric_fibre`: the projecting line over a point of the quadric (or through a point
//!   of space) and, for δ and ψ, the stereographic inverse `σ⁻¹(k)` / `τ⁻¹(k)`;
//! * `quadric_preimage`: the preimage quadric of the circle (conic) through three points;
//! * `quadric_collineation`: the image of a curve or patch under a 4×4 collineation, with
//!   the image quadric;
//! * `quadric_miquel_points`: the Miquel points of a biquadratic patch on a quadric;
//! * `quadric_psi_interpolate`: interpolation on `z = xy` by ψ of any degree.

use super::quadric::{
    control_points, exportable_curve, exportable_patch, hom, located, target,
    COEFFICIENTS, MATRIX, QUADRIC, RATIONAL_POINT,
};
use super::{OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use num_traits::Zero;
use rcagd::quadric::query::{
    collineation_curve, collineation_patch, fibre_query, fibre_through, miquel_points,
    preimage_quadric_through, psi_interpolate, PlaneInverse,
};
use rcagd::quadric::{Hom, Mat4, QuadricKind};
use rcagd::Certified;
use rcagd_algebra::Rational;
use rcagd_geom::{BezierCurve, BezierPatch};
use rcagd_io::quantity::{NamedQuantity, Quantity};

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[
    QUADRIC_FIBRE,
    QUADRIC_PREIMAGE,
    QUADRIC_COLLINEATION,
    QUADRIC_MIQUEL_POINTS,
    QUADRIC_PSI_INTERPOLATE,
];

type Q = Rational;

const QUADRIC_FIBRE: OpSpec = OpSpec {
    name: "quadric_fibre",
    summary: "the projecting line (fibre) of the generalized stereographic projection over a point k of the quadric, or through a point p of space with k = F(p), certified F(λa + μb) ∥ k; for the unit sphere also σ⁻¹(k) = (k0−k3, k1, k2, 0) in p3 = 0, for z = xy also τ⁻¹(k) = (k0, k1, k2, k0) in q3 = q0 (Jüttler, Zur Konstruktion rationaler Kurven und Flächen auf Quadriken, Lemma 4 (12), Lemma 10 (18)); the object is a segment of the line",
    params: &[
        ParamSpec::optional("point", ParamKind::Point, "a point k of the quadric, [x, y, z] or homogeneous [w, w·x, w·y, w·z]"),
        ParamSpec::optional("preimage_point", ParamKind::Point, "instead of `point`: a point p of space, [x, y, z] or homogeneous; k = F(p)"),
        QUADRIC,
        COEFFICIENTS,
        MATRIX,
        RATIONAL_POINT,
    ],
    example: r#"[[object]]
name = "hopf_fibre"
op = "quadric_fibre"
preimage_point = [1, 2, -1, 3]
"#,
    build: build_fibre,
};

const QUADRIC_PREIMAGE: OpSpec = OpSpec {
    name: "quadric_preimage",
    summary: "the preimage quadric pᵀ(Σ πᵢ Mᵢ)p = 0 of the circle (conic) of the quadric through three points, πᵀF(p) = 0 for its plane π, with its type (Jüttler §2, §3: a one-sheet hyperboloid for a circle of the sphere, a hyperbolic paraboloid for one through the centre z and for every conic of z = xy; docs/math/quadrics.md, \"Preimage quadrics\"); the object is the circle (conic), the image of a line of the preimage quadric",
    params: &[
        ParamSpec::required("points", ParamKind::Points, "three points of the quadric, [x, y, z] or homogeneous"),
        QUADRIC,
        COEFFICIENTS,
        MATRIX,
        RATIONAL_POINT,
    ],
    example: r#"[[object]]
name = "circle_preimage"
op = "quadric_preimage"
points = [[1, 0, 0], [0, 1, 0], ["3/5", 0, "4/5"]]
"#,
    build: build_preimage,
};

const QUADRIC_COLLINEATION: OpSpec = OpSpec {
    name: "quadric_collineation",
    summary: "the image of a rational curve (`points`) or patch (`net`) under the collineation X ↦ A X of homogeneous coordinates X = (w, x, y, z), certified Y ≡ A·X; with `on_quadric` Q (which the input must lie on) also the image quadric Q' = A⁻ᵀ Q A⁻¹ and Yᵀ Q' Y ≡ 0 (Jüttler, Schlussbemerkung: collineations carry constructions between quadrics)",
    params: &[
        ParamSpec::required("collineation", ParamKind::Grid, "the regular 4×4 matrix A acting on (w, x, y, z)"),
        ParamSpec::optional("points", ParamKind::Points, "control points of a curve, [x, y, z] (homogeneous with `homogeneous = true`)").degree(),
        ParamSpec::optional("net", ParamKind::Net, "instead of `points`: the control net of a patch (rows)").degree(),
        ParamSpec::optional("weights", ParamKind::Grid, "weights: one row for a curve, rows like `net` for a patch (default all 1)"),
        ParamSpec::with_default("homogeneous", ParamKind::Bool, "false", "the points are homogeneous (weight first); then `weights` must be absent"),
        ParamSpec::optional("on_quadric", ParamKind::Grid, "a symmetric 4×4 matrix Q with Xᵀ Q X ≡ 0 on the input: adds the image quadric"),
    ],
    example: r#"[[object]]
name = "sphere_arc_to_ellipsoid"
op = "quadric_collineation"
collineation = [[1, 0, 0, 0], [0, 2, 0, 0], [0, 0, 3, 0], [0, 0, 0, 4]]
# a circle arc on the unit sphere (the δ-image of a line), homogeneous (w, w·x, w·y, w·z)
homogeneous = true
points = [[1, 0, 0, -1], [1, 0, 1, -1], [2, 0, 2, 0]]
on_quadric = [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
"#,
    build: build_collineation,
};

const QUADRIC_MIQUEL_POINTS: OpSpec = OpSpec {
    name: "quadric_miquel_points",
    summary: "the Miquel configuration of a biquadratic patch on the quadric: corners p1..p4, the planes of the boundary conics, the second intersections q1..q4 of adjacent boundary conics, and whether p1, q2, p3, q4 and q1, p2, q3, p4 are concyclic (det = 0; Jüttler Satz 7); the object is the patch",
    params: &[
        ParamSpec::required("net", ParamKind::Net, "the 3×3 control net of the patch on the quadric: rows of [x, y, z] (homogeneous with `homogeneous = true`)").degree(),
        ParamSpec::optional("weights", ParamKind::Grid, "3×3 weights (default all 1)"),
        ParamSpec::with_default("homogeneous", ParamKind::Bool, "false", "the points are homogeneous (weight first); then `weights` must be absent"),
        QUADRIC,
        COEFFICIENTS,
        MATRIX,
        RATIONAL_POINT,
    ],
    example: r#"[[object]]
name = "octant_miquel"
op = "quadric_miquel_points"
homogeneous = true
# the δ-image of the bilinear patch with corners (1,0,0,0), (1,1,0,0), (2,1,1,1), (1,0,1,0)
net = [[[1, 0, 0, -1], [1, 0, 1, -1], [2, 0, 2, 0]], [[1, 1, 0, -1], ["3/2", 1, 1, "-3/2"], [3, 0, 3, -1]], [[2, 2, 0, 0], [3, 3, 2, -1], [7, 2, 6, -3]]]
"#,
    build: build_miquel_points,
};

const QUADRIC_PSI_INTERPOLATE: OpSpec = OpSpec {
    name: "quadric_psi_interpolate",
    summary: "a rational curve y = u ⊗ v of any degree n = r + s ≥ the lowest on the hyperbolic paraboloid z = xy (h0h3 = h1h2) through points at parameters, from the Segre factors u = (q0, q1), v = (q3, q2) of ψ (Jüttler (8), (15)): the lowest degrees, the dimensions of the solution spaces of u and v, the free parameters and the coefficients",
    params: &[
        ParamSpec::required("points", ParamKind::Points, "points of z = xy, [x, y, z] or homogeneous [w, w·x, w·y, w·z] with w·z = x·y·…"),
        ParamSpec::optional("params", ParamKind::Numbers, "one parameter per point, pairwise distinct (default 0, 1/(N−1), …, 1)"),
        ParamSpec::required("degree", ParamKind::Int, "the degree n = r + s of the curve").degree(),
        ParamSpec::optional("u_degree", ParamKind::Int, "the degree r of u (default: the extra degree split evenly, u first)").degree(),
    ],
    example: r#"[[object]]
name = "psi_quartic"
op = "quadric_psi_interpolate"
# three points of the twisted cubic (t, t², t³) on z = xy, by a quartic
points = [[0, 0, 0], ["1/2", "1/4", "1/8"], [1, 1, 1]]
degree = 4
"#,
    build: build_psi_interpolate,
};

fn value(name: &str, doc: &str, v: Quantity) -> NamedQuantity {
    NamedQuantity::new(name, doc, v)
}

fn point_value(name: &str, doc: &str, p: &[Q]) -> NamedQuantity {
    value(name, doc, Quantity::rationals(p))
}

fn matrix_value(name: &str, doc: &str, m: &Mat4<Q>) -> NamedQuantity {
    value(name, doc, Quantity::Vector(m.iter().map(|r| Quantity::rationals(r)).collect()))
}

fn kind_text(k: QuadricKind) -> String {
    format!("{k:?}")
        .chars()
        .fold(String::new(), |mut s, c| {
            if c.is_uppercase() && !s.is_empty() {
                s.push('_');
            }
            s.push(c.to_ascii_lowercase());
            s
        })
}

/// A segment of the line through `a` and `b` with positive weights, or an error for the
/// line at infinity.
fn line_segment(a: &Hom<Q>, b: &Hom<Q>) -> Result<BezierCurve<Q>, OpError> {
    let norm = |p: &Hom<Q>| p.clone().map(|x| x / p[0].clone());
    let (x, y) = match (a[0].is_zero(), b[0].is_zero()) {
        (false, false) => (norm(a), norm(b)),
        (false, true) => {
            let x = norm(a);
            let y = core::array::from_fn(|i| x[i].clone() + b[i].clone());
            (x, y)
        }
        (true, false) => {
            let y = norm(b);
            let x = core::array::from_fn(|i| y[i].clone() + a[i].clone());
            (x, y)
        }
        (true, true) => {
            return Err(OpError::new(
                "the projecting line lies in the plane at infinity (w = 0): its values are exact, but it has no finite segment to draw; choose another point",
            ))
        }
    };
    Ok(BezierCurve::from_homogeneous(vec![x.to_vec(), y.to_vec()])?)
}

fn build_fibre(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let t = target(args)?;
    let quadric_name = args.string("quadric")?;
    let plain = args.get("coefficients").is_none_or(|v| v == &crate::value::Value::Numbers(Vec::new()))
        && args.get("rational_point").is_none();
    let inverse = match quadric_name {
        "unit_sphere" if plain => Some(PlaneInverse::Sigma),
        "hyperbolic_paraboloid_xy" | "seed_paraboloid" if plain => Some(PlaneInverse::Tau),
        _ => None,
    };
    let f = match (args.opt_point("point")?, args.opt_point("preimage_point")?) {
        (Some(k), None) => {
            let k = hom(&k, "point", "the point")?;
            fibre_query(t.proj.as_ref(), &k).map_err(|e| located(e, "point"))?
        }
        (None, Some(p)) => {
            let p = hom(&p, "preimage_point", "the point")?;
            fibre_through(t.proj.as_ref(), &p).map_err(|e| located(e, "preimage_point"))?
        }
        (None, None) => return Err(OpError::new("give `point` (on the quadric) or `preimage_point` (in space)")),
        (Some(_), Some(_)) => {
            return Err(OpError::param("preimage_point", "give `point` or `preimage_point`, not both"))
        }
    };
    let f = match inverse {
        Some(w) => f.with_plane_inverse(w),
        None => f,
    };
    let mut certs = t.certs;
    certs.extend(f.certify());
    let [a, b] = &f.fibre;
    let [fa, fab, fb] = f.images();
    let mut values = vec![
        point_value("k", "the point k of the quadric (homogeneous w, w·x, w·y, w·z)", &f.point),
        point_value("a", "first spanning point of the projecting line over k", a),
        point_value("b", "second spanning point", b),
        point_value("F_a", "F(a), a multiple of k (or 0)", fa),
        point_value("F_ab", "the polar value F̂(a, b), a multiple of k (or 0)", fab),
        point_value("F_b", "F(b), a multiple of k (or 0)", fb),
    ];
    if let Some((w, x)) = &f.plane_point {
        let (name, doc) = match w {
            PlaneInverse::Sigma => ("sigma_inverse", "σ⁻¹(k) = (k0−k3, k1, k2, 0), the point of the fibre in p3 = 0"),
            PlaneInverse::Tau => ("tau_inverse", "τ⁻¹(k) = (k0, k1, k2, k0), the point of the fibre in q3 = q0"),
        };
        values.push(point_value(name, doc, x));
    }
    Ok(vec![args
        .object(Geometry::Curve(line_segment(a, b)?), certs)
        .with_values(values)])
}

fn build_preimage(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let t = target(args)?;
    let pts = args.points("points")?;
    if pts.len() != 3 {
        return Err(OpError::param("points", format!("give exactly 3 points, got {}", pts.len())));
    }
    let v = pts
        .iter()
        .enumerate()
        .map(|(i, p)| hom(p, "points", &format!("point {i}")))
        .collect::<Result<Vec<_>, _>>()?;
    let three = [v[0].clone(), v[1].clone(), v[2].clone()];
    let pq = preimage_quadric_through(t.proj.as_ref(), &three).map_err(|e| located(e, "points"))?;
    let mut certs = t.certs;
    certs.extend(pq.certify());
    let section = pq
        .section
        .as_ref()
        .ok_or_else(|| OpError::new("internal error: no section curve"))?;
    let values = vec![
        point_value("plane", "the plane π (π0 w + π1 x + π2 y + π3 z = 0) of the section", &pq.plane),
        matrix_value("preimage_quadric", "the symmetric matrix Σ πᵢ Mᵢ of πᵀF(p) = pᵀ M p", &pq.matrix),
        value("kind", "the affine type of the preimage quadric", Quantity::Text(kind_text(pq.kind))),
        value(
            "preimage_line",
            "control points (homogeneous) of the line whose image is the section",
            Quantity::Vector(section.preimage().control_points().map(Quantity::rationals).collect()),
        ),
    ];
    let (geometry, extra) = exportable_curve(section.curve().clone(), &t.proj.quadric())?;
    certs.extend(extra);
    Ok(vec![args.object(positive_weights(geometry)?, certs).with_values(values)])
}

fn mat4(rows: &[Vec<Q>], param: &'static str) -> Result<Mat4<Q>, OpError> {
    if rows.len() != 4 || rows.iter().any(|r| r.len() != 4) {
        return Err(OpError::param(param, "a 4×4 matrix is needed (four rows of four numbers)"));
    }
    Ok(core::array::from_fn(|i| core::array::from_fn(|j| rows[i][j].clone())))
}

fn build_collineation(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let a = mat4(&args.opt_grid("collineation")?.unwrap_or_default(), "collineation")?;
    let quadric = args
        .opt_grid("on_quadric")?
        .map(|g| mat4(&g, "on_quadric"))
        .transpose()?;
    let homogeneous = args.bool("homogeneous")?;
    let weights = args.opt_grid("weights")?;
    let blame = |e: rcagd::quadric::QuadricError, input: &'static str| {
        let msg = e.to_string();
        let param = match e {
            rcagd::quadric::QuadricError::Degenerate(_) | rcagd::quadric::QuadricError::NotFinite(_) => "collineation",
            rcagd::quadric::QuadricError::NotOnQuadric { .. } => "on_quadric",
            _ => input,
        };
        OpError::param(param, msg)
    };
    let (geometry, certs, det, image_pts, image_q) = match (args.get("points").is_some(), args.get("net").is_some()) {
        (true, false) => {
            let w = match weights {
                Some(mut g) if g.len() == 1 => Some(g.remove(0)),
                Some(_) => return Err(OpError::param("weights", "a curve takes one row of weights")),
                None => None,
            };
            let hom = control_points(args.points("points")?, w, homogeneous, "points", |i| format!("control point {i}"))?;
            let curve = BezierCurve::from_homogeneous(hom).map_err(|e| OpError::param("points", e.to_string()))?;
            let img = collineation_curve(&a, &curve, quadric.as_ref()).map_err(|e| blame(e, "points"))?;
            let certs = img.certify();
            let pts: Vec<Quantity> = img.image.control_points().map(Quantity::rationals).collect();
            let q2 = img.quadrics.as_ref().map(|(_, q)| q.clone());
            let (g, extra) = match &q2 {
                Some(q) => exportable_curve(img.image.clone(), q)?,
                None => (Geometry::Curve(img.image.clone()), Vec::new()),
            };
            let mut certs = certs;
            certs.extend(extra);
            (g, certs, img.det, pts, q2)
        }
        (false, true) => {
            let net = args.net("net")?;
            let mut rows = Vec::with_capacity(net.len());
            for (i, row) in net.into_iter().enumerate() {
                let w = weights.as_ref().and_then(|w| w.get(i)).cloned();
                rows.push(control_points(row, w, homogeneous, "net", |j| format!("control point ({i}, {j})"))?);
            }
            let patch = BezierPatch::from_homogeneous(rows).map_err(|e| OpError::param("net", e.to_string()))?;
            let img = collineation_patch(&a, &patch, quadric.as_ref()).map_err(|e| blame(e, "net"))?;
            let certs = img.certify();
            let (m, n) = img.image.degree();
            let pts: Vec<Quantity> = (0..=m)
                .flat_map(|i| (0..=n).map(move |j| (i, j)))
                .map(|(i, j)| Quantity::rationals(img.image.control_point(i, j)))
                .collect();
            let q2 = img.quadrics.as_ref().map(|(_, q)| q.clone());
            let (g, extra) = match &q2 {
                Some(q) => exportable_patch(img.image.clone(), q)?,
                None => (Geometry::Patch(img.image.clone()), Vec::new()),
            };
            let mut certs = certs;
            certs.extend(extra);
            (g, certs, img.det, pts, q2)
        }
        _ => return Err(OpError::param("points", "give the curve as `points` or the patch as `net` (one of them)")),
    };
    let mut values = vec![
        value("det", "det A", Quantity::Rational(det)),
        value("image_control_points", "homogeneous control points of the image (row by row for a patch)", Quantity::Vector(image_pts)),
    ];
    if let Some(q) = &image_q {
        values.push(matrix_value("image_quadric", "Q' = A⁻ᵀ Q A⁻¹", q));
    }
    Ok(vec![args.object(positive_weights(geometry)?, certs).with_values(values)])
}

fn build_miquel_points(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let t = target(args)?;
    let net = args.net("net")?;
    let weights = args.opt_grid("weights")?;
    let homogeneous = args.bool("homogeneous")?;
    let mut rows = Vec::with_capacity(net.len());
    for (i, row) in net.into_iter().enumerate() {
        let w = weights.as_ref().and_then(|w| w.get(i)).cloned();
        rows.push(control_points(row, w, homogeneous, "net", |j| format!("control point ({i}, {j})"))?);
    }
    let patch = BezierPatch::from_homogeneous(rows).map_err(|e| OpError::param("net", e.to_string()))?;
    let q = t.proj.quadric();
    let m = miquel_points(&q, &patch).map_err(|e| OpError::param("net", e.to_string()))?;
    let mut certs = t.certs;
    certs.extend(m.certify());
    let list = |v: &[Hom<Q>]| Quantity::Vector(v.iter().map(|p| Quantity::rationals(p)).collect());
    let mut values = vec![
        value("miquel", "det[p1, q2, p3, q4] = det[q1, p2, q3, p4] = 0 (Jüttler Satz 7)", Quantity::Bool(m.is_miquel())),
        value("corners", "p1 = y(0,0), p2 = y(1,0), p3 = y(1,1), p4 = y(0,1)", list(&m.corners)),
        value("second_points", "q1..q4: the second intersections of the boundary conics at p1..p4", list(&m.second)),
        value("circle_planes", "the planes of C12 (v = 0), C23 (u = 1), C34 (v = 1), C41 (u = 0)", list(&m.planes)),
        value("miquel_residual_1", "det[p1, q2, p3, q4] (points with first non-zero coordinate 1)", Quantity::Rational(m.residuals.0.clone())),
        value("miquel_residual_2", "det[q1, p2, q3, p4]", Quantity::Rational(m.residuals.1.clone())),
    ];
    for (k, p) in m.miquel_planes.iter().enumerate() {
        if let Some(p) = p {
            let doc = if k == 0 { "the plane of the Miquel circle through p1, q2, p3 (q4 on it iff Miquel)" } else { "the plane through q1, p2, q3 (p4 on it iff Miquel)" };
            values.push(point_value(&format!("miquel_plane_{}", k + 1), doc, p));
        }
    }
    let (geometry, extra) = exportable_patch(patch, &q)?;
    certs.extend(extra);
    Ok(vec![args.object(positive_weights(geometry)?, certs).with_values(values)])
}

fn build_psi_interpolate(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let pts = args.points("points")?;
    let points = pts
        .iter()
        .enumerate()
        .map(|(i, p)| hom(p, "points", &format!("point {i}")))
        .collect::<Result<Vec<_>, _>>()?;
    let n = points.len();
    let params = match args.opt_numbers("params")? {
        Some(p) => p,
        None if n == 1 => vec![Q::zero()],
        None => (0..n).map(|i| Q::from(i as i64) / Q::from((n - 1) as i64)).collect(),
    };
    let degree = usize::try_from(args.int("degree")?).map_err(|_| OpError::param("degree", "the degree is 0, 1, …"))?;
    let u_degree = match args.get("u_degree") {
        Some(_) => Some(usize::try_from(args.int("u_degree")?).map_err(|_| OpError::param("u_degree", "the degree is 0, 1, …"))?),
        None => None,
    };
    let it = psi_interpolate(&points, &params, degree, u_degree).map_err(|e| {
        let p = match e {
            rcagd::quadric::QuadricError::NoInterpolant { .. } => if u_degree.is_some() { "u_degree" } else { "degree" },
            rcagd::quadric::QuadricError::RepeatedParameters(..) | rcagd::quadric::QuadricError::Dimension(_) => "params",
            _ => "points",
        };
        OpError::param(p, e.to_string())
    })?;
    let mut certs = it.certify();
    let (r, s) = it.degrees();
    let binary = |w: &[[Q; 2]]| Quantity::Vector(w.iter().map(|p| Quantity::rationals(p)).collect());
    let values = vec![
        value("degrees", "(r, s) = (deg u, deg v)", Quantity::Vector(vec![Quantity::Integer(r as i64), Quantity::Integer(s as i64)])),
        value("lowest_degrees", "the lowest (r, s) through these points", Quantity::Vector(vec![Quantity::Integer(it.lowest.0 as i64), Quantity::Integer(it.lowest.1 as i64)])),
        value("u_dimension", "dimension of the solution space of u", Quantity::Integer(it.u_dimension as i64)),
        value("v_dimension", "dimension of the solution space of v", Quantity::Integer(it.v_dimension as i64)),
        value("free_parameters", "(dim U − 1) + (dim V − 1): the family of interpolants of these degrees", Quantity::Integer(it.free_parameters() as i64)),
        value("u", "Bernstein coefficients [q0, q1] of u", binary(&it.u)),
        value("v", "Bernstein coefficients [q3, q2] of v", binary(&it.v)),
    ];
    let h = rcagd::quadric::paraboloid::paraboloid_matrix::<Q>();
    let (geometry, extra) = exportable_curve(it.curve.clone(), &h)?;
    certs.extend(extra);
    Ok(vec![args.object(positive_weights(geometry)?, certs).with_values(values)])
}

/// The same geometry with every curve or patch whose weights are all negative negated
/// and, where all weights are equal, scaled to weight 1 (the same projective object; the
/// exchange formats then write a polynomial B-spline whose numbers are the exact ones).
pub(super) fn positive_weights(g: Geometry) -> Result<Geometry, OpError> {
    let scale = |coords: &[Q], stride: usize| -> Option<Q> {
        let ws: Vec<&Q> = coords.iter().step_by(stride).collect();
        let first = (*ws.first()?).clone();
        if ws.iter().all(|w| **w == first) && !first.is_zero() && first != Q::from(1) {
            return Some(first);
        }
        ws.iter().all(|w| **w < Q::zero()).then(|| Q::from(-1))
    };
    let apply = |coords: &[Q], c: &Q| coords.iter().map(|x| x.clone() / c.clone()).collect::<Vec<Q>>();
    let curve = |c: BezierCurve<Q>| -> Result<BezierCurve<Q>, OpError> {
        match scale(c.coords(), c.dim() + 1) {
            Some(k) => Ok(BezierCurve::from_flat(c.dim(), apply(c.coords(), &k))?),
            None => Ok(c),
        }
    };
    let patch = |p: BezierPatch<Q>| -> Result<BezierPatch<Q>, OpError> {
        match scale(p.coords(), p.dim() + 1) {
            Some(k) => {
                let (m, n) = p.degree();
                Ok(BezierPatch::from_flat(p.dim(), m, n, apply(p.coords(), &k))?)
            }
            None => Ok(p),
        }
    };
    // several pieces: only a factor common to all of them (joins stay exact)
    let common = |ks: Vec<Option<Q>>| -> bool {
        ks.first().is_some_and(|k0| k0.is_some() && ks.iter().all(|k| k == k0))
    };
    Ok(match g {
        Geometry::Curve(c) => Geometry::Curve(curve(c)?),
        Geometry::Patch(p) => Geometry::Patch(patch(p)?),
        Geometry::Curves(cs) => {
            if common(cs.iter().map(|c| scale(c.coords(), c.dim() + 1)).collect()) {
                Geometry::Curves(cs.into_iter().map(curve).collect::<Result<_, _>>()?)
            } else {
                Geometry::Curves(cs)
            }
        }
        Geometry::Patches(ps) => {
            if common(ps.iter().map(|p| scale(p.coords(), p.dim() + 1)).collect()) {
                Geometry::Patches(ps.into_iter().map(patch).collect::<Result<_, _>>()?)
            } else {
                Geometry::Patches(ps)
            }
        }
    })
}
