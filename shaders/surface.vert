#version 330 core
// The ruled surface: positions in mm, normals per patch, the wire slope at each vertex.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aSlope;
layout(location = 3) in uint aFlags;
uniform mat4 uViewProjection;
uniform mat4 uView;
out vec3 vNormal;  // eye space
out float vSlope;
flat out uint vFlags;
void main() {
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
  vNormal = mat3(uView) * aNormal;
  vSlope = aSlope;
  vFlags = aFlags;
}
