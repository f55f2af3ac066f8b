// Fuzz target: bytes → the STL importer as they are. Seeded with ASCII files, so mostly the ASCII
// readers (the fast one and the careful one it falls back to); a size that matches the count at byte 80
// goes to the binary reader, as it would in a real file.
#include "tests/fuzz/fuzz_input.hpp"
#include "tests/fuzz/fuzz_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  hlr::fuzz::import_or_refuse([&](const hlr::stdlib::MeshImportOptions& options) {
    return hlr::stdlib::import_stl(hlr::fuzz::as_text(data, size), "fuzz.stl", options);
  });
  return 0;
}
