//! GATHAN (GATHAN1, GATHANG): paper numbers only, no implementation.
//!
//! \[DW01\] T. K. Dey, R. Wenger, *Reconstructing curves with sharp corners*, Computational
//! Geometry: Theory and Applications, 2001. \[DW02\] T. K. Dey, R. Wenger, *Fast
//! reconstruction of curves with sharp corners*, International Journal of Computational
//! Geometry and Applications, 2002.
//!
//! # What is known
//! - [MOW22] §2 summarises GATHANG as filtering Delaunay edges "using the angle and the ratio
//!   between edge lengths", specialised for curves with sharp corners.
//! - The benchmark [OPP21] runs two variants, GATHAN1 and GATHANG, with clearly different
//!   results ([MOW22] Table 2: manifold 62.4 % / 63.2 %, sharp 44.6 % / 80.8 %, open 13.0 % /
//!   21.7 %, multiple 24.0 % / 35.1 %, ε < 1 65.3 % / 65.7 %; 0.3 ms / 1.9 ms per set).
//!
//! # Why there is no function here
//! Neither paper's text, nor the authors' program (distributed by Ohio State as part of Dey's
//! curve-reconstruction software), nor the benchmark's wrapper could be found in the sources
//! available to us (searched: documentation, web pages, public code; see the project's
//! research notes). Without them the per-sample angle test, the length-ratio test, their
//! thresholds, how corner samples are completed, and what separates GATHAN1 from GATHANG
//! cannot be stated reliably, and a guessed rule would not be GATHAN. Comparisons therefore
//! quote the paper's numbers above.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
//! [OPP21]: https://arxiv.org/abs/2103.09583
