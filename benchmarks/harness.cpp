// Runner of the benchmark harness: tessera_bench [--quick] [--filter TEXT] [--out FILE].
#include "harness.h"

#include <sys/utsname.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace tessera::bench {
namespace {

std::vector<std::pair<std::string, Case>>& registry() {
  static std::vector<std::pair<std::string, Case>> cases;
  return cases;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0)
      return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

std::string machine_line() {
  utsname u{};
  uname(&u);
  std::ostringstream os;
  os << cpu_model() << ", " << std::thread::hardware_concurrency() << " hardware threads, "
     << u.sysname << " " << u.release;
  return os.str();
}

} // namespace

bool register_case(const std::string& name, Case fn) {
  registry().emplace_back(name, std::move(fn));
  return true;
}

void Report::add(const std::string& table, Row row) {
  if (!rows_.count(table))
    order_.push_back(table);
  rows_[table].push_back(std::move(row));
}

void Report::note(const std::string& table, const std::string& text) {
  if (!rows_.count(table)) {
    order_.push_back(table);
    rows_[table];
  }
  notes_[table].push_back(text);
}

std::string Report::markdown() const {
  std::ostringstream os;
  for (const std::string& t : order_) {
    os << "\n### " << t << "\n\n";
    const auto& rows = rows_.at(t);
    if (!rows.empty()) {
      os << "|";
      for (const auto& c : rows.front())
        os << " " << c.first << " |";
      os << "\n|";
      for (std::size_t i = 0; i < rows.front().size(); ++i)
        os << "---|";
      os << "\n";
      for (const Row& r : rows) {
        os << "|";
        for (const auto& c : r)
          os << " " << c.second << " |";
        os << "\n";
      }
    }
    if (notes_.count(t))
      for (const std::string& n : notes_.at(t))
        os << "\n" << n << "\n";
  }
  return os.str();
}

double time_best(const std::function<void()>& f, int repeats) {
  double best = 1e300;
  for (int i = 0; i < std::max(1, repeats); ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

std::string data_dir() {
  return TESSERA_BENCH_DATA_DIR;
}

std::string fixed(double value, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, value);
  return buf;
}

} // namespace tessera::bench

int main(int argc, char** argv) {
  using namespace tessera::bench;
  Config config;
  std::string filter, out = "benchmarks/results.md";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick")
      config.quick = true;
    else if (a == "--filter" && i + 1 < argc)
      filter = argv[++i];
    else if (a == "--out" && i + 1 < argc)
      out = argv[++i];
    else {
      std::cerr << "usage: tessera_bench [--quick] [--filter TEXT] [--out FILE]\n";
      return 1;
    }
  }
  Report report;
  for (auto& [name, fn] : registry()) {
    if (!filter.empty() && name.find(filter) == std::string::npos)
      continue;
    std::cout << "running " << name << "..." << std::endl;
    fn(report, config);
  }
  const std::string body = report.markdown();
  std::cout << body;
  std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  std::ofstream f(out);
  if (!f) {
    std::cerr << "tessera_bench: cannot write " << out << "\n";
    return 1;
  }
  f << "# Tessera benchmark results\n\nMeasured " << date << " on " << machine_line() << ".\n"
    << "Regenerate with `./build/benchmarks/tessera_bench` from the repository root"
    << (config.quick ? " (this run used --quick sizes)" : "") << ".\n"
    << (filter.empty() ? "" : "Cases run: those matching '" + filter + "'.\n") << body;
  std::cout << "\nwrote " << out << "\n";
  return 0;
}
