#version 330 core
// Lambert + a little Blinn-Phong from one directional light, plus ambient;
// uLit = 0 passes the colour through (lines, floor decals).
in vec3 vWorld;
in vec3 vNormal;
in vec4 vColor;

uniform int uLit;
uniform vec4 uTint;
uniform vec3 uLightDirection;  // towards the light, unit
uniform vec3 uEye;

out vec4 fragColor;

void main() {
  vec4 base = vColor * uTint;
  if (uLit == 0) {
    fragColor = base;
    return;
  }
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;
  vec3 v = normalize(uEye - vWorld);
  vec3 h = normalize(uLightDirection + v);
  float diffuse = max(dot(n, uLightDirection), 0.0);
  float specular = pow(max(dot(n, h), 0.0), 32.0) * 0.25;
  fragColor = vec4(base.rgb * (0.35 + 0.65 * diffuse) + vec3(specular), base.a);
}
