#pragma once
// Trajectories whose features are known by construction, for the analysis
// tests: the paper's rose (eqs. 49-50), a circular arc with loops (a
// trochoid), a precession angle made of three phases. Sampled at `rate` Hz.

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace hemiroll::test {

struct Planar {
  std::vector<double> t, x, y;
};

// x = r1 cos(W t) + r2 cos(k W t), y = r1 sin(W t) - r2 sin(k W t).
inline Planar rose(double r1, double r2, double k, double omega, double duration, double rate) {
  Planar p;
  const auto n = static_cast<std::size_t>(std::lround(duration * rate)) + 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / rate, phi = omega * t;
    p.t.push_back(t);
    p.x.push_back(r1 * std::cos(phi) + r2 * std::cos(k * phi));
    p.y.push_back(r1 * std::sin(phi) - r2 * std::sin(k * phi));
  }
  return p;
}

// A point drifting at `speed` along a circle of radius `arcRadius`
// (counter-clockwise for speed > 0) about (cx, cy), plus a circle of radius
// `loopRadius` turned at `loopRate` rad/s (counter-clockwise for > 0):
// loops when loopRadius |loopRate| > |speed|.
inline Planar trochoidArc(double arcRadius, double speed, double loopRadius, double loopRate, double loopPhase,
                          double duration, double rate, double cx = 0.0, double cy = 0.0) {
  Planar p;
  const auto n = static_cast<std::size_t>(std::lround(duration * rate)) + 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / rate, a = speed * t / arcRadius;
    p.t.push_back(t);
    p.x.push_back(cx + arcRadius * std::cos(a) + loopRadius * std::cos(loopRate * t + loopPhase));
    p.y.push_back(cy + arcRadius * std::sin(a) + loopRadius * std::sin(loopRate * t + loopPhase));
  }
  return p;
}

inline void addNoise(std::vector<double>& v, double sigma, unsigned seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  for (double& x : v) x += normal(random);
}

}  // namespace hemiroll::test
