// hemiroll-touch-client: a 3D Systems Touch or Touch X (OpenHaptics HD API)
// on hemiroll's UDP bridge. Built only where OpenHaptics is installed.
#include "tools/sdkclients/ClientMain.h"
#include "tools/sdkclients/touch/TouchDriver.h"

int main(int argc, char** argv) {
  using namespace hemiroll::sdkclients;
  // 0.88 N: the Touch's continuous force (3D Systems' specification); the SDK's own figure wins when lower.
  const ClientCommand command{"hemiroll-touch-client", "a 3D Systems Touch or Touch X (OpenHaptics)", 0.88, {}};
  return clientMain(command, argc, argv, [] { return std::make_unique<TouchDriver>(); });
}
