//! Closing a `G¹` spline of spatial PH quintics exactly: the last two pieces are re-solved so
//! that the spline ends at its start point with its start tangent direction
//! (docs/math/pipes.md, "Closing the PH spline").
//!
//! A PH quintic `r′ = A i A*`, `A(s) = A₀b₀² + A₁b₁² + A₂b₂²` (Farouki, *Pythagorean-Hodograph
//! Curves*, 2008, §25.2) has the displacement
//!
//! `Φ(B) = 120Δp − 15(d₀ + d₂) + 5(A₀ i A₂* + A₂ i A₀*)`, `B = 4A₁ + 3(A₀ + A₂)`,
//! `dₖ = Aₖ i Aₖ*`, `Φ(B) = B i B*`.
//!
//! With the end quaternions of the last two pieces fixed (the penultimate piece's `A₀`
//! continues the spline, its `A₂ = C`, the last piece's `A₀ = νC`, its `A₂ = A₀⁽¹⁾z` with
//! `z ∈ Q(i)`: then `d₂ = |z|²d₀⁽¹⁾`, the tangent direction of the start), the two end
//! points add up: the spline closes iff `Φ(B′) + Φ(B″) = W` for one rational vector `W`.
//! One equation `Φ(B) = W` has a rational solution only if `|W| ∈ Q` and a norm condition
//! hold; the sum of two always has one, found constructively ([`split_hodograph_sum`]):
//!
//! Write `B = α + βj` (`α = w + xi`, `β = y + zi`): `Φ(B) = (|α|² − |β|², −2iαβ)` (the last
//! two coordinates as one complex number). With `a = (α′, α″)`, `b = (β′, β″) ∈ C²`,
//! `Φ(B′) + Φ(B″) = W = (X, Y + iZ)` reads `|a|² − |b|² = X`, `a·b = ω := i(Y + iZ)/2`
//! (bilinear, no conjugation). For `r = |a|²` the second equation's solutions are
//! `b = ω ā/r + t(α″, −α′)`, `t ∈ C`, whose `|b|² = |ω|²/r + |t|²r`; so the first asks
//! `|t|² r² = (r − X/2)² − |W|²/4`. Writing `R = r − X/2`, `R² − P² = |W|²/4` is a hyperbola
//! with the rational points `R = (m + c²/m)/2`, `P = (c²/m − m)/2` (`c² = |W|²/4`, any
//! rational `m ≠ 0`), and `t = (P/r)u` for any rational unit complex `u`. What is left is a
//! rational point `a` on the 3-sphere `|a|² = r`: one is Lagrange's four squares of `r`
//! ([`rcagd_algebra::integer_squares::rational_four_squares`]), and the line through it and
//! a rational point near the wanted `a` meets the sphere again near the wanted `a`. Every
//! real solution is reached this way (`m`, the point on the sphere, the phase of `u`), so
//! `m`, `a` and `u` are rounded from the `f64` solution nearest the fitted pieces, and the
//! result is checked exactly.

use super::approximation::dyadic;
use super::hodograph::PhCurve;
use super::spatial_hermite::middle_rhs;
use super::util::aib;
use rcagd_algebra::integer_squares::rational_four_squares;
use rcagd_algebra::quaternion::Quaternion;
use rcagd_algebra::{Rational, Scalar};

/// A complex number `(re, im)` over `Q`.
type Cx = (Rational, Rational);

fn cmul(a: &Cx, b: &Cx) -> Cx {
    (&a.0 * &b.0 - &a.1 * &b.1, &a.0 * &b.1 + &a.1 * &b.0)
}

fn cconj(a: &Cx) -> Cx {
    (a.0.clone(), -a.1.clone())
}

fn cscale(a: &Cx, s: &Rational) -> Cx {
    (&a.0 * s, &a.1 * s)
}

fn vector(q: &Quaternion<Rational>) -> [Rational; 3] {
    [q.x.clone(), q.y.clone(), q.z.clone()]
}

/// `B i B*` as a 3-vector.
fn phi(b: &Quaternion<Rational>) -> [Rational; 3] {
    vector(&aib(b, b))
}

/// Rational `B′`, `B″` with `B′ i B′* + B″ i B″* = w` (module docs), near the `f64`
/// quaternions `near` (the first two of whose coordinates are matched to a few units of
/// `2⁻ᵇⁱᵗˢ`; the rest follow from the equation). `None` for `w = 0`, or if no solution near
/// `near` was found (the result is always checked exactly).
pub fn split_hodograph_sum(
    w: &[Rational; 3],
    near: [&Quaternion<f64>; 2],
    bits: u32,
) -> Option<[Quaternion<Rational>; 2]> {
    let [xw, yw, zw] = w;
    let four = Rational::from(4);
    let c2 = (xw * xw + yw * yw + zw * zw) / &four;
    if c2.is_zero() {
        return None;
    }
    let [b1, b2] = near;
    // the f64 solution to round: r*, R*, P*, m*
    let a_star = [b1.w, b1.x, b2.w, b2.x];
    let r_star: f64 = a_star.iter().map(|v| v * v).sum();
    let half_x = Scalar::to_f64(xw) / 2.0;
    let big_r = r_star - half_x;
    let c2f = Scalar::to_f64(&c2);
    let p_star = (big_r * big_r - c2f).max(0.0).sqrt();
    let m_star = big_r - p_star;
    let m = dyadic(m_star, bits).filter(|m| *m > Rational::ZERO)?;
    let two = Rational::from(2);
    let r_cap = (&m + &c2 / &m) / &two;
    let p_cap = (&c2 / &m - &m) / &two;
    let r = xw / &two + r_cap;
    if r <= Rational::ZERO {
        return None;
    }
    // a point of the 3-sphere |a|² = r near a*
    let target: Vec<Rational> = a_star
        .iter()
        .map(|v| dyadic(*v, bits))
        .collect::<Option<_>>()?;
    let mut best: Option<(f64, [Rational; 4])> = None;
    for seed in 0..4u64 {
        let Some(a0) = rational_four_squares(&r, seed) else {
            continue;
        };
        for signs in 0..16u32 {
            let a0: [Rational; 4] = core::array::from_fn(|k| {
                if signs >> k & 1 == 1 {
                    -a0[k].clone()
                } else {
                    a0[k].clone()
                }
            });
            let v: [Rational; 4] = core::array::from_fn(|k| &target[k] - &a0[k]);
            let vv = v.iter().fold(Rational::ZERO, |s, x| s + x * x);
            let a = if vv.is_zero() {
                a0
            } else {
                let av = (0..4).fold(Rational::ZERO, |s, k| s + &a0[k] * &v[k]);
                let lambda = -(&two * av) / vv;
                core::array::from_fn(|k| &a0[k] + &lambda * &v[k])
            };
            let err = (0..4)
                .map(|k| (Scalar::to_f64(&a[k]) - a_star[k]).powi(2))
                .sum::<f64>();
            if best.as_ref().is_none_or(|b| err < b.0) {
                best = Some((err, a));
            }
        }
        if best
            .as_ref()
            .is_some_and(|b| b.0.sqrt() < 2f64.powi(4 - bits as i32))
        {
            break;
        }
    }
    let (_, a) = best?;
    let [aw1, ax1, aw2, ax2] = a;
    let (al1, al2): (Cx, Cx) = ((aw1, ax1), (aw2, ax2));
    // ω = i(Y + iZ)/2 = (−Z + iY)/2; b₀ = ω ā / r
    let omega: Cx = (-zw.clone() / &two, yw.clone() / &two);
    let b01 = cscale(&cmul(&omega, &cconj(&al1)), &(Rational::ONE / &r));
    let b02 = cscale(&cmul(&omega, &cconj(&al2)), &(Rational::ONE / &r));
    // the phase of t nearest the f64 solution: t* = ⟨b* − b₀, (α″, −α′)⟩ / r
    let c = |z: &Cx| (Scalar::to_f64(&z.0), Scalar::to_f64(&z.1));
    let (d1, d2) = (
        (b1.y - c(&b01).0, b1.z - c(&b01).1),
        (b2.y - c(&b02).0, b2.z - c(&b02).1),
    );
    let (g2, g1) = (c(&al2), c(&al1));
    // d1·conj(α″) + d2·conj(−α′)
    let ts = (
        d1.0 * g2.0 + d1.1 * g2.1 - d2.0 * g1.0 - d2.1 * g1.1,
        d1.1 * g2.0 - d1.0 * g2.1 - d2.1 * g1.0 + d2.0 * g1.1,
    );
    let theta = if ts.0 == 0.0 && ts.1 == 0.0 {
        0.0
    } else {
        ts.1.atan2(ts.0)
    };
    let (flip, half) = if theta.abs() > core::f64::consts::FRAC_PI_2 {
        (true, (theta - core::f64::consts::PI.copysign(theta)) / 2.0)
    } else {
        (false, theta / 2.0)
    };
    let s = dyadic(half.tan(), bits)?;
    let one_s2 = Rational::ONE + &s * &s;
    let mut u: Cx = ((Rational::ONE - &s * &s) / &one_s2, &two * &s / &one_s2);
    if flip {
        u = (-u.0, -u.1);
    }
    let t = cscale(&u, &(&p_cap / &r));
    let ta2 = cmul(&t, &al2);
    let ta1 = cmul(&t, &al1);
    let be1: Cx = (&b01.0 + &ta2.0, &b01.1 + &ta2.1);
    let be2: Cx = (&b02.0 - &ta1.0, &b02.1 - &ta1.1);
    let q1 = Quaternion {
        w: al1.0,
        x: al1.1,
        y: be1.0,
        z: be1.1,
    };
    let q2 = Quaternion {
        w: al2.0,
        x: al2.1,
        y: be2.0,
        z: be2.1,
    };
    let (p1, p2) = (phi(&q1), phi(&q2));
    let ok = (0..3).all(|k| &p1[k] + &p2[k] == w[k]);
    ok.then_some([q1, q2])
}

/// The last two pieces of a spline re-solved so that it ends at `first`'s start point with
/// `first`'s start tangent direction (module docs): `(penultimate, last)`, each with the same
/// `A₀` as before (so the spline stays `G¹` with what precedes them) and the same start
/// point; the last piece's `A₂ = A₀⁽¹⁾z` with `z ∈ Q(i)` rounded to `2⁻ᵇⁱᵗˢ` from the fitted
/// `A₂`. `None` if the pieces are not quintics or no solution was found; the result is
/// checked exactly (the last end point is `first`'s start point).
pub fn close_two_pieces(
    first: &PhCurve<Rational>,
    penultimate: &PhCurve<Rational>,
    last: &PhCurve<Rational>,
    bits: u32,
) -> Option<(PhCurve<Rational>, PhCurve<Rational>)> {
    let a0f = first.coefficients().first()?.clone();
    let [pa0, pa1, pc]: [Quaternion<Rational>; 3] =
        penultimate.coefficients().to_vec().try_into().ok()?;
    let [la0, la1, la2]: [Quaternion<Rational>; 3] =
        last.coefficients().to_vec().try_into().ok()?;
    // z ≈ (A₀⁽¹⁾)⁻¹ A₂, projected on span{1, i}
    let zq = a0f.to_f64().inverse()? * la2.to_f64();
    let (zw, zx) = (dyadic(zq.w, bits)?, dyadic(zq.x, bits)?);
    if zw.is_zero() && zx.is_zero() {
        return None;
    }
    let z = Quaternion {
        w: zw,
        x: zx,
        y: Rational::ZERO,
        z: Rational::ZERO,
    };
    let a2 = a0f.clone() * z;
    // W = c′ + c″, the two middle equations' right-hand sides with the joint between the
    // pieces taken at P (it cancels from the sum): 120(p⁽¹⁾ − P) − 15Σd + 5Σ(cross terms)
    let (d1, d2, d3, d4) = (phi(&pa0), phi(&pc), phi(&la0), phi(&a2));
    let (p_end, p_start) = (first.start(), penultimate.start());
    let c1 = middle_rhs((p_start, &d1), (p_start, &d2), &pa0, &pc);
    let c2 = middle_rhs((p_start, &d3), (p_end, &d4), &la0, &a2);
    let w: [Rational; 3] = core::array::from_fn(|k| &c1[k] + &c2[k]);
    let three = Rational::from(3);
    let four = Rational::from(4);
    let middle =
        |a0: &Quaternion<Rational>, a1: &Quaternion<Rational>, a2: &Quaternion<Rational>| {
            (a1.scale(&four) + (a0.clone() + a2.clone()).scale(&three)).to_f64()
        };
    let (n1, n2) = (middle(&pa0, &pa1, &pc), middle(&la0, &la1, &a2));
    let [b1, b2] = split_hodograph_sum(&w, [&n1, &n2], bits)?;
    let quarter = Rational::ONE / &four;
    let a1p = (b1 - (pa0.clone() + pc.clone()).scale(&three)).scale(&quarter);
    let a1l = (b2 - (la0.clone() + a2.clone()).scale(&three)).scale(&quarter);
    let pen = PhCurve::new(vec![pa0, a1p, pc], penultimate.start().clone()).ok()?;
    let end = pen.eval(&Rational::ONE);
    let lst = PhCurve::new(vec![la0, a1l, a2], end).ok()?;
    (lst.eval(&Rational::ONE) == *first.start()).then_some((pen, lst))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn quat(v: [f64; 4]) -> Quaternion<f64> {
        Quaternion {
            w: v[0],
            x: v[1],
            y: v[2],
            z: v[3],
        }
    }

    #[test]
    fn phi_is_the_hopf_map_of_the_module_docs() {
        // Φ(α + βj) = (|α|² − |β|², −2iαβ)
        let b = Quaternion {
            w: Rational::from(2),
            x: Rational::from(-3),
            y: Rational::from(5),
            z: Rational::from(7),
        };
        let (aw, ax, by, bz) = (2i64, -3i64, 5i64, 7i64);
        // αβ = (aw + i ax)(by + i bz)
        let (re, im) = (aw * by - ax * bz, aw * bz + ax * by);
        let expect = [aw * aw + ax * ax - by * by - bz * bz, 2 * im, -2 * re];
        assert_eq!(phi(&b), expect.map(Rational::from));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// Random `B′, B″` in `f64`, a rational `w` near their `Φ` sum (perturbed): the split
        /// is exact and near the given quaternions in its `α` parts.
        #[test]
        fn sums_of_two_hodograph_squares_are_split_exactly(
            b in proptest::collection::vec(-3.0f64..3.0, 8),
            e in proptest::collection::vec(-1000i64..1000, 3),
        ) {
            let (q1, q2) = (quat([b[0], b[1], b[2], b[3]]), quat([b[4], b[5], b[6], b[7]]));
            let f = |q: &Quaternion<f64>| aib(q, q);
            let (s1, s2) = (f(&q1), f(&q2));
            let sum = [s1.x + s2.x, s1.y + s2.y, s1.z + s2.z];
            let w: [Rational; 3] = core::array::from_fn(|k| {
                dyadic(sum[k], 20).expect("finite") + Rational::from_ratio(e[k], 1_000_000_007)
            });
            prop_assume!(w.iter().any(|x| !x.is_zero()));
            let [r1, r2] = split_hodograph_sum(&w, [&q1, &q2], 30).expect("a split");
            let (p1, p2) = (phi(&r1), phi(&r2));
            for k in 0..3 {
                prop_assert_eq!(&p1[k] + &p2[k], w[k].clone());
            }
            // the α parts are matched closely
            let d = [Scalar::to_f64(&r1.w) - q1.w, Scalar::to_f64(&r1.x) - q1.x, Scalar::to_f64(&r2.w) - q2.w, Scalar::to_f64(&r2.x) - q2.x];
            let err = d.iter().map(|x| x * x).sum::<f64>().sqrt();
            prop_assert!(err < 1e-4, "α parts moved by {}", err);
        }
    }
}
