pub(crate) mod add;

#[path = "../generic/digits.rs"]
pub(crate) mod digits;

#[path = "../generic_32_bit/ntt.rs"]
pub(crate) mod ntt;

#[path = "../generic_32_bit/word.rs"]
pub(crate) mod word;
