//! Exact factorization over `Q` and `Q(i)`: re-exported from the algebra layer
//! ([`rcagd_algebra::factor`]), where the sum-of-squares and conic-point engines use it.

pub use rcagd_algebra::factor::*;
