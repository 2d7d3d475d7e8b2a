//! glTF 2.0 binary (`.glb`): triangle meshes with normals from the exact surface, and
//! curves as line strips.
//!
//! One file holds a scene with one node per part (object), named after it. A part has a
//! mesh whose primitives are
//!
//! * triangles (`mode` 4): `POSITION` and `NORMAL` (`f32` `VEC3`, the unit normals of
//!   the exact surface carried by [`TriMesh`]) and `u32` indices;
//! * line strips (`mode` 3): `POSITION` only, one per polyline (the curves of an
//!   object, sampled adaptively).
//!
//! Each part has its own material (metallic-roughness, metallic 0, roughness 0.6,
//! double-sided, a colour of a fixed palette). rcagd's geometry is `z`-up; glTF is
//! `y`-up, so the part nodes hang below a root node rotated by −90° about `x`
//! (`(x, y, z) ↦ (x, z, −y)`); coordinates are unchanged, one unit stays one unit.
//!
//! Layout (glTF 2.0 §4.4): the 12-byte header `glTF`, version 2, total length; a JSON
//! chunk padded with spaces and a BIN chunk padded with zeros to 4-byte boundaries.
//! Accessors of positions carry `min` and `max` as the specification requires.

use crate::model::Object;
use crate::stl::{check_mesh, object_mesh, object_size, MeshOptions};
use crate::IoError;
use rcagd_geom::tessellate::{tessellate_curve_adaptive, TriMesh};
use serde_json::{json, Value};

/// One part of a glTF scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GlbPart<'a> {
    /// The node's name.
    pub name: &'a str,
    /// A triangle mesh, if any.
    pub mesh: Option<&'a TriMesh>,
    /// Polylines drawn as line strips (polylines with fewer than 2 points are skipped).
    pub polylines: &'a [Vec<[f64; 3]>],
    /// Base colour, linear RGB in `[0, 1]`.
    pub color: [f32; 3],
}

/// The palette of part colours (linear RGB).
pub const PALETTE: [[f32; 3]; 6] = [
    [0.12, 0.32, 0.62],
    [0.72, 0.30, 0.10],
    [0.16, 0.52, 0.26],
    [0.45, 0.30, 0.65],
    [0.70, 0.62, 0.15],
    [0.10, 0.48, 0.55],
];

struct Builder {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
}

impl Builder {
    fn view(&mut self, bytes: &[u8], target: u32) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        self.views.push(json!({
            "buffer": 0,
            "byteOffset": offset,
            "byteLength": bytes.len(),
            "target": target,
        }));
        self.views.len() - 1
    }

    /// A `VEC3` float accessor (with `min`/`max` when `bounds`).
    fn vec3(&mut self, v: &[[f32; 3]], bounds: bool) -> usize {
        let mut bytes = Vec::with_capacity(v.len() * 12);
        let mut lo = [f32::INFINITY; 3];
        let mut hi = [f32::NEG_INFINITY; 3];
        for p in v {
            for k in 0..3 {
                bytes.extend_from_slice(&p[k].to_le_bytes());
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let view = self.view(&bytes, 34962);
        let mut acc = json!({
            "bufferView": view,
            "componentType": 5126,
            "count": v.len(),
            "type": "VEC3",
        });
        if bounds {
            acc["min"] = json!(lo);
            acc["max"] = json!(hi);
        }
        self.accessors.push(acc);
        self.accessors.len() - 1
    }

    fn indices(&mut self, t: &[[u32; 3]]) -> usize {
        let mut bytes = Vec::with_capacity(t.len() * 12);
        for tri in t {
            for i in tri {
                bytes.extend_from_slice(&i.to_le_bytes());
            }
        }
        let view = self.view(&bytes, 34963);
        self.accessors.push(json!({
            "bufferView": view,
            "componentType": 5125,
            "count": t.len() * 3,
            "type": "SCALAR",
        }));
        self.accessors.len() - 1
    }
}

fn f32x3(p: [f64; 3]) -> [f32; 3] {
    p.map(|x| x as f32)
}

/// The unit normal in `f32` (re-normalised after rounding; `+z` for a zero normal).
fn unit_f32(n: [f64; 3]) -> [f32; 3] {
    let v = f32x3(n);
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if l.is_finite() && l > 0.0 {
        [v[0] / l, v[1] / l, v[2] / l]
    } else {
        [0.0, 0.0, 1.0]
    }
}

/// A `.glb` of parts (module docs).
///
/// # Errors
/// [`IoError::Invalid`] for no parts, a bad mesh ([`check_mesh`]), a non-finite
/// polyline point, or a file beyond 4 GiB.
pub fn write_glb(parts: &[GlbPart]) -> Result<Vec<u8>, IoError> {
    if parts.is_empty() {
        return Err(IoError::Invalid("no parts to write to glTF".into()));
    }
    let mut b = Builder {
        bin: Vec::new(),
        views: Vec::new(),
        accessors: Vec::new(),
    };
    let mut nodes = vec![json!({
        "name": "rcagd (z up)",
        "rotation": [-std::f64::consts::FRAC_1_SQRT_2, 0.0, 0.0, std::f64::consts::FRAC_1_SQRT_2],
        "children": (1..=parts.len()).collect::<Vec<_>>(),
    })];
    let mut meshes = Vec::new();
    let mut materials = Vec::new();
    for part in parts {
        let mut prims = Vec::new();
        let material = materials.len();
        materials.push(json!({
            "name": part.name,
            "pbrMetallicRoughness": {
                "baseColorFactor": [part.color[0], part.color[1], part.color[2], 1.0],
                "metallicFactor": 0.0,
                "roughnessFactor": 0.6,
            },
            "doubleSided": true,
        }));
        if let Some(m) = part.mesh.filter(|m| !m.triangles.is_empty()) {
            check_mesh(m)?;
            let pos: Vec<[f32; 3]> = m.positions.iter().map(|&p| f32x3(p)).collect();
            let p = b.vec3(&pos, true);
            let mut attributes = json!({ "POSITION": p });
            if m.normals.len() == m.positions.len() {
                let nor: Vec<[f32; 3]> = m.normals.iter().map(|&n| unit_f32(n)).collect();
                attributes["NORMAL"] = json!(b.vec3(&nor, false));
            }
            let idx = b.indices(&m.triangles);
            prims.push(json!({
                "attributes": attributes,
                "indices": idx,
                "material": material,
                "mode": 4,
            }));
        }
        for (k, pl) in part.polylines.iter().enumerate() {
            if pl.len() < 2 {
                continue;
            }
            if let Some(i) = pl.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
                return Err(IoError::Invalid(format!(
                    "part {:?}, polyline {k}: point {i} is not finite",
                    part.name
                )));
            }
            let pos: Vec<[f32; 3]> = pl.iter().map(|&p| f32x3(p)).collect();
            let p = b.vec3(&pos, true);
            prims.push(json!({
                "attributes": { "POSITION": p },
                "material": material,
                "mode": 3,
            }));
        }
        let mut node = json!({ "name": part.name });
        if !prims.is_empty() {
            node["mesh"] = json!(meshes.len());
            meshes.push(json!({ "name": part.name, "primitives": prims }));
        }
        nodes.push(node);
    }
    while !b.bin.len().is_multiple_of(4) {
        b.bin.push(0);
    }
    let mut doc = json!({
        "asset": {
            "version": "2.0",
            "generator": format!("rcagd-io {}", env!("CARGO_PKG_VERSION")),
        },
        "scene": 0,
        "scenes": [{ "name": "rcagd", "nodes": [0] }],
        "nodes": nodes,
        "materials": materials,
    });
    if !meshes.is_empty() {
        doc["meshes"] = json!(meshes);
        doc["accessors"] = json!(b.accessors);
        doc["bufferViews"] = json!(b.views);
        doc["buffers"] = json!([{ "byteLength": b.bin.len() }]);
    }
    let mut text = serde_json::to_vec(&doc)?;
    while text.len() % 4 != 0 {
        text.push(b' ');
    }
    let has_bin = !b.bin.is_empty();
    let total = 12 + 8 + text.len() + if has_bin { 8 + b.bin.len() } else { 0 };
    let total32 = u32::try_from(total)
        .map_err(|_| IoError::Invalid("the glTF binary would exceed 4 GiB".into()))?;
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&total32.to_le_bytes());
    out.extend_from_slice(&(text.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&text);
    if has_bin {
        out.extend_from_slice(&(b.bin.len() as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(&b.bin);
    }
    Ok(out)
}

/// A `.glb` of objects: patches meshed by [`object_mesh`], curves sampled adaptively
/// (chord tolerance `opts.relative_tolerance · size`, at most 2¹² segments each) as
/// line strips; colours from [`PALETTE`] in object order.
///
/// # Errors
/// As [`object_mesh`] and [`write_glb`].
pub fn objects_to_glb(objects: &[Object], opts: &MeshOptions) -> Result<Vec<u8>, IoError> {
    let mut meshes = Vec::with_capacity(objects.len());
    let mut lines = Vec::with_capacity(objects.len());
    for o in objects {
        meshes.push(if o.geometry.patches().is_empty() {
            None
        } else {
            Some(object_mesh(o, opts)?)
        });
        let tol = opts.relative_tolerance * object_size(o);
        let pls = o
            .geometry
            .drawable_curves()?
            .iter()
            .map(|c| tessellate_curve_adaptive(c, tol, 12).map(|p| p.points))
            .collect::<Result<Vec<_>, _>>()?;
        lines.push(pls);
    }
    let parts: Vec<GlbPart> = objects
        .iter()
        .enumerate()
        .map(|(k, o)| GlbPart {
            name: &o.name,
            mesh: meshes[k].as_ref(),
            polylines: &lines[k],
            color: PALETTE[k % PALETTE.len()],
        })
        .collect();
    write_glb(&parts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glb_layout_and_json() {
        let m = TriMesh {
            positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 2.0, 0.0]],
            normals: vec![[0.0, 0.0, 2.0]; 3],
            triangles: vec![[0, 1, 2]],
        };
        let pl = vec![vec![[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]];
        let glb = write_glb(&[GlbPart {
            name: "a",
            mesh: Some(&m),
            polylines: &pl,
            color: PALETTE[0],
        }])
        .expect("valid");
        assert_eq!(&glb[0..4], b"glTF");
        let u =
            |k: usize| u32::from_le_bytes([glb[k], glb[k + 1], glb[k + 2], glb[k + 3]]) as usize;
        assert_eq!(u(4), 2);
        assert_eq!(u(8), glb.len());
        let jlen = u(12);
        assert_eq!(&glb[16..20], b"JSON");
        assert_eq!(jlen % 4, 0);
        let doc: Value = serde_json::from_slice(&glb[20..20 + jlen]).expect("json");
        assert_eq!(doc["asset"]["version"], "2.0");
        assert_eq!(doc["accessors"][0]["max"], json!([1.0, 2.0, 0.0]));
        assert_eq!(doc["meshes"][0]["primitives"][1]["mode"], 3);
        let blen = u(20 + jlen);
        assert_eq!(&glb[24 + jlen..28 + jlen], b"BIN\0");
        assert_eq!(
            blen,
            doc["buffers"][0]["byteLength"].as_u64().expect("n") as usize
        );
        // normals re-normalised
        let nview = doc["accessors"][1]["bufferView"].as_u64().expect("n") as usize;
        let off = doc["bufferViews"][nview]["byteOffset"].as_u64().expect("n") as usize;
        let base = 28 + jlen + off;
        let z = f32::from_le_bytes([glb[base + 8], glb[base + 9], glb[base + 10], glb[base + 11]]);
        assert_eq!(z, 1.0);
        assert!(write_glb(&[]).is_err());
    }
}
