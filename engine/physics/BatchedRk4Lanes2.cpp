// BatchedRk4's widths 1 (plain doubles) and 2 (SSE2, every x86-64), built
// with the project's baseline flags.
#include "engine/physics/BatchedRk4Kernels.h"

namespace hemiroll::physics::lanes {

namespace {
typedef double Lanes2 __attribute__((vector_size(16)));
}  // namespace

[[gnu::flatten]] bool roseStepLanes1(const BatchView& v, double t, double h) { return roseStep<double>(v, t, h); }
[[gnu::flatten]] bool roseStepLanes2(const BatchView& v, double t, double h) { return roseStep<Lanes2>(v, t, h); }
[[gnu::flatten]] void forceDrivenStepLanes1(const BatchView& v, double h) { forceDrivenStep<double>(v, h); }
[[gnu::flatten]] void forceDrivenStepLanes2(const BatchView& v, double h) { forceDrivenStep<Lanes2>(v, h); }

}  // namespace hemiroll::physics::lanes
