// Runner of the benchmark harness: tessera_bench [--quick] [--filter TEXT] [--out FILE]. The output
// file is read back on a --filter run, whose sections replace only those of the cases that ran.
#include "harness.h"

#include <tessera/blas_threads.h>

#include <sys/utsname.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
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

/// The sections of a results file (its header, up to the first "### " line, is dropped). A section
/// ends before the next "### " line; its trailing blank lines are not part of it. Its case is read
/// from its first line of text when that says "Measured ..., by the case `name`".
std::vector<Section> read_sections(std::istream& in) {
  std::vector<Section> sections;
  std::string line;
  std::size_t blank = 0; // blank lines read since the last line of text
  while (std::getline(in, line)) {
    if (line.rfind("### ", 0) == 0) {
      sections.push_back({line.substr(4), "", line + "\n"});
      blank = 0;
      continue;
    }
    if (sections.empty())
      continue;
    Section& s = sections.back();
    if (line.find_first_not_of(" \t\r") == std::string::npos) {
      ++blank;
      continue;
    }
    const bool first_text = s.text.find('\n') + 1 == s.text.size();
    s.text.append(blank, '\n');
    s.text += line + "\n";
    blank = 0;
    const std::string tag = ", by the case `";
    const std::size_t at = line.find(tag);
    if (first_text && line.rfind("Measured ", 0) == 0 && at != std::string::npos) {
      const std::size_t from = at + tag.size(), to = line.find('`', from);
      if (to != std::string::npos)
        s.case_name = line.substr(from, to - from);
    }
  }
  return sections;
}

/// The sections of a --filter run merged into the file's: a section whose heading this run wrote,
/// or whose case ran, is replaced where it stood by all sections of that case from this run (in
/// the order the case wrote them; a table the case no longer writes goes); sections of cases that
/// did not run are kept verbatim and in place; sections of cases new to the file are appended.
std::vector<Section> merge_sections(const std::vector<Section>& old,
                                    const std::vector<Section>& fresh,
                                    const std::set<std::string>& ran) {
  std::map<std::string, std::string> case_of_heading;
  for (const Section& s : fresh)
    case_of_heading.emplace(s.heading, s.case_name);
  std::vector<Section> out;
  std::set<std::string> emitted; // cases whose fresh sections are out
  const auto emit_case = [&](const std::string& name) {
    if (!emitted.insert(name).second)
      return;
    for (const Section& s : fresh)
      if (s.case_name == name)
        out.push_back(s);
  };
  for (const Section& s : old) {
    const auto by_heading = case_of_heading.find(s.heading);
    if (by_heading != case_of_heading.end())
      emit_case(by_heading->second);
    else if (ran.count(s.case_name))
      emit_case(s.case_name);
    else
      out.push_back(s);
  }
  for (const Section& s : fresh)
    emit_case(s.case_name);
  return out;
}

} // namespace

bool register_case(const std::string& name, Case fn) {
  registry().emplace_back(name, std::move(fn));
  return true;
}

void Report::open(const std::string& table) {
  if (rows_.count(table))
    return;
  order_.push_back(table);
  case_of_[table] = case_;
  rows_[table];
}

void Report::add(const std::string& table, Row row) {
  open(table);
  rows_[table].push_back(std::move(row));
}

void Report::note(const std::string& table, const std::string& text) {
  open(table);
  notes_[table].push_back(text);
}

std::vector<Section> Report::sections(const std::string& measured) const {
  std::vector<Section> out;
  for (const std::string& t : order_) {
    const std::string& name = case_of_.at(t);
    std::ostringstream os;
    os << "### " << t << "\n\n" << measured << ", by the case `" << name << "`.\n";
    const auto& rows = rows_.at(t);
    if (!rows.empty()) {
      os << "\n|";
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
    out.push_back({t, name, os.str()});
  }
  return out;
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
  tessera::set_blas_threads(1); // as the command-line tool: see tessera/blas_threads.h
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
  std::set<std::string> ran;
  for (auto& [name, fn] : registry()) {
    if (!filter.empty() && name.find(filter) == std::string::npos)
      continue;
    std::cout << "running " << name << "..." << std::endl;
    report.begin_case(name);
    fn(report, config);
    ran.insert(name);
  }
  if (ran.empty())
    std::cerr << "tessera_bench: no case matches '" << filter << "'\n";
  std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  const std::vector<Section> fresh =
      report.sections(std::string("Measured ") + date + " on " + machine_line() +
                      (config.quick ? " at --quick sizes" : ""));
  for (const Section& s : fresh)
    std::cout << "\n" << s.text;
  // A --filter run keeps the sections of the cases it did not run.
  std::vector<Section> sections = fresh;
  if (!filter.empty()) {
    std::ifstream in(out);
    if (in)
      sections = merge_sections(read_sections(in), fresh, ran);
  }
  const std::string tmp = out + ".tmp";
  {
    std::ofstream f(tmp);
    f << "# Tessera benchmark results\n\n"
      << "Written by `tessera_bench` (benchmarks/harness.cpp), not by hand: one section per table, "
         "each with the date (UTC), CPU and hardware threads of the run that measured it and the "
         "benchmark case that wrote it. `./build/benchmarks/tessera_bench` from the repository "
         "root runs every case and rewrites this file; `--filter TEXT` runs the cases whose name "
         "contains TEXT and replaces only their sections, keeping the others as they are. What "
         "changed between runs, and why: [doc/performance-notes.md]"
         "(../doc/performance-notes.md#benchmark-history).\n";
    for (const Section& s : sections)
      f << "\n" << s.text;
    if (!f.flush()) {
      std::cerr << "tessera_bench: cannot write " << tmp << "\n";
      return 1;
    }
  }
  if (std::rename(tmp.c_str(), out.c_str()) != 0) {
    std::cerr << "tessera_bench: cannot write " << out << "\n";
    return 1;
  }
  std::cout << "\nwrote " << out << "\n";
  return 0;
}
