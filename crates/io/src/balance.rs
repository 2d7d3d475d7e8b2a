//! Balancing the weights of exported rational Bézier pieces by exact Möbius
//! reparametrizations.
//!
//! # Why
//!
//! OpenCascade's IGES reader warns "Difference between weights is too big" (message
//! `IGES_1374`) when, for one entity 126 or 128, `max wᵢ − min wᵢ > 1000`: an
//! **absolute** difference of the written weights (`checkBSplineCurve` /
//! `checkBSplineSurface` in `IGESToBRep_BasicCurve.cxx` / `IGESToBRep_BasicSurface.cxx`).
//! Weights spread over several orders of magnitude also cost precision in every
//! floating-point evaluation of the rounded NURBS.
//!
//! # How
//!
//! For a rational Bézier piece `P(t) = Σ Bᵢⁿ(t) Pᵢ` (homogeneous `Pᵢ = (wᵢ, wᵢxᵢ)`) the
//! end-point-preserving Möbius map
//!
//! ```text
//! t = φ_ρ(s) = ρ s / ((1 − s) + ρ s),   ρ > 0,
//! ```
//!
//! gives `Bᵢⁿ(φ_ρ(s)) = ρⁱ Bᵢⁿ(s) / ((1 − s) + ρ s)ⁿ`, so `P(φ_ρ(s))` is the projective
//! point of `Σ Bᵢⁿ(s) ρⁱ Pᵢ`: multiplying the `i`-th homogeneous control point by `ρⁱ`
//! is an exact reparametrization (same point set, same end points, same Euclidean
//! control points; the weights become `ρⁱ wᵢ`). For a tensor-product patch the maps act
//! independently in `u` (`ρⁱ`) and `v` (`σʲ`), and a common factor `c` of all
//! homogeneous points changes nothing.
//!
//! [`balance_patch`] picks `ρ = 2ᵃ`, `σ = 2ᵇ` (integers `a`, `b`; dyadic factors keep
//! the rationals short and their `f64` images exact up to the one rounding already
//! there) minimizing `log₂(max w / min w)` over the net, and then `c = 2ᵏ` centring the
//! weights about 1 (`max w · min w ≈ 1`). It acts only where needed: the Möbius
//! balancing when `max w / min w > 16` ([`RATIO_LIMIT`]), the scaling when a weight
//! lies outside `[2⁻⁸, 2⁸]` ([`SCALE_LIMIT`]); other pieces are returned unchanged
//! (circles, tori, most constructions). [`balance_curve`] does the same for a curve.
//!
//! The exported NURBS is built from the balanced pieces
//! ([`crate::step::exchange_object`]), so STEP, IGES and the exact sidecar carry the
//! same control points and weights.

use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::{BezierCurve, BezierPatch};

/// Pieces whose weights vary by at most this factor are not reparametrized.
pub const RATIO_LIMIT: f64 = 16.0;

/// Pieces whose weights all lie in `[1/SCALE_LIMIT, SCALE_LIMIT]` are not rescaled.
pub const SCALE_LIMIT: f64 = 256.0;

/// The exponents of a balancing: the `i`-th (`u`), `j`-th (`v`) homogeneous control
/// point is multiplied by `2^(k + a·i + b·j)`. The balanced piece at `(s, t)` is the
/// original at `(φ_{2ᵃ}(s), φ_{2ᵇ}(t))` (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Balance {
    /// `log₂ ρ` of the Möbius map in `u` (the curve parameter for curves).
    pub a: i64,
    /// `log₂ σ` of the Möbius map in `v` (0 for curves).
    pub b: i64,
    /// `log₂ c` of the common factor.
    pub k: i64,
}

impl Balance {
    /// `true` for the identity.
    pub fn is_identity(&self) -> bool {
        *self == Balance::default()
    }
}

/// `log₂ |q|`, approximately (to well under 1 for every rational ≠ 0; `−∞` for 0).
fn log2_abs(q: &Rational) -> f64 {
    let zero = Rational::from(0);
    if *q == zero {
        return f64::NEG_INFINITY;
    }
    // bring |q| into the normal f64 range by exact powers of 2
    let step = pow2(512);
    let mut x = Scalar::abs(q);
    let mut e = 0.0;
    while !Scalar::to_f64(&x).is_finite() {
        x /= step.clone();
        e += 512.0;
    }
    while Scalar::to_f64(&x) < 1e-250 {
        x *= step.clone();
        e -= 512.0;
    }
    e + Scalar::to_f64(&x).log2()
}

/// `2^e` as a rational (a shift, not `|e|` products).
fn pow2(e: i64) -> Rational {
    // |e| stays far below isize::MAX (exponents of weights and MAX_EXPONENT)
    rcagd_algebra::interval::pow2(e as isize)
}

/// The largest |exponent| searched (a weight range of `2¹⁰²⁴` needs no more).
const MAX_EXPONENT: i64 = 1100;

/// The balancing of weights `w[i][j]` (all of one sign, non-zero) with `log₂ |w|` given
/// (module docs); `i` runs over `0..=m`, `j` over `0..=n`.
fn choose(logs: &[Vec<f64>], m: usize, n: usize) -> Balance {
    let range = |a: f64, b: f64| {
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for (i, row) in logs.iter().enumerate() {
            for (j, l) in row.iter().enumerate() {
                let x = l + a * i as f64 + b * j as f64;
                lo = lo.min(x);
                hi = hi.max(x);
            }
        }
        (lo, hi)
    };
    let (lo0, hi0) = range(0.0, 0.0);
    let spread = hi0 - lo0;
    let (mut a, mut b) = (0i64, 0i64);
    let (mut lo, mut hi) = (lo0, hi0);
    if spread > RATIO_LIMIT.log2() {
        // cost(a, b) ≥ |a|·m − spread: beyond 2·spread/m nothing beats a = 0
        let bound = |deg: usize| {
            if deg == 0 {
                0
            } else {
                ((2.0 * spread / deg as f64).ceil() as i64).clamp(0, MAX_EXPONENT)
            }
        };
        let (ba, bb) = (bound(m), bound(n));
        let mut best = (spread, 0i64);
        for ca in -ba..=ba {
            for cb in -bb..=bb {
                let (l, h) = range(ca as f64, cb as f64);
                let cost = (h - l, ca.abs() + cb.abs());
                // strictly better by more than rounding noise, or as good and smaller
                if cost.0 < best.0 - 1e-9 || (cost.0 <= best.0 + 1e-9 && cost.1 < best.1) {
                    best = cost;
                    (a, b) = (ca, cb);
                    (lo, hi) = (l, h);
                }
            }
        }
    }
    let limit = SCALE_LIMIT.log2();
    let k = if hi > limit || lo < -limit {
        (-(hi + lo) / 2.0).round() as i64
    } else {
        0
    };
    Balance {
        a,
        b,
        k: k.clamp(-MAX_EXPONENT, MAX_EXPONENT),
    }
}

/// The weights' `log₂ |w|`, or `None` if a weight is 0.
fn weight_logs(weights: &[Rational]) -> Option<Vec<f64>> {
    weights
        .iter()
        .map(|w| (*w != Rational::from(0)).then(|| log2_abs(w)))
        .collect()
}

/// The balancing [`balance_patch`] applies (identity for a weight 0 or a degree-0
/// direction).
pub fn patch_balance(p: &BezierPatch<Rational>) -> Balance {
    let (m, n) = p.degree();
    let Some(logs) = weight_logs(&p.weights()) else {
        return Balance::default();
    };
    let rows: Vec<Vec<f64>> = logs.chunks(n + 1).map(<[f64]>::to_vec).collect();
    choose(&rows, m, n)
}

/// The balancing [`balance_curve`] applies.
pub fn curve_balance(c: &BezierCurve<Rational>) -> Balance {
    let Some(logs) = weight_logs(&c.weights()) else {
        return Balance::default();
    };
    let rows: Vec<Vec<f64>> = logs.iter().map(|l| vec![*l]).collect();
    choose(&rows, c.degree(), 0)
}

/// The patch with the `(i, j)`-th homogeneous control point multiplied by
/// `2^(k + a·i + b·j)`: the same patch reparametrized by `(φ_{2ᵃ}, φ_{2ᵇ})`, scaled.
pub fn apply_patch(p: &BezierPatch<Rational>, bal: Balance) -> BezierPatch<Rational> {
    if bal.is_identity() {
        return p.clone();
    }
    let (m, n) = p.degree();
    let s = p.dim() + 1;
    let fu: Vec<Rational> = (0..=m as i64).map(|i| pow2(bal.k + bal.a * i)).collect();
    let fv: Vec<Rational> = (0..=n as i64).map(|j| pow2(bal.b * j)).collect();
    let mut coords = p.coords().to_vec();
    for (idx, h) in coords.chunks_mut(s).enumerate() {
        let f = fu[idx / (n + 1)].clone() * fv[idx % (n + 1)].clone();
        for x in h.iter_mut() {
            *x *= f.clone();
        }
    }
    // same shape as the input: cannot fail
    BezierPatch::from_flat(p.dim(), m, n, coords).unwrap_or_else(|_| p.clone())
}

/// The curve with the `i`-th homogeneous control point multiplied by `2^(k + a·i)`.
pub fn apply_curve(c: &BezierCurve<Rational>, bal: Balance) -> BezierCurve<Rational> {
    if bal.is_identity() {
        return c.clone();
    }
    let s = c.dim() + 1;
    let mut coords = c.coords().to_vec();
    for (i, h) in coords.chunks_mut(s).enumerate() {
        let f = pow2(bal.k + bal.a * i as i64);
        for x in h.iter_mut() {
            *x *= f.clone();
        }
    }
    BezierCurve::from_flat(c.dim(), coords).unwrap_or_else(|_| c.clone())
}

/// The patch with balanced weights (module docs); unchanged if its weights vary by at
/// most [`RATIO_LIMIT`] and lie in `[1/SCALE_LIMIT, SCALE_LIMIT]`, or if a weight is 0.
pub fn balance_patch(p: &BezierPatch<Rational>) -> BezierPatch<Rational> {
    apply_patch(p, patch_balance(p))
}

/// The curve with balanced weights (as [`balance_patch`]).
pub fn balance_curve(c: &BezierCurve<Rational>) -> BezierCurve<Rational> {
    apply_curve(c, curve_balance(c))
}

/// `max |w| / min |w|` of the weights as `f64` (`∞` for a weight 0).
pub fn weight_ratio(weights: &[Rational]) -> f64 {
    let mut lo = f64::INFINITY;
    let mut hi = 0.0f64;
    for w in weights {
        let f = Scalar::to_f64(w).abs();
        lo = lo.min(f);
        hi = hi.max(f);
    }
    if lo == 0.0 {
        f64::INFINITY
    } else {
        hi / lo
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    /// `φ_ρ` as `(as + b)/(cs + d)`: `a = ρ, b = 0, c = ρ − 1, d = 1`.
    fn mobius(rho: &Rational) -> [Rational; 4] {
        [rho.clone(), q(0, 1), rho.clone() - q(1, 1), q(1, 1)]
    }

    fn skewed_patch() -> BezierPatch<Rational> {
        // weights 1 … 2¹⁴·3 growing along u and v
        let net = (0..3)
            .map(|i| {
                (0..4)
                    .map(|j| {
                        let w = pow2(5 * i + 3 * j) * q(1 + (i + j) % 3, 1);
                        vec![
                            w.clone(),
                            w.clone() * q(i, 2),
                            w.clone() * q(j, 3),
                            w * q(i * j - 1, 5),
                        ]
                    })
                    .collect()
            })
            .collect();
        BezierPatch::from_homogeneous(net).expect("valid")
    }

    #[test]
    fn balancing_is_an_exact_mobius_reparametrization() {
        let p = skewed_patch();
        let bal = patch_balance(&p);
        assert!(!bal.is_identity());
        let b = apply_patch(&p, bal);
        assert!(weight_ratio(&b.weights()) <= 16.0, "{bal:?}");
        let (rho, sigma) = (pow2(bal.a), pow2(bal.b));
        let [a, bb, c, d] = mobius(&rho);
        let re = p
            .reparametrize_mobius_u(&a, &bb, &c, &d)
            .expect("invertible");
        let [a, bb, c, d] = mobius(&sigma);
        let re = re
            .reparametrize_mobius_v(&a, &bb, &c, &d)
            .expect("invertible");
        for (i, j) in [(0, 0), (1, 3), (2, 5), (7, 7), (3, 1)] {
            let (s, t) = (q(i, 7), q(j, 7));
            // the balanced patch is the original at the Möbius-mapped parameters
            let phi = |r: &Rational, s: &Rational| {
                r.clone() * s.clone() / (q(1, 1) - s.clone() + r.clone() * s.clone())
            };
            let orig = p.eval(&phi(&rho, &s), &phi(&sigma, &t)).expect("finite");
            assert_eq!(b.eval(&s, &t).expect("finite"), orig);
            assert_eq!(re.eval(&s, &t).expect("finite"), orig);
        }
        // the Euclidean control points do not move
        for i in 0..3 {
            for j in 0..4 {
                let (x, y) = (p.control_point(i, j), b.control_point(i, j));
                let ex: Vec<Rational> = x[1..].iter().map(|v| v.clone() / x[0].clone()).collect();
                let ey: Vec<Rational> = y[1..].iter().map(|v| v.clone() / y[0].clone()).collect();
                assert_eq!(ex, ey);
            }
        }
    }

    #[test]
    fn well_balanced_pieces_are_unchanged() {
        let c = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(1, 1), q(0, 1)],
            vec![q(1, 1), q(1, 1), q(1, 1)],
            vec![q(2, 1), q(0, 1), q(2, 1)],
        ])
        .expect("valid");
        assert!(curve_balance(&c).is_identity());
        assert_eq!(balance_curve(&c), c);
    }

    #[test]
    fn large_weights_are_scaled_and_skewed_curves_balanced() {
        let big = BezierCurve::from_homogeneous(vec![
            vec![q(3000, 1), q(0, 1)],
            vec![q(5000, 1), q(5000, 1)],
        ])
        .expect("valid");
        let b = balance_curve(&big);
        let w = b.weights();
        assert!(w.iter().all(|x| *x < q(256, 1) && *x > q(1, 256)), "{w:?}");
        let skew = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(0, 1)],
            vec![q(1000, 1), q(1000, 1)],
            vec![q(1_000_000, 1), q(0, 1)],
        ])
        .expect("valid");
        let bal = curve_balance(&skew);
        assert_eq!(bal.a, -10);
        let b = apply_curve(&skew, bal);
        assert!(weight_ratio(&b.weights()) < 2.0);
        let rho = pow2(bal.a);
        for k in 0..=8 {
            let s = q(k, 8);
            let t = rho.clone() * s.clone() / (q(1, 1) - s.clone() + rho.clone() * s.clone());
            assert_eq!(b.eval(&s).expect("finite"), skew.eval(&t).expect("finite"));
        }
    }
}
