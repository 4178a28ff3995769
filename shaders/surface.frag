#version 330 core
// Two-sided headlight shading; optional colour ramp by slope or colour by pass; optional highlight
// of flagged moves.
in vec3 vNormal;
in float vSlope;
flat in uint vFlags;
uniform vec3 uBaseColour;
uniform int uColourBySlope;
uniform vec2 uSlopeRange;  // degrees: the ramp's ends
uniform int uHighlight;
uniform int uColourByPass;
uniform vec3 uPassColours[6];  // render::passColour(1..6), the rough cut first
out vec4 fragColour;

// Blue - cyan - green - yellow - red, the same stops as the legend (render/colour_ramp.h).
vec3 ramp(float x) {
  const vec3 c0 = vec3(0.19, 0.30, 0.80);
  const vec3 c1 = vec3(0.10, 0.70, 0.85);
  const vec3 c2 = vec3(0.25, 0.75, 0.30);
  const vec3 c3 = vec3(0.95, 0.80, 0.15);
  const vec3 c4 = vec3(0.85, 0.20, 0.15);
  x = clamp(x, 0.0, 1.0) * 4.0;
  if (x < 1.0) return mix(c0, c1, x);
  if (x < 2.0) return mix(c1, c2, x - 1.0);
  if (x < 3.0) return mix(c2, c3, x - 2.0);
  return mix(c3, c4, x - 3.0);
}

void main() {
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;
  vec3 base = uBaseColour;
  if (uColourBySlope != 0) {
    float span = max(uSlopeRange.y - uSlopeRange.x, 1e-6);
    base = ramp((vSlope - uSlopeRange.x) / span);
  }
  // Bits 8-15 of the flags: the move's pass (0: none); the colours repeat after six passes.
  uint pass = (vFlags >> 8u) & 255u;
  if (uColourByPass != 0 && pass > 0u) base = uPassColours[int((pass - 1u) % 6u)];
  // Moves with findings: tinted red; under the slope colours (whose top is red) they keep their
  // colour and the others are greyed instead.
  bool flagged = (vFlags & 1u) != 0u;
  if (uHighlight != 0 && uColourBySlope == 0 && flagged) base = mix(base, vec3(0.95, 0.12, 0.10), 0.7);
  if (uHighlight != 0 && uColourBySlope != 0 && !flagged) base = mix(base, vec3(0.62, 0.63, 0.66), 0.8);
  // A key light from the upper left, a fill from the right, both fixed to the eye.
  vec3 key = normalize(vec3(-0.45, 0.60, 0.65));
  vec3 fill = normalize(vec3(0.70, -0.15, 0.70));
  float light = 0.38 + 0.52 * max(dot(n, key), 0.0) + 0.22 * max(dot(n, fill), 0.0);
  vec3 h = normalize(key + vec3(0.0, 0.0, 1.0));
  float specular = pow(max(dot(n, h), 0.0), 48.0) * 0.18;
  fragColour = vec4(min(base * light + vec3(specular), vec3(1.0)), 1.0);
}
