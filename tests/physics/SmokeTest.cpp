#include <gtest/gtest.h>
#include <cstdio>
#include "engine/physics/Physics.h"
using namespace hemiroll::physics;
TEST(Smoke, FreeEnergy) {
  HemisphereParams P;
  ForceDrivenSystem sys(P);
  ForceDrivenState x = ForceDrivenState::Zero();
  x << 0.01, -0.005, 0.02, 0.01, 0.3, -0.2, 1.0, 0, 0, 0.2, -0.1, 0.3;
  RungeKutta4<12> rk;
  Stepper<12> st(sys, rk, x);
  double E0 = mechanicalEnergy(sys.dynamics(), x).total();
  for (int i = 0; i < 1000; ++i) st.advance(1e-4);
  double E1 = mechanicalEnergy(sys.dynamics(), st.state()).total();
  std::printf("E0 %.15g E1 %.15g event %s t %g\n", E0, E1, domainEventName(st.event()), st.time());
  EXPECT_NEAR(E0, E1, 1e-10);
}
