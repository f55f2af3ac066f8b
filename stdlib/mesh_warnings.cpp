#include "stdlib/mesh_warnings.hpp"

#include <utility>

namespace hlr::stdlib::mesh_detail {

void Warnings::add(const std::string& kind, MeshProblem problem) {
  auto [it, fresh] = counts_.try_emplace(kind, 0);
  if (fresh) order_.push_back(kind);
  if (++it->second <= kWarningsPerKind) {
    problems_.push_back(std::move(problem));
    if (it->second == 1) file_of_[kind] = problems_.back().file;
  }
}

std::vector<MeshProblem> Warnings::finish() {
  for (const std::string& kind : order_) {
    const std::size_t n = counts_[kind];
    if (n > kWarningsPerKind)
      problems_.push_back(
          {file_of_[kind], 0, 0,
           std::to_string(n - kWarningsPerKind) + " more warnings of this kind [" + kind + "]", ""});
  }
  return std::move(problems_);
}

}  // namespace hlr::stdlib::mesh_detail
