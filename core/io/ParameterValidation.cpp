#include "core/io/ParameterValidation.hpp"

#include "base/InputError.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_StrUtils.hpp>

#include <cmath>
#include <sstream>

namespace contactlab {
namespace {

using Teuchos::Array;
using Teuchos::ParameterEntry;
using Teuchos::ParameterList;

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "/" + key;
}

std::string typeName(const ParameterEntry& e) {
  if (e.isType<double>()) return "a number";
  if (e.isType<int>()) return "an integer";
  if (e.isType<bool>()) return "true or false";
  if (e.isType<std::string>()) return "a string";
  if (e.isType<Array<double>>()) return "a list of numbers";
  if (e.isType<Array<int>>()) return "a list of integers";
  if (e.isList()) return "a sublist";
  return "a value of type " + e.getAny(false).typeName();
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

bool parseDouble(const std::string& text, double& value) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  char* end = nullptr;
  value = std::strtod(t.c_str(), &end);
  return end && *end == '\0';
}

bool parseInt(const std::string& text, int& value) {
  double d = 0;
  if (!parseDouble(text, d) || d != std::floor(d) || std::fabs(d) > 2e9) return false;
  value = static_cast<int>(d);
  return true;
}

bool parseBool(const std::string& text, bool& value) {
  const std::string t = trim(text);
  if (t == "true" || t == "yes" || t == "on" || t == "1") return value = true, true;
  if (t == "false" || t == "no" || t == "off" || t == "0") return value = false, true;
  return false;
}

template <class T>
bool parseArray(std::string text, Array<T>& out, bool (*parse)(const std::string&, T&)) {
  text = trim(text);
  if (!text.empty() && text.front() == '[') text = text.substr(1);
  if (!text.empty() && text.back() == ']') text.pop_back();
  out.clear();
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    T v;
    if (!parse(item, v)) return false;
    out.push_back(v);
  }
  return !out.empty();
}

std::string valueText(const ParameterEntry& e) {
  std::ostringstream s;
  e.getAny(false).print(s);
  return s.str();
}

// Converts `entry` in place to the type of `valid`; returns false when it cannot.
bool coerce(ParameterEntry& entry, const ParameterEntry& valid) {
  if (entry.getAny(false).type() == valid.getAny(false).type()) return true;
  const bool isString = entry.isType<std::string>();
  const std::string text = isString ? Teuchos::getValue<std::string>(entry) : "";
  if (valid.isType<double>()) {
    double v;
    if (entry.isType<int>())
      v = Teuchos::getValue<int>(entry);
    else if (!isString || !parseDouble(text, v))
      return false;
    entry.setValue(v);
  } else if (valid.isType<int>()) {
    int v;
    if (entry.isType<double>()) {
      const double d = Teuchos::getValue<double>(entry);
      if (d != std::floor(d)) return false;
      v = static_cast<int>(d);
    } else if (!isString || !parseInt(text, v)) {
      return false;
    }
    entry.setValue(v);
  } else if (valid.isType<bool>()) {
    bool v;
    if (!isString || !parseBool(text, v)) return false;
    entry.setValue(v);
  } else if (valid.isType<std::string>()) {
    // YAML reads `true` as a bool: a choice among strings may still be "true" or "false".
    if (entry.isType<int>())
      entry.setValue(std::to_string(Teuchos::getValue<int>(entry)));
    else if (entry.isType<bool>())
      entry.setValue(std::string(Teuchos::getValue<bool>(entry) ? "true" : "false"));
    else
      return false;
  } else if (valid.isType<Array<double>>()) {
    Array<double> v;
    if (entry.isType<Array<int>>()) {
      for (int i : Teuchos::getValue<Array<int>>(entry))
        v.push_back(i);
    } else if (!isString || !parseArray<double>(text, v, parseDouble)) {
      return false;
    }
    entry.setValue(v);
  } else if (valid.isType<Array<int>>()) {
    Array<int> v;
    if (!isString || !parseArray<int>(text, v, parseInt)) return false;
    entry.setValue(v);
  } else if (valid.isType<Array<std::string>>()) {
    // A --set value "[a, b]" (or one name).
    Array<std::string> v;
    const auto name = [](const std::string& item, std::string& out) {
      out = trim(item);
      return !out.empty();
    };
    if (!isString || !parseArray<std::string>(text, v, name)) return false;
    entry.setValue(v);
  } else {
    return false;
  }
  return true;
}

std::string validChoices(const ParameterEntry& valid) {
  auto validator = valid.validator();
  if (validator.is_null()) return "";
  auto strings = validator->validStringValues();
  if (strings.is_null()) return "";
  std::string s;
  for (const auto& v : *strings)
    s += (s.empty() ? "" : ", ") + v;
  return s;
}

// The name a pass-through valid sublist carries (Teuchos keeps no public flag for it).
const char* const kPassThroughName = "contactlab:pass-through";

// Strings from --set that read as a bool, an int or a double become one (recursively).
void typeStrings(ParameterList& list) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string key = list.name(it);
    ParameterEntry& e = list.getEntry(key);
    if (e.isList()) {
      typeStrings(list.sublist(key));
      continue;
    }
    if (!e.isType<std::string>()) continue;
    const std::string text = e.getValue<std::string>(nullptr);
    int i;
    double d;
    if (text == "true" || text == "false")
      e.setValue(text == "true");
    else if (text.find_first_of(".eE") == std::string::npos && parseInt(text, i))
      e.setValue(i);
    else if (parseDouble(text, d))
      e.setValue(d);
  }
}

}  // namespace

ParameterList& markPassThrough(ParameterList& valid) {
  valid.setName(kPassThroughName);
  return valid.disableRecursiveValidation();
}

bool isPassThrough(const ParameterList& valid) {
  return valid.name() == kPassThroughName;
}

std::string keysOf(const ParameterList& list) {
  std::string s;
  for (auto it = list.begin(); it != list.end(); ++it)
    s += (s.empty() ? "" : ", ") + list.name(it);
  return s.empty() ? "(none)" : s;
}

void validateAndSetDefaults(ParameterList& user, const ParameterList& valid,
                            const std::string& where, const std::string& path) {
  const std::string in = path.empty() ? "at the top level" : "in " + path;
  for (auto it = user.begin(); it != user.end(); ++it) {
    const std::string& key = user.name(it);
    const std::string keyPath = join(path, key);
    if (!valid.isParameter(key))
      throw InputError(where + ": unknown key '" + key + "' " + in +
                       "; valid keys: " + keysOf(valid));
    const ParameterEntry& v = valid.getEntry(key);
    ParameterEntry& u = user.getEntry(key);
    if (v.isList() != u.isList())
      throw InputError(where + ": " + keyPath + " must be " + typeName(v) + ", not " + typeName(u));
    if (v.isList()) {
      if (isPassThrough(valid.sublist(key)))
        typeStrings(user.sublist(key));
      else
        validateAndSetDefaults(user.sublist(key), valid.sublist(key), where, keyPath);
      continue;
    }
    if (!coerce(u, v))
      throw InputError(where + ": " + keyPath + " must be " + typeName(v) + " (got '" +
                       valueText(u) + "')");
    if (auto validator = v.validator(); !validator.is_null()) {
      try {
        validator->validate(u, key, user.name());
      } catch (const std::exception&) {
        const std::string choices = validChoices(v);
        throw InputError(where + ": invalid value '" + valueText(u) + "' for " + keyPath +
                         (choices.empty() ? "" : "; valid choices: " + choices));
      }
    }
  }
  // Defaults for what the user left out.
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& key = valid.name(it);
    if (user.isParameter(key)) continue;
    const ParameterEntry& v = valid.entry(it);
    if (v.isList()) {
      ParameterList& sub = user.sublist(key);
      validateAndSetDefaults(sub, valid.sublist(key), where, join(path, key));
    } else {
      // Marked as a default (ParameterEntry::isDefault): a reader may tell a value left out
      // from the same value given.
      user.setEntry(key, v);
      user.getEntry(key).setAnyValue(v.getAny(), true);
    }
  }
}

void applyOverride(ParameterList& list, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(
        "--set expects key=value with a '/'-separated key path, e.g. "
        "Mesh/rectangle/nx=20 (got '" +
        assignment + "')");
  const std::string keyPath = assignment.substr(0, eq);
  const std::string value = assignment.substr(eq + 1);
  ParameterList* current = &list;
  std::string key;
  std::stringstream ss(keyPath);
  std::vector<std::string> parts;
  while (std::getline(ss, key, '/'))
    parts.push_back(key);
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (current->isParameter(parts[i]) && !current->isSublist(parts[i]))
      throw InputError("--set " + keyPath + ": '" + parts[i] + "' is a value, not a sublist");
    current = &current->sublist(parts[i]);
  }
  const std::string& last = parts.back();
  if (current->isSublist(last))
    throw InputError("--set " + keyPath + ": '" + last + "' is a sublist, not a value");
  ParameterEntry entry(value);
  if (current->isParameter(last)) {
    const ParameterEntry& old = current->getEntry(last);
    if (!coerce(entry, old))
      throw InputError("--set " + keyPath + ": '" + value + "' is not " + typeName(old));
  }
  current->setEntry(last, entry);
}

}  // namespace contactlab
