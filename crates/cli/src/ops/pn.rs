//! PN-surface ops (`rcagd::pn`, `rcagd::laguerre`; Peternell ch. 3–5): PN surfaces from a
//! function of the isotropic model or from a support function, the §4.4 modeling scheme,
//! PN ruled surfaces, canal surfaces, surfaces of revolution and ellipsoids, Laguerre
//! images, planar PH curves from the isotropic model, anticaustics — each with its exact
//! offsets at every distance of `distances` (one extra object per distance, named
//! `<name>_offset<k>`).
//!
//! Every surface is exported as rational Bézier patches over the parameter rectangle
//! `domain = [u0, u1, v0, v1]`; it must be regular there (`W ≠ 0`, `x_u × x_v ≠ 0`,
//! decided exactly by Bernstein signs), and so must every offset: a distance equal to a
//! principal radius of curvature somewhere on the rectangle is an error on `distances`
//! that names the parameter point.

use super::poly_io::{self, MPolyQ};
use super::arith::{self, OpScalar};
use super::{prefixed, OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::{ParamKind, Value};
use rcagd::laguerre::LaguerreMap;
use rcagd::pn::developable::DevelopablePn;
use rcagd::pn::focal::{FocalSurfaces, GammaSection};
use rcagd::pn::hypercyclide::{QuadricPn, CyclographicImage, Hypercyclide, PeSimilarity, RegularQuadric};
use rcagd::pn::modeling::{HermiteDatum, PnModel};
use rcagd::laguerre::Cycle;
use rcagd::pn::motion::{
    moved_cone_envelope, ruled_surface_image, DevelopableMotionEnvelope, LaguerreFamily,
};
use rcagd::pn::planar::{surface_of_revolution, PnCurve};
use rcagd::pn::reducing_frame::ReducedConeEnvelope;
use rcagd::pn::ruled::{CanalPn, CycleFamily, EllipsoidPn, RuledPn};
use rcagd::pn::support::{anticaustic, anticaustic_certificates, from_support_function};
use rcagd::pn::two_sheet::TwoSheetPn;
use rcagd::pn::{Domain, IsotropicSurface, PnError, PnSurface, RatFn};
use rcagd::Certified;
use rcagd_algebra::rational::format_rational;
use rcagd_algebra::{Certificate, Rational, Scalar};
use rcagd_geom::BezierPatch;
use rcagd_io::quantity::{NamedQuantity, Quantity};

type Q = Rational;

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[
    PN_GRAPH,
    PN_SUPPORT,
    PN_MODEL,
    PN_LOFT,
    PN_RULED,
    PN_CANAL,
    PN_CONE_ENVELOPE,
    PN_DEVELOPABLE,
    PN_DEVELOPABLE_EDGE,
    PN_DEVELOPABLE_MOTION,
    PN_CONE_MOTION,
    PN_RULED_CYCLOGRAPHIC,
    PN_REVOLUTION,
    PN_ELLIPSOID,
    PN_QUADRIC,
    PN_TWO_SHEET,
    HYPERCYCLIDE,
    CYCLOGRAPHIC_SURFACE,
    CYCLOGRAPHIC_SECTION,
    PN_FOCAL_SURFACE,
    PN_LAGUERRE,
    PN_ANTICAUSTIC,
    PN_PLANAR,
];

// ---------------------------------------------------------------------------------
// shared parameters and helpers
// ---------------------------------------------------------------------------------

const DOMAIN: ParamSpec = ParamSpec::with_default(
    "domain",
    ParamKind::Numbers,
    "[-1, 1, -1, 1]",
    "parameter rectangle [u0, u1, v0, v1] of the exported patch (u0 < u1, v0 < v1)",
);
const DISTANCES: ParamSpec = ParamSpec::optional(
    "distances",
    ParamKind::Numbers,
    "oriented offset distances d (x + d n); one extra object `<name>_offset<k>` per distance",
);
const ORIENTATION: ParamSpec = ParamSpec::with_default(
    "orientation",
    ParamKind::Choice(&["positive", "negative"]),
    "\"positive\"",
    "orientation of the exported surface: \"negative\" keeps the points and flips the unit normal n ↦ −n (support h ↦ −h), so an offset at distance d lies on the other side",
);
const OFFSET: ParamSpec = ParamSpec::optional(
    "offset",
    ParamKind::Number,
    "build the offset x + d n at this oriented distance instead of the input itself (certified as its offset; `distances` stay relative to the input)",
);
const COEFFICIENTS: ParamSpec = ParamSpec::required(
    "coefficients",
    ParamKind::Grid,
    "power-basis coefficients c[i][j] of u^i v^j of the numerator of F(u, v)",
).degree();
const DENOMINATOR: ParamSpec = ParamSpec::optional(
    "denominator",
    ParamKind::Grid,
    "power-basis coefficients of the denominator of F (default 1)",
).degree();

use poly_io::grid_mpoly as poly_from_grid;

/// `Σ c[k] t^k` (a polynomial in the first of the two parameters).
fn poly_from_list(list: &[Q]) -> Result<MPolyQ, OpError> {
    poly_io::list_mpoly(list, 2)
}

/// The rational function `numerator/denominator` of two grid parameters.
fn ratfn<T: OpScalar>(args: &OpArgs, num: &'static str, den: &'static str) -> Result<RatFn<T>, OpError> {
    let n = poly_from_grid(&args.opt_grid(num)?.unwrap_or_default())?;
    let d = match args.opt_grid(den)? {
        Some(g) => poly_from_grid(&g)?,
        None => poly_io::mpoly_constant(2, Q::from(1)),
    };
    RatFn::new(poly_io::mpoly_in(&n), poly_io::mpoly_in(&d)).map_err(|e| OpError::param(den, e.to_string()))
}

/// `N` polynomials in `t` from a grid of `N` rows of power coefficients (`rows` names them
/// in the error message).
fn n_polys<const N: usize>(
    args: &OpArgs,
    param: &'static str,
    rows: &str,
) -> Result<[RatFn<Q>; N], OpError> {
    let g = args.opt_grid(param)?.unwrap_or_default();
    if g.len() != N {
        return Err(OpError::param(
            param,
            format!("give {N} rows ({rows}) of power coefficients in t, got {} rows", g.len()),
        ));
    }
    let polys = g
        .iter()
        .map(|row| poly_from_list(row).map(RatFn::poly))
        .collect::<Result<Vec<_>, _>>()?;
    polys
        .try_into()
        .map_err(|_| OpError::param(param, format!("give {N} rows ({rows})")))
}

/// Three polynomials in `t` from a grid of three rows of power coefficients.
fn three_polys(args: &OpArgs, param: &'static str) -> Result<[RatFn<Q>; 3], OpError> {
    n_polys(args, param, "x, y, z")
}

/// An exact rational function of the input in `T`.
fn ratfn_in<T: OpScalar>(f: &RatFn<Q>) -> RatFn<T> {
    RatFn {
        num: poly_io::mpoly_in(&f.num),
        den: poly_io::mpoly_in(&f.den),
    }
}

/// Exact rational functions of the input in `T`.
fn ratfns_in<T: OpScalar, const N: usize>(f: &[RatFn<Q>; N]) -> [RatFn<T>; N] {
    core::array::from_fn(|i| ratfn_in(&f[i]))
}

/// The splitting `p₁² + p₂²` of a cone-family envelope (Peternell Thm 4.5) as `T` needs
/// it: `None` for exact scalars (the construction searches it over Q itself), the exact
/// splitting of the exact input for `f64` — whether a polynomial is a sum of two squares
/// over Q is exact-only algebra, so the float path decides it on the recipe's exact
/// numbers (`exact` builds the exact envelope) and runs the construction in `f64` with it.
fn exact_splitting<T: OpScalar>(
    exact: impl FnOnce() -> Result<[RatFn<Q>; 2], OpError>,
) -> Result<Option<[RatFn<T>; 2]>, OpError> {
    if T::EXACT {
        return Ok(None);
    }
    Ok(Some(ratfns_in(&exact()?)))
}

fn domain<T: OpScalar>(args: &OpArgs) -> Result<Domain<T>, OpError> {
    let d = args.opt_numbers("domain")?.unwrap_or_default();
    if d.len() != 4 {
        return Err(OpError::param(
            "domain",
            format!("give four numbers [u0, u1, v0, v1], got {}", d.len()),
        ));
    }
    Domain::new(arith::of(&d[0]), arith::of(&d[1]), arith::of(&d[2]), arith::of(&d[3]))
        .map_err(|e| OpError::param("domain", e.to_string()))
}

fn distances(args: &OpArgs) -> Result<Vec<Q>, OpError> {
    Ok(args.opt_numbers("distances")?.unwrap_or_default())
}

/// A construction error, blamed on `param`.
fn blame(param: &'static str) -> impl Fn(PnError) -> OpError {
    move |e| OpError::param(param, e.to_string())
}

/// The object of `surface` on `dom` (certified and checked regular, errors blamed on
/// `param`) followed by one object per offset distance (errors blamed on `distances`).
fn surface_objects<T: OpScalar>(
    args: &OpArgs,
    surface: &PnSurface<T>,
    dom: &Domain<T>,
    certs: Vec<Certificate>,
    param: &'static str,
) -> Result<Vec<Object>, OpError> {
    let objs = surface_objects_in(args, surface, dom, certs, param, &|p| {
        Ok(Geometry::Patch(T::exact_patch(p.clone())?))
    })?;
    Ok(objs.into_iter().map(T::finish).collect())
}

/// [`surface_objects`] in any scalar (the float path, `crate::float`, builds the same
/// objects in `f64`): `geometry` turns a patch into the object's exact geometry.
pub(crate) fn surface_objects_in<T: Scalar>(
    args: &OpArgs,
    surface: &PnSurface<T>,
    dom: &Domain<T>,
    mut certs: Vec<Certificate>,
    param: &'static str,
    geometry: &dyn Fn(&BezierPatch<T>) -> Result<Geometry, OpError>,
) -> Result<Vec<Object>, OpError> {
    certs.extend(surface.certify());
    certs.push(surface.check_regular(dom).map_err(|e| {
        OpError::param(
            param,
            format!("the input surface is not regular on the domain: {e}"),
        )
    })?);
    let patch = match main_offset(args)? {
        None => surface.patch(dom).map_err(blame("domain"))?,
        Some(d) => {
            let off = surface.offset(T::from_rational(&d));
            certs.extend(off.certify());
            certs.push(off.check_regular(dom).map_err(blame("offset"))?);
            off.patch(dom).map_err(blame("offset"))?
        }
    };
    let mut out = vec![args.object(geometry(&patch)?, certs)];
    for (k, d) in distances(args)?.into_iter().enumerate() {
        let off = surface.offset(T::from_rational(&d));
        let mut c = off.certify();
        c.push(off.check_regular(dom).map_err(|e| {
            OpError::param(
                "distances",
                format!("distance {} (entry {k}): {e}", format_rational(&d)),
            )
        })?);
        let patch = off.patch(dom).map_err(blame("distances"))?;
        out.push(offset_object(args, k, &d, geometry(&patch)?, c));
    }
    Ok(out)
}

/// The `offset` parameter, if given and non-zero.
fn main_offset(args: &OpArgs) -> Result<Option<Q>, OpError> {
    Ok(args.opt_number("offset")?.filter(|d| !d.is_zero()))
}

/// `true` if the `orientation` parameter asks for the opposite orientation (read as the
/// canal ops read it; absent means positive).
fn negative_orientation(args: &OpArgs) -> bool {
    matches!(args.get("orientation"), Some(Value::Str(s)) if s == "negative")
}

/// `surface` with the orientation the `orientation` parameter asks for.
fn oriented<T: Scalar>(args: &OpArgs, surface: &PnSurface<T>) -> PnSurface<T> {
    if negative_orientation(args) {
        surface.opposite()
    } else {
        surface.clone()
    }
}

fn offset_object(
    args: &OpArgs,
    k: usize,
    d: &Q,
    geometry: Geometry,
    certificates: Vec<Certificate>,
) -> Object {
    let mut params = args.params_json();
    if let Some(m) = params.as_object_mut() {
        m.insert(
            "offset_distance".into(),
            serde_json::Value::String(format_rational(d)),
        );
    }
    Object {
        name: format!("{}_offset{}", args.name(), k + 1),
        op: args.op().name.to_string(),
        params,
        geometry,
        certificates,
        values: Vec::new(),
    }
}

// ---------------------------------------------------------------------------------
// PN surface from a function of the isotropic model (Peternell Theorem 4.3/4.4,
// docs/math/laguerre-pn.md#closed-formula)
// ---------------------------------------------------------------------------------

const PN_GRAPH: OpSpec = OpSpec {
    name: "pn_graph",
    summary: "the PN surface Λ⁻¹ of the graph y₃ = F(u, v) of the isotropic model (Peternell Thm 4.3/4.4, closed formula), with exact offsets (F ↦ F − (d/2)(u² + v² + 1))",
    params: &[COEFFICIENTS, DENOMINATOR, DOMAIN, OFFSET, ORIENTATION, DISTANCES],
    example: r#"[[object]]
name = "pn_cubic_graph"
op = "pn_graph"
# F(u, v) = 1 + v²/2 − u v + u³/3
coefficients = [[1, 0, "1/2"], [0, -1, 0], [0, 0, 0], ["1/3", 0, 0]]
domain = [0, "1/2", 0, "1/2"]
distances = ["1/4", "-1/4"]
"#,
    build: build_graph::<Rational>,
};

/// `pn_graph` in `T` (one builder for the exact op and the float path).
pub(crate) fn build_graph<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let f = ratfn::<T>(args, "coefficients", "denominator")?;
    let surface = IsotropicSurface::graph(&f)
        .to_pn_surface()
        .map_err(blame("coefficients"))?;
    surface_objects(args, &oriented(args, &surface), &domain(args)?, Vec::new(), "coefficients")
}

// ---------------------------------------------------------------------------------
// PN surface from its support function ((4.2))
// ---------------------------------------------------------------------------------

const PN_SUPPORT: OpSpec = OpSpec {
    name: "pn_support",
    summary: "the PN surface with tangent planes h + n·x = 0, n = (2ac, 2bc, a² + b² − c²)/(a² + b² + c²) (Peternell (4.2); default a = u, b = v, c = 1) and rational support function h, with offsets (h ↦ h − d)",
    params: &[
        ParamSpec::required(
            "support",
            ParamKind::Grid,
            "power coefficients c[i][j] of u^i v^j of the numerator of h",
        ).degree(),
        ParamSpec::optional(
            "support_denominator",
            ParamKind::Grid,
            "power coefficients of the denominator of h (default 1)",
        ).degree(),
        ParamSpec::optional("a", ParamKind::Grid, "polynomial a(u, v) (default u)"),
        ParamSpec::optional("b", ParamKind::Grid, "polynomial b(u, v) (default v)"),
        ParamSpec::optional("c", ParamKind::Grid, "polynomial c(u, v) (default 1)"),
        DOMAIN,
        OFFSET,
        ORIENTATION, DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_from_support"
op = "pn_support"
# h(u, v) = 2 + u² v
support = [[2, 0], [0, 0], [0, 1]]
domain = [0, "1/2", 0, "1/2"]
distances = ["1/2"]
"#,
    build: build_support::<Rational>,
};

fn opt_poly<T: OpScalar>(args: &OpArgs, param: &'static str, default: MPolyQ) -> Result<poly_io::MPolyIn<T>, OpError> {
    match args.opt_grid(param)? {
        Some(g) => Ok(poly_io::mpoly_in(&poly_from_grid(&g)?)),
        None => Ok(poly_io::mpoly_in(&default)),
    }
}

/// `pn_support` in `T`.
pub(crate) fn build_support<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let h = ratfn::<T>(args, "support", "support_denominator")?;
    let a = opt_poly(args, "a", poly_io::mpoly_var(2, 0))?;
    let b = opt_poly(args, "b", poly_io::mpoly_var(2, 1))?;
    let c = opt_poly(args, "c", poly_io::mpoly_constant(2, Q::from(1)))?;
    // the rectangle is checked before the (possibly long) construction
    let rect = domain(args)?;
    let surface = from_support_function(a, b, c, &h).map_err(blame("c"))?;
    surface_objects(args, &oriented(args, &surface), &rect, Vec::new(), "support")
}

// ---------------------------------------------------------------------------------
// §4.4 modeling scheme
// ---------------------------------------------------------------------------------

const PN_MODEL: OpSpec = OpSpec {
    name: "pn_model",
    summary: "a G¹ PN surface of parabolic Dupin cyclide pieces interpolating points with unit normals (Peternell §4.4: Hermite data → gradient data in I³ → C¹ Powell–Sabin quadratic spline → Λ⁻¹), with offsets",
    params: &[
        ParamSpec::required("points", ParamKind::Points, "data points A_i [x, y, z]").degree(),
        ParamSpec::required(
            "normals",
            ParamKind::Points,
            "exact rational unit normals n_i [n1, n2, n3] of the tangent planes (n ≠ (0, 0, 1))",
        ),
        ParamSpec::required(
            "triangles",
            ParamKind::Points,
            "triangulation of the isotropic parameter points: index triples [i, j, k] into `points`",
        ),
        OFFSET,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_modeled_patch"
op = "pn_model"
# data sampled from the PN surface of F = u² + v²/2 at (u, v) = (0,0), (1/2,0), (0,1/2), (1/2,1/2)
points = [[0, 0, 0], ["-4/5", 0, "-2/5"], [0, "-2/5", "-1/5"], ["-3/4", "-1/4", "-1/2"]]
normals = [[0, 0, -1], ["4/5", 0, "-3/5"], [0, "4/5", "-3/5"], ["2/3", "2/3", "-1/3"]]
triangles = [[0, 1, 3], [0, 3, 2]]
"#,
    build: build_model::<Rational>,
};

fn point3<T: OpScalar>(p: &[Q], param: &'static str, i: usize) -> Result<[T; 3], OpError> {
    <[T; 3]>::try_from(arith::all_of::<T>(p)).map_err(|_| {
        OpError::param(
            param,
            format!("entry {i} must have three coordinates, got {}", p.len()),
        )
    })
}

fn model_error(e: PnError) -> OpError {
    let msg = e.to_string();
    let param = if msg.contains("triangle") || msg.contains("edge") || msg.contains("index") {
        "triangles"
    } else {
        "normals"
    };
    OpError::param(param, msg)
}

/// `pn_model` in `T`.
pub(crate) fn build_model<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let points = args.points("points")?;
    let normals = args.points("normals")?;
    if points.len() != normals.len() {
        return Err(OpError::param(
            "normals",
            format!(
                "{} points but {} normals: give one unit normal per point",
                points.len(),
                normals.len()
            ),
        ));
    }
    let mut data = Vec::with_capacity(points.len());
    for (i, (p, n)) in points.iter().zip(&normals).enumerate() {
        data.push(
            HermiteDatum::<T>::new(point3(p, "points", i)?, point3(n, "normals", i)?)
                .map_err(|e| OpError::param("normals", format!("datum {i}: {e}")))?,
        );
    }
    let mut triangles = Vec::new();
    for (k, t) in args.points("triangles")?.iter().enumerate() {
        let idx: Option<Vec<usize>> = t
            .iter()
            .map(|x| {
                if x.is_int() {
                    usize::try_from(x.numerator()).ok()
                } else {
                    None
                }
            })
            .collect();
        match idx.as_deref() {
            Some([a, b, c]) => triangles.push([*a, *b, *c]),
            _ => {
                return Err(OpError::param(
                    "triangles",
                    format!("triangle {k} must be three non-negative integer indices"),
                ))
            }
        }
    }
    let model = PnModel::interpolate(&data, &triangles).map_err(model_error)?;
    model_objects(args, &model, "normals")
}

/// The model's object (with its offsets, one object per distance).
fn model_objects<T: OpScalar>(
    args: &OpArgs,
    model: &PnModel<T>,
    param: &'static str,
) -> Result<Vec<Object>, OpError> {
    let patches = |m: &PnModel<T>| -> Result<Vec<_>, OpError> {
        let ps = m
            .pieces()
            .iter()
            .map(|p| p.patch().map_err(|e| OpError::new(e.to_string())))
            .collect::<Result<Vec<_>, _>>()?;
        arith::exact_patches(ps)
    };
    let mut certs = model.certify();
    certs.push(regularity_cert(model, param)?);
    let main = match main_offset(args)? {
        None => patches(model)?,
        Some(d) => {
            let off = model.offset(arith::of(&d)).map_err(blame("offset"))?;
            certs.extend(prefixed("offset model: ", off.certify()));
            certs.push(regularity_cert(&off, "offset")?);
            patches(&off)?
        }
    };
    let mut out = vec![arith::object::<T>(args, Geometry::Patches(main), certs)];
    for (k, d) in distances(args)?.into_iter().enumerate() {
        let off = model.offset(arith::of(&d)).map_err(blame("distances"))?;
        let mut c = off.certify();
        c.push(regularity_cert(&off, "distances").map_err(|e| OpError {
            message: format!("distance {} (entry {k}): {}", format_rational(&d), e.message),
            param: e.param,
        })?);
        out.push(T::finish(offset_object(args, k, &d, Geometry::Patches(patches(&off)?), c)));
    }
    Ok(out)
}

fn regularity_cert<T: OpScalar>(model: &PnModel<T>, param: &'static str) -> Result<Certificate, OpError> {
    model.check_regular().map_err(|e| {
        OpError::param(
            param,
            format!("the modeled surface has a singular point (point regularity is not guaranteed by §4.4): {e}"),
        )
    })?;
    Ok(Certificate::holds(
        "every cyclide piece is regular on its micro-triangle (W ≠ 0, x_u × x_v ≠ 0)",
        T::EXACT,
    ))
}

const PN_LOFT: OpSpec = OpSpec {
    name: "pn_loft",
    summary: "a G¹ PN surface of parabolic Dupin cyclide pieces between two boundary curves with rational unit normal fields (surface strips), sampled and interpolated by the §4.4 scheme (Peternell), with offsets",
    params: &[
        ParamSpec::required(
            "curve0",
            ParamKind::Grid,
            "first boundary curve, homogeneous: four rows (W, X1, X2, X3) of power coefficients in t ∈ [0, 1]",
        ).degree(),
        ParamSpec::required(
            "normal0",
            ParamKind::Grid,
            "its unit normal field, four rows (N0, N1, N2, N3) with N1² + N2² + N3² = N0²",
        ),
        ParamSpec::required("curve1", ParamKind::Grid, "second boundary curve, like `curve0`"),
        ParamSpec::required("normal1", ParamKind::Grid, "its unit normal field, like `normal0`"),
        ParamSpec::with_default(
            "samples",
            ParamKind::Int,
            "4",
            "samples per curve at t = k/(samples − 1), 2 to 32; the strip between is split into triangles",
        ).samples(),
        OFFSET,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_torus_loft"
op = "pn_loft"
# two latitude circles (quarter arcs) of the torus R = 2, r = 1 with the torus normals
# (cos φ, sin φ) = (4/5, ±3/5): x = (2 + r cos φ)(c, s, 0) + (0, 0, r sin φ), c = (1 − t²)/(1 + t²)
curve0 = [[1, 0, 1], ["14/5", 0, "-14/5"], [0, "28/5", 0], ["3/5", 0, "3/5"]]
normal0 = [[1, 0, 1], ["4/5", 0, "-4/5"], [0, "8/5", 0], ["3/5", 0, "3/5"]]
curve1 = [[1, 0, 1], ["14/5", 0, "-14/5"], [0, "28/5", 0], ["-3/5", 0, "-3/5"]]
normal1 = [[1, 0, 1], ["4/5", 0, "-4/5"], [0, "8/5", 0], ["-3/5", 0, "-3/5"]]
samples = 5
"#,
    build: build_loft::<Rational>,
};

/// A surface strip: a curve and its unit normal field, rational functions of `t`.
type Strip = ([RatFn<Q>; 3], [RatFn<Q>; 3]);

/// A strip `(point, normal)` of rational functions in `t` from two homogeneous grids.
fn strip(
    args: &OpArgs,
    curve: &'static str,
    normal: &'static str,
) -> Result<Strip, OpError> {
    let four = |param: &'static str| -> Result<Vec<MPolyQ>, OpError> {
        let g = args.opt_grid(param)?.unwrap_or_default();
        if g.len() != 4 {
            return Err(OpError::param(
                param,
                format!("give four rows (weight first) of power coefficients in t, got {}", g.len()),
            ));
        }
        g.iter().map(|r| poly_from_list(r)).collect()
    };
    let rat = |v: &[MPolyQ], param: &'static str| -> Result<[RatFn<Q>; 3], OpError> {
        let f = |k: usize| {
            RatFn::new(v[k].clone(), v[0].clone()).map_err(|e| OpError::param(param, e.to_string()))
        };
        Ok([f(1)?, f(2)?, f(3)?])
    };
    let c = four(curve)?;
    let n = four(normal)?;
    Ok((rat(&c, curve)?, rat(&n, normal)?))
}

/// `pn_loft` in `T` (the strips are sampled in `T`).
pub(crate) fn build_loft<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let count = args.int("samples")?;
    let n = usize::try_from(count)
        .ok()
        .filter(|n| (2..=32).contains(n))
        .ok_or_else(|| OpError::param("samples", format!("give 2 to 32 samples, got {count}")))?;
    let params: Vec<T> = (0..n)
        .map(|k| arith::of(&(Q::from(k as i64) / Q::from((n - 1) as i64))))
        .collect();
    let (c0, n0) = strip(args, "curve0", "normal0")?;
    let (c1, n1) = strip(args, "curve1", "normal1")?;
    let (c0, n0, c1, n1) = (
        ratfns_in::<T, 3>(&c0),
        ratfns_in::<T, 3>(&n0),
        ratfns_in::<T, 3>(&c1),
        ratfns_in::<T, 3>(&n1),
    );
    let mut data = HermiteDatum::sample_strip(&c0, &n0, &params).map_err(blame("normal0"))?;
    data.extend(HermiteDatum::sample_strip(&c1, &n1, &params).map_err(blame("normal1"))?);
    let mut triangles = Vec::with_capacity(2 * (n - 1));
    for k in 0..n - 1 {
        triangles.push([k, k + 1, n + k + 1]);
        triangles.push([k, n + k + 1, n + k]);
    }
    let model = PnModel::interpolate(&data, &triangles)
        .map_err(|e| OpError::param("normal1", e.to_string()))?;
    model_objects(args, &model, "normal1")
}

// ---------------------------------------------------------------------------------
// ruled surfaces, canal surfaces, surfaces of revolution, ellipsoids
// ---------------------------------------------------------------------------------

const PN_RULED: OpSpec = OpSpec {
    name: "pn_ruled",
    summary: "the PN parametrization of a non-developable ruled surface l(t) + v g(t) (Peternell Cor. 4.2 via Thm 4.5) with exact rational offsets",
    params: &[
        ParamSpec::required(
            "directrix",
            ParamKind::Grid,
            "l(t): three rows (x, y, z) of power coefficients in t",
        ).degree(),
        ParamSpec::required(
            "ruling",
            ParamKind::Grid,
            "g(t): three rows (x, y, z) of power coefficients in t",
        ).degree(),
        DOMAIN,
        OFFSET,
        ORIENTATION, DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_hyperbolic_paraboloid"
op = "pn_ruled"
# l(t) = (t, 0, 0), g(t) = (0, 1, t): z = x y
directrix = [[0, 1], [0, 0], [0, 0]]
ruling = [[0, 0], [1, 0], [0, 1]]
domain = ["1/4", 1, "1/4", 1]
distances = ["1/4"]
"#,
    build: build_ruled::<Rational>,
};

/// `pn_ruled` in `T` (the splitting p₁² + p₂² = |g|² decided on the exact input).
pub(crate) fn build_ruled<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let l = three_polys(args, "directrix")?;
    let g = three_polys(args, "ruling")?;
    let p = exact_splitting::<T>(|| {
        let exact = RuledPn::<Q>::new(l.clone(), g.clone(), None).map_err(blame("ruling"))?;
        Ok(exact.envelope().p().clone())
    })?;
    let ruled = RuledPn::<T>::new(ratfns_in(&l), ratfns_in(&g), p).map_err(blame("ruling"))?;
    // every point on its ruling, tangent planes through both point families (l; 0), (l + g; 0)
    let mut certs = prefixed("ruled: ", ruled.on_ruling_certificates());
    certs.extend(prefixed("ruled: ", ruled.envelope().tangency_certificates()));
    surface_objects(args, &oriented(args, ruled.surface()), &domain(args)?, certs, "domain")
}

const PN_CANAL: OpSpec = OpSpec {
    name: "pn_canal",
    summary: "a canal surface with polynomial spine m(t) and radius r(t) as a PN surface (Peternell Cor. 4.3), with exact offsets (radius r + d)",
    params: &[
        ParamSpec::required(
            "spine",
            ParamKind::Grid,
            "m(t): three rows (x, y, z) of power coefficients in t",
        ).degree(),
        ParamSpec::required(
            "radius",
            ParamKind::Numbers,
            "power coefficients of the signed radius r(t)",
        ).degree(),
        DOMAIN,
        OFFSET,
        ORIENTATION, DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_pipe"
op = "pn_canal"
# pipe of radius 1/2 around the parabola (t, t², 0)
spine = [[0, 1, 0], [0, 0, 1], [0, 0, 0]]
radius = ["1/2"]
domain = [0, 1, 0, 1]
distances = ["1/4"]
"#,
    build: build_canal::<Rational>,
};

/// `pn_canal` in `T` (the splitting p₁² + p₂² = |m′|² − r′² decided on the exact input).
pub(crate) fn build_canal<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let m = three_polys(args, "spine")?;
    // the negative orientation envelopes the oriented family (m; −r), as the canal ops do:
    // the radius is read with the orientation's sign
    let radius = args.opt_numbers("radius")?.unwrap_or_default();
    let radius: Vec<Q> = if negative_orientation(args) {
        radius.into_iter().map(|c| -c).collect()
    } else {
        radius
    };
    let r = poly_from_list(&radius)?;
    let one = poly_io::mpoly_constant(2, Q::from(1));
    let family = |r: &MPolyQ, one: &MPolyQ| {
        CycleFamily::<T>::new(
            [0, 1, 2].map(|i| poly_io::mpoly_in(&m[i].num)),
            poly_io::mpoly_in(r),
            poly_io::mpoly_in(one),
        )
        .map_err(blame("spine"))
    };
    let p = exact_splitting::<T>(|| {
        let fam = CycleFamily::<Q>::new([0, 1, 2].map(|i| m[i].num.clone()), r.clone(), one.clone())
            .map_err(blame("spine"))?;
        let exact = CanalPn::new(fam, None).map_err(blame("radius"))?;
        Ok(exact.envelope().p().clone())
    })?;
    let canal = CanalPn::new(family(&r, &one)?, p).map_err(blame("radius"))?;
    let certs = prefixed("canal: ", canal.on_spheres_certificates());
    surface_objects(args, canal.surface(), &domain(args)?, certs, "domain")
}

const PN_CONE_ENVELOPE: OpSpec = OpSpec {
    name: "pn_cone_envelope",
    summary: "the envelope of the cones of revolution spanned by two rational cycle curves (m₁; r₁)(t), (m₂; r₂)(t) (Peternell Thm 4.5) as a PN surface in (t, u), with exact offsets (r_i ↦ r_i + d), built in the degree-reducing frame of §4.5.1 when one is rational (Prop. 4.1: unit normal of degree 2k − 2 in t); needs |m₁ − m₂|² − (r₁ − r₂)² to be a sum of two squares over Q(t)",
    params: &[
        ParamSpec::required(
            "center1",
            ParamKind::Grid,
            "numerator of m₁(t): three rows (x, y, z) of power coefficients in t",
        ).degree(),
        ParamSpec::with_default(
            "radius1",
            ParamKind::Numbers,
            "[0]",
            "power coefficients of the numerator of the signed radius r₁(t)",
        ).degree(),
        ParamSpec::with_default(
            "denominator1",
            ParamKind::Numbers,
            "[1]",
            "power coefficients of the common denominator w₁(t) of m₁ and r₁",
        ).degree(),
        ParamSpec::required(
            "center2",
            ParamKind::Grid,
            "numerator of m₂(t): three rows (x, y, z) of power coefficients in t",
        ).degree(),
        ParamSpec::with_default(
            "radius2",
            ParamKind::Numbers,
            "[0]",
            "power coefficients of the numerator of the signed radius r₂(t)",
        ).degree(),
        ParamSpec::with_default(
            "denominator2",
            ParamKind::Numbers,
            "[1]",
            "power coefficients of the common denominator w₂(t) of m₂ and r₂",
        ).degree(),
        DOMAIN,
        OFFSET,
        ORIENTATION,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_cone_envelope"
op = "pn_cone_envelope"
# c₁ = ((2t, t², 2); 3), c₂ = ((0, 1, 0); 1): |M|² − R² = (t² + 1)²
center1 = [[0, 2, 0], [0, 0, 1], [2, 0, 0]]
radius1 = [3]
center2 = [[0], [1], [0]]
radius2 = [1]
domain = [1, 2, "1/4", 1]
distances = ["1/4"]
"#,
    build: build_cone_envelope,
};

/// The cycle family `(center; radius)/denominator` of three parameters.
fn cycle_family(
    args: &OpArgs,
    center: &'static str,
    radius: &'static str,
    den: &'static str,
) -> Result<CycleFamily<Q>, OpError> {
    let m = three_polys(args, center)?;
    let r = poly_from_list(&args.opt_numbers(radius)?.unwrap_or_default())?;
    let w = poly_from_list(&args.opt_numbers(den)?.unwrap_or_else(|| vec![Q::from(1)]))?;
    CycleFamily::new([m[0].num.clone(), m[1].num.clone(), m[2].num.clone()], r, w)
        .map_err(blame(den))
}

fn build_cone_envelope(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let c1 = cycle_family(args, "center1", "radius1", "denominator1")?;
    let c2 = cycle_family(args, "center2", "radius2", "denominator2")?;
    let reduced = ReducedConeEnvelope::new(c1, c2).map_err(blame("center2"))?;
    let env = reduced.envelope();
    let mut certs = prefixed("cone family: ", env.tangency_certificates());
    certs.extend(prefixed("cone family: ", env.cone_certificates()));
    certs.extend(prefixed("degree-reducing frame: ", reduced.frame_certificates()));
    let mut objs =
        surface_objects(args, &oriented(args, env.surface()), &domain(args)?, certs, "domain")?;
    let axis = match reduced.frame() {
        Some(f) => Quantity::rationals(&f.zeta),
        None => Quantity::Text("none".into()),
    };
    let values = vec![
        NamedQuantity::new(
            "frame_axis",
            "the x₃-axis ζ of the degree-reducing frame (Peternell §4.5.1) in which the envelope was built, or none",
            axis,
        ),
        NamedQuantity::new(
            "normal_degree_t",
            "the degree in t of the unit normal's numerators (Prop. 4.1: 2k − 2 in the reducing frame)",
            Quantity::Integer(env.surface().normal_degree().0 as i64),
        ),
    ];
    if let Some(first) = objs.first_mut() {
        first.values = values;
    }
    // each offset object: the offset touches the offset cycle families (m_i; r_i ± d)
    let sign = if negative_orientation(args) { -Q::from(1) } else { Q::from(1) };
    for (k, d) in distances(args)?.into_iter().enumerate() {
        if let Some(o) = objs.get_mut(k + 1) {
            o.certificates.extend(prefixed(
                "cone family: ",
                env.offset_tangency_certificates(&(d * sign.clone())),
            ));
        }
    }
    Ok(objs)
}

const PN_DEVELOPABLE: OpSpec = OpSpec {
    name: "pn_developable",
    summary: "the developable PN surface enveloped by the planes Λ⁻¹(y(t)) of a rational curve y(t) of the isotropic model (Peternell Thm 4.3, developable case): x(t, v) = f(t) + v (P × Ṗ), rational unit normal constant along each ruling, exact offsets (planes e₀ ↦ e₀ − d)",
    params: &[
        ParamSpec::required(
            "curve",
            ParamKind::Grid,
            "numerators of y(t) = (y₁, y₂, y₃): three rows of power coefficients in t",
        ).degree(),
        ParamSpec::with_default(
            "denominator",
            ParamKind::Numbers,
            "[1]",
            "power coefficients of the common denominator of y(t)",
        ).degree(),
        ParamSpec::with_default(
            "domain",
            ParamKind::Numbers,
            "[-1, 1, -1, 1]",
            "parameter rectangle [t0, t1, v0, v1]: curve parameter t, ruling parameter v (away from the edge of regression)",
        ),
        ParamSpec::with_default(
            "form",
            ParamKind::Choice(&["edge", "foot"]),
            "\"edge\"",
            "point form: \"edge\" x = r(t) + v Q(t)/D(t) from the edge of regression r (lower degree; v = 0 is the edge, D = 0 where r is at infinity), \"foot\" x = f(t) + v Q/(Q·Q′) from the foot point f of each ruling (defined for every t); cylinders always use the foot form",
        ),
        OFFSET,
        ORIENTATION,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_developable_cubic"
op = "pn_developable"
# the twisted cubic y = (t, t², t³/3) of the isotropic model
curve = [[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "1/3"]]
domain = [1, 2, -60, -4]
distances = ["1/4"]
"#,
    build: build_developable::<Rational>,
};

/// `pn_developable` in `T`.
pub(crate) fn build_developable<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let dev = developable_arg::<T>(args)?;
    let certs = prefixed("developable: ", dev.ruling_certificates());
    if matches!(args.get("form"), Some(Value::Str(f)) if f == "foot") {
        let foot = dev.foot_point_surface().map_err(blame("curve"))?;
        return surface_objects(args, &oriented(args, &foot), &domain(args)?, certs, "domain");
    }
    surface_objects(args, &oriented(args, dev.surface()), &domain(args)?, certs, "domain")
}

/// The developable of the `curve`/`denominator` parameters (shared by the developable ops).
fn developable_arg<T: OpScalar>(args: &OpArgs) -> Result<DevelopablePn<T>, OpError> {
    let c = three_polys(args, "curve")?;
    let den = poly_from_list(&args.opt_numbers("denominator")?.unwrap_or_else(|| vec![Q::from(1)]))?;
    let den = poly_io::mpoly_in::<T>(&den);
    let [y1, y2, y3] = c.map(|ci| {
        RatFn::new(poly_io::mpoly_in(&ci.num), den.clone()).map_err(blame("denominator"))
    });
    DevelopablePn::from_isotropic_curve(&[y1?, y2?, y3?]).map_err(blame("curve"))
}

const CURVE_PARAM: ParamSpec = ParamSpec::required(
    "curve",
    ParamKind::Grid,
    "numerators of the isotropic curve y(t) = (y₁, y₂, y₃) (its planes Λ⁻¹(y(t)) are the tangent planes of the developable): three rows of power coefficients in t",
).degree();
const CURVE_DENOMINATOR: ParamSpec = ParamSpec::with_default(
    "denominator",
    ParamKind::Numbers,
    "[1]",
    "power coefficients of the common denominator of y(t)",
).degree();

const PN_DEVELOPABLE_EDGE: OpSpec = OpSpec {
    name: "pn_developable_edge",
    summary: "the edge of regression r = e ∩ ė ∩ ë of the developable PN surface of a rational isotropic curve y(t) (Peternell Thm 4.3, developable case; §4.5 remark before Cor. 4.3) as a rational curve, with the edges of regression of its offsets r + d n + d κ (n × ṅ), κ = |ṅ|²/det(n, ṅ, n̈); cylinders and cones are named errors",
    params: &[
        CURVE_PARAM,
        CURVE_DENOMINATOR,
        ParamSpec::with_default(
            "interval",
            ParamKind::Numbers,
            "[0, 1]",
            "parameter interval [t0, t1] (the edge must be finite there: D = det(P, Ṗ, P̈) ≠ 0)",
        ),
        DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_developable_cubic_edge"
op = "pn_developable_edge"
# the edge of regression of the developable of y = (t, t², t³/3) and of its offset at 1/4
curve = [[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "1/3"]]
interval = [1, "3/2"]
distances = ["1/4"]
"#,
    build: build_developable_edge::<Rational>,
};

/// `pn_developable_edge` in `T`.
pub(crate) fn build_developable_edge<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let dev = developable_arg::<T>(args)?;
    let iv = args.opt_numbers("interval")?.unwrap_or_else(|| vec![Q::from(0), Q::from(1)]);
    let [t0, t1]: [T; 2] = arith::array(&iv, "interval", "give two numbers [t0, t1]")?;
    let edge = dev.edge_of_regression().map_err(blame("curve"))?;
    let mut certs = prefixed("developable: ", dev.certify());
    certs.extend(edge.certify());
    let bez = edge.curve(&t0, &t1).map_err(blame("interval"))?;
    let mut out = vec![arith::object::<T>(args, Geometry::Curve(T::exact_curve(bez)?), certs)];
    for (k, d) in distances(args)?.into_iter().enumerate() {
        let off = dev.offset_edge(arith::of(&d)).map_err(blame("distances"))?;
        let c = off.certify();
        let bez = off.curve(&t0, &t1).map_err(|e| {
            OpError::param(
                "distances",
                format!("distance {} (entry {k}): {e}", format_rational(&d)),
            )
        })?;
        let geometry = Geometry::Curve(T::exact_curve(bez)?);
        out.push(T::finish(offset_object(args, k, &d, geometry, c)));
    }
    Ok(out)
}

const PN_DEVELOPABLE_MOTION: OpSpec = OpSpec {
    name: "pn_developable_motion",
    summary: "the envelope of a developable PN surface (planes Λ⁻¹(y(t)) of a rational isotropic curve) moved by the rational motions x ↦ R(u) x + b(u), R the rotation about a coordinate axis by 2 atan u, or by any rational family of Laguerre maps given in the form (4.21) (`family`; Peternell Prop. 4.2, (4.21)): a PN surface with exact offsets; certified AᵀEA ≡ κE, contact with every moved developable",
    params: &[
        CURVE_PARAM,
        CURVE_DENOMINATOR,
        AXIS,
        TRANSLATION,
        LAGUERRE_FAMILY,
        ParamSpec::with_default(
            "domain",
            ParamKind::Numbers,
            "[-1, 1, -1, 1]",
            "parameter rectangle [t0, t1, u0, u1]: t of the developable's planes, u of the motion",
        ),
        OFFSET,
        ORIENTATION,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_developable_motion_screw"
op = "pn_developable_motion"
# Peternell §4.6: the parabolic cylinder y = (2t/(1+t²), (t²−1)/(1+t²), −(1+t²)/t)
# moved by screw motions about the x-axis (rotation 2 atan u, translation −u/4)
curve = [[0, 0, 2, 0, 0], [0, -1, 0, 1, 0], [-1, 0, -2, 0, -1]]
denominator = [0, 1, 0, 1]
axis = "x"
translation = [[0, "-1/4"], [0, 0], [0, 0]]
domain = ["3/2", 4, "-6/5", "6/5"]
distances = ["1/2"]
"#,
    build: build_developable_motion::<Rational>,
};

/// `pn_developable_motion` in `T`.
pub(crate) fn build_developable_motion<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let dev = developable_arg::<T>(args)?;
    let fam = laguerre_family::<T>(args)?;
    let env = DevelopableMotionEnvelope::new(&dev, &fam).map_err(blame("translation"))?;
    let mut certs = prefixed("developable: ", dev.certify());
    certs.extend(env.family().certificates());
    certs.extend(env.contact_certificates());
    surface_objects(args, &oriented(args, env.surface()), &domain(args)?, certs, "domain")
}

const AXIS: ParamSpec = ParamSpec::with_default(
    "axis",
    ParamKind::Choice(&["x", "y", "z"]),
    "\"z\"",
    "rotation axis of the motions",
);
const TRANSLATION: ParamSpec = ParamSpec::optional(
    "translation",
    ParamKind::Grid,
    "translation b(u) of the motions: three rows of power coefficients in the family parameter (needed unless `family` is given)",
).degree();
const LAGUERRE_FAMILY: ParamSpec = ParamSpec::optional(
    "family",
    ParamKind::Grid,
    "any rational family of Laguerre maps in the form (4.21), ε ↦ ε·[[w, 0], [a, A]](u), instead of axis/translation: 21 rows of power coefficients in the family parameter — w, then a₁, a₂, a₃, a₄, then the 16 entries of A row by row (A[i][j] multiplies εᵢ into ε'ⱼ; oriented planes are ε = (e₀, n, 1)); AᵀEA ≡ κE (E = diag(1, 1, 1, −1)) is required and certified",
).degree();

/// The family of the `family` parameter (any (4.21) family), else the screw family of the
/// `axis` and `translation` parameters.
fn laguerre_family<T: OpScalar>(args: &OpArgs) -> Result<LaguerreFamily<T>, OpError> {
    if args.get("family").is_none() {
        return screw_family(args);
    }
    let rows: [RatFn<Q>; 21] = n_polys(args, "family", "w, a₁…a₄, A₁₁…A₄₄")?;
    let p = |i: usize| poly_io::mpoly_in::<T>(&rows[i].num);
    LaguerreFamily::new(
        p(0),
        [p(1), p(2), p(3), p(4)],
        core::array::from_fn(|i| core::array::from_fn(|j| p(5 + 4 * i + j))),
    )
    .map_err(blame("family"))
}

/// The screw family of the `axis` and `translation` parameters.
fn screw_family<T: OpScalar>(args: &OpArgs) -> Result<LaguerreFamily<T>, OpError> {
    if args.get("translation").is_none() {
        return Err(OpError::param(
            "translation",
            "give the translation b(u) of the screw family (three rows), or a general `family`",
        ));
    }
    let axis = match args.get("axis") {
        Some(Value::Str(a)) if a == "x" => 0,
        Some(Value::Str(a)) if a == "y" => 1,
        _ => 2,
    };
    let b = three_polys(args, "translation")?;
    LaguerreFamily::screw_about(axis, [0, 1, 2].map(|i| poly_io::mpoly_in(&b[i].num)))
        .map_err(blame("translation"))
}

/// A cycle `[m₁, m₂, m₃, r]` parameter.
fn cycle_arg<T: OpScalar>(args: &OpArgs, param: &'static str) -> Result<Cycle<T>, OpError> {
    let p = args.opt_point(param)?.unwrap_or_default();
    let [m1, m2, m3, r]: [T; 4] = arith::array(&p, param, "give a cycle [m1, m2, m3, r]")?;
    Cycle::new([m1, m2, m3], r).map_err(|e| OpError::param(param, e.to_string()))
}

const PN_CONE_MOTION: OpSpec = OpSpec {
    name: "pn_cone_motion",
    summary: "the envelope of a cone of revolution (spanned by two cycles) moved by the rational motions x ↦ R(t) x + b(t), R the rotation about a coordinate axis by 2 atan t, or by any rational family of Laguerre maps in the form (4.21) (`family`; Peternell Cor. 4.4 via Thm 4.5): a PN surface with exact offsets, touching every moved cone along a curve",
    params: &[
        ParamSpec::required(
            "cycle1",
            ParamKind::Point,
            "first cycle [m1, m2, m3, r] spanning the cone (r = 0: the vertex)",
        ),
        ParamSpec::required(
            "cycle2",
            ParamKind::Point,
            "second cycle [m1, m2, m3, r] (|m₁ − m₂|² > (r₁ − r₂)²)",
        ),
        AXIS,
        TRANSLATION,
        LAGUERRE_FAMILY,
        ParamSpec::with_default(
            "domain",
            ParamKind::Numbers,
            "[-1, 1, -1, 1]",
            "parameter rectangle [t0, t1, u0, u1]: t of the motion, u around the moved cone",
        ),
        OFFSET,
        ORIENTATION,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_cone_motion_parabola"
op = "pn_cone_motion"
# the cone with vertex 0 and axis x (opening angle: sin = 3/5) turning about z while its
# vertex runs along the parabola (t, t²/2, 0)
cycle1 = [0, 0, 0, 0]
cycle2 = [5, 0, 0, 3]
axis = "z"
translation = [[0, 1, 0], [0, 0, "1/2"], [0, 0, 0]]
domain = ["1/4", "3/4", "1/4", "3/4"]
distances = ["1/4"]
"#,
    build: build_cone_motion::<Rational>,
};

/// `pn_cone_motion` in `T`.
pub(crate) fn build_cone_motion<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let c1 = cycle_arg::<T>(args, "cycle1")?;
    let c2 = cycle_arg::<T>(args, "cycle2")?;
    let fam = laguerre_family::<T>(args)?;
    let env = moved_cone_envelope(&c1, &c2, &fam).map_err(blame("cycle2"))?;
    let (f1, f2) = env.families();
    let mut certs = fam.certificates();
    certs.extend(fam.cycle_image_certificates(&c1, f1));
    certs.extend(fam.cycle_image_certificates(&c2, f2));
    certs.extend(prefixed("cone family: ", env.tangency_certificates()));
    certs.extend(prefixed("cone family: ", env.cone_certificates()));
    surface_objects(args, &oriented(args, env.surface()), &domain(args)?, certs, "domain")
}

/// Four polynomials in `t` from a grid of four rows of power coefficients.
fn four_polys(args: &OpArgs, param: &'static str) -> Result<[RatFn<Q>; 4], OpError> {
    n_polys(args, param, "m₁, m₂, m₃, r")
}

const PN_RULED_CYCLOGRAPHIC: OpSpec = OpSpec {
    name: "pn_ruled_cyclographic",
    summary: "the cyclographic image of a non-developable ruled surface l(t) + s g(t) of R⁴ (points (m, r) are cycles): the envelope of the cones of revolution of its rulings, a PN surface (Peternell Cor. 4.1 via Thm 4.5); needs ⟨g, g⟩ = |g₁₋₃|² − g₄² to be a sum of two squares over Q(t)",
    params: &[
        ParamSpec::required(
            "directrix",
            ParamKind::Grid,
            "l(t) = (m₁, m₂, m₃, r): four rows of power coefficients in t",
        ).degree(),
        ParamSpec::required(
            "ruling",
            ParamKind::Grid,
            "g(t): four rows of power coefficients in t (spacelike: |g₁₋₃|² > g₄²)",
        ).degree(),
        DOMAIN,
        OFFSET,
        ORIENTATION,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_ruled_cyclographic_r4"
op = "pn_ruled_cyclographic"
# l(t) = (t, 0, 0; t²/2), g(t) = (0, 5, t; 3): ⟨g, g⟩ = t² + 16
directrix = [[0, 1, 0], [0, 0, 0], [0, 0, 0], [0, 0, "1/2"]]
ruling = [[0, 0, 0], [5, 0, 0], [0, 1, 0], [3, 0, 0]]
domain = ["1/4", "3/4", "1/4", "3/4"]
distances = ["-1/10"]
"#,
    build: build_ruled_cyclographic,
};

fn build_ruled_cyclographic(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let l = four_polys(args, "directrix")?;
    let g = four_polys(args, "ruling")?;
    let env = ruled_surface_image(l, g).map_err(blame("ruling"))?;
    let mut certs = prefixed("cone family: ", env.tangency_certificates());
    certs.extend(prefixed("cone family: ", env.cone_certificates()));
    surface_objects(args, &oriented(args, env.surface()), &domain(args)?, certs, "domain")
}

const PN_REVOLUTION: OpSpec = OpSpec {
    name: "pn_revolution",
    summary: "the surface of revolution (about the z-axis) of a polynomial PH profile with preimage (u(t), v(t)) — a PN surface whose offsets are the surfaces of revolution of the profile's offsets",
    params: &[
        ParamSpec::required(
            "u",
            ParamKind::Numbers,
            "Bernstein coefficients of the preimage u(t) on [0, 1] (hodograph (u² − v², 2uv) in the (ρ, z) half-plane)",
        ).degree(),
        ParamSpec::required(
            "v",
            ParamKind::Numbers,
            "Bernstein coefficients of v(t), as many as u",
        ).degree(),
        ParamSpec::with_default(
            "start",
            ParamKind::Point2,
            "[1, 0]",
            "profile start point (ρ, z)",
        ),
        ParamSpec::with_default(
            "domain",
            ParamKind::Numbers,
            "[0, 1, 0, 1]",
            "rectangle [t0, t1, s0, s1]: profile parameter t, rotation parameter s (angle 2 atan s)",
        ),
        OFFSET,
        ORIENTATION, DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_revolution_ph_cubic"
op = "pn_revolution"
u = [1, 2]
v = [1, 0]
start = [2, 0]
distances = ["1/2"]
"#,
    build: build_revolution::<Rational>,
};

/// `pn_revolution` in `T`.
pub(crate) fn build_revolution<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let u = arith::all_of::<T>(&args.opt_numbers("u")?.unwrap_or_default());
    let v = arith::all_of::<T>(&args.opt_numbers("v")?.unwrap_or_default());
    let start: [T; 2] = arith::point(args, "start", "the start point needs two coordinates")?;
    let profile = PnCurve::from_ph_preimage(&u, &v, start).map_err(blame("v"))?;
    let surface = surface_of_revolution(&profile).map_err(blame("u"))?;
    let certs = prefixed("profile: ", profile.certify());
    surface_objects(args, &oriented(args, &surface), &domain(args)?, certs, "domain")
}

const PN_ELLIPSOID: OpSpec = OpSpec {
    name: "pn_ellipsoid",
    summary: "the ellipsoid x²/a² + y²/b² + z²/c² = 1 as a PN surface in the umbilic frame of Peternell §4.7 (envelope of cones of revolution with vertices on the focal hyperbola), with exact rational offsets",
    params: &[
        ParamSpec::required("a", ParamKind::Number, "largest semi-axis"),
        ParamSpec::required("b", ParamKind::Number, "middle semi-axis (a ≥ b ≥ c > 0, a > c)"),
        ParamSpec::required(
            "c",
            ParamKind::Number,
            "smallest semi-axis; √(b²−c²)·√(a²−b²) and √(ac) must be rational",
        ),
        ParamSpec::with_default(
            "domain",
            ParamKind::Numbers,
            "[\"1/4\", \"3/4\", -1, 1]",
            "parameter rectangle [t0, t1, u0, u1] (t = ±1 are poles)",
        ),
        OFFSET,
        ORIENTATION, DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_ellipsoid_4_7"
op = "pn_ellipsoid"
# the triaxial ellipsoid of Peternell §4.7: α = 4, γ = 20/3, μ = 5
a = "25/3"
b = 5
c = 3
domain = ["1/4", "1/2", 0, "1/2"]
distances = [1]
"#,
    build: build_ellipsoid,
};

fn build_ellipsoid(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let ell = EllipsoidPn::new(args.number("a")?, args.number("b")?, args.number("c")?)
        .map_err(blame("c"))?;
    let surface = oriented(args, ell.surface());
    let mut objs = surface_objects(args, &surface, &domain(args)?, Vec::new(), "domain")?;
    // the dual quadric identity e0² = nᵀK*n for the base and every offset (with h − d)
    if let Some(first) = objs.first_mut() {
        first
            .certificates
            .push(ell.dual_quadric_certificate(&surface));
    }
    if let (Some(d), Some(first)) = (main_offset(args)?, objs.first_mut()) {
        let off = surface.offset(d);
        first
            .certificates
            .push(ell.dual_quadric_certificate(off.surface()));
    }
    for (k, d) in distances(args)?.into_iter().enumerate() {
        if let Some(o) = objs.get_mut(k + 1) {
            let off = surface.offset(d);
            o.certificates
                .push(ell.dual_quadric_certificate(off.surface()));
        }
    }
    Ok(objs)
}

// ---------------------------------------------------------------------------------
// regular quadrics (Theorem 4.6) and hypercyclides (Prop. 4.3)
// ---------------------------------------------------------------------------------

const QUADRIC_KIND: ParamSpec = ParamSpec::required(
    "quadric",
    ParamKind::Choice(&["ellipsoid", "two_sheet_hyperboloid", "elliptic_paraboloid"]),
    "ellipsoid x²/a² + y²/b² + z²/c² = 1 (a > b > c > 0), two_sheet_hyperboloid x²/a² − y²/b² − z²/c² = 1 (b > c > 0), elliptic_paraboloid x²/a² + y²/b² = 2z (a > b > 0; c unused)",
);
const QA: ParamSpec = ParamSpec::required("a", ParamKind::Number, "first axis parameter a");
const QB: ParamSpec = ParamSpec::required("b", ParamKind::Number, "second axis parameter b");
const QC: ParamSpec = ParamSpec::with_default(
    "c",
    ParamKind::Number,
    "0",
    "third axis parameter c (not used by the elliptic paraboloid)",
);
const FAMILY: ParamSpec = ParamSpec::with_default(
    "family",
    ParamKind::Choice(&["first", "second"]),
    "\"first\"",
    "which of the two ruling families of the ruled quadric ψ of the pencil gives the cones",
);

fn regular_quadric(args: &OpArgs) -> Result<RegularQuadric, OpError> {
    let (a, b) = (args.number("a")?, args.number("b")?);
    let c = args.opt_number("c")?.unwrap_or_default();
    Ok(match args.get("quadric") {
        Some(Value::Str(s)) if s == "two_sheet_hyperboloid" => {
            RegularQuadric::TwoSheetHyperboloid { a, b, c }
        }
        Some(Value::Str(s)) if s == "elliptic_paraboloid" => {
            RegularQuadric::EllipticParaboloid { a, b }
        }
        _ => RegularQuadric::Ellipsoid { a, b, c },
    })
}

fn first_family(args: &OpArgs) -> bool {
    !matches!(args.get("family"), Some(Value::Str(s)) if s == "second")
}

/// The objects of a hypercyclide (or quadric) with the certificates of the cyclographic
/// image on the base surface and on every offset.
fn hypercyclide_objects(args: &OpArgs, h: &Hypercyclide<Q>) -> Result<Vec<Object>, OpError> {
    let mut certs = h.rulings().certify();
    certs.extend(prefixed("cones: ", h.envelope().tangency_certificates()));
    certs.extend(prefixed("cones: ", h.envelope().cone_certificates()));
    certs.extend(h.image_certificates(h.surface()));
    if let Some(d) = main_offset(args)? {
        certs.extend(h.image_certificates(h.surface().offset(d).surface()));
    }
    let mut objs = surface_objects(
        args,
        &oriented(args, h.surface()),
        &domain(args)?,
        certs,
        "domain",
    )?;
    for (k, d) in distances(args)?.into_iter().enumerate() {
        if let Some(o) = objs.get_mut(k + 1) {
            o.certificates
                .extend(h.image_certificates(h.surface().offset(d).surface()));
        }
    }
    Ok(objs)
}

const PN_QUADRIC: OpSpec = OpSpec {
    name: "pn_quadric",
    summary: "a regular quadric (ellipsoid, two-sheet hyperboloid, elliptic paraboloid) in its principal frame as a PN surface with exact rational offsets (Peternell Thm 4.6): envelope of the cones of revolution of the rulings of the ruled quadric ψ of the pencil φ* + μΩ*; a two-sheet hyperboloid whose rulings give no rational family falls back to the unirational parametrization of pn_two_sheet_hyperboloid (parameters τ, σ; it covers the wedge |z| ≥ k|x − a| of both sheets, docs/math/hypercyclides.md#two-sheet-region)",
    params: &[
        QUADRIC_KIND,
        QA,
        QB,
        QC,
        FAMILY,
        ParamSpec::with_default(
            "domain",
            ParamKind::Numbers,
            "[\"1/4\", \"3/4\", -1, 1]",
            "parameter rectangle [s0, s1, u0, u1] (s: the double-cover parameter of the rulings, u: along the characteristic conics); for the two-sheet hyperboloid (unirational construction) [τ0, τ1, σ0, σ1], avoiding σ = 0 (the vertex)",
        ),
        OFFSET,
        ORIENTATION,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_quadric_ellipsoid"
op = "pn_quadric"
# the ellipsoid (25/3, 5, 3) of Peternell §4.7, here in its principal frame
quadric = "ellipsoid"
a = "25/3"
b = 5
c = 3
domain = [20, 70, -1, 1]
distances = [1]
"#,
    build: build_pn_quadric,
};

fn build_pn_quadric(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    match QuadricPn::<Q>::new(regular_quadric(args)?, first_family(args)).map_err(blame("a"))? {
        QuadricPn::Rulings(h) => hypercyclide_objects(args, &h),
        QuadricPn::TwoSheet { pn, .. } => two_sheet_objects(args, &pn),
    }
}

const PN_TWO_SHEET: OpSpec = OpSpec {
    name: "pn_two_sheet_hyperboloid",
    summary: "the two-sheet hyperboloid x²/a² − y²/b² − z²/c² = 1 (b² ≠ c²) as a PN surface with exact rational offsets for every rational a, b, c: a degree-2 unirational parametrization of its tangent planes (the conic bundle through the vertex normal, base-changed along its 2-section; docs/math/hypercyclides.md#two-sheet-unirational), certified PN and on the quadric",
    params: &[
        ParamSpec::required("a", ParamKind::Number, "semi-axis a (the real axis x)"),
        ParamSpec::required("b", ParamKind::Number, "semi-axis b"),
        ParamSpec::required("c", ParamKind::Number, "semi-axis c, c² ≠ b²"),
        ParamSpec::with_default(
            "domain",
            ParamKind::Numbers,
            "[\"3/2\", 3, \"1/4\", 1]",
            "parameter rectangle [τ0, τ1, σ0, σ1]; avoid τ = 0 and σ = 0, which map to the vertex (a, 0, 0)",
        ),
        OFFSET,
        ORIENTATION,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_two_sheet"
op = "pn_two_sheet_hyperboloid"
a = 9
b = 13
c = 3
domain = ["3/2", 3, "1/4", 1]
"#,
    build: build_pn_two_sheet::<Rational>,
};

/// `pn_two_sheet_hyperboloid` in `T`.
pub(crate) fn build_pn_two_sheet<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let n = |k: &'static str| arith::number::<T>(args, k);
    let h = TwoSheetPn::<T>::new(n("a")?, n("b")?, n("c")?).map_err(blame("c"))?;
    two_sheet_objects(args, &h)
}

/// The objects of the two-sheet hyperboloid's unirational PN parametrization with the
/// tangency certificates on the base surface and on every offset.
fn two_sheet_objects<T: OpScalar>(args: &OpArgs, h: &TwoSheetPn<T>) -> Result<Vec<Object>, OpError> {
    let s = oriented(args, h.surface());
    let mut certs = vec![h.quadric_certificate()];
    certs.extend(h.tangency_certificates(h.surface()));
    if let Some(d) = main_offset(args)? {
        certs.extend(h.tangency_certificates(s.offset(arith::of(&d)).surface()));
    }
    let mut objs = surface_objects(args, &s, &domain(args)?, certs, "domain")?;
    for (k, d) in distances(args)?.into_iter().enumerate() {
        if let Some(o) = objs.get_mut(k + 1) {
            o.certificates
                .extend(h.tangency_certificates(s.offset(arith::of(&d)).surface()));
        }
    }
    Ok(objs)
}

const HYPERCYCLIDE: OpSpec = OpSpec {
    name: "hypercyclide",
    summary: "the hypercyclide η(L(φ)): cyclographic image of a regular quadric φ moved into a (tilted) Euclidean hyperplane of R⁴ by a rational pe similarity L (boost, translation, scale), as a PN surface (Peternell Prop. 4.3, §4.7), certified as the envelope of the cycles of L(φ)",
    params: &[
        QUADRIC_KIND,
        QA,
        QB,
        QC,
        FAMILY,
        ParamSpec::with_default(
            "boost_axis",
            ParamKind::Int,
            "0",
            "axis 0, 1 or 2 of the Lorentz boost in the (x_axis, r) plane",
        ),
        ParamSpec::with_default(
            "boost",
            ParamKind::Number,
            "0",
            "boost parameter β (cosh = (1 + β²)/(1 − β²)), β² ≠ 1",
        ),
        ParamSpec::with_default(
            "translation",
            ParamKind::Numbers,
            "[0, 0, 0, 0]",
            "translation (x, y, z, r) of R⁴ (r: a dilatation, i.e. an offset)",
        ),
        ParamSpec::with_default("scale", ParamKind::Number, "1", "similarity factor s ≠ 0"),
        ParamSpec::with_default(
            "domain",
            ParamKind::Numbers,
            "[\"1/4\", \"3/4\", -1, 1]",
            "parameter rectangle [s0, s1, u0, u1]",
        ),
        OFFSET,
        ORIENTATION,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "hypercyclide_boosted_paraboloid"
op = "hypercyclide"
# the paraboloid x²/25 + y²/9 = 2z in the hyperplane tilted by the boost β = 1/3
quadric = "elliptic_paraboloid"
a = 5
b = 3
boost_axis = 1
boost = "1/3"
translation = [0, 0, 0, "1/2"]
domain = [4, 8, "-1/2", "1/2"]
"#,
    build: build_hypercyclide,
};

fn build_hypercyclide(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let axis = usize::try_from(args.int("boost_axis")?)
        .map_err(|_| OpError::param("boost_axis", "the boost axis must be 0, 1 or 2"))?;
    let t = args.opt_numbers("translation")?.unwrap_or_default();
    let t: [Q; 4] = <[Q; 4]>::try_from(t).map_err(|_| {
        OpError::param("translation", "the translation needs four numbers (x, y, z, r)")
    })?;
    let mut map = PeSimilarity::boost(axis, args.number("boost")?, t).map_err(blame("boost"))?;
    map.s = args.number("scale")?;
    let h = Hypercyclide::<Q>::new(regular_quadric(args)?, map, first_family(args))
        .map_err(blame("a"))?;
    hypercyclide_objects(args, &h)
}

/// The parameters `x, y, z, r` of a rational 2-surface `(m; r)` of R⁴ (numerators in power form).
const SURFACE_X: ParamSpec = ParamSpec::required(
    "x",
    ParamKind::Grid,
    "power coefficients c[i][j] of u^i v^j of the numerator of m₁",
)
.degree();
const SURFACE_Y: ParamSpec =
    ParamSpec::required("y", ParamKind::Grid, "numerator of m₂ (same layout)");
const SURFACE_Z: ParamSpec =
    ParamSpec::required("z", ParamKind::Grid, "numerator of m₃ (same layout)");
const SURFACE_R: ParamSpec =
    ParamSpec::required("r", ParamKind::Grid, "numerator of the radius r (same layout)");
const SHEET: ParamSpec = ParamSpec::with_default(
    "sheet",
    ParamKind::Int,
    "1",
    "which sheet of the image: 1 or 2 (a γ-surface has only sheet 1)",
);

const REPARAMETRIZE: ParamSpec = ParamSpec::with_default(
    "reparametrize",
    ParamKind::Choice(&["none", "quadric"]),
    "\"none\"",
    "\"quadric\": if Δ is not a square but its odd part δ has degree 1 or 2, reparametrize (u, v) by the stereographic projection of the quadric w² = δ(u, v) from a rational point (docs/math/hypercyclides.md#non-square-delta); the domain is then in the new parameters",
);

const CYCLOGRAPHIC_SURFACE: OpSpec = OpSpec {
    name: "cyclographic_surface",
    summary: "the cyclographic image of a rational 2-surface s(u, v) = (m; r) of R⁴ (Peternell §3.9, Lemma 3.5): one sheet of the envelope of its cycles, rational when Δ is a square (one sheet for a γ-surface), as a PN surface",
    params: &[
        SURFACE_X,
        SURFACE_Y,
        SURFACE_Z,
        SURFACE_R,
        DENOMINATOR,
        SHEET,
        REPARAMETRIZE,
        DOMAIN,
        OFFSET,
        ORIENTATION,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "cyclographic_spheres_on_a_plane"
op = "cyclographic_surface"
# the spheres (u, v, −ρ; ρ), ρ = (u² + v²)/4 + 2, all touch z = 0; sheet 2 is their
# other envelope
x = [[0, 0], [1, 0]]
y = [[0, 1]]
z = [[-2, 0, "-1/4"], [0, 0, 0], ["-1/4", 0, 0]]
r = [[2, 0, "1/4"], [0, 0, 0], ["1/4", 0, 0]]
sheet = 2
domain = [-1, 1, -1, 1]
"#,
    build: build_cyclographic_surface,
};

fn build_cyclographic_surface(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (img, k) = cyclographic_sheet(args)?;
    let sheet = img.sheets().get(k).ok_or_else(|| OpError::param("sheet", "no such sheet"))?;
    let mut certs = img.image_certificates(sheet);
    if let Some(d) = main_offset(args)? {
        certs.extend(img.image_certificates(sheet.offset(d).surface()));
    }
    let mut objs = surface_objects(args, &oriented(args, sheet), &domain(args)?, certs, "domain")?;
    for (i, d) in distances(args)?.into_iter().enumerate() {
        if let Some(o) = objs.get_mut(i + 1) {
            o.certificates
                .extend(img.image_certificates(sheet.offset(d).surface()));
        }
    }
    Ok(objs)
}

/// The cyclographic image of the `cyclographic_surface` / `cyclographic_section`
/// parameters and the index of the sheet asked for.
fn cyclographic_sheet(args: &OpArgs) -> Result<(CyclographicImage, usize), OpError> {
    let g = |p: &'static str| -> Result<MPolyQ, OpError> {
        poly_from_grid(&args.opt_grid(p)?.unwrap_or_default())
    };
    let w = match args.opt_grid("denominator")? {
        Some(d) => poly_from_grid(&d)?,
        None => poly_io::mpoly_constant(2, Q::from(1)),
    };
    let s = [g("x")?, g("y")?, g("z")?, g("r")?];
    let img = if args.string("reparametrize")? == "quadric" {
        CyclographicImage::reparametrized(s, w)
            .map_err(blame("reparametrize"))?
            .0
    } else {
        CyclographicImage::new(s, w).map_err(blame("r"))?
    };
    let k = args.int("sheet")?;
    let i = usize::try_from(k - 1)
        .ok()
        .filter(|i| *i < img.sheets().len())
        .ok_or_else(|| {
            OpError::param(
                "sheet",
                format!(
                    "the image has {} sheet(s) (a γ-surface has one), got sheet {k}",
                    img.sheets().len()
                ),
            )
        })?;
    Ok((img, i))
}

const CYCLOGRAPHIC_SECTION: OpSpec = OpSpec {
    name: "cyclographic_section",
    summary: "the section Γ(φ) ∩ π of the γ-hypersurface of the cyclographic image of a rational 2-surface s(u, v) = (m; r) of R⁴ by a hyperplane π of R⁴ (Peternell §3.9): the cycle of π in oriented contact with each surface element, drawn by its top view; for π ∥ R³ (y₄ = c) the top view is the offset at distance −c",
    params: &[
        SURFACE_X,
        SURFACE_Y,
        SURFACE_Z,
        SURFACE_R,
        DENOMINATOR,
        SHEET,
        REPARAMETRIZE,
        ParamSpec::required(
            "hyperplane",
            ParamKind::Numbers,
            "π: h₀ + h₁y₁ + h₂y₂ + h₃y₃ + h₄y₄ = 0 as [h₀, h₁, h₂, h₃, h₄]; [−c, 0, 0, 0, 1] is y₄ = c",
        ),
        DOMAIN,
    ],
    example: r#"[[object]]
name = "cyclographic_section_offset"
op = "cyclographic_section"
# the second sheet of the spheres (u, v, −ρ; ρ), ρ = (u² + v²)/4 + 2, cut by y₄ = −1/2:
# the top view is its offset at distance 1/2
x = [[0, 0], [1, 0]]
y = [[0, 1]]
z = [[-2, 0, "-1/4"], [0, 0, 0], ["-1/4", 0, 0]]
r = [[2, 0, "1/4"], [0, 0, 0], ["1/4", 0, 0]]
sheet = 2
hyperplane = ["1/2", 0, 0, 0, 1]
domain = [-1, 1, -1, 1]
"#,
    build: build_cyclographic_section,
};

fn build_cyclographic_section(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (img, k) = cyclographic_sheet(args)?;
    let sheet = img.sheets().get(k).ok_or_else(|| OpError::param("sheet", "no such sheet"))?;
    let h = args.opt_numbers("hyperplane")?.unwrap_or_default();
    let h: [Q; 5] = <[Q; 5]>::try_from(h).map_err(|h| {
        OpError::param(
            "hyperplane",
            format!("give five numbers [h₀, h₁, h₂, h₃, h₄], got {}", h.len()),
        )
    })?;
    let sec = GammaSection::new(sheet, h).map_err(blame("hyperplane"))?;
    let dom: Domain<Q> = domain(args)?;
    let mut certs = prefixed("image sheet: ", sheet.certify());
    certs.extend(img.image_certificates(sheet));
    certs.extend(sec.certify());
    let patch = sec.top_view_patch(&dom).map_err(blame("domain"))?;
    Ok(vec![args.object(Geometry::Patch(patch), certs)])
}

const PN_FOCAL_SURFACE: OpSpec = OpSpec {
    name: "pn_focal_surface",
    summary: "a focal sheet (locus of principal curvature centres) of the PN surface of a graph F(u, v) of the isotropic model, rational when the principal radii are (D = B² − 4AC a square; e.g. F_uv ≡ 0); or, with output = \"image\", the cyclographic image of that family's curvature spheres — a γ-surface of R⁴ (Peternell §3.9) — which is the PN surface again",
    params: &[
        COEFFICIENTS,
        DENOMINATOR,
        ParamSpec::with_default(
            "sheet",
            ParamKind::Int,
            "1",
            "which focal sheet: 1 or 2 (a sphere or a developable has only sheet 1)",
        ),
        ParamSpec::with_default(
            "output",
            ParamKind::Choice(&["focal", "image"]),
            "\"focal\"",
            "\"focal\": the focal sheet; \"image\": the cyclographic image of the sheet's curvature-sphere γ-surface",
        ),
        DOMAIN,
        OFFSET,
        ORIENTATION,
        DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_focal_sheet_cubic"
op = "pn_focal_surface"
# F = u³/6 + v²/2: principal radii rational (F_uv ≡ 0); sheet 1 belongs to the
# eigenvalue u of the Hessian, a genuine surface
coefficients = [[0, 0, "1/2"], [0, 0, 0], [0, 0, 0], ["1/6", 0, 0]]
domain = ["1/2", 1, 0, "1/2"]
"#,
    build: build_pn_focal_surface,
};

fn build_pn_focal_surface(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let f: RatFn<Q> = ratfn(args, "coefficients", "denominator")?;
    let surface = IsotropicSurface::graph(&f)
        .to_pn_surface()
        .map_err(blame("coefficients"))?;
    let foc = FocalSurfaces::new(&surface).map_err(blame("coefficients"))?;
    let k = args.int("sheet")?;
    let sheet = usize::try_from(k - 1)
        .ok()
        .and_then(|i| foc.sheets().get(i))
        .ok_or_else(|| {
            OpError::param(
                "sheet",
                format!("the surface has {} focal sheet(s), got sheet {k}", foc.sheets().len()),
            )
        })?;
    let mut certs = prefixed("PN surface: ", surface.certify());
    certs.extend(foc.sheet_certificates(sheet));
    certs.push(foc.gamma_certificate(sheet));
    let dom: Domain<Q> = domain(args)?;
    if args.string("output")? == "image" {
        let (cycles, w) = sheet.cycles();
        let img = CyclographicImage::new(cycles, w).map_err(blame("sheet"))?;
        let image = img
            .sheets()
            .first()
            .ok_or_else(|| OpError::param("sheet", "the γ-surface has no image sheet"))?;
        certs.extend(img.image_certificates(image));
        certs.push(Certificate::decide(
            "the curvature-sphere cycles form a γ-surface: their cyclographic image has one sheet",
            img.is_gamma_surface(),
            true,
            || format!("{} sheets", img.sheets().len()),
        ));
        return surface_objects(args, &oriented(args, image), &dom, certs, "domain");
    }
    if !sheet.is_surface() {
        return Err(OpError::param(
            "sheet",
            format!("focal sheet {k} degenerates to a curve or a point (f_u × f_v ≡ 0, e.g. a Dupin cyclide's focal conic); it is not exported as a patch"),
        ));
    }
    let patch = sheet.patch(&dom).map_err(blame("domain"))?;
    Ok(vec![args.object(Geometry::Patch(patch), certs)])
}

// ---------------------------------------------------------------------------------
// Laguerre images (Theorem 4.2)
// ---------------------------------------------------------------------------------

const PN_LAGUERRE: OpSpec = OpSpec {
    name: "pn_laguerre",
    summary: "the image of the PN surface of a graph F(u, v) of the isotropic model under the Laguerre map x ↦ λ·B·(x + (t, d)) of the cyclographic model (B a rational Lorentz boost; dilatation d = offset), Peternell (3.8), Thm 4.2",
    params: &[
        COEFFICIENTS,
        DENOMINATOR,
        ParamSpec::with_default("scale", ParamKind::Number, "1", "similarity factor λ ≠ 0"),
        ParamSpec::with_default(
            "boost_axis",
            ParamKind::Int,
            "0",
            "axis 0, 1 or 2 of the Lorentz boost in the (x_axis, r) plane",
        ),
        ParamSpec::with_default(
            "boost",
            ParamKind::Number,
            "0",
            "boost parameter s (cosh = (1 + s²)/(1 − s²)), s² ≠ 1",
        ),
        ParamSpec::with_default(
            "translation",
            ParamKind::Point3,
            "[0, 0, 0]",
            "translation t of the points",
        ),
        ParamSpec::with_default(
            "dilatation",
            ParamKind::Number,
            "0",
            "dilatation r ↦ r + d (the offset at distance d, sign of docs/math/laguerre-pn.md#conventions)",
        ),
        DOMAIN,
        OFFSET,
        ORIENTATION, DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_boosted_cyclide"
op = "pn_laguerre"
# the parabolic Dupin cyclide F = u²/2 − v², boosted (s = 1/3) and dilated by 1/2
coefficients = [[0, 0, -1], [0, 0, 0], ["1/2", 0, 0]]
boost_axis = 2
boost = "1/3"
dilatation = "1/2"
domain = [0, "1/2", 0, "1/2"]
"#,
    build: build_laguerre::<Rational>,
};

/// `pn_laguerre` in `T`.
pub(crate) fn build_laguerre<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let f = ratfn::<T>(args, "coefficients", "denominator")?;
    let base = IsotropicSurface::graph(&f)
        .to_pn_surface()
        .map_err(blame("coefficients"))?;
    let axis = usize::try_from(args.int("boost_axis")?)
        .map_err(|_| OpError::param("boost_axis", "the boost axis must be 0, 1 or 2"))?;
    let t: [T; 3] =
        arith::point(args, "translation", "the translation needs three coordinates")?;
    let map = LaguerreMap::similarity(arith::number::<T>(args, "scale")?)
        .map_err(|e| OpError::param("scale", e.to_string()))?
        .compose(
            &LaguerreMap::boost(axis, arith::number(args, "boost")?)
                .map_err(|e| OpError::param("boost", e.to_string()))?,
        )
        .compose(&LaguerreMap::translation(t))
        .compose(&LaguerreMap::dilatation(arith::number(args, "dilatation")?));
    let image = base.laguerre_image(&map).map_err(blame("boost"))?;
    let certs = prefixed("Laguerre map: ", map.certify());
    surface_objects(args, &oriented(args, &image), &domain(args)?, certs, "domain")
}

// ---------------------------------------------------------------------------------
// anticaustic (§3.6, Theorem 4.1, (3.18) corrected)
// ---------------------------------------------------------------------------------

const PN_ANTICAUSTIC: OpSpec = OpSpec {
    name: "pn_anticaustic",
    summary: "the anticaustic of the mirror z = F(u, v) for light parallel to the z-axis (Peternell §3.6, (3.18) corrected): a PN surface orthogonal to the reflected rays; other levels c give its offsets",
    params: &[
        ParamSpec::required(
            "mirror",
            ParamKind::Grid,
            "power coefficients c[i][j] of u^i v^j of the mirror height F(u, v) (polynomial)",
        ).degree(),
        ParamSpec::with_default(
            "level",
            ParamKind::Number,
            "0",
            "the level c: the wavefront z = c before reflection",
        ),
        DOMAIN,
        OFFSET,
        ORIENTATION, DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_anticaustic_cubic_mirror"
op = "pn_anticaustic"
# mirror F = u²/3 + u v − v³/5
mirror = [[0, 0, 0, "-1/5"], [0, 1, 0, 0], ["1/3", 0, 0, 0]]
level = -1
domain = [0, "1/2", 0, "1/2"]
"#,
    build: build_anticaustic::<Rational>,
};

/// `pn_anticaustic` in `T`.
pub(crate) fn build_anticaustic<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let g = args.opt_grid("mirror")?.unwrap_or_default();
    let f = poly_from_grid(&g)?;
    let mirror = [
        poly_io::mpoly_constant(2, Q::from(1)),
        poly_io::mpoly_var(2, 0),
        poly_io::mpoly_var(2, 1),
        f,
    ]
    .map(|p| poly_io::mpoly_in::<T>(&p));
    let c: T = arith::number(args, "level")?;
    let surface = anticaustic(&mirror, &c).map_err(blame("mirror"))?;
    let certs = prefixed("anticaustic: ", anticaustic_certificates(&mirror, &surface));
    surface_objects(args, &oriented(args, &surface), &domain(args)?, certs, "mirror")
}

// ---------------------------------------------------------------------------------
// planar case: PH curves from the isotropic model of the plane
// ---------------------------------------------------------------------------------

const PN_PLANAR: OpSpec = OpSpec {
    name: "pn_planar",
    summary: "the planar PH curve of the graph y₂ = F(t) of the isotropic model of the plane (x = ((t² − 1)F' − 2tF, 2(F − tF'))/(t² + 1)) with exact rational offsets",
    params: &[
        ParamSpec::required(
            "function",
            ParamKind::Numbers,
            "power coefficients of the numerator of F(t)",
        ).degree(),
        ParamSpec::optional(
            "denominator",
            ParamKind::Numbers,
            "power coefficients of the denominator of F (default 1)",
        ).degree(),
        ParamSpec::with_default(
            "interval",
            ParamKind::Numbers,
            "[-1, 1]",
            "parameter interval [t0, t1], t0 < t1",
        ),
        OFFSET,
        ORIENTATION, DISTANCES,
    ],
    example: r#"[[object]]
name = "pn_planar_ph"
op = "pn_planar"
# F(t) = 1/2 − 2t + t³
function = ["1/2", -2, 0, 1]
interval = [0, "1/2"]
distances = ["1/10", "-1/10"]
"#,
    build: build_planar::<Rational>,
};

/// `pn_planar` in `T`.
pub(crate) fn build_planar<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let num = poly_from_list(&args.opt_numbers("function")?.unwrap_or_default())?;
    let den = match args.opt_numbers("denominator")? {
        // a rational F: the exact op cancels common factors of the point over Q, which
        // f64 does not find (the fuzzer's finding: degree 5 in f64, 4 exact)
        Some(d) if !T::EXACT && d.iter().skip(1).any(|c| !c.is_zero()) => {
            return Err(OpError::param("denominator", crate::float::RATIONAL_F_REFUSED));
        }
        Some(d) => poly_from_list(&d)?,
        None => poly_io::mpoly_constant(2, Q::from(1)),
    };
    let f = RatFn::<T>::new(poly_io::mpoly_in(&num), poly_io::mpoly_in(&den))
        .map_err(blame("denominator"))?;
    let iv = args.opt_numbers("interval")?.unwrap_or_default();
    let [t0, t1]: [T; 2] = arith::array(&iv, "interval", "give two numbers [t0, t1]")?;
    let curve = PnCurve::from_graph(&f).map_err(blame("function"))?;
    let curve = if negative_orientation(args) {
        curve.opposite()
    } else {
        curve
    };
    let mut certs = curve.certify();
    certs.push(curve.check_regular(&t0, &t1).map_err(blame("interval"))?);
    let bez = match main_offset(args)? {
        None => curve.curve(&t0, &t1).map_err(blame("interval"))?,
        Some(d) => {
            let off = curve.offset(arith::of(&d));
            certs.extend(off.certify());
            certs.extend(off.offset_certificates(&curve));
            certs.push(off.check_regular(&t0, &t1).map_err(blame("offset"))?);
            off.curve(&t0, &t1).map_err(blame("offset"))?
        }
    };
    let mut out = vec![arith::object::<T>(args, Geometry::Curve(T::exact_curve(bez)?), certs)];
    for (k, d) in distances(args)?.into_iter().enumerate() {
        let off = curve.offset(arith::of(&d));
        let mut c = off.certify();
        c.extend(off.offset_certificates(&curve));
        c.push(off.check_regular(&t0, &t1).map_err(|e| {
            OpError::param(
                "distances",
                format!("distance {} (entry {k}): {e}", format_rational(&d)),
            )
        })?);
        let bez = off.curve(&t0, &t1).map_err(blame("interval"))?;
        let geometry = Geometry::Curve(T::exact_curve(bez)?);
        out.push(T::finish(offset_object(args, k, &d, geometry, c)));
    }
    Ok(out)
}
