// Text output of doubles as the shortest decimal that reads back to the same double
// (std::to_chars), for the streams our mesh and field writers hand to CGAL's writers. A stream
// asked for max_digits10 (17) digits otherwise goes through printf's multi-precision formatting:
// on a 53k-face quadrangulation that was half the time of writing its three files (0.18 -> 0.11 s
// for the three, see doc/performance-notes.md), and the files are 8-10 % longer.
#pragma once

#include <algorithm>
#include <charconv>
#include <ios>
#include <limits>
#include <locale>
#include <ostream>

namespace tessera::internal {

/// A num_put facet that writes a double in the shortest round-trip form when the stream asks for
/// at least max_digits10 significant digits in the default (general) notation with no width; any
/// other request (fixed, scientific, a width, fewer digits, showpos, uppercase) is formatted by
/// the standard facet as before.
class Shortest_double_put : public std::num_put<char> {
public:
  using std::num_put<char>::num_put;

protected:
  iter_type do_put(iter_type out, std::ios_base& str, char fill, double v) const override {
    constexpr auto other_format =
        std::ios_base::floatfield | std::ios_base::showpos | std::ios_base::uppercase;
    if (str.precision() < std::numeric_limits<double>::max_digits10 || str.width() != 0 ||
        (str.flags() & other_format) != 0)
      return std::num_put<char>::do_put(out, str, fill, v);
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, v).ptr;
    return std::copy(text, end, out);
  }
};

/// Makes `os` write doubles at full precision in their shortest round-trip form.
inline void write_shortest_doubles(std::ostream& os) {
  os.imbue(std::locale(os.getloc(), new Shortest_double_put));
  os.precision(std::numeric_limits<double>::max_digits10);
}

} // namespace tessera::internal
