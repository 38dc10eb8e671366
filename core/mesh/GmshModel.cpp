#include "core/mesh/GmshModel.hpp"

#include <gmsh.h>

#include <algorithm>
#include <vector>

namespace contactlab {
namespace {

int modelCounter = 0;

}  // namespace

GmshModel::GmshModel() : name_("contactlab-" + std::to_string(++modelCounter)) {
  try {
    gmsh::model::getCurrent(previous_);
    gmsh::model::add(name_);
  } catch (const std::string& msg) {
    throw std::runtime_error("gmsh could not create a model: " + msg);
  }
}

GmshModel::~GmshModel() {
  try {
    gmsh::model::setCurrent(name_);
    gmsh::model::remove();
    std::vector<std::string> names;
    gmsh::model::list(names);
    if (std::find(names.begin(), names.end(), previous_) != names.end())
      gmsh::model::setCurrent(previous_);
  } catch (...) {
    // A destructor must not throw; a leftover scratch model only costs memory.
  }
}

}  // namespace contactlab
