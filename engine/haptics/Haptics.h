#pragma once
// engine/haptics: the haptic side of hemiroll, in the CHAI3D manner.
//
// Owns: the device interface (HapticDevice, DeviceSpec; the devices
// themselves live in engine/haptics/devices, Devices.h), the UDP bridge's
// wire format and socket (UdpProtocol, UdpSocket: the bridge device's and
// its clients'), the input mappings (PointerMapping for the mouse, the pure
// JoystickMapping; VelocityEstimator for position-only inputs), the
// workspace mapping from device to scene,
// safety on every tick (force clamp, force-rate limit, velocity guard,
// engagement with ramp-in/out, watchdogs for device errors, stale data and
// instability), and the 1 kHz servo loop (ServoLoop: pacing on absolute
// deadlines, catch-up policy, timing statistics, the lock-free snapshot
// buffer and command ring, the headless mode), and what the loop hands to
// a recorder (RecordRow.h: rows, per-tick inputs and applied commands into
// caller-owned lock-free rings).
//
// Must not know: rendering, windows or SDL, any particular device (they
// live in engine/haptics/devices, libraries of their own, with the factory
// that makes devices by name), Lua, files, levels, recording formats (the rings'
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
#include "engine/haptics/PointerMapping.h"
#include "engine/haptics/RealtimeThread.h"
#include "engine/haptics/RecordRow.h"
#include "engine/haptics/ServoClock.h"
#include "engine/haptics/ServoCommand.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/haptics/ServoSnapshot.h"
#include "engine/haptics/SpscRing.h"
#include "engine/haptics/TimingHistogram.h"
#include "engine/haptics/TripleBuffer.h"
#include "engine/haptics/UdpProtocol.h"
#include "engine/haptics/UdpSocket.h"
#include "engine/haptics/VelocityEstimator.h"
#include "engine/haptics/WorkspaceMapping.h"
