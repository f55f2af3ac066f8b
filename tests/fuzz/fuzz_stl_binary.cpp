// Fuzz target: bytes → the triangles of a binary STL (50 bytes each: normal, three corners, attribute),
// behind an 80-byte header that starts with "solid" (as many exporters write) and the right count, so
// that the importer takes the binary path; a trailing partial triangle is dropped.
#include <cstring>
#include <string>

#include "tests/fuzz/fuzz_input.hpp"
#include "tests/fuzz/fuzz_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::size_t count = size / 50;
  std::string file(84 + 50 * count, '\0');
  std::memcpy(file.data(), "solid fuzz", 10);
  for (int i = 0; i < 4; ++i) file[80 + i] = static_cast<char>((count >> (8 * i)) & 0xFF);
  if (count > 0) std::memcpy(file.data() + 84, data, 50 * count);
  hlr::fuzz::import_or_refuse([&](const hlr::stdlib::MeshImportOptions& options) {
    return hlr::stdlib::import_stl(file, "fuzz.stl", options);
  });
  return 0;
}
