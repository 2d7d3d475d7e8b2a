//! Limits on the size of the work a recipe can ask for, checked before any construction
//! starts: the recipe's size in bytes, its number of objects, and the digits of an input
//! number (the decimal exponent is limited separately to `±`[`MAX_EXPONENT`]). Each limit has
//! a command-line option of `rcagd build` that raises it; the error names the limit and the
//! option.
//!
//! The limits are process-wide settings (`rcagd build` sets them once from its options),
//! so that the number reader of every op sees them without threading them through the op
//! registry.
//!
//! [`MAX_EXPONENT`]: crate::value::MAX_EXPONENT

use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

/// Default largest recipe, in bytes (16 MiB).
pub const DEFAULT_RECIPE_BYTES: u64 = 16 << 20;
/// Default largest number of objects in one recipe.
pub const DEFAULT_OBJECTS: usize = 10_000;
/// Default largest number of digits of one input number (numerator and denominator
/// together, or the digits of a decimal).
pub const DEFAULT_DIGITS: usize = 10_000;

static RECIPE_BYTES: AtomicU64 = AtomicU64::new(DEFAULT_RECIPE_BYTES);
static OBJECTS: AtomicUsize = AtomicUsize::new(DEFAULT_OBJECTS);
static DIGITS: AtomicUsize = AtomicUsize::new(DEFAULT_DIGITS);

/// The limits of one run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Largest recipe in bytes (`--max-recipe-bytes`).
    pub recipe_bytes: u64,
    /// Largest number of objects (`--max-objects`).
    pub objects: usize,
    /// Largest number of digits of an input number (`--max-digits`).
    pub digits: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            recipe_bytes: DEFAULT_RECIPE_BYTES,
            objects: DEFAULT_OBJECTS,
            digits: DEFAULT_DIGITS,
        }
    }
}

impl Limits {
    /// Makes these limits the process-wide ones.
    pub fn install(&self) {
        RECIPE_BYTES.store(self.recipe_bytes, Ordering::Relaxed);
        OBJECTS.store(self.objects, Ordering::Relaxed);
        DIGITS.store(self.digits, Ordering::Relaxed);
    }

    /// The process-wide limits.
    pub fn current() -> Self {
        Limits {
            recipe_bytes: RECIPE_BYTES.load(Ordering::Relaxed),
            objects: OBJECTS.load(Ordering::Relaxed),
            digits: DIGITS.load(Ordering::Relaxed),
        }
    }
}

/// The number of decimal (or other radix) digits in a number's text: every ASCII digit
/// and hexadecimal letter before an exponent mark, in numerator and denominator.
pub fn digit_count(text: &str) -> usize {
    text.split('/')
        .map(|part| {
            let lower = part.trim().to_ascii_lowercase();
            let hex =
                lower.starts_with("0x") || lower.starts_with("-0x") || lower.starts_with("+0x");
            let mantissa = if hex {
                lower.as_str()
            } else {
                lower.split('e').next().unwrap_or("")
            };
            mantissa
                .chars()
                .filter(|c| c.is_ascii_digit() || (hex && c.is_ascii_hexdigit()))
                .count()
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn digits_are_counted_without_exponent_sign_or_separators() {
        assert_eq!(digit_count("123"), 3);
        assert_eq!(digit_count("-1_000"), 4);
        assert_eq!(digit_count("3/7"), 2);
        assert_eq!(digit_count("-2.5e-300"), 2);
        assert_eq!(digit_count("0x1F"), 3);
        assert_eq!(digit_count("1.5/20"), 4);
    }
}
