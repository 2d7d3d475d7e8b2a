//! Exact against `f64` (issue 19, item 4): a fuzz case that builds exactly and whose ops
//! all have a float path ([`crate::float`], `rcagd build --float`) is built again in
//! `f64` and the two results are compared by the rule of the float path's tests,
//! [`crate::float_agreement::agree_or_split`], with the tolerance [`REL`] (looser than
//! the tests' 1e-12: generated data reach the ops' limits of size and degree).
//!
//! The `f64` build failing where the exact one succeeds is a finding only when every
//! input number is of moderate size (within `10^±`[`SMALL_ORDER`]): beyond that the
//! `f64` path may overflow or lose the data by design (the op then says "input too
//! large for f64"), and so is a refusal the float path documents ("the float path does
//! not decide …; build without --float"). Objects an op adds for display only
//! (`ph_curve`'s frames, combs and feed marks) have no float path; such cases are not
//! compared.

use crate::build::{build_recipe_with, Arithmetic};
use crate::float_agreement::agree_or_split;
use crate::model::Object;
use crate::recipe::{Format, Recipe};
use rcagd_algebra::Rational;

/// The agreement demanded of `f64` and exact control points, relative to the object's
/// largest coordinate.
pub const REL: f64 = 1e-9;

/// Input numbers within `10^±SMALL_ORDER` are "of moderate size": the `f64` path must
/// build what the exact path builds.
pub const SMALL_ORDER: f64 = 6.0;

/// Whether every object of the recipe text has an op with a float path (and no display
/// parameter that the float path refuses).
pub fn comparable(recipe: &Recipe) -> bool {
    !recipe.objects.is_empty()
        && recipe.objects.iter().all(|o| {
            crate::float::has_float_path(&o.op)
                && !o
                    .params
                    .iter()
                    .any(|e| crate::float::is_display_param(&o.op, &e.key))
        })
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
        Ok(float) => agree_or_split(exact, &float, REL)
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
            // weight function has a zero; build without --float") or does not build
            // (display objects): not a disagreement
            if m.contains(super::WORK_LIMIT)
                || m.contains("the float path does not")
                || m.contains(crate::float::DISPLAY_OBJECTS_REFUSED)
                || m.contains(crate::float::UNVERIFIED_REFUSED)
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
