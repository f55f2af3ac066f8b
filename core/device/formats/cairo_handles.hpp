// Owners of cairo objects, so that an exception part-way never leaks a surface or a context, and the one
// way a cairo failure becomes an exception. Shared by the devices and the REPL's terminal pictures.
#pragma once

#include <stdexcept>
#include <string>

#include "core/device/formats/cairo_library.hpp"

namespace hlr {

struct CairoSurface {
  cairo_surface_t* p;
  ~CairoSurface() { cairo_library().cairo_surface_destroy(p); }
};
struct CairoContext {
  cairo_t* p;
  ~CairoContext() { cairo_library().cairo_destroy(p); }
};

inline void check_cairo(cairo_status_t status) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cairo: ") + cairo_library().cairo_status_to_string(status));
}

// A cairo write function that appends to the std::string `closure` (PNG and SVG streams).
inline cairo_status_t append_to_string(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace hlr
