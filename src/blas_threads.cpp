// tessera/blas_threads.h: OpenBLAS's thread setting, found at run time.
#include <tessera/blas_threads.h>

#include <dlfcn.h>

namespace tessera {

namespace {

template <typename F> F openblas_function(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_DEFAULT, name));
}

} // namespace

bool set_blas_threads(int threads) {
  const auto set = openblas_function<void (*)(int)>("openblas_set_num_threads");
  if (!set || threads < 1)
    return false;
  set(threads);
  return true;
}

int blas_threads() {
  const auto get = openblas_function<int (*)()>("openblas_get_num_threads");
  return get ? get() : 0;
}

} // namespace tessera
