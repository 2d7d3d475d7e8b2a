//! Exchange formats: STEP and IGES writers and readers, meshes (STL, PLY, glTF) and
//! PNG pictures, on exact objects with known geometry.
//!
//! Set `RCAGD_EXCHANGE_OUT=DIR` to also write every file of [`write_gallery_files`]
//! to `DIR` (for `scripts/occ_check.sh DIR`, the OpenCascade check).

use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::{BezierCurve, BezierPatch};
use rcagd_io::model::{Geometry, Object};
use serde_json::Value;

fn q(p: i64, d: i64) -> Rational {
    Rational::from_ratio(p, d)
}

fn int(p: i64) -> Rational {
    Rational::from(p)
}

/// The quarter circle `(1−t², 2t)/(1+t²)` as homogeneous `(w, w·cos, w·sin)` control
/// points, rotated by `k` quarter turns.
fn quarter(k: usize) -> [[Rational; 3]; 3] {
    let base = [
        [int(1), int(1), int(0)],
        [int(1), int(1), int(1)],
        [int(2), int(0), int(2)],
    ];
    base.map(|[w, c, s]| {
        let (mut c, mut s) = (c, s);
        for _ in 0..k % 4 {
            (c, s) = (-s, c);
        }
        [w, c, s]
    })
}

/// One octant of the unit sphere (biquadratic, degenerate at the pole `u = 0`),
/// reflected by the signs `(sx, sy, sz)`.
fn sphere_octant(
    sx: i64,
    sy: i64,
    sz: i64,
    center: [i64; 3],
    radius: i64,
) -> BezierPatch<Rational> {
    // meridian (w, w·r, w·z) from the pole to the equator
    let mer = [
        [int(1), int(0), int(1)],
        [int(1), int(1), int(1)],
        [int(2), int(2), int(0)],
    ];
    let eq = quarter(0);
    let net = mer
        .iter()
        .map(|m| {
            eq.iter()
                .map(|e| {
                    let w = m[0].clone() * e[0].clone();
                    let r = int(radius);
                    vec![
                        w.clone(),
                        int(sx) * r.clone() * m[1].clone() * e[1].clone()
                            + w.clone() * int(center[0]),
                        int(sy) * r.clone() * m[1].clone() * e[2].clone()
                            + w.clone() * int(center[1]),
                        int(sz) * r * m[2].clone() * e[0].clone() + w * int(center[2]),
                    ]
                })
                .collect()
        })
        .collect();
    BezierPatch::from_homogeneous(net).expect("valid net")
}

/// The whole sphere as 8 exact biquadratic patches (a closed shell).
pub fn sphere(center: [i64; 3], radius: i64) -> Vec<BezierPatch<Rational>> {
    let mut out = Vec::new();
    for sz in [1, -1] {
        for sy in [1, -1] {
            for sx in [1, -1] {
                out.push(sphere_octant(sx, sy, sz, center, radius));
            }
        }
    }
    out
}

/// A torus with radii `big > small` as 16 exact biquadratic patches:
/// `x = (R + r cos v) cos u`, `y = (R + r cos v) sin u`, `z = r sin v`, each circle
/// as four rational quarter circles; homogeneous `W = wᵤ w_v`,
/// `X = (R w_v + r c_v) cᵤ`, `Y = (R w_v + r c_v) sᵤ`, `Z = r s_v wᵤ`.
pub fn torus(big: Rational, small: Rational) -> Vec<BezierPatch<Rational>> {
    let mut out = Vec::new();
    for a in 0..4 {
        for b in 0..4 {
            let (cu, cv) = (quarter(a), quarter(b));
            let net = cu
                .iter()
                .map(|[wu, c, s]| {
                    cv.iter()
                        .map(|[wv, cc, ss]| {
                            let rad = big.clone() * wv.clone() + small.clone() * cc.clone();
                            vec![
                                wu.clone() * wv.clone(),
                                rad.clone() * c.clone(),
                                rad * s.clone(),
                                small.clone() * ss.clone() * wu.clone(),
                            ]
                        })
                        .collect()
                })
                .collect();
            out.push(BezierPatch::from_homogeneous(net).expect("valid net"));
        }
    }
    out
}

/// An open tube: the cylinder `x² + y² = 1`, `0 ≤ z ≤ 2` as 4 ruled patches.
pub fn tube() -> Vec<BezierPatch<Rational>> {
    (0..4)
        .map(|k| {
            let arc = |z: i64| {
                BezierCurve::from_homogeneous(
                    quarter(k)
                        .iter()
                        .map(|[w, c, s]| vec![w.clone(), c.clone(), s.clone(), w.clone() * int(z)])
                        .collect(),
                )
                .expect("valid")
            };
            BezierPatch::from_curves_ruled(&arc(0), &arc(2)).expect("same dimension")
        })
        .collect()
}

/// A rational bicubic patch with varied weights and non-dyadic coordinates.
pub fn bicubic() -> BezierPatch<Rational> {
    let net = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| {
                    let w = q(1 + ((i * 3 + j * 5) % 4) as i64, 2);
                    let x = q(i as i64, 3);
                    let y = q(j as i64, 3) + q(i as i64, 7);
                    let z = q(((i * j) % 5) as i64 - 2, 9);
                    vec![w.clone(), w.clone() * x, w.clone() * y, w * z]
                })
                .collect()
        })
        .collect();
    BezierPatch::from_homogeneous(net).expect("valid net")
}

/// The unit circle in the plane as 4 rational quadratic pieces.
pub fn circle() -> Vec<BezierCurve<Rational>> {
    (0..4)
        .map(|k| {
            BezierCurve::from_homogeneous(quarter(k).iter().map(|p| p.to_vec()).collect())
                .expect("valid")
        })
        .collect()
}

/// A spatial rational cubic.
pub fn space_cubic() -> BezierCurve<Rational> {
    BezierCurve::from_homogeneous(vec![
        vec![int(1), int(0), int(0), int(0)],
        vec![q(2, 3), q(1, 3), q(2, 3), q(1, 7)],
        vec![q(3, 2), q(3, 2), q(-1, 2), q(3, 5)],
        vec![int(1), int(2), int(1), int(1)],
    ])
    .expect("valid")
}

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
