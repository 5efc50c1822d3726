// Shared pieces of the CLI: common flags, terminal progress, JSON/text output helpers.
#pragma once

#include "envcrust/errors.h"
#include "envcrust/progress.h"
#include "envcrust/render.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace envcrust::cli {

/// Flags every subcommand offers.
struct CommonFlags {
  bool json = false;   ///< print the report as JSON on stdout
  bool quiet = false;  ///< no progress bar and no human-readable summary
  int threads = 0;     ///< --threads (add_threads_option); 0: every core
};

/// Add --json and --quiet to a subcommand.
void add_common_flags(CLI::App& command, CommonFlags& flags);

/// A Progress that draws a one-line bar on stderr when stderr is a terminal and not quiet.
Progress terminal_progress(bool quiet);

/// The document as indented JSON text ending in a newline; invalid UTF-8 in strings (file
/// names are bytes) is replaced rather than refused.
std::string json_text(const nlohmann::json& document);

/// Refuses two outputs of one run that name the same file ("-o and --envelope-out name the
/// same file 'out.ply'"): the later one would silently replace the earlier. Pairs of (flag,
/// path); empty paths are not written and skipped. @throws UsageError
void check_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& outputs);

/// Refuses an output that is the same file as an input: the same device and inode, whatever
/// the spelling (another path to it, a symlink, a hard link), since writing the output would
/// replace the input ("-o 'b.xyz' is the input file 'a.xyz' (the same file): choose another
/// output"). Pairs of (flag, path); inputs that are no file (builtin:NAME) and outputs that do
/// not exist yet are skipped. @throws UsageError
void check_outputs_are_not_inputs(const std::vector<std::pair<std::string, std::string>>& inputs,
                                  const std::vector<std::pair<std::string, std::string>>& outputs);

/// Add `--threads N` (N >= 1; unset: every core) to a heavy subcommand.
void add_threads_option(CLI::App& command, int& threads);

/// Limits oneTBB to `threads` workers while the result lives (0: no limit, every core).
std::unique_ptr<tbb::global_control> limit_threads(int threads);

/// The number of threads oneTBB may use now (what --threads set, else the cores).
int allowed_threads();

/// Print a JSON document on stdout (json_text).
void print_json(const nlohmann::json& document);

/// "1.23%" style formatting of a fraction.
std::string percent(double fraction);

/// Check of an option holding a count: a whole number >= `min`, else "must be a whole number
/// >= 1 (got '-5')" (CLI11's PositiveNumber takes 2.5, and a negative value read into an
/// unsigned option wraps around to a huge count).
CLI::Validator whole_number_at_least(long long min);

/// The same with an upper bound: "must be a whole number in 1..100000000 (got '1e12')".
CLI::Validator whole_number_in(long long min, long long max);

/// The font file `path` read and checked for captions at `pixel_height`.
/// @throws IoError when it cannot be read; InvalidInput naming it when FreeType cannot use it.
render::Font read_checked_font(const std::string& path, int pixel_height);

/// A seed: a whole number from 0 to 2^64 - 1, as typed (CLI11 alone wraps -1 and saturates
/// 99999999999999999999 without a word). Its description is empty: the help stays "UINT".
CLI::Validator seed_number();

/// Most points a command draws or measures with (-n, --samples): 1e8 points with normals
/// take 4.8 GB before any stage runs; more fail to allocate on common machines.
inline constexpr long long kMaxPointCount = 100'000'000;

/// Check of a real option: a finite number above `min` (or at least `min` when `inclusive`),
/// else "must be a number > 0 (got '-1')" (CLI11's own checks print the whole double range).
CLI::Validator number_above(double min, bool inclusive = false);

/// Check of a real option in a range: a finite number between `min` and `max`, each bound
/// included or not, else "must be a number in (0, 4] (got 'nan')" (CLI11's Range lets NaN by).
CLI::Validator number_in(double min, double max, bool min_inclusive, bool max_inclusive);

/// Runs a stage on an input, naming the input (`spec`) at the head of what the stage refuses
/// (DegenerateInput, NumericalFailure, InvalidInput), unless the message already starts so.
template <class Stage>
auto naming_input(const std::string& spec, Stage&& stage) {
  auto named = [&](const std::string& what) { return what.rfind(spec + ":", 0) == 0 ? what : spec + ": " + what; };
  try {
    return stage();
  } catch (const DegenerateInput& e) {
    throw DegenerateInput(named(e.what()));
  } catch (const NumericalFailure& e) {
    throw NumericalFailure(named(e.what()));
  } catch (const InvalidInput& e) {
    throw InvalidInput(named(e.what()));
  }
}

/// Usage error raised by a subcommand after parsing (exit code 2, like CLI11's own errors).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Exit code of a run that wrote its result, but the result fails its own checks (see
/// ChecksFailed).
inline constexpr int kExitChecksFailed = 4;

/// Raised after a run wrote all its outputs and printed its report, when the result fails its
/// own checks: main() prints the message and exits with kExitChecksFailed, so that a script
/// can tell such a result from a sound one.
class ChecksFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace envcrust::cli
