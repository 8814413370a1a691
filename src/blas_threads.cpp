// tessera/blas_threads.h: OpenBLAS's thread setting and OpenMP's dynamic adjustment, found at run
// time.
#include <tessera/blas_threads.h>

#include <dlfcn.h>

namespace tessera {

namespace {

template <typename F> F loaded_function(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_DEFAULT, name));
}

} // namespace

bool set_blas_threads(int threads) {
  const auto set = loaded_function<void (*)(int)>("openblas_set_num_threads");
  if (!set || threads < 1)
    return false;
  set(threads);
  // CHOLMOD's `num_threads(4)` loops in its supernodal factorization: with dynamic adjustment
  // OpenMP gives them at most the idle cores (the 207k-face field: 1.73 s instead of 2.07 s on two
  // idle cores, 17 context switches instead of 16k).
  if (const auto dynamic = loaded_function<void (*)(int)>("omp_set_dynamic"))
    dynamic(1);
  return true;
}

int blas_threads() {
  const auto get = loaded_function<int (*)()>("openblas_get_num_threads");
  return get ? get() : 0;
}

bool openmp_dynamic_threads() {
  const auto get = loaded_function<int (*)()>("omp_get_dynamic");
  return get && get() != 0;
}

} // namespace tessera
