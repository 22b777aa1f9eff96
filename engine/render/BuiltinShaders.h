#pragma once
// Copies of assets/shaders/scene.{vert,frag}, used when the files are
// missing or do not compile, so a broken install still draws. Keep them in
// step with the files (ShaderProgramTest compiles both).

namespace hemiroll::render {

extern const char* const kBuiltinSceneVertex;
extern const char* const kBuiltinSceneFragment;

}  // namespace hemiroll::render
