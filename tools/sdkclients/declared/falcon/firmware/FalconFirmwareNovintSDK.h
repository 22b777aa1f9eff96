// libnifalcon's firmware policy class, declared only (see ../core/FalconDevice.h).
#ifndef HEMIROLL_DECLARED_FALCON_FIRMWARE_NOVINT_SDK_H
#define HEMIROLL_DECLARED_FALCON_FIRMWARE_NOVINT_SDK_H
namespace libnifalcon {
class FalconFirmwareNovintSDK;
}
#endif
