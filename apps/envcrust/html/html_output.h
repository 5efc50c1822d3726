// The CLI's side of the HTML report: the --html option, its checks before a run, the page's
// pieces from an analysis, and writing the file.
#pragma once

#include "html_report.h"

#include "envcrust/analysis.h"

#include <CLI/CLI.hpp>

#include <string>

namespace envcrust::cli::html {

/// Adds `--html FILE` to a subcommand (`what`: what the 3D view shows, for --help).
void add_html_option(CLI::App& command, std::string& path, const std::string& what);

/// Before a run: a build without three.js refuses --html (UsageError: "--html: this envcrust
/// was built without three.js ..."), and the file must be writable (io::check_output_path).
/// Does nothing for an empty path.
void check_html_output(const std::string& path);

/// Fills the page's summary (topology_in_words), boundary loops (the analysis' loops, in its
/// order) and messages (not a 2-manifold, passes through itself, the analysis' warnings).
void add_analysis(ReportPage& page, const analysis::AnalysisReport& report);

/// The page of `envcrust reconstruct`: `result` with its analysis (null with --no-analysis:
/// its topology alone), each vertex coloured by its distance to the nearest of `input_points`,
/// `failed_checks` and `hints` as messages, and the JSON report as the figures.
ReportPage reconstruct_page(const std::string& title, const TriangleMesh& result,
                            const analysis::AnalysisReport* report, const std::vector<Point3>& input_points,
                            const std::vector<std::string>& failed_checks, const std::vector<std::string>& hints,
                            const nlohmann::json& figures);

/// The page of `envcrust analyze`: `mesh` with its analysis; with a reference (of geometry),
/// each vertex coloured by its distance to it (`reference_name` labels the colour scale).
ReportPage analyze_page(const std::string& title, const TriangleMesh& mesh, const analysis::AnalysisReport& report,
                        const analysis::Reference& reference, const std::string& reference_name,
                        const nlohmann::json& figures);

/// The page of a mesh that could not be analyzed: `problem` (the one-line error) as the
/// message and the summary, and `mesh` (null: none; without faces: its vertices as points).
ReportPage failure_page(const std::string& title, const TriangleMesh* mesh, const std::string& problem);

/// Writes the page to `path` atomically (io::write_atomic). @throws IoError naming the file.
void write_html_report(const std::string& path, const ReportPage& page);

}  // namespace envcrust::cli::html
