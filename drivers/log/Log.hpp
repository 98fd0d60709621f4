#pragma once
/// \file Log.hpp
/// \brief Levelled logging for every stage (spdlog underneath): `hikiln -v` shows debug lines,
/// `hikiln -q` only warnings and errors.

#include <spdlog/spdlog.h>

#include <string>

namespace hikiln::log {

/// \brief Sets the global level from a name (trace, debug, info, warn, error, off); throws
/// std::invalid_argument naming the accepted values for anything else.
void setLevel(const std::string& level);

/// \brief Configures the default logger: "[hikiln] [level] message" on stderr.
void configure(const std::string& level = "info");

} // namespace hikiln::log
