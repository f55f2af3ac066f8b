// Frees a container's storage at once. `v = {}` does not: for a std::vector it assigns an empty
// initializer list and keeps the capacity, as `s = std::string()` keeps a long string's, so buffers meant
// to be let go early (an imported file's text, 37 MB for a 10⁶-triangle mesh) stayed until their scope
// ended, and the stages after them took fresh memory instead.
#pragma once

namespace hlr {

template <typename Container>
void release(Container& c) noexcept {
  Container().swap(c);
}

}  // namespace hlr
