// Desens' (1969) verified test data, tests/data/desens_fixtures.json: the L-block and the aircraft carrier,
// their view parameters, per-node projections and the thesis's printed visible-line lists.
#pragma once

#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/camera/desens_camera.hpp"
#include "core/geometry/vector.hpp"

namespace hlr::test {

struct DesensView {
  std::string name;
  DesensParameters params;  // thesis_pi is left false; callers reproducing printed digits set it
};

struct DesensModel {
  std::map<int, Point3> nodes;              // node number → object coordinates (u, v, w)
  std::vector<std::vector<int>> faces;      // LSTFAC loops, as printed (carrier loops revisit nodes)
  std::map<std::string, DesensView> views;  // "L1".."L3" or "C1".."C5"
  // view → node → (depth x, Y′, Z′) as the thesis program computes them (with TPI = 3.1416/180)
  std::map<std::string, std::map<int, std::array<double, 3>>> projections;
  // view → the printed VISIBLE LINES rows (XSTART, YSTART, XEND, YEND) in picture coordinates
  std::map<std::string, std::vector<std::array<double, 4>>> thesis_lines;
  nlohmann::json raw;  // the model's whole JSON object, for the other fields
};

// "lblock" or "carrier"; loaded once and cached. Throws std::runtime_error for an unknown name or bad file.
const DesensModel& desens_model(const std::string& which);

// A view's printed visible lines (XSTART, YSTART, XEND, YEND) as a correct program draws them: the
// thesis's rows with the fixture's corrections applied — OCR repairs, exact values for the quantised
// T-junctions, edge 9–56 of Carrier (1) whole, and the two edges the 1969 program missed there
// (shared/reference/001_desens.md §5.4, fields thesis_corrections and known_deviations).
std::vector<std::array<double, 4>> desens_expected_lines(const DesensModel& model, const std::string& view);

}  // namespace hlr::test
