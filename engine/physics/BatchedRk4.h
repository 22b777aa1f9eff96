#pragma once
// Many independent trajectories of one model, stepped with RK4 in lockstep,
// one trajectory per SIMD lane: the 8-state rose drive (sweeps) and the
// 12-state force-driven model, free or coupled to a held proxy (rollouts).
//
// Why lanes: one trajectory is near its limit (a right-hand side is a long
// dependent chain of about 48 ns); many trajectories of the same model are
// the same chain many times over, which a vector unit runs side by side.
//
// Same bits as the scalar path, in every lane and at every width: each lane
// runs the very functions the scalar systems evaluate (prescribedRatesOf,
// forceDrivenRatesOf, roseSampleOf: templates over the number type), with
// sinCosLanes for the engine's sinCos and RK4's operations in RungeKutta4's
// order; the build forbids FMA contraction (-ffp-contract=off), so a vector
// lane rounds as a scalar does. tests/physics/BatchedRk4Test checks it bit
// for bit against RungeKutta4 and the scalar systems at every width this CPU
// runs. A sweep or a replay is therefore the same whatever the lane width.
//
// Widths: 8 lanes with AVX-512F, 4 with AVX2, 2 with SSE2 (every x86-64),
// chosen at run time (bestLaneWidth); 1 runs the same code on plain doubles.
// Each width is its own translation unit compiled for its instruction set
// (BatchedRk4Lanes*.cpp); the release binary runs on any x86-64.
//
// Lanes that stop (a domain event, located by the caller with the scalar
// Stepper) are retired: they keep their last state and no longer change,
// while the others go on.

#include <optional>
#include <vector>

#include "engine/physics/DomainEvents.h"
#include "engine/physics/ForceCoupling.h"
#include "engine/physics/HemisphereParams.h"
#include "engine/physics/RoseDrive.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::physics {

// The widest lane count this CPU runs: 8, 4 or 2.
int bestLaneWidth();
// True when this CPU runs `width` lanes (1, 2, 4 or 8).
bool laneWidthSupported(int width);

namespace lanes {
// The data of a batch, structure of arrays: row r of `rows` is one quantity
// for every lane (rows + r * padded), the state likewise; padded is a
// multiple of 8, unused lanes are inactive.
struct BatchView {
  const double* rows;
  double* state;
  int padded;
  int method;  // the coupling's ForceMethod, or -1 for free motion (12-state only)
  // Rose only: kDriveRows rows of `padded` (DriveRow). The kernel writes the
  // drive's p at the step's end t + h (RoseBatch::drivePosition) and the
  // rose's p and p' at gridEnd with that time (gridDrivePosition, and the
  // sample the next step reuses if it begins there). The caller sets the
  // kept time to NaN where the rows hold no sample of the lanes' roses.
  // The kernel also writes kSurelyInside (RoseBatch::surelyInside), 1 or 0.
  double* drive = nullptr;
  double gridEnd = 0.0;
};
enum DriveRow : int {
  kEndX, kEndY, kGridX, kGridY, kKeptPDotX, kKeptPDotY, kKeptSampleTime, kSurelyInside, kDriveRows
};
// Rows shared by both models: the mass constants, then whether a lane is active.
enum Row : int {
  kPointMass,
  kShellMass,
  kRadius,
  kGravity,
  kComDepth,
  kShellMoment,
  kActive,
  kCommonRows,
  // The rose drive's.
  kRoseR1 = kCommonRows,
  kRoseR2,
  kRoseK,
  kRoseOmega,
  kTiltSumBound,  // the lane's InteriorCheck
  kFaceBoundSquared,
  kRoseRows,
  // The coupling's, and the held proxy's pose.
  kStiffness = kCommonRows,
  kDamping,
  kAlpha,
  kProxyX,
  kProxyY,
  kProxyZ,
  kProxyVx,
  kProxyVy,
  kProxyVz,
  kCoupledRows,
};

// One width's step of every active lane, defined in BatchedRk4Lanes<W>.cpp
// (widths 1 and 2 in BatchedRk4Lanes2.cpp). The rose's returns whether every
// active lane is surely inside (RoseBatch::everyActiveLaneSurelyInside).
bool roseStepLanes1(const BatchView& v, double t, double h);
bool roseStepLanes2(const BatchView& v, double t, double h);
bool roseStepLanes4(const BatchView& v, double t, double h);
bool roseStepLanes8(const BatchView& v, double t, double h);
void forceDrivenStepLanes1(const BatchView& v, double h);
void forceDrivenStepLanes2(const BatchView& v, double h);
void forceDrivenStepLanes4(const BatchView& v, double h);
void forceDrivenStepLanes8(const BatchView& v, double h);
}  // namespace lanes

// The lockstep state shared by both models: N states per lane.
template <int N>
class LaneBatch {
 public:
  int width() const { return width_; }
  int size() const { return size_; }
  StateVector<N> state(int lane) const;
  // The state before the last step (for locating an event inside it); the
  // state itself before any step. A lane added since the last step has none.
  StateVector<N> previousState(int lane) const;
  void setState(int lane, const StateVector<N>& x);
  bool active(int lane) const { return row(lanes::kActive)[lane] != 0.0; }
  // The lane keeps its state and stops changing.
  void retire(int lane) { rowMutable(lanes::kActive)[lane] = 0.0; }
  int activeCount() const;

 protected:
  LaneBatch(int width, int rowCount);
  int addLane(const HemisphereParams& params, const StateVector<N>& x0);
  const double* row(int r) const { return rows_.data() + static_cast<std::size_t>(r) * padded_; }
  double* rowMutable(int r) { return rows_.data() + static_cast<std::size_t>(r) * padded_; }
  // Keeps the states as previousState() and gives the kernels the batch.
  lanes::BatchView beginStep(int method);

 private:
  void grow();

  int width_;
  int rowCount_;
  int size_ = 0;
  int padded_ = 0;
  std::vector<double> rows_;
  std::vector<double> state_;
  std::vector<double> previous_;
};

// The 8-state prescribed rose drive (PrescribedDriveSystem with a RoseDrive).
class RoseBatch final : public LaneBatch<8> {
 public:
  explicit RoseBatch(int width = bestLaneWidth());
  // The new lane's index. `interior` is the lane's system's
  // (PrescribedDriveSystem::interior); without one, no state of the lane is
  // surely inside (surelyInside is always false).
  int add(const HemisphereParams& params, const RoseDef& rose, const BodyState& x0);
  int add(const HemisphereParams& params, const RoseDef& rose, const BodyState& x0, const InteriorCheck& interior);
  // One RK4 step of every active lane from t to t + h; gridEnd is the time
  // the caller puts the clock on after it (the grid time, which may differ
  // from t + h in the last bit), where gridDrivePosition evaluates the rose.
  void step(double t, double h) { step(t, h, t + h); }
  void step(double t, double h, double gridEnd);
  // The drive's p at t + h of the last step, as the step's last stage
  // evaluated it in the lanes: the bits of RoseDrive::at(t + h).p, so the
  // domain check after a step needs no scalar evaluation of the rose
  // (PrescribedDriveSystem::domainEventWith). Only for a lane that was
  // active in the last step (a group of retired lanes is not stepped).
  Vec2 drivePosition(int lane) const;
  // The same at the last step's gridEnd (RoseDrive::at(gridEnd).p's bits).
  Vec2 gridDrivePosition(int lane) const;
  // Whether the lane's state after the last step is finite and passes its
  // InteriorCheck::surelyInside at drivePosition and at gridDrivePosition:
  // then PrescribedDriveSystem::domainEventWith would answer None at both
  // times by its fast path, and the caller need not ask it. Computed in the
  // lanes, with the scalar test's operations in its order, so the same
  // answer (BatchedRk4Test); false where it is not, and the caller checks
  // the lane exactly. Only for a lane that was active in the last step.
  bool surelyInside(int lane) const;
  // The same for every lane active in the last step (a step where this holds
  // and no row is due needs nothing lane by lane).
  bool everyActiveLaneSurelyInside() const { return everyActiveLaneSurelyInside_; }

 private:
  std::vector<double> driveEnd_;
  int drivePadded_ = 0;
  // A lane was added since the drive rows were laid out: their kept samples
  // are not of the lanes' present roses (or rows).
  bool driveRowsStale_ = true;
  bool everyActiveLaneSurelyInside_ = false;
};

// The 12-state force-driven model (ForceDrivenSystem): free motion, or every
// lane coupled by the same method to its own proxy, held between steps.
class ForceDrivenBatch final : public LaneBatch<12> {
 public:
  // Free motion without a coupling method; else the method all lanes share.
  explicit ForceDrivenBatch(std::optional<ForceMethod> coupling, int width = bestLaneWidth());
  // The coupling's gains (its method must be the batch's); ignored when free.
  int add(const HemisphereParams& params, const CouplingDef& coupling, const ForceDrivenState& x0);
  void holdProxy(int lane, const ProxyPose& pose);
  // One RK4 step of every active lane (autonomous: t does not enter).
  void step(double t, double h);

 private:
  int method_;
};

}  // namespace hemiroll::physics
