// The chaos game on the GPU (Gröller & Wegenkittl's stochastic algorithm, as in the CPU renderer;
// structural colour after Draves & Reckase, §5): one independent chain per invocation.
// The host prepends "#version 430", the extensions and these defines:
//   ATOMIC64          1: z-buffer keys are (depth bits << 32 | rgba8) under 64-bit atomicMin (exact,
//                     as on the CPU); 0: a 32-bit key (16-bit depth over the scene's depth range,
//                     RGB565 colour) under 32-bit atomicMin.
//   ACCUMULATE_COLOR  1: per-pixel colour sums for the flame display (fixed point, 16 fraction
//                     bits, 64 bits per channel as two 32-bit words with carry, so sums are exact
//                     and independent of the order of the atomics).
//   EMIT_POINTS       1: write every plotted point (world xyz, rgb) instead of projecting it.
//   BIN_VOXELS        1: count every plotted point in its voxel of an n³ lattice over X = [-1, 1]³
//                     instead of projecting it (the density volume; Sokolov & Gentil §3.4's
//                     measure binned), with ACCUMULATE_COLOR: fixed-point rgb sums per voxel.
//   VARIATIONS        1: functions may have flame variations (flame_variations.comp.glsl, prepended).
//   EVALUATE_MAPS     1: no chaos game; map given points through one function each (tests).
layout(local_size_x = 64) in;

struct Fn {
  vec4 toLattice;
  vec4 maxCell;
  vec4 color;  // r g b c
  float speed;
  uint strideJ, strideK, pairOffset;
};
struct Chain {
  vec4 p;      // xyz
  vec4 color;  // r g b c
  uvec4 rng;   // xoshiro128** state
  uvec4 misc;  // iterations left, skip left, transition row, steps since the last restart
};

layout(std430, binding = 0) readonly buffer Functions { Fn fns[]; };
layout(std430, binding = 1) readonly buffer Nodes { vec4 nodes[]; };  // node pairs: a, b, a, b, ...
layout(std430, binding = 2) readonly buffer Alias { uvec2 aliasTable[]; };
layout(std430, binding = 3) buffer Chains { Chain chains[]; };
layout(std430, binding = 4) buffer Tallies { uvec2 tallies[]; };  // per chain: bad, plotted
// CompiledIfs::transitionWalk (threshold, alias, keepRow, aliasRow), read only when uTransitions.
layout(std430, binding = 10) readonly buffer TransitionWalk { uvec4 walk[]; };
#if EMIT_POINTS
layout(std430, binding = 5) writeonly buffer Points { vec4 points[]; };  // xyz valid, rgb 0 per slot
#elif BIN_VOXELS
layout(std430, binding = 6) buffer Density { uint density[]; };  // hits per voxel, x fastest
#if ACCUMULATE_COLOR
layout(std430, binding = 7) buffer ColorSums { uint sums[]; };  // 6 words per voxel: lo, hi per channel
#endif
#else
#if ATOMIC64
layout(std430, binding = 5) buffer ZBuffer { uint64_t keys[]; };
#else
layout(std430, binding = 5) buffer ZBuffer { uint keys[]; };
#endif
layout(std430, binding = 6) buffer Density { uint density[]; };
#if ACCUMULATE_COLOR
layout(std430, binding = 7) buffer ColorSums { uint sums[]; };  // 8 words per pixel: lo, hi per channel
layout(std430, binding = 8) readonly buffer Palette { vec4 palette[]; };  // 257 entries when used
#endif
#endif

uniform uint uMode;        // 0: seed the chains, 1: iterate
uniform uint uChains;      // the chains in this dispatch's buffers
uniform uint uChainBase;   // the job's index of the first of them (a render part's first chain)
uniform uint uCount;       // functions (the final function, if any, is fns[uCount])
uniform bool uHasFinal;
uniform uint uSkip;
uniform float uEscape;
uniform uvec2 uSeed;       // low, high 32 bits
uniform uvec2 uBudget;     // job chain i iterates uBudget.x + (i < uBudget.y ? 1 : 0) times in all
uniform bool uUnlimited;
uniform uint uIterations;  // per chain in this dispatch
uniform vec4 uCamX, uCamY, uCamZ, uCam1;  // (px·w, py·w, w, depth) = columns · (x, y, z, 1)
uniform vec2 uSize;
uniform float uNear;
// Panoramic cameras and stereo eyes (render/camera.h): the rows above are eye 0's; uCamRight
// holds eye 1's columns. Panoramic rows are the view rows (x, y, z, view depth).
uniform int uProjection;          // 0: flat, 1: fisheye, 2: equirectangular
uniform bool uStereo;             // two eyes: a chain's plotted samples alternate between them
uniform vec4 uCamRight[4];
uniform vec4 uEyeBounds[2];       // x0, x1, y0, y1 in frame pixels
uniform vec2 uEyeCentre[2];
uniform float uPixelsPerRadian, uHalfFov, uEyeRadius;
uniform vec3 uViewUp;
uniform mat3 uEyeTurn[2];
uniform float uEyeSign[2];
// The camera's lens blur (flam3's cam_dof): a sample at view depth d moves in the image plane,
// at a uniform angle, by a uniform distance up to uLensAperture · |d − uLensFocus|.
uniform float uLensAperture;  // 0: no blur
uniform float uLensFocus;
uniform vec4 uLensDepthRow;   // view depth = dot(uLensDepthRow, (x, y, z, 1))
uniform vec3 uLensRight, uLensUp;
uniform uint uStride;
uniform vec2 uDepthQuant;  // 32-bit keys: q = (depth - x) · y in [0, 65535]
uniform bool uPalette;
uniform uint uVoxels;      // BIN_VOXELS: voxels per axis
uniform bool uTransitions;       // walk the transition rows (a transition matrix or states)
uniform uint uRestartInterval;   // CompiledIfs::restartInterval (0: never)
uniform uint uStateRowsOffset;   // CompiledIfs::stateRowsOffset (0 without states)

// The flags on a transition row offset for an IFS matrix with states, as the CPU kernel's
// (render/compiled_ifs.h): hidden (move without plotting), peek (plot the image, keep the chain),
// skip phase (the chain stays in one strongly connected part while it skips).
const uint kHidden = 1u << 31;
const uint kPeek = 1u << 30;
const uint kSkipPhase = 1u << 29;
const uint kTransitionFlags = kHidden | kPeek | kSkipPhase;
const uint kRowMask = kSkipPhase - 1u;

uint rotl(uint x, int k) { return (x << k) | (x >> (32 - k)); }

// xoshiro128** (Blackman & Vigna 2018): four 32-bit words, no 64-bit arithmetic needed.
uint nextRandom(inout uvec4 s) {
  const uint result = rotl(s.y * 5u, 7) * 9u;
  const uint t = s.y << 9;
  s.z ^= s.x;
  s.w ^= s.y;
  s.y ^= s.z;
  s.x ^= s.w;
  s.z ^= t;
  s.w = rotl(s.w, 11);
  return result;
}

// A 32-bit integer mixer (Wellons' lowbias32) to seed each chain from (seed, chain).
uint mix32(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

float signedUnit(uint bits) { return float(bits >> 8) * (2.0 / 16777216.0) - 1.0; }

vec4 randomPoint(inout uvec4 rng) {
  return vec4(signedUnit(nextRandom(rng)), signedUnit(nextRandom(rng)), signedUnit(nextRandom(rng)), 0.0);
}

void restartChain(inout Chain ch) {
  ch.p = randomPoint(ch.rng);
  ch.color = vec4(0.5, 0.5, 0.5, float(nextRandom(ch.rng) >> 8) * (1.0 / 16777216.0));
  ch.misc.y = uSkip;
  ch.misc.z = 0u;  // the first-function row
  ch.misc.w = 0u;
}

// The trilinear interpolation of function f's distorted nodes at lattice coordinate s in cell c.
vec3 interpolateCell(const Fn f, const vec3 s, const vec3 c) {
  const vec3 t = s - c;
  const uvec3 ci = uvec3(c);
  const uint i00 = 2u * (f.pairOffset + ci.x + f.strideJ * ci.y + f.strideK * ci.z);
  const uint dj = 2u * f.strideJ, dk = 2u * f.strideK;
  const vec4 a00 = nodes[i00], b00 = nodes[i00 + 1u];
  const vec4 a10 = nodes[i00 + dj], b10 = nodes[i00 + dj + 1u];
  const vec4 a01 = nodes[i00 + dk], b01 = nodes[i00 + dk + 1u];
  const vec4 a11 = nodes[i00 + dj + dk], b11 = nodes[i00 + dj + dk + 1u];
  const vec4 ea0 = a00 + (a10 - a00) * t.y, eb0 = b00 + (b10 - b00) * t.y;
  const vec4 ea1 = a01 + (a11 - a01) * t.y, eb1 = b01 + (b11 - b01) * t.y;
  const vec4 ea = ea0 + (ea1 - ea0) * t.z, eb = eb0 + (eb1 - eb0) * t.z;
  return (ea + (eb - ea) * t.x).xyz;
}

// p = f(p): clamp to X, locate the cell, trilinear interpolation of the distorted nodes (the same
// operations as CompiledFunction::evaluate).
vec3 applyFunction(uint fi, vec3 p) {
  const Fn f = fns[fi];
  p = clamp(p, vec3(-1.0), vec3(1.0));
  const vec3 s = (p + 1.0) * f.toLattice.xyz;
  return interpolateCell(f, s, min(floor(s), f.maxCell.xyz));
}

#if VARIATIONS
// The grid map of a function with variations, continued beyond X from its border cells (as
// CompiledFunction::evaluateExtrapolated): p is not clamped, the cell is.
vec3 applyExtrapolated(uint fi, vec3 p) {
  const Fn f = fns[fi];
  const vec3 s = (p + 1.0) * f.toLattice.xyz;
  return interpolateCell(f, s, max(min(floor(s), f.maxCell.xyz), vec3(0.0)));
}
#endif

// The whole map f of function fi: with a variation stage (stages[fi].x, the stage's offset, is
// not ~0) post(Σ w_i V_i) of the extrapolated grid map, drawing from the chain's stream; else the
// grid map.
vec3 mapPoint(uint fi, vec3 p, inout uvec4 rng) {
#if VARIATIONS
  const uvec4 stage = stages[fi];
  if (stage.x != 0xFFFFFFFFu) return applyVariationStage(stage.x, stage.y, applyExtrapolated(fi, p), rng);
#endif
  return applyFunction(fi, p);
}

// Whether every coordinate is finite and within the escape bound, compared on the bits as the CPU
// does (false for NaN and infinities even where a compiler assumes IEEE comparisons away).
bool inBounds(vec3 p) {
  return all(lessThanEqual(floatBitsToUint(p) & 0x7FFFFFFFu, uvec3(floatBitsToUint(uEscape))));
}

uint chooseFunction(inout uvec4 rng) {
  uint column, low;
  umulExtended(nextRandom(rng), uCount, column, low);
  const uvec2 e = aliasTable[column];
  return nextRandom(rng) < e.x ? column : e.y;
}

// The next function by the transition row at `row` (Thollot et al. §3.2: the matrix's Markov
// chain), which becomes the row after that function: the same alias draw as chooseFunction.
uint chooseAfter(inout uint row, inout uvec4 rng) {
  uint column, low;
  umulExtended(nextRandom(rng), uCount, column, low);
  const uvec4 e = walk[row + column];
  const bool keep = nextRandom(rng) < e.x;
  row = keep ? e.z : e.w;
  return keep ? column : e.y;
}

#if ACCUMULATE_COLOR
void addFixed(uint word, float value) {
  const uint v = uint(clamp(value, 0.0, 1.0) * 65536.0 + 0.5);
  const uint old = atomicAdd(sums[word], v);
  if (old + v < old) atomicAdd(sums[word + 1u], 1u);  // carry into the high word
}
#endif

#if BIN_VOXELS

// The voxel of q by the same float arithmetic as the CPU's binning: s = (q + 1) · n/2.
bool plot(vec3 q, vec4 col) {
  const float n = float(uVoxels);
  const vec3 s = (q + 1.0) * (0.5 * n);
  if (!(all(greaterThanEqual(s, vec3(0.0))) && all(lessThan(s, vec3(n))))) return false;  // NaN fails
  const uvec3 v = uvec3(s);
  const uint voxel = v.x + uVoxels * (v.y + uVoxels * v.z);
  if (atomicAdd(density[voxel], 1u) == 0xFFFFFFFFu) atomicMax(density[voxel], 0xFFFFFFFFu);  // saturate
#if ACCUMULATE_COLOR
  for (uint k = 0u; k < 3u; ++k) addFixed(voxel * 6u + 2u * k, col[k]);
#endif
  return true;
}

#elif !EMIT_POINTS

uint plotEye = 0u;  // stereo: the eye of this chain's next plotted sample

// A panoramic camera's pixel and depth of view-space point v for `eye` (OrbitCamera::project).
bool projectPanoramic(vec3 v, uint eye, out vec2 xy, out float depth) {
  if (uStereo) {
    // The eye on the circle of radius uEyeRadius whose ray to the point touches it.
    const vec3 h = v - dot(v, uViewUp) * uViewUp;
    const float d2 = dot(h, h), r2 = uEyeRadius * uEyeRadius;
    if (!(d2 > r2)) return false;
    const float t = sqrt(d2 - r2);
    const vec3 e = (r2 / d2) * h + (uEyeSign[eye] * uEyeRadius * t / d2) * cross(h, uViewUp);
    v = uEyeTurn[eye] * (v - e);
  }
  depth = length(v);
  if (uProjection == 1) {
    const float len = length(v.xy), theta = atan(len, -v.z);
    if (theta > uHalfFov) return false;
    const float k = len > 0.0 ? theta * uPixelsPerRadian / len : 0.0;
    xy = uEyeCentre[eye] + vec2(k * v.x, -k * v.y);
  } else {
    xy = uEyeCentre[eye] + uPixelsPerRadian * vec2(atan(v.x, -v.z), -atan(v.y, length(v.xz)));
  }
  return true;
}

bool plot(vec3 q, vec4 col) {
  const uint eye = plotEye;
  if (uStereo) plotEye ^= 1u;
  const vec4 r = eye == 0u ? uCamX * q.x + uCamY * q.y + uCamZ * q.z + uCam1
                           : uCamRight[0] * q.x + uCamRight[1] * q.y + uCamRight[2] * q.z + uCamRight[3];
  float depth = r.w;
  vec2 xy;
  if (uProjection == 0) {
    xy = r.xy * (1.0 / r.z);
  } else if (!projectPanoramic(r.xyz, eye, xy, depth)) {
    return false;
  }
  if (!(depth > uNear)) return false;
  const vec4 bounds = uEyeBounds[eye];
  if (!(xy.x >= bounds.x && xy.x < bounds.y && xy.y >= bounds.z && xy.y < bounds.w)) return false;
  const uvec2 ixy = uvec2(xy);
  const uint pixel = ixy.y * uStride + ixy.x;
#if ATOMIC64
  const uint64_t key = (uint64_t(floatBitsToUint(depth)) << 32) | uint64_t(packUnorm4x8(col));
  atomicMin(keys[pixel], key);
#else
  const uint q16 = uint(clamp((depth - uDepthQuant.x) * uDepthQuant.y, 0.0, 65534.0));
  const uvec3 c565 = uvec3(clamp(col.rgb, 0.0, 1.0) * vec3(31.0, 63.0, 31.0) + 0.5);
  atomicMin(keys[pixel], (q16 << 16) | (c565.r << 11) | (c565.g << 5) | c565.b);
#endif
  if (atomicAdd(density[pixel], 1u) == 0xFFFFFFFFu) atomicMax(density[pixel], 0xFFFFFFFFu);  // saturate
#if ACCUMULATE_COLOR
  vec4 add = col;
  if (uPalette) {  // flam3's linear palette mode: index c·256, blend entries i and i+1
    const float x = clamp(col.w * 256.0, 0.0, 256.0);
    const int i = min(int(x), 255);
    add = vec4(mix(palette[i].rgb, palette[i + 1].rgb, x - float(i)), col.w);
  }
  for (uint k = 0u; k < 4u; ++k) addFixed(pixel * 8u + 2u * k, add[k]);
#endif
  return true;
}
#endif

// The stream of job chain `id` under uSeed.
uvec4 seedStream(uint id) {
  uvec4 rng = uvec4(mix32(uSeed.x ^ mix32(id)), mix32(uSeed.y ^ mix32(id + 0x9e3779b9u)),
                    mix32(uSeed.x + mix32(id ^ 0x85ebca6bu)), mix32(uSeed.y + mix32(id ^ 0xc2b2ae35u)));
  if (all(equal(rng, uvec4(0u)))) rng.x = 1u;
  for (int k = 0; k < 4; ++k) nextRandom(rng);
  return rng;
}

#if EVALUATE_MAPS
// Tests: slot i holds a point (p) and a function index (misc.x); f(p) replaces the point, drawn
// from stream uChainBase + i. The same mapPoint as the chaos game's, so the tests check the code
// that renders.
void main() {
  const uint chain = gl_GlobalInvocationID.x;
  if (chain >= uChains) return;
  Chain ch = chains[chain];
  ch.rng = seedStream(uChainBase + chain);
  ch.p.xyz = mapPoint(ch.misc.x, ch.p.xyz, ch.rng);
  chains[chain] = ch;
}
#else
void main() {
  const uint chain = gl_GlobalInvocationID.x;  // the slot in this dispatch's buffers
  if (chain >= uChains) return;
  Chain ch;
  if (uMode == 0u) {
    // Seed and budget from the chain's index in the whole job, so that a chain plays the same
    // points in a render part as in the whole render (the parts' sums are then the whole's).
    const uint id = uChainBase + chain;
    ch.rng = seedStream(id);
    restartChain(ch);
    ch.misc.x = uUnlimited ? 0xFFFFFFFFu : uBudget.x + (id < uBudget.y ? 1u : 0u);
    chains[chain] = ch;
    tallies[chain] = uvec2(0u);
    return;
  }
  ch = chains[chain];
  uvec2 tally = tallies[chain];
  const uint n = min(ch.misc.x, uIterations);
  for (uint k = 0u; k < n; ++k) {
    if (uRestartInterval > 0u && ++ch.misc.w > uRestartInterval) restartChain(ch);
    uint nextRow = ch.misc.z;
    const uint fi = uTransitions ? chooseAfter(nextRow, ch.rng) : chooseFunction(ch.rng);
    const vec3 p = mapPoint(fi, ch.p.xyz, ch.rng);
    const Fn f = fns[fi];
    const vec4 col = ch.color + (f.color - ch.color) * f.speed;  // c = mix(c, c_i, speed)
#if EMIT_POINTS
    points[2u * (k * uChains + chain)] = vec4(0.0);
#endif
    if (!inBounds(p)) {
      ++tally.x;
#if VARIATIONS
      // A bad value of a flame variation (spherical at 0, log of 0, …): as flam3 and the CPU
      // kernel, a fresh random point and the chain goes on, without a new skip (Draves & Reckase
      // 2003, §2); colour and skip count stay.
      ch.p = randomPoint(ch.rng);
#else
      restartChain(ch);
#endif
      continue;
    }
    if ((nextRow & kTransitionFlags) != 0u) {
      // An IFS matrix with states, as the CPU kernel's advanceAndPlot: a skip-phase step moves the
      // chain and, with its last skip, enters the plotting rows; a hidden step moves it without
      // plotting; a peek plots its image and leaves the chain as it was.
      if ((nextRow & kSkipPhase) != 0u) {
        ch.p.xyz = p;
        ch.color = col;
        ch.misc.z = (nextRow & kRowMask) + (ch.misc.y <= 1u ? uStateRowsOffset : 0u);
        if (ch.misc.y > 0u) --ch.misc.y;
        continue;
      }
      if ((nextRow & kPeek) == 0u) {
        ch.p.xyz = p;
        ch.color = col;
        ch.misc.z = nextRow & kRowMask;
        if (ch.misc.y > 0u) --ch.misc.y;
        continue;
      }
      if (ch.misc.y > 0u) continue;
    } else {
      ch.p.xyz = p;
      ch.color = col;
      ch.misc.z = nextRow;
      if (ch.misc.y > 0u) {
        --ch.misc.y;
        continue;
      }
    }
    vec3 q = p;
    vec4 qc = col;
    if (uHasFinal) {
      const Fn g = fns[uCount];
      q = mapPoint(uCount, p, ch.rng);
      if (!inBounds(q)) {
        ++tally.x;
        continue;
      }
      qc = col + (g.color - col) * g.speed;
    }
#if EMIT_POINTS
    points[2u * (k * uChains + chain)] = vec4(q, 1.0);
    points[2u * (k * uChains + chain) + 1u] = vec4(clamp(qc.rgb, 0.0, 1.0), 0.0);
    ++tally.y;
#else
    if (uLensAperture > 0.0) {
      const float radius = uLensAperture * abs(dot(uLensDepthRow, vec4(q, 1.0)) - uLensFocus);
      const float angle = float(nextRandom(ch.rng) >> 8) * (6.28318530718 / 16777216.0);
      const float distance = float(nextRandom(ch.rng) >> 8) * (1.0 / 16777216.0) * radius;
      q += (cos(angle) * uLensRight + sin(angle) * uLensUp) * distance;
    }
    if (plot(q, qc)) ++tally.y;
#endif
  }
#if EMIT_POINTS
  for (uint k = n; k < uIterations; ++k) points[2u * (k * uChains + chain)] = vec4(0.0);  // past this chain's budget
#endif
  if (!uUnlimited) ch.misc.x -= n;
  chains[chain] = ch;
  tallies[chain] = tally;
}
#endif
