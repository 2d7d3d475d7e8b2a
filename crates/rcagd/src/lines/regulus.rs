//! Reguli and common transversals.
//!
//! **Regulus through three pairwise skew lines `a, b, c`.** The span of `a, b, c` is a plane
//! of `P⁵`; on it the Klein quadric restricts to the conic
//! `λμ·Ω(a,b) + λν·Ω(a,c) + μν·Ω(b,c) = 0` for `x = λa + μb + νc` (non-degenerate because
//! `Ω(a,b)Ω(a,c)Ω(b,c) ≠ 0` for skew lines). Projecting from `a` gives the rational
//! quadratic parametrization of the regulus
//! `x(μ, ν) = −μν·Ω(b,c)·a + (μΩ(a,b) + νΩ(a,c))(μb + νc)`, with `x(1,0) ∝ b`,
//! `x(0,1) ∝ c` and `x ∝ a` where `μΩ(a,b) + νΩ(a,c) = 0`.
//!
//! The **transversals** (the complementary regulus, the lines meeting `a, b, c`): through
//! the point `P(s) = (1 − s)p₀ + s p₁` of `a` passes exactly one, the intersection of the
//! planes `P ∨ b = M(b)P` and `P ∨ c = M(c)P` (Gruber §1.1.6, hyperbolic net); its
//! Plücker coordinates are quadratic polynomials in `s`.
//!
//! The carrier quadric `xᵀQx = 0` contains both rulings; it is the kernel of the 9 linear
//! conditions "three points of each of `a, b, c` lie on `Q`".
//!
//! **Common transversals of four lines** `l₁, …, l₄`: the solutions of `Ω(lᵢ, x) = 0`
//! (`i = 1..4`) form (generically) a pencil `σy + τz`, and on it the Klein quadric gives the
//! binary quadratic `σ²q(y) + 2στβ(y,z) + τ²q(z) = 0` (`q(x) = x₁x₄ + x₂x₅ + x₃x₆`,
//! `β = Ω/2`): two real, one double, or two conjugate complex transversals, or infinitely
//! many (the four lines belong to one regulus, or to a special configuration).

use super::plucker::{klein_form, mat_vec, reciprocal_product, swap, wedge, Line};
use super::{fmt_vec, is_small, scale_of, LineError, SqrtScalar};
use crate::Certified;
use num_traits::{One, Zero};
use rcagd_algebra::{Certificate, Matrix, Poly, Scalar};

/// The regulus through three pairwise skew lines and its transversals.
#[derive(Debug, Clone, PartialEq)]
pub struct Regulus<F> {
    lines: [Line<F>; 3],
    ab: F,
    ac: F,
    bc: F,
}

fn check_skew<F: Scalar>(g: &Line<F>, h: &Line<F>) -> Result<F, LineError> {
    if g.meets(h) {
        return Err(LineError::NotSkew(fmt_vec(g.coords()), fmt_vec(h.coords())));
    }
    Ok(g.reciprocal_product(h))
}

/// `Σ aₖ vₖ` for polynomial weights.
fn poly_combo<F: Scalar>(terms: &[(Poly<F>, &[F; 6])]) -> [Poly<F>; 6] {
    core::array::from_fn(|k| {
        terms
            .iter()
            .fold(Poly::zero(), |acc, (w, v)| &acc + &w.scale(&v[k]))
    })
}

impl<F: Scalar> Regulus<F> {
    /// The regulus containing the three lines.
    ///
    /// # Errors
    /// [`LineError::NotSkew`] unless the lines are pairwise skew.
    pub fn from_lines(a: &Line<F>, b: &Line<F>, c: &Line<F>) -> Result<Self, LineError> {
        let ab = check_skew(a, b)?;
        let ac = check_skew(a, c)?;
        let bc = check_skew(b, c)?;
        Ok(Regulus {
            lines: [a.clone(), b.clone(), c.clone()],
            ab,
            ac,
            bc,
        })
    }

    /// The three defining lines.
    pub fn lines(&self) -> &[Line<F>; 3] {
        &self.lines
    }

    /// The generator `x(μ, ν)` of the regulus (module docs); `(1, 0) ↦ b`, `(0, 1) ↦ c`.
    pub fn generator(&self, mu: &F, nu: &F) -> Line<F> {
        let [a, b, c] = &self.lines;
        let k = mu.clone() * self.ab.clone() + nu.clone() * self.ac.clone();
        let wa = -(mu.clone() * nu.clone() * self.bc.clone());
        let wb = k.clone() * mu.clone();
        let wc = k * nu.clone();
        Line::from_coords_unchecked(core::array::from_fn(|i| {
            wa.clone() * a.coords()[i].clone()
                + wb.clone() * b.coords()[i].clone()
                + wc.clone() * c.coords()[i].clone()
        }))
    }

    /// The generator polynomials `x((1 − s), s)` (degree ≤ 2 in `s`).
    pub fn generator_polys(&self) -> [Poly<F>; 6] {
        let [a, b, c] = &self.lines;
        let mu = Poly::new(vec![F::one(), -F::one()]);
        let nu = Poly::x();
        let k = &mu.scale(&self.ab) + &nu.scale(&self.ac);
        let wa = (&mu * &nu).scale(&-self.bc.clone());
        let wb = &k * &mu;
        let wc = &k * &nu;
        poly_combo(&[(wa, a.coords()), (wb, b.coords()), (wc, c.coords())])
    }

    fn point_polys(&self) -> [Poly<F>; 4] {
        let (p0, p1) = self.lines[0].points();
        core::array::from_fn(|i| Poly::new(vec![p0[i].clone(), p1[i].clone() - p0[i].clone()]))
    }

    /// The transversal through `P(s) = (1 − s)p₀ + s p₁ ∈ a` (module docs).
    pub fn transversal(&self, s: &F) -> Line<F> {
        let l = self.transversal_polys();
        Line::from_coords_unchecked(core::array::from_fn(|k| l[k].eval(s)))
    }

    /// The transversal family's Plücker coordinates as polynomials in `s` (degree ≤ 2):
    /// `swap((M(b)P(s)) ∧ (M(c)P(s)))`.
    pub fn transversal_polys(&self) -> [Poly<F>; 6] {
        let p = self.point_polys();
        let mb = self.lines[1]
            .incidence_matrix()
            .map(|row| row.map(|x| Poly::constant(x)));
        let mc = self.lines[2]
            .incidence_matrix()
            .map(|row| row.map(|x| Poly::constant(x)));
        let u = mat_vec(&mb, &p);
        let v = mat_vec(&mc, &p);
        swap(&wedge(&u, &v))
    }

    /// The carrier quadric `Q` (symmetric 4×4, `xᵀQx = 0`) through the three lines.
    ///
    /// # Errors
    /// [`LineError::Algebra`] only if the (exactly one-dimensional) kernel is not found
    /// (inconsistent `f64` data).
    pub fn quadric(&self) -> Result<[[F; 4]; 4], LineError> {
        let idx: Vec<(usize, usize)> = (0..4).flat_map(|i| (i..4).map(move |j| (i, j))).collect();
        let mut rows = Vec::new();
        for l in &self.lines {
            let (p, q) = l.points();
            let r: [F; 4] = core::array::from_fn(|k| p[k].clone() + q[k].clone());
            for x in [p, q, r] {
                rows.push(
                    idx.iter()
                        .map(|&(i, j)| {
                            let m = x[i].clone() * x[j].clone();
                            if i == j {
                                m
                            } else {
                                m * F::from_i64(2)
                            }
                        })
                        .collect::<Vec<F>>(),
                );
            }
        }
        let m = Matrix::from_rows(rows).map_err(rcagd_algebra::AlgebraError::from)?;
        let ns = m.null_space();
        let v = ns.first().ok_or_else(|| {
            LineError::Algebra(rcagd_algebra::AlgebraError::NotRepresentable(
                "no quadric through the three lines".into(),
            ))
        })?;
        let mut q: [[F; 4]; 4] = core::array::from_fn(|_| core::array::from_fn(|_| F::zero()));
        for (&(i, j), c) in idx.iter().zip(v) {
            q[i][j] = c.clone();
            q[j][i] = c.clone();
        }
        Ok(q)
    }
}

fn quad_form<F: Scalar>(q: &[[F; 4]; 4], x: &[F; 4]) -> F {
    let y = mat_vec(q, x);
    super::dot(x, &y)
}

fn poly_zero_cert<F: Scalar>(property: String, p: &Poly<F>, scale: f64) -> Certificate {
    rcagd_geom::certify::polynomial_is_zero_scaled(&property, p.coeffs(), scale)
}

impl<F: Scalar> Certified for Regulus<F> {
    /// Both families lie on the Klein quadric identically in `s`; the transversals meet
    /// `a, b, c` identically; every generator meets every transversal
    /// (`Ω(G(s), T(s')) ≡ 0`, coefficient-wise); the generators at `s = 0, 1` are `b, c`;
    /// the quadric contains the three lines and the mid generator and transversal.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        let g = self.generator_polys();
        let t = self.transversal_polys();
        let sc = |v: &[Poly<F>; 6]| {
            v.iter()
                .flat_map(|p| p.coeffs().iter())
                .map(|x| x.to_f64().abs())
                .fold(0.0, f64::max)
        };
        let (gs, ts) = (sc(&g), sc(&t));
        out.push(poly_zero_cert(
            "generators x(s) of the regulus: l₁l₄ + l₂l₅ + l₃l₆ ≡ 0".into(),
            &klein_form(&g),
            gs * gs,
        ));
        out.push(poly_zero_cert(
            "transversals T(s): l₁l₄ + l₂l₅ + l₃l₆ ≡ 0".into(),
            &klein_form(&t),
            ts * ts,
        ));
        for (name, l) in ["a", "b", "c"].iter().zip(&self.lines) {
            let lp: [Poly<F>; 6] = core::array::from_fn(|k| Poly::constant(l.coords()[k].clone()));
            out.push(poly_zero_cert(
                format!("every transversal meets {name}: Ω(T(s), {name}) ≡ 0"),
                &reciprocal_product(&t, &lp),
                ts * scale_of(l.coords()),
            ));
        }
        let mut worst = F::zero();
        for i in 0..3 {
            for j in 0..3 {
                let gi: [F; 6] = core::array::from_fn(|k| g[k].coeff(i));
                let tj: [F; 6] = core::array::from_fn(|k| t[k].coeff(j));
                let v = reciprocal_product(&gi, &tj);
                if v.abs() > worst.abs() {
                    worst = v;
                }
            }
        }
        out.push(Certificate::decide(
            "every generator meets every transversal: Ω(G(s), T(s')) ≡ 0",
            is_small(&worst, gs * ts),
            F::EXACT,
            || crate::error::format_scalar(&worst),
        ));
        let g0 = self.generator(&F::one(), &F::zero());
        let g1 = self.generator(&F::zero(), &F::one());
        out.push(Certificate::decide(
            "x(1, 0) = b and x(0, 1) = c",
            g0.same_line(&self.lines[1]) && g1.same_line(&self.lines[2]),
            F::EXACT,
            || "generator end lines differ".into(),
        ));
        match self.quadric() {
            Ok(q) => {
                let half = F::one() / F::from_i64(2);
                let mut lines: Vec<Line<F>> = self.lines.to_vec();
                lines.push(self.generator(&half, &half));
                lines.push(self.transversal(&half));
                let mut bad = None;
                for l in &lines {
                    let (p, r) = l.points();
                    let m: [F; 4] = core::array::from_fn(|k| p[k].clone() + r[k].clone());
                    for x in [p, r, m] {
                        let v = quad_form(&q, &x);
                        let s = scale_of(&x).powi(2)
                            * q.iter().map(|r| scale_of(r)).fold(0.0, f64::max);
                        if !is_small(&v, s) {
                            bad = Some(v);
                        }
                    }
                }
                out.push(Certificate::decide(
                    "the carrier quadric contains a, b, c, a generator and a transversal",
                    bad.is_none(),
                    F::EXACT,
                    || format!("xᵀQx = {bad:?}"),
                ));
            }
            Err(e) => out.push(Certificate::fails(
                "carrier quadric",
                e.to_string(),
                F::EXACT,
            )),
        }
        out
    }
}

/// The common transversals of four lines (module docs). `F` is the input scalar, `E` its
/// square-root extension.
#[derive(Debug, Clone, PartialEq)]
pub enum CommonTransversals<F, E> {
    /// Two distinct real transversals (over the extension by the square root of the
    /// discriminant).
    Two([Line<E>; 2]),
    /// One (double) transversal.
    One(Line<F>),
    /// Two conjugate complex transversals `re ± i·im` (coordinate vectors).
    ComplexPair {
        /// Real part.
        re: [E; 6],
        /// Imaginary part.
        im: [E; 6],
    },
    /// Infinitely many (a regulus or a pencil of lines); the kernel of the four conditions
    /// is returned.
    Infinitely(Vec<[F; 6]>),
}

/// How many common transversals four lines have (the case [`common_transversals`]
/// decides), without the lines.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TransversalCount {
    /// Infinitely many (a regulus or a special position).
    Infinitely,
    /// One double transversal.
    One,
    /// Two real ones.
    Two,
    /// A conjugate complex pair.
    ComplexPair,
}

/// The decisions [`common_transversals`] takes on its input, recorded on exact lines
/// ([`common_transversals_recorded`]) and replayed in another scalar
/// ([`common_transversals_along`]), so that an `f64` build computes the same transversals
/// in the same order: the pivot columns of the 4 × 6 system `Ω(lᵢ, x) = 0` (the kernel
/// basis `y, z` of the pencil; an `f64` rounding residue of an exact 0 taken as a pivot
/// gives another basis, [`crate::cyclide::route::Route::null_space`]), the number of
/// transversals (the discriminant `β² − q(y)q(z)` zero, positive or negative, or all of
/// `q(y), q(z), β` zero) and which of `q(y)`, `q(z)` is non-zero (the root formula used).
#[derive(Debug, Clone)]
pub struct TransversalRoute {
    kernel: crate::cyclide::route::Route,
    count: TransversalCount,
    branch: usize,
}

impl TransversalRoute {
    /// The number of transversals decided.
    pub fn count(&self) -> TransversalCount {
        self.count
    }
}

/// The common transversals of four lines (module docs).
///
/// # Errors
/// [`LineError::Algebra`] only for malformed input of the linear algebra.
pub fn common_transversals<F: SqrtScalar>(
    lines: [&Line<F>; 4],
) -> Result<CommonTransversals<F, F::Ext>, LineError> {
    transversals_in(lines, None).map(|(t, _)| t)
}

/// [`common_transversals`] of exact lines with its decisions ([`TransversalRoute`]).
///
/// # Errors
/// As [`common_transversals`].
pub fn common_transversals_recorded<F: SqrtScalar>(
    lines: [&Line<F>; 4],
) -> Result<(CommonTransversals<F, F::Ext>, TransversalRoute), LineError> {
    transversals_in(lines, None)
}

/// [`common_transversals`] taking the decisions recorded on the exact input (`route`)
/// instead of deciding them in `F`: every number is computed in `F`, no test is.
///
/// # Errors
/// As [`common_transversals`]; [`LineError::Algebra`] if the route does not fit these lines
/// (another number of lines in the kernel, a negative discriminant where the exact one is
/// positive).
pub fn common_transversals_along<F: SqrtScalar>(
    lines: [&Line<F>; 4],
    route: &TransversalRoute,
) -> Result<CommonTransversals<F, F::Ext>, LineError> {
    transversals_in(lines, Some(route)).map(|(t, _)| t)
}

fn route_error(e: crate::cyclide::CyclideError) -> LineError {
    LineError::Algebra(rcagd_algebra::AlgebraError::NotRepresentable(e.to_string()))
}

fn transversals_in<F: SqrtScalar>(
    lines: [&Line<F>; 4],
    replay: Option<&TransversalRoute>,
) -> Result<(CommonTransversals<F, F::Ext>, TransversalRoute), LineError> {
    let rows: Vec<Vec<F>> = lines.iter().map(|l| l.axis_coords().to_vec()).collect();
    let mut kernel =
        replay.map_or_else(crate::cyclide::route::Route::record, |r| r.kernel.replay());
    let ns: Vec<[F; 6]> = kernel
        .null_space(&rows)
        .map_err(route_error)?
        .into_iter()
        .map(|v| core::array::from_fn(|k| v.get(k).cloned().unwrap_or_else(F::zero)))
        .collect();
    let recorded = |count: TransversalCount, branch: usize| TransversalRoute {
        kernel: kernel.clone(),
        count,
        branch,
    };
    let count_is = |c: TransversalCount| replay.map(|r| r.count == c);
    if ns.len() != 2 {
        if replay.is_some_and(|r| r.count != TransversalCount::Infinitely) {
            return Err(route_error(crate::cyclide::CyclideError::InvalidArgument(
                "the replayed kernel of the four conditions is not a pencil".into(),
            )));
        }
        let r = recorded(TransversalCount::Infinitely, 2);
        return Ok((CommonTransversals::Infinitely(ns), r));
    }
    let (y, z) = (&ns[0], &ns[1]);
    let qy = klein_form(y);
    let qz = klein_form(z);
    let b = reciprocal_product(y, z) / F::from_i64(2);
    let s = scale_of(y).max(scale_of(z)).powi(2);
    if count_is(TransversalCount::Infinitely)
        .unwrap_or_else(|| [&qy, &qz, &b].iter().all(|x| is_small(*x, s)))
    {
        let r = recorded(TransversalCount::Infinitely, 2);
        return Ok((CommonTransversals::Infinitely(ns), r));
    }
    let branch = replay.map_or_else(
        || {
            if !is_small(&qy, s) {
                0
            } else if !is_small(&qz, s) {
                1
            } else {
                2
            }
        },
        |r| r.branch,
    );
    let disc = b.clone() * b.clone() - qy.clone() * qz.clone();
    let e = |v: &[F; 6]| -> [F::Ext; 6] { core::array::from_fn(|k| v[k].embed()) };
    let combo = |sig: &F::Ext, v: &[F::Ext; 6], tau: &F::Ext, w: &[F::Ext; 6]| -> [F::Ext; 6] {
        core::array::from_fn(|k| sig.clone() * v[k].clone() + tau.clone() * w[k].clone())
    };
    let one = F::Ext::one();
    let zero = F::Ext::zero();
    if count_is(TransversalCount::One).unwrap_or_else(|| is_small(&disc, s * s)) {
        // double root
        let x: [F; 6] = match branch {
            0 => {
                let sig = -b / qy;
                core::array::from_fn(|k| sig.clone() * y[k].clone() + z[k].clone())
            }
            1 => {
                let tau = -b / qz;
                core::array::from_fn(|k| y[k].clone() + tau.clone() * z[k].clone())
            }
            _ => y.clone(),
        };
        let r = recorded(TransversalCount::One, branch);
        return Ok((CommonTransversals::One(Line::from_coords_unchecked(x)), r));
    }
    let (ye, ze) = (e(y), e(z));
    if count_is(TransversalCount::Two).unwrap_or_else(|| disc > F::zero()) {
        let r = disc.sqrt_ext().ok_or_else(|| {
            LineError::Algebra(rcagd_algebra::AlgebraError::NotRepresentable(
                "square root of the discriminant".into(),
            ))
        })?;
        let (x1, x2) = match branch {
            0 => {
                let (qe, be) = (qy.embed(), b.embed());
                let s1 = (-be.clone() + r.clone()) / qe.clone();
                let s2 = (-be - r) / qe;
                (combo(&s1, &ye, &one, &ze), combo(&s2, &ye, &one, &ze))
            }
            1 => {
                let (qe, be) = (qz.embed(), b.embed());
                let t1 = (-be.clone() + r.clone()) / qe.clone();
                let t2 = (-be - r) / qe;
                (combo(&one, &ye, &t1, &ze), combo(&one, &ye, &t2, &ze))
            }
            _ => (ye, ze),
        };
        let rec = recorded(TransversalCount::Two, branch);
        return Ok((
            CommonTransversals::Two([
                Line::from_coords_unchecked(x1),
                Line::from_coords_unchecked(x2),
            ]),
            rec,
        ));
    }
    // conjugate complex pair: qy ≠ 0 here (otherwise disc = b² ≥ 0)
    let r = (-disc).sqrt_ext().ok_or_else(|| {
        LineError::Algebra(rcagd_algebra::AlgebraError::NotRepresentable(
            "square root of the discriminant".into(),
        ))
    })?;
    let qe = qy.embed();
    let re = combo(&(-b.embed() / qe.clone()), &ye, &one, &ze);
    let im = combo(&(r / qe), &ye, &zero, &ze);
    let rec = recorded(TransversalCount::ComplexPair, branch);
    Ok((CommonTransversals::ComplexPair { re, im }, rec))
}

/// The common perpendicular of two skew affine lines: the intersection of the planes
/// through each line containing the direction `d = g × h`.
///
/// # Errors
/// [`LineError::NotSkew`] if the lines meet or are parallel (`g × h = 0` or `Ω = 0`),
/// [`LineError::ZeroVector`] for a line at infinity.
pub fn common_perpendicular<F: Scalar>(g: &Line<F>, h: &Line<F>) -> Result<Line<F>, LineError> {
    if g.is_at_infinity() || h.is_at_infinity() {
        return Err(LineError::ZeroVector(
            "a line at infinity has no perpendicular".into(),
        ));
    }
    check_skew(g, h)?;
    let (a, b) = (g.direction(), h.direction());
    let d = [
        a[1].clone() * b[2].clone() - a[2].clone() * b[1].clone(),
        a[2].clone() * b[0].clone() - a[0].clone() * b[2].clone(),
        a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone(),
    ];
    let inf = [F::zero(), d[0].clone(), d[1].clone(), d[2].clone()];
    let u = g.join_point(&inf)?;
    let v = h.join_point(&inf)?;
    Line::from_planes(&u, &v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::{QuadExt, Rational};

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }
    fn aff(a: [i64; 3], b: [i64; 3]) -> Line<Rational> {
        Line::from_affine_points(&a.map(q), &b.map(q)).expect("line")
    }

    #[test]
    fn regulus_of_hyperbolic_paraboloid() {
        // z = xy contains the lines (t, 0, 0)+…: x = c, z = c·y
        let a = aff([0, 0, 0], [0, 1, 0]);
        let b = aff([1, 0, 0], [1, 1, 1]);
        let c = aff([2, 0, 0], [2, 1, 2]);
        let r = Regulus::from_lines(&a, &b, &c).expect("regulus");
        assert!(r.all_hold(), "{:?}", r.certify());
        let quad = r.quadric().expect("quadric");
        // a point of z = xy: (3, 2, 6)
        let x = [q(1), q(3), q(2), q(6)];
        assert!(quad_form(&quad, &x).is_zero());
        let t = r.transversal(&q(5));
        assert!(t.meets(&a) && t.meets(&b) && t.meets(&c));
        assert!(matches!(
            Regulus::from_lines(&a, &a, &c),
            Err(LineError::NotSkew(..))
        ));
    }

    #[test]
    fn four_lines_transversals() {
        let a = aff([0, 0, 0], [0, 1, 0]);
        let b = aff([1, 0, 0], [1, 1, 1]);
        let c = aff([2, 0, 0], [2, 1, 2]);
        // a fourth line of the same regulus: infinitely many
        let d = aff([3, 0, 0], [3, 1, 3]);
        assert!(matches!(
            common_transversals([&a, &b, &c, &d]).expect("ok"),
            CommonTransversals::Infinitely(_)
        ));
        // a generic fourth line: two transversals (meets the quadric z = xy twice)
        let e = aff([0, 0, 1], [1, 1, 1]);
        match common_transversals([&a, &b, &c, &e]).expect("ok") {
            CommonTransversals::Two([t1, t2]) => {
                for t in [&t1, &t2] {
                    for l in [&a, &b, &c, &e] {
                        let le = l.map_scalar(|x| QuadExt::rational(x.clone()));
                        assert!(t.reciprocal_product(&le).is_zero());
                    }
                    assert!(t.klein_form().is_zero());
                }
            }
            other => panic!("expected two transversals, got {other:?}"),
        }
    }

    /// The decisions recorded on exact lines and replayed in `f64` give the exact
    /// transversals in the same order, to rounding: four lines through points of the
    /// x-axis and of the line `(0, s, 1)` with non-binary coordinates (tenths).
    #[test]
    fn replayed_transversals_are_the_exact_ones() {
        let tenth = |n: i64| q(n) / q(10);
        let ends = [(1, 3), (-7, 2), (4, -9), (11, 5)];
        let lines: Vec<Line<Rational>> = ends
            .iter()
            .map(|&(a, b)| {
                Line::from_affine_points(&[tenth(a), q(0), q(0)], &[q(0), tenth(b), q(1)])
                    .expect("line")
            })
            .collect();
        let (exact, route) =
            common_transversals_recorded([&lines[0], &lines[1], &lines[2], &lines[3]])
                .expect("exact");
        assert_eq!(route.count(), TransversalCount::Two);
        let CommonTransversals::Two(exact) = exact else {
            panic!("two transversals expected")
        };
        let float: Vec<Line<f64>> = lines.iter().map(|l| l.map_scalar(Scalar::to_f64)).collect();
        let replayed =
            common_transversals_along([&float[0], &float[1], &float[2], &float[3]], &route)
                .expect("f64");
        let CommonTransversals::Two(replayed) = replayed else {
            panic!("two transversals expected in f64")
        };
        for (e, f) in exact.iter().zip(&replayed) {
            let e: Vec<f64> = e.coords().iter().map(Scalar::to_f64).collect();
            let size = e.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            for (a, b) in e.iter().zip(f.coords()) {
                assert!((a - b).abs() <= 1e-13 * size, "{e:?} vs {:?}", f.coords());
            }
        }
    }

    #[test]
    fn perpendicular() {
        let g = aff([0, 0, 0], [1, 0, 0]);
        let h = aff([0, 0, 2], [0, 1, 2]);
        let p = common_perpendicular(&g, &h).expect("perp");
        assert!(p.meets(&g) && p.meets(&h));
        assert_eq!(p.direction()[0], q(0));
        assert_eq!(p.direction()[1], q(0));
    }
}
