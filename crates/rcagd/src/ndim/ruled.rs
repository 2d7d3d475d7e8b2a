//! Ruled `(k+1)`-manifolds of `Rⁿ` and their offset hypersurfaces (Peternell §5.4–§5.5,
//! (5.13)–(5.26), Lemma 5.1, Theorem 5.2; derivations in
//! docs/math/n-dimensional.md#ruled-manifolds).
//!
//! `x(t, u₁, …, u_k) = l(t) + Σ uⱼ gⱼ(t)` (5.13), `l = L/w` rational, `gⱼ` polynomial
//! (scaling a generator by a rational function only reparametrizes `uⱼ`); variable 0 is
//! `t`, variable `j` is `uⱼ`.
//!
//! **Structure.** `A(t) = span(g, ġ)` has dimension `k + m` (5.14), `T(t) = span(l̇, g, ġ)`
//! dimension `k + m` (Case 1) or `k + m + 1` (Case 2) (5.15). With `cⱼ` the component of
//! `ġⱼ` orthogonal to `G = span(g)` (`A ∩ G^⊥ = span(cⱼ)`, dimension `m`), a point `u` of the
//! generator is singular (Case 1, Lemma 5.1: `K = G ∩ Ġ`) or central (Case 2) iff
//! `p_t(u)·cᵢ = 0` for all `i`: `p_t ∈ T`, and `p_t ⟂ A ∩ G^⊥` says `p_t ∈ G` (Case 1) or
//! `p_t ∈ span(a, G)`, `a ⟂ A` (Case 2). These are `m` independent linear equations
//! (their matrix is the Gram matrix of the `cᵢ`), so the space has dimension `k − m`.
//!
//! **Offsets (Theorem 5.2).** Step 1: with a polynomial basis `bᵢ` of `G^⊥` and `b₁·p_t ≢ 0`,
//! `zᵢ = −(bᵢ·p_t) b₁ + (b₁·p_t) bᵢ` (5.23) span the normal space `N(p)` and are linear in
//! `u`: `z(ū) = ū₀c₀ + Σ ūⱼcⱼ` (5.24), `uⱼ = ūⱼ/ū₀`. A unit normal needs a point of the
//! quadric family `|z(ū)|² = w²` (5.25); Prop. 5.1: a conic section of it has a polynomial
//! point, found here on the plane of two coordinates `ū_a, ū_b` by the algebra layer's
//! conic-point engine (`α ū_a² + 2β ū_a ū_b + γ ū_b² = w²` ⇔ `X² + (αγ − β²)Y² − αZ² = 0`,
//! `X = αū_a + βū_b`, `Y = ū_b`, `Z = w`). Step 2: the stereographic projection from that
//! point `P` with directions `δ = (1, s₁, …, s_k)`, `ū(s) = |z(δ)|² ū* − 2 (z(ū*)·z(δ)) δ`,
//! `w(s) = |z(δ)|² w*`, parametrizes the whole quadric, so `u = u(t, s)` reparametrizes
//! the generators and `M = z(ū(s))/w(s)` is a rational unit normal everywhere. Where the
//! normal does not depend on `u` (Case 1 with `m = 1`, Case 2 with `m = 0`) a constant
//! direction of `N(t)` is combined instead ((5.27)/(5.28)); if `dim N = 1` its length is
//! in general irrational and the offset is not rational ([`NdimError::NotRational`]).
//! Step 3 (5.26): `y = p + dM − 2d (M·c/(c·c)) c` with `c(v) = Σ vᵢzᵢ + z_last` in `N(p)`.

use super::poly::{clean, cross, dot, dot_scale, mag, only_var0, rank};
use super::NdimError;
use crate::error::format_scalar;
use crate::pn::poly::{univariate_sqrt, zero_cert};
use crate::pn::{Domain, RatFn};
use crate::Certified;
use rcagd_algebra::conic_point::{conic_point, ConicPoint};
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};
use rcagd_geom::BezierPatch;

/// Case 1 (`dim T = k + m`: a singular space in each generator) or Case 2
/// (`dim T = k + m + 1`: a central space) of §5.4.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RuledKind {
    /// `l̇ ∈ A(t)`: the generators carry a `(k − m)`-space of singular points (Lemma 5.1).
    Singular,
    /// `l̇ ∉ A(t)`: the generators carry a `(k − m)`-dimensional central space.
    Central,
}

/// A rational ruled `(k+1)`-manifold `l(t) + Σ uⱼ gⱼ(t)` in `Rⁿ` (module docs).
#[derive(Debug, Clone)]
pub struct RuledManifold<F> {
    l: Vec<MPoly<F>>,
    w: MPoly<F>,
    g: Vec<Vec<MPoly<F>>>,
}

/// The structure of a ruled manifold (§5.4): dimensions and the singular or central
/// space `s(t) + span(directions)` of each generator.
#[derive(Debug, Clone)]
pub struct RuledStructure<F> {
    /// `dim A(t) = k + m`.
    pub dim_a: usize,
    /// `dim T(t)`.
    pub dim_t: usize,
    /// `m`.
    pub m: usize,
    /// Case 1 or Case 2.
    pub kind: RuledKind,
    /// The parameters `u*(t)` of a point of the singular/central space.
    pub params: Vec<RatFn<F>>,
    /// Its point `s(t) = l + Σ u*ⱼ gⱼ`.
    pub point: Vec<RatFn<F>>,
    /// Directions (in parameter space) spanning the singular/central space: `k − m` vectors.
    pub directions: Vec<Vec<RatFn<F>>>,
    certs: Vec<Certificate>,
}

impl<F: Scalar> RuledStructure<F> {
    /// The certificates: `p_t(u*)·cᵢ ≡ 0` and `(Σ δⱼ ġⱼ)·cᵢ ≡ 0` for each direction `δ`.
    pub fn certificates(&self) -> &[Certificate] {
        &self.certs
    }
}

fn t_poly<F: Scalar>(p: &MPoly<F>) -> Result<Poly<Rational>, NdimError> {
    let deg = p.degree_in(0).unwrap_or(0) as usize;
    let coeffs = (0..=deg)
        .map(|i| {
            let mut e = vec![0u32; p.nvars().max(1)];
            e[0] = i as u32;
            p.coeff(&e).to_rational().ok_or_else(|| {
                NdimError::InvalidInput("a coefficient is not a finite number".into())
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Poly::new(coeffs))
}

fn from_t_poly<F: Scalar>(p: &Poly<Rational>) -> MPoly<F> {
    p.coeffs()
        .iter()
        .enumerate()
        .fold(MPoly::zero(1), |acc, (i, c)| {
            &acc + &MPoly::monomial(1, &[i as u32], F::from_rational(c))
        })
}

/// Polynomials `(λ_a, λ_b, w)` in `t` with `|λ_a v_a + λ_b v_b|² ≡ w²`, `w ≢ 0` (module docs);
/// `Err(reason)` if the conic-point engine finds none over `Q`.
fn unit_pair<F: Scalar>(va: &[MPoly<F>], vb: &[MPoly<F>]) -> Result<[MPoly<F>; 3], String> {
    let (alpha, beta, gamma) = (dot(va, va), dot(va, vb), dot(vb, vb));
    let one = MPoly::constant(1, F::one());
    let zero = MPoly::zero(1);
    if let Some(s) = univariate_sqrt(&alpha).filter(|s| !s.is_zero()) {
        return Ok([one, zero, s]);
    }
    if let Some(s) = univariate_sqrt(&gamma).filter(|s| !s.is_zero()) {
        return Ok([zero, one, s]);
    }
    let delta = clean(&(&(&alpha * &gamma) - &(&beta * &beta)));
    if delta.is_zero() || alpha.is_zero() {
        return Err("the two normals are parallel".into());
    }
    let (l, m, n) = (
        Poly::constant(Rational::ONE),
        t_poly(&delta).map_err(|e| e.to_string())?,
        -t_poly(&alpha).map_err(|e| e.to_string())?,
    );
    match conic_point(&l, &m, &n) {
        Ok(ConicPoint::Rational([x, y, z])) if !z.is_zero() => {
            let (x, y, z): (MPoly<F>, MPoly<F>, MPoly<F>) =
                (from_t_poly(&x), from_t_poly(&y), from_t_poly(&z));
            Ok([&x - &(&beta * &y), &alpha * &y, &alpha * &z])
        }
        Ok(ConicPoint::Rational(_)) => Err("the conic point has w = 0".into()),
        Ok(ConicPoint::QuadraticField {
            radicand,
            obstruction,
            ..
        }) => Err(format!(
            "the conic X² + ΔY² − αZ² = 0 has a point only over Q(√{}): {obstruction}",
            format_scalar(&radicand)
        )),
        Ok(ConicPoint::NoPoint { obstruction, .. }) => Err(obstruction.to_string()),
        Err(e) => Err(e.to_string()),
    }
}

/// The coefficient vectors `(c₀, c₁, …, c_k)` of `z = c₀ + Σ uⱼcⱼ` (polynomials in `t`).
fn linear_parts<F: Scalar>(z: &[MPoly<F>], k: usize) -> Vec<Vec<MPoly<F>>> {
    (0..=k)
        .map(|j| {
            z.iter()
                .map(|c| {
                    c.terms()
                        .filter(|(e, _)| {
                            (1..=k).all(|i| e.get(i).copied().unwrap_or(0) == u32::from(i == j))
                        })
                        .fold(MPoly::zero(1), |acc, (e, co)| {
                            &acc + &MPoly::monomial(
                                1,
                                &[e.first().copied().unwrap_or(0)],
                                co.clone(),
                            )
                        })
                })
                .collect()
        })
        .collect()
}

/// `Σ ūⱼ cⱼ` for homogeneous parameters `ū = (ū₀, …, ū_k)`.
fn combine<F: Scalar>(parts: &[Vec<MPoly<F>>], ub: &[MPoly<F>]) -> Vec<MPoly<F>> {
    let n = parts[0].len();
    (0..n)
        .map(|i| {
            parts
                .iter()
                .zip(ub)
                .fold(MPoly::zero(0), |acc, (c, u)| &acc + &(&c[i] * u))
        })
        .collect()
}

impl<F: Scalar> RuledManifold<F> {
    /// The manifold `L(t)/w(t) + Σ uⱼ gⱼ(t)` in `Rⁿ` (`n = l.len()`), `1 ≤ k ≤ n − 2`
    /// generators (polynomials in `t` = variable 0).
    ///
    /// # Errors
    /// [`NdimError::InvalidInput`] for wrong lengths, `k` out of range, `w ≡ 0`, a
    /// dependence on other variables, or generators that are dependent for all `t`.
    pub fn new(l: Vec<MPoly<F>>, w: MPoly<F>, g: Vec<Vec<MPoly<F>>>) -> Result<Self, NdimError> {
        let n = l.len();
        let k = g.len();
        if n < 3 || k == 0 || k + 2 > n {
            return Err(NdimError::InvalidInput(format!(
                "a ruled (k+1)-manifold with offsets needs 1 ≤ k ≤ n − 2, got k = {k}, n = {n}"
            )));
        }
        if let Some(j) = g.iter().position(|v| v.len() != n) {
            return Err(NdimError::InvalidInput(format!(
                "generator g{} has {} coordinates, the directrix {n}",
                j + 1,
                g[j].len()
            )));
        }
        if w.is_zero() {
            return Err(NdimError::InvalidInput(
                "the directrix denominator w is zero".into(),
            ));
        }
        if !l
            .iter()
            .chain(g.iter().flatten())
            .chain(std::iter::once(&w))
            .all(only_var0)
        {
            return Err(NdimError::InvalidInput(
                "l(t) and gⱼ(t) must depend on t (variable 0) only".into(),
            ));
        }
        if rank(&g) < k {
            return Err(NdimError::InvalidInput(format!(
                "the {k} generators g₁…g_{k} are linearly dependent for all t (rank {})",
                rank(&g)
            )));
        }
        Ok(RuledManifold { l, w, g })
    }

    /// The ambient dimension `n`.
    pub fn dim(&self) -> usize {
        self.l.len()
    }

    /// The number `k` of generators.
    pub fn k(&self) -> usize {
        self.g.len()
    }

    fn gdot(&self) -> Vec<Vec<MPoly<F>>> {
        self.g
            .iter()
            .map(|v| v.iter().map(|c| c.partial(0)).collect())
            .collect()
    }

    /// `L'w − Lw'` (∝ `l̇`, over `w²`).
    fn ldot(&self) -> Vec<MPoly<F>> {
        let wd = self.w.partial(0);
        self.l
            .iter()
            .map(|c| &(&c.partial(0) * &self.w) - &(c * &wd))
            .collect()
    }

    /// `P_t = (L'w − Lw') + w² Σ uⱼ ġⱼ ∝ p_t`, in `t, u₁, …, u_k`.
    fn pt(&self) -> Vec<MPoly<F>> {
        let k = self.k();
        let w2 = &self.w * &self.w;
        let gd = self.gdot();
        self.ldot()
            .iter()
            .enumerate()
            .map(|(i, c)| {
                (0..k).fold(c.clone(), |acc, j| {
                    &acc + &(&(&w2 * &gd[j][i]) * &MPoly::var(k + 1, j + 1))
                })
            })
            .collect()
    }

    /// The components `cⱼ` of `ġⱼ` orthogonal to `G` (times the Gram determinant).
    fn orth_gdot(&self) -> Vec<Vec<MPoly<F>>> {
        let k = self.k();
        let gram: Vec<Vec<MPoly<F>>> = (0..k)
            .map(|a| (0..k).map(|b| dot(&self.g[a], &self.g[b])).collect())
            .collect();
        let det_g = super::poly::det(&gram);
        // adj(Gram)[a][b] = (−1)^{a+b} det(Gram without row b, column a)
        let adj = |a: usize, b: usize| {
            let m: Vec<Vec<MPoly<F>>> = (0..k)
                .filter(|&r| r != b)
                .map(|r| {
                    (0..k)
                        .filter(|&c| c != a)
                        .map(|c| gram[r][c].clone())
                        .collect()
                })
                .collect();
            let d = super::poly::det(&m);
            if (a + b).is_multiple_of(2) {
                d
            } else {
                -d
            }
        };
        let adjm: Vec<Vec<MPoly<F>>> = (0..k)
            .map(|a| (0..k).map(|b| adj(a, b)).collect())
            .collect();
        self.gdot()
            .iter()
            .map(|gd| {
                let gtg: Vec<MPoly<F>> = self.g.iter().map(|g| dot(g, gd)).collect();
                let coef: Vec<MPoly<F>> = (0..k).map(|a| dot(&adjm[a], &gtg)).collect();
                (0..self.dim())
                    .map(|i| {
                        let proj = (0..k)
                            .fold(MPoly::zero(1), |acc, a| &acc + &(&coef[a] * &self.g[a][i]));
                        clean(&(&(&det_g * &gd[i]) - &proj))
                    })
                    .collect()
            })
            .collect()
    }

    /// `A(t)`, `T(t)`, `m`, the case and the singular (Case 1) or central (Case 2) space
    /// (§5.4, Lemma 5.1; module docs).
    ///
    /// # Errors
    /// [`NdimError::Degenerate`] if every point is singular (`m = 0` in Case 1).
    pub fn structure(&self) -> Result<RuledStructure<F>, NdimError> {
        let k = self.k();
        let gd = self.gdot();
        let ld = self.ldot();
        let mut a_rows = self.g.clone();
        a_rows.extend(gd.iter().cloned());
        let dim_a = rank(&a_rows);
        let mut t_rows = a_rows.clone();
        t_rows.push(ld.clone());
        let dim_t = rank(&t_rows);
        let m = dim_a - k;
        let kind = if dim_t == dim_a {
            RuledKind::Singular
        } else {
            RuledKind::Central
        };
        if m == 0 && kind == RuledKind::Singular {
            return Err(NdimError::Degenerate(
                "every point is singular (l̇, ġⱼ ∈ span(g) for all t): the manifold is a k-plane"
                    .into(),
            ));
        }
        let c = self.orth_gdot();
        let mut sel: Vec<usize> = Vec::new();
        for j in 0..k {
            let mut rows: Vec<Vec<MPoly<F>>> = sel.iter().map(|&i| c[i].clone()).collect();
            rows.push(c[j].clone());
            if rank(&rows) == rows.len() {
                sel.push(j);
            }
        }
        let rest: Vec<usize> = (0..k).filter(|j| !sel.contains(j)).collect();
        let w2 = &self.w * &self.w;
        // Σ_{j∈sel} (cᵢ·ġⱼ) w² uⱼ = −cᵢ·l̇' − Σ_{r∈rest} (cᵢ·ġ_r) w² u_r
        let msel: Vec<Vec<MPoly<F>>> = sel
            .iter()
            .map(|&i| sel.iter().map(|&j| &dot(&c[i], &gd[j]) * &w2).collect())
            .collect();
        let dm = super::poly::det(&msel);
        let solve = |rhs: &[MPoly<F>]| -> Vec<MPoly<F>> {
            (0..sel.len())
                .map(|a| {
                    let mut mm = msel.clone();
                    for (r, row) in mm.iter_mut().enumerate() {
                        row[a] = rhs[r].clone();
                    }
                    super::poly::det(&mm)
                })
                .collect()
        };
        let rhs0: Vec<MPoly<F>> = sel.iter().map(|&i| -dot(&c[i], &ld)).collect();
        let x0 = solve(&rhs0);
        let mut params = vec![RatFn::constant(F::zero()); k];
        for (a, &j) in sel.iter().enumerate() {
            params[j] = RatFn::new(x0[a].clone(), dm.clone())?;
        }
        let directions: Vec<Vec<RatFn<F>>> = rest
            .iter()
            .map(|&r| {
                let rhs: Vec<MPoly<F>> =
                    sel.iter().map(|&i| -(&dot(&c[i], &gd[r]) * &w2)).collect();
                let x = solve(&rhs);
                let mut d = vec![RatFn::constant(F::zero()); k];
                d[r] = RatFn::constant(F::one());
                for (a, &j) in sel.iter().enumerate() {
                    d[j] = RatFn {
                        num: x[a].clone(),
                        den: dm.clone(),
                    };
                }
                d
            })
            .collect();
        let point: Vec<RatFn<F>> = (0..self.dim())
            .map(|i| {
                (0..k).fold(
                    RatFn {
                        num: self.l[i].clone(),
                        den: self.w.clone(),
                    },
                    |acc, j| acc.add(&params[j].mul(&RatFn::poly(self.g[j][i].clone()))),
                )
            })
            .collect();
        // certificates: cᵢ·p_t(u*) ≡ 0 and cᵢ·(Σ δⱼ ġⱼ) ≡ 0
        let mut certs = Vec::new();
        let name = match kind {
            RuledKind::Singular => "singular",
            RuledKind::Central => "central",
        };
        for &i in &sel {
            // cᵢ·(l̇' + w² Σ u*ⱼ ġⱼ) with u*ⱼ = x/dm: dm·cᵢ·l̇' + w² Σ xⱼ cᵢ·ġⱼ
            let mut r = &dm * &dot(&c[i], &ld);
            // f64 tolerance: the size of the terms before cancellation
            let mut scale = mag(&dm) * dot_scale(&c[i], &ld);
            for (a, &j) in sel.iter().enumerate() {
                r = &r + &(&(&x0[a] * &w2) * &dot(&c[i], &gd[j]));
                scale += mag(&x0[a]) * mag(&w2) * dot_scale(&c[i], &gd[j]);
            }
            let dscale = mag(&dm) * (0..k).map(|j| dot_scale(&c[i], &gd[j])).sum::<f64>();
            out_cert(
                &mut certs,
                scale,
                &format!(
                    "{name} space (Lemma 5.1): p_t(s)·c{} ≡ 0 (p_t ∈ span(g) resp. span(a, g))",
                    i + 1
                ),
                &r,
            );
            for (dn, d) in directions.iter().enumerate() {
                let r = rest_term(d, &c[i], &gd, &rest, &dm);
                let dir_scale = dscale * d.iter().map(|x| mag(&x.num)).fold(1.0, f64::max);
                out_cert(
                    &mut certs,
                    dir_scale,
                    &format!(
                        "{name} space: direction {} stays in it ((Σ δⱼ ġⱼ)·c{} ≡ 0)",
                        dn + 1,
                        i + 1
                    ),
                    &r,
                );
            }
        }
        Ok(RuledStructure {
            dim_a,
            dim_t,
            m,
            kind,
            params,
            point,
            directions,
            certs,
        })
    }
}

/// `dm·Σⱼ δⱼ (cᵢ·ġⱼ)` for a direction whose selected entries are `x/dm` and free entry 1.
fn rest_term<F: Scalar>(
    d: &[RatFn<F>],
    ci: &[MPoly<F>],
    gd: &[Vec<MPoly<F>>],
    rest: &[usize],
    dm: &MPoly<F>,
) -> MPoly<F> {
    let mut r = MPoly::zero(1);
    for (j, dj) in d.iter().enumerate() {
        let cg = dot(ci, &gd[j]);
        if rest.contains(&j) {
            r = &r + &(&(&dj.num * dm) * &cg);
        } else {
            r = &r + &(&dj.num * &cg);
        }
    }
    r
}

fn out_cert<F: Scalar>(certs: &mut Vec<Certificate>, scale: f64, name: &str, r: &MPoly<F>) {
    certs.push(zero_cert(name, r, scale.max(1.0)));
}

/// All `k`-subsets of `0..n`, in lexicographic order.
fn subsets(n: usize, k: usize) -> Vec<Vec<usize>> {
    if k == 0 {
        return vec![Vec::new()];
    }
    if n < k {
        return Vec::new();
    }
    let mut out = subsets(n - 1, k);
    for mut s in subsets(n - 1, k - 1) {
        s.push(n - 1);
        out.push(s);
    }
    out.sort();
    out
}

/// The unit normal of Steps 1–2: `(ū(s), M numerators, M denominator, normal basis)`.
type UnitNormal<F> = (Vec<MPoly<F>>, Vec<MPoly<F>>, MPoly<F>, Vec<Vec<MPoly<F>>>);

impl<F: Scalar> RuledManifold<F> {
    /// A polynomial basis `b₁, …, b_{n−k}` of `G(t)^⊥` (generalized cross products).
    fn perp_basis(&self) -> Result<Vec<Vec<MPoly<F>>>, NdimError> {
        let (n, k) = (self.dim(), self.k());
        let pivots = subsets(n, k)
            .into_iter()
            .find(|cols| {
                let m: Vec<Vec<MPoly<F>>> = self
                    .g
                    .iter()
                    .map(|v| cols.iter().map(|&c| v[c].clone()).collect())
                    .collect();
                !clean(&super::poly::det(&m)).is_zero()
            })
            .ok_or_else(|| NdimError::Degenerate("the generators are dependent".into()))?;
        let free: Vec<usize> = (0..n).filter(|c| !pivots.contains(c)).collect();
        Ok(free
            .iter()
            .map(|&f| {
                let mut rows = self.g.clone();
                for &q in free.iter().filter(|&&q| q != f) {
                    let mut e = vec![MPoly::zero(1); n];
                    e[q] = MPoly::constant(1, F::one());
                    rows.push(e);
                }
                cross(&rows).iter().map(clean).collect()
            })
            .collect())
    }

    /// Steps 1–2: a rational unit normal on a reparametrization of the generators.
    fn unit_normal(&self, zs: &[Vec<MPoly<F>>]) -> Result<UnitNormal<F>, NdimError> {
        let (n, k) = (self.dim(), self.k());
        let nv = n - 1;
        let lift = |p: &MPoly<F>| &MPoly::zero(nv) + p;
        let delta: Vec<MPoly<F>> = (0..=k)
            .map(|j| {
                if j == 0 {
                    MPoly::constant(nv, F::one())
                } else {
                    MPoly::var(nv, j)
                }
            })
            .collect();
        let all_parts: Vec<Vec<Vec<MPoly<F>>>> = zs.iter().map(|z| linear_parts(z, k)).collect();
        let mut choices: Vec<Vec<Vec<MPoly<F>>>> = all_parts.clone();
        for p in all_parts.iter().skip(1) {
            choices.push(
                all_parts[0]
                    .iter()
                    .zip(p)
                    .map(|(a, b)| a.iter().zip(b).map(|(x, y)| x + y).collect())
                    .collect(),
            );
        }
        let mut reasons = Vec::new();
        let mut u_dependent = false;
        for parts in &choices {
            for a in 0..=k {
                for b in a + 1..=k {
                    let delta_ab = clean(
                        &(&(&dot(&parts[a], &parts[a]) * &dot(&parts[b], &parts[b]))
                            - &dot(&parts[a], &parts[b]).pow(2)),
                    );
                    if delta_ab.is_zero() {
                        continue;
                    }
                    u_dependent = true;
                    let [la, lb, ws] = match unit_pair(&parts[a], &parts[b]) {
                        Ok(x) => x,
                        Err(r) => {
                            reasons.push(format!("coordinates ū{a}, ū{b}: {r}"));
                            continue;
                        }
                    };
                    let mut ustar = vec![MPoly::zero(nv); k + 1];
                    ustar[a] = lift(&la);
                    ustar[b] = lift(&lb);
                    let lparts: Vec<Vec<MPoly<F>>> =
                        parts.iter().map(|c| c.iter().map(lift).collect()).collect();
                    let zp = combine(&lparts, &ustar);
                    let zd = combine(&lparts, &delta);
                    let q = dot(&zd, &zd);
                    let bb = dot(&zp, &zd).scale(&F::from_i64(2));
                    let ub: Vec<MPoly<F>> = (0..=k)
                        .map(|j| clean(&(&(&q * &ustar[j]) - &(&bb * &delta[j]))))
                        .collect();
                    if ub[0].is_zero() {
                        reasons.push(format!(
                            "coordinates ū{a}, ū{b}: ū₀ ≡ 0 after the projection"
                        ));
                        continue;
                    }
                    let mn: Vec<MPoly<F>> = (0..n)
                        .map(|i| clean(&(&(&q * &zp[i]) - &(&bb * &zd[i]))))
                        .collect();
                    let mw = &q * &lift(&ws);
                    let basis: Vec<Vec<MPoly<F>>> = all_parts
                        .iter()
                        .map(|p| {
                            let lp: Vec<Vec<MPoly<F>>> =
                                p.iter().map(|c| c.iter().map(lift).collect()).collect();
                            combine(&lp, &ub)
                        })
                        .collect();
                    return Ok((ub, mn, mw, basis));
                }
            }
        }
        if u_dependent {
            return Err(NdimError::NoRationalPoint(format!(
                "no polynomial point on the quadric family |z(ū)|² = w² (5.25) over Q on any coordinate plane: {}",
                reasons.join("; ")
            )));
        }
        // the normal space N(t) does not depend on u: combine constant directions (5.27)
        let dirs: Vec<Vec<MPoly<F>>> = all_parts
            .iter()
            .filter_map(|p| {
                p.iter()
                    .find(|c| c.iter().any(|x| !clean(x).is_zero()))
                    .cloned()
            })
            .collect();
        let ub = delta.clone();
        let basis: Vec<Vec<MPoly<F>>> = dirs.iter().map(|d| d.iter().map(lift).collect()).collect();
        if dirs.len() == 1 {
            let len2 = dot(&dirs[0], &dirs[0]);
            return match univariate_sqrt(&len2) {
                Some(s) if !s.is_zero() => Ok((ub, basis[0].clone(), lift(&s), basis)),
                _ => Err(NdimError::NotRational(format!(
                    "the normal is constant along the generators and dim N = 1 (Theorem 5.2's excluded case: Case 1 with m = 1 or Case 2 with m = 0), and |N|² = {} is not a square in Q[t]",
                    t_poly(&len2).map(|p| rcagd_algebra::format_poly(&p, "t")).unwrap_or_default()
                ))),
            };
        }
        for a in 0..dirs.len() {
            for b in a + 1..dirs.len() {
                match unit_pair(&dirs[a], &dirs[b]) {
                    Ok([la, lb, ws]) => {
                        let mn: Vec<MPoly<F>> = (0..n)
                            .map(|i| lift(&(&(&la * &dirs[a][i]) + &(&lb * &dirs[b][i]))))
                            .collect();
                        return Ok((ub, mn, lift(&ws), basis));
                    }
                    Err(r) => reasons.push(format!("normals {a}, {b}: {r}")),
                }
            }
        }
        Err(NdimError::NoRationalPoint(format!(
            "no polynomial point on the quadric (5.28) over Q on any coordinate plane: {}",
            reasons.join("; ")
        )))
    }

    /// The offset hypersurface at distance `d` (Theorem 5.2, Steps 1–3, (5.26)): a rational
    /// map of the `n − 1` parameters `(t, s₁, …, s_k, v₁, …, v_{n−k−2})` (module docs).
    ///
    /// # Errors
    /// [`NdimError::Degenerate`] if every point is singular; [`NdimError::NotRational`] in
    /// the excluded case of Theorem 5.2 without a rational normal length;
    /// [`NdimError::NoRationalPoint`] if the conic-point engine finds no point over `Q`.
    pub fn offset(&self, d: F) -> Result<RuledOffset<F>, NdimError> {
        let (n, k) = (self.dim(), self.k());
        let nv = n - 1;
        let lift = |p: &MPoly<F>| &MPoly::zero(nv) + p;
        let b = self.perp_basis()?;
        let pt = self.pt();
        let dots: Vec<MPoly<F>> = b.iter().map(|bi| clean(&dot(bi, &pt))).collect();
        let first = dots.iter().position(|x| !x.is_zero()).ok_or_else(|| {
            NdimError::Degenerate("p_t ∈ span(g) everywhere: every point is singular".into())
        })?;
        let zs: Vec<Vec<MPoly<F>>> = (0..b.len())
            .filter(|&i| i != first)
            .map(|i| {
                (0..n)
                    .map(|c| clean(&(&(&dots[first] * &b[i][c]) - &(&dots[i] * &b[first][c]))))
                    .collect()
            })
            .collect();
        let (ub, mn, mw, basis) = self.unit_normal(&zs)?;
        let (w, w2) = (lift(&self.w), lift(&(&self.w * &self.w)));
        let gd = self.gdot();
        let ld = self.ldot();
        let pn: Vec<MPoly<F>> = (0..n)
            .map(|i| {
                (0..k).fold(&lift(&self.l[i]) * &ub[0], |acc, j| {
                    &acc + &(&(&w * &ub[j + 1]) * &lift(&self.g[j][i]))
                })
            })
            .collect();
        let pd = &w * &ub[0];
        let t0: Vec<MPoly<F>> = (0..n)
            .map(|i| {
                (0..k).fold(&lift(&ld[i]) * &ub[0], |acc, j| {
                    &acc + &(&(&w2 * &ub[j + 1]) * &lift(&gd[j][i]))
                })
            })
            .collect();
        let mut tangent = vec![t0];
        tangent.extend(self.g.iter().map(|v| v.iter().map(lift).collect()));
        let dim_n = n - k - 1;
        let (y, den) = if dim_n >= 2 {
            let last = basis.len() - 1;
            let cvec: Vec<MPoly<F>> = (0..n)
                .map(|i| {
                    basis
                        .iter()
                        .enumerate()
                        .fold(MPoly::zero(nv), |acc, (j, z)| {
                            let coef = if j == last {
                                MPoly::constant(nv, F::one())
                            } else {
                                MPoly::var(nv, k + 1 + j)
                            };
                            &acc + &(&coef * &z[i])
                        })
                })
                .collect();
            let cc = dot(&cvec, &cvec);
            let mc = dot(&mn, &cvec).scale(&(F::from_i64(2) * d.clone()));
            let y: Vec<MPoly<F>> = (0..n)
                .map(|i| {
                    let a = &(&pn[i] * &mw) * &cc;
                    let bterm = (&(&mn[i] * &pd) * &cc).scale(&d);
                    let c = &(&mc * &cvec[i]) * &pd;
                    &(&a + &bterm) - &c
                })
                .collect();
            (y, &(&pd * &mw) * &cc)
        } else {
            let y: Vec<MPoly<F>> = (0..n)
                .map(|i| &(&pn[i] * &mw) + &(&mn[i] * &pd).scale(&d))
                .collect();
            (y, &pd * &mw)
        };
        let reparam = (0..k)
            .map(|j| RatFn {
                num: ub[j + 1].clone(),
                den: ub[0].clone(),
            })
            .collect();
        Ok(RuledOffset {
            distance: d,
            point: (pn, pd),
            normal: (mn, mw),
            tangent,
            offset: (y, den),
            reparam,
        })
    }
}

/// The offset hypersurface of a ruled `(k+1)`-manifold (Theorem 5.2, (5.26)).
#[derive(Debug, Clone)]
pub struct RuledOffset<F> {
    distance: F,
    point: (Vec<MPoly<F>>, MPoly<F>),
    normal: (Vec<MPoly<F>>, MPoly<F>),
    tangent: Vec<Vec<MPoly<F>>>,
    offset: (Vec<MPoly<F>>, MPoly<F>),
    reparam: Vec<RatFn<F>>,
}

impl<F: Scalar> RuledOffset<F> {
    /// The offset distance.
    pub fn distance(&self) -> &F {
        &self.distance
    }

    /// The homogeneous offset map `(D, Y₁, …, Yₙ)`, `y = Y/D`, in `(t, s, v)`.
    pub fn homogeneous(&self) -> Vec<MPoly<F>> {
        let mut v = vec![self.offset.1.clone()];
        v.extend(self.offset.0.iter().cloned());
        v
    }

    /// The reparametrization `uⱼ = uⱼ(t, s)` of the generators (Step 2; `uⱼ = sⱼ` where the
    /// normal does not depend on `u`).
    pub fn reparametrization(&self) -> &[RatFn<F>] {
        &self.reparam
    }

    /// The rational unit normal `M = (M₁, …, Mₙ)/M₀` at the manifold point `p(t, s)`.
    pub fn unit_normal(&self) -> Vec<RatFn<F>> {
        self.normal
            .0
            .iter()
            .map(|c| RatFn {
                num: c.clone(),
                den: self.normal.1.clone(),
            })
            .collect()
    }

    /// The offset point at the parameters (`None` where a denominator vanishes).
    pub fn eval(&self, x: &[F]) -> Option<Vec<F>> {
        let inv = crate::pn::poly::pad_eval(&self.offset.1, x)?.inv()?;
        self.offset
            .0
            .iter()
            .map(|p| crate::pn::poly::pad_eval(p, x).map(|v| v * inv.clone()))
            .collect()
    }

    /// The manifold point `p(t, s)` (`None` where a denominator vanishes).
    pub fn eval_base(&self, x: &[F]) -> Option<Vec<F>> {
        let inv = crate::pn::poly::pad_eval(&self.point.1, x)?.inv()?;
        self.point
            .0
            .iter()
            .map(|p| crate::pn::poly::pad_eval(p, x).map(|v| v * inv.clone()))
            .collect()
    }

    /// A parameter slice projected onto three coordinates, as a patch (see
    /// [`super::PnHypersurface::projected_slice`]).
    ///
    /// # Errors
    /// As [`super::PnHypersurface::projected_slice`].
    pub fn projected_slice(
        &self,
        free: [usize; 2],
        fixed: &[F],
        coords: [usize; 3],
        domain: &Domain<F>,
    ) -> Result<BezierPatch<F>, NdimError> {
        super::hypersurface::slice_patch(&self.homogeneous(), free, fixed, coords, domain)
    }
}

impl<F: Scalar> Certified for RuledOffset<F> {
    /// `|M|² ≡ 1`, `M ⟂ τ(p)`, `|y − p|² ≡ d²` and `y − p ⟂ τ(p)` ((5.18), (5.19)), as
    /// polynomial identities in all parameters.
    fn certify(&self) -> Vec<Certificate> {
        let (mn, mw) = &self.normal;
        let (pn, pd) = &self.point;
        let (y, den) = &self.offset;
        let mut out = Vec::new();
        let unit = &dot(mn, mn) - &(mw * mw);
        out.push(zero_cert(
            "rational unit normal (5.25): |M|² ≡ 1",
            &unit,
            dot_scale(mn, mn) + dot_scale(std::slice::from_ref(mw), std::slice::from_ref(mw)),
        ));
        let names = |j: usize| {
            if j == 0 {
                "p_t".to_string()
            } else {
                format!("g{j}")
            }
        };
        for (j, tv) in self.tangent.iter().enumerate() {
            let r = dot(mn, tv);
            out.push(zero_cert(
                &format!("unit normal ⟂ tangent space: M·{} ≡ 0", names(j)),
                &r,
                dot_scale(mn, tv),
            ));
        }
        // y − p = (Y pd − P den)/(den pd)
        let diff: Vec<MPoly<F>> = (0..pn.len())
            .map(|i| &(&y[i] * pd) - &(&pn[i] * den))
            .collect();
        let dp = den * pd;
        let r = &dot(&diff, &diff)
            - &(&dp * &dp).scale(&(self.distance.clone() * self.distance.clone()));
        out.push(zero_cert(
            &format!(
                "offset (5.19): |y − p|² ≡ d² = {}",
                format_scalar(&(self.distance.clone() * self.distance.clone()))
            ),
            &r,
            dot_scale(&diff, &diff)
                + dot_scale(std::slice::from_ref(&dp), std::slice::from_ref(&dp)),
        ));
        for (j, tv) in self.tangent.iter().enumerate() {
            let r = dot(&diff, tv);
            out.push(zero_cert(
                &format!(
                    "offset (5.19): (y − p)·{} ≡ 0 (y in the normal space)",
                    names(j)
                ),
                &r,
                dot_scale(&diff, tv),
            ));
        }
        out
    }
}
