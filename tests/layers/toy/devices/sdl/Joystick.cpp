// The toy's SDL device library, in a subfolder of the headless devices' folder.
#include "tests/layers/toy/devices/sdl/Joystick.h"
