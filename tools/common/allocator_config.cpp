// jemalloc's settings for Prism's tools, read by jemalloc when the process starts (its
// documented `malloc_conf` global; the MALLOC_CONF environment variable still overrides it).
//
// Why jemalloc, and why these settings (issue 31, docs/benchmarks.md "The first image"): on
// the virtual machines Prism is measured on, the first write to a fresh 4 KiB page costs a page
// fault of several microseconds, and a million-triangle mesh touches about a gigabyte between
// its OBJ text, its triangles, the grid build's working arrays and lavapipe's device memory:
// a third of the time from command to image went to those faults. `thp:always` backs jemalloc's
// memory with 2 MiB transparent huge pages (it asks with madvise, so it works where the system
// leaves huge pages to programs that ask), which made the faults 10-25 times cheaper; jemalloc
// also keeps freed memory for reuse a while (`dirty_decay_ms`), where glibc's malloc gives large
// blocks back to the kernel at once and faults them in again at the next allocation.
// glibc's own huge-page switch (GLIBC_TUNABLES=glibc.malloc.hugetlb=1) can only be set
// before the process starts.
extern "C" {
extern const char *malloc_conf;
const char *malloc_conf = "thp:always,metadata_thp:auto";
}
