// libFuzzer target for the readers of cuttings made elsewhere and the validation behind them: any
// bytes are read as a seam file on a torus and as an OBJ with texture coordinates; whatever reads
// is validated (charts as disks, a schema or quads, texture folds), which must answer, never crash.
// The same bytes go through the exact readers (an OBJ layout over CGAL::Epeck, and OFF/OBJ files
// read by read_exact_polygon_mesh), where a number like 1e3000000 must be refused, not expanded.
// And as a vertex-set file (texture regions for texture-preserving resizing) on the torus: what
// reads marks exactly the vertices it counted; and as a deformation handles file (JSON): what
// reads has handles, each with a selection and finite numbers; as a control-vector file, whose
// controls are checked against the torus; and as `--features` / `--align` specifications.
#include <tessera/types.h>

#include <tessera/generators/surfaces.h>
#include <tessera/io/read_cutting.h>
#include <tessera/io/read_handles.h>
#include <tessera/fields/control_vectors.h>
#include <tessera/fields/feature_specs.h>
#include <tessera/io/read_vertex_set.h>
#include <tessera/topology/validate_charts.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const tessera::Mesh torus = [] {
    tessera::Mesh m;
    tessera::make_torus(m, 2.0, 0.7, 8, 6);
    return m;
  }();
  const std::string text(reinterpret_cast<const char*>(data), size);
  tessera::Validate_charts_options options;
  options.expect = tessera::Expected_cutting(size % 3);

  tessera::Mesh mesh = torus;
  auto seams =
      mesh.add_property_map<tessera::Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  std::istringstream seam_text(text);
  if (tessera::read_seams(seam_text, mesh, seams)) {
    const tessera::Cutting_validation v = tessera::validate_seams(mesh, seams, options);
    if (v && v.charts.empty())
      __builtin_trap();
  }

  std::istringstream ids_text(text);
  auto marked =
      mesh.add_property_map<tessera::Mesh::Vertex_index, bool>("v:tessera_marked", false).first;
  if (const tessera::Vertex_set_read_result r = tessera::read_vertex_set(ids_text, mesh, marked)) {
    std::size_t count = 0;
    for (auto v : vertices(mesh))
      count += marked[v] ? 1 : 0;
    if (count != r.count || count == 0)
      __builtin_trap();
  }

  std::istringstream handles_text(text);
  if (const tessera::Handles_read_result r = tessera::read_deformation_handles(handles_text)) {
    if (r.handles.empty())
      __builtin_trap();
    for (const auto& h : r.handles)
      if (!std::isfinite(h.transform.scale) || !(h.transform.scale > 0) ||
          !std::isfinite(h.transform.angle) || !std::isfinite(h.transform.twist))
        __builtin_trap();
  } else if (!r.handles.empty() || r.region || r.message.empty()) {
    __builtin_trap();
  }

  std::istringstream controls_text(text);
  if (const tessera::Control_vectors_read_result r = tessera::read_control_vectors(controls_text)) {
    const auto c = tessera::control_vector_constraints(torus, r.controls);
    if (c && c.constraints.size() < r.controls.size())
      __builtin_trap();
  } else if (!r.controls.empty() || r.message.empty()) {
    __builtin_trap();
  }
  if (const auto f = tessera::parse_feature_spec(text); !f && f.message.empty())
    __builtin_trap();
  if (const auto a = tessera::parse_alignment_spec(text, 7); a && a.alignment.size() != 7)
    __builtin_trap();

  std::istringstream obj_text(text);
  tessera::Uv_layout<tessera::Mesh> layout;
  if (tessera::read_obj_with_uvs(obj_text, layout)) {
    const tessera::Cutting_validation v =
        tessera::validate_charts(layout.mesh, layout.charts, layout.chart_to_mesh, options);
    if (v && v.charts.empty())
      __builtin_trap();
    tessera::validate_uv_layout(layout.charts, layout.uv);
  }

  std::istringstream exact_text(text);
  tessera::Uv_layout<tessera::Exact_mesh> exact_layout;
  if (tessera::read_obj_with_uvs(exact_text, exact_layout))
    tessera::validate_uv_layout(exact_layout.charts, exact_layout.uv);
  static const std::string stem = "/tmp/fuzz_read_cutting_" + std::to_string(getpid());
  for (const char* ext : {".off", ".obj"}) {
    const std::string path = stem + ext;
    std::ofstream(path, std::ios::binary) << text;
    tessera::Exact_mesh exact;
    tessera::read_exact_polygon_mesh(path, exact);
    std::remove(path.c_str());
  }
  return 0;
}
