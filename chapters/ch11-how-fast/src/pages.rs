//! Step 13: the walk's memory in 2 MB pages. Every address a program
//! reads is translated to a physical one through the CPU's TLB, a cache
//! of translations with a few thousand entries (3 072 on Zen 4, 2 048 on
//! recent Xeons). In 4 KB pages that covers 8–12 MB; the big bunny's
//! nodes and blocks are 15 MB, read all over, so many of an incoherent
//! ray's loads first wait on a page-table walk (in a virtual machine, a
//! walk through two page tables). In 2 MB pages eight translations cover
//! them all.
//!
//! Linux gives a program 2 MB pages ("transparent huge pages") where it
//! asks for them with `madvise(MADV_HUGEPAGE)` before first touching the
//! memory, unless they are switched off for the whole system
//! (`/sys/kernel/mm/transparent_hugepage/enabled` says `never`): then the
//! memory is plain 4 KB pages, and the walk the same as step 12's.
//!
//! [`Pages`] holds a step's nodes or blocks: in memory asked for in 2 MB
//! pages ([`Pages::huge`], Linux only), or on the heap as a `Vec` (every
//! other step, and any system where the mapping fails).
use std::fmt;
use std::ops::{Deref, DerefMut};

/// The size of a huge page on x86-64 (and of the alignment it needs).
pub const HUGE_PAGE: usize = 2 << 20;

/// An array of `T` on the heap, or in its own mapping asked for in 2 MB
/// pages; read as a slice either way.
pub struct Pages<T: Copy> {
    storage: Storage<T>,
}

enum Storage<T> {
    Heap(Vec<T>),
    /// `len` values at `data`, the start of a 2 MB page inside a mapping
    /// of `bytes` bytes at `base` (unmapped when dropped).
    #[cfg(target_os = "linux")]
    Mapped {
        base: *mut libc::c_void,
        bytes: usize,
        data: *mut T,
        len: usize,
    },
}

// SAFETY: a mapping is owned by its `Pages` alone, as a `Vec`'s buffer
// is; sharing or sending it is sharing or sending the `T`s.
unsafe impl<T: Copy + Send> Send for Pages<T> {}
// SAFETY: as above; `&Pages` gives only `&[T]`.
unsafe impl<T: Copy + Sync> Sync for Pages<T> {}

impl<T: Copy> From<Vec<T>> for Pages<T> {
    fn from(values: Vec<T>) -> Self {
        Pages {
            storage: Storage::Heap(values),
        }
    }
}

// ANCHOR: huge
impl<T: Copy> Pages<T> {
    /// A copy of `values` in a mapping of its own, asked for in 2 MB
    /// pages before it is written (on the heap where that fails, or off
    /// Linux).
    pub fn huge(values: &[T]) -> Pages<T> {
        #[cfg(target_os = "linux")]
        if let Some(pages) = Pages::mapped(values) {
            return pages;
        }
        Pages::from(values.to_vec())
    }

    #[cfg(target_os = "linux")]
    fn mapped(values: &[T]) -> Option<Pages<T>> {
        if values.is_empty() || align_of::<T>() > HUGE_PAGE {
            return None;
        }
        // Step 1: whole 2 MB pages for the values, and one more page so
        // that the first can start on a 2 MB boundary.
        let used = size_of_val(values).next_multiple_of(HUGE_PAGE);
        let bytes = used + HUGE_PAGE;
        // SAFETY: a new private anonymous mapping; no memory of ours is
        // named.
        let base = unsafe {
            libc::mmap(
                std::ptr::null_mut(),
                bytes,
                libc::PROT_READ | libc::PROT_WRITE,
                libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
                -1,
                0,
            )
        };
        if base == libc::MAP_FAILED {
            return None;
        }
        let start = (base as usize).next_multiple_of(HUGE_PAGE);
        let data = start as *mut T;
        // Step 2: ask for 2 MB pages before any is touched (after, the
        // kernel would only merge them later, in the background). A
        // refusal is no error: the pages are then 4 KB ones.
        // SAFETY: [start, start + used) lies within the mapping.
        unsafe { libc::madvise(data.cast(), used, libc::MADV_HUGEPAGE) };
        // Step 3: the values copied in: the first touch of each page.
        // SAFETY: the mapping is writable, `start` aligned for `T` (a
        // 2 MB boundary), `used` bytes hold the values, and a new mapping
        // overlaps nothing.
        unsafe {
            std::ptr::copy_nonoverlapping(values.as_ptr(), data, values.len())
        };
        Some(Pages {
            storage: Storage::Mapped {
                base,
                bytes,
                data,
                len: values.len(),
            },
        })
    }

    /// Are they in a mapping of their own (asked for in 2 MB pages)?
    pub fn is_mapped(&self) -> bool {
        !matches!(self.storage, Storage::Heap(_))
    }
}
// ANCHOR_END: huge

impl<T: Copy> Deref for Pages<T> {
    type Target = [T];

    #[inline(always)]
    fn deref(&self) -> &[T] {
        match &self.storage {
            Storage::Heap(values) => values,
            // SAFETY: `len` values written at `data`, alive as long as
            // the mapping, which `self` owns.
            #[cfg(target_os = "linux")]
            Storage::Mapped { data, len, .. } => unsafe {
                std::slice::from_raw_parts(*data, *len)
            },
        }
    }
}

impl<T: Copy> DerefMut for Pages<T> {
    fn deref_mut(&mut self) -> &mut [T] {
        match &mut self.storage {
            Storage::Heap(values) => values,
            // SAFETY: as in `deref`, and `&mut self` is the only access.
            #[cfg(target_os = "linux")]
            Storage::Mapped { data, len, .. } => unsafe {
                std::slice::from_raw_parts_mut(*data, *len)
            },
        }
    }
}

impl<T: Copy> Drop for Pages<T> {
    fn drop(&mut self) {
        #[cfg(target_os = "linux")]
        if let Storage::Mapped { base, bytes, .. } = self.storage {
            // SAFETY: the mapping `mapped` made, unmapped once; `T` is
            // `Copy`, so nothing in it needs dropping.
            unsafe { libc::munmap(base, bytes) };
        }
    }
}

impl<T: Copy> Clone for Pages<T> {
    /// A copy stored as this one is (mapped or on the heap).
    fn clone(&self) -> Self {
        if self.is_mapped() {
            Pages::huge(self)
        } else {
            Pages::from(self.to_vec())
        }
    }
}

impl<T: Copy + PartialEq> PartialEq for Pages<T> {
    /// The same values, wherever they are stored.
    fn eq(&self, other: &Self) -> bool {
        **self == **other
    }
}

impl<T: Copy + fmt::Debug> fmt::Debug for Pages<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&**self, f)
    }
}

#[cfg(test)]
mod tests {
    use super::{HUGE_PAGE, Pages};

    /// The kilobytes in 2 MB pages of the mapping holding `address`, as
    /// `/proc/self/smaps` reports them (Linux).
    fn huge_kb(address: usize) -> u64 {
        let smaps = std::fs::read_to_string("/proc/self/smaps").unwrap();
        let mut within = false;
        for line in smaps.lines() {
            // A mapping's first line starts with its range, "lo-hi ".
            let range = line.split(' ').next().and_then(|r| r.split_once('-'));
            let bounds = range.and_then(|(lo, hi)| {
                let hex = |x| usize::from_str_radix(x, 16).ok();
                Some((hex(lo)?, hex(hi)?))
            });
            if let Some((lo, hi)) = bounds {
                within = (lo..hi).contains(&address);
            } else if within
                && let Some(kb) = line.strip_prefix("AnonHugePages:")
            {
                let kb = kb.trim().trim_end_matches("kB").trim();
                return kb.parse().unwrap();
            }
        }
        0
    }

    /// Mapped, the values read back the same, from a 2 MB boundary, and
    /// a clone is mapped too; from a `Vec`, on the heap.
    #[test]
    fn huge_pages_hold_the_values_from_a_boundary() {
        let values: Vec<[u32; 5]> =
            (0..300_000u32).map(|i| [i, i ^ 7, 3 * i, 1, 0]).collect();
        let pages = Pages::huge(&values);
        assert_eq!(&*pages, values.as_slice());
        if cfg!(target_os = "linux") {
            assert!(pages.is_mapped());
            assert_eq!(pages.as_ptr() as usize % HUGE_PAGE, 0);
            // Unless the system has them switched off, the kernel gave
            // 2 MB pages (the values take three).
            let setting = "/sys/kernel/mm/transparent_hugepage/enabled";
            let setting = std::fs::read_to_string(setting).unwrap_or_default();
            if setting.contains("[always]") || setting.contains("[madvise]") {
                let huge = huge_kb(pages.as_ptr() as usize);
                assert!(huge >= 2048, "{huge} kB in 2 MB pages ({setting})");
            }
        }
        let copy = pages.clone();
        assert_eq!(copy.is_mapped(), pages.is_mapped());
        assert_eq!(copy, pages);
        let heap = Pages::from(values.clone());
        assert!(!heap.is_mapped());
        assert_eq!(heap, pages);
        assert!(Pages::<u8>::huge(&[]).is_empty());
    }
}
