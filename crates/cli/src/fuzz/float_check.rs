//! Exact against `f64` (issue 19, item 4): a fuzz case that builds exactly and whose ops
//! all have a float path ([`crate::float`], `rcagd build --float`) is built again in
//! `f64` and the two results are compared by the rule of the float path's tests
//! (`crates/cli/tests/it/float.rs`, `agree_or_split`):
//!
//! * the same objects (names, kinds) with the same degrees, every homogeneous control
//!   point coordinate within [`REL`] of the object's largest coordinate after both pieces
//!   are divided by their weight at the index of the exact piece's largest weight (a
//!   rational curve is defined up to a common factor), and every `f64` certificate
//!   holding and marked inexact; or
//! * a different split (the same objects and bidegrees, another number of pieces: an
//!   exact sign test whose `0` is a rounding residue `±ε` in `f64`) whose `f64`
//!   certificates all hold.
//!
//! The `f64` build failing where the exact one succeeds is a finding only when every
//! input number is of moderate size (within `10^±`[`SMALL_ORDER`]): beyond that the
//! `f64` path may overflow or lose the data by design (the op then says "input too
//! large for f64"), and so is a refusal the float path documents ("the float path does
//! not decide …; build without --float"). Objects an op adds for display only
//! (`ph_curve`'s frames, combs and feed marks) have no float path; such cases are not
//! compared.

use crate::build::{build_recipe_with, Arithmetic};
use crate::model::Object;
use crate::recipe::{Format, Recipe};
use rcagd_algebra::{Rational, Scalar};

/// The agreement demanded of `f64` and exact control points, relative to the object's
/// largest coordinate.
pub const REL: f64 = 1e-9;

/// Input numbers within `10^±SMALL_ORDER` are "of moderate size": the `f64` path must
/// build what the exact path builds.
pub const SMALL_ORDER: f64 = 6.0;

/// Certificates of the `f64` path whose tolerance is known to be scaled by the cancelled
/// result rather than by the size of the terms (docs/plans/float.md; the same list as
/// the float tests'): they may fail on agreeing control points by rounding alone.
const KNOWN_TOLERANCE_DEFECTS: &[(&[&str], &str)] = &[(
    &[
        "torus",
        "dupin_canal",
        "dupin_cyclide",
        "dupin_cyclide_parabolic",
    ],
    "det(λC + μΩ)",
)];

/// Whether every object of the recipe text has an op with a float path (and no display
/// parameter that the float path refuses).
pub fn comparable(recipe: &Recipe) -> bool {
    !recipe.objects.is_empty()
        && recipe.objects.iter().all(|o| {
            crate::float::has_float_path(&o.op)
                && !(o.op == "ph_curve"
                    && o.params.iter().any(|e| {
                        ["frame", "comb", "feed", "samples", "frame_length"]
                            .contains(&e.key.as_str())
                    }))
        })
}

/// Every homogeneous coordinate of every piece as `f64`, with the stride of each piece.
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

/// Divides both pieces by their weight at the index of the exact piece's largest |weight|.
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

fn exempt(op: &str, c: &rcagd_algebra::Certificate) -> bool {
    KNOWN_TOLERANCE_DEFECTS
        .iter()
        .any(|(ops, prop)| ops.contains(&op) && c.property.starts_with(prop))
}

/// The objects agree piece by piece (see the module docs).
///
/// # Errors
/// The first difference.
pub fn agree(exact: &[Object], float: &[Object]) -> Result<(), String> {
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
        for (k, ((_, a), (_, b))) in ce.iter().zip(&cf).enumerate() {
            for (i, (x, y)) in a.iter().zip(b).enumerate() {
                if (x - y).abs() > REL * scale || (x - y).is_nan() {
                    return Err(format!(
                        "{:?}: piece {k} coordinate {i}: exact {x:e}, f64 {y:e}, |Δ|/scale = {:e}",
                        e.name,
                        (x - y).abs() / scale
                    ));
                }
            }
        }
        if let Some(c) = f
            .certificates
            .iter()
            .find(|c| c.exact || (!c.holds && !exempt(&f.op, c)))
        {
            return Err(format!("{:?}: f64 certificate {c}", f.name));
        }
    }
    Ok(())
}

/// [`agree`], or a different split with the same objects and bidegrees whose `f64`
/// certificates hold.
///
/// # Errors
/// The difference (and the failing `f64` certificate of a different split).
pub fn agree_or_split(exact: &[Object], float: &[Object]) -> Result<(), String> {
    let Err(m) = agree(exact, float) else {
        return Ok(());
    };
    let shape = |o: &Object| {
        let d = o.degree_summary();
        let rest = d.split_once(' ').map_or(d.clone(), |(_, r)| r.to_string());
        (o.name.clone(), o.kind().to_string(), rest)
    };
    let same_up_to_split =
        exact.len() == float.len() && exact.iter().zip(float).all(|(e, f)| shape(e) == shape(f));
    let counts_differ = exact
        .iter()
        .zip(float)
        .any(|(e, f)| e.degree_summary() != f.degree_summary());
    if !(counts_differ && same_up_to_split) {
        return Err(m);
    }
    match float.iter().find_map(|o| {
        o.certificates
            .iter()
            .find(|c| !c.holds && !exempt(&o.op, c))
    }) {
        Some(c) => Err(format!("{m}; and an f64 certificate fails: {c}")),
        None => Ok(()),
    }
}

/// Whether every non-zero input number of the recipe lies within `10^±SMALL_ORDER`.
fn small_magnitude(recipe: &Recipe) -> bool {
    recipe.objects.iter().all(|o| {
        o.params.iter().all(|e| {
            let mut ok = true;
            visit(&e.value, &mut |x| {
                if let Some(l) = crate::limits::log10_abs(x) {
                    ok &= l.abs() <= SMALL_ORDER;
                }
            });
            ok
        })
    })
}

fn visit(v: &crate::recipe::RecipeValue, f: &mut impl FnMut(&Rational)) {
    use crate::recipe::ValueKind;
    match &v.kind {
        ValueKind::Array(items) => items.iter().for_each(|i| visit(i, f)),
        ValueKind::Table(entries) => entries.iter().for_each(|e| visit(&e.value, f)),
        ValueKind::Number(_) | ValueKind::String(_) => {
            if let Ok(crate::value::Value::Number(q)) =
                crate::value::convert(crate::value::ParamKind::Number, v)
            {
                f(&q);
            }
        }
        _ => {}
    }
}

/// Builds a recipe text that built exactly (`exact`: its objects) in `f64` and compares.
/// `None` when the two agree (or the case is not comparable: an op without a float
/// path, an `f64` refusal of large data); `Some(message)` for a finding.
pub fn check(file_name: &str, text: &str, exact: &[Object]) -> Option<String> {
    let recipe = Recipe::parse(file_name, text, Some(Format::Toml)).ok()?;
    if !comparable(&recipe) {
        return None;
    }
    match build_recipe_with(&recipe, Arithmetic::Float, |_| {}) {
        Ok(float) => agree_or_split(exact, &float)
            .err()
            .map(|m| format!("exact and f64 disagree: {m}")),
        Err(d) => {
            let m = d
                .iter()
                .map(|d| d.message.clone())
                .collect::<Vec<_>>()
                .join("; ");
            // the case's budget ended the f64 build, or the float path refuses what it
            // does not decide by design ("the float path does not decide whether the
            // weight function has a zero; build without --float"): not a disagreement
            if m.contains(super::WORK_LIMIT)
                || m.contains("the float path does not")
                || !small_magnitude(&recipe)
            {
                None
            } else {
                Some(format!(
                    "the f64 path fails where the exact one builds (input numbers of moderate size): {}",
                    crate::source::clip(&m)
                ))
            }
        }
    }
}
