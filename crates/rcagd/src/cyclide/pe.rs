//! Small helpers on vectors of the cyclographic model `R^{3,1}` with the pe (Lorentz)
//! product `⟨a, b⟩ = a₁b₁ + a₂b₂ + a₃b₃ − a₄b₄` (Peternell, "Rational Parametrizations
//! for Envelopes of Quadric Families", §3.2).

use crate::certs::is_negligible;
pub use crate::cyclographic::lorentz as pe;
use rcagd_algebra::Scalar;

/// `a + b`.
pub(crate) fn add<F: Scalar>(a: &[F; 4], b: &[F; 4]) -> [F; 4] {
    core::array::from_fn(|i| a[i].clone() + b[i].clone())
}

/// `a − b`.
pub(crate) fn sub<F: Scalar>(a: &[F; 4], b: &[F; 4]) -> [F; 4] {
    core::array::from_fn(|i| a[i].clone() - b[i].clone())
}

/// `k a`.
pub(crate) fn scale<F: Scalar>(k: &F, a: &[F; 4]) -> [F; 4] {
    core::array::from_fn(|i| k.clone() * a[i].clone())
}

/// The row `(a₁, a₂, a₃, −a₄)`: its Euclidean dot product with `x` is `⟨a, x⟩`.
pub(crate) fn pe_row<F: Scalar>(a: &[F; 4]) -> Vec<F> {
    vec![a[0].clone(), a[1].clone(), a[2].clone(), -a[3].clone()]
}

/// Largest `|aᵢ|` as `f64` (the scale of the `f64` tolerance checks).
pub(crate) fn size<F: Scalar>(a: &[F]) -> f64 {
    a.iter().map(|x| x.to_f64().abs()).fold(0.0, f64::max)
}

/// `x == 0` exactly (exact scalars) or up to the relative tolerance `10⁻⁹ · scale`
/// (`f64`).
pub(crate) fn negligible<F: Scalar>(x: &F, scale: f64) -> bool {
    is_negligible(x, scale)
}

pub(crate) use rcagd_algebra::sqrt_in_field;

/// A power of two within a factor `√2` of `√|x|` (a rational scale that balances a
/// parametrization; `1` for `x = 0`).
pub(crate) fn power_of_two_near_sqrt<F: Scalar>(x: &F) -> F {
    let v = x.to_f64().abs();
    if !(v.is_finite() && v > 0.0) {
        return F::one();
    }
    let e = (v.log2() / 2.0).round().clamp(-60.0, 60.0) as i32;
    let two = F::from_i64(2);
    let mut k = F::one();
    for _ in 0..e.unsigned_abs() {
        k = if e > 0 {
            k * two.clone()
        } else {
            k / two.clone()
        };
    }
    k
}
