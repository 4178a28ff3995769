#version 330 core
// Widens each line segment to a screen-aligned quad uWidth pixels wide (core profile lines are
// one pixel), and passes the distance along it in pixels for dashing.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
uniform vec2 uViewport;  // pixels
uniform float uWidth;    // pixels
in vec4 vColour[];
out vec4 gColour;
noperspective out float gDistance;
void main() {
  vec4 p0 = gl_in[0].gl_Position;
  vec4 p1 = gl_in[1].gl_Position;
  vec2 half_ = 0.5 * uViewport;
  vec2 s0 = p0.xy / p0.w * half_;
  vec2 s1 = p1.xy / p1.w * half_;
  vec2 d = s1 - s0;
  float len = length(d);
  vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 side = vec2(-dir.y, dir.x) * (0.5 * uWidth);
  vec2 along = dir * (0.5 * uWidth);
  vec2 corners[4] = vec2[4](s0 - along + side, s0 - along - side, s1 + along + side, s1 + along - side);
  float dist[4] = float[4](-0.5 * uWidth, -0.5 * uWidth, len + 0.5 * uWidth, len + 0.5 * uWidth);
  for (int i = 0; i < 4; ++i) {
    vec4 p = i < 2 ? p0 : p1;
    gl_Position = vec4(corners[i] / half_ * p.w, p.z, p.w);
    gColour = i < 2 ? vColour[0] : vColour[1];
    gDistance = dist[i];
    EmitVertex();
  }
  EndPrimitive();
}
