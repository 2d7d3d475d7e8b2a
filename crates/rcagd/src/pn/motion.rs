//! Envelopes of surfaces moved by rational one-parameter families of Laguerre
//! transformations (Peternell, "Rational Parametrizations for Envelopes of Quadric
//! Families", §4.5 Cor. 4.1, Cor. 4.4, §4.6 Prop. 4.2 and (4.21);
//! docs/math/laguerre-pn.md#laguerre-families).
//!
//! **Families (4.21).** A rational family of Laguerre transformations acts on the
//! γ-hyperplanes `(ε₀, ε₁, ε₂, ε₃, ε₄)` of the cyclographic model (an oriented plane
//! `(e₀, n)` is `(e₀, n, 1)`) as the row-vector map
//! `ε ↦ ε·[[w, 0], [a, A]]`: `ε₀' = w ε₀ + Σ εᵢ aᵢ`, `ε'_j = Σ εᵢ A_ij` (`i, j = 1…4`),
//! with polynomials `w(u)`, `a(u)`, `A(u)` and `AᵀEA ≡ κE` (`E = diag(1, 1, 1, −1)`,
//! `κ ≢ 0`; `κ = w²` for pe-orthogonal `A/w`, i.e. Laguerre maps without scaling). The
//! matrix of [`crate::laguerre::LaguerreMap::hyperplane_matrix`] is the constant case. On
//! points `(1, m, r)` of `R⁴` (cycles) the family acts by the inverse,
//! `(m; r) ↦ (w EAᵀE (m, r) − EAᵀE a)/κ` (because `A E Aᵀ = κE`).
//!
//! **Prop. 4.2.** The tangent planes `E(t) = (P₀, P, s)/s` of a developable PN surface
//! ([`DevelopablePn`]) moved by the family give the two-parameter family
//! `G(t, u) = E(t)·[[w, 0], [a, A]](u)` of γ-hyperplanes with
//! `G₁² + G₂² + G₃² − G₄² = κ (|P|² − s²) ≡ 0`: the oriented planes `(G₀, G₁, G₂, G₃)/G₄`
//! have a rational unit normal, and their envelope (if it is not developable) is a PN
//! surface ([`super::support::from_plane_field`]). It touches every moved developable
//! `Δ_u`: its point lies on `G`, `G_t` (the ruling of `Δ_u`) and `G_u`.
//!
//! **Cor. 4.1.** A ruled surface `φ(t, s) = l(t) + s g(t)` of `R⁴` (points are cycles)
//! has as cyclographic image the envelope of the cones of revolution spanned by the cycles
//! `l(t)` and `l(t) + g(t)` (Theorem 4.5): a PN surface, if `φ` is not developable
//! (`l̇, g, ġ` independent) and the image is real.
//!
//! **Cor. 4.4.** A fixed cone of revolution `Δ₀`, spanned by two cycles `c₁, c₂`, moved by
//! a rational family of Laguerre maps: the cones `Δ(t)` are spanned by the image cycle
//! curves, and their envelope is a PN surface by Theorem 4.5.

use super::developable::DevelopablePn;
use super::poly::{compose, det3, dot3, identity_cert, int, var, RatFn};
use super::ruled::{ConeFamilyEnvelope, CycleFamily};
use super::support::from_plane_field_with;
use super::surface::PnSurface;
use super::PnError;
use crate::laguerre::{Cycle, LaguerreError};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};

/// `E = diag(1, 1, 1, −1)`.
fn eta<F: Scalar>(i: usize) -> F {
    if i == 3 {
        -F::one()
    } else {
        F::one()
    }
}

/// `AᵀEA`.
fn ate<F: Scalar>(a: &[[MPoly<F>; 4]; 4]) -> [[MPoly<F>; 4]; 4] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..4).fold(MPoly::zero(2), |s, k| {
                &s + &(&a[k][i] * &a[k][j]).scale(&eta::<F>(k))
            })
        })
    })
}

/// The 16 certificates `(AᵀEA)[i][j] ≡ κ E[i][j]`.
fn pe_certificates<F: Scalar>(a: &[[MPoly<F>; 4]; 4], kappa: &MPoly<F>) -> Vec<Certificate> {
    let m = ate(a);
    m.iter()
        .enumerate()
        .flat_map(|(i, row)| {
            row.iter().enumerate().map(move |(j, mij)| {
                let want = if i == j {
                    kappa.scale(&eta::<F>(i))
                } else {
                    MPoly::zero(2)
                };
                identity_cert(
                    &format!(
                        "Laguerre family: (A(u)ᵀ E A(u))[{}][{}] ≡ κ(u) E[{}][{}] (pe-orthogonal up to a factor)",
                        i + 1,
                        j + 1,
                        i + 1,
                        j + 1
                    ),
                    mij,
                    &want,
                )
            })
        })
        .collect()
}

fn only_var0<F: Scalar>(p: &MPoly<F>) -> bool {
    p.terms().all(|(e, _)| e.iter().skip(1).all(|&k| k == 0))
}

/// A rational one-parameter family of Laguerre transformations in the form (4.21):
/// polynomials `w(u)`, `a(u) = (a₁, …, a₄)`, `A(u)` (4×4) in the variable 0 with
/// `A(u)ᵀ E A(u) ≡ κ(u) E`, acting on γ-hyperplanes by `ε ↦ ε·[[w, 0], [a, A]]` (module
/// docs).
#[derive(Debug, Clone)]
pub struct LaguerreFamily<F> {
    weight: MPoly<F>,
    shift: [MPoly<F>; 4],
    matrix: [[MPoly<F>; 4]; 4],
    kappa: MPoly<F>,
}

impl<F: Scalar> LaguerreFamily<F> {
    /// The family `[[w, 0], [a, A]]` (rows of `A`: `A[i][j]` multiplies `εᵢ₊₁` into
    /// `ε'ⱼ₊₁`).
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] if a polynomial involves another variable than 0 or
    /// `w ≡ 0`; [`PnError::Laguerre`] ([`LaguerreError::NotOrthogonal`]) unless
    /// `AᵀEA ≡ κE` for a polynomial `κ ≢ 0` (then it is no Laguerre map).
    pub fn new(
        weight: MPoly<F>,
        shift: [MPoly<F>; 4],
        matrix: [[MPoly<F>; 4]; 4],
    ) -> Result<Self, PnError> {
        if weight.is_zero() {
            return Err(PnError::InvalidInput(
                "a Laguerre family needs a non-zero weight w(u)".into(),
            ));
        }
        if !std::iter::once(&weight)
            .chain(shift.iter())
            .chain(matrix.iter().flatten())
            .all(only_var0)
        {
            return Err(PnError::InvalidInput(
                "a Laguerre family must depend on its parameter only (variable 0)".into(),
            ));
        }
        let kappa = ate(&matrix)[0][0].clone();
        if kappa.is_zero() {
            return Err(PnError::Laguerre(LaguerreError::NotOrthogonal {
                kind: "pe-orthogonal up to a factor (AᵀEA ≡ κE, κ ≢ 0)".into(),
                residual: "κ = (AᵀEA)₁₁ ≡ 0".into(),
            }));
        }
        if let Some(bad) = pe_certificates(&matrix, &kappa)
            .into_iter()
            .find(|c| !c.holds)
        {
            return Err(PnError::Laguerre(LaguerreError::NotOrthogonal {
                kind: "pe-orthogonal up to a factor (AᵀEA ≡ κE, E = diag(1,1,1,−1))".into(),
                residual: format!("{}: {}", bad.property, bad.residual.unwrap_or_default()),
            }));
        }
        Ok(LaguerreFamily {
            weight,
            shift,
            matrix,
            kappa,
        })
    }

    /// The rational motions `x ↦ R(u) x + b(u)` with `R(u)` the rotation about the
    /// `x₃`-axis by the angle `2 atan u` ([`Self::screw_about`] with axis 2).
    ///
    /// # Errors
    /// As [`Self::new`] (not expected).
    pub fn screw(b: [MPoly<F>; 3]) -> Result<Self, PnError> {
        Self::screw_about(2, b)
    }

    /// The rational motions `x ↦ R(u) x + b(u)`: `R(u)` the rotation about the axis
    /// `x_k` (`k = 0, 1, 2`) by the angle `2 atan u` (Cayley: `cos = (1 − u²)/(1 + u²)`,
    /// `sin = 2u/(1 + u²)`, turning `x_i` towards `x_j`, `(i, j) = (k + 1, k + 2) mod 3`),
    /// `b` polynomials in `u`. An oriented plane `e₀ + n·x = 0` goes to `n' = R n`,
    /// `e₀' = e₀ − n'·b`; in the form (4.21): `w = 1 + u²`, `A = diag(C, w)` with `C` the
    /// rotation (times `w`) acting on row vectors, `a = −(C b, 0)`
    /// (docs/math/laguerre-pn.md#laguerre-families). A translation `b` along the axis
    /// makes a screw motion (the §4.6 example).
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] for `k > 2`; as [`Self::new`].
    pub fn screw_about(axis: usize, b: [MPoly<F>; 3]) -> Result<Self, PnError> {
        if axis > 2 {
            return Err(PnError::InvalidInput(format!(
                "the rotation axis must be 0, 1 or 2 (got {axis})"
            )));
        }
        let u = var::<F>(0);
        let uu = &u * &u;
        let w = &uu + &int(1);
        let c = &int(1) - &uu;
        let s = u.scale(&F::from_i64(2));
        let z = MPoly::zero(2);
        let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
        // rot[r][col]: n'_col = Σ_r n_r rot[r][col]
        let mut rot: [[MPoly<F>; 3]; 3] =
            std::array::from_fn(|_| std::array::from_fn(|_| z.clone()));
        rot[axis][axis] = w.clone();
        rot[i][i] = c.clone();
        rot[j][j] = c;
        rot[i][j] = s.clone();
        rot[j][i] = -s;
        // e₀' w = w e₀ − (n·rot)·b: a_r = −Σ_col rot[r][col] b_col
        let sh: [MPoly<F>; 3] = std::array::from_fn(|r| {
            -(0..3).fold(MPoly::zero(2), |acc, col| &acc + &(&rot[r][col] * &b[col]))
        });
        let shift = [sh[0].clone(), sh[1].clone(), sh[2].clone(), z.clone()];
        let matrix: [[MPoly<F>; 4]; 4] = std::array::from_fn(|r| {
            std::array::from_fn(|col| match (r, col) {
                (3, 3) => w.clone(),
                (3, _) | (_, 3) => z.clone(),
                _ => rot[r][col].clone(),
            })
        });
        Self::new(w, shift, matrix)
    }

    /// `w(u)`.
    pub fn weight(&self) -> &MPoly<F> {
        &self.weight
    }

    /// `a(u)`.
    pub fn shift(&self) -> &[MPoly<F>; 4] {
        &self.shift
    }

    /// `A(u)`.
    pub fn matrix(&self) -> &[[MPoly<F>; 4]; 4] {
        &self.matrix
    }

    /// `κ(u)` with `AᵀEA ≡ κE`.
    pub fn kappa(&self) -> &MPoly<F> {
        &self.kappa
    }

    /// The certificates `AᵀEA ≡ κE` (all 16 entries; `κ ≡ w²` is additionally certified
    /// when `A/w` is pe-orthogonal, i.e. the family has no scaling part).
    pub fn certificates(&self) -> Vec<Certificate> {
        pe_certificates(&self.matrix, &self.kappa)
    }

    /// `true` if `κ ≡ w²` (then `A/w` is pe-orthogonal: `(A/w)ᵀ E (A/w) ≡ E`).
    pub fn is_pe_orthogonal(&self) -> bool {
        identity_cert("κ ≡ w²", &self.kappa, &(&self.weight * &self.weight)).holds
    }

    /// The family with its parameter moved to the variable `k` (0 or 1).
    fn in_var(&self, k: usize) -> Self {
        let qs = if k == 1 {
            [var::<F>(1), var::<F>(0)]
        } else {
            [var::<F>(0), var::<F>(1)]
        };
        let c = |p: &MPoly<F>| compose(p, &qs);
        LaguerreFamily {
            weight: c(&self.weight),
            shift: std::array::from_fn(|i| c(&self.shift[i])),
            matrix: std::array::from_fn(|i| std::array::from_fn(|j| c(&self.matrix[i][j]))),
            kappa: c(&self.kappa),
        }
    }

    /// `ε·[[w, 0], [a, A]]` for a γ-hyperplane row vector `ε` (polynomials).
    fn apply_hyperplane(&self, e: &[MPoly<F>; 5]) -> [MPoly<F>; 5] {
        let g0 = (0..4).fold(&e[0] * &self.weight, |s, i| {
            &s + &(&e[i + 1] * &self.shift[i])
        });
        let gv: [MPoly<F>; 4] = std::array::from_fn(|j| {
            (0..4).fold(MPoly::zero(2), |s, i| {
                &s + &(&e[i + 1] * &self.matrix[i][j])
            })
        });
        [
            g0,
            gv[0].clone(),
            gv[1].clone(),
            gv[2].clone(),
            gv[3].clone(),
        ]
    }

    /// The image cycle curve `t ↦ α(t)(c)` of a fixed cycle `c` (the family's parameter
    /// as `t`): `(m; r) ↦ (w EAᵀE (m, r) − EAᵀE a)/κ`.
    ///
    /// # Errors
    /// As [`CycleFamily::new`] (not expected: `κ ≢ 0`).
    pub fn cycle_curve(&self, c: &Cycle<F>) -> Result<CycleFamily<F>, PnError> {
        let x = [
            c.center[0].clone(),
            c.center[1].clone(),
            c.center[2].clone(),
            c.radius.clone(),
        ];
        // y = E Aᵀ E (w x − a): yᵢ = ηᵢ Σ_k A[k][i] η_k (w x_k − a_k)
        let y: [MPoly<F>; 4] = std::array::from_fn(|i| {
            (0..4)
                .fold(MPoly::zero(2), |s, k| {
                    let z = &self.weight.scale(&x[k]) - &self.shift[k];
                    &s + &(&self.matrix[k][i] * &z).scale(&eta::<F>(k))
                })
                .scale(&eta::<F>(i))
        });
        CycleFamily::new(
            [y[0].clone(), y[1].clone(), y[2].clone()],
            y[3].clone(),
            self.kappa.clone(),
        )
    }

    /// The certificate that a cycle curve is the image of the fixed cycle `c`: the
    /// point `(κ, Y)` of the curve satisfies `[[w, 0], [a, A]]·(κ, Y)ᵀ ≡ wκ·(1, m, r)ᵀ`
    /// (a γ-hyperplane `ε` through `c` is mapped to one through the image cycle).
    pub fn cycle_image_certificates(&self, c: &Cycle<F>, img: &CycleFamily<F>) -> Vec<Certificate> {
        let (m, r, den) = img.parts();
        let y = [m[0].clone(), m[1].clone(), m[2].clone(), r.clone()];
        let x = [
            c.center[0].clone(),
            c.center[1].clone(),
            c.center[2].clone(),
            c.radius.clone(),
        ];
        let wk = &self.weight * den;
        (0..4)
            .map(|i| {
                let lhs = (0..4).fold(&self.shift[i] * den, |s, j| &s + &(&self.matrix[i][j] * &y[j]));
                identity_cert(
                    &format!(
                        "Laguerre family: the cycle curve is the image of the fixed cycle (coordinate {})",
                        i + 1
                    ),
                    &lhs,
                    &wk.scale(&x[i]),
                )
            })
            .collect()
    }
}

/// The envelope of a developable PN surface moved by a rational family of Laguerre
/// transformations (Peternell Prop. 4.2, (4.21); module docs), in the parameters
/// `(t, u)`: `t` of the developable, `u` of the family.
#[derive(Debug, Clone)]
pub struct DevelopableMotionEnvelope<F> {
    family: LaguerreFamily<F>,
    moved: [MPoly<F>; 5],
    surface: PnSurface<F>,
}

impl<F: Scalar> DevelopableMotionEnvelope<F> {
    /// The envelope of `α(u)(Δ)` for the developable `Δ` and the family `α` (whose
    /// parameter, the variable 0 of `family`, becomes the surface parameter `u`).
    ///
    /// # Errors
    /// [`PnError::Developable`] if the moved planes `G(t, u)` form only a one-parameter
    /// family (e.g. a constant family, or motions that map `Δ` into itself): then the
    /// envelope is developable and Prop. 4.2 does not apply; also if the planes envelope
    /// only a curve or a point (`det(x_t, x_u, n) ≡ 0`).
    pub fn new(dev: &DevelopablePn<F>, family: &LaguerreFamily<F>) -> Result<Self, PnError> {
        let pl = dev.planes();
        let e = [
            pl[0].clone(),
            pl[1].clone(),
            pl[2].clone(),
            pl[3].clone(),
            dev.plane_norm().clone(),
        ];
        let fam = family.in_var(1);
        let g = fam.apply_hyperplane(&e);
        let h = RatFn::new(g[0].clone(), g[4].clone())?;
        let normal = [g[4].clone(), g[1].clone(), g[2].clone(), g[3].clone()];
        // the raw envelope point shares the factor w(u)⁴ s(t)³ (screw families; sympy:
        // scripts/checks/prop_4_2_common_factor.py, docs/math/laguerre-pn.md#prop-4-2-common-factor):
        // name w and s (and κ) so that the f64 path cancels them as the exact gcd does
        let factors = [fam.weight.clone(), e[4].clone(), fam.kappa.clone()];
        let surface = from_plane_field_with(&h, &normal, &factors)
            .map_err(|err| match err {
                PnError::Developable(m) => PnError::Developable(format!(
                    "the moved planes G(t, u) form a one-parameter family ({m}): the envelope is developable (Prop. 4.2 needs a non-developable envelope)"
                )),
                other => other,
            })?
            .named("envelope of a developable PN surface under a Laguerre family (Prop. 4.2)");
        if surface.point_map_degenerate() {
            return Err(PnError::Developable(
                "the envelope of the moved developables is a curve or a point (det(x_t, x_u, n) ≡ 0), not a surface (e.g. a translation that slides the developable along one of its own rulings' directions through a fixed point)".into(),
            ));
        }
        Ok(DevelopableMotionEnvelope {
            family: family.clone(),
            moved: g,
            surface,
        })
    }

    /// The PN surface in `(t, u)`.
    pub fn surface(&self) -> &PnSurface<F> {
        &self.surface
    }

    /// The family.
    pub fn family(&self) -> &LaguerreFamily<F> {
        &self.family
    }

    /// The moved γ-hyperplanes `G(t, u) = E(t)·[[w, 0], [a, A]](u)` (4.21).
    pub fn moved_planes(&self) -> &[MPoly<F>; 5] {
        &self.moved
    }

    /// The contact certificates: the point lies on `G` (its tangent plane), on `G_t` (so
    /// on the ruling `G ∩ G_t` of the moved developable `α(u)(Δ)`, which it touches
    /// there along the ruling's common tangent plane `G`), on `G_u` (the envelope
    /// condition); the unit normal is the normal of `G` (`N_k G₄ ≡ N₀ G_k`), and
    /// `G₁² + G₂² + G₃² ≡ G₄²`.
    pub fn contact_certificates(&self) -> Vec<Certificate> {
        let x = self.surface.point_polys();
        let n = self.surface.normal_polys();
        let g = &self.moved;
        let on = |p: [MPoly<F>; 4], what: &str| {
            identity_cert(what, &(&p[0] * &x[0]), &-dot3(&p[1..], &x[1..]))
        };
        let gp = [g[0].clone(), g[1].clone(), g[2].clone(), g[3].clone()];
        let gt: [MPoly<F>; 4] = std::array::from_fn(|i| gp[i].partial(0));
        let gu: [MPoly<F>; 4] = std::array::from_fn(|i| gp[i].partial(1));
        let mut out = vec![
            on(gp, "Prop. 4.2: x on the moved plane G(t, u): G₀W + G·X ≡ 0"),
            on(
                gt,
                "Prop. 4.2: x on the ruling G ∩ G_t of the moved developable α(u)(Δ): ∂_tG₀W + ∂_tG·X ≡ 0",
            ),
            on(gu, "Prop. 4.2: envelope condition ∂_uG₀W + ∂_uG·X ≡ 0"),
            identity_cert(
                "Prop. 4.2: the moved planes are γ-hyperplanes: G₁² + G₂² + G₃² ≡ G₄²",
                &dot3(&g[1..4], &g[1..4]),
                &(&g[4] * &g[4]),
            ),
        ];
        for k in 1..4 {
            out.push(identity_cert(
                &format!("Prop. 4.2: the unit normal is the normal of G (N{k} G₄ ≡ N₀ G{k})"),
                &(&n[k] * &g[4]),
                &(&n[0] * &g[k]),
            ));
        }
        out
    }
}

impl<F: Scalar> Certified for DevelopableMotionEnvelope<F> {
    /// The family (`AᵀEA ≡ κE`), the PN identities, the contact with every moved
    /// developable.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.family.certificates();
        out.extend(self.surface.certify());
        out.extend(self.contact_certificates());
        out
    }
}

/// Cor. 4.1: the cyclographic image of the ruled surface `φ(t, s) = l(t) + s g(t)` of
/// `R⁴` (`l`, `g` rational in `t`; a point `(m, r)` of `R⁴` is the cycle `(m; r)`): the
/// envelope of the cones of revolution spanned by the cycles `l(t)` and `l(t) + g(t)`
/// (Theorem 4.5), a PN surface. Its certificates include the contact of every tangent
/// plane with both cycle curves, hence (by linearity of `e₀ + n·m + r`) with every cycle
/// `l + s g` of the ruling.
///
/// # Errors
/// [`PnError::Developable`] if `φ` is developable (`l̇, g, ġ` linearly dependent) or the
/// envelope is; [`PnError::IsotropicCycles`] for isotropic rulings (`⟨g, g⟩ ≡ 0`);
/// [`PnError::NoRationalPoint`] if `⟨g, g⟩ = |g₁₋₃|² − g₄²` is no sum of two squares over
/// `Q(t)` (in particular where the rulings are timelike: no real image).
pub fn ruled_surface_image<F: Scalar>(
    l: [RatFn<F>; 4],
    g: [RatFn<F>; 4],
) -> Result<ConeFamilyEnvelope<F>, PnError> {
    // the rank of the rows (l̇, g, ġ) is unchanged by scaling column i by
    // dlᵢ² dgᵢ² ≠ 0: the entries become polynomials
    let deriv = |f: &RatFn<F>| -> MPoly<F> {
        &(&f.num.partial(0) * &f.den) - &(&f.num * &f.den.partial(0))
    };
    let ltw: [MPoly<F>; 4] = std::array::from_fn(|i| &deriv(&l[i]) * &(&g[i].den * &g[i].den));
    let ggw: [MPoly<F>; 4] =
        std::array::from_fn(|i| &(&g[i].num * &g[i].den) * &(&l[i].den * &l[i].den));
    let gtw: [MPoly<F>; 4] = std::array::from_fn(|i| &deriv(&g[i]) * &(&l[i].den * &l[i].den));
    let minors_zero = (0..4).all(|skip| {
        let idx: Vec<usize> = (0..4).filter(|&k| k != skip).collect();
        let pick = |v: &[MPoly<F>; 4]| [v[idx[0]].clone(), v[idx[1]].clone(), v[idx[2]].clone()];
        det3([&pick(&ltw), &pick(&ggw), &pick(&gtw)]).is_zero()
    });
    if minors_zero {
        return Err(PnError::Developable(
            "the ruled surface l(t) + s g(t) of R⁴ is developable (l̇, g, ġ linearly dependent): Cor. 4.1 needs a non-developable ruled surface".into(),
        ));
    }
    let c1 = CycleFamily::from_rational([l[0].clone(), l[1].clone(), l[2].clone()], l[3].clone())?;
    let sum: [RatFn<F>; 4] = std::array::from_fn(|i| l[i].add(&g[i]));
    let c2 = CycleFamily::from_rational(
        [sum[0].clone(), sum[1].clone(), sum[2].clone()],
        sum[3].clone(),
    )?;
    ConeFamilyEnvelope::new(c1, c2, None)
}

/// Cor. 4.4: the envelope of the cone of revolution `Δ₀` spanned by the cycles `c₁, c₂`,
/// moved by the rational family of Laguerre maps `α(t)` (the family's parameter becomes
/// `t`): the envelope of the cones spanned by `α(t)(c₁)` and `α(t)(c₂)` (Theorem 4.5), a
/// PN surface. Returns the envelope and the image cycle curves.
///
/// # Errors
/// [`PnError::InvalidInput`] if `c₁ = c₂`; [`PnError::IsotropicCycles`] if the cycles
/// touch (`|m₁ − m₂|² = (r₁ − r₂)²`: no cone); [`PnError::NoRationalPoint`] if
/// `|m₁ − m₂|² − (r₁ − r₂)²` (a constant, preserved up to `κ`) needs a square root that is
/// not available; [`PnError::Developable`] if the envelope is developable (e.g. a constant
/// family).
pub fn moved_cone_envelope<F: Scalar>(
    c1: &Cycle<F>,
    c2: &Cycle<F>,
    family: &LaguerreFamily<F>,
) -> Result<ConeFamilyEnvelope<F>, PnError> {
    if c1 == c2 {
        return Err(PnError::InvalidInput(
            "the two cycles of a cone of revolution must differ".into(),
        ));
    }
    let f1 = family.cycle_curve(c1)?;
    let f2 = family.cycle_curve(c2)?;
    ConeFamilyEnvelope::new(f1, f2, None)
}
