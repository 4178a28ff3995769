#version 330 core
// A filled disc with a dark rim.
in vec4 vColour;
out vec4 fragColour;
void main() {
  float r = length(gl_PointCoord - vec2(0.5)) * 2.0;
  if (r > 1.0) discard;
  vec3 c = r > 0.72 ? vec3(0.1) : vColour.rgb;
  fragColour = vec4(c, vColour.a);
}
