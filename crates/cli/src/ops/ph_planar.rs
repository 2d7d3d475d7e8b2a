//! Ops of the `ph_planar` topic (issue 5 part B, `rcagd::ph::{planar, planar_hermite,
//! spline, spatial_hermite}`): planar PH curves from a complex preimage, their exact
//! rational offsets, planar PH quintic Hermite interpolants, C2 PH quintic splines and
//! spatial PH quintic Hermite interpolants.
//!
//! Results solved in `f64` (irrational square roots, Newton–Raphson) are stored as the
//! exact PH curve of the preimage rounded to rationals: its PH certificates are exact,
//! and the interpolation conditions are checked to a tolerance (reported, `f64`).

use super::arith::{self, OpScalar};
use super::{prefixed, OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use rcagd::ph::{
    PhCurve, PhQuinticSpline, PlanarHermiteData, PlanarHermiteInterpolant, PlanarHermiteResult,
    PlanarPhCurve, SpatialHermiteData, SpatialHermiteQuintic, SpatialHermiteResult, SplineEnds,
};
use rcagd::ph::hermite_values::{planar_hermite_branches, PlanarHermiteBranch};
use rcagd::ph::PhError;
use rcagd_algebra::{Certificate, Complex, Quaternion, Rational, Scalar};
use rcagd_io::quantity::{NamedQuantity, Quantity};

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[
    PH_PLANAR_CURVE,
    PH_PLANAR_OFFSET,
    PH_PLANAR_HERMITE,
    PH_PLANAR_SPLINE,
    PH_SPATIAL_HERMITE,
];

const PREIMAGE: ParamSpec = ParamSpec::required(
    "preimage",
    ParamKind::Points,
    "Bernstein coefficients [re, im] of the complex preimage w(t); the curve has r' = w², degree 2·len − 1",
).degree();
const START: ParamSpec =
    ParamSpec::with_default("start", ParamKind::Point2, "[0, 0]", "start point r(0)");

const PH_PLANAR_CURVE: OpSpec = OpSpec {
    name: "ph_planar_curve",
    summary: "a planar PH curve r' = w² from the Bernstein coefficients of a complex polynomial w(t) (exact control points, σ = |w|², arc length)",
    params: &[PREIMAGE, START],
    example: r#"[[object]]
name = "tschirnhausen_cubic"
op = "ph_planar_curve"
preimage = [[1, 0], [1, 1]]
start = [0, 0]
"#,
    build: build_curve::<Rational>,
};

const PH_PLANAR_OFFSET: OpSpec = OpSpec {
    name: "ph_planar_offset",
    summary: "the exact rational offset r + d·n (degree 2n − 1) of a planar PH curve given by its complex preimage",
    params: &[
        PREIMAGE,
        START,
        ParamSpec::required(
            "distance",
            ParamKind::Number,
            "signed offset distance d (positive: to the right of the direction of travel)",
        ),
    ],
    example: r#"[[object]]
name = "tschirnhausen_offset"
op = "ph_planar_offset"
preimage = [[1, 0], [1, 1]]
distance = "-1/4"
"#,
    build: build_offset::<Rational>,
};

const PH_PLANAR_HERMITE: OpSpec = OpSpec {
    name: "ph_planar_hermite",
    summary: "planar PH quintic C1 Hermite interpolants (Farouki–Neff): the best (least absolute rotation index) or all four; exact when the square roots are rational; values for all four: the elimination quadratic 2w₁² + 3(w₀ + w₂)w₁ + 3w₀² + w₀w₂ + 3w₂² − 15Δp = 0, its discriminant, w, arc length, rotation index, bending energy",
    params: &[
        ParamSpec::required("p0", ParamKind::Point2, "start point"),
        ParamSpec::required("d0", ParamKind::Point2, "start derivative r'(0), non-zero"),
        ParamSpec::required("p1", ParamKind::Point2, "end point, ≠ p0"),
        ParamSpec::required("d1", ParamKind::Point2, "end derivative r'(1), non-zero"),
        ParamSpec::with_default(
            "select",
            ParamKind::Choice(&["best", "all"]),
            "\"best\"",
            "the best interpolant only, or all four",
        ),
    ],
    example: r#"[[object]]
name = "ph_quintic_hermite"
op = "ph_planar_hermite"
p0 = [0, 0]
d0 = [1, 0]
p1 = ["2/15", "2/3"]
d1 = [0, 2]
select = "all"
"#,
    build: build_hermite::<Rational>,
};

const PH_PLANAR_SPLINE: OpSpec = OpSpec {
    name: "ph_planar_spline",
    summary: "a C2 PH quintic spline through points (open with natural or given end derivatives, or closed), by Newton–Raphson; exact PH segments, exact C2 junctions",
    params: &[
        ParamSpec::required("points", ParamKind::Points, "the points [x, y] (at least 2; 3 for closed)").degree(),
        ParamSpec::with_default(
            "ends",
            ParamKind::Choice(&["natural", "derivatives", "closed"]),
            "\"natural\"",
            "end conditions: r'' = 0 at the ends, given end derivatives d0 and d1, or a closed loop",
        ),
        ParamSpec::optional("d0", ParamKind::Point2, "start derivative (ends = \"derivatives\")"),
        ParamSpec::optional("d1", ParamKind::Point2, "end derivative (ends = \"derivatives\")"),
    ],
    example: r#"[[object]]
name = "ph_spline_wave"
op = "ph_planar_spline"
points = [[0, 0], [1, 1], [2, 0], [3, 1], [4, 0]]
ends = "natural"
"#,
    build: build_spline::<Rational>,
};

const PH_SPATIAL_HERMITE: OpSpec = OpSpec {
    name: "ph_spatial_hermite",
    summary: "a spatial PH quintic C1 Hermite interpolant (Farouki–al-Kandari–Sakkalis) with free angles φ0, φ2; exact when the square roots are rational; values: the angles, the preimage coefficients, arc length, bending energy, end residual",
    params: &[
        ParamSpec::required("p0", ParamKind::Point3, "start point"),
        ParamSpec::required("d0", ParamKind::Point3, "start derivative, non-zero"),
        ParamSpec::required("p1", ParamKind::Point3, "end point, ≠ p0"),
        ParamSpec::required("d1", ParamKind::Point3, "end derivative, non-zero"),
        ParamSpec::optional(
            "tau0",
            ParamKind::Number,
            "tan(φ0/2) (φ0 = −π/2 is −1); with tau2 selects the member; default: the least bending energy of φ0, φ2 ∈ {−π/2, 0, π/2, π}, refined by a golden-section search (a local minimum)",
        ),
        ParamSpec::optional("tau2", ParamKind::Number, "tan(φ2/2)"),
    ],
    example: r#"[[object]]
name = "spatial_ph_quintic"
op = "ph_spatial_hermite"
p0 = [0, 0, 0]
d0 = [1, 0, 0]
p1 = ["-1/15", "9/5", "-1/15"]
d1 = [-1, 2, 2]
tau0 = 0
tau2 = 0
"#,
    build: build_spatial,
};

fn point2(v: &[Rational], param: &'static str) -> Result<[Rational; 2], OpError> {
    <[Rational; 2]>::try_from(v.to_vec())
        .map_err(|_| OpError::param(param, format!("`{param}` needs points [x, y]")))
}

fn arg2(args: &OpArgs, param: &'static str) -> Result<[Rational; 2], OpError> {
    point2(&args.point(param)?, param)
}

fn arg3(args: &OpArgs, param: &'static str) -> Result<[Rational; 3], OpError> {
    <[Rational; 3]>::try_from(args.point(param)?)
        .map_err(|_| OpError::param(param, format!("`{param}` needs a point [x, y, z]")))
}

fn planar_curve<T: OpScalar>(args: &OpArgs) -> Result<PlanarPhCurve<T>, OpError> {
    let w = args
        .points("preimage")?
        .iter()
        .map(|p| point2(p, "preimage").map(|[a, b]| Complex::new(arith::of(&a), arith::of(&b))))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(PlanarPhCurve::new(w, arg2(args, "start")?.each_ref().map(arith::of))?)
}

/// `ph_planar_curve` in `T` (one builder for the exact op and the float path).
pub(crate) fn build_curve<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let c = planar_curve::<T>(args)?;
    let certs = c.certify();
    let values = vec![NamedQuantity::new(
        "arc_length",
        if T::EXACT { "∫₀¹ |w|² dt (exact)" } else { "∫₀¹ |w|² dt (f64)" },
        T::quantity(c.arc_length()),
    )];
    Ok(vec![arith::object_with::<T>(args, Geometry::Curve(T::exact_curve(c.to_bezier()?)?), certs, values)])
}

/// `ph_planar_offset` in `T`.
pub(crate) fn build_offset<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let c = planar_curve::<T>(args)?;
    let off = c.offset(&arith::number(args, "distance")?)?;
    // the offset's weight is σ = |w|² ≥ 0: a zero of w on [0, 1] (a cusp of the curve,
    // σ = 0) is a pole of the offset; the one rule for weights decides it exactly (in
    // f64 only weights of one sign are accepted)
    let pole_free = T::curve_pole_free(&off.curve).map_err(|e| {
        let Some(e) = e else {
            return OpError::param(
                "preimage",
                "the offset's weights σ = |w|² are not all of one sign (a cusp of the curve on or near [0, 1]): the float path does not decide whether σ has a zero; build without --float",
            );
        };
        let at: Vec<String> = e
            .zeros
            .iter()
            .map(|(lo, hi, x)| {
                if lo == hi {
                    format!("t = {}", rcagd_algebra::rational::format_rational(lo))
                } else {
                    format!("t ≈ {x}")
                }
            })
            .collect();
        OpError::param(
            "preimage",
            format!(
                "the curve has a cusp at {} (w(t) = 0, so the speed σ = |w|² vanishes): its offset has a pole there; give a preimage without a zero on [0, 1]",
                at.join(", ")
            ),
        )
    })?;
    let mut certs = prefixed("base: ", c.certify());
    certs.extend(off.certify());
    certs.push(pole_free);
    Ok(vec![arith::object::<T>(args, Geometry::Curve(T::exact_curve(off.curve)?), certs)])
}

fn rat(x: f64) -> Result<Rational, OpError> {
    Rational::try_from(x).map_err(|_| OpError::new("non-finite f64 result"))
}

/// An f64 planar interpolant as the exact PH curve of its rounded preimage.
fn round_planar(c: &PlanarPhCurve<f64>, p0: &[Rational; 2]) -> Result<PlanarPhCurve<Rational>, OpError> {
    c.rounded(p0).map_err(|e| match e {
        PhError::OutOfRange(m) => OpError::new(m),
        e => e.into(),
    })
}

/// `ph_planar_hermite` in `T`: the exact op solves in the quadratic fields the branches
/// live in when their square roots are rational, else in `f64` and rounds the control
/// points to rationals with exact certificates of the rounded curves
/// ([`PlanarHermiteData::solve_auto`]); the float path solves in `f64` and keeps the
/// `f64` curves with their tolerance certificates ([`PlanarHermiteData::solve_f64`]).
pub(crate) fn build_hermite<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let data = PlanarHermiteData::new(
        arg2(args, "p0")?,
        arg2(args, "d0")?,
        arg2(args, "p1")?,
        arg2(args, "d1")?,
    );
    let all = args.string("select")? == "all";
    let mut curves = Vec::new();
    let mut certs = Vec::new();
    let keep = |best: bool| all || best;
    let result = if T::EXACT {
        data.solve_auto()?
    } else {
        PlanarHermiteResult::Float(Box::new(data.solve_f64()?))
    };
    let values = match result {
        PlanarHermiteResult::Exact(s) => {
            for (k, c) in s.interpolants.iter().enumerate() {
                if !keep(c.best) {
                    continue;
                }
                certs.extend(prefixed(&tag(k, c), only(&s, c).certify()));
                curves.push(c.curve.to_bezier()?);
            }
            let branches = planar_hermite_branches(&s);
            for b in &branches {
                certs.extend(b.certify());
            }
            hermite_values(&branches, true, |x: &Rational| Quantity::Rational(x.clone()))
        }
        PlanarHermiteResult::Float(s) => {
            for (k, c) in s.interpolants.iter().enumerate() {
                if !keep(c.best) {
                    continue;
                }
                let tag = tag(k, c);
                if T::EXACT {
                    let exact = round_planar(&c.curve, &data.p0)?;
                    certs.extend(prefixed(&tag, exact.certify()));
                    certs.push(exact.rounded_hermite_certificate(&data));
                    curves.push(exact.to_bezier()?);
                } else {
                    certs.extend(prefixed(&tag, only(&s, c).certify()));
                    curves.push(f64::exact_curve(c.curve.to_bezier()?)?);
                }
            }
            let branches = planar_hermite_branches(&s);
            for b in &branches {
                certs.extend(b.certify());
            }
            hermite_values(&branches, false, |x: &f64| Quantity::Approx(*x))
        }
    };
    let geometry = if curves.len() == 1 {
        Geometry::Curve(curves.remove(0))
    } else {
        Geometry::Curves(curves)
    };
    Ok(vec![T::finish(
        args.object(geometry, certs).with_values(values),
    )])
}

/// The solution `s` reduced to its interpolant `c` (to certify one interpolant alone).
fn only<F: Scalar>(
    s: &rcagd::ph::PlanarHermiteSolution<F>,
    c: &PlanarHermiteInterpolant<F>,
) -> rcagd::ph::PlanarHermiteSolution<F> {
    rcagd::ph::PlanarHermiteSolution {
        data: s.data.clone(),
        interpolants: vec![c.clone()],
        exact: s.exact,
    }
}

/// The values of the four interpolants: the elimination quadratic of `w₁`, its
/// discriminant, `w`, arc length, rotation index, energy; exact when `exact`.
fn hermite_values<F: Scalar>(
    branches: &[PlanarHermiteBranch<F>],
    exact: bool,
    num: impl Fn(&F) -> Quantity,
) -> Vec<NamedQuantity> {
    let cx = |z: &Complex<F>| Quantity::Vector(vec![num(&z.re), num(&z.im)]);
    let sign = |s: i8| if s > 0 { '+' } else { '−' };
    let mut v = vec![
        NamedQuantity::new("exact", "every square root is rational: exact interpolants", Quantity::Bool(exact)),
        NamedQuantity::new("solutions", "the number of interpolants (w₂ = ±√d₁, two roots w₁ each)", Quantity::Integer(branches.len() as i64)),
    ];
    for (k, b) in branches.iter().enumerate() {
        let t = |s: &str| format!("{s}_{k}");
        v.push(NamedQuantity::new(t("signs"), "(sign of w₂ = ±√d₁, sign of the root of the quadratic)", Quantity::Text(format!("({}, {})", sign(b.signs.0), sign(b.signs.1)))));
        v.push(NamedQuantity::new(t("quadratic"), "[c₀, c₁, c₂] of c₂w₁² + c₁w₁ + c₀ = 0, each [re, im] (Farouki–Neff)", Quantity::Vector(b.quadratic.iter().map(cx).collect())));
        v.push(NamedQuantity::new(t("discriminant"), "120Δp − 15(d₀ + d₁) + 10w₀w₂, [re, im]", cx(&b.discriminant)));
        v.push(NamedQuantity::new(t("w"), "Bernstein coefficients w₀, w₁, w₂ of w(t), r' = w², each [re, im]", Quantity::Vector(b.w.iter().map(cx).collect())));
        v.push(NamedQuantity::new(t("arc_length"), "∫₀¹ |w|² dt", num(&b.arc_length)));
        v.push(NamedQuantity::new(t("rotation_index"), "absolute rotation index (1/2π)∫|κ| ds", Quantity::Approx(b.absolute_rotation_index)));
        v.push(NamedQuantity::new(t("bending_energy"), "∫κ² ds", Quantity::Approx(b.bending_energy)));
        v.push(NamedQuantity::new(t("best"), "the good interpolant (least rotation index, then energy)", Quantity::Bool(b.best)));
    }
    v
}

fn tag<F>(k: usize, c: &PlanarHermiteInterpolant<F>) -> String {
    format!(
        "interpolant {k} (R = {:.4}, E = {:.4}{}): ",
        c.absolute_rotation_index,
        c.bending_energy,
        if c.best { ", best" } else { "" }
    )
}

/// `ph_planar_spline` in `T` (one builder for the exact op and the float path).
pub(crate) fn build_spline<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let in_t = |p: [Rational; 2]| p.each_ref().map(arith::of::<T>);
    let pts = args
        .points("points")?
        .iter()
        .map(|p| point2(p, "points").map(in_t))
        .collect::<Result<Vec<_>, _>>()?;
    let ends = match args.string("ends")? {
        "closed" => SplineEnds::Closed,
        "derivatives" => {
            let d0 = args
                .opt_point("d0")?
                .ok_or_else(|| OpError::param("d0", "ends = \"derivatives\" needs d0"))?;
            let d1 = args
                .opt_point("d1")?
                .ok_or_else(|| OpError::param("d1", "ends = \"derivatives\" needs d1"))?;
            SplineEnds::Derivatives(in_t(point2(&d0, "d0")?), in_t(point2(&d1, "d1")?))
        }
        _ => SplineEnds::Natural,
    };
    let s = PhQuinticSpline::interpolate(&pts, &ends)?;
    let certs = s.certify();
    let curves = s
        .segments
        .iter()
        .map(|c| c.to_bezier())
        .collect::<Result<Vec<_>, _>>()?;
    Ok(vec![arith::object::<T>(args, Geometry::Curves(arith::exact_curves(curves)?), certs)])
}

fn spatial_float(
    s: &SpatialHermiteQuintic<f64>,
    data: &SpatialHermiteData<Rational>,
) -> Result<(PhCurve<Rational>, Vec<Certificate>), OpError> {
    let coeffs = s
        .curve
        .coefficients()
        .iter()
        .map(|a| Ok(Quaternion::new(rat(a.w)?, rat(a.x)?, rat(a.y)?, rat(a.z)?)))
        .collect::<Result<Vec<_>, OpError>>()?;
    let curve = PhCurve::new(coeffs, data.p0.clone())?;
    let exact = SpatialHermiteQuintic {
        data: data.clone(),
        rotation0: (Rational::from(1), Rational::from(0)),
        rotation2: (Rational::from(1), Rational::from(0)),
        curve: curve.clone(),
        bending_energy: s.bending_energy,
    };
    let res = exact.residual();
    let scale = [&data.p0, &data.d0, &data.p1, &data.d1]
        .iter()
        .flat_map(|v| v.iter().map(|x| Scalar::to_f64(x).abs()))
        .fold(1.0, f64::max);
    let tol = 1e-9 * scale;
    let mut certs = curve.certify();
    certs.push(Certificate::decide(
        format!("Hermite conditions to {tol:e} (preimage rounded from f64; bending energy {:.6})", s.bending_energy),
        res <= tol,
        false,
        || format!("{res:e}"),
    ));
    Ok((curve, certs))
}

fn build_spatial(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let data = SpatialHermiteData::new(
        arg3(args, "p0")?,
        arg3(args, "d0")?,
        arg3(args, "p1")?,
        arg3(args, "d1")?,
    );
    let t0 = args.opt_number("tau0")?;
    let t2 = args.opt_number("tau2")?;
    let (curve, certs) = match (t0.clone(), t2.clone()) {
        (Some(a), Some(b)) => match data.solve_auto(&a, &b)? {
            SpatialHermiteResult::Exact(s) => {
                let c = s.certify();
                (s.curve, c)
            }
            SpatialHermiteResult::Float(s) => spatial_float(&s, &data)?,
        },
        (None, None) => spatial_float(&data.default_f64()?, &data)?,
        _ => {
            return Err(OpError::param(
                "tau2",
                "give both tau0 and tau2, or neither (least bending energy default)",
            ))
        }
    };
    let values = spatial_values(&curve, &data, t0.as_ref(), t2.as_ref());
    Ok(vec![args
        .object(Geometry::Curve(curve.to_bezier()?), certs)
        .with_values(values)])
}

/// The values of the chosen spatial interpolant: the angles, its preimage coefficients,
/// arc length and bending energy.
fn spatial_values(
    curve: &PhCurve<Rational>,
    data: &SpatialHermiteData<Rational>,
    t0: Option<&Rational>,
    t2: Option<&Rational>,
) -> Vec<NamedQuantity> {
    let mut v = Vec::new();
    if let (Some(a), Some(b)) = (t0, t2) {
        let (c0, s0) = rcagd::ph::spatial_hermite::rotation_from_half_tangent(a);
        let (c2, s2) = rcagd::ph::spatial_hermite::rotation_from_half_tangent(b);
        v.push(NamedQuantity::new("rotation0", "(cos φ0, sin φ0) from τ0 = tan(φ0/2)", Quantity::rationals(&[c0, s0])));
        v.push(NamedQuantity::new("rotation2", "(cos φ2, sin φ2) from τ2 = tan(φ2/2)", Quantity::rationals(&[c2, s2])));
    }
    v.push(NamedQuantity::new(
        "quaternion_coefficients",
        "Bernstein coefficients [w, x, y, z] of the preimage A(t), r' = A i A*",
        Quantity::Vector(curve.coefficients().iter().map(|q| Quantity::rationals(&[q.w.clone(), q.x.clone(), q.y.clone(), q.z.clone()])).collect()),
    ));
    v.push(NamedQuantity::new("arc_length", "∫₀¹ σ dt", Quantity::Rational(curve.arc_length())));
    let member = SpatialHermiteQuintic {
        data: data.clone(),
        rotation0: (Rational::from(1), Rational::from(0)),
        rotation2: (Rational::from(1), Rational::from(0)),
        curve: curve.clone(),
        bending_energy: 0.0,
    };
    v.push(NamedQuantity::new("residual", "max deviation of the end conditions (0 when exact)", Quantity::Approx(member.residual())));
    if let Ok(e) = curve.to_poly_curve().bending_energy() {
        v.push(NamedQuantity::new("bending_energy", "∫κ² ds", Quantity::Approx(e)));
    }
    v
}
