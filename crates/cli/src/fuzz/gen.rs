//! The recipe generator of `rcagd fuzz`: single-object recipes built from each op's
//! parameter table ([`OpSpec::params`]) and seeded by the op's own example and the
//! gallery recipes, in four categories (valid, near-valid, degenerate, hostile).
//!
//! Everything is deterministic: a case is a function of the run's seed and the case
//! number ([`Rng`], SplitMix64).

use crate::ops::{OpSpec, ParamSpec};
use crate::recipe::{Format, Recipe, RecipeValue, ValueKind};
use crate::value::ParamKind;

/// SplitMix64 (Steele, Lea, Flood: "Fast splittable pseudorandom number generators",
/// OOPSLA 2014): a small, well-mixed 64-bit generator; no dependency.
#[derive(Debug, Clone)]
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }

    /// The generator of case `case` of a run with seed `seed`.
    pub fn for_case(seed: u64, case: u64) -> Self {
        let mut r = Rng(seed ^ case.wrapping_mul(0xA076_1D64_78BD_642F));
        r.next_u64();
        r
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (0 when `n == 0`).
    pub fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.next_u64() % n as u64) as usize
        }
    }

    /// `true` with probability `p / q`.
    pub fn chance(&mut self, p: usize, q: usize) -> bool {
        self.below(q) < p
    }

    /// An integer in `lo..=hi`.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        let span = (hi - lo) as u64 + 1;
        lo + (self.next_u64() % span) as i64
    }

    /// One element of a non-empty slice (`None` for an empty one).
    pub fn pick<'a, T>(&mut self, xs: &'a [T]) -> Option<&'a T> {
        if xs.is_empty() {
            None
        } else {
            xs.get(self.below(xs.len()))
        }
    }
}

/// A recipe value as the generator sees it (rendered as TOML by [`V::toml`]).
#[derive(Debug, Clone, PartialEq)]
pub enum V {
    /// A number: its TOML text (`3`, `-0.5`, `1e20`) or, if `quoted`, a string `"1/3"`.
    Num(String),
    /// A string.
    Str(String),
    /// A boolean.
    Bool(bool),
    /// An array.
    Arr(Vec<V>),
    /// An inline table.
    Table(Vec<(String, V)>),
    /// Literal TOML text (dates, odd literals).
    Raw(String),
}

fn quote(s: &str) -> String {
    // a JSON string literal is a TOML basic string (same escapes, \uXXXX)
    serde_json::to_string(s).unwrap_or_else(|_| "\"\"".into())
}

fn key(s: &str) -> String {
    if !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
    {
        s.to_string()
    } else {
        quote(s)
    }
}

impl V {
    /// The TOML text of the value.
    pub fn toml(&self) -> String {
        match self {
            V::Num(t) => {
                if t.contains('/') || t.starts_with('+') && t.contains('/') {
                    quote(t)
                } else {
                    t.clone()
                }
            }
            V::Str(s) => quote(s),
            V::Bool(b) => b.to_string(),
            V::Arr(items) => {
                let parts: Vec<String> = items.iter().map(V::toml).collect();
                format!("[{}]", parts.join(", "))
            }
            V::Table(entries) => {
                let parts: Vec<String> = entries
                    .iter()
                    .map(|(k, v)| format!("{} = {}", key(k), v.toml()))
                    .collect();
                format!("{{{}}}", parts.join(", "))
            }
            V::Raw(t) => t.clone(),
        }
    }

    /// Converts a parsed recipe value.
    pub fn from_recipe(v: &RecipeValue) -> V {
        match &v.kind {
            ValueKind::Number(n) => V::Num(match n.radix {
                16 => format!("0x{}", n.raw),
                8 => format!("0o{}", n.raw),
                2 => format!("0b{}", n.raw),
                _ => n.raw.clone(),
            }),
            ValueKind::String(s) => {
                if rcagd_algebra::parse_rational(s).is_ok() {
                    V::Num(s.clone())
                } else {
                    V::Str(s.clone())
                }
            }
            ValueKind::Bool(b) => V::Bool(*b),
            ValueKind::Null => V::Raw("\"\"".into()),
            ValueKind::Datetime(d) => V::Raw(d.clone()),
            ValueKind::Array(items) => V::Arr(items.iter().map(V::from_recipe).collect()),
            ValueKind::Table(entries) => V::Table(
                entries
                    .iter()
                    .map(|e| (e.key.clone(), V::from_recipe(&e.value)))
                    .collect(),
            ),
        }
    }

    /// Every number leaf, as mutable references.
    fn leaves_mut(&mut self) -> Vec<&mut V> {
        match self {
            V::Num(_) => vec![self],
            V::Arr(items) => items.iter_mut().flat_map(V::leaves_mut).collect(),
            V::Table(entries) => entries
                .iter_mut()
                .flat_map(|(_, v)| v.leaves_mut())
                .collect(),
            _ => Vec::new(),
        }
    }

    fn is_num(&self) -> bool {
        matches!(self, V::Num(_))
    }
}

/// One generated single-object recipe.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// The op (as written; a hostile case may name an unknown op).
    pub op: String,
    /// The object's name.
    pub name: String,
    /// The parameters, in order.
    pub params: Vec<(String, V)>,
    /// How it was made: `valid`, `near-valid: …`, `degenerate: …`, `hostile: …`.
    pub category: String,
}

impl Case {
    /// The recipe as TOML text.
    pub fn toml(&self) -> String {
        let mut s = format!(
            "[[object]]\nname = {}\nop = {}\n",
            quote(&self.name),
            quote(&self.op)
        );
        for (k, v) in &self.params {
            s.push_str(&format!("{} = {}\n", key(k), v.toml()));
        }
        s
    }
}

/// The valid seed objects of an op: its doc example's objects of this op and the
/// gallery recipes' objects of this op (parameters as generator values).
pub fn seeds(op: &OpSpec) -> Vec<Vec<(String, V)>> {
    let mut out: Vec<Vec<(String, V)>> = Vec::new();
    let texts = std::iter::once(op.example).chain(crate::gallery::RECIPES.iter().map(|(_, t)| *t));
    for text in texts {
        let Ok(r) = Recipe::parse("seed.toml", text, Some(Format::Toml)) else {
            continue;
        };
        for o in r.objects.iter().filter(|o| o.op == op.name) {
            let params: Vec<(String, V)> = o
                .params
                .iter()
                .map(|e| (e.key.clone(), V::from_recipe(&e.value)))
                .collect();
            if !out.contains(&params) {
                out.push(params);
            }
        }
    }
    out
}

const SMALL: &[&str] = &[
    "0", "1", "-1", "2", "-2", "3", "1/2", "-1/2", "1/3", "2/3", "0.1", "-0.25", "5", "10", "7/5",
    "-3/7", "4", "1/10",
];
/// Hostile numbers of moderate size: they test ranges, signs and rounding without
/// asking exact arithmetic for unbounded work.
const HOSTILE_NUMBERS: &[&str] = &[
    "1e12",
    "-1e12",
    "1e-12",
    "1e20",
    "-1e-9",
    "123456789012",
    "1/1234567",
    "0.000001",
    "9007199254740993",
    "-9223372036854775809",
    "0x7fffffffffffffff",
    "1.0000000001",
    "1e5",
    "-1e5",
    "1/3e6",
];

/// Huge and tiny numbers within the recipe limits (`rcagd fuzz --huge`): they find work
/// that is not bounded (issue 19 item 1), so a run with them reports timeouts.
const HUGE_NUMBERS: &[&str] = &[
    "1e30",
    "-1e30",
    "1e-30",
    "1e100",
    "-1e-100",
    "1e300",
    "1e-300",
    "123456789012345678901234567890",
    "1/123456789012345678901",
    "0.000000000000000000001",
    "1/3e20",
];

/// A random small exact number (as text).
pub fn small_number(rng: &mut Rng) -> String {
    if rng.chance(2, 3) {
        rng.pick(SMALL).unwrap_or(&"1").to_string()
    } else {
        let p = rng.range(-40, 40);
        let q = rng.range(1, 12);
        if q == 1 {
            p.to_string()
        } else {
            format!("{p}/{q}")
        }
    }
}

fn point(rng: &mut Rng, dim: usize) -> V {
    V::Arr((0..dim).map(|_| V::Num(small_number(rng))).collect())
}

fn dim_of(kind: ParamKind, rng: &mut Rng) -> usize {
    match kind {
        ParamKind::Point2 => 2,
        ParamKind::Point3 => 3,
        _ => *rng.pick(&[2, 3, 3, 4]).unwrap_or(&3),
    }
}

/// A fresh value of a parameter's kind (for parameters the seed does not give).
pub fn value_of_kind(rng: &mut Rng, p: &ParamSpec) -> V {
    match p.kind {
        ParamKind::Number => V::Num(small_number(rng)),
        ParamKind::Int => V::Num(
            rng.pick(&["0", "1", "2", "3", "4", "5", "-1", "8", "16"])
                .unwrap_or(&"1")
                .to_string(),
        ),
        ParamKind::Bool => V::Bool(rng.chance(1, 2)),
        ParamKind::String => V::Str(
            rng.pick(&["", "missing-file.step", "missing.igs", "x.json"])
                .unwrap_or(&"")
                .to_string(),
        ),
        ParamKind::Choice(cs) => V::Str(rng.pick(cs).unwrap_or(&"").to_string()),
        ParamKind::Point2 | ParamKind::Point3 | ParamKind::Point => {
            let d = dim_of(p.kind, rng);
            point(rng, d)
        }
        ParamKind::Numbers => V::Arr(
            (0..rng.range(1, 5))
                .map(|_| V::Num(small_number(rng)))
                .collect(),
        ),
        ParamKind::Points => {
            let d = dim_of(p.kind, rng);
            V::Arr((0..rng.range(2, 5)).map(|_| point(rng, d)).collect())
        }
        ParamKind::Net => {
            let (m, n) = (rng.range(2, 3), rng.range(2, 3));
            V::Arr(
                (0..m)
                    .map(|_| V::Arr((0..n).map(|_| point(rng, 3)).collect()))
                    .collect(),
            )
        }
        ParamKind::Grid => {
            let (m, n) = (rng.range(2, 3), rng.range(2, 3));
            V::Arr(
                (0..m)
                    .map(|_| V::Arr((0..n).map(|_| V::Num(small_number(rng))).collect()))
                    .collect(),
            )
        }
    }
}

/// The seed of a case: one of the op's seeds, or (no seed, or 1 in 8) a recipe made
/// from the parameter table alone (required parameters, some optional ones).
fn base(rng: &mut Rng, op: &OpSpec, seeds: &[Vec<(String, V)>]) -> Vec<(String, V)> {
    if let Some(s) = rng.pick(seeds).filter(|_| !rng.chance(1, 8)) {
        return s.clone();
    }
    let mut out = Vec::new();
    for p in op.params {
        if p.required || rng.chance(1, 3) {
            out.push((p.name.to_string(), value_of_kind(rng, p)));
        }
    }
    out
}

/// Changes one number: a neighbour, its negative, zero, a power of ten times it, …
fn mutate_number(rng: &mut Rng, t: &str) -> String {
    let x = t.trim_start_matches('+');
    match rng.below(9) {
        0 => "0".into(),
        1 => {
            if let Some(rest) = x.strip_prefix('-') {
                rest.to_string()
            } else {
                format!("-{x}")
            }
        }
        2 => format!("{x}e{}", rng.range(-6, 6)).replace("/e", "e"),
        3 => small_number(rng),
        4 => format!("{}/{}", rng.range(-100, 100), rng.range(1, 1000)),
        5 => "1/1000000".into(),
        6 => match rcagd_algebra::parse_rational(x) {
            Ok(q) => {
                let d = rcagd_algebra::parse_rational(&format!("1/{}", rng.range(1, 1000)))
                    .unwrap_or_default();
                rcagd_algebra::rational::format_rational(&(q + d))
            }
            Err(_) => "1".into(),
        },
        7 => "1".into(),
        _ => "-1".into(),
    }
}

/// A valid seed with one value mutated (a number, a list's length, a choice).
fn near_valid(
    rng: &mut Rng,
    op: &OpSpec,
    mut params: Vec<(String, V)>,
) -> (Vec<(String, V)>, String) {
    match rng.below(6) {
        // one number leaf of one parameter
        0..=2 => {
            let mut leaves: Vec<&mut V> = params
                .iter_mut()
                .flat_map(|(_, v)| v.leaves_mut())
                .collect();
            let n = leaves.len();
            if let Some(leaf) = leaves.get_mut(rng.below(n)) {
                if let V::Num(t) = &**leaf {
                    let new = mutate_number(rng, t);
                    **leaf = V::Num(new);
                }
            }
            (params, "near-valid: one number changed".into())
        }
        // drop an item of a list, or duplicate one
        3 => {
            let lists: Vec<usize> = (0..params.len())
                .filter(|&i| matches!(&params[i].1, V::Arr(xs) if xs.len() > 1 && !xs[0].is_num()))
                .collect();
            if let Some(&i) = rng.pick(&lists) {
                if let Some((_, V::Arr(xs))) = params.get_mut(i) {
                    let j = rng.below(xs.len());
                    if rng.chance(1, 2) {
                        xs.remove(j);
                    } else {
                        let x = xs[j].clone();
                        xs.insert(j, x);
                    }
                }
            }
            (params, "near-valid: a list item dropped or repeated".into())
        }
        // add an optional parameter the seed does not give
        4 => {
            let absent: Vec<&ParamSpec> = op
                .params
                .iter()
                .filter(|p| !params.iter().any(|(k, _)| k == p.name))
                .collect();
            if let Some(p) = rng.pick(&absent) {
                let v = value_of_kind(rng, p);
                params.push((p.name.to_string(), v));
            }
            (params, "near-valid: an optional parameter added".into())
        }
        // remove an optional parameter
        _ => {
            let optional: Vec<usize> = (0..params.len())
                .filter(|&i| op.param(&params[i].0).is_some_and(|p| !p.required))
                .collect();
            if let Some(&i) = rng.pick(&optional) {
                params.remove(i);
            }
            (params, "near-valid: an optional parameter removed".into())
        }
    }
}

fn zeros(v: &V) -> V {
    match v {
        V::Num(_) => V::Num("0".into()),
        V::Arr(xs) => V::Arr(xs.iter().map(zeros).collect()),
        other => other.clone(),
    }
}

/// Every point of a list (or every row of a net) made equal to the first.
fn all_equal(v: &V) -> V {
    match v {
        V::Arr(xs) if !xs.is_empty() && !xs[0].is_num() => {
            if let V::Arr(inner) = &xs[0] {
                if inner.first().is_some_and(|x| !x.is_num()) {
                    // a net: every point of every row equal to the first point
                    if let Some(p) = inner.first() {
                        return V::Arr(
                            xs.iter()
                                .map(|r| match r {
                                    V::Arr(row) => V::Arr(row.iter().map(|_| p.clone()).collect()),
                                    o => o.clone(),
                                })
                                .collect(),
                        );
                    }
                }
            }
            V::Arr(xs.iter().map(|_| xs[0].clone()).collect())
        }
        V::Arr(xs) if !xs.is_empty() => V::Arr(xs.iter().map(|_| xs[0].clone()).collect()),
        o => o.clone(),
    }
}

/// Points on one line: the last coordinate of each point set to the first's, the
/// others kept on the line through the first two points (x_i = t y_i pattern: every
/// coordinate equal to the first coordinate times a constant).
fn collinear(v: &V) -> V {
    match v {
        V::Arr(xs) if xs.first().is_some_and(|x| matches!(x, V::Arr(_))) => V::Arr(
            xs.iter()
                .enumerate()
                .map(|(i, p)| match p {
                    V::Arr(c) if c.iter().all(V::is_num) => V::Arr(
                        (0..c.len())
                            .map(|k| V::Num(((k + 1) * i).to_string()))
                            .collect(),
                    ),
                    o => collinear(o),
                })
                .collect(),
        ),
        o => o.clone(),
    }
}

/// A degenerate variant: zeros, equal points, collinear points, empty or one-element
/// lists, equal ends of an interval.
fn degenerate(rng: &mut Rng, mut params: Vec<(String, V)>) -> (Vec<(String, V)>, String) {
    let n = params.len();
    if n == 0 {
        return (params, "degenerate: no parameters".into());
    }
    let i = rng.below(n);
    let (k, v) = params[i].clone();
    let (nv, what) = match rng.below(7) {
        0 => (zeros(&v), "zero"),
        1 => (all_equal(&v), "equal points"),
        2 => (collinear(&v), "collinear points"),
        3 => (V::Arr(Vec::new()), "empty list"),
        4 => match &v {
            V::Arr(xs) if !xs.is_empty() => (V::Arr(vec![xs[0].clone()]), "one element"),
            _ => (zeros(&v), "zero"),
        },
        5 => {
            // two parameters of one kind made equal (t0 = t1, from = to, p0 = p1)
            let same: Vec<usize> = (0..n)
                .filter(|&j| {
                    j != i && std::mem::discriminant(&params[j].1) == std::mem::discriminant(&v)
                })
                .collect();
            match rng.pick(&same) {
                Some(&j) => (params[j].1.clone(), "equal to another parameter"),
                None => (zeros(&v), "zero"),
            }
        }
        _ => (
            match &v {
                V::Arr(xs) => V::Arr(xs.iter().rev().cloned().collect()),
                V::Num(t) => V::Num(if let Some(r) = t.strip_prefix('-') {
                    r.to_string()
                } else {
                    format!("-{t}")
                }),
                o => o.clone(),
            },
            "reversed or negated",
        ),
    };
    params[i].1 = nv;
    (params, format!("degenerate: {what} `{k}`"))
}

/// A hostile variant: huge or tiny numbers (within the exponent limit), `1/0`,
/// wrong kinds, nested lists, unknown keys, odd names.
fn hostile(
    rng: &mut Rng,
    op: &OpSpec,
    mut params: Vec<(String, V)>,
    huge: bool,
) -> (Vec<(String, V)>, String, Option<String>) {
    let n = params.len();
    let mut name = None;
    let what: String = match rng.below(10) {
        0..=2 if n > 0 => {
            let mut leaves: Vec<&mut V> = params
                .iter_mut()
                .flat_map(|(_, v)| v.leaves_mut())
                .collect();
            let m = leaves.len();
            let pool = if huge && rng.chance(1, 2) {
                HUGE_NUMBERS
            } else {
                HOSTILE_NUMBERS
            };
            let t = rng.pick(pool).unwrap_or(&"1e12").to_string();
            if let Some(leaf) = leaves.get_mut(rng.below(m)) {
                **leaf = V::Num(t.clone());
            }
            format!("number {t}")
        }
        3 if n > 0 => {
            let i = rng.below(n);
            let bad = rng
                .pick(&[
                    "1/0", "0/0", "nan", "inf", "-inf", "1/", "--1", "1e99999", "0x", "1__0", "",
                ])
                .unwrap_or(&"1/0")
                .to_string();
            let mut leaves: Vec<&mut V> = params[i].1.leaves_mut();
            let m = leaves.len();
            match leaves.get_mut(rng.below(m)) {
                Some(leaf) => **leaf = V::Str(bad.clone()),
                None => params[i].1 = V::Str(bad.clone()),
            }
            format!("bad number {bad:?}")
        }
        4 if n > 0 => {
            let i = rng.below(n);
            let v = params[i].1.clone();
            params[i].1 = match rng.below(6) {
                0 => V::Str("x".into()),
                1 => V::Bool(true),
                2 => V::Arr(vec![v]),
                3 => V::Table(vec![("a".into(), V::Num("1".into()))]),
                4 => V::Raw("1979-05-27T07:32:00Z".into()),
                _ => V::Num("1".into()),
            };
            format!("wrong kind `{}`", params[i].0)
        }
        5 if n > 0 => {
            // a nested list: one number becomes a list, or a list of lists deeper
            let i = rng.below(n);
            let mut leaves: Vec<&mut V> = params[i].1.leaves_mut();
            let m = leaves.len();
            if let Some(leaf) = leaves.get_mut(rng.below(m)) {
                let x = (**leaf).clone();
                **leaf = V::Arr(vec![x.clone(), V::Arr(vec![x])]);
            }
            format!("nested list `{}`", params[i].0)
        }
        6 if n > 0 => {
            // a long list (bounded: at most 24 copies) or a point of many coordinates
            let i = rng.below(n);
            if let V::Arr(xs) = &mut params[i].1 {
                if let Some(x) = xs.first().cloned() {
                    let extra = rng.range(4, 24) as usize;
                    for _ in 0..extra {
                        let mut y = x.clone();
                        for leaf in y.leaves_mut() {
                            *leaf = V::Num(small_number(rng));
                        }
                        xs.push(y);
                    }
                }
            }
            format!("long list `{}`", params[i].0)
        }
        7 => {
            let k = rng
                .pick(&["unknown", "Name", "op", "radius ", "", "\u{e9}"])
                .unwrap_or(&"x")
                .to_string();
            params.push((k.clone(), V::Num("1".into())));
            format!("extra key {k:?}")
        }
        8 => {
            let nm = rng
                .pick(&[
                    "",
                    "a/b",
                    "..",
                    "con",
                    "x y",
                    "é",
                    &"n".repeat(120),
                    "a.exact",
                ])
                .unwrap_or(&"")
                .to_string();
            name = Some(nm.clone());
            format!("name {nm:?}")
        }
        _ => {
            // a required parameter removed, or a missing one given the wrong kind
            let req: Vec<usize> = (0..n)
                .filter(|&i| op.param(&params[i].0).is_some_and(|p| p.required))
                .collect();
            if let Some(&i) = rng.pick(&req) {
                let k = params.remove(i).0;
                format!("required `{k}` removed")
            } else {
                "unchanged".into()
            }
        }
    };
    (params, format!("hostile: {what}"), name)
}

/// Case `case` of op `op` (the category drawn by the generator).
pub fn generate(rng: &mut Rng, op: &OpSpec, seeds: &[Vec<(String, V)>]) -> Case {
    generate_with(rng, op, seeds, false)
}

/// [`generate`], with huge and tiny hostile numbers when `huge` (`rcagd fuzz --huge`).
pub fn generate_with(rng: &mut Rng, op: &OpSpec, seeds: &[Vec<(String, V)>], huge: bool) -> Case {
    let base = base(rng, op, seeds);
    let (params, category, name) = match rng.below(10) {
        0 | 1 => (base, "valid".to_string(), None),
        2..=4 => {
            let (p, c) = near_valid(rng, op, base);
            (p, c, None)
        }
        5..=7 => {
            let (p, c) = degenerate(rng, base);
            (p, c, None)
        }
        _ => hostile(rng, op, base, huge),
    };
    Case {
        op: op.name.to_string(),
        name: name.unwrap_or_else(|| "fz".to_string()),
        params,
        category,
    }
}
