#version 330 core
// hemiroll scene shader (engine/render/Renderer): one vertex layout for
// everything; lit solids and unlit lines/decals share it.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aColor;

uniform mat4 uModel;
uniform mat4 uViewProjection;
uniform mat3 uNormalMatrix;

out vec3 vWorld;
out vec3 vNormal;
out vec4 vColor;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorld = world.xyz;
  vNormal = uNormalMatrix * aNormal;
  vColor = aColor;
  gl_Position = uViewProjection * world;
}
