#pragma once
// Errors a user can cause (bad files, bad values). They carry one line:
// "<file>: <place>: <problem>", which the CLI prints before exiting with code 2
// and the viewer shows in its panel. Every part goes through printable()
// (core/message_text.h): no line break, terminal escape or NUL from a file or a user string
// reaches the terminal, and no part is longer than kMessagePartLimit (the problem, which may
// nest the message of a file this one referenced, up to kMessageLineLimit).
#include <stdexcept>
#include <string>

#include "marble/core/message_text.h"

namespace marble {

class InputError : public std::runtime_error {
public:
  InputError(const std::string& file, const std::string& place, const std::string& problem)
      : std::runtime_error(compose(file, place, problem)) {}
  explicit InputError(const std::string& line) : std::runtime_error(printable(line, kMessageLineLimit)) {}

private:
  static std::string compose(const std::string& file, const std::string& place, const std::string& problem) {
    std::string s = printable(file);
    if (!place.empty()) s += ": " + printable(place);
    return s + ": " + printable(problem, kMessageLineLimit);
  }
};

// Something the environment lacks (no display, no EGL, GL too old, not enough memory): also one
// line, exit code 1.
class EnvironmentError : public std::runtime_error {
public:
  explicit EnvironmentError(const std::string& line) : std::runtime_error(printable(line, kMessageLineLimit)) {}
};

}  // namespace marble
