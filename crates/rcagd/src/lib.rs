//! rcagd rcagd (to be filled)
