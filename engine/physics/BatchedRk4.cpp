#include "engine/physics/BatchedRk4.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace hemiroll::physics {

namespace {

// Lanes are allocated in blocks of the widest width, so that every width
// steps whole groups and a group never reads past the rows.
constexpr int kLaneBlock = 8;

void requireSupported(int width) {
  if (!laneWidthSupported(width))
    throw std::invalid_argument("lane width " + std::to_string(width) + " is not run by this CPU (1, 2" +
                                (laneWidthSupported(4) ? ", 4" : "") + (laneWidthSupported(8) ? ", 8" : "") +
                                " are)");
}

}  // namespace

bool laneWidthSupported(int width) {
  switch (width) {
    case 1:
    case 2: return true;  // plain doubles and SSE2: every x86-64
    case 4: return __builtin_cpu_supports("avx2");
    case 8: return __builtin_cpu_supports("avx512f");
    default: return false;
  }
}

int bestLaneWidth() {
  static const int best = laneWidthSupported(8) ? 8 : laneWidthSupported(4) ? 4 : 2;
  return best;
}

template <int N>
LaneBatch<N>::LaneBatch(int width, int rowCount) : width_(width), rowCount_(rowCount) {
  requireSupported(width);
}

template <int N>
void LaneBatch<N>::grow() {
  const int padded = padded_ + kLaneBlock;
  auto regrow = [&](std::vector<double>& data, int rows) {
    std::vector<double> wider(static_cast<std::size_t>(rows) * padded, 0.0);
    for (int r = 0; r < rows; ++r)
      std::copy_n(data.begin() + static_cast<std::ptrdiff_t>(r) * padded_, padded_,
                  wider.begin() + static_cast<std::ptrdiff_t>(r) * padded);
    data.swap(wider);
  };
  regrow(rows_, rowCount_);
  regrow(state_, N);
  if (!previous_.empty()) regrow(previous_, N);
  // The new lanes are inactive; give them a harmless model (unit masses and
  // radius) so that stepping their group beside active lanes computes no NaN.
  for (int lane = padded_; lane < padded; ++lane)
    for (int r : {lanes::kPointMass, lanes::kShellMass, lanes::kRadius, lanes::kShellMoment})
      rows_[static_cast<std::size_t>(r) * padded + lane] = 1.0;
  padded_ = padded;
}

template <int N>
int LaneBatch<N>::addLane(const HemisphereParams& params, const StateVector<N>& x0) {
  if (size_ == padded_) grow();
  const int lane = size_++;
  const ModelConstants c(params);
  const MassConstantsOf<double> m = massConstantsOf(c);
  rowMutable(lanes::kPointMass)[lane] = m.pointMass;
  rowMutable(lanes::kShellMass)[lane] = m.shellMass;
  rowMutable(lanes::kRadius)[lane] = m.radius;
  rowMutable(lanes::kGravity)[lane] = m.gravity;
  rowMutable(lanes::kComDepth)[lane] = m.comDepth;
  rowMutable(lanes::kShellMoment)[lane] = m.shellMoment;
  rowMutable(lanes::kActive)[lane] = 1.0;
  setState(lane, x0);
  return lane;
}

template <int N>
StateVector<N> LaneBatch<N>::state(int lane) const {
  StateVector<N> x;
  for (int i = 0; i < N; ++i) x[i] = state_[static_cast<std::size_t>(i) * padded_ + lane];
  return x;
}

template <int N>
StateVector<N> LaneBatch<N>::previousState(int lane) const {
  if (previous_.empty()) return state(lane);  // no step yet
  StateVector<N> x;
  for (int i = 0; i < N; ++i) x[i] = previous_[static_cast<std::size_t>(i) * padded_ + lane];
  return x;
}

template <int N>
void LaneBatch<N>::setState(int lane, const StateVector<N>& x) {
  for (int i = 0; i < N; ++i) state_[static_cast<std::size_t>(i) * padded_ + lane] = x[i];
}

template <int N>
int LaneBatch<N>::activeCount() const {
  const double* active = row(lanes::kActive);
  return static_cast<int>(std::count_if(active, active + size_, [](double a) { return a != 0.0; }));
}

template <int N>
lanes::BatchView LaneBatch<N>::beginStep(int method) {
  previous_ = state_;  // same size after the first step: a copy, no allocation
  return {rows_.data(), state_.data(), padded_, method};
}

template class LaneBatch<8>;
template class LaneBatch<12>;

RoseBatch::RoseBatch(int width) : LaneBatch<8>(width, lanes::kRoseRows) {}

int RoseBatch::add(const HemisphereParams& params, const RoseDef& rose, const BodyState& x0) {
  // Negative bounds: no state passes (as InteriorCheck's own where no sum or
  // radius is safe).
  return add(params, rose, x0, InteriorCheck(1.0, 0.0));
}

int RoseBatch::add(const HemisphereParams& params, const RoseDef& rose, const BodyState& x0,
                   const InteriorCheck& interior) {
  const int lane = addLane(params, x0);
  rowMutable(lanes::kRoseR1)[lane] = rose.r1;
  rowMutable(lanes::kRoseR2)[lane] = rose.r2;
  rowMutable(lanes::kRoseK)[lane] = rose.k;
  rowMutable(lanes::kRoseOmega)[lane] = rose.omega;
  rowMutable(lanes::kTiltSumBound)[lane] = interior.tiltSumBound();
  rowMutable(lanes::kFaceBoundSquared)[lane] = interior.faceBoundSquared();
  driveRowsStale_ = true;
  return lane;
}

void RoseBatch::step(double t, double h, double gridEnd) {
  lanes::BatchView v = beginStep(-1);
  if (driveRowsStale_) {  // allocates only when lanes were added
    drivePadded_ = v.padded;
    driveEnd_.assign(lanes::kDriveRows * static_cast<std::size_t>(v.padded), 0.0);
    std::fill_n(driveEnd_.begin() + static_cast<std::ptrdiff_t>(lanes::kKeptSampleTime) * v.padded, v.padded,
                std::numeric_limits<double>::quiet_NaN());
    driveRowsStale_ = false;
  }
  v.drive = driveEnd_.data();
  v.gridEnd = gridEnd;
  switch (width()) {
    case 8: everyActiveLaneSurelyInside_ = lanes::roseStepLanes8(v, t, h); break;
    case 4: everyActiveLaneSurelyInside_ = lanes::roseStepLanes4(v, t, h); break;
    case 2: everyActiveLaneSurelyInside_ = lanes::roseStepLanes2(v, t, h); break;
    default: everyActiveLaneSurelyInside_ = lanes::roseStepLanes1(v, t, h); break;
  }
}

Vec2 RoseBatch::drivePosition(int lane) const {
  auto at = [&](int r) { return driveEnd_[static_cast<std::size_t>(r) * drivePadded_ + lane]; };
  return {at(lanes::kEndX), at(lanes::kEndY)};
}

Vec2 RoseBatch::gridDrivePosition(int lane) const {
  auto at = [&](int r) { return driveEnd_[static_cast<std::size_t>(r) * drivePadded_ + lane]; };
  return {at(lanes::kGridX), at(lanes::kGridY)};
}

bool RoseBatch::surelyInside(int lane) const {
  return driveEnd_[static_cast<std::size_t>(lanes::kSurelyInside) * drivePadded_ + lane] != 0.0;
}

ForceDrivenBatch::ForceDrivenBatch(std::optional<ForceMethod> coupling, int width)
    : LaneBatch<12>(width, lanes::kCoupledRows), method_(coupling ? static_cast<int>(*coupling) : -1) {}

int ForceDrivenBatch::add(const HemisphereParams& params, const CouplingDef& coupling, const ForceDrivenState& x0) {
  if (method_ >= 0 && static_cast<int>(coupling.method) != method_)
    throw std::invalid_argument(std::string("a batch coupled by one method was given a lane coupled by ") +
                                forceMethodName(coupling.method));
  const int lane = addLane(params, x0);
  rowMutable(lanes::kStiffness)[lane] = coupling.stiffness;
  rowMutable(lanes::kDamping)[lane] = coupling.damping;
  rowMutable(lanes::kAlpha)[lane] = coupling.alpha;
  return lane;
}

void ForceDrivenBatch::holdProxy(int lane, const ProxyPose& pose) {
  const double values[] = {pose.position.x(), pose.position.y(), pose.position.z(),
                           pose.velocity.x(), pose.velocity.y(), pose.velocity.z()};
  for (int i = 0; i < 6; ++i) rowMutable(lanes::kProxyX + i)[lane] = values[i];
}

void ForceDrivenBatch::step(double, double h) {
  const lanes::BatchView v = beginStep(method_);
  switch (width()) {
    case 8: lanes::forceDrivenStepLanes8(v, h); break;
    case 4: lanes::forceDrivenStepLanes4(v, h); break;
    case 2: lanes::forceDrivenStepLanes2(v, h); break;
    default: lanes::forceDrivenStepLanes1(v, h); break;
  }
}

}  // namespace hemiroll::physics
