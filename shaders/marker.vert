#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColour;
layout(location = 2) in float aSize;
uniform mat4 uViewProjection;
uniform float uScale;
out vec4 vColour;
void main() {
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
  gl_Position.z = -gl_Position.w;  // always in front
  gl_PointSize = aSize * uScale;
  vColour = aColour;
}
