#pragma once
#include "algorithms/StaticSolver.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <unistd.h>

namespace contactlab {

// Progress on stderr (rank 0). On a terminal: a live line per Newton iterate, with the run's
// ETA once a step has converged (extrapolated linearly in load time), replaced by one line per
// step. In a log: one line per iterate and per step, so a long step is never silent. `--quiet`:
// none (and Console prints nothing but warnings, errors and the closing lines).
// Whatever the console shows, the same iterate and step lines go to `logPath` (the output
// folder's progress.log), flushed line by line: a quiet or captured run (a bench, a study) can
// be followed with `tail -f`; a continued run (--restart) appends to it.
class RunProgress {
 public:
  RunProgress(bool enabled, double endTime, const std::string& logPath = "", bool append = false)
      : enabled_(enabled), tty_(isatty(STDERR_FILENO)), endTime_(endTime) {
    if (logPath.empty()) return;
    log_.reset(std::fopen(logPath.c_str(), append ? "a" : "w"));
    if (log_ && append) writeLog("  (continued from the checkpoint)\n");
  }
  void iteration(const StaticSolver::IterateProgress& p, double elapsed) {
    if (!enabled_ && !log_) return;
    // How the step is being solved again, the fixed-point update that restarted Newton here,
    // and the cycling treatment that changed the law at this iterate (its residual jumps then:
    // the treated law's).
    std::string notes = *p.attempt ? std::string("  (") + p.attempt + ")" : std::string();
    // Which fixed point moved: a step that goes round shows which one cycles.
    if (*p.restartedBy) notes += std::string("  after a ") + p.restartedBy + " update";
    if (p.treatedPoints > 0)
      notes += "  cycling treatment at " + std::to_string(p.treatedPoints) + " point(s)";
    // Below the target and still going: what Newton waits for (a status that keeps changing at
    // a converged residual is a stall the line alone would not explain).
    if (p.iteration > 0 && p.residual <= p.target &&
        (p.statusChanges > 0 || p.contactResidual > p.target)) {
      char wait[128];
      if (p.statusChanges > 0)
        std::snprintf(wait, sizeof wait, "  below the target %.1e; %d contact status(es) changed",
                      p.target, p.statusChanges);
      else
        std::snprintf(wait, sizeof wait, "  below the target %.1e; contact rows %.1e above it",
                      p.target, p.contactResidual);
      notes += wait;
    }
    char line[256];
    std::snprintf(line, sizeof line,
                  "    step %d  t = %g  iteration %d  |R| = %.3e  elapsed %.1f s", p.step, p.time,
                  p.iteration, p.residual, elapsed);
    const std::string text = line + notes + "\n";
    writeLog(text);
    if (!enabled_) return;
    if (!tty_) {
      std::fputs(text.c_str(), stderr);
      return;
    }
    char eta[48] = "";
    if (lastTime_ > 0 && endTime_ > lastTime_)
      std::snprintf(eta, sizeof eta, "  ETA %.0f s",
                    std::max(0.0, lastElapsed_ * endTime_ / lastTime_ - elapsed));
    std::fprintf(stderr, "\r  step %d  t = %g  iteration %d  |R| = %.3e  elapsed %.1f s%s%s   ",
                 p.step, p.time, p.iteration, p.residual, elapsed, eta, notes.c_str());
    std::fflush(stderr);
  }
  void step(const StepReport& s, int steps, double elapsed) {
    lastTime_ = s.time;
    lastElapsed_ = elapsed;
    char line[256];
    std::snprintf(
        line, sizeof line,
        "  step %d (%d planned)  t = %g  %d iterations%s%s%s%s  |R| = %.3e  elapsed %.1f s\n",
        s.step, steps, s.time, s.iterations, s.cuts ? " after cuts" : "",
        s.geometryRetry ? " (geometry retry)" : "",
        s.updateLimitRetry ? " (update-limit retry)" : "",
        s.lineSearchRetry ? " (line-search retry)" : "", s.residual, elapsed);
    writeLog(line);
    if (!enabled_) return;
    if (tty_) std::fprintf(stderr, "\r%90s\r", "");
    std::fputs(line, stderr);
  }
  // The run's closing line (converged or failed), to the log only: the console has its own.
  void finish(const std::string& text) { writeLog(text + "\n"); }

 private:
  void writeLog(const std::string& text) {
    if (!log_) return;
    std::fputs(text.c_str(), log_.get());
    std::fflush(log_.get());
  }
  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };

  bool enabled_, tty_;
  double endTime_, lastTime_ = 0, lastElapsed_ = 0;
  std::unique_ptr<std::FILE, Close> log_;
};

}  // namespace contactlab
