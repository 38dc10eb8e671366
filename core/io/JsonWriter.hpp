#pragma once
// A minimal JSON value for summary.json: null, booleans, numbers, strings, arrays and objects
// whose keys keep their insertion order (so the file reads in the order it was built).
// Doubles are written with 17 significant digits; NaN and infinities become null, because
// JSON has no spelling for them.
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace contactlab {

class JsonValue {
 public:
  enum class Kind { Null, Bool, Integer, Number, String, Array, Object };

  JsonValue() = default;  // null
  JsonValue(std::nullptr_t) {}
  JsonValue(bool value) : kind_(Kind::Bool), bool_(value) {}
  JsonValue(double value) : kind_(Kind::Number), number_(value) {}
  // Every integer type except bool, kept exact (64-bit counts such as dofs).
  template <class Int,
            class = std::enable_if_t<std::is_integral_v<Int> && !std::is_same_v<Int, bool>>>
  JsonValue(Int value) : kind_(Kind::Integer), integer_(static_cast<std::int64_t>(value)) {}
  JsonValue(const char* text) : kind_(Kind::String), string_(text) {}
  JsonValue(std::string text) : kind_(Kind::String), string_(std::move(text)) {}

  static JsonValue object() { return JsonValue(Kind::Object); }
  static JsonValue array() { return JsonValue(Kind::Array); }
  template <class T>
  static JsonValue array(const std::vector<T>& values) {
    JsonValue a = array();
    for (const auto& v : values)
      a.push(JsonValue(v));
    return a;
  }

  Kind kind() const { return kind_; }
  bool isNull() const { return kind_ == Kind::Null; }
  std::size_t size() const { return items_.size(); }  // array items or object members

  // Object: sets `key` (replacing its value in place if present, else appending); returns
  // *this for chaining. A null value becomes an empty object first.
  JsonValue& set(const std::string& key, JsonValue value);
  // Object member access, inserting null when absent (a null value becomes an object).
  JsonValue& operator[](const std::string& key);
  // Array: appends; returns *this. A null value becomes an empty array first.
  JsonValue& push(JsonValue value);

  // Pretty-printed with `indent` spaces per level; indent < 0 gives one compact line.
  std::string dump(int indent = 2) const;
  // Writes dump(indent) plus a newline to `path` atomically (AtomicFile.hpp).
  void write(const std::string& path, int indent = 2) const;

 private:
  explicit JsonValue(Kind kind) : kind_(kind) {}
  void becomeIfNull(Kind kind, const char* operation);
  void dumpTo(std::string& out, int indent, int depth) const;

  Kind kind_ = Kind::Null;
  bool bool_ = false;
  std::int64_t integer_ = 0;
  double number_ = 0.0;
  std::string string_;
  std::vector<std::string> keys_;  // objects: keys_[i] names items_[i]
  std::vector<JsonValue> items_;
};

}  // namespace contactlab
