// Overloaded{lambdas...}: one visitor from several lambdas, for std::visit over the AST's variants (and
// the runtime's values).
#pragma once

namespace hlr::lang {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace hlr::lang
