// Progress on stderr for long stages: nothing for a stage that ends within a second, then one line
// a second ("tessera: cutting paths 12/48, 3.1 s") and a last one when it completes; and `timed`,
// which names a stage without steps (writing a file, validating) when it took more than a second.
#pragma once

#include <tessera/progress.h>

#include <chrono>
#include <iostream>
#include <string>
#include <utility>

namespace tessera::cli {

class Progress_printer {
public:
  /// A callback for an options struct's `progress`; the printer must outlive its use.
  Progress_callback callback() {
    return [this](const Progress& p) { report(p); };
  }

  void report(const Progress& p) {
    const auto now = Clock::now();
    if (stage_ != p.stage) {
      stage_ = p.stage;
      start_ = last_ = now;
    }
    const double elapsed = seconds(start_, now);
    const bool last = p.total > 0 && p.done >= p.total;
    if (elapsed < 1 || (!last && seconds(last_, now) < 1))
      return;
    last_ = now;
    std::cerr << "tessera: " << p.stage << " " << p.done;
    if (p.total > 0)
      std::cerr << "/" << p.total;
    std::cerr << ", " << static_cast<long>(elapsed * 10) / 10.0 << " s\n";
  }

private:
  using Clock = std::chrono::steady_clock;
  static double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  }
  std::string stage_;
  Clock::time_point start_, last_;
};

/// Runs `f()` and says on stderr how long `stage` took when it took more than a second.
template <typename F> decltype(auto) timed(const char* stage, F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  struct Say {
    const char* stage;
    std::chrono::steady_clock::time_point t0;
    ~Say() {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (s >= 1)
        std::cerr << "tessera: " << stage << ", " << static_cast<long>(s * 10) / 10.0 << " s\n";
    }
  } say{stage, t0};
  return std::forward<F>(f)();
}

} // namespace tessera::cli
