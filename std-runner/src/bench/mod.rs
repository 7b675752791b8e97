//! `gdsmc bench`: throughput of the hot loops beside the machine's limits, work against
//! precision of the schemes, and the scaling of ensembles with threads.

mod command;
pub mod line;
pub mod scaling;
pub mod throughput;
pub mod work_precision;

pub use command::{WorkPrecision, work_precision};
