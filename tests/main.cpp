// Catch2's main, compiled once for the whole suite, and the suite's data and output directories.
// The suite runs with one BLAS thread, as the command-line tool does (tessera/blas_threads.h):
// ctest runs two test processes at once on two cores.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <tessera/blas_threads.h>

#include "paths.h"

int main(int argc, char** argv) {
  tessera::set_blas_threads(1);
  return Catch::Session().run(argc, argv);
}

namespace tessera::test {

std::string data_path(const std::string& file) {
  return std::string(TESSERA_TEST_DATA_DIR) + "/" + file;
}
std::string output_path(const std::string& file) {
  return std::string(TESSERA_TEST_OUTPUT_DIR) + "/" + file;
}

} // namespace tessera::test
