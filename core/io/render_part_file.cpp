#include "io/render_part_file.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "base/errors.h"

namespace gridifs {
namespace {

constexpr char kMagic[8] = {'G', 'R', 'I', 'D', 'P', 'A', 'R', 'T'};
constexpr char kEndMagic[8] = {'P', 'A', 'R', 'T', 'E', 'N', 'D', '\n'};
/// Elements shuffled and compressed at a time: bounds the scratch memory (≤ 512 KB at 8 bytes).
constexpr std::size_t kBlockElements = 65536;
constexpr std::size_t kMaxHeaderBytes = 64u << 20;  // the project JSON is limited far below this
constexpr std::size_t kMaxNameBytes = 64;

template <class T>
void putLittle(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string headerJson(const RenderPartHeader& h) {
  nlohmann::json j = {{"kind", h.kind},     {"digest", h.digest},   {"part", h.part},
                      {"parts", h.parts},   {"device", h.device},   {"chunks", {h.chunkBegin, h.chunkEnd}},
                      {"source", h.source}, {"project", h.project}, {"options", h.options}};
  j["frame"] = h.frame ? nlohmann::json(*h.frame) : nlohmann::json(nullptr);
  return j.dump();
}

RenderPartHeader parseHeader(const std::string& text, const std::string& file) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    RenderPartHeader h;
    h.kind = j.at("kind").get<std::string>();
    h.digest = j.at("digest").get<std::string>();
    h.part = j.at("part").get<std::int64_t>();
    h.parts = j.at("parts").get<std::int64_t>();
    h.device = j.at("device").get<std::string>();
    h.chunkBegin = j.at("chunks").at(0).get<std::int64_t>();
    h.chunkEnd = j.at("chunks").at(1).get<std::int64_t>();
    h.source = j.at("source").get<std::string>();
    h.project = j.at("project").get<std::string>();
    h.options = j.at("options").get<std::string>();
    if (!j.at("frame").is_null()) h.frame = j.at("frame").get<std::int64_t>();
    if (h.parts < 1 || h.part < 0 || h.part >= h.parts)
      throw PartFileError(file + " is damaged: its part number is outside 0.." + std::to_string(h.parts - 1));
    return h;
  } catch (const nlohmann::json::exception&) {
    throw PartFileError(file + " is damaged: its header is not the header of a render part");
  }
}

/// Every element's byte 0, then every byte 1, ...: the planes of sums and keys whose high bytes
/// are mostly zero compress far better than the interleaved bytes.
void shuffle(const std::uint8_t* in, std::uint8_t* out, std::size_t size, std::size_t count) {
  for (std::size_t b = 0; b < size; ++b)
    for (std::size_t i = 0; i < count; ++i) out[b * count + i] = in[i * size + b];
}

void unshuffle(const std::uint8_t* in, std::uint8_t* out, std::size_t size, std::size_t count) {
  for (std::size_t b = 0; b < size; ++b)
    for (std::size_t i = 0; i < count; ++i) out[i * size + b] = in[b * count + i];
}

}  // namespace

std::string renderDigest(const std::string& text) {
  std::uint64_t a = 0xCBF29CE484222325ull, b = 0x84222325CBF29CE4ull;
  for (unsigned char c : text) {
    a = (a ^ c) * 0x100000001B3ull;
    b = (b ^ (c + 0x9Bu)) * 0x100000001B3ull;
    b ^= b >> 29;
  }
  char out[33];
  std::snprintf(out, sizeof out, "%016llx%016llx", static_cast<unsigned long long>(a),
                static_cast<unsigned long long>(b));
  return out;
}

// ---------------------------------------------------------------------------------------------
struct RenderPartWriter::Impl {
  AtomicFile atomic;
  std::ofstream file;
  z_stream z{};
  std::uint64_t streamBytes = 0;
  std::uint32_t crc = 0;
  std::vector<std::uint8_t> scratch, out;

  explicit Impl(const std::filesystem::path& target) : atomic(target), out(1 << 16) {}

  [[noreturn]] void fail() {
    throw IoError("cannot write " + atomic.target().string() + ": the disk refused the data");
  }

  void raw(const void* data, std::size_t bytes) {
    file.write(static_cast<const char*>(data), std::streamsize(bytes));
    if (!file) fail();
  }

  void compress(const void* data, std::size_t bytes, int flush) {
    crc = std::uint32_t(crc32_z(crc, static_cast<const Bytef*>(data), bytes));
    streamBytes += bytes;
    z.next_in = static_cast<Bytef*>(const_cast<void*>(data));
    z.avail_in = uInt(bytes);
    do {
      z.next_out = out.data();
      z.avail_out = uInt(out.size());
      if (deflate(&z, flush) == Z_STREAM_ERROR) fail();
      raw(out.data(), out.size() - z.avail_out);
    } while (z.avail_out == 0 || z.avail_in > 0);
  }
};

RenderPartWriter::RenderPartWriter(const std::filesystem::path& target, const RenderPartHeader& header)
    : impl_(std::make_unique<Impl>(target)) {
  Impl& w = *impl_;
  w.file.open(w.atomic.temporaryPath(), std::ios::binary | std::ios::trunc);
  if (!w.file) throw IoError("cannot write " + target.string() + ": its folder does not take new files");
  if (deflateInit(&w.z, 6) != Z_OK) throw IoError("cannot write " + target.string() + ": zlib failed to start");
  const std::string json = headerJson(header);
  std::string head(kMagic, sizeof kMagic);
  putLittle(head, kRenderPartVersion);
  putLittle(head, std::uint32_t(json.size()));
  head += json;
  putLittle(head, std::uint32_t(crc32_z(0, reinterpret_cast<const Bytef*>(json.data()), json.size())));
  w.raw(head.data(), head.size());
}

RenderPartWriter::~RenderPartWriter() { deflateEnd(&impl_->z); }

void RenderPartWriter::buffer(const std::string& name, std::size_t elementSize, const void* data, std::size_t count) {
  Impl& w = *impl_;
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  // Only what the render touched is stored: runs of untouched elements (every byte the fill
  // byte: 0 for counts and sums, 0xFF for empty keys and depths) are skipped.
  const auto filledWith = [&](std::size_t i, std::uint8_t fill) {
    for (std::size_t b = 0; b < elementSize; ++b)
      if (bytes[i * elementSize + b] != fill) return false;
    return true;
  };
  std::size_t zeros = 0, ones = 0;
  for (std::size_t i = 0; i < count; i += 61) zeros += filledWith(i, 0x00), ones += filledWith(i, 0xFF);
  const std::uint8_t fill = ones > zeros ? 0xFF : 0x00;
  std::vector<std::uint32_t> runs;  // skip, take, skip, take, ...
  std::size_t kept = 0;
  for (std::size_t i = 0; i < count;) {
    std::size_t skip = 0, take = 0;
    while (i < count && skip < 0xFFFFFFFFu && filledWith(i, fill)) ++i, ++skip;
    while (i < count && take < 0xFFFFFFFFu && !filledWith(i, fill)) ++i, ++take;
    runs.push_back(std::uint32_t(skip));
    runs.push_back(std::uint32_t(take));
    kept += take;
  }
  std::string record;
  putLittle(record, std::uint32_t(name.size()));
  record += name;
  putLittle(record, std::uint32_t(elementSize));
  putLittle(record, std::uint64_t(count));
  record += char(fill);
  putLittle(record, std::uint64_t(runs.size() / 2));
  w.compress(record.data(), record.size(), Z_NO_FLUSH);
  if (!runs.empty()) w.compress(runs.data(), runs.size() * sizeof(std::uint32_t), Z_NO_FLUSH);
  // The kept elements, gathered and shuffled a block at a time.
  std::vector<std::uint8_t> gathered;
  gathered.reserve(std::min(kept, kBlockElements) * elementSize);
  const auto flushBlock = [&] {
    const std::size_t n = gathered.size() / elementSize;
    w.scratch.resize(gathered.size());
    shuffle(gathered.data(), w.scratch.data(), elementSize, n);
    w.compress(w.scratch.data(), w.scratch.size(), Z_NO_FLUSH);
    gathered.clear();
  };
  std::size_t at = 0;
  for (std::size_t r = 0; r < runs.size(); r += 2) {
    at += runs[r];
    for (std::size_t k = 0; k < runs[r + 1]; ++k, ++at) {
      gathered.insert(gathered.end(), bytes + at * elementSize, bytes + (at + 1) * elementSize);
      if (gathered.size() == kBlockElements * elementSize) flushBlock();
    }
  }
  if (!gathered.empty()) flushBlock();
}

void RenderPartWriter::commit() {
  Impl& w = *impl_;
  const std::uint32_t end = 0;  // a record with an empty name ends the stream
  w.compress(&end, sizeof end, Z_FINISH);
  std::string trailer;
  putLittle(trailer, w.streamBytes);
  putLittle(trailer, w.crc);
  trailer.append(kEndMagic, sizeof kEndMagic);
  w.raw(trailer.data(), trailer.size());
  w.file.close();
  if (!w.file) w.fail();
  w.atomic.commit();
}

// ---------------------------------------------------------------------------------------------
struct RenderPartReader::Impl {
  std::string name;
  std::ifstream file;
  RenderPartHeader header;
  z_stream z{};
  bool zOpen = false, streamEnded = false;
  std::vector<std::uint8_t> in, scratch;
  std::uint64_t streamBytes = 0;
  std::uint32_t crc = 0;
  std::size_t pendingSize = 0, pendingCount = 0;
  bool endRecordRead = false;
  std::uint32_t version = kRenderPartVersion;
  // Version 2's sparse record: the fill byte and the (skip, take) runs of the pending buffer.
  std::uint8_t pendingFill = 0;
  std::vector<std::uint32_t> pendingRuns;

  /// After a record's name, size and count: version 2's fill byte and runs (checked against the
  /// count), none in version 1.
  void readRuns(std::uint64_t count) {
    pendingRuns.clear();
    if (version < 2) return;
    inflateExactly(&pendingFill, 1);
    if (pendingFill != 0x00 && pendingFill != 0xFF) damaged("is damaged: a buffer's fill byte is neither 0 nor 255");
    const auto runCount = little<std::uint64_t>();
    if (runCount > count + 1) damaged("is damaged: a buffer has more runs than elements");
    // A block at a time, so that a damaged run count costs no more memory than the data that is
    // really there.
    std::uint64_t covered = 0;
    for (std::uint64_t at = 0; at < runCount;) {
      const std::size_t n = std::size_t(std::min<std::uint64_t>(kBlockElements, runCount - at));
      const std::size_t old = pendingRuns.size();
      pendingRuns.resize(old + 2 * n);
      inflateExactly(pendingRuns.data() + old, 2 * n * sizeof(std::uint32_t));
      for (std::size_t k = old; k < pendingRuns.size(); ++k) covered += pendingRuns[k];
      if (covered > count) damaged("is damaged: a buffer's runs are longer than the buffer");
      at += n;
    }
    if (covered != count) damaged("is damaged: a buffer's runs do not add up to its length");
  }
  /// The elements stored for the pending buffer (all of them in version 1).
  std::uint64_t storedElements(std::uint64_t count) const {
    if (version < 2) return count;
    std::uint64_t kept = 0;
    for (std::size_t r = 1; r < pendingRuns.size(); r += 2) kept += pendingRuns[r];
    return kept;
  }

  [[noreturn]] void damaged(const std::string& why) { throw PartFileError(name + " " + why); }

  void rawRead(void* data, std::size_t bytes) {
    file.read(static_cast<char*>(data), std::streamsize(bytes));
    if (std::size_t(file.gcount()) != bytes) damaged("is truncated: it ends before its header does");
  }

  /// Inflates exactly `bytes` bytes of the stream into `data`.
  void inflateExactly(void* data, std::size_t bytes) {
    z.next_out = static_cast<Bytef*>(data);
    z.avail_out = uInt(bytes);
    while (z.avail_out > 0) {
      if (streamEnded) damaged("is damaged: its data ends early");
      if (z.avail_in == 0) {
        file.read(reinterpret_cast<char*>(in.data()), std::streamsize(in.size()));
        z.next_in = in.data();
        z.avail_in = uInt(file.gcount());
        if (z.avail_in == 0) damaged("is truncated: its data stops in the middle (was its render killed?)");
      }
      const int rc = inflate(&z, Z_NO_FLUSH);
      if (rc == Z_STREAM_END) {
        streamEnded = true;
      } else if (rc != Z_OK && rc != Z_BUF_ERROR) {
        damaged("is damaged: its compressed data does not decode");
      }
    }
    crc = std::uint32_t(crc32_z(crc, static_cast<const Bytef*>(data), bytes));
    streamBytes += bytes;
  }

  template <class T>
  T little() {
    T value;
    inflateExactly(&value, sizeof value);
    return value;
  }
};

RenderPartReader::RenderPartReader(const std::filesystem::path& file) : impl_(std::make_unique<Impl>()) {
  Impl& r = *impl_;
  r.name = file.string();
  r.file.open(file, std::ios::binary);
  if (!r.file) throw PartFileError(r.name + " cannot be opened (is it missing?)");
  char magic[8] = {};
  r.file.read(magic, sizeof magic);
  if (r.file.gcount() != sizeof magic || std::memcmp(magic, kMagic, sizeof kMagic) != 0)
    r.damaged("is not a GridIFS render part (it does not start with GRIDPART)");
  std::uint32_t version = 0, length = 0, crc = 0;
  r.rawRead(&version, 4);
  r.version = version;
  if (version != kRenderPartVersion && version != 1)
    r.damaged("is a render part of format version " + std::to_string(version) + ", but this gridifs reads version " +
              std::to_string(kRenderPartVersion));
  r.rawRead(&length, 4);
  if (length > kMaxHeaderBytes) r.damaged("is damaged: its header length is absurd");
  std::string json(length, '\0');
  r.rawRead(json.data(), length);
  r.rawRead(&crc, 4);
  if (crc != std::uint32_t(crc32_z(0, reinterpret_cast<const Bytef*>(json.data()), json.size())))
    r.damaged("is damaged: its header fails its checksum");
  r.header = parseHeader(json, r.name);
  if (inflateInit(&r.z) != Z_OK) r.damaged("cannot be read: zlib failed to start");
  r.zOpen = true;
  r.in.resize(1 << 16);
}

RenderPartReader::~RenderPartReader() {
  if (impl_->zOpen) inflateEnd(&impl_->z);
}

const RenderPartHeader& RenderPartReader::header() const { return impl_->header; }

std::size_t RenderPartReader::nextBuffer(const std::string& name, std::size_t elementSize, std::size_t maxCount) {
  Impl& r = *impl_;
  const auto nameLength = r.little<std::uint32_t>();
  if (nameLength == 0 || nameLength > kMaxNameBytes) r.damaged("is damaged: the buffer \"" + name + "\" is missing");
  std::string got(nameLength, '\0');
  r.inflateExactly(got.data(), nameLength);
  const auto size = r.little<std::uint32_t>();
  const auto count = r.little<std::uint64_t>();
  if (got != name || size != elementSize)
    r.damaged("is damaged: it has the buffer \"" + got + "\" where \"" + name + "\" belongs");
  if (count > maxCount) r.damaged("is damaged: the buffer \"" + name + "\" is larger than the render");
  r.readRuns(count);
  r.pendingSize = size;
  r.pendingCount = std::size_t(count);
  return std::size_t(count);
}

void RenderPartReader::readElements(void* data, std::size_t elementSize, std::size_t count) {
  Impl& r = *impl_;
  auto* bytes = static_cast<std::uint8_t*>(data);
  if (r.version < 2) {
    for (std::size_t at = 0; at < count; at += kBlockElements) {
      const std::size_t n = std::min(kBlockElements, count - at);
      r.scratch.resize(n * elementSize);
      r.inflateExactly(r.scratch.data(), r.scratch.size());
      unshuffle(r.scratch.data(), bytes + at * elementSize, elementSize, n);
    }
    return;
  }
  // The stored elements come a block at a time; each lands in its run, the rest is the fill.
  std::vector<std::uint8_t> block;
  std::size_t blockAt = 0, blockCount = 0;
  std::uint64_t left = r.storedElements(count);
  std::size_t at = 0;
  for (std::size_t k = 0; k < r.pendingRuns.size(); k += 2) {
    std::memset(bytes + at * elementSize, r.pendingFill, std::size_t(r.pendingRuns[k]) * elementSize);
    at += r.pendingRuns[k];
    for (std::uint32_t take = r.pendingRuns[k + 1]; take > 0;) {
      if (blockAt == blockCount) {
        blockCount = std::size_t(std::min<std::uint64_t>(kBlockElements, left));
        if (blockCount == 0) r.damaged("is damaged: a buffer's runs ask for more elements than it stores");
        left -= blockCount;
        r.scratch.resize(blockCount * elementSize);
        block.resize(blockCount * elementSize);
        r.inflateExactly(r.scratch.data(), r.scratch.size());
        unshuffle(r.scratch.data(), block.data(), elementSize, blockCount);
        blockAt = 0;
      }
      const std::size_t n = std::min<std::size_t>(take, blockCount - blockAt);
      std::memcpy(bytes + at * elementSize, block.data() + blockAt * elementSize, n * elementSize);
      at += n;
      blockAt += n;
      take -= std::uint32_t(n);
    }
  }
}

void RenderPartReader::finish() {
  Impl& r = *impl_;
  if (!r.endRecordRead && r.little<std::uint32_t>() != 0)
    r.damaged("is damaged: it has more buffers than a render part of its kind");
  // The end of the zlib stream: inflate until it says so (no more output is expected).
  std::uint8_t extra = 0;
  while (!r.streamEnded) {
    if (r.z.avail_in == 0) {
      r.file.read(reinterpret_cast<char*>(r.in.data()), std::streamsize(r.in.size()));
      r.z.next_in = r.in.data();
      r.z.avail_in = uInt(r.file.gcount());
      if (r.z.avail_in == 0) r.damaged("is truncated: its data stops before its end");
    }
    r.z.next_out = &extra;
    r.z.avail_out = 1;
    const int rc = inflate(&r.z, Z_NO_FLUSH);
    if (rc == Z_STREAM_END && r.z.avail_out == 1)
      r.streamEnded = true;
    else if (rc != Z_OK && rc != Z_BUF_ERROR)
      r.damaged("is damaged: its compressed data does not decode");
    else if (r.z.avail_out == 0)
      r.damaged("is damaged: it has data after its last buffer");
  }
  // The trailer: what inflate left of the last read, then the rest of the file.
  std::string rest(reinterpret_cast<const char*>(r.z.next_in), r.z.avail_in);
  char more[64];
  while (r.file.read(more, sizeof more) || r.file.gcount() > 0) {
    rest.append(more, std::size_t(r.file.gcount()));
    if (rest.size() > 20) break;
  }
  if (rest.size() != 20 || std::memcmp(rest.data() + 12, kEndMagic, sizeof kEndMagic) != 0)
    r.damaged(rest.size() < 20 ? "is truncated: its trailer is missing" : "is damaged: it has bytes after its end");
  std::uint64_t length = 0;
  std::uint32_t crc = 0;
  std::memcpy(&length, rest.data(), 8);
  std::memcpy(&crc, rest.data() + 8, 4);
  if (length != r.streamBytes || crc != r.crc) r.damaged("is damaged: its data fails its checksum");
}

void RenderPartReader::skipRest() {
  Impl& r = *impl_;
  for (;;) {
    const auto nameLength = r.little<std::uint32_t>();
    if (nameLength == 0) break;
    if (nameLength > kMaxNameBytes) r.damaged("is damaged: a buffer's name is absurdly long");
    std::string got(nameLength, '\0');
    r.inflateExactly(got.data(), nameLength);
    const auto size = r.little<std::uint32_t>();
    const auto count = r.little<std::uint64_t>();
    if (size == 0 || size > 64 || count > (std::uint64_t(1) << 36)) r.damaged("is damaged: a buffer's size is absurd");
    r.readRuns(count);
    const std::uint64_t stored = r.storedElements(count);
    for (std::uint64_t at = 0; at < stored; at += kBlockElements) {
      r.scratch.resize(std::size_t(std::min<std::uint64_t>(kBlockElements, stored - at)) * size);
      r.inflateExactly(r.scratch.data(), r.scratch.size());
    }
  }
  r.endRecordRead = true;
  finish();
}

RenderPartHeader verifyRenderPart(const std::filesystem::path& file) {
  RenderPartReader reader(file);
  reader.skipRest();
  return reader.header();
}

void RenderPartReader::checkTrailerOnly() {
  Impl& r = *impl_;
  // Parts are renamed into place once written whole, so a part with its header and its trailer
  // is one a render finished; only its checksum (merge's business) needs the data read.
  const std::streamoff headerEnd = r.file.tellg();
  r.file.seekg(0, std::ios::end);
  const std::streamoff size = r.file.tellg();
  if (size < headerEnd + 20) r.damaged("is truncated: its trailer is missing");
  char trailer[20];
  r.file.seekg(size - 20);
  r.rawRead(trailer, sizeof trailer);
  if (std::memcmp(trailer + 12, kEndMagic, sizeof kEndMagic) != 0) r.damaged("is truncated: its trailer is missing");
}

RenderPartHeader inspectRenderPart(const std::filesystem::path& file) {
  RenderPartReader reader(file);
  reader.checkTrailerOnly();
  return reader.header();
}

}  // namespace gridifs
