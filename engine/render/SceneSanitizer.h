#pragma once
// Never NaN on screen: every number of a RenderScene is checked before it
// reaches the GPU. The hemisphere's pose (centre, orientation, radius, mass
// point) falls back to the last good pose as a whole (a half-updated pose
// would tear the body apart); a non-finite proxy, force or marker is left out
// of this frame. The orientation must also be a rotation (orthonormal within
// 1e-3): a corrupt matrix would shear the mesh.

#include "engine/render/RenderScene.h"

namespace hemiroll::render {

class SceneSanitizer {
 public:
  // Writes a drawable copy of `in` into `out` (out's vectors are reused).
  // Returns false when something had to be replaced or dropped.
  bool sanitize(const RenderScene& in, RenderScene& out);
  bool hasGoodPose() const { return hasGoodPose_; }

 private:
  bool hasGoodPose_ = false;
  RenderScene lastGood_;  // only its pose fields are used
};

}  // namespace hemiroll::render
