//! Affine classes of quadratic polynomial maps `R² → Rᵐ` after J. Peters and U. Reif, "The
//! 42 equivalence classes of quadratic surfaces in affine n-space", Computer Aided
//! Geometric Design 15 (1998) 459–473 (docs/math/sphere-families.md, "Summary table"), used
//! to classify `Φ`, its centre surface `π(Φ)` and its radius function `Φ₄` (Gruber 2008,
//! "Zusammenfassung" of chapter 3).
//!
//! Two maps are equivalent if they differ by an affine map of the image and an affine
//! reparametrization. The label `n-k-x` is computed from exact invariants:
//!
//! * `n`: the dimension of the affine hull (rank of the coefficients of `u, v, u², uv, v²`);
//! * `k`: the dimension of the span `V` of the quadratic parts;
//! * `x`: for `k = 1` the type of the quadratic form `Q` (discriminant `B² − 4AC` of
//!   `Au² + Buv + Cv²`: `< 0` definite `1`, `> 0` indefinite `2`, `= 0` a square `3`); for
//!   `k = 2` the type of the pencil `V` (the discriminant of `disc(λQ₁ + μQ₂)` as a binary
//!   form in `(λ, μ)`: two real squares `1`, one `2`, none `3`); letters from the position
//!   of the pure linear coordinates `L` (combinations with zero quadratic part) relative to
//!   the squares `ℓ²` of `V` (`L ∝ ℓ ⟺ L² ∈ V`) and from the linear part of the coordinate
//!   whose quadratic part is `L²` (modulo `L`, which translations and the image map can
//!   change).
//!
//! Handled: `0-0`, `1-0`, `2-0`, `1-1-*`, `2-1-*`, `3-1-*`, `3-2-*`, `4-2-*`; other
//! combinations (`k = 3`, `2-2-*`) are reported as `n-k` with the letter unresolved.

use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::{Matrix, Rational};

/// The Peters–Reif label of a quadratic map (module docs), e.g. `"4-2-1"`, or the reason it
/// has none.
pub fn peters_reif_class(coords: &[MPoly<Rational>]) -> Result<String, String> {
    let z = Rational::from(0);
    let mut lin: Vec<[Rational; 2]> = Vec::new();
    let mut quad: Vec<[Rational; 3]> = Vec::new();
    for c in coords {
        if c.total_degree().unwrap_or(0) > 2 || c.nvars() > 2 {
            return Err("not a quadratic map of two parameters".into());
        }
        let co = |e: [u32; 2]| c.coeff(&e);
        lin.push([co([1, 0]), co([0, 1])]);
        quad.push([co([2, 0]), co([1, 1]), co([0, 2])]);
    }
    let full: Vec<Vec<Rational>> = lin
        .iter()
        .zip(&quad)
        .map(|(l, q)| l.iter().chain(q).cloned().collect())
        .collect();
    let rank = |rows: Vec<Vec<Rational>>| -> usize {
        if rows.is_empty() {
            0
        } else {
            Matrix::from_rows(rows).map(|m| m.rank()).unwrap_or(0)
        }
    };
    let n = rank(full);
    let k = rank(quad.iter().map(|q| q.to_vec()).collect());
    // pure linear combinations: left kernel of the quadratic part
    let qt = Matrix::from_fn(3, quad.len(), |r, c| quad[c][r].clone());
    let kernel = qt.null_space();
    let pure: Vec<[Rational; 2]> = kernel
        .iter()
        .map(|y| {
            let mut s = [z.clone(), z.clone()];
            for (yi, l) in y.iter().zip(&lin) {
                s[0] = s[0].clone() + yi.clone() * l[0].clone();
                s[1] = s[1].clone() + yi.clone() * l[1].clone();
            }
            s
        })
        .filter(|s| !(s[0].is_zero() && s[1].is_zero()))
        .collect();
    let disc = |q: &[Rational; 3]| {
        q[1].clone() * q[1].clone() - Rational::from(4) * q[0].clone() * q[2].clone()
    };
    let sign = |x: &Rational| -> i32 {
        if x.is_zero() {
            0
        } else if *x > z {
            1
        } else {
            -1
        }
    };
    let qtype = |q: &[Rational; 3]| match sign(&disc(q)) {
        -1 => 1,
        1 => 2,
        _ => 3,
    };
    let square = |l: &[Rational; 2]| -> [Rational; 3] {
        [
            l[0].clone() * l[0].clone(),
            Rational::from(2) * l[0].clone() * l[1].clone(),
            l[1].clone() * l[1].clone(),
        ]
    };
    let prop2 = |a: &[Rational; 2], b: &[Rational; 2]| {
        (a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone()).is_zero()
    };
    // a basis of V (rows of the quadratic part, reduced)
    let basis: Vec<[Rational; 3]> = {
        let m = Matrix::from_rows(quad.iter().map(|q| q.to_vec()).collect::<Vec<_>>());
        match m {
            Ok(m) => {
                let (r, piv) = m.rref();
                (0..piv.len())
                    .filter_map(|i| {
                        r.row(i)
                            .map(|row| [row[0].clone(), row[1].clone(), row[2].clone()])
                    })
                    .collect()
            }
            Err(_) => Vec::new(),
        }
    };
    let in_span = |q: &[Rational; 3]| {
        rank(
            basis
                .iter()
                .map(|b| b.to_vec())
                .chain([q.to_vec()])
                .collect(),
        ) == basis.len()
    };
    // the linear part of the coordinate combination whose quadratic part is `target`
    let lin_of = |target: &[Rational; 3]| -> Option<[Rational; 2]> {
        let a = Matrix::from_fn(3, quad.len(), |r, c| quad[c][r].clone());
        let y = a.solve(target).ok()?.particular()?.to_vec();
        let mut s = [z.clone(), z.clone()];
        for (yi, l) in y.iter().zip(&lin) {
            s[0] = s[0].clone() + yi.clone() * l[0].clone();
            s[1] = s[1].clone() + yi.clone() * l[1].clone();
        }
        Some(s)
    };
    let label = match (n, k) {
        (0, 0) => "0-0".to_string(),
        (1, 0) => "1-0".to_string(),
        (2, 0) => "2-0".to_string(),
        (_, 1) => {
            let q = basis.first().ok_or("no quadratic part")?;
            let t = qtype(q);
            match (n, t) {
                (3, t) => format!("3-1-{t}"),
                (1, 1) | (1, 2) => format!("1-1-{t}"),
                (1, _) => {
                    // Q = c ℓ²; the coordinate's linear part in span(ℓ) ⇒ b (complete the square)
                    let l = lin_of(q).unwrap_or([z.clone(), z.clone()]);
                    let b = (l[0].is_zero() && l[1].is_zero()) || in_span(&square(&l));
                    format!("1-1-3{}", if b { "b" } else { "a" })
                }
                (2, 1) => "2-1-1".to_string(),
                (2, t) => {
                    let l = pure.first().ok_or("no pure linear coordinate")?;
                    if t == 2 {
                        // L divides Q ⟺ Q vanishes on the kernel direction of L
                        let (x, y) = (l[1].clone(), -l[0].clone());
                        let v = q[0].clone() * x.clone() * x.clone()
                            + q[1].clone() * x.clone() * y.clone()
                            + q[2].clone() * y.clone() * y;
                        format!("2-1-2{}", if v.is_zero() { "b" } else { "a" })
                    } else if !in_span(&square(l)) {
                        "2-1-3a".to_string()
                    } else {
                        let m = lin_of(q).unwrap_or([z.clone(), z.clone()]);
                        format!("2-1-3{}", if prop2(&m, l) { "b" } else { "c" })
                    }
                }
                _ => format!("{n}-1"),
            }
        }
        (_, 2) => {
            let (q1, q2) = (&basis[0], &basis[1]);
            // disc(λq₁ + μq₂) = a λ² + b λμ + c μ²
            let a = disc(q1);
            let c = disc(q2);
            let four = Rational::from(4);
            let b = Rational::from(2) * q1[1].clone() * q2[1].clone()
                - four.clone() * (q1[0].clone() * q2[2].clone() + q2[0].clone() * q1[2].clone());
            let t = match sign(&(b.clone() * b - four * a * c)) {
                1 => 1,
                0 => 2,
                _ => 3,
            };
            match n {
                4 => format!("4-2-{t}"),
                3 if t == 3 => "3-2-3".to_string(),
                3 => {
                    let l = pure.first().ok_or("no pure linear coordinate")?;
                    let sq = square(l);
                    if !in_span(&sq) {
                        format!("3-2-{t}a")
                    } else {
                        let m = lin_of(&sq).unwrap_or([z.clone(), z.clone()]);
                        let extra = !prop2(&m, l);
                        let letter = match (t, extra) {
                            (1, true) => "c",
                            (1, false) => "b",
                            (_, true) => "b",
                            (_, false) => "c",
                        };
                        format!("3-2-{t}{letter}")
                    }
                }
                _ => format!("{n}-2"),
            }
        }
        _ => format!("{n}-{k}"),
    };
    Ok(label)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(terms: &[([u32; 2], i64)]) -> MPoly<Rational> {
        terms.iter().fold(MPoly::zero(2), |acc, (e, c)| {
            &acc + &MPoly::monomial(2, e, Rational::from(*c))
        })
    }
    const U: [u32; 2] = [1, 0];
    const V: [u32; 2] = [0, 1];
    const UU: [u32; 2] = [2, 0];
    const UV: [u32; 2] = [1, 1];
    const VV: [u32; 2] = [0, 2];

    #[test]
    fn normal_forms_are_recognized() {
        let cls = |c: &[&[([u32; 2], i64)]]| {
            peters_reif_class(&c.iter().map(|t| p(t)).collect::<Vec<_>>()).expect("class")
        };
        // the normal forms of the Peters–Reif table
        assert_eq!(cls(&[&[(U, 1)]]), "1-0");
        assert_eq!(cls(&[&[(UU, 1), (VV, 1)]]), "1-1-1");
        assert_eq!(cls(&[&[(UU, 1), (VV, -1)]]), "1-1-2");
        assert_eq!(cls(&[&[(UU, 1), (V, 1)]]), "1-1-3a");
        assert_eq!(cls(&[&[(UU, 1), (U, 3)]]), "1-1-3b");
        assert_eq!(cls(&[&[(UU, 1), (VV, 1)], &[(U, 1)]]), "2-1-1");
        assert_eq!(cls(&[&[(UV, 1)], &[(U, 1), (V, 1)]]), "2-1-2a");
        assert_eq!(cls(&[&[(UV, 1)], &[(U, 1)]]), "2-1-2b");
        assert_eq!(cls(&[&[(UU, 1)], &[(V, 1)]]), "2-1-3a");
        assert_eq!(cls(&[&[(UU, 1)], &[(U, 1)]]), "2-1-3b");
        assert_eq!(cls(&[&[(UU, 1), (V, 1)], &[(U, 1)]]), "2-1-3c");
        assert_eq!(cls(&[&[(UU, 1), (VV, 1)], &[(U, 1)], &[(V, 1)]]), "3-1-1");
        assert_eq!(cls(&[&[(UV, 1)], &[(U, 1)], &[(V, 1)]]), "3-1-2");
        assert_eq!(cls(&[&[(UU, 1)], &[(U, 1)], &[(V, 1)]]), "3-1-3");
        assert_eq!(cls(&[&[(UU, 1)], &[(VV, 1)], &[(U, 1), (V, 1)]]), "3-2-1a");
        assert_eq!(cls(&[&[(UU, 1)], &[(VV, 1)], &[(U, 1)]]), "3-2-1b");
        assert_eq!(cls(&[&[(UU, 1)], &[(VV, 1), (U, 1)], &[(V, 1)]]), "3-2-1c");
        assert_eq!(cls(&[&[(UU, 1)], &[(UV, 1)], &[(V, 1)]]), "3-2-2a");
        assert_eq!(cls(&[&[(UU, 1), (V, 1)], &[(UV, 1)], &[(U, 1)]]), "3-2-2b");
        assert_eq!(cls(&[&[(UU, 1)], &[(UV, 1)], &[(U, 1)]]), "3-2-2c");
        assert_eq!(cls(&[&[(UU, 1), (VV, -1)], &[(UV, 1)], &[(U, 1)]]), "3-2-3");
        assert_eq!(
            cls(&[&[(UU, 1)], &[(VV, 1)], &[(U, 1)], &[(V, 1)]]),
            "4-2-1"
        );
        assert_eq!(
            cls(&[&[(UU, 1)], &[(UV, 1)], &[(U, 1)], &[(V, 1)]]),
            "4-2-2"
        );
        assert_eq!(
            cls(&[&[(UU, 1), (VV, -1)], &[(UV, 1)], &[(U, 1)], &[(V, 1)]]),
            "4-2-3"
        );
        // invariance: an affine image and reparametrization of 3-2-2b
        // (u, v) ↦ (u + 2v + 1, v − 1), image mixed
        let u = p(&[(U, 1), (V, 2), ([0, 0], 1)]);
        let v = p(&[(V, 1), ([0, 0], -1)]);
        let x = &(&u * &u) + &v;
        let y = &u * &v;
        let w = u.clone();
        let mixed = [&x + &w.scale(&Rational::from(3)), &y - &x, &w + &y];
        assert_eq!(peters_reif_class(&mixed).expect("class"), "3-2-2b");
        assert!(peters_reif_class(&[p(&[([3, 0], 1)])]).is_err());
    }
}
