// The threads of the linear algebra under the sparse Cholesky factorizations. CHOLMOD's supernodal
// kernels call the BLAS the system links (on Debian, OpenBLAS with one thread per core by
// default), and its own OpenMP loops ask for four threads whatever the core count (a constant of
// its build). Tessera's systems (fields, parameterizations, resizing volumes) are surface-sized
// and those calls small; the extra threads wait for work by spinning and yielding, and on a
// machine whose cores are busy (a build, a parallel test run, the mosaic's own threads) they stall
// the solve: the 200k-triangle field took 17-92 s beside a two-job compile with OpenBLAS's default
// threads, and 2.9 s with one (2.3-2.5 s either way on an idle machine); CHOLMOD's four OpenMP
// threads on two cores cost 16k context switches and 0.3 s more of its 2 s. Applications set it
// once at the start; the command-line tool, the benchmarks and the tests set one thread.
#pragma once

namespace tessera {

/// Sets the number of threads of the loaded BLAS when it is OpenBLAS, and, when OpenMP is loaded
/// (by CHOLMOD), turns on OpenMP's dynamic adjustment for the calling thread, so that CHOLMOD's
/// loops take no more threads than there are idle cores. Both are looked up at run time, so there
/// is no link to either. Returns false when the loaded BLAS has no such setting.
bool set_blas_threads(int threads);

/// The number of threads of the loaded OpenBLAS, or 0 when the loaded BLAS is not OpenBLAS.
int blas_threads();

/// Whether OpenMP's dynamic adjustment is on for the calling thread (false when OpenMP is not
/// loaded).
bool openmp_dynamic_threads();

} // namespace tessera
