#pragma once
/// \file Progress.hpp
/// \brief Progress of a long loop: on a terminal one line rewritten in place (simulated time,
/// steps/s, ETA); otherwise a log line every few seconds, so batch logs stay readable.

#include <chrono>
#include <cstdint>
#include <string>

namespace hikiln::log {

/// \brief Reports how far a run from 0 to `endTime` (simulated seconds) has got.
class Progress {
public:
  /// \brief `label` names the loop; `endTime` is the simulated time at which it ends.
  Progress(std::string label, double endTime, double logIntervalSeconds = 10.0);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// \brief Called often (cheap): prints only when the display interval has passed. A non-empty
  /// `note` is appended to the line (e.g. what a loop that runs past endTime waits for).
  void update(double simulatedTime, std::int64_t step, const std::string& note = {});
  /// \brief Final line with totals; called by the destructor if not called explicitly.
  void finish();

  /// \brief The status text for a given state, `note` appended when non-empty (exposed for
  /// tests).
  static std::string format(double simulatedTime, double endTime, double stepsPerSecond,
                            double etaSeconds, const std::string& note = {});

private:
  using Clock = std::chrono::steady_clock;
  std::string _label;
  double _endTime;
  double _logInterval;
  bool _terminal;
  bool _finished = false;
  Clock::time_point _start;
  Clock::time_point _lastPrint;
  double _lastTime = 0.0;
  std::int64_t _lastStep = 0;
  std::int64_t _firstStep = -1;
  double _firstTime = 0.0; ///< simulated time at the first update (a restart starts late)
};

} // namespace hikiln::log
