//! Helpers shared by the CLI test modules: the binary, per-test temporary directories,
//! and output text.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The `rcagd` binary built for these tests.
pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rcagd"))
}

/// A fresh directory under `target/tmp` for one test, removed when the test passes
/// (kept for inspection when it fails).
pub struct TempDir(PathBuf);

impl std::ops::Deref for TempDir {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<std::ffi::OsStr> for TempDir {
    fn as_ref(&self) -> &std::ffi::OsStr {
        self.0.as_os_str()
    }
}

impl AsRef<Path> for TempDir {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

/// A fresh, empty directory named after the test module and `tag`.
pub fn temp_dir(tag: &str) -> TempDir {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("create temp dir");
    TempDir(dir)
}

/// Writes `text` to `dir/name` and returns the path.
pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).expect("write file");
    p
}

/// Runs `cmd` and asserts that it exits successfully (showing its stderr if not).
pub fn run_ok(cmd: &mut Command) -> Output {
    let out = cmd.output().expect("run rcagd");
    assert!(out.status.success(), "{}", stderr(&out));
    out
}

/// Writes `recipe` to `dir/r.toml`, runs `rcagd build r.toml --format json --out dir/out`,
/// asserts that it succeeds and returns the output directory.
pub fn build_json_in(dir: &Path, recipe: &str) -> PathBuf {
    let file = write(dir, "r.toml", recipe);
    let out = dir.join("out");
    run_ok(
        bin()
            .arg("build")
            .arg(&file)
            .args(["--format", "json", "--out"])
            .arg(&out),
    );
    out
}

/// Writes `recipe` to `dir/r.toml`, runs `rcagd build r.toml --format json --out dir/out`,
/// asserts that it is refused (exit code 2) and returns its stderr.
pub fn build_refused(dir: &Path, recipe: &str) -> String {
    let file = write(dir, "r.toml", recipe);
    let o = bin()
        .arg("build")
        .arg(&file)
        .args(["--format", "json", "--out"])
        .arg(dir.join("out"))
        .output()
        .expect("run rcagd");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    stderr(&o)
}

/// Builds `recipe` in a fresh directory and returns the JSON of object `name`, asserting
/// that all its certificates hold.
pub fn build_json_certified(tag: &str, recipe: &str, name: &str) -> serde_json::Value {
    let dir = temp_dir(tag);
    let v = read_json(&build_json_in(&dir, recipe), name);
    assert_eq!(v["all_certificates_hold"], true, "{v}");
    v
}

/// The exact text of the named value of an object's JSON (a JSON string as is, anything
/// else in its JSON form).
pub fn value_exact(obj: &serde_json::Value, name: &str) -> String {
    let v = obj["values"]
        .as_array()
        .expect("values")
        .iter()
        .find(|v| v["name"] == name)
        .unwrap_or_else(|| panic!("no value {name}"));
    match &v["exact"] {
        serde_json::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// The JSON document `out/<name>.json` written by a build.
pub fn read_json(out: &Path, name: &str) -> serde_json::Value {
    let text = std::fs::read_to_string(out.join(format!("{name}.json"))).expect("json");
    serde_json::from_str(&text).expect("valid json")
}

/// Asserts that `o` is a patch set whose certificates all hold exactly, one of them
/// naming `property`.
pub fn assert_exact_patches_certifying(o: &rcagd_cli::model::Object, property: &str) {
    assert!(matches!(o.geometry, rcagd_cli::model::Geometry::Patches(_)));
    assert!(
        o.certificates.iter().all(|c| c.holds && c.exact),
        "{:#?}",
        o.certificates
    );
    assert!(
        o.certificates.iter().any(|c| c.property.contains(property)),
        "no certificate names {property:?}: {:#?}",
        o.certificates
    );
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The triangle mesh of an OBJ text (`v` and `f` lines; `f a//n b//n c//n` or `f a b c`).
pub fn obj_mesh(text: &str) -> rcagd_geom::tessellate::TriMesh {
    let mut m = rcagd_geom::tessellate::TriMesh::default();
    for line in text.lines() {
        let mut it = line.split_whitespace();
        match it.next() {
            Some("v") => {
                let c: Vec<f64> = it.map(|x| x.parse().expect("coordinate")).collect();
                m.positions.push([c[0], c[1], c[2]]);
            }
            Some("f") => {
                let i: Vec<u32> = it
                    .map(|x| {
                        x.split('/')
                            .next()
                            .expect("index")
                            .parse::<u32>()
                            .expect("index")
                            - 1
                    })
                    .collect();
                m.triangles.push([i[0], i[1], i[2]]);
            }
            _ => {}
        }
    }
    m
}

/// One op's example recipe, parsed and built once (exact arithmetic, as `rcagd build`).
pub struct BuiltExample {
    /// The op whose example this is.
    pub op: &'static str,
    /// The ops of the recipe's objects, or the first parse error.
    pub recipe_ops: Result<Vec<String>, String>,
    /// The built objects, or the first build error (`None` when the recipe did not parse).
    pub built: Option<Result<Vec<rcagd_cli::model::Object>, String>>,
}

/// Every op's example, built once per test binary and shared by the tests that check
/// them (`docs::every_op_example_builds`, `unit::build::every_example_builds_and_holds`):
/// both checked the same `build_recipe` of the same text, and building every example
/// takes seconds of the CLI tests' time.
pub fn op_examples() -> &'static [BuiltExample] {
    static EXAMPLES: std::sync::OnceLock<Vec<BuiltExample>> = std::sync::OnceLock::new();
    EXAMPLES.get_or_init(|| {
        rcagd_cli::ops::all()
            .map(|op| {
                let recipe = rcagd_cli::recipe::Recipe::parse("example.toml", op.example, None);
                let recipe_ops = match &recipe {
                    Ok(r) => Ok(r.objects.iter().map(|o| o.op.clone()).collect()),
                    Err(e) => Err(e[0].to_string()),
                };
                let built = recipe.ok().map(|r| {
                    rcagd_cli::build::build_recipe(&r, |_| {}).map_err(|e| e[0].to_string())
                });
                BuiltExample {
                    op: op.name,
                    recipe_ops,
                    built,
                }
            })
            .collect()
    })
}
