#version 330 core
// Grid nodes, selected nodes, centers and handles as round sprites; aSize is in pixels at
// content scale 1, uPointScale carries the monitor content scale.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColor;
layout(location = 2) in float aSize;
uniform mat4 uViewProjection;
uniform float uPointScale;
out vec4 vColor;
out float vSize;
void main() {
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
  // Nodes are drawn on top of the lines they join (a small depth bias toward the viewer).
  gl_Position.z -= 0.002 * gl_Position.w;
  vSize = aSize * uPointScale;
  gl_PointSize = vSize;
  vColor = aColor;
}
