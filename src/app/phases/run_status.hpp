// How a run stands while its phases run: converged until a procedure fails (the first failure is
// the one reported), and stopping once a signal, -stop_after_step or a failed result-file write
// ends the step loops. Every change is made on all ranks together (the callers agree first), so
// the state is equal on every rank. The phases change it only through these methods.
#pragma once
#include <string>

namespace sinew {

class RunStatus {
 public:
  /// interruptSignal() of a -stop_after_step stop.
  static constexpr int kStopAfterStep = -1;

  bool converged() const { return converged_; }
  /// The first failure's message ("" while converged).
  const std::string& failure() const { return failure_; }
  /// A procedure failed: the run is not converged; only the first failure's message is kept.
  void fail(const std::string& message) {
    if (!converged_) return;
    converged_ = false;
    failure_ = message;
  }
  /// More lines for the failure already reported (what a check found after the failed step).
  void explainFailure(const std::string& lines) {
    if (!converged_) failure_ += "\n" + lines;
  }

  /// The step loops end after the current step.
  bool stopping() const { return stop_; }
  /// The flag the procedures' step loops poll (setStopFlag).
  const bool* stopFlag() const { return &stop_; }
  /// A signal (or kStopAfterStep) stops the run.
  void interrupt(int signal) {
    interruptSignal_ = signal;
    stop_ = true;
  }
  int interruptSignal() const { return interruptSignal_; }
  /// Writing the result file failed: the run stops; the file keeps its committed steps.
  void writeFailed(const std::string& what) {
    ioError_ = what;
    stop_ = true;
  }
  bool writeOk() const { return ioError_.empty(); }
  const std::string& ioError() const { return ioError_; }

  /// Where the run is: the running phase's step name ("load step", ...) and its last converged step.
  void enterPhase(const std::string& stepName) {
    stepName_ = stepName;
    lastStep_ = 0;
  }
  void reached(int stepIndex) { lastStep_ = stepIndex; }
  /// "load step 7", or "set-up" before any phase ran.
  std::string position() const { return stepName_.empty() ? "set-up" : stepName_ + " " + std::to_string(lastStep_); }

 private:
  bool converged_ = true;
  std::string failure_;
  bool stop_ = false;
  int interruptSignal_ = 0;
  std::string ioError_;
  std::string stepName_;
  int lastStep_ = 0;
};

}  // namespace sinew
