// Tests of resample_curve.
#include <gtest/gtest.h>
