// The contact columns of the convergence table with FORMULATION='CONTINUE' (named after code_aster's):
//   CONT_NEWT  ALGO_RESO_CONT='NEWTON': the slave nodes (contact points) whose status at the row's
//              iterate differs from the one of the last correction; a step converges with 0;
//   BOUC_CONT  ALGO_RESO_CONT='POINT_FIXE': the status loops of the step so far (the status is frozen
//              within the Newton iterations);
//   RESI_GEOM  the geometric criterion at the row's iterate, max |u - u_pairing| on the contact nodes
//              over max |u - u_start| (REAC_GEOM='AUTOMATIQUE' pairs again above RESI_GEOM at
//              convergence; '-' with REAC_GEOM='SANS' or nothing resolved);
//   FROT_NEWT  with friction, ALGO_RESO_FROT='NEWTON': max |d|LAGS_C|| of the last correction over
//              max |LAGS_C| (a step converges at most RESI_FROT); BOUC_FROT with POINT_FIXE: the same
//              since the threshold of the last friction loop ('-' before the first correction).
// The free-text note follows them (active nodes, sticking ones, interpenetration); the contact points
// (ContinuousPointContactConstraint) have the same columns, the note counting points.

#include "solver/contact/ContinuousContactConstraint.hpp"
#include "solver/contact/ContinuousPointContact.hpp"

#include <fmt/format.h>
#include <optional>
#include <string>
#include <vector>

namespace stella::contact {
namespace {

std::string headerCell(const char* name) {
  return fmt::format(" {:<10} |", name);
}

// The driver writes one space before the note: the first cell is then " value |" as the header's.
std::string firstCell(int value) {
  return fmt::format("{:>10} |", value);
}

std::string realCell(double value) {
  return value < 0.0 ? fmt::format(" {:>10} |", "-") : fmt::format(" {:>10.3e} |", value);
}

const char* statusColumn(const ContactDefinition& d) {
  return d.settings.continuous.statusLoop == StatusLoop::Newton ? "CONT_NEWT" : "BOUC_CONT";
}

template <class Status>
int statusCount(const ContactDefinition& d, const Status& now, const Status& last, int loops) {
  if (d.settings.continuous.statusLoop != StatusLoop::Newton) {
    return loops;
  }
  int changes = 0;
  for (std::size_t k = 0; k < now.size() && k < last.size(); ++k) {
    changes += now[k] != last[k] ? 1 : 0;
  }
  return changes;
}

std::string columnsHeader(const ContactDefinition& d) {
  std::string h = headerCell(statusColumn(d)) + headerCell("RESI_GEOM");
  if (d.hasFriction()) {
    h += headerCell(d.settings.continuous.frictionFixedPoint ? "BOUC_FROT" : "FROT_NEWT");
  }
  return h;
}

// The columns and the note; `what` names the counted entities ("" nodes, "pts " contact points),
// `frictionCriterion` is given with friction.
std::string columnsNote(const ContactDefinition& d, const std::vector<char>& status,
                        const std::vector<char>& last, int loops, double geometry,
                        std::optional<double> frictionCriterion, int active, double penetration,
                        const char* what) {
  std::string cells = firstCell(statusCount(d, status, last, loops)) + realCell(geometry);
  if (frictionCriterion) {
    int sticking = 0;
    for (char st : status) {
      sticking += st == 1 ? 1 : 0;
    }
    return cells + realCell(*frictionCriterion) +
           fmt::format(" CONT {}{} act. ({} stick) pene {:.2e}", active, what, sticking, penetration);
  }
  return cells + fmt::format(" CONT {}{} act. pene {:.2e}", active, what, penetration);
}

} // namespace

std::string ContinuousContactConstraint::iterationHeader() const {
  return columnsHeader(*definition_);
}

std::string ContinuousContactConstraint::iterationNote() const {
  return columnsNote(*definition_, status_, lastStatus_, statusIterations_, noteGeometry_,
                     friction() ? std::optional<double>(frictionCriterion()) : std::nullopt, noteActive_,
                     notePenetration_, "");
}

std::string ContinuousPointContactConstraint::iterationHeader() const {
  return columnsHeader(*definition_);
}

std::string ContinuousPointContactConstraint::iterationNote() const {
  return columnsNote(*definition_, status_, lastStatus_, statusIterations_, noteGeometry_,
                     friction() ? std::optional<double>(frictionCriterion()) : std::nullopt, noteActive_,
                     notePenetration_, " pts");
}

} // namespace stella::contact
