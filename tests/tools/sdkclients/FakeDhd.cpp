// A fake of the Force Dimension DHD calls declared in
// tools/sdkclients/declared: a device at 0.01, 0.02, 0.03 m, still.

#include <dhdc.h>

#include "tests/tools/sdkclients/FakeSdk.h"

namespace hemiroll::sdkclients::test {
FakeSdk& fakeDhd() {
  static FakeSdk sdk;
  return sdk;
}
}  // namespace hemiroll::sdkclients::test

using hemiroll::sdkclients::test::fakeDhd;

int dhdOpen() {
  fakeDhd().call("dhdOpen");
  return fakeDhd().failOpen ? -1 : 0;
}
int dhdClose(char) {
  fakeDhd().call("dhdClose");
  return 0;
}
int dhdEnableForce(unsigned char on, char) {
  fakeDhd().forcesOn = on == DHD_ON;
  fakeDhd().call(on == DHD_ON ? "dhdEnableForce(DHD_ON)" : "dhdEnableForce(DHD_OFF)");
  return 0;
}
int dhdGetPosition(double* x, double* y, double* z, char) {
  *x = 0.01, *y = 0.02, *z = 0.03;
  return 0;
}
int dhdGetLinearVelocity(double* x, double* y, double* z, char) {
  *x = *y = *z = 0.0;
  return 0;
}
int dhdSetForce(double fx, double fy, double fz, char) {
  const double f[3] = {fx, fy, fz};
  fakeDhd().force(f);
  return 0;
}
int dhdGetButtonMask(char) { return 0; }
const char* dhdGetSystemName(char) { return "fake omega.3"; }
const char* dhdErrorGetLastStr() { return "no device found (fake)"; }
