#include "engine/analysis/GuidanceWork.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::analysis {

namespace {

struct Terms {
  double power = 0.0;     // F_g . v [W]
  double opposing = 0.0;  // max(0, -F_h . g) [N]
  double hand = 0.0;      // |F_h| [N]
  bool guided = false;
};

Terms termsAt(const GuidanceSamples& s, std::size_t i) {
  Terms t;
  const double gx = s.guidanceX[i], gy = s.guidanceY[i], gz = s.guidanceZ[i];
  const double g = std::sqrt(gx * gx + gy * gy + gz * gz);
  if (!(g > 0.0)) return t;
  t.guided = true;
  t.power = gx * s.proxyVelocityX[i] + gy * s.proxyVelocityY[i] + gz * s.proxyVelocityZ[i];
  const double hx = s.handForceX[i], hy = s.handForceY[i], hz = s.handForceZ[i];
  t.opposing = std::max(0.0, -(hx * gx + hy * gy + hz * gz) / g);
  t.hand = std::sqrt(hx * hx + hy * hy + hz * hz);
  return t;
}

}  // namespace

GuidanceWork guidanceWork(const GuidanceSamples& s) {
  GuidanceWork out;
  const std::size_t n = s.time.size();
  double opposing = 0.0, hand = 0.0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double dt = s.time[i + 1] - s.time[i];
    if (!(dt > 0.0)) continue;  // a repeated or backwards time contributes nothing
    const Terms a = termsAt(s, i), b = termsAt(s, i + 1);
    if (!a.guided && !b.guided) continue;
    out.present = true;
    out.work += 0.5 * (a.power + b.power) * dt;
    opposing += 0.5 * (a.opposing + b.opposing) * dt;
    hand += 0.5 * (a.hand + b.hand) * dt;
    out.guidedTime += dt;
  }
  if (n == 1 && termsAt(s, 0).guided) out.present = true;
  out.opposedShare = hand > 0.0 ? opposing / hand : 0.0;
  return out;
}

}  // namespace hemiroll::analysis
