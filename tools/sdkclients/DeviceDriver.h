#pragma once
// One device SDK behind the few calls every client needs (the CHAI3D shape:
// a small class per device, one interface). A driver knows its SDK and
// nothing of the bridge; ClientRun puts the calls in their order.

#include <cstdint>
#include <string>

#include "tools/sdkclients/BridgeLink.h"

namespace hemiroll::sdkclients {

// What the driver's servo loop calls once per device period, on the SDK's
// thread or the driver's own: the sample it read, the force to write back
// [N, device frame]. Implemented by ClientRun; allocates nothing.
class ServoTick {
 public:
  virtual ~ServoTick() = default;
  virtual Vec3 tick(const DeviceSample& sample, std::int64_t nowNs) = 0;
};

class DeviceDriver {
 public:
  virtual ~DeviceDriver() = default;
  virtual const char* name() const = 0;
  // The device's continuous force [N] as its SDK reports it; 0 when it cannot say.
  virtual double continuousForce() const = 0;
  virtual AxisMap axes() const = 0;
  // Each returns "" or the reason in the SDK's words, naming the call.
  virtual std::string open() = 0;
  virtual std::string startServo(ServoTick& tick) = 0;  // forces still off
  virtual std::string setForcesEnabled(bool on) = 0;
  virtual void stopServo() = 0;
  virtual void close() = 0;
};

}  // namespace hemiroll::sdkclients
