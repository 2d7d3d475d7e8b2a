//! Wavefront OBJ text for triangle meshes (with normals) and polylines.
//!
//! * A mesh becomes `v x y z` lines, `vn nx ny nz` lines (one normal per vertex) and
//!   `f a//a b//b c//c` faces (1-based, counter-clockwise as given).
//! * Polylines become `v` lines and one `l i j k …` element per polyline.
//!
//! Numbers are written as the shortest decimal that reads back to the same `f64`.

use crate::model::{Geometry, Object};
use crate::IoError;
use rcagd_algebra::Scalar;
use rcagd_geom::tessellate::{tessellate_curve_adaptive, Polyline, TriMesh};
use std::fmt::Write as _;

/// A coordinate as written: `0` for both zeros, else the shortest round-trip decimal
/// (written straight into the output, no string per number).
struct Num(f64);

impl std::fmt::Display for Num {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.0 == 0.0 {
            f.write_str("0")
        } else {
            write!(f, "{}", self.0)
        }
    }
}

fn num(x: f64) -> Num {
    Num(x)
}

fn check_finite(kind: &str, i: usize, p: &[f64; 3]) -> Result<(), IoError> {
    if p.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(IoError::Invalid(format!(
            "{kind} {i} has a non-finite coordinate: {p:?}"
        )))
    }
}

/// Sanitizes an object name for an `o` line (whitespace becomes `_`).
fn obj_name(name: &str) -> String {
    let n: String = name
        .chars()
        .map(|c| if c.is_whitespace() { '_' } else { c })
        .collect();
    if n.is_empty() {
        "object".into()
    } else {
        n
    }
}

/// OBJ text of a triangle mesh. `normals` is either empty or has one normal per
/// position (then faces are written `a//a b//b c//c`).
///
/// # Errors
/// [`IoError::Invalid`] if a triangle index is out of range, the normal count is
/// neither 0 nor the position count, or a coordinate is NaN/infinite.
pub fn mesh_to_obj(
    name: &str,
    positions: &[[f64; 3]],
    normals: &[[f64; 3]],
    triangles: &[[u32; 3]],
) -> Result<String, IoError> {
    if !normals.is_empty() && normals.len() != positions.len() {
        return Err(IoError::Invalid(format!(
            "{} normals for {} positions (need one per position, or none)",
            normals.len(),
            positions.len()
        )));
    }
    // about 60 bytes per `v`/`vn` line and 30 per face
    let mut s = String::with_capacity(120 * positions.len() + 30 * triangles.len() + 64);
    let _ = writeln!(
        s,
        "# rcagd OBJ: {} vertices, {} triangles",
        positions.len(),
        triangles.len()
    );
    let _ = writeln!(s, "o {}", obj_name(name));
    for (i, p) in positions.iter().enumerate() {
        check_finite("position", i, p)?;
        let _ = writeln!(s, "v {} {} {}", num(p[0]), num(p[1]), num(p[2]));
    }
    for (i, n) in normals.iter().enumerate() {
        check_finite("normal", i, n)?;
        let _ = writeln!(s, "vn {} {} {}", num(n[0]), num(n[1]), num(n[2]));
    }
    for (k, t) in triangles.iter().enumerate() {
        if let Some(bad) = t.iter().find(|&&i| i as usize >= positions.len()) {
            return Err(IoError::Invalid(format!(
                "triangle {k} refers to vertex {bad}, but there are {} vertices",
                positions.len()
            )));
        }
        let [a, b, c] = t.map(|i| i + 1);
        if normals.is_empty() {
            let _ = writeln!(s, "f {a} {b} {c}");
        } else {
            let _ = writeln!(s, "f {a}//{a} {b}//{b} {c}//{c}");
        }
    }
    Ok(s)
}

/// OBJ text of polylines: all vertices, then one `l` element per polyline (polylines
/// with fewer than two points are skipped).
///
/// # Errors
/// [`IoError::Invalid`] for a NaN/infinite coordinate.
pub fn polylines_to_obj(name: &str, polylines: &[Vec<[f64; 3]>]) -> Result<String, IoError> {
    let total: usize = polylines.iter().map(Vec::len).sum();
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# rcagd OBJ: {} polylines, {total} vertices",
        polylines.len()
    );
    let _ = writeln!(s, "o {}", obj_name(name));
    let mut lines = String::new();
    let mut next = 1usize;
    for (k, pl) in polylines.iter().enumerate() {
        for (i, p) in pl.iter().enumerate() {
            check_finite(&format!("polyline {k} point"), i, p)?;
            let _ = writeln!(s, "v {} {} {}", num(p[0]), num(p[1]), num(p[2]));
        }
        if pl.len() >= 2 {
            let idx: Vec<String> = (next..next + pl.len()).map(|i| i.to_string()).collect();
            let _ = writeln!(lines, "l {}", idx.join(" "));
        }
        next += pl.len();
    }
    s.push_str(&lines);
    Ok(s)
}

/// OBJ text of a [`TriMesh`] (positions, per-vertex normals, triangles).
///
/// # Errors
/// As [`mesh_to_obj`].
pub fn trimesh_to_obj(name: &str, mesh: &TriMesh) -> Result<String, IoError> {
    mesh_to_obj(name, &mesh.positions, &mesh.normals, &mesh.triangles)
}

/// OBJ text of [`Polyline`]s.
///
/// # Errors
/// As [`polylines_to_obj`].
pub fn polyline_list_to_obj(name: &str, polylines: &[Polyline]) -> Result<String, IoError> {
    let pts: Vec<Vec<[f64; 3]>> = polylines.iter().map(|p| p.points.clone()).collect();
    polylines_to_obj(name, &pts)
}

/// One mesh from several (vertex indices offset; normals kept only if every mesh has
/// them).
///
/// # Errors
/// [`IoError::Invalid`] if the vertex count exceeds `u32`.
pub fn merge_meshes(meshes: &[TriMesh]) -> Result<TriMesh, IoError> {
    let with_normals = meshes.iter().all(|m| m.normals.len() == m.positions.len());
    let mut out = TriMesh::default();
    for m in meshes {
        let base = u32::try_from(out.positions.len())
            .map_err(|_| IoError::Invalid("more than 2³² vertices".into()))?;
        out.positions.extend_from_slice(&m.positions);
        if with_normals {
            out.normals.extend_from_slice(&m.normals);
        }
        for t in &m.triangles {
            let shifted = t.map(|i| i.checked_add(base));
            let [Some(a), Some(b), Some(c)] = shifted else {
                return Err(IoError::Invalid("more than 2³² vertices".into()));
            };
            out.triangles.push([a, b, c]);
        }
    }
    Ok(out)
}

/// The default chord tolerance for exporting geometry: `10⁻³` of the diagonal of the
/// bounding box of the (Euclidean, finite) control points (1e-3 if there are none).
pub fn default_tolerance(g: &Geometry) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let mut add = |h: &[rcagd_algebra::Rational]| {
        let Some((w, rest)) = h.split_first() else {
            return;
        };
        let w = Scalar::to_f64(w);
        if w == 0.0 {
            return;
        }
        for (k, x) in rest.iter().take(3).enumerate() {
            let v = Scalar::to_f64(x) / w;
            if v.is_finite() {
                lo[k] = lo[k].min(v);
                hi[k] = hi[k].max(v);
            }
        }
    };
    for c in g.curves() {
        c.control_points().for_each(&mut add);
    }
    for p in g.patches() {
        let d = p.dim() + 1;
        p.coords().chunks(d).for_each(&mut add);
    }
    let diag2: f64 = lo
        .iter()
        .zip(&hi)
        .filter(|(a, b)| a.is_finite() && b.is_finite())
        .map(|(a, b)| (b - a) * (b - a))
        .sum();
    let diag = diag2.sqrt();
    if diag > 0.0 && diag.is_finite() {
        1e-3 * diag
    } else {
        1e-3
    }
}

/// OBJ text of exact geometry: curves as adaptive polylines (`l`), patches as one
/// merged adaptive triangle mesh with normals, both within the chord tolerance `tol`
/// (via `rcagd_geom::tessellate`).
///
/// # Errors
/// [`IoError::Geom`] if tessellation fails (dimension above 3, a point at infinity,
/// a bad tolerance), [`IoError::Invalid`] as in [`mesh_to_obj`] and for a curve or
/// patch whose weight function has a zero (pieces with weights of mixed sign are split
/// into pieces of one sign first, [`Geometry::drawable_patches`]).
pub fn geometry_to_obj(name: &str, g: &Geometry, tol: f64) -> Result<String, IoError> {
    match g {
        Geometry::Curve(_) | Geometry::Curves(_) => {
            let lines = g
                .drawable_curves()?
                .iter()
                .map(|c| tessellate_curve_adaptive(c, tol, 16))
                .collect::<Result<Vec<_>, _>>()?;
            polyline_list_to_obj(name, &lines)
        }
        Geometry::Patch(_) | Geometry::Patches(_) => {
            let pieces: Vec<_> = g.drawable_patches()?.into_iter().map(|(_, p)| p).collect();
            trimesh_to_obj(name, &crate::mesh::patches_mesh(&pieces, tol)?)
        }
    }
}

/// OBJ text of an object with the [`default_tolerance`].
///
/// # Errors
/// As [`geometry_to_obj`].
pub fn object_to_obj(o: &Object) -> Result<String, IoError> {
    geometry_to_obj(&o.name, &o.geometry, default_tolerance(&o.geometry))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_snapshot() {
        let obj = mesh_to_obj(
            "tri angle",
            &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.5, -0.0]],
            &[[0.0, 0.0, 1.0]; 3],
            &[[0, 1, 2]],
        )
        .expect("valid");
        let want =
            "# rcagd OBJ: 3 vertices, 1 triangles\no tri_angle\nv 0 0 0\nv 1 0 0\nv 0 0.5 0\n\
                    vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nf 1//1 2//2 3//3\n";
        assert_eq!(obj, want);
    }

    #[test]
    fn bad_meshes_are_errors() {
        assert!(mesh_to_obj("m", &[[0.0; 3]], &[], &[[0, 0, 1]]).is_err());
        assert!(mesh_to_obj("m", &[[0.0; 3]], &[[0.0; 3]; 2], &[]).is_err());
        assert!(mesh_to_obj("m", &[[f64::NAN, 0.0, 0.0]], &[], &[]).is_err());
        assert_eq!(
            mesh_to_obj("m", &[[0.0; 3]; 3], &[], &[[0, 1, 2]])
                .expect("valid")
                .lines()
                .last(),
            Some("f 1 2 3")
        );
    }

    #[test]
    fn polyline_snapshot() {
        let obj = polylines_to_obj(
            "p",
            &[
                vec![[0.0, 0.0, 0.0], [1.0, 2.0, 3.0]],
                vec![[4.0, 5.0, 6.0]],
                vec![[7.0, 8.0, 9.0], [0.25, 0.0, 0.0]],
            ],
        )
        .expect("valid");
        let want = "# rcagd OBJ: 3 polylines, 5 vertices\no p\nv 0 0 0\nv 1 2 3\nv 4 5 6\nv 7 8 9\nv 0.25 0 0\nl 1 2\nl 4 5\n";
        assert_eq!(obj, want);
    }
}
