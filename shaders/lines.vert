#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColour;
uniform mat4 uViewProjection;
uniform vec4 uColourOverride;  // used when alpha > 0
out vec4 vColour;
void main() {
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
  vColour = uColourOverride.a > 0.0 ? uColourOverride : aColour;
}
