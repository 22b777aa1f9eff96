#pragma once
// engine/physics: the exact model of a homogeneous hemisphere rolling without
// slipping on a plane, driven by a mass point on its flat face (Svinin et al.,
// "Dynamic Model, Haptic Solution, and Human-Inspired Motion Planning for
// Rolling-Based Manipulation", Sec. 2, 3.1, 3.2, 5).
//
// Owns: parameters, state layouts, the orientation and contact kinematics,
// the dynamics of the 12-state force-driven model and the 8-state prescribed
// drive, the force couplings M1/M2/M3 to a haptic proxy, energy, domain events
// (tip-over, off-face), integrators and the event-aware stepper, and the
// lockstep RK4 of many trajectories in SIMD lanes (BatchedRk4.h).
//
// Must not know: Lua, devices, threads, clocks, files, rendering, levels.
// Depends on Eigen and the standard library only.

#include "engine/physics/AdaptiveIntegrator.h"
#include "engine/physics/BatchedRk4.h"
#include "engine/physics/BodyRotation.h"
#include "engine/physics/CouplingStability.h"
#include "engine/physics/DomainEvents.h"
#include "engine/physics/DormandPrince54.h"
#include "engine/physics/DormandPrince853.h"
#include "engine/physics/Energy.h"
#include "engine/physics/ForceCoupling.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/ForceInput.h"
#include "engine/physics/GaussLegendre.h"
#include "engine/physics/HemisphereParams.h"
#include "engine/physics/Integrator.h"
#include "engine/physics/NormalDraws.h"
#include "engine/physics/Orientation.h"
#include "engine/physics/PrescribedDriveSystem.h"
#include "engine/physics/RollingDynamics.h"
#include "engine/physics/RotationDrivenSystem.h"
#include "engine/physics/RoseDrive.h"
#include "engine/physics/StateLayout.h"
#include "engine/physics/Stepper.h"
#include "engine/physics/SubsteppingIntegrator.h"
#include "engine/physics/Tsitouras54.h"
#include "engine/physics/Verner76.h"
#include "engine/physics/Verner98.h"
