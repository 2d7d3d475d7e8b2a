//! Pieces with weights of one sign: splitting rational Bézier curves and patches until
//! every piece has Bernstein weights all `> 0` (or all `< 0`).
//!
//! Exchange formats (STEP, IGES) need positive weights, and a picture or mesh of a piece
//! whose weight function `w` vanishes inside draws a spike to infinity. If `w` has no
//! zero on the parameter domain, the Bernstein coefficients of the restrictions to
//! smaller and smaller intervals converge to values of `w` (uniformly, at rate `O(h)`),
//! so a finite subdivision gives pieces whose weights all have the sign of `w`; the
//! converse is the convex-hull property: weights all of one sign ⇒ `w` has no zero on
//! the piece (no pole, no point at infinity). If `w` has a zero on the closed domain
//! (e.g. a weight that vanishes on a whole boundary edge), no subdivision helps: the
//! splitters give up after a bounded depth and say so.
//!
//! * [`split_curve_uniform`], [`split_patch_uniform`]: the restrictions to the `2ᴸ`
//!   intervals `[i/2ᴸ, (i+1)/2ᴸ]` (`2ᴸ × 2ᴸ` squares) for the least `L` that works;
//! * [`split_patches_adaptive`]: bisection at `1/2` of only the pieces that need it,
//!   first in `v` then in `u` (canal surfaces: a characteristic circle over more than a
//!   half turn has a weight ≤ 0 in the middle of its quadratic Bézier form).
//!
//! All pieces are exact restrictions of the input (de Casteljau / Möbius
//! reparametrization), so they lie on whatever the input lies on.

use crate::{BezierCurve, BezierPatch, GeomError};
use rcagd_algebra::Scalar;

/// Which weights a piece must have.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SignRule {
    /// All weights `> 0`.
    Positive,
    /// All weights `> 0` or all `< 0` (an all-negative piece is the same projective
    /// object as its negation).
    OneSign,
}

impl SignRule {
    /// `true` if the weights (every `stride`-th coordinate, from the first) obey the rule.
    pub fn holds<F: Scalar>(self, coords: &[F], stride: usize) -> bool {
        let zero = F::zero();
        let mut w = coords.iter().step_by(stride.max(1));
        match self {
            SignRule::Positive => w.all(|x| *x > zero),
            SignRule::OneSign => {
                let all: Vec<&F> = w.collect();
                all.iter().all(|x| **x > zero) || all.iter().all(|x| **x < zero)
            }
        }
    }
}

/// `true` if the curve's weights are all `> 0` or all `< 0`.
pub fn curve_has_one_sign<F: Scalar>(c: &BezierCurve<F>) -> bool {
    SignRule::OneSign.holds(c.coords(), c.dim() + 1)
}

/// `true` if the patch's weights are all `> 0` or all `< 0`.
pub fn patch_has_one_sign<F: Scalar>(p: &BezierPatch<F>) -> bool {
    SignRule::OneSign.holds(p.coords(), p.dim() + 1)
}

/// `i / 2ᴸ` as a scalar.
fn dyadic<F: Scalar>(i: u32, level: u32) -> F {
    F::from_i64(i64::from(i)) / F::from_i64(1i64 << level)
}

/// The restrictions of `curve` to `[i/2ᴸ, (i+1)/2ᴸ]`, `i < 2ᴸ`, for the least
/// `L ≤ max_level` whose pieces all have weights of one sign (`L = 0`: the curve
/// itself); `None` if no such `L` exists (the weight function has a zero on `[0, 1]`,
/// or the zero-free margin is too thin for `max_level`).
///
/// # Errors
/// [`GeomError::Parameter`] if `max_level > 20` (over a million pieces).
pub fn split_curve_uniform<F: Scalar>(
    curve: &BezierCurve<F>,
    max_level: u32,
) -> Result<Option<Vec<BezierCurve<F>>>, GeomError> {
    check_level(max_level)?;
    for level in 0..=max_level {
        let k = 1u32 << level;
        let pieces = (0..k)
            .map(|i| {
                if level == 0 {
                    Ok(curve.clone())
                } else {
                    curve.restrict(&dyadic(i, level), &dyadic(i + 1, level))
                }
            })
            .collect::<Result<Vec<_>, _>>()?;
        if pieces.iter().all(curve_has_one_sign) {
            return Ok(Some(pieces));
        }
    }
    Ok(None)
}

/// As [`split_curve_uniform`] for a patch: its restrictions to the `2ᴸ × 2ᴸ` squares
/// `[i/2ᴸ, (i+1)/2ᴸ] × [j/2ᴸ, (j+1)/2ᴸ]`, in the order `(i, j)` with `j` fastest.
///
/// # Errors
/// [`GeomError::Parameter`] if `max_level > 10`.
pub fn split_patch_uniform<F: Scalar>(
    patch: &BezierPatch<F>,
    max_level: u32,
) -> Result<Option<Vec<BezierPatch<F>>>, GeomError> {
    if max_level > 10 {
        return Err(GeomError::Parameter(format!(
            "split_patch_uniform: level {max_level} > 10 would make over a million pieces"
        )));
    }
    for level in 0..=max_level {
        let k = 1u32 << level;
        let mut pieces = Vec::with_capacity((k * k) as usize);
        for i in 0..k {
            for j in 0..k {
                pieces.push(if level == 0 {
                    patch.clone()
                } else {
                    patch.restrict(
                        &dyadic(i, level),
                        &dyadic(i + 1, level),
                        &dyadic(j, level),
                        &dyadic(j + 1, level),
                    )?
                });
            }
        }
        if pieces.iter().all(patch_has_one_sign) {
            return Ok(Some(pieces));
        }
    }
    Ok(None)
}

fn check_level(level: u32) -> Result<(), GeomError> {
    if level > 20 {
        return Err(GeomError::Parameter(format!(
            "split level {level} > 20 would make over a million pieces"
        )));
    }
    Ok(())
}

/// The result of [`split_patches_adaptive`].
#[derive(Debug, Clone, PartialEq)]
pub struct AdaptiveSplit<F> {
    /// The pieces, in the order of the input patches, each patch's pieces in parameter
    /// order (bisection halves `[0, 1/2]` before `[1/2, 1]`).
    pub pieces: Vec<BezierPatch<F>>,
    /// For each piece, the index of the input patch it comes from.
    pub source: Vec<usize>,
    /// How many pieces still break the rule after the deepest bisection (they are in
    /// `pieces` as they are).
    pub failed: usize,
}

/// Bisects (at parameter `1/2`) every patch whose weights break `rule`: first up to
/// `max_splits.0` times in `v`, then up to `max_splits.1` times in `u`, only where still
/// needed. Pieces that obey the rule are kept as they are.
///
/// # Errors
/// [`GeomError::Parameter`] if `max_splits.0 + max_splits.1 > 20`.
pub fn split_patches_adaptive<F: Scalar>(
    patches: Vec<BezierPatch<F>>,
    rule: SignRule,
    max_splits: (usize, usize),
) -> Result<AdaptiveSplit<F>, GeomError> {
    if max_splits.0 + max_splits.1 > 20 {
        return Err(GeomError::Parameter(format!(
            "split_patches_adaptive: {} + {} bisections would make over a million pieces",
            max_splits.0, max_splits.1
        )));
    }
    let half = F::from_ratio(1, 2);
    let mut out = AdaptiveSplit {
        pieces: Vec::new(),
        source: Vec::new(),
        failed: 0,
    };
    let mut todo: Vec<(BezierPatch<F>, usize, usize, usize)> = patches
        .into_iter()
        .enumerate()
        .rev()
        .map(|(k, p)| (p, k, 0, 0))
        .collect();
    while let Some((p, k, dv, du)) = todo.pop() {
        if rule.holds(p.coords(), p.dim() + 1) {
            out.pieces.push(p);
            out.source.push(k);
        } else if dv < max_splits.0 {
            let (a, b) = p.subdivide_v(&half)?;
            todo.push((b, k, dv + 1, du));
            todo.push((a, k, dv + 1, du));
        } else if du < max_splits.1 {
            let (a, b) = p.subdivide_u(&half)?;
            todo.push((b, k, dv, du + 1));
            todo.push((a, k, dv, du + 1));
        } else {
            out.failed += 1;
            out.pieces.push(p);
            out.source.push(k);
        }
    }
    Ok(out)
}

/// The index of a boundary curve of the patch (`v = 0, u = 1, v = 1, u = 0`, as
/// [`BezierPatch::boundary_curves`]) whose weights are all zero: the weight function
/// vanishes on that whole edge (the edge lies at infinity), so no subdivision gives
/// pieces of one sign.
pub fn zero_weight_edge<F: Scalar>(p: &BezierPatch<F>) -> Option<usize> {
    let zero = F::zero();
    p.boundary_curves()
        .iter()
        .position(|c| c.control_points().all(|h| h.first() == Some(&zero)))
}

/// Decides that a patch has no pole on `[0, 1]²`: weights of one sign (convex hull
/// property), or — weights of mixed sign — pieces of one sign after at most `5 + 5` exact
/// bisections ([`split_patches_adaptive`]; each piece's weight function is then non-zero,
/// so the union is). The certificate, or `None` when neither decides (the weight function
/// may vanish on the square: the patch passes through or near points at infinity).
pub fn patch_pole_free<F: Scalar>(patch: &BezierPatch<F>) -> Option<rcagd_algebra::Certificate> {
    use rcagd_algebra::Certificate;
    if patch_has_one_sign(patch) {
        return Some(Certificate::decide(
            "the weights wᵢⱼ all have one sign (Σ wᵢⱼ Bᵢ Bⱼ ≠ 0 on [0, 1]²: no pole)",
            true,
            F::EXACT,
            String::new,
        ));
    }
    match split_patches_adaptive(vec![patch.clone()], SignRule::OneSign, (5, 5)) {
        Ok(split) if split.failed == 0 => Some(Certificate::decide(
            format!(
                "weights of mixed sign, but each of {} subpatches (exact bisections) has weights of one sign: Σ wᵢⱼ Bᵢ Bⱼ ≠ 0 on [0, 1]² (no pole)",
                split.pieces.len()
            ),
            true,
            F::EXACT,
            String::new,
        )),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    /// The arc `(1 − t², 2t)/(1 + t²)`, `t ∈ [−1, 3]`, reparametrized to `[0, 1]`: its
    /// weight `1 + t² > 0` has a negative middle Bernstein coefficient.
    fn three_quarter_circle() -> BezierCurve<Rational> {
        // blossoms at (−1, −1), (−1, 3), (3, 3): middle weight 1 + (−1)(3) = −2 < 0
        BezierCurve::from_homogeneous(vec![
            vec![q(2, 1), q(0, 1), q(-2, 1)],
            vec![q(-2, 1), q(4, 1), q(2, 1)],
            vec![q(10, 1), q(-8, 1), q(6, 1)],
        ])
        .expect("valid")
    }

    #[test]
    fn rules() {
        let c = [q(1, 1), q(5, 1), q(2, 1), q(-1, 1)];
        assert!(SignRule::Positive.holds(&c, 2));
        assert!(!SignRule::OneSign.holds(&c, 1));
        let n = [q(-1, 1), q(0, 1), q(-2, 1), q(7, 1)];
        assert!(!SignRule::Positive.holds(&n, 2));
        assert!(SignRule::OneSign.holds(&n, 2));
        let z = [q(0, 1), q(1, 1)];
        assert!(!SignRule::OneSign.holds(&z, 2));
    }

    #[test]
    fn a_curve_with_a_zero_free_weight_splits_into_one_sign_pieces() {
        let c = three_quarter_circle();
        assert!(!curve_has_one_sign(&c));
        let pieces = split_curve_uniform(&c, 4)
            .expect("level ok")
            .expect("splits");
        assert!(pieces.len() > 1 && pieces.iter().all(curve_has_one_sign));
        // the pieces are the restrictions: the joints are points of the curve
        for (i, p) in pieces.iter().enumerate() {
            let t = q(i as i64, pieces.len() as i64);
            assert_eq!(
                p.eval(&q(0, 1)).expect("finite"),
                c.eval(&t).expect("finite")
            );
        }
        // a curve with a pole on [0, 1] (weight 1 − 2t) does not split
        let pole =
            BezierCurve::from_homogeneous(vec![vec![q(1, 1), q(0, 1)], vec![q(-1, 1), q(1, 1)]])
                .expect("valid");
        assert_eq!(split_curve_uniform(&pole, 6).expect("level ok"), None);
        assert!(split_curve_uniform(&pole, 21).is_err());
    }

    #[test]
    fn patches_split_uniformly_and_adaptively() {
        // the ruled patch between the 3/4 circle and its lift z = 1
        let c = three_quarter_circle();
        let lift = BezierCurve::from_homogeneous(
            c.control_points()
                .map(|h| vec![h[0].clone(), h[1].clone(), h[2].clone(), h[0].clone()])
                .collect(),
        )
        .expect("valid");
        let flat = BezierCurve::from_homogeneous(
            c.control_points()
                .map(|h| vec![h[0].clone(), h[1].clone(), h[2].clone(), q(0, 1)])
                .collect(),
        )
        .expect("valid");
        // u along the ruling, v along the circle
        let p = BezierPatch::from_curves_ruled(&flat, &lift)
            .expect("same dim")
            .transpose();
        assert_eq!(p.degree(), (1, 2));
        assert!(!patch_has_one_sign(&p));
        let uni = split_patch_uniform(&p, 3).expect("ok").expect("splits");
        assert!(uni.iter().all(patch_has_one_sign));
        let ad = split_patches_adaptive(vec![p.clone()], SignRule::Positive, (4, 4)).expect("ok");
        assert_eq!(ad.failed, 0);
        assert!(ad.source.iter().all(|&k| k == 0));
        assert!(ad
            .pieces
            .iter()
            .all(|x| SignRule::Positive.holds(x.coords(), 4)));
        // only v was bisected: no more pieces than the uniform split
        assert!(
            ad.pieces.len() <= uni.len(),
            "{} {}",
            ad.pieces.len(),
            uni.len()
        );
        assert_eq!(zero_weight_edge(&p), None);
    }

    #[test]
    fn a_weight_vanishing_on_an_edge_is_found_and_does_not_split() {
        // w = u (bilinear): zero on the edge u = 0
        let net = vec![
            vec![
                vec![q(0, 1), q(1, 1), q(0, 1), q(0, 1)],
                vec![q(0, 1), q(1, 1), q(1, 1), q(0, 1)],
            ],
            vec![
                vec![q(1, 1), q(1, 1), q(0, 1), q(0, 1)],
                vec![q(1, 1), q(1, 1), q(1, 1), q(0, 1)],
            ],
        ];
        let p = BezierPatch::from_homogeneous(net).expect("valid");
        assert_eq!(zero_weight_edge(&p), Some(3));
        let ad = split_patches_adaptive(vec![p.clone()], SignRule::OneSign, (2, 2)).expect("ok");
        assert!(ad.failed > 0);
        assert_eq!(split_patch_uniform(&p, 3).expect("ok"), None);
    }

    #[test]
    fn patch_pole_free_decides_one_sign_and_refuses_a_vanishing_weight() {
        use rcagd_algebra::Rational;
        let q = |n: i64| Rational::from(n);
        let patch = |w: [[i64; 2]; 2]| {
            BezierPatch::from_homogeneous(
                (0..2)
                    .map(|i| {
                        (0..2)
                            .map(|j| {
                                let wij = q(w[i][j]);
                                vec![wij.clone(), wij.clone() * q(i as i64), wij * q(j as i64)]
                            })
                            .collect()
                    })
                    .collect(),
            )
            .unwrap()
        };
        let c = patch_pole_free(&patch([[1, 2], [3, 1]])).unwrap();
        assert!(c.holds && c.exact);
        // w(u, v) = (1 − 2u)(1 − 2v) vanishes on the square
        assert!(patch_pole_free(&patch([[1, -1], [-1, 1]])).is_none());
    }
}

/// Where the weight function of an exact curve vanishes on `[0, 1]`: the curve passes
/// through a point at infinity there (a pole).
#[derive(Debug, Clone, PartialEq)]
pub struct WeightZero {
    /// The distinct zeros of `w(t) = Σ wᵢ Bᵢⁿ(t)` in `[0, 1]`, as exact isolating
    /// intervals `[lo, hi]` (equal ends for a rational zero) with the zero rounded to
    /// `f64`.
    pub zeros: Vec<(rcagd_algebra::Rational, rcagd_algebra::Rational, f64)>,
}

impl core::fmt::Display for WeightZero {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        use crate::certify::format_scalar;
        let at: Vec<String> = self
            .zeros
            .iter()
            .map(|(lo, hi, t)| {
                if t.is_nan() {
                    "every t (it is identically zero)".to_string()
                } else if lo == hi {
                    format!("t = {}", format_scalar(lo))
                } else {
                    format!(
                        "t ≈ {t:.9} (in [{}, {}])",
                        format_scalar(lo),
                        format_scalar(hi)
                    )
                }
            })
            .collect();
        write!(
            f,
            "the weight function Σ wᵢ Bᵢ(t) vanishes at {}: the curve passes through a point at infinity (a pole) on [0, 1]",
            at.join(", ")
        )
    }
}

/// Decides exactly that an exact rational curve has no pole on `[0, 1]` — the one rule
/// every op applies to a user's weights: weights of one sign suffice (convex hull
/// property; all negative is the same curve), otherwise the weight polynomial's zeros in
/// `[0, 1]` are counted by exact real-root isolation (Sturm/Descartes bisection,
/// [`rcagd_algebra::roots::isolate_real_roots_in`]). Returns the certificate; weights of mixed
/// sign whose weight function has no zero on `[0, 1]` are accepted (the exporters split
/// such a curve into pieces of one sign).
///
/// # Errors
/// [`WeightZero`] naming every zero of the weight function on `[0, 1]` (also for a
/// weight function that is identically zero: every point is at infinity).
pub fn curve_pole_free(
    c: &BezierCurve<rcagd_algebra::Rational>,
) -> Result<rcagd_algebra::Certificate, WeightZero> {
    use rcagd_algebra::roots::isolate_real_roots_in;
    use rcagd_algebra::Certificate;
    use rcagd_algebra::Rational;
    if curve_has_one_sign(c) {
        return Ok(Certificate::decide(
            "the weights wᵢ all have one sign (Σ wᵢ Bᵢ ≠ 0 on [0, 1]: no pole)",
            true,
            true,
            String::new,
        ));
    }
    let (zero, one) = (Rational::from(0), Rational::from(1));
    let w = c.weight_poly();
    if w.is_zero() {
        return Err(WeightZero {
            zeros: vec![(zero, one, f64::NAN)],
        });
    }
    match isolate_real_roots_in(&w, &zero, &one) {
        Ok(roots) if roots.is_empty() => Ok(Certificate::decide(
            "the weight function Σ wᵢ Bᵢ(t) has no zero on [0, 1] (weights of mixed sign; exact real-root isolation): no pole",
            true,
            true,
            String::new,
        )),
        Ok(roots) => Err(WeightZero {
            zeros: roots
                .iter()
                .map(|r| {
                    let t = r.root_f64(&w).unwrap_or((Scalar::to_f64(&r.lo) + Scalar::to_f64(&r.hi)) / 2.0);
                    (r.lo.clone(), r.hi.clone(), t)
                })
                .collect(),
        }),
        Err(_) => Err(WeightZero {
            zeros: vec![(zero, one, f64::NAN)],
        }),
    }
}
