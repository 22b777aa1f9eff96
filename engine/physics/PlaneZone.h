#pragma once
// A region of the plane in the contact point's coordinates (u_a, v_a): a
// circle or an axis-aligned box. One type for the task's forbidden zones
// wherever they are read as geometry: what a bot observes
// (script::BotObservation, which crosses threads as plain bytes, so the
// fields are plain numbers) and what the autopilot plans around
// (autopilot::Goal). A level declares its zones as task::ZoneDef (with a
// name for messages); the judge's view of them is filled into this.

#include <array>

#include "engine/physics/StateLayout.h"

namespace hemiroll::physics {

struct PlaneZone {
  bool circle = true;
  std::array<double, 2> centre{};      // circle [m]
  double radius = 0.0;                 // circle [m]
  std::array<double, 2> min{}, max{};  // box [m]

  // Distance from the zone's edge, negative inside [m].
  double clearance(const Vec2& point) const;
  bool operator==(const PlaneZone&) const = default;
};

}  // namespace hemiroll::physics
