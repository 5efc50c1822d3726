// Progress reporting and cancellation for long stages, without printing anything.
#pragma once

#include <atomic>
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

}  // namespace envcrust
