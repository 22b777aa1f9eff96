#pragma once
// engine/render: draws the game's 3-D scene with OpenGL 3.3 core.
//
// Owns: the RenderScene contract (plain data the game fills every frame from
// a ServoSnapshot and the level), its sanitising (never NaN on screen), the
// camera (follow, orbit, top; zoom), shader programs (assets/shaders with
// built-in fallbacks), GPU meshes, the procedural hemisphere with markings,
// marker meshes from files through assimp (built-in fallbacks), the contact
// trace ring, the per-frame floor geometry (grid, targets, zones, trace,
// spring), the offscreen Framebuffer and PNG images.
//
// Must not know: levels, the judge, Lua, haptics, the servo loop, SDL or
// windows (engine/platform gives it a current GL context), game rules.
// Depends on engine/physics's Eigen, libepoxy, assimp and stb (Debian).
// Usage: docs/RENDERING.md.

#include "engine/render/Camera.h"
#include "engine/render/ContactTrace.h"
#include "engine/render/Framebuffer.h"
#include "engine/render/Image.h"
#include "engine/render/RenderError.h"
#include "engine/render/RenderScene.h"
#include "engine/render/Renderer.h"
