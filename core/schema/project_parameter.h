#pragma once
// A number of a project, addressed by its path in the project file ("functions[0].ops[1].k",
// "render.flame.gamma", "camera.target[2]"), resolved once into a typed accessor: which settings
// group, function, operation and field, with the field's description from the settings tables
// and the operation table. Keyframe tracks read and write their parameters through it, without
// going through the file's JSON.
//
// A path names exactly the numbers the project file holds, where it holds them: a matrix
// function has no placement, "render.shading" is there once the shading differs from its
// defaults or is the display mode, a field written only when changed is there only then, "time"
// only when it is not 0. Setting a number checks it as reading it from the file would, with the
// reader's words and path, so a keyed value is accepted exactly when a file holding it would be.
//
// Thread-safety: a ProjectParameter is a plain value; get and set touch only the project given.
#include <array>
#include <cstdint>
#include <string>

#include "anim/track_path.h"
#include "model/project.h"
#include "schema/field_schema.h"
#include "schema/operation_table.h"
#include "schema/settings_table.h"

namespace gridifs {

/// The range a slider (or a mutation) moves a number over; lo == hi when there is none.
struct ParameterSpan {
  double lo = 0.0, hi = 0.0;
};

class ProjectParameter {
 public:
  /// The number as the project file holds it (integers and seeds as doubles).
  double get(const Project& project) const;
  /// Sets the number as reading `value` from the project file would. Throws ModelError at path()
  /// with the file reader's words when a file could not hold it (out of range, not a whole
  /// number where one is expected, not finite); the project is then unchanged. Expects the
  /// project to have the parameter (as found by findParameter).
  void set(Project& project, double value) const;
  /// Its description's slider range where it has one, else the file reader's range where that
  /// is a span a hand would move over (finite and at most 1000 wide), else none.
  ParameterSpan span() const;
  /// The parameter's path as messages name it ("camera.target[1]", "functions[0].ops[2].k").
  std::string path() const;

  /// Whether the parameter belongs to "animation", which reading the file validates as a whole
  /// but validateProject does not.
  bool inAnimation() const;
  /// Whether the file holds it only while some values are what they are (see above), so it may
  /// be gone once it is set.
  bool dependsOnValues() const { return fragile_; }
  /// "time", which the project at a moment takes from the moment, not from a track.
  bool isTime() const { return where_ == Where::Time; }
  /// Whether the file holds it as a whole number (a resolution, a seed, an index).
  bool wholeNumber() const {
    return reader_ == Reader::Integer || reader_ == Reader::NounInteger || reader_ == Reader::IntegerRange ||
           reader_ == Reader::Seed;
  }

  /// Whether reading the project file meets this number before `other` (its position in the
  /// file's reading order); equal positions are the same number.
  bool readBefore(const ProjectParameter& other) const { return order_ < other.order_; }
  bool sameNumber(const ProjectParameter& other) const { return order_ == other.order_; }

 private:
  friend class ParameterResolver;

  enum class Where : std::uint8_t {
    Setting,           // field `setting` of settings group `group` (light `a`, function `f`), component `c`
    OpParam,           // function `f`, operation `o`: `param`, component `c`
    CalculatorVar,     // ... `param` (vars): variable `a`, `b` 0 value, 1 min, 2 max
    MorphPoint,        // ... `param` (pairs): pair `a`, `b` 0 from, 1 to, component `c`
    NodeMoveIndex,     // ... `param` (moves): move `a`, index `c`
    NodeMoveShift,     // ... `param` (moves): move `a`, displacement component `c`
    OpCenter,          // ... the center point, component `c`
    SelectionBound,    // ... selection box `a`, axis `b` (i, j, k), `c` 0 first, 1 last
    Resolution,        // function `f`: resolution `c`
    MatrixEntry,       // function `f`: row `a`, column `c`
    MedianRotate,      // function `f`
    MedianRotateAxis,  // function `f`: component `c`
    VariationWeight,   // function `f`: the weight of variation `key`
    VariationParam,    // function `f`: variation parameter `key`
    PostMatrix,        // function `f`'s post matrix: row `a`, column `c`
    Transition,        // row `a`, column `c`
    ControlPoint,      // point `a`, component `c`
    DensityParam,      // volume.field (layer `a`): `param`, component `c`
    Time,
    Version,
  };
  /// The settings groups (schema/settings_tables.h).
  enum class Group : std::uint8_t {
    Function,
    Placement,
    PostPlacement,
    FieldLayer,
    Set,           // a condensation set: functions[f].set, volume.start or a field layer's shape
    SetPlacement,  // that set's placement
    VolumeRender,
    TransferStop,
    Camera,
    Stereo,
    Render,
    Flame,
    Light,
    Shading,
    Ao,
    Fog,
    Dof,
    Animation,
    Volume
  };
  /// How the file reader checks the number; each has its own words.
  enum class Reader : std::uint8_t {
    Number,        // in [lo, hi]
    Integer,       // a whole number in [lo, hi]
    Seed,          // a non-negative whole number
    Finite,        // settings with a noun: finite, magnitude at most 1e6 (validation names the range)
    NounInteger,   // settings with a noun: Finite, then a whole number in [lo, hi]
    AnyFinite,     // settings read with SettingWords::FiniteOnly
    IntegerRange,  // settings read with SettingWords::IntegerRange: a whole number in [lo, hi]
    Time,          // finite
    Version,       // never: the format version is no parameter
  };
  /// The C++ type the number is kept in.
  enum class Storage : std::uint8_t { Double, Int, Int64, UInt64, Optional, None };

  /// Where the number lives in `project` (null for Version).
  void* locate(Project& project) const;
  /// The condensation set a Group::Set or Group::SetPlacement number lies in, and its path.
  CondensationSet& setOf(Project& project) const;
  std::string setPath() const;
  /// Component c_ of field_ at `field` when it is a vector, else `field`.
  void* fieldComponent(void* field) const;
  void check(double value) const;

  Where where_ = Where::Version;
  Group group_ = Group::Camera;
  Reader reader_ = Reader::Version;
  Storage storage_ = Storage::None;
  bool fragile_ = false;
  static constexpr int kStartSet = -2;
  int f_ = 0;  // function index; -1: the final function; kStartSet: volume.start
  int o_ = 0, a_ = 0, b_ = 0, c_ = 0;
  double lo_ = 0.0, hi_ = 0.0;  // the reader's range
  /// The field's description (schema/field_schema.h): a setting (Setting) or an operation's
  /// parameter (OpParam and the rows below it, DensityParam).
  const FieldSchema* field_ = nullptr;
  std::size_t offset_ = 0;   // DensityParam: the field's offset in FractalFieldParams
  std::string key_;          // VariationWeight, VariationParam: the name
  bool layerList_ = false;   // volume.field is a list: its layers are volume.field[a]
  bool layerShape_ = false;  // the Set* rows name the shape of field layer `a`, not a function's set
  /// Positions along the file's reading order, level by level (the root's member, the
  /// function, the field, ...), so sorting by it sorts numbers as reading meets them.
  std::array<std::int32_t, 9> order_{};
};

/// What a path names in a project.
enum class ParameterLookup {
  Number,      // a number: `parameter` reads and writes it
  NotANumber,  // a string, a switch, a list or an object
  Missing,     // nothing the project file holds
};

struct FoundParameter {
  ParameterLookup lookup = ParameterLookup::Missing;
  ProjectParameter parameter;  // when lookup is Number
};

/// Which numbers a path may name.
enum class ParameterScope {
  /// What the project file holds now (keyframe tracks, whose keys must survive a save).
  File,
  /// Also the numbers the file leaves out while they keep their defaults: a field written only
  /// when changed, an optional number not yet set, the shading of a project not shaded yet, a
  /// median's rotation axis. An edit sets them as a panel would (SetParameter).
  Edit,
};

/// Looks `path` up in `project`. Never throws.
FoundParameter findParameter(const Project& project, const TrackPath& path,
                             ParameterScope scope = ParameterScope::File);

}  // namespace gridifs
