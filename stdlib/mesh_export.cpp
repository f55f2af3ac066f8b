// Mesh export (mesh_export.hpp): OFF, OBJ and binary STL written from a scene's solids.
#include "stdlib/mesh_export.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "core/device/formats/devices.hpp"
#include "core/device/page/atomic_file.hpp"
#include "stdlib/booleans.hpp"

namespace hlr::stdlib {

namespace {

using Triangle = std::array<VertexIndex, 3>;

// One solid's surface as it goes into the file: the vertices on its faces (numbered from 0 in the order
// they are first used) and its faces as polygons — a face with holes, or every face for a file of triangles,
// as its triangles.
struct SurfaceOut {
  std::vector<Point3> vertices;
  std::vector<std::vector<std::uint32_t>> polygons;
  std::vector<Vector3> normals;  // per polygon, the face's outward normal
};

SurfaceOut surface_of(const Solid& s, bool triangles_only) {
  SurfaceOut out;
  std::vector<std::uint32_t> number(s.vertices.size(), std::numeric_limits<std::uint32_t>::max());
  auto use = [&](VertexIndex v) {
    if (number[v] == std::numeric_limits<std::uint32_t>::max()) {
      number[v] = static_cast<std::uint32_t>(out.vertices.size());
      out.vertices.push_back(s.vertices[v]);
    }
    return number[v];
  };
  std::vector<Triangle> triangles;
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const Face& face = s.faces[f];
    if (face.rings.size() == 1 && (!triangles_only || face.rings[0].vertices.size() == 3)) {
      std::vector<std::uint32_t> polygon;
      for (const VertexIndex v : face.rings[0].vertices) polygon.push_back(use(v));
      out.polygons.push_back(std::move(polygon));
      out.normals.push_back(s.planes[f].normal);
      continue;
    }
    triangles.clear();
    face_triangles(s, f, triangles);
    for (const Triangle& t : triangles) {
      out.polygons.push_back({use(t[0]), use(t[1]), use(t[2])});
      out.normals.push_back(s.planes[f].normal);
    }
  }
  return out;
}

void check_finite(const SurfaceOut& surface) {
  for (const Point3& p : surface.vertices)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw DeviceError("a vertex is not finite");
}

// The shortest text that reads back as the same double.
void append_number(std::string& out, double value) {
  if (value == 0) value = 0;  // -0 as 0
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_point(std::string& out, Point3 p) {
  append_number(out, p.x);
  out += ' ';
  append_number(out, p.y);
  out += ' ';
  append_number(out, p.z);
}

// A comment line's text: the title on one line.
std::string one_line(const std::string& text) {
  std::string line = text;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  return line;
}

// An OBJ object name: no spaces (the name ends at the first), never empty.
std::string obj_name(const std::string& name) {
  std::string out;
  for (const char c : name) out += (c == ' ' || c == '\t' || c == '\n' || c == '\r') ? '_' : c;
  return out.empty() ? "solid" : out;
}

std::string off_bytes(const std::vector<SurfaceOut>& surfaces, const std::string& title) {
  std::size_t vertices = 0, faces = 0;
  for (const SurfaceOut& s : surfaces) vertices += s.vertices.size(), faces += s.polygons.size();
  std::string out = "OFF\n# " + one_line(title) + "\n";
  out += std::to_string(vertices) + ' ' + std::to_string(faces) + " 0\n";
  for (const SurfaceOut& s : surfaces)
    for (const Point3& p : s.vertices) {
      append_point(out, p);
      out += '\n';
    }
  std::size_t base = 0;
  for (const SurfaceOut& s : surfaces) {
    for (const auto& polygon : s.polygons) {
      out += std::to_string(polygon.size());
      for (const std::uint32_t v : polygon) out += ' ' + std::to_string(base + v);
      out += '\n';
    }
    base += s.vertices.size();
  }
  return out;
}

std::string obj_bytes(const std::vector<SurfaceOut>& surfaces, const std::vector<std::string>& names,
                      const std::string& title) {
  std::string out = "# " + one_line(title) + "\n";
  std::size_t base = 1;  // OBJ counts vertices from 1, through the whole file
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const SurfaceOut& s = surfaces[i];
    out += "o " + obj_name(names[i]) + '\n';
    for (const Point3& p : s.vertices) {
      out += "v ";
      append_point(out, p);
      out += '\n';
    }
    for (const auto& polygon : s.polygons) {
      out += 'f';
      for (const std::uint32_t v : polygon) out += ' ' + std::to_string(base + v);
      out += '\n';
    }
    base += s.vertices.size();
  }
  return out;
}

void append_le32(std::string& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((value >> (8 * i)) & 0xffu);
}

void append_float(std::string& out, double value) {
  append_le32(out, std::bit_cast<std::uint32_t>(static_cast<float>(value)));
}

// `surfaces` are triangles only (surface_of(..., true)).
std::string stl_bytes(const std::vector<SurfaceOut>& surfaces, const std::string& title) {
  std::uint64_t triangles = 0;
  for (const SurfaceOut& s : surfaces) triangles += s.polygons.size();
  if (triangles > std::numeric_limits<std::uint32_t>::max())
    throw DeviceError("STL holds at most 4294967295 triangles");
  // The header must not start with "solid": readers would take the file for ASCII STL.
  std::string out = "hlrscript " + one_line(title);
  out.resize(80, ' ');
  out.reserve(84 + 50 * triangles);
  append_le32(out, static_cast<std::uint32_t>(triangles));
  for (const SurfaceOut& s : surfaces)
    for (std::size_t i = 0; i < s.polygons.size(); ++i) {
      const Vector3 n = s.normals[i];
      for (const double c : {n.x, n.y, n.z}) append_float(out, c);
      for (const std::uint32_t v : s.polygons[i])
        for (const double c : {s.vertices[v].x, s.vertices[v].y, s.vertices[v].z}) append_float(out, c);
      out.append(2, '\0');  // the attribute byte count
    }
  return out;
}

class MeshDevice : public Device {
 public:
  MeshDevice(MeshFormat format, std::string title) : format_(format), title_(std::move(title)) {}
  const char* name() const override {
    return format_ == MeshFormat::Off ? "OFF" : format_ == MeshFormat::Obj ? "OBJ" : "STL";
  }
  bool one_frame_per_file() const override { return true; }
  DevicePlanning planning(double, double) const override { return page_device_planning(); }
  EncodedFrame encode(const DeviceFrame& frame) const override {
    EncodedFrame out;
    out.bytes = mesh_file_bytes(frame.scene ? *frame.scene : Scene{}, format_, title_);
    return out;
  }
  std::unique_ptr<DeviceFile> open(const std::filesystem::path& path) const override {
    return open_byte_file(path);
  }

 private:
  MeshFormat format_;
  std::string title_;
};

}  // namespace

std::string mesh_file_bytes(const Scene& scene, MeshFormat format, const std::string& title) {
  std::vector<SurfaceOut> surfaces;
  std::vector<std::string> names;
  for (const SceneObject& object : scene.objects) {
    SurfaceOut surface = surface_of(*object.solid, format == MeshFormat::Stl);
    if (surface.polygons.empty()) continue;
    check_finite(surface);
    surfaces.push_back(std::move(surface));
    names.push_back(object.name);
  }
  switch (format) {
    case MeshFormat::Off:
      return off_bytes(surfaces, title);
    case MeshFormat::Obj:
      return obj_bytes(surfaces, names, title);
    case MeshFormat::Stl:
      return stl_bytes(surfaces, title);
  }
  return {};
}

std::unique_ptr<Device> make_mesh_device(MeshFormat format, const std::string& title) {
  return std::make_unique<MeshDevice>(format, title);
}

}  // namespace hlr::stdlib
