#include "tools/sdkclients/ClientRun.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include "engine/haptics/ServoClock.h"

namespace hemiroll::sdkclients {

namespace {

// The servo side: the link's exchange, with forces held at zero until the
// supervisor has turned them on (and after it starts turning them off).
class LinkTick final : public ServoTick {
 public:
  explicit LinkTick(BridgeLink& link) : link_(link) {}

  Vec3 tick(const DeviceSample& sample, std::int64_t nowNs) override {
    const Vec3 f = link_.exchange(sample, nowNs);
    const LinkCounters& c = link_.counters();
    anyOk_.store(c.anyOkForce, std::memory_order_relaxed);
    closing_.store(c.bridgeClosing, std::memory_order_relaxed);
    deviceFault_.store(sample.deviceFault, std::memory_order_relaxed);
    return pushing_.load(std::memory_order_acquire) ? f : Vec3{};
  }

  std::atomic<bool> pushing_{false}, anyOk_{false}, closing_{false}, deviceFault_{false};

 private:
  BridgeLink& link_;
};

}  // namespace

ClientRunResult runDeviceClient(DeviceDriver& driver, ClientRunDef def, const std::atomic<bool>& stop) {
  ClientRunResult result;
  def.link.axes = driver.axes();  // the SDK's frame is the driver's to know
  if (std::string why = driver.open(); !why.empty()) {
    result.error = std::string(driver.name()) + ": " + why;
    return result;
  }
  // The SDK's own figure (known once the device is open) wins when it is
  // lower: a profile may be optimistic.
  if (const double sdk = driver.continuousForce(); sdk > 0.0) def.link.maxForce = std::min(def.link.maxForce, sdk);
  result.forceLimit = def.link.maxForce;
  BridgeLink link(def.link);
  if (std::string why = link.open(); !why.empty()) {
    driver.close();
    result.error = why;
    return result;
  }
  LinkTick tick(link);
  if (std::string why = driver.startServo(tick); !why.empty()) {
    driver.close();
    result.error = std::string(driver.name()) + ": " + why;
    return result;
  }

  haptics::SteadyServoClock clock;
  const std::int64_t start = clock.now();
  while (!stop.load(std::memory_order_relaxed)) {
    if (def.duration > 0.0 && static_cast<double>(clock.now() - start) * 1e-9 >= def.duration) break;
    if (tick.closing_.load(std::memory_order_relaxed)) break;
    if (tick.deviceFault_.load(std::memory_order_relaxed)) {
      result.error = std::string(driver.name()) + ": the device reported a fault; stopped";
      break;
    }
    if (!result.forcesWereEnabled && tick.anyOk_.load(std::memory_order_relaxed)) {
      if (std::string why = driver.setForcesEnabled(true); !why.empty()) {
        result.error = std::string(driver.name()) + ": " + why;
        break;
      }
      result.forcesWereEnabled = true;
      tick.pushing_.store(true, std::memory_order_release);
    }
    std::this_thread::sleep_for(std::chrono::nanoseconds(def.pollNs));
  }
  // Zero first (the next tick writes it), then forces off, then the loop.
  tick.pushing_.store(false, std::memory_order_release);
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (result.forcesWereEnabled) driver.setForcesEnabled(false);
  driver.stopServo();
  driver.close();
  result.counters = link.counters();
  return result;
}

}  // namespace hemiroll::sdkclients
