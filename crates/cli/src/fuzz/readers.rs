//! Adversarial variants of the STEP and IGES files the exporters write, for the readers
//! (`rcagd_io::step_read::read_step`, `rcagd_io::iges_read::read_iges`): truncated,
//! garbled (bytes replaced, lines dropped or repeated), and adversarial (references to
//! missing or to their own entity, huge counts and numbers, negative indices).

use super::gen::Rng;

/// The file kinds a reader accepts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    /// ISO 10303-21.
    Step,
    /// IGES 5.3.
    Iges,
}

impl FileKind {
    /// The file extension of corpus files.
    pub fn extension(self) -> &'static str {
        match self {
            FileKind::Step => "step",
            FileKind::Iges => "igs",
        }
    }

    /// Runs the reader; `Ok(n)` objects read or `Err(message)`.
    ///
    /// # Errors
    /// The reader's message.
    pub fn read(self, text: &str) -> Result<usize, String> {
        match self {
            FileKind::Step => rcagd_io::step_read::read_step(text)
                .map(|v| v.len())
                .map_err(|e| e.to_string()),
            FileKind::Iges => rcagd_io::iges_read::read_iges(text)
                .map(|v| v.len())
                .map_err(|e| e.to_string()),
        }
    }
}

fn char_boundary(s: &str, mut i: usize) -> usize {
    i = i.min(s.len());
    while !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// Replaces the `k`-th occurrence (mod count) of a pattern-matching token.
fn replace_nth_number(text: &str, rng: &mut Rng, with: &str) -> String {
    let bytes = text.as_bytes();
    let starts: Vec<usize> = (0..bytes.len())
        .filter(|&i| bytes[i].is_ascii_digit() && (i == 0 || !bytes[i - 1].is_ascii_alphanumeric()))
        .collect();
    let Some(&s) = rng.pick(&starts) else {
        return text.to_string();
    };
    let mut e = s;
    while e < bytes.len()
        && (bytes[e].is_ascii_digit()
            || bytes[e] == b'.'
            || bytes[e] == b'E'
            || bytes[e] == b'D'
            || bytes[e] == b'-' && e > s && (bytes[e - 1] == b'E' || bytes[e - 1] == b'D'))
    {
        e += 1;
    }
    format!("{}{}{}", &text[..s], with, &text[e..])
}

/// One adversarial variant of `text` and what was done.
pub fn variant(kind: FileKind, text: &str, rng: &mut Rng) -> (String, String) {
    let lines: Vec<&str> = text.lines().collect();
    match rng.below(10) {
        0 => {
            let at = char_boundary(text, rng.below(text.len() + 1));
            (text[..at].to_string(), format!("truncated at byte {at}"))
        }
        1 => {
            let mut b: Vec<u8> = text.as_bytes().to_vec();
            let flips = rng.range(1, 8);
            for _ in 0..flips {
                let i = rng.below(b.len());
                if let Some(x) = b.get_mut(i) {
                    *x = *rng.pick(b"#=(),;'.0123456789-E \nSDPG$/*").unwrap_or(&b'#');
                }
            }
            (
                String::from_utf8_lossy(&b).into_owned(),
                format!("{flips} bytes replaced"),
            )
        }
        2 if !lines.is_empty() => {
            let i = rng.below(lines.len());
            let mut l = lines.clone();
            l.remove(i);
            (l.join("\n") + "\n", format!("line {} dropped", i + 1))
        }
        3 if !lines.is_empty() => {
            let i = rng.below(lines.len());
            let mut l = lines.clone();
            let x = l[i];
            for _ in 0..rng.range(1, 4) {
                l.insert(i, x);
            }
            (l.join("\n") + "\n", format!("line {} repeated", i + 1))
        }
        4 => {
            let with = rng
                .pick(&[
                    "0",
                    "-1",
                    "99999999",
                    "18446744073709551616",
                    "1.0E308",
                    "1.0E309",
                    "-0.",
                    "3",
                    "1.0D400",
                    "00000000",
                ])
                .unwrap_or(&"0")
                .to_string();
            (
                replace_nth_number(text, rng, &with),
                format!("a number replaced by {with}"),
            )
        }
        5 => match kind {
            FileKind::Step => {
                // a reference to a missing entity, or an entity referring to itself
                let refs: Vec<usize> = text.match_indices('#').map(|(i, _)| i).collect();
                match rng.pick(&refs) {
                    Some(&i) => {
                        let with = rng
                            .pick(&["#999999", "#0", "#1", "#-3", "#"])
                            .unwrap_or(&"#1")
                            .to_string();
                        let mut e = i + 1;
                        while e < text.len() && text.as_bytes()[e].is_ascii_digit() {
                            e += 1;
                        }
                        (
                            format!("{}{}{}", &text[..i], with, &text[e..]),
                            format!("a reference replaced by {with}"),
                        )
                    }
                    None => (text.to_string(), "unchanged".into()),
                }
            }
            FileKind::Iges => {
                // a directory pointer field made huge, zero or odd
                let with = rng
                    .pick(&["9999999", "0", "2", "-1"])
                    .unwrap_or(&"0")
                    .to_string();
                (
                    replace_nth_number(text, rng, &with),
                    format!("a pointer replaced by {with}"),
                )
            }
        },
        6 => {
            // the data section repeated (many entities), bounded
            let n = rng.range(2, 4) as usize;
            (text.repeat(n), format!("the whole file repeated {n} times"))
        }
        7 => {
            // deep nesting inside one record
            let depth = rng.range(50, 3000) as usize;
            let at = char_boundary(text, rng.below(text.len() + 1));
            let nest = format!("{}{}", "(".repeat(depth), ")".repeat(depth));
            (
                format!("{}{}{}", &text[..at], nest, &text[at..]),
                format!("{depth} nested parentheses inserted"),
            )
        }
        8 if !lines.is_empty() => {
            // two lines swapped
            let (i, j) = (rng.below(lines.len()), rng.below(lines.len()));
            let mut l = lines.clone();
            l.swap(i, j);
            (
                l.join("\n") + "\n",
                format!("lines {} and {} swapped", i + 1, j + 1),
            )
        }
        _ => {
            let junk = rng
                .pick(&[
                    "",
                    "\0\0\0",
                    "ISO-10303-21;\nENDSEC;",
                    "S      1\n",
                    "\u{feff}",
                    "#1=#1;",
                    "'unterminated",
                ])
                .unwrap_or(&"")
                .to_string();
            let at = char_boundary(text, rng.below(text.len() + 1));
            (
                format!("{}{}{}", &text[..at], junk, &text[at..]),
                format!("{junk:?} inserted"),
            )
        }
    }
}
