//! Krasauskas' degree reduction of rational canal surfaces (Gruber §2.4.2, (2.29)–(2.37);
//! docs/math/lines-and-canal.md, "Canal surfaces" and errata G7, G9).
//!
//! **The construction.** The unit normals `q` of the envelope along the characteristic
//! circle at `t` are the points of the unit sphere in the plane `B(t)ᵀ(1, q) = 0`,
//! `B = (P₄, P₁, P₂, P₃) ∝ (ṙ, ṁ)` (2.31). Through the map
//!
//! ```text
//! f_s(U₀, U₁) = (|U₀|² + |U₁|², 2 Re U₀Ū₁, 2 Im U₀Ū₁, |U₀|² − |U₁|²)          (2.29)
//! ```
//!
//! `Bᵀ f_s(U) = U* H U` is a Hermitian form with
//! `H = [[α, β], [β̄, γ]]`, `α = P₄ + σPⱼ`, `γ = P₄ − σPⱼ`, `β = P_a + iP_b` (for the axis
//! choice `(j, σ)` and the other axes `a, b`, as in [`super::envelope`]) and
//! `det H = −D`. Every circle of normals is the image `f_s(a(t) + u b(t))`, `u ∈ R ∪ ∞`, of a
//! real pencil in `C²`: the ruled surface `R(t, u) = a + u b` of Gruber §2.4.2, and the
//! envelope is
//!
//! ```text
//! x(t, u) = m(t) + r(t) · (x₁, x₂, x₃)/x₀,   x = f_s(a(t) + u b(t)),   bidegree (k + 2·deg(a, b), 2)
//! ```
//!
//! **A first pencil.** With `w = g₁ + i g₂`, `w w̄ = D` (the split of
//! [`super::sum_of_squares`]), `U(v) = (−β + w v, α)` is isotropic for `|v| = 1`
//! (`U*HU = α(|w v|² − D) = 0`); `v = (1 + iu)/(1 − iu)` gives the pencil
//! `a = (w − β, α)`, `b = i(w + β, −α)` of degree `deg(a, b) ≤ max(deg P)`, with
//! `det(a, b) = −2iαw`.
//!
//! **The reduction (2.36).** The pencil can be changed without changing the circles:
//! `(a, b) ≈ (a + ρb, b)` for real `ρ ∈ R[t]` (a shift of `u`), `(a, b) ∼ (a/σ, σ̄ b)` for
//! `σ ∈ C[t]` dividing `a` (the scaling `u ↦ |σ|²u` and division by `σ`), `(a, b) ∼ (a/π, b)`
//! for a real `π` dividing `a`, and a common factor of all of `a, b` may be divided out
//! (`f_s(νU) = |ν|² f_s(U)`). The reduction here applies, while they lower
//! `(max(deg a, deg b), deg a + deg b)`:
//! 1. `a ← a − r t^{deg a − deg b} b` when the leading coefficient vectors are real
//!    multiples;
//! 2. division of `a` by its real content, or by a complex factor `σ` of
//!    `gcd(a₀, a₁)` with `deg a − deg b ≥ 2 deg σ`;
//! 3. the combination of both seed operations: for an irreducible factor `σ` of
//!    `det(a, b)` over the coefficient field (with `i`), a real `ρ` of degree
//!    `≤ deg a − deg b` with `σ | a + ρb` (a linear system over the field), then
//!    `(a, b) ← ((a + ρb)/σ, σ̄b)`; the factors are tried lowest degree first, within a
//!    degree in a fixed order of their coefficients (so the pencil reached depends on the
//!    factors of `det(a, b)`, not on the order a factorization lists them in).
//!
//! **What it reaches.** Gruber Satz 2 states the degree `(k + n, 2)`,
//! `n = 2 max(k − 1, 2k − 2 − Σ⌈pᵢ/2⌉)` ([`super::krasauskas_bound`]), over `C`: the
//! operations may need the roots of `D`. Over the field of the data, step 3 needs the
//! irreducible factors of `det(a, b)` over that field with `i`:
//! * over `Q` the factors over `Q(i)` (`gaussian_factors_of`, complete);
//! * over `Q(√d)` (a split `D = g₁² + g₂²` that needs `√d`) the factors over
//!   `K = Q(√d)(i)` (`biquadratic_factors_of`, Trager's norm method with the primitive
//!   element `√d + i`, [`rcagd_algebra::factor_ext`]): complete — linear factors (roots in
//!   `K`), factors over `Q(i)`, `Q(√d)` and `Q(√−d)` alike — unless a Zassenhaus
//!   factorization over `Q` gives up (more than 16 modular factors); then only the
//!   factors over `Q(i)` and the `gcd`s of `det(a, b)` with the `Q`-irreducible factors of
//!   its norm are found, and the `K`-irreducible pieces of such a `gcd` are the factors
//!   *not found*.
//!
//! When the factors of `det(a, b)` over the field are of degree > 1 (roots of `D` outside
//! `K`), the reduction can stop above the bound, and the result says which degree it
//! reached (e.g. `D = (t² − (4 + 2i)t − 1)(t² − (4 − 2i)t − 1)`, roots `2 ± i ± 2√(1 ± i)`:
//! `(6, 2)` against `(4, 2)`). docs/math/lines-and-canal.md, Errata G9: for polynomial data the bound (2.37) itself can
//! be exceeded by the construction's own degree being lower. The builders of
//! [`super::canal_surface`] try this construction and the Peternell–Pottmann one for every
//! axis and split, over `Q` and over `Q(√d)`, and keep the lowest bidegree (e.g. the ring
//! torus and the Dupin cyclide from rational circle spines come out biquadratic, `(2, 2)`,
//! where the first pencil gives `(6, 2)`; a rational quadratic family with
//! `D = 3(t⁴ + 6t² + 1)`, which needs `Q(√3)`, comes out `(4, 2)` = (2.37), where
//! Peternell–Pottmann gives `(6, 2)`).
//!
//! **Base points.** A real root `t₀` of `det(a, b)` with `D(t₀) ≠ 0` would collapse the
//! iso-curve `x(t₀, ·)` to a point; a pencil with such a root is rejected
//! ([`CanalError::DegenerateSpine`]) and the other constructions are used.

use super::bipoly::BiPoly;
use super::{CanalError, CanalSpine};
use num_traits::{One, Zero};
use rcagd_algebra::complex::{conj_poly, re_im_polys};
use rcagd_algebra::factor::gaussian_coprime_mod_p;
use rcagd_algebra::linalg::{solve, Matrix};
use rcagd_algebra::roots::isolate_real_roots;
use rcagd_algebra::sum_of_squares::GaussianSplit;
use rcagd_algebra::{Complex, Poly, QuadExt, Rational, Scalar};
use std::sync::Mutex;

type CPoly<F> = Poly<Complex<F>>;

/// A total order of polynomials over `F(i)` of equal degree: lexicographic in the
/// coefficients from the constant one up, each compared by its real, then its imaginary
/// part (`F` is ordered: `Q` or `Q(√d)` with `d > 0`).
fn canonical_cmp<F: Scalar>(f: &CPoly<F>, g: &CPoly<F>) -> std::cmp::Ordering {
    f.coeffs()
        .iter()
        .zip(g.coeffs())
        .map(|(x, y)| {
            x.re.partial_cmp(&y.re)
                .unwrap_or(std::cmp::Ordering::Equal)
                .then_with(|| x.im.partial_cmp(&y.im).unwrap_or(std::cmp::Ordering::Equal))
        })
        .find(|o| o.is_ne())
        .unwrap_or(std::cmp::Ordering::Equal)
}

/// The irreducible factors of `det(a, b)` over the coefficient field with `i`, for step 3
/// of the reduction.
pub(crate) trait FactorSource<F: Scalar> {
    /// The irreducible factors of `l` (monic, without repetition) that the reduction tries;
    /// an empty list disables step 3.
    fn factors(&self, l: &CPoly<F>) -> Vec<CPoly<F>>;

    /// [`Self::factors`] of `l` when every irreducible factor of `l` is among `candidates`
    /// (monic irreducible polynomials), if that can be shown to be the same list without
    /// factoring `l`; `None` otherwise (then [`Self::factors`] is used).
    fn factors_among(&self, _l: &CPoly<F>, _candidates: &[CPoly<F>]) -> Option<Vec<CPoly<F>>> {
        None
    }

    /// Whether [`Self::factors_among`] can answer (then the reduction collects the
    /// candidates).
    fn uses_candidates(&self) -> bool {
        false
    }
}

/// A factorization function as a [`FactorSource`] (no shortcut).
pub(crate) struct FnFactors<'a, F>(pub &'a dyn Fn(&CPoly<F>) -> Vec<CPoly<F>>);

impl<F: Scalar> FactorSource<F> for FnFactors<'_, F> {
    fn factors(&self, l: &CPoly<F>) -> Vec<CPoly<F>> {
        (self.0)(l)
    }
}

/// The particular solution (free variables zero) of the linear system `rows · x = rhs`
/// ([`rcagd_algebra::Solution::particular`]), `None` if it is inconsistent: for rational
/// entries by the fraction-free elimination on integers
/// ([`Matrix::particular_solution_integral`], the same solution), otherwise by
/// Gauss–Jordan elimination over `F`.
fn particular_solution<F: Scalar>(rows: Vec<Vec<F>>, rhs: &[F]) -> Option<Vec<F>> {
    if F::EXACT {
        let q: Option<Vec<Vec<Rational>>> = rows
            .iter()
            .map(|r| r.iter().map(Scalar::to_rational).collect())
            .collect();
        let b: Option<Vec<Rational>> = rhs.iter().map(Scalar::to_rational).collect();
        if let (Some(q), Some(b)) = (q, b) {
            let m = Matrix::from_rows(q).ok()?;
            let x = m.particular_solution_integral(&b).ok()??;
            return Some(x.iter().map(F::from_rational).collect());
        }
    }
    let m = Matrix::from_rows(rows).ok()?;
    let sol = solve(&m, rhs).ok()?;
    sol.particular().map(<[F]>::to_vec)
}

/// A real pencil `a + u b` in `C²` (module docs) and its reduction history.
#[derive(Debug, Clone, PartialEq)]
pub struct Pencil<F> {
    /// `a(t) ∈ C[t]²`.
    pub a: [CPoly<F>; 2],
    /// `b(t) ∈ C[t]²`.
    pub b: [CPoly<F>; 2],
    /// The degree `max(deg a, deg b)` of the first pencil.
    pub initial_degree: usize,
    /// The number of reduction steps applied.
    pub steps: usize,
}

fn cdeg<F: Scalar>(v: &[CPoly<F>; 2]) -> Option<usize> {
    match (v[0].degree(), v[1].degree()) {
        (None, None) => None,
        (x, y) => Some(x.unwrap_or(0).max(y.unwrap_or(0))),
    }
}

fn deg_or_zero<F: Scalar>(v: &[CPoly<F>; 2]) -> usize {
    cdeg(v).unwrap_or(0)
}

fn cpoly<F: Scalar>(p: &Poly<F>) -> CPoly<F> {
    p.map(|c| Complex::from_real(c.clone()))
}

/// `c·v` for a polynomial `c` and a vector `v ∈ C[t]²`.
fn times<F: Scalar>(c: &CPoly<F>, v: &[CPoly<F>; 2]) -> [CPoly<F>; 2] {
    [c * &v[0], c * &v[1]]
}

fn times_i<F: Scalar>(p: &CPoly<F>) -> CPoly<F> {
    p.scale(&Complex::i())
}

impl<F: Scalar> Pencil<F> {
    /// The first pencil `a = (w − β, α)`, `b = i(w + β, −α)` (module docs).
    ///
    /// # Errors
    /// [`CanalError::DegenerateSpine`] if `α ≡ 0` (choose another axis).
    pub fn initial(alpha: &Poly<F>, beta: &CPoly<F>, w: &CPoly<F>) -> Result<Self, CanalError> {
        if alpha.is_zero() {
            return Err(CanalError::DegenerateSpine(
                "α = P₄ + σPⱼ ≡ 0 for this axis (Krasauskas pencil)".into(),
            ));
        }
        let al = cpoly(alpha);
        let a = [w - beta, al.clone()];
        let b = [times_i(&(w + beta)), times_i(&-&al)];
        let mut p = Pencil {
            initial_degree: 0,
            a,
            b,
            steps: 0,
        };
        p.initial_degree = p.degree();
        Ok(p)
    }

    /// `max(deg a, deg b)`: the surface has bidegree `(k + 2·degree, 2)` before cancellation.
    pub fn degree(&self) -> usize {
        deg_or_zero(&self.a).max(deg_or_zero(&self.b))
    }

    /// `det(a, b) = a₀b₁ − a₁b₀` (the Plücker coordinate `l₀₁` of Gruber (2.33)).
    pub fn det(&self) -> CPoly<F> {
        &(&self.a[0] * &self.b[1]) - &(&self.a[1] * &self.b[0])
    }

    fn key(&self) -> (usize, usize) {
        let (da, db) = (deg_or_zero(&self.a), deg_or_zero(&self.b));
        (da.max(db), da + db)
    }

    /// Divides all four entries by their common factor (exact scalars).
    fn remove_content(&mut self) {
        // the usual case, no common factor: two coprime entries, proved modulo a prime
        let [a0, a1] = &self.a;
        let [b0, b1] = &self.b;
        if gaussian_coprime_mod_p(a0, a1) || gaussian_coprime_mod_p(b0, b1) {
            return;
        }
        // the gcd stops at a constant
        let mut g = CPoly::<F>::zero();
        for p in self.a.iter().chain(self.b.iter()) {
            g = g.gcd(p);
            if g.degree() == Some(0) {
                return;
            }
        }
        if g.degree().is_some_and(|d| d > 0) {
            if let (Ok(a0), Ok(a1), Ok(b0), Ok(b1)) = (
                self.a[0].div_exact(&g),
                self.a[1].div_exact(&g),
                self.b[0].div_exact(&g),
                self.b[1].div_exact(&g),
            ) {
                self.a = [a0, a1];
                self.b = [b0, b1];
            }
        }
    }

    fn swap_if_needed(&mut self) {
        if deg_or_zero(&self.a) < deg_or_zero(&self.b) {
            std::mem::swap(&mut self.a, &mut self.b);
        }
    }

    /// Step 1: `a ← a − r tᵉ b` if the leading coefficient vectors are real multiples.
    fn shift_leading(&mut self) -> bool {
        let (Some(da), Some(db)) = (cdeg(&self.a), cdeg(&self.b)) else {
            return false;
        };
        let la = [self.a[0].coeff(da), self.a[1].coeff(da)];
        let lb = [self.b[0].coeff(db), self.b[1].coeff(db)];
        let Some(k) = (0..2).find(|&k| !lb[k].is_zero()) else {
            return false;
        };
        let Some(inv) = lb[k].inverse() else {
            return false;
        };
        let r = la[k].clone() * inv;
        if !r.im.is_zero() || r.re.is_zero() {
            return false;
        }
        if (0..2).any(|i| la[i] != lb[i].clone() * r.clone()) {
            return false;
        }
        let mb = times(&Poly::monomial(r, da - db), &self.b);
        self.a = [&self.a[0] - &mb[0], &self.a[1] - &mb[1]];
        true
    }

    /// Step 2: divide `a` by its real content or by a complex factor of it.
    fn divide_a(&mut self) -> bool {
        if gaussian_coprime_mod_p(&self.a[0], &self.a[1]) {
            return false;
        }
        let g = self.a[0].gcd(&self.a[1]);
        if g.degree().is_none_or(|d| d == 0) {
            return false;
        }
        let real = g.gcd(&conj_poly(&g));
        let (da, db) = (deg_or_zero(&self.a), deg_or_zero(&self.b));
        if real.degree().is_some_and(|d| d > 0) {
            return self.quotient(&real, None).map(|a| self.a = a).is_some();
        }
        let d = g.degree().unwrap_or(0);
        if da < db + 2 * d {
            return false;
        }
        // (a, b) ← (a/σ, σ̄b)
        let Some(a) = self.quotient(&g, None) else {
            return false;
        };
        self.b = times(&conj_poly(&g), &self.b);
        self.a = a;
        true
    }

    /// `(a + ρb)/σ` (`a/σ` without `ρ`), if `σ` divides both entries.
    fn quotient(&self, sigma: &CPoly<F>, rho: Option<&CPoly<F>>) -> Option<[CPoly<F>; 2]> {
        let num = match rho {
            Some(r) => {
                let rb = times(r, &self.b);
                [&self.a[0] + &rb[0], &self.a[1] + &rb[1]]
            }
            None => self.a.clone(),
        };
        match (num[0].div_exact(sigma), num[1].div_exact(sigma)) {
            (Ok(a0), Ok(a1)) => Some([a0, a1]),
            _ => None,
        }
    }

    /// Step 3 for one irreducible factor `σ` of `det(a, b)` (module docs). For a real `σ`
    /// (a real root of `det`: a collapsed circle of the pencil) `ρ` has degree `< deg σ`,
    /// `b` is kept and the step is always taken (it lowers `deg det`); for a complex `σ` it is
    /// taken when it lowers the degree.
    fn shift_and_divide(&mut self, sigma: &CPoly<F>) -> bool {
        let (da, db) = (deg_or_zero(&self.a), deg_or_zero(&self.b));
        let Some(ds) = sigma.degree() else {
            return false;
        };
        let real = sigma == &conj_poly(sigma);
        if ds == 0 || (!real && da < db + 2 * ds) {
            return false;
        }
        let e = if real { ds - 1 } else { da - db };
        // unknowns ρ₀..ρₑ (real); equations: Re and Im of the coefficients of
        // (a_k + ρ b_k) mod σ, k = 0, 1
        let rem = |p: &CPoly<F>| p.div_rem(sigma).map(|(_, r)| r);
        let mut rows: Vec<Vec<F>> = Vec::new();
        let mut rhs: Vec<F> = Vec::new();
        let mut cols: Vec<[CPoly<F>; 2]> = Vec::new();
        // tⁱ b mod σ = t·(tⁱ⁻¹ b mod σ) mod σ: each column from the one before
        let t = Poly::monomial(Complex::one(), 1);
        for i in 0..=e {
            let next = match cols.last() {
                None => (rem(&self.b[0]), rem(&self.b[1])),
                Some([c0, c1]) if i > 0 => (rem(&(&t * c0)), rem(&(&t * c1))),
                Some(_) => return false,
            };
            let (Ok(r0), Ok(r1)) = next else {
                return false;
            };
            cols.push([r0, r1]);
        }
        for k in 0..2 {
            let Ok(ak) = rem(&self.a[k]) else {
                return false;
            };
            for c in 0..ds {
                let (re_row, im_row): (Vec<F>, Vec<F>) = cols
                    .iter()
                    .map(|col| {
                        let z = col[k].coeff(c);
                        (z.re, z.im)
                    })
                    .unzip();
                let z = ak.coeff(c);
                rows.push(re_row);
                rhs.push(-z.re);
                rows.push(im_row);
                rhs.push(-z.im);
            }
        }
        let Some(rho) = particular_solution(rows, &rhs) else {
            return false;
        };
        let rho = Poly::new(rho.into_iter().map(Complex::from_real).collect());
        let Some(a) = self.quotient(sigma, Some(&rho)) else {
            return false;
        };
        if real {
            // a real σ: `b` is kept ((a + ρb)/σ is a real change of the pencil)
            self.a = a;
            return true;
        }
        let b = times(&conj_poly(sigma), &self.b);
        let (da, db) = (deg_or_zero(&a), deg_or_zero(&b));
        if (da.max(db), da + db) >= self.key() {
            return false;
        }
        self.a = a;
        self.b = b;
        true
    }

    /// Applies the reduction steps (module docs) while they lower the degree;
    /// `factors.factors(l)` returns irreducible factors of `l = det(a, b)` over the
    /// coefficient field (an empty list disables step 3). `candidates` (if given) are monic
    /// irreducible polynomials among which every irreducible factor of every `det(a, b)`
    /// of the reduction lies, closed under conjugation (the factors of `det` of the first
    /// pencil and their conjugates: every step multiplies `det` by a conjugate of what it
    /// divides out, module docs); [`FactorSource::factors_among`] may then find the factors
    /// without factoring.
    pub(crate) fn reduce_with(
        &mut self,
        factors: &dyn FactorSource<F>,
        candidates: Option<&[CPoly<F>]>,
    ) {
        if !F::EXACT {
            return;
        }
        self.remove_content();
        let cap = 4 * (self.degree() + 2) + 16;
        for _ in 0..cap {
            self.swap_if_needed();
            if self.shift_leading() || self.divide_a() {
                self.steps += 1;
                self.remove_content();
                continue;
            }
            let l = self.det();
            let mut done = false;
            let mut fs = match candidates.and_then(|c| factors.factors_among(&l, c)) {
                Some(fs) => fs,
                None => factors.factors(&l),
            };
            // lowest degree first; within a degree in a canonical order (so the pencil found
            // depends on the factors, not on the order a factorization returns them in)
            fs.sort_by(|f, g| {
                f.degree()
                    .cmp(&g.degree())
                    .then_with(|| canonical_cmp(f, g))
            });
            for f in &fs {
                if self.shift_and_divide(f) {
                    done = true;
                    break;
                }
                if f == &conj_poly(f) {
                    // a real factor: the shift may have to go the other way
                    std::mem::swap(&mut self.a, &mut self.b);
                    if self.shift_and_divide(f) {
                        done = true;
                        break;
                    }
                    std::mem::swap(&mut self.a, &mut self.b);
                }
            }
            if !done {
                break;
            }
            self.steps += 1;
            self.remove_content();
        }
        self.swap_if_needed();
    }

    /// [`Self::reduce_with`] by a factorization function (no candidates).
    pub fn reduce(&mut self, factors: &dyn Fn(&CPoly<F>) -> Vec<CPoly<F>>) {
        self.reduce_with(&FnFactors(factors), None);
    }

    /// The homogeneous point `f_s(a + u b)` as four polynomials in `(t, u)` of degree 2 in
    /// `u` (2.29), in the order `(x₀, Re-part, Im-part, difference)`.
    pub fn sphere_image(&self) -> [BiPoly<F>; 4] {
        let two = F::from_i64(2);
        let herm = |p: &CPoly<F>, q: &CPoly<F>| &p.clone() * &conj_poly(q);
        let [a0, a1] = &self.a;
        let [b0, b1] = &self.b;
        // |U0|² and |U1|² as (1, u, u²) coefficient triples, U = a + u b
        let sq = |a: &CPoly<F>, b: &CPoly<F>| -> [Poly<F>; 3] {
            let aa = re_im_polys(&herm(a, a)).0;
            let ab = re_im_polys(&herm(a, b)).0.scale(&two);
            let bb = re_im_polys(&herm(b, b)).0;
            [aa, ab, bb]
        };
        let n0 = sq(a0, b0);
        let n1 = sq(a1, b1);
        // z = U0 Ū1 = a0ā1 + u(a0b̄1 + b0ā1) + u² b0b̄1
        let z = [herm(a0, a1), &herm(a0, b1) + &herm(b0, a1), herm(b0, b1)];
        let zr: Vec<Poly<F>> = z.iter().map(|c| re_im_polys(c).0.scale(&two)).collect();
        let zi: Vec<Poly<F>> = z.iter().map(|c| re_im_polys(c).1.scale(&two)).collect();
        let sum: Vec<Poly<F>> = (0..3).map(|i| &n0[i] + &n1[i]).collect();
        let diff: Vec<Poly<F>> = (0..3).map(|i| &n0[i] - &n1[i]).collect();
        [
            BiPoly::new(sum),
            BiPoly::new(zr),
            BiPoly::new(zi),
            BiPoly::new(diff),
        ]
    }
}

impl<F: Scalar> Pencil<F> {
    /// A constant real change of the pencil basis (a real Möbius map of `u`, which keeps the
    /// circles and the degree) that makes `a(t₀)` and `b(t₀)` orthogonal
    /// (`Re⟨a, b⟩ = 0`) and of nearly equal length (a rational factor within 1/64 of
    /// `|a|/|b|`): then the weight `|a + u b|²` at `t₀` is `|a|²(1 + u²)`-like, and its
    /// Bernstein coefficients on the charts `u ∈ [−1, 0], [0, 1]` (and `u ↦ 1/u`) are
    /// positive near `t₀`.
    pub fn balance_at(&mut self, t0: &Rational) {
        let z = Complex::from_real(F::from_rational(t0));
        let ev = |p: &CPoly<F>| p.eval(&z);
        let (a0, a1) = (ev(&self.a[0]), ev(&self.a[1]));
        let (b0, b1) = (ev(&self.b[0]), ev(&self.b[1]));
        let aa = a0.norm_sq() + a1.norm_sq();
        if aa.is_zero() {
            return;
        }
        let ab = (a0.clone() * b0.conj() + a1.clone() * b1.conj()).re;
        let mu = Complex::from_real(ab / aa.clone());
        let b = [
            &self.b[0] - &self.a[0].scale(&mu),
            &self.b[1] - &self.a[1].scale(&mu),
        ];
        let bb = ev(&b[0]).norm_sq() + ev(&b[1]).norm_sq();
        if bb.is_zero() {
            return;
        }
        let ratio = Scalar::to_f64(&(aa / bb)).sqrt();
        let num = (ratio * 64.0).round().clamp(1.0, 1e12) as i64;
        let lambda = Complex::from_real(F::from_ratio(num, 64));
        self.b = [b[0].scale(&lambda), b[1].scale(&lambda)];
    }
}

/// The scalars whose real-root question is decided exactly here: `Q` (real-root isolation)
/// and `Q(√d)` (through the norm, [`rcagd_algebra::factor_ext::has_real_root_quad`]).
pub(crate) trait RealRoots: Scalar {
    /// Whether the non-zero `g` has a real root.
    ///
    /// # Errors
    /// From real-root isolation.
    fn has_real_root(g: &Poly<Self>) -> Result<bool, CanalError>;
}

impl RealRoots for Rational {
    fn has_real_root(g: &Poly<Self>) -> Result<bool, CanalError> {
        Ok(!isolate_real_roots(g)?.is_empty())
    }
}

impl RealRoots for QuadExt {
    fn has_real_root(g: &Poly<Self>) -> Result<bool, CanalError> {
        Ok(rcagd_algebra::factor_ext::has_real_root_quad(g)?)
    }
}

/// `true` if `det(a, b)` has a real root where `D ≠ 0` (a collapsed iso-curve).
///
/// # Errors
/// From real-root isolation.
pub(crate) fn has_interior_base_point<F: RealRoots>(
    pencil: &Pencil<F>,
    d: &Poly<F>,
) -> Result<bool, CanalError> {
    let l = pencil.det();
    let (re, im) = re_im_polys(&l);
    let mut g = re.gcd(&im);
    if g.is_zero() {
        return Ok(true);
    }
    // remove the factors shared with D
    loop {
        let c = g.gcd(d);
        if c.degree().is_none_or(|k| k == 0) {
            break;
        }
        match g.div_exact(&c) {
            Ok(q) => g = q,
            Err(_) => break,
        }
    }
    if g.degree().is_none_or(|k| k == 0) {
        return Ok(false);
    }
    F::has_real_root(&g)
}

/// The Krasauskas pencil of a spine for one axis and split (module docs), reduced.
///
/// # Errors
/// [`CanalError::DegenerateSpine`] if `α ≡ 0` for this axis.
pub(crate) fn reduced_pencil<F: Scalar>(
    numerators: &[Poly<F>; 4],
    g: &[Poly<F>; 2],
    axis: super::AxisChoice,
    factors: &dyn FactorSource<F>,
) -> Result<Pencil<F>, CanalError> {
    let alpha = axis.pole_polynomial(numerators);
    let (pa, pb) = axis.other_numerators(numerators);
    let beta = &cpoly(pa) + &times_i(&cpoly(pb));
    let w = &cpoly(&g[0]) + &times_i(&cpoly(&g[1]));
    let mut pencil = Pencil::initial(&alpha, &beta, &w)?;
    // det of the first pencil = −2iαw (module docs): its irreducible factors are those of
    // the real α and of w; with the conjugates of those of w they contain the factors of
    // every later det(a, b)
    let candidates = factors.uses_candidates().then(|| {
        let mut c: Vec<CPoly<F>> = factors.factors(&cpoly(&alpha));
        for h in factors.factors(&w) {
            for h in [conj_poly(&h), h] {
                if !c.contains(&h) {
                    c.push(h);
                }
            }
        }
        c
    });
    pencil.reduce_with(factors, candidates.as_deref());
    Ok(pencil)
}

/// Irreducible factors over `Q(i)` of a Gaussian polynomial `l` (through the norm `l l̄`),
/// those that divide `l`; empty if the factorization gives up. (The builders use the memoized
/// [`FactorMemo::gaussian_factors`]; this is its reference in the tests.)
#[cfg_attr(not(test), allow(dead_code))]
pub(crate) fn gaussian_factors_of(l: &CPoly<Rational>) -> Vec<CPoly<Rational>> {
    gaussian_factors_with(l, &|f| super::factor::factor_gaussian_q_first(f).ok())
}

/// Irreducible factors over `Q(i)`.
type GaussFactors = Vec<CPoly<Rational>>;

/// [`gaussian_factors_of`] with the factorization over `Q(i)` of the monic square-free
/// factors of the norm supplied by `factor` (`None`: it gave up).
fn gaussian_factors_with(
    l: &CPoly<Rational>,
    factor: &dyn Fn(&Poly<Rational>) -> Option<GaussFactors>,
) -> Vec<CPoly<Rational>> {
    use rcagd_algebra::complex::norm_sq_poly;
    use rcagd_algebra::roots::square_free_decomposition;
    let n = norm_sq_poly(l);
    if n.degree().is_none_or(|d| d == 0) {
        return Vec::new();
    }
    let mut out: Vec<CPoly<Rational>> = Vec::new();
    for (f, _) in square_free_decomposition(&n) {
        let Some(fs) = factor(&f) else {
            continue;
        };
        for h in fs {
            if l.div_rem(&h).is_ok_and(|(_, r)| r.is_zero()) && !out.contains(&h) {
                out.push(h);
            }
        }
    }
    out
}

/// A memo of the exact computations one construction repeats (the candidate search of
/// [`super::exportable`] builds every frame × method × interval): the factors over `Q(i)`
/// of `det(a, b)` ([`gaussian_factors_of`], keyed by the monic `det`: the monic factors of
/// `c·l` and `l` are the same), the factorizations over `Q(i)` of the square-free factors
/// of its norm and of their irreducible factors over `Q`
/// ([`rcagd_algebra::factor::factor_gaussian_with`]), the Gaussian split of `D` ([`super::sum_of_squares::gaussian_split`]) and
/// the reality checks of the family ([`CanalSpine::check_real_envelope`]). Every entry is
/// the value of a pure function of its key, so a search with the memo makes the same
/// choices as one without; it may be shared by threads (a lookup that misses computes
/// the value without holding the lock).
#[derive(Debug, Default)]
pub(crate) struct FactorMemo {
    dets: Table<CPoly<Rational>, GaussFactors>,
    norms: Table<Poly<Rational>, Option<GaussFactors>>,
    irreducibles: Table<Poly<Rational>, Option<GaussFactors>>,
    splits: Table<Poly<Rational>, GaussianSplit>,
    real: Table<RealKey, ()>,
    /// Remember nothing (the reference of the tests).
    off: bool,
}

/// The discriminant `D = |ṁ|² − ṙ²` of a family and a domain (`None`: all of `R`) on which
/// its envelope was found real (the reality check reads the family only through `D`, so
/// the families of the tilted frames, orthogonal images of one family with the same `D`,
/// share the entry).
type RealKey = (Poly<Rational>, Option<(Rational, Rational)>);

/// The most entries per table of a [`FactorMemo`] (then it starts over).
const MEMO_ENTRIES: usize = 256;

/// Key–value pairs, found by equality (the keys are polynomials: few, and compared fast).
#[derive(Debug)]
struct Table<K, V>(Mutex<Vec<(K, V)>>);

impl<K, V> Default for Table<K, V> {
    fn default() -> Self {
        Table(Mutex::new(Vec::new()))
    }
}

impl<K: PartialEq, V: Clone> Table<K, V> {
    fn get(&self, key: &K) -> Option<V> {
        let t = self.0.lock().ok()?;
        t.iter().find(|(k, _)| k == key).map(|(_, v)| v.clone())
    }

    fn put(&self, key: K, value: V) {
        if let Ok(mut t) = self.0.lock() {
            if t.len() >= MEMO_ENTRIES {
                t.clear();
            }
            t.push((key, value));
        }
    }
}

impl FactorMemo {
    /// A memo that remembers nothing: every call computes (the reference in the tests).
    #[cfg(test)]
    pub(crate) fn off() -> Self {
        FactorMemo {
            off: true,
            ..FactorMemo::default()
        }
    }

    /// Whether the search may derive a candidate from another one instead of building it
    /// (the mirrored frames of a pipe, [`super::envelope::CanalSurface::mirrored`]); the
    /// memo without memory (the tests' reference) builds every candidate.
    pub(crate) fn derives(&self) -> bool {
        !self.off
    }

    fn get<K: PartialEq, V: Clone>(&self, table: &Table<K, V>, key: &K) -> Option<V> {
        if self.off {
            None
        } else {
            table.get(key)
        }
    }

    /// [`gaussian_factors_of`], memoized.
    pub(crate) fn gaussian_factors(&self, l: &CPoly<Rational>) -> Vec<CPoly<Rational>> {
        if l.is_zero() {
            return Vec::new();
        }
        let key = l.monic();
        if let Some(v) = self.get(&self.dets, &key) {
            return v;
        }
        let v = gaussian_factors_with(l, &|f| self.factor_gaussian(f));
        self.dets.put(key, v.clone());
        v
    }

    fn factor_gaussian(&self, f: &Poly<Rational>) -> Option<GaussFactors> {
        if let Some(v) = self.get(&self.norms, f) {
            return v;
        }
        let v = if self.off {
            super::factor::factor_gaussian_q_first(f).ok()
        } else {
            // the split over Q(i) of each Q-irreducible factor once per search: the norms
            // of the different det(a, b) share most of their factors
            super::factor::factor_gaussian_with(f, &|g| {
                if let Some(v) = self.get(&self.irreducibles, g) {
                    return v.ok_or(super::factor::FactorError::NoGoodPrime);
                }
                let v = super::factor::factor_gaussian_irreducible(g);
                self.irreducibles.put(g.clone(), v.clone().ok());
                v
            })
            .ok()
        };
        self.norms.put(f.clone(), v.clone());
        v
    }

    /// [`CanalSpine::check_real_envelope`], memoized by the discriminant and the domain
    /// (the check is a function of those two: the sign of `D` on the domain); errors are not
    /// memoized.
    ///
    /// # Errors
    /// As [`CanalSpine::check_real_envelope`].
    pub(crate) fn check_real_envelope(
        &self,
        spine: &CanalSpine<Rational>,
        domain: Option<(&Rational, &Rational)>,
    ) -> Result<(), CanalError> {
        let key = (
            spine.discriminant()?,
            domain.map(|(a, b)| (a.clone(), b.clone())),
        );
        if self.get(&self.real, &key).is_some() {
            return Ok(());
        }
        spine.check_real_envelope(domain)?;
        self.real.put(key, ());
        Ok(())
    }

    /// [`super::sum_of_squares::gaussian_split`], memoized (errors are not).
    ///
    /// # Errors
    /// As [`super::sum_of_squares::gaussian_split`].
    pub(crate) fn gaussian_split(&self, d: &Poly<Rational>) -> Result<GaussianSplit, CanalError> {
        if let Some(v) = self.get(&self.splits, d) {
            return Ok(v);
        }
        let v = super::sum_of_squares::gaussian_split(d)?;
        self.splits.put(d.clone(), v.clone());
        Ok(v)
    }
}

impl FactorSource<Rational> for FactorMemo {
    fn factors(&self, l: &CPoly<Rational>) -> Vec<CPoly<Rational>> {
        self.gaussian_factors(l)
    }

    fn uses_candidates(&self) -> bool {
        !self.off
    }

    /// The factors of `l` among `candidates` (those that divide `l`), when they are all of
    /// them (their degrees with multiplicity add up to `deg l`) and [`gaussian_factors_of`]
    /// of `l` is known to find all of them too, so that both give the same list: every
    /// square-free part of the norm `l l̄` has degree `≤`
    /// [`rcagd_algebra::factor::MAX_MODULAR_FACTORS`] and the product of the irreducible
    /// factors over `Q` of the norm has a good prime
    /// ([`rcagd_algebra::factor::has_good_prime`]), so no factorization over `Q` of a part
    /// gives up; and the split over `Q(i)` of each of those irreducible factors succeeded
    /// where the candidates came from (a pure function of the factor). The memo without
    /// memory (the tests' reference) always factors.
    fn factors_among(
        &self,
        l: &CPoly<Rational>,
        candidates: &[CPoly<Rational>],
    ) -> Option<Vec<CPoly<Rational>>> {
        use rcagd_algebra::complex::norm_sq_poly;
        use rcagd_algebra::factor::{has_good_prime, MAX_MODULAR_FACTORS};
        if self.off {
            return None;
        }
        let n = l.degree().filter(|&n| n > 0)?;
        // a det seen before (in another frame or method: the monic det is the key)
        let key = l.monic();
        if let Some(v) = self.get(&self.dets, &key) {
            return Some(v);
        }
        // the candidates that divide l, with their multiplicities
        let mut found: Vec<(CPoly<Rational>, usize)> = Vec::new();
        let mut total = 0;
        for h in candidates {
            let d = h.degree().filter(|&d| d > 0)?;
            if found.iter().any(|(f, _)| f == h) {
                continue;
            }
            let mut q = l.clone();
            let mut m = 0;
            while let Ok((quo, rem)) = q.div_rem(h) {
                if !rem.is_zero() {
                    break;
                }
                q = quo;
                m += 1;
            }
            if m > 0 {
                total += m * d;
                found.push((h.clone(), m));
            }
        }
        if total != n {
            return None;
        }
        // the irreducible factors g over Q of the norm with their multiplicities: a real h
        // is g with multiplicity 2m, a complex h gives g = h h̄ (multiplicity m(h) + m(h̄))
        let mut norm_factors: Vec<(Poly<Rational>, usize)> = Vec::new();
        for (h, m) in &found {
            let hc = conj_poly(h);
            let (g, mult) = if &hc == h {
                (re_im_polys(h).0, 2 * m)
            } else {
                let mc = found.iter().find(|(f, _)| f == &hc).map_or(0, |(_, k)| *k);
                (norm_sq_poly(h), m + mc)
            };
            if !norm_factors.iter().any(|(f, _)| f == &g) {
                norm_factors.push((g, mult));
            }
        }
        // the degree of every square-free part (the product of the g of one multiplicity)
        let mut parts: Vec<(usize, usize)> = Vec::new();
        for (g, mult) in &norm_factors {
            let d = g.degree().unwrap_or(0);
            match parts.iter_mut().find(|(k, _)| k == mult) {
                Some(p) => p.1 += d,
                None => parts.push((*mult, d)),
            }
        }
        if parts.iter().any(|&(_, d)| d > MAX_MODULAR_FACTORS) {
            return None;
        }
        let radical = norm_factors
            .iter()
            .fold(Poly::constant(Rational::ONE), |acc, (g, _)| &acc * g);
        if !has_good_prime(&radical) {
            return None;
        }
        // the same list as `gaussian_factors` would store (as a set; the reduction sorts it)
        let v: Vec<CPoly<Rational>> = found.into_iter().map(|(h, _)| h).collect();
        self.dets.put(key, v.clone());
        Some(v)
    }
}

/// Irreducible factors over `K = Q(√d)(i)` of `l ∈ K[t]` that divide `l`
/// ([`rcagd_algebra::factor_ext::factor_biquadratic`]: complete unless a factorization over
/// `Q` gives up; then the factors over `Q(i)` and the `gcd`s with the `Q`-irreducible
/// factors of the norm, which may be reducible over `K`). Empty on failure.
pub(crate) fn biquadratic_factors_of(l: &CPoly<QuadExt>, d: &Rational) -> Vec<CPoly<QuadExt>> {
    match rcagd_algebra::factor_ext::factor_biquadratic(l, d) {
        Ok(f) => f.factors,
        Err(_) => Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::canal::AxisChoice;

    fn sorted(mut v: Vec<CPoly<Rational>>) -> Vec<CPoly<Rational>> {
        v.sort_by(|f, g| {
            f.degree()
                .cmp(&g.degree())
                .then_with(|| canonical_cmp(f, g))
        });
        v
    }

    fn gauss(c: &[(i64, i64)]) -> CPoly<Rational> {
        Poly::new(
            c.iter()
                .map(|&(re, im)| Complex::new(Rational::from(re), Rational::from(im)))
                .collect(),
        )
    }

    /// `l = h₁² h₂ h̄₁ h₃` and the candidates from the factors of `h₁`, `h₂`, `h₃` and their
    /// conjugates: [`FactorSource::factors_among`] of the memo finds the factorization's
    /// list (as a set), or declines.
    fn among_agrees(h: [CPoly<Rational>; 3]) -> bool {
        let memo = FactorMemo::default();
        let l = &(&(&(&h[0] * &h[0]) * &h[1]) * &conj_poly(&h[0])) * &h[2];
        let mut cands: Vec<CPoly<Rational>> = Vec::new();
        for p in &h {
            for f in gaussian_factors_of(p) {
                for f in [conj_poly(&f), f] {
                    if !cands.contains(&f) {
                        cands.push(f);
                    }
                }
            }
        }
        match memo.factors_among(&l, &cands) {
            Some(v) => {
                assert_eq!(sorted(v), sorted(gaussian_factors_of(&l)));
                true
            }
            None => false,
        }
    }

    #[test]
    fn factors_among_candidates_are_the_factors() {
        // (t − i)² (t² + 2)(t + i)(t + 1 + 2i)
        assert!(among_agrees([
            gauss(&[(0, -1), (1, 0)]),
            gauss(&[(2, 0), (0, 0), (1, 0)]),
            gauss(&[(1, 2), (1, 0)]),
        ]));
        // a candidate list that misses a factor: declined
        let memo = FactorMemo::default();
        let l = &gauss(&[(0, -1), (1, 0)]) * &gauss(&[(3, 0), (1, 0)]);
        assert!(memo
            .factors_among(&l, &[gauss(&[(0, -1), (1, 0)])])
            .is_none());
        // the reference memo never answers
        assert!(FactorMemo::off()
            .factors_among(&l, &gaussian_factors_of(&l))
            .is_none());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]

        /// Random Gaussian polynomials of degree 1 to 3: the candidates' answer is the
        /// factorization's whenever it answers.
        #[test]
        fn factors_among_agrees_with_the_factorization(
            c in proptest::collection::vec((-4i64..5, -4i64..5), 9),
            d in proptest::collection::vec(1usize..4, 3),
        ) {
            let h: [CPoly<Rational>; 3] = core::array::from_fn(|k| {
                let mut v: Vec<(i64, i64)> = c[3 * k..3 * k + d[k]].to_vec();
                v.push((1, 0));
                gauss(&v)
            });
            among_agrees(h);
        }
    }

    #[test]
    fn pencil_is_isotropic_and_reduces() {
        // ring torus: circle spine (1 − t², 2t, 0)/(1 + t²), r = 1/2
        let w = Poly::from_ints(&[1, 0, 1]);
        let m = [
            Poly::from_ints(&[1, 0, -1]),
            Poly::from_ints(&[0, 2]),
            Poly::zero(),
        ];
        let r = w.scale(&Rational::from_ratio(1, 2));
        let spine = CanalSpine::new(w, m, r).expect("spine");
        let p = spine.derivative_numerators().expect("P");
        let d = spine.discriminant().expect("D");
        // P = (−4t, 2 − 2t², 0, 0), D = 4(1 + t²)²: w = 2(1 + t²)
        assert_eq!(d, Poly::from_ints(&[4, 0, 8, 0, 4]));
        let g = [Poly::from_ints(&[2, 0, 2]), Poly::zero()];
        let axis = AxisChoice {
            axis: 0,
            positive: true,
        };
        let pencil =
            reduced_pencil(&p, &g, axis, &FnFactors(&gaussian_factors_of)).expect("pencil");
        assert!(pencil.degree() < pencil.initial_degree || pencil.degree() <= 1);
        // Bᵀ f_s ≡ 0
        let s = pencil.sphere_image();
        let j = 0;
        let (ia, ib) = (1, 2);
        let b0 = &p[3];
        let plane = s[0]
            .mul_t(b0)
            .add(&s[1].mul_t(&p[ia]))
            .add(&s[2].mul_t(&p[ib]))
            .add(&s[3].mul_t(&p[j]));
        assert!(plane.is_zero());
        // sphere identity: x0² = xr² + xi² + xd²
        let lhs = s[0].mul(&s[0]);
        let rhs = s[1].mul(&s[1]).add(&s[2].mul(&s[2])).add(&s[3].mul(&s[3]));
        assert!(lhs.sub(&rhs).is_zero());
        assert!(!has_interior_base_point(&pencil, &d).expect("roots"));
    }
}
