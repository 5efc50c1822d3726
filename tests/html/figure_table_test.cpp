#include "figure_table.h"

#include <gtest/gtest.h>

namespace envcrust::cli::html {
namespace {

TEST(FigureTable, nested_values_are_listed_under_their_paths) {
  const nlohmann::json report = {{"input", "scan.xyz"},
                                 {"analysis", {{"euler_characteristic", 0}, {"is_orientable", false}}},
                                 {"rho", 0.0123456789},
                                 {"loops", {{{"vertices", 12}}, {{"vertices", 30}}}}};
  const auto rows = figure_rows(report);
  const std::vector<FigureRow> expected = {{"analysis.euler_characteristic", "0"},
                                           {"analysis.is_orientable", "false"},
                                           {"input", "scan.xyz"},
                                           {"loops[0].vertices", "12"},
                                           {"loops[1].vertices", "30"},
                                           {"rho", "0.0123457"}};
  EXPECT_EQ(rows, expected);
}

TEST(FigureTable, number_arrays_stay_on_one_row_and_long_ones_are_cut) {
  const nlohmann::json report = {{"short", {1, 2, 3}}, {"long", std::vector<int>(1000, 7)}, {"empty", nlohmann::json::array()}};
  const auto rows = figure_rows(report);
  const std::vector<FigureRow> expected = {
      {"empty", "(none)"}, {"long", "1000 values: 7, 7, 7, ..."}, {"short", "[1, 2, 3]"}};
  EXPECT_EQ(rows, expected);
}

TEST(FigureTable, rows_beyond_the_limits_are_counted_not_listed) {
  nlohmann::json loops = nlohmann::json::array();
  for (int i = 0; i < 20; ++i) loops.push_back({{"length", i}, {"vertices", 3}});
  const auto rows = figure_rows({{"loops", loops}}, 400, 4);
  ASSERT_EQ(rows.size(), 9u);  // 4 loops of 2 rows, and the rest counted
  EXPECT_EQ(rows.back(), FigureRow("loops", "... and 16 more (in the JSON report)"));
  const auto capped = figure_rows({{"loops", loops}}, 5, 12);
  ASSERT_EQ(capped.size(), 6u);
  EXPECT_EQ(capped.back(), FigureRow("...", "20 more figures in the JSON report"));
}

}  // namespace
}  // namespace envcrust::cli::html
