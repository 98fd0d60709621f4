#pragma once
/// \file CaseError.hpp
/// \brief The one exception a user sees for a bad case file or a bad `--set`.

#include <stdexcept>
#include <string>
#include <vector>

namespace hikiln::cases {

/// \brief Everything wrong with a case file, one message per line ("file:line:col: reason").
/// Thrown only for mistakes in user input; mistakes in the calling code are std::logic_error.
class CaseError : public std::runtime_error {
public:
  /// \brief Joins `messages` with newlines into what().
  explicit CaseError(std::vector<std::string> messages)
      : std::runtime_error(join(messages)), _messages(std::move(messages)) {}

  /// \brief The individual messages, in the order they were found.
  const std::vector<std::string>& messages() const { return _messages; }

private:
  static std::string join(const std::vector<std::string>& messages) {
    std::string text;
    for (const auto& m : messages)
      text += (text.empty() ? "" : "\n") + m;
    return text;
  }

  std::vector<std::string> _messages;
};

} // namespace hikiln::cases
