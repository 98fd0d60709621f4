#include "drivers/dem/SweepStudy.hpp"

#include "drivers/case/CaseError.hpp"
#include "drivers/dem/DemCase.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <regex>

namespace hikiln::dem {

namespace {

[[noreturn]] void fail(const std::string& path, const YAML::Node& node, const std::string& what) {
  const auto mark = node.Mark();
  if (mark.line >= 0) {
    throw std::runtime_error(
        fmt::format("{}:{}:{}: {}", path, mark.line + 1, mark.column + 1, what));
  }
  throw std::runtime_error(fmt::format("{}: {}", path, what));
}

std::vector<std::string> overridesOf(const std::string& path, const YAML::Node& map,
                                     const std::string& where) {
  std::vector<std::string> out;
  if (!map)
    return out;
  if (!map.IsMap())
    fail(path, map, where + " must be a map of dotted keys to values");
  for (const auto& kv : map) {
    const auto key = kv.first.as<std::string>();
    if (!kv.second.IsScalar())
      fail(path, kv.second, fmt::format("{}: '{}' must be a single value", where, key));
    out.push_back(key + "=" + kv.second.Scalar());
  }
  return out;
}

} // namespace

SweepStudy loadSweepStudy(const std::string& path, const std::vector<std::string>& extra) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw std::runtime_error(path + ": cannot open study file");
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(fmt::format("{}:{}:{}: malformed YAML: {}", path, e.mark.line + 1,
                                         e.mark.column + 1, e.msg));
  }
  if (!root.IsMap())
    fail(path, root, "a study file is a map with keys base, defaults, cases");
  for (const auto& kv : root) {
    const auto key = kv.first.as<std::string>();
    if (key != "base" && key != "defaults" && key != "cases") {
      fail(path, kv.first,
           fmt::format("unknown key '{}' (a study has base, defaults, cases)", key));
    }
  }
  if (!root["base"] || !root["base"].IsScalar())
    fail(path, root, "missing 'base: CASE_FILE'");
  if (!root["cases"] || !root["cases"].IsMap() || root["cases"].size() == 0) {
    fail(path, root, "missing 'cases:' (a map of case name -> overrides)");
  }
  SweepStudy study;
  study.source = path;
  const std::filesystem::path base(root["base"].Scalar());
  study.baseCase = base.is_absolute() ? base.string()
                                      : (std::filesystem::path(path).parent_path() / base).string();
  const auto defaults = overridesOf(path, root["defaults"], "defaults");
  const std::regex safeName("[A-Za-z0-9_.-]+");
  for (const auto& kv : root["cases"]) {
    SweepCase c;
    c.name = kv.first.as<std::string>();
    if (!std::regex_match(c.name, safeName) || c.name == "." || c.name == "..") {
      fail(path, kv.first,
           fmt::format("case name '{}' must use letters, digits, '_', '-', '.'", c.name));
    }
    c.overrides = defaults;
    for (auto& o : overridesOf(path, kv.second, "case '" + c.name + "'"))
      c.overrides.push_back(o);
    for (const auto& o : extra)
      c.overrides.push_back(o);
    try {
      cases::CaseFile::load(study.baseCase, demSchema(), c.overrides);
    } catch (const cases::CaseError& e) {
      throw std::runtime_error(fmt::format("{}: case '{}': {}", path, c.name, e.what()));
    }
    study.cases.push_back(std::move(c));
  }
  return study;
}

} // namespace hikiln::dem
