//! Criterion benchmarks of `gdsmc-core`'s hot loops: the no-splitting event loop, the batch
//! kick (SIMD against its scalar twin), the moment sums and the samplers. The benchmarks are in
//! `benches/engine.rs` (`cargo bench -p gdsmc-bench`); this library is empty, a crate of its own
//! only so that the test build never compiles criterion.
#![no_std]
