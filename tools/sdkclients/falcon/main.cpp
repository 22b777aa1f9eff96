// hemiroll-falcon-client: a Novint Falcon (libnifalcon) on hemiroll's UDP
// bridge. Built only where libnifalcon is installed.
#include "tools/sdkclients/ClientMain.h"
#include "tools/sdkclients/falcon/FalconDriver.h"

int main(int argc, char** argv) {
  using namespace hemiroll::sdkclients;
  FalconDriverDef def;
  ClientCommand command{"hemiroll-falcon-client", "a Novint Falcon (libnifalcon)", def.continuousForce,
                        {{"--falcon-firmware", "FILE",
                          "firmware to load when the Falcon has none (libnifalcon's firmware folder)",
                          &def.firmwareFile}}};
  return clientMain(command, argc, argv, [&def] { return std::make_unique<FalconDriver>(def); });
}
