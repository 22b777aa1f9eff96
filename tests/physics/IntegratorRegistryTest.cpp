// engine/physics/IntegratorRegistry. It lives here, not in tests/physics,
// only because that directory was being reworked when the registry was added;
// move it to physics_tests when convenient.

#include "engine/physics/IntegratorRegistry.h"

#include <gtest/gtest.h>

#include "engine/physics/ForceDrivenSystem.h"

namespace hemiroll::physics {
namespace {

TEST(IntegratorRegistry, ListsRk4) {
  const auto& registry = IntegratorRegistry::builtin();
  ASSERT_FALSE(registry.list().empty());
  EXPECT_EQ(registry.list().front().name, "rk4");
  EXPECT_EQ(registry.list().front().order, 4);
  EXPECT_TRUE(registry.contains("rk4"));
  EXPECT_FALSE(registry.contains("nope"));
}

TEST(IntegratorRegistry, MakesBothStateSizes) {
  const auto& registry = IntegratorRegistry::builtin();
  for (const IntegratorInfo& info : registry.list()) {
    auto a = registry.make<12>(info.name);
    auto b = registry.make<8>(info.name);
    ASSERT_NE(a, nullptr) << info.name;
    ASSERT_NE(b, nullptr) << info.name;
    EXPECT_EQ(a->name(), info.name);
    EXPECT_EQ(b->name(), info.name);
  }
  EXPECT_EQ(registry.make<12>("nope"), nullptr);
  EXPECT_EQ(registry.makePrescribed("nope"), nullptr);
}

TEST(IntegratorRegistry, EachCallGivesAFreshIntegrator) {
  const auto& registry = IntegratorRegistry::builtin();
  auto a = registry.make<12>("rk4");
  auto b = registry.make<12>("rk4");
  EXPECT_NE(a.get(), b.get());
  // A made integrator steps a model: free motion from a tilted start changes the state.
  ForceDrivenSystem system{HemisphereParams{}};
  ForceDrivenState x = ForceDrivenState::Zero();
  x[force_slot::w_x] = 0.1;
  const ForceDrivenState before = x;
  a->step(system, 0.0, x, 1e-3);
  EXPECT_NE(x, before);
  EXPECT_TRUE(x.allFinite());
}

}  // namespace
}  // namespace hemiroll::physics
