// Tables, cell formatting, Markdown and the registry of experiments.
#include <gtest/gtest.h>

#include "envcrust/errors.h"
#include "envcrust/experiments.h"

namespace envcrust::experiments {
namespace {

TEST(Table, cells_format_as_yes_no_integers_and_three_significant_digits) {
  EXPECT_EQ(format_cell(Cell{}), "-");
  EXPECT_EQ(format_cell(Cell{true}), "yes");
  EXPECT_EQ(format_cell(Cell{false}), "no");
  EXPECT_EQ(format_cell(Cell{std::int64_t{40000}}), "40000");
  EXPECT_EQ(format_cell(Cell{0.083312}), "0.0833");
  EXPECT_EQ(format_cell(Cell{12345.6}), "12346");
  EXPECT_EQ(format_cell(Cell{std::string("trefoil,trefoil")}), "trefoil,trefoil");
}

TEST(Table, a_row_of_the_wrong_width_is_refused_with_the_counts) {
  Table t;
  t.title = "t";
  t.columns = {"a", "b"};
  try {
    t.add_row({Cell{true}});
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "table 't': row of 1 cells, expected 2");
  }
  EXPECT_EQ(t.column("b"), 1u);
  EXPECT_THROW((void)t.column("c"), InvalidInput);
}

TEST(Table, markdown_has_a_header_a_separator_and_escaped_pipes) {
  ExperimentResult r;
  r.name = "demo";
  r.description = "what it shows";
  Table t;
  t.columns = {"|lk|", "ok"};
  t.add_row({std::int64_t{3}, true});
  r.tables.push_back(t);
  r.notes.push_back("a finding");
  EXPECT_EQ(to_markdown(r), "## demo\n\nwhat it shows\n\n| \\|lk\\| | ok |\n|---|---|\n| 3 | yes |\n\n- a finding\n\n");
}

TEST(Registry, lists_the_paper_experiments_in_figure_order) {
  std::vector<std::string> names;
  for (const auto& e : experiment_list()) names.push_back(e.name);
  EXPECT_EQ(names, (std::vector<std::string>{"trefoil", "cylinder", "scan", "paraboloid", "cusp", "normals",
                                             "unknot-curve", "unknot-radius", "density"}));
}

TEST(Registry, an_unknown_name_is_refused_with_the_known_ones) {
  try {
    (void)run_experiment("nope");
    FAIL() << "no exception";
  } catch (const InvalidOptions& e) {
    EXPECT_STREQ(e.what(),
                 "unknown experiment 'nope' (known: trefoil, cylinder, scan, paraboloid, cusp, normals, "
                 "unknot-curve, unknot-radius, density)");
  }
}

}  // namespace
}  // namespace envcrust::experiments
