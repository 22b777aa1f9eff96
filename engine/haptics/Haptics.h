#pragma once
// engine/haptics: the haptic side of hemiroll, in the CHAI3D manner.
//
// Owns: the device interface (HapticDevice, DeviceSpec) and the simple
// devices (ScriptedDevice; SimulatedHandDevice, a spring-mass hand that
// closes the loop in tests), the devices that need no outside library
// (UdpBridgeDevice and its wire format UdpProtocol, for real devices driven
// by an external program; MouseDevice with PointerMapping; the pure
// JoystickMapping; VelocityEstimator for position-only inputs), the
// workspace mapping from device to scene,
// safety on every tick (force clamp, force-rate limit, velocity guard,
// engagement with ramp-in/out, watchdogs for device errors, stale data and
// instability), and the 1 kHz servo loop (ServoLoop: pacing on absolute
// deadlines, catch-up policy, timing statistics, the lock-free snapshot
// buffer and command ring, the headless mode), and what the loop hands to
// a recorder (RecordRow.h: rows, per-tick inputs and applied commands into
// caller-owned lock-free rings) and the ReplayDevice that plays inputs back.
//
// Must not know: rendering, windows or SDL (devices that need SDL live in
// engine/haptics/devices, a library of their own, with the factory that
// makes devices by name), Lua, files, levels, recording formats (the rings'
// consumers and every file live in engine/record).
// Depends on engine/physics and the standard library (and the POSIX clock,
// scheduler and, for the UDP bridge, sockets) only.

#include "engine/haptics/DeviceSpec.h"
#include "engine/haptics/EngagementRamp.h"
#include "engine/haptics/ForceClamp.h"
#include "engine/haptics/ForceSafety.h"
#include "engine/haptics/HapticDevice.h"
#include "engine/haptics/JoystickMapping.h"
#include "engine/haptics/MonotonicClock.h"
#include "engine/haptics/MouseDevice.h"
#include "engine/haptics/PointerMapping.h"
#include "engine/haptics/RealtimeThread.h"
#include "engine/haptics/RecordRow.h"
#include "engine/haptics/ReplayDevice.h"
#include "engine/haptics/ScriptedDevice.h"
#include "engine/haptics/ServoClock.h"
#include "engine/haptics/ServoCommand.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/haptics/ServoSnapshot.h"
#include "engine/haptics/SimulatedHandDevice.h"
#include "engine/haptics/SpscRing.h"
#include "engine/haptics/TimingHistogram.h"
#include "engine/haptics/TripleBuffer.h"
#include "engine/haptics/UdpBridgeDevice.h"
#include "engine/haptics/UdpProtocol.h"
#include "engine/haptics/UdpSocket.h"
#include "engine/haptics/VelocityEstimator.h"
#include "engine/haptics/WorkspaceMapping.h"
