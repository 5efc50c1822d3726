// Tests of mesh_boundary_curves.
#include <gtest/gtest.h>
