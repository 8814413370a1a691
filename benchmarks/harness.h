// A small benchmark harness: named cases register themselves, each adds rows to named tables, and
// the runner prints the tables and writes them to a Markdown file (benchmarks/results.md by
// default, which the README links), one section per table with the date, machine and case of its
// run. A run with --filter replaces only the sections of the cases it ran and keeps the others.
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tessera::bench {

struct Config {
  /// Small sizes only (used by the test suite to check the cases still run).
  bool quick = false;
};

/// One table row: column name and formatted value, in order.
using Row = std::vector<std::pair<std::string, std::string>>;

/// One section of the results file: a table's heading and everything up to the next heading.
struct Section {
  std::string heading;   ///< the table's name (the line "### heading")
  std::string case_name; ///< the case that wrote it, read from its "Measured" line; empty if none
  std::string text;      ///< the section from "### " to its last non-blank line, '\n' ended
};

class Report {
public:
  /// Tables added from now on belong to the case `name` (called by the runner).
  void begin_case(const std::string& name) { case_ = name; }
  void add(const std::string& table, Row row);
  /// A note printed under the table (what was compared, what the target is).
  void note(const std::string& table, const std::string& text);
  /// The tables in the order they were first added, each a section whose line under the heading is
  /// `measured` (the date and machine) and the case that wrote it.
  std::vector<Section> sections(const std::string& measured) const;

private:
  void open(const std::string& table);
  std::string case_;
  std::vector<std::string> order_;
  std::map<std::string, std::string> case_of_;
  std::map<std::string, std::vector<Row>> rows_;
  std::map<std::string, std::vector<std::string>> notes_;
};

using Case = std::function<void(Report&, const Config&)>;

/// Registers a case; returns true so it can initialize a namespace-scope constant.
bool register_case(const std::string& name, Case fn);

/// Seconds taken by `f()`, the best of `repeats` runs.
double time_best(const std::function<void()>& f, int repeats = 1);

std::string fixed(double value, int digits);

/// The repository's tests/data directory. Defined in harness.cpp, the one translation unit compiled
/// with the checkout's absolute path, so ccache shares the cases' objects between clones.
std::string data_dir();

} // namespace tessera::bench

#define TESSERA_BENCH_CAT2(a, b) a##b
#define TESSERA_BENCH_CAT(a, b) TESSERA_BENCH_CAT2(a, b)
#define TESSERA_BENCHMARK(name, fn)                                                                \
  static const bool TESSERA_BENCH_CAT(tessera_bench_registered_, __LINE__) =                       \
      ::tessera::bench::register_case(name, fn)
