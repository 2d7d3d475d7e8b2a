//! Pivot decisions shared by the eliminations that run in both arithmetics: a candidate
//! pivot is zero exactly for exact scalars, and in `f64` when it is at most a relative
//! threshold times the largest entry of the matrix (a rounding residue of an exact zero
//! must not be taken as a pivot; G. H. Golub, C. F. Van Loan, *Matrix Computations*,
//! 4th ed., 2013, §3.4 on pivoting and §5.4.1 on numerical rank).

use rcagd_algebra::Scalar;

/// The zero test of a pivot for the matrix with entries `rows`: exact zero for exact
/// scalars; for `f64`, `|x| ≤ rel · max |entry|`.
pub(crate) fn pivot_zero_test<F: Scalar>(rows: &[Vec<F>], rel: f64) -> impl Fn(&F) -> bool {
    let scale = rows
        .iter()
        .flatten()
        .map(|x| x.to_f64().abs())
        .fold(0.0, f64::max);
    move |x: &F| {
        if F::EXACT {
            x.is_zero()
        } else {
            x.to_f64().abs() <= rel * scale
        }
    }
}
