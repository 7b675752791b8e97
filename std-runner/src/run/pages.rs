//! Transparent huge pages for the particle array: at large n every candidate pair touches two
//! random particles, and with 4 KiB pages nearly every touch also misses the TLB. Linux backs a
//! range with 2 MiB pages when asked (`madvise(MADV_HUGEPAGE)`, the only way where transparent
//! huge pages are set to `madvise`, as on the development machine); elsewhere, or when the
//! kernel refuses, nothing changes. The advice changes how memory is backed, never its
//! contents, so results are the same bits either way.

/// Below this many bytes the advice is not worth a system call (half a huge page).
const WORTH: usize = 1 << 20;

/// Asks the kernel to back the memory of `buf` (typically a vector's spare capacity, before it
/// is first written) with huge pages. Returns whether the advice was taken.
pub fn advise_huge<T>(buf: &mut [T]) -> bool {
    let bytes = std::mem::size_of_val(buf);
    if bytes < WORTH {
        return false;
    }
    advise(buf.as_mut_ptr() as usize, bytes)
}

#[cfg(target_os = "linux")]
#[allow(unsafe_code)]
fn advise(start: usize, bytes: usize) -> bool {
    // madvise wants a page-aligned start; the range is shrunk to the whole pages inside.
    let page = 4096;
    let begin = start.next_multiple_of(page);
    let end = (start + bytes) / page * page;
    if end <= begin {
        return false;
    }
    // SAFETY: the range lies inside `buf`, memory this process owns for the whole call;
    // MADV_HUGEPAGE only tells the kernel how to back those pages (it never frees, moves or
    // changes their contents), so no reference into `buf` can be invalidated by it.
    unsafe {
        rustix::mm::madvise(
            begin as *mut core::ffi::c_void,
            end - begin,
            rustix::mm::Advice::LinuxHugepage,
        )
        .is_ok()
    }
}

#[cfg(not(target_os = "linux"))]
fn advise(_start: usize, _bytes: usize) -> bool {
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_buffers_are_left_alone_and_large_ones_keep_their_contents() {
        let mut small = vec![1u8; 1000];
        assert!(!advise_huge(&mut small));
        let mut big: Vec<u64> = (0..(4 << 20) / 8).collect();
        advise_huge(&mut big); // taken or not, the contents stay
        assert!(big.iter().enumerate().all(|(i, &x)| x == i as u64));
    }
}
