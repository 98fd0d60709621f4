#pragma once
/// \file YamlText.hpp
/// \brief A small writer of commented YAML text (yaml-cpp's emitter cannot align comments and
/// prints doubles with 17 digits); numbers come out in their shortest exact form.

#include <sstream>
#include <string>
#include <vector>

namespace hikiln::calibration {

/// \brief A double as a YAML scalar: shortest round-trip form, .nan / .inf / -.inf.
std::string yamlNumber(double value);

/// \brief A string as a double-quoted YAML scalar (JSON escaping, which YAML accepts).
std::string yamlString(const std::string& value);

/// \brief A flow sequence of numbers: [1, 2.5, .nan].
std::string yamlNumberList(const std::vector<double>& values);

/// \brief Builds YAML line by line with two-space indentation and right-hand comments.
class YamlText {
public:
  /// \brief Appends "# text" at the current indentation (an empty text gives a bare "#").
  void comment(const std::string& text);
  /// \brief Appends "key:" and indents what follows until close().
  void open(const std::string& key, const std::string& commentText = "");
  /// \brief Ends the innermost open().
  void close();
  /// \brief Appends "- " + the next key: starts a mapping inside a sequence (close() ends it).
  void openListItem();
  /// \brief Appends "key: value  # comment" (the comment column is aligned).
  void entry(const std::string& key, const std::string& value, const std::string& commentText = "");
  /// \brief The document so far.
  std::string str() const { return _out.str(); }

private:
  std::string indentation() const;
  std::ostringstream _out;
  int _depth = 0;
  bool _listItemPending = false;
};

} // namespace hikiln::calibration
