// BatchedRk4's width 4, built with -mavx2 (engine/physics/CMakeLists.txt)
// and called only when the CPU has AVX2 (bestLaneWidth).
#include "engine/physics/BatchedRk4Kernels.h"

namespace hemiroll::physics::lanes {

namespace {
typedef double Lanes4 __attribute__((vector_size(32)));
}  // namespace

[[gnu::flatten]] bool roseStepLanes4(const BatchView& v, double t, double h) { return roseStep<Lanes4>(v, t, h); }
[[gnu::flatten]] void forceDrivenStepLanes4(const BatchView& v, double h) { forceDrivenStep<Lanes4>(v, h); }

}  // namespace hemiroll::physics::lanes
