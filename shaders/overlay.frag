#version 330 core
in vec2 vUv;
in vec4 vColour;
uniform sampler2D uTexture;
out vec4 fragColour;
void main() { fragColour = vColour * texture(uTexture, vUv); }
