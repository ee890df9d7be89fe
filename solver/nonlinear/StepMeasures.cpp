// StepMeasures: MESURE of STAT_NON_LINE, the table 'STAT' of the time measures of each step.

#include "solver/nonlinear/StepMeasures.hpp"

#include "solver/session/Session.hpp"

#include <algorithm>
#include <fstream>

namespace stella {

StepMeasures::StepMeasures(bool keepTable, std::optional<int> unit, const SourceLocation& unitAt)
    : keepTable_(keepTable), unit_(unit), unitAt_(unitAt) {
  table_->title = "STAT";
}

StepMeasures::Snapshot StepMeasures::take(const MechanicalSystem& system) {
  const PhaseTimes t = system.phaseTimes();
  return {std::chrono::steady_clock::now(), t.assembly, t.factorisation, t.solve,
          system.solver().factorizations()};
}

void StepMeasures::startStep(const MechanicalSystem& system) {
  start_ = take(system);
}

void StepMeasures::endStep(const MechanicalSystem& system, double time, int iterations,
                           int lineSearchIterations) {
  const Snapshot end = take(system);
  const double step = std::chrono::duration<double>(end.wall - start_.wall).count();
  const double integrate = end.integrate - start_.integrate;
  const double factor = end.factor - start_.factor;
  const double solve = end.solve - start_.solve;
  table_->addRow(
      {{"INST", Value(time)},
       {"Time_Time_Step", Value(step)},
       {"Count_Newt_Iter", Value(static_cast<std::int64_t>(iterations))},
       {"Time_Integrate", Value(integrate)},
       {"Time_Factor", Value(factor)},
       {"Count_Factor", Value(static_cast<std::int64_t>(end.factorizations - start_.factorizations))},
       {"Time_Solve", Value(solve)},
       {"Count_LineSearch", Value(static_cast<std::int64_t>(lineSearchIterations))},
       {"Time_Other", Value(std::max(0.0, step - integrate - factor - solve))}});
}

void StepMeasures::attach(Result& result) const {
  if (keepTable_) {
    result.tables["STAT"] = table_;
  }
}

void StepMeasures::write(Session& session) const {
  if (!unit_) {
    return;
  }
  const std::string text = table_->format("TABLEAU");
  if (*unit_ == 6) {
    session.message() << text << "\n";
  } else if (*unit_ == 8) {
    session.result() << text << "\n";
  } else {
    std::ofstream out(session.unitPath(*unit_, unitAt_, false), std::ios::app);
    out << text << "\n";
  }
  session.message() << "   MESURE: the table of the step times (" << table_->rowCount()
                    << " rows) written to unit " << *unit_ << "\n";
}

} // namespace stella
