#pragma once
// engine/haptics/devices: every device, in one place, and their names.
//
// Owns: the devices that need only the standard library and POSIX
// (hemiroll_devices: ScriptedDevice, a pose function of time;
// SimulatedHandDevice, a spring-mass hand that closes the loop in tests;
// MouseDevice, fed by the UI through PointerMapping; ReplayDevice, a
// recording's inputs played back; UdpBridgeDevice, a real device driven by
// an external program over the bridge, UDP_BRIDGE.md), the devices' names
// (DeviceNames.h: the one list), and in sdl/ (hemiroll_haptics_devices, which
// links SDL2) the force-feedback joystick and the factory that makes any
// device by name. Headless layers may link hemiroll_devices, never sdl/.
// A new device: its class here (sdl/ if it needs SDL), its name in
// DeviceNames.h, its maker in DeviceFactory's constructor.
// Must not know: windows and rendering (the mouse's pixels are the UI's
// business, via PointerMapping), levels, Lua, files, recordings.
// The interface, safety, the servo loop and the wire format the bridge
// shares with its clients (UdpProtocol, UdpSocket) are engine/haptics'.

#include "engine/haptics/devices/DeviceNames.h"
#include "engine/haptics/devices/MouseDevice.h"
#include "engine/haptics/devices/ReplayDevice.h"
#include "engine/haptics/devices/ScriptedDevice.h"
#include "engine/haptics/devices/SimulatedHandDevice.h"
#include "engine/haptics/devices/UdpBridgeDevice.h"
// Not included here, so that a headless layer may include this header:
// sdl/DeviceFactory.h and sdl/SdlJoystickDevice.h (they bring SDL).
