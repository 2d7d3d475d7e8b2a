//! Exchange formats: export and import time and file size per object, and tessellation
//! throughput against a peer, in the same run.
//!
//! * `export/OBJECT/*` for three objects — the exact torus of 16 rational biquadratic
//!   patches (a closed solid), a rational bicubic patch (open) and the unit circle
//!   (4 rational quadratic arcs): JSON, STEP (with topology: shared edges,
//!   orientation), IGES, the exact JSON sidecar, OBJ, glTF binary, meshing
//!   ([`rcagd_io::stl::object_mesh`]) and binary STL (patches), a 320 × 240 PNG
//!   (2 × 2 supersampling); the file sizes are printed once per object.
//! * `import/OBJECT/*` — reading the object back from STEP and IGES (exact rationals).
//! * `tessellation/*` — one rational bicubic patch with non-trivial weights:
//!   `rcagd_uniform_64x64` ([`tessellate_patch_uniform`]: 65 × 65 points with unit
//!   normals from the exact partials, 8192 triangles) against
//!   `curvo_grid_64x64` (curvo 0.3: `regular_sample_points` + `regular_sample_normals`
//!   on the same grid and the same triangles), and the two adaptive tessellations
//!   (`rcagd_adaptive`, chord tolerance 10⁻³; `curvo_adaptive_default`, curvo's
//!   default normal-deviation criterion). Throughput is in triangles.
//!
//! Run: `cargo bench -p rcagd-benches --features bench --bench export -- --warm-up-time 1 --measurement-time 3`

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use curvo::prelude::{AdaptiveTessellationOptions, NurbsSurface3D, Tessellation};
use nalgebra::Point4;
use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::tessellate::{tessellate_patch_adaptive, tessellate_patch_uniform, TriMesh};
use rcagd_geom::BezierPatch;
use rcagd_io::model::{Geometry, Object};
use std::hint::black_box;

#[path = "../crates/io/tests/it/samples/mod.rs"]
mod samples;

/// The torus `R = 3`, `r = 1` as 16 exact biquadratic patches ([`samples::torus`]).
fn torus() -> Object {
    Object::new(
        "torus",
        "bench",
        serde_json::Value::Null,
        Geometry::Patches(samples::torus(samples::int(3), samples::int(1))),
        Vec::new(),
    )
}

/// A rational bicubic wave with weights in `{1, 5/4, 3/2, 2}` (as in rcagd-geom's
/// grid benchmark).
fn bicubic() -> BezierPatch<f64> {
    let ws = [1.0, 1.25, 1.5, 2.0];
    let net = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| {
                    let w = ws[(i + 2 * j + i * j) % 4];
                    let x = i as f64 / 3.0 + j as f64 / 16.0;
                    let y = j as f64 / 3.0 - i as f64 / 8.0;
                    let z = ((i * 3 + j * 5) % 7) as f64 / 4.0 - 0.75;
                    vec![w, w * x, w * y, w * z]
                })
                .collect()
        })
        .collect();
    BezierPatch::from_homogeneous(net).expect("valid")
}

fn curvo_surface(p: &BezierPatch<f64>) -> NurbsSurface3D<f64> {
    // curvo stores homogeneous points weight last: (wx, wy, wz, w)
    let cps: Vec<Vec<Point4<f64>>> = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| {
                    let c = p.control_point(i, j);
                    Point4::new(c[1], c[2], c[3], c[0])
                })
                .collect()
        })
        .collect();
    let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    NurbsSurface3D::new(3, 3, knots.clone(), knots, cps)
}

/// curvo's grid with normals and the same triangles as rcagd's uniform mesh.
fn curvo_grid_mesh(s: &NurbsSurface3D<f64>, n: usize) -> TriMesh {
    let pts = s.regular_sample_points(n, n);
    let nor = s.regular_sample_normals(n, n);
    let positions: Vec<[f64; 3]> = pts.iter().flatten().map(|p| [p.x, p.y, p.z]).collect();
    let normals: Vec<[f64; 3]> = nor.iter().flatten().map(|v| [v.x, v.y, v.z]).collect();
    let cols = n + 1;
    let idx = |i: usize, j: usize| (i * cols + j) as u32;
    let mut tris = Vec::with_capacity(2 * n * n);
    for i in 0..n {
        for j in 0..n {
            tris.push([idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)]);
            tris.push([idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)]);
        }
    }
    TriMesh {
        positions,
        normals,
        triangles: tris,
    }
}

/// The unit circle as four exact rational quadratic arcs ([`samples::circle`]).
fn circle() -> Object {
    Object::new(
        "circle",
        "bench",
        serde_json::Value::Null,
        Geometry::Curves(samples::circle()),
        Vec::new(),
    )
}

/// [`bicubic`] with exact rational coordinates (an open patch object).
fn bicubic_object() -> Object {
    let q = |n: i64, d: i64| Rational::from(n) / Rational::from(d);
    let ws = [q(1, 1), q(5, 4), q(3, 2), q(2, 1)];
    let net = (0..4i64)
        .map(|i| {
            (0..4i64)
                .map(|j| {
                    let w = ws[((i + 2 * j + i * j) % 4) as usize].clone();
                    let x = q(i, 3) + q(j, 16);
                    let y = q(j, 3) - q(i, 8);
                    let z = q((i * 3 + j * 5) % 7, 4) - q(3, 4);
                    vec![w.clone(), w.clone() * x, w.clone() * y, w * z]
                })
                .collect()
        })
        .collect();
    Object::new(
        "bicubic",
        "bench",
        serde_json::Value::Null,
        Geometry::Patch(BezierPatch::from_homogeneous(net).expect("valid")),
        Vec::new(),
    )
}

fn export(c: &mut Criterion) {
    let ropts = rcagd_io::raster::RenderOptions {
        width: 320,
        height: 240,
        supersample: 2,
        ..Default::default()
    };
    let objects = [torus(), bicubic_object(), circle()];
    for o in &objects {
        let name = o.name.as_str();
        let objs = std::slice::from_ref(o);
        let step = rcagd_io::step::write_step(objs).expect("step");
        let iges = rcagd_io::iges::write_iges(objs).expect("iges");
        let side = serde_json::to_string(&rcagd_io::step::exact_sidecar(objs).expect("sidecar"))
            .expect("json");
        let json = serde_json::to_string(&rcagd_io::json::object_to_json(o)).expect("json");
        let obj = rcagd_io::obj::object_to_obj(o).expect("obj");
        let glb = rcagd_io::gltf::objects_to_glb(objs, &Default::default()).expect("glb");
        let svg = rcagd_io::svg::object_svg(o, &Default::default()).expect("svg");
        let png = rcagd_io::raster::render_png(o, &ropts).expect("png");
        let mesh = rcagd_io::stl::object_mesh(o, &Default::default()).ok();
        let stl = mesh
            .as_ref()
            .map(|m| rcagd_io::stl::write_stl_binary(name, m).expect("stl"));
        eprintln!(
            "{name} ({}, {} control points): JSON {} B, STEP {} B, IGES {} B, sidecar {} B, \
             OBJ {} B, GLB {} B, SVG {} B, PNG 320x240 {} B{}",
            o.degree_summary(),
            o.control_point_count(),
            json.len(),
            step.len(),
            iges.len(),
            side.len(),
            obj.len(),
            glb.len(),
            svg.len(),
            png.len(),
            match (&mesh, &stl) {
                (Some(m), Some(s)) =>
                    format!(", mesh {} triangles, STL {} B", m.triangles.len(), s.len()),
                _ => String::new(),
            }
        );
        let mut g = c.benchmark_group(format!("export/{name}"));
        g.bench_function("json", |b| {
            b.iter(|| black_box(rcagd_io::json::object_to_json(black_box(o))))
        });
        g.bench_function("step", |b| {
            b.iter(|| black_box(rcagd_io::step::write_step(black_box(objs))))
        });
        g.bench_function("iges", |b| {
            b.iter(|| black_box(rcagd_io::iges::write_iges(black_box(objs))))
        });
        g.bench_function("sidecar", |b| {
            b.iter(|| black_box(rcagd_io::step::exact_sidecar(black_box(objs))))
        });
        g.bench_function("obj", |b| {
            b.iter(|| black_box(rcagd_io::obj::object_to_obj(black_box(o))))
        });
        g.bench_function("glb", |b| {
            b.iter(|| {
                black_box(rcagd_io::gltf::objects_to_glb(
                    black_box(objs),
                    &Default::default(),
                ))
            })
        });
        if let Some(mesh) = &mesh {
            g.bench_function("object_mesh", |b| {
                b.iter(|| {
                    black_box(rcagd_io::stl::object_mesh(
                        black_box(o),
                        &Default::default(),
                    ))
                })
            });
            g.bench_function("stl_binary", |b| {
                b.iter(|| black_box(rcagd_io::stl::write_stl_binary(name, black_box(mesh))))
            });
        }
        g.sample_size(10);
        g.bench_function("png_320x240", |b| {
            b.iter(|| black_box(rcagd_io::raster::render_png(black_box(o), &ropts)))
        });
        g.finish();

        let mut g = c.benchmark_group(format!("import/{name}"));
        g.bench_function("step", |b| {
            b.iter(|| black_box(rcagd_io::step_read::read_step(black_box(&step))))
        });
        g.bench_function("iges", |b| {
            b.iter(|| black_box(rcagd_io::iges_read::read_iges(black_box(&iges))))
        });
        g.finish();
    }
}

fn tessellation(c: &mut Criterion) {
    const N: usize = 64;
    let p = bicubic();
    let s = curvo_surface(&p);
    let ours = tessellate_patch_uniform(&p, N, N).expect("mesh");
    let TriMesh {
        positions: cp,
        normals: cn,
        triangles: ct,
    } = curvo_grid_mesh(&s, N);
    // the two grids agree
    let d = ours
        .positions
        .iter()
        .zip(&cp)
        .map(|(a, b)| (0..3).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max))
        .fold(0.0, f64::max);
    let dn = ours
        .normals
        .iter()
        .zip(&cn)
        .map(|(a, b)| (0..3).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max))
        .fold(0.0, f64::max);
    assert!(
        d < 1e-9 && dn < 1e-6,
        "grids disagree: points {d:.1e}, normals {dn:.1e}"
    );
    assert_eq!(ct.len(), ours.triangles.len());
    let adaptive = tessellate_patch_adaptive(&p, 1e-3).expect("adaptive");
    let copts: AdaptiveTessellationOptions<f64> = AdaptiveTessellationOptions::default();
    let curvo_adaptive = s.tessellate(Some(copts.clone()));
    eprintln!(
        "tessellation: uniform {N}x{N} = {} triangles (points agree to {d:.1e}, normals to {dn:.1e}); \
         rcagd adaptive (tol 1e-3) {} triangles; curvo adaptive (default) {} triangles",
        ours.triangles.len(),
        adaptive.triangles.len(),
        curvo_adaptive.faces().len()
    );
    let mut g = c.benchmark_group("tessellation");
    g.throughput(Throughput::Elements(ours.triangles.len() as u64));
    g.bench_function("rcagd_uniform_64x64", |b| {
        b.iter(|| black_box(tessellate_patch_uniform(black_box(&p), N, N)))
    });
    g.bench_function("curvo_grid_64x64", |b| {
        b.iter(|| black_box(curvo_grid_mesh(black_box(&s), N)))
    });
    g.throughput(Throughput::Elements(adaptive.triangles.len() as u64));
    g.bench_function("rcagd_adaptive", |b| {
        b.iter(|| black_box(tessellate_patch_adaptive(black_box(&p), 1e-3)))
    });
    g.throughput(Throughput::Elements(curvo_adaptive.faces().len() as u64));
    g.bench_function("curvo_adaptive_default", |b| {
        b.iter(|| black_box(s.tessellate(Some(copts.clone()))))
    });
    g.finish();
    let _ = Scalar::to_f64(&samples::int(0));
}

criterion_group!(benches, export, tessellation);
criterion_main!(benches);
