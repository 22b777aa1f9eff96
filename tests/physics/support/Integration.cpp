#include "tests/physics/support/Integration.h"

namespace hemiroll::test {

void ForceDrivenWithWork::derivative(double t, const physics::StateVector<13>& x,
                                     physics::StateVector<13>& dxdt) const {
  const physics::ForceDrivenState state = x.head<12>();
  physics::ForceDrivenState d;
  system_.derivative(t, state, d);
  dxdt.head<12>() = d;
  dxdt(12) = physics::externalPower(system_.dynamics(), state, system_.externalForce(t, state));
}

void PrescribedWithWork::derivative(double t, const physics::StateVector<9>& x, physics::StateVector<9>& dxdt) const {
  const physics::BodyState body = x.head<8>();
  physics::BodyState d;
  system_.derivative(t, body, d);
  dxdt.head<8>() = d;
  const physics::ForceDrivenState full = system_.fullState(t, body);
  const Mat3 R = orientationFromAngles(body(5), body(6), body(7));
  const Vec2 f = system_.drivingForce(t, body);
  const Vec3 force = R.col(0) * f.x() + R.col(1) * f.y();
  dxdt(8) = physics::externalPower(system_.dynamics(), full, force);
}

}  // namespace hemiroll::test
