#pragma once
// The typed exception for bad input (STYLE.md habit 6): it carries the file and
// the place inside it (a JSON path such as "objects[3].convex[2]", or "line 12"),
// and is caught once, in the command line, which prints it and exits with status 2.

#include <stdexcept>
#include <string>

namespace penumbra {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string location, const std::string& message)
      : std::runtime_error(format(file, location, message)),
        file_(std::move(file)),
        location_(std::move(location)),
        message_(message) {}

  const std::string& file() const { return file_; }
  // the JSON path or "line N" inside the file; empty when the whole file is meant.
  const std::string& location() const { return location_; }
  const std::string& message() const { return message_; }

 private:
  static std::string format(const std::string& file, const std::string& location,
                            const std::string& message) {
    std::string text = file.empty() ? std::string("<input>") : file;
    if (!location.empty()) text += ": " + location;
    return text + ": " + message;
  }

  std::string file_;
  std::string location_;
  std::string message_;
};

}  // namespace penumbra
