// libFuzzer target for one mesh format; TESSERA_FUZZ_EXTENSION (".off", ".obj", ".ply", ".stl")
// is set per target by fuzz/CMakeLists.txt.
#include "read_mesh_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tessera::fuzz::read_mesh_bytes(data, size, TESSERA_FUZZ_EXTENSION);
  return 0;
}
