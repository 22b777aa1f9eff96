#pragma once
// engine/haptics/devices: the devices that need a library beyond the
// standard one and POSIX (SDL2 for the force-feedback joystick), and the
// factory that makes any device by name. A separate library
// (hemiroll_haptics_devices), so that engine/haptics itself stays free of
// SDL and its tests need no SDL.
//
// Owns: SdlJoystickDevice, DeviceFactory.
// Must not know: windows and rendering (the mouse's pixels are the UI's
// business, via PointerMapping), levels, Lua, files, recordings.

#include "engine/haptics/devices/DeviceFactory.h"
#include "engine/haptics/devices/SdlJoystickDevice.h"
