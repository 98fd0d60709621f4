#include "drivers/log/Progress.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstdio>

namespace hikiln::log {

namespace {
std::string formatDuration(double seconds) {
  if (!(seconds >= 0.0) || seconds > 1e7)
    return "--";
  const auto s = static_cast<long>(seconds + 0.5);
  if (s >= 3600)
    return fmt::format("{}h{:02d}m", s / 3600, (s / 60) % 60);
  if (s >= 60)
    return fmt::format("{}m{:02d}s", s / 60, s % 60);
  return fmt::format("{}s", s);
}
} // namespace

Progress::Progress(std::string label, double endTime, double logIntervalSeconds)
    : _label(std::move(label)), _endTime(endTime), _logInterval(logIntervalSeconds),
      _terminal(::isatty(STDERR_FILENO) != 0), _start(Clock::now()), _lastPrint(_start) {}

Progress::~Progress() {
  if (!_finished)
    finish();
}

std::string Progress::format(double simulatedTime, double endTime, double stepsPerSecond,
                             double etaSeconds, const std::string& note) {
  const double percent = endTime > 0 ? 100.0 * simulatedTime / endTime : 100.0;
  return fmt::format("t = {:.3f} / {:.3f} s ({:5.1f} %), {:.3g} steps/s, ETA {}{}{}", simulatedTime,
                     endTime, percent, stepsPerSecond, formatDuration(etaSeconds),
                     note.empty() ? "" : ", ", note);
}

void Progress::update(double simulatedTime, std::int64_t step, const std::string& note) {
  if (_firstStep < 0) {
    _firstStep = step;
    _firstTime = simulatedTime;
  }
  _lastTime = simulatedTime;
  _lastStep = step;
  const auto now = Clock::now();
  const double sincePrint = std::chrono::duration<double>(now - _lastPrint).count();
  if (sincePrint < (_terminal ? 0.25 : _logInterval))
    return;
  _lastPrint = now;
  const double elapsed = std::chrono::duration<double>(now - _start).count();
  const double rate = elapsed > 0 ? static_cast<double>(step - _firstStep) / elapsed : 0.0;
  // from the progress made by this process: a restarted run does not count the time before it
  const double done = simulatedTime - _firstTime;
  const double eta = done > 0 ? elapsed * (_endTime - simulatedTime) / done : -1.0;
  const std::string text = format(simulatedTime, _endTime, rate, eta, note);
  if (_terminal) {
    std::fprintf(stderr, "\r[%s] %s\x1b[K", _label.c_str(), text.c_str());
    std::fflush(stderr);
  } else {
    spdlog::info("{}: {}", _label, text);
  }
}

void Progress::finish() {
  _finished = true;
  const double elapsed = std::chrono::duration<double>(Clock::now() - _start).count();
  const double steps = _firstStep < 0 ? 0.0 : static_cast<double>(_lastStep - _firstStep);
  if (_terminal)
    std::fprintf(stderr, "\r\x1b[K");
  spdlog::info("{}: done, t = {:.3f} s, {:.0f} steps in {} ({:.3g} steps/s)", _label, _lastTime,
               steps, formatDuration(elapsed), elapsed > 0 ? steps / elapsed : 0.0);
}

} // namespace hikiln::log
