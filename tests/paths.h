// Where the tests read their data and write their output. Defined in main.cpp, the one translation
// unit compiled with the checkout's absolute paths, so that every other test unit compiles the same
// in any clone (and ccache shares its objects between clones).
#pragma once

#include <string>

namespace tessera::test {

/// `file` under tests/data.
std::string data_path(const std::string& file);
/// `file` under the build's tests/output directory.
std::string output_path(const std::string& file);

} // namespace tessera::test
