//! The state reader (`--initial-state`, Python's `read_state`; docs/state.md "The checks") on
//! any bytes: a refusal naming the file, or a state whose header is within its bounds and whose
//! every record is a set of finite, bounded velocities, never a panic or a hang. And on a valid
//! file changed in one byte anywhere: always a refusal (CRC-32 detects every error confined to
//! 32 consecutive bits), so a flipped bit never runs silently to another result.

use gdsmc_runner::run::state::StateReader;
use gdsmc_runner::run::state::checks::{MAX_COMPONENT, MAX_SEGMENT};
use std::path::PathBuf;

/// Valid files of format 2 (the corpus's seeds, made by `gdsmc run ... --save-state`): a
/// smooth gas, a rough gas, a mixture.
const VALID: [&[u8]; 3] = [
    include_bytes!("../../corpus/state_reader/smooth-v2"),
    include_bytes!("../../corpus/state_reader/rough-v2"),
    include_bytes!("../../corpus/state_reader/mixture-v2"),
];

/// The first byte that selects the one-byte change of a valid file.
const CHANGE: u8 = b'~';

/// A scratch file of this process and thread for the bytes under test.
fn scratch() -> PathBuf {
    std::env::temp_dir().join(format!(
        "gdsmc-fuzz-state-{}-{:?}.state",
        std::process::id(),
        std::thread::current().id()
    ))
}

/// Fuzz target `state_reader`: `data` as a state file; or, when it starts with `~`, a valid
/// file (`data[1]` picks which) with the byte at offset `data[2..6]` (modulo its length)
/// XORed with `data[6]` (made nonzero), which must be refused.
pub fn state_reader(data: &[u8]) {
    let path = scratch();
    let changed = data.first() == Some(&CHANGE) && data.len() >= 7;
    if changed {
        let mut bytes = VALID[data[1] as usize % VALID.len()].to_vec();
        let at = u32::from_le_bytes(data[2..6].try_into().expect("4 bytes")) as usize % bytes.len();
        bytes[at] ^= data[6].max(1);
        std::fs::write(&path, &bytes).expect("a scratch file");
    } else {
        std::fs::write(&path, data).expect("a scratch file");
    }
    let read = StateReader::open(&path);
    let name = path.file_name().unwrap().to_string_lossy().into_owned();
    match read {
        Err(e) => {
            let m = e.to_string();
            assert!(m.contains(&name), "the refusal names no file: {m}");
            assert!(m.len() < 2000, "a refusal of {} bytes", m.len());
        }
        Ok(r) => {
            assert!(!changed, "a valid file changed in one byte was accepted");
            let h = &r.header;
            assert!(h.segment <= MAX_SEGMENT && h.time.is_finite() && h.time >= 0.0);
            assert!(matches!(h.dimension, 2 | 3) && h.n > 0 && h.ensembles > 0);
            for k in 0..h.ensembles {
                let x = r.record(k).expect("an accepted file's records read");
                assert!(x[0].is_finite() && x[0] >= 0.0);
                assert!(
                    x[1..]
                        .iter()
                        .all(|v| v.is_finite() && v.abs() <= MAX_COMPONENT)
                );
            }
        }
    }
    let _ = std::fs::remove_file(&path);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The seeds are valid, and every one-byte change of each, at every offset, is refused
    /// (the property the fuzzer samples, here exhaustive over offsets for one XOR value).
    #[test]
    fn every_one_byte_change_of_a_valid_file_is_refused() {
        let path = scratch();
        for valid in VALID {
            std::fs::write(&path, valid).unwrap();
            assert!(StateReader::open(&path).is_ok());
            for at in 0..valid.len() {
                let mut b = valid.to_vec();
                b[at] ^= 0x10;
                std::fs::write(&path, &b).unwrap();
                assert!(
                    StateReader::open(&path).is_err(),
                    "byte {at} changed was accepted"
                );
            }
        }
        let _ = std::fs::remove_file(&path);
    }
}
