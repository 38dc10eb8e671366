#include "apps/output/ContactCsv.hpp"

#include "core/io/CsvWriter.hpp"

#include <limits>
#include <utility>

namespace contactlab {

ContactCsv::ContactCsv(std::string path) : path_(std::move(path)) {}

void ContactCsv::write(const ContactProblem& contact, const std::vector<ContactZone>& zones,
                       const Mesh& mesh) const {
  CsvWriter table({"zone", "node", "x", "y", "z", "reference_x", "reference_y", "reference_z",
                   "gap", "pressure", "traction_x", "traction_y", "traction_z", "slip_x", "slip_y",
                   "slip_z", "status"});
  for (const auto& p : contact.results())
    table.addRow(
        zones[p.zone].name, static_cast<long long>(mesh.nodeId(p.node)), p.x[0], p.x[1], p.x[2],
        mesh.coords[3 * p.node], mesh.coords[3 * p.node + 1], mesh.coords[3 * p.node + 2],
        p.paired ? p.gap : std::numeric_limits<double>::quiet_NaN(), p.pressure, p.traction[0],
        p.traction[1], p.traction[2], p.slip[0], p.slip[1], p.slip[2], outputStatus(p));
  table.write(path_);
}

}  // namespace contactlab
