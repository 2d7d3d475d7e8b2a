//! Exchange formats: STEP and IGES writers and readers, meshes (STL, PLY, glTF) and
//! PNG pictures, on exact objects with known geometry.
//!
//! Set `RCAGD_EXCHANGE_OUT=DIR` to also write every file of [`write_gallery_files`]
//! to `DIR` (for `scripts/occ_check.sh DIR`, the OpenCascade check).

use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::{BezierCurve, BezierPatch};
use rcagd_io::model::{Geometry, Object};
use rcagd_io::IoError;
use serde_json::Value;

use crate::samples;

use samples::{bicubic, circle, int, q, space_cubic, sphere, torus, tube};

fn object(name: &str, geometry: Geometry) -> Object {
    Object::new(name, "test", Value::Null, geometry, Vec::new())
}

/// The objects of the exchange tests.
pub fn gallery() -> Vec<Object> {
    vec![
        object("sphere", Geometry::Patches(sphere([0, 0, 0], 1))),
        object("torus", Geometry::Patches(torus(int(3), int(1)))),
        object("tube", Geometry::Patches(tube())),
        object("bicubic", Geometry::Patch(bicubic())),
        object("circle", Geometry::Curves(circle())),
        object("space cubic", Geometry::Curve(space_cubic())),
    ]
}

#[test]
fn write_gallery_files() {
    let Ok(dir) = std::env::var("RCAGD_EXCHANGE_OUT") else {
        return;
    };
    let dir = std::path::PathBuf::from(dir);
    std::fs::create_dir_all(&dir).expect("create dir");
    let objects = gallery();
    for o in &objects {
        let stem = o.name.replace(' ', "_");
        let one = std::slice::from_ref(o);
        let step = rcagd_io::step::write_step(one).expect("step");
        std::fs::write(dir.join(format!("{stem}.step")), step).expect("write");
        let iges = rcagd_io::iges::write_iges(one).expect("iges");
        std::fs::write(dir.join(format!("{stem}.igs")), iges).expect("write");
        let side = rcagd_io::step::exact_sidecar(one).expect("sidecar");
        std::fs::write(
            dir.join(format!("{stem}.exact.json")),
            serde_json::to_string_pretty(&side).expect("json"),
        )
        .expect("write");
    }
    for o in &objects {
        let stem = o.name.replace(' ', "_");
        let png = rcagd_io::raster::render_png(o, &Default::default()).expect("png");
        std::fs::write(dir.join(format!("{stem}.png")), png).expect("write");
    }
    let glb = rcagd_io::gltf::objects_to_glb(&objects, &Default::default()).expect("glb");
    std::fs::write(dir.join("all.glb"), glb).expect("write");
    for o in objects.iter().filter(|o| !o.geometry.patches().is_empty()) {
        let stem = o.name.replace(' ', "_");
        let mesh = rcagd_io::stl::object_mesh(o, &Default::default()).expect("mesh");
        let stl = rcagd_io::stl::write_stl_binary(&o.name, &mesh).expect("stl");
        std::fs::write(dir.join(format!("{stem}.stl")), stl).expect("write");
        let ply = rcagd_io::ply::write_ply(&o.name, &mesh).expect("ply");
        std::fs::write(dir.join(format!("{stem}.ply")), ply).expect("write");
    }
    // the same objects under AP242
    let opts = rcagd_io::step::StepOptions {
        schema: rcagd_io::step::StepSchema::Ap242,
        ..Default::default()
    };
    let ap242 = rcagd_io::step::write_step_with(&objects, &opts).expect("step");
    std::fs::write(dir.join("all_ap242.step"), ap242).expect("write");
    let side = rcagd_io::step::exact_sidecar(&objects).expect("sidecar");
    std::fs::write(
        dir.join("all_ap242.exact.json"),
        serde_json::to_string_pretty(&side).expect("json"),
    )
    .expect("write");
    let all = rcagd_io::step::write_step(&objects).expect("step");
    std::fs::write(dir.join("all.step"), all).expect("write");
    let iges = rcagd_io::iges::write_iges(&objects).expect("iges");
    std::fs::write(dir.join("all.igs"), iges).expect("write");
    let side = rcagd_io::step::exact_sidecar(&objects).expect("sidecar");
    std::fs::write(
        dir.join("all.exact.json"),
        serde_json::to_string_pretty(&side).expect("json"),
    )
    .expect("write");
    let _ = Scalar::to_f64(&int(1));
}

/// Writes STEP with a fixed timestamp (for reproducible text).
fn step_text(objects: &[Object]) -> String {
    let opts = rcagd_io::step::StepOptions {
        timestamp: Some("2024-01-01T00:00:00".into()),
        ..Default::default()
    };
    rcagd_io::step::write_step_with(objects, &opts).expect("step")
}

#[test]
fn step_round_trip_is_exact_with_the_sidecar() {
    use rcagd_io::step::{exact_sidecar, exchange_object};
    use rcagd_io::step_read::{apply_sidecar, curve_rounds_to, read_step, surface_rounds_to};
    let objects = gallery();
    let text = step_text(&objects);
    let mut read = read_step(&text).expect("reads back");
    assert_eq!(read.len(), objects.len());
    for (o, r) in objects.iter().zip(&read) {
        assert_eq!(o.name, r.name);
        let x = exchange_object(o).expect("exchange");
        let surfaces = x.surfaces().expect("surfaces");
        assert_eq!(surfaces.len(), r.surfaces.len(), "{}", o.name);
        assert_eq!(x.curves.len(), r.curves.len(), "{}", o.name);
        for (a, b) in surfaces.iter().zip(&r.surfaces) {
            assert!(surface_rounds_to(a, b), "{}", o.name);
        }
        for (a, b) in x.curves.iter().zip(&r.curves) {
            assert!(curve_rounds_to(a, b), "{}", o.name);
        }
    }
    let side = exact_sidecar(&objects).expect("sidecar");
    apply_sidecar(&mut read, &side).expect("sidecar matches");
    for (o, r) in objects.iter().zip(&read) {
        let x = exchange_object(o).expect("exchange");
        assert_eq!(x.surfaces().expect("surfaces"), r.surfaces);
        assert_eq!(x.curves, r.curves);
    }
}

fn iges_text(objects: &[Object]) -> String {
    let opts = rcagd_io::iges::IgesOptions {
        time: Some(1_704_067_200),
        ..Default::default()
    };
    rcagd_io::iges::write_iges_with(objects, &opts).expect("iges")
}

/// Entity type → count, from the Directory Entry section.
fn iges_entity_counts(text: &str) -> std::collections::BTreeMap<u32, usize> {
    let mut out = std::collections::BTreeMap::new();
    for line in text.lines().filter(|l| l.as_bytes().get(72) == Some(&b'D')) {
        let seq: usize = line[73..].trim().parse().expect("sequence number");
        if seq % 2 == 1 {
            *out.entry(line[..8].trim().parse().expect("entity type"))
                .or_default() += 1;
        }
    }
    out
}

/// Closed objects are manifold solid B-reps (one 186 of one closed shell 514, a face
/// 510 with a loop 508 per patch, shared edges once in the edge list); open ones loose
/// surfaces.
#[test]
fn closed_objects_are_manifold_solids_in_iges() {
    let all = gallery();
    let counts = |name: &str| {
        let o = all.iter().find(|o| o.name == name).expect("object");
        iges_entity_counts(&iges_text(std::slice::from_ref(o)))
    };
    let sphere = counts("sphere");
    for (kind, n) in [
        (186, 1),
        (514, 1),
        (510, 8),
        (508, 8),
        (128, 8),
        (504, 1),
        (502, 1),
    ] {
        assert_eq!(
            sphere.get(&kind),
            Some(&n),
            "sphere: entity {kind}: {sphere:?}"
        );
    }
    // 12 shared edge curves (the 4 pole sides are vertex-type loop entries) and one
    // parameter line per loop entry (8 faces × 4 sides)
    assert_eq!(sphere.get(&126), Some(&(12 + 32)), "{sphere:?}");
    let torus = counts("torus");
    assert_eq!(torus.get(&186), Some(&1), "{torus:?}");
    assert_eq!(torus.get(&126), Some(&(32 + 64)), "{torus:?}");
    let tube = counts("tube");
    assert_eq!(
        tube.get(&186),
        None,
        "an open tube is not a solid: {tube:?}"
    );
    assert_eq!(tube.get(&128), Some(&4));
}

#[test]
fn iges_round_trip_is_exact_with_the_sidecar() {
    use rcagd_io::iges_read::read_iges;
    use rcagd_io::step::{exact_sidecar, exchange_object};
    use rcagd_io::step_read::{apply_sidecar, curve_rounds_to, surface_rounds_to};
    let objects = gallery();
    let text = iges_text(&objects);
    for (k, line) in text.lines().enumerate() {
        assert_eq!(line.len(), 80, "line {} is not 80 columns: {line:?}", k + 1);
    }
    let mut read = read_iges(&text).expect("reads back");
    assert_eq!(read.len(), objects.len());
    for (o, r) in objects.iter().zip(&read) {
        assert_eq!(o.name, r.name);
        let x = exchange_object(o).expect("exchange");
        let surfaces = x.surfaces().expect("surfaces");
        assert_eq!(surfaces.len(), r.surfaces.len(), "{}", o.name);
        assert_eq!(x.curves.len(), r.curves.len(), "{}", o.name);
        for (a, b) in surfaces.iter().zip(&r.surfaces) {
            assert!(surface_rounds_to(a, b), "{}", o.name);
        }
        for (a, b) in x.curves.iter().zip(&r.curves) {
            assert!(curve_rounds_to(a, b), "{}", o.name);
        }
    }
    let side = exact_sidecar(&objects).expect("sidecar");
    apply_sidecar(&mut read, &side).expect("sidecar matches");
    for (o, r) in objects.iter().zip(&read) {
        let x = exchange_object(o).expect("exchange");
        assert_eq!(x.surfaces().expect("surfaces"), r.surfaces);
        assert_eq!(x.curves, r.curves);
    }
}

fn quarter_object() -> Object {
    object("arc", Geometry::Curve(circle().remove(0)))
}

#[test]
fn step_snapshot_of_a_quarter_circle() {
    let text = step_text(&[quarter_object()]);
    let want = "ISO-10303-21;
HEADER;
FILE_DESCRIPTION(('rcagd exact rational geometry: 1 object(s)'),'2;1');
FILE_NAME('rcagd.step','2024-01-01T00:00:00',('rcagd'),('rcagd'),'rcagd-io 0.1.0','rcagd 0.1.0','');
FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));
ENDSEC;
DATA;
#1 = APPLICATION_CONTEXT('core data for automotive mechanical design processes');
#2 = APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#1);
#3 = PRODUCT_CONTEXT('',#1,'mechanical');
#4 = PRODUCT_DEFINITION_CONTEXT('part definition',#1,'design');
#5 = (LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.));
#6 = (NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.));
#7 = (NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT());
#8 = UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#5,'distance_accuracy_value','confusion accuracy');
#9 = (GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#8)) GLOBAL_UNIT_ASSIGNED_CONTEXT((#5,#6,#7)) REPRESENTATION_CONTEXT('3D','3D context with units and uncertainty'));
#10 = CARTESIAN_POINT('',(0.,0.,0.));
#11 = DIRECTION('',(0.,0.,1.));
#12 = DIRECTION('',(1.,0.,0.));
#13 = AXIS2_PLACEMENT_3D('',#10,#11,#12);
#14 = PRODUCT('arc','arc','',(#3));
#15 = PRODUCT_DEFINITION_FORMATION('','',#14);
#16 = PRODUCT_DEFINITION('design','',#15,#4);
#17 = PRODUCT_DEFINITION_SHAPE('','',#16);
#18 = CARTESIAN_POINT('',(1.,0.,0.));
#19 = CARTESIAN_POINT('',(1.,1.,0.));
#20 = CARTESIAN_POINT('',(0.,1.,0.));
#21 = (BOUNDED_CURVE() B_SPLINE_CURVE(2,(#18,#19,#20),.UNSPECIFIED.,.F.,.F.) B_SPLINE_CURVE_WITH_KNOTS((3,3),(0.,1.),.PIECEWISE_BEZIER_KNOTS.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_CURVE((1.,1.,2.)) REPRESENTATION_ITEM('curve 0'));
#22 = GEOMETRIC_CURVE_SET('arc',(#21));
#23 = GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION('arc',(#13,#22),#9);
#24 = SHAPE_DEFINITION_REPRESENTATION(#17,#23);
#25 = PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(#14));
ENDSEC;
END-ISO-10303-21;
";
    assert_eq!(text, want);
}

#[test]
fn iges_snapshot_of_a_quarter_circle() {
    let text = iges_text(&[quarter_object()]);
    let want = "\
rcagd exact rational geometry (IGES 5.3)                                S      1
1 object(s), entities 126/128                                           S      2
1H,,1H;,9Hrcagd.igs,9Hrcagd.igs,11Hrcagd 0.1.0,14Hrcagd-io 0.1.0,32,38, G      1
6,308,15,9Hrcagd.igs,1.,2,2HMM,1,0.01,15H20240101.000000,1.E-07,1.,     G      2
5Hrcagd,5Hrcagd,11,0,15H20240101.000000,;                               G      3
     126       1       0       0       0       0       0       000020000D      1
     126       0       0       2       0                     ARC       0D      2
     406       3       0       0       0       0       0       000010300D      3
     406       0       0       1      15                    NAME       0D      4
     402       4       0       0       0       0       0       000000000D      5
     402       0       0       1       7                     ARC       0D      6
126,2,2,1,0,0,0,0.,0.,0.,1.,1.,1.,1.,1.,2.,1.,0.,0.,1.,1.,0.,0.,       1P      1
1.,0.,0.,1.,0.,0.,1.;                                                  1P      2
406,1,3Harc;                                                           3P      3
402,1,1,0,1,3;                                                         5P      4
S      2G      3D      6P      4                                        T      1
";
    assert_eq!(text, want);
}

/// A regression: with 100 or more objects the one-line Start section was 81 characters
/// wide, and the reader (rightly) refused the file. Every card is 80 columns.
#[test]
fn iges_cards_stay_80_columns_with_many_objects() {
    let objects: Vec<_> = (0..120).map(|_| quarter_object()).collect();
    let text = iges_text(&objects);
    assert!(
        text.lines().all(|l| l.len() == 80),
        "a card is not 80 columns"
    );
    rcagd_io::iges_read::read_iges(&text).expect("reads back");
}

fn assert_err_mentions(
    r: Result<Vec<rcagd_io::step_read::ImportedObject>, rcagd_io::IoError>,
    want: &[&str],
) {
    let e = r.expect_err("malformed input must be an error").to_string();
    for w in want {
        assert!(e.contains(w), "error {e:?} should mention {w:?}");
    }
}

#[test]
fn malformed_step_is_an_error_with_line_and_entity() {
    use rcagd_io::step_read::read_step;
    let good = step_text(&[quarter_object()]);
    // a dangling reference
    let bad = good.replace(
        "B_SPLINE_CURVE(2,(#18,#19,#20)",
        "B_SPLINE_CURVE(2,(#18,#19,#99)",
    );
    assert_err_mentions(read_step(&bad), &["#21", "#99", "not defined"]);
    // knots that do not fit the control points
    let bad = good.replace(
        "B_SPLINE_CURVE_WITH_KNOTS((3,3)",
        "B_SPLINE_CURVE_WITH_KNOTS((3,2)",
    );
    assert_err_mentions(read_step(&bad), &["line 28", "#21", "knot"]);
    // a negative weight
    let bad = good.replace(
        "RATIONAL_B_SPLINE_CURVE((1.,1.,2.))",
        "RATIONAL_B_SPLINE_CURVE((1.,-1.,2.))",
    );
    assert_err_mentions(read_step(&bad), &["#21", "weight"]);
    // a bad number
    let bad = good.replace(
        "CARTESIAN_POINT('',(1.,1.,0.))",
        "CARTESIAN_POINT('',(1.,1.E,0.))",
    );
    assert_err_mentions(read_step(&bad), &["#19"]);
    // syntax: a missing parenthesis
    let bad = good.replace(
        "#22 = GEOMETRIC_CURVE_SET('arc',(#21));",
        "#22 = GEOMETRIC_CURVE_SET('arc',(#21);",
    );
    assert_err_mentions(read_step(&bad), &["line 29", "#22"]);
    // unsupported geometry
    let bad = good.replace(
        "#22 = GEOMETRIC_CURVE_SET('arc',(#21));",
        "#22 = GEOMETRIC_CURVE_SET('arc',(#26));\n#26 = LINE('',#18,#19);",
    );
    assert_err_mentions(read_step(&bad), &["#26", "LINE"]);
    // not STEP at all, and empty
    assert_err_mentions(read_step("solid x\nendsolid x\n"), &["line 1"]);
    assert_err_mentions(read_step(""), &["line 1"]);
}

#[test]
fn malformed_iges_is_an_error_with_line_and_entity() {
    use rcagd_io::iges_read::read_iges;
    let good = iges_text(&[quarter_object()]);
    let lines: Vec<&str> = good.lines().collect();
    // a negative weight on the first P line of entity DE 1 (file line 12)
    let bad = good.replace("1.,1.,1.,1.,1.,2.,", "1.,1.,1.,1.,0.,2.,");
    assert_err_mentions(read_iges(&bad), &["line 12", "DE 1", "weight"]);
    // knots not clamped
    let bad = good.replace(
        "126,2,2,1,0,0,0,0.,0.,0.,1.,",
        "126,2,2,1,0,0,0,0.,0.,5.,1.,",
    );
    assert_err_mentions(read_iges(&bad), &["line 12", "DE 1", "knot"]);
    // a parameter pointer beyond the P section
    let bad = good.replace(
        "     126       1       0       0       0       0       0       000020000D      1",
        "     126      17       0       0       0       0       0       000020000D      1",
    );
    assert_err_mentions(read_iges(&bad), &["line 6", "DE 1"]);
    // a group member that does not exist
    let bad = good.replace("402,1,1,0,1,3;", "402,1,9,0,1,3;");
    assert_err_mentions(read_iges(&bad), &["DE 5", "DE 9"]);
    // a truncated file (no T section), a short record
    let truncated = lines[..lines.len() - 1].join("\n");
    assert_err_mentions(read_iges(&truncated), &["Terminate"]);
    let short = good.replacen(lines[0], "a short record", 1);
    assert_err_mentions(read_iges(&short), &["line 1", "column"]);
}

/// A reader's error must be [`IoError::Read`] naming the format and a line or entity.
fn assert_located(r: &Result<Vec<rcagd_io::step_read::ImportedObject>, IoError>, what: &str) {
    if let Err(e) = r {
        assert!(
            matches!(e, IoError::Read { .. }),
            "{what}: not a read error: {e:?}"
        );
        assert!(
            e.line().is_some() || e.entity().is_some(),
            "{what}: the error names neither line nor entity: {e}"
        );
    }
}

#[test]
fn readers_never_panic_on_truncated_or_corrupted_files() {
    use rcagd_io::iges_read::read_iges;
    use rcagd_io::step_read::read_step;
    let objects = vec![
        quarter_object(),
        object("bicubic", Geometry::Patch(bicubic())),
        object("sphere", Geometry::Patches(sphere([0, 0, 0], 2))),
    ];
    let step = step_text(&objects);
    let iges = iges_text(&objects);
    let mut errors = 0usize;
    for (is_step, text) in [(true, &step), (false, &iges)] {
        let bytes = text.as_bytes();
        // Truncated files: an error (with its line) whenever the end is cut off; the
        // IGES reader accepts a T record cut after its column 73.
        for cut in (0..bytes.len()).step_by(37) {
            let t = String::from_utf8_lossy(&bytes[..cut]);
            let (a, b) = (read_step(&t), read_iges(&t));
            assert_located(&a, "truncated, STEP reader");
            assert_located(&b, "truncated, IGES reader");
            if cut + 10 < bytes.len() {
                let r = if is_step { &a } else { &b };
                assert!(
                    r.is_err(),
                    "a file cut at byte {cut} of {} reads",
                    bytes.len()
                );
                errors += 1;
            }
        }
        // Garbled files: byte flips at many positions give a located error or a
        // result, never a panic.
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        for _ in 0..400 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let mut b = bytes.to_vec();
            let k = (x % b.len() as u64) as usize;
            b[k] = b"0123456789.,;()#'$*-E \n"[(x >> 32) as usize % 23];
            let t = String::from_utf8_lossy(&b);
            let r = if is_step {
                read_step(&t)
            } else {
                read_iges(&t)
            };
            assert_located(&r, "garbled");
            errors += usize::from(r.is_err());
            let other = if is_step {
                read_iges(&t)
            } else {
                read_step(&t)
            };
            assert_located(&other, "garbled, other reader");
        }
        // Lines deleted or duplicated.
        let lines: Vec<&str> = text.lines().collect();
        for k in (0..lines.len()).step_by(5) {
            let mut del = lines.clone();
            del.remove(k);
            let mut dup = lines.clone();
            dup.insert(k, lines[k]);
            for t in [del.join("\n"), dup.join("\n")] {
                let r = if is_step {
                    read_step(&t)
                } else {
                    read_iges(&t)
                };
                assert_located(&r, "lines deleted/duplicated");
            }
        }
    }
    assert!(errors > 100, "only {errors} malformed files were rejected");
}

#[test]
fn meshes_of_the_sphere_are_consistent() {
    use rcagd_io::stl::{object_mesh, write_stl_ascii, write_stl_binary};
    let o = &gallery()[0];
    let mesh = object_mesh(o, &Default::default()).expect("mesh");
    assert!(!mesh.triangles.is_empty());
    for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
        let r = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        assert!((r - 1.0).abs() < 1e-12, "vertex on the unit sphere");
        let d = (p[0] * n[0] + p[1] * n[1] + p[2] * n[2]).abs();
        assert!(
            d > 1.0 - 1e-5,
            "normal along the radius (exact surface normal)"
        );
    }
    let bin = write_stl_binary(&o.name, &mesh).expect("stl");
    assert_eq!(bin.len(), 84 + 50 * mesh.triangles.len());
    let ascii = write_stl_ascii(&o.name, &mesh).expect("stl");
    assert_eq!(ascii.matches("facet normal").count(), mesh.triangles.len());
    let ply = rcagd_io::ply::write_ply(&o.name, &mesh).expect("ply");
    let header_end = ply
        .windows(11)
        .position(|w| w == b"end_header\n")
        .expect("header")
        + 11;
    assert_eq!(
        ply.len() - header_end,
        24 * mesh.positions.len() + 13 * mesh.triangles.len()
    );
    let glb = rcagd_io::gltf::objects_to_glb(&gallery(), &Default::default()).expect("glb");
    let jlen = u32::from_le_bytes([glb[12], glb[13], glb[14], glb[15]]) as usize;
    let doc: Value = serde_json::from_slice(&glb[20..20 + jlen]).expect("json chunk");
    assert_eq!(
        doc["nodes"].as_array().map(Vec::len),
        Some(1 + gallery().len())
    );
    assert_eq!(doc["nodes"][1]["name"], "sphere");
    // curve objects become line strips
    assert_eq!(doc["meshes"][4]["primitives"][0]["mode"], 3);
    // the mesh of curves is an error, not a panic
    assert!(object_mesh(&gallery()[4], &Default::default()).is_err());
}

#[test]
fn pictures_have_the_requested_size() {
    use rcagd_io::raster::{render, render_png, RenderOptions};
    let opts = RenderOptions {
        width: 160,
        height: 120,
        supersample: 2,
        grid: 12,
        ..Default::default()
    };
    for o in gallery() {
        let img = render(&o, &opts).expect("renders");
        assert_eq!(img.rgb.len(), 160 * 120 * 3);
        // something was drawn: not all pixels are background-light
        assert!(
            img.rgb.chunks(3).filter(|p| p[0] < 150).count() > 50,
            "{}",
            o.name
        );
        let png = render_png(&o, &opts).expect("png");
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
        assert_eq!(
            u32::from_be_bytes([png[16], png[17], png[18], png[19]]),
            160
        );
        assert_eq!(
            u32::from_be_bytes([png[20], png[21], png[22], png[23]]),
            120
        );
    }
}

mod property {
    use super::*;
    use proptest::prelude::*;

    fn small_rational() -> impl Strategy<Value = Rational> {
        (-40i64..=40, 1i64..=12).prop_map(|(p, d)| q(p, d))
    }

    fn positive_rational() -> impl Strategy<Value = Rational> {
        (1i64..=30, 1i64..=12).prop_map(|(p, d)| q(p, d))
    }

    fn patch() -> impl Strategy<Value = BezierPatch<Rational>> {
        (1usize..=3, 1usize..=3).prop_flat_map(|(m, n)| {
            proptest::collection::vec(
                (
                    positive_rational(),
                    small_rational(),
                    small_rational(),
                    small_rational(),
                ),
                (m + 1) * (n + 1),
            )
            .prop_map(move |pts| {
                let coords = pts
                    .into_iter()
                    .flat_map(|(w, x, y, z)| [w.clone(), w.clone() * x, w.clone() * y, w * z])
                    .collect();
                BezierPatch::from_flat(3, m, n, coords).expect("valid")
            })
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]

        /// write → read → evaluate agrees with the exact patch (to f64 rounding), and
        /// the sidecar restores the exact values, for STEP and IGES.
        #[test]
        fn write_read_evaluate_agrees(p in patch(), u in 0u32..=16, v in 0u32..=16) {
            let o = object("random patch", Geometry::Patch(p.clone()));
            let side = rcagd_io::step::exact_sidecar(std::slice::from_ref(&o)).expect("sidecar");
            // the exchanged surface: `p` itself or `p` with balanced weights (an exact
            // Möbius reparametrization, rcagd_io::balance)
            let x = rcagd_io::step::exchange_object(&o).expect("exchange");
            let exact = x.surfaces().expect("surfaces").remove(0);
            let bal = rcagd_io::balance::patch_balance(&p);
            prop_assert_eq!(&x.patches[0], &rcagd_io::balance::apply_patch(&p, bal));
            let (uq, vq) = (q(u as i64, 16), q(v as i64, 16));
            let want = exact.eval(&uq, &vq).expect("finite");
            let size = rcagd_io::stl::object_size(&o);
            for read in [
                rcagd_io::step_read::read_step(&step_text(std::slice::from_ref(&o))).expect("step"),
                rcagd_io::iges_read::read_iges(&iges_text(std::slice::from_ref(&o))).expect("iges"),
            ] {
                prop_assert_eq!(read.len(), 1);
                let s = read[0].surfaces_f64();
                prop_assert_eq!(s.len(), 1);
                let got = s[0].eval_f64(u as f64 / 16.0, v as f64 / 16.0).expect("finite");
                for (a, b) in got.iter().zip(&want) {
                    prop_assert!((a - Scalar::to_f64(b)).abs() <= 1e-12 * size);
                }
                let mut read = read;
                rcagd_io::step_read::apply_sidecar(&mut read, &side).expect("sidecar");
                prop_assert_eq!(&read[0].surfaces[0], &exact);
                prop_assert_eq!(read[0].surfaces[0].eval(&uq, &vq).expect("finite"), want.clone());
            }
        }
    }
}

/// A bilinear square `[x0, x0 + 1] × [0, 1]` at height `z` (weights 1).
fn square(x0: i64, z: i64) -> BezierPatch<Rational> {
    let net = (0..2)
        .map(|i| {
            (0..2)
                .map(|j| vec![int(1), int(x0 + i), int(j), int(z)])
                .collect()
        })
        .collect();
    BezierPatch::from_homogeneous(net).expect("valid net")
}

/// Patches 0 and 2 share an edge (one shell), patch 1 is apart (a second shell): the
/// writer emits them in patch order, the shells list them as 0, 2, 1. The reader must
/// return them in file order so that the exact sidecar applies (regression: the Dupin
/// cyclide of the gallery failed this way).
#[test]
fn multi_shell_objects_round_trip_in_patch_order() {
    use rcagd_io::step::exact_sidecar;
    use rcagd_io::step_read::{apply_sidecar, read_step};
    let objects = vec![object(
        "two_shells",
        Geometry::Patches(vec![square(0, 0), square(5, 3), square(1, 0)]),
    )];
    let side = exact_sidecar(&objects).expect("sidecar");
    let mut read = read_step(&step_text(&objects)).expect("STEP reads");
    apply_sidecar(&mut read, &side).expect("STEP: sidecar matches, in patch order");
    let mut read = rcagd_io::iges_read::read_iges(&iges_text(&objects)).expect("IGES reads");
    apply_sidecar(&mut read, &side).expect("IGES: sidecar matches, in patch order");
}

/// `(start vertex, end vertex)` of every `EDGE_CURVE` line of STEP text.
fn edge_curves(text: &str) -> Vec<(String, String)> {
    text.lines()
        .filter_map(|l| l.split_once("= EDGE_CURVE('',"))
        .map(|(_, rest)| {
            let mut it = rest.split(',');
            let a = it.next().unwrap_or_default().to_string();
            let b = it.next().unwrap_or_default().to_string();
            (a, b)
        })
        .collect()
}

/// The number of oriented edges of every `EDGE_LOOP` of STEP text.
fn loop_sizes(text: &str) -> Vec<usize> {
    text.lines()
        .filter_map(|l| l.split_once("= EDGE_LOOP('',"))
        .map(|(_, rest)| rest.matches('#').count())
        .collect()
}

/// Regression (issue 8): a patch side that collapses to a point (a pole) is written as a
/// degenerate edge — an `EDGE_CURVE` from the pole's vertex to itself with the side's
/// parameter line as `PCURVE` — and every edge carries its parameter lines on its faces.
/// Without them OpenCascade closed the loops itself, straight across the parameter
/// square where two adjacent sides collapse, and grew the tolerance to 0.31.
#[test]
fn collapsed_sides_are_degenerate_edges_with_parameter_lines() {
    use rcagd_io::step_read::read_step;
    // 8 octants, each collapsed at u = 0: 12 shared edges, 8 degenerate ones
    let text = step_text(&[object("sphere", Geometry::Patches(sphere([0, 0, 0], 1)))]);
    let edges = edge_curves(&text);
    assert_eq!(edges.len(), 12 + 8);
    assert_eq!(edges.iter().filter(|(a, b)| a == b).count(), 8);
    assert_eq!(loop_sizes(&text), vec![4; 8]);
    // 2 parameter lines per shared edge, 1 per degenerate edge
    assert_eq!(text.matches("PCURVE('',").count(), 2 * 12 + 8);
    assert_eq!(text.matches("SURFACE_CURVE(").count(), 12 + 8);
    assert!(text.contains("MANIFOLD_SOLID_BREP"));
    let back = read_step(&text).expect("reads back");
    assert_eq!(back[0].surfaces.len(), 8);

    // a biquadratic patch whose sides u = 1 and v = 1 both collapse to one point (as
    // four of the 16 patches of `sphere_cover`): two degenerate edges in one loop
    let pole = [int(1), int(0), int(0), int(2)];
    let net: Vec<Vec<Vec<Rational>>> = (0..3)
        .map(|i| {
            (0..3)
                .map(|j| {
                    if i == 2 || j == 2 {
                        pole.iter().map(|x| x.clone() * int(1 + i + j)).collect()
                    } else {
                        let w = int(1 + i * j);
                        vec![w.clone(), w.clone() * int(i), w.clone() * int(j), int(0)]
                    }
                })
                .collect()
        })
        .collect();
    let corner = BezierPatch::from_homogeneous(net).expect("valid");
    let text = step_text(&[object("corner", Geometry::Patch(corner))]);
    let edges = edge_curves(&text);
    assert_eq!(edges.len(), 4, "{edges:?}");
    assert_eq!(edges.iter().filter(|(a, b)| a == b).count(), 2);
    assert_eq!(loop_sizes(&text), vec![4]);
    let back = read_step(&text).expect("reads back");
    assert_eq!(back[0].surfaces.len(), 1);
}

/// A piece whose weights are all equal but not 1 is written in the polynomial form; the
/// sidecar carries weight 1 too, so the exact round trip works (a defect before: the
/// sidecar kept the weight 3 and `apply_sidecar` refused the file's numbers).
#[test]
fn equal_weights_other_than_one_round_trip() {
    use rcagd_io::step_read::{apply_sidecar, read_step};
    let three = int(3);
    let h = |x: i64, y: i64, z: i64| vec![three.clone(), int(3 * x), int(3 * y), int(3 * z)];
    let patch = BezierPatch::from_homogeneous(vec![
        vec![h(0, 0, 0), h(1, 0, 0)],
        vec![h(0, 1, 0), h(1, 1, 1)],
    ])
    .expect("bilinear");
    let curve =
        BezierCurve::from_homogeneous(vec![h(0, 0, 0), h(1, 2, 0), h(2, 0, 1)]).expect("curve");
    let objects = vec![
        object("bilinear", Geometry::Patch(patch)),
        object("parabola", Geometry::Curve(curve)),
    ];
    let side = rcagd_io::step::exact_sidecar(&objects).expect("sidecar");
    let mut read = read_step(&step_text(&objects)).expect("reads");
    apply_sidecar(&mut read, &side).expect("the sidecar matches the file");
    let mut read = rcagd_io::iges_read::read_iges(&iges_text(&objects)).expect("reads");
    apply_sidecar(&mut read, &side).expect("the sidecar matches the IGES file");
}
