//! Crack-free triangle meshes of patch sets: every shared boundary is tessellated once.
//!
//! Meshing each patch on its own grid leaves cracks where two patches meet (their
//! boundary samples differ) and winds each patch by its own `∂ᵤx × ∂ᵥx`, so half of a
//! closed surface can face inward. Here the patches are first joined into the boundary
//! representation of [`crate::step::build_topology`] (edges shared exactly, faces
//! oriented consistently per shell, closed shells outward), then:
//!
//! 1. **Edges**: each topological edge is sampled once, adaptively within the chord
//!    tolerance ([`adaptive_curve_params`]); its end points are the exact topological
//!    vertices, rounded once. Every face that uses the edge uses these same vertices,
//!    found in its own parameter through the Möbius reparametrization that relates its
//!    boundary curve to the edge (`σ = ρs / ((1 − s) + ρs)`). A boundary that collapses
//!    to a point (a sphere's pole) is one vertex shared by every face around it.
//! 2. **Faces**: the interior of each patch is the adaptive tensor grid of
//!    [`adaptive_patch_params`] (at least two segments per direction) without its
//!    boundary rows; the ring between the shared boundary polylines and the grid's
//!    outermost interior rows is triangulated side by side by merging the two
//!    polylines in parameter order (each side's region is bounded by the segments that
//!    join the patch corners to the interior corners, so the four regions tile the
//!    ring). Every triangle is made counter-clockwise in the parameter plane, then
//!    reversed on a face that is flipped in its shell.
//! 3. **Normals**: the unit normal of the exact surface, averaged over the faces that
//!    meet at a vertex (oriented as in the shell); where it degenerates on every face
//!    (a pole) the area-weighted normal of the adjacent triangles.
//!
//! The result has no duplicate positions: a closed shell gives a closed, consistently
//! wound 2-manifold mesh (each edge in exactly two triangles, traversed in opposite
//! directions), wound outward.

use crate::step::{build_topology_with, embed_e3, Topology};
use crate::IoError;
use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::grid::{
    cross, eval_curve3_f64, norm, sub, PatchEvaluator3, SurfacePoint3, DEGENERATE_NORMAL_RELATIVE,
};
use rcagd_geom::tessellate::{
    adaptive_curve_params, adaptive_patch_params, tessellate_patch_adaptive, TriMesh,
    MAX_CURVE_DEPTH, MAX_TESSELLATION_POINTS,
};
use rcagd_geom::BezierPatch;
use std::collections::HashMap;

/// The adaptive depth used for edges (as for curves in OBJ export).
const EDGE_DEPTH: usize = 16;

/// How one side of a face is bounded.
enum Side {
    /// Vertex indices with their side parameter `σ ∈ [0, 1]` (increasing along the
    /// side's direction in the boundary loop).
    Polyline(Vec<(f64, u32)>),
    /// The side collapses to one vertex.
    Point(u32),
}

/// Vertices with accumulated normals.
#[derive(Default)]
struct Builder {
    positions: Vec<[f64; 3]>,
    normal_sum: Vec<[f64; 3]>,
    normal_count: Vec<u32>,
    triangles: Vec<[u32; 3]>,
}

impl Builder {
    fn vertex(&mut self, p: [f64; 3]) -> Result<u32, IoError> {
        if !p.iter().all(|x| x.is_finite()) {
            return Err(IoError::Invalid(format!(
                "the mesh has a non-finite vertex {p:?}"
            )));
        }
        if self.positions.len() >= MAX_TESSELLATION_POINTS {
            return Err(IoError::Invalid(format!(
                "the mesh would need more than {MAX_TESSELLATION_POINTS} vertices"
            )));
        }
        self.positions.push(p);
        self.normal_sum.push([0.0; 3]);
        self.normal_count.push(0);
        u32::try_from(self.positions.len() - 1)
            .map_err(|_| IoError::Invalid("the mesh has more vertices than u32 indices".into()))
    }

    /// Room for `vertices` more vertices and `triangles` more triangles.
    fn reserve(&mut self, vertices: usize, triangles: usize) {
        self.positions.reserve(vertices);
        self.normal_sum.reserve(vertices);
        self.normal_count.reserve(vertices);
        self.triangles.reserve(triangles);
    }

    fn add_normal(&mut self, v: u32, n: Option<[f64; 3]>) {
        if let Some(n) = n {
            let s = &mut self.normal_sum[v as usize];
            for k in 0..3 {
                s[k] += n[k];
            }
            self.normal_count[v as usize] += 1;
        }
    }

    fn finish(self) -> TriMesh {
        let Builder {
            positions,
            normal_sum,
            normal_count,
            triangles,
        } = self;
        // area-weighted triangle normals for vertices without a surface normal (formed
        // only if some vertex needs them)
        let mut fallback_sums: Option<Vec<[f64; 3]>> = None;
        let mut fallback = |i: usize| {
            fallback_sums.get_or_insert_with(|| {
                let mut f = vec![[0.0; 3]; positions.len()];
                for t in &triangles {
                    let [a, b, c] = t.map(|i| positions[i as usize]);
                    let n = cross(sub(b, a), sub(c, a));
                    for &i in t {
                        for k in 0..3 {
                            f[i as usize][k] += n[k];
                        }
                    }
                }
                f
            })[i]
        };
        let normals = (0..positions.len())
            .map(|i| {
                let s = if normal_count[i] > 0 {
                    normal_sum[i]
                } else {
                    fallback(i)
                };
                let l = norm(s);
                if l > 0.0 && l.is_finite() {
                    [s[0] / l, s[1] / l, s[2] / l]
                } else {
                    let f = fallback(i);
                    let lf = norm(f);
                    if lf > 0.0 && lf.is_finite() {
                        [f[0] / lf, f[1] / lf, f[2] / lf]
                    } else {
                        [0.0, 0.0, 1.0]
                    }
                }
            })
            .collect();
        TriMesh {
            positions,
            normals,
            triangles,
        }
    }
}

fn to3(v: &[f64]) -> [f64; 3] {
    [
        v.first().copied().unwrap_or(0.0),
        v.get(1).copied().unwrap_or(0.0),
        v.get(2).copied().unwrap_or(0.0),
    ]
}

fn rational_point(p: &[Rational]) -> [f64; 3] {
    let v: Vec<f64> = p.iter().map(Scalar::to_f64).collect();
    to3(&v)
}

/// The unit normal `∂ᵤx × ∂ᵥx / |…|` of a patch from its partials at a point, `None`
/// where it degenerates.
fn surface_normal(d: &SurfacePoint3, flipped: bool) -> Option<[f64; 3]> {
    let (du, dv) = (d.du, d.dv);
    let n = cross(du, dv);
    let l = norm(n);
    let scale = norm(du).max(norm(dv));
    if !(l.is_finite() && l > DEGENERATE_NORMAL_RELATIVE * scale * scale && l > 0.0) {
        return None;
    }
    let s = if flipped { -1.0 / l } else { 1.0 / l };
    Some([n[0] * s, n[1] * s, n[2] * s])
}

/// The parameter point of side `side` (boundary-loop order of
/// [`BezierPatch::boundary_curves`]) at loop parameter `σ`.
fn side_uv(side: usize, s: f64) -> [f64; 2] {
    match side {
        0 => [s, 0.0],
        1 => [1.0, s],
        2 => [1.0 - s, 1.0],
        _ => [0.0, 1.0 - s],
    }
}

/// `φ_ρ(s) = ρs / ((1 − s) + ρs)`.
fn mobius(rho: f64, s: f64) -> f64 {
    if rho == 1.0 {
        s
    } else {
        let d = (1.0 - s) + rho * s;
        if d == 0.0 {
            s
        } else {
            rho * s / d
        }
    }
}

/// Appends the triangles of the region between an outer and an inner polyline, both
/// ordered by their parameter in `[0, 1]`. A vertex of `poles` (a collapsed side of the
/// face) is left at once and reached last: a triangle with a pole and two inner
/// vertices would lie along an iso-parameter line through the pole (a fold); the
/// collapsed side's own fan covers that corner.
fn stitch(
    outer: &[(f64, u32, [f64; 2])],
    inner: &[(f64, u32, [f64; 2])],
    poles: &[u32],
    out: &mut Vec<([u32; 3], [[f64; 2]; 3])>,
) {
    let (mut a, mut c) = (0usize, 0usize);
    while a + 1 < outer.len() || c + 1 < inner.len() {
        let advance_outer = if a + 1 >= outer.len() {
            false
        } else if c + 1 >= inner.len() || poles.contains(&outer[a].1) {
            true
        } else if poles.contains(&outer[a + 1].1) {
            false
        } else {
            outer[a + 1].0 <= inner[c + 1].0
        };
        if advance_outer {
            out.push((
                [outer[a].1, outer[a + 1].1, inner[c].1],
                [outer[a].2, outer[a + 1].2, inner[c].2],
            ));
            a += 1;
        } else {
            out.push((
                [outer[a].1, inner[c + 1].1, inner[c].1],
                [outer[a].2, inner[c + 1].2, inner[c].2],
            ));
            c += 1;
        }
    }
}

/// At least two segments per direction (so that the interior grid has a row).
fn at_least_two(mut ps: Vec<f64>) -> Vec<f64> {
    if ps.len() < 3 {
        ps = vec![0.0, 0.5, 1.0];
    }
    ps
}

/// One crack-free triangle mesh of patches (module docs) within the chord tolerance
/// `tol` (absolute).
///
/// # Errors
/// [`IoError::Invalid`] for a patch outside E1–E3, with a control point of weight 0 or
/// weights of mixed sign, or a mesh beyond the size limits; [`IoError::Geom`] from the
/// adaptive sampling (a bad tolerance, a point at infinity).
pub fn shared_edge_mesh(patches: &[BezierPatch<Rational>], tol: f64) -> Result<TriMesh, IoError> {
    let e3 = patches
        .iter()
        .enumerate()
        .map(|(k, p)| embed_e3(p, &format!("patch {k}")))
        .collect::<Result<Vec<_>, _>>()?;
    let e3_f64: Vec<BezierPatch<f64>> = e3.iter().map(BezierPatch::to_f64).collect();
    let topo = build_topology_with(&e3, Some(&e3_f64))?;
    mesh_topology(&e3, &e3_f64, &topo, tol)
}

/// The mesh of drawable patches (pieces whose weight function has one sign): the
/// [`shared_edge_mesh`]; where the patches have no boundary representation (a control
/// point of weight 0, control weights of mixed sign on a piece whose weight function
/// has one sign) each patch is meshed on its own adaptive grid and the meshes are
/// concatenated (closed, but with cracks at the shared boundaries).
///
/// # Errors
/// As [`tessellate_patch_adaptive`] and the mesh size limits.
pub fn patches_mesh(patches: &[BezierPatch<Rational>], tol: f64) -> Result<TriMesh, IoError> {
    match shared_edge_mesh(patches, tol) {
        Ok(m) => Ok(m),
        Err(IoError::Invalid(_)) => {
            let mut out = TriMesh::default();
            for p in patches {
                let m = tessellate_patch_adaptive(p, tol)?;
                crate::stl::append_mesh(&mut out, &m)?;
            }
            Ok(out)
        }
        Err(e) => Err(e),
    }
}

/// The `u` and `v` parameters of a face's tensor grid.
type GridParams = (Vec<f64>, Vec<f64>);

fn mesh_topology(
    patches: &[BezierPatch<Rational>],
    patches_f64: &[BezierPatch<f64>],
    topo: &Topology,
    tol: f64,
) -> Result<TriMesh, IoError> {
    let mut b = Builder::default();
    // each face's grid parameters first (their errors are reported where the face is
    // meshed, as before), so that the mesh is allocated once
    let mut face_params: Vec<Option<Result<GridParams, IoError>>> = topo
        .faces
        .iter()
        .map(|face| {
            let pf = patches_f64
                .get(face.patch)
                .ok_or_else(|| IoError::Invalid(format!("face of missing patch {}", face.patch)))?;
            let (us, vs) = adaptive_patch_params(pf, tol)?;
            Ok((at_least_two(us), at_least_two(vs)))
        })
        .map(Some)
        .collect();
    let (mut verts, mut tris) = (topo.vertices.len(), 0usize);
    for (us, vs) in face_params.iter().flatten().flatten() {
        verts += us.len() * vs.len();
        tris += 2 * (us.len() + 1) * (vs.len() + 1);
    }
    b.reserve(verts, tris);
    let mut vertex_of: HashMap<&[Rational], u32> = HashMap::new();
    let mut topo_vertex = Vec::with_capacity(topo.vertices.len());
    for v in &topo.vertices {
        let id = b.vertex(rational_point(v))?;
        vertex_of.insert(v.as_slice(), id);
        topo_vertex.push(id);
    }
    // edges: parameters and vertex ids (ends are the topological vertices)
    let mut edge_samples: Vec<Vec<(f64, u32)>> = Vec::with_capacity(topo.edges.len());
    for e in &topo.edges {
        // the f64 curve once (adaptive_curve_params rounds the exact curve the same way)
        let c = e.curve.to_f64();
        let params = adaptive_curve_params(&c, tol, EDGE_DEPTH.min(MAX_CURVE_DEPTH))?;
        let mut samples = Vec::with_capacity(params.len());
        let last = params.len().saturating_sub(1);
        for (i, &s) in params.iter().enumerate() {
            let id = if i == 0 {
                topo_vertex[e.start]
            } else if i == last {
                topo_vertex[e.end]
            } else {
                b.vertex(eval_curve3_f64(&c, s))?
            };
            samples.push((s, id));
        }
        edge_samples.push(samples);
    }
    let mut extra_vertices: HashMap<Vec<Rational>, u32> = HashMap::new();
    let mut ders: Vec<SurfacePoint3> = Vec::new();
    for (fi, face) in topo.faces.iter().enumerate() {
        let patch = &patches[face.patch];
        let pf = &patches_f64[face.patch];
        let mut eval = PatchEvaluator3::new(pf)?;
        let (m, n) = patch.degree();
        // the four sides
        let mut sides: Vec<Side> = Vec::with_capacity(4);
        for side in 0..4 {
            if let Some(k) = face.sides.iter().position(|&s| s == side) {
                let (e, fwd) = face.edges[k];
                let rho = face
                    .ratios
                    .get(k)
                    .and_then(Option::as_ref)
                    .map_or(1.0, Scalar::to_f64);
                let mut pts: Vec<(f64, u32)> = edge_samples[e]
                    .iter()
                    .map(|&(s, id)| {
                        let t = mobius(rho, s);
                        (if fwd { t } else { 1.0 - t }, id)
                    })
                    .collect();
                if !fwd {
                    pts.reverse();
                }
                sides.push(Side::Polyline(pts));
            } else {
                // collapsed: one vertex at the exact point (the side's first corner in
                // loop order, BezierPatch::boundary_curves)
                let (i, j) = [(0, 0), (m, 0), (m, n), (0, n)][side];
                let h = patch.control_point(i, j);
                let p: Vec<Rational> = h[1..].iter().map(|x| x.clone() / h[0].clone()).collect();
                let id = match vertex_of.get(p.as_slice()) {
                    Some(&id) => id,
                    None => match extra_vertices.get(&p) {
                        Some(&id) => id,
                        None => {
                            let id = b.vertex(rational_point(&p))?;
                            extra_vertices.insert(p, id);
                            id
                        }
                    },
                };
                sides.push(Side::Point(id));
            }
        }
        // the interior grid (adaptive_patch_params rounds the exact patch as to_f64 does)
        let (us, vs) = face_params
            .get_mut(fi)
            .and_then(Option::take)
            .ok_or_else(|| IoError::Invalid("a face without grid parameters".into()))??;
        let (nu, nv) = (us.len() - 1, vs.len() - 1);
        let mut grid = vec![0u32; (nu + 1) * (nv + 1)];
        let at = |i: usize, j: usize| i * (nv + 1) + j;
        eval.grid_derivatives(&us[1..nu], &vs[1..nv], &mut ders)?;
        let mut inner = ders.iter();
        for i in 1..nu {
            for j in 1..nv {
                let d = inner.next().ok_or_else(|| {
                    IoError::Invalid("the interior grid has fewer points than parameters".into())
                })?;
                let id = b.vertex(d.point)?;
                b.add_normal(id, surface_normal(d, face.flipped));
                grid[at(i, j)] = id;
            }
        }
        // the interior cells: counter-clockwise in the parameter plane (both parameter
        // lists increase), so reversed exactly on a flipped face
        for i in 1..nu.saturating_sub(1) {
            for j in 1..nv.saturating_sub(1) {
                for mut t in [
                    [grid[at(i, j)], grid[at(i + 1, j)], grid[at(i + 1, j + 1)]],
                    [grid[at(i, j)], grid[at(i + 1, j + 1)], grid[at(i, j + 1)]],
                ] {
                    if face.flipped {
                        t.swap(1, 2);
                    }
                    b.triangles.push(t);
                }
            }
        }
        let mut tris: Vec<([u32; 3], [[f64; 2]; 3])> = Vec::new();
        // the inner ring, side by side in loop direction
        let poles: Vec<u32> = sides
            .iter()
            .filter_map(|b| match b {
                Side::Point(id) => Some(*id),
                Side::Polyline(_) => None,
            })
            .collect();
        for (side, bound) in sides.iter().enumerate() {
            let inner_ij: Vec<(usize, usize)> = match side {
                0 => (1..nu).map(|i| (i, 1)).collect(),
                1 => (1..nv).map(|j| (nu - 1, j)).collect(),
                2 => (1..nu).rev().map(|i| (i, nv - 1)).collect(),
                _ => (1..nv).rev().map(|j| (1, j)).collect(),
            };
            let n_in = inner_ij.len();
            let inner: Vec<(f64, u32, [f64; 2])> = inner_ij
                .iter()
                .enumerate()
                .map(|(k, &(i, j))| {
                    let tau = if n_in > 1 {
                        k as f64 / (n_in - 1) as f64
                    } else {
                        0.5
                    };
                    (tau, grid[at(i, j)], [us[i], vs[j]])
                })
                .collect();
            let outer: Vec<(f64, u32, [f64; 2])> = match bound {
                Side::Polyline(pts) => pts
                    .iter()
                    .map(|&(s, id)| (s, id, side_uv(side, s)))
                    .collect(),
                Side::Point(id) => vec![(0.5, *id, side_uv(side, 0.5))],
            };
            stitch(&outer, &inner, &poles, &mut tris);
        }
        // boundary vertices: the surface normal at their parameter on this face (a
        // side's last point is the next side's first)
        for (side, bound) in sides.iter().enumerate() {
            if let Side::Polyline(pts) = bound {
                for &(s, id) in &pts[..pts.len().saturating_sub(1)] {
                    let [u, v] = side_uv(side, s);
                    b.add_normal(id, surface_normal(&eval.derivatives(u, v), face.flipped));
                }
            }
        }
        for (mut t, [p, q, r]) in tris {
            if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
                continue;
            }
            let area = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
            if (area < 0.0) != face.flipped {
                t.swap(1, 2);
            }
            b.triangles.push(t);
        }
    }
    Ok(b.finish())
}

/// The edge structure of a triangle mesh after welding bit-identical positions: what
/// makes a mesh a closed, consistently wound 2-manifold.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgeCensus {
    /// Undirected edges of exactly one triangle (the open boundary, or cracks).
    pub boundary: usize,
    /// Undirected edges of more than two triangles.
    pub non_manifold: usize,
    /// Directed edges traversed by more than one triangle (inconsistent winding).
    pub repeated_directed: usize,
    /// `V − E + F` over the welded vertices used by triangles (2 for a sphere, 0 for a
    /// torus).
    pub euler: i64,
    /// `Σ a·(b × c) / 6`: the enclosed volume of a closed mesh, positive when it is
    /// wound outward.
    pub volume: f64,
}

impl EdgeCensus {
    /// `true` for a closed, consistently wound 2-manifold mesh (every edge in exactly
    /// two triangles, traversed in opposite directions) wound outward.
    pub fn is_closed_outward(&self) -> bool {
        self.boundary == 0
            && self.non_manifold == 0
            && self.repeated_directed == 0
            && self.volume > 0.0
    }
}

/// The [`EdgeCensus`] of a mesh. Triangles that weld to fewer than three vertices are
/// ignored.
pub fn edge_census(m: &TriMesh) -> EdgeCensus {
    let mut id: HashMap<[u64; 3], usize> = HashMap::new();
    let weld: Vec<usize> = m
        .positions
        .iter()
        .map(|p| {
            let n = id.len();
            *id.entry(p.map(f64::to_bits)).or_insert(n)
        })
        .collect();
    let mut directed: HashMap<(usize, usize), usize> = HashMap::new();
    let mut undirected: HashMap<(usize, usize), usize> = HashMap::new();
    let mut used = std::collections::HashSet::new();
    let (mut faces, mut volume) = (0i64, 0.0);
    for t in &m.triangles {
        let Some(w) = t
            .iter()
            .map(|&i| weld.get(i as usize).copied())
            .collect::<Option<Vec<usize>>>()
        else {
            continue;
        };
        let (a, b, c) = (w[0], w[1], w[2]);
        if a == b || b == c || a == c {
            continue;
        }
        faces += 1;
        used.extend([a, b, c]);
        for (x, y) in [(a, b), (b, c), (c, a)] {
            *directed.entry((x, y)).or_default() += 1;
            *undirected.entry((x.min(y), x.max(y))).or_default() += 1;
        }
        let [p, q, r] = t.map(|i| m.positions[i as usize]);
        let cr = cross(q, r);
        volume += (p[0] * cr[0] + p[1] * cr[1] + p[2] * cr[2]) / 6.0;
    }
    EdgeCensus {
        boundary: undirected.values().filter(|&&n| n == 1).count(),
        non_manifold: undirected.values().filter(|&&n| n > 2).count(),
        repeated_directed: directed.values().filter(|&&n| n > 1).count(),
        euler: used.len() as i64 - undirected.len() as i64 + faces,
        volume,
    }
}
