//! Hermite interpolation by general helical PH quintics (Besednjak ch. 9;
//! docs/math/ph-curves.md, "Hermite interpolation by helical PH quintics", after Farouki–Han–Manni–Sestini 2004).
//!
//! Data `p_s, d_s, p_f, d_f`; the quintic with preimage `A_0, A_1 = c_0A_0 + c_2A_2, A_2`
//! (real `c`'s, Besednjak (6.11)) interpolates `r(0) = p_s`, `r'(0) = d_s`, `r(1) = p_f`,
//! `r'(1) = d_f` iff `A_0iA_0* = d_s`, `A_2iA_2* = d_f` (9.7) and, with `k_i = c_i + 3/4`,
//! `X = A_0iA_2* + A_2iA_0*`, `h = 120Δp − 15(d_s + d_f)` (9.22):
//!
//! `16k_0² d_s + 16k_2² d_f + (16k_0k_2 − 5) X = h`.
//!
//! # The elimination used here (replaces the `ξ = tan(φ/2)` quartic (9.27)–(9.28))
//!
//! As `φ` runs, `X` runs over an ellipse that is intrinsic to `d_s, d_f` (checked
//! symbolically: `checks/001`-style sympy identity, see the tests): with
//! `m = |d_s||d_f|`, `g = d_s·d_f`,
//!
//! * (E1) `m (d_s·X) = |d_s|² (d_f·X)` (a plane), and
//! * (E2) `|d_s|²|X|² − (d_s·X)² = 2(m − g)|d_s|²` (a cylinder).
//!
//! With unknowns `r_1 = 16k_0²`, `r_2 = 16k_2²`, `r_3 = 16k_0k_2 − 5` and
//! `Y = h − r_1 d_s − r_2 d_f = r_3 X`, (E1) is linear, `a_1 r_1 + a_2 r_2 = c` with
//! `a_1 = |d_s|²(m − g)`, `a_2 = m(g − m)`, `c = m(d_s·h) − |d_s|²(d_f·h)`; so
//! `r_1 = s`, `r_2 = e_0 + e_1 s`. (E2) reads `G(s) = κ r_3²` with
//! `G = |d_s × Y|²`, `κ = 2(m − g)|d_s|²`, and the compatibility (9.26)
//! `r_1r_2 = (r_3 + 5)²` then gives `r_3 = L(s) = (s(e_0 + e_1 s) − 25 − G/κ)/10` and the
//! quartic
//!
//! `Q(s) = κ L(s)² − G(s) = 0`,
//!
//! whose coefficients lie in `Q(m)` — rational when `|d_s|²|d_f|²` is a square (as in
//! Besednjak Ex 9.1), otherwise in the real quadratic field `Q(√(|d_s|²|d_f|²))`, where
//! the real roots are isolated exactly (Sturm sequences with exact signs). Unlike the
//! `ξ`-quartic this loses no solution at `φ = π` (docs/math/ph-curves.md, Errata E25) and needs no particular
//! solution of (9.7) (whose coefficients are nested radicals); it works for
//! antiparallel end tangents too (where Cramer's rule (9.23)–(9.25) fails). Each real
//! root with `r_1, r_2 ≥ 0` and `r_3 ≠ 0` gives two interpolants
//! `k_0 = ±√r_1/4`, `k_2 = ±sgn(r_3+5)√r_2/4` (same sign), so there are at most 8.
//!
//! The control points depend on `d_s, d_f, X, c_0, c_2` only ((9.4) with
//! `A_0iA_1* + A_1iA_0* = 2c_0d_s + c_2X`, `A_1iA_1* = c_0²d_s + c_0c_2X + c_2²d_f`,
//! `A_1iA_2* + A_2iA_1* = c_0X + 2c_2d_f`); they are exact whenever the root and the two
//! square roots are rational. The quaternion preimage (`A_0 = Â_0`, `A_2 = Â_2e^{iφ}`
//! with `X = u cos φ + v sin φ`, `u = Â_0iÂ_2* + Â_2iÂ_0*`, `v = Â_0Â_2* − Â_2Â_0*`,
//! docs/math/ph-curves.md, "Hermite interpolation by helical PH quintics") is computed in `f64`.

use super::frame::RationalFunction;
use super::helix::HelixTest;
use super::hodograph::{solve_qiq, PhCurve, PhPolyCurve};
use super::util::*;
use super::PhError;
use rcagd_algebra::quadratic::{sqrt_in_extension, QuadExt};
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Certificate, Poly, Rational, Ring, Scalar};

/// Hermite data: end points and end derivatives.
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteData<F> {
    /// `p_s = r(0)`.
    pub p_s: [F; 3],
    /// `d_s = r'(0)`.
    pub d_s: [F; 3],
    /// `p_f = r(1)`.
    pub p_f: [F; 3],
    /// `d_f = r'(1)`.
    pub d_f: [F; 3],
}

/// One real root of the elimination quartic `Q(s)` (`s = r_1 = 16k_0²`).
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteRoot<K> {
    /// Isolating interval `(lo, hi]` (or `lo = hi` for an exactly found root) — exact for
    /// exact `K`.
    pub lo: K,
    /// Upper end.
    pub hi: K,
    /// The exact root, when it was found in `K`.
    pub exact: Option<K>,
    /// `s ≈ r_1` in `f64`.
    pub s: f64,
    /// `r_2 = 16k_2²` in `f64`.
    pub r2: f64,
    /// `r_3 = 16k_0k_2 − 5` in `f64`.
    pub r3: f64,
    /// `true` if `r_1 ≥ 0`, `r_2 ≥ 0` and `r_3 ≠ 0` (decided exactly for exact `K`).
    pub valid: bool,
}

/// One interpolating helical quintic.
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteInterpolant {
    /// Index of its root in [`HermiteSolution::roots`].
    pub root_index: usize,
    /// The branch `ε = ±1`: `k_0 = ε√r_1/4`, `k_2 = ε·sgn(r_3 + 5)·√r_2/4`.
    pub eps: i8,
    /// `k_0 = c_0 + 3/4`.
    pub k0: f64,
    /// `k_2 = c_2 + 3/4`.
    pub k2: f64,
    /// `c_0`.
    pub c0: f64,
    /// `c_2`.
    pub c2: f64,
    /// `φ` with `A_2 = Â_2 e^{iφ}` (`Â` the particular solutions at `φ = 0`,
    /// docs/math/ph-curves.md, "Prescribed tangents (Lemma 2.1)").
    pub phi: f64,
    /// `ξ = tan(φ/2)`, the unknown of Besednjak's quartic (9.27).
    pub xi: f64,
    /// `X = A_0iA_2* + A_2iA_0*`.
    pub x: [f64; 3],
    /// The curve, quaternion form, `f64`.
    pub curve: PhCurve<f64>,
    /// The exact control points, when the root and both square roots are rational.
    pub exact_control_points: Option<Vec<[Rational; 3]>>,
    /// Bending energy `∫κ²σ dt` (Besednjak (9.29)).
    pub bending_energy: f64,
    /// The `f64` helix test: an axis (`a·r' ≡ σ`), or planar (ψ = π/2, a trivial helix).
    pub helix: HelixTest<f64>,
    /// `true` for the least-energy interpolant(s) (ties within `1e-9` relative).
    pub least_energy: bool,
}

/// All solutions of the Hermite problem.
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteSolution<K> {
    /// The data (in `K`).
    pub data: HermiteData<K>,
    /// `m = |d_s||d_f|`.
    pub m: K,
    /// `r_2 = e_0 + e_1 s` on the plane (E1).
    pub e: [K; 2],
    /// The elimination quartic `Q(s)` (power form).
    pub quartic: Poly<K>,
    /// `r_3 = L(s)`.
    pub r3_poly: Poly<K>,
    /// Real roots of `Q`.
    pub roots: Vec<HermiteRoot<K>>,
    /// Every interpolant (≤ 8), valid roots only.
    pub interpolants: Vec<HermiteInterpolant>,
    /// `Some((16k_0², 16k_2²))` if a root has `r_3 = 16k_0k_2 − 5 = 0` with `r_1, r_2 ≥ 0`:
    /// then `h = r_1d_s + r_2d_f` and every `φ` gives an interpolant (a one-parameter
    /// family, not enumerated in [`Self::interpolants`]).
    pub continuum: Option<(f64, f64)>,
}

impl<F: Scalar> HermiteData<F> {
    /// New data.
    pub fn new(p_s: [F; 3], d_s: [F; 3], p_f: [F; 3], d_f: [F; 3]) -> Self {
        HermiteData { p_s, d_s, p_f, d_f }
    }

    fn map<K: Scalar>(&self, f: impl Fn(&F) -> K) -> HermiteData<K> {
        let m3 = |v: &[F; 3]| [f(&v[0]), f(&v[1]), f(&v[2])];
        HermiteData {
            p_s: m3(&self.p_s),
            d_s: m3(&self.d_s),
            p_f: m3(&self.p_f),
            d_f: m3(&self.d_f),
        }
    }

    /// Exact solution over `Q(m)`, `m = |d_s||d_f|` (a [`QuadExt`]; rational when
    /// `|d_s|²|d_f|²` is a square). `f64` data are converted exactly.
    ///
    /// # Errors
    /// [`PhError::ZeroTangent`], [`PhError::ParallelEndTangents`] (same direction),
    /// [`PhError::CoincidentEndPoints`], [`PhError::NoRealSolution`] if no interpolant
    /// exists; [`PhError::OutOfRange`] for non-finite `f64` data.
    pub fn solve_exact(&self) -> Result<HermiteSolution<QuadExt>, PhError> {
        let bad = core::cell::Cell::new(false);
        let data = self.map(|x| match x.to_rational() {
            Some(q) => QuadExt::rational(q),
            None => {
                bad.set(true);
                QuadExt::rational(Rational::from(0))
            }
        });
        if bad.get() {
            return Err(PhError::OutOfRange("non-finite Hermite data".into()));
        }
        check_data(&data)?;
        let m2 = dot3(&data.d_s, &data.d_s) * dot3(&data.d_f, &data.d_f);
        let m2r = m2.to_rational().unwrap_or_else(|| Rational::from(0));
        let m = sqrt_in_extension(&m2r)?;
        solve_in(data, m)
    }

    /// The same algorithm in `f64` (roots by Sturm sequences in floating point).
    ///
    /// # Errors
    /// As [`Self::solve_exact`].
    pub fn solve_f64(&self) -> Result<HermiteSolution<f64>, PhError> {
        let data = self.map(|x| x.to_f64());
        super::util::check_finite(
            || "the Hermite data (p_s, d_s, p_f, d_f) in f64".into(),
            data.p_s
                .iter()
                .chain(&data.d_s)
                .chain(&data.p_f)
                .chain(&data.d_f),
        )?;
        check_data(&data)?;
        let m = (dot3(&data.d_s, &data.d_s) * dot3(&data.d_f, &data.d_f)).sqrt();
        super::util::check_finite(|| "|d_s|·|d_f| (from d_s, d_f)".into(), [&m])?;
        // The f64 elimination decides the refusals (near-parallel tangents within a
        // tolerance, overflow) as before; its values are not used: formed in f64, the
        // quartic's coefficients lose up to 8 digits to cancellation in κl² − g (a random
        // draw: k₀ off by 2e-9). They are formed exactly over Q(|d_s||d_f|) from the f64
        // data's exact binary values (a few dozen operations) and rounded once.
        eliminate(&data, &m)?;
        let exact = solve_exact_elimination(&data)?;
        solve_with(data, m, exact.to_f64())
    }

    /// `h = 120Δp − 15(d_s + d_f)` (Besednjak (9.22)).
    pub fn h(&self) -> [F; 3] {
        let dp = sub3(&self.p_f, &self.p_s);
        sub3(
            &scale3(&dp, &F::from_i64(120)),
            &scale3(&add3(&self.d_s, &self.d_f), &F::from_i64(15)),
        )
    }
}

/// The [`Elimination`] of finite `f64` data, exactly over `Q(m)`, `m = |d_s||d_f|`.
fn solve_exact_elimination(data: &HermiteData<f64>) -> Result<Elimination<QuadExt>, PhError> {
    let exact = data.map(|x| QuadExt::rational(x.to_rational().unwrap_or_default()));
    let m2 = dot3(&exact.d_s, &exact.d_s) * dot3(&exact.d_f, &exact.d_f);
    let m = sqrt_in_extension(&m2.to_rational().unwrap_or_default())?;
    eliminate(&exact, &m)
}

fn check_data<K: Scalar>(d: &HermiteData<K>) -> Result<(), PhError> {
    if is_zero3(&d.d_s) {
        return Err(PhError::ZeroTangent("the start tangent d_s is zero".into()));
    }
    if is_zero3(&d.d_f) {
        return Err(PhError::ZeroTangent("the end tangent d_f is zero".into()));
    }
    if is_zero3(&sub3(&d.p_f, &d.p_s)) {
        return Err(PhError::CoincidentEndPoints(
            "p_s = p_f: a helix with cos ψ ≠ 0 cannot close (a·(p_f − p_s) = L·cos ψ)".into(),
        ));
    }
    Ok(())
}

/// The control points of the helical quintic from `d_s, d_f, X, c_0, c_2` (Besednjak (9.4)),
/// in any ring that can represent the fractions `f(p, q) = p/q` (exact scalars, `f64`,
/// intervals).
pub(crate) fn control_points_from<K: Ring>(
    p_s: &[K; 3],
    d_s: &[K; 3],
    d_f: &[K; 3],
    x: &[K; 3],
    c0: &K,
    c2: &K,
    f: &dyn Fn(i64, i64) -> K,
) -> Vec<[K; 3]> {
    let inc = [
        scale3(d_s, &f(1, 5)),
        scale3(
            &add3(&scale3(d_s, &(K::from_i64(2) * c0.clone())), &scale3(x, c2)),
            &f(1, 10),
        ),
        scale3(
            &add3(
                x,
                &scale3(
                    &add3(
                        &add3(
                            &scale3(d_s, &(c0.clone() * c0.clone())),
                            &scale3(x, &(c0.clone() * c2.clone())),
                        ),
                        &scale3(d_f, &(c2.clone() * c2.clone())),
                    ),
                    &K::from_i64(4),
                ),
            ),
            &f(1, 30),
        ),
        scale3(
            &add3(&scale3(x, c0), &scale3(d_f, &(K::from_i64(2) * c2.clone()))),
            &f(1, 10),
        ),
        scale3(d_f, &f(1, 5)),
    ];
    let mut pts = vec![p_s.clone()];
    for d in inc.iter() {
        let next = add3(pts.last().unwrap_or(p_s), d);
        pts.push(next);
    }
    pts
}

/// The elimination of the Hermite system in `s = r₁ = 16k₀²`: `r₂ = e₀ + e₁s`,
/// `Y(s) = Y₀ + sY₁`, `r₃ = l(s)` and the quartic whose real roots give the interpolants.
struct Elimination<K> {
    e0: K,
    e1: K,
    y0: [K; 3],
    y1: [K; 3],
    l: Poly<K>,
    quartic: Poly<K>,
}

impl<K: Scalar> Elimination<K> {
    /// Each value correctly rounded to `f64`.
    fn to_f64(&self) -> Elimination<f64> {
        Elimination {
            e0: self.e0.to_f64(),
            e1: self.e1.to_f64(),
            y0: to_f64_3(&self.y0),
            y1: to_f64_3(&self.y1),
            l: poly_f64(&self.l),
            quartic: poly_f64(&self.quartic),
        }
    }
}

fn solve_in<K: Scalar>(data: HermiteData<K>, m: K) -> Result<HermiteSolution<K>, PhError> {
    let elimination = eliminate(&data, &m)?;
    solve_with(data, m, elimination)
}

/// [`Elimination`] of `data` (`m = |d_s||d_f|`).
///
/// # Errors
/// [`PhError::ParallelEndTangents`] (in `f64` within a tolerance), a non-finite quartic,
/// [`PhError::Degenerate`] for a quartic that vanishes identically.
fn eliminate<K: Scalar>(data: &HermiteData<K>, m: &K) -> Result<Elimination<K>, PhError> {
    let m = m.clone();
    let ds = data.d_s.clone();
    let df = data.d_f.clone();
    let h = data.h();
    let nds = dot3(&ds, &ds);
    let g = dot3(&ds, &df);
    let a1 = nds.clone() * (m.clone() - g.clone());
    let a2 = m.clone() * (g.clone() - m.clone());
    if a2.is_zero()
        || (!K::EXACT && a2.to_f64().abs() <= 1e-12 * m.to_f64().abs() * m.to_f64().abs())
    {
        return Err(PhError::ParallelEndTangents(
            "d_s and d_f point in the same direction: the interpolation system is degenerate \
             (X is confined to the common line)"
                .into(),
        ));
    }
    let c = m.clone() * dot3(&ds, &h) - nds.clone() * dot3(&df, &h);
    let e0 = c / a2.clone();
    let e1 = -(a1 / a2);
    // Y(s) = h − s d_s − (e0 + e1 s) d_f = Y0 + s Y1
    let y0 = sub3(&h, &scale3(&df, &e0));
    let y1 = scale3(&add3(&ds, &scale3(&df, &e1)), &-K::one());
    let cy0 = cross3(&ds, &y0);
    let cy1 = cross3(&ds, &y1);
    let gpoly = Poly::new(vec![
        dot3(&cy0, &cy0),
        K::from_i64(2) * dot3(&cy0, &cy1),
        dot3(&cy1, &cy1),
    ]);
    let kappa = K::from_i64(2) * (m.clone() - g) * nds;
    let r1r2 = Poly::new(vec![K::zero(), e0.clone(), e1.clone()]);
    let l = (&(&r1r2 - &Poly::constant(K::from_i64(25)))
        - &gpoly.scale(&(K::one() / kappa.clone())))
        .scale(&(K::one() / K::from_i64(10)));
    let quartic = &(&l * &l).scale(&kappa) - &gpoly;
    super::util::check_finite(
        || "the elimination quartic's coefficients (from the Hermite data)".into(),
        quartic.coeffs(),
    )?;
    if quartic.is_zero() {
        return Err(PhError::Degenerate(
            "the elimination quartic vanishes identically (a continuum of solutions)".into(),
        ));
    }
    Ok(Elimination {
        e0,
        e1,
        y0,
        y1,
        l,
        quartic,
    })
}

/// The interpolants from the roots of the elimination quartic.
fn solve_with<K: Scalar>(
    data: HermiteData<K>,
    m: K,
    elimination: Elimination<K>,
) -> Result<HermiteSolution<K>, PhError> {
    let Elimination {
        e0,
        e1,
        y0,
        y1,
        l,
        quartic,
    } = elimination;
    let r2lin = Poly::new(vec![e0.clone(), e1.clone()]);
    let roots_iv = isolate_roots(&quartic);
    let mut roots = Vec::new();
    let mut interpolants = Vec::new();
    let mut continuum = None;
    for (idx, iv) in roots_iv.into_iter().enumerate() {
        let (lo, hi, exact) = iv;
        let s_sign = sign_at_root(&quartic, &lo, &hi, &exact, &Poly::x());
        let r2_sign = sign_at_root(&quartic, &lo, &hi, &exact, &r2lin);
        let r3_sign = sign_at_root(&quartic, &lo, &hi, &exact, &l);
        let (lo, hi) = refine(&quartic, lo, hi, &exact);
        let s = match &exact {
            Some(x) => x.to_f64(),
            None => polish_f64(&quartic, &lo, &hi),
        };
        let r2 = e0.to_f64() + e1.to_f64() * s;
        let r3 = poly_f64(&l).eval(&s);
        let valid = s_sign >= 0 && r2_sign >= 0 && r3_sign != 0;
        roots.push(HermiteRoot {
            lo,
            hi,
            exact: exact.clone(),
            s,
            r2,
            r3,
            valid,
        });
        if s_sign >= 0 && r2_sign >= 0 && r3_sign == 0 {
            continuum = Some((s, r2));
        }
        if !valid {
            continue;
        }
        let r1f = s.max(0.0);
        let r2f = r2.max(0.0);
        let sg = if r3 + 5.0 >= 0.0 { 1.0 } else { -1.0 };
        for eps in [1.0, -1.0] {
            let k0 = eps * r1f.sqrt() / 4.0;
            let k2 = eps * sg * r2f.sqrt() / 4.0;
            let c0 = k0 - 0.75;
            let c2 = k2 - 0.75;
            let yv = add3(&to_f64_3(&y0), &scale3(&to_f64_3(&y1), &s));
            let x = scale3(&yv, &(1.0 / r3));
            let exact_pts = exact
                .as_ref()
                .and_then(|sx| exact_points(&data, sx, &e0, &e1, &l, &y0, &y1, eps > 0.0));
            let curve = build_f64_curve(&data, &x, c0, c2)?;
            let pc = curve.to_poly_curve();
            let energy = pc.bending_energy().unwrap_or(f64::INFINITY);
            let helix = pc.helix_test().unwrap_or(HelixTest::NotHelix);
            let phi = phi_of(&curve);
            interpolants.push(HermiteInterpolant {
                root_index: idx,
                eps: if eps > 0.0 { 1 } else { -1 },
                k0,
                k2,
                c0,
                c2,
                phi,
                xi: (phi / 2.0).tan(),
                x,
                curve,
                exact_control_points: exact_pts,
                bending_energy: energy,
                helix,
                least_energy: false,
            });
        }
    }
    if interpolants.is_empty() {
        if continuum.is_some() {
            return Err(PhError::Degenerate(
                "16k_0k_2 = 5 and h = 120Δp − 15(d_s + d_f) lies in span(d_s, d_f): every φ gives \
                 an interpolant (a one-parameter family)"
                    .into(),
            ));
        }
        return Err(PhError::NoRealSolution(format!(
            "none of the {} real roots of the elimination quartic gives 16k_0² ≥ 0, 16k_2² ≥ 0 \
             and 16k_0k_2 ≠ 5 (roots s = 16k_0² ≈ {:?}, 16k_2² ≈ {:?})",
            roots.len(),
            roots.iter().map(|r| r.s).collect::<Vec<_>>(),
            roots.iter().map(|r| r.r2).collect::<Vec<_>>()
        )));
    }
    let best = interpolants
        .iter()
        .map(|i| i.bending_energy)
        .fold(f64::INFINITY, f64::min);
    for i in interpolants.iter_mut() {
        i.least_energy = (i.bending_energy - best).abs() <= 1e-9 * best.abs().max(1e-300);
    }
    Ok(HermiteSolution {
        data,
        m,
        e: [e0, e1],
        quartic,
        r3_poly: l,
        roots,
        interpolants,
        continuum,
    })
}

/// Exact control points when `s`, `√r_1`, `√r_2` are rational.
#[allow(clippy::too_many_arguments)]
fn exact_points<K: Scalar>(
    data: &HermiteData<K>,
    s: &K,
    e0: &K,
    e1: &K,
    l: &Poly<K>,
    y0: &[K; 3],
    y1: &[K; 3],
    plus: bool,
) -> Option<Vec<[Rational; 3]>> {
    let r2 = e0.clone() + e1.clone() * s.clone();
    let r3 = l.eval(s);
    if r3.is_zero() {
        return None;
    }
    let four = K::from_i64(4);
    let sq1 = sqrt_scalar(s)?;
    let sq2 = sqrt_scalar(&r2)?;
    let sgn = if r3.clone() + K::from_i64(5) >= K::zero() {
        K::one()
    } else {
        -K::one()
    };
    let eps = if plus { K::one() } else { -K::one() };
    let k0 = eps.clone() * sq1 / four.clone();
    let k2 = eps * sgn * sq2 / four;
    let three_q = K::from_i64(3) / K::from_i64(4);
    let c0 = k0 - three_q.clone();
    let c2 = k2 - three_q;
    let x = scale3(&add3(y0, &scale3(y1, s)), &(K::one() / r3));
    let frac = |p: i64, q: i64| K::from_i64(p) / K::from_i64(q);
    let pts = control_points_from(&data.p_s, &data.d_s, &data.d_f, &x, &c0, &c2, &frac);
    pts.iter()
        .map(|p| {
            Some([
                p[0].to_rational()?,
                p[1].to_rational()?,
                p[2].to_rational()?,
            ])
        })
        .collect()
}

/// The `f64` curve: `A_0 = Â_0`, `A_2 = Â_2 e^{iφ}` with `X = u cos φ + v sin φ`.
fn build_f64_curve<K: Scalar>(
    data: &HermiteData<K>,
    x: &[f64; 3],
    c0: f64,
    c2: f64,
) -> Result<PhCurve<f64>, PhError> {
    let ds = to_f64_3(&data.d_s);
    let df = to_f64_3(&data.d_f);
    let a0 = solve_qiq(&ds, None)?;
    let a2h = solve_qiq(&df, None)?;
    let u = qvec(&qadd(&sandwich(&a0, 1, &a2h), &sandwich(&a2h, 1, &a0)));
    let v = qvec(&qsub(&qmul(&a0, &qconj(&a2h)), &qmul(&a2h, &qconj(&a0))));
    // least squares for (cos φ, sin φ)
    let (uu, uv, vv) = (dot3(&u, &u), dot3(&u, &v), dot3(&v, &v));
    let (ux, vx) = (dot3(&u, x), dot3(&v, x));
    let det = uu * vv - uv * uv;
    let (co, si) = if det.abs() > 1e-300 {
        ((vv * ux - uv * vx) / det, (uu * vx - uv * ux) / det)
    } else if uu > 0.0 {
        (ux / uu, 0.0)
    } else {
        (1.0, 0.0)
    };
    let n = (co * co + si * si).sqrt();
    let (co, si) = if n > 0.0 {
        (co / n, si / n)
    } else {
        (1.0, 0.0)
    };
    let a2 = qmul(&a2h, &Quaternion::new(co, si, 0.0, 0.0));
    let a1 = qadd(&qscale(&a0, &c0), &qscale(&a2, &c2));
    PhCurve::new(vec![a0, a1, a2], to_f64_3(&data.p_s))
}

fn phi_of(curve: &PhCurve<f64>) -> f64 {
    // A_2 = Â_2 e^{iφ}: recover φ from A_2 and the particular solution of A_2 i A_2*.
    let a2 = &curve.coefficients()[2];
    let df = qvec(&sandwich(a2, 1, a2));
    match solve_qiq(&df, None) {
        Ok(h) => {
            // e^{iφ} = Â_2^{-1} A_2 = Â_2* A_2 / |Â_2|²
            let e = qmul(&qconj(&h), a2);
            e.x.atan2(e.w)
        }
        Err(_) => 0.0,
    }
}

impl<K: Scalar> HermiteSolution<K> {
    /// The least-energy interpolants (several on ties).
    pub fn best(&self) -> Vec<&HermiteInterpolant> {
        self.interpolants
            .iter()
            .filter(|i| i.least_energy)
            .collect()
    }

    /// `r_3(s) = L(s)` as a rational function of nothing (convenience for tests).
    pub fn r3_function(&self) -> RationalFunction<K> {
        RationalFunction {
            num: self.r3_poly.clone(),
            den: Poly::constant(K::one()),
        }
    }

    /// Certificates: for each root, the Sturm count of `Q` on its isolating interval is
    /// 1 (exact for exact `K`); for each interpolant (`f64`): `p_0 = p_s`, `p_5 = p_f`,
    /// `A_0iA_0* = d_s`, `A_2iA_2* = d_f`, (9.22), the PH identity, the helix identity
    /// `a·r' ≡ σ`; and, when exact control points exist, `p_0 = p_s`, `p_5 = p_f`,
    /// `5(p_1 − p_0) = d_s`, `5(p_5 − p_4) = d_f`, PH and helix tests exactly.
    pub fn certify(&self) -> Vec<Certificate> {
        let mut certs = Vec::new();
        let chain = sturm_chain(&self.quartic);
        for (i, r) in self.roots.iter().enumerate() {
            if !K::EXACT {
                certs.push(f64_root_certificate(i, &self.quartic, r));
                continue;
            }
            let count = if r.exact.is_some() {
                1
            } else {
                sign_changes(&chain, &r.lo) as i64 - sign_changes(&chain, &r.hi) as i64
            };
            certs.push(Certificate::decide(
                format!("root {i}: the quartic Q(s) has exactly one real root in its isolating interval"),
                count == 1,
                K::EXACT,
                || format!("Sturm count {count}"),
            ));
        }
        let d = &self.data;
        let (ps, pf, ds, df) = (
            to_f64_3(&d.p_s),
            to_f64_3(&d.p_f),
            to_f64_3(&d.d_s),
            to_f64_3(&d.d_f),
        );
        let hf = to_f64_3(&d.h());
        for (i, s) in self.interpolants.iter().enumerate() {
            let pts = s.curve.control_points();
            let a = s.curve.coefficients();
            certs.push(v3_cert(format!("interpolant {i}: p_0 = p_s"), &pts[0], &ps));
            certs.push(v3_cert(format!("interpolant {i}: p_5 = p_f"), &pts[5], &pf));
            certs.push(v3_cert(
                format!("interpolant {i}: A_0 i A_0* = d_s"),
                &qvec(&sandwich(&a[0], 1, &a[0])),
                &ds,
            ));
            certs.push(v3_cert(
                format!("interpolant {i}: A_2 i A_2* = d_f"),
                &qvec(&sandwich(&a[2], 1, &a[2])),
                &df,
            ));
            let lhs = add3(
                &add3(
                    &scale3(&ds, &(16.0 * s.k0 * s.k0)),
                    &scale3(&df, &(16.0 * s.k2 * s.k2)),
                ),
                &scale3(&s.x, &(16.0 * s.k0 * s.k2 - 5.0)),
            );
            certs.push(v3_cert(
                format!("interpolant {i}: 16k_0²d_s + 16k_2²d_f + (16k_0k_2−5)X = h (9.22)"),
                &lhs,
                &hf,
            ));
            certs.extend(s.curve.certify());
            certs.extend(s.curve.to_poly_curve().certify_helix_test(&s.helix));
            if let Some(ep) = &s.exact_control_points {
                certs.extend(certify_exact_points(i, ep, d));
            }
        }
        certs
    }
}

/// The `f64` root certificate: a Sturm count evaluated in floating point is not
/// reliable (its sequence's signs near a root are rounding), so in `f64` the root `i` is
/// certified by a sign change of `Q` at the ends of its interval, or by `|Q(s)|` within
/// rounding of its terms, `|Q(s)| ≤ 10⁻⁹ Σ|q_k||s|^k` (an even-multiplicity root has no
/// sign change).
fn f64_root_certificate<K: Scalar>(i: usize, quartic: &Poly<K>, r: &HermiteRoot<K>) -> Certificate {
    let coeffs: Vec<f64> = quartic.coeffs().iter().map(Scalar::to_f64).collect();
    let eval = |x: f64| coeffs.iter().rev().fold(0.0, |acc, c| acc * x + c);
    let size = |x: f64| {
        coeffs
            .iter()
            .rev()
            .fold(0.0, |acc, c| acc * x.abs() + c.abs())
    };
    let (lo, hi) = (r.lo.to_f64(), r.hi.to_f64());
    let (a, b, at) = (eval(lo), eval(hi), eval(r.s));
    let change = a * b <= 0.0;
    let small = at.abs() <= 1e-9 * size(r.s);
    Certificate::decide(
        format!("root {i}: the quartic Q(s) has a real root in its interval (f64: a sign change at its ends, or |Q(s)| within rounding of its terms)"),
        change || small,
        false,
        || format!("Q(lo) = {a:e}, Q(hi) = {b:e}, Q(s) = {at:e}"),
    )
}

impl<K: Scalar> crate::Certified for HermiteSolution<K> {
    fn certify(&self) -> Vec<Certificate> {
        HermiteSolution::certify(self)
    }
}

fn certify_exact_points<K: Scalar>(
    i: usize,
    ep: &[[Rational; 3]],
    d: &HermiteData<K>,
) -> Vec<Certificate> {
    let r3 = |v: &[K; 3]| -> [Rational; 3] {
        let z = || Rational::from(0);
        [
            v[0].to_rational().unwrap_or_else(z),
            v[1].to_rational().unwrap_or_else(z),
            v[2].to_rational().unwrap_or_else(z),
        ]
    };
    let mut certs = Vec::new();
    let (Some(first), Some(last)) = (ep.first(), ep.last()) else {
        return certs;
    };
    let five = Rational::from(5);
    certs.push(v3_cert(
        format!("interpolant {i} (exact): p_0 = p_s"),
        first,
        &r3(&d.p_s),
    ));
    certs.push(v3_cert(
        format!("interpolant {i} (exact): p_5 = p_f"),
        last,
        &r3(&d.p_f),
    ));
    if ep.len() == 6 {
        certs.push(v3_cert(
            format!("interpolant {i} (exact): 5(p_1 − p_0) = d_s"),
            &scale3(&sub3(&ep[1], &ep[0]), &five),
            &r3(&d.d_s),
        ));
        certs.push(v3_cert(
            format!("interpolant {i} (exact): 5(p_5 − p_4) = d_f"),
            &scale3(&sub3(&ep[5], &ep[4]), &five),
            &r3(&d.d_f),
        ));
    }
    let comp = |c: usize| {
        rcagd_algebra::bernstein::from_bernstein(
            &ep.iter().map(|p| p[c].clone()).collect::<Vec<_>>(),
        )
    };
    match PhPolyCurve::from_polynomials([comp(0), comp(1), comp(2)]) {
        Ok(pc) => {
            certs.extend(pc.certify());
            match pc.helix_test() {
                Ok(t) => certs.extend(pc.certify_helix_test(&t)),
                Err(e) => certs.push(Certificate::fails(
                    format!("interpolant {i} (exact): helix"),
                    e.to_string(),
                    true,
                )),
            }
        }
        Err(e) => certs.push(Certificate::fails(
            format!("interpolant {i} (exact): PH"),
            e.to_string(),
            true,
        )),
    }
    certs
}

// ------------------------------------------------------------------ real roots (Sturm)

/// Sturm chain `p, p', −rem(…)…` (for `f64`, tiny remainder coefficients are dropped).
fn sturm_chain<K: Scalar>(p: &Poly<K>) -> Vec<Poly<K>> {
    let mut chain = vec![p.clone(), p.derivative()];
    while let Some(last) = chain.last() {
        if last.is_zero() || last.degree() == Some(0) {
            break;
        }
        let prev = &chain[chain.len() - 2];
        let Ok((_, r)) = prev.div_rem(last) else {
            break;
        };
        let r = if K::EXACT {
            r
        } else {
            let sc = poly_scale(prev).max(poly_scale(last));
            Poly::new(
                r.coeffs()
                    .iter()
                    .map(|c| {
                        if c.to_f64().abs() <= 1e-12 * sc {
                            K::zero()
                        } else {
                            c.clone()
                        }
                    })
                    .collect(),
            )
        };
        if r.is_zero() {
            break;
        }
        chain.push(-r);
    }
    chain
}

fn sign_changes<K: Scalar>(chain: &[Poly<K>], x: &K) -> usize {
    let mut last = 0i8;
    let mut n = 0;
    for p in chain {
        let v = p.eval(x);
        let s = if v > K::zero() {
            1
        } else if v < K::zero() {
            -1
        } else {
            0
        };
        if s != 0 {
            if last != 0 && s != last {
                n += 1;
            }
            last = s;
        }
    }
    n
}

/// Square-free part (exact division by `gcd(p, p')`).
pub(super) fn square_free<K: Scalar>(p: &Poly<K>) -> Poly<K> {
    let g = gcd_tol(p, &p.derivative());
    if g.degree().unwrap_or(0) == 0 {
        return p.clone();
    }
    p.div_rem(&g).map(|(q, _)| q).unwrap_or_else(|_| p.clone())
}

type RootIv<K> = (K, K, Option<K>);

/// Isolating intervals `(lo, hi]` of the distinct real roots of `p`, sorted, with the
/// exact root when a split point hit it (or a nearby simple rational is a root).
fn isolate_roots<K: Scalar>(p: &Poly<K>) -> Vec<RootIv<K>> {
    if !K::EXACT {
        // f64: isolate the roots of the (exactly converted) coefficients exactly
        // (integer Sturm/Descartes isolation of `rcagd_algebra::roots`), so that round-off
        // cannot invent or lose roots; each interval is refined exactly to ~1e-13
        // relative, and its endpoints are rounded to f64
        let Some(coeffs) = p
            .coeffs()
            .iter()
            .map(|c| c.to_rational())
            .collect::<Option<Vec<Rational>>>()
        else {
            return Vec::new();
        };
        let pq = Poly::new(coeffs);
        let Ok(ivs) = rcagd_algebra::roots::isolate_real_roots(&pq) else {
            return Vec::new();
        };
        return ivs
            .into_iter()
            .map(|mut iv| {
                if iv.is_exact() {
                    let x = K::from_rational(&iv.lo);
                    return (x.clone(), x.clone(), Some(x));
                }
                let mag = iv.midpoint_f64().abs().max(1.0);
                if let Ok(w) = Rational::try_from(1e-13 * mag) {
                    let _ = iv.refine(&pq, &w);
                }
                if iv.is_exact() {
                    let x = K::from_rational(&iv.lo);
                    return (x.clone(), x.clone(), Some(x));
                }
                (K::from_rational(&iv.lo), K::from_rational(&iv.hi), None)
            })
            .collect();
    }
    let sf = square_free(p);
    let Some(deg) = sf.degree() else {
        return Vec::new();
    };
    if deg == 0 {
        return Vec::new();
    }
    let lc = sf.leading();
    let bound = sf
        .coeffs()
        .iter()
        .take(deg)
        .map(|c| (c.clone() / lc.clone()).abs())
        .fold(K::zero(), |a, b| if b > a { b } else { a })
        + K::one()
        + K::one();
    let chain = sturm_chain(&sf);
    let mut out: Vec<RootIv<K>> = Vec::new();
    let mut stack = vec![(-bound.clone(), bound)];
    let mut guard = 0;
    while let Some((lo, hi)) = stack.pop() {
        guard += 1;
        if guard > 20_000 {
            break;
        }
        let n = sign_changes(&chain, &lo) as i64 - sign_changes(&chain, &hi) as i64;
        if n <= 0 {
            continue;
        }
        if n == 1 {
            out.push((lo, hi, None));
            continue;
        }
        if !K::EXACT && (hi.to_f64() - lo.to_f64()).abs() < 1e-13 * hi.to_f64().abs().max(1.0) {
            out.push((lo, hi, None));
            continue;
        }
        let mid = split_point(&sf, &lo, &hi);
        stack.push((mid.clone(), hi));
        stack.push((lo, mid));
    }
    out.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(core::cmp::Ordering::Equal));
    // look for exact (simple rational) roots
    out.into_iter()
        .map(|(lo, hi, _)| {
            let ex = find_simple_root(&sf, &lo, &hi);
            match ex {
                Some(x) => (x.clone(), x.clone(), Some(x)),
                None => (lo, hi, None),
            }
        })
        .collect()
}

/// A split point in `(lo, hi)` that is not a root of `p`.
fn split_point<K: Scalar>(p: &Poly<K>, lo: &K, hi: &K) -> K {
    let w = hi.clone() - lo.clone();
    for (a, b) in [
        (1, 2),
        (1, 3),
        (2, 3),
        (1, 5),
        (2, 5),
        (3, 5),
        (4, 5),
        (1, 7),
    ] {
        let x = lo.clone() + w.clone() * K::from_i64(a) / K::from_i64(b);
        if !p.eval(&x).is_zero() {
            return x;
        }
    }
    lo.clone() + w * K::from_i64(5) / K::from_i64(11)
}

/// Tries simple rationals (continued-fraction convergents of the `f64` root) in `(lo, hi]`.
fn find_simple_root<K: Scalar>(p: &Poly<K>, lo: &K, hi: &K) -> Option<K> {
    if !K::EXACT {
        return None;
    }
    if p.eval(hi).is_zero() {
        return Some(hi.clone());
    }
    let (lo2, hi2) = refine(p, lo.clone(), hi.clone(), &None);
    let x = polish_f64(p, &lo2, &hi2);
    if !x.is_finite() {
        return None;
    }
    // continued fraction convergents
    let (mut h0, mut h1, mut k0, mut k1) = (0i128, 1i128, 1i128, 0i128);
    let mut y = x;
    for _ in 0..40 {
        let a = y.floor();
        if a.abs() > 1e15 {
            break;
        }
        let ai = a as i128;
        let h2 = ai.checked_mul(h1)?.checked_add(h0)?;
        let k2 = ai.checked_mul(k1)?.checked_add(k0)?;
        if k2.abs() > 1_000_000_000 || h2.abs() > 1_000_000_000_000 {
            break;
        }
        let cand = K::from_i64(h2 as i64) / K::from_i64(k2 as i64);
        if cand > *lo && cand <= *hi && p.eval(&cand).is_zero() {
            return Some(cand);
        }
        h0 = h1;
        h1 = h2;
        k0 = k1;
        k1 = k2;
        let frac = y - a;
        if frac.abs() < 1e-15 {
            break;
        }
        y = 1.0 / frac;
    }
    None
}

/// Bisects `(lo, hi]` (one root, `p(lo) ≠ 0`) until its width is below `1e-12`
/// relative (exact sign tests for exact `K`).
fn refine<K: Scalar>(p: &Poly<K>, mut lo: K, mut hi: K, exact: &Option<K>) -> (K, K) {
    if let Some(x) = exact {
        return (x.clone(), x.clone());
    }
    let plo = p.eval(&lo);
    let two = K::from_i64(2);
    for _ in 0..200 {
        let w = (hi.to_f64() - lo.to_f64()).abs();
        if w <= 1e-13 * hi.to_f64().abs().max(lo.to_f64().abs()).max(1.0) {
            break;
        }
        let mid = if K::EXACT {
            // dyadic midpoint keeps the numbers small
            let m = (lo.clone() + hi.clone()) / two.clone();
            match Rational::try_from(m.to_f64()) {
                Ok(q) => {
                    let c = K::from_rational(&q);
                    if c > lo && c < hi {
                        c
                    } else {
                        m
                    }
                }
                Err(_) => m,
            }
        } else {
            (lo.clone() + hi.clone()) / two.clone()
        };
        let pm = p.eval(&mid);
        if pm.is_zero() {
            return (mid.clone(), mid);
        }
        if (pm > K::zero()) == (plo > K::zero()) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (lo, hi)
}

/// Newton polish in `f64` inside `[lo, hi]`.
fn polish_f64<K: Scalar>(p: &Poly<K>, lo: &K, hi: &K) -> f64 {
    let pf = poly_f64(p);
    let d = pf.derivative();
    let (a, b) = (lo.to_f64(), hi.to_f64());
    let mut x = 0.5 * (a + b);
    for _ in 0..8 {
        let dv = d.eval(&x);
        if dv == 0.0 {
            break;
        }
        let nx = x - pf.eval(&x) / dv;
        if !(nx >= a.min(b) && nx <= a.max(b)) {
            break;
        }
        x = nx;
    }
    x
}

/// The sign (−1, 0, 1) of `q` at the root of `p` isolated in `(lo, hi]` (exact root
/// `exact` if known): refines until `q` has no root in the interval or decides `q = 0`
/// at the root by a gcd test.
fn sign_at_root<K: Scalar>(p: &Poly<K>, lo: &K, hi: &K, exact: &Option<K>, q: &Poly<K>) -> i8 {
    let sgn = |v: K| {
        if v > K::zero() {
            1
        } else if v < K::zero() {
            -1
        } else {
            0
        }
    };
    if let Some(x) = exact {
        let v = q.eval(x);
        return if is_negligible(&v, 1.0) { 0 } else { sgn(v) };
    }
    if K::EXACT {
        // q vanishes at the root iff gcd(p, q) has a root in (lo, hi]
        let g = gcd_tol(p, q);
        if g.degree().unwrap_or(0) > 0 {
            let ch = sturm_chain(&square_free(&g));
            let n = sign_changes(&ch, lo) as i64 - sign_changes(&ch, hi) as i64;
            if n > 0 {
                return 0;
            }
        }
        let (mut a, mut b) = (lo.clone(), hi.clone());
        let chq = sturm_chain(&square_free(q));
        for _ in 0..400 {
            let n = if q.degree().unwrap_or(0) == 0 {
                0
            } else {
                sign_changes(&chq, &a) as i64 - sign_changes(&chq, &b) as i64
            };
            if n == 0 {
                return sgn(q.eval(&b));
            }
            let (a2, b2) = refine_once(p, a, b);
            a = a2;
            b = b2;
        }
        sgn(q.eval(hi))
    } else {
        let x = polish_f64(p, lo, hi);
        let v = poly_f64(q).eval(&x);
        if v.abs() <= 1e-9 * poly_scale(q).max(1.0) {
            0
        } else if v > 0.0 {
            1
        } else {
            -1
        }
    }
}

pub(super) fn refine_once<K: Scalar>(p: &Poly<K>, lo: K, hi: K) -> (K, K) {
    let mid = (lo.clone() + hi.clone()) / K::from_i64(2);
    let pm = p.eval(&mid);
    if pm.is_zero() {
        return (mid.clone(), mid);
    }
    if (pm > K::zero()) == (p.eval(&lo) > K::zero()) {
        (mid, hi)
    } else {
        (lo, mid)
    }
}

/// Besednjak's quartic (9.27)–(9.28) in `ξ = tan(φ/2)`, `[d_0, …, d_4]`, in `f64`, with
/// `u, v` from the particular solutions `Â_0, Â_2` (docs/math/ph-curves.md,
/// "Prescribed tangents (Lemma 2.1)" and "Hermite interpolation by helical PH quintics", step 2).
///
/// # Errors
/// [`PhError::ZeroTangent`] for a zero tangent.
pub fn seed_xi_quartic<F: Scalar>(data: &HermiteData<F>) -> Result<[f64; 5], PhError> {
    let ds = to_f64_3(&data.d_s);
    let df = to_f64_3(&data.d_f);
    let h = to_f64_3(&data.h());
    let a0 = solve_qiq(&ds, None)?;
    let a2 = solve_qiq(&df, None)?;
    let u = qvec(&qadd(&sandwich(&a0, 1, &a2), &sandwich(&a2, 1, &a0)));
    let v = qvec(&qsub(&qmul(&a0, &qconj(&a2)), &qmul(&a2, &qconj(&a0))));
    let b = |a: &[f64; 3], b: &[f64; 3], c: &[f64; 3]| det3(a, b, c);
    let hm = sub3(&h, &scale3(&u, &5.0));
    let hp = add3(&h, &scale3(&u, &5.0));
    let d4 = b(&h, &df, &u) * b(&ds, &h, &u) - b(&ds, &df, &hm).powi(2);
    let d3 = -2.0 * b(&h, &df, &u) * b(&ds, &h, &v)
        - 2.0 * b(&ds, &h, &u) * b(&h, &df, &v)
        - 20.0 * b(&ds, &df, &v) * b(&ds, &df, &hm);
    let d2 = -2.0 * b(&h, &df, &u) * b(&ds, &h, &u) + 4.0 * b(&h, &df, &v) * b(&ds, &h, &v)
        - 100.0 * b(&ds, &df, &v).powi(2)
        - 2.0 * b(&ds, &df, &hm) * b(&ds, &df, &hp);
    let d1 = 2.0 * b(&h, &df, &v) * b(&ds, &h, &u) + 2.0 * b(&ds, &h, &v) * b(&h, &df, &u)
        - 20.0 * b(&ds, &df, &v) * b(&ds, &df, &hp);
    let d0 = b(&h, &df, &u) * b(&ds, &h, &u) - b(&ds, &df, &hp).powi(2);
    Ok([d0, d1, d2, d3, d4])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(p: i64, q: i64) -> Rational {
        Rational::from(p) / Rational::from(q)
    }

    /// A random draw of the float tests (`p_s = 0`, `p_f = (0, 0, 1)`, long tangents): formed
    /// in f64 the quartic's coefficients lost up to 8 digits to cancellation and the root
    /// `s ≈ 241853` was off by ≈ 1e-9 relative; the f64 solve forms the elimination
    /// exactly from the f64 data and rounds once, so its roots are the exact solve's.
    #[test]
    fn f64_roots_are_the_exact_roots_to_rounding() {
        let data = HermiteData::new(
            [r(0, 1), r(0, 1), r(0, 1)],
            [r(-19, 6), r(-14, 9), r(16, 5)],
            [r(0, 1), r(0, 1), r(1, 1)],
            [r(-11, 4), r(-13, 9), r(31, 11)],
        );
        let exact = data.solve_exact().expect("exact");
        let float = data.map(Scalar::to_f64).solve_f64().expect("f64");
        assert_eq!(exact.roots.len(), float.roots.len());
        assert_eq!(float.roots.len(), 4);
        for (a, b) in exact.roots.iter().zip(&float.roots) {
            assert!((a.s - b.s).abs() <= 1e-13 * a.s.abs(), "{} {}", a.s, b.s);
        }
    }

    /// Regression: data of a helical quintic with `16k_0k_2 = 5` (a double root of `Q`).
    #[test]
    fn double_root_continuum() {
        let a0 = Quaternion::new(r(-5, 3), r(-3, 2), r(-5, 2), r(1, 2));
        let a2 = Quaternion::new(r(-2, 1), r(0, 1), r(5, 2), r(0, 1));
        let a1 = qadd(&qscale(&a0, &r(-1, 1)), &qscale(&a2, &r(-2, 1)));
        let curve = PhCurve::new(vec![a0, a1, a2], [r(0, 1), r(0, 1), r(0, 1)]).unwrap();
        let pts = curve.control_points();
        let five = r(5, 1);
        let d_s = scale3(&sub3(&pts[1], &pts[0]), &five);
        let d_f = scale3(&sub3(&pts[5], &pts[4]), &five);
        let data = HermiteData::new(pts[0].clone(), d_s, pts[5].clone(), d_f);
        let dq = data.map(|x| QuadExt::rational(x.clone()));
        let m2 = dot3(&dq.d_s, &dq.d_s) * dot3(&dq.d_f, &dq.d_f);
        let m = sqrt_in_extension(&m2.to_rational().unwrap()).unwrap();
        let ds = dq.d_s.clone();
        let df = dq.d_f.clone();
        let h = dq.h();
        let nds = dot3(&ds, &ds);
        let g = dot3(&ds, &df);
        let a1 = nds.clone() * (m.clone() - g.clone());
        let a2 = m.clone() * (g.clone() - m.clone());
        let c = m.clone() * dot3(&ds, &h) - nds.clone() * dot3(&df, &h);
        eprintln!(
            "m = {m}, e0 = {}, e1 = {}",
            c.clone() / a2.clone(),
            -(a1.clone() / a2.clone())
        );
        match solve_in(dq.clone(), m.clone()) {
            Ok(s) => {
                eprintln!("quartic {:?}", s.quartic.map(|x| x.to_f64()));
                for rt in &s.roots {
                    eprintln!("{} {} {} {}", rt.s, rt.r2, rt.r3, rt.valid);
                }
            }
            Err(e) => eprintln!("{e}"),
        }
    }
}
