#pragma once
// A quantity the HUD shows, in a player's words and units: a judged task
// variable (TaskVariable) or a plot channel of a level's `scene.plots`
// (docs/LEVELS.md, "Plot channels"), read from a servo snapshot. Everything
// inside is SI; player units (mm, degrees, mm/s, degrees/s, mJ, N) appear
// only where a number is drawn.

#include <optional>
#include <string_view>

#include "engine/haptics/ServoSnapshot.h"
#include "engine/physics/RollingDynamics.h"
#include "engine/task/TaskDef.h"

namespace hemiroll::game {

struct PlayerUnit {
  const char* label;  // "contact x", "tilt u", ...
  const char* unit;   // "mm", "°", "mm/s", ...
  double scale;       // SI value * scale = the value in `unit`
};

// How the HUD names a judged variable and in which unit it shows it.
PlayerUnit playerUnitOf(task::TaskVariable variable);

class HudChannel {
 public:
  // The channel of a name LevelLoader accepts; nullopt for any other.
  static std::optional<HudChannel> fromName(std::string_view name);
  const PlayerUnit& unit() const { return unit_; }
  // The channel's SI value in this snapshot (energy needs the model).
  double value(const haptics::ServoSnapshot& s, const physics::RollingDynamics& dynamics) const;

 private:
  enum class Source : unsigned char { StateSlot, OmegaNorm, Energy, Proxy, Force, ForceNorm };
  HudChannel(Source source, int index, PlayerUnit unit) : source_(source), index_(index), unit_(unit) {}
  Source source_;
  int index_;  // the state slot, or the axis of the proxy and force
  PlayerUnit unit_;
};

// The hemisphere's tilt: the face normal's angle from vertical [rad], and
// the horizontal direction it leans towards (the face's downhill side, the
// way the mass point would slide), unit length or zero when upright.
struct Tilt {
  double angle = 0.0;
  double downhillX = 0.0, downhillY = 0.0;
};
Tilt tiltOf(const haptics::ServoSnapshot& s);

}  // namespace hemiroll::game
