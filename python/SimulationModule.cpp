// The Python module's compiled part, contactlab._contactlab: the Simulation (apps/Simulation.hpp)
// with its results as NumPy arrays. The package (python/contactlab/__init__.py) wraps it with
// the conversions a Python user expects (a scene as a dict, overrides as a dict).
//
// MPI and Kokkos start when the module is imported (as `contactlab` does when started alone: an
// isolated singleton with a session directory of its own, apps/MpiSessionDirectory.hpp) and end
// at the interpreter's exit, after every simulation still alive was released.
#include "apps/MpiSessionDirectory.hpp"
#include "apps/Simulation.hpp"
#include "base/InputError.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactProblem.hpp"
#include "linear/LinearSolver.hpp"

#include <Tpetra_Core.hpp>

#include <cstdlib>
#include <dlfcn.h>
#include <memory>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <set>

namespace py = pybind11;
using namespace contactlab;

namespace {

// A Simulation the interpreter holds; released before MPI ends if Python still holds it then.
class SimulationHandle;

// MPI and Kokkos for the interpreter's lifetime.
class Runtime {
 public:
  static Runtime& get() {
    static Runtime* runtime = new Runtime();  // ended by end(), at the interpreter's exit
    return *runtime;
  }
  Teuchos::RCP<const Comm> comm() const {
    if (ended_) throw std::runtime_error("contactlab: MPI has ended (the interpreter is exiting)");
    return Tpetra::getDefaultComm();
  }
  void add(SimulationHandle* h) { handles_.insert(h); }
  void remove(SimulationHandle* h) { handles_.erase(h); }
  void end();

 private:
  Runtime() {
    // Open MPI loads its components with dlopen, which needs libmpi's symbols global; a Python
    // extension is loaded local (mpi4py does the same).
    dlopen("libmpi.so.40", RTLD_NOW | RTLD_GLOBAL | RTLD_NOLOAD);
    if (std::getenv("OMPI_COMM_WORLD_SIZE") == nullptr)
      setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    session_ = std::make_unique<MpiSessionDirectory>();
    Tpetra::initialize(&argc_, &argv_);
  }
  int argc_ = 1;
  char name_[11] = "contactlab";
  char* args_[2] = {name_, nullptr};
  char** argv_ = args_;
  std::unique_ptr<MpiSessionDirectory> session_;
  std::set<SimulationHandle*> handles_;
  bool ended_ = false;
};

class SimulationHandle {
 public:
  explicit SimulationHandle(const SimulationOptions& options) {
    Runtime& runtime = Runtime::get();
    simulation_ = std::make_unique<Simulation>(options, runtime.comm());
    runtime.add(this);
  }
  ~SimulationHandle() { Runtime::get().remove(this); }
  Simulation& operator*() const {
    if (!simulation_) throw std::runtime_error("contactlab: the simulation was released at exit");
    return *simulation_;
  }
  Simulation* operator->() const { return &**this; }
  void release() { simulation_.reset(); }

 private:
  std::unique_ptr<Simulation> simulation_;
};

void Runtime::end() {
  if (ended_) return;
  for (SimulationHandle* h : handles_)
    h->release();
  handles_.clear();
  ended_ = true;
  Tpetra::finalize();
  session_.reset();
}

py::dict reportDict(const RunReport& r) {
  py::dict d;
  d["converged"] = r.converged;
  d["failure"] = r.failure;
  d["message"] = r.message;
  d["steps"] = r.steps;
  d["iterations"] = r.iterations;
  d["linear_solves"] = r.linearSolves;
  d["cuts"] = r.cuts;
  d["status_iterations"] = r.statusIterations;
  d["geometry_iterations"] = r.geometryIterations;
  d["line_search_retries"] = r.lineSearchRetries;
  return d;
}

// An n x columns array from a row-major vector.
py::array_t<double> matrix(const std::vector<double>& values, std::size_t columns) {
  const auto rows = static_cast<py::ssize_t>(columns ? values.size() / columns : 0);
  py::array_t<double> a({rows, static_cast<py::ssize_t>(columns)});
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

template <class T>
py::array_t<T> column(const std::vector<T>& values) {
  py::array_t<T> a(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

// The steps.csv columns a force history needs, by the same names.
py::dict history(const Simulation& s) {
  std::vector<int> step, iterations, cuts, contact, stick, slip;
  std::vector<double> time, residual, normal, force;
  for (const StepResult& r : s.history()) {
    step.push_back(r.step), time.push_back(r.time), iterations.push_back(r.iterations);
    cuts.push_back(r.cuts), residual.push_back(r.residual);
    normal.push_back(r.contact.normalForceMagnitude);
    for (int c = 0; c < 3; ++c)
      force.push_back(r.contact.normalForce[c] + r.contact.tangentialForce[c]);
    contact.push_back(r.contact.contact), stick.push_back(r.contact.stick);
    slip.push_back(r.contact.slip);
  }
  py::dict d;
  d["step"] = column(step);
  d["time"] = column(time);
  d["newton_iterations"] = column(iterations);
  d["cuts"] = column(cuts);
  d["residual"] = column(residual);
  d["normal_force"] = column(normal);
  d["contact_force"] = matrix(force, 3);
  d["contact_points"] = column(contact);
  d["stick_points"] = column(stick);
  d["slip_points"] = column(slip);
  return d;
}

py::dict contactPoints(const Simulation& s) {
  const std::vector<ContactPointResult> points = s.contactPoints();
  const Mesh& mesh = *s.scene().model.mesh;
  py::list zone;
  std::vector<std::int64_t> node;
  std::vector<int> status;
  std::vector<double> x, reference, gap, pressure, weight, traction, slip, normal;
  for (const ContactPointResult& p : points) {
    zone.append(s.scene().contact[p.zone].name);
    node.push_back(mesh.nodeId(p.node));
    x.insert(x.end(), p.x.begin(), p.x.end());
    reference.insert(reference.end(), &mesh.coords[3 * p.node], &mesh.coords[3 * p.node] + 3);
    gap.push_back(p.paired ? p.gap : std::numeric_limits<double>::quiet_NaN());
    pressure.push_back(p.pressure);
    weight.push_back(p.weight);
    traction.insert(traction.end(), p.traction.begin(), p.traction.end());
    slip.insert(slip.end(), p.slip.begin(), p.slip.end());
    normal.insert(normal.end(), p.normal.begin(), p.normal.end());
    status.push_back(outputStatus(p));
  }
  py::dict d;
  d["zone"] = zone;
  d["node"] = column(node);
  d["x"] = matrix(x, 3);
  d["reference"] = matrix(reference, 3);
  d["gap"] = column(gap);
  d["pressure"] = column(pressure);
  d["weight"] = column(weight);
  d["traction"] = matrix(traction, 3);
  d["slip"] = matrix(slip, 3);
  d["normal"] = matrix(normal, 3);
  d["status"] = column(status);
  return d;
}

}  // namespace

PYBIND11_MODULE(_contactlab, m) {
  m.doc() = "contactlab's Simulation (the compiled part of the contactlab package)";
  static py::exception<InputError> inputError(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      inputError(e.what());
    } catch (const LinearSolverError& e) {
      inputError(e.what());
    }
  });
  Runtime::get();
  m.add_object("_end", py::cpp_function([] { Runtime::get().end(); }));
  py::module_::import("atexit").attr("register")(m.attr("_end"));
  m.def(
      "ranks", [] { return Runtime::get().comm()->getSize(); }, "The number of MPI ranks.");
  m.def(
      "rank", [] { return Runtime::get().comm()->getRank(); }, "This process's MPI rank.");

  py::class_<SimulationHandle>(m, "Simulation")
      .def(py::init([](const std::string& scenePath, const std::string& sceneText,
                       const std::vector<std::string>& overrides, const std::string& out,
                       bool quiet, const std::string& restart, bool validateOnly, bool criticalMu) {
             SimulationOptions o;
             o.scenePath = scenePath;
             o.sceneText = sceneText;
             o.overrides = overrides;
             o.outputDirectory = out;
             o.quiet = quiet;
             o.restartDirectory = restart;
             o.validateOnly = validateOnly;
             o.criticalMu = criticalMu;
             return std::make_unique<SimulationHandle>(o);
           }),
           py::arg("scene_path"), py::arg("scene_text"), py::arg("overrides"), py::arg("out"),
           py::arg("quiet"), py::arg("restart"), py::arg("validate_only"), py::arg("critical_mu"))
      .def("step", [](SimulationHandle& h) { return h->step(); })
      .def("on_iteration",
           [](SimulationHandle& h, py::object observer) {
             if (observer.is_none()) return h->onIteration({});
             h->onIteration([observer](const StaticSolver::IterateProgress& p) {
               py::dict d;
               d["step"] = p.step;
               d["time"] = p.time;
               d["iteration"] = p.iteration;
               d["residual"] = p.residual;
               d["target"] = p.target;
               d["status_changes"] = p.statusChanges;
               d["attempt"] = std::string(p.attempt);
               observer(d);
             });
           })
      .def("run", [](SimulationHandle& h) { return reportDict(h->run()); })
      .def("finish", [](SimulationHandle& h) { return h->finish(); })
      .def("report", [](const SimulationHandle& h) { return reportDict(h->report()); })
      .def("ended", [](const SimulationHandle& h) { return h->ended(); })
      .def("time", [](const SimulationHandle& h) { return h->time(); })
      .def("history", [](const SimulationHandle& h) { return history(*h); })
      .def("contact_points", [](const SimulationHandle& h) { return contactPoints(*h); })
      .def("displacement",
           [](const SimulationHandle& h) {
             return matrix(h->displacement(), static_cast<std::size_t>(h->problem().dim()));
           })
      .def("nodal_fields",
           [](const SimulationHandle& h) {
             const NodalFields f = h->nodalFields();
             py::dict d;
             d["stress"] = matrix(f.stress, 6);
             d["von_mises"] = column(f.vonMises);
             if (!f.plasticStrain.empty()) d["equivalent_plastic_strain"] = column(f.plasticStrain);
             return d;
           })
      .def("coordinates",
           [](const SimulationHandle& h) { return matrix(h->scene().model.mesh->coords, 3); })
      .def("node_ids",
           [](const SimulationHandle& h) {
             const Mesh& mesh = *h->scene().model.mesh;
             std::vector<std::int64_t> ids(mesh.numNodes());
             for (std::size_t i = 0; i < ids.size(); ++i)
               ids[i] = mesh.nodeId(static_cast<std::int64_t>(i));
             return column(ids);
           })
      .def("summary_json", [](const SimulationHandle& h) { return h->summary().dump(); })
      .def("output_directory", [](const SimulationHandle& h) { return h->outputDirectory(); })
      .def("scene_name", [](const SimulationHandle& h) { return h->scene().scene.name; })
      .def("dofs", [](const SimulationHandle& h) { return h->problem().dofs().numGlobalDofs(); });
}
