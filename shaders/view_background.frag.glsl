#version 330 core
// A soft vertical gradient behind the grid views, so black lines and dark nodes stay visible.
in vec2 vUv;
uniform vec3 uTop;
uniform vec3 uBottom;
out vec4 fragColor;
void main() { fragColor = vec4(mix(uTop, uBottom, clamp(vUv.y, 0.0, 1.0)), 1.0); }
