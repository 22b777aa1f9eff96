// A research source that includes a header of the SDL devices' subfolder:
// its parent folder (the headless devices) is allowed, the subfolder is not.
#include "tests/layers/toy/devices/sdl/Joystick.h"
