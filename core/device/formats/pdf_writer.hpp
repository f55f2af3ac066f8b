// PDF written directly: a line drawing needs a page of stroked paths and one line of text, which PDF 1.4
// says in a few operators. Written by hand (not through cairo) so that the expensive part — every page's
// content stream, its numbers and its compression — is made by make_pdf_page() on any thread, beside the
// other frames', and the document is only assembled in order: page objects streamed to the file as they
// come, the page tree, metadata and cross-reference table at the end. Memory stays flat for any number
// of pages, and the bytes do not depend on which thread made which page.
//
// The picture is the cairo devices' (core/device/page/page_style.hpp): pens' colours and widths, round caps
// and joins, hidden strokes dashed, the camera frame's thin grey border and the caption in Helvetica (one
// of PDF's standard fonts, so nothing is embedded; characters outside Latin-1 print as '?'). Page
// coordinates are mapped by one transformation from millimetres, top-left origin, y down.
// Metadata: Title (when given), Creator and Producer "hlrscript", CreationDate (options.creation_date,
// ISO 8601, else the current time).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/device/page/pen_style.hpp"
#include "core/device/page/plot_page.hpp"

namespace hlr {

struct PdfOptions {
  PenTable pens;
  std::string title;
  std::string creation_date;  // "2026-12-01T12:00:00Z"; empty: now
  bool decorations = true;    // border and caption
};

// One page, ready to be written: its size and its content stream, compressed in parts (FlateDecode each;
// the page lists them in order, and PDF reads them as one stream).
struct PdfPage {
  double width_mm = 0, height_mm = 0;
  std::vector<std::string> contents;
};

// Throws DeviceError for a page check_page_spec() refuses or a non-finite point.
PdfPage make_pdf_page(const PlotPage& page, const PdfOptions& options);

class PdfWriter {
 public:
  // Creates `path` and writes the header. Throws DeviceError.
  PdfWriter(const std::filesystem::path& path, const PdfOptions& options);
  void add_page(const PdfPage& page);
  // The page tree, metadata, cross-reference table and trailer. Throws DeviceError.
  void finish();

 private:
  void begin_object(std::size_t number);
  void write(const std::string& text);

  std::filesystem::path path_;
  PdfOptions options_;
  std::ofstream out_;
  std::uint64_t offset_ = 0;
  std::vector<std::uint64_t> offsets_;  // by object number; 0 unused
  std::vector<std::size_t> page_objects_;
  std::size_t next_object_;  // the number the next page's first object gets
};

// make_pdf_page() for every page, written atomically (core/device/page/atomic_file.hpp).
void write_pdf(const std::filesystem::path& target, const std::vector<PlotPage>& pages,
               const PdfOptions& options);

}  // namespace hlr
