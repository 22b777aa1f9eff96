// engine/autopilot/Reachability: the refusals it can prove up front.

#include "engine/autopilot/Reachability.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/autopilot/PaperGoal.h"

namespace hemiroll::autopilot {
namespace {

using physics::Vec3;
using test::paperGoal;

TEST(Reachability, RefusesWhatCanNeverBeReached) {
  const physics::HemisphereParams params;
  Workspace ws;
  Goal far = paperGoal();
  far.target[7] = 0.2;  // 20 cm: beyond a 10 cm device
  EXPECT_NE(unreachableReason(far, params, ws).find("beyond its reach"), std::string::npos);

  Goal rim;
  rim.set[9] = true;
  rim.target[9] = 1.7;
  rim.tolerance[9] = 0.05;
  EXPECT_NE(unreachableReason(rim, params, ws).find("past the rim"), std::string::npos);

  Goal offFace;
  offFace.set[0] = true;
  offFace.target[0] = 0.05;
  offFace.tolerance[0] = 0.005;
  EXPECT_NE(unreachableReason(offFace, params, ws).find("off the face"), std::string::npos);

  // At rest tilted by 0.5 rad needs p ~ R sin 0.5 = 19 mm; p held within 4 mm.
  Goal contradictory = paperGoal();
  contradictory.target[9] = 0.5;
  contradictory.tolerance[9] = 0.05;
  EXPECT_NE(unreachableReason(contradictory, params, ws).find("rest at a tilt"), std::string::npos);

  EXPECT_EQ(unreachableReason(paperGoal(), params, ws), "");
}

}  // namespace
}  // namespace hemiroll::autopilot
