#include "json_cursor.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "penumbra/base/input_error.h"

namespace penumbra::detail {
namespace {

const char* type_name(const nlohmann::json& value) {
  return value.type_name();
}

std::string format_bound(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

}  // namespace

void JsonCursor::fail(const std::string& message) const {
  throw InputError(*file_, path_, message);
}

void JsonCursor::require_object() const {
  if (!value_->is_object()) fail(std::string("expected an object, found ") + type_name(*value_));
}

JsonCursor JsonCursor::at(const char* key) const {
  require_object();
  const auto it = value_->find(key);
  if (it == value_->end()) fail(std::string("missing required key \"") + key + "\"");
  return JsonCursor(*it, path_.empty() ? key : path_ + "." + key, *file_, warnings_);
}

std::optional<JsonCursor> JsonCursor::find(const char* key) const {
  require_object();
  const auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return JsonCursor(*it, path_.empty() ? key : path_ + "." + key, *file_, warnings_);
}

JsonCursor JsonCursor::at(std::size_t i) const {
  return JsonCursor((*value_)[i], path_ + "[" + std::to_string(i) + "]", *file_, warnings_);
}

std::vector<JsonCursor> JsonCursor::elements() const {
  if (!value_->is_array()) fail(std::string("expected an array, found ") + type_name(*value_));
  std::vector<JsonCursor> result;
  for (std::size_t i = 0; i < value_->size(); ++i) result.push_back(at(i));
  return result;
}

std::vector<std::pair<std::string, JsonCursor>> JsonCursor::members() const {
  require_object();
  std::vector<std::pair<std::string, JsonCursor>> result;
  for (auto it = value_->begin(); it != value_->end(); ++it)
    result.emplace_back(
        it.key(), JsonCursor(it.value(), path_.empty() ? it.key() : path_ + "." + it.key(), *file_,
                             warnings_));
  return result;
}

double JsonCursor::number() const {
  if (!value_->is_number()) fail(std::string("expected a number, found ") + type_name(*value_));
  const double x = value_->get<double>();
  if (!std::isfinite(x)) fail("the number is not finite");
  return x;
}

double JsonCursor::positive_number() const {
  const double x = number();
  if (!(x > 0)) fail("must be greater than 0, found " + value_->dump());
  return x;
}

double JsonCursor::non_negative_number() const {
  const double x = number();
  if (x < 0) fail("must not be negative, found " + value_->dump());
  return x;
}

double JsonCursor::number_in(double low, double high) const {
  const double x = number();
  if (x < low || x > high)
    fail("must lie in [" + format_bound(low) + ", " + format_bound(high) + "], found " +
         value_->dump());
  return x;
}

int JsonCursor::positive_integer() const {
  const double x = number();
  if (!value_->is_number_integer() || x < 1 || x > std::numeric_limits<int>::max())
    fail("expected a positive integer, found " + value_->dump());
  return static_cast<int>(x);
}

bool JsonCursor::boolean() const {
  if (!value_->is_boolean())
    fail(std::string("expected true or false, found ") + type_name(*value_));
  return value_->get<bool>();
}

std::string JsonCursor::string() const {
  if (!value_->is_string()) fail(std::string("expected a string, found ") + type_name(*value_));
  return value_->get<std::string>();
}

Vec3d JsonCursor::vec3() const {
  if (!value_->is_array() || value_->size() != 3)
    fail("expected an array of 3 numbers [x, y, z], found " + value_->dump());
  return {at(std::size_t{0}).number(), at(1).number(), at(2).number()};
}

Vec3d JsonCursor::direction() const {
  const Vec3d v = vec3();
  if (v[0] == 0 && v[1] == 0 && v[2] == 0) fail("a direction must not be the zero vector");
  return v;
}

std::vector<Vec3d> JsonCursor::points(std::size_t at_least) const {
  std::vector<Vec3d> result;
  for (const JsonCursor& element : elements()) result.push_back(element.vec3());
  if (result.size() < at_least)
    fail("expected at least " + std::to_string(at_least) + " points, found " +
         std::to_string(result.size()));
  return result;
}

void JsonCursor::warn_unknown_keys(std::initializer_list<const char*> known) const {
  if (!value_->is_object() || warnings_ == nullptr) return;
  for (auto it = value_->begin(); it != value_->end(); ++it) {
    bool found = false;
    for (const char* key : known) found = found || it.key() == key;
    if (!found)
      warnings_->push_back(*file_ + ": " + (path_.empty() ? "" : path_ + ".") + it.key() +
                           ": unknown key, ignored");
  }
}

}  // namespace penumbra::detail
