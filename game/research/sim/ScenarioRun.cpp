#include "game/research/sim/ScenarioRun.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "engine/physics/CouplingStability.h"
#include "engine/physics/Energy.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/IntegratorRegistry.h"
#include "engine/physics/LastSampleTrajectory.h"
#include "engine/physics/Orientation.h"
#include "engine/physics/PrescribedDriveSystem.h"
#include "engine/physics/RoseDrive.h"
#include "engine/physics/RotationDrivenSystem.h"
#include "engine/physics/Stepper.h"
#include "engine/physics/SubsteppingIntegrator.h"

namespace hemiroll::game {

namespace {

// Duration/dt within this relative distance of a whole number counts as one:
// 35 / 0.001 is 34999.999999999996 in binary floating point.
constexpr double kWholeStepTolerance = 1e-9;

template <int N>
std::unique_ptr<physics::Integrator<N>> makeIntegrator(const std::string& name, double tolerance) {
  auto integrator = physics::IntegratorRegistry::builtin().make<N>(name);
  if (!integrator) throw std::invalid_argument("unknown integrator '" + name + "'");
  if (auto* adaptive = integrator->adaptive()) adaptive->setTolerance(tolerance);
  return integrator;
}

// For the models that need nothing after each step.
struct NothingAfterStep {
  template <class State>
  void operator()(const State&) const {}
};

// The stepping loop shared by all models; `observe` turns (t, x) into a row,
// `afterStep` sees every state on the step grid (the quaternion form keeps
// psi continuous there).
template <int N, class Observe, class AfterStep = NothingAfterStep>
RunSummary integrate(const physics::OdeSystem<N>& system, physics::Integrator<N>& integrator,
                     const physics::StateVector<N>& x0, const RunSettings& settings, const Observe& observe,
                     const ScenarioRun::RowCallback& onRow, const AfterStep& afterStep = {}) {
  physics::Stepper<N> stepper(system, integrator, x0, 0.0);
  RunSummary summary;
  auto emit = [&] {
    const TrajectoryRow row = observe(stepper.time(), stepper.state());
    summary.endTime = row.time;
    summary.finalEnergy = row.energy;
    onRow(row);
  };
  emit();
  summary.event = stepper.event();  // the initial state may already be outside the domain
  if (stepper.halted()) return summary;

  const long long steps = ScenarioRun::stepCount(settings);
  const double lastStep = settings.duration - static_cast<double>(steps - 1) * settings.timeStep;
  for (long long i = 1; i <= steps; ++i) {
    const double h = i == steps ? lastStep : settings.timeStep;
    // Adaptive integrators take their own steps; the grid time comes from
    // their dense output (no reset: that would restart the step control).
    const double target = i == steps ? settings.duration : static_cast<double>(i) * settings.timeStep;
    const physics::StepReport report = stepper.adaptive() ? stepper.advanceTo(target) : stepper.advance(h);
    summary.steps = i;
    if (report.event != physics::DomainEvent::None) {
      summary.event = report.event;
      emit();
      return summary;
    }
    // The stepper accumulates t += h, which drifts (35000 steps of 1 ms end
    // at 35.000000000009); put the clock on the exact grid i * dt instead, so
    // that the drive is evaluated at the nominal times and the CSV shows them.
    if (!stepper.adaptive()) stepper.reset(stepper.state(), target);
    afterStep(stepper.state());
    if (i % settings.every == 0 || i == steps) emit();
  }
  return summary;
}

}  // namespace

TrajectoryRow roseRow(const physics::PrescribedDriveSystem& system, double t, const physics::BodyState& x) {
  TrajectoryRow row;
  row.time = t;
  row.state = system.fullState(t, x);
  row.energy = physics::mechanicalEnergy(system.dynamics(), row.state).total();
  row.faceForce = system.drivingForce(t, x);  // eq. (46)
  return row;
}

long long ScenarioRun::stepCount(const RunSettings& settings) {
  const double ratio = settings.duration / settings.timeStep;
  const double whole = std::round(ratio);
  if (std::abs(ratio - whole) <= kWholeStepTolerance * std::max(1.0, whole))
    return std::max(1LL, static_cast<long long>(whole));
  return static_cast<long long>(std::ceil(ratio));
}

ScenarioRun::ScenarioRun(const task::ScenarioDef& scenario, const RunSettings& settings, RowContent content)
    : scenario_(scenario), settings_(settings), content_(content) {}

RunSummary ScenarioRun::run(const RowCallback& onRow) const {
  return scenario_.drive.kind == task::DriveKind::Rose ? runRose(onRow) : runForceDriven(onRow);
}

RunSummary ScenarioRun::runRose(const RowCallback& onRow) const {
  const physics::RoseDrive rose(scenario_.drive.rose);
  // This run's alone (LastSampleTrajectory.h: a step asks the rose at ~2 distinct times of 6).
  const physics::LastSampleTrajectory remembered(rose);
  const physics::PrescribedDriveSystem system(scenario_.params, remembered);
  auto integrator = makeIntegrator<8>(settings_.integrator, settings_.tolerance);
  const physics::BodyState x0 = scenario_.initial.tail<8>();
  if (content_ == RowContent::StateOnly) {
    auto observe = [&](double t, const physics::BodyState& x) {
      TrajectoryRow row;
      row.time = t;
      row.state.segment<2>(physics::force_slot::x_p) = remembered.at(t).p;
      row.state.tail<8>() = x;
      return row;
    };
    return integrate<8>(system, *integrator, x0, settings_, observe, onRow);
  }
  auto observe = [&](double t, const physics::BodyState& x) { return roseRow(system, t, x); };
  return integrate<8>(system, *integrator, x0, settings_, observe, onRow);
}

namespace {

// Both forms of the force-driven model take the scenario's input the same way.
template <class System>
void applyDrive(const task::ScenarioDef& scenario, System& system) {
  if (scenario.drive.kind == task::DriveKind::Proxy)
    system.setCoupling(scenario.drive.coupling, *scenario.drive.proxy);
  else
    system.setFree();
}

// A coupling too stiff for the fixed step is substepped (CouplingStability.h);
// one substep (every paper setting) is the integrator itself, bit for bit.
template <int N>
int substepsFor(const physics::ForceDrivenSystem& system, physics::Integrator<N>& integrator,
                const RunSettings& settings, double pointMass) {
  if (!system.coupled() || integrator.adaptive()) return 1;
  return physics::couplingStepPolicy(settings.integrator, system.coupling(), pointMass, settings.timeStep).substeps;
}

// Rows (energy, forces) are computed only for the rows written (every
// `every`-th step), never for the steps in between; both forms give the
// 12-state here.
TrajectoryRow rowOf(const physics::ForceDrivenSystem& system, double t, const physics::ForceDrivenState& x) {
  TrajectoryRow row;
  row.time = t;
  row.state = x;
  row.energy = physics::mechanicalEnergy(system.dynamics(), x).total();
  if (system.coupled()) {
    const physics::CouplingForces forces = system.couplingForces(t, x);
    // Face coordinates: the components along the body's x and y axes,
    // the first two columns of R (eq. 6).
    using namespace physics::force_slot;
    const physics::Mat3 R = physics::makeOrientation(x[u_o], x[v_o], x[psi]).R;
    row.faceForce = physics::Vec2(R.col(0).dot(forces.modelForce), R.col(1).dot(forces.modelForce));
    row.handForce = forces.handForce;
  }
  return row;
}

}  // namespace

RunSummary ScenarioRun::runForceDriven(const RowCallback& onRow) const {
  // The 12-state model also computes the rows of the quaternion form.
  physics::ForceDrivenSystem system(scenario_.params);
  applyDrive(scenario_, system);
  if (settings_.orientation == physics::OrientationForm::Quaternion) return runRotation(system, onRow);

  auto integrator = makeIntegrator<12>(settings_.integrator, settings_.tolerance);
  const int substeps = substepsFor<12>(system, *integrator, settings_, scenario_.params.pointMass);
  physics::SubsteppingIntegrator<12> policed(*integrator, substeps);
  physics::Integrator<12>& stepping = substeps > 1 ? static_cast<physics::Integrator<12>&>(policed) : *integrator;
  auto observe = [&](double t, const physics::ForceDrivenState& x) { return rowOf(system, t, x); };
  return integrate<12>(system, stepping, scenario_.initial, settings_, observe, onRow);
}

RunSummary ScenarioRun::runRotation(const physics::ForceDrivenSystem& rows, const RowCallback& onRow) const {
  physics::RotationDrivenSystem system(scenario_.params);
  applyDrive(scenario_, system);
  auto integrator = makeIntegrator<13>(settings_.integrator, settings_.tolerance);
  const int substeps = substepsFor<13>(rows, *integrator, settings_, scenario_.params.pointMass);
  physics::SubsteppingIntegrator<13> policed(*integrator, substeps);
  physics::Integrator<13>& stepping = substeps > 1 ? static_cast<physics::Integrator<13>&>(policed) : *integrator;

  const physics::RotationState x0 = physics::toRotationState(scenario_.initial);
  physics::HeadingTracker heading(physics::quaternionOf(x0), scenario_.initial[physics::force_slot::psi]);
  auto follow = [&](const physics::RotationState& x) { heading.follow(physics::quaternionOf(x)); };
  auto observe = [&](double t, const physics::RotationState& x) {
    follow(x);  // an event row lies inside a step that afterStep has not seen
    return rowOf(rows, t, physics::toContactState(x, heading.psi(physics::quaternionOf(x))));
  };
  return integrate<13>(system, stepping, x0, settings_, observe, onRow, follow);
}

}  // namespace hemiroll::game
