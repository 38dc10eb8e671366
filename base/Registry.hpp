#pragma once
// One registry per axis (linear solver, material, formulation, ...): a name maps to a doc
// string, a function returning the valid parameters of that type (each with a default and a
// doc string), and a builder. Scenes pick an entry with `Type: name` and give its parameters in
// a sibling sublist named after the type. Registration is explicit (a register function per
// module, e.g. registerMaterials(); the app's registerAll() calls them all).
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace contactlab {

template <class Product, class... Args>
class Registry {
 public:
  using Builder =
      std::function<std::unique_ptr<Product>(const Teuchos::ParameterList& params, Args...)>;
  struct Entry {
    std::string name;
    std::string doc;
    std::function<Teuchos::RCP<const Teuchos::ParameterList>()> validParameters;
    Builder build;
  };

  explicit Registry(std::string axis) : axis_(std::move(axis)) {}

  const std::string& axis() const { return axis_; }

  void add(Entry entry) {
    if (entries_.count(entry.name)) return;  // registerAll() may run more than once
    names_.push_back(entry.name);
    entries_.emplace(entry.name, std::move(entry));
  }

  bool has(const std::string& name) const { return entries_.count(name) > 0; }

  const Entry& get(const std::string& name) const {
    auto it = entries_.find(name);
    if (it == entries_.end())
      throw std::invalid_argument("unknown " + axis_ + " '" + name +
                                  "'; valid choices: " + joinedNames());
    return it->second;
  }

  // Names in registration order.
  const std::vector<std::string>& names() const { return names_; }

  std::string joinedNames() const {
    std::string s;
    for (const auto& n : names_)
      s += (s.empty() ? "" : ", ") + n;
    return s;
  }

 private:
  std::string axis_;
  std::vector<std::string> names_;
  std::map<std::string, Entry> entries_;
};

}  // namespace contactlab
