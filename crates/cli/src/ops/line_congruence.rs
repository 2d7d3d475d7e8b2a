//! Ops of the `line_congruence` topic: line nets and congruences of order one drawn as
//! ruled strips (`rcagd::lines::congruence_strips`; D. Gruber, "Rationale
//! Parametrisierungen von Kugelhüllflächen", 2008, §1.1.6–1.1.8).

use super::arith::{self, OpScalar};
use super::poly_io::{self, MPolyQ};
use super::{OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use rcagd::lines::{
    congruence_strips, point_family_patches, CongruenceSpec, NetKind, ParametrizedCongruence,
    PointRow,
};
use rcagd_algebra::Rational;
use rcagd_io::quantity::{NamedQuantity, Quantity};

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[LINE_CONGRUENCE_STRIPS, LINE_CONGRUENCE_PARAMETRIZED];

const LINE_CONGRUENCE_STRIPS: OpSpec = OpSpec {
    name: "line_congruence_strips",
    summary: "a line net or congruence of order one (net by its axes, pencil of planes with a projectivity, a pencil of planes cut with a bundle of planes, two reguli sharing two lines, chords of a twisted cubic, joins of a plane collineation, (1, n)-congruence of a line and a curve) drawn as ruled strips: the lines p(u, v) ∨ q(u, v) along v = v_k + twist·u, cut to the segments (1 − λ)p + λq; the congruence is certified (Klein quadric, complexes, fibration, order, class, focal sheets)",
    params: &[
        ParamSpec::required(
            "congruence",
            ParamKind::Choice(&["hyperbolic", "elliptic", "parabolic", "pencil", "cubic_chords", "collineation", "one_n", "ruled_tangents", "reguli", "pencil_bundle"]),
            "the congruence type",
        ),
        ParamSpec::required(
            "points",
            ParamKind::Points,
            "homogeneous points [x0, x1, x2, x3] (weight first): nets c0, c1, d0, d1 (axes c0 + u c1, d0 + v d1; parabolic: lines through c(u) to d0 + u d1 + v c1) or Re c0, Im c0, Re c1, Im c1 (elliptic); pencil c0, c1, e0, e1 (the point c0 + u c1 of the axis is mapped to the plane e0 + u e1 through it; lines through c(u) in that plane: a parabolic net); cubic_chords a0, a1, a2, a3 of k(t) = a0 + t a1 + t² a2 + t³ a3 (chord k(u) ∨ k(v)); collineation a0, a1, a2, b0, b1, b2 (κ(x0 a0 + x1 a1 + x2 a2) = x0 b0 + x1 b1 + x2 b2, lines x(u, v) ∨ κ(x(u, v)) with x = a0 + u a1 + v a2); one_n g0, g1 of the focal line (lines k(u) ∨ (g0 + v g1)); ruled_tangents: the power coefficients of p(t) (see `ruling`) of the ruled surface X(t, v) = p(t) + v q(t); reguli (Gruber §1.1.6: the net of two reguli sharing two lines) a0, a1, b0, b1, c0, c1 of three pairwise skew lines a, b, c of the first regulus, then the same for the second: one strip per regulus, its generators x(1 − u, u) (x(1, 0) = b, x(0, 1) = c) between the transversals through the points (1 − v)a0 + v a1 of a for the two values of `v`; pencil_bundle (Gruber §1.1.6) the plane coordinates [u0, u1, u2, u3] (plane u0 + u1 x + u2 y + u3 z = 0) of ε0, ε1, φ0, φ1, φ2: the lines ε(u) ∩ φ(u, v) of the pencil ε0 + u ε1 about the axis and the bundle φ0 + u φ1 + v φ2 through a point off the axis, φ2 containing the axis (a parabolic net, drawn by its pencils about the vertices)",
        ).degree(),
        ParamSpec::optional(
            "curve",
            ParamKind::Points,
            "one_n only: the curve k(t) = Σ t^m curve[m], homogeneous coefficient points",
        ),
        ParamSpec::optional(
            "ruling",
            ParamKind::Points,
            "ruled_tangents only: the power coefficients of q(t) (homogeneous points) of the ruled surface X(t, v) = p(t) + v q(t); the net is the tangents along the generator t = t0 (Gruber §1.1.6: a parabolic net with axis the generator)",
        ).degree(),
        ParamSpec::with_default(
            "t0",
            ParamKind::Number,
            "0",
            "ruled_tangents only: the (non-torsal) generator t = t0",
        ),
        ParamSpec::with_default("u", ParamKind::Numbers, "[0, 1]", "the interval [u0, u1] of every strip"),
        ParamSpec::with_default("v", ParamKind::Numbers, "[0]", "the values v_k, one strip each"),
        ParamSpec::with_default("twist", ParamKind::Number, "1", "strip k follows v = v_k + twist·u (0: the lines through one point of the second generator, a fan)"),
        ParamSpec::with_default("lambda", ParamKind::Numbers, "[0, 1]", "the segment [λ0, λ1] of every line, points (1 − λ)p + λq; the points must stay finite"),
    ],
    example: r#"[[object]]
name = "line_congruence_cubic_chords"
op = "line_congruence_strips"
# chords k(u) ∨ k(u + v_k) of the twisted cubic (1, t, t², t³): order 1, class 3
congruence = "cubic_chords"
points = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
u = [-1, 1]
v = ["1/2", 1]
"#,
    build: build_strips::<Rational>,
};

fn four<T: OpScalar>(param: &'static str, p: &[Rational]) -> Result<[T; 4], OpError> {
    <[T; 4]>::try_from(arith::all_of::<T>(p)).map_err(|_| {
        OpError::param(param, format!("a homogeneous point has four coordinates [x0, x1, x2, x3], got {}", p.len()))
    })
}

fn pair<T: OpScalar>(param: &'static str, v: Option<Vec<Rational>>) -> Result<(T, T), OpError> {
    let v = v.unwrap_or_default();
    match v.as_slice() {
        [a, b] => Ok((arith::of(a), arith::of(b))),
        _ => Err(OpError::param(param, format!("an interval has two numbers, got {}", v.len()))),
    }
}

/// `line_congruence_strips` in `T`.
pub(crate) fn build_strips<T: OpScalar>(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let pts: Vec<[T; 4]> = args
        .points("points")?
        .iter()
        .map(|p| four("points", p))
        .collect::<Result<_, _>>()?;
    let n = pts.len();
    let need = |k: usize| {
        if n == k {
            Ok(())
        } else {
            Err(OpError::param("points", format!("this congruence needs {k} points, got {n}")))
        }
    };
    let spec = match args.string("congruence")? {
        "hyperbolic" => CongruenceSpec::Net(NetKind::Hyperbolic, pts),
        "elliptic" => CongruenceSpec::Net(NetKind::Elliptic, pts),
        "parabolic" => CongruenceSpec::Net(NetKind::Parabolic, pts),
        "pencil" => {
            need(4)?;
            let c = PointRow::new(pts[0].clone(), pts[1].clone())
                .map_err(|e| OpError::param("points", e.to_string()))?;
            CongruenceSpec::PencilProjectivity(c, pts[2].clone(), pts[3].clone())
        }
        "cubic_chords" => {
            need(4)?;
            CongruenceSpec::CubicChords([pts[0].clone(), pts[1].clone(), pts[2].clone(), pts[3].clone()])
        }
        "collineation" => {
            need(6)?;
            CongruenceSpec::Collineation(
                [pts[0].clone(), pts[1].clone(), pts[2].clone()],
                [pts[3].clone(), pts[4].clone(), pts[5].clone()],
            )
        }
        "pencil_bundle" => {
            need(5)?;
            CongruenceSpec::PencilBundle(core::array::from_fn(|k| pts[k].clone()))
        }
        "reguli" if !T::EXACT => {
            return Err(OpError::param("congruence", crate::float::REGULI_REFUSED));
        }
        "reguli" => {
            need(12)?;
            let r = |o: usize| -> [[T; 4]; 6] { core::array::from_fn(|k| pts[o + k].clone()) };
            CongruenceSpec::Reguli(Box::new([r(0), r(6)]))
        }
        "ruled_tangents" => {
            let ruling: Vec<[T; 4]> = args
                .get("ruling")
                .map(|_| args.points("ruling"))
                .transpose()?
                .ok_or_else(|| OpError::param("ruling", "ruled_tangents needs the ruling directions q(t)"))?
                .iter()
                .map(|p| four("ruling", p))
                .collect::<Result<_, _>>()?;
            CongruenceSpec::RuledSurfaceTangents(pts, ruling, arith::number(args, "t0")?)
        }
        _ => {
            need(2)?;
            let curve: Vec<[T; 4]> = args
                .get("curve")
                .map(|_| args.points("curve"))
                .transpose()?
                .ok_or_else(|| OpError::param("curve", "one_n needs the curve k(t)"))?
                .iter()
                .map(|p| four("curve", p))
                .collect::<Result<_, _>>()?;
            CongruenceSpec::OneN(pts[0].clone(), pts[1].clone(), curve)
        }
    };
    let u = pair("u", args.opt_numbers("u")?)?;
    let lambda = pair("lambda", args.opt_numbers("lambda")?)?;
    let v = arith::all_of::<T>(&args.opt_numbers("v")?.unwrap_or_default());
    let twist: T = arith::number(args, "twist")?;
    let d = congruence_strips(&spec, u, &v, &twist, lambda)
        .map_err(|e| OpError::param("points", e.to_string()))?;
    let geometry = Geometry::Patches(arith::exact_patches(d.patches)?);
    Ok(vec![arith::object::<T>(args, geometry, d.certificates)])
}

const LINE_CONGRUENCE_PARAMETRIZED: OpSpec = OpSpec {
    name: "line_congruence_parametrized",
    summary: "any rational two-parameter line congruence p(u, v) ∨ q(u, v), or the normal congruence of a rational surface X(u, v), drawn as ruled strips like line_congruence_strips, with its order and class (lines through a generic point / in a generic plane, by exact elimination at independent choices, certified when two choices reach the maximum: proved lower bounds, exact when they reach the Bézout bound minus the base points, docs/math/lines-and-canal.md; Pottmann and Wallner 2001 §3.2, §5.1) and its focal sheets as surfaces where they are rational (A₀ ≡ 0, A₂ ≡ 0 or a square discriminant of the focal polynomial)",
    params: &[
        ParamSpec::optional(
            "surface",
            ParamKind::Net,
            "the normal congruence of X(u, v): surface[i][j] = [W, X, Y, Z] is the homogeneous coefficient of u^i v^j (the normal line X ∨ (0, X_u × X_v) in affine terms; drawn as the segments X + λ(X_u × X_v)/W)",
        ),
        ParamSpec::optional(
            "p",
            ParamKind::Net,
            "instead of `surface`: the first point p(u, v) of every line, p[i][j] = [x0, x1, x2, x3] the coefficient of u^i v^j",
        ),
        ParamSpec::optional(
            "q",
            ParamKind::Net,
            "with `p`: the second point q(u, v) of every line (an ideal point q0 ≡ 0 gives the segments p + λq)",
        ),
        ParamSpec::with_default("u", ParamKind::Numbers, "[0, 1]", "the interval [u0, u1] of every strip"),
        ParamSpec::with_default("v", ParamKind::Numbers, "[0]", "the values v_k, one strip each"),
        ParamSpec::with_default("twist", ParamKind::Number, "0", "strip k follows v = v_k + twist·u"),
        ParamSpec::with_default("lambda", ParamKind::Numbers, "[0, 1]", "the segment [λ0, λ1] of every line, points (1 − λ)p + λq (resp. p + λq for an ideal q)"),
        ParamSpec::with_default("trials", ParamKind::Int, "3", "independent choices of point and plane for the order and class (2 to 6)"),
        ParamSpec::with_default("focal_sheets", ParamKind::Bool, "false", "also output the rational focal sheets that are surfaces over `domain`, as NAME_focal_1 and NAME_focal_2 (an error if the focal sheets are irrational; sheets that are curves or points are reported and skipped)"),
        ParamSpec::optional("domain", ParamKind::Numbers, "focal_sheets only: the rectangle [u0, u1, v0, v1] of the sheets (the sheet's weight must not vanish there)"),
    ],
    example: r#"[[object]]
name = "line_congruence_normals_paraboloid"
op = "line_congruence_parametrized"
# normals of the paraboloid of revolution z = u² + v²: order 3, class 2; focal sheets the
# axis (a curve, skipped) and the evolute surface
surface = [[[1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], [[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]], [[0, 0, 0, 1], [0, 0, 0, 0], [0, 0, 0, 0]]]
u = ["1/4", 1]
v = [0, "1/2"]
lambda = [0, "1/2"]
focal_sheets = true
domain = ["1/4", 1, 0, "1/2"]
"#,
    build: build_parametrized,
};

/// `Σ net[i][j] uⁱ vʲ` per homogeneous coordinate.
fn net_point(param: &'static str, net: &[Vec<Vec<Rational>>]) -> Result<[MPolyQ; 4], OpError> {
    let net4 = net
        .iter()
        .map(|row| row.iter().map(|pt| four(param, pt)).collect::<Result<Vec<_>, _>>())
        .collect::<Result<Vec<_>, _>>()?;
    poly_io::net_mpolys4(&net4)
}

fn build_parametrized(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let cong = match (args.get("surface"), args.get("p"), args.get("q")) {
        (Some(_), None, None) => {
            let x = net_point("surface", &args.net("surface")?)?;
            ParametrizedCongruence::normals(x).map_err(|e| OpError::param("surface", e.to_string()))?
        }
        (None, Some(_), Some(_)) => {
            let p = net_point("p", &args.net("p")?)?;
            let q = net_point("q", &args.net("q")?)?;
            ParametrizedCongruence::new(p, q).map_err(|e| OpError::param("p", e.to_string()))?
        }
        (Some(_), _, _) => return Err(OpError::param("surface", "give either `surface` or both `p` and `q`, not both")),
        _ => return Err(OpError::param("p", "give either `surface` (a normal congruence) or both `p` and `q`")),
    };
    let trials = args.int("trials")?;
    if !(2..=6).contains(&trials) {
        return Err(OpError::param("trials", format!("between 2 and 6 choices, got {trials}")));
    }
    let oc = cong
        .order_class(trials as usize)
        .map_err(|e| OpError::param("trials", e.to_string()))?;
    let sheets = cong.rational_focal_sheets();
    let u = pair("u", args.opt_numbers("u")?)?;
    let lambda = pair("lambda", args.opt_numbers("lambda")?)?;
    let v = args.opt_numbers("v")?.unwrap_or_default();
    let twist = args.number("twist")?;
    let spec = CongruenceSpec::Parametrized(Box::new(cong));
    let d = congruence_strips(&spec, u, &v, &twist, lambda).map_err(|e| OpError::param("lambda", e.to_string()))?;
    let mut certs = d.certificates;
    certs.push(oc.certificate());
    let mut main = args.object(Geometry::Patches(d.patches), certs);
    let int = |k: usize| Quantity::Integer(k as i64);
    main.values.push(NamedQuantity::new("order", "lines through a generic point", int(oc.order)));
    main.values.push(NamedQuantity::new("class", "lines in a generic plane", int(oc.class)));
    main.values.push(NamedQuantity::new("mu", "parameter points (u, v) per generic line", int(oc.mu)));
    main.values.push(NamedQuantity::new(
        "order_class_exact",
        "the counted order and class (proved lower bounds) reach the Bézout upper bound of (m + n)·μ",
        Quantity::Bool(oc.exact()),
    ));
    if let Some((m, n)) = oc.at_most() {
        main.values.push(NamedQuantity::new("order_at_most", "upper bound of the order (Bézout minus base points)", int(m)));
        main.values.push(NamedQuantity::new("class_at_most", "upper bound of the class (Bézout minus base points)", int(n)));
    }
    main.values.push(NamedQuantity::new("order_class", "order and class in words", Quantity::Text(oc.describe())));
    let mut out = vec![main];
    if args.bool("focal_sheets")? {
        let sheets = sheets.ok_or_else(|| {
            OpError::param("focal_sheets", "the focal sheets are irrational: the focal polynomial A₀ + λA₁ + λ²A₂ has no rational root (A₀, A₂ ≢ 0 and A₁² − 4A₀A₂ is not a square over Q)")
        })?;
        let dom = args
            .opt_numbers("domain")?
            .ok_or_else(|| OpError::param("domain", "focal_sheets needs the rectangle [u0, u1, v0, v1]"))?;
        let [u0, u1, v0, v1] = <[Rational; 4]>::try_from(dom.clone())
            .map_err(|_| OpError::param("domain", format!("a rectangle has four numbers [u0, u1, v0, v1], got {}", dom.len())))?;
        let curves: Vec<usize> = (0..2).filter(|k| !ParametrizedCongruence::is_surface(&sheets[*k])).collect();
        if curves.len() == 2 {
            return Err(OpError::param("focal_sheets", "both focal sheets are curves or points (a congruence of lines meeting two curves): nothing to draw as a surface"));
        }
        out[0].values.push(NamedQuantity::new(
            "focal_curves",
            "indices (1, 2) of the focal sheets that are curves or points, not drawn",
            Quantity::Vector(curves.iter().map(|k| int(k + 1)).collect()),
        ));
        for (k, f) in sheets.iter().enumerate() {
            if curves.contains(&k) {
                continue;
            }
            let (pieces, cert) = point_family_patches(f, (u0.clone(), u1.clone()), (v0.clone(), v1.clone()))
                .map_err(|e| OpError::param("domain", format!("focal sheet {}: {e}", k + 1)))?;
            let mut o = args.object(Geometry::Patches(pieces), vec![cert]);
            o.name = format!("{}_focal_{}", args.name(), k + 1);
            out.push(o);
        }
        // the focal sheets' own certificates (on the lines, focal) are part of the
        // congruence's certify(), already on the main object
    }
    Ok(out)
}
