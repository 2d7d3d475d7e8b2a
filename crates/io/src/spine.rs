//! Spine curves for sweeps and pipes, read from files: STEP and IGES (every rational
//! B-spline curve of the file, split into its Bézier pieces, the curves chained end to end)
//! and exact JSON (rcagd's own curve objects, control points as exact `"p/q"` strings).
//!
//! * STEP (`.step`, `.stp`, `.p21`): [`crate::step_read::read_step`]; if the exact sidecar
//!   `NAME.exact.json` of an rcagd export lies beside the file, its exact values replace
//!   the file's decimals ([`crate::step_read::apply_sidecar`]).
//! * IGES (`.igs`, `.iges`): [`crate::iges_read::read_iges`], with the exact sidecar as for
//!   STEP. Without a sidecar the numbers are the file's decimals: a PH spine rounded to
//!   decimals is no longer PH, and its pipe then needs a quadratic field or more.
//! * JSON (`.json`): one rcagd object (`"kind": "curve"` or `"curves"`, homogeneous
//!   `"control_points"`), a list of them, or `{"objects": [...]}` as `rcagd build --format
//!   json` writes it; every curve object is used.
//!
//! Every number is read exactly (the decimal `0.1` is `1/10`). The curves are chained in
//! file order: each next curve is the remaining one with an end nearest to the current end
//! of the chain, reversed if needed ([`chain_curves`]); whether consecutive pieces meet is
//! for the caller to certify (exactly: their end points are rational).

use crate::IoError;
use rcagd_algebra::{parse_rational, Rational, Scalar};
use rcagd_geom::nurbs::NurbsCurve;
use rcagd_geom::BezierCurve;
use serde_json::Value;
use std::path::Path;

/// The file formats [`read_spine`] accepts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpineFormat {
    /// ISO 10303-21.
    Step,
    /// IGES 5.3.
    Iges,
    /// rcagd's exact JSON.
    Json,
}

impl SpineFormat {
    /// The format of a file name by its extension (case-insensitive).
    pub fn of_path(path: &Path) -> Option<Self> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "step" | "stp" | "p21" => Some(SpineFormat::Step),
            "igs" | "iges" => Some(SpineFormat::Iges),
            "json" => Some(SpineFormat::Json),
            _ => None,
        }
    }
}

fn no_curves(what: &str) -> IoError {
    IoError::NoSpineCurves(what.to_string())
}

/// The Bézier pieces of the curves of a file, in E3, chained (module docs).
///
/// # Errors
/// [`IoError::Read`] for a file that cannot be read or parsed (naming the file);
/// [`IoError::NoSpineCurves`] if it has no curve; [`IoError::Invalid`] for an unknown
/// extension or a curve outside E3.
pub fn read_spine(path: &Path) -> Result<Vec<BezierCurve<Rational>>, IoError> {
    let format = SpineFormat::of_path(path).ok_or_else(|| {
        IoError::Invalid(format!(
            "spine file {}: unknown extension (use .step, .stp, .igs, .iges or .json)",
            path.display()
        ))
    })?;
    let text = std::fs::read_to_string(path).map_err(|e| IoError::Read {
        format: "spine file",
        line: None,
        entity: None,
        message: format!("cannot read {}: {e}", path.display()),
    })?;
    let sidecar = if format != SpineFormat::Json {
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("");
        let side = path.with_file_name(format!("{stem}.exact.json"));
        std::fs::read_to_string(side)
            .ok()
            .and_then(|t| serde_json::from_str::<Value>(&t).ok())
    } else {
        None
    };
    let curves = spine_from_text(&text, format, sidecar.as_ref()).map_err(|e| match e {
        IoError::NoSpineCurves(_) => no_curves(&path.display().to_string()),
        other => other,
    })?;
    Ok(curves)
}

/// As [`read_spine`] for the text of a file of the given format (and the exact sidecar of
/// a STEP or IGES file, if any).
///
/// # Errors
/// As [`read_spine`].
pub fn spine_from_text(
    text: &str,
    format: SpineFormat,
    sidecar: Option<&Value>,
) -> Result<Vec<BezierCurve<Rational>>, IoError> {
    let nurbs: Vec<NurbsCurve<Rational>> = match format {
        SpineFormat::Step => {
            let mut objs = crate::step_read::read_step(text)?;
            if let Some(s) = sidecar {
                crate::step_read::apply_sidecar(&mut objs, s)?;
            }
            objs.into_iter().flat_map(|o| o.curves).collect()
        }
        SpineFormat::Iges => {
            let mut objs = crate::iges_read::read_iges(text)?;
            if let Some(s) = sidecar {
                crate::step_read::apply_sidecar(&mut objs, s)?;
            }
            objs.into_iter().flat_map(|o| o.curves).collect()
        }
        SpineFormat::Json => {
            let v: Value = serde_json::from_str(text).map_err(|e| IoError::Read {
                format: "JSON",
                line: Some(e.line()),
                entity: None,
                message: e.to_string(),
            })?;
            return chain_curves(json_curves(&v)?);
        }
    };
    let mut curves = Vec::new();
    for c in &nurbs {
        let pieces = c.to_bezier_pieces()?;
        // one chain element per NURBS curve: its pieces in order
        curves.push(pieces.into_iter().map(|p| p.curve).collect::<Vec<_>>());
    }
    let flat = chain_groups(curves)?;
    if flat.is_empty() {
        return Err(no_curves("the file"));
    }
    Ok(flat)
}

fn json_err(message: String) -> IoError {
    IoError::Read {
        format: "JSON",
        line: None,
        entity: None,
        message,
    }
}

fn exact(v: &Value) -> Result<Rational, IoError> {
    match v {
        Value::String(s) => {
            parse_rational(s).map_err(|e| json_err(format!("not an exact number: {s:?} ({e})")))
        }
        Value::Number(n) => parse_rational(&n.to_string())
            .map_err(|e| json_err(format!("not an exact number: {n} ({e})"))),
        other => Err(json_err(format!("expected a number, got {other}"))),
    }
}

fn json_curve(points: &Value) -> Result<BezierCurve<Rational>, IoError> {
    let pts = points
        .as_array()
        .ok_or_else(|| json_err("control_points must be a list of points".into()))?;
    let hom: Vec<Vec<Rational>> = pts
        .iter()
        .map(|p| {
            p.as_array()
                .ok_or_else(|| json_err("a control point must be a list [w, wx, wy, wz]".into()))?
                .iter()
                .map(exact)
                .collect::<Result<Vec<_>, _>>()
        })
        .collect::<Result<_, _>>()?;
    let c = BezierCurve::from_homogeneous(hom)?;
    if c.dim() != 3 {
        return Err(IoError::Invalid(format!(
            "a spine curve must lie in E3 (points [w, wx, wy, wz]), got dimension {}",
            c.dim()
        )));
    }
    Ok(c)
}

/// The curves of rcagd JSON objects (module docs), in order.
fn json_curves(v: &Value) -> Result<Vec<BezierCurve<Rational>>, IoError> {
    let objects: Vec<&Value> = match v {
        Value::Array(a) => a.iter().collect(),
        Value::Object(m) => match m.get("objects") {
            Some(Value::Array(a)) => a.iter().collect(),
            _ => vec![v],
        },
        _ => Vec::new(),
    };
    let mut out = Vec::new();
    for o in objects {
        let kind = o.get("kind").and_then(Value::as_str).unwrap_or("");
        let Some(cp) = o.get("control_points") else {
            continue;
        };
        match kind {
            "curve" => out.push(json_curve(cp)?),
            "curves" => {
                for c in cp.as_array().into_iter().flatten() {
                    out.push(json_curve(c)?);
                }
            }
            _ => {}
        }
    }
    if out.is_empty() {
        return Err(no_curves("the JSON"));
    }
    Ok(out)
}

fn end_point(c: &BezierCurve<Rational>, last: bool) -> Option<[f64; 3]> {
    let h = c.control_point(if last { c.degree() } else { 0 });
    let w = Scalar::to_f64(h.first()?);
    if w == 0.0 {
        return None;
    }
    Some(core::array::from_fn(|k| {
        h.get(k + 1).map_or(0.0, Scalar::to_f64) / w
    }))
}

fn dist(p: Option<[f64; 3]>, q: Option<[f64; 3]>) -> f64 {
    match (p, q) {
        (Some(p), Some(q)) => {
            ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
        }
        _ => f64::INFINITY,
    }
}

fn reversed(c: &BezierCurve<Rational>) -> Result<BezierCurve<Rational>, IoError> {
    let pts: Vec<Vec<Rational>> = c.control_points().rev().map(<[Rational]>::to_vec).collect();
    Ok(BezierCurve::from_homogeneous(pts)?)
}

/// Chains curves end to end: starting with the first, each next one is the remaining curve
/// with an end nearest to the current end of the chain (reversed if its end is nearer
/// than its start). Single curves are chain elements of one piece.
///
/// # Errors
/// Geometry failures only.
pub fn chain_curves(
    curves: Vec<BezierCurve<Rational>>,
) -> Result<Vec<BezierCurve<Rational>>, IoError> {
    chain_groups(curves.into_iter().map(|c| vec![c]).collect())
}

fn chain_groups(
    mut groups: Vec<Vec<BezierCurve<Rational>>>,
) -> Result<Vec<BezierCurve<Rational>>, IoError> {
    groups.retain(|g| !g.is_empty());
    if groups.is_empty() {
        return Ok(Vec::new());
    }
    let mut chain = groups.remove(0);
    while !groups.is_empty() {
        let end = chain.last().and_then(|c| end_point(c, true));
        let mut best: Option<(f64, usize, bool)> = None;
        for (k, g) in groups.iter().enumerate() {
            let start = g.first().and_then(|c| end_point(c, false));
            let stop = g.last().and_then(|c| end_point(c, true));
            for (d, rev) in [(dist(end, start), false), (dist(end, stop), true)] {
                if best.is_none_or(|(bd, _, _)| d < bd) {
                    best = Some((d, k, rev));
                }
            }
        }
        let Some((_, k, rev)) = best else { break };
        let g = groups.remove(k);
        if rev {
            for c in g.iter().rev() {
                chain.push(reversed(c)?);
            }
        } else {
            chain.extend(g);
        }
    }
    Ok(chain)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Geometry, Object};

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    fn arc() -> BezierCurve<Rational> {
        // the quarter circle (1 − t², 2t, 0)/(1 + t²) in E3
        BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(1, 1), q(0, 1), q(0, 1)],
            vec![q(1, 1), q(1, 1), q(1, 1), q(0, 1)],
            vec![q(2, 1), q(0, 1), q(2, 1), q(1, 3)],
        ])
        .expect("curve")
    }

    fn line(p: [i64; 3], r: [i64; 3]) -> BezierCurve<Rational> {
        BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(p[0], 1), q(p[1], 1), q(p[2], 1)],
            vec![q(1, 1), q(r[0], 1), q(r[1], 1), q(r[2], 1)],
        ])
        .expect("line")
    }

    fn object(name: &str, g: Geometry) -> Object {
        Object::new(name, "test", serde_json::json!({}), g, Vec::new())
    }

    #[test]
    fn json_step_and_iges_give_the_exact_curve() {
        let c = arc();
        let objs = vec![object("spine", Geometry::Curve(c.clone()))];
        let json = crate::json::objects_to_json(&objs).to_string();
        let from_json = spine_from_text(&json, SpineFormat::Json, None).expect("json");
        assert_eq!(from_json, vec![c.clone()]);
        let step = crate::step::write_step(&objs).expect("step");
        let side = crate::step::exact_sidecar(&objs).expect("sidecar");
        let from_step = spine_from_text(&step, SpineFormat::Step, Some(&side)).expect("step");
        assert_eq!(from_step.len(), 1);
        // the same curve up to the exported (balanced) parametrization: same end points
        for last in [false, true] {
            assert_eq!(end_point(&from_step[0], last), end_point(&c, last));
        }
        let iges = crate::iges::write_iges(&objs).expect("iges");
        let from_iges = spine_from_text(&iges, SpineFormat::Iges, None).expect("iges");
        assert_eq!(from_iges.len(), 1);
    }

    #[test]
    fn curves_are_chained_and_a_file_without_curves_is_named() {
        // three segments given out of order and one reversed
        let segs = vec![
            line([0, 0, 0], [1, 0, 0]),
            line([2, 1, 0], [1, 0, 0]),
            line([2, 1, 0], [2, 2, 1]),
        ];
        let chain = chain_curves(segs).expect("chain");
        let ends: Vec<_> = chain
            .iter()
            .map(|c| (end_point(c, false), end_point(c, true)))
            .collect();
        assert_eq!(ends[1].0, Some([1.0, 0.0, 0.0]));
        assert_eq!(ends[1].1, Some([2.0, 1.0, 0.0]));
        assert_eq!(ends[2].1, Some([2.0, 2.0, 1.0]));
        let patch = rcagd_geom::BezierPatch::from_homogeneous(vec![
            vec![
                vec![q(1, 1), q(0, 1), q(0, 1), q(0, 1)],
                vec![q(1, 1), q(1, 1), q(0, 1), q(0, 1)],
            ],
            vec![
                vec![q(1, 1), q(0, 1), q(1, 1), q(0, 1)],
                vec![q(1, 1), q(1, 1), q(1, 1), q(1, 1)],
            ],
        ])
        .expect("patch");
        let objs = vec![object("p", Geometry::Patch(patch))];
        let json = crate::json::objects_to_json(&objs).to_string();
        assert!(matches!(
            spine_from_text(&json, SpineFormat::Json, None),
            Err(IoError::NoSpineCurves(_))
        ));
        let step = crate::step::write_step(&objs).expect("step");
        assert!(matches!(
            spine_from_text(&step, SpineFormat::Step, None),
            Err(IoError::NoSpineCurves(_))
        ));
    }

    /// A STEP file written by OpenCascade: its spine is a TRIMMED_CURVE of a cubic
    /// B_SPLINE_CURVE_WITH_KNOTS (three spans); trimmed to the whole curve, and to a part of
    /// it by PARAMETER_VALUEs.
    #[test]
    fn trimmed_bspline_of_opencascade() {
        let text = include_str!("../../../examples/spines/bspline_spine.step");
        let whole = spine_from_text(text, SpineFormat::Step, None).expect("whole");
        assert_eq!(whole.len(), 3);
        let first = whole[0].eval(&Rational::ZERO).expect("start");
        assert_eq!(first, vec![Rational::ZERO, Rational::ZERO, Rational::ZERO]);
        let part = text
            .replace("PARAMETER_VALUE(0.)", "PARAMETER_VALUE(0.5)")
            .replace("PARAMETER_VALUE(3.)", "PARAMETER_VALUE(2.5)");
        let cut = spine_from_text(&part, SpineFormat::Step, None).expect("part");
        assert_eq!(cut.len(), 3);
        let half = Rational::from_parts(1.into(), 2u8.into());
        let start = cut[0].eval(&Rational::ZERO).expect("start");
        let end = cut[2].eval(&Rational::ONE).expect("end");
        let (s_at, e_at) = (
            whole[0].eval(&half).expect("s"),
            whole[2].eval(&half).expect("e"),
        );
        // the chain may run either way
        assert!(
            (start == s_at && end == e_at) || (start == e_at && end == s_at),
            "{start:?} {end:?}"
        );
        let bad = text.replace("PARAMETER_VALUE(3.)", "PARAMETER_VALUE(4.)");
        let e = spine_from_text(&bad, SpineFormat::Step, None).expect_err("outside");
        assert!(e.to_string().contains("outside the basis curve"), "{e}");
    }
}
