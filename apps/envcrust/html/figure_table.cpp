#include "figure_table.h"

#include <algorithm>
#include <sstream>

namespace envcrust::cli::html {
namespace {

std::string scalar_text(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_float()) {
    std::ostringstream text;
    text.precision(6);
    text << value.get<double>();
    return text.str();
  }
  if (value.is_null()) return "none";
  return value.dump();
}

bool is_number_array(const nlohmann::json& value) {
  return value.is_array() && !value.empty() &&
         std::all_of(value.begin(), value.end(), [](const nlohmann::json& v) { return v.is_number(); });
}

struct Collector {
  std::size_t max_rows, max_elements;
  std::vector<FigureRow> rows;
  std::size_t left_out = 0;

  void add(std::string path, std::string text) {
    if (rows.size() < max_rows) {
      rows.emplace_back(std::move(path), std::move(text));
    } else {
      ++left_out;
    }
  }

  void visit(const std::string& path, const nlohmann::json& value) {
    if (value.is_object()) {
      if (value.empty()) add(path, "(none)");
      for (const auto& [key, item] : value.items()) visit(path.empty() ? key : path + "." + key, item);
    } else if (is_number_array(value)) {
      std::string text = value.size() > 8 ? std::to_string(value.size()) + " values: " : "[";
      const std::size_t shown = value.size() > 8 ? 3 : value.size();
      for (std::size_t i = 0; i < shown; ++i) text += (i ? ", " : "") + scalar_text(value[i]);
      add(path, text + (value.size() > 8 ? ", ..." : "]"));
    } else if (value.is_array()) {
      if (value.empty()) add(path, "(none)");
      const std::size_t shown = std::min(value.size(), max_elements);
      for (std::size_t i = 0; i < shown; ++i) visit(path + "[" + std::to_string(i) + "]", value[i]);
      if (shown < value.size())
        add(path, "... and " + std::to_string(value.size() - shown) + " more (in the JSON report)");
    } else {
      add(path, scalar_text(value));
    }
  }
};

}  // namespace

std::vector<FigureRow> figure_rows(const nlohmann::json& report, std::size_t max_rows, std::size_t max_elements) {
  Collector collector{max_rows, max_elements, {}, 0};
  collector.visit("", report);
  if (collector.left_out > 0)
    collector.rows.emplace_back("...", std::to_string(collector.left_out) + " more figures in the JSON report");
  return collector.rows;
}

}  // namespace envcrust::cli::html
