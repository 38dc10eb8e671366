#include "apps/output/ContactCsv.hpp"

#include "core/io/CsvWriter.hpp"

#include <limits>
#include <utility>

namespace contactlab {

ContactCsv::ContactCsv(std::string path) : path_(std::move(path)) {}

void ContactCsv::write(const ContactProblem& contact, const std::vector<ContactZone>& zones,
                       const Mesh& mesh) const {
  const std::vector<ContactPointResult> points = contact.results();
  std::vector<std::string> columns = {
      "zone",        "node",        "x",      "y",        "z",          "reference_x",
      "reference_y", "reference_z", "gap",    "pressure", "traction_x", "traction_y",
      "traction_z",  "slip_x",      "slip_y", "slip_z",   "status"};
  // Then the formulation's unknowns by name, empty where a point's formulation has no such one.
  const std::vector<std::string> unknowns = unknownNames(points);
  for (const std::string& name : unknowns)
    columns.push_back("unknown_" + name);
  CsvWriter table(columns);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& p : points) {
    std::vector<std::string> cells = {
        zones[p.zone].name,
        CsvWriter::format(static_cast<long long>(mesh.nodeId(p.node))),
        CsvWriter::format(p.x[0]),
        CsvWriter::format(p.x[1]),
        CsvWriter::format(p.x[2]),
        CsvWriter::format(mesh.coords[3 * p.node]),
        CsvWriter::format(mesh.coords[3 * p.node + 1]),
        CsvWriter::format(mesh.coords[3 * p.node + 2]),
        CsvWriter::format(p.paired ? p.gap : nan),
        CsvWriter::format(p.pressure),
        CsvWriter::format(p.traction[0]),
        CsvWriter::format(p.traction[1]),
        CsvWriter::format(p.traction[2]),
        CsvWriter::format(p.slip[0]),
        CsvWriter::format(p.slip[1]),
        CsvWriter::format(p.slip[2]),
        CsvWriter::format(outputStatus(p))};
    for (const std::string& name : unknowns)
      cells.push_back(CsvWriter::format(unknownValue(p, name, nan)));
    table.addFormattedRow(std::move(cells));
  }
  table.write(path_);
}

}  // namespace contactlab
