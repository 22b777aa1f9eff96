#pragma once
// What the fake SDKs (FakeHd.cpp, FakeDhd.cpp, FakeFalcon.cpp) record of the
// calls a driver makes: the order of the calls that set a device up and take
// it down, the last force written and any force written while the device's
// forces were off. A device reads a fixed pose (each fake's own units).

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

namespace hemiroll::sdkclients::test {

struct FakeSdk {
  std::mutex mutex;
  std::vector<std::string> calls;     // set-up and take-down calls, in order
  std::array<double, 3> lastForce{};  // device frame [N]
  double largestForce = 0.0;          // the largest |F| written [N]
  std::atomic<int> forcesWritten{0};
  std::atomic<int> pushedWhileOff{0};  // nonzero forces written with forces off
  std::atomic<bool> forcesOn{false};
  bool failOpen = false;

  void call(const std::string& name) {
    std::lock_guard lock(mutex);
    calls.push_back(name);
  }
  void force(const double* f) {
    std::lock_guard lock(mutex);
    lastForce = {f[0], f[1], f[2]};
    largestForce = std::max(largestForce, std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
    ++forcesWritten;
    if (!forcesOn && (f[0] != 0.0 || f[1] != 0.0 || f[2] != 0.0)) ++pushedWhileOff;
  }
  // Position of `name` in the call log; calls.size() when absent.
  std::size_t at(const std::string& name) {
    std::lock_guard lock(mutex);
    return static_cast<std::size_t>(std::find(calls.begin(), calls.end(), name) - calls.begin());
  }
  void reset() {
    std::lock_guard lock(mutex);
    calls.clear();
    lastForce = {};
    largestForce = 0.0;
    forcesWritten = 0;
    pushedWhileOff = 0;
    forcesOn = false;
    failOpen = false;
  }
};

FakeSdk& fakeHd();
FakeSdk& fakeDhd();
FakeSdk& fakeFalcon();

}  // namespace hemiroll::sdkclients::test
