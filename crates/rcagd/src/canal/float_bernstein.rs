//! `f64` Bernstein coefficients with a proven error bound, for the sign tests of the two
//! global checks (the pipe's, [`super::self_intersection`], and the canal surface's,
//! [`super::canal_global`]; docs/math/pipes.md, "Global check: `f64` filters that keep the
//! proof").
//!
//! Exact Bernstein coefficients `cᵢ` are converted once to `f64` values `c̃ᵢ` together with a
//! bound `e ≥ |c̃ᵢ − cᵢ|` (the exact distance of each conversion, rounded up), then halved by
//! `f64` de Casteljau at `1/2`. A level of de Casteljau replaces neighbours by their
//! average `(x + y)·½`: the exact average of the exact values moves by at most the old
//! bound (a convex combination), the one rounding of the sum adds at most `u·|x + y|`
//! (`u = 2⁻⁵³`, the standard model `fl(a ∘ b) = (a ∘ b)(1 + δ)`, `|δ| ≤ u`; N. J. Higham,
//! "Accuracy and Stability of Numerical Algorithms", 2nd ed., SIAM 2002, §2.2) and the
//! halving is exact except below the normal range (at most `2⁻¹⁰⁷⁴`). Every intermediate
//! is an average of averages of the `c̃ᵢ` with `≤ k` roundings, so its magnitude is at most
//! `M(1 + u)^k ≤ M(1 + 10⁻⁹)` for the largest input magnitude `M` and `k < 10⁶` levels.
//! So `k` levels add at most `k(u·M(1 + 10⁻⁹) + 2⁻¹⁰⁷⁴)` to the bound ([`grown_error`]).
//! A coefficient `c̃ > e` then proves the exact coefficient `> 0`, `c̃ ≤ −e` proves it `≤ 0`;
//! anything else is undecided ([`Tri::Unsure`]) and the callers fall back to exact
//! arithmetic, so every decision is the one exact arithmetic would make. A non-finite value
//! or bound makes the coefficients unusable (every test undecided).

use rcagd_algebra::{Rational, Scalar};

/// The unit roundoff of `f64` (`2⁻⁵³`).
pub(crate) const UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;

/// A three-valued test result: proved, disproved (exactly), or not decided in `f64`.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Tri {
    Yes,
    No,
    Unsure,
}

/// The exact `|x − f|` rounded up (`∞` if `f` is not finite).
pub(crate) fn conversion_error(x: &Rational, f: f64) -> f64 {
    match Rational::try_from(f) {
        Ok(q) => {
            let d = q - x.clone();
            let d = if d < Rational::ZERO { -d } else { d };
            let e = Scalar::to_f64(&d);
            // to_f64 is within one unit in the last place: two steps up are above
            e.next_up().next_up()
        }
        Err(_) => f64::INFINITY,
    }
}

/// A rational `≤ x` as `f64` (`f64::MAX` above its range).
pub(crate) fn f64_below(x: &Rational) -> f64 {
    let mut f = Scalar::to_f64(x);
    if f == f64::INFINITY {
        return f64::MAX;
    }
    while Rational::try_from(f).is_ok_and(|q| q > *x) {
        f = f.next_down();
    }
    f
}

/// A rational `≥ x` as `f64` (`−f64::MAX` below its range).
pub(crate) fn f64_above(x: &Rational) -> f64 {
    let mut f = Scalar::to_f64(x);
    if f == f64::NEG_INFINITY {
        return -f64::MAX;
    }
    while Rational::try_from(f).is_ok_and(|q| q < *x) {
        f = f.next_up();
    }
    f
}

/// The error bound after `levels` de Casteljau levels at `1/2` of coefficients of magnitude
/// `≤ mag` (module docs): each level adds `u·M′ + 2⁻¹⁰⁷⁴` with `M′ = mag·(1 + 10⁻⁹)` bounding
/// every intermediate (`(1 + u)^levels ≤ 1 + 10⁻⁹`); the outer factor covers the rounding
/// of this sum.
pub(crate) fn grown_error(err: f64, mag: f64, levels: usize) -> f64 {
    let per = UNIT_ROUNDOFF * mag * (1.0 + 1e-9) + 1e-323;
    ((err + levels as f64 * per) * (1.0 + 1e-12)).next_up()
}

/// The `f64` values of `exact` and a bound of their conversion errors (module docs).
fn convert(exact: &[Rational]) -> (Vec<f64>, f64) {
    let mut err = 0.0f64;
    let c = exact
        .iter()
        .map(|x| {
            let f = Scalar::to_f64(x);
            let e = conversion_error(x, f);
            if e.is_nan() || e > err {
                err = e; // NaN-safe: a NaN or larger bound replaces
            }
            f
        })
        .collect();
    (c, err)
}

/// The bound, or `∞` if it or a value is not finite.
fn usable_err(c: &[f64], err: f64) -> f64 {
    if !err.is_finite() || c.iter().any(|x| !x.is_finite()) {
        f64::INFINITY
    } else {
        err
    }
}

fn magnitude(c: &[f64]) -> f64 {
    c.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// Every exact coefficient `> 0`?
pub(crate) fn all_pos_f(c: &[f64], err: f64) -> Tri {
    if !err.is_finite() {
        Tri::Unsure
    } else if c.iter().all(|x| *x > err) {
        Tri::Yes
    } else if c.iter().any(|x| *x <= -err) {
        Tri::No
    } else {
        Tri::Unsure
    }
}

/// Every exact coefficient `< 0`?
pub(crate) fn all_neg_f(c: &[f64], err: f64) -> Tri {
    if !err.is_finite() {
        Tri::Unsure
    } else if c.iter().all(|x| *x < -err) {
        Tri::Yes
    } else if c.iter().any(|x| *x >= err) {
        Tri::No
    } else {
        Tri::Unsure
    }
}

/// `f64` de Casteljau at `1/2`: the coefficients of the two halves.
pub(crate) fn split_row_f(b: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let k = b.len();
    let (mut left, mut right) = (vec![0.0; k], vec![0.0; k]);
    split_row_into(b, &mut left, &mut right, &mut Vec::with_capacity(k));
    (left, right)
}

/// [`split_row_f`] into `left` and `right` (each as long as `b`), `work` a scratch buffer:
/// the same operations in the same order, without allocating.
fn split_row_into(b: &[f64], left: &mut [f64], right: &mut [f64], work: &mut Vec<f64>) {
    let k = b.len();
    work.clear();
    work.extend_from_slice(b);
    for level in 0..k {
        left[level] = work[0];
        right[k - 1 - level] = work[k - 1 - level];
        for i in 0..k - 1 - level {
            work[i] = (work[i] + work[i + 1]) * 0.5;
        }
    }
}

/// Univariate `f64` Bernstein coefficients `c̃` with a proven bound `err ≥ |c̃ᵢ − cᵢ|` on
/// their distance to the exact ones (`err` not finite: unusable, every test
/// [`Tri::Unsure`]).
#[derive(Clone, Debug)]
pub(crate) struct FCoeffs {
    pub(crate) c: Vec<f64>,
    pub(crate) err: f64,
}

impl FCoeffs {
    pub(crate) fn of(exact: &[Rational]) -> Self {
        let (c, err) = convert(exact);
        FCoeffs { c, err }.checked()
    }

    /// Marks the bound unusable if a coefficient is not finite.
    pub(crate) fn checked(mut self) -> Self {
        self.err = usable_err(&self.c, self.err);
        self
    }

    pub(crate) fn usable(&self) -> bool {
        self.err.is_finite()
    }

    pub(crate) fn mag(&self) -> f64 {
        magnitude(&self.c)
    }

    /// de Casteljau at `1/2`.
    pub(crate) fn halves(&self) -> (FCoeffs, FCoeffs) {
        let (l, r) = split_row_f(&self.c);
        let err = grown_error(self.err, self.mag(), self.c.len().saturating_sub(1));
        (
            FCoeffs { c: l, err }.checked(),
            FCoeffs { c: r, err }.checked(),
        )
    }

    /// Every exact coefficient `> 0`?
    pub(crate) fn all_pos(&self) -> Tri {
        all_pos_f(&self.c, self.err)
    }

    /// A lower bound of the least exact coefficient (`−∞` if unusable).
    pub(crate) fn min_lower(&self) -> f64 {
        if !self.usable() {
            return f64::NEG_INFINITY;
        }
        let m = self.c.iter().fold(f64::INFINITY, |m, x| m.min(*x));
        (m - self.err).next_down()
    }

    /// An upper bound of the least exact coefficient.
    pub(crate) fn min_upper(&self) -> f64 {
        if !self.usable() {
            return f64::INFINITY;
        }
        let m = self.c.iter().fold(f64::INFINITY, |m, x| m.min(*x));
        (m + self.err).next_up()
    }

    /// An upper bound of the largest exact coefficient (`∞` if unusable).
    pub(crate) fn max_upper(&self) -> f64 {
        if !self.usable() {
            return f64::INFINITY;
        }
        let m = self.c.iter().fold(f64::NEG_INFINITY, |m, x| m.max(*x));
        (m + self.err).next_up()
    }

    /// A lower bound of the largest exact coefficient.
    pub(crate) fn max_lower(&self) -> f64 {
        if !self.usable() {
            return f64::NEG_INFINITY;
        }
        let m = self.c.iter().fold(f64::NEG_INFINITY, |m, x| m.max(*x));
        (m - self.err).next_down()
    }
}

/// Tensor Bernstein coefficients (`(m + 1) × (n + 1)`, row-major in the first parameter
/// `t`) in `f64` with a proven bound `err ≥ |c̃ − c|` on every coefficient's distance to the
/// exact one (`err` not finite: unusable). A halving in `t` is `n + 1` univariate halvings
/// of `m` levels, one in `s` is `m + 1` of `n` levels: the bound grows as for [`FCoeffs`].
#[derive(Clone, Debug)]
pub(crate) struct FTensor {
    pub(crate) m: usize,
    pub(crate) n: usize,
    pub(crate) c: Vec<f64>,
    pub(crate) err: f64,
}

impl FTensor {
    /// The exact coefficients `exact` (row-major, `(m + 1)(n + 1)` of them) in `f64`.
    pub(crate) fn of(exact: &[Rational], m: usize, n: usize) -> Self {
        let (c, err) = convert(exact);
        FTensor { m, n, c, err }.checked()
    }

    /// Marks the bound unusable if a coefficient is not finite.
    pub(crate) fn checked(mut self) -> Self {
        self.err = usable_err(&self.c, self.err);
        self
    }

    pub(crate) fn mag(&self) -> f64 {
        magnitude(&self.c)
    }

    /// The halves in `t`.
    pub(crate) fn split_t(&self) -> (FTensor, FTensor) {
        let (m, n) = (self.m, self.n);
        let w = n + 1;
        let mut a = vec![0.0; self.c.len()];
        let mut b = a.clone();
        let (mut col, mut l, mut r, mut work) = (
            Vec::with_capacity(m + 1),
            vec![0.0; m + 1],
            vec![0.0; m + 1],
            Vec::with_capacity(m + 1),
        );
        for j in 0..w {
            col.clear();
            col.extend((0..=m).map(|i| self.c[i * w + j]));
            split_row_into(&col, &mut l, &mut r, &mut work);
            for i in 0..=m {
                a[i * w + j] = l[i];
                b[i * w + j] = r[i];
            }
        }
        let err = grown_error(self.err, self.mag(), m);
        (
            FTensor { m, n, c: a, err }.checked(),
            FTensor { m, n, c: b, err }.checked(),
        )
    }

    /// The halves in `s`.
    pub(crate) fn split_s(&self) -> (FTensor, FTensor) {
        let (m, n) = (self.m, self.n);
        let w = n + 1;
        let mut a = vec![0.0; self.c.len()];
        let mut b = a.clone();
        let mut work = Vec::with_capacity(w);
        for i in 0..=m {
            let row = i * w..(i + 1) * w;
            split_row_into(
                &self.c[row.clone()],
                &mut a[row.clone()],
                &mut b[row],
                &mut work,
            );
        }
        let err = grown_error(self.err, self.mag(), n);
        (
            FTensor { m, n, c: a, err }.checked(),
            FTensor { m, n, c: b, err }.checked(),
        )
    }

    /// The four quarters `(t₁, s₁), (t₁, s₂), (t₂, s₁), (t₂, s₂)`: the halves in `t`, each
    /// halved in `s`.
    pub(crate) fn quarters(&self) -> [FTensor; 4] {
        let (l, r) = self.split_t();
        let (ll, lr) = l.split_s();
        let (rl, rr) = r.split_s();
        [ll, lr, rl, rr]
    }

    /// Every exact coefficient `> 0`?
    pub(crate) fn all_pos(&self) -> Tri {
        all_pos_f(&self.c, self.err)
    }

    /// Every exact coefficient `> 0`, or every one `< 0`?
    pub(crate) fn strict_sign(&self) -> Tri {
        match (all_pos_f(&self.c, self.err), all_neg_f(&self.c, self.err)) {
            (Tri::Yes, _) | (_, Tri::Yes) => Tri::Yes,
            (Tri::No, Tri::No) => Tri::No,
            _ => Tri::Unsure,
        }
    }

    /// A lower bound of the least exact coefficient (`−∞` if unusable).
    pub(crate) fn min_lower(&self) -> f64 {
        if !self.err.is_finite() {
            return f64::NEG_INFINITY;
        }
        let m = self.c.iter().fold(f64::INFINITY, |m, x| m.min(*x));
        (m - self.err).next_down()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    /// Exact de Casteljau at `1/2` (the reference).
    fn split_exact(b: &[Rational]) -> (Vec<Rational>, Vec<Rational>) {
        let k = b.len();
        let half = q(1, 2);
        let mut work = b.to_vec();
        let (mut left, mut right) = (Vec::new(), Vec::new());
        for level in 0..k {
            left.push(work[0].clone());
            right.push(work[k - 1 - level].clone());
            for i in 0..k - 1 - level {
                work[i] = (work[i].clone() + work[i + 1].clone()) * half.clone();
            }
        }
        right.reverse();
        (left, right)
    }

    fn within(exact: &[Rational], c: &[f64], err: f64) -> bool {
        exact.iter().zip(c).all(|(x, y)| {
            let d = Rational::try_from(*y).expect("finite") - x.clone();
            let d = if d < Rational::ZERO { -d } else { d };
            Rational::try_from(err).is_ok_and(|e| d <= e)
        })
    }

    #[test]
    fn directed_roundings_bracket_the_rational() {
        for x in [q(1, 3), q(-2, 7), q(5, 1), q(-1, 1_000_000_007)] {
            let (lo, hi) = (f64_below(&x), f64_above(&x));
            assert!(Rational::try_from(lo).expect("finite") <= x);
            assert!(Rational::try_from(hi).expect("finite") >= x);
            assert!(hi == lo || hi == lo.next_up());
        }
        assert_eq!(conversion_error(&q(1, 2), 0.5).next_down().next_down(), 0.0);
        assert_eq!(conversion_error(&q(1, 2), f64::NAN), f64::INFINITY);
    }

    #[test]
    fn non_finite_values_are_unusable() {
        let f = FCoeffs {
            c: vec![1.0, f64::INFINITY],
            err: 0.0,
        }
        .checked();
        assert_eq!(f.all_pos(), Tri::Unsure);
        let t = FTensor {
            m: 0,
            n: 1,
            c: vec![1.0, f64::NAN],
            err: 0.0,
        }
        .checked();
        assert_eq!(t.strict_sign(), Tri::Unsure);
        assert_eq!(t.min_lower(), f64::NEG_INFINITY);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]

        /// The `f64` de Casteljau halves stay within their proven bound of the exact halves
        /// (random exact coefficients of mixed sizes, eight levels deep), and the tensor
        /// quarters of a `(2, k)` tensor within theirs, three levels deep; a decided sign
        /// is the exact one.
        #[test]
        fn float_halving_stays_within_its_bound(
            nums in proptest::collection::vec(-1_000_000i64..1_000_000, 4..24),
            dens in proptest::collection::vec(1i64..100_000, 24),
            path in proptest::collection::vec(0usize..4, 8),
        ) {
            let exact: Vec<Rational> = nums
                .iter()
                .zip(&dens)
                .map(|(n, d)| q(*n, *d))
                .collect();
            let mut e = exact.clone();
            let mut f = FCoeffs::of(&exact);
            prop_assert!(within(&e, &f.c, f.err));
            for step in &path {
                let (l, r) = split_exact(&e);
                let (fl, fr) = f.halves();
                (e, f) = if step % 2 == 1 { (r, fr) } else { (l, fl) };
                prop_assert!(within(&e, &f.c, f.err), "{:?} {}", f.c, f.err);
                prop_assert!(f.err <= 1e-9 * (1.0 + f.mag()));
                let pos = e.iter().all(|x| *x > Rational::ZERO);
                match f.all_pos() {
                    Tri::Yes => prop_assert!(pos),
                    Tri::No => prop_assert!(!pos),
                    Tri::Unsure => {}
                }
            }
            // tensors: a (2, k) tensor quartered three times along the path
            let m = 1;
            let n = exact.len() / 2 - 1;
            let w = n + 1;
            let mut t: Vec<Rational> = exact[..2 * w].to_vec();
            let mut ft = FTensor::of(&t, m, n);
            for quarter in path.iter().take(3) {
                // exact quarter: halves in t (columns), then in s (rows)
                let cols: Vec<(Vec<Rational>, Vec<Rational>)> = (0..w)
                    .map(|j| split_exact(&[t[j].clone(), t[w + j].clone()]))
                    .collect();
                let half: Vec<Rational> = (0..=m)
                    .flat_map(|i| {
                        cols.iter().map(move |(l, r)| {
                            if quarter >> 1 == 1 { r[i].clone() } else { l[i].clone() }
                        })
                    })
                    .collect();
                t = (0..=m)
                    .flat_map(|i| {
                        let (l, r) = split_exact(&half[i * w..(i + 1) * w]);
                        if quarter & 1 == 1 { r } else { l }
                    })
                    .collect();
                ft = ft.quarters()[*quarter].clone();
                prop_assert!(within(&t, &ft.c, ft.err));
                let pos = t.iter().all(|x| *x > Rational::ZERO);
                let neg = t.iter().all(|x| *x < Rational::ZERO);
                match ft.strict_sign() {
                    Tri::Yes => prop_assert!(pos || neg),
                    Tri::No => prop_assert!(!pos && !neg),
                    Tri::Unsure => {}
                }
            }
        }
    }
}
