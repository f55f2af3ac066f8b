// Fuzz target: bytes → the OFF importer (stdlib/mesh_import.hpp), in memory.
#include "tests/fuzz/fuzz_input.hpp"
#include "tests/fuzz/fuzz_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  hlr::fuzz::import_or_refuse([&](const hlr::stdlib::MeshImportOptions& options) {
    return hlr::stdlib::import_off(hlr::fuzz::as_text(data, size), "fuzz.off", options);
  });
  return 0;
}
