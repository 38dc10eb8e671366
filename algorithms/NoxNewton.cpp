#include "algorithms/NoxNewton.hpp"

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

#include <cmath>

namespace contactlab {
namespace {

using TOE = Thyra::TpetraOperatorVectorExtraction<Scalar, LO, GO, Node>;
using Teuchos::RCP;
using Teuchos::rcp;

// J x = b solved by the project's LinearSolver, factored when the factory initializes it.
class SolverOp : public Thyra::LinearOpWithSolveBase<double> {
 public:
  void set(const RCP<const Thyra::LinearOpBase<double>>& op, LinearSolver* solver) {
    op_ = op;
    solver_ = solver;
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
    auto b = TOE::getConstTpetraMultiVector(Teuchos::rcpFromRef(B));
    auto x = TOE::getTpetraMultiVector(Teuchos::rcpFromPtr(X));
    solver_->solve(*b, *x);  // LinearSolverError propagates: NOX reports the failure
    Thyra::SolveStatus<double> status;
    status.solveStatus = Thyra::SOLVE_STATUS_CONVERGED;
    return status;
  }

 private:
  RCP<const Thyra::LinearOpBase<double>> op_;
  LinearSolver* solver_ = nullptr;
};

class SolverFactory : public Thyra::LinearOpWithSolveFactoryBase<double>,
                      public Teuchos::ParameterListAcceptorDefaultBase {
 public:
  SolverFactory(LinearSolver& solver, NonlinearSystem& system) : solver_(solver), system_(system) {}
  bool isCompatible(const Thyra::LinearOpSourceBase<double>&) const override { return true; }
  RCP<Thyra::LinearOpWithSolveBase<double>> createOp() const override { return rcp(new SolverOp); }
  void initializeOp(const RCP<const Thyra::LinearOpSourceBase<double>>& source,
                    Thyra::LinearOpWithSolveBase<double>* op,
                    const Thyra::ESupportSolveUse) const override {
    auto matrix =
        Teuchos::rcp_dynamic_cast<const Matrix>(TOE::getConstTpetraOperator(source->getOp()), true);
    solver_.setMatrix(matrix, first_ || system_.takePatternChanged());
    first_ = false;
    dynamic_cast<SolverOp&>(*op).set(source->getOp(), &solver_);
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
  mutable bool first_ = true;
};

// R(x, t) = 0 at a fixed time t as a Thyra model: f = R, W = dR/dx.
class SystemModel : public Thyra::StateFuncModelEvaluatorBase<double> {
 public:
  SystemModel(NonlinearSystem& system, LinearSolver& solver, const RCP<const Map>& map)
      : system_(system),
        space_(Thyra::createVectorSpace<Scalar, LO, GO, Node>(map)),
        factory_(rcp(new SolverFactory(solver, system))) {
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
    // The system's tangent; its graph is fixed while the geometry is frozen (one NOX solve).
    return Thyra::createLinearOp<Scalar, LO, GO, Node>(
        Teuchos::rcp_implicit_cast<Tpetra::Operator<Scalar, LO, GO, Node>>(system_.tangent()),
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
    system_.assemble(*x, t_, f.get(), !out.get_W_op().is_null());
  }

  NonlinearSystem& system_;
  RCP<const Thyra::VectorSpaceBase<double>> space_;
  RCP<SolverFactory> factory_;
  Thyra::ModelEvaluatorBase::InArgs<double> inArgs_, nominal_;
  double t_ = 0;
};

}  // namespace

NoxNewton::NoxNewton(NonlinearSystem& system, LinearSolver& solver, NoxNewtonOptions options)
    : system_(system), solver_(solver), options_(std::move(options)) {}

RunReport NoxNewton::run(Vector& x, const StaticSolver::StepCallback& onStep) {
  RunReport report;
  const StaticSolverOptions& o = options_.steps;
  auto trial = system_.createVector();
  auto residual = system_.createVector();
  for (int step = 1; step <= o.steps; ++step) {
    StepReport sr;
    sr.step = step;
    sr.time = o.endTime * step / o.steps;
    trial->assign(x);
    system_.applyDirichlet(sr.time, *trial);
    system_.updateGeometry(*trial, sr.time);
    system_.assemble(*trial, sr.time, residual.get(), false);
    const double reference = residual->norm2();
    bool converged = false;
    for (int geometry = 0;; ++geometry) {
      // One NOX solve per frozen geometry (the tangent's graph is fixed during it).
      auto model = rcp(new SystemModel(system_, solver_, trial->getMap()));
      model->setTime(sr.time);
      auto thyraX =
          Thyra::createVector(Teuchos::rcp_implicit_cast<Vector>(trial), model->get_x_space());
      model->setNominal(thyraX);
      auto group = rcp(new NOX::Thyra::Group(NOX::Thyra::Vector(thyraX), model));
      auto params = rcp(new Teuchos::ParameterList);
      params->set("Nonlinear Solver", "Line Search Based");
      params->sublist("Line Search").set("Method", options_.lineSearch);
      // The linear solves are direct: no need for NOX to check (and re-apply) the Jacobian.
      params->sublist("Direction").sublist("Newton").set("Rescue Bad Newton Solve", false);
      // More'-Thuente's slope J d at a trial point would need a Jacobian there: use its
      // Jacobian-free slope (a difference of residuals) instead.
      params->sublist("Line Search")
          .sublist("More'-Thuente")
          .set("Optimize Slope Calculation", true);
      params->sublist("Printing").set("Output Information", 0);
      params->sublist("Printing").set("MyPID", 0);
      params->sublist("Printing").set("Output Processor", 0);
      const double target = std::max(o.absoluteTolerance, o.relativeTolerance * reference);
      auto normF = rcp(new NOX::StatusTest::NormF(target, NOX::StatusTest::NormF::Unscaled));
      auto maxIters = rcp(new NOX::StatusTest::MaxIters(o.maxIterations - sr.iterations));
      auto finite = rcp(new NOX::StatusTest::FiniteValue);
      auto tests = rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
      tests->addStatusTest(finite);
      tests->addStatusTest(normF);
      tests->addStatusTest(maxIters);
      auto solver = NOX::Solver::buildSolver(group, tests, params);
      NOX::StatusTest::StatusType status = NOX::StatusTest::Failed;
      try {
        status = solver->solve();
      } catch (const LinearSolverError& e) {
        report.failure = "linear-solver-failed";
        report.message = std::string(e.what()) + " (step " + std::to_string(step) + ")";
      } catch (const std::exception& e) {
        report.failure = "nonlinear-solver-error";
        report.message = "NOX (" + options_.lineSearch + ") stopped at step " +
                         std::to_string(step) + ": " + e.what();
      }
      sr.iterations += solver->getNumIterations();
      report.linearSolves += solver->getNumIterations();
      const auto& solution =
          dynamic_cast<const NOX::Thyra::Vector&>(solver->getSolutionGroup().getX());
      trial->assign(*TOE::getConstTpetraVector(solution.getThyraRCPVector()));
      if (!report.failure.empty()) break;
      if (status != NOX::StatusTest::Converged) {
        report.failure =
            finite->getStatus() == NOX::StatusTest::Failed ? "nan-detected" : "max-iterations";
        report.message =
            "NOX (" + options_.lineSearch + ") did not converge at step " + std::to_string(step);
        break;
      }
      // Geometric fixed point, as in StaticSolver.
      if (!system_.updateGeometry(*trial, sr.time)) {
        converged = true;
        break;
      }
      system_.assemble(*trial, sr.time, residual.get(), false);
      sr.residual = residual->norm2();
      if (sr.residual <= std::max(o.absoluteTolerance, o.geometryTolerance * reference)) {
        converged = true;
        break;
      }
      if (geometry == o.maxGeometryIterations) {
        report.failure = "geometry-not-converged";
        report.message = "the contact geometry still moved at step " + std::to_string(step);
        break;
      }
      ++sr.geometryIterations;
    }
    report.iterations += sr.iterations;
    report.geometryIterations += sr.geometryIterations;
    if (!converged) return report;
    x.assign(*trial);
    system_.commitState(x, sr.time);
    ++report.steps;
    if (onStep) onStep(sr, x);
  }
  report.converged = true;
  return report;
}

}  // namespace contactlab
