// gridifs merge PART... -o OUT: the parts of one split render (render --part K/N) or volume
// (volume --part K/N), summed exactly in any order and finished into the file `render` (or
// `volume`) writes with the same options. Every part's header is checked before any payload is
// read (missing, duplicated or foreign parts, parts from another device among them, are refused
// at once); the payloads are then streamed one at a time into one running sum, so memory stays at
// two accumulations whatever the number of parts. A damaged or truncated part is refused; nothing
// is written then.
#include <algorithm>
#include <atomic>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

#include "app/cli.h"
#include "app/render_parts.h"
#include "app/render_setup.h"
#include "io/project_io.h"
#include "volume/vdb_volume_file.h"

namespace gridifs::cli {
namespace {

struct MergeArgs {
  std::vector<std::string> parts;
  std::string out;
  std::optional<int> bitDepth;
  bool transparent = false;
};

/// "a.gpart, b.gpart and c.gpart"
std::string listOf(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : (i + 1 == names.size() ? " and " : ", ")) + names[i];
  return out;
}

std::string describeMissing(const std::vector<std::int64_t>& missing) {
  std::string out;
  const std::size_t shown = std::min<std::size_t>(missing.size(), 8);
  for (std::size_t i = 0; i < shown; ++i) out += (i ? ", " : "") + std::to_string(missing[i]);
  if (missing.size() > shown) out += " and " + std::to_string(missing.size() - shown) + " more";
  return out;
}

/// Reads every header and checks that the parts are exactly parts 0..N-1 of one render.
RenderPartHeader checkHeaders(const std::vector<std::string>& files) {
  std::vector<RenderPartHeader> headers;
  for (const std::string& f : files) {
    try {
      headers.push_back(RenderPartReader(f).header());
    } catch (const PartFileError& e) {
      throw CliError(kBadInput, std::string(e.what()) + "; nothing was merged");
    }
  }
  auto renderOf = [](const RenderPartHeader& h) {
    return h.kind + '\n' + h.digest + '\n' + std::to_string(h.parts) + '\n' +
           (h.frame ? std::to_string(*h.frame) : std::string("-"));
  };
  // The render is the one most of the files belong to (the first of equals), so that a foreign
  // part given first is the one named, not every other part.
  std::map<std::string, std::size_t> filesOf;
  for (const RenderPartHeader& h : headers) ++filesOf[renderOf(h)];
  std::size_t reference = 0;
  for (std::size_t i = 1; i < headers.size(); ++i)
    if (filesOf[renderOf(headers[i])] > filesOf[renderOf(headers[reference])]) reference = i;
  const RenderPartHeader& first = headers[reference];
  const std::string render = renderOf(first);
  // Another device is foreign too (the digest covers it), but said apart: the parts may be of the
  // same project and options, and the fix is to render them on one device. The CPU plays chunks
  // and a GPU plays its chains, each from other random streams (and 32-bit GPU keys quantise
  // depth), so their accumulations are of different, if equally valid, images and do not sum to
  // either.
  std::map<std::string, std::vector<std::string>> byDevice;  // the parts not from first.device
  for (std::size_t i = 0; i < headers.size(); ++i)
    if (headers[i].device != first.device) byDevice[headers[i].device].push_back(files[i]);
  if (!byDevice.empty()) {
    std::string others;
    for (const auto& [device, names] : byDevice)
      others += (others.empty() ? "" : ", ") + listOf(names) + " on " + device;
    throw CliError(kBadInput, files[reference] + " was rendered on " + first.device + " but " + others +
                                  "; the CPU and each GPU draw different samples, so all parts of a render must "
                                  "come from one device (--device); nothing was merged");
  }
  std::vector<std::string> foreign;
  std::map<std::int64_t, std::vector<std::string>> byPart;
  for (std::size_t i = 0; i < headers.size(); ++i) {
    if (renderOf(headers[i]) != render)
      foreign.push_back(files[i]);
    else
      byPart[headers[i].part].push_back(files[i]);
  }
  if (!foreign.empty())
    throw CliError(kBadInput, listOf(foreign) + (foreign.size() == 1 ? " belongs" : " belong") +
                                  " to another render than " + files[reference] +
                                  " (another project, options, frame or part count); nothing was merged");
  for (const auto& [k, names] : byPart)
    if (names.size() > 1) {
      // One file named twice reads "a.gpart is given 2 times", not "a.gpart and a.gpart are ...".
      std::vector<std::string> distinct = names;
      std::sort(distinct.begin(), distinct.end());
      distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
      const std::string what = " part " + std::to_string(k) + " of " + std::to_string(first.parts);
      if (distinct.size() == 1)
        throw CliError(kBadInput, names.front() + " is given " + std::to_string(names.size()) + " times (it is" + what +
                                      "); nothing was merged");
      throw CliError(kBadInput, listOf(names) + " are the same" + what + "; nothing was merged");
    }
  std::vector<std::int64_t> missing;
  for (std::int64_t k = 0; k < first.parts; ++k)
    if (!byPart.count(k)) missing.push_back(k);
  if (!missing.empty())
    throw CliError(kBadInput, "part" + std::string(missing.size() == 1 ? " " : "s ") + describeMissing(missing) +
                                  " of " + std::to_string(first.parts) + " of " + first.source +
                                  (missing.size() == 1 ? " is" : " are") + " missing; nothing was merged");
  return first;
}

Project embeddedProject(const RenderPartHeader& header, const std::string& file) {
  try {
    return parseProject(header.project);
  } catch (const std::exception& e) {
    throw CliError(kBadInput, file + " is damaged: its project does not load (" + std::string(e.what()) + ")");
  }
}

int runMerge(const MergeArgs& a) {
  const RenderPartHeader header = checkHeaders(a.parts);
  const bool volume = header.kind == "volume";
  if (volume) {
    checkOutputPath(a.out, {"vdb"}, "a merged volume");
    if (a.bitDepth || a.transparent) throw CliError(kBadInput, "--bit-depth and --transparent apply to images only");
    try {
      requireVdbVolumeWriter();
    } catch (const IoError& e) {
      throw CliError(kFailure, e.what());
    }
  } else {
    checkOutputPath(a.out, {"png", "exr", "tif", "tiff"}, "a merged image");
  }
  const Project project = embeddedProject(header, a.parts.front());
  // What the command line says of part `file` when reading or adding it threw.
  const auto failure = [](const std::string& file, std::exception_ptr error) {
    try {
      std::rethrow_exception(error);
    } catch (const PartFileError& e) {
      const std::string why = e.what();
      // Buffer-level messages do not name the file; the reader's own ones start with it.
      return (why.rfind(file, 0) == 0 ? why : file + " is damaged: " + why) + "; nothing was merged";
    } catch (const std::invalid_argument& e) {
      return file + " does not match the other parts: " + e.what() + "; nothing was merged";
    }
  };
  std::vector<Accumulation> sums;
  VoxelAccumulation voxels;
  for (std::size_t i = 0; i < a.parts.size() && (volume || i == 0); ++i) {
    try {
      RenderPartReader reader(a.parts[i]);
      if (volume)
        addVolumePart(reader, voxels, i == 0);
      else
        readImagePart(reader, sums);  // the first part starts the sums
      reader.finish();
    } catch (const std::exception&) {
      throw CliError(kBadInput, failure(a.parts[i], std::current_exception()));
    }
  }
  if (!volume && a.parts.size() > 1) {
    // The other parts are read on several threads at once (reading is inflating their data:
    // nearly all of a merge's time) and added under a lock. Additions and minima: the order in
    // which parts arrive never changes a byte. Every part is read, so a failure names the first
    // failing part in order, whichever thread met it.
    std::mutex lock;
    std::atomic<std::size_t> next{1};
    std::size_t failedPart = a.parts.size();
    std::exception_ptr failedWith;
    const auto work = [&] {
      std::vector<Accumulation> part;  // buffers reused from part to part
      for (std::size_t i = next++; i < a.parts.size(); i = next++) {
        try {
          RenderPartReader reader(a.parts[i]);
          readImagePart(reader, part);
          reader.finish();
          const std::lock_guard<std::mutex> held(lock);
          addImageParts(sums, part);
        } catch (const std::exception&) {
          const std::lock_guard<std::mutex> held(lock);
          if (i < failedPart) failedPart = i, failedWith = std::current_exception();
        }
      }
    };
    const std::size_t threads =
        std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, std::min<std::size_t>(8, a.parts.size() - 1));
    std::vector<std::thread> helpers;
    for (std::size_t t = 1; t < threads; ++t) helpers.emplace_back(work);
    work();
    for (std::thread& h : helpers) h.join();
    if (failedWith) throw CliError(kBadInput, failure(a.parts[failedPart], failedWith));
  }
  if (!volume) return finishMergedFrame(project, header.source, a.out, header.options, sums, a.bitDepth, a.transparent);
  VolumeJob job;
  job.settings = project.volume.value_or(VolumeSettings{});
  DensityVolume density;
  try {
    density = developVoxels(project, job, voxels);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, header.source + ": " + e.what());
  }
  if (density.totalMass <= 0.0)
    throw CliError(kFailure, header.source + ": no point of the attractor fell inside X, so the volume is empty");
  try {
    writeVdbVolume(density, a.out);
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  }
  return kSuccess;
}

const VerbRegistration kMerge{
    {"merge",
     "PART... -o OUT.(png|exr|tif|vdb) [--bit-depth B --transparent]: sum the parts of a split render "
     "(render/volume --part K/N) into the image or volume the whole render makes",
     [](CLI::App& app) {
       auto a = std::make_shared<MergeArgs>();
       app.add_option("PART", a->parts, "the part files (.gpart) of one render, all N of them, in any order")
           ->required();
       app.add_option("-o,--output", a->out, "the image (.png, .tif, .exr) or, for volume parts, the volume (.vdb)")
           ->required();
       app.add_option("--bit-depth", a->bitDepth, "flame parts: 8 or 16 bits for PNG/TIFF, 16 or 32 for EXR");
       app.add_flag("--transparent", a->transparent, "flame parts: PNG/TIFF with alpha instead of the background");
       return [a] { return runMerge(*a); };
     },
     /*hugePageHeap=*/true}};

}  // namespace
}  // namespace gridifs::cli
