//! Crack-free meshes of patch sets (`rcagd_io::mesh`): closed shells become closed,
//! consistently and outward wound 2-manifold meshes.

use crate::samples::{int, q, sphere, torus, tube};
use rcagd_algebra::Rational;
use rcagd_geom::tessellate::{tessellate_patch_adaptive, TriMesh};
use rcagd_geom::BezierPatch;
use rcagd_io::mesh::{edge_census, patches_mesh, shared_edge_mesh};
use std::collections::HashMap;

fn closed_manifold(m: &TriMesh, euler: i64, volume: f64, rel_tol: f64, what: &str) {
    let a = edge_census(m);
    assert_eq!(a.boundary, 0, "{what}: cracks");
    assert_eq!(a.non_manifold, 0, "{what}: non-manifold edges");
    assert_eq!(a.repeated_directed, 0, "{what}: inconsistent winding");
    assert_eq!(a.euler, euler, "{what}: Euler characteristic");
    let rel = (a.volume - volume).abs() / volume;
    assert!(
        a.volume > 0.0 && rel < rel_tol,
        "{what}: volume {} (outward), want {volume}",
        a.volume
    );
    // normals point outward where the winding does
    for t in &m.triangles {
        let [p, r, s] = t.map(|i| m.positions[i as usize]);
        let f = [
            (r[1] - p[1]) * (s[2] - p[2]) - (r[2] - p[2]) * (s[1] - p[1]),
            (r[2] - p[2]) * (s[0] - p[0]) - (r[0] - p[0]) * (s[2] - p[2]),
            (r[0] - p[0]) * (s[1] - p[1]) - (r[1] - p[1]) * (s[0] - p[0]),
        ];
        let n = m.normals[t[0] as usize];
        let l = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
        if l > 1e-9 {
            let d = (f[0] * n[0] + f[1] * n[1] + f[2] * n[2]) / l;
            assert!(
                d > 0.0,
                "{what}: a vertex normal against its triangle ({d}): {:?} {:?} area {l}",
                [p, r, s],
                t.map(|i| m.normals[i as usize])
            );
        }
    }
}

/// `tol` relative to a size of about 1.
const TOL: f64 = 2e-3;

#[test]
fn sphere_mesh_is_a_closed_outward_2_manifold() {
    let s = sphere([1, -2, 3], 2);
    let m = shared_edge_mesh(&s, TOL).expect("mesh");
    closed_manifold(
        &m,
        2,
        4.0 / 3.0 * std::f64::consts::PI * 8.0,
        2e-3,
        "sphere",
    );
    // the same patches with half of them reversed in u (wound inward on their own) still
    // give an outward mesh: the orientation comes from the shell
    let mixed: Vec<BezierPatch<Rational>> = s
        .iter()
        .enumerate()
        .map(|(k, p)| if k % 2 == 0 { p.reverse_u() } else { p.clone() })
        .collect();
    let m = shared_edge_mesh(&mixed, TOL).expect("mesh");
    closed_manifold(
        &m,
        2,
        4.0 / 3.0 * std::f64::consts::PI * 8.0,
        2e-3,
        "sphere, mixed orientation",
    );
}

#[test]
fn torus_mesh_is_a_closed_outward_2_manifold() {
    let t = torus(int(3), int(1));
    let m = shared_edge_mesh(&t, TOL * 4.0).expect("mesh");
    let vol = 2.0 * std::f64::consts::PI.powi(2) * 3.0;
    closed_manifold(&m, 0, vol, 1e-2, "torus");
    let t = torus(q(5, 2), q(1, 3));
    let m = shared_edge_mesh(&t, TOL).expect("mesh");
    let vol = 2.0 * std::f64::consts::PI.powi(2) * 2.5 / 9.0;
    closed_manifold(&m, 0, vol, 1e-2, "thin torus");
}

/// The per-patch meshes this module replaces leave cracks on the same sphere: the check
/// above can fail.
#[test]
fn independent_patch_meshes_have_cracks() {
    let s = sphere([0, 0, 0], 1);
    let mut all = TriMesh::default();
    for (k, p) in s.iter().enumerate() {
        // different tolerances per patch, as adaptive meshes of different patches get
        let m = tessellate_patch_adaptive(p, if k % 2 == 0 { 1e-3 } else { 3e-4 }).expect("mesh");
        let base = all.positions.len() as u32;
        all.positions.extend(m.positions);
        all.normals.extend(m.normals);
        all.triangles
            .extend(m.triangles.iter().map(|t| t.map(|i| i + base)));
    }
    assert!(edge_census(&all).boundary > 0);
}

#[test]
fn open_tube_has_only_its_two_rim_circles_as_boundary() {
    let m = shared_edge_mesh(&tube(), TOL).expect("mesh");
    let a = edge_census(&m);
    assert_eq!(a.non_manifold, 0);
    assert_eq!(a.repeated_directed, 0, "consistent winding");
    assert!(a.boundary > 0);
    // every boundary vertex lies on a rim (z = 0 or z = 2)
    let mut count: HashMap<(u32, u32), usize> = HashMap::new();
    for t in &m.triangles {
        for (x, y) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            *count.entry((x.min(y), x.max(y))).or_default() += 1;
        }
    }
    for ((x, y), n) in count {
        if n == 1 {
            for v in [x, y] {
                let z = m.positions[v as usize][2];
                assert!(
                    z.abs() < 1e-12 || (z - 2.0).abs() < 1e-12,
                    "boundary vertex at z = {z}"
                );
            }
        }
    }
}

#[test]
fn patches_without_topology_fall_back_to_independent_meshes() {
    // a control point of weight 0 inside (the weight function is still positive, 3/4 at
    // the centre): no boundary representation (STEP refuses such a patch), but a mesh
    let net: Vec<Vec<Vec<Rational>>> = (0..3)
        .map(|i| {
            (0..3)
                .map(|j| {
                    let w = if i == 1 && j == 1 { 0 } else { 1 };
                    vec![int(w), int(i * w), int(j * w), int((i * j) % 2 * w)]
                })
                .collect()
        })
        .collect();
    let p = BezierPatch::from_homogeneous(net).expect("biquadratic");
    assert!(shared_edge_mesh(std::slice::from_ref(&p), TOL).is_err());
    let m = patches_mesh(&[p], TOL).expect("mesh");
    assert!(!m.triangles.is_empty());
}
