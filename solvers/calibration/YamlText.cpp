#include "solvers/calibration/YamlText.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace hikiln::calibration {

std::string yamlNumber(double value) {
  if (std::isnan(value))
    return ".nan";
  if (std::isinf(value))
    return value > 0 ? ".inf" : "-.inf";
  std::string text = fmt::format("{}", value);
  // "1e-05" and "3" are valid YAML floats/ints; keep integers looking like reals.
  if (text.find_first_of(".eEn") == std::string::npos)
    text += ".0";
  return text;
}

std::string yamlString(const std::string& value) {
  return nlohmann::json(value).dump();
}

std::string yamlNumberList(const std::vector<double>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    text += (i == 0 ? "" : ", ") + yamlNumber(values[i]);
  return text + "]";
}

std::string YamlText::indentation() const {
  return std::string(static_cast<std::size_t>(2 * _depth), ' ');
}

void YamlText::comment(const std::string& text) {
  _out << indentation() << (text.empty() ? "#" : "# " + text) << "\n";
}

void YamlText::open(const std::string& key, const std::string& commentText) {
  entry(key, "", commentText);
  ++_depth;
}

void YamlText::close() {
  if (_depth > 0)
    --_depth;
}

void YamlText::openListItem() {
  _listItemPending = true;
}

void YamlText::entry(const std::string& key, const std::string& value,
                     const std::string& commentText) {
  std::string line;
  if (_listItemPending) {
    // "- key: value" opens a mapping whose later keys align with `key`.
    line = indentation() + "- " + key + ":";
    _listItemPending = false;
    ++_depth;
  } else {
    line = indentation() + key + ":";
  }
  if (!value.empty())
    line += " " + value;
  if (!commentText.empty())
    line = fmt::format("{:<40} # {}", line, commentText);
  _out << line << "\n";
}

} // namespace hikiln::calibration
