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
//!   half chord), `H_s` likewise and `X = δ² − H_t⁺ − H_s⁺`: `X > 0` and `X² > 4H_t⁺H_s⁺`.
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
            coeffs,
        }
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

/// How a box was settled.
#[derive(Clone, Copy)]
enum Settled {
    LemmaA,
    Far,
    Plane,
    Chords,
}

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

/// The subdivision state: the polynomials and the tiles computed so far.
struct Search {
    a: Rational,
    width: Rational,
    polys: Vec<P>,
    tiles: HashMap<(u32, u64), Rc<Tile>>,
}

impl Search {
    fn param(&self, level: u32, k: u64) -> Rational {
        self.a.clone() + self.width.clone() * Rational::from(k) / Rational::from(1u64 << level)
    }

    fn interval(&self, level: u32, k: u64) -> String {
        format!(
            "[{}, {}]",
            format_scalar(&self.param(level, k)),
            format_scalar(&self.param(level, k + 1))
        )
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

    /// Tests the box `(level, i, j)`, `i ≤ j`.
    fn settle(&mut self, level: u32, i: u64, j: u64) -> Option<Settled> {
        if j > i {
            let (ti, tj) = (self.tile(level, i), self.tile(level, j));
            if let Some(s) = pair_tests(&ti, &tj) {
                return Some(s);
            }
        }
        // Lemma A over the stretch (only short runs of tiles: longer ones cannot pass)
        if j - i <= 3 {
            let run: Vec<Rc<Tile>> = (i..=j).map(|k| self.tile(level, k)).collect();
            if lemma_a(&run) {
                return Some(Settled::LemmaA);
            }
        }
        None
    }
}

/// Decides exactly that the closed discs bounded by the characteristic circles of the canal
/// surface of `spine` at distinct parameters of `[a, b]` are pairwise disjoint — the surface
/// (a union of these circles) has no self-intersection — and returns the certificate
/// (module docs; docs/math/pipes.md#canal-global). Any radius: for a constant one it is the
/// pipe's statement of [`super::check_pipe_embedded`] (normal discs of radius `|r|`), decided
/// by other tests. The domain is an open arc of the spine (the discs at `a` and `b` count as
/// distinct).
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
    let (max_depth, max_boxes) = limits;
    let (a, b) = domain;
    spine.check_real_envelope(Some((a, b)))?;
    super::regularity::check_canal_regularity(spine, (a, b))?;
    if a == b {
        return Ok(Certificate::holds(
            format!("one characteristic circle (t = {})", format_scalar(a)),
            true,
        ));
    }
    let polys = polys(spine);
    let mut search = Search {
        a: a.clone(),
        width: b.clone() - a.clone(),
        polys,
        tiles: HashMap::new(),
    };
    let mut queue: VecDeque<(u32, u64, u64)> = VecDeque::from([(0, 0, 0)]);
    let mut counts = [0usize; 4];
    let mut boxes = 0usize;
    let half = Rational::from_ratio(1, 2);
    while let Some((level, i, j)) = queue.pop_front() {
        rcagd_algebra::budget::checkpoint();
        boxes += 1;
        if let Some(how) = search.settle(level, i, j) {
            counts[how as usize] += 1;
            continue;
        }
        if j > i {
            // an exact witness at the centre pair
            let t = (search.param(level, i) + search.param(level, i + 1)) * half.clone();
            let s = (search.param(level, j) + search.param(level, j + 1)) * half.clone();
            let (pt, ps) = (point(&search.polys, &t)?, point(&search.polys, &s)?);
            if discs_meet_at(&pt, &ps) {
                return Err(CanalError::CanalSelfIntersects {
                    first: search.interval(level, i),
                    second: search.interval(level, j),
                    t: format_scalar(&t),
                    s: format_scalar(&s),
                });
            }
        }
        if level >= max_depth || boxes + queue.len() + 4 > max_boxes {
            return Err(CanalError::CanalPartsNotApart {
                first: search.interval(level, i),
                second: search.interval(level, j),
                boxes,
            });
        }
        let (l, i2, j2) = (level + 1, 2 * i, 2 * j);
        if i == j {
            queue.extend([(l, i2, i2), (l, i2, i2 + 1), (l, i2 + 1, i2 + 1)]);
        } else {
            queue.extend([
                (l, i2, j2),
                (l, i2, j2 + 1),
                (l, i2 + 1, j2),
                (l, i2 + 1, j2 + 1),
            ]);
        }
    }
    let [lemma, far, plane, chords] = counts;
    Ok(Certificate::holds(
        format!(
            "the closed discs bounded by the characteristic circles at distinct t ∈ [{}, {}] are pairwise disjoint (the canal surface has no self-intersection): {boxes} boxes of parameter pairs examined, {lemma} settled by Lemma A with varying radius (κ_max(ρ_max + κ_max L(g_max + L/2)) + Q_max < 1 or Q_min − … > 1 over the stretch), {far} by |c(t) − c(s)| > ρ(t) + ρ(s), {plane} because a disc misses the other's plane, {chords} by disjoint chords on the line of the two planes; exact rational interval bounds from Bernstein coefficients (docs/math/pipes.md#canal-global)",
            format_scalar(a),
            format_scalar(b)
        ),
        true,
    ))
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
}
