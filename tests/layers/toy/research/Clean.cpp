// A research source that keeps to its layer.
#include <vector>
#include "tests/layers/toy/research/Reaching.h"
// The headless devices: allowed, though the forbidden joystick lies below their folder.
#include "tests/layers/toy/devices/Mouse.h"
