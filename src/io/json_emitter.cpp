#include "json_emitter.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "penumbra/base/parallel.h"

namespace penumbra::io {

void JsonEmitter::values(std::size_t count,
                         const std::function<void(std::size_t, JsonEmitter&)>& write) {
  for (std::size_t k = 0; k < count; ++k) write(k, *this);
}

nlohmann::json& TreeEmitter::put(nlohmann::json value) {
  if (stack_.empty()) {
    root_ = std::move(value);
    return root_;
  }
  nlohmann::json& parent = *stack_.back();
  if (parent.is_array()) {
    parent.push_back(std::move(value));
    return parent.back();
  }
  nlohmann::json& member = parent[key_];
  member = std::move(value);
  return member;
}

void TextEmitter::before_value(bool is_object) {
  if (levels_.empty()) return;
  Level& level = levels_.back();
  switch (level.kind) {
    case Kind::object:  // key() placed it
      break;
    case Kind::undecided_array:
      if (is_object) {
        level.kind = Kind::expanded_array;
        out_ += "[\n";
        indent(depth());
      } else {
        level.kind = Kind::compact_array;
        out_ += '[';
      }
      break;
    case Kind::expanded_array:
      out_ += ",\n";
      indent(depth());
      break;
    case Kind::compact_array:
      if (level.count > 0) out_ += ',';
      break;
  }
  ++level.count;
}

void TextEmitter::begin_object() {
  before_value(true);
  out_ += '{';
  levels_.push_back({Kind::object});
}

void TextEmitter::end_object() {
  const bool empty = levels_.back().count == 0;
  levels_.pop_back();
  if (empty) {
    out_ += '}';
    return;
  }
  out_ += '\n';
  indent(depth());
  out_ += '}';
}

void TextEmitter::begin_array() {
  before_value(false);
  levels_.push_back({Kind::undecided_array});
}

void TextEmitter::end_array() {
  const Kind kind = levels_.back().kind;
  levels_.pop_back();
  switch (kind) {
    case Kind::undecided_array:
      out_ += "[]";
      break;
    case Kind::compact_array:
      out_ += ']';
      break;
    default:
      out_ += '\n';
      indent(depth());
      out_ += ']';
  }
}

void TextEmitter::key(const char* name) {
  Level& level = levels_.back();
  out_ += level.count++ > 0 ? ",\n" : "\n";
  indent(depth());
  out_ += '"';
  out_ += name;
  out_ += "\": ";
}

void TextEmitter::number(double value) {
  before_value(false);
  if (!std::isfinite(value)) {
    out_ += "null";
    return;
  }
  // nlohmann::json's own conversion (Grisu2, shortest round trip): the same characters dump()
  // writes.
  std::array<char, 64> buffer;
  char* end = nlohmann::detail::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out_.append(buffer.data(), end);
}

void TextEmitter::integer(std::size_t value) {
  before_value(false);
  out_ += std::to_string(value);
}

void TextEmitter::boolean(bool value) {
  before_value(false);
  out_ += value ? "true" : "false";
}

void TextEmitter::string(const std::string& value) {
  before_value(false);
  out_ += nlohmann::json(value).dump();  // its escaping
}

void TextEmitter::values(std::size_t count,
                         const std::function<void(std::size_t, JsonEmitter&)>& write) {
  // A value of the current array starts where its closing bracket is indented: at this
  // emitter's depth, the array on the stack.
  std::vector<std::string> texts(count);
  for_each_index(
      count, count > 16,
      [&](std::size_t k) {
        TextEmitter emitter(texts[k], depth());
        write(k, emitter);
      },
      8);
  for (const std::string& text : texts) {
    before_value(!text.empty() && text.front() == '{');
    out_ += text;
  }
}

// The document is an object whose keys nlohmann::json keeps sorted: the members before
// "faces" are written at begin(), the faces as they come, the rest at end().
void FacesDocumentWriter::begin(const nlohmann::json& header, std::size_t faces) {
  faces_ = faces;
  std::string text = "{\n";
  for (const auto& [key, value] : header.items()) {
    if (key > "faces") {
      after_faces_[key] = value;
      continue;
    }
    format_member(text, key, value, 0);
    text += ",\n";
  }
  text += " \"faces\": ";
  text += faces == 0 ? "[]" : "[\n";
  out_ << text;
}

void FacesDocumentWriter::face(const std::string& text) {
  out_ << "  " << text << (++written_ < faces_ ? ",\n" : "\n ]");
}

void FacesDocumentWriter::end() {
  std::string text;
  for (const auto& [key, value] : after_faces_.items()) {
    text += ",\n";
    format_member(text, key, value, 0);
  }
  out_ << text << "\n}\n";
}

void write_faces(FacesDocumentWriter& writer, std::size_t count,
                 const std::function<void(std::size_t, std::string&)>& text) {
  constexpr std::size_t kBlock = 256;
  std::vector<std::string> texts;
  for (std::size_t first = 0; first < count; first += kBlock) {
    texts.assign(std::min(kBlock, count - first), std::string());
    for_each_index(texts.size(), true, [&](std::size_t k) { text(first + k, texts[k]); });
    for (const std::string& entry : texts) writer.face(entry);
  }
}

}  // namespace penumbra::io
