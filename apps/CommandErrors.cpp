#include "apps/CommandErrors.hpp"

#include "base/InputError.hpp"

#include <mpi.h>

#include <iostream>
#include <new>
#include <string>

namespace contactlab {
namespace {

int escaped(const Teuchos::Comm<int>& comm, const std::string& what, int code) {
  std::cerr << "contactlab: error: " << what << "\n";
  if (comm.getSize() > 1) MPI_Abort(MPI_COMM_WORLD, code);
  return code;
}

}  // namespace

int withErrorsReported(const Teuchos::Comm<int>& comm, const std::function<int()>& command) {
  try {
    return command();
  } catch (const InputError& e) {
    return escaped(comm, e.what(), 2);
  } catch (const std::bad_alloc&) {
    return escaped(comm, "out of memory (the model is too large for this machine)", 1);
  } catch (const std::exception& e) {
    return escaped(comm, e.what(), 1);
  } catch (const std::string& e) {  // gmsh throws strings
    return escaped(comm, "gmsh: " + e, 1);
  } catch (const char* e) {
    return escaped(comm, std::string("gmsh: ") + e, 1);
  } catch (...) {
    return escaped(comm, "an unknown error stopped the run", 1);
  }
}

}  // namespace contactlab
