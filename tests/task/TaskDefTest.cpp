// engine/task/TaskDef: the names of judged variables and the paper's
// vector groups.

#include "engine/task/TaskDef.h"

#include <gtest/gtest.h>

#include "engine/physics/StateLayout.h"

namespace hemiroll::task {
namespace {

TEST(TaskDef, SlotVariablesHaveTheStateLayoutsNamesAndOrder) {
  for (int slot = 0; slot < 12; ++slot) {
    const auto variable = taskVariableFromName(physics::kStateNames[slot]);
    ASSERT_TRUE(variable.has_value()) << physics::kStateNames[slot];
    EXPECT_EQ(static_cast<int>(*variable), slot);
    EXPECT_STREQ(taskVariableName(*variable), physics::kStateNames[slot]);
  }
  EXPECT_EQ(taskVariableFromName("omega_norm"), TaskVariable::omega_norm);
  EXPECT_FALSE(taskVariableFromName("p").has_value());  // a group, not a variable
  EXPECT_FALSE(taskVariableFromName("X_P").has_value());
}

TEST(TaskDef, GroupsAreThePapersVectors) {
  const auto uca = taskVariableGroup("u_ca");
  ASSERT_TRUE(uca.has_value());
  EXPECT_EQ(uca->size, 2);
  EXPECT_EQ(uca->members[0], TaskVariable::u_a);
  EXPECT_EQ(uca->members[1], TaskVariable::v_a);
  const auto omega = taskVariableGroup("omega");
  ASSERT_TRUE(omega.has_value());
  EXPECT_EQ(omega->size, 3);
  EXPECT_EQ(omega->members[2], TaskVariable::w_z);
  for (const char* name : {"p", "p_dot", "u_co"}) EXPECT_EQ(taskVariableGroup(name)->size, 2) << name;
  EXPECT_FALSE(taskVariableGroup("x_p").has_value());
}

TEST(TaskDef, NoTargetsMeansWatchOnly) {
  TaskDef task;
  EXPECT_TRUE(task.watchOnly());
  task.stages.push_back({});
  EXPECT_FALSE(task.watchOnly());
}

}  // namespace
}  // namespace hemiroll::task
