// Colour regions of a mesh read from an OFF or PLY file's per-face or per-vertex colours, as
// integer region ids per face: the borders between regions are feature lines for the field (Lai et
// al., §5).
#pragma once

#include <cstddef>
#include <string>

namespace tessera {

enum class Color_regions_status { ok, unsupported_extension, read_failed, no_colors, mismatch };

/// Summary of `read_color_regions()` and `read_face_colors()`.
struct Color_regions_result {
  Color_regions_status status = Color_regions_status::ok;
  std::string message;
  /// Where the colours came from.
  bool face_colors = false;
  /// Number of distinct colours (regions are numbered 0 .. regions−1 in colour order).
  std::size_t regions = 0;
  explicit operator bool() const { return status == Color_regions_status::ok; }
};

/// Reads the colours of `path` (OFF or PLY) for `tm`, which must have been read from the same file
/// by `read_mesh()` (vertices in file order). Face colours win over vertex colours; with vertex
/// colours a face takes the colour that at least two of its corners share (else its first
/// corner's). Faces that `read_mesh()` made by splitting a polygon keep the polygon's colour.
/// `face_region` receives an integer region id per face.
template <typename TriangleMesh, typename FaceRegionMap>
Color_regions_result read_color_regions(const std::string& path, const TriangleMesh& tm,
                                        FaceRegionMap face_region);

/// Reads the colours of `path` for `tm` as `read_color_regions()` does, and writes each face's
/// colour (a `CGAL::IO::Color`) into `face_color`: the file's colour of the face, or the mean of
/// its corners' vertex colours.
template <typename TriangleMesh, typename FaceColorMap>
Color_regions_result read_face_colors(const std::string& path, const TriangleMesh& tm,
                                      FaceColorMap face_color);

} // namespace tessera

#include <tessera/fields/internal/color_regions_impl.h>
