//! Modeling with PN surfaces (Peternell §4.4; docs/math/laguerre-pn.md): Hermite data — points `Aᵢ`
//! with oriented tangent planes `αᵢ` (unit normals `nᵢ`) — interpolated by a G¹ surface
//! made of parabolic Dupin cyclide pieces, all with rational offsets.
//!
//! 1. `Bᵢ = Λ(αᵢ) = (uᵢ, vᵢ, Fᵢ)` (3.11) (needs `nᵢ ≠ (0, 0, 1)`; rotate the frame
//!    otherwise).
//! 2. The point datum becomes a gradient datum: the graph must touch at `Bᵢ` the
//!    isotropic sphere of the point cycle `(Aᵢ; 0)`,
//!    `F_A(u, v) = −[A₃(u² + v²) + 2A₁u + 2A₂v − A₃]/2`, so
//!    `∇F(uᵢ, vᵢ) = −(A₃uᵢ + A₁, A₃vᵢ + A₂)` (the closed formula of Theorem 4.3/4.4 uses
//!    only `F`, `F_u`, `F_v`, and `F_A` maps to the constant point `Aᵢ`).
//! 3. The data `(uᵢ, vᵢ; Fᵢ, ∇Fᵢ)` are interpolated by the C¹ piecewise quadratic
//!    Powell–Sabin spline (6-split; the split point of a macro triangle is its centroid, the
//!    split point of an interior edge is where the segment between the two centroids
//!    crosses it, of a boundary edge its midpoint).
//! 4. `Λ⁻¹` of every quadratic piece is a parabolic Dupin cyclide patch
//!    (docs/math/laguerre-pn.md#closed-formula; Errata E11): C¹ in
//!    `I³` gives G¹ (continuous tangent planes) in `R³`; the pieces meet along cubics.
//!    Point regularity is not guaranteed (parabolic points ↔ Gauss-map singularities):
//!    [`PnModel::check_regular`] decides it. The offset of the whole model is
//!    `F ↦ F − (d/2)(S + 1)` piecewise — still piecewise quadratic, still cyclides.
//!
//! Certificates: `x(uᵢ, vᵢ) = Aᵢ`, `n(uᵢ, vᵢ) = nᵢ`, value and gradient of `F` continuous
//! across every edge of the split (exact polynomial identities along the edge), and the PN
//! identities of every piece.

use super::isotropic::IsotropicSurface;
use super::poly::{compose, compose_fan, int, patch_of, var, Domain};
use super::surface::{check_nonzero, PnSurface};
use super::PnError;
use crate::error::{format_point, format_scalar};
use crate::laguerre::OrientedPlane;
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::BezierPatch;

/// A Hermite datum: a point and a rational unit normal of the oriented tangent plane there.
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteDatum<F> {
    /// The point `A`.
    pub point: [F; 3],
    /// The unit normal `n` of the oriented plane `α` through `A`.
    pub normal: [F; 3],
}

impl<F: Scalar> HermiteDatum<F> {
    /// The datum `(A, n)`.
    ///
    /// # Errors
    /// [`PnError::ModelingData`] unless `|n|² = 1` (exactly for exact scalars).
    pub fn new(point: [F; 3], normal: [F; 3]) -> Result<Self, PnError> {
        OrientedPlane::through_point(normal.clone(), &point).map_err(|e| {
            PnError::ModelingData(format!("datum at {}: {e}", format_point(&point)))
        })?;
        Ok(HermiteDatum { point, normal })
    }

    /// Samples a surface strip — a boundary curve `c(t)` with a rational unit normal field
    /// `n(t)` along it — at the given parameters (so a boundary curve is approximated by
    /// interpolating its samples).
    ///
    /// # Errors
    /// [`PnError::ModelingData`] where the strip is undefined or `n` is not a unit vector.
    pub fn sample_strip(
        curve: &[super::RatFn<F>; 3],
        normal: &[super::RatFn<F>; 3],
        params: &[F],
    ) -> Result<Vec<Self>, PnError> {
        params
            .iter()
            .map(|t| {
                let x = [t.clone(), F::zero()];
                let ev = |f: &super::RatFn<F>| {
                    f.eval(&x).ok_or_else(|| {
                        PnError::ModelingData(format!(
                            "the strip is undefined at t = {}",
                            format_scalar(t)
                        ))
                    })
                };
                Self::new(
                    [ev(&curve[0])?, ev(&curve[1])?, ev(&curve[2])?],
                    [ev(&normal[0])?, ev(&normal[1])?, ev(&normal[2])?],
                )
            })
            .collect()
    }
}

/// One parabolic Dupin cyclide piece: a micro-triangle of the Powell–Sabin split, its
/// quadratic `F` and the PN surface `Λ⁻¹(graph F)`.
#[derive(Debug, Clone)]
pub struct PnPiece<F> {
    /// The macro triangle (index into the triangulation).
    pub macro_triangle: usize,
    /// The micro-triangle in the `(u, v)` plane.
    pub vertices: [[F; 2]; 3],
    /// The quadratic `F(u, v)` on it.
    pub f: MPoly<F>,
    /// The PN surface of the graph of `F`.
    pub surface: PnSurface<F>,
}

impl<F: Scalar> PnPiece<F> {
    /// The collapsed parametrization `(s, t) ↦ P₀ + s(P₁ − P₀) + st(P₂ − P₁)` of the
    /// micro-triangle (degenerate edge `s = 0` at `P₀`).
    /// `p` composed with [`Self::collapse_map`]: for exact scalars by [`compose_fan`]
    /// with `e₁ = P₁ − P₀`, `e₂ = P₂ − P₁` (the same polynomial); for `f64` (whose
    /// rounding depends on the order of the operations) and for polynomials in other
    /// variables by [`compose`].
    fn collapsed(&self, p: &MPoly<F>) -> MPoly<F> {
        if !F::EXACT {
            return compose(p, &self.collapse_map());
        }
        let [p0, p1, p2] = &self.vertices;
        let e1 = [p1[0].clone() - p0[0].clone(), p1[1].clone() - p0[1].clone()];
        let e2 = [p2[0].clone() - p1[0].clone(), p2[1].clone() - p1[1].clone()];
        compose_fan(p, p0, &e1, &e2).unwrap_or_else(|| compose(p, &self.collapse_map()))
    }

    fn collapse_map(&self) -> [MPoly<F>; 2] {
        let [p0, p1, p2] = &self.vertices;
        let (s, t) = (var::<F>(0), var::<F>(1));
        let st = &s * &t;
        std::array::from_fn(|k| {
            &(&MPoly::constant(2, p0[k].clone()) + &s.scale(&(p1[k].clone() - p0[k].clone())))
                + &st.scale(&(p2[k].clone() - p1[k].clone()))
        })
    }

    /// The piece as a rational tensor-product Bézier patch over the triangle (a degenerate
    /// patch with the edge `s = 0` collapsed to the first vertex).
    ///
    /// # Errors
    /// Only geometry-layer failures.
    pub fn patch(&self) -> Result<BezierPatch<F>, PnError> {
        let coords: Vec<MPoly<F>> = self
            .surface
            .point_polys()
            .iter()
            .map(|p| self.collapsed(p))
            .collect();
        patch_of(&coords, &Domain::unit())
    }
}

/// A PN surface interpolating Hermite data, made of parabolic Dupin cyclide pieces
/// (Peternell §4.4).
#[derive(Debug, Clone)]
pub struct PnModel<F> {
    data: Vec<HermiteDatum<F>>,
    params: Vec<[F; 2]>,
    values: Vec<F>,
    grads: Vec<[F; 2]>,
    triangles: Vec<[usize; 3]>,
    pieces: Vec<PnPiece<F>>,
    distance: F,
}

fn sub2<F: Scalar>(a: &[F; 2], b: &[F; 2]) -> [F; 2] {
    [a[0].clone() - b[0].clone(), a[1].clone() - b[1].clone()]
}
fn lerp2<F: Scalar>(a: &[F; 2], b: &[F; 2], l: &F) -> [F; 2] {
    [
        a[0].clone() + l.clone() * (b[0].clone() - a[0].clone()),
        a[1].clone() + l.clone() * (b[1].clone() - a[1].clone()),
    ]
}
fn mid2<F: Scalar>(a: &[F; 2], b: &[F; 2]) -> [F; 2] {
    lerp2(a, b, &F::from_ratio(1, 2))
}
fn cross2<F: Scalar>(a: &[F; 2], b: &[F; 2]) -> F {
    a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone()
}
/// Barycentric coordinates of `x` w.r.t. the triangle `(p, q, r)`.
fn bary<F: Scalar>(x: &[F; 2], p: &[F; 2], q: &[F; 2], r: &[F; 2]) -> [F; 3] {
    let area = cross2(&sub2(q, p), &sub2(r, p));
    let l1 = cross2(&sub2(x, p), &sub2(r, p)) / area.clone();
    let l2 = cross2(&sub2(q, p), &sub2(x, p)) / area;
    [F::one() - l1.clone() - l2.clone(), l1, l2]
}

impl<F: Scalar> PnModel<F> {
    /// Interpolates the Hermite data over the given triangulation of their isotropic
    /// parameter points `(uᵢ, vᵢ)` (index triples into `data`).
    ///
    /// # Errors
    /// [`PnError::ModelingData`] for data the scheme cannot match: a normal `(0, 0, 1)`
    /// (no isotropic image; rotate the frame), two data with the same isotropic parameter
    /// point (equal normals), an index out of range, a degenerate triangle, an edge shared
    /// by more than two triangles, a datum that is a vertex of no triangle, or an interior
    /// edge that the segment between the two
    /// centroids does not cross inside (the Powell–Sabin split fails).
    pub fn interpolate(
        data: &[HermiteDatum<F>],
        triangles: &[[usize; 3]],
    ) -> Result<Self, PnError> {
        if triangles.is_empty() {
            return Err(PnError::ModelingData("no triangles given".into()));
        }
        let mut params = Vec::with_capacity(data.len());
        let mut values = Vec::with_capacity(data.len());
        let mut grads = Vec::with_capacity(data.len());
        for (i, d) in data.iter().enumerate() {
            let plane = OrientedPlane::through_point(d.normal.clone(), &d.point)
                .map_err(|e| PnError::ModelingData(format!("datum {i}: {e}")))?;
            let y = plane.to_isotropic().map_err(|_| {
                PnError::ModelingData(format!(
                    "datum {i} has the normal (0, 0, 1), which has no image in the isotropic model: rotate the frame"
                ))
            })?;
            let [u, v, f] = y;
            let a = &d.point;
            // ∇F = −(A₃u + A₁, A₃v + A₂)
            grads.push([
                -(a[2].clone() * u.clone() + a[0].clone()),
                -(a[2].clone() * v.clone() + a[1].clone()),
            ]);
            params.push([u, v]);
            values.push(f);
        }
        for i in 0..params.len() {
            for j in i + 1..params.len() {
                if params[i] == params[j] {
                    return Err(PnError::ModelingData(format!(
                        "data {i} and {j} have the same normal, hence the same isotropic parameter point {}: the graph cannot interpolate both",
                        format_point(&params[i])
                    )));
                }
            }
        }
        // orient the triangles counter-clockwise; validate
        let mut tris = Vec::with_capacity(triangles.len());
        for (k, t) in triangles.iter().enumerate() {
            if t.iter().any(|&i| i >= data.len()) {
                return Err(PnError::ModelingData(format!(
                    "triangle {k} has an index out of range"
                )));
            }
            let area = cross2(
                &sub2(&params[t[1]], &params[t[0]]),
                &sub2(&params[t[2]], &params[t[0]]),
            );
            if area.is_zero() {
                return Err(PnError::ModelingData(format!(
                    "triangle {k} is degenerate in the isotropic parameter plane"
                )));
            }
            tris.push(if area > F::zero() {
                *t
            } else {
                [t[0], t[2], t[1]]
            });
        }
        if let Some(i) = (0..data.len()).find(|i| !triangles.iter().any(|t| t.contains(i))) {
            return Err(PnError::ModelingData(format!(
                "datum {i} is a vertex of no triangle: every datum must be a vertex of the triangulation (the surface could not interpolate it)"
            )));
        }
        let centroid = |t: &[usize; 3]| -> [F; 2] {
            let third = F::from_ratio(1, 3);
            [0, 1].map(|c| {
                (params[t[0]][c].clone() + params[t[1]][c].clone() + params[t[2]][c].clone())
                    * third.clone()
            })
        };
        let centroids: Vec<[F; 2]> = tris.iter().map(centroid).collect();
        // split point of every edge: λ with R = (1 − λ)V_a + λV_b for (a, b) = (min, max)
        let mut edges: std::collections::BTreeMap<(usize, usize), Vec<usize>> = Default::default();
        for (k, t) in tris.iter().enumerate() {
            for e in 0..3 {
                let (a, b) = (t[e], t[(e + 1) % 3]);
                edges.entry((a.min(b), a.max(b))).or_default().push(k);
            }
        }
        let mut split: std::collections::BTreeMap<(usize, usize), F> = Default::default();
        for (&(a, b), ts) in &edges {
            let l = match ts.as_slice() {
                [_] => F::from_ratio(1, 2),
                [t1, t2] => {
                    // Z₁ + s(Z₂ − Z₁) = V_a + λ(V_b − V_a)
                    let (z1, z2) = (&centroids[*t1], &centroids[*t2]);
                    let (va, vb) = (&params[a], &params[b]);
                    let dz = sub2(z2, z1);
                    let dv = sub2(vb, va);
                    let den = cross2(&dv, &dz);
                    if den.is_zero() {
                        return Err(PnError::ModelingData(format!(
                            "edge ({a}, {b}): the centroids of its two triangles lie on a parallel line; the Powell–Sabin split fails"
                        )));
                    }
                    let lam = cross2(&sub2(z1, va), &dz) / den;
                    if !(lam > F::zero() && lam < F::one()) {
                        return Err(PnError::ModelingData(format!(
                            "edge ({a}, {b}): the segment between the centroids of its triangles crosses the edge line outside the edge (λ = {}); the Powell–Sabin split fails — refine or flip the triangulation",
                            format_scalar(&lam)
                        )));
                    }
                    lam
                }
                _ => {
                    return Err(PnError::ModelingData(format!(
                        "edge ({a}, {b}) is shared by {} triangles",
                        ts.len()
                    )))
                }
            };
            split.insert((a, b), l);
        }
        let mut model = PnModel {
            data: data.to_vec(),
            params,
            values,
            grads,
            triangles: tris,
            pieces: Vec::new(),
            distance: F::zero(),
        };
        model.pieces = model.build_pieces(&centroids, &split)?;
        Ok(model)
    }

    /// The Powell–Sabin Bézier ordinates and pieces.
    fn build_pieces(
        &self,
        centroids: &[[F; 2]],
        split: &std::collections::BTreeMap<(usize, usize), F>,
    ) -> Result<Vec<PnPiece<F>>, PnError> {
        let mut pieces = Vec::new();
        for (k, t) in self.triangles.iter().enumerate() {
            let z = centroids[k].clone();
            let v: Vec<[F; 2]> = t.iter().map(|&i| self.params[i].clone()).collect();
            // tangent plane at vertex i evaluated at x
            let tp = |i: usize, x: &[F; 2]| -> F {
                let idx = t[i];
                let d = sub2(x, &self.params[idx]);
                self.values[idx].clone()
                    + self.grads[idx][0].clone() * d[0].clone()
                    + self.grads[idx][1].clone() * d[1].clone()
            };
            // split points R_i between vertex i and i+1
            let r: Vec<([F; 2], F)> = (0..3)
                .map(|i| {
                    let (a, b) = (t[i], t[(i + 1) % 3]);
                    let lam = split
                        .get(&(a.min(b), a.max(b)))
                        .cloned()
                        .unwrap_or_else(|| F::from_ratio(1, 2));
                    // λ is measured from min(a, b)
                    let lam_i = if a < b { lam } else { F::one() - lam };
                    (lerp2(&v[i], &v[(i + 1) % 3], &lam_i), lam_i)
                })
                .collect();
            // ordinates: vertex, mid(V,R), R, mid(V,Z), Z, mid(R,Z)
            let mid_vz: Vec<F> = (0..3).map(|i| tp(i, &mid2(&v[i], &z))).collect();
            let third = F::from_ratio(1, 3);
            let bz = (mid_vz[0].clone() + mid_vz[1].clone() + mid_vz[2].clone()) * third;
            // the tangent plane at Z through the points (mid(Vᵢ, Z), b): evaluate at x
            let lz = |x: &[F; 2]| -> F {
                // barycentric of 2x − Z w.r.t. V
                let y = [
                    F::from_i64(2) * x[0].clone() - z[0].clone(),
                    F::from_i64(2) * x[1].clone() - z[1].clone(),
                ];
                let g = bary(&y, &v[0], &v[1], &v[2]);
                (0..3).fold(F::zero(), |s, i| s + g[i].clone() * mid_vz[i].clone())
            };
            for i in 0..3 {
                let j = (i + 1) % 3;
                let (ri, lam) = (&r[i].0, &r[i].1);
                let b_mid_vr = tp(i, &mid2(&v[i], ri));
                let b_mid_rv = tp(j, &mid2(ri, &v[j]));
                let b_r =
                    (F::one() - lam.clone()) * b_mid_vr.clone() + lam.clone() * b_mid_rv.clone();
                let b_mid_rz = lz(&mid2(ri, &z));
                // micro-triangle (Vᵢ, Rᵢ, Z): mids are b(P₀P₁), b(P₁P₂), b(P₀P₂)
                let t1 = (
                    [v[i].clone(), ri.clone(), z.clone()],
                    [self.values[t[i]].clone(), b_r.clone(), bz.clone()],
                    [b_mid_vr, b_mid_rz.clone(), mid_vz[i].clone()],
                );
                // micro-triangle (Rᵢ, V_j, Z)
                let t2 = (
                    [ri.clone(), v[j].clone(), z.clone()],
                    [b_r, self.values[t[j]].clone(), bz.clone()],
                    [b_mid_rv, mid_vz[j].clone(), b_mid_rz],
                );
                for (pts, vals, mids) in [t1, t2] {
                    let f = quadratic_from_bezier(
                        [&pts[0], &pts[1], &pts[2]],
                        [&vals[0], &vals[1], &vals[2]],
                        [&mids[0], &mids[1], &mids[2]],
                    );
                    let f =
                        f.ok_or_else(|| PnError::ModelingData("degenerate micro-triangle".into()))?;
                    let g = &f
                        - &(&(&(&var::<F>(0) * &var::<F>(0)) + &(&var::<F>(1) * &var::<F>(1)))
                            + &int(1))
                            .scale(&(self.distance.clone() / F::from_i64(2)));
                    let surface = IsotropicSurface::graph_poly(g.clone())
                        .to_pn_surface()?
                        .named(format!("cyclide piece of triangle {k}"));
                    pieces.push(PnPiece {
                        macro_triangle: k,
                        vertices: pts,
                        f: g,
                        surface,
                    });
                }
            }
        }
        Ok(pieces)
    }

    /// The pieces.
    pub fn pieces(&self) -> &[PnPiece<F>] {
        &self.pieces
    }

    /// The isotropic parameter points `(uᵢ, vᵢ)` of the data.
    pub fn params(&self) -> &[[F; 2]] {
        &self.params
    }

    /// The (counter-clockwise) macro triangles.
    pub fn triangles(&self) -> &[[usize; 3]] {
        &self.triangles
    }

    /// The offset of the whole model at distance `d` (`F ↦ F − (d/2)(S + 1)` piecewise;
    /// it interpolates the offset data `(Aᵢ + d nᵢ, nᵢ)`).
    pub fn offset(&self, d: F) -> Result<Self, PnError> {
        let half = d.clone() / F::from_i64(2);
        let pieces = self
            .pieces
            .iter()
            .map(|p| {
                let (u, v) = (var::<F>(0), var::<F>(1));
                let g = &p.f - &(&(&(&u * &u) + &(&v * &v)) + &int(1)).scale(&half);
                let surface = IsotropicSurface::graph_poly(g.clone()).to_pn_surface()?;
                Ok(PnPiece {
                    macro_triangle: p.macro_triangle,
                    vertices: p.vertices.clone(),
                    f: g,
                    surface: surface.named(format!(
                        "{} offset by {}",
                        p.surface.name(),
                        format_scalar(&d)
                    )),
                })
            })
            .collect::<Result<Vec<_>, PnError>>()?;
        let data = self
            .data
            .iter()
            .map(|h| HermiteDatum {
                point: std::array::from_fn(|i| {
                    h.point[i].clone() + d.clone() * h.normal[i].clone()
                }),
                normal: h.normal.clone(),
            })
            .collect();
        let (values, grads) = (
            self.params
                .iter()
                .zip(&self.values)
                .map(|(p, f)| {
                    f.clone()
                        - half.clone()
                            * (p[0].clone() * p[0].clone() + p[1].clone() * p[1].clone() + F::one())
                })
                .collect(),
            self.params
                .iter()
                .zip(&self.grads)
                .map(|(p, g)| {
                    [
                        g[0].clone() - d.clone() * p[0].clone(),
                        g[1].clone() - d.clone() * p[1].clone(),
                    ]
                })
                .collect(),
        );
        Ok(PnModel {
            data,
            params: self.params.clone(),
            values,
            grads,
            triangles: self.triangles.clone(),
            pieces,
            distance: self.distance.clone() + d,
        })
    }

    /// Checks that every piece is a regular surface over its micro-triangle (the scheme
    /// does not guarantee it, Peternell §4.4).
    ///
    /// # Errors
    /// [`PnError::Singular`] naming the piece and a parameter point where `x_u × x_v = 0`.
    pub fn check_regular(&self) -> Result<(), PnError> {
        for (k, p) in self.pieces.iter().enumerate() {
            let at = p.surface.regularity_poly();
            let reg = p.collapsed(&at);
            // the collapse map's Jacobian vanishes only on s = 0; R itself must not vanish:
            // test R∘map on [1/64, 1] × [0, 1] and at the collapsed vertex separately
            let dom = Domain::new(F::from_ratio(1, 64), F::one(), F::zero(), F::one())?;
            check_nonzero(
                &reg,
                &dom,
                &format!("piece {k}: singular point (x_u × x_v = 0)"),
            )?;
            let val = super::poly::pad_eval(&at, &p.vertices[0]).unwrap_or_else(F::zero);
            if val.is_zero() {
                return Err(PnError::Singular {
                    what: format!("piece {k}: singular point (x_u × x_v = 0)"),
                    at: format_point(&p.vertices[0]),
                });
            }
        }
        Ok(())
    }
}

/// The quadratic polynomial in `(u, v)` with Bézier ordinates at the vertices and edge
/// midpoints of the triangle `p`: `mids[i]` belongs to the edge opposite... namely
/// `mids = [b(P₀P₁), b(P₁P₂), b(P₀P₂)]`.
fn quadratic_from_bezier<F: Scalar>(
    p: [&[F; 2]; 3],
    vals: [&F; 3],
    mids: [&F; 3],
) -> Option<MPoly<F>> {
    let area = cross2(&sub2(p[1], p[0]), &sub2(p[2], p[0]));
    let inv = area.inv()?;
    let (u, v) = (var::<F>(0), var::<F>(1));
    // barycentric coordinates as affine polynomials: τ₁ = cross(x − p₀, p₂ − p₀)/area, …
    let xp0 = [
        &u - &MPoly::constant(2, p[0][0].clone()),
        &v - &MPoly::constant(2, p[0][1].clone()),
    ];
    let e2 = sub2(p[2], p[0]);
    let e1 = sub2(p[1], p[0]);
    let t1 = (&xp0[0].scale(&e2[1]) - &xp0[1].scale(&e2[0])).scale(&inv);
    let t2 = (&xp0[1].scale(&e1[0]) - &xp0[0].scale(&e1[1])).scale(&inv);
    let t0 = &(&int(1) - &t1) - &t2;
    let two = F::from_i64(2);
    let f = &(&(&(&(&t0 * &t0).scale(vals[0]) + &(&t1 * &t1).scale(vals[1]))
        + &(&t2 * &t2).scale(vals[2]))
        + &(&(&t0 * &t1).scale(&(two.clone() * mids[0].clone()))
            + &(&t1 * &t2).scale(&(two.clone() * mids[1].clone()))))
        + &(&t0 * &t2).scale(&(two * mids[2].clone()));
    Some(f)
}

impl<F: Scalar> Certified for PnModel<F> {
    /// Interpolation of every datum (point and normal), C¹ of `F` across every edge of the
    /// split (value and gradient equal along the common edge), and the PN identities of
    /// every piece.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        // interpolation
        for (i, d) in self.data.iter().enumerate() {
            let [u, v] = &self.params[i];
            let piece = self
                .pieces
                .iter()
                .find(|p| p.vertices.iter().any(|w| w == &self.params[i]));
            let (x, n) = match piece {
                Some(p) => (p.surface.eval(u, v), p.surface.normal_at(u, v)),
                None => {
                    out.push(Certificate::fails(
                        format!("datum {i} interpolated"),
                        "no piece at the datum",
                        F::EXACT,
                    ));
                    continue;
                }
            };
            let ok = matches!((&x, &n), (Ok(x), Ok(n)) if x == &d.point && n == &d.normal)
                || (!F::EXACT
                    && matches!((&x, &n), (Ok(x), Ok(n)) if x.iter().zip(&d.point).chain(n.iter().zip(&d.normal)).all(|(a, b)| (a.to_f64() - b.to_f64()).abs() <= 1e-9 * (1.0 + b.to_f64().abs()))));
            out.push(Certificate::decide(
                format!("datum {i}: x(uᵢ, vᵢ) = Aᵢ and n(uᵢ, vᵢ) = nᵢ (Peternell §4.4)"),
                ok,
                F::EXACT,
                || format!("x = {x:?}, n = {n:?}"),
            ));
        }
        // C¹ across every shared edge of the micro-triangles
        let mut c1_ok = true;
        let mut c1_res = String::new();
        let mut shared = 0usize;
        for a in 0..self.pieces.len() {
            for b in a + 1..self.pieces.len() {
                let (pa, pb) = (&self.pieces[a], &self.pieces[b]);
                let common: Vec<&[F; 2]> = pa
                    .vertices
                    .iter()
                    .filter(|x| pb.vertices.contains(x))
                    .collect();
                if common.len() != 2 {
                    continue;
                }
                shared += 1;
                let (p, q) = (common[0], common[1]);
                let s = var::<F>(0);
                let line = [
                    &MPoly::constant(2, p[0].clone()) + &s.scale(&(q[0].clone() - p[0].clone())),
                    &MPoly::constant(2, p[1].clone()) + &s.scale(&(q[1].clone() - p[1].clone())),
                ];
                let diff = &pa.f - &pb.f;
                for g in [diff.clone(), diff.partial(0), diff.partial(1)] {
                    let r = compose(&g, &line);
                    let zero = if F::EXACT {
                        r.is_zero()
                    } else {
                        r.terms().all(|(_, c)| {
                            c.to_f64().abs() <= 1e-9 * (1.0 + super::poly::mag(&pa.f))
                        })
                    };
                    if !zero {
                        c1_ok = false;
                        c1_res = format!(
                            "pieces {a} and {b} along {} – {}",
                            format_point(p),
                            format_point(q)
                        );
                    }
                }
            }
        }
        out.push(Certificate::decide(
            format!("F is C¹ across all {shared} interior edges of the Powell–Sabin split (value and gradient)"),
            c1_ok,
            F::EXACT,
            || c1_res.clone(),
        ));
        let mut all_pn = true;
        let mut first_bad = String::new();
        for p in &self.pieces {
            for c in p.surface.certify() {
                if !c.holds {
                    all_pn = false;
                    first_bad = c.to_string();
                }
            }
        }
        out.push(Certificate::decide(
            format!(
                "all {} pieces are PN surfaces (n·n ≡ 1, n ⟂ x_u, x_v, x on its plane)",
                self.pieces.len()
            ),
            all_pn,
            F::EXACT,
            || first_bad.clone(),
        ));
        out
    }
}
