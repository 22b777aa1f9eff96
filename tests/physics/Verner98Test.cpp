// engine/physics/Verner98: Verner's 9(8) table against every Runge-Kutta
// order condition up to the 9th (486 rooted trees; the embedded weights
// against the 200 up to the 8th), generated from the trees
// (support/OrderConditions.h), then the pair on a known solution beside
// DOP853.

#include "engine/physics/Verner98.h"

#include <gtest/gtest.h>

#include "tests/physics/support/BesideDop853.h"
#include "tests/physics/support/OrderConditions.h"

namespace hemiroll::test {
namespace {

using namespace physics;

// Coefficients of up to 36 in size, each rounded to double once: the
// conditions hold to a few units in the last place of the largest products
// (measured 6e-16); the embedded weights miss order 9 by 1e-5.
TEST(Verner98, TheTableMeetsEveryOrderCondition) { expectPairMeetsOrderConditions<Vern9Tableau>(1e-13, 1e-8); }

TEST(Verner98, ItsErrorFollowsTheTolerance) { expectErrorFollowsToleranceBesideDop853<Verner98<2>>(); }

}  // namespace
}  // namespace hemiroll::test
