#include "core/problem/ElementKernel.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/ReferenceElement.hpp"
#include "core/materials/Tensor3.hpp"
#include "core/problem/AxisymmetricKernel.hpp"
#include "core/problem/AxisymmetricTotalLagrangianKernel.hpp"
#include "core/problem/ElementUpdateError.hpp"
#include "core/problem/SmallStrainKernel.hpp"
#include "core/problem/TotalLagrangianKernel.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace contactlab {

ElementKernel::ElementKernel(ElementType type, int quadratureDegree, bool axisymmetric)
    : type_(type), dim_(info(type).dim), numNodes_(info(type).nodes), axisymmetric_(axisymmetric) {
  if (dim_ != 2 && dim_ != 3)
    throw std::invalid_argument(std::string("a solid element kernel needs a 2D or 3D cell type, "
                                            "got ") +
                                info(type).name);
  if (axisymmetric && dim_ != 2)
    throw std::invalid_argument(std::string("an axisymmetric kernel needs a 2D cell type, got ") +
                                info(type).name);
  rule_ = &quadratureRule(
      type, quadratureDegree < 0 ? stiffnessQuadratureDegree(type) : quadratureDegree);
  numPoints_ = rule_->size();
  const ReferenceElement& ref = ReferenceElement::get(type);
  N_.resize(numPoints_ * numNodes_);
  dNdxi_.resize(numPoints_ * numNodes_ * dim_);
  for (int q = 0; q < numPoints_; ++q) {
    const double* xi = &rule_->points[q * dim_];
    ref.shape(xi, &N_[q * numNodes_]);
    ref.shapeDerivatives(xi, &dNdxi_[q * numNodes_ * dim_]);
  }
}

void ElementKernel::initializeState(const Material& material, double* state) const {
  const int ss = material.stateSize();
  if (ss == 0) return;
  for (int q = 0; q < numPoints_; ++q)
    material.initializeState(state + q * ss);
}

double ElementKernel::gradients(int q, const double* x, double* dNdx) const {
  const double w = rule_->weights[q] *
                   physicalGradients(dim_, numNodes_, x, &dNdxi_[q * numNodes_ * dim_], dNdx);
  if (!axisymmetric_) return w;
  double r = 0.0;  // the quadrature point's radius
  for (int a = 0; a < numNodes_; ++a)
    r += N_[q * numNodes_ + a] * x[3 * a];
  return 2.0 * M_PI * r * w;
}

double ElementKernel::measure(int q, const double* x) const {
  double dNdx[kMaxNodes * 3];
  return gradients(q, x, dNdx);
}

void ElementKernel::checkMaterial(const Material& material, const double* stateOld,
                                  double* stateNew) const {
  if (material.kinematics() != kinematics())
    throw std::invalid_argument(
        "material '" + material.name() + "' is " +
        (material.kinematics() == Kinematics::SmallStrain ? "small-strain" : "finite-strain") +
        " but the element kernel is not");
  if (material.stateSize() > 0 && (!stateOld || !stateNew))
    throw std::invalid_argument("material '" + material.name() +
                                "' has internal variables: the kernel needs state arrays");
}

void ElementKernel::beginEvaluation(const Material& material, const double* stateOld,
                                    double* stateNew, double* residual, double* tangent,
                                    double* averageStress) const {
  checkMaterial(material, stateOld, stateNew);
  const int nd = numDofs();
  if (residual)
    for (int k = 0; k < nd; ++k)
      residual[k] = 0.0;
  if (tangent)
    for (int k = 0; k < nd * nd; ++k)
      tangent[k] = 0.0;
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] = 0.0;
}

void ElementKernel::evaluateSmallStrainPoint(int q, double w, const Material& material,
                                             const double* stateOld, double* stateNew,
                                             MaterialInput& in, MaterialOutput& out,
                                             double* pointStress, double* averageStress,
                                             double& volume) const {
  const int ss = material.stateSize();
  in.stateOld = ss ? stateOld + q * ss : nullptr;
  out.stateNew = ss ? stateNew + q * ss : nullptr;
  out.stress.fill(0.0);
  out.tangent.fill(0.0);
  material.evaluate(in, out);
  if (out.failed) throw ElementUpdateError("material-update-failed", q, out.failure);
  if (pointStress)
    for (int k = 0; k < 6; ++k)
      pointStress[6 * q + k] = out.stress[k];
  if (averageStress) {
    for (int k = 0; k < 6; ++k)
      averageStress[k] += w * out.stress[k];
    volume += w;
  }
}

void ElementKernel::evaluateFiniteStrainPoint(int q, double w, const Material& material,
                                              const double* stateOld, double* stateNew,
                                              MaterialInput& in, MaterialOutput& out,
                                              double* pointStress, double* averageStress,
                                              double& volume) const {
  const double detF = tensor3::determinant(in.F);
  if (!(detF > 0)) {
    std::ostringstream s;
    s << "det F = " << detF << " <= 0: the displacement turns the element inside out";
    throw ElementUpdateError("inverted-element", q, s.str());
  }
  const int ss = material.stateSize();
  in.stateOld = ss ? stateOld + q * ss : nullptr;
  out.stateNew = ss ? stateNew + q * ss : nullptr;
  out.outOfPlane.reset();
  material.evaluate(in, out);
  if (out.failed) throw ElementUpdateError("material-update-failed", q, out.failure);
  if (!pointStress && !averageStress) return;
  // In plane stress the law solved for F_zz: the Cauchy stress takes that F, whose J is
  // det F_2D F_zz (the thickness changed).
  std::array<double, 9> F = in.F;
  if (out.outOfPlane) F[8] = *out.outOfPlane;
  const double J = out.outOfPlane ? detF * *out.outOfPlane : detF;
  constexpr int kVoigt3[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
  double sigma[6] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      double s = 0.0;
      for (int K = 0; K < 3; ++K)
        s += out.P[i * 3 + K] * F[j * 3 + K];
      sigma[kVoigt3[i][j]] = s / J;
    }
  for (int k = 0; k < 6; ++k) {
    if (pointStress) pointStress[6 * q + k] = sigma[k];
    if (averageStress) averageStress[k] += w * sigma[k];
  }
  volume += w;
}

void ElementKernel::addOperatorTerms(int rows, const int* slots, const double (*B)[kMaxNodes * 2],
                                     int nd, double w, const double* s, const double* C, int ldC,
                                     double* residual, double* tangent) {
  if (residual)
    for (int k = 0; k < nd; ++k)
      for (int r = 0; r < rows; ++r)
        residual[k] += w * B[r][k] * s[slots[r]];
  if (!tangent) return;
  double CB[9][kMaxNodes * 2];  // w C B, then K += B^T (w C B)
  for (int r = 0; r < rows; ++r)
    for (int k = 0; k < nd; ++k) {
      double v = 0.0;
      for (int m = 0; m < rows; ++m)
        v += C[slots[r] * ldC + slots[m]] * B[m][k];
      CB[r][k] = w * v;
    }
  for (int i = 0; i < nd; ++i)
    for (int r = 0; r < rows; ++r) {
      if (B[r][i] == 0.0) continue;
      double* row = &tangent[i * nd];
      for (int k = 0; k < nd; ++k)
        row[k] += B[r][i] * CB[r][k];
    }
}

void ElementKernel::quadraturePoints(const double* x, double* points) const {
  for (int q = 0; q < numPoints_; ++q)
    interpolatePosition(numNodes_, x, &N_[q * numNodes_], points + 3 * q);
}

void ElementKernel::referencePoints(double* points) const {
  for (int q = 0; q < numPoints_; ++q)
    for (int i = 0; i < 3; ++i)
      points[3 * q + i] = i < dim_ ? rule_->points[q * dim_ + i] : 0.0;
}

void ElementKernel::pointMeasures(const double* x, double* measures) const {
  for (int q = 0; q < numPoints_; ++q)
    measures[q] = measure(q, x);
}

double ElementKernel::volume(const double* x) const {
  double v = 0.0;
  for (int q = 0; q < numPoints_; ++q)
    v += measure(q, x);
  return v;
}

void ElementKernel::bodyForce(const double* x, const double* b, double* f) const {
  bodyForce(
      x, [&](const double*, double* value) { std::copy(b, b + dim_, value); }, f);
}

void ElementKernel::bodyForce(const double* x,
                              const std::function<void(const double* x, double* b)>& b,
                              double* f) const {
  for (int k = 0; k < numDofs(); ++k)
    f[k] = 0.0;
  for (int q = 0; q < numPoints_; ++q) {
    const double w = measure(q, x);
    const double* N = &N_[q * numNodes_];
    double point[3], value[3] = {0.0, 0.0, 0.0};
    interpolatePosition(numNodes_, x, N, point);
    b(point, value);
    for (int a = 0; a < numNodes_; ++a)
      for (int i = 0; i < dim_; ++i)
        f[a * dim_ + i] += w * N[a] * value[i];
  }
}

std::unique_ptr<ElementKernel> makeElementKernel(ElementType type, Kinematics kinematics,
                                                 int quadratureDegree, bool axisymmetric) {
  if (axisymmetric) {
    if (kinematics == Kinematics::FiniteStrain)
      return std::make_unique<AxisymmetricTotalLagrangianKernel>(type, quadratureDegree);
    return std::make_unique<AxisymmetricKernel>(type, quadratureDegree);
  }
  if (kinematics == Kinematics::FiniteStrain)
    return std::make_unique<TotalLagrangianKernel>(type, quadratureDegree);
  return std::make_unique<SmallStrainKernel>(type, quadratureDegree);
}

}  // namespace contactlab
