//! JSON output of objects (DESIGN.md, "The user-facing contract").
//!
//! One object becomes
//!
//! ```json
//! {
//!   "name": "quarter", "op": "circle_arc", "kind": "curve",
//!   "degree": 2, "dim": 2, "pieces": 1, "control_point_count": 3,
//!   "coordinates": ["w", "wx", "wy"],
//!   "control_points": [["1", "1", "0"], ["1", "1", "1"], ["2", "0", "2"]],
//!   "control_points_f64": [[1.0, 1.0, 0.0], [1.0, 1.0, 1.0], [2.0, 0.0, 2.0]],
//!   "certificates": [{"property": "…", "holds": true, "exact": true, "residual": null}],
//!   "all_certificates_hold": true,
//!   "params": { … },
//!   "values": [{"name": "arc_length", "doc": "…", "type": "rational", "exact": "7/3", "f64": 2.3333333333333335}]
//! }
//! ```
//!
//! Control points are homogeneous (weight first), exact strings `"p/q"` (or `"p"`) and
//! their correctly rounded floats. Shapes by kind:
//! * `curve`: `degree` is `n`, `control_points` a list of points;
//! * `curves`: `degree` a list of `n`s, `control_points` a list of point lists;
//! * `patch`: `degree` is `[m, n]`, `control_points` the net, rows along `u`
//!   (`control_points[i][j]` is `Pᵢⱼ`);
//! * `patches`: `degree` a list of `[m, n]`, `control_points` a list of nets.
//!
//! `values` lists the named exact values the op computed besides the geometry
//! ([`crate::quantity`]): each `{"name", "doc", "type", "exact", "f64"}` with `type` one
//! of `bool`, `integer`, `text`, `rational`, `quadratic` (`a + b√d`, with `a`, `b`, `d`),
//! `polynomial` (`variable`, `degree`, `power` and `bernstein` coefficients on
//! `[0, 1]`), `real_root` (`polynomial`, isolating `interval`) and `vector` (`items`).

use crate::model::{Geometry, Object};
use crate::quantity::NamedQuantity;
use rcagd_algebra::rational::format_rational;
use rcagd_algebra::{Certificate, Rational, Scalar};
use rcagd_geom::{BezierCurve, BezierPatch};
use serde_json::{json, Value};

/// An exact rational as a JSON string `"p/q"` (or `"p"`).
pub fn rational_to_json(q: &Rational) -> Value {
    Value::String(format_rational(q))
}

/// A float as JSON (`null` for NaN or infinities, which JSON cannot represent).
pub fn f64_to_json(x: f64) -> Value {
    serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number)
}

fn point_exact(p: &[Rational]) -> Value {
    Value::Array(p.iter().map(rational_to_json).collect())
}

fn point_f64(p: &[Rational]) -> Value {
    Value::Array(p.iter().map(|x| f64_to_json(Scalar::to_f64(x))).collect())
}

fn curve_points(c: &BezierCurve<Rational>, f: fn(&[Rational]) -> Value) -> Value {
    Value::Array(c.control_points().map(f).collect())
}

fn patch_net(p: &BezierPatch<Rational>, f: fn(&[Rational]) -> Value) -> Value {
    let (m, n) = p.degree();
    Value::Array(
        (0..=m)
            .map(|i| Value::Array((0..=n).map(|j| f(p.control_point(i, j))).collect()))
            .collect(),
    )
}

fn geometry_points(g: &Geometry, f: fn(&[Rational]) -> Value) -> Value {
    match g {
        Geometry::Curve(c) => curve_points(c, f),
        Geometry::Curves(cs) => Value::Array(cs.iter().map(|c| curve_points(c, f)).collect()),
        Geometry::Patch(p) => patch_net(p, f),
        Geometry::Patches(ps) => Value::Array(ps.iter().map(|p| patch_net(p, f)).collect()),
    }
}

/// The `degree` field: `n`, `[m, n]`, or a list of those for several pieces.
pub fn degree_json(g: &Geometry) -> Value {
    let patch_deg = |p: &BezierPatch<Rational>| {
        let (m, n) = p.degree();
        json!([m, n])
    };
    match g {
        Geometry::Curve(c) => json!(c.degree()),
        Geometry::Curves(cs) => Value::Array(cs.iter().map(|c| json!(c.degree())).collect()),
        Geometry::Patch(p) => patch_deg(p),
        Geometry::Patches(ps) => Value::Array(ps.iter().map(patch_deg).collect()),
    }
}

/// The names of the homogeneous coordinates: `["w", "wx", "wy"]` in the plane,
/// `["w", "wx", "wy", "wz"]` in space, `"wx4"`… beyond.
pub fn coordinate_names(dim: usize) -> Value {
    let mut names = vec![Value::String("w".into())];
    for k in 0..dim {
        let n = match k {
            0 => "wx".to_string(),
            1 => "wy".to_string(),
            2 => "wz".to_string(),
            _ => format!("wx{}", k + 1),
        };
        names.push(Value::String(n));
    }
    Value::Array(names)
}

/// One certificate as `{property, holds, exact, residual}`.
pub fn certificate_to_json(c: &Certificate) -> Value {
    json!({
        "property": c.property,
        "holds": c.holds,
        "exact": c.exact,
        "residual": c.residual,
    })
}

/// All certificates.
pub fn certificates_to_json(certs: &[Certificate]) -> Value {
    Value::Array(certs.iter().map(certificate_to_json).collect())
}

/// The summary of an object without its control points (used by the report):
/// `name, op, kind, degree, degree_summary, dim, pieces, control_point_count,
/// certificates, all_certificates_hold, params`.
pub fn object_summary_json(o: &Object) -> Value {
    json!({
        "name": o.name,
        "op": o.op,
        "kind": o.kind(),
        "degree": degree_json(&o.geometry),
        "degree_summary": o.degree_summary(),
        "dim": o.geometry.dim(),
        "pieces": o.geometry.piece_count(),
        "control_point_count": o.control_point_count(),
        "certificates": certificates_to_json(&o.certificates),
        "all_certificates_hold": o.all_certificates_hold(),
        "params": o.params,
        "values": Value::Array(o.values.iter().map(NamedQuantity::to_json).collect()),
    })
}

/// The full JSON of an object (module docs): the summary plus `coordinates`,
/// `control_points` (exact strings) and `control_points_f64`.
pub fn object_to_json(o: &Object) -> Value {
    let mut v = object_summary_json(o);
    if let Value::Object(map) = &mut v {
        map.insert("coordinates".into(), coordinate_names(o.geometry.dim()));
        map.insert(
            "control_points".into(),
            geometry_points(&o.geometry, point_exact),
        );
        map.insert(
            "control_points_f64".into(),
            geometry_points(&o.geometry, point_f64),
        );
    }
    v
}

/// Several objects: `{"objects": [...], "all_certificates_hold": bool}`.
pub fn objects_to_json(objects: &[Object]) -> Value {
    json!({
        "objects": objects.iter().map(object_to_json).collect::<Vec<_>>(),
        "all_certificates_hold": objects.iter().all(Object::all_certificates_hold),
    })
}

/// Pretty-printed JSON text of several objects (see [`objects_to_json`]).
pub fn objects_to_json_string(objects: &[Object]) -> Result<String, crate::IoError> {
    Ok(serde_json::to_string_pretty(&objects_to_json(objects))?)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    #[test]
    fn exact_strings_and_floats() {
        assert_eq!(rational_to_json(&q(-3, 6)), json!("-1/2"));
        assert_eq!(rational_to_json(&q(4, 2)), json!("2"));
        assert_eq!(f64_to_json(f64::NAN), Value::Null);
        assert_eq!(coordinate_names(3), json!(["w", "wx", "wy", "wz"]));
    }

    #[test]
    fn curve_object_snapshot() {
        let c = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(1, 1), q(0, 1)],
            vec![q(1, 1), q(1, 1), q(1, 3)],
        ])
        .expect("valid");
        let o = Object::new(
            "seg",
            "test",
            json!({"a": "1/3"}),
            Geometry::Curve(c),
            vec![Certificate::fails("p", "r", true)],
        );
        let got = serde_json::to_string(&object_to_json(&o)).expect("json");
        let want = r#"{"all_certificates_hold":false,"certificates":[{"exact":true,"holds":false,"property":"p","residual":"r"}],"control_point_count":2,"control_points":[["1","1","0"],["1","1","1/3"]],"control_points_f64":[[1.0,1.0,0.0],[1.0,1.0,0.3333333333333333]],"coordinates":["w","wx","wy"],"degree":1,"degree_summary":"degree 1","dim":2,"kind":"curve","name":"seg","op":"test","params":{"a":"1/3"},"pieces":1,"values":[]}"#;
        assert_eq!(got, want);
    }
}
