//! Linear line complexes and their null polarity (Gruber §1.1.3).
//!
//! A linear complex `C(c)` is the set of lines `x` with
//! `c₄x₁ + c₅x₂ + c₆x₃ + c₁x₄ + c₂x₅ + c₃x₆ = ⟨c̄, x⟩ + ⟨c, x̄⟩ = Ω(c, x) = 0` (Gruber (1.11)).
//! It is *singular* if `c` itself is a line (`c₁c₄ + c₂c₅ + c₃c₆ = 0`): then `C` consists of
//! the lines meeting the axis `c`; otherwise *regular*.
//!
//! **Null polarity.** `Ω(c, p ∧ q) = pᵀ A q` with the skew matrix
//! `A₀₁ = c₄, A₀₂ = c₅, A₀₃ = c₆, A₂₃ = c₁, A₃₁ = c₂, A₁₂ = c₃` (`A = −Aᵀ`; a direct
//! expansion of (1.1) in (1.11)). The lines of `C` through a point `p` are the lines through
//! `p` in its *null plane* `π(p) = Aᵀp`; `p ∈ π(p)` because `A` is skew. For a regular
//! complex `A` is invertible (`det A = (c₁c₄ + c₂c₅ + c₃c₆)²`) and the null point of a
//! plane `u` is the solution of `Aᵀp = u`. For a singular complex `π(p)` is the plane
//! through `p` and the axis (zero for `p` on the axis).
//!
//! **Axis and parameter** (affine): write `c̄ = (c̄ − λc) + λc` with
//! `λ = ⟨c, c̄⟩/⟨c, c⟩`; then `a = (c; c̄ − λc)` is a line (the axis of the complex) and
//! `Ω(c, x) = Ω(a, x) + λ(c₁x₁ + c₂x₂ + c₃x₃)`. `λ` is the parameter (pitch) of the complex; `λ = 0` iff
//! the complex is singular.

use super::plucker::{klein_form, reciprocal_product, Line};
use super::{all_zero, dot, fmt_vec, is_small, scale_of, LineError};
use crate::Certified;
use rcagd_algebra::{Certificate, Matrix, Scalar};

/// A linear line complex `Ω(c, x) = 0` (Gruber (1.11)).
#[derive(Debug, Clone, PartialEq)]
pub struct LinearComplex<F> {
    c: [F; 6],
}

impl<F: Scalar> LinearComplex<F> {
    /// The complex with coordinates `c = (c₁, …, c₆)` (any non-zero 6-vector).
    ///
    /// # Errors
    /// [`LineError::ZeroVector`] for `c = 0`.
    pub fn new(c: [F; 6]) -> Result<Self, LineError> {
        if all_zero(&c) {
            return Err(LineError::ZeroVector(
                "a linear complex needs non-zero coordinates".into(),
            ));
        }
        Ok(LinearComplex { c })
    }

    /// The singular complex of all lines meeting `axis`.
    pub fn singular(axis: &Line<F>) -> Self {
        LinearComplex {
            c: axis.coords().clone(),
        }
    }

    /// The coordinates `c`.
    pub fn coords(&self) -> &[F; 6] {
        &self.c
    }

    /// The invariant `c₁c₄ + c₂c₅ + c₃c₆` (zero iff singular).
    pub fn invariant(&self) -> F {
        klein_form(&self.c)
    }

    /// `true` for a singular complex (its coordinates form a line, the axis).
    pub fn is_singular(&self) -> bool {
        let s = scale_of(&self.c);
        is_small(&self.invariant(), s * s)
    }

    /// The axis of a singular complex.
    ///
    /// # Errors
    /// [`LineError::ComplexKind`] for a regular complex.
    pub fn singular_axis(&self) -> Result<Line<F>, LineError> {
        if !self.is_singular() {
            return Err(LineError::ComplexKind(format!(
                "the complex {} is regular (c₁c₄ + c₂c₅ + c₃c₆ ≠ 0): it has no singular axis",
                fmt_vec(&self.c)
            )));
        }
        Line::from_coords(self.c.clone())
    }

    /// `Ω(c, x)` for a line `x`.
    pub fn evaluate(&self, x: &Line<F>) -> F {
        reciprocal_product(&self.c, x.coords())
    }

    /// `true` if the line belongs to the complex (`Ω(c, x) = 0`).
    pub fn contains(&self, x: &Line<F>) -> bool {
        let s = scale_of(&self.c) * scale_of(x.coords());
        is_small(&self.evaluate(x), s)
    }

    /// The skew matrix `A` with `pᵀAq = Ω(c, p ∧ q)` (module docs).
    pub fn null_matrix(&self) -> [[F; 4]; 4] {
        let [c1, c2, c3, c4, c5, c6] = self.c.clone();
        let z = F::zero;
        [
            [z(), c4.clone(), c5.clone(), c6.clone()],
            [-c4, z(), c3.clone(), -c2.clone()],
            [-c5, -c3, z(), c1.clone()],
            [-c6, c2, -c1, z()],
        ]
    }

    /// The null plane `π(p) = Aᵀp` of a point: the carrier of the pencil of complex lines
    /// through `p`.
    ///
    /// # Errors
    /// [`LineError::PointOnLine`] if `π(p) = 0` (a point of the axis of a singular complex).
    pub fn null_plane(&self, p: &[F; 4]) -> Result<[F; 4], LineError> {
        let a = self.null_matrix();
        let u: [F; 4] = core::array::from_fn(|j| {
            (0..4).fold(F::zero(), |acc, i| acc + p[i].clone() * a[i][j].clone())
        });
        let s = scale_of(&self.c) * scale_of(p);
        if u.iter().all(|x| is_small(x, s)) {
            return Err(LineError::PointOnLine(fmt_vec(p), fmt_vec(&self.c)));
        }
        Ok(u)
    }

    /// The null point of a plane (regular complexes): the solution of `Aᵀp = u`.
    ///
    /// # Errors
    /// [`LineError::ComplexKind`] for a singular complex, [`LineError::ZeroVector`] for
    /// `u = 0`.
    pub fn null_point(&self, u: &[F; 4]) -> Result<[F; 4], LineError> {
        if all_zero(u) {
            return Err(LineError::ZeroVector("the plane must be non-zero".into()));
        }
        if self.is_singular() {
            return Err(LineError::ComplexKind(
                "a singular complex has no null points (its null polarity is degenerate)".into(),
            ));
        }
        let a = self.null_matrix();
        let at = Matrix::from_fn(4, 4, |i, j| a[j][i].clone());
        let p = at
            .solve_unique(u)
            .map_err(rcagd_algebra::AlgebraError::from)?;
        Ok([p[0].clone(), p[1].clone(), p[2].clone(), p[3].clone()])
    }

    /// The parameter (pitch) `λ = ⟨c, c̄⟩/⟨c, c⟩` and the axis `(c; c̄ − λc)` of the complex
    /// (affine notions; module docs). `λ = 0` for singular complexes.
    ///
    /// # Errors
    /// [`LineError::ComplexKind`] if the direction part `(c₁, c₂, c₃)` vanishes (the axis is
    /// at infinity).
    pub fn axis_and_parameter(&self) -> Result<(Line<F>, F), LineError> {
        let d = [self.c[0].clone(), self.c[1].clone(), self.c[2].clone()];
        let m = [self.c[3].clone(), self.c[4].clone(), self.c[5].clone()];
        let dd = dot(&d, &d);
        if dd.is_zero() {
            return Err(LineError::ComplexKind(
                "the complex has direction part c₁ = c₂ = c₃ = 0: its axis is at infinity".into(),
            ));
        }
        let lambda = dot(&d, &m) / dd;
        let axis = [
            d[0].clone(),
            d[1].clone(),
            d[2].clone(),
            m[0].clone() - lambda.clone() * d[0].clone(),
            m[1].clone() - lambda.clone() * d[1].clone(),
            m[2].clone() - lambda.clone() * d[2].clone(),
        ];
        Ok((Line::from_coords_unchecked(axis), lambda))
    }
}

impl<F: Scalar> Certified for LinearComplex<F> {
    /// The null polarity at the four base points `eᵢ` and at `(1, 1, 1, 1)`: `p ∈ π(p)`, and
    /// for a regular complex the null point of `π(p)` is `p` again (involution), and the
    /// lines `p ∧ q` for points `q` of `π(p)` belong to the complex.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        let one = F::one();
        let pts: Vec<[F; 4]> = (0..4)
            .map(super::plucker::unit4)
            .chain(std::iter::once([
                one.clone(),
                one.clone(),
                one.clone(),
                one.clone(),
            ]))
            .collect();
        for p in &pts {
            let Ok(u) = self.null_plane(p) else {
                continue;
            };
            let s = scale_of(&self.c) * scale_of(p) * scale_of(p);
            let inc = dot(&u, p);
            out.push(Certificate::decide(
                format!("p = {} lies in its null plane π(p)", fmt_vec(p)),
                is_small(&inc, s),
                F::EXACT,
                || crate::error::format_scalar(&inc),
            ));
            // a second point of the null plane: q = plane ∩ (line through p, e_k)
            let lp = Line::from_planes(&u, &super::plucker::unit4(0))
                .or_else(|_| Line::from_planes(&u, &super::plucker::unit4(1)));
            if let Ok(line_in_plane) = lp {
                let (a, b) = line_in_plane.points();
                for q in [a, b] {
                    if let Ok(x) = Line::from_points(p, &q) {
                        let v = self.evaluate(&x);
                        let sc = scale_of(&self.c) * scale_of(x.coords());
                        out.push(Certificate::decide(
                            format!(
                                "the line p ∧ q through p = {} in π(p) belongs to the complex",
                                fmt_vec(p)
                            ),
                            is_small(&v, sc),
                            F::EXACT,
                            || crate::error::format_scalar(&v),
                        ));
                    }
                }
            }
            if !self.is_singular() {
                if let Ok(back) = self.null_point(&u) {
                    let ok = super::proportional(&back, p);
                    out.push(Certificate::decide(
                        format!("null point of π(p) is p = {}", fmt_vec(p)),
                        ok,
                        F::EXACT,
                        || fmt_vec(&back),
                    ));
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn regular_complex_null_polarity() {
        let c = LinearComplex::new([1, 2, 0, 3, -1, 1].map(q)).expect("c");
        assert!(!c.is_singular());
        assert!(c.all_hold());
        let p = [q(1), q(2), q(-1), q(3)];
        let u = c.null_plane(&p).expect("plane");
        let back = c.null_point(&u).expect("point");
        assert!(super::super::proportional(&back, &p));
    }

    #[test]
    fn singular_complex_is_lines_meeting_axis() {
        let axis = Line::from_affine_points(&[q(0), q(0), q(0)], &[q(0), q(0), q(1)]).expect("a");
        let c = LinearComplex::singular(&axis);
        assert!(c.is_singular());
        let meets = Line::from_affine_points(&[q(0), q(0), q(5)], &[q(1), q(2), q(3)]).expect("m");
        let skew = Line::from_affine_points(&[q(1), q(0), q(0)], &[q(1), q(1), q(0)]).expect("s");
        assert!(c.contains(&meets) && !c.contains(&skew));
        assert!(c.null_plane(&[q(1), q(0), q(0), q(2)]).is_err());
        assert!(c.all_hold());
        let (ax, lambda) = c.axis_and_parameter().expect("axis");
        assert!(lambda.is_zero() && ax.same_line(&axis));
    }
}
