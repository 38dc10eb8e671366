#include "core/mesh/GmshSession.hpp"

#include <gmsh.h>

#include <mutex>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

std::mutex sessionMutex;
int sessionCount = 0;

}  // namespace

GmshSession::GmshSession() {
  std::lock_guard<std::mutex> lock(sessionMutex);
  if (sessionCount == 0) {
    try {
      gmsh::initialize(0, nullptr, false);
      // gmsh reports errors by throwing; printing them as well would only clutter the output.
      gmsh::option::setNumber("General.Terminal", 0);
      gmsh::option::setNumber("General.Verbosity", 1);
      // An error aborts the meshing instead of throwing from inside gmsh's OpenMP loops,
      // which no caller can catch (inGmshModel reads it from the log).
      gmsh::option::setNumber("General.AbortOnError", 1);
    } catch (const std::string& msg) {
      throw std::runtime_error("gmsh could not be initialised: " + msg);
    }
  }
  ++sessionCount;
}

GmshSession::~GmshSession() {
  std::lock_guard<std::mutex> lock(sessionMutex);
  if (--sessionCount == 0) {
    try {
      gmsh::finalize();
    } catch (...) {
      // Nothing sensible to do in a destructor; gmsh's state is gone either way.
    }
  }
}

bool GmshSession::active() {
  std::lock_guard<std::mutex> lock(sessionMutex);
  return sessionCount > 0;
}

}  // namespace contactlab
