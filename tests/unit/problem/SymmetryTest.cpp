// Symmetry (roller) conditions on inclined planes (LinearConstraints.hpp). A bar held by
// rollers on its lower faces and pulled at its end is rotated rigidly: its rollers become
// inclined symmetry planes, and by frame invariance its displacement must be the unrotated
// bar's, rotated, to solver precision; in finite strain too, where Newton must keep its
// iteration count (a wrong elimination or a missing increment completion would not). Run on 1
// and 2 ranks: the planes' nodes straddle the partition.
#include "ProblemTestSupport.hpp"

#include "base/InputError.hpp"
#include "core/materials/NeoHookean.hpp"
#include "core/problem/LinearConstraints.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab::test {
namespace {

using Rotation = std::array<double, 9>;

// 2D: 30 degrees about z; 3D: 40 degrees about (1, 2, 3).
Rotation rotation(int dim) {
  const double a = (dim == 2 ? 30.0 : 40.0) * M_PI / 180.0;
  std::array<double, 3> k =
      dim == 2 ? std::array<double, 3>{0, 0, 1} : std::array<double, 3>{1, 2, 3};
  const double norm = std::sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
  for (double& v : k)
    v /= norm;
  const double c = std::cos(a), s = std::sin(a);
  Rotation r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double cross = i == j ? 0.0 : (((j - i + 3) % 3 == 1) ? -1.0 : 1.0) * k[3 - i - j];
      r[i * 3 + j] = (i == j ? c : 0.0) + (1 - c) * k[i] * k[j] + s * cross;
    }
  return r;
}

std::array<double, 3> rotate(const Rotation& r, const std::array<double, 3>& v) {
  std::array<double, 3> out{0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      out[i] += r[i * 3 + j] * v[j];
  return out;
}

std::shared_ptr<Mesh> bar(int dim) {
  if (dim == 3) {
    BoxParams p;
    p.lengths = {2.0, 0.5, 0.5};
    p.divisions = {6, 2, 2};
    return std::make_shared<Mesh>(generateBox(p));
  }
  RectangleParams p;
  p.lengths = {2.0, 0.5};
  p.divisions = {8, 2};
  return std::make_shared<Mesh>(generateRectangle(p));
}

std::vector<std::string> lowerFaces(int dim) {
  if (dim == 3) return {"xmin", "ymin", "zmin"};
  return {"left", "bottom"};
}

// Rollers on the lower faces (axis-aligned Dirichlet conditions, or, rotated, inclined symmetry
// planes), a total force on the far end.
SolidModel pulledBar(int dim, bool finiteStrain, const Rotation* r, bool fittedNormals = false) {
  SolidModel model;
  model.mesh = bar(dim);
  if (finiteStrain)
    model.materials["body"] = std::make_shared<NeoHookean>(NeoHookean::fromYoungPoisson(1e3, 0.3));
  else
    model.materials["body"] = std::make_shared<LinearElastic>(1e3, 0.3);
  const auto faces = lowerFaces(dim);
  PointLoad load;
  load.name = "pull";
  load.group = dim == 3 ? "xmax" : "right";
  load.force = {finiteStrain ? 150.0 : 1.0, 0, 0};
  if (!r) {
    for (int c = 0; c < dim; ++c) {
      DirichletCondition bc;
      bc.name = bc.group = faces[c];
      bc.components = {c};
      model.dirichlet.push_back(bc);
    }
    model.pointLoads.push_back(load);
    return model;
  }
  auto mesh = std::make_shared<Mesh>(*model.mesh);
  for (std::size_t n = 0; n < mesh->numNodes(); ++n) {
    const auto x =
        rotate(*r, {mesh->coords[3 * n], mesh->coords[3 * n + 1], mesh->coords[3 * n + 2]});
    std::copy(x.begin(), x.end(), mesh->coords.begin() + 3 * n);
  }
  model.mesh = mesh;
  for (int c = 0; c < dim; ++c) {
    std::array<double, 3> axis{0, 0, 0};
    axis[c] = 1.0;
    SymmetryCondition s;
    s.name = s.group = faces[c];
    if (!fittedNormals) s.normal = rotate(*r, axis);
    model.symmetries.push_back(s);
  }
  load.force = rotate(*r, load.force);
  model.pointLoads.push_back(load);
  return model;
}

class RotatedBar : public ::testing::TestWithParam<std::tuple<int, bool, bool>> {};

TEST_P(RotatedBar, IsTheAxisAlignedBarRotated) {
  const auto [dim, finiteStrain, fitted] = GetParam();
  auto comm = Tpetra::getDefaultComm();
  const Rotation r = rotation(dim);
  Problem aligned(pulledBar(dim, finiteStrain, nullptr), comm);
  Problem rotated(pulledBar(dim, finiteStrain, &r, fitted), comm);
  EXPECT_TRUE(rotated.model().dirichlet.empty());  // every plane is inclined
  const StaticRun ra = runWithMumps(aligned, 12), rb = runWithMumps(rotated, 12);
  ASSERT_TRUE(ra.report.converged && rb.report.converged) << ra.report.message << rb.report.message;
  const Vector &ua = *ra.u, &ub = *rb.u;
  // The same Newton: an inexact elimination or an increment left incomplete would cost more.
  EXPECT_LE(std::abs(rb.report.iterations - ra.report.iterations), 1);
  double largest = 0, error = 0;
  for (std::size_t n = 0; n < aligned.model().mesh->numNodes(); ++n) {
    const auto a = rotate(r, aligned.nodeDisplacement(ua, static_cast<std::int64_t>(n)));
    const auto b = rotated.nodeDisplacement(ub, static_cast<std::int64_t>(n));
    for (int i = 0; i < 3; ++i) {
      largest = std::max(largest, std::abs(a[i]));
      error = std::max(error, std::abs(a[i] - b[i]));
    }
  }
  EXPECT_GT(largest, finiteStrain ? 0.05 : 1e-4);  // a real deformation
  EXPECT_LT(error, 1e-9 * largest);
  // Each plane's reaction is the aligned roller's, rotated.
  for (int c = 0; c < dim; ++c) {
    const auto expected = rotate(r, aligned.reactions()[c].force);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(rotated.reactions()[c].force[i], expected[i],
                  1e-8 * (finiteStrain ? 150.0 : 1.0));
  }
}

INSTANTIATE_TEST_SUITE_P(TwoAndThreeD, RotatedBar,
                         ::testing::Combine(::testing::Values(2, 3), ::testing::Bool(),
                                            ::testing::Bool()));

// T^T K T keeps the tangent symmetric (MUMPS' symmetric modes stay usable): w . K v = v . K w
// for random w, v at a deformed finite-strain state.
TEST(LinearConstraints, KeepTheTangentSymmetric) {
  auto comm = Tpetra::getDefaultComm();
  for (int dim : {2, 3}) {
    const Rotation r = rotation(dim);
    Problem problem(pulledBar(dim, true, &r), comm);
    expectSymmetricTangent(problem, std::to_string(dim) + "D");
  }
}

// A plane normal to an axis is that axis' Dirichlet condition (the contact code then drops a
// friction direction it fixes, as for any roller).
TEST(LinearConstraints, AnAxisPlaneIsADirichletCondition) {
  auto comm = Tpetra::getDefaultComm();
  SolidModel model = pulledBar(2, false, nullptr);
  model.dirichlet.clear();
  model.symmetries = {{"left", "left", {-2.0, 0, 0}}, {"bottom", "bottom", {0, 0, 0}}};
  Problem problem(std::move(model), comm);
  ASSERT_EQ(problem.model().dirichlet.size(), 2u);
  EXPECT_TRUE(problem.model().symmetries.empty());
  EXPECT_EQ(problem.model().dirichlet[0].components, std::vector<int>{0});
  EXPECT_EQ(problem.model().dirichlet[1].components, std::vector<int>{1});  // fitted
  EXPECT_TRUE(problem.constraints().empty());
}

TEST(LinearConstraints, RefuseWhatIsNotAPlane) {
  auto comm = Tpetra::getDefaultComm();
  const Rotation r = rotation(2);
  const auto refused = expectRefused;
  SolidModel bent = pulledBar(2, false, &r, true);
  bent.symmetries[0].group = "boundary_corner_test";
  refused(bent, "boundary_corner_test");  // no such group
  SolidModel tilted = pulledBar(2, false, &r);
  tilted.symmetries[0].normal = {1, 0, 0};  // not the rotated face's normal
  refused(tilted, "off the plane");
  SolidModel outOfPlane = pulledBar(2, false, &r);
  outOfPlane.symmetries[0].normal = {0, 0.5, 1};
  refused(outOfPlane, "z component");
  SolidModel distorted = pulledBar(2, false, &r, true);
  auto mesh = std::make_shared<Mesh>(*distorted.mesh);
  mesh->coords[3 * mesh->boundaryNodes("left")[1]] += 0.01;
  distorted.mesh = mesh;
  refused(distorted, "planar");
}

}  // namespace
}  // namespace contactlab::test
