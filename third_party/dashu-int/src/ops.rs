//! Re-exported relevant operator traits from `dashu-base`

pub use dashu_base::bit::{BitTest, PowerOfTwo};
pub use dashu_base::math::{CubicRoot, EstimatedLog2, SquareRoot};
pub use dashu_base::ring::{
    CubicRootRem, DivEuclid, DivRem, DivRemAssign, DivRemEuclid, ExtendedGcd, Gcd, RemEuclid,
    SquareRootRem,
};
pub use dashu_base::sign::{Abs, UnsignedAbs};
