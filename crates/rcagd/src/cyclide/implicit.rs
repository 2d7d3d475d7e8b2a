//! The implicit equation of a Dupin cyclide (docs/math/cyclides.md#implicit).
//!
//! A point `x` lies on the cyclographic image of the conic `C` iff the function
//! `f = ⟨Y − (C − C₀), Y − (C − C₀)⟩` with `Y = (x, 0) − C₀` has a double zero along the
//! conic (the point cycle `(x; 0)` touches the family). For the pe circle
//! `f(θ) = ⟨Y, Y⟩ + ρ² − 2ρ(cos θ ⟨Y, U⟩ + sin θ ⟨Y, V⟩)`, whence the quartic
//!
//! ```text
//! F(x) = (⟨Y, Y⟩ + ρ²R)² − 4ρ²(⟨Y, U⟩² + ⟨Y, V⟩²),   R = ⟨U, U⟩ (= 1 normally),
//! ```
//!
//! which for `U = (1, 0, 0, 0)`, `V = (0, b/ρ, 0, c/ρ)` is the classical
//! `(x² + y² + z² − μ² + b²)² = 4(ax − cμ)² + 4b²y²` (Peternell §3.8.1 with the axes
//! relabelled); for the pe parabola `f(t) = ⟨Y, Y⟩ − 2t⟨Y, U⟩ + t²(g − ⟨Y, N⟩)`
//! (`g = ⟨U, U⟩`, 1 normally), whence the cubic `F(x) = ⟨Y, U⟩² − ⟨Y, Y⟩(g − ⟨Y, N⟩)`
//! (Prop. 3.2: order 3).

use super::conic::PeConic;
use crate::canal::bipoly::BiPoly;
use rcagd_algebra::Scalar;

/// The operations the formula needs (implemented for scalars and bivariate polynomials).
pub(crate) trait Alg<F>: Clone {
    fn add(&self, o: &Self) -> Self;
    fn sub(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
    fn scale(&self, k: &F) -> Self;
}

impl<F: Scalar> Alg<F> for BiPoly<F> {
    fn add(&self, o: &Self) -> Self {
        BiPoly::add(self, o)
    }
    fn sub(&self, o: &Self) -> Self {
        BiPoly::sub(self, o)
    }
    fn mul(&self, o: &Self) -> Self {
        BiPoly::mul(self, o)
    }
    fn scale(&self, k: &F) -> Self {
        BiPoly::scale(self, k)
    }
}

/// Scalars as an [`Alg`] (a newtype, to avoid clashing with the operator traits).
#[derive(Clone)]
pub(crate) struct S<F>(pub F);

impl<F: Scalar> Alg<F> for S<F> {
    fn add(&self, o: &Self) -> Self {
        S(self.0.clone() + o.0.clone())
    }
    fn sub(&self, o: &Self) -> Self {
        S(self.0.clone() - o.0.clone())
    }
    fn mul(&self, o: &Self) -> Self {
        S(self.0.clone() * o.0.clone())
    }
    fn scale(&self, k: &F) -> Self {
        S(self.0.clone() * k.clone())
    }
}

/// `⟨Y, A⟩` for `Y` given by homogeneous components and a constant vector `A`.
fn pe_const<F: Scalar, T: Alg<F>>(y: &[T; 4], a: &[F; 4]) -> T {
    y[0].scale(&a[0])
        .add(&y[1].scale(&a[1]))
        .add(&y[2].scale(&a[2]))
        .sub(&y[3].scale(&a[3]))
}

/// The homogeneous implicit form `F(X₀, X₁, X₂, X₃)` (degree 4, or 3 for the parabola).
pub(crate) fn implicit_generic<F: Scalar, T: Alg<F>>(conic: &PeConic<F>, x: &[T; 4]) -> T {
    let c = match conic {
        PeConic::Circle { center, .. } => center,
        PeConic::Parabola { vertex, .. } => vertex,
    };
    // Y = (X₁ − X₀c₁, X₂ − X₀c₂, X₃ − X₀c₃, −X₀r₀)
    let y: [T; 4] = [
        x[1].sub(&x[0].scale(&c[0])),
        x[2].sub(&x[0].scale(&c[1])),
        x[3].sub(&x[0].scale(&c[2])),
        x[0].scale(&(-c[3].clone())),
    ];
    let yy = y[0]
        .mul(&y[0])
        .add(&y[1].mul(&y[1]))
        .add(&y[2].mul(&y[2]))
        .sub(&y[3].mul(&y[3]));
    match conic {
        PeConic::Circle {
            u, v, rho, ratio, ..
        } => {
            let rr = rho.clone() * rho.clone();
            let a = yy.add(&x[0].mul(&x[0]).scale(&(rr.clone() * super::pe::pe(u, u))));
            let (yu, yv) = (pe_const(&y, u), pe_const(&y, v));
            let four_rr = rr * F::from_i64(4);
            a.mul(&a).sub(
                &yu.mul(&yu)
                    .add(&yv.mul(&yv).scale(&(F::one() / ratio.clone())))
                    .mul(&x[0])
                    .mul(&x[0])
                    .scale(&four_rr),
            )
        }
        PeConic::Parabola { u, n, .. } => {
            let (yu, yn) = (pe_const(&y, u), pe_const(&y, n));
            let g = super::pe::pe(u, u);
            x[0].mul(&yu)
                .mul(&yu)
                .sub(&yy.mul(&x[0].scale(&g).sub(&yn)))
        }
    }
}

/// The implicit form on a parametrization (a polynomial identity to certify).
pub(crate) fn implicit_on<F: Scalar>(conic: &PeConic<F>, x: &[BiPoly<F>; 4]) -> BiPoly<F> {
    implicit_generic(conic, x)
}

/// The implicit form at a homogeneous point.
pub(crate) fn implicit_at<F: Scalar>(conic: &PeConic<F>, x: &[F; 4]) -> F {
    let s: [S<F>; 4] = core::array::from_fn(|i| S(x[i].clone()));
    implicit_generic(conic, &s).0
}
