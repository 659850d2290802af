#version 330 core
// A filled disc with a dark rim, anti-aliased over about one pixel.
in vec4 vColor;
in float vSize;
out vec4 fragColor;
void main() {
  float r = length(gl_PointCoord - vec2(0.5)) * vSize;  // distance from the center in pixels
  float radius = vSize * 0.5;
  float alpha = clamp(radius - r, 0.0, 1.0);
  if (alpha <= 0.0) discard;
  float rim = smoothstep(radius - 2.0, radius - 1.0, r);
  fragColor = vec4(mix(vColor.rgb, vColor.rgb * 0.25, rim), vColor.a * alpha);
}
