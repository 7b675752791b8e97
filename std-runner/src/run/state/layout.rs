//! Where a state file's bytes are, by format version (docs/state.md, "The format").
//!
//! Version 2 (written): the 16 bytes [`MAGIC`], a header of [`HEADER_BYTES`] bytes (one JSON
//! object padded with spaces), the header's checksum (8 bytes: the CRC-32 of the magic and the
//! header as a little-endian u64), then one record per ensemble: its payload (collisions per
//! particle, velocities, rim velocities: little-endian f64s) and the record's checksum (8
//! bytes: the CRC-32 of the ensemble's index as a little-endian u64 followed by the payload,
//! so a record moved to another place no longer verifies).
//!
//! Version 1 (read, with a warning): the magic `GDSMC-STATE\0v001`, the same header, no
//! checksums, the payloads one after another.

/// The first bytes of every state file this gdsmc writes: the name and the format's version.
pub const MAGIC: &[u8; 16] = b"GDSMC-STATE\0v002";

/// The magic of the first format (read, unchecked bytes: a warning says so).
pub const MAGIC_V1: &[u8; 16] = b"GDSMC-STATE\0v001";

/// The format version this gdsmc writes.
pub const VERSION: u32 = 2;

/// The header's fixed size in bytes (its JSON padded with spaces).
pub const HEADER_BYTES: usize = 4096;

/// Bytes of a checksum (a CRC-32 stored as a little-endian u64, its high half zero).
pub const SUM_BYTES: usize = 8;

/// The layout of one version's file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// The format version (1 or 2).
    pub version: u32,
}

impl Layout {
    /// The layout of format `version`, if this gdsmc reads it.
    pub fn of(version: u32) -> Option<Self> {
        matches!(version, 1 | 2).then_some(Layout { version })
    }

    /// The layout a file starting with `magic` has, if this gdsmc reads it.
    pub fn of_magic(magic: &[u8]) -> Option<Self> {
        match magic {
            m if m == MAGIC => Self::of(2),
            m if m == MAGIC_V1 => Self::of(1),
            _ => None,
        }
    }

    /// Whether the file holds checksums (version 2 on).
    pub fn summed(self) -> bool {
        self.version >= 2
    }

    /// Bytes of a checksum in this layout (0 without checksums).
    fn sum_bytes(self) -> u64 {
        if self.summed() { SUM_BYTES as u64 } else { 0 }
    }

    /// Where the first record starts.
    pub fn data_start(self) -> u64 {
        (MAGIC.len() + HEADER_BYTES) as u64 + self.sum_bytes()
    }

    /// A record's size in bytes for `payload` bytes of values, `None` when it overflows.
    pub fn record_bytes(self, payload: u64) -> Option<u64> {
        payload.checked_add(self.sum_bytes())
    }

    /// The file's size for `ensembles` records of `payload` bytes, `None` when it overflows
    /// (a forged header).
    pub fn file_bytes(self, ensembles: u64, payload: u64) -> Option<u64> {
        ensembles
            .checked_mul(self.record_bytes(payload)?)?
            .checked_add(self.data_start())
    }

    /// Where record `k` of `payload` bytes starts (`k` below the record count: no overflow
    /// once [`Layout::file_bytes`] held).
    pub fn record_at(self, k: u64, payload: u64) -> u64 {
        self.data_start() + k * (payload + self.sum_bytes())
    }
}

/// The checksum of the magic and header bytes `head`, as stored.
pub fn header_sum(head: &[u8]) -> [u8; SUM_BYTES] {
    u64::from(crc32fast::hash(head)).to_le_bytes()
}

/// The checksum of record `k`'s payload `payload`, as stored.
pub fn record_sum(k: u64, payload: &[u8]) -> [u8; SUM_BYTES] {
    let mut h = crc32fast::Hasher::new();
    h.update(&k.to_le_bytes());
    h.update(payload);
    u64::from(h.finalize()).to_le_bytes()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_layouts_place_records_after_the_header_and_its_sum() {
        let (v1, v2) = (Layout::of(1).unwrap(), Layout::of(2).unwrap());
        assert_eq!(v1.data_start(), 16 + 4096);
        assert_eq!(v2.data_start(), 16 + 4096 + 8);
        assert_eq!(v2.record_at(3, 40), 16 + 4096 + 8 + 3 * 48);
        assert_eq!(v1.record_at(3, 40), 16 + 4096 + 3 * 40);
        assert_eq!(Layout::of_magic(MAGIC), Some(v2));
        assert_eq!(Layout::of_magic(MAGIC_V1), Some(v1));
        assert_eq!(Layout::of_magic(b"GDSMC-STATE\0v003"), None);
        assert_eq!(Layout::of(3), None);
        // A forged size overflows to None, never wraps.
        assert_eq!(v2.file_bytes(u64::MAX, 40), None);
        assert_eq!(v2.file_bytes(2, u64::MAX), None);
    }

    #[test]
    fn a_record_sum_binds_its_place() {
        let p = [1u8, 2, 3];
        assert_ne!(record_sum(0, &p), record_sum(1, &p));
        assert_ne!(record_sum(0, &p), record_sum(0, &[1, 2, 4]));
        assert_eq!(record_sum(0, &p)[4..], [0; 4]);
    }
}
