#include "drivers/io/Summary.hpp"

#include "drivers/io/AtomicFile.hpp"

#include <fstream>
#include <stdexcept>

namespace hikiln::io {

void writeSummaryJson(const std::string& path, const nlohmann::json& summary) {
  writeTextAtomically(path, summary.dump(2) + "\n");
}

nlohmann::json readSummaryJson(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot open summary '" + path + "'");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw std::runtime_error("summary '" + path + "' is not valid JSON: " + error.what());
  }
}

} // namespace hikiln::io
