#version 330 core
// Flat lighting from screen-space derivatives: the copies of F^n(A) are not welded, so a face
// normal is what a ray tracer would see too. A key light over the viewer's shoulder plus a
// dim fill from below and an ambient term; both sides lit (copies may be turned inside out).
in vec3 vViewPosition;
in vec3 vColor;
out vec4 fragColor;
void main() {
  vec3 n = normalize(cross(dFdx(vViewPosition), dFdy(vViewPosition)));
  if (dot(n, vViewPosition) > 0.0) n = -n;  // face the viewer
  vec3 key = normalize(vec3(-0.4, 0.6, 0.7));
  vec3 fill = normalize(vec3(0.5, -0.7, 0.3));
  vec3 v = normalize(-vViewPosition);
  float diffuse = max(dot(n, key), 0.0) * 0.75 + max(dot(n, fill), 0.0) * 0.25;
  float specular = pow(max(dot(n, normalize(key + v)), 0.0), 32.0) * 0.25;
  vec3 color = vColor * (0.18 + diffuse) + vec3(specular);
  fragColor = vec4(pow(clamp(color, 0.0, 1.0), vec3(1.0 / 1.1)), 1.0);
}
