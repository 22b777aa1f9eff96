// libnifalcon's FalconDevice as far as hemiroll-falcon-client calls it: the
// member names and signatures of libnifalcon's public headers
// (include/falcon/core/FalconDevice.h, FalconFirmware.h), declared here so
// that the client is compiled in `make test` where libnifalcon is not
// installed. It is NOT libnifalcon's header and holds none of its code; a
// build that finds libnifalcon uses its headers (tools/sdkclients/
// CMakeLists.txt). libnifalcon's releases differ in the array type of
// getPosition/setForce (double*, boost::array, std::array) and the count's
// type; the client is written for all three (FalconDriver.cpp). The tests
// link a fake implementation (tests/tools/sdkclients/FakeFalcon.cpp).
#ifndef HEMIROLL_DECLARED_FALCON_DEVICE_H
#define HEMIROLL_DECLARED_FALCON_DEVICE_H

#include <array>
#include <cstdint>
#include <memory>
#include <string>

namespace libnifalcon {

class FalconFirmware {
 public:
  virtual ~FalconFirmware() = default;
  void setHomingMode(bool value);
  bool isHomed();
  void setLEDStatus(unsigned int leds);
  enum { GREEN_LED = 0x2, BLUE_LED = 0x4, RED_LED = 0x8 };
};

class FalconDevice {
 public:
  FalconDevice();
  ~FalconDevice();
  template <class T> void setFalconFirmware();
  template <class T> void setFalconKinematic();
  bool getDeviceCount(unsigned int& count);
  bool open(unsigned int index);
  void close();
  bool isFirmwareLoaded();
  bool setFirmwareFile(const std::string& filename);
  bool loadFirmware(unsigned int retries, bool skip_checksum = false);
  bool runIOLoop(unsigned int exe_flags = 0x7);
  std::array<double, 3> getPosition();
  void setForce(const std::array<double, 3>& force);
  std::shared_ptr<FalconFirmware> getFalconFirmware();
  unsigned int getErrorCode();
};

}  // namespace libnifalcon

#endif
