//! Building recipes: check each object against its op's parameter list, run the op,
//! and turn every problem into a located [`Diagnostic`].

use crate::model::Object;
use crate::ops::{self, OpArgs, OpError, OpSpec, ParamSpec};
use crate::output::{self, OutFormat};
use crate::recipe::{Recipe, RecipeObject, RecipeValue};
use crate::source::{clip, closest, Diagnostic, SourceFile, Span};
use crate::value::{convert, Value};
use crate::{EXIT_FAIL, EXIT_INPUT, EXIT_OK};
use rayon::prelude::*;
use std::io::Read as _;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

/// The notes listing an op's parameters.
fn param_notes(op: &OpSpec) -> String {
    let mut s = format!("parameters of `{}`:", op.name);
    if op.params.is_empty() {
        s.push_str(" none");
    }
    for l in op.param_lines() {
        s.push('\n');
        s.push_str("  ");
        s.push_str(&l);
    }
    s
}

/// The typed default of a parameter (its TOML text parsed and converted).
///
/// # Errors
/// A message when the op's declared default is not valid for its type (an op bug,
/// caught by the registry tests).
pub fn default_value(p: &ParamSpec) -> Result<Option<Value>, String> {
    let Some(text) = p.default else {
        return Ok(None);
    };
    let doc = crate::recipe::toml::parse(&format!("v = {text}"))
        .map_err(|e| format!("default of `{}` is not TOML: {}", p.name, e.message))?;
    let v = doc
        .get("v")
        .ok_or_else(|| format!("default of `{}` is empty", p.name))?;
    convert(p.kind, &v.value)
        .map(Some)
        .map_err(|e| format!("default of `{}`: {}", p.name, e.message))
}

/// Checks an object's parameters against its op: unknown op, unknown, missing and
/// ill-typed parameters.
///
/// # Errors
/// Every problem found, located in `file`.
pub fn check_object(
    file: &SourceFile,
    obj: &RecipeObject,
) -> Result<(&'static OpSpec, OpArgs), Vec<Diagnostic>> {
    let Some(op) = ops::find(&obj.op) else {
        let mut d = file.error(obj.op_span, format!("unknown op {:?}", clip(&obj.op)));
        if let Some(s) = closest(&obj.op, ops::all().map(|o| o.name)) {
            d = d.note(format!("did you mean {s:?}?"));
        }
        let names: Vec<&str> = ops::all().map(|o| o.name).collect();
        d = d.note(format!(
            "known ops: {} (`rcagd ops` describes them)",
            names.join(", ")
        ));
        return Err(vec![d]);
    };
    let mut diags = Vec::new();
    for e in &obj.params {
        if op.param(&e.key).is_none() {
            let mut d = file.error(
                e.key_span,
                format!("unknown parameter `{}` for op `{}`", clip(&e.key), op.name),
            );
            if let Some(s) = closest(&e.key, op.params.iter().map(|p| p.name)) {
                d = d.note(format!("did you mean `{s}`?"));
            }
            diags.push(d.note(param_notes(op)));
        }
    }
    let mut values = Vec::with_capacity(op.params.len());
    for p in op.params {
        let given: Option<&RecipeValue> = obj
            .params
            .iter()
            .find(|e| e.key == p.name)
            .map(|e| &e.value)
            .filter(|v| !matches!(v.kind, crate::recipe::ValueKind::Null) || p.required);
        match given {
            Some(v) => match convert(p.kind, v) {
                Ok(x) => values.push((p.name, x)),
                Err(e) => diags.push(
                    file.error(e.span, format!("parameter `{}`: {}", p.name, e.message))
                        .note(format!(
                            "{}: {} ({}) — {}",
                            p.name,
                            p.kind.type_name(),
                            p.requirement(),
                            p.doc
                        )),
                ),
            },
            None if p.required => diags.push(
                file.error(
                    obj.span,
                    format!(
                        "object {:?}: op `{}` needs the parameter `{}` ({})",
                        obj.name,
                        op.name,
                        p.name,
                        p.kind.type_name()
                    ),
                )
                .note(param_notes(op)),
            ),
            None => match default_value(p) {
                Ok(Some(x)) => values.push((p.name, x)),
                Ok(None) => {}
                Err(m) => diags.push(file.error(obj.op_span, format!("internal error: {m}"))),
            },
        }
    }
    if diags.is_empty() {
        // the per-op limits (list sizes, degrees, sample counts, magnitudes), before
        // anything is built
        if let Err((param, message)) =
            crate::limits::check_params(op, &values, &crate::limits::Limits::current())
        {
            let span = obj
                .params
                .iter()
                .find(|e| e.key == param)
                .map_or(obj.op_key_span, |e| e.value.span);
            return Err(vec![file.error(
                span,
                format!("object {:?} (op `{}`): {message}", obj.name, op.name),
            )]);
        }
        let mut args = OpArgs::new(obj.name.clone(), op, values);
        // file parameters are relative to the recipe's directory (stdin: the working one)
        if file.name() != "-" {
            if let Some(dir) = Path::new(file.name()).parent() {
                args = args.with_base_dir(dir);
            }
        }
        Ok((op, args))
    } else {
        diags.sort_by_key(|d| (d.line, d.column));
        Err(diags)
    }
}

/// Runs an op, turning a panic into an error (no input may crash the CLI), under the
/// work budget of [`Limits::seconds`](crate::limits::Limits) (nested in any budget the
/// caller installed): a construction still working at its deadline ends at its next
/// checkpoint with "work limit exceeded" (an input error, exit 2).
pub fn run_op(op: &OpSpec, args: &OpArgs) -> Result<Vec<Object>, OpError> {
    run_build(op.build, args)
}

/// Runs a build function (an op's, or its float path's) under the work budget, turning a
/// panic into an error.
fn run_build(build: ops::BuildFn, args: &OpArgs) -> Result<Vec<Object>, OpError> {
    let _budget = crate::limits::Limits::current()
        .work_limit()
        .map(rcagd_algebra::budget::install);
    // an object its op says is closed but whose pieces do not close gets a note
    // (`closure_warning`, printed by `rcagd build`), checked under the same budget
    let build_and_check = || {
        build(args).map(|mut objs| {
            for o in &mut objs {
                let _ = crate::closure::annotate(o);
            }
            objs
        })
    };
    match catch_unwind(AssertUnwindSafe(build_and_check)) {
        Ok(r) => r,
        Err(payload) => {
            if let Some(e) = rcagd_algebra::budget::as_work_limit(&*payload) {
                return Err(OpError::new(crate::limits::work_limit_message(
                    args.name(),
                    e,
                )));
            }
            let msg = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            Err(OpError::new(format!(
                "internal error (please report): the construction panicked: {msg}"
            )))
        }
    }
}

/// Checks and builds one object.
///
/// # Errors
/// Parameter problems, or the construction's error located at the `op` key (or at
/// the parameter the op names).
pub fn build_object(file: &SourceFile, obj: &RecipeObject) -> Result<Vec<Object>, Vec<Diagnostic>> {
    build_object_with(file, obj, Arithmetic::Exact)
}

/// The arithmetic a recipe is built in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Arithmetic {
    /// Exact rational arithmetic: the op's build, certificates are proofs (the default).
    #[default]
    Exact,
    /// `f64` (`rcagd build --float`, module [`crate::float`]): the op's float path, for
    /// speed; certificates are tolerance checks. An op without a float path is refused.
    Float,
}

/// Checks and builds one object in the given arithmetic (see [`build_object`]).
///
/// # Errors
/// As [`build_object`]; with [`Arithmetic::Float`] also an op that has no float path
/// (located at the `op` key, listing the ops that have one).
pub fn build_object_with(
    file: &SourceFile,
    obj: &RecipeObject,
    arithmetic: Arithmetic,
) -> Result<Vec<Object>, Vec<Diagnostic>> {
    let (op, args) = check_object(file, obj)?;
    let build = match arithmetic {
        Arithmetic::Exact => op.build,
        Arithmetic::Float => match crate::float::find(op.name) {
            Some(f) => f.build,
            None => {
                return Err(vec![file
                    .error(
                        obj.op_key_span,
                        format!(
                            "op `{}` of {:?} has no float path: `--float` builds only ops whose construction runs in f64",
                            op.name, obj.name
                        ),
                    )
                    .note(format!(
                        "ops with a float path: {}",
                        crate::float::float_op_names()
                    ))
                    .note("build this recipe without --float (exact), or move the object to a recipe of its own")]);
            }
        },
    };
    let checked = run_build(build, &args).and_then(|objs| f64_overflow(&args, objs));
    checked.map_err(|mut e| {
        // the library's typed overflow (`PhError::NonFinite`: the f64 solvers check their
        // intermediates): the input is too large for f64, say which; other ops' `f64`
        // computations that overflowed show `inf`/`NaN` in whatever they say ("√(inf) is
        // irrational", …), recognised with a large input
        let typed = crate::limits::is_typed_overflow(&e.message)
            .then(|| crate::limits::largest_input(&args))
            .flatten();
        if let Some(large) = typed.or_else(|| {
            crate::limits::large_input(&args).filter(|_| {
                crate::limits::shows_non_finite(&e.message)
                    && !e.message.starts_with("input too large")
            })
        }) {
            e.param = Some(large.0);
            e.message = crate::limits::too_large_for_f64(large, &e.message);
        }
        let span = e
            .param
            .and_then(|p| obj.params.iter().find(|x| x.key == p))
            .map_or(obj.op_key_span, |x| x.value.span);
        vec![file.error(
            span,
            format!(
                "cannot build {:?} (op `{}`): {}",
                obj.name, op.name, e.message
            ),
        )]
    })
}

/// An object whose `f64` certificate failed with a non-finite residual (`inf`, `NaN`)
/// while an input number is large ([`crate::limits::large_input`]): the `f64`
/// computation overflowed, an input error ("input too large for f64", exit 2, nothing
/// written) rather than a failed certificate.
fn f64_overflow(args: &OpArgs, objs: Vec<Object>) -> Result<Vec<Object>, OpError> {
    let overflow = objs.iter().find_map(|o| {
        o.certificates
            .iter()
            .find(|c| !c.holds && crate::limits::shows_non_finite(&c.to_string()))
            .map(|c| format!("certificate of {:?}: {c}", o.name))
    });
    match overflow.zip(crate::limits::large_input(args)) {
        None => Ok(objs),
        Some((what, large)) => {
            let param = large.0;
            let mut e = OpError::new(crate::limits::too_large_for_f64(large, &what));
            e.param = Some(param);
            Err(e)
        }
    }
}

/// Builds every object of a recipe, calling `progress(name)` after each one.
/// Independent objects are built in parallel (rayon); the result keeps the recipe's
/// order, so the output does not depend on the schedule. Objects produced by one op
/// under additional names are checked for uniqueness.
///
/// # Errors
/// All problems of all objects.
pub fn build_recipe(
    recipe: &Recipe,
    progress: impl Fn(&str) + Sync,
) -> Result<Vec<Object>, Vec<Diagnostic>> {
    build_recipe_with(recipe, Arithmetic::Exact, progress)
}

/// Builds every object of a recipe in the given arithmetic (see [`build_recipe`]).
///
/// # Errors
/// All problems of all objects.
pub fn build_recipe_with(
    recipe: &Recipe,
    arithmetic: Arithmetic,
    progress: impl Fn(&str) + Sync,
) -> Result<Vec<Object>, Vec<Diagnostic>> {
    // the caller's work budget (the fuzzer's per case) holds on the worker threads too
    let built: Vec<_> = recipe
        .objects
        .par_iter()
        .map(rcagd_algebra::budget::inherit(|obj: &RecipeObject| {
            let r = build_object_with(&recipe.file, obj, arithmetic);
            progress(&obj.name);
            r
        }))
        .collect();
    let mut out: Vec<Object> = Vec::new();
    // which recipe object made each output name
    let mut owner: Vec<&crate::recipe::RecipeObject> = Vec::new();
    let mut diags = Vec::new();
    for (obj, result) in recipe.objects.iter().zip(built) {
        match result {
            Ok(objs) => {
                for o in objs {
                    match out.iter().position(|x| x.name == o.name) {
                        Some(i) if std::ptr::eq(owner[i], obj) => {
                            diags.push(recipe.file.error(
                                obj.op_key_span,
                                format!(
                                    "op `{}` produced a second object called {:?}",
                                    obj.op, o.name
                                ),
                            ));
                        }
                        Some(i) => {
                            let first = owner[i];
                            let made = |r: &crate::recipe::RecipeObject| {
                                if r.name == o.name {
                                    format!("object {:?} (op `{}`)", r.name, r.op)
                                } else {
                                    format!(
                                        "object {:?} (op `{}`, which names its extra results {:?}, …)",
                                        r.name, r.op, o.name
                                    )
                                }
                            };
                            diags.push(recipe.file.error(
                                obj.span,
                                format!(
                                    "two results are called {:?}: {} and {}; rename one of them",
                                    o.name,
                                    made(first),
                                    made(obj)
                                ),
                            ));
                        }
                        None => {
                            out.push(o);
                            owner.push(obj);
                        }
                    }
                }
            }
            Err(d) => diags.extend(d),
        }
    }
    if diags.is_empty() {
        Ok(out)
    } else {
        Err(diags)
    }
}

/// Reads a recipe file (`-`: standard input), refusing a recipe larger than
/// [`Limits::recipe_bytes`](crate::limits::Limits) (reading stops there, so `/dev/zero` is an
/// error, not an exhausted memory) or with more than
/// [`Limits::objects`](crate::limits::Limits) objects.
///
/// # Errors
/// The diagnostics of an unreadable, too large or invalid recipe.
pub fn load(path: &Path) -> Result<Recipe, Vec<Diagnostic>> {
    let limits = crate::limits::Limits::current();
    let display = path.display().to_string();
    let name = if display == "-" {
        "<stdin>".to_string()
    } else {
        display.clone()
    };
    let mut buf = Vec::new();
    let read = if display == "-" {
        std::io::stdin()
            .take(limits.recipe_bytes.saturating_add(1))
            .read_to_end(&mut buf)
            .map_err(|e| format!("cannot read standard input: {e}"))
    } else {
        std::fs::File::open(path)
            .and_then(|f| {
                f.take(limits.recipe_bytes.saturating_add(1))
                    .read_to_end(&mut buf)
            })
            .map_err(|e| format!("cannot read the recipe: {e}"))
    };
    if let Err(message) = read {
        return Err(vec![Diagnostic::whole_file(&name, message)]);
    }
    if buf.len() as u64 > limits.recipe_bytes {
        return Err(vec![Diagnostic::whole_file(
            &name,
            format!(
                "the recipe is larger than the limit of {} bytes (`rcagd build --max-recipe-bytes N` raises it)",
                limits.recipe_bytes
            ),
        )]);
    }
    let recipe = Recipe::from_bytes(&name, &buf, None)?;
    if recipe.objects.len() > limits.objects {
        return Err(vec![Diagnostic::whole_file(
            &name,
            format!(
                "the recipe has {} objects, more than the limit of {} (`rcagd build --max-objects N` raises it)",
                recipe.objects.len(),
                limits.objects
            ),
        )]);
    }
    Ok(recipe)
}

/// The exit code of a recipe that could not be built: 1 when a construction panicked
/// or reported an internal error (a defect: "internal error" at the start of the op's
/// message or of the diagnostic), else 2 (an input error).
pub fn build_error_exit(diags: &[Diagnostic]) -> u8 {
    let internal = |m: &str| m.starts_with("internal error") || m.contains("`): internal error");
    if diags.iter().any(|d| internal(&d.message)) {
        EXIT_FAIL
    } else {
        EXIT_INPUT
    }
}

fn print_diagnostics(diags: &[Diagnostic]) {
    err!("{}", crate::source::render_all(diags));
}

/// Renders and writes every requested file of every object ([`output::write_objects`],
/// all or nothing) under a work budget of its own: [`Limits::seconds`](crate::limits::Limits)
/// (`--max-seconds`) for the whole export phase, separate from the objects' construction
/// budgets (exporters of exact objects compute exact boundary curves and meshes, work of
/// the same kind as a construction). The exporters run in parallel and inherit the budget.
///
/// # Errors
/// The exporter's or file system's message ([`crate::limits::export_error`]), or "work
/// limit exceeded: exporting … took more than N s" — in every case nothing was written
/// (every file is rendered before any is written).
pub fn export_within_budget(
    dir: &Path,
    objects: &[Object],
    formats: &[OutFormat],
) -> Result<Vec<std::path::PathBuf>, String> {
    let limit = crate::limits::Limits::current().work_limit();
    let _budget = limit.map(rcagd_algebra::budget::install);
    match rcagd_algebra::budget::catch(|| output::write_objects(dir, objects, formats)) {
        Ok(r) => r.map_err(|e| crate::limits::export_error(&e)),
        Err(e) => Err(crate::limits::export_work_limit_message(
            objects, formats, e,
        )),
    }
}

/// Runs `rcagd build`; returns the exit code (0 all certificates hold, 1 one fails,
/// 2 usage or input error; nothing is written on an input error).
/// A progress bar on standard error, one step per object: drawn when `show` is set or
/// standard error is a terminal, hidden otherwise.
fn progress_bar(len: usize, show: bool) -> indicatif::ProgressBar {
    use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
    use std::io::IsTerminal as _;
    let pb = ProgressBar::with_draw_target(Some(len as u64), ProgressDrawTarget::stderr());
    if !show && !std::io::stderr().is_terminal() {
        pb.set_draw_target(ProgressDrawTarget::hidden());
    }
    if let Ok(style) =
        ProgressStyle::with_template("{spinner} building [{bar:30}] {pos}/{len} {wide_msg}")
    {
        pb.set_style(style.progress_chars("=> "));
    }
    pb
}

/// Runs `rcagd build`; `progress` forces the per-object progress bar on standard error
/// (it is shown anyway when standard error is a terminal). Nothing is written before
/// every object is built and rendered, so an interrupt (Ctrl-C) leaves no file behind
/// (at most the `.NAME.rcagd-partial` temporaries of the final write phase).
pub fn run(
    path: &Path,
    out: Option<&Path>,
    formats: &[OutFormat],
    progress: bool,
    arithmetic: Arithmetic,
) -> u8 {
    let mut formats: Vec<OutFormat> = formats.to_vec();
    if formats.is_empty() {
        formats.push(OutFormat::Json);
    }
    let mut seen = Vec::new();
    formats.retain(|f| {
        let new = !seen.contains(f);
        seen.push(*f);
        new
    });
    if out.is_none() && formats != [OutFormat::Json] {
        errln!("error: formats other than json need --out DIR (without --out, JSON is printed to stdout)");
        return EXIT_INPUT;
    }
    let recipe = match load(path) {
        Ok(r) => r,
        Err(d) => {
            print_diagnostics(&d);
            return EXIT_INPUT;
        }
    };
    let pb = progress_bar(recipe.objects.len(), progress);
    // indicatif draws only on a terminal: a forced progress to a file or pipe is one line
    // per object
    let lines = progress && !std::io::IsTerminal::is_terminal(&std::io::stderr());
    let done = std::sync::atomic::AtomicUsize::new(0);
    let total = recipe.objects.len();
    let built = build_recipe_with(&recipe, arithmetic, |name| {
        if lines {
            let k = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            errln!("built {k}/{total}: {}", clip(name));
        }
        pb.set_message(clip(name).into_owned());
        pb.inc(1);
    });
    pb.finish_and_clear();
    let objects = match built {
        Ok(o) => o,
        Err(d) => {
            print_diagnostics(&d);
            // a construction that panicked (or otherwise reported an internal error) is
            // a defect, not the input's fault: exit 1, as documented
            return build_error_exit(&d);
        }
    };
    match out {
        None => match output::objects_json_text(&objects) {
            Ok(text) => outln!("{text}"),
            Err(e) => {
                errln!("error: {e}");
                return EXIT_INPUT;
            }
        },
        Some(dir) => {
            if let Err(e) = export_within_budget(dir, &objects, &formats) {
                errln!("error: {e}");
                return EXIT_INPUT;
            }
        }
    }
    for o in &objects {
        for w in o.values.iter().filter(|v| v.name == "closure_warning") {
            if let rcagd_io::quantity::Quantity::Text(t) = &w.value {
                errln!("warning: object {:?} (op `{}`) {t}", clip(&o.name), o.op);
            }
        }
    }
    let mut failed = false;
    for o in &objects {
        let at = recipe
            .objects
            .iter()
            .find(|r| r.name == o.name)
            .map_or(Span::default(), |r| r.op_key_span);
        for c in o.certificates.iter().filter(|c| !c.holds) {
            failed = true;
            err!(
                "{}",
                recipe
                    .file
                    .error(at, format!("certificate of {:?} fails: {c}", o.name))
            );
        }
    }
    if failed {
        EXIT_FAIL
    } else {
        EXIT_OK
    }
}
