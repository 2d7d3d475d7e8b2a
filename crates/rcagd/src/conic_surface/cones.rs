//! Envelopes of rational one-parameter families of quadratic cones, and canal surfaces as
//! envelopes of cones of revolution (M. Peternell, "Rational Parametrizations for Envelopes
//! of Quadric Families", chapter 2: (2.1)–(2.11), Cor. 2.1, Cor. 2.2, Thm 2.1, Thm 2.2,
//! Thm 2.3; derivation in `docs/math/conic-surfaces.md`, section "Quadratic cones").
//!
//! **Duality.** A cone family `xᵀC(t)x = 0` (points, rank 3, vertex `v = ker C`) is the
//! projective dual of the conic family `X·C(t)·Xᵀ = 0` (planes, carrier plane `γ = ker C`)
//! of [`super::ConicFamily`]: Peternell's identities (2.4), (2.6), (2.7) are (1.6), (1.8),
//! (1.9) with `v` for `γ`; a generator of the cone (a line through `v` on it) is dual to a
//! tangent line of the conic in `γ`; the points of a generator are dual to the planes of the
//! pencil through the tangent line; the second intersection of a generator with `ċ(t)` —
//! Peternell's surface point `z(t, u)` and, for a rational generator `y(t)`, the curve of
//! Cor. 2.2 — is dual to the second tangent plane of `ċ(t)` through the tangent line
//! (Thm 1.3). So the envelope `z(t, u)` is the plane form `F(t, u)` of the dual conic
//! surface read as points, and the rational tangent planes of the cones (Cor. 2.1) are the
//! dual conic surface's rational curve read as planes. The certificate is the defining
//! property of the envelope: `z·C(t)·zᵀ ≡ 0` and `z·Ċ(t)·zᵀ ≡ 0`.
//!
//! **Canal surfaces (Thm 2.2, Thm 2.3).** The sphere `|y − m(t)|² = ρ(t)` (`ρ = r²`, only
//! `ρ` needs to be rational) touches the canal surface along the characteristic circle in
//! the plane `Ṡ: (y − m)·ṁ + ρ̇/2 = 0` (2.14). The cone of revolution `D(t)` circumscribing
//! the sphere along that circle has its vertex at the pole `a(t)` of `Ṡ`; for the sphere
//! matrix `A` (homogeneous `xᵀAx = 0`) it is `D = (aᵀAa)·A − (Aa)(Aa)ᵀ` (rank 3, kernel
//! `a`). A generic generator of `D(t)` meets `Ḋ(t)` again on the characteristic circle, so
//! the envelope construction above parametrizes the canal surface.

use super::{point_bidegree, point_patch, ConicFamily, ConicSurfaceError, Mat4, P, Q};
use crate::pn::poly::cancel_gcd;
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Poly};
use rcagd_geom::BezierPatch;

/// A rational one-parameter family of quadratic cones `xᵀC(t)x = 0` (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct ConeFamily {
    dual: ConicFamily,
}

impl ConeFamily {
    /// The cone family of the symmetric polynomial matrix `C(t)`.
    ///
    /// # Errors
    /// As [`ConicFamily::new`] (rank ≠ 3, not symmetric; a fixed vertex is reported as
    /// [`ConicSurfaceError::ConstantPlane`]: the cones share their vertex).
    pub fn new(c: Mat4) -> Result<Self, ConicSurfaceError> {
        Ok(ConeFamily {
            dual: ConicFamily::new(c)?,
        })
    }

    /// `C(t)`.
    pub fn matrix(&self) -> &Mat4 {
        self.dual.matrix()
    }

    /// The vertex `v(t)` (`C·v ≡ 0`, (2.2)).
    pub fn vertex(&self) -> &[P; 4] {
        self.dual.carrier_plane()
    }

    /// The plane `φ = Ċv` tangent to the pencil `λC + μĊ` at `v` (2.6).
    pub fn tangent_plane_at_vertex(&self) -> [P; 4] {
        self.dual.pole()
    }

    /// (2.2), (2.4), (2.6), (2.7) as exact certificates.
    pub fn identities(&self) -> Vec<Certificate> {
        self.dual
            .identities()
            .into_iter()
            .map(|mut c| {
                c.property = c
                    .property
                    .replace(
                        "γ(t) is the carrier plane, Peternell (1.4)",
                        "v(t) is the vertex, Peternell (2.2)",
                    )
                    .replace(
                        "Peternell (1.6), corrected: first derivative",
                        "Peternell (2.4)",
                    )
                    .replace(
                        "the pole p of g = γ ∩ γ̇, Peternell (1.8)",
                        "the plane φ, Peternell (2.6)",
                    )
                    .replace("Peternell (1.9)", "Peternell (2.7)")
                    .replace('γ', "v")
                    .replace("2p·", "2φ·");
                c
            })
            .collect()
    }

    /// Cor. 2.2: a rational curve `f(t)` on the envelope (on the characteristic curve of
    /// `c(t)`): the second intersection of a rational generator with `ċ(t)`.
    ///
    /// # Errors
    /// As [`ConicFamily::tangent_developable`].
    pub fn rational_curve(&self) -> Result<[P; 4], ConicSurfaceError> {
        self.dual.tangent_developable()
    }

    /// Cor. 2.1: a rational family of tangent planes `Y(t)` of the cones (the tangent plane
    /// of `c(t)` along a rational generator).
    ///
    /// # Errors
    /// As [`ConicFamily::rational_curve`].
    pub fn tangent_planes(&self) -> Result<[P; 4], ConicSurfaceError> {
        self.dual.rational_curve()
    }

    /// Thm 2.1: the envelope `z(t, u)` (module docs).
    ///
    /// # Errors
    /// As [`ConicFamily::parametrize`].
    pub fn envelope(&self) -> Result<ConeEnvelope, ConicSurfaceError> {
        let s = self.dual.parametrize()?;
        let mut point = s.planes().clone();
        cancel_gcd(&mut point);
        if point[0].is_zero() {
            return Err(ConicSurfaceError::Degenerate(
                "the envelope lies in the plane at infinity (z₀ ≡ 0: e.g. translated copies of one cone share their conic at infinity)".into(),
            ));
        }
        Ok(ConeEnvelope {
            c: self.dual.matrix().clone(),
            point,
        })
    }
}

/// The envelope of a cone family: homogeneous `z(t, u)` (`z₀` the weight; `t` variable 0,
/// `u` variable 1).
#[derive(Debug, Clone, PartialEq)]
pub struct ConeEnvelope {
    c: Mat4,
    point: [MPoly<Q>; 4],
}

impl ConeEnvelope {
    /// The homogeneous point `z(t, u)`.
    pub fn point(&self) -> &[MPoly<Q>; 4] {
        &self.point
    }

    /// The bidegree `(deg_t, deg_u)`.
    pub fn degree(&self) -> (u32, u32) {
        point_bidegree(&self.point)
    }

    /// The rational Bézier patch on `[t₀, t₁] × [u₀, u₁]`.
    ///
    /// # Errors
    /// [`ConicSurfaceError::Patch`] for an empty rectangle or a vanishing weight `z₀`.
    pub fn patch(&self, t: (Q, Q), u: (Q, Q)) -> Result<BezierPatch<Q>, ConicSurfaceError> {
        point_patch(&self.point, t, u, "z₀")
    }
}

impl Certified for ConeEnvelope {
    /// `z·C·zᵀ ≡ 0` (on the cone `c(t)`), `z·Ċ·zᵀ ≡ 0` (on `ċ(t)`: the characteristic
    /// curve), and `1 ≤ deg_u z ≤ 4`: the characteristic curve `c ∩ ċ` is a quartic with a
    /// double point at the vertex, traced once by the generators (degree 2 in `u`) —
    /// degree 4 in general, lower where it splits (a circle: 2).
    fn certify(&self) -> Vec<Certificate> {
        let dc: Mat4 =
            core::array::from_fn(|i| core::array::from_fn(|j| self.c[i][j].derivative()));
        let f1 = super::form4(&self.c, &self.point, &self.point);
        let f2 = super::form4(&dc, &self.point, &self.point);
        let (_, du) = self.degree();
        vec![
            Certificate::decide(
                "z·C(t)·zᵀ ≡ 0 (z(t, u) lies on the cone c(t))",
                f1.is_zero(),
                true,
                || format!("{} terms", f1.num_terms()),
            ),
            Certificate::decide(
                "z·Ċ(t)·zᵀ ≡ 0 (z(t, u) lies on ċ(t): the envelope touches c(t) there)",
                f2.is_zero(),
                true,
                || format!("{} terms", f2.num_terms()),
            ),
            Certificate::decide(
                format!("degree {du} in u, 1 ≤ {du} ≤ 4 (each characteristic curve traced by the generators once)"),
                (1..=4).contains(&du),
                true,
                || format!("degree {du} in u"),
            ),
        ]
    }
}

/// The cone of revolution `D(t) = (aᵀAa)·A − (Aa)(Aa)ᵀ` circumscribing the sphere
/// `|y − m|² = ρ` along its characteristic circle (module docs), for `m = M/w`,
/// `ρ = R/w²` (`M`, `R`, `w` polynomials; `R` is `r²·w²`, only it needs to be
/// rational).
pub fn circumscribed_cones(m: &[P; 3], rho: &P, w: &P) -> Mat4 {
    // sphere: w²|y|² − 2w M·y·y₀ + (|M|² − R)y₀² with homogeneous y = (y₀, y)
    let z = Poly::zero;
    let mm = (0..3).fold(z(), |acc, i| &acc + &(&m[i] * &m[i]));
    let w2 = w * w;
    let mut a: Mat4 = core::array::from_fn(|_| core::array::from_fn(|_| z()));
    a[0][0] = &mm - rho;
    for i in 0..3 {
        a[0][i + 1] = -&(w * &m[i]);
        a[i + 1][0] = a[0][i + 1].clone();
        a[i + 1][i + 1] = w2.clone();
    }
    // the plane Ṡ: (y − m)·ṁ + ρ̇/2 = 0 with m = M/w, ρ = R/w², times w³·y₀:
    // (w y − M y₀)·(M′w − M w′) + (R′w − 2R w′)/2·y₀ = 0
    let dm: [P; 3] =
        core::array::from_fn(|i| &(&m[i].derivative() * w) - &(&m[i] * &w.derivative()));
    // (y − M/w)·(M/w)′ + (R/w²)′/2 = 0, times w³:
    // (w y − M)·(M′w − M w′) + (R′w − 2R w′)/2 = 0  (homogeneous in y = (y₀, y))
    let half = Q::from_parts(1u8.into(), 2u8.into());
    let mut e: [P; 4] = core::array::from_fn(|_| z());
    let rterm =
        (&(&rho.derivative() * w) - &(rho * &w.derivative()).scale(&Q::from(2))).scale(&half);
    let mdm = (0..3).fold(z(), |acc, i| &acc + &(&m[i] * &dm[i]));
    e[0] = &rterm - &mdm;
    for i in 0..3 {
        e[i + 1] = w * &dm[i];
    }
    // vertex a = A⁻¹e (the pole of e); with A·a = det A·e the cone
    // (aᵀAa)A − (Aa)(Aa)ᵀ is det A·[(eᵀ adj A e)·A − det A·e eᵀ]
    let adj = super::adjugate(&a);
    let det = (0..4).fold(z(), |acc, j| &acc + &(&a[0][j] * &adj[j][0]));
    let eae = (0..4).fold(z(), |acc, i| {
        (0..4).fold(acc, |acc, j| &acc + &(&(&e[i] * &adj[i][j]) * &e[j]))
    });
    let d: Mat4 = core::array::from_fn(|i| {
        core::array::from_fn(|j| &(&eae * &a[i][j]) - &(&det * &(&e[i] * &e[j])))
    });
    // remove the common factor of the entries
    let g = d
        .iter()
        .flatten()
        .filter(|x| !x.is_zero())
        .fold(
            z(),
            |acc, x| if acc.is_zero() { x.clone() } else { acc.gcd(x) },
        );
    if g.degree().is_none_or(|k| k == 0) {
        return d;
    }
    let g = g.monic();
    d.map(|r| r.map(|x| x.div_exact(&g).unwrap_or(x)))
}

/// A canal surface as the envelope of its circumscribed cones of revolution (Thm 2.2,
/// Thm 2.3): the sphere family `|y − M/w|² = R/w²` (only `R = r²w²` rational).
#[derive(Debug, Clone, PartialEq)]
pub struct CanalViaCones {
    m: [P; 3],
    rho: P,
    w: P,
    envelope: ConeEnvelope,
}

impl CanalViaCones {
    /// The canal surface of centres `M/w` and squared radii `R/w²`.
    ///
    /// # Errors
    /// [`ConicSurfaceError::Degenerate`] if `w ≡ 0` or the cone family is degenerate
    /// (e.g. `ṁ ≡ 0`); as [`ConeFamily::envelope`] (no rational point over `Q`: the proof).
    pub fn new(m: [P; 3], rho: P, w: P) -> Result<Self, ConicSurfaceError> {
        if w.is_zero() {
            return Err(ConicSurfaceError::Degenerate(
                "the denominator w(t) is zero".into(),
            ));
        }
        let d = circumscribed_cones(&m, &rho, &w);
        if d.iter().all(|r| r.iter().all(|x| x.is_zero())) {
            return Err(ConicSurfaceError::Degenerate(
                "the characteristic plane is undefined (ṁ ≡ 0 and ρ̇ ≡ 0)".into(),
            ));
        }
        let fam = ConeFamily::new(d)?;
        let envelope = fam.envelope()?;
        Ok(CanalViaCones {
            m,
            rho,
            w,
            envelope,
        })
    }

    /// The envelope of the cones (the canal surface).
    pub fn envelope(&self) -> &ConeEnvelope {
        &self.envelope
    }
}

impl Certified for CanalViaCones {
    /// The envelope certificates, and for every point: on its sphere
    /// `|z − m z₀|² ≡ ρ z₀²` and on the characteristic plane `(z − m z₀)·ṁ + ρ̇ z₀/2 ≡ 0`
    /// (multiplied by the powers of `w` that make them polynomial).
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.envelope.certify();
        let (_, du) = self.envelope.degree();
        out.push(Certificate::decide(
            "degree 2 in u (each characteristic circle parametrized once)",
            du == 2,
            true,
            || format!("degree {du} in u"),
        ));
        let z = &self.envelope.point;
        let lift = |p: &P| MPoly::from_poly(p, 2, 0);
        let w = lift(&self.w);
        // y − m = (w z_i − M_i z₀)/(w z₀)
        let d: Vec<MPoly<Q>> = (0..3)
            .map(|i| &(&w * &z[i + 1]) - &(&lift(&self.m[i]) * &z[0]))
            .collect();
        let dd = d.iter().fold(MPoly::zero(2), |acc, x| &acc + &(x * x));
        let on_sphere = &dd - &(&lift(&self.rho) * &(&z[0] * &z[0]));
        out.push(Certificate::decide(
            "|w·z − M·z₀|² ≡ R·z₀² (every point lies on its sphere |y − m|² = r²)",
            on_sphere.is_zero(),
            true,
            || format!("{} terms", on_sphere.num_terms()),
        ));
        let dm: Vec<MPoly<Q>> = (0..3)
            .map(|i| {
                lift(&(&(&self.m[i].derivative() * &self.w) - &(&self.m[i] * &self.w.derivative())))
            })
            .collect();
        let rdot = lift(
            &(&(&self.rho.derivative() * &self.w)
                - &(&self.rho * &self.w.derivative()).scale(&Q::from(2))),
        );
        // (y − m)·ṁ + ρ̇/2 times 2w³z₀: 2(d·dm) + rdot·z₀
        let plane = &(0..3)
            .fold(MPoly::zero(2), |acc, i| &acc + &(&d[i] * &dm[i]))
            .scale(&Q::from(2))
            + &(&rdot * &z[0]);
        out.push(Certificate::decide(
            "(y − m)·ṁ + ρ̇/2 ≡ 0 (every point lies on the characteristic circle, Peternell (2.14))",
            plane.is_zero(),
            true,
            || format!("{} terms", plane.num_terms()),
        ));
        out
    }
}

/// The envelope of a cone family (Thm 2.1) as positive-weight patches over
/// `[t₀, t₁] × [u₀, u₁]`, with the family's identities and the envelope's certificates.
///
/// # Errors
/// As [`ConeFamily::new`], [`ConeFamily::envelope`] and [`ConeEnvelope::patch`].
pub fn cone_envelope_patches(
    c: Mat4,
    t: (Q, Q),
    u: (Q, Q),
) -> Result<(Vec<BezierPatch<Q>>, Vec<Certificate>), ConicSurfaceError> {
    let fam = ConeFamily::new(c)?;
    let env = fam.envelope()?;
    let (patches, weights) = super::positive_pieces(env.patch(t, u)?)?;
    let mut certs = fam.identities();
    certs.extend(env.certify());
    certs.push(weights);
    Ok((patches, certs))
}

/// The canal surface of centres `M/w` and squared radii `R/w²` as the envelope of its
/// circumscribed cones (Thm 2.3) — positive-weight patches with certificates.
///
/// # Errors
/// As [`CanalViaCones::new`] and [`ConeEnvelope::patch`].
pub fn canal_via_cones_patches(
    m: [P; 3],
    rho: P,
    w: P,
    t: (Q, Q),
    u: (Q, Q),
) -> Result<(Vec<BezierPatch<Q>>, Vec<Certificate>), ConicSurfaceError> {
    let canal = CanalViaCones::new(m, rho, w)?;
    let (patches, weights) = super::positive_pieces(canal.envelope().patch(t, u)?)?;
    let mut certs = canal.certify();
    certs.push(weights);
    Ok((patches, certs))
}

/// A conic surface of Thomsen type C as the envelope of quadratic cones (Peternell §2.2,
/// the remark on type-C conic surfaces; derivation in `docs/math/conic-surfaces.md`,
/// "Type-C conic surfaces as envelopes of cones").
///
/// For a family of type C at every parameter, `φ(s) = det(C + sĊ) = s²(a₂ + a₃s + a₄s²)`
/// has a double zero `s* = −a₃/(2a₄)` where the member `B = 2a₄C − a₃Ċ` of the pencil
/// has rank 2: `B = v·pᵀ + p·vᵀ` (a pair of bundles of planes), `p = Ċγ` the pole of
/// `g = γ ∩ γ̇` (`p` lies in `γ`) and `v` the vertex of the cone `D(t)` over `c(t)` that
/// touches the surface along `c(t)`. With `pᵢ ≢ 0`, `v = 2pᵢ·B·eᵢ − Bᵢᵢ·p` (then
/// `2pᵢ²·B = v·pᵀ + p·vᵀ`, certified). The cone is `D = Tᵀ·A·T`, `A = adj(C + γγᵀ)` (the
/// point form of `c`), `T = (γ·v)·I − v·γᵀ` (the projection from `v` onto `γ`); its
/// envelope ([`ConeFamily::envelope`]) is the conic surface: every point lies on its conic.
#[derive(Debug, Clone, PartialEq)]
pub struct TypeCEnvelope {
    family: ConicFamily,
    vertex: [P; 4],
    cones: Mat4,
    scaled_b: (P, Mat4),
    envelope: ConeEnvelope,
}

impl TypeCEnvelope {
    /// The cones of a type-C conic family (struct docs).
    ///
    /// # Errors
    /// [`ConicSurfaceError::Degenerate`] if the family is not of type C at every parameter
    /// (the named condition fails), or the vertex lies in the carrier plane; as
    /// [`ConeFamily::envelope`].
    pub fn new(family: &ConicFamily) -> Result<Self, ConicSurfaceError> {
        let c = family.matrix();
        let dc: Mat4 = core::array::from_fn(|i| core::array::from_fn(|j| c[i][j].derivative()));
        let (a2, a3, a4) = family.pencil_quadratic();
        if a4.is_zero() || !(&(&a3 * &a3) - &(&a2 * &a4).scale(&Q::from(4))).is_zero() {
            return Err(ConicSurfaceError::Degenerate(
                "not of Thomsen type C at every parameter: det(C + sĊ)/s² has no double zero identically (a₃² − 4a₂a₄ ≢ 0 or a₄ ≡ 0)".into(),
            ));
        }
        let b: Mat4 = core::array::from_fn(|i| {
            core::array::from_fn(|j| &(&c[i][j].scale(&Q::from(2)) * &a4) - &(&dc[i][j] * &a3))
        });
        if super::adjugate(&b).iter().flatten().any(|x| !x.is_zero()) {
            return Err(ConicSurfaceError::Degenerate(
                "type B, not C: the double member 2a₄C − a₃Ċ of the pencil has rank 3".into(),
            ));
        }
        let p = family.pole();
        let Some(i) = (0..4).find(|&i| !p[i].is_zero()) else {
            return Err(ConicSurfaceError::Degenerate(
                "the pole p = Ċγ vanishes".into(),
            ));
        };
        let v: [P; 4] =
            core::array::from_fn(|k| &(&b[k][i] * &p[i]).scale(&Q::from(2)) - &(&b[i][i] * &p[k]));
        let scale = (&p[i] * &p[i]).scale(&Q::from(2));
        let g = family.carrier_plane();
        let gv = (0..4).fold(Poly::zero(), |acc, k| &acc + &(&g[k] * &v[k]));
        if gv.is_zero() {
            return Err(ConicSurfaceError::Degenerate(
                "the vertex of the double member lies in the carrier plane (no cone over c(t))"
                    .into(),
            ));
        }
        let cg: Mat4 =
            core::array::from_fn(|r| core::array::from_fn(|s| &c[r][s] + &(&g[r] * &g[s])));
        let a = super::adjugate(&cg);
        // T = (γ·v)I − vγᵀ; D = Tᵀ A T
        let t: Mat4 = core::array::from_fn(|r| {
            core::array::from_fn(|s| {
                let d = if r == s { gv.clone() } else { Poly::zero() };
                &d - &(&v[r] * &g[s])
            })
        });
        let mut d: Mat4 = core::array::from_fn(|r| {
            core::array::from_fn(|s| {
                let mut acc = Poly::zero();
                for x in 0..4 {
                    for y in 0..4 {
                        if !a[x][y].is_zero() {
                            acc = &acc + &(&(&t[x][r] * &a[x][y]) * &t[y][s]);
                        }
                    }
                }
                acc
            })
        });
        let content = d
            .iter()
            .flatten()
            .filter(|x| !x.is_zero())
            .fold(Poly::zero(), |acc, x| {
                if acc.is_zero() {
                    x.clone()
                } else {
                    acc.gcd(x)
                }
            });
        if content.degree().is_some_and(|k| k > 0) {
            let m = content.monic();
            d = d.map(|r| r.map(|x| x.div_exact(&m).unwrap_or(x)));
        }
        let envelope = ConeFamily::new(d.clone())?.envelope()?;
        Ok(TypeCEnvelope {
            family: family.clone(),
            vertex: v,
            cones: d,
            scaled_b: (scale, b),
            envelope,
        })
    }

    /// The vertex curve `v(t)` of the cones.
    pub fn vertex(&self) -> &[P; 4] {
        &self.vertex
    }

    /// The cones `D(t)` (point quadrics, rank 3, kernel `v`).
    pub fn cones(&self) -> &Mat4 {
        &self.cones
    }

    /// The envelope of the cones.
    pub fn envelope(&self) -> &ConeEnvelope {
        &self.envelope
    }
}

impl Certified for TypeCEnvelope {
    /// `2pᵢ²·B ≡ v·pᵀ + p·vᵀ` (the double member is the pair of bundles `v`, `p`: type C),
    /// `D·v ≡ 0` (`v` is the vertex), the envelope's certificates (`zDzᵀ ≡ zḊzᵀ ≡ 0`), and
    /// every point on its conic: `γ·z ≡ 0`, `zᵀ·adj(C + γγᵀ)·z ≡ 0`.
    fn certify(&self) -> Vec<Certificate> {
        let p = self.family.pole();
        let v = &self.vertex;
        let (scale, b) = &self.scaled_b;
        let pair = (0..4).all(|i| {
            (0..4).all(|j| (&(&(&v[i] * &p[j]) + &(&p[i] * &v[j])) - &(scale * &b[i][j])).is_zero())
        });
        let dv = (0..4).all(|i| {
            (0..4)
                .fold(Poly::zero(), |acc, j| &acc + &(&self.cones[i][j] * &v[j]))
                .is_zero()
        });
        let z = &self.envelope.point;
        let g = self.family.carrier_plane();
        let on_plane = (0..4).fold(MPoly::zero(2), |acc, i| {
            &acc + &(&MPoly::from_poly(&g[i], 2, 0) * &z[i])
        });
        let c = self.family.matrix();
        let cg: Mat4 =
            core::array::from_fn(|r| core::array::from_fn(|s| &c[r][s] + &(&g[r] * &g[s])));
        let on_conic = super::form4(&super::adjugate(&cg), z, z);
        let mut out = vec![
            Certificate::decide(
                "2pᵢ²·(2a₄C − a₃Ċ) ≡ v·pᵀ + p·vᵀ (the double member of the pencil is the pair of bundles v, p: Thomsen type C)",
                pair,
                true,
                || "non-zero".into(),
            ),
            Certificate::decide(
                "D(t)·v(t) ≡ 0 (v is the vertex of the cone over c(t))",
                dv,
                true,
                || "non-zero".into(),
            ),
        ];
        out.extend(self.envelope.certify());
        out.push(Certificate::decide(
            "γ(t)·z(t, u) ≡ 0 and zᵀ·adj(C + γγᵀ)·z ≡ 0 (the envelope of the cones is the conic surface)",
            on_plane.is_zero() && on_conic.is_zero(),
            true,
            || format!("{} + {} terms", on_plane.num_terms(), on_conic.num_terms()),
        ));
        out
    }
}

/// A type-C conic surface as the envelope of its cones ([`TypeCEnvelope`]) as
/// positive-weight patches over `[t₀, t₁] × [u₀, u₁]`, with every certificate.
///
/// # Errors
/// As [`ConicFamily::new`], [`TypeCEnvelope::new`] and [`ConeEnvelope::patch`].
pub fn type_c_envelope_patches(
    c: Mat4,
    t: (Q, Q),
    u: (Q, Q),
) -> Result<(Vec<BezierPatch<Q>>, Vec<Certificate>), ConicSurfaceError> {
    let fam = ConicFamily::new(c)?;
    let env = TypeCEnvelope::new(&fam)?;
    let (patches, weights) = super::positive_pieces(env.envelope().patch(t, u)?)?;
    let mut certs = fam.identities();
    certs.extend(env.certify());
    certs.push(weights);
    Ok((patches, certs))
}
