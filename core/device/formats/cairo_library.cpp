#include "core/device/formats/cairo_library.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace hlr {
namespace {

constexpr const char* kCairoSoname = "libcairo.so.2";

CairoLibrary load() {
  // Kept loaded for the rest of the run: nothing unloads it.
  void* handle = ::dlopen(kCairoSoname, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = ::dlerror();
    throw std::runtime_error(std::string("cannot load cairo (") + kCairoSoname +
                             "), which draws PNG and SVG pictures: " + (why ? why : "not found") +
                             "; install it with 'apt-get install libcairo2'");
  }
  CairoLibrary lib;
#define HLR_CAIRO_LOAD(name)                                                                          \
  lib.name = reinterpret_cast<decltype(lib.name)>(::dlsym(handle, #name));                            \
  if (lib.name == nullptr)                                                                            \
    throw std::runtime_error(std::string("the cairo library loaded (") + kCairoSoname + ") has no " + \
                             #name + "; install cairo 1.16 or later");
  HLR_CAIRO_FUNCTIONS(HLR_CAIRO_LOAD)
#undef HLR_CAIRO_LOAD
  return lib;
}

}  // namespace

const CairoLibrary& cairo_library() {
  static const CairoLibrary lib = load();  // a failed load throws, and the next use tries again
  return lib;
}

}  // namespace hlr
