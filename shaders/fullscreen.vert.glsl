#version 330 core
// One triangle covering the viewport; vUv in [0, 1]² over the visible part, row 0 at the top.
// uRect = (x0, y0, x1, y1) in normalised device coordinates places an image inside the view.
uniform vec4 uRect;
out vec2 vUv;
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));  // (0,0) (2,0) (0,2)
  vec2 ndc = mix(uRect.xy, uRect.zw, corner);
  vUv = vec2(corner.x, 1.0 - corner.y);
  gl_Position = vec4(ndc, 0.0, 1.0);
}
