//! Reading STEP (ISO 10303-21) files: the subset that [`crate::step`] writes.
//!
//! The parser reads any well-formed exchange structure (header and data section,
//! simple and complex entity instances, strings with `''` and `\X2\…\X0\` escapes,
//! comments). From the data section it takes
//!
//! * parts: every `SHAPE_DEFINITION_REPRESENTATION` → `PRODUCT_DEFINITION_SHAPE` →
//!   `PRODUCT_DEFINITION` → `PRODUCT_DEFINITION_FORMATION` → `PRODUCT` gives one
//!   object named after the product; its representation (and representations related
//!   to it by `SHAPE_REPRESENTATION_RELATIONSHIP`) is searched for faces
//!   (`ADVANCED_FACE`, `FACE_SURFACE`) and curve sets (`GEOMETRIC_CURVE_SET`,
//!   `GEOMETRIC_SET`), in file order; without any part, all faces and curve sets
//!   of the file form one object `"step"`;
//! * geometry: `B_SPLINE_SURFACE_WITH_KNOTS` and `B_SPLINE_CURVE_WITH_KNOTS`, simple or
//!   in the complex rational form (`RATIONAL_B_SPLINE_SURFACE`/`_CURVE` weights), with
//!   `CARTESIAN_POINT`s in 2 or 3 dimensions (2-D points get `z = 0`).
//!
//! Face bounds are not read (rcagd's faces are whole patches). Every number is read
//! exactly: the decimal `0.1` is the rational `1/10`, so the result is the exact value
//! of the file's text; [`apply_sidecar`] replaces it by the exact values of an
//! [`crate::step::exact_sidecar`] after checking that they round to the file's numbers.
//!
//! Errors are values: a malformed file gives [`IoError::Read`] naming the line and,
//! inside the data section, the entity (`STEP line 12, entity #7: …`).

use crate::IoError;
use rcagd_algebra::{parse_rational, Rational, Scalar};
use rcagd_geom::nurbs::{NurbsCurve, NurbsSurface};
use serde_json::Value;
use std::collections::{HashMap, HashSet};

/// An object read from a STEP or IGES file: its name and its exact NURBS geometry
/// (homogeneous control points `(w, wx, wy, wz)`, weight first, in E3).
#[derive(Debug, Clone, PartialEq)]
pub struct ImportedObject {
    /// The object's name (the product name in STEP, the group name in IGES).
    pub name: String,
    /// The curves, in file order.
    pub curves: Vec<NurbsCurve<Rational>>,
    /// The surfaces (one per face), in file order.
    pub surfaces: Vec<NurbsSurface<Rational>>,
}

impl ImportedObject {
    /// The curves with `f64` knots and control points.
    pub fn curves_f64(&self) -> Vec<NurbsCurve<f64>> {
        self.curves.iter().map(NurbsCurve::to_f64).collect()
    }

    /// The surfaces with `f64` knots and control points.
    pub fn surfaces_f64(&self) -> Vec<NurbsSurface<f64>> {
        self.surfaces.iter().map(NurbsSurface::to_f64).collect()
    }
}

// ---------------------------------------------------------------------------------
// Lexer and parser of ISO 10303-21
// ---------------------------------------------------------------------------------

/// A parameter of an entity instance.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Param {
    /// `#123`
    Ref(u64),
    /// An integer or real, as written.
    Number(String),
    /// A decoded string.
    Str(String),
    /// `.ENUM.` (without the dots).
    Enum(String),
    /// `( … )`
    List(Vec<Param>),
    /// `TYPE( … )`, a typed parameter such as `LENGTH_MEASURE(1.E-07)`.
    Typed(String, Vec<Param>),
    /// `$`
    Unset,
    /// `*`
    Derived,
}

/// One record `NAME(params)`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Record {
    pub name: String,
    pub params: Vec<Param>,
}

/// An entity instance: its records (one for a simple instance, several for a complex
/// one) and the line where it starts.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Instance {
    pub line: usize,
    pub records: Vec<Record>,
}

impl Instance {
    pub(crate) fn record(&self, name: &str) -> Option<&Record> {
        self.records.iter().find(|r| r.name == name)
    }
    fn is_simple(&self, name: &str) -> bool {
        self.records.len() == 1 && self.records[0].name == name
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Keyword(String),
    Ref(u64),
    Number(String),
    Str(String),
    Enum(String),
    LParen,
    RParen,
    Comma,
    Semi,
    Eq,
    Dollar,
    Star,
}

fn err_at(line: usize, entity: Option<u64>, msg: impl std::fmt::Display) -> IoError {
    IoError::read("STEP", Some(line), entity.map(|e| format!("#{e}")), msg)
}

struct Lexer<'a> {
    s: &'a [u8],
    pos: usize,
    line: usize,
}

impl<'a> Lexer<'a> {
    fn new(text: &'a str) -> Self {
        Lexer {
            s: text.as_bytes(),
            pos: 0,
            line: 1,
        }
    }

    fn peek(&self) -> Option<u8> {
        self.s.get(self.pos).copied()
    }

    fn bump(&mut self) -> Option<u8> {
        let c = self.peek()?;
        self.pos += 1;
        if c == b'\n' {
            self.line += 1;
        }
        Some(c)
    }

    fn skip_space(&mut self) -> Result<(), IoError> {
        loop {
            match self.peek() {
                Some(c) if c.is_ascii_whitespace() => {
                    self.bump();
                }
                Some(b'/') if self.s.get(self.pos + 1) == Some(&b'*') => {
                    let start = self.line;
                    self.pos += 2;
                    loop {
                        match self.bump() {
                            None => return Err(err_at(start, None, "unterminated comment")),
                            Some(b'*') if self.peek() == Some(b'/') => {
                                self.pos += 1;
                                break;
                            }
                            _ => {}
                        }
                    }
                }
                _ => return Ok(()),
            }
        }
    }

    /// The next token with its line, `None` at the end of the input.
    fn next(&mut self) -> Result<Option<(Tok, usize)>, IoError> {
        self.skip_space()?;
        let line = self.line;
        let Some(c) = self.peek() else {
            return Ok(None);
        };
        let tok = match c {
            b'(' => {
                self.bump();
                Tok::LParen
            }
            b')' => {
                self.bump();
                Tok::RParen
            }
            b',' => {
                self.bump();
                Tok::Comma
            }
            b';' => {
                self.bump();
                Tok::Semi
            }
            b'=' => {
                self.bump();
                Tok::Eq
            }
            b'$' => {
                self.bump();
                Tok::Dollar
            }
            b'*' => {
                self.bump();
                Tok::Star
            }
            b'#' => {
                self.bump();
                let start = self.pos;
                while self.peek().is_some_and(|c| c.is_ascii_digit()) {
                    self.bump();
                }
                let digits = std::str::from_utf8(&self.s[start..self.pos]).unwrap_or("");
                let id = digits
                    .parse::<u64>()
                    .map_err(|_| err_at(line, None, "`#` is not followed by an entity number"))?;
                Tok::Ref(id)
            }
            b'\'' => Tok::Str(self.string(line)?),
            b'.' if self
                .s
                .get(self.pos + 1)
                .is_some_and(|c| c.is_ascii_alphabetic()) =>
            {
                self.bump();
                let start = self.pos;
                while self
                    .peek()
                    .is_some_and(|c| c.is_ascii_alphanumeric() || c == b'_')
                {
                    self.bump();
                }
                let name = String::from_utf8_lossy(&self.s[start..self.pos]).into_owned();
                if self.bump() != Some(b'.') {
                    return Err(err_at(
                        line,
                        None,
                        format!("enumeration .{name} is not closed by `.`"),
                    ));
                }
                Tok::Enum(name)
            }
            b'+' | b'-' | b'.' | b'0'..=b'9' => {
                let start = self.pos;
                self.bump();
                while self.peek().is_some_and(|c| {
                    c.is_ascii_digit() || matches!(c, b'.' | b'E' | b'e' | b'+' | b'-')
                }) {
                    self.bump();
                }
                Tok::Number(String::from_utf8_lossy(&self.s[start..self.pos]).into_owned())
            }
            c if c.is_ascii_alphabetic() || c == b'_' || c == b'!' => {
                let start = self.pos;
                self.bump();
                while self
                    .peek()
                    .is_some_and(|c| c.is_ascii_alphanumeric() || c == b'_' || c == b'-')
                {
                    self.bump();
                }
                Tok::Keyword(String::from_utf8_lossy(&self.s[start..self.pos]).to_ascii_uppercase())
            }
            other => {
                return Err(err_at(
                    line,
                    None,
                    format!("unexpected character {:?}", other as char),
                ))
            }
        };
        Ok(Some((tok, line)))
    }

    /// A string literal after its opening quote, decoding `''`, `\\`, `\X2\…\X0\`,
    /// `\X4\…\X0\` and `\X\hh`.
    fn string(&mut self, line: usize) -> Result<String, IoError> {
        self.bump();
        let mut raw = Vec::new();
        loop {
            match self.bump() {
                None => return Err(err_at(line, None, "unterminated string")),
                Some(b'\'') => {
                    if self.peek() == Some(b'\'') {
                        self.bump();
                        raw.push(b'\'');
                    } else {
                        break;
                    }
                }
                Some(b'\n') | Some(b'\r') => {}
                Some(c) => raw.push(c),
            }
        }
        decode_step_string(&raw).map_err(|m| err_at(line, None, m))
    }
}

fn hex_units(s: &[u8], width: usize) -> Result<Vec<u32>, String> {
    if !s.len().is_multiple_of(width) {
        return Err("bad \\X2\\ or \\X4\\ escape length".into());
    }
    s.chunks(width)
        .map(|c| {
            std::str::from_utf8(c)
                .ok()
                .and_then(|h| u32::from_str_radix(h, 16).ok())
                .ok_or_else(|| "bad hexadecimal digits in a string escape".to_string())
        })
        .collect()
}

fn decode_step_string(raw: &[u8]) -> Result<String, String> {
    let mut out = String::new();
    let mut i = 0;
    while i < raw.len() {
        if raw[i] == b'\\' {
            let rest = &raw[i..];
            if rest.starts_with(b"\\\\") {
                out.push('\\');
                i += 2;
            } else if rest.starts_with(b"\\X2\\") || rest.starts_with(b"\\X4\\") {
                let width = if rest[2] == b'2' { 4 } else { 8 };
                let body = &rest[4..];
                let end = body
                    .windows(4)
                    .position(|w| w == b"\\X0\\")
                    .ok_or("a \\X2\\ or \\X4\\ escape is not closed by \\X0\\")?;
                let units = hex_units(&body[..end], width)?;
                if width == 4 {
                    let u16s: Vec<u16> = units.iter().map(|&u| u as u16).collect();
                    out.push_str(
                        &String::from_utf16(&u16s).map_err(|_| "invalid UTF-16 in \\X2\\")?,
                    );
                } else {
                    for u in units {
                        out.push(char::from_u32(u).ok_or("invalid code point in \\X4\\")?);
                    }
                }
                i += 4 + end + 4;
            } else if rest.starts_with(b"\\X\\") && rest.len() >= 5 {
                let u = hex_units(&rest[3..5], 2)?;
                out.push(char::from_u32(u[0]).unwrap_or('?'));
                i += 5;
            } else if rest.starts_with(b"\\S\\") && rest.len() >= 4 {
                out.push(char::from_u32(u32::from(rest[3]) + 128).unwrap_or('?'));
                i += 4;
            } else if rest.len() >= 4 && rest[1] == b'P' && rest[3] == b'\\' {
                // \PA\ selects a code page for \S\: ignored
                i += 4;
            } else {
                out.push('\\');
                i += 1;
            }
        } else {
            // bytes outside ASCII are taken as UTF-8 (some writers do that)
            let end = raw[i..]
                .iter()
                .position(|&c| c == b'\\')
                .map_or(raw.len(), |p| i + p);
            out.push_str(&String::from_utf8_lossy(&raw[i..end]));
            i = end;
        }
    }
    Ok(out)
}

struct Parser<'a> {
    lex: Lexer<'a>,
    peeked: Option<(Tok, usize)>,
    entity: Option<u64>,
    depth: usize,
}

impl<'a> Parser<'a> {
    fn peek(&mut self) -> Result<Option<&(Tok, usize)>, IoError> {
        if self.peeked.is_none() {
            self.peeked = self.lex.next()?;
        }
        Ok(self.peeked.as_ref())
    }

    fn next(&mut self) -> Result<(Tok, usize), IoError> {
        self.peek()?;
        self.peeked
            .take()
            .ok_or_else(|| err_at(self.lex.line, self.entity, "unexpected end of file"))
    }

    fn expect(&mut self, want: Tok, what: &str) -> Result<usize, IoError> {
        let (t, line) = self.next()?;
        if t == want {
            Ok(line)
        } else {
            Err(err_at(
                line,
                self.entity,
                format!("expected {what}, found {t:?}"),
            ))
        }
    }

    fn keyword(&mut self, what: &str) -> Result<(String, usize), IoError> {
        match self.next()? {
            (Tok::Keyword(k), line) => Ok((k, line)),
            (t, line) => Err(err_at(
                line,
                self.entity,
                format!("expected {what}, found {t:?}"),
            )),
        }
    }

    /// `( param, … )` after the opening parenthesis has been read.
    fn param_list(&mut self) -> Result<Vec<Param>, IoError> {
        self.depth += 1;
        let r = self.param_list_inner();
        self.depth -= 1;
        r
    }

    fn param_list_inner(&mut self) -> Result<Vec<Param>, IoError> {
        if self.depth > MAX_NESTING {
            return Err(err_at(
                self.lex.line,
                self.entity,
                format!("parameter lists nested deeper than {MAX_NESTING}"),
            ));
        }
        let mut out = Vec::new();
        if let Some((Tok::RParen, _)) = self.peek()? {
            self.next()?;
            return Ok(out);
        }
        loop {
            out.push(self.param()?);
            match self.next()? {
                (Tok::Comma, _) => {}
                (Tok::RParen, _) => return Ok(out),
                (t, line) => {
                    return Err(err_at(
                        line,
                        self.entity,
                        format!("expected `,` or `)`, found {t:?}"),
                    ))
                }
            }
        }
    }

    fn param(&mut self) -> Result<Param, IoError> {
        let (t, line) = self.next()?;
        Ok(match t {
            Tok::Ref(r) => Param::Ref(r),
            Tok::Number(n) => Param::Number(n),
            Tok::Str(s) => Param::Str(s),
            Tok::Enum(e) => Param::Enum(e),
            Tok::Dollar => Param::Unset,
            Tok::Star => Param::Derived,
            Tok::LParen => Param::List(self.param_list()?),
            Tok::Keyword(k) => {
                self.expect(Tok::LParen, "`(` after a type name")?;
                Param::Typed(k, self.param_list()?)
            }
            other => {
                return Err(err_at(
                    line,
                    self.entity,
                    format!("expected a parameter, found {other:?}"),
                ))
            }
        })
    }

    /// `NAME(params)`.
    fn record(&mut self) -> Result<Record, IoError> {
        let (name, _) = self.keyword("an entity name")?;
        self.expect(Tok::LParen, "`(` after the entity name")?;
        Ok(Record {
            name,
            params: self.param_list()?,
        })
    }
}

/// The parsed data section: entity number → instance, and the numbers in file order.
#[derive(Debug)]
pub(crate) struct Part21 {
    pub entities: HashMap<u64, Instance>,
    pub order: Vec<u64>,
}

/// Parses an exchange structure (ISO 10303-21).
pub(crate) fn parse_part21(text: &str) -> Result<Part21, IoError> {
    let mut p = Parser {
        lex: Lexer::new(text),
        peeked: None,
        entity: None,
        depth: 0,
    };
    let (magic, line) = p.keyword("ISO-10303-21")?;
    if magic != "ISO-10303-21" {
        return Err(err_at(
            line,
            None,
            format!("not a STEP file: starts with {magic:?}, not ISO-10303-21"),
        ));
    }
    p.expect(Tok::Semi, "`;` after ISO-10303-21")?;
    let (h, line) = p.keyword("HEADER")?;
    if h != "HEADER" {
        return Err(err_at(line, None, format!("expected HEADER, found {h}")));
    }
    p.expect(Tok::Semi, "`;` after HEADER")?;
    // header entities until ENDSEC
    loop {
        if let Some((Tok::Keyword(k), _)) = p.peek()? {
            if k == "ENDSEC" {
                p.next()?;
                p.expect(Tok::Semi, "`;` after ENDSEC")?;
                break;
            }
        }
        p.record()?;
        p.expect(Tok::Semi, "`;` after a header entity")?;
    }
    let mut entities = HashMap::new();
    let mut order = Vec::new();
    let mut saw_data = false;
    loop {
        let (k, line) = p.keyword("DATA or END-ISO-10303-21")?;
        match k.as_str() {
            "END-ISO-10303-21" => {
                p.expect(Tok::Semi, "`;` after END-ISO-10303-21")?;
                break;
            }
            "DATA" => {
                saw_data = true;
                // optional parameters of DATA (edition 3)
                if let Some((Tok::LParen, _)) = p.peek()? {
                    p.next()?;
                    p.param_list()?;
                }
                p.expect(Tok::Semi, "`;` after DATA")?;
                loop {
                    let (t, line) = p.next()?;
                    match t {
                        Tok::Keyword(k) if k == "ENDSEC" => {
                            p.expect(Tok::Semi, "`;` after ENDSEC")?;
                            break;
                        }
                        Tok::Ref(id) => {
                            p.entity = Some(id);
                            p.expect(Tok::Eq, "`=` after the entity number")?;
                            let records = if let Some((Tok::LParen, _)) = p.peek()? {
                                p.next()?;
                                let mut rs = Vec::new();
                                loop {
                                    if let Some((Tok::RParen, _)) = p.peek()? {
                                        p.next()?;
                                        break;
                                    }
                                    rs.push(p.record()?);
                                }
                                if rs.is_empty() {
                                    return Err(err_at(line, Some(id), "empty complex entity"));
                                }
                                rs
                            } else {
                                vec![p.record()?]
                            };
                            p.expect(Tok::Semi, "`;` after the entity")?;
                            if entities.insert(id, Instance { line, records }).is_some() {
                                return Err(err_at(line, Some(id), "entity number defined twice"));
                            }
                            order.push(id);
                            p.entity = None;
                        }
                        other => {
                            return Err(err_at(
                                line,
                                None,
                                format!("expected an entity `#n = …;` or ENDSEC, found {other:?}"),
                            ))
                        }
                    }
                }
            }
            other => {
                return Err(err_at(
                    line,
                    None,
                    format!("expected DATA or END-ISO-10303-21, found {other}"),
                ))
            }
        }
    }
    if !saw_data {
        return Err(err_at(p.lex.line, None, "the file has no DATA section"));
    }
    Ok(Part21 { entities, order })
}

// ---------------------------------------------------------------------------------
// From entities to geometry
// ---------------------------------------------------------------------------------

/// The largest degree read (rcagd's constructions stay far below).
const MAX_DEGREE: usize = 64;

/// The deepest nesting of parameter lists accepted (guards the recursion).
const MAX_NESTING: usize = 64;

struct Model<'a> {
    p21: &'a Part21,
}

impl<'a> Model<'a> {
    fn get(&self, id: u64, from: (usize, u64)) -> Result<&'a Instance, IoError> {
        self.p21.entities.get(&id).ok_or_else(|| {
            err_at(
                from.0,
                Some(from.1),
                format!("refers to #{id}, which is not defined"),
            )
        })
    }
}

fn param_err(inst: &Instance, id: u64, msg: impl std::fmt::Display) -> IoError {
    err_at(inst.line, Some(id), msg)
}

fn get_param<'p>(r: &'p Record, i: usize, inst: &Instance, id: u64) -> Result<&'p Param, IoError> {
    r.params.get(i).ok_or_else(|| {
        param_err(
            inst,
            id,
            format!(
                "{} has {} parameters, expected more than {i}",
                r.name,
                r.params.len()
            ),
        )
    })
}

fn as_list<'p>(p: &'p Param, inst: &Instance, id: u64, what: &str) -> Result<&'p [Param], IoError> {
    match p {
        Param::List(v) => Ok(v),
        other => Err(param_err(
            inst,
            id,
            format!("{what}: expected a list, found {other:?}"),
        )),
    }
}

fn as_usize(p: &Param, inst: &Instance, id: u64, what: &str) -> Result<usize, IoError> {
    match p {
        Param::Number(n) => n.parse::<usize>().map_err(|_| {
            param_err(
                inst,
                id,
                format!("{what}: expected a non-negative integer, found {n}"),
            )
        }),
        other => Err(param_err(
            inst,
            id,
            format!("{what}: expected an integer, found {other:?}"),
        )),
    }
}

fn as_number(p: &Param, inst: &Instance, id: u64, what: &str) -> Result<Rational, IoError> {
    let text = match p {
        Param::Number(n) => n.as_str(),
        Param::Typed(_, v) if v.len() == 1 => return as_number(&v[0], inst, id, what),
        other => {
            return Err(param_err(
                inst,
                id,
                format!("{what}: expected a number, found {other:?}"),
            ))
        }
    };
    parse_rational(text).map_err(|e| param_err(inst, id, format!("{what}: {e}")))
}

fn as_ref(p: &Param, inst: &Instance, id: u64, what: &str) -> Result<u64, IoError> {
    match p {
        Param::Ref(r) => Ok(*r),
        other => Err(param_err(
            inst,
            id,
            format!("{what}: expected a reference #n, found {other:?}"),
        )),
    }
}

fn as_string(p: &Param) -> String {
    match p {
        Param::Str(s) => s.clone(),
        _ => String::new(),
    }
}

/// The Euclidean coordinates of a `CARTESIAN_POINT`, padded to 3.
fn point(m: &Model, pid: u64, from: (usize, u64)) -> Result<Vec<Rational>, IoError> {
    let inst = m.get(pid, from)?;
    let r = inst.record("CARTESIAN_POINT").ok_or_else(|| {
        param_err(
            inst,
            pid,
            format!("expected a CARTESIAN_POINT, found {}", inst.records[0].name),
        )
    })?;
    let coords = as_list(get_param(r, 1, inst, pid)?, inst, pid, "coordinates")?;
    if coords.is_empty() || coords.len() > 3 {
        return Err(param_err(
            inst,
            pid,
            format!("a point needs 1 to 3 coordinates, found {}", coords.len()),
        ));
    }
    let mut out = coords
        .iter()
        .map(|c| as_number(c, inst, pid, "coordinate"))
        .collect::<Result<Vec<_>, _>>()?;
    out.resize(3, Rational::from(0));
    Ok(out)
}

/// Knots from `(multiplicities)` and `(values)`.
fn expand_knots(
    mults: &Param,
    values: &Param,
    inst: &Instance,
    id: u64,
    what: &str,
) -> Result<Vec<Rational>, IoError> {
    let ms = as_list(mults, inst, id, &format!("{what} knot multiplicities"))?;
    let vs = as_list(values, inst, id, &format!("{what} knots"))?;
    if ms.len() != vs.len() {
        return Err(param_err(
            inst,
            id,
            format!("{what}: {} multiplicities for {} knots", ms.len(), vs.len()),
        ));
    }
    let mut out = Vec::new();
    for (m, v) in ms.iter().zip(vs) {
        let m = as_usize(m, inst, id, "knot multiplicity")?;
        if m > 64 {
            return Err(param_err(
                inst,
                id,
                format!("knot multiplicity {m} is implausibly large"),
            ));
        }
        let v = as_number(v, inst, id, "knot")?;
        out.extend(std::iter::repeat_n(v, m));
    }
    Ok(out)
}

fn weight_check(w: &Rational, inst: &Instance, id: u64) -> Result<(), IoError> {
    if *w > Rational::from(0) {
        Ok(())
    } else {
        Err(param_err(
            inst,
            id,
            format!(
                "weight {} is not positive",
                crate::json::rational_to_json(w)
            ),
        ))
    }
}

fn homogeneous(x: &[Rational], w: &Rational) -> Vec<Rational> {
    let mut h = Vec::with_capacity(4);
    h.push(w.clone());
    h.extend(x.iter().map(|c| c.clone() * w.clone()));
    h
}

/// The parameters of a B-spline curve or surface entity (`kind` `"CURVE"` or
/// `"SURFACE"`), simple or complex, and its weights (`None`: polynomial). The simple
/// entity `B_SPLINE_{kind}_WITH_KNOTS` has the parameters at the indices `simple`; the
/// complex one splits them into the `B_SPLINE_{kind}` record (indices `base`) followed by
/// the `B_SPLINE_{kind}_WITH_KNOTS` record (indices `knots`), with the weights as the
/// first parameter of `RATIONAL_B_SPLINE_{kind}`.
fn bspline_params<'i>(
    inst: &'i Instance,
    id: u64,
    kind: &str,
    simple: &[usize],
    base: &[usize],
    knots: &[usize],
) -> Result<(Vec<&'i Param>, Option<&'i Param>), IoError> {
    let with_knots = format!("B_SPLINE_{kind}_WITH_KNOTS");
    if inst.is_simple(&with_knots) {
        let r = &inst.records[0];
        let ps = simple
            .iter()
            .map(|&i| get_param(r, i, inst, id))
            .collect::<Result<Vec<_>, _>>()?;
        return Ok((ps, None));
    }
    let (Some(b), Some(k)) = (
        inst.record(&format!("B_SPLINE_{kind}")),
        inst.record(&with_knots),
    ) else {
        let names: Vec<&str> = inst.records.iter().map(|r| r.name.as_str()).collect();
        return Err(param_err(
            inst,
            id,
            format!(
                "unsupported {} {}: rcagd reads {with_knots}",
                kind.to_lowercase(),
                names.join(" ")
            ),
        ));
    };
    let w = match inst.record(&format!("RATIONAL_B_SPLINE_{kind}")) {
        Some(r) => Some(get_param(r, 0, inst, id)?),
        None => None,
    };
    let mut ps = Vec::with_capacity(base.len() + knots.len());
    for &i in base {
        ps.push(get_param(b, i, inst, id)?);
    }
    for &i in knots {
        ps.push(get_param(k, i, inst, id)?);
    }
    Ok((ps, w))
}

/// A `TRIMMED_CURVE` of a B-spline curve (trimmed by `PARAMETER_VALUE`s, or by the end
/// points of the basis curve), or a B-spline curve entity.
///
/// ISO 10303-42: `TRIMMED_CURVE(name, basis_curve, trim_1, trim_2, sense_agreement,
/// master_representation)`, each trim a set of `CARTESIAN_POINT` and/or `PARAMETER_VALUE`.
/// The part of the basis curve between the two parameters is kept (the direction does not
/// matter to the spine reader, which orients the chain itself).
fn read_curve_or_trimmed(m: &Model, id: u64) -> Result<NurbsCurve<Rational>, IoError> {
    let inst = m.get(id, (0, id))?;
    let r = &inst.records[0];
    if r.name != "TRIMMED_CURVE" {
        return read_curve(m, id);
    }
    let basis = as_ref(get_param(r, 1, inst, id)?, inst, id, "basis curve")?;
    let bi = m.get(basis, (inst.line, id))?;
    if !bi
        .records
        .iter()
        .any(|x| x.name.starts_with("B_SPLINE_CURVE"))
    {
        return Err(param_err(
            bi,
            basis,
            format!(
                "unsupported basis curve {} of TRIMMED_CURVE #{id}: rcagd reads B_SPLINE_CURVE_WITH_KNOTS",
                bi.records[0].name
            ),
        ));
    }
    let curve = read_curve(m, basis)?;
    let (d0, d1) = curve.domain();
    let mut ends = Vec::with_capacity(2);
    for (k, end) in [(2, &d0), (3, &d1)] {
        let trims = as_list(get_param(r, k, inst, id)?, inst, id, "trim")?;
        let value = trims.iter().find_map(|t| match t {
            Param::Typed(name, v) if name == "PARAMETER_VALUE" && v.len() == 1 => Some(&v[0]),
            _ => None,
        });
        ends.push(match value {
            Some(v) => as_number(v, inst, id, "trim parameter")?,
            // trimmed by points only: accepted where the point is the basis curve's own end
            None => {
                let at = curve.eval(end).map_err(|e| param_err(inst, id, e))?;
                let point = trims
                    .iter()
                    .find_map(|t| match t {
                        Param::Ref(p) => Some(*p),
                        _ => None,
                    })
                    .ok_or_else(|| param_err(inst, id, "a trim without parameter or point"))?;
                let pi = m.get(point, (inst.line, id))?;
                let coords = as_list(get_param(&pi.records[0], 1, pi, point)?, pi, point, "coordinates")?
                    .iter()
                    .map(|x| as_number(x, pi, point, "coordinate"))
                    .collect::<Result<Vec<_>, _>>()?;
                let close = coords.len() == at.len()
                    && coords.iter().zip(&at).all(|(a, b)| {
                        let d = (a.clone() - b.clone()).to_f64().value().abs();
                        d <= 1e-9 * (1.0 + b.to_f64().value().abs())
                    });
                if !close {
                    return Err(param_err(
                        inst,
                        id,
                        "TRIMMED_CURVE trimmed by a point inside the basis curve: rcagd reads trims given as PARAMETER_VALUE",
                    ));
                }
                end.clone()
            }
        });
    }
    let (a, b) = match (ends.first(), ends.get(1)) {
        (Some(x), Some(y)) if x <= y => (x.clone(), y.clone()),
        (Some(x), Some(y)) => (y.clone(), x.clone()),
        _ => return Err(param_err(inst, id, "internal: trim ends")),
    };
    if a < d0 || b > d1 || a == b {
        return Err(param_err(
            inst,
            id,
            format!(
                "trim parameters [{a}, {b}] outside the basis curve's domain [{d0}, {d1}] (a periodic basis curve is not read)"
            ),
        ));
    }
    if a == d0 && b == d1 {
        return Ok(curve);
    }
    let pieces = curve
        .to_bezier_pieces()
        .map_err(|e| param_err(inst, id, e))?;
    let mut kept = Vec::new();
    let mut breaks = vec![a.clone()];
    for p in pieces {
        let (s, t) = p.interval.clone();
        if t <= a || s >= b {
            continue;
        }
        let lo = if s < a { a.clone() } else { s.clone() };
        let hi = if t > b { b.clone() } else { t.clone() };
        let w = t.clone() - s.clone();
        let piece = if lo == s && hi == t {
            p.curve
        } else {
            p.curve
                .restrict(
                    &((lo.clone() - s.clone()) / w.clone()),
                    &((hi.clone() - s) / w),
                )
                .map_err(|e| param_err(inst, id, e))?
        };
        kept.push(piece);
        breaks.push(hi);
    }
    NurbsCurve::from_bezier_pieces_at(&kept, &breaks).map_err(|e| param_err(inst, id, e))
}

/// A B-spline curve entity (simple or complex).
fn read_curve(m: &Model, id: u64) -> Result<NurbsCurve<Rational>, IoError> {
    let inst = m.get(id, (0, id))?;
    let (params, weights_p) = bspline_params(inst, id, "CURVE", &[1, 2, 6, 7], &[0, 1], &[0, 1])?;
    let [deg_p, pts_p, mults_p, knots_p] = params[..] else {
        return Err(param_err(inst, id, "internal: B-spline curve parameters"));
    };
    let degree = as_usize(deg_p, inst, id, "degree")?;
    if degree > MAX_DEGREE {
        return Err(param_err(
            inst,
            id,
            format!("degree {degree} exceeds {MAX_DEGREE}"),
        ));
    }
    let pts = as_list(pts_p, inst, id, "control points")?;
    let knots = expand_knots(mults_p, knots_p, inst, id, "curve")?;
    let weights = match weights_p {
        Some(w) => {
            let ws = as_list(w, inst, id, "weights")?;
            ws.iter()
                .map(|x| as_number(x, inst, id, "weight"))
                .collect::<Result<Vec<_>, _>>()?
        }
        None => vec![Rational::from(1); pts.len()],
    };
    if weights.len() != pts.len() {
        return Err(param_err(
            inst,
            id,
            format!("{} weights for {} control points", weights.len(), pts.len()),
        ));
    }
    let mut hom = Vec::with_capacity(pts.len());
    for (p, w) in pts.iter().zip(&weights) {
        weight_check(w, inst, id)?;
        let x = point(m, as_ref(p, inst, id, "control point")?, (inst.line, id))?;
        hom.push(homogeneous(&x, w));
    }
    if hom.is_empty() {
        return Err(param_err(
            inst,
            id,
            "a B-spline curve without control points",
        ));
    }
    NurbsCurve::new(degree, knots, hom).map_err(|e| param_err(inst, id, e))
}

/// A B-spline surface entity (simple or complex).
fn read_surface(m: &Model, id: u64) -> Result<NurbsSurface<Rational>, IoError> {
    let inst = m.get(id, (0, id))?;
    let (params, w_p) = bspline_params(
        inst,
        id,
        "SURFACE",
        &[1, 2, 3, 8, 9, 10, 11],
        &[0, 1, 2],
        &[0, 1, 2, 3],
    )?;
    let [du, dv, net_p, mu, mv, ku, kv] = params[..] else {
        return Err(param_err(inst, id, "internal: B-spline surface parameters"));
    };
    let p = as_usize(du, inst, id, "u degree")?;
    let q = as_usize(dv, inst, id, "v degree")?;
    if p > MAX_DEGREE || q > MAX_DEGREE {
        return Err(param_err(
            inst,
            id,
            format!("degree ({p}, {q}) exceeds {MAX_DEGREE}"),
        ));
    }
    let rows = as_list(net_p, inst, id, "control net")?;
    let knots_u = expand_knots(mu, ku, inst, id, "u")?;
    let knots_v = expand_knots(mv, kv, inst, id, "v")?;
    let wrows: Option<Vec<&[Param]>> = match w_p {
        Some(w) => Some(
            as_list(w, inst, id, "weights")?
                .iter()
                .map(|r| as_list(r, inst, id, "weight row"))
                .collect::<Result<Vec<_>, _>>()?,
        ),
        None => None,
    };
    if let Some(w) = &wrows {
        if w.len() != rows.len() {
            return Err(param_err(
                inst,
                id,
                format!(
                    "{} weight rows for {} control point rows",
                    w.len(),
                    rows.len()
                ),
            ));
        }
    }
    let mut net = Vec::with_capacity(rows.len());
    for (i, row) in rows.iter().enumerate() {
        let row = as_list(row, inst, id, "control point row")?;
        let mut out_row = Vec::with_capacity(row.len());
        for (j, pt) in row.iter().enumerate() {
            let w = match &wrows {
                Some(w) => {
                    let x = w[i].get(j).ok_or_else(|| {
                        param_err(
                            inst,
                            id,
                            format!("weight row {i} has fewer entries than control point row {i}"),
                        )
                    })?;
                    as_number(x, inst, id, "weight")?
                }
                None => Rational::from(1),
            };
            weight_check(&w, inst, id)?;
            let x = point(m, as_ref(pt, inst, id, "control point")?, (inst.line, id))?;
            out_row.push(homogeneous(&x, &w));
        }
        if let Some(w) = &wrows {
            if w[i].len() != row.len() {
                return Err(param_err(
                    inst,
                    id,
                    format!(
                        "weight row {i} has {} entries, control point row has {}",
                        w[i].len(),
                        row.len()
                    ),
                ));
            }
        }
        net.push(out_row);
    }
    NurbsSurface::new((p, q), knots_u, knots_v, net).map_err(|e| param_err(inst, id, e))
}

/// Collects faces' surfaces and curve-set curves reachable from `start`, in the order
/// of the references, each entity once.
struct Collector<'a, 'm> {
    m: &'m Model<'a>,
    seen: HashSet<u64>,
    surfaces: Vec<u64>,
    curves: Vec<u64>,
}

impl Collector<'_, '_> {
    /// Depth-first, in reference order, with an explicit stack (no recursion on
    /// input-controlled depth).
    fn visit(&mut self, root: u64, from: (usize, u64)) -> Result<(), IoError> {
        let mut stack = vec![(root, from)];
        while let Some((id, from)) = stack.pop() {
            self.visit_one(id, from, &mut stack)?;
        }
        Ok(())
    }

    fn visit_one(
        &mut self,
        id: u64,
        from: (usize, u64),
        stack: &mut Vec<(u64, (usize, u64))>,
    ) -> Result<(), IoError> {
        if !self.seen.insert(id) {
            return Ok(());
        }
        let inst = self.m.get(id, from)?;
        let here = (inst.line, id);
        let first = inst.records[0].name.as_str();
        match first {
            "ADVANCED_FACE" | "FACE_SURFACE" => {
                let r = &inst.records[0];
                let s = as_ref(get_param(r, 2, inst, id)?, inst, id, "face geometry")?;
                if !self.surfaces.contains(&s) {
                    self.surfaces.push(s);
                }
            }
            "GEOMETRIC_CURVE_SET" | "GEOMETRIC_SET" => {
                let r = &inst.records[0];
                for e in as_list(get_param(r, 1, inst, id)?, inst, id, "set elements")? {
                    let c = as_ref(e, inst, id, "set element")?;
                    let ci = self.m.get(c, here)?;
                    if ci
                        .records
                        .iter()
                        .any(|r| r.name.starts_with("B_SPLINE_CURVE") || r.name == "TRIMMED_CURVE")
                    {
                        if !self.curves.contains(&c) {
                            self.curves.push(c);
                        }
                    } else if ci.records[0].name != "CARTESIAN_POINT" {
                        return Err(param_err(
                            ci,
                            c,
                            format!(
                                "unsupported curve {}: rcagd reads B_SPLINE_CURVE_WITH_KNOTS (also trimmed)",
                                ci.records[0].name
                            ),
                        ));
                    }
                }
            }
            "AXIS2_PLACEMENT_3D" | "CARTESIAN_POINT" | "DIRECTION" => {}
            _ => {
                // a topological container: follow every reference
                let mut refs = Vec::new();
                for r in &inst.records {
                    collect_refs(&r.params, &mut refs);
                }
                stack.extend(refs.into_iter().rev().map(|c| (c, here)));
            }
        }
        Ok(())
    }
}

fn collect_refs(ps: &[Param], out: &mut Vec<u64>) {
    for p in ps {
        match p {
            Param::Ref(r) => out.push(*r),
            Param::List(v) | Param::Typed(_, v) => collect_refs(v, out),
            _ => {}
        }
    }
}

/// The items of a representation (its second parameter) and of the representations
/// related to it by `SHAPE_REPRESENTATION_RELATIONSHIP`.
fn representation_items(m: &Model, rep: u64, from: (usize, u64)) -> Result<Vec<u64>, IoError> {
    let mut reps = vec![rep];
    let mut k = 0;
    while k < reps.len() {
        let r = reps[k];
        for &id in &m.p21.order {
            let inst = &m.p21.entities[&id];
            if let Some(rec) = inst.record("SHAPE_REPRESENTATION_RELATIONSHIP") {
                if rec.params.len() >= 4 {
                    let a = as_ref(&rec.params[2], inst, id, "rep_1")?;
                    let b = as_ref(&rec.params[3], inst, id, "rep_2")?;
                    for (x, y) in [(a, b), (b, a)] {
                        if x == r && !reps.contains(&y) {
                            reps.push(y);
                        }
                    }
                }
            }
        }
        k += 1;
    }
    let mut items = Vec::new();
    for r in reps {
        let inst = m.get(r, from)?;
        let rec = &inst.records[0];
        let list = as_list(get_param(rec, 1, inst, r)?, inst, r, "representation items")?;
        for it in list {
            items.push(as_ref(it, inst, r, "representation item")?);
        }
    }
    Ok(items)
}

fn product_name(m: &Model, pds: u64, from: (usize, u64)) -> Result<String, IoError> {
    let step = |id: u64, name: &str, idx: usize, from: (usize, u64)| -> Result<u64, IoError> {
        let inst = m.get(id, from)?;
        let r = inst.record(name).ok_or_else(|| {
            param_err(
                inst,
                id,
                format!("expected {name}, found {}", inst.records[0].name),
            )
        })?;
        as_ref(get_param(r, idx, inst, id)?, inst, id, name)
    };
    let pd = step(pds, "PRODUCT_DEFINITION_SHAPE", 2, from)?;
    let pdf = step(pd, "PRODUCT_DEFINITION", 2, from)?;
    let prod = step(pdf, "PRODUCT_DEFINITION_FORMATION", 2, from).or_else(|_| {
        step(
            pdf,
            "PRODUCT_DEFINITION_FORMATION_WITH_SPECIFIED_SOURCE",
            2,
            from,
        )
    })?;
    let inst = m.get(prod, from)?;
    let r = inst
        .record("PRODUCT")
        .ok_or_else(|| param_err(inst, prod, "expected PRODUCT"))?;
    Ok(as_string(get_param(r, 1, inst, prod)?))
}

/// Reads the objects of a STEP file (module docs).
///
/// # Errors
/// [`IoError::Read`] naming the line (and entity) for a syntax error, a dangling
/// reference, unsupported geometry in a part, or invalid B-spline data (knots,
/// weights, counts).
pub fn read_step(text: &str) -> Result<Vec<ImportedObject>, IoError> {
    let p21 = parse_part21(text)?;
    let m = Model { p21: &p21 };
    let mut parts: Vec<(String, Vec<u64>)> = Vec::new();
    for &id in &p21.order {
        let inst = &p21.entities[&id];
        if let Some(r) = inst.record("SHAPE_DEFINITION_REPRESENTATION") {
            let here = (inst.line, id);
            let pds = as_ref(get_param(r, 0, inst, id)?, inst, id, "definition")?;
            let rep = as_ref(get_param(r, 1, inst, id)?, inst, id, "used_representation")?;
            let name = product_name(&m, pds, here)?;
            parts.push((name, representation_items(&m, rep, here)?));
        }
    }
    if parts.is_empty() {
        // no product structure: every top-level container
        let roots: Vec<u64> = p21
            .order
            .iter()
            .copied()
            .filter(|id| {
                let n = p21.entities[id].records[0].name.as_str();
                matches!(
                    n,
                    "MANIFOLD_SOLID_BREP"
                        | "SHELL_BASED_SURFACE_MODEL"
                        | "GEOMETRIC_CURVE_SET"
                        | "GEOMETRIC_SET"
                        | "BREP_WITH_VOIDS"
                )
            })
            .collect();
        parts.push(("step".to_string(), roots));
    }
    let mut out = Vec::with_capacity(parts.len());
    for (name, items) in parts {
        let mut c = Collector {
            m: &m,
            seen: HashSet::new(),
            surfaces: Vec::new(),
            curves: Vec::new(),
        };
        for it in items {
            c.visit(it, (0, it))?;
        }
        // File order (entity ids), not traversal order: rcagd writes the geometry of an
        // object in patch/curve order, and shells visit faces in a different order.
        c.surfaces.sort_unstable();
        c.curves.sort_unstable();
        let surfaces = c
            .surfaces
            .iter()
            .map(|&s| read_surface(&m, s))
            .collect::<Result<Vec<_>, _>>()?;
        let curves = c
            .curves
            .iter()
            .map(|&s| read_curve_or_trimmed(&m, s))
            .collect::<Result<Vec<_>, _>>()?;
        out.push(ImportedObject {
            name,
            curves,
            surfaces,
        });
    }
    Ok(out)
}

// ---------------------------------------------------------------------------------
// The exact sidecar
// ---------------------------------------------------------------------------------

fn sidecar_err(msg: impl std::fmt::Display) -> IoError {
    IoError::read("sidecar", None, None, msg)
}

fn json_rational(v: &Value) -> Result<Rational, IoError> {
    let s = v
        .as_str()
        .ok_or_else(|| sidecar_err(format!("expected an exact number string, found {v}")))?;
    parse_rational(s).map_err(sidecar_err)
}

fn json_list<'v>(v: &'v Value, what: &str) -> Result<&'v Vec<Value>, IoError> {
    v.as_array()
        .ok_or_else(|| sidecar_err(format!("{what} is not a list")))
}

fn json_hom(v: &Value) -> Result<Vec<Rational>, IoError> {
    json_list(v, "a control point")?
        .iter()
        .map(json_rational)
        .collect()
}

fn json_knots(v: &Value, what: &str) -> Result<Vec<Rational>, IoError> {
    json_list(v, what)?.iter().map(json_rational).collect()
}

fn json_usize(v: &Value, what: &str) -> Result<usize, IoError> {
    v.as_u64()
        .map(|x| x as usize)
        .ok_or_else(|| sidecar_err(format!("{what} is not a non-negative integer")))
}

/// An exact curve of a sidecar (`{degree, knots, control_points}`).
///
/// # Errors
/// [`IoError::Read`] for a malformed entry or invalid NURBS data.
pub fn sidecar_curve(v: &Value) -> Result<NurbsCurve<Rational>, IoError> {
    let p = json_usize(&v["degree"], "degree")?;
    let knots = json_knots(&v["knots"], "knots")?;
    let pts = json_list(&v["control_points"], "control_points")?
        .iter()
        .map(json_hom)
        .collect::<Result<Vec<_>, _>>()?;
    NurbsCurve::new(p, knots, pts).map_err(sidecar_err)
}

/// An exact surface of a sidecar (`{degree: [p, q], knots_u, knots_v, control_points}`).
///
/// # Errors
/// [`IoError::Read`] for a malformed entry or invalid NURBS data.
pub fn sidecar_surface(v: &Value) -> Result<NurbsSurface<Rational>, IoError> {
    let d = json_list(&v["degree"], "degree")?;
    if d.len() != 2 {
        return Err(sidecar_err("a surface degree is [p, q]"));
    }
    let (p, q) = (json_usize(&d[0], "degree")?, json_usize(&d[1], "degree")?);
    let ku = json_knots(&v["knots_u"], "knots_u")?;
    let kv = json_knots(&v["knots_v"], "knots_v")?;
    let net = json_list(&v["control_points"], "control_points")?
        .iter()
        .map(|row| {
            json_list(row, "a control point row")?
                .iter()
                .map(json_hom)
                .collect()
        })
        .collect::<Result<Vec<_>, _>>()?;
    NurbsSurface::new((p, q), ku, kv, net).map_err(sidecar_err)
}

/// Euclidean coordinates and weight of homogeneous points, rounded to `f64`.
fn rounded_points<'a>(pts: impl Iterator<Item = &'a [Rational]>) -> Vec<Vec<f64>> {
    pts.map(|h| {
        if h.first().is_none_or(|w| *w == Rational::from(0)) {
            // a point at infinity never matches (NaN ≠ NaN)
            return vec![f64::NAN];
        }
        let mut v = vec![Scalar::to_f64(&h[0])];
        v.extend(
            h[1..]
                .iter()
                .map(|x| Scalar::to_f64(&(x.clone() / h[0].clone()))),
        );
        v
    })
    .collect()
}

fn rounded(xs: &[Rational]) -> Vec<f64> {
    xs.iter().map(Scalar::to_f64).collect()
}

/// `true` if the exact curve rounds to the file's curve: same degree, and every knot,
/// weight and Euclidean coordinate of the file is the correctly rounded exact value.
pub fn curve_rounds_to(exact: &NurbsCurve<Rational>, file: &NurbsCurve<Rational>) -> bool {
    exact.degree() == file.degree()
        && rounded(exact.knots()) == rounded(file.knots())
        && rounded_points(exact.control_points()) == rounded_points(file.control_points())
}

/// As [`curve_rounds_to`] for surfaces.
pub fn surface_rounds_to(exact: &NurbsSurface<Rational>, file: &NurbsSurface<Rational>) -> bool {
    exact.degree() == file.degree()
        && exact.num_control_points() == file.num_control_points()
        && rounded(exact.knots_u()) == rounded(file.knots_u())
        && rounded(exact.knots_v()) == rounded(file.knots_v())
        && rounded_points(exact.coords().chunks(exact.dim() + 1))
            == rounded_points(file.coords().chunks(file.dim() + 1))
}

/// Replaces the geometry read from a file by the exact values of its sidecar
/// ([`crate::step::exact_sidecar`]): object `k` of the file takes object `k` of the
/// sidecar, after checking that the names agree and that every exact curve and
/// surface rounds to the file's (knots, weights and Euclidean coordinates, see
/// [`curve_rounds_to`]). Works for STEP and IGES imports.
///
/// # Errors
/// [`IoError::Read`] naming the object and piece where file and sidecar disagree
/// (nothing is replaced then), or for a malformed sidecar.
pub fn apply_sidecar(objects: &mut [ImportedObject], sidecar: &Value) -> Result<(), IoError> {
    if sidecar["format"] != "rcagd-exact-nurbs" {
        return Err(sidecar_err(
            "not an rcagd exact sidecar (format ≠ \"rcagd-exact-nurbs\")",
        ));
    }
    let side = json_list(&sidecar["objects"], "objects")?;
    if side.len() != objects.len() {
        return Err(sidecar_err(format!(
            "{} objects in the sidecar, {} in the file",
            side.len(),
            objects.len()
        )));
    }
    let mut replaced = Vec::with_capacity(objects.len());
    for (o, s) in objects.iter().zip(side) {
        if s["name"].as_str() != Some(o.name.as_str()) {
            return Err(sidecar_err(format!(
                "object {:?} of the file is {} in the sidecar",
                o.name, s["name"]
            )));
        }
        let curves = json_list(&s["curves"], "curves")?
            .iter()
            .map(sidecar_curve)
            .collect::<Result<Vec<_>, _>>()?;
        let surfaces = json_list(&s["surfaces"], "surfaces")?
            .iter()
            .map(sidecar_surface)
            .collect::<Result<Vec<_>, _>>()?;
        if curves.len() != o.curves.len() || surfaces.len() != o.surfaces.len() {
            return Err(sidecar_err(format!(
                "object {:?}: the sidecar has {} curves and {} surfaces, the file {} and {}",
                o.name,
                curves.len(),
                surfaces.len(),
                o.curves.len(),
                o.surfaces.len()
            )));
        }
        if let Some(k) = (0..curves.len()).find(|&k| !curve_rounds_to(&curves[k], &o.curves[k])) {
            return Err(sidecar_err(format!(
                "object {:?}, curve {k}: the file's numbers are not the rounded exact values",
                o.name
            )));
        }
        if let Some(k) =
            (0..surfaces.len()).find(|&k| !surface_rounds_to(&surfaces[k], &o.surfaces[k]))
        {
            return Err(sidecar_err(format!(
                "object {:?}, surface {k}: the file's numbers are not the rounded exact values",
                o.name
            )));
        }
        replaced.push((curves, surfaces));
    }
    for (o, (c, s)) in objects.iter_mut().zip(replaced) {
        o.curves = c;
        o.surfaces = s;
    }
    Ok(())
}

/// Exact JSON of an imported object: `{name, curves, surfaces}` in the sidecar format.
pub fn imported_to_json(o: &ImportedObject) -> Value {
    serde_json::json!({
        "name": o.name,
        "curves": o.curves.iter().map(crate::step::nurbs_curve_json).collect::<Vec<_>>(),
        "surfaces": o.surfaces.iter().map(crate::step::nurbs_surface_json).collect::<Vec<_>>(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_complex_entities_strings_and_comments() {
        let text = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('x'),'2;1');\nENDSEC;\nDATA;\n\
                    /* a comment */\n#1 = PRODUCT('it''s','M\\X2\\00F6\\X0\\bius','',(#2));\n\
                    #2 = (A() B(1.E-07,.T.,$,*,LENGTH_MEASURE(2.)));\nENDSEC;\nEND-ISO-10303-21;\n";
        let p = parse_part21(text).expect("parses");
        assert_eq!(p.order, vec![1, 2]);
        let r = &p.entities[&1].records[0];
        assert_eq!(r.params[0], Param::Str("it's".into()));
        assert_eq!(r.params[1], Param::Str("Möbius".into()));
        let b = p.entities[&2].record("B").expect("B");
        assert_eq!(b.params[0], Param::Number("1.E-07".into()));
        assert_eq!(b.params[1], Param::Enum("T".into()));
        assert_eq!(b.params[2], Param::Unset);
        assert_eq!(b.params[3], Param::Derived);
        assert!(matches!(&b.params[4], Param::Typed(n, _) if n == "LENGTH_MEASURE"));
        assert_eq!(p.entities[&2].line, 8);
    }

    #[test]
    fn syntax_errors_name_the_line_and_entity() {
        let text = "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1 = A(1,2);\n#2 = B(1,,2);\nENDSEC;\nEND-ISO-10303-21;\n";
        let e = parse_part21(text).expect_err("error").to_string();
        assert!(e.contains("STEP line 6, entity #2"), "{e}");
        let e = parse_part21("hello").expect_err("error").to_string();
        assert!(e.contains("not a STEP file"), "{e}");
        let e = parse_part21("ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1 = A('x);\n")
            .expect_err("error")
            .to_string();
        assert!(e.contains("unterminated string"), "{e}");
    }
}
