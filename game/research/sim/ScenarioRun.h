#pragma once
// Runs a loaded scenario headless: builds the model its drive asks for (the
// 8-state prescribed drive for "rose", the 12-state force-driven model for
// "free" and "proxy", or its 13-state quaternion form on request), steps it with the chosen integrator through the
// event-locating Stepper, and hands sampled rows to a callback.
//
// Rows: the initial state, every `every`-th step, the last step, and, when a
// domain event stops the run, the state at the located event time.

#include <functional>
#include <string>

#include "engine/physics/DomainEvents.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/PrescribedDriveSystem.h"
#include "engine/physics/RotationDrivenSystem.h"
#include "engine/task/ScenarioDef.h"
#include "game/research/sim/TrajectoryRow.h"

namespace hemiroll::game {

struct RunSettings {
  double duration = 10.0;        // [s]
  double timeStep = 1e-3;        // [s]
  std::string integrator = "rk4";
  long long every = 1;           // a row every N steps
  double tolerance = 1e-8;       // adaptive integrators only (--tol); they step freely and
                                 // the rows on the timeStep grid come from dense output
  // Free and proxy drives only: the quaternion form integrates the same
  // physics on 13 states (RotationDrivenSystem.h); rows are the 12-state.
  physics::OrientationForm orientation = physics::OrientationForm::ContactAngles;
};

struct RunSummary {
  long long steps = 0;           // steps taken (the event step included)
  double endTime = 0.0;          // time of the last state [s]
  double finalEnergy = 0.0;      // [J]
  physics::DomainEvent event = physics::DomainEvent::None;
};

// What a rose drive's row holds: everything, or only the time, the mass
// point's position and the body's state (the mass point's velocity, the
// energy and the face force left 0, and so the summary's final energy): a
// sweep point measures none of those (PointMeasurement), and they cost a
// geometry and a dynamics evaluation per row. Rows of the other drives are
// always whole.
enum class RowContent { Full, StateOnly };

// The row of the 8-state rose drive at (t, x): the 12-state with p and p'
// from the curve, the energy and the driving force of eq. (46). Shared by
// ScenarioRun and RoseLockstepRun, so that both write the same rows.
TrajectoryRow roseRow(const physics::PrescribedDriveSystem& system, double t, const physics::BodyState& x);

class ScenarioRun {
 public:
  using RowCallback = std::function<void(const TrajectoryRow&)>;

  // Steps of length timeStep; the last one is shortened to end at duration.
  static long long stepCount(const RunSettings& settings);

  ScenarioRun(const task::ScenarioDef& scenario, const RunSettings& settings, RowContent content = RowContent::Full);

  // True when rows carry F_h (the proxy drive).
  bool hasHandForce() const { return scenario_.drive.kind == task::DriveKind::Proxy; }

  // Throws script::ScriptError if a Lua proxy fails during the run, and
  // std::invalid_argument for an unknown integrator name.
  RunSummary run(const RowCallback& onRow) const;

 private:
  RunSummary runRose(const RowCallback& onRow) const;
  RunSummary runForceDriven(const RowCallback& onRow) const;
  RunSummary runRotation(const physics::ForceDrivenSystem& rows, const RowCallback& onRow) const;

  task::ScenarioDef scenario_;  // a copy: shares the proxy (and its Lua state), owns the rest
  RunSettings settings_;
  RowContent content_;
};

}  // namespace hemiroll::game
