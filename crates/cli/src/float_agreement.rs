//! When an `f64` build agrees with the exact one: the one rule used by the float path's
//! tests (`crates/cli/tests/it/float.rs`) and by the fuzzer's exact-against-`f64` check
//! ([`crate::fuzz`]), so that the two cannot drift apart.
//!
//! * The same objects (names, kinds) with the same degrees, every homogeneous control
//!   point coordinate within `rel` of the object's largest coordinate (plus
//!   [`power_form_slack`] for ops that pass through the power basis) after both pieces
//!   are divided by their weight at the index of the exact piece's largest weight (a
//!   rational curve is defined up to a common factor, and the exact ops may divide one
//!   out where the `f64` builder does not), and every `f64` certificate holding and
//!   marked inexact ([`agree`]); or
//! * a different split (the same objects and bidegrees, another number of pieces: an
//!   exact sign or threshold test whose `0` is a rounding residue `±ε` in `f64`, e.g.
//!   the positive-weight split of a patch or the subdivision of an arc by its turn)
//!   whose `f64` certificates all hold ([`agree_or_split`]).

use crate::model::Object;
use rcagd_algebra::{Certificate, Scalar};

/// Library `f64` certificates whose tolerance is scaled by the *cancelled* result instead
/// of the size of the terms that cancel (known defects, docs/plans/float.md): they may
/// fail on exact-agreeing control points by rounding alone. Only these, and only for
/// these ops, are exempt from holding (they must still be marked inexact). Empty since
/// `DualPencil::certify` compares `det(λC + Ω)` with the permanent of `|λC| + |Ω|`.
pub const KNOWN_TOLERANCE_DEFECTS: &[(&[&str], &str)] = &[];

/// Whether the failing `f64` certificate `c` of an object of op `op` is a known tolerance
/// defect ([`KNOWN_TOLERANCE_DEFECTS`]).
pub fn exempt(op: &str, c: &Certificate) -> bool {
    KNOWN_TOLERANCE_DEFECTS
        .iter()
        .any(|(ops, prop)| ops.contains(&op) && c.property.starts_with(prop))
}

/// The first `f64` certificate of `f` that is marked exact, or fails and is not exempt.
pub fn bad_certificate(f: &Object) -> Option<&Certificate> {
    f.certificates
        .iter()
        .find(|c| c.exact || (!c.holds && !exempt(&f.op, c)))
}

/// Every homogeneous coordinate of every piece, in order, as `f64`, with the stride
/// (dimension + 1) of each piece.
fn coords(o: &Object) -> Vec<(usize, Vec<f64>)> {
    let mut out = Vec::new();
    for c in o.geometry.curves() {
        out.push((c.dim() + 1, c.coords().iter().map(Scalar::to_f64).collect()));
    }
    for p in o.geometry.patches() {
        out.push((p.dim() + 1, p.coords().iter().map(Scalar::to_f64).collect()));
    }
    out
}

/// Divides both pieces by their weight at the index of the exact piece's largest
/// |weight| (the same index for both): the only normalization before the comparison.
fn normalize(exact: &mut [f64], float: &mut [f64], stride: usize) {
    let stride = stride.max(1);
    let k = (0..exact.len() / stride)
        .max_by(|&a, &b| exact[a * stride].abs().total_cmp(&exact[b * stride].abs()))
        .unwrap_or(0);
    let (we, wf) = (
        exact.get(k * stride).copied().unwrap_or(1.0),
        float.get(k * stride).copied().unwrap_or(1.0),
    );
    if we != 0.0 && wf != 0.0 {
        exact.iter_mut().for_each(|x| *x /= we);
        float.iter_mut().for_each(|x| *x /= wf);
    }
}

/// The rounding an op that builds its control points through the power basis may add
/// beyond the relative tolerance: `ph_planar_offset` converts the base curve's control
/// points to power form, multiplies (σ·x + d·y′, σ·y − d·x′) and converts the
/// degree-`n = 4m + 1` result back to Bernstein form. Each step rounds in proportion to
/// the power coefficients, which for Bernstein coefficients of size `B` reach `2ⁿ·B`;
/// the bound is `16·(n + 1)·ε·S`, `S` the largest `Σⱼ |aⱼ|` of a coordinate's exact
/// power coefficients, in the units of the comparison (divided by the largest weight).
/// Every other op: 0.
pub fn power_form_slack(e: &Object) -> f64 {
    if e.op != "ph_planar_offset" {
        return 0.0;
    }
    let mut slack = 0.0f64;
    for c in e.geometry.curves() {
        let n = c.degree() as f64;
        let w = c
            .weights()
            .iter()
            .map(|x| Scalar::to_f64(x).abs())
            .fold(0.0, f64::max);
        if w == 0.0 {
            continue;
        }
        for p in c.coordinate_polys() {
            let s: f64 = p.coeffs().iter().map(|a| Scalar::to_f64(a).abs()).sum();
            slack = slack.max(16.0 * (n + 1.0) * f64::EPSILON * s / w);
        }
    }
    slack
}

/// The objects agree piece by piece, control points within `rel` (see the module docs).
///
/// # Errors
/// The first difference.
pub fn agree(exact: &[Object], float: &[Object], rel: f64) -> Result<(), String> {
    if exact.len() != float.len() {
        return Err(format!(
            "{} exact objects, {} in f64",
            exact.len(),
            float.len()
        ));
    }
    for (e, f) in exact.iter().zip(float) {
        if e.name != f.name || e.kind() != f.kind() || e.degree_summary() != f.degree_summary() {
            return Err(format!(
                "exact {:?} {} {}, f64 {:?} {} {}",
                e.name,
                e.kind(),
                e.degree_summary(),
                f.name,
                f.kind(),
                f.degree_summary()
            ));
        }
        let (mut ce, mut cf) = (coords(e), coords(f));
        if ce.len() != cf.len() {
            return Err(format!("{:?}: piece counts differ", e.name));
        }
        for ((stride, a), (_, b)) in ce.iter_mut().zip(cf.iter_mut()) {
            if a.len() != b.len() {
                return Err(format!("{:?}: pieces of different sizes", e.name));
            }
            normalize(a, b, *stride);
        }
        let scale = ce
            .iter()
            .flat_map(|(_, v)| v.iter())
            .fold(0.0f64, |m, x| m.max(x.abs()))
            .max(f64::MIN_POSITIVE);
        let slack = power_form_slack(e);
        for (k, ((_, a), (_, b))) in ce.iter().zip(&cf).enumerate() {
            for (i, (x, y)) in a.iter().zip(b).enumerate() {
                if (x - y).abs() > rel * scale + slack || (x - y).is_nan() {
                    return Err(format!(
                        "{:?}: piece {k} coordinate {i}: exact {x:e}, f64 {y:e}, |Δ|/scale = {:e}",
                        e.name,
                        (x - y).abs() / scale
                    ));
                }
            }
        }
        if let Some(c) = bad_certificate(f) {
            return Err(format!("{:?}: f64 certificate {c}", f.name));
        }
    }
    Ok(())
}

/// The same objects (names, kinds) with the same bidegrees, the number of pieces aside
/// (`"N patches of bidegree (p, q)"`).
pub fn same_up_to_split(exact: &[Object], float: &[Object]) -> bool {
    let shape = |o: &Object| {
        let d = o.degree_summary();
        let rest = d.split_once(' ').map_or(d.clone(), |(_, r)| r.to_string());
        (o.name.clone(), o.kind().to_string(), rest)
    };
    exact.len() == float.len() && exact.iter().zip(float).all(|(e, f)| shape(e) == shape(f))
}

/// [`agree`]; or, where only the number of pieces differs, the same objects and
/// bidegrees and holding `f64` certificates (see the module docs).
///
/// # Errors
/// The difference (and the failing `f64` certificate of a different split).
pub fn agree_or_split(exact: &[Object], float: &[Object], rel: f64) -> Result<(), String> {
    let Err(m) = agree(exact, float, rel) else {
        return Ok(());
    };
    let counts_differ = exact
        .iter()
        .zip(float)
        .any(|(e, f)| e.degree_summary() != f.degree_summary());
    if !(counts_differ && same_up_to_split(exact, float)) {
        return Err(m);
    }
    match float.iter().find_map(bad_certificate) {
        Some(c) => Err(format!("{m}; and an f64 certificate fails: {c}")),
        None => Ok(()),
    }
}
