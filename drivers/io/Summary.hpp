#pragma once
/// \file Summary.hpp
/// \brief Run summaries: small JSON documents (key numbers, timings, pass/fail) that scripts and
/// the next stage read.

#include <nlohmann/json.hpp>

#include <string>

namespace hikiln::io {

/// \brief Writes `summary` to `path` pretty-printed (2-space indent) and atomically.
void writeSummaryJson(const std::string& path, const nlohmann::json& summary);

/// \brief Parses the JSON file at `path`; throws std::runtime_error naming the path if it is
/// missing or malformed.
nlohmann::json readSummaryJson(const std::string& path);

} // namespace hikiln::io
