//! The pencil of dual quadrics `λC + μΩ` of a Dupin cyclide (Peternell, "Rational
//! Parametrizations for Envelopes of Quadric Families", §3.8.1, Prop. 3.1 and 3.2;
//! corrected determinant: docs/math/cyclides.md#pencil).
//!
//! Hyperplanes of `R⁴` are `X₀ + X₁x₁ + … + X₄x₄ = 0`; a conic is the dual quadric of the
//! hyperplanes tangent to it, `Ω = diag(0, 1, 1, 1, −1)` the absolute quadric. For the pe
//! circle, with `e = (1, C₀)`, `Ũ = (0, U)`, `Ṽ = (0, V)`:
//! `C = e eᵀ − ρ²(Ũ Ũᵀ + Ṽ Ṽᵀ)` and the second singular member is `D = C + ρ²Ω` (the pe
//! hyperbola of the second family); `det(λC + μΩ) = κ λ μ² (μ − ρ²λ)²`, i.e. `λ = 0` (Ω)
//! is a simple zero and `μ = 0` (C) a double zero (the printed text has them the other
//! way round). For the pe parabola, `C = (ŨŨᵀ − (e Ñᵀ + Ñ eᵀ))/g` with `Ñ = (0, N)` and
//! `g = ⟨U, U⟩` (the form of the pe-unit tangent `U/√g` and `N/g`), every
//! member is singular (`det ≡ 0`), `D = Ω − C` is the parabola of the second family and
//! `P = C + Ω` a paraboloid of rank 4 in the γ-hyperplane `⟨N, x − C₀⟩ = −1`.
//!
//! The cyclide is the cyclographic image of each singular member: its oriented tangent
//! planes `e₀ + n·x = 0` give the γ-hyperplanes `(e₀, n, 1)`, tangent to every member.

use super::conic::PeConic;
use super::pe::{negligible, pe_row, size};
use super::surface::DupinCyclide;
use super::CyclideError;
use crate::canal::bipoly::BiPoly;
use rcagd_algebra::{format_scalar, Certificate, Poly, Scalar};
use rcagd_geom::certify::polynomial_is_zero_scaled;

/// One named member of the pencil: a symmetric 5×5 matrix.
#[derive(Debug, Clone, PartialEq)]
pub struct PencilMember<F> {
    /// `"C"`, `"Ω"`, `"D"` or `"P"`.
    pub name: &'static str,
    /// The symmetric matrix (hyperplane coordinates).
    pub matrix: Vec<Vec<F>>,
    /// Hyperplanes spanning its kernel (empty where not computed).
    pub kernel: Vec<[F; 5]>,
}

/// The pencil `λC + μΩ` of a cyclide with its singular members.
#[derive(Debug, Clone, PartialEq)]
pub struct DualPencil<F> {
    /// `C`, `Ω`, `D` and, for the parabolic cyclide, `P`.
    pub members: Vec<PencilMember<F>>,
    /// `ρ²` for the pe circle (`D = C + ρ²Ω`), `None` for the parabola.
    pub rho2: Option<F>,
}

fn outer<F: Scalar>(a: &[F; 5], b: &[F; 5]) -> Vec<Vec<F>> {
    (0..5)
        .map(|i| (0..5).map(|j| a[i].clone() * b[j].clone()).collect())
        .collect()
}

fn lin<F: Scalar>(terms: &[(F, &Vec<Vec<F>>)]) -> Vec<Vec<F>> {
    (0..5)
        .map(|i| {
            (0..5)
                .map(|j| {
                    terms
                        .iter()
                        .fold(F::zero(), |acc, (k, m)| acc + k.clone() * m[i][j].clone())
                })
                .collect()
        })
        .collect()
}

fn lift<F: Scalar>(a: &[F; 4], w: F) -> [F; 5] {
    [w, a[0].clone(), a[1].clone(), a[2].clone(), a[3].clone()]
}

fn omega<F: Scalar>() -> Vec<Vec<F>> {
    (0..5)
        .map(|i| {
            (0..5)
                .map(|j| match (i, j) {
                    (1, 1) | (2, 2) | (3, 3) => F::one(),
                    (4, 4) => -F::one(),
                    _ => F::zero(),
                })
                .collect()
        })
        .collect()
}

/// A basis of `{X : ⟨X, Aᵢ⟩ = 0 ∀i}` (as `conic::pe_complement`, with the pivots of
/// [`super::route::null_space_rounded`]).
fn pe_complement_rounded<F: Scalar>(a: &[[F; 4]]) -> Result<Vec<[F; 4]>, CyclideError> {
    let rows: Vec<Vec<F>> = a.iter().map(pe_row).collect();
    super::route::null_space_rounded(&rows)
        .into_iter()
        .map(|v| {
            <[F; 4]>::try_from(v).map_err(|_| CyclideError::InvalidArgument("kernel length".into()))
        })
        .collect()
}

/// Hyperplanes containing the plane `{P₀ + αA + βB}`: `X·(1, P₀) = 0`, `X'·A = X'·B = 0`
/// (Euclidean dot products in hyperplane coordinates).
fn plane_kernel<F: Scalar>(
    p0: &[F; 4],
    a: &[F; 4],
    b: &[F; 4],
) -> Result<Vec<[F; 5]>, CyclideError> {
    // pe_complement solves ⟨X, ·⟩ = 0; use it on 5-vectors via an explicit matrix instead
    let rows = vec![
        lift(p0, F::one()).to_vec(),
        lift(a, F::zero()).to_vec(),
        lift(b, F::zero()).to_vec(),
    ];
    // in f64 a rounding residue of an exact 0 must not become a pivot (the kernel would
    // be ill-conditioned): any basis of the kernel serves the certificate
    super::route::null_space_rounded(&rows)
        .into_iter()
        .map(|v| {
            <[F; 5]>::try_from(v).map_err(|_| CyclideError::InvalidArgument("kernel length".into()))
        })
        .collect()
}

impl<F: Scalar> DualPencil<F> {
    /// The pencil of the cyclide's conic with its singular members and their kernels.
    ///
    /// # Errors
    /// As [`PeConic::conjugate`].
    pub fn of(cyclide: &DupinCyclide<F>) -> Result<Self, CyclideError> {
        let om = omega::<F>();
        match cyclide.conic() {
            PeConic::Circle {
                center,
                u,
                v,
                rho,
                ratio,
            } => {
                let e = lift(center, F::one());
                let (ut, vt) = (lift(u, F::zero()), lift(v, F::zero()));
                let rr = rho.clone() * rho.clone();
                let (ee, uu, vv) = (outer(&e, &e), outer(&ut, &ut), outer(&vt, &vt));
                // V/√k is the second pe-orthonormal direction (times ρ): its outer product is VVᵀ/k
                let c = lin(&[
                    (F::one(), &ee),
                    (-rr.clone(), &uu),
                    (-rr.clone() / ratio.clone(), &vv),
                ]);
                let rr_d = rr.clone() * super::pe::pe(u, u);
                let d = lin(&[(F::one(), &c), (rr_d.clone(), &om)]);
                let ck = plane_kernel(center, u, v)?;
                let comp = pe_complement_rounded(&[u.clone(), v.clone()])?;
                let dk = match comp.as_slice() {
                    [a, b] => plane_kernel(center, a, b)?,
                    _ => Vec::new(),
                };
                Ok(DualPencil {
                    members: vec![
                        PencilMember {
                            name: "C",
                            matrix: c,
                            kernel: ck,
                        },
                        PencilMember {
                            name: "Ω",
                            matrix: om,
                            kernel: vec![lift(
                                &[F::zero(), F::zero(), F::zero(), F::zero()],
                                F::one(),
                            )],
                        },
                        PencilMember {
                            name: "D",
                            matrix: d,
                            kernel: dk,
                        },
                    ],
                    rho2: Some(rr_d),
                })
            }
            PeConic::Parabola { vertex, u, n } => {
                let e = lift(vertex, F::one());
                let (ut, nt) = (lift(u, F::zero()), lift(n, F::zero()));
                // in the pe-unit form U/√g, N/g (g = ⟨U, U⟩) the member C is this over g
                let gi = F::one() / super::pe::pe(u, u);
                let c = lin(&[
                    (gi.clone(), &outer(&ut, &ut)),
                    (-gi.clone(), &outer(&e, &nt)),
                    (-gi, &outer(&nt, &e)),
                ]);
                let d = lin(&[(F::one(), &om), (-F::one(), &c)]);
                let p = lin(&[(F::one(), &om), (F::one(), &c)]);
                let ck = plane_kernel(vertex, u, n)?;
                let (m, pv, _) = super::conic::parabola_frame(u, n)?;
                let dv = super::pe::add(vertex, &m);
                let dk = plane_kernel(&dv, &pv, n)?;
                Ok(DualPencil {
                    members: vec![
                        PencilMember {
                            name: "C",
                            matrix: c,
                            kernel: ck,
                        },
                        PencilMember {
                            name: "Ω",
                            matrix: om,
                            kernel: Vec::new(),
                        },
                        PencilMember {
                            name: "D",
                            matrix: d,
                            kernel: dk,
                        },
                        PencilMember {
                            name: "P",
                            matrix: p,
                            kernel: Vec::new(),
                        },
                    ],
                    rho2: None,
                })
            }
        }
    }

    /// `det(λC + Ω)` as a polynomial in `λ` (`μ = 1`).
    pub fn determinant(&self) -> Poly<F> {
        let (c, om) = match (self.members.first(), self.members.get(1)) {
            (Some(c), Some(o)) => (&c.matrix, &o.matrix),
            _ => return Poly::zero(),
        };
        let m: Vec<Vec<Poly<F>>> = (0..5)
            .map(|i| {
                (0..5)
                    .map(|j| Poly::new(vec![om[i][j].clone(), c[i][j].clone()]))
                    .collect()
            })
            .collect();
        det_poly(&m)
    }

    /// The magnitude of `det(λC + Ω)`: the permanent of `|λC| + |Ω|` (entrywise absolute
    /// values, in `f64`), whose coefficient `k` bounds the sum of the absolute values of the
    /// terms of coefficient `k` of the determinant (the `f64` tolerance scale).
    pub fn determinant_magnitude(&self) -> Poly<f64> {
        let (c, om) = match (self.members.first(), self.members.get(1)) {
            (Some(c), Some(o)) => (&c.matrix, &o.matrix),
            _ => return Poly::zero(),
        };
        let m: Vec<Vec<Poly<f64>>> = (0..5)
            .map(|i| {
                (0..5)
                    .map(|j| Poly::new(vec![om[i][j].to_f64().abs(), c[i][j].to_f64().abs()]))
                    .collect()
            })
            .collect();
        permanent_poly(&m)
    }

    /// Certificates: the kernels (singular members of rank ≤ 3), the determinant of the
    /// pencil, and the cyclide's tangent γ-hyperplanes `(−n·x, n, 1)` tangent to every
    /// member (the cyclide is the cyclographic image of each).
    pub fn certify(&self, cyclide: &DupinCyclide<F>) -> Vec<Certificate> {
        let mut out = Vec::new();
        let ex = F::EXACT;
        for m in &self.members {
            if m.kernel.len() >= 2 {
                let sc = m
                    .matrix
                    .iter()
                    .flatten()
                    .map(|x| x.to_f64().abs())
                    .fold(1.0, f64::max)
                    * m.kernel.iter().map(|k| size(k)).fold(1.0, f64::max);
                let res: Vec<F> = m
                    .kernel
                    .iter()
                    .flat_map(|k| {
                        m.matrix
                            .iter()
                            .map(|row| {
                                row.iter()
                                    .zip(k)
                                    .fold(F::zero(), |a, (x, y)| a + x.clone() * y.clone())
                            })
                            .collect::<Vec<_>>()
                    })
                    .collect();
                let first = res.iter().find(|x| !negligible(*x, sc)).cloned();
                out.push(Certificate::decide(
                    format!("{} K = 0 for {} independent hyperplanes K through the plane of the conic (a singular member of rank ≤ {})", m.name, m.kernel.len(), 5 - m.kernel.len()),
                    first.is_none(),
                    ex,
                    || first.map(|x| format_scalar(&x)).unwrap_or_default(),
                ));
            }
        }
        let p = self.determinant();
        // f64: coefficient k of a residual is compared with the sum of the absolute values
        // of the terms that make it up — the permanent of |λC| + |Ω| (the determinant's
        // terms without their signs), not the determinant's own largest coefficient
        let mag = self.determinant_magnitude();
        let within = |res: &Poly<F>, extra: &[f64]| {
            res.coeffs().iter().enumerate().all(|(k, x)| {
                let m = mag.coeff(k).max(extra.get(k).copied().unwrap_or(0.0));
                negligible(x, m)
            })
        };
        match &self.rho2 {
            Some(rr) => {
                let l0 = F::one() / rr.clone();
                let dp = p.derivative();
                let ok = p.eval(&F::zero()).is_zero()
                    && !dp.eval(&F::zero()).is_zero()
                    && p.degree() == Some(3)
                    && p.eval(&l0).is_zero()
                    && dp.eval(&l0).is_zero();
                let ok = ok
                    || (!ex && {
                        let k = p.coeff(1);
                        // κλ(1 − ρ²λ)² expanded
                        let want = Poly::new(vec![
                            F::zero(),
                            k.clone(),
                            -F::from_i64(2) * k.clone() * rr.clone(),
                            k.clone() * rr.clone() * rr.clone(),
                        ]);
                        let (kf, rf) = (k.to_f64().abs(), rr.to_f64().abs());
                        let extra = [0.0, kf, 2.0 * kf * rf, kf * rf * rf];
                        !k.is_zero() && within(&(&p - &want), &extra)
                    });
                out.push(Certificate::decide(
                    "det(λC + μΩ) = κλμ²(μ − ρ²λ)², κ ≠ 0: Ω (λ = 0) simple, C (μ = 0) double, D = C + ρ²Ω double (Peternell §3.8.1, corrected)",
                    ok,
                    ex,
                    || format!("det(λC + Ω) = {:?}", p.coeffs().iter().map(format_scalar).collect::<Vec<_>>()),
                ));
            }
            None => {
                let ok = within(&p, &[]);
                out.push(Certificate::decide(
                    "det(λC + μΩ) ≡ 0 (every member of the parabolic pencil is singular; C and D have rank 3)",
                    ok,
                    ex,
                    || format!("det(λC + Ω) = {:?}", p.coeffs().iter().map(format_scalar).collect::<Vec<_>>()),
                ));
            }
        }
        // tangent γ-hyperplanes H = (−N·X, X₀N, X₀²)
        let x = cyclide.homogeneous();
        let n = cyclide.normal_numerators();
        let nx = n[0].mul(&x[1]).add(&n[1].mul(&x[2])).add(&n[2].mul(&x[3]));
        let h: [BiPoly<F>; 5] = [
            nx.neg(),
            x[0].mul(&n[0]),
            x[0].mul(&n[1]),
            x[0].mul(&n[2]),
            x[0].mul(&x[0]),
        ];
        let hsc = h
            .iter()
            .flat_map(|p| p.all_coeffs())
            .map(|c| c.to_f64().abs())
            .fold(1.0, f64::max);
        for m in &self.members {
            let mut acc = BiPoly::zero();
            for i in 0..5 {
                for j in 0..5 {
                    let k = m.matrix[i][j].clone();
                    if !k.is_zero() {
                        acc = acc.add(&h[i].mul(&h[j]).scale(&k));
                    }
                }
            }
            let msc = m
                .matrix
                .iter()
                .flatten()
                .map(|x| x.to_f64().abs())
                .fold(1.0, f64::max);
            out.push(polynomial_is_zero_scaled(
                &format!("H {} Hᵀ ≡ 0 for the tangent γ-hyperplanes H = (−n·x, n, 1) (the cyclide is the cyclographic image of {})", m.name, m.name),
                &acc.all_coeffs(),
                hsc * hsc * msc,
            ));
        }
        out
    }
}

/// Permanent of a square matrix of polynomials (the cofactor expansion of
/// [`det_poly`] without signs; 5×5 here).
fn permanent_poly(m: &[Vec<Poly<f64>>]) -> Poly<f64> {
    cofactor_expansion(m, false)
}

/// Determinant of a square matrix of polynomials (cofactor expansion; 5×5 here).
fn det_poly<F: Scalar>(m: &[Vec<Poly<F>>]) -> Poly<F> {
    cofactor_expansion(m, true)
}

/// The cofactor expansion along the first row: the determinant when `signed`, else the
/// permanent.
fn cofactor_expansion<F: Scalar>(m: &[Vec<Poly<F>>], signed: bool) -> Poly<F> {
    let Some((first, rest)) = m.split_first() else {
        return Poly::constant(F::one());
    };
    let mut acc = Poly::zero();
    for (j, a) in first.iter().enumerate() {
        if a.is_zero() {
            continue;
        }
        let minor: Vec<Vec<Poly<F>>> = rest
            .iter()
            .map(|row| {
                row.iter()
                    .enumerate()
                    .filter(|(k, _)| *k != j)
                    .map(|(_, x)| x.clone())
                    .collect()
            })
            .collect();
        let term = a * &cofactor_expansion(&minor, signed);
        acc = if signed && j % 2 == 1 {
            &acc - &term
        } else {
            &acc + &term
        };
    }
    acc
}
