//! Certified global regularity of canal surfaces of varying radius: the closed discs bounded
//! by the characteristic circles are pairwise disjoint, so the surface has no
//! self-intersection (docs/math/pipes.md#canal-global).
//!
//! The envelope of the spheres `|x − m(t)|² = r(t)²` is the union of the characteristic
//! circles `C(t) = S(t) ∩ Π(t)`, `Π(t): (x − m)·ṁ + r ṙ = 0`, with centre
//! `c = m − (r ṙ/|ṁ|²) ṁ` and radius `ρ = |r|(1 − ṙ²/|ṁ|²)^{1/2}` (Peternell–Pottmann,
//! "Computing rational parametrizations of canal surfaces", J. Symbolic Computation 23
//! (1997), §2). For `m = M/W`, `r = R/W` and `A = WM′ − W′M`, `B = WR′ − W′R`:
//!
//! ```text
//! c = (M|A|² − RBA)/(W|A|²),   ρ² = R²(|A|² − B²)/(W²|A|²),   Π(t): x·A − E/W = 0,  E = M·A − RB.
//! ```
//!
//! [`check_canal_embedded`] decides that the closed discs `Δ(t)` (bounded by `C(t)`) of
//! distinct parameters of `[a, b]` are pairwise disjoint by subdividing the triangle of
//! parameter pairs `t ≤ s` into dyadic boxes `I × J`. A box is settled by
//!
//! * **Lemma A with varying radius** over the stretch from `min I` to `max J`:
//!   `κ_max(ρ_max + κ_max L(g_max + L/2)) + Q_max < 1` or
//!   `Q_min − κ_max(ρ_max + κ_max L(g_max + L/2)) > 1`, with `κ` the spine's curvature, `L`
//!   the stretch's arc length, `g = r dr/dσ = RB/(W|A|)` and `Q = dg/dσ =
//!   ((B² + RD)|A|² − RB(A·C))/|A|⁴` (`C = WA′ − 2W′A`, `D = WB′ − 2W′B`, `σ` arc length);
//!   then no two discs over the stretch meet;
//! * **far**: `|c(t) − c(s)| > ρ(t) + ρ(s)`;
//! * **a disc misses the other's plane**: `φ_s(c(t))²|A(t)|² > ρ(t)²|A(s) × A(t)|²`,
//!   `φ_s(y) = y·A(s) − E(s)/W(s)` (or with `t` and `s` exchanged);
//! * **disjoint chords** on the line `Π(t) ∩ Π(s)` (direction `u = A(t) × A(s)`): with
//!   `δ = (c(t) − c(s))·u`, `H_t = ρ(t)²|u|² − φ_s(c(t))²|A(t)|²` (`|u|²` times the squared
//!   half chord), `H_s` likewise and `X = δ² − H_t⁺ − H_s⁺`: `X > 0` and `X² > 4H_t⁺H_s⁺`;
//! * **the plane test as one polynomial** `G(t, s) > 0` ([`plane_poly`]; on one piece
//!   divided by `(s − t)²`, which leaves the local condition on the diagonal, so boxes
//!   touching it settle wherever the local check passed), decided by the signs of its
//!   tensor Bernstein coefficients: exact once per pair of pieces, then `f64` halvings with
//!   a proven error bound, the exact corner values and the exact tensor where `f64` does
//!   not decide.
//!
//! Each test is evaluated in exact rational interval arithmetic: every quantity is a ratio
//! of polynomials in one parameter, enclosed on a dyadic interval by the hull of the exact
//! Bernstein coefficients of its numerator and denominator (convex hull property; a
//! denominator hull that contains 0 leaves the test unsettled); square roots appear only as
//! rational upper bounds of `ρ`, `κ`, `g`, `|ṁ|` (squared back and checked,
//! [`super::regularity::sqrt_upper`]) or are cleared by squaring with the sign conditions
//! above. An unsettled box is split into four (a box on the diagonal into three) breadth
//! first; its centre pair is tested exactly for meeting discs first ([`discs_meet`]: an exact
//! witness refuses the surface). Limits [`CANAL_GLOBAL_DEPTH`] halvings and
//! [`CANAL_GLOBAL_BOXES`] boxes: then the answer is "undecided", an error naming the box.
//!
//! **Chains and closed spines** ([`check_canal_chain_embedded`]): boxes are pairs of dyadic
//! intervals of any two pieces; Lemma A runs across a joint where the discs run on smoothly
//! (the same sphere, tangent direction and `g`) and, on a closed chain, through the seam.
//! **The cyclographic `Γ(s, t)`** ([`check_cyclographic_embedded`]): the discs over an
//! enclosure of the spine parameters its rectangle reaches (docs/math/pipes.md#canal-global,
//! "Chains and closed spines" and "On a rectangle of the cyclographic parametrization").

use super::bipoly::BiPoly;
use super::float_bernstein::{f64_above, f64_below, FTensor, Tri};
use super::regularity::{cross, dot};
use super::{CanalError, CanalSpine};
use crate::error::format_scalar;
use rcagd_algebra::bernstein::{subdivide_blocks, to_bernstein_blocks};
use rcagd_algebra::{Certificate, Poly, Rational, Scalar};
use std::collections::{HashMap, VecDeque};
use std::rc::Rc;

/// Most halvings of the parameter interval in [`check_canal_embedded`].
pub const CANAL_GLOBAL_DEPTH: u32 = 16;
/// Most boxes of parameter pairs [`check_canal_embedded`] examines.
pub const CANAL_GLOBAL_BOXES: usize = 20_000;

type P = Poly<Rational>;

// Indices of the polynomials of `Polys::all` (one Bernstein block per interval).
const I_W: usize = 0;
const I_A: usize = 1; // 1, 2, 3
const I_E: usize = 4;
const I_NC: usize = 5; // 5, 6, 7
const I_DC: usize = 8;
const I_NRHO: usize = 9;
const I_DRHO: usize = 10;
const I_NK: usize = 11;
const I_DK: usize = 12;
const I_NQ: usize = 13;
const I_DQ: usize = 14;
const I_NG: usize = 15;
const I_AA: usize = 16;
const I_W4: usize = 17;
const COUNT: usize = 18;

/// The polynomials of the module docs, in the order of the `I_*` indices:
/// `W, A, E, M|A|² − RBA, W|A|², R²(|A|² − B²), W²|A|², W²|A × C|², |A|⁶,
/// (B² + RD)|A|² − RB(A·C), |A|⁴, R²B², |A|², W⁴`.
fn polys(spine: &CanalSpine<Rational>) -> Vec<P> {
    let w = spine.weight();
    let wd = w.derivative();
    let m = spine.center_polys();
    let r = spine.radius_poly();
    let two = Rational::from(2);
    let a: [P; 3] = core::array::from_fn(|i| &(w * &m[i].derivative()) - &(&wd * &m[i]));
    let b = &(w * &r.derivative()) - &(&wd * r);
    let c: [P; 3] =
        core::array::from_fn(|i| &(w * &a[i].derivative()) - &(&wd * &a[i]).scale(&two));
    let d = &(w * &b.derivative()) - &(&wd * &b).scale(&two);
    let aa = dot(&a, &a);
    let rb = r * &b;
    let w2 = w * w;
    let axc = cross(&a, &c);
    let mut out = vec![w.clone()];
    out.extend(a.iter().cloned());
    out.push(&dot(m, &a) - &rb);
    out.extend((0..3).map(|i| &(&m[i] * &aa) - &(&rb * &a[i])));
    out.push(w * &aa);
    out.push(&(r * r) * &(&aa - &(&b * &b)));
    out.push(&w2 * &aa);
    out.push(&w2 * &dot(&axc, &axc));
    out.push(&(&aa * &aa) * &aa);
    out.push(&(&(&(&b * &b) + &(r * &d)) * &aa) - &(&rb * &dot(&a, &c)));
    out.push(&aa * &aa);
    out.push(&rb * &rb);
    out.push(aa.clone());
    out.push(&w2 * &w2);
    out
}

/// A closed interval `[lo, hi]` of rationals.
#[derive(Debug, Clone)]
struct Iv {
    lo: Rational,
    hi: Rational,
}

fn rmin(a: &Rational, b: &Rational) -> Rational {
    if a <= b {
        a.clone()
    } else {
        b.clone()
    }
}

fn rmax(a: &Rational, b: &Rational) -> Rational {
    if a >= b {
        a.clone()
    } else {
        b.clone()
    }
}

impl Iv {
    fn hull<'a>(mut it: impl Iterator<Item = &'a Rational>) -> Iv {
        let first = it.next().cloned().unwrap_or(Rational::ZERO);
        it.fold(
            Iv {
                lo: first.clone(),
                hi: first,
            },
            |acc, x| Iv {
                lo: rmin(&acc.lo, x),
                hi: rmax(&acc.hi, x),
            },
        )
    }

    fn add(&self, o: &Iv) -> Iv {
        Iv {
            lo: self.lo.clone() + o.lo.clone(),
            hi: self.hi.clone() + o.hi.clone(),
        }
    }

    fn sub(&self, o: &Iv) -> Iv {
        Iv {
            lo: self.lo.clone() - o.hi.clone(),
            hi: self.hi.clone() - o.lo.clone(),
        }
    }

    fn mul(&self, o: &Iv) -> Iv {
        let p = [
            self.lo.clone() * o.lo.clone(),
            self.lo.clone() * o.hi.clone(),
            self.hi.clone() * o.lo.clone(),
            self.hi.clone() * o.hi.clone(),
        ];
        Iv::hull(p.iter())
    }

    /// `{x² : x ∈ self}`.
    fn sq(&self) -> Iv {
        let (a, b) = (
            self.lo.clone() * self.lo.clone(),
            self.hi.clone() * self.hi.clone(),
        );
        if self.lo <= Rational::ZERO && self.hi >= Rational::ZERO {
            Iv {
                lo: Rational::ZERO,
                hi: rmax(&a, &b),
            }
        } else {
            Iv {
                lo: rmin(&a, &b),
                hi: rmax(&a, &b),
            }
        }
    }

    /// `self / o`, `None` if `0 ∈ o`.
    fn div(&self, o: &Iv) -> Option<Iv> {
        if o.lo <= Rational::ZERO && o.hi >= Rational::ZERO {
            return None;
        }
        let inv = Iv {
            lo: Rational::ONE / o.hi.clone(),
            hi: Rational::ONE / o.lo.clone(),
        };
        Some(self.mul(&inv))
    }

    /// `{max(x, 0)}`.
    fn pos(&self) -> Iv {
        Iv {
            lo: rmax(&self.lo, &Rational::ZERO),
            hi: rmax(&self.hi, &Rational::ZERO),
        }
    }
}

fn iv_dot(a: &[Iv; 3], b: &[Iv; 3]) -> Iv {
    a[0].mul(&b[0]).add(&a[1].mul(&b[1])).add(&a[2].mul(&b[2]))
}

fn iv_cross(a: &[Iv; 3], b: &[Iv; 3]) -> [Iv; 3] {
    [
        a[1].mul(&b[2]).sub(&a[2].mul(&b[1])),
        a[2].mul(&b[0]).sub(&a[0].mul(&b[2])),
        a[0].mul(&b[1]).sub(&a[1].mul(&b[0])),
    ]
}

fn iv_norm_sq(a: &[Iv; 3]) -> Iv {
    a[0].sq().add(&a[1].sq()).add(&a[2].sq())
}

/// Enclosures of the quantities of the module docs on one dyadic parameter interval
/// (`None` where a denominator hull contains 0).
#[derive(Debug)]
struct Tile {
    /// Bernstein coefficients of all polynomials on the interval (blocks of `COUNT`).
    coeffs: Vec<Rational>,
    /// The interval's length.
    h: Rational,
    a: [Iv; 3],
    /// `|A|²`.
    aa: Iv,
    /// `E/W`.
    e: Option<Iv>,
    /// The disc centre `c`.
    c: Option<[Iv; 3]>,
    /// `ρ²` (clipped at 0).
    rho2: Option<Iv>,
    /// `κ²`, `Q`, `g²`, `|ṁ|²` (Lemma A).
    kappa2: Option<Iv>,
    q: Option<Iv>,
    g2: Option<Iv>,
    speed2: Option<Iv>,
    /// `A`, `|A|²`, `E/W`, `c`, `ρ²` in `f64` with outward rounding (the pair tests' filter).
    f: FTile,
}

impl Tile {
    fn new(coeffs: Vec<Rational>, h: Rational) -> Tile {
        let hull = |j: usize| Iv::hull(coeffs.iter().skip(j).step_by(COUNT));
        let ratio = |n: usize, d: usize| hull(n).div(&hull(d));
        let a = [hull(I_A), hull(I_A + 1), hull(I_A + 2)];
        let dc = hull(I_DC);
        let c = match (
            hull(I_NC).div(&dc),
            hull(I_NC + 1).div(&dc),
            hull(I_NC + 2).div(&dc),
        ) {
            (Some(x), Some(y), Some(z)) => Some([x, y, z]),
            _ => None,
        };
        Tile {
            h,
            a,
            aa: hull(I_AA),
            e: ratio(I_E, I_W),
            c,
            rho2: ratio(I_NRHO, I_DRHO).map(|x| x.pos()),
            kappa2: ratio(I_NK, I_DK).map(|x| x.pos()),
            q: ratio(I_NQ, I_DQ),
            g2: ratio(I_NG, I_DRHO).map(|x| x.pos()),
            speed2: ratio(I_AA, I_W4).map(|x| x.pos()),
            f: FTile::default(),
            coeffs,
        }
        .with_f64()
    }
}

/// The exact values of the quantities at one parameter (for [`discs_meet`]).
struct Point {
    a: [Rational; 3],
    aa: Rational,
    e: Rational,
    c: [Rational; 3],
    rho2: Rational,
}

fn point(polys: &[P], t: &Rational) -> Result<Point, CanalError> {
    let v: Vec<Rational> = polys.iter().map(|p| p.eval(t)).collect();
    let nz = |x: &Rational, what: &str| {
        if x.is_zero() {
            Err(CanalError::DegenerateSpine(format!(
                "{what} vanishes at t = {}",
                format_scalar(t)
            )))
        } else {
            Ok(x.clone())
        }
    };
    let w = nz(&v[I_W], "the weight W")?;
    let dc = nz(&v[I_DC], "W|A|² (a zero tangent or a point at infinity)")?;
    let drho = nz(&v[I_DRHO], "W²|A|²")?;
    Ok(Point {
        a: [v[I_A].clone(), v[I_A + 1].clone(), v[I_A + 2].clone()],
        aa: v[I_AA].clone(),
        e: v[I_E].clone() / w,
        c: core::array::from_fn(|i| v[I_NC + i].clone() / dc.clone()),
        rho2: v[I_NRHO].clone() / drho,
    })
}

fn rdot(a: &[Rational; 3], b: &[Rational; 3]) -> Rational {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
}

fn rcross(a: &[Rational; 3], b: &[Rational; 3]) -> [Rational; 3] {
    [
        a[1].clone() * b[2].clone() - a[2].clone() * b[1].clone(),
        a[2].clone() * b[0].clone() - a[0].clone() * b[2].clone(),
        a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone(),
    ]
}

/// `√x + √y ≥ √z` decided exactly for `x, y, z ≥ 0`: `z − x − y ≤ 0` or
/// `(z − x − y)² ≤ 4xy`.
fn sqrt_sum_reaches(x: &Rational, y: &Rational, z: &Rational) -> bool {
    let d = z.clone() - x.clone() - y.clone();
    d <= Rational::ZERO || d.clone() * d <= Rational::from(4) * x.clone() * y.clone()
}

fn discs_meet_at(p: &Point, q: &Point) -> bool {
    let diff: [Rational; 3] = core::array::from_fn(|i| p.c[i].clone() - q.c[i].clone());
    let u = rcross(&p.a, &q.a);
    let phi_pq = rdot(&p.c, &q.a) - q.e.clone(); // centre of Δ(t) in the plane of Δ(s)
    let phi_qp = rdot(&q.c, &p.a) - p.e.clone();
    let (rp, rq) = (
        rmax(&p.rho2, &Rational::ZERO),
        rmax(&q.rho2, &Rational::ZERO),
    );
    if u.iter().all(|x| x.is_zero()) {
        // parallel planes: distinct ones do not meet; in one plane the discs meet iff
        // |c_t − c_s| ≤ ρ_t + ρ_s
        return phi_pq.is_zero() && sqrt_sum_reaches(&rp, &rq, &rdot(&diff, &diff));
    }
    let uu = rdot(&u, &u);
    let ht = rp * uu.clone() - phi_pq.clone() * phi_pq * p.aa.clone();
    let hs = rq * uu - phi_qp.clone() * phi_qp * q.aa.clone();
    if ht < Rational::ZERO || hs < Rational::ZERO {
        return false; // a disc misses the line of the two planes
    }
    let delta = rdot(&diff, &u);
    sqrt_sum_reaches(&ht, &hs, &(delta.clone() * delta))
}

/// Decides exactly whether the closed discs bounded by the characteristic circles at `t`
/// and at `s` meet (module docs; `ρ² < 0`, no real circle, is taken as a point).
///
/// # Errors
/// [`CanalError::DegenerateSpine`] where `W = 0` or `A = 0` (no characteristic plane).
pub fn discs_meet(
    spine: &CanalSpine<Rational>,
    t: &Rational,
    s: &Rational,
) -> Result<bool, CanalError> {
    let p = polys(spine);
    Ok(discs_meet_at(&point(&p, t)?, &point(&p, s)?))
}

// ---------------------------------------------------------------------------------------
// The plane test as one bivariate polynomial, divided by `(s − t)²` on one piece
// (docs/math/pipes.md#canal-global).

/// `p(t, s)/(s − t)` exactly (`None` if `s − t` does not divide `p`): with `p = Σ cⱼ(t) sʲ`,
/// synthetic division `q_{n−1} = c_n`, `q_{j−1} = c_j + t·q_j`, remainder `c₀ + t·q₀`.
fn div_s_minus_t(p: &BiPoly<Rational>) -> Option<BiPoly<Rational>> {
    let c = p.coeffs();
    let Some(n) = c.len().checked_sub(1) else {
        return Some(BiPoly::zero());
    };
    let t = P::x();
    let mut q: Vec<P> = vec![P::zero(); n];
    let mut carry = c[n].clone();
    for j in (1..=n).rev() {
        q[j - 1] = carry.clone();
        carry = &c[j - 1] + &(&t * &carry);
    }
    carry.is_zero().then(|| BiPoly::new(q))
}

/// `G(t, s)` of the plane test for `t` on the piece of `p` and `s` on the piece of `q`
/// (polynomials in the order of [`polys`]): `Δ(t) ∩ Π(s) = ∅` wherever `G > 0`
/// (docs/math/pipes.md#canal-global). With `A`, `B`, `R`, `W` as in the module docs,
///
/// ```text
/// N(t, s) = |A(t)|²[(W(s)M(t) − W(t)M(s))·A(s) + W(t)R(s)B(s)] − R(t)B(t)W(s) A(t)·A(s),
/// G(t, s) = N² − R(t)²(|A(t)|² − B(t)²)·W(s)²·|A(t) × A(s)|²
/// ```
///
/// (`φ_s(c(t))²|A(t)|² − ρ(t)²|A(t) × A(s)|²` times `W(t)²|A(t)|²W(s)² > 0`). For a constant
/// radius (`B ≡ 0`) the common factor `|A(t)|²` is removed:
/// `G = |A(t)|²((W(s)M(t) − W(t)M(s))·A(s))² − R(t)²W(s)²|A(t) × A(s)|²`. On one piece
/// (`same`) `N` and `A(t) × A(s)` vanish at `s = t` and `G/(s − t)²` is returned: it is
/// positive at `s = t` exactly where the local condition holds (the disc misses the line
/// `Π₁ ∩ Π₂`), so boxes touching the diagonal are settled too.
fn plane_poly(p: &PlaneParts, q: &PlaneParts, same: bool) -> Option<BiPoly<Rational>> {
    let t = |x: &P| BiPoly::from_t(x.clone());
    let s = |x: &P| BiPoly::from_u(x);
    let dot_ts = |x: &[P; 3], y: &[P; 3]| -> BiPoly<Rational> {
        (0..3).fold(BiPoly::zero(), |acc, i| acc.add(&t(&x[i]).mul(&s(&y[i]))))
    };
    // (W(s)M(t) − W(t)M(s))·A(s)
    let mdiff = dot_ts(&p.m, &q.a)
        .mul(&s(&q.w))
        .sub(&t(&p.w).mul(&s(&dot(&q.m, &q.a))));
    let pipe = p.rb.is_zero() && q.rb.is_zero();
    let mut n = if pipe {
        mdiff
    } else {
        t(&p.aa)
            .mul(&mdiff.add(&t(&p.w).mul(&s(&q.rb))))
            .sub(&t(&p.rb).mul(&s(&q.w)).mul(&dot_ts(&p.a, &q.a)))
    };
    let mut u: [BiPoly<Rational>; 3] = core::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        t(&p.a[j])
            .mul(&s(&q.a[k]))
            .sub(&t(&p.a[k]).mul(&s(&q.a[j])))
    });
    if same {
        n = div_s_minus_t(&n)?;
        for x in &mut u {
            *x = div_s_minus_t(x)?;
        }
    }
    let uu = u.iter().fold(BiPoly::zero(), |acc, x| acc.add(&x.mul(x)));
    let ws2 = s(&(&q.w * &q.w));
    let lhs = n.mul(&n);
    Some(if pipe {
        t(&p.aa).mul(&lhs).sub(&t(&p.r2).mul(&ws2).mul(&uu))
    } else {
        lhs.sub(&t(&p.nrho).mul(&ws2).mul(&uu))
    })
}

/// The polynomials of one piece that [`plane_poly`] needs.
struct PlaneParts {
    w: P,
    m: [P; 3],
    a: [P; 3],
    /// `|A|²`, `R·B`, `R²`, `R²(|A|² − B²)`.
    aa: P,
    rb: P,
    r2: P,
    nrho: P,
}

impl PlaneParts {
    fn of(spine: &CanalSpine<Rational>) -> PlaneParts {
        let w = spine.weight().clone();
        let wd = w.derivative();
        let m = spine.center_polys().clone();
        let r = spine.radius_poly();
        let a: [P; 3] = core::array::from_fn(|i| &(&w * &m[i].derivative()) - &(&wd * &m[i]));
        let b = &(&w * &r.derivative()) - &(&wd * r);
        let aa = dot(&a, &a);
        let r2 = r * r;
        PlaneParts {
            nrho: &r2 * &(&aa - &(&b * &b)),
            rb: r * &b,
            w,
            m,
            a,
            aa,
            r2,
        }
    }
}

/// How a box was settled.
#[derive(Clone, Copy)]
enum Settled {
    LemmaA,
    Far,
    Plane,
    Chords,
    /// By the plane test's bivariate polynomial ([`plane_poly`]).
    PlanePoly,
}

/// Boxes settled by each [`Settled`] kind, then (last) the bivariate plane tests redone
/// exactly because `f64` did not decide them.
type Counts = [usize; 6];

/// `√x` rounded up (`x ≥ 0`).
fn root_up(x: &Rational) -> Rational {
    if *x <= Rational::ZERO {
        Rational::ZERO
    } else {
        super::regularity::sqrt_upper(x)
    }
}

/// Lemma A over a run of tiles (module docs).
fn lemma_a(tiles: &[Rc<Tile>]) -> bool {
    let mut k2 = Rational::ZERO;
    let mut rho2 = Rational::ZERO;
    let mut g2 = Rational::ZERO;
    let mut length = Rational::ZERO;
    let mut q: Option<Iv> = None;
    for t in tiles {
        let (Some(tk), Some(tr), Some(tg), Some(tq), Some(ts)) =
            (&t.kappa2, &t.rho2, &t.g2, &t.q, &t.speed2)
        else {
            return false;
        };
        k2 = rmax(&k2, &tk.hi);
        rho2 = rmax(&rho2, &tr.hi);
        g2 = rmax(&g2, &tg.hi);
        length += t.h.clone() * root_up(&ts.hi);
        q = Some(match q {
            None => tq.clone(),
            Some(q) => Iv {
                lo: rmin(&q.lo, &tq.lo),
                hi: rmax(&q.hi, &tq.hi),
            },
        });
    }
    let Some(q) = q else { return false };
    let kappa = root_up(&k2);
    let half = Rational::from_ratio(1, 2);
    let e = root_up(&rho2) + kappa.clone() * length.clone() * (root_up(&g2) + length * half);
    let bend = kappa * e;
    bend.clone() + q.hi < Rational::ONE || q.lo - bend > Rational::ONE
}

/// An interval `[lo, hi]` of `f64` that contains the exact one: every operation is rounded
/// to nearest and its ends moved one step outward (round to nearest is within half a unit in
/// the last place; N. J. Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed.,
/// 2002, §2.2); a `NaN` (from `∞ − ∞` or `0·∞`) widens to `[−∞, ∞]`.
#[derive(Debug, Clone, Copy)]
struct FIv {
    lo: f64,
    hi: f64,
}

const FIV_ALL: FIv = FIv {
    lo: f64::NEG_INFINITY,
    hi: f64::INFINITY,
};

impl FIv {
    fn of(x: &Iv) -> FIv {
        FIv {
            lo: f64_below(&x.lo),
            hi: f64_above(&x.hi),
        }
    }

    fn out(lo: f64, hi: f64) -> FIv {
        if lo.is_nan() || hi.is_nan() {
            FIV_ALL
        } else {
            FIv {
                lo: lo.next_down(),
                hi: hi.next_up(),
            }
        }
    }

    fn add(self, o: FIv) -> FIv {
        FIv::out(self.lo + o.lo, self.hi + o.hi)
    }

    fn sub(self, o: FIv) -> FIv {
        FIv::out(self.lo - o.hi, self.hi - o.lo)
    }

    fn mul(self, o: FIv) -> FIv {
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        if p.iter().any(|x| x.is_nan()) {
            return FIV_ALL;
        }
        FIv::out(
            p.iter().fold(f64::INFINITY, |m, x| m.min(*x)),
            p.iter().fold(f64::NEG_INFINITY, |m, x| m.max(*x)),
        )
    }

    fn sq(self) -> FIv {
        let (a, b) = (self.lo * self.lo, self.hi * self.hi);
        if self.lo <= 0.0 && self.hi >= 0.0 {
            FIv::out(0.0, a.max(b)).pos()
        } else {
            FIv::out(a.min(b), a.max(b)).pos()
        }
    }

    fn pos(self) -> FIv {
        FIv {
            lo: self.lo.max(0.0),
            hi: self.hi.max(0.0),
        }
    }
}

fn fiv_dot(a: &[FIv; 3], b: &[FIv; 3]) -> FIv {
    a[0].mul(b[0]).add(a[1].mul(b[1])).add(a[2].mul(b[2]))
}

fn fiv_cross(a: &[FIv; 3], b: &[FIv; 3]) -> [FIv; 3] {
    [
        a[1].mul(b[2]).sub(a[2].mul(b[1])),
        a[2].mul(b[0]).sub(a[0].mul(b[2])),
        a[0].mul(b[1]).sub(a[1].mul(b[0])),
    ]
}

fn fiv_norm_sq(a: &[FIv; 3]) -> FIv {
    a[0].sq().add(a[1].sq()).add(a[2].sq())
}

/// The enclosures of a [`Tile`] that the pair tests use, in `f64` (outward).
#[derive(Debug, Default)]
struct FTile {
    a: Option<[FIv; 3]>,
    aa: Option<FIv>,
    e: Option<FIv>,
    c: Option<[FIv; 3]>,
    rho2: Option<FIv>,
}

impl Tile {
    fn with_f64(mut self) -> Tile {
        let v3 = |x: &[Iv; 3]| [FIv::of(&x[0]), FIv::of(&x[1]), FIv::of(&x[2])];
        self.f = FTile {
            a: Some(v3(&self.a)),
            aa: Some(FIv::of(&self.aa)),
            e: self.e.as_ref().map(FIv::of),
            c: self.c.as_ref().map(v3),
            rho2: self.rho2.as_ref().map(FIv::of),
        };
        self
    }
}

/// `√x` rounded up in `f64` (`x ≥ 0`; `sqrt` is correctly rounded).
fn f64_root_up(x: f64) -> f64 {
    if x <= 0.0 {
        0.0
    } else {
        x.sqrt().next_up()
    }
}

/// [`pair_tests`] in `f64` interval arithmetic with outward rounding: a test that holds here
/// holds for the exact enclosures as well (they lie inside), so a box settled here is
/// settled by the same statement; `None` leaves the box to the exact tests.
fn pair_tests_f64(ti: &Tile, tj: &Tile) -> Option<Settled> {
    let (fi, fj) = (&ti.f, &tj.f);
    let (ci, cj) = (fi.c.as_ref()?, fj.c.as_ref()?);
    let (ri, rj) = (fi.rho2?, fj.rho2?);
    let (ei, ej) = (fi.e?, fj.e?);
    let (ai, aj) = (fi.a.as_ref()?, fj.a.as_ref()?);
    let (aai, aaj) = (fi.aa?, fj.aa?);
    let diff: [FIv; 3] = core::array::from_fn(|k| ci[k].sub(cj[k]));
    let reach = (f64_root_up(ri.hi) + f64_root_up(rj.hi)).next_up();
    if fiv_norm_sq(&diff).lo > (reach * reach).next_up() {
        return Some(Settled::Far);
    }
    let u = fiv_cross(ai, aj);
    let uu = fiv_norm_sq(&u);
    let pij2 = fiv_dot(ci, aj).sub(ej).sq();
    let pji2 = fiv_dot(cj, ai).sub(ei).sq();
    let down = |x: f64, y: f64| (x * y).next_down();
    let up = |x: f64, y: f64| (x * y).next_up();
    if down(pij2.lo, aai.lo) > up(ri.hi, uu.hi) || down(pji2.lo, aaj.lo) > up(rj.hi, uu.hi) {
        return Some(Settled::Plane);
    }
    let ht = ri.mul(uu).sub(pij2.mul(aai)).pos().hi;
    let hs = rj.mul(uu).sub(pji2.mul(aaj)).pos().hi;
    let x = ((fiv_dot(&diff, &u).sq().lo - ht).next_down() - hs).next_down();
    if x > 0.0 && down(x, x) > up(up(4.0, ht), hs) {
        return Some(Settled::Chords);
    }
    None
}

/// The per-pair tests (far, plane, chords) on `I × J` (module docs).
fn pair_tests(ti: &Tile, tj: &Tile) -> Option<Settled> {
    let (ci, cj) = (ti.c.as_ref()?, tj.c.as_ref()?);
    let (ri, rj) = (ti.rho2.as_ref()?, tj.rho2.as_ref()?);
    let (ei, ej) = (ti.e.as_ref()?, tj.e.as_ref()?);
    let diff: [Iv; 3] = core::array::from_fn(|k| ci[k].sub(&cj[k]));
    // far
    let reach = root_up(&ri.hi) + root_up(&rj.hi);
    if iv_norm_sq(&diff).lo > reach.clone() * reach {
        return Some(Settled::Far);
    }
    // a disc misses the other's plane
    let u = iv_cross(&ti.a, &tj.a);
    let uu_hi = iv_norm_sq(&u).hi;
    let phi_ij = iv_dot(ci, &tj.a).sub(ej); // c(t) in the plane of s
    let phi_ji = iv_dot(cj, &ti.a).sub(ei);
    let (pij2, pji2) = (phi_ij.sq(), phi_ji.sq());
    if pij2.lo.clone() * ti.aa.lo.clone() > ri.hi.clone() * uu_hi.clone()
        || pji2.lo.clone() * tj.aa.lo.clone() > rj.hi.clone() * uu_hi.clone()
    {
        return Some(Settled::Plane);
    }
    // disjoint chords on the line of the planes
    let uu = iv_norm_sq(&u);
    let ht = ri.mul(&uu).sub(&pij2.mul(&ti.aa)).pos().hi;
    let hs = rj.mul(&uu).sub(&pji2.mul(&tj.aa)).pos().hi;
    let x = iv_dot(&diff, &u).sq().lo - ht.clone() - hs.clone();
    if x > Rational::ZERO && x.clone() * x > Rational::from(4) * ht * hs {
        return Some(Settled::Chords);
    }
    None
}

/// One spine piece of the subdivision: its polynomials and the tiles computed so far.
struct PieceSearch {
    /// The piece's index in the chain.
    index: usize,
    a: Rational,
    width: Rational,
    polys: Vec<P>,
    /// What [`plane_poly`] needs.
    parts: PlaneParts,
    tiles: HashMap<(u32, u64), Rc<Tile>>,
}

impl PieceSearch {
    fn new(index: usize, spine: &CanalSpine<Rational>, a: &Rational, b: &Rational) -> PieceSearch {
        PieceSearch {
            index,
            a: a.clone(),
            width: b.clone() - a.clone(),
            polys: polys(spine),
            parts: PlaneParts::of(spine),
            tiles: HashMap::new(),
        }
    }

    fn param(&self, level: u32, k: u64) -> Rational {
        self.a.clone() + self.width.clone() * Rational::from(k) / Rational::from(1u64 << level)
    }

    fn tile(&mut self, level: u32, k: u64) -> Rc<Tile> {
        if let Some(t) = self.tiles.get(&(level, k)) {
            return t.clone();
        }
        let coeffs = if level == 0 {
            self.root_coeffs()
        } else {
            let parent = self.tile(level - 1, k / 2);
            let (l, r) = subdivide_blocks(&parent.coeffs, COUNT, &Rational::from_ratio(1, 2));
            if k.is_multiple_of(2) {
                l
            } else {
                r
            }
        };
        let h = self.width.clone() / Rational::from(1u64 << level);
        let t = Rc::new(Tile::new(coeffs, h));
        self.tiles.insert((level, k), t.clone());
        t
    }

    /// The Bernstein coefficients of all polynomials on `[a, a + width]` (common degree).
    fn root_coeffs(&self) -> Vec<Rational> {
        let lin = Poly::new(vec![self.a.clone(), self.width.clone()]);
        let moved: Vec<P> = self.polys.iter().map(|p| p.compose(&lin)).collect();
        let n = moved.iter().filter_map(Poly::degree).max().unwrap_or(0);
        let mut power = vec![Rational::ZERO; (n + 1) * COUNT];
        for (j, p) in moved.iter().enumerate() {
            for (i, c) in p.coeffs().iter().enumerate() {
                power[i * COUNT + j] = c.clone();
            }
        }
        // degree n ≥ every polynomial's degree: cannot fail
        to_bernstein_blocks(&power, COUNT, n).unwrap_or_default()
    }
}

/// [`plane_poly`] of a pair of pieces with its `f64` tensor on their whole box (`None`:
/// not available).
type PlanePoly = Option<(BiPoly<Rational>, FTensor)>;

/// A dyadic interval of one piece at the current level: `(piece, index)`.
type Key = (usize, u64);

/// Longest run of tiles Lemma A is tried on (longer runs cannot pass).
const LEMMA_A_RUN: usize = 8;

/// The subdivision state of a chain of pieces (one piece for a single spine).
struct Search {
    pieces: Vec<PieceSearch>,
    /// `smooth[k]`: Lemma A runs across the joint of pieces `k` and `k + 1`.
    smooth: Vec<bool>,
    /// The end of the last piece is joined smoothly to the start of the first (a closed
    /// spine: Lemma A runs across the seam).
    closed: bool,
    /// Name the piece in intervals (a chain of more than one piece).
    named: bool,
    /// [`plane_poly`] of each ordered pair of pieces (`None`: not available) with its
    /// exact Bernstein coefficients on the pair's whole box, in `f64` with an error bound.
    planes: HashMap<(usize, usize), PlanePoly>,
    /// The `f64` tensors of boxes `(level, t-interval, s-interval)`, by halving.
    boxes: HashMap<(u32, Key, Key), FTensor>,
    /// Boxes whose bivariate plane test was not decided in `f64` and was redone exactly.
    exact_boxes: usize,
}

impl Search {
    fn interval(&self, level: u32, (p, k): Key) -> String {
        let piece = &self.pieces[p];
        let iv = format!(
            "[{}, {}]",
            format_scalar(&piece.param(level, k)),
            format_scalar(&piece.param(level, k + 1))
        );
        if self.named {
            format!("{iv} (spine piece {})", piece.index)
        } else {
            iv
        }
    }

    fn centre(&self, level: u32, (p, k): Key) -> Rational {
        let piece = &self.pieces[p];
        (piece.param(level, k) + piece.param(level, k + 1)) * Rational::from_ratio(1, 2)
    }

    /// The tiles from `from` forward to `to` (through joints that are smooth, and through
    /// the seam of a closed spine), `None` if longer than [`LEMMA_A_RUN`] or blocked.
    fn run(&mut self, level: u32, from: Key, to: Key) -> Option<Vec<Rc<Tile>>> {
        let per = 1u64 << level;
        let mut cur = from;
        let mut out = vec![self.pieces[cur.0].tile(level, cur.1)];
        while cur != to {
            if out.len() >= LEMMA_A_RUN {
                return None;
            }
            cur = if cur.1 + 1 < per {
                (cur.0, cur.1 + 1)
            } else if cur.0 + 1 < self.pieces.len() {
                if !self.smooth.get(cur.0).copied().unwrap_or(false) {
                    return None;
                }
                (cur.0 + 1, 0)
            } else if self.closed {
                (0, 0)
            } else {
                return None;
            };
            out.push(self.pieces[cur.0].tile(level, cur.1));
        }
        Some(out)
    }

    /// [`plane_poly`] of the pieces `(k, l)` and its tensor on their whole box.
    fn plane(&mut self, k: usize, l: usize) -> PlanePoly {
        if let Some(p) = self.planes.get(&(k, l)) {
            return p.clone();
        }
        let (pk, pl) = (&self.pieces[k], &self.pieces[l]);
        let out = plane_poly(&pk.parts, &pl.parts, k == l).and_then(|g| {
            let (m, n) = (g.degree_t()?, g.degree_u()?);
            let (tb, sb) = (
                pk.a.clone() + pk.width.clone(),
                pl.a.clone() + pl.width.clone(),
            );
            let c = g.bernstein_on((&pk.a, &tb), (&pl.a, &sb), m, n).ok()?;
            Some((g, FTensor::of(&c, m, n)))
        });
        self.planes.insert((k, l), out.clone());
        out
    }

    /// The `f64` tensor of [`plane_poly`] on the box `t ∈ x`, `s ∈ y` at `level`.
    fn plane_tensor(&mut self, level: u32, x: Key, y: Key) -> Option<FTensor> {
        if level == 0 {
            return self.plane(x.0, y.0).map(|p| p.1);
        }
        if let Some(f) = self.boxes.get(&(level, x, y)) {
            return Some(f.clone());
        }
        let (px, py) = ((x.0, x.1 / 2), (y.0, y.1 / 2));
        let quarters = self.plane_tensor(level - 1, px, py)?.quarters();
        let mut out = None;
        for (q, f) in quarters.into_iter().enumerate() {
            let key = (x.0, 2 * px.1 + (q as u64 >> 1));
            let kez = (y.0, 2 * py.1 + (q as u64 & 1));
            if (key, kez) == (x, y) {
                out = Some(f.clone());
            }
            self.boxes.insert((level, key, kez), f);
        }
        out
    }

    /// `Δ(t) ∩ Π(s) = ∅` for all `t ∈ x`, `s ∈ y` (`s ≠ t`) by the signs of the Bernstein
    /// coefficients of [`plane_poly`]: in `f64` with a proven error bound, exactly where
    /// that does not decide.
    fn plane_box(&mut self, level: u32, x: Key, y: Key) -> bool {
        match self
            .plane_tensor(level, x, y)
            .map_or(Tri::Unsure, |f| f.all_pos())
        {
            Tri::Yes => true,
            Tri::No => false,
            Tri::Unsure => {
                let Some((g, f)) = self.plane(x.0, y.0) else {
                    return false;
                };
                let (px, py) = (&self.pieces[x.0], &self.pieces[y.0]);
                let (t0, t1) = (px.param(level, x.1), px.param(level, x.1 + 1));
                let (s0, s1) = (py.param(level, y.1), py.param(level, y.1 + 1));
                // a corner coefficient is the value there: one ≤ 0 (e.g. G = 0 at a joint)
                // disproves the test without the whole tensor
                let corners = [(&t0, &s0), (&t0, &s1), (&t1, &s0), (&t1, &s1)];
                if corners
                    .iter()
                    .any(|(t, s)| g.sign_at(t, s) != Some(core::cmp::Ordering::Greater))
                {
                    return false;
                }
                self.exact_boxes += 1;
                g.bernstein_on((&t0, &t1), (&s0, &s1), f.m, f.n)
                    .is_ok_and(|c| c.iter().all(|v| *v > Rational::ZERO))
            }
        }
    }

    /// Forgets the `f64` tensors of levels below `level − 1` (no longer needed breadth
    /// first).
    fn forget_below(&mut self, level: u32) {
        self.boxes.retain(|k, _| k.0 + 1 >= level);
    }

    /// Tests the box `x × y`, `x ≤ y` (lexicographic).
    fn settle(&mut self, level: u32, x: Key, y: Key) -> Option<Settled> {
        if x != y {
            let (tx, ty) = (
                self.pieces[x.0].tile(level, x.1),
                self.pieces[y.0].tile(level, y.1),
            );
            if let Some(s) = pair_tests_f64(&tx, &ty).or_else(|| pair_tests(&tx, &ty)) {
                return Some(s);
            }
        }
        // Lemma A over the stretch from x to y (and, on a closed spine, from y through the
        // seam to x)
        if let Some(run) = self.run(level, x, y) {
            if lemma_a(&run) {
                return Some(Settled::LemmaA);
            }
        }
        if self.closed && x != y {
            if let Some(run) = self.run(level, y, x) {
                if lemma_a(&run) {
                    return Some(Settled::LemmaA);
                }
            }
        }
        // a disc misses the other's plane, by one bivariate polynomial (either way round)
        if self.plane_box(level, x, y) || (x != y && self.plane_box(level, y, x)) {
            return Some(Settled::PlanePoly);
        }
        None
    }
}

/// The values at `t` that decide how two pieces join: `m`, `r²`, `A` and `RB/W`
/// (`g = RB/(W|A|)`), `None` where `W = 0`.
fn end_values(
    spine: &CanalSpine<Rational>,
    t: &Rational,
) -> Option<([Rational; 3], Rational, [Rational; 3], Rational)> {
    let w = spine.weight().eval(t);
    if w.is_zero() {
        return None;
    }
    let wd = spine.weight().derivative().eval(t);
    let mp = spine.center_polys();
    let a: [Rational; 3] = core::array::from_fn(|i| {
        w.clone() * mp[i].derivative().eval(t) - wd.clone() * mp[i].eval(t)
    });
    let m: [Rational; 3] = core::array::from_fn(|i| mp[i].eval(t) / w.clone());
    let rr = spine.radius_poly().eval(t);
    let b = w.clone() * spine.radius_poly().derivative().eval(t) - wd * rr.clone();
    let r = rr.clone() / w.clone();
    Some((m, r.clone() * r, a, rr * b / w))
}

/// Why the characteristic discs of a chain do not run on smoothly across a joint
/// ([`canal_joint_defect`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JointDefect {
    /// A weight vanishes at an end (a point at infinity) or a tangent is zero.
    Degenerate,
    /// The spine points differ (a gap).
    Gap,
    /// The spheres have different radii (`r²` jumps).
    RadiusJump,
    /// The tangent directions differ (a corner, or a reversal).
    Corner,
    /// `g = r dr/dσ` (the radius's slope along arc length, times `r`) jumps.
    SlopeJump,
}

impl core::fmt::Display for JointDefect {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            JointDefect::Degenerate => "a weight or a tangent vanishes at an end",
            JointDefect::Gap => "the spine ends do not meet (a gap)",
            JointDefect::RadiusJump => "the spheres there have different radii (r² jumps)",
            JointDefect::Corner => {
                "the spine's tangent directions differ (a corner: the surfaces would overlap on its inner side)"
            }
            JointDefect::SlopeJump => {
                "the radius changes at different rates along the spine on the two sides (r dr/dσ jumps)"
            }
        })
    }
}

/// Whether the characteristic discs run on smoothly from `first` at `t` to `second` at `s`
/// (`None`) or why not: the same sphere (`m`, `r²`), tangents in the same direction
/// (`A(t) = λA(s)`, `λ > 0`) and the same `g = r dr/dσ` (`RB/W` at `t` equal to `λ·RB/W`
/// at `s`) — what Lemma A needs to run across the joint, decided exactly
/// (docs/math/pipes.md#canal-global, "Chains and closed spines").
pub fn canal_joint_defect(
    first: &CanalSpine<Rational>,
    t: &Rational,
    second: &CanalSpine<Rational>,
    s: &Rational,
) -> Option<JointDefect> {
    let (Some((m1, r1, a1, g1)), Some((m2, r2, a2, g2))) =
        (end_values(first, t), end_values(second, s))
    else {
        return Some(JointDefect::Degenerate);
    };
    let aa2 = rdot(&a2, &a2);
    if m1 != m2 {
        return Some(JointDefect::Gap);
    }
    if r1 != r2 {
        return Some(JointDefect::RadiusJump);
    }
    if aa2.is_zero() || rdot(&a1, &a1).is_zero() {
        return Some(JointDefect::Degenerate);
    }
    if rcross(&a1, &a2).iter().any(|x| !x.is_zero()) {
        return Some(JointDefect::Corner);
    }
    let lambda = rdot(&a1, &a2) / aa2;
    if lambda <= Rational::ZERO {
        return Some(JointDefect::Corner);
    }
    (g1 != lambda * g2).then_some(JointDefect::SlopeJump)
}

fn joins_smoothly(
    first: &CanalSpine<Rational>,
    t: &Rational,
    second: &CanalSpine<Rational>,
    s: &Rational,
) -> bool {
    canal_joint_defect(first, t, second, s).is_none()
}

/// The result of one subdivision run.
enum Outcome {
    /// Every box settled: the number of boxes and how (by [`Settled`]).
    Certified(usize, Counts),
    /// The discs at the exact centre pair `(t, s)` of the box `first × second` meet.
    Meet {
        first: String,
        second: String,
        t: Rational,
        s: Rational,
    },
    /// The box `first × second` is unsettled at the limits.
    Undecided {
        first: String,
        second: String,
        boxes: usize,
    },
}

/// The breadth-first subdivision of the pairs of parameters of `search` (module docs).
fn subdivide(search: &mut Search, limits: (u32, usize)) -> Result<Outcome, CanalError> {
    let (max_depth, max_boxes) = limits;
    let n = search.pieces.len();
    let mut queue: VecDeque<(u32, Key, Key)> = VecDeque::new();
    for p in 0..n {
        for q in p..n {
            queue.push_back((0, (p, 0), (q, 0)));
        }
    }
    let mut counts: Counts = [0; 6];
    let mut boxes = 0usize;
    let mut current = 0u32;
    while let Some((level, x, y)) = queue.pop_front() {
        rcagd_algebra::budget::checkpoint();
        boxes += 1;
        if level > current {
            current = level;
            search.forget_below(level);
        }
        if let Some(how) = search.settle(level, x, y) {
            counts[how as usize] += 1;
            continue;
        }
        if x != y {
            // an exact witness at the centre pair
            let (t, s) = (search.centre(level, x), search.centre(level, y));
            let pt = point(&search.pieces[x.0].polys, &t)?;
            let ps = point(&search.pieces[y.0].polys, &s)?;
            if discs_meet_at(&pt, &ps) {
                return Ok(Outcome::Meet {
                    first: search.interval(level, x),
                    second: search.interval(level, y),
                    t,
                    s,
                });
            }
        }
        if level >= max_depth || boxes + queue.len() + 4 > max_boxes {
            return Ok(Outcome::Undecided {
                first: search.interval(level, x),
                second: search.interval(level, y),
                boxes,
            });
        }
        let l = level + 1;
        let (x0, x1) = ((x.0, 2 * x.1), (x.0, 2 * x.1 + 1));
        let (y0, y1) = ((y.0, 2 * y.1), (y.0, 2 * y.1 + 1));
        if x == y {
            queue.extend([(l, x0, x0), (l, x0, x1), (l, x1, x1)]);
        } else {
            queue.extend([(l, x0, y0), (l, x0, y1), (l, x1, y0), (l, x1, y1)]);
        }
    }
    counts[5] = search.exact_boxes;
    Ok(Outcome::Certified(boxes, counts))
}

fn settled_text(boxes: usize, counts: Counts) -> String {
    let [lemma, far, plane, chords, poly, exact] = counts;
    format!("{boxes} boxes of parameter pairs examined, {lemma} settled by Lemma A with varying radius (κ_max(ρ_max + κ_max L(g_max + L/2)) + Q_max < 1 or Q_min − … > 1 over the stretch), {far} by |c(t) − c(s)| > ρ(t) + ρ(s), {plane} because a disc misses the other's plane, {chords} by disjoint chords on the line of the two planes; exact rational interval bounds from Bernstein coefficients; {poly} because a disc misses the other's plane by the signs of the tensor Bernstein coefficients of one bivariate polynomial (divided by (s − t)² on one piece; in f64 with a proven error bound, {exact} redone exactly) (docs/math/pipes.md#canal-global)")
}

/// Decides exactly that the closed discs bounded by the characteristic circles of the canal
/// surface of `spine` at distinct parameters of `[a, b]` are pairwise disjoint — the surface
/// (a union of these circles) has no self-intersection — and returns the certificate
/// (module docs; docs/math/pipes.md#canal-global). Any radius: for a constant one it is the
/// pipe's statement of [`super::check_pipe_embedded`] (normal discs of radius `|r|`), decided
/// by other tests. A spine whose discs at `a` and `b` coincide and run on smoothly (the same
/// sphere, tangent direction and `r dr/dσ`) is closed: `a` and `b` are one parameter and
/// Lemma A runs across the seam; otherwise the discs at `a` and `b` count as distinct.
///
/// The local condition ([`super::check_canal_regularity`]) is checked first.
///
/// # Errors
/// The errors of [`super::check_canal_regularity`] and
/// [`CanalSpine::check_real_envelope`]; [`CanalError::CanalSelfIntersects`] naming the two
/// parameter intervals whose discs meet with an exact witness pair;
/// [`CanalError::CanalPartsNotApart`] (undecided) naming a box of two intervals that the
/// subdivision could not settle within [`CANAL_GLOBAL_DEPTH`] halvings and
/// [`CANAL_GLOBAL_BOXES`] boxes.
pub fn check_canal_embedded(
    spine: &CanalSpine<Rational>,
    domain: (&Rational, &Rational),
) -> Result<Certificate, CanalError> {
    check_canal_embedded_within(spine, domain, (CANAL_GLOBAL_DEPTH, CANAL_GLOBAL_BOXES))
}

/// [`check_canal_embedded`] with other limits `(halvings, boxes)` of the subdivision.
///
/// # Errors
/// As [`check_canal_embedded`].
pub fn check_canal_embedded_within(
    spine: &CanalSpine<Rational>,
    domain: (&Rational, &Rational),
    limits: (u32, usize),
) -> Result<Certificate, CanalError> {
    let (a, b) = domain;
    if a == b {
        spine.check_real_envelope(Some((a, b)))?;
        super::regularity::check_canal_regularity(spine, (a, b))?;
        return Ok(Certificate::holds(
            format!("one characteristic circle (t = {})", format_scalar(a)),
            true,
        ));
    }
    check_canal_chain_embedded_within(&[(spine.clone(), (a.clone(), b.clone()))], limits)
}

/// [`check_canal_embedded`] for a chain of pieces (each a canal family on its own domain
/// `[a_k, b_k]`, `a_k < b_k`), joined end to start: no two characteristic discs at distinct
/// points of the chain meet. Lemma A runs across a joint where the discs run on smoothly
/// (the same sphere, tangent direction and `r dr/dσ`; then the discs of the two ends are one
/// disc), and across the seam when the end of the last piece joins the start of the first
/// so (a closed chain). A joint that is not smooth (a corner, a jump of the radius, a gap)
/// cuts the chain into runs that are checked each on its own; pairs in different runs are
/// not checked and the certificate then fails, saying so (as
/// [`super::check_chain_embedded`] does for pipes).
///
/// # Errors
/// As [`check_canal_embedded`] (the intervals name their piece);
/// [`CanalError::InvalidArgument`] for an empty chain or an empty domain;
/// [`CanalError::SpinePiece`] around the local errors of a piece.
pub fn check_canal_chain_embedded(
    chain: &[(CanalSpine<Rational>, (Rational, Rational))],
) -> Result<Certificate, CanalError> {
    check_canal_chain_embedded_within(chain, (CANAL_GLOBAL_DEPTH, CANAL_GLOBAL_BOXES))
}

/// [`check_canal_chain_embedded`] with other limits `(halvings, boxes)`.
///
/// # Errors
/// As [`check_canal_chain_embedded`].
pub fn check_canal_chain_embedded_within(
    chain: &[(CanalSpine<Rational>, (Rational, Rational))],
    limits: (u32, usize),
) -> Result<Certificate, CanalError> {
    let n = chain.len();
    if n == 0 {
        return Err(CanalError::InvalidArgument("no spine piece".into()));
    }
    for (k, (spine, (a, b))) in chain.iter().enumerate() {
        if a >= b {
            return Err(CanalError::InvalidArgument(format!(
                "empty parameter interval [{}, {}]",
                format_scalar(a),
                format_scalar(b)
            )));
        }
        let local = || -> Result<(), CanalError> {
            spine.check_real_envelope(Some((a, b)))?;
            super::regularity::check_canal_regularity(spine, (a, b))?;
            Ok(())
        };
        local().map_err(|e| {
            if n > 1 {
                CanalError::SpinePiece {
                    index: k,
                    source: Box::new(e),
                }
            } else {
                e
            }
        })?;
    }
    let smooth: Vec<bool> = (0..n - 1)
        .map(|k| {
            joins_smoothly(
                &chain[k].0,
                &chain[k].1 .1,
                &chain[k + 1].0,
                &chain[k + 1].1 .0,
            )
        })
        .collect();
    let closed = smooth.iter().all(|s| *s)
        && joins_smoothly(
            &chain[n - 1].0,
            &chain[n - 1].1 .1,
            &chain[0].0,
            &chain[0].1 .0,
        );
    // runs of smoothly joined pieces
    let mut runs: Vec<(usize, usize)> = Vec::new();
    let mut start = 0;
    for k in 0..n {
        if smooth.get(k).is_none_or(|s| !*s) {
            runs.push((start, k));
            start = k + 1;
        }
    }
    let mut total = 0usize;
    let mut counts: Counts = [0; 6];
    for &(first, last) in &runs {
        let mut search = Search {
            pieces: chain[first..=last]
                .iter()
                .enumerate()
                .map(|(k, (s, (a, b)))| PieceSearch::new(first + k, s, a, b))
                .collect(),
            smooth: smooth[first..last].to_vec(),
            closed: closed && runs.len() == 1,
            named: n > 1,
            planes: HashMap::new(),
            boxes: HashMap::new(),
            exact_boxes: 0,
        };
        match subdivide(&mut search, limits)? {
            Outcome::Certified(b, c) => {
                total += b;
                for (sum, x) in counts.iter_mut().zip(c) {
                    *sum += x;
                }
            }
            Outcome::Meet {
                first: f,
                second,
                t,
                s,
            } => {
                return Err(CanalError::CanalSelfIntersects {
                    first: f,
                    second,
                    t: format_scalar(&t),
                    s: format_scalar(&s),
                })
            }
            Outcome::Undecided {
                first: f,
                second,
                boxes,
            } => {
                return Err(CanalError::CanalPartsNotApart {
                    first: f,
                    second,
                    boxes: total + boxes,
                })
            }
        }
    }
    let what = "the closed discs bounded by the characteristic circles at distinct points";
    let domain = if n == 1 {
        format!(
            "t ∈ [{}, {}]{}",
            format_scalar(&chain[0].1 .0),
            format_scalar(&chain[0].1 .1),
            if closed {
                ", a closed spine: t = a and t = b are one point"
            } else {
                ""
            }
        )
    } else {
        format!(
            "{n} spine pieces, {}",
            if closed { "closed" } else { "open" }
        )
    };
    if runs.len() > 1 {
        let cut: Vec<String> = (0..n - 1)
            .filter(|&k| !smooth[k])
            .map(|k| format!("{k}/{}", k + 1))
            .collect();
        return Ok(Certificate::fails(
            format!("{what} ({domain}) are pairwise disjoint (the canal surface has no self-intersection)"),
            format!(
                "checked within each smoothly joined run of pieces ({total} boxes), not between runs: the joints {} are not smooth (another sphere, tangent direction or r dr/dσ on the two sides, or a gap)",
                cut.join(", ")
            ),
            true,
        ));
    }
    Ok(Certificate::holds(
        format!(
            "{what} ({domain}) are pairwise disjoint (the canal surface has no self-intersection): {}",
            settled_text(total, counts)
        ),
        true,
    ))
}

/// Most boxes [`parameter_range`] subdivides the rectangle into.
const RANGE_BOXES: usize = 2048;

/// Bounds of the spine parameter `p = N/Dn` over a rectangle of Ω(s, t): `inner` between
/// exact values of `p` at points of the rectangle (so `inner ⊆ p(rectangle)`, an interval
/// since the rectangle is connected and `Dn ≠ 0` there), `outer ⊇ p(rectangle)` with dyadic
/// ends.
struct ParamRange {
    inner: (Rational, Rational),
    outer: (Rational, Rational),
    boxes: usize,
}

/// [`ParamRange`] by exact tensor Bernstein coefficients: on a box where those of `Dn` have
/// one strict sign, `p` is a rational Bézier function with control values `N_k/Dn_k` and
/// weights `Dn_k`, so it lies between the least and the largest `N_k/Dn_k` (convex hull); a
/// corner coefficient is a value, so the corners' `N/Dn` are exact values of `p`. Boxes
/// whose hull reaches farther than `(inner width)/2¹⁶` beyond the inner bounds are
/// quartered, at most [`RANGE_BOXES`] boxes (docs/math/pipes.md#canal-global, "On a
/// rectangle of the cyclographic parametrization").
fn parameter_range(
    num: &BiPoly<Rational>,
    den: &BiPoly<Rational>,
    rect: &[Rational; 4],
) -> Result<ParamRange, CanalError> {
    let m = num.degree_t().unwrap_or(0).max(den.degree_t().unwrap_or(0));
    let n = num.degree_u().unwrap_or(0).max(den.degree_u().unwrap_or(0));
    let value = |s: &Rational, t: &Rational| -> Result<Rational, CanalError> {
        let d = den.eval(s, t);
        if d.is_zero() {
            return Err(CanalError::InvalidArgument(format!(
                "the spine parameter p = N/Dn of Γ is infinite at (s, t) = ({}, {}) of the rectangle",
                format_scalar(s),
                format_scalar(t)
            )));
        }
        Ok(num.eval(s, t) / d)
    };
    let corners = [
        value(&rect[0], &rect[2])?,
        value(&rect[0], &rect[3])?,
        value(&rect[1], &rect[2])?,
        value(&rect[1], &rect[3])?,
    ];
    let mut inner = Iv::hull(corners.iter());
    let two = Rational::from(2);
    let mut todo: VecDeque<[Rational; 4]> = VecDeque::from([rect.clone()]);
    let mut done: Vec<Iv> = Vec::new();
    let mut boxes = 0usize;
    let mut tol: Option<Rational> = None;
    while let Some(b) = todo.pop_front() {
        rcagd_algebra::budget::checkpoint();
        boxes += 1;
        let [s0, s1, t0, t1] = &b;
        let cn = num.bernstein_on((s0, s1), (t0, t1), m, n)?;
        let cd = den.bernstein_on((s0, s1), (t0, t1), m, n)?;
        for k in [0, n, m * (n + 1), m * (n + 1) + n] {
            if let (Some(x), Some(d)) = (cn.get(k), cd.get(k)) {
                if !d.is_zero() {
                    let v = x.clone() / d.clone();
                    inner = Iv {
                        lo: rmin(&inner.lo, &v),
                        hi: rmax(&inner.hi, &v),
                    };
                }
            }
        }
        let signed =
            cd.iter().all(|d| *d > Rational::ZERO) || cd.iter().all(|d| *d < Rational::ZERO);
        let hull = signed.then(|| {
            let ratios: Vec<Rational> = cn
                .iter()
                .zip(&cd)
                .map(|(x, d)| x.clone() / d.clone())
                .collect();
            Iv::hull(ratios.iter())
        });
        let tol = tol
            .get_or_insert_with(|| {
                let w = inner.hi.clone() - inner.lo.clone();
                let w = match (&hull, w.is_zero()) {
                    (Some(h), true) => h.hi.clone() - h.lo.clone(),
                    _ => w,
                };
                w / Rational::from(1u64 << 16)
            })
            .clone();
        let fine = hull.as_ref().is_some_and(|h| {
            h.lo >= inner.lo.clone() - tol.clone() && h.hi <= inner.hi.clone() + tol.clone()
        });
        if fine || (hull.is_some() && boxes + todo.len() + 4 > RANGE_BOXES) {
            done.extend(hull);
            continue;
        }
        if boxes + todo.len() + 4 > RANGE_BOXES {
            return Err(CanalError::InvalidArgument(format!(
                "the denominator Dn of the spine parameter p = N/Dn of Γ could not be shown of one sign on [{}, {}] × [{}, {}]",
                format_scalar(&rect[0]),
                format_scalar(&rect[1]),
                format_scalar(&rect[2]),
                format_scalar(&rect[3])
            )));
        }
        let (sm, tm) = (
            (s0.clone() + s1.clone()) / two.clone(),
            (t0.clone() + t1.clone()) / two.clone(),
        );
        todo.extend([
            [s0.clone(), sm.clone(), t0.clone(), tm.clone()],
            [s0.clone(), sm.clone(), tm.clone(), t1.clone()],
            [sm.clone(), s1.clone(), t0.clone(), tm.clone()],
            [sm, s1.clone(), tm, t1.clone()],
        ]);
    }
    let outer = done.iter().fold(inner.clone(), |acc, h| Iv {
        lo: rmin(&acc.lo, &h.lo),
        hi: rmax(&acc.hi, &h.hi),
    });
    // round outward to a dyadic grid about as fine as the tolerance
    let width = Scalar::to_f64(&(outer.hi.clone() - outer.lo.clone())).max(1e-300);
    let k = ((-(width / 65536.0).log2()).ceil()).clamp(0.0, 62.0) as u32;
    let scale = Rational::from(1u64 << k);
    let lo = Rational::from((outer.lo.clone() * scale.clone()).floor()) / scale.clone();
    let hi = Rational::from((outer.hi.clone() * scale.clone()).ceil()) / scale;
    Ok(ParamRange {
        inner: (inner.lo, inner.hi),
        outer: (lo, hi),
        boxes,
    })
}

/// Decides that the cyclographic canal surface `Γ(s, t)` of the polynomial family `spine`
/// on the rectangle `rect = [s₀, s₁, t₀, t₁]` of Ω(s, t), with spine parameter
/// `p = N(s, t)/Dn(s, t)` (`param = (N, Dn)`, `Dn ≠ 0` on the rectangle), has no global
/// self-intersection, and returns the certificate (docs/math/pipes.md#canal-global, "On a
/// rectangle of the cyclographic parametrization"). `Γ(s, t)` lies on the characteristic
/// circle of `p(s, t)` in the direction `−w(s, t)` (the inverse stereographic image of
/// `(s, t)`, one-to-one), so two points of the rectangle with the same `p` have distinct
/// images, and with distinct `p` their images are distinct when the characteristic discs are
/// pairwise disjoint over the interval `p(rectangle)`. That interval is enclosed by
/// [`parameter_range`] (`inner ⊆ p(rectangle) ⊆ outer`) and the discs are checked on `outer`
/// by the subdivision of [`check_canal_embedded`].
///
/// Assumes the local condition on the rectangle ([`super::check_cyclographic_regularity`],
/// which [`super::canal_surface_rational`] checks first); the local condition on `outer` is
/// checked again here.
///
/// # Errors
/// [`CanalError::CyclographicDiscsMeet`] with an exact witness pair of spine parameters,
/// both reached by the rectangle (within `inner`), whose discs meet (a sufficient test: `Γ`
/// covers arcs of the circles only, so it may still be free of self-intersection);
/// [`CanalError::CanalPartsNotApart`] (undecided) when the subdivision stops, when the
/// witness lies in the thin margin `outer ∖ inner` that may not be reached, or when the
/// local condition fails in that margin; [`CanalError::InvalidArgument`] where `Dn` is not
/// shown of one sign on the rectangle.
pub fn check_cyclographic_embedded(
    spine: &CanalSpine<Rational>,
    param: (&BiPoly<Rational>, &BiPoly<Rational>),
    rect: &[Rational; 4],
) -> Result<Certificate, CanalError> {
    check_cyclographic_embedded_within(spine, param, rect, (CANAL_GLOBAL_DEPTH, CANAL_GLOBAL_BOXES))
}

/// [`check_cyclographic_embedded`] with other limits `(halvings, boxes)`.
///
/// # Errors
/// As [`check_cyclographic_embedded`].
pub fn check_cyclographic_embedded_within(
    spine: &CanalSpine<Rational>,
    param: (&BiPoly<Rational>, &BiPoly<Rational>),
    rect: &[Rational; 4],
    limits: (u32, usize),
) -> Result<Certificate, CanalError> {
    let range = parameter_range(param.0, param.1, rect)?;
    let (lo, hi) = &range.outer;
    let (ilo, ihi) = &range.inner;
    let rect_text = format!(
        "[{}, {}] × [{}, {}]",
        format_scalar(&rect[0]),
        format_scalar(&rect[1]),
        format_scalar(&rect[2]),
        format_scalar(&rect[3])
    );
    let reached = format!(
        "the rectangle {rect_text} of Γ reaches the spine parameters p from ≈ {:.6} to ≈ {:.6}, all within [{}, {}]",
        Scalar::to_f64(ilo),
        Scalar::to_f64(ihi),
        format_scalar(lo),
        format_scalar(hi)
    );
    if lo == hi {
        return Ok(Certificate::holds(
            format!(
                "Γ on {rect_text} lies on one characteristic circle (p = {})",
                format_scalar(lo)
            ),
            true,
        ));
    }
    let margin = |boxes: usize| CanalError::CanalPartsNotApart {
        first: format!("[{}, {}]", format_scalar(lo), format_scalar(ilo)),
        second: format!(
            "[{}, {}] ({reached}; the margins may not be reached)",
            format_scalar(ihi),
            format_scalar(hi)
        ),
        boxes,
    };
    if spine
        .check_real_envelope(Some((lo, hi)))
        .and_then(|_| super::regularity::check_canal_regularity(spine, (lo, hi)).map(|_| ()))
        .is_err()
    {
        return Err(margin(0));
    }
    let mut search = Search {
        pieces: vec![PieceSearch::new(0, spine, lo, hi)],
        smooth: Vec::new(),
        closed: false,
        named: false,
        planes: HashMap::new(),
        boxes: HashMap::new(),
        exact_boxes: 0,
    };
    let inside = |x: &Rational| ilo <= x && x <= ihi;
    match subdivide(&mut search, limits)? {
        Outcome::Certified(boxes, counts) => Ok(Certificate::holds(
            format!(
                "Γ(s, t) has no self-intersection on {rect_text}: {reached} (exact values at points of the rectangle; Bernstein hulls of N/Dn, {} boxes); points of Γ with one p lie on one characteristic circle in distinct directions w(s, t) (stereographic, one-to-one), and the closed discs bounded by the characteristic circles at distinct p of [{}, {}] are pairwise disjoint: {}",
                range.boxes,
                format_scalar(lo),
                format_scalar(hi),
                settled_text(boxes, counts)
            ),
            true,
        )),
        Outcome::Meet { first, second, t, s } if inside(&t) && inside(&s) => {
            Err(CanalError::CyclographicDiscsMeet {
                first: format!("{first} ({reached})"),
                second,
                t: format_scalar(&t),
                s: format_scalar(&s),
            })
        }
        Outcome::Meet { .. } => Err(margin(0)),
        Outcome::Undecided {
            first,
            second,
            boxes,
        } => Err(CanalError::CanalPartsNotApart {
            first: format!("{first} (spine parameter p of Γ; {reached})"),
            second,
            boxes,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    #[test]
    fn interval_arithmetic_encloses() {
        let x = Iv {
            lo: q(-1, 2),
            hi: q(3, 1),
        };
        let y = Iv {
            lo: q(2, 1),
            hi: q(5, 1),
        };
        let p = x.mul(&y);
        assert_eq!((p.lo, p.hi), (q(-5, 2), q(15, 1)));
        let s = x.sq();
        assert_eq!((s.lo, s.hi), (q(0, 1), q(9, 1)));
        assert!(y.div(&x).is_none());
        let d = x.div(&y).expect("0 ∉ y");
        assert_eq!((d.lo, d.hi), (q(-1, 4), q(3, 2)));
        assert!(sqrt_sum_reaches(&q(1, 1), &q(4, 1), &q(9, 1)));
        assert!(!sqrt_sum_reaches(&q(1, 1), &q(4, 1), &q(10, 1)));
    }

    #[test]
    fn discs_of_a_cylinder_and_a_crossing() {
        // spheres of radius 1 on the z-axis: the discs at t = 0 and t = 1/2 are parallel and
        // apart; on the unit circle of radius 2 with r = 1, the discs at t and at the
        // antipode −1/t (rational parametrization) meet iff r ≥ 2
        let cyl = CanalSpine::polynomial(
            [Poly::zero(), Poly::zero(), Poly::from_ints(&[0, 1])],
            Poly::constant(q(1, 1)),
        );
        assert!(!discs_meet(&cyl, &q(0, 1), &q(1, 2)).expect("discs"));
        assert!(discs_meet(&cyl, &q(0, 1), &q(0, 1)).expect("discs"));
        let w = Poly::from_ints(&[1, 0, 1]);
        let circle = |r: Rational| {
            CanalSpine::new(
                w.clone(),
                [
                    Poly::from_ints(&[2, 0, -2]),
                    Poly::from_ints(&[0, 4]),
                    Poly::zero(),
                ],
                w.scale(&r),
            )
            .expect("family")
        };
        // t = 1/2 and its antipode t = −2
        assert!(!discs_meet(&circle(q(199, 100)), &q(1, 2), &q(-2, 1)).expect("discs"));
        assert!(discs_meet(&circle(q(2, 1)), &q(1, 2), &q(-2, 1)).expect("discs"));
    }

    #[test]
    fn parameter_range_encloses_the_image_of_the_rectangle() {
        // p = (s + t)/(1 + s²) on [−1, 2] × [0, 1]: p = (s + t)/(1 + s²) is largest at
        // t = 1, s = √2 − 1 (value (1 + √2)/2 ≈ 1.2071) and least at s = −1, t = 0 (−1/2)
        let num = BiPoly::new(vec![Poly::from_ints(&[0, 1]), Poly::from_ints(&[1])]);
        let den = BiPoly::from_t(Poly::from_ints(&[1, 0, 1]));
        let rect = [q(-1, 1), q(2, 1), q(0, 1), q(1, 1)];
        let r = parameter_range(&num, &den, &rect).expect("range");
        let (lo, hi) = (q(-1, 2), (1.0 + 2f64.sqrt()) / 2.0);
        assert!(
            r.outer.0 <= lo && r.inner.0 == lo,
            "{:?}",
            (&r.outer, &r.inner)
        );
        let (ihi, ohi) = (Scalar::to_f64(&r.inner.1), Scalar::to_f64(&r.outer.1));
        assert!(ihi <= hi && hi <= ohi, "{ihi} {hi} {ohi}");
        assert!(ohi - ihi < 1e-3, "{ihi} {ohi}");
        // a denominator with a zero on the rectangle is refused
        let den0 = BiPoly::from_t(Poly::from_ints(&[0, 1]));
        assert!(parameter_range(&num, &den0, &rect).is_err());
    }

    #[test]
    fn joints_run_on_smoothly_only_with_the_same_sphere_tangent_and_g() {
        // two segments of the x-axis, r = 1 + t/4 then r = 5/4 + t/4: smooth at the joint;
        // r = 5/4 + t/2 changes dr/dσ (so g); r = 1 + t/4 twice jumps
        let line = |r: &[Rational]| {
            CanalSpine::polynomial(
                [Poly::from_ints(&[0, 1]), Poly::zero(), Poly::zero()],
                Poly::new(r.to_vec()),
            )
        };
        let first = line(&[q(1, 1), q(1, 4)]);
        let shifted = |r: &[Rational]| {
            CanalSpine::polynomial(
                [Poly::from_ints(&[1, 1]), Poly::zero(), Poly::zero()],
                Poly::new(r.to_vec()),
            )
        };
        let (zero, one) = (q(0, 1), q(1, 1));
        assert!(joins_smoothly(
            &first,
            &one,
            &shifted(&[q(5, 4), q(1, 4)]),
            &zero
        ));
        assert!(!joins_smoothly(
            &first,
            &one,
            &shifted(&[q(5, 4), q(1, 2)]),
            &zero
        ));
        assert!(!joins_smoothly(
            &first,
            &one,
            &shifted(&[q(1, 1), q(1, 4)]),
            &zero
        ));
        // the same line at twice the speed: the same g = r dr/dσ needs dr/dt doubled
        let fast = CanalSpine::polynomial(
            [Poly::from_ints(&[1, 2]), Poly::zero(), Poly::zero()],
            Poly::new(vec![q(5, 4), q(1, 2)]),
        );
        assert!(joins_smoothly(&first, &one, &fast, &zero));
    }

    /// A canal family of varying radius (`B ≠ 0`) and a pipe (`B ≡ 0`).
    fn families() -> [CanalSpine<Rational>; 2] {
        let lifted = CanalSpine::polynomial(
            [
                Poly::from_ints(&[-1, 0, 1]),
                Poly::from_ints(&[0, -1, 0, 1]),
                Poly::new(vec![q(0, 1), q(1, 5)]),
            ],
            Poly::new(vec![q(1, 10), q(0, 1), q(1, 40)]),
        );
        let w = Poly::from_ints(&[1, 0, 1]);
        let arc = CanalSpine::new(
            w.clone(),
            [
                Poly::from_ints(&[1, 0, -1]),
                Poly::from_ints(&[0, 2]),
                Poly::zero(),
            ],
            w.scale(&q(3, 4)),
        )
        .expect("arc");
        [lifted, arc]
    }

    /// `G` of [`plane_poly`] is the plane test `φ_s(c(t))²|A(t)|² − ρ(t)²|A(t) × A(s)|²`
    /// (exact values at the two parameters) times `W(t)²|A(t)|²W(s)²` (divided by `|A(t)|²`
    /// more for a pipe, and by `(s − t)²` on one piece): an exact identity at sample pairs.
    #[test]
    fn plane_polynomial_is_the_plane_test_times_positive_factors() {
        let [lifted, arc] = families();
        let ts = [q(-3, 2), q(-1, 3), q(0, 1), q(2, 7), q(5, 4)];
        for (first, second, pipe) in [
            (&lifted, &lifted, false),
            (&lifted, &arc, false),
            (&arc, &arc, true),
            (&arc, &lifted, false),
        ] {
            let (pf, ps) = (polys(first), polys(second));
            let same = core::ptr::eq(first, second);
            let g = plane_poly(&PlaneParts::of(first), &PlaneParts::of(second), same)
                .expect("divisible");
            for t in &ts {
                for s in &ts {
                    if same && t == s {
                        continue;
                    }
                    let (p, r) = (point(&pf, t).expect("t"), point(&ps, s).expect("s"));
                    let phi = rdot(&p.c, &r.a) - r.e.clone();
                    let u = rcross(&p.a, &r.a);
                    let direct = phi.clone() * phi * p.aa.clone() - p.rho2.clone() * rdot(&u, &u);
                    let (wt, ws) = (pf[I_W].eval(t), ps[I_W].eval(s));
                    let mut factor = wt.clone() * wt * ws.clone() * ws;
                    if !pipe {
                        factor *= p.aa.clone();
                    }
                    if same {
                        let d = s.clone() - t.clone();
                        factor /= d.clone() * d;
                    }
                    assert_eq!(g.eval(t, s), direct * factor, "t = {t}, s = {s}");
                }
            }
        }
    }

    /// The `f64` quarters stay within their error bound of the exact tensor coefficients
    /// of the same boxes, over three levels.
    #[test]
    fn float_quarters_stay_within_their_bound() {
        let [lifted, _] = families();
        let parts = PlaneParts::of(&lifted);
        let g = plane_poly(&parts, &parts, true).expect("divisible");
        let (m, n) = (g.degree_t().expect("m"), g.degree_u().expect("n"));
        let (a, b) = (q(-3, 2), q(3, 2));
        let root = FTensor::of(
            &g.bernstein_on((&a, &b), (&a, &b), m, n).expect("root"),
            m,
            n,
        );
        assert!(
            root.err.is_finite()
                && root.err < 1e-12 * root.c.iter().fold(0.0f64, |x, y| x.max(y.abs()))
        );
        // the box (t-index, s-index) of each quarter, at three levels
        let mut boxes = vec![(0u64, 0u64, root)];
        for level in 1..=3u32 {
            boxes = boxes
                .into_iter()
                .flat_map(|(i, j, f)| {
                    f.quarters()
                        .into_iter()
                        .enumerate()
                        .map(move |(k, f)| (2 * i + (k as u64 >> 1), 2 * j + (k as u64 & 1), f))
                })
                .collect();
            let h = (b.clone() - a.clone()) / Rational::from(1u64 << level);
            for (i, j, f) in boxes.iter().step_by(7) {
                let end = |k: u64| a.clone() + h.clone() * Rational::from(k);
                let exact = g
                    .bernstein_on((&end(*i), &end(i + 1)), (&end(*j), &end(j + 1)), m, n)
                    .expect("exact");
                for (x, y) in exact.iter().zip(&f.c) {
                    let d = Scalar::to_f64(&(x.clone() - Rational::try_from(*y).expect("finite")));
                    assert!(d.abs() <= f.err, "level {level}: {d} > {}", f.err);
                }
            }
        }
    }

    /// The `f64` intervals contain the exact rational results of the same operations.
    #[test]
    fn f64_intervals_enclose_the_exact_ones() {
        let ten = |k: usize| (0..k).fold(Rational::ONE, |a, _| a * Rational::from(10));
        let ivs = [
            Iv {
                lo: q(-1, 3),
                hi: q(2, 7),
            },
            Iv {
                lo: q(1, 10),
                hi: q(3, 10),
            },
            Iv {
                lo: q(-7, 3),
                hi: q(-1, 1_000_000_007),
            },
            Iv {
                lo: ten(300) / q(3, 1),
                hi: ten(301),
            },
        ];
        let inside = |f: FIv, x: &Iv| {
            let lo_ok =
                f.lo == f64::NEG_INFINITY || Rational::try_from(f.lo).is_ok_and(|l| l <= x.lo);
            let hi_ok = f.hi == f64::INFINITY || Rational::try_from(f.hi).is_ok_and(|h| h >= x.hi);
            lo_ok && hi_ok
        };
        for x in &ivs {
            assert!(inside(FIv::of(x), x));
            assert!(inside(FIv::of(x).sq(), &x.sq()));
            for y in &ivs {
                let (fx, fy) = (FIv::of(x), FIv::of(y));
                assert!(inside(fx.add(fy), &x.add(y)));
                assert!(inside(fx.sub(fy), &x.sub(y)));
                assert!(inside(fx.mul(fy), &x.mul(y)), "{x:?} {y:?}");
            }
        }
        // ∞ − ∞ is no bound: the whole line
        let big = FIv {
            lo: f64::INFINITY,
            hi: f64::INFINITY,
        };
        let w = big.sub(big);
        assert!(w.lo == f64::NEG_INFINITY && w.hi == f64::INFINITY);
    }
}
