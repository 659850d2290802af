#version 330 core
// The measure attractor's density (Sokolov & Gentil, §3.4) ray-marched front to back with
// emission and absorption over the unit cube X = [-1, 1]³: each step of length uStep absorbs
// 1 - exp(-σ·density·uStep) of what lies behind it and adds as much of its own light, the
// albedo lit by the ambient term plus one directional light attenuated by the optical depth
// towards it (a precomputed 3D texture: Beer–Lambert self-shadowing, exp(-σ·depth)).
in vec2 vUv;
uniform mat4 uInverseViewProjection;
uniform sampler3D uDensity;     // density in [0, 1]
uniform sampler3D uLightDepth;  // ∫ density ds towards the light, world units
uniform sampler3D uColor;       // mean structural colour of the visits (when uHasColor)
uniform sampler2D uPalette;     // 256 × 1 palette, indexed by density otherwise
uniform int uHasColor;
uniform vec3 uLightColor;
uniform float uAmbient;
uniform vec3 uBackground;
uniform float uDensityScale;    // σ: extinction per world unit at density 1
uniform float uStep;            // world units per step (half a voxel)
out vec4 fragColor;

// A per-pixel offset of the first step, so the step pattern reads as fine noise instead of
// bands.
float jitter(vec2 p) { return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453); }

void main() {
  // Rows run bottom-up here: the picture is then shown through the preview's image blit, which
  // takes row 0 as the top.
  vec2 ndc = vUv * 2.0 - 1.0;
  vec4 nearPoint = uInverseViewProjection * vec4(ndc, -1.0, 1.0);
  vec4 farPoint = uInverseViewProjection * vec4(ndc, 1.0, 1.0);
  vec3 origin = nearPoint.xyz / nearPoint.w;
  vec3 direction = normalize(farPoint.xyz / farPoint.w - origin);
  // Slab test against the cube.
  vec3 inverse = 1.0 / direction;
  vec3 t0 = (vec3(-1.0) - origin) * inverse, t1 = (vec3(1.0) - origin) * inverse;
  vec3 tNear = min(t0, t1), tFar = max(t0, t1);
  float enter = max(max(max(tNear.x, tNear.y), tNear.z), 0.0);
  float leave = min(min(tFar.x, tFar.y), tFar.z);
  if (!(leave > enter)) {
    fragColor = vec4(uBackground, 1.0);
    return;
  }
  vec3 radiance = vec3(0.0);
  float transmittance = 1.0;
  for (float t = enter + uStep * jitter(gl_FragCoord.xy); t < leave; t += uStep) {
    vec3 uvw = (origin + direction * t) * 0.5 + 0.5;
    float density = texture(uDensity, uvw).r;
    if (density <= 1e-4) continue;
    float alpha = 1.0 - exp(-uDensityScale * density * uStep);
    vec3 albedo = uHasColor == 1 ? texture(uColor, uvw).rgb
                                 : texture(uPalette, vec2((density * 255.0 + 0.5) / 256.0, 0.5)).rgb;
    float shadow = exp(-uDensityScale * texture(uLightDepth, uvw).r);
    radiance += transmittance * alpha * albedo * (uAmbient + uLightColor * shadow);
    transmittance *= 1.0 - alpha;
    if (transmittance < 0.004) break;
  }
  fragColor = vec4(radiance + transmittance * uBackground, 1.0);
}
