//! Ops of the `line_congruence` topic: line nets and congruences of order one drawn as
//! ruled strips (`rcagd::lines::congruence_strips`; D. Gruber, "Rationale
//! Parametrisierungen von Kugelhüllflächen", 2008, §1.1.6–1.1.8).

use super::{OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use rcagd::lines::{congruence_strips, CongruenceSpec, NetKind, PointRow};
use rcagd_algebra::Rational;

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[LINE_CONGRUENCE_STRIPS];

const LINE_CONGRUENCE_STRIPS: OpSpec = OpSpec {
    name: "line_congruence_strips",
    summary: "a line net or congruence of order one (net by its axes, pencil of planes with a projectivity, chords of a twisted cubic, joins of a plane collineation, (1, n)-congruence of a line and a curve) drawn as ruled strips: the lines p(u, v) ∨ q(u, v) along v = v_k + twist·u, cut to the segments (1 − λ)p + λq; the congruence is certified (Klein quadric, complexes, fibration, order, class, focal sheets)",
    params: &[
        ParamSpec::required(
            "congruence",
            ParamKind::Choice(&["hyperbolic", "elliptic", "parabolic", "pencil", "cubic_chords", "collineation", "one_n", "ruled_tangents"]),
            "the congruence type",
        ),
        ParamSpec::required(
            "points",
            ParamKind::Points,
            "homogeneous points [x0, x1, x2, x3] (weight first): nets c0, c1, d0, d1 (axes c0 + u c1, d0 + v d1; parabolic: lines through c(u) to d0 + u d1 + v c1) or Re c0, Im c0, Re c1, Im c1 (elliptic); pencil c0, c1, e0, e1 (the point c0 + u c1 of the axis is mapped to the plane e0 + u e1 through it; lines through c(u) in that plane: a parabolic net); cubic_chords a0, a1, a2, a3 of k(t) = a0 + t a1 + t² a2 + t³ a3 (chord k(u) ∨ k(v)); collineation a0, a1, a2, b0, b1, b2 (κ(x0 a0 + x1 a1 + x2 a2) = x0 b0 + x1 b1 + x2 b2, lines x(u, v) ∨ κ(x(u, v)) with x = a0 + u a1 + v a2); one_n g0, g1 of the focal line (lines k(u) ∨ (g0 + v g1)); ruled_tangents: the power coefficients of p(t) (see `ruling`) of the ruled surface X(t, v) = p(t) + v q(t)",
        ),
        ParamSpec::optional(
            "curve",
            ParamKind::Points,
            "one_n only: the curve k(t) = Σ t^m curve[m], homogeneous coefficient points",
        ),
        ParamSpec::optional(
            "ruling",
            ParamKind::Points,
            "ruled_tangents only: the power coefficients of q(t) (homogeneous points) of the ruled surface X(t, v) = p(t) + v q(t); the net is the tangents along the generator t = t0 (Gruber §1.1.6: a parabolic net with axis the generator)",
        ),
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
    build: build_strips,
};

fn four(param: &'static str, p: &[Rational]) -> Result<[Rational; 4], OpError> {
    <[Rational; 4]>::try_from(p.to_vec()).map_err(|_| {
        OpError::param(param, format!("a homogeneous point has four coordinates [x0, x1, x2, x3], got {}", p.len()))
    })
}

fn pair(param: &'static str, v: Option<Vec<Rational>>) -> Result<(Rational, Rational), OpError> {
    let v = v.unwrap_or_default();
    match v.as_slice() {
        [a, b] => Ok((a.clone(), b.clone())),
        _ => Err(OpError::param(param, format!("an interval has two numbers, got {}", v.len()))),
    }
}

fn build_strips(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let pts: Vec<[Rational; 4]> = args
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
        "ruled_tangents" => {
            let ruling: Vec<[Rational; 4]> = args
                .get("ruling")
                .map(|_| args.points("ruling"))
                .transpose()?
                .ok_or_else(|| OpError::param("ruling", "ruled_tangents needs the ruling directions q(t)"))?
                .iter()
                .map(|p| four("ruling", p))
                .collect::<Result<_, _>>()?;
            CongruenceSpec::RuledSurfaceTangents(pts, ruling, args.number("t0")?)
        }
        _ => {
            need(2)?;
            let curve: Vec<[Rational; 4]> = args
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
    let v = args.opt_numbers("v")?.unwrap_or_default();
    let twist = args.number("twist")?;
    let d = congruence_strips(&spec, u, &v, &twist, lambda)
        .map_err(|e| OpError::param("points", e.to_string()))?;
    Ok(vec![args.object(Geometry::Patches(d.patches), d.certificates)])
}
