// rim_candidate_count counts what rim_candidates makes (rings along the curves, lunes at the
// square's convex corners), and sample_envelope refuses a rho whose rims could not be stored,
// naming a rho that could.
#include "envcrust/envelope.h"
#include "envcrust/errors.h"
#include "fixtures/surface_samples.h"

#include "envelope_candidates.h"

#include <gtest/gtest.h>

#include <string>

using namespace envcrust;

TEST(RimCandidateCount, counts_what_rim_candidates_makes) {
  for (const char* name : {"square", "cylinder", "trefoil-ribbon"}) {
    const auto samples = fixtures::builtin_samples(name, 2000);
    for (const double rho : {0.05, 0.013}) {
      std::vector<std::vector<double>> rim_rho;
      for (const auto& c : samples.boundary) rim_rho.emplace_back(c.vertices.size(), rho);
      const auto made = envelope::rim_candidates(samples.boundary, rim_rho, 0.25, 1 / 3.3);
      EXPECT_EQ(envelope::rim_candidate_count(samples.boundary, rim_rho, 0.25, 1 / 3.3),
                static_cast<double>(made.size()))
          << name << " rho " << rho;
    }
  }
}

TEST(RimCandidateCount, a_rho_too_small_for_the_rims_is_refused_before_they_are_made) {
  const auto samples = fixtures::builtin_samples("cylinder", 2000);
  envelope::EnvelopeOptions options;
  options.rho = 1e-6;
  try {
    (void)envelope::sample_envelope(samples, options);
    FAIL() << "expected DegenerateInput";
  } catch (const DegenerateInput& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("rho 1e-06 at a sample spacing of 0.25 rho is too small for the boundary curves: their "
                      "half-tubes would take ", 0), 0u) << m;
    // The rho it names keeps the rims at the limit: 1e7 candidates.
    const auto at = m.find("rho >= ");
    ASSERT_NE(at, std::string::npos) << m;
    const double named = std::stod(m.substr(at + 7));
    std::vector<std::vector<double>> rim_rho;
    for (const auto& c : samples.boundary) rim_rho.emplace_back(c.vertices.size(), 1.01 * named);
    EXPECT_LT(envelope::rim_candidate_count(samples.boundary, rim_rho, options.spacing_rel_rho, 1 / 3.3), 1e7);
    for (auto& r : rim_rho) r.assign(r.size(), 0.9 * named);
    EXPECT_GT(envelope::rim_candidate_count(samples.boundary, rim_rho, options.spacing_rel_rho, 1 / 3.3), 1e7);
    // A spacing above the default would thin the envelope out: not offered.
    EXPECT_EQ(m.find("a spacing of "), std::string::npos) << m;
    // Below the default it is: at 10x that rho and a spacing of 0.002 rho, the spacing it
    // names keeps the rims at the limit too.
    options.rho = 10 * named;
    options.spacing_rel_rho = 0.002;
    try {
      (void)envelope::sample_envelope(samples, options);
      FAIL() << "expected DegenerateInput at spacing 0.002";
    } catch (const DegenerateInput& small) {
      const std::string n = small.what();
      const auto spacing_at = n.find("a spacing of ");
      ASSERT_NE(spacing_at, std::string::npos) << n;
      const double spacing = std::stod(n.substr(spacing_at + 13));
      for (auto& r : rim_rho) r.assign(r.size(), 10 * named);
      EXPECT_LT(envelope::rim_candidate_count(samples.boundary, rim_rho, 1.01 * spacing, 1 / 3.3), 1e7);
      EXPECT_GT(envelope::rim_candidate_count(samples.boundary, rim_rho, 0.9 * spacing, 1 / 3.3), 1e7);
    }
  }
}
