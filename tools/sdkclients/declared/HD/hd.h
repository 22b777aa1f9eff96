/* The OpenHaptics HD API as far as hemiroll-touch-client calls it: the
 * names, types and signatures of the OpenHaptics Toolkit's API reference
 * (3D Systems, "OpenHaptics Toolkit API Reference", HDAPI), declared here so
 * that the client is compiled in `make test` on a machine without the
 * toolkit. It is NOT the toolkit's header and holds none of its code: the
 * numeric values of the constants below are this file's own (the client uses
 * only their names), and a build that finds the real toolkit uses the real
 * header instead (tools/sdkclients/CMakeLists.txt). The tests link a fake
 * implementation (tests/tools/sdkclients/FakeHd.cpp). */
#ifndef HEMIROLL_DECLARED_HD_H
#define HEMIROLL_DECLARED_HD_H

#ifdef __cplusplus
extern "C" {
#endif

#define HDCALLBACK
#define HDAPI

typedef double HDdouble;
typedef int HDint;
typedef unsigned int HDenum;
typedef unsigned int HHD;
typedef unsigned int HDerror;
typedef unsigned short HDushort;
typedef unsigned long HDSchedulerHandle;
typedef const char* HDstring;
typedef unsigned int HDCallbackCode;
typedef HDCallbackCode(HDCALLBACK* HDSchedulerCallback)(void* pUserData);

typedef struct {
  HDerror errorCode;
  int internalErrorCode;
  HHD hHD;
} HDErrorInfo;

#define HD_DEFAULT_DEVICE 0
#define HD_INVALID_HANDLE 0xFFFFFFFFu
#define HD_SUCCESS 0x0000
#define HD_DEVICE_ERROR(X) (((X).errorCode) != HD_SUCCESS)
#define HD_CALLBACK_DONE 0
#define HD_CALLBACK_CONTINUE 1
#define HD_MAX_SCHEDULER_PRIORITY 0xFFFF
/* Parameters (hdGet*v / hdSet*v) and capabilities (hdEnable). */
#define HD_CURRENT_BUTTONS 0x2000
#define HD_CURRENT_POSITION 0x2050
#define HD_CURRENT_VELOCITY 0x2051
#define HD_CURRENT_FORCE 0x2700
#define HD_NOMINAL_MAX_CONTINUOUS_FORCE 0x2603
#define HD_FORCE_OUTPUT 0x4000

HHD HDAPI hdInitDevice(HDstring pConfigName);
void HDAPI hdDisableDevice(HHD hHD);
HHD HDAPI hdGetCurrentDevice(void);
void HDAPI hdBeginFrame(HHD hHD);
void HDAPI hdEndFrame(HHD hHD);
void HDAPI hdEnable(HDenum cap);
void HDAPI hdDisable(HDenum cap);
void HDAPI hdGetDoublev(HDenum pname, HDdouble* params);
void HDAPI hdGetIntegerv(HDenum pname, HDint* params);
void HDAPI hdSetDoublev(HDenum pname, const HDdouble* params);
HDErrorInfo HDAPI hdGetError(void);
void HDAPI hdStartScheduler(void);
void HDAPI hdStopScheduler(void);
HDSchedulerHandle HDAPI hdScheduleAsynchronous(HDSchedulerCallback pCallback, void* pUserData, HDushort nPriority);
void HDAPI hdUnschedule(HDSchedulerHandle hHandle);

#ifdef __cplusplus
}
#endif

#endif
