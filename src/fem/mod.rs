//! Finite-element core (beams, springs, rigid links, sparse Cholesky).
