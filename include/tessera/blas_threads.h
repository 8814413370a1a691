// The BLAS threads of the sparse Cholesky factorizations (CHOLMOD's supernodal kernels call the
// BLAS the system links: on Debian, OpenBLAS with one thread per core by default). Tessera's
// systems (fields, parameterizations, resizing volumes) are surface-sized and their BLAS calls
// small; OpenBLAS's threads then wait for work by spinning and yielding, and on a machine whose
// cores are busy (a build, a parallel test run, the mosaic's own threads) they stall the solve:
// the 200k-triangle field took 17-92 s beside a two-job compile with OpenBLAS's default threads,
// and 2.9 s with one (2.3-2.5 s either way on an idle machine). Applications set it once at the
// start; the command-line tool, the benchmarks and the tests set one thread.
#pragma once

namespace tessera {

/// Sets the number of threads of the loaded BLAS when it is OpenBLAS (looked up at run time, so
/// there is no link to OpenBLAS); returns false when the loaded BLAS has no such setting.
bool set_blas_threads(int threads);

/// The number of threads of the loaded OpenBLAS, or 0 when the loaded BLAS is not OpenBLAS.
int blas_threads();

} // namespace tessera
