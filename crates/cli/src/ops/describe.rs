//! `rcagd ops`: the op reference, as plain text (terminal) or Markdown (the op section
//! of `docs/recipes.md` is generated with `rcagd ops --markdown`).

use super::OpSpec;
use crate::source::closest;
use crate::{EXIT_INPUT, EXIT_OK};
use std::fmt::Write as _;

/// Runs `rcagd ops [NAME] [--markdown]`; returns the exit code.
pub fn run(name: Option<&str>, markdown: bool) -> u8 {
    match name {
        None if markdown => out!("{}", self::markdown()),
        None => out!("{}", list_text()),
        Some(n) => match super::find(n) {
            Some(op) if markdown => out!("{}", op_markdown(op)),
            Some(op) => out!("{}", op_text(op)),
            None => {
                errln!("error: unknown op {n:?}");
                if let Some(s) = closest(n, super::all().map(|o| o.name)) {
                    errln!("  = did you mean {s:?}?");
                }
                let names: Vec<&str> = super::all().map(|o| o.name).collect();
                errln!("  = known ops: {}", names.join(", "));
                return EXIT_INPUT;
            }
        },
    }
    EXIT_OK
}

/// The list of all ops: one line each plus one line per parameter.
pub fn list_text() -> String {
    let mut s = String::new();
    for (topic, ops) in super::TOPICS {
        let _ = writeln!(s, "{topic}:");
        for op in *ops {
            let _ = writeln!(s, "  {:<16} {}", op.name, op.summary);
            for l in op.param_lines() {
                let _ = writeln!(s, "      {l}");
            }
        }
        s.push('\n');
    }
    s.push_str("`rcagd ops NAME` shows one op with an example recipe.\n");
    s
}

/// One op in detail, with its example.
pub fn op_text(op: &OpSpec) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{} — {}\n", op.name, op.summary);
    let _ = writeln!(s, "parameters (besides `name` and `op`):");
    if op.params.is_empty() {
        let _ = writeln!(s, "  none");
    }
    for p in op.params {
        let _ = writeln!(
            s,
            "  {:<12} {} ({})\n  {:<12} {}",
            p.name,
            p.kind.type_name(),
            p.requirement(),
            "",
            p.doc
        );
    }
    let limits = op.limit_lines();
    if !limits.is_empty() {
        let _ = writeln!(
            s,
            "\nlimits (checked before building; `rcagd build` options raise them):"
        );
        for l in limits {
            let _ = writeln!(s, "  {l}");
        }
    }
    let _ = writeln!(s, "\n{}", crate::float::describe(op.name));
    let _ = writeln!(s, "\nexample:\n");
    for l in op.example.lines() {
        let _ = writeln!(s, "    {l}");
    }
    s
}

/// The Markdown reference of one op: a `### \`name\`` heading, the summary, a
/// parameter table and the example recipe.
pub fn op_markdown(op: &OpSpec) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "### `{}`\n", op.name);
    let _ = writeln!(s, "{}.\n", capitalize(op.summary));
    if op.params.is_empty() {
        let _ = writeln!(s, "No parameters besides `name` and `op`.\n");
    } else {
        let _ = writeln!(s, "| parameter | type | required / default | meaning |");
        let _ = writeln!(s, "|---|---|---|---|");
        for p in op.params {
            let _ = writeln!(
                s,
                "| `{}` | {} | {} | {} |",
                p.name,
                p.kind.type_name().replace('|', "\\|"),
                match (p.required, p.default) {
                    (true, _) => "required".to_string(),
                    (false, Some(d)) => format!("`{d}`"),
                    (false, None) => "optional".to_string(),
                },
                p.doc.replace('|', "\\|")
            );
        }
        s.push('\n');
    }
    let limits = op.limit_lines();
    if !limits.is_empty() {
        let _ = writeln!(
            s,
            "Limits (`rcagd build` options raise them): {}.\n",
            limits.join("; ")
        );
    }
    let _ = writeln!(s, "{}\n", crate::float::describe_markdown(op.name));
    let _ = writeln!(s, "```toml\n{}```\n", op.example);
    s
}

/// The Markdown reference of every op, grouped by topic.
pub fn markdown() -> String {
    let mut s = String::new();
    for (topic, ops) in super::TOPICS.iter().filter(|(_, ops)| !ops.is_empty()) {
        let _ = writeln!(s, "## Ops: {topic}\n");
        for op in *ops {
            s.push_str(&op_markdown(op));
        }
    }
    s
}

fn capitalize(s: &str) -> String {
    let mut c = s.chars();
    match c.next() {
        Some(f) => f.to_uppercase().chain(c).collect(),
        None => String::new(),
    }
}
