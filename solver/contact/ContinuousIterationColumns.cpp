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

} // namespace

std::string ContinuousContactConstraint::iterationHeader() const {
  std::string h = headerCell(statusColumn(*definition_)) + headerCell("RESI_GEOM");
  if (friction()) {
    h += headerCell(definition_->settings.continuous.frictionFixedPoint ? "BOUC_FROT" : "FROT_NEWT");
  }
  return h;
}

std::string ContinuousContactConstraint::iterationNote() const {
  const int count = statusCount(*definition_, status_, lastStatus_, statusIterations_);
  std::string cells = firstCell(count) + realCell(noteGeometry_);
  if (friction()) {
    int sticking = 0;
    for (char st : status_) {
      sticking += st == 1 ? 1 : 0;
    }
    return cells + realCell(frictionCriterion()) +
           fmt::format(" CONT {} act. ({} stick) pene {:.2e}", noteActive_, sticking, notePenetration_);
  }
  return cells + fmt::format(" CONT {} act. pene {:.2e}", noteActive_, notePenetration_);
}

std::string ContinuousPointContactConstraint::iterationHeader() const {
  std::string h = headerCell(statusColumn(*definition_)) + headerCell("RESI_GEOM");
  if (friction()) {
    h += headerCell(definition_->settings.continuous.frictionFixedPoint ? "BOUC_FROT" : "FROT_NEWT");
  }
  return h;
}

std::string ContinuousPointContactConstraint::iterationNote() const {
  const int count = statusCount(*definition_, status_, lastStatus_, statusIterations_);
  std::string cells = firstCell(count) + realCell(noteGeometry_);
  if (friction()) {
    int sticking = 0;
    for (char st : status_) {
      sticking += st == 1 ? 1 : 0;
    }
    return cells + realCell(frictionCriterion()) +
           fmt::format(" CONT {} pts act. ({} stick) pene {:.2e}", noteActive_, sticking, notePenetration_);
  }
  return cells + fmt::format(" CONT {} pts act. pene {:.2e}", noteActive_, notePenetration_);
}

} // namespace stella::contact
