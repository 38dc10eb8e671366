#include "apps/output/StepsCsv.hpp"

#include "core/io/AtomicFile.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace contactlab {
namespace {

std::vector<std::string> stepColumns(bool criticalMuColumn) {
  std::vector<std::string> columns{"step",
                                   "time",
                                   "cuts",
                                   "newton_iterations",
                                   "status_iterations",
                                   "threshold_iterations",
                                   "geometry_iterations",
                                   "linear_solves",
                                   "residual",
                                   "contact_points",
                                   "stick_points",
                                   "slip_points",
                                   "normal_force",
                                   "contact_force_x",
                                   "contact_force_y",
                                   "contact_force_z",
                                   "cycling_events"};
  for (int k = 1; k < kCyclingKinds; ++k)
    columns.push_back(std::string("cycling_") + cyclingKindName(static_cast<CyclingKind>(k)));
  for (const char* c :
       {"condition_estimate", "assembly_s", "pairing_s", "contact_s", "linear_solve_s"})
    columns.push_back(c);
  if (criticalMuColumn) columns.push_back("critical_mu");
  return columns;
}

}  // namespace

StepsCsv::StepsCsv(OutputManifest& folder, bool criticalMuColumn)
    : folder_(folder), table_(stepColumns(criticalMuColumn)) {}

void StepsCsv::addStep(const StepReport& s, const ContactResultants& cr,
                       std::optional<double> condition,
                       const std::optional<ContactPhaseSeconds>& contactSeconds,
                       const std::optional<std::string>& criticalMu) {
  double assembly = s.seconds.assembly, pairing = 0, contactTerms = 0;
  if (contactSeconds) {
    assembly = contactSeconds->solid - last_.solid;
    pairing = contactSeconds->pairing - last_.pairing;
    contactTerms = contactSeconds->contact - last_.contact;
    last_ = *contactSeconds;
  }
  int events = 0;
  for (int k = 1; k < kCyclingKinds; ++k)
    events += s.cycling[k];
  using F = CsvWriter;
  std::vector<std::string> row{F::format(s.step),
                               F::format(s.time),
                               F::format(s.cuts),
                               F::format(s.iterations),
                               F::format(s.statusIterations),
                               F::format(s.thresholdIterations),
                               F::format(s.geometryIterations),
                               F::format(s.iterations),
                               F::format(s.residual),
                               F::format(cr.contact),
                               F::format(cr.stick),
                               F::format(cr.slip),
                               F::format(cr.normalForceMagnitude)};
  // The force history of a pressed or dragged body: the contact force on the slave surfaces.
  for (int i = 0; i < 3; ++i)
    row.push_back(F::format(cr.normalForce[i] + cr.tangentialForce[i]));
  row.push_back(F::format(events));
  for (int k = 1; k < kCyclingKinds; ++k)
    row.push_back(F::format(s.cycling[k]));
  row.push_back(condition ? F::format(*condition) : std::string());
  if (condition) maxCondition_ = std::max(maxCondition_, *condition);
  for (double v : {assembly, pairing, contactTerms, s.seconds.linearSolve})
    row.push_back(F::format(v));
  if (criticalMu) row.push_back(*criticalMu);
  table_.addFormattedRow(std::move(row));
}

void StepsCsv::resume(std::int64_t rows) {
  // Rows are single lines: no cell of steps.csv holds a line break.
  const std::string path = folder_.folder() + "/" + kFileName;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // the header, written again by write()
  std::int64_t n = 0;
  for (; n < rows && std::getline(in, line); ++n)
    earlierRows_ += line + "\n";
  if (n < rows)
    throw std::runtime_error(path + ": " + std::to_string(n) +
                             " step rows, the checkpoint counts " + std::to_string(rows));
}

void StepsCsv::write() {
  const std::string path = folder_.path(kFileName);
  if (earlierRows_.empty()) {
    table_.write(path);
    return;
  }
  const std::string table = table_.str();
  const std::size_t header = table.find('\n') + 1;
  writeFileAtomically(path, [&](std::ostream& out) {
    out << table.substr(0, header) << earlierRows_ << table.substr(header);
  });
}

}  // namespace contactlab
