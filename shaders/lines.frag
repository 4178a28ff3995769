#version 330 core
in vec4 gColour;
noperspective in float gDistance;
uniform float uDash;  // pixels on, pixels off; 0: solid
out vec4 fragColour;
void main() {
  if (uDash > 0.0 && mod(max(gDistance, 0.0), 2.0 * uDash) > uDash) discard;
  fragColour = gColour;
}
