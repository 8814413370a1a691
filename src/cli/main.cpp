// Entry point of the tessera tool: argument parsing and error reporting only.
#include "commands.h"

#include <tessera/blas_threads.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
  tessera::set_blas_threads(1); // see tessera/blas_threads.h
  CLI::App app{"tessera: surface topology, tangent fields and mosaics on CGAL meshes"};
  app.require_subcommand(1);
  std::function<int()> run;
  tessera::cli::register_mesh_commands(app, run);
  tessera::cli::register_topology_commands(app, run);
  tessera::cli::register_quad_commands(app, run);
  tessera::cli::register_check_commands(app, run);
  tessera::cli::register_field_commands(app, run);
  tessera::cli::register_mosaic_commands(app, run);
  tessera::cli::register_planar_mosaic_commands(app, run);
  tessera::cli::register_resize_commands(app, run);
  tessera::cli::register_view_commands(app, run);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? tessera::cli::exit_ok : tessera::cli::exit_bad_input;
  }
  try {
    return run ? run() : tessera::cli::exit_ok;
  } catch (const tessera::cli::User_error& e) {
    std::cerr << "tessera: error: " << e.what() << "\n";
    return tessera::cli::exit_bad_input;
  } catch (const std::exception& e) {
    std::cerr << "tessera: internal error: " << e.what() << "\n";
    return tessera::cli::exit_internal;
  }
}
