#version 330 core
// The deterministic preview (Gröller & Wegenkittl 1994, §3.2): F^n(A) as a lit mesh. Positions are world space;
// the color is each copy's structural color (the chaos game's blend, see deterministic_ifs.h).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColor;
uniform mat4 uViewProjection;
uniform mat4 uView;
out vec3 vViewPosition;
out vec3 vColor;
void main() {
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
  vViewPosition = (uView * vec4(aPosition, 1.0)).xyz;
  vColor = aColor.rgb;
}
