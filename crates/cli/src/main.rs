//! `rcagd`: exact rational curves and surfaces with certificates.
//!
//! * `rcagd gallery [--out DIR] [--quiet] [--only RECIPE,…] [--max-seconds N]` — build every
//!   embedded default recipe, write JSON/STEP/IGES/OBJ/SVG/PNG and the exact sidecar per object,
//!   `report.json` and `index.html` (each construction, and the export phase, under the budget);
//! * `rcagd build RECIPE [--out DIR] [--format json|step|iges|exact|obj|stl|ply|gltf|svg|png]…`
//!   `[--max-recipe-bytes N] [--max-objects N] [--max-digits N] [--max-degree N] [--max-points N]`
//!   `[--max-samples N] [--max-magnitude N] [--max-seconds N] [--progress] [--float]` — build a
//!   user's recipe (the limits: `rcagd_cli::limits`; `--float`: `rcagd_cli::float`);
//! * `rcagd ops [NAME] [--markdown]` — the op reference;
//! * `rcagd fuzz [--cases N] [--seed S] [--op NAME] [--corpus DIR] [--case-seconds T] [--huge]` —
//!   the structured fuzzer over the op registry (`rcagd_cli::fuzz`).
//!
//! Exit codes: 0 all certificates hold, 1 a certificate fails (or an object of the
//! gallery cannot be built, or a construction fails internally: a panic caught, an
//! "internal error"), 2 a usage or input error.

use clap::{Parser, Subcommand};
use rcagd_cli::output::OutFormat;
use rcagd_cli::{build, gallery, ops, EXIT_INPUT};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "rcagd",
    version,
    about = "Exact rational curves and surfaces for CAD, with certificates",
    long_about = "Exact rational curves and surfaces for CAD, with certificates.\n\n\
        Exit codes: 0 = every certificate holds, 1 = a certificate fails (or an internal error), 2 = usage or input error."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Build every construction of the embedded default recipes and write a report.
    ///
    /// Writes NAME.json, NAME.step, NAME.igs, NAME.obj, NAME.svg and NAME.png per
    /// object, report.json and index.html into DIR, and prints a summary table.
    Gallery {
        /// Output directory (created if missing).
        #[arg(long, value_name = "DIR", default_value = "gallery-out")]
        out: PathBuf,
        /// No progress bar and no table; only failures are printed.
        #[arg(long, short)]
        quiet: bool,
        /// Build only these recipes (short names such as `pn` or `canal`: the file
        /// names of examples/recipes without extension; repeatable or comma-separated).
        #[arg(long, value_delimiter = ',', value_name = "RECIPE")]
        only: Vec<String>,
        /// Work budget of one object's construction, and of the export phase (all
        /// files rendered), in seconds (0: none); over it: "work limit exceeded",
        /// nothing written.
        #[arg(long, value_name = "N", default_value_t = rcagd_cli::limits::DEFAULT_SECONDS)]
        max_seconds: u64,
    },
    /// Build the objects of a recipe (TOML or JSON).
    ///
    /// Without --out the JSON of all objects is printed to stdout. RECIPE may be `-`
    /// for standard input.
    Build {
        /// The recipe file (.toml or .json; other extensions are recognised by content).
        recipe: PathBuf,
        /// Output directory: one file per object and format.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Output formats (repeatable or comma-separated); default json.
        #[arg(
            long = "format",
            value_enum,
            value_delimiter = ',',
            value_name = "FORMAT"
        )]
        formats: Vec<OutFormat>,
        /// Largest recipe accepted, in bytes.
        #[arg(long, value_name = "N", default_value_t = rcagd_cli::limits::DEFAULT_RECIPE_BYTES)]
        max_recipe_bytes: u64,
        /// Largest number of objects in the recipe.
        #[arg(long, value_name = "N", default_value_t = rcagd_cli::limits::DEFAULT_OBJECTS)]
        max_objects: usize,
        /// Largest number of digits of one input number.
        #[arg(long, value_name = "N", default_value_t = rcagd_cli::limits::DEFAULT_DIGITS)]
        max_digits: usize,
        /// Largest degree a parameter may ask for (control points, coefficients,
        /// interpolation or Hermite data, degree parameters).
        #[arg(long, value_name = "N", default_value_t = rcagd_cli::limits::DEFAULT_DEGREE)]
        max_degree: usize,
        /// Largest number of items of one list parameter.
        #[arg(long, value_name = "N", default_value_t = rcagd_cli::limits::DEFAULT_POINTS)]
        max_points: usize,
        /// Largest sample or mesh count of a parameter.
        #[arg(long, value_name = "N", default_value_t = rcagd_cli::limits::DEFAULT_SAMPLES)]
        max_samples: usize,
        /// Largest spread of one object's input numbers, in decimal orders of magnitude.
        #[arg(long, value_name = "N", default_value_t = rcagd_cli::limits::DEFAULT_MAGNITUDE)]
        max_magnitude: u32,
        /// Work budget of one object's construction, in seconds (0: none); a longer
        /// construction ends with "work limit exceeded" (exit 2, nothing written).
        #[arg(long, value_name = "N", default_value_t = rcagd_cli::limits::DEFAULT_SECONDS)]
        max_seconds: u64,
        /// Show progress per object on standard error (default: only on a terminal).
        #[arg(long)]
        progress: bool,
        /// Build in f64 instead of exact arithmetic, for speed: control points are the
        /// exact binary values of f64 results, certificates are tolerance checks (not
        /// proofs) and every object says `arithmetic = "f64"`. Ops without a float path
        /// are refused (`rcagd ops NAME` says which have one).
        #[arg(long)]
        float: bool,
    },
    /// List the recipe ops and their parameters, or describe one op.
    Ops {
        /// Show only this op, with an example recipe.
        name: Option<String>,
        /// Print the reference as Markdown (as in docs/recipes.md).
        #[arg(long)]
        markdown: bool,
    },
    /// Fuzz the ops: generated recipes through parse, build and every exporter.
    ///
    /// Valid, near-valid, degenerate and hostile recipes from each op's parameter
    /// table, run in-process; STEP and IGES readers on damaged files. Exit 0 when
    /// nothing was found, 1 when a case panicked, said "internal error", failed a
    /// certificate or ran past --case-seconds (each finding is printed with its recipe
    /// and, with --corpus, written there as a regression recipe).
    Fuzz(rcagd_cli::fuzz::Options),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() { EXIT_INPUT } else { 0 });
        }
    };
    let code = match cli.command {
        Command::Gallery {
            out,
            quiet,
            only,
            max_seconds,
        } => {
            rcagd_cli::limits::Limits {
                seconds: max_seconds,
                ..rcagd_cli::limits::Limits::default()
            }
            .install();
            gallery::run(&out, quiet, &only)
        }
        Command::Build {
            recipe,
            out,
            formats,
            max_recipe_bytes,
            max_objects,
            max_digits,
            max_degree,
            max_points,
            max_samples,
            max_magnitude,
            max_seconds,
            progress,
            float,
        } => {
            rcagd_cli::limits::Limits {
                recipe_bytes: max_recipe_bytes,
                objects: max_objects,
                digits: max_digits,
                degree: max_degree,
                points: max_points,
                samples: max_samples,
                magnitude: max_magnitude,
                seconds: max_seconds,
            }
            .install();
            let arithmetic = if float {
                build::Arithmetic::Float
            } else {
                build::Arithmetic::Exact
            };
            build::run(&recipe, out.as_deref(), &formats, progress, arithmetic)
        }
        Command::Ops { name, markdown } => ops::describe::run(name.as_deref(), markdown),
        Command::Fuzz(options) => {
            let code = rcagd_cli::fuzz::run(&options);
            // cases still running past their time limit are abandoned here
            if let Some(e) = rcagd_cli::stdout_error() {
                if e.kind() != std::io::ErrorKind::BrokenPipe {
                    rcagd_cli::write_stderr(&format!(
                        "error: cannot write to standard output: {e}\n"
                    ));
                }
                std::process::exit(i32::from(code.max(EXIT_INPUT)));
            }
            std::process::exit(i32::from(code));
        }
    };
    // output that did not arrive is a failure (a full disk, `> /dev/full`); a reader
    // that closed the pipe early gets no message
    if let Some(e) = rcagd_cli::stdout_error() {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            rcagd_cli::write_stderr(&format!("error: cannot write to standard output: {e}\n"));
        }
        return ExitCode::from(code.max(EXIT_INPUT));
    }
    ExitCode::from(code)
}
