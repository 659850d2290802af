// Split renders underneath the command line (docs/FARM.md): the sample budget's chunks and how
// parts share them (render/sample_chunks.h), the undeveloped buffers and their exact sum
// (render/accumulation.h), the renderer's accumulation for any thread count and any split, and the
// part file (io/render_part_file.h): a round trip, and truncation found wherever it cuts.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/project_io.h"
#include "io/render_part_file.h"
#include "render/accumulation.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "render/sample_chunks.h"
#include "render/shaded_image.h"
#include "tone/palette.h"

namespace gridifs {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Chunks.

TEST(SampleChunks, CountsAndSizes) {
  EXPECT_EQ(chunkCount(0), 0);
  EXPECT_EQ(chunkCount(-5), 0);
  EXPECT_EQ(chunkCount(1), 1);
  EXPECT_EQ(chunkCount(kChunkSamples), 1);
  EXPECT_EQ(chunkCount(kChunkSamples + 1), 2);
  EXPECT_EQ(chunkCount(1'000'000), 16);  // 15 full chunks and 16960 samples
  EXPECT_EQ(chunkCount(limits::kMaxRenderSamples), (limits::kMaxRenderSamples + kChunkSamples - 1) / kChunkSamples);

  EXPECT_EQ(chunkSize(1'000'000, 0), kChunkSamples);
  EXPECT_EQ(chunkSize(1'000'000, 14), kChunkSamples);
  EXPECT_EQ(chunkSize(1'000'000, 15), 1'000'000 - 15 * kChunkSamples);
  EXPECT_EQ(chunkSize(1'000'000, 16), 0);
  EXPECT_EQ(chunkSize(1'000'000, 1000), 0);
  EXPECT_EQ(chunkSize(3 * kChunkSamples, 2), kChunkSamples) << "a budget of whole chunks has no short chunk";
  EXPECT_EQ(chunkSize(1, 0), 1);

  for (const std::int64_t samples : {std::int64_t(1), std::int64_t(65535), std::int64_t(65536), std::int64_t(65537),
                                     std::int64_t(1'000'000), std::int64_t(20'000'000), std::int64_t(123'456'789)}) {
    SCOPED_TRACE(samples);
    const std::int64_t chunks = chunkCount(samples);
    std::int64_t total = 0;
    for (std::int64_t c = 0; c < chunks; ++c) {
      EXPECT_GT(chunkSize(samples, c), 0);
      total += chunkSize(samples, c);
    }
    EXPECT_EQ(total, samples);
    EXPECT_EQ(rangeSamples(samples, {0, chunks}), samples);
    EXPECT_EQ(rangeSamples(samples, {0, chunks + 10}), samples) << "chunks past the budget hold nothing";
    EXPECT_EQ(rangeSamples(samples, {3, 3}), 0);
    EXPECT_EQ(rangeSamples(samples, {5, 2}), 0) << "an inverted range is empty";
    // Any cut into two ranges adds up.
    for (std::int64_t cut = 0; cut <= chunks; cut += std::max<std::int64_t>(1, chunks / 7))
      EXPECT_EQ(rangeSamples(samples, {0, cut}) + rangeSamples(samples, {cut, chunks}), samples);
    for (std::int64_t c = 0; c < chunks; c += std::max<std::int64_t>(1, chunks / 5))
      EXPECT_EQ(rangeSamples(samples, {c, c + 1}), chunkSize(samples, c));
    EXPECT_EQ(chunksOf(samples, nullptr), (ChunkRange{0, chunks}));
  }
}

TEST(SampleChunks, PartsCoverEveryChunkExactlyOnceAndDifferByAtMostOne) {
  std::vector<std::int64_t> chunkCounts = {0, 1, 2, 3, 5, 7, 15, 16, 17, 64, 100, 999, 65537};
  chunkCounts.push_back(chunkCount(limits::kMaxRenderSamples));  // 1525879: K·C needs more than 32 bits
  chunkCounts.push_back(std::int64_t(1) << 40);                  // K·C needs more than 64 bits at N = 10^5
  for (const std::int64_t chunks : chunkCounts)
    for (const std::int64_t parts : {1, 2, 3, 4, 7, 10, 16, 33, 100, 1000, 100000}) {
      SCOPED_TRACE("C = " + std::to_string(chunks) + ", N = " + std::to_string(parts));
      std::int64_t expectedBegin = 0, smallest = chunks + 1, largest = -1;
      for (std::int64_t k = 0; k < parts; ++k) {
        const ChunkRange r = partChunks(chunks, k, parts);
        ASSERT_EQ(r.begin, expectedBegin) << "part " << k << " starts where part " << k - 1 << " ends";
        ASSERT_GE(r.end, r.begin) << "part " << k;
        expectedBegin = r.end;
        smallest = std::min(smallest, r.size());
        largest = std::max(largest, r.size());
      }
      EXPECT_EQ(expectedBegin, chunks) << "the last part ends at the last chunk";
      EXPECT_LE(largest - smallest, 1);
      EXPECT_EQ(smallest, chunks / parts);
    }
}

TEST(SampleChunks, ThePartsOfABudgetAddUpToIt) {
  for (const std::int64_t samples : {std::int64_t(100'000), std::int64_t(1'000'000), std::int64_t(7 * kChunkSamples)})
    for (const std::int64_t parts : {1, 2, 3, 7, 16, 40}) {
      std::int64_t total = 0;
      for (std::int64_t k = 0; k < parts; ++k) {
        const RenderPart part{k, parts};
        total += rangeSamples(samples, chunksOf(samples, &part));
      }
      EXPECT_EQ(total, samples) << samples << " samples in " << parts << " parts";
    }
}

// ---------------------------------------------------------------------------------------------
// Accumulation::add.

constexpr std::uint64_t kNoKey = ~std::uint64_t(0);

/// A 3×2 accumulation with colour sums and one shadowed light, filled from `seed`.
Accumulation smallAccumulation(std::uint32_t seed) {
  std::mt19937_64 rng(seed);
  Accumulation a;
  a.width = 3;
  a.height = 2;
  for (int i = 0; i < 6; ++i) {
    a.keys.push_back(rng() % 3 == 0 ? kNoKey : rng() >> 8);
    a.density.push_back(std::uint32_t(rng() % 1000));
    for (int c = 0; c < 4; ++c) a.colorSums.push_back(rng() % (std::uint64_t(1) << 40));
  }
  a.lightViews.push_back(LightView({0.3, -1.0, 0.2}, BoundingSphere{{0.0, 0.0, 0.0}, 1.5}, 16));
  a.lightDepth.emplace_back(16 * 16);
  for (auto& d : a.lightDepth[0]) d = rng() % 5 == 0 ? std::uint16_t(0xFFFF) : std::uint16_t(rng() % 60000);
  a.samples = std::int64_t(rng() % 100000);
  a.badSamples = std::int64_t(rng() % 10);
  a.plotted = std::int64_t(rng() % 100000);
  return a;
}

void expectSameAccumulation(const Accumulation& a, const Accumulation& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_TRUE(a.keys == b.keys) << "z-buffer keys";
  EXPECT_TRUE(a.keys32 == b.keys32) << "32-bit keys";
  EXPECT_EQ(a.depthMin, b.depthMin);
  EXPECT_EQ(a.depthScale, b.depthScale);
  EXPECT_TRUE(a.density == b.density) << "hit counts";
  EXPECT_TRUE(a.colorSums == b.colorSums) << "colour sums";
  EXPECT_TRUE(a.lightViews == b.lightViews) << "light views";
  EXPECT_TRUE(a.lightDepth == b.lightDepth) << "light depths";
  EXPECT_EQ(a.samples, b.samples);
  EXPECT_EQ(a.badSamples, b.badSamples);
  EXPECT_EQ(a.plotted, b.plotted);
}

TEST(AccumulationAdd, KeysAndLightDepthsByMinimumCountsAndSumsByAddition) {
  const Accumulation a = smallAccumulation(1), b = smallAccumulation(2);
  Accumulation sum = a;
  sum.add(b);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(sum.keys[i], std::min(a.keys[i], b.keys[i]));
    EXPECT_EQ(sum.density[i], a.density[i] + b.density[i]);
    for (std::size_t c = 0; c < 4; ++c)
      EXPECT_EQ(sum.colorSums[4 * i + c], a.colorSums[4 * i + c] + b.colorSums[4 * i + c]);
  }
  for (std::size_t i = 0; i < a.lightDepth[0].size(); ++i)
    EXPECT_EQ(sum.lightDepth[0][i], std::min(a.lightDepth[0][i], b.lightDepth[0][i]));
  EXPECT_EQ(sum.samples, a.samples + b.samples);
  EXPECT_EQ(sum.badSamples, a.badSamples + b.badSamples);
  EXPECT_EQ(sum.plotted, a.plotted + b.plotted);
  EXPECT_TRUE(sum.lightViews == a.lightViews);
  // An empty pixel (no key) takes the other's key; two empty pixels stay empty.
  Accumulation empty = a;
  std::fill(empty.keys.begin(), empty.keys.end(), kNoKey);
  Accumulation filled = empty;
  filled.add(a);
  EXPECT_TRUE(filled.keys == a.keys);
  Accumulation none = empty;
  none.add(empty);
  EXPECT_TRUE(std::all_of(none.keys.begin(), none.keys.end(), [](std::uint64_t k) { return k == kNoKey; }));
}

TEST(AccumulationAdd, HitCountsSaturateAsThePlottersDo) {
  Accumulation a = smallAccumulation(3), b = smallAccumulation(4);
  a.density = {0xFFFFFFF0u, 0xFFFFFFFFu, 0x80000000u, 7, 0, 0xFFFFFFFFu};
  b.density = {0x20u, 1, 0x80000000u, 9, 0, 0xFFFFFFFFu};
  a.add(b);
  EXPECT_EQ(a.density, (std::vector<std::uint32_t>{0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, 16, 0, 0xFFFFFFFFu}));
}

TEST(AccumulationAdd, TheOrderOfAddingDoesNotMatter) {
  const Accumulation a = smallAccumulation(5), b = smallAccumulation(6), c = smallAccumulation(7);
  Accumulation abc = a;
  abc.add(b);
  abc.add(c);
  Accumulation cba = c;
  cba.add(b);
  cba.add(a);
  Accumulation bc = b;
  bc.add(c);
  Accumulation aBc = a;
  aBc.add(bc);
  expectSameAccumulation(abc, cba);
  expectSameAccumulation(abc, aBc);
}

TEST(AccumulationAdd, MismatchesAreRefusedWithAReason) {
  const Accumulation a = smallAccumulation(8);
  auto refused = [&](Accumulation other, const std::string& words) {
    SCOPED_TRACE(words);
    const std::string why = a.mismatch(other);
    EXPECT_NE(why.find(words), std::string::npos) << why;
    Accumulation target = a;
    try {
      target.add(other);
      ADD_FAILURE() << "add() took a mismatched accumulation";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), why);
    }
    expectSameAccumulation(target, a);  // untouched
  };
  EXPECT_EQ(a.mismatch(smallAccumulation(9)), "");

  Accumulation wider = smallAccumulation(9);
  wider.width = 4;
  wider.height = 1;
  wider.keys.resize(4);
  refused(wider, "4×1");
  refused(wider, "3×2");
  Accumulation keys32 = smallAccumulation(9);
  keys32.keys.clear();
  keys32.keys32.assign(6, 0xFFFFFFFFu);
  refused(keys32, "key forms");
  Accumulation noColour = smallAccumulation(9);
  noColour.colorSums.clear();
  refused(noColour, "colour sums");
  Accumulation otherLight = smallAccumulation(9);
  otherLight.lightViews[0] = LightView({1.0, 0.0, 0.0}, BoundingSphere{{0.0, 0.0, 0.0}, 1.5}, 16);
  refused(otherLight, "lights");
  Accumulation noLight = smallAccumulation(9);
  noLight.lightViews.clear();
  noLight.lightDepth.clear();
  refused(noLight, "lights");

  // 32-bit keys: the depth quantisation must agree.
  Accumulation q1 = a, q2 = a;
  for (Accumulation* q : {&q1, &q2}) {
    q->keys.clear();
    q->keys32.assign(6, 0xFFFFFFFFu);
    q->depthMin = 1.0f;
    q->depthScale = 100.0f;
  }
  q2.depthScale = 101.0f;
  const std::string why = q1.mismatch(q2);
  EXPECT_NE(why.find("quantize depth"), std::string::npos) << why;
  EXPECT_THROW(q1.add(q2), std::invalid_argument);
  q2.depthScale = 100.0f;
  q2.keys32[2] = 5;
  q1.add(q2);
  EXPECT_EQ(q1.keys32[2], 5u);
}

// ---------------------------------------------------------------------------------------------
// The renderer: the same accumulation for any thread count and any split.

struct Scene {
  std::shared_ptr<const CompiledIfs> ifs;
  RenderJob job;
};

/// A z-buffer job, a flame job (palette colour sums) and a shaded one (a shadowed light's depth
/// buffer, depth of field with its own lens streams, colour sums): every buffer a part stores.
/// 600 000 samples: 10 chunks, the last one short.
Scene sceneFor(const std::string& kind) {
  const std::string file = kind == "shaded" ? "/shaded_tetrahedron.gridifs" : "/twisted_functions.gridifs";
  const Project p = loadProject(std::string(GRIDIFS_ASSETS) + file);
  Scene s;
  s.ifs = compileIfs(p);
  s.job = RenderJob::fromProject(p, 1);
  s.job.width = 96;
  s.job.height = 72;
  s.job.samples = 600'000;
  if (kind != "zbuffer") {
    s.job.accumulateColor = true;
    s.job.palette = std::make_shared<const Palette>(builtinPalette("ember"));
  }
  if (kind == "shaded") {
    s.job = shadedRenderJob(s.job, p.render.shading, *s.ifs);
    s.job.dofAperture = 0.04;
    s.job.dofFocus = p.camera.distance;
  }
  return s;
}

TEST(RenderDeterminism, OneAndFourThreadsGiveTheSameAccumulation) {
  for (const std::string kind : {"zbuffer", "flame", "shaded"}) {
    SCOPED_TRACE(kind);
    Scene s = sceneFor(kind);
    s.job.threads = 1;
    const Accumulation one = accumulateToCompletion(s.ifs, s.job);
    s.job.threads = 4;
    const Accumulation four = accumulateToCompletion(s.ifs, s.job);
    expectSameAccumulation(one, four);
    // Not vacuous: points were plotted into every buffer the job has.
    EXPECT_EQ(one.samples, 600'000);
    EXPECT_GT(one.plotted, 100'000);
    EXPECT_GT(std::count_if(one.keys.begin(), one.keys.end(), [](std::uint64_t k) { return k != kNoKey; }), 500);
    EXPECT_EQ(one.colorSums.empty(), kind == "zbuffer");
    if (kind == "shaded") {
      ASSERT_FALSE(one.lightDepth.empty());
      EXPECT_GT(std::count_if(one.lightDepth[0].begin(), one.lightDepth[0].end(),
                              [](std::uint16_t d) { return d != 0xFFFF; }),
                100);
    }
  }
}

TEST(RenderDeterminism, AFlameJobWithoutKeysCountsAndSumsAsOneWithThem) {
  Scene s = sceneFor("flame");
  s.job.threads = 2;
  const Accumulation withKeys = accumulateToCompletion(s.ifs, s.job);
  s.job.depthKeys = false;  // what the command line's flame renders ask for
  const Accumulation without = accumulateToCompletion(s.ifs, s.job);
  EXPECT_TRUE(without.keys.empty());
  EXPECT_FALSE(withKeys.keys.empty());
  EXPECT_TRUE(without.density == withKeys.density);
  EXPECT_TRUE(without.colorSums == withKeys.colorSums);
  EXPECT_EQ(without.plotted, withKeys.plotted);
  EXPECT_GT(without.plotted, 100'000);
  // And its parts add up to it as the keyed ones do.
  RenderJob part = s.job;
  part.part = RenderPart{1, 2};
  Accumulation sum = accumulateToCompletion(s.ifs, part);
  part.part = RenderPart{0, 2};
  sum.add(accumulateToCompletion(s.ifs, part));
  EXPECT_TRUE(sum.density == without.density);
  EXPECT_TRUE(sum.colorSums == without.colorSums);
  EXPECT_TRUE(sum.keys.empty());
}

TEST(RenderDeterminism, ThePartsOfARenderAddUpToTheWholeRender) {
  for (const std::string kind : {"zbuffer", "flame", "shaded"}) {
    SCOPED_TRACE(kind);
    Scene s = sceneFor(kind);
    s.job.threads = 2;
    const Accumulation whole = accumulateToCompletion(s.ifs, s.job);
    // 40 parts of 10 chunks: most parts have no chunk and add nothing.
    for (const std::int64_t n : {1, 2, 3, 7, 40}) {
      SCOPED_TRACE("N = " + std::to_string(n));
      Accumulation sum;
      std::int64_t emptyParts = 0;
      for (std::int64_t k = n - 1; k >= 0; --k) {  // backwards: the order does not matter
        RenderJob job = s.job;
        job.part = RenderPart{k, n};
        job.threads = int(1 + k % 3);
        const Accumulation part = accumulateToCompletion(s.ifs, job);
        EXPECT_EQ(part.samples, rangeSamples(s.job.samples, partChunks(chunkCount(s.job.samples), k, n)));
        emptyParts += part.samples == 0;
        if (k == n - 1)
          sum = part;
        else
          sum.add(part);
      }
      expectSameAccumulation(whole, sum);
      if (n == 40) {
        EXPECT_EQ(emptyParts, 30);
      }
    }
    // A part is not the whole: the split is real.
    RenderJob half = s.job;
    half.part = RenderPart{0, 2};
    EXPECT_LT(accumulateToCompletion(s.ifs, half).samples, whole.samples);
  }
}

// ---------------------------------------------------------------------------------------------
// The part file.

struct PartFolder {
  fs::path path;
  PartFolder() {
    path = fs::temp_directory_path() / ("gridifs-part-file-" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~PartFolder() { fs::remove_all(path); }
};

RenderPartHeader sampleHeader() {
  RenderPartHeader h;
  h.kind = "image";
  h.digest = renderDigest("a project and its options");
  h.part = 2;
  h.parts = 5;
  h.device = "cpu";
  h.chunkBegin = 6;
  h.chunkEnd = 9;
  h.frame = 12;
  h.source = "folder/plate.gridifs";
  h.project = R"({"format": "gridifs", "version": 1, "functions": []})";
  h.options = R"({"mode": "flame", "motion_blur": 1, "shutter": 0.0})";
  return h;
}

void expectSameHeader(const RenderPartHeader& a, const RenderPartHeader& b) {
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.digest, b.digest);
  EXPECT_EQ(a.part, b.part);
  EXPECT_EQ(a.parts, b.parts);
  EXPECT_EQ(a.device, b.device);
  EXPECT_EQ(a.chunkBegin, b.chunkBegin);
  EXPECT_EQ(a.chunkEnd, b.chunkEnd);
  EXPECT_EQ(a.frame, b.frame);
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.project, b.project);
  EXPECT_EQ(a.options, b.options);
}

TEST(RenderPartFile, RoundTrip) {
  PartFolder dir;
  const fs::path file = dir.path / "p.gpart";
  std::mt19937_64 rng(3);
  // More elements than one shuffle block (65536), so a block boundary is crossed.
  std::vector<std::uint64_t> keys(150'001);
  for (auto& k : keys) k = rng() % 4 == 0 ? kNoKey : rng() >> (rng() % 64);
  std::vector<std::uint32_t> nothing;
  std::vector<std::uint16_t> depths(257);
  for (auto& d : depths) d = std::uint16_t(rng());
  const std::vector<double> view = {0.5, -1.0, 1e-300, -0.0, 3.25};
  const RenderPartHeader header = sampleHeader();
  {
    RenderPartWriter writer(file, header);
    writer.buffer("keys", keys);
    writer.buffer("nothing", nothing);
    writer.buffer("light_depth", depths);
    writer.buffer("view", view);
    EXPECT_FALSE(fs::exists(file)) << "nothing at the target before commit()";
    writer.commit();
  }
  ASSERT_TRUE(fs::exists(file));
  {
    RenderPartReader reader(file);
    expectSameHeader(reader.header(), header);
    std::vector<std::uint64_t> keysBack;
    std::vector<std::uint32_t> nothingBack = {1, 2, 3};
    std::vector<std::uint16_t> depthsBack;
    std::vector<double> viewBack;
    reader.buffer("keys", keysBack, keys.size());
    reader.buffer("nothing", nothingBack, 10);
    reader.buffer("light_depth", depthsBack, depths.size());
    reader.buffer("view", viewBack, 5);
    EXPECT_NO_THROW(reader.finish());
    EXPECT_TRUE(keysBack == keys);
    EXPECT_TRUE(nothingBack.empty()) << "a 0-element buffer reads back empty";
    EXPECT_TRUE(depthsBack == depths);
    ASSERT_EQ(viewBack.size(), view.size());
    EXPECT_EQ(std::memcmp(viewBack.data(), view.data(), view.size() * sizeof(double)), 0) << "bit for bit (-0.0)";
  }
  expectSameHeader(verifyRenderPart(file), header);
  // A header without a frame; a 0-element buffer as the only one.
  RenderPartHeader still = header;
  still.frame.reset();
  {
    RenderPartWriter writer(file, still);
    writer.buffer("nothing", nothing);
    writer.commit();
  }
  RenderPartReader reader(file);
  EXPECT_FALSE(reader.header().frame.has_value());
  std::vector<std::uint32_t> back;
  reader.buffer("nothing", back, 0);
  EXPECT_TRUE(back.empty());
  EXPECT_NO_THROW(reader.finish());
}

TEST(RenderPartFile, AReaderRefusesWhatTheFileDoesNotHold) {
  PartFolder dir;
  const fs::path file = dir.path / "p.gpart";
  const std::vector<std::uint32_t> counts(1000, 7);
  {
    RenderPartWriter writer(file, sampleHeader());
    writer.buffer("density", counts);
    writer.commit();
  }
  std::vector<std::uint32_t> out;
  {
    RenderPartReader reader(file);
    EXPECT_THROW(reader.buffer("keys", out, 1000), PartFileError) << "another name";
  }
  {
    RenderPartReader reader(file);
    std::vector<std::uint64_t> wide;
    EXPECT_THROW(reader.buffer("density", wide, 1000), PartFileError) << "another element size";
  }
  {
    RenderPartReader reader(file);
    EXPECT_THROW(reader.buffer("density", out, 999), PartFileError) << "more elements than the render has";
  }
  {
    RenderPartReader reader(file);
    EXPECT_THROW(reader.finish(), PartFileError) << "a buffer left unread";
  }
  // Bytes after the end.
  std::ofstream(file, std::ios::binary | std::ios::app) << "x";
  EXPECT_THROW(verifyRenderPart(file), PartFileError);
  try {
    verifyRenderPart(file);
  } catch (const PartFileError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << "names the file: " << e.what();
  }
  EXPECT_THROW(verifyRenderPart(dir.path / "missing.gpart"), PartFileError);
}

TEST(RenderPartFile, AWriterThatDoesNotCommitLeavesNothing) {
  PartFolder dir;
  const fs::path file = dir.path / "p.gpart";
  {
    RenderPartWriter writer(file, sampleHeader());
    writer.buffer("density", std::vector<std::uint32_t>(5000, 1));
  }
  EXPECT_TRUE(fs::is_empty(dir.path)) << "neither the part nor its temporary";
}

TEST(RenderPartFile, TruncationIsFoundWhereverItCuts) {
  PartFolder dir;
  const fs::path file = dir.path / "p.gpart";
  std::mt19937_64 rng(9);
  std::vector<std::uint64_t> sums(3000);
  for (auto& s : sums) s = rng() % 100000;
  {
    RenderPartWriter writer(file, sampleHeader());
    writer.buffer("color_sums", sums);
    writer.buffer("density", std::vector<std::uint32_t>(700, 3));
    writer.buffer("nothing", std::vector<std::uint32_t>{});
    writer.commit();
  }
  const std::string bytes = [&] {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }();
  ASSERT_GT(bytes.size(), 2000u);
  EXPECT_NO_THROW(verifyRenderPart(file));
  const fs::path cut = dir.path / "cut.gpart";
  int refused = 0;
  for (std::size_t at = 0; at < bytes.size(); at += 97) {
    std::ofstream(cut, std::ios::binary | std::ios::trunc) << bytes.substr(0, at);
    try {
      verifyRenderPart(cut);
      ADD_FAILURE() << "a part cut at byte " << at << " of " << bytes.size() << " passed";
    } catch (const PartFileError& e) {
      ++refused;
      EXPECT_NE(std::string(e.what()).find(cut.string()), std::string::npos) << e.what();
    }
  }
  // And the last bytes one by one: the trailer.
  for (std::size_t drop = 1; drop <= 21; ++drop) {
    std::ofstream(cut, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() - drop);
    EXPECT_THROW(verifyRenderPart(cut), PartFileError) << "without its last " << drop << " bytes";
  }
  EXPECT_GT(refused, 20);
}

TEST(RenderPartFile, SparseBuffersComeBackWithTheirFill) {
  // Only touched elements are stored: runs of zeros (counts, sums) or of all-ones (empty keys and
  // depths) come back as they were, across blocks, at the buffer's ends, and with element sizes
  // of 2, 4 and 8 bytes; a buffer nothing touched is a few bytes.
  PartFolder dir;
  const fs::path file = dir.path / "sparse.gpart";
  std::mt19937_64 rng(21);
  std::vector<std::uint32_t> counts(200000, 0);
  for (std::size_t i = 0; i < counts.size(); ++i)
    if (rng() % 7 == 0 || (i > 70000 && i < 140000)) counts[i] = std::uint32_t(rng() % 1000 + 1);
  counts.back() = 5;
  std::vector<std::uint64_t> keys(150000, ~std::uint64_t(0));
  for (std::size_t i = 0; i < keys.size(); i += std::size_t(rng() % 50 + 1)) keys[i] = rng();
  keys.front() = 42;
  std::vector<std::uint16_t> depths(9000, 0xFFFF);
  for (std::size_t i = 3000; i < 3100; ++i) depths[i] = std::uint16_t(i);
  const std::vector<std::uint32_t> untouched(1000000, 0);
  {
    RenderPartWriter writer(file, sampleHeader());
    writer.buffer("counts", counts);
    writer.buffer("keys", keys);
    writer.buffer("depths", depths);
    writer.buffer("untouched", untouched);
    writer.commit();
  }
  EXPECT_LT(fs::file_size(file), 700000u) << "a million untouched counts and sparse keys stay small";
  RenderPartReader reader(file);
  std::vector<std::uint32_t> c, u;
  std::vector<std::uint64_t> k;
  std::vector<std::uint16_t> d(5, 7);  // a buffer that held something before is overwritten whole
  reader.buffer("counts", c, counts.size());
  reader.buffer("keys", k, keys.size());
  reader.buffer("depths", d, depths.size());
  reader.buffer("untouched", u, untouched.size());
  reader.finish();
  EXPECT_EQ(c, counts);
  EXPECT_EQ(k, keys);
  EXPECT_EQ(d, depths);
  EXPECT_EQ(u, untouched);
  EXPECT_NO_THROW(verifyRenderPart(file));
}

TEST(RenderPartFile, InspectingReadsTheHeaderAndTrailerOnly) {
  // What a farm status reads of every part: a whole part passes with its header, one cut anywhere
  // (a render killed before its rename could leave no such file, but a copy can) is refused, and
  // damage inside the data is left to the merge's checksum.
  PartFolder dir;
  const fs::path file = dir.path / "p.gpart";
  {
    RenderPartWriter writer(file, sampleHeader());
    writer.buffer("density", std::vector<std::uint32_t>(5000, 7));
    writer.commit();
  }
  const RenderPartHeader h = inspectRenderPart(file);
  EXPECT_EQ(h.part, sampleHeader().part);
  EXPECT_EQ(h.digest, sampleHeader().digest);
  const std::string bytes = [&] {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }();
  const fs::path cut = dir.path / "cut.gpart";
  for (std::size_t at = 0; at < bytes.size(); at += 7) {
    std::ofstream(cut, std::ios::binary | std::ios::trunc) << bytes.substr(0, at);
    EXPECT_THROW(inspectRenderPart(cut), PartFileError) << "cut at byte " << at;
  }
  std::string damaged = bytes;
  damaged[bytes.size() - 30] ^= 0x5A;  // in the compressed data, before the 20-byte trailer
  std::ofstream(cut, std::ios::binary | std::ios::trunc) << damaged;
  EXPECT_NO_THROW(inspectRenderPart(cut));
  EXPECT_THROW(verifyRenderPart(cut), PartFileError);
}

}  // namespace
}  // namespace gridifs
