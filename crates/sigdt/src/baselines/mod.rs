//! The reconstruction methods SIG-CONNECT2D is measured against, one module per paper.

pub mod connect2d;
pub mod crawl;
pub mod crust;
pub mod gathan;
pub mod hnn_crust;
pub mod nn_crust;
pub mod peel;
