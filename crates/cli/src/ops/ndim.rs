//! n-dimensional ops (`rcagd::ndim`; Peternell ch. 5): PN hypersurfaces of `Rⁿ` from the
//! support-function form (5.4) with exact offsets, and the offset hypersurfaces of ruled
//! `(k+1)`-manifolds (Theorem 5.2).
//!
//! An object of `Rⁿ`, `n > 3`, is exported twice: exactly, as the named value
//! `homogeneous_map` (its homogeneous polynomial coordinates `X₀, …, Xₙ` in all parameters,
//! `rcagd_io::ndim`), and as a picture: the 2-parameter slice with the parameters `free`
//! running over `domain` and the others fixed at `slice`, projected orthogonally onto the
//! coordinates `project` — an ordinary rational Bézier patch of `R³`.

use super::arith::{self, OpScalar};
use super::poly_io::{self, MPolyIn, MPolyQ};
use super::{OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use rcagd::ndim::ruled::RuledKind;
use rcagd::ndim::{Anticaustic, HyperconeEnvelope, NdimError, PnHypersurface, RuledManifold};
use rcagd::pn::{Domain, RatFn};
use rcagd::Certified;
use rcagd_algebra::rational::format_rational;
use rcagd_algebra::{Rational, Scalar};
use rcagd_io::quantity::{NamedQuantity, Quantity};

type Q = Rational;

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[PN_HYPERSURFACE, HYPERCONE_ENVELOPE, ANTICAUSTIC_ND, RULED_OFFSET];

const SLICE: ParamSpec = ParamSpec::optional(
    "slice",
    ParamKind::Numbers,
    "values of all parameters for the 3-D picture (the two `free` ones are ignored; default all 0)",
);
const DISTANCES: ParamSpec = ParamSpec::optional(
    "distances",
    ParamKind::Numbers,
    "oriented offset distances d (x + d n); one extra object `<name>_offset<k>` per distance",
);
const FREE: ParamSpec = ParamSpec::with_default(
    "free",
    ParamKind::Numbers,
    "[1, 2]",
    "the two parameters (1-based) that run over `domain` in the 3-D picture",
);
const PROJECT: ParamSpec = ParamSpec::with_default(
    "project",
    ParamKind::Numbers,
    "[1, 2, 3]",
    "the three coordinates (1-based) of Rⁿ the picture is projected onto",
);
const DOMAIN: ParamSpec = ParamSpec::with_default(
    "domain",
    ParamKind::Numbers,
    "[0, 1, 0, 1]",
    "rectangle [s0, s1, t0, t1] of the two free parameters in the picture",
);

fn blame(param: &'static str) -> impl Fn(NdimError) -> OpError {
    move |e| OpError::param(param, e.to_string())
}

fn index(x: &Q, max: usize, param: &'static str) -> Result<usize, OpError> {
    let msg = || OpError::param(param, format!("entries must be integers in 1..={max}"));
    let i: i64 = x.to_string().parse().map_err(|_| msg())?;
    usize::try_from(i)
        .ok()
        .filter(|&i| (1..=max).contains(&i))
        .map(|i| i - 1)
        .ok_or_else(msg)
}

/// `(free, fixed, project, domain)` of a 3-D picture.
type Picture<T = Q> = ([usize; 2], Vec<T>, [usize; 3], Domain<T>);

/// [`picture`] in `T`.
fn picture_in<T: Scalar>(args: &OpArgs, params: usize, n: usize) -> Result<Picture<T>, OpError> {
    let (free, fixed, proj, dom) = picture(args, params, n)?;
    let dom = Domain::new(arith::of(&dom.u.0), arith::of(&dom.u.1), arith::of(&dom.v.0), arith::of(&dom.v.1))
        .map_err(|e| OpError::param("domain", e.to_string()))?;
    Ok((free, arith::all_of(&fixed), proj, dom))
}

/// `(free, fixed, project, domain)` of the 3-D picture of a map with `params` parameters
/// into `Rⁿ`.
fn picture(
    args: &OpArgs,
    params: usize,
    n: usize,
) -> Result<Picture, OpError> {
    let free = args.opt_numbers("free")?.unwrap_or_default();
    let proj = args.opt_numbers("project")?.unwrap_or_default();
    if free.len() != 2 || proj.len() != 3 {
        return Err(OpError::new("`free` needs two entries and `project` three"));
    }
    let f = [index(&free[0], params, "free")?, index(&free[1], params, "free")?];
    let p = [
        index(&proj[0], n, "project")? + 1,
        index(&proj[1], n, "project")? + 1,
        index(&proj[2], n, "project")? + 1,
    ];
    let fixed = args.opt_numbers("slice")?.unwrap_or_else(|| vec![Q::ZERO; params]);
    if fixed.len() != params {
        return Err(OpError::param(
            "slice",
            format!("give a value for each of the {params} parameters, got {}", fixed.len()),
        ));
    }
    let d = args.opt_numbers("domain")?.unwrap_or_default();
    if d.len() != 4 {
        return Err(OpError::param("domain", "give [s0, s1, t0, t1]"));
    }
    let dom = Domain::new(d[0].clone(), d[1].clone(), d[2].clone(), d[3].clone())
        .map_err(|e| OpError::param("domain", e.to_string()))?;
    Ok((f, fixed, p, dom))
}

use poly_io::map_value;

// ---------------------------------------------------------------------------------
// PN hypersurfaces (5.4)
// ---------------------------------------------------------------------------------

const PN_HYPERSURFACE: OpSpec = OpSpec {
    name: "pn_hypersurface",
    summary: "a PN hypersurface of Rⁿ from its tangent hyperplanes h + n·x = 0, n = (2a₁c, …, 2aₙ₋₁c, Σaᵢ² − c²)/(Σaᵢ² + c²) (Peternell (5.3)/(5.4)), points e ∩ e_u₁ ∩ … ∩ e_uₙ₋₁, exact offsets h ↦ h − d; exported exactly and as a projected 3-D slice",
    params: &[
        ParamSpec::required("dimension", ParamKind::Int, "the dimension n of the ambient space, 3 to 6"),
        ParamSpec::required(
            "support",
            ParamKind::Points,
            "terms [c, e₁, …, eₙ₋₁] of the numerator of the support function h(u₁, …, uₙ₋₁)",
        ),
        ParamSpec::optional(
            "support_denominator",
            ParamKind::Points,
            "terms [c, e₁, …, eₙ₋₁] of the denominator of h (default 1)",
        ),
        ParamSpec::optional(
            "a",
            ParamKind::Points,
            "terms [i, c, e₁, …, eₙ₋₁] of the polynomials aᵢ, i = 1 … n − 1 (default aᵢ = uᵢ)",
        ),
        ParamSpec::optional("c", ParamKind::Points, "terms [c, e₁, …, eₙ₋₁] of c (default 1)"),
        DISTANCES,
        SLICE,
        FREE,
        PROJECT,
        DOMAIN,
    ],
    example: r#"[[object]]
name = "pn_hypersurface_r4"
op = "pn_hypersurface"
dimension = 4
# h = 1 + u₁u₂ − u₃²/2, n = (2u₁, 2u₂, 2u₃, u₁² + u₂² + u₃² − 1)/(u₁² + u₂² + u₃² + 1)
support = [[1, 0, 0, 0], [1, 1, 1, 0], ["-1/2", 0, 0, 2]]
slice = [0, 0, "1/2"]
project = [1, 2, 4]
domain = [0, "1/2", 0, "1/2"]
distances = ["1/4"]
"#,
    build: build_hypersurface::<Rational>,
};

use poly_io::terms_mpoly as terms_poly;

/// `pn_hypersurface` in `T` (one builder for the exact op and the float path).
pub(crate) fn build_hypersurface<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let n = dimension(args)?;
    let p = n - 1;
    let num = terms_poly(&args.points("support")?, p, "support")?;
    let den = match args.get("support_denominator") {
        Some(_) => terms_poly(&args.points("support_denominator")?, p, "support_denominator")?,
        None => poly_io::mpoly_constant(p, Q::ONE),
    };
    let h = RatFn::new(poly_io::mpoly_in::<T>(&num), poly_io::mpoly_in::<T>(&den))
        .map_err(|e| OpError::param("support_denominator", e.to_string()))?;
    let a = if args.get("a").is_some() {
        let mut terms = Vec::new();
        for r in args.points("a")? {
            let i = r.first().map_or(Ok(0), |x| index(x, p, "a"))?;
            terms.push((i, r.get(1..).unwrap_or_default().to_vec()));
        }
        poly_io::indexed_terms_mpolys(&terms, p, p, "a")?
    } else {
        (0..p).map(|i| poly_io::mpoly_var(p, i)).collect()
    };
    let c = match args.get("c") {
        Some(_) => terms_poly(&args.points("c")?, p, "c")?,
        None => poly_io::mpoly_constant(p, Q::ONE),
    };
    let a: Vec<MPolyIn<T>> = a.iter().map(poly_io::mpoly_in::<T>).collect();
    let surface = PnHypersurface::from_support(&a, &poly_io::mpoly_in::<T>(&c), &h).map_err(blame("support"))?;
    let names: Vec<String> = (1..=p).map(|i| format!("u{i}")).collect();
    hypersurface_objects(args, &surface, surface.certify(), names)
}

/// The coefficients of `T` polynomials as exact numbers (an `f64` one: its exact binary
/// value; a non-finite one is an error, as for control points).
fn exact_polys<T: Scalar>(ps: &[MPolyIn<T>]) -> Result<Vec<MPolyQ>, OpError> {
    let finite = core::cell::Cell::new(true);
    let out: Vec<MPolyQ> = ps
        .iter()
        .map(|p| {
            p.map(|c| {
                c.to_rational().unwrap_or_else(|| {
                    finite.set(false);
                    Q::ZERO
                })
            })
        })
        .collect();
    if finite.get() {
        Ok(out)
    } else {
        Err(OpError::new(
            "the f64 construction produced a non-finite coefficient (overflow or an ill-conditioned input); build it without --float",
        ))
    }
}

/// The object of a PN hypersurface (its picture and exact map) and one per offset distance.
fn hypersurface_objects<T: OpScalar>(
    args: &OpArgs,
    surface: &PnHypersurface<T>,
    certs: Vec<rcagd_algebra::Certificate>,
    names: Vec<String>,
) -> Result<Vec<Object>, OpError> {
    let n = surface.dim();
    let (free, fixed, proj, dom) = picture_in::<T>(args, n - 1, n)?;
    let object = |s: &PnHypersurface<T>, certs, name: Option<String>| -> Result<Object, OpError> {
        let patch = s.projected_slice(free, &fixed, proj, &dom).map_err(blame("domain"))?;
        let map = map_value(names.clone(), &exact_polys(s.point_polys())?, s.name())?;
        let mut o = arith::object_with::<T>(args, arith::patches(vec![patch])?, certs, vec![map]);
        if let Some(nm) = name {
            o.name = nm;
        }
        Ok(o)
    };
    let mut out = vec![object(surface, certs, None)?];
    for (k, d) in args.opt_numbers("distances")?.unwrap_or_default().iter().enumerate() {
        let off = surface.offset(&arith::of::<T>(d)).map_err(blame("distances"))?;
        let mut o = object(off.surface(), off.certify(), Some(format!("{}_offset{}", args.name(), k + 1)))?;
        if let Some(m) = o.params.as_object_mut() {
            m.insert("offset_distance".into(), serde_json::Value::String(format_rational(d)));
        }
        out.push(o);
    }
    Ok(out)
}

// ---------------------------------------------------------------------------------
// envelopes of sphere-hypercones (Theorem 5.1)
// ---------------------------------------------------------------------------------

const HYPERCONE_ENVELOPE: OpSpec = OpSpec {
    name: "hypercone_envelope",
    summary: "the envelope of the sphere-hypercones spanned by two rational cycle families (m₁; r₁)(t), (m₂; r₂)(t) of Rⁿ (Peternell Theorem 5.1, (5.5)–(5.12)): a PN hypersurface in (t, u₁, …, uₙ₋₂) with exact offsets; exported exactly and as a projected 3-D slice",
    params: &[
        ParamSpec::required("center1", ParamKind::Grid, "n rows: power coefficients in t of the centres m₁(t)").degree(),
        ParamSpec::required("radius1", ParamKind::Numbers, "power coefficients in t of the signed radius r₁(t)").degree(),
        ParamSpec::required("center2", ParamKind::Grid, "n rows: power coefficients in t of m₂(t)").degree(),
        ParamSpec::required("radius2", ParamKind::Numbers, "power coefficients in t of r₂(t)").degree(),
        DISTANCES,
        SLICE,
        FREE,
        PROJECT,
        DOMAIN,
    ],
    example: r#"[[object]]
name = "hypercone_envelope_r4"
op = "hypercone_envelope"
# point cycles on the line (t, 0, 0, 0) and unit spheres about (0, t, 1, 0): |M|² − R² = 2t²
center1 = [[0, 1], [0, 0], [0, 0], [0, 0]]
radius1 = [0]
center2 = [[0, 0], [0, 1], [1, 0], [0, 0]]
radius2 = [1]
slice = [0, 0, "1/2"]
project = [1, 2, 3]
domain = ["1/4", "3/4", "1/4", "3/4"]
"#,
    build: build_hypercone::<Rational>,
};

/// `hypercone_envelope` in `T`. The sum of two squares `|M|² − R² = P₁² + P₂²` over `Q(t)`
/// that the construction needs is found exactly (exact-only algebra on the input); in
/// `f64` the envelope is then built from the rounded `P₁, P₂`.
pub(crate) fn build_hypercone<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let m1 = polys_t(&args.opt_grid("center1")?.unwrap_or_default())?;
    let m2 = polys_t(&args.opt_grid("center2")?.unwrap_or_default())?;
    let r1 = poly_io::list_mpoly(&args.opt_numbers("radius1")?.unwrap_or_default(), 1)?;
    let r2 = poly_io::list_mpoly(&args.opt_numbers("radius2")?.unwrap_or_default(), 1)?;
    let exact = HyperconeEnvelope::new(m1.clone(), r1.clone(), m2.clone(), r2.clone(), None)
        .map_err(blame("center2"))?;
    let env = match arith::same::<_, HyperconeEnvelope<T>>(exact) {
        Ok(env) => env,
        Err(exact) => {
            let all = |v: &[MPolyQ]| v.iter().map(poly_io::mpoly_in::<T>).collect::<Vec<_>>();
            let [p1, p2] = exact.p();
            let rat = |p: &RatFn<Q>| RatFn { num: poly_io::mpoly_in::<T>(&p.num), den: poly_io::mpoly_in::<T>(&p.den) };
            let p = if [p1, p2].iter().all(|p| p.num.is_zero()) { None } else { Some([rat(p1), rat(p2)]) };
            HyperconeEnvelope::new(all(&m1), poly_io::mpoly_in(&r1), all(&m2), poly_io::mpoly_in(&r2), p)
                .map_err(blame("center2"))?
        }
    };
    let n = env.surface().dim();
    let mut names = vec!["t".to_string()];
    names.extend((1..n - 1).map(|j| format!("u{j}")));
    hypersurface_objects(args, env.surface(), env.certify(), names)
}

// ---------------------------------------------------------------------------------
// anticaustics (§3.6)
// ---------------------------------------------------------------------------------

const ANTICAUSTIC_ND: OpSpec = OpSpec {
    name: "anticaustic_nd",
    summary: "the anticaustic in Rⁿ of a rational mirror of dimension k ≤ n − 1 for light parallel to xₙ: q = (p₁, …, pₙ₋₁, c) + 2(pₙ − c) mₙ m/|m|² (Peternell (3.18), corrected), m running over the mirror's normals; a PN hypersurface with unit normal the reflected ray (Theorem 4.1), offsets by c ↦ c + d; exported exactly and as a projected 3-D slice",
    params: &[
        ParamSpec::required("dimension", ParamKind::Int, "the dimension n of the ambient space, 3 to 6"),
        ParamSpec::required("mirror_dimension", ParamKind::Int, "the dimension k of the mirror, 1 to n − 1"),
        ParamSpec::required(
            "mirror",
            ParamKind::Points,
            "terms [i, c, e₁, …, e_k] of the mirror's homogeneous coordinates Pᵢ (i = 0 the weight, 1 … n the coordinates)",
        ),
        ParamSpec::with_default("c", ParamKind::Number, "0", "the height c of the wavefront plane xₙ = c"),
        DISTANCES,
        SLICE,
        FREE,
        PROJECT,
        DOMAIN,
    ],
    example: r#"[[object]]
name = "anticaustic_r4"
op = "anticaustic_nd"
dimension = 4
mirror_dimension = 3
# the mirror x₄ = (u₁² + u₂² − u₃²)/2 + u₁u₃
mirror = [[0, 1, 0, 0, 0], [1, 1, 1, 0, 0], [2, 1, 0, 1, 0], [3, 1, 0, 0, 1], [4, "1/2", 2, 0, 0], [4, "1/2", 0, 2, 0], [4, "-1/2", 0, 0, 2], [4, 1, 1, 0, 1]]
c = "1/2"
slice = [0, 0, "1/4"]
domain = [0, "1/2", 0, "1/2"]
distances = ["1/4"]
"#,
    build: build_anticaustic::<Rational>,
};

/// `anticaustic_nd` in `T` (one builder for the exact op and the float path).
pub(crate) fn build_anticaustic<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let n = dimension(args)?;
    let k = usize::try_from(args.int("mirror_dimension")?)
        .ok()
        .filter(|k| (1..n).contains(k))
        .ok_or_else(|| OpError::param("mirror_dimension", format!("k must be 1 to {}", n - 1)))?;
    let mut terms = Vec::new();
    for r in args.points("mirror")? {
        let i = r
            .first()
            .and_then(|x| x.to_string().parse::<usize>().ok())
            .filter(|&i| i <= n)
            .ok_or_else(|| OpError::param("mirror", format!("the first entry of a term is the coordinate 0 … {n}")))?;
        terms.push((i, r.get(1..).unwrap_or_default().to_vec()));
    }
    let mirror = poly_io::indexed_terms_mpolys(&terms, n + 1, k, "mirror")?;
    let c = args.opt_number("c")?.unwrap_or(Q::ZERO);
    let mirror: Vec<MPolyIn<T>> = mirror.iter().map(poly_io::mpoly_in::<T>).collect();
    let ac = Anticaustic::new(mirror, k, arith::of::<T>(&c)).map_err(blame("mirror"))?;
    let mut names: Vec<String> = (1..=k).map(|i| format!("u{i}")).collect();
    names.extend((1..n - k).map(|j| format!("v{j}")));
    hypersurface_objects(args, ac.surface(), ac.certify(), names)
}

// ---------------------------------------------------------------------------------
// offsets of ruled (k+1)-manifolds (Theorem 5.2)
// ---------------------------------------------------------------------------------

const RULED_OFFSET: OpSpec = OpSpec {
    name: "ruled_manifold_offset",
    summary: "the offset hypersurface at distance d of a ruled (k+1)-manifold l(t) + Σ uⱼ gⱼ(t) of Rⁿ (Peternell (5.13), Theorem 5.2: unit normal from a polynomial point on the quadric family (5.25) by the conic-point engine, spheres (5.26)), with its structure (m, Case 1/2, singular or central space); exported exactly and as a projected 3-D slice",
    params: &[
        ParamSpec::required(
            "directrix",
            ParamKind::Grid,
            "n rows: power coefficients in t of the numerators of l(t) (zero-padded to one length)",
        ).degree(),
        ParamSpec::optional(
            "directrix_denominator",
            ParamKind::Numbers,
            "power coefficients of the common denominator w(t) of l (default 1)",
        ).degree(),
        ParamSpec::required(
            "generators",
            ParamKind::Grid,
            "k·n rows: power coefficients in t of g₁ (n rows), then g₂, … (1 ≤ k ≤ n − 2)",
        ).degree(),
        ParamSpec::required("distance", ParamKind::Number, "the offset distance d"),
        SLICE,
        FREE,
        PROJECT,
        DOMAIN,
    ],
    example: r#"[[object]]
name = "ruled_2_manifold_r4_offset"
op = "ruled_manifold_offset"
# the non-developable 2-manifold (t, t², 0, 0) + u (0, 0, 1, t) of R⁴ (Peternell §5.5, second example)
directrix = [[0, 1, 0], [0, 0, 1], [0, 0, 0], [0, 0, 0]]
generators = [[0, 0], [0, 0], [1, 0], [0, 1]]
distance = "1/4"
slice = [0, 0, "1/2"]
free = [1, 2]
project = [1, 3, 4]
domain = ["1/4", "3/4", "1/4", "3/4"]
"#,
    build: build_ruled_offset,
};

/// The parameter `dimension`: the ambient dimension n, 3 to 6.
fn dimension(args: &OpArgs) -> Result<usize, OpError> {
    usize::try_from(args.int("dimension")?)
        .ok()
        .filter(|n| (3..=6).contains(n))
        .ok_or_else(|| OpError::param("dimension", "n must be 3 to 6"))
}

fn polys_t(rows: &[Vec<Q>]) -> Result<Vec<MPolyQ>, OpError> {
    poly_io::list_mpolys(rows)
}

fn build_ruled_offset(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let l = polys_t(&args.opt_grid("directrix")?.unwrap_or_default())?;
    let n = l.len();
    let g = polys_t(&args.opt_grid("generators")?.unwrap_or_default())?;
    if n < 3 || g.is_empty() || !g.len().is_multiple_of(n) {
        return Err(OpError::param(
            "generators",
            format!("give k·n rows (n = {n} directrix rows), got {}", g.len()),
        ));
    }
    let gens: Vec<Vec<MPolyQ>> = g.chunks(n).map(<[MPolyQ]>::to_vec).collect();
    let w = match args.opt_numbers("directrix_denominator")? {
        Some(c) => poly_io::list_mpoly(&c, 1)?,
        None => poly_io::mpoly_constant(1, Q::ONE),
    };
    let k = gens.len();
    let manifold = RuledManifold::new(l, w, gens).map_err(blame("generators"))?;
    let st = manifold.structure().map_err(blame("generators"))?;
    let d = args.number("distance")?;
    let off = manifold.offset(d).map_err(blame("generators"))?;
    let (free, fixed, proj, dom) = picture(args, n - 1, n)?;
    let patch = off.projected_slice(free, &fixed, proj, &dom).map_err(blame("domain"))?;
    let mut certs = st.certificates().to_vec();
    certs.extend(off.certify());
    let mut names = vec!["t".to_string()];
    names.extend((1..=k).map(|j| format!("s{j}")));
    names.extend((1..n - k - 1).map(|j| format!("v{j}")));
    let case = match st.kind {
        RuledKind::Singular => "case 1: singular space",
        RuledKind::Central => "case 2: central space",
    };
    let values = vec![
        map_value(names, &off.homogeneous(), "offset hypersurface")?,
        NamedQuantity::new("m", "dim A(t) − k (5.14)", Quantity::Integer(st.m as i64)),
        NamedQuantity::new("dim_T", "dim T(t) (5.15)", Quantity::Integer(st.dim_t as i64)),
        NamedQuantity::new("case", "§5.4 case of the generators", Quantity::Text(case.into())),
    ];
    Ok(vec![args.object(Geometry::Patch(patch), certs).with_values(values)])
}
