// Every output is written to a temporary file beside its target and renamed over it only when complete,
// so a failure never leaves a partial or corrupted file.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>

namespace hlr {

struct DeviceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Calls write(temporary path); on success renames it to `target`, on any failure removes it and throws
// DeviceError naming `target`.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& write);

}  // namespace hlr
