//! `rcagd fuzz`: a structured, deterministic fuzzer over the op registry.
//!
//! The stable toolchain has no libFuzzer, so the fuzzer generates recipes itself
//! ([`gen`]): for every op, from its parameter table and its valid examples, cases that
//! are valid, near-valid (one value mutated), degenerate (zeros, equal or collinear
//! points, empty lists, equal parameters) or hostile (huge and tiny numbers within the
//! recipe limits, `1/0`, wrong kinds, nested lists, odd keys and names). Each case runs
//! in-process through the path `rcagd build` takes (parse → build → every exporter
//! into memory: JSON, STEP, IGES, OBJ, STL, PLY, glTF, SVG, exact NURBS, PNG), under
//! `catch_unwind`, on a worker thread, under a work budget of `--case-seconds`
//! ([`rcagd_algebra::budget`]: the case's exact work ends at its next checkpoint after
//! the deadline, and the thread with it); a thread still running a few seconds after
//! the deadline (work without checkpoints) is abandoned. For some
//! of the cases that build, truncated, garbled and adversarial variants of the STEP and
//! IGES files are fed to the readers ([`readers`]).
//!
//! A *finding* is a panic (of the parser, an op, an exporter or a reader), an
//! "internal error" message, a certificate that fails on a recipe that built (exit 1:
//! either a defect or an input error reported as a certificate failure), or a case
//! that runs longer than the time limit. Findings are minimized (optional parameters
//! dropped while the finding persists) and written to the corpus directory as TOML
//! recipes with the expected exit class in a header line (`# expect: exit N`); the CLI
//! test `fuzz_corpus` replays the corpus ([`replay`]).

pub mod float_check;
pub mod gen;
pub mod readers;

use crate::build::build_recipe;
use crate::output::{self, OutFormat};
use crate::recipe::{Format, Recipe};
use gen::{Case, Rng};
use readers::FileKind;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Every export format, in the order they are tried.
pub const FORMATS: [OutFormat; 10] = [
    OutFormat::Json,
    OutFormat::Step,
    OutFormat::Iges,
    OutFormat::Obj,
    OutFormat::Stl,
    OutFormat::Ply,
    OutFormat::Gltf,
    OutFormat::Svg,
    OutFormat::Exact,
    OutFormat::Png,
];

/// What kind of defect a case revealed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum FindingKind {
    /// A panic (caught) in parsing, building or exporting.
    Panic,
    /// A message saying "internal error".
    Internal,
    /// A certificate failed on a recipe that built (exit 1).
    Certificate,
    /// The case ran longer than the time limit.
    Timeout,
    /// A STEP or IGES reader panicked.
    ReaderPanic,
    /// The exact and the `f64` build of a case disagree, or the `f64` path fails on data
    /// of moderate size where the exact one builds ([`float_check`]).
    FloatMismatch,
}

impl FindingKind {
    /// A short label.
    pub fn label(self) -> &'static str {
        match self {
            FindingKind::Panic => "panic",
            FindingKind::Internal => "internal-error",
            FindingKind::Certificate => "certificate",
            FindingKind::Timeout => "timeout",
            FindingKind::ReaderPanic => "reader-panic",
            FindingKind::FloatMismatch => "float-mismatch",
        }
    }
}

/// The result of one recipe, as `rcagd build --format` with every format would see it.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The exit code `rcagd build` gives: 0 every certificate holds, 1 a certificate
    /// fails, 2 an input error (parse, parameters, construction or export refused).
    pub exit: u8,
    /// The exit code of `rcagd build` with the default format (JSON to standard output):
    /// as `exit`, but an exporter that refuses the object does not count.
    pub build_exit: u8,
    /// Where it ended: `parse`, `build`, `export FORMAT`, `certificate` or `ok`.
    pub stage: String,
    /// The first error message (empty on success).
    pub message: String,
    /// The defect, if any.
    pub finding: Option<FindingKind>,
    /// The STEP and IGES texts of the objects (when they could be written).
    pub files: Vec<(FileKind, String)>,
}

impl Outcome {
    /// A case still running after `limit`: a timeout finding (exit 1).
    fn timeout(limit: Duration) -> Self {
        Outcome {
            exit: 1,
            build_exit: 1,
            stage: "timeout".into(),
            message: format!("still running after {:.1} s", limit.as_secs_f64()),
            finding: Some(FindingKind::Timeout),
            files: Vec::new(),
        }
    }
}

static PANIC_SITE: Mutex<Option<String>> = Mutex::new(None);

/// Replaces the panic hook by one that prints nothing and records where the last panic
/// happened (the fuzzer reports it with the finding).
pub fn quiet_panics() {
    std::panic::set_hook(Box::new(|info| {
        let site = info
            .location()
            .map(|l| format!("{}:{}", l.file(), l.line()))
            .unwrap_or_default();
        if let Ok(mut g) = PANIC_SITE.lock() {
            *g = Some(site);
        }
    }));
}

fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    let msg = payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into());
    let site = PANIC_SITE
        .lock()
        .ok()
        .and_then(|g| g.clone())
        .unwrap_or_default();
    format!("panicked: {msg} (at {site})")
}

fn first_line(s: &str) -> String {
    let l = s.lines().next().unwrap_or("");
    crate::source::clip(l).into_owned()
}

/// Runs a recipe text the way `rcagd build --format json,step,…,png` does, in memory.
pub fn evaluate(file_name: &str, text: &str) -> Outcome {
    evaluate_into(file_name, text, None)
}

/// [`evaluate`], with the objects built (when the build succeeded).
pub fn evaluate_objects(
    file_name: &str,
    text: &str,
) -> (Outcome, Option<Vec<crate::model::Object>>) {
    let mut built = None;
    let o = evaluate_into(file_name, text, Some(&mut built));
    (o, built)
}

fn evaluate_into(
    file_name: &str,
    text: &str,
    built: Option<&mut Option<Vec<crate::model::Object>>>,
) -> Outcome {
    let fail = |exit: u8, stage: &str, message: String, finding: Option<FindingKind>| Outcome {
        exit,
        build_exit: exit,
        stage: stage.to_string(),
        message,
        finding,
        files: Vec::new(),
    };
    let internal = |m: &str| m.contains("internal error");
    let recipe = match catch_unwind(AssertUnwindSafe(|| {
        Recipe::parse(file_name, text, Some(Format::Toml))
    })) {
        Err(p) => return fail(101, "parse", panic_message(&*p), Some(FindingKind::Panic)),
        Ok(Err(d)) => {
            let m = joined_messages(&d);
            let f = internal(&m).then_some(FindingKind::Internal);
            return fail(2, "parse", m, f);
        }
        Ok(Ok(r)) => r,
    };
    let objects = match catch_unwind(AssertUnwindSafe(|| build_recipe(&recipe, |_| {}))) {
        Err(p) => return fail(101, "build", panic_message(&*p), Some(FindingKind::Panic)),
        Ok(Err(d)) => {
            let m = joined_messages(&d);
            let f = if m.contains("the construction panicked") {
                Some(FindingKind::Panic)
            } else if m.contains(WORK_LIMIT) {
                // the case's (or the op's) work budget ended it: a timeout, stopped
                Some(FindingKind::Timeout)
            } else {
                internal(&m).then_some(FindingKind::Internal)
            };
            // as `rcagd build`: a panic caught by the registry is an internal error, exit 1
            let exit = crate::build::build_error_exit(&d);
            return fail(exit, "build", m, f);
        }
        Ok(Ok(o)) => o,
    };
    let mut files = Vec::new();
    let mut export_error: Option<(String, String)> = None;
    let mut finding = None;
    for o in &objects {
        for f in FORMATS {
            match catch_unwind(AssertUnwindSafe(|| output::render(o, f))) {
                Err(p) if rcagd_algebra::budget::as_work_limit(&*p).is_some() => {
                    return fail(
                        2,
                        &format!("export {}", f.label()),
                        format!("{WORK_LIMIT}: exporting {:?} as {}", o.name, f.label()),
                        Some(FindingKind::Timeout),
                    );
                }
                Err(p) => {
                    return fail(
                        101,
                        &format!("export {}", f.label()),
                        panic_message(&*p),
                        Some(FindingKind::Panic),
                    );
                }
                Ok(Err(e)) => {
                    if internal(&e) {
                        finding = Some(FindingKind::Internal);
                    }
                    export_error
                        .get_or_insert((f.label().to_string(), crate::limits::export_error(&e)));
                }
                Ok(Ok(bytes)) => {
                    let kind = match f {
                        OutFormat::Step => Some(FileKind::Step),
                        OutFormat::Iges => Some(FileKind::Iges),
                        _ => None,
                    };
                    if let Some(k) = kind {
                        files.push((k, String::from_utf8_lossy(&bytes).into_owned()));
                    }
                }
            }
        }
    }
    if let Err(p) = catch_unwind(AssertUnwindSafe(|| output::objects_json_text(&objects))) {
        return fail(
            101,
            "export JSON",
            panic_message(&*p),
            Some(FindingKind::Panic),
        );
    }
    let failing: Vec<String> = output::failures(&objects);
    if let Some(b) = built {
        *b = Some(objects.clone());
    }
    if !failing.is_empty() {
        return Outcome {
            exit: 1,
            build_exit: 1,
            stage: "certificate".into(),
            message: failing.join("; "),
            finding: finding.or(Some(FindingKind::Certificate)),
            files,
        };
    }
    match export_error {
        Some((fmt, e)) => Outcome {
            exit: 2,
            build_exit: if fmt == OutFormat::Json.label() { 2 } else { 0 },
            stage: format!("export {fmt}"),
            message: e,
            finding,
            files,
        },
        None => Outcome {
            exit: 0,
            build_exit: 0,
            stage: "ok".into(),
            message: String::new(),
            finding,
            files,
        },
    }
}

/// The start of the message of a construction (or export) that ran out of its work
/// budget.
pub const WORK_LIMIT: &str = "work limit exceeded";

/// How long past its work budget a case may take to end (its next checkpoint, the
/// unwinding, the exporters' work after a checkpoint) before its thread is abandoned.
fn grace(limit: Duration) -> Duration {
    limit / 2 + Duration::from_secs(5)
}

/// The result of a case run on a worker thread under a work budget of `limit`
/// ([`rcagd_algebra::budget`], so that its exact work ends soon after the deadline):
/// `None` when it did not finish within `limit` and [`grace`] (its thread is left
/// running; the process ends it on exit).
fn with_limit<T: Send + 'static>(
    limit: Duration,
    f: impl FnOnce() -> T + Send + 'static,
) -> Option<T> {
    let (tx, rx) = mpsc::channel();
    let spawned = std::thread::Builder::new()
        .name("rcagd-fuzz-case".into())
        .stack_size(8 << 20)
        .spawn(move || {
            let _budget = rcagd_algebra::budget::install(limit);
            let _ = tx.send(f());
        });
    if spawned.is_err() {
        return None;
    }
    rx.recv_timeout(limit + grace(limit)).ok()
}

/// Evaluates a recipe under a work budget of `limit`; a case over the limit is a timeout
/// finding (ended by the budget: exit 2 with "work limit exceeded"; not ended within
/// the grace time: exit 1, "still running").
pub fn evaluate_limited(file_name: &str, text: &str, limit: Duration) -> (Outcome, Duration) {
    let start = Instant::now();
    let (n, t) = (file_name.to_string(), text.to_string());
    match with_limit(limit, move || evaluate(&n, &t)) {
        Some(o) => (o, start.elapsed()),
        None => (Outcome::timeout(limit), start.elapsed()),
    }
}

/// The work budget a corpus recipe asks for in a `# max-seconds: N` header line (an
/// input that is slow by nature: it must end with "work limit exceeded" under it).
pub fn expected_seconds(text: &str) -> Option<f64> {
    text.lines()
        .take_while(|l| l.starts_with('#'))
        .find_map(|l| l.strip_prefix("# max-seconds: "))
        .and_then(|n| n.trim().parse().ok())
        .filter(|s: &f64| s.is_finite() && *s > 0.0)
}

/// Reads a file with a reader under `catch_unwind`: `Err(panic message)` on a panic.
///
/// # Errors
/// The panic message.
pub fn read_no_panic(kind: FileKind, text: &str) -> Result<Result<usize, String>, String> {
    match catch_unwind(AssertUnwindSafe(|| kind.read(text))) {
        Ok(r) => Ok(r),
        // the case's work budget ran out while reading: not a panic of the reader
        Err(p) if rcagd_algebra::budget::as_work_limit(&*p).is_some() => {
            Ok(Err(format!("{WORK_LIMIT} while reading")))
        }
        Err(p) => Err(panic_message(&*p)),
    }
}

/// The options of `rcagd fuzz` (also its command-line arguments).
#[derive(Debug, Clone, clap::Args)]
pub struct Options {
    /// Number of cases (spread over the ops in turn).
    #[arg(long, value_name = "N", default_value_t = 1000)]
    pub cases: u64,
    /// The seed: a run is a function of the seed and the case count.
    #[arg(long, value_name = "S", default_value_t = 1)]
    pub seed: u64,
    /// Only this op.
    #[arg(long, value_name = "NAME")]
    pub op: Option<String>,
    /// Write each finding (a minimal recipe or reader file) into DIR.
    #[arg(long, value_name = "DIR")]
    pub corpus: Option<PathBuf>,
    /// Time limit of one case, in seconds: the case's work budget (a case still working
    /// then ends with "work limit exceeded"; a longer case is a finding).
    #[arg(long, value_name = "T", default_value_t = 10.0)]
    pub case_seconds: f64,
    /// Print every recipe before running it (to standard error).
    #[arg(long, short)]
    pub verbose: bool,
    /// Hostile numbers up to 1e±300 and 30 digits: finds work that is not bounded
    /// (reported as timeouts).
    #[arg(long)]
    pub huge: bool,
    /// Stop after N cases were abandoned: still running `--case-seconds`/2 + 5 s past
    /// their budget (work without a checkpoint; each keeps a thread busy until the
    /// process ends).
    #[arg(long, value_name = "N", default_value_t = 3)]
    pub max_abandoned: u32,
}

#[derive(Default)]
struct OpStats {
    cases: u64,
    exit: [u64; 3],
    findings: u64,
}

/// A finding with the recipe (or reader file) that caused it.
#[derive(Debug, Clone)]
pub struct Finding {
    /// The kind.
    pub kind: FindingKind,
    /// The op.
    pub op: String,
    /// The case number.
    pub case: u64,
    /// How the case was generated.
    pub category: String,
    /// The message.
    pub message: String,
    /// The (minimized) recipe.
    pub recipe: String,
    /// For a reader finding: the file kind and the adversarial file.
    pub file: Option<(FileKind, String)>,
}

fn fnv(s: &str) -> u64 {
    s.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// A message with digits removed, for telling findings apart.
fn signature(kind: FindingKind, op: &str, message: &str) -> String {
    let m: String = first_line(message)
        .chars()
        .filter(|c| !c.is_ascii_digit())
        .take(80)
        .collect();
    format!("{}|{op}|{m}", kind.label())
}

/// Drops optional parameters one by one while the finding stays the same.
fn minimize(case: &Case, kind: FindingKind, limit: Duration) -> Case {
    let mut best = case.clone();
    let mut i = 0;
    while i < best.params.len() {
        let mut trial = best.clone();
        trial.params.remove(i);
        let (o, _) = evaluate_limited("fuzz.toml", &trial.toml(), limit);
        if o.finding == Some(kind) {
            best = trial;
        } else {
            i += 1;
        }
    }
    best
}

/// The corpus file for a finding: `OP-KIND-HASH.toml` (a reader finding: the file
/// itself, `.step` or `.igs`). Returns the path written.
///
/// # Errors
/// A message naming the file.
pub fn write_finding(dir: &Path, f: &Finding, seed: u64) -> Result<PathBuf, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let (path, text) = match &f.file {
        Some((k, file)) => (
            dir.join(format!(
                "reader-{}-{:016x}.{}",
                f.op,
                fnv(file),
                k.extension()
            )),
            file.clone(),
        ),
        None => {
            let expect = match f.kind {
                // the documented class of a defect in the library: exit 1
                FindingKind::Panic | FindingKind::Internal => 1,
                // to be decided when it is fixed: a defect (1) or an input error (2)
                _ => 2,
            };
            let mut t = String::new();
            let _ = writeln!(
                t,
                "# rcagd fuzz finding ({}): {}",
                f.kind.label(),
                first_line(&f.message)
            );
            let _ = writeln!(
                t,
                "# found by `rcagd fuzz --seed {seed}`, case {} ({})",
                f.case, f.category
            );
            let _ = writeln!(t, "# expect: exit {expect}");
            t.push_str(&f.recipe);
            (
                dir.join(format!(
                    "{}-{}-{:016x}.toml",
                    f.op,
                    f.kind.label(),
                    fnv(&f.recipe)
                )),
                t,
            )
        }
    };
    std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(path)
}

/// The expectation of a corpus recipe: the `# expect: exit N` header line.
pub fn expected_exit(text: &str) -> Option<u8> {
    text.lines()
        .take_while(|l| l.starts_with('#'))
        .find_map(|l| l.strip_prefix("# expect: exit "))
        .and_then(|n| n.trim().parse().ok())
}

/// Replays one corpus file: a recipe must end without panic or internal error, with
/// its expected exit class, within `limit`; a STEP or IGES file must be read without
/// panic within `limit`. Returns the time taken.
///
/// # Errors
/// What went wrong.
pub fn replay(path: &Path, limit: Duration) -> Result<Duration, String> {
    let text = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let text = String::from_utf8_lossy(&text).into_owned();
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
    let start = Instant::now();
    let kind = match ext {
        "step" => Some(FileKind::Step),
        "igs" => Some(FileKind::Iges),
        _ => None,
    };
    if let Some(k) = kind {
        return match with_limit(limit, move || read_no_panic(k, &text)) {
            None => Err(format!(
                "{}: the reader ran longer than {limit:?}",
                path.display()
            )),
            Some(Err(p)) => Err(format!("{}: {p}", path.display())),
            Some(Ok(_)) => Ok(start.elapsed()),
        };
    }
    let expect = expected_exit(&text)
        .ok_or_else(|| format!("{}: no `# expect: exit N` line", path.display()))?;
    let budget = expected_seconds(&text);
    let (o, t) = evaluate_limited(
        &path.display().to_string(),
        &text,
        budget.map_or(limit, |s| limit.min(Duration::from_secs_f64(s))),
    );
    // under its `# max-seconds` budget, the named work-limit error is the expected end
    let stopped = budget.is_some()
        && o.exit == 2
        && o.finding == Some(FindingKind::Timeout)
        && o.message.contains(WORK_LIMIT);
    if stopped && t > limit {
        return Err(format!(
            "{}: the work limit ended it only after {:.1} s",
            path.display(),
            t.as_secs_f64()
        ));
    }
    if let Some(k) = o
        .finding
        .filter(|k| *k != FindingKind::Certificate || expect != 1)
        .filter(|_| !stopped)
    {
        return Err(format!(
            "{}: {} at {}: {}",
            path.display(),
            k.label(),
            o.stage,
            o.message
        ));
    }
    if o.exit != expect {
        return Err(format!(
            "{}: exit {} (expected {expect}) at {}: {}",
            path.display(),
            o.exit,
            o.stage,
            first_line(&o.message)
        ));
    }
    Ok(t)
}

/// Runs the fuzzer; prints the summary; returns the exit code (0 no finding, 1
/// findings, 2 usage error).
pub fn run(opts: &Options) -> u8 {
    let ops: Vec<&'static crate::ops::OpSpec> = match &opts.op {
        Some(n) => match crate::ops::find(n) {
            Some(op) => vec![op],
            None => {
                errln!(
                    "error: unknown op {:?} (`rcagd ops` lists them)",
                    crate::source::clip(n)
                );
                return crate::EXIT_INPUT;
            }
        },
        None => crate::ops::all().collect(),
    };
    if !(opts.case_seconds > 0.0 && opts.case_seconds.is_finite()) {
        errln!("error: --case-seconds must be a positive number of seconds");
        return crate::EXIT_INPUT;
    }
    let limit = Duration::from_secs_f64(opts.case_seconds);
    quiet_panics();
    let seeds: Vec<Vec<(String, gen::V)>> = Vec::new();
    let seeds: Vec<_> = ops
        .iter()
        .map(|op| gen::seeds(op))
        .chain(std::iter::once(seeds))
        .collect();
    let start = Instant::now();
    let mut stats: BTreeMap<&str, OpStats> = BTreeMap::new();
    let mut findings: Vec<Finding> = Vec::new();
    let mut seen: BTreeMap<String, u64> = BTreeMap::new();
    let mut reader_runs = 0u64;
    let mut float_runs = 0u64;
    let mut running = 0u32;
    let mut slowest = (Duration::ZERO, String::new());
    let mut stages: BTreeMap<String, u64> = BTreeMap::new();
    let mut done = 0u64;
    for case in 0..opts.cases {
        let k = (case % ops.len() as u64) as usize;
        let (op, op_seeds) = (ops[k], &seeds[k]);
        let mut rng = Rng::for_case(opts.seed, case);
        let c = gen::generate_with(&mut rng, op, op_seeds, opts.huge);
        let text = c.toml();
        if opts.verbose {
            errln!("case {case} ({}):\n{text}", c.category);
        }
        let with_readers = rng.chance(1, 3);
        // exact against f64 for half of the cases (those that build and whose ops have a
        // float path)
        let with_float = rng.chance(1, 2);
        let mut reader_rng = rng.clone();
        let t2 = text.clone();
        let started = Instant::now();
        // under the case's work budget (installed by `with_limit`): a case still working
        // at `limit` ends at its next checkpoint, so its thread does not run on
        let result = with_limit(limit, move || {
            let (o, exact) = evaluate_objects("fuzz.toml", &t2);
            let float = exact
                .filter(|_| with_float && o.build_exit == 0)
                .and_then(|objs| float_check::check("fuzz.toml", &t2, &objs));
            let mut bad: Option<(FileKind, String, String)> = None;
            let mut n = 0u64;
            if with_readers && o.exit == 0 {
                'files: for (kind, file) in &o.files {
                    if kind_ok(*kind, file).is_err() {
                        bad = Some((*kind, file.clone(), "the unmodified file".into()));
                        break;
                    }
                    for _ in 0..3 {
                        let (v, what) = readers::variant(*kind, file, &mut reader_rng);
                        n += 1;
                        if let Err(p) = read_no_panic(*kind, &v) {
                            bad = Some((*kind, v, format!("{what}: {p}")));
                            break 'files;
                        }
                    }
                }
            }
            (o, bad, n, float)
        });
        let elapsed = started.elapsed();
        done += 1;
        if opts.verbose {
            match &result {
                Some((o, _, _, _)) => errln!(
                    "  -> exit {} at {} ({:.2} s): {}",
                    o.exit,
                    o.stage,
                    elapsed.as_secs_f64(),
                    first_line(&o.message)
                ),
                None => errln!("  -> still running after the time limit"),
            }
        }
        let st = stats.entry(op.name).or_default();
        st.cases += 1;
        let (outcome, reader_bad, float_bad) = match result {
            Some((o, bad, n, float)) => {
                reader_runs += n;
                if with_float && o.build_exit == 0 {
                    float_runs += 1;
                }
                (o, bad, float)
            }
            None => {
                running += 1;
                (Outcome::timeout(limit), None, None)
            }
        };
        if elapsed > slowest.0 && outcome.finding != Some(FindingKind::Timeout) {
            slowest = (elapsed, format!("{} case {case}", op.name));
        }
        if let Some(e) = st.exit.get_mut(usize::from(outcome.exit.min(2))) {
            *e += 1;
        }
        *stages
            .entry(format!(
                "exit {} at {}",
                outcome.exit,
                outcome.stage.split(' ').next().unwrap_or("")
            ))
            .or_default() += 1;
        let mut new: Vec<Finding> = Vec::new();
        if let Some(kind) = outcome.finding {
            new.push(Finding {
                kind,
                op: op.name.to_string(),
                case,
                category: c.category.clone(),
                message: outcome.message.clone(),
                recipe: c.toml(),
                file: None,
            });
        }
        if let Some(msg) = float_bad {
            new.push(Finding {
                kind: FindingKind::FloatMismatch,
                op: op.name.to_string(),
                case,
                category: c.category.clone(),
                message: msg,
                recipe: c.toml(),
                file: None,
            });
        }
        if let Some((fk, file, msg)) = reader_bad {
            new.push(Finding {
                kind: FindingKind::ReaderPanic,
                op: fk.extension().to_string(),
                case,
                category: c.category.clone(),
                message: msg,
                recipe: c.toml(),
                file: Some((fk, file)),
            });
        }
        for mut f in new {
            st.findings += 1;
            let sig = signature(f.kind, &f.op, &f.message);
            let count = seen.entry(sig).or_default();
            *count += 1;
            if *count > 1 {
                continue;
            }
            if f.file.is_none()
                && !matches!(f.kind, FindingKind::Timeout | FindingKind::FloatMismatch)
            {
                f.recipe = minimize(&c, f.kind, limit).toml();
            }
            errln!(
                "finding ({}) in `{}`, case {case} ({}): {}",
                f.kind.label(),
                f.op,
                f.category,
                first_line(&f.message)
            );
            if let Some(dir) = &opts.corpus {
                match write_finding(dir, &f, opts.seed) {
                    Ok(p) => errln!("  written to {}", p.display()),
                    Err(e) => errln!("  {e}"),
                }
            }
            findings.push(f);
        }
        if done.is_multiple_of(500) {
            errln!(
                "… {done} cases, {:.0} s, {} findings",
                start.elapsed().as_secs_f64(),
                findings.len()
            );
        }
        if running >= opts.max_abandoned.max(1) {
            errln!("stopping early: {running} cases are still running past the time limit");
            break;
        }
    }
    let total = start.elapsed();
    let mut s = String::new();
    let _ = writeln!(
        s,
        "rcagd fuzz: {done} cases (seed {}) in {:.1} s, {} reader runs, {} exact-vs-f64 comparisons tried; slowest case {:.2} s ({})",
        opts.seed,
        total.as_secs_f64(),
        reader_runs,
        float_runs,
        slowest.0.as_secs_f64(),
        slowest.1
    );
    let _ = writeln!(
        s,
        "{:<32} {:>7} {:>7} {:>7} {:>7} {:>8}",
        "op", "cases", "exit 0", "exit 1", "exit 2", "findings"
    );
    for (name, st) in &stats {
        let _ = writeln!(
            s,
            "{name:<32} {:>7} {:>7} {:>7} {:>7} {:>8}",
            st.cases, st.exit[0], st.exit[1], st.exit[2], st.findings
        );
    }
    let _ = writeln!(s, "outcomes:");
    for (k, n) in &stages {
        let _ = writeln!(s, "  {k}: {n}");
    }
    let distinct = findings.len();
    let all: u64 = seen.values().sum();
    let _ = writeln!(s, "findings: {all} ({distinct} distinct)");
    for f in &findings {
        let _ = writeln!(
            s,
            "  [{}] {} case {} ({}): {}",
            f.kind.label(),
            f.op,
            f.case,
            f.category,
            first_line(&f.message)
        );
        if f.file.is_none() {
            for l in f.recipe.lines() {
                let _ = writeln!(s, "      {l}");
            }
        }
    }
    out!("{s}");
    if findings.is_empty() {
        crate::EXIT_OK
    } else {
        crate::EXIT_FAIL
    }
}

/// Reads an unmodified exported file: it must read without panic (a reader error on
/// a file rcagd wrote is reported too).
fn kind_ok(kind: FileKind, file: &str) -> Result<(), String> {
    match read_no_panic(kind, file) {
        Err(p) => Err(p),
        Ok(_) => Ok(()),
    }
}

/// The messages of a list of diagnostics, joined by `; `.
fn joined_messages(d: &[crate::source::Diagnostic]) -> String {
    d.iter()
        .map(|d| d.message.clone())
        .collect::<Vec<_>>()
        .join("; ")
}
