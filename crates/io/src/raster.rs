//! PNG pictures of objects by a small software rasterizer (no GPU, no display).
//!
//! # Pipeline
//!
//! 1. **Scene.** Patches are tessellated on a uniform `grid × grid` parameter grid per
//!    patch ([`tessellate_patch_uniform`]: vertex normals from the exact partial
//!    derivatives). Iso-parameter lines `u = i/(k−1)` and `v = j/(k−1)` (`k` =
//!    [`RenderOptions::iso_lines`], boundaries included) are sampled from the exact
//!    patch; boundary lines are drawn darker and wider, so the patch structure shows.
//!    Curves are sampled adaptively (chord tolerance 10⁻⁴ of the object's size).
//! 2. **View.** An orthographic camera: planar geometry from the top, spatial geometry
//!    from azimuth `α` and elevation `ε` (default 35°, 25°, as in the SVG pictures):
//!    view direction `d = (cos ε cos α, cos ε sin α, sin ε)`, screen axes
//!    `r = (−sin α, cos α, 0)`, `up = d × r`. The projection is fitted to the image
//!    with a 6 % margin.
//! 3. **Rasterization** at `s × s` supersampling: triangles by edge functions with a
//!    z-buffer (larger `p·d` is nearer), the normal interpolated barycentrically and
//!    shaded per pixel (deferred, after the z-buffer is complete) — ambient 0.3,
//!    Lambert `max(0, n·l)` from a key light at the upper left, mostly from the side
//!    (`l ∝ −0.6 r + 0.35 up + 0.7 d`, weight 0.7, so that vertical surfaces such as
//!    cylinders show their curvature) and a fill light from the right (0.2),
//!    Blinn-Phong highlight `0.25 (n·h)²⁴`.
//!    Faces seen from behind (`n·d < 0`) are shaded with their flipped normal in a
//!    warm sand colour, so the inside of an open surface is recognisable; when most
//!    visible pixels show the back (an open patch seen from its other side), the two
//!    sides are swapped, so the side facing the viewer is always blue.
//! 4. **Lines on top**: each polyline is walked in steps of half a (supersampled)
//!    pixel; where its depth is within `10⁻³·(depth range) + ` the mesh's chord error of
//!    the z-buffer at that pixel (it lies on the visible surface) a disc of the line's
//!    radius is stamped. Hidden parts of lines are not drawn. Interior iso-parameter
//!    lines darken the shaded surface under them (× 0.62, through a mask, so each
//!    pixel once): they stay visible on light and dark shading alike; patch
//!    boundaries and curves are drawn in their own colours on top.
//! 5. **Anti-aliasing**: the `s × s` blocks are averaged (box filter), then the image
//!    is encoded by [`crate::png`].

use crate::model::Object;
use crate::png::{encode_png, ColorType};
use crate::step::exchange_object;
use crate::stl::object_size;
use crate::IoError;
use rcagd_geom::grid::eval_patch_f64;
use rcagd_geom::tessellate::{tessellate_curve_adaptive, tessellate_patch_uniform, TriMesh};
use rcagd_geom::BezierPatch;

/// Options of a rendering.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Supersampling factor per axis (1 = none; 3 gives 9 samples per pixel).
    pub supersample: u32,
    /// Camera azimuth in degrees (spatial geometry).
    pub azimuth_deg: f64,
    /// Camera elevation in degrees (spatial geometry).
    pub elevation_deg: f64,
    /// Tessellation segments per patch side.
    pub grid: usize,
    /// Iso-parameter lines per patch direction, boundaries included (0 = none,
    /// otherwise at least 2).
    pub iso_lines: usize,
    /// Width of iso-parameter lines in output pixels.
    pub line_width: f64,
    /// Width of curves in output pixels.
    pub curve_width: f64,
    /// Draw the control polygons and nets (thin grey lines, not depth tested).
    pub control_net: bool,
    /// For spatial curves without patches: choose the azimuth (every 30°) and
    /// elevation (25° or 50°) under which the curves are drawn longest, instead of
    /// `azimuth_deg`/`elevation_deg` (a curve seen end-on says little).
    pub auto_view: bool,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 640,
            height: 480,
            supersample: 3,
            azimuth_deg: 35.0,
            elevation_deg: 25.0,
            grid: 40,
            iso_lines: 7,
            line_width: 1.0,
            curve_width: 2.5,
            control_net: false,
            auto_view: true,
        }
    }
}

/// An RGB image, 8 bits per channel, rows top to bottom.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width · height · 3` bytes.
    pub rgb: Vec<u8>,
}

impl Image {
    /// The PNG file of the image.
    ///
    /// # Errors
    /// As [`encode_png`].
    pub fn to_png(&self) -> Result<Vec<u8>, IoError> {
        encode_png(self.width, self.height, ColorType::Rgb, &self.rgb)
    }
}

type V3 = [f64; 3];

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn normalize(a: V3) -> V3 {
    let l = dot(a, a).sqrt();
    if l > 0.0 && l.is_finite() {
        [a[0] / l, a[1] / l, a[2] / l]
    } else {
        [0.0, 0.0, 1.0]
    }
}

/// Patch base colours (sRGB, 0–1): the palette of the SVG pictures.
const PATCH_COLORS: [V3; 5] = [
    [96.0 / 255.0, 150.0 / 255.0, 205.0 / 255.0],
    [222.0 / 255.0, 150.0 / 255.0, 90.0 / 255.0],
    [110.0 / 255.0, 190.0 / 255.0, 140.0 / 255.0],
    [170.0 / 255.0, 140.0 / 255.0, 215.0 / 255.0],
    [215.0 / 255.0, 200.0 / 255.0, 95.0 / 255.0],
];

/// Curve colours (sRGB, 0–1).
const CURVE_COLORS: [V3; 6] = [
    [0.122, 0.373, 0.659],
    [0.753, 0.224, 0.169],
    [0.118, 0.518, 0.286],
    [0.490, 0.235, 0.596],
    [0.827, 0.329, 0.0],
    [0.067, 0.478, 0.545],
];

struct Line {
    points: Vec<V3>,
    color: V3,
    /// radius in output pixels
    radius: f64,
    depth_test: bool,
    /// Drawn by darkening the shaded surface under it (interior iso-parameter
    /// lines: visible on light and dark shading alike) instead of in `color`.
    darken: bool,
}

struct Mesh {
    mesh: TriMesh,
    color: V3,
}

struct Camera {
    r: V3,
    up: V3,
    d: V3,
}

impl Camera {
    fn new(planar: bool, opts: &RenderOptions) -> Self {
        if planar {
            Self::from_angles(-90f64.to_radians(), 90f64.to_radians())
        } else {
            Self::from_angles(
                opts.azimuth_deg.to_radians(),
                opts.elevation_deg.to_radians(),
            )
        }
    }

    /// The view of [`RenderOptions::auto_view`]: the candidate under which the
    /// polyline points spread most: the largest determinant of the 2 × 2 covariance
    /// of their projections (a curve seen end-on has almost none).
    fn best_for(polylines: &[&[V3]]) -> Self {
        let mut best = (
            f64::NEG_INFINITY,
            Self::from_angles(35f64.to_radians(), 25f64.to_radians()),
        );
        for el in [25.0f64, 50.0] {
            for k in 0..12 {
                let az = 35.0 + 30.0 * k as f64;
                let cam = Self::from_angles(az.to_radians(), el.to_radians());
                let (mut n, mut sx, mut sy, mut sxx, mut syy, mut sxy) =
                    (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
                for &p in polylines.iter().flat_map(|pl| pl.iter()) {
                    let v = cam.view(p);
                    n += 1.0;
                    sx += v[0];
                    sy += v[1];
                    sxx += v[0] * v[0];
                    syy += v[1] * v[1];
                    sxy += v[0] * v[1];
                }
                if n < 1.0 {
                    continue;
                }
                let (mx, my) = (sx / n, sy / n);
                let (cxx, cyy, cxy) = (sxx / n - mx * mx, syy / n - my * my, sxy / n - mx * my);
                let score = cxx * cyy - cxy * cxy;
                if score > best.0 * (1.0 + 1e-9) {
                    best = (score, cam);
                }
            }
        }
        best.1
    }

    fn from_angles(az: f64, el: f64) -> Self {
        let (sa, ca) = az.sin_cos();
        let (se, ce) = el.sin_cos();
        Camera {
            d: [ce * ca, ce * sa, se],
            r: [-sa, ca, 0.0],
            up: [-se * ca, -se * sa, ce],
        }
    }

    /// `(x, y, depth)` in view coordinates.
    fn view(&self, p: V3) -> V3 {
        [dot(p, self.r), dot(p, self.up), dot(p, self.d)]
    }
}

fn pad3(p: &[f64]) -> V3 {
    [
        p.first().copied().unwrap_or(0.0),
        p.get(1).copied().unwrap_or(0.0),
        p.get(2).copied().unwrap_or(0.0),
    ]
}

/// The patch with `f64` homogeneous coordinates in E3.
fn patch3(p: &BezierPatch<rcagd_algebra::Rational>) -> Result<BezierPatch<f64>, IoError> {
    let d = p.dim();
    if d > 3 {
        return Err(IoError::Invalid(format!(
            "a picture needs geometry in E1, E2 or E3; this patch lies in E{d}"
        )));
    }
    let (m, n) = p.degree();
    let mut coords = Vec::with_capacity((m + 1) * (n + 1) * 4);
    for h in p.coords().chunks(d + 1) {
        coords.extend(h.iter().map(rcagd_algebra::Scalar::to_f64));
        coords.extend(std::iter::repeat_n(0.0, 3 - d));
    }
    Ok(BezierPatch::from_flat(3, m, n, coords)?)
}

fn scene(o: &Object, opts: &RenderOptions) -> Result<(Vec<Mesh>, Vec<Line>), IoError> {
    let mut meshes = Vec::new();
    let mut lines = Vec::new();
    let mut shadows = Vec::new();
    let size = object_size(o);
    let grid = opts.grid.max(1);
    let patches = o.geometry.patches();
    let base = PATCH_COLORS[0];
    // consistent (and, for closed shells, outward) orientation from the exact topology
    let flips: Vec<bool> = if patches.is_empty() {
        Vec::new()
    } else {
        // the exchange form orients its patches; the pieces drawn here are the
        // unoriented drawable pieces, so reverse those it reversed
        exchange_object(o).map(|x| x.reversed).unwrap_or_default()
    };
    // pieces with weights of one sign (a weight zero inside would draw a spike)
    for (k, p) in o.geometry.drawable_patches()? {
        let p3 = patch3(&p)?;
        let mut mesh = tessellate_patch_uniform(&p3, grid, grid)?;
        if flips.get(k) == Some(&true) {
            for n in &mut mesh.normals {
                *n = [-n[0], -n[1], -n[2]];
            }
        }
        // neighbouring patches alternate between two close shades
        let shade = if k % 2 == 0 { 1.0 } else { 0.9 };
        let color = base.map(|c| c * shade);
        meshes.push(Mesh { mesh, color });
        if opts.iso_lines >= 2 {
            let k_iso = opts.iso_lines;
            let samples = 4 * grid;
            for dir in 0..2 {
                for i in 0..k_iso {
                    let s = i as f64 / (k_iso - 1) as f64;
                    let pts: Vec<V3> = (0..=samples)
                        .map(|j| {
                            let t = j as f64 / samples as f64;
                            let (u, v) = if dir == 0 { (s, t) } else { (t, s) };
                            pad3(&eval_patch_f64(&p3, u, v))
                        })
                        .filter(|x| x.iter().all(|c| c.is_finite()))
                        .collect();
                    let boundary = i == 0 || i + 1 == k_iso;
                    lines.push(Line {
                        points: pts,
                        color: if boundary {
                            [0.11, 0.20, 0.32]
                        } else {
                            [0.20, 0.33, 0.48]
                        },
                        radius: opts.line_width * if boundary { 0.9 } else { 0.5 },
                        depth_test: true,
                        darken: !boundary,
                    });
                }
            }
        }
        if opts.control_net {
            let (m, n) = p3.degree();
            let pt = |i: usize, j: usize| {
                let h = p3.control_point(i, j);
                [h[1] / h[0], h[2] / h[0], h[3] / h[0]]
            };
            for i in 0..=m {
                lines.push(Line {
                    points: (0..=n).map(|j| pt(i, j)).collect(),
                    color: [0.45, 0.45, 0.45],
                    radius: 0.4,
                    depth_test: false,
                    darken: false,
                });
            }
            for j in 0..=n {
                lines.push(Line {
                    points: (0..=m).map(|i| pt(i, j)).collect(),
                    color: [0.45, 0.45, 0.45],
                    radius: 0.4,
                    depth_test: false,
                    darken: false,
                });
            }
        }
    }
    let mut dots: Vec<(V3, f64)> = Vec::new();
    let mut curve_points: Vec<V3> = Vec::new();
    for (k, c) in o.geometry.drawable_curves()?.iter().enumerate() {
        if c.dim() > 3 {
            return Err(IoError::Invalid(format!(
                "a picture needs geometry in E1, E2 or E3; curve {k} lies in E{}",
                c.dim()
            )));
        }
        let pl = tessellate_curve_adaptive(c, 1e-4 * size, 14)?;
        if let (Some(&a), Some(&b)) = (pl.points.first(), pl.points.last()) {
            dots.push((a, 3.0 * opts.curve_width));
            dots.push((b, 3.0 * opts.curve_width));
        }
        curve_points.extend(pl.points.iter().copied());
        lines.push(Line {
            points: pl.points,
            color: CURVE_COLORS[k % CURVE_COLORS.len()],
            radius: 0.5 * opts.curve_width,
            depth_test: true,
            darken: false,
        });
        if opts.control_net {
            if let Ok(pts) = c.euclidean_control_points() {
                lines.push(Line {
                    points: pts
                        .iter()
                        .map(|p| {
                            pad3(
                                &p.iter()
                                    .map(rcagd_algebra::Scalar::to_f64)
                                    .collect::<Vec<_>>(),
                            )
                        })
                        .collect(),
                    color: [0.5, 0.5, 0.5],
                    radius: 0.4,
                    depth_test: false,
                    darken: false,
                });
            }
        }
    }
    // spatial curves: their shadow on the plane z = min z, for depth perception
    if o.geometry.dim() > 2 && meshes.is_empty() && !curve_points.is_empty() {
        let zmin = curve_points
            .iter()
            .map(|p| p[2])
            .fold(f64::INFINITY, f64::min);
        for l in lines
            .iter()
            .filter(|l| l.depth_test)
            .collect::<Vec<_>>()
            .iter()
        {
            shadows.push(Line {
                points: l.points.iter().map(|p| [p[0], p[1], zmin]).collect(),
                color: [0.80, 0.81, 0.84],
                radius: l.radius,
                depth_test: false,
                darken: false,
            });
        }
    }
    shadows.append(&mut lines);
    let mut lines = shadows;
    for (p, d) in dots {
        lines.push(Line {
            points: vec![p, p],
            color: [0.15, 0.15, 0.18],
            radius: 0.5 * d,
            depth_test: true,
            darken: false,
        });
    }
    if meshes.is_empty() && lines.is_empty() {
        return Err(IoError::Invalid(format!(
            "object {:?} has no geometry to draw",
            o.name
        )));
    }
    Ok((meshes, lines))
}

struct Frame {
    w: usize,
    h: usize,
    color: Vec<[f32; 3]>,
    depth: Vec<f64>,
}

/// Renders an object (module docs).
///
/// # Errors
/// [`IoError::Invalid`] for a bad image size or supersampling factor, no drawable
/// geometry, geometry beyond E3, or a curve or patch whose weight function has a zero
/// (pieces with weights of mixed sign are drawn as pieces of one sign,
/// [`crate::model::Geometry::drawable_patches`]); [`IoError::Geom`] from the
/// tessellation.
pub fn render(o: &Object, opts: &RenderOptions) -> Result<Image, IoError> {
    if opts.width == 0 || opts.height == 0 || opts.width > 8192 || opts.height > 8192 {
        return Err(IoError::Invalid(format!(
            "the image size must be 1 to 8192 pixels per side, got {} × {}",
            opts.width, opts.height
        )));
    }
    if !(1..=8).contains(&opts.supersample) {
        return Err(IoError::Invalid(format!(
            "supersampling must be 1 to 8, got {}",
            opts.supersample
        )));
    }
    if opts.iso_lines == 1 {
        return Err(IoError::Invalid(
            "iso_lines must be 0 or at least 2 (the boundaries)".into(),
        ));
    }
    let (meshes, lines) = scene(o, opts)?;
    let planar = o.geometry.dim() <= 2;
    let cam = if !planar && opts.auto_view && meshes.is_empty() {
        let pls: Vec<&[V3]> = lines
            .iter()
            .filter(|l| l.depth_test)
            .map(|l| l.points.as_slice())
            .collect();
        Camera::best_for(&pls)
    } else {
        Camera::new(planar, opts)
    };
    let ss = opts.supersample as usize;
    let (w, h) = (opts.width as usize * ss, opts.height as usize * ss);

    // view coordinates and their bounds
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let mut see = |p: V3| {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    };
    let vmeshes: Vec<Vec<V3>> = meshes
        .iter()
        .map(|m| m.mesh.positions.iter().map(|&p| cam.view(p)).collect())
        .collect();
    let vlines: Vec<Vec<V3>> = lines
        .iter()
        .map(|l| l.points.iter().map(|&p| cam.view(p)).collect())
        .collect();
    vmeshes.iter().flatten().for_each(|&p| see(p));
    vlines.iter().flatten().for_each(|&p| see(p));
    if !lo.iter().chain(&hi).all(|x| x.is_finite()) {
        return Err(IoError::Invalid(
            "the geometry has no finite points to draw".into(),
        ));
    }
    let margin = 0.06;
    let bw = (hi[0] - lo[0]).max(1e-300);
    let bh = (hi[1] - lo[1]).max(1e-300);
    let scale =
        ((w as f64 * (1.0 - 2.0 * margin)) / bw).min((h as f64 * (1.0 - 2.0 * margin)) / bh);
    let (cx, cy) = (0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]));
    let to_screen = |p: V3| -> V3 {
        [
            w as f64 / 2.0 + (p[0] - cx) * scale,
            h as f64 / 2.0 - (p[1] - cy) * scale,
            p[2],
        ]
    };
    let depth_range = (hi[2] - lo[2]).max(bw.max(bh) * 1e-3);

    // background: a light vertical gradient
    let mut frame = Frame {
        w,
        h,
        color: Vec::with_capacity(w * h),
        depth: vec![f64::NEG_INFINITY; w * h],
    };
    for y in 0..h {
        let t = y as f32 / h as f32;
        let c = [0.985 - 0.05 * t, 0.988 - 0.045 * t, 0.995 - 0.035 * t];
        frame.color.extend(std::iter::repeat_n(c, w));
    }

    let key = normalize([
        -0.6 * cam.r[0] + 0.35 * cam.up[0] + 0.7 * cam.d[0],
        -0.6 * cam.r[1] + 0.35 * cam.up[1] + 0.7 * cam.d[1],
        -0.6 * cam.r[2] + 0.35 * cam.up[2] + 0.7 * cam.d[2],
    ]);
    let fill = normalize([
        0.7 * cam.r[0] - 0.2 * cam.up[0] + 0.5 * cam.d[0],
        0.7 * cam.r[1] - 0.2 * cam.up[1] + 0.5 * cam.d[1],
        0.7 * cam.r[2] - 0.2 * cam.up[2] + 0.5 * cam.d[2],
    ]);
    let half = normalize([key[0] + cam.d[0], key[1] + cam.d[1], key[2] + cam.d[2]]);
    let shade = |n: V3, base: V3| -> [f32; 3] {
        let mut n = normalize(n);
        let mut col = base;
        if dot(n, cam.d) < 0.0 {
            n = [-n[0], -n[1], -n[2]];
            // the back side: a warm sand colour, so insides read as such
            col = [0.86, 0.74, 0.52];
        }
        let lambert = 0.3 + 0.7 * dot(n, key).max(0.0) + 0.2 * dot(n, fill).max(0.0);
        let spec = 0.25 * dot(n, half).max(0.0).powi(24);
        [
            (col[0] * lambert + spec).min(1.0) as f32,
            (col[1] * lambert + spec).min(1.0) as f32,
            (col[2] * lambert + spec).min(1.0) as f32,
        ]
    };

    const NONE: u32 = u32::MAX;
    let mut normals = vec![[0f32; 3]; w * h];
    let mut owner = vec![NONE; w * h];
    for (mi, (m, vm)) in meshes.iter().zip(&vmeshes).enumerate() {
        let sp: Vec<V3> = vm.iter().map(|&p| to_screen(p)).collect();
        for t in &m.mesh.triangles {
            // the picture runs under the caller's work budget
            rcagd_algebra::budget::checkpoint();
            let [a, b, c] = t.map(|i| i as usize);
            let (pa, pb, pc) = (sp[a], sp[b], sp[c]);
            let area = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0]);
            if area.abs() < 1e-12 || !area.is_finite() {
                continue;
            }
            let x0 = pa[0].min(pb[0]).min(pc[0]).floor().max(0.0) as usize;
            let x1 = (pa[0].max(pb[0]).max(pc[0]).ceil() as isize).clamp(0, w as isize) as usize;
            let y0 = pa[1].min(pb[1]).min(pc[1]).floor().max(0.0) as usize;
            let y1 = (pa[1].max(pb[1]).max(pc[1]).ceil() as isize).clamp(0, h as isize) as usize;
            let (na, nb, nc) = (m.mesh.normals[a], m.mesh.normals[b], m.mesh.normals[c]);
            for y in y0..y1 {
                let py = y as f64 + 0.5;
                for x in x0..x1 {
                    let px = x as f64 + 0.5;
                    let wa = ((pb[0] - px) * (pc[1] - py) - (pb[1] - py) * (pc[0] - px)) / area;
                    let wb = ((pc[0] - px) * (pa[1] - py) - (pc[1] - py) * (pa[0] - px)) / area;
                    let wc = 1.0 - wa - wb;
                    if wa < -1e-9 || wb < -1e-9 || wc < -1e-9 {
                        continue;
                    }
                    let z = wa * pa[2] + wb * pb[2] + wc * pc[2];
                    let k = y * w + x;
                    if z <= frame.depth[k] {
                        continue;
                    }
                    frame.depth[k] = z;
                    normals[k] = [
                        (wa * na[0] + wb * nb[0] + wc * nc[0]) as f32,
                        (wa * na[1] + wb * nb[1] + wc * nc[1]) as f32,
                        (wa * na[2] + wb * nb[2] + wc * nc[2]) as f32,
                    ];
                    owner[k] = mi as u32;
                }
            }
        }
    }
    // Deferred shading. An open surface has no preferred side: when most of what is
    // seen is its back, the sides are swapped, so the side facing the viewer is drawn
    // in the front colour (a closed, outward oriented shell never shows its back).
    let facing = |n: [f32; 3]| {
        f64::from(n[0]) * cam.d[0] + f64::from(n[1]) * cam.d[1] + f64::from(n[2]) * cam.d[2]
    };
    let (mut front, mut back) = (0usize, 0usize);
    for (n, &o) in normals.iter().zip(&owner) {
        if o != NONE {
            if facing(*n) >= 0.0 {
                front += 1;
            } else {
                back += 1;
            }
        }
    }
    let sign = if back > front { -1.0 } else { 1.0 };
    for (k, (n, &o)) in normals.iter().zip(&owner).enumerate() {
        if let Some(m) = meshes.get(o as usize) {
            let n = [
                sign * f64::from(n[0]),
                sign * f64::from(n[1]),
                sign * f64::from(n[2]),
            ];
            frame.color[k] = shade(n, m.color);
        }
    }

    // lines: chord error of the mesh bounds how far an exact curve lies behind it
    let chord = depth_range * 2.5 / (opts.grid.max(1) as f64).powi(2);
    let eps = 1e-3 * depth_range + chord;
    // darkening lines first, through a mask (a pixel is darkened once however often
    // it is stamped), then the others on top in their colours
    let mut darkened = vec![false; w * h];
    let order = lines
        .iter()
        .zip(&vlines)
        .filter(|(l, _)| l.darken)
        .chain(lines.iter().zip(&vlines).filter(|(l, _)| !l.darken));
    let mut mask_applied = false;
    for (l, vl) in order {
        if !l.darken && !mask_applied {
            for (c, &d) in frame.color.iter_mut().zip(&darkened) {
                if d {
                    *c = c.map(|x| x * 0.62);
                }
            }
            mask_applied = true;
        }
        let r = l.radius * ss as f64;
        let col = [l.color[0] as f32, l.color[1] as f32, l.color[2] as f32];
        let sp: Vec<V3> = vl.iter().map(|&p| to_screen(p)).collect();
        for seg in sp.windows(2) {
            let (a, b) = (seg[0], seg[1]);
            let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
            let steps = (len / 0.5).ceil().clamp(1.0, 1e6) as usize;
            for s in 0..=steps {
                let t = s as f64 / steps as f64;
                let p = [
                    a[0] + t * (b[0] - a[0]),
                    a[1] + t * (b[1] - a[1]),
                    a[2] + t * (b[2] - a[2]),
                ];
                if l.depth_test {
                    let (xi, yi) = (p[0].floor(), p[1].floor());
                    if xi >= 0.0 && yi >= 0.0 && (xi as usize) < w && (yi as usize) < h {
                        let k = yi as usize * w + xi as usize;
                        if p[2] + eps < frame.depth[k] {
                            continue;
                        }
                    }
                }
                if l.darken {
                    stamp_mask((w, h), &mut darkened, p, r);
                } else {
                    stamp(&mut frame, p, r, col);
                }
            }
        }
    }
    if !mask_applied {
        for (c, &d) in frame.color.iter_mut().zip(&darkened) {
            if d {
                *c = c.map(|x| x * 0.62);
            }
        }
    }

    // an axis tripod (x red, y green, z blue) in the lower left corner of spatial views
    if !planar {
        let len = 22.0 * ss as f64;
        let o = [16.0 * ss as f64 + len, h as f64 - 16.0 * ss as f64 - len];
        let axes = [
            (0, [0.80f32, 0.22, 0.20]),
            (1, [0.20, 0.60, 0.25]),
            (2, [0.20, 0.35, 0.82]),
        ];
        for (k, col) in axes {
            let (dx, dy) = (cam.r[k], -cam.up[k]);
            let steps = (len * 2.0).ceil() as usize;
            for s in 0..=steps {
                let t = s as f64 / steps as f64 * len;
                stamp(
                    &mut frame,
                    [o[0] + t * dx, o[1] + t * dy, 0.0],
                    0.75 * ss as f64,
                    col,
                );
            }
        }
    }

    // box filter
    let (ow, oh) = (opts.width as usize, opts.height as usize);
    let mut rgb = Vec::with_capacity(ow * oh * 3);
    let norm = 1.0 / (ss * ss) as f32;
    for y in 0..oh {
        for x in 0..ow {
            let mut acc = [0f32; 3];
            for dy in 0..ss {
                let row = (y * ss + dy) * w + x * ss;
                for c in &frame.color[row..row + ss] {
                    acc[0] += c[0];
                    acc[1] += c[1];
                    acc[2] += c[2];
                }
            }
            for a in acc {
                rgb.push((a * norm * 255.0 + 0.5).clamp(0.0, 255.0) as u8);
            }
        }
    }
    Ok(Image {
        width: opts.width,
        height: opts.height,
        rgb,
    })
}

/// Marks the pixels of a disc of radius `r` (supersampled pixels) centred at `p`.
fn stamp_mask((w, h): (usize, usize), marks: &mut [bool], p: V3, r: f64) {
    let r = r.max(0.5);
    let x0 = (p[0] - r).floor().max(0.0) as usize;
    let y0 = (p[1] - r).floor().max(0.0) as usize;
    let x1 = ((p[0] + r).ceil() as isize).clamp(0, w as isize) as usize;
    let y1 = ((p[1] + r).ceil() as isize).clamp(0, h as isize) as usize;
    for y in y0..y1 {
        for x in x0..x1 {
            let dx = x as f64 + 0.5 - p[0];
            let dy = y as f64 + 0.5 - p[1];
            if dx * dx + dy * dy <= r * r {
                if let Some(m) = marks.get_mut(y * w + x) {
                    *m = true;
                }
            }
        }
    }
}

/// Paints a disc of radius `r` (supersampled pixels) centred at `p`.
fn stamp(f: &mut Frame, p: V3, r: f64, col: [f32; 3]) {
    let r = r.max(0.5);
    let x0 = (p[0] - r).floor().max(0.0) as usize;
    let y0 = (p[1] - r).floor().max(0.0) as usize;
    let x1 = ((p[0] + r).ceil() as isize).clamp(0, f.w as isize) as usize;
    let y1 = ((p[1] + r).ceil() as isize).clamp(0, f.h as isize) as usize;
    for y in y0..y1 {
        for x in x0..x1 {
            let dx = x as f64 + 0.5 - p[0];
            let dy = y as f64 + 0.5 - p[1];
            if dx * dx + dy * dy <= r * r {
                f.color[y * f.w + x] = col;
            }
        }
    }
}

/// The PNG of an object (see [`render`]).
///
/// # Errors
/// As [`render`] and [`encode_png`].
pub fn render_png(o: &Object, opts: &RenderOptions) -> Result<Vec<u8>, IoError> {
    render(o, opts)?.to_png()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Geometry;
    use rcagd_algebra::Rational;
    use rcagd_geom::BezierCurve;

    fn q(p: i64) -> Rational {
        Rational::from(p)
    }

    #[test]
    fn renders_a_curve_and_rejects_bad_options() {
        let c = BezierCurve::from_homogeneous(vec![
            vec![q(1), q(1), q(0)],
            vec![q(1), q(1), q(1)],
            vec![q(2), q(0), q(2)],
        ])
        .expect("valid");
        let o = Object::new(
            "arc",
            "t",
            serde_json::Value::Null,
            Geometry::Curve(c),
            vec![],
        );
        let opts = RenderOptions {
            width: 64,
            height: 48,
            ..Default::default()
        };
        let img = render(&o, &opts).expect("renders");
        assert_eq!(img.rgb.len(), 64 * 48 * 3);
        // some pixels carry the curve colour (dark blue-ish), the corners are background
        assert!(img
            .rgb
            .chunks(3)
            .any(|p| u16::from(p[2]) > u16::from(p[0]) + 60));
        assert!(img.rgb[0] > 240);
        let png = render_png(&o, &opts).expect("png");
        assert!(png.starts_with(b"\x89PNG"));
        for bad in [
            RenderOptions {
                width: 0,
                ..opts.clone()
            },
            RenderOptions {
                supersample: 0,
                ..opts.clone()
            },
            RenderOptions {
                iso_lines: 1,
                ..opts.clone()
            },
        ] {
            assert!(render(&o, &bad).is_err());
        }
        let empty = Object::new(
            "e",
            "t",
            serde_json::Value::Null,
            Geometry::Curves(vec![]),
            vec![],
        );
        assert!(render(&empty, &opts).is_err());
    }

    /// A flat square in z = 0 whose normal points down (`flip`) or up.
    fn square(flip: bool) -> Object {
        let net: Vec<Vec<Vec<Rational>>> = (0..2i64)
            .map(|i| {
                (0..2i64)
                    .map(|j| {
                        // swapping the parameters reverses the normal
                        let (x, y) = if flip { (j, i) } else { (i, j) };
                        vec![q(1), q(x), q(y), q(0)]
                    })
                    .collect()
            })
            .collect();
        Object::new(
            "square",
            "t",
            serde_json::Value::Null,
            Geometry::Patch(BezierPatch::from_homogeneous(net).expect("valid")),
            vec![],
        )
    }

    /// Pixels of the front colour (blue dominates) and of the back colour (sand: red
    /// dominates).
    fn front_back(img: &Image) -> (usize, usize) {
        let front = img
            .rgb
            .chunks(3)
            .filter(|p| u16::from(p[2]) > u16::from(p[0]) + 40)
            .count();
        let back = img
            .rgb
            .chunks(3)
            .filter(|p| u16::from(p[0]) > u16::from(p[2]) + 40)
            .count();
        (front, back)
    }

    #[test]
    fn an_open_patch_shows_its_front_colour_from_either_side() {
        let opts = RenderOptions {
            width: 80,
            height: 60,
            supersample: 1,
            iso_lines: 0,
            ..Default::default()
        };
        for flip in [false, true] {
            let img = render(&square(flip), &opts).expect("renders");
            let (front, back) = front_back(&img);
            assert!(front > 1000, "flip {flip}: {front} front pixels");
            // (the red x axis of the tripod counts as "back" too)
            assert!(back < 60, "flip {flip}: {back} back pixels");
        }
    }
}
