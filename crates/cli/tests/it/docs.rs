//! `docs/recipes.md` and `examples/recipes/` stay consistent with the op registry:
//! every op (with every parameter and its example) is documented, and every recipe in
//! the docs and the examples builds with all certificates holding.

use rcagd_cli::build::build_recipe;
use rcagd_cli::ops::{self, describe};
use rcagd_cli::recipe::Recipe;
use std::path::{Path, PathBuf};

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn recipes_md() -> String {
    std::fs::read_to_string(workspace().join("docs/recipes.md")).expect("docs/recipes.md exists")
}

/// The ```toml blocks of a Markdown text, with their 1-based starting line.
fn toml_blocks(md: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut current: Option<(usize, String)> = None;
    for (i, line) in md.lines().enumerate() {
        match &mut current {
            None if line.trim_start().starts_with("```toml") => {
                current = Some((i + 2, String::new()))
            }
            None => {}
            Some(_) if line.trim_start().starts_with("```") => out.extend(current.take()),
            Some((_, text)) => {
                text.push_str(line);
                text.push('\n');
            }
        }
    }
    out
}

fn assert_builds_and_holds(label: &str, text: &str) -> Vec<String> {
    let recipe = Recipe::parse(label, text, None).unwrap_or_else(|d| panic!("{label}: {}", d[0]));
    let objects = build_recipe(&recipe, |_| {}).unwrap_or_else(|d| panic!("{label}: {}", d[0]));
    for o in &objects {
        for c in &o.certificates {
            assert!(c.holds, "{label}: {}: {c}", o.name);
        }
    }
    objects.into_iter().map(|o| o.op).collect()
}

#[test]
fn every_op_is_documented() {
    let md = recipes_md();
    let regenerate =
        "regenerate the op section with `rcagd ops --markdown` (or `rcagd ops NAME --markdown`)";
    for op in ops::all() {
        let heading = format!("### `{}`\n", op.name);
        let start = md
            .find(&heading)
            .unwrap_or_else(|| panic!("docs/recipes.md has no section {heading:?}; {regenerate}"));
        let rest = &md[start + heading.len()..];
        let section = &rest[..rest
            .find("\n### ")
            .or_else(|| rest.find("\n## "))
            .unwrap_or(rest.len())];
        for p in op.params {
            let row = format!("| `{}` | {} |", p.name, p.kind.type_name());
            assert!(
                section.contains(&row),
                "{}: parameter row {row:?} missing; {regenerate}",
                op.name
            );
        }
        assert!(
            section.contains(op.example.trim()),
            "{}: the example differs from `rcagd ops {}`; {regenerate}",
            op.name,
            op.name
        );
        // The generated section matches what `rcagd ops --markdown` prints now.
        assert!(
            md.contains(describe::op_markdown(op).trim_end()),
            "{}: section out of date; {regenerate}",
            op.name
        );
    }
}

#[test]
fn every_documented_op_exists() {
    let md = recipes_md();
    for line in md.lines() {
        if let Some(name) = line.strip_prefix("### `").and_then(|l| l.strip_suffix('`')) {
            assert!(
                ops::find(name).is_some(),
                "docs/recipes.md documents unknown op {name}"
            );
        }
    }
}

#[test]
fn every_recipe_in_the_docs_builds() {
    let md = recipes_md();
    let blocks = toml_blocks(&md);
    assert!(
        blocks.len() >= ops::all().count(),
        "expected an example per op"
    );
    // The op sections show each op's example, which `every_op_example_builds` builds
    // (and `every_op_is_documented` checks is the same text): build the others.
    let examples: Vec<&str> = ops::all().map(|op| op.example.trim()).collect();
    for (line, text) in blocks {
        if !examples.contains(&text.trim()) {
            assert_builds_and_holds(&format!("docs/recipes.md (block at line {line})"), &text);
        }
    }
}

/// Every example recipe is embedded in the gallery, byte for byte; the gallery test
/// (`cli::gallery_writes_everything_and_all_certificates_hold`) builds them all through
/// the binary and checks every certificate, so they are not built a second time here.
#[test]
fn every_example_recipe_is_in_the_gallery() {
    let dir = workspace().join("examples/recipes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("examples/recipes")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            matches!(
                p.extension().and_then(|e| e.to_str()),
                Some("toml" | "json")
            )
        })
        .collect();
    files.sort();
    assert!(!files.is_empty());
    for f in files {
        let text = std::fs::read_to_string(&f).expect("read recipe");
        let label = format!(
            "examples/recipes/{}",
            f.file_name().and_then(|n| n.to_str()).unwrap_or("?")
        );
        assert!(
            rcagd_cli::gallery::RECIPES
                .iter()
                .any(|(name, t)| *name == label && *t == text),
            "{label} is not embedded in the gallery (add it to gallery::RECIPES)"
        );
    }
}

/// The examples are built once for this test and `unit::build::every_example_builds_and_holds`
/// (`common::op_examples`).
#[test]
fn every_op_example_builds() {
    let examples = crate::common::op_examples();
    assert_eq!(examples.len(), ops::all().count());
    for ex in examples {
        let label = format!("example of {}", ex.op);
        if let Err(e) = &ex.recipe_ops {
            panic!("{label}: {e}");
        }
        let objects = match &ex.built {
            Some(Ok(objects)) => objects,
            Some(Err(e)) => panic!("{label}: {e}"),
            None => panic!("{label}: not built"),
        };
        for o in objects {
            for c in &o.certificates {
                assert!(c.holds, "{label}: {}: {c}", o.name);
            }
        }
        assert!(
            objects.iter().any(|o| o.op == ex.op),
            "the example of {} does not use it",
            ex.op
        );
    }
}

/// User-facing text names only what a user can see: published sources (author, title,
/// equation) and pages of this repository, never the project's internal seed files or
/// their notes. Checked on the strings of the built binary (messages, certificates, op
/// summaries, the embedded recipes) and on the user documentation.
#[test]
fn user_facing_text_cites_published_sources_only() {
    let forbidden = ["NOTES-", "seed 00", "Seed 00", "seeds/"];
    let bin = std::fs::read(env!("CARGO_BIN_EXE_rcagd")).expect("read the rcagd binary");
    for f in forbidden {
        let hit = bin.windows(f.len()).position(|w| w == f.as_bytes());
        assert!(
            hit.is_none(),
            "the rcagd binary contains {f:?}: {}",
            String::from_utf8_lossy(&bin[hit.unwrap_or(0).saturating_sub(80)..][..200])
        );
    }
    let mut docs = vec![
        workspace().join("README.md"),
        workspace().join("docs/recipes.md"),
    ];
    for e in std::fs::read_dir(workspace().join("examples/recipes")).expect("examples") {
        docs.push(e.expect("entry").path());
    }
    for p in docs {
        let text = std::fs::read_to_string(&p).expect("read doc");
        for (i, line) in text.lines().enumerate() {
            for f in forbidden {
                assert!(
                    !line.contains(f),
                    "{}:{}: cites {f:?}: {line}",
                    p.display(),
                    i + 1
                );
            }
        }
    }
}

/// All `.rs` files below `dir` (recursively), and `.md` files if `md`.
fn source_files(dir: &Path, md: bool, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries {
        let p = e.expect("directory entry").path();
        if p.is_dir() {
            source_files(&p, md, out);
        } else if p
            .extension()
            .is_some_and(|x| x == "rs" || (md && x == "md"))
        {
            out.push(p);
        }
    }
}

/// Doc comments and comments cite the published sources and the pages of docs/math/,
/// never the seed notes (files outside the repository): no file under `crates/*/src`,
/// `crates/*/tests` or `docs/math` contains "NOTES-" or "seed 00x". Every reference
/// `docs/math/PAGE.md, "Section"` or `docs/math/PAGE.md, Errata X` names an existing
/// page, section heading and erratum.
#[test]
fn sources_cite_published_sources_and_docs_math_only() {
    let ws = workspace();
    let mut files = Vec::new();
    for e in std::fs::read_dir(ws.join("crates")).expect("crates/") {
        let krate = e.expect("entry").path();
        source_files(&krate.join("src"), false, &mut files);
        source_files(&krate.join("tests"), false, &mut files);
    }
    source_files(&ws.join("docs/math"), true, &mut files);
    assert!(files.len() > 50, "found only {} files", files.len());
    let mut bad = Vec::new();
    for p in &files {
        let rel = p
            .strip_prefix(&ws)
            .unwrap_or(p)
            .to_string_lossy()
            .replace('\\', "/");
        let rel = rel.trim_start_matches("./").to_string();
        if rel.ends_with("cli/tests/it/docs.rs") {
            continue;
        }
        let text = std::fs::read_to_string(p).expect("read source");
        for (i, line) in text.lines().enumerate() {
            for f in ["NOTES-", "seed 00", "Seed 00", "seeds/"] {
                if line.contains(f) {
                    bad.push(format!("{rel}:{}: cites {f:?}: {}", i + 1, line.trim()));
                }
            }
            let mut rest = line;
            while let Some(k) = rest.find("docs/math/") {
                rest = &rest[k + "docs/math/".len()..];
                let Some(end) = rest.find(".md") else {
                    break;
                };
                let page = &rest[..end + 3];
                let after = &rest[end + 3..];
                let Ok(md) = std::fs::read_to_string(ws.join("docs/math").join(page)) else {
                    bad.push(format!("{rel}:{}: no page docs/math/{page}", i + 1));
                    continue;
                };
                if let Some(t) = after.strip_prefix(", \"") {
                    if let Some(q) = t.find('"') {
                        let title = &t[..q];
                        if !md
                            .lines()
                            .any(|l| l.trim_start_matches('#').trim() == title)
                        {
                            bad.push(format!(
                                "{rel}:{}: docs/math/{page} has no section {title:?}",
                                i + 1
                            ));
                        }
                    }
                } else if let Some(t) = after.strip_prefix(", Errata ") {
                    let id: String = t.chars().take_while(|c| c.is_alphanumeric()).collect();
                    if !md.contains(&format!("**{id}**")) {
                        bad.push(format!(
                            "{rel}:{}: docs/math/{page} has no erratum {id}",
                            i + 1
                        ));
                    }
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
