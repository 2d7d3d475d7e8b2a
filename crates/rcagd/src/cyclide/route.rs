//! The decisions a cyclide construction takes on its input, recorded in exact arithmetic
//! and replayed in another scalar (`f64`), so that both build the *same* parametrization.
//!
//! Some steps of [`super::from_three_spheres`] and of [`super::PeConic::conjugate`] choose
//! between constructions by a test that only exact arithmetic decides: whether a norm
//! ratio is a square in the field (every positive `f64` is one), whether an entry is 0
//! (an `f64` rounding residue is not), which rational point a conic over `ℚ` has
//! (Legendre's theorem: exact-only algebra), which columns of a Gram system are its
//! pivots. A [`Route`] in the mode [`Route::record`] takes each decision as the exact
//! scalar does and stores it; [`Route::replay`] hands the stored decisions, in order, to
//! the same construction in `f64`, which then runs every computation in floating point
//! but takes no decision of its own. [`Route::free`] decides in the scalar at hand (the
//! behaviour of the plain constructions).

use super::CyclideError;
use rcagd_algebra::{sqrt_in_field, Matrix, Rational, Scalar};

/// One recorded decision.
#[derive(Debug, Clone, PartialEq)]
pub enum Decision {
    /// A yes/no test (a square root exists, an entry is 0).
    Flag(bool),
    /// A choice among candidates.
    Index(usize),
    /// The pivot columns of a linear system.
    Columns(Vec<usize>),
    /// A rational point `(x, y)` of a conic over `ℚ`.
    Point([Rational; 2]),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Free,
    Record,
    Replay,
}

/// The decisions of one construction (see the module documentation).
#[derive(Debug, Clone)]
pub struct Route {
    mode: Mode,
    taken: Vec<Decision>,
    next: usize,
}

fn mismatch(what: &str) -> CyclideError {
    CyclideError::InvalidArgument(format!(
        "the recorded exact route does not fit this construction (expected {what}): the input differs from the exact one it was recorded on"
    ))
}

impl Route {
    /// Decide in the scalar at hand, record nothing.
    pub fn free() -> Self {
        Route {
            mode: Mode::Free,
            taken: Vec::new(),
            next: 0,
        }
    }

    /// Decide in the scalar at hand (meant: exact) and record each decision.
    pub fn record() -> Self {
        Route {
            mode: Mode::Record,
            ..Self::free()
        }
    }

    /// A route that replays the decisions recorded in `self`, from the first.
    pub fn replay(&self) -> Self {
        Route {
            mode: Mode::Replay,
            taken: self.taken.clone(),
            next: 0,
        }
    }

    /// The decisions recorded (or to replay), in order.
    pub fn decisions(&self) -> &[Decision] {
        &self.taken
    }

    fn take(
        &mut self,
        compute: impl FnOnce() -> Result<Decision, CyclideError>,
    ) -> Result<Decision, CyclideError> {
        match self.mode {
            Mode::Free => compute(),
            Mode::Record => {
                let d = compute()?;
                self.taken.push(d.clone());
                Ok(d)
            }
            Mode::Replay => {
                let d = self
                    .taken
                    .get(self.next)
                    .cloned()
                    .ok_or_else(|| mismatch("another decision"))?;
                self.next += 1;
                Ok(d)
            }
        }
    }

    /// A yes/no test.
    pub(crate) fn flag(&mut self, test: impl FnOnce() -> bool) -> Result<bool, CyclideError> {
        match self.take(|| Ok(Decision::Flag(test())))? {
            Decision::Flag(b) => Ok(b),
            _ => Err(mismatch("a yes/no test")),
        }
    }

    /// A choice among candidates (`None`: no candidate, an error of the caller).
    pub(crate) fn index(
        &mut self,
        choose: impl FnOnce() -> Option<usize>,
    ) -> Result<Option<usize>, CyclideError> {
        if self.mode == Mode::Free {
            return Ok(choose());
        }
        match self.take(|| {
            choose()
                .map(Decision::Index)
                .ok_or_else(|| CyclideError::InvalidArgument("no candidate to choose".into()))
        }) {
            Ok(Decision::Index(i)) => Ok(Some(i)),
            Ok(_) => Err(mismatch("a choice")),
            Err(CyclideError::InvalidArgument(_)) if self.mode == Mode::Record => Ok(None),
            Err(e) => Err(e),
        }
    }

    /// `√x` if it lies in the field: decided exactly when recording, replayed as "take
    /// the root" (computed in the scalar at hand) or "no root".
    pub(crate) fn sqrt<F: Scalar>(&mut self, x: &F) -> Result<Option<F>, CyclideError> {
        match self.mode {
            Mode::Free => Ok(sqrt_in_field(x)),
            Mode::Record => {
                let r = sqrt_in_field(x);
                self.taken.push(Decision::Flag(r.is_some()));
                Ok(r)
            }
            Mode::Replay => {
                if self.flag(|| false)? {
                    sqrt_in_field(x).map(Some).ok_or_else(|| {
                        mismatch("a square root of a non-negative number (rounded below 0)")
                    })
                } else {
                    Ok(None)
                }
            }
        }
    }

    /// A rational point of a conic over `ℚ`, found by `find` when recording (exact-only
    /// algebra), the recorded one when replaying.
    pub(crate) fn point<F: Scalar>(
        &mut self,
        find: impl FnOnce() -> Result<(F, F), CyclideError>,
    ) -> Result<(F, F), CyclideError> {
        match self.mode {
            Mode::Free => find(),
            Mode::Record => {
                let (x, y) = find()?;
                let q = |v: &F| {
                    v.to_rational().ok_or_else(|| {
                        CyclideError::NotRational("a recorded point must be rational".into())
                    })
                };
                self.taken.push(Decision::Point([q(&x)?, q(&y)?]));
                Ok((x, y))
            }
            Mode::Replay => match self.take(|| Err(mismatch("a point")))? {
                Decision::Point([x, y]) => Ok((F::from_rational(&x), F::from_rational(&y))),
                _ => Err(mismatch("a rational point")),
            },
        }
    }

    /// A basis of the kernel of `m` (rows `m`): the reduced-row-echelon basis, one vector
    /// per free column `f` (`1` at `f`, `0` at the other free columns), as
    /// [`Matrix::null_space`]. Recording takes its pivot columns from the exact rank of
    /// the leading columns; replaying solves for each vector with the recorded pivot
    /// columns, so that an `f64` rounding residue of an exact 0 does not become a pivot.
    pub(crate) fn null_space<F: Scalar>(
        &mut self,
        m: &[Vec<F>],
    ) -> Result<Vec<Vec<F>>, CyclideError> {
        let cols = m.first().map_or(0, Vec::len);
        let matrix = |rows: Vec<Vec<F>>| {
            Matrix::from_rows(rows).map_err(|e| CyclideError::InvalidArgument(e.to_string()))
        };
        if self.mode != Mode::Replay {
            let full = matrix(m.to_vec())?;
            if self.mode == Mode::Record {
                // pivot columns: those that raise the rank of the columns before them
                let mut pivots: Vec<usize> = Vec::new();
                for c in 0..cols {
                    let mut with = pivots.clone();
                    with.push(c);
                    let sub = matrix(
                        m.iter()
                            .map(|r| with.iter().map(|&j| r[j].clone()).collect())
                            .collect(),
                    )?;
                    if sub.rank() > pivots.len() {
                        pivots = with;
                    }
                }
                self.taken.push(Decision::Columns(pivots));
            }
            return Ok(full.null_space());
        }
        let pivots = match self.take(|| Err(mismatch("pivot columns")))? {
            Decision::Columns(p) => p,
            _ => return Err(mismatch("pivot columns")),
        };
        if pivots.iter().any(|&p| p >= cols) || pivots.len() > m.len() {
            return Err(mismatch("pivot columns of this matrix"));
        }
        // the rows restricted to the pivot columns: exactly pivots.len() of them are
        // independent (the exact rank); keep those
        let rows: Vec<Vec<F>> = m
            .iter()
            .map(|r| pivots.iter().map(|&c| r[c].clone()).collect())
            .collect();
        let keep = independent_rows(&rows, pivots.len())?;
        let mut basis = Vec::new();
        for f in (0..cols).filter(|c| !pivots.contains(c)) {
            let mut v = vec![F::zero(); cols];
            v[f] = F::one();
            if !pivots.is_empty() {
                let sub = matrix(keep.iter().map(|&i| rows[i].clone()).collect())?;
                let rhs: Vec<F> = keep.iter().map(|&i| -m[i][f].clone()).collect();
                let x = sub
                    .solve_unique(&rhs)
                    .map_err(|e| CyclideError::InvalidArgument(e.to_string()))?;
                for (k, &p) in pivots.iter().enumerate() {
                    v[p] = x[k].clone();
                }
            }
            basis.push(v);
        }
        Ok(basis)
    }
}

/// A basis of the kernel of the matrix with rows `rows` by Gauss–Jordan elimination with
/// partial pivoting in which, for an inexact scalar, a candidate pivot of size at most
/// `10⁻¹⁰` times the largest entry counts as 0 (a rounding residue of an exact 0 is not
/// taken as a pivot; exact scalars: the reduced-row-echelon basis of
/// [`Matrix::null_space`]). For kernels a certificate only needs to be *some* basis of.
pub(crate) fn null_space_rounded<F: Scalar>(rows: &[Vec<F>]) -> Vec<Vec<F>> {
    let cols = rows.first().map_or(0, Vec::len);
    let tiny = crate::pivot::pivot_zero_test(rows, 1e-10);
    let mut m: Vec<Vec<F>> = rows.to_vec();
    let mut pivots = Vec::new();
    let mut r = 0;
    for c in 0..cols {
        if r >= m.len() {
            break;
        }
        let best = (r..m.len()).max_by(|&a, &b| {
            m[a][c]
                .to_f64()
                .abs()
                .partial_cmp(&m[b][c].to_f64().abs())
                .unwrap_or(core::cmp::Ordering::Equal)
        });
        let Some(p) = best.filter(|&p| !tiny(&m[p][c])) else {
            continue;
        };
        m.swap(p, r);
        let inv = F::one() / m[r][c].clone();
        for v in m[r].iter_mut() {
            *v = v.clone() * inv.clone();
        }
        let prow = m[r].clone();
        for (i, row) in m.iter_mut().enumerate() {
            if i == r {
                continue;
            }
            let f = row[c].clone();
            for j in 0..cols {
                row[j] = row[j].clone() - f.clone() * prow[j].clone();
            }
            row[c] = F::zero();
        }
        pivots.push(c);
        r += 1;
    }
    (0..cols)
        .filter(|c| !pivots.contains(c))
        .map(|f| {
            let mut v = vec![F::zero(); cols];
            v[f] = F::one();
            for (i, &p) in pivots.iter().enumerate() {
                v[p] = -m[i][f].clone();
            }
            v
        })
        .collect()
}

/// `k` rows of `rows` that are linearly independent (partial pivoting by `f64` magnitude;
/// the caller knows the exact rank is `k`).
fn independent_rows<F: Scalar>(rows: &[Vec<F>], k: usize) -> Result<Vec<usize>, CyclideError> {
    if rows.len() == k {
        return Ok((0..k).collect());
    }
    let mut m: Vec<Vec<F>> = rows.to_vec();
    let mut order: Vec<usize> = (0..rows.len()).collect();
    for c in 0..k {
        let best = (c..m.len())
            .max_by(|&a, &b| {
                m[a][c]
                    .to_f64()
                    .abs()
                    .partial_cmp(&m[b][c].to_f64().abs())
                    .unwrap_or(core::cmp::Ordering::Equal)
            })
            .ok_or_else(|| mismatch("a full-rank system"))?;
        m.swap(c, best);
        order.swap(c, best);
        if m[c][c].is_zero() {
            return Err(mismatch("a full-rank system"));
        }
        let prow = m[c].clone();
        for row in m.iter_mut().skip(c + 1) {
            let f = row[c].clone() / prow[c].clone();
            for (x, p) in row.iter_mut().zip(&prow).skip(c).take(k - c) {
                *x = x.clone() - f.clone() * p.clone();
            }
        }
    }
    let mut keep: Vec<usize> = order.into_iter().take(k).collect();
    keep.sort_unstable();
    Ok(keep)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    /// The exact kernel basis's pivot columns, replayed in `f64`, give the same basis
    /// (up to rounding) although an `f64` rounding residue stands where the exact
    /// elimination has a 0.
    #[test]
    fn replayed_null_space_keeps_the_exact_pivots() {
        // rows (1/10, 3/10, 1, 0) and (3/10, 9/10, 1, 1): column 1 is 3 × column 0, so
        // after eliminating column 0 it is 0 exactly, a residue in f64 (1/10 is not binary)
        let tenth = |n: i64| q(n) / q(10);
        let exact = vec![
            vec![tenth(1), tenth(3), q(1), q(0)],
            vec![tenth(3), tenth(9), q(1), q(1)],
        ];
        let mut rec = Route::record();
        let kernel = rec.null_space(&exact).unwrap();
        assert_eq!(rec.decisions(), &[Decision::Columns(vec![0, 2])]);
        assert_eq!(kernel.len(), 2);
        let float: Vec<Vec<f64>> = exact
            .iter()
            .map(|r| r.iter().map(Scalar::to_f64).collect())
            .collect();
        let plain = Route::free().null_space(&float).unwrap();
        let differs = plain.len() != kernel.len()
            || kernel.iter().zip(&plain).any(|(e, f)| {
                e.iter()
                    .zip(f)
                    .any(|(a, b)| (Scalar::to_f64(a) - b).abs() > 1e-6)
            });
        assert!(
            differs,
            "the f64 elimination should take the residue as a pivot: {plain:?}"
        );
        let replayed = rec.replay().null_space(&float).unwrap();
        assert_eq!(replayed.len(), kernel.len());
        for (e, f) in kernel.iter().zip(&replayed) {
            for (a, b) in e.iter().zip(f) {
                assert!((Scalar::to_f64(a) - b).abs() < 1e-14, "{a} vs {b}");
            }
        }
    }

    #[test]
    fn a_square_decided_exactly_is_replayed_either_way() {
        let mut rec = Route::record();
        assert_eq!(rec.sqrt(&Rational::from(2)).unwrap(), None);
        assert_eq!(rec.sqrt(&Rational::from(4)).unwrap(), Some(q(2)));
        let mut rep = rec.replay();
        assert_eq!(rep.sqrt(&2.0f64).unwrap(), None);
        assert_eq!(rep.sqrt(&4.0f64).unwrap(), Some(2.0));
        assert!(rep.flag(|| true).is_err(), "nothing left to replay");
    }
}
