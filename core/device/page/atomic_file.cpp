#include "core/device/page/atomic_file.hpp"

#include <unistd.h>

#include <string>
#include <system_error>

namespace hlr {

std::filesystem::path temporary_path_for(const std::filesystem::path& target) {
  const std::filesystem::path dir =
      target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
  std::string name(1, '.');
  name.append(target.filename().string())
      .append(".tmp-")
      .append(std::to_string(static_cast<long>(::getpid())));
  return dir / name;
}

void check_target_directory(const std::filesystem::path& target) {
  const std::filesystem::path dir =
      target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw DeviceError("cannot write '" + target.string() + "': directory '" + dir.string() +
                      "' does not exist");
}

void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& write) {
  namespace fs = std::filesystem;
  check_target_directory(target);
  std::error_code ec;
  const fs::path temp = temporary_path_for(target);
  try {
    write(temp);
  } catch (const std::exception& e) {
    fs::remove(temp, ec);
    throw DeviceError("cannot write '" + target.string() + "': " + e.what());
  }
  fs::rename(temp, target, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw DeviceError("cannot write '" + target.string() + "': " + ec.message());
  }
}

}  // namespace hlr
