// A fake of the libnifalcon members declared in tools/sdkclients/declared:
// one Falcon, its firmware loaded, homed after 50 I/O loops, the grip 0.03 m
// out from the workspace's centre (0.11 m) towards the user.

#include <falcon/core/FalconDevice.h>

#include "tests/tools/sdkclients/FakeSdk.h"

namespace hemiroll::sdkclients::test {
FakeSdk& fakeFalcon() {
  static FakeSdk sdk;
  return sdk;
}
}  // namespace hemiroll::sdkclients::test

using hemiroll::sdkclients::test::fakeFalcon;

namespace libnifalcon {

class FalconFirmwareNovintSDK {};
class FalconKinematicStamper {};

namespace {
int gLoops = 0;
bool gHoming = false;
}  // namespace

void FalconFirmware::setHomingMode(bool value) {
  gHoming = value;
  fakeFalcon().call("setHomingMode");
}
bool FalconFirmware::isHomed() { return gHoming && gLoops >= 50; }
void FalconFirmware::setLEDStatus(unsigned int) {}

FalconDevice::FalconDevice() { gLoops = 0, gHoming = false; }
FalconDevice::~FalconDevice() = default;
template <> void FalconDevice::setFalconFirmware<FalconFirmwareNovintSDK>() { fakeFalcon().call("setFalconFirmware"); }
template <> void FalconDevice::setFalconKinematic<FalconKinematicStamper>() { fakeFalcon().call("setFalconKinematic"); }
bool FalconDevice::getDeviceCount(unsigned int& count) {
  count = fakeFalcon().failOpen ? 0 : 1;
  return true;
}
bool FalconDevice::open(unsigned int) {
  fakeFalcon().call("open");
  return true;
}
void FalconDevice::close() { fakeFalcon().call("close"); }
bool FalconDevice::isFirmwareLoaded() { return true; }
bool FalconDevice::setFirmwareFile(const std::string&) { return true; }
bool FalconDevice::loadFirmware(unsigned int, bool) { return true; }
bool FalconDevice::runIOLoop(unsigned int) {
  ++gLoops;
  return true;
}
std::array<double, 3> FalconDevice::getPosition() { return {0.0, 0.0, 0.14}; }
void FalconDevice::setForce(const std::array<double, 3>& force) {
  // libnifalcon has no force switch: the driver's "on" is what the fake checks.
  fakeFalcon().force(force.data());
}
std::shared_ptr<FalconFirmware> FalconDevice::getFalconFirmware() {
  static auto firmware = std::make_shared<FalconFirmware>();
  return firmware;
}
unsigned int FalconDevice::getErrorCode() { return 0; }

}  // namespace libnifalcon
