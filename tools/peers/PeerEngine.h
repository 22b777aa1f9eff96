#pragma once
// One interface for every engine of the study, CHAI3D-style: each engine is a
// small class that builds its world for a scene and setting; the shared
// driver (runWorld) reads, computes the drive, applies, steps and samples, so
// the engines differ only in how they model the bodies and the contact.

#include <memory>
#include <string>
#include <vector>

#include "tools/peers/PeerRun.h"

namespace hemiroll::tools::peers {

struct PeerSetting {
  std::string name;         // "default", "tuned"
  std::string description;  // what is set, for PEERS.md
};

// A built world: bodies, joints and contact of one scene at one setting.
class PeerWorld {
 public:
  virtual ~PeerWorld() = default;
  virtual Pose pose() const = 0;
  // The world force on the mass point over the next step [N]: the tether's
  // spring, or the hand that carries the prescribed point.
  virtual void setPointForce(const Vec3& force) = 0;
  // True when the engine models the tether's spring itself (inside its own
  // integrator's stages) rather than taking it from setPointForce.
  virtual bool ownsTether() const { return false; }
  virtual void step() = 0;
};

class PeerEngine {
 public:
  virtual ~PeerEngine() = default;
  virtual std::string name() const = 0;
  virtual std::string version() const = 0;
  virtual std::vector<PeerSetting> settings() const = 0;
  // The scene's world at t = 0; nullptr with `error` set if the engine
  // refuses it.
  virtual std::unique_ptr<PeerWorld> build(const PeerScene& scene, const std::string& setting, double timestep,
                                           std::string& error) const = 0;
};

std::unique_ptr<PeerEngine> makeMujocoEngine();
std::unique_ptr<PeerEngine> makeBulletEngine();
std::unique_ptr<PeerEngine> makeOdeEngine();

// Builds and runs one scene to its horizon, sampling every kSampleInterval;
// cpuSeconds covers the stepping loop only. A run whose state stops being
// finite ends there, with `failure` saying when.
RunResult runPeer(const PeerEngine& engine, const PeerScene& scene, const std::string& setting, double timestep);

}  // namespace hemiroll::tools::peers
