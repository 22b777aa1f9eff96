// The toy's headless devices, beside the SDL ones' folder (sdl/).
#include "tests/layers/toy/devices/Mouse.h"
