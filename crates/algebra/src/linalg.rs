//! Exact linear algebra over any [`Field`], and `f64` counterparts via nalgebra.
//!
//! [`Matrix<F>`] is a dense row-major matrix. The exact algorithms decide every zero
//! test exactly, so over [`Rational`] (or `Q(√d)`, `Q(i)`) they return the true rank,
//! kernel and solution set:
//!
//! * [`Matrix::determinant`], [`Matrix::rank`]: fraction-free Gaussian elimination
//!   (Bareiss 1968). With pivot `p₀ = 1`, step `k` updates
//!   `m_ij ← (m_kk·m_ij − m_ik·m_kj) / p_{k−1}` for `i, j > k`; the division is exact
//!   and every intermediate entry is a minor of the input, so entry sizes stay
//!   polynomial; `det = ± m_{n−1,n−1}` (sign from row swaps).
//!   [`Matrix::determinant_integral`] (for `Matrix<Rational>`) first multiplies row
//!   `i` by the lcm `Lᵢ` of its denominators, runs Bareiss on integers and returns
//!   `det / ∏Lᵢ`.
//! * [`Matrix::rref`], [`Matrix::solve`], [`Matrix::null_space`], [`Matrix::inverse`]:
//!   Gauss–Jordan elimination to the reduced row echelon form `R = rref(A)` with pivot
//!   columns `P`. `A x = b` is inconsistent iff `rref([A | b])` has a pivot in the last
//!   column; otherwise `xₚ = R_{·,n}` on pivot columns (free variables 0) is a
//!   particular solution, and the kernel has the basis `e_f − Σᵢ R_{i,f} e_{P(i)}`, one
//!   vector per free column `f`. `rank + nullity = cols`.
//!
//! The generic algorithms also run on `f64` (which implements [`Field`]) but then test
//! floating-point values against exact zero; for floating point use the SVD/LU based
//! [`solve_f64`], [`solve_least_squares_f64`], [`rank_f64`] and [`null_space_f64`].

use crate::rational::Rational;
use crate::scalar::{Field, Ring, Scalar};
use core::fmt;
use dashu_base::Gcd;
use dashu_int::{IBig, UBig};
use nalgebra::{DMatrix, DVector};
use thiserror::Error;

/// Errors of the linear-algebra layer.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LinalgError {
    /// Operand shapes do not fit together.
    #[error("dimension mismatch in {op}: expected {expected}, found {found}")]
    DimensionMismatch {
        /// The operation.
        op: &'static str,
        /// The required shape.
        expected: String,
        /// The given shape.
        found: String,
    },
    /// The operation needs a square matrix.
    #[error("{op} needs a square matrix, got {rows}×{cols}")]
    NotSquare {
        /// The operation.
        op: &'static str,
        /// Rows of the given matrix.
        rows: usize,
        /// Columns of the given matrix.
        cols: usize,
    },
    /// The matrix is singular (exactly, or numerically for the `f64` functions).
    #[error("{op}: the matrix is singular")]
    Singular {
        /// The operation.
        op: &'static str,
    },
    /// An index outside the matrix.
    #[error("index ({row}, {col}) out of bounds for a {rows}×{cols} matrix")]
    IndexOutOfBounds {
        /// Requested row.
        row: usize,
        /// Requested column.
        col: usize,
        /// Rows of the matrix.
        rows: usize,
        /// Columns of the matrix.
        cols: usize,
    },
    /// A NaN or infinite entry in an `f64` computation.
    #[error("{op}: the input has a non-finite entry")]
    NonFinite {
        /// The operation.
        op: &'static str,
    },
    /// A tolerance that is negative or not finite.
    #[error("{op}: tolerance must be finite and non-negative, got {tol}")]
    InvalidTolerance {
        /// The operation.
        op: &'static str,
        /// The given tolerance.
        tol: f64,
    },
    /// The singular value decomposition did not converge.
    #[error("{op}: the singular value decomposition did not converge")]
    NoConvergence {
        /// The operation.
        op: &'static str,
    },
}

impl From<LinalgError> for crate::error::AlgebraError {
    fn from(e: LinalgError) -> Self {
        use crate::error::AlgebraError as A;
        let msg = e.to_string();
        match e {
            LinalgError::DimensionMismatch { .. } | LinalgError::NotSquare { .. } => {
                A::Mismatch(msg)
            }
            LinalgError::Singular { .. } => A::DivisionByZero(msg),
            LinalgError::NoConvergence { .. } => A::NotRepresentable(msg),
            LinalgError::IndexOutOfBounds { .. }
            | LinalgError::NonFinite { .. }
            | LinalgError::InvalidTolerance { .. } => A::InvalidArgument(msg),
        }
    }
}

/// The solution set of a linear system `A x = b`.
#[derive(Debug, Clone, PartialEq)]
pub enum Solution<F> {
    /// Exactly one solution.
    Unique(Vec<F>),
    /// Infinitely many: `particular + Σ λₖ null_space[k]`, the kernel basis non-empty.
    Underdetermined {
        /// One solution (free variables set to zero).
        particular: Vec<F>,
        /// A basis of the kernel of `A`.
        null_space: Vec<Vec<F>>,
    },
    /// No solution.
    Inconsistent,
}

impl<F> Solution<F> {
    /// A solution, if there is one.
    pub fn particular(&self) -> Option<&[F]> {
        match self {
            Solution::Unique(x) => Some(x),
            Solution::Underdetermined { particular, .. } => Some(particular),
            Solution::Inconsistent => None,
        }
    }

    /// `true` for a unique solution.
    pub fn is_unique(&self) -> bool {
        matches!(self, Solution::Unique(_))
    }

    /// `true` if the system has at least one solution.
    pub fn is_consistent(&self) -> bool {
        !matches!(self, Solution::Inconsistent)
    }
}

/// A dense `rows × cols` matrix, entries stored row-major.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Matrix<F> {
    rows: usize,
    cols: usize,
    data: Vec<F>,
}

fn shape(r: usize, c: usize) -> String {
    format!("{r}×{c}")
}

impl<F> Matrix<F> {
    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// `(rows, cols)`.
    pub fn shape(&self) -> (usize, usize) {
        (self.rows, self.cols)
    }

    /// `true` if `rows = cols`.
    pub fn is_square(&self) -> bool {
        self.rows == self.cols
    }

    /// The entries, row-major.
    pub fn as_slice(&self) -> &[F] {
        &self.data
    }

    /// Consumes the matrix, returning its row-major entries.
    pub fn into_vec(self) -> Vec<F> {
        self.data
    }

    /// The entry `(i, j)`, `None` outside the matrix.
    pub fn get(&self, i: usize, j: usize) -> Option<&F> {
        if i < self.rows && j < self.cols {
            self.data.get(i * self.cols + j)
        } else {
            None
        }
    }

    /// Row `i`, `None` outside the matrix.
    pub fn row(&self, i: usize) -> Option<&[F]> {
        if i < self.rows {
            self.data.get(i * self.cols..(i + 1) * self.cols)
        } else {
            None
        }
    }

    /// Iterates over the rows.
    pub fn row_iter(&self) -> impl Iterator<Item = &[F]> {
        (0..self.rows).filter_map(move |i| self.row(i))
    }

    /// Sets entry `(i, j)`.
    ///
    /// # Errors
    /// [`LinalgError::IndexOutOfBounds`].
    pub fn set(&mut self, i: usize, j: usize, v: F) -> Result<(), LinalgError> {
        let (rows, cols) = (self.rows, self.cols);
        let oob = LinalgError::IndexOutOfBounds {
            row: i,
            col: j,
            rows,
            cols,
        };
        if i >= rows || j >= cols {
            return Err(oob);
        }
        match self.data.get_mut(i * cols + j) {
            Some(slot) => {
                *slot = v;
                Ok(())
            }
            None => Err(oob),
        }
    }

    /// Applies `f` to every entry (e.g. `Rational → f64`).
    pub fn map<G>(&self, f: impl Fn(&F) -> G) -> Matrix<G> {
        Matrix {
            rows: self.rows,
            cols: self.cols,
            data: self.data.iter().map(f).collect(),
        }
    }
}

impl<F: Clone> Matrix<F> {
    /// The rows of `[A | b]` for solving `A x = b` (`op` names the caller in the error).
    ///
    /// # Errors
    /// [`LinalgError::DimensionMismatch`] unless `b.len() = A.rows`.
    fn augmented(&self, b: &[F], op: &'static str) -> Result<Vec<Vec<F>>, LinalgError> {
        if b.len() != self.rows {
            return Err(LinalgError::DimensionMismatch {
                op,
                expected: format!("a right-hand side of length {}", self.rows),
                found: format!("length {}", b.len()),
            });
        }
        Ok(self
            .row_iter()
            .zip(b)
            .map(|(r, bi)| {
                let mut v = r.to_vec();
                v.push(bi.clone());
                v
            })
            .collect())
    }

    /// From row-major entries.
    ///
    /// # Errors
    /// [`LinalgError::DimensionMismatch`] unless `data.len() = rows·cols`.
    pub fn from_vec(rows: usize, cols: usize, data: Vec<F>) -> Result<Self, LinalgError> {
        if rows.checked_mul(cols) != Some(data.len()) {
            return Err(LinalgError::DimensionMismatch {
                op: "Matrix::from_vec",
                expected: format!(
                    "{} entries ({})",
                    rows.saturating_mul(cols),
                    shape(rows, cols)
                ),
                found: format!("{} entries", data.len()),
            });
        }
        Ok(Matrix { rows, cols, data })
    }

    /// From a list of rows of equal length (no rows: the `0×0` matrix).
    ///
    /// # Errors
    /// [`LinalgError::DimensionMismatch`] naming the first row whose length differs
    /// from the first row's.
    pub fn from_rows(rows: Vec<Vec<F>>) -> Result<Self, LinalgError> {
        let cols = rows.first().map_or(0, Vec::len);
        let nrows = rows.len();
        let mut data = Vec::with_capacity(nrows.saturating_mul(cols));
        for (i, r) in rows.into_iter().enumerate() {
            if r.len() != cols {
                return Err(LinalgError::DimensionMismatch {
                    op: "Matrix::from_rows",
                    expected: format!("row {i} of length {cols}"),
                    found: format!("length {}", r.len()),
                });
            }
            data.extend(r);
        }
        Ok(Matrix {
            rows: nrows,
            cols,
            data,
        })
    }

    /// From a list of columns of length `rows` (`rows` is needed for an empty list).
    ///
    /// # Errors
    /// [`LinalgError::DimensionMismatch`] if a column's length is not `rows`.
    pub fn from_columns(rows: usize, columns: &[Vec<F>]) -> Result<Self, LinalgError> {
        for (j, c) in columns.iter().enumerate() {
            if c.len() != rows {
                return Err(LinalgError::DimensionMismatch {
                    op: "Matrix::from_columns",
                    expected: format!("column {j} of length {rows}"),
                    found: format!("length {}", c.len()),
                });
            }
        }
        let cols = columns.len();
        let mut data = Vec::with_capacity(rows.saturating_mul(cols));
        for i in 0..rows {
            for c in columns {
                if let Some(v) = c.get(i) {
                    data.push(v.clone());
                }
            }
        }
        Ok(Matrix { rows, cols, data })
    }

    /// The `rows × cols` matrix with entries `f(i, j)`.
    pub fn from_fn(rows: usize, cols: usize, f: impl Fn(usize, usize) -> F) -> Self {
        let mut data = Vec::with_capacity(rows.saturating_mul(cols));
        for i in 0..rows {
            for j in 0..cols {
                data.push(f(i, j));
            }
        }
        Matrix { rows, cols, data }
    }

    /// Column `j`, `None` outside the matrix.
    pub fn column(&self, j: usize) -> Option<Vec<F>> {
        if j >= self.cols {
            return None;
        }
        (0..self.rows).map(|i| self.get(i, j).cloned()).collect()
    }

    /// The transpose `Aᵀ`.
    pub fn transpose(&self) -> Self {
        let mut data = Vec::with_capacity(self.data.len());
        for j in 0..self.cols {
            for i in 0..self.rows {
                if let Some(v) = self.get(i, j) {
                    data.push(v.clone());
                }
            }
        }
        Matrix {
            rows: self.cols,
            cols: self.rows,
            data,
        }
    }

    fn rows_vec(&self) -> Vec<Vec<F>> {
        self.row_iter().map(<[F]>::to_vec).collect()
    }
}

impl<F: Ring> Matrix<F> {
    /// The zero matrix.
    pub fn zeros(rows: usize, cols: usize) -> Self {
        Matrix::from_fn(rows, cols, |_, _| F::zero())
    }

    /// The `n × n` identity.
    pub fn identity(n: usize) -> Self {
        Matrix::from_fn(n, n, |i, j| if i == j { F::one() } else { F::zero() })
    }

    /// The product `A·B`, `(AB)_ij = Σₖ A_ik B_kj`.
    ///
    /// # Errors
    /// [`LinalgError::DimensionMismatch`] unless `A.cols = B.rows`.
    pub fn mul(&self, other: &Matrix<F>) -> Result<Matrix<F>, LinalgError> {
        if self.cols != other.rows {
            return Err(LinalgError::DimensionMismatch {
                op: "Matrix::mul",
                expected: format!("{} rows on the right", self.cols),
                found: shape(other.rows, other.cols),
            });
        }
        let mut data = Vec::with_capacity(self.rows.saturating_mul(other.cols));
        for r in self.row_iter() {
            for j in 0..other.cols {
                let mut acc = F::zero();
                for (k, a) in r.iter().enumerate() {
                    if let Some(b) = other.get(k, j) {
                        acc += a.clone() * b.clone();
                    }
                }
                data.push(acc);
            }
        }
        Ok(Matrix {
            rows: self.rows,
            cols: other.cols,
            data,
        })
    }

    /// The product `A·v` with a column vector.
    ///
    /// # Errors
    /// [`LinalgError::DimensionMismatch`] unless `v.len() = A.cols`.
    pub fn mul_vec(&self, v: &[F]) -> Result<Vec<F>, LinalgError> {
        if v.len() != self.cols {
            return Err(LinalgError::DimensionMismatch {
                op: "Matrix::mul_vec",
                expected: format!("a vector of length {}", self.cols),
                found: format!("length {}", v.len()),
            });
        }
        Ok(self
            .row_iter()
            .map(|r| {
                r.iter()
                    .zip(v)
                    .fold(F::zero(), |acc, (a, b)| acc + a.clone() * b.clone())
            })
            .collect())
    }

    fn same_shape(&self, other: &Matrix<F>, op: &'static str) -> Result<(), LinalgError> {
        if self.shape() == other.shape() {
            Ok(())
        } else {
            Err(LinalgError::DimensionMismatch {
                op,
                expected: shape(self.rows, self.cols),
                found: shape(other.rows, other.cols),
            })
        }
    }

    /// The sum `A + B`.
    ///
    /// # Errors
    /// [`LinalgError::DimensionMismatch`] for different shapes.
    pub fn add(&self, other: &Matrix<F>) -> Result<Matrix<F>, LinalgError> {
        self.same_shape(other, "Matrix::add")?;
        Ok(Matrix {
            rows: self.rows,
            cols: self.cols,
            data: self
                .data
                .iter()
                .zip(&other.data)
                .map(|(a, b)| a.clone() + b.clone())
                .collect(),
        })
    }

    /// The difference `A − B`.
    ///
    /// # Errors
    /// [`LinalgError::DimensionMismatch`] for different shapes.
    pub fn sub(&self, other: &Matrix<F>) -> Result<Matrix<F>, LinalgError> {
        self.same_shape(other, "Matrix::sub")?;
        Ok(Matrix {
            rows: self.rows,
            cols: self.cols,
            data: self
                .data
                .iter()
                .zip(&other.data)
                .map(|(a, b)| a.clone() - b.clone())
                .collect(),
        })
    }

    /// `c·A` (each entry multiplied by `c` on the left).
    pub fn scale(&self, c: &F) -> Matrix<F> {
        self.map(|a| c.clone() * a.clone())
    }

    /// `true` if every entry is zero.
    pub fn is_zero(&self) -> bool {
        self.data.iter().all(|a| a.is_zero())
    }
}

impl<S: Scalar> Matrix<S> {
    /// The nearest-`f64` matrix.
    pub fn to_f64(&self) -> Matrix<f64> {
        self.map(|a| a.to_f64())
    }
}

/// Bareiss elimination on row vectors over a field: brings `m` to a fraction-free row
/// echelon form in place and returns `(rank, number of row swaps)`.
/// The pivot row for column `c` among rows `r..`: the first non-zero entry for exact
/// fields, the largest by [`Field::pivot_size`] for floating point (partial pivoting).
fn pivot_row<F: Field>(m: &[Vec<F>], r: usize, c: usize) -> Option<usize> {
    let first = (r..m.len()).find(|&i| !m[i][c].is_zero())?;
    let Some(mut best) = m[first][c].pivot_size() else {
        return Some(first);
    };
    let mut p = first;
    for (i, row) in m.iter().enumerate().skip(first + 1) {
        if let Some(sz) = row[c].pivot_size() {
            if sz > best {
                best = sz;
                p = i;
            }
        }
    }
    Some(p)
}

fn bareiss_echelon<F: Field>(m: &mut [Vec<F>], cols: usize) -> (usize, usize) {
    let rows = m.len();
    let mut prev = F::one();
    let mut r = 0;
    let mut swaps = 0;
    for c in 0..cols {
        if r >= rows {
            break;
        }
        let Some(p) = pivot_row(m, r, c) else {
            continue;
        };
        if p != r {
            m.swap(p, r);
            swaps += 1;
        }
        let pivot = m[r][c].clone();
        let (top, bottom) = m.split_at_mut(r + 1);
        let prow = &top[r];
        for row in bottom.iter_mut() {
            crate::budget::checkpoint();
            let f = row[c].clone();
            for j in c + 1..cols {
                let v =
                    (pivot.clone() * row[j].clone() - f.clone() * prow[j].clone()) / prev.clone();
                row[j] = v;
            }
            row[c] = F::zero();
        }
        prev = pivot;
        r += 1;
    }
    (r, swaps)
}

/// Gauss–Jordan elimination to the reduced row echelon form on the first `cols`
/// columns of `m` (all columns are transformed); returns the pivot columns.
fn gauss_jordan<F: Field>(m: &mut [Vec<F>], cols: usize) -> Vec<usize> {
    let rows = m.len();
    let width = m.first().map_or(0, Vec::len);
    let mut pivots = Vec::new();
    let mut r = 0;
    for c in 0..cols {
        if r >= rows {
            break;
        }
        let Some(p) = pivot_row(m, r, c) else {
            continue;
        };
        m.swap(p, r);
        let Some(inv) = m[r][c].inv() else {
            continue;
        };
        for v in m[r].iter_mut().skip(c) {
            *v = v.clone() * inv.clone();
        }
        let prow = m[r].clone();
        for (i, row) in m.iter_mut().enumerate() {
            if i == r || row[c].is_zero() {
                continue;
            }
            crate::budget::checkpoint();
            let f = row[c].clone();
            for j in c..width {
                row[j] = row[j].clone() - f.clone() * prow[j].clone();
            }
        }
        pivots.push(c);
        r += 1;
    }
    pivots
}

/// The kernel basis from a reduced row echelon form `r` (first `cols` columns).
fn kernel_from_rref<F: Field>(r: &[Vec<F>], pivots: &[usize], cols: usize) -> Vec<Vec<F>> {
    let mut basis = Vec::new();
    for f in (0..cols).filter(|c| !pivots.contains(c)) {
        let mut v = vec![F::zero(); cols];
        v[f] = F::one();
        for (i, &p) in pivots.iter().enumerate() {
            v[p] = -r[i][f].clone();
        }
        basis.push(v);
    }
    basis
}

impl<F: Field> Matrix<F> {
    fn require_square(&self, op: &'static str) -> Result<(), LinalgError> {
        if self.is_square() {
            Ok(())
        } else {
            Err(LinalgError::NotSquare {
                op,
                rows: self.rows,
                cols: self.cols,
            })
        }
    }

    /// The determinant by fraction-free Bareiss elimination (module documentation);
    /// `det` of the `0×0` matrix is 1.
    ///
    /// # Errors
    /// [`LinalgError::NotSquare`].
    pub fn determinant(&self) -> Result<F, LinalgError> {
        self.require_square("determinant")?;
        let n = self.rows;
        if n == 0 {
            return Ok(F::one());
        }
        let mut m = self.rows_vec();
        let (rank, swaps) = bareiss_echelon(&mut m, n);
        if rank < n {
            return Ok(F::zero());
        }
        let d = m[n - 1][n - 1].clone();
        Ok(if swaps % 2 == 1 { -d } else { d })
    }

    /// The rank (fraction-free elimination; exact over exact fields).
    pub fn rank(&self) -> usize {
        let mut m = self.rows_vec();
        bareiss_echelon(&mut m, self.cols).0
    }

    /// The reduced row echelon form and its pivot columns (Gauss–Jordan).
    pub fn rref(&self) -> (Matrix<F>, Vec<usize>) {
        let mut m = self.rows_vec();
        let pivots = gauss_jordan(&mut m, self.cols);
        let data = m.into_iter().flatten().collect();
        (
            Matrix {
                rows: self.rows,
                cols: self.cols,
                data,
            },
            pivots,
        )
    }

    /// A basis of the kernel `{x : A x = 0}` (one vector per free column of
    /// `rref(A)`; empty if `A` has full column rank).
    pub fn null_space(&self) -> Vec<Vec<F>> {
        let mut m = self.rows_vec();
        let pivots = gauss_jordan(&mut m, self.cols);
        kernel_from_rref(&m, &pivots, self.cols)
    }

    /// The solution set of `A x = b` (module documentation).
    ///
    /// # Errors
    /// [`LinalgError::DimensionMismatch`] unless `b.len() = A.rows`.
    pub fn solve(&self, b: &[F]) -> Result<Solution<F>, LinalgError> {
        let n = self.cols;
        let mut m = self.augmented(b, "solve")?;
        let pivots = gauss_jordan(&mut m, n + 1);
        if pivots.last() == Some(&n) {
            return Ok(Solution::Inconsistent);
        }
        let mut x = vec![F::zero(); n];
        for (i, &p) in pivots.iter().enumerate() {
            x[p] = m[i][n].clone();
        }
        if pivots.len() == n {
            return Ok(Solution::Unique(x));
        }
        Ok(Solution::Underdetermined {
            particular: x,
            null_space: kernel_from_rref(&m, &pivots, n),
        })
    }

    /// The unique solution of `A x = b`.
    ///
    /// # Errors
    /// [`LinalgError::DimensionMismatch`], or [`LinalgError::Singular`] if the system
    /// has no solution or infinitely many.
    pub fn solve_unique(&self, b: &[F]) -> Result<Vec<F>, LinalgError> {
        match self.solve(b)? {
            Solution::Unique(x) => Ok(x),
            _ => Err(LinalgError::Singular { op: "solve_unique" }),
        }
    }

    /// The inverse, by Gauss–Jordan elimination of `[A | I]`.
    ///
    /// # Errors
    /// [`LinalgError::NotSquare`], [`LinalgError::Singular`].
    pub fn inverse(&self) -> Result<Matrix<F>, LinalgError> {
        self.require_square("inverse")?;
        let n = self.rows;
        let mut m: Vec<Vec<F>> = self
            .row_iter()
            .enumerate()
            .map(|(i, r)| {
                let mut v = r.to_vec();
                v.extend((0..n).map(|j| if i == j { F::one() } else { F::zero() }));
                v
            })
            .collect();
        let pivots = gauss_jordan(&mut m, n);
        if pivots.len() < n {
            return Err(LinalgError::Singular { op: "inverse" });
        }
        let data = m.into_iter().flat_map(|r| r.into_iter().skip(n)).collect();
        Ok(Matrix {
            rows: n,
            cols: n,
            data,
        })
    }
}

fn lcm(a: &UBig, b: &UBig) -> UBig {
    let g = a.gcd(b);
    a / g * b
}

/// Bareiss determinant over the integers (exact divisions).
fn bareiss_det_int(mut m: Vec<Vec<IBig>>) -> IBig {
    let n = m.len();
    if n == 0 {
        return IBig::ONE;
    }
    let mut prev = IBig::ONE;
    let mut negate = false;
    for k in 0..n {
        let Some(p) = (k..n).find(|&i| m[i][k] != IBig::ZERO) else {
            return IBig::ZERO;
        };
        if p != k {
            m.swap(p, k);
            negate = !negate;
        }
        let (top, bottom) = m.split_at_mut(k + 1);
        let prow = &top[k];
        let pivot = &prow[k];
        for row in bottom.iter_mut() {
            for j in k + 1..n {
                row[j] = (pivot * &row[j] - &row[k] * &prow[j]) / &prev;
            }
            row[k] = IBig::ZERO;
        }
        prev = prow[k].clone();
    }
    if negate {
        -prev
    } else {
        prev
    }
}

/// Rows of rationals multiplied each by the lcm of its denominators (the row space and so
/// the reduced row echelon form are unchanged).
fn integral_rows<'a>(rows: impl Iterator<Item = &'a [Rational]>) -> Vec<Vec<IBig>> {
    rows.map(|r| {
        let l = r.iter().fold(UBig::ONE, |l, q| lcm(&l, q.denominator()));
        let li = IBig::from(l);
        r.iter()
            .map(|q| q.numerator() * &li / IBig::from(q.denominator().clone()))
            .collect()
    })
    .collect()
}

impl Matrix<Rational> {
    /// The particular solution of [`Matrix::solve`] (free variables zero), `None` for an
    /// inconsistent system, by fraction-free elimination on integers: row `i` of `[A | b]`
    /// is multiplied by the lcm of its denominators, Bareiss' elimination (module
    /// documentation) brings it to a row echelon form with the pivot columns of
    /// `rref([A | b])` (a row echelon form of the same row space has the same pivot
    /// columns), and back substitution over `Q` on the pivot columns gives the unique
    /// solution with the free variables zero — the particular solution of
    /// [`Matrix::solve`], which is read off the reduced row echelon form.
    ///
    /// # Errors
    /// [`LinalgError::DimensionMismatch`] unless `b.len() = A.rows`.
    pub fn particular_solution_integral(
        &self,
        b: &[Rational],
    ) -> Result<Option<Vec<Rational>>, LinalgError> {
        let n = self.cols;
        let aug = self.augmented(b, "particular_solution_integral")?;
        let mut m = integral_rows(aug.iter().map(Vec::as_slice));
        // Bareiss to a row echelon form on all n + 1 columns
        let rows = m.len();
        let mut prev = IBig::ONE;
        let mut pivots: Vec<usize> = Vec::new();
        let mut r = 0;
        for c in 0..=n {
            if r >= rows {
                break;
            }
            let Some(p) = (r..rows).find(|&i| m[i][c] != IBig::ZERO) else {
                continue;
            };
            m.swap(p, r);
            let (top, bottom) = m.split_at_mut(r + 1);
            let prow = &top[r];
            let pivot = &prow[c];
            for row in bottom.iter_mut() {
                crate::budget::checkpoint();
                for j in c + 1..=n {
                    row[j] = (pivot * &row[j] - &row[c] * &prow[j]) / &prev;
                }
                row[c] = IBig::ZERO;
            }
            prev = prow[c].clone();
            pivots.push(c);
            r += 1;
        }
        if pivots.last() == Some(&n) {
            return Ok(None);
        }
        // back substitution, free variables zero
        let mut x = vec![Rational::ZERO; n];
        for (i, &p) in pivots.iter().enumerate().rev() {
            let row = &m[i];
            let mut acc = Rational::from(row[n].clone());
            for &q in pivots.iter().skip(i + 1) {
                acc -= Rational::from(row[q].clone()) * &x[q];
            }
            x[p] = acc / Rational::from(row[p].clone());
        }
        Ok(Some(x))
    }

    /// The determinant with the elimination on integers: row `i` is multiplied by the
    /// lcm `Lᵢ` of its denominators, Bareiss runs on the integer matrix (every division
    /// exact), and `det A = det(diag(L)·A) / ∏ Lᵢ`. Equal to [`Matrix::determinant`];
    /// faster when the entries have many different denominators.
    ///
    /// # Errors
    /// [`LinalgError::NotSquare`].
    pub fn determinant_integral(&self) -> Result<Rational, LinalgError> {
        self.require_square("determinant_integral")?;
        let mut scale = UBig::ONE;
        let mut rows = Vec::with_capacity(self.rows);
        for r in self.row_iter() {
            let l = r.iter().fold(UBig::ONE, |l, q| lcm(&l, q.denominator()));
            let li = IBig::from(l.clone());
            rows.push(
                r.iter()
                    .map(|q| q.numerator() * &li / IBig::from(q.denominator().clone()))
                    .collect(),
            );
            scale *= l;
        }
        let d = bareiss_det_int(rows);
        Ok(Rational::from_parts(d, scale))
    }
}

impl<F: fmt::Display> fmt::Display for Matrix<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("[")?;
        for (i, r) in self.row_iter().enumerate() {
            if i > 0 {
                f.write_str("; ")?;
            }
            for (j, v) in r.iter().enumerate() {
                if j > 0 {
                    f.write_str(", ")?;
                }
                write!(f, "{v}")?;
            }
        }
        f.write_str("]")
    }
}

/// The solution set of `A x = b`; see [`Matrix::solve`].
///
/// # Errors
/// [`LinalgError::DimensionMismatch`] unless `b.len() = A.rows`.
pub fn solve<F: Field>(a: &Matrix<F>, b: &[F]) -> Result<Solution<F>, LinalgError> {
    a.solve(b)
}

// ---------------------------------------------------------------------------------
// f64 via nalgebra
// ---------------------------------------------------------------------------------

/// Maximum SVD iterations (nalgebra's `try_svd`); far above what finite input needs.
const SVD_MAX_ITER: usize = 100_000;

/// The nalgebra matrix with the same entries.
pub fn to_nalgebra(a: &Matrix<f64>) -> DMatrix<f64> {
    DMatrix::from_row_slice(a.rows, a.cols, &a.data)
}

/// The [`Matrix`] with the same entries as a nalgebra matrix.
pub fn from_nalgebra(m: &DMatrix<f64>) -> Matrix<f64> {
    Matrix::from_fn(m.nrows(), m.ncols(), |i, j| m[(i, j)])
}

fn check_finite(a: &Matrix<f64>, b: &[f64], op: &'static str) -> Result<(), LinalgError> {
    if a.data.iter().chain(b).all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(LinalgError::NonFinite { op })
    }
}

fn check_tol(tol: f64, op: &'static str) -> Result<(), LinalgError> {
    if tol.is_finite() && tol >= 0.0 {
        Ok(())
    } else {
        Err(LinalgError::InvalidTolerance { op, tol })
    }
}

/// Singular values (descending) and the full `cols × cols` matrix `Vᵀ` of `A`.
/// A wide matrix is padded with zero rows so that `Vᵀ` is square.
fn svd_full(a: &Matrix<f64>, op: &'static str) -> Result<(Vec<f64>, DMatrix<f64>), LinalgError> {
    let n = a.cols;
    let mut m = to_nalgebra(a);
    if a.rows < n {
        m = m.resize_vertically(n, 0.0);
    }
    let svd = m
        .try_svd(false, true, f64::EPSILON, SVD_MAX_ITER)
        .ok_or(LinalgError::NoConvergence { op })?;
    let vt = svd.v_t.ok_or(LinalgError::NoConvergence { op })?;
    let sv: Vec<f64> = svd.singular_values.iter().copied().collect();
    if sv.iter().chain(vt.iter()).all(|x| x.is_finite()) {
        Ok((sv, vt))
    } else {
        // entries near f64::MAX can overflow inside the decomposition
        Err(LinalgError::NonFinite { op })
    }
}

/// Solves the square system `A x = b` by LU decomposition with partial pivoting.
///
/// # Errors
/// [`LinalgError::NotSquare`], [`LinalgError::DimensionMismatch`],
/// [`LinalgError::NonFinite`], [`LinalgError::Singular`] (a zero pivot or a non-finite
/// solution).
pub fn solve_f64(a: &Matrix<f64>, b: &[f64]) -> Result<Vec<f64>, LinalgError> {
    a.require_square("solve_f64")?;
    if b.len() != a.rows {
        return Err(LinalgError::DimensionMismatch {
            op: "solve_f64",
            expected: format!("a right-hand side of length {}", a.rows),
            found: format!("length {}", b.len()),
        });
    }
    check_finite(a, b, "solve_f64")?;
    if a.rows == 0 {
        return Ok(Vec::new());
    }
    let x = to_nalgebra(a)
        .lu()
        .solve(&DVector::from_column_slice(b))
        .ok_or(LinalgError::Singular { op: "solve_f64" })?;
    if x.iter().all(|v| v.is_finite()) {
        Ok(x.iter().copied().collect())
    } else {
        Err(LinalgError::Singular { op: "solve_f64" })
    }
}

/// The minimum-norm least-squares solution of `A x ≈ b` (any shape) by the SVD,
/// treating singular values `σ ≤ tol·σ_max` as zero.
///
/// # Errors
/// [`LinalgError::DimensionMismatch`], [`LinalgError::NonFinite`],
/// [`LinalgError::InvalidTolerance`], [`LinalgError::NoConvergence`].
pub fn solve_least_squares_f64(
    a: &Matrix<f64>,
    b: &[f64],
    tol: f64,
) -> Result<Vec<f64>, LinalgError> {
    const OP: &str = "solve_least_squares_f64";
    if b.len() != a.rows {
        return Err(LinalgError::DimensionMismatch {
            op: OP,
            expected: format!("a right-hand side of length {}", a.rows),
            found: format!("length {}", b.len()),
        });
    }
    check_tol(tol, OP)?;
    check_finite(a, b, OP)?;
    if a.rows == 0 || a.cols == 0 {
        return Ok(vec![0.0; a.cols]);
    }
    let svd = to_nalgebra(a)
        .try_svd(true, true, f64::EPSILON, SVD_MAX_ITER)
        .ok_or(LinalgError::NoConvergence { op: OP })?;
    let smax = svd.singular_values.iter().copied().fold(0.0, f64::max);
    let eps = tol * smax;
    let x = svd
        .solve(&DVector::from_column_slice(b), eps)
        .map_err(|_| LinalgError::NoConvergence { op: OP })?;
    if x.iter().all(|v| v.is_finite()) {
        Ok(x.iter().copied().collect())
    } else {
        Err(LinalgError::NonFinite { op: OP })
    }
}

/// The numerical rank: the number of singular values `σ > tol·σ_max`.
///
/// # Errors
/// [`LinalgError::NonFinite`], [`LinalgError::InvalidTolerance`],
/// [`LinalgError::NoConvergence`].
pub fn rank_f64(a: &Matrix<f64>, tol: f64) -> Result<usize, LinalgError> {
    check_tol(tol, "rank_f64")?;
    check_finite(a, &[], "rank_f64")?;
    if a.rows == 0 || a.cols == 0 {
        return Ok(0);
    }
    let (sv, _) = svd_full(a, "rank_f64")?;
    let smax = sv.iter().copied().fold(0.0, f64::max);
    Ok(sv.iter().filter(|&&s| s > tol * smax && s > 0.0).count())
}

/// An orthonormal basis of the numerical kernel: the right singular vectors of the
/// singular values `σ ≤ tol·σ_max` (and all of them for the zero matrix). A wide
/// matrix is padded with zero rows so that the full `Vᵀ` is computed.
///
/// # Errors
/// [`LinalgError::NonFinite`], [`LinalgError::InvalidTolerance`],
/// [`LinalgError::NoConvergence`].
pub fn null_space_f64(a: &Matrix<f64>, tol: f64) -> Result<Vec<Vec<f64>>, LinalgError> {
    check_tol(tol, "null_space_f64")?;
    check_finite(a, &[], "null_space_f64")?;
    let n = a.cols;
    if a.rows == 0 || n == 0 {
        return Ok((0..n)
            .map(|k| (0..n).map(|j| if j == k { 1.0 } else { 0.0 }).collect())
            .collect());
    }
    let (sv, vt) = svd_full(a, "null_space_f64")?;
    let smax = sv.iter().copied().fold(0.0, f64::max);
    Ok((0..vt.nrows())
        .filter(|&k| {
            let s = sv.get(k).copied().unwrap_or(0.0);
            !(s > tol * smax && s > 0.0)
        })
        .map(|k| vt.row(k).iter().copied().collect())
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Partial pivoting in f64: without it the rounding residue 3 − 5·0.6000000000000001
    /// (≈ −4·10⁻¹⁶) became the second pivot and the solution was off by 25 %. The
    /// exact solution of this system is (3/5, 1, 1, −1).
    #[test]
    fn f64_solve_pivots_by_size() {
        let a = Matrix::from_rows(vec![
            vec![-5.0, 3.0, 0.0, 0.0],
            vec![-5.0, 3.0, 1.0, 1.0],
            vec![0.0, 0.0, 0.0, -1.0],
            vec![0.0, 1.0, 0.0, 1.0],
        ])
        .expect("matrix");
        let x = a.solve_unique(&[0.0, 0.0, 1.0, 0.0]).expect("solution");
        for (xi, e) in x.iter().zip([0.6, 1.0, 1.0, -1.0]) {
            assert!((xi - e).abs() < 1e-14, "{x:?}");
        }
        assert!((a.determinant().expect("det") - 5.0).abs() < 1e-13);
    }
    use dashu_int::IBig;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_parts_signed(IBig::from(p), IBig::from(d))
    }

    fn m(rows: &[&[i64]]) -> Matrix<Rational> {
        Matrix::from_rows(
            rows.iter()
                .map(|r| r.iter().map(|&x| Rational::from(x)).collect())
                .collect(),
        )
        .expect("rectangular")
    }

    #[test]
    fn construction_and_access() {
        assert!(Matrix::from_rows(vec![vec![1.0, 2.0], vec![3.0]]).is_err());
        assert!(Matrix::from_vec(2, 2, vec![1.0; 3]).is_err());
        assert!(Matrix::<f64>::from_vec(usize::MAX, 2, vec![]).is_err());
        let mut a = m(&[&[1, 2, 3], &[4, 5, 6]]);
        assert_eq!(a.shape(), (2, 3));
        assert_eq!(a.get(1, 2), Some(&q(6, 1)));
        assert_eq!(a.get(2, 0), None);
        assert!(a.set(0, 3, q(0, 1)).is_err());
        a.set(0, 0, q(7, 1)).expect("in range");
        assert_eq!(a.row(0), Some(&[q(7, 1), q(2, 1), q(3, 1)][..]));
        assert_eq!(a.column(1), Some(vec![q(2, 1), q(5, 1)]));
        assert_eq!(a.transpose().shape(), (3, 2));
        assert_eq!(a.transpose().transpose(), a);
        let cols = Matrix::from_columns(2, &[vec![q(1, 1), q(2, 1)]]).expect("fits");
        assert_eq!(cols, m(&[&[1], &[2]]));
        assert!(a.mul(&a).is_err());
        assert_eq!(a.to_string(), "[7, 2, 3; 4, 5, 6]");
    }

    #[test]
    fn determinant_rank_inverse() {
        let a = m(&[&[2, 1, 1], &[1, 3, 2], &[1, 1, 1]]);
        assert_eq!(a.determinant(), Ok(q(1, 1)));
        assert_eq!(a.determinant_integral(), Ok(q(1, 1)));
        let inv = a.inverse().expect("det 1");
        assert_eq!(a.mul(&inv).expect("square"), Matrix::identity(3));
        let s = m(&[&[1, 2], &[2, 4]]);
        assert_eq!(s.determinant(), Ok(q(0, 1)));
        assert_eq!(s.rank(), 1);
        assert!(matches!(s.inverse(), Err(LinalgError::Singular { .. })));
        assert!(matches!(
            m(&[&[1, 2]]).determinant(),
            Err(LinalgError::NotSquare { .. })
        ));
        // needs a row swap: det [[0,1],[1,0]] = −1
        assert_eq!(m(&[&[0, 1], &[1, 0]]).determinant(), Ok(q(-1, 1)));
        assert_eq!(m(&[&[0, 1], &[1, 0]]).determinant_integral(), Ok(q(-1, 1)));
        let r =
            Matrix::from_rows(vec![vec![q(1, 2), q(1, 3)], vec![q(1, 4), q(1, 5)]]).expect("2×2");
        // 1/10 − 1/12 = 1/60
        assert_eq!(r.determinant(), Ok(q(1, 60)));
        assert_eq!(r.determinant_integral(), Ok(q(1, 60)));
        assert_eq!(Matrix::<Rational>::zeros(0, 0).determinant(), Ok(q(1, 1)));
    }

    #[test]
    fn solve_cases() {
        let a = m(&[&[1, 1], &[1, -1]]);
        assert_eq!(
            a.solve(&[q(3, 1), q(1, 1)]),
            Ok(Solution::Unique(vec![q(2, 1), q(1, 1)]))
        );
        let s = m(&[&[1, 2], &[2, 4]]);
        assert_eq!(s.solve(&[q(1, 1), q(3, 1)]), Ok(Solution::Inconsistent));
        match s.solve(&[q(1, 1), q(2, 1)]).expect("shape") {
            Solution::Underdetermined {
                particular,
                null_space,
            } => {
                assert_eq!(particular, vec![q(1, 1), q(0, 1)]);
                assert_eq!(null_space, vec![vec![q(-2, 1), q(1, 1)]]);
            }
            other => panic!("expected underdetermined, got {other:?}"),
        }
        assert!(s.solve(&[q(1, 1)]).is_err());
        assert!(s.solve_unique(&[q(1, 1), q(2, 1)]).is_err());
        let (r, piv) = m(&[&[2, 4, 2], &[1, 3, 2]]).rref();
        assert_eq!(r, m(&[&[1, 0, -1], &[0, 1, 1]]));
        assert_eq!(piv, vec![0, 1]);
        assert_eq!(
            m(&[&[1, 2, 3]]).null_space(),
            vec![
                vec![q(-2, 1), q(1, 1), q(0, 1)],
                vec![q(-3, 1), q(0, 1), q(1, 1)]
            ]
        );
    }

    #[test]
    fn f64_versions() {
        let a = Matrix::from_rows(vec![vec![1.0, 1.0], vec![1.0, -1.0]]).expect("2×2");
        let x = solve_f64(&a, &[3.0, 1.0]).expect("regular");
        assert!((x[0] - 2.0).abs() < 1e-12 && (x[1] - 1.0).abs() < 1e-12);
        let s = Matrix::from_rows(vec![vec![1.0, 2.0], vec![2.0, 4.0]]).expect("2×2");
        assert!(solve_f64(&s, &[1.0, 2.0]).is_err());
        assert_eq!(rank_f64(&s, 1e-12), Ok(1));
        let ns = null_space_f64(&s, 1e-12).expect("finite");
        assert_eq!(ns.len(), 1);
        assert!((ns[0][0] + 2.0 * ns[0][1]).abs() < 1e-12);
        let wide = Matrix::from_rows(vec![vec![1.0, 2.0, 3.0]]).expect("1×3");
        assert_eq!(null_space_f64(&wide, 1e-12).expect("finite").len(), 2);
        assert!(rank_f64(&s, -1.0).is_err());
        assert!(rank_f64(&Matrix::from_rows(vec![vec![f64::NAN]]).expect("1×1"), 0.0).is_err());
        assert_eq!(rank_f64(&Matrix::zeros(2, 3), 1e-12), Ok(0));
        assert_eq!(
            null_space_f64(&Matrix::zeros(2, 3), 1e-12).map(|v| v.len()),
            Ok(3)
        );
        let ls = solve_least_squares_f64(&wide, &[14.0], 1e-12).expect("finite");
        assert!((ls[0] - 1.0).abs() < 1e-12 && (ls[2] - 3.0).abs() < 1e-12);
        assert_eq!(from_nalgebra(&to_nalgebra(&wide)), wide);
        // huge finite entries: an answer or a typed error, never a panic
        let big = Matrix::from_rows(vec![vec![1e308, 1e308], vec![1e308, -1e308]]).expect("2×2");
        let _ = rank_f64(&big, 1e-12);
        let _ = null_space_f64(&big, 1e-12);
        let _ = solve_least_squares_f64(&big, &[1e308, 0.0], 1e-12);
        let _ = solve_f64(&big, &[1e308, 0.0]);
    }

    #[test]
    fn integral_particular_solution_examples() {
        // unique, underdetermined, inconsistent, with fractions and a zero column
        let a = Matrix::from_rows(vec![
            vec![q(1, 2), q(1, 3), q(0, 1)],
            vec![q(1, 4), q(1, 5), q(0, 1)],
        ])
        .expect("2×3");
        let b = [q(1, 1), q(2, 7)];
        let x = a.particular_solution_integral(&b).expect("shape");
        assert_eq!(x.as_deref(), a.solve(&b).expect("shape").particular());
        let x = x.expect("consistent");
        assert_eq!(x[2], q(0, 1));
        let s = m(&[&[1, 2], &[2, 4]]);
        assert_eq!(
            s.particular_solution_integral(&[q(1, 1), q(3, 1)]),
            Ok(None)
        );
        assert_eq!(
            s.particular_solution_integral(&[q(1, 1), q(2, 1)]),
            Ok(Some(vec![q(1, 1), q(0, 1)]))
        );
        assert!(s.particular_solution_integral(&[q(1, 1)]).is_err());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// Random rational systems (1–6 rows, 1–5 columns, often rank-deficient: entries
        /// from a small range, some rows repeated as multiples): the fraction-free particular
        /// solution is the one of Gauss–Jordan (`solve`), or both are inconsistent.
        #[test]
        fn integral_particular_solution_is_gauss_jordans(
            rows in 1usize..7,
            cols in 1usize..6,
            entries in proptest::collection::vec((-3i64..4, 1i64..5), 42),
            copy in proptest::option::of((0usize..6, 1usize..6, -2i64..3)),
        ) {
            let mut it = entries.iter().cycle();
            let mut data: Vec<Vec<Rational>> = (0..rows)
                .map(|_| (0..=cols).map(|_| {
                    let (n, d) = it.next().copied().unwrap_or((0, 1));
                    q(n, d)
                }).collect())
                .collect();
            if let Some((from, to, k)) = copy {
                if from < rows && to < rows {
                    let r: Vec<Rational> = data[from].iter().map(|x| x * q(k, 1)).collect();
                    data[to] = r;
                }
            }
            let b: Vec<Rational> = data.iter().map(|r| r[cols].clone()).collect();
            let a = Matrix::from_rows(data.iter().map(|r| r[..cols].to_vec()).collect())
                .expect("rectangular");
            let fast = a.particular_solution_integral(&b).expect("shape");
            let slow = a.solve(&b).expect("shape");
            proptest::prop_assert_eq!(fast.as_deref(), slow.particular());
        }
    }
}
