//! Rational one-parameter families of quadrics in `Pⁿ` (M. Peternell, "Rational
//! Parametrizations for Envelopes of Quadric Families", §5.1: Cor. 5.1 and Prop. 5.1;
//! derivation in `docs/math/conic-surfaces.md`, section "Families of quadrics in Pⁿ").
//!
//! **Input.** A symmetric `(n+1)×(n+1)` polynomial matrix `Q(t)`, `n ≥ 2`: the quadric
//! `Q(t): xᵀQ(t)x = 0` of `Pⁿ` for every `t`.
//!
//! **A rational point (Cor. 5.1).** A fraction-free congruence `E·Q·Eᵀ = diag(β₀, …, βₙ)`
//! over `Q[t]` gives the normal form (5.1) (rows `vᵢ` of `E`: `vᵢᵀQvⱼ = 0` for `i ≠ j`,
//! `vᵢᵀQvᵢ = βᵢ`). The plane spanned by three rows with `βᵢ, βⱼ, βₖ ≢ 0` cuts `Q(t)` in the
//! conic `β_i X² + β_j Y² + β_k Z² = 0` (5.2); the complete conic-point engine
//! ([`rcagd_algebra::conic_point`], Thm 1.1) finds a polynomial point `(X, Y, Z)` on it or
//! proves that none exists, and `f = X·vᵢ + Y·vⱼ + Z·vₖ` lies on `Q(t)` for every `t`. For
//! `n ≥ 3` further planes are tried: the third spanning vector `a·vₖ + b·vₗ` with small
//! integers `a, b` (conic `βᵢX² + βⱼY² + (a²βₖ + b²βₗ)Z² = 0`). A point of a regular plane
//! section is a regular point of `Q(t)` (if `Q·f ≡ 0` the restricted conic would be
//! singular at `f`).
//!
//! **The parametrization (Prop. 5.1).** The stereographic projection from `f(t)`
//! ((1.28)–(1.32) in `n` dimensions): with `x_k = 0` a coordinate hyperplane missing `f`
//! (`f_k ≢ 0`) and its affine chart `q(u) = e_{j₀} + u₁e_{j₁} + … + u_{n−1}e_{j_{n−1}}`,
//! the line `f ∨ q(u)` meets `Q(t)` again in
//!
//! ```text
//! g(t, u) = (qᵀQq)·f − 2(fᵀQq)·q                 (λf + μq with λ = qᵀQq, μ = −2fᵀQq),
//! ```
//!
//! of degree 2 in `u`, because `fᵀQf ≡ 0`; for `Q = diag(1, …, 1, −1, …, −1)` and the pole
//! `f = (1, 0, …, 0, 1)` this is (1.32). **Certificates:** `fᵀQf ≡ 0`, `Q·f ≢ 0` (a regular
//! point), `g(t, u)ᵀ·Q(t)·g(t, u) ≡ 0` and total degree 2 in `u`.
//!
//! **No point.** If `Q(t₀)` is definite at a rational `t₀`, no real point exists there and
//! no polynomial point can exist ([`QuadricFamilyError::NoRealPoints`], a proof: a
//! primitive point does not vanish at `t₀`). For a family of rank 3 (a conic family,
//! `n = 2`, or cones over one) the engine's obstruction is a proof: every regular point
//! projects onto the section conic ([`QuadricFamilyError::NoRationalPoint`]). For rank ≥ 4
//! a failing plane section does not prove that the quadric has no point: the error
//! ([`QuadricFamilyError::NoPointFound`]) names every plane tried and its obstruction.

use super::{point_patch, positive_pieces, ConicSurfaceError, P, Q};
use crate::Certified;
use rcagd_algebra::bernstein::to_bernstein;
use rcagd_algebra::conic_point::{
    conic_point, rational_conic_point, sqrt_mod_irreducible, ConicPoint, ConicPointError,
    Obstruction, TernaryOutcome,
};
use rcagd_algebra::linalg::Matrix;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{format_poly, Certificate, Poly};
use rcagd_geom::{BezierCurve, BezierPatch};
use thiserror::Error;

/// Errors of the quadric-family constructions.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum QuadricFamilyError {
    /// The matrix is not square or has fewer than three rows.
    #[error("Q(t) must be a square matrix of size n + 1 ≥ 3 (a quadric of Pⁿ, n ≥ 2): {0}")]
    Shape(String),
    /// `Q(t)` is not symmetric.
    #[error("Q(t) is not symmetric: entries ({0}, {1}) and ({1}, {0}) differ")]
    NotSymmetric(usize, usize),
    /// Rank ≤ 2 over `Q(t)`: every quadric is a pair of hyperplanes (or one, or all of
    /// `Pⁿ`), excluded by Peternell's assumption 2 of §5.1.
    #[error(
        "Q(t) has rank {0} over Q(t): the quadrics consist of hyperplanes (§5.1 needs rank ≥ 3)"
    )]
    Rank(usize),
    /// `Q(t₀)` is definite: the quadric has no real point there, so no polynomial point
    /// exists (a primitive point does not vanish at `t₀`).
    #[error("Q(t) is {sign} definite at t = {t}: the quadric has no real point there, so the family has no rational point")]
    NoRealPoints {
        /// The parameter.
        t: Q,
        /// `"positive"` or `"negative"`.
        sign: &'static str,
    },
    /// A family of rank 3 (a conic family, `n = 2`, or cones over a conic family) without a
    /// regular polynomial point over `Q`: the engine's proof.
    #[error("no rational point on the conic family: {0}")]
    NoRationalPoint(String),
    /// `n ≥ 3`: no plane section tried has a point over `Q` (not a proof for the
    /// quadric itself): the planes and their obstructions.
    #[error("no rational point found on the {} plane sections tried (this is no proof for n ≥ 3): {}", .0.len(), .0.join("; "))]
    NoPointFound(Vec<String>),
    /// The conic-point engine could not decide.
    #[error(transparent)]
    Engine(#[from] ConicPointError),
    /// A step degenerates identically (named).
    #[error("degenerate: {0}")]
    Degenerate(String),
    /// The picture cannot be built on the given parameters (a point at infinity, an
    /// empty rectangle).
    #[error("picture: {0}")]
    Patch(String),
}

impl From<QuadricFamilyError> for ConicSurfaceError {
    fn from(e: QuadricFamilyError) -> Self {
        match e {
            QuadricFamilyError::Engine(e) => ConicSurfaceError::Engine(e),
            QuadricFamilyError::NoRationalPoint(s) => ConicSurfaceError::NoRationalPoint(s),
            other => ConicSurfaceError::Degenerate(other.to_string()),
        }
    }
}

type Mat = Vec<Vec<P>>;
/// A plane candidate `(i, j, third)`: spanned by `vᵢ`, `vⱼ` and `Σ a·v_k` over `third`.
type Plane = (usize, usize, Vec<(usize, i64)>);

fn pz() -> P {
    Poly::zero()
}

/// Divides a polynomial vector by the monic gcd of its entries.
fn primitive(mut v: Vec<P>) -> Vec<P> {
    super::make_primitive(&mut v);
    v
}

fn form(m: &Mat, a: &[P], b: &[P]) -> P {
    let mut s = pz();
    for (i, ai) in a.iter().enumerate() {
        if ai.is_zero() {
            continue;
        }
        for (j, bj) in b.iter().enumerate() {
            if !m[i][j].is_zero() && !bj.is_zero() {
                s = &s + &(&(ai * &m[i][j]) * bj);
            }
        }
    }
    s
}

/// A fraction-free congruence `E·M·Eᵀ = diag(β)` of a symmetric polynomial matrix
/// (symmetric elimination; a zero pivot is replaced by a row with a non-zero diagonal, or
/// by `eᵢ + eⱼ`; a pivot whose row vanishes in the remaining block gives `β = 0`).
pub(crate) fn diagonalize(m: &Mat) -> (Vec<P>, Mat) {
    let n = m.len();
    let one = Poly::constant(Q::ONE);
    let mut e: Mat = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| if i == j { one.clone() } else { pz() })
                .collect()
        })
        .collect();
    let congr = |e: &Mat, i: usize, j: usize| form(m, &e[i], &e[j]);
    for piv in 0..n {
        if congr(&e, piv, piv).is_zero() {
            if let Some(j) = (piv + 1..n).find(|&j| !congr(&e, j, j).is_zero()) {
                e.swap(piv, j);
            } else if let Some(j) = (piv + 1..n).find(|&j| !congr(&e, piv, j).is_zero()) {
                let rj = e[j].clone();
                for (a, x) in e[piv].iter_mut().enumerate() {
                    *x = &*x + &rj[a];
                }
            } else {
                continue;
            }
        }
        let a = congr(&e, piv, piv);
        for i in piv + 1..n {
            let b = congr(&e, i, piv);
            if b.is_zero() {
                continue;
            }
            let rp = e[piv].clone();
            let row: Vec<P> = e[i]
                .iter()
                .zip(&rp)
                .map(|(x, y)| &(&a * x) - &(&b * y))
                .collect();
            e[i] = primitive(row);
        }
    }
    let diag = (0..n).map(|i| congr(&e, i, i)).collect();
    (diag, e)
}

/// `±1` if the rational symmetric matrix is positive / negative definite (Sylvester's
/// criterion on the leading principal minors), else `0`.
fn definiteness(m: &Matrix<Q>, n: usize) -> i32 {
    let mut pos = true;
    let mut neg = true;
    for k in 1..=n {
        let sub = Matrix::from_fn(k, k, |i, j| m.get(i, j).cloned().unwrap_or(Q::ZERO));
        let d = sub.determinant().unwrap_or(Q::ZERO);
        if d <= Q::ZERO {
            pos = false;
        }
        let want_neg = if k % 2 == 1 { d < Q::ZERO } else { d > Q::ZERO };
        if !want_neg {
            neg = false;
        }
    }
    if pos {
        1
    } else if neg {
        -1
    } else {
        0
    }
}

/// A rational one-parameter family of quadrics `xᵀQ(t)x = 0` in `Pⁿ` (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct QuadricFamily {
    q: Mat,
}

/// A polynomial point `f(t)` on every quadric of the family (Cor. 5.1), with the plane
/// section it was found on.
#[derive(Debug, Clone, PartialEq)]
pub struct FamilyPoint {
    /// `f(t)`, primitive.
    pub point: Vec<P>,
    /// The three vectors spanning the plane of the section (rows of `E` or combinations).
    pub plane: [Vec<P>; 3],
    /// The diagonal conic `(L, M, N)` of the section, `X²L + Y²M + Z²N = 0`.
    pub conic: [P; 3],
    /// The engine's point `(X, Y, Z)` on it.
    pub conic_point: [P; 3],
}

impl QuadricFamily {
    /// The family of the symmetric polynomial matrix `Q(t)` (size `n + 1 ≥ 3`).
    ///
    /// # Errors
    /// [`QuadricFamilyError::Shape`], [`QuadricFamilyError::NotSymmetric`],
    /// [`QuadricFamilyError::Rank`] (rank ≤ 2 over `Q(t)`).
    pub fn new(q: Vec<Vec<P>>) -> Result<Self, QuadricFamilyError> {
        let n = q.len();
        if n < 3 {
            return Err(QuadricFamilyError::Shape(format!("{n} rows")));
        }
        if let Some(r) = q.iter().position(|r| r.len() != n) {
            return Err(QuadricFamilyError::Shape(format!(
                "row {r} has {} entries, not {n}",
                q[r].len()
            )));
        }
        for i in 0..n {
            for j in i + 1..n {
                if q[i][j] != q[j][i] {
                    return Err(QuadricFamilyError::NotSymmetric(i, j));
                }
            }
        }
        let fam = QuadricFamily { q };
        let r = fam.rank();
        if r < 3 {
            return Err(QuadricFamilyError::Rank(r));
        }
        Ok(fam)
    }

    /// `Q(t)`.
    pub fn matrix(&self) -> &[Vec<P>] {
        &self.q
    }

    /// `n` (the quadrics lie in `Pⁿ`).
    pub fn dim(&self) -> usize {
        self.q.len() - 1
    }

    /// The rank over `Q(t)`: the number of non-zero `βᵢ` of the congruence (module docs).
    pub fn rank(&self) -> usize {
        diagonalize(&self.q)
            .0
            .iter()
            .filter(|b| !b.is_zero())
            .count()
    }

    /// The normal form (5.1): `(β, E)` with `E·Q·Eᵀ = diag(β)`.
    pub fn normal_form(&self) -> (Vec<P>, Vec<Vec<P>>) {
        diagonalize(&self.q)
    }

    /// `Q(t₀)`.
    pub fn at(&self, t0: &Q) -> Matrix<Q> {
        let n = self.q.len();
        Matrix::from_fn(n, n, |i, j| self.q[i][j].eval(t0))
    }

    /// A rational `t₀` where `Q(t₀)` is definite (no real point), searched among
    /// `0, ±1/2, ±1, …, ±8` and between the real roots' integer parts (a proof when found).
    pub fn definite_at(&self) -> Option<(Q, i32)> {
        let n = self.q.len();
        let mut ts: Vec<Q> = vec![Q::ZERO];
        for k in 1..=16i64 {
            ts.push(Q::from_parts(k.into(), 2u8.into()));
            ts.push(Q::from_parts((-k).into(), 2u8.into()));
        }
        ts.into_iter().find_map(|t| {
            let s = definiteness(&self.at(&t), n);
            (s != 0).then_some((t, s))
        })
    }

    /// Cor. 5.1: a polynomial point `f(t)` with `fᵀQf ≡ 0` on a regular plane section
    /// (module docs).
    ///
    /// # Errors
    /// [`QuadricFamilyError::NoRealPoints`] (a proof), [`QuadricFamilyError::NoRationalPoint`]
    /// (`n = 2`, the engine's proof), [`QuadricFamilyError::NoPointFound`] (`n ≥ 3`, the
    /// planes tried), [`QuadricFamilyError::Engine`] (undecided).
    pub fn rational_point(&self) -> Result<FamilyPoint, QuadricFamilyError> {
        if let Some((t, s)) = self.definite_at() {
            return Err(QuadricFamilyError::NoRealPoints {
                t,
                sign: if s > 0 { "positive" } else { "negative" },
            });
        }
        let (beta, e) = diagonalize(&self.q);
        let nz: Vec<usize> = (0..beta.len()).filter(|&i| !beta[i].is_zero()).collect();
        let mut tried = Vec::new();
        // candidate planes: (i, j, [(k, a), (l, b)]) with third vector a·v_k + b·v_l
        let mut cands: Vec<Plane> = Vec::new();
        for (x, &i) in nz.iter().enumerate() {
            for (y, &j) in nz.iter().enumerate().skip(x + 1) {
                for &k in nz.iter().skip(y + 1) {
                    cands.push((i, j, vec![(k, 1)]));
                }
            }
        }
        for (x, &i) in nz.iter().enumerate() {
            for &j in nz.iter().skip(x + 1) {
                let rest: Vec<usize> = nz.iter().copied().filter(|&k| k != i && k != j).collect();
                for (z, &k) in rest.iter().enumerate() {
                    for &l in rest.iter().skip(z + 1) {
                        for (a, b) in [(1, 1), (1, 2), (2, 1), (1, 3), (3, 1), (2, 3), (3, 2)] {
                            cands.push((i, j, vec![(k, a), (l, b)]));
                        }
                    }
                }
            }
        }
        for (i, j, third) in cands {
            let n1 = e[0].len();
            let mut w: Vec<P> = vec![pz(); n1];
            let mut bw = pz();
            for &(k, a) in &third {
                let a = Q::from(a);
                for (c, x) in w.iter_mut().enumerate() {
                    *x = &*x + &e[k][c].scale(&a);
                }
                bw = &bw + &beta[k].scale(&(&a * &a));
            }
            if bw.is_zero() {
                continue;
            }
            let conic = [beta[i].clone(), beta[j].clone(), bw];
            let label = || {
                let third: Vec<String> = third
                    .iter()
                    .map(|(k, a)| {
                        if *a == 1 {
                            format!("v{k}")
                        } else {
                            format!("{a}·v{k}")
                        }
                    })
                    .collect();
                format!("plane (v{i}, v{j}, {})", third.join(" + "))
            };
            match conic_point(&conic[0], &conic[1], &conic[2])? {
                ConicPoint::Rational(pt) => {
                    let point: Vec<P> = (0..n1)
                        .map(|c| {
                            &(&(&pt[0] * &e[i][c]) + &(&pt[1] * &e[j][c])) + &(&pt[2] * &w[c])
                        })
                        .collect();
                    if point.iter().all(|x| x.is_zero()) {
                        tried.push(format!("{}: the point vanishes", label()));
                        continue;
                    }
                    return Ok(FamilyPoint {
                        point: primitive(point),
                        plane: [e[i].clone(), e[j].clone(), w],
                        conic,
                        conic_point: pt,
                    });
                }
                ConicPoint::QuadraticField {
                    radicand,
                    obstruction,
                    ..
                } => tried.push(format!(
                    "{} with the conic ({}, {}, {}): {obstruction} (a point exists over Q(√{radicand}))",
                    label(),
                    format_poly(&conic[0], "t"),
                    format_poly(&conic[1], "t"),
                    format_poly(&conic[2], "t")
                )),
                ConicPoint::NoPoint { obstruction, .. } => tried.push(format!(
                    "{} with the conic ({}, {}, {}): {obstruction}",
                    label(),
                    format_poly(&conic[0], "t"),
                    format_poly(&conic[1], "t"),
                    format_poly(&conic[2], "t")
                )),
            }
        }
        // rank 3 (n = 2, or a cone over the section conic with vertex space spanned by the
        // rows with β = 0): every regular point projects onto the section, so the
        // engine's obstruction is a proof
        if nz.len() == 3 {
            Err(QuadricFamilyError::NoRationalPoint(tried.join("; ")))
        } else {
            Err(QuadricFamilyError::NoPointFound(tried))
        }
    }

    /// Prop. 5.1: the stereographic parametrization `g(t, u)` of the family from the point
    /// of [`Self::rational_point`] (module docs).
    ///
    /// # Errors
    /// As [`Self::rational_point`]; [`QuadricFamilyError::Degenerate`] if no coordinate
    /// chart gives a projection of degree 2 (a defect: the point is regular).
    pub fn parametrize(&self) -> Result<QuadricFamilyParam, QuadricFamilyError> {
        let fp = self.rational_point()?;
        self.parametrize_from(fp)
    }

    /// Prop. 5.1 from a given point `f(t)` of the family (checked: `fᵀQf ≡ 0`, `Qf ≢ 0`).
    ///
    /// # Errors
    /// [`QuadricFamilyError::Degenerate`] if `f` is not on the family, is singular, or no
    /// chart gives degree 2.
    pub fn parametrize_from(
        &self,
        fp: FamilyPoint,
    ) -> Result<QuadricFamilyParam, QuadricFamilyError> {
        let n1 = self.q.len();
        let f = &fp.point;
        if f.len() != n1 || !form(&self.q, f, f).is_zero() {
            return Err(QuadricFamilyError::Degenerate(
                "the given point does not lie on every quadric (fᵀQf ≢ 0)".into(),
            ));
        }
        let qf: Vec<P> = (0..n1)
            .map(|i| (0..n1).fold(pz(), |acc, j| &acc + &(&self.q[i][j] * &f[j])))
            .collect();
        if qf.iter().all(|x| x.is_zero()) {
            return Err(QuadricFamilyError::Degenerate(
                "the point is singular on every quadric (Q·f ≡ 0): the projection from it degenerates".into(),
            ));
        }
        let nv = n1 - 1; // t and u₁ … u_{n−1}
        let lift = |p: &P| MPoly::from_poly(p, nv, 0);
        let qm: Vec<Vec<MPoly<Q>>> = self
            .q
            .iter()
            .map(|r| r.iter().map(lift).collect())
            .collect();
        let fm: Vec<MPoly<Q>> = f.iter().map(lift).collect();
        let mform = |a: &[MPoly<Q>], b: &[MPoly<Q>]| {
            let mut s = MPoly::zero(nv);
            for i in 0..n1 {
                for j in 0..n1 {
                    if !qm[i][j].is_zero() && !a[i].is_zero() && !b[j].is_zero() {
                        s = &s + &(&(&a[i] * &qm[i][j]) * &b[j]);
                    }
                }
            }
            s
        };
        for k in (0..n1).rev().filter(|&k| !f[k].is_zero()) {
            let others: Vec<usize> = (0..n1).filter(|&j| j != k).collect();
            let mut q: Vec<MPoly<Q>> = vec![MPoly::zero(nv); n1];
            q[others[0]] = MPoly::constant(nv, Q::ONE);
            for (a, &j) in others.iter().enumerate().skip(1) {
                q[j] = MPoly::var(nv, a);
            }
            let lam = mform(&q, &q);
            let mu = mform(&fm, &q).scale(&Q::from(-2));
            let g: Vec<MPoly<Q>> = (0..n1).map(|i| &(&lam * &fm[i]) + &(&mu * &q[i])).collect();
            if u_degree(&g) == 2 {
                return Ok(QuadricFamilyParam {
                    family: self.clone(),
                    point: fp,
                    chart: k,
                    g,
                });
            }
        }
        Err(QuadricFamilyError::Degenerate(
            "no coordinate chart gives a stereographic projection of degree 2".into(),
        ))
    }
}

/// The total degree in `u₁ … u_{n−1}` (variables `1…`) of a polynomial vector.
fn u_degree(g: &[MPoly<Q>]) -> u32 {
    g.iter()
        .flat_map(|p| p.terms().map(|(e, _)| e.iter().skip(1).sum::<u32>()))
        .max()
        .unwrap_or(0)
}

/// The rational parametrization `g(t, u)` of a quadric family (Prop. 5.1): variables
/// `t` (index 0), `u₁ … u_{n−1}` (indices `1 … n−1`).
#[derive(Debug, Clone, PartialEq)]
pub struct QuadricFamilyParam {
    family: QuadricFamily,
    point: FamilyPoint,
    chart: usize,
    g: Vec<MPoly<Q>>,
}

impl QuadricFamilyParam {
    /// `g(t, u)`, homogeneous coordinates `(x₀, …, xₙ)`.
    pub fn map(&self) -> &[MPoly<Q>] {
        &self.g
    }

    /// The point `f(t)` projected from (Cor. 5.1).
    pub fn point(&self) -> &FamilyPoint {
        &self.point
    }

    /// The family.
    pub fn family(&self) -> &QuadricFamily {
        &self.family
    }

    /// The index `k` of the coordinate hyperplane `x_k = 0` whose chart is the parameter
    /// space.
    pub fn chart(&self) -> usize {
        self.chart
    }

    /// `(deg_t, total degree in u)`.
    pub fn degree(&self) -> (u32, u32) {
        let dt = self
            .g
            .iter()
            .filter_map(|p| p.degree_in(0))
            .max()
            .unwrap_or(0);
        (dt, u_degree(&self.g))
    }

    /// `g(t₀, u)` as polynomials in `u₁ … u_{n−1}` (the quadric `Q(t₀)`).
    pub fn at(&self, t0: &Q) -> Vec<MPoly<Q>> {
        let nv = self.g.len() - 1;
        self.g
            .iter()
            .map(|p| {
                let s = p.specialize(0, t0);
                // drop the variable t (index 0)
                MPoly::from_terms(
                    nv - 1,
                    s.terms()
                        .map(|(e, c)| (e[1..].to_vec(), c.clone()))
                        .collect(),
                )
                .unwrap_or_else(|_| MPoly::zero(nv - 1))
            })
            .collect()
    }
}

impl Certified for QuadricFamilyParam {
    /// `fᵀQf ≡ 0`, `Q·f ≢ 0` (regular point), `gᵀQg ≡ 0` and total degree 2 in `u`.
    fn certify(&self) -> Vec<Certificate> {
        let q = &self.family.q;
        let n1 = q.len();
        let f = &self.point.point;
        let ff = form(q, f, f);
        let qf_zero = (0..n1).all(|i| {
            (0..n1)
                .fold(pz(), |acc, j| &acc + &(&q[i][j] * &f[j]))
                .is_zero()
        });
        let nv = n1 - 1;
        let mut s = MPoly::zero(nv);
        for i in 0..n1 {
            for j in 0..n1 {
                if !q[i][j].is_zero() {
                    s = &s + &(&(&self.g[i] * &MPoly::from_poly(&q[i][j], nv, 0)) * &self.g[j]);
                }
            }
        }
        let du = u_degree(&self.g);
        let [l, m, nn] = &self.point.conic;
        let [x, y, z] = &self.point.conic_point;
        let conic = &(&(&(x * x) * l) + &(&(y * y) * m)) + &(&(z * z) * nn);
        vec![
            Certificate::decide(
                "X²β_i + Y²β_j + Z²β_k ≡ 0 (the point of the plane section (5.2), Peternell Thm 1.1)",
                conic.is_zero(),
                true,
                || format!("residual {}", format_poly(&conic, "t")),
            ),
            Certificate::decide(
                "f(t)ᵀ·Q(t)·f(t) ≡ 0 (a rational curve on the family, Peternell Cor. 5.1)",
                ff.is_zero(),
                true,
                || format!("residual {}", format_poly(&ff, "t")),
            ),
            Certificate::decide(
                "Q(t)·f(t) ≢ 0 (f is a regular point: the projection from it is birational)",
                !qf_zero,
                true,
                || "Q·f ≡ 0".into(),
            ),
            Certificate::decide(
                "g(t, u)ᵀ·Q(t)·g(t, u) ≡ 0 (every point lies on its quadric, Peternell Prop. 5.1)",
                s.is_zero(),
                true,
                || format!("{} terms", s.num_terms()),
            ),
            Certificate::decide(
                "total degree 2 in u (the stereographic projection (1.29)/(1.32) from f)",
                du == 2,
                true,
                || format!("degree {du} in u"),
            ),
        ]
    }
}

/// The quadric family of the diagonal normal form (5.1), `Σ βᵢ(t)xᵢ² = 0`.
pub fn diagonal_family(beta: &[P]) -> Vec<Vec<P>> {
    let n = beta.len();
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| if i == j { beta[i].clone() } else { pz() })
                .collect()
        })
        .collect()
}

/// A picture of a quadric family in the affine chart `x_w = 1` of a coordinate whose
/// hyperplane misses the real quadric where there is one (the principal minor of `Q`
/// without `w` definite; else `w = 0`), the other coordinates in order: for `n = 2` the
/// surface swept by the conics stacked over `t`, `(t, x_i/x_w, x_j/x_w)` on
/// `[t₀, t₁] × [u₀, u₁]`; for `n ≥ 3` the quadric `Q(t₀)`, `g(t₀, u₁, u₂)` on
/// `[u₁₀, u₁₁] × [u₂₀, u₂₁]` (for `n ≥ 4` the slice `u₃ = … = 0`, projected to the first
/// three other coordinates). Positive weights, split where needed.
#[derive(Debug, Clone)]
pub struct QuadricFamilyPicture {
    /// The parametrization.
    pub param: QuadricFamilyParam,
    /// The patches.
    pub patches: Vec<BezierPatch<Q>>,
    /// The certificates of the parametrization and of the weights.
    pub certificates: Vec<Certificate>,
}

impl QuadricFamilyParam {
    /// The picture (see [`QuadricFamilyPicture`]); `t0` is used for `n ≥ 3`, `a`, `b` are
    /// the two parameter intervals.
    ///
    /// # Errors
    /// [`QuadricFamilyError::Patch`] where the weight `x₀` vanishes on the rectangle (a
    /// point at infinity) or the rectangle is empty.
    pub fn picture(
        &self,
        t0: &Q,
        a: (Q, Q),
        b: (Q, Q),
    ) -> Result<(Vec<BezierPatch<Q>>, Certificate), QuadricFamilyError> {
        let n = self.g.len() - 1;
        let pe = |e: ConicSurfaceError| QuadricFamilyError::Patch(e.to_string());
        // the weight: a coordinate x_w whose hyperplane x_w = 0 misses the real quadric
        // (the principal minor without w is definite), so x_w ≠ 0 on every real point
        let ts = if n == 2 {
            (&a.0 + &a.1) / Q::from(2)
        } else {
            t0.clone()
        };
        let qt = self.family.at(&ts);
        let w = (0..=n)
            .find(|&w| {
                let idx: Vec<usize> = (0..=n).filter(|&i| i != w).collect();
                let m = Matrix::from_fn(n, n, |i, j| {
                    qt.get(idx[i], idx[j]).cloned().unwrap_or(Q::ZERO)
                });
                definiteness(&m, n) != 0
            })
            .unwrap_or(0);
        let order: Vec<usize> = core::iter::once(w)
            .chain((0..=n).filter(|&i| i != w))
            .collect();
        let coords: [MPoly<Q>; 4] = if n == 2 {
            // (x_w, t·x_w, x_i, x_j) in the variables (t, u)
            let t = MPoly::var(2, 0);
            let gw = &self.g[order[0]];
            [
                gw.clone(),
                &t * gw,
                self.g[order[1]].clone(),
                self.g[order[2]].clone(),
            ]
        } else {
            let at = self.at(t0);
            // keep u₁, u₂; set u₃ … = 0
            core::array::from_fn(|i| super::restrict_to_first_two(&at[order[i]]))
        };
        let patch = point_patch(&coords, a, b, &format!("x{w}")).map_err(pe)?;
        positive_pieces(patch).map_err(pe)
    }
}

/// §5.1 as one call: the family `Q(t)`, its parametrization (Prop. 5.1) and its picture
/// ([`QuadricFamilyParam::picture`]) with every certificate.
///
/// # Errors
/// As [`QuadricFamily::new`], [`QuadricFamily::parametrize`] and
/// [`QuadricFamilyParam::picture`].
pub fn quadric_family_picture(
    q: Vec<Vec<P>>,
    t0: &Q,
    a: (Q, Q),
    b: (Q, Q),
) -> Result<QuadricFamilyPicture, QuadricFamilyError> {
    let fam = QuadricFamily::new(q)?;
    let param = fam.parametrize()?;
    let (patches, weights) = param.picture(t0, a, b)?;
    let mut certificates = param.certify();
    certificates.push(weights);
    Ok(QuadricFamilyPicture {
        param,
        patches,
        certificates,
    })
}

/// The engine's answer for a conic family `X²L + Y²M + Z²N = 0` with a picture: where a
/// point exists, the conics stacked over `t` (the `n = 2` picture of
/// [`QuadricFamilyParam::picture`] on `[t₀, t₁] × [u₀, u₁]`); otherwise the graphs
/// `(t, L(t))`, `(t, M(t))`, `(t, N(t))` on `[t₀, t₁]` whose roots and signs the decision
/// is about.
#[derive(Debug, Clone)]
pub struct ConicPointReport {
    /// The decision (module [`rcagd_algebra::conic_point`]).
    pub decision: ConicPoint,
    /// The stacked conics (a point exists over `Q`).
    pub patches: Vec<BezierPatch<Q>>,
    /// The coefficient graphs (no point over `Q`).
    pub graphs: Vec<BezierCurve<Q>>,
    /// The certificates (the point, the parametrization, the weights).
    pub certificates: Vec<Certificate>,
}

/// The graph `(t, p(t))` of a polynomial on `[t₀, t₁]` as a polynomial Bézier curve.
///
/// # Errors
/// [`QuadricFamilyError::Patch`] for an empty interval.
pub fn graph_curve(p: &P, t: &(Q, Q)) -> Result<BezierCurve<Q>, QuadricFamilyError> {
    if t.0 >= t.1 {
        return Err(QuadricFamilyError::Patch(format!(
            "the interval [{}, {}] is empty",
            t.0, t.1
        )));
    }
    let lin = Poly::new(vec![t.0.clone(), &t.1 - &t.0]);
    let d = p.degree().unwrap_or(0).max(1);
    let err = |e: rcagd_algebra::AlgebraError| QuadricFamilyError::Patch(e.to_string());
    let xs = to_bernstein(&lin, d).map_err(err)?;
    let ys = to_bernstein(&p.compose(&lin), d).map_err(err)?;
    let pts = xs
        .into_iter()
        .zip(ys)
        .map(|(x, y)| vec![Q::ONE, x, y])
        .collect();
    BezierCurve::from_homogeneous(pts).map_err(|e| QuadricFamilyError::Patch(e.to_string()))
}

/// The conic-point engine on `(L, M, N)` with its certificates and picture
/// ([`ConicPointReport`]).
///
/// # Errors
/// [`QuadricFamilyError::Rank`]`(0)` when `L = M = N = 0` (the zero form, no conic),
/// [`QuadricFamilyError::Engine`] (undecided), [`QuadricFamilyError::Patch`] (picture).
pub fn conic_point_report(
    coeffs: [P; 3],
    t: (Q, Q),
    u: (Q, Q),
) -> Result<ConicPointReport, QuadricFamilyError> {
    // L = M = N = 0 is the zero form: every point satisfies it, no conic (rank 0)
    if coeffs.iter().all(P::is_zero) {
        return Err(QuadricFamilyError::Rank(0));
    }
    let decision = conic_point(&coeffs[0], &coeffs[1], &coeffs[2])?;
    let mut certificates = Vec::new();
    let mut patches = Vec::new();
    let mut graphs = Vec::new();
    match &decision {
        ConicPoint::Rational(pt) => {
            certificates.push(rcagd_algebra::conic_point::certify_conic_point(&coeffs, pt));
            if coeffs.iter().all(|c| !c.is_zero()) {
                let fam = QuadricFamily::new(diagonal_family(&coeffs))?;
                let fp = FamilyPoint {
                    point: pt.to_vec(),
                    plane: [0, 1, 2].map(|i| {
                        (0..3)
                            .map(|j| Poly::constant(if i == j { Q::ONE } else { Q::ZERO }))
                            .collect()
                    }),
                    conic: coeffs.clone(),
                    conic_point: pt.clone(),
                };
                let param = fam.parametrize_from(fp)?;
                let (p, w) = param.picture(&Q::ZERO, t, u)?;
                certificates.extend(param.certify());
                certificates.push(w);
                patches = p;
            } else {
                for c in &coeffs {
                    graphs.push(graph_curve(c, &t)?);
                }
            }
        }
        ConicPoint::QuadraticField {
            radicand,
            point,
            obstruction,
        } => {
            let mut c = rcagd_algebra::conic_point::certify_conic_point_ext(&coeffs, point);
            c.property = format!("{} (d = {radicand})", c.property);
            certificates.push(c);
            if let Obstruction::AtInfinity { .. } = obstruction {
                certificates.push(obstruction_certificate(obstruction, &coeffs)?);
            }
            for c in &coeffs {
                graphs.push(graph_curve(c, &t)?);
            }
        }
        ConicPoint::NoPoint {
            obstruction,
            reduced,
        } => {
            certificates.push(obstruction_certificate(obstruction, reduced)?);
            for c in &coeffs {
                graphs.push(graph_curve(c, &t)?);
            }
        }
    }
    Ok(ConicPointReport {
        decision,
        patches,
        graphs,
        certificates,
    })
}

/// The obstruction re-checked: for a residue, `p` divides its coefficient of the reduced
/// family exactly and the residue has no square root in `Q[t]/(p)`; at infinity, the
/// leading conic has no rational point (Legendre's conditions, named place).
///
/// # Errors
/// [`QuadricFamilyError::Engine`] if a factorization is undecided.
pub fn obstruction_certificate(
    obstruction: &Obstruction,
    reduced: &[P; 3],
) -> Result<Certificate, QuadricFamilyError> {
    Ok(match obstruction {
        Obstruction::Residue {
            factor,
            divides,
            value,
        } => {
            use rcagd_algebra::conic_point::Coefficient;
            let c = match divides {
                Coefficient::L => &reduced[0],
                Coefficient::M => &reduced[1],
                Coefficient::N => &reduced[2],
            };
            let divides_ok = c.div_rem(factor).map(|(_, r)| r.is_zero()).unwrap_or(false);
            let no_root = sqrt_mod_irreducible(value, factor)?.is_none();
            Certificate::decide(
                format!(
                    "p(t) = {} divides its coefficient and {} is not a square in Q[t]/(p) (no point over Q)",
                    format_poly(factor, "t"),
                    format_poly(value, "t")
                ),
                divides_ok && no_root,
                true,
                || format!("divides: {divides_ok}, non-square: {no_root}"),
            )
        }
        Obstruction::AtInfinity { conic, place } => {
            let out = rational_conic_point(&conic[0], &conic[1], &conic[2])?;
            let ok = matches!(&out, TernaryOutcome::NoPoint(p) if p == place);
            Certificate::decide(
                format!(
                    "the leading conic {}·X² + {}·Y² + {}·Z² = 0 has no point over {place} (no point over Q at t = ∞)",
                    conic[0], conic[1], conic[2]
                ),
                ok,
                true,
                || format!("{out:?}"),
            )
        }
    })
}
