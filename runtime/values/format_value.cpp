#include "runtime/values/format_value.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

#include "runtime/values/function.hpp"

namespace hlr::runtime {
namespace {

// Lists nested deeper than this print as "[...]": the text stays readable and the recursion shallow.
constexpr int kMaxDisplayDepth = 64;

struct Spec {
  bool zero = false;
  int width = 0;
  int precision = -1;  // -1: none given
  char type = 0;       // f e g d x, or 0
  bool numeric_only() const { return zero || precision >= 0 || type != 0; }
};

Spec parse_spec(std::string_view text) {
  const std::string bad =
      "bad format '" + std::string(text) + "': expected [0][width][.precision][f|e|g|d|x]";
  Spec spec;
  std::size_t i = 0;
  auto digits = [&](int& out, int max) {
    const std::size_t start = i;
    int value = 0;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
      value = value * 10 + (text[i] - '0');
      if (value > max) throw FormatError(bad + " (" + std::to_string(max) + " at most)");
      ++i;
    }
    out = value;
    return i > start;
  };
  if (i < text.size() && text[i] == '0') {
    spec.zero = true;
    ++i;
  }
  digits(spec.width, 200);
  if (i < text.size() && text[i] == '.') {
    ++i;
    if (!digits(spec.precision, 100)) throw FormatError(bad);
  }
  if (i < text.size() && std::string_view("fegdx").find(text[i]) != std::string_view::npos)
    spec.type = text[i++];
  if (i != text.size()) throw FormatError(bad);
  return spec;
}

std::string printf_double(const char* format, int precision, double x) {
  const int n = std::snprintf(nullptr, 0, format, precision, x);
  std::vector<char> buf(static_cast<std::size_t>(n) + 1);
  std::snprintf(buf.data(), buf.size(), format, precision, x);
  return std::string(buf.data(), static_cast<std::size_t>(n));
}

// |x| below 2^63 and whole: safe to convert to an integer.
bool is_whole(double x) { return std::floor(x) == x && std::fabs(x) < 9.2e18; }

std::string whole_digits(double x, int base) {
  const bool negative = x < 0;
  auto magnitude = static_cast<unsigned long long>(std::fabs(x));
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, magnitude, base);
  return (negative ? "-" : "") + std::string(buf, result.ptr);
}

std::string pad(std::string text, const Spec& spec, bool number) {
  const auto width = static_cast<std::size_t>(spec.width);
  if (text.size() >= width) return text;
  const std::size_t fill = width - text.size();
  if (!number) return text + std::string(fill, ' ');
  if (spec.zero) {
    const std::size_t sign = (!text.empty() && (text[0] == '-' || text[0] == '+')) ? 1 : 0;
    return text.insert(sign, fill, '0');
  }
  return std::string(fill, ' ') + text;
}

std::string format_number_with(double x, const Spec& spec) {
  std::string text;
  switch (spec.type) {
    case 'f':
      text = printf_double("%.*f", spec.precision < 0 ? 6 : spec.precision, x);
      break;
    case 'e':
      text = printf_double("%.*e", spec.precision < 0 ? 6 : spec.precision, x);
      break;
    case 'g':
      text = printf_double("%.*g", spec.precision < 0 ? 6 : spec.precision, x);
      break;
    case 'd':
    case 'x':
      if (!is_whole(x))
        throw FormatError("format '" + std::string(1, spec.type) + "' needs a whole number, got " +
                          format_number(x));
      text = whole_digits(x, spec.type == 'x' ? 16 : 10);
      break;
    default:
      text = spec.precision >= 0 ? printf_double("%.*g", spec.precision, x) : format_number(x);
  }
  return pad(std::move(text), spec, true);
}

class Writer {
 public:
  Writer(std::size_t max_length, const Spec* spec) : max_(max_length), spec_(spec) {}

  void value(const Value& v, bool quoted, int depth) {
    switch (v.kind()) {
      case ValueKind::None:
        put("none");
        break;
      case ValueKind::Number:
        put(spec_ ? format_number_with(v.as_number(), *spec_) : format_number(v.as_number()));
        break;
      case ValueKind::Bool:
        put(v.as_bool() ? "true" : "false");
        break;
      case ValueKind::String:
        if (quoted) {
          put("\"");
          put(v.as_string());
          put("\"");
        } else {
          put(v.as_string());
        }
        break;
      case ValueKind::Vector: {
        const Vector3 p = v.as_vector();
        put("(");
        value(Value::number(p.x), true, depth + 1);
        put(", ");
        value(Value::number(p.y), true, depth + 1);
        put(", ");
        value(Value::number(p.z), true, depth + 1);
        put(")");
        break;
      }
      case ValueKind::Range: {
        const RangeValue& r = v.as_range();
        if (!spec_ && r.step == 1) {
          put(format_number(r.start) + ".." + format_number(r.start + static_cast<double>(r.count)));
          break;
        }
        [[fallthrough]];
      }
      case ValueKind::List: {
        if (depth >= kMaxDisplayDepth) {
          put("[...]");
          break;
        }
        put("[");
        const std::size_t n = sequence_size(v);
        for (std::size_t i = 0; i < n; ++i) {
          if (i > 0) put(", ");
          value(sequence_item(v, i), true, depth + 1);
        }
        put("]");
        break;
      }
      case ValueKind::Transform: {
        const Affine3& a = v.as_transform();
        put("matrix([");
        for (int r = 0; r < 3; ++r) {
          put(r ? ", [" : "[");
          for (int c = 0; c < 3; ++c) put(format_number(a.m[r][c]) + ", ");
          put(format_number(a.t[r]) + "]");
        }
        put("])");
        break;
      }
      case ValueKind::Solid:
        put("solid " + v.as_solid().name + " (" + std::to_string(v.as_solid().solid->faces.size()) +
            " faces)");
        break;
      case ValueKind::Group:
        put("group of " + std::to_string(v.as_group().size()) + " solids");
        break;
      case ValueKind::Camera:
        put("camera " + v.as_camera().kind);
        break;
      case ValueKind::Function: {
        const Function& f = *v.as_function();
        if (f.is_builtin()) {
          put("built-in " + f.name);
          break;
        }
        put("function " + f.name + "(");
        const auto& params = std::get<UserFunction>(f.body).def->params;
        for (std::size_t i = 0; i < params.size(); ++i) put((i ? ", " : "") + params[i].name.text);
        put(")");
        break;
      }
    }
  }

  std::string take() { return std::move(out_); }

 private:
  void put(const std::string& text) {
    if (out_.size() + text.size() > max_)
      throw FormatError("the text would be longer than " + std::to_string(max_) + " bytes");
    out_ += text;
  }

  std::string out_;
  std::size_t max_;
  const Spec* spec_;
};

}  // namespace

std::string format_number(double x) {
  if (x == 0) return "0";  // also for -0
  // Shortest round-trip digits; positional from 1e-6 up to 1e21 (as JavaScript prints numbers), so frame
  // numbers and counts never turn into "1e+05", scientific beyond ("1e-07", "1e+21").
  const double m = std::fabs(x);
  const auto format = (m >= 1e-6 && m < 1e21) ? std::chars_format::fixed : std::chars_format::scientific;
  char buf[64];
  const auto result = std::to_chars(buf, buf + sizeof buf, x, format);
  return std::string(buf, result.ptr);
}

std::string display(const Value& value, std::size_t max_length) {
  Writer w(max_length, nullptr);
  w.value(value, false, 0);
  return w.take();
}

std::string format_value(const Value& value, std::string_view spec_text, std::size_t max_length) {
  const Spec spec = parse_spec(spec_text);
  if (value.is(ValueKind::String) || value.is(ValueKind::Bool)) {
    if (spec.numeric_only())
      throw FormatError("format '" + std::string(spec_text) + "' needs a number, got " +
                        kind_with_article(value.kind()));
    return pad(display(value, max_length), spec, false);
  }
  Writer w(max_length, &spec);
  w.value(value, false, 0);
  return w.take();
}

}  // namespace hlr::runtime
