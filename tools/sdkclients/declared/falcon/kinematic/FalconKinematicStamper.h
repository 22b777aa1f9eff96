// libnifalcon's kinematics policy class, declared only (see ../core/FalconDevice.h).
#ifndef HEMIROLL_DECLARED_FALCON_KINEMATIC_STAMPER_H
#define HEMIROLL_DECLARED_FALCON_KINEMATIC_STAMPER_H
namespace libnifalcon {
class FalconKinematicStamper;
}
#endif
