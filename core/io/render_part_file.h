#pragma once
// The render part file (.gpart): one part of a split render's accumulation, before anything is
// developed from it (docs/FARM.md describes the layout byte by byte).
//
//   "GRIDPART" · u32 format version · u32 header length · header (JSON) · u32 CRC-32 of the header
//   · zlib stream of buffer records · u64 stream length · u32 CRC-32 of the stream · "PARTEND\n"
//
// The header names the part (K of N), the device, the chunk range, a digest of the project and
// the options, and carries the project itself (as rendered: at the frame's time, with the
// command-line overrides applied), so that `gridifs merge` finishes the image without the project
// file. A buffer record is a name, an element size, a count, a fill byte and the runs of elements
// the render left at the fill (every byte 0, or 0xFF for empty keys) and of those it touched; only
// the touched ones are stored, with their bytes plane by plane (every element's byte 0, then byte
// 1, ...): sums and keys whose high bytes are mostly zero then compress to a fraction of their
// size. Version 1 (every element stored, no fill or runs) is still read.
//
// Little-endian throughout. Not thread-safe; a writer or reader is used by one thread.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gridifs {

/// Written: 2 (records store only the elements a render touched). Read: 1 and 2.
inline constexpr std::uint32_t kRenderPartVersion = 2;

/// What a part file says about itself.
struct RenderPartHeader {
  std::string kind;    // "image" (gridifs render) or "volume" (gridifs volume)
  std::string digest;  // of the project and every option that shapes the accumulation
  std::int64_t part = 0, parts = 1;
  std::string device;                         // "cpu" or a GPU's name
  std::int64_t chunkBegin = 0, chunkEnd = 0;  // of every time sample's chunk list (a GPU part: its chains)
  std::optional<std::int64_t> frame;          // with --frames
  std::string source;                         // the project file as given on the command line
  std::string project;                        // the project as rendered (JSON)
  std::string options;                        // the finishing options (JSON object), as `render` had them
};

/// A digest of `text` as 32 hex digits (two independent 64-bit FNV-1a passes): enough to tell the
/// parts of one render from those of another, not a cryptographic hash.
std::string renderDigest(const std::string& text);

/// Writes a part file atomically: nothing appears at `target` until commit().
class RenderPartWriter {
 public:
  RenderPartWriter(const std::filesystem::path& target, const RenderPartHeader& header);
  ~RenderPartWriter();
  RenderPartWriter(const RenderPartWriter&) = delete;
  RenderPartWriter& operator=(const RenderPartWriter&) = delete;

  /// Appends a buffer of `count` elements of `elementSize` bytes. Throws IoError.
  void buffer(const std::string& name, std::size_t elementSize, const void* data, std::size_t count);
  template <class T>
  void buffer(const std::string& name, const std::vector<T>& values) {
    buffer(name, sizeof(T), values.data(), values.size());
  }
  /// Ends the stream, writes the trailer and renames the file into place. Throws IoError.
  void commit();

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

/// Reads a part file front to back. Every method throws PartFileError with one sentence naming
/// the file when it is not a part file, is of another version, truncated or damaged.
class RenderPartReader {
 public:
  explicit RenderPartReader(const std::filesystem::path& file);
  ~RenderPartReader();
  RenderPartReader(const RenderPartReader&) = delete;
  RenderPartReader& operator=(const RenderPartReader&) = delete;

  const RenderPartHeader& header() const;
  /// Reads the next buffer, which must be called `name` with elements of sizeof(T), into `out`.
  template <class T>
  void buffer(const std::string& name, std::vector<T>& out, std::size_t maxCount) {
    const std::size_t count = nextBuffer(name, sizeof(T), maxCount);
    out.resize(count);
    readElements(out.data(), sizeof(T), count);
  }
  /// After the last buffer: checks the end of the stream, its length and checksum.
  void finish();
  /// Reads past the remaining buffers, then finish().
  void skipRest();

  /// Right after opening: checks that the file ends with a part's trailer, without reading the
  /// data in between (which the reader cannot read afterwards).
  void checkTrailerOnly();

  struct Impl;

 private:
  std::size_t nextBuffer(const std::string& name, std::size_t elementSize, std::size_t maxCount);
  void readElements(void* data, std::size_t elementSize, std::size_t count);
  std::unique_ptr<Impl> impl_;
};

/// Checks a whole part file (header, every record, the checksum) without keeping its buffers.
/// Returns the header; throws PartFileError.
RenderPartHeader verifyRenderPart(const std::filesystem::path& file);

/// Reads a part file's header and checks that its trailer is in place, without reading its data:
/// what `farm --status` needs of every part (a part appears only once written whole; `merge`
/// checks the data). Returns the header; throws PartFileError.
RenderPartHeader inspectRenderPart(const std::filesystem::path& file);

struct PartFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace gridifs
