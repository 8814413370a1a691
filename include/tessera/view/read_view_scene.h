// Builds a View_scene from the files a Tessera command wrote into its --out directory
// (doc/formats.md), or from a `tessera check --report` file, through Tessera's and CGAL's readers.
#pragma once

#include <tessera/view/view_scene.h>
#include <tessera/view/write_view_html.h>

#include <string>

namespace tessera {

/// A scene read from a result, with the status of reading it.
struct View_scene_result : View_result {
  View_scene scene;
};

/// Reads the result directory `dir` of cut, quadrangulate, field, mosaic, planar-mosaic, resize or
/// deform. The kind is told by the files present: quads.obj (quadrangulate), opened.off (cut),
/// field.csv (field), tiles.ply (mosaic), tiles.json without tiles.ply (planar-mosaic), resized.off
/// (resize), deformed.off (deform). `mesh` is the input mesh for results that do not write theirs
/// (field, mosaic, resize, deform: the before mesh), for a planar mosaic its input image; empty:
/// the path report.json gives, if any, else those layers are left out. A planar mosaic is a flat
/// scene (View_scene::flat) in its pixel frame with y up: the image, field.png and the tiles. A
/// regular file `dir` is read as a `tessera check --report` file (kind "check"): the surface of its
/// "input" (a result directory, an OBJ with texture coordinates or a mesh) with its charts
/// coloured, the seams, and the problems and notes at the vertices and faces they name.
View_scene_result read_view_scene(const std::string& dir, const std::string& mesh = {});

} // namespace tessera
