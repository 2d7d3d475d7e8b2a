//! STL (binary and ASCII) of triangle meshes, and the meshing of objects shared by the
//! mesh formats ([`object_mesh`]).
//!
//! * Binary STL: an 80-byte header (`rcagd binary STL: name`, never starting with
//!   `solid`, so readers do not take it for ASCII), the triangle count (`u32`, little
//!   endian), then per triangle the facet normal and the three vertices as `f32`
//!   triples and a zero attribute word — 50 bytes per triangle.
//! * ASCII STL: `solid name` / `facet normal nx ny nz` / `outer loop` / three
//!   `vertex x y z` / `endloop` / `endfacet` … `endsolid name`, numbers in the
//!   shortest round-trip exponent form of the `f64` (`1e0`, `-2.5e-1`).
//!
//! The facet normal is the unit normal of the triangle's plane, `(b − a) × (c − a)`
//! normalised (the triangles of [`rcagd_geom::tessellate`] are counter-clockwise about
//! the surface normal `∂ᵤx × ∂ᵥx`); for a degenerate triangle the mean of its vertex
//! normals (from the exact surface), failing that `0 0 0`.

use crate::model::Object;
use crate::IoError;
use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::grid::{cross, sub};
use rcagd_geom::tessellate::TriMesh;
use std::fmt::Write as _;

/// How objects are meshed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshOptions {
    /// Chord tolerance relative to the object's size (the diagonal of its control
    /// points' bounding box): every patch is meshed by
    /// [`tessellate_patch_adaptive`] with `tolerance · size`.
    pub relative_tolerance: f64,
}

impl Default for MeshOptions {
    fn default() -> Self {
        MeshOptions {
            relative_tolerance: 5e-4,
        }
    }
}

/// The diagonal of the bounding box of the Euclidean control points of patches
/// (points at infinity ignored; 1 if there are none).
pub(crate) fn net_size<'a>(coords: impl Iterator<Item = &'a [Rational]>) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for h in coords {
        let w = Scalar::to_f64(&h[0]);
        if w == 0.0 || !w.is_finite() {
            continue;
        }
        for k in 0..3 {
            let x = h.get(k + 1).map_or(0.0, |c| Scalar::to_f64(c) / w);
            if x.is_finite() {
                lo[k] = lo[k].min(x);
                hi[k] = hi[k].max(x);
            }
        }
    }
    let d = (0..3)
        .map(|k| (hi[k] - lo[k]).max(0.0).powi(2))
        .sum::<f64>()
        .sqrt();
    if d.is_finite() && d > 0.0 {
        d
    } else {
        1.0
    }
}

/// The size of an object (see [`net_size`]), over its curves and patches.
pub fn object_size(o: &Object) -> f64 {
    let curves = o.geometry.curves();
    let patches = o.geometry.patches();
    let it = curves
        .iter()
        .flat_map(|c| c.control_points())
        .chain(patches.iter().flat_map(|p| p.coords().chunks(p.dim() + 1)));
    net_size(it)
}

/// One triangle mesh of all patches of an object (module docs of
/// [`rcagd_geom::tessellate`]: vertex normals from the exact surface), the patches'
/// meshes concatenated.
///
/// # Errors
/// [`IoError::Invalid`] for an object without patches, a bad tolerance or a patch whose
/// weight function has a zero (patches with weights of mixed sign are meshed as pieces
/// of one sign, [`crate::model::Geometry::drawable_patches`]), [`IoError::Geom`] from
/// the tessellation (a point at infinity, dimension above 3).
pub fn object_mesh(o: &Object, opts: &MeshOptions) -> Result<TriMesh, IoError> {
    let patches = o.geometry.patches();
    if patches.is_empty() {
        return Err(IoError::Invalid(format!(
            "object {:?} has no patches to mesh (it is a {})",
            o.name,
            o.kind()
        )));
    }
    if !(opts.relative_tolerance.is_finite() && opts.relative_tolerance > 0.0) {
        return Err(IoError::Invalid(format!(
            "the relative chord tolerance must be positive, got {}",
            opts.relative_tolerance
        )));
    }
    let tol = opts.relative_tolerance * object_size(o);
    // pieces with weights of one sign (a weight zero inside would mesh a spike), shared
    // boundaries tessellated once
    let pieces: Vec<_> = o
        .geometry
        .drawable_patches()?
        .into_iter()
        .map(|(_, p)| p)
        .collect();
    crate::mesh::patches_mesh(&pieces, tol)
}

/// Appends `m` to `out` (indices shifted).
pub(crate) fn append_mesh(out: &mut TriMesh, m: &TriMesh) -> Result<(), IoError> {
    let base = u32::try_from(out.positions.len())
        .ok()
        .filter(|b| b.checked_add(m.positions.len() as u32).is_some())
        .ok_or_else(|| IoError::Invalid("the mesh has more vertices than u32 indices".into()))?;
    out.positions.extend_from_slice(&m.positions);
    out.normals.extend_from_slice(&m.normals);
    out.triangles
        .extend(m.triangles.iter().map(|t| t.map(|i| i + base)));
    Ok(())
}

/// Checks indices, normal count and finiteness of a mesh.
///
/// # Errors
/// [`IoError::Invalid`] naming the triangle or vertex.
pub fn check_mesh(mesh: &TriMesh) -> Result<(), IoError> {
    if !mesh.normals.is_empty() && mesh.normals.len() != mesh.positions.len() {
        return Err(IoError::Invalid(format!(
            "{} normals for {} positions (need one per position, or none)",
            mesh.normals.len(),
            mesh.positions.len()
        )));
    }
    if let Some(i) = mesh
        .positions
        .iter()
        .position(|p| !p.iter().all(|x| x.is_finite()))
    {
        return Err(IoError::Invalid(format!(
            "vertex {i} has a non-finite coordinate: {:?}",
            mesh.positions[i]
        )));
    }
    if let Some(i) = mesh
        .normals
        .iter()
        .position(|p| !p.iter().all(|x| x.is_finite()))
    {
        return Err(IoError::Invalid(format!("normal {i} is not finite")));
    }
    let n = mesh.positions.len();
    if let Some((k, t)) = mesh
        .triangles
        .iter()
        .enumerate()
        .find(|(_, t)| t.iter().any(|&i| i as usize >= n))
    {
        return Err(IoError::Invalid(format!(
            "triangle {k} refers to vertex {:?}, but there are {n} vertices",
            t
        )));
    }
    Ok(())
}

fn unit(v: [f64; 3]) -> Option<[f64; 3]> {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    (l.is_finite() && l > 0.0).then(|| [v[0] / l, v[1] / l, v[2] / l])
}

/// The facet normal of triangle `t` (module docs). Indices must be valid.
pub(crate) fn facet_normal(mesh: &TriMesh, t: [u32; 3]) -> [f64; 3] {
    let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
    if let Some(n) = unit(cross(sub(b, a), sub(c, a))) {
        return n;
    }
    if mesh.normals.len() == mesh.positions.len() {
        let mut s = [0.0; 3];
        for i in t {
            let n = mesh.normals[i as usize];
            for k in 0..3 {
                s[k] += n[k];
            }
        }
        if let Some(n) = unit(s) {
            return n;
        }
    }
    [0.0; 3]
}

/// Binary STL of a mesh (module docs).
///
/// # Errors
/// As [`check_mesh`], and [`IoError::Invalid`] for more than `u32::MAX` triangles.
pub fn write_stl_binary(name: &str, mesh: &TriMesh) -> Result<Vec<u8>, IoError> {
    check_mesh(mesh)?;
    let count = u32::try_from(mesh.triangles.len())
        .map_err(|_| IoError::Invalid("more than u32::MAX triangles".into()))?;
    let mut out = Vec::with_capacity(84 + 50 * mesh.triangles.len());
    let mut header = format!("rcagd binary STL: {name}").into_bytes();
    header.resize(80, b' ');
    out.extend_from_slice(&header);
    out.extend_from_slice(&count.to_le_bytes());
    for &t in &mesh.triangles {
        let n = facet_normal(mesh, t);
        for x in n {
            out.extend_from_slice(&(x as f32).to_le_bytes());
        }
        for i in t {
            for x in mesh.positions[i as usize] {
                out.extend_from_slice(&(x as f32).to_le_bytes());
            }
        }
        out.extend_from_slice(&0u16.to_le_bytes());
    }
    Ok(out)
}

/// A name for `solid`/`endsolid` lines: whitespace becomes `_`, non-ASCII `?`.
fn solid_name(name: &str) -> String {
    let n: String = name
        .chars()
        .map(|c| {
            if c.is_whitespace() {
                '_'
            } else if c.is_ascii() {
                c
            } else {
                '?'
            }
        })
        .collect();
    if n.is_empty() {
        "rcagd".into()
    } else {
        n
    }
}

/// ASCII STL of a mesh (module docs).
///
/// # Errors
/// As [`check_mesh`].
pub fn write_stl_ascii(name: &str, mesh: &TriMesh) -> Result<String, IoError> {
    check_mesh(mesh)?;
    let name = solid_name(name);
    let mut s = String::with_capacity(64 + 250 * mesh.triangles.len());
    let _ = writeln!(s, "solid {name}");
    for &t in &mesh.triangles {
        let n = facet_normal(mesh, t);
        let _ = writeln!(s, "  facet normal {:e} {:e} {:e}", n[0], n[1], n[2]);
        s.push_str("    outer loop\n");
        for i in t {
            let p = mesh.positions[i as usize];
            let _ = writeln!(s, "      vertex {:e} {:e} {:e}", p[0], p[1], p[2]);
        }
        s.push_str("    endloop\n  endfacet\n");
    }
    let _ = writeln!(s, "endsolid {name}");
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri() -> TriMesh {
        TriMesh {
            positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.5, 0.0]],
            normals: vec![[0.0, 0.0, 1.0]; 3],
            triangles: vec![[0, 1, 2]],
        }
    }

    #[test]
    fn ascii_snapshot() {
        let s = write_stl_ascii("one tri", &tri()).expect("valid");
        let want = "solid one_tri\n  facet normal 0e0 0e0 1e0\n    outer loop\n      vertex 0e0 0e0 0e0\n      vertex 1e0 0e0 0e0\n      vertex 0e0 5e-1 0e0\n    endloop\n  endfacet\nendsolid one_tri\n";
        assert_eq!(s, want);
    }

    #[test]
    fn binary_layout() {
        let b = write_stl_binary("t", &tri()).expect("valid");
        assert_eq!(b.len(), 84 + 50);
        assert!(b.starts_with(b"rcagd binary STL: t"));
        assert_eq!(u32::from_le_bytes([b[80], b[81], b[82], b[83]]), 1);
        let f = |k: usize| f32::from_le_bytes([b[k], b[k + 1], b[k + 2], b[k + 3]]);
        assert_eq!((f(84), f(88), f(92)), (0.0, 0.0, 1.0));
        assert_eq!(f(84 + 12 + 24 + 4), 0.5);
    }

    #[test]
    fn bad_meshes_are_errors() {
        let mut m = tri();
        m.triangles.push([0, 1, 7]);
        assert!(write_stl_binary("x", &m).is_err());
        let mut m = tri();
        m.positions[1][2] = f64::NAN;
        assert!(write_stl_ascii("x", &m).is_err());
        let mut m = tri();
        m.normals.pop();
        assert!(check_mesh(&m).is_err());
    }
}
