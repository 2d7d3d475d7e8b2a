//! The op registry: every recipe op, its parameters and how to build it.
//!
//! Ops live in one file per topic (`kernel.rs`, later `quadric.rs`, `ph.rs`, …); each
//! file exports `pub const OPS: &[OpSpec]`. To add a topic, write the file and add its
//! module name to the `topics!` line below — nothing else changes: `rcagd ops`,
//! recipe checking, `docs/recipes.md` tests and the gallery pick it up.
//!
//! The registry checks every parameter before an op's `build` runs: unknown and
//! missing parameters, types, array lengths and exact numbers. `build` receives the
//! typed values through [`OpArgs`] and returns the objects, or an [`OpError`] that
//! the CLI locates at the object's `op` key (or at one parameter, see
//! [`OpError::param`]).

use crate::model::{Geometry, Object};
use crate::value::{ParamKind, Value};
use rcagd_algebra::{Certificate, Rational};

/// Declares the topic modules; the registry lists their `OPS` in this order.
macro_rules! topics {
    ($($topic:ident),* $(,)?) => {
        $(pub mod $topic;)*
        /// Every topic with its ops, in registry order.
        pub const TOPICS: &[(&str, &[OpSpec])] = &[$((stringify!($topic), $topic::OPS)),*];
    };
}

topics!(
    kernel,
    quadric,
    ph,
    ph_planar,
    canal,
    cyclide,
    pn,
    sphere_family,
    line_congruence,
    conic_surface,
    analysis,
    quadric_query,
    laguerre_query,
    ndim,
    sweep
);

pub mod arith;
pub mod describe;

/// Prefixes every certificate's property with `prefix` (certificates of a part or an
/// input of the object, e.g. `"spine: "`).
pub fn prefixed(prefix: &str, certs: Vec<Certificate>) -> Vec<Certificate> {
    certs
        .into_iter()
        .map(|mut c| {
            c.property = format!("{prefix}{}", c.property);
            c
        })
        .collect()
}
pub mod poly_io;

/// What the size of a parameter asks of the construction: the limit it is checked
/// against before the op starts ([`crate::limits::check_params`]). Every list parameter
/// is limited to `--max-points` items and every object's numbers to a spread of
/// `--max-magnitude` decimal orders, whatever its bound.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bound {
    /// Only the limits of every parameter.
    Items,
    /// The degree of the construction grows with it: a list of `n + 1` control points,
    /// coefficients or interpolation/Hermite data asks for degree `n` (a net or grid in
    /// each direction), an integer is the degree itself; limited to `--max-degree`.
    Degree,
    /// An integer that is a sample or mesh count; limited to `--max-samples`.
    Samples,
    /// A tolerance or precision: not part of the data, so not counted in the spread of
    /// magnitudes (`1e-27` beside coordinates of size 1 is a demand, not a scale).
    Tolerance,
}

/// One parameter of an op.
#[derive(Debug, Clone, Copy)]
pub struct ParamSpec {
    /// The key in the recipe.
    pub name: &'static str,
    /// The type.
    pub kind: ParamKind,
    /// `true` if the recipe must give it.
    pub required: bool,
    /// The default, as recipe (TOML) text, if any.
    pub default: Option<&'static str>,
    /// What it means (one line).
    pub doc: &'static str,
    /// The limit its size is checked against (see [`Bound`]).
    pub bound: Bound,
}

impl ParamSpec {
    /// A required parameter.
    pub const fn required(name: &'static str, kind: ParamKind, doc: &'static str) -> Self {
        ParamSpec {
            name,
            kind,
            required: true,
            default: None,
            doc,
            bound: Bound::Items,
        }
    }

    /// An optional parameter without default (absent means "not given").
    pub const fn optional(name: &'static str, kind: ParamKind, doc: &'static str) -> Self {
        ParamSpec {
            name,
            kind,
            required: false,
            default: None,
            doc,
            bound: Bound::Items,
        }
    }

    /// An optional parameter with a default (TOML value text, e.g. `"[0, 0, 0]"`).
    pub const fn with_default(
        name: &'static str,
        kind: ParamKind,
        default: &'static str,
        doc: &'static str,
    ) -> Self {
        ParamSpec {
            name,
            kind,
            required: false,
            default: Some(default),
            doc,
            bound: Bound::Items,
        }
    }

    /// The same parameter, whose size fixes the degree of the construction
    /// ([`Bound::Degree`]).
    pub const fn degree(mut self) -> Self {
        self.bound = Bound::Degree;
        self
    }

    /// The same parameter, a tolerance ([`Bound::Tolerance`]).
    pub const fn tolerance(mut self) -> Self {
        self.bound = Bound::Tolerance;
        self
    }

    /// The same parameter, a sample or mesh count ([`Bound::Samples`]).
    pub const fn samples(mut self) -> Self {
        self.bound = Bound::Samples;
        self
    }

    /// `required`, `default: …` or `optional`, for listings.
    pub fn requirement(&self) -> String {
        match (self.required, self.default) {
            (true, _) => "required".into(),
            (false, Some(d)) => format!("default {d}"),
            (false, None) => "optional".into(),
        }
    }
}

/// The build function of an op.
pub type BuildFn = fn(&OpArgs) -> Result<Vec<Object>, OpError>;

/// A recipe op.
#[derive(Debug, Clone, Copy)]
pub struct OpSpec {
    /// The `op = "…"` name.
    pub name: &'static str,
    /// One line: what it builds.
    pub summary: &'static str,
    /// Its parameters (besides `name` and `op`).
    pub params: &'static [ParamSpec],
    /// A complete recipe (TOML) using it; it must build with all certificates holding.
    pub example: &'static str,
    /// Builds the objects.
    pub build: BuildFn,
}

impl OpSpec {
    /// The parameter called `name`.
    pub fn param(&self, name: &str) -> Option<&'static ParamSpec> {
        self.params.iter().find(|p| p.name == name)
    }

    /// The limits this op's parameters are checked against, one line each, with the
    /// option that raises each (for `rcagd ops NAME` and docs/recipes.md).
    pub fn limit_lines(&self) -> Vec<String> {
        crate::limits::limit_lines(self, &crate::limits::Limits::default())
    }

    /// One line per parameter: `name: type (required) — doc`.
    pub fn param_lines(&self) -> Vec<String> {
        self.params
            .iter()
            .map(|p| {
                format!(
                    "{}: {} ({}) — {}",
                    p.name,
                    p.kind.type_name(),
                    p.requirement(),
                    p.doc
                )
            })
            .collect()
    }
}

/// Every registered op, in registry order.
pub fn all() -> impl Iterator<Item = &'static OpSpec> {
    TOPICS.iter().flat_map(|(_, ops)| ops.iter())
}

/// The op called `name`.
pub fn find(name: &str) -> Option<&'static OpSpec> {
    all().find(|o| o.name == name)
}

/// An error of an op's construction.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OpError {
    /// What went wrong (the construction's error message).
    pub message: String,
    /// The parameter to blame, if one can be named; else the error is located at the
    /// object's `op` key.
    pub param: Option<&'static str>,
}

impl OpError {
    /// An error about the object as a whole.
    pub fn new(message: impl Into<String>) -> Self {
        OpError {
            message: message.into(),
            param: None,
        }
    }

    /// An error about one parameter.
    pub fn param(param: &'static str, message: impl Into<String>) -> Self {
        OpError {
            message: message.into(),
            param: Some(param),
        }
    }
}

impl<E: std::error::Error> From<E> for OpError {
    fn from(e: E) -> Self {
        OpError::new(e.to_string())
    }
}

/// The checked, typed arguments of one object.
#[derive(Debug, Clone)]
pub struct OpArgs {
    name: String,
    op: &'static OpSpec,
    values: Vec<(&'static str, Value)>,
    /// The directory of the recipe file: relative file parameters are resolved in it.
    base_dir: Option<std::path::PathBuf>,
}

impl OpArgs {
    /// Arguments from already typed values (the registry's checker builds these).
    pub fn new(
        name: impl Into<String>,
        op: &'static OpSpec,
        values: Vec<(&'static str, Value)>,
    ) -> Self {
        OpArgs {
            name: name.into(),
            op,
            values,
            base_dir: None,
        }
    }

    /// Relative file parameters (see [`Self::path`]) are resolved in `dir`, the directory
    /// of the recipe file.
    pub fn with_base_dir(mut self, dir: impl Into<std::path::PathBuf>) -> Self {
        self.base_dir = Some(dir.into());
        self
    }

    /// A file-name parameter as a path: absolute as given, relative to the recipe's
    /// directory (the working directory for a recipe read from standard input).
    pub fn path(&self, param: &str) -> Option<std::path::PathBuf> {
        match self.get(param) {
            Some(Value::Str(s)) => {
                let p = std::path::Path::new(s);
                Some(match &self.base_dir {
                    Some(dir) if p.is_relative() => dir.join(p),
                    _ => p.to_path_buf(),
                })
            }
            _ => None,
        }
    }

    /// The object's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The op.
    pub fn op(&self) -> &'static OpSpec {
        self.op
    }

    /// The value of a parameter (given or defaulted); `None` if an optional parameter
    /// without default was not given.
    pub fn get(&self, param: &str) -> Option<&Value> {
        self.values
            .iter()
            .find(|(n, _)| *n == param)
            .map(|(_, v)| v)
    }

    fn missing(&self, param: &str) -> OpError {
        OpError::new(format!(
            "internal error: op `{}` reads parameter `{param}` that it does not declare with this type",
            self.op.name
        ))
    }

    /// A number parameter.
    pub fn number(&self, param: &str) -> Result<Rational, OpError> {
        self.opt_number(param)?.ok_or_else(|| self.missing(param))
    }

    /// An optional number parameter.
    pub fn opt_number(&self, param: &str) -> Result<Option<Rational>, OpError> {
        match self.get(param) {
            None => Ok(None),
            Some(Value::Number(x)) => Ok(Some(x.clone())),
            Some(_) => Err(self.missing(param)),
        }
    }

    /// An integer parameter.
    pub fn int(&self, param: &str) -> Result<i64, OpError> {
        match self.get(param) {
            Some(Value::Int(n)) => Ok(*n),
            _ => Err(self.missing(param)),
        }
    }

    /// A boolean parameter.
    pub fn bool(&self, param: &str) -> Result<bool, OpError> {
        match self.get(param) {
            Some(Value::Bool(b)) => Ok(*b),
            _ => Err(self.missing(param)),
        }
    }

    /// A string or choice parameter.
    pub fn string(&self, param: &str) -> Result<&str, OpError> {
        match self.get(param) {
            Some(Value::Str(s)) => Ok(s),
            _ => Err(self.missing(param)),
        }
    }

    /// A point parameter.
    pub fn point(&self, param: &str) -> Result<Vec<Rational>, OpError> {
        self.opt_point(param)?.ok_or_else(|| self.missing(param))
    }

    /// An optional point parameter.
    pub fn opt_point(&self, param: &str) -> Result<Option<Vec<Rational>>, OpError> {
        match self.get(param) {
            None => Ok(None),
            Some(Value::Point(p)) => Ok(Some(p.clone())),
            Some(_) => Err(self.missing(param)),
        }
    }

    /// An optional list of numbers. An empty list is refused, naming the parameter, when
    /// the parameter is required or has a non-empty default (`function = []`,
    /// `radius = []`): the op would otherwise fail with an unrelated geometric message.
    pub fn opt_numbers(&self, param: &str) -> Result<Option<Vec<Rational>>, OpError> {
        match self.get(param) {
            None => Ok(None),
            Some(Value::Numbers(p)) if p.is_empty() => match self.op.param(param) {
                Some(spec) if spec.required || spec.default.is_some_and(|d| d.trim() != "[]") => {
                    Err(OpError::param(
                        spec.name,
                        format!("`{}` is empty: give at least one number", spec.name),
                    ))
                }
                _ => Ok(Some(Vec::new())),
            },
            Some(Value::Numbers(p)) => Ok(Some(p.clone())),
            Some(_) => Err(self.missing(param)),
        }
    }

    /// A list of points.
    pub fn points(&self, param: &str) -> Result<Vec<Vec<Rational>>, OpError> {
        match self.get(param) {
            Some(Value::Points(p)) => Ok(p.clone()),
            _ => Err(self.missing(param)),
        }
    }

    /// A net of points (rows).
    pub fn net(&self, param: &str) -> Result<Vec<Vec<Vec<Rational>>>, OpError> {
        match self.get(param) {
            Some(Value::Net(p)) => Ok(p.clone()),
            _ => Err(self.missing(param)),
        }
    }

    /// An optional grid of numbers (rows).
    pub fn opt_grid(&self, param: &str) -> Result<Option<Vec<Vec<Rational>>>, OpError> {
        match self.get(param) {
            None => Ok(None),
            Some(Value::Grid(g)) => Ok(Some(g.clone())),
            Some(_) => Err(self.missing(param)),
        }
    }

    /// The parameters as JSON (exact numbers as strings), defaults included.
    pub fn params_json(&self) -> serde_json::Value {
        serde_json::Value::Object(
            self.values
                .iter()
                .map(|(n, v)| (n.to_string(), v.to_json()))
                .collect(),
        )
    }

    /// The object `name` built by this op with the given geometry and certificates.
    pub fn object(&self, geometry: Geometry, certificates: Vec<Certificate>) -> Object {
        Object {
            name: self.name.clone(),
            op: self.op.name.to_string(),
            params: self.params_json(),
            geometry,
            certificates,
            values: Vec::new(),
        }
    }
}
