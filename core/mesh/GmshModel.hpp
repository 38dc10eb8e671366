#pragma once
// Internal to core/mesh: a scratch gmsh model for one reader/generator call, so that calls
// nest inside a caller's own gmsh session without touching its models.
#include "core/mesh/GmshSession.hpp"

#include <stdexcept>
#include <string>

namespace contactlab {

// Creates a fresh current model; on destruction removes it and restores the previous current.
class GmshModel {
 public:
  GmshModel();
  ~GmshModel();
  GmshModel(const GmshModel&) = delete;
  GmshModel& operator=(const GmshModel&) = delete;

 private:
  GmshSession session_;
  std::string name_;
  std::string previous_;
};

// Runs `build` in a scratch model. gmsh 4.8 reports errors by throwing std::string; they are
// turned into std::runtime_error("<context>: <gmsh's message>"). Inside gmsh's OpenMP meshing
// loops a throw cannot leave (it would end the process), so the session makes gmsh abort the
// meshing there instead (GmshSession): the incomplete mesh is then refused by the checks of
// meshFromGmshModel, with one sentence.
template <class F>
auto inGmshModel(const std::string& context, F&& build) {
  GmshModel model;
  try {
    return build();
  } catch (const std::string& msg) {
    throw std::runtime_error(context + ": " + msg);
  }
}

}  // namespace contactlab
