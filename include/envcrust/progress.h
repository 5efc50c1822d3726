// Progress reporting and cancellation for long stages, without printing anything.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <string_view>

namespace envcrust {

/// Passed to long stages. The stage calls report(stage_name, fraction in [0,1]); the caller
/// (the CLI) decides whether to draw a bar. Setting `cancel` asks the stage to stop early.
struct Progress {
  std::function<void(std::string_view stage, double fraction)> callback;
  const std::atomic<bool>* cancel = nullptr;

  void report(std::string_view stage, double fraction) const {
    if (callback) callback(stage, fraction);
  }
  [[nodiscard]] bool is_cancelled() const { return cancel != nullptr && cancel->load(); }
};

/// Wall-clock seconds of the steps of a stage: lap() returns the time since construction or
/// the last lap.
class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace envcrust
