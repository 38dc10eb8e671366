#pragma once
// RAII guard around gmsh::initialize / gmsh::finalize. gmsh is one global library state, so
// sessions nest: only the outermost one initialises and finalises. gmsh is started silent,
// without reading the user's gmshrc (results must not depend on it) and without command-line
// arguments (gmsh would otherwise try to consume ours). Not thread-safe beyond the counter:
// gmsh itself must only be used by one thread.
namespace contactlab {

class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  // True while at least one session is alive.
  static bool active();
};

}  // namespace contactlab
