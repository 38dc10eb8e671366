#include "algorithms/NoxNewton.hpp"

#include "base/Elapsed.hpp"

#include <NOX_Observer.hpp>
#include <NOX_Solver_Factory.H>
#include <NOX_Solver_Generic.H>
#include <NOX_StatusTest_Combo.H>
#include <NOX_StatusTest_FiniteValue.H>
#include <NOX_StatusTest_MaxIters.H>
#include <NOX_StatusTest_NormF.H>
#include <NOX_Thyra_Group.H>
#include <NOX_Thyra_Vector.H>
#include <Teuchos_ParameterListAcceptorDefaultBase.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_StateFuncModelEvaluatorBase.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace contactlab {
namespace {

using TOE = Thyra::TpetraOperatorVectorExtraction<Scalar, LO, GO, Node>;
using Teuchos::RCP;
using Teuchos::rcp;

// NOX calls the model and the solver, so the phases are timed (PhaseTimer) where it calls them.

// J x = b solved by the project's LinearSolver, factored when the factory initializes it.
class SolverOp : public Thyra::LinearOpWithSolveBase<double> {
 public:
  void set(const RCP<const Thyra::LinearOpBase<double>>& op, LinearSolver* solver,
           RCP<const Matrix> matrix, const NonlinearSystem* system, double* solveSeconds) {
    op_ = op;
    solver_ = solver;
    matrix_ = std::move(matrix);
    system_ = system;
    solveSeconds_ = solveSeconds;
  }
  RCP<const Thyra::LinearOpBase<double>> op() const { return op_; }
  RCP<const Thyra::VectorSpaceBase<double>> range() const override { return op_->range(); }
  RCP<const Thyra::VectorSpaceBase<double>> domain() const override { return op_->domain(); }

 protected:
  bool opSupportedImpl(Thyra::EOpTransp t) const override { return t == Thyra::NOTRANS; }
  void applyImpl(Thyra::EOpTransp t, const Thyra::MultiVectorBase<double>& X,
                 const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& Y, double alpha,
                 double beta) const override {
    Thyra::apply(*op_, t, X, Y, alpha, beta);
  }
  bool solveSupportsImpl(Thyra::EOpTransp t) const override { return t == Thyra::NOTRANS; }
  // A direct solve meets any residual criterion NOX asks for.
  bool solveSupportsSolveMeasureTypeImpl(Thyra::EOpTransp t,
                                         const Thyra::SolveMeasureType&) const override {
    return t == Thyra::NOTRANS;
  }
  Thyra::SolveStatus<double> solveImpl(
      Thyra::EOpTransp, const Thyra::MultiVectorBase<double>& B,
      const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& X,
      const Teuchos::Ptr<const Thyra::SolveCriteria<double>>) const override {
    PhaseTimer timer(solveSeconds_);
    auto b = TOE::getConstTpetraMultiVector(Teuchos::rcpFromRef(B));
    auto x = TOE::getTpetraMultiVector(Teuchos::rcpFromPtr(X));
    solver_->solve(*b, *x);  // LinearSolverError propagates: NOX reports the failure
    throwIfNumericallySingular(*matrix_, *b, *x);
    // NOX solves for the Newton direction: complete it (its eliminated components are not in
    // J's range, so J d is unchanged off their zero-residual rows).
    for (std::size_t v = 0; v < x->getNumVectors(); ++v)
      system_->completeIncrement(*x->getVectorNonConst(v));
    Thyra::SolveStatus<double> status;
    status.solveStatus = Thyra::SOLVE_STATUS_CONVERGED;
    return status;
  }

 private:
  RCP<const Thyra::LinearOpBase<double>> op_;
  LinearSolver* solver_ = nullptr;
  RCP<const Matrix> matrix_;  // the one factored, for the singularity check of each solve
  const NonlinearSystem* system_ = nullptr;
  double* solveSeconds_ = nullptr;
};

class SolverFactory : public Thyra::LinearOpWithSolveFactoryBase<double>,
                      public Teuchos::ParameterListAcceptorDefaultBase {
 public:
  SolverFactory(LinearSolver& solver, NonlinearSystem& system, double* solveSeconds)
      : solver_(solver), system_(system), solveSeconds_(solveSeconds) {}
  bool isCompatible(const Thyra::LinearOpSourceBase<double>&) const override { return true; }
  RCP<Thyra::LinearOpWithSolveBase<double>> createOp() const override { return rcp(new SolverOp); }
  void initializeOp(const RCP<const Thyra::LinearOpSourceBase<double>>& source,
                    Thyra::LinearOpWithSolveBase<double>* op,
                    const Thyra::ESupportSolveUse) const override {
    // The system's current tangent (with geometry in Newton a re-pairing may have replaced it).
    // The solver analyses on its first matrix by itself.
    {
      PhaseTimer timer(solveSeconds_);
      solver_.setMatrix(system_.tangent(), system_.takePatternChanged());
    }
    dynamic_cast<SolverOp&>(*op).set(source->getOp(), &solver_, system_.tangent(), &system_,
                                     solveSeconds_);
  }
  void uninitializeOp(Thyra::LinearOpWithSolveBase<double>* op,
                      RCP<const Thyra::LinearOpSourceBase<double>>* source,
                      RCP<const Thyra::PreconditionerBase<double>>* prec,
                      RCP<const Thyra::LinearOpSourceBase<double>>* approx,
                      Thyra::ESupportSolveUse* use) const override {
    if (source) *source = Thyra::defaultLinearOpSource<double>(dynamic_cast<SolverOp&>(*op).op());
    if (prec) *prec = Teuchos::null;
    if (approx) *approx = Teuchos::null;
    if (use) *use = Thyra::SUPPORT_SOLVE_UNSPECIFIED;
  }
  bool supportsPreconditionerInputType(const Thyra::EPreconditionerInputType) const override {
    return false;
  }
  void initializePreconditionedOp(const RCP<const Thyra::LinearOpSourceBase<double>>&,
                                  const RCP<const Thyra::PreconditionerBase<double>>&,
                                  Thyra::LinearOpWithSolveBase<double>*,
                                  const Thyra::ESupportSolveUse) const override {
    throw std::logic_error("SolverFactory: no preconditioner input");
  }
  void setParameterList(const RCP<Teuchos::ParameterList>& list) override { setMyParamList(list); }

 private:
  LinearSolver& solver_;
  NonlinearSystem& system_;
  double* solveSeconds_;  // factorizations and solves: NewtonOutcome::linearSolveSeconds
};

// The system's tangent as it is now: re-pairing replaces the matrix (and its graph) during a
// solve with geometry in Newton, so the operator NOX holds forwards to the current one.
class TangentOperator : public Tpetra::Operator<Scalar, LO, GO, Node> {
 public:
  explicit TangentOperator(const NonlinearSystem& system) : system_(system) {}
  Teuchos::RCP<const Map> getDomainMap() const override {
    return system_.tangent()->getDomainMap();
  }
  Teuchos::RCP<const Map> getRangeMap() const override { return system_.tangent()->getRangeMap(); }
  void apply(const Tpetra::MultiVector<Scalar, LO, GO, Node>& X,
             Tpetra::MultiVector<Scalar, LO, GO, Node>& Y, Teuchos::ETransp mode, Scalar alpha,
             Scalar beta) const override {
    system_.tangent()->apply(X, Y, mode, alpha, beta);
  }

 private:
  const NonlinearSystem& system_;
};

// NOX's side of contactSettled (NormF checks the residual).
class ContactStatusTest : public NOX::StatusTest::Generic {
 public:
  ContactStatusTest(const ContactControls* controls, double target)
      : controls_(controls), target_(target) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver,
                                          NOX::StatusTest::CheckType) override {
    status_ = contactSettled(controls_, target_, solver.getNumIterations())
                  ? NOX::StatusTest::Converged
                  : NOX::StatusTest::Unconverged;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& stream, int indent) const override {
    return stream << std::string(indent, ' ') << status_ << " contact statuses unchanged\n";
  }

 private:
  const ContactControls* controls_;
  double target_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

// Hands every accepted iterate to the driver's observer (cycling detection, progress).
class IterateObserver : public NOX::Observer {
 public:
  explicit IterateObserver(const NewtonMethod::Observer& observer) : observer_(observer) {}
  void runPostIterate(const NOX::Solver::Generic& solver) override {
    const int iteration = solver.getNumIterations();
    if (observer_.treat && observer_.treat(iteration)) {
      // The observer changed the law at the iterate (a cycling treatment). NOX observes after
      // its status tests, so the treatment acts from the next iteration, whose direction and
      // line search read this residual: it is evaluated again (the Jacobian is invalidated
      // with it). NOX hands observers a const solver; the group is its own working state.
      auto& group = const_cast<NOX::Abstract::Group&>(solver.getSolutionGroup());
      const Teuchos::RCP<NOX::Abstract::Vector> x = group.getX().clone();
      group.setX(*x);
      group.computeF();
    }
    const double norm = solver.getSolutionGroup().getNormF();
    if (observer_.report && std::isfinite(norm)) observer_.report(iteration, norm);
  }

 private:
  const NewtonMethod::Observer& observer_;
};

// R(x, t) = 0 at a fixed time t as a Thyra model: f = R, W = dR/dx.
class SystemModel : public Thyra::StateFuncModelEvaluatorBase<double> {
 public:
  // The phases' seconds are added to `seconds` (the outcome the solve returns).
  SystemModel(NonlinearSystem& system, LinearSolver& solver, const RCP<const Map>& map,
              bool geometryInNewton, NewtonOutcome& seconds)
      : system_(system),
        space_(Thyra::createVectorSpace<Scalar, LO, GO, Node>(map)),
        factory_(rcp(new SolverFactory(solver, system, &seconds.linearSolveSeconds))),
        geometryInNewton_(geometryInNewton),
        assemblySeconds_(&seconds.assemblySeconds) {
    Thyra::ModelEvaluatorBase::InArgsSetup<double> in;
    in.setModelEvalDescription("contactlab::SystemModel");
    in.setSupports(Thyra::ModelEvaluatorBase::IN_ARG_x);
    inArgs_ = in;
    nominal_ = in;
  }
  void setTime(double t) { t_ = t; }
  void setNominal(const RCP<Thyra::VectorBase<double>>& x) { nominal_.set_x(x); }

  RCP<const Thyra::VectorSpaceBase<double>> get_x_space() const override { return space_; }
  RCP<const Thyra::VectorSpaceBase<double>> get_f_space() const override { return space_; }
  Thyra::ModelEvaluatorBase::InArgs<double> getNominalValues() const override { return nominal_; }
  Thyra::ModelEvaluatorBase::InArgs<double> createInArgs() const override { return inArgs_; }
  RCP<Thyra::LinearOpBase<double>> create_W_op() const override {
    return Thyra::createLinearOp<Scalar, LO, GO, Node>(
        Teuchos::rcp_implicit_cast<Tpetra::Operator<Scalar, LO, GO, Node>>(
            rcp(new TangentOperator(system_))),
        space_, space_);
  }
  RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> get_W_factory() const override {
    return factory_;
  }

 private:
  Thyra::ModelEvaluatorBase::OutArgs<double> createOutArgsImpl() const override {
    Thyra::ModelEvaluatorBase::OutArgsSetup<double> out;
    out.setModelEvalDescription("contactlab::SystemModel");
    out.setSupports(Thyra::ModelEvaluatorBase::OUT_ARG_f);
    out.setSupports(Thyra::ModelEvaluatorBase::OUT_ARG_W_op);
    return out;
  }
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<double>& in,
                     const Thyra::ModelEvaluatorBase::OutArgs<double>& out) const override {
    auto x = TOE::getConstTpetraVector(in.get_x());
    RCP<Vector> f = out.get_f().is_null() ? Teuchos::null : TOE::getTpetraVector(out.get_f());
    PhaseTimer timer(assemblySeconds_);
    if (geometryInNewton_) system_.updateGeometry(*x, t_);
    system_.assemble(*x, t_, f.get(), !out.get_W_op().is_null());
  }

  NonlinearSystem& system_;
  RCP<const Thyra::VectorSpaceBase<double>> space_;
  RCP<SolverFactory> factory_;
  Thyra::ModelEvaluatorBase::InArgs<double> inArgs_, nominal_;
  bool geometryInNewton_;
  double* assemblySeconds_;
  double t_ = 0;
};

}  // namespace

NoxNewton::NoxNewton(NonlinearSystem& system, LinearSolver& solver, const ContactControls* controls,
                     std::string lineSearch, Teuchos::ParameterList noxParameters)
    : system_(system),
      solver_(solver),
      controls_(controls),
      lineSearch_(std::move(lineSearch)),
      noxParameters_(std::move(noxParameters)) {}

NewtonOutcome NoxNewton::solve(Vector& x, const NewtonRequest& request, const Observer& observer) {
  NewtonOutcome out;
  auto model = rcp(new SystemModel(system_, solver_, x.getMap(), request.geometryInNewton, out));
  model->setTime(request.time);
  auto trial = system_.createVector();
  trial->assign(x);
  auto thyraX =
      Thyra::createVector(Teuchos::rcp_implicit_cast<Vector>(trial), model->get_x_space());
  model->setNominal(thyraX);
  auto group = rcp(new NOX::Thyra::Group(NOX::Thyra::Vector(thyraX), model));
  auto params = rcp(new Teuchos::ParameterList(noxParameters_));
  params->set("Nonlinear Solver", "Line Search Based");
  params->sublist("Line Search").set("Method", lineSearch_);
  // The linear solves are direct: no need for NOX to check (and re-apply) the Jacobian.
  params->sublist("Direction").sublist("Newton").get("Rescue Bad Newton Solve", false);
  // More'-Thuente's slope J d at a trial point would need a Jacobian there: use its
  // Jacobian-free slope (a difference of residuals) instead.
  params->sublist("Line Search").sublist("More'-Thuente").get("Optimize Slope Calculation", true);
  params->sublist("Printing").get("Output Information", 0);
  params->sublist("Printing").set("MyPID", 0);
  params->sublist("Printing").set("Output Processor", 0);
  params->sublist("Solver Options")
      .set<RCP<NOX::Observer>>("Observer", rcp(new IterateObserver(observer)));
  // NewtonRequest::forcing: the target raised to the forcing times the first ||R|| (the solver
  // finds the residual at its initial guess computed and does not evaluate it again).
  double target = request.target;
  if (request.forcing > 0) {
    group->computeF();
    target = std::max(target, request.forcing * group->getNormF());
  }
  auto normF = rcp(new NOX::StatusTest::NormF(target, NOX::StatusTest::NormF::Unscaled));
  auto converged = rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::AND));
  converged->addStatusTest(normF);
  converged->addStatusTest(rcp(new ContactStatusTest(controls_, target)));
  auto maxIters = rcp(new NOX::StatusTest::MaxIters(request.maxIterations));
  auto finite = rcp(new NOX::StatusTest::FiniteValue);
  auto tests = rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
  tests->addStatusTest(finite);
  tests->addStatusTest(converged);
  tests->addStatusTest(maxIters);
  NOX::StatusTest::StatusType status = NOX::StatusTest::Failed;
  Teuchos::RCP<NOX::Solver::Generic> solver;
  try {
    solver = NOX::Solver::buildSolver(group, tests, params);
    status = solver->solve();
  } catch (const SingularMatrixError& e) {
    out.failure = kSingularTangent;
    out.message =
        singularTangentMessage(solver.is_null() ? 0 : solver->getNumIterations(), e.what());
  } catch (const LinearSolverError& e) {
    out.failure = "linear-solver-failed";
    out.message = e.what();
  } catch (const std::exception& e) {
    out.failure = "nonlinear-solver-error";
    out.message = "NOX (" + lineSearch_ + ") stopped: " + e.what();
  }
  if (solver.is_null()) return out;
  out.iterations = solver->getNumIterations();
  const auto& solution = dynamic_cast<const NOX::Thyra::Vector&>(solver->getSolutionGroup().getX());
  x.assign(*TOE::getConstTpetraVector(solution.getThyraRCPVector()));
  out.residual = solver->getSolutionGroup().getNormF();
  if (!out.failure.empty()) return out;
  if (status != NOX::StatusTest::Converged) {
    out.failure = finite->getStatus() == NOX::StatusTest::Failed     ? "nan-detected"
                  : maxIters->getStatus() == NOX::StatusTest::Failed ? "max-iterations"
                                                                     : "diverged";
    out.message = "NOX (" + lineSearch_ + ") did not converge in " +
                  std::to_string(out.iterations) + " iterations";
  }
  return out;
}

}  // namespace contactlab
