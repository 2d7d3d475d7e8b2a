//! Sparse multivariate polynomials over any [`Ring`].
//!
//! `MPoly { nvars, terms }` stores `Σ c_e x₀^{e₀} x₁^{e₁} ⋯ x_{n−1}^{e_{n−1}}` as a map
//! from exponent vectors `e` (length `nvars`) to non-zero coefficients `c_e`; the map
//! is ordered lexicographically by exponent vector (ascending), which is the order of
//! [`MPoly::terms`]. The variables commute with each other and with the coefficients;
//! for non-commutative coefficients products keep the order of the factors,
//! `(Σ a_e xᵉ)(Σ b_f xᶠ) = Σ (a_e b_f) x^{e+f}`.
//!
//! **Mixed numbers of variables.** A polynomial in `x₀, …, x_{k−1}` is also a polynomial in
//! `x₀, …, x_{n−1}` for `n ≥ k`. Arithmetic on operands with different `nvars` pads the
//! smaller one with absent variables (the result has the larger `nvars`), and equality
//! compares the padded polynomials, so `MPoly::zero(2) == MPoly::zero(3)`. This makes
//! `MPoly<R>` a [`Ring`] whose `zero()`, `one()` and `from_i64` have `nvars = 0`, so
//! `Poly<MPoly<R>>` (a polynomial in one distinguished variable with multivariate
//! coefficients, [`MPoly::to_univariate_in`]) works.
//!
//! Exponents are `u32`; sums of exponents saturate at `u32::MAX` (degrees of 2³² and
//! above are outside the supported range). Conversions to dense univariate form
//! refuse degrees above [`MAX_DENSE_DEGREE`] instead of exhausting memory.
//!
//! Elimination: [`resultant_in`] eliminates one variable from two polynomials in two
//! variables, `Res_{x_var}(f, g) ∈ ℚ[x_other]`, via [`crate::resultant::resultant_poly`].

use crate::error::AlgebraError;
use crate::poly::Poly;
use crate::rational::Rational;
use crate::resultant::resultant_poly;
use crate::scalar::{ring_pow, Ring};
use core::fmt;
use core::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::borrow::Cow;
use std::collections::BTreeMap;

/// The largest degree that conversions to dense univariate polynomials accept.
pub const MAX_DENSE_DEGREE: u32 = 1 << 24;

/// A sparse multivariate polynomial in `x₀, …, x_{nvars−1}`; no zero coefficients are
/// stored.
#[derive(Debug, Clone)]
pub struct MPoly<R> {
    nvars: usize,
    terms: BTreeMap<Vec<u32>, R>,
}

fn add_exps(a: &[u32], b: &[u32], n: usize) -> Vec<u32> {
    (0..n)
        .map(|i| {
            let x = a.get(i).copied().unwrap_or(0);
            let y = b.get(i).copied().unwrap_or(0);
            x.saturating_add(y)
        })
        .collect()
}

impl<R: Ring> MPoly<R> {
    /// The zero polynomial in `nvars` variables.
    pub fn zero(nvars: usize) -> Self {
        MPoly {
            nvars,
            terms: BTreeMap::new(),
        }
    }

    /// The constant `c` in `nvars` variables.
    pub fn constant(nvars: usize, c: R) -> Self {
        let mut p = MPoly::zero(nvars);
        if !c.is_zero() {
            p.terms.insert(vec![0; nvars], c);
        }
        p
    }

    /// The variable `xᵢ`. If `i ≥ nvars` the result has `i + 1` variables (it is a
    /// programming error, handled without panicking).
    pub fn var(nvars: usize, i: usize) -> Self {
        let n = nvars.max(i.saturating_add(1));
        let mut e = vec![0; n];
        e[i] = 1;
        let mut p = MPoly::zero(n);
        p.terms.insert(e, R::one());
        p
    }

    /// The polynomial `Σ c·xᵉ` from `(e, c)` pairs; like terms are summed and zero sums
    /// dropped.
    ///
    /// # Errors
    /// [`AlgebraError::Mismatch`] if an exponent vector does not have length `nvars`.
    pub fn from_terms(nvars: usize, terms: Vec<(Vec<u32>, R)>) -> Result<Self, AlgebraError> {
        let mut p = MPoly::zero(nvars);
        for (e, c) in terms {
            if e.len() != nvars {
                return Err(AlgebraError::Mismatch(format!(
                    "exponent vector {e:?} has length {}, expected nvars = {nvars}",
                    e.len()
                )));
            }
            p.add_term(e, c);
        }
        Ok(p)
    }

    /// The monomial `c·xᵉ`; `e` is padded or must fit `nvars` (a longer `e` raises
    /// `nvars` to its length).
    pub fn monomial(nvars: usize, e: &[u32], c: R) -> Self {
        let n = nvars.max(e.len());
        let mut p = MPoly::zero(n);
        p.add_term(add_exps(e, &[], n), c);
        p
    }

    /// Adds `c·xᵉ` (`e` of length `nvars`), removing the term if it cancels.
    fn add_term(&mut self, e: Vec<u32>, c: R) {
        if c.is_zero() {
            return;
        }
        match self.terms.get_mut(&e) {
            Some(v) => {
                *v += c;
                if v.is_zero() {
                    self.terms.remove(&e);
                }
            }
            None => {
                self.terms.insert(e, c);
            }
        }
    }

    /// Adds `c·xᵉ` for a borrowed exponent vector `e` (length `nvars`): the key is
    /// allocated only when the monomial is new.
    fn add_term_ref(&mut self, e: &[u32], c: R) {
        if c.is_zero() {
            return;
        }
        match self.terms.get_mut(e) {
            Some(v) => {
                *v += c;
                if v.is_zero() {
                    self.terms.remove(e);
                }
            }
            None => {
                self.terms.insert(e.to_vec(), c);
            }
        }
    }

    /// The polynomial of terms given in ascending order of their (distinct) exponent
    /// vectors of length `nvars`; zero coefficients are dropped (one bulk build of the
    /// map instead of a search per term).
    fn from_sorted_terms(nvars: usize, terms: impl IntoIterator<Item = (Vec<u32>, R)>) -> Self {
        MPoly {
            nvars,
            terms: terms.into_iter().filter(|(_, c)| !c.is_zero()).collect(),
        }
    }

    /// The number of variables.
    pub fn nvars(&self) -> usize {
        self.nvars
    }

    /// The terms `(e, c)`, exponent vectors in ascending lexicographic order.
    pub fn terms(&self) -> impl Iterator<Item = (&[u32], &R)> {
        self.terms.iter().map(|(e, c)| (e.as_slice(), c))
    }

    /// The number of (non-zero) terms.
    pub fn num_terms(&self) -> usize {
        self.terms.len()
    }

    /// The coefficient of `xᵉ` (zero if absent; `e` is compared after padding).
    pub fn coeff(&self, e: &[u32]) -> R {
        if e.len() > self.nvars && e[self.nvars..].iter().any(|&k| k != 0) {
            return R::zero();
        }
        let key = add_exps(e, &[], self.nvars);
        self.terms.get(&key).cloned().unwrap_or_else(R::zero)
    }

    /// `true` for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The total degree `max Σᵢ eᵢ` over the terms; `None` for the zero polynomial.
    pub fn total_degree(&self) -> Option<usize> {
        self.terms
            .keys()
            .map(|e| e.iter().map(|&k| k as usize).sum())
            .max()
    }

    /// The degree in `xᵢ`; `None` for the zero polynomial (0 if `xᵢ` does not occur).
    pub fn degree_in(&self, i: usize) -> Option<u32> {
        self.terms
            .keys()
            .map(|e| e.get(i).copied().unwrap_or(0))
            .max()
    }

    /// `true` if all terms have the same total degree (the zero polynomial is
    /// homogeneous).
    pub fn is_homogeneous(&self) -> bool {
        let mut degs = self
            .terms
            .keys()
            .map(|e| e.iter().map(|&k| k as usize).sum::<usize>());
        match degs.next() {
            None => true,
            Some(d) => degs.all(|x| x == d),
        }
    }

    /// The value `Σ c_e ∏ᵢ xᵢ^{eᵢ}` (coefficient on the left of the monomial).
    ///
    /// # Errors
    /// [`AlgebraError::Mismatch`] if `x.len() != nvars`.
    pub fn eval(&self, x: &[R]) -> Result<R, AlgebraError> {
        if x.len() != self.nvars {
            return Err(AlgebraError::Mismatch(format!(
                "eval: {} values for {} variables",
                x.len(),
                self.nvars
            )));
        }
        let mut cache: BTreeMap<(usize, u32), R> = BTreeMap::new();
        let mut acc = R::zero();
        for (e, c) in &self.terms {
            let mut t = c.clone();
            for (i, &k) in e.iter().enumerate() {
                if k == 0 {
                    continue;
                }
                let pw = cache
                    .entry((i, k))
                    .or_insert_with(|| ring_pow(&x[i], k as usize))
                    .clone();
                t *= pw;
            }
            acc += t;
        }
        Ok(acc)
    }

    /// The partial derivative `∂/∂xᵢ` (zero if `i ≥ nvars`).
    pub fn partial(&self, i: usize) -> Self {
        // lowering xᵢ's exponent by one keeps the lexicographic order of the terms with xᵢ
        let terms = self.terms.iter().filter_map(|(e, c)| {
            let k = *e.get(i)?;
            if k == 0 {
                return None;
            }
            let mut f = e.clone();
            f[i] = k - 1;
            Some((f, R::from_i64(i64::from(k)) * c.clone()))
        });
        MPoly::from_sorted_terms(self.nvars, terms)
    }

    /// Multiplies every coefficient by `c` on the right.
    pub fn scale(&self, c: &R) -> Self {
        if c.is_zero() {
            return MPoly::zero(self.nvars);
        }
        let terms = self
            .terms
            .iter()
            .map(|(e, a)| (e.clone(), a.clone() * c.clone()));
        MPoly::from_sorted_terms(self.nvars, terms)
    }

    /// `selfᵏ` (`self⁰ = 1`), by repeated squaring.
    pub fn pow(&self, k: u32) -> Self {
        let mut result = MPoly::constant(self.nvars, R::one());
        let mut base = self.clone();
        let mut e = k;
        while e > 0 {
            if e & 1 == 1 {
                result = &result * &base;
            }
            e >>= 1;
            if e > 0 {
                base = &base * &base;
            }
        }
        result
    }

    /// Applies `f` to every coefficient (zero images are dropped).
    pub fn map<S: Ring>(&self, f: impl Fn(&R) -> S) -> MPoly<S> {
        MPoly::from_sorted_terms(
            self.nvars,
            self.terms.iter().map(|(e, c)| (e.clone(), f(c))),
        )
    }

    /// The univariate polynomial `p(x₀(t), …, x_{n−1}(t))`.
    ///
    /// # Errors
    /// [`AlgebraError::Mismatch`] if `x.len() != nvars`; [`AlgebraError::InvalidArgument`]
    /// if the result degree bound `maxₑ Σᵢ eᵢ·deg xᵢ` exceeds [`MAX_DENSE_DEGREE`].
    pub fn substitute_univariate(&self, x: &[Poly<R>]) -> Result<Poly<R>, AlgebraError> {
        if x.len() != self.nvars {
            return Err(AlgebraError::Mismatch(format!(
                "substitute_univariate: {} polynomials for {} variables",
                x.len(),
                self.nvars
            )));
        }
        let bound = self
            .terms
            .keys()
            .map(|e| {
                e.iter()
                    .zip(x)
                    .map(|(&k, xi)| u128::from(k) * xi.degree().unwrap_or(0) as u128)
                    .sum::<u128>()
            })
            .max()
            .unwrap_or(0);
        if bound > u128::from(MAX_DENSE_DEGREE) {
            return Err(AlgebraError::InvalidArgument(format!(
                "substitute_univariate: result degree {bound} exceeds {MAX_DENSE_DEGREE}"
            )));
        }
        let mut cache: BTreeMap<(usize, u32), Poly<R>> = BTreeMap::new();
        let mut acc = Poly::zero();
        for (e, c) in &self.terms {
            let mut t = Poly::constant(c.clone());
            for (i, &k) in e.iter().enumerate() {
                if k == 0 {
                    continue;
                }
                let pw = cache.entry((i, k)).or_insert_with(|| x[i].pow(k));
                t = &t * pw;
            }
            acc = &acc + &t;
        }
        Ok(acc)
    }

    /// Substitutes the value `v` for `xᵢ` (the result keeps `nvars`, without `xᵢ`);
    /// `i ≥ nvars` returns `self`.
    pub fn specialize(&self, i: usize, v: &R) -> Self {
        if i >= self.nvars {
            return self.clone();
        }
        let mut p = MPoly::zero(self.nvars);
        for (e, c) in &self.terms {
            let mut f = e.clone();
            f[i] = 0;
            p.add_term(f, c.clone() * ring_pow(v, e[i] as usize));
        }
        p
    }

    /// The homogenization `x_n^{d} p(x₀/x_n, …)` in `nvars + 1` variables, `d` the total
    /// degree; the new variable is `x_{nvars}`.
    pub fn homogenize(&self) -> Self {
        let d = self.total_degree().unwrap_or(0);
        let mut p = MPoly::zero(self.nvars + 1);
        for (e, c) in &self.terms {
            let s: usize = e.iter().map(|&k| k as usize).sum();
            let mut f = e.clone();
            f.push(u32::try_from(d - s).unwrap_or(u32::MAX));
            p.add_term(f, c.clone());
        }
        p
    }

    /// The polynomial `p(t)` placed in the variable `x_var` of a polynomial with
    /// `max(nvars, var + 1)` variables.
    pub fn from_poly(p: &Poly<R>, nvars: usize, var: usize) -> Self {
        let n = nvars.max(var.saturating_add(1));
        let mut out = MPoly::zero(n);
        for (k, c) in p.coeffs().iter().enumerate() {
            let mut e = vec![0; n];
            e[var] = u32::try_from(k).unwrap_or(u32::MAX);
            out.add_term(e, c.clone());
        }
        out
    }

    /// `self` as a polynomial in `x_var` whose coefficients are polynomials in the other
    /// variables: `Σₖ cₖ x_varᵏ`, each `cₖ` with the same `nvars` and no `x_var`.
    ///
    /// # Errors
    /// [`AlgebraError::InvalidArgument`] if the degree in `x_var` exceeds
    /// [`MAX_DENSE_DEGREE`].
    pub fn to_univariate_in(&self, var: usize) -> Result<Poly<MPoly<R>>, AlgebraError> {
        let d = self.degree_in(var).unwrap_or(0);
        if d > MAX_DENSE_DEGREE {
            return Err(AlgebraError::InvalidArgument(format!(
                "to_univariate_in: degree {d} exceeds {MAX_DENSE_DEGREE}"
            )));
        }
        let mut coeffs = vec![MPoly::zero(self.nvars); d as usize + 1];
        for (e, c) in &self.terms {
            let k = e.get(var).copied().unwrap_or(0) as usize;
            let mut f = e.clone();
            if let Some(x) = f.get_mut(var) {
                *x = 0;
            }
            coeffs[k].add_term(f, c.clone());
        }
        Ok(Poly::new(coeffs))
    }

    /// The inverse of [`MPoly::to_univariate_in`]: `Σₖ cₖ x_varᵏ` (the result has the
    /// largest `nvars` of the coefficients and `var + 1`).
    pub fn from_univariate_in(p: &Poly<MPoly<R>>, var: usize) -> Self {
        let n = p
            .coeffs()
            .iter()
            .map(|c| c.nvars)
            .max()
            .unwrap_or(0)
            .max(var.saturating_add(1));
        let mut out = MPoly::zero(n);
        for (k, c) in p.coeffs().iter().enumerate() {
            let kk = u32::try_from(k).unwrap_or(u32::MAX);
            for (e, a) in &c.terms {
                let mut f = add_exps(e, &[], n);
                f[var] = f[var].saturating_add(kk);
                out.add_term(f, a.clone());
            }
        }
        out
    }

    /// The bivariate view `Σᵢ (Σⱼ c_{ij} tʲ) xⁱ` with `x = x_outer`, `t = x_inner`: a
    /// polynomial in `x_outer` with coefficients polynomials in `x_inner`.
    ///
    /// # Errors
    /// [`AlgebraError::InvalidArgument`] if `outer == inner`, if another variable occurs,
    /// or if a degree exceeds [`MAX_DENSE_DEGREE`].
    pub fn to_bivariate(&self, outer: usize, inner: usize) -> Result<Poly<Poly<R>>, AlgebraError> {
        if outer == inner {
            return Err(AlgebraError::InvalidArgument(
                "to_bivariate: the two variables must differ".into(),
            ));
        }
        let dout = self.degree_in(outer).unwrap_or(0);
        let din = self.degree_in(inner).unwrap_or(0);
        if dout > MAX_DENSE_DEGREE || din > MAX_DENSE_DEGREE {
            return Err(AlgebraError::InvalidArgument(format!(
                "to_bivariate: degrees ({dout}, {din}) exceed {MAX_DENSE_DEGREE}"
            )));
        }
        let mut rows: Vec<Vec<R>> = vec![Vec::new(); dout as usize + 1];
        for (e, c) in &self.terms {
            if let Some(v) = e
                .iter()
                .enumerate()
                .position(|(i, &k)| k != 0 && i != outer && i != inner)
            {
                return Err(AlgebraError::InvalidArgument(format!(
                    "to_bivariate: the variable x{v} occurs besides x{outer} and x{inner}"
                )));
            }
            let i = e.get(outer).copied().unwrap_or(0) as usize;
            let j = e.get(inner).copied().unwrap_or(0) as usize;
            let row = &mut rows[i];
            if row.len() <= j {
                row.resize(j + 1, R::zero());
            }
            row[j] += c.clone();
        }
        Ok(Poly::new(rows.into_iter().map(Poly::new).collect()))
    }

    /// Pads to `n ≥ nvars` variables.
    fn padded(&self, n: usize) -> Cow<'_, MPoly<R>> {
        if n <= self.nvars {
            return Cow::Borrowed(self);
        }
        Cow::Owned(MPoly {
            nvars: n,
            terms: self
                .terms
                .iter()
                .map(|(e, c)| (add_exps(e, &[], n), c.clone()))
                .collect(),
        })
    }
}

/// The resultant `Res_{x_var}(f, g)` of two polynomials in `x_var` and (at most) one other
/// variable `y`, as a polynomial in `y`: `det Sylₘ,ₙ(f, g)` with `m = deg_{x_var} f`,
/// `n = deg_{x_var} g` (see [`resultant_poly`]). `R(y₀) = 0` iff `f(·, y₀)` and
/// `g(·, y₀)` have a common root or both leading coefficients vanish at `y₀`; the
/// projection of the common zeros of `f` and `g` onto the `y`-axis lies in the zeros of
/// `R`. A zero `f` or `g` gives the zero polynomial.
///
/// # Errors
/// [`AlgebraError::InvalidArgument`] if, besides `x_var`, more than one variable occurs in
/// `f` and `g` together, or a degree exceeds [`MAX_DENSE_DEGREE`].
pub fn resultant_in(
    f: &MPoly<Rational>,
    g: &MPoly<Rational>,
    var: usize,
) -> Result<Poly<Rational>, AlgebraError> {
    let mut others: Vec<usize> = f
        .terms()
        .chain(g.terms())
        .flat_map(|(e, _)| {
            e.iter()
                .enumerate()
                .filter(|&(i, &k)| k != 0 && i != var)
                .map(|(i, _)| i)
                .collect::<Vec<_>>()
        })
        .collect();
    others.sort_unstable();
    others.dedup();
    if others.len() > 1 {
        return Err(AlgebraError::InvalidArgument(format!(
            "resultant_in: eliminating x{var} needs bivariate input, but x{others:?} occur besides it"
        )));
    }
    let other = others
        .first()
        .copied()
        .unwrap_or(if var == 0 { 1 } else { 0 });
    let fb = f.to_bivariate(var, other)?;
    let gb = g.to_bivariate(var, other)?;
    Ok(resultant_poly(&fb, &gb))
}

impl<R: Ring> PartialEq for MPoly<R> {
    /// Equality as polynomials (the operand with fewer variables is padded).
    fn eq(&self, other: &Self) -> bool {
        let n = self.nvars.max(other.nvars);
        self.padded(n).terms == other.padded(n).terms
    }
}

impl<R: Ring> Add for &MPoly<R> {
    type Output = MPoly<R>;
    fn add(self, rhs: &MPoly<R>) -> MPoly<R> {
        merge_add(self, rhs, false)
    }
}
impl<R: Ring> Sub for &MPoly<R> {
    type Output = MPoly<R>;
    fn sub(self, rhs: &MPoly<R>) -> MPoly<R> {
        merge_add(self, rhs, true)
    }
}

/// The lexicographic order of two exponent vectors padded with zeros to equal length.
fn cmp_padded(a: &[u32], b: &[u32]) -> core::cmp::Ordering {
    let n = a.len().max(b.len());
    (0..n)
        .map(|i| {
            let x = a.get(i).copied().unwrap_or(0);
            let y = b.get(i).copied().unwrap_or(0);
            x.cmp(&y)
        })
        .find(|o| o.is_ne())
        .unwrap_or(core::cmp::Ordering::Equal)
}

/// `a + b` (or `a − b` with `negate`) by one merge of the two ordered term lists.
fn merge_add<R: Ring>(a: &MPoly<R>, b: &MPoly<R>, negate: bool) -> MPoly<R> {
    use core::cmp::Ordering;
    let n = a.nvars.max(b.nvars);
    let key = |e: &Vec<u32>| {
        if e.len() == n {
            e.clone()
        } else {
            add_exps(e, &[], n)
        }
    };
    let sign = |c: &R| if negate { -c.clone() } else { c.clone() };
    let mut out = Vec::with_capacity(a.terms.len() + b.terms.len());
    let mut ia = a.terms.iter().peekable();
    let mut ib = b.terms.iter().peekable();
    loop {
        let ord = match (ia.peek(), ib.peek()) {
            (Some((ea, _)), Some((eb, _))) => cmp_padded(ea, eb),
            (Some(_), None) => Ordering::Less,
            (None, Some(_)) => Ordering::Greater,
            (None, None) => break,
        };
        match (ord, ia.peek(), ib.peek()) {
            (Ordering::Less, Some(&(e, c)), _) => {
                out.push((key(e), c.clone()));
                ia.next();
            }
            (Ordering::Greater, _, Some(&(e, c))) => {
                out.push((key(e), sign(c)));
                ib.next();
            }
            (Ordering::Equal, Some(&(e, c)), Some(&(_, d))) => {
                let v = if negate {
                    c.clone() - d.clone()
                } else {
                    c.clone() + d.clone()
                };
                out.push((key(e), v));
                ia.next();
                ib.next();
            }
            _ => break,
        }
    }
    MPoly::from_sorted_terms(n, out)
}

/// The exponent vectors of a product laid out densely: result degree `dᵢ` per variable,
/// index `Σ eᵢ·strideᵢ` with `x₀` most significant, so ascending indices are ascending
/// lexicographic exponent vectors, and the index of `e + f` is the sum of the indices.
struct DenseLayout {
    dims: Vec<usize>,
    strides: Vec<usize>,
    size: usize,
}

impl DenseLayout {
    /// The layout of the products of `a`'s and `b`'s exponent vectors in `n` variables,
    /// if its size is at most `4·|a|·|b| + 64` (else a sparse accumulation is cheaper).
    fn new(a: &[&[u32]], b: &[&[u32]], n: usize) -> Option<Self> {
        let deg = |v: &[&[u32]], i: usize| v.iter().map(|e| e.get(i).copied().unwrap_or(0)).max();
        let limit = a
            .len()
            .saturating_mul(b.len())
            .saturating_mul(4)
            .saturating_add(64);
        let mut dims = vec![0usize; n];
        let mut size = 1usize;
        for (i, d) in dims.iter_mut().enumerate() {
            let di = usize::try_from(deg(a, i)?)
                .ok()?
                .checked_add(usize::try_from(deg(b, i)?).ok()?)?
                .checked_add(1)?;
            *d = di;
            size = size.checked_mul(di)?;
            if size > limit {
                return None;
            }
        }
        let mut strides = vec![1usize; n];
        for i in (0..n.saturating_sub(1)).rev() {
            strides[i] = strides[i + 1] * dims[i + 1];
        }
        Some(DenseLayout {
            dims,
            strides,
            size,
        })
    }

    fn index(&self, e: &[u32]) -> usize {
        e.iter()
            .zip(&self.strides)
            .map(|(&k, s)| k as usize * s)
            .sum()
    }

    fn exponents(&self, mut idx: usize) -> Vec<u32> {
        let mut e = vec![0u32; self.dims.len()];
        for i in (0..self.dims.len()).rev() {
            // each digit is below its dimension, which came from a sum of u32 exponents + 1
            e[i] = u32::try_from(idx % self.dims[i]).unwrap_or(u32::MAX);
            idx /= self.dims[i];
        }
        e
    }
}

/// The terms of `Σᵢⱼ (term i of a)(term j of b)`: `add(acc, i, j)` adds the product of
/// the coefficients `i` of `a` and `j` of `b` into the accumulator `acc` of their
/// monomial; the result's terms in ascending order, zero sums dropped. A dense array
/// when the exponents are dense enough ([`DenseLayout`]), else an ordered map.
fn accumulate_product<T: Clone>(
    a: &[&[u32]],
    b: &[&[u32]],
    n: usize,
    zero: T,
    mut add: impl FnMut(&mut T, usize, usize),
    is_zero: impl Fn(&T) -> bool,
) -> Vec<(Vec<u32>, T)> {
    if let Some(layout) = DenseLayout::new(a, b, n) {
        let ib: Vec<usize> = b.iter().map(|e| layout.index(e)).collect();
        let mut acc = vec![zero; layout.size];
        for (i, ea) in a.iter().enumerate() {
            crate::budget::checkpoint();
            let base = layout.index(ea);
            for (j, &k) in ib.iter().enumerate() {
                add(&mut acc[base + k], i, j);
            }
        }
        return acc
            .into_iter()
            .enumerate()
            .filter(|(_, c)| !is_zero(c))
            .map(|(k, c)| (layout.exponents(k), c))
            .collect();
    }
    let mut acc: BTreeMap<Vec<u32>, T> = BTreeMap::new();
    let mut buf = vec![0u32; n];
    for (i, ea) in a.iter().enumerate() {
        crate::budget::checkpoint();
        for (j, eb) in b.iter().enumerate() {
            for (t, x) in buf.iter_mut().enumerate() {
                let p = ea.get(t).copied().unwrap_or(0);
                let q = eb.get(t).copied().unwrap_or(0);
                *x = p.saturating_add(q);
            }
            match acc.get_mut(buf.as_slice()) {
                Some(c) => add(c, i, j),
                None => {
                    let mut c = zero.clone();
                    add(&mut c, i, j);
                    acc.insert(buf.clone(), c);
                }
            }
        }
    }
    acc.into_iter().filter(|(_, c)| !is_zero(c)).collect()
}

/// The generic product: coefficients multiplied and summed in `R`.
fn mul_generic<R: Ring>(a: &MPoly<R>, b: &MPoly<R>) -> MPoly<R> {
    let n = a.nvars.max(b.nvars);
    let (ae, ac): (Vec<&[u32]>, Vec<&R>) = a.terms.iter().map(|(e, c)| (e.as_slice(), c)).unzip();
    let (be, bc): (Vec<&[u32]>, Vec<&R>) = b.terms.iter().map(|(e, c)| (e.as_slice(), c)).unzip();
    let terms = accumulate_product(
        &ae,
        &be,
        n,
        R::zero(),
        |acc, i, j| *acc += ac[i].clone() * bc[j].clone(),
        |c| c.is_zero(),
    );
    MPoly::from_sorted_terms(n, terms)
}

/// The coefficients of `p` as integers over one common denominator `L` (the least
/// common multiple of the denominators): `p = (Σ Aₑ xᵉ)/L`.
fn integer_coefficients(p: &MPoly<Rational>) -> (Vec<dashu_int::IBig>, dashu_int::UBig) {
    integers_over_common_denominator(p.terms.values())
}

/// The integers `Aᵢ` and the common denominator `L` (least common multiple of the
/// denominators) with `cᵢ = Aᵢ/L`.
fn integers_over_common_denominator<'a>(
    cs: impl Iterator<Item = &'a Rational> + Clone,
) -> (Vec<dashu_int::IBig>, dashu_int::UBig) {
    use dashu_int::{IBig, UBig};
    let mut l = UBig::ONE;
    for c in cs.clone() {
        let d = c.denominator();
        if d != &UBig::ONE && d != &l {
            let g = dashu_base::Gcd::gcd(&l, d);
            l = &l / &g * d;
        }
    }
    let ints = cs
        .map(|c| {
            let d = c.denominator();
            if d == &l {
                c.numerator().clone()
            } else {
                c.numerator() * IBig::from(&l / d)
            }
        })
        .collect();
    (ints, l)
}

/// The product of two dense univariate coefficient vectors over `ℚ` (constant term
/// first), fraction-free like [`mul_rational`]: integer convolution over the two common
/// denominators, one reduction per result coefficient.
pub(crate) fn poly_mul_rational(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    use dashu_int::IBig;
    let (ia, la) = integers_over_common_denominator(a.iter());
    let (ib, lb) = integers_over_common_denominator(b.iter());
    let mut out = vec![IBig::ZERO; (a.len() + b.len()).saturating_sub(1)];
    for (i, x) in ia.iter().enumerate() {
        if x == &IBig::ZERO {
            continue;
        }
        crate::budget::checkpoint();
        for (j, y) in ib.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    let den = la * lb;
    let one = den == dashu_int::UBig::ONE;
    out.into_iter()
        .map(|c| {
            if one {
                Rational::from(c)
            } else {
                Rational::from_parts(c, den.clone())
            }
        })
        .collect()
}

/// The product of two polynomials over `ℚ`, fraction-free: `(A/L)(B/M) = (AB)/(LM)` with
/// the integer coefficient vectors `A`, `B` over one common denominator per factor
/// ([`integer_coefficients`]), products and sums of integers only, and one reduction per
/// result coefficient (instead of a gcd per product and per sum). Exact: the same
/// polynomial as the term-by-term product.
pub(crate) fn mul_rational(a: &MPoly<Rational>, b: &MPoly<Rational>) -> MPoly<Rational> {
    use dashu_int::IBig;
    let n = a.nvars.max(b.nvars);
    let (ia, la) = integer_coefficients(a);
    let (ib, lb) = integer_coefficients(b);
    let ae: Vec<&[u32]> = a.terms.keys().map(Vec::as_slice).collect();
    let be: Vec<&[u32]> = b.terms.keys().map(Vec::as_slice).collect();
    let terms = accumulate_product(
        &ae,
        &be,
        n,
        IBig::ZERO,
        |acc, i, j| *acc += &ia[i] * &ib[j],
        |c| c == &IBig::ZERO,
    );
    let den = la * lb;
    let one = den == dashu_int::UBig::ONE;
    MPoly::from_sorted_terms(
        n,
        terms.into_iter().map(|(e, c)| {
            let q = if one {
                Rational::from(c)
            } else {
                Rational::from_parts(c, den.clone())
            };
            (e, q)
        }),
    )
}

/// The exact quotient `p/d` over `ℚ` if `d` divides `p` (`None` if it does not, or `d` is
/// zero), with `max(nvars(p), nvars(d), min_vars)` variables: the same polynomial as the
/// lexicographic division in `ℚ[x]` (leading term = largest exponent vector), computed
/// **fraction-free**. With `p = P/L_p`, `d = c·D/L_d` (`P`, `D` integer coefficient
/// vectors over common denominators, `c` the content of `c·D`, `D` primitive), Gauss's
/// lemma makes `Q = P/D` an integer polynomial whenever `d | p`, so the division runs on
/// integers: each quotient coefficient is an exact integer quotient of leading
/// coefficients (a non-exact one proves `d ∤ p`), the remainder is updated by integer
/// products, and `p/d = Q·L_d/(c·L_p)` takes one reduction per coefficient (Geddes,
/// Czapor, Labahn, *Algorithms for Computer Algebra*, 1992, §2.8 on Gauss's lemma, §2.9
/// on the multivariate division). The remainder lives in a dense array over `p`'s degree
/// box when that box has at most `64·|p| + 4096` entries, else in an ordered map.
pub fn div_exact_rational(
    p: &MPoly<Rational>,
    d: &MPoly<Rational>,
    min_vars: usize,
) -> Option<MPoly<Rational>> {
    use dashu_int::{IBig, UBig};
    let nv = p.nvars.max(d.nvars).max(min_vars);
    if d.is_zero() {
        return None;
    }
    if p.is_zero() {
        return Some(MPoly::zero(nv));
    }
    let pad = |e: &[u32]| -> Vec<u32> {
        let mut v = e.to_vec();
        v.resize(nv, 0);
        v
    };
    let (pi, lp) = integer_coefficients(p);
    let (mut di, ld) = integer_coefficients(d);
    let cont = di.iter().fold(UBig::ZERO, |g, x| {
        dashu_base::Gcd::gcd(&g, &dashu_base::UnsignedAbs::unsigned_abs(x))
    });
    if cont != UBig::ONE {
        let c = IBig::from(cont.clone());
        for x in di.iter_mut() {
            *x = &*x / &c;
        }
    }
    let de: Vec<Vec<u32>> = d.terms.keys().map(|e| pad(e)).collect();
    let pe: Vec<Vec<u32>> = p.terms.keys().map(|e| pad(e)).collect();
    let (lde, ldc) = (de.last()?.clone(), di.last()?.clone());
    // the degree box of p; d must fit in it
    let dims: Vec<usize> = (0..nv)
        .map(|i| pe.iter().map(|e| e[i] as usize).max().unwrap_or(0) + 1)
        .collect();
    if de
        .iter()
        .any(|e| e.iter().zip(&dims).any(|(&k, &m)| k as usize >= m))
    {
        return None;
    }
    let dmax: Vec<usize> = (0..nv)
        .map(|i| de.iter().map(|e| e[i] as usize).max().unwrap_or(0))
        .collect();
    let size = dims.iter().try_fold(1usize, |a, &m| a.checked_mul(m));
    let limit = pe.len().saturating_mul(64).saturating_add(4096);
    let mut quot: Vec<(Vec<u32>, IBig)> = Vec::new();
    match size {
        Some(size) if size <= limit => {
            let mut strides = vec![1usize; nv];
            for i in (0..nv.saturating_sub(1)).rev() {
                strides[i] = strides[i + 1] * dims[i + 1];
            }
            let index =
                |e: &[u32]| -> usize { e.iter().zip(&strides).map(|(&k, s)| k as usize * s).sum() };
            let mut r = vec![IBig::ZERO; size];
            for (e, c) in pe.iter().zip(pi) {
                r[index(e)] = c;
            }
            let di_idx: Vec<usize> = de.iter().map(|e| index(e)).collect();
            let ld_idx = index(&lde);
            let mut top = size;
            while let Some(i) = (0..top).rev().find(|&i| r[i] != IBig::ZERO) {
                crate::budget::checkpoint();
                top = i + 1;
                // the exponent vector of index i
                let mut e = vec![0u32; nv];
                let mut rest = i;
                for k in (0..nv).rev() {
                    e[k] = u32::try_from(rest % dims[k]).ok()?;
                    rest /= dims[k];
                }
                if e.iter().zip(&lde).any(|(a, b)| a < b) {
                    return None;
                }
                let (t, rem) = (&r[i] / &ldc, &r[i] % &ldc);
                if rem != IBig::ZERO {
                    return None;
                }
                let q: Vec<u32> = e.iter().zip(&lde).map(|(a, b)| a - b).collect();
                // every monomial of q·d stays in p's degree box when d | p (degrees in
                // each variable add up); outside it, d ∤ p
                if q.iter()
                    .zip(&dmax)
                    .zip(&dims)
                    .any(|((&a, &b), &m)| a as usize + b >= m)
                {
                    return None;
                }
                let shift = i - ld_idx;
                for (&k, c) in di_idx.iter().zip(&di) {
                    r[k + shift] -= &t * c;
                }
                quot.push((q, t));
            }
        }
        _ => {
            let mut r: BTreeMap<Vec<u32>, IBig> = pe.into_iter().zip(pi).collect();
            let mut buf = vec![0u32; nv];
            while let Some((e, c)) = r.pop_last() {
                crate::budget::checkpoint();
                if e.iter().zip(&lde).any(|(a, b)| a < b) {
                    return None;
                }
                let (t, rem) = (&c / &ldc, &c % &ldc);
                if rem != IBig::ZERO {
                    return None;
                }
                let q: Vec<u32> = e.iter().zip(&lde).map(|(a, b)| a - b).collect();
                // all terms of t·xᵠ·D but the leading one (which cancels c)
                for (f, dc) in de.iter().zip(&di).rev().skip(1) {
                    for (k, x) in buf.iter_mut().enumerate() {
                        *x = f[k] + q[k];
                    }
                    let v = &t * dc;
                    match r.get_mut(buf.as_slice()) {
                        Some(x) => {
                            *x -= v;
                            if *x == IBig::ZERO {
                                r.remove(buf.as_slice());
                            }
                        }
                        None => {
                            r.insert(buf.clone(), -v);
                        }
                    }
                }
                quot.push((q, t));
            }
        }
    }
    // p/d = Q·L_d/(c·L_p)
    let num = IBig::from(ld);
    let den = lp * cont;
    quot.reverse();
    Some(MPoly::from_sorted_terms(
        nv,
        quot.into_iter()
            .map(|(e, q)| (e, Rational::from_parts(q * &num, den.clone()))),
    ))
}

/// `p(P₀ + s·(e₁ + t·e₂))` as a polynomial in `(s, t)` for a bivariate `p` over `ℚ`
/// (`None` if `p` has other variables than `x₀`, `x₁`): the composition with the map
/// `(s, t) ↦ P₀ + s e₁ + st e₂` that collapses the edge `s = 0` of the unit square to
/// `P₀` (a triangle's parametrization), **fraction-free**. With one common denominator
/// `K` of `P₀` and `e₁, e₂` (`P₀ = A/K`, `s(e₁ + t e₂) = s λ(t)/K` with integer linear
/// `λ`) and `p = Σ cᵢⱼ uⁱvʲ = (Σ Cᵢⱼ uⁱvʲ)/L`:
/// `L Kᵈ p(P₀ + s λ/K) = P̃(A + sλ)` for `P̃ = Σ Cᵢⱼ K^{d−i−j} XⁱYʲ`, `d = m + n`. The
/// integer Taylor shift `S(x, y) = P̃(A + (x, y))` (Horner's shifts of the columns and
/// rows) and, for each homogeneous part `S_k` of `S`, `h_k(t) = S_k(λ_x(t), λ_y(t))` by
/// Horner's rule in `λ_x` give `p(P₀ + s ℓ(t)) = Σ_k sᵏ h_k(t)/(L Kᵈ)`: integer products
/// and sums only, one reduction per result coefficient. The same polynomial as the
/// substitution.
pub fn compose_fan_rational(
    p: &MPoly<Rational>,
    p0: &[Rational; 2],
    e1: &[Rational; 2],
    e2: &[Rational; 2],
) -> Option<MPoly<Rational>> {
    use dashu_int::IBig;
    if p.nvars > 2 && p.terms.keys().any(|e| e[2..].iter().any(|&k| k != 0)) {
        return None;
    }
    if p.is_zero() {
        return Some(MPoly::zero(2));
    }
    let deg = |i: usize| {
        p.terms
            .keys()
            .map(|e| e.get(i).copied().unwrap_or(0) as usize)
            .max()
            .unwrap_or(0)
    };
    let (m, n) = (deg(0), deg(1));
    let d = m + n;
    let (ci, l) = integer_coefficients(p);
    // one common denominator K of P₀, e₁, e₂
    let pts = [&p0[0], &p0[1], &e1[0], &e1[1], &e2[0], &e2[1]];
    let (ints, k) = integers_over_common_denominator(pts.into_iter());
    let kk = IBig::from(k.clone());
    let kpow: Vec<IBig> = std::iter::successors(Some(IBig::ONE), |x| Some(x * &kk))
        .take(d + 1)
        .collect();
    // P̃ dense: c[i][j] = C_ij K^{d−i−j}
    let mut c = vec![vec![IBig::ZERO; n + 1]; m + 1];
    for (e, x) in p.terms.keys().zip(ci) {
        let (i, j) = (
            e.first().copied().unwrap_or(0) as usize,
            e.get(1).copied().unwrap_or(0) as usize,
        );
        c[i][j] = x * &kpow[d - i - j];
    }
    // S(x, y) = P̃(A_u + x, A_v + y): Horner's Taylor shifts
    let shift = |v: &mut [IBig], a: &IBig| {
        let deg = v.len().saturating_sub(1);
        if a == &IBig::ZERO {
            return;
        }
        for r in 0..deg {
            crate::budget::checkpoint();
            for i in (r..deg).rev() {
                let next = &v[i + 1] * a;
                v[i] += next;
            }
        }
    };
    for j in 0..=n {
        let mut col: Vec<IBig> = c.iter().map(|row| row[j].clone()).collect();
        shift(&mut col, &ints[0]);
        for (row, x) in c.iter_mut().zip(col) {
            row[j] = x;
        }
    }
    for row in c.iter_mut() {
        shift(row, &ints[1]);
    }
    // λ_x = E1x + t E2x, λ_y = E1y + t E2y (integers over K)
    let (lx, ly) = ([&ints[2], &ints[4]], [&ints[3], &ints[5]]);
    let times_linear = |acc: &[IBig], a: &IBig, b: &IBig| -> Vec<IBig> {
        let mut next = vec![IBig::ZERO; acc.len() + 1];
        for (q, x) in acc.iter().enumerate() {
            if x == &IBig::ZERO {
                continue;
            }
            next[q] += x * a;
            next[q + 1] += x * b;
        }
        next
    };
    let mut ly_pow: Vec<Vec<IBig>> = vec![vec![IBig::ONE]];
    for j in 1..=n {
        let next = times_linear(&ly_pow[j - 1], ly[0], ly[1]);
        ly_pow.push(next);
    }
    let den = l * k.pow(d);
    let mut terms: Vec<(Vec<u32>, Rational)> = Vec::new();
    for kdeg in 0..=d {
        crate::budget::checkpoint();
        let (lo, hi) = (kdeg.saturating_sub(n), kdeg.min(m));
        let mut acc: Vec<IBig> = Vec::new();
        for i in (lo..=hi).rev() {
            if !acc.is_empty() {
                acc = times_linear(&acc, lx[0], lx[1]);
            }
            let cij = &c[i][kdeg - i];
            if cij != &IBig::ZERO {
                let pw = &ly_pow[kdeg - i];
                if acc.len() < pw.len() {
                    acc.resize(pw.len(), IBig::ZERO);
                }
                for (q, y) in pw.iter().enumerate() {
                    acc[q] += cij * y;
                }
            }
        }
        for _ in 0..lo {
            if acc.is_empty() {
                break;
            }
            acc = times_linear(&acc, lx[0], lx[1]);
        }
        for (q, x) in acc.into_iter().enumerate() {
            if x != IBig::ZERO {
                let e = vec![u32::try_from(kdeg).ok()?, u32::try_from(q).ok()?];
                terms.push((e, Rational::from_parts(x, den.clone())));
            }
        }
    }
    Some(MPoly::from_sorted_terms(2, terms))
}

/// The content of a list of rationals: the positive generator `g` of the `ℤ`-module
/// `c₁ℤ + … + c_kℤ`, i.e. `gcd(numerators)/lcm(denominators)` of the reduced fractions (so
/// every `cᵢ/g` is an integer and these integers have no common factor); `0` for an empty
/// or all-zero list. The same number as Euclid's algorithm on the rationals themselves,
/// computed with one integer gcd per numerator and one per denominator.
pub fn content_rational<'a>(cs: impl Iterator<Item = &'a Rational>) -> Rational {
    use dashu_int::UBig;
    let (mut g, mut l) = (UBig::ZERO, UBig::ONE);
    for c in cs {
        let n = dashu_base::UnsignedAbs::unsigned_abs(c.numerator());
        if n == UBig::ZERO {
            continue;
        }
        if g != UBig::ONE {
            g = dashu_base::Gcd::gcd(&g, &n);
        }
        let d = c.denominator();
        if d != &UBig::ONE && d != &l {
            let h = dashu_base::Gcd::gcd(&l, d);
            l = &l / &h * d;
        }
    }
    Rational::from_parts(dashu_int::IBig::from(g), l)
}

/// Decides `Σₖ ±∏ⱼ f_{kj} ≡ 0` for polynomials over `ℚ` (their coefficients converted by
/// `to_q`), **fraction-free** in one dense integer array: each factor over the common
/// denominator of its coefficients (`f = F/L_f`), each product `∏ F_{kj}` in integers over
/// the degree box of the sum (in each variable the largest over the products of the sum
/// of the factors' degrees; indices add like exponents, [`DenseLayout`]) and scaled by
/// `D/∏ L_{kj}` with `D` the least common multiple of the products' denominators, so the
/// integer sum is `D·Σₖ ±∏ⱼ f_{kj}`: zero exactly when the polynomial identity holds.
/// Integer products and sums only, no rational arithmetic. `Some(true)` if the identity
/// holds, `Some(false)` if not, `None` if a coefficient does not convert or the box has
/// more than `2¹⁸` entries (then decide it over `ℚ`).
pub fn sum_of_products_is_zero<R: Ring>(
    terms: &[(bool, &[&MPoly<R>])],
    to_q: impl Fn(&R) -> Option<Rational>,
) -> Option<bool> {
    use dashu_int::{IBig, UBig};
    let n = terms
        .iter()
        .flat_map(|(_, fs)| fs.iter())
        .map(|p| p.nvars)
        .max()
        .unwrap_or(0);
    let mut dims = vec![1usize; n];
    for (_, fs) in terms {
        if fs.iter().any(|p| p.is_zero()) {
            continue;
        }
        for (i, d) in dims.iter_mut().enumerate() {
            let s = fs.iter().try_fold(1usize, |s, p| {
                s.checked_add(usize::try_from(p.degree_in(i).unwrap_or(0)).ok()?)
            })?;
            *d = (*d).max(s);
        }
    }
    let size = dims.iter().try_fold(1usize, |s, &d| s.checked_mul(d))?;
    if size > 1 << 18 {
        return None;
    }
    let mut strides = vec![1usize; n];
    for i in (0..n.saturating_sub(1)).rev() {
        strides[i] = strides[i + 1] * dims[i + 1];
    }
    let layout = DenseLayout {
        dims,
        strides,
        size,
    };
    type Sparse = Vec<(usize, IBig)>;
    // the integer factors and each product's denominator
    let mut products: Vec<(bool, Vec<Sparse>, UBig)> = Vec::with_capacity(terms.len());
    for (negate, fs) in terms {
        if fs.iter().any(|p| p.is_zero()) {
            continue;
        }
        let mut den = UBig::ONE;
        let mut factors = Vec::with_capacity(fs.len());
        for p in fs.iter() {
            let qs: Vec<Rational> = p.terms.values().map(&to_q).collect::<Option<_>>()?;
            let (ints, l) = integers_over_common_denominator(qs.iter());
            den *= l;
            factors.push(
                p.terms
                    .keys()
                    .map(|e| layout.index(e))
                    .zip(ints)
                    .collect::<Sparse>(),
            );
        }
        products.push((*negate, factors, den));
    }
    let mut lcm = UBig::ONE;
    for (_, _, d) in &products {
        if d != &lcm && d != &UBig::ONE {
            let g = dashu_base::Gcd::gcd(&lcm, d);
            lcm = &lcm / &g * d;
        }
    }
    let mut sum = vec![IBig::ZERO; size];
    let mut tmp = vec![IBig::ZERO; size];
    for (negate, factors, den) in products {
        let cofactor = IBig::from(&lcm / &den);
        let cofactor = if negate { -cofactor } else { cofactor };
        let mut it = factors.into_iter();
        let Some(first) = it.next() else { continue };
        let mut cur: Sparse = first.into_iter().map(|(k, c)| (k, c * &cofactor)).collect();
        for f in it {
            for (i, x) in &cur {
                crate::budget::checkpoint();
                for (j, y) in &f {
                    tmp[i + j] += x * y;
                }
            }
            cur = tmp
                .iter_mut()
                .enumerate()
                .filter(|(_, c)| **c != IBig::ZERO)
                .map(|(k, c)| (k, core::mem::replace(c, IBig::ZERO)))
                .collect();
        }
        for (k, c) in cur {
            sum[k] += c;
        }
    }
    Some(sum.iter().all(|c| c == &IBig::ZERO))
}

/// Laplace's expansion of a 4×4 determinant along rows 0 and 1: each column pair `(k, l)`
/// of the 2×2 minor, its complement `(k′, l′)` and whether its sign `(−1)^{k+l+1}` is `+`
/// (`det = Σ ± minor₀₁(k, l)·minor₂₃(k′, l′)`; used by [`det4_rational`] and by the `pn`
/// determinants).
pub const LAPLACE_PAIRS_4: [([usize; 4], bool); 6] = [
    ([0, 1, 2, 3], true),
    ([0, 2, 1, 3], false),
    ([0, 3, 1, 2], true),
    ([1, 2, 0, 3], true),
    ([1, 3, 0, 2], false),
    ([2, 3, 0, 1], true),
];

/// The determinant of a 4×4 matrix of polynomials over `ℚ` (given by rows, its entries'
/// coefficients converted by `to_q`), **fraction-free** in one dense integer array: each
/// row `r` over one common denominator `L_r` of its four entries (`det` is linear in each
/// row, so `det(M) = det(M̃)/(L₀L₁L₂L₃)` with the integer rows `M̃_r = L_r M_r`), Laplace's
/// expansion along the first two rows, `det M̃ = Σ_{k<l} (−1)^{k+l+1} A_{kl} B_{k'l'}`
/// with the 2×2 minors `A_{kl}` of rows 0, 1 and `B_{k'l'}` of rows 2, 3 on the
/// complementary columns (Laplace's theorem, e.g. Gantmacher, *The Theory of Matrices*,
/// vol. 1, 1959, ch. I §3), every product and sum in integers over the degree box of the
/// result (in each variable the sum over the rows of the row's largest degree; indices
/// add like exponents, [`DenseLayout`]), and one reduction per result coefficient. The
/// same polynomial as the expansion over `ℚ`. `None` if a coefficient does not convert or
/// the box has more than `2¹⁸` entries (then expand over `ℚ`).
pub fn det4_rational<R: Ring>(
    m: [[&MPoly<R>; 4]; 4],
    to_q: impl Fn(&R) -> Option<Rational>,
) -> Option<MPoly<Rational>> {
    use dashu_int::IBig;
    let n = m.iter().flatten().map(|p| p.nvars).max().unwrap_or(0);
    let mut dims = vec![1usize; n];
    for row in &m {
        for (i, d) in dims.iter_mut().enumerate() {
            let r = row.iter().filter_map(|p| p.degree_in(i)).max().unwrap_or(0);
            *d = d.checked_add(usize::try_from(r).ok()?)?;
        }
    }
    let size = dims.iter().try_fold(1usize, |s, &d| s.checked_mul(d))?;
    if size > 1 << 18 {
        return None;
    }
    let mut strides = vec![1usize; n];
    for i in (0..n.saturating_sub(1)).rev() {
        strides[i] = strides[i + 1] * dims[i + 1];
    }
    let layout = DenseLayout {
        dims,
        strides,
        size,
    };
    // the integer rows: sparse (index, coefficient) lists over the row's denominator
    type Sparse = Vec<(usize, IBig)>;
    let mut den = dashu_int::UBig::ONE;
    let mut rows: Vec<[Sparse; 4]> = Vec::with_capacity(4);
    for row in &m {
        let qs: Vec<Rational> = row
            .iter()
            .flat_map(|p| p.terms.values().map(&to_q))
            .collect::<Option<_>>()?;
        let (ints, l) = integers_over_common_denominator(qs.iter());
        den *= l;
        let mut it = ints.into_iter();
        let entries: [Sparse; 4] = core::array::from_fn(|k| {
            row[k]
                .terms
                .keys()
                .map(|e| (layout.index(e), it.next().unwrap_or(IBig::ZERO)))
                .collect()
        });
        rows.push(entries);
    }
    let mut acc = vec![IBig::ZERO; size];
    let add_product = |acc: &mut [IBig], a: &Sparse, b: &Sparse, negate: bool| {
        for (i, x) in a {
            crate::budget::checkpoint();
            for (j, y) in b {
                let t = x * y;
                if negate {
                    acc[i + j] -= t;
                } else {
                    acc[i + j] += t;
                }
            }
        }
    };
    let drain = |acc: &mut [IBig]| -> Sparse {
        acc.iter_mut()
            .enumerate()
            .filter(|(_, c)| **c != IBig::ZERO)
            .map(|(k, c)| (k, core::mem::replace(c, IBig::ZERO)))
            .collect()
    };
    let mut minors: Vec<(Sparse, Sparse, bool)> = Vec::with_capacity(6);
    for ([k, l, kk, ll], plus) in LAPLACE_PAIRS_4 {
        add_product(&mut acc, &rows[0][k], &rows[1][l], false);
        add_product(&mut acc, &rows[0][l], &rows[1][k], true);
        let a = drain(&mut acc);
        if a.is_empty() {
            continue;
        }
        add_product(&mut acc, &rows[2][kk], &rows[3][ll], false);
        add_product(&mut acc, &rows[2][ll], &rows[3][kk], true);
        let b = drain(&mut acc);
        if b.is_empty() {
            continue;
        }
        minors.push((a, b, plus));
    }
    for (a, b, plus) in &minors {
        add_product(&mut acc, a, b, !plus);
    }
    let one = den == dashu_int::UBig::ONE;
    let terms = acc
        .into_iter()
        .enumerate()
        .filter(|(_, c)| *c != IBig::ZERO)
        .map(|(k, c)| {
            let q = if one {
                Rational::from(c)
            } else {
                Rational::from_parts(c, den.clone())
            };
            (layout.exponents(k), q)
        });
    Some(MPoly::from_sorted_terms(n, terms.collect::<Vec<_>>()))
}

/// Exact signs of a bivariate polynomial `p = Σ cᵢⱼ uⁱvʲ` over `ℚ` at rational points,
/// fraction-free: `p = (Σ Cᵢⱼ uⁱvʲ)/L` with integers `Cᵢⱼ` (one common denominator
/// `L > 0`), and at `u = a/b`, `v = c/e` (`b, e > 0`) the sign of `p` is the sign of the
/// integer `L bᵐ eⁿ p(a/b, c/e) = Σᵢ aⁱ bᵐ⁻ⁱ Σⱼ Cᵢⱼ cʲ eⁿ⁻ʲ` (homogeneous Horner's rule):
/// integer products and sums only, no gcd.
#[derive(Debug, Clone)]
pub struct BivariateSigns {
    c: Vec<dashu_int::IBig>,
    m: usize,
    n: usize,
}

impl BivariateSigns {
    /// From the power coefficients `power[i(n + 1) + j] = cᵢⱼ` of bidegree `(m, n)`
    /// (`None` if the length is not `(m + 1)(n + 1)`).
    pub fn new(power: &[Rational], m: usize, n: usize) -> Option<Self> {
        if power.len() != (m + 1).checked_mul(n + 1)? {
            return None;
        }
        let (c, _) = integers_over_common_denominator(power.iter());
        Some(BivariateSigns { c, m, n })
    }

    /// The sign of `p(u, v)`.
    pub fn sign_at(&self, u: &Rational, v: &Rational) -> core::cmp::Ordering {
        use dashu_int::IBig;
        let (a, b) = (u.numerator(), IBig::from(u.denominator().clone()));
        let (c, e) = (v.numerator(), IBig::from(v.denominator().clone()));
        // Σⱼ Cᵢⱼ cʲ eⁿ⁻ʲ for each row, then Σᵢ rowᵢ aⁱ bᵐ⁻ⁱ, both by homogeneous Horner
        let homogeneous = |coef: &mut dyn Iterator<Item = IBig>, x: &IBig, y: &IBig| -> IBig {
            // coefficients from the highest power of x down: acc ← acc·x + cₖ·y^{deg−k}
            let mut acc = IBig::ZERO;
            let mut ypow = IBig::ONE;
            for (k, ck) in coef.enumerate() {
                if k == 0 {
                    acc = ck;
                } else {
                    ypow *= y;
                    acc = acc * x + ck * &ypow;
                }
            }
            acc
        };
        let rows: Vec<IBig> = (0..=self.m)
            .rev()
            .map(|i| {
                let row = &self.c[i * (self.n + 1)..(i + 1) * (self.n + 1)];
                homogeneous(&mut row.iter().rev().cloned(), c, &e)
            })
            .collect();
        let total = homogeneous(&mut rows.into_iter(), a, &b);
        total.cmp(&IBig::ZERO)
    }
}

/// Word-size primes (the six largest below 2⁶¹) for the modular coprimality tests.
const COPRIME_TEST_PRIMES: [u64; 6] = [
    2_305_843_009_213_693_951,
    2_305_843_009_213_693_921,
    2_305_843_009_213_693_907,
    2_305_843_009_213_693_723,
    2_305_843_009_213_693_693,
    2_305_843_009_213_693_669,
];

fn mul_mod(a: u64, b: u64, p: u64) -> u64 {
    ((u128::from(a) * u128::from(b)) % u128::from(p)) as u64
}

fn pow_mod(mut a: u64, mut e: u64, p: u64) -> u64 {
    let mut r = 1 % p;
    while e > 0 {
        if e & 1 == 1 {
            r = mul_mod(r, a, p);
        }
        a = mul_mod(a, a, p);
        e >>= 1;
    }
    r
}

/// `a⁻¹ mod p` (Fermat, `p` prime, `a ≢ 0`).
fn inv_mod(a: u64, p: u64) -> u64 {
    pow_mod(a, p - 2, p)
}

/// The residue of `q` modulo the prime `p`; `None` if `p` divides the denominator.
fn rational_mod(q: &Rational, p: u64) -> Option<u64> {
    use dashu_int::{IBig, UBig};
    let pb = UBig::from(p);
    let d = u64::try_from(q.denominator() % &pb).ok()?;
    if d == 0 {
        return None;
    }
    let n = q.numerator() % IBig::from(p);
    let n = i128::try_from(n).ok()?;
    let n = n.rem_euclid(i128::from(p)) as u64;
    Some(mul_mod(n, inv_mod(d, p), p))
}

/// The images modulo `p` of rational coefficients (constant term first); `None` if `p`
/// divides a denominator or the last (leading) coefficient.
fn images_mod(c: &[Rational], p: u64) -> Option<Vec<u64>> {
    let v = c
        .iter()
        .map(|x| rational_mod(x, p))
        .collect::<Option<Vec<_>>>()?;
    (v.last().is_some_and(|&l| l != 0)).then_some(v)
}

/// The degree of the greatest common divisor of two univariate polynomials over `𝔽_p`
/// (constant term first, leading coefficients non-zero), by Euclid's algorithm.
fn gcd_degree_mod(mut a: Vec<u64>, mut b: Vec<u64>, p: u64) -> usize {
    let trim = |v: &mut Vec<u64>| {
        while v.last() == Some(&0) {
            v.pop();
        }
    };
    trim(&mut a);
    trim(&mut b);
    if a.len() < b.len() {
        std::mem::swap(&mut a, &mut b);
    }
    while !b.is_empty() {
        crate::budget::checkpoint();
        // a ← a mod b
        let inv = inv_mod(b[b.len() - 1], p);
        while a.len() >= b.len() {
            let Some(&lead) = a.last() else { break };
            let f = mul_mod(lead, inv, p);
            let shift = a.len() - b.len();
            for (k, &bk) in b.iter().enumerate() {
                let t = mul_mod(f, bk, p);
                a[k + shift] = (a[k + shift] + p - t) % p;
            }
            a.pop();
            trim(&mut a);
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len().saturating_sub(1)
}

/// `true` if the non-zero polynomials `a`, `b ∈ ℚ[x]` (coefficients, constant term
/// first, leading coefficient non-zero) are **proven** coprime by their images modulo a
/// word-size prime `p` that divides no denominator and neither leading coefficient:
/// then the primitive integer multiples keep their degrees modulo `p`, and the image of
/// their gcd (Gauss's lemma: a divisor over `ℤ` whose leading coefficient divides both
/// leading coefficients) divides both images with its degree, so
/// `deg gcd_ℚ(a, b) ≤ deg gcd_𝔽ₚ(ā, b̄)` (Geddes, Czapor, Labahn, *Algorithms for
/// Computer Algebra*, 1992, §7.4, Lemma 7.3). `false` means "not proven" (a common
/// factor, or an unlucky prime): the caller computes the gcd exactly.
pub fn coprime_by_modular_image(a: &[Rational], b: &[Rational]) -> bool {
    for &p in &COPRIME_TEST_PRIMES[..3] {
        if let (Some(x), Some(y)) = (images_mod(a, p), images_mod(b, p)) {
            return gcd_degree_mod(x, y, p) == 0;
        }
    }
    false
}

/// `true` if the non-zero polynomials `a = Σⱼ aⱼ(x₀) x₁ʲ`, `b = Σⱼ bⱼ(x₀) x₁ʲ` of
/// `ℚ[x₀][x₁]` (`a[j]` the coefficients of `aⱼ`, constant term first; the last `aⱼ`, `bⱼ`
/// non-zero) are **proven** to have a greatest common divisor of degree 0 in `x₁` (a
/// polynomial in `x₀` alone): by their images under `x₀ ↦ t`, modulo a prime `p`, for a
/// `t` where neither leading coefficient `a_last(t)`, `b_last(t)` vanishes modulo `p`
/// (the image of a common divisor keeps its degree in `x₁` and divides both images;
/// Geddes, Czapor, Labahn 1992, §7.4). `false` means "not proven".
pub fn coprime_in_last_variable_by_modular_image(a: &[Vec<Rational>], b: &[Vec<Rational>]) -> bool {
    let eval = |c: &[Rational], t: u64, p: u64| -> Option<u64> {
        let mut acc = 0u64;
        for x in c.iter().rev() {
            acc = (mul_mod(acc, t, p) + rational_mod(x, p)?) % p;
        }
        Some(acc)
    };
    let image = |c: &[Vec<Rational>], t: u64, p: u64| -> Option<Vec<u64>> {
        let v = c
            .iter()
            .map(|x| eval(x, t, p))
            .collect::<Option<Vec<_>>>()?;
        (v.last().is_some_and(|&l| l != 0)).then_some(v)
    };
    for &p in &COPRIME_TEST_PRIMES[..3] {
        for t in [1_000_003u64, 7_919, 104_729] {
            if let (Some(x), Some(y)) = (image(a, t, p), image(b, t, p)) {
                return gcd_degree_mod(x, y, p) == 0;
            }
        }
    }
    false
}

impl<R: Ring> Mul for &MPoly<R> {
    type Output = MPoly<R>;
    fn mul(self, rhs: &MPoly<R>) -> MPoly<R> {
        let n = self.nvars.max(rhs.nvars);
        if self.terms.is_empty() || rhs.terms.is_empty() {
            return MPoly::zero(n);
        }
        // a monomial factor shifts every exponent vector: the order is kept
        if self.terms.len() == 1 || rhs.terms.len() == 1 {
            crate::budget::checkpoint();
            let mut out = Vec::with_capacity(self.terms.len().max(rhs.terms.len()));
            for (ea, a) in &self.terms {
                for (eb, b) in &rhs.terms {
                    out.push((add_exps(ea, eb, n), a.clone() * b.clone()));
                }
            }
            return MPoly::from_sorted_terms(n, out);
        }
        R::mpoly_mul(self, rhs).unwrap_or_else(|| mul_generic(self, rhs))
    }
}
impl<R: Ring> Neg for &MPoly<R> {
    type Output = MPoly<R>;
    fn neg(self) -> MPoly<R> {
        MPoly {
            nvars: self.nvars,
            terms: self
                .terms
                .iter()
                .map(|(e, c)| (e.clone(), -c.clone()))
                .collect(),
        }
    }
}
impl<R: Ring> Add for MPoly<R> {
    type Output = MPoly<R>;
    fn add(mut self, rhs: MPoly<R>) -> MPoly<R> {
        self += rhs;
        self
    }
}
impl<R: Ring> Sub for MPoly<R> {
    type Output = MPoly<R>;
    fn sub(mut self, rhs: MPoly<R>) -> MPoly<R> {
        self -= rhs;
        self
    }
}
impl<R: Ring> Mul for MPoly<R> {
    type Output = MPoly<R>;
    fn mul(self, rhs: MPoly<R>) -> MPoly<R> {
        &self * &rhs
    }
}
impl<R: Ring> Neg for MPoly<R> {
    type Output = MPoly<R>;
    fn neg(self) -> MPoly<R> {
        -&self
    }
}

impl<R: Ring> MPoly<R> {
    /// `self += sign·rhs` in place when `rhs` is small against `self` (a search per term
    /// of `rhs`), else by a merge.
    fn add_assign_signed(&mut self, rhs: &MPoly<R>, negate: bool) {
        if rhs.terms.len().saturating_mul(4) > self.terms.len() {
            *self = merge_add(self, rhs, negate);
            return;
        }
        let n = self.nvars.max(rhs.nvars);
        if n > self.nvars {
            *self = self.padded(n).into_owned();
        }
        for (e, c) in &rhs.terms {
            let c = if negate { -c.clone() } else { c.clone() };
            if e.len() == n {
                self.add_term_ref(e, c);
            } else {
                self.add_term(add_exps(e, &[], n), c);
            }
        }
    }
}
impl<R: Ring> AddAssign for MPoly<R> {
    fn add_assign(&mut self, rhs: MPoly<R>) {
        self.add_assign_signed(&rhs, false);
    }
}
impl<R: Ring> SubAssign for MPoly<R> {
    fn sub_assign(&mut self, rhs: MPoly<R>) {
        self.add_assign_signed(&rhs, true);
    }
}
impl<R: Ring> AddAssign<&MPoly<R>> for MPoly<R> {
    fn add_assign(&mut self, rhs: &MPoly<R>) {
        self.add_assign_signed(rhs, false);
    }
}
impl<R: Ring> SubAssign<&MPoly<R>> for MPoly<R> {
    fn sub_assign(&mut self, rhs: &MPoly<R>) {
        self.add_assign_signed(rhs, true);
    }
}
impl<R: Ring> MulAssign for MPoly<R> {
    fn mul_assign(&mut self, rhs: MPoly<R>) {
        *self = &*self * &rhs;
    }
}
impl<R: Ring> num_traits::Zero for MPoly<R> {
    /// The zero polynomial with `nvars = 0` (it pads to any number of variables).
    fn zero() -> Self {
        MPoly::zero(0)
    }
    fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
}
impl<R: Ring> num_traits::One for MPoly<R> {
    /// The constant 1 with `nvars = 0`.
    fn one() -> Self {
        MPoly::constant(0, R::one())
    }
}
impl<R: Ring> Ring for MPoly<R> {
    fn from_i64(n: i64) -> Self {
        MPoly::constant(0, R::from_i64(n))
    }
}

impl<R: Ring> MPoly<R> {
    /// The polynomial as text, highest exponent vector first, terms joined by `" + "`:
    /// variable `i` written `var(i)` (with `^d` for a power `d > 1`), the factors of a
    /// monomial joined by `times`, a coefficient written `coefficient(c, alone)` (`alone`:
    /// the constant term) and left out where it is 1 in front of a monomial; `"0"` for the
    /// zero polynomial.
    pub fn format_with(
        &self,
        var: impl Fn(usize) -> String,
        times: &str,
        coefficient: impl Fn(&R, bool) -> String,
    ) -> String {
        if self.terms.is_empty() {
            return "0".into();
        }
        self.terms
            .iter()
            .rev()
            .map(|(e, c)| {
                let mono: Vec<String> = e
                    .iter()
                    .enumerate()
                    .filter(|(_, &d)| d > 0)
                    .map(|(i, &d)| {
                        if d == 1 {
                            var(i)
                        } else {
                            format!("{}^{d}", var(i))
                        }
                    })
                    .collect();
                if mono.is_empty() {
                    coefficient(c, true)
                } else if c.is_one() {
                    mono.join(times)
                } else {
                    format!("{}{times}{}", coefficient(c, false), mono.join(times))
                }
            })
            .collect::<Vec<_>>()
            .join(" + ")
    }
}

impl<R: Ring + fmt::Display> fmt::Display for MPoly<R> {
    /// `c·x0^2·x1 + …`, highest exponent vector first; `0` for the zero polynomial.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = self.format_with(
            |i| format!("x{i}"),
            "*",
            |c, alone| {
                if alone {
                    format!("{c}")
                } else {
                    format!("({c})")
                }
            },
        );
        f.write_str(&text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::{One, Zero};

    type M = MPoly<Rational>;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    fn circle() -> M {
        // x² + y² − 1
        M::from_terms(
            2,
            vec![(vec![2, 0], q(1)), (vec![0, 2], q(1)), (vec![0, 0], q(-1))],
        )
        .expect("valid")
    }

    #[test]
    fn construction_and_queries() {
        let x = M::var(2, 0);
        let y = M::var(2, 1);
        let p = &(&x * &x) + &(&(&y * &y) - &M::constant(2, q(1)));
        assert_eq!(p, circle());
        assert_eq!(p.nvars(), 2);
        assert_eq!(p.num_terms(), 3);
        assert_eq!(p.total_degree(), Some(2));
        assert!(!p.is_homogeneous());
        assert!((&x * &y).is_homogeneous());
        assert!(M::zero(3).is_homogeneous());
        assert_eq!(M::zero(3).total_degree(), None);
        assert_eq!(p.coeff(&[0, 2]), q(1));
        assert_eq!(p.coeff(&[0, 0]), q(-1));
        assert_eq!(p.coeff(&[1, 1]), q(0));
        assert_eq!(p.degree_in(1), Some(2));
        // like terms summed, cancellation removes terms
        let s = M::from_terms(1, vec![(vec![1], q(2)), (vec![1], q(-2)), (vec![0], q(5))])
            .expect("valid");
        assert_eq!(s, M::constant(1, q(5)));
        assert!(M::from_terms(2, vec![(vec![1], q(1))]).is_err());
        // out-of-range variable is padded, not a panic
        assert_eq!(M::var(1, 3).nvars(), 4);
    }

    #[test]
    fn eval_partial_pow_map() {
        let p = circle();
        assert_eq!(p.eval(&[q(3), q(4)]).expect("2 values"), q(24));
        assert!(p.eval(&[q(1)]).is_err());
        assert_eq!(p.partial(0), M::var(2, 0).scale(&q(2)));
        assert!(p.partial(7).is_zero());
        let sq = p.pow(2);
        assert_eq!(sq, &p * &p);
        assert_eq!(p.pow(0), M::constant(2, q(1)));
        let f = p.map(|c| Scalar::to_f64(c) * 0.5);
        assert_eq!(f.eval(&[2.0, 0.0]).expect("2 values"), 1.5);
        let z = p.map(|_| q(0));
        assert!(z.is_zero());
    }

    use crate::scalar::Scalar;

    #[test]
    fn substitution_and_parametrization() {
        // The rational parametrization ((1−t²), 2t, (1+t²)) of the circle, homogenized:
        // X² + Y² − W² vanishes identically.
        let h = circle().homogenize();
        assert_eq!(h.nvars(), 3);
        assert!(h.is_homogeneous());
        let x = Poly::from_ints(&[1, 0, -1]);
        let y = Poly::from_ints(&[0, 2]);
        let w = Poly::from_ints(&[1, 0, 1]);
        let r = h.substitute_univariate(&[x, y, w]).expect("3 polys");
        assert!(r.is_zero());
        assert!(h.substitute_univariate(&[Poly::x()]).is_err());
        // specialize y = 1/2 gives x² − 3/4
        let s = circle().specialize(1, &(q(1) / q(2)));
        assert_eq!(
            s,
            M::from_terms(2, vec![(vec![2, 0], q(1)), (vec![0, 0], q(-3) / q(4))]).expect("ok")
        );
    }

    #[test]
    fn mixed_nvars_pad() {
        let a = M::var(1, 0);
        let b = M::var(3, 2);
        let s = &a + &b;
        assert_eq!(s.nvars(), 3);
        assert_eq!(s.eval(&[q(2), q(5), q(7)]).expect("3 values"), q(9));
        assert_eq!(M::zero(2), M::zero(5));
        assert_eq!(M::var(1, 0), M::var(4, 0));
        assert_ne!(M::var(2, 0), M::var(2, 1));
        // Ring structure
        let one = <M as One>::one();
        assert_eq!(&one * &s, s);
        assert_eq!(&<M as Zero>::zero() + &s, s);
        assert_eq!(<M as Ring>::from_i64(3), M::constant(4, q(3)));
    }

    #[test]
    fn univariate_views_round_trip() {
        let p = &circle() * &M::var(2, 0);
        let u = p.to_univariate_in(1).expect("small degree");
        assert_eq!(u.degree(), Some(2));
        assert_eq!(M::from_univariate_in(&u, 1), p);
        let b = p.to_bivariate(0, 1).expect("bivariate");
        // x³ + x y² − x: in x with coefficients in y
        assert_eq!(b.coeff(3), Poly::from_ints(&[1]));
        assert_eq!(b.coeff(1), Poly::from_ints(&[-1, 0, 1]));
        assert!(p.to_bivariate(0, 0).is_err());
        let t = &p * &M::var(3, 2);
        assert!(t.to_bivariate(0, 1).is_err());
        let e = M::from_poly(&Poly::from_ints(&[1, 2, 3]), 2, 1);
        assert_eq!(e.coeff(&[0, 2]), q(3));
    }

    #[test]
    fn resultant_in_eliminates() {
        // circle ∩ line x = y: Res_x(x² + y² − 1, x − y) = 2y² − 1
        let line = &M::var(2, 0) - &M::var(2, 1);
        let r = resultant_in(&circle(), &line, 0).expect("bivariate");
        assert_eq!(r, Poly::from_ints(&[-1, 0, 2]));
        // eliminating y instead gives 2x² − 1
        let r1 = resultant_in(&circle(), &line, 1).expect("bivariate");
        assert_eq!(r1, Poly::from_ints(&[-1, 0, 2]));
        let three = &circle() * &M::var(3, 2);
        assert!(resultant_in(&three, &line, 0).is_err());
        assert!(resultant_in(&M::zero(2), &line, 0).expect("ok").is_zero());
    }

    #[test]
    fn huge_exponents_do_not_panic() {
        let m = M::monomial(2, &[u32::MAX, 1], q(1));
        let sq = &m * &m; // exponents saturate
        assert_eq!(sq.degree_in(0), Some(u32::MAX));
        assert_eq!(m.pow(3).degree_in(1), Some(3));
        assert!(m.to_univariate_in(0).is_err());
        assert!(m.to_bivariate(0, 1).is_err());
        assert!(m.substitute_univariate(&[Poly::x(), Poly::x()]).is_err());
        assert!(resultant_in(&m, &M::var(2, 0), 0).is_err());
        assert_eq!(m.eval(&[q(-1), q(3)]).expect("2 values"), q(-3));
        assert!(m.homogenize().is_homogeneous());
        assert_eq!(
            m.partial(0).coeff(&[u32::MAX - 1, 1]),
            q(i64::from(u32::MAX))
        );
    }

    #[test]
    fn display() {
        assert_eq!(format!("{}", M::zero(2)), "0");
        let s = format!("{}", circle());
        assert!(s.contains("x0^2") && s.contains("x1^2"), "{s}");
        // 3·x0²·x1 + x1 − 2/5, highest exponent vector first
        let p = M::from_terms(
            2,
            vec![
                (vec![0, 0], q(-2) / q(5)),
                (vec![0, 1], q(1)),
                (vec![2, 1], q(3)),
            ],
        )
        .unwrap();
        assert_eq!(format!("{p}"), "(3)*x0^2*x1 + x1 + -2/5");
        let styled = p.format_with(
            |i| ["s", "t"][i].to_string(),
            "·",
            |c, alone| {
                if alone {
                    format!("[{c}]")
                } else {
                    c.to_string()
                }
            },
        );
        assert_eq!(styled, "3·s^2·t + t + [-2/5]");
    }

    /// The product by its definition, `Σ (a_e b_f) x^{e+f}` term by term into a map
    /// (the reference for the fraction-free, dense and sparse products).
    fn naive_mul<R: Ring>(a: &MPoly<R>, b: &MPoly<R>) -> MPoly<R> {
        let n = a.nvars().max(b.nvars());
        let mut out = MPoly::zero(n);
        for (ea, x) in a.terms() {
            for (eb, y) in b.terms() {
                out.add_term(add_exps(ea, eb, n), x.clone() * y.clone());
            }
        }
        out
    }

    /// The sum `a + s·b` term by term (the reference for the merged sum and the in-place
    /// sums).
    fn naive_add<R: Ring>(a: &MPoly<R>, b: &MPoly<R>, s: i64) -> MPoly<R> {
        let n = a.nvars().max(b.nvars());
        let mut out = MPoly::zero(n);
        for (e, c) in a.terms().chain([]) {
            out.add_term(add_exps(e, &[], n), c.clone());
        }
        for (e, c) in b.terms() {
            out.add_term(add_exps(e, &[], n), R::from_i64(s) * c.clone());
        }
        out
    }

    /// Random terms `(exponents, p, d)` (coefficient `p/d`) for [`from_list`], three
    /// exponents in `exps` each (unused ones are cut off by `from_list`).
    fn term_list(
        exps: core::ops::Range<u32>,
        len: core::ops::Range<usize>,
    ) -> impl proptest::strategy::Strategy<Value = Vec<(Vec<u32>, i64, i64)>> {
        proptest::collection::vec(
            (proptest::collection::vec(exps, 3), -9i64..10, 1i64..13),
            len,
        )
    }

    /// The terms with every exponent multiplied by `by` (sparse polynomials for `by > 1`).
    fn stretched(t: &[(Vec<u32>, i64, i64)], by: u32) -> Vec<(Vec<u32>, i64, i64)> {
        t.iter()
            .map(|(e, p, d)| (e.iter().map(|k| k * by).collect(), *p, *d))
            .collect()
    }

    fn from_list(nvars: usize, terms: &[(Vec<u32>, i64, i64)]) -> M {
        M::from_terms(
            nvars,
            terms
                .iter()
                .map(|(e, p, d)| {
                    (
                        e[..nvars].to_vec(),
                        Rational::from_parts_signed((*p).into(), (*d).into()),
                    )
                })
                .collect(),
        )
        .expect("lengths")
    }

    fn same_terms<R: Ring>(a: &MPoly<R>, b: &MPoly<R>) -> bool {
        a.nvars() == b.nvars() && a.terms().eq(b.terms())
    }

    #[test]
    fn products_agree_with_the_definition_on_dense_sparse_and_monomial_factors() {
        // dense (bivariate), sparse (exponents far apart: the ordered-map path), a
        // monomial factor, a factor with fewer variables, and an integer-only product
        let dense = from_list(
            2,
            &[
                (vec![0, 0], 1, 3),
                (vec![1, 2], -5, 7),
                (vec![2, 1], 2, 9),
                (vec![3, 0], 1, 1),
            ],
        );
        let dense2 = from_list(
            2,
            &[(vec![0, 1], 3, 4), (vec![1, 0], -1, 6), (vec![2, 2], 7, 1)],
        );
        let sparse = from_list(
            3,
            &[
                (vec![0, 0, 0], 1, 2),
                (vec![900, 0, 3], 3, 5),
                (vec![0, 700, 1], -2, 3),
            ],
        );
        let sparse2 = from_list(
            3,
            &[
                (vec![5, 0, 0], 1, 7),
                (vec![0, 800, 0], -1, 1),
                (vec![1, 1, 600], 4, 9),
            ],
        );
        let mono = from_list(2, &[(vec![3, 1], -2, 5)]);
        let uni = from_list(1, &[(vec![0], 1, 2), (vec![4], -3, 1)]);
        let int = from_list(2, &[(vec![0, 0], 3, 1), (vec![1, 1], -4, 1)]);
        let cases = [
            (&dense, &dense2),
            (&sparse, &sparse2),
            (&dense, &sparse),
            (&mono, &dense),
            (&dense2, &mono),
            (&uni, &dense),
            (&dense, &uni),
            (&int, &int),
            (&dense, &M::zero(2)),
        ];
        for (a, b) in cases {
            let r = naive_mul(a, b);
            assert!(same_terms(&(a * b), &r), "{a} · {b}");
            assert!(same_terms(&mul_generic(a, b), &r), "generic {a} · {b}");
            let fa = a.map(|c| c.to_f64().value());
            let fb = b.map(|c| c.to_f64().value());
            let fr = naive_mul(&fa, &fb);
            let got = &fa * &fb;
            assert_eq!(got.num_terms(), fr.num_terms());
            for ((e1, c1), (e2, c2)) in got.terms().zip(fr.terms()) {
                assert_eq!(e1, e2);
                assert!((c1 - c2).abs() <= 1e-12 * c2.abs().max(1.0));
            }
        }
        // cancellation to zero in the fraction-free sum: (x + 1)(x − 1) = x² − 1
        let x = M::var(1, 0);
        let one = M::constant(1, q(1));
        assert_eq!(&(&x + &one) * &(&x - &one), &(&x * &x) - &one);
    }

    #[test]
    fn sums_agree_with_the_definition_by_merge_and_in_place() {
        let a = from_list(
            2,
            &[(vec![0, 0], 1, 3), (vec![1, 2], -5, 7), (vec![2, 1], 2, 9)],
        );
        let b = from_list(2, &[(vec![1, 2], 5, 7), (vec![0, 1], 1, 2)]);
        let c = from_list(3, &[(vec![0, 0, 1], 1, 1), (vec![2, 1, 0], -2, 9)]);
        let big = &(&a * &a) * &a;
        for (x, y) in [
            (&a, &b),
            (&b, &a),
            (&a, &c),
            (&c, &a),
            (&big, &b),
            (&a, &a),
            (&b, &big),
        ] {
            assert!(same_terms(&(x + y), &naive_add(x, y, 1)), "{x} + {y}");
            assert!(same_terms(&(x - y), &naive_add(x, y, -1)), "{x} − {y}");
            let mut s = x.clone();
            s += y;
            assert!(same_terms(&s, &naive_add(x, y, 1)), "{x} += {y}");
            let mut d = x.clone();
            d -= y.clone();
            assert!(same_terms(&d, &naive_add(x, y, -1)), "{x} −= {y}");
        }
        assert!((&a - &a).is_zero());
        let mut z = a.clone();
        z -= &a;
        assert!(z.is_zero());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// The fraction-free univariate product equals the convolution in `ℚ`.
        #[test]
        fn univariate_fraction_free_product_is_the_convolution(
            a in proptest::collection::vec((-20i64..21, 1i64..30), 1..8),
            b in proptest::collection::vec((-20i64..21, 1i64..30), 1..8),
        ) {
            let qa: Vec<Rational> = a.iter().map(|&(p, d)| Rational::from_parts_signed(p.into(), d.into())).collect();
            let qb: Vec<Rational> = b.iter().map(|&(p, d)| Rational::from_parts_signed(p.into(), d.into())).collect();
            let mut want = vec![Rational::ZERO; qa.len() + qb.len() - 1];
            for (i, x) in qa.iter().enumerate() {
                for (j, y) in qb.iter().enumerate() {
                    want[i + j] += x * y;
                }
            }
            proptest::prop_assert_eq!(poly_mul_rational(&qa, &qb), want.clone());
            proptest::prop_assert_eq!(
                (&Poly::new(qa.clone()) * &Poly::new(qb.clone())).coeffs().to_vec(),
                Poly::new(want).coeffs().to_vec()
            );
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// The product (fraction-free for ℚ, dense or sparse) and the sums equal their
        /// term-by-term definitions on random polynomials in up to three variables.
        #[test]
        fn random_products_and_sums_agree_with_the_definition(
            ta in term_list(0..5, 0..9),
            tb in term_list(0..5, 0..9),
            na in 1usize..4,
            nb in 1usize..4,
            spread in proptest::bool::ANY,
        ) {
            let stretch = |t: &Vec<(Vec<u32>, i64, i64)>| stretched(t, if spread { 97 } else { 1 });
            let a = from_list(na, &stretch(&ta));
            let b = from_list(nb, &stretch(&tb));
            proptest::prop_assert!(same_terms(&(&a * &b), &naive_mul(&a, &b)));
            proptest::prop_assert!(same_terms(&(&a + &b), &naive_add(&a, &b, 1)));
            proptest::prop_assert!(same_terms(&(&a - &b), &naive_add(&a, &b, -1)));
            let mut s = a.clone();
            s -= &b;
            proptest::prop_assert!(same_terms(&s, &naive_add(&a, &b, -1)));
            proptest::prop_assert!(same_terms(&a.scale(&q(-3)), &naive_add(&M::zero(na), &a, -3)));
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// The fraction-free signs equal the signs of the rational values, at random
        /// points and at roots of the polynomial (a factor `(u − a)` built in).
        #[test]
        fn fraction_free_signs_are_the_signs_of_the_values(
            c in proptest::collection::vec((-9i64..10, 1i64..13), 12),
            (un, ud, vn, vd) in (-20i64..21, 1i64..9, -20i64..21, 1i64..9),
            root in proptest::bool::ANY,
        ) {
            let (m, n) = (2usize, 3usize);
            let mut power: Vec<Rational> = c.iter().map(|(p, d)| Rational::from_parts_signed((*p).into(), (*d).into())).collect();
            let u = Rational::from_parts_signed(un.into(), ud.into());
            let v = Rational::from_parts_signed(vn.into(), vd.into());
            if root {
                // make p(u, v) = 0 by adjusting the constant term
                let val: Rational = (0..=m).flat_map(|i| (0..=n).map(move |j| (i, j)))
                    .map(|(i, j)| power[i * (n + 1) + j].clone() * ring_pow(&u, i) * ring_pow(&v, j))
                    .fold(Rational::ZERO, |a, b| a + b);
                power[0] = power[0].clone() - val;
            }
            let val: Rational = (0..=m).flat_map(|i| (0..=n).map(move |j| (i, j)))
                .map(|(i, j)| power[i * (n + 1) + j].clone() * ring_pow(&u, i) * ring_pow(&v, j))
                .fold(Rational::ZERO, |a, b| a + b);
            let sg = BivariateSigns::new(&power, m, n).expect("(m + 1)(n + 1) coefficients");
            proptest::prop_assert_eq!(sg.sign_at(&u, &v), val.cmp(&Rational::ZERO));
        }
    }

    /// The lexicographic exact division in `ℚ` term by term (the definition).
    fn naive_div_exact(p: &M, d: &M, min_vars: usize) -> Option<M> {
        let nv = p.nvars().max(d.nvars()).max(min_vars);
        let pad = |e: &[u32]| {
            let mut v = e.to_vec();
            v.resize(nv, 0);
            v
        };
        let (lde, ldc) = d.terms().last().map(|(e, c)| (pad(e), c.clone()))?;
        let mut r = p.clone();
        let mut quot = M::zero(nv);
        while let Some((le, lc)) = r.terms().last().map(|(e, c)| (pad(e), c.clone())) {
            if le.iter().zip(&lde).any(|(a, b)| a < b) {
                return None;
            }
            let e: Vec<u32> = le.iter().zip(&lde).map(|(a, b)| a - b).collect();
            let t = M::monomial(nv, &e, lc / ldc.clone());
            r = &r - &naive_mul(&t, d);
            quot = &quot + &t;
        }
        Some(quot)
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// The fraction-free exact division (dense or sparse remainder) returns the
        /// quotient of the definition for products `d·q` (and `d·q + r` with a random
        /// `r`, usually not divisible: then both return `None`), in up to three variables.
        #[test]
        fn fraction_free_exact_division_agrees_with_the_definition(
            td in term_list(0..4, 1..6),
            tq in term_list(0..4, 0..6),
            tr in term_list(0..4, 0..3),
            n in 1usize..4,
            spread in proptest::bool::ANY,
        ) {
            let stretch = |t: &Vec<(Vec<u32>, i64, i64)>| stretched(t, if spread { 97 } else { 1 });
            let d = from_list(n, &stretch(&td));
            let quo = from_list(n, &stretch(&tq));
            let r = from_list(n, &stretch(&tr));
            let p = &d * &quo;
            let got = div_exact_rational(&p, &d, 2);
            proptest::prop_assert_eq!(got.clone(), naive_div_exact(&p, &d, 2));
            if !d.is_zero() {
                proptest::prop_assert_eq!(got, Some(quo));
            }
            let p2 = &p + &r;
            proptest::prop_assert_eq!(div_exact_rational(&p2, &d, 2), naive_div_exact(&p2, &d, 2));
        }
    }

    /// `Σ ±∏` expanded term by term over `ℚ` (the definition).
    fn sum_of_products(terms: &[(bool, Vec<&M>)], n: usize) -> M {
        let mut acc = M::zero(n);
        for (neg, fs) in terms {
            let p = fs.iter().fold(M::constant(n, q(1)), |a, f| &a * *f);
            acc = if *neg { &acc - &p } else { &acc + &p };
        }
        acc
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// The fraction-free decision of `Σ ±∏ fᵢ ≡ 0` agrees with the expansion over `ℚ`:
        /// on true identities (`fg + gh − g(f + h) + k² − k·k`, with a zero factor) and on the
        /// same with a planted extra term `r` (false unless `r` is zero), in up to three
        /// variables and with sparse high exponents.
        #[test]
        fn fraction_free_sum_of_products_decides_the_identity(
            tf in term_list(0..4, 0..5),
            tg in term_list(0..4, 0..5),
            th in term_list(0..4, 0..5),
            tr in term_list(0..4, 0..3),
            n in 1usize..4,
            spread in proptest::bool::ANY,
        ) {
            let stretch = |t: &Vec<(Vec<u32>, i64, i64)>| stretched(t, if spread { 5 } else { 1 });
            let (f, g, h, r) = (from_list(n, &stretch(&tf)), from_list(n, &stretch(&tg)), from_list(n, &stretch(&th)), from_list(n, &stretch(&tr)));
            let fh = &f + &h;
            let zero = M::zero(n);
            let mut terms: Vec<(bool, Vec<&M>)> = vec![
                (false, vec![&f, &g]),
                (false, vec![&g, &h]),
                (true, vec![&g, &fh]),
                (false, vec![&h, &h, &f]),
                (true, vec![&f, &h, &h]),
                (false, vec![&r, &zero]),
            ];
            let decide = |t: &[(bool, Vec<&M>)]| {
                let refs: Vec<(bool, &[&M])> = t.iter().map(|(s, fs)| (*s, fs.as_slice())).collect();
                sum_of_products_is_zero(&refs, |c| Some(c.clone()))
            };
            proptest::prop_assert_eq!(decide(&terms), Some(true));
            terms.push((false, vec![&r]));
            let expanded = sum_of_products(&terms, n);
            proptest::prop_assert_eq!(decide(&terms), Some(expanded.is_zero()));
            proptest::prop_assert_eq!(expanded.is_zero(), r.is_zero());
        }

        /// The fraction-free 4×4 determinant equals the expansion along the first row over
        /// `ℚ` (rows with different denominators, zero entries, up to three variables).
        #[test]
        fn fraction_free_det4_equals_the_expansion(
            entries in proptest::collection::vec(
                proptest::collection::vec((proptest::collection::vec(0u32..3, 3), -5i64..6, 1i64..7), 0..4), 16),
            n in 1usize..4,
        ) {
            let e: Vec<M> = entries.iter().map(|t| from_list(n, t)).collect();
            let m: [[&M; 4]; 4] = core::array::from_fn(|r| core::array::from_fn(|c| &e[4 * r + c]));
            let minor3 = |skip: usize| -> M {
                // rows 1..4, columns ≠ skip: the 3×3 determinant by its definition
                let cols: Vec<usize> = (0..4).filter(|&c| c != skip).collect();
                let a = |r: usize, k: usize| m[r][cols[k]];
                let t = |x: &M, y: &M, z: &M| &(x * y) * z;
                let plus = &(&t(a(1, 0), a(2, 1), a(3, 2)) + &t(a(1, 1), a(2, 2), a(3, 0))) + &t(a(1, 2), a(2, 0), a(3, 1));
                let minus = &(&t(a(1, 2), a(2, 1), a(3, 0)) + &t(a(1, 0), a(2, 2), a(3, 1))) + &t(a(1, 1), a(2, 0), a(3, 2));
                &plus - &minus
            };
            let mut det = M::zero(n);
            for (c, entry) in m[0].iter().enumerate() {
                let t = *entry * &minor3(c);
                det = if c % 2 == 0 { &det + &t } else { &det - &t };
            }
            proptest::prop_assert_eq!(det4_rational(m, |c| Some(c.clone())), Some(det));
        }
    }
}
