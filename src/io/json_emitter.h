#pragma once
// One way to write a JSON value, two places it goes (private to io/): a tree of
// nlohmann::json (for the writers that read the document back, and golden comparisons)
// or text in the layout of format_json (shadow_json.h), written directly for files too
// large to hold as trees. The code that describes a value calls the same methods for both;
// object members must be given in the order nlohmann::json keeps them (sorted by key),
// so that both give the same document.

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace penumbra::io {

class JsonEmitter {
 public:
  virtual ~JsonEmitter() = default;
  virtual void begin_object() = 0;
  virtual void end_object() = 0;
  virtual void begin_array() = 0;
  virtual void end_array() = 0;
  // names the next value of the current object.
  virtual void key(const char* name) = 0;
  virtual void number(double value) = 0;
  virtual void integer(std::size_t value) = 0;
  virtual void boolean(bool value) = 0;
  virtual void string(const std::string& value) = 0;
  // emits count values into the current array, value k by write(k, emitter). Here one after
  // the other; an emitter of text writes them apart, across threads, and places them in
  // order (a ground's thousands of polygons).
  virtual void values(std::size_t count,
                      const std::function<void(std::size_t, JsonEmitter&)>& write);
};

// Builds a tree.
class TreeEmitter : public JsonEmitter {
 public:
  void begin_object() override { open(nlohmann::json::object()); }
  void end_object() override { stack_.pop_back(); }
  void begin_array() override { open(nlohmann::json::array()); }
  void end_array() override { stack_.pop_back(); }
  void key(const char* name) override { key_ = name; }
  void number(double value) override { put(value); }
  void integer(std::size_t value) override { put(value); }
  void boolean(bool value) override { put(value); }
  void string(const std::string& value) override { put(value); }

  nlohmann::json& result() { return root_; }

 private:
  nlohmann::json& put(nlohmann::json value);
  void open(nlohmann::json value) { stack_.push_back(&put(std::move(value))); }

  nlohmann::json root_;
  std::vector<nlohmann::json*> stack_;
  std::string key_;
};

// Writes text as format_json lays it out: an object's members on lines of their own,
// indented one space per depth; an array of objects likewise; any other array on one line,
// compact, as nlohmann::json::dump writes it (its number format too). An array's layout
// follows its first element (format_json looks at all of them: the documents written here
// have no array that mixes objects with other values, nor arrays of arrays of objects).
class TextEmitter : public JsonEmitter {
 public:
  // starts at depth (the indentation of the value's closing bracket).
  explicit TextEmitter(std::string& out, int depth = 0) : out_(out), depth_(depth) {}

  void begin_object() override;
  void end_object() override;
  void begin_array() override;
  void end_array() override;
  void key(const char* name) override;
  void number(double value) override;
  void integer(std::size_t value) override;
  void boolean(bool value) override;
  void string(const std::string& value) override;
  void values(std::size_t count,
              const std::function<void(std::size_t, JsonEmitter&)>& write) override;

 private:
  enum class Kind { object, undecided_array, expanded_array, compact_array };
  struct Level {
    Kind kind;
    std::size_t count = 0;
  };
  // prepares for a value: separators and indentation, deciding an array's layout by its
  // first element.
  void before_value(bool is_object);
  void indent(int depth) { out_.append(static_cast<std::size_t>(depth), ' '); }
  int depth() const { return depth_ + static_cast<int>(levels_.size()); }

  std::string& out_;
  int depth_;
  std::vector<Level> levels_;
};

// writes one member "key": value of an object at depth, as format_json lays it out
// (shadow_json.cpp).
void format_member(std::string& out, const std::string& key, const nlohmann::json& value,
                   int depth);

// Writes, as format_json lays it out, a document whose "faces" member is an array too large
// to hold as a tree: begin() writes the header's members that sort before "faces", face()
// each entry, given as text at depth 2 (TextEmitter(text, 2)), end() the members after.
class FacesDocumentWriter {
 public:
  explicit FacesDocumentWriter(std::ostream& out) : out_(out) {}
  void begin(const nlohmann::json& header, std::size_t faces);
  void face(const std::string& text);
  void end();

 private:
  std::ostream& out_;
  nlohmann::json after_faces_;  // the header's keys that sort after "faces"
  std::size_t written_ = 0, faces_ = 0;
};

// writes count face entries to writer in order, each made by text(k, out) into out (at
// depth 2), a block of them at a time across threads: what a document of every face
// holds at once is one block's text.
void write_faces(FacesDocumentWriter& writer, std::size_t count,
                 const std::function<void(std::size_t, std::string&)>& text);

}  // namespace penumbra::io
