#pragma once
// Wall-clock laps for the timings programs report (bake.json's "timings", ...).
#include <chrono>

namespace iblkit {

class Stopwatch {
 public:
  // Seconds since the previous call (or construction).
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace iblkit
