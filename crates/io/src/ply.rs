//! PLY (Stanford polygon format) of triangle meshes, binary little-endian or ASCII.
//!
//! ```text
//! ply
//! format binary_little_endian 1.0        (or: format ascii 1.0)
//! comment rcagd mesh: NAME
//! element vertex N
//! property float x / y / z
//! property float nx / ny / nz            (when the mesh has normals)
//! element face M
//! property list uchar uint vertex_indices
//! end_header
//! ```
//!
//! Vertices are `f32` (the common PLY reader type), normals the unit normals of the exact
//! surface carried by the mesh; faces are counter-clockwise triangles. The ASCII form
//! writes the `f32` values in their shortest round-trip decimal form.

use crate::stl::check_mesh;
use crate::IoError;
use rcagd_geom::tessellate::TriMesh;
use std::fmt::Write as _;

fn header(name: &str, mesh: &TriMesh, format: &str) -> String {
    let clean: String = name
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect();
    let mut h = String::new();
    let _ = writeln!(h, "ply\nformat {format} 1.0\ncomment rcagd mesh: {clean}");
    let _ = writeln!(h, "element vertex {}", mesh.positions.len());
    h.push_str("property float x\nproperty float y\nproperty float z\n");
    if !mesh.normals.is_empty() {
        h.push_str("property float nx\nproperty float ny\nproperty float nz\n");
    }
    let _ = writeln!(h, "element face {}", mesh.triangles.len());
    h.push_str("property list uchar uint vertex_indices\nend_header\n");
    h
}

/// Binary little-endian PLY of a mesh (module docs).
///
/// # Errors
/// As [`check_mesh`].
pub fn write_ply(name: &str, mesh: &TriMesh) -> Result<Vec<u8>, IoError> {
    check_mesh(mesh)?;
    let mut out = header(name, mesh, "binary_little_endian").into_bytes();
    out.reserve(mesh.positions.len() * 24 + mesh.triangles.len() * 13);
    for (i, p) in mesh.positions.iter().enumerate() {
        for x in p {
            out.extend_from_slice(&(*x as f32).to_le_bytes());
        }
        if let Some(n) = mesh.normals.get(i) {
            for x in n {
                out.extend_from_slice(&(*x as f32).to_le_bytes());
            }
        }
    }
    for t in &mesh.triangles {
        out.push(3);
        for i in t {
            out.extend_from_slice(&i.to_le_bytes());
        }
    }
    Ok(out)
}

/// ASCII PLY of a mesh (module docs).
///
/// # Errors
/// As [`check_mesh`].
pub fn write_ply_ascii(name: &str, mesh: &TriMesh) -> Result<String, IoError> {
    check_mesh(mesh)?;
    let mut s = header(name, mesh, "ascii");
    for (i, p) in mesh.positions.iter().enumerate() {
        let _ = write!(s, "{} {} {}", p[0] as f32, p[1] as f32, p[2] as f32);
        if let Some(n) = mesh.normals.get(i) {
            let _ = write!(s, " {} {} {}", n[0] as f32, n[1] as f32, n[2] as f32);
        }
        s.push('\n');
    }
    for t in &mesh.triangles {
        let _ = writeln!(s, "3 {} {} {}", t[0], t[1], t[2]);
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri() -> TriMesh {
        TriMesh {
            positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.1, 0.0]],
            normals: vec![[0.0, 0.0, 1.0]; 3],
            triangles: vec![[0, 1, 2]],
        }
    }

    #[test]
    fn ascii_snapshot() {
        let s = write_ply_ascii("t", &tri()).expect("valid");
        let want = "ply\nformat ascii 1.0\ncomment rcagd mesh: t\nelement vertex 3\n\
                    property float x\nproperty float y\nproperty float z\n\
                    property float nx\nproperty float ny\nproperty float nz\n\
                    element face 1\nproperty list uchar uint vertex_indices\nend_header\n\
                    0 0 0 0 0 1\n1 0 0 0 0 1\n0 0.1 0 0 0 1\n3 0 1 2\n";
        assert_eq!(s, want);
    }

    #[test]
    fn binary_layout() {
        let b = write_ply("t", &tri()).expect("valid");
        let h = header("t", &tri(), "binary_little_endian");
        assert!(b.starts_with(h.as_bytes()));
        assert_eq!(b.len(), h.len() + 3 * 24 + 13);
        assert_eq!(b[h.len() + 72], 3);
        let mut m = tri();
        m.triangles[0][2] = 9;
        assert!(write_ply("t", &m).is_err());
    }
}
