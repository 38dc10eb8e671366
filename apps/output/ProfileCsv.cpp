#include "apps/output/ProfileCsv.hpp"

#include "apps/output/CylindricalComponents.hpp"
#include "core/io/CsvWriter.hpp"

#include <cmath>
#include <vector>

namespace contactlab {
namespace {

std::vector<std::string> columns(const Profile& p, int dim) {
  std::vector<std::string> c{"time",   "s",      "point_x", "point_y", "point_z",
                             "node_x", "node_y", "node_z",  "distance"};
  if (p.field == "displacement") {
    const char* names[] = {"u_x", "u_y", "u_z", "u_r", "u_t", "u_z"};
    for (int k = 0; k < dim; ++k)
      c.push_back(names[(p.frame == "cylindrical" ? 3 : 0) + k]);
    return c;
  }
  const bool cylindrical = p.frame == "cylindrical";
  for (const char* s : cylindrical ? std::vector<const char*>{"rr", "tt", "zz", "rt", "tz", "rz"}
                                   : std::vector<const char*>{"xx", "yy", "zz", "xy", "yz", "xz"})
    c.push_back(std::string("stress_") + s);
  return c;
}

}  // namespace

ProfileCsv::ProfileCsv(const SceneModel& sm, const Problem& problem) : sm_(sm), problem_(problem) {}

void ProfileCsv::write(OutputManifest& folder, const std::string& suffix, const Vector& u,
                       double t) const {
  const bool root = u.getMap()->getComm()->getRank() == 0;
  const int dim = problem_.dim();
  for (const Profile& p : sm_.profiles) {
    CsvWriter table(columns(p, dim));
    const bool cylindrical = p.frame == "cylindrical";
    const double length =
        std::sqrt(std::pow(p.to[0] - p.from[0], 2) + std::pow(p.to[1] - p.from[1], 2) +
                  std::pow(p.to[2] - p.from[2], 2));
    std::vector<std::array<double, 6>> stresses;
    if (p.field == "stress") stresses = problem_.nodeStresses(u, p.nodes, t);
    for (std::size_t k = 0; k < p.points.size(); ++k) {
      const double* xn = &sm_.model.mesh->coords[3 * p.nodes[k]];
      const std::array<double, 3> node{xn[0], xn[1], xn[2]};
      std::vector<double> row{t,
                              length * k / (p.points.size() - 1),
                              p.points[k][0],
                              p.points[k][1],
                              p.points[k][2],
                              node[0],
                              node[1],
                              node[2],
                              p.distances[k]};
      if (p.field == "displacement") {
        auto d = problem_.nodeDisplacement(u, p.nodes[k]);
        if (cylindrical) d = cylindricalComponents(d, node, p.centre, p.axis);
        for (int c = 0; c < dim; ++c)
          row.push_back(d[c]);
      } else {
        auto s = stresses[k];
        if (cylindrical) s = cylindricalComponents(s, node, p.centre, p.axis);
        row.insert(row.end(), s.begin(), s.end());
      }
      table.addRow(row);
    }
    if (root) table.write(folder.path("profile_" + p.name + suffix + ".csv"));
  }
}

}  // namespace contactlab
