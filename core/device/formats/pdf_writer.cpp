#include "core/device/formats/pdf_writer.hpp"

#include <libdeflate.h>
#include <tbb/enumerable_thread_specific.h>

#include <cmath>
#include <ctime>
#include <memory>
#include <stdexcept>
#include <string_view>

#include "core/device/formats/fixed_decimal.hpp"
#include "core/device/page/atomic_file.hpp"
#include "core/device/page/page_layout.hpp"
#include "core/device/page/page_style.hpp"
#include "core/geometry/clip2d.hpp"
#include "core/parallel.hpp"

namespace hlr {

namespace {

// Object numbers: the catalogue, the page tree, the font and the metadata come first; each page then
// takes two, its content stream and its page object.
constexpr std::size_t kCatalog = 1, kPages = 2, kFont = 3, kInfo = 4, kFirstPageObject = 5;

// A number in a content stream: fixed point, `decimals` digits, trailing zeros dropped.
void put_number(std::string& out, double v, int decimals = 3) { append_fixed(out, v, decimals); }

void put_point(std::string& out, Point2 p, const char* op) {
  put_number(out, p.x);
  out += ' ';
  put_number(out, p.y);
  out += op;
}

void put_rgb(std::string& out, double r, double g, double b) {
  put_number(out, r);
  out += ' ';
  put_number(out, g);
  out += ' ';
  put_number(out, b);
  out += " RG\n";
}

// A PDF literal string in Helvetica's WinAnsi encoding: ASCII and Latin-1 as they are, any other
// character '?', and the delimiters escaped.
std::string win_ansi_literal(const std::string& utf8) {
  std::string out = "(";
  for (std::size_t i = 0; i < utf8.size();) {
    const auto c = static_cast<unsigned char>(utf8[i]);
    unsigned cp = '?';
    std::size_t n = 1;
    if (c < 0x80) {
      cp = c;
    } else if ((c >> 5) == 0x6 && i + 1 < utf8.size() &&
               (static_cast<unsigned char>(utf8[i + 1]) & 0xc0) == 0x80) {
      cp = ((c & 0x1fU) << 6) | (static_cast<unsigned char>(utf8[i + 1]) & 0x3fU);
      n = 2;
      if (cp < 0xa0) cp = '?';
    } else {
      while (i + n < utf8.size() && (static_cast<unsigned char>(utf8[i + n]) & 0xc0) == 0x80) ++n;
    }
    i += n;
    if (cp == '(' || cp == ')' || cp == '\\') out += '\\';
    if (cp < 0x20) cp = '?';
    out += static_cast<char>(cp);
  }
  return out + ")";
}

// A metadata string: ASCII as a literal, anything else as UTF-16BE with its byte-order mark.
std::string text_string(const std::string& utf8) {
  bool ascii = true;
  for (const char c : utf8) ascii = ascii && static_cast<unsigned char>(c) < 0x80 && c >= 0x20;
  if (ascii) return win_ansi_literal(utf8);
  static const char* hex = "0123456789ABCDEF";
  std::string out = "<FEFF";
  auto unit = [&](unsigned u) {
    for (int shift = 12; shift >= 0; shift -= 4) out += hex[(u >> shift) & 0xf];
  };
  for (std::size_t i = 0; i < utf8.size();) {
    const auto c = static_cast<unsigned char>(utf8[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 1;
    unsigned cp = n == 1 ? (c < 0x80 ? c : '?') : c & (0xffU >> (n + 1));
    for (std::size_t k = 1; k < n; ++k)
      cp = i + k < utf8.size() ? (cp << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3fU) : '?';
    i += n;
    if (cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) cp = '?';
    if (cp >= 0x10000) {
      unit(0xd800 + ((cp - 0x10000) >> 10));
      unit(0xdc00 + ((cp - 0x10000) & 0x3ff));
    } else {
      unit(cp);
    }
  }
  return out + ">";
}

// "D:20261201120000Z" from "2026-12-01T12:00:00Z", or the current time.
std::string pdf_date(const std::string& iso) {
  std::string digits;
  for (const char c : iso)
    if (c >= '0' && c <= '9') digits += c;
  if (digits.size() < 14) {
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y%m%d%H%M%S", &tm);
    digits = buf;
  }
  return "D:" + digits.substr(0, 14) + "Z";
}

// libdeflate's level 2: on the 10⁶-triangle torus's page (5.8 MB of operators) it takes 30 ms on one core
// where zlib's level 4, used before, took 61 ms, for a file 1 % larger (1.298 against 1.285 MB); on the
// bunny's (509 kB), 2.8 ms against 4.8 ms for the same size. Its level 1 halves that time again for a file
// 6 % larger; zlib's level 6 (its default) takes thrice level 4's time for 8 % less.
constexpr int kPageCompression = 2;
// A page's operators are compressed in parts of about this size, each a content stream of its own, on all
// cores. Parts this small share out evenly: the bunny's page (509 kB) in eight, where three parts of 256 kB
// kept one core busy twice as long as the other. The parts depend on the text alone, not on the cores, so
// the bytes do not either; each costs its dictionary's warm-up (the bunny's file 1 % larger).
constexpr std::size_t kContentPartBytes = 64 * 1024;

struct FreeCompressor {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};
using Compressor = std::unique_ptr<libdeflate_compressor, FreeCompressor>;

// `text` in the zlib format, which FlateDecode reads.
std::string deflate(libdeflate_compressor& compressor, std::string_view text) {
  std::string out(libdeflate_zlib_compress_bound(&compressor, text.size()), '\0');
  const std::size_t size =
      libdeflate_zlib_compress(&compressor, text.data(), text.size(), out.data(), out.size());
  if (size == 0) throw DeviceError("cannot compress a PDF page");
  out.resize(size);
  return out;
}

// The text in parts of about kContentPartBytes, each ending at a line end (a page's content streams may
// divide only between tokens, and every operator here ends its line), compressed side by side.
std::vector<std::string> deflate_in_parts(const std::string& text) {
  std::vector<std::size_t> ends;
  for (std::size_t at = kContentPartBytes; at < text.size();) {
    const std::size_t line_end = text.find('\n', at);
    if (line_end == std::string::npos || line_end + 1 >= text.size()) break;
    ends.push_back(line_end + 1);
    at = line_end + 1 + kContentPartBytes;
  }
  ends.push_back(text.size());
  std::vector<std::string> parts(ends.size());
  tbb::enumerable_thread_specific<Compressor> compressors(
      [] { return Compressor(libdeflate_alloc_compressor(kPageCompression)); });  // one a thread
  parallel_chunks(parts.size(), 0, [&](std::size_t k) {
    Compressor& compressor = compressors.local();
    if (!compressor) throw DeviceError("cannot compress a PDF page: out of memory");
    const std::size_t begin = k == 0 ? 0 : ends[k - 1];
    parts[k] = deflate(*compressor, std::string_view(text).substr(begin, ends[k] - begin));
  });
  return parts;
}

// Strokes [first, end) as path operators, appended to `out`. A long run is written in parts side by side
// and joined in order (the text is the same): the 10⁶-triangle torus's page took 40 ms to write on one
// core. Parts of a few hundred strokes share out evenly over the cores (the bunny's 2 589 strokes in 11).
void put_strokes(std::string& out, const std::vector<PlotStroke>& strokes, std::size_t first, std::size_t end,
                 const Rect2& box) {
  auto put = [&](std::string& text, std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i)
      clip_polyline_to_rect(
          strokes[i].points, box, [&](Point2 p) { put_point(text, p, " m\n"); },
          [&](Point2 p) { put_point(text, p, " l\n"); });
  };
  constexpr std::size_t kPartStrokes = 256;
  const std::size_t count = (end - first + kPartStrokes - 1) / kPartStrokes;
  if (count < 2) {
    put(out, first, end);
    return;
  }
  std::vector<std::string> parts(count);
  parallel_chunks(count, 0, [&](std::size_t k) {
    const std::size_t from = first + k * kPartStrokes;
    put(parts[k], from, std::min(end, from + kPartStrokes));
  });
  for (const std::string& part : parts) out += part;
}

}  // namespace

PdfPage make_pdf_page(const PlotPage& page, const PdfOptions& o) {
  check_page_spec(PageSpec{{page.width_mm, page.height_mm}, page.margin_mm});
  for (std::size_t s = 0; s < page.strokes.size(); ++s)
    for (const Point2& p : page.strokes[s].points)
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw DeviceError("stroke " + std::to_string(s + 1) + " has a non-finite point");

  std::string c;
  c.reserve(64 + 24 * page.strokes.size());
  // Millimetres from the top-left corner, y down.
  put_number(c, kPointsPerMm, 8);
  c += " 0 0 ";
  put_number(c, -kPointsPerMm, 8);
  c += " 0 ";
  put_number(c, page.height_mm * kPointsPerMm, 4);
  c += " cm\n1 J 1 j\n";

  if (o.decorations && page.border && !page.border->empty()) {
    const Rect2& b = *page.border;
    put_rgb(c, kBorderGrey, kBorderGrey, kBorderGrey);
    put_number(c, 0.5 * o.pens.default_width_mm());
    c += " w\n";
    put_point(c, {b.xmin, b.ymin}, " ");
    put_number(c, b.width());
    c += ' ';
    put_number(c, b.height());
    c += " re S\n";
  }

  const Rect2 box = stroke_clip_box(page, o.pens);
  for_each_pen_run(
      page, o.pens,
      [&](const PenStyle& style, StrokeLayer layer, int level, std::size_t first, std::size_t end) {
        put_rgb(c, style.r, style.g, style.b);
        put_number(c, style.width_mm);
        c += " w\n";
        if (layer == StrokeLayer::Hidden) {
          c += '[';
          put_number(c, dash_on_mm(style.width_mm, level));
          c += ' ';
          put_number(c, dash_off_mm(style.width_mm, level));
          c += "] 0 d\n";
        } else {
          c += "[] 0 d\n";
        }
        put_strokes(c, page.strokes, first, end, box);
        c += "S\n";
      });

  if (o.decorations && !page.caption.empty()) {
    // In the bottom margin, so a caption never moves the drawing; the text matrix turns it upright.
    c += "[] 0 d\n0 0 0 rg\nBT /F1 ";
    put_number(c, kCaptionPt / kPointsPerMm);
    c += " Tf 1 0 0 -1 ";
    put_point(c, {page.margin_mm, page.height_mm - 0.6 * page.margin_mm}, " Tm ");
    c += win_ansi_literal(page.caption) + " Tj ET\n";
  }
  return {page.width_mm, page.height_mm, deflate_in_parts(c)};
}

PdfWriter::PdfWriter(const std::filesystem::path& path, const PdfOptions& options)
    : path_(path),
      options_(options),
      out_(path, std::ios::binary | std::ios::trunc),
      offsets_(kFirstPageObject, 0),
      next_object_(kFirstPageObject) {
  if (!out_) throw DeviceError("cannot create '" + path.string() + "'");
  write("%PDF-1.4\n%\xe2\xe3\xcf\xd3\n");
  begin_object(kCatalog);
  write("<< /Type /Catalog /Pages 2 0 R >>\nendobj\n");
  begin_object(kFont);
  write("<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>\nendobj\n");
}

void PdfWriter::begin_object(std::size_t number) {
  if (offsets_.size() <= number) offsets_.resize(number + 1, 0);
  offsets_[number] = offset_;
  write(std::to_string(number) + " 0 obj\n");
}

void PdfWriter::write(const std::string& text) {
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out_) throw DeviceError("write to '" + path_.string() + "' failed");
  offset_ += text.size();
}

void PdfWriter::add_page(const PdfPage& page) {
  std::string contents;  // the page's content streams: "N 0 R" or an array of them
  for (const std::string& part : page.contents) {
    const std::size_t number = next_object_++;
    begin_object(number);
    write("<< /Length " + std::to_string(part.size()) + " /Filter /FlateDecode >>\nstream\n");
    write(part);
    write("\nendstream\nendobj\n");
    contents += (contents.empty() ? "" : " ") + std::to_string(number) + " 0 R";
  }
  if (page.contents.size() != 1) contents = "[" + contents + "]";
  const std::size_t page_object = next_object_++;
  begin_object(page_object);
  std::string dict = "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 ";
  put_number(dict, page.width_mm * kPointsPerMm, 4);
  dict += ' ';
  put_number(dict, page.height_mm * kPointsPerMm, 4);
  dict += "] /Contents " + contents + " /Resources << /Font << /F1 3 0 R >> >> >>\nendobj\n";
  write(dict);
  page_objects_.push_back(page_object);
}

void PdfWriter::finish() {
  begin_object(kPages);
  std::string kids;
  for (const std::size_t p : page_objects_) kids += std::to_string(p) + " 0 R ";
  write("<< /Type /Pages /Kids [" + kids + "] /Count " + std::to_string(page_objects_.size()) +
        " >>\nendobj\n");
  begin_object(kInfo);
  std::string info = "<< ";
  if (!options_.title.empty()) info += "/Title " + text_string(options_.title) + " ";
  info += "/Creator (hlrscript) /Producer (hlrscript) /CreationDate (" + pdf_date(options_.creation_date) +
          ") >>\nendobj\n";
  write(info);
  const std::uint64_t xref = offset_;
  std::string table = "xref\n0 " + std::to_string(offsets_.size()) + "\n0000000000 65535 f \n";
  char line[24];
  for (std::size_t i = 1; i < offsets_.size(); ++i) {
    std::snprintf(line, sizeof line, "%010llu 00000 n \n", static_cast<unsigned long long>(offsets_[i]));
    table += line;
  }
  table += "trailer\n<< /Size " + std::to_string(offsets_.size()) +
           " /Root 1 0 R /Info 4 0 R >>\nstartxref\n" + std::to_string(xref) + "\n%%EOF\n";
  write(table);
  out_.close();
  if (!out_) throw DeviceError("write to '" + path_.string() + "' failed");
}

void write_pdf(const std::filesystem::path& target, const std::vector<PlotPage>& pages,
               const PdfOptions& options) {
  std::vector<PdfPage> made;
  try {
    if (pages.empty()) throw DeviceError("nothing to draw: no pages");
    for (std::size_t i = 0; i < pages.size(); ++i) {
      try {
        made.push_back(make_pdf_page(pages[i], options));
      } catch (const DeviceError& e) {
        throw DeviceError((pages.size() > 1 ? "page " + std::to_string(i + 1) + ": " : std::string()) +
                          e.what());
      }
    }
  } catch (const DeviceError& e) {
    throw DeviceError("cannot write '" + target.string() + "': " + e.what());
  }
  write_atomically(target, [&](const std::filesystem::path& temp) {
    PdfWriter pdf(temp, options);
    for (const PdfPage& p : made) pdf.add_page(p);
    pdf.finish();
  });
}

}  // namespace hlr
