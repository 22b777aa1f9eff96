#include "tests/physics/support/TestModel.h"

#include <cmath>

namespace hemiroll::test {

Mat3 hat(const Vec3& a) {
  Mat3 m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

Mat3 orientationFromAngles(double u_o, double v_o, double psi) {
  using Eigen::AngleAxisd;
  const Mat3 Rz = AngleAxisd(psi, Vec3::UnitZ()).toRotationMatrix();
  const Mat3 Rx = AngleAxisd(v_o, Vec3::UnitX()).toRotationMatrix();
  const Mat3 Ry = AngleAxisd(u_o, Vec3::UnitY()).toRotationMatrix();
  return Rz.transpose() * Rx.transpose() * Ry.transpose();
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  const double unit = static_cast<double>(rng() >> 11) * 0x1.0p-53;  // [0, 1)
  return lo + (hi - lo) * unit;
}

State12 randomState(std::mt19937_64& rng, const HemisphereParams& params, const RandomStateSpec& spec) {
  State12 x;
  // Contact angles: rejection sampling inside the tilt cone cos u cos v >= cos(maxTilt).
  double u = 0.0, v = 0.0;
  do {
    u = uniform(rng, -spec.maxTilt, spec.maxTilt);
    v = uniform(rng, -spec.maxTilt, spec.maxTilt);
  } while (std::cos(u) * std::cos(v) < std::cos(spec.maxTilt));
  double px = 0.0, py = 0.0;
  const double rMax = spec.maxPointRadius * params.radius;
  do {
    px = uniform(rng, -rMax, rMax);
    py = uniform(rng, -rMax, rMax);
  } while (px * px + py * py > rMax * rMax);
  x << px, py, uniform(rng, -spec.maxPointSpeed, spec.maxPointSpeed),
      uniform(rng, -spec.maxPointSpeed, spec.maxPointSpeed), uniform(rng, -spec.maxSpin, spec.maxSpin),
      uniform(rng, -spec.maxSpin, spec.maxSpin), uniform(rng, -spec.maxSpin, spec.maxSpin),
      uniform(rng, -spec.maxPlane, spec.maxPlane), uniform(rng, -spec.maxPlane, spec.maxPlane), u, v,
      uniform(rng, -kPi, kPi);
  return x;
}

}  // namespace hemiroll::test
