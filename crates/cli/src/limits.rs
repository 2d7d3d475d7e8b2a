//! Limits on the size of the work a recipe can ask for, checked before any construction
//! starts: the recipe's size in bytes, its number of objects, and the digits of an input
//! number (the decimal exponent is limited separately to `±`[`MAX_EXPONENT`]); per object
//! (checked where the parameters are read, from the op's parameter table, see
//! [`crate::ops::Bound`]): the number of items of every list parameter, the degree that a
//! list of control points, coefficients or interpolation data asks for, a sample or mesh
//! count, and the spread of the magnitudes of the input numbers (a coordinate `1e300`
//! beside coordinates of size 1 makes exact arithmetic carry 1000-bit numbers through
//! every step, and floating-point solvers lose every digit). Each limit has a
//! command-line option of `rcagd build` that raises it; the error names the limit and the
//! option.
//!
//! The work of one op is bounded as well, not by its input size but by time: every
//! object's construction runs under a work budget of [`Limits::seconds`]
//! (`--max-seconds`, default [`DEFAULT_SECONDS`]; [`rcagd_algebra::budget`]), whose
//! checkpoints in the exact algebra end it with the error "work limit exceeded:
//! building NAME took more than N s (raise with --max-seconds)" (exit 2, nothing
//! written).
//!
//! The limits are process-wide settings (`rcagd build` sets them once from its options),
//! so that the number reader of every op sees them without threading them through the op
//! registry.
//!
//! [`MAX_EXPONENT`]: crate::value::MAX_EXPONENT

use crate::ops::{Bound, OpSpec};
use crate::value::{ParamKind, Value};
use rcagd_algebra::Rational;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

/// Default largest recipe, in bytes (16 MiB).
pub const DEFAULT_RECIPE_BYTES: u64 = 16 << 20;
/// Default largest number of objects in one recipe.
pub const DEFAULT_OBJECTS: usize = 10_000;
/// Default largest number of digits of one input number (numerator and denominator
/// together, or the digits of a decimal).
pub const DEFAULT_DIGITS: usize = 10_000;
/// Default largest degree asked for by a list of control points, coefficients or
/// interpolation data (a degree-`n` list has `n + 1` items) or by a degree parameter.
pub const DEFAULT_DEGREE: usize = 64;
/// Default largest number of items of one list parameter (points, numbers, net or grid
/// entries).
pub const DEFAULT_POINTS: usize = 10_000;
/// Default largest sample or mesh count of one parameter.
pub const DEFAULT_SAMPLES: usize = 1_000;
/// Default largest spread of the input numbers of one object, in decimal orders of
/// magnitude: `log10(max |x| / min |x|)` over its non-zero numbers.
pub const DEFAULT_MAGNITUDE: u32 = 20;
/// Default work budget of one object's construction, in seconds (0: none). Ten minutes:
/// every gallery object, op example and test input builds in a few seconds, so only a
/// computation that would run far longer meets it.
pub const DEFAULT_SECONDS: u64 = 600;

static RECIPE_BYTES: AtomicU64 = AtomicU64::new(DEFAULT_RECIPE_BYTES);
static OBJECTS: AtomicUsize = AtomicUsize::new(DEFAULT_OBJECTS);
static DIGITS: AtomicUsize = AtomicUsize::new(DEFAULT_DIGITS);
static DEGREE: AtomicUsize = AtomicUsize::new(DEFAULT_DEGREE);
static POINTS: AtomicUsize = AtomicUsize::new(DEFAULT_POINTS);
static SAMPLES: AtomicUsize = AtomicUsize::new(DEFAULT_SAMPLES);
static MAGNITUDE: AtomicUsize = AtomicUsize::new(DEFAULT_MAGNITUDE as usize);
static SECONDS: AtomicU64 = AtomicU64::new(DEFAULT_SECONDS);

/// The limits of one run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Largest recipe in bytes (`--max-recipe-bytes`).
    pub recipe_bytes: u64,
    /// Largest number of objects (`--max-objects`).
    pub objects: usize,
    /// Largest number of digits of an input number (`--max-digits`).
    pub digits: usize,
    /// Largest degree asked for by a parameter (`--max-degree`).
    pub degree: usize,
    /// Largest number of items of a list parameter (`--max-points`).
    pub points: usize,
    /// Largest sample or mesh count (`--max-samples`).
    pub samples: usize,
    /// Largest spread of the magnitudes of one object's input numbers, in decimal orders
    /// (`--max-magnitude`).
    pub magnitude: u32,
    /// Work budget of one object's construction in seconds, 0 for none
    /// (`--max-seconds`).
    pub seconds: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            recipe_bytes: DEFAULT_RECIPE_BYTES,
            objects: DEFAULT_OBJECTS,
            digits: DEFAULT_DIGITS,
            degree: DEFAULT_DEGREE,
            points: DEFAULT_POINTS,
            samples: DEFAULT_SAMPLES,
            magnitude: DEFAULT_MAGNITUDE,
            seconds: DEFAULT_SECONDS,
        }
    }
}

impl Limits {
    /// Makes these limits the process-wide ones.
    pub fn install(&self) {
        RECIPE_BYTES.store(self.recipe_bytes, Ordering::Relaxed);
        OBJECTS.store(self.objects, Ordering::Relaxed);
        DIGITS.store(self.digits, Ordering::Relaxed);
        DEGREE.store(self.degree, Ordering::Relaxed);
        POINTS.store(self.points, Ordering::Relaxed);
        SAMPLES.store(self.samples, Ordering::Relaxed);
        MAGNITUDE.store(self.magnitude as usize, Ordering::Relaxed);
        SECONDS.store(self.seconds, Ordering::Relaxed);
    }

    /// The process-wide limits.
    pub fn current() -> Self {
        Limits {
            recipe_bytes: RECIPE_BYTES.load(Ordering::Relaxed),
            objects: OBJECTS.load(Ordering::Relaxed),
            digits: DIGITS.load(Ordering::Relaxed),
            degree: DEGREE.load(Ordering::Relaxed),
            points: POINTS.load(Ordering::Relaxed),
            samples: SAMPLES.load(Ordering::Relaxed),
            magnitude: u32::try_from(MAGNITUDE.load(Ordering::Relaxed)).unwrap_or(u32::MAX),
            seconds: SECONDS.load(Ordering::Relaxed),
        }
    }

    /// The work budget of one object's construction (`None` for `seconds = 0`).
    pub fn work_limit(&self) -> Option<std::time::Duration> {
        (self.seconds > 0).then(|| std::time::Duration::from_secs(self.seconds))
    }
}

/// Whether a message shows a non-finite `f64` (`inf`, `-inf`, `NaN` as a word): an `f64`
/// computation overflowed (or computed `inf − inf`, `0·inf`) on the way.
pub fn shows_non_finite(text: &str) -> bool {
    text.split(|c: char| !c.is_alphanumeric())
        .any(|w| matches!(w, "inf" | "NaN" | "nan"))
}

/// Inputs from this decimal order on can overflow an `f64` computation of moderate
/// degree (a product of 20 such coordinates exceeds 1.8e308); below it a non-finite
/// intermediate is taken for something else (`0/0` of degenerate data), not for size.
pub const F64_LARGE_ORDER: f64 = 15.0;

/// The parameter of an object holding its input number of largest magnitude, with that
/// number (shortened to `≈ 1eN` when long), when that number is at least
/// 10^[`F64_LARGE_ORDER`] in magnitude (large enough to overflow `f64` products).
pub fn large_input(args: &crate::ops::OpArgs) -> Option<(&'static str, String)> {
    largest(args)
        .filter(|(_, l, _)| *l >= F64_LARGE_ORDER)
        .map(|(name, _, x)| (name, short(x)))
}

/// The parameter of an object holding its input number of largest magnitude, with that
/// number (shortened to `≈ 1eN` when long), whatever its size: the input to blame for a
/// typed `f64` overflow (the library's `PhError::NonFinite`, "f64 overflow: …").
pub fn largest_input(args: &crate::ops::OpArgs) -> Option<(&'static str, String)> {
    largest(args).map(|(name, _, x)| (name, short(x)))
}

/// Whether a construction's message is the library's typed `f64` overflow
/// (`rcagd::ph::PhError::NonFinite`, whose message starts with "f64 overflow").
pub fn is_typed_overflow(message: &str) -> bool {
    message.starts_with("f64 overflow:") || message.contains(": f64 overflow:")
}

fn largest(args: &crate::ops::OpArgs) -> Option<(&'static str, f64, &Rational)> {
    let mut best: Option<(&'static str, f64, &Rational)> = None;
    for p in args.op().params {
        let Some(v) = args.get(p.name) else {
            continue;
        };
        for x in numbers(v) {
            if let Some(l) = log10_abs(x) {
                if best.is_none_or(|(_, b, _)| l > b) {
                    best = Some((p.name, l, x));
                }
            }
        }
    }
    best
}

/// The message of an `f64` computation that overflowed: names the input to blame (the
/// parameter with the largest number) and what showed the overflow.
pub fn too_large_for_f64(largest: (&str, String), what: &str) -> String {
    let who = format!("`{}` (its largest number is {})", largest.0, largest.1);
    format!(
        "input too large for f64: {who}: the floating-point computation overflowed ({}); \
         f64 ends near 1.8e308 and the construction multiplies coordinates, so rescale the \
         data to numbers of moderate size",
        crate::source::clip(what)
    )
}

/// An exporter's error, said as "input too large for f64" when it shows a non-finite
/// number (exact coordinates beyond the `f64` range of a floating-point format).
pub fn export_error(e: &str) -> String {
    if shows_non_finite(e) && !e.starts_with("input too large") {
        format!(
            "input too large for f64: {e}; the object's exact coordinates exceed the f64 \
             range (±1.8e308) of the format: rescale the data"
        )
    } else {
        e.to_string()
    }
}

/// The message of a construction that ran out of its work budget.
pub fn work_limit_message(name: &str, e: rcagd_algebra::budget::WorkLimitExceeded) -> String {
    format!(
        "work limit exceeded: building {:?} took more than {} s (raise with --max-seconds)",
        crate::source::clip(name),
        rcagd_algebra::budget::secs(e.limit)
    )
}

/// The message of an export phase (`rcagd build --out`) that ran out of its work budget:
/// names the objects and formats, and says that nothing was written.
pub fn export_work_limit_message(
    objects: &[crate::model::Object],
    formats: &[crate::output::OutFormat],
    e: rcagd_algebra::budget::WorkLimitExceeded,
) -> String {
    let names: Vec<String> = objects
        .iter()
        .take(5)
        .map(|o| format!("{:?}", crate::source::clip(&o.name)))
        .collect();
    let more = if objects.len() > 5 { ", …" } else { "" };
    let formats: Vec<&str> = formats.iter().map(|f| f.label()).collect();
    format!(
        "work limit exceeded: exporting {}{more} as {} took more than {} s (raise with \
         --max-seconds; the export has a budget of its own, after the construction's); \
         nothing was written",
        names.join(", "),
        formats.join(", "),
        rcagd_algebra::budget::secs(e.limit)
    )
}

/// `log10 |x|` of a non-zero rational to about 15 significant digits (from the leading
/// 64 bits of numerator and denominator, so it works for numbers beyond `f64`'s range);
/// `None` for zero.
pub fn log10_abs(x: &Rational) -> Option<f64> {
    use dashu_int::ops::{BitTest as _, UnsignedAbs as _};
    let n = x.numerator().clone().unsigned_abs();
    if n == dashu_int::UBig::ZERO {
        return None;
    }
    // log2 of a positive integer from its top 64 bits
    let log2 = |m: &dashu_int::UBig| -> f64 {
        let len = m.bit_len();
        let shift = len.saturating_sub(64);
        let top: dashu_int::UBig = m >> shift;
        let top = u64::try_from(&top).unwrap_or(u64::MAX);
        (top as f64).log2() + shift as f64
    };
    Some((log2(&n) - log2(x.denominator())) * std::f64::consts::LOG10_2)
}

/// The decimal order of magnitude `⌊log10 |x|⌋` of a non-zero rational; `None` for zero.
pub fn decimal_order(x: &Rational) -> Option<i64> {
    // |log10| ≤ ~10⁶ for any number the reader accepts: the cast is exact
    log10_abs(x).map(|l| l.floor() as i64)
}

/// The spread of magnitudes of `numbers` in decimal orders, `log10(max |x| / min |x|)`
/// over the non-zero numbers, with the smallest and the largest of them in magnitude;
/// `None` without a non-zero number.
pub fn magnitude_spread<'a>(
    numbers: impl IntoIterator<Item = &'a Rational>,
) -> Option<(f64, &'a Rational, &'a Rational)> {
    let mut lo: Option<(f64, &Rational)> = None;
    let mut hi: Option<(f64, &Rational)> = None;
    for x in numbers {
        let Some(o) = log10_abs(x) else { continue };
        if lo.is_none_or(|(l, _)| o < l) {
            lo = Some((o, x));
        }
        if hi.is_none_or(|(h, _)| o > h) {
            hi = Some((o, x));
        }
    }
    let ((l, a), (h, b)) = (lo?, hi?);
    Some((h - l, a, b))
}

/// The number of decimal (or other radix) digits in a number's text: every ASCII digit
/// and hexadecimal letter before an exponent mark, in numerator and denominator.
pub fn digit_count(text: &str) -> usize {
    text.split('/')
        .map(|part| {
            let lower = part.trim().to_ascii_lowercase();
            let hex =
                lower.starts_with("0x") || lower.starts_with("-0x") || lower.starts_with("+0x");
            let mantissa = if hex {
                lower.as_str()
            } else {
                lower.split('e').next().unwrap_or("")
            };
            mantissa
                .chars()
                .filter(|c| c.is_ascii_digit() || (hex && c.is_ascii_hexdigit()))
                .count()
        })
        .sum()
}

/// The number of items of a list value and, for a net or grid, its rows and columns.
fn list_size(v: &Value) -> Option<(usize, Option<(usize, usize)>)> {
    match v {
        Value::Numbers(xs) => Some((xs.len(), None)),
        Value::Points(ps) => Some((ps.len(), None)),
        Value::Grid(rows) => {
            let cols = rows.first().map_or(0, Vec::len);
            Some((rows.len().saturating_mul(cols), Some((rows.len(), cols))))
        }
        Value::Net(rows) => {
            let cols = rows.first().map_or(0, Vec::len);
            Some((rows.len().saturating_mul(cols), Some((rows.len(), cols))))
        }
        _ => None,
    }
}

/// The numbers of a value (none for integers, booleans and strings).
fn numbers(v: &Value) -> Box<dyn Iterator<Item = &Rational> + '_> {
    match v {
        Value::Number(x) => Box::new(std::iter::once(x)),
        Value::Point(p) | Value::Numbers(p) => Box::new(p.iter()),
        Value::Points(ps) | Value::Grid(ps) => Box::new(ps.iter().flatten()),
        Value::Net(rows) => Box::new(rows.iter().flatten().flatten()),
        Value::Int(_) | Value::Bool(_) | Value::Str(_) => Box::new(std::iter::empty()),
    }
}

/// Checks the typed parameters of one object against `limits` and the op's bounds
/// ([`Bound`]), before the op starts: every list at most [`Limits::points`] items, a
/// [`Bound::Degree`] parameter asking for at most degree [`Limits::degree`], a
/// [`Bound::Samples`] integer at most [`Limits::samples`], and the non-zero numbers of
/// the object within [`Limits::magnitude`] decimal orders of each other.
///
/// # Errors
/// The parameter to blame and a message naming the limit and the option that raises it.
pub fn check_params(
    op: &OpSpec,
    values: &[(&'static str, Value)],
    limits: &Limits,
) -> Result<(), (&'static str, String)> {
    for (name, v) in values {
        let bound = op.param(name).map_or(Bound::Items, |p| p.bound);
        if let Some((items, shape)) = list_size(v) {
            if items > limits.points {
                return Err((
                    name,
                    format!(
                        "`{name}` has {items} items; the limit is {} items per list \
                         (`rcagd build --max-points N` raises it)",
                        limits.points
                    ),
                ));
            }
            if bound == Bound::Degree {
                let degree = match shape {
                    Some((r, c)) => r.max(c).saturating_sub(1),
                    None => items.saturating_sub(1),
                };
                if degree > limits.degree {
                    let what = match shape {
                        Some((r, c)) => format!("a {r} × {c} net"),
                        None => format!("{items} items"),
                    };
                    return Err((
                        name,
                        format!(
                            "`{name}` asks for degree {degree} ({what}); the limit is degree {} \
                             (`rcagd build --max-degree N` raises it)",
                            limits.degree
                        ),
                    ));
                }
            }
        }
        if let Value::Int(n) = v {
            let (limit, what, option) = match bound {
                Bound::Degree => (limits.degree, "degree", "--max-degree"),
                Bound::Samples => (limits.samples, "samples", "--max-samples"),
                Bound::Items | Bound::Tolerance => continue,
            };
            if usize::try_from(*n).is_ok_and(|n| n > limit) {
                return Err((
                    name,
                    format!(
                        "`{name}` = {n}: the limit is {limit} ({what}; \
                         `rcagd build {option} N` raises it)"
                    ),
                ));
            }
        }
    }
    let all = || {
        values
            .iter()
            .filter(|(n, _)| op.param(n).is_none_or(|p| p.bound != Bound::Tolerance))
            .flat_map(|(n, v)| numbers(v).map(move |x| (*n, x)))
    };
    if let Some((spread, lo, hi)) = magnitude_spread(all().map(|(_, x)| x)) {
        if spread > f64::from(limits.magnitude) {
            // blame the number farther from 1
            let (lo_o, hi_o) = (log10_abs(lo).unwrap_or(0.0), log10_abs(hi).unwrap_or(0.0));
            let odd = if hi_o.abs() >= lo_o.abs() { hi } else { lo };
            let name = all()
                .find(|(_, x)| std::ptr::eq(*x, odd))
                .map_or("", |(n, _)| n);
            return Err((
                name,
                format!(
                    "the numbers span {spread:.1} decimal orders of magnitude ({} beside {}); \
                     the limit is {} orders, because exact and floating-point work grows \
                     with it (rescale the data, or `rcagd build --max-magnitude N` raises it)",
                    crate::source::clip(&short(odd)),
                    crate::source::clip(&short(if std::ptr::eq(odd, hi) { lo } else { hi })),
                    limits.magnitude
                ),
            ));
        }
    }
    Ok(())
}

/// A number for a message: exact when short, else its decimal order (`≈ 1e300`).
fn short(x: &Rational) -> String {
    let s = rcagd_algebra::rational::format_rational(x);
    if s.len() <= 24 {
        return s;
    }
    let sign = if x.numerator() < &dashu_int::IBig::ZERO {
        "-"
    } else {
        ""
    };
    format!("≈ {sign}1e{}", decimal_order(x).unwrap_or(0))
}

/// The limits an op's parameters are checked against under `limits`, one line each.
pub fn limit_lines(op: &OpSpec, limits: &Limits) -> Vec<String> {
    let mut out = Vec::new();
    for p in op.params {
        let list = matches!(
            p.kind,
            ParamKind::Numbers | ParamKind::Points | ParamKind::Net | ParamKind::Grid
        );
        match (p.bound, list) {
            (Bound::Degree, true) => out.push(format!(
                "`{}`: degree ≤ {} (at most {} items{}; `--max-degree`)",
                p.name,
                limits.degree,
                limits.degree + 1,
                if matches!(p.kind, ParamKind::Net | ParamKind::Grid) {
                    " per row and column"
                } else {
                    ""
                }
            )),
            (Bound::Degree, false) => {
                out.push(format!("`{}` ≤ {} (`--max-degree`)", p.name, limits.degree))
            }
            (Bound::Samples, _) => out.push(format!(
                "`{}` ≤ {} (`--max-samples`)",
                p.name, limits.samples
            )),
            (Bound::Items | Bound::Tolerance, _) => {}
        }
    }
    if op.params.iter().any(|p| {
        matches!(
            p.kind,
            ParamKind::Numbers | ParamKind::Points | ParamKind::Net | ParamKind::Grid
        )
    }) {
        out.push(format!(
            "every list ≤ {} items (`--max-points`)",
            limits.points
        ));
    }
    if op.params.iter().any(|p| {
        !matches!(
            p.kind,
            ParamKind::Int | ParamKind::Bool | ParamKind::String | ParamKind::Choice(_)
        )
    }) {
        out.push(format!(
            "non-zero numbers within {} decimal orders of magnitude of each other (`--max-magnitude`); \
             each number ≤ {} digits (`--max-digits`), exponents within ±{}",
            limits.magnitude,
            limits.digits,
            crate::value::MAX_EXPONENT
        ));
    }
    out
}
