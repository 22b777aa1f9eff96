// The Force Dimension DHD API as far as hemiroll-omega-client calls it: the
// names and signatures of the Force Dimension SDK's reference (dhdc.h,
// "DHD-API"), declared here so that the client is compiled in `make test`
// on a machine without the SDK. It is NOT the SDK's header and holds none of
// its code: the values of the constants are this file's own (the client uses
// only their names), and a build that finds the SDK uses its header
// (tools/sdkclients/CMakeLists.txt). The tests link a fake implementation
// (tests/tools/sdkclients/FakeDhd.cpp).
#ifndef HEMIROLL_DECLARED_DHDC_H
#define HEMIROLL_DECLARED_DHDC_H

#define DHD_ON 1
#define DHD_OFF 0
#define DHD_MOTOR_SATURATED 2

int dhdOpen();
int dhdClose(char ID = -1);
int dhdEnableForce(unsigned char val, char ID = -1);
int dhdGetPosition(double* px, double* py, double* pz, char ID = -1);
int dhdGetLinearVelocity(double* pvx, double* pvy, double* pvz, char ID = -1);
int dhdSetForce(double fx, double fy, double fz, char ID = -1);
int dhdGetButtonMask(char ID = -1);
const char* dhdGetSystemName(char ID = -1);
const char* dhdErrorGetLastStr();

#endif
