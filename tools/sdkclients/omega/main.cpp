// hemiroll-omega-client: a Force Dimension omega.3/omega.6 (DHD API) on
// hemiroll's UDP bridge. Built only where the Force Dimension SDK is installed.
#include "tools/sdkclients/ClientMain.h"
#include "tools/sdkclients/omega/OmegaDriver.h"

int main(int argc, char** argv) {
  using namespace hemiroll::sdkclients;
  // 12 N: the omega.3's continuous force (Force Dimension's specification).
  const ClientCommand command{"hemiroll-omega-client", "a Force Dimension omega.3 or omega.6 (DHD)", 12.0, {}};
  return clientMain(command, argc, argv, [] { return std::make_unique<OmegaDriver>(); });
}
