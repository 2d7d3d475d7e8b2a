//! Ops of the `sphere_family` topic: envelopes of two-parameter sphere families from a line
//! net and two support functions (`rcagd::envelope`; D. Gruber, "Rationale
//! Parametrisierungen von Kugelhüllflächen", 2008, §3.2–3.5). The envelope `Ψ(s, t)` is
//! rational over the whole absolute quadric `Ω(s, t)`; both sheets (the two contact points
//! with each sphere) are parameter regions of the same map. `sphere_family_recognize` takes
//! the family itself (centre and radius as rational functions of two parameters), recovers
//! its line net and support functions (`rcagd::envelope::SphereFamily::recognize`) and
//! builds the same envelope, or names why the family has none of this kind.

use super::arith::{self, OpScalar};
use super::{poly_io, OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::Geometry;
use crate::model::Object;
use rcagd_geom::BezierPatch;
use crate::value::ParamKind;
use rcagd::envelope::{Recognition, Reductions, SphereFamily, SphereFamilyEnvelope};
use rcagd::lines::NetKind;
use rcagd::Certified;
use rcagd::lines::SqrtScalar;
use rcagd_algebra::{Certificate, QuadExt, Rational, Scalar};

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[
    SPHERE_FAMILY_ENVELOPE,
    SPHERE_FAMILY_RECOGNIZE,
    SPHERE_FAMILY_CYCLOGRAPHIC,
    CYCLOGRAPHIC_PLANE_IMAGE,
];

const SPHERE_FAMILY_ENVELOPE: OpSpec = OpSpec {
    name: "sphere_family_envelope",
    summary: "the rational envelope Ψ(s, t) of the two-parameter sphere family of a line net (hyperbolic, elliptic or parabolic) and two support functions (Gruber §3.2: linear system (3.7), reparametrization (3.16) by the net's fibration, isotropic projection)",
    params: &[
        NET,
        POINTS,
        A,
        A_IMAGINARY,
        B,
        A_DENOMINATOR,
        B_DENOMINATOR,
        DOMAIN,
        CENTRES,
        SPHERES,
        OTHER_SHEET,
        COMBINE,
    ],
    example: r#"[[object]]
name = "sphere_family_polar_axes"
op = "sphere_family_envelope"
# Gruber §3.3.4 (polar axes): c(u) = (1, 0, 0, −u), d(v) = (0, 1, v, 0), a = u², b = v²;
# Φ = (−u², −v², 2v, 2u), an envelope of degree 6
net = "hyperbolic"
points = [[1, 0, 0, 0], [0, 0, 0, -1], [0, 1, 0, 0], [0, 0, 1, 0]]
a = [[0], [0], [1]]
b = [[0, 0, 1]]
domain = ["1/4", 1, "1/4", 1]
"#,
    build: build_envelope::<Rational>,
};

/// The recipe's net and support functions, as data in `T`.
struct NetData<T> {
    kind: NetKind,
    points: Vec<Vec<T>>,
    a: Vec<Vec<T>>,
    a_im: Option<Vec<Vec<T>>>,
    b: Option<Vec<Vec<T>>>,
    a_den: Option<Vec<Vec<T>>>,
    b_den: Option<Vec<Vec<T>>>,
}

impl<T: OpScalar> NetData<T> {
    fn read(args: &OpArgs) -> Result<Self, OpError> {
        let kind = match args.string("net")? {
            "elliptic" => NetKind::Elliptic,
            "parabolic" => NetKind::Parabolic,
            _ => NetKind::Hyperbolic,
        };
        let grid = |g: Vec<Vec<Rational>>| -> Vec<Vec<T>> {
            g.iter().map(|r| arith::all_of::<T>(r)).collect()
        };
        let data = NetData {
            kind,
            points: grid(args.points("points")?),
            a: grid(
                args.opt_grid("a")?
                    .ok_or_else(|| OpError::param("a", "the support function a is required"))?,
            ),
            a_im: args.opt_grid("a_imaginary")?.map(grid),
            b: args.opt_grid("b")?.map(grid),
            a_den: args.opt_grid("a_denominator")?.map(grid),
            b_den: args.opt_grid("b_denominator")?.map(grid),
        };
        if data.b.is_none() && data.b_den.is_some() {
            return Err(OpError::param(
                "b_denominator",
                "b_denominator without b: an elliptic net's default b = ā(v) takes a's denominator",
            ));
        }
        Ok(data)
    }

    fn envelope(
        &self,
        replay: Option<&Reductions<T>>,
    ) -> Result<SphereFamilyEnvelope<T>, OpError> {
        SphereFamilyEnvelope::<T>::from_data_along(
            self.kind,
            &self.points,
            &self.a,
            self.a_im.as_deref(),
            self.b.as_deref(),
            [self.a_den.as_deref(), self.b_den.as_deref()],
            replay,
        )
        .map_err(|e| OpError::param(e.input(), e.to_string()))
    }
}

/// The envelope of the recipe's net and support functions, built in `T`. An inexact
/// build replays the common factors the exact construction divides out (decided over Q on
/// the exact input, [`rcagd::envelope::Reductions`]); `other_sheet`: including the other
/// sheet's.
fn net_envelope<T: OpScalar>(
    args: &OpArgs,
    other_sheet: bool,
) -> Result<SphereFamilyEnvelope<T>, OpError> {
    let data = NetData::<T>::read(args)?;
    if T::EXACT {
        return data.envelope(None);
    }
    let exact = NetData::<Rational>::read(args)?.envelope(None)?;
    let exact = if other_sheet {
        exact.with_other_sheet_divisor()
    } else {
        exact
    };
    let replay = exact.reductions().map(|x| T::from_rational(x));
    data.envelope(Some(&replay))
}

const SPHERE_FAMILY_CYCLOGRAPHIC: OpSpec = OpSpec {
    name: "sphere_family_cyclographic",
    summary: "the cyclographic construction of the envelope (Gruber §3.1.2) at given spheres of a net's family: the ideal line of the tangent plane of Φ, its polar line h (the normal line), h ∩ Ω and the isotropic projections give the two contact points; drawn as the radii from the centre to both contact points",
    params: &[
        NET,
        POINTS,
        A,
        A_IMAGINARY,
        B,
        A_DENOMINATOR,
        B_DENOMINATOR,
        ParamSpec::required(
            "at",
            ParamKind::Points,
            "parameter points [s, t] of Ω(s, t) = (2s, 2t, 1 − s² − t², 1 + s² + t²): the spheres Φ(s, t) (rational contact points)",
        ),
    ],
    example: r#"[[object]]
name = "sphere_family_cyclographic_polar"
op = "sphere_family_cyclographic"
# Gruber §3.3.4 (polar axes): the radii to both contact points of three spheres
net = "hyperbolic"
points = [[1, 0, 0, 0], [0, 0, 0, -1], [0, 1, 0, 0], [0, 0, 1, 0]]
a = [[0], [0], [1]]
b = [[0, 0, 1]]
at = [["1/2", "1/2"], ["3/4", "1/3"], ["1/3", "3/4"]]
"#,
    build: build_cyclographic::<Rational>,
};

/// `sphere_family_cyclographic` in `T` (exact registry: `Rational`; float path:
/// double-double). An inexact build first runs the exact op (its decisions: the contact
/// points are rational, the other sheet's factors), then the construction, the other
/// sheet `Ψ₂` (along the exact reductions) and the certificates in `T`.
pub(crate) fn build_cyclographic<T>(args: &OpArgs) -> Result<Vec<Object>, OpError>
where
    T: OpScalar + SqrtScalar,
{
    // the exact build's contact points, in its order (the end of each radius): the float
    // path draws the two points of a sphere in the same order (which of the two roots of
    // h ∩ Ω comes first is a decision of the exact square root)
    let exact_order: Option<Vec<[f64; 3]>> = if T::EXACT {
        None
    } else {
        let objs = build_cyclographic::<Rational>(args)?;
        Some(match objs.first().map(|o| &o.geometry) {
            Some(Geometry::Curves(cs)) => cs
                .iter()
                .map(|c| {
                    let p = c.control_point(c.degree());
                    let w = Scalar::to_f64(&p[0]);
                    core::array::from_fn(|i| Scalar::to_f64(&p[i + 1]) / w)
                })
                .collect(),
            _ => Vec::new(),
        })
    };
    let env = net_envelope::<T>(args, true)?;
    let at = args.points("at")?;
    let mut curves = Vec::new();
    let mut certs = Vec::new();
    let psi2 = env.other_sheet_homogeneous();
    for (k, st) in at.iter().enumerate() {
        let [s, t] = <[T; 2]>::try_from(arith::all_of::<T>(st)).map_err(|_| {
            OpError::param("at", format!("a parameter point is [s, t], got {} numbers", st.len()))
        })?;
        let mut c = env
            .certified_contacts(&s, &t, &psi2)
            .map_err(|e| OpError::param("at", e.to_string()))?;
        if let Some([e0, e1]) = exact_order.as_ref().and_then(|v| v.get(2 * k..2 * k + 2)) {
            let d = |p: &[T; 3], q: &[f64; 3]| -> f64 {
                (0..3).map(|i| (p[i].to_f64() - q[i]).powi(2)).sum()
            };
            let [p0, p1] = &c.points;
            if d(p0, e1) + d(p1, e0) < d(p0, e0) + d(p1, e1) {
                // (the certificates "contact point 1/2 lies on its sphere" keep the
                // construction's numbering)
                c.points.swap(0, 1);
            }
        }
        let m = &c.sphere.0;
        for pt in &c.points {
            let hom = |p: &[T; 3]| -> Vec<T> {
                let mut h = vec![T::one()];
                h.extend(p.iter().cloned());
                h
            };
            curves.push(
                rcagd_geom::BezierCurve::from_homogeneous(vec![hom(m), hom(pt)])
                    .map_err(|e| OpError::new(e.to_string()))?,
            );
        }
        certs.extend(c.certificates);
    }
    Ok(vec![arith::object::<T>(args, arith::curves(curves)?, certs)])
}

/// `sphere_family_envelope`, in `T` (exact registry: `Rational`; float path:
/// [`rcagd_algebra::DoubleDouble`], whose digits cover the cancellations of elliptic nets,
/// other sheets and enveloped spheres that `f64` lost: docs/plans/float.md, "Session 18,
/// ddfloat").
pub(crate) fn build_envelope<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let env = net_envelope::<T>(args, args.bool("other_sheet")? || args.int("spheres")? > 0)?;
    let certs = env.certify();
    envelope_object(args, &env, certs)
}

/// The envelope's positive-weight patches on the `domain` rectangle, with `certs` and the
/// weight certificate.
fn envelope_object<T: OpScalar>(
    args: &OpArgs,
    env: &SphereFamilyEnvelope<T>,
    mut certs: Vec<Certificate>,
) -> Result<Vec<Object>, OpError> {
    let dom = args.opt_numbers("domain")?.unwrap_or_default();
    let [s0, s1, t0, t1] = <[T; 4]>::try_from(arith::all_of::<T>(&dom)).map_err(|_| {
        OpError::param(
            "domain",
            format!(
                "the domain has four numbers [s0, s1, t0, t1], got {}",
                dom.len()
            ),
        )
    })?;
    let (patches, weight_cert) = env
        .export_patches((s0.clone(), s1.clone()), (t0.clone(), t1.clone()))
        .map_err(|e| OpError::param("domain", e.to_string()))?;
    certs.push(weight_cert);
    let main = (patches, certs);
    let mut extra: Vec<Extra<T>> = Vec::new();
    let mut out = Vec::new();
    if args.bool("centres")? {
        let (pieces, cert) = env
            .centre_patches((s0.clone(), s1.clone()), (t0.clone(), t1.clone()))
            .map_err(|e| OpError::param("centres", e.to_string()))?;
        let mut o = arith::object::<T>(
            args,
            Geometry::Patches(arith::exact_patches(pieces)?),
            vec![cert],
        );
        o.name = format!("{}_centres", args.name());
        out.push(o);
    }
    if args.bool("other_sheet")? {
        let (patches, certs) = env
            .other_sheet_patches((s0.clone(), s1.clone()), (t0.clone(), t1.clone()))
            .map_err(|e| OpError::param("other_sheet", format!("the other sheet: {e}")))?;
        extra.push(("other_sheet", patches, certs));
    }
    let n = args.int("spheres")?;
    if n > 0 {
        if n > MAX_SPHERES {
            return Err(OpError::param(
                "spheres",
                format!("at most {MAX_SPHERES} enveloped spheres, got {n}"),
            ));
        }
        let spheres = env
            .enveloped_spheres((s0, s1), (t0, t1), n as usize)
            .map_err(|e| OpError::param("spheres", e.to_string()))?;
        let mut patches = Vec::new();
        let mut certs = Vec::new();
        for sp in &spheres {
            certs.extend(env.enveloped_sphere_certificates(sp));
            patches.extend(sp.cover.patches().iter().cloned());
        }
        extra.push(("spheres", patches, certs));
    } else if n < 0 {
        return Err(OpError::param(
            "spheres",
            format!("the number of enveloped spheres is ≥ 0, got {n}"),
        ));
    }
    let (mut patches, mut certs) = main;
    if args.bool("combine")? {
        for (_, p, c) in extra.drain(..) {
            patches.extend(p);
            certs.extend(c);
        }
    }
    out.insert(
        0,
        arith::object::<T>(args, Geometry::Patches(arith::exact_patches(patches)?), certs),
    );
    for (suffix, p, c) in extra {
        let mut o = arith::object::<T>(args, Geometry::Patches(arith::exact_patches(p)?), c);
        o.name = format!("{}_{suffix}", args.name());
        out.push(o);
    }
    Ok(out)
}

/// An extra object of the envelope ops: name suffix, patches, certificates.
type Extra<T> = (&'static str, Vec<BezierPatch<T>>, Vec<Certificate>);

/// The most enveloped spheres one object draws.
const MAX_SPHERES: i64 = 16;

const NET: ParamSpec = ParamSpec::required(
    "net",
    ParamKind::Choice(&["hyperbolic", "elliptic", "parabolic"]),
    "the net type",
);

const POINTS: ParamSpec = ParamSpec::required(
    "points",
    ParamKind::Points,
    "four points of the ideal space [y1, y2, y3, y4]: c0, c1, d0, d1 (axes c(u) = c0 + u c1, d(v) = d0 + v d1; parabolic: d(u, v) = d0 + u d1 + v c1) or, elliptic, Re c0, Im c0, Re c1, Im c1",
);

const A: ParamSpec = ParamSpec::required(
    "a",
    ParamKind::Grid,
    "support function a of the planes e = D c: power coefficients a[i][j] of u^i v^j (a depends on u only)",
).degree();

const A_IMAGINARY: ParamSpec = ParamSpec::optional(
    "a_imaginary",
    ParamKind::Grid,
    "elliptic nets: the imaginary part of a (default 0)",
);

const A_DENOMINATOR: ParamSpec = ParamSpec::optional(
    "a_denominator",
    ParamKind::Grid,
    "a rational support function a = (a + i·a_imaginary)/a_denominator: power coefficients of u^i v^j of the real denominator (default 1)",
).degree();

const B_DENOMINATOR: ParamSpec = ParamSpec::optional(
    "b_denominator",
    ParamKind::Grid,
    "a rational support function b = b/b_denominator: power coefficients of u^i v^j (default 1; elliptic nets with the default b = ā(v) use a's denominator)",
).degree();

const B: ParamSpec = ParamSpec::optional(
    "b",
    ParamKind::Grid,
    "support function b of the planes f = D d: power coefficients b[i][j] of u^i v^j (hyperbolic: v only; parabolic: b_v = a_u; elliptic: default and required value ā(v))",
).degree();

/// The parameter rectangle of the sphere-family ops.
const DOMAIN: ParamSpec = ParamSpec::with_default(
    "domain",
    ParamKind::Numbers,
    "[\"1/4\", 1, \"1/4\", 1]",
    "parameter rectangle [s0, s1, t0, t1] of Ω(s, t) = (2s, 2t, 1 − s² − t², 1 + s² + t²); the envelope must have no pole on it",
);

const CENTRES: ParamSpec = ParamSpec::with_default(
    "centres",
    ParamKind::Bool,
    "false",
    "also output the centre surface of the enveloped spheres over the same rectangle, as the object NAME_centres",
);

const SPHERES: ParamSpec = ParamSpec::with_default(
    "spheres",
    ParamKind::Int,
    "0",
    "also output N ≤ 16 enveloped spheres (exact sixteen-patch sphere covers) at N points of the rectangle's diagonal, as the object NAME_spheres; certified: each cover lies on its sphere and both contact points Ψ(s, t), Ψ(s', t') (first and other sheet) lie on it",
);

const COMBINE: ParamSpec = ParamSpec::with_default(
    "combine",
    ParamKind::Bool,
    "false",
    "put the other sheet and the enveloped spheres into the envelope's own object (one picture, one STEP body list) instead of NAME_other_sheet and NAME_spheres",
);

const OTHER_SHEET: ParamSpec = ParamSpec::with_default(
    "other_sheet",
    ParamKind::Bool,
    "false",
    "also output the other sheet over the same rectangle, as the object NAME_other_sheet: the second contact points Ψ₂(s, t) of the same spheres Φ(s, t) (the second intersection of the net line with Ω), certified like Ψ",
);

const SPHERE_FAMILY_RECOGNIZE: OpSpec = OpSpec {
    name: "sphere_family_recognize",
    summary: "a given rational two-parameter sphere family (centre, radius) recognized as the family of a line net (Gruber §3.2–3.5): the normal lines E(Φ_u ∧ Φ_v) span a linear congruence, whose axes, the support functions and the rational envelope Ψ(s, t) are recovered — or a named error (not two-parametric, no real envelope, not a fibration, axes over Q(√d), non-polynomial support)",
    params: &[
        ParamSpec::required(
            "centre",
            ParamKind::Net,
            "numerators of the centres: centre[i][j] = [x, y, z] is the coefficient of u^i v^j",
        ),
        ParamSpec::required(
            "radius",
            ParamKind::Grid,
            "numerator of the signed radius: radius[i][j] is the coefficient of u^i v^j",
        ),
        ParamSpec::with_default(
            "denominator",
            ParamKind::Grid,
            "[[1]]",
            "common denominator W(u, v) of centre and radius (power coefficients of u^i v^j)",
        ).degree(),
        DOMAIN,
        CENTRES,
        SPHERES,
        OTHER_SHEET,
        COMBINE,
        ParamSpec::optional(
            "at",
            ParamKind::Points,
            "family parameter points [[u, v], …]: also run the cyclographic construction (Gruber §3.1.2) at the spheres Φ(u, v) of the given family (recognition then construction, `SphereFamily::cyclographic_at`) and output the object NAME_contacts: the radii from each centre to its two contact points, certified on S ∩ S_u ∩ S_v of the given family; the contact points must be rational there (the normal line meets Ω in rational points), else a located error names them over Q(√d)",
        ),
    ],
    example: r#"[[object]]
name = "sphere_family_recognized_331"
op = "sphere_family_recognize"
# Gruber (3.15): centres (−u², 2u, 2v), radii 4u + v² — recognized as the hyperbolic net
# with two passant axes (§3.3.1)
centre = [[[0, 0, 0], [0, 0, 2]], [[0, 2, 0], [0, 0, 0]], [[-1, 0, 0], [0, 0, 0]]]
radius = [[0, 0, 1], [4, 0, 0]]
domain = [1, 2, "1/4", 1]
"#,
    build: build_recognized::<Rational>,
};


/// `sphere_family_recognize` in `T`: the recognition exact, the envelope built in `T`
/// along the exact build's reductions ([`Recognition::in_scalar`]).
pub(crate) fn build_recognized<T>(args: &OpArgs) -> Result<Vec<Object>, OpError>
where
    T: OpScalar + SqrtScalar,
{
    let centre = args.net("centre")?;
    let mut xyz: [Vec<Vec<Rational>>; 3] = Default::default();
    for (i, row) in centre.iter().enumerate() {
        for (j, p) in row.iter().enumerate() {
            if p.len() != 3 {
                return Err(OpError::param(
                    "centre",
                    format!(
                        "centre[{i}][{j}] has {} coordinates, a centre coefficient has three [x, y, z]",
                        p.len()
                    ),
                ));
            }
            for (k, g) in xyz.iter_mut().enumerate() {
                if g.len() <= i {
                    g.resize(i + 1, Vec::new());
                }
                g[i].push(p[k].clone());
            }
        }
    }
    let radius = args
        .opt_grid("radius")?
        .ok_or_else(|| OpError::param("radius", "the radius is required"))?;
    let den = args
        .opt_grid("denominator")?
        .unwrap_or_else(|| vec![vec![Rational::from(1)]]);
    let fam = SphereFamily::new(
        [
            poly_io::grid_mpoly(&xyz[0])?,
            poly_io::grid_mpoly(&xyz[1])?,
            poly_io::grid_mpoly(&xyz[2])?,
        ],
        poly_io::grid_mpoly(&radius)?,
        poly_io::grid_mpoly(&den)?,
    )
    .map_err(|e| OpError::param("denominator", e.to_string()))?;
    // the recognition is a query of the exact input (ranks, the pencil's discriminant,
    // squares in Q, kernels): decided exactly for both arithmetics
    let rec = fam
        .recognize()
        .map_err(|e| OpError::param("centre", e.to_string()))?;
    // the `at` contacts: exactly (the exact op's object, and its decision that the contact
    // points are rational)
    let contacts = if args.get("at").is_some() {
        Some(family_contacts(args, &rec)?)
    } else {
        None
    };
    let (rec, contacts) = match arith::same::<_, Recognition<T>>(rec) {
        Ok(r) => (r, contacts),
        Err(exact) => {
            let other = args.bool("other_sheet")? || args.int("spheres")? > 0;
            let r = exact
                .in_scalar::<T>(other)
                .map_err(|e| OpError::param("centre", e.to_string()))?;
            let c = match contacts {
                Some(_) => Some(family_contacts_in(args, &r)?),
                None => None,
            };
            (r, c)
        }
    };
    let certs = rec.certify();
    let mut out = envelope_object(args, rec.envelope(), certs)?;
    out.extend(contacts);
    Ok(out)
}

/// The object `NAME_contacts` of `sphere_family_recognize` in `T` (the float path; the
/// exact op's [`family_contacts`] has decided that the contact points are rational): the
/// cyclographic construction at the spheres `Φ(u, v)` of the recognition in `T`
/// ([`Recognition::cyclographic_at`]), its certificates checked in `T`.
fn family_contacts_in<T>(args: &OpArgs, rec: &Recognition<T>) -> Result<Object, OpError>
where
    T: OpScalar + SqrtScalar,
{
    let mut curves = Vec::new();
    let mut certs = Vec::new();
    for uv in &args.points("at")? {
        let [u, v] = arith::array::<T, 2>(uv, "at", "a parameter point is [u, v]")?;
        let fc = rec
            .cyclographic_at(&u, &v)
            .map_err(|e| OpError::param("at", e.to_string()))?;
        certs.extend(fc.certify());
        let (m, _) = &fc.sphere;
        let mut hom_m = vec![T::one()];
        hom_m.extend(m.iter().cloned());
        for p in &fc.points {
            let mut h = vec![T::one()];
            for x in p {
                let q = Scalar::to_rational(x).ok_or_else(|| {
                    OpError::param("at", "the f64 construction produced a non-finite contact point: build it without --float")
                })?;
                h.push(T::from_rational(&q));
            }
            curves.push(
                rcagd_geom::BezierCurve::from_homogeneous(vec![hom_m.clone(), h])
                    .map_err(|e| OpError::param("at", e.to_string()))?,
            );
        }
    }
    let mut o = arith::object::<T>(
        args,
        Geometry::Curves(arith::exact_curves(curves)?),
        certs,
    );
    o.name = format!("{}_contacts", args.name());
    Ok(o)
}

/// The object `NAME_contacts` of `sphere_family_recognize`: the cyclographic construction
/// at the family's spheres `Φ(u, v)` for the parameter points `at`.
fn family_contacts(args: &OpArgs, rec: &rcagd::envelope::Recognition<Rational>) -> Result<Object, OpError> {
    let mut curves = Vec::new();
    let mut certs = Vec::new();
    for uv in &args.points("at")? {
        let [u, v] = <[Rational; 2]>::try_from(uv.clone()).map_err(|_| {
            OpError::param("at", format!("a parameter point is [u, v], got {} numbers", uv.len()))
        })?;
        let fc = rec.cyclographic_at(&u, &v).map_err(|e| OpError::param("at", e.to_string()))?;
        let pts = fc.rational_points().ok_or_else(|| {
            let show = |p: &[rcagd_algebra::QuadExt; 3]| {
                format!("({}, {}, {})", p[0], p[1], p[2])
            };
            OpError::param(
                "at",
                format!(
                    "the contact points of the sphere Φ({u}, {v}) are irrational: {} and {} (the normal line meets Ω over a quadratic field); choose a parameter point where they are rational",
                    show(&fc.points[0]),
                    show(&fc.points[1])
                ),
            )
        })?;
        certs.extend(fc.certify());
        let (m, _) = &fc.sphere;
        let hom = |p: &[Rational; 3]| -> Vec<Rational> {
            let mut h = vec![Rational::from(1)];
            h.extend(p.iter().cloned());
            h
        };
        for pt in &pts {
            curves.push(
                rcagd_geom::BezierCurve::from_homogeneous(vec![hom(m), hom(pt)])
                    .map_err(|e| OpError::param("at", e.to_string()))?,
            );
        }
    }
    let mut o = args.object(Geometry::Curves(curves), certs);
    o.name = format!("{}_contacts", args.name());
    Ok(o)
}

const CYCLOGRAPHIC_PLANE_IMAGE: OpSpec = OpSpec {
    name: "cyclographic_plane_image",
    summary: "the cyclographic image of a 2-plane a + u g + v h of R^{3,1} (Gruber §1.2.2): its type (horizontal, spacelike, lightlike, timelike) and the oriented planes touching all its cycles (two, one or none, over Q(√d)), certified exactly over the extension; drawn as the cycles (spheres) at the given parameter points, the image planes reported as values",
    params: &[
        ParamSpec::required("point", ParamKind::Point, "the point a = [x, y, z, r] of the 2-plane: the cycle with centre (x, y, z) and signed radius r"),
        ParamSpec::required("directions", ParamKind::Points, "the two directions g, h = [[x, y, z, r], [x, y, z, r]] spanning the 2-plane"),
        ParamSpec::with_default("cycles", ParamKind::Points, "[[0, 0], [1, 0], [0, 1]]", "parameter points [u, v] of the cycles a + u g + v h drawn as exact sphere covers (at most 8; a zero radius is an error)"),
    ],
    example: r#"[[object]]
name = "cyclographic_plane_image_spacelike"
op = "cyclographic_plane_image"
# cycles (u, v, 0) with radius 1 + u/2: a spacelike 2-plane, two image planes over Q(√3)
point = [0, 0, 0, 1]
directions = [[1, 0, 0, "1/2"], [0, 1, 0, 0]]
cycles = [[0, 0], [2, 0], [-1, 1]]
"#,
    build: build_plane_image::<Rational>,
};

/// `cyclographic_plane_image`, in `T`. The type of the 2-plane (lightlike: `1 − |n₀|² = 0`)
/// is an exact-only decision: an inexact build decides it on the exact input and refuses
/// the input if its own (tolerance) decision differs.
pub(crate) fn build_plane_image<T>(args: &OpArgs) -> Result<Vec<Object>, OpError>
where
    T: OpScalar + SqrtScalar,
    T::Ext: 'static,
{
    use rcagd_io::quantity::{NamedQuantity, Quantity};
    let four = |param: &'static str, p: &[Rational]| -> Result<[T; 4], OpError> {
        arith::array::<T, 4>(
            p,
            param,
            &format!(
                "a point of R^{{3,1}} has four coordinates [x, y, z, r], got {}",
                p.len()
            ),
        )
    };
    let a_q = args.point("point")?;
    let a = four("point", &a_q)?;
    let dirs = args.points("directions")?;
    let [g_q, h_q] = <[Vec<Rational>; 2]>::try_from(dirs.clone()).map_err(|_| {
        OpError::param(
            "directions",
            format!("a 2-plane has two directions g, h, got {}", dirs.len()),
        )
    })?;
    let (g, h) = (four("directions", &g_q)?, four("directions", &h_q)?);
    let img = rcagd::cyclographic::plane_image(&a, &g, &h)
        .map_err(|e| OpError::param("directions", e.to_string()))?;
    if !T::EXACT {
        let q4 = |v: &[Rational]| <[Rational; 4]>::try_from(v.to_vec()).ok();
        if let (Some(aq), Some(gq), Some(hq)) = (q4(&a_q), q4(&g_q), q4(&h_q)) {
            let exact = rcagd::cyclographic::plane_image(&aq, &gq, &hq)
                .map_err(|e| OpError::param("directions", e.to_string()))?;
            if exact.kind != img.kind {
                return Err(OpError::param(
                    "directions",
                    format!(
                        "the float path does not decide the 2-plane as the exact build does: it finds {:?} where the exact type is {:?} (1 − |n₀|² within rounding of 0): build it without --float",
                        img.kind, exact.kind
                    ),
                ));
            }
        }
    }
    let mut certs = img.certify();
    let cycles = args.points("cycles")?;
    if cycles.len() > 8 {
        return Err(OpError::param(
            "cycles",
            format!("at most 8 cycles, got {}", cycles.len()),
        ));
    }
    let mut patches: Vec<BezierPatch<T>> = Vec::new();
    for uv in &cycles {
        let [u, v] = <[Rational; 2]>::try_from(uv.clone()).map_err(|_| {
            OpError::param(
                "cycles",
                format!("a parameter point is [u, v], got {} numbers", uv.len()),
            )
        })?;
        let (ut, vt) = (arith::of::<T>(&u), arith::of::<T>(&v));
        let c: [T; 4] = core::array::from_fn(|i| {
            a[i].clone() + ut.clone() * g[i].clone() + vt.clone() * h[i].clone()
        });
        let r = c[3].abs();
        let cover = rcagd::quadric::sphere_cover(
            [c[0].clone(), c[1].clone(), c[2].clone()],
            [r.clone(), r.clone(), r],
        )
        .map_err(|e| OpError::param("cycles", format!("the cycle at ({u}, {v}): {e}")))?;
        certs.extend(cover.certify());
        patches.extend(cover.into_patches());
    }
    let kind = match img.kind {
        rcagd::cyclographic::PlaneImageKind::Horizontal => "horizontal",
        rcagd::cyclographic::PlaneImageKind::Spacelike => "spacelike",
        rcagd::cyclographic::PlaneImageKind::Lightlike => "lightlike",
        rcagd::cyclographic::PlaneImageKind::Timelike => "timelike",
    };
    // an exact coordinate lives in Q(√d), an inexact one is a number
    let ext = |x: &T::Ext| match arith::same_ref::<T::Ext, QuadExt>(x) {
        Some(q) => Quantity::Quadratic(q.clone()),
        None => Quantity::Approx(x.to_f64()),
    };
    let values = vec![
        NamedQuantity::new(
            "kind",
            "the type of the 2-plane and of its image (Gruber §1.2.2)",
            Quantity::Text(kind.into()),
        ),
        NamedQuantity::new(
            "planes",
            "the image planes [e0, n1, n2, n3]: e0 + n·x = 0, |n| = 1, touching every cycle (over Q(√d))",
            Quantity::Vector(
                img.planes
                    .iter()
                    .map(|p| {
                        let mut v = vec![ext(&p.offset)];
                        v.extend(p.normal.iter().map(ext));
                        Quantity::Vector(v)
                    })
                    .collect(),
            ),
        ),
    ];
    let mut o = arith::object::<T>(
        args,
        Geometry::Patches(arith::exact_patches(patches)?),
        certs,
    );
    o.values.extend(values);
    Ok(vec![o])
}
