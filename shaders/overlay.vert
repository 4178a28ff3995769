#version 330 core
// 2D overlay (text, legend, scale bar) in pixels, origin top left.
layout(location = 0) in vec2 aPosition;
layout(location = 1) in vec2 aUv;
layout(location = 2) in vec4 aColour;
uniform vec2 uScreen;
out vec2 vUv;
out vec4 vColour;
void main() {
  gl_Position = vec4(aPosition.x / uScreen.x * 2.0 - 1.0, 1.0 - aPosition.y / uScreen.y * 2.0, 0.0, 1.0);
  vUv = aUv;
  vColour = aColour;
}
