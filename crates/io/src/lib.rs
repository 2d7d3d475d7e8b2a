//! rcagd io (to be filled)
