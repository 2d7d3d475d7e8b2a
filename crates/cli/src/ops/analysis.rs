//! Ops of the `analysis` topic: questions about a given curve, answered exactly as named
//! values (`rcagd_io::quantity`) beside the curve itself.
//!
//! * `ph_analyze`: the PH test of a polynomial space curve (control points, power form
//!   or quaternion preimage), its speed `σ`, arc length, `ρ` with `deg ρ ≤ 2n − 6`, the
//!   DPH and helix tests with axis and `κ/τ`, and the exact Frenet data at given
//!   parameters (`rcagd::ph::analysis`); for a septic preimage also the ch. 7 helicity
//!   criteria (`rcagd::ph::dph_criteria`).
//! * `ph_preimage`: the quaternion preimage `A(t)` of a PH curve, `r' = A i A*`
//!   (`rcagd::ph::preimage::recover_preimage`).
//! * `ph_dph_forms`: the quaternion DPH forms of a DPH curve (`rcagd::ph::dph_forms`).
//! * `ph_qiq`: the solutions `Q(φ)` of `Q i Q* = c` (`rcagd::ph::preimage::solve_qiq_certified`).

use super::{poly_io, OpArgs, OpError, OpSpec, ParamSpec};
use crate::model::{Geometry, Object};
use crate::value::ParamKind;
use rcagd::ph::analysis::{ph_test, PhAnalysis, PhTest};
use rcagd::ph::{DphClass, DphTest, HelixTest, PhCurve};
use rcagd_algebra::quadratic::{sqrt_in_extension, QuadExt};
use rcagd_algebra::Rational;
use rcagd_geom::BezierCurve;
use rcagd_io::quantity::{NamedQuantity, Quantity};

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[PH_ANALYZE, PH_PREIMAGE, PH_QIQ, PH_DPH_FORMS];

type Q = Rational;

const PH_ANALYZE: OpSpec = OpSpec {
    name: "ph_analyze",
    summary: "answers about a polynomial space curve, exact: the PH test (|r'|² = σ²), σ, arc length, ρ = |r'×r''|²/σ² with deg ρ ≤ 2n − 6, the DPH test ρ = c·ω̃², the helix test a·r' ≡ σ with axis and (κ/τ)², the DPH class of a quaternion preimage (for degree 7 with the helicity criteria of ch. 7: Lemmas 7.1, 7.2, Props. 7.6–7.9 and Δ of (7.11)), and the Frenet frame, curvature and torsion at given parameters in Q(√ρ(t)) (Besednjak, DPH-krivulje in polinomske vijačnice, §3–4, 7)",
    params: &[
        ParamSpec::optional(
            "points",
            ParamKind::Points,
            "Bézier control points [x, y, z] of a polynomial curve on t ∈ [0, 1]",
        ).degree(),
        ParamSpec::optional(
            "power",
            ParamKind::Points,
            "instead of `points`: power-form coefficients [x_k, y_k, z_k] of t^k, k = 0, 1, …",
        ).degree(),
        ParamSpec::optional(
            "quaternions",
            ParamKind::Points,
            "instead of `points`: Bernstein coefficients [u, v, p, q] of a preimage A(t), r' = A i A* (adds the DPH class αβ' − α'β = λhW²)",
        ).degree(),
        ParamSpec::with_default(
            "start",
            ParamKind::Point3,
            "[0, 0, 0]",
            "r(0) for `quaternions`",
        ),
        ParamSpec::optional(
            "at",
            ParamKind::Numbers,
            "parameters t ∈ [0, 1] at which to give the Frenet data (point, t, p, b, κ, τ) exactly",
        ),
    ],
    example: r#"[[object]]
name = "ph_cubic_analysis"
op = "ph_analyze"
quaternions = [[1, 0, 1, 0], [0, 1, 0, 1]]
at = [0, "1/2"]
"#,
    build: build_ph_analyze,
};

const PH_PREIMAGE: OpSpec = OpSpec {
    name: "ph_preimage",
    summary: "the quaternion preimage A(t) of a PH curve, r' = A i A*, recovered exactly from its hodograph (Besednjak, DPH-krivulje in polinomske vijačnice, Remark 3.15; construction in docs/math/ph-preimage.md): Bernstein coefficients A_l = [u, v, p, q], the components u, v, p, q, σ = |A|², the content gcd(x', y', z') and the number of choices of its complex factors; every other preimage of a choice is A·(cos φ + i sin φ)",
    params: &[
        ParamSpec::optional("points", ParamKind::Points, "Bézier control points [x, y, z] of a PH curve on t ∈ [0, 1]").degree(),
        ParamSpec::optional("power", ParamKind::Points, "instead of `points`: power-form coefficients [x_k, y_k, z_k] of t^k").degree(),
        ParamSpec::optional("quaternions", ParamKind::Points, "instead of `points`: Bernstein coefficients [u, v, p, q] of some preimage (a round trip)").degree(),
        ParamSpec::with_default("start", ParamKind::Point3, "[0, 0, 0]", "r(0) for `quaternions`"),
        ParamSpec::with_default("choice", ParamKind::Int, "0", "which complex factors of the content gcd(x', y', z') go into A (0 … choices − 1)"),
        ParamSpec::optional("rotation", ParamKind::Point2, "[cos φ, sin φ] (rational, cos²φ + sin²φ = 1): the member A·(cos φ + i sin φ) of the family"),
    ],
    example: r#"[[object]]
name = "ph_cubic_preimage"
op = "ph_preimage"
points = [[0, 0, 0], [0, 0, "-2/3"], ["1/3", "2/3", -1], ["2/3", "4/3", "-1/3"]]
"#,
    build: build_ph_preimage,
};

const PH_QIQ: OpSpec = OpSpec {
    name: "ph_qiq",
    summary: "the solution Q(φ) of Q i Q* = c (Besednjak, DPH-krivulje in polinomske vijačnice, Lemma 2.1, with the branch Q = √|c|(cos φ j + sin φ k) for every c = −|c| i), exact when |c| and (|c| + c_x)/2 are rational squares; the object is the PH segment t·c with preimage Q",
    params: &[
        ParamSpec::required("c", ParamKind::Point3, "the right-hand side c ≠ 0"),
        ParamSpec::optional("rotation", ParamKind::Point2, "[cos φ, sin φ] (rational, cos²φ + sin²φ = 1); default φ = 0"),
    ],
    example: r#"[[object]]
name = "lemma_2_1_solution"
op = "ph_qiq"
c = [-1, 2, 2]
rotation = ["3/5", "4/5"]
"#,
    build: build_ph_qiq,
};

const PH_DPH_FORMS: OpSpec = OpSpec {
    name: "ph_dph_forms",
    summary: "the quaternion forms of the DPH condition of a PH curve given by its preimage (Besednjak, DPH-krivulje in polinomske vijačnice, §4.2–4.3): f, g with r'×r'' = 2A(f j + g k)A*, f + i g = h(a + ib)² (4.12), B = A·C with r'×r'' = h·B i B* (Prop. 4.6), and D with (A*A' − A'*A) × i = h̃·D i D* ((4.21), built from the Hopf form αβ' − α'β = h̃(ã + ib̃)²: docs/math/ph-preimage.md#dph-forms)",
    params: &[
        ParamSpec::required(
            "quaternions",
            ParamKind::Points,
            "Bernstein coefficients [u, v, p, q] of the preimage A(t), r' = A i A*",
        ).degree(),
        ParamSpec::with_default("start", ParamKind::Point3, "[0, 0, 0]", "r(0)"),
    ],
    example: r#"[[object]]
name = "ph_cubic_dph_forms"
op = "ph_dph_forms"
quaternions = [[1, 0, 1, 0], [0, 1, 0, 1]]
"#,
    build: build_ph_dph_forms,
};

fn build_ph_dph_forms(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let coeffs = super::ph::quaternions(args)?;
    let start = <[Q; 3]>::try_from(args.point("start")?)
        .map_err(|_| OpError::param("start", "r(0) must be [x, y, z]"))?;
    let pc = PhCurve::new(coeffs, start)?;
    let forms = rcagd::ph::dph_forms::dph_quaternion_forms(&pc)?;
    let mut certificates = pc.certify();
    certificates.extend(forms.certify());
    let values = vec![
        value("f", "f = up' − u'p + vq' − v'q", Quantity::poly_t(forms.f.clone())),
        value("g", "g = uq' − u'q − vp' + v'p", Quantity::poly_t(forms.g.clone())),
        value("h", "h of f + i g = h(a + ib)² (4.12)", Quantity::poly_t(forms.h.clone())),
        value("a", "a of (4.12)", Quantity::poly_t(forms.a.clone())),
        value("b", "b of (4.12)", Quantity::poly_t(forms.b.clone())),
        poly_io::polys_value("C", "C = −b + a i + a j + b k, components [1, i, j, k]", &forms.c),
        poly_io::polys_value("B", "B = A·C, r'×r'' = h·B i B* (Prop. 4.6)", &forms.b_quat),
        value("h_hopf", "h̃ of αβ' − α'β = h̃(ã + ib̃)²", Quantity::poly_t(forms.h_hopf.clone())),
        value("a_hopf", "ã", Quantity::poly_t(forms.a_hopf.clone())),
        value("b_hopf", "b̃", Quantity::poly_t(forms.b_hopf.clone())),
        poly_io::polys_value("D", "D = −ã + b̃ i − b̃ j − ã k, (A*A' − A'*A) × i = h̃·D i D* (4.21)", &forms.d),
    ];
    Ok(vec![args
        .object(Geometry::Curve(pc.to_bezier()?), certificates)
        .with_values(values)])
}

fn rotation(args: &OpArgs) -> Result<Option<(Q, Q)>, OpError> {
    Ok(args.opt_point("rotation")?.and_then(|v| match v.as_slice() {
        [c, s] => Some((c.clone(), s.clone())),
        _ => None,
    }))
}

fn quaternion_values(name: &str, doc: &str, a: &[rcagd_algebra::Quaternion<Q>]) -> NamedQuantity {
    value(
        name,
        doc,
        Quantity::Vector(
            a.iter()
                .map(|q| Quantity::rationals(&[q.w.clone(), q.x.clone(), q.y.clone(), q.z.clone()]))
                .collect(),
        ),
    )
}

fn build_ph_preimage(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (bez, _) = input_curve(args)?;
    let [x, y, z] = poly_io::space_polys(&bez)?;
    let choice = usize::try_from(args.int("choice")?)
        .map_err(|_| OpError::param("choice", "a choice is 0, 1, …"))?;
    let rec = rcagd::ph::preimage::recover_preimage([x, y, z], choice)?;
    let mut certificates = rec.certify();
    let curve = match rotation(args)? {
        Some((c, s)) => {
            let rotated = rec
                .rotated(&c, &s)
                .map_err(|e| OpError::param("rotation", e.to_string()))?;
            certificates.extend(rotated.certify());
            rotated
        }
        None => rec.curve.clone(),
    };
    let [u, v, p, q] = curve.preimage();
    let values = vec![
        quaternion_values(
            "quaternion_coefficients",
            "Bernstein coefficients A_l = [u, v, p, q] of A(t) = u + v i + p j + q k",
            curve.coefficients(),
        ),
        value("u", "u(t), power form", Quantity::poly_t(u)),
        value("v", "v(t)", Quantity::poly_t(v)),
        value("p", "p(t)", Quantity::poly_t(p)),
        value("q", "q(t)", Quantity::poly_t(q)),
        value("sigma", "σ = |A|² = u² + v² + p² + q²", Quantity::poly_t(curve.speed())),
        value("content", "gcd(x', y', z'), monic", Quantity::poly_t(rec.content.clone())),
        value(
            "choices",
            "number of choices of complex factors of the content",
            Quantity::Integer(rec.choices as i64),
        ),
    ];
    Ok(vec![args
        .object(Geometry::Curve(curve.to_bezier()?), certificates)
        .with_values(values)])
}

fn build_ph_qiq(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let c = <[Q; 3]>::try_from(args.point("c")?)
        .map_err(|_| OpError::param("c", "c must be [x, y, z]"))?;
    let sol = rcagd::ph::preimage::solve_qiq_certified(&c, rotation(args)?)?;
    let values = vec![
        quaternion_values("q", "Q = [w, x, y, z] = w + x i + y j + z k with Q i Q* = c", std::slice::from_ref(&sol.q)),
        value(
            "rotation",
            "[cos φ, sin φ] of the member Q(φ)",
            Quantity::rationals(&[sol.rotation.0.clone(), sol.rotation.1.clone()]),
        ),
    ];
    Ok(vec![args
        .object(Geometry::Curve(sol.segment.to_bezier()?), sol.certify())
        .with_values(values)])
}

fn value(name: &str, doc: &str, v: Quantity) -> NamedQuantity {
    NamedQuantity::new(name, doc, v)
}

fn quads(v: [QuadExt; 3]) -> Quantity {
    Quantity::Vector(v.into_iter().map(Quantity::Quadratic).collect())
}

/// The input curve as a Bézier curve and (for `quaternions`) its PH preimage.
fn input_curve(args: &OpArgs) -> Result<(BezierCurve<Q>, Option<PhCurve<Q>>), OpError> {
    let given: Vec<&str> = ["points", "power", "quaternions"]
        .into_iter()
        .filter(|p| args.get(p).is_some())
        .collect();
    match given.as_slice() {
        ["points"] => {
            let pts = args.points("points")?;
            if pts.iter().any(|p| p.len() != 3) {
                return Err(OpError::param("points", "control points must be [x, y, z]"));
            }
            Ok((BezierCurve::from_points(&pts)?, None))
        }
        ["power"] => {
            let rows = args.points("power")?;
            if rows.iter().any(|p| p.len() != 3) {
                return Err(OpError::param(
                    "power",
                    "each coefficient must be [x_k, y_k, z_k]",
                ));
            }
            let [x, y, z] = poly_io::coordinate_polys(&rows);
            let polys = [poly_io::poly_one(), x, y, z];
            let n = rows.len().saturating_sub(1).max(1);
            Ok((BezierCurve::from_coordinate_polys(&polys, n)?, None))
        }
        ["quaternions"] => {
            let coeffs = super::ph::quaternions(args)?;
            let start = <[Q; 3]>::try_from(args.point("start")?)
                .map_err(|_| OpError::param("start", "r(0) must be [x, y, z]"))?;
            let pc = PhCurve::new(coeffs, start)?;
            Ok((pc.to_bezier()?, Some(pc)))
        }
        [] => Err(OpError::new(
            "give the curve as `points`, `power` or `quaternions`",
        )),
        _ => Err(OpError::param(
            "points",
            format!(
                "give the curve once: `{}` are alternatives",
                given.join("`, `")
            ),
        )),
    }
}

fn analysis_values(a: &PhAnalysis<Q>) -> Vec<NamedQuantity> {
    let mut v = vec![
        value("ph", "|r'|² is the square of a polynomial σ", Quantity::Bool(true)),
        value(
            "sigma",
            "parametric speed σ(t) = |r'(t)|",
            Quantity::poly_t(a.curve.speed().clone()),
        ),
        value(
            "arc_length",
            "arc length on [0, 1], ∫σ",
            Quantity::Rational(a.curve.arc_length()),
        ),
        value(
            "rho",
            "ρ(t) = |r'×r''|²/σ² (κ² = ρ/σ⁴)",
            Quantity::poly_t(a.rho.clone()),
        ),
        value(
            "rho_degree_bound",
            "2n − 6, the bound on deg ρ",
            Quantity::Integer(a.rho_degree_bound() as i64),
        ),
    ];
    match &a.dph {
        DphTest::Dph(d) => {
            v.push(value(
                "dph",
                "double PH: ρ = c·ω̃² (rational Frenet frame)",
                Quantity::Text("dph".into()),
            ));
            v.push(value(
                "dph_c",
                "the constant c of ρ = c·ω̃²",
                Quantity::Rational(d.c.clone()),
            ));
            v.push(value(
                "dph_omega_tilde",
                "ω̃ of ρ = c·ω̃²",
                Quantity::poly_t(d.omega_tilde.clone()),
            ));
        }
        DphTest::NotDph { .. } => v.push(value(
            "dph",
            "ρ is not a constant times a square: not double PH",
            Quantity::Text("not dph".into()),
        )),
        DphTest::Line => v.push(value(
            "dph",
            "ρ ≡ 0: a straight line",
            Quantity::Text("line".into()),
        )),
    }
    match &a.helix {
        HelixTest::Helix(h) => {
            v.push(value(
                "helix",
                "a·r' ≡ σ has a solution a (the axis)",
                Quantity::Text("helix".into()),
            ));
            v.push(value(
                "axis",
                "a with a·r' ≡ σ, |a| = 1/cos ψ",
                Quantity::rationals(&h.a),
            ));
            v.push(value(
                "kappa_over_tau_squared",
                "(κ/τ)² = tan²ψ = |a|² − 1 (constant: Lancret)",
                Quantity::Rational(h.tan2_psi()),
            ));
            if let Ok(k) = sqrt_in_extension(&h.tan2_psi()) {
                v.push(value(
                    "kappa_over_tau",
                    "|κ/τ| = tan ψ",
                    Quantity::Quadratic(k),
                ));
            }
        }
        HelixTest::Planar { normal } => {
            v.push(value(
                "helix",
                "planar (a trivial helix, ψ = π/2)",
                Quantity::Text("planar".into()),
            ));
            v.push(value(
                "plane_normal",
                "n with n·r' ≡ 0",
                Quantity::rationals(normal),
            ));
        }
        HelixTest::Line => v.push(value(
            "helix",
            "a straight line",
            Quantity::Text("line".into()),
        )),
        HelixTest::NotHelix => v.push(value(
            "helix",
            "a·r' ≡ σ has no solution: not a helix",
            Quantity::Text("not a helix".into()),
        )),
    }
    v
}

/// The ch. 7 helicity criteria of a DPH septic as values.
fn chapter7_values(c: &rcagd::ph::dph_criteria::SepticDphCriteria) -> Vec<NamedQuantity> {
    let mut v = vec![
        value(
            "ch7_statement",
            "the statement of Besednjak ch. 7 that decides helicity",
            Quantity::Text(c.statement.citation().into()),
        ),
        value(
            "ch7_gcd_degree",
            "r = deg gcd(α, β)",
            Quantity::Integer(c.gcd_degree as i64),
        ),
        value(
            "ch7_helical",
            "the verdict of the ch. 7 criterion",
            Quantity::Bool(c.helical),
        ),
    ];
    if let Some(d) = &c.delta {
        v.push(value(
            "ch7_delta",
            "Δ = 9h₂² + 3h₀h₄ − 12h₁h₃ (7.11), h monic; helical iff Δ ≥ 0 (Prop. 7.9)",
            Quantity::Rational(d.clone()),
        ));
    }
    if let Some(r) = c.w_roots_real_or_conjugate {
        v.push(value(
            "ch7_w_roots_real_or_conjugate",
            "the roots of w are both real or conjugate (Lemma 7.5)",
            Quantity::Bool(r),
        ));
    }
    v
}

fn frenet_values(a: &PhAnalysis<Q>, ts: &[Q]) -> Result<Vec<NamedQuantity>, OpError> {
    let mut v = Vec::new();
    for (k, t) in ts.iter().enumerate() {
        if *t < Q::from(0) || *t > Q::from(1) {
            return Err(OpError::param(
                "at",
                format!("t = {t} is outside the curve's parameter domain [0, 1]"),
            ));
        }
        let f = a
            .frenet_at(t)
            .map_err(|e| OpError::param("at", format!("at t = {t}: {e}")))?;
        let tag = |s: &str| format!("{s}_{k}");
        v.push(value(&tag("t"), "the parameter", Quantity::Rational(t.clone())));
        v.push(value(&tag("point"), "r(t)", Quantity::rationals(&f.point)));
        v.push(value(
            &tag("tangent"),
            "unit tangent r'/σ",
            Quantity::rationals(&f.tangent),
        ));
        v.push(value(
            &tag("normal"),
            "principal normal (σr'' − σ'r')/(σ√ρ)",
            quads(f.normal_exact()?),
        ));
        v.push(value(
            &tag("binormal"),
            "binormal (r'×r'')/(σ√ρ)",
            quads(f.binormal_exact()?),
        ));
        v.push(value(
            &tag("curvature"),
            "κ = √ρ/σ²",
            Quantity::Quadratic(f.curvature_exact()?),
        ));
        v.push(value(
            &tag("torsion"),
            "τ = (r'×r'')·r'''/(σ²ρ)",
            Quantity::Rational(f.torsion.clone()),
        ));
    }
    Ok(v)
}

fn build_ph_analyze(args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let (bez, preimage) = input_curve(args)?;
    let [x, y, z] = poly_io::space_polys(&bez)?;
    let test = ph_test([x, y, z])?;
    let mut certificates = test.certify();
    let values = match &test {
        PhTest::NotPh { speed_squared } => vec![
            value(
                "ph",
                "|r'|² is the square of a polynomial σ",
                Quantity::Bool(false),
            ),
            value(
                "speed_squared",
                "|r'(t)|², not a perfect square",
                Quantity::poly_t(speed_squared.clone()),
            ),
        ],
        PhTest::Ph(a) => {
            let mut values = analysis_values(a);
            if let Some(pc) = &preimage {
                let class = match pc.classify()? {
                    DphClass::NotDph => "not dph".to_string(),
                    DphClass::Line => "line".to_string(),
                    DphClass::Dph {
                        h_degree,
                        w_degree,
                        helical,
                    } => format!(
                        "dph, st h = {h_degree}, st w = {w_degree}, {}",
                        if helical { "helical" } else { "not helical" }
                    ),
                };
                values.push(value(
                    "dph_class",
                    "αβ' − α'β = λ·h·W² with st h, st W and helicity (Besednjak §4.3, ch. 7)",
                    Quantity::Text(class),
                ));
                certificates.extend(pc.certify());
                if pc.preimage_degree() == 3 && matches!(a.dph, DphTest::Dph(_)) {
                    if let Ok(c) = rcagd::ph::dph_criteria::septic_dph_criteria(pc) {
                        values.extend(chapter7_values(&c));
                        certificates.extend(c.certify());
                    }
                }
                // Lemma 7.2 whenever r = deg gcd(α, β) = 1 (DPH or not)
                if let Ok(l) = rcagd::ph::dph_criteria::lemma_7_2(pc) {
                    values.push(value(
                        "reduced_wronskian_discriminant",
                        "discriminant of α̃β̃' − α̃'β̃ (α = γα̃, β = γβ̃, deg γ = 1); Besednjak Lemma 7.2: never c·(t − τ)², so h is not constant or a square",
                        Quantity::Vector(vec![
                            Quantity::Rational(l.discriminant.re.clone()),
                            Quantity::Rational(l.discriminant.im.clone()),
                        ]),
                    ));
                    certificates.push(l.certify());
                }
            }
            if let Some(ts) = args.opt_numbers("at")? {
                values.extend(frenet_values(a, &ts)?);
            }
            values
        }
    };
    Ok(vec![args
        .object(Geometry::Curve(bez), certificates)
        .with_values(values)])
}
