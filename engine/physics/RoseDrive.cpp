#include "engine/physics/RoseDrive.h"

#include "engine/physics/SinCos.h"

namespace hemiroll::physics {

MassPointTrajectory::Sample RoseDrive::at(double t) const {
  const RoseSampleOf<double> s = roseSampleOf(def_.r1, def_.r2, def_.k, def_.omega, t);
  return Sample{s.p.eigen(), s.pDot.eigen(), s.pDDot.eigen()};
}

}  // namespace hemiroll::physics
