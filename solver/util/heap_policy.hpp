#pragma once
/// @file heap_policy.hpp
/// @brief How the C library's allocator treats the large blocks of a run (process-wide).
///
/// A model of 1e6 DOFs touches 300-400 MB of new memory before its first step, and the first
/// touch of each 4 kB page is a page fault (1-4 us on a virtual machine): by default glibc hands
/// blocks above 128 kB-32 MB straight back to the system when they are freed, so every run of the
/// same process faults its pages in again. keep_freed_memory() makes freed blocks up to 32 MB stay
/// in the process for the next run instead.

namespace beamimpact {

/// @brief True when glibc's allocator serves malloc in this build: not another C library's, nor
/// a sanitizer's. Only then do keep_freed_memory() and reserve_heap() act.
bool glibc_heap();

/// @brief Keeps freed blocks in the process (glibc mallopt: blocks up to 32 MB come from the heap,
/// the heap is not trimmed below 2 GB of free top, and grows 64 MB at a time). Called by
/// beamimpact::run before an in-process method's set-up when RunOptions::tune_heap asks for it; idempotent
/// and thread-safe. A process that runs a large model holds that run's memory (its peak, up to the 2 GB)
/// after it for the next; set BEAMIMPACT_RELEASE_MEMORY=1 in the environment to keep glibc's defaults.
/// Without glibc's allocator (another C library, a sanitizer's) it does nothing.
void keep_freed_memory();

/// @brief Makes room for a run that will touch about `bytes` of new memory: grows the heap by that
/// much (up to 1 GB) of untouched memory marked for transparent huge pages (madvise
/// MADV_HUGEPAGE), unless as much is free in the heap already. The run's pages then fault
/// in 2 MB at a time instead of 4 kB (on a kernel with transparent_hugepage "madvise" or
/// "always"). Untouched memory costs address space only. Calls keep_freed_memory(); nothing below
/// 64 MB, with BEAMIMPACT_RELEASE_MEMORY=1 or without glibc's allocator.
void reserve_heap(double bytes);

}  // namespace beamimpact
