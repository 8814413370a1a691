// Catch2's main, compiled once for the whole suite, and the suite's data and output directories.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include "paths.h"

namespace tessera::test {

std::string data_path(const std::string& file) {
  return std::string(TESSERA_TEST_DATA_DIR) + "/" + file;
}
std::string output_path(const std::string& file) {
  return std::string(TESSERA_TEST_OUTPUT_DIR) + "/" + file;
}

} // namespace tessera::test
