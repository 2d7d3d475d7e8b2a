//! Rational rotation-minimizing frames (RRMF) on spatial PH curves (docs/math/rrmf.md).
//!
//! For `r' = A i A*` the Euler–Rodrigues frame (ERF) `(A i A*, A j A*, A k A*)/σ` turns
//! about the tangent with angular speed `e_2'·e_3 = 2N/σ`,
//! `N = u v' − u' v − p q' + p' q` (Choi, Han 2002, "Euler–Rodrigues frames on spatial
//! Pythagorean-hodograph curves"; checked with sympy in docs/math/rrmf.md). Replacing `A`
//! by `Ã = A w` with a complex polynomial `w = a + b i` gives the same curve direction
//! (`Ã i Ã* = |w|² A i A*`) and the frame `(Ã j Ã*, Ã k Ã*)/(σ|w|²)` turned by `2 arg w`;
//! its twist numerator is `N(Ã) = |w|² N + σ (a b' − a' b)`. The frame is
//! rotation-minimizing iff `N(Ã) ≡ 0`, i.e. `Im(w'/w) = −N/σ` (Han 2008, "Nonexistence of
//! rational rotation-minimizing frames on cubic curves", and Farouki, Sakkalis 2010, "Rational
//! rotation-minimizing frames on polynomial space curves of arbitrary degree", J. Symb.
//! Comput. 45: the ERF twist must be the logarithmic-derivative form
//! `(a b' − a' b)/(a² + b²)`).
//!
//! * [`erf_twist_numerator`]: the twist numerator `N`;
//! * [`rmf_rotation`]: the decision and the polynomial `w`: with `N/σ = N₁/D` in lowest
//!   terms, `Im(w'/w) = −N₁/D` holds for some `w` iff `D` is square-free and at every
//!   root `z` of `D` the number `2 N₁(z)/D'(z)` is `±i m` with a positive integer `m`
//!   (the multiplicity of `z` as a root of `w`). The residues are found exactly by the
//!   Rothstein–Trager resultant `R(s) = res_t(D, 4N₁² + s D'²)` (its roots must be
//!   `m²`), the factors by `G_m = gcd(D, N₁ − (i m/2) D')` over `Q(i)`, `w = Π G_m^m`;
//! * [`RationalRmf`]: the exact rational RMF `(f_1, f_2)` with its certificates;
//! * [`quintic_class1_residual`], [`rrmf_quintic_class1`]: the quintic condition
//!   `A_0 i A_2* + A_2 i A_0* = 2 A_1 i A_1*` on the Bernstein coefficients of
//!   `A = A_0 b_0² + A_1 b_1² + A_2 b_2²` (`b_1² = 2(1−t)t`; Farouki, Giannelli, Manni,
//!   Sestini 2009, "Quintic space curves with rational rotation-minimizing frames", CAGD
//!   26; Farouki 2010, "Quaternion and Hopf map characterizations for the existence of
//!   rational rotation-minimizing frames on quintic space curves", Adv. Comput. Math. 33;
//!   the factor 2 belongs to our Bernstein convention, checked with sympy), sufficient
//!   for an RRMF quintic with `|w|² ∝ σ` ("class I"), and a generator of such quintics
//!   from `A_0`, `A_1` and one real parameter (the condition is linear in `A_2`).

use super::hodograph::PhCurve;
use super::util::*;
use super::PhError;
use rcagd_algebra::complex::{self, Complex};
use rcagd_algebra::quaternion::{self, Quaternion};
use rcagd_algebra::resultant::resultant_poly;
use rcagd_algebra::roots::rational_roots;
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};

type V3<F> = [F; 3];
type PV3<F> = [Poly<F>; 3];

/// The ERF twist numerator `N = u v' − u' v − p q' + p' q` of `A = u + v i + p j + q k`:
/// the ERF turns about the tangent with `e_2'·e_3 = 2N/σ` (docs/math/rrmf.md, "The twist
/// of the Euler–Rodrigues frame").
pub fn erf_twist_numerator<F: Scalar>(curve: &PhCurve<F>) -> Poly<F> {
    let [u, v, p, q] = curve.preimage();
    twist_of(&u, &v, &p, &q)
}

fn twist_of<F: Scalar>(u: &Poly<F>, v: &Poly<F>, p: &Poly<F>, q: &Poly<F>) -> Poly<F> {
    let d = |x: &Poly<F>| x.derivative();
    &(&(u * &d(v)) - &(&d(u) * v)) - &(&(p * &d(q)) - &(&d(p) * q))
}

/// The residual vector `A_0 i A_2* + A_2 i A_0* − 2 A_1 i A_1*` of a PH quintic
/// (docs/math/rrmf.md, "RRMF quintics"); zero means an RRMF quintic with `|w|² ∝ σ`.
///
/// # Errors
/// [`PhError::DegreeMismatch`] unless the curve is a quintic (`m = 2`).
pub fn quintic_class1_residual<F: Scalar>(curve: &PhCurve<F>) -> Result<V3<F>, PhError> {
    let [a0, a1, a2] = curve.coefficients() else {
        return Err(PhError::DegreeMismatch(format!(
            "the quintic RRMF condition needs a quintic (3 preimage coefficients), got degree {}",
            curve.degree()
        )));
    };
    let r = aib(a0, a2) + aib(a2, a0) - aib(a1, a1).scale(&F::from_i64(2));
    Ok([r.x, r.y, r.z])
}

/// `true` if the quintic condition `A_0 i A_2* + A_2 i A_0* = 2 A_1 i A_1*` holds (exactly;
/// to `1e-12` relative for `f64`).
///
/// # Errors
/// As [`quintic_class1_residual`].
pub fn is_rrmf_quintic_class1<F: Scalar>(curve: &PhCurve<F>) -> Result<bool, PhError> {
    let r = quintic_class1_residual(curve)?;
    let scale = curve
        .coefficients()
        .iter()
        .map(|a| a.norm_sq().to_f64())
        .fold(0.0, f64::max);
    Ok(r.iter().all(|x| is_negligible(x, scale)))
}

/// The RRMF quintic with preimage coefficients `A_0`, `A_1` and
/// `A_2 = A_0 X`, `X = M_x/2 + x i − (M_z/2) j + (M_y/2) k`,
/// `M = A_0* (2 A_1 i A_1*) A_0 / |A_0|⁴`: the general solution of the (in `A_2` linear)
/// condition `A_0 i A_2* + A_2 i A_0* = 2 A_1 i A_1*`, with free real `x`
/// (docs/math/rrmf.md, "A generator").
///
/// # Errors
/// [`PhError::Degenerate`] if `A_0 = 0`; as [`PhCurve::new`].
pub fn rrmf_quintic_class1<F: Scalar>(
    a0: Quaternion<F>,
    a1: Quaternion<F>,
    x: F,
    start: V3<F>,
) -> Result<PhCurve<F>, PhError> {
    let n = a0.norm_sq();
    if n.is_zero() {
        return Err(PhError::Degenerate(
            "A_0 = 0: the quintic RRMF generator needs A_0 ≠ 0 (r'(0) ≠ 0)".into(),
        ));
    }
    let c = aib(&a1, &a1).scale(&F::from_i64(2));
    let m = (a0.conj() * c * a0.clone()).scale(&(F::one() / (n.clone() * n)));
    let half = F::from_ratio(1, 2);
    let xq = Quaternion::new(
        m.x.clone() * half.clone(),
        x,
        -(m.z.clone() * half.clone()),
        m.y.clone() * half,
    );
    let a2 = a0.clone() * xq;
    PhCurve::new(vec![a0, a1, a2], start)
}

/// The rotation polynomial `w = a + b i` (returned as `(a, b)`) that turns the ERF of the
/// curve into a rotation-minimizing frame: `N(A w) ≡ 0` (docs/math/rrmf.md, "Deciding
/// RRMF"). `w = 1` if the ERF is already rotation-minimizing (`N ≡ 0`).
///
/// For exact scalars the decision is exact. For `f64` the same conditions are tested
/// numerically on the roots of `σ` (Durand–Kerner): `2N(z)/σ'(z)` must be within `1e-6`
/// of `±i m` (integer `m`; `0` for a root that cancels against `N`), `w = Π (t − z)^m` over
/// the roots with `m > 0`, and `N(A w)` must vanish to `1e-9` relative — so rounded RRMF
/// data are accepted.
///
/// # Errors
/// [`PhError::NotRrmf`] naming the failed condition (repeated or real root of the reduced
/// denominator `D`, a residue that is not `±i m/2` with integer `m`); [`PhError::OutOfRange`]
/// for non-finite coefficients.
pub fn rmf_rotation<F: Scalar>(curve: &PhCurve<F>) -> Result<(Poly<F>, Poly<F>), PhError> {
    if !F::EXACT {
        return rotation_f64(curve);
    }
    let comps = curve.preimage();
    let mut qc: Vec<Poly<Rational>> = Vec::with_capacity(4);
    for c in &comps {
        qc.push(poly_rational(c).ok_or_else(|| {
            PhError::OutOfRange("a preimage coefficient is not a finite number".into())
        })?);
    }
    let (a, b) = rotation_exact(&qc[0], &qc[1], &qc[2], &qc[3])?;
    let back = |p: &Poly<Rational>| p.map(F::from_rational);
    Ok((back(&a), back(&b)))
}

/// The `f64` decision (see [`rmf_rotation`]).
fn rotation_f64<F: Scalar>(curve: &PhCurve<F>) -> Result<(Poly<F>, Poly<F>), PhError> {
    type C = Complex<f64>;
    let comps = curve.preimage().map(|p| poly_f64(&p));
    let [u, v, p, q] = &comps;
    let n = twist_of(u, v, p, q);
    let sigma = &(&(u * u) + &(v * v)) + &(&(p * p) + &(q * q));
    let scale = poly_scale(&sigma).max(f64::MIN_POSITIVE);
    let back = |x: &Poly<f64>| -> Result<Poly<F>, PhError> {
        let c = x
            .coeffs()
            .iter()
            .map(|c| {
                Rational::try_from(*c)
                    .map(|r| F::from_rational(&r))
                    .map_err(|_| PhError::NonFinite {
                        what: format!("the f64 preimage coefficient {c}"),
                    })
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Poly::new(c))
    };
    if n.coeffs().iter().all(|c| c.abs() <= 1e-12 * scale) {
        return back(&Poly::constant(1.0)).map(|a| (a, Poly::zero()));
    }
    let roots = rcagd_algebra::roots::complex_roots_f64(&sigma)
        .ok_or_else(|| not_rrmf("the roots of σ could not be found in f64".into()))?;
    let ds = sigma.derivative();
    let ev = |p: &Poly<f64>, z: &C| {
        p.coeffs()
            .iter()
            .rev()
            .fold(Complex::new(0.0, 0.0), |acc, c| {
                acc * z.clone() + Complex::new(*c, 0.0)
            })
    };
    let mut w: Poly<C> = Poly::constant(Complex::new(1.0, 0.0));
    for z in &roots {
        let d = ev(&ds, z);
        if d.norm_sq() == 0.0 {
            return Err(not_rrmf("σ has a repeated root (f64)".into()));
        }
        let rho = (ev(&n, z) * Complex::new(2.0, 0.0)) / d;
        let m = rho.im.round();
        if (rho.clone() - Complex::new(0.0, m)).norm_sq().sqrt() > 1e-6 * (1.0 + m.abs()) {
            return Err(not_rrmf(format!(
                "a residue 2N(z)/σ'(z) = {:.6} + {:.6}i of the ERF twist is not ±i m with integer m (f64)",
                rho.re, rho.im
            )));
        }
        if m > 0.0 {
            let lin = Poly::new(vec![-z.clone(), Complex::new(1.0, 0.0)]);
            w = &w * &lin.pow(m as u32);
        }
    }
    let (a, b) = complex::re_im_polys(&w);
    let check = &(&(&(&a * &a) + &(&b * &b)) * &n)
        + &(&sigma * &(&(&a * &b.derivative()) - &(&a.derivative() * &b)));
    let ww = poly_scale(&(&(&a * &a) + &(&b * &b))).max(1.0);
    if check
        .coeffs()
        .iter()
        .any(|c| c.abs() > 1e-9 * scale * ww * poly_scale(&n).max(1.0))
    {
        return Err(not_rrmf(
            "the candidate rotation polynomial w does not annul the twist N(A w) (f64)".into(),
        ));
    }
    Ok((back(&a)?, back(&b)?))
}

fn not_rrmf(msg: String) -> PhError {
    PhError::NotRrmf(msg)
}

fn rotation_exact(
    u: &Poly<Rational>,
    v: &Poly<Rational>,
    p: &Poly<Rational>,
    q: &Poly<Rational>,
) -> Result<(Poly<Rational>, Poly<Rational>), PhError> {
    type Q = Rational;
    let n = twist_of(u, v, p, q);
    if n.is_zero() {
        return Ok((Poly::constant(Q::from(1)), Poly::zero()));
    }
    let sigma = &(&(u * u) + &(v * v)) + &(&(p * p) + &(q * q));
    let g = n.gcd(&sigma);
    let n1 = n.div_exact(&g).map_err(PhError::Algebra)?;
    let d = sigma.div_exact(&g).map_err(PhError::Algebra)?;
    let (Some(dn), Some(dd)) = (n1.degree(), d.degree()) else {
        return Err(not_rrmf("the ERF twist 2N/σ has no denominator".into()));
    };
    if dn >= dd {
        return Err(not_rrmf(format!(
            "the ERF twist N/σ = N₁/D (lowest terms) has deg N₁ = {dn} ≥ deg D = {dd}, \
             but Im(w'/w) vanishes at infinity"
        )));
    }
    let dp = d.derivative();
    if d.gcd(&dp).degree() != Some(0) {
        return Err(not_rrmf(
            "the reduced denominator D of the ERF twist N/σ has a repeated root, \
             but Im(w'/w) has only simple poles"
                .into(),
        ));
    }
    // Rothstein–Trager: R(s) = res_t(D, 4N₁² + s D'²), roots s_z = −4N₁(z)²/D'(z)².
    let n1sq = (&n1 * &n1).scale(&Q::from(4));
    let dp2 = &dp * &dp;
    let len = n1sq.coeffs().len().max(dp2.coeffs().len());
    let outer_p: Poly<Poly<Q>> =
        Poly::new(d.coeffs().iter().cloned().map(Poly::constant).collect());
    let outer_q: Poly<Poly<Q>> = Poly::new(
        (0..len)
            .map(|k| Poly::new(vec![n1sq.coeff(k), dp2.coeff(k)]))
            .collect(),
    );
    let mut rest = resultant_poly(&outer_p, &outer_q);
    let mut ms: Vec<u64> = Vec::new();
    for r in rational_roots(&rest.clone()) {
        let mi = rcagd_algebra::rational::rational_sqrt(&r)
            .map(|m| (Scalar::to_f64(&m).round() as i64, m))
            .filter(|(mi, m)| *mi > 0 && *m == Q::from(*mi))
            .map(|(mi, _)| mi as u64)
            .ok_or_else(|| {
                not_rrmf(format!(
                    "a residue of the ERF twist is i·√({})/2, not ±i m/2 with a positive integer m",
                    rcagd_algebra::rational::format_rational(&r)
                ))
            })?;
        let lin = Poly::new(vec![-r.clone(), Q::from(1)]);
        while let Ok((quo, rem)) = rest.div_rem(&lin) {
            if !rem.is_zero() {
                break;
            }
            rest = quo;
        }
        ms.push(mi);
    }
    if rest.degree() != Some(0) {
        return Err(not_rrmf(
            "a residue of the ERF twist N/σ is irrational: the rotation angle of the ERF \
             into the RMF is not 2·arg of a polynomial"
                .into(),
        ));
    }
    // w = Π_m gcd(D, N₁ − (i m/2) D')^m over Q(i)
    let cpoly = |p: &Poly<Q>| p.map(|c| Complex::new(c.clone(), Q::from(0)));
    let dc = cpoly(&d);
    let mut w: Poly<Complex<Q>> = Poly::constant(Complex::new(Q::from(1), Q::from(0)));
    let mut covered = 0usize;
    for m in ms {
        let c = Complex::new(Q::from(0), Q::from_ratio(m as i64, 2));
        let h = &cpoly(&n1) - &cpoly(&dp).scale(&c);
        let gm = dc.gcd(&h);
        covered += gm.degree().unwrap_or(0);
        w = &w * &gm.pow(m as u32);
    }
    if 2 * covered != dd {
        return Err(not_rrmf(format!(
            "the roots of D found with integer residues account for degree {} of deg D = {dd}",
            2 * covered
        )));
    }
    let (a, b) = complex::re_im_polys(&w);
    // the defining identity, checked exactly: N(A w) = |w|² N + σ (a b' − a' b) ≡ 0
    let check = &(&(&(&a * &a) + &(&b * &b)) * &n)
        + &(&sigma * &(&(&a * &b.derivative()) - &(&a.derivative() * &b)));
    if !check.is_zero() {
        return Err(not_rrmf(
            "the candidate rotation polynomial w does not annul the twist N(A w)".into(),
        ));
    }
    Ok((a, b))
}

/// An exact rational rotation-minimizing frame on a PH curve: with `Ã = A w`,
/// `f_1 = F_1/d`, `f_2 = F_2/d`, `F_1 = Ã j Ã*/g`, `F_2 = Ã k Ã*/g`, `d = σ|w|²/g` (`g` the
/// common polynomial factor, cancelled for exact scalars; docs/math/rrmf.md, "The frame").
/// The tangent is `t = r'/σ`; `(t, f_1, f_2)` is right-handed.
#[derive(Debug, Clone, PartialEq)]
pub struct RationalRmf<F> {
    /// The curve.
    pub curve: PhCurve<F>,
    /// The rotation polynomial `w = a + b i` as `(a, b)`.
    pub rotation: (Poly<F>, Poly<F>),
    /// Numerator `F_1` of the first normal-plane vector.
    pub f1: PV3<F>,
    /// Numerator `F_2` of the second normal-plane vector.
    pub f2: PV3<F>,
    /// The common denominator `d` (positive at `t = 1/2`).
    pub den: Poly<F>,
}

impl<F: Scalar> RationalRmf<F> {
    /// The RMF of an RRMF curve (decided and found by [`rmf_rotation`]).
    ///
    /// # Errors
    /// As [`rmf_rotation`].
    pub fn new(curve: &PhCurve<F>) -> Result<Self, PhError> {
        let w = rmf_rotation(curve)?;
        Ok(Self::from_rotation(curve, w))
    }

    /// The frame `(Ã j Ã*, Ã k Ã*)/(σ|w|²)` for a given `w = a + b i` (rotation-minimizing
    /// iff `N(A w) ≡ 0`, which [`Self::certify`] decides).
    pub fn from_rotation(curve: &PhCurve<F>, rotation: (Poly<F>, Poly<F>)) -> Self {
        let (mut f1, mut f2, mut den) = raw_frame(curve, &rotation);
        if F::EXACT {
            let mut g = den.clone();
            for c in f1.iter().chain(f2.iter()) {
                g = g.gcd(c);
            }
            if g.degree().is_some_and(|k| k > 0) {
                let div = |p: &Poly<F>| p.div_exact(&g).unwrap_or_else(|_| p.clone());
                den = div(&den);
                f1 = [div(&f1[0]), div(&f1[1]), div(&f1[2])];
                f2 = [div(&f2[0]), div(&f2[1]), div(&f2[2])];
            }
        }
        let half = F::from_ratio(1, 2);
        let lc = den.eval(&half);
        let s = if lc < F::zero() { -F::one() } else { F::one() };
        let sc = |p: &PV3<F>| [p[0].scale(&s), p[1].scale(&s), p[2].scale(&s)];
        RationalRmf {
            curve: curve.clone(),
            rotation,
            f1: sc(&f1),
            f2: sc(&f2),
            den: den.scale(&s),
        }
    }

    /// The frame of `curve` along the exact decisions of `exact`, the RMF of the same curve
    /// over Q (for a float build, `curve` is the construction in `F` from the same input):
    /// the rotation polynomial `w` ([`rmf_rotation`]: Rothstein–Trager residues and gcds
    /// over Q(i)) and the common factor `g` of `σ|w|²`, `Ã j Ã*` and `Ã k Ã*` (a gcd over
    /// Q) are exact-only decisions, taken on `exact` and converted to `F`; the frame
    /// `(Ã j Ã*, Ã k Ã*, σ|w|²)` is computed in `F` and divided by `g` (the quotient of the
    /// long division: exact for exact `F`, where the remainder is 0). `g` carries the sign
    /// that makes `d(1/2) > 0` over Q, so no sign is decided in `F` either
    /// (docs/math/rrmf.md, "The frame").
    ///
    /// # Errors
    /// [`PhError::Degenerate`] if `exact`'s denominator does not divide its uncancelled
    /// `σ|w|²` (it was not built from its curve by [`Self::new`] or [`Self::from_rotation`]);
    /// [`PhError::Algebra`] from the division in `F`.
    pub fn along(curve: &PhCurve<F>, exact: &RationalRmf<Rational>) -> Result<Self, PhError> {
        let (_, _, raw_den) = raw_frame(&exact.curve, &exact.rotation);
        let g = raw_den.div_exact(&exact.den).map_err(|_| {
            PhError::Degenerate(
                "the exact frame's denominator does not divide σ|w|² of its curve".into(),
            )
        })?;
        let conv = |p: &Poly<Rational>| p.map(F::from_rational);
        let rotation = (conv(&exact.rotation.0), conv(&exact.rotation.1));
        let (f1, f2, den) = raw_frame(curve, &rotation);
        let gf = conv(&g);
        let div = |p: &Poly<F>| -> Result<Poly<F>, PhError> {
            p.div_rem(&gf).map(|(q, _)| q).map_err(PhError::Algebra)
        };
        Ok(RationalRmf {
            curve: curve.clone(),
            rotation,
            f1: [div(&f1[0])?, div(&f1[1])?, div(&f1[2])?],
            f2: [div(&f2[0])?, div(&f2[1])?, div(&f2[2])?],
            den: div(&den)?,
        })
    }

    /// `(t, f_1, f_2)` at `t` (unit vectors), `None` where `σ` or `d` vanishes.
    ///
    /// For `f64` the normal-plane vectors are evaluated as `Ã j Ã*/|Ã|²`, `Ã k Ã*/|Ã|²`
    /// from `Ã(t) = A(t) w(t)` (`A(t)` by de Casteljau on the Bernstein coefficients), which
    /// is `F_k(t)/d(t)` (`|Ã|² = σ|w|²`; [`Self::from_rotation`]) but does not evaluate the
    /// power forms of `F_k` and `d`, whose coefficients may be much larger than the values
    /// (Horner's rounding grows with `Σ|coefficients|`); where `|Ã(t)|²` is negligible, and
    /// for exact scalars, `F_k(t)/d(t)`.
    pub fn eval(&self, t: &F) -> Option<[V3<F>; 3]> {
        let s = self.curve.speed().eval(t);
        let d = self.den.eval(t);
        if s.is_zero() || d.is_zero() {
            return None;
        }
        let h = peval(&self.curve.hodograph(), t);
        if !F::EXACT {
            if let Some([f1, f2]) = self.normal_vectors_at(t) {
                return Some([scale3(&h, &(F::one() / s)), f1, f2]);
            }
        }
        Some([
            scale3(&h, &(F::one() / s)),
            scale3(&peval(&self.f1, t), &(F::one() / d.clone())),
            scale3(&peval(&self.f2, t), &(F::one() / d)),
        ])
    }

    /// `Ã j Ã*/|Ã|²` and `Ã k Ã*/|Ã|²` at `t` (see [`Self::eval`]); `None` where `|Ã(t)|²`
    /// is negligible against `|A(t)|²|w(t)|²` computed from the sizes of their terms.
    fn normal_vectors_at(&self, t: &F) -> Option<[V3<F>; 2]> {
        let mut q: Vec<Quaternion<F>> = self.curve.coefficients().to_vec();
        let u = F::one() - t.clone();
        for r in 1..q.len() {
            for i in 0..q.len() - r {
                q[i] = q[i].scale(&u) + q[i + 1].scale(t);
            }
        }
        let a = q.first()?.clone();
        let w = Quaternion::new(
            self.rotation.0.eval(t),
            self.rotation.1.eval(t),
            F::zero(),
            F::zero(),
        );
        let at = a * w;
        let n = at.norm_sq();
        let size =
            at.w.to_f64().abs() + at.x.to_f64().abs() + at.y.to_f64().abs() + at.z.to_f64().abs();
        let nf = n.to_f64();
        if nf.is_nan() || nf <= 1e-12 * size * size {
            return None;
        }
        let v = |e: Quaternion<F>| {
            let p = at.clone() * e * at.conj();
            [p.x / n.clone(), p.y / n.clone(), p.z / n.clone()]
        };
        Some([v(Quaternion::j()), v(Quaternion::k())])
    }

    /// `cos θ`, `sin θ` of the angle from the ERF `(e_2, e_3)` to `(f_1, f_2)` at `t`:
    /// `((a² − b²), 2ab)/(a² + b²)`.
    pub fn angle_from_erf(&self, t: &F) -> Option<(F, F)> {
        let a = self.rotation.0.eval(t);
        let b = self.rotation.1.eval(t);
        let n = a.clone() * a.clone() + b.clone() * b.clone();
        if n.is_zero() {
            return None;
        }
        Some((
            (a.clone() * a.clone() - b.clone() * b.clone()) / n.clone(),
            F::from_i64(2) * a * b / n,
        ))
    }

    /// The same frame in `f64`.
    pub fn to_f64(&self) -> RationalRmf<f64> {
        let m = |p: &PV3<F>| [poly_f64(&p[0]), poly_f64(&p[1]), poly_f64(&p[2])];
        RationalRmf {
            curve: self.curve.to_f64(),
            rotation: (poly_f64(&self.rotation.0), poly_f64(&self.rotation.1)),
            f1: m(&self.f1),
            f2: m(&self.f2),
            den: poly_f64(&self.den),
        }
    }

    /// Certificates (docs/math/rrmf.md, "The frame"), all polynomial identities after
    /// clearing denominators: `F_k·r' ≡ 0`, `F_1·F_2 ≡ 0`, `|F_1|² ≡ |F_2|² ≡ d²`,
    /// `(F_1 × F_2)·σ ≡ d²·r'` (right-handed with the tangent), and rotation-minimizing:
    /// `F_1'·F_2 ≡ 0` (`f_1'·f_2 = F_1'·F_2/d²` as `F_1·F_2 ≡ 0`), plus the curve's own
    /// certificates.
    pub fn certify(&self) -> Vec<Certificate> {
        let h = self.curve.hodograph();
        let sigma = self.curve.speed();
        let d2 = &self.den * &self.den;
        let mut certs = self.curve.certify();
        certs.push(zero_dot_cert(
            "f₁·r' ≡ 0 (RMF normal-plane vector, docs/math/rrmf.md)",
            &self.f1,
            &h,
        ));
        certs.push(zero_dot_cert(
            "f₂·r' ≡ 0 (RMF normal-plane vector, docs/math/rrmf.md)",
            &self.f2,
            &h,
        ));
        certs.push(zero_dot_cert(
            "f₁·f₂ ≡ 0 (RMF orthogonal, docs/math/rrmf.md)",
            &self.f1,
            &self.f2,
        ));
        certs.push(identity_cert(
            "|F₁|² ≡ d² (|f₁| = 1, docs/math/rrmf.md)",
            &pdot(&self.f1, &self.f1),
            &d2,
        ));
        certs.push(identity_cert(
            "|F₂|² ≡ d² (|f₂| = 1, docs/math/rrmf.md)",
            &pdot(&self.f2, &self.f2),
            &d2,
        ));
        let c = pcross(&self.f1, &self.f2);
        let ps = |p: &PV3<F>| p.iter().map(poly_scale).fold(0.0, f64::max);
        let len = |p: &Poly<F>| p.coeffs().len() as f64;
        let n = len(&self.den).max(len(&self.f1[0])) + len(&sigma);
        let cross_scale = n * n * ps(&self.f1) * ps(&self.f2) * poly_scale(&sigma);
        for k in 0..3 {
            let lhs = &c[k] * &sigma;
            let rhs = &h[k] * &d2;
            let diff = &lhs - &rhs;
            certs.push(Certificate::decide(
                format!(
                    "σ·[F₁ × F₂]_{k} ≡ d²·[r']_{k} (right-handed (t, f₁, f₂), docs/math/rrmf.md)"
                ),
                poly_negligible(
                    &diff,
                    cross_scale.max(poly_scale(&lhs)).max(poly_scale(&rhs)),
                ),
                F::EXACT,
                || {
                    format!(
                        "residual polynomial {}",
                        rcagd_algebra::format_poly(&diff, "t")
                    )
                },
            ));
        }
        certs.push(zero_dot_cert(
            "F₁'·F₂ ≡ 0 (rotation-minimizing: no turn about the tangent, ω·t = f₁'·f₂ = 0; Han 2008, docs/math/rrmf.md)",
            &pderiv(&self.f1),
            &self.f2,
        ));
        certs
    }
}

/// The uncancelled frame `(Ã j Ã*, Ã k Ã*, σ|w|²)` of `Ã = A w`, `w = a + b i`.
fn raw_frame<F: Scalar>(
    curve: &PhCurve<F>,
    rotation: &(Poly<F>, Poly<F>),
) -> (PV3<F>, PV3<F>, Poly<F>) {
    let (a, b) = rotation;
    let wq: Poly<Quaternion<F>> = Poly::new(
        (0..a.coeffs().len().max(b.coeffs().len()))
            .map(|k| Quaternion::new(a.coeff(k), b.coeff(k), F::zero(), F::zero()))
            .collect(),
    );
    let at = &curve.preimage_poly() * &wq;
    let f1 = quaternion::vector_polys(&quaternion::sandwich(&at, &Quaternion::j()));
    let f2 = quaternion::vector_polys(&quaternion::sandwich(&at, &Quaternion::k()));
    let den = &curve.speed() * &(&(a * a) + &(b * b));
    (f1, f2, den)
}

/// A certificate for `a·b ≡ 0`; for `f64` relative to the size of the products
/// (`Σ_k |a_k||b_k|` over the coefficients), not to the residual itself.
fn zero_dot_cert<F: Scalar>(property: &str, a: &PV3<F>, b: &PV3<F>) -> Certificate {
    let lhs = pdot(a, b);
    let scale: f64 = a
        .iter()
        .zip(b)
        .map(|(x, y)| {
            let n = x.coeffs().len().max(y.coeffs().len()) as f64;
            n * poly_scale(x) * poly_scale(y)
        })
        .sum();
    Certificate::decide(property, poly_negligible(&lhs, scale), F::EXACT, || {
        format!(
            "residual polynomial {}",
            rcagd_algebra::format_poly(&lhs, "t")
        )
    })
}

impl<F: Scalar> crate::Certified for RationalRmf<F> {
    fn certify(&self) -> Vec<Certificate> {
        RationalRmf::certify(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn qt(a: [i64; 4]) -> Quaternion<Rational> {
        Quaternion::new(
            Rational::from(a[0]),
            Rational::from(a[1]),
            Rational::from(a[2]),
            Rational::from(a[3]),
        )
    }

    fn curve() -> PhCurve<Rational> {
        let z = Rational::from(0);
        PhCurve::new(
            vec![qt([1, 2, 0, -1]), qt([0, 1, 1, 3]), qt([2, -1, 1, 0])],
            [z.clone(), z.clone(), z],
        )
        .unwrap()
    }

    /// The ERF turns about the tangent with `e_2'·e_3 = 2N/σ`: `E_2'·E_3 ≡ 2Nσ` for the
    /// numerators `E_k = σ e_k` (docs/math/rrmf.md, "The twist of the Euler–Rodrigues frame").
    #[test]
    fn erf_twist_is_two_n_over_sigma() {
        let c = curve();
        let erf = c.euler_rodrigues_frame();
        let lhs = pdot(&pderiv(&erf.numerators[1]), &erf.numerators[2]);
        let rhs = (&erf_twist_numerator(&c) * &c.speed()).scale(&Rational::from(2));
        assert_eq!(lhs, rhs);
    }

    /// `N(A w) = |w|² N(A) + σ (a b' − a' b)` for a sample `w` (docs/math/rrmf.md,
    /// "Rotating the frame by a complex polynomial").
    #[test]
    fn twist_of_rotated_preimage() {
        let c = curve();
        let a = Poly::from_ints(&[1, -2, 3]);
        let b = Poly::from_ints(&[2, 1]);
        let rot = RationalRmf::from_rotation(&c, (a.clone(), b.clone()));
        let wq: Poly<Quaternion<Rational>> = Poly::new(
            (0..3)
                .map(|k| {
                    Quaternion::new(a.coeff(k), b.coeff(k), Rational::from(0), Rational::from(0))
                })
                .collect(),
        );
        let [u, v, p, q] = quaternion::component_polys(&(&c.preimage_poly() * &wq));
        let lhs = twist_of(&u, &v, &p, &q);
        let rhs = &(&(&(&a * &a) + &(&b * &b)) * &erf_twist_numerator(&c))
            + &(&c.speed() * &(&(&a * &b.derivative()) - &(&a.derivative() * &b)));
        assert_eq!(lhs, rhs);
        // not rotation-minimizing: the RMF certificate fails, the others hold
        let certs = rot.certify();
        assert!(certs
            .iter()
            .any(|c| !c.holds && c.property.contains("rotation-minimizing")));
        assert!(certs
            .iter()
            .filter(|c| !c.property.contains("rotation-minimizing"))
            .all(|c| c.holds));
    }
}
