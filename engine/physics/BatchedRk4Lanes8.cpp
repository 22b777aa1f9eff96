// BatchedRk4's width 8, built with -mavx512f (engine/physics/CMakeLists.txt)
// and called only when the CPU has AVX-512F (bestLaneWidth).
#include "engine/physics/BatchedRk4Kernels.h"

namespace hemiroll::physics::lanes {

namespace {
typedef double Lanes8 __attribute__((vector_size(64)));
}  // namespace

[[gnu::flatten]] bool roseStepLanes8(const BatchView& v, double t, double h) { return roseStep<Lanes8>(v, t, h); }
[[gnu::flatten]] void forceDrivenStepLanes8(const BatchView& v, double h) { forceDrivenStep<Lanes8>(v, h); }

}  // namespace hemiroll::physics::lanes
