#pragma once
// The devices' names, as the command line, levels, settings and recordings
// write them: the one list. DeviceFactory (sdl/) makes a device by these
// names; code that only names a device (a headless trial at the bridge, the
// settings file) takes the name from here without linking SDL.

#include <string>

namespace hemiroll::haptics {

inline constexpr const char* kMouseDevice = "mouse";
inline constexpr const char* kJoystickDevice = "joystick";
inline constexpr const char* kUdpDevice = "udp";
inline constexpr const char* kScriptedDevice = "scripted";
inline constexpr const char* kSimulatedHandDevice = "simulated-hand";

// The devices a person plays with, in the order the settings offer them: the
// one list the settings, the screens and the play session use (a level's
// per_device mappings also take "bot": task::kMappedDevices).
inline constexpr const char* kPlayerDevices[] = {kMouseDevice, kJoystickDevice, kUdpDevice};
// The mouse with the "hand" feel (Settings::mouseFeel): the settings offer
// it as a way of playing the mouse, not as a device of its own.
inline constexpr const char* kMouseHandDevice = "mouse-hand";
// Either of the two: the UI feeds the pointer.
inline bool isMouseDevice(const std::string& name) { return name == kMouseDevice || name == kMouseHandDevice; }

}  // namespace hemiroll::haptics
