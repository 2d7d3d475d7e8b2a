//! SVG pictures of curves and patches, meant to be read by a person.
//!
//! * Planar geometry (dimension 2) is drawn in orthographic projection onto the
//!   `x`-`y` plane ([`View::Top`]); spatial geometry in a fixed oblique (axonometric)
//!   view from azimuth 35°, elevation 25° ([`View::Oblique`]).
//! * Curves are sampled adaptively (chord-midpoint deviation) and drawn as paths,
//!   one colour per piece, with the joins and end points marked; the control polygon
//!   (Euclidean control points) is optional.
//! * Patches are drawn as facets of a parameter grid in painter's order (far to near)
//!   with two-sided Lambert shading, and with iso-parameter lines along the facet
//!   edges (drawn with their facets, so hidden parts are covered), or as a wireframe
//!   of iso-parameter lines.
//! * The viewBox is fitted to the drawing; stroke widths are relative to its size, so
//!   the picture reads the same at any scale. No axes, white background, no ids (the
//!   SVG can be inlined into HTML any number of times).

use crate::model::{Geometry, Object};
use crate::IoError;
use rcagd_geom::{BezierCurve, BezierPatch};
use std::fmt::Write as _;

/// The projection.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum View {
    /// Orthographic onto the `x`-`y` plane (`z` is depth).
    Top,
    /// Fixed oblique view: azimuth 35° from `+x` towards `+y`, elevation 25°.
    Oblique,
}

/// How patches are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PatchStyle {
    /// Lambert-shaded facets in painter's order with iso-parameter lines.
    Shaded,
    /// Iso-parameter lines only.
    Wireframe,
}

/// Options of the pictures.
#[derive(Debug, Clone, PartialEq)]
pub struct SvgOptions {
    /// Largest width in pixels (the picture keeps the drawing's aspect ratio).
    pub width: f64,
    /// Largest height in pixels.
    pub height: f64,
    /// Draw the control polygon / control net.
    pub control_polygon: bool,
    /// Patch style.
    pub patch_style: PatchStyle,
    /// The projection; `None` chooses [`View::Top`] for planar and [`View::Oblique`]
    /// for spatial geometry.
    pub view: Option<View>,
    /// Facets per patch side.
    pub grid: usize,
    /// Iso-parameter lines per patch direction, boundaries included (at least 2).
    pub iso_lines: usize,
    /// A `<title>` (tooltip) for the picture.
    pub title: Option<String>,
}

impl Default for SvgOptions {
    fn default() -> Self {
        SvgOptions {
            width: 480.0,
            height: 360.0,
            control_polygon: false,
            patch_style: PatchStyle::Shaded,
            view: None,
            grid: 16,
            iso_lines: 5,
            title: None,
        }
    }
}

const CURVE_COLORS: [&str; 6] = [
    "#1f5fa8", "#c0392b", "#1e8449", "#7d3c98", "#d35400", "#117a8b",
];
const PATCH_COLORS: [[f64; 3]; 5] = [
    [96.0, 150.0, 205.0],
    [222.0, 150.0, 90.0],
    [110.0, 190.0, 140.0],
    [170.0, 140.0, 215.0],
    [215.0, 200.0, 95.0],
];

type P3 = [f64; 3];

fn sub3(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot3(a: P3, b: P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross3(a: P3, b: P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn norm3(a: P3) -> f64 {
    dot3(a, a).sqrt()
}

/// Euclidean point of a homogeneous point, padded/truncated to 3 coordinates;
/// `None` at (or numerically near) infinity.
fn dehomogenize(h: &[f64]) -> Option<P3> {
    let (&w, rest) = h.split_first()?;
    if !w.is_finite() || w.abs() < 1e-300 {
        return None;
    }
    let mut p = [0.0; 3];
    for (k, x) in rest.iter().take(3).enumerate() {
        p[k] = x / w;
    }
    p.iter().all(|x| x.is_finite()).then_some(p)
}

fn de_casteljau(points: &[&[f64]], t: f64) -> Vec<f64> {
    let mut pts: Vec<Vec<f64>> = points.iter().map(|p| p.to_vec()).collect();
    while pts.len() > 1 {
        pts = pts
            .windows(2)
            .map(|w| {
                w[0].iter()
                    .zip(&w[1])
                    .map(|(a, b)| (1.0 - t) * a + t * b)
                    .collect()
            })
            .collect();
    }
    pts.pop().unwrap_or_default()
}

fn curve_point(c: &BezierCurve<f64>, t: f64) -> Option<P3> {
    let pts: Vec<&[f64]> = c.control_points().collect();
    dehomogenize(&de_casteljau(&pts, t))
}

fn patch_point(p: &BezierPatch<f64>, u: f64, v: f64) -> Option<P3> {
    // the pictures run under the caller's work budget
    rcagd_algebra::budget::checkpoint();
    let (m, n) = p.degree();
    let rows: Vec<Vec<f64>> = (0..=m)
        .map(|i| {
            let row: Vec<&[f64]> = (0..=n).map(|j| p.control_point(i, j)).collect();
            de_casteljau(&row, v)
        })
        .collect();
    let refs: Vec<&[f64]> = rows.iter().map(Vec::as_slice).collect();
    dehomogenize(&de_casteljau(&refs, u))
}

/// Samples a curve adaptively: uniform start, then bisection where the midpoint
/// deviates from the chord by more than `tol`. Points at infinity split the polyline.
fn sample_curve(c: &BezierCurve<f64>, tol: f64) -> Vec<Vec<P3>> {
    let n0 = 8 * (c.degree() + 1);
    let mut runs: Vec<Vec<P3>> = Vec::new();
    let mut run: Vec<P3> = Vec::new();
    let mut prev: Option<(f64, P3)> = None;
    for k in 0..=n0 {
        let t = k as f64 / n0 as f64;
        match curve_point(c, t) {
            Some(p) => {
                if let Some((t0, p0)) = prev {
                    refine(c, t0, p0, t, p, tol, 8, &mut run);
                } else {
                    run.push(p);
                }
                run.push(p);
                prev = Some((t, p));
            }
            None => {
                if run.len() > 1 {
                    runs.push(std::mem::take(&mut run));
                }
                run.clear();
                prev = None;
            }
        }
    }
    if run.len() > 1 {
        runs.push(run);
    }
    runs
}

/// Pushes the interior points between `(t0, p0)` and `(t1, p1)`.
#[allow(clippy::too_many_arguments)]
fn refine(
    c: &BezierCurve<f64>,
    t0: f64,
    p0: P3,
    t1: f64,
    p1: P3,
    tol: f64,
    depth: u32,
    out: &mut Vec<P3>,
) {
    if depth == 0 {
        return;
    }
    let tm = 0.5 * (t0 + t1);
    let Some(pm) = curve_point(c, tm) else {
        return;
    };
    let mid = [
        0.5 * (p0[0] + p1[0]),
        0.5 * (p0[1] + p1[1]),
        0.5 * (p0[2] + p1[2]),
    ];
    if norm3(sub3(pm, mid)) > tol {
        refine(c, t0, p0, tm, pm, tol, depth - 1, out);
        out.push(pm);
        refine(c, tm, pm, t1, p1, tol, depth - 1, out);
    }
}

/// The projection: screen right, screen up, towards the viewer.
struct Camera {
    right: P3,
    up: P3,
    toward: P3,
}

impl Camera {
    fn new(view: View) -> Self {
        match view {
            View::Top => Camera {
                right: [1.0, 0.0, 0.0],
                up: [0.0, 1.0, 0.0],
                toward: [0.0, 0.0, 1.0],
            },
            View::Oblique => {
                let (az, el) = (35f64.to_radians(), 25f64.to_radians());
                Camera {
                    right: [-az.sin(), az.cos(), 0.0],
                    up: [-el.sin() * az.cos(), -el.sin() * az.sin(), el.cos()],
                    toward: [el.cos() * az.cos(), el.cos() * az.sin(), el.sin()],
                }
            }
        }
    }

    /// Screen coordinates (SVG: `y` down).
    fn project(&self, p: P3) -> [f64; 2] {
        [dot3(p, self.right), -dot3(p, self.up)]
    }

    fn depth(&self, p: P3) -> f64 {
        dot3(p, self.toward)
    }

    /// A light from over the viewer's left shoulder.
    fn light(&self) -> P3 {
        let l = [
            self.toward[0] + 0.6 * self.up[0] - 0.4 * self.right[0],
            self.toward[1] + 0.6 * self.up[1] - 0.4 * self.right[1],
            self.toward[2] + 0.6 * self.up[2] - 0.4 * self.right[2],
        ];
        let n = norm3(l);
        [l[0] / n, l[1] / n, l[2] / n]
    }
}

/// Bounding box of screen points.
#[derive(Clone, Copy)]
struct Bounds {
    min: [f64; 2],
    max: [f64; 2],
}

impl Bounds {
    fn of<'a>(pts: impl Iterator<Item = &'a [f64; 2]>) -> Option<Bounds> {
        let mut b: Option<Bounds> = None;
        for p in pts {
            if !(p[0].is_finite() && p[1].is_finite()) {
                continue;
            }
            b = Some(match b {
                None => Bounds { min: *p, max: *p },
                Some(b) => Bounds {
                    min: [b.min[0].min(p[0]), b.min[1].min(p[1])],
                    max: [b.max[0].max(p[0]), b.max[1].max(p[1])],
                },
            });
        }
        b
    }

    fn size(&self) -> f64 {
        (self.max[0] - self.min[0]).max(self.max[1] - self.min[1])
    }
}

/// Formats a coordinate with about 5 significant digits relative to the picture size.
struct Fmt {
    decimals: usize,
}

impl Fmt {
    fn new(size: f64) -> Self {
        let mag = if size > 0.0 {
            size.log10().floor()
        } else {
            0.0
        };
        Fmt {
            decimals: (4.0 - mag).clamp(0.0, 10.0) as usize,
        }
    }

    fn n(&self, x: f64) -> String {
        let s = format!("{:.*}", self.decimals, x);
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        };
        if s == "-0" {
            "0".into()
        } else {
            s
        }
    }

    fn pt(&self, p: [f64; 2]) -> String {
        format!("{},{}", self.n(p[0]), self.n(p[1]))
    }

    fn path(&self, pts: &[[f64; 2]], closed: bool) -> String {
        let mut d = String::new();
        for (k, p) in pts.iter().enumerate() {
            let _ = write!(d, "{}{}", if k == 0 { "M" } else { " L" }, self.pt(*p));
        }
        if closed {
            d.push_str(" Z");
        }
        d
    }
}

/// Escapes text for XML/HTML content and attributes.
pub fn escape_xml(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// The SVG document around a body drawn in screen coordinates.
fn document(b: Bounds, opts: &SvgOptions, body: &str) -> String {
    let size = b.size().max(1e-12);
    let margin = 0.06 * size;
    let (x0, y0) = (b.min[0] - margin, b.min[1] - margin);
    let w = (b.max[0] - b.min[0]).max(0.02 * size) + 2.0 * margin;
    let h = (b.max[1] - b.min[1]).max(0.02 * size) + 2.0 * margin;
    let scale = (opts.width.max(16.0) / w).min(opts.height.max(16.0) / h);
    let f = Fmt::new(size);
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="{} {} {} {}" width="{:.0}" height="{:.0}" stroke-linecap="round" stroke-linejoin="round">"#,
        f.n(x0),
        f.n(y0),
        f.n(w),
        f.n(h),
        w * scale,
        h * scale
    );
    if let Some(t) = &opts.title {
        let _ = write!(s, "<title>{}</title>", escape_xml(t));
    }
    let _ = write!(
        s,
        r##"<rect x="{}" y="{}" width="{}" height="{}" fill="#ffffff"/>"##,
        f.n(x0),
        f.n(y0),
        f.n(w),
        f.n(h)
    );
    s.push_str(body);
    s.push_str("</svg>\n");
    s
}

fn choose_view(dim: usize, opts: &SvgOptions) -> View {
    opts.view
        .unwrap_or(if dim <= 2 { View::Top } else { View::Oblique })
}

/// Euclidean control points of a curve (points at infinity skipped).
fn curve_control_points(c: &BezierCurve<f64>) -> Vec<P3> {
    c.control_points().filter_map(dehomogenize).collect()
}

/// An SVG picture of curves (see the module docs).
///
/// # Errors
/// [`IoError::Invalid`] if there is nothing finite to draw.
pub fn curves_svg(curves: &[BezierCurve<f64>], opts: &SvgOptions) -> Result<String, IoError> {
    let dim = curves.iter().map(|c| c.dim()).max().unwrap_or(2);
    let cam = Camera::new(choose_view(dim, opts));
    // Tolerance from the control points' extent.
    let ctrl: Vec<Vec<P3>> = curves.iter().map(curve_control_points).collect();
    let ctrl_screen: Vec<[f64; 2]> = ctrl.iter().flatten().map(|p| cam.project(*p)).collect();
    let extent = Bounds::of(ctrl_screen.iter()).map_or(1.0, |b| b.size().max(1e-12));
    let tol = 2e-4 * extent;
    let runs: Vec<Vec<Vec<[f64; 2]>>> = curves
        .iter()
        .map(|c| {
            sample_curve(c, tol)
                .into_iter()
                .map(|run| run.into_iter().map(|p| cam.project(p)).collect())
                .collect()
        })
        .collect();
    let mut all: Vec<[f64; 2]> = runs.iter().flatten().flatten().copied().collect();
    if opts.control_polygon {
        all.extend(ctrl_screen.iter().copied());
    }
    let b = Bounds::of(all.iter())
        .ok_or_else(|| IoError::Invalid("no finite curve points to draw".into()))?;
    let size = b.size().max(1e-12);
    let f = Fmt::new(size);
    let sw = 0.008 * size;
    let mut body = String::new();
    if opts.control_polygon {
        for pts in &ctrl {
            let scr: Vec<[f64; 2]> = pts.iter().map(|p| cam.project(*p)).collect();
            let _ = write!(
                body,
                r##"<path d="{}" fill="none" stroke="#9aa0a6" stroke-width="{}" stroke-dasharray="{} {}"/>"##,
                f.path(&scr, false),
                f.n(0.4 * sw),
                f.n(2.0 * sw),
                f.n(1.5 * sw)
            );
            for p in &scr {
                let s = 1.6 * sw;
                let _ = write!(
                    body,
                    r##"<rect x="{}" y="{}" width="{}" height="{}" fill="#ffffff" stroke="#6b7075" stroke-width="{}"/>"##,
                    f.n(p[0] - s / 2.0),
                    f.n(p[1] - s / 2.0),
                    f.n(s),
                    f.n(s),
                    f.n(0.3 * sw)
                );
            }
        }
    }
    for (k, c_runs) in runs.iter().enumerate() {
        let color = CURVE_COLORS[k % CURVE_COLORS.len()];
        for run in c_runs {
            let _ = write!(
                body,
                r#"<path d="{}" fill="none" stroke="{color}" stroke-width="{}"/>"#,
                f.path(run, false),
                f.n(sw)
            );
        }
    }
    // End points and joins.
    let mut marks: Vec<[f64; 2]> = Vec::new();
    for c_runs in &runs {
        for run in c_runs {
            for p in [run.first(), run.last()].into_iter().flatten() {
                if !marks
                    .iter()
                    .any(|m| (m[0] - p[0]).hypot(m[1] - p[1]) < 1e-9 * size)
                {
                    marks.push(*p);
                }
            }
        }
    }
    for p in &marks {
        let _ = write!(
            body,
            r##"<circle cx="{}" cy="{}" r="{}" fill="#ffffff" stroke="#202124" stroke-width="{}"/>"##,
            f.n(p[0]),
            f.n(p[1]),
            f.n(1.3 * sw),
            f.n(0.5 * sw)
        );
    }
    Ok(document(b, opts, &body))
}

/// A grid of Euclidean points of a patch, `grid + 1` per side (`None` at infinity).
fn patch_grid(p: &BezierPatch<f64>, grid: usize) -> Vec<Vec<Option<P3>>> {
    (0..=grid)
        .map(|i| {
            let u = i as f64 / grid as f64;
            (0..=grid)
                .map(|j| patch_point(p, u, j as f64 / grid as f64))
                .collect()
        })
        .collect()
}

struct Facet {
    depth: f64,
    corners: [[f64; 2]; 4],
    fill: String,
    iso: Vec<[[f64; 2]; 2]>,
}

fn rgb(c: [f64; 3], k: f64) -> String {
    let ch = |x: f64| (x * k).round().clamp(0.0, 255.0) as u8;
    format!("#{:02x}{:02x}{:02x}", ch(c[0]), ch(c[1]), ch(c[2]))
}

/// An SVG picture of patches (see the module docs).
///
/// # Errors
/// [`IoError::Invalid`] if there is nothing finite to draw.
pub fn patches_svg(patches: &[BezierPatch<f64>], opts: &SvgOptions) -> Result<String, IoError> {
    let dim = patches.iter().map(|p| p.dim()).max().unwrap_or(3);
    let cam = Camera::new(choose_view(dim, opts));
    let light = cam.light();
    let grid = opts.grid.clamp(1, 256);
    let lines = opts.iso_lines.max(2);
    let grids: Vec<Vec<Vec<Option<P3>>>> = patches.iter().map(|p| patch_grid(p, grid)).collect();
    // Grid indices of the iso-parameter lines (boundaries included).
    let iso: Vec<usize> = (0..lines)
        .map(|k| ((k * grid) as f64 / (lines - 1) as f64).round() as usize)
        .collect();
    let is_iso = |i: usize| iso.contains(&i);
    let ctrl: Vec<Vec<Vec<Option<P3>>>> = patches
        .iter()
        .map(|p| {
            let (m, n) = p.degree();
            (0..=m)
                .map(|i| {
                    (0..=n)
                        .map(|j| dehomogenize(p.control_point(i, j)))
                        .collect()
                })
                .collect()
        })
        .collect();
    let mut all: Vec<[f64; 2]> = grids
        .iter()
        .flatten()
        .flatten()
        .flatten()
        .map(|p| cam.project(*p))
        .collect();
    if opts.control_polygon {
        all.extend(
            ctrl.iter()
                .flatten()
                .flatten()
                .flatten()
                .map(|p| cam.project(*p)),
        );
    }
    let b = Bounds::of(all.iter())
        .ok_or_else(|| IoError::Invalid("no finite patch points to draw".into()))?;
    let size = b.size().max(1e-12);
    let f = Fmt::new(size);
    let sw = 0.008 * size;
    let mut body = String::new();
    match opts.patch_style {
        PatchStyle::Shaded => {
            let mut facets: Vec<Facet> = Vec::new();
            for (k, g) in grids.iter().enumerate() {
                let base = PATCH_COLORS[k % PATCH_COLORS.len()];
                for i in 0..grid {
                    for j in 0..grid {
                        let quad = (g[i][j], g[i + 1][j], g[i + 1][j + 1], g[i][j + 1]);
                        let (Some(a), Some(bq), Some(c), Some(d)) = quad else {
                            continue;
                        };
                        let n = cross3(sub3(c, a), sub3(d, bq));
                        let len = norm3(n);
                        let lambert = if len > 0.0 {
                            (dot3(n, light) / len).abs()
                        } else {
                            1.0
                        };
                        let corners = [a, bq, c, d].map(|p| cam.project(p));
                        let depth = [a, bq, c, d].iter().map(|p| cam.depth(*p)).sum::<f64>() / 4.0;
                        let mut iso_edges = Vec::new();
                        if is_iso(i) {
                            iso_edges.push([corners[0], corners[3]]);
                        }
                        if is_iso(i + 1) {
                            iso_edges.push([corners[1], corners[2]]);
                        }
                        if is_iso(j) {
                            iso_edges.push([corners[0], corners[1]]);
                        }
                        if is_iso(j + 1) {
                            iso_edges.push([corners[3], corners[2]]);
                        }
                        facets.push(Facet {
                            depth,
                            corners,
                            fill: rgb(base, 0.35 + 0.7 * lambert),
                            iso: iso_edges,
                        });
                    }
                }
            }
            facets.sort_by(|x, y| x.depth.total_cmp(&y.depth));
            let hair = f.n(0.4 * sw);
            let iso_w = f.n(0.35 * sw);
            for fc in &facets {
                let _ = write!(
                    body,
                    r#"<path d="{}" fill="{}" stroke="{}" stroke-width="{hair}"/>"#,
                    f.path(&fc.corners, true),
                    fc.fill,
                    fc.fill
                );
                if !fc.iso.is_empty() {
                    let mut d = String::new();
                    for [p, q] in &fc.iso {
                        let _ = write!(d, "M{} L{} ", f.pt(*p), f.pt(*q));
                    }
                    let _ = write!(
                        body,
                        r##"<path d="{}" fill="none" stroke="#2b3a4a" stroke-width="{iso_w}"/>"##,
                        d.trim_end()
                    );
                }
            }
        }
        PatchStyle::Wireframe => {
            for (k, g) in grids.iter().enumerate() {
                let color = CURVE_COLORS[k % CURVE_COLORS.len()];
                let mut polylines: Vec<Vec<Option<P3>>> = Vec::new();
                for &i in &iso {
                    polylines.push(g[i].clone());
                    polylines.push(g.iter().map(|row| row[i]).collect());
                }
                for pl in polylines {
                    for run in pl.split(Option::is_none) {
                        let pts: Vec<[f64; 2]> =
                            run.iter().flatten().map(|p| cam.project(*p)).collect();
                        if pts.len() > 1 {
                            let _ = write!(
                                body,
                                r#"<path d="{}" fill="none" stroke="{color}" stroke-width="{}"/>"#,
                                f.path(&pts, false),
                                f.n(0.45 * sw)
                            );
                        }
                    }
                }
            }
        }
    }
    if opts.control_polygon {
        for net in &ctrl {
            let cols = net.first().map_or(0, Vec::len);
            let mut lines_: Vec<Vec<Option<P3>>> = net.clone();
            lines_.extend((0..cols).map(|j| {
                net.iter()
                    .map(|row| row.get(j).copied().flatten())
                    .collect()
            }));
            for pl in lines_ {
                for run in pl.split(Option::is_none) {
                    let pts: Vec<[f64; 2]> =
                        run.iter().flatten().map(|p| cam.project(*p)).collect();
                    if pts.len() > 1 {
                        let _ = write!(
                            body,
                            r##"<path d="{}" fill="none" stroke="#5f6368" stroke-width="{}" stroke-dasharray="{} {}"/>"##,
                            f.path(&pts, false),
                            f.n(0.3 * sw),
                            f.n(1.5 * sw),
                            f.n(1.0 * sw)
                        );
                    }
                }
            }
            for p in net.iter().flatten().flatten() {
                let s = cam.project(*p);
                let _ = write!(
                    body,
                    r##"<circle cx="{}" cy="{}" r="{}" fill="#ffffff" stroke="#202124" stroke-width="{}"/>"##,
                    f.n(s[0]),
                    f.n(s[1]),
                    f.n(0.9 * sw),
                    f.n(0.3 * sw)
                );
            }
        }
    }
    Ok(document(b, opts, &body))
}

/// The picture of exact geometry (converted to `f64`), curves and patches split into
/// pieces whose weights have one sign ([`Geometry::drawable_curves`],
/// [`Geometry::drawable_patches`]).
///
/// # Errors
/// As [`curves_svg`] / [`patches_svg`]; [`IoError::Invalid`] for a piece whose weight
/// function has a zero (a point at infinity would be drawn as a spike).
pub fn geometry_svg(g: &Geometry, opts: &SvgOptions) -> Result<String, IoError> {
    match g {
        Geometry::Curve(_) | Geometry::Curves(_) => {
            let curves: Vec<BezierCurve<f64>> = g
                .drawable_curves()?
                .iter()
                .map(BezierCurve::to_f64)
                .collect();
            curves_svg(&curves, opts)
        }
        Geometry::Patch(_) | Geometry::Patches(_) => {
            let patches: Vec<BezierPatch<f64>> = g
                .drawable_patches()?
                .iter()
                .map(|(_, p)| p.to_f64())
                .collect();
            patches_svg(&patches, opts)
        }
    }
}

/// The picture of an object, titled with its name and op (unless `opts.title` is set).
///
/// # Errors
/// As [`geometry_svg`].
pub fn object_svg(o: &Object, opts: &SvgOptions) -> Result<String, IoError> {
    let mut opts = opts.clone();
    if opts.title.is_none() {
        opts.title = Some(format!("{} ({}, {})", o.name, o.op, o.degree_summary()));
    }
    geometry_svg(&o.geometry, &opts)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quarter() -> BezierCurve<f64> {
        BezierCurve::from_homogeneous(vec![
            vec![1.0, 1.0, 0.0],
            vec![1.0, 1.0, 1.0],
            vec![2.0, 0.0, 2.0],
        ])
        .expect("valid")
    }

    #[test]
    fn curve_samples_lie_on_the_circle() {
        for run in sample_curve(&quarter(), 1e-4) {
            assert!(run.len() > 16);
            for p in run {
                assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn numbers_are_compact() {
        let f = Fmt::new(2.0);
        assert_eq!(f.n(0.5), "0.5");
        assert_eq!(f.n(-0.000_001), "0");
        assert_eq!(f.n(1.0), "1");
        assert_eq!(f.n(0.123_456_789), "0.1235");
    }

    #[test]
    fn escapes() {
        assert_eq!(escape_xml("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }
}
