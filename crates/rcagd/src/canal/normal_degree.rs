//! A lower bound of the degree of the rational unit normal fields of a polynomial space
//! curve, decided exactly, and what it implies for the size of a pipe's exported patches
//! (docs/math/pipes.md, "The degree of a unit normal field").
//!
//! A real rational unit normal field `N = P/q` of a curve with hodograph `h` (reduced:
//! `gcd(P₁, P₂, P₃, q) = 1`) has `|P|² = q²`, `P·h ≡ 0`, a denominator `q` without real
//! roots (so of even degree) and `deg P = deg q`. So `deg q ≤ 2` puts `P` into
//! `L₂ = {V ∈ R[t]³ : deg V ≤ 2, V·h ≡ 0}` with `|P|²` a square. [`unit_normal_degree_bound`]
//! decides exactly that no `V ∈ L₂ ∖ 0` has `|V|²` the square of a real polynomial (for
//! `dim L₂ ≤ 2`), which proves `deg q ≥ 4` for every unit normal field.

use rcagd_algebra::roots::isolate_real_roots;
use rcagd_algebra::{Matrix, Poly, Rational};

/// A basis (over `Q`, hence over `R`) of `{V ∈ Q[t]³ : deg V ≤ d, V·h ≡ 0}`, each element as
/// its three coordinate polynomials.
fn orthogonal_fields(h: &[Poly<Rational>; 3], d: usize) -> Vec<[Poly<Rational>; 3]> {
    let dh = h.iter().filter_map(Poly::degree).max().unwrap_or(0);
    let rows = d + dh + 1;
    let cols = 3 * (d + 1);
    // unknown 3k + i: the coefficient of t^k in V_i; row e: the coefficient of t^e of V·h
    let m = Matrix::from_fn(rows, cols, |e, col| {
        let (k, i) = (col / 3, col % 3);
        e.checked_sub(k)
            .and_then(|j| h[i].coeffs().get(j).cloned())
            .unwrap_or(Rational::ZERO)
    });
    m.null_space()
        .into_iter()
        .map(|v| {
            core::array::from_fn(|i| {
                Poly::new(
                    (0..=d)
                        .map(|k| v.get(3 * k + i).cloned().unwrap_or(Rational::ZERO))
                        .collect(),
                )
            })
        })
        .collect()
}

/// `|V|² = V₁² + V₂² + V₃²`.
fn norm2<R: rcagd_algebra::Ring>(v: &[Poly<R>; 3]) -> Poly<R> {
    v.iter()
        .fold(Poly::zero(), |acc: Poly<R>, p| &acc + &(p * p))
}

/// The coefficient of `t^k` of `f` (zero beyond its degree).
fn coeff<R: rcagd_algebra::Ring>(f: &Poly<R>, k: usize) -> R {
    f.coeff(k)
}

/// The discriminant of `f` as a polynomial of formal degree 4, `f = a t⁴ + b t³ + c t² +
/// d t + e` (the classical 16-term formula, checked against sympy's `discriminant` by
/// docs/math/pipes_unit_normal_check.py). Every term has the factor `a` or `b`, so it vanishes when
/// `deg f ≤ 2`; for `deg f = 4` it vanishes iff `f` has a multiple root.
fn disc4<R: rcagd_algebra::Ring>(f: &Poly<R>) -> R {
    let xs = [4, 3, 2, 1, 0].map(|k| coeff(f, k));
    // (coefficient, exponents of a, b, c, d, e)
    const TERMS: [(i64, [u32; 5]); 16] = [
        (256, [3, 0, 0, 0, 3]),
        (-192, [2, 1, 0, 1, 2]),
        (-128, [2, 0, 2, 0, 2]),
        (144, [2, 0, 1, 2, 1]),
        (-27, [2, 0, 0, 4, 0]),
        (144, [1, 2, 1, 0, 2]),
        (-6, [1, 2, 0, 2, 1]),
        (-80, [1, 1, 2, 1, 1]),
        (18, [1, 1, 1, 3, 0]),
        (16, [1, 0, 4, 0, 1]),
        (-4, [1, 0, 3, 2, 0]),
        (-27, [0, 4, 0, 0, 2]),
        (18, [0, 3, 1, 1, 1]),
        (-4, [0, 3, 0, 3, 0]),
        (-4, [0, 2, 3, 0, 1]),
        (1, [0, 2, 2, 2, 0]),
    ];
    let mut acc = R::zero();
    for (k, es) in TERMS {
        let mut term = R::from_i64(k);
        for (x, e) in xs.iter().zip(es) {
            for _ in 0..e {
                term *= x.clone();
            }
        }
        acc += term;
    }
    acc
}

/// A lower bound `δ ∈ {0, 2, 4}` of the degree of the (reduced) denominator of every real
/// rational unit normal field of a curve with the polynomial hodograph `h`
/// (docs/math/pipes.md, "The degree of a unit normal field"):
///
/// * `0` if `h ≡ 0` or the curve is planar (a constant `V ⊥ h`: a constant unit normal may
///   exist);
/// * `4` if no `V ∈ L₂ ∖ 0` has `|V|²` a square, decided for `dim L₂ ≤ 2`:
///   `L₂ = 0`; `L₂ = span(V)` with `L₁ = 0`: `disc₄(|V|²) ≠ 0`; `L₂ = {α p : deg α ≤ 1}`
///   (`L₁ = span(p)`): `disc(|p|²) ≠ 0`; `L₂ = span(V_a, V_b)` with `L₁ = 0`:
///   `disc₄(|V_a|²) ≠ 0` and `disc₄(|λ V_a + V_b|²) ∈ Q[λ]` without a real root;
/// * `2` otherwise (not planar, nothing more shown).
pub(crate) fn unit_normal_degree_bound(h: &[Poly<Rational>; 3]) -> usize {
    if h.iter().all(Poly::is_zero) || !orthogonal_fields(h, 0).is_empty() {
        return 0;
    }
    let l1 = orthogonal_fields(h, 1);
    let l2 = orthogonal_fields(h, 2);
    let nonzero = |x: Rational| x != Rational::ZERO;
    let shown = match (l1.as_slice(), l2.as_slice()) {
        (_, []) => true,
        ([], [v]) => nonzero(disc4(&norm2(v))),
        ([p], [_, _]) => {
            // L₂ = {α p}: |α p|² = α²|p|² is a square iff |p|² (degree ≤ 2) is one
            let f = norm2(p);
            let (a, b, c) = (coeff(&f, 2), coeff(&f, 1), coeff(&f, 0));
            nonzero(b.clone() * b - Rational::from(4) * a * c)
        }
        ([], [va, vb]) => {
            let at_infinity = nonzero(disc4(&norm2(va)));
            // |λ V_a + V_b|² with coefficients in Q[λ]
            let lam = Poly::new(vec![Rational::ZERO, Rational::ONE]);
            let pencil: [Poly<Poly<Rational>>; 3] = core::array::from_fn(|i| {
                let n = va[i].coeffs().len().max(vb[i].coeffs().len());
                Poly::new(
                    (0..n)
                        .map(|k| &lam.scale(&coeff(&va[i], k)) + &Poly::constant(coeff(&vb[i], k)))
                        .collect(),
                )
            });
            let delta = disc4(&norm2(&pencil));
            at_infinity
                && !delta.is_zero()
                && isolate_real_roots(&delta).is_ok_and(|r| r.is_empty())
        }
        _ => false,
    };
    if shown {
        4
    } else {
        2
    }
}

/// The least size key `(control points, deg_t + deg_u)` any exported candidate of a pipe
/// of constant radius around a polynomial spine of degree `k ≥ 1` can have, when every real
/// unit normal field of the spine has a denominator of degree `≥ delta` and the candidate
/// exports at least `patches` patches (docs/math/pipes.md, "The degree of a unit normal
/// field"): each patch has bidegree `(≥ delta + k, ≥ 2)`.
pub(crate) fn candidate_size_bound(delta: usize, k: usize, patches: usize) -> (usize, usize) {
    (patches * (delta + k + 1) * 3, delta + k + 2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::quaternion::Quaternion;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    /// The hodograph `A i A*` of the quadratic preimage with Bernstein coefficients `a`.
    fn hodograph(a: &[[i64; 4]; 3]) -> [Poly<Rational>; 3] {
        let c = crate::ph::PhCurve::new(
            a.iter()
                .map(|c| Quaternion::new(q(c[0]), q(c[1]), q(c[2]), q(c[3])))
                .collect(),
            [q(0), q(0), q(0)],
        )
        .expect("ph");
        core::array::from_fn(|i| c.position()[i].derivative())
    }

    #[test]
    fn seed_quintics_have_no_unit_normal_of_degree_two() {
        // the gallery quintic (L₁ = span(p), |p|² = 17t² − 2t + 1) and issue 17's (dim L₂ = 2)
        assert_eq!(
            unit_normal_degree_bound(&hodograph(&[[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]])),
            4
        );
        assert_eq!(
            unit_normal_degree_bound(&hodograph(&[[1, 0, 0, 0], [1, 1, 0, 1], [0, 0, 1, 1]])),
            4
        );
    }

    #[test]
    fn planar_and_special_quintics_are_not_bounded() {
        // planar: the preimage in R + R k gives a hodograph in the plane z = 0
        assert_eq!(
            unit_normal_degree_bound(&hodograph(&[[1, 0, 0, 0], [1, 0, 0, 2], [0, 0, 0, 1]])),
            0
        );
        // A = (t + i + k)(t − 1 − j): the right factor t − (1 + j) commutes with j, so
        // e₂ = A j A*/|A|² = B j B*/|B|² with B = t + i + k has a denominator of degree 2
        // (docs/math/pipes.md): the bound must not claim 4
        let h = hodograph_of_product([[0, 1, 0, 1], [1, 0, 0, 0]], [[-1, 0, -1, 0], [1, 0, 0, 0]]);
        assert_eq!(unit_normal_degree_bound(&h), 2);
        // the same factors in the other order: the right factor t + i + k is in neither
        // R + R i nor R + R j, yet V = (−2t, −2t, t² − 2) ⊥ A i A* has |V|² = (t² + 2)²
        // (docs/math/pipes.md: the factors alone do not decide it, the test does)
        let h = hodograph_of_product([[-1, 0, -1, 0], [1, 0, 0, 0]], [[0, 1, 0, 1], [1, 0, 0, 0]]);
        assert_eq!(unit_normal_degree_bound(&h), 2);
        let v = [
            Poly::from_ints(&[0, -2]),
            Poly::from_ints(&[0, -2]),
            Poly::from_ints(&[-2, 0, 1]),
        ];
        assert!((0..3)
            .fold(Poly::zero(), |acc: Poly<Rational>, i| &acc
                + &(&v[i] * &h[i]))
            .is_zero());
        assert_eq!(norm2(&v), Poly::from_ints(&[4, 0, 4, 0, 1]));
    }

    /// The hodograph `A i A*` of `A = (f₀ + f₁ t)(g₀ + g₁ t)` (power coefficients).
    fn hodograph_of_product(f: [[i64; 4]; 2], g: [[i64; 4]; 2]) -> [Poly<Rational>; 3] {
        use rcagd_algebra::quaternion::{sandwich_i, vector_polys};
        let qt = |c: [i64; 4]| Quaternion::new(q(c[0]), q(c[1]), q(c[2]), q(c[3]));
        let a = &Poly::new(f.map(qt).to_vec()) * &Poly::new(g.map(qt).to_vec());
        vector_polys(&sandwich_i(&a))
    }
}
