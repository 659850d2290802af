#version 330 core
// The renderer's z-buffer image (Gröller & Wegenkittl 1994, §3.1), already depth-cued and composited over the
// project background by ChaosRenderer::snapshot(); uploaded with row 0 at the top.
in vec2 vUv;
uniform sampler2D uImage;
out vec4 fragColor;
void main() {
  if (vUv.x < 0.0 || vUv.x > 1.0 || vUv.y < 0.0 || vUv.y > 1.0) discard;
  fragColor = vec4(texture(uImage, vUv).rgb, 1.0);
}
