//! Tessellation of rational Bézier curves and patches into polylines and triangle meshes.
//!
//! Everything is evaluated in `f64` through [`crate::grid`]; inputs may be exact (any
//! [`Scalar`]) and are converted once (correctly rounded). Curves and patches in E1, E2
//! are embedded in E3 with zero trailing coordinates; higher dimensions are rejected.
//!
//! * **Curves, uniform**: `n` segments at `tᵢ = i/n`.
//! * **Curves, adaptive**: recursive bisection in the parameter. A segment `[a, b]` is
//!   accepted when the points at `a + (b−a)·{¼, ½, ¾}` lie within `tol` of the chord
//!   `x(a) x(b)` (Euclidean point–segment distance), or when the depth bound is reached.
//!   The recursion starts from `max(p, 1)` uniform segments (`p` the degree), so a
//!   segment whose midpoint happens to lie on its chord (an S-shaped cubic) is still
//!   caught by the quarter points.
//! * **Patches, uniform**: an `nu × nv` grid, two triangles per cell
//!   `(i,j),(i+1,j),(i+1,j+1)` and `(i,j),(i+1,j+1),(i,j+1)`, counter-clockwise about
//!   the normal `∂ᵤx × ∂ᵥx`. Normals come from the exact partial derivatives
//!   ([`crate::grid::eval_patch_grid_with_normals`]); where they degenerate (a sphere's
//!   pole, a collapsed edge) the normal is taken at a neighbouring parameter moved
//!   `10⁻⁶` towards the inside of the domain, failing that from the adjacent faces.
//!   Triangles whose doubled area `|e₁ × e₂|` is at most `10⁻¹²` times their longest
//!   squared edge (e.g. the collapsed triangles at a pole) are dropped. Vertices are
//!   shared, so the mesh of one patch is watertight.
//! * **Patches, adaptive**: a tensor grid `us × vs` (so the mesh is watertight) whose
//!   strips are chosen per direction. The start is a uniform grid with counts from the
//!   second differences of the (Euclidean) control net: for a polynomial patch the
//!   piecewise-linear interpolant on that triangulation deviates by at most
//!   `⅛ (M_uu/nu² + 2 M_uv/(nu nv) + M_vv/nv²)` with `M_uu = m(m−1) max|Δ²ᵤ Pᵢⱼ|`,
//!   `M_uv = m n max|ΔᵤΔᵥ Pᵢⱼ|`, `M_vv = n(n−1) max|Δ²ᵥ Pᵢⱼ|` (Filip, Magedson & Markot
//!   1986, *Surface algorithms using bounds on derivatives*, CAGD 3), and the counts make
//!   each term `≤ tol/3` (at least the degree, at most 256 per direction). Rational patches are not covered by that bound, so the grid is
//!   then checked: the patch is evaluated at every edge midpoint and cell centre and
//!   compared with the mesh at the same parameters (edge midpoint, diagonal midpoint);
//!   a cell centre's deviation is charged to the direction whose edges of that cell
//!   deviate at least twice as much as the other's (to both when neither dominates);
//!   each `u`- or `v`-strip whose sampled deviation exceeds `tol` is split into
//!   `⌈1.1 √(err/tol)⌉` parts (the error shrinks like the square of the width), until
//!   every sampled deviation is `≤ tol`. The guarantee is on these samples, not a bound
//!   on the Hausdorff distance.

use crate::curve::BezierCurve;
use crate::error::GeomError;
use crate::grid::{
    control_net_scale, cross, eval_curve3_f64, eval_patch_derivatives_f64,
    eval_patch_grid_with_normals, linspace, norm, sub, unit_normal, PatchGridRows3,
    DEGENERATE_NORMAL_RELATIVE,
};
use crate::patch::BezierPatch;
use rcagd_algebra::Scalar;

/// A polyline in E3.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Polyline {
    /// The vertices in parameter order.
    pub points: Vec<[f64; 3]>,
}

/// An indexed triangle mesh with per-vertex unit normals.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TriMesh {
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Unit vertex normals (same length as `positions`).
    pub normals: Vec<[f64; 3]>,
    /// Triangles as vertex indices, counter-clockwise about the normals.
    pub triangles: Vec<[u32; 3]>,
}

/// The largest recursion depth accepted by the adaptive curve tessellation.
pub const MAX_CURVE_DEPTH: usize = 40;
/// The largest segment count per direction the adaptive patch tessellation will use.
pub const MAX_PATCH_SEGMENTS: usize = 2048;
/// The largest number of polyline points or mesh vertices any tessellation produces
/// (2²⁴); larger requests are a [`GeomError::Parameter`], not an out-of-memory abort.
pub const MAX_TESSELLATION_POINTS: usize = 1 << 24;

fn too_many(what: &str) -> GeomError {
    GeomError::Parameter(format!(
        "{what} would need more than {MAX_TESSELLATION_POINTS} points"
    ))
}

fn check_tol(tol: f64) -> Result<(), GeomError> {
    if tol.is_finite() && tol > 0.0 {
        Ok(())
    } else {
        Err(GeomError::Parameter(format!(
            "chord tolerance must be positive and finite, got {tol}"
        )))
    }
}

fn check_segments(n: usize, what: &str) -> Result<(), GeomError> {
    if n == 0 {
        Err(GeomError::Parameter(format!(
            "{what}: the number of segments must be at least 1, got 0"
        )))
    } else {
        Ok(())
    }
}

/// The curve with `f64` homogeneous coordinates, in E3 (zero-padded from E1/E2).
fn curve3<F: Scalar>(curve: &BezierCurve<F>) -> Result<BezierCurve<f64>, GeomError> {
    let d = curve.dim();
    if d > 3 {
        return Err(GeomError::Dimension(format!(
            "tessellation needs a curve in E1, E2 or E3, this one lies in E{d}"
        )));
    }
    let mut coords = Vec::with_capacity((curve.degree() + 1) * 4);
    for p in curve.control_points() {
        coords.extend(p.iter().map(Scalar::to_f64));
        coords.extend(std::iter::repeat_n(0.0, 3 - d));
    }
    BezierCurve::from_flat(3, coords)
}

/// The patch with `f64` homogeneous coordinates, in E3 (zero-padded from E1/E2).
fn patch3<F: Scalar>(patch: &BezierPatch<F>) -> Result<BezierPatch<f64>, GeomError> {
    let d = patch.dim();
    if d > 3 {
        return Err(GeomError::Dimension(format!(
            "tessellation needs a patch in E1, E2 or E3, this one lies in E{d}"
        )));
    }
    let (m, n) = patch.degree();
    let mut coords = Vec::with_capacity((m + 1) * (n + 1) * 4);
    for p in patch.coords().chunks(d + 1) {
        coords.extend(p.iter().map(Scalar::to_f64));
        coords.extend(std::iter::repeat_n(0.0, 3 - d));
    }
    BezierPatch::from_flat(3, m, n, coords)
}

fn point3(curve: &BezierCurve<f64>, t: f64) -> Result<[f64; 3], GeomError> {
    // the value of eval_curve_f64, without its allocations
    let p = eval_curve3_f64(curve, t);
    if p.iter().all(|c| c.is_finite()) {
        Ok(p)
    } else {
        Err(GeomError::Weight(format!(
            "the curve passes through a point at infinity (weight 0) near t = {t}"
        )))
    }
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    norm(sub(a, b))
}

fn lerp(a: [f64; 3], b: [f64; 3], s: f64) -> [f64; 3] {
    [
        a[0] + s * (b[0] - a[0]),
        a[1] + s * (b[1] - a[1]),
        a[2] + s * (b[2] - a[2]),
    ]
}

/// Euclidean distance from `x` to the segment `ab`.
pub fn point_segment_distance(x: [f64; 3], a: [f64; 3], b: [f64; 3]) -> f64 {
    let ab = sub(b, a);
    let l2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    let ax = sub(x, a);
    if l2 == 0.0 {
        return norm(ax);
    }
    let s = ((ax[0] * ab[0] + ax[1] * ab[1] + ax[2] * ab[2]) / l2).clamp(0.0, 1.0);
    dist(x, lerp(a, b, s))
}

/// A uniform polyline: `segments + 1` points at `tᵢ = i / segments`.
///
/// # Errors
/// [`GeomError::Parameter`] for zero segments or more than
/// [`MAX_TESSELLATION_POINTS`] points, [`GeomError::Dimension`] beyond E3,
/// [`GeomError::Weight`] if a sample is a point at infinity.
pub fn tessellate_curve_uniform<F: Scalar>(
    curve: &BezierCurve<F>,
    segments: usize,
) -> Result<Polyline, GeomError> {
    check_segments(segments, "curve tessellation")?;
    if segments >= MAX_TESSELLATION_POINTS {
        return Err(too_many("the uniform polyline"));
    }
    let c = curve3(curve)?;
    let points = linspace(0.0, 1.0, segments)
        .into_iter()
        .map(|t| point3(&c, t))
        .collect::<Result<_, _>>()?;
    Ok(Polyline { points })
}

/// The parameters of the adaptive polyline (see the module docs): increasing, from `0`
/// to `1`; every segment `[a, b]` has its points at `¼, ½, ¾` within `tol` of the chord
/// unless it sits at depth `max_depth` (clamped to [`MAX_CURVE_DEPTH`]).
///
/// # Errors
/// [`GeomError::Parameter`] for a tolerance that is not positive and finite or a result
/// of more than [`MAX_TESSELLATION_POINTS`] points, [`GeomError::Dimension`] beyond E3,
/// [`GeomError::Weight`] at a point at infinity.
pub fn adaptive_curve_params<F: Scalar>(
    curve: &BezierCurve<F>,
    tol: f64,
    max_depth: usize,
) -> Result<Vec<f64>, GeomError> {
    check_tol(tol)?;
    let c = curve3(curve)?;
    let max_depth = max_depth.min(MAX_CURVE_DEPTH);
    let start = linspace(0.0, 1.0, curve.degree().max(1));
    let mut params = vec![0.0];
    let mut prev = point3(&c, 0.0)?;
    for w in start.windows(2) {
        let pb = point3(&c, w[1])?;
        refine_curve(&c, (w[0], prev), (w[1], pb), tol, max_depth, &mut params)?;
        prev = pb;
    }
    Ok(params)
}

/// Pushes the parameters of `(a, b]` for segment `[a, b]` (recursive bisection).
fn refine_curve(
    c: &BezierCurve<f64>,
    (a, pa): (f64, [f64; 3]),
    (b, pb): (f64, [f64; 3]),
    tol: f64,
    depth_left: usize,
    out: &mut Vec<f64>,
) -> Result<(), GeomError> {
    let m = 0.5 * (a + b);
    let pm = point3(c, m)?;
    let q1 = point3(c, 0.5 * (a + m))?;
    let q3 = point3(c, 0.5 * (m + b))?;
    let err = point_segment_distance(pm, pa, pb)
        .max(point_segment_distance(q1, pa, pb))
        .max(point_segment_distance(q3, pa, pb));
    if err <= tol || depth_left == 0 || m <= a || m >= b {
        if out.len() >= MAX_TESSELLATION_POINTS {
            return Err(too_many(
                "the adaptive polyline (chord tolerance too small)",
            ));
        }
        out.push(b);
        return Ok(());
    }
    refine_curve(c, (a, pa), (m, pm), tol, depth_left - 1, out)?;
    refine_curve(c, (m, pm), (b, pb), tol, depth_left - 1, out)
}

/// The adaptive polyline of [`adaptive_curve_params`], evaluated.
///
/// # Errors
/// As [`adaptive_curve_params`].
pub fn tessellate_curve_adaptive<F: Scalar>(
    curve: &BezierCurve<F>,
    tol: f64,
    max_depth: usize,
) -> Result<Polyline, GeomError> {
    let params = adaptive_curve_params(curve, tol, max_depth)?;
    let c = curve3(curve)?;
    let points = params
        .iter()
        .map(|&t| point3(&c, t))
        .collect::<Result<_, _>>()?;
    Ok(Polyline { points })
}

/// A uniform `nu × nv` triangle mesh of a patch (see the module docs).
///
/// # Errors
/// [`GeomError::Parameter`] for zero segments or more than [`MAX_TESSELLATION_POINTS`]
/// vertices, [`GeomError::Dimension`] beyond E3,
/// [`GeomError::Weight`] if a vertex is a point at infinity.
pub fn tessellate_patch_uniform<F: Scalar>(
    patch: &BezierPatch<F>,
    nu: usize,
    nv: usize,
) -> Result<TriMesh, GeomError> {
    check_segments(nu, "patch tessellation in u")?;
    check_segments(nv, "patch tessellation in v")?;
    let p = patch3(patch)?;
    mesh_grid(&p, &linspace(0.0, 1.0, nu), &linspace(0.0, 1.0, nv))
}

/// The triangle mesh of a patch on the tensor grid `us × vs` (vertex `(i, j)` at
/// `(us[i], vs[j])`, index `i · vs.len() + j`; triangulation, normals and dropped
/// triangles as in the module docs). Two patches meshed with the same parameters along
/// a shared boundary get the same boundary vertices.
///
/// # Errors
/// [`GeomError::Parameter`] unless both lists have at least two finite, strictly
/// increasing values, [`GeomError::Dimension`] beyond E3, [`GeomError::Weight`] if a
/// vertex is a point at infinity.
pub fn tessellate_patch_grid<F: Scalar>(
    patch: &BezierPatch<F>,
    us: &[f64],
    vs: &[f64],
) -> Result<TriMesh, GeomError> {
    check_params(us, "u")?;
    check_params(vs, "v")?;
    let p = patch3(patch)?;
    mesh_grid(&p, us, vs)
}

fn check_params(ts: &[f64], what: &str) -> Result<(), GeomError> {
    if ts.len() < 2 {
        return Err(GeomError::Parameter(format!(
            "a grid needs at least two {what} parameters (one segment), got {}",
            ts.len()
        )));
    }
    if ts.iter().any(|t| !t.is_finite()) || ts.windows(2).any(|w| w[0] >= w[1]) {
        return Err(GeomError::Parameter(format!(
            "{what} parameters must be finite and strictly increasing"
        )));
    }
    Ok(())
}

fn mesh_grid(p: &BezierPatch<f64>, us: &[f64], vs: &[f64]) -> Result<TriMesh, GeomError> {
    let (nu, nv) = (us.len() - 1, vs.len() - 1);
    let vertices = us
        .len()
        .checked_mul(vs.len())
        .filter(|&v| v <= u32::MAX as usize);
    if vertices.is_none() {
        return Err(GeomError::Parameter(format!(
            "a {nu} × {nv} grid has more vertices than u32 indices can address"
        )));
    }
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    eval_patch_grid_with_normals(p, us, vs, &mut positions, &mut normals)?;
    if let Some(k) = positions
        .iter()
        .position(|x| !x.iter().all(|c| c.is_finite()))
    {
        return Err(GeomError::Weight(format!(
            "the patch has a point at infinity (weight 0) near (u, v) = ({}, {})",
            us[k / (nv + 1)],
            vs[k % (nv + 1)]
        )));
    }
    let cols = nv + 1;
    let idx = |i: usize, j: usize| (i * cols + j) as u32;
    let mut triangles = Vec::with_capacity(2 * nu * nv);
    for i in 0..nu {
        for j in 0..nv {
            for t in [
                [idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)],
                [idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)],
            ] {
                if !degenerate_triangle(&positions, t) {
                    triangles.push(t);
                }
            }
        }
    }
    repair_normals(p, us, vs, &positions, &mut normals, &triangles);
    Ok(TriMesh {
        positions,
        normals,
        triangles,
    })
}

/// `|e₁ × e₂| ≤ 10⁻¹² · (longest edge)²`, or a non-finite vertex.
fn degenerate_triangle(pos: &[[f64; 3]], t: [u32; 3]) -> bool {
    let [a, b, c] = t.map(|k| pos[k as usize]);
    let e1 = sub(b, a);
    let e2 = sub(c, a);
    let e3 = sub(c, b);
    let longest = norm(e1).max(norm(e2)).max(norm(e3));
    let area2 = norm(cross(e1, e2));
    !(area2.is_finite() && longest.is_finite()) || area2 <= 1e-12 * longest * longest
}

/// Replaces zero (degenerate) normals: first the exact normal at a parameter moved
/// `10⁻⁶` into the domain, then the mean of the adjacent face normals, then `+z`.
fn repair_normals(
    p: &BezierPatch<f64>,
    us: &[f64],
    vs: &[f64],
    positions: &[[f64; 3]],
    normals: &mut [[f64; 3]],
    triangles: &[[u32; 3]],
) {
    let scale = control_net_scale(p);
    let thresh = DEGENERATE_NORMAL_RELATIVE * scale * scale;
    let cols = vs.len();
    let mut face_sum: Option<Vec<[f64; 3]>> = None;
    for k in 0..normals.len() {
        if normals[k] != [0.0; 3] {
            continue;
        }
        let (u, v) = (us[k / cols], vs[k % cols]);
        let h = 1e-6;
        let du = if u < 0.5 { h } else { -h };
        let dv = if v < 0.5 { h } else { -h };
        let nudged = [(u + du, v), (u, v + dv), (u + du, v + dv)]
            .into_iter()
            .map(|(a, b)| {
                let d = eval_patch_derivatives_f64(p, a, b);
                unit_normal(
                    [d.du[0], d.du[1], d.du[2]],
                    [d.dv[0], d.dv[1], d.dv[2]],
                    thresh * h,
                )
            })
            .find(|n| *n != [0.0; 3]);
        if let Some(n) = nudged {
            normals[k] = n;
            continue;
        }
        let sums = face_sum.get_or_insert_with(|| {
            let mut s = vec![[0.0; 3]; positions.len()];
            for t in triangles {
                let [a, b, c] = t.map(|i| positions[i as usize]);
                let f = cross(sub(b, a), sub(c, a));
                for &i in t {
                    let e = &mut s[i as usize];
                    e[0] += f[0];
                    e[1] += f[1];
                    e[2] += f[2];
                }
            }
            s
        });
        let l = norm(sums[k]);
        normals[k] = if l.is_finite() && l > 0.0 {
            [sums[k][0] / l, sums[k][1] / l, sums[k][2] / l]
        } else {
            [0.0, 0.0, 1.0]
        };
    }
}

/// The Euclidean control points (points at infinity as the origin).
fn net_points(p: &BezierPatch<f64>) -> Vec<[f64; 3]> {
    p.coords()
        .chunks_exact(4)
        .map(|c| {
            if c[0] == 0.0 {
                [0.0; 3]
            } else {
                [c[1] / c[0], c[2] / c[0], c[3] / c[0]]
            }
        })
        .collect()
}

/// The largest initial segment count per direction taken from the second-difference
/// bound; finer grids come from the sampled strip refinement.
const INITIAL_SEGMENTS_CAP: usize = 256;

/// Initial segment counts `(nu, nv)` from the second-difference bound (module docs).
fn counts_from_net(p: &BezierPatch<f64>, tol: f64) -> (usize, usize) {
    let (m, n) = p.degree();
    let x = net_points(p);
    let at = |i: usize, j: usize| x[i * (n + 1) + j];
    let mut duu: f64 = 0.0;
    let mut dvv: f64 = 0.0;
    let mut duv: f64 = 0.0;
    for i in 0..=m {
        for j in 0..=n {
            if i + 2 <= m {
                let d = sub(sub(at(i + 2, j), at(i + 1, j)), sub(at(i + 1, j), at(i, j)));
                duu = duu.max(norm(d));
            }
            if j + 2 <= n {
                let d = sub(sub(at(i, j + 2), at(i, j + 1)), sub(at(i, j + 1), at(i, j)));
                dvv = dvv.max(norm(d));
            }
            if i < m && j < n {
                let d = sub(
                    sub(at(i + 1, j + 1), at(i, j + 1)),
                    sub(at(i + 1, j), at(i, j)),
                );
                duv = duv.max(norm(d));
            }
        }
    }
    let muu = (m * m.saturating_sub(1)) as f64 * duu;
    let mvv = (n * n.saturating_sub(1)) as f64 * dvv;
    let muv = (m * n) as f64 * duv;
    // each of the three terms ≤ tol/3: nu ≥ a, nv ≥ b, nu·nv ≥ c, with the smallest
    // product; then at least the degree (so every wiggle is sampled) and at most
    // INITIAL_SEGMENTS_CAP (the strip refinement takes over from there)
    let a = (3.0 * muu / (8.0 * tol)).sqrt().max(1.0);
    let b = (3.0 * mvv / (8.0 * tol)).sqrt().max(1.0);
    let c = 3.0 * muv / (4.0 * tol);
    let (nu, nv) = if a * b >= c {
        (a, b)
    } else if a >= c.sqrt() {
        (a, c / a)
    } else if b >= c.sqrt() {
        (c / b, b)
    } else {
        (c.sqrt(), c.sqrt())
    };
    let clamp = |x: f64, deg: usize| {
        let lo = deg.max(1);
        if x.is_finite() {
            (x.ceil() as usize).clamp(lo, INITIAL_SEGMENTS_CAP.max(lo))
        } else {
            INITIAL_SEGMENTS_CAP.max(lo)
        }
    };
    (clamp(nu, m), clamp(nv, n))
}

/// Sampled deviations of the grid mesh on `us × vs` from the patch.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GridChordErrors {
    /// Per `u`-strip `[us[i], us[i+1]]`: the largest distance at its `u`-edge midpoints
    /// `(u_{i+½}, v_j)` and at those cell centres `(u_{i+½}, v_{j+½})` whose error is
    /// charged to `u` (the cell's `u`-edges deviate at least twice as much as its
    /// `v`-edges, or neither direction dominates).
    pub u_strips: Vec<f64>,
    /// Per `v`-strip: the same with the `v`-edge midpoints `(u_i, v_{j+½})`.
    pub v_strips: Vec<f64>,
}

impl GridChordErrors {
    /// The largest sampled deviation.
    pub fn max(&self) -> f64 {
        self.u_strips
            .iter()
            .chain(&self.v_strips)
            .fold(0.0, |a, &b| a.max(b))
    }
}

/// The sampled chord errors of the grid mesh on `us × vs`: at every edge midpoint the
/// distance between the patch and the edge's midpoint, at every cell centre the distance
/// to the midpoint of the cell's diagonal `(i, j)–(i+1, j+1)` (the mesh at that
/// parameter), collected per strip.
///
/// # Errors
/// As [`tessellate_patch_grid`].
pub fn grid_chord_errors<F: Scalar>(
    patch: &BezierPatch<F>,
    us: &[f64],
    vs: &[f64],
) -> Result<GridChordErrors, GeomError> {
    check_params(us, "u")?;
    check_params(vs, "v")?;
    let p = patch3(patch)?;
    grid_errors(&p, us, vs)
}

/// `t₀, (t₀+t₁)/2, t₁, …`: the parameters and their midpoints.
fn with_midpoints(ts: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(2 * ts.len());
    for w in ts.windows(2) {
        out.push(w[0]);
        out.push(0.5 * (w[0] + w[1]));
    }
    out.extend(ts.last());
    out
}

fn grid_errors(p: &BezierPatch<f64>, us: &[f64], vs: &[f64]) -> Result<GridChordErrors, GeomError> {
    let (nu, nv) = (us.len() - 1, vs.len() - 1);
    let uh = with_midpoints(us);
    let vh = with_midpoints(vs);
    let mut errs = GridChordErrors {
        u_strips: vec![0.0; nu],
        v_strips: vec![0.0; nv],
    };
    let mut edge_u = vec![0.0f64; nv + 1];
    // one strip of cells at a time: rows u_i, u_{i+½}, u_{i+1} (the points of
    // eval_patch_grid; the row u_{i+1} is the next strip's first)
    let mut grid = PatchGridRows3::new(p, &vh)?;
    let mut rows: [Vec<[f64; 3]>; 3] = Default::default();
    let finite = |r: &[[f64; 3]]| r.iter().all(|x| x.iter().all(|c| c.is_finite()));
    for (i, ts) in uh.windows(3).step_by(2).enumerate() {
        if i == 0 {
            grid.row(ts[0], &mut rows[0]);
        } else {
            rows.swap(0, 2);
        }
        grid.row(ts[1], &mut rows[1]);
        grid.row(ts[2], &mut rows[2]);
        if !rows.iter().all(|r| finite(r)) {
            return Err(GeomError::Weight(format!(
                "the patch has a point at infinity (weight 0) for u in [{}, {}]",
                ts[0], ts[2]
            )));
        }
        let at = |r: usize, j: usize| rows[r][j];
        for (j, e) in edge_u.iter_mut().enumerate() {
            let b = 2 * j;
            *e = dist(at(1, b), lerp(at(0, b), at(2, b), 0.5));
        }
        let mut eu = edge_u.iter().fold(0.0f64, |a, &b| a.max(b));
        for j in 0..nv {
            let b = 2 * j;
            let ev = dist(at(0, b + 1), lerp(at(0, b), at(0, b + 2), 0.5))
                .max(dist(at(2, b + 1), lerp(at(2, b), at(2, b + 2), 0.5)));
            let ec = dist(at(1, b + 1), lerp(at(0, b), at(2, b + 2), 0.5));
            // the centre error goes to the direction whose edges bend more; to both
            // when neither dominates (twist)
            let euc = edge_u[j].max(edge_u[j + 1]);
            let (to_u, to_v) = if euc >= 2.0 * ev {
                (ec, 0.0)
            } else if ev >= 2.0 * euc {
                (0.0, ec)
            } else {
                (ec, ec)
            };
            eu = eu.max(to_u);
            errs.v_strips[j] = errs.v_strips[j].max(ev).max(to_v);
        }
        errs.u_strips[i] = eu;
    }
    Ok(errs)
}

/// Splits every strip whose error exceeds `tol` into `⌈1.1 √(err/tol)⌉` equal parts
/// (2 to 8; the interpolation error of a strip shrinks like the square of its width).
fn refine_params(ts: &[f64], errs: &[f64], tol: f64) -> Vec<f64> {
    let mut out = Vec::with_capacity(ts.len() * 2);
    for (w, &e) in ts.windows(2).zip(errs) {
        out.push(w[0]);
        if e > tol {
            let k = ((e / tol).sqrt() * 1.1).ceil();
            let k = if k.is_finite() {
                (k as usize).clamp(2, 8)
            } else {
                8
            };
            for s in 1..k {
                out.push(w[0] + (w[1] - w[0]) * (s as f64 / k as f64));
            }
        }
    }
    out.extend(ts.last());
    out
}

/// The parameters `(us, vs)` of an adaptive tensor grid whose mesh deviates from the
/// patch by at most `tol` at every edge midpoint and cell centre (module docs): start
/// from the uniform counts of the second-difference bound, then split the `u`- and
/// `v`-strips whose sampled error exceeds `tol` until none does. Strips are refined
/// where the patch needs it (e.g. where the weights concentrate the parametrisation),
/// and the grid stays a tensor grid, so the mesh is watertight.
///
/// # Errors
/// [`GeomError::Parameter`] for a bad tolerance or when more than
/// [`MAX_PATCH_SEGMENTS`] segments per direction would be needed,
/// [`GeomError::Dimension`] beyond E3, [`GeomError::Weight`] at a point at infinity.
pub fn adaptive_patch_params<F: Scalar>(
    patch: &BezierPatch<F>,
    tol: f64,
) -> Result<(Vec<f64>, Vec<f64>), GeomError> {
    check_tol(tol)?;
    let p = patch3(patch)?;
    adaptive_params(&p, tol)
}

fn adaptive_params(p: &BezierPatch<f64>, tol: f64) -> Result<(Vec<f64>, Vec<f64>), GeomError> {
    let (nu, nv) = counts_from_net(p, tol);
    let mut us = linspace(0.0, 1.0, nu);
    let mut vs = linspace(0.0, 1.0, nv);
    for _ in 0..64 {
        let errs = grid_errors(p, &us, &vs)?;
        if errs.max() <= tol {
            return Ok((us, vs));
        }
        let new_us = refine_params(&us, &errs.u_strips, tol);
        let new_vs = refine_params(&vs, &errs.v_strips, tol);
        let stuck = new_us.len() == us.len() && new_vs.len() == vs.len();
        if stuck
            || new_us.len() > MAX_PATCH_SEGMENTS + 1
            || new_vs.len() > MAX_PATCH_SEGMENTS + 1
            || new_us.windows(2).any(|w| w[0] >= w[1])
            || new_vs.windows(2).any(|w| w[0] >= w[1])
        {
            break;
        }
        us = new_us;
        vs = new_vs;
    }
    Err(GeomError::Parameter(format!(
        "chord tolerance {tol} needs more than {MAX_PATCH_SEGMENTS} segments per direction"
    )))
}

/// An adaptive triangle mesh on the grid of [`adaptive_patch_params`].
///
/// # Errors
/// As [`adaptive_patch_params`].
pub fn tessellate_patch_adaptive<F: Scalar>(
    patch: &BezierPatch<F>,
    tol: f64,
) -> Result<TriMesh, GeomError> {
    check_tol(tol)?;
    let p = patch3(patch)?;
    let (us, vs) = adaptive_params(&p, tol)?;
    mesh_grid(&p, &us, &vs)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The octant of the unit sphere as a rational biquadratic patch (degenerate at
    /// `u = 0`: the north pole): `x(u, v)` = stereographic-style product of two
    /// quarter circles.
    pub(crate) fn sphere_octant() -> BezierPatch<f64> {
        // meridian quarter circle in (r, z): (0,1) → (1,1) → (1,0), weights 1, 1, 2
        let mer = [[1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [2.0, 2.0, 0.0]];
        // equator quarter circle in (x, y): (1,0) → (1,1) → (0,1)
        let eq = [[1.0, 1.0, 0.0], [1.0, 1.0, 1.0], [2.0, 0.0, 2.0]];
        let mut net = Vec::new();
        for m in &mer {
            let mut row = Vec::new();
            for e in &eq {
                // (w, r·x, r·y, z) with r, z from the meridian, x, y from the equator
                row.push(vec![m[0] * e[0], m[1] * e[1], m[1] * e[2], m[2] * e[0]]);
            }
            net.push(row);
        }
        BezierPatch::from_homogeneous(net).expect("valid")
    }

    #[test]
    fn sphere_mesh_has_unit_outward_normals_and_no_nan() {
        let p = sphere_octant();
        let mesh = tessellate_patch_uniform(&p, 8, 8).expect("ok");
        assert_eq!(mesh.positions.len(), 81);
        for (x, n) in mesh.positions.iter().zip(&mesh.normals) {
            assert!((norm(*x) - 1.0).abs() < 1e-14);
            assert!((norm(*n) - 1.0).abs() < 1e-12);
            // on the unit sphere the normal is ±x; pole normals come from a nudge
            let dot = x[0] * n[0] + x[1] * n[1] + x[2] * n[2];
            assert!(dot.abs() > 1.0 - 1e-5, "dot = {dot}");
        }
        // 8 collapsed triangles at the pole are dropped
        assert_eq!(mesh.triangles.len(), 2 * 64 - 8);
        // triangles are oriented like the normals
        for t in &mesh.triangles {
            let [a, b, c] = t.map(|k| mesh.positions[k as usize]);
            let f = cross(sub(b, a), sub(c, a));
            let n = mesh.normals[t[1] as usize];
            assert!(f[0] * n[0] + f[1] * n[1] + f[2] * n[2] > 0.0);
        }
    }

    #[test]
    fn adaptive_patch_meets_tolerance() {
        let p = sphere_octant();
        for tol in [1e-2, 1e-3, 1e-4] {
            let (us, vs) = adaptive_patch_params(&p, tol).expect("ok");
            let errs = grid_chord_errors(&p, &us, &vs).expect("ok");
            assert!(errs.max() <= tol);
            let mesh = tessellate_patch_adaptive(&p, tol).expect("ok");
            assert_eq!(mesh.positions.len(), us.len() * vs.len());
        }
        assert!(matches!(
            adaptive_patch_params(&p, 0.0),
            Err(GeomError::Parameter(_))
        ));
        assert!(matches!(
            adaptive_patch_params(&p, f64::NAN),
            Err(GeomError::Parameter(_))
        ));
    }

    #[test]
    fn s_curve_is_refined_even_when_midpoint_is_on_chord() {
        // symmetric cubic S: midpoint lies on the chord
        let c = BezierCurve::from_points(&[
            vec![0.0, 0.0],
            vec![1.0, 1.0],
            vec![2.0, -1.0],
            vec![3.0, 0.0],
        ])
        .expect("valid");
        let params = adaptive_curve_params(&c, 1e-3, 20).expect("ok");
        assert!(params.len() > 4);
        let pl = tessellate_curve_adaptive(&c, 1e-3, 20).expect("ok");
        assert_eq!(pl.points.len(), params.len());
        assert!(matches!(
            tessellate_curve_uniform(&c, 0),
            Err(GeomError::Parameter(_))
        ));
    }
}
