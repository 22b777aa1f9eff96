#pragma once
// engine/haptics: the haptic side of hemiroll, in the CHAI3D manner.
//
// Owns: the device interface (HapticDevice, DeviceSpec) and the simple
// devices (ScriptedDevice; SimulatedHandDevice, a spring-mass hand that
// closes the loop in tests), the workspace mapping from device to scene,
// safety on every tick (force clamp, force-rate limit, velocity guard,
// engagement with ramp-in/out, watchdogs for device errors, stale data and
// instability), and the 1 kHz servo loop (ServoLoop: pacing on absolute
// deadlines, catch-up policy, timing statistics, the lock-free snapshot
// buffer and command ring, the headless mode).
//
// Must not know: rendering, windows or SDL (devices that need SDL live
// elsewhere and implement HapticDevice), Lua, files, levels, recordings.
// Depends on engine/physics and the standard library (and the POSIX clock
// and scheduler) only.

#include "engine/haptics/DeviceSpec.h"
#include "engine/haptics/EngagementRamp.h"
#include "engine/haptics/ForceClamp.h"
#include "engine/haptics/ForceSafety.h"
#include "engine/haptics/HapticDevice.h"
#include "engine/haptics/RealtimeThread.h"
#include "engine/haptics/ScriptedDevice.h"
#include "engine/haptics/ServoClock.h"
#include "engine/haptics/ServoCommand.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/haptics/ServoSnapshot.h"
#include "engine/haptics/SimulatedHandDevice.h"
#include "engine/haptics/SpscRing.h"
#include "engine/haptics/TimingHistogram.h"
#include "engine/haptics/TripleBuffer.h"
#include "engine/haptics/WorkspaceMapping.h"
