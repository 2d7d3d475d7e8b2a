//! Snapshot-style and structural tests of the exporters on a tiny curve and patch.

use rcagd_algebra::{Certificate, Rational, Scalar};
use rcagd_geom::{BezierCurve, BezierPatch};
use rcagd_io::json::{object_summary_json, objects_to_json_string};
use rcagd_io::obj::{mesh_to_obj, polylines_to_obj};
use rcagd_io::report::{report_html, report_json};
use rcagd_io::{
    curves_svg, geometry_svg, object_svg, object_to_json, objects_to_json, patches_svg,
    write_report, Geometry, Object, PatchStyle, ReportEntry, SvgOptions,
};
use serde_json::json;

fn q(p: i64, d: i64) -> Rational {
    Rational::from_ratio(p, d)
}

/// The unit quarter circle, homogeneous (1,1,0), (1,1,1), (2,0,2).
fn quarter() -> BezierCurve<Rational> {
    BezierCurve::from_homogeneous(vec![
        vec![q(1, 1), q(1, 1), q(0, 1)],
        vec![q(1, 1), q(1, 1), q(1, 1)],
        vec![q(2, 1), q(0, 1), q(2, 1)],
    ])
    .expect("valid")
}

/// A quarter cylinder x² + y² = 1, 0 ≤ z ≤ 1, bidegree (2, 1).
fn quarter_cylinder() -> BezierPatch<Rational> {
    let arc = [[1, 1, 0], [1, 1, 1], [2, 0, 2]];
    let net = arc
        .iter()
        .map(|h| {
            (0..2)
                .map(|j| vec![q(h[0], 1), q(h[1], 1), q(h[2], 1), q(h[0] * j, 1)])
                .collect()
        })
        .collect();
    BezierPatch::from_homogeneous(net).expect("valid")
}

fn curve_object() -> Object {
    Object::new(
        "quarter",
        "circle_arc",
        json!({"center": ["0", "0"], "radius": "1", "from": ["1", "0"], "to": ["0", "1"]}),
        Geometry::Curve(quarter()),
        vec![Certificate::holds("x² + y² − w² ≡ 0", true)],
    )
}

fn patch_object() -> Object {
    Object::new(
        "wall",
        "cylinder_patch",
        json!({"radius": "1", "z0": "0", "z1": "1"}),
        Geometry::Patch(quarter_cylinder()),
        vec![
            Certificate::holds("x² + y² − w² ≡ 0", true),
            Certificate::fails("made-up failing property", "3/7 at u = 1/2", true),
        ],
    )
}

#[test]
fn curve_json_has_the_contract_fields() {
    let v = object_to_json(&curve_object());
    assert_eq!(v["name"], "quarter");
    assert_eq!(v["op"], "circle_arc");
    assert_eq!(v["kind"], "curve");
    assert_eq!(v["degree"], 2);
    assert_eq!(v["dim"], 2);
    assert_eq!(v["coordinates"], json!(["w", "wx", "wy"]));
    assert_eq!(
        v["control_points"],
        json!([["1", "1", "0"], ["1", "1", "1"], ["2", "0", "2"]])
    );
    assert_eq!(
        v["control_points_f64"],
        json!([[1.0, 1.0, 0.0], [1.0, 1.0, 1.0], [2.0, 0.0, 2.0]])
    );
    assert_eq!(
        v["certificates"],
        json!([{"property": "x² + y² − w² ≡ 0", "holds": true, "exact": true, "residual": null}])
    );
    assert_eq!(v["all_certificates_hold"], true);
    assert_eq!(v["params"]["radius"], "1");
}

#[test]
fn patch_json_is_a_net() {
    let o = patch_object();
    let v = object_to_json(&o);
    assert_eq!(v["kind"], "patch");
    assert_eq!(v["degree"], json!([2, 1]));
    assert_eq!(v["dim"], 3);
    assert_eq!(v["control_point_count"], 6);
    assert_eq!(v["control_points"][2][1], json!(["2", "0", "2", "2"]));
    assert_eq!(v["certificates"][1]["holds"], false);
    assert_eq!(v["certificates"][1]["residual"], "3/7 at u = 1/2");
    assert_eq!(v["all_certificates_hold"], false);
    let summary = object_summary_json(&o);
    assert!(summary.get("control_points").is_none());
    assert_eq!(summary["degree_summary"], "bidegree (2, 1)");
}

#[test]
fn several_pieces() {
    let o = Object::new(
        "circle",
        "circle",
        json!({}),
        Geometry::Curves(vec![quarter(), quarter()]),
        vec![],
    );
    let v = object_to_json(&o);
    assert_eq!(v["kind"], "curves");
    assert_eq!(v["degree"], json!([2, 2]));
    assert_eq!(v["pieces"], 2);
    assert_eq!(v["control_points"][1][2], json!(["2", "0", "2"]));
    let all = objects_to_json(&[o.clone(), patch_object()]);
    assert_eq!(all["objects"].as_array().map(Vec::len), Some(2));
    assert_eq!(all["all_certificates_hold"], false);
    let text = objects_to_json_string(&[o]).expect("serializes");
    assert!(text.contains("\"kind\": \"curves\""));
}

#[test]
fn obj_of_a_tiny_mesh_and_polyline() {
    let mesh = mesh_to_obj(
        "square",
        &[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ],
        &[[0.0, 0.0, 1.0]; 4],
        &[[0, 1, 2], [0, 2, 3]],
    )
    .expect("valid");
    assert_eq!(
        mesh,
        "# rcagd OBJ: 4 vertices, 2 triangles\no square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
         vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nf 1//1 2//2 3//3\nf 1//1 3//3 4//4\n"
    );
    let pl = polylines_to_obj(
        "arc",
        &[vec![[1.0, 0.0, 0.0], [0.5, 0.5, 0.0], [0.0, 1.0, 0.0]]],
    )
    .expect("valid");
    assert_eq!(
        pl,
        "# rcagd OBJ: 1 polylines, 3 vertices\no arc\nv 1 0 0\nv 0.5 0.5 0\nv 0 1 0\nl 1 2 3\n"
    );
}

fn count(s: &str, pat: &str) -> usize {
    s.matches(pat).count()
}

#[test]
fn curve_svg_structure() {
    let c = Geometry::Curve(quarter()).curves_f64().expect("finite");
    let opts = SvgOptions {
        control_polygon: true,
        ..SvgOptions::default()
    };
    let svg = curves_svg(&c, &opts).expect("drawable");
    assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\""));
    assert!(svg.trim_end().ends_with("</svg>"));
    // One curve path, one dashed control polygon, three control-point squares (+ background rect),
    // two end-point marks.
    assert_eq!(count(&svg, "stroke-dasharray"), 1);
    assert_eq!(count(&svg, "<rect"), 4);
    assert_eq!(count(&svg, "<circle"), 2);
    // The view box contains the unit quarter (y is flipped): x ∈ [0, 1], −y ∈ [−1, 0].
    let vb: Vec<f64> = svg
        .split("viewBox=\"")
        .nth(1)
        .and_then(|s| s.split('"').next())
        .expect("viewBox")
        .split(' ')
        .map(|x| x.parse().expect("number"))
        .collect();
    assert!(
        vb[0] < 0.0 && vb[1] < -1.0 && vb[0] + vb[2] > 1.0 && vb[1] + vb[3] > 0.0,
        "{vb:?}"
    );
    assert!(vb[2] < 1.3 && vb[3] < 1.3);
    // No control polygon by default.
    let plain = curves_svg(&c, &SvgOptions::default()).expect("drawable");
    assert_eq!(count(&plain, "stroke-dasharray"), 0);
}

#[test]
fn patch_svg_structure() {
    let g = Geometry::Patch(quarter_cylinder());
    let opts = SvgOptions {
        grid: 4,
        iso_lines: 3,
        ..SvgOptions::default()
    };
    let svg = geometry_svg(&g, &opts).expect("drawable");
    // 16 facets, each a closed filled path.
    assert_eq!(count(&svg, " Z\" fill=\"#"), 16);
    assert!(count(&svg, "stroke=\"#2b3a4a\"") >= 4);
    let wire = patches_svg(
        &g.patches_f64().expect("finite"),
        &SvgOptions {
            patch_style: PatchStyle::Wireframe,
            ..opts
        },
    )
    .expect("drawable");
    // 3 iso-lines per direction.
    assert_eq!(count(&wire, "<path"), 6);
    let titled = object_svg(&patch_object(), &SvgOptions::default()).expect("drawable");
    assert!(titled.contains("<title>wall (cylinder_patch, bidegree (2, 1))</title>"));
}

#[test]
fn report_files() {
    let entries = vec![
        ReportEntry::new(curve_object())
            .with_svg(object_svg(&curve_object(), &SvgOptions::default()).expect("drawable"))
            .with_file("JSON", "quarter.json"),
        ReportEntry::new(patch_object()).with_file("SVG", "wall.svg"),
    ];
    let v = report_json(&entries);
    assert_eq!(v["object_count"], 2);
    assert_eq!(v["certificate_count"], 3);
    assert_eq!(v["failed_certificate_count"], 1);
    assert_eq!(v["all_certificates_hold"], false);
    assert_eq!(
        v["objects"][0]["files"],
        json!([{"label": "JSON", "path": "quarter.json"}])
    );
    let html = report_html(&entries);
    assert!(html.starts_with("<!DOCTYPE html>"));
    assert_eq!(count(&html, "<section class=\"card"), 2);
    assert_eq!(count(&html, "<section class=\"card failed\">"), 1);
    assert!(html.contains("<img src=\"wall.svg\""));
    assert!(html.contains("residual: <code>3/7 at u = 1/2</code>"));
    assert!(html.contains("1 certificate FAIL"));
    assert!(!html.contains("<script"));

    let dir = std::env::temp_dir().join(format!("rcagd-io-report-{}", std::process::id()));
    write_report(&dir, &entries).expect("writes");
    let back: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).expect("read"))
            .expect("json");
    assert_eq!(back, v);
    assert_eq!(
        std::fs::read_to_string(dir.join("index.html")).expect("read"),
        html
    );
    let _ = std::fs::remove_dir_all(&dir);

    // a PNG picture replaces the inline SVG; header links to whole-report files
    let entries = vec![ReportEntry::new(patch_object())
        .with_svg(object_svg(&patch_object(), &SvgOptions::default()).expect("drawable"))
        .with_picture("wall.png")];
    let links = [rcagd_io::FileLink {
        label: "all objects as STEP".into(),
        path: "all.step".into(),
    }];
    let html = rcagd_io::report::report_html_with(&entries, &links);
    assert!(html.contains("<img src=\"wall.png\""));
    assert_eq!(count(&html, "<svg"), 0);
    assert!(html.contains("<a href=\"all.step\">all objects as STEP</a>"));
    let dir = std::env::temp_dir().join(format!("rcagd-io-report2-{}", std::process::id()));
    rcagd_io::report::write_report_with(&dir, &entries, &links).expect("writes");
    let back: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).expect("read"))
            .expect("json");
    assert_eq!(back["files"][0]["path"], "all.step");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn obj_of_exact_geometry() {
    use rcagd_io::obj::{default_tolerance, geometry_to_obj, merge_meshes, object_to_obj};
    let curve = object_to_obj(&curve_object()).expect("tessellates");
    assert!(curve.starts_with("# rcagd OBJ: 1 polylines"));
    assert_eq!(curve.matches("\nl ").count(), 1);
    for line in curve.lines().filter(|l| l.starts_with("v ")) {
        let v: Vec<f64> = line[2..]
            .split(' ')
            .map(|x| x.parse().expect("number"))
            .collect();
        assert!(
            (v[0].hypot(v[1]) - 1.0).abs() < 1e-12 && v[2] == 0.0,
            "{line}"
        );
    }
    let g = Geometry::Patches(vec![quarter_cylinder(), quarter_cylinder()]);
    assert!((default_tolerance(&g) - 1e-3 * 3f64.sqrt()).abs() < 1e-12);
    let mesh = geometry_to_obj("wall", &g, 1e-2).expect("tessellates");
    let nv = mesh.lines().filter(|l| l.starts_with("v ")).count();
    let nn = mesh.lines().filter(|l| l.starts_with("vn ")).count();
    let nf = mesh.lines().filter(|l| l.starts_with("f ")).count();
    assert!(nv > 8 && nn == nv && nf > 0);
    // The second patch's faces refer to its own (offset) vertices.
    let max_index = mesh
        .lines()
        .filter(|l| l.starts_with("f "))
        .flat_map(|l| {
            l[2..].split(' ').map(|t| {
                t.split("//")
                    .next()
                    .unwrap_or("0")
                    .parse::<usize>()
                    .expect("idx")
            })
        })
        .max();
    assert_eq!(max_index, Some(nv));
    assert!(merge_meshes(&[]).expect("empty").positions.is_empty());
    assert!(geometry_to_obj("bad", &g, 0.0).is_err());
}
