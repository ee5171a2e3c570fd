#include "BenchmarkRunner.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <limits>
#include <sstream>

namespace cmp::bench
{
namespace
{

// ---------------------------------------------------------------------------
// Memory of the calling process (Linux /proc).

/// \brief A "Name:  1234 kB" field of /proc/self/status, in kB (0 if absent).
long statusFieldKB(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::size_t length = std::strlen(field);
  while (std::getline(status, line))
  {
    if (line.compare(0, length, field) == 0)
      return std::atol(line.c_str() + length);
  }
  return 0;
}

/// \brief Resets the peak resident size to the current one, so the next
///        reading is the peak of the next stage alone (Linux >= 4.0).
bool resetPeakMemory()
{
  std::ofstream clearRefs("/proc/self/clear_refs");
  clearRefs << "5";
  clearRefs.flush();
  return static_cast<bool>(clearRefs);
}

double toMB(long kB)
{
  return kB / 1024.0;
}

// ---------------------------------------------------------------------------
// Child side: run the stages, report one tab-separated line per event.
//
//   start <rss kB> <1 if per-stage peaks>
//   size <vertices> <triangles>
//   done <stage> <seconds> <runs> <peak kB>
//   figure <name> <value>          (after `done`, every figure set so far)
//   na <stage>
//   failed <stage> <seconds> <peak kB> <message>
//   fatal <message>

void sendLine(int fd, const std::string& line)
{
  const std::string text = line + "\n";
  std::size_t written = 0;
  while (written < text.size())
  {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n <= 0)
      return; // The parent is gone; nothing useful left to do.
    written += static_cast<std::size_t>(n);
  }
}

std::string joinTabs(std::initializer_list<std::string> fields)
{
  std::string line;
  for (const std::string& field : fields)
    line += (line.empty() ? "" : "\t") + field;
  return line;
}

/// \brief `text` with tabs and newlines (the protocol's separators) as spaces.
std::string oneField(std::string text)
{
  std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\t'; }, ' ');
  return text;
}

/// \brief Sends every figure set so far. Resending earlier stages' figures
///        is harmless (the parent replaces by name) and keeps the child free
///        of bookkeeping about what it already sent.
void sendFigures(int fd, const FigureList& figures)
{
  for (const Figure& figure : figures)
  {
    char value[32];
    std::snprintf(value, sizeof value, "%.17g", figure.value); // round-trips a double
    sendLine(fd, joinTabs({ "figure", oneField(figure.name), value }));
  }
}

/// \brief Runs one stage `repetitions` times (stopping at the first error)
///        and reports its best time and peak memory.
bool timeStage(int fd, const Stage& stage, ModelContext& ctx, int repetitions)
{
  using Clock = std::chrono::steady_clock;
  resetPeakMemory();
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> bestParts;
  Status status;
  int runs = 0;
  while (runs < repetitions && status.ok())
  {
    ctx.partSeconds.clear();
    const Clock::time_point start = Clock::now();
    status = stage.run(ctx);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (seconds < best)
      bestParts = ctx.partSeconds;
    best = std::min(best, seconds);
    ++runs;
  }
  const std::vector<std::string> columns = stageColumns(stage);
  const std::string peak = std::to_string(statusFieldKB("VmHWM:"));
  sendLine(fd, joinTabs({ "size", std::to_string(ctx.surface().vertexCount()),
                          std::to_string(ctx.surface().triangleCount()) }));
  if (!status.ok())
  {
    sendLine(fd, joinTabs({ "failed", columns.front(), std::to_string(best), peak, oneField(status.message()) }));
    return false;
  }
  if (!stage.parts.empty() && bestParts.size() != stage.parts.size())
  {
    sendLine(fd, joinTabs({ "failed", columns.front(), std::to_string(best), peak, "the stage did not time its parts" }));
    return false;
  }
  for (std::size_t c = 0; c < columns.size(); ++c)
    sendLine(fd, joinTabs({ "done", columns[c], std::to_string(stage.parts.empty() ? best : bestParts[c]),
                            std::to_string(runs), peak }));
  sendFigures(fd, ctx.figures);
  return true;
}

[[noreturn]] void childMain(
  int fd, const ModelSpec& spec, const SharedInputs& shared, const std::vector<Stage>& stages, int repetitions)
{
  int exitCode = 0;
  try
  {
    const bool perStage = resetPeakMemory();
    sendLine(fd, joinTabs({ "start", std::to_string(statusFieldKB("VmRSS:")), perStage ? "1" : "0" }));
    ModelContext ctx;
    ctx.spec = spec;
    ctx.shared = &shared;
    for (const Stage& stage : stages)
    {
      if (!stageApplies(stage, spec))
      {
        for (const std::string& column : stageColumns(stage))
          sendLine(fd, joinTabs({ "na", column }));
      }
      else if (!timeStage(fd, stage, ctx, repetitions))
      {
        exitCode = 1;
        break;
      }
    }
  }
  catch (const std::exception& e)
  {
    sendLine(fd, joinTabs({ "fatal", e.what() }));
    exitCode = 1;
  }
  ::close(fd);
  // _exit: the child must not run the parent's atexit handlers or flush
  // stdio buffers it inherited.
  ::_exit(exitCode);
}

// ---------------------------------------------------------------------------
// Parent side: parse the child's lines into a ModelResult.

std::vector<std::string> splitTabs(const std::string& line)
{
  std::vector<std::string> fields;
  std::istringstream in(line);
  std::string field;
  while (std::getline(in, field, '\t'))
    fields.push_back(field);
  return fields;
}

StageResult* findStage(ModelResult& result, const std::string& name)
{
  for (StageResult& stage : result.stages)
  {
    if (stage.stage == name)
      return &stage;
  }
  return nullptr;
}

std::string formatProgress(const ModelResult& result, const StageResult& stage)
{
  char text[200];
  std::snprintf(text, sizeof text, "%-10s %-15s %9.3f s  %8.1f MB", result.model.c_str(), stage.stage.c_str(),
    stage.seconds, stage.peakMB);
  return text;
}

/// \brief Applies one child line to `result`; returns a progress line or "".
std::string applyLine(ModelResult& result, const std::string& line)
{
  const std::vector<std::string> f = splitTabs(line);
  if (f.empty())
    return "";
  if (f[0] == "start" && f.size() >= 3)
  {
    result.startMB = toMB(std::atol(f[1].c_str()));
    result.perStagePeaks = f[2] == "1";
  }
  else if (f[0] == "size" && f.size() >= 3)
  {
    result.vertices = std::atoi(f[1].c_str());
    result.triangles = std::atoi(f[2].c_str());
  }
  else if (f[0] == "figure" && f.size() >= 3)
    setFigure(result.figures, f[1], std::atof(f[2].c_str()));
  else if (f[0] == "fatal" && f.size() >= 2)
    result.error = "exception: " + f[1];
  else if (StageResult* stage = f.size() >= 2 ? findStage(result, f[1]) : nullptr)
  {
    if (f[0] == "na")
      stage->state = StageState::NotApplicable;
    else if (f[0] == "done" && f.size() >= 5)
    {
      stage->state = StageState::Done;
      stage->seconds = std::atof(f[2].c_str());
      stage->runs = std::atoi(f[3].c_str());
      stage->peakMB = toMB(std::atol(f[4].c_str()));
      return formatProgress(result, *stage);
    }
    else if (f[0] == "failed" && f.size() >= 5)
    {
      stage->state = StageState::Failed;
      stage->seconds = std::atof(f[2].c_str());
      stage->runs = 1;
      stage->peakMB = toMB(std::atol(f[3].c_str()));
      result.error = stage->stage + ": " + f[4];
      return result.model + ": " + result.error;
    }
  }
  return "";
}

/// \brief Reads the child's lines until it closes the pipe.
void readChild(int fd, ModelResult& result, const ProgressFunction& progress)
{
  std::string pending;
  char buffer[4096];
  ssize_t n;
  while ((n = ::read(fd, buffer, sizeof buffer)) > 0 || (n < 0 && errno == EINTR))
  {
    pending.append(buffer, static_cast<std::size_t>(std::max<ssize_t>(n, 0)));
    std::size_t end;
    while ((end = pending.find('\n')) != std::string::npos)
    {
      const std::string message = applyLine(result, pending.substr(0, end));
      pending.erase(0, end + 1);
      if (!message.empty() && progress)
        progress(message);
    }
  }
}

/// \brief Records how the child ended and its whole-process peak memory.
void collectChild(pid_t pid, ModelResult& result)
{
  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR)
  {
  }
  // ru_maxrss only covers the time since the last peak reset, so combine
  // it with the per-stage peaks.
  result.peakMB = std::max(result.peakMB, toMB(usage.ru_maxrss));
  for (const StageResult& stage : result.stages)
    result.peakMB = std::max(result.peakMB, stage.peakMB);
  if (WIFSIGNALED(status))
    result.error = std::string("killed by signal ") + std::to_string(WTERMSIG(status)) + " (" +
      strsignal(WTERMSIG(status)) + ")" + (result.error.empty() ? "" : " after " + result.error);
  else if (WEXITSTATUS(status) != 0 && result.error.empty())
    result.error = "exit code " + std::to_string(WEXITSTATUS(status));
}

} // namespace

double ModelResult::totalSeconds() const
{
  double total = 0.0;
  for (const StageResult& stage : stages)
    total += stage.state == StageState::Done && stage.inTotal ? stage.seconds : 0.0;
  return total;
}

ModelResult runModel(const ModelSpec& spec, const SharedInputs& shared, const std::vector<Stage>& stages,
  int repetitions, const ProgressFunction& progress)
{
  ModelResult result;
  result.model = spec.name;
  for (const Stage& stage : stages)
  {
    for (const std::string& column : stageColumns(stage))
    {
      StageResult stageResult;
      stageResult.stage = column;
      stageResult.inTotal = stage.inTotal;
      result.stages.push_back(stageResult);
    }
  }
  int fds[2];
  if (::pipe(fds) != 0)
  {
    result.error = std::string("pipe: ") + std::strerror(errno);
    return result;
  }
  // Anything buffered now would be written twice, once by each process.
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0)
  {
    ::close(fds[0]);
    childMain(fds[1], spec, shared, stages, std::max(1, repetitions));
  }
  ::close(fds[1]);
  if (pid < 0)
  {
    ::close(fds[0]);
    result.error = std::string("fork: ") + std::strerror(errno);
    return result;
  }
  readChild(fds[0], result, progress);
  ::close(fds[0]);
  collectChild(pid, result);
  return result;
}

} // namespace cmp::bench
