// game/research/sweep/PhysicsFingerprint: the same arithmetic gives the same
// fingerprint; a difference of one ulp anywhere in the run's inputs (as
// another C library's sin or a changed build would make) gives another.
#include "game/research/sweep/PhysicsFingerprint.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hemiroll::game {
namespace {

TEST(PhysicsFingerprint, StableWithinAProcessAndFromItsParts) {
  const std::string& a = physicsFingerprint();
  EXPECT_EQ(a.rfind("fnv1a-", 0), 0u) << a;
  EXPECT_EQ(a.size(), 6u + 16u) << a;
  EXPECT_EQ(&physicsFingerprint(), &a);  // computed once
  EXPECT_EQ(physicsFingerprintOf(task::SweepDef{}), a);
}

// The rows hashed also hold the point's parameters, so a nudged parameter
// would change the text trivially; the tolerance is in no row, and one ulp
// of it changes only the arithmetic (DOP853's step sizes), as another libm's
// last bit would.
TEST(PhysicsFingerprint, OneUlpOfArithmeticChangesIt) {
  const std::string base = physicsFingerprintOf(task::SweepDef{});
  task::SweepDef nudged;
  nudged.tolerance = std::nextafter(nudged.tolerance, 1.0);
  EXPECT_NE(physicsFingerprintOf(nudged), base);
}

}  // namespace
}  // namespace hemiroll::game
