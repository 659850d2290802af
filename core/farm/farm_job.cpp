#include "farm/farm_job.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/text_format.h"
#include "io/render_part_file.h"

extern char** environ;

namespace gridifs {
namespace {

namespace fs = std::filesystem;

bool isStill(const FarmRequest& r) { return !r.firstFrame; }
std::int64_t frameCount(const FarmRequest& r) { return isStill(r) ? 1 : *r.lastFrame - *r.firstFrame + 1; }
std::int64_t frameAt(const FarmRequest& r, std::int64_t index) { return isStill(r) ? 0 : *r.firstFrame + index; }

/// A word for bash, in single quotes.
std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string readWhole(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

nlohmann::json toJson(const FarmRequest& r) {
  nlohmann::json j = {{"project", r.project.string()},
                      {"output", r.output},
                      {"parts", r.parts},
                      {"render_options", r.renderOptions},
                      {"merge_options", r.mergeOptions},
                      {"sbatch_options", r.sbatchOptions},
                      {"executable", r.executable.string()}};
  j["frames"] = r.firstFrame ? nlohmann::json::array({*r.firstFrame, *r.lastFrame}) : nlohmann::json(nullptr);
  j["video"] = r.video ? nlohmann::json(*r.video) : nlohmann::json(nullptr);
  return j;
}

/// What makes two requests the same render: everything but the folder, the scheduler options and
/// the executable's path, plus the project file's content (an edited project is another render).
std::string requestDigest(const FarmRequest& r) {
  nlohmann::json j = toJson(r);
  j.erase("sbatch_options");
  j.erase("executable");
  return renderDigest(j.dump() + '\n' + readWhole(r.project));
}

/// Runs `argv` and returns its standard output; `status` gets the exit status (-1: it could not run).
std::string capture(const std::vector<std::string>& args, int& status) {
  int pipefd[2];
  if (::pipe(pipefd) != 0) {
    status = -1;
    return "";
  }
  posix_spawn_file_actions_t actions;
  ::posix_spawn_file_actions_init(&actions);
  ::posix_spawn_file_actions_adddup2(&actions, pipefd[1], 1);
  ::posix_spawn_file_actions_addclose(&actions, pipefd[0]);
  ::posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", 0x1 /* O_WRONLY */, 0);
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = ::posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  ::posix_spawn_file_actions_destroy(&actions);
  ::close(pipefd[1]);
  std::string out;
  if (rc == 0) {
    char buffer[4096];
    ssize_t n;
    while ((n = ::read(pipefd[0], buffer, sizeof buffer)) > 0) out.append(buffer, std::size_t(n));
  }
  ::close(pipefd[0]);
  if (rc != 0) {
    status = -1;
    return "";
  }
  int wstatus = 0;
  ::waitpid(pid, &wstatus, 0);
  status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1;
  return out;
}

/// A job submitted for the folder (the `jobs` file: "id kind offset" lines).
struct SubmittedJob {
  std::string id, kind;
  std::int64_t offset = 0;
};

std::vector<SubmittedJob> submittedJobs(const fs::path& dir) {
  std::vector<SubmittedJob> jobs;
  std::ifstream in(dir / "jobs");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    SubmittedJob job;
    if (words >> job.id >> job.kind) {
      words >> job.offset;
      jobs.push_back(job);
    }
  }
  return jobs;
}

/// What Slurm still knows of the folder's jobs (finished ones for MinJobAge, 300 s by default).
struct SlurmView {
  std::vector<std::string> active;                  // "id STATE reason" of jobs pending or running
  std::map<std::int64_t, std::string> failedTasks;  // render task → its state (CANCELLED, FAILED, ...)
};

SlurmView askSlurm(const fs::path& dir) {
  SlurmView view;
  const std::vector<SubmittedJob> jobs = submittedJobs(dir);
  if (jobs.empty()) return view;
  std::string list;
  std::map<std::string, const SubmittedJob*> byId;
  for (const SubmittedJob& job : jobs) {
    list += (list.empty() ? "" : ",") + job.id;
    byId[job.id] = &job;
  }
  int status = 0;
  const std::string out = capture({"squeue", "-h", "--states=all", "-j", list, "-o", "%i %T %r"}, status);
  if (status != 0) return view;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string id, state, reason;
    if (!(words >> id >> state)) continue;
    words >> reason;
    if (state == "PENDING" || state == "RUNNING" || state == "CONFIGURING" || state == "COMPLETING" ||
        state == "SUSPENDED" || state == "REQUEUED" || state == "RESIZING") {
      view.active.push_back(id + " " + state + " " + reason);
      continue;
    }
    if (state == "COMPLETED") continue;
    const auto underscore = id.find('_');
    const auto job = byId.find(id.substr(0, underscore));
    if (underscore == std::string::npos || job == byId.end() || job->second->kind != "render") continue;
    const std::string element = id.substr(underscore + 1);
    if (element.empty() || element.find_first_not_of("0123456789") != std::string::npos) continue;
    view.failedTasks[job->second->offset + std::atoll(element.c_str())] = state;
  }
  return view;
}

std::vector<std::string> queuedJobs(const fs::path& dir) { return askSlurm(dir).active; }

/// "0-3,7,9-11" of sorted ids, less `offset`.
std::string arrayRanges(const std::vector<std::int64_t>& ids, std::int64_t offset) {
  std::string out;
  for (std::size_t i = 0; i < ids.size();) {
    std::size_t j = i;
    while (j + 1 < ids.size() && ids[j + 1] == ids[j] + 1) ++j;
    out += (out.empty() ? "" : ",") + std::to_string(ids[i] - offset);
    if (j > i) out += "-" + std::to_string(ids[j] - offset);
    i = j + 1;
  }
  return out;
}

/// Slurm's largest array index plus one (MaxArraySize; 1001 unless the cluster sets it).
std::int64_t maxArraySize() {
  int status = 0;
  const std::string out = capture({"scontrol", "show", "config"}, status);
  const auto at = out.find("MaxArraySize");
  if (status != 0 || at == std::string::npos) return 1001;
  const auto eq = out.find('=', at);
  const long long v = eq == std::string::npos ? 0 : std::atoll(out.c_str() + eq + 1);
  return v > 1 ? v : 1001;
}

/// sbatch calls for the ids, each array within Slurm's index limit: (array, offset) pairs.
std::vector<std::pair<std::string, std::int64_t>> arraysFor(const std::vector<std::int64_t>& ids, std::int64_t limit) {
  std::map<std::int64_t, std::vector<std::int64_t>> byBlock;
  for (std::int64_t id : ids) byBlock[id / (limit - 1) * (limit - 1)].push_back(id);
  std::vector<std::pair<std::string, std::int64_t>> out;
  for (const auto& [offset, block] : byBlock) out.push_back({arrayRanges(block, offset), offset});
  return out;
}

void writeScript(const fs::path& file, const std::string& text) {
  try {
    writeFileAtomically(file, text);
  } catch (const IoError& e) {
    throw FarmError(e.what());
  }
  fs::permissions(file, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                            fs::perms::others_exec);
}

std::string header(const FarmRequest& r, const std::string& name, const std::string& log, bool gpuOptions) {
  std::string s = "#!/bin/bash\n#SBATCH --job-name=gridifs-" + name +
                  "\n#SBATCH --output=" + (r.dir / "logs" / log).string() + "\n";
  for (const std::string& o : r.sbatchOptions) {
    const bool gpu = o.rfind("--gres", 0) == 0 || o.rfind("--gpus", 0) == 0 || o.rfind("--gpu", 0) == 0;
    if (gpuOptions || !gpu) s += "#SBATCH " + o + "\n";
  }
  return s;
}

std::string renderScript(const FarmRequest& r) {
  std::string s = header(r, "render", "render_%A_%a.out", true);
  s += "# Task T (plus the offset given as $1) renders part T mod N of frame index T div N.\n";
  s += "# Written by gridifs farm; running the farm command again rewrites it.\n";
  s += "set -u\ndir=" + shellQuote(r.dir.string()) + "\nparts=" + std::to_string(r.parts) + "\n";
  s += "task=$(( ${1:-0} + SLURM_ARRAY_TASK_ID ))\nindex=$(( task / parts ))\npart=$(( task % parts ))\n";
  s += "rm -f \"$dir/failed/task_$task\"\n";
  s += "threads=()\n[ -n \"${SLURM_CPUS_PER_TASK:-}\" ] && threads=(--threads \"$SLURM_CPUS_PER_TASK\")\n";
  s += shellQuote(r.executable.string()) + " render " + shellQuote(r.project.string()) + " -q --part \"$part/$parts\"";
  if (isStill(r)) {
    s += " -o \"$dir/parts/s_p$part.gpart\"";
  } else {
    s += " --frames \"$(( " + std::to_string(*r.firstFrame) + " + index )):$(( " + std::to_string(*r.firstFrame) +
         " + index ))\" -o \"$dir/parts/f%06d_p$part.gpart\"";
  }
  for (const std::string& o : r.renderOptions) s += " " + shellQuote(o);
  s += " \"${threads[@]}\"\nrc=$?\n";
  s += "# A failure is recorded for `gridifs farm --status` (143: cancelled, 137: killed).\n";
  s += "[ \"$rc\" -ne 0 ] && echo \"$rc\" > \"$dir/failed/task_$task\"\nexit \"$rc\"\n";
  return s;
}

std::string mergeScript(const FarmRequest& r) {
  std::string s = header(r, "merge", "merge_%A_%a.out", false);
  s += "# Task F (plus the offset given as $1) merges the parts of frame index F into its image.\n";
  s += "set -u\ndir=" + shellQuote(r.dir.string()) + "\nparts=" + std::to_string(r.parts) + "\n";
  s += "index=$(( ${1:-0} + SLURM_ARRAY_TASK_ID ))\noutputs=(\n";
  for (std::int64_t i = 0; i < frameCount(r); ++i)
    s += "  " + shellQuote(isStill(r) ? r.output : frameFileName(r.output, frameAt(r, i))) + "\n";
  s += ")\nlist=()\nfor (( k = 0; k < parts; k++ )); do\n";
  if (isStill(r)) {
    s += "  list+=(\"$dir/parts/s_p$k.gpart\")\ndone\nframe=0\n";
  } else {
    s += "  list+=(\"$dir/parts/f$(printf %06d $(( " + std::to_string(*r.firstFrame) +
         " + index )))_p$k.gpart\")\ndone\nframe=$(( " + std::to_string(*r.firstFrame) + " + index ))\n";
  }
  s += shellQuote(r.executable.string()) + " merge \"${list[@]}\" -o \"${outputs[$index]}\"";
  for (const std::string& o : r.mergeOptions) s += " " + shellQuote(o);
  s += " || exit $?\necho merged > \"$dir/merged/f$frame\"\n";
  return s;
}

std::string videoScript(const FarmRequest& r) {
  std::string s = header(r, "video", "video_%j.out", false);
  s += "# Assembles the merged frames into the video with ffmpeg.\nset -u\n";
  s += shellQuote(r.executable.string()) + " farm --assemble-video " + shellQuote(r.dir.string()) + " || exit $?\n";
  s += "echo merged > " + shellQuote((r.dir / "merged" / "video").string()) + "\n";
  return s;
}

/// Whether a part file is valid for (frame index, part) of the request: its header names that part
/// of this request, and its trailer (or, with PartCheck::WholeData, its data) checks out.
bool validPart(const FarmRequest& r, std::int64_t index, std::int64_t part, PartCheck check) {
  try {
    const fs::path file = farmPartPath(r, index, part);
    const RenderPartHeader h = check == PartCheck::WholeData ? verifyRenderPart(file) : inspectRenderPart(file);
    const bool frameMatches =
        isStill(r) ? !h.frame.has_value() : (h.frame.has_value() && *h.frame == frameAt(r, index));
    return h.kind == "image" && h.part == part && h.parts == r.parts && frameMatches;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

fs::path farmPartPath(const FarmRequest& r, std::int64_t index, std::int64_t part) {
  char name[64];
  if (isStill(r))
    std::snprintf(name, sizeof name, "s_p%lld.gpart", static_cast<long long>(part));
  else
    std::snprintf(name, sizeof name, "f%06lld_p%lld.gpart", static_cast<long long>(frameAt(r, index)),
                  static_cast<long long>(part));
  return r.dir / "parts" / name;
}

void writeFarmJob(const FarmRequest& request) {
  FarmRequest r = request;
  if (r.parts < 1 || r.parts > kMaxFarmParts)
    throw FarmError("--parts must be between 1 and " + std::to_string(kMaxFarmParts));
  if (r.firstFrame.has_value() != r.lastFrame.has_value() || (r.firstFrame && *r.lastFrame < *r.firstFrame))
    throw FarmError("the frame range must be A:B with B ≥ A");
  if (frameCount(r) * r.parts > kMaxFarmTasks)
    throw FarmError(std::to_string(frameCount(r) * r.parts) + " render tasks are more than the limit of " +
                    std::to_string(kMaxFarmTasks));
  if (!isStill(r))
    if (const auto problem = framePatternProblem(r.output)) throw FarmError("-o " + r.output + ": " + *problem);
  if (r.video && isStill(r)) throw FarmError("--video needs a frame range (--frames A:B)");
  std::error_code ec;
  if (!fs::is_regular_file(r.project, ec)) throw FarmError("cannot read " + r.project.string() + ": no such file");
  r.project = fs::absolute(r.project);
  r.dir = fs::absolute(r.dir);
  if (r.output.empty() || r.output.front() != '/') r.output = fs::absolute(r.output).string();
  if (r.video && r.video->front() != '/') r.video = fs::absolute(*r.video).string();
  if (r.dir.string().find_first_of(" \t\n'\"$`\\") != std::string::npos)
    throw FarmError("the job folder " + r.dir.string() +
                    " must not contain spaces, quotes or $ (Slurm's #SBATCH lines take it unquoted)");
  const std::string digest = requestDigest(r);
  if (fs::exists(r.dir / "farm.json", ec)) {
    std::string stored;
    try {
      stored = nlohmann::json::parse(readWhole(r.dir / "farm.json")).at("digest").get<std::string>();
    } catch (const std::exception&) {
      throw FarmError(r.dir.string() + "/farm.json is damaged; use another --dir or remove the folder");
    }
    if (stored != digest)
      throw FarmError(r.dir.string() +
                      " holds the job of another render (another project file content, output, "
                      "frames, parts or options); use another --dir or remove the folder");
  } else if (fs::exists(r.dir, ec) && !fs::is_empty(r.dir, ec)) {
    throw FarmError(r.dir.string() + " is not empty and is not a farm job folder; use an empty or new --dir");
  }
  for (const char* sub : {"parts", "failed", "merged", "logs"}) {
    fs::create_directories(r.dir / sub, ec);
    if (ec) throw FarmError("cannot create " + (r.dir / sub).string() + ": " + ec.message());
  }
  nlohmann::json j = toJson(r);
  j["digest"] = digest;
  try {
    writeFileAtomically(r.dir / "farm.json", j.dump(2) + "\n");
  } catch (const IoError& e) {
    throw FarmError(e.what());
  }
  writeScript(r.dir / "render.sbatch", renderScript(r));
  writeScript(r.dir / "merge.sbatch", mergeScript(r));
  if (r.video) writeScript(r.dir / "video.sbatch", videoScript(r));
}

FarmRequest readFarmRequest(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir / "farm.json", ec))
    throw FarmError(dir.string() + " is not a farm job folder (it has no farm.json)");
  try {
    const nlohmann::json j = nlohmann::json::parse(readWhole(dir / "farm.json"));
    FarmRequest r;
    r.project = j.at("project").get<std::string>();
    r.output = j.at("output").get<std::string>();
    r.parts = j.at("parts").get<std::int64_t>();
    r.renderOptions = j.at("render_options").get<std::vector<std::string>>();
    r.mergeOptions = j.at("merge_options").get<std::vector<std::string>>();
    r.sbatchOptions = j.at("sbatch_options").get<std::vector<std::string>>();
    r.executable = j.at("executable").get<std::string>();
    if (!j.at("frames").is_null()) {
      r.firstFrame = j.at("frames").at(0).get<std::int64_t>();
      r.lastFrame = j.at("frames").at(1).get<std::int64_t>();
    }
    if (!j.at("video").is_null()) r.video = j.at("video").get<std::string>();
    r.dir = fs::absolute(dir);
    if (r.parts < 1 || r.parts > kMaxFarmParts) throw FarmError("");
    return r;
  } catch (const std::exception&) {
    throw FarmError(dir.string() + "/farm.json is damaged");
  }
}

FarmStatus readFarmStatus(const fs::path& dir, bool slurm, PartCheck check) {
  FarmStatus status;
  status.request = readFarmRequest(dir);
  const FarmRequest& r = status.request;
  std::error_code ec;
  for (std::int64_t i = 0; i < frameCount(r); ++i) {
    FarmFrame f;
    f.frame = frameAt(r, i);
    for (std::int64_t k = 0; k < r.parts; ++k) {
      const bool valid = validPart(r, i, k, check);
      if (valid)
        ++f.partsDone;
      else
        f.missingParts.push_back(k);
      const std::int64_t task = i * r.parts + k;
      const fs::path marker = r.dir / "failed" / ("task_" + std::to_string(task));
      if (fs::exists(marker, ec)) {
        std::string code = readWhole(marker);
        while (!code.empty() && (code.back() == '\n' || code.back() == ' ')) code.pop_back();
        const std::string why = code == "143"   ? "cancelled (SIGTERM)"
                                : code == "137" ? "killed (SIGKILL)"
                                                : "exit " + code;
        if (!valid)  // a record of a task that a later run redid is history
          f.failedTasks.push_back("task " + std::to_string(task) + " (part " + std::to_string(k) + "): " + why);
      }
    }
    const std::string out = isStill(r) ? r.output : frameFileName(r.output, f.frame);
    f.merged = fs::exists(r.dir / "merged" / ("f" + std::to_string(f.frame)), ec) && fs::exists(out, ec);
    status.frames.push_back(std::move(f));
  }
  status.videoDone = r.video && fs::exists(r.dir / "merged" / "video", ec) && fs::exists(*r.video, ec);
  if (slurm) {
    const SlurmView view = askSlurm(r.dir);
    status.queued = view.active;
    // Tasks that Slurm saw fail or cancelled, unless the task's part is valid now (a later run
    // rendered it) or the task wrote its own failure record.
    for (const auto& [task, state] : view.failedTasks) {
      const std::int64_t index = task / r.parts, part = task % r.parts;
      if (index >= std::int64_t(status.frames.size())) continue;
      FarmFrame& f = status.frames[std::size_t(index)];
      if (std::find(f.missingParts.begin(), f.missingParts.end(), part) == f.missingParts.end()) continue;
      const std::string prefix = "task " + std::to_string(task) + " ";
      if (std::any_of(f.failedTasks.begin(), f.failedTasks.end(),
                      [&](const std::string& t) { return t.rfind(prefix, 0) == 0; }))
        continue;
      std::string word = state;
      std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return char(std::tolower(c)); });
      f.failedTasks.push_back(prefix + "(part " + std::to_string(part) + "): " + word + " in Slurm");
    }
  }
  return status;
}

std::vector<std::string> describeFarmStatus(const FarmStatus& s) {
  std::vector<std::string> lines;
  const FarmRequest& r = s.request;
  std::int64_t merged = 0, complete = 0;
  for (const FarmFrame& f : s.frames) {
    merged += f.merged;
    complete += f.partsDone == r.parts;
    std::string line = (s.still() ? std::string("still") : "frame " + std::to_string(f.frame)) + ": " +
                       std::to_string(f.partsDone) + "/" + std::to_string(r.parts) + " parts" +
                       (f.merged ? ", merged" : ", not merged");
    for (const std::string& failed : f.failedTasks) line += "; failed " + failed;
    lines.push_back(line);
  }
  lines.push_back(std::to_string(complete) + " of " + std::to_string(s.frames.size()) + " frame" +
                  (s.frames.size() == 1 ? "" : "s") + " have every part, " + std::to_string(merged) + " merged" +
                  (r.video ? (s.videoDone ? "; video assembled" : "; video not assembled") : ""));
  for (const std::string& q : s.queued) lines.push_back("queued: job " + q);
  return lines;
}

FarmPlan planFarm(const FarmStatus& s) {
  FarmPlan plan;
  const std::int64_t n = s.request.parts;
  for (std::size_t i = 0; i < s.frames.size(); ++i) {
    const FarmFrame& f = s.frames[i];
    for (std::int64_t k : f.missingParts) plan.renderTasks.push_back(std::int64_t(i) * n + k);
    if (!f.merged || !f.missingParts.empty()) plan.mergeFrames.push_back(std::int64_t(i));
  }
  plan.video = s.request.video && (!s.videoDone || !plan.mergeFrames.empty());
  return plan;
}

bool slurmAvailable() {
  // On the PATH is enough: `sbatch --version` itself fails on a machine without a cluster
  // configuration, and submitting then says so in one sentence.
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');)
    if (!folder.empty() && ::access((fs::path(folder) / "sbatch").c_str(), X_OK) == 0) return true;
  return false;
}

std::vector<std::string> farmSubmitCommands(const fs::path& dir, const FarmPlan& plan) {
  std::vector<std::string> lines;
  const std::string d = fs::absolute(dir).string();
  for (const auto& [array, offset] : arraysFor(plan.renderTasks, 1001))
    lines.push_back("sbatch --array=" + array + " " + d + "/render.sbatch " + std::to_string(offset));
  for (const auto& [array, offset] : arraysFor(plan.mergeFrames, 1001))
    lines.push_back("sbatch --array=" + array +
                    (plan.renderTasks.empty() ? "" : " --dependency=afterok:<render jobs>") + " " + d +
                    "/merge.sbatch " + std::to_string(offset));
  if (plan.video) lines.push_back("sbatch --dependency=afterok:<merge jobs> " + d + "/video.sbatch");
  return lines;
}

std::vector<std::string> submitFarm(const fs::path& dir, const FarmPlan& plan) {
  const FarmRequest r = readFarmRequest(dir);
  // Jobs still queued from an earlier submission: a merge that waits on a failed or cancelled
  // render can never run and is cancelled; anything else must finish (or be cancelled) first.
  std::vector<std::string> stale, busy;
  for (const std::string& line : queuedJobs(r.dir)) {
    std::istringstream in(line);
    std::string id, state, reason;
    in >> id >> state >> reason;
    if (state == "PENDING" && reason == "DependencyNeverSatisfied")
      stale.push_back(id);
    else
      busy.push_back(id + " (" + state + ")");
  }
  if (!busy.empty()) {
    std::string list;
    for (const std::string& b : busy) list += (list.empty() ? "" : ", ") + b;
    throw FarmError(r.dir.string() + " still has jobs in Slurm: " + list + "; wait for them or scancel them first");
  }
  for (const std::string& id : stale) {
    int status = 0;
    capture({"scancel", id.substr(0, id.find('_'))}, status);
  }
  std::error_code ec;
  // A frame whose parts are rendered again must be merged again.
  for (std::int64_t f : plan.mergeFrames) fs::remove(r.dir / "merged" / ("f" + std::to_string(frameAt(r, f))), ec);
  if (plan.video) fs::remove(r.dir / "merged" / "video", ec);
  std::vector<std::string> submitted;
  std::ofstream jobs(r.dir / "jobs", std::ios::app);
  auto sbatch = [&](std::vector<std::string> args, const std::string& what, std::int64_t offset) {
    args.insert(args.begin(), {"sbatch", "--parsable"});
    int status = 0;
    std::string out = capture(args, status);
    const std::string id = out.substr(0, out.find_first_of(";\n"));
    if (status != 0 || id.empty())
      throw FarmError("sbatch refused the " + what + " job of " + r.dir.string() + " (exit " + std::to_string(status) +
                      "); is Slurm running and SLURM_CONF set?");
    jobs << id << " " << what << " " << offset << "\n";
    jobs.flush();
    submitted.push_back(id + " " + what);
    return id;
  };
  const std::int64_t limit = maxArraySize();
  std::string renderIds;
  for (const auto& [array, offset] : arraysFor(plan.renderTasks, limit))
    renderIds += ":" + sbatch({"--array=" + array, (r.dir / "render.sbatch").string(), std::to_string(offset)},
                              "render", offset);
  std::string mergeIds;
  for (const auto& [array, offset] : arraysFor(plan.mergeFrames, limit)) {
    std::vector<std::string> args = {"--array=" + array};
    if (!renderIds.empty()) args.push_back("--dependency=afterok" + renderIds);
    args.insert(args.end(), {(r.dir / "merge.sbatch").string(), std::to_string(offset)});
    mergeIds += ":" + sbatch(args, "merge", offset);
  }
  if (plan.video) {
    std::vector<std::string> args;
    if (!mergeIds.empty()) args.push_back("--dependency=afterok" + mergeIds);
    args.push_back((r.dir / "video.sbatch").string());
    sbatch(args, "video", 0);
  }
  return submitted;
}

}  // namespace gridifs
