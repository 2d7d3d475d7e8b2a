//! Writing built objects: JSON (per DESIGN.md, via `rcagd_io::json`), STEP, IGES, OBJ,
//! STL, PLY, glTF, SVG and PNG (all via `rcagd_io`), one file per object and format, and
//! the summary table.

use crate::model::Object;
use rayon::prelude::*;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// An output format of `rcagd build --format`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum OutFormat {
    /// Exact JSON: homogeneous control points as "p/q" strings and floats, certificates.
    Json,
    /// STEP AP214 (ISO 10303-21): exact rational B-splines rounded once to f64.
    Step,
    /// IGES 5.3: rational B-spline entities 126/128.
    Iges,
    /// Wavefront OBJ: adaptive polylines (curves) or triangle meshes with normals (patches).
    Obj,
    /// Binary STL triangle mesh (patches only).
    Stl,
    /// Binary PLY triangle mesh with normals (patches only).
    Ply,
    /// glTF 2.0 binary (.glb): meshes and line strips.
    Gltf,
    /// SVG picture: plane curves from the top, spatial geometry obliquely.
    Svg,
    /// The exact NURBS behind the STEP and IGES numbers (`NAME.exact.json`,
    /// `rcagd_io::step::exact_sidecar`): for exact round trips and `scripts/occ_check.sh`.
    Exact,
    /// PNG picture rendered in software: shaded patches with iso-parameter lines,
    /// curves as lines (`rcagd_io::raster`).
    Png,
}

impl OutFormat {
    /// The file extension.
    pub fn extension(self) -> &'static str {
        match self {
            OutFormat::Json => "json",
            OutFormat::Step => "step",
            OutFormat::Iges => "igs",
            OutFormat::Obj => "obj",
            OutFormat::Stl => "stl",
            OutFormat::Ply => "ply",
            OutFormat::Gltf => "glb",
            OutFormat::Svg => "svg",
            OutFormat::Png => "png",
            OutFormat::Exact => "exact.json",
        }
    }

    /// The name shown in the report's file links.
    pub fn label(self) -> &'static str {
        match self {
            OutFormat::Json => "JSON",
            OutFormat::Step => "STEP",
            OutFormat::Iges => "IGES",
            OutFormat::Obj => "OBJ",
            OutFormat::Stl => "STL",
            OutFormat::Ply => "PLY",
            OutFormat::Gltf => "glTF",
            OutFormat::Svg => "SVG",
            OutFormat::Png => "PNG",
            OutFormat::Exact => "exact NURBS",
        }
    }
}

/// The JSON of one object (DESIGN.md: name, op, kind, degree, exact and float
/// homogeneous control points, certificates).
pub fn object_json(o: &Object) -> serde_json::Value {
    rcagd_io::json::object_to_json(o)
}

/// The JSON document of several objects: `{"objects": […], "all_certificates_hold": …}`.
///
/// # Errors
/// The serializer's message.
pub fn objects_json_text(objects: &[Object]) -> Result<String, String> {
    rcagd_io::json::objects_to_json_string(objects).map_err(|e| e.to_string())
}

/// The file contents of one object in one format.
///
/// # Errors
/// The exporter's message (e.g. STEP needs positive weights, STL needs patches).
pub fn render(o: &Object, format: OutFormat) -> Result<Vec<u8>, String> {
    render_with(&mut Exchange::new(o), format)
}

/// An object and its exact exchange form ([`rcagd_io::step::exchange_object`]: the
/// positive-weight pieces, their orientation and topology), computed on first use: STEP,
/// IGES and the exact sidecar of one object share it.
pub struct Exchange<'a> {
    object: &'a Object,
    form: Option<Result<rcagd_io::step::ExchangeObject, String>>,
}

impl<'a> Exchange<'a> {
    /// The object, its exchange form not computed yet.
    pub fn new(object: &'a Object) -> Self {
        Exchange { object, form: None }
    }

    /// The exchange form, computed once.
    ///
    /// # Errors
    /// The exporter's message (zero weights, geometry beyond E3, …).
    pub fn form(&mut self) -> Result<&rcagd_io::step::ExchangeObject, String> {
        let object = self.object;
        self.form
            .get_or_insert_with(|| {
                rcagd_io::step::exchange_object(object).map_err(|e| e.to_string())
            })
            .as_ref()
            .map_err(Clone::clone)
    }

    /// The exchange form if it was computed and exists.
    pub fn into_form(self) -> Option<rcagd_io::step::ExchangeObject> {
        self.form.and_then(Result::ok)
    }
}

/// [`render`] of the object of `ex`, its exchange form computed at most once over calls.
///
/// # Errors
/// As [`render`].
pub fn render_with(ex: &mut Exchange<'_>, format: OutFormat) -> Result<Vec<u8>, String> {
    use rcagd_io::stl::{object_mesh, MeshOptions};
    let o = ex.object;
    let one = std::slice::from_ref(o);
    let text =
        |r: Result<String, rcagd_io::IoError>| r.map(String::into_bytes).map_err(|e| e.to_string());
    match format {
        OutFormat::Json => serde_json::to_string_pretty(&object_json(o))
            .map(|s| (s + "\n").into_bytes())
            .map_err(|e| e.to_string()),
        OutFormat::Step => {
            let x = ex.form()?;
            text(rcagd_io::step::write_step_exchanged(
                std::slice::from_ref(x),
                &rcagd_io::step::StepOptions::default(),
            ))
        }
        OutFormat::Iges => {
            let x = ex.form()?;
            text(rcagd_io::iges::write_iges_exchanged(
                std::slice::from_ref(x),
                &rcagd_io::iges::IgesOptions::default(),
            ))
        }
        OutFormat::Obj => text(rcagd_io::obj::object_to_obj(o)),
        OutFormat::Stl => object_mesh(o, &MeshOptions::default())
            .and_then(|m| rcagd_io::stl::write_stl_binary(&o.name, &m))
            .map_err(|e| e.to_string()),
        OutFormat::Ply => object_mesh(o, &MeshOptions::default())
            .and_then(|m| rcagd_io::ply::write_ply(&o.name, &m))
            .map_err(|e| e.to_string()),
        OutFormat::Gltf => {
            rcagd_io::gltf::objects_to_glb(one, &MeshOptions::default()).map_err(|e| e.to_string())
        }
        OutFormat::Svg => object_svg(o).map(String::into_bytes),
        OutFormat::Exact => {
            let x = ex.form()?;
            rcagd_io::step::exact_sidecar_exchanged(std::slice::from_ref(x))
                .and_then(|v| Ok(serde_json::to_string_pretty(&v)? + "\n"))
                .map(String::into_bytes)
                .map_err(|e| e.to_string())
        }
        OutFormat::Png => {
            rcagd_io::raster::render_png(o, &rcagd_io::raster::RenderOptions::default())
                .map_err(|e| e.to_string())
        }
    }
}

/// The SVG picture of an object (`rcagd_io::svg::object_svg`, default options).
///
/// # Errors
/// The exporter's message.
pub fn object_svg(o: &Object) -> Result<String, String> {
    rcagd_io::svg::object_svg(o, &rcagd_io::svg::SvgOptions::default()).map_err(|e| e.to_string())
}

/// Creates `dir` (and parents).
///
/// # Errors
/// A message naming the directory.
pub fn create_dir(dir: &Path) -> Result<(), String> {
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("cannot create directory {}: {e}", dir.display()))
}

/// Writes `<dir>/<name>.<ext>` for every object and format, all or nothing: every file
/// is rendered first, so an exporter that refuses an object (STEP with a zero weight,
/// STL of a curve) writes nothing; then `dir` is created and the files are written, and
/// if a write fails the files written so far (and `dir`, when this call created it) are
/// removed again. Returns the paths written.
///
/// # Errors
/// The first exporter error (naming the object and format) or file-system error (naming
/// the file).
pub fn write_objects(
    dir: &Path,
    objects: &[Object],
    formats: &[OutFormat],
) -> Result<Vec<PathBuf>, String> {
    // rendered in parallel, one (object, format) per task; the first error in order wins
    let jobs: Vec<(&Object, OutFormat)> = objects
        .iter()
        .flat_map(|o| formats.iter().map(move |&f| (o, f)))
        .collect();
    // two outputs with one path (object `a` with --format exact and `a.exact` with
    // --format json) would overwrite each other silently
    let mut owner: std::collections::HashMap<PathBuf, (&str, &str)> =
        std::collections::HashMap::new();
    for &(o, f) in &jobs {
        let path = dir.join(format!("{}.{}", o.name, f.extension()));
        if let Some((other, fmt)) = owner.insert(path.clone(), (o.name.as_str(), f.label())) {
            return Err(format!(
                "objects {other:?} (format {fmt}) and {:?} (format {}) would both be written to {}: \
                 rename one of them (nothing was written)",
                o.name,
                f.label(),
                path.display()
            ));
        }
    }
    let files: Vec<(String, Vec<u8>)> = jobs
        .par_iter()
        .map(rcagd_algebra::budget::inherit(
            |&(o, f): &(&Object, OutFormat)| {
                let file = format!("{}.{}", o.name, f.extension());
                render(o, f)
                    .map(|bytes| (file.clone(), bytes))
                    .map_err(|e| {
                        format!("{}: {e} (nothing was written)", dir.join(&file).display())
                    })
            },
        ))
        .collect::<Vec<_>>()
        .into_iter()
        .collect::<Result<_, _>>()?;
    write_files_atomically(dir, &files)?;
    Ok(files.iter().map(|(name, _)| dir.join(name)).collect())
}

/// The temporary name of `file` while it is written: `.FILE.rcagd-partial` beside it.
pub fn partial_name(file: &str) -> String {
    format!(".{file}.rcagd-partial")
}

/// Writes `files` (name in `dir`, contents) all or nothing: `dir` is created if
/// missing; a target that exists as a directory is refused before anything is
/// written; every file goes to [`partial_name`] first (synced), and only when all were
/// written are they renamed into place. On a failed write the temporaries (and `dir`,
/// when this call created it) are removed.
///
/// # Errors
/// A message naming the file and saying that nothing was written.
pub fn write_files_atomically(dir: &Path, files: &[(String, Vec<u8>)]) -> Result<(), String> {
    let mut seen = std::collections::HashSet::new();
    for (name, _) in files {
        if !seen.insert(name.as_str()) {
            return Err(format!(
                "two files would both be written to {} (nothing was written)",
                dir.join(name).display()
            ));
        }
        if dir.join(name).is_dir() {
            return Err(format!(
                "cannot write {}: a directory of that name is in the way (nothing was written)",
                dir.join(name).display()
            ));
        }
    }
    let created = !dir.exists();
    create_dir(dir)?;
    let mut temps: Vec<std::path::PathBuf> = Vec::with_capacity(files.len());
    let cleanup = |temps: &[std::path::PathBuf]| {
        for t in temps {
            let _ = std::fs::remove_file(t);
        }
        if created {
            let _ = std::fs::remove_dir(dir);
        }
    };
    for (name, bytes) in files {
        let tmp = dir.join(partial_name(name));
        let result = std::fs::File::create(&tmp).and_then(|mut f| {
            use std::io::Write as _;
            f.write_all(bytes)?;
            f.sync_all()
        });
        if result.is_ok() || tmp.is_file() {
            temps.push(tmp);
        }
        if let Err(e) = result {
            cleanup(&temps);
            return Err(format!(
                "cannot write {} (as its temporary {}): {e} (nothing was written; the \
                 directory is as it was)",
                dir.join(name).display(),
                partial_name(name)
            ));
        }
    }
    for ((name, _), tmp) in files.iter().zip(&temps) {
        let path = dir.join(name);
        if let Err(e) = std::fs::rename(tmp, &path) {
            cleanup(&temps);
            return Err(format!("cannot move {} into place: {e}", path.display()));
        }
    }
    Ok(())
}

/// `"3/3 hold"` or `"2/3 hold, 1 FAILS"`.
pub fn certificate_summary(o: &Object) -> String {
    let n = o.certificates.len();
    let failed = o.certificates.iter().filter(|c| !c.holds).count();
    if failed == 0 {
        format!("{n}/{n} hold")
    } else {
        format!("{}/{n} hold, {failed} FAIL", n - failed)
    }
}

/// The summary table: name, op, kind, degree, #control points, certificates.
pub fn summary_table(objects: &[Object]) -> String {
    let header = ["name", "op", "kind", "degree", "#cp", "certificates"];
    let rows: Vec<[String; 6]> = objects
        .iter()
        .map(|o| {
            [
                o.name.clone(),
                o.op.clone(),
                o.kind().to_string(),
                o.degree_summary(),
                o.control_point_count().to_string(),
                certificate_summary(o),
            ]
        })
        .collect();
    let mut widths = header.map(|h| h.chars().count());
    for r in &rows {
        for (w, c) in widths.iter_mut().zip(r) {
            *w = (*w).max(c.chars().count());
        }
    }
    let mut s = String::new();
    let line = |s: &mut String, cells: &[String]| {
        let mut l = String::new();
        for (i, (c, w)) in cells.iter().zip(widths).enumerate() {
            if i > 0 {
                l.push_str("  ");
            }
            if i == 4 {
                let _ = write!(l, "{c:>w$}");
            } else {
                let _ = write!(l, "{c:<w$}");
            }
        }
        s.push_str(l.trim_end());
        s.push('\n');
    };
    line(&mut s, &header.map(String::from));
    line(&mut s, &widths.map(|w| "-".repeat(w)));
    for r in &rows {
        line(&mut s, r);
    }
    for o in objects.iter().filter(|o| !o.values.is_empty()) {
        let _ = writeln!(s, "{}:", o.name);
        for v in &o.values {
            let _ = writeln!(s, "  {}", v.summary_line());
        }
    }
    let total: usize = objects.iter().map(|o| o.certificates.len()).sum();
    let failed: usize = objects
        .iter()
        .map(|o| o.certificates.iter().filter(|c| !c.holds).count())
        .sum();
    let _ = writeln!(
        s,
        "{} object{}, {total} certificate{}: {}",
        objects.len(),
        if objects.len() == 1 { "" } else { "s" },
        if total == 1 { "" } else { "s" },
        if failed == 0 {
            "all hold".to_string()
        } else {
            format!("{failed} FAIL")
        }
    );
    s
}

/// One line per failing certificate: `name: [FAILS, exact] property — residual …`.
pub fn failures(objects: &[Object]) -> Vec<String> {
    objects
        .iter()
        .flat_map(|o| {
            o.certificates
                .iter()
                .filter(|c| !c.holds)
                .map(move |c| format!("{}: {c}", o.name))
        })
        .collect()
}
