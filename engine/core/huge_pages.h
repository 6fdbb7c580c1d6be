#pragma once
// Transparent huge pages for large arrays that are about to be written for the first time.
//
// Why: on the machines Prism is measured on (virtual machines), the first write to each 4 KiB
// page of fresh memory costs a page fault of several microseconds: 144 MB of triangles took
// 387 ms to touch, against 14-37 ms in 2 MiB pages (a physical machine's faults cost about a
// tenth as much; huge pages still save most of them). Loading, building and uploading a
// million-triangle mesh spent a third of its time in such faults (issue 31, docs/benchmarks.md
// "The first image"). Linux only backs memory with huge pages where the program asks
// (transparent_hugepage = madvise, the usual default), which is what adviseHugePages does.
#include <cstddef>
#include <vector>

namespace prism {

// Advises the kernel to back the whole 2 MiB pages inside [data, data + bytes) with huge
// pages. Call it before the first write: pages already touched stay small. Below a few MiB, or
// where the kernel has no such pages or the memory is not ordinary (a GPU's mapped memory), it
// does nothing; it never fails.
void adviseHugePages(const void *data, size_t bytes);

// An empty vector made ready for `count` elements in huge pages (a vector that already holds
// elements would have copied them into small pages before the advice could be given).
template <typename T> void reserveInHugePages(std::vector<T> &v, size_t count) {
    if (v.empty())
        v.shrink_to_fit();
    v.reserve(count);
    adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

} // namespace prism
