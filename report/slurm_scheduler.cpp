#include "report/slurm_scheduler.h"

#include <pwd.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "core/error.h"
#include "core/file_io.h"
#include "report/program_runner.h"
#include "report/stage_plan.h"

namespace iblkit {

namespace fs = std::filesystem;

namespace {

// Slurm's default MaxArraySize is 1001: task indices 0..1000.
constexpr std::size_t kMostTasksPerArray = 1000;

std::string findCommand(const std::string& name) {
  std::vector<fs::path> folders;
  if (const char* path = std::getenv("PATH")) {
    std::stringstream stream(path);
    for (std::string folder; std::getline(stream, folder, ':');)
      if (!folder.empty()) folders.push_back(folder);
  }
  folders.insert(folders.end(), {"/usr/bin", "/usr/sbin", "/usr/local/bin"});
  for (const fs::path& folder : folders)
    if (::access((folder / name).c_str(), X_OK) == 0) return (folder / name).string();
  fail(name, "not found in PATH: --scheduler slurm needs Slurm's commands (Debian: slurm-client)");
}

// A file name's part from a case or stage name: letters, digits, '.', '_' and '-'.
std::string fileNamePart(const std::string& name) {
  std::string part = name;
  for (char& c : part)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
  return part;
}

// The stage's kind: "bake", "view", "trace" (the name's first part).
std::string stageKind(const PendingStage& stage) { return stage.name.substr(0, stage.name.find('-')); }

}  // namespace

std::map<std::string, std::string> parseQueueStates(const std::string& output) {
  static const std::regex line(R"(^\s*([0-9]+)_([0-9]+)\s+([A-Z_]+)\s*$)");
  std::map<std::string, std::string> states;
  std::stringstream stream(output);
  for (std::string text; std::getline(stream, text);) {
    std::smatch match;
    if (std::regex_match(text, match, line)) states[match[1].str() + "_" + match[2].str()] = match[3].str();
  }
  return states;
}

std::string failedTaskSummary(const std::string& output) {
  std::string summary;
  for (const char* field : {"JobState", "Reason", "ExitCode"}) {
    const std::regex pattern(std::string(R"((^|\s))") + field + R"(=(\S+))");
    std::smatch match;
    if (std::regex_search(output, match, pattern)) {
      if (!summary.empty()) summary += ' ';
      summary += std::string(field) + "=" + match[2].str();
    }
  }
  return summary;
}

SlurmScheduler::SlurmScheduler(SlurmOptions options, fs::path cacheRoot)
    : options_(std::move(options)), cacheRoot_(std::move(cacheRoot)), folder_(cacheRoot_ / "slurm") {
  sbatch_ = findCommand("sbatch");
  squeue_ = findCommand("squeue");
  scontrol_ = findCommand("scontrol");
  if (std::getenv("USER") == nullptr || *std::getenv("USER") == '\0') {
    // sbatch and slurmd want USER; a container's shell may not set it.
    if (const passwd* user = ::getpwuid(::getuid())) ::setenv("USER", user->pw_name, 1);
  }
  std::error_code error;
  fs::create_directories(folder_, error);
  if (error) fail(folder_, "cannot create folder: " + error.message());
}

std::string SlurmScheduler::capture(const std::vector<std::string>& argv, bool keepLog) {
  // runProgram appends to its log: submissions are kept in submissions.log, polls are not.
  const fs::path log = folder_ / (keepLog ? "submissions.log" : ".poll.log");
  std::error_code error;
  if (!keepLog) fs::remove(log, error);
  std::string output = runProgram(argv, log);
  if (!keepLog) fs::remove(log, error);
  return output;
}

std::string SlurmScheduler::submitArray(const std::string& group, const std::vector<const PendingStage*>& stages,
                                        const std::vector<std::string>& after, bool engineFrames,
                                        std::vector<Task>& tasks) {
  const std::string name = "wave" + std::to_string(waves_) + "-" + fileNamePart(group);
  std::vector<PendingStage> planned;
  for (const PendingStage* stage : stages) planned.push_back(*stage);
  const fs::path plan = fs::absolute(folder_ / (name + ".json"));
  writeStagePlan(plan, cacheRoot_, planned);
  const fs::path script = fs::absolute(folder_ / (name + ".sh"));
  writeAtomically(script, [&](const fs::path& temporary) {
    std::ofstream stream(temporary);
    stream << "#!/bin/sh\n# iblkit-report's job array " << name << " (docs/cluster.md): task I runs stage I of\n# "
           << plan.string() << "\nexec " << shellQuoted(fs::absolute(options_.reportProgram).string())
           << " --stage-task " << shellQuoted(plan.string()) << " --task-index \"$SLURM_ARRAY_TASK_ID\"\n";
    if (!stream.flush()) fail(script, "cannot write the job script");
  });
  fs::permissions(script, fs::perms::owner_all | fs::perms::group_read | fs::perms::others_read);

  std::vector<std::string> argv = {sbatch_,
                                   "--parsable",
                                   "--job-name=iblkit-" + fileNamePart(group),
                                   "--array=0-" + std::to_string(stages.size() - 1),
                                   "--output=" + fs::absolute(folder_ / (name + "-%A_%a.log")).string(),
                                   "--chdir=" + fs::current_path().string()};
  if (!options_.partition.empty()) argv.push_back("--partition=" + options_.partition);
  if (!after.empty()) {
    std::string dependency = "--dependency=afterok";
    for (const std::string& job : after) dependency += ":" + job;
    argv.insert(argv.end(), {dependency, "--kill-on-invalid-dep=yes"});
  }
  argv.insert(argv.end(), options_.sbatchArguments.begin(), options_.sbatchArguments.end());
  if (engineFrames) argv.insert(argv.end(), options_.viewSbatchArguments.begin(), options_.viewSbatchArguments.end());
  argv.push_back(script.string());
  std::string output;
  try {
    output = capture(argv, /*keepLog=*/true);
  } catch (const Error& e) {
    fail(plan, std::string("sbatch refused the job array: ") + e.what());
  }
  static const std::regex jobId(R"(^\s*([0-9]+))");
  std::smatch match;
  // --parsable prints "JOBID" or "JOBID;CLUSTER"; the log header line comes first.
  std::string id;
  std::stringstream stream(output);
  for (std::string text; std::getline(stream, text);)
    if (std::regex_search(text, match, jobId)) id = match[1].str();
  if (id.empty()) fail(plan, "sbatch printed no job id: " + printableExcerpt(output, 200));
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const fs::path log = folder_ / (name + "-" + id + "_" + std::to_string(i) + ".log");
    tasks.push_back({stages[i], id, int(i), log});
    ++submissions_[stages[i]->folderName()];
  }
  tasksSubmitted_ += int(stages.size());
  return id;
}

void SlurmScheduler::waitFor(const std::vector<Task>& tasks) {
  std::set<std::string> ids;
  std::string jobs;
  for (const Task& task : tasks)
    if (ids.insert(task.jobId).second) jobs += (jobs.empty() ? "" : ",") + task.jobId;
  const auto start = std::chrono::steady_clock::now();
  std::string lastLine;
  double pause = 0.2;
  for (int failedPolls = 0;;) {
    std::map<std::string, std::string> states;
    try {
      states = parseQueueStates(capture({squeue_, "-h", "-r", "-j", jobs, "-o", "%i %T"}));
      failedPolls = 0;
    } catch (const Error& e) {
      // The controller forgets finished jobs (MinJobAge): then squeue rejects their ids.
      if (std::string(e.what()).find("Invalid job id") == std::string::npos) {
        if (++failedPolls < 5) {
          std::this_thread::sleep_for(std::chrono::seconds(1));
          continue;
        }
        throw;
      }
    }
    int pending = 0, running = 0, done = 0, failed = 0;
    for (const Task& task : tasks) {
      const auto found = states.find(task.jobId + "_" + std::to_string(task.index));
      const std::string state = found == states.end() ? "" : found->second;
      // squeue lists pending, running and completing tasks by default: a listed task is still in
      // the queue, whatever its state; one that left it is judged by its stage folder.
      if (!state.empty())
        ++(state == "PENDING" ? pending : running);
      else
        ++(fs::is_directory(cacheRoot_ / task.stage->folderName()) ? done : failed);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char line[200];
    std::snprintf(line, sizeof line, "iblkit-report: slurm wave %d: %zu tasks: %d pending, %d running, %d done, %d failed",
                  waves_, tasks.size(), pending, running, done, failed);
    if (line != lastLine) {
      std::fprintf(stderr, "%s (%.0f s)\n", line, seconds);
      lastLine = line;
      pause = 0.2;
    }
    if (pending + running == 0) return;
    std::this_thread::sleep_for(std::chrono::duration<double>(pause));
    pause = std::min(pause * 1.5, 5.0);  // polling squeue, gently on a busy controller
  }
}

void SlurmScheduler::runWave(const PendingStages& pending) {
  ++waves_;
  // The groups: bakes, engine frames, each case's reference passes (and any other kind of stage).
  std::vector<std::pair<std::string, std::vector<const PendingStage*>>> groups;
  for (const PendingStage& stage : pending.stages()) {
    const std::string kind = stageKind(stage);
    const std::string group = kind == "trace" ? kind + "-" + stage.caseName : kind;
    auto found = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == group; });
    if (found == groups.end()) found = groups.insert(groups.end(), {group, {}});
    found->second.push_back(&stage);
  }
  std::set<std::string> inWave;  // the folders of the stages collected
  for (const PendingStage& stage : pending.stages()) inWave.insert(stage.folderName());
  // Submitted in dependency order: a group waits (afterok) for the arrays of the stages it reads.
  std::map<std::string, std::vector<std::string>> jobsOfFolder;  // a submitted stage's array job ids
  std::vector<Task> tasks;
  std::set<std::string> submitted;
  while (submitted.size() < groups.size()) {
    bool progress = false;
    for (const auto& [group, stages] : groups) {
      if (submitted.contains(group)) continue;
      std::set<std::string> after;
      bool ready = true;
      for (const PendingStage* stage : stages)
        for (const std::string& folder : stage->needs) {
          if (!inWave.contains(folder)) continue;  // not collected: the task fails on its missing input, reported below
          if (!jobsOfFolder.contains(folder)) ready = false;
          else after.insert(jobsOfFolder[folder].begin(), jobsOfFolder[folder].end());
        }
      if (!ready) continue;
      for (std::size_t first = 0; first < stages.size(); first += kMostTasksPerArray) {
        const std::vector<const PendingStage*> chunk(
            stages.begin() + std::ptrdiff_t(first),
            stages.begin() + std::ptrdiff_t(std::min(stages.size(), first + kMostTasksPerArray)));
        const std::string id = submitArray(group, chunk, {after.begin(), after.end()},
                                           stageKind(*chunk.front()) == "view", tasks);
        for (const PendingStage* stage : chunk) jobsOfFolder[stage->folderName()].push_back(id);
      }
      submitted.insert(group);
      progress = true;
    }
    if (!progress) fail(folder_, "the pending stages' dependencies form a cycle");
  }
  std::fprintf(stderr, "iblkit-report: slurm wave %d: submitted %zu stages in %zu arrays (logs in %s)\n", waves_,
               tasks.size(), groups.size(), folder_.c_str());
  waitFor(tasks);

  for (const Task& task : tasks) {
    const PendingStage& stage = *task.stage;
    std::error_code error;
    if (fs::is_directory(cacheRoot_ / stage.folderName(), error)) {
      ++stagesRun_;
      continue;
    }
    std::string how;
    try {
      how = failedTaskSummary(capture({scontrol_, "-o", "show", "job", task.jobId + "_" + std::to_string(task.index)}));
    } catch (const Error&) {
    }
    if (how.empty()) how = "state unknown (the controller no longer knows the task)";
    const std::string what = "stage " + stage.name + " (Slurm task " + task.jobId + "_" + std::to_string(task.index) +
                             ", " + how + ", log " + task.log.string() + ")";
    // A task that left no log never started (cancelled because a stage it reads failed, or
    // never scheduled): resubmitted with it, not counted as its own failure.
    if (fs::exists(task.log, error)) {
      if (++failures_[stage.folderName()] >= 2) fail("case " + stage.caseName, what + " failed twice");
      std::fprintf(stderr, "iblkit-report: slurm: case %s: %s failed; resubmitting it once\n", stage.caseName.c_str(),
                   what.c_str());
    } else {
      if (submissions_[stage.folderName()] >= 3)
        fail("case " + stage.caseName, what + " was submitted three times and never started");
      std::fprintf(stderr, "iblkit-report: slurm: case %s: %s did not start; resubmitting it\n",
                   stage.caseName.c_str(), what.c_str());
    }
  }
}

}  // namespace iblkit
