// Fuzz target: bytes → an Albers .VER/.SUR pair: the .VER text up to the first NUL byte, the .SUR text
// after it (empty when there is none).
#include <string_view>

#include "tests/fuzz/fuzz_input.hpp"
#include "tests/fuzz/fuzz_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input = hlr::fuzz::as_text(data, size);
  const std::size_t split = input.find('\0');
  const std::string_view ver = input.substr(0, split);
  const std::string_view sur = split == std::string_view::npos ? std::string_view() : input.substr(split + 1);
  hlr::fuzz::import_or_refuse([&](const hlr::stdlib::MeshImportOptions& options) {
    return hlr::stdlib::import_albers(ver, sur, "FUZZ.VER", "FUZZ.SUR", options);
  });
  return 0;
}
