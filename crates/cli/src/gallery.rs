//! `rcagd gallery`: builds every object of the embedded default recipes
//! (`examples/recipes/*.toml`, a fixed list compiled into the binary), writes
//! `<name>.json`, `<name>.step`, `<name>.igs`, `<name>.obj`, `<name>.svg` and
//! `<name>.png` per object, the exact sidecar `<name>.exact.json`
//! (`rcagd_io::step::exact_sidecar`), all objects in `gallery-all.step` / `.igs` /
//! `.exact.json`, plus `report.json` and `index.html` (each card shows the PNG render
//! for surfaces, the inline SVG plot for curves), and prints a summary table.
//!
//! Exit code 0 if every certificate holds, 1 if one fails or an object cannot be
//! built or exported, 2 if the output directory cannot be written.

use crate::build::build_object;
use crate::model::Object;
use crate::output::{self, OutFormat};
use crate::recipe::{Format, Recipe};
use crate::{EXIT_FAIL, EXIT_INPUT, EXIT_OK};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use rcagd_io::report::{FileLink, ReportEntry};
use std::io::IsTerminal;
use std::path::Path;

/// The embedded default recipes: (file name, text). Adding a recipe file to the
/// gallery is one line here.
pub const RECIPES: &[(&str, &str)] = &[
    (
        "examples/recipes/kernel.toml",
        include_str!("../../../examples/recipes/kernel.toml"),
    ),
    (
        "examples/recipes/quadric.toml",
        include_str!("../../../examples/recipes/quadric.toml"),
    ),
    (
        "examples/recipes/ph.toml",
        include_str!("../../../examples/recipes/ph.toml"),
    ),
    (
        "examples/recipes/ph_planar.toml",
        include_str!("../../../examples/recipes/ph_planar.toml"),
    ),
    (
        "examples/recipes/canal.toml",
        include_str!("../../../examples/recipes/canal.toml"),
    ),
    (
        "examples/recipes/cyclide.toml",
        include_str!("../../../examples/recipes/cyclide.toml"),
    ),
    (
        "examples/recipes/pn.toml",
        include_str!("../../../examples/recipes/pn.toml"),
    ),
    (
        "examples/recipes/pn_laguerre.toml",
        include_str!("../../../examples/recipes/pn_laguerre.toml"),
    ),
    (
        "examples/recipes/hypercyclide.toml",
        include_str!("../../../examples/recipes/hypercyclide.toml"),
    ),
    (
        "examples/recipes/sphere_family.toml",
        include_str!("../../../examples/recipes/sphere_family.toml"),
    ),
    (
        "examples/recipes/line_congruence.toml",
        include_str!("../../../examples/recipes/line_congruence.toml"),
    ),
    (
        "examples/recipes/conic_surface.toml",
        include_str!("../../../examples/recipes/conic_surface.toml"),
    ),
    (
        "examples/recipes/thomsen.toml",
        include_str!("../../../examples/recipes/thomsen.toml"),
    ),
    (
        "examples/recipes/analysis.toml",
        include_str!("../../../examples/recipes/analysis.toml"),
    ),
    (
        "examples/recipes/queries.toml",
        include_str!("../../../examples/recipes/queries.toml"),
    ),
    (
        "examples/recipes/n_dimensional.toml",
        include_str!("../../../examples/recipes/n_dimensional.toml"),
    ),
    (
        "examples/recipes/sweep.toml",
        include_str!("../../../examples/recipes/sweep.toml"),
    ),
];

/// The formats written per gallery object.
pub const FORMATS: &[OutFormat] = &[
    OutFormat::Json,
    OutFormat::Step,
    OutFormat::Iges,
    OutFormat::Obj,
    OutFormat::Svg,
    OutFormat::Png,
    OutFormat::Exact,
];

/// The outcome of building the gallery (before writing anything).
#[derive(Debug)]
pub struct GalleryBuild {
    /// Every object built, in recipe order.
    pub objects: Vec<Object>,
    /// Rendered diagnostics of objects that could not be built.
    pub errors: Vec<String>,
}

/// Input files the embedded recipes read (a spine read from a STEP file), compiled in as
/// well, so that the gallery builds anywhere: a file parameter whose file does not exist is
/// looked up here by its path relative to the repository root
/// ([`embedded_input`]).
pub const INPUTS: &[(&str, &str)] = &[(
    "examples/spines/bspline_spine.step",
    include_str!("../../../examples/spines/bspline_spine.step"),
)];

/// The embedded input file at `path` (`examples/recipes/../spines/x.step` and
/// `examples/spines/x.step` are the same file), if the gallery has one.
pub fn embedded_input(path: &Path) -> Option<&'static str> {
    let mut parts: Vec<&str> = Vec::new();
    for c in path.components() {
        match c {
            std::path::Component::Normal(s) => parts.push(s.to_str()?),
            std::path::Component::ParentDir => {
                parts.pop()?;
            }
            _ => {}
        }
    }
    let norm = parts.join("/");
    INPUTS
        .iter()
        .find(|(name, _)| norm == *name || norm.ends_with(&format!("/{name}")))
        .map(|(_, text)| *text)
}

/// The short name of a gallery recipe: the file stem (`examples/recipes/pn.toml` → `pn`),
/// as `rcagd gallery --only` takes it.
pub fn recipe_name(file: &str) -> &str {
    let base = file.rsplit('/').next().unwrap_or(file);
    base.split_once('.').map_or(base, |(stem, _)| stem)
}

/// The embedded recipes selected by `only` (short names, see [`recipe_name`]; all of
/// them when `only` is empty).
///
/// # Errors
/// The message names an unknown recipe and lists the known ones.
pub fn select(only: &[String]) -> Result<Vec<(&'static str, &'static str)>, String> {
    if let Some(bad) = only
        .iter()
        .find(|n| !RECIPES.iter().any(|(f, _)| recipe_name(f) == n.as_str()))
    {
        let known: Vec<&str> = RECIPES.iter().map(|(f, _)| recipe_name(f)).collect();
        return Err(format!(
            "--only: the gallery has no recipe called {bad:?}; it has {}",
            known.join(", ")
        ));
    }
    Ok(RECIPES
        .iter()
        .filter(|(f, _)| only.is_empty() || only.iter().any(|n| n == recipe_name(f)))
        .copied()
        .collect())
}

/// Parses and builds the given embedded recipes (see [`select`]), calling `tick(name)`
/// after each object. Objects are built in parallel (rayon) and kept in recipe order.
pub fn build_all(
    recipes_in: &[(&str, &str)],
    total_hint: impl FnOnce(usize),
    tick: impl Fn(&str) + Sync,
) -> GalleryBuild {
    let mut errors = Vec::new();
    let mut recipes = Vec::new();
    for (file, text) in recipes_in {
        match Recipe::parse(file, text, Some(Format::Toml)) {
            Ok(r) => recipes.push(r),
            Err(ds) => errors.extend(ds.iter().map(ToString::to_string)),
        }
    }
    total_hint(recipes.iter().map(|r| r.objects.len()).sum());
    let jobs: Vec<_> = recipes
        .iter()
        .flat_map(|r| r.objects.iter().map(move |obj| (r, obj)))
        .collect();
    let built: Vec<_> = jobs
        .par_iter()
        .map(|(r, obj)| {
            let b = build_object(&r.file, obj);
            tick(&obj.name);
            b
        })
        .collect();
    let mut objects: Vec<Object> = Vec::new();
    for ((r, _), result) in jobs.iter().zip(built) {
        match result {
            Ok(objs) => {
                for o in objs {
                    if objects.iter().any(|x| x.name == o.name) {
                        errors.push(format!(
                            "{}: error: the gallery has two objects called {:?} (names must be unique across recipes)",
                            r.file.name(),
                            o.name
                        ));
                    } else {
                        objects.push(o);
                    }
                }
            }
            Err(ds) => errors.extend(ds.iter().map(ToString::to_string)),
        }
    }
    GalleryBuild { objects, errors }
}

fn progress_bar(quiet: bool) -> ProgressBar {
    let pb = ProgressBar::with_draw_target(Some(0), ProgressDrawTarget::stderr());
    if quiet || !std::io::stderr().is_terminal() {
        pb.set_draw_target(ProgressDrawTarget::hidden());
    }
    if let Ok(style) = ProgressStyle::with_template("{spinner} [{bar:30}] {pos}/{len} {wide_msg}") {
        pb.set_style(style.progress_chars("=> "));
    }
    pb
}

/// Writes one file per object and format of [`FORMATS`], `report.json` and
/// `index.html` into `out` (created if missing), calling `tick(name)` after each
/// object. An object that an exporter cannot write is reported in the returned list
/// and left out of that format.
///
/// All or nothing, like `rcagd build --out` ([`output::write_objects`]): every file is
/// rendered in memory first, then written under a temporary name beside its target
/// and renamed into place only when all were written; if a write fails, the
/// temporaries are removed and `out` is as it was (old files of the same names intact).
///
/// The rendering runs under the work budget of `--max-seconds`
/// ([`crate::limits::Limits::work_limit`], the export phase's own budget, after the
/// constructions'), as `rcagd build --out` ([`crate::build::export_within_budget`]).
///
/// # Errors
/// A file-system error (the directory or a file cannot be written), naming the path;
/// "work limit exceeded: exporting … nothing was written" when the rendering outlasts
/// the budget.
pub fn write_all(
    out: &Path,
    objects: &[Object],
    tick: impl Fn(&str) + Sync,
) -> Result<Vec<String>, String> {
    let limit = crate::limits::Limits::current().work_limit();
    write_all_within(out, objects, limit, tick)
}

/// [`write_all`] with the work budget `limit` (`None`: unbounded) for rendering every
/// file; over the budget nothing is written.
///
/// # Errors
/// As [`write_all`].
pub fn write_all_within(
    out: &Path,
    objects: &[Object],
    limit: Option<std::time::Duration>,
    tick: impl Fn(&str) + Sync,
) -> Result<Vec<String>, String> {
    let _budget = limit.map(rcagd_algebra::budget::install);
    let (files, export_errors) = rcagd_algebra::budget::catch(|| render_all(objects, &tick))
        .map_err(|e| crate::limits::export_work_limit_message(objects, FORMATS, e))??;
    output::write_files_atomically(out, &files)?;
    Ok(export_errors)
}

/// Files in memory: (name, contents).
type Files = Vec<(String, Vec<u8>)>;

/// Every file of the gallery rendered in memory (per object and format, the combined
/// files, `report.json`, `index.html`), and the export errors.
fn render_all(
    objects: &[Object],
    tick: &(impl Fn(&str) + Sync),
) -> Result<(Files, Vec<String>), String> {
    // Rendering (tessellation, rasterisation, exact export) is the expensive part: one
    // object per task, in parallel, under the caller's budget; the files are collected in
    // order; each object's exact exchange form is computed once, for its STEP, IGES and
    // sidecar files and for the combined files.
    let rendered: Vec<(Vec<_>, _)> = objects
        .par_iter()
        .map(rcagd_algebra::budget::inherit(|o: &Object| {
            let mut ex = output::Exchange::new(o);
            let r: Vec<_> = FORMATS
                .iter()
                .map(|&f| (f, output::render_with(&mut ex, f)))
                .collect();
            tick(&o.name);
            (r, ex.into_form())
        }))
        .collect();
    let mut export_errors = Vec::new();
    let mut entries = Vec::with_capacity(objects.len());
    let mut files: Vec<(String, Vec<u8>)> = Vec::new();
    let mut exchanged = Vec::new();
    for (o, (renders, form)) in objects.iter().zip(rendered) {
        let mut entry = ReportEntry::new(o.clone());
        // the combined files hold the objects whose exact sidecar could be written
        let sidecar_ok = renders
            .iter()
            .any(|(f, r)| *f == OutFormat::Exact && r.is_ok());
        if let (true, Some(x)) = (sidecar_ok, form) {
            exchanged.push(x);
        }
        for (f, text) in renders {
            let file = format!("{}.{}", o.name, f.extension());
            let text = match text {
                Ok(t) => t,
                Err(e) => {
                    export_errors.push(format!(
                        "cannot export {:?} as {}: {e}",
                        o.name,
                        f.extension()
                    ));
                    continue;
                }
            };
            match f {
                OutFormat::Svg => {
                    entry = entry.with_svg(String::from_utf8_lossy(&text).into_owned());
                }
                // surfaces read best shaded; curves keep their (sharper) SVG plot
                OutFormat::Png if !o.geometry.patches().is_empty() => {
                    entry = entry.with_picture(file.clone());
                }
                _ => {}
            }
            entry = entry.with_file(f.label(), file.clone());
            files.push((file, text));
        }
        entries.push(entry);
    }
    let links = combined_files(&exchanged, &mut export_errors, &mut files)?;
    let mut json = rcagd_io::report::report_json(&entries);
    if let serde_json::Value::Object(map) = &mut json {
        if !links.is_empty() {
            let list = links
                .iter()
                .map(|f| serde_json::json!({"label": f.label, "path": f.path}))
                .collect();
            map.insert("files".into(), serde_json::Value::Array(list));
        }
    }
    files.push(("report.json".into(), json_bytes(&json)?));
    files.push((
        "index.html".into(),
        rcagd_io::report::report_html_with(&entries, &links).into_bytes(),
    ));
    Ok((files, export_errors))
}

/// The stem of the files holding every object: [`ALL_STEM`]`.step`, `.igs` and
/// `.exact.json`.
pub const ALL_STEM: &str = "gallery-all";

fn json_bytes(v: &serde_json::Value) -> Result<Vec<u8>, String> {
    Ok((serde_json::to_string_pretty(v).map_err(|e| e.to_string())? + "\n").into_bytes())
}

/// Renders the exchange forms of the objects whose exact sidecar could be written (every
/// object STEP can hold) into one STEP and one IGES file (one product / group per object,
/// named after it) with their exact sidecar, appending them to `files`; returns the links
/// for the report's header.
fn combined_files(
    ok: &[rcagd_io::step::ExchangeObject],
    export_errors: &mut Vec<String>,
    files: &mut Vec<(String, Vec<u8>)>,
) -> Result<Vec<FileLink>, String> {
    let mut links = Vec::new();
    if ok.is_empty() {
        return Ok(links);
    }
    let rendered = [
        (
            OutFormat::Step,
            rcagd_io::step::write_step_exchanged(ok, &rcagd_io::step::StepOptions::default()),
        ),
        (
            OutFormat::Iges,
            rcagd_io::iges::write_iges_exchanged(ok, &rcagd_io::iges::IgesOptions::default()),
        ),
    ];
    for (f, r) in rendered {
        let ext = f.extension();
        match r {
            Ok(text) => {
                let file = format!("{ALL_STEM}.{ext}");
                files.push((file.clone(), text.into_bytes()));
                links.push(FileLink {
                    label: format!("all objects as {}", f.label()),
                    path: file,
                });
            }
            Err(e) => export_errors.push(format!("cannot export the whole gallery as {ext}: {e}")),
        }
    }
    match rcagd_io::step::exact_sidecar_exchanged(ok) {
        Ok(side) => {
            let file = format!("{ALL_STEM}.exact.json");
            files.push((file.clone(), json_bytes(&side)?));
            links.push(FileLink {
                label: "their exact NURBS".into(),
                path: file,
            });
        }
        Err(e) => export_errors.push(format!("cannot write the exact sidecar: {e}")),
    }
    Ok(links)
}

/// Checks before the (long) build that `dir` can be created and written: creates it
/// (reporting whether this call did) and writes and removes a probe file in it.
///
/// # Errors
/// A message naming the directory.
fn check_writable(dir: &Path) -> Result<bool, String> {
    let created = !dir.exists();
    output::create_dir(dir)?;
    let probe = dir.join(output::partial_name("write-test"));
    match std::fs::File::create(&probe) {
        Ok(_) => {
            let _ = std::fs::remove_file(&probe);
            Ok(created)
        }
        Err(e) => {
            if created {
                let _ = std::fs::remove_dir(dir);
            }
            Err(format!(
                "cannot write into the output directory {}: {e} (nothing was built)",
                dir.display()
            ))
        }
    }
}

/// Runs `rcagd gallery` on the recipes named in `only` (all when empty); returns the
/// exit code.
pub fn run(out: &Path, quiet: bool, only: &[String]) -> u8 {
    let recipes = match select(only) {
        Ok(r) => r,
        Err(e) => {
            errln!("error: {e}");
            return EXIT_INPUT;
        }
    };
    // An output directory that cannot be created or written fails before the (long)
    // build; one this run created is removed again if the gallery is not written.
    let created = match check_writable(out) {
        Ok(c) => c,
        Err(e) => {
            errln!("error: {e}");
            return EXIT_INPUT;
        }
    };
    let pb = progress_bar(quiet);
    let built = build_all(
        &recipes,
        // Building and writing: two steps per object.
        |n| pb.set_length(2 * n as u64),
        |name| {
            pb.set_message(format!("building {name}"));
            pb.inc(1);
        },
    );
    let written = write_all(out, &built.objects, |name| {
        pb.set_message(format!("writing {name}"));
        pb.inc(1);
    });
    pb.finish_and_clear();
    for e in &built.errors {
        if e.ends_with('\n') {
            err!("{e}");
        } else {
            errln!("{e}");
        }
    }
    let export_errors = match written {
        Ok(e) => e,
        Err(e) => {
            if created {
                let _ = std::fs::remove_dir(out);
            }
            errln!("error: {e}");
            return EXIT_INPUT;
        }
    };
    for e in &export_errors {
        errln!("error: {e}");
    }
    let failures = output::failures(&built.objects);
    if !quiet {
        out!("{}", output::summary_table(&built.objects));
        outln!("wrote {}", out.display());
    }
    for f in &failures {
        errln!("certificate fails: {f}");
    }
    if failures.is_empty() && built.errors.is_empty() && export_errors.is_empty() {
        EXIT_OK
    } else {
        EXIT_FAIL
    }
}
