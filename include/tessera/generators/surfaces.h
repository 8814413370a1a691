// Generators of the test corpus: closed surfaces of any genus at chosen resolutions (sphere, torus
// of revolution, genus-g "plate with g holes" smoothed by Loop subdivision) and a way to punch
// holes in them to get bordered surfaces. They write into any MutableFaceGraph through a polygon
// soup.
#pragma once

#include <cstddef>

namespace tessera {

/// Torus of revolution around the z axis: `major_radius` R from the axis to the tube's centre,
/// `minor_radius` r of the tube, `u_segments` around the axis and `v_segments` around the tube
/// (2·u·v triangles, genus 1).
template <typename MutableFaceGraph>
void make_torus(MutableFaceGraph& tm, double major_radius, double minor_radius,
                std::size_t u_segments, std::size_t v_segments);

/// Capsule along the x axis: a cylinder of radius `radius` whose axis runs from x = −length/2 to
/// length/2, closed by two hemispheres, with `segments` (a multiple of 4, at least 8) vertices
/// around it and rings about as far apart along it as around (genus 0, outward oriented).
template <typename MutableFaceGraph>
void make_capsule(MutableFaceGraph& tm, double radius, double length, std::size_t segments);

/// Geodesic sphere: an icosahedron whose triangles are split `subdivisions` times into four, every
/// vertex projected onto the sphere (20·4^s triangles, genus 0).
template <typename MutableFaceGraph>
void make_sphere(MutableFaceGraph& tm, double radius, std::size_t subdivisions);

/// Options of `make_genus_surface()`.
struct Genus_surface_options {
  /// Lattice squares along each side of one unit cell of the plate.
  std::size_t cell_resolution = 4;
  /// Lattice steps across the plate's thickness on the walls.
  std::size_t wall_resolution = 2;
  /// Thickness of the plate, in cell units.
  double thickness = 0.6;
  /// Loop subdivision steps applied after building the plate (each multiplies faces by 4 and
  /// rounds the plate's sharp edges).
  std::size_t subdivision_steps = 1;
};

/// Number of triangles `make_genus_surface(tm, genus, options)` produces.
inline std::size_t genus_surface_face_count(std::size_t genus, const Genus_surface_options& o);

/// A closed surface of genus `genus` (0 gives a rounded box): a plate of (2g+1) x 3 unit cells with
/// the g cells (2i+1, 1) removed, its top, bottom and walls triangulated on a lattice, then
/// smoothed by Loop subdivision.
template <typename MutableFaceGraph>
void make_genus_surface(MutableFaceGraph& tm, std::size_t genus,
                        const Genus_surface_options& options = {});

/// Removes the closed stars of `holes` vertices chosen at random but at least 4 edges apart from
/// each other and from any existing boundary, so each removal adds exactly one boundary loop and
/// leaves the genus unchanged. Returns the number of holes made (fewer when the mesh is too small).
template <typename MutableFaceGraph>
std::size_t punch_holes(MutableFaceGraph& tm, std::size_t holes, unsigned seed = 1);

} // namespace tessera

#include <tessera/generators/internal/surfaces_impl.h>
