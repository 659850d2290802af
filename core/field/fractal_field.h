#pragma once
// Colonna's fractal fields ("Animation of fractal objects", §1.2 and §2): the sum of m
// independent meshes M_1..M_m of decreasing cell size, each carrying random values RDN at its
// vertices and interpolated between them, weighted by p(k). GridIFS samples the field in four
// dimensions (x, y, z, t), so one dimension is time, and maps a point to the field with the
// wind shift and the modulo wrap of Colonna's §3.2 (cloud dynamics).
//
// Choices where the paper leaves them open:
// - RDN is a hash of (vertex, level, seed) — no stored tables, equal on every machine; one
//   32-bit hash gives the 16-bit values of two seeds (field_lattice.h).
// - p(k) ∝ gain^k, normalised to sum 1.
// - Each level's mesh is shifted by a fraction of its cell (an additive recurrence on the
//   generalised golden ratio), so vertices of different levels do not coincide.
// - A periodic coordinate (period L > 0) uses, per level, a whole number of cells per period
//   (the nearest one to L / cell size) and wraps vertex indices, so the field is continuous
//   across the wrap and F(s + L) = F(s) exactly — loops close without a seam.
//
// Thread-safety: a FractalField is immutable after construction; evaluate it from any thread.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/types.h"

namespace gridifs {

enum class FieldInterpolation {
  Linear,  // n-linear over the 2^n nodes of the cell
  Cubic,   // Colonna's pseudo n-cubic (second appendix), extended to four dimensions
};

const char* toString(FieldInterpolation interpolation);
/// Parses "linear" or "cubic"; returns false for anything else.
bool parseFieldInterpolation(const std::string& text, FieldInterpolation& out);

/// The parameters of the `field` operation (names as in the project file).
struct FractalFieldParams {
  Vec3 amplitude{0.1, 0.1, 0.1};
  double scale = 0.5;  // cell size of the first (coarsest) mesh
  double ratio = 0.5;  // each further mesh's cell size is the previous one's times this
  int octaves = 6;     // number of meshes m
  double gain = 0.5;   // p(k) ∝ gain^k
  FieldInterpolation interpolation = FieldInterpolation::Cubic;
  std::uint64_t seed = 0;                            // axis a uses seed + a (modulo 2^64)
  Vec3 wind{0.0, 0.0, 0.0};                          // shift of the sample point per unit time
  std::array<double, 4> period{0.0, 0.0, 0.0, 0.0};  // Lx, Ly, Lz, Lt; 0 = not periodic
  /// Not a file field: the wind's displacement ∫₀ᵗ wind(τ) dτ at the project's time when the
  /// wind is keyed (set with the project at a moment, schema/wind_drift.h); none: wind·t.
  std::optional<Vec3> drift;

  /// The shift of the sample point at time t: the integral of the wind from 0 to t.
  Vec3 windShift(double t) const { return drift ? *drift : wind * t; }

  static constexpr int kMaxOctaves = 16;
  bool operator==(const FractalFieldParams&) const = default;
};

/// One sample point of the four-dimensional field space.
using FieldPoint = std::array<double, 4>;

class FractalField {
 public:
  /// Expects parameters that passed validation (octaves 1..16, ratio in (0, 1), scale and gain
  /// positive, periods non-negative).
  explicit FractalField(const FractalFieldParams& params);

  /// amplitude ⊙ (F_S(s), F_S+1(s), F_S+2(s)) with s = (q + windShift(t), t), wrapped by the periods.
  Vec3 displacement(const Vec3& q, double t) const;

  /// nodes[n] += displacement(nodes[n], t) for every n with mask[n] set, up to single-precision
  /// rounding (about 1e-7 of the amplitude): many nodes share the lattice vertices of the coarse
  /// meshes, so this evaluates the field for the whole time step at once (see field_step.h). Work is split over
  /// `threads` workers (≤ 0: all); no result depends on the split.
  void displaceNodes(std::vector<Vec3>& nodes, const std::vector<unsigned char>& mask, double t, int threads = 0) const;

  /// F for one axis (seed + axis) at a sample point (wind already applied, not yet wrapped).
  double value(int axis, FieldPoint s) const;

  /// A bound on |F|: 1 for linear interpolation (a convex combination of values in [-1, 1]);
  /// 2 for the pseudo-cubic one — each of the four cubic passes may overshoot by at most a
  /// quarter of the largest finite-difference slope (|slope| ≤ 1), since the Hermite slope
  /// weights u(1-u)^2 and u^2(1-u) sum to at most 1/4 in absolute value.
  double bound() const;

  const FractalFieldParams& params() const { return params_; }

  /// Where mesh `level` (1-based) has its vertices: at origin + index ⊙ cell. For tests and
  /// for tools that draw the meshes.
  struct MeshGeometry {
    FieldPoint origin{};
    FieldPoint cell{};
    double weight = 0.0;  // p(k)
  };
  MeshGeometry mesh(int level) const;

  /// One mesh as the evaluation reads it.
  struct Level {
    std::array<double, 4> cell{};        // cell size per dimension (periodic ones rounded to fit)
    std::array<double, 4> offset{};      // this level's shift of the mesh, within one cell
    std::array<std::int64_t, 4> wrap{};  // cells per period, 0 = not periodic
    double weight = 0.0;                 // p(k)
    // Seeds S, S+1, S+2 at this level: the hash key of each one's seed pair and the shift of
    // its half of the hash (field_lattice.h). Axes 0 and 2 are always in different pairs.
    std::array<std::uint32_t, 3> keys{};
    std::array<std::uint32_t, 3> shifts{};
  };
  int levelCount() const { return levelCount_; }
  /// Mesh `index` (0-based, < levelCount()).
  const Level& level(int index) const { return levels_[index]; }
  /// s with each coordinate wrapped modulo its period where the period is > 0.
  FieldPoint wrapped(FieldPoint s) const;

 private:
  /// One level's interpolated RDN for the first `axes` keys at s (already wrapped) into out.
  void levelValues(const Level& level, const std::array<std::uint32_t, 3>& keys,
                   const std::array<std::uint32_t, 3>& shifts, int axes, const FieldPoint& s, double* out) const;

  FractalFieldParams params_;
  std::array<Level, FractalFieldParams::kMaxOctaves> levels_{};
  int levelCount_ = 0;
};

}  // namespace gridifs
