//! What a loop reports beyond the whole gas's moments ([`crate::moments`]): a rough gas's
//! rotational observables and a mixture's per species. They sit below the event loops, which
//! report them ([`crate::engine::EventLoop::rough`], [`crate::engine::EventLoop::species`]),
//! and below the rough and mixture modules that build on the loops.

pub mod cooling;
pub mod rotation;
pub mod species;

pub use cooling::Cooling;
pub use rotation::RoughObservables;
pub use species::MixtureObservables;
