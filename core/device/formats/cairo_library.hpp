// cairo, loaded when a picture is first drawn with it (PNG, SVG for screens, the REPL's terminal pictures)
// rather than when the program starts: with the X11 and font libraries it brings (fourteen of them), it
// took 1.3–1.8 ms of every run, most of which (PDF, HPGL, G-code, plotter SVG, DXF, JSON) never use it.
// Its types and constants come from <cairo.h> as usual; its functions are called through cairo_library().
#pragma once

#include <cairo-svg.h>
#include <cairo.h>

namespace hlr {

// The functions the program calls, each a member of the same name and type.
#define HLR_CAIRO_FUNCTIONS(F)                                                                              \
  F(cairo_create)                                                                                           \
  F(cairo_destroy) F(cairo_get_target) F(cairo_image_surface_create) F(cairo_image_surface_get_data)        \
      F(cairo_image_surface_get_stride) F(cairo_line_to) F(cairo_move_to) F(cairo_paint) F(cairo_rectangle) \
          F(cairo_restore) F(cairo_save) F(cairo_scale) F(cairo_select_font_face) F(cairo_set_antialias)    \
              F(cairo_set_dash) F(cairo_set_font_size) F(cairo_set_line_cap) F(cairo_set_line_join)         \
                  F(cairo_set_line_width) F(cairo_set_operator) F(cairo_set_source_rgb)                     \
                      F(cairo_set_source_rgba) F(cairo_show_page) F(cairo_show_text) F(cairo_status)        \
                          F(cairo_status_to_string) F(cairo_stroke) F(cairo_surface_destroy)                \
                              F(cairo_surface_finish) F(cairo_surface_flush) F(cairo_surface_get_type)      \
                                  F(cairo_surface_status) F(cairo_surface_write_to_png_stream)              \
                                      F(cairo_svg_surface_create_for_stream)                                \
                                          F(cairo_svg_surface_set_document_unit) F(cairo_translate)

struct CairoLibrary {
#define HLR_CAIRO_MEMBER(name) decltype(&::name) name = nullptr;
  HLR_CAIRO_FUNCTIONS(HLR_CAIRO_MEMBER)
#undef HLR_CAIRO_MEMBER
};

// Loads cairo on first use (thread-safe). Throws std::runtime_error, naming the library and what to
// install, when it cannot be loaded.
const CairoLibrary& cairo_library();

}  // namespace hlr
