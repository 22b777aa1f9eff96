#pragma once
// Inputs shared by several tests: a moving haptic proxy, a held mass point.

#include <cmath>

#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/PrescribedDriveSystem.h"
#include "tests/physics/support/NewtonEulerModel.h"

namespace hemiroll::test {

// A proxy circling above the upright face centre while bobbing vertically:
// smooth, so RK4 keeps its order, and with an out-of-face component so that
// M1, M2 and M3 differ.
struct CirclingProxy final : physics::ProxyTrajectory {
  double radius = 0.01, rate = 3.0, heave = 0.004, heaveRate = 5.0, height = 0.04;
  physics::ProxyPose at(double t) const override {
    physics::ProxyPose pose;
    pose.position = Vec3(radius * std::cos(rate * t), radius * std::sin(rate * t), height + heave * std::sin(heaveRate * t));
    pose.velocity = Vec3(-radius * rate * std::sin(rate * t), radius * rate * std::cos(rate * t),
                         heave * heaveRate * std::cos(heaveRate * t));
    return pose;
  }
  ProxyMotion motion() const {
    return {[this](double t) { return at(t).position; }, [this](double t) { return at(t).velocity; }};
  }
};

// A proxy at rest.
struct FixedProxy final : physics::ProxyTrajectory {
  explicit FixedProxy(const Vec3& where) : position(where) {}
  Vec3 position;
  physics::ProxyPose at(double) const override { return {position, Vec3::Zero()}; }
};

// p(t) = p0: the hand holds the mass point still on the face.
struct HeldPoint final : physics::MassPointTrajectory {
  explicit HeldPoint(const Vec2& where) : p(where) {}
  Vec2 p;
  Sample at(double) const override { return {p, Vec2::Zero(), Vec2::Zero()}; }
};

}  // namespace hemiroll::test
