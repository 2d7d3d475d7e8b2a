//! Ops of the `ph` topic: spatial Pythagorean-hodograph curves (`rcagd::ph`, Besednjak,
//! docs/math/ph-curves.md): a PH curve from quaternion or Hopf coefficients with optional frames,
//! curvature comb and constant-feed (arc-length-uniform) marks; polynomial helices from a
//! line/circle seed (reparametrization, multiplication or both); the septic DPH
//! constructor; Hermite interpolation by helical PH quintics (Besednjak ch. 9).
//!
//! Extra objects are named after the main object: `<name>_frame` (frame vectors as line
//! segments), `<name>_comb` (curvature comb: teeth `r(t) → r(t) − scale·κn(t)` and the
//! polyline through their tips), `<name>_feed` (short marks across the curve at the
//! arc-length-uniform parameters). Each extra object holds the curve itself as its
//! first piece, so that its picture shows the curve with the frame, comb or marks.

use super::arith::{self, OpScalar};
use super::{poly_io, OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use num_traits::{One, Zero};
use rcagd::ph::dph::{certify_dph_septic, dph_septic, dph_septic_z_roots};
use rcagd::ph::hermite_enclosure::EnclosedInterpolant;

use rcagd::ph::{
    DphTest, HelixTest, HermiteData, HermiteInterpolant, HermiteSolution, LineCircle, PhCurve,
    PhPolyCurve,
};
use rcagd_algebra::quadratic::QuadExt;
use super::poly_io::RootInterval;
use rcagd_io::quantity::{NamedQuantity, Quantity};
use rcagd_algebra::complex::Complex;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::interval::pow2;
use rcagd_algebra::rational::round_decimal;
use rcagd_algebra::{Certificate, Rational, Scalar};
use rcagd_geom::BezierCurve;

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[PH_CURVE, PH_HELIX, PH_DPH_SEPTIC, PH_HERMITE];

type Q = Rational;

const START: ParamSpec =
    ParamSpec::with_default("start", ParamKind::Point3, "[0, 0, 0]", "the start point r(0)");

/// Display options shared by the curve-building ops.
const DISPLAY_PARAMS: [ParamSpec; 6] = [
    ParamSpec::with_default(
        "frame",
        ParamKind::Choice(&["none", "euler_rodrigues", "frenet"]),
        "\"none\"",
        "frame vectors drawn as `<name>_frame`: the rational Euler–Rodrigues frame (A i A*, A j A*, A k A*)/σ, or the Frenet frame (t, p, b) of a DPH curve (p, b rounded to f64 unless √c is rational)",
    ),
    ParamSpec::with_default(
        "samples",
        ParamKind::Int,
        "9",
        "number of parameters t = k/(samples−1) for frame vectors and comb teeth, 2 to 200",
    ).samples(),
    ParamSpec::with_default(
        "frame_length",
        ParamKind::Number,
        "\"1/2\"",
        "length of the drawn frame vectors",
    ),
    ParamSpec::with_default(
        "comb",
        ParamKind::Bool,
        "false",
        "draw the curvature comb `<name>_comb`: teeth from r(t) to r(t) − comb_scale·κn(t), away from the centre of curvature as CAD systems draw them (exact: κn = (σr''−σ'r')/σ³)",
    ),
    ParamSpec::with_default(
        "comb_scale",
        ParamKind::Number,
        "1",
        "length of a comb tooth per unit curvature (negative: teeth toward the centre of curvature)",
    ),
    ParamSpec::with_default(
        "feed",
        ParamKind::Int,
        "0",
        "if > 0: mark the parameters of `feed` equal arc-length steps (constant feed) as `<name>_feed`, up to 200",
    ).samples(),
];

const PH_CURVE: OpSpec = OpSpec {
    name: "ph_curve",
    summary: "a spatial PH curve r' = A i A* of degree 2m+1 from the quaternion (or Hopf) Bernstein coefficients of A, exact control points; optional frames, curvature comb, constant-feed marks",
    params: &[
        ParamSpec::optional(
            "quaternions",
            ParamKind::Points,
            "Bernstein coefficients A_0..A_m of A(t), each [u, v, p, q] = u + v i + p j + q k",
        ).degree(),
        ParamSpec::optional(
            "alpha",
            ParamKind::Points,
            "Hopf form instead of `quaternions`: Bernstein coefficients of α = u + i v, each [re, im]",
        ).degree(),
        ParamSpec::optional(
            "beta",
            ParamKind::Points,
            "Hopf form: Bernstein coefficients of β = q + i p, each [re, im] (A = α + k β)",
        ).degree(),
        START,
        DISPLAY_PARAMS[0],
        DISPLAY_PARAMS[1],
        DISPLAY_PARAMS[2],
        DISPLAY_PARAMS[3],
        DISPLAY_PARAMS[4],
        DISPLAY_PARAMS[5],
    ],
    example: r#"[[object]]
name = "ph_cubic"
op = "ph_curve"
quaternions = [[1, 0, 1, 0], [0, 1, 0, 1]]
frame = "euler_rodrigues"
samples = 5
comb = true
feed = 8
"#,
    build: build_ph_curve::<Rational>,
};

const PH_HELIX: OpSpec = OpSpec {
    name: "ph_helix",
    summary: "a polynomial helix from a line/circle seed z = (a0(1−t)+a1 t)/(b0(1−t)+b1 t): reparametrization by f/g and/or multiplication by w (Besednjak §6); certified axis a·r' ≡ σ",
    params: &[
        ParamSpec::required("a0", ParamKind::Point2, "complex a0 = [re, im]"),
        ParamSpec::required("a1", ParamKind::Point2, "complex a1"),
        ParamSpec::required("b0", ParamKind::Point2, "complex b0"),
        ParamSpec::required(
            "b1",
            ParamKind::Point2,
            "complex b1 (a0 b1 − a1 b0 ≠ 0)",
        ),
        ParamSpec::with_default(
            "f",
            ParamKind::Numbers,
            "[0, 1]",
            "real Bernstein coefficients of f (reparametrization f/g; [0, 1] with g = [1, 1] is none)",
        ).degree(),
        ParamSpec::with_default(
            "g",
            ParamKind::Numbers,
            "[1, 1]",
            "real Bernstein coefficients of g (as many as f)",
        ).degree(),
        ParamSpec::with_default(
            "w",
            ParamKind::Points,
            "[[1, 0]]",
            "complex Bernstein coefficients [re, im] of the multiplier w ([[1, 0]]: none)",
        ).degree(),
        START,
        DISPLAY_PARAMS[0],
        DISPLAY_PARAMS[1],
        DISPLAY_PARAMS[2],
        DISPLAY_PARAMS[3],
        DISPLAY_PARAMS[4],
        DISPLAY_PARAMS[5],
    ],
    example: r#"[[object]]
name = "helix_8_1"
op = "ph_helix"
a0 = [1, 0]
a1 = [1, 1]
b0 = [1, -1]
b1 = [0, 1]
f = [1, 2, 2, 1]
g = [1, 2, 3, 3]
"#,
    build: build_ph_helix::<Rational>,
};

const PH_DPH_SEPTIC: OpSpec = OpSpec {
    name: "ph_dph_septic",
    summary: "a double-PH septic with αβ' − α'β = h w² (st h + 2 st w = 4) from free α0, α1, β0 and a root of the quadratic (5.12) (Besednjak §5.2); helical or not",
    params: &[
        ParamSpec::required(
            "h",
            ParamKind::Numbers,
            "real Bernstein coefficients of h (1, 3 or 5 of them)",
        ).degree(),
        ParamSpec::required(
            "w",
            ParamKind::Points,
            "complex Bernstein coefficients [re, im] of w (3, 2 or 1 of them)",
        ).degree(),
        ParamSpec::required("alpha0", ParamKind::Point2, "complex α0 ≠ 0"),
        ParamSpec::required("alpha1", ParamKind::Point2, "complex α1"),
        ParamSpec::required("beta0", ParamKind::Point2, "complex β0"),
        ParamSpec::with_default(
            "root",
            ParamKind::Int,
            "0",
            "which root z = α1β2 − α2β1 of (5.12): 0 = (3T2 + √Δ)/9, 1 = (3T2 − √Δ)/9",
        ),
        START,
        DISPLAY_PARAMS[0],
        DISPLAY_PARAMS[1],
        DISPLAY_PARAMS[2],
        DISPLAY_PARAMS[3],
        DISPLAY_PARAMS[4],
        DISPLAY_PARAMS[5],
    ],
    example: r#"[[object]]
name = "dph_septic_8_4"
op = "ph_dph_septic"
h = [1]
w = [[1, 0], [1, 1], [0, 1]]
alpha0 = [1, 0]
alpha1 = [0, 2]
beta0 = [0, 1]
root = 0
"#,
    build: build_ph_dph_septic,
};

const PH_HERMITE: OpSpec = OpSpec {
    name: "ph_hermite",
    summary: "every helical PH quintic with r(0) = p_s, r'(0) = d_s, r(1) = p_f, r'(1) = d_f (Besednjak ch. 9), by increasing bending energy: the least-energy one is the object `<name>`, the others `<name>_2`, `<name>_3`, … (a tie for the least energy ends in `_min`)",
    params: &[
        ParamSpec::required("p_s", ParamKind::Point3, "start point"),
        ParamSpec::required("d_s", ParamKind::Point3, "start derivative r'(0) ≠ 0"),
        ParamSpec::required("p_f", ParamKind::Point3, "end point ≠ p_s"),
        ParamSpec::required(
            "d_f",
            ParamKind::Point3,
            "end derivative r'(1) ≠ 0, not a positive multiple of d_s",
        ),
    ],
    example: r#"[[object]]
name = "hermite_9_1"
op = "ph_hermite"
p_s = [0, 0, 0]
d_s = [1, 0, 1]
p_f = [1, 1, 1]
d_f = [0, 1, 1]
"#,
    build: build_ph_hermite,
};

// ------------------------------------------------------------------ helpers

fn qi(n: i64) -> Q {
    Q::from(n)
}

fn point3<T: OpScalar>(args: &OpArgs, param: &'static str) -> Result<[T; 3], OpError> {
    arith::point(args, param, &format!("internal error: `{param}` is not a 3D point"))
}

fn complex<T: OpScalar>(args: &OpArgs, param: &'static str) -> Result<Complex<T>, OpError> {
    let p = args.point(param)?;
    match <[Q; 2]>::try_from(p) {
        Ok([re, im]) => Ok(Complex::new(arith::of(&re), arith::of(&im))),
        Err(_) => Err(OpError::param(
            param,
            format!("internal error: `{param}` is not a complex number [re, im]"),
        )),
    }
}

fn complexes<T: OpScalar>(args: &OpArgs, param: &'static str) -> Result<Vec<Complex<T>>, OpError> {
    args.points(param)?
        .into_iter()
        .enumerate()
        .map(|(k, p)| match <[Q; 2]>::try_from(p) {
            Ok([re, im]) => Ok(Complex::new(arith::of(&re), arith::of(&im))),
            Err(p) => Err(OpError::param(
                param,
                format!(
                    "entry {k} must be a complex number [re, im], got {} numbers",
                    p.len()
                ),
            )),
        })
        .collect()
}

/// The quaternion coefficients `A_k = [u, v, p, q]` of the parameter `quaternions`.
pub(super) fn quaternions<T: OpScalar>(args: &OpArgs) -> Result<Vec<Quaternion<T>>, OpError> {
    args.points("quaternions")?
        .into_iter()
        .enumerate()
        .map(|(k, p)| match <[Q; 4]>::try_from(p) {
            Ok([u, v, p, q]) => Ok(Quaternion::new(arith::of(&u), arith::of(&v), arith::of(&p), arith::of(&q))),
            Err(p) => Err(OpError::param(
                "quaternions",
                format!(
                    "A_{k} must be a quaternion [u, v, p, q], got {} numbers",
                    p.len()
                ),
            )),
        })
        .collect()
}

fn numbers<T: OpScalar>(args: &OpArgs, param: &'static str) -> Result<Vec<T>, OpError> {
    args.opt_numbers(param)?.map(|v| arith::all_of(&v)).ok_or_else(|| {
        OpError::param(
            param,
            format!("internal error: `{param}` has no value"),
        )
    })
}

fn segment(a: &[Q; 3], b: &[Q; 3]) -> Result<BezierCurve<Q>, OpError> {
    Ok(BezierCurve::from_points(&[a.to_vec(), b.to_vec()])?)
}

fn add(a: &[Q; 3], b: &[Q; 3]) -> [Q; 3] {
    [&a[0] + &b[0], &a[1] + &b[1], &a[2] + &b[2]]
}

fn scale(a: &[Q; 3], s: &Q) -> [Q; 3] {
    [&a[0] * s, &a[1] * s, &a[2] * s]
}

fn to_q(x: f64) -> Result<Q, OpError> {
    Q::try_from(x).map_err(|_| {
        OpError::new(
            rcagd::ph::PhError::NonFinite {
                what: format!("the value {x} of an f64 result"),
            }
            .to_string(),
        )
    })
}

/// The main curve object with the PH, arc-length and curvature certificates, plus the
/// display objects requested by [`DISPLAY_PARAMS`].
/// Appends the PH, arc-length and curvature certificates of `curve` to `certs`, each
/// property once (the curve object of `ph_curve`, exact or `f64`).
pub(crate) fn add_curve_certificates<F: rcagd_algebra::Scalar>(
    certs: &mut Vec<Certificate>,
    curve: &PhCurve<F>,
) {
    for c in curve
        .certify()
        .into_iter()
        .chain(curve.certify_arc_length())
        .chain(curve.certify_curvature())
    {
        if !certs.iter().any(|x| x.property == c.property) {
            certs.push(c);
        }
    }
}

/// The curve object (in `T`) and, for an exact curve, the display objects.
fn curve_objects<T: OpScalar>(
    args: &OpArgs,
    curve: &PhCurve<T>,
    mut certs: Vec<Certificate>,
) -> Result<Vec<Object>, OpError> {
    if !T::EXACT && (args.string("frame")? != "none" || args.bool("comb")? || args.int("feed")? != 0) {
        return Err(OpError::new(
            crate::float::DISPLAY_OBJECTS_REFUSED,
        ));
    }
    let pc = curve.to_poly_curve();
    add_curve_certificates(&mut certs, curve);
    let bez = T::exact_curve(curve.to_bezier()?)?;
    // the arc length the certificates speak of, as a value (exact: σ is a polynomial)
    let values = vec![NamedQuantity::new(
        "arc_length",
        if T::EXACT { "∫₀¹ σ dt (σ = |A|², exact)" } else { "∫₀¹ σ dt (f64)" },
        T::quantity(pc.arc_length()),
    )];
    let mut out = vec![arith::object_with::<T>(args, Geometry::Curve(bez.clone()), certs, values)];
    // the display objects are exact only (refused in f64 above)
    let (Some(curve), Ok(pc)) = (
        arith::same_ref::<_, PhCurve<Q>>(curve),
        arith::same::<_, PhPolyCurve<Q>>(pc),
    ) else {
        return Ok(out);
    };
    let samples = args.int("samples")?;
    if !(2..=200).contains(&samples) {
        return Err(OpError::param(
            "samples",
            format!("samples must be in 2..=200, got {samples}"),
        ));
    }
    let ts: Vec<Q> = (0..samples)
        .map(|k| Q::from(k) / Q::from(samples - 1))
        .collect();
    let name = args.name().to_string();
    match args.string("frame")? {
        "euler_rodrigues" => out.push(erf_object(args, &name, curve, &pc, &ts, &bez)?),
        "frenet" => out.push(frenet_object(args, &name, &pc, &ts, &bez)?),
        _ => {}
    }
    if args.bool("comb")? {
        out.push(comb_object(args, &name, &pc, &ts, &bez)?);
    }
    let feed = args.int("feed")?;
    if feed > 0 {
        out.push(feed_object(args, &name, curve, &pc, feed, &bez)?);
    } else if feed < 0 {
        return Err(OpError::param("feed", format!("feed must be ≥ 0, got {feed}")));
    }
    Ok(out)
}

fn named(args: &OpArgs, name: String, geometry: Geometry, certs: Vec<Certificate>) -> Object {
    let mut o = args.object(geometry, certs);
    o.name = name;
    o
}

fn erf_object(
    args: &OpArgs,
    name: &str,
    curve: &PhCurve<Q>,
    pc: &PhPolyCurve<Q>,
    ts: &[Q],
    bez: &BezierCurve<Q>,
) -> Result<Object, OpError> {
    let frame = curve.euler_rodrigues_frame();
    let len = args.number("frame_length")?;
    let mut segs = vec![bez.clone()];
    for t in ts {
        let Some(e) = frame.eval(t) else { continue };
        let p = pc.eval(t);
        for v in &e {
            segs.push(segment(&p, &add(&p, &scale(v, &len)))?);
        }
    }
    let certs = frame.certify();
    Ok(named(
        args,
        format!("{name}_frame"),
        Geometry::Curves(segs),
        certs,
    ))
}

fn frenet_object(
    args: &OpArgs,
    name: &str,
    pc: &PhPolyCurve<Q>,
    ts: &[Q],
    bez: &BezierCurve<Q>,
) -> Result<Object, OpError> {
    let dph = match pc.dph_test()? {
        DphTest::Dph(d) => d,
        DphTest::Line => {
            return Err(OpError::param(
                "frame",
                "a straight line has no Frenet frame (use frame = \"euler_rodrigues\")",
            ))
        }
        DphTest::NotDph { .. } => {
            return Err(OpError::param(
                "frame",
                "the curve is not DPH (ρ = |r'×r''|²/σ² is not c·ω̃²): its Frenet frame is not rational; use frame = \"euler_rodrigues\"",
            ))
        }
    };
    let frame = pc.frenet_frame(&dph);
    let len = args.number("frame_length")?;
    let root_c = rcagd_algebra::sqrt_in_field(frame.radicand()).filter(|r| *r > Q::zero());
    let mut segs = vec![bez.clone()];
    for t in ts {
        let Some((tt, pt, bt)) = frame.eval_scaled(t) else {
            continue;
        };
        let p = pc.eval(t);
        let vecs: Vec<[Q; 3]> = match &root_c {
            // √c rational: exact p = p̃/√c, b = b̃/√c
            Some(r) => {
                let inv = Q::one() / r.clone();
                vec![tt, scale(&pt, &inv), scale(&bt, &inv)]
            }
            None => {
                let k = 1.0 / Scalar::to_f64(frame.radicand()).sqrt();
                let f = |v: &[Q; 3]| -> Result<[Q; 3], OpError> {
                    Ok([
                        to_q(Scalar::to_f64(&v[0]) * k)?,
                        to_q(Scalar::to_f64(&v[1]) * k)?,
                        to_q(Scalar::to_f64(&v[2]) * k)?,
                    ])
                };
                vec![tt, f(&pt)?, f(&bt)?]
            }
        };
        for v in &vecs {
            segs.push(segment(&p, &add(&p, &scale(v, &len)))?);
        }
    }
    let mut certs = pc.certify_dph(&dph);
    certs.extend(frame.certify());
    Ok(named(
        args,
        format!("{name}_frame"),
        Geometry::Curves(segs),
        certs,
    ))
}

fn comb_object(
    args: &OpArgs,
    name: &str,
    pc: &PhPolyCurve<Q>,
    ts: &[Q],
    bez: &BezierCurve<Q>,
) -> Result<Object, OpError> {
    let k = -args.number("comb_scale")?;
    let mut teeth = vec![bez.clone()];
    let mut tips: Vec<[Q; 3]> = Vec::new();
    for (p, tip) in pc.curvature_comb(ts, &k) {
        teeth.push(segment(&p, &tip)?);
        tips.push(tip);
    }
    for w in tips.windows(2) {
        teeth.push(segment(&w[0], &w[1])?);
    }
    let certs = pc.certify_curvature_vector()?;
    Ok(named(
        args,
        format!("{name}_comb"),
        Geometry::Curves(teeth),
        certs,
    ))
}

fn feed_object(
    args: &OpArgs,
    name: &str,
    curve: &PhCurve<Q>,
    pc: &PhPolyCurve<Q>,
    feed: i64,
    bez: &BezierCurve<Q>,
) -> Result<Object, OpError> {
    if feed > 200 {
        return Err(OpError::param("feed", format!("feed must be ≤ 200, got {feed}")));
    }
    let n = usize::try_from(feed).map_err(|_| OpError::param("feed", "feed must be ≥ 0"))?;
    let tol = Q::one() / Q::from(1i64 << 40);
    let fm = curve.constant_feed_marks(n, &tol)?;
    let frame = curve.euler_rodrigues_frame();
    let half = args.number("frame_length")? / qi(4);
    let mut marks = vec![bez.clone()];
    for t in &fm.parameters {
        let p = pc.eval(t);
        let Some(e) = frame.eval(t) else { continue };
        let off = scale(&e[1], &half);
        let a = add(&p, &scale(&off, &-Q::one()));
        marks.push(segment(&a, &add(&p, &off))?);
    }
    let certs = vec![fm.certificate("2⁻⁴⁰")];
    Ok(named(
        args,
        format!("{name}_feed"),
        Geometry::Curves(marks),
        certs,
    ))
}

/// The helix/DPH certificates of a constructed curve (exact): the DPH identity when it
/// is DPH and the helix axis identities when it has an axis.
fn shape_certificates(curve: &PhCurve<Q>) -> Result<Vec<Certificate>, OpError> {
    let pc = curve.to_poly_curve();
    let mut certs = Vec::new();
    if let DphTest::Dph(d) = pc.dph_test()? {
        certs.extend(pc.certify_dph(&d));
    }
    match pc.helix_test()? {
        t @ (HelixTest::Helix(_) | HelixTest::Planar { .. }) => {
            certs.extend(pc.certify_helix_test(&t))
        }
        HelixTest::Line | HelixTest::NotHelix => {}
    }
    Ok(certs)
}

// ------------------------------------------------------------------ builds

/// `ph_curve` in `T` (one builder for the exact op and the float path; the display
/// objects are exact only).
pub(crate) fn build_ph_curve<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let start = point3::<T>(args, "start")?;
    let quats = args.get("quaternions").is_some();
    let hopf = args.get("alpha").is_some() || args.get("beta").is_some();
    let curve = match (quats, hopf) {
        (true, false) => {
            PhCurve::new(quaternions(args)?, start)?
        }
        (false, true) => {
            if args.get("alpha").is_none() || args.get("beta").is_none() {
                return Err(OpError::new("the Hopf form needs both `alpha` and `beta`"));
            }
            PhCurve::from_hopf(&complexes(args, "alpha")?, &complexes(args, "beta")?, start)?
        }
        (true, true) => {
            return Err(OpError::param(
                "quaternions",
                "give either `quaternions` or `alpha` and `beta`, not both",
            ))
        }
        (false, false) => {
            return Err(OpError::new(
                "a PH curve needs `quaternions` (or `alpha` and `beta`)",
            ))
        }
    };
    curve_objects(args, &curve, Vec::new())
}

/// `ph_helix` in `T` (one builder for the exact op and the float path).
pub(crate) fn build_ph_helix<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let seed = LineCircle::new(
        complex::<T>(args, "a0")?,
        complex(args, "a1")?,
        complex(args, "b0")?,
        complex(args, "b1")?,
    )?;
    let f = numbers::<T>(args, "f")?;
    let g = numbers::<T>(args, "g")?;
    let w = complexes::<T>(args, "w")?;
    let curve = seed.helix(&f, &g, &w, point3(args, "start")?)?;
    let mut certs = seed.certify_helix_construction(&curve, &f, &g, &w)?;
    let pc = curve.to_poly_curve();
    match pc.helix_test()? {
        HelixTest::NotHelix => {
            return Err(OpError::new(
                "internal error: the constructed curve fails the helix axis test",
            ))
        }
        HelixTest::Line => {
            return Err(OpError::new(
                "the data give a straight line (αβ' − α'β ≡ 0 after cancellation)",
            ))
        }
        _ => {}
    }
    if let DphTest::Dph(d) = pc.dph_test()? {
        certs.extend(pc.certify_dph(&d));
    }
    curve_objects(args, &curve, certs)
}

fn build_ph_dph_septic(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let h = numbers(args, "h")?;
    let w = complexes(args, "w")?;
    let root = args.int("root")?;
    let roots = dph_septic_z_roots(&h, &w)?;
    let z = match root {
        0 => &roots[0],
        1 => &roots[1],
        _ => {
            return Err(OpError::param(
                "root",
                format!("root must be 0 or 1, got {root}"),
            ))
        }
    };
    let curve = dph_septic(
        &h,
        &w,
        &complex(args, "alpha0")?,
        &complex(args, "alpha1")?,
        &complex(args, "beta0")?,
        z,
        point3(args, "start")?,
    )?;
    let mut certs = certify_dph_septic(&curve, &h, &w)?;
    certs.extend(shape_certificates(&curve)?);
    curve_objects(args, &curve, certs)
}

fn build_ph_hermite(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let data = HermiteData::new(
        point3(args, "p_s")?,
        point3(args, "d_s")?,
        point3(args, "p_f")?,
        point3(args, "d_f")?,
    );
    let sol = data.solve_exact()?;
    // every interpolant enclosed from the exact root: control points to 2⁻⁸⁰, the bending
    // energy to 2⁻⁴⁰ relative (None where σ cannot be proven positive: the energy diverges)
    let ranked = sol.ranked_interpolants(&data, &pow2(-80), &pow2(-40))?;
    let mut out = Vec::with_capacity(ranked.len());
    for r in ranked {
        let k = r.rank - 1;
        let s = sol
            .interpolants
            .get(r.index)
            .ok_or_else(|| OpError::new("internal error: a ranked interpolant out of range"))?;
        let enc = r.enclosure.as_ref();
        let exact = r.exact;
        let pts = r.control_points;
        let certs = r.certificates;
        let bez = BezierCurve::from_points(&pts)?;
        let name = match (k, s.least_energy) {
            (0, _) => args.name().to_string(),
            (_, true) => format!("{}_{}_min", args.name(), k + 1),
            (_, false) => format!("{}_{}", args.name(), k + 1),
        };
        let mut values = if k == 0 {
            hermite_problem_values(&sol)
        } else {
            Vec::new()
        };
        values.extend(hermite_interpolant_values(s, enc.ok(), k + 1, exact));
        if let (Ok(e), false) = (enc, exact) {
            let written: Vec<[Q; 3]> = pts
                .iter()
                .map(|p| [p[0].clone(), p[1].clone(), p[2].clone()])
                .collect();
            values.push(NamedQuantity::new(
                "control_point_error",
                "every exact control point is within this distance (per coordinate) of the \
                 written one (interval arithmetic from the exact root)",
                Quantity::Rational(round_decimal(&e.distance_bound(&written), 3, true)),
            ));
        }
        out.push(named(args, name, Geometry::Curve(bez), certs).with_values(values));
    }
    Ok(out)
}

/// `ph_hermite` in `f64` (the float path, `rcagd build --float`): the same algorithm with
/// roots by Sturm sequences in floating point ([`HermiteData::solve_f64`]), the
/// interpolants ranked by their `f64` bending energy and named as by the exact op
/// (`NAME`, `NAME_2`, `NAME_3_min`, …), each with its `f64` certificates (the root
/// certificates on the first). The exact op works in `Q(|d_s||d_f|)` and encloses every
/// interpolant from its exact root; no such proof is made here.
pub(crate) fn build_ph_hermite_f64(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let data = HermiteData::<Q>::new(
        point3(args, "p_s")?,
        point3(args, "d_s")?,
        point3(args, "p_f")?,
        point3(args, "d_f")?,
    );
    let sol = data.solve_f64()?;
    let certs = sol.certify();
    let mut order: Vec<usize> = (0..sol.interpolants.len()).collect();
    order.sort_by(|a, b| {
        let e = |i: &usize| sol.interpolants.get(*i).map_or(f64::NAN, |s| s.bending_energy);
        e(a).total_cmp(&e(b))
    });
    let mut out = Vec::with_capacity(order.len());
    for (k, &i) in order.iter().enumerate() {
        let s = sol
            .interpolants
            .get(i)
            .ok_or_else(|| OpError::new("internal error: an interpolant out of range"))?;
        let prefix = format!("interpolant {i}");
        let mut own: Vec<Certificate> = certs
            .iter()
            .filter(|c| {
                c.property.starts_with(&format!("{prefix}:"))
                    || c.property.starts_with(&format!("{prefix} "))
            })
            .cloned()
            .collect();
        if k == 0 {
            own.extend(
                certs
                    .iter()
                    .filter(|c| !c.property.starts_with("interpolant "))
                    .cloned(),
            );
        }
        let bez = f64::exact_curve(s.curve.to_bezier()?)?;
        let name = match (k, s.least_energy) {
            (0, _) => args.name().to_string(),
            (_, true) => format!("{}_{}_min", args.name(), k + 1),
            (_, false) => format!("{}_{}", args.name(), k + 1),
        };
        let mut values = hermite_interpolant_values(s, None, k + 1, false);
        if k == 0 {
            values.push(NamedQuantity::new(
                "interpolants",
                "number of interpolating helical quintics",
                Quantity::Integer(sol.interpolants.len() as i64),
            ));
        }
        let o = named(args, name, Geometry::Curve(bez), own).with_values(values);
        out.push(<f64 as OpScalar>::finish(o));
    }
    Ok(out)
}

/// The values of the whole Hermite problem (on the least-energy object): the elimination
/// quartic, its real roots (exact, or with an exact isolating interval), counts.
fn hermite_problem_values(sol: &HermiteSolution<QuadExt>) -> Vec<NamedQuantity> {
    let rational_quartic = poly_io::rational_poly(&sol.quartic);
    let roots: Vec<Quantity> = sol
        .roots
        .iter()
        .map(|r| match (&r.exact, &rational_quartic, r.lo.to_rational(), r.hi.to_rational()) {
            (Some(x), _, _, _) => Quantity::Quadratic(x.clone()),
            (None, Some(poly), Some(lo), Some(hi)) => Quantity::RealRoot {
                poly: poly.clone(),
                interval: RootInterval { lo, hi },
            },
            _ => Quantity::Vector(vec![
                Quantity::Quadratic(r.lo.clone()),
                Quantity::Quadratic(r.hi.clone()),
            ]),
        })
        .collect();
    let valid = sol.roots.iter().filter(|r| r.valid).count();
    vec![
        NamedQuantity::new(
            "elimination_quartic",
            "Q(s), s = r₁ = 16k₀²: Besednjak (9.22) and (9.26) eliminated in r₁ instead of ξ = tan(φ/2); its real roots give the interpolants",
            poly_io::quad_poly_value(&sol.quartic, "s"),
        ),
        NamedQuantity::new(
            "quartic_roots",
            "the real roots s of Q, exact or with an exact isolating interval",
            Quantity::Vector(roots),
        ),
        NamedQuantity::new(
            "valid_roots",
            "roots with r₁ ≥ 0, r₂ ≥ 0, r₃ ≠ 0 (each gives two interpolants)",
            Quantity::Integer(valid as i64),
        ),
        NamedQuantity::new(
            "interpolants",
            "number of interpolating helical quintics",
            Quantity::Integer(sol.interpolants.len() as i64),
        ),
    ]
}

/// The values of one interpolant: rank, energy, k₀, k₂, φ, the helix axis.
fn hermite_interpolant_values(
    s: &HermiteInterpolant,
    enc: Option<&EnclosedInterpolant>,
    rank: usize,
    exact: bool,
) -> Vec<NamedQuantity> {
    let energy = match enc {
        Some(e) => NamedQuantity::new(
            "bending_energy",
            "E = ∫κ²σ dt (Besednjak (9.29)): an interval proven to contain it (validated \
             quadrature on control points enclosed from the exact root)",
            Quantity::enclosure(&e.bending_energy.lo(), &e.bending_energy.hi(), 17),
        ),
        None => NamedQuantity::new(
            "bending_energy",
            "E = ∫κ²σ dt (Besednjak (9.29)), by adaptive quadrature (σ could not be proven \
             positive: no enclosure)",
            Quantity::Approx(s.bending_energy),
        ),
    };
    let mut v = vec![
        NamedQuantity::new(
            "rank",
            "rank by increasing bending energy (1 = least)",
            Quantity::Integer(rank as i64),
        ),
        NamedQuantity::new(
            "least_energy",
            "the least bending energy of all interpolants",
            Quantity::Bool(s.least_energy),
        ),
        energy,
        NamedQuantity::new("k0", "k₀ = c₀ + 3/4", Quantity::Approx(s.k0)),
        NamedQuantity::new("k2", "k₂ = c₂ + 3/4", Quantity::Approx(s.k2)),
        NamedQuantity::new("phi", "φ with A₂ = Â₂e^{iφ}", Quantity::Approx(s.phi)),
        NamedQuantity::new(
            "exact_control_points",
            "the control points are exact (rational root and square roots)",
            Quantity::Bool(exact),
        ),
    ];
    match &s.helix {
        HelixTest::Helix(h) => {
            let n = h.a.iter().map(|x| x * x).sum::<f64>().sqrt();
            v.push(NamedQuantity::new(
                "axis",
                "unit helix axis a/|a| with a·r' ≡ σ",
                Quantity::Vector(h.a.iter().map(|x| Quantity::Approx(x / n)).collect()),
            ));
            v.push(NamedQuantity::new(
                "kappa_over_tau",
                "|κ/τ| = tan ψ = √(|a|² − 1)",
                Quantity::Approx((n * n - 1.0).max(0.0).sqrt()),
            ));
        }
        HelixTest::Planar { normal } => v.push(NamedQuantity::new(
            "plane_normal",
            "planar interpolant: n with n·r' ≡ 0",
            Quantity::Vector(normal.iter().map(|x| Quantity::Approx(*x)).collect()),
        )),
        HelixTest::Line | HelixTest::NotHelix => {}
    }
    v
}
