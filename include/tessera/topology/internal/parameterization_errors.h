// Messages for CGAL's Surface_mesh_parameterization error codes. CGAL 5.5's own get_error_message()
// has 9 messages for its 10 codes (ERROR_NO_TOPOLOGICAL_BALL's is missing), so codes 4-8 get the
// message of the next code and ERROR_WRONG_PARAMETER a null pointer.
#pragma once

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <string>

namespace tessera::internal {

inline std::string
parameterization_error_message(CGAL::Surface_mesh_parameterization::Error_code code) {
  namespace SMP = CGAL::Surface_mesh_parameterization;
  switch (code) {
  case SMP::OK:
    return "success";
  case SMP::ERROR_EMPTY_MESH:
    return "the tile is empty";
  case SMP::ERROR_NON_TRIANGULAR_MESH:
    return "the tile is not triangulated";
  case SMP::ERROR_NO_TOPOLOGICAL_DISC:
    return "the tile is not a topological disk";
  case SMP::ERROR_NO_TOPOLOGICAL_BALL:
    return "the tile is not a topological ball";
  case SMP::ERROR_BORDER_TOO_SHORT:
    return "the tile's border is too short for this border map";
  case SMP::ERROR_NON_CONVEX_BORDER:
    return "this interior map needs a convex border";
  case SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM:
    return "the linear system could not be solved";
  case SMP::ERROR_NO_1_TO_1_MAPPING:
    return "the map is not one-to-one";
  case SMP::ERROR_WRONG_PARAMETER:
    return "a parameterizer received a wrong parameter";
  }
  return "unknown parameterization error " + std::to_string(int(code));
}

} // namespace tessera::internal
