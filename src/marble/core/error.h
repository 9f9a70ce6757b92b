#pragma once
// Errors a user can cause (bad files, bad values). They carry one line:
// "<file>: <place>: <problem>", which the CLI prints before exiting with code 2
// and the viewer shows in its panel.
#include <stdexcept>
#include <string>

namespace marble {

class InputError : public std::runtime_error {
public:
  InputError(const std::string& file, const std::string& place, const std::string& problem)
      : std::runtime_error(compose(file, place, problem)) {}
  explicit InputError(const std::string& line) : std::runtime_error(line) {}

private:
  static std::string compose(const std::string& file, const std::string& place, const std::string& problem) {
    std::string s = file;
    if (!place.empty()) s += ": " + place;
    return s + ": " + problem;
  }
};

// Something the environment lacks (no display, no EGL, GL too old): also one line, exit code 1.
class EnvironmentError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

}  // namespace marble
