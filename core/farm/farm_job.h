#pragma once
// A render farm job on Slurm: the folder, batch scripts and bookkeeping for one render split into
// parts (gridifs render --part K/N) over frames, merged per frame (gridifs merge), and optionally
// assembled into a video. Slurm schedules, retries and tracks the tasks; this module only writes
// the job folder, decides which tasks still have work (a part that is missing or fails its
// checks), submits with sbatch and reads back what happened (docs/FARM.md).
//
// The job folder:
//   farm.json         the request (project, output, frames, parts, options) and its digest
//   render.sbatch     the render job array: task T renders part T mod N of frame index T div N
//   merge.sbatch      the merge job array: task F merges frame index F's parts
//   video.sbatch      with a video: assembles the merged frames
//   parts/            the part files, f<frame>_p<K>.gpart (s_p<K>.gpart for a still)
//   failed/           task_<T>: the exit code of a render task that failed
//   merged/           f<frame>: written by a merge task that succeeded
//   logs/             Slurm's output files
//   jobs              the ids of every job submitted for this folder, one per line
//
// Thread-safety: none needed; every function works on the folder it is given. Errors: FarmError
// (one sentence naming the folder or file) for bad requests and unusable folders.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gridifs {

struct FarmError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// What to render, as given to `gridifs farm` (or the modeller's Render animation dialog).
struct FarmRequest {
  std::filesystem::path project;                      // the .gridifs file
  std::string output;                                 // the image, or a printf pattern with frames
  std::optional<std::int64_t> firstFrame, lastFrame;  // both or neither
  std::int64_t parts = 1;
  std::filesystem::path dir;
  std::vector<std::string> renderOptions;  // given to every `gridifs render --part` (size, samples, mode, ...)
  std::vector<std::string> mergeOptions;   // given to every `gridifs merge` (--bit-depth, --transparent)
  std::optional<std::string> video;        // assembled from the frames by the video job
  std::vector<std::string> sbatchOptions;  // #SBATCH lines of every script (GPU requests: render only)
  std::filesystem::path executable;        // the gridifs that the tasks run
};

/// One frame's state in a job folder.
struct FarmFrame {
  std::int64_t frame = 0;      // the frame number (0 for a still)
  std::int64_t partsDone = 0;  // parts present and valid
  std::vector<std::int64_t> missingParts;
  std::vector<std::string> failedTasks;  // "task 7 (part 3): exit 1" from the failure records
  bool merged = false;                   // the merge task succeeded and the output exists
};

struct FarmStatus {
  FarmRequest request;
  std::vector<FarmFrame> frames;
  bool videoDone = false;
  /// Jobs of this folder that Slurm still knows: "1234 RUNNING", "1235 PENDING (DependencyNeverSatisfied)".
  std::vector<std::string> queued;
  bool still() const { return !request.firstFrame; }
};

/// Limits of a request: parts per frame, frames, and tasks in all.
inline constexpr std::int64_t kMaxFarmParts = 10000;
inline constexpr std::int64_t kMaxFarmTasks = 10'000'000;

/// Checks `request`, creates the folder and writes farm.json and the batch scripts. A folder
/// that already holds another request (another project file content, output, frames, parts or
/// options) is refused; the same request again keeps its parts. Throws FarmError.
void writeFarmJob(const FarmRequest& request);

/// How a job folder's parts are checked: their header and trailer only (what a status needs: a
/// part appears only once written whole), or their whole data against its checksum (before
/// planning what to render again, so a part damaged since is rendered anew).
enum class PartCheck { HeaderAndTrailer, WholeData };

/// Reads a job folder: every part checked as `check` says, failures, merges, and what Slurm still
/// has queued (when squeue answers). Throws FarmError when the folder is not a job folder.
FarmStatus readFarmStatus(const std::filesystem::path& dir, bool askSlurm = true,
                          PartCheck check = PartCheck::HeaderAndTrailer);

/// Human-readable lines of a status (gridifs farm --status, the modeller's dialog).
std::vector<std::string> describeFarmStatus(const FarmStatus& status);

/// What a submission would run: render task ids of missing or invalid parts, frames to merge,
/// and whether the video job is needed.
struct FarmPlan {
  std::vector<std::int64_t> renderTasks;
  std::vector<std::int64_t> mergeFrames;  // frame indices (0-based in the frame range)
  bool video = false;
};
FarmPlan planFarm(const FarmStatus& status);

/// Submits `plan` with sbatch (render arrays, then the merge array depending on them with
/// afterok, then the video job on the merges). Refuses while jobs of the folder are still queued
/// or running; cancels earlier merge jobs whose dependency can never be satisfied (a failed or
/// cancelled render). Returns the new job ids with what each is. Throws FarmError.
std::vector<std::string> submitFarm(const std::filesystem::path& dir, const FarmPlan& plan);

/// The sbatch command lines that submitFarm would run (printed without --submit).
std::vector<std::string> farmSubmitCommands(const std::filesystem::path& dir, const FarmPlan& plan);

/// Whether sbatch is on the PATH.
bool slurmAvailable();

/// The part file of (frame index, part) in a job folder.
std::filesystem::path farmPartPath(const FarmRequest& request, std::int64_t frameIndex, std::int64_t part);

/// The request stored in a job folder. Throws FarmError.
FarmRequest readFarmRequest(const std::filesystem::path& dir);

}  // namespace gridifs
