// The shared test corpus: generated closed surfaces of genus 0..5, the same with holes, and the
// real meshes in tests/data with their known genus and boundary counts.
#pragma once

#include "paths.h"

#include <tessera/generators.h>
#include <tessera/io.h>
#include <tessera/types.h>

#include <string>
#include <vector>

namespace tessera::test {

struct Corpus_entry {
  std::string name;
  Mesh mesh;
  long genus;
  std::size_t boundaries;
};

/// The problems a validator reports, as one line for a Catch2 INFO (an INFO inside a loop ends with
/// the loop's body and would show nothing).
inline std::string joined(const std::vector<std::string>& problems) {
  std::string out;
  for (const auto& p : problems)
    out += (out.empty() ? "" : "; ") + p;
  return out;
}

inline Mesh load(const std::string& file) {
  Mesh m;
  const Read_mesh_result r = read_mesh(data_path(file), m);
  if (!r)
    throw std::runtime_error(r.message);
  return m;
}

/// Generated surfaces: genus 0..max_genus closed, and the same with `holes` boundaries.
inline std::vector<Corpus_entry> generated_corpus(std::size_t max_genus = 5,
                                                  std::size_t holes = 2) {
  std::vector<Corpus_entry> out;
  Genus_surface_options options;
  options.cell_resolution = 3;
  options.subdivision_steps = 1;
  for (std::size_t g = 0; g <= max_genus; ++g) {
    Corpus_entry e{"genus-" + std::to_string(g), {}, long(g), 0};
    make_genus_surface(e.mesh, g, options);
    out.push_back(e);
    if (holes > 0) {
      Corpus_entry h{e.name + "-holes", e.mesh, long(g), holes};
      punch_holes(h.mesh, holes, unsigned(g + 7));
      out.push_back(std::move(h));
    }
  }
  return out;
}

/// The real meshes copied from ../shared/data, with the genus and boundary counts published there.
inline std::vector<Corpus_entry> real_corpus() {
  struct Known {
    const char* file;
    long genus;
    std::size_t boundaries;
  };
  const Known known[] = {{"eight.off", 2, 0},    {"double-torus-example.off", 2, 0},
                         {"elephant.off", 3, 0}, {"knot1.off", 1, 0},
                         {"rotor.off", 1, 0},    {"cube-meshed.off", 0, 0},
                         {"fandisk.off", 0, 0},  {"mushroom.off", 0, 1},
                         {"pig.off", 0, 7},      {"mesh_with_border.off", 0, 1}};
  std::vector<Corpus_entry> out;
  for (const Known& k : known)
    out.push_back({k.file, load(k.file), k.genus, k.boundaries});
  return out;
}

} // namespace tessera::test
