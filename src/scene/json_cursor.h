#pragma once
// A position in a JSON document with its path ("objects[3].convex[2]"), so that
// every value read can be checked and every failure named precisely.

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "penumbra/geometry/kernel.h"

namespace penumbra::detail {

class JsonCursor {
 public:
  JsonCursor(const nlohmann::json& value, std::string path, const std::string& file,
             std::vector<std::string>* warnings)
      : value_(&value), path_(std::move(path)), file_(&file), warnings_(warnings) {}

  const nlohmann::json& value() const { return *value_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }

  // throws InputError at this path.
  [[noreturn]] void fail(const std::string& message) const;

  bool has(const char* key) const { return value_->is_object() && value_->contains(key); }
  // returns the required member key (fails when missing or when this is not an object).
  JsonCursor at(const char* key) const;
  // returns the member key when present.
  std::optional<JsonCursor> find(const char* key) const;
  // returns element i of an array.
  JsonCursor at(std::size_t i) const;
  // returns the elements of an array (fails when this is not one).
  std::vector<JsonCursor> elements() const;
  // returns the members of an object, in document order of their keys.
  std::vector<std::pair<std::string, JsonCursor>> members() const;

  void require_object() const;
  double number() const;           // finite
  double positive_number() const;  // finite, > 0
  double non_negative_number() const;
  double number_in(double low, double high) const;  // finite, low <= x <= high
  int positive_integer() const;
  bool boolean() const;
  std::string string() const;
  Vec3d vec3() const;       // [x, y, z], finite
  Vec3d direction() const;  // [x, y, z], finite, not the zero vector (as written)
  std::vector<Vec3d> points(std::size_t at_least) const;

  // records a warning for every member whose key is not in known.
  void warn_unknown_keys(std::initializer_list<const char*> known) const;

 private:
  const nlohmann::json* value_;
  std::string path_;
  const std::string* file_;
  std::vector<std::string>* warnings_;
};

}  // namespace penumbra::detail
