#pragma once
// engine/platform: the operating-system side of the game's main thread.
//
// Owns: the SDL2 window with its OpenGL 3.3 core context (Window: resizable,
// vsync on by default, high-DPI aware, or hidden for offscreen rendering),
// the translation of SDL input events into the engine's own InputEvent (so
// that screens and the HUD never see an SDL type), the frame clock, and the
// frame pacer (the main thread sleeps out what a frame does not need).
//
// Must not know: what is drawn (engine/render), physics, haptics, Lua,
// levels, files. It gives the caller a current GL context and events; what
// the game does with them is the game's business.
// Depends on SDL2 (Debian's libsdl2-dev) and libepoxy (the GL loader).

#include "engine/platform/FrameClock.h"
#include "engine/platform/FramePacer.h"
#include "engine/platform/InputEvent.h"
#include "engine/platform/InputTranslator.h"
#include "engine/platform/KeyNames.h"
#include "engine/platform/PlatformError.h"
#include "engine/platform/Window.h"
