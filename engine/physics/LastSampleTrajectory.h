#pragma once
// A mass-point trajectory that remembers its last sample: asked again for
// the same time (the same bits), it answers from memory. The sample is a pure
// function of t, so the answer has the bits a fresh evaluation would have.
//
// Why: the stepping loop asks the drive for the same time several times in a
// row. A scalar RK4 step asks at t, t + h/2 twice, t + h, then the Stepper's
// domain check at t + h and its reset onto the grid time, which is where the
// next step starts: six evaluations of the rose (two sines and cosines each,
// ~37 % of a scalar rose run) where two or three times are distinct. DOP853
// asks twice at the step's end (the last stage, then k13 and the check).
//
// One run's own: the memory is written by const calls (the systems hold
// their trajectory as const), so an instance must not be shared between
// threads. The wrapped trajectory is referenced and must outlive it.

#include <cstring>

#include "engine/physics/PrescribedDriveSystem.h"

namespace hemiroll::physics {

class LastSampleTrajectory final : public MassPointTrajectory {
 public:
  explicit LastSampleTrajectory(const MassPointTrajectory& source) : source_(source) {}

  Sample at(double t) const override {
    // Bits, not ==: -0.0 == 0.0, yet the sines of the two differ in sign.
    if (!remembered_ || std::memcmp(&t, &time_, sizeof t) != 0) {
      sample_ = source_.at(t);
      time_ = t;
      remembered_ = true;
    }
    return sample_;
  }

 private:
  const MassPointTrajectory& source_;
  mutable bool remembered_ = false;
  mutable double time_ = 0.0;
  mutable Sample sample_;
};

}  // namespace hemiroll::physics
