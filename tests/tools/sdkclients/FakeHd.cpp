// A fake of the OpenHaptics HD calls declared in tools/sdkclients/declared:
// a device at 10, 20, 30 mm moving at 1, 2, 3 mm/s, with a scheduler thread
// that calls the scheduled callback every millisecond.

#include <HD/hd.h>

#include <chrono>
#include <thread>

#include "tests/tools/sdkclients/FakeSdk.h"

namespace hemiroll::sdkclients::test {
FakeSdk& fakeHd() {
  static FakeSdk sdk;
  return sdk;
}
}  // namespace hemiroll::sdkclients::test

namespace {
using hemiroll::sdkclients::test::fakeHd;
HDErrorInfo gError{HD_SUCCESS, 0, 0};
HDSchedulerCallback gCallback = nullptr;
void* gUserData = nullptr;
std::atomic<bool> gRunning{false};
std::thread gScheduler;
}  // namespace

extern "C" {
HHD hdInitDevice(HDstring) {
  fakeHd().call("hdInitDevice");
  if (fakeHd().failOpen) gError = HDErrorInfo{0x0101, 7, 0};
  return 1;
}
void hdDisableDevice(HHD) { fakeHd().call("hdDisableDevice"); }
HHD hdGetCurrentDevice(void) { return 1; }
void hdBeginFrame(HHD) {}
void hdEndFrame(HHD) {}
void hdEnable(HDenum cap) {
  if (cap == HD_FORCE_OUTPUT) fakeHd().forcesOn = true;
  fakeHd().call(cap == HD_FORCE_OUTPUT ? "hdEnable(HD_FORCE_OUTPUT)" : "hdEnable");
}
void hdDisable(HDenum cap) {
  if (cap == HD_FORCE_OUTPUT) fakeHd().forcesOn = false;
  fakeHd().call(cap == HD_FORCE_OUTPUT ? "hdDisable(HD_FORCE_OUTPUT)" : "hdDisable");
}
void hdGetDoublev(HDenum pname, HDdouble* p) {
  if (pname == HD_CURRENT_POSITION) p[0] = 10.0, p[1] = 20.0, p[2] = 30.0;
  if (pname == HD_CURRENT_VELOCITY) p[0] = 1.0, p[1] = 2.0, p[2] = 3.0;
  if (pname == HD_NOMINAL_MAX_CONTINUOUS_FORCE) p[0] = 0.88;
}
void hdGetIntegerv(HDenum, HDint* p) { p[0] = 0; }
void hdSetDoublev(HDenum pname, const HDdouble* p) {
  if (pname == HD_CURRENT_FORCE) fakeHd().force(p);
}
HDErrorInfo hdGetError(void) {
  const HDErrorInfo e = gError;
  gError = HDErrorInfo{HD_SUCCESS, 0, 0};
  return e;
}
void hdStartScheduler(void) {
  fakeHd().call("hdStartScheduler");
  gRunning = true;
  gScheduler = std::thread([] {
    while (gRunning) {
      if (gCallback) gCallback(gUserData);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
}
void hdStopScheduler(void) {
  fakeHd().call("hdStopScheduler");
  gRunning = false;
  if (gScheduler.joinable()) gScheduler.join();
}
HDSchedulerHandle hdScheduleAsynchronous(HDSchedulerCallback callback, void* data, HDushort) {
  fakeHd().call("hdScheduleAsynchronous");
  gCallback = callback;
  gUserData = data;
  return 42;
}
void hdUnschedule(HDSchedulerHandle) {
  fakeHd().call("hdUnschedule");
  gCallback = nullptr;
}
}
