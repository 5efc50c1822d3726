// Shared pieces of the CLI: common flags, terminal progress, JSON/text output helpers.
#pragma once

#include "envcrust/progress.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace envcrust::cli {

/// Flags every subcommand offers.
struct CommonFlags {
  bool json = false;   ///< print the report as JSON on stdout
  bool quiet = false;  ///< no progress bar and no human-readable summary
};

/// Add --json and --quiet to a subcommand.
void add_common_flags(CLI::App& command, CommonFlags& flags);

/// A Progress that draws a one-line bar on stderr when stderr is a terminal and not quiet.
Progress terminal_progress(bool quiet);

/// Print a JSON document on stdout (2-space indent, trailing newline).
void print_json(const nlohmann::json& document);

/// "1.23%" style formatting of a fraction.
std::string percent(double fraction);

/// Check of an option holding a count: a whole number >= `min`, else "must be a whole number
/// >= 1 (got '-5')" (CLI11's PositiveNumber takes 2.5, and a negative value read into an
/// unsigned option wraps around to a huge count).
CLI::Validator whole_number_at_least(long long min);

/// Check of a real option: a finite number above `min` (or at least `min` when `inclusive`),
/// else "must be a number > 0 (got '-1')" (CLI11's own checks print the whole double range).
CLI::Validator number_above(double min, bool inclusive = false);

/// Usage error raised by a subcommand after parsing (exit code 2, like CLI11's own errors).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace envcrust::cli
