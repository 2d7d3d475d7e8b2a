//! A rational PN parametrization over `Q` of the two-sheet hyperboloid
//! `x₁²/a² − x₂²/b² − x₃²/c² = 1` (`b ≠ c`) for every rational `a, b, c`, by a degree-2
//! unirational parametrization of the surface of its tangent planes (Peternell §4.7 and
//! Theorem 4.6 ask for one; the principal-frame construction of [`super::hypercyclide`]
//! finds none; derivation in docs/math/hypercyclides.md#two-sheet-unirational).
//!
//! The oriented tangent planes `n·x = h` with `n = (N₁, N₂, N₃)/W`, `h = S/W` are the points
//! of the del Pezzo surface `X: N₁² + N₂² + N₃² = W²`, `a²N₁² − b²N₂² − c²N₃² = S²` of `P⁴`
//! (degree 4), which has the rational point `P = (1, 0, 0, 1, a)` (the vertex normal).
//! The hyperplanes through its tangent plane, `S − aN₁ = μ(W − N₁)`, cut `X` in the conics
//! `μ(a − μ)e² = (b² + aμ)N₂² + (c² + aμ)N₃²` (`e = W − N₁`); these meet the exceptional
//! curve over `P` (`e = 0`) in the two points `N₂ : N₃ = τ : 1` with
//! `μ = −(b²τ² + c²)/(a(τ² + 1))`. Over `Q(τ)` the conic has the rational point
//! `(0, τ, 1)`, and the lines `(0, τ, 1) + k(1, σ, 0)` through it give the second point
//!
//! ```text
//! k = −2a²q(b² − c²)τσ / Dₖ,   q = τ² + 1,   p = b²τ² + c²,
//! Dₖ = p(a²q + p) + a²q(b² − c²)σ²,
//! ```
//!
//! so `e = k`, `N₂ = τ + kσ`, `N₃ = 1`, `W + N₁ = (N₂² + N₃²)/e`, `S = μe + aN₁`. The
//! contact point of the plane is `x = (a²N₁, −b²N₂, −c²N₃)/S`.
//!
//! **What the real parameters cover** (docs/math/hypercyclides.md#two-sheet-region). Real
//! `τ` give `μ ∈ [−b²/a, −c²/a]` (`τ = 0` gives `−c²/a`, `τ → ∞` gives `−b²/a`), and for
//! each such `μ` the real `σ` run through the whole conic but one point. Real points of `X`
//! are the tangent planes oriented with `n₁ > 0`; on the hyperboloid, with
//! `μ = (h − an₁)/(1 − n₁)`, the condition `−b²/a ≤ μ ≤ −c²/a` (for `b > c`) reduces to
//!
//! ```text
//! |x₃| ≥ k |x₁ − a|,   k = c²√(a² + b²) / (a b √(b² − c²)),
//! ```
//!
//! (the lower bound holds on the whole surface): the wedge between the two planes
//! `x₃ = ±k(x₁ − a)` through the vertex tangent `{x₁ = a, x₃ = 0}`, on **both** sheets —
//! the sheet `x₁ ≥ a` with the normal pointing away from the centre, the sheet `x₁ ≤ −a`
//! with the normal pointing towards it; the parametrization passes from one to the other
//! through the planes with `h = 0` (its poles `S = 0`, the asymptotic cone). For `c > b`
//! exchange the roles of `(x₂, b)` and `(x₃, c)`. `σ = 0` (and `τ = ±i`) map to the vertex
//! `(a, 0, 0)`.

use super::poly::{int, mag, var, zero_cert};
use super::surface::PnSurface;
use super::PnError;
use crate::error::format_scalar;
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::certify::polynomial_is_zero_scaled;

/// The two-sheet hyperboloid `x₁²/a² − x₂²/b² − x₃²/c² = 1` as a PN surface in `(τ, σ)`.
#[derive(Debug, Clone)]
pub struct TwoSheetPn<F> {
    a: F,
    b: F,
    c: F,
    surface: PnSurface<F>,
}

impl<F: Scalar> TwoSheetPn<F> {
    /// The parametrization of the module docs.
    ///
    /// # Errors
    /// [`PnError::InvalidInput`] if an axis is 0 or `b² = c²` (a hyperboloid of revolution
    /// about `x₁`: the construction degenerates to the vertex; use the canal-surface
    /// constructions for surfaces of revolution).
    pub fn new(a: F, b: F, c: F) -> Result<Self, PnError> {
        if a.is_zero() || b.is_zero() || c.is_zero() {
            return Err(PnError::InvalidInput(format!(
                "the semi-axes must be non-zero, got a = {}, b = {}, c = {}",
                format_scalar(&a),
                format_scalar(&b),
                format_scalar(&c)
            )));
        }
        let (a2, b2, c2) = (
            a.clone() * a.clone(),
            b.clone() * b.clone(),
            c.clone() * c.clone(),
        );
        let bc = b2.clone() - c2.clone();
        if crate::certs::is_negligible(&bc, b2.to_f64().abs().max(c2.to_f64().abs())) {
            return Err(PnError::InvalidInput(format!(
                "b² = c² = {}: a two-sheet hyperboloid of revolution (about x₁); this construction needs b ≠ c",
                format_scalar(&b2)
            )));
        }
        let (t, s) = (var::<F>(0), var::<F>(1));
        let k = |x: &F| MPoly::constant(2, x.clone());
        let q = &(&t * &t) + &int(1);
        let p = &(&(&t * &t) * &k(&b2)) + &k(&c2);
        let a2q = q.scale(&a2);
        let dk = &(&p * &(&a2q + &p)) + &(&a2q * &(&s * &s)).scale(&bc);
        let kn = (&(&a2q * &t) * &s).scale(&(-(F::from_i64(2) * bc)));
        // homogeneous with the denominator Dₖ·kₙ: e = kₙ², N₂ = (τDₖ + σkₙ)kₙ, N₃ = Dₖkₙ,
        // W + N₁ = (τDₖ + σkₙ)² + Dₖ²
        let e = &kn * &kn;
        let m2 = &(&t * &dk) + &(&s * &kn);
        let n2 = &m2 * &kn;
        let n3 = &dk * &kn;
        let f = &(&m2 * &m2) + &(&dk * &dk);
        // times 2a·q: W = aq(e + f), N₁ = aq(f − e), S = −2p·e + a²q(f − e)
        let aq = q.scale(&a);
        let two = F::from_i64(2);
        let w = &aq * &(&e + &f);
        let n1 = &aq * &(&f - &e);
        let n2 = (&aq * &n2).scale(&two);
        let n3 = (&aq * &n3).scale(&two);
        let sh = &(&p * &e).scale(&(-two)) + &(&a2q * &(&f - &e));
        let point = [sh, n1.scale(&a2), -n2.scale(&b2), -n3.scale(&c2)];
        let normal = [w, n1, n2, n3];
        let surface = PnSurface::from_point_normal(point, normal)?
            .named("two-sheet hyperboloid (unirational PN parametrization)");
        Ok(TwoSheetPn { a, b, c, surface })
    }

    /// The PN surface in `(τ, σ)`.
    pub fn surface(&self) -> &PnSurface<F> {
        &self.surface
    }

    /// The semi-axes `(a, b, c)`.
    pub fn axes(&self) -> [&F; 3] {
        [&self.a, &self.b, &self.c]
    }

    /// The tangency certificates for `surface`, the base surface or one of its offsets at
    /// the oriented distance `d = surface.distance()`: with `p = x − d n` (homogeneous
    /// `P = (X N₀ − d X₀ N, X₀ N₀)`),
    /// * `b²c²P₁² − a²c²P₂² − a²b²P₃² − a²b²c²P₀² ≡ 0`: `p` lies on the hyperboloid;
    /// * `∇φ(p) × n ≡ 0` with `∇φ ∝ (b²c²P₁, −a²c²P₂, −a²b²P₃)`: the normal is the
    ///   hyperboloid's normal at `p`, so the plane of `surface` at `x` is the tangent plane
    ///   at `p` moved by `d` (Theorem 4.6: the quadric and its exact offsets).
    pub fn tangency_certificates(&self, surface: &PnSurface<F>) -> Vec<Certificate> {
        let d = surface.distance().clone();
        let x = surface.point_polys();
        let n = surface.normal_polys();
        let p0 = &x[0] * &n[0];
        let p: [MPoly<F>; 3] =
            std::array::from_fn(|i| &(&x[i + 1] * &n[0]) - &(&x[0] * &n[i + 1]).scale(&d));
        let (a2, b2, c2) = (
            self.a.clone() * self.a.clone(),
            self.b.clone() * self.b.clone(),
            self.c.clone() * self.c.clone(),
        );
        let on = &(&(&(&p[0] * &p[0]).scale(&(b2.clone() * c2.clone()))
            - &(&p[1] * &p[1]).scale(&(a2.clone() * c2.clone())))
            - &(&p[2] * &p[2]).scale(&(a2.clone() * b2.clone())))
            - &(&p0 * &p0).scale(&(a2.clone() * b2.clone() * c2.clone()));
        let g = [
            p[0].scale(&(b2.clone() * c2.clone())),
            -p[1].scale(&(a2.clone() * c2)),
            -p[2].scale(&(a2 * b2)),
        ];
        let nn = [n[1].clone(), n[2].clone(), n[3].clone()];
        let cr = super::poly::cross3(&g, &nn);
        // f64 tolerance from the sizes without cancellation (not from the residual)
        let terms = |q: &MPoly<F>| q.num_terms().max(1) as f64;
        let mp = p
            .iter()
            .chain(std::iter::once(&p0))
            .map(|q| mag(q) * terms(q))
            .fold(1.0, f64::max);
        let mn = n.iter().map(|q| mag(q) * terms(q)).fold(1.0, f64::max);
        let ax = [&self.a, &self.b, &self.c]
            .iter()
            .map(|v| v.to_f64().abs())
            .fold(1.0, f64::max)
            .powi(6);
        let mut out = vec![zero_cert(
            "the foot point x − d n lies on the two-sheet hyperboloid x₁²/a² − x₂²/b² − x₃²/c² = 1",
            &on,
            16.0 * mp * mp * ax,
        )];
        for (i, c) in cr.iter().enumerate() {
            out.push(zero_cert(
                &format!(
                    "the normal is the hyperboloid's normal at the foot point: (∇φ × n)_{i} ≡ 0"
                ),
                c,
                16.0 * mp * mn * ax,
            ));
        }
        out
    }

    /// `b²c²X₁² − a²c²X₂² − a²b²X₃² − a²b²c²W² ≡ 0`: the point lies on the hyperboloid.
    pub fn quadric_certificate(&self) -> Certificate {
        let x = self.surface.point_polys();
        let (a2, b2, c2) = (
            self.a.clone() * self.a.clone(),
            self.b.clone() * self.b.clone(),
            self.c.clone() * self.c.clone(),
        );
        let r = &(&(&(&x[1] * &x[1]).scale(&(b2.clone() * c2.clone()))
            - &(&x[2] * &x[2]).scale(&(a2.clone() * c2.clone())))
            - &(&x[3] * &x[3]).scale(&(a2.clone() * b2.clone())))
            - &(&x[0] * &x[0]).scale(&(a2 * b2 * c2));
        let coeffs: Vec<F> = r.terms().map(|(_, c)| c.clone()).collect();
        let sc = x
            .iter()
            .flat_map(|p| p.terms().map(|(_, c)| c.to_f64().abs()))
            .fold(1.0, f64::max);
        polynomial_is_zero_scaled(
            "x₁²/a² − x₂²/b² − x₃²/c² ≡ 1 (the point lies on the two-sheet hyperboloid)",
            &coeffs,
            sc * sc
                * [&self.a, &self.b, &self.c]
                    .iter()
                    .map(|v| v.to_f64().abs())
                    .fold(1.0, f64::max)
                    .powi(6),
        )
    }
}

impl<F: Scalar> Certified for TwoSheetPn<F> {
    /// The PN certificates of the surface and the quadric identity.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.surface.certify();
        out.push(self.quadric_certificate());
        out.extend(self.tangency_certificates(&self.surface));
        out
    }
}
