//! IGES 5.3 export of exact rational geometry: entities 126 (rational B-spline curve)
//! and 128 (rational B-spline surface), closed objects as manifold solid B-reps (186),
//! grouped and named per object.
//!
//! # Layout
//!
//! Fixed 80-column ASCII records in the five sections Start (`S`), Global (`G`),
//! Directory Entry (`D`, two records per entity), Parameter Data (`P`, columns 1–64
//! data, 66–72 the entity's directory pointer) and Terminate (`T`). Per object:
//!
//! * one entity 126 per curve and one entity 128 per patch (on `[0, 1]²`, knots
//!   `0ᵐ⁺¹ 1ᵐ⁺¹`), status `00020000` (logically dependent: members of a group). A curve
//!   whose pieces were joined (as in STEP, see [`crate::step::exchange_object`]) is an
//!   entity 102 (composite curve) of its Bézier pieces, each an entity 126 on its knot
//!   interval `[k, k+1]` with status `00010000` (physically dependent): the joints are
//!   only C0 in the parameter, and readers split C0 B-splines (OpenCascade warns);
//! * an object whose patches form closed shells only (a sphere, a torus, a cyclide:
//!   [`crate::step::build_topology`], faces oriented outward by
//!   [`crate::step::exchange_object`]) is written as a manifold solid B-rep instead of
//!   loose surfaces: one entity 186 per shell (status `00020000`, the group's member)
//!   pointing to a closed shell 514 form 1 of faces 510 form 1 (orientation flags 1),
//!   each on its surface 128 with one outer loop 508 form 1 in side order
//!   (counter-clockwise in `(u, v)`); the loop's edges point into one edge list 504 form
//!   1 (shared edges once, their exact curves as entities 126, vertices in one vertex
//!   list 502 form 1) with orientation flag 1 where the face traverses the edge in the
//!   curve's direction; a collapsed side (a pole) is a vertex-type loop entry (TYPE 1,
//!   read by OpenCascade as a degenerated edge). Every loop entry has one parameter-space
//!   curve (ISOP 1): the side of the parameter square as an exact rational line
//!   (126, status `00010500`), parametrized like the edge curve (as STEP's pcurves,
//!   [`crate::step`]). All of these are physically dependent (`00010000`);
//! * an entity 406 form 15 (name property) with the object's name;
//! * an entity 402 form 7 (unordered group without back pointers) of the members,
//!   carrying the name property through its property pointer; status `00000000`.
//!
//! Directory entries also carry the first eight characters of the name (upper case) as
//! entity label and the piece number as subscript.
//!
//! Entity 126 parameters: `K, M, PROP1..4, T(−M..N+M), W(0..K), P(0..K), V(0), V(1),
//! normal` with `PROP1 = 1` (planar, normal `0,0,1`) when every control point has the
//! same `z`, `PROP2 = 0` (the closed flag is informational; OpenCascade turns flagged
//! curves into periodic ones, which changes rational curves), `PROP3 = 1` when all
//! weights are equal, `PROP4 = 0`. Entity 128: `K1, K2, M1, M2, PROP1..5, S, T, W, P,
//! U(0), U(1), V(0), V(1)`, the first index (`u`) varying fastest in `W` and `P`.
//!
//! Numbers as in STEP ([`crate::step::format_real`]): each exact rational rounded once
//! to the nearest `f64`, written as the shortest decimal that reads back to it
//! (`1.`, `0.5`, `1.E-07`). Units: millimetre (flag 2), model scale 1.
//! Names are written in printable ASCII (other characters become `_`), at most 56
//! characters.

use crate::model::Object;
use crate::step::{
    civil_time, collapsed, exchange_objects, export_time, format_real, pcurve, rational_real,
    ExchangeObject, Topology,
};
use crate::IoError;
use rcagd_algebra::{Rational, Scalar};
use rcagd_geom::nurbs::{NurbsCurve, NurbsSurface};
use rcagd_geom::BezierCurve;
use std::collections::HashMap;
use std::fmt::Write as _;

/// Header fields of an IGES file.
#[derive(Debug, Clone, PartialEq)]
pub struct IgesOptions {
    /// The file name in the Global section.
    pub file_name: String,
    /// Seconds since the Unix epoch for the file date; `None`: `SOURCE_DATE_EPOCH` if
    /// set, else now.
    pub time: Option<i64>,
    /// The author.
    pub author: String,
    /// The organization.
    pub organization: String,
}

impl Default for IgesOptions {
    fn default() -> Self {
        IgesOptions {
            file_name: "rcagd.igs".into(),
            time: None,
            author: "rcagd".into(),
            organization: "rcagd".into(),
        }
    }
}

/// Longest name written.
const MAX_NAME: usize = 56;

/// Printable ASCII only (others become `_`), at most [`MAX_NAME`] characters.
fn ascii_name(s: &str) -> String {
    s.chars()
        .map(|c| if (' '..='~').contains(&c) { c } else { '_' })
        .take(MAX_NAME)
        .collect()
}

/// An IGES Hollerith string `nHtext`.
fn hollerith(s: &str) -> String {
    format!("{}H{s}", s.len())
}

/// One entity: directory fields and parameter tokens (without delimiters).
struct Entity {
    kind: u32,
    form: u32,
    status: &'static str,
    label: String,
    subscript: usize,
    params: Vec<String>,
}

fn reals(xs: &[Rational], out: &mut Vec<String>) -> Result<(), IoError> {
    for x in xs {
        out.push(rational_real(x)?);
    }
    Ok(())
}

/// Euclidean coordinates of a homogeneous point.
fn euclid(h: &[Rational]) -> Vec<Rational> {
    h[1..].iter().map(|x| x.clone() / h[0].clone()).collect()
}

fn curve_params(c: &NurbsCurve<Rational>) -> Result<Vec<String>, IoError> {
    let n = c.num_control_points();
    let m = c.degree();
    let w: Vec<Rational> = c.control_points().map(|h| h[0].clone()).collect();
    let pts: Vec<Vec<Rational>> = c.control_points().map(euclid).collect();
    let polynomial = w.iter().all(|x| *x == w[0]);
    let planar = pts.iter().all(|p| p[2] == pts[0][2]);
    let mut out = vec![
        "126".to_string(),
        (n - 1).to_string(),
        m.to_string(),
        u8::from(planar).to_string(),
        "0".into(),
        u8::from(polynomial).to_string(),
        "0".into(),
    ];
    reals(c.knots(), &mut out)?;
    reals(&w, &mut out)?;
    for p in &pts {
        reals(p, &mut out)?;
    }
    let (a, b) = c.domain();
    reals(&[a, b], &mut out)?;
    if planar {
        out.extend(["0.", "0.", "1."].map(String::from));
    } else {
        out.extend(["0.", "0.", "0."].map(String::from));
    }
    Ok(out)
}

fn surface_params(s: &NurbsSurface<Rational>) -> Result<Vec<String>, IoError> {
    let (nu, nv) = s.num_control_points();
    let (p, q) = s.degree();
    let mut w = Vec::with_capacity(nu * nv);
    let mut pts = Vec::with_capacity(nu * nv);
    // the first index (u) varies fastest
    for j in 0..nv {
        for i in 0..nu {
            let h = s
                .control_point(i, j)
                .ok_or_else(|| IoError::Invalid(format!("control point ({i}, {j}) missing")))?;
            w.push(h[0].clone());
            pts.push(euclid(h));
        }
    }
    let polynomial = w.iter().all(|x| *x == w[0]);
    let mut out = vec![
        "128".to_string(),
        (nu - 1).to_string(),
        (nv - 1).to_string(),
        p.to_string(),
        q.to_string(),
        "0".into(),
        "0".into(),
        u8::from(polynomial).to_string(),
        "0".into(),
        "0".into(),
    ];
    reals(s.knots_u(), &mut out)?;
    reals(s.knots_v(), &mut out)?;
    reals(&w, &mut out)?;
    for x in &pts {
        reals(x, &mut out)?;
    }
    let ((u0, u1), (v0, v1)) = s.domain();
    reals(&[u0, u1, v0, v1], &mut out)?;
    Ok(out)
}

/// The directory-entry pointer of the entity just pushed.
fn last_de(entities: &[Entity]) -> usize {
    2 * entities.len() - 1
}

/// A parameter-space line of the `(u, v)` square as a planar entity 126 (`z = 0`).
fn pcurve_params(pc: &NurbsCurve<Rational>) -> Result<Vec<String>, IoError> {
    let coords: Vec<Rational> = pc
        .control_points()
        .flat_map(|h| [h[0].clone(), h[1].clone(), h[2].clone(), Rational::from(0)])
        .collect();
    let line = BezierCurve::from_flat(3, coords)?;
    curve_params(&NurbsCurve::from_bezier(&line)?)
}

/// The manifold solid B-rep of an object whose shells are all closed (module docs):
/// entities 502, 126 (edge curves), 504, 128, 126 (parameter lines), 508, 510, 514 and
/// one 186 per shell; returns the 186 pointers.
fn brep_entities(
    o: &ExchangeObject,
    topo: &Topology,
    label: &str,
    entities: &mut Vec<Entity>,
) -> Result<Vec<usize>, IoError> {
    let dependent = |kind: u32, form: u32, status: &'static str, params: Vec<String>| Entity {
        kind,
        form,
        status,
        label: label.to_string(),
        subscript: 0,
        params,
    };
    // the vertices: the topology's and the poles of collapsed sides (by exact position)
    let mut vertices: Vec<Vec<Rational>> = topo.vertices.clone();
    let mut index: HashMap<Vec<Rational>, usize> = vertices
        .iter()
        .cloned()
        .enumerate()
        .map(|(i, v)| (v, i))
        .collect();
    for f in &topo.faces {
        for (side, c) in o.patches[f.patch].boundary_curves().iter().enumerate() {
            if !f.sides.contains(&side) && collapsed(c) {
                let p = euclid(c.control_point(0));
                if !index.contains_key(&p) {
                    index.insert(p.clone(), vertices.len());
                    vertices.push(p);
                }
            }
        }
    }
    let mut params = vec!["502".to_string(), vertices.len().to_string()];
    for v in &vertices {
        reals(v, &mut params)?;
    }
    entities.push(dependent(502, 1, "00010000", params));
    let vertex_list = last_de(entities);
    // edge curves and the edge list
    let mut curve_des = Vec::with_capacity(topo.edges.len());
    for e in &topo.edges {
        entities.push(dependent(
            126,
            0,
            "00010000",
            curve_params(&NurbsCurve::from_bezier(&e.curve)?)?,
        ));
        curve_des.push(last_de(entities));
    }
    let mut params = vec!["504".to_string(), topo.edges.len().to_string()];
    for (e, c) in topo.edges.iter().zip(&curve_des) {
        params.extend(
            [c, &vertex_list, &(e.start + 1), &vertex_list, &(e.end + 1)].map(|x| x.to_string()),
        );
    }
    entities.push(dependent(504, 1, "00010000", params));
    let edge_list = last_de(entities);
    // faces
    let surfaces = o.surfaces()?;
    let mut face_des = Vec::with_capacity(topo.faces.len());
    for f in &topo.faces {
        entities.push(dependent(
            128,
            0,
            "00010000",
            surface_params(&surfaces[f.patch])?,
        ));
        let surf = last_de(entities);
        let boundary = o.patches[f.patch].boundary_curves();
        // the loop in side order (counter-clockwise in (u, v)); parameter lines follow the
        // model curve's direction (the loop's orientation flag reverses both)
        let mut uses: Vec<[String; 6]> = Vec::with_capacity(4);
        for (side, c) in boundary.iter().enumerate() {
            if let Some(i) = f.sides.iter().position(|&x| x == side) {
                let (e, fwd) = f.edges[i];
                let along = if fwd { c.clone() } else { c.reverse() };
                let pc = pcurve(&topo.edges[e].curve, &along, side, fwd)?;
                entities.push(dependent(126, 0, "00010500", pcurve_params(&pc)?));
                uses.push([
                    "0".into(),
                    edge_list.to_string(),
                    (e + 1).to_string(),
                    u8::from(fwd).to_string(),
                    "1".into(),
                    last_de(entities).to_string(),
                ]);
            } else if collapsed(c) {
                let v = index
                    .get(&euclid(c.control_point(0)))
                    .copied()
                    .ok_or_else(|| IoError::Invalid("a pole without a vertex".into()))?;
                let pc = pcurve(c, c, side, true)?;
                entities.push(dependent(126, 0, "00010500", pcurve_params(&pc)?));
                uses.push([
                    "1".into(),
                    vertex_list.to_string(),
                    (v + 1).to_string(),
                    "1".into(),
                    "1".into(),
                    last_de(entities).to_string(),
                ]);
            }
        }
        let mut params = vec!["508".to_string(), uses.len().to_string()];
        for [ty, list, ndx, of, k, pc] in uses {
            // TYPE, EDGE, NDX, OF, K, then ISOP and CURV for the one parameter curve
            params.extend([ty, list, ndx, of, k, "1".into(), pc]);
        }
        entities.push(dependent(508, 1, "00010000", params));
        let lp = last_de(entities);
        entities.push(dependent(
            510,
            1,
            "00010000",
            vec![
                "510".into(),
                surf.to_string(),
                "1".into(),
                "1".into(),
                lp.to_string(),
            ],
        ));
        face_des.push(last_de(entities));
    }
    let mut solids = Vec::with_capacity(topo.shells.len());
    for s in &topo.shells {
        let mut params = vec!["514".to_string(), s.faces.len().to_string()];
        for &f in &s.faces {
            params.extend([
                face_des[f].to_string(),
                u8::from(!topo.faces[f].flipped).to_string(),
            ]);
        }
        entities.push(dependent(514, 1, "00010000", params));
        let shell = last_de(entities);
        entities.push(Entity {
            kind: 186,
            form: 0,
            status: "00020000",
            label: label.to_string(),
            subscript: solids.len(),
            params: vec!["186".into(), shell.to_string(), "1".into(), "0".into()],
        });
        solids.push(last_de(entities));
    }
    Ok(solids)
}

fn label_of(name: &str) -> String {
    let l: String = ascii_name(name)
        .to_ascii_uppercase()
        .chars()
        .map(|c| if c == ' ' { '_' } else { c })
        .take(8)
        .collect();
    if l.is_empty() {
        "OBJECT".into()
    } else {
        l
    }
}

/// Packs tokens into lines of at most `width` characters, each token followed by the
/// parameter delimiter `,`, the last by the record delimiter `;`.
fn pack(tokens: &[String], width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut cur = String::new();
    for (k, t) in tokens.iter().enumerate() {
        let d = if k + 1 == tokens.len() { ';' } else { ',' };
        let piece = format!("{t}{d}");
        if !cur.is_empty() && cur.len() + piece.len() > width {
            lines.push(std::mem::take(&mut cur));
        }
        cur.push_str(&piece);
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    lines
}

/// The largest absolute coordinate of the objects (Global field 20).
fn max_coordinate(objs: &[ExchangeObject]) -> f64 {
    let mut m: f64 = 0.0;
    let mut see = |h: &[Rational]| {
        for x in euclid(h) {
            m = m.max(Scalar::to_f64(&x).abs());
        }
    };
    for o in objs {
        for c in &o.curves {
            c.control_points().for_each(&mut see);
        }
        for p in &o.patches {
            p.coords().chunks(4).for_each(&mut see);
        }
    }
    if m.is_finite() && m > 0.0 {
        m
    } else {
        1.0
    }
}

/// IGES text of the objects with default header fields.
///
/// # Errors
/// As [`write_iges_with`].
pub fn write_iges(objects: &[Object]) -> Result<String, IoError> {
    write_iges_with(objects, &IgesOptions::default())
}

/// IGES 5.3 text of the objects (module docs).
///
/// # Errors
/// [`IoError::Invalid`] for no objects, an object without geometry, geometry beyond
/// E3, degree 0, zero or mixed-sign weights, or a coordinate beyond the `f64` range.
pub fn write_iges_with(objects: &[Object], opts: &IgesOptions) -> Result<String, IoError> {
    write_iges_exchanged(&exchange_objects(objects)?, opts)
}

/// [`write_iges_with`] of objects already in their exchange form
/// ([`crate::step::exchange_object`]): a caller writing one object in several formats
/// computes that form once.
///
/// # Errors
/// As [`write_iges_with`].
pub fn write_iges_exchanged(
    exch: &[ExchangeObject],
    opts: &IgesOptions,
) -> Result<String, IoError> {
    if exch.is_empty() {
        return Err(IoError::Invalid("no objects to write to IGES".into()));
    }
    for o in exch {
        o.check_f64_range("IGES")?;
    }
    let mut entities: Vec<Entity> = Vec::new();
    for o in exch {
        if o.curves.is_empty() && o.patches.is_empty() {
            return Err(IoError::Invalid(format!(
                "object {:?} has no curves or patches to write",
                o.name
            )));
        }
        let label = label_of(&o.name);
        let mut members = Vec::new();
        for (k, c) in o.curves.iter().enumerate() {
            let pieces = c.to_bezier_pieces()?;
            if pieces.len() == 1 {
                entities.push(Entity {
                    kind: 126,
                    form: 0,
                    status: "00020000",
                    label: label.clone(),
                    subscript: k,
                    params: curve_params(c)?,
                });
            } else {
                // C0 joints: a composite curve (102) of the Bézier pieces, each on its
                // knot interval (readers split C0 B-splines into C1 pieces otherwise)
                let mut refs = Vec::with_capacity(pieces.len());
                for pc in pieces {
                    let (a, b) = pc.interval;
                    let nc = NurbsCurve::from_bezier_on(&pc.curve, a, b)?;
                    entities.push(Entity {
                        kind: 126,
                        form: 0,
                        status: "00010000",
                        label: label.clone(),
                        subscript: k,
                        params: curve_params(&nc)?,
                    });
                    refs.push(2 * entities.len() - 1);
                }
                let mut params = vec!["102".to_string(), refs.len().to_string()];
                params.extend(refs.iter().map(usize::to_string));
                entities.push(Entity {
                    kind: 102,
                    form: 0,
                    status: "00020000",
                    label: label.clone(),
                    subscript: k,
                    params,
                });
            }
            members.push(2 * entities.len() - 1);
        }
        let topo = o
            .topology
            .as_ref()
            .filter(|t| !t.shells.is_empty() && t.shells.iter().all(|s| s.closed));
        if let Some(topo) = topo {
            members.extend(brep_entities(o, topo, &label, &mut entities)?);
        } else {
            for (k, s) in o.surfaces()?.iter().enumerate() {
                entities.push(Entity {
                    kind: 128,
                    form: 0,
                    status: "00020000",
                    label: label.clone(),
                    subscript: k,
                    params: surface_params(s)?,
                });
                members.push(2 * entities.len() - 1);
            }
        }
        entities.push(Entity {
            kind: 406,
            form: 15,
            status: "00010300",
            label: "NAME".into(),
            subscript: 0,
            params: vec!["406".into(), "1".into(), hollerith(&ascii_name(&o.name))],
        });
        let name_de = 2 * entities.len() - 1;
        let mut params = vec!["402".to_string(), members.len().to_string()];
        params.extend(members.iter().map(usize::to_string));
        params.extend(["0".to_string(), "1".to_string(), name_de.to_string()]);
        entities.push(Entity {
            kind: 402,
            form: 7,
            status: "00000000",
            label,
            subscript: 0,
            params,
        });
    }

    // Start and Global sections
    let secs = opts.time.unwrap_or_else(export_time);
    let (y, mo, d, h, mi, s) = civil_time(secs);
    let date = format!("{y:04}{mo:02}{d:02}.{h:02}{mi:02}{s:02}");
    let version = env!("CARGO_PKG_VERSION");
    // one Start line each, so that no count overflows the 72 columns of a card
    let start = [
        "rcagd exact rational geometry (IGES 5.3)".to_string(),
        format!("{} object(s), entities 126/128", exch.len()),
    ];
    let global = vec![
        hollerith(","),
        hollerith(";"),
        hollerith(&ascii_name(&opts.file_name)),
        hollerith(&ascii_name(&opts.file_name)),
        hollerith(&format!("rcagd {version}")),
        hollerith(&format!("rcagd-io {version}")),
        "32".into(),
        "38".into(),
        "6".into(),
        "308".into(),
        "15".into(),
        hollerith(&ascii_name(&opts.file_name)),
        "1.".into(),
        "2".into(),
        hollerith("MM"),
        "1".into(),
        "0.01".into(),
        hollerith(&date),
        "1.E-07".into(),
        format_real(max_coordinate(exch))?,
        hollerith(&ascii_name(&opts.author)),
        hollerith(&ascii_name(&opts.organization)),
        "11".into(),
        "0".into(),
        hollerith(&date),
        String::new(),
    ];

    let mut out = String::new();
    for (k, l) in start.iter().enumerate() {
        let _ = writeln!(out, "{:<72}S{:>7}", l, k + 1);
    }
    let glines = pack(&global, 72);
    for (k, l) in glines.iter().enumerate() {
        let _ = writeln!(out, "{:<72}G{:>7}", l, k + 1);
    }
    // parameter data first (to know pointers and line counts)
    let mut plines: Vec<(String, usize)> = Vec::new();
    let mut dir = Vec::with_capacity(entities.len());
    for (k, e) in entities.iter().enumerate() {
        let de = 2 * k + 1;
        let lines = pack(&e.params, 64);
        dir.push((plines.len() + 1, lines.len()));
        plines.extend(lines.into_iter().map(|l| (l, de)));
    }
    for (k, (e, (pd, count))) in entities.iter().zip(&dir).enumerate() {
        let de = 2 * k + 1;
        let _ = writeln!(
            out,
            "{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}D{:>7}",
            e.kind, pd, 0, 0, 0, 0, 0, 0, e.status, de
        );
        let _ = writeln!(
            out,
            "{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}D{:>7}",
            e.kind,
            0,
            0,
            count,
            e.form,
            "",
            "",
            e.label,
            e.subscript,
            de + 1
        );
    }
    for (k, (l, de)) in plines.iter().enumerate() {
        let _ = writeln!(out, "{l:<64} {de:>7}P{:>7}", k + 1);
    }
    let term = format!(
        "S{:>7}G{:>7}D{:>7}P{:>7}",
        start.len(),
        glines.len(),
        2 * entities.len(),
        plines.len()
    );
    let _ = writeln!(out, "{term:<72}T{:>7}", 1);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packing_respects_the_width() {
        let toks: Vec<String> = (0..40).map(|i| format!("{}.5", i * 1000)).collect();
        let lines = pack(&toks, 64);
        assert!(lines.iter().all(|l| l.len() <= 64));
        assert!(lines.last().is_some_and(|l| l.ends_with(';')));
        assert_eq!(lines.concat().matches(',').count(), 39);
        assert_eq!(hollerith("MM"), "2HMM");
        assert_eq!(label_of("space cubic"), "SPACE_CU");
        assert_eq!(ascii_name("Möbius"), "M_bius");
    }
}
