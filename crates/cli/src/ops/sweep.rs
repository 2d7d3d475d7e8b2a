//! Ops of the `sweep` topic: rational rotation-minimizing frames on PH curves and exact
//! twist-free sweeps of rational profiles along them (`rcagd::ph::rrmf`,
//! `rcagd::ph::sweep`; docs/math/rrmf.md).
//!
//! The curve is given either by its quaternion preimage (`quaternions`, any degree; the
//! op decides exactly whether it carries a rational RMF) or, for a quintic, by `a0`, `a1`
//! and the free real `x` of the RRMF quintic generator (`A_2` solves
//! `A_0 i A_2* + A_2 i A_0* = 2 A_1 i A_1*`).

use super::arith::{self, of, OpScalar};
use super::{OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use rcagd::ph::rrmf::{is_rrmf_quintic_class1, rrmf_quintic_class1, RationalRmf};
use rcagd::ph::rrmf_hermite::RrmfHermiteData;
use rcagd_io::quantity::{NamedQuantity, Quantity};
use rcagd::ph::sweep::{profile_joints, sweep_profile};
use rcagd::ph::PhCurve;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Certificate, Rational, Scalar};
use rcagd_geom::BezierCurve;

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[PH_RRMF, SWEEP_RRMF];

type Q = Rational;

const CURVE_PARAMS: [ParamSpec; 5] = [
    ParamSpec::optional(
        "quaternions",
        ParamKind::Points,
        "Bernstein coefficients A_0..A_m of the preimage A(t), each [u, v, p, q] = u + v i + p j + q k; the op decides exactly whether the curve has a rational RMF",
    ).degree(),
    ParamSpec::optional(
        "a0",
        ParamKind::Point,
        "instead of `quaternions`: A_0 = [u, v, p, q] of an RRMF quintic (A_0 ≠ 0)",
    ),
    ParamSpec::optional(
        "a1",
        ParamKind::Point,
        "with `a0`: A_1 = [u, v, p, q]; A_2 = A_0 X solves A_0 i A_2* + A_2 i A_0* = 2 A_1 i A_1*",
    ),
    ParamSpec::with_default(
        "x",
        ParamKind::Number,
        "0",
        "with `a0`, `a1`: the free real part x (the i-component of X = A_0⁻¹A_2)",
    ),
    ParamSpec::with_default("start", ParamKind::Point3, "[0, 0, 0]", "the start point r(0)"),
];

const PH_RRMF: OpSpec = OpSpec {
    name: "ph_rrmf",
    summary: "a PH curve with its exact rational rotation-minimizing frame (f1, f2) = (Ã j Ã*, Ã k Ã*)/(σ|w|²), Ã = A w: decided exactly (Rothstein–Trager on the ERF twist), or an RRMF quintic from the quintic condition; frame vectors as `<name>_frame`",
    params: &[
        CURVE_PARAMS[0],
        CURVE_PARAMS[1],
        CURVE_PARAMS[2],
        CURVE_PARAMS[3],
        CURVE_PARAMS[4],
        ParamSpec::optional(
            "hermite",
            ParamKind::Points,
            "instead of a preimage: RRMF Hermite data [p_i, t_i, u_i, p_f, t_f, u_f] (end points, tangents, first frame vectors ⟂ tangents); the interpolating RRMF quintic is solved in f64 and made exact (residuals reported)",
        ).degree(),
        ParamSpec::with_default(
            "samples",
            ParamKind::Int,
            "9",
            "number of parameters t = k/(samples−1) at which the frame (t, f1, f2) is drawn, 2 to 200",
        ).samples(),
        ParamSpec::with_default(
            "frame_length",
            ParamKind::Number,
            "\"1/2\"",
            "length of the drawn frame vectors",
        ),
    ],
    example: r#"[[object]]
name = "rrmf_quintic"
op = "ph_rrmf"
a0 = [1, 0, 1, 0]
a1 = [0, 1, 0, 1]
x = 1
samples = 7
"#,
    build: build_ph_rrmf::<Rational>,
};

const SWEEP_RRMF: OpSpec = OpSpec {
    name: "sweep_rrmf",
    summary: "an exact twist-free sweep S(t, u) = r(t) + x(u) f1(t) + y(u) f2(t) of rational plane profile pieces along an RRMF curve by its rational RMF: rational tensor-product patches with positive weights",
    params: &[
        CURVE_PARAMS[0],
        CURVE_PARAMS[1],
        CURVE_PARAMS[2],
        CURVE_PARAMS[3],
        CURVE_PARAMS[4],
        ParamSpec::required(
            "profile",
            ParamKind::Net,
            "profile pieces, each a list of control points [x, y] of a rational Bézier curve in the normal plane (x along f1, y along f2); consecutive pieces must meet (certified), and a profile whose last piece ends where the first starts is certified closed",
        ).degree(),
        ParamSpec::optional(
            "weights",
            ParamKind::Grid,
            "weights of the profile control points (one row per piece, all > 0); default all 1",
        ).degree(),
    ],
    example: r#"[[object]]
name = "rrmf_sweep"
op = "sweep_rrmf"
a0 = [2, 0, 1, 0]
a1 = [1, 2, 0, -1]
x = 0
profile = [[[1, 0], [1, "1/2"], [0, "1/2"]], [[0, "1/2"], [-1, "1/2"], [-1, 0]]]
weights = [[1, 1, 2], [2, 1, 1]]
"#,
    build: build_sweep_rrmf::<Rational>,
};

fn quat<T: Scalar>(
    args: &OpArgs,
    p: Vec<Q>,
    param: &'static str,
) -> Result<Quaternion<T>, OpError> {
    match <[Q; 4]>::try_from(p) {
        Ok([w, x, y, z]) => Ok(Quaternion::new(of(&w), of(&x), of(&y), of(&z))),
        Err(p) => Err(OpError::param(
            param,
            format!(
                "`{param}` of `{}` needs quaternions [u, v, p, q], got {} coordinates",
                args.name(),
                p.len()
            ),
        )),
    }
}

/// The curve of the shared parameters in `T` and whether it came from the quintic
/// generator.
fn curve<T: Scalar>(args: &OpArgs) -> Result<(PhCurve<T>, bool), OpError> {
    let start: [T; 3] = arith::point(args, "start", "internal error: `start` is not a 3D point")?;
    match (
        args.get("quaternions").is_some(),
        args.get("a0").is_some() || args.get("a1").is_some(),
    ) {
        (true, false) => {
            let qs = args
                .points("quaternions")?
                .into_iter()
                .map(|p| quat(args, p, "quaternions"))
                .collect::<Result<Vec<_>, _>>()?;
            Ok((PhCurve::new(qs, start)?, false))
        }
        (false, true) => {
            let (Some(a0), Some(a1)) = (args.opt_point("a0")?, args.opt_point("a1")?) else {
                return Err(OpError::new("the RRMF quintic generator needs both `a0` and `a1`"));
            };
            let a0 = quat(args, a0, "a0")?;
            let a1 = quat(args, a1, "a1")?;
            let c = rrmf_quintic_class1(a0, a1, arith::number(args, "x")?, start)
                .map_err(|e| OpError::param("a0", e.to_string()))?;
            Ok((c, true))
        }
        (true, true) => Err(OpError::param(
            "quaternions",
            "give either `quaternions` or `a0` and `a1`, not both",
        )),
        (false, false) => Err(OpError::new(
            "an RRMF curve needs `quaternions` or `a0` and `a1`",
        )),
    }
}

/// The certificate of the quintic RRMF condition (exact for exact `T`, to `1e-12`
/// relative in `f64`).
fn quintic_cert<T: Scalar>(c: &PhCurve<T>) -> Result<Certificate, OpError> {
    Ok(Certificate::decide(
        "A_0 i A_2* + A_2 i A_0* ≡ 2 A_1 i A_1* (the quintic RRMF condition, docs/math/rrmf.md)",
        is_rrmf_quintic_class1(c)?,
        T::EXACT,
        || "non-zero residual vector".into(),
    ))
}

fn rmf_and_certs(args: &OpArgs) -> Result<(RationalRmf<Q>, Vec<Certificate>), OpError> {
    let (c, generated) = curve::<Q>(args)?;
    let rmf = RationalRmf::new(&c)?;
    let mut certs = rmf.certify();
    if generated {
        certs.push(quintic_cert(&c)?);
    }
    Ok((rmf, certs))
}

/// The curve, its RMF, certificates and values in `T`. The exact-only decisions of the
/// frame (the rotation polynomial `w`: Rothstein–Trager residues over Q(i); the common
/// factor `g` cancelled over Q) are taken on the exact input and replayed in `f64`
/// ([`RationalRmf::along`]); the curve itself is built in `T` from the same parameters
/// (the `hermite` interpolant: the exact op's rounded preimage, converted).
fn solved<T: OpScalar>(args: &OpArgs) -> Result<Solved<T>, OpError> {
    let hermite_data = args.get("hermite").is_some();
    let (exact, certs, values) = if hermite_data {
        hermite(args)?
    } else {
        let (rmf, certs) = rmf_and_certs(args)?;
        (rmf, certs, Vec::new())
    };
    let exact = match arith::same::<RationalRmf<Q>, RationalRmf<T>>(exact) {
        Ok(rmf) => return Ok((rmf, certs, values)),
        Err(exact) => exact,
    };
    let (c, generated) = if hermite_data {
        let e = &exact.curve;
        let qs = e
            .coefficients()
            .iter()
            .map(|a| Quaternion::new(of(&a.w), of(&a.x), of(&a.y), of(&a.z)))
            .collect();
        let s = e.start();
        (PhCurve::new(qs, [of(&s[0]), of(&s[1]), of(&s[2])])?, true)
    } else {
        curve::<T>(args)?
    };
    let rmf = RationalRmf::along(&c, &exact)?;
    let mut certs = rmf.certify();
    if generated {
        certs.push(quintic_cert(&c)?);
    }
    Ok((rmf, certs, values))
}


/// A curve with its RMF, certificates and reported values.
type Solved<T = Q> = (RationalRmf<T>, Vec<Certificate>, Vec<NamedQuantity>);

/// The interpolant of the `hermite` data, its certificates and values.
fn hermite(
    args: &OpArgs,
) -> Result<Solved, OpError> {
    if args.get("quaternions").is_some() || args.get("a0").is_some() || args.get("a1").is_some() {
        return Err(OpError::param(
            "hermite",
            "give either `hermite` or a preimage (`quaternions`, `a0`/`a1`), not both",
        ));
    }
    let pts = args.points("hermite")?;
    let v: Vec<[f64; 3]> = pts
        .iter()
        .map(|p| match p.as_slice() {
            [x, y, z] => Ok([x.to_f64().value(), y.to_f64().value(), z.to_f64().value()]),
            _ => Err(OpError::param("hermite", "Hermite data are 3D points and vectors")),
        })
        .collect::<Result<_, _>>()?;
    let [p_i, t_i, u_i, p_f, t_f, u_f] = <[[f64; 3]; 6]>::try_from(v).map_err(|v| {
        OpError::param(
            "hermite",
            format!(
                "`hermite` needs 6 entries [p_i, t_i, u_i, p_f, t_f, u_f], got {}",
                v.len()
            ),
        )
    })?;
    let h = RrmfHermiteData { p_i, t_i, u_i, p_f, t_f, u_f }
        .solve()
        .map_err(|e| OpError::param("hermite", e.to_string()))?;
    let mut certs = h.rmf.certify();
    certs.push(quintic_cert(&h.rmf.curve)?);
    let values = vec![
        NamedQuantity::new(
            "point_residual",
            "max |r(0) − p_i|, |r(1) − p_f| of the exact interpolant (f64)",
            Quantity::Approx(h.point_residual),
        ),
        NamedQuantity::new(
            "tangent_residual",
            "max |r'/|r'| − t̂| at both ends (f64)",
            Quantity::Approx(h.tangent_residual),
        ),
        NamedQuantity::new(
            "frame_residual",
            "max |cos γ f1 + sin γ f2 − û| at both ends (f64)",
            Quantity::Approx(h.frame_residual),
        ),
        NamedQuantity::new(
            "gamma",
            "constant angle γ turning the exact RMF (f1, f2) into the frame through u_i (radians, f64)",
            Quantity::Approx(h.gamma),
        ),
    ];
    Ok((h.rmf, certs, values))
}

fn segment<T: Scalar>(a: &[T; 3], b: &[T; 3]) -> Result<BezierCurve<T>, OpError> {
    Ok(BezierCurve::from_points(&[a.to_vec(), b.to_vec()])?)
}

pub(crate) fn build_ph_rrmf<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (rmf, certs, mut values) = solved::<T>(args)?;
    values.push(NamedQuantity::new(
        "rotation_re",
        "a(t) of the rotation polynomial w = a + b i (Ã = A w; the RMF is the ERF turned by 2 arg w)",
        Quantity::poly_t(super::poly_io::poly_exact(&rmf.rotation.0)?),
    ));
    values.push(NamedQuantity::new(
        "rotation_im",
        "b(t) of w = a + b i",
        Quantity::poly_t(super::poly_io::poly_exact(&rmf.rotation.1)?),
    ));
    values.push(NamedQuantity::new(
        "frame_denominator",
        "the common denominator d(t) of f1 = F1/d, f2 = F2/d",
        Quantity::poly_t(super::poly_io::poly_exact(&rmf.den)?),
    ));
    let bez = rmf.curve.to_bezier()?;
    let samples = args.int("samples")?;
    if !(2..=200).contains(&samples) {
        return Err(OpError::param(
            "samples",
            format!("samples must be in 2..=200, got {samples}"),
        ));
    }
    let len: T = arith::number(args, "frame_length")?;
    let mut segs = vec![bez.clone()];
    for k in 0..samples {
        let t = T::from_ratio(k, samples - 1);
        let Some(frame) = rmf.eval(&t) else { continue };
        let p = rmf.curve.eval(&t);
        for v in &frame {
            let tip = [
                p[0].clone() + v[0].clone() * len.clone(),
                p[1].clone() + v[1].clone() * len.clone(),
                p[2].clone() + v[2].clone() * len.clone(),
            ];
            segs.push(segment(&p, &tip)?);
        }
    }
    let segs = Geometry::Curves(arith::exact_curves(segs)?);
    let mut frame_obj = arith::object::<T>(args, segs, rmf.certify());
    frame_obj.name = format!("{}_frame", args.name());
    let main = arith::object_with::<T>(args, Geometry::Curve(T::exact_curve(bez)?), certs, values);
    Ok(vec![main, frame_obj])
}

pub(crate) fn build_sweep_rrmf<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    if args.get("hermite").is_some() {
        return Err(OpError::param("hermite", "`sweep_rrmf` takes no `hermite` data"));
    }
    let (rmf, mut certs, _) = solved::<T>(args)?;
    let net = args.net("profile")?;
    let weights = args.opt_grid("weights")?;
    if let Some(w) = &weights {
        if w.len() != net.len() || w.iter().zip(&net).any(|(a, b)| a.len() != b.len()) {
            return Err(OpError::param(
                "weights",
                "`weights` must have one row per profile piece and one weight per control point",
            ));
        }
    }
    let mut patches = Vec::new();
    let mut pieces = Vec::with_capacity(net.len());
    for (k, piece) in net.iter().enumerate() {
        let pts = piece
            .iter()
            .map(|p| arith::array::<T, 2>(p, "profile", "profile control points are [x, y]"))
            .collect::<Result<Vec<_>, _>>()?;
        let ws: Vec<T> = match &weights {
            Some(w) => arith::all_of(&w[k]),
            None => vec![T::one(); pts.len()],
        };
        let s = sweep_profile(&rmf, &pts, &ws)
            .map_err(|e| OpError::param("profile", format!("profile piece {k}: {e}")))?;
        // the frame's certificates are already in `certs`; add the sweep's own
        let own = s.certify().into_iter().skip(rmf.certify().len());
        for mut c in own {
            c.property = format!("piece {k}: {}", c.property);
            certs.push(c);
        }
        patches.extend(s.patches());
        pieces.push((pts, ws));
    }
    let joints = profile_joints(&pieces);
    // pieces that do not join are one profile given wrongly (an input error), not a
    // construction whose certificate fails
    if let Some(gap) = joints.iter().find(|c| !c.holds) {
        return Err(OpError::param(
            "profile",
            format!(
                "{}: the pieces of one profile must join end to start (sweep separate profiles as separate objects)",
                gap.residual.as_deref().unwrap_or(&gap.property)
            ),
        ));
    }
    certs.extend(joints);
    Ok(vec![arith::object::<T>(
        args,
        Geometry::Patches(arith::exact_patches(patches)?),
        certs,
    )])
}
