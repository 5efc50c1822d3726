// Arcs and Alexander matrix of a knot diagram, and identify_knot voting over projections.
#include "alexander.h"

#include "bareiss.h"
#include "envcrust/errors.h"
#include "envcrust/knots.h"
#include "input.h"
#include "simplify.h"

#include <algorithm>
#include <map>
#include <random>
#include <string>
#include <tuple>

namespace envcrust::knots {
namespace detail {
namespace {

/// A passage of the curve through a crossing, ordered along the curve.
struct Passage {
  std::uint32_t segment;
  double param;
  std::size_t crossing;
  bool under;
};

// Fewer crossings make the determinant much cheaper; projections themselves are cheap.
constexpr int diagrams_per_projection = 4;


}  // namespace

Polynomial alexander_polynomial(const Diagram& diagram) {
  const std::size_t c = diagram.crossings.size();
  if (c == 0) {
    return Polynomial(BigInt(1));
  }
  std::vector<Passage> passages;
  passages.reserve(2 * c);
  for (std::size_t k = 0; k < c; ++k) {
    const Crossing& x = diagram.crossings[k];
    passages.push_back({x.over_segment, x.over_param, k, false});
    passages.push_back({x.under_segment, x.under_param, k, true});
  }
  std::sort(passages.begin(), passages.end(), [](const Passage& a, const Passage& b) {
    return std::tie(a.segment, a.param) < std::tie(b.segment, b.param);
  });
  // Arc j starts at the j-th under-passage along the curve; passages before the first
  // under-passage belong to the arc that wraps around, the last one.
  std::vector<std::size_t> over_arc(c);
  std::vector<std::size_t> incoming(c);
  std::vector<std::size_t> outgoing(c);
  std::size_t arc = c - 1;
  std::size_t next_arc = 0;
  for (const Passage& p : passages) {
    if (p.under) {
      incoming[p.crossing] = arc;
      arc = next_arc++;
      outgoing[p.crossing] = arc;
    } else {
      over_arc[p.crossing] = arc;
    }
  }
  const Polynomial one_minus_t(std::vector<BigInt>{1, -1});
  const Polynomial t = Polynomial::monomial(1, 1);
  const Polynomial minus_one(BigInt(-1));
  PolynomialMatrix m(c, std::vector<Polynomial>(c));
  for (std::size_t k = 0; k < c; ++k) {
    // With sign = sign(d_over x d_under), the outgoing under-arc lies left of the over-strand
    // exactly at positive crossings.
    const bool outgoing_left = diagram.crossings[k].sign > 0;
    m[k][over_arc[k]] += one_minus_t;
    m[k][outgoing[k]] += outgoing_left ? t : minus_one;
    m[k][incoming[k]] += outgoing_left ? minus_one : t;
  }
  m.pop_back();
  for (auto& row : m) {
    row.pop_back();
  }
  return normalize_unit(determinant_up_to_units(std::move(m)));
}

}  // namespace detail

std::string to_string(KnotType type) {
  switch (type) {
    case KnotType::Unknot:
      return "unknot";
    case KnotType::Trefoil:
      return "trefoil";
    case KnotType::FigureEight:
      return "figure-eight";
    case KnotType::Other:
      return "other";
    case KnotType::Unknown:
      return "unknown";
  }
  return "other";
}

KnotReport identify_knot(const Polyline& closed, const KnotOptions& options) {
  detail::validate_closed_polyline(closed);
  if (options.projections < 1) {
    throw InvalidOptions("KnotOptions.projections must be >= 1 (got " +
                         std::to_string(options.projections) + ")");
  }
  if (options.max_crossings < 0) {
    throw InvalidOptions("KnotOptions.max_crossings must be >= 0 (got " +
                         std::to_string(options.max_crossings) + ")");
  }
  const Polyline cleaned = detail::remove_repeated_points(closed);
  std::vector<Polyline> loops = {cleaned};
  if (cleaned.size() > 3) {
    loops = detail::simplify_loops(loops);
  }
  KnotReport report;
  report.simplified_vertices = loops.front().size();
  report.alexander.assign(1, '1');  // (operator=("1") trips a GCC 12 -Wrestrict false positive)
  // A triangle is planar, hence unknotted. (Every polygon with fewer than 6 edges is, but
  // projecting those still catches self-intersecting input.)
  if (loops.front().size() <= 3) {
    return report;
  }

  struct Reading {
    std::string polynomial;
    std::int64_t determinant;
    int crossings;
  };
  std::mt19937_64 rng(options.seed);
  std::vector<Reading> readings;
  std::map<std::string, int> votes;
  for (int i = 0; i < options.projections; ++i) {
    const detail::Diagram diagram =
        detail::simplest_generic_diagram(loops, rng, detail::diagrams_per_projection);
    if (diagram.crossings.size() > static_cast<std::size_t>(options.max_crossings)) {
      report.type = KnotType::Unknown;
      report.alexander.clear();
      report.determinant = 0;
      report.crossings = static_cast<int>(diagram.crossings.size());
      return report;
    }
    const detail::Polynomial delta = detail::alexander_polynomial(diagram);
    const detail::BigInt at_minus_one = abs(delta.evaluate(-1));
    readings.push_back({detail::to_string(delta), at_minus_one.convert_to<std::int64_t>(),
                        static_cast<int>(diagram.crossings.size())});
    ++votes[readings.back().polynomial];
  }
  // Majority; among equally voted polynomials the one read first wins.
  const Reading* chosen = &readings.front();
  for (const Reading& r : readings) {
    if (votes[r.polynomial] > votes[chosen->polynomial]) {
      chosen = &r;
    }
  }
  report.alexander = chosen->polynomial;
  report.determinant = chosen->determinant;
  report.crossings = chosen->crossings;
  report.projections_agree = votes.size() == 1;
  if (chosen->polynomial == "1") {
    report.type = KnotType::Unknot;
  } else if (chosen->polynomial == "t^2 - t + 1") {
    report.type = KnotType::Trefoil;
  } else if (chosen->polynomial == "t^2 - 3t + 1") {
    report.type = KnotType::FigureEight;
  } else {
    report.type = KnotType::Other;
  }
  return report;
}

}  // namespace envcrust::knots
