#include "core/io/JsonWriter.hpp"

#include "core/io/AtomicFile.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace contactlab {
namespace {

void appendEscaped(std::string& out, const std::string& text) {
  out += '"';
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\b':
        out += "\\b";
        break;
      case '\f':
        out += "\\f";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buffer[8];
          std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(c));
          out += buffer;
        } else {
          out += c;  // UTF-8 passes through unchanged: JSON text is UTF-8
        }
    }
  }
  out += '"';
}

void newline(std::string& out, int indent, int depth) {
  if (indent < 0) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent * depth), ' ');
}

}  // namespace

void JsonValue::becomeIfNull(Kind kind, const char* operation) {
  if (kind_ == Kind::Null) kind_ = kind;
  if (kind_ != kind)
    throw std::logic_error(std::string("JSON: ") + operation + " on a non-" +
                           (kind == Kind::Object ? "object" : "array"));
}

JsonValue& JsonValue::set(const std::string& key, JsonValue value) {
  (*this)[key] = std::move(value);
  return *this;
}

JsonValue& JsonValue::operator[](const std::string& key) {
  becomeIfNull(Kind::Object, "member access");
  for (std::size_t i = 0; i < keys_.size(); ++i)
    if (keys_[i] == key) return items_[i];
  keys_.push_back(key);
  items_.emplace_back();
  return items_.back();
}

JsonValue& JsonValue::push(JsonValue value) {
  becomeIfNull(Kind::Array, "push");
  items_.push_back(std::move(value));
  return *this;
}

std::string JsonValue::dump(int indent) const {
  std::string out;
  dumpTo(out, indent, 0);
  return out;
}

void JsonValue::write(const std::string& path, int indent) const {
  writeFileAtomically(path, [&](std::ostream& out) { out << dump(indent) << '\n'; });
}

void JsonValue::dumpTo(std::string& out, int indent, int depth) const {
  switch (kind_) {
    case Kind::Null:
      out += "null";
      return;
    case Kind::Bool:
      out += bool_ ? "true" : "false";
      return;
    case Kind::Integer:
      out += std::to_string(integer_);
      return;
    case Kind::Number: {
      if (!std::isfinite(number_)) {
        out += "null";
        return;
      }
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.17g", number_);
      out += buffer;
      return;
    }
    case Kind::String:
      appendEscaped(out, string_);
      return;
    case Kind::Array:
    case Kind::Object:
      break;
  }
  const bool isObject = kind_ == Kind::Object;
  out += isObject ? '{' : '[';
  if (items_.empty()) {
    out += isObject ? '}' : ']';
    return;
  }
  for (std::size_t i = 0; i < items_.size(); ++i) {
    if (i) out += ',';
    newline(out, indent, depth + 1);
    if (isObject) {
      appendEscaped(out, keys_[i]);
      out += indent < 0 ? ":" : ": ";
    }
    items_[i].dumpTo(out, indent, depth + 1);
  }
  newline(out, indent, depth);
  out += isObject ? '}' : ']';
}

}  // namespace contactlab
