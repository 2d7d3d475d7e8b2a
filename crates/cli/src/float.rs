//! The float path: `rcagd build --float` builds an op's construction with the library's
//! `f64` instantiation instead of the exact one (issue 20, item 3).
//!
//! Every construction of the library is generic over [`rcagd_algebra::Scalar`]; the
//! op registry ([`crate::ops`]) calls it with `F = Rational`. This module is a second,
//! smaller registry: op name → a builder that reads the same checked parameters
//! ([`OpArgs`]), rounds them to the nearest `f64`, calls the same library function with
//! `F = f64`, and wraps the result in the same [`Object`]s (same names, same geometry
//! kind). Two things keep the result honest:
//!
//! * the control points are stored as the *exact binary values* of the `f64` results
//!   (dyadic rationals, [`Scalar::to_rational`]), so every exporter works unchanged and
//!   nothing is rounded a second time;
//! * the certificates are the library's `f64` ones (`exact = false`: an identity checked
//!   to a tolerance scaled by the data, not a proof), and every object carries the value
//!   `arithmetic = "f64"` ([`ARITHMETIC`]) in its JSON `values`, so a float result cannot
//!   be mistaken for an exact one.
//!
//! Ops without a float builder are refused by `rcagd build --float` (see
//! [`NO_FLOAT_PATH`] for why each topic has none). Where the exact op first solves an
//! exact-only sub-problem on its *input* (a rational point on a quadric, the pole-freeness
//! of user weights), the float builder does the same exact step on the input and runs the
//! construction itself in `f64` (documented per builder).

use crate::model::{Geometry, Object};
use crate::ops::{prefixed, OpArgs, OpError};
use num_traits::{One, Zero};
use rcagd::Certified;
use rcagd_algebra::{Certificate, Rational, Scalar};
use rcagd_geom::{BezierCurve, BezierPatch};
use rcagd_io::quantity::{NamedQuantity, Quantity};

/// The name of the value that says which arithmetic built an object.
pub const ARITHMETIC: &str = "arithmetic";

/// A float builder: the op's construction in `f64`.
pub type FloatBuildFn = fn(&OpArgs) -> Result<Vec<Object>, OpError>;

/// One op's float path.
#[derive(Debug, Clone, Copy)]
pub struct FloatOp {
    /// The op (`OpSpec::name`).
    pub name: &'static str,
    /// Builds the objects in `f64`.
    pub build: FloatBuildFn,
    /// What differs from the exact op, if anything (one line, for the docs).
    pub note: &'static str,
}

/// Every op with a float path, in registry order.
pub const FLOAT_OPS: &[FloatOp] = &[
    FloatOp {
        name: "circle_arc",
        build: kernel::circle_arc,
        note: "",
    },
    FloatOp {
        name: "circle",
        build: kernel::circle,
        note: "",
    },
    FloatOp {
        name: "cylinder_patch",
        build: kernel::cylinder_patch,
        note: "",
    },
    FloatOp {
        name: "bezier_curve",
        build: kernel::bezier_curve,
        note: "weights of mixed sign are refused (the exact op proves pole-freeness by exact bisection)",
    },
    FloatOp {
        name: "degree_elevate",
        build: kernel::degree_elevate,
        note: "weights of mixed sign are refused",
    },
    FloatOp {
        name: "subdivide",
        build: kernel::subdivide,
        note: "weights of mixed sign are refused",
    },
    FloatOp {
        name: "bezier_patch",
        build: kernel::bezier_patch,
        note: "weights of mixed sign are refused",
    },
    FloatOp {
        name: "quadric_curve_image",
        build: quadric::curve_image,
        note: "the quadric's rational point is found exactly (exact-only algebra), the image is built in f64",
    },
    FloatOp {
        name: "quadric_patch_image",
        build: quadric::patch_image,
        note: "the quadric's rational point is found exactly (exact-only algebra), the image is built in f64",
    },
    FloatOp {
        name: "sphere_cover",
        build: quadric::sphere_cover,
        note: "",
    },
    FloatOp {
        name: "torus",
        build: cyclide::torus,
        note: "",
    },
    FloatOp {
        name: "dupin_canal",
        build: cyclide::dupin_canal,
        note: "",
    },
    FloatOp {
        name: "dupin_cyclide",
        build: cyclide::dupin_cyclide,
        note: "",
    },
    FloatOp {
        name: "dupin_cyclide_parabolic",
        build: cyclide::dupin_cyclide_parabolic,
        note: "",
    },
    FloatOp {
        name: "pn_graph",
        build: pn::graph,
        note: "regularity is decided by f64 Bernstein signs",
    },
    FloatOp {
        name: "pn_support",
        build: pn::support,
        note: "regularity is decided by f64 Bernstein signs",
    },
    FloatOp {
        name: "pn_revolution",
        build: pn::revolution,
        note: "regularity is decided by f64 Bernstein signs",
    },
    FloatOp {
        name: "ph_curve",
        build: ph::ph_curve,
        note: "the curve only: the display objects (`frame`, `comb`, `feed`) are refused; `arc_length` is an f64 value",
    },
    FloatOp {
        name: "ph_planar_curve",
        build: ph::planar_curve,
        note: "`arc_length` is an f64 value",
    },
    FloatOp {
        name: "ph_planar_offset",
        build: ph::planar_offset,
        note: "a preimage with a zero on [0, 1] (offset weights not all positive) is refused",
    },
];

/// Ops (or whole topics) without a float path, and why; an op listed by name takes
/// precedence over its topic. Ops in neither have no float builder yet.
pub const NO_FLOAT_PATH: &[(&str, &str)] = &[
    ("quadric_interpolate", "not yet written (the interpolation solves a linear system over Q and picks a rational point; an f64 version needs its own pivoting rule)"),
    ("quadric_miquel_patch", "not yet written (it chooses among sign flips by exact weight signs)"),
    ("ph_hermite", "exact-only algebra: the interpolants live in a quadratic field Q(√d) and are enclosed and rounded to rationals exactly"),
    ("ph_dph_septic", "exact-only algebra: exact real roots of the z-polynomial"),
    ("ph_planar_hermite", "exact-only algebra: the branches live in quadratic fields"),
    ("ph_spatial_hermite", "exact-only algebra: the branches live in quadratic fields"),
    ("pipe", "exact-only algebra: the op searches the splittings of |m′|² as sums of two squares over Q (Gaussian factorizations, every frame and method) and keeps the smallest with positive weights; an f64 pipe (`rcagd::canal::pipe_around_ph::<f64>`) would be a different parametrization, so it is not offered as the same construction"),
    ("pipe_ph", "exact-only algebra: as `pipe`, a search over exact splittings of |m′|² = σ² and their Gaussian factors"),
    ("canal_surface", "exact-only algebra: |ṁ|² − ṙ² must split as a sum of two squares over Q"),
    ("ph_helix", "tried and withdrawn (session 12): the library's LineCircle::helix runs in f64, but `certify_helix_construction` decides αβ' − α'β ≡ (f'g − fg')(a0b1 − a1b0)w² on the already-subtracted residual with the scale of that residual (`ph::util::identity_cert` with a right side 0), an absolute 10⁻⁹ that rounding exceeds for seeds of size ~5"),
    ("pn_ellipsoid", "tried and withdrawn (session 12): the library's EllipsoidPn runs in f64, but its f64 regularity check (Bernstein signs of x_u × x_v) finds a singular point at the corner (1/4, 0) of the example's domain that the exact signs exclude"),
    ("conic_point", "exact-only algebra: a rational point of a conic over Q"),
    ("analysis", "exact analysis of a PH curve (factorization, exact roots): queries, not constructions"),
    ("quadric_query", "queries of exact algebra (rational points, fibres, collineations over Q)"),
    ("laguerre_query", "queries of exact algebra (Laguerre models over Q)"),
];

/// The float path of the op called `name`.
pub fn find(name: &str) -> Option<&'static FloatOp> {
    FLOAT_OPS.iter().find(|f| f.name == name)
}

/// `true` if the op called `name` has a float path.
pub fn has_float_path(name: &str) -> bool {
    find(name).is_some()
}

/// The names of the ops with a float path, comma-separated (for messages).
pub fn float_op_names() -> String {
    FLOAT_OPS
        .iter()
        .map(|f| f.name)
        .collect::<Vec<_>>()
        .join(", ")
}

/// The nearest `f64` of an exact number.
fn f(q: &Rational) -> f64 {
    <f64 as Scalar>::from_rational(q)
}

/// The nearest `f64`s of exact numbers.
fn fv(v: &[Rational]) -> Vec<f64> {
    v.iter().map(f).collect()
}

/// The nearest `f64`s of a fixed-size array of exact numbers.
fn fa<const N: usize>(v: &[Rational], param: &'static str) -> Result<[f64; N], OpError> {
    <[f64; N]>::try_from(fv(v)).map_err(|_| {
        OpError::param(
            param,
            format!("internal error: `{param}` does not have {N} coordinates"),
        )
    })
}

/// The exact binary value of a finite `f64` (a non-finite one is an error: the
/// construction overflowed).
fn exact(x: f64) -> Result<Rational, OpError> {
    Rational::try_from(x).map_err(|_| {
        OpError::new(format!(
            "the f64 construction produced the non-finite value {x} (overflow or an ill-conditioned input); build it without --float"
        ))
    })
}

fn check_finite(coords: &[f64]) -> Result<(), OpError> {
    match coords.iter().find(|x| !x.is_finite()) {
        Some(x) => exact(*x).map(|_| ()),
        None => Ok(()),
    }
}

/// An `f64` curve with its exact binary control points.
pub fn exact_curve(c: &BezierCurve<f64>) -> Result<BezierCurve<Rational>, OpError> {
    check_finite(c.coords())?;
    Ok(c.map_scalar(|x| Rational::try_from(*x).unwrap_or_else(|_| Rational::zero())))
}

/// An `f64` patch with its exact binary control points.
pub fn exact_patch(p: &BezierPatch<f64>) -> Result<BezierPatch<Rational>, OpError> {
    check_finite(p.coords())?;
    Ok(p.map_scalar(|x| Rational::try_from(*x).unwrap_or_else(|_| Rational::zero())))
}

/// `Curve` for one curve, `Curves` for several.
fn curves_geometry(cs: &[BezierCurve<f64>]) -> Result<Geometry, OpError> {
    let mut v = cs.iter().map(exact_curve).collect::<Result<Vec<_>, _>>()?;
    Ok(if v.len() == 1 {
        Geometry::Curve(v.remove(0))
    } else {
        Geometry::Curves(v)
    })
}

/// `Patch` for one patch, `Patches` for several.
fn patches_geometry(ps: &[BezierPatch<f64>]) -> Result<Geometry, OpError> {
    let mut v = ps.iter().map(exact_patch).collect::<Result<Vec<_>, _>>()?;
    Ok(if v.len() == 1 {
        Geometry::Patch(v.remove(0))
    } else {
        Geometry::Patches(v)
    })
}

/// The object of a float build: as [`OpArgs::object`], marked `arithmetic = "f64"`.
pub fn float_object(args: &OpArgs, geometry: Geometry, certificates: Vec<Certificate>) -> Object {
    mark(args.object(geometry, certificates))
}

/// Marks an object as built in `f64` (the value [`ARITHMETIC`]).
pub fn mark(mut o: Object) -> Object {
    o.values.retain(|v| v.name != ARITHMETIC);
    o.values.insert(
        0,
        NamedQuantity::new(
            ARITHMETIC,
            "built in f64 (`rcagd build --float`): the control points are the exact binary values of f64 results and the certificates are tolerance checks (exact = false), not proofs",
            Quantity::Text("f64".into()),
        ),
    );
    o
}

/// Homogeneous control points `(w, w·x, …)` from exact `points`/`weights`/`homogeneous`
/// parameters, in `f64` (the products `w·x` are formed exactly, then rounded once).
fn homogeneous_f64(
    points: &[Vec<Rational>],
    weights: Option<&[Rational]>,
    homogeneous: bool,
    param: &'static str,
) -> Result<Vec<Vec<f64>>, OpError> {
    if homogeneous {
        if weights.is_some() {
            return Err(OpError::param(
                "weights",
                "give the weights either in `weights` or as the first coordinate of homogeneous points, not both",
            ));
        }
        if points.iter().any(|p| p.len() < 2) {
            return Err(OpError::param(
                param,
                "a homogeneous point needs a weight and at least one coordinate",
            ));
        }
        return Ok(points.iter().map(|p| fv(p)).collect());
    }
    let one = vec![Rational::one(); points.len()];
    let weights = weights.unwrap_or(&one);
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
    if weights.iter().any(Zero::is_zero) {
        return Err(OpError::param(
            "weights",
            "a weight is zero: a Euclidean point cannot have weight 0 (use homogeneous = true for points at infinity)",
        ));
    }
    Ok(points
        .iter()
        .zip(weights)
        .map(|(p, w)| {
            let mut h = vec![f(w)];
            h.extend(p.iter().map(|x| f(&(x * w))));
            h
        })
        .collect())
}

/// The certificate that the weights have one sign (no pole on `[0, 1]` or `[0, 1]²`),
/// decided on the `f64` weights; mixed signs are refused (the exact op decides them by
/// exact bisection).
fn one_sign_certificate(one_sign: bool, param: &'static str) -> Result<Certificate, OpError> {
    if one_sign {
        Ok(Certificate::holds(
            "the weights all have one sign (the weight function has no zero: no pole)",
            false,
        ))
    } else {
        Err(OpError::param(
            param,
            "weights of mixed sign: the float path does not decide whether the weight function has a zero; build without --float",
        ))
    }
}

/// Kernel ops in `f64`: `rcagd::conic`, `rcagd::cylinder`, inline Bézier curves and
/// patches.
mod kernel {
    use super::*;
    use rcagd::{full_circle, CircleArcs, CylinderPatch};
    use rcagd_geom::certify::curves_agree;
    use rcagd_geom::weight_sign::{curve_has_one_sign, patch_has_one_sign};

    fn arcs(args: &OpArgs, clockwise: bool) -> Result<CircleArcs<f64>, OpError> {
        Ok(CircleArcs::new(
            fa(&args.point("center")?, "center")?,
            f(&args.number("radius")?),
            fa(&args.point("from")?, "from")?,
            fa(&args.point("to")?, "to")?,
            clockwise,
        )?)
    }

    pub(super) fn circle_arc(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let arcs = arcs(args, args.bool("clockwise")?)?;
        let certs = arcs.certify();
        let g = curves_geometry(&arcs.into_curves())?;
        Ok(vec![float_object(args, g, certs)])
    }

    pub(super) fn circle(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let c = full_circle(
            fa(&args.point("center")?, "center")?,
            f(&args.number("radius")?),
        )?;
        let certs = c.certify();
        let curves = c.into_curves();
        let g = Geometry::Curves(curves.iter().map(exact_curve).collect::<Result<_, _>>()?);
        Ok(vec![float_object(args, g, certs)])
    }

    pub(super) fn cylinder_patch(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let z0 = args.number("z0")?;
        let z1 = args.number("z1")?;
        if z0 >= z1 {
            return Err(OpError::param("z1", "the heights must satisfy z0 < z1"));
        }
        let arcs = arcs(args, false)?;
        let many = arcs.pieces().len() > 1;
        let mut certs = Vec::new();
        if many {
            certs.extend(prefixed("base arc: ", arcs.certify()));
        }
        let mut patches = Vec::new();
        for (k, arc) in arcs.pieces().iter().enumerate() {
            let p = CylinderPatch::from_arc(arc.clone(), f(&z0), f(&z1))?;
            if many {
                certs.extend(prefixed(&format!("patch {k}: "), p.certify()));
            } else {
                certs.extend(p.certify());
            }
            patches.push(p.into_patch());
        }
        Ok(vec![float_object(args, patches_geometry(&patches)?, certs)])
    }

    fn inline_curve(args: &OpArgs) -> Result<(BezierCurve<f64>, Certificate), OpError> {
        let homogeneous = args.bool("homogeneous")?;
        let hom = homogeneous_f64(
            &args.points("points")?,
            args.opt_numbers("weights")?.as_deref(),
            homogeneous,
            "points",
        )?;
        let c = BezierCurve::from_homogeneous(hom)
            .map_err(|e| OpError::param("points", e.to_string()))?;
        let cert = one_sign_certificate(
            curve_has_one_sign(&c),
            if homogeneous { "points" } else { "weights" },
        )?;
        Ok((c, cert))
    }

    pub(super) fn bezier_curve(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let (c, cert) = inline_curve(args)?;
        Ok(vec![float_object(
            args,
            Geometry::Curve(exact_curve(&c)?),
            vec![cert],
        )])
    }

    pub(super) fn degree_elevate(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let (c, cert) = inline_curve(args)?;
        let by = args.int("by")?;
        let r = usize::try_from(by)
            .ok()
            .filter(|r| (1..=32).contains(r))
            .ok_or_else(|| {
                OpError::param(
                    "by",
                    format!("the degree increase must be between 1 and 32, got {by}"),
                )
            })?;
        let e = c.elevate(r);
        let certs = vec![curves_agree(&c, &e)?, cert];
        Ok(vec![float_object(
            args,
            Geometry::Curve(exact_curve(&e)?),
            certs,
        )])
    }

    pub(super) fn subdivide(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let (c, cert) = inline_curve(args)?;
        let at_q = args.number("at")?;
        if at_q <= Rational::zero() || at_q >= Rational::one() {
            return Err(OpError::param(
                "at",
                "the subdivision parameter must satisfy 0 < at < 1",
            ));
        }
        let at = f(&at_q);
        let (left, right) = c.subdivide(&at)?;
        let mut certs = vec![cert];
        certs.extend(prefixed(
            &format!("left piece = P on [0, {at}]: "),
            vec![curves_agree(&left, &c.restrict(&0.0, &at)?)?],
        ));
        certs.extend(prefixed(
            &format!("right piece = P on [{at}, 1]: "),
            vec![curves_agree(&right, &c.restrict(&at, &1.0)?)?],
        ));
        let joined = left.control_points().last() == right.control_points().next();
        certs.push(Certificate::decide(
            "left(1) = right(0): the pieces join (equal homogeneous end points)",
            joined,
            false,
            || "the end points differ".to_string(),
        ));
        Ok(vec![float_object(
            args,
            Geometry::Curves(vec![exact_curve(&left)?, exact_curve(&right)?]),
            certs,
        )])
    }

    pub(super) fn bezier_patch(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let net = args.net("net")?;
        let weights = args.opt_grid("weights")?;
        let homogeneous = args.bool("homogeneous")?;
        if let Some(w) = &weights {
            let cols = net.first().map_or(0, Vec::len);
            if w.len() != net.len() || w.iter().any(|r| r.len() != cols) {
                return Err(OpError::param(
                    "weights",
                    "the weights do not have the shape of the net",
                ));
            }
        }
        let mut rows = Vec::with_capacity(net.len());
        for (i, row) in net.iter().enumerate() {
            let w = weights.as_ref().and_then(|w| w.get(i));
            rows.push(homogeneous_f64(
                row,
                w.map(Vec::as_slice),
                homogeneous,
                "net",
            )?);
        }
        let p = BezierPatch::from_homogeneous(rows)
            .map_err(|e| OpError::param("net", e.to_string()))?;
        let cert = one_sign_certificate(
            patch_has_one_sign(&p),
            if homogeneous { "net" } else { "weights" },
        )?;
        Ok(vec![float_object(
            args,
            Geometry::Patch(exact_patch(&p)?),
            vec![cert],
        )])
    }
}

/// Quadric ops in `f64` (`rcagd::quadric`, Jüttler).
mod quadric {
    use super::*;
    use rcagd::quadric::image::{certify_curve_on_quadric, certify_patch_on_quadric};
    use rcagd::quadric::{
        curve_image as lib_curve_image, patch_image as lib_patch_image,
        sphere_cover as lib_sphere_cover, Delta, GeneralizedProjection, Psi, Quadric,
    };
    use rcagd_geom::weight_sign::{split_curve_uniform, split_patch_uniform};

    type Hom = [Rational; 4];
    /// A projection onto a quadric, in `f64`.
    type Projection = Box<dyn GeneralizedProjection<f64>>;

    fn hom(p: &[Rational], param: &'static str) -> Result<Hom, OpError> {
        match p {
            [x, y, z] => Ok([Rational::one(), x.clone(), y.clone(), z.clone()]),
            [w, x, y, z] => Ok([w.clone(), x.clone(), y.clone(), z.clone()]),
            _ => Err(OpError::param(
                param,
                "a point must be [x, y, z] or homogeneous [w, w·x, w·y, w·z]",
            )),
        }
    }

    fn h4(p: &Hom) -> [f64; 4] {
        [f(&p[0]), f(&p[1]), f(&p[2]), f(&p[3])]
    }

    /// The projection onto the recipe's quadric, in `f64`. The quadric and its rational
    /// point are found exactly (the point by exact-only algebra: a rational point of a
    /// quadratic form over ℚ); the projection is then set up in `f64` from the rounded
    /// matrix and point, so the construction runs in `f64` as in the exact op.
    fn target(args: &OpArgs) -> Result<(Projection, Vec<Certificate>), OpError> {
        let name = args.string("quadric")?;
        let coefficients = args.opt_numbers("coefficients")?.unwrap_or_default();
        let matrix = args.opt_grid("matrix")?;
        let point = args
            .opt_point("rational_point")?
            .map(|p| hom(&p, "rational_point"))
            .transpose()?;
        if point.is_none() && coefficients.is_empty() {
            match name {
                "unit_sphere" => return Ok((Box::new(Delta), Vec::new())),
                "hyperbolic_paraboloid_xy" | "seed_paraboloid" => {
                    return Ok((Box::new(Psi), Vec::new()))
                }
                _ => {}
            }
        }
        let quadric = if name == "matrix" {
            let rows = matrix.ok_or_else(|| {
                OpError::param(
                    "quadric",
                    "quadric = \"matrix\" needs the `matrix` parameter",
                )
            })?;
            Quadric::<Rational>::from_rows(&rows)
                .map_err(|e| OpError::param("matrix", e.to_string()))?
        } else {
            Quadric::<Rational>::by_name(name, &coefficients)
                .map_err(|e| OpError::param("quadric", e.to_string()))?
        };
        let c = match point {
            Some(p) => p,
            None => quadric
                .rational_point()
                .map_err(|e| OpError::param("quadric", e.to_string()))?,
        };
        let rows: Vec<Vec<f64>> = quadric.matrix().iter().map(|r| fv(r)).collect();
        let qf = Quadric::<f64>::from_rows(&rows)
            .map_err(|e| OpError::param("quadric", e.to_string()))?
            .with_point(h4(&c))
            .map_err(|e| OpError::param("quadric", e.to_string()))?;
        let proj = qf
            .projection()
            .map_err(|e| OpError::param("quadric", e.to_string()))?;
        let certs = prefixed("projection: ", proj.certify());
        Ok((Box::new(proj), certs))
    }

    fn control_points(
        points: &[Vec<Rational>],
        weights: Option<&[Rational]>,
        homogeneous: bool,
        param: &'static str,
    ) -> Result<Vec<Vec<f64>>, OpError> {
        let want = if homogeneous { 4 } else { 3 };
        if points.iter().any(|p| p.len() != want) {
            return Err(OpError::param(
                param,
                "the control points must be [x, y, z] (homogeneous: [w, w·x, w·y, w·z])",
            ));
        }
        homogeneous_f64(points, weights, homogeneous, param)
    }

    pub(super) fn curve_image(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let (proj, mut certs) = target(args)?;
        let hom = control_points(
            &args.points("points")?,
            args.opt_numbers("weights")?.as_deref(),
            args.bool("homogeneous")?,
            "points",
        )?;
        let curve = BezierCurve::from_homogeneous(hom)
            .map_err(|e| OpError::param("points", e.to_string()))?;
        let img = lib_curve_image(proj.as_ref(), &curve)
            .map_err(|e| OpError::param("points", e.to_string()))?;
        certs.extend(img.certify());
        let image = img.into_image();
        // as the exact op: a curve with weights of mixed sign is split for export
        let geometry = match split_curve_uniform(&image, 4)? {
            Some(pieces) if pieces.len() > 1 => {
                let q = proj.quadric();
                let k = pieces.len();
                certs.push(Certificate::decide(
                    format!("split into {k} pieces [i/{k}, (i+1)/{k}] with weights of one sign (export); every piece lies on the quadric: Xᵀ Q X ≡ 0"),
                    pieces.iter().all(|p| certify_curve_on_quadric(p, &q, "").holds),
                    false,
                    || "a piece is off the quadric".to_string(),
                ));
                curves_geometry(&pieces)?
            }
            _ => Geometry::Curve(exact_curve(&image)?),
        };
        Ok(vec![float_object(args, geometry, certs)])
    }

    pub(super) fn patch_image(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let (proj, mut certs) = target(args)?;
        let net = args.net("net")?;
        let weights = args.opt_grid("weights")?;
        let homogeneous = args.bool("homogeneous")?;
        let mut rows = Vec::with_capacity(net.len());
        for (i, row) in net.iter().enumerate() {
            let w = weights.as_ref().and_then(|w| w.get(i));
            rows.push(control_points(
                row,
                w.map(Vec::as_slice),
                homogeneous,
                "net",
            )?);
        }
        let patch = BezierPatch::from_homogeneous(rows)
            .map_err(|e| OpError::param("net", e.to_string()))?;
        let img = lib_patch_image(proj.as_ref(), &patch)
            .map_err(|e| OpError::param("net", e.to_string()))?;
        certs.extend(img.certify());
        let image = img.into_image();
        let geometry = match split_patch_uniform(&image, 3)? {
            Some(pieces) if pieces.len() > 1 => {
                let q = proj.quadric();
                certs.push(Certificate::decide(
                    "split into sub-patches with weights of one sign (export); every sub-patch lies on the quadric: Xᵀ Q X ≡ 0",
                    pieces.iter().all(|p| certify_patch_on_quadric(p, &q, "").holds),
                    false,
                    || "a sub-patch is off the quadric".to_string(),
                ));
                patches_geometry(&pieces)?
            }
            _ => Geometry::Patch(exact_patch(&image)?),
        };
        Ok(vec![float_object(args, geometry, certs)])
    }

    pub(super) fn sphere_cover(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let c = fa::<3>(&args.point("center")?, "center")?;
        let r = fa::<3>(&args.point("radii")?, "radii")?;
        let cover = lib_sphere_cover(c, r).map_err(|e| OpError::param("radii", e.to_string()))?;
        let certs = cover.certify();
        Ok(vec![float_object(
            args,
            patches_geometry(&cover.into_patches())?,
            certs,
        )])
    }
}

/// PH curve ops in `f64` (`rcagd::ph`: Farouki; Besednjak).
mod ph {
    use super::*;
    use rcagd::ph::{PhCurve, PlanarPhCurve};
    use rcagd_algebra::complex::Complex;
    use rcagd_algebra::quaternion::Quaternion;
    use rcagd_geom::weight_sign::curve_has_one_sign;

    fn quaternions(args: &OpArgs) -> Result<Vec<Quaternion<f64>>, OpError> {
        args.points("quaternions")?
            .iter()
            .enumerate()
            .map(|(k, p)| match fa::<4>(p, "quaternions") {
                Ok([u, v, p, q]) => Ok(Quaternion::new(u, v, p, q)),
                Err(_) => Err(OpError::param(
                    "quaternions",
                    format!("A_{k} must be a quaternion [u, v, p, q]"),
                )),
            })
            .collect()
    }

    fn complexes(args: &OpArgs, param: &'static str) -> Result<Vec<Complex<f64>>, OpError> {
        args.points(param)?
            .iter()
            .map(|p| fa::<2>(p, param).map(|[a, b]| Complex::new(a, b)))
            .collect()
    }

    fn arc_length(x: f64) -> NamedQuantity {
        NamedQuantity::new("arc_length", "∫₀¹ σ dt (f64)", Quantity::Approx(x))
    }

    pub(super) fn ph_curve(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        if args.string("frame")? != "none" || args.bool("comb")? || args.int("feed")? != 0 {
            return Err(OpError::new(
                "the display objects (frame, comb, feed) have no float path: build them without --float",
            ));
        }
        let start = fa::<3>(&args.point("start")?, "start")?;
        let curve = match (
            args.get("quaternions").is_some(),
            args.get("alpha").is_some() && args.get("beta").is_some(),
        ) {
            (true, false) => PhCurve::new(quaternions(args)?, start)?,
            (false, true) => {
                PhCurve::from_hopf(&complexes(args, "alpha")?, &complexes(args, "beta")?, start)?
            }
            _ => {
                return Err(OpError::new(
                    "a PH curve needs `quaternions` or both `alpha` and `beta` (not both forms)",
                ))
            }
        };
        curve_object(args, &curve, Vec::new())
    }

    /// The curve object of `ph_curve`: the PH, arc-length and curvature
    /// certificates after `certs`, and the arc length as an f64 value.
    fn curve_object(
        args: &OpArgs,
        curve: &PhCurve<f64>,
        mut certs: Vec<Certificate>,
    ) -> Result<Vec<Object>, OpError> {
        crate::ops::ph::add_curve_certificates(&mut certs, curve);
        let bez = curve.to_bezier()?;
        let len = curve.to_poly_curve().arc_length();
        let o = float_object(args, Geometry::Curve(exact_curve(&bez)?), certs);
        Ok(vec![with_value(o, arc_length(len))])
    }

    fn planar(args: &OpArgs) -> Result<PlanarPhCurve<f64>, OpError> {
        let w = args
            .points("preimage")?
            .iter()
            .map(|p| fa::<2>(p, "preimage").map(|[a, b]| Complex::new(a, b)))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(PlanarPhCurve::new(
            w,
            fa::<2>(&args.point("start")?, "start")?,
        )?)
    }

    pub(super) fn planar_curve(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let c = planar(args)?;
        let certs = c.certify();
        let o = float_object(args, Geometry::Curve(exact_curve(&c.to_bezier()?)?), certs);
        Ok(vec![with_value(o, arc_length(c.arc_length()))])
    }

    pub(super) fn planar_offset(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let c = planar(args)?;
        let off = c.offset(&f(&args.number("distance")?))?;
        // the offset's weight is σ = |w|² ≥ 0; the exact op proves it has no zero on
        // [0, 1] (exact root isolation); here all Bernstein weights must be > 0
        let cert = if curve_has_one_sign(&off.curve) {
            Certificate::holds(
                "the offset's Bernstein weights all have one sign (σ = |w|² has no zero on [0, 1]: no pole)",
                false,
            )
        } else {
            return Err(OpError::param(
                "preimage",
                "the offset's weights σ = |w|² are not all of one sign (a cusp of the curve on or near [0, 1]): the float path does not decide whether σ has a zero; build without --float",
            ));
        };
        let mut certs = prefixed("base: ", c.certify());
        certs.extend(off.certify());
        certs.push(cert);
        Ok(vec![float_object(
            args,
            Geometry::Curve(exact_curve(&off.curve)?),
            certs,
        )])
    }
}

/// The object with one more value (after [`ARITHMETIC`]).
fn with_value(mut o: Object, v: NamedQuantity) -> Object {
    o.values.push(v);
    o
}

/// The topic of an op (its registry module), if registered.
fn topic_of(name: &str) -> Option<&'static str> {
    crate::ops::TOPICS
        .iter()
        .find(|(_, ops)| ops.iter().any(|o| o.name == name))
        .map(|(t, _)| *t)
}

/// Why the op called `name` has no float path (`None` if it has one).
pub fn no_float_reason(name: &str) -> Option<&'static str> {
    if has_float_path(name) {
        return None;
    }
    let by_op = NO_FLOAT_PATH.iter().find(|(k, _)| *k == name);
    let by_topic = topic_of(name).and_then(|t| NO_FLOAT_PATH.iter().find(|(k, _)| *k == t));
    Some(by_op.or(by_topic).map_or(
        "not yet written (the construction may have an f64 instantiation; no float builder wraps it yet)",
        |(_, r)| *r,
    ))
}

/// One line for `rcagd ops NAME`: whether the op has a float path, and what differs.
pub fn describe(name: &str) -> String {
    match (find(name), no_float_reason(name)) {
        (Some(op), _) if op.note.is_empty() => {
            "float path (`rcagd build --float`): yes".to_string()
        }
        (Some(op), _) => format!("float path (`rcagd build --float`): yes — {}", op.note),
        (None, Some(why)) => format!("float path (`rcagd build --float`): none — {why}"),
        (None, None) => "float path (`rcagd build --float`): none".to_string(),
    }
}

/// [`describe`] as a Markdown sentence for docs/recipes.md.
pub fn describe_markdown(name: &str) -> String {
    match (find(name), no_float_reason(name)) {
        (Some(op), _) if op.note.is_empty() => {
            "Float path (`rcagd build --float`): yes.".to_string()
        }
        (Some(op), _) => format!("Float path (`rcagd build --float`): yes; {}.", op.note),
        (None, Some(why)) => format!("Float path (`rcagd build --float`): none; {why}."),
        (None, None) => "Float path (`rcagd build --float`): none.".to_string(),
    }
}

/// Dupin cyclides and tori in `f64` (`rcagd::cyclide`: Peternell, Lemma 3.4 and
/// Prop. 3.2).
mod cyclide {
    use super::*;
    use rcagd::cyclide::{DualPencil, DupinCyclide};
    use rcagd_geom::weight_sign::{split_patches_adaptive, SignRule};

    fn vec4(args: &OpArgs, param: &'static str) -> Result<[f64; 4], OpError> {
        fa::<4>(&args.point(param)?, param)
    }

    fn range(args: &OpArgs, param: &'static str) -> Result<(f64, f64), OpError> {
        match args.opt_numbers(param)?.unwrap_or_default().as_slice() {
            [a, b] if a < b => Ok((f(a), f(b))),
            _ => Err(OpError::param(
                param,
                format!("`{param}` must be an interval [a, b] with a < b"),
            )),
        }
    }

    /// As the exact op: the cyclide's and its dual pencil's certificates, the offset's if
    /// asked, and the patches split until every Bernstein weight is positive (the same
    /// adaptive bisection, `rcagd::canal::EXPORT_SPLITS`, deciding signs in `f64`).
    fn object(
        args: &OpArgs,
        cy: &DupinCyclide<f64>,
        patches: Vec<BezierPatch<f64>>,
    ) -> Result<Vec<Object>, OpError> {
        let mut certs = cy.certify();
        let pencil = DualPencil::of(cy).map_err(|e| OpError::new(e.to_string()))?;
        certs.extend(pencil.certify(cy));
        if let Some(d) = args.opt_number("offset")? {
            certs.extend(
                cy.certify_offset(&f(&d))
                    .map_err(|e| OpError::param("offset", e.to_string()))?,
            );
        }
        let split =
            split_patches_adaptive(patches, SignRule::Positive, rcagd::canal::EXPORT_SPLITS)?;
        if split.failed > 0 {
            return Err(OpError::new(
                "the surface's weight is not positive on the whole domain (a pole or a point near infinity)",
            ));
        }
        let n = split.pieces.len();
        certs.push(Certificate::holds(
            format!("every Bernstein weight of the {n} patches is > 0 (the weight has no zero: no pole, no base point)"),
            false,
        ));
        let kind = NamedQuantity::new(
            "kind",
            "the type of the Dupin cyclide (ring, horn, spindle, parabolic)",
            Quantity::Text(cy.kind().name().into()),
        );
        let o = float_object(
            args,
            Geometry::Patches(
                split
                    .pieces
                    .iter()
                    .map(exact_patch)
                    .collect::<Result<_, _>>()?,
            ),
            certs,
        );
        Ok(vec![with_value(o, kind)])
    }

    pub(super) fn torus(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let big = args.number("major_radius")?;
        let rho = args.number("minor_radius")?;
        if big <= Rational::zero() {
            return Err(OpError::param("major_radius", "R must be positive"));
        }
        if rho <= Rational::zero() || rho >= big {
            return Err(OpError::param(
                "minor_radius",
                "a ring torus needs 0 < ρ < R",
            ));
        }
        let cy = DupinCyclide::tilted(
            fa::<3>(&args.point("center")?, "center")?,
            f(&big),
            f(&rho),
            0.0,
        )
        .map_err(|e| OpError::new(e.to_string()))?;
        let patches = cy
            .covering_patches()
            .map_err(|e| OpError::new(e.to_string()))?;
        object(args, &cy, patches)
    }

    pub(super) fn dupin_canal(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let cy = DupinCyclide::tilted(
            fa::<3>(&args.point("center")?, "center")?,
            f(&args.number("rho")?),
            f(&args.number("r0")?),
            f(&args.number("s")?),
        )
        .map_err(|e| OpError::new(e.to_string()))?;
        let patches = cy
            .covering_patches()
            .map_err(|e| OpError::new(e.to_string()))?;
        object(args, &cy, patches)
    }

    pub(super) fn dupin_cyclide(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let cy = DupinCyclide::from_pe_circle(
            vec4(args, "center")?,
            vec4(args, "u")?,
            vec4(args, "v")?,
            f(&args.number("rho")?),
        )
        .map_err(|e| OpError::new(e.to_string()))?;
        let patches = cy
            .covering_patches()
            .map_err(|e| OpError::new(e.to_string()))?;
        object(args, &cy, patches)
    }

    pub(super) fn dupin_cyclide_parabolic(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let cy = DupinCyclide::from_pe_parabola(
            vec4(args, "vertex")?,
            vec4(args, "u")?,
            vec4(args, "n")?,
        )
        .map_err(|e| OpError::new(e.to_string()))?;
        let (t0, t1) = range(args, "t")?;
        let (s0, s1) = range(args, "s")?;
        let patch = cy
            .patch((&t0, &t1), (&s0, &s1))
            .map_err(|e| OpError::new(e.to_string()))?;
        object(args, &cy, vec![patch])
    }
}

/// PN surfaces in `f64` (`rcagd::pn`: Peternell, Theorem 4.3/4.4 and (4.2)).
mod pn {
    use super::*;
    use rcagd::pn::planar::{surface_of_revolution, PnCurve};
    use rcagd::pn::support::from_support_function;
    use rcagd::pn::{Domain, IsotropicSurface, PnError, PnSurface, RatFn};
    use rcagd_algebra::mpoly::MPoly;

    fn blame(param: &'static str) -> impl Fn(PnError) -> OpError {
        move |e| OpError::param(param, e.to_string())
    }

    /// `Σ c[i][j] u^i v^j` in `f64` (the exact op's converter, rounded).
    fn poly_from_grid(grid: &[Vec<Rational>]) -> Result<MPoly<f64>, OpError> {
        Ok(crate::ops::poly_io::grid_mpoly(grid)?.map(f))
    }

    fn ratfn(args: &OpArgs, num: &'static str, den: &'static str) -> Result<RatFn<f64>, OpError> {
        let n = poly_from_grid(&args.opt_grid(num)?.unwrap_or_default())?;
        let d = match args.opt_grid(den)? {
            Some(g) => poly_from_grid(&g)?,
            None => MPoly::constant(2, 1.0),
        };
        RatFn::new(n, d).map_err(|e| OpError::param(den, e.to_string()))
    }

    fn opt_poly(
        args: &OpArgs,
        param: &'static str,
        default: MPoly<f64>,
    ) -> Result<MPoly<f64>, OpError> {
        match args.opt_grid(param)? {
            Some(g) => poly_from_grid(&g),
            None => Ok(default),
        }
    }

    fn domain(args: &OpArgs) -> Result<Domain<f64>, OpError> {
        match args.opt_numbers("domain")?.unwrap_or_default().as_slice() {
            [a, b, c, d] => Domain::new(f(a), f(b), f(c), f(d))
                .map_err(|e| OpError::param("domain", e.to_string())),
            d => Err(OpError::param(
                "domain",
                format!("give four numbers [u0, u1, v0, v1], got {}", d.len()),
            )),
        }
    }

    fn oriented(args: &OpArgs, s: PnSurface<f64>) -> Result<PnSurface<f64>, OpError> {
        Ok(match args.get("orientation") {
            Some(crate::value::Value::Str(o)) if o == "negative" => s.opposite(),
            _ => s,
        })
    }

    /// As the exact op (`ops::pn::surface_objects_in`): the surface on the domain
    /// (certified, checked regular), then one object `NAME_offsetK` per offset distance,
    /// every object marked f64.
    fn surface_objects(
        args: &OpArgs,
        surface: &PnSurface<f64>,
        dom: &Domain<f64>,
        certs: Vec<Certificate>,
        param: &'static str,
    ) -> Result<Vec<Object>, OpError> {
        let objs = crate::ops::pn::surface_objects_in(args, surface, dom, certs, param, &|p| {
            Ok(Geometry::Patch(exact_patch(p)?))
        })?;
        Ok(objs.into_iter().map(mark).collect())
    }

    pub(super) fn graph(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let fun = ratfn(args, "coefficients", "denominator")?;
        let s = IsotropicSurface::graph(&fun)
            .to_pn_surface()
            .map_err(blame("coefficients"))?;
        surface_objects(
            args,
            &oriented(args, s)?,
            &domain(args)?,
            Vec::new(),
            "coefficients",
        )
    }

    pub(super) fn revolution(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let u = fv(&args.opt_numbers("u")?.unwrap_or_default());
        let v = fv(&args.opt_numbers("v")?.unwrap_or_default());
        let start = fa::<2>(&args.point("start")?, "start")?;
        let profile = PnCurve::from_ph_preimage(&u, &v, start).map_err(blame("v"))?;
        let s = surface_of_revolution(&profile).map_err(blame("u"))?;
        let certs = prefixed("profile: ", profile.certify());
        surface_objects(args, &oriented(args, s)?, &domain(args)?, certs, "domain")
    }

    pub(super) fn support(args: &OpArgs) -> Result<Vec<Object>, OpError> {
        let h = ratfn(args, "support", "support_denominator")?;
        let a = opt_poly(args, "a", MPoly::var(2, 0))?;
        let b = opt_poly(args, "b", MPoly::var(2, 1))?;
        let c = opt_poly(args, "c", MPoly::constant(2, 1.0))?;
        let rect = domain(args)?;
        let s = from_support_function(a, b, c, &h).map_err(blame("c"))?;
        surface_objects(args, &oriented(args, s)?, &rect, Vec::new(), "support")
    }
}
