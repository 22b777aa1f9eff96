#include "engine/autopilot/SettleRegulator.h"

#include <Eigen/Dense>
#include <cmath>

#include "engine/autopilot/PlantModel.h"
#include "engine/physics/Orientation.h"

namespace hemiroll::autopilot {

using physics::Vec2;
using physics::Vec3;

namespace {

constexpr int kN = SettleGain::kStates;
using State = SettleGain::State;
using Square = Eigen::Matrix<double, kN, kN>;
// The model's 12 states and the proxy's horizontal position.
using Extended = Eigen::Matrix<double, 14, 1>;

// (x, y) of each horizontal pair turned by `angle`; w_z (slot 8) is kept.
State turned(const State& z, double angle) {
  State out = z;
  const double c = std::cos(angle), s = std::sin(angle);
  for (const int i : {0, 2, 4, 6, 9}) {
    out[i] = c * z[i] - s * z[i + 1];
    out[i + 1] = s * z[i] + c * z[i + 1];
  }
  return out;
}

struct Linearisation {
  explicit Linearisation(const physics::HemisphereParams& params, const physics::CouplingDef& coupling, double dt)
      : model(params, coupling, dt), constants(params), dt(dt), height(params.radius) {}

  // One tick from X with the proxy moved by d: the model's next state and
  // the proxy where it now is.
  Extended next(const Extended& X, const Vec2& d) {
    model.reset(X.head<12>(), 0.0);
    const Vec3 proxy(X[12] + d.x(), X[13] + d.y(), height);
    model.tick(proxy, Vec3(d.x() / dt, d.y() / dt, 0.0));
    Extended out;
    out.head<12>() = model.state();
    out[12] = proxy.x();
    out[13] = proxy.y();
    return out;
  }
  State coordinates(const Extended& X) const {
    return settleCoordinates(constants, X.head<12>(), Vec2(X[12], X[13]));
  }

  PlantModel model;
  physics::ModelConstants constants;
  double dt, height;
};

// The rest at lean `lean` along the sphere's u_o: the mass point and the
// proxy where one tick from rest changes no velocity (Gauss-Newton).
bool findRest(Linearisation& lin, double lean, Extended& X) {
  X.setZero();
  X[physics::force_slot::u_o] = -lean;
  Eigen::Vector4d u = Eigen::Vector4d::Zero();  // mass point (x, y), proxy (x, y)
  const auto residual = [&](const Eigen::Vector4d& v) {
    Extended Y = X;
    Y[0] = v[0];
    Y[1] = v[1];
    Y[12] = v[2];
    Y[13] = v[3];
    const Extended n = lin.next(Y, Vec2::Zero());
    Eigen::Matrix<double, 5, 1> r;
    r << n[2], n[3], n[4], n[5], n[6];
    return Eigen::Matrix<double, 5, 1>(r / lin.dt);
  };
  double norm = 1e30;
  for (int it = 0; it < 30 && norm > 1e-12; ++it) {
    const Eigen::Matrix<double, 5, 1> r0 = residual(u);
    norm = r0.norm();
    Eigen::Matrix<double, 5, 4> J;
    for (int j = 0; j < 4; ++j) {
      Eigen::Vector4d e = Eigen::Vector4d::Zero();
      e[j] = 1e-7;
      J.col(j) = (residual(u + e) - residual(u - e)) / 2e-7;
    }
    u -= J.completeOrthogonalDecomposition().solve(r0);
  }
  X[0] = u[0];
  X[1] = u[1];
  X[12] = u[2];
  X[13] = u[3];
  return std::isfinite(norm) && norm < 1e-8;
}

// The discounted discrete Riccati equation by the structure-preserving
// doubling algorithm (quadratic convergence: tens of iterations where the
// plain recursion needed over 10^5 at a 1 ms step).
bool solveRiccati(const Square& A, const Eigen::Matrix<double, kN, 2>& B, const Square& Q, const Eigen::Matrix2d& R,
                  Square& P) {
  Square Ak = A;
  Square Gk = B * R.inverse() * B.transpose();
  Square Hk = Q;
  const Square I = Square::Identity();
  for (int it = 0; it < 60; ++it) {
    const Eigen::PartialPivLU<Square> W(I + Gk * Hk);
    const Square WA = W.solve(Ak);
    const Square WG = W.solve(Gk);
    const Square Hn = Hk + Ak.transpose() * Hk * WA;
    const Square Gn = Gk + Ak * WG * Ak.transpose();
    Ak = Ak * WA;
    const double change = (Hn - Hk).norm() / std::max(Hn.norm(), 1e-300);
    Hk = 0.5 * (Hn + Hn.transpose());
    Gk = 0.5 * (Gn + Gn.transpose());
    if (!Hk.allFinite()) return false;
    if (change < 1e-13) break;
  }
  P = Hk;
  return true;
}

}  // namespace

namespace {

// The gain is used only where the model shows it works: from upright and
// still, regulated towards its rest for kCheckTime, the hemisphere must
// stand there, leaning the same way within a fifth of the lean, and still.
// (On the tutorials' heavy shells, m_s / m_p = 5, the regulator of these
// weights came to rest leaning the other way; measured, so checked.)
constexpr double kCheckTime = 6.0;  // [s]

bool reachesItsRest(const SettleGain& gain, Linearisation& lin) {
  const Vec2 lean = gain.restLean * Vec2(std::cos(gain.restHeading), std::sin(gain.restHeading));
  lin.model.reset(physics::ForceDrivenState::Zero(), 0.0);
  Vec2 proxy = Vec2::Zero();
  const long long ticks = std::llround(kCheckTime / lin.dt);
  for (long long k = 0; k < ticks; ++k) {
    const Vec2 step = settleStep(gain, lin.constants, lin.model.state(), proxy, lean, 0.25 * lin.dt);
    proxy += step;
    if (lin.model.tick(Vec3(proxy.x(), proxy.y(), gain.proxyHeight), Vec3(step.x() / lin.dt, step.y() / lin.dt, 0.0)) !=
        physics::DomainEvent::None)
      return false;
  }
  const State z = settleCoordinates(lin.constants, lin.model.state(), proxy);
  const double leanError = std::hypot(z[0] - lean.x(), z[1] - lean.y());
  const double rocking = std::sqrt(z[6] * z[6] + z[7] * z[7] + z[8] * z[8]);
  return leanError < 0.2 * gain.restLean && rocking < 1e-3;
}

}  // namespace

State settleCoordinates(const physics::ModelConstants& constants, const physics::ForceDrivenState& x,
                        const Vec2& proxy) {
  using namespace physics::force_slot;
  (void)constants;
  const physics::Orientation o = physics::makeOrientation(x[u_o], x[v_o], x[psi]);
  const Vec3 normal = o.faceNormal();
  const Vec3 point = o.R * Vec3(x[x_p], x[y_p], 0.0);
  const Vec3 pointSpeed = o.R * Vec3(x[xd_p], x[yd_p], 0.0);
  State z;
  z << normal.x(), normal.y(), point.x(), point.y(), pointSpeed.x(), pointSpeed.y(), x[w_x], x[w_y], x[w_z],
      proxy.x() - x[u_a], proxy.y() - x[v_a];
  return z;
}

SettleGain settleGainFor(const physics::HemisphereParams& params, const physics::CouplingDef& coupling, double dt,
                         const SettleWeights& weights) {
  SettleGain out;
  Linearisation lin(params, coupling, dt);
  Extended X;
  if (!findRest(lin, std::asin(weights.restLean), X)) return out;
  const State rest = lin.coordinates(X);

  // The regulator's coordinates miss the contact point and psi (the model
  // is the same wherever the contact is and however psi turns), so the
  // columns come from moves along the pseudo-inverse of their Jacobian.
  Eigen::Matrix<double, kN, 14> J;
  for (int j = 0; j < 14; ++j) {
    Extended e = Extended::Zero();
    e[j] = 1e-7;
    J.col(j) = (lin.coordinates(X + e) - lin.coordinates(X - e)) / 2e-7;
  }
  const Eigen::Matrix<double, 14, kN> inverse = J.completeOrthogonalDecomposition().pseudoInverse();
  Square A;
  Eigen::Matrix<double, kN, 2> B;
  for (int i = 0; i < kN; ++i) {
    const Extended d = 1e-7 * inverse.col(i);
    A.col(i) = (lin.coordinates(lin.next(X + d, Vec2::Zero())) - lin.coordinates(lin.next(X - d, Vec2::Zero()))) / 2e-7;
  }
  for (int i = 0; i < 2; ++i) {
    Vec2 d = Vec2::Zero();
    d[i] = 1e-8;
    B.col(i) = (lin.coordinates(lin.next(X, d)) - lin.coordinates(lin.next(X, -d))) / 2e-8;
  }

  const double R = params.radius;
  const auto w = [](double scale) { return 1.0 / (scale * scale); };
  State q;
  q << w(weights.lean), w(weights.lean), w(weights.point * R), w(weights.point * R), w(weights.pointSpeed * R),
      w(weights.pointSpeed * R), w(weights.spin), w(weights.spin), w(weights.spin), w(weights.proxy * R),
      w(weights.proxy * R);
  const Square Q = q.asDiagonal();
  const Eigen::Matrix2d Rw = Eigen::Matrix2d::Identity() * w(weights.step);
  // Discounted: spin about the axis keeps an eigenvalue 1 no gain moves.
  const double root = std::sqrt(std::exp(-dt / weights.horizon));
  const Square Ad = root * A;
  const Eigen::Matrix<double, kN, 2> Bd = root * B;
  Square P;
  if (!solveRiccati(Ad, Bd, Q, Rw, P)) return out;
  const Eigen::Matrix<double, 2, kN> K = (Rw + Bd.transpose() * P * Bd).ldlt().solve(Bd.transpose() * P * Ad);
  if (!K.allFinite()) return out;

  // Stable but for that one mode: every other closed-loop eigenvalue inside.
  const Eigen::EigenSolver<Square> closed(A - B * K);
  int onCircle = 0;
  double slowest = 0.0;
  for (int i = 0; i < kN; ++i) {
    const double m = std::abs(closed.eigenvalues()[i]);
    if (m > 1.0 - 1e-9) {
      ++onCircle;
      continue;
    }
    slowest = std::max(slowest, m);
  }
  if (onCircle > 1) return out;
  out.gain = K;
  out.rest = rest;
  out.restLean = std::hypot(rest[0], rest[1]);
  out.restHeading = std::atan2(rest[1], rest[0]);
  out.proxyHeight = lin.height;
  out.slowest = slowest > 0.0 ? -dt / std::log(slowest) : 0.0;
  out.valid = reachesItsRest(out, lin);
  return out;
}
Vec2 settleStep(const SettleGain& gain, const physics::ModelConstants& constants, const physics::ForceDrivenState& x,
                const Vec2& proxy, const Vec2& lean, double most) {
  // Near upright the rests form a line through the upright one: scaled.
  const double size = lean.norm();
  const double heading = size > 1e-12 ? std::atan2(lean.y(), lean.x()) : gain.restHeading;
  const double turn = heading - gain.restHeading;
  const State reference = gain.rest * (size / gain.restLean);
  const State error = turned(settleCoordinates(constants, x, proxy), -turn) - reference;
  const Eigen::Vector2d step = -gain.gain * error;
  return physics::limitedTo(physics::turnedBy(Vec2(step.x(), step.y()), turn), most);
}

}  // namespace hemiroll::autopilot
