#include "drivers/log/Log.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>

#include <stdexcept>

namespace hikiln::log {

void setLevel(const std::string& level) {
  const auto parsed = spdlog::level::from_str(level);
  // from_str maps unknown names to "off"; only accept "off" when it was asked for.
  if (parsed == spdlog::level::off && level != "off") {
    throw std::invalid_argument("unknown log level '" + level +
                                "' (use trace, debug, info, warn, error or off)");
  }
  spdlog::set_level(parsed);
}

void configure(const std::string& level) {
  auto logger = spdlog::stderr_color_mt("hikiln");
  logger->set_pattern("[%n] %^[%l]%$ %v");
  spdlog::set_default_logger(logger);
  setLevel(level);
}

} // namespace hikiln::log
