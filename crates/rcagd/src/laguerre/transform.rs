//! Laguerre transformations (Peternell §3.2 (3.8)/(3.9), §3.4 (3.14)/(3.15), §4.3 Thm 4.2).
//!
//! In the cyclographic model `R⁴` a Laguerre transformation is a pe similarity
//! `x ↦ a + λ A x` with `AᵀEA = E`, `E = diag(1, 1, 1, −1)`, `λ ≠ 0` (3.8)/(3.9). It maps
//! cycles (points of `R⁴`) to cycles and γ-hyperplanes (oriented planes) to γ-hyperplanes,
//! preserving oriented contact. On hyperplane coordinates `ε = (ε₀, ε_v)` of
//! `ε₀ + ε_v·x = 0` it acts as the row-vector map
//! `ε_v' = ε_v B`, `ε₀' = ε₀ − ε_v B a`, `B = A⁻¹/λ = E Aᵀ E/λ`
//! ([`LaguerreMap::hyperplane_matrix`]).
//!
//! Special maps: the **dilatation** `r ↦ r + d` (3.4), `a = (0,0,0,d)`, which is the
//! offset at distance `d` (`e0 ↦ e0 − d`, docs/math/laguerre-pn.md#conventions); translations,
//! rotations and central similarities (`A = diag(R, 1)`); Lorentz boosts (rational
//! `cosh = (1+s²)/(1−s²)`, `sinh = 2s/(1−s²)`).
//!
//! In the isotropic model the dilatation is `y₃ ↦ y₃ − (d/2)(S + 1)` (Peternell (3.15)
//! **corrected**: the printed `+` is the offset by `−d`), and the translation of points
//! by `t` is `y₃ ↦ y₃ − t₁y₁ − t₂y₂ − (t₃/2)(S − 1)` (Peternell (3.14) with `a = −t`).

use super::models::{Cycle, OrientedPlane};
use super::LaguerreError;
use crate::certs::is_negligible;
use crate::error::{format_point, format_scalar};
use crate::Certified;
use rcagd_algebra::{Certificate, Scalar};

type M4<F> = [[F; 4]; 4];

fn eta<F: Scalar>(i: usize) -> F {
    if i == 3 {
        -F::one()
    } else {
        F::one()
    }
}

fn identity4<F: Scalar>() -> M4<F> {
    std::array::from_fn(|i| std::array::from_fn(|j| if i == j { F::one() } else { F::zero() }))
}

fn mat_mul<F: Scalar>(a: &M4<F>, b: &M4<F>) -> M4<F> {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..4).fold(F::zero(), |s, k| s + a[i][k].clone() * b[k][j].clone())
        })
    })
}

fn mat_vec<F: Scalar>(a: &M4<F>, x: &[F; 4]) -> [F; 4] {
    std::array::from_fn(|i| (0..4).fold(F::zero(), |s, k| s + a[i][k].clone() * x[k].clone()))
}

/// `AᵀEA − E` (zero iff `A` is pe-orthogonal).
fn pe_residual<F: Scalar>(a: &M4<F>) -> M4<F> {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let s = (0..4).fold(F::zero(), |s, k| {
                s + a[k][i].clone() * eta::<F>(k) * a[k][j].clone()
            });
            if i == j {
                s - eta::<F>(i)
            } else {
                s
            }
        })
    })
}

/// A Laguerre transformation as the pe similarity `x ↦ a + λ A x` of the cyclographic
/// model (Peternell (3.8)); `A` is pe-orthogonal (3.9).
#[derive(Debug, Clone, PartialEq)]
pub struct LaguerreMap<F> {
    shift: [F; 4],
    scale: F,
    matrix: M4<F>,
}

impl<F: Scalar> LaguerreMap<F> {
    /// The map `x ↦ a + λ A x`.
    ///
    /// # Errors
    /// [`LaguerreError::Degenerate`] for `λ = 0`; [`LaguerreError::NotOrthogonal`] unless
    /// `AᵀEA = E` (exactly for exact scalars).
    pub fn new(shift: [F; 4], scale: F, matrix: [[F; 4]; 4]) -> Result<Self, LaguerreError> {
        let mut all: Vec<F> = shift.to_vec();
        all.push(scale.clone());
        all.extend(matrix.iter().flatten().cloned());
        if !F::EXACT && all.iter().any(|x| !x.to_f64().is_finite()) {
            return Err(LaguerreError::NotFinite("Laguerre map".into()));
        }
        if scale.is_zero() {
            return Err(LaguerreError::Degenerate(
                "the scale factor λ of a pe similarity must be non-zero".into(),
            ));
        }
        let res = pe_residual(&matrix);
        let scale_mag = matrix
            .iter()
            .flatten()
            .map(|x| x.to_f64().abs())
            .fold(1.0, f64::max);
        if let Some(bad) = res
            .iter()
            .flatten()
            .find(|x| !is_negligible(*x, scale_mag * scale_mag))
        {
            return Err(LaguerreError::NotOrthogonal {
                kind: "pe-orthogonal (AᵀEA = E, E = diag(1,1,1,−1))".into(),
                residual: format_scalar(bad),
            });
        }
        Ok(LaguerreMap {
            shift,
            scale,
            matrix,
        })
    }

    /// The identity.
    pub fn identity() -> Self {
        LaguerreMap {
            shift: [F::zero(), F::zero(), F::zero(), F::zero()],
            scale: F::one(),
            matrix: identity4(),
        }
    }

    /// The dilatation `(m; r) ↦ (m; r + d)` (3.4): on every surface (as a set of oriented
    /// tangent planes) the one-sided offset `x + d n`; on planes `e0 ↦ e0 − d`
    /// (docs/math/laguerre-pn.md#conventions).
    pub fn dilatation(d: F) -> Self {
        LaguerreMap {
            shift: [F::zero(), F::zero(), F::zero(), d],
            ..Self::identity()
        }
    }

    /// The translation of points by `t` (cycles `(m; r) ↦ (m + t; r)`, planes
    /// `e0 ↦ e0 − n·t`).
    pub fn translation(t: [F; 3]) -> Self {
        let [a, b, c] = t;
        LaguerreMap {
            shift: [a, b, c, F::zero()],
            ..Self::identity()
        }
    }

    /// The rotation (or reflection) `x ↦ R x` for an orthogonal 3×3 matrix `R`
    /// (`A = diag(R, 1)`).
    ///
    /// # Errors
    /// [`LaguerreError::NotOrthogonal`] unless `RᵀR = I`.
    pub fn rotation(r: [[F; 3]; 3]) -> Result<Self, LaguerreError> {
        for i in 0..3 {
            for j in 0..3 {
                let s = (0..3).fold(F::zero(), |s, k| s + r[k][i].clone() * r[k][j].clone());
                let want = if i == j { F::one() } else { F::zero() };
                let d = s - want;
                if !is_negligible(&d, 1.0) {
                    return Err(LaguerreError::NotOrthogonal {
                        kind: "orthogonal (RᵀR = I)".into(),
                        residual: format_scalar(&d),
                    });
                }
            }
        }
        let mut m = identity4::<F>();
        for i in 0..3 {
            for j in 0..3 {
                m[i][j] = r[i][j].clone();
            }
        }
        Ok(LaguerreMap {
            matrix: m,
            ..Self::identity()
        })
    }

    /// The central similarity `x ↦ λ x` (centres and radii scaled by `λ`).
    ///
    /// # Errors
    /// [`LaguerreError::Degenerate`] for `λ = 0`.
    pub fn similarity(lambda: F) -> Result<Self, LaguerreError> {
        Self::new(
            [F::zero(), F::zero(), F::zero(), F::zero()],
            lambda,
            identity4(),
        )
    }

    /// The Lorentz boost in the `(x_axis, x₄)` plane of the cyclographic model with the
    /// rational parameter `s`: `cosh φ = (1 + s²)/(1 − s²)`, `sinh φ = 2s/(1 − s²)`
    /// (`axis` ∈ {0, 1, 2}). It maps cycles `(m; r)` to cycles with mixed centre and radius
    /// — a genuine Laguerre map that is no similarity of `R³`.
    ///
    /// # Errors
    /// [`LaguerreError::Degenerate`] for `s² = 1` or `axis > 2`.
    pub fn boost(axis: usize, s: F) -> Result<Self, LaguerreError> {
        if axis > 2 {
            return Err(LaguerreError::Degenerate(format!(
                "boost axis {axis}: must be 0, 1 or 2"
            )));
        }
        let den = F::one() - s.clone() * s.clone();
        let inv = den
            .inv()
            .ok_or_else(|| LaguerreError::Degenerate("a rational boost needs s² ≠ 1".into()))?;
        let ch = (F::one() + s.clone() * s.clone()) * inv.clone();
        let sh = F::from_i64(2) * s * inv;
        let mut m = identity4::<F>();
        m[axis][axis] = ch.clone();
        m[3][3] = ch;
        m[axis][3] = sh.clone();
        m[3][axis] = sh;
        Ok(LaguerreMap {
            matrix: m,
            ..Self::identity()
        })
    }

    /// The translation part `a`.
    pub fn shift(&self) -> &[F; 4] {
        &self.shift
    }

    /// The scale factor `λ`.
    pub fn scale(&self) -> &F {
        &self.scale
    }

    /// The pe-orthogonal matrix `A`.
    pub fn matrix(&self) -> &[[F; 4]; 4] {
        &self.matrix
    }

    /// `self ∘ other` (first `other`, then `self`).
    pub fn compose(&self, other: &LaguerreMap<F>) -> Self {
        // a₁ + λ₁A₁(a₂ + λ₂A₂x) = (a₁ + λ₁A₁a₂) + λ₁λ₂ A₁A₂ x
        let a1a2 = mat_vec(&self.matrix, &other.shift);
        LaguerreMap {
            shift: std::array::from_fn(|i| {
                self.shift[i].clone() + self.scale.clone() * a1a2[i].clone()
            }),
            scale: self.scale.clone() * other.scale.clone(),
            matrix: mat_mul(&self.matrix, &other.matrix),
        }
    }

    /// The inverse map `x ↦ −A⁻¹a/λ + (1/λ) A⁻¹ x`, `A⁻¹ = E Aᵀ E`.
    pub fn inverse(&self) -> Self {
        let ainv = self.inverse_matrix();
        let inv_l = F::one() / self.scale.clone();
        let b = mat_vec(&ainv, &self.shift);
        LaguerreMap {
            shift: std::array::from_fn(|i| -b[i].clone() * inv_l.clone()),
            scale: inv_l,
            matrix: ainv,
        }
    }

    /// `A⁻¹ = E Aᵀ E`.
    fn inverse_matrix(&self) -> M4<F> {
        std::array::from_fn(|i| {
            std::array::from_fn(|j| eta::<F>(i) * self.matrix[j][i].clone() * eta::<F>(j))
        })
    }

    /// The image of a point of the cyclographic model.
    pub fn apply_point(&self, x: &[F; 4]) -> [F; 4] {
        let ax = mat_vec(&self.matrix, x);
        std::array::from_fn(|i| self.shift[i].clone() + self.scale.clone() * ax[i].clone())
    }

    /// The image cycle.
    pub fn apply_cycle(&self, c: &Cycle<F>) -> Cycle<F> {
        Cycle::from_cyclographic(&self.apply_point(&c.to_cyclographic()))
    }

    /// The 5×5 matrix `H` of the action on hyperplane coordinates as a row vector,
    /// `ε' = ε H`: `H = [[1, 0], [−B a, B]]` with `B = A⁻¹/λ` (module docs).
    pub fn hyperplane_matrix(&self) -> [[F; 5]; 5] {
        let inv_l = F::one() / self.scale.clone();
        let b: M4<F> = {
            let ainv = self.inverse_matrix();
            std::array::from_fn(|i| std::array::from_fn(|j| ainv[i][j].clone() * inv_l.clone()))
        };
        let ba = mat_vec(&b, &self.shift);
        std::array::from_fn(|r| {
            std::array::from_fn(|c| match (r, c) {
                (0, 0) => F::one(),
                (0, _) => F::zero(),
                (_, 0) => -ba[r - 1].clone(),
                (_, _) => b[r - 1][c - 1].clone(),
            })
        })
    }

    /// The image oriented plane (its γ-hyperplane mapped by [`Self::hyperplane_matrix`],
    /// normalized by `ε₄`).
    ///
    /// # Errors
    /// [`LaguerreError::Degenerate`] only for numerically broken `f64` input.
    pub fn apply_plane(&self, e: &OrientedPlane<F>) -> Result<OrientedPlane<F>, LaguerreError> {
        let eps = e.to_gamma_hyperplane();
        let h = self.hyperplane_matrix();
        let img: [F; 5] = std::array::from_fn(|c| {
            (0..5).fold(F::zero(), |s, r| s + eps[r].clone() * h[r][c].clone())
        });
        OrientedPlane::from_gamma_hyperplane(&img)
    }

    /// The image of a point of the isotropic model: `Λ ∘ α ∘ Λ⁻¹` (an isotropic Möbius
    /// transformation, Peternell §3.4).
    ///
    /// # Errors
    /// [`LaguerreError::NoIsotropicImage`] if the image plane has normal `(0, 0, 1)`.
    pub fn apply_isotropic(&self, y: &[F; 3]) -> Result<[F; 3], LaguerreError> {
        self.apply_plane(&OrientedPlane::from_isotropic(y))?
            .to_isotropic()
    }
}

impl<F: Scalar> Certified for LaguerreMap<F> {
    /// `AᵀEA = E` (pe-orthogonality, (3.9)) and `λ ≠ 0`.
    fn certify(&self) -> Vec<Certificate> {
        let res = pe_residual(&self.matrix);
        let bad = res
            .iter()
            .flatten()
            .find(|x| !is_negligible(*x, 1.0))
            .cloned();
        vec![
            Certificate::decide(
                "AᵀEA − E = 0 (pe-orthogonal, Peternell (3.9))",
                bad.is_none(),
                F::EXACT,
                || match &bad {
                    Some(b) => format!("entry {}", format_scalar(b)),
                    None => String::new(),
                },
            ),
            Certificate::decide("λ ≠ 0", !self.scale.is_zero(), F::EXACT, || {
                "λ = 0".into()
            }),
        ]
    }
}

/// The dilatation in the isotropic model: `x ↦ x + d n` is
/// `y₃ ↦ y₃ − (d/2)(y₁² + y₂² + 1)` (Peternell (3.15) **corrected**,
/// docs/math/laguerre-pn.md#conventions: the printed `+ (d/2)(S+1)` is the offset by `−d`).
pub fn isotropic_dilatation<F: Scalar>(y: &[F; 3], d: &F) -> [F; 3] {
    let s = y[0].clone() * y[0].clone() + y[1].clone() * y[1].clone();
    [
        y[0].clone(),
        y[1].clone(),
        y[2].clone() - d.clone() * (s + F::one()) / F::from_i64(2),
    ]
}

/// The translation of points by `t` in the isotropic model:
/// `y₃ ↦ y₃ − t₁y₁ − t₂y₂ − (t₃/2)(y₁² + y₂² − 1)` (Peternell (3.14) with its `a = −t`: the
/// printed map `e0 ↦ e0 + a·n` moves points by `−a`).
pub fn isotropic_translation<F: Scalar>(y: &[F; 3], t: &[F; 3]) -> [F; 3] {
    let s = y[0].clone() * y[0].clone() + y[1].clone() * y[1].clone();
    [
        y[0].clone(),
        y[1].clone(),
        y[2].clone()
            - t[0].clone() * y[0].clone()
            - t[1].clone() * y[1].clone()
            - t[2].clone() * (s - F::one()) / F::from_i64(2),
    ]
}

impl<F: Scalar> core::fmt::Display for LaguerreMap<F> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let rows: Vec<String> = self.matrix.iter().map(|r| format_point(r)).collect();
        write!(
            f,
            "x ↦ {} + {}·[{}]·x",
            format_point(&self.shift),
            format_scalar(&self.scale),
            rows.join(", ")
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    fn sample_plane() -> OrientedPlane<Rational> {
        OrientedPlane::new(q(-2, 3), [q(2, 7), q(-3, 7), q(6, 7)]).expect("unit")
    }

    fn sample_maps() -> Vec<LaguerreMap<Rational>> {
        let rot = [
            [q(3, 5), q(-4, 5), q(0, 1)],
            [q(4, 5), q(3, 5), q(0, 1)],
            [q(0, 1), q(0, 1), q(1, 1)],
        ];
        vec![
            LaguerreMap::dilatation(q(3, 2)),
            LaguerreMap::translation([q(1, 1), q(-2, 1), q(1, 3)]),
            LaguerreMap::rotation(rot).expect("orthogonal"),
            LaguerreMap::similarity(q(5, 2)).expect("λ ≠ 0"),
            LaguerreMap::boost(2, q(1, 3)).expect("s² ≠ 1"),
            LaguerreMap::boost(0, q(-1, 2))
                .expect("s² ≠ 1")
                .compose(&LaguerreMap::translation([q(1, 2), q(0, 1), q(-1, 1)])),
        ]
    }

    #[test]
    fn maps_preserve_oriented_contact() {
        let e = sample_plane();
        let m = [q(1, 1), q(2, 1), q(-1, 2)];
        let r = -e.e0.clone() - (0..3).fold(q(0, 1), |s, i| s + e.n[i].clone() * m[i].clone());
        let c = Cycle::new(m, r).expect("finite");
        assert!(c.in_oriented_contact(&e));
        for map in sample_maps() {
            assert!(map.all_hold(), "{map}");
            let e2 = map.apply_plane(&e).expect("plane");
            let c2 = map.apply_cycle(&c);
            assert!(c2.in_oriented_contact(&e2), "{map}");
            // the inverse undoes the map
            let inv = map.inverse();
            assert_eq!(inv.apply_plane(&e2).expect("plane"), e);
            assert_eq!(inv.apply_cycle(&c2), c);
            assert_eq!(map.compose(&inv).apply_cycle(&c), c);
        }
    }

    #[test]
    fn dilatation_is_the_offset() {
        let e = sample_plane();
        let d = q(7, 4);
        let img = LaguerreMap::dilatation(d.clone())
            .apply_plane(&e)
            .expect("plane");
        // e0 ↦ e0 − d (docs/math/laguerre-pn.md, Errata E6): the plane is moved by +d along n
        assert_eq!(img, e.offset(&d));
        let x = [q(0, 1), q(0, 1), q(7, 9)]; // on e: −2/3 + 6/7·7/9 = 0
        assert!(e.contains(&x));
        let xd: [Rational; 3] = std::array::from_fn(|i| x[i].clone() + d.clone() * e.n[i].clone());
        assert!(img.contains(&xd));
        // isotropic model: corrected (3.15)
        let y = e.to_isotropic().expect("image");
        assert_eq!(
            img.to_isotropic().expect("image"),
            isotropic_dilatation(&y, &d)
        );
        assert_eq!(
            LaguerreMap::dilatation(d.clone())
                .apply_isotropic(&y)
                .expect("image"),
            isotropic_dilatation(&y, &d)
        );
        // the printed (3.15) (y3 + d/2 (S+1)) is the offset by −d
        let printed = isotropic_dilatation(&y, &(-d.clone()));
        assert_eq!(OrientedPlane::from_isotropic(&printed), e.offset(&(-d)));
    }

    #[test]
    fn translation_in_the_isotropic_model() {
        let e = sample_plane();
        let t = [q(1, 2), q(-3, 1), q(2, 1)];
        let y = e.to_isotropic().expect("image");
        let map = LaguerreMap::translation(t.clone());
        assert_eq!(
            map.apply_isotropic(&y).expect("image"),
            isotropic_translation(&y, &t)
        );
    }

    #[test]
    fn invalid_maps_are_errors() {
        let bad = [
            [q(1, 1), q(1, 1), q(0, 1), q(0, 1)],
            [q(0, 1), q(1, 1), q(0, 1), q(0, 1)],
            [q(0, 1), q(0, 1), q(1, 1), q(0, 1)],
            [q(0, 1), q(0, 1), q(0, 1), q(1, 1)],
        ];
        let z = [q(0, 1), q(0, 1), q(0, 1), q(0, 1)];
        assert!(matches!(
            LaguerreMap::new(z.clone(), q(1, 1), bad),
            Err(LaguerreError::NotOrthogonal { .. })
        ));
        assert!(LaguerreMap::new(z, q(0, 1), identity4()).is_err());
        assert!(LaguerreMap::<Rational>::boost(1, q(1, 1)).is_err());
        assert!(LaguerreMap::<Rational>::boost(3, q(1, 2)).is_err());
        let skew = [
            [q(1, 1), q(1, 1), q(0, 1)],
            [q(0, 1), q(1, 1), q(0, 1)],
            [q(0, 1), q(0, 1), q(1, 1)],
        ];
        assert!(LaguerreMap::rotation(skew).is_err());
    }

    #[test]
    fn f64_agrees() {
        let e = OrientedPlane::new(-2.0 / 3.0, [2.0 / 7.0, -3.0 / 7.0, 6.0 / 7.0]).expect("unit");
        let map = LaguerreMap::boost(2, 0.25).expect("ok");
        let img = map.apply_plane(&e).expect("plane");
        let exact = LaguerreMap::boost(2, q(1, 4))
            .expect("ok")
            .apply_plane(&sample_plane())
            .expect("plane");
        assert!((img.e0 - Scalar::to_f64(&exact.e0)).abs() < 1e-12);
    }
}
