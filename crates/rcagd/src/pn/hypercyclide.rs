//! Regular quadrics as PN surfaces (Peternell, Theorem 4.6) and hypercyclides, the
//! cyclographic images of two-dimensional quadrics of `R⁴` (Peternell, Prop. 4.3, §4.7);
//! derivations in docs/math/hypercyclides.md.
//!
//! **The pencil.** A regular quadric `φ` of `R³ = {x₄ = 0} ⊂ R⁴` and the absolute quadric
//! `Ω` (`x₀ = 0, x₁² + x₂² + x₃² − x₄² = 0`), both as sets of tangent hyperplanes
//! `u = (u₀, …, u₄)` of `P⁴`, span the pencil `φ* + μΩ*` with `Ω* = diag(0, 1, 1, 1, −1)`.
//! Every member has the same common tangent γ-hyperplanes, so the same cyclographic image.
//! For the three non-ruled regular quadrics one singular member `ψ* = φ* + μ₀Ω*` is a
//! ruled quadric `ψ` of a hyperplane `x_k = 0` (docs/math/hypercyclides.md#pencil):
//!
//! | `φ` | `μ₀` | `ψ` |
//! |---|---|---|
//! | `x₁²/a² + x₂²/b² + x₃²/c² = 1`, `a > b > c` | `−b²` | `x₁²/(a²−b²) − x₃²/(b²−c²) + x₄²/b² = 1`, `x₂ = 0` |
//! | `x₁²/a² − x₂²/b² − x₃²/c² = 1`, `b > c` | `b²` | `x₁²/(a²+b²) + x₃²/(b²−c²) − x₄²/b² = 1`, `x₂ = 0` |
//! | `x₁²/a² + x₂²/b² = 2x₃`, `a > b` | `−a²` | `−x₂²/(a²−b²) + x₄²/a² = 2x₃ − a²`, `x₁ = 0` |
//!
//! (Peternell prints `2x₃ − a` for the paraboloid; the inverse of the restricted matrix of
//! `ψ*` gives `2x₃ − a²`, docs/math/hypercyclides.md#paraboloid-correction.)
//!
//! **Rulings → cones.** The rulings `g(T) = P(T) + λD(T)` of one family of `ψ` are lines
//! of `R⁴` through the points `P(T)` of the focal conic `ψ ∩ {x₄ = 0}`; their cyclographic
//! images are the cones of revolution spanned by the cycles `c₁ = (P; 0)` and
//! `c₂ = (P + D)`, and `η(φ) = η(ψ)` is their envelope (Theorem 4.5,
//! [`ConeFamilyEnvelope`]). The family is defined over `Q` iff the square root named in
//! [`RegularQuadric`] is rational. A ruling is real (hyperbolic) where
//! `N(T) = ⟨D, D⟩ = D₁² + D₂² + D₃² − D₄² ≥ 0`; `N` changes sign at the parabolic
//! rulings (the normals at the umbilics). A double cover `T = T(S)` branched at two of
//! them (a rational conic `w² = κ q(T)`, `q` a rational quadratic factor of `N` or a
//! product of two rational linear ones) makes `N(T(S))` a square times a positive
//! polynomial; where that is a sum of two squares over `Q(S)` Theorem 4.5 gives a PN
//! parametrization. The covers are searched through the rational points `(T₀, q(T₀))`
//! (`κ = q(T₀)`), and the sum-of-two-squares question is decided exactly by the algebra
//! layer. No cover found → [`PnError::NoRationalPoint`] naming what failed.
//!
//! **Hypercyclides.** A rational pe similarity `L(y) = s·A·y + t` of `R⁴`
//! (`AᵀEA = E`, `E = diag(1, 1, 1, −1)`) maps `Ω` to itself, `φ` to a quadric `φ′` of the
//! Euclidean hyperplane `π = L({x₄ = 0})` (tilted when `A` is a boost) and the pencil to
//! the pencil of `φ′`; so `η(φ′)` is the envelope of the cones of the mapped cycle
//! families. [`Hypercyclide`] certifies the defining properties directly: every tangent
//! plane `(e₀, n)` gives the γ-hyperplane `(e₀, n, 1)`, which is tangent to `φ′`
//! (`Γᵀφ′*Γ ≡ 0`), its contact point `y = φ′*Γ` lies on `φ′`, and the surface point is the
//! contact point `x = m + r n` of the plane with the cycle `η(y) = (m; r)`.

use super::poly::{dot3, identity_cert, scalar_sqrt, zero_cert, RatFn};
use super::ruled::{ConeFamilyEnvelope, CycleFamily};
use super::surface::PnSurface;
use super::two_sheet::TwoSheetPn;
use super::PnError;
use crate::error::format_scalar;
use crate::Certified;
use rcagd_algebra::factor::factor_rational;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::sum_of_squares::{sum_of_two_squares, SumOfSquares};
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};

type Q = Rational;
type P = Poly<Rational>;

/// A regular, non-ruled quadric of `R³` in its principal frame (exact data).
#[derive(Debug, Clone, PartialEq)]
pub enum RegularQuadric {
    /// `x²/a² + y²/b² + z²/c² = 1` with `a > b > c > 0`; the rulings of `ψ` need
    /// `√((a² − b²)(b² − c²))` rational.
    Ellipsoid {
        /// Largest semi-axis.
        a: Q,
        /// Middle semi-axis.
        b: Q,
        /// Smallest semi-axis.
        c: Q,
    },
    /// `x²/a² − y²/b² − z²/c² = 1` with `a > 0`, `b > c > 0`; needs
    /// `√((a² + b²)(b² − c²))` rational.
    TwoSheetHyperboloid {
        /// Real semi-axis.
        a: Q,
        /// Larger imaginary semi-axis.
        b: Q,
        /// Smaller imaginary semi-axis.
        c: Q,
    },
    /// `x²/a² + y²/b² = 2z` with `a > b > 0`; needs `√(a² − b²)` rational.
    EllipticParaboloid {
        /// Larger parameter.
        a: Q,
        /// Smaller parameter.
        b: Q,
    },
}

/// The ruled member `ψ` of the pencil, its focal conic and one family of its rulings.
#[derive(Debug, Clone)]
pub struct RulingFamily {
    /// `μ₀` with `ψ* = φ* + μ₀Ω*`.
    pub mu0: Q,
    /// The coordinate `k ∈ {1, 2}` with `ψ ⊂ {x_k = 0}`.
    pub hyperplane: usize,
    /// The dual matrix `φ*` (5×5 on `(u₀, …, u₄)`).
    pub phi_dual: [[Q; 5]; 5],
    /// The point form of `φ` in `R³` (4×4 on `(w, x₁, x₂, x₃)`).
    pub phi_point: [[Q; 4]; 4],
    /// The point form of `ψ` (5×5 on `(w, x₁, …, x₄)`, with `x_k = 0`).
    pub psi_point: [[Q; 5]; 5],
    /// The focal-conic point `P(T) = (P₁, …, P₄)/P₀` (`P₄ ≡ 0`).
    pub point: [P; 5],
    /// The ruling direction `D(T) = (D₁, …, D₄)/D₀`.
    pub direction: [P; 5],
}

fn q(n: i64) -> Q {
    Q::from(n)
}

fn zero5() -> [[Q; 5]; 5] {
    std::array::from_fn(|_| std::array::from_fn(|_| Q::ZERO))
}

fn sqrt_q(x: &Q, what: &str) -> Result<Q, PnError> {
    scalar_sqrt(x).ok_or_else(|| {
        PnError::NoRationalPoint(format!(
            "{what} = √{} is irrational: the rulings of the ruled quadric ψ of the pencil are then defined only over Q(√{}), so no rational family of cones of revolution exists",
            format_scalar(x),
            format_scalar(x)
        ))
    })
}

fn poly(c: &[Q]) -> P {
    Poly::new(c.to_vec())
}

impl RegularQuadric {
    /// Validates the axis data.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] for unordered or non-positive axes, naming the quadrics
    /// of revolution (equal axes), which are canal surfaces (Peternell, Cor. 4.3;
    /// `CanalPn`, `EllipsoidPn`).
    pub fn validate(&self) -> Result<(), PnError> {
        let z = Q::ZERO;
        let bad = |s: String| Err(PnError::InvalidInput(s));
        match self {
            RegularQuadric::Ellipsoid { a, b, c } => {
                if !(c > &z && b > c && a > b) {
                    return bad(format!(
                        "the ellipsoid needs a > b > c > 0, got ({}, {}, {}); with two equal axes it is a quadric of revolution, a canal surface (use the canal or umbilic-frame ellipsoid constructions)",
                        a, b, c
                    ));
                }
            }
            RegularQuadric::TwoSheetHyperboloid { a, b, c } => {
                if !(a > &z && c > &z && b > c) {
                    return bad(format!(
                        "the two-sheet hyperboloid x²/a² − y²/b² − z²/c² = 1 needs a > 0 and b > c > 0, got ({}, {}, {}); b = c is a quadric of revolution (a canal surface)",
                        a, b, c
                    ));
                }
            }
            RegularQuadric::EllipticParaboloid { a, b } => {
                if !(b > &z && a > b) {
                    return bad(format!(
                        "the elliptic paraboloid x²/a² + y²/b² = 2z needs a > b > 0, got ({}, {}); a = b is a paraboloid of revolution (a canal surface)",
                        a, b
                    ));
                }
            }
        }
        Ok(())
    }

    /// The ruled member `ψ` of the pencil `φ* + μΩ*` and one family of its rulings
    /// (`family` chooses the sign of the `x₄`-component).
    ///
    /// # Errors
    /// As [`Self::validate`]; [`PnError::NoRationalPoint`] if the rulings of `ψ` are not
    /// defined over `Q`.
    pub fn rulings(&self, family: bool) -> Result<RulingFamily, PnError> {
        self.validate()?;
        let sg = if family { q(1) } else { q(-1) };
        let two = q(2);
        match self {
            RegularQuadric::Ellipsoid { a, b, c }
            | RegularQuadric::TwoSheetHyperboloid { a, b, c } => {
                let ell = matches!(self, RegularQuadric::Ellipsoid { .. });
                let (a2, b2, c2) = (a * a, b * b, c * c);
                // ψ: k1 x1² + k3 x3² + k4 x4² = 1 in x2 = 0; focal conic k1 x1² + k3 x3² = 1
                let (aa, cc) = if ell {
                    (&a2 - &b2, &b2 - &c2)
                } else {
                    (&a2 + &b2, &b2 - &c2)
                };
                let s = sqrt_q(
                    &(&aa * &cc),
                    if ell {
                        "√((a² − b²)(b² − c²))"
                    } else {
                        "√((a² + b²)(b² − c²))"
                    },
                )?;
                let k1 = Q::ONE / &aa;
                let k3 = if ell { -(Q::ONE / &cc) } else { Q::ONE / &cc };
                let k4 = if ell { Q::ONE / &b2 } else { -(Q::ONE / &b2) };
                let mut phi_dual = zero5();
                phi_dual[0][0] = q(-1);
                phi_dual[1][1] = a2.clone();
                phi_dual[2][2] = if ell { b2.clone() } else { -b2.clone() };
                phi_dual[3][3] = if ell { c2.clone() } else { -c2.clone() };
                let mut phi_point: [[Q; 4]; 4] =
                    std::array::from_fn(|_| std::array::from_fn(|_| Q::ZERO));
                phi_point[0][0] = q(-1);
                phi_point[1][1] = Q::ONE / &a2;
                phi_point[2][2] = if ell { Q::ONE / &b2 } else { -(Q::ONE / &b2) };
                phi_point[3][3] = if ell { Q::ONE / &c2 } else { -(Q::ONE / &c2) };
                let mut psi_point = zero5();
                psi_point[0][0] = q(-1);
                psi_point[1][1] = k1.clone();
                psi_point[3][3] = k3.clone();
                psi_point[4][4] = k4.clone();
                // focal conic point
                let (p0, p1, p3) = if ell {
                    // hyperbola: (C x1 − s x3)(C x1 + s x3) = s²C, C x1 − s x3 = T
                    let s2c = &(&s * &s) * &cc;
                    (
                        poly(&[Q::ZERO, &two * &(&cc * &s)]),
                        poly(&[&s2c * &s, Q::ZERO, s.clone()]),
                        poly(&[&s2c * &cc, Q::ZERO, -cc.clone()]),
                    )
                } else {
                    // ellipse through (a, b s/A): lines of slope T
                    let (x0, z0) = (a.clone(), &(b * &s) / &aa);
                    // λ = −2(k1 x0 + k3 z0 T)/(k1 + k3 T²)
                    let den = poly(&[k1.clone(), Q::ZERO, k3.clone()]);
                    let lam = poly(&[-(&two * &(&k1 * &x0)), -(&two * &(&k3 * &z0))]);
                    (
                        den.clone(),
                        &den.scale(&x0) + &lam,
                        &den.scale(&z0) + &(&lam * &poly(&[Q::ZERO, Q::ONE])),
                    )
                };
                // D = (−σ k3 P3, 0, σ k1 P1, b) with σ = ±s (one family)
                let sig = &sg * &s;
                let direction = [
                    p0.clone(),
                    p3.scale(&-(&sig * &k3)),
                    P::zero(),
                    p1.scale(&(&sig * &k1)),
                    p0.scale(b),
                ];
                let mu0 = if ell { -b2 } else { b2 };
                Ok(RulingFamily {
                    mu0,
                    hyperplane: 2,
                    phi_dual,
                    phi_point,
                    psi_point,
                    point: [p0, p1, P::zero(), p3, P::zero()],
                    direction,
                })
            }
            RegularQuadric::EllipticParaboloid { a, b } => {
                let (a2, b2) = (a * a, b * b);
                let g2 = &a2 - &b2;
                let g = sqrt_q(&g2, "√(a² − b²)")?;
                let mut phi_dual = zero5();
                phi_dual[1][1] = a2.clone();
                phi_dual[2][2] = b2.clone();
                phi_dual[0][3] = q(-1);
                phi_dual[3][0] = q(-1);
                let mut phi_point: [[Q; 4]; 4] =
                    std::array::from_fn(|_| std::array::from_fn(|_| Q::ZERO));
                phi_point[1][1] = Q::ONE / &a2;
                phi_point[2][2] = Q::ONE / &b2;
                phi_point[0][3] = q(-1);
                phi_point[3][0] = q(-1);
                // ψ: −x2²/G + x4²/a² − 2x3 + a² = 0, x1 = 0
                let mut psi_point = zero5();
                psi_point[0][0] = a2.clone();
                psi_point[2][2] = -(Q::ONE / &g2);
                psi_point[4][4] = Q::ONE / &a2;
                psi_point[0][3] = q(-1);
                psi_point[3][0] = q(-1);
                // P = (0, T, (a² − T²/G)/2, 0), D = (0, γ, −T/γ, ±a)
                let point = [
                    poly(&[Q::ONE]),
                    P::zero(),
                    poly(&[Q::ZERO, Q::ONE]),
                    poly(&[&a2 / &two, Q::ZERO, -(Q::ONE / &(&two * &g2))]),
                    P::zero(),
                ];
                let direction = [
                    poly(&[Q::ONE]),
                    P::zero(),
                    poly(std::slice::from_ref(&g)),
                    poly(&[Q::ZERO, -(Q::ONE / &g)]),
                    poly(&[&sg * a]),
                ];
                Ok(RulingFamily {
                    mu0: -a2,
                    hyperplane: 1,
                    phi_dual,
                    phi_point,
                    psi_point,
                    point,
                    direction,
                })
            }
        }
    }

    /// A short name.
    pub fn name(&self) -> &'static str {
        match self {
            RegularQuadric::Ellipsoid { .. } => "ellipsoid",
            RegularQuadric::TwoSheetHyperboloid { .. } => "two-sheet hyperboloid",
            RegularQuadric::EllipticParaboloid { .. } => "elliptic paraboloid",
        }
    }
}

/// `Ω* = diag(0, 1, 1, 1, −1)`.
pub fn absolute_dual() -> [[Q; 5]; 5] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| match (i == j, i) {
            (true, 1..=3) => Q::ONE,
            (true, 4) => q(-1),
            _ => Q::ZERO,
        })
    })
}

impl RulingFamily {
    /// `ψ* = φ* + μ₀Ω*`.
    pub fn psi_dual(&self) -> [[Q; 5]; 5] {
        let o = absolute_dual();
        std::array::from_fn(|i| {
            std::array::from_fn(|j| &self.phi_dual[i][j] + &(&self.mu0 * &o[i][j]))
        })
    }

    /// Exact certificates that `ψ` is the ruled member of the pencil and carries the
    /// rulings: `ψ*·e_k = 0` (singular, in the hyperplane `x_k = 0`), the point form is the
    /// inverse of `ψ*` restricted to the other coordinates (up to a factor), and
    /// `P(T) + λD(T)` lies on `ψ` identically in `(T, λ)`.
    pub fn certify(&self) -> Vec<Certificate> {
        let psi = self.psi_dual();
        let k = self.hyperplane;
        let mut out = Vec::new();
        let kernel = psi.iter().all(|row| row[k].is_zero());
        out.push(cert_bool(
            &format!("ψ* = φ* + μ₀Ω* is singular with kernel e_{k}: ψ lies in the hyperplane x_{k} = 0 (Peternell Thm 4.6)"),
            kernel,
        ));
        // restricted inverse: Ψ_r · ψ*_r = c I on the indices ≠ k
        let idx: Vec<usize> = (0..5).filter(|&i| i != k).collect();
        let prod = |i: usize, j: usize| -> Q {
            idx.iter().fold(Q::ZERO, |acc, &m| {
                &acc + &(&self.psi_point[i][m] * &psi[m][j])
            })
        };
        let c = prod(idx[0], idx[0]);
        let inv = !c.is_zero()
            && idx.iter().all(|&i| {
                idx.iter()
                    .all(|&j| prod(i, j) == if i == j { c.clone() } else { Q::ZERO })
            });
        out.push(cert_bool(
            "the point form of ψ is the inverse of its dual matrix ψ* (restricted to x_k = 0)",
            inv,
        ));
        // P + λD on ψ: homogeneous (P D₀ + λ D P₀, P₀D₀)
        let lam = MPoly::<Q>::var(2, 1);
        let up = |p: &P| MPoly::from_poly(p, 2, 0);
        let x: Vec<MPoly<Q>> = (0..5)
            .map(|i| {
                if i == 0 {
                    &up(&self.point[0]) * &up(&self.direction[0])
                } else {
                    &(&up(&self.point[i]) * &up(&self.direction[0]))
                        + &(&lam * &(&up(&self.direction[i]) * &up(&self.point[0])))
                }
            })
            .collect();
        let mut form = MPoly::zero(2);
        for i in 0..5 {
            for j in 0..5 {
                if !self.psi_point[i][j].is_zero() {
                    form = &form + &(&x[i] * &x[j]).scale(&self.psi_point[i][j]);
                }
            }
        }
        out.push(zero_cert(
            "every ruling P(T) + λD(T) lies on ψ (identity in T and λ)",
            &form,
            1.0,
        ));
        out.push(zero_cert(
            "the rulings lie in the hyperplane x_k = 0 and start on {x₄ = 0}",
            &(&(&x[k] * &x[k]) + &up(&self.point[4]).pow(2)),
            1.0,
        ));
        out
    }

    /// `N(T) = ⟨D, D⟩` numerator (`D₁² + D₂² + D₃² − D₄²`), over `D₀²`.
    pub fn pe_norm(&self) -> P {
        let d = &self.direction;
        &(&(&(&d[1] * &d[1]) + &(&d[2] * &d[2])) + &(&d[3] * &d[3])) - &(&d[4] * &d[4])
    }
}

fn cert_bool(property: &str, holds: bool) -> Certificate {
    if holds {
        Certificate::holds(property, true)
    } else {
        Certificate::fails(property, "violated (exact check)", true)
    }
}

/// `p(n/d)·d^deg` for a univariate `p` of degree ≤ `deg`.
fn subst(p: &P, n: &P, d: &P, deg: usize) -> P {
    let mut acc = P::zero();
    for (i, c) in p.coeffs().iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        acc = &acc + &(&n.pow(i as u32) * &d.pow((deg - i) as u32)).scale(c);
    }
    acc
}

/// The double cover `T = n(S)/d(S)` found for a ruling family.
#[derive(Debug, Clone)]
pub struct Cover {
    /// The branch polynomial `q` (two parabolic rulings).
    pub branch: P,
    /// The rational point `(T₀, w₀)` of `w² = κ q(T)` the cover is drawn from
    /// (`κ = q(T₀)`, `w₀ = κ`), or `None` for the point at infinity (`κ` = leading
    /// coefficient of `q`).
    pub t0: Option<Q>,
    /// Numerator of `T(S)`.
    pub num: P,
    /// Denominator of `T(S)`.
    pub den: P,
}

/// Small rationals ordered by height.
fn small_rationals() -> Vec<Q> {
    let mut out = vec![Q::ZERO];
    for h in 1..=7i64 {
        for d in 1..=h {
            for n in [h, d] {
                let (nn, dd) = if n == h { (h, d) } else { (d, h) };
                if gcd(nn, dd) != 1 {
                    continue;
                }
                for s in [1, -1] {
                    let v = Q::from_ratio(s * nn, dd);
                    if !out.contains(&v) {
                        out.push(v);
                    }
                }
            }
        }
    }
    out
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 {
        a.abs()
    } else {
        gcd(b, a % b)
    }
}

/// Searches a double cover `T(S)` with `N(T(S))` a sum of two squares over `Q(S)`.
fn find_cover(n: &P, deg: usize) -> Result<Cover, PnError> {
    let (_, factors) = factor_rational(n).map_err(|e| {
        PnError::NoRationalPoint(format!("the ruling norm N(T) could not be factored: {e}"))
    })?;
    let odd: Vec<&P> = factors
        .iter()
        .filter(|(_, e)| e % 2 == 1)
        .map(|(f, _)| f)
        .collect();
    let mut branches: Vec<P> = odd
        .iter()
        .filter(|f| f.degree() == Some(2))
        .map(|f| (*f).clone())
        .collect();
    let lin: Vec<&&P> = odd.iter().filter(|f| f.degree() == Some(1)).collect();
    for i in 0..lin.len() {
        for j in i + 1..lin.len() {
            branches.push(&**lin[i] * &**lin[j]);
        }
    }
    let ndeg = n.degree().unwrap_or(0);
    if (deg - ndeg.min(deg)) % 2 == 1 {
        // ∞ is a root of odd multiplicity: pair it with a rational root
        for l in &lin {
            branches.push((**l).clone());
        }
    }
    if branches.is_empty() {
        // N has no sign change: try N itself
        let n2 = n.clone();
        if let Ok(SumOfSquares::Rational { .. }) = sum_of_two_squares(&n2) {
            return Ok(Cover {
                branch: poly(&[Q::ONE]),
                t0: Some(Q::ZERO),
                num: poly(&[Q::ZERO, Q::ONE]),
                den: poly(&[Q::ONE]),
            });
        }
    }
    let sos = |num: &P, den: &P| -> bool {
        let sub = subst(n, num, den, deg);
        // N(T(S)) = sub/den^deg (deg even): a sum of two squares iff sub is
        matches!(sum_of_two_squares(&sub), Ok(SumOfSquares::Rational { .. }))
    };
    // Cauchy bound of the roots: candidates T₀ beyond every root as well
    let lead = n.leading();
    let bound = n
        .coeffs()
        .iter()
        .map(|c| Scalar::to_f64(&(c / &lead)).abs() + 1.0)
        .fold(1.0f64, f64::max)
        .ceil()
        .min(1e6);
    let bound = Q::from(bound as i64);
    let mut tried: Vec<(usize, Q)> = Vec::new();
    for (bi, qb) in branches.iter().enumerate() {
        // the cover through the point at infinity of w² = lc·q(T): q(T(S)) = lc·square
        let (num, den) = if qb.degree() == Some(2) {
            let lc = qb.leading();
            let p = &qb.coeff(1) / &lc;
            let r = &qb.coeff(0) / &lc;
            let delta = &(&(&p * &p) / &q(4)) - &r;
            (poly(&[delta, -p, Q::ONE]), poly(&[Q::ZERO, q(2)]))
        } else {
            (poly(&[-qb.coeff(0), Q::ZERO, Q::ONE]), poly(&[qb.coeff(1)]))
        };
        tried.push((bi, qb.leading()));
        if sos(&num, &den) {
            return Ok(Cover {
                branch: qb.clone(),
                t0: None,
                num,
                den,
            });
        }
        let lc2 = if qb.degree() == Some(2) {
            qb.leading()
        } else {
            Q::ZERO
        };
        let dq = qb.derivative();
        let small = small_rationals();
        let cands = small
            .iter()
            .cloned()
            .chain(small.iter().skip(1).map(|t| t * &bound));
        for t0 in cands {
            let kappa = qb.eval(&t0);
            if kappa.is_zero() {
                continue;
            }
            // same square class as a tried κ → an isomorphic cover
            if tried
                .iter()
                .any(|(b, k)| *b == bi && scalar_sqrt(&(&kappa / k)).is_some())
            {
                continue;
            }
            tried.push((bi, kappa.clone()));
            let w0 = kappa.clone();
            // T = T₀ + (κq′(T₀) − 2w₀S)/(S² − κ lc)
            let den = poly(&[-(&kappa * &lc2), Q::ZERO, Q::ONE]);
            let lin = poly(&[&kappa * &dq.eval(&t0), -(&w0 * &q(2))]);
            let num = &den.scale(&t0) + &lin;
            if sos(&num, &den) {
                return Ok(Cover {
                    branch: qb.clone(),
                    t0: Some(t0),
                    num,
                    den,
                });
            }
        }
    }
    Err(PnError::NoRationalPoint(format!(
        "N(T) = {} (the pe norm of the ruling directions) becomes a sum of two squares over Q(S) under none of the {} double covers tried (branched at pairs of parabolic rulings); a rational PN parametrization by this family of cones needs a further quadratic extension",
        rcagd_algebra::format_poly(n, "T"),
        tried.len()
    )))
}

/// The cycle families `c₁ = (P; 0)`, `c₂ = (P + D)` in the cover parameter `S` (exact)
/// and `p = (p₁, p₂)` for Theorem 4.5.
#[derive(Debug, Clone)]
struct ExactCones {
    c1: [P; 5],
    c2: [P; 5],
    p: [(P, P); 2],
}

fn exact_cones(r: &RulingFamily) -> Result<(Cover, ExactCones), PnError> {
    // common degree in T: P = Pn/P0, D = Dn/D0
    let dgt = |v: &[P; 5]| v.iter().filter_map(|p| p.degree()).max().unwrap_or(0);
    let deg = dgt(&r.point).max(dgt(&r.direction));
    let n = r.pe_norm();
    let cover = find_cover(&n, 2 * dgt(&r.direction))?;
    let sub = |p: &P| subst(p, &cover.num, &cover.den, deg);
    let pt: [P; 5] = std::array::from_fn(|i| sub(&r.point[i]));
    let dr: [P; 5] = std::array::from_fn(|i| sub(&r.direction[i]));
    // c1 = (P; 0) (P₄ = 0), c2 = P + D over P₀D₀
    let c1 = pt.clone();
    let c2: [P; 5] = std::array::from_fn(|i| {
        if i == 0 {
            &pt[0] * &dr[0]
        } else {
            &(&pt[i] * &dr[0]) + &(&dr[i] * &pt[0])
        }
    });
    // M = m1 − m2 = −D (over D₀), R = −D₄: |M|² − R² = N(T(S))/D₀²
    let nn =
        &(&(&(&dr[1] * &dr[1]) + &(&dr[2] * &dr[2])) + &(&dr[3] * &dr[3])) - &(&dr[4] * &dr[4]);
    let (g1, g2) = match sum_of_two_squares(&nn) {
        Ok(SumOfSquares::Rational { g1, g2 }) => (g1, g2),
        _ => {
            return Err(PnError::NoRationalPoint(
                "the pulled-back ruling norm is not a sum of two squares (internal: the cover test and the decomposition disagree)".into(),
            ))
        }
    };
    Ok((
        cover,
        ExactCones {
            c1,
            c2,
            p: [(g1, dr[0].clone()), (g2, dr[0].clone())],
        },
    ))
}

/// A rational pe similarity `y ↦ s·A·y + t` of the cyclographic model `R⁴` (a Laguerre
/// transformation of `R³`; Peternell (3.8)): `A` is pe-orthogonal (`AᵀEA = E`,
/// `E = diag(1, 1, 1, −1)`), `s ≠ 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct PeSimilarity {
    /// The Lorentz matrix `A` (rows).
    pub a: [[Q; 4]; 4],
    /// The translation `t`.
    pub t: [Q; 4],
    /// The factor `s`.
    pub s: Q,
}

impl PeSimilarity {
    /// The identity.
    pub fn identity() -> Self {
        PeSimilarity {
            a: std::array::from_fn(|i| {
                std::array::from_fn(|j| if i == j { Q::ONE } else { Q::ZERO })
            }),
            t: std::array::from_fn(|_| Q::ZERO),
            s: Q::ONE,
        }
    }

    /// The rational boost in the plane of the axes `(axis, x₄)` with parameter `b`
    /// (`cosh = (1 + b²)/(1 − b²)`, `sinh = 2b/(1 − b²)`), then the translation `t`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] for `axis > 2` or `b² = 1`.
    pub fn boost(axis: usize, b: Q, t: [Q; 4]) -> Result<Self, PnError> {
        let den = &Q::ONE - &(&b * &b);
        if axis > 2 || den.is_zero() {
            return Err(PnError::InvalidInput(format!(
                "a boost needs an axis 0, 1 or 2 and a parameter b with b² ≠ 1 (got axis {axis}, b = {b})"
            )));
        }
        let ch = &(&Q::ONE + &(&b * &b)) / &den;
        let sh = &(&q(2) * &b) / &den;
        let mut m = Self::identity();
        m.a[axis][axis] = ch.clone();
        m.a[3][3] = ch;
        m.a[axis][3] = sh.clone();
        m.a[3][axis] = sh;
        m.t = t;
        Ok(m)
    }

    /// The homogeneous 5×5 matrix `H = [[1, 0], [t, sA]]` acting on `(w, y)`.
    pub fn homogeneous(&self) -> [[Q; 5]; 5] {
        let mut h = zero5();
        h[0][0] = Q::ONE;
        for i in 0..4 {
            h[i + 1][0] = self.t[i].clone();
            for j in 0..4 {
                h[i + 1][j + 1] = &self.s * &self.a[i][j];
            }
        }
        h
    }

    /// `AᵀEA = E` and `s ≠ 0` (exact).
    pub fn is_pe_similarity(&self) -> bool {
        let e = |i: usize| if i == 3 { q(-1) } else { Q::ONE };
        !self.s.is_zero()
            && (0..4).all(|i| {
                (0..4).all(|j| {
                    let v = (0..4).fold(Q::ZERO, |acc, k| {
                        &acc + &(&(&self.a[k][i] * &e(k)) * &self.a[k][j])
                    });
                    v == if i == j { e(i) } else { Q::ZERO }
                })
            })
    }
}

fn to_f<F: Scalar>(p: &P) -> MPoly<F> {
    MPoly::from_poly(&p.map(F::from_rational), 2, 0)
}

/// A hypercyclide: the cyclographic image `η(φ′)` of the quadric `φ′ = L(φ)`, `φ` a
/// regular quadric of `R³ = {x₄ = 0}` and `L` a rational pe similarity of `R⁴`, as a PN
/// surface (Peternell Prop. 4.3, Theorem 4.6; module docs). With `L = id` it is the
/// quadric itself (Theorem 4.6), its offsets are `PnSurface::offset`.
#[derive(Debug, Clone)]
pub struct Hypercyclide<F> {
    quadric: RegularQuadric,
    map: PeSimilarity,
    rulings: RulingFamily,
    cover: Cover,
    envelope: ConeFamilyEnvelope<Q>,
    surface: PnSurface<F>,
}

impl<F: Scalar> Hypercyclide<F> {
    /// The regular quadric itself as a PN surface (Theorem 4.6), principal frame.
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn quadric(quadric: RegularQuadric, family: bool) -> Result<Self, PnError> {
        Self::new(quadric, PeSimilarity::identity(), family)
    }

    /// The hypercyclide `η(L(φ))`; `family` chooses one of the two ruling families of `ψ`.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] for bad axes or a map that is not a pe similarity;
    /// [`PnError::NoRationalPoint`] if the rulings of `ψ` are irrational or no double
    /// cover makes the ruling norm a sum of two squares (module docs).
    pub fn new(quadric: RegularQuadric, map: PeSimilarity, family: bool) -> Result<Self, PnError> {
        if !map.is_pe_similarity() {
            return Err(PnError::InvalidInput(
                "the map is not a pe similarity of R⁴: AᵀEA ≠ E (E = diag(1, 1, 1, −1)) or s = 0"
                    .into(),
            ));
        }
        let rulings = quadric.rulings(family)?;
        let (cover, cones) = exact_cones(&rulings)?;
        let h = map.homogeneous();
        let apply = |c: &[P; 5]| -> [P; 5] {
            std::array::from_fn(|i| {
                (0..5).fold(P::zero(), |acc, j| {
                    if h[i][j].is_zero() {
                        acc
                    } else {
                        &acc + &c[j].scale(&h[i][j])
                    }
                })
            })
        };
        let fam = |c: &[P; 5]| -> Result<CycleFamily<Q>, PnError> {
            let c = apply(c);
            CycleFamily::new(
                [to_f(&c[1]), to_f(&c[2]), to_f(&c[3])],
                to_f(&c[4]),
                to_f(&c[0]),
            )
        };
        let c1 = fam(&cones.c1)?;
        let c2 = fam(&cones.c2)?;
        // M and R scale by s (A is pe-orthogonal): p ↦ s·p
        let p = [0, 1].map(|i| {
            let (n, d) = &cones.p[i];
            RatFn {
                num: to_f::<Q>(n).scale(&map.s),
                den: to_f(d),
            }
        });
        // the families' denominators: c1 over P₀, c2 over P₀D₀; M = (m1 w2 − m2 w1)/(w1 w2)
        let envelope = ConeFamilyEnvelope::new(c1, c2, Some(p))?;
        // the construction is exact (the sum-of-two-squares decision needs it); the
        // surface in the scalar F is the exact one with its coefficients converted
        let surface = envelope.surface().map_scalar(F::from_rational);
        Ok(Hypercyclide {
            quadric,
            map,
            rulings,
            cover,
            envelope,
            surface,
        })
    }

    /// The PN surface (parameters `(S, u)`).
    pub fn surface(&self) -> &PnSurface<F> {
        &self.surface
    }

    /// The cone-family envelope behind it (exact).
    pub fn envelope(&self) -> &ConeFamilyEnvelope<Q> {
        &self.envelope
    }

    /// The ruled member `ψ` and the ruling family.
    pub fn rulings(&self) -> &RulingFamily {
        &self.rulings
    }

    /// The double cover used.
    pub fn cover(&self) -> &Cover {
        &self.cover
    }

    /// The quadric data.
    pub fn quadric_data(&self) -> &RegularQuadric {
        &self.quadric
    }

    /// The pe similarity `L`.
    pub fn map(&self) -> &PeSimilarity {
        &self.map
    }

    /// `φ′* = H φ* Hᵀ`, the dual matrix of the mapped quadric.
    pub fn phi_dual(&self) -> [[Q; 5]; 5] {
        let h = self.map.homogeneous();
        let f = &self.rulings.phi_dual;
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let mut acc = Q::ZERO;
                for k in 0..5 {
                    for l in 0..5 {
                        if !f[k][l].is_zero() {
                            acc = &acc + &(&(&h[i][k] * &f[k][l]) * &h[j][l]);
                        }
                    }
                }
                acc
            })
        })
    }

    /// The certificates of the cyclographic image for the surface `surface` (the base or
    /// an offset, whose support function is `h − d`: the offset is the image of `φ′`
    /// translated by `d` along `x₄`): with `Γ = (h + d, n, 1)`,
    /// * `Γᵀφ′*Γ ≡ 0`: every tangent plane's γ-hyperplane is tangent to `φ′`;
    /// * the contact point `y = φ′*Γ` lies on `φ′` (`L⁻¹y` in `x₄ = 0` and on `φ`);
    /// * the surface point is the contact point of the plane with the cycle of `y`:
    ///   `x ≡ m + (r + d) n` (so it is on that sphere, and the plane touches it there).
    pub fn image_certificates(&self, surface: &PnSurface<F>) -> Vec<Certificate> {
        let d = surface.distance().clone();
        let n = surface.normal_polys();
        let hs = surface.support();
        let x = surface.point_polys();
        // Γ homogeneous: (e0 N0, N1 L, N2 L, N3 L, N0 L) with e0 = (h + d) = (H + dL)/L
        let e0 = &hs.num + &hs.den.scale(&d);
        let g: [MPoly<F>; 5] = [
            &e0 * &n[0],
            &n[1] * &hs.den,
            &n[2] * &hs.den,
            &n[3] * &hs.den,
            &n[0] * &hs.den,
        ];
        let fd = self.phi_dual();
        let ff = |i: usize, j: usize| F::from_rational(&fd[i][j]);
        let mut quad = MPoly::zero(2);
        if F::EXACT {
            // Σᵢ φ′ᵢᵢ gᵢ² + Σ_{i<j} (φ′ᵢⱼ + φ′ⱼᵢ) gᵢgⱼ: the same polynomial with 15 products
            // instead of 25 (for f64 the sum below, whose rounding depends on the order)
            for i in 0..5 {
                for j in i..5 {
                    let c = if i == j {
                        fd[i][i].clone()
                    } else {
                        &fd[i][j] + &fd[j][i]
                    };
                    if !c.is_zero() {
                        quad += &(&g[i] * &g[j]).scale(&F::from_rational(&c));
                    }
                }
            }
        } else {
            for i in 0..5 {
                for j in 0..5 {
                    if !fd[i][j].is_zero() {
                        quad = &quad + &(&g[i] * &g[j]).scale(&ff(i, j));
                    }
                }
            }
        }
        let mut out = vec![zero_cert(
            "every tangent plane's γ-hyperplane (e0, n, 1) touches the quadric φ′ of R⁴: Γᵀφ′*Γ ≡ 0 (Peternell §4.7)",
            &quad,
            1e3 * super::poly::mag(&quad).max(1.0),
        )];
        // contact point y = φ′* Γ (homogeneous (y0, y1..y4))
        let y: [MPoly<F>; 5] = std::array::from_fn(|i| {
            (0..5).fold(MPoly::zero(2), |acc, j| {
                if fd[i][j].is_zero() {
                    acc
                } else {
                    &acc + &g[j].scale(&ff(i, j))
                }
            })
        });
        // pull back: z = H⁻¹ y; H⁻¹ = [[1, 0], [−A⁻¹t/s, A⁻¹/s]], A⁻¹ = E Aᵀ E
        let a = &self.map.a;
        let e = |i: usize| if i == 3 { q(-1) } else { Q::ONE };
        let ainv: [[Q; 4]; 4] =
            std::array::from_fn(|i| std::array::from_fn(|j| &(&e(i) * &a[j][i]) * &e(j)));
        let z: [MPoly<F>; 5] = std::array::from_fn(|i| {
            if i == 0 {
                return y[0].clone();
            }
            let mut acc = MPoly::zero(2);
            for j in 0..4 {
                if ainv[i - 1][j].is_zero() {
                    continue;
                }
                let c = &ainv[i - 1][j] / &self.map.s;
                // (y_{j+1} − t_j y0)
                let yj = &y[j + 1] - &y[0].scale(&F::from_rational(&self.map.t[j]));
                acc = &acc + &yj.scale(&F::from_rational(&c));
            }
            acc
        });
        out.push(zero_cert(
            "the contact point y = φ′*Γ lies in the hyperplane of φ′ (x₄ ∘ L⁻¹ ≡ 0)",
            &z[4],
            1e3 * super::poly::mag(&z[4]).max(1.0),
        ));
        let pp = &self.rulings.phi_point;
        let mut on = MPoly::zero(2);
        for i in 0..4 {
            for j in 0..4 {
                if !pp[i][j].is_zero() {
                    on = &on + &(&z[i] * &z[j]).scale(&F::from_rational(&pp[i][j]));
                }
            }
        }
        out.push(zero_cert(
            "the contact point y lies on the quadric φ′ (L⁻¹y on φ)",
            &on,
            1e3 * super::poly::mag(&on).max(1.0),
        ));
        // x ≡ m + r n: X_i N0 y0 ≡ W (y_i N0 + (y4 + d y0) N_i)
        for i in 0..3 {
            let lhs = &(&x[i + 1] * &n[0]) * &y[0];
            let r = &y[4] + &y[0].scale(&d);
            let rhs = &x[0] * &(&(&y[i + 1] * &n[0]) + &(&r * &n[i + 1]));
            out.push(identity_cert(
                &format!("the point is the contact point m + r n of its plane with the cycle η(y) = (m; r) (component {i})"),
                &lhs,
                &rhs,
            ));
        }
        out
    }
}

impl<F: Scalar> Certified for Hypercyclide<F> {
    /// The pencil member `ψ` and its rulings (exact), the Theorem 4.5 certificates (PN,
    /// tangency to both cycle families, contact with every cone), the pe similarity, and
    /// the cyclographic-image certificates of [`Self::image_certificates`].
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.rulings.certify();
        out.push(cert_bool(
            "the map is a pe similarity: AᵀEA = E, s ≠ 0",
            self.map.is_pe_similarity(),
        ));
        out.extend(self.envelope.certify());
        out.extend(self.image_certificates(self.surface()));
        out
    }
}

/// A regular quadric as a PN surface (Peternell Theorem 4.6) through one entry point:
/// the envelope of the cones of the rulings of `ψ` ([`Hypercyclide::quadric`]) where that
/// construction finds a rational family, and for the two-sheet hyperboloid, where it
/// does not (module docs; no example is known where it does), the unirational
/// parametrization [`TwoSheetPn`] (docs/math/hypercyclides.md#two-sheet-unirational),
/// which exists for every rational `a, b, c`.
#[derive(Debug, Clone)]
pub enum QuadricPn<F> {
    /// The envelope of the cones of the rulings of `ψ` (parameters `(S, u)`).
    Rulings(Box<Hypercyclide<F>>),
    /// The two-sheet hyperboloid by [`TwoSheetPn`] (parameters `(τ, σ)`), with the reason
    /// the ruling construction gave.
    TwoSheet {
        /// The parametrization.
        pn: Box<TwoSheetPn<F>>,
        /// Why the ruling construction failed (its `NoRationalPoint` message).
        rulings_error: String,
    },
}

impl<F: Scalar> QuadricPn<F> {
    /// Theorem 4.6 for every regular quadric of [`RegularQuadric`]: the ruling
    /// construction first; for a two-sheet hyperboloid whose rulings give no rational
    /// family ([`PnError::NoRationalPoint`]) the unirational parametrization.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] for bad axes; [`PnError::NoRationalPoint`] for an
    /// ellipsoid or paraboloid whose rulings or covers are not rational (the message names
    /// the obstruction).
    pub fn new(quadric: RegularQuadric, family: bool) -> Result<Self, PnError> {
        match Hypercyclide::quadric(quadric.clone(), family) {
            Ok(h) => Ok(QuadricPn::Rulings(Box::new(h))),
            Err(PnError::NoRationalPoint(why)) => match quadric {
                RegularQuadric::TwoSheetHyperboloid { a, b, c } => Ok(QuadricPn::TwoSheet {
                    pn: Box::new(TwoSheetPn::new(
                        F::from_rational(&a),
                        F::from_rational(&b),
                        F::from_rational(&c),
                    )?),
                    rulings_error: why,
                }),
                _ => Err(PnError::NoRationalPoint(why)),
            },
            Err(e) => Err(e),
        }
    }

    /// The PN surface.
    pub fn surface(&self) -> &PnSurface<F> {
        match self {
            QuadricPn::Rulings(h) => h.surface(),
            QuadricPn::TwoSheet { pn, .. } => pn.surface(),
        }
    }

    /// Which construction was used: `"rulings"` or `"two_sheet_unirational"`.
    pub fn construction(&self) -> &'static str {
        match self {
            QuadricPn::Rulings(_) => "rulings",
            QuadricPn::TwoSheet { .. } => "two_sheet_unirational",
        }
    }

    /// The certificates that `surface` (the base or an offset) belongs to the quadric:
    /// [`Hypercyclide::image_certificates`] or [`TwoSheetPn::tangency_certificates`].
    pub fn quadric_certificates(&self, surface: &PnSurface<F>) -> Vec<Certificate> {
        match self {
            QuadricPn::Rulings(h) => h.image_certificates(surface),
            QuadricPn::TwoSheet { pn, .. } => pn.tangency_certificates(surface),
        }
    }
}

impl<F: Scalar> Certified for QuadricPn<F> {
    /// The certificates of the construction used.
    fn certify(&self) -> Vec<Certificate> {
        match self {
            QuadricPn::Rulings(h) => h.certify(),
            QuadricPn::TwoSheet { pn, .. } => pn.certify(),
        }
    }
}

// -------------------------------------------------------------------------------------
// Cyclographic images of surfaces of R⁴ (Peternell §3.9, Lemma 3.5)
// -------------------------------------------------------------------------------------

/// The square root of a polynomial with rational coefficients (any number of variables),
/// `None` if it is not the square of a polynomial over `Q`: term by term in the
/// lexicographic order (the leading term of `p − q²` is `2·LT(q)·t` for the next term `t`).
pub fn mpoly_sqrt(p: &MPoly<Q>) -> Option<MPoly<Q>> {
    if p.is_zero() {
        return Some(MPoly::zero(p.nvars().max(2)));
    }
    let nv = p.nvars().max(2);
    let pad = |e: &[u32]| -> Vec<u32> { (0..nv).map(|i| e.get(i).copied().unwrap_or(0)).collect() };
    let lead = |x: &MPoly<Q>| -> Option<(Vec<u32>, Q)> {
        x.terms()
            .map(|(e, c)| (pad(e), c.clone()))
            .max_by(|a, b| a.0.cmp(&b.0))
    };
    let (e0, c0) = lead(p)?;
    if e0.iter().any(|k| k % 2 == 1) {
        return None;
    }
    let r0 = scalar_sqrt(&c0)?;
    let lt_e: Vec<u32> = e0.iter().map(|k| k / 2).collect();
    let mut q = MPoly::monomial(nv, &lt_e, r0.clone());
    let two_lt = r0 * q2();
    let max_terms = p.num_terms() * 4 + 16;
    for _ in 0..max_terms {
        let rest = p - &(&q * &q);
        let Some((e, c)) = lead(&rest) else {
            return Some(q);
        };
        // t = LT(rest) / (2·LT(q)); its exponent must be ≥ 0 and below LT(q)
        if e.iter().zip(&lt_e).any(|(a, b)| a < b) {
            return None;
        }
        let te: Vec<u32> = e.iter().zip(&lt_e).map(|(a, b)| a - b).collect();
        if te >= lt_e {
            return None;
        }
        q = &q + &MPoly::monomial(nv, &te, &c / &two_lt);
    }
    None
}

fn q2() -> Q {
    q(2)
}

/// The cyclographic image `η(φ)` of a rational 2-surface `φ: s(u, v) = (m; r)(u, v)` of
/// `R⁴` (Peternell §3.9, Lemma 3.5): the envelope of its cycles. A tangent plane
/// `(e₀, n)` of the envelope at the cycle `s` satisfies the contact condition and its
/// derivatives, `n·m_u = −r_u`, `n·m_v = −r_v`, `|n| = 1`; with the numerators
/// `a = S_u w − S w_u`, `b = S_v w − S w_v` of the partial derivatives (`s = S/w`), the Gram
/// matrix `G` of `a, b` (first three coordinates) and
/// `Δ = det G − (a₄²G₂₂ − 2a₄b₄G₁₂ + b₄²G₁₁)`,
///
/// `n = [(−a₄G₂₂ + b₄G₁₂) a + (−b₄G₁₁ + a₄G₁₂) b ± √Δ (a × b)] / det G`,
/// `x = m + r n`
///
/// (docs/math/hypercyclides.md#surfaces). The image is rational by this construction iff
/// `Δ` is a square in `Q[u, v]`: two sheets `η(φ)₁, η(φ)₂`, or one for a γ-surface
/// (`Δ ≡ 0`: every tangent plane of `φ` is a γ-plane). Each sheet is a PN surface.
#[derive(Debug, Clone)]
pub struct CyclographicImage {
    s: [MPoly<Q>; 4],
    w: MPoly<Q>,
    derivatives: [[MPoly<Q>; 4]; 2],
    sheets: Vec<PnSurface<Q>>,
}

/// The first-order data of `s = S/w` that [`CyclographicImage::new`] and its
/// reparametrization share: the numerators `a = S_u w − S w_u`, `b = S_v w − S w_v` of the
/// partial derivatives, the Gram entries `G₁₁, G₁₂, G₂₂` of their R³ parts, `det G`, and
/// `Δ = det G − (a₄²G₂₂ − 2a₄b₄G₁₂ + b₄²G₁₁)`.
struct FirstOrder {
    a: [MPoly<Q>; 4],
    b: [MPoly<Q>; 4],
    g11: MPoly<Q>,
    g12: MPoly<Q>,
    g22: MPoly<Q>,
    det: MPoly<Q>,
    delta: MPoly<Q>,
}

impl FirstOrder {
    fn of(s: &[MPoly<Q>; 4], w: &MPoly<Q>) -> Self {
        let der = |p: &MPoly<Q>, i: usize| &(&p.partial(i) * w) - &(p * &w.partial(i));
        let a: [MPoly<Q>; 4] = std::array::from_fn(|k| der(&s[k], 0));
        let b: [MPoly<Q>; 4] = std::array::from_fn(|k| der(&s[k], 1));
        let g11 = dot3(&a[..3], &a[..3]);
        let g12 = dot3(&a[..3], &b[..3]);
        let g22 = dot3(&b[..3], &b[..3]);
        let det = &(&g11 * &g22) - &(&g12 * &g12);
        let (a4, b4) = (&a[3], &b[3]);
        let delta = &det
            - &(&(&(&(a4 * a4) * &g22) - &(&(a4 * b4) * &g12).scale(&q(2))) + &(&(b4 * b4) * &g11));
        FirstOrder {
            a,
            b,
            g11,
            g12,
            g22,
            det,
            delta,
        }
    }
}

impl CyclographicImage {
    /// The image of `s = (S₁, S₂, S₃, S₄)/w` (polynomials in `(u, v)`).
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] for `w ≡ 0` or centres that do not span a surface
    /// (`m_u × m_v ≡ 0`); [`PnError::NoRationalPoint`] if `Δ` is not a square (the two
    /// sheets are conjugate over `Q(u, v)(√Δ)`).
    pub fn new(s: [MPoly<Q>; 4], w: MPoly<Q>) -> Result<Self, PnError> {
        if w.is_zero() {
            return Err(PnError::InvalidInput(
                "the surface of R⁴ needs a non-zero denominator w(u, v)".into(),
            ));
        }
        let FirstOrder {
            a,
            b,
            g11,
            g12,
            g22,
            det,
            delta,
        } = FirstOrder::of(&s, &w);
        if det.is_zero() {
            return Err(PnError::InvalidInput(
                "the centres m(u, v) of the cycles do not span a surface (m_u × m_v ≡ 0)".into(),
            ));
        }
        let (a4, b4) = (&a[3], &b[3]);
        let ca = &(&(-a4) * &g22) + &(b4 * &g12);
        let cb = &(&(-b4) * &g11) + &(a4 * &g12);
        let base: [MPoly<Q>; 3] = std::array::from_fn(|k| &(&ca * &a[k]) + &(&cb * &b[k]));
        let cr = super::poly::cross3(
            &[a[0].clone(), a[1].clone(), a[2].clone()],
            &[b[0].clone(), b[1].clone(), b[2].clone()],
        );
        let roots: Vec<MPoly<Q>> = if delta.is_zero() {
            vec![MPoly::zero(2)]
        } else {
            let r = mpoly_sqrt(&delta).ok_or_else(|| {
                PnError::NoRationalPoint(format!(
                    "Δ = det G − (a₄²G₂₂ − 2a₄b₄G₁₂ + b₄²G₁₁) is not the square of a polynomial over Q ({} terms): the two sheets of the cyclographic image are conjugate over Q(u, v)(√Δ)",
                    delta.num_terms()
                ))
            })?;
            vec![r.clone(), -r]
        };
        let mut sheets = Vec::new();
        for (k, root) in roots.iter().enumerate() {
            let n: [MPoly<Q>; 3] = std::array::from_fn(|i| &base[i] + &(root * &cr[i]));
            let point = [
                &w * &det,
                &(&s[0] * &det) + &(&s[3] * &n[0]),
                &(&s[1] * &det) + &(&s[3] * &n[1]),
                &(&s[2] * &det) + &(&s[3] * &n[2]),
            ];
            let normal = [det.clone(), n[0].clone(), n[1].clone(), n[2].clone()];
            let sheet = PnSurface::from_point_normal(point, normal)?
                .named(format!("cyclographic image, sheet {}", k + 1));
            sheets.push(sheet);
        }
        Ok(CyclographicImage {
            s,
            w,
            derivatives: [a, b],
            sheets,
        })
    }

    /// The sheets (two, or one for a γ-surface).
    pub fn sheets(&self) -> &[PnSurface<Q>] {
        &self.sheets
    }

    /// `true` if `φ` is a γ-surface (`Δ ≡ 0`, one sheet).
    pub fn is_gamma_surface(&self) -> bool {
        self.sheets.len() == 1
    }

    /// For a sheet (or its offset at `d`, support `h − d`): every surface point is the
    /// contact point of its tangent plane with its cycle, `x ≡ m + (r + d) n` (so on the
    /// sphere of the cycle, and the plane touches it there), and the plane is in contact
    /// with the neighbouring cycles: `n·m_u ≡ −r_u`, `n·m_v ≡ −r_v`.
    pub fn image_certificates(&self, sheet: &PnSurface<Q>) -> Vec<Certificate> {
        let d = sheet.distance().clone();
        let x = sheet.point_polys();
        let n = sheet.normal_polys();
        let s = &self.s;
        let w = &self.w;
        let mut out = Vec::new();
        for i in 0..3 {
            let lhs = &(&x[i + 1] * &n[0]) * w;
            let r = &s[3] + &w.scale(&d);
            let rhs = &x[0] * &(&(&s[i] * &n[0]) + &(&r * &n[i + 1]));
            out.push(identity_cert(
                &format!("the point is the contact point m + r n of its plane with its cycle (component {i}; Peternell Lemma 3.5)"),
                &lhs,
                &rhs,
            ));
        }
        for (j, a) in self.derivatives.iter().enumerate() {
            let lhs = dot3(&n[1..], &a[..3]);
            let rhs = -(&n[0] * &a[3]);
            out.push(identity_cert(
                &format!(
                    "the tangent plane touches the neighbouring cycles: n·m_{} ≡ −r_{}",
                    ["u", "v"][j],
                    ["u", "v"][j]
                ),
                &lhs,
                &rhs,
            ));
        }
        out
    }
}

/// The part of odd multiplicity `δ` of `p ∈ Q[u, v]`: `p = δ·g²` with `δ` squarefree and
/// `g ∈ Q[u, v]` (the constant of `δ` chosen so that `p/δ` is a square); by successive
/// radicals `rad(x) = x/gcd(x, x_u, x_v)` (characteristic 0). `None` if a division fails
/// (it cannot for exact input) or `p ≡ 0`.
pub fn odd_part(p: &MPoly<Q>) -> Option<MPoly<Q>> {
    use super::poly::{div_exact, gcd2};
    if p.is_zero() {
        return None;
    }
    let one = MPoly::constant(2, q(1));
    let is_const = |x: &MPoly<Q>| x.total_degree().unwrap_or(0) == 0;
    let rad = |x: &MPoly<Q>| -> Option<MPoly<Q>> {
        if is_const(x) {
            return Some(one.clone());
        }
        let g = gcd2(&gcd2(x, &x.partial(0)), &x.partial(1));
        div_exact(x, &g)
    };
    let mut cur = p.clone();
    let mut r = rad(&cur)?;
    let mut delta = one.clone();
    let mut k = 0usize;
    while !is_const(&cur) && k < 64 {
        let next = div_exact(&cur, &r)?;
        let r_next = rad(&next)?;
        let t = div_exact(&r, &r_next)?;
        if k.is_multiple_of(2) {
            delta = &delta * &t;
        }
        cur = next;
        r = r_next;
        k += 1;
    }
    let quot = div_exact(p, &delta)?;
    let lc = quot.terms().last().map(|(_, c)| c.clone())?;
    let delta = delta.scale(&lc);
    let quot = div_exact(p, &delta)?;
    mpoly_sqrt(&quot).map(|_| delta)
}

/// A reparametrization `(u, v) = (U, V)/D(p, q)` of the plane that makes a squarefree
/// `δ` of total degree 1 or 2 a square: the stereographic projection of the quadric
/// `w² = δ(u, v)` from a rational point `(u₀, v₀, w₀)`, `w₀ ≠ 0` (the lines
/// `(u₀ + λp, v₀ + λq, w₀ + λ)`, `λ = (2w₀ − L(p, q))/(H(p, q) − 1)` with `L` the linear
/// and `H` the quadratic part of `δ` at the point; docs/math/hypercyclides.md#non-square-delta).
/// The point is searched among `u₀, v₀ = a/b`, `|a| ≤ 8`, `1 ≤ b ≤ 4`; `None` if there
/// is none there.
pub fn quadric_reparametrization(delta: &MPoly<Q>) -> Option<[MPoly<Q>; 3]> {
    let deg = delta.total_degree()?;
    if !(1..=2).contains(&deg) {
        return None;
    }
    let gcd = |mut a: i64, mut b: i64| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a.abs()
    };
    let mut pairs: Vec<(i64, i64)> = (1..=4i64)
        .flat_map(|b| (-8..=8i64).map(move |a| (a, b)))
        .filter(|&(a, b)| gcd(a, b) == 1)
        .collect();
    pairs.sort_by_key(|&(a, b)| (a.abs() + b, b));
    let cands: Vec<Q> = pairs
        .into_iter()
        .map(|(a, b)| Q::from_ratio(a, b))
        .collect();
    let (pv, qv) = (MPoly::<Q>::var(2, 0), MPoly::<Q>::var(2, 1));
    for u0 in &cands {
        for v0 in &cands {
            let val = delta.eval(&[u0.clone(), v0.clone()]).ok()?;
            if val.is_zero() {
                continue;
            }
            let Some(w0) = scalar_sqrt(&val) else {
                continue;
            };
            // δ(u₀ + λp, v₀ + λq) = δ₀ + λL + λ²H
            let shifted = super::poly::compose(
                delta,
                &[
                    &pv + &MPoly::constant(2, u0.clone()),
                    &qv + &MPoly::constant(2, v0.clone()),
                ],
            );
            let part = |degree: u32| {
                MPoly::from_terms(
                    2,
                    shifted
                        .terms()
                        .filter(|(e, _)| e.iter().sum::<u32>() == degree)
                        .map(|(e, c)| (e.to_vec(), c.clone()))
                        .collect(),
                )
                .ok()
            };
            let lin = part(1)?;
            let quad = part(2)?;
            let d = &quad - &MPoly::constant(2, q(1));
            let num = &MPoly::constant(2, &w0 * &q(2)) - &lin;
            let u = &d.scale(u0) + &(&pv * &num);
            let v = &d.scale(v0) + &(&qv * &num);
            return Some([u, v, d]);
        }
    }
    None
}

impl CyclographicImage {
    /// The image of `s = S/w` after the reparametrization of
    /// [`quadric_reparametrization`] when `Δ` is not a square but its odd part `δ`
    /// ([`odd_part`]) has total degree 1 or 2 (docs/math/hypercyclides.md#non-square-delta):
    /// the image of `s((U, V)/D)` in the new parameters `(p, q)`, returned with `(U, V, D)`.
    /// A square `Δ` needs no reparametrization (`(U, V, D) = (u, v, 1)`).
    ///
    /// # Errors
    /// [`PnError::NoRationalPoint`] naming what is missing: `δ` a non-square constant
    /// (the sheets are conjugate over `Q(√δ)`), `δ` of degree ≥ 3 (a double plane, not a
    /// quadric), or no rational point of the quadric `w² = δ` found; as [`Self::new`].
    pub fn reparametrized(s: [MPoly<Q>; 4], w: MPoly<Q>) -> Result<(Self, [MPoly<Q>; 3]), PnError> {
        let e = match Self::new(s.clone(), w.clone()) {
            Ok(img) => {
                return Ok((
                    img,
                    [MPoly::var(2, 0), MPoly::var(2, 1), MPoly::constant(2, q(1))],
                ))
            }
            Err(PnError::NoRationalPoint(m)) => m,
            Err(e) => return Err(e),
        };
        let delta = FirstOrder::of(&s, &w).delta;
        let odd = odd_part(&delta).ok_or_else(|| PnError::NoRationalPoint(e.clone()))?;
        let deg = odd.total_degree().unwrap_or(0);
        let psi = match deg {
            0 => {
                return Err(PnError::NoRationalPoint(format!(
                    "{e}; its odd part is the non-square constant {}: the sheets are conjugate over Q(√{}) and no reparametrization makes Δ a square",
                    format_scalar(&odd.coeff(&[0, 0])),
                    format_scalar(&odd.coeff(&[0, 0]))
                )))
            }
            1 | 2 => quadric_reparametrization(&odd).ok_or_else(|| {
                PnError::NoRationalPoint(format!(
                    "{e}; its odd part δ has degree {deg}, but no rational point of the quadric w² = δ(u, v) was found among u, v = a/b, |a| ≤ 8, b ≤ 4 (the stereographic projection from one would make Δ a square)"
                ))
            })?,
            _ => {
                return Err(PnError::NoRationalPoint(format!(
                    "{e}; its odd part δ has degree {deg} ≥ 3: a rational sheet needs a rational parametrization of the double plane w² = δ(u, v), which the library does not construct (docs/math/hypercyclides.md#non-square-delta)"
                )))
            }
        };
        let m = s
            .iter()
            .chain(std::iter::once(&w))
            .filter_map(|p| p.total_degree())
            .max()
            .unwrap_or(0) as u32;
        let sub = |p: &MPoly<Q>| -> MPoly<Q> {
            let mut acc = MPoly::zero(2);
            for (ex, c) in p.terms() {
                let i = ex.first().copied().unwrap_or(0);
                let j = ex.get(1).copied().unwrap_or(0);
                let t = &(&psi[0].pow(i) * &psi[1].pow(j)) * &psi[2].pow(m - i - j);
                acc = &acc + &t.scale(c);
            }
            acc
        };
        let s2: [MPoly<Q>; 4] = std::array::from_fn(|k| sub(&s[k]));
        let img = Self::new(s2, sub(&w))?;
        Ok((img, psi))
    }
}

impl Certified for CyclographicImage {
    /// PN identities and the image certificates of every sheet.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        for s in &self.sheets {
            out.extend(s.certify());
            out.extend(self.image_certificates(s));
        }
        out
    }
}
