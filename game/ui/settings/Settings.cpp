#include "game/ui/settings/Settings.h"

#include "engine/haptics/devices/DeviceNames.h"
#include "engine/task/ProtocolDef.h"

namespace hemiroll::game {

// The player's override is a protocol's, applied the same way (ProtocolDef).
physics::CouplingDef couplingFor(const Settings& s, const physics::CouplingDef& level) {
  if (!s.overrideCoupling) return level;
  task::TrialOverrides o;
  o.method = methodLabel(s.method);  // "?" for an unknown index: M3, as before
  o.stiffness = s.stiffness;
  o.damping = s.damping;
  o.alpha = s.alpha;
  return task::overriddenCoupling(o, level);
}

std::string playDeviceName(const Settings& s) {
  if (s.device == haptics::kMouseDevice && s.mouseFeel == MouseFeel::Hand) return haptics::kMouseHandDevice;
  return s.device;
}

const char* methodLabel(int method) {
  static constexpr const char* kLabels[] = {"M1", "M2", "M3", "visual"};
  return method >= 0 && method < 4 ? kLabels[method] : "?";
}

}  // namespace hemiroll::game
