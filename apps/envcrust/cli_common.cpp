// Common flags, the terminal progress bar and output helpers of the CLI.
#include "cli_common.h"

#include "envcrust/io.h"

#include <sys/stat.h>
#include <unistd.h>

#include <charconv>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

namespace envcrust::cli {

void add_common_flags(CLI::App& command, CommonFlags& flags) {
  command.add_flag("--json", flags.json, "Print the report as JSON on stdout");
  command.add_flag("-q,--quiet", flags.quiet, "No progress bar and no text summary");
}

Progress terminal_progress(bool quiet) {
  Progress progress;
  if (quiet || isatty(STDERR_FILENO) == 0) return progress;
  struct Shown {
    std::string stage;
    int percent = -1;
  };
  auto last = std::make_shared<Shown>();
  progress.callback = [last](std::string_view stage, double fraction) {
    const int percent = static_cast<int>(fraction * 100.0 + 0.5);
    if (percent == last->percent && stage == last->stage) return;
    *last = {std::string(stage), percent};
    const int width = 30;
    const int filled = percent * width / 100;
    std::fprintf(stderr, "\r%-24.*s [%.*s%*s] %3d%%", static_cast<int>(stage.size()), stage.data(),
                 filled, "##############################", width - filled, "", percent);
    if (percent >= 100) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  };
  return progress;
}

std::string json_text(const nlohmann::json& document) {
  return document.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

void check_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& outputs) {
  std::vector<std::pair<std::string, std::filesystem::path>> seen;
  for (const auto& [flag, path] : outputs) {
    if (path.empty()) continue;
    std::error_code ec;
    std::filesystem::path resolved = std::filesystem::weakly_canonical(path, ec);
    if (ec) resolved = std::filesystem::absolute(path).lexically_normal();
    for (const auto& [other_flag, other] : seen)
      if (other == resolved) throw UsageError(other_flag + " and " + flag + " name the same file '" + path + "'");
    seen.emplace_back(flag, resolved);
  }
}

void check_outputs_are_not_inputs(const std::vector<std::pair<std::string, std::string>>& inputs,
                                  const std::vector<std::pair<std::string, std::string>>& outputs) {
  // stat() follows symlinks: two spellings, a link and its target, or two hard links of one
  // file all give one device and inode.
  auto identity = [](const std::string& path) -> std::optional<std::pair<dev_t, ino_t>> {
    struct stat info {};
    if (path.empty() || ::stat(path.c_str(), &info) != 0) return std::nullopt;
    return std::make_pair(info.st_dev, info.st_ino);
  };
  for (const auto& [out_flag, out_path] : outputs) {
    const auto out_id = identity(out_path);
    if (!out_id) continue;  // not written yet: no input can be it
    for (const auto& [in_flag, in_path] : inputs)
      if (identity(in_path) == out_id)
        throw UsageError(out_flag + " '" + out_path + "' is the " + in_flag + " file '" + in_path +
                         "' (the same file): writing it would replace the input; choose another output");
  }
}

void add_threads_option(CLI::App& command, int& threads) {
  command.add_option("--threads", threads, "Threads to run on (default: every core)")->check(whole_number_in(1, 4096));
}

std::unique_ptr<tbb::global_control> limit_threads(int threads) {
  if (threads <= 0) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                               static_cast<std::size_t>(threads));
}

int allowed_threads() {
  return static_cast<int>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
}

void print_json(const nlohmann::json& document) { std::cout << json_text(document); }

std::string percent(double fraction) {
  std::ostringstream out;
  out.precision(3);
  out << fraction * 100.0 << '%';
  return out.str();
}

namespace {

// A whole number in [min, max]; `expected` says which ("in 1..100", ">= 1").
CLI::Validator whole_number(long long min, long long max, const std::string& expected) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        long long value = 0;
        const char* end = text.data() + text.size();
        const auto [at, error] = std::from_chars(text.data(), end, value);
        if (error == std::errc() && at == end && value >= min && value <= max) return "";
        return "must be a whole number " + expected + " (got '" + text + "')";
      },
      "INT " + expected);
}

}  // namespace

CLI::Validator whole_number_at_least(long long min) {
  return whole_number(min, std::numeric_limits<long long>::max(), ">= " + std::to_string(min));
}

CLI::Validator whole_number_in(long long min, long long max) {
  return whole_number(min, max, "in " + std::to_string(min) + ".." + std::to_string(max));
}

render::Font read_checked_font(const std::string& path, int pixel_height) {
  render::Font font{io::read_binary_file(path), pixel_height};
  try {
    render::check_font(font);
  } catch (const InvalidInput& e) {
    throw InvalidInput(path + ": " + e.what());
  }
  return font;
}

CLI::Validator seed_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [at, error] = std::from_chars(text.data(), end, value);
        if (error == std::errc() && at == end) return "";
        return "must be a whole number from 0 to 18446744073709551615 (got '" + text + "')";
      },
      "");
}

CLI::Validator number_above(double min, bool inclusive) {
  std::ostringstream bound;
  bound << (inclusive ? ">= " : "> ") << min;
  return CLI::Validator(
      [min, inclusive, bound = bound.str()](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool parsed = !text.empty() && end == text.c_str() + text.size() && std::isfinite(value);
        if (parsed && (inclusive ? value >= min : value > min)) return "";
        return "must be a number " + bound + " (got '" + text + "')";
      },
      "NUMBER" + bound.str());
}

CLI::Validator number_in(double min, double max, bool min_inclusive, bool max_inclusive) {
  std::ostringstream range;
  range << (min_inclusive ? '[' : '(') << min << ", " << max << (max_inclusive ? ']' : ')');
  return CLI::Validator(
      [=, range = range.str()](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool parsed = !text.empty() && end == text.c_str() + text.size() && std::isfinite(value);
        if (parsed && (min_inclusive ? value >= min : value > min) && (max_inclusive ? value <= max : value < max))
          return "";
        return "must be a number in " + range + " (got '" + text + "')";
      },
      "FLOAT in " + range.str());
}

}  // namespace envcrust::cli
