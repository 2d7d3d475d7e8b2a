#[path = "../generic/add.rs"]
pub(crate) mod add;

#[path = "../generic/digits.rs"]
pub(crate) mod digits;

pub(crate) mod ntt;
pub(crate) mod word;
