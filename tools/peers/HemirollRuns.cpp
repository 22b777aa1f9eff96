#include "tools/peers/HemirollRuns.h"

#include <cmath>
#include <functional>
#include <memory>

#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/IntegratorRegistry.h"

namespace hemiroll::tools::peers {

using namespace physics;

namespace {

template <int N>
std::vector<Sample> integrate(const PeerScene& scene, const OdeSystem<N>& system, StateVector<N> x,
                              Integrator<N>& method, double stepOrTolerance,
                              const std::function<Pose(double, const StateVector<N>&)>& poseAt) {
  const int intervals = static_cast<int>(std::lround(scene.horizon / kSampleInterval));
  std::vector<Sample> samples;
  samples.reserve(intervals + 1);
  samples.push_back(sampleOf(scene, poseAt(0.0, x), 0.0));
  double t = 0.0;
  if (AdaptiveIntegrator<N>* adaptive = method.adaptive()) {
    adaptive->setTolerance(stepOrTolerance);
    for (int i = 1; i <= intervals; ++i) {
      method.step(system, t, x, kSampleInterval);  // adaptive inside, lands on t + interval
      t = i * kSampleInterval;
      samples.push_back(sampleOf(scene, poseAt(t, x), t));
    }
    return samples;
  }
  const long perSample = std::lround(kSampleInterval / stepOrTolerance);
  for (int i = 1; i <= intervals; ++i) {
    for (long k = 0; k < perSample; ++k) {
      method.step(system, t, x, stepOrTolerance);
      t += stepOrTolerance;
    }
    t = i * kSampleInterval;  // no drift of the clock over 10^5 steps
    samples.push_back(sampleOf(scene, poseAt(t, x), t));
  }
  return samples;
}

// Samples of one run; cpuSeconds gets the CPU time of the integration.
std::vector<Sample> runScene(const PeerScene& scene, const std::string& integrator, double stepOrTolerance,
                             double& cpuSeconds) {
  const IntegratorRegistry& registry = IntegratorRegistry::builtin();
  if (scene.drive == PointDrive::Prescribed) {
    PrescribedDriveSystem system(scene.params, *scene.trajectory);
    auto method = registry.makePrescribed(integrator);
    const BodyState x0 = scene.x0.tail<8>();
    const double t0 = cpuNow();
    auto samples = integrate<8>(scene, system, x0, *method, stepOrTolerance, [&](double t, const BodyState& x) {
      return poseOf(scene.params, system.fullState(t, x));
    });
    cpuSeconds = cpuNow() - t0;
    return samples;
  }
  ForceDrivenSystem system(scene.params);
  if (scene.drive == PointDrive::Tether) {
    system.setCoupling(CouplingDef{ForceMethod::M2, scene.tetherStiffness, 0.0, 1.0, false});
    system.holdProxy({scene.proxy, Vec3::Zero()});
  }
  auto method = registry.makeForceDriven(integrator);
  const double t0 = cpuNow();
  auto samples = integrate<12>(scene, system, scene.x0, *method, stepOrTolerance,
                               [&](double, const ForceDrivenState& x) { return poseOf(scene.params, x); });
  cpuSeconds = cpuNow() - t0;
  return samples;
}

}  // namespace

std::vector<Sample> referenceSamples(const PeerScene& scene, double tolerance) {
  double unused = 0.0;
  return runScene(scene, "dop853ld", tolerance, unused);
}

RunResult hemirollRun(const PeerScene& scene, const std::string& integrator, double stepOrTolerance,
                      double targetSeconds, int maxRepeats) {
  const bool adaptive = IntegratorRegistry::builtin().makeForceDriven(integrator)->adaptive() != nullptr;
  return timedRun(
      [&] {
        RunResult r;
        r.engine = "hemiroll";
        r.setting = integrator;
        r.step = stepOrTolerance;
        r.adaptive = adaptive;
        r.samples = runScene(scene, integrator, stepOrTolerance, r.cpuSeconds);
        return r;
      },
      targetSeconds, maxRepeats);
}

}  // namespace hemiroll::tools::peers
