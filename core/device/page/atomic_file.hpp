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

// Where a file for `target` is written before it is renamed over it: beside it, hidden, named after the
// process (".landing.pdf.tmp-4711").
std::filesystem::path temporary_path_for(const std::filesystem::path& target);

// Throws DeviceError ("cannot write 'x/y.pdf': directory 'x' does not exist") unless the target's directory
// exists.
void check_target_directory(const std::filesystem::path& target);

// Calls write(temporary path); on success renames it to `target`, on any failure removes it and throws
// DeviceError naming `target`.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& write);

}  // namespace hlr
