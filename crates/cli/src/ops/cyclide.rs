//! Ops of the `cyclide` topic: Dupin cyclides as cyclographic images of pe conics
//! (`rcagd::cyclide`; Peternell, "Rational Parametrizations for Envelopes of Quadric
//! Families", §3.8.1): from a pe circle, from three spheres, and the parabolic cyclide.
//! The ring, horn and spindle cyclides arrive as 16 biquadratic patches covering the whole
//! surface; the parabolic one (unbounded) on a parameter box.

use super::arith::{self, OpScalar};
use super::{OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::{ParamKind, Value};
use rcagd::cyclide::spheres::certify_three_spheres;
use rcagd::cyclide::{
    blend_cones, fitting_contact_sphere, from_three_spheres, DualPencil, DupinCyclide,
};
use rcagd::cyclographic::OrientedSphere;
use rcagd::Certified;
use rcagd_algebra::{Certificate, Rational};
use rcagd_geom::BezierPatch;
use rcagd_io::quantity::{NamedQuantity, Quantity};

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[
    DUPIN_CYCLIDE,
    DUPIN_CYCLIDE_SPHERES,
    DUPIN_CYCLIDE_PARABOLIC,
    CYCLIDE_BLEND,
];


fn vec4<T: OpScalar>(args: &OpArgs, param: &'static str) -> Result<[T; 4], OpError> {
    arith::point(args, param, &format!("`{param}` must be a vector of R^{{3,1}}: [x, y, z, r]"))
}

fn range<T: OpScalar>(args: &OpArgs, param: &'static str) -> Result<(T, T), OpError> {
    let v = args.opt_numbers(param)?.unwrap_or_default();
    match <[Rational; 2]>::try_from(v) {
        Ok([a, b]) if a < b => Ok((arith::of(&a), arith::of(&b))),
        _ => Err(OpError::param(param, format!("`{param}` must be an interval [a, b] with a < b"))),
    }
}

/// The object of a cyclide: its covering (or boxed) patches with positive weights, every
/// certificate (surface, offset, pencil), and its type as a value.
pub(super) fn cyclide_object<T: OpScalar>(
    args: &OpArgs,
    cy: &DupinCyclide<T>,
    patches: Vec<BezierPatch<T>>,
    mut certs: Vec<Certificate>,
) -> Result<Vec<Object>, OpError> {
    certs.extend(cy.certify());
    let pencil = DualPencil::of(cy).map_err(|e| OpError::new(e.to_string()))?;
    certs.extend(pencil.certify(cy));
    if let Some(d) = args.opt_number("offset")? {
        certs.extend(cy.certify_offset(&arith::of::<T>(&d)).map_err(|e| OpError::param("offset", e.to_string()))?);
    }
    let (patches, wcert) = super::canal::positive_pieces(patches, None)?;
    certs.push(wcert);
    let kind = NamedQuantity::new("kind", "the type of the Dupin cyclide (ring, horn, spindle, parabolic)", Quantity::Text(cy.kind().name().into()));
    Ok(vec![arith::object_with::<T>(args, Geometry::Patches(arith::exact_patches(patches)?), certs, vec![kind])])
}

const DUPIN_CYCLIDE: OpSpec = OpSpec {
    name: "dupin_cyclide",
    summary: "the Dupin cyclide of the pe circle C₀ + ρ(cos θ U + sin θ V) of R^{3,1} (⟨U,U⟩ = ⟨V,V⟩ = 1, ⟨U,V⟩ = 0; Peternell Lemma 3.4): 16 biquadratic patches x = (R_C M_D − R_D M_C)/(R_C W_D − R_D W_C) from the contact points of its two sphere families, with a rational unit normal; type ring/horn/spindle",
    params: &[
        ParamSpec::with_default("center", ParamKind::Point, "[0, 0, 0, 3]", "centre C₀ = (c, r₀): the middle sphere"),
        ParamSpec::with_default("u", ParamKind::Point, "[1, 0, 0, 0]", "U, pe-unit"),
        ParamSpec::with_default("v", ParamKind::Point, "[0, \"5/4\", 0, \"3/4\"]", "V, pe-unit and pe-orthogonal to U"),
        ParamSpec::required("rho", ParamKind::Number, "pe radius ρ ≠ 0"),
        ParamSpec::optional("offset", ParamKind::Number, "also certify the offset at this distance (r → r + d)"),
    ],
    example: r#"[[object]]
name = "ring_cyclide"
op = "dupin_cyclide"
center = [0, 0, 0, 4]
u = [1, 0, 0, 0]
v = [0, "5/4", 0, "3/4"]
rho = 4
"#,
    build: build_dupin_cyclide::<Rational>,
};

/// `dupin_cyclide` in `T` (one builder for the exact op and the float path).
pub(crate) fn build_dupin_cyclide<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let c = vec4::<T>(args, "center")?;
    let (u, v) = (vec4(args, "u")?, vec4(args, "v")?);
    let rho = arith::number::<T>(args, "rho")?;
    let cy = DupinCyclide::from_pe_circle(c, u, v, rho).map_err(|e| OpError::new(e.to_string()))?;
    let patches = cy.covering_patches().map_err(|e| OpError::new(e.to_string()))?;
    cyclide_object(args, &cy, patches, Vec::new())
}

const DUPIN_CYCLIDE_SPHERES: OpSpec = OpSpec {
    name: "dupin_cyclide_spheres",
    summary: "the Dupin cyclide enveloping all spheres tangent (in oriented contact) to three oriented spheres (Peternell §3.8.1: Γ(A₁) ∩ Γ(A₂) ∩ Γ(A₃) is a pe conic): the cyclide of the pe circle through the three cycles (Euclidean plane), of the pe circle conjugate to the pe hyperbola through them (pseudo-Euclidean plane; 16 covering patches), or the parabolic cyclide of the pe parabola through them (γ-plane; one patch over the box t × s); reversing a radius's sign picks another of the cyclides",
    params: &[
        ParamSpec::required("centers", ParamKind::Points, "the three centres [[x, y, z], …]"),
        ParamSpec::required("radii", ParamKind::Numbers, "the three signed radii (the sign is the orientation)"),
        ParamSpec::optional("offset", ParamKind::Number, "also certify the offset at this distance"),
        ParamSpec::with_default("t", ParamKind::Numbers, "[-2, 2]", "parabolic cyclide only: parameter interval of the first family (the parabola through the three cycles)"),
        ParamSpec::with_default("s", ParamKind::Numbers, "[-2, 2]", "parabolic cyclide only: parameter interval of the second family"),
    ],
    example: r#"[[object]]
name = "cyclide_of_three_spheres"
op = "dupin_cyclide_spheres"
centers = [[0, 0, 0], [4, 0, 0], [0, 4, 0]]
radii = [1, 1, 1]
"#,
    build: build_spheres::<Rational>,
};

/// `dupin_cyclide_spheres` in `T` (one builder for the exact op and the float path).
/// The pe conic through the three cycles and its two families of spheres (a few dozen
/// operations, with the exact-only decisions: is a norm ratio a square over ℚ, the
/// rational point of a conic, which entries are 0) are built exactly from the exact input
/// and, in `f64`, rounded once ([`DupinCyclide::rounded`]: formed in `f64` the conjugate
/// conic loses the digits its Gram matrix cancels); the surface, its patches and every
/// certificate are then computed in `T`.
pub(crate) fn build_spheres<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let centers = args.points("centers")?;
    let radii = args.opt_numbers("radii")?.unwrap_or_default();
    if centers.len() != 3 || centers.iter().any(|c| c.len() != 3) {
        return Err(OpError::param("centers", "give exactly three centres [x, y, z]"));
    }
    if radii.len() != 3 {
        return Err(OpError::param("radii", "give exactly three radii"));
    }
    let exact: [OrientedSphere<Rational>; 3] = core::array::from_fn(|i| {
        OrientedSphere::new(core::array::from_fn(|k| centers[i][k].clone()), radii[i].clone())
    });
    let spheres: [OrientedSphere<T>; 3] = core::array::from_fn(|i| {
        OrientedSphere::new(core::array::from_fn(|k| arith::of(&centers[i][k])), arith::of(&radii[i]))
    });
    let blame = |e: rcagd::cyclide::CyclideError| OpError::param("radii", e.to_string());
    let exact_cy = from_three_spheres(&exact).map_err(blame)?;
    let cy = match arith::same_ref::<_, DupinCyclide<T>>(&exact_cy) {
        Some(cy) => cy.clone(),
        None => DupinCyclide::<T>::rounded(&exact_cy),
    };
    let patches = if cy.conic().is_parabola() {
        let (t0, t1) = range::<T>(args, "t")?;
        let (s0, s1) = range::<T>(args, "s")?;
        vec![cy.patch((&t0, &t1), (&s0, &s1)).map_err(|e| OpError::new(e.to_string()))?]
    } else {
        cy.covering_patches().map_err(|e| OpError::new(e.to_string()))?
    };
    let certs = certify_three_spheres(&cy, &spheres);
    cyclide_object(args, &cy, patches, certs)
}

const DUPIN_CYCLIDE_PARABOLIC: OpSpec = OpSpec {
    name: "dupin_cyclide_parabolic",
    summary: "the parabolic Dupin cyclide (a cubic) of the pe parabola C₀ + tU + (t²/2)N in a γ-plane (⟨U,U⟩ = 1, N isotropic, ⟨U,N⟩ = 0; Peternell Prop. 3.2), as the biquadratic patch over a parameter box",
    params: &[
        ParamSpec::with_default("vertex", ParamKind::Point, "[0, 0, 0, 1]", "vertex C₀ = (c, r₀)"),
        ParamSpec::with_default("u", ParamKind::Point, "[1, 0, 0, 0]", "U, pe-unit"),
        ParamSpec::with_default("n", ParamKind::Point, "[0, \"3/5\", \"4/5\", 1]", "N ≠ 0 isotropic, pe-orthogonal to U"),
        ParamSpec::with_default("t", ParamKind::Numbers, "[-2, 2]", "parameter interval of the first family"),
        ParamSpec::with_default("s", ParamKind::Numbers, "[-2, 2]", "parameter interval of the second family"),
        ParamSpec::optional("offset", ParamKind::Number, "also certify the offset at this distance"),
    ],
    example: r#"[[object]]
name = "parabolic_cyclide"
op = "dupin_cyclide_parabolic"
vertex = [0, 0, 0, 1]
u = [1, 0, 0, 0]
n = [0, "3/5", "4/5", 1]
t = [-2, 2]
s = [-1, 1]
"#,
    build: build_parabolic::<Rational>,
};

/// `dupin_cyclide_parabolic` in `T`.
pub(crate) fn build_parabolic<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let c = vec4::<T>(args, "vertex")?;
    let (u, n) = (vec4(args, "u")?, vec4(args, "n")?);
    let (t0, t1) = range::<T>(args, "t")?;
    let (s0, s1) = range::<T>(args, "s")?;
    let cy = DupinCyclide::from_pe_parabola(c, u, n).map_err(|e| OpError::new(e.to_string()))?;
    let patch = cy.patch((&t0, &t1), (&s0, &s1)).map_err(|e| OpError::new(e.to_string()))?;
    cyclide_object(args, &cy, vec![patch], Vec::new())
}


const CYCLIDE_BLEND: OpSpec = OpSpec {
    name: "cyclide_blend",
    summary: "a Dupin cyclide blend between two cones or cylinders of revolution with intersecting or parallel axes, tangent to both along the circles where the spheres P₁, P₂ touch them (Peternell §3.8: cones are images of lines of R^{3,1}; the blend is the image of the pe circle tangent to both lines)",
    params: &[
        ParamSpec::required("sphere1", ParamKind::Point, "P₁ = (m₁, r₁): the sphere inscribed in cone 1 along the contact circle"),
        ParamSpec::required("direction1", ParamKind::Point, "d₁ = (a₁, δ₁): axis direction a₁ and radius change δ₁ of cone 1 (δ₁ = 0: cylinder), |a₁|² > δ₁²; the blend leaves P₁ along +d₁"),
        ParamSpec::optional("sphere2", ParamKind::Point, "P₂ = (m₂, r₂), with equal pe tangent lengths to the common cycle of both lines; or give `point2` instead"),
        ParamSpec::required("direction2", ParamKind::Point, "d₂ = (a₂, δ₂) of cone 2"),
        ParamSpec::optional("point2", ParamKind::Point, "instead of `sphere2`: any sphere (m, r) of cone 2 (a point of its line); P₂ is then computed to fit P₁ (equal tangent lengths; for parallel axes the sphere level with P₁)"),
        ParamSpec::with_default("side2", ParamKind::Number, "1", "with `point2` and meeting axes: +1 or −1, which of the two fitting spheres of cone 2 (on either side of the axes' intersection)"),
        ParamSpec::with_default("arc", ParamKind::Choice(&["blend", "complement"]), "\"blend\"", "which band of the cyclide between the two contact circles: the blend, or the complementary arc (the rest of the same cyclide, through the other side of the contact spheres)"),
    ],
    example: r#"[[object]]
name = "elbow_blend"
op = "cyclide_blend"
sphere1 = [2, 0, 0, 1]
direction1 = [1, 0, 0, 0]
sphere2 = [0, 2, 0, 1]
direction2 = [0, 1, 0, 0]
"#,
    build: build_blend::<Rational>,
};

/// `cyclide_blend` in `T`.
pub(crate) fn build_blend<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (p1, d1) = (vec4::<T>(args, "sphere1")?, vec4(args, "direction1")?);
    let d2 = vec4(args, "direction2")?;
    let (p2, blame) = match (args.opt_point("sphere2")?, args.opt_point("point2")?) {
        (Some(_), Some(_)) => {
            return Err(OpError::param("point2", "give either `sphere2` or `point2`, not both"))
        }
        (Some(_), None) => (vec4(args, "sphere2")?, "sphere2"),
        (None, Some(_)) => {
            let side = match args.opt_number("side2")? {
                Some(x) if x == Rational::from(-1) => -1,
                Some(x) if x == Rational::from(1) => 1,
                None => 1,
                Some(_) => return Err(OpError::param("side2", "`side2` must be 1 or -1")),
            };
            let q2 = vec4(args, "point2")?;
            let p2 = fitting_contact_sphere(&p1, &d1, &q2, &d2, side)
                .map_err(|e| OpError::param("point2", e.to_string()))?;
            (p2, "point2")
        }
        (None, None) => {
            return Err(OpError::param("sphere2", "give `sphere2` (the contact sphere of cone 2) or `point2` (any sphere of cone 2)"))
        }
    };
    let blend = blend_cones(p1, d1, p2, d2).map_err(|e| OpError::param(blame, e.to_string()))?;
    let patches = match args.get("arc") {
        Some(Value::Str(a)) if a == "complement" => blend.complement_patches(),
        _ => blend.patches(),
    }
    .map_err(|e| OpError::new(e.to_string()))?;
    let mut certs = blend.certify();
    let (patches, wcert) = super::canal::positive_pieces(patches, Some("sphere2"))?;
    certs.push(wcert);
    let kind = NamedQuantity::new(
        "kind",
        "the type of the blending Dupin cyclide",
        Quantity::Text(blend.cyclide.kind().name().into()),
    );
    Ok(vec![arith::object_with::<T>(args, Geometry::Patches(arith::exact_patches(patches)?), certs, vec![kind])])
}
