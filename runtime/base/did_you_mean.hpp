// "did you mean 'box'?": the hint for a misspelt name, used by every room that reports one.
#pragma once

#include <string>
#include <vector>

namespace hlr::runtime {

// "did you mean 'box'?" for the closest candidate within a small edit distance, else "".
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace hlr::runtime
