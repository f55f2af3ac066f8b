// An import's warnings, as a user reads them: in the order found, at most kWarningsPerKind of each kind,
// then one line counting the rest.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "stdlib/mesh_import.hpp"

namespace hlr::stdlib::mesh_detail {

inline constexpr std::size_t kWarningsPerKind = 10;

class Warnings {
 public:
  void add(const std::string& kind, MeshProblem problem);
  std::vector<MeshProblem> finish();

 private:
  std::vector<MeshProblem> problems_;
  std::map<std::string, std::size_t> counts_;
  std::map<std::string, std::string> file_of_;
  std::vector<std::string> order_;
};

}  // namespace hlr::stdlib::mesh_detail
