// Reads a mesh (default: the genus-2 "eight"), remeshes faces many tiles wide (a CAD box of 12
// triangles), computes the smoothest cross field on it smoothed at the tiles' scale (along the
// boundaries, if any; turned along parts fewer than 8 tiles around), lays 400 square tiles along
// it as `tessera mosaic` does by default (Lai, Hu, Martin, "Surface Mosaics", 2006) and prints
// the run and how the tiles cover the surface.
#include <tessera/fields.h>
#include <tessera/io.h>
#include <tessera/mosaic.h>
#include <tessera/types.h>

#include <iostream>

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : TESSERA_EXAMPLE_DATA_DIR "/eight.off";
  tessera::Mesh mesh;
  const tessera::Read_mesh_result read = tessera::read_mesh(path, mesh);
  if (!read) {
    std::cerr << read.message << "\n";
    return 1;
  }
  // Tiles line up with the boundaries and stay off them.
  auto lines = tessera::feature_lines(mesh);
  tessera::Surface_mosaic_options options;
  options.tiles.tile_count = 400;
  const auto layout = tessera::surface_layout(mesh, options.tiles);
  if (!layout) {
    std::cerr << path << ": no surface area to lay tiles on\n";
    return 1;
  }
  // The field lives on the vertices: faces with edges over four tile spacings are remeshed first.
  tessera::refine_coarse_mesh(mesh, tessera::coarse_mesh_options(*layout), lines);
  const auto constraints =
      tessera::feature_alignment_constraints(mesh, lines, {tessera::Feature_alignment::parallel},
                                             tessera::feature_alignment_options(*layout));
  auto field =
      mesh.add_property_map<tessera::Mesh::Vertex_index, tessera::Vector_3>("v:tessera_field")
          .first;
  // The field solved on the surface smoothed at the tiles' scale (rows follow the shape, not its
  // small bumps) and turned along thin parts.
  auto points =
      mesh.add_property_map<tessera::Mesh::Vertex_index, tessera::Point_3>("v:tile_scale").first;
  tessera::tile_scale_points(mesh, layout->spacing, lines, points);
  const auto np = CGAL::parameters::vertex_point_map(points);
  const auto solved = tessera::smoothest_field_with_thin_parts(
      mesh, constraints, field, tessera::thin_part_options(*layout, lines), {}, np);
  if (!solved) {
    std::cerr << solved.message() << "\n";
    return 1;
  }

  const auto mosaic = tessera::surface_mosaic(mesh, field, lines, options);
  if (!mosaic) {
    std::cerr << mosaic.message << "\n";
    return 1;
  }
  const tessera::Mosaic_quality quality = tessera::mosaic_quality(mesh, mosaic.tiles, field, lines);
  std::cout << path << ": field turned along thin parts at " << solved.thin_parts.guided_vertices
            << " vertices\n"
            << mosaic.tiles.size() << " tiles of side " << mosaic.layout.tile_size[0] << ", "
            << mosaic.stats.iterations << " iterations"
            << (mosaic.stats.converged ? " (converged)" : "") << "\ncoverage " << quality.coverage
            << ", overlap " << quality.overlap << ", course drift median "
            << quality.course_drift_median << " degrees, widest bare patch " << quality.largest_gap
            << " tiles\n";
  return 0;
}
