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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recipe::Recipe;

    fn build(src: &str) -> Vec<Object> {
        let r = Recipe::parse("r.toml", src, None).unwrap();
        crate::build::build_recipe(&r, |_| {}).unwrap()
    }

    #[test]
    fn a_closed_cover_closes_and_one_with_a_piece_missing_is_reported() {
        let torus =
            build("[[object]]\nname = \"t\"\nop = \"torus\"\nmajor_radius = 3\nminor_radius = 1\n");
        assert_eq!(should_close(&torus[0]), Some("a whole torus"));
        assert_eq!(closure_warning(&torus[0]), None);
        let mut sphere = build("[[object]]\nname = \"s\"\nop = \"sphere_cover\"\n");
        assert_eq!(closure_warning(&sphere[0]), None);
        // a piece missing: the shell is open and the object is annotated
        let Geometry::Patches(p) = &mut sphere[0].geometry else {
            panic!("patches expected");
        };
        p.pop();
        let w = annotate(&mut sphere[0]).expect("a warning");
        assert!(w.contains("does not close") && w.contains("open"), "{w}");
        assert!(sphere[0].values.iter().any(|v| v.name == "closure_warning"));
        // a pipe around a spine closed with G¹ should close, and does (its seam is
        // closed exactly, rcagd::canal::seam); an open spine need not close
        let open = build(
            "[[object]]\nname = \"q\"\nop = \"pipe\"\npoints = [[0, 0, 0], [4, 0, 0], [4, 4, 0]]\nradius = \"1/20\"\n",
        );
        assert_eq!(should_close(&open[0]), None);
        let closed = build(
            "[[object]]\nname = \"c\"\nop = \"pipe\"\npoints = [[0, 0, 0], [3, 0, 0], [1, 4, 0], [-1, 0, 0], [0, 0, 0]]\nradius = \"1/8\"\n",
        );
        assert_eq!(
            should_close(&closed[0]),
            Some("a pipe around a closed spine")
        );
        assert_eq!(closure_warning(&closed[0]), None);
        // with one patch of the seam removed it is reported again
        let mut cut = closed[0].clone();
        let Geometry::Patches(p) = &mut cut.geometry else {
            panic!("patches expected");
        };
        p.pop();
        assert!(closure_warning(&cut).is_some_and(|w| w.contains("does not close")));
    }

    #[test]
    fn a_pipe_around_a_closed_spine_file_should_close() {
        // the same G¹-closed quartic loop as a spine file (rcagd JSON, homogeneous
        // [w, wx, wy, wz]): the rule no longer depends on how the spine was given
        let dir = std::env::temp_dir().join(format!("rcagd-closure-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let spine = dir.join("loop.json");
        std::fs::write(
            &spine,
            r#"{"kind": "curve", "control_points": [[1, 0, 0, 0], [1, 3, 0, 0], [1, 1, 4, 0], [1, -1, 0, 0], [1, 0, 0, 0]]}"#,
        )
        .unwrap();
        let recipe = format!(
            "[[object]]\nname = \"f\"\nop = \"pipe\"\nspine_file = {:?}\nradius = \"1/8\"\n",
            spine.display().to_string()
        );
        let from_file = build(&recipe);
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(
            should_close(&from_file[0]),
            Some("a pipe around a closed spine")
        );
        assert_eq!(closure_warning(&from_file[0]), None);
        // a loop closed with G⁰ only (end tangent (2, 1, 0) against start tangent
        // (3, 0, 0)) is not a closed tube: its end discs meet, and the op refuses it
        let r = Recipe::parse(
            "r.toml",
            "[[object]]\nname = \"k\"\nop = \"pipe\"\npoints = [[0, 0, 0], [3, 0, 0], [1, 4, 0], [-2, -1, 0], [0, 0, 0]]\nradius = \"1/100\"\n",
            None,
        )
        .unwrap();
        let err = crate::build::build_recipe(&r, |_| {}).unwrap_err();
        assert!(format!("{err:?}").contains("intersects itself"), "{err:?}");
        // an open spine says so
        let open = build(
            "[[object]]\nname = \"q\"\nop = \"pipe\"\npoints = [[0, 0, 0], [4, 0, 0], [4, 4, 0]]\nradius = \"1/20\"\n",
        );
        assert!(
            open[0]
                .values
                .iter()
                .any(|v| v.name == crate::ops::canal::SPINE_CLOSED
                    && v.value == Quantity::Bool(false))
        );
    }
}
