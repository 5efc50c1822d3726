// Tables of measurements and their Markdown form.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "envcrust/errors.h"
#include "envcrust/experiments.h"

namespace envcrust::experiments {
namespace {

std::string format_number(double value) {
  if (!std::isfinite(value)) return std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
  char buffer[64];
  // Three significant digits, but never exponents for the magnitudes tables hold.
  if (std::abs(value) >= 1000)
    std::snprintf(buffer, sizeof buffer, "%.0f", value);
  else if (std::abs(value) >= 1e-4 || value == 0)
    std::snprintf(buffer, sizeof buffer, "%.3g", value);
  else
    std::snprintf(buffer, sizeof buffer, "%.2e", value);
  return buffer;
}

// Pipes inside a cell would split the Markdown column.
std::string escape(std::string text) {
  for (std::size_t i = text.find('|'); i != std::string::npos; i = text.find('|', i + 2)) text.replace(i, 1, "\\|");
  return text;
}

}  // namespace

void Table::add_row(std::vector<Cell> row) {
  if (row.size() != columns.size())
    throw InvalidInput("table '" + title + "': row of " + std::to_string(row.size()) + " cells, expected " +
                       std::to_string(columns.size()));
  rows.push_back(std::move(row));
}

std::size_t Table::column(std::string_view name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw InvalidInput("table '" + title + "' has no column '" + std::string(name) + "'");
}

std::string format_cell(const Cell& cell) {
  struct Visitor {
    std::string operator()(std::monostate) const { return "-"; }
    std::string operator()(bool b) const { return b ? "yes" : "no"; }
    std::string operator()(std::int64_t i) const { return std::to_string(i); }
    std::string operator()(double d) const { return format_number(d); }
    std::string operator()(const std::string& s) const { return s; }
  };
  return std::visit(Visitor{}, cell);
}

std::string to_markdown(const ExperimentResult& result) {
  std::ostringstream out;
  out << "## " << result.name << "\n\n" << result.description << "\n\n";
  for (const auto& table : result.tables) {
    if (!table.title.empty()) out << "**" << table.title << "**\n\n";
    out << "|";
    for (const auto& c : table.columns) out << " " << escape(c) << " |";
    out << "\n|";
    for (std::size_t i = 0; i < table.columns.size(); ++i) out << "---|";
    out << "\n";
    for (const auto& row : table.rows) {
      out << "|";
      for (const auto& cell : row) out << " " << escape(format_cell(cell)) << " |";
      out << "\n";
    }
    out << "\n";
  }
  for (const auto& note : result.notes) out << "- " << note << "\n";
  if (!result.notes.empty()) out << "\n";
  return out.str();
}

}  // namespace envcrust::experiments
