#include "drivers/case/CaseFile.hpp"

#include "drivers/case/CaseValue.hpp"
#include "drivers/io/AtomicFile.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <utility>

namespace hikiln::cases {

namespace {

/// Comments are single lines; a stray newline in a doc string would end the comment early.
std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r')
      c = ' ';
  return text;
}

/// Keys nested by dotted path, children in order of first appearance in the schema, so the
/// output is schema order while each section appears exactly once.
struct Tree {
  std::string name;
  std::optional<std::size_t> spec;
  std::vector<Tree> children;

  Tree& child(const std::string& childName) {
    for (auto& c : children)
      if (c.name == childName)
        return c;
    children.push_back(Tree{childName, std::nullopt, {}});
    return children.back();
  }
};

} // namespace

CaseFile::CaseFile(const CaseSchema& schema, std::string source, std::vector<std::string> overrides,
                   std::vector<Value> values, std::vector<Origin> origins)
    : _schema(schema), _source(std::move(source)), _overrides(std::move(overrides)),
      _values(std::move(values)), _origins(std::move(origins)) {}

CaseFile CaseFile::load(const std::string& path, const CaseSchema& schema,
                        const std::vector<std::string>& overrides) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file)
    throw CaseError({path + ": cannot open file: " + std::strerror(errno)});
  std::string text;
  char buffer[8192];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof(buffer), file.get())) > 0)
    text.append(buffer, n);
  if (std::ferror(file.get())) // e.g. the path is a directory
    throw CaseError({path + ": cannot read file: " + std::strerror(errno)});
  return fromString(text, path, schema, overrides);
}

std::size_t CaseFile::indexFor(const std::string& key, ValueType type,
                               ValueType alternative) const {
  const auto index = _schema.indexOf(key);
  if (!index)
    throw std::logic_error("case key '" + key + "' is not in schema '" + _schema.name() + "'");
  const ValueType actual = _schema.specs()[*index].type;
  if (actual != type && actual != alternative)
    throw std::logic_error("case key '" + key + "' of schema '" + _schema.name() + "' is a " +
                           typeName(actual) + ", not a " + typeName(type));
  return *index;
}

double CaseFile::real(const std::string& key) const {
  return std::get<double>(_values[indexFor(key, ValueType::Real, ValueType::Real)]);
}

std::int64_t CaseFile::integer(const std::string& key) const {
  return std::get<std::int64_t>(_values[indexFor(key, ValueType::Integer, ValueType::Integer)]);
}

bool CaseFile::boolean(const std::string& key) const {
  return std::get<bool>(_values[indexFor(key, ValueType::Boolean, ValueType::Boolean)]);
}

const std::string& CaseFile::string(const std::string& key) const {
  return std::get<std::string>(_values[indexFor(key, ValueType::String, ValueType::Choice)]);
}

const std::vector<double>& CaseFile::realList(const std::string& key) const {
  return std::get<std::vector<double>>(
      _values[indexFor(key, ValueType::RealList, ValueType::RealList)]);
}

CaseFile::Origin CaseFile::origin(const std::string& key) const {
  const auto index = _schema.indexOf(key);
  if (!index)
    throw std::logic_error("case key '" + key + "' is not in schema '" + _schema.name() + "'");
  return _origins[*index];
}

std::string CaseFile::valuesText(const std::vector<std::string>& exclude) const {
  std::string out;
  const auto& specs = _schema.specs();
  for (std::size_t i = 0; i < specs.size(); ++i) {
    if (std::find(exclude.begin(), exclude.end(), specs[i].key) != exclude.end())
      continue;
    out += specs[i].key + ": " + detail::formatValue(_values[i]) + "\n";
  }
  return out;
}

std::string CaseFile::resolvedYaml() const {
  std::string out = "# Resolved case for stage '" + oneLine(_schema.name()) +
                    "': every key with its final value.\n# source: " + oneLine(_source) + "\n";
  if (_overrides.empty())
    out += "# overrides: none\n";
  for (const auto& o : _overrides)
    out += "# override: --set " + oneLine(o) + "\n";

  const auto& specs = _schema.specs();
  Tree root;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    Tree* node = &root;
    std::size_t start = 0;
    for (auto dot = specs[i].key.find('.'); dot != std::string::npos;
         dot = specs[i].key.find('.', start)) {
      node = &node->child(specs[i].key.substr(start, dot - start));
      start = dot + 1;
    }
    node->child(specs[i].key.substr(start)).spec = i;
  }

  // Lines first, comments aligned afterwards (to a capped column, so one long list does not push
  // every comment off screen).
  std::vector<std::pair<std::string, std::string>> lines; // text, comment
  const auto emit = [&](const auto& self, const Tree& tree, const std::string& indent) -> void {
    for (const auto& c : tree.children) {
      if (!c.spec) {
        lines.emplace_back(indent + c.name + ":", "");
        self(self, c, indent + "  ");
        continue;
      }
      const KeySpec& spec = specs[*c.spec];
      std::string comment;
      if (!spec.unit.empty())
        comment += "[" + spec.unit + "] ";
      comment += spec.doc;
      if (_origins[*c.spec] == Origin::Default)
        comment += " (default)";
      else if (_origins[*c.spec] == Origin::Override)
        comment += " (--set)";
      const auto first = comment.find_first_not_of(' ');
      lines.emplace_back(indent + c.name + ": " + detail::formatValue(_values[*c.spec]),
                         first == std::string::npos ? "" : oneLine(comment.substr(first)));
    }
  };
  emit(emit, root, "");
  std::size_t column = 0;
  for (const auto& [text, comment] : lines)
    if (!comment.empty())
      column = std::max(column, std::min<std::size_t>(text.size(), 40));
  for (const auto& [text, comment] : lines) {
    out += text;
    if (!comment.empty())
      out += std::string(column > text.size() ? column - text.size() : 0, ' ') + "  # " + comment;
    out += "\n";
  }
  return out;
}

void CaseFile::writeResolved(const std::string& path) const {
  io::writeTextAtomically(path, resolvedYaml());
}

} // namespace hikiln::cases
