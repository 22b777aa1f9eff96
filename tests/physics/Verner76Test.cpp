// engine/physics/Verner76: the typed table against every Runge-Kutta order
// condition up to the 7th (85 rooted trees; the embedded weights against the
// 37 up to the 6th), generated from the trees (support/OrderConditions.h),
// then the pair on a known solution beside DOP853.

#include "engine/physics/Verner76.h"

#include <gtest/gtest.h>

#include "tests/physics/support/BesideDop853.h"
#include "tests/physics/support/OrderConditions.h"

namespace hemiroll::test {
namespace {

using namespace physics;

// 17 significant digits of coefficients up to 187 in size: the conditions
// hold to a few units in the last place of the largest products (measured
// 4e-15); the embedded weights miss order 7 by 4e-4.
TEST(Verner76, TheTypedTableMeetsEveryOrderCondition) { expectPairMeetsOrderConditions<Vern7Tableau>(1e-13, 1e-6); }

TEST(Verner76, ItsErrorFollowsTheTolerance) { expectErrorFollowsToleranceBesideDop853<Verner76<2>>(); }

}  // namespace
}  // namespace hemiroll::test
