// error_diffusion_points(): the first positions of a mosaic's tiles, by error diffusion over faces
// (Lai, Hu, Martin, "Surface Mosaics" §3.2): faces are visited by region growing; each takes its
// real-valued share N·A_T/A plus the error passed to it, places the rounded number of tiles at
// random points inside it, and passes the rounding error on to its neighbours not yet visited, so
// that the count matches N and the density follows the area.
#pragma once

#include <tessera/mosaic/internal/surface_arrays.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace tessera::internal {

/// `count` points spread over the surface by error diffusion; deterministic for a given `seed`.
/// With `face_weight` (one positive number per face) the density follows area × weight.
template <typename TriangleMesh>
std::vector<Surface_point> error_diffusion_points(const Surface_arrays<TriangleMesh>& s,
                                                  std::size_t count, unsigned seed,
                                                  const std::vector<double>& face_weight = {}) {
  std::vector<Surface_point> points;
  const std::size_t nf = s.number_of_faces();
  if (nf == 0 || !(s.total_area() > 0))
    return points;
  points.reserve(count + 1);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> carried(nf, 0);
  std::vector<char> seen(nf, 0);
  std::vector<std::uint32_t> queue;
  queue.reserve(nf);
  const bool weighted = face_weight.size() == nf;
  double weighted_area = 0;
  for (std::uint32_t f = 0; f < nf; ++f)
    weighted_area += s.area(f) * (weighted ? face_weight[f] : 1.0);
  const double density = double(count) / weighted_area;
  double leftover = 0; // the error left at the end of one component goes on to the next
  for (std::uint32_t start = 0; start < nf; ++start) {
    if (seen[start])
      continue;
    seen[start] = 1;
    carried[start] += leftover;
    leftover = 0;
    queue.assign(1, start);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t f = queue[head];
      // Neighbours across feature lines too: the error must not pile up in small regions.
      std::uint32_t open[3];
      int n_open = 0;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t g = s.across(f, k);
        if (g != no_index && !seen[g]) {
          seen[g] = 1;
          queue.push_back(g);
          open[n_open++] = g;
        }
      }
      const double share = density * s.area(f) * (weighted ? face_weight[f] : 1.0) + carried[f];
      const long placed = std::max(0L, std::lround(share));
      for (long i = 0; i < placed; ++i) {
        // Uniform in the triangle: the square-root warp of two uniform numbers.
        const double r1 = std::sqrt(unit(rng)), r2 = unit(rng);
        points.push_back({f, {{1 - r1, r1 * (1 - r2), r1 * r2}}});
      }
      const double error = share - double(placed);
      if (n_open > 0) {
        for (int k = 0; k < n_open; ++k)
          carried[open[k]] += error / n_open;
      } else if (head + 1 < queue.size()) {
        carried[queue[head + 1]] += error; // a dead end passes its error to the next face in line
      } else {
        leftover += error;
      }
    }
  }
  return points;
}

} // namespace tessera::internal
