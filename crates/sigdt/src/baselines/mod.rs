//! The reconstruction methods SIG-CONNECT2D is measured against, one module per paper.

pub mod connect2d;
