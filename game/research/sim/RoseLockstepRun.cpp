#include "game/research/sim/RoseLockstepRun.h"

#include <deque>
#include <stdexcept>

#include "engine/physics/BatchedRk4.h"
#include "engine/physics/Integrator.h"
#include "engine/physics/RoseDrive.h"
#include "engine/physics/StateLayout.h"
#include "engine/physics/Stepper.h"

namespace hemiroll::game {

namespace {

// A StateOnly row element by element: LaneBatch::state has just written x
// one element at a time, and paired loads of it would wait for those stores
// to reach the cache instead of being forwarded (as in RungeKutta4::step).
HEMIROLL_SCALAR_LOOPS void fillStateOnly(TrajectoryRow& row, double t, const physics::Vec2& p,
                                         const physics::BodyState& x) {
  row.time = t;
  row.state[physics::force_slot::x_p] = p[0];
  row.state[physics::force_slot::y_p] = p[1];
  for (int k = 0; k < 8; ++k) row.state[physics::force_slot::body + k] = x[k];
}

}  // namespace

bool RoseLockstepRun::eligible(const task::ScenarioDef& scenario, const RunSettings& settings) {
  return scenario.drive.kind == task::DriveKind::Rose && settings.integrator == "rk4" &&
         settings.orientation == physics::OrientationForm::ContactAngles;
}

RoseLockstepRun::RoseLockstepRun(std::vector<task::ScenarioDef> scenarios, const RunSettings& settings, int width,
                                 RowContent content)
    : scenarios_(std::move(scenarios)), settings_(settings), width_(width), content_(content) {
  for (const task::ScenarioDef& s : scenarios_)
    if (!eligible(s, settings_))
      throw std::invalid_argument("a lockstep run takes rose drives with rk4 on the contact angles only");
  if (!physics::laneWidthSupported(width_))
    throw std::invalid_argument("lane width " + std::to_string(width_) + " is not run by this CPU");
}

// The loop of ScenarioRun's integrate(), lane by lane: the same clock (each
// step from the grid time (i - 1) dt, the last one shortened), the same
// domain check at the step's end, the same rows.
std::vector<RunSummary> RoseLockstepRun::run(const LaneRowCallback& onRow) const {
  const std::size_t lanes = scenarios_.size();
  std::deque<physics::RoseDrive> roses;  // a deque: the systems keep references to them
  std::deque<physics::PrescribedDriveSystem> systems;
  physics::RoseBatch batch(width_);
  physics::RungeKutta4<8> rk4;
  std::vector<RunSummary> summaries(lanes);
  // A row at t; `drive` is the rose's p at t where the lanes have it
  // already (a StateOnly row then needs no scalar evaluation of the rose).
  auto emitWith = [&](std::size_t lane, double t, const physics::BodyState& x, const physics::Vec2* drive) {
    TrajectoryRow row;
    if (content_ == RowContent::Full) {
      row = roseRow(systems[lane], t, x);
    } else {
      fillStateOnly(row, t, drive != nullptr ? *drive : roses[lane].at(t).p, x);
    }
    summaries[lane].endTime = row.time;
    summaries[lane].finalEnergy = row.energy;
    onRow(lane, row);
  };
  auto emit = [&](std::size_t lane, double t, const physics::BodyState& x) { emitWith(lane, t, x, nullptr); };

  std::size_t active = lanes;  // batch.activeCount(), kept here rather than counted at every step
  auto retire = [&](int lane) {
    batch.retire(lane);
    --active;
  };
  for (std::size_t lane = 0; lane < lanes; ++lane) {
    const task::ScenarioDef& s = scenarios_[lane];
    roses.emplace_back(s.drive.rose);
    systems.emplace_back(s.params, roses.back());
    const physics::BodyState x0 = s.initial.tail<8>();
    batch.add(s.params, s.drive.rose, x0, systems.back().interior());
    emit(lane, 0.0, x0);
    summaries[lane].event = systems[lane].domainEvent(0.0, x0);  // as the Stepper classifies its start
    if (summaries[lane].event != physics::DomainEvent::None) retire(static_cast<int>(lane));
  }

  const long long steps = ScenarioRun::stepCount(settings_);
  const double lastStep = settings_.duration - static_cast<double>(steps - 1) * settings_.timeStep;
  double start = 0.0;  // the grid time the step begins at
  long long stepped = 0;  // the last step taken: the count of every lane still active
  for (long long i = 1; i <= steps && active > 0; ++i) {
    const double h = i == steps ? lastStep : settings_.timeStep;
    const double target = i == steps ? settings_.duration : static_cast<double>(i) * settings_.timeStep;
    batch.step(start, h, target);
    stepped = i;
    // The same for every lane of this step (a division per lane was ~1 % of a sweep).
    const double end = start + h;
    const bool rowStep = i % settings_.every == 0 || i == steps;
    const bool offGrid = i < steps && target != end;
    // Every lane surely inside at both times (the lanes' own domain check)
    // and no row due: no lane has anything to do (~10 % of a sweep when
    // each was checked here).
    if (!rowStep && batch.everyActiveLaneSurelyInside()) {
      start = target;
      continue;
    }
    for (std::size_t lane = 0; lane < lanes; ++lane) {
      const int index = static_cast<int>(lane);
      if (!batch.active(index)) continue;
      RunSummary& summary = summaries[lane];
      summary.steps = i;
      const physics::BodyState x = batch.state(index);
      // surelyInside: domainEventWith's fast path, at end and at target.
      const bool surelyInside = batch.surelyInside(index);
      if (surelyInside ||
          systems[lane].domainEventWith(end, x, batch.drivePosition(index)) == physics::DomainEvent::None) {
        if (rowStep) {
          const physics::Vec2 drive = batch.gridDrivePosition(index);  // the rose at target, RoseDrive::at's bits
          emitWith(lane, target, x, &drive);
        }
        // ScenarioRun puts the clock on the grid (Stepper::reset), which
        // classifies the state again at the grid time; where that differs
        // from start + h in the last bit, so may the verdict, and its next
        // step then reports the event without stepping.
        if (offGrid && !surelyInside) {
          const physics::DomainEvent atGrid = systems[lane].domainEventWith(target, x, batch.gridDrivePosition(index));
          if (atGrid != physics::DomainEvent::None) {
            summary.steps = i + 1;
            summary.event = atGrid;
            const physics::Vec2 drive = batch.gridDrivePosition(index);
            emitWith(lane, target, x, &drive);
            retire(index);
          }
        }
        continue;
      }
      // The scalar Stepper takes the step again from the same state and
      // locates the event by bisection, exactly as ScenarioRun's would.
      physics::Stepper<8> stepper(systems[lane], rk4, batch.previousState(index), start);
      summary.event = stepper.advance(h).event;
      emit(lane, stepper.time(), stepper.state());
      retire(index);
    }
    start = target;
  }
  for (std::size_t lane = 0; lane < lanes; ++lane)
    if (batch.active(static_cast<int>(lane))) summaries[lane].steps = stepped;
  return summaries;
}

}  // namespace hemiroll::game
