// engine/analysis/GuidanceWork: the guidance's work and the share of the
// hand's force against it, checked on signals whose integrals are known in
// closed form.

#include "engine/analysis/GuidanceWork.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace hemiroll::analysis {
namespace {

struct Columns {
  std::vector<double> t, gx, gy, gz, vx, vy, vz, hx, hy, hz;
  GuidanceSamples samples() const { return {t, gx, gy, gz, vx, vy, vz, hx, hy, hz}; }
  void add(double time, double g, double v, double h) {
    t.push_back(time);
    gx.push_back(g), gy.push_back(0.0), gz.push_back(0.0);
    vx.push_back(v), vy.push_back(0.0), vz.push_back(0.0);
    hx.push_back(h), hy.push_back(0.0), hz.push_back(0.0);
  }
};

TEST(GuidanceWorkTest, ConstantForceAlongAConstantVelocityDoesForceTimesDistance) {
  Columns c;
  for (int i = 0; i <= 1000; ++i) c.add(0.002 * i, 0.5, 0.03, 0.2);  // 2 s, 0.5 N along 3 cm/s
  const GuidanceWork w = guidanceWork(c.samples());
  EXPECT_TRUE(w.present);
  EXPECT_NEAR(w.work, 0.5 * 0.03 * 2.0, 1e-12);  // F v T: the trapezoid is exact for a constant
  EXPECT_NEAR(w.guidedTime, 2.0, 1e-12);
  EXPECT_EQ(w.opposedShare, 0.0);  // the hand pushed along it
}

TEST(GuidanceWorkTest, TheHandAgainstTheGuidanceHalfTheTimeIsAnOpposedShareOfAHalf) {
  Columns c;
  // The hand pushes +1 N for the first second and -1 N for the second,
  // against a guidance force of +2 N all along; work on a sine velocity
  // over whole periods is zero.
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= 2000; ++i) {
    const double t = 0.001 * i;
    c.add(t, 2.0, 0.01 * std::sin(2.0 * pi * t), t < 1.0 ? 1.0 : -1.0);
  }
  const GuidanceWork w = guidanceWork(c.samples());
  // The trapezoid crosses the sign change in one 1 ms step: 0.5 ms of error in 2 s.
  EXPECT_NEAR(w.opposedShare, 0.5, 0.0005 / 2.0 + 1e-12);
  EXPECT_NEAR(w.work, 0.0, 1e-12);
}

TEST(GuidanceWorkTest, NoGuidanceIsNotPresentAndNoSamplesAreNothing) {
  Columns c;
  for (int i = 0; i < 10; ++i) c.add(0.01 * i, 0.0, 0.1, 1.0);
  const GuidanceWork none = guidanceWork(c.samples());
  EXPECT_FALSE(none.present);
  EXPECT_EQ(none.work, 0.0);
  EXPECT_EQ(none.opposedShare, 0.0);
  EXPECT_FALSE(guidanceWork(GuidanceSamples{}).present);
}

}  // namespace
}  // namespace hemiroll::analysis
