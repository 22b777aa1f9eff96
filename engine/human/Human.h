#pragma once
// engine/human: a simulated person at a device, the project's measuring stick
// for what a player can learn (docs/HUMAN_MODEL.md).
//
// Owns: what a person sees and when (ScreenView, ViewDelay: the screen a
// visual delay late), how often they correct and by how much (HumanModel:
// event-triggered corrections at most every `interval`, signal-dependent
// motor noise), how a correction becomes a hand movement (MotorPlan:
// minimum-jerk submovements and a stir that goes round by itself, under a
// wrist's speed limit), the hand itself (Limb: mass, stiffness, damping,
// pushed at once by the force a haptic device renders), and the technique a
// person who has learned it in words applies (Technique). Every default
// comes from the motor-control literature (HumanDef.h).
// Must not know: Lua, levels, devices, the game, the autopilot. What the
// screen shows, the hint included, is handed to it as plain numbers
// (game/trial/HumanBot builds the view; game/trial/HintCoach the hint).

#include "engine/human/HumanDef.h"
#include "engine/human/HumanModel.h"
#include "engine/human/Limb.h"
#include "engine/human/MotorPlan.h"
#include "engine/human/ScreenView.h"
#include "engine/human/Technique.h"
#include "engine/human/ViewDelay.h"
