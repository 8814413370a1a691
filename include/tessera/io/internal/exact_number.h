// Numbers written as exact text (mesh.exact.off).
#pragma once

#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/Number_types/internal/Exact_type_selector.h>

#include <ostream>
#include <type_traits>

namespace tessera {

namespace internal {

// A number as exact text: a lazy exact number as its exact value, a double as the rational it is
// (a double is a dyadic rational; its 17-digit decimal is not), anything else as it prints.
template <typename ET> void write_exact_number(std::ostream& os, const CGAL::Lazy_exact_nt<ET>& x) {
  os << CGAL::exact(x);
}
template <typename T> void write_exact_number(std::ostream& os, const T& x) {
  if constexpr (std::is_floating_point_v<T>)
    os << typename CGAL::internal::Exact_field_selector<double>::Type(double(x));
  else
    os << x;
}

} // namespace internal

} // namespace tessera
