//! Special functions, quadrature and root finding: pure f64 code, no I/O.
