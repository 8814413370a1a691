// The allocator settings of Tessera's programs (the command-line tool and the benchmarks), linked
// into them with jemalloc when CMake finds it (TESSERA_USE_JEMALLOC): arenas backed by transparent
// huge pages. A mosaic of 40k tiles on 207k triangles touches some 630 MB, mostly fresh vectors,
// sparse factors and charts; with glibc's malloc and 4 KiB pages that is 184k page faults, 1.6 s of
// system time on this 2-core virtual machine, where the kernel leaves huge pages to those who ask
// (transparent_hugepage=madvise). With 2 MiB pages: 17k faults, the run 14 % shorter end to end
// (paired runs, median; doc/performance-notes.md). The library itself allocates with the standard
// allocator and sets nothing: an application chooses its allocator.
extern "C" {
// Read by jemalloc when it starts (its documented `malloc_conf` global; MALLOC_CONF in the
// environment still overrides it).
const char* malloc_conf = "thp:always,metadata_thp:auto";
}
