//! The degree-reducing frame of Peternell, *Rational Parametrizations for Envelopes of
//! Quadric Families* (1997), §4.5.1 and Proposition 4.1, for the envelope of the cones of
//! revolution spanned by two rational cycle families ([`ConeFamilyEnvelope`], Theorem 4.5).
//!
//! With `M = m₁ − m₂`, `R = r₁ − r₂` (polynomials) and `p₁² + p₂² = |M|² − R²`, the unit
//! normal of the envelope has the numerators (4.19), polynomials of degree `2k` in `t` for
//! data of degree `k`. Let `d(t)` be a factor of `|M|² − R²` with zeros `τ, τ̄` (an
//! irreducible quadratic factor, or a linear one). If the `x₃`-axis `ζ` of the frame
//! satisfies
//!
//! `ζ·M(τ) = −R(τ)` (and so also at `τ̄`),
//!
//! then `d` divides `β = R + M₃` and `α = M₁² + M₂² = (|M|² − R²) − (M₃² − R²)`, and after
//! choosing the sign of `p₂` also `γ` and `δ` (the real and imaginary parts of
//! `(M₁ + iM₂)(p₁ + ip₂)`): `d` divides every numerator of (4.19), and the normal drops to
//! degree `2k − 2` (Proposition 4.1). Peternell constructs `ζ` projectively, as the pole
//! `A × Ā` of the line joining the tangency points of the tangents from `M(τ)` to the
//! absolute conic (4.15)–(4.17); the condition above is the same (`α(τ) = 0` says that
//! `M(τ)` projects to an isotropic vector of `ζ^⊥`, and the orientation of `ζ` gives
//! `β(τ) = 0`) and is what we solve, rationally: writing `M ≡ S t + r₀`, `R ≡ s_R t + r_R`
//! modulo a quadratic `d`, the conditions are the two rational linear equations
//! `ζ·S = −s_R`, `ζ·r₀ = −r_R`, whose solution line meets the unit sphere in rational points
//! iff a rational number is a square; for a linear `d = t − τ₀` it is `ζ = −M(τ₀)/R(τ₀)`
//! (`|M(τ₀)| = |R(τ₀)|`). The frame is the rational reflection `H = I − 2wwᵀ/(w·w)`,
//! `w = e₃ − ζ`, so `H e₃ = ζ` and the new coordinates are `x′ = H x`
//! (docs/math/laguerre-pn.md#degree-reducing-frame).

use super::poly::{dot3, zero_cert};
use super::ruled::{ConeFamilyEnvelope, CycleFamily};
use super::PnError;
use crate::Certified;
use rcagd_algebra::factor::factor_rational;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{format_poly, sqrt_in_field, Certificate, Poly, Rational, Scalar};

/// A frame of §4.5.1: the factor `d(t)` of `|M|² − R²`, the new `x₃`-axis `ζ` (a rational
/// unit vector with `ζ·M ≡ −R` modulo `d`) and the reflection `H` (`H = Hᵀ = H⁻¹`,
/// `H e₃ = ζ`); coordinates in the frame are `x′ = H x`.
#[derive(Debug, Clone)]
pub struct ReducingFrame<F> {
    /// The factor `d(t)` (monic, of degree 1 or 2) whose zeros fix the frame.
    pub factor: MPoly<F>,
    /// The new `x₃`-axis.
    pub zeta: [F; 3],
    /// The reflection `H` with `H e₃ = ζ`.
    pub matrix: [[F; 3]; 3],
}

fn to_poly_q<F: Scalar>(p: &MPoly<F>) -> Option<Poly<Rational>> {
    if p.terms().any(|(e, _)| e.get(1).is_some_and(|&k| k > 0)) {
        return None;
    }
    let n = p.degree_in(0).unwrap_or(0) as usize;
    (0..=n)
        .map(|i| p.coeff(&[i as u32, 0]).to_rational())
        .collect::<Option<Vec<_>>>()
        .map(Poly::new)
}

fn from_poly_q<F: Scalar>(p: &Poly<Rational>) -> MPoly<F> {
    MPoly::from_terms(
        2,
        p.coeffs()
            .iter()
            .enumerate()
            .map(|(i, c)| (vec![i as u32, 0], F::from_rational(c)))
            .collect(),
    )
    .unwrap_or_else(|_| MPoly::zero(2))
}

type V3 = [Rational; 3];

fn dotq(a: &V3, b: &V3) -> Rational {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
}

fn crossq(a: &V3, b: &V3) -> V3 {
    [
        a[1].clone() * b[2].clone() - a[2].clone() * b[1].clone(),
        a[2].clone() * b[0].clone() - a[0].clone() * b[2].clone(),
        a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone(),
    ]
}

fn is_zero3(a: &V3) -> bool {
    a.iter().all(|x| *x == Rational::from(0))
}

/// The rational unit vectors `ζ` with `ζ·a_i = b_i` for one or two equations: the solution
/// set's intersection with the unit sphere when it consists of rational points (a line:
/// `±` when `(1 − |ζ₀|²)/|a₁ × a₂|²` is a rational square; a plane: only when it touches
/// the sphere).
fn unit_solutions(eqs: &[(V3, Rational)]) -> Vec<V3> {
    let zero = Rational::from(0);
    let one = Rational::from(1);
    let nonzero: Vec<&(V3, Rational)> = eqs.iter().filter(|(a, _)| !is_zero3(a)).collect();
    if eqs.iter().any(|(a, b)| is_zero3(a) && *b != zero) {
        return Vec::new();
    }
    let scaled = |a: &V3, s: &Rational| -> V3 { std::array::from_fn(|i| a[i].clone() * s.clone()) };
    match nonzero.as_slice() {
        [] => Vec::new(),
        [(a, b)] => {
            let z0 = scaled(a, &(b.clone() / dotq(a, a)));
            if dotq(&z0, &z0) == one {
                vec![z0]
            } else {
                Vec::new()
            }
        }
        [(a1, b1), (a2, b2), ..] => {
            let n = crossq(a1, a2);
            if is_zero3(&n) {
                // parallel rows: consistent iff b₂a₁ = b₁a₂ (as vectors); then one plane
                let consistent =
                    (0..3).all(|i| b2.clone() * a1[i].clone() == b1.clone() * a2[i].clone());
                return if consistent {
                    unit_solutions(&[((*a1).clone(), b1.clone())])
                } else {
                    Vec::new()
                };
            }
            // ζ₀ = x a₁ + y a₂ with the Gram system
            let (g11, g12, g22) = (dotq(a1, a1), dotq(a1, a2), dotq(a2, a2));
            let det = g11.clone() * g22.clone() - g12.clone() * g12.clone();
            let x = (b1.clone() * g22 - b2.clone() * g12.clone()) / det.clone();
            let y = (b2.clone() * g11 - b1.clone() * g12) / det;
            let z0: V3 =
                std::array::from_fn(|i| x.clone() * a1[i].clone() + y.clone() * a2[i].clone());
            let s2 = (one - dotq(&z0, &z0)) / dotq(&n, &n);
            match sqrt_in_field(&s2) {
                Some(s) if s == zero => vec![z0],
                Some(s) => [s.clone(), -s]
                    .iter()
                    .map(|s| std::array::from_fn(|i| z0[i].clone() + s.clone() * n[i].clone()))
                    .collect(),
                None => Vec::new(),
            }
        }
    }
}

/// `g mod f` as `(coefficient of t, constant)` for a monic quadratic `f`.
fn linear_remainder(g: &Poly<Rational>, f: &Poly<Rational>) -> Option<(Rational, Rational)> {
    let (_, rem) = g.div_rem(f).ok()?;
    Some((rem.coeff(1), rem.coeff(0)))
}

/// The reflection `H = I − 2wwᵀ/(w·w)`, `w = e₃ − ζ` (the identity for `ζ = e₃`).
fn reflection(zeta: &V3) -> [[Rational; 3]; 3] {
    let w: V3 = [
        -zeta[0].clone(),
        -zeta[1].clone(),
        Rational::from(1) - zeta[2].clone(),
    ];
    let ww = dotq(&w, &w);
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let id = if i == j {
                Rational::from(1)
            } else {
                Rational::from(0)
            };
            if ww == Rational::from(0) {
                id
            } else {
                id - Rational::from(2) * w[i].clone() * w[j].clone() / ww.clone()
            }
        })
    })
}

/// The frames of §4.5.1 for the data `M = (M₁, M₂, M₃)`, `R` (polynomials in `t`; exact
/// binary values for `f64`): one or two per linear or quadratic factor of `|M|² − R²` whose
/// `ζ` is rational. Empty if `|M|² − R²` has no such factor or no rational `ζ`.
pub fn reducing_frames<F: Scalar>(m: &[MPoly<F>; 3], r: &MPoly<F>) -> Vec<ReducingFrame<F>> {
    let Some(mq) = m.iter().map(to_poly_q).collect::<Option<Vec<_>>>() else {
        return Vec::new();
    };
    let Some(rq) = to_poly_q(r) else {
        return Vec::new();
    };
    let p = mq
        .iter()
        .fold(Poly::zero(), |acc, x| acc + x.clone() * x.clone())
        - rq.clone() * rq.clone();
    let Ok((_, factors)) = factor_rational(&p) else {
        return Vec::new();
    };
    let mut out: Vec<ReducingFrame<F>> = Vec::new();
    for (f, _) in factors {
        let zetas = match f.degree() {
            Some(1) => {
                let tau = -f.coeff(0);
                let v: V3 = std::array::from_fn(|i| mq[i].eval(&tau));
                unit_solutions(&[(v, -rq.eval(&tau))])
            }
            Some(2) => {
                let rem: Option<Vec<(Rational, Rational)>> = mq
                    .iter()
                    .chain([&rq])
                    .map(|g| linear_remainder(g, &f))
                    .collect();
                let Some(rem) = rem else { continue };
                let s: V3 = std::array::from_fn(|i| rem[i].0.clone());
                let r0: V3 = std::array::from_fn(|i| rem[i].1.clone());
                unit_solutions(&[(s, -rem[3].0.clone()), (r0, -rem[3].1.clone())])
            }
            _ => continue,
        };
        for z in zetas {
            let h = reflection(&z);
            let frame = ReducingFrame {
                factor: from_poly_q(&f),
                zeta: z.clone().map(|c| F::from_rational(&c)),
                matrix: h.map(|row| row.map(|c| F::from_rational(&c))),
            };
            if !out.iter().any(|o| o.zeta == frame.zeta) {
                out.push(frame);
            }
        }
    }
    out
}

impl<F: Scalar> ReducingFrame<F> {
    /// The certificates of the frame for the data `M, R`: `HᵀH = I`, `H e₃ = ζ`, and
    /// `d | R + ζ·M` and `d | |M|² − (ζ·M)²` (so `d` divides `β` and `α` in the frame).
    pub fn certify(&self, m: &[MPoly<F>; 3], r: &MPoly<F>) -> Vec<Certificate> {
        let h = &self.matrix;
        let mut orth = Vec::new();
        for i in 0..3 {
            for j in 0..3 {
                let s = (0..3).fold(F::zero(), |acc, k| acc + h[k][i].clone() * h[k][j].clone());
                let id = if i == j { F::one() } else { F::zero() };
                orth.push(s - id);
            }
        }
        let col: Vec<F> = (0..3)
            .map(|i| h[i][2].clone() - self.zeta[i].clone())
            .collect();
        let as_poly = |cs: &[F]| {
            MPoly::from_terms(
                2,
                cs.iter()
                    .enumerate()
                    .map(|(i, c)| (vec![i as u32, 0], c.clone()))
                    .collect(),
            )
            .unwrap_or_else(|_| MPoly::zero(2))
        };
        let z: [MPoly<F>; 3] = std::array::from_fn(|i| MPoly::constant(2, self.zeta[i].clone()));
        let zm = dot3(&z, m);
        let beta = &zm + r;
        let alpha = &dot3(m, m) - &(&zm * &zm);
        let rem = |p: &MPoly<F>| -> MPoly<F> { remainder_t(p, &self.factor) };
        let deg = self.factor.degree_in(0).unwrap_or(0);
        let d = format_poly(
            &Poly::new((0..=deg).map(|i| self.factor.coeff(&[i, 0])).collect()),
            "t",
        );
        vec![
            zero_cert("HᵀH = I (the frame is orthonormal)", &as_poly(&orth), 1.0),
            zero_cert("H e₃ = ζ (the new x₃-axis)", &as_poly(&col), 1.0),
            zero_cert(
                &format!("d(t) = {d} divides β = R + ζ·M (Peternell §4.5.1)"),
                &rem(&beta),
                1.0,
            ),
            zero_cert(
                &format!("d(t) = {d} divides α = |M|² − (ζ·M)² (Peternell §4.5.1)"),
                &rem(&alpha),
                1.0,
            ),
        ]
    }
}

/// The remainder of `p(t)` (a polynomial in `t` only) modulo `d(t)` (`Poly::div_rem`), as a
/// polynomial of the two-variable ring.
fn remainder_t<F: Scalar>(p: &MPoly<F>, d: &MPoly<F>) -> MPoly<F> {
    let univariate = |m: &MPoly<F>| {
        let n = m.degree_in(0).unwrap_or(0);
        Poly::new((0..=n).map(|i| m.coeff(&[i, 0])).collect())
    };
    match univariate(p).div_rem(&univariate(d)) {
        Ok((_, r)) => MPoly::from_terms(
            2,
            r.coeffs()
                .iter()
                .enumerate()
                .map(|(i, c)| (vec![i as u32, 0], c.clone()))
                .collect(),
        )
        .unwrap_or_else(|_| p.clone()),
        Err(_) => p.clone(),
    }
}

/// The envelope of Theorem 4.5 built in the best frame of §4.5.1 (Proposition 4.1), and
/// the degrees before and after.
#[derive(Debug, Clone)]
pub struct ReducedConeEnvelope<F> {
    envelope: ConeFamilyEnvelope<F>,
    frame: Option<ReducingFrame<F>>,
    k: usize,
    unreduced: (usize, usize),
}

/// `deg_t` of the unit normal numerators of a PN surface.
fn normal_degree_t<F: Scalar>(e: &ConeFamilyEnvelope<F>) -> usize {
    e.surface().normal_degree().0
}

impl<F: Scalar> ReducedConeEnvelope<F> {
    /// The envelope of the cones spanned by `c₁(t)`, `c₂(t)` (Theorem 4.5) in the given
    /// coordinates and in every frame of [`reducing_frames`] (with both signs of `p₂`),
    /// mapped back to the given coordinates; the one whose unit normal has the least degree
    /// in `t` (then the least point degree) is kept.
    ///
    /// # Errors
    /// As [`ConeFamilyEnvelope::new`] in the given coordinates, when no frame gives an
    /// envelope either.
    pub fn new(c1: CycleFamily<F>, c2: CycleFamily<F>) -> Result<Self, PnError> {
        let k = [&c1, &c2]
            .iter()
            .flat_map(|c| {
                let (m, r, w) = c.parts();
                m.into_iter()
                    .chain([r, w])
                    .map(|p| p.degree_in(0).unwrap_or(0) as usize)
            })
            .max()
            .unwrap_or(0);
        match ConeFamilyEnvelope::new(c1.clone(), c2.clone(), None) {
            Ok(e) => Self::search(c1, c2, None, k, Some(e)),
            Err(e) => Self::search(c1, c2, Some(e), k, None),
        }
    }

    fn search(
        c1: CycleFamily<F>,
        c2: CycleFamily<F>,
        err: Option<PnError>,
        k: usize,
        plain: Option<ConeFamilyEnvelope<F>>,
    ) -> Result<Self, PnError> {
        let (m, r) = difference(&c1, &c2);
        let unreduced = plain
            .as_ref()
            .map(|e| (normal_degree_t(e), e.surface().degree().0))
            .unwrap_or((usize::MAX, usize::MAX));
        let mut best: Option<(ConeFamilyEnvelope<F>, Option<ReducingFrame<F>>)> =
            plain.map(|e| (e, None));
        let key = |e: &ConeFamilyEnvelope<F>| {
            (
                normal_degree_t(e),
                e.surface().degree().0,
                e.surface().degree().1,
            )
        };
        for frame in reducing_frames(&m, &r) {
            let (Some(a), Some(b)) = (
                rotate_family(&c1, &frame.matrix),
                rotate_family(&c2, &frame.matrix),
            ) else {
                continue;
            };
            let Ok(first) = ConeFamilyEnvelope::new(a.clone(), b.clone(), None) else {
                continue;
            };
            let [p1, p2] = first.p().clone();
            let conj = [p1, p2.scale(&-F::one())];
            let mut tries = vec![first];
            if let Ok(second) = ConeFamilyEnvelope::new(a, b, Some(conj)) {
                tries.push(second);
            }
            for env in tries {
                let Ok(back) = env.transformed(&frame.matrix, c1.clone(), c2.clone()) else {
                    continue;
                };
                if best.as_ref().is_none_or(|(b, _)| key(&back) < key(b)) {
                    best = Some((back, Some(frame.clone())));
                }
            }
        }
        match best {
            Some((envelope, frame)) => Ok(ReducedConeEnvelope {
                envelope,
                frame,
                k,
                unreduced,
            }),
            None => Err(err.unwrap_or_else(|| {
                PnError::InvalidInput("no frame gives an envelope of the cones".into())
            })),
        }
    }

    /// The envelope, in the given coordinates.
    pub fn envelope(&self) -> &ConeFamilyEnvelope<F> {
        &self.envelope
    }

    /// The frame used (`None`: the given coordinates were best).
    pub fn frame(&self) -> Option<&ReducingFrame<F>> {
        self.frame.as_ref()
    }

    /// The degree `k` of the data (the largest degree of the cycle polynomials).
    pub fn data_degree(&self) -> usize {
        self.k
    }

    /// `(deg_t n, deg_t x)` of the envelope built in the given coordinates
    /// (`usize::MAX` if it could not be built there).
    pub fn unreduced_degrees(&self) -> (usize, usize) {
        self.unreduced
    }
}

/// `M = m₁ − m₂`, `R = r₁ − r₂` as polynomials over the common denominator `w₁w₂`.
fn difference<F: Scalar>(c1: &CycleFamily<F>, c2: &CycleFamily<F>) -> ([MPoly<F>; 3], MPoly<F>) {
    let (m1, r1, w1) = c1.parts();
    let (m2, r2, w2) = c2.parts();
    (
        std::array::from_fn(|i| &(m1[i] * w2) - &(m2[i] * w1)),
        &(r1 * w2) - &(r2 * w1),
    )
}

/// The cycle family in the coordinates `x′ = H x` (`None` if it cannot be formed: the frame
/// is then skipped, never used with the unrotated family).
fn rotate_family<F: Scalar>(c: &CycleFamily<F>, h: &[[F; 3]; 3]) -> Option<CycleFamily<F>> {
    let (m, r, w) = c.parts();
    let centre: [MPoly<F>; 3] =
        std::array::from_fn(|i| (0..3).fold(MPoly::zero(2), |acc, j| &acc + &m[j].scale(&h[i][j])));
    CycleFamily::new(centre, r.clone(), w.clone()).ok()
}

impl<F: Scalar> ReducedConeEnvelope<F> {
    /// The frame's certificates (orthonormal, `d | β`, `d | α`) and Proposition 4.1's
    /// degree `deg_t n ≤ 2k − 2`; empty when no frame was used.
    pub fn frame_certificates(&self) -> Vec<Certificate> {
        let Some(f) = &self.frame else {
            return Vec::new();
        };
        let (c1, c2) = self.envelope.families();
        let (m, r) = difference(c1, c2);
        let mut out = f.certify(&m, &r);
        let deg = normal_degree_t(&self.envelope);
        let bound = (2 * self.k).saturating_sub(2);
        let given = if self.unreduced.0 == usize::MAX {
            "no envelope".to_string()
        } else {
            self.unreduced.0.to_string()
        };
        out.push(Certificate {
            property: format!(
                "deg_t n = {deg} ≤ 2k − 2 = {bound} for data of degree k = {} (Peternell, Prop. 4.1; in the given coordinates: {given})",
                self.k
            ),
            holds: deg <= bound,
            exact: true,
            residual: (deg > bound).then(|| format!("degree {deg}")),
        });
        out.extend(self.dual_degree_certificates());
        out
    }

    /// Proposition 4.1's degree of the dual representation, for polynomial data (constant
    /// cycle denominators): the tangent planes `(E₀ : N₁ : N₂ : N₃)` with
    /// `E₀ = −(N·m₁ + N₀r₁)` (the support of the plane touching the cycles `c₁ = (m₁; r₁)`,
    /// certified by the tangency certificates) have `deg_t ≤ (2k_M − 2) + k`, `k_M` the
    /// degree of `M = m₁ − m₂, R = r₁ − r₂`: `3k − 2` for general data (`k_M = k`) and
    /// `3k − 4` for canal surfaces (`c₂ = c₁ + ċ₁`, so `M = −ṁ₁` has degree `k − 1`); the
    /// unit normal then has `deg_t ≤ 2k_M − 2` (docs/math/laguerre-pn.md#degree-reducing-frame).
    /// Empty without a frame or for rational data.
    pub fn dual_degree_certificates(&self) -> Vec<Certificate> {
        if self.frame.is_none() {
            return Vec::new();
        }
        let (c1, c2) = self.envelope.families();
        let (m1, r1, w1) = c1.parts();
        let (_, _, w2) = c2.parts();
        if w1.total_degree().unwrap_or(0) > 0 || w2.total_degree().unwrap_or(0) > 0 {
            return Vec::new();
        }
        let (m, r) = difference(c1, c2);
        let km = m
            .iter()
            .chain(std::iter::once(&r))
            .map(|p| p.degree_in(0).unwrap_or(0) as usize)
            .max()
            .unwrap_or(0);
        let k = self.k;
        let n = self.envelope.surface().normal_polys();
        let e0 = -(&(&(&(&n[1] * m1[0]) + &(&n[2] * m1[1])) + &(&n[3] * m1[2])) + &(&n[0] * r1));
        let deg_n = n
            .iter()
            .map(|p| p.degree_in(0).unwrap_or(0) as usize)
            .max()
            .unwrap_or(0);
        let deg = deg_n.max(e0.degree_in(0).unwrap_or(0) as usize);
        let nbound = (2 * km).saturating_sub(2);
        let bound = nbound + k;
        let name = if km == k {
            format!("3k − 2 = {bound}")
        } else if km + 1 == k {
            format!("the canal bound 3k − 4 = {bound} (k_M = k − 1)")
        } else {
            format!("(2k_M − 2) + k = {bound} (k_M = {km})")
        };
        vec![
            Certificate {
                property: format!(
                    "deg_t n = {deg_n} ≤ 2k_M − 2 = {nbound} for M, R of degree k_M = {km} (Peternell, Prop. 4.1)"
                ),
                holds: deg_n <= nbound,
                exact: true,
                residual: (deg_n > nbound).then(|| format!("degree {deg_n}")),
            },
            Certificate {
                property: format!(
                    "deg_t of the dual representation (E₀ : N), E₀ = −(N·m₁ + N₀r₁): {deg} ≤ {name} for data of degree k = {k} (Peternell, Prop. 4.1)"
                ),
                holds: deg <= bound,
                exact: true,
                residual: (deg > bound).then(|| format!("degree {deg}")),
            },
        ]
    }
}

impl<F: Scalar> Certified for ReducedConeEnvelope<F> {
    /// The envelope's certificates (PN, tangency to both cycle families, contact with every
    /// cone) and [`Self::frame_certificates`].
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.envelope.certify();
        out.extend(self.frame_certificates());
        out
    }
}
