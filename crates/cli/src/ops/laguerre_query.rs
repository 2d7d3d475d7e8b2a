//! Ops of the `laguerre_query` topic: questions about the models of Laguerre and Möbius
//! geometry answered exactly as named values (library `rcagd::laguerre::query`):
//!
//! * `laguerre_models`: a cycle or an oriented plane, given in any model, in every model;
//! * `laguerre_isotropic_quadric`: the isotropic-model function `y₃ = F(y₁, y₂)` of a
//!   quadric given implicitly (rational for paraboloids, else the quadratic it solves);
//! * `laguerre_cycles`: the images of cycles under a Laguerre map and its fixed cycles;
//! * `laguerre_pe_sphere`: the cyclographic image of a pe sphere `π ∩ Γ(a)` of `R^{3,1}`.

use super::quadric::{exportable_patch, target, COEFFICIENTS, MATRIX, QUADRIC, RATIONAL_POINT};
use super::poly_io::{self, MPolyQ};
use super::{OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use num_traits::{One, Signed, Zero};
use rcagd::laguerre::query::{
    cycle_from_blaschke, cycle_models, cycles_from_mobius, isotropic_quadric, laguerre_cycles,
    plane_models,
};
use rcagd::laguerre::{Cycle, IsotropicSphere, LaguerreMap, OrientedPlane};
use rcagd::quadric::patch_image;
use rcagd::Certified;
use rcagd_algebra::{Certificate, Rational};
use rcagd_geom::BezierPatch;
use rcagd_io::quantity::{NamedQuantity, Quantity};

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[LAGUERRE_MODELS, LAGUERRE_ISOTROPIC_QUADRIC, LAGUERRE_CYCLES, LAGUERRE_PE_SPHERE];

type Q = Rational;

const MODEL_INPUTS: [&str; 7] = [
    "cycle",
    "plane",
    "isotropic_point",
    "isotropic_sphere",
    "mobius_point",
    "blaschke_point",
    "blaschke_hyperplane",
];

const LAGUERRE_MODELS: OpSpec = OpSpec {
    name: "laguerre_models",
    summary: "a cycle (oriented sphere, point for r = 0) or an oriented plane, given in one model, in every model of Laguerre and Möbius geometry (Peternell, Rational Parametrizations for Envelopes of Quadric Families, §2.4, §3.1–§3.5): cyclographic point (m, r) (3.6), Blaschke hyperplane (r, m, 1) / Blaschke point (1, n, e0) (3.10), isotropic sphere (3.12) / isotropic point Λ(e) (3.11), dual isotropic plane (3.16), Möbius point (2.13); certified round trips and incidences; the object is the sphere (16 patches), for a point cycle its isotropic sphere over [−1, 1]², for a plane a square of it",
    params: &[
        ParamSpec::optional("cycle", ParamKind::Point, "[m1, m2, m3, r]: a cycle, i.e. the point of the cyclographic model"),
        ParamSpec::optional("plane", ParamKind::Point, "[e0, n1, n2, n3] with |n| = 1: the oriented plane e0 + n·x = 0"),
        ParamSpec::optional("isotropic_point", ParamKind::Point3, "[y1, y2, y3]: the oriented plane Λ⁻¹(y) (3.13)"),
        ParamSpec::optional("isotropic_sphere", ParamKind::Point, "[α, β1, β2, γ] of y3 = α(y1² + y2²) + β1 y1 + β2 y2 + γ: a cycle"),
        ParamSpec::optional("mobius_point", ParamKind::Point, "[p0, p1, p2, p3, p4] of the Möbius quadric model: the sphere μ(p) (2.13), both orientations, when r² is a rational square"),
        ParamSpec::optional("blaschke_point", ParamKind::Point, "[x0, x1, x2, x3, x4] on x1² + x2² + x3² = x0²: an oriented plane"),
        ParamSpec::optional("blaschke_hyperplane", ParamKind::Point, "[h0, …, h4] ∥ (r, m1, m2, m3, 1): a cycle"),
    ],
    example: r#"[[object]]
name = "cycle_models"
op = "laguerre_models"
cycle = [1, 2, 3, 4]
"#,
    build: build_models,
};

const LAGUERRE_ISOTROPIC_QUADRIC: OpSpec = OpSpec {
    name: "laguerre_isotropic_quadric",
    summary: "the isotropic-model function y3 = F(y1, y2) of a quadric given implicitly: its tangent planes Λ⁻¹(y) (Peternell (3.13)) satisfy A y3² + B y3 + C = 0 (uᵀ Q* u = 0, Q* = adj Q); F = −C/B is rational exactly when A = 0 (paraboloids), and then its PN surface lies on the quadric (Peternell Thm 4.3); otherwise the branches F± = (−B ± g)/(2A) are rational when B² − 4AC = g² (spheres: their two isotropic spheres); derivation in docs/math/laguerre-pn.md#isotropic-function-of-a-quadric; the object is a patch of the quadric",
    params: &[QUADRIC, COEFFICIENTS, MATRIX, RATIONAL_POINT],
    example: r#"[[object]]
name = "paraboloid_isotropic_function"
op = "laguerre_isotropic_quadric"
quadric = "elliptic_paraboloid"
coefficients = [1, 1]
"#,
    build: build_isotropic_quadric,
};

const LAGUERRE_CYCLES: OpSpec = OpSpec {
    name: "laguerre_cycles",
    summary: "the cycles of a Laguerre map x ↦ a + λ·A·x of the cyclographic model (A pe-orthogonal, Peternell (3.8)/(3.9)): the images of given cycles (certified: oriented contact with tangent planes is preserved) and the fixed cycles, the solutions of (I − λA)x = a; the object is the image spheres",
    params: &[
        ParamSpec::required("cycles", ParamKind::Points, "cycles [m1, m2, m3, r]"),
        ParamSpec::with_default("shift", ParamKind::Point, "[0, 0, 0, 0]", "a = [a1, a2, a3, a4]: translation (a1, a2, a3) and dilatation a4 (r ↦ r + a4)"),
        ParamSpec::with_default("scale", ParamKind::Number, "1", "λ ≠ 0"),
        ParamSpec::optional("matrix", ParamKind::Grid, "the 4×4 pe-orthogonal matrix A (AᵀEA = E, E = diag(1, 1, 1, −1)); default the identity"),
    ],
    example: r#"[[object]]
name = "boost_cycles"
op = "laguerre_cycles"
cycles = [[1, 2, 3, 4], [0, 0, 0, 1]]
shift = [0, 0, 0, "1/2"]
matrix = [["5/4", 0, 0, "3/4"], [0, 1, 0, 0], [0, 0, 1, 0], ["3/4", 0, 0, "5/4"]]
"#,
    build: build_cycles,
};

fn value(name: &str, doc: &str, v: Quantity) -> NamedQuantity {
    NamedQuantity::new(name, doc, v)
}

fn cycle_quantity(c: &Cycle<Q>) -> Quantity {
    Quantity::rationals(&[
        c.center[0].clone(),
        c.center[1].clone(),
        c.center[2].clone(),
        c.radius.clone(),
    ])
}

fn arr<const N: usize>(v: &[Q], param: &'static str, what: &str) -> Result<[Q; N], OpError> {
    <[Q; N]>::try_from(v.to_vec())
        .map_err(|_| OpError::param(param, format!("{what} needs {N} numbers, got {}", v.len())))
}

/// A square piece `[−1, 1]²` of the plane around the foot point `−e0 n`.
fn plane_square(e: &OrientedPlane<Q>) -> Result<BezierPatch<Q>, OpError> {
    Ok(e.square_patch()?)
}

/// The isotropic sphere `y3 = α S + β·y + γ` over `[−1, 1]²` as a polynomial patch of
/// bidegree (2, 2).
fn isotropic_patch(s: &IsotropicSphere<Q>) -> Result<BezierPatch<Q>, OpError> {
    Ok(s.square_patch()?)
}

fn cycle_geometry(c: &Cycle<Q>) -> Result<Geometry, OpError> {
    if c.radius.is_zero() {
        return Ok(Geometry::Patch(isotropic_patch(&c.isotropic_sphere())?));
    }
    let r = c.radius.abs();
    let cover = rcagd::quadric::sphere_cover(c.center.clone(), [r.clone(), r.clone(), r])?;
    Ok(Geometry::Patches(cover.into_patches()))
}

fn build_models(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let given: Vec<&'static str> = MODEL_INPUTS
        .into_iter()
        .filter(|p| args.get(p).is_some())
        .collect();
    let [input] = given.as_slice() else {
        return Err(OpError::new(format!(
            "give exactly one of `{}` (got {})",
            MODEL_INPUTS.join("`, `"),
            if given.is_empty() { "none".to_string() } else { given.join(", ") }
        )));
    };
    let input = *input;
    let v = args.point(input)?;
    let blame = |e: rcagd::laguerre::LaguerreError| OpError::param(input, e.to_string());
    enum Obj {
        Cycles(Vec<Cycle<Q>>),
        Plane(OrientedPlane<Q>),
    }
    let obj = match input {
        "cycle" => {
            let [m1, m2, m3, r] = arr::<4>(&v, input, "a cycle")?;
            Obj::Cycles(vec![Cycle::new([m1, m2, m3], r).map_err(blame)?])
        }
        "isotropic_sphere" => {
            let [alpha, b1, b2, gamma] = arr::<4>(&v, input, "an isotropic sphere")?;
            Obj::Cycles(vec![IsotropicSphere { alpha, beta: [b1, b2], gamma }.to_cycle()])
        }
        "mobius_point" => Obj::Cycles(cycles_from_mobius(&arr::<5>(&v, input, "a Möbius point")?).map_err(blame)?),
        "blaschke_hyperplane" => Obj::Cycles(vec![cycle_from_blaschke(&arr::<5>(&v, input, "a Blaschke hyperplane")?).map_err(blame)?]),
        "plane" => {
            let [e0, n1, n2, n3] = arr::<4>(&v, input, "an oriented plane")?;
            Obj::Plane(OrientedPlane::new(e0, [n1, n2, n3]).map_err(blame)?)
        }
        "isotropic_point" => Obj::Plane(OrientedPlane::from_isotropic(&arr::<3>(&v, input, "an isotropic point")?)),
        _ => Obj::Plane(OrientedPlane::from_blaschke(&arr::<5>(&v, input, "a Blaschke point")?).map_err(blame)?),
    };
    let mut out = Vec::new();
    match obj {
        Obj::Cycles(cs) => {
            let many = cs.len() > 1;
            for (k, c) in cs.iter().enumerate() {
                let m = cycle_models(c);
                let s = &m.isotropic_sphere;
                let values = vec![
                    value("cycle", "(m1, m2, m3, r): the cyclographic point (3.6)", cycle_quantity(c)),
                    value("blaschke_hyperplane", "(r, m1, m2, m3, 1): r x0 + m·(x1, x2, x3) + x4 = 0", Quantity::rationals(&m.blaschke_hyperplane)),
                    value("isotropic_sphere", "(α, β1, β2, γ) of y3 = α(y1² + y2²) + β1 y1 + β2 y2 + γ (3.12)", Quantity::rationals(&[s.alpha.clone(), s.beta[0].clone(), s.beta[1].clone(), s.gamma.clone()])),
                    value("mobius_point", "((|m|² − r² + 1)/2, m, (|m|² − r² − 1)/2) of the Möbius quadric model (2.13)", Quantity::rationals(&m.mobius)),
                ];
                let mut obj = args.object(cycle_geometry(c)?, m.certify()).with_values(values);
                if many {
                    obj.name = format!("{}_{}", args.name(), if k == 0 { "positive" } else { "negative" });
                }
                out.push(obj);
            }
        }
        Obj::Plane(e) => {
            let m = plane_models(&e);
            let mut values = vec![
                value("plane", "(e0, n1, n2, n3) of e0 + n·x = 0", Quantity::rationals(&[e.e0.clone(), e.n[0].clone(), e.n[1].clone(), e.n[2].clone()])),
                value("gamma_hyperplane", "(e0, n1, n2, n3, 1) of the cyclographic model (3.5)", Quantity::rationals(&m.gamma_hyperplane)),
                value("blaschke_point", "(1, n1, n2, n3, e0) on the Blaschke cylinder (3.10)", Quantity::rationals(&m.blaschke)),
                value("mobius_point", "(−e0, n, −e0) of the Möbius quadric model (p0 = p4: a plane)", Quantity::rationals(&m.mobius)),
            ];
            if let Some(y) = &m.isotropic {
                values.push(value("isotropic_point", "Λ(e) = (e1, e2, e0)/(1 − e3) (3.11)", Quantity::rationals(y)));
            }
            if let Some(d) = &m.dual_isotropic {
                values.push(value("dual_isotropic_plane", "Λ*(e) = (e0, e1, e2, e3 − 1) (3.16): Y0 + Y1 x + Y2 y + Y3 z = 0", Quantity::rationals(d)));
            }
            out.push(args.object(Geometry::Patch(plane_square(&e)?), m.certify()).with_values(values));
        }
    }
    Ok(out)
}

fn mpoly_value(name: &str, doc: &str, p: &MPolyQ) -> NamedQuantity {
    value(name, doc, Quantity::Text(poly_io::format_mpoly(p)))
}

fn build_isotropic_quadric(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let t = target(args)?;
    let q = t.proj.quadric();
    let iq = isotropic_quadric(&q).map_err(|e| OpError::param("quadric", e.to_string()))?;
    let mut certs = t.certs;
    certs.extend(iq.certify());
    let mut values = vec![
        value("dual_quadric", "Q* = adj Q (tangent planes uᵀ Q* u = 0)", Quantity::Vector(iq.dual.iter().map(|r| Quantity::rationals(r)).collect())),
        value("A", "A = 4 Q*₀₀ of A y3² + B y3 + C = 0", Quantity::Rational(iq.a.clone())),
        mpoly_value("B", "B(y1, y2) = 4(2y1 Q*₀₁ + 2y2 Q*₀₂ + (y1² + y2² − 1) Q*₀₃)", &iq.b),
        mpoly_value("C", "C(y1, y2) = (0, 2y1, 2y2, y1² + y2² − 1) Q* (…)ᵀ", &iq.c),
        mpoly_value("discriminant", "B² − 4AC", &iq.discriminant),
        value("rational", "F is a rational function (A = 0)", Quantity::Bool(iq.rational.is_some())),
    ];
    if let Some([fp, fm]) = iq.branches() {
        values.push(mpoly_value("F_plus_numerator", "F+ = (−B + g)/(2A), g² = B² − 4AC: numerator", &fp.num));
        values.push(mpoly_value("F_minus_numerator", "F− = (−B − g)/(2A): numerator", &fm.num));
        values.push(value("F_denominator_branches", "2A, the denominator of F±", Quantity::Rational(Q::from(2) * iq.a.clone())));
    }
    if let Some(f) = &iq.rational {
        values.push(mpoly_value("F_numerator", "F = numerator/denominator = −C/B", &f.num));
        values.push(mpoly_value("F_denominator", "the denominator B", &f.den));
    }
    // a patch of the quadric: the image of the first of a few bilinear patches whose image
    // has weights of one sign (the projection's exceptional lines differ per quadric)
    let bases: [[i64; 4]; 4] = [[1, 0, 0, 0], [2, 1, 1, 1], [3, 1, 2, -1], [2, -1, 1, 3]];
    let mut chosen = None;
    let mut last_err = None;
    for b in bases {
        let corner = |x: i64, y: i64| vec![Q::from(b[0]), Q::from(b[1] + x), Q::from(b[2] + y), Q::from(b[3])];
        let bilinear = BezierPatch::from_homogeneous(vec![
            vec![corner(0, 0), corner(0, 1)],
            vec![corner(1, 0), corner(1, 1)],
        ])?;
        match patch_image(t.proj.as_ref(), &bilinear) {
            Ok(img) => {
                let stride = img.image().dim() + 1;
                let ws: Vec<&Q> = img.image().coords().iter().step_by(stride).collect();
                let one_sign = ws.iter().all(|w| **w > Q::zero()) || ws.iter().all(|w| **w < Q::zero());
                if one_sign {
                    chosen = Some(img);
                    break;
                }
                if chosen.is_none() && last_err.is_none() {
                    last_err = Some(format!("the patch {b:?} + [0, 1]² has weights of both signs"));
                }
            }
            Err(e) => last_err = Some(e.to_string()),
        }
    }
    let img = chosen.ok_or_else(|| {
        OpError::param(
            "quadric",
            format!("no patch of the quadric to draw: {}", last_err.unwrap_or_default()),
        )
    })?;
    certs.extend(img.certify());
    let (geometry, extra) = exportable_patch(img.into_image(), &q)?;
    certs.extend(extra);
    Ok(vec![args
        .object(super::quadric_query::positive_weights(geometry)?, certs)
        .with_values(values)])
}

fn build_cycles(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let shift = arr::<4>(&args.point("shift")?, "shift", "the shift a")?;
    let scale = args.number("scale")?;
    let matrix: [[Q; 4]; 4] = match args.opt_grid("matrix")? {
        None => core::array::from_fn(|i| core::array::from_fn(|j| if i == j { Q::one() } else { Q::zero() })),
        Some(g) => {
            if g.len() != 4 || g.iter().any(|r| r.len() != 4) {
                return Err(OpError::param("matrix", "A must be a 4×4 matrix"));
            }
            core::array::from_fn(|i| core::array::from_fn(|j| g[i][j].clone()))
        }
    };
    let map = LaguerreMap::new(shift, scale.clone(), matrix).map_err(|e| {
        OpError::param(if scale.is_zero() { "scale" } else { "matrix" }, e.to_string())
    })?;
    let cycles = args
        .points("cycles")?
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let [m1, m2, m3, r] = arr::<4>(c, "cycles", &format!("cycle {k}"))?;
            Cycle::new([m1, m2, m3], r).map_err(|e| OpError::param("cycles", e.to_string()))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let lc = laguerre_cycles(&map, &cycles);
    let certs: Vec<Certificate> = lc.certify();
    let mut values = vec![value(
        "images",
        "the image cycles (m1, m2, m3, r), in the order given",
        Quantity::Vector(lc.images.iter().map(|(_, i)| cycle_quantity(i)).collect()),
    )];
    match &lc.fixed {
        Some(f) => values.push(value("fixed_cycle", "a fixed cycle: a + λA x = x", cycle_quantity(f))),
        None => values.push(value("fixed_cycle", "(I − λA)x = a has no solution", Quantity::Text("none".into()))),
    }
    values.push(value(
        "fixed_directions",
        "a basis of {d : λA d = d}: the fixed cycles are the fixed cycle + their span",
        Quantity::Vector(lc.fixed_directions.iter().map(|d| Quantity::rationals(d)).collect()),
    ));
    let mut patches = Vec::new();
    for (_, img) in &lc.images {
        match cycle_geometry(img)? {
            Geometry::Patches(p) => patches.extend(p),
            Geometry::Patch(p) => patches.push(p),
            _ => {}
        }
    }
    Ok(vec![args.object(Geometry::Patches(patches), certs).with_values(values)])
}

const LAGUERRE_PE_SPHERE: OpSpec = OpSpec {
    name: "laguerre_pe_sphere",
    summary: "the cyclographic image of the 2-dimensional pe sphere q = π ∩ Γ(a) of R^{3,1} (the cycles of the hyperplane π: ⟨x, ν⟩ = c in oriented contact with the cycle a; Peternell, Rational Parametrizations for Envelopes of Quadric Families, §3.9.1): the two cycles η(a) and η(σ(a)), σ the pe reflection in π, or for a γ-hyperplane π the cycle η(a) and the oriented plane π ∩ R³; certified; the object shows both (spheres as 16 patches, the plane as a square)",
    params: &[
        ParamSpec::required("vertex", ParamKind::Point, "a = [m1, m2, m3, r]: the vertex of the γ-cone Γ(a), a cycle"),
        ParamSpec::required("normal", ParamKind::Point, "ν = [ν1, ν2, ν3, ν4] ≠ 0 of the hyperplane π: ν1x1 + ν2x2 + ν3x3 − ν4x4 = c (the Lorentz product ⟨x, ν⟩)"),
        ParamSpec::required("offset", ParamKind::Number, "c of the hyperplane π; a must not lie in π"),
    ],
    example: r#"[[object]]
name = "pe_sphere"
op = "laguerre_pe_sphere"
# the cycles of radius 1 touching the sphere of radius 3 about the origin
vertex = [0, 0, 0, 3]
normal = [0, 0, 0, 1]
offset = -1
"#,
    build: build_pe_sphere,
};

fn build_pe_sphere(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    use rcagd::cyclographic::{certify_pe_sphere_image, pe_sphere_image, PeSphereImage};
    let four = |param: &'static str| -> Result<[Q; 4], OpError> {
        <[Q; 4]>::try_from(args.point(param)?)
            .map_err(|_| OpError::param(param, format!("`{param}` must be a vector [x1, x2, x3, x4]")))
    };
    let (a, nu, c) = (four("vertex")?, four("normal")?, args.number("offset")?);
    let image = pe_sphere_image(&a, &nu, &c).map_err(|e| OpError::param("normal", e.to_string()))?;
    let certs = certify_pe_sphere_image(&a, &nu, &c, &image);
    let cycle = |k: &rcagd::cyclographic::OrientedSphere<Q>| Cycle {
        center: k.center.clone(),
        radius: k.radius.clone(),
    };
    let mut patches = Vec::new();
    let mut push = |g: Geometry| match g {
        Geometry::Patches(p) => patches.extend(p),
        Geometry::Patch(p) => patches.push(p),
        _ => {}
    };
    let values = match &image {
        PeSphereImage::TwoCycles(k1, k2) => {
            let (c1, c2) = (cycle(k1), cycle(k2));
            push(cycle_geometry(&c1)?);
            push(cycle_geometry(&c2)?);
            vec![value(
                "cycles",
                "the two image cycles η(a), η(σ(a)) as (m1, m2, m3, r)",
                Quantity::Vector(vec![cycle_quantity(&c1), cycle_quantity(&c2)]),
            )]
        }
        PeSphereImage::CycleAndPlane(k, plane) => {
            let c1 = cycle(k);
            push(cycle_geometry(&c1)?);
            let e = OrientedPlane::new(plane.offset.clone(), plane.normal.clone())
                .map_err(|e| OpError::new(e.to_string()))?;
            push(Geometry::Patch(plane_square(&e)?));
            vec![
                value("cycles", "the image cycle η(a) as (m1, m2, m3, r)", Quantity::Vector(vec![cycle_quantity(&c1)])),
                value(
                    "plane",
                    "the oriented plane π ∩ R³ as (e0, n1, n2, n3): e0 + n·x = 0",
                    Quantity::rationals(&[
                        plane.offset.clone(),
                        plane.normal[0].clone(),
                        plane.normal[1].clone(),
                        plane.normal[2].clone(),
                    ]),
                ),
            ]
        }
    };
    Ok(vec![args.object(Geometry::Patches(patches), certs).with_values(values)])
}
