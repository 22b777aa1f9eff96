// game/ui/view/ForceCues: the coupling force as a strain (over the mass
// point's weight), and the ring, pitch and rumble that show it.

#include "game/ui/view/ForceCues.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hemiroll::game {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ForceCues, StrainIsTheForceOverTheMassPointsWeightClamped) {
  // The paper's body: m_p = 1 kg, g = 9.81: 0.981 N is a strain of 0.1
  // (the pull that holds the point on a face tilted by asin 0.1 = 5.7 deg).
  EXPECT_NEAR(couplingStrain(0.981, 1.0, 9.81), 0.1, 1e-12);
  EXPECT_NEAR(couplingStrain(-0.981, 1.0, 9.81), 0.1, 1e-12);  // a magnitude
  EXPECT_NEAR(couplingStrain(0.981, 0.5, 9.81), 0.2, 1e-12);   // a lighter point strains more
  EXPECT_EQ(couplingStrain(50.0, 1.0, 9.81), 1.0);
  EXPECT_EQ(couplingStrain(kInf, 1.0, 9.81), 1.0);
  EXPECT_EQ(couplingStrain(kNan, 1.0, 9.81), 0.0);
  EXPECT_EQ(couplingStrain(1.0, 0.0, 9.81), 0.0);
  EXPECT_EQ(couplingStrain(1.0, kNan, 9.81), 0.0);
  EXPECT_EQ(couplingStrain(1.0, 1.0, kInf), 0.0);
}

// Radius: its area follows the force (radius from the square root of the
// strain), between the stated fractions of R; colour: blue, green at
// 0.075, yellow at 0.15, red from 0.4, never a washed-out grey on the way
// (the largest channel at least 0.5 above the smallest). Never NaN,
// whatever comes in.
TEST(ForceCues, TheRingGrowsAndReddensWithTheStrainAndStaysFinite) {
  const double R = 0.04;
  EXPECT_NEAR(strainRing(0.0, R).radius, kRingMinRadii * R, 1e-15);
  EXPECT_NEAR(strainRing(1.0, R).radius, kRingMaxRadii * R, 1e-15);
  EXPECT_NEAR(strainRing(0.25, R).radius, (kRingMinRadii + 0.5 * (kRingMaxRadii - kRingMinRadii)) * R, 1e-15);
  double last = 0.0;
  for (double s = 0.0; s <= 1.0; s += 0.005) {
    const StrainRing ring = strainRing(s, R);
    EXPECT_GE(ring.radius, last);
    last = ring.radius;
    const auto [lo, hi] = std::minmax({ring.colour[0], ring.colour[1], ring.colour[2]});
    EXPECT_GE(hi - lo, 0.5f) << "strain " << s << " is greyish";
  }
  const StrainRing green = strainRing(0.075, R);
  EXPECT_GT(green.colour[1], green.colour[0] + 0.5f);
  const StrainRing calm = strainRing(0.0, R), warm = strainRing(0.15, R), hot = strainRing(0.4, R);
  EXPECT_GT(calm.colour[2], calm.colour[0]);  // blue
  EXPECT_NEAR(warm.colour[0], 1.0f, 1e-6);    // yellow
  EXPECT_NEAR(warm.colour[1], 0.85f, 1e-6);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(hot.colour[i], strainRing(1.0, R).colour[i], 1e-6);  // red from 0.4 on
  EXPECT_GT(hot.colour[0], 3 * hot.colour[1]);
  for (double s : {kNan, kInf, -kInf, -3.0, 7.0}) {
    const StrainRing ring = strainRing(s, R);
    EXPECT_TRUE(std::isfinite(ring.radius)) << s;
    EXPECT_GE(ring.radius, kRingMinRadii * R) << s;
    EXPECT_LE(ring.radius, kRingMaxRadii * R) << s;
    for (float c : ring.colour) EXPECT_TRUE(std::isfinite(c)) << s;
  }
  EXPECT_EQ(strainRing(0.5, kNan).radius, 0.0);
}

TEST(ForceCues, PitchSpansTwoOctavesAndRumbleIsLimited) {
  EXPECT_NEAR(strainPitch(0.0), 180.0, 1e-12);
  EXPECT_NEAR(strainPitch(0.5), 360.0, 1e-9);
  EXPECT_NEAR(strainPitch(1.0), 720.0, 1e-9);
  EXPECT_NEAR(strainPitch(kNan), 180.0, 1e-12);
  EXPECT_NEAR(strainRumble(0.5), 0.3, 1e-12);
  EXPECT_NEAR(strainRumble(1.0), 0.6, 1e-12);
  EXPECT_NEAR(strainRumble(4.0, 2.0), 1.0, 1e-12);  // never past the motors' full
  EXPECT_EQ(strainRumble(kNan), 0.0);
  EXPECT_EQ(strainRumble(0.5, kNan), 0.0);
}

}  // namespace
}  // namespace hemiroll::game
