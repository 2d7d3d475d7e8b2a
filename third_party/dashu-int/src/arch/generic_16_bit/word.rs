/// Machine word.
pub type Word = u16;

/// Signed machine word.
pub type SignedWord = i16;

/// Double machine word.
pub type DoubleWord = u32;

/// Signed double machine word.
pub type SignedDoubleWord = i32;
