//! Closed objects that do not close (issue 19, item 3): an object whose op says it is a
//! closed surface — a sphere or ellipsoid cover, a torus, a pipe around a closed spine —
//! must arrive as closed shells (every boundary curve of a piece shared exactly with
//! another piece, [`rcagd_io::step::build_topology`]). When it does not, the object gets a
//! note (the value `closure_warning`) and `rcagd build` prints a warning; nothing is
//! refused (the geometry is what the op built, the exporters write open shells and
//! meshes with boundary edges).

use crate::model::{Geometry, Object};
use rcagd_io::quantity::{NamedQuantity, Quantity};

/// Why the object's op says it is closed, or `None` when it need not be.
///
/// `sphere_cover` and `torus` are closed surfaces by construction; a `pipe` whose spine
/// (given by `points` or by `spine_file`) ends where it starts with the same tangent
/// direction is a closed tube (the op's value `spine_closed`, decided exactly by
/// `rcagd::canal::chain_is_g1_closed`; a spine closed with only `G⁰` has a corner and
/// gives a tube with two ends).
pub fn should_close(o: &Object) -> Option<&'static str> {
    if !matches!(o.geometry, Geometry::Patch(_) | Geometry::Patches(_)) {
        return None;
    }
    match o.op.as_str() {
        "sphere_cover" => Some("a cover of a whole sphere or ellipsoid"),
        "torus" => Some("a whole torus"),
        "pipe" => o
            .values
            .iter()
            .any(|v| v.name == crate::ops::canal::SPINE_CLOSED && v.value == Quantity::Bool(true))
            .then_some("a pipe around a closed spine"),
        _ => None,
    }
}

/// The warning for an object that should be closed and is not: its open shells (or why
/// it has no boundary representation). `None` when it closes or need not.
pub fn closure_warning(o: &Object) -> Option<String> {
    let why = should_close(o)?;
    let exch = match rcagd_io::step::exchange_object(o) {
        Ok(x) => x,
        Err(e) => {
            return Some(format!(
                "should be closed ({why}) but has no exchange form: {e}"
            ))
        }
    };
    let topo = match exch.brep() {
        Ok(t) => t,
        Err(e) => {
            return Some(format!(
                "should be closed ({why}) but its pieces form no boundary representation: {e}"
            ))
        }
    };
    let open = topo.shells.iter().filter(|s| !s.closed).count();
    (open > 0 || topo.shells.is_empty()).then(|| {
        format!(
            "should be closed ({why}) but does not close: {open} of {} shells are open (the \
             pieces do not share their boundary curves exactly, or are not oriented \
             consistently); STEP and IGES get open shells, meshes have boundary edges",
            topo.shells.len()
        )
    })
}

/// Adds the note `closure_warning` to an object that should be closed and is not;
/// returns the warning.
pub fn annotate(o: &mut Object) -> Option<String> {
    let w = closure_warning(o)?;
    o.values.push(NamedQuantity::new(
        "closure_warning",
        "the op says this object is closed, but its pieces do not close exactly",
        Quantity::Text(w.clone()),
    ));
    Some(w)
}
