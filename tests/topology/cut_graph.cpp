// Cut graphs open every surface of the corpus into disks, with paired sides and corners at branch
// points; costs steer the cut; bad input is reported.
#include "corpus.h"

#include <tessera/topology.h>
#include <tessera/validation.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace tessera;

namespace {

struct Cut_run {
  Cut_result<Mesh> result;
  Cut_validation validation;
};

Cut_run run_cut(Mesh& mesh, Cut_method method) {
  auto seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  Cut_options options;
  options.method = method;
  Cut_run run{cut_to_disk(mesh, seam_e, seam_v, options), {}};
  run.validation = validate_cut(mesh, seam_e, seam_v, run.result);
  return run;
}

} // namespace

TEST_CASE("greedy and intermediate cuts open the corpus into disks", "[topology][cut]") {
  auto corpus = test::generated_corpus(5, 2);
  for (auto& r : test::real_corpus()) corpus.push_back(std::move(r));
  for (Cut_method method : {Cut_method::greedy, Cut_method::intermediate}) {
    for (auto& e : corpus) {
      INFO(e.name << (method == Cut_method::greedy ? " greedy" : " intermediate"));
      Mesh mesh = e.mesh;
      const Cut_run run = run_cut(mesh, method);
      INFO(run.result.message);
      for (const auto& p : run.validation.problems) INFO(p);
      REQUIRE(run.result);
      CHECK(run.validation.opens_to_disks);
      CHECK(run.validation.sides_paired);
      CHECK(run.validation.corners_are_branch_points);
      REQUIRE(run.result.polygons.size() == 1);
      CHECK(run.result.polygons[0].genus == e.genus);
      CHECK(run.result.polygons[0].boundaries == e.boundaries);
      // Euler: a disk from genus g with b boundaries; the cut is non-empty unless already a disk.
      if (e.genus > 0 || e.boundaries != 1) CHECK(run.result.cut_length > 0);
    }
  }
}
