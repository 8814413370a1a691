// Peak memory at scale (issue 17, item 5): genus-10 generated surfaces of about 1M, 5M and 10M
// faces are written to OFF, and the commands each run on them as a child process whose peak
// resident set (max RSS) wait4() reports, against the mesh's own size in memory: `info`, `cut` and
// `field` at every size, `quadrangulate` and `mosaic` up to 5M, `resize` (TetGen) at 1M. Then a
// 10M-face plate of nothing but slivers (item 3) through `info`, `cut` and `field`.
#include "harness.h"

#include <tessera/generators.h>
#include <tessera/generators/textures.h>
#include <tessera/io.h>
#include <tessera/types.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace tessera;

struct Child {
  int status = -1;
  double seconds = 0;
  long max_rss_kb = 0;
};

// Runs `args` (args[0] the program) with its output thrown away; its exit status, wall time and
// peak resident set.
Child run_child(const std::vector<std::string>& args) {
  Child c;
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    std::vector<char*> argv;
    for (const std::string& a : args)
      argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  if (pid < 0)
    return c;
  rusage usage{};
  int status = 0;
  if (wait4(pid, &status, 0, &usage) != pid)
    return c;
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  c.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  c.max_rss_kb = usage.ru_maxrss;
  return c;
}

// Bytes of a Surface_mesh's own arrays: per vertex its point and halfedge, per halfedge its next,
// previous, target vertex and face, per face its halfedge (removal flags are bits).
double mesh_bytes(std::size_t vertices, std::size_t halfedges, std::size_t faces) {
  return double(vertices) * (sizeof(Point_3) + 4) + double(halfedges) * 16 + double(faces) * 4;
}

void memory(bench::Report& report, const bench::Config& config) {
  const std::string table = "Reliability: peak memory (max RSS) per command on genus-10 surfaces";
  const std::filesystem::path cli =
      std::filesystem::read_symlink("/proc/self/exe").parent_path().parent_path() / "tessera";
  if (!std::filesystem::exists(cli)) {
    report.note(table, "Not measured: the tessera command was not built beside the benchmarks.");
    return;
  }
  // Per process: the test suite runs this case too (--quick) and removes its directory at the end.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("tessera_bench_memory-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  // TESSERA_BENCH_MEMORY_ONLY=slivers (or =genus) runs one part alone: the full run takes hours.
  const char* only_env = std::getenv("TESSERA_BENCH_MEMORY_ONLY");
  const std::string only = only_env ? only_env : "";
  std::vector<double> targets =
      config.quick ? std::vector<double>{2e4} : std::vector<double>{1e6, 5e6, 1e7};
  if (only == "slivers")
    targets.clear();
  long floor_kb = 0; // the benchmark's own peak, which every child's figure may include
  const std::string off = (dir / "surface.off").string();
  // The surface is made and written by a child process: a child's ru_maxrss counts the pages it
  // had at fork, so the benchmark itself must stay small.
  const auto make_in_child = [&](const auto& make) {
    const pid_t maker = fork();
    if (maker == 0) {
      Mesh mesh;
      make(mesh);
      _exit(write_mesh(off, mesh) ? 0 : 1);
    }
    int made = -1;
    if (maker < 0 || waitpid(maker, &made, 0) != maker || !WIFEXITED(made) ||
        WEXITSTATUS(made) != 0)
      throw std::runtime_error("cannot make " + off);
    rusage self{};
    getrusage(RUSAGE_SELF, &self);
    floor_kb = std::max(floor_kb, long(self.ru_maxrss));
  };
  const auto measure = [&](const std::string& surface, std::size_t faces, double own,
                           const std::vector<std::string>& commands) {
    const std::string file_mb = bench::fixed(double(std::filesystem::file_size(off)) / 1e6, 0);
    for (const std::string& command : commands) {
      std::vector<std::string> args{cli.string(), command, off};
      if (command == "mosaic") // one tile per 50 faces, a usual density
        args.insert(args.end(), {"--tiles", std::to_string(faces / 50)});
      if (command == "resize")
        args.insert(args.end(), {"--scale", "2,1,1"});
      if (command != "info")
        args.insert(args.end(), {"--out", (dir / command).string(), "--force"});
      const Child c = run_child(args);
      const double rss = double(c.max_rss_kb) * 1024;
      std::cerr << "memory: " << surface << ", " << faces << " faces, " << command << ": exit "
                << c.status << ", " << c.seconds << " s, " << rss / 1e6 << " MB\n";
      report.add(table, {{"surface", surface},
                         {"faces", std::to_string(faces)},
                         {"OFF file (MB)", file_mb},
                         {"mesh in memory (MB)", bench::fixed(own / 1e6, 0)},
                         {"command", command},
                         {"exit code", std::to_string(c.status)},
                         {"seconds", bench::fixed(c.seconds, 1)},
                         {"max RSS (MB)", bench::fixed(rss / 1e6, 0)},
                         {"max RSS / mesh", bench::fixed(rss / own, 1)}});
    }
  };
  for (const double target : targets) {
    // Faces grow as the square of the cell resolution (one Loop step).
    Genus_surface_options o;
    o.cell_resolution = 1;
    while (double(genus_surface_face_count(10, o)) < target) {
      ++o.cell_resolution;
      o.wall_resolution = std::max<std::size_t>(1, o.cell_resolution / 2);
    }
    make_in_child([&](Mesh& mesh) { make_genus_surface(mesh, 10, o); });
    // A closed genus-10 triangle mesh: E = 3F/2 and V = E - F + 2 - 2g.
    const std::size_t faces = genus_surface_face_count(10, o);
    std::vector<std::string> commands{"info", "cut", "field"};
    if (target <= 5e6)
      commands.insert(commands.end(), {"quadrangulate", "mosaic"});
    if (target <= 1e6)
      commands.push_back("resize");
    measure("genus 10", faces, mesh_bytes(faces / 2 - 18, 3 * faces, faces), commands);
  }
  if (only != "genus") {
    // Slivers: a unit square plate of n x n cells, two triangles each, squashed a millionfold.
    const std::size_t n = config.quick ? 100 : 2237;
    make_in_child([&](Mesh& mesh) {
      make_plate(mesh, 1, 1, double(n));
      for (auto v : vertices(mesh))
        mesh.point(v) = Point_3(mesh.point(v).x(), 1e-6 * mesh.point(v).y(), 0);
    });
    const std::size_t faces = 2 * n * n;
    measure("slivers 1e-6", faces, mesh_bytes((n + 1) * (n + 1), 2 * (3 * n * n + 2 * n), faces),
            {"info", "cut", "field"});
  }
  std::filesystem::remove_all(dir);
  report.note(
      table,
      "The benchmark process itself peaked at " + bench::fixed(double(floor_kb) / 1e3, 0) +
          " MB, a floor under every figure (a child's ru_maxrss counts the pages it had at fork). "
          "Each command runs as a child process of the benchmark (fork, exec, wait4's ru_maxrss) "
          "on a surface written as OFF (17 digits); `cut` is the default greedy cut with "
          "its validation, opened mesh and picture, `field` the smoothest 4-field with its CSV "
          "and picture, `quadrangulate` the default (greedy) quadrangulation with every file it "
          "writes, `mosaic` one tile per 50 faces along the smoothest field, `resize` 2x along x "
          "(non-homogeneous, TetGen's volume mesh). The sliver plate is a unit square of 2237 x "
          "2237 cells squashed a millionfold along y: every triangle has an aspect ratio of 1e6. "
          "'Mesh in memory' is a Surface_mesh's own arrays (point and halfedge per "
          "vertex, four indices per halfedge, one per face). Target (issue 17): a documented "
          "bound per command, and a 10M-face input through info, cut and field on this 24 GiB "
          "machine.");
}

} // namespace

TESSERA_BENCHMARK("memory", memory);
