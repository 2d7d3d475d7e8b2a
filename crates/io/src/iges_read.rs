//! Reading IGES files: the subset that [`crate::iges`] writes.
//!
//! The fixed 80-column ASCII form (5.3) is parsed completely: Start, Global (its
//! parameter and record delimiters), Directory Entry pairs and Parameter Data
//! (Hollerith strings, `D` or `E` exponents, empty fields as defaults). Entities read:
//!
//! * 126 (rational B-spline curve) and 128 (rational B-spline surface), non-periodic,
//!   on their whole knot domain (a proper sub-range `V(0), V(1)` or `U, V` is an
//!   error: trimming is not read);
//! * 102 (composite curve): its 126 members, joined into one B-spline when they are
//!   single-span Bézier pieces meeting at their knot intervals (as rcagd writes them),
//!   else kept as separate curves;
//! * 402 forms 1, 7, 14, 15 (groups) → one object per group that is not itself a member
//!   of a group, named by its 406 form 15 name property, else by its entity label;
//! * 406 form 15 (name property);
//! * 186 (manifold solid B-rep object): the surfaces (128) of the faces (510) of its
//!   shell (514), as rcagd writes closed objects; the loops (508) are not read (rcagd's
//!   faces are whole patches).
//!
//! Without groups, every independent (subordinate switch `00`) 126, 128, 102 or 186 is an
//! object, and so is the surface of an independent 143/144 (its trimming is not read).
//! Numbers are read exactly (`0.1` is `1/10`); [`crate::step_read::apply_sidecar`]
//! restores rcagd's exact values. Errors ([`IoError::Read`]) name the line and entity:
//! `IGES line 12, entity type 126 at DE 5: …`.

use crate::step_read::ImportedObject;
use crate::IoError;
use rcagd_algebra::{parse_rational, Rational};
use rcagd_geom::nurbs::{NurbsCurve, NurbsSurface};
use rcagd_geom::BezierCurve;
use std::collections::{HashMap, HashSet};

fn line_err(line: usize, msg: impl std::fmt::Display) -> IoError {
    IoError::read("IGES", Some(line), None, msg)
}

/// A directory entry.
#[derive(Debug, Clone)]
struct Dir {
    kind: i64,
    pd: usize,
    status: String,
    lines: usize,
    form: i64,
    label: String,
    subscript: String,
    /// line number (in the file) of the first directory record
    line: usize,
    /// line number of the first parameter record
    pline: usize,
}

/// A parameter: `None` for an empty (default) field.
#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Text(String),
    Str(String),
    Empty,
}

/// Splits free-format parameters by `delim`, ending at `record`, reading Hollerith
/// strings `nH…` by their length.
fn tokenize(s: &str, delim: char, record: char) -> Result<Vec<Tok>, String> {
    let chars: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    loop {
        while i < chars.len() && chars[i] == ' ' {
            i += 1;
        }
        if i >= chars.len() {
            return Err(format!(
                "the parameters end without the record delimiter {record:?}"
            ));
        }
        // Hollerith?
        let mut j = i;
        while j < chars.len() && chars[j].is_ascii_digit() {
            j += 1;
        }
        let tok = if j > i && j < chars.len() && (chars[j] == 'H' || chars[j] == 'h') {
            let n: usize = chars[i..j]
                .iter()
                .collect::<String>()
                .parse()
                .map_err(|_| "bad Hollerith length".to_string())?;
            let start = j + 1;
            let end = start + n;
            if end > chars.len() {
                return Err(format!(
                    "a Hollerith string of length {n} runs past the parameters"
                ));
            }
            i = end;
            Tok::Str(chars[start..end].iter().collect())
        } else {
            let start = i;
            while i < chars.len() && chars[i] != delim && chars[i] != record {
                i += 1;
            }
            let t: String = chars[start..i]
                .iter()
                .collect::<String>()
                .trim()
                .to_string();
            if t.is_empty() {
                Tok::Empty
            } else {
                Tok::Text(t)
            }
        };
        while i < chars.len() && chars[i] == ' ' {
            i += 1;
        }
        out.push(tok);
        match chars.get(i) {
            Some(&c) if c == delim => i += 1,
            Some(&c) if c == record => return Ok(out),
            Some(&c) => {
                return Err(format!(
                    "expected a delimiter after a parameter, found {c:?}"
                ))
            }
            None => {
                return Err(format!(
                    "the parameters end without the record delimiter {record:?}"
                ))
            }
        }
    }
}

/// The parameters of one entity with typed accessors.
struct Params<'a> {
    toks: Vec<Tok>,
    pos: usize,
    dir: &'a Dir,
    de: usize,
}

impl Params<'_> {
    fn err(&self, msg: impl std::fmt::Display) -> IoError {
        IoError::read(
            "IGES",
            Some(self.dir.pline),
            Some(format!("type {} at DE {}", self.dir.kind, self.de)),
            msg,
        )
    }

    fn next(&mut self, what: &str) -> Result<Tok, IoError> {
        let t = self
            .toks
            .get(self.pos)
            .cloned()
            .ok_or_else(|| self.err(format!("too few parameters: {what} is missing")))?;
        self.pos += 1;
        Ok(t)
    }

    fn int(&mut self, what: &str) -> Result<i64, IoError> {
        match self.next(what)? {
            Tok::Empty => Ok(0),
            Tok::Text(t) => t
                .parse::<i64>()
                .map_err(|_| self.err(format!("{what}: expected an integer, found {t:?}"))),
            Tok::Str(s) => Err(self.err(format!(
                "{what}: expected an integer, found the string {s:?}"
            ))),
        }
    }

    fn count(&mut self, what: &str, max: i64) -> Result<usize, IoError> {
        let n = self.int(what)?;
        if n < 0 || n > max {
            return Err(self.err(format!("{what} = {n} is out of range")));
        }
        Ok(n as usize)
    }

    fn real(&mut self, what: &str) -> Result<Rational, IoError> {
        match self.next(what)? {
            Tok::Empty => Ok(Rational::from(0)),
            Tok::Text(t) => {
                let s = t.replace(['D', 'd'], "E");
                parse_rational(&s).map_err(|e| self.err(format!("{what}: {e}")))
            }
            Tok::Str(s) => {
                Err(self.err(format!("{what}: expected a number, found the string {s:?}")))
            }
        }
    }

    fn reals(&mut self, n: usize, what: &str) -> Result<Vec<Rational>, IoError> {
        (0..n).map(|_| self.real(what)).collect()
    }

    fn string(&mut self, what: &str) -> Result<String, IoError> {
        match self.next(what)? {
            Tok::Str(s) => Ok(s),
            Tok::Empty => Ok(String::new()),
            Tok::Text(t) => {
                Err(self.err(format!("{what}: expected a Hollerith string, found {t:?}")))
            }
        }
    }

    /// The property pointers after the entity's own parameters (IGES §2.2.4.5.2:
    /// `NV`, `NV` pointers, `NP`, `NP` pointers); empty if absent.
    fn properties(&mut self) -> Result<Vec<usize>, IoError> {
        if self.pos >= self.toks.len() {
            return Ok(Vec::new());
        }
        let nv = self.count("number of associativity pointers", 1 << 20)?;
        for _ in 0..nv {
            self.int("associativity pointer")?;
        }
        if self.pos >= self.toks.len() {
            return Ok(Vec::new());
        }
        let np = self.count("number of property pointers", 1 << 20)?;
        (0..np)
            .map(|_| self.count("property pointer", i64::MAX))
            .collect()
    }
}

/// The parsed file: directory entries by DE number and their parameter tokens.
struct Iges {
    dirs: HashMap<usize, Dir>,
    params: HashMap<usize, Vec<Tok>>,
    order: Vec<usize>,
}

fn parse_sections(text: &str) -> Result<Iges, IoError> {
    let mut global = String::new();
    let mut global_line: Option<usize> = None;
    let mut dlines: Vec<(usize, String)> = Vec::new();
    let mut plines: Vec<(usize, String)> = Vec::new();
    let mut seen_t = false;
    for (k, raw) in text.lines().enumerate() {
        let n = k + 1;
        let line = raw.trim_end_matches('\r');
        if line.trim().is_empty() {
            continue;
        }
        if !line.is_ascii() {
            return Err(line_err(n, "not ASCII (IGES records are 80 ASCII columns)"));
        }
        if line.len() < 73 {
            return Err(line_err(
                n,
                format!(
                    "{} columns; an IGES record has its section letter in column 73",
                    line.len()
                ),
            ));
        }
        let section = line.as_bytes()[72] as char;
        let data = &line[..72];
        match section {
            'S' => {}
            'G' => {
                global_line.get_or_insert(n);
                global.push_str(data)
            }
            'D' => dlines.push((n, data.to_string())),
            'P' => plines.push((n, line.to_string())),
            'T' => seen_t = true,
            'B' | 'C' => return Err(line_err(n, "binary and compressed IGES are not supported")),
            other => {
                return Err(line_err(
                    n,
                    format!("unknown section letter {other:?} in column 73"),
                ))
            }
        }
    }
    if !seen_t {
        return Err(IoError::read(
            "IGES",
            Some(text.lines().count().max(1)),
            None,
            "the file ends without a Terminate (T) section; it is truncated",
        ));
    }
    if global.trim().is_empty() {
        return Err(IoError::read("IGES", None, None, "no Global (G) section"));
    }
    // delimiters: `1Hx` or a default (empty) field
    let g: Vec<char> = global.trim_start().chars().collect();
    let (delim, rest) = if g.first() == Some(&',') {
        (',', 1)
    } else if g.len() >= 4 && g[0] == '1' && (g[1] == 'H' || g[1] == 'h') {
        (g[2], 4)
    } else {
        return Err(IoError::read(
            "IGES",
            global_line,
            None,
            "Global section: cannot read the parameter delimiter",
        ));
    };
    let record = if g.get(rest) == Some(&delim) || g.get(rest) == Some(&';') {
        ';'
    } else if g.len() >= rest + 3 && g[rest] == '1' && (g[rest + 1] == 'H' || g[rest + 1] == 'h') {
        g[rest + 2]
    } else {
        ';'
    };
    if !dlines.len().is_multiple_of(2) {
        return Err(line_err(
            dlines.last().map_or(0, |l| l.0),
            "the Directory Entry section has an odd number of records",
        ));
    }
    let field =
        |s: &str, k: usize| -> String { s.get(8 * k..8 * k + 8).unwrap_or("").trim().to_string() };
    let num = |s: &str, k: usize, n: usize, what: &str| -> Result<i64, IoError> {
        let f = field(s, k);
        if f.is_empty() {
            return Ok(0);
        }
        f.parse::<i64>().map_err(|_| {
            line_err(
                n,
                format!("directory field {what}: expected an integer, found {f:?}"),
            )
        })
    };
    let mut dirs = HashMap::new();
    let mut order = Vec::new();
    for (k, pair) in dlines.chunks(2).enumerate() {
        let (n1, a) = (&pair[0].0, &pair[0].1);
        let (n2, b) = (&pair[1].0, &pair[1].1);
        let de = 2 * k + 1;
        let kind = num(a, 0, *n1, "entity type")?;
        let kind2 = num(b, 0, *n2, "entity type")?;
        if kind != kind2 {
            return Err(line_err(*n2, format!("the two directory records of DE {de} disagree on the entity type ({kind} vs {kind2})")));
        }
        let pd = num(a, 1, *n1, "parameter data pointer")?;
        let lines = num(b, 3, *n2, "parameter line count")?;
        if kind != 0 && (pd < 1 || lines < 1) {
            return Err(line_err(
                *n1,
                format!("DE {de}: parameter data pointer {pd} / line count {lines} out of range"),
            ));
        }
        dirs.insert(
            de,
            Dir {
                kind,
                pd: pd.max(0) as usize,
                status: format!("{:0>8}", field(a, 8)),
                lines: lines.max(0) as usize,
                form: num(b, 4, *n2, "form number")?,
                label: field(b, 7),
                subscript: field(b, 8),
                line: *n1,
                pline: 0,
            },
        );
        order.push(de);
    }
    let mut params = HashMap::new();
    for &de in &order {
        let Some(d) = dirs.get_mut(&de) else {
            continue;
        };
        if let Some((n, _)) = plines.get(d.pd.saturating_sub(1)) {
            d.pline = *n;
        }
        let d = &dirs[&de];
        if d.kind == 0 {
            continue;
        }
        let (start, end) = (d.pd, d.pd + d.lines);
        if end - 1 > plines.len() {
            return Err(line_err(
                d.line,
                format!(
                    "DE {de}: parameter lines {start}..{} are beyond the P section ({} lines)",
                    end - 1,
                    plines.len()
                ),
            ));
        }
        let mut text = String::new();
        for (n, l) in &plines[start - 1..end - 1] {
            let back = l.get(64..72).unwrap_or("").trim();
            if back.parse::<usize>().ok() != Some(de) {
                return Err(line_err(
                    *n,
                    format!("parameter line belongs to DE {back:?}, expected {de}"),
                ));
            }
            text.push_str(&l[..64]);
        }
        let toks = tokenize(&text, delim, record).map_err(|m| {
            IoError::read(
                "IGES",
                Some(plines[start - 1].0),
                Some(format!("type {} at DE {de}", d.kind)),
                m,
            )
        })?;
        let first = match toks.first() {
            Some(Tok::Text(t)) => t.parse::<i64>().ok(),
            _ => None,
        };
        if first != Some(d.kind) {
            return Err(IoError::read(
                "IGES",
                Some(plines[start - 1].0),
                Some(format!("type {} at DE {de}", d.kind)),
                format!(
                    "the parameters start with {:?}, expected the entity type {}",
                    toks.first(),
                    d.kind
                ),
            ));
        }
        params.insert(de, toks);
    }
    Ok(Iges {
        dirs,
        params,
        order,
    })
}

impl Iges {
    fn params(&self, de: usize) -> Result<Params<'_>, IoError> {
        let dir = self.dirs.get(&de).ok_or_else(|| {
            IoError::read(
                "IGES",
                None,
                Some(format!("DE {de}")),
                "a pointer refers to this directory entry, which does not exist",
            )
        })?;
        let toks = self.params.get(&de).cloned().ok_or_else(|| {
            IoError::read("IGES", None, Some(format!("DE {de}")), "no parameters")
        })?;
        Ok(Params {
            toks,
            pos: 1,
            dir,
            de,
        })
    }

    fn name_of(&self, de: usize) -> Result<Option<String>, IoError> {
        let dir = &self.dirs[&de];
        let mut p = self.params(de)?;
        // skip the entity's own parameters to reach its property pointers
        match dir.kind {
            402 => {
                let n = p.count("number of group members", 1 << 20)?;
                for _ in 0..n {
                    p.int("member")?;
                }
            }
            _ => return Ok(None),
        }
        for prop in p.properties()? {
            if let Some(d) = self.dirs.get(&prop) {
                if d.kind == 406 && d.form == 15 {
                    let mut q = self.params(prop)?;
                    let n = q.count("number of property values", 1 << 10)?;
                    if n >= 1 {
                        return Ok(Some(q.string("name")?));
                    }
                }
            }
        }
        Ok(None)
    }

    fn curve(&self, de: usize) -> Result<NurbsCurve<Rational>, IoError> {
        let mut p = self.params(de)?;
        let k = p.count("K (upper index of the control points)", 1 << 20)?;
        let m = p.count("M (degree)", 64)?;
        let _planar = p.int("PROP1")?;
        let _closed = p.int("PROP2")?;
        let _polynomial = p.int("PROP3")?;
        if p.int("PROP4")? != 0 {
            return Err(p.err("periodic curves (PROP4 = 1) are not read"));
        }
        let knots = p.reals(k + m + 2, "knot")?;
        let w = p.reals(k + 1, "weight")?;
        let mut pts = Vec::with_capacity(k + 1);
        for wi in &w {
            if *wi <= Rational::from(0) {
                return Err(p.err("a weight is not positive"));
            }
            let x = p.reals(3, "control point coordinate")?;
            let mut h = vec![wi.clone()];
            h.extend(x.into_iter().map(|c| c * wi.clone()));
            pts.push(h);
        }
        let v0 = p.real("V(0)")?;
        let v1 = p.real("V(1)")?;
        let c = NurbsCurve::new(m, knots, pts).map_err(|e| p.err(e))?;
        let (a, b) = c.domain();
        if v0 > a || v1 < b {
            return Err(p.err("the parameter range [V(0), V(1)] is a proper sub-range; trimmed curves are not read"));
        }
        Ok(c)
    }

    fn surface(&self, de: usize) -> Result<NurbsSurface<Rational>, IoError> {
        let mut p = self.params(de)?;
        let k1 = p.count("K1", 1 << 12)?;
        let k2 = p.count("K2", 1 << 12)?;
        let m1 = p.count("M1 (degree in u)", 64)?;
        let m2 = p.count("M2 (degree in v)", 64)?;
        for what in ["PROP1", "PROP2", "PROP3"] {
            p.int(what)?;
        }
        if p.int("PROP4")? != 0 || p.int("PROP5")? != 0 {
            return Err(p.err("periodic surfaces (PROP4/PROP5 = 1) are not read"));
        }
        let ku = p.reals(k1 + m1 + 2, "u knot")?;
        let kv = p.reals(k2 + m2 + 2, "v knot")?;
        let w = p.reals((k1 + 1) * (k2 + 1), "weight")?;
        // first index fastest: point (i, j) is number j(K1+1) + i
        let mut flat = Vec::with_capacity(w.len());
        for wi in &w {
            if *wi <= Rational::from(0) {
                return Err(p.err("a weight is not positive"));
            }
            let x = p.reals(3, "control point coordinate")?;
            let mut h = vec![wi.clone()];
            h.extend(x.into_iter().map(|c| c * wi.clone()));
            flat.push(h);
        }
        let range = p.reals(4, "parameter range")?;
        let net: Vec<Vec<Vec<Rational>>> = (0..=k1)
            .map(|i| (0..=k2).map(|j| flat[j * (k1 + 1) + i].clone()).collect())
            .collect();
        let s = NurbsSurface::new((m1, m2), ku, kv, net).map_err(|e| p.err(e))?;
        let ((u0, u1), (v0, v1)) = s.domain();
        if range[0] > u0 || range[1] < u1 || range[2] > v0 || range[3] < v1 {
            return Err(
                p.err("the parameter range is a proper sub-range; trimmed surfaces are not read")
            );
        }
        Ok(s)
    }

    /// The curves of a 102: joined if they are Bézier pieces meeting at their intervals.
    fn composite(&self, de: usize) -> Result<Vec<NurbsCurve<Rational>>, IoError> {
        let mut p = self.params(de)?;
        let n = p.count("number of curves", 1 << 20)?;
        let mut curves = Vec::with_capacity(n);
        for _ in 0..n {
            let m = p.count("member", i64::MAX)?;
            let kind = self.dirs.get(&m).map(|d| d.kind);
            match kind {
                Some(126) => curves.push(self.curve(m)?),
                Some(k) => {
                    return Err(p.err(format!(
                        "composite member DE {m} is entity {k}; only 126 is read"
                    )))
                }
                None => return Err(p.err(format!("composite member DE {m} does not exist"))),
            }
        }
        Ok(join_pieces(curves))
    }

    fn geometry(&self, de: usize, obj: &mut ImportedObject) -> Result<(), IoError> {
        let kind = self.dirs.get(&de).map(|d| d.kind).ok_or_else(|| {
            IoError::read(
                "IGES",
                None,
                Some(format!("DE {de}")),
                "a pointer refers to this directory entry, which does not exist",
            )
        })?;
        match kind {
            126 => obj.curves.push(self.curve(de)?),
            128 => obj.surfaces.push(self.surface(de)?),
            102 => obj.curves.extend(self.composite(de)?),
            143 | 144 => {
                let mut p = self.params(de)?;
                if kind == 143 {
                    p.int("type")?;
                }
                let s = p.count("surface", i64::MAX)?;
                match self.dirs.get(&s).map(|d| d.kind) {
                    Some(128) => obj.surfaces.push(self.surface(s)?),
                    Some(k) => {
                        return Err(p.err(format!(
                            "the surface DE {s} is entity {k}; only 128 is read"
                        )))
                    }
                    None => return Err(p.err(format!("the surface DE {s} does not exist"))),
                }
            }
            186 => {
                // manifold solid B-rep: its shell's faces' surfaces (trimming by the
                // loops is not read: rcagd's faces are whole patches)
                let mut p = self.params(de)?;
                let shell = p.count("shell", i64::MAX)?;
                let mut q = self.expect(shell, 514, &p)?;
                let n = q.count("number of faces", 1 << 24)?;
                for _ in 0..n {
                    let face = q.count("face", i64::MAX)?;
                    q.int("face orientation flag")?;
                    let mut f = self.expect(face, 510, &q)?;
                    let surf = f.count("surface", i64::MAX)?;
                    self.expect(surf, 128, &f)?;
                    obj.surfaces.push(self.surface(surf)?);
                }
            }
            _ => {}
        }
        Ok(())
    }

    /// The parameters of the entity at `de`, which `from` points to and which must be of
    /// type `kind`.
    fn expect(&self, de: usize, kind: i64, from: &Params) -> Result<Params<'_>, IoError> {
        match self.dirs.get(&de).map(|d| d.kind) {
            Some(k) if k == kind => self.params(de),
            Some(k) => Err(from.err(format!("DE {de} is entity {k}, expected {kind}"))),
            None => Err(from.err(format!("DE {de} does not exist"))),
        }
    }
}

/// Joins single-span Bézier pieces whose intervals and end points meet into one
/// NURBS (`from_bezier_pieces_at`); otherwise returns them unchanged.
fn join_pieces(curves: Vec<NurbsCurve<Rational>>) -> Vec<NurbsCurve<Rational>> {
    if curves.len() < 2 {
        return curves;
    }
    let mut beziers = Vec::with_capacity(curves.len());
    let mut breaks = Vec::with_capacity(curves.len() + 1);
    for c in &curves {
        let (a, b) = c.domain();
        if c.num_control_points() != c.degree() + 1 {
            return curves;
        }
        match breaks.last() {
            None => breaks.push(a),
            Some(last) if *last == a => {}
            Some(_) => return curves,
        }
        breaks.push(b);
        match BezierCurve::from_flat(c.dim(), c.coords().to_vec()) {
            Ok(bz) => beziers.push(bz),
            Err(_) => return curves,
        }
    }
    match NurbsCurve::from_bezier_pieces_at(&beziers, &breaks) {
        Ok(j) => vec![j],
        Err(_) => curves,
    }
}

/// Reads the objects of an IGES file (module docs).
///
/// # Errors
/// [`IoError::Read`] naming the line (and entity) for a malformed record, a
/// dangling pointer, invalid B-spline data, periodic or trimmed geometry.
pub fn read_iges(text: &str) -> Result<Vec<ImportedObject>, IoError> {
    let iges = parse_sections(text)?;
    let groups: Vec<usize> = iges
        .order
        .iter()
        .copied()
        .filter(|de| {
            matches!(iges.dirs[de].kind, 402) && matches!(iges.dirs[de].form, 1 | 7 | 14 | 15)
        })
        .collect();
    let mut out = Vec::new();
    if !groups.is_empty() {
        let mut members_of: HashMap<usize, Vec<usize>> = HashMap::new();
        let mut nested = HashSet::new();
        for &g in &groups {
            let mut p = iges.params(g)?;
            let n = p.count("number of group members", 1 << 20)?;
            let mut ms = Vec::with_capacity(n);
            for _ in 0..n {
                let m = p.count("member", i64::MAX)?;
                if !iges.dirs.contains_key(&m) {
                    return Err(p.err(format!("group member DE {m} does not exist")));
                }
                if iges.dirs[&m].kind == 402 {
                    nested.insert(m);
                }
                ms.push(m);
            }
            members_of.insert(g, ms);
        }
        for &g in &groups {
            if nested.contains(&g) {
                continue;
            }
            let d = &iges.dirs[&g];
            let name = iges.name_of(g)?.unwrap_or_else(|| d.label.clone());
            let mut obj = ImportedObject {
                name,
                curves: Vec::new(),
                surfaces: Vec::new(),
            };
            let mut stack: Vec<usize> = members_of[&g].iter().rev().copied().collect();
            let mut seen = HashSet::new();
            while let Some(m) = stack.pop() {
                if !seen.insert(m) {
                    continue;
                }
                if let Some(sub) = members_of.get(&m) {
                    stack.extend(sub.iter().rev().copied());
                } else {
                    iges.geometry(m, &mut obj)?;
                }
            }
            out.push(obj);
        }
    } else {
        for &de in &iges.order {
            let d = &iges.dirs[&de];
            let independent = d.status.get(2..4) == Some("00");
            if independent && matches!(d.kind, 102 | 126 | 128 | 143 | 144 | 186) {
                let name = if d.subscript.is_empty() || d.subscript == "0" {
                    d.label.clone()
                } else {
                    format!("{}.{}", d.label, d.subscript)
                };
                let mut obj = ImportedObject {
                    name,
                    curves: Vec::new(),
                    surfaces: Vec::new(),
                };
                iges.geometry(de, &mut obj)?;
                out.push(obj);
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokenizer_reads_hollerith_and_defaults() {
        let t = tokenize("406,1, 6Hab,c;d,,1.5D-3;", ',', ';').expect("ok");
        assert_eq!(
            t,
            vec![
                Tok::Text("406".into()),
                Tok::Text("1".into()),
                Tok::Str("ab,c;d".into()),
                Tok::Empty,
                Tok::Text("1.5D-3".into()),
            ]
        );
        assert!(tokenize("1,2", ',', ';').is_err());
        assert!(tokenize("9Hab;", ',', ';').is_err());
    }

    #[test]
    fn short_and_unknown_records_are_errors() {
        let e = read_iges("hello\n").expect_err("error").to_string();
        assert!(e.contains("IGES line 1"), "{e}");
        let bad = format!("{:<72}X{:>7}\n", "", 1);
        let e = read_iges(&bad).expect_err("error").to_string();
        assert!(e.contains("unknown section"), "{e}");
    }
}
