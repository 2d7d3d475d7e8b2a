//! Biquadratic patches on the sphere and the Miquel configuration (Jüttler §2, Satz 7;
//! docs/math/quadrics.md, "Biquadratic sphere patches and the Miquel configuration").
//!
//! * **Bilinear → biquadratic** (docs/math/quadrics.md, "Biquadratic sphere patches and the Miquel configuration"): the δ-image of a bilinear patch with corners
//!   `c00, c10, c11, c01` is a biquadratic patch on `K` with corners `p1 = y(0,0)`,
//!   `p2 = y(1,0)`, `p3 = y(1,1)`, `p4 = y(0,1)` and boundary circles `C12: v = 0`,
//!   `C23: u = 1`, `C34: v = 1`, `C41: u = 0`, each in the plane of its three edge
//!   control points. Adjacent circles meet at `pᵢ` and a second point `qᵢ` (rational: the
//!   other root on the line `plane ∩ plane`; `qᵢ = pᵢ` for tangent circles), which is δ of
//!   the projecting line in the plane of the two edge lines at that corner.
//!   Satz 7: `p1, q2, p3, q4` are concyclic (on a sphere: coplanar,
//!   `det[p1,q2,p3,q4] = 0`), and so are `q1, p2, q3, p4` (Miquel's theorem).
//! * **Converse** (docs/math/quadrics.md, "Biquadratic sphere patches and the Miquel configuration"): from corners and boundary circles in Miquel position, chain
//!   `c00 ∈ F(p1)`, `c10 = F(p2) ∩ span(c00, F(e12))`, `c11 = F(p3) ∩ span(c10, F(e23))`,
//!   `c01 = F(p4) ∩ span(c11, F(e34))`, where `F(k)` is the projecting line over `k` and
//!   `e_ij` a third point of the circle `C_ij`; the closing step
//!   `c00' = F(p1) ∩ span(c01, F(e41))` returns to `c00` exactly for Miquel data. One
//!   weight (of `c11`) is essential: a one-parameter family of patches.
//!
//! The constructions are generic over the projection; the Miquel statements are
//! Jüttler's for δ (and transfer to every oval quadric through [`super::QuadricProjection`]).

use super::helpers::{self, fmt_scalar, fmt_vec};
use super::image::{patch_image, ImagePatch};
use super::{check_on_quadric, GeneralizedProjection, Hom, Mat4, QuadricError};
use crate::Certified;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::BezierPatch;

/// A biquadratic patch on a quadric, the image of a bilinear patch, with its corners,
/// boundary conics and Miquel points.
#[derive(Debug, Clone, PartialEq)]
pub struct BiquadraticPatch<F> {
    bilinear: [Hom<F>; 4],
    image: ImagePatch<F>,
    corners: [Hom<F>; 4],
    second: [Hom<F>; 4],
    planes: [Hom<F>; 4],
    corner_fibre_images: [Hom<F>; 4],
    quadric: Mat4<F>,
    closure: Option<(Hom<F>, Hom<F>)>,
}

/// The plane (covector) through three points, or `None` if they are not independent.
fn plane_through<F: Scalar>(a: &Hom<F>, b: &Hom<F>, c: &Hom<F>) -> Option<Hom<F>> {
    let ann = helpers::annihilator(&[a.clone(), b.clone(), c.clone()]);
    if ann.len() == 1 {
        ann.into_iter().next()
    } else {
        None
    }
}

/// The second intersection `q` of the quadric with the line `plane_a ∩ plane_b` through
/// `p`: `q = (wᵀQw)·p − 2(pᵀQw)·w` for a second point `w` of the line; `q = p` when the
/// line touches the quadric (tangent circles).
///
/// # Errors
/// [`QuadricError::Degenerate`] if the planes coincide or the line lies on the quadric.
pub fn second_intersection<F: Scalar>(
    q: &Mat4<F>,
    p: &Hom<F>,
    plane_a: &Hom<F>,
    plane_b: &Hom<F>,
) -> Result<Hom<F>, QuadricError> {
    let line = helpers::null_space(&[plane_a.to_vec(), plane_b.to_vec()], 4);
    if line.len() != 2 {
        return Err(QuadricError::Degenerate(
            "two boundary circles lie in the same plane".into(),
        ));
    }
    let w = line
        .iter()
        .map(|v| helpers::to_hom(v))
        .filter(|w| !helpers::parallel(w, p))
        .max_by(|a, b| helpers::magnitude(a).total_cmp(&helpers::magnitude(b)))
        .ok_or_else(|| {
            QuadricError::Degenerate(
                "the corner is not on the line of the two circle planes".into(),
            )
        })?;
    let wqw = helpers::bilinear(q, &w, &w);
    let pqw = helpers::bilinear(q, p, &w);
    let scale = helpers::magnitude(&q.concat())
        * helpers::magnitude(&w)
        * helpers::magnitude(p).max(helpers::magnitude(&w));
    if helpers::negligible(&pqw, scale) {
        if helpers::negligible(&wqw, scale) {
            return Err(QuadricError::Degenerate(
                "the line of two circle planes lies on the quadric".into(),
            ));
        }
        return Ok(p.clone());
    }
    let two = F::from_i64(2);
    Ok(helpers::sub4(
        &helpers::scale4(&wqw, p),
        &helpers::scale4(&(two * pqw), &w),
    ))
}

/// Normalizes a homogeneous point by its first non-zero coordinate (for `k ∈ K`: `k0 = 1`).
fn normalized<F: Scalar>(p: &Hom<F>) -> Hom<F> {
    match p.iter().find(|x| !x.is_zero()) {
        Some(d) => {
            let d = d.clone();
            p.clone().map(|x| x / d.clone())
        }
        None => p.clone(),
    }
}

fn det4<F: Scalar>(a: &Hom<F>, b: &Hom<F>, c: &Hom<F>, d: &Hom<F>) -> F {
    let m: Vec<Vec<F>> = [a, b, c, d]
        .iter()
        .map(|p| normalized(p).to_vec())
        .collect();
    helpers::det(&m)
}

/// The Miquel residuals `(det[p1,q2,p3,q4], det[q1,p2,q3,p4])`, points normalized by their
/// first non-zero coordinate (`k0 = 1` on the sphere). Both vanish for a biquadratic patch
/// on the quadric (Satz 7).
pub fn miquel_residuals<F: Scalar>(p: &[Hom<F>; 4], q: &[Hom<F>; 4]) -> (F, F) {
    (
        det4(&p[0], &q[1], &p[2], &q[3]),
        det4(&q[0], &p[1], &q[2], &p[3]),
    )
}

/// `F(line) ∩ span(cur, F(r))`: the point of the projecting line `[a, b]` in the plane
/// spanned by `cur` and the projecting line over `r`.
fn chain_step<F: Scalar, P: GeneralizedProjection<F> + ?Sized>(
    proj: &P,
    cur: &Hom<F>,
    target: &Hom<F>,
    third: &Hom<F>,
    label: &str,
) -> Result<Hom<F>, QuadricError> {
    let [ra, rb] = proj.fibre(third)?;
    let plane = plane_through(cur, &ra, &rb).ok_or_else(|| {
        QuadricError::Degenerate(format!(
            "{label}: the corner lies on the projecting line of the circle point"
        ))
    })?;
    let [a, b] = proj.fibre(target)?;
    let la = helpers::dot(&plane, &b);
    let mu = -helpers::dot(&plane, &a);
    let x = helpers::add4(&helpers::scale4(&la, &a), &helpers::scale4(&mu, &b));
    if helpers::all_negligible(
        &x,
        helpers::magnitude(&a).max(helpers::magnitude(&b)) * helpers::magnitude(&plane),
    ) {
        return Err(QuadricError::Degenerate(format!(
            "{label}: the projecting line of the next corner lies in the plane (the circle is not determined)"
        )));
    }
    Ok(x)
}

impl<F: Scalar> BiquadraticPatch<F> {
    /// The biquadratic image of the bilinear patch with corners `c00, c10, c11, c01`
    /// (docs/math/quadrics.md, "Biquadratic sphere patches and the Miquel configuration"), with its corners, circle planes and second intersections `qᵢ`.
    ///
    /// # Errors
    /// [`QuadricError::Degenerate`] if an edge maps to less than a proper conic (e.g. an
    /// edge is a projecting line) or two boundary circles coincide; errors of
    /// [`patch_image`].
    pub fn from_bilinear<P: GeneralizedProjection<F> + ?Sized>(
        proj: &P,
        c00: Hom<F>,
        c10: Hom<F>,
        c11: Hom<F>,
        c01: Hom<F>,
    ) -> Result<Self, QuadricError> {
        Self::build(proj, [c00, c10, c11, c01], None)
    }

    fn build<P: GeneralizedProjection<F> + ?Sized>(
        proj: &P,
        c: [Hom<F>; 4],
        closure: Option<(Hom<F>, Hom<F>)>,
    ) -> Result<Self, QuadricError> {
        let [c00, c10, c11, c01] = c.clone();
        let net = vec![
            vec![c00.to_vec(), c01.to_vec()],
            vec![c10.to_vec(), c11.to_vec()],
        ];
        let patch = BezierPatch::from_homogeneous(net)?;
        let image = patch_image(proj, &patch)?;
        let y = image.image();
        let d = |i: usize, j: usize| helpers::to_hom(y.control_point(i, j));
        let corners = [d(0, 0), d(2, 0), d(2, 2), d(0, 2)];
        for (i, k) in corners.iter().enumerate() {
            if helpers::all_negligible(k, helpers::magnitude(k)) {
                return Err(QuadricError::Degenerate(format!(
                    "corner p{} of the image vanishes (the bilinear corner lies on the exceptional set)",
                    i + 1
                )));
            }
        }
        let edge = |pts: [Hom<F>; 3], name: &str| {
            plane_through(&pts[0], &pts[1], &pts[2]).ok_or_else(|| {
                QuadricError::Degenerate(format!(
                    "the boundary curve {name} is not a proper conic (its control points do not span a plane)"
                ))
            })
        };
        let planes = [
            edge([d(0, 0), d(1, 0), d(2, 0)], "C12 (v = 0)")?,
            edge([d(2, 0), d(2, 1), d(2, 2)], "C23 (u = 1)")?,
            edge([d(0, 2), d(1, 2), d(2, 2)], "C34 (v = 1)")?,
            edge([d(0, 0), d(0, 1), d(0, 2)], "C41 (u = 0)")?,
        ];
        let q = proj.quadric();
        // p1: C41 ∩ C12; p2: C12 ∩ C23; p3: C23 ∩ C34; p4: C34 ∩ C41
        let second = [
            second_intersection(&q, &corners[0], &planes[3], &planes[0])?,
            second_intersection(&q, &corners[1], &planes[0], &planes[1])?,
            second_intersection(&q, &corners[2], &planes[1], &planes[2])?,
            second_intersection(&q, &corners[3], &planes[2], &planes[3])?,
        ];
        // the projecting line in the plane of the two edge lines at each corner
        let corner_planes = [
            (c00.clone(), c10.clone(), c01.clone()),
            (c10.clone(), c00.clone(), c11.clone()),
            (c11.clone(), c10.clone(), c01.clone()),
            (c01.clone(), c11.clone(), c00.clone()),
        ];
        let mut corner_fibre_images = [
            helpers::zero4(),
            helpers::zero4(),
            helpers::zero4(),
            helpers::zero4(),
        ];
        for (i, (a, b, cc)) in corner_planes.iter().enumerate() {
            if let Some(pl) = plane_through(a, b, cc) {
                if let Ok([fa, fb]) = proj.fibre_in_plane(&pl) {
                    let s = helpers::add4(&fa, &fb);
                    let mut img = proj.apply(&s);
                    if helpers::is_zero_vec(&img) {
                        img = proj.apply(&fa);
                    }
                    corner_fibre_images[i] = img;
                }
            }
        }
        Ok(BiquadraticPatch {
            bilinear: c,
            image,
            corners,
            second,
            planes,
            corner_fibre_images,
            quadric: q,
            closure,
        })
    }

    /// The biquadratic patch with corners `p1..p4` whose boundary circles are
    /// `C12 ∋ p1, p2, e12`, `C23 ∋ p2, p3, e23`, `C34 ∋ p3, p4, e34`, `C41 ∋ p4, p1, e41`
    /// (each `e_ij` a third point of the circle), by the chain of docs/math/quadrics.md, "Biquadratic sphere patches and the Miquel configuration". `weight`
    /// scales the corner `c11` (the essential weight; `1` is a good default).
    ///
    /// # Errors
    /// [`QuadricError::NotOnQuadric`]; [`QuadricError::Degenerate`] if a circle is not
    /// determined by its three points or a corner repeats; [`QuadricError::MiquelFails`]
    /// with the residual `det[p1,q2,p3,q4]` if the configuration is not Miquel (Satz 7:
    /// then no biquadratic patch with these corners and circles exists). When points of
    /// the configuration coincide (`q2 = p3`, tangent circles) the determinant vanishes
    /// trivially; then the closure of the chain decides, and a failing closure is
    /// reported as `MiquelFails` with residual `0` and the coincidences.
    pub fn from_corners<P: GeneralizedProjection<F> + ?Sized>(
        proj: &P,
        corners: [Hom<F>; 4],
        edge_points: [Hom<F>; 4],
        weight: F,
    ) -> Result<Self, QuadricError> {
        let q = proj.quadric();
        let name = proj.name();
        for (i, p) in corners.iter().enumerate() {
            check_on_quadric(&q, p, &format!("corner p{}", i + 1), &name)?;
        }
        const EDGES: [&str; 4] = ["e12", "e23", "e34", "e41"];
        for (i, e) in edge_points.iter().enumerate() {
            check_on_quadric(&q, e, &format!("circle point {}", EDGES[i]), &name)?;
        }
        if weight.is_zero() || !helpers::all_finite(std::slice::from_ref(&weight)) {
            return Err(QuadricError::InvalidArgument(
                "the weight must be finite and non-zero".into(),
            ));
        }
        let mut planes = Vec::new();
        for i in 0..4 {
            let (a, b) = (&corners[i], &corners[(i + 1) % 4]);
            if helpers::parallel(a, b) {
                return Err(QuadricError::Degenerate(format!(
                    "corners p{} and p{} coincide",
                    i + 1,
                    (i + 1) % 4 + 1
                )));
            }
            let pl = plane_through(a, b, &edge_points[i]).ok_or_else(|| {
                QuadricError::Degenerate(format!(
                    "circle C{}{} is not determined: {} coincides with a corner",
                    i + 1,
                    (i + 1) % 4 + 1,
                    EDGES[i]
                ))
            })?;
            planes.push(pl);
        }
        let second = [
            second_intersection(&q, &corners[0], &planes[3], &planes[0])?,
            second_intersection(&q, &corners[1], &planes[0], &planes[1])?,
            second_intersection(&q, &corners[2], &planes[1], &planes[2])?,
            second_intersection(&q, &corners[3], &planes[2], &planes[3])?,
        ];
        let (r1, r2) = miquel_residuals(&corners, &second);
        let scale = 1.0;
        if !helpers::negligible(&r1, scale) {
            return Err(QuadricError::MiquelFails {
                residual: fmt_scalar(&r1),
                detail: format!("; det[q1, p2, q3, p4] = {}", fmt_scalar(&r2)),
            });
        }
        let [a1, b1] = proj.fibre(&corners[0])?;
        let c00 = helpers::add4(&a1, &b1);
        let c10 = chain_step(proj, &c00, &corners[1], &edge_points[0], "c00 → c10")?;
        let c11 = chain_step(proj, &c10, &corners[2], &edge_points[1], "c10 → c11")?;
        let c01 = chain_step(proj, &c11, &corners[3], &edge_points[2], "c11 → c01")?;
        let back = chain_step(proj, &c01, &corners[0], &edge_points[3], "c01 → c00")?;
        if !helpers::parallel(&back, &c00) {
            // det[p1,q2,p3,q4] = 0 holds but is vacuous when points of the configuration
            // coincide (e.g. q2 = p3); the chain decides (docs/math/quadrics.md, "Biquadratic sphere patches and the Miquel configuration").
            let coincide: Vec<String> = (0..4)
                .flat_map(|i| (0..4).map(move |j| (i, j)))
                .filter(|&(i, j)| helpers::parallel(&second[i], &corners[j]))
                .map(|(i, j)| format!("q{} = p{}", i + 1, j + 1))
                .collect();
            return Err(QuadricError::MiquelFails {
                residual: fmt_scalar(&r1),
                detail: format!(
                    "; the determinant test is vacuous for this degenerate configuration ({}) and the chain construction does not close: c00' = {} ∦ c00 = {}",
                    if coincide.is_empty() { "no coincidences".to_string() } else { coincide.join(", ") },
                    fmt_vec(&back),
                    fmt_vec(&c00)
                ),
            });
        }
        let c11w = helpers::scale4(&weight, &c11);
        Self::build(proj, [c00.clone(), c10, c11w, c01], Some((c00, back)))
    }

    /// The converse of Satz 7 from the eight points of a Miquel configuration: corners
    /// `p1..p4` and second intersections `q1..q4` with `C12 ∋ p1,p2,q1,q2`,
    /// `C23 ∋ p2,p3,q2,q3`, `C34 ∋ p3,p4,q3,q4`, `C41 ∋ p4,p1,q4,q1` (docs/math/quadrics.md, "Biquadratic sphere patches and the Miquel configuration").
    ///
    /// # Errors
    /// As [`Self::from_corners`]; [`QuadricError::Degenerate`] if a boundary circle is not
    /// determined by its points (all its points coincide with its corners).
    pub fn from_miquel_points<P: GeneralizedProjection<F> + ?Sized>(
        proj: &P,
        p: [Hom<F>; 4],
        q: [Hom<F>; 4],
        weight: F,
    ) -> Result<Self, QuadricError> {
        let mut edge = Vec::new();
        for i in 0..4 {
            let j = (i + 1) % 4;
            let cand = [&q[i], &q[j]];
            let e = cand
                .iter()
                .find(|e| plane_through(&p[i], &p[j], e).is_some())
                .ok_or_else(|| {
                    QuadricError::Degenerate(format!(
                        "circle C{}{} is not determined by p{}, p{}, q{}, q{}",
                        i + 1,
                        j + 1,
                        i + 1,
                        j + 1,
                        i + 1,
                        j + 1
                    ))
                })?;
            edge.push((*e).clone());
        }
        let edge: [Hom<F>; 4] = [
            edge[0].clone(),
            edge[1].clone(),
            edge[2].clone(),
            edge[3].clone(),
        ];
        // the four boundary circles must contain the given q's
        for i in 0..4 {
            let j = (i + 1) % 4;
            let d = det4(&p[i], &p[j], &q[i], &q[j]);
            if !helpers::negligible(&d, 1.0) {
                return Err(QuadricError::Degenerate(format!(
                    "p{}, p{}, q{}, q{} are not concyclic: det = {}",
                    i + 1,
                    j + 1,
                    i + 1,
                    j + 1,
                    fmt_scalar(&d)
                )));
            }
        }
        Self::from_corners(proj, p, edge, weight)
    }

    /// The bilinear preimage `[c00, c10, c11, c01]`.
    pub fn bilinear(&self) -> &[Hom<F>; 4] {
        &self.bilinear
    }
    /// The biquadratic patch on the quadric.
    pub fn patch(&self) -> &BezierPatch<F> {
        self.image.image()
    }
    /// The image construction (polar-form rule).
    pub fn image(&self) -> &ImagePatch<F> {
        &self.image
    }
    /// The corners `p1 = y(0,0)`, `p2 = y(1,0)`, `p3 = y(1,1)`, `p4 = y(0,1)`.
    pub fn corners(&self) -> &[Hom<F>; 4] {
        &self.corners
    }
    /// The second intersections `q1..q4` of adjacent boundary circles.
    pub fn second_points(&self) -> &[Hom<F>; 4] {
        &self.second
    }
    /// The planes (covectors) of the boundary circles `C12, C23, C34, C41`.
    pub fn circle_planes(&self) -> &[Hom<F>; 4] {
        &self.planes
    }
    /// The Miquel residuals `(det[p1,q2,p3,q4], det[q1,p2,q3,p4])`.
    pub fn miquel_residuals(&self) -> (F, F) {
        miquel_residuals(&self.corners, &self.second)
    }
}

impl<F: Scalar> Certified for BiquadraticPatch<F> {
    /// The image certificates (on the quadric, polar-form rule); boundary conics in their
    /// planes; `C_ij ∋ p_i, p_j, q_i, q_j`; the `qᵢ` on the quadric and equal to the image
    /// of the projecting line in the corner plane; Satz 7 / Miquel:
    /// `det[p1,q2,p3,q4] = det[q1,p2,q3,p4] = 0`; for the chain construction the closure
    /// `c00' ∥ c00`.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.image.certify();
        let y = self.image.image();
        let names = ["C12 (v = 0)", "C23 (u = 1)", "C34 (v = 1)", "C41 (u = 0)"];
        let edges: [Vec<(usize, usize)>; 4] = [
            (0..3).map(|i| (i, 0)).collect(),
            (0..3).map(|j| (2, j)).collect(),
            (0..3).map(|i| (i, 2)).collect(),
            (0..3).map(|j| (0, j)).collect(),
        ];
        for (k, pl) in self.planes.iter().enumerate() {
            let pts: Vec<Hom<F>> = edges[k]
                .iter()
                .map(|&(i, j)| helpers::to_hom(y.control_point(i, j)))
                .collect();
            let members = [
                &self.corners[k],
                &self.corners[(k + 1) % 4],
                &self.second[k],
                &self.second[(k + 1) % 4],
            ];
            let scale = helpers::magnitude(pl)
                * pts
                    .iter()
                    .chain(members.iter().copied())
                    .map(|p| helpers::magnitude(p))
                    .fold(1.0, f64::max);
            let ok = pts
                .iter()
                .chain(members.iter().copied())
                .all(|p| helpers::negligible(&helpers::dot(pl, p), scale));
            out.push(Certificate::decide(
                format!(
                    "boundary {} is the plane section through p{}, p{}, q{}, q{}",
                    names[k],
                    k + 1,
                    (k + 1) % 4 + 1,
                    k + 1,
                    (k + 1) % 4 + 1
                ),
                ok,
                F::EXACT,
                || format!("plane {} misses a point", fmt_vec(pl)),
            ));
        }
        for (i, qi) in self.second.iter().enumerate() {
            let (r, mag) = helpers::quad_form(&self.quadric, qi);
            out.push(Certificate::decide(
                format!("q{} lies on the quadric", i + 1),
                helpers::negligible(&r, mag),
                F::EXACT,
                || fmt_scalar(&r),
            ));
            let f = &self.corner_fibre_images[i];
            let ok = !helpers::is_zero_vec(f) && helpers::parallel(f, qi);
            out.push(Certificate::decide(
                format!("q{} is the image of the projecting line in the plane of the edges at corner {}", i + 1, i + 1),
                ok,
                F::EXACT,
                || format!("{} vs {}", fmt_vec(f), fmt_vec(qi)),
            ));
        }
        let (r1, r2) = self.miquel_residuals();
        out.push(Certificate::decide(
            "Satz 7: p1, q2, p3, q4 concyclic: det[p1, q2, p3, q4] = 0",
            helpers::negligible(&r1, 1.0),
            F::EXACT,
            || fmt_scalar(&r1),
        ));
        out.push(Certificate::decide(
            "Miquel: q1, p2, q3, p4 concyclic: det[q1, p2, q3, p4] = 0",
            helpers::negligible(&r2, 1.0),
            F::EXACT,
            || fmt_scalar(&r2),
        ));
        if let Some((start, back)) = &self.closure {
            out.push(Certificate::decide(
                "the chain closes, c00' ∥ c00",
                helpers::parallel(start, back),
                F::EXACT,
                || format!("{} vs {}", fmt_vec(start), fmt_vec(back)),
            ));
        }
        out
    }
}
