//! Typed parameter values: reading exact numbers, points and nets out of the recipe
//! value tree, with errors that point at the offending value.
//!
//! Numbers are exact [`Rational`]s read from their source text: TOML/JSON integers
//! and decimals (`0.1` is 1/10), or strings `"3/7"`, `"-0.125"`, `"1e-3"`
//! ([`rcagd_algebra::parse_rational`]). No `f64` is ever involved.

use crate::recipe::{RecipeValue, ValueKind};
use crate::source::Span;
use dashu_int::IBig;
use rcagd_algebra::rational::format_rational;
use rcagd_algebra::{parse_rational, Rational};

/// The type of an op parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamKind {
    /// An exact number.
    Number,
    /// An integer (any exact number with an integral value, within ±2⁶³).
    Int,
    /// `true` or `false`.
    Bool,
    /// Any string.
    String,
    /// One of the listed strings.
    Choice(&'static [&'static str]),
    /// A point `[x, y]`.
    Point2,
    /// A point `[x, y, z]`.
    Point3,
    /// A point of any dimension `[x, y, …]` (at least one coordinate).
    Point,
    /// A list of numbers `[a, b, …]`.
    Numbers,
    /// A non-empty list of points of one dimension `[[x, y], …]`.
    Points,
    /// A non-empty rectangular net of points of one dimension: a list of rows
    /// `[[[x, y, z], …], …]`.
    Net,
    /// A non-empty rectangular grid of numbers: a list of rows `[[a, b], [c, d]]`.
    Grid,
}

impl ParamKind {
    /// The type as shown to users: `number`, `point [x, y]`, …
    pub fn type_name(&self) -> String {
        match self {
            ParamKind::Number => "number".into(),
            ParamKind::Int => "integer".into(),
            ParamKind::Bool => "boolean".into(),
            ParamKind::String => "string".into(),
            ParamKind::Choice(cs) => {
                let q: Vec<String> = cs.iter().map(|c| format!("\"{c}\"")).collect();
                format!("one of {}", q.join(", "))
            }
            ParamKind::Point2 => "point [x, y]".into(),
            ParamKind::Point3 => "point [x, y, z]".into(),
            ParamKind::Point => "point [x, y, …]".into(),
            ParamKind::Numbers => "list of numbers".into(),
            ParamKind::Points => "list of points".into(),
            ParamKind::Net => "net of points (list of rows)".into(),
            ParamKind::Grid => "grid of numbers (list of rows)".into(),
        }
    }
}

/// A typed parameter value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// [`ParamKind::Number`].
    Number(Rational),
    /// [`ParamKind::Int`].
    Int(i64),
    /// [`ParamKind::Bool`].
    Bool(bool),
    /// [`ParamKind::String`] and [`ParamKind::Choice`].
    Str(String),
    /// [`ParamKind::Point2`], [`ParamKind::Point3`], [`ParamKind::Point`].
    Point(Vec<Rational>),
    /// [`ParamKind::Numbers`].
    Numbers(Vec<Rational>),
    /// [`ParamKind::Points`].
    Points(Vec<Vec<Rational>>),
    /// [`ParamKind::Net`].
    Net(Vec<Vec<Vec<Rational>>>),
    /// [`ParamKind::Grid`].
    Grid(Vec<Vec<Rational>>),
}

impl Value {
    /// The value as JSON for the `params` echo of an object: numbers as exact
    /// strings `"p/q"`.
    pub fn to_json(&self) -> serde_json::Value {
        use serde_json::Value as J;
        let q = |x: &Rational| J::String(format_rational(x));
        let pt = |p: &[Rational]| J::Array(p.iter().map(q).collect());
        match self {
            Value::Number(x) => q(x),
            Value::Int(n) => J::from(*n),
            Value::Bool(b) => J::Bool(*b),
            Value::Str(s) => J::String(s.clone()),
            Value::Point(p) | Value::Numbers(p) => pt(p),
            Value::Points(ps) | Value::Grid(ps) => J::Array(ps.iter().map(|p| pt(p)).collect()),
            Value::Net(rows) => J::Array(
                rows.iter()
                    .map(|r| J::Array(r.iter().map(|p| pt(p)).collect()))
                    .collect(),
            ),
        }
    }
}

/// Why a recipe value does not fit its parameter type, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ValueError {
    /// The offending value.
    pub span: Span,
    /// What is wrong.
    pub message: String,
}

fn err(span: Span, message: impl Into<String>) -> ValueError {
    ValueError {
        span,
        message: message.into(),
    }
}

fn wrong_type(v: &RecipeValue, expected: &str) -> ValueError {
    err(
        v.span,
        format!("expected {expected}, found {}", describe(v)),
    )
}

/// `a string "abc"`, `a number 1.5`, `an array of 3 elements`, `null`, …
pub fn describe(v: &RecipeValue) -> String {
    match &v.kind {
        ValueKind::Null => "null".into(),
        ValueKind::Array(items) => format!(
            "an array of {} element{}",
            items.len(),
            if items.len() == 1 { "" } else { "s" }
        ),
        ValueKind::Table(_) => "a table".into(),
        _ => format!("{} {}", a_an(v.type_name()), v.preview()),
    }
}

fn a_an(word: &str) -> String {
    match word.chars().next() {
        Some('a' | 'e' | 'i' | 'o' | 'u') => format!("an {word}"),
        _ => format!("a {word}"),
    }
}

/// The largest decimal exponent accepted (`1e1000`): bounds the size of the numbers a
/// recipe can ask for.
pub const MAX_EXPONENT: u32 = 1000;

/// Rejects decimal exponents beyond [`MAX_EXPONENT`] in magnitude.
fn check_exponent(text: &str, span: Span) -> Result<(), ValueError> {
    for part in text.split('/') {
        if let Some(i) = part.find(['e', 'E']) {
            let e = part[i + 1..].trim().trim_start_matches(['+', '-']);
            let big = e.len() > 6 || e.parse::<u32>().is_ok_and(|n| n > MAX_EXPONENT);
            if big {
                return Err(err(
                    span,
                    format!(
                        "number out of range: `{}` (exponents are limited to ±{MAX_EXPONENT})",
                        text.trim()
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// Rejects numbers with more digits than [`crate::limits::Limits::digits`] (the work of
/// exact arithmetic grows with the digits; `--max-digits` raises the limit).
fn check_digits(text: &str, span: Span) -> Result<(), ValueError> {
    let max = crate::limits::Limits::current().digits;
    let n = crate::limits::digit_count(text);
    if n > max {
        return Err(err(
            span,
            format!(
                "number too long: {n} digits (the limit is {max} digits per number; `rcagd build --max-digits N` raises it)"
            ),
        ));
    }
    Ok(())
}

/// The message for `text` that [`parse_rational`] refused: the reason it gives (a zero
/// denominator said as such, the text shown once and [`clip`](crate::source::clip)ped)
/// and how to write a number.
fn number_message(text: &str, e: &rcagd_algebra::AlgebraError) -> String {
    let shown = crate::source::clip(text);
    match e {
        rcagd_algebra::AlgebraError::ParseNumber { reason, .. } if reason == "zero denominator" => {
            format!("{shown:?}: zero denominator (a fraction p/q needs q ≠ 0)")
        }
        rcagd_algebra::AlgebraError::ParseNumber { reason, .. } => format!(
            "not a number: {shown:?} ({reason}; write an integer \"12\", a fraction \"3/7\" or a \
             decimal \"-0.125\", \"1e-3\")"
        ),
        other => format!("not a number: {shown:?} ({other})"),
    }
}

/// Reads an exact number: a number literal (from its source text) or a string.
///
/// # Errors
/// Wrong type, or text that is not an exact number (the message shows the text).
pub fn number(v: &RecipeValue) -> Result<Rational, ValueError> {
    match &v.kind {
        ValueKind::Number(n) if n.radix == 10 => check_exponent(&n.raw, v.span)?,
        ValueKind::String(s) => check_exponent(s, v.span)?,
        _ => {}
    }
    if let ValueKind::Number(crate::recipe::tree::NumberText { raw: text, .. })
    | ValueKind::String(text) = &v.kind
    {
        check_digits(text, v.span)?;
    }
    match &v.kind {
        ValueKind::Number(n) if n.radix == 10 => {
            let lower = n.raw.to_ascii_lowercase();
            if lower.contains("inf") || lower.contains("nan") {
                return Err(err(
                    v.span,
                    format!(
                        "not a number: `{}` (infinities and NaN are not exact numbers)",
                        crate::source::clip(&n.raw)
                    ),
                ));
            }
            parse_rational(&n.raw).map_err(|e| err(v.span, number_message(&n.raw, &e)))
        }
        ValueKind::Number(n) => {
            let digits = n.raw.replace('_', "");
            IBig::from_str_radix(&digits, n.radix)
                .map(Rational::from)
                .map_err(|_| err(v.span, format!("not a number: `{}`", v.preview())))
        }
        ValueKind::String(s) => parse_rational(s).map_err(|e| err(v.span, number_message(s, &e))),
        _ => Err(wrong_type(v, "a number")),
    }
}

/// The largest magnitude accepted for integer parameters.
const INT_LIMIT: i64 = 1 << 53;

fn int(v: &RecipeValue) -> Result<i64, ValueError> {
    let q = match number(v) {
        Ok(q) => q,
        Err(e) if matches!(v.kind, ValueKind::Number(_) | ValueKind::String(_)) => return Err(e),
        Err(_) => return Err(wrong_type(v, "an integer")),
    };
    if q.denominator() != &dashu_int::UBig::ONE {
        return Err(err(
            v.span,
            format!("expected an integer, found {}", format_rational(&q)),
        ));
    }
    i64::try_from(q.numerator())
        .ok()
        .filter(|n| n.abs() <= INT_LIMIT)
        .ok_or_else(|| {
            err(
                v.span,
                format!("the integer {} is too large", q.numerator()),
            )
        })
}

fn point(v: &RecipeValue, dim: Option<usize>) -> Result<Vec<Rational>, ValueError> {
    let shape = match dim {
        Some(2) => "a point [x, y]".to_string(),
        Some(3) => "a point [x, y, z]".to_string(),
        Some(d) => format!("a point with {d} coordinates"),
        None => "a point [x, y, …]".to_string(),
    };
    let Some(items) = v.as_array() else {
        return Err(wrong_type(v, &shape));
    };
    match dim {
        Some(d) if items.len() != d => {
            return Err(err(
                v.span,
                format!(
                    "expected {shape}, found an array of {} element{}",
                    items.len(),
                    if items.len() == 1 { "" } else { "s" }
                ),
            ))
        }
        None if items.is_empty() => {
            return Err(err(
                v.span,
                format!("expected {shape}, found an empty array"),
            ))
        }
        _ => {}
    }
    items.iter().map(number).collect()
}

/// Points of one dimension (the first point's, or `dim` if given).
fn points(
    v: &RecipeValue,
    dim: Option<usize>,
    what: &str,
) -> Result<Vec<Vec<Rational>>, ValueError> {
    let Some(items) = v.as_array() else {
        return Err(wrong_type(v, &format!("{what} (an array of points)")));
    };
    if items.is_empty() {
        return Err(err(
            v.span,
            format!("expected {what}, found an empty array"),
        ));
    }
    let mut dim = dim;
    let mut out = Vec::with_capacity(items.len());
    for (i, p) in items.iter().enumerate() {
        let q = point(p, dim).map_err(|mut e| {
            if dim.is_some() && p.as_array().is_some() {
                e.message = format!(
                    "{} (all points must have the dimension of the first point)",
                    e.message
                );
            }
            e.message = format!("point {i}: {}", e.message);
            e
        })?;
        dim = Some(q.len());
        out.push(q);
    }
    Ok(out)
}

fn net(v: &RecipeValue) -> Result<Vec<Vec<Vec<Rational>>>, ValueError> {
    let Some(rows) = v.as_array() else {
        return Err(wrong_type(v, "a net (an array of rows of points)"));
    };
    if rows.is_empty() {
        return Err(err(
            v.span,
            "expected a net of points, found an empty array",
        ));
    }
    let mut dim = None;
    let mut cols = None;
    let mut out = Vec::with_capacity(rows.len());
    for (i, row) in rows.iter().enumerate() {
        let r = points(row, dim, "a row of points").map_err(|mut e| {
            e.message = format!("row {i}: {}", e.message);
            e
        })?;
        if let Some(c) = cols {
            if r.len() != c {
                return Err(err(
                    row.span,
                    format!(
                        "row {i} has {} points, row 0 has {c} (the net must be rectangular)",
                        r.len()
                    ),
                ));
            }
        }
        cols = Some(r.len());
        dim = r.first().map(Vec::len);
        out.push(r);
    }
    Ok(out)
}

fn grid(v: &RecipeValue) -> Result<Vec<Vec<Rational>>, ValueError> {
    let Some(rows) = v.as_array() else {
        return Err(wrong_type(v, "a grid of numbers (an array of rows)"));
    };
    if rows.is_empty() {
        return Err(err(
            v.span,
            "expected a grid of numbers, found an empty array",
        ));
    }
    let mut out: Vec<Vec<Rational>> = Vec::with_capacity(rows.len());
    for (i, row) in rows.iter().enumerate() {
        let Some(items) = row.as_array() else {
            return Err(wrong_type(row, &format!("row {i} of numbers")));
        };
        let r = items.iter().map(number).collect::<Result<Vec<_>, _>>()?;
        if let Some(first) = out.first() {
            if r.len() != first.len() {
                return Err(err(
                    row.span,
                    format!(
                        "row {i} has {} numbers, row 0 has {} (the grid must be rectangular)",
                        r.len(),
                        first.len()
                    ),
                ));
            }
        }
        out.push(r);
    }
    Ok(out)
}

/// Converts a recipe value to the typed value of `kind`.
///
/// # Errors
/// Wrong type, wrong array length, not a number, ragged nets, …, located at the
/// offending (sub-)value.
pub fn convert(kind: ParamKind, v: &RecipeValue) -> Result<Value, ValueError> {
    Ok(match kind {
        ParamKind::Number => Value::Number(number(v)?),
        ParamKind::Int => Value::Int(int(v)?),
        ParamKind::Bool => match v.kind {
            ValueKind::Bool(b) => Value::Bool(b),
            _ => return Err(wrong_type(v, "a boolean (true or false)")),
        },
        ParamKind::String => match &v.kind {
            ValueKind::String(s) => Value::Str(s.clone()),
            _ => return Err(wrong_type(v, "a string")),
        },
        ParamKind::Choice(choices) => match &v.kind {
            ValueKind::String(s) if choices.contains(&s.as_str()) => Value::Str(s.clone()),
            ValueKind::String(s) => {
                return Err(err(
                    v.span,
                    format!("{:?} is not {}", crate::source::clip(s), kind.type_name()),
                ))
            }
            _ => return Err(wrong_type(v, &kind.type_name())),
        },
        ParamKind::Point2 => Value::Point(point(v, Some(2))?),
        ParamKind::Point3 => Value::Point(point(v, Some(3))?),
        ParamKind::Point => Value::Point(point(v, None)?),
        ParamKind::Numbers => {
            let Some(items) = v.as_array() else {
                return Err(wrong_type(v, "a list of numbers"));
            };
            Value::Numbers(items.iter().map(number).collect::<Result<_, _>>()?)
        }
        ParamKind::Points => Value::Points(points(v, None, "a list of points")?),
        ParamKind::Net => Value::Net(net(v)?),
        ParamKind::Grid => Value::Grid(grid(v)?),
    })
}
